package dev.strahl.denoise.net;

import dev.strahl.codec.exr.Half;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/** Tensor archives written for tests, in OIDN's layout: header, the tensors' data, then the table. */
final class TzaFiles {
    private TzaFiles() {
    }

    /** A tensor to write: name, dimensions, type ('f' or 'h'), values. */
    record Entry(String name, int[] dims, char type, float[] values) {
        String layout() {
            return dims.length == 1 ? "x" : "oihw";
        }
    }

    static byte[] write(List<Entry> entries) {
        ByteArrayOutputStream data = new ByteArrayOutputStream();
        List<Long> offsets = new ArrayList<>();
        for (Entry e : entries) {
            while ((12 + data.size()) % 64 != 0) {         // OIDN aligns each tensor's data
                data.write(0);
            }
            offsets.add(12L + data.size());
            ByteBuffer b = ByteBuffer.allocate(e.values().length * (e.type() == 'f' ? 4 : 2)).order(ByteOrder.LITTLE_ENDIAN);
            for (float v : e.values()) {
                if (e.type() == 'f') {
                    b.putFloat(v);
                } else {
                    b.putShort((short) Half.fromFloat(v));
                }
            }
            data.writeBytes(b.array());
        }
        ByteArrayOutputStream table = new ByteArrayOutputStream();
        ByteBuffer count = ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN).putInt(entries.size());
        table.writeBytes(count.array());
        for (int i = 0; i < entries.size(); i++) {
            Entry e = entries.get(i);
            byte[] name = e.name().getBytes(StandardCharsets.US_ASCII);
            ByteBuffer t = ByteBuffer.allocate(2 + name.length + 1 + 5 * e.dims().length + 1 + 8).order(ByteOrder.LITTLE_ENDIAN);
            t.putShort((short) name.length).put(name).put((byte) e.dims().length);
            for (int d : e.dims()) {
                t.putInt(d);
            }
            t.put(e.layout().getBytes(StandardCharsets.US_ASCII)).put((byte) e.type()).putLong(offsets.get(i));
            table.writeBytes(t.array());
        }
        ByteBuffer header = ByteBuffer.allocate(12).order(ByteOrder.LITTLE_ENDIAN);
        header.putShort((short) TensorArchive.MAGIC).put((byte) 2).put((byte) 0).putLong(12L + data.size());
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        all.writeBytes(header.array());
        all.writeBytes(data.toByteArray());
        all.writeBytes(table.toByteArray());
        return all.toByteArray();
    }

    /**
     * A complete, tiny U-Net for 9 input channels: every layer 2 channels wide (dec_conv0: 3), random
     * weights in half precision.
     */
    static List<Entry> tinyUNet(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        String[][] layers = {{"enc_conv0", "9"}, {"enc_conv1", "2"}, {"enc_conv2", "2"}, {"enc_conv3", "2"}, {"enc_conv4", "2"},
            {"enc_conv5a", "2"}, {"enc_conv5b", "2"}, {"dec_conv4a", "4"}, {"dec_conv4b", "2"}, {"dec_conv3a", "4"}, {"dec_conv3b", "2"},
            {"dec_conv2a", "4"}, {"dec_conv2b", "2"}, {"dec_conv1a", "11"}, {"dec_conv1b", "2"}, {"dec_conv0", "2"}};
        List<Entry> entries = new ArrayList<>();
        for (String[] l : layers) {
            int in = Integer.parseInt(l[1]);
            int out = l[0].equals("dec_conv0") ? 3 : 2;
            float[] w = new float[out * in * 9];
            for (int i = 0; i < w.length; i++) {
                w[i] = (float) r.nextDouble(-0.5, 0.5);
            }
            entries.add(new Entry(l[0] + ".weight", new int[] {out, in, 3, 3}, 'h', w));
            entries.add(new Entry(l[0] + ".bias", new int[] {out}, 'h', new float[out]));
        }
        return entries;
    }
}
