package dev.strahl.camera;

import dev.strahl.scene.TestScenes;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.Camera;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.scene.TriangleMesh;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;

/**
 * The pinhole camera against the convention of DESIGN.md §3, written out independently here:
 * f = normalize(target − origin), r = normalize(f × up), u = r × f, t = tan(vfov/2),
 * dir = normalize(f + (2px/W − 1)·t·(W/H)·r + (1 − 2py/H)·t·u), film y growing downwards.
 */
class CameraTest {
    /** The camera of Cornell Original / Mirror / Empty-RG. */
    private static final Camera ORIGINAL = new Camera(new Vector3d(0, 1, 3.9), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40);

    private static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    /** The DESIGN §3 formula, evaluated with JOML, independent of {@link CameraRays}. */
    private static Vector3d designDirection(Camera c, int w, int h, double px, double py) {
        Vector3d f = new Vector3d(c.lookAt()).sub(c.lookFrom()).normalize();
        Vector3d r = f.cross(c.up(), new Vector3d()).normalize();
        Vector3d u = r.cross(f, new Vector3d());
        double t = Math.tan(Math.toRadians(c.fovDegrees()) / 2);
        return new Vector3d(f)
                .add(r.mul((2 * px / w - 1) * t * w / h))
                .add(u.mul((1 - 2 * py / h) * t))
                .normalize();
    }

    private static Ray ray(Camera c, int w, int h, double px, double py) {
        Ray ray = new Ray();
        Meshes.rays(c, w, h).generate(px, py, ray);
        return ray;
    }

    private static Vector3d viewDirection(Camera c) {
        return new Vector3d(c.lookAt()).sub(c.lookFrom()).normalize();
    }

    private static void assertDirection(Vector3dc actual, Vector3dc expected, String what) {
        assertThat(actual.distance(expected)).as("%s: got %s, expected %s", what, actual, expected).isLessThan(1e-12);
    }

    // ---------------------------------------------------------------------------------------------
    // The formula

    @Test
    void centrePixelRayIsTheViewDirection() {
        for (int[] size : new int[][] {{512, 512}, {640, 360}, {300, 700}, {1, 1}}) {
            Ray r = ray(ORIGINAL, size[0], size[1], size[0] / 2.0, size[1] / 2.0);
            assertDirection(r.d, v(0, 0, -1), "centre ray of " + size[0] + "x" + size[1]);
        }
        Camera oblique = new Camera(v(1, 2, 3), v(-2, 0.5, 1), v(0.2, 1, -0.1), 55);
        assertDirection(ray(oblique, 800, 600, 400, 300).d, viewDirection(oblique), "centre ray of an oblique camera");
    }

