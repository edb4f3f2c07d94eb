package dev.strahl.codec;

import dev.strahl.image.Image;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Writes the linear HDR image as a Portable Float Map: the ASCII header {@code "PF\n<w> <h>\n-1.0\n"}
 * (three channels; the negative scale marks little-endian data), then r, g, b as 32-bit floats,
 * rows from the BOTTOM of the image to the top, as the format prescribes. Values are stored as
 * they are, bit for bit (no clamping, NaN and infinities included).
 */
public final class PfmWriter {

    /** Bytes encoded before each write: big enough to amortise the call, small for huge images. */
    private static final int CHUNK_BYTES = 1 << 20;

    private PfmWriter() {
    }

    /** Writes {@code img} to {@code out}; does not close {@code out}. */
    public static void write(Image img, OutputStream out) throws IOException {
        int w = img.width();
        int h = img.height();
        byte[] header = ("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII);
        long total = header.length + 12L * w * h;
        ByteBuffer buf = ByteBuffer.allocate((int) Math.min(total, CHUNK_BYTES)).order(ByteOrder.LITTLE_ENDIAN);
        buf.put(header);                    // one buffer for header and pixels: a single write for small images
        for (int y = h - 1; y >= 0; y--) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) {
                    if (buf.remaining() < Float.BYTES) {   // the header leaves the chunk unaligned
                        out.write(buf.array(), 0, buf.position());
                        buf.clear();
                    }
                    buf.putFloat(img.get(x, y, c));
                }
            }
        }
        out.write(buf.array(), 0, buf.position());
    }
}
