package dev.strahl.light;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Aabb;
import dev.strahl.testing.ChiSquare;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;

/**
 * The light tree on its own: its choice is a probability distribution over the emitters at every
 * shading point (they sum to one), sampling reports exactly the probability that walking the
 * emitter's path recomputes (what a BSDF sample's MIS weight uses), the choices follow those
 * probabilities (chi-square), no emitter that can light a point is ever left out, and the depth
 * stays bounded however the emitters lie.
 *
 * <p>The emitters: a mix of small one-sided quads-worth of triangles facing random ways, spheres
 * (every way), point lights and spots, spread over a 10-unit box with intensities over three
 * decades.
 */
class LightTreeTest {
    private static final double ALPHA = ChiSquare.sidak(0.01, 2);

    /** Random emitters: 60 % small triangles, then spheres, points and spots. */
    private static LightBounds[] mixedEmitters(int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        LightBounds[] out = new LightBounds[n];
        for (int i = 0; i < n; i++) {
            double x = 10 * random.nextDouble(), y = 10 * random.nextDouble(), z = 10 * random.nextDouble();
            double phi = Math.pow(10, 3 * random.nextDouble() - 1);
            double size = 0.05 + 0.3 * random.nextDouble();
            Aabb box = new Aabb().include(x, y, z).include(x + size, y + size * random.nextDouble(), z + size);
            double kind = random.nextDouble();
            if (kind < 0.6) {
                Vector3d w = randomUnit(random);
                out[i] = LightBounds.facing(box, w.x, w.y, w.z, 1, 0, phi);
            } else if (kind < 0.75) {
                out[i] = LightBounds.everyWay(box, phi);
            } else if (kind < 0.9) {
                out[i] = LightBounds.everyWay(new Aabb().include(x, y, z), phi);
            } else {
                Vector3d w = randomUnit(random);
                double inner = 0.5 * random.nextDouble(), outer = inner + 0.5 * random.nextDouble();
                out[i] = LightBounds.facing(new Aabb().include(x, y, z), w.x, w.y, w.z, Math.cos(inner), Math.cos(outer - inner), phi);
            }
        }
        return out;
    }