    @Test
    void raysStartAtTheOriginWithUnitDirectionAndInfiniteReach() {
        Ray r = ray(ORIGINAL, 512, 512, 17.25, 400.5);
        assertThat(r.o).isEqualTo(v(0, 1, 3.9));
        assertThat(r.d.length()).isCloseTo(1, within(1e-14));
        assertThat(r.tMax).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @Test
    void filmCornersFollowTheDesignFormula() {
        double t = Math.tan(Math.toRadians(20));
        double aspect = 640.0 / 360;
        // Original camera: f = -z, r = +x, u = +y.
        assertDirection(ray(ORIGINAL, 640, 360, 0, 0).d, v(-t * aspect, t, -1).normalize(), "top-left corner");
        assertDirection(ray(ORIGINAL, 640, 360, 640, 0).d, v(t * aspect, t, -1).normalize(), "top-right corner");
        assertDirection(ray(ORIGINAL, 640, 360, 0, 360).d, v(-t * aspect, -t, -1).normalize(), "bottom-left corner");
        assertDirection(ray(ORIGINAL, 640, 360, 640, 360).d, v(t * aspect, -t, -1).normalize(), "bottom-right corner");
    }

    @Test
    void everyFilmPointFollowsTheDesignFormulaForArbitraryCameras() {
        SplittableRandom random = new SplittableRandom(11);
        for (int k = 0; k < 200; k++) {
            Vector3d from = v(random.nextDouble(-5, 5), random.nextDouble(-5, 5), random.nextDouble(-5, 5));
            Vector3d at = v(random.nextDouble(-5, 5), random.nextDouble(-5, 5), random.nextDouble(-5, 5));
            // An up vector that is not perpendicular to the view direction: u = r × f must fix that.
            Vector3d up = v(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            Camera c = new Camera(from, at, up, random.nextDouble(5, 120));
            int w = 1 + random.nextInt(1000), h = 1 + random.nextInt(1000);
            double px = random.nextDouble() * w, py = random.nextDouble() * h;
            assertDirection(ray(c, w, h, px, py).d, designDirection(c, w, h, px, py), "camera " + c + " at " + px + ", " + py);
        }
    }

    @Test
    void filmYGrowsDownwardsAndXToTheRight() {
        Ray top = ray(ORIGINAL, 512, 512, 256, 0.5);
        Ray bottom = ray(ORIGINAL, 512, 512, 256, 511.5);
        Ray left = ray(ORIGINAL, 512, 512, 0.5, 256);
        Ray right = ray(ORIGINAL, 512, 512, 511.5, 256);
        assertThat(top.d.y).as("row 0 looks up").isGreaterThan(0);
        assertThat(bottom.d.y).as("the last row looks down").isLessThan(0);
        assertThat(left.d.x).as("column 0 looks left (-x for this camera)").isLessThan(0);
        assertThat(right.d.x).isGreaterThan(0);
    }

    @Test
    void verticalFieldOfViewIsTheFullAngleBetweenTopAndBottomEdges() {
        for (double fov : new double[] {1, 40, 90, 150}) {
            Camera c = ORIGINAL.withFov(fov);
            // A wide film: the vertical angle must not depend on the aspect ratio.
            Ray top = ray(c, 1000, 250, 500, 0);
            Ray bottom = ray(c, 1000, 250, 500, 250);
            assertThat(Math.toDegrees(top.d.angle(bottom.d))).as("vfov %s", fov).isCloseTo(fov, within(1e-9));
        }
    }

    @Test
    void aspectRatioWidensTheHorizontalNotTheVertical() {
        double t = Math.tan(Math.toRadians(20));
        for (int[] size : new int[][] {{1024, 512}, {512, 1024}, {512, 512}}) {
            double aspect = (double) size[0] / size[1];
            Ray rightEdge = ray(ORIGINAL, size[0], size[1], size[0], size[1] / 2.0);
            Ray topEdge = ray(ORIGINAL, size[0], size[1], size[0] / 2.0, 0);
            assertThat(Math.tan(rightEdge.d.angle(v(0, 0, -1)))).as("horizontal half-angle, %sx%s", size[0], size[1])
                    .isCloseTo(t * aspect, within(1e-12));
            assertThat(Math.tan(topEdge.d.angle(v(0, 0, -1)))).as("vertical half-angle, %sx%s", size[0], size[1])
                    .isCloseTo(t, within(1e-12));
        }
    }

    // ---------------------------------------------------------------------------------------------
    // The DESIGN check on Cornell Original

    /** The light quad of Cornell Original as two triangles (the winding of the OBJ: facing down). */
    private static Geometry lightQuad() {
        float[] p = {-0.24f, 1.98f, 0.16f, -0.24f, 1.98f, -0.22f, 0.23f, 1.98f, -0.22f, 0.23f, 1.98f, 0.16f};
        return new MeshGeometry().addMesh(new TriangleMesh(p, new int[] {0, 1, 2, 0, 2, 3}, null), new int[] {0, 0}, false).build();
    }

    private static boolean hits(Geometry g, Ray ray) {
        Hit hit = new Hit().reset();
        boolean any = false;
        for (int prim = 0; prim < g.primitiveCount(); prim++) {
            any |= g.intersect(prim, ray, hit, false);
        }
        return any;
    }

    /**
     * DESIGN §3: "at 512×512 the light quad of Original covers pixels x ∈ [211, 299), y ∈ [71, 89)".
     * Through pixel centres the quad is seen in exactly x ∈ [211, 299), y ∈ [72, 89): the quad's
     * near edge projects to py = 71.70, so row 71 is covered only in its lower 30 % and its centre
     * (71.5) misses; the Mitsuba reference shows the same (row 71 at ≈ 30 % of the light's value).
     * {@link #lightQuadCoversThirtyPercentOfRow71} checks that part.
     */
    @Test
    void lightQuadOfCornellOriginalProjectsOntoTheDesignPixels() {
        Geometry light = lightQuad();
        CameraRays rays = Meshes.rays(ORIGINAL, 512, 512);
        Ray ray = new Ray();
        int minX = Integer.MAX_VALUE, maxX = -1, minY = Integer.MAX_VALUE, maxY = -1;
        for (int y = 0; y < 512; y++) {
            for (int x = 0; x < 512; x++) {
                rays.generate(x + 0.5, y + 0.5, ray);
                if (hits(light, ray)) {
                    minX = Math.min(minX, x);
                    maxX = Math.max(maxX, x);
                    minY = Math.min(minY, y);
                    maxY = Math.max(maxY, y);
                }
            }
        }
        assertThat(new int[] {minX, maxX + 1}).as("columns [from, to) whose centre sees the light").containsExactly(211, 299);
        assertThat(new int[] {minY, maxY + 1}).as("rows [from, to) whose centre sees the light").containsExactly(72, 89);
    }

    @Test
    void lightQuadCoversThirtyPercentOfRow71() {
        Geometry light = lightQuad();
        CameraRays rays = Meshes.rays(ORIGINAL, 512, 512);
        Ray ray = new Ray();
        int n = 64;
        double[] coverage = new double[4];
        int[] rows = {70, 71, 88, 89};
        for (int k = 0; k < rows.length; k++) {
            int covered = 0;
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    rays.generate(255 + (i + 0.5) / n, rows[k] + (j + 0.5) / n, ray);
                    covered += hits(light, ray) ? 1 : 0;
                }
            }
            coverage[k] = (double) covered / (n * n);
        }
        assertThat(coverage[0]).as("row 70").isZero();
        assertThat(coverage[1]).as("row 71: the near edge at py = 71.70").isCloseTo(0.30, within(0.02));
        assertThat(coverage[2]).as("row 88: the far edge at py = 88.70").isCloseTo(0.70, within(0.02));
        assertThat(coverage[3]).as("row 89").isZero();
    }

