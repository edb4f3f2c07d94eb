package dev.strahl.codec.exr;

import java.util.List;

/**
 * Decoding of PIZ-compressed chunks (lossless: a wavelet transform whose coefficients are Huffman
 * coded). A chunk's uncompressed data are seen as 16-bit words (a HALF sample is one word; FLOAT
 * and UINT samples are two, the low word first), which the compressor has
 * <ol>
 * <li>regrouped by channel: all the words of the chunk's first channel, row after row, then those of
 *     the second channel, and so on;</li>
 * <li>mapped through a table to dense codes: the words that occur are numbered 0, 1, 2, ... in
 *     increasing order (0 always counts as occurring); a bitmap of which words occur is stored;</li>
 * <li>transformed, per channel and per word of a sample, by a two-dimensional Haar-like integer
 *     wavelet ({@link #waveletDecode});</li>
 * <li>Huffman coded with a run-length escape ({@link PizHuffman}).</li>
 * </ol>
 * The stored block: the bitmap's first and last non-zero byte index (two little-endian uint16),
 * those bitmap bytes (none if first &gt; last), the length of the Huffman data (int32), the Huffman
 * data. Decoding runs the steps backwards.
 */
final class Piz {
    /** Bytes of the bitmap of occurring 16-bit values. */
    static final int BITMAP_BYTES = 1 << 13;

    private Piz() {
    }

    /**
     * Decodes one chunk into {@code out} (scan-line order, as for NONE).
     *
     * @param width    pixels per line
     * @param lines    lines in this chunk
     * @param channels the channels, in the order of the data
     */
    static void decode(byte[] in, int inLength, byte[] out, int outLength, int width, int lines, List<ExrHeader.Channel> channels)
            throws CorruptDataException {
        decode(in, inLength, out, outLength, width, lines, channels, new Scratch());
    }

    /**
     * The arrays every chunk needs whatever its size, kept from chunk to chunk: a file of many small
     * chunks (200 000 of 32 lines in 9.6 MB) paid 380 us each for making and filling them, 77 s in all.
     */
    static final class Scratch {
        final byte[] bitmap = new byte[BITMAP_BYTES];
        final char[] values = new char[1 << 16];
        final int[] table = new int[1 << PizHuffman.TABLE_BITS];
    }

    /** As above, with arrays kept from the previous chunk. */
    static void decode(byte[] in, int inLength, byte[] out, int outLength, int width, int lines, List<ExrHeader.Channel> channels,
            Scratch scratch) throws CorruptDataException {
        if (inLength < 4) {
            throw new CorruptDataException("PIZ data end inside the bitmap range");
        }
        int first = u16(in, 0);
        int last = u16(in, 2);
        if (first >= BITMAP_BYTES || last >= BITMAP_BYTES) {
            throw new CorruptDataException("PIZ bitmap range " + first + ".." + last + " is beyond its " + BITMAP_BYTES + " bytes");
        }
        byte[] bitmap = scratch.bitmap;
        java.util.Arrays.fill(bitmap, (byte) 0);
        int pos = 4;
        if (first <= last) {
            int n = last - first + 1;
            if (n > inLength - pos) {
                throw new CorruptDataException("PIZ data end inside the bitmap");
            }
            System.arraycopy(in, pos, bitmap, first, n);
            pos += n;
        }
        char[] values = scratch.values;
        int maxCode = valuesOfCodes(bitmap, first, last, values);
        if (4 > inLength - pos) {
            throw new CorruptDataException("PIZ data end before the length of the Huffman data");
        }
        int length = u16(in, pos) | u16(in, pos + 2) << 16;
        pos += 4;
        if (length < 0 || length > inLength - pos) {
            throw new CorruptDataException("PIZ Huffman data claim " + Integer.toUnsignedString(length) + " bytes, but "
                    + (inLength - pos) + " follow");
        }
        char[] words = new char[outLength / 2];
        PizHuffman.decode(in, pos, length, words, scratch.table);

        int start = 0;
        for (ExrHeader.Channel c : channels) {
            int wordsPerSample = c.type().bytes() / 2;
            for (int j = 0; j < wordsPerSample; j++) {
                waveletDecode(words, start + j, width, wordsPerSample, lines, width * wordsPerSample, maxCode);
            }
            start += width * lines * wordsPerSample;
        }
        for (int i = 0; i < words.length; i++) {
            words[i] = words[i] <= maxCode ? values[words[i]] : 0;       // codes past the last map to 0
        }
        // back from one block per channel to scan lines of all channels, little-endian bytes
        int o = 0;
        int[] planeStart = new int[channels.size()];
        for (int c = 0, s = 0; c < channels.size(); c++) {
            planeStart[c] = s;
            s += width * lines * (channels.get(c).type().bytes() / 2);
        }
        for (int y = 0; y < lines; y++) {
            for (int c = 0; c < channels.size(); c++) {
                int count = width * (channels.get(c).type().bytes() / 2);
                int from = planeStart[c] + y * count;
                for (int k = 0; k < count; k++) {
                    char w = words[from + k];
                    out[o++] = (byte) w;
                    out[o++] = (byte) (w >>> 8);
                }
            }
        }
        assert o == outLength;
    }

