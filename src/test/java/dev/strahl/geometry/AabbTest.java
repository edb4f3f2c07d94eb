package dev.strahl.geometry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class AabbTest {

    private static Aabb box(double x0, double y0, double z0, double x1, double y1, double z1) {
        return new Aabb().include(x0, y0, z0).include(x1, y1, z1);
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        return new Ray().set(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz).normalize(), tMax);
    }

    @Test
    void newBoxIsEmptyWithZeroAreaAndDiagonal() {
        Aabb box = new Aabb();
        assertThat(box.isEmpty()).isTrue();
        assertThat(box.area()).isZero();
        assertThat(box.diagonal()).isZero();
        assertThat(box.intersects(ray(0, 0, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).isFalse();
    }

    @Test
    void includeGrowsToTheSmallestEnclosingBox() {
        Aabb box = new Aabb().include(1, 2, 3);
        assertThat(box.isEmpty()).isFalse();
        assertThat(box.area()).isZero();
        box.include(-1, 5, 3).include(0, 0, 4);
        assertThat(new double[] {box.minX, box.minY, box.minZ, box.maxX, box.maxY, box.maxZ})
                .containsExactly(-1, 0, 3, 1, 5, 4);
        Aabb other = box(10, -10, 3.5, 11, -9, 3.6);
        box.include(other);
        assertThat(new double[] {box.minX, box.minY, box.minZ, box.maxX, box.maxY, box.maxZ})
                .containsExactly(-1, -10, 3, 11, 5, 4);
        assertThat(box.include(new Aabb()).maxX).as("including an empty box changes nothing").isEqualTo(11);
        assertThat(box.extent(0)).isEqualTo(12);
        assertThat(box.min(1)).isEqualTo(-10);
        assertThat(box.max(2)).isEqualTo(4);
        assertThat(box.reset().isEmpty()).isTrue();
    }

    @Test
    void areaAndDiagonalOfABox() {
        Aabb box = box(0, 0, 0, 1, 2, 3);
        assertThat(box.area()).isEqualTo(2 * (1 * 2 + 2 * 3 + 3 * 1));
        assertThat(box.diagonal()).isCloseTo(Math.sqrt(14), within(1e-15));
        Aabb flat = box(0, 0, 5, 2, 3, 5);
        assertThat(flat.area()).as("a flat box has the area of both faces").isEqualTo(12);
    }

    @Test
    void rayThroughTheBoxIntersects() {
        Aabb box = box(-1, -1, -1, 1, 1, 1);
        assertThat(box.intersects(ray(-5, 0.3, 0.2, 1, 0, 0, Double.POSITIVE_INFINITY))).isTrue();
        assertThat(box.intersects(ray(-5, -5, -5, 1, 1, 1, Double.POSITIVE_INFINITY))).isTrue();
        assertThat(box.intersects(ray(0, 0, 0, 0.3, -0.4, 0.5, 1e-9))).as("origin inside").isTrue();
    }

    @Test
    void rayBesideBehindOrShortOfTheBoxMisses() {
        Aabb box = box(-1, -1, -1, 1, 1, 1);
        assertThat(box.intersects(ray(-5, 1.5, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).as("beside").isFalse();
        assertThat(box.intersects(ray(5, 0, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).as("behind").isFalse();
        assertThat(box.intersects(ray(-5, 0, 0, 1, 0, 0, 3.9))).as("tMax short of the box").isFalse();
        assertThat(box.intersects(ray(-5, 0, 0, 1, 0, 0, 4.1))).as("tMax inside the box").isTrue();
        assertThat(box.intersects(ray(-3, 0, -3, 1, 0, 2.5, Double.POSITIVE_INFINITY))).as("past an edge").isFalse();
    }

    /**
     * A ray lying in the plane of a face gives 0·∞ = NaN in that slab, which the test ignores: the
     * ray counts as intersecting (conservative, boundary inclusive) when it crosses the face.
     */
    @Test
    void rayAlongAFacePlaneIntersectsIffItCrossesTheFace() {
        Aabb box = box(-1, -1, -1, 1, 1, 1);
        assertThat(box.intersects(ray(-5, 1, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).as("in the top face plane").isTrue();
        assertThat(box.intersects(ray(-5, -1, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).as("in the bottom face plane").isTrue();
        assertThat(box.intersects(ray(-1, -1, -5, 0, 0, 1, Double.POSITIVE_INFINITY))).as("along an edge").isTrue();
        assertThat(box.intersects(ray(-5, 1, 2, 1, 0, 0, Double.POSITIVE_INFINITY))).as("in the face plane, beside the face").isFalse();
        assertThat(box.intersects(ray(5, 1, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).as("in the face plane, leaving").isFalse();
        Aabb flat = box(0, 0, 0, 1, 1, 0);
        assertThat(flat.intersects(ray(0.5, 0.5, 2, 0, 0, -1, Double.POSITIVE_INFINITY))).as("through a flat box").isTrue();
        assertThat(flat.intersects(ray(-1, 0.5, 0, 1, 0, 0, Double.POSITIVE_INFINITY))).as("within a flat box's plane").isTrue();
    }

    @Test
    void slabTestAgreesWithPointSampling() {
        // A ray intersects iff some point o + t d, 0 < t < tMax, lies in the box: check against
        // dense sampling of the segment, away from grazing cases.
        SplittableRandom random = new SplittableRandom(1);
        Aabb box = box(-1, -0.5, -0.25, 1, 0.5, 0.25);
        Vector3d p = new Vector3d();
        int agreed = 0;
        for (int i = 0; i < 2000; i++) {
            Vector3d o = new Vector3d(random.nextDouble(-3, 3), random.nextDouble(-3, 3), random.nextDouble(-3, 3));
            Vector3d d = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
            Ray r = new Ray().set(o, d, random.nextDouble(0, 8));
            double deepest = Double.NEGATIVE_INFINITY;   // how far inside the box the segment gets
            for (int k = 1; k < 4000; k++) {
                r.at(r.tMax * k / 4000, p);
                double inside = Math.min(Math.min(Math.min(p.x - box.minX, box.maxX - p.x), Math.min(p.y - box.minY, box.maxY - p.y)),
                        Math.min(p.z - box.minZ, box.maxZ - p.z));
                deepest = Math.max(deepest, inside);
            }
            if (Math.abs(deepest) < 1e-2) {
                continue;                               // grazing: sampling cannot decide
            }
            assertThat(box.intersects(r)).as("%s", r).isEqualTo(deepest > 0);
            agreed++;
        }
        assertThat(agreed).isGreaterThan(1500);
    }
}
