package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Ray;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Texture;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Renders;
import dev.strahl.world.World;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Tangent-space normal maps: the shading frame a map gives, against the frame computed by hand
 * from the texture coordinates (MikkTSpace's tangent and bitangent), and a flat map that changes
 * no bit of a render.
 */
class NormalMapTest {
    /** The quad z = 0, |x|, |y| ≤ 1, facing +z, with the given (u, v) at its corners (−1,−1), (1,−1), (1,1), (−1,1). */
    static TriangleMesh quad(float[] uvs) {
        return new TriangleMesh(new float[] {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, new int[] {0, 1, 2, 0, 2, 3}, null, uvs);
    }

    static final float[] PLAIN = {0, 0, 1, 0, 1, 1, 0, 1};          // u along +x, v along +y
    static final float[] TURNED = {0, 1, 0, 0, 1, 0, 1, 1};         // u along +y, v along −x
    static final float[] MIRRORED = {1, 0, 0, 0, 0, 1, 1, 1};       // u along −x, v along +y (det < 0)

    /** The texel of a map that tilts the normal by angle a towards +t (red) or +b (green). */
    static Rgb tilt(double a, boolean towardsBitangent) {
        double s = 0.5 + 0.5 * Math.sin(a), c = 0.5 + 0.5 * Math.cos(a);
        return towardsBitangent ? new Rgb(0.5, s, c) : new Rgb(s, 0.5, c);
    }

    /** The shading normal at (x, y) of the quad seen from above. */
    static Vector3d shadingNormal(TriangleMesh mesh, Material m, double x, double y, boolean fromBelow) {
        Scene scene = Scene.builder().addMesh(mesh, m).build();
        World world = World.of(scene);
        Tracer tracer = new Tracer(world, Shading.bsdfs(world, false), false);
        Shading s = new Shading();
        Ray ray = new Ray().set(new Vector3d(x, y, fromBelow ? -3 : 3), new Vector3d(0, 0, fromBelow ? 1 : -1), Double.POSITIVE_INFINITY);
        assertThat(tracer.trace(ray, s)).isCloseTo(3, within(1e-9));
        Vector3d local = new Vector3d();
        s.frame.toLocal(s.sp.n, local);
        assertThat(local.z).as("the frame is built on the tilted normal").isCloseTo(1, within(1e-12));
        return new Vector3d(s.sp.n);
    }

    @ParameterizedTest(name = "tilt {0} rad")
    @ValueSource(doubles = {0.1, 0.5, 1.0, -0.7})
    void redTiltsAlongTheTangentAndGreenAlongTheBitangent(double a) {
        Material base = Material.diffuse("d", Rgb.gray(0.5));
        double sa = Math.sin(a), ca = Math.cos(a);
        // n' = sin a · t + cos a · n; t = dp/du, b = dp/dv (the quad's uvs are orthonormal there).
        assertClose(shadingNormal(quad(PLAIN), base.withNormalMap(Texture.constant(tilt(a, false)), 1), 0.3, 0.2, false), sa, 0, ca);
        assertClose(shadingNormal(quad(PLAIN), base.withNormalMap(Texture.constant(tilt(a, true)), 1), 0.3, 0.2, false), 0, sa, ca);
        assertClose(shadingNormal(quad(TURNED), base.withNormalMap(Texture.constant(tilt(a, false)), 1), -0.4, 0.1, false), 0, sa, ca);
        assertClose(shadingNormal(quad(TURNED), base.withNormalMap(Texture.constant(tilt(a, true)), 1), -0.4, 0.1, false), -sa, 0, ca);
        // A mirrored mapping keeps the bitangent along dp/dv (MikkTSpace's sign).
        assertClose(shadingNormal(quad(MIRRORED), base.withNormalMap(Texture.constant(tilt(a, false)), 1), 0.5, -0.5, false), -sa, 0, ca);
        assertClose(shadingNormal(quad(MIRRORED), base.withNormalMap(Texture.constant(tilt(a, true)), 1), 0.5, -0.5, false), 0, sa, ca);
        // Seen from below, the two-sided material's frame is the tilted normal turned round.
        assertClose(shadingNormal(quad(PLAIN), base.withNormalMap(Texture.constant(tilt(a, false)), 1), 0.3, 0.2, true), -sa, 0, -ca);
    }

    @Test
    void scaleMultipliesXAndYAsGltfDoes() {
        double a = 0.4, k = 0.5;
        Vector3d n = shadingNormal(quad(PLAIN), Material.diffuse("d", Rgb.gray(0.5)).withNormalMap(Texture.constant(tilt(a, false)), k),
                0.1, 0.1, false);
        double x = k * Math.sin(a), z = Math.cos(a), len = Math.hypot(x, z);
        assertClose(n, x / len, 0, z / len);
    }

    @Test
    void aMapThatTiltsTheNormalBelowTheSurfaceIsIgnoredThere() {
        // n = (sin 2, 0, cos 2): 115° from the geometric normal.
        Vector3d n = shadingNormal(quad(PLAIN), Material.diffuse("d", Rgb.gray(0.5)).withNormalMap(Texture.constant(tilt(2.0, false)), 1),
                0.3, 0.2, false);
        assertClose(n, 0, 0, 1);
    }

    @Test
    void everyKindOfMaterialSeesTheTiltedFrame() {
        Material[] kinds = {Material.conductor("c", "gold", 0.2), Material.dielectric("g", 1.5, 0.1), Material.mirror("m", Rgb.gray(0.9)),
            Material.principled("p").roughness(0.3).build()};
        for (Material m : kinds) {
            assertClose(shadingNormal(quad(PLAIN), m.withNormalMap(Texture.constant(tilt(0.3, true)), 1), 0.3, 0.2, false),
                    0, Math.sin(0.3), Math.cos(0.3));
        }
    }

    /** A diffuse floor with texture coordinates under a small square lamp, seen at an angle. */
    static Scene litFloor(Material floor) {
        float[] lamp = {-0.3f, -0.3f, 1.5f, -0.3f, 0.3f, 1.5f, 0.3f, 0.3f, 1.5f, 0.3f, -0.3f, 1.5f};
        return Scene.builder()
                .addMesh(quad(PLAIN), floor)
                .addMesh(new TriangleMesh(lamp, new int[] {0, 1, 2, 0, 2, 3}, null), Material.emissive("lamp", Rgb.BLACK, Rgb.gray(10)))
                .camera(new Camera(new Vector3d(0, -2.5, 2), new Vector3d(0, 0, 0), new Vector3d(0, 0, 1), 50))
                .build();
    }

    @Test
    void aFlatMapRendersBitIdenticalToNone() {
        RenderSettings settings = RenderSettings.defaults().withSize(24, 24).withSamplesPerPixel(8).withSeed(5).withThreads(2);
        Material plain = Material.diffuse("floor", Rgb.gray(0.6));
        Image none = Renders.render(litFloor(plain), settings);
        Image flat = Renders.render(litFloor(plain.withNormalMap(Texture.constant(new Rgb(0.5, 0.5, 1)), 1)), settings);
        assertThat(flat.rgb()).isEqualTo(none.rgb());
        // The comparison sees a map that is not flat.
        Image tilted = Renders.render(litFloor(plain.withNormalMap(Texture.constant(tilt(0.3, false)), 1)), settings);
        assertThat(tilted.rgb()).isNotEqualTo(none.rgb());
    }

    private static void assertClose(Vector3d n, double x, double y, double z) {
        assertThat(n.x).as("x of %s", n).isCloseTo(x, within(1e-9));
        assertThat(n.y).as("y of %s", n).isCloseTo(y, within(1e-9));
        assertThat(n.z).as("z of %s", n).isCloseTo(z, within(1e-9));
    }
}