    @Test
    void redWallIsOnTheLeftAndGreenWallOnTheRight() {
        // Red wall x = -1 (material 1), green wall x = +1 (material 2), both spanning the room. The
        // outermost columns look past the open front (z = 0.99), so the rays go through columns 60 and 451.
        float[] p = {
            -1, 0, 0.99f, -1, 1.99f, 0.99f, -1, 1.99f, -1.04f, -1, 0, -1.04f,
            1, 0, 0.99f, 1, 1.99f, 0.99f, 1, 1.99f, -1.04f, 1, 0, -1.04f};
        int[] idx = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
        Geometry walls = new MeshGeometry().addMesh(new TriangleMesh(p, idx, null), new int[] {1, 1, 2, 2}, false).build();
        assertThat(materialSeen(walls, ray(ORIGINAL, 512, 512, 60.5, 256.5))).as("left part of the image").isEqualTo(1);
        assertThat(materialSeen(walls, ray(ORIGINAL, 512, 512, 451.5, 256.5))).as("right part of the image").isEqualTo(2);
    }

    private static int materialSeen(Geometry g, Ray ray) {
        Hit hit = new Hit().reset();
        for (int prim = 0; prim < g.primitiveCount(); prim++) {
            g.intersect(prim, ray, hit, false);
        }
        return hit.found() ? g.material(hit.prim) : -1;
    }

    // ---------------------------------------------------------------------------------------------
    // framing

    /** Film coordinates of a world point, by inverting the DESIGN formula; NaN if behind the camera. */
    private static double[] project(Camera c, int w, int h, Vector3dc point) {
        Vector3d f = viewDirection(c);
        Vector3d r = f.cross(c.up(), new Vector3d()).normalize();
        Vector3d u = r.cross(f, new Vector3d());
        double t = Math.tan(Math.toRadians(c.fovDegrees()) / 2);
        Vector3d d = new Vector3d(point).sub(c.lookFrom());
        double z = d.dot(f);
        if (!(z > 0)) {
            return new double[] {Double.NaN, Double.NaN};
        }
        double sx = d.dot(r) / (z * t * w / h);
        double sy = d.dot(u) / (z * t);
        return new double[] {(sx + 1) * w / 2, (1 - sy) * h / 2};
    }

    private static Aabb box(double x0, double y0, double z0, double x1, double y1, double z1) {
        return new Aabb().include(x0, y0, z0).include(x1, y1, z1);
    }

