package dev.strahl.light;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Warp;
import java.util.Arrays;
import java.util.Locale;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The light arriving from infinitely far away where rays leave the scene: a constant radiance or a
 * latitude–longitude map. Directions point away from the scene, towards the environment.
 *
 * <p><b>Orientation</b> (Mitsuba 3's {@code envmap}): +Y is up and the image's top row is the +Y
 * pole; the centre column is seen looking along +Z, the column at a quarter of the width along +X,
 * at three quarters along −X, the left and right edges along −Z. In the map's own frame,
 * d = (sin φ sin θ, cos θ, −cos φ sin θ) with φ = 2πu, θ = πv. Texel (x, y) sits at
 * u = (x + ½)/W (wrapping) and v = y/(H − 1); radiance between texels is bilinear. The map is
 * turned by {@code rotateDegrees} about +Y (right-handed) and multiplied by {@code scale}.
 *
 * <p><b>Sampling.</b> A constant environment is sampled uniformly over the sphere. A map is
 * sampled by a piecewise-constant 2D distribution over the cells between texel centres, each
 * weighted by the mean luminance of its four corner texels (the integral of the bilinear
 * radiance over the cell, in (u, v)) times sin θ at the cell's centre; the solid-angle density is
 * p(u, v) / (2π² sin θ). A cell whose four texels are black is never sampled, and its radiance is
 * zero, so the estimate stays unbiased. Immutable, thread-safe; evaluation and sampling allocate
 * nothing.
 */
public final class Environment {
    private static final double LUM_R = 0.2126, LUM_G = 0.7152, LUM_B = 0.0722;

    /** Black: no environment. */
    public static final Environment BLACK = new Environment(Rgb.BLACK);

    private final Rgb constant;            // null for a map
    private final int width, height;
    private final float[] rgb;             // scaled, row by row from the top
    private final double cosRot, sinRot;
    private final Distribution2D distribution;
    private final double power;            // ∫ mean(L) dω over the sphere
    private final String description;

    private Environment(Rgb constant) {
        this.constant = constant;
        this.width = 0;
        this.height = 0;
        this.rgb = null;
        this.cosRot = 1;
        this.sinRot = 0;
        this.distribution = null;
        this.power = (constant.r() + constant.g() + constant.b()) / 3 * 4 * Math.PI;
        this.description = constant.toString();
    }

    private Environment(int width, int height, float[] rgb, double rotateDegrees, String description) {
        this.constant = null;
        this.width = width;
        this.height = height;
        this.rgb = rgb;
        double a = Math.toRadians(rotateDegrees);
        this.cosRot = Math.cos(a);
        this.sinRot = Math.sin(a);
        this.description = description;
        int rows = height - 1;
        float[] weights = new float[width * rows];
        double sum = 0;
        for (int j = 0; j < rows; j++) {
            double theta0 = Math.PI * j / rows, theta1 = Math.PI * (j + 1) / rows;
            double sinCentre = Math.sin(0.5 * (theta0 + theta1));
            double band = 2 * Math.PI / width * (Math.cos(theta0) - Math.cos(theta1));   // solid angle of a cell
            for (int i = 0; i < width; i++) {
                int i1 = i + 1 == width ? 0 : i + 1;
                double lum = 0.25 * (luminance(i, j) + luminance(i1, j) + luminance(i, j + 1) + luminance(i1, j + 1));
                weights[j * width + i] = (float) (lum * sinCentre);
                sum += band * 0.25 * (mean(i, j) + mean(i1, j) + mean(i, j + 1) + mean(i1, j + 1));
            }
        }
        this.power = sum;
        this.distribution = sum > 0 ? new Distribution2D(width, rows, weights) : null;
    }

    /**
     * A constant environment.
     *
     * @param radiance the radiance from every direction
     */
    public static Environment constant(Rgb radiance) {
        return radiance.isBlack() ? BLACK : new Environment(radiance);
    }

    /**
     * A latitude–longitude map. Negative and NaN samples count as black.
     *
     * @param width         texels per row, ≥ 1
     * @param height        rows, ≥ 2 (the rows sit at v = y/(H − 1))
     * @param rgb           3 · width · height linear floats, rows from the top (not kept: copied and scaled)
     * @param scale         factor on the radiance, ≥ 0
     * @param rotateDegrees rotation of the map about +Y
     * @param name          what the map is (a file name), for descriptions
     */
    public static Environment map(int width, int height, float[] rgb, double scale, double rotateDegrees, String name) {
        if (width < 1 || height < 2) {
            throw new IllegalArgumentException("an environment map needs at least 1x2 texels, got " + width + "x" + height);
        }
        if (rgb.length != 3L * width * height) {
            throw new IllegalArgumentException("expected " + 3L * width * height + " floats for " + width + "x" + height + ", got " + rgb.length);
        }
        if (!(scale >= 0) || Double.isInfinite(scale) || !Double.isFinite(rotateDegrees)) {
            throw new IllegalArgumentException("environment scale must be finite and >= 0 and rotation finite, got " + scale + ", " + rotateDegrees);
        }
        float[] scaled = new float[rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            float s = (float) (rgb[i] * scale);
            scaled[i] = s > 0 && s < Float.POSITIVE_INFINITY ? s : s == Float.POSITIVE_INFINITY ? Float.MAX_VALUE : 0;
        }
        String description = String.format(Locale.ROOT, "envmap %s %dx%d scale %s rotate %s data %08x", name, width, height,
                scale, rotateDegrees, Arrays.hashCode(scaled));
        Environment env = new Environment(width, height, scaled, rotateDegrees, description);
        return env.power > 0 ? env : BLACK;
    }

    /** Whether nothing arrives from the environment. */
    public boolean isBlack() {
        return constant != null && constant.isBlack();
    }

    /** Whether this is a constant radiance (then {@link #constantRadiance()} is it). */
    public boolean isConstant() {
        return constant != null;
    }

    /** The constant radiance; black for a map. */
    public Rgb constantRadiance() {
        return constant != null ? constant : Rgb.BLACK;
    }

    /** ∫ mean(L) dω over the sphere: the environment's brightness, for choosing between it and other lights. */
    public double power() {
        return power;
    }

    /** The radiance arriving from direction {@code d} (unit, pointing away from the scene), into {@code dest}. */
    public MutableRgb eval(Vector3dc d, MutableRgb dest) {
        if (constant != null) {
            return dest.set(constant);
        }
        double x = d.x() * cosRot - d.z() * sinRot;
        double z = d.x() * sinRot + d.z() * cosRot;
        double u = Math.atan2(x, -z) * (0.5 / Math.PI);
        if (u < 0) {
            u += 1;
        }
        double v = Math.acos(Math.max(-1, Math.min(1, d.y()))) / Math.PI;
        return lookup(u, v, dest);
    }

    /** Bilinear radiance at (u, v) of the map. */
    private MutableRgb lookup(double u, double v, MutableRgb dest) {
        double fx = u * width - 0.5;
        double fy = v * (height - 1);
        int x0 = (int) Math.floor(fx);
        int y0 = Math.min((int) fy, height - 2);
        double tx = fx - x0, ty = fy - y0;
        x0 = Math.floorMod(x0, width);
        int x1 = x0 + 1 == width ? 0 : x0 + 1;
        int a = 3 * (y0 * width + x0), b = 3 * (y0 * width + x1);
        int c = 3 * ((y0 + 1) * width + x0), e = 3 * ((y0 + 1) * width + x1);
        double w00 = (1 - tx) * (1 - ty), w10 = tx * (1 - ty), w01 = (1 - tx) * ty, w11 = tx * ty;
        return dest.set(w00 * rgb[a] + w10 * rgb[b] + w01 * rgb[c] + w11 * rgb[e],
                w00 * rgb[a + 1] + w10 * rgb[b + 1] + w01 * rgb[c + 1] + w11 * rgb[e + 1],
                w00 * rgb[a + 2] + w10 * rgb[b + 2] + w01 * rgb[c + 2] + w11 * rgb[e + 2]);
    }

    /**
     * Samples a direction towards the environment: writes it into {@code wi} and its radiance into
     * {@code radiance}, returns the solid-angle density (0 if nothing was sampled).
     *
     * @param uv scratch of two doubles
     */
    public double sample(double u1, double u2, double[] uv, Vector3d wi, MutableRgb radiance) {
        if (constant != null) {
            if (constant.isBlack()) {
                return 0;
            }
            Warp.uniformSphere(u1, u2, wi);
            radiance.set(constant);
            return Warp.uniformSpherePdf();
        }
        if (distribution == null) {
            return 0;
        }
        double pdfUv = distribution.sample(u1, u2, uv);
        double u = uv[0] + 0.5 / width;
        if (u >= 1) {
            u -= 1;
        }
        double v = uv[1];
        double theta = Math.PI * v, phi = 2 * Math.PI * u;
        double sinTheta = Math.sin(theta);
        if (!(sinTheta > 0) || !(pdfUv > 0)) {
            return 0;
        }
        double x = Math.sin(phi) * sinTheta, y = Math.cos(theta), z = -Math.cos(phi) * sinTheta;
        wi.set(x * cosRot + z * sinRot, y, -x * sinRot + z * cosRot);
        lookup(u, v, radiance);
        return pdfUv / (2 * Math.PI * Math.PI * sinTheta);
    }

    /** The solid-angle density with which {@link #sample} picks direction {@code d}. */
    public double pdf(Vector3dc d) {
        if (constant != null) {
            return constant.isBlack() ? 0 : Warp.uniformSpherePdf();
        }
        if (distribution == null) {
            return 0;
        }
        double x = d.x() * cosRot - d.z() * sinRot;
        double z = d.x() * sinRot + d.z() * cosRot;
        double sinTheta = Math.sqrt(x * x + z * z);
        if (!(sinTheta > 0)) {
            return 0;
        }
        double u = Math.atan2(x, -z) * (0.5 / Math.PI) - 0.5 / width;
        u -= Math.floor(u);
        double v = Math.acos(Math.max(-1, Math.min(1, d.y()))) / Math.PI;
        return distribution.pdf(u, v) / (2 * Math.PI * Math.PI * sinTheta);
    }

    private double luminance(int x, int y) {
        int o = 3 * (y * width + x);
        return LUM_R * rgb[o] + LUM_G * rgb[o + 1] + LUM_B * rgb[o + 2];
    }

    private double mean(int x, int y) {
        int o = 3 * (y * width + x);
        return (rgb[o] + rgb[o + 1] + rgb[o + 2]) / 3.0;
    }

    /** What the environment is: the constant, or the map's name, size, scale, rotation and a hash of its texels. */
    @Override
    public String toString() {
        return description;
    }
}
