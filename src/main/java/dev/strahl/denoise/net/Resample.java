package dev.strahl.denoise.net;

import java.util.stream.IntStream;

/** The U-Net's changes of resolution: 2x2 max pooling on the way down, nearest-neighbour 2x upsampling on the way up. */
final class Resample {
    private Resample() {
    }

    /** Each output pixel is the largest of the 2x2 input pixels it covers; the input's size must be even. */
    static FeatureMap pool(FeatureMap src) {
        if (src.height % 2 != 0 || src.width % 2 != 0) {
            throw new IllegalArgumentException("pooling needs an even size, got " + src.width + "x" + src.height);
        }
        FeatureMap dst = new FeatureMap(src.channels, src.height / 2, src.width / 2);
        IntStream.range(0, src.channels).parallel().forEach(c -> {
            for (int y = 0; y < dst.height; y++) {
                int top = src.at(c, 2 * y, 0);
                int bottom = top + src.stride;
                int out = dst.at(c, y, 0);
                for (int x = 0; x < dst.width; x++) {
                    float a = Math.max(src.data[top + 2 * x], src.data[top + 2 * x + 1]);
                    float b = Math.max(src.data[bottom + 2 * x], src.data[bottom + 2 * x + 1]);
                    dst.data[out + x] = Math.max(a, b);
                }
            }
        });
        return dst;
    }

    /** Each input pixel becomes a 2x2 block of the output. */
    static FeatureMap upsample(FeatureMap src) {
        FeatureMap dst = new FeatureMap(src.channels, 2 * src.height, 2 * src.width);
        IntStream.range(0, src.channels).parallel().forEach(c -> {
            for (int y = 0; y < src.height; y++) {
                int in = src.at(c, y, 0);
                int top = dst.at(c, 2 * y, 0);
                int bottom = top + dst.stride;
                for (int x = 0; x < src.width; x++) {
                    float v = src.data[in + x];
                    dst.data[top + 2 * x] = v;
                    dst.data[top + 2 * x + 1] = v;
                    dst.data[bottom + 2 * x] = v;
                    dst.data[bottom + 2 * x + 1] = v;
                }
            }
        });
        return dst;
    }
}