    /**
     * {@code framing} fits the box's bounding sphere into the VERTICAL field of view, so it sees the
     * whole box on films at least as wide as tall (on portrait films the horizontal view is
     * narrower than the vertical one and wide boxes can be cut; see the class report).
     */
    @Test
    void framingSeesEveryCornerOfTheBox() {
        Aabb[] boxes = {
            box(-1, 0, -1.04, 1, 1.99, 0.99),          // the Cornell box
            box(-0.5, -0.5, -0.5, 0.5, 0.5, 0.5),
            box(10, 20, 30, 10.001, 20.001, 30.001),  // tiny and far from the origin
            box(-100, -1, -1, 100, 1, 1),              // long along x
            box(-1, -100, -1, 1, 100, 1),              // tall
            box(-1, -1, -100, 1, 1, 100),              // deep along the view axis
            box(3, 3, 3, 3, 3, 3)};                    // a single point
        for (Aabb b : boxes) {
            for (double fov : new double[] {10, 40, 90, 170}) {
                Camera c = TestScenes.framing(b, fov);
                for (int[] size : new int[][] {{512, 512}, {1920, 1080}}) {
                    for (int corner = 0; corner < 8; corner++) {
                        Vector3d p = v((corner & 1) == 0 ? b.minX : b.maxX, (corner & 2) == 0 ? b.minY : b.maxY,
                                (corner & 4) == 0 ? b.minZ : b.maxZ);
                        double[] film = project(c, size[0], size[1], p);
                        assertThat(film[0]).as("x of corner %s of %s, fov %s, %sx%s", p, b, fov, size[0], size[1])
                                .isBetween(0.0, (double) size[0]);
                        assertThat(film[1]).as("y of corner %s of %s, fov %s, %sx%s", p, b, fov, size[0], size[1])
                                .isBetween(0.0, (double) size[1]);
                        // The projection is the inverse of the ray generator: the ray through it meets the corner.
                        Ray ray = ray(c, size[0], size[1], film[0], film[1]);
                        Vector3d toCorner = new Vector3d(p).sub(ray.o);
                        assertThat(toCorner.cross(ray.d, new Vector3d()).length()).isLessThan(1e-9 * (1 + toCorner.length()));
                    }
                }
            }
        }
    }

    @Test
    void framingAnEmptyBoxGivesAValidCamera() {
        Camera c = TestScenes.framing(new Aabb(), 40);
        assertThat(c.fovDegrees()).isEqualTo(40);
        assertThat(c.lookFrom().isFinite()).isTrue();
    }

    // ---------------------------------------------------------------------------------------------
    // Validation and immutability

    @Test
    void refusesFieldsOfViewOutsideZeroTo180() {
        for (double fov : new double[] {0, -10, 180, 200, Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThatThrownBy(() -> ORIGINAL.withFov(fov)).as("fov %s", fov)
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("field of view");
        }
        assertThat(ORIGINAL.withFov(179.9).fovDegrees()).isEqualTo(179.9);
        assertThat(ORIGINAL.withFov(1e-3).fovDegrees()).isEqualTo(1e-3);
    }

    @Test
    void refusesCoincidentPositionAndTarget() {
        assertThatThrownBy(() -> new Camera(v(1, 2, 3), v(1, 2, 3), v(0, 1, 0), 40))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("coincide");
    }

    @Test
    void refusesUpParallelToTheViewDirection() {
        for (Vector3d up : new Vector3d[] {v(0, 1, 0), v(0, -3, 0), v(0, 0, 0)}) {
            assertThatThrownBy(() -> new Camera(v(0, 5, 0), v(0, 0, 0), up, 40)).as("up %s", up)
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("parallel");
        }
        // Oblique view direction, up along it.
        assertThatThrownBy(() -> new Camera(v(1, 1, 1), v(2, 3, 4), v(1, 2, 3), 40))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("parallel");
    }

    @Test
    void refusesNonFiniteVectors() {
        double nan = Double.NaN, inf = Double.POSITIVE_INFINITY;
        Vector3d ok = v(0, 0, 0);
        assertThatThrownBy(() -> new Camera(v(nan, 0, 1), ok, v(0, 1, 0), 40)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("finite");
        assertThatThrownBy(() -> new Camera(v(0, 0, 1), v(0, inf, 0), v(0, 1, 0), 40)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("finite");
        assertThatThrownBy(() -> new Camera(v(0, 0, 1), ok, v(0, -inf, 0), 40)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("finite");
    }

    @Test
    void refusesEmptyFilm() {
        assertThatThrownBy(() -> Meshes.rays(ORIGINAL, 0, 10)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> Meshes.rays(ORIGINAL, 10, -1)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void copiesTheCallersVectors() {
        Vector3d from = v(0, 1, 3.9), at = v(0, 1, 0), up = v(0, 1, 0);
        Camera c = new Camera(from, at, up, 40);
        Ray before = ray(c, 64, 64, 3.5, 60.25);
        from.set(7, 7, 7);
        at.set(-1, -2, -3);
        up.set(1, 0, 0);
        assertThat(c.lookFrom()).isEqualTo(v(0, 1, 3.9));
        assertThat(c.lookAt()).isEqualTo(v(0, 1, 0));
        assertThat(c.up()).isEqualTo(v(0, 1, 0));
        Ray after = ray(c, 64, 64, 3.5, 60.25);
        assertThat(after.o).isEqualTo(before.o);
        assertThat(after.d).isEqualTo(before.d);
    }

    @Test
    void withFovKeepsThePose() {
        Camera wide = ORIGINAL.withFov(90);
        assertThat(wide).isEqualTo(new Camera(v(0, 1, 3.9), v(0, 1, 0), v(0, 1, 0), 90));
    }
}
