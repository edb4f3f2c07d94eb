package dev.strahl.units;

import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.util.Arrays;

/**
 * One piece of a cluster render: samples [{@code firstSample}, {@code endSample}) of the pixels of
 * one tile (or of those a mask names: the ones adaptive sampling has not found converged), with the state those pixels had before (their sample counts and the film's sums: r, g,
 * b, squared luminance and, with feature buffers, the feature sums). A
 * member renders it by going on from that state, adding each pixel's samples in index order, and
 * sends the same unit back with the new state. So a unit's result is the very sums the local
 * render holds after the same samples, and the coordinator merges it by replacing the tile's
 * state: no floating-point sum is ever split and re-added in another order.
 *
 * <p>Wire form (big-endian): int x0, y0, width, height, firstSample, endSample, sums per pixel;
 * int invalid samples, long rays (both 0 on the way out); then either int -1 and one count for
 * every pixel, or the count of every pixel; then int 0 (every pixel takes the samples) or 1 and a byte
 * per pixel (1 if it takes them); then the sums as doubles, pixel by pixel, row by row.
 */
public final class WorkUnit {
    /** Largest tile edge a unit may have (a check on what arrives from the network). */
    public static final int MAX_EDGE = 256;
    /** Most sums a pixel may carry (a check on what arrives from the network). */
    public static final int MAX_SUMS = 16;

    private final int x0;
    private final int y0;
    private final int width;
    private final int height;
    private final int firstSample;
    private final int endSample;
    private final int[] counts;
    private final double[] sums;
    private final int sumsPerPixel;
    /** Per pixel, row by row: whether it takes the samples; null when every pixel does. */
    private final boolean[] renders;
    private int invalidSamples;
    private long rays;

    /**
     * A unit with the given state; the arrays are taken over, not copied.
     *
     * @param x0          left column of the tile
     * @param y0          top row of the tile
     * @param width       tile width
     * @param height      tile height
     * @param firstSample the first sample index to render
     * @param endSample   one past the last sample index
     * @param counts      per pixel, row by row within the tile: the samples it holds
     * @param sums        per pixel, the same number of sums each (r, g, b first; at most {@value #MAX_SUMS})
     */
    public WorkUnit(int x0, int y0, int width, int height, int firstSample, int endSample, int[] counts, double[] sums) {
        this(x0, y0, width, height, firstSample, endSample, counts, sums, null);
    }

    /**
     * A unit whose samples only some pixels take; the arrays are taken over, not copied.
     *
     * @param x0          left column of the tile
     * @param y0          top row of the tile
     * @param width       tile width
     * @param height      tile height
     * @param firstSample the first sample index to render
     * @param endSample   one past the last sample index
     * @param counts      per pixel, row by row within the tile: the samples it holds
     * @param sums        per pixel, the same number of sums each (r, g, b first; at most {@value #MAX_SUMS})
     * @param renders     per pixel, row by row: whether it takes the samples; null for every pixel
     */
    public WorkUnit(int x0, int y0, int width, int height, int firstSample, int endSample, int[] counts, double[] sums, boolean[] renders) {
        if (width <= 0 || height <= 0 || width > MAX_EDGE || height > MAX_EDGE || x0 < 0 || y0 < 0) {
            throw new IllegalArgumentException("bad unit tile " + x0 + "," + y0 + " " + width + "x" + height);
        }
        if (firstSample < 0 || endSample < firstSample) {
            throw new IllegalArgumentException("bad unit sample range " + firstSample + ".." + endSample);
        }
        int pixels = width * height;
        if (counts.length != pixels || sums.length % pixels != 0 || sums.length < 3 * pixels || sums.length > MAX_SUMS * pixels) {
            throw new IllegalArgumentException("unit arrays do not fit its tile");
        }
        if (renders != null && renders.length != pixels) {
            throw new IllegalArgumentException("unit mask does not fit its tile");
        }
        this.renders = renders;
        this.sumsPerPixel = sums.length / pixels;
        this.x0 = x0;
        this.y0 = y0;
        this.width = width;
        this.height = height;
        this.firstSample = firstSample;
        this.endSample = endSample;
        this.counts = counts;
        this.sums = sums;
    }

    public int x0() {
        return x0;
    }

