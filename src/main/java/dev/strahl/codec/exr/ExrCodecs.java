package dev.strahl.codec.exr;

import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;

/**
 * The byte-level codecs of the EXR compressions RLE, ZIPS and ZIP (PIZ is {@link Piz}).
 *
 * <p>All three first reorder a chunk's uncompressed bytes and take differences, which turns
 * smooth images into runs of small numbers:
 * <ol>
 * <li>reorder: the bytes at even offsets (0, 2, 4, ...) go to the first half of the buffer, those
 *     at odd offsets to the second half (for a little-endian half, the low bytes and then the
 *     high bytes); with an odd count the first half has one byte more;</li>
 * <li>predict: every byte but the first is replaced by {@code (b[i] - b[i-1] + 128) mod 256},
 *     b[i-1] being the previous byte of the reordered (not yet predicted) buffer.</li>
 * </ol>
 * ZIPS and ZIP then compress with zlib (RFC 1950); RLE with a run-length code of signed count
 * bytes: a count c &lt; 0 is followed by -c literal bytes, a count c &ge; 0 by one byte to repeat
 * c + 1 times.
 */
final class ExrCodecs {
    private ExrCodecs() {
    }

    /** Reorders and predicts {@code n} bytes of {@code raw} into {@code out} (the encoder's side). */
    static void toPredicted(byte[] raw, byte[] out, int n) {
        int half = (n + 1) / 2;
        for (int i = 0, even = 0, odd = half; i < n; i += 2) {
            out[even++] = raw[i];
            if (i + 1 < n) {
                out[odd++] = raw[i + 1];
            }
        }
        int previous = n > 0 ? out[0] : 0;
        for (int i = 1; i < n; i++) {
            int b = out[i];
            out[i] = (byte) (b - previous + 128);
            previous = b;
        }
    }

    /** Undoes {@link #toPredicted}: {@code predicted} (changed in place) back into {@code raw}. */
    static void fromPredicted(byte[] predicted, byte[] raw, int n) {
        for (int i = 1; i < n; i++) {
            predicted[i] = (byte) (predicted[i - 1] + predicted[i] - 128);
        }
        int half = (n + 1) / 2;
        for (int i = 0, even = 0, odd = half; i < n; i += 2) {
            raw[i] = predicted[even++];
            if (i + 1 < n) {
                raw[i + 1] = predicted[odd++];
            }
        }
    }

    /**
     * Run-length decodes {@code in[0, inLength)} into exactly {@code outLength} bytes of {@code out}.
     *
     * @throws CorruptDataException if the code is cut short or yields more or fewer bytes
     */
    static void rleDecode(byte[] in, int inLength, byte[] out, int outLength) throws CorruptDataException {
        int i = 0;
        int o = 0;
        while (i < inLength) {
            int count = in[i++];
            if (count < 0) {
                int n = -count;
                if (n > inLength - i) {
                    throw new CorruptDataException("RLE data end inside a literal run of " + n + " bytes");
                }
                if (n > outLength - o) {
                    throw new CorruptDataException("RLE data decode to more than the chunk's " + outLength + " bytes");
                }
                System.arraycopy(in, i, out, o, n);
                i += n;
                o += n;
            } else {
                int n = count + 1;
                if (i >= inLength) {
                    throw new CorruptDataException("RLE data end before the byte of a run");
                }
                if (n > outLength - o) {
                    throw new CorruptDataException("RLE data decode to more than the chunk's " + outLength + " bytes");
                }
                java.util.Arrays.fill(out, o, o + n, in[i++]);
                o += n;
            }
        }
        if (o != outLength) {
            throw new CorruptDataException("RLE data decode to " + o + " bytes, the chunk needs " + outLength);
        }
    }

    /**
     * Run-length encodes {@code n} bytes: runs of 3 to 128 equal bytes as (length − 1, byte),
     * everything else as literal runs of up to 127 bytes.
     *
     * @param out room for {@code n + n / 127 + 2} bytes (the worst case)
     * @return the encoded length
     */
    static int rleEncode(byte[] in, int n, byte[] out) {
        int o = 0;
        int i = 0;
        int literalStart = 0;
        while (i < n) {
            int run = 1;
            while (i + run < n && run < 128 && in[i + run] == in[i]) {
                run++;
            }
            if (run >= 3) {
                o = literals(in, literalStart, i, out, o);
                out[o++] = (byte) (run - 1);
                out[o++] = in[i];
                i += run;
                literalStart = i;
            } else {
                i += run;
            }
        }
        return literals(in, literalStart, n, out, o);
    }

    private static int literals(byte[] in, int from, int to, byte[] out, int o) {
        while (from < to) {
            int k = Math.min(127, to - from);
            out[o++] = (byte) -k;
            System.arraycopy(in, from, out, o, k);
            o += k;
            from += k;
        }
        return o;
    }

    /**
     * Inflates zlib data into exactly {@code outLength} bytes.
     *
     * @throws CorruptDataException if the stream is malformed, ends early or holds more
     */
    static void inflate(Inflater inflater, byte[] in, int inLength, byte[] out, int outLength) throws CorruptDataException {
        inflater.reset();
        inflater.setInput(in, 0, inLength);
        int got = 0;
        try {
            while (got < outLength) {
                int k = inflater.inflate(out, got, outLength - got);
                if (k == 0) {
                    if (inflater.needsDictionary()) {
                        throw new CorruptDataException("zlib data need a preset dictionary");
                    }
                    if (inflater.finished() || inflater.needsInput()) {
                        break;
                    }
                }
                got += k;
            }
            if (got < outLength) {
                throw new CorruptDataException("zlib data end after " + got + " bytes, the chunk needs " + outLength);
            }
            if (!inflater.finished()) {
                byte[] one = new byte[1];
                if (inflater.inflate(one) > 0) {
                    throw new CorruptDataException("zlib data decode to more than the chunk's " + outLength + " bytes");
                }
                if (!inflater.finished()) {
                    throw new CorruptDataException("zlib data do not end where the chunk's " + outLength + " bytes do (cut short?)");
                }
            }
        } catch (DataFormatException e) {
            throw new CorruptDataException("zlib data are corrupt (" + e.getMessage() + ")");
        }
    }

    /**
     * Deflates {@code n} bytes with zlib.
     *
     * @param out room for at least {@code n} bytes
     * @return the compressed length, or -1 if it would not be shorter than {@code n}
     */
    static int deflate(Deflater deflater, byte[] in, int n, byte[] out) {
        deflater.reset();
        deflater.setInput(in, 0, n);
        deflater.finish();
        int o = 0;
        while (!deflater.finished()) {
            if (o == out.length) {
                return -1;                   // as long as the input or longer: stored raw
            }
            o += deflater.deflate(out, o, out.length - o);
        }
        return o < n ? o : -1;
    }
}