    private static int u16(byte[] b, int at) {
        return (b[at] & 0xff) | (b[at + 1] & 0xff) << 8;
    }

    /**
     * Fills {@code values[code]} with the 16-bit value of each dense code: the values whose bit is
     * set in the bitmap, and 0, in increasing order (codes past the last map to 0: the caller's
     * business). Only the bitmap's bytes {@code first..last} can be set: the rest is not looked at.
     *
     * @return the largest code
     */
    static int valuesOfCodes(byte[] bitmap, int first, int last, char[] values) {
        int k = 0;
        values[k++] = 0;
        for (int i = first; i <= last; i++) {
            if (bitmap[i] == 0) {
                continue;
            }
            for (int bit = 0; bit < 8; bit++) {
                int v = i << 3 | bit;
                if (v != 0 && (bitmap[i] & (1 << bit)) != 0) {
                    values[k++] = (char) v;
                }
            }
        }
        return k - 1;
    }

    /**
     * Inverts the PIZ wavelet transform of one component, in place. The component's samples are
     * {@code w[start + x·ox + y·oy]} for x &lt; nx, y &lt; ny.
     *
     * <p>The forward transform runs over levels of block size 2, 4, 8, ... up to the largest power
     * of two that is at most min(nx, ny). At block size s (half h = s/2), for every s×s block whose
     * corner (x, y) has x ≤ nx − s and y ≤ ny − s, the four samples at (x, y), (x+h, y), (x, y+h),
     * (x+h, y+h) are transformed by pairs: horizontally first ((x, y) with (x+h, y), and (x, y+h)
     * with (x+h, y+h)), then vertically (each result at x with its partner at y+h, likewise at
     * x+h). Where nx has the bit h set, the column just right of the last block is transformed by
     * vertical pairs; where ny has it set, the row just below the last block by horizontal pairs.
     * A pair (a, b) becomes (l, h) by {@link #pairDecode}'s inverse. Decoding runs the levels from
     * the largest block size down, and within a block undoes the vertical pairs first.
     *
     * @param maxCode the largest value of the data: below 2^14 the pairs use plain 16-bit
     *                arithmetic, otherwise the modular variant
     */
    static void waveletDecode(char[] w, int start, int nx, int ox, int ny, int oy, int maxCode) {
        boolean small = maxCode < 1 << 14;
        int n = Math.min(nx, ny);
        for (int s = Integer.highestOneBit(n); s >= 2; s >>= 1) {
            int h = s >> 1;
            int dx = ox * h;
            int dy = oy * h;
            int y = 0;
            for (; y <= ny - s; y += s) {
                int row = start + y * oy;
                int x = 0;
                for (; x <= nx - s; x += s) {
                    int p00 = row + x * ox;
                    int p01 = p00 + dx;
                    int p10 = p00 + dy;
                    int p11 = p10 + dx;
                    pairDecode(w, p00, p10, small);
                    pairDecode(w, p01, p11, small);
                    pairDecode(w, p00, p01, small);
                    pairDecode(w, p10, p11, small);
                }
                if ((nx & h) != 0) {
                    int p00 = row + x * ox;
                    pairDecode(w, p00, p00 + dy, small);
                }
            }
            if ((ny & h) != 0) {
                int row = start + y * oy;
                for (int x = 0; x <= nx - s; x += s) {
                    int p00 = row + x * ox;
                    pairDecode(w, p00, p00 + dx, small);
                }
            }
        }
    }

    /**
     * Replaces the pair (l, h) at {@code w[i]}, {@code w[j]} with the (a, b) it was made from.
     * The forward step, for data below 2^14 (as signed 16-bit numbers): l = ⌊(a + b) / 2⌋,
     * h = a − b; so a = l + ⌊h / 2⌋ + (h mod 2) and b = a − h. For larger data, all modulo 2^16:
     * a' = a + 2^15, l = ⌊(a' + b) / 2⌋ (+ 2^15 if a' &lt; b), h = a' − b; so
     * b = l − ⌊h / 2⌋ and a = h + b − 2^15.
     */
    static void pairDecode(char[] w, int i, int j, boolean small) {
        if (small) {
            int l = (short) w[i];
            int h = (short) w[j];
            int a = l + (h & 1) + (h >> 1);
            w[i] = (char) a;
            w[j] = (char) (a - h);
        } else {
            int l = w[i];
            int h = w[j];
            int b = (l - (h >> 1)) & 0xffff;
            w[i] = (char) ((h + b - (1 << 15)) & 0xffff);
            w[j] = (char) b;
        }
    }
}
