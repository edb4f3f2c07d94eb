package dev.strahl.geometry;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.ChiSquare;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;

/**
 * Ray–triangle (Möller–Trumbore) and ray–sphere intersection, surface data and point sampling of
 * {@link Geometry}, and the self-intersection guard {@link SurfacePoint#spawnOrigin}.
 */
class GeometryTest {
    private static final double INF = Double.POSITIVE_INFINITY;

    // ---------------------------------------------------------------------------------------------
    // Fixtures

    /** One triangle per 9 floats, each with its own vertices; material of triangle i is 10 + i. */
    private static Geometry triangles(boolean closed, float... xyz) {
        return new MeshGeometry().addMesh(mesh(xyz), materials(xyz.length / 9), closed).build();
    }

    private static TriangleMesh mesh(float... xyz) {
        int[] idx = new int[xyz.length / 3];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        return new TriangleMesh(xyz, idx, null);
    }

    private static int[] materials(int count) {
        int[] m = new int[count];
        for (int i = 0; i < count; i++) {
            m[i] = 10 + i;
        }
        return m;
    }

    /** The unit right triangle (0,0,0), (1,0,0), (0,1,0) in the plane z = 0; its ng is +z. */
    private static final float[] UNIT = {0, 0, 0, 1, 0, 0, 0, 1, 0};

