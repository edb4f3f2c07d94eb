package dev.strahl.medium;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/** Writes {@code .vol} files for the tests (one channel, float32, version 3). */
public final class VolFiles {
    private VolFiles() {}

    /** The bytes of a VOL file of X·Y·Z values (x fastest) with the header box (min, max). */
    public static byte[] bytes(int nx, int ny, int nz, float[] box, float[] values) {
        ByteBuffer buf = ByteBuffer.allocate(VolFile.HEADER_BYTES + 4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
        buf.put((byte) 'V').put((byte) 'O').put((byte) 'L').put((byte) 3).putInt(1).putInt(nx).putInt(ny).putInt(nz).putInt(1);
        for (float b : box) {
            buf.putFloat(b);
        }
        buf.asFloatBuffer().put(values);
        return buf.array();
    }

    /** Writes such a file and returns its path. */
    public static Path write(Path file, int nx, int ny, int nz, float[] box, float[] values) throws IOException {
        return Files.write(file, bytes(nx, ny, nz, box, values));
    }
}
