package dev.strahl.denoise.net;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.IntStream;

/**
 * Intel Open Image Denoise's RT filter for HDR colour, in pure Java: OIDN 2.5.1's trained U-Net
 * ({@link UNet}, weights shipped as resources beside this class) with OIDN's preparation of its
 * input and output:
 * <ol>
 *   <li>colour scaled by the auto-exposure ({@link HdrTransfer#autoexposure}), NaN and negatives
 *       to 0, through the PU curve; albedo clamped to [0, 1]; normals clamped to [-1, 1] and
 *       mapped to [0, 1];</li>
 *   <li>the image in square tiles of at most {@link #tileSide} pixels a side (one tile if it fits), each
 *       padded with zeros to a multiple of 16 and overlapping its neighbours by
 *       {@link UNet#OVERLAP} pixels, so that every kept pixel gets what the whole image would
 *       give it: the result does not depend on the tiling;</li>
 *   <li>the output through the inverse curve and the inverse exposure.</li>
 * </ol>
 * The network is chosen by the guides given: colour, albedo and normal ({@code rt_hdr_alb_nrm}),
 * colour and albedo ({@code rt_hdr_alb}) or colour alone ({@code rt_hdr}); OIDN takes normals
 * only with an albedo. Each network's weights are read once, when first used.
 */
public final class NeuralDenoiser {
    /** Bytes per pixel a tile needs at most while the network runs (the input, 64 + 64 channels at full size, the coarser levels). */
    private static final long BYTES_PER_PIXEL = 4L * 170;
    /** The smallest tile side: the overlap on both sides and 64 pixels kept between them. */
    static final int MIN_TILE = 2 * UNet.OVERLAP + 4 * UNet.ALIGNMENT;
    private static final ConcurrentHashMap<String, UNet> NETWORKS = new ConcurrentHashMap<>();

    private final int tileSide;

    /** @param tileSide the side of the largest tile, in pixels: a multiple of 16, at least {@link #MIN_TILE} */
    NeuralDenoiser(int tileSide) {
        if (tileSide < MIN_TILE || tileSide % UNet.ALIGNMENT != 0) {
            throw new IllegalArgumentException("tile side " + tileSide + " is not a multiple of 16 from " + MIN_TILE);
        }
        this.tileSide = tileSide;
    }

    /**
     * A denoiser whose tiles take at most a quarter of the heap's limit (a tile of n pixels needs
     * about 680·n bytes while the network runs): tiles of 880x880 pixels with a 2 GiB heap.
     */
    public static NeuralDenoiser create() {
        long pixels = Runtime.getRuntime().maxMemory() / 4 / BYTES_PER_PIXEL;
        int side = (int) Math.min(1 << 14, (long) Math.sqrt((double) pixels)) / UNet.ALIGNMENT * UNet.ALIGNMENT;
        return new NeuralDenoiser(Math.max(MIN_TILE, side));
    }

    /**
     * The most heap a denoise of a {@code width}×{@code height} image takes: the largest tile while
     * the network runs and the result (3 floats a pixel, and the copy an image makes of it).
     *
     * @param width  width in pixels
     * @param height height in pixels
     * @return bytes
     */
    public long bytesNeeded(int width, int height) {
        long tile = (long) Math.min(roundUp(width), tileSide) * Math.min(roundUp(height), tileSide);
        return BYTES_PER_PIXEL * tile + 2L * 12 * width * height;
    }

    /**
     * Denoises an HDR render.
     *
     * @param width  width in pixels
     * @param height height in pixels
     * @param color  r, g, b per pixel, row by row from the top
     * @param albedo the same layout, or null
     * @param normal world- or camera-space normals, the same layout, or null (used only with an albedo)
     * @return the denoised colour, the same layout
     * @throws UncheckedIOException (its message one line) if the network's weights are missing or damaged
     */
    public float[] denoise(int width, int height, float[] color, float[] albedo, float[] normal) {
        String name = albedo == null ? "rt_hdr" : normal == null ? "rt_hdr_alb" : "rt_hdr_alb_nrm";
        return denoise(network(name, albedo == null ? 3 : normal == null ? 6 : 9), width, height, color, albedo, normal);
    }

