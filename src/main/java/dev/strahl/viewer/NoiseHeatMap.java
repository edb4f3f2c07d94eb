package dev.strahl.viewer;

import dev.strahl.image.Image;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * View → Noise: the remaining relative error of every pixel's mean ({@link dev.strahl.render.RenderBuffers#relativeError()},
 * what a noise threshold bounds) as colours against a scale T, the threshold when one is set: dark blue for no error,
 * through blue to cyan at T (met: a pixel with its neighbours there takes no more samples), then yellow, orange and
 * red at 4·T and above, on a logarithmic scale above T.
 */
final class NoiseHeatMap {
    /** The scale without a noise threshold: 1 %. */
    static final double DEFAULT_SCALE = 0.01;

    private NoiseHeatMap() {
    }

    /** The heat map of an error image (its r channel) against the scale {@code t}. */
    static BufferedImage of(Image error, double t) {
        BufferedImage img = new BufferedImage(error.width(), error.height(), BufferedImage.TYPE_INT_RGB);
        int[] out = ((DataBufferInt) img.getRaster().getDataBuffer()).getData();
        float[] e = error.rgb();
        for (int i = 0; i < out.length; i++) {
            out[i] = color(e[3 * i] / t);
        }
        return img;
    }

    /** The colour of an error of {@code v} times the scale, as 0xRRGGBB. */
    static int color(double v) {
        if (!(v >= 0)) {
            return 0xff00ff;                                 // NaN: magenta, never met
        }
        if (v <= 1) {                                        // met: dark blue to cyan
            return rgb(0, 0.2 + 0.8 * v, 0.35 + 0.65 * v);
        }
        double s = Math.min(1, Math.log(v) / Math.log(4));  // 1 .. 4T: yellow to red
        return rgb(1, 0.9 * (1 - s), 0.2 * (1 - s));
    }

    private static int rgb(double r, double g, double b) {
        return (int) Math.round(255 * r) << 16 | (int) Math.round(255 * g) << 8 | (int) Math.round(255 * b);
    }
}
