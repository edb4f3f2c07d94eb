package dev.strahl.light;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3dc;

/**
 * The choice of a light by what it gives the shading point ({@link LightSampler}'s default):
 * the part of the light samples that is not the environment's goes to the directional lights
 * (which have no position to bound) with their share of the power, P_directional / (P_directional
 * + P_local), and otherwise to the {@link LightTree} over the local emitters: the emissive
 * primitives (emitters 0 .. n − 1, in the order of {@code prims}) and the point and spot lights
 * (emitters n ..). Among the directional lights by power, as before the tree.
 *
 * <p>An area emitter's point is uniform by area, so its density per unit area is
 * P(choice at the shading point) / area: the density of a point seen from a BSDF sample's origin
 * is the tree's {@link LightTree#probability} there, worked out by {@link #pdf} with the same
 * arithmetic as {@link #sample}. Immutable.
 */
final class TreeSelection {
    private final LightTree tree;                 // null without local emitters
    private final int[] prims;                    // the area emitters, ascending (the sampler's array)
    private final double[] area;                  // of each area emitter
    private final PunctualLight[] local;          // point and spot lights: emitters prims.length ..
    private final PunctualLight[] directional;
    private final double[] directionalCdf;
    private final double[] directionalProbability;
    private final double pDirectional;            // the directional lights' share of the non-environment samples

    /**
     * @param weight      per emissive primitive, its weight per unit area (mean radiance): the
     *                    emitter's intensity is weight × area, its power π × that
     * @param sceneRadius sizes the directional lights' power ({@link PunctualLight})
     */
    TreeSelection(Geometry geometry, int[] prims, double[] weight, PunctualLight[] punctual, double sceneRadius) {
        this.prims = prims;
        this.area = new double[prims.length];
        List<LightBounds> bounds = new ArrayList<>();
        SurfacePoint sp = new SurfacePoint();
        Aabb box = new Aabb();
        double localPower = 0;
        for (int e = 0; e < prims.length; e++) {
            int prim = prims[e];
            area[e] = geometry.area(prim);
            localPower += Math.PI * weight[e] * area[e];
            geometry.includeBounds(prim, box.reset());
            if (geometry.isTriangle(prim)) {
                geometry.samplePoint(prim, 0, 0, sp);
                bounds.add(LightBounds.facing(box, sp.ng.x, sp.ng.y, sp.ng.z, 1, 0, weight[e] * area[e]));
            } else {
                bounds.add(LightBounds.everyWay(box, weight[e] * area[e] / 4));    // intensity L·πr² every way
            }
        }
        List<PunctualLight> locals = new ArrayList<>(), directions = new ArrayList<>();
        for (PunctualLight light : punctual) {
            if (light.type() == PunctualLight.Type.DIRECTIONAL) {
                directions.add(light);
            } else {
                locals.add(light);
                localPower += light.power(sceneRadius);
                bounds.add(light.bounds());
            }
        }
        this.local = locals.toArray(new PunctualLight[0]);
        this.directional = directions.toArray(new PunctualLight[0]);
        this.directionalCdf = new double[directional.length];
        this.directionalProbability = new double[directional.length];
        double directionalPower = PowerSelection.cumulate(directional, sceneRadius, directionalCdf, directionalProbability);
        this.pDirectional = directional.length == 0 ? 0 : bounds.isEmpty() ? 1 : directionalPower / (directionalPower + localPower);
        this.tree = LightTree.build(bounds.toArray(new LightBounds[0]));
    }

    /** Whether there is anything to choose. */
    boolean isEmpty() {
        return tree == null && directional.length == 0;
    }

    /** The tree's nodes, 0 without local emitters. */
    int nodeCount() {
        return tree == null ? 0 : tree.nodeCount();
    }

    /**
     * Samples a local or directional light for the shading point (ref, n) with u, already rescaled
     * to this part of the samples, of probability {@code pLocal}; as {@link LightSampler#sample}.
     */
    boolean sample(Geometry geometry, Emission[] emission, Vector3dc ref, Vector3dc n, double u, double u1, double u2, double pLocal,
                   SurfacePoint scratch, LightSample out) {
        if (pDirectional > 0) {
            if (u < pDirectional) {
                int i = PowerSelection.select(directionalCdf, Math.min(u / pDirectional, Math.nextDown(1.0)));
                out.pdf = pLocal * pDirectional * directionalProbability[i];
                return directional[i].illuminate(ref, out) && out.pdf > 0;
            }
            u = Math.min((u - pDirectional) / (1 - pDirectional), Math.nextDown(1.0));
        }
        int e = tree.sample(ref, n, u, out);
        if (e < 0) {
            return false;
        }
        double choice = pLocal * (1 - pDirectional) * out.pdf;
        if (e >= prims.length) {
            out.pdf = choice;
            return local[e - prims.length].illuminate(ref, out) && out.pdf > 0;
        }
        double cosLight = out.aimAtAreaLight(geometry, prims[e], ref, u1, u2, scratch);
        if (cosLight <= 0) {
            return false;
        }
        out.pdf = solidAngleDensity(choice, e, out.distance, cosLight);
        emission[scratch.material].eval(scratch.uv, out.radiance);
        return out.pdf > 0 && Double.isFinite(out.pdf);
    }

    /** The density {@link #sample} gives the point of emissive primitive {@code prim} seen from (ref, n); see {@link LightSampler#pdf}. */
    double pdf(Vector3dc ref, Vector3dc n, int prim, double dist, double cosLight, double pLocal) {
        int e = java.util.Arrays.binarySearch(prims, prim);
        if (e < 0 || cosLight <= 0 || tree == null) {
            return 0;
        }
        return solidAngleDensity(pLocal * (1 - pDirectional) * tree.probability(e, ref, n), e, dist, cosLight);
    }

    /** Choice probability × the uniform density 1/area, turned per unit solid angle by d²/cos: one expression for both ways. */
    private double solidAngleDensity(double choice, int e, double dist, double cosLight) {
        return choice / area[e] * dist * dist / cosLight;
    }

    /** The probability that the tree chooses emitter e at (ref, n), for the tests. */
    double treeProbability(int e, Vector3dc ref, Vector3dc n) {
        return tree.probability(e, ref, n);
    }

    /** The directional lights' share of the non-environment samples. */
    double directionalShare() {
        return pDirectional;
    }

    /** Bytes of the tree. */
    long byteSize() {
        return tree == null ? 0 : tree.byteSize() + 8L * area.length;
    }
}
