package dev.strahl.io;

import dev.strahl.codec.PfmWriter;
import dev.strahl.image.Image;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;

/**
 * Fuzzing inputs for the PFM reader: headers from the format's grammar with hostile tokens (tags,
 * sizes up to 2^31 and beyond, scales of zero, NaN, both signs, odd separators and CR LF) followed
 * by too little, enough or too much pixel data, and files from strahl's own writer mutated.
 */
final class PfmFuzzInputs {
    static final List<String> WORDS = List.of("PF", "Pf", "P6", "-1.0", "1.0", "0", "NaN", "1e400", "2147483647", "4294967296", "\r\n",
            "\n", " ", "\t", "-0", "+1");

    private static final String[] SIZES = {"0", "1", "2", "3", "7", "64", "-1", "+5", "2147483647", "2147483648", "46341", "100000",
        "01", "1e3", "", "x"};
    private static final String[] SCALES = {"-1.0", "1.0", "-1", "1", "0", "-0.0", "NaN", "Infinity", "1e400", "-2.5", ".5", "1.", "e", ""};
    private static final String[] SEPARATORS = {"\n", " ", "\r\n", "\t", "  \n", "\n\n", ""};

    private PfmFuzzInputs() {}

    /** Files of strahl's writer: colour and grey, both byte orders, small and odd sizes. */
    static List<byte[]> seeds() {
        List<byte[]> seeds = new ArrayList<>();
        SplittableRandom r = new SplittableRandom(11);
        for (int[] size : new int[][] {{1, 1}, {3, 2}, {7, 5}}) {
            float[] rgb = new float[3 * size[0] * size[1]];
            for (int i = 0; i < rgb.length; i++) {
                rgb[i] = (float) r.nextGaussian();
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            try {
                PfmWriter.write(new Image(size[0], size[1], rgb), out);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            seeds.add(out.toByteArray());
        }
        seeds.add(grey(4, 3, ByteOrder.BIG_ENDIAN));
        seeds.add(grey(2, 2, ByteOrder.LITTLE_ENDIAN));
        return seeds;
    }

    private static byte[] grey(int w, int h, ByteOrder order) {
        String head = "Pf\n" + w + " " + h + "\n" + (order == ByteOrder.LITTLE_ENDIAN ? "-1.0" : "1.0") + "\n";
        ByteBuffer b = ByteBuffer.allocate(4 * w * h).order(order);
        for (int i = 0; i < w * h; i++) {
            b.putFloat(i * 0.5f);
        }
        return concat(head.getBytes(StandardCharsets.US_ASCII), b.array());
    }

    /** Headers from the grammar, each token right or hostile, then pixel data of about the right length, or not. */
    static Arbitrary<byte[]> random() {
        return Arbitraries.longs().map(seed -> random(new SplittableRandom(seed)));
    }

    private static byte[] random(SplittableRandom r) {
        String tag = r.nextInt(8) == 0 ? pick(r, new String[] {"P6", "pf", "PFX", "", "\u0000F", "F"}) : r.nextBoolean() ? "PF" : "Pf";
        int w = r.nextInt(1, 9);
        int h = r.nextInt(1, 9);
        String width = r.nextInt(5) == 0 ? pick(r, SIZES) : Integer.toString(w);
        String height = r.nextInt(5) == 0 ? pick(r, SIZES) : Integer.toString(h);
        String scale = r.nextInt(5) == 0 ? pick(r, SCALES) : r.nextBoolean() ? "-1.0" : "1.0";
        String head = tag + sep(r) + width + sep(r) + height + sep(r) + scale + (r.nextInt(10) == 0 ? sep(r) : "\n");
        int channels = tag.equals("Pf") ? 1 : 3;
        int floats = w * h * channels;
        int n = switch (r.nextInt(6)) {
            case 0 -> r.nextInt(floats + 1);              // too little
            case 1 -> floats + 1 + r.nextInt(8);          // trailing data
            default -> floats;
        };
        ByteBuffer b = ByteBuffer.allocate(4 * n + (r.nextInt(8) == 0 ? 1 + r.nextInt(3) : 0));
        for (int i = 0; i < n; i++) {
            b.putInt(r.nextInt(4) == 0 ? r.nextInt() : Float.floatToIntBits((float) r.nextGaussian()));
        }
        return concat(head.getBytes(StandardCharsets.ISO_8859_1), b.array());
    }

    private static String sep(SplittableRandom r) {
        return r.nextInt(6) == 0 ? pick(r, SEPARATORS) : r.nextBoolean() ? "\n" : " ";
    }

    private static String pick(SplittableRandom r, String[] options) {
        return options[r.nextInt(options.length)];
    }

    private static byte[] concat(byte[] a, byte[] b) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(a);
        out.writeBytes(b);
        return out.toByteArray();
    }
}
