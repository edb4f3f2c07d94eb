package dev.strahl.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.accel.TraversalStack;
import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Transform;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.Renders;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A scene with instances against the same scene with every instance's meshes copied and moved
 * (the flattened scene, which {@code Transform} moves vertex by vertex): the same surfaces under
 * every ray (point, normals, texture coordinates, material), rotated, scaled unequally and
 * mirrored; the same images within noise with every integrator; the same bits on 1, 2 and 3
 * threads; and the builder's refusals.
 */
class InstancingTest {
    static final Material FLOOR = Material.diffuse("floor", Rgb.gray(0.6));
    static final Material LAMP = Material.emissive("lamp", Rgb.gray(0), Rgb.gray(12));
    static final Material BALL = Material.glossy("ball", new Rgb(0.6, 0.2, 0.1), Rgb.gray(0.2), 40);
    static final Material CARD = Material.diffuse("card", new Rgb(0.1, 0.3, 0.7));
    static final TriangleMesh SPHERE = Meshes.icosphere(2, 0.5, false);
    /** An open quad with texture coordinates, so that the tangent frame's handedness shows. */
    static final TriangleMesh QUAD = new TriangleMesh(new float[] {-0.6f, 0, -0.6f, 0.6f, 0, -0.6f, 0.6f, 0.3f, 0.6f, -0.6f, 0.3f, 0.6f},
            new int[] {0, 1, 2, 0, 2, 3}, null, new float[] {0, 0, 1, 0, 1, 1, 0, 1});