    /** {@link #denoise(int, int, float[], float[], float[])} with the given network (its input channels say which guides it takes). */
    float[] denoise(UNet net, int width, int height, float[] color, float[] albedo, float[] normal) {
        if (net.inputChannels > 3 && albedo == null || net.inputChannels > 6 && normal == null) {
            throw new IllegalArgumentException("the network takes " + net.inputChannels + " channels");
        }
        long floats = 3L * width * height;
        if (width <= 0 || height <= 0 || color.length != floats || albedo != null && albedo.length != floats
                || normal != null && normal.length != floats) {
            throw new IllegalArgumentException("a " + width + "x" + height + " image needs " + floats + " floats per buffer");
        }
        float inputScale = HdrTransfer.autoexposure(color, width, height);
        float outputScale = inputScale != 0 ? 1 / inputScale : 0;
        Input input = new Input(width, height, color, net.inputChannels > 3 ? albedo : null, net.inputChannels > 6 ? normal : null, inputScale);
        float[] out = new float[3 * width * height];
        int paddedH = roundUp(height), paddedW = roundUp(width);
        int stepY = paddedH <= tileSide ? paddedH : tileSide - 2 * UNet.OVERLAP;
        int stepX = paddedW <= tileSide ? paddedW : tileSide - 2 * UNet.OVERLAP;
        for (int y0 = 0; y0 < height; y0 += stepY) {
            for (int x0 = 0; x0 < width; x0 += stepX) {
                int inY = Math.max(0, y0 - UNet.OVERLAP);
                int inX = Math.max(0, x0 - UNet.OVERLAP);
                int inH = Math.min(paddedH, y0 + stepY + UNet.OVERLAP) - inY;
                int inW = Math.min(paddedW, x0 + stepX + UNet.OVERLAP) - inX;
                FeatureMap result = net.run(input.tile(net.inputChannels, inY, inX, inH, inW));
                output(result, inY, inX, out, width, y0, Math.min(height, y0 + stepY), x0, Math.min(width, x0 + stepX), outputScale);
            }
        }
        return out;
    }

    /** Pixels y0..y1 x x0..x1 of the image from the network's output for the tile at (inY, inX). */
    private static void output(FeatureMap result, int inY, int inX, float[] out, int width, int y0, int y1, int x0, int x1, float scale) {
        IntStream.range(y0, y1).parallel().forEach(y -> {
            for (int x = x0; x < x1; x++) {
                for (int c = 0; c < 3; c++) {
                    float v = HdrTransfer.sanitize(result.get(c, y - inY, x - inX));
                    out[3 * (y * width + x) + c] = HdrTransfer.inverse(v) * scale;
                }
            }
        });
    }

    /** The network's input, made one tile at a time. */
    private record Input(int width, int height, float[] color, float[] albedo, float[] normal, float scale) {
        FeatureMap tile(int channels, int y0, int x0, int h, int w) {
            FeatureMap in = new FeatureMap(channels, h, w);
            IntStream.range(0, Math.min(h, height - y0)).parallel().forEach(ty -> {
                for (int tx = 0; tx < Math.min(w, width - x0); tx++) {
                    int p = 3 * ((y0 + ty) * width + x0 + tx);
                    for (int c = 0; c < 3; c++) {
                        in.set(c, ty, tx, HdrTransfer.forward(HdrTransfer.sanitize(color[p + c] * scale)));
                        if (albedo != null) {
                            in.set(3 + c, ty, tx, clamp(albedo[p + c], 0, 1));
                        }
                        if (normal != null) {
                            in.set(6 + c, ty, tx, clamp(normal[p + c], -1, 1) * 0.5f + 0.5f);
                        }
                    }
                }
            });
            return in;
        }

        /** NaN to 0, then clamped. */
        private static float clamp(float v, float lo, float hi) {
            return v >= lo ? Math.min(v, hi) : v < lo ? lo : 0;
        }
    }

    private static int roundUp(int n) {
        return (int) (((long) n + UNet.ALIGNMENT - 1) / UNet.ALIGNMENT * UNet.ALIGNMENT);
    }

    /** The named network, read from its resource when first asked for. */
    static UNet network(String name, int inputChannels) {
        return NETWORKS.computeIfAbsent(name, n -> {
            String file = n + ".tza";
            try (InputStream in = NeuralDenoiser.class.getResourceAsStream(file)) {
                if (in == null) {
                    throw failure("the weights " + file + " are missing from the strahl jar (dev/strahl/denoise/net/)", null);
                }
                return new UNet(TensorArchive.read(file, in.readAllBytes()), file, inputChannels);
            } catch (TensorArchiveException e) {
                throw failure("damaged weights: " + e.getMessage(), e);
            } catch (IOException e) {
                throw failure("cannot read the weights " + file + ": " + e.getMessage(), e);
            }
        });
    }

    private static UncheckedIOException failure(String what, IOException cause) {
        String message = "strahl's denoiser: " + what;
        return new UncheckedIOException(message, cause != null ? cause : new IOException(message));
    }
}