    private static Vector3d randomUnit(SplittableRandom random) {
        double z = 2 * random.nextDouble() - 1, phi = 2 * Math.PI * random.nextDouble(), r = Math.sqrt(1 - z * z);
        return new Vector3d(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    /** Shading points in and around the emitters' box, half of them with a normal. */
    private static List<Vector3d[]> shadingPoints(int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        List<Vector3d[]> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Vector3d p = new Vector3d(14 * random.nextDouble() - 2, 14 * random.nextDouble() - 2, 14 * random.nextDouble() - 2);
            out.add(new Vector3d[] {p, i % 2 == 0 ? randomUnit(random) : null});
        }
        return out;
    }

    @Test
    void probabilitiesSumToOneAtEveryShadingPoint() {
        LightBounds[] emitters = mixedEmitters(300, 1);
        LightTree tree = LightTree.build(emitters);
        assertThat(tree.nodeCount()).isEqualTo(2 * emitters.length - 1);
        for (Vector3d[] point : shadingPoints(500, 2)) {
            double sum = 0;
            for (int e = 0; e < emitters.length; e++) {
                double p = tree.probability(e, point[0], point[1]);
                assertThat(p).isBetween(0.0, 1.0);
                sum += p;
            }
            assertThat(sum).as("at %s, n %s", point[0], point[1]).isCloseTo(1, within(1e-12));
        }
    }

    @Test
    void samplingReportsTheProbabilityItsPathRecomputes() {
        LightBounds[] emitters = mixedEmitters(300, 3);
        LightTree tree = LightTree.build(emitters);
        SplittableRandom random = new SplittableRandom(4);
        LightSample out = new LightSample();
        for (Vector3d[] point : shadingPoints(200, 5)) {
            for (int i = 0; i < 50; i++) {
                int e = tree.sample(point[0], point[1], random.nextDouble(), out);
                assertThat(e).isBetween(0, emitters.length - 1);
                assertThat(out.pdf).as("the very same bits").isEqualTo(tree.probability(e, point[0], point[1]));
            }
        }
    }

    /**
     * 400 000 choices at two shading points against n·P(e). The mutant: the probabilities of a
     * choice by intensity alone (what power-based selection does) are rejected by the same counts.
     */
    @Test
    void choicesFollowTheProbabilitiesChiSquare() {
        LightBounds[] emitters = mixedEmitters(120, 6);
        LightTree tree = LightTree.build(emitters);
        double totalPhi = 0;
        for (LightBounds b : emitters) {
            totalPhi += b.phi;
        }
        int n = 400_000;
        Vector3dc[][] points = {{new Vector3d(5, 5, 5), new Vector3d(0, 1, 0)}, {new Vector3d(1, 9, 2), null}};
        SplittableRandom random = new SplittableRandom(7);
        LightSample out = new LightSample();
        for (Vector3dc[] point : points) {
            long[] observed = new long[emitters.length];
            for (int i = 0; i < n; i++) {
                observed[tree.sample(point[0], point[1], random.nextDouble(), out)]++;
            }
            double[] expected = new double[emitters.length], byIntensity = new double[emitters.length];
            for (int e = 0; e < emitters.length; e++) {
                expected[e] = n * tree.probability(e, point[0], point[1]);
                byIntensity[e] = n * emitters[e].phi / totalPhi;
            }
            ChiSquare.fromCounts(expected, observed).assertAccepted(ALPHA);
            ChiSquare.fromCounts(byIntensity, observed).assertRejected(ALPHA);
        }
    }

    /**
     * Leaving out an emitter that lights the point would bias the image: a triangle's tree
     * probability is positive wherever the point lies in front of it (its centre seen at less
     * than 90° from its normal), whatever the point's normal; a point light's everywhere.
     */
    @Test
    void noEmitterThatCanLightAPointIsLeftOut() {
        LightBounds[] emitters = mixedEmitters(200, 8);
        LightTree tree = LightTree.build(emitters);
        int checked = 0;
        for (Vector3d[] point : shadingPoints(300, 9)) {
            for (int e = 0; e < emitters.length; e++) {
                LightBounds b = emitters[e];
                double dx = point[0].x - b.centroid(0), dy = point[0].y - b.centroid(1), dz = point[0].z - b.centroid(2);
                boolean inFront = b.cosO < 0 || dx * b.wx + dy * b.wy + dz * b.wz > 0;
                boolean spot = b.cosO > -1 && b.cosO < 1;
                double angle = Math.acos((dx * b.wx + dy * b.wy + dz * b.wz) / Math.sqrt(dx * dx + dy * dy + dz * dz));
                boolean insideCone = !spot || angle < Math.acos(b.cosO) + Math.acos(b.cosE) - 1e-9;
                if (inFront && insideCone) {
                    assertThat(tree.probability(e, point[0], point[1])).as("emitter %s at %s", e, point[0]).isPositive();
                    checked++;
                }
            }
        }
        assertThat(checked).isGreaterThan(10_000);
    }

    /** Lights spaced ever further apart would make SAH splits peel them off one by one: the tree stays within 62 levels. */
    @Test
    void depthStaysWithinTheBitsOfAPath() {
        LightBounds[] emitters = new LightBounds[300];
        for (int i = 0; i < emitters.length; i++) {
            double x = Math.pow(1.3, i);
            emitters[i] = LightBounds.everyWay(new Aabb().include(x, 0, 0), 1);
        }
        LightTree tree = LightTree.build(emitters);
        assertThat(tree.maxDepth()).isLessThanOrEqualTo(LightTree.MAX_DEPTH);
        for (Vector3dc p : new Vector3dc[] {new Vector3d(0, 1, 0), new Vector3d(1e20, 5, 0), new Vector3d(3e34, 0, 1)}) {
            double sum = 0;
            for (int e = 0; e < emitters.length; e++) {
                sum += tree.probability(e, p, null);
            }
            assertThat(sum).isCloseTo(1, within(1e-9));
        }
    }

    /**
     * A point just under one of a 16 × 16 ceiling of equal lamps (0.2 below it, the next lamps 1
     * away) chooses its own lamp most of the time, not 1/256 of it; a point far below the middle
     * of the ceiling, to which all lamps are about equally near, chooses each about evenly.
     */
    @Test
    void aPointUnderALampChoosesItMostly() {
        LightBounds[] lamps = new LightBounds[256];
        for (int i = 0; i < 256; i++) {
            double x = i % 16, z = i / 16;
            lamps[i] = LightBounds.facing(new Aabb().include(x, 3, z).include(x + 0.2, 3, z + 0.2), 0, -1, 0, 1, 0, 1);
        }
        LightTree tree = LightTree.build(lamps);
        Vector3dc underLamp37 = new Vector3d(5.1, 2.8, 2.1);
        assertThat(tree.probability(37, underLamp37, new Vector3d(0, 1, 0))).isGreaterThan(0.5);
        Vector3dc farBelow = new Vector3d(7.6, -60, 7.6);
        for (int i = 0; i < 256; i++) {
            assertThat(tree.probability(i, farBelow, new Vector3d(0, 1, 0))).isBetween(0.8 / 256, 1.25 / 256);
        }
    }

    /**
     * The docs' many-lights floor (16 × 16 lamps of two triangles, pitch 0.5, 0.35 above the
     * floor): at random floor points the variance of the tree's choice relative to what each lamp
     * gives there (c = cos·cos/d², a lamp as a point), Σ c²/P / (Σ c)² − 1, is about 0.4, against 62
     * for a uniform choice (power: the lamps are equal). The bound 0.6 also fails the tree that
     * estimates by the distance to a node's centre alone (0.81 at these points).
     */
    @Test
    void aCeilingOfLampsIsChosenNearlyAsTheLampsGive() {
        int lamps = 256;
        LightBounds[] triangles = new LightBounds[2 * lamps];
        for (int i = 0; i < 2 * lamps; i++) {
            double x = (i / 2 % 16 - 7.5) * 0.5, z = (i / 32 - 7.5) * 0.5;
            triangles[i] = LightBounds.facing(new Aabb().include(x - 0.04, 0.35, z - 0.04).include(x + 0.04, 0.35, z + 0.04), 0, -1, 0, 1, 0, 0.0032);
        }
        LightTree tree = LightTree.build(triangles);
        SplittableRandom random = new SplittableRandom(10);
        Vector3dc up = new Vector3d(0, 1, 0);
        double treeVariance = 0, uniformVariance = 0;
        int points = 500;
        for (int k = 0; k < points; k++) {
            Vector3d p = new Vector3d(8 * random.nextDouble() - 4, 0, 8 * random.nextDouble() - 4);
            double sum = 0, byTree = 0, byUniform = 0;
            for (int i = 0; i < triangles.length; i++) {
                double dx = triangles[i].centroid(0) - p.x, dz = triangles[i].centroid(2) - p.z, d2 = dx * dx + 0.35 * 0.35 + dz * dz;
                double c = 0.35 * 0.35 / (d2 * d2);
                sum += c;
                byTree += c * c / tree.probability(i, p, up);
                byUniform += c * c * triangles.length;
            }
            treeVariance += byTree / (sum * sum) - 1;
            uniformVariance += byUniform / (sum * sum) - 1;
        }
        assertThat(treeVariance / points).isLessThan(0.6);
        assertThat(uniformVariance / points).isGreaterThan(50);
    }

    @Test
    void oneEmitterIsChosenWhereverItCanLight() {
        LightTree tree = LightTree.build(new LightBounds[] {
            LightBounds.facing(new Aabb().include(0, 1, 0).include(1, 1, 1), 0, -1, 0, 1, 0, 2)});
        LightSample out = new LightSample();
        assertThat(tree.sample(new Vector3d(0.5, 0, 0.5), null, 0.3, out)).isZero();
        assertThat(out.pdf).isEqualTo(1);
        assertThat(tree.probability(0, new Vector3d(0.5, 0, 0.5), null)).isEqualTo(1);
        assertThat(tree.sample(new Vector3d(0.5, 2, 0.5), null, 0.3, out)).as("above a light facing down").isEqualTo(-1);
        assertThat(tree.probability(0, new Vector3d(0.5, 2, 0.5), null)).isZero();
        assertThat(LightTree.build(new LightBounds[0])).isNull();
    }
}
