package dev.strahl.scene;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.MeshTopology;
import dev.strahl.image.Image;
import dev.strahl.light.Emission;
import dev.strahl.light.Environment;
import dev.strahl.material.Bsdf;
import dev.strahl.world.SurfaceMaps;
import dev.strahl.texture.Bitmap;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/** The work behind some of {@link Scene}'s and {@link Scene.Builder}'s methods, kept out of the API class. */
final class SceneParts {
    private SceneParts() {}

    /** The bytes of the materials' texture images, each image once. */
    static long textureBytes(List<Material> materials) {
        Set<Bitmap> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        long bytes = 0;
        for (Material m : materials) {
            for (Bitmap b : m.images()) {
                if (seen.add(b)) {
                    bytes += b.byteSize();
                }
            }
        }
        return bytes;
    }

    /**
     * Adds a mesh whose triangle t is of the material index {@code global[materialOfTriangle[t]]},
     * marking the closed, outward-facing parts of each material for back-face culling and noting
     * the degenerate triangles skipped.
     */
    static void addMesh(GeometryBuilder geometry, TriangleMesh mesh, int[] materialOfTriangle, int[] global, List<String> notes) {
        if (materialOfTriangle.length != mesh.triangleCount()) {
            throw new IllegalArgumentException("need one material per triangle: " + materialOfTriangle.length + " for " + mesh.triangleCount());
        }
        boolean[] closed = MeshTopology.closedOutwardGroups(mesh.positionsUnsafe(), mesh.indicesUnsafe(), materialOfTriangle, global.length);
        int[] materialsOut = new int[mesh.triangleCount()];
        byte[] flags = new byte[mesh.triangleCount()];
        for (int t = 0; t < materialsOut.length; t++) {
            int local = materialOfTriangle[t];
            if (local < 0 || local >= global.length) {
                throw new IllegalArgumentException("triangle " + t + " refers to material " + local + " of " + global.length);
            }
            materialsOut[t] = global[local];
            flags[t] = closed[local] ? Geometry.CLOSED : 0;
        }
        int before = geometry.degenerateCount();
        geometry.addMesh(mesh.positionsUnsafe(), mesh.indicesUnsafe(), mesh.normalsUnsafe(), mesh.uvsUnsafe(), materialsOut, flags);
        int skipped = geometry.degenerateCount() - before;
        if (skipped > 0) {
            notes.add("skipped " + skipped + " degenerate triangle" + (skipped == 1 ? "" : "s") + " (zero area)");
        }
    }

    /** Each material's BSDF. */
    static Bsdf[] bsdfs(List<Material> materials) {
        return materials.stream().map(m -> m.surface().bsdf()).toArray(Bsdf[]::new);
    }

    /** Each material's emission table. */
    static Emission[] emission(List<Material> materials) {
        return materials.stream().map(m -> m.surface().emissionTable()).toArray(Emission[]::new);
    }

    /** Each material's normal map and cut-out (null: none). */
    static SurfaceMaps[] maps(List<Material> materials) {
        return materials.stream().map(m -> m.surface().maps()).toArray(SurfaceMaps[]::new);
    }

    /** A latitude–longitude map as the world's environment. */
    static Environment mapOf(Image map, double scale, double rotateDegrees) {
        Objects.requireNonNull(map, "map");
        return Environment.map(map.width(), map.height(), map.rgb(), scale, rotateDegrees, "map");
    }

    /** The notes with the one that says the scene is lit by the studio sky (and framed, without a camera). */
    static List<String> withStudioNote(List<String> notes, boolean framed) {
        List<String> all = new java.util.ArrayList<>(notes);
        all.add(framed ? "the scene has no light and no camera: lighting it with " + StudioSky.DESCRIPTION + " and framing it from "
                + Camera.FRAMING_DESCRIPTION : "the scene has no light: lighting it with " + StudioSky.DESCRIPTION);
        return List.copyOf(all);
    }

    /** Whether any primitive's material emits. */
    static boolean anyEmits(Geometry g, Emission[] emission) {
        for (int prim = 0; prim < g.primitiveCount(); prim++) {
            if (!emission[g.material(prim)].isBlack()) {
                return true;
            }
        }
        return false;
    }
}