    private static Geometry sphere(double cx, double cy, double cz, double r) {
        return new MeshGeometry().addSphere(new Vector3d(cx, cy, cz), r, 7).build();
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray().set(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz).normalize(), INF);
    }

    private static Ray ray(Vector3dc o, Vector3dc d, double tMax) {
        return new Ray().set(o, new Vector3d(d).normalize(), tMax);
    }

    private static Vector3d randomDirection(SplittableRandom random) {
        return new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
    }

    private static Vector3d vertex(float[] xyz, int triangle, int k) {
        int o = 9 * triangle + 3 * k;
        return new Vector3d(xyz[o], xyz[o + 1], xyz[o + 2]);
    }

    private static Vector3d barycentricPoint(Vector3dc v0, Vector3dc v1, Vector3dc v2, double b1, double b2) {
        double b0 = 1 - b1 - b2;
        return new Vector3d(v0).mul(b0).add(new Vector3d(v1).mul(b1)).add(new Vector3d(v2).mul(b2));
    }

    private static Vector3d geometricNormal(Vector3dc v0, Vector3dc v1, Vector3dc v2) {
        return new Vector3d(v1).sub(v0).cross(new Vector3d(v2).sub(v0)).normalize();
    }

    /** A random triangle of float vertices that is not too thin, so its barycentrics are well conditioned. */
    private static float[] wellShapedTriangle(SplittableRandom random, double scale, double offset) {
        while (true) {
            float[] xyz = new float[9];
            for (int i = 0; i < 9; i++) {
                xyz[i] = (float) (offset + scale * random.nextDouble(-1, 1));
            }
            Vector3d v0 = new Vector3d(xyz[0], xyz[1], xyz[2]), v1 = new Vector3d(xyz[3], xyz[4], xyz[5]), v2 = new Vector3d(xyz[6], xyz[7], xyz[8]);
            double area2 = new Vector3d(v1).sub(v0).cross(new Vector3d(v2).sub(v0)).length();
            double longest = Math.max(v0.distance(v1), Math.max(v1.distance(v2), v2.distance(v0)));
            if (area2 > 0.3 * longest * longest) {
                return xyz;
            }
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Triangles

    @Test
    void triangleHitHasTheExactDistanceAndBarycentrics() {
        Geometry g = triangles(false, UNIT);
        Ray r = ray(0.25, 0.5, 2, 0, 0, -1);
        Hit hit = new Hit().reset();
        assertThat(g.intersect(0, r, hit, false)).isTrue();
        assertThat(hit.prim).isZero();
        assertThat(hit.t).isEqualTo(2);
        assertThat(r.tMax).as("tMax shortened to the hit").isEqualTo(2);
        assertThat(hit.b1).isEqualTo(0.25);
        assertThat(hit.b2).isEqualTo(0.5);
    }

    @Test
    void randomRaysAimedAtRandomTrianglesHitWhereAimed() {
        SplittableRandom random = new SplittableRandom(1);
        for (int i = 0; i < 2000; i++) {
            float[] xyz = wellShapedTriangle(random, 2, 0);
            Geometry g = triangles(false, xyz);
            Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
            Vector3d ng = geometricNormal(v0, v1, v2);
            double b1 = random.nextDouble(0.01, 0.98), b2 = random.nextDouble(0.01, 0.99 - b1);
            Vector3d target = barycentricPoint(v0, v1, v2, b1, b2);
            Vector3d d = randomDirection(random);
            if (Math.abs(d.dot(ng)) < 0.1) {
                continue;
            }
            double s = random.nextDouble(0.5, 3);
            Ray r = ray(new Vector3d(d).mul(-s).add(target), d, INF);
            Hit hit = new Hit().reset();
            assertThat(g.intersect(0, r, hit, false)).as("ray %s at triangle %d", r, i).isTrue();
            assertThat(hit.t).isCloseTo(s, within(1e-12));
            assertThat(hit.b1).isCloseTo(b1, within(1e-12));
            assertThat(hit.b2).isCloseTo(b2, within(1e-12));
            assertThat(g.occludes(0, ray(r.o, d, INF))).isTrue();
        }
    }

    @Test
    void raysJustBesideEachEdgeMissAndJustInsideHit() {
        SplittableRandom random = new SplittableRandom(2);
        double delta = 1e-6;
        for (int i = 0; i < 500; i++) {
            float[] xyz = wellShapedTriangle(random, 1, 0);
            Geometry g = triangles(false, xyz);
            Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
            Vector3d d = randomDirection(random);
            if (Math.abs(d.dot(geometricNormal(v0, v1, v2))) < 0.2) {
                continue;
            }
            double along = random.nextDouble(0.1, 0.9);
            for (int edge = 0; edge < 3; edge++) {
                for (double side : new double[] {-delta, delta}) {
                    // Barycentrics (b0, b1, b2) with b[edge] = side: just outside or inside the edge opposite vertex 'edge'.
                    double[] b = new double[3];
                    b[edge] = side;
                    b[(edge + 1) % 3] = (1 - side) * along;
                    b[(edge + 2) % 3] = (1 - side) * (1 - along);
                    Vector3d target = barycentricPoint(v0, v1, v2, b[1], b[2]);
                    Ray r = ray(new Vector3d(d).mul(-2).add(target), d, INF);
                    assertThat(g.intersect(0, r, new Hit().reset(), false))
                            .as("edge opposite v%d, offset %s", edge, side).isEqualTo(side > 0);
                }
            }
        }
    }

    /**
     * Behaviour on the boundary: the barycentric tests are inclusive (b ≥ 0, b1 + b2 ≤ 1), so a
     * ray exactly through a vertex or an edge hits, and both triangles sharing an edge report a
     * ray through it (no crack where exact arithmetic decides).
     */
    @Test
    void raysExactlyThroughVerticesAndEdgesHit() {
        Geometry g = triangles(false, UNIT);
        double[][] points = {{0, 0, 0, 0}, {1, 0, 1, 0}, {0, 1, 0, 1}, {0.5, 0, 0.5, 0}, {0, 0.5, 0, 0.5}, {0.5, 0.5, 0.5, 0.5}};
        for (double[] p : points) {
            Hit hit = new Hit().reset();
            assertThat(g.intersect(0, ray(p[0], p[1], 1, 0, 0, -1), hit, false)).as("through (%s, %s)", p[0], p[1]).isTrue();
            assertThat(hit.b1).isEqualTo(p[2]);
            assertThat(hit.b2).isEqualTo(p[3]);
        }
        assertThat(g.intersect(0, ray(Math.nextDown(0.0), 0.5, 1, 0, 0, -1), new Hit().reset(), false)).isFalse();
        assertThat(g.intersect(0, ray(0.5, 0.5 + 1e-15, 1, 0, 0, -1), new Hit().reset(), false)).isFalse();

        // A unit square as two triangles sharing the diagonal (1,0)–(0,1).
        Geometry square = triangles(false, 0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 1, 0, 0, 1, 1, 0, 0, 1, 0);
        for (double x : new double[] {0.25, 0.5, 0.75}) {
            for (int prim = 0; prim < 2; prim++) {
                assertThat(square.intersect(prim, ray(x, 1 - x, 1, 0, 0, -1), new Hit().reset(), false))
                        .as("triangle %d at diagonal point x = %s", prim, x).isTrue();
            }
        }
    }

    @Test
    void rayParallelToTheTrianglePlaneMissesWithoutNaN() {
        Geometry g = triangles(false, UNIT);
        Ray[] rays = {
            ray(-1, 0.25, 0, 1, 0, 0),         // in the plane, crossing the triangle
            ray(-1, -1, 0, 1, 1, 0),           // in the plane, through a vertex
            ray(-1, 0.25, 1e-9, 1, 0, 0),      // just above the plane
            ray(-1, 0.25, -0.5, 1, 0.3, 0),    // below the plane
        };
        for (Ray r : rays) {
            Hit hit = new Hit().reset();
            assertThat(g.intersect(0, r, hit, false)).as("%s", r).isFalse();
            assertThat(g.occludes(0, r)).isFalse();
            assertThat(hit.prim).isEqualTo(-1);
            assertThat(hit.t).isEqualTo(INF);
            assertThat(r.tMax).isEqualTo(INF);
        }
        // A tilted triangle: directions in its plane (up to round-off) passing just above or below it.
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 1000; i++) {
            float[] xyz = wellShapedTriangle(random, 1, 0);
            Geometry tilted = triangles(false, xyz);
            Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
            Vector3d ng = geometricNormal(v0, v1, v2);
            Vector3d d = new Vector3d(v1).sub(v0).normalize();
            Vector3d target = barycentricPoint(v0, v1, v2, 1 / 3.0, 1 / 3.0);
            for (double offset : new double[] {1e-6, -1e-6}) {
                Vector3d o = new Vector3d(d).mul(-3).add(target).add(new Vector3d(ng).mul(offset));
                Ray r = ray(o, d, INF);
                Hit hit = new Hit().reset();
                assertThat(tilted.intersect(0, r, hit, false)).as("parallel ray %s, offset %s", r, offset).isFalse();
                assertThat(tilted.occludes(0, r)).isFalse();
                assertThat(r.tMax).isEqualTo(INF);
            }
        }
    }

    @Test
    void hitsOutsideTheOpenIntervalZeroToTMaxAreIgnored() {
        Geometry g = triangles(false, UNIT);
        assertThat(g.intersect(0, ray(new Vector3d(0.25, 0.25, 2), new Vector3d(0, 0, -1), 1.999), new Hit().reset(), false))
                .as("beyond tMax").isFalse();
        assertThat(g.intersect(0, ray(new Vector3d(0.25, 0.25, 2), new Vector3d(0, 0, -1), 2), new Hit().reset(), false))
                .as("exactly at tMax (open interval)").isFalse();
        assertThat(g.occludes(0, ray(new Vector3d(0.25, 0.25, 2), new Vector3d(0, 0, -1), 1.999))).isFalse();
        assertThat(g.occludes(0, ray(new Vector3d(0.25, 0.25, 2), new Vector3d(0, 0, -1), 2.001))).isTrue();
        assertThat(g.intersect(0, ray(0.25, 0.25, 2, 0, 0, 1), new Hit().reset(), false)).as("behind the origin").isFalse();
        assertThat(g.intersect(0, ray(0.25, 0.25, 0, 0, 0, -1), new Hit().reset(), false)).as("at t = 0").isFalse();
        assertThat(g.occludes(0, ray(0.25, 0.25, 0, 0, 0, -1))).isFalse();
    }

    @Test
    void aHitShortensTMaxSoThatOnlyCloserHitsFollow() {
        // Triangle 0 at z = 0, triangle 1 at z = 1; the ray comes down from z = 3.
        Geometry g = triangles(false, 0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 0, 0, 1, 1, 0, 1, 0, 1, 1);
        Ray r = ray(0.25, 0.25, 3, 0, 0, -1);
        Hit hit = new Hit().reset();
        assertThat(g.intersect(0, r, hit, false)).isTrue();
        assertThat(r.tMax).isEqualTo(3);
        assertThat(g.intersect(1, r, hit, false)).as("closer hit replaces").isTrue();
        assertThat(hit.prim).isEqualTo(1);
        assertThat(r.tMax).isEqualTo(2);
        assertThat(g.intersect(0, r, hit, false)).as("farther hit ignored").isFalse();
        assertThat(hit.prim).isEqualTo(1);
        assertThat(hit.t).isEqualTo(2);
    }

    @Test
    void degenerateTrianglesAreSkippedAndCounted() {
        float[] xyz = {
            0, 0, 0, 1, 0, 0, 0, 1, 0,        // fine
            0, 0, 0, 1, 0, 0, 1, 0, 0,        // two equal vertices
            0, 0, 0, 1, 1, 1, 2, 2, 2,        // collinear
            3, 3, 3, 3, 3, 3, 3, 3, 3,        // a point
            0, 0, 5, 1, 0, 5, 0, 1, 5,        // fine
        };
        MeshGeometry builder = new MeshGeometry().addMesh(mesh(xyz), new int[] {0, 1, 2, 3, 4}, false);
        assertThat(builder.degenerateCount()).isEqualTo(3);
        builder.addMesh(mesh(0, 0, 0, 0, 0, 0, 1, 1, 1), new int[] {5}, false);
        assertThat(builder.degenerateCount()).isEqualTo(4);
        Geometry g = builder.build();
        assertThat(g.triangleCount()).isEqualTo(2);
        assertThat(g.material(0)).isZero();
        assertThat(g.material(1)).as("the kept triangles keep their own materials").isEqualTo(4);
        Hit hit = new Hit().reset();
        assertThat(g.intersect(1, ray(0.2, 0.2, 9, 0, 0, -1), hit, false)).isTrue();
        assertThat(hit.t).isEqualTo(4);
    }

    @Test
    void meshesAreAppendedWithTheirOwnVertices() {
        Geometry g = new MeshGeometry()
                .addMesh(mesh(UNIT), new int[] {3}, false)
                .addSphere(new Vector3d(0, 0, -10), 1, 9)
                .addMesh(new TriangleMesh(new float[] {5, 5, 1, 6, 5, 1, 5, 6, 1, 9, 9, 9}, new int[] {0, 1, 2}, null), new int[] {4}, true)
                .build();
        assertThat(g.triangleCount()).isEqualTo(2);
        assertThat(g.sphereCount()).isEqualTo(1);
        assertThat(g.primitiveCount()).isEqualTo(3);
        assertThat(g.isTriangle(1)).isTrue();
        assertThat(g.isTriangle(2)).as("spheres follow the triangles").isFalse();
        assertThat(g.material(1)).isEqualTo(4);
        assertThat(g.material(2)).isEqualTo(9);
        assertThat(g.isClosed(0)).isFalse();
        assertThat(g.isClosed(1)).isTrue();
        assertThat(g.isClosed(2)).isFalse();
        Hit hit = new Hit().reset();
        assertThat(g.intersect(1, ray(5.25, 5.25, 3, 0, 0, -1), hit, false)).isTrue();
        assertThat(hit.t).isEqualTo(2);
        Aabb box = g.bounds();
        assertThat(new double[] {box.minX, box.minY, box.minZ, box.maxX, box.maxY, box.maxZ})
                .as("bounds of all primitives, the unused vertex (9, 9, 9) excluded").containsExactly(-1, -1, -11, 6, 6, 1);
        assertThat(g.area(0)).isEqualTo(0.5);
        assertThat(g.area(2)).isCloseTo(4 * Math.PI, within(1e-12));
    }

    // ---------------------------------------------------------------------------------------------
    // Back-face culling

    @Test
    void backFacesAreCulledOnlyOnClosedTrianglesAndOnlyWhenAsked() {
        Geometry closed = triangles(true, UNIT), open = triangles(false, UNIT);
        // ng = +z: a ray going down meets the front face, a ray going up the back face.
        Ray front = ray(0.25, 0.25, 1, 0, 0, -1);
        Ray back = ray(0.25, 0.25, -1, 0, 0, 1);
        assertThat(closed.intersect(0, ray(front.o, front.d, INF), new Hit().reset(), true)).isTrue();
        assertThat(closed.intersect(0, ray(front.o, front.d, INF), new Hit().reset(), false)).isTrue();
        assertThat(closed.intersect(0, ray(back.o, back.d, INF), new Hit().reset(), true)).as("culled").isFalse();
        assertThat(closed.intersect(0, ray(back.o, back.d, INF), new Hit().reset(), false)).isTrue();
        assertThat(closed.occludes(0, ray(back.o, back.d, INF))).as("shadow rays never cull").isTrue();
        assertThat(open.intersect(0, ray(back.o, back.d, INF), new Hit().reset(), true)).as("open mesh: no culling").isTrue();
    }

    @Test
    void spheresAreNeverCulled() {
        Geometry g = sphere(0, 0, 0, 1);
        Hit hit = new Hit().reset();
        assertThat(g.intersect(0, ray(0, 0, 0, 0, 0, 1), hit, true)).as("from inside, a back face").isTrue();
        assertThat(hit.t).isEqualTo(1);
        assertThat(g.intersect(0, ray(0, 0, -5, 0, 0, 1), new Hit().reset(), true)).isTrue();
    }

    // ---------------------------------------------------------------------------------------------
    // Spheres

    @Test
    void sphereHitFromOutsideIsTheNearSide() {
        Geometry g = sphere(1, 2, 3, 2);
        Hit hit = new Hit().reset();
        Ray r = ray(1, 2, -7, 0, 0, 1);
        assertThat(g.intersect(0, r, hit, false)).isTrue();
        assertThat(hit.t).isCloseTo(8, within(1e-12));
        assertThat(r.tMax).isEqualTo(hit.t);
        assertThat(hit.prim).isZero();
        assertThat(g.intersect(0, ray(new Vector3d(1, 2, -7), new Vector3d(0, 0, 1), 7.9), new Hit().reset(), false))
                .as("near side beyond tMax: the far side is farther still").isFalse();
    }

    @Test
    void rayFromInsideTheSphereHitsTheFarSide() {
        Geometry g = sphere(1, 2, 3, 2);
        Hit hit = new Hit().reset();
        assertThat(g.intersect(0, ray(1.5, 2, 3, 1, 0, 0), hit, false)).isTrue();
        assertThat(hit.t).isCloseTo(1.5, within(1e-12));
        assertThat(g.intersect(0, ray(1.5, 2, 3, -1, 0, 0), hit.reset(), false)).isTrue();
        assertThat(hit.t).isCloseTo(2.5, within(1e-12));
        SplittableRandom random = new SplittableRandom(4);
        Vector3d p = new Vector3d();
        for (int i = 0; i < 1000; i++) {
            Vector3d o = randomDirection(random).mul(random.nextDouble(0, 1.99)).add(1, 2, 3);
            Ray r = ray(o, randomDirection(random), INF);
            assertThat(g.intersect(0, r, hit.reset(), false)).isTrue();
            assertThat(r.at(hit.t, p).distance(1, 2, 3)).isCloseTo(2, within(1e-12));
        }
    }

    @Test
    void sphereBehindBesideOrPassedMisses() {
        Geometry g = sphere(1, 2, 3, 2);
        assertThat(g.intersect(0, ray(1, 2, 10, 0, 0, 1), new Hit().reset(), false)).as("behind").isFalse();
        assertThat(g.intersect(0, ray(1, 2, 5.5, 0, 0, 1), new Hit().reset(), false)).as("just passed").isFalse();
        assertThat(g.intersect(0, ray(1, 4.01, -7, 0, 0, 1), new Hit().reset(), false)).as("beside").isFalse();
        assertThat(g.occludes(0, ray(1, 2, 10, 0, 0, 1))).isFalse();
        assertThat(g.occludes(0, ray(1, 2, -7, 0, 0, 1))).isTrue();
    }

    // ---------------------------------------------------------------------------------------------
    // Surface data

    @Test
    void triangleSurfaceHasTheUnitWindingNormalOnBothSides() {
        SplittableRandom random = new SplittableRandom(5);
        SurfacePoint sp = new SurfacePoint();
        for (int i = 0; i < 500; i++) {
            float[] xyz = wellShapedTriangle(random, 3, 0);
            Geometry g = triangles(false, xyz);
            Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
            Vector3d expectedNg = geometricNormal(v0, v1, v2);
            Vector3d target = barycentricPoint(v0, v1, v2, 0.3, 0.2);
            for (double side : new double[] {1, -1}) {
                Vector3d d = new Vector3d(expectedNg).mul(-side).add(randomDirection(random).mul(0.5)).normalize();
                Ray r = ray(new Vector3d(d).mul(-2).add(target), d, INF);
                Hit hit = new Hit().reset();
                assertThat(g.intersect(0, r, hit, false)).isTrue();
                g.surface(r, hit, sp);
                assertThat(sp.ng.length()).isCloseTo(1, within(1e-14));
                assertThat(sp.ng.distance(expectedNg)).as("ng from the winding, whichever side is hit").isCloseTo(0, within(1e-12));
                assertThat(sp.n).isEqualTo(sp.ng);
                assertThat(sp.p.distance(target)).isCloseTo(0, within(1e-12));
                assertThat(sp.p.distance(barycentricPoint(v0, v1, v2, hit.b1, hit.b2))).isZero();
                assertThat(sp.prim).isZero();
                assertThat(sp.material).isEqualTo(10);
            }
        }
    }

    @Test
    void shadingNormalInterpolatesVertexNormals() {
        float[] n = {0, 0, 1, 1, 0, 1, 0, 1, 2};     // not unit: only their interpolation's direction counts
        Geometry g = new MeshGeometry().addMesh(new TriangleMesh(UNIT, new int[] {0, 1, 2}, n), new int[] {0}, false).build();
        Ray r = ray(0.25, 0.5, 1, 0, 0, -1);
        Hit hit = new Hit().reset();
        g.intersect(0, r, hit, false);
        SurfacePoint sp = new SurfacePoint();
        g.surface(r, hit, sp);
        // b = (0.25, 0.25, 0.5): 0.25 (0,0,1) + 0.25 (1,0,1) + 0.5 (0,1,2) = (0.25, 0.5, 1.5).
        Vector3d expected = new Vector3d(0.25, 0.5, 1.5).normalize();
        assertThat(sp.n.distance(expected)).isCloseTo(0, within(1e-12));
        assertThat(sp.ng).isEqualTo(new Vector3d(0, 0, 1));
    }

    @Test
    void missingOrCancellingVertexNormalsFallBackToTheGeometricNormal() {
        float nan = Float.NaN;
        Geometry g = new MeshGeometry()
                .addMesh(mesh(UNIT), new int[] {0}, false)                                    // no normals at all
                .addMesh(new TriangleMesh(UNIT, new int[] {0, 1, 2}, new float[] {0, 0, 1, nan, nan, nan, 0, 0, 1}), new int[] {1}, false)
                .addMesh(new TriangleMesh(UNIT, new int[] {0, 1, 2}, new float[] {0, 0, 1, 0, 0, -1, 1, 0, 0}), new int[] {2}, false)
                .addMesh(new TriangleMesh(UNIT, new int[] {0, 1, 2}, new float[] {1, 0, 0, 1, 0, 0, 1, 0, 0}), new int[] {3}, false)
                .addMesh(mesh(UNIT), new int[] {4}, false)                                    // no normals, after some
                .build();
        SurfacePoint sp = new SurfacePoint();
        Vector3d up = new Vector3d(0, 0, 1);
        for (int prim = 0; prim < 5; prim++) {
            Ray r = prim == 2 ? ray(0.5, 0, 1, 0, 0, -1) : ray(0.25, 0.25, 1, 0, 0, -1);    // prim 2: on the edge where n0 + n1 = 0
            Hit hit = new Hit().reset();
            assertThat(g.intersect(prim, r, hit, false)).isTrue();
            g.surface(r, hit, sp);
            assertThat(sp.ng).isEqualTo(up);
            if (prim == 3) {
                assertThat(sp.n).as("complete normals are used").isEqualTo(new Vector3d(1, 0, 0));
            } else {
                assertThat(sp.n).as("prim %d", prim).isEqualTo(up);
            }
        }
    }

    @Test
    void sphereSurfaceNormalPointsOutwardAndThePointLiesOnTheSphere() {
        SplittableRandom random = new SplittableRandom(6);
        Geometry g = sphere(1, 2, 3, 2);
        Vector3d c = new Vector3d(1, 2, 3);
        SurfacePoint sp = new SurfacePoint();
        for (int i = 0; i < 1000; i++) {
            boolean inside = i % 2 == 0;
            Vector3d o = randomDirection(random).mul(inside ? random.nextDouble(0, 1.9) : random.nextDouble(2.5, 50)).add(c);
            Vector3d towards = randomDirection(random).mul(1.5).add(c).sub(o).normalize();
            Ray r = ray(o, towards, INF);
            Hit hit = new Hit().reset();
            assertThat(g.intersect(0, r, hit, false)).isTrue();
            g.surface(r, hit, sp);
            assertThat(sp.p.distance(c)).isCloseTo(2, within(1e-12));
            assertThat(sp.ng.length()).isCloseTo(1, within(1e-14));
            assertThat(sp.ng.distance(new Vector3d(sp.p).sub(c).div(2))).isCloseTo(0, within(1e-12));
            assertThat(sp.ng.dot(r.d)).as("outward: against the ray from outside, along it from inside")
                    .matches(cos -> inside ? cos > 0 : cos < 0);
            assertThat(sp.n).isEqualTo(sp.ng);
            assertThat(sp.material).isEqualTo(7);
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Point sampling

    @Test
    void sampledPointsLieOnTheirPrimitive() {
        float[] xyz = {1, 2, 3, 4, -1, 2, 0.5f, 0, 7};
        Geometry g = new MeshGeometry().addMesh(mesh(xyz), new int[] {5}, false)
                .addSphere(new Vector3d(-3, 1, 4), 0.75, 6).build();
        Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
        Vector3d ng = geometricNormal(v0, v1, v2);
        Vector3d e1 = new Vector3d(v1).sub(v0), e2 = new Vector3d(v2).sub(v0);
        SurfacePoint sp = new SurfacePoint();
        double[] us = {0, 1e-9, 0.3, 0.5, 0.99, Math.nextDown(1.0)};
        for (double u1 : us) {
            for (double u2 : us) {
                g.samplePoint(0, u1, u2, sp);
                Vector3d q = new Vector3d(sp.p).sub(v0);
                assertThat(q.dot(ng)).as("on the plane").isCloseTo(0, within(1e-12));
                // Barycentrics of p by Cramer's rule in the plane.
                double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2), q1 = q.dot(e1), q2 = q.dot(e2);
                double det = d11 * d22 - d12 * d12;
                double b1 = (d22 * q1 - d12 * q2) / det, b2 = (d11 * q2 - d12 * q1) / det;
                assertThat(b1).isGreaterThanOrEqualTo(-1e-12);
                assertThat(b2).isGreaterThanOrEqualTo(-1e-12);
                assertThat(b1 + b2).isLessThanOrEqualTo(1 + 1e-12);
                assertThat(sp.ng.distance(ng)).isCloseTo(0, within(1e-14));
                assertThat(sp.n).isEqualTo(sp.ng);
                assertThat(sp.material).isEqualTo(5);
                g.samplePoint(1, u1, u2, sp);
                assertThat(sp.p.distance(-3, 1, 4)).isCloseTo(0.75, within(1e-12));
                assertThat(sp.ng.distance(new Vector3d(sp.p).sub(-3, 1, 4).div(0.75))).isCloseTo(0, within(1e-12));
                assertThat(sp.prim).isEqualTo(1);
                assertThat(sp.material).isEqualTo(6);
            }
        }
    }

    @Test
    void sampledPointsAreUniformByArea() {
        Geometry g = new MeshGeometry().addMesh(mesh(UNIT), new int[] {0}, false)
                .addSphere(new Vector3d(5, 6, 7), 3, 0).build();
        SurfacePoint sp = new SurfacePoint();
        double alpha = ChiSquare.sidak(0.01, 2);
        // On the unit triangle p = (b1, b2, 0): uniform means density 2 over the (b1, b2) triangle.
        ChiSquare.test2d((u1, u2, p) -> {
            g.samplePoint(0, u1, u2, sp);
            p.set(sp.p.x, sp.p.y);
            return true;
        }, (x, y) -> 2, ChiSquare.Chart.unitTriangle(), 10, 10, 500_000, 7).assertAccepted(alpha);
        // On a sphere, uniform by area means a uniform direction of the normal.
        ChiSquare.test((u1, u2, w) -> {
            g.samplePoint(1, u1, u2, sp);
            w.set(sp.ng);
            return true;
        }, w -> 1 / (4 * Math.PI), 500_000, 8).assertAccepted(alpha);
    }

    // ---------------------------------------------------------------------------------------------
    // Leaving a surface

    /**
     * Rays leaving a hit point from {@code spawnOrigin} never hit the triangle they start on, for
     * all directions including grazing ones, near the origin and far from it at large scale.
     */
    @Test
    void spawnedRaysDoNotReHitTheirTriangle() {
        SplittableRandom random = new SplittableRandom(9);
        double[][] placements = {{1, 0}, {1, 1e4}, {1e3, 1e4}, {1e-3, 1}, {10, -3e4}};
        SurfacePoint sp = new SurfacePoint();
        Vector3d o = new Vector3d();
        for (double[] placement : placements) {
            double scale = placement[0], offset = placement[1];
            for (int i = 0; i < 100; i++) {
                float[] xyz = wellShapedTriangle(random, scale, offset);
                Geometry g = triangles(i % 2 == 0, xyz);
                Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
                Vector3d target = barycentricPoint(v0, v1, v2, random.nextDouble(0, 0.5), random.nextDouble(0, 0.5));
                Vector3d d = randomDirection(random);
                Ray r = ray(new Vector3d(d).mul(-scale * random.nextDouble(0.1, 10)).add(target), d, INF);
                Hit hit = new Hit().reset();
                if (!g.intersect(0, r, hit, false)) {
                    continue;                        // aimed at a grazing angle and slipped past: no hit to leave
                }
                g.surface(r, hit, sp);
                for (int k = 0; k < 200; k++) {
                    Vector3d dir = leavingDirection(random, sp.ng, k);
                    sp.spawnOrigin(dir, o);
                    Ray out = ray(o, dir, INF);
                    Hit again = new Hit().reset();
                    assertThat(g.intersect(0, out, again, false))
                            .as("re-hit at t = %s leaving %s (scale %s at %s) towards %s", again.t, sp.p, scale, offset, dir).isFalse();
                    assertThat(g.occludes(0, ray(o, dir, INF))).isFalse();
                }
            }
        }
    }

    /**
     * Leaving a sphere outwards never hits it again; inwards it hits the far side, never the
     * point it left (any hit is at least the spawn offset away, and on the sphere).
     */
    @Test
    void spawnedRaysDoNotReHitTheirSphere() {
        SplittableRandom random = new SplittableRandom(10);
        double[][] placements = {{1, 0}, {1, 1e4}, {1e3, 1e4}, {0.1, 1e3}, {5e3, -2e4}};
        SurfacePoint sp = new SurfacePoint();
        Vector3d o = new Vector3d(), p = new Vector3d();
        for (double[] placement : placements) {
            double radius = placement[0];
            Vector3d c = new Vector3d(placement[1], -placement[1] / 2, placement[1] / 3);
            Geometry g = sphere(c.x, c.y, c.z, radius);
            for (int i = 0; i < 100; i++) {
                Vector3d from = randomDirection(random).mul(radius * random.nextDouble(0, 5)).add(c);
                Ray r = ray(from, randomDirection(random), INF);
                Hit hit = new Hit().reset();
                if (!g.intersect(0, r, hit, false)) {
                    continue;
                }
                g.surface(r, hit, sp);
                for (int k = 0; k < 200; k++) {
                    Vector3d dir = leavingDirection(random, sp.ng, k);
                    sp.spawnOrigin(dir, o);
                    Ray out = ray(o, dir, INF);
                    Hit again = new Hit().reset();
                    boolean found = g.intersect(0, out, again, false);
                    if (dir.dot(sp.ng) >= 0) {
                        assertThat(found).as("outward re-hit at t = %s from %s towards %s", again.t, sp.p, dir).isFalse();
                    } else {
                        double depth = radius - o.distance(c);            // how far inside the origin was moved
                        assertThat(found).as("inward ray must reach the far side").isTrue();
                        assertThat(again.t).as("far side, not the start point").isGreaterThan(0.99 * depth);
                        assertThat(out.at(again.t, p).distance(c)).isCloseTo(radius, within(1e-9 * (radius + c.length())));
                    }
                }
            }
        }
    }

    /**
     * The hardest case for a relative offset: a large triangle whose hit point is near the origin,
     * so the offset is tiny (~1e-6) while the triangle reaches 1e3 away. A ray leaving at a grazing
     * angle must still not come back to it, which needs ng to agree with the plane the
     * intersection test uses to far better than 1e-6/1e3.
     */
    @Test
    void spawnedRaysDoNotReHitALargeTriangleNearTheOrigin() {
        SplittableRandom random = new SplittableRandom(11);
        SurfacePoint sp = new SurfacePoint();
        Vector3d o = new Vector3d();
        for (int i = 0; i < 200; i++) {
            // Vertices around a point c near the origin: c + a, c + b, c - a - b with |a|, |b| ~ 1e3.
            Vector3d c = randomDirection(random).mul(random.nextDouble(0, 1));
            Vector3d a = randomDirection(random).mul(1e3), b = randomDirection(random).mul(1e3);
            if (new Vector3d(a).cross(b).length() < 0.5e6) {
                continue;
            }
            float[] xyz = new float[9];
            Vector3d[] v = {new Vector3d(c).add(a), new Vector3d(c).add(b), new Vector3d(c).sub(a).sub(b)};
            for (int k = 0; k < 3; k++) {
                xyz[3 * k] = (float) v[k].x;
                xyz[3 * k + 1] = (float) v[k].y;
                xyz[3 * k + 2] = (float) v[k].z;
            }
            Geometry g = triangles(false, xyz);
            Vector3d v0 = vertex(xyz, 0, 0), v1 = vertex(xyz, 0, 1), v2 = vertex(xyz, 0, 2);
            Vector3d target = barycentricPoint(v0, v1, v2, 1 / 3.0, 1 / 3.0);
            Vector3d d = new Vector3d(geometricNormal(v0, v1, v2)).negate().add(randomDirection(random).mul(0.5)).normalize();
            Ray r = ray(new Vector3d(d).mul(-5).add(target), d, INF);
            Hit hit = new Hit().reset();
            assertThat(g.intersect(0, r, hit, false)).isTrue();
            g.surface(r, hit, sp);
            for (int k = 0; k < 200; k++) {
                Vector3d dir = leavingDirection(random, sp.ng, 2 * k + 1);
                sp.spawnOrigin(dir, o);
                Hit again = new Hit().reset();
                assertThat(g.intersect(0, ray(o, dir, INF), again, false))
                        .as("re-hit at t = %s leaving %s towards %s", again.t, sp.p, dir).isFalse();
            }
        }
    }

    /** Directions around a normal: uniform on the sphere, or grazing with a tiny normal component of either sign. */
    private static Vector3d leavingDirection(SplittableRandom random, Vector3dc ng, int k) {
        if (k % 2 == 0) {
            return randomDirection(random);
        }
        Vector3d tangent = randomDirection(random).cross(ng).normalize();
        double[] tilts = {1e-3, -1e-3, 1e-6, -1e-6, 1e-9, -1e-9, 0};
        return tangent.add(new Vector3d(ng).mul(tilts[random.nextInt(tilts.length)])).normalize();
    }
}
