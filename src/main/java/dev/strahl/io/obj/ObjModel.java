package dev.strahl.io.obj;

import dev.strahl.scene.TriangleMesh;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * What {@link ObjReader} makes of an OBJ file: one triangle mesh, the material of every triangle
 * and the warnings about what was read but not understood (one line each, starting with the file
 * they concern).
 *
 * @param mesh             the triangles, fan-triangulated from the OBJ faces in file order
 * @param triangleMaterial for triangle i of {@code mesh}, the index of its material in {@code materials}
 * @param materials        the materials faces use, in order of first use, each once
 * @param warnings         problems that did not stop the reading, in the order they were found
 */
public record ObjModel(TriangleMesh mesh, int[] triangleMaterial, List<MtlMaterial> materials, List<String> warnings) {

    public ObjModel {
        Objects.requireNonNull(mesh, "mesh");
        materials = List.copyOf(materials);
        warnings = List.copyOf(warnings);
        if (triangleMaterial.length != mesh.triangleCount()) {
            throw new IllegalArgumentException("one material per triangle expected: " + triangleMaterial.length
                    + " for " + mesh.triangleCount() + " triangles");
        }
        for (int i = 0; i < triangleMaterial.length; i++) {
            if (triangleMaterial[i] < 0 || triangleMaterial[i] >= materials.size()) {
                throw new IllegalArgumentException("triangle " + i + " refers to material " + triangleMaterial[i]
                        + " of " + materials.size());
            }
        }
        triangleMaterial = triangleMaterial.clone();
    }

    @Override
    public int[] triangleMaterial() {
        return triangleMaterial.clone();
    }

    /** The material of triangle {@code i}, without copying the array. */
    MtlMaterial materialOf(int triangle) {
        return materials.get(triangleMaterial[triangle]);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ObjModel m && mesh.equals(m.mesh) && Arrays.equals(triangleMaterial, m.triangleMaterial)
                && materials.equals(m.materials) && warnings.equals(m.warnings);
    }

    @Override
    public int hashCode() {
        return Objects.hash(mesh, Arrays.hashCode(triangleMaterial), materials, warnings);
    }

    @Override
    public String toString() {
        return "ObjModel[" + mesh + ", " + materials.size() + " materials, " + warnings.size() + " warnings]";
    }
}
