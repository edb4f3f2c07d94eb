package dev.strahl.testing;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.Sphere;
import dev.strahl.scene.TriangleMesh;
import org.joml.Vector3dc;

/** A {@link GeometryBuilder} that takes {@link TriangleMesh}es, as the tests build geometry. */
public final class MeshGeometry {
    private final GeometryBuilder builder = new GeometryBuilder();

    /** Adds every non-degenerate triangle, all of them closed (back faces may be culled) or not. */
    public MeshGeometry addMesh(TriangleMesh mesh, int[] materials, boolean closed) {
        Meshes.add(builder, mesh, materials, closed);
        return this;
    }

    /** Adds every non-degenerate triangle with its flags. */
    public MeshGeometry addMesh(TriangleMesh mesh, int[] materials, byte[] flags) {
        Meshes.add(builder, mesh, materials, flags);
        return this;
    }

    public MeshGeometry addSphere(Vector3dc center, double radius, int material) {
        builder.addSphere(new Sphere(center, radius), material);
        return this;
    }

    public int degenerateCount() {
        return builder.degenerateCount();
    }

    public Geometry build() {
        return builder.build();
    }
}