    /** Twelve placements: rotations, unequal scales, every third mirrored. */
    static List<Transform> placements() {
        List<Transform> out = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            double sx = 0.6 + 0.1 * (i % 4), sy = 0.5 + 0.15 * (i % 3), sz = 0.8 + 0.05 * i;
            out.add(Transform.scaling(1).scale(i % 3 == 0 ? -sx : sx, sy, sz).rotate(30 * i, 1, 2, 0.5)
                    .translate(-2.4 + 1.6 * (i % 4), 0.5 + 0.2 * (i % 2), -1.5 + 1.5 * (i / 4)));
        }
        return out;
    }

    static Scene.Builder room() {
        TriangleMesh floor = new TriangleMesh(new float[] {-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5}, new int[] {0, 2, 1, 0, 3, 2}, null, null);
        TriangleMesh lamp = new TriangleMesh(new float[] {-1, 4, -1, 1, 4, -1, 1, 4, 1, -1, 4, 1}, new int[] {0, 1, 2, 0, 2, 3}, null, null);
        return Scene.builder().addMesh(floor, FLOOR).addMesh(lamp, LAMP)
                .camera(new Camera(new Vector3d(0, 3, 6), new Vector3d(0, 0.5, 0), new Vector3d(0, 1, 0), 50));
    }

    static Scene instanced() {
        Scene.Builder b = room().beginGroup("thing").addMesh(SPHERE, BALL).addMesh(QUAD, CARD).endGroup();
        placements().forEach(t -> b.addInstance("thing", t));
        return b.build();
    }

    static Scene flattened() {
        Scene.Builder b = room();
        placements().forEach(t -> b.addMesh(SPHERE, BALL, t).addMesh(QUAD, CARD, t));
        return b.build();
    }

    @Test
    void everyRayMeetsTheSameSurfaceAsInTheFlattenedScene() {
        Scene a = instanced(), b = flattened();
        World wa = World.of(a), wb = World.of(b);
        assertThat(wa.instances().count()).isEqualTo(12);
        assertThat(wb.instances().count()).isZero();
        assertThat(wa.instancedTriangles()).isEqualTo(wb.uniqueTriangles());
        assertThat(wa.uniqueTriangles()).isEqualTo(4 + SPHERE.triangleCount() + 2);
        CameraRays rays = CameraRays.pinholeOf(a.camera(), 96, 96);
        TraversalStack stack = new TraversalStack();
        SurfacePoint sa = new SurfacePoint(), sb = new SurfacePoint();
        int instanceHits = 0, mirroredQuads = 0, differ = 0;
        for (int y = 0; y < 96; y++) {
            for (int x = 0; x < 96; x++) {
                Ray ra = new Ray(), rb = new Ray();
                rays.generate(x + 0.5, y + 0.5, ra);
                rays.generate(x + 0.5, y + 0.5, rb);
                Hit ha = new Hit().reset(), hb = new Hit().reset();
                boolean fa = wa.bvh().intersect(ra, ha, stack, true), fb = wb.bvh().intersect(rb, hb, stack, true);
                if (fa != fb) {
                    differ++;                   // a ray through an edge, whose float vertices differ in the last bit
                    continue;
                }
                if (!fa) {
                    continue;
                }
                wa.surface(ra, ha, sa);
                wb.surface(rb, hb, sb);
                String what = "pixel " + x + ", " + y;
                assertThat(a.materials().get(sa.material).name()).as(what).isEqualTo(b.materials().get(sb.material).name());
                assertThat(ha.t).as(what).isCloseTo(hb.t, org.assertj.core.data.Offset.offset(1e-5 * hb.t));
                assertThat(sa.p.distance(sb.p)).as(what).isLessThan(1e-5);
                assertThat(sa.ng.dot(sb.ng)).as(what + ": geometric normal " + sa.ng + " vs " + sb.ng).isGreaterThan(1 - 1e-9);
                assertThat(sa.n.dot(sb.n)).as(what + ": shading normal").isGreaterThan(1 - 1e-6);
                if (a.materials().get(sa.material) == CARD) {
                    // (The ball has no texture coordinates: its (u, v) are barycentrics, which a mirror's reversed winding renames.)
                    assertThat(sa.uv.distance(sb.uv)).as(what).isLessThan(1e-5);
                    assertThat(sa.tangentSign).as(what).isEqualTo(sb.tangentSign);
                    assertThat(sa.dpdu.angle(sb.dpdu)).as(what).isLessThan(1e-5);
                }
                instanceHits += ha.instance >= 0 ? 1 : 0;
                mirroredQuads += ha.instance % 3 == 0 && a.materials().get(sa.material) == CARD ? 1 : 0;
            }
        }
        assertThat(instanceHits).isGreaterThan(1000);
        assertThat(mirroredQuads).as("rays that meet a mirrored card").isGreaterThan(20);
        assertThat(differ).isLessThan(96 * 96 / 200);
    }

    @ParameterizedTest
    @EnumSource(IntegratorKind.class)
    void theImageIsTheFlattenedScenesWithinNoise(IntegratorKind kind) {
        RenderSettings s = RenderSettings.defaults().withSize(48, 48).withSamplesPerPixel(kind == IntegratorKind.PHOTON ? 8 : 32)
                .withSeed(5).withIntegrator(kind).withMaxDepth(4);
        Image a = Renders.render(instanced(), s), b = Renders.render(flattened(), s);
        double[] ma = a.mean(), mb = b.mean();
        for (int c = 0; c < 3; c++) {
            assertThat(ma[c]).as("%s mean %d", kind, c).isCloseTo(mb[c], org.assertj.core.data.Percentage.withPercentage(1));
        }
        // Equal means per 16×16 region: the same seed makes the same paths, apart from the last bits of the vertices.
        for (int by = 0; by < 3; by++) {
            for (int bx = 0; bx < 3; bx++) {
                double la = 0, lb = 0;
                for (int y = 16 * by; y < 16 * by + 16; y++) {
                    for (int x = 16 * bx; x < 16 * bx + 16; x++) {
                        la += a.get(x, y, 0) + a.get(x, y, 1) + a.get(x, y, 2);
                        lb += b.get(x, y, 0) + b.get(x, y, 1) + b.get(x, y, 2);
                    }
                }
                assertThat(la).as("%s region %d, %d", kind, bx, by).isCloseTo(lb, org.assertj.core.data.Offset.offset(0.03 * lb + 1e-3));
            }
        }
    }

    @Test
    void theSameBitsOnOneTwoAndThreeThreads() {
        Scene scene = instanced();
        RenderSettings s = RenderSettings.defaults().withSize(40, 40).withSamplesPerPixel(8).withSeed(9);
        Image one = Renders.render(scene, s.withThreads(1));
        assertThat(Renders.render(scene, s.withThreads(2))).isEqualTo(one);
        assertThat(Renders.render(scene, s.withThreads(3))).isEqualTo(one);
    }

    @Test
    void theBuilderRefusesWhatInstancingCannotDo() {
        assertThatThrownBy(() -> room().beginGroup("g").addMesh(QUAD, LAMP))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("emissive material 'lamp' in group 'g'");
        assertThatThrownBy(() -> room().beginGroup("g").beginGroup("h"))
                .isInstanceOf(IllegalStateException.class).hasMessageContaining("groups do not nest");
        assertThatThrownBy(() -> room().beginGroup("g").addMesh(QUAD, CARD).addInstance("g", Transform.IDENTITY))
                .isInstanceOf(IllegalStateException.class).hasMessageContaining("groups do not nest");
        assertThatThrownBy(() -> room().addInstance("tree", Transform.IDENTITY))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("unknown group 'tree'");
        assertThatThrownBy(() -> room().beginGroup("g").addMesh(QUAD, CARD).build())
                .isInstanceOf(IllegalStateException.class).hasMessageContaining("group 'g' is never ended");
        assertThatThrownBy(() -> room().beginGroup("g").endGroup().beginGroup("g"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("defined twice");
    }

    @Test
    void aGroupWithoutInstancesIsNotRenderedAndAnInstancedSphereIsAnEllipsoid() {
        Scene none = room().beginGroup("g").addMesh(QUAD, CARD).endGroup().build();
        assertThat(World.of(none).instances().count()).isZero();
        assertThat(World.of(none).uniqueTriangles()).isEqualTo(4);
        Scene ellipsoid = room().beginGroup("e").addSphere(new Vector3d(), 1, BALL).endGroup()
                .addInstance("e", Transform.scaling(1).scale(2, 0.5, 1).translate(0, 1, 0)).build();
        World w = World.of(ellipsoid);
        TraversalStack stack = new TraversalStack();
        SurfacePoint sp = new SurfacePoint();
        // Along x the ellipsoid reaches 2 from its centre, along y 0.5, along z 1: rays from outside along each axis.
        double[][] rays = {{10, 1, 0, -1, 0, 0, 8}, {0, 3.8, 0, 0, -1, 0, 2.3}, {0, 1, 10, 0, 0, -1, 9}};
        for (double[] r : rays) {
            Ray ray = new Ray().set(new Vector3d(r[0], r[1], r[2]), new Vector3d(r[3], r[4], r[5]), Double.POSITIVE_INFINITY);
            Hit hit = new Hit().reset();
            assertThat(w.bvh().intersect(ray, hit, stack, false)).isTrue();
            assertThat(hit.t).isCloseTo(r[6], org.assertj.core.data.Offset.offset(1e-9));
            w.surface(ray, hit, sp);
            assertThat(sp.ng.dot(new Vector3d(-r[3], -r[4], -r[5]))).isCloseTo(1, org.assertj.core.data.Offset.offset(1e-9));
        }
        // Off the axes the normal is the inverse transpose's: at (1, 1.25, √½) it is along (x/4, (y−1)/0.25, z).
        double z = Math.sqrt(0.5);
        Ray ray = new Ray().set(new Vector3d(1, 1.25, 5), new Vector3d(0, 0, -1), Double.POSITIVE_INFINITY);
        Hit hit = new Hit().reset();
        assertThat(w.bvh().intersect(ray, hit, stack, false)).isTrue();
        assertThat(hit.t).isCloseTo(5 - z, org.assertj.core.data.Offset.offset(1e-9));
        w.surface(ray, hit, sp);
        Vector3d expected = new Vector3d(0.25, 1, z).normalize();
        assertThat(sp.ng.dot(expected)).as("normal %s", sp.ng).isCloseTo(1, org.assertj.core.data.Offset.offset(1e-6));
    }
}