    public int y0() {
        return y0;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int firstSample() {
        return firstSample;
    }

    public int endSample() {
        return endSample;
    }

    /** Per pixel of the tile, row by row: its sample count (the renderer updates it in place). */
    public int[] counts() {
        return counts;
    }

    /** Per pixel of the tile, {@link #sumsPerPixel()} sums each (the renderer updates them in place). */
    public double[] sums() {
        return sums;
    }

    /**
     * Whether a pixel takes this unit's samples.
     *
     * @param i the pixel, row by row within the tile
     * @return false for a pixel adaptive sampling has found converged
     */
    public boolean renders(int i) {
        return renders == null || renders[i];
    }

    /** How many sums each pixel carries: the film's per-pixel state. */
    public int sumsPerPixel() {
        return sumsPerPixel;
    }

    /** Samples of this unit that were NaN or infinite (added as black). */
    public int invalidSamples() {
        return invalidSamples;
    }

    /** Rays the unit traced. */
    public long rays() {
        return rays;
    }

    /**
     * Records what rendering the unit cost.
     *
     * @param invalid NaN or infinite samples
     * @param traced  rays traced
     */
    public void recordFigures(int invalid, long traced) {
        this.invalidSamples = invalid;
        this.rays = traced;
    }

    /** Camera samples this unit adds to its tile (pixels that already hold more add none). */
    public long samples() {
        long n = 0;
        for (int i = 0; i < counts.length; i++) {
            n += renders(i) ? Math.max(0, endSample - Math.max(firstSample, counts[i])) : 0;
        }
        return n;
    }

    /** Bytes of the wire form. */
    public int wireSize() {
        boolean uniform = uniformCount() >= 0;
        return 8 * 4 + 8 + (uniform ? 8 : 4 * counts.length) + 4 + (renders != null ? renders.length : 0) + 8 * sums.length;
    }

    private int uniformCount() {
        int c = counts[0];
        for (int v : counts) {
            if (v != c) {
                return -1;
            }
        }
        return c;
    }

    /**
     * The wire form, after {@code headroom} bytes left for the caller (a status byte, say).
     *
     * @param headroom bytes to leave free at the start
     * @return the bytes
     */
    public byte[] encode(int headroom) {
        int uniform = uniformCount();
        byte[] bytes = new byte[headroom + wireSize()];
        ByteBuffer b = ByteBuffer.wrap(bytes, headroom, bytes.length - headroom);
        b.putInt(x0).putInt(y0).putInt(width).putInt(height).putInt(firstSample).putInt(endSample).putInt(sumsPerPixel)
                .putInt(invalidSamples).putLong(rays);
        if (uniform >= 0) {
            b.putInt(-1).putInt(uniform);
        } else {
            b.asIntBuffer().put(counts);
            b.position(b.position() + 4 * counts.length);
        }
        b.putInt(renders != null ? 1 : 0);
        if (renders != null) {
            for (boolean r : renders) {
                b.put((byte) (r ? 1 : 0));
            }
        }
        b.asDoubleBuffer().put(sums);
        return bytes;
    }

    /**
     * Reads a unit {@link #encode} wrote.
     *
     * @param bytes  the bytes
     * @param offset where the unit starts
     * @return the unit
     * @throws IOException if the bytes are no unit
     */
    public static WorkUnit decode(byte[] bytes, int offset) throws IOException {
        try {
            ByteBuffer b = ByteBuffer.wrap(bytes, offset, bytes.length - offset);
            int x0 = b.getInt();
            int y0 = b.getInt();
            int w = b.getInt();
            int h = b.getInt();
            int first = b.getInt();
            int end = b.getInt();
            int perPixel = b.getInt();
            int invalid = b.getInt();
            long rays = b.getLong();
            if (w <= 0 || h <= 0 || w > MAX_EDGE || h > MAX_EDGE || perPixel < 3 || perPixel > MAX_SUMS) {
                throw new IOException("not a work unit (tile " + w + "x" + h + ", " + perPixel + " sums per pixel)");
            }
            int[] counts = new int[w * h];
            int c0 = b.getInt(b.position());
            if (c0 == -1) {
                b.getInt();
                Arrays.fill(counts, b.getInt());
            } else {
                b.asIntBuffer().get(counts);
                b.position(b.position() + 4 * counts.length);
            }
            int masked = b.getInt();
            if (masked != 0 && masked != 1) {
                throw new IOException("not a work unit (mask flag " + masked + ")");
            }
            boolean[] renders = masked == 1 ? new boolean[w * h] : null;
            for (int i = 0; renders != null && i < renders.length; i++) {
                renders[i] = b.get() != 0;
            }
            double[] sums = new double[perPixel * w * h];
            b.asDoubleBuffer().get(sums);
            WorkUnit unit = new WorkUnit(x0, y0, w, h, first, end, counts, sums, renders);
            unit.recordFigures(invalid, rays);
            return unit;
        } catch (BufferUnderflowException | IllegalArgumentException e) {
            throw new IOException("not a work unit: " + e, e);
        }
    }
}
