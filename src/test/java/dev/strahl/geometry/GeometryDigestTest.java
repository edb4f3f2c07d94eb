package dev.strahl.geometry;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.scene.TriangleMesh;
import java.security.MessageDigest;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** The digest that ties a checkpoint to its geometry changes with any primitive's data. */
class GeometryDigestTest {
    private static Geometry geometry(float z, float normalZ, int material, double radius) {
        TriangleMesh mesh = new TriangleMesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, z}, new int[] {0, 1, 2},
                new float[] {0, 0, 1, 0, 0, 1, 0, 0, normalZ});
        return new MeshGeometry().addMesh(mesh, new int[] {material}, false)
                .addSphere(new Vector3d(0, 0, 2), radius, 0).build();
    }

    private static byte[] digest(Geometry g) throws Exception {
        MessageDigest md = MessageDigest.getInstance("SHA-256");
        g.digest(md);
        return md.digest();
    }

    @Test
    void equalContentGivesEqualDigestsAndEveryChangeAnother() throws Exception {
        byte[] base = digest(geometry(0, 1, 0, 1));
        assertThat(digest(geometry(0, 1, 0, 1))).isEqualTo(base);
        assertThat(digest(geometry(Math.ulp(0f), 1, 0, 1))).as("a vertex").isNotEqualTo(base);
        assertThat(digest(geometry(0, -1, 0, 1))).as("a normal").isNotEqualTo(base);
        assertThat(digest(geometry(0, 1, 1, 1))).as("a material").isNotEqualTo(base);
        assertThat(digest(geometry(0, 1, 0, Math.nextUp(1.0)))).as("a sphere").isNotEqualTo(base);
    }
}
