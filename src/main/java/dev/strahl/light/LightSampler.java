package dev.strahl.light;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.image.Rgb;
import java.util.Arrays;
import org.joml.Vector3dc;

/**
 * Picks points on the emissive primitives (area lights) for next-event estimation. A primitive is
 * chosen in proportion to its power, area × mean(Le), then a point uniformly by area with
 * {@link Geometry#samplePoint} (the one sampling of a primitive); the density per unit area is
 * thus mean(Le) / total power for every emitter, which lets {@link #pdf} work from the material
 * alone. Lights are one-sided: they emit into the hemisphere of their geometric normal.
 * Immutable and thread-safe.
 */
public final class LightSampler {
    private final Geometry geometry;
    private final Rgb[] emission;        // per material: the caller's table, not a copy
    private final int[] prims;           // emissive primitives
    private final double[] cdf;          // cumulative power, cdf[last] = 1
    private final double totalPower;     // sum of area × mean(Le)
    private final double[] density;      // per material: mean(Le) / total power, the density per unit area

    /**
     * @param emissionByMaterial emitted radiance of each material index (black = not a light); kept,
     *                           not copied (the world's one table), so it must not change afterwards
     */
    public LightSampler(Geometry geometry, Rgb[] emissionByMaterial) {
        this.geometry = geometry;
        this.emission = emissionByMaterial;
        int n = 0;
        int[] found = new int[16];
        double[] power = new double[16];
        double total = 0;
        for (int prim = 0; prim < geometry.primitiveCount(); prim++) {
            double w = weight(geometry.material(prim));
            if (w > 0) {
                if (n == found.length) {
                    found = Arrays.copyOf(found, 2 * n);
                    power = Arrays.copyOf(power, 2 * n);
                }
                found[n] = prim;
                total += w * geometry.area(prim);
                power[n++] = total;
            }
        }
        this.prims = Arrays.copyOf(found, n);
        this.cdf = Arrays.copyOf(power, n);
        for (int i = 0; i < n; i++) {
            cdf[i] /= total;
        }
        this.totalPower = total;
        this.density = new double[emission.length];
        for (int m = 0; m < emission.length; m++) {
            density[m] = total > 0 ? weight(m) / total : 0;
        }
    }

    /** Number of emissive primitives. */
    public int lightCount() {
        return prims.length;
    }

    public boolean isEmpty() {
        return prims.length == 0;
    }

    /** Total emitted power over π: the sum of area × mean(Le) (the flux of a Lambertian emitter is π times this). */
    public double totalPower() {
        return totalPower;
    }

    /** The emitted radiance of a material, black if it is not a light. */
    public Rgb emission(int material) {
        return emission[material];
    }

    private double weight(int material) {
        Rgb le = emission[material];
        return (le.r() + le.g() + le.b()) / 3;
    }

    /**
     * Samples a direction towards a light from {@code ref}. Returns false when nothing can be
     * sampled or the chosen point faces away from ref.
     *
     * @param scratch a per-thread surface record for the sampled point
     */
    public boolean sample(Vector3dc ref, double uLight, double u1, double u2, SurfacePoint scratch, LightSample out) {
        if (prims.length == 0) {
            return false;
        }
        geometry.samplePoint(prims[select(uLight)], u1, u2, scratch);
        int m = scratch.material;
        out.p.set(scratch.p);
        out.ng.set(scratch.ng);
        double dx = out.p.x - ref.x(), dy = out.p.y - ref.y(), dz = out.p.z - ref.z();
        double dist2 = dx * dx + dy * dy + dz * dz;
        double dist = Math.sqrt(dist2);
        if (!(dist > 0)) {
            return false;
        }
        double inv = 1 / dist;
        out.wi.set(dx * inv, dy * inv, dz * inv);
        double cosLight = -out.ng.dot(out.wi);
        if (cosLight <= 0) {
            return false;
        }
        out.distance = dist;
        out.pdf = density[m] * dist * dist / cosLight;
        out.radiance = emission[m];
        return out.pdf > 0 && Double.isFinite(out.pdf);
    }

    /** Index of the first emitter whose cumulative power exceeds u: a linear scan for a few lights, else bisection. */
    private int select(double u) {
        int n = cdf.length;
        if (n <= 8) {
            int i = 0;
            while (i < n - 1 && !(cdf[i] > u)) {
                i++;
            }
            return i;
        }
        int i = Arrays.binarySearch(cdf, u);
        i = i >= 0 ? i + 1 : -i - 1;                 // first entry with cdf > uLight
        return Math.min(i, n - 1);
    }

    /**
     * Picks an emissive primitive in proportion to its power and a point on it uniformly by area,
     * as {@link #sample} does but without a reference point: the start of a light path (photon
     * emission). Writes the point, its geometric normal and material into {@code dest} and returns
     * the point's density per unit area, mean(Le) / {@link #totalPower()}; 0 if there is no light.
     */
    public double samplePoint(double uLight, double u1, double u2, SurfacePoint dest) {
        if (prims.length == 0) {
            return 0;
        }
        geometry.samplePoint(prims[select(uLight)], u1, u2, dest);
        return weight(dest.material) / totalPower;
    }

    /**
     * Solid-angle density with which {@link #sample} picks a point of a light of the given
     * material at distance {@code dist} whose normal makes cosine {@code cosLight} with the
     * direction to the reference point.
     */
    public double pdf(int material, double dist, double cosLight) {
        if (cosLight <= 0 || totalPower <= 0) {
            return 0;
        }
        return density[material] * dist * dist / cosLight;
    }
}
