package dev.strahl.denoise.net;

/**
 * A stack of feature channels over a grid of pixels, the network's tensors: channel by channel
 * (planar), each plane row by row with a one-pixel frame of zeros around it, so that a 3x3
 * convolution reads its zero padding like any other value and needs no edge cases. The frame is
 * never written.
 */
final class FeatureMap {
    final int channels;
    final int height;
    final int width;
    /** Floats from one row to the next: {@code width + 2}. */
    final int stride;
    /** Floats from one channel to the next: {@code (height + 2) * stride}. */
    final int plane;
    final float[] data;

    FeatureMap(int channels, int height, int width) {
        long planeSize = (long) (height + 2) * (width + 2);
        if (channels <= 0 || height <= 0 || width <= 0 || channels * planeSize > Integer.MAX_VALUE - 16) {
            throw new IllegalArgumentException("feature map " + channels + "x" + height + "x" + width + " is empty or too large");
        }
        this.channels = channels;
        this.height = height;
        this.width = width;
        this.stride = width + 2;
        this.plane = (int) planeSize;
        this.data = new float[channels * plane];
    }

    /** Index of channel c, row y, column x (0-based, inside the frame). */
    int at(int c, int y, int x) {
        return c * plane + (y + 1) * stride + x + 1;
    }

    float get(int c, int y, int x) {
        return data[at(c, y, x)];
    }

    void set(int c, int y, int x, float v) {
        data[at(c, y, x)] = v;
    }
}
