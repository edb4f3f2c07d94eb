package dev.strahl.scene;

import dev.strahl.light.Environment;

/**
 * The environment of a scene that has no light of its own: a procedural sky with a soft sun, built
 * in code (no file), the same bits every time. It is there to show a bare model's shape: a key
 * light from the front left, a blue sky from above as fill, and a dark ground that a grey model
 * stands out against when the framing camera looks down at it.
 *
 * <ul>
 *   <li>Sky (directions above the horizon, elevation e): from horizon (0.55, 0.62, 0.75) to zenith
 *       (0.16, 0.28, 0.55), mixed by (1 − sin e)².</li>
 *   <li>Ground (below): (0.07, 0.065, 0.06), rising to the horizon colour in a thin band
 *       (weight exp(−12 |sin e|)).</li>
 *   <li>Sun: at azimuth {@value #SUN_AZIMUTH}° (from +Z towards +X, so front left of the framing
 *       camera, which sits at +40°) and elevation {@value #SUN_ELEVATION}°; radiance
 *       {@value #SUN_PEAK} × exp(−α²/2σ²) at angle α from its centre, σ = {@value #SUN_SIGMA}°
 *       (a soft disk of about 0.012 sr), plus a glow of 0.6 × exp(−α²/2·(12°)²).</li>
 * </ul>
 * Sampled as a {@value #WIDTH}×{@value #HEIGHT} latitude–longitude map (0.7° per texel), so the
 * light sampler importance-samples the sun like any map's.
 */
final class StudioSky {
    static final int WIDTH = 512;
    static final int HEIGHT = 256;
    static final double SUN_AZIMUTH = -35;
    static final double SUN_ELEVATION = 40;
    static final double SUN_SIGMA = 2.5;
    static final double SUN_PEAK = 120;
    /** What the note says. */
    static final String DESCRIPTION = "strahl's studio sky (a procedural blue sky with a soft sun high at the front left, dark ground)";

    private StudioSky() {
    }

    /** The sky, made once per process: every bare model gets the same immutable environment (a fuzzer loads a million). */
    static Environment environment() {
        return Made.SKY;
    }

    /** Holds the sky, made when first asked for. */
    private static final class Made {
        static final Environment SKY = Environment.map(WIDTH, HEIGHT, texels(), 1, 0, "studio-sky");
    }

    /** The texels, rows from the top, placed as {@link Environment} says (u = (x + ½)/W, v = y/(H − 1)). */
    static float[] texels() {
        float[] rgb = new float[3 * WIDTH * HEIGHT];
        double az = Math.toRadians(SUN_AZIMUTH), el = Math.toRadians(SUN_ELEVATION);
        double sx = Math.sin(az) * Math.cos(el), sy = Math.sin(el), sz = Math.cos(az) * Math.cos(el);
        double sigma = Math.toRadians(SUN_SIGMA), glow = Math.toRadians(12);
        for (int y = 0; y < HEIGHT; y++) {
            double theta = Math.PI * y / (HEIGHT - 1);
            for (int x = 0; x < WIDTH; x++) {
                double phi = 2 * Math.PI * (x + 0.5) / WIDTH;
                double dx = Math.sin(phi) * Math.sin(theta), dy = Math.cos(theta), dz = -Math.cos(phi) * Math.sin(theta);
                double r, g, b;
                if (dy >= 0) {
                    double t = (1 - dy) * (1 - dy);
                    r = 0.16 + (0.55 - 0.16) * t;
                    g = 0.28 + (0.62 - 0.28) * t;
                    b = 0.55 + (0.75 - 0.55) * t;
                } else {
                    double t = Math.exp(12 * dy);
                    r = 0.07 + (0.55 - 0.07) * t;
                    g = 0.065 + (0.62 - 0.065) * t;
                    b = 0.06 + (0.75 - 0.06) * t;
                }
                double alpha = Math.acos(Math.max(-1, Math.min(1, dx * sx + dy * sy + dz * sz)));
                double sun = SUN_PEAK * Math.exp(-alpha * alpha / (2 * sigma * sigma)) + 0.6 * Math.exp(-alpha * alpha / (2 * glow * glow));
                int o = 3 * (y * WIDTH + x);
                rgb[o] = (float) (r + sun);
                rgb[o + 1] = (float) (g + 0.95 * sun);
                rgb[o + 2] = (float) (b + 0.85 * sun);
            }
        }
        return rgb;
    }
}
