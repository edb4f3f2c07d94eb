package dev.strahl.io.ply;

import dev.strahl.scene.SceneException;
import dev.strahl.io.ply.PlyHeader.Element;
import dev.strahl.io.ply.PlyHeader.Format;
import dev.strahl.io.ply.PlyHeader.Property;
import java.nio.file.Path;

/**
 * Where the mesh lives in a PLY header: the vertex and face elements, the positions of x, y, z
 * (and nx, ny, nz) among the vertex properties and of the index list among the face properties.
 * Made only for a header that describes a usable mesh and fits into the file.
 */
final class PlyLayout {
    private static final int MAX_ARRAY = Integer.MAX_VALUE - 8;

    final Element vertices;
    final Element faces;
    final int x;
    final int y;
    final int z;
    /** Positions of nx, ny, nz, or null if the vertices have no normals. */
    final int[] normals;
    final int indexList;

    private PlyLayout(Element vertices, Element faces, int x, int y, int z, int[] normals, int indexList) {
        this.vertices = vertices;
        this.faces = faces;
        this.x = x;
        this.y = y;
        this.z = z;
        this.normals = normals;
        this.indexList = indexList;
    }

    /** Checks the header against what a mesh needs and against {@code bodyBytes}, the size of the body. */
    static PlyLayout of(Path file, PlyHeader h, long bodyBytes) throws SceneException {
        Element v = h.element("vertex");
        if (v == null) {
            throw new SceneException(file, h.lines, "the header declares no 'vertex' element");
        }
        Element f = h.element("face");
        if (f == null) {
            throw new SceneException(file, h.lines, "the header declares no 'face' element (a point cloud cannot be rendered)");
        }
        if (v.count() > MAX_ARRAY / 3) {
            throw new SceneException(file, v.line(), "too many vertices for one mesh: " + v.count());
        }
        if (f.count() > MAX_ARRAY / 3) {
            throw new SceneException(file, f.line(), "too many faces for one mesh: " + f.count());
        }
        int x = scalar(file, v, "x", true);
        int y = scalar(file, v, "y", true);
        int z = scalar(file, v, "z", true);
        int nx = scalar(file, v, "nx", false);
        int ny = scalar(file, v, "ny", false);
        int nz = scalar(file, v, "nz", false);
        int[] normals = null;
        if (nx >= 0 && ny >= 0 && nz >= 0) {
            normals = new int[] {nx, ny, nz};
        } else if (nx >= 0 || ny >= 0 || nz >= 0) {
            throw new SceneException(file, v.line(), "element 'vertex' has only some of the normal properties nx, ny, nz");
        }
        int list = f.indexOf("vertex_indices");
        if (list < 0) {
            list = f.indexOf("vertex_index");
        }
        if (list < 0) {
            throw new SceneException(file, f.line(), "element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
        }
        Property p = f.properties().get(list);
        if (!p.isList()) {
            throw new SceneException(file, p.line(), "property '" + p.name() + "' of element 'face' must be a list");
        }
        if (!p.type().integer) {
            throw new SceneException(file, p.line(), "list '" + p.name() + "' must hold an integer type, got " + p.type().name);
        }
        long least = 0;
        for (Element e : h.elements) {
            least += Math.min(Long.MAX_VALUE / 64, e.count()) * e.minimumBytes(h.format);
        }
        if (least > bodyBytes) {
            throw new SceneException(file, h.lines, "the file is truncated: its header declares elements that need at least "
                    + least + " bytes" + (h.format == Format.ASCII ? " of text" : "") + ", but only " + bodyBytes + " follow the header");
        }
        return new PlyLayout(v, f, x, y, z, normals, list);
    }

    /** Room for the indices when every face is a triangle (grown for polygons). */
    int initialIndexCapacity() {
        return (int) (3 * faces.count());
    }

    private static int scalar(Path file, Element v, String name, boolean required) throws SceneException {
        int i = v.indexOf(name);
        if (i < 0) {
            if (required) {
                throw new SceneException(file, v.line(), "element 'vertex' has no property '" + name + "'");
            }
            return -1;
        }
        Property p = v.properties().get(i);
        if (p.isList()) {
            throw new SceneException(file, p.line(), "property '" + name + "' of element 'vertex' must be a scalar, not a list");
        }
        return i;
    }
}
