package dev.strahl.medium;

import dev.strahl.codec.ImageFormatException;
import dev.strahl.codec.ImageLimits;
import dev.strahl.codec.Printable;
import dev.strahl.files.FileReads;
import java.io.EOFException;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Locale;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A Mitsuba volume file ({@code .vol}, the format of Mitsuba 3's {@code gridvolume}) holding a
 * density grid: the grid and the bounding box its header names.
 *
 * <p>The format, little-endian: the bytes {@code 'V' 'O' 'L'}, the version byte 3, an int32
 * encoding (1: float32), int32 sizes X, Y, Z, an int32 channel count, six float32 (xmin, ymin,
 * zmin, xmax, ymax, zmax), then X·Y·Z·channels float32 values, x fastest, then y, then z. strahl
 * reads one channel (a density); Mitsuba's 3- and 6-channel files (colours) are refused, as are
 * other versions and encodings. Every size in the header is checked against the file's length and
 * the free heap ({@link ImageLimits#heapShortfall}, the readers' one heap check) before any voxel
 * memory is allocated, so a corrupt or absurd header is a one-line
 * {@link ImageFormatException} naming the file, never an {@link OutOfMemoryError}. Bytes after the
 * values are ignored.
 *
 * @param grid the densities (finite and ≥ 0)
 * @param min  the header box's lower corner (as stored; it may be degenerate)
 * @param max  the header box's upper corner
 */
public record VolFile(DensityGrid grid, Vector3dc min, Vector3dc max) {
    /** Bytes before the values. */
    public static final int HEADER_BYTES = 48;
    private static final int CHUNK_BYTES = 1 << 20;

    /**
     * Reads a {@code .vol} file.
     *
     * @throws ImageFormatException if it is not a one-channel float32 VOL version 3 file, is
     *                              truncated, holds a negative or non-finite density, or its grid
     *                              does not fit the heap
     * @throws IOException          if the file cannot be read at all (missing, a directory)
     */
    public static VolFile read(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new ImageFormatException(file, "is a directory, not a .vol file");
        }
        FileReads.note(file);
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = ch.size();
            if (size < HEADER_BYTES) {
                throw new ImageFormatException(file, "truncated: " + size + " bytes, but a VOL header alone has " + HEADER_BYTES);
            }
            ByteBuffer head = ByteBuffer.allocate(HEADER_BYTES).order(ByteOrder.LITTLE_ENDIAN);
            readFully(ch, head, file);
            head.flip();
            byte[] magic = new byte[3];
            head.get(magic);
            if (magic[0] != 'V' || magic[1] != 'O' || magic[2] != 'L') {
                throw new ImageFormatException(file, "not a Mitsuba volume file: it starts with '"
                        + Printable.bytes(magic, 0, magic.length) + "', not 'VOL'");
            }
            int version = head.get() & 0xff;
            if (version != 3) {
                throw new ImageFormatException(file, "VOL version " + version + ": strahl reads version 3");
            }
            int encoding = head.getInt();
            if (encoding != 1) {
                throw new ImageFormatException(file, "VOL encoding " + encoding + ": strahl reads encoding 1 (float32)");
            }
            int nx = head.getInt(), ny = head.getInt(), nz = head.getInt(), channels = head.getInt();
            if (nx <= 0 || ny <= 0 || nz <= 0) {
                throw new ImageFormatException(file, "grid size must be positive, got " + nx + "x" + ny + "x" + nz);
            }
            if (channels != 1) {
                throw new ImageFormatException(file, "holds " + channels + " channels per voxel; a density grid has one");
            }
            Vector3d min = new Vector3d(head.getFloat(), head.getFloat(), head.getFloat());
            Vector3d max = new Vector3d(head.getFloat(), head.getFloat(), head.getFloat());
            double voxels = (double) nx * ny * nz;       // up to 2^93: a long could overflow
            if (voxels > ImageLimits.MAX_ARRAY) {
                throw new ImageFormatException(file, String.format(Locale.ROOT, "a %dx%dx%d grid is too large to load (%.3g voxels; at most"
                        + " %d fit in one array)", nx, ny, nz, voxels, ImageLimits.MAX_ARRAY));
            }
            long bytes = (long) voxels * Float.BYTES;
            if (bytes > size - HEADER_BYTES) {
                throw new ImageFormatException(file, String.format(Locale.ROOT, "truncated: a %dx%dx%d grid needs %d bytes after the"
                        + " header, the file holds %d", nx, ny, nz, bytes, size - HEADER_BYTES));
            }
            String shortfall = ImageLimits.heapShortfall(bytes + Math.min(bytes, CHUNK_BYTES));
            if (shortfall != null) {
                throw new ImageFormatException(file, String.format(Locale.ROOT, "a %dx%dx%d grid %s", nx, ny, nz, shortfall));
            }
            float[] values = new float[(int) (bytes / Float.BYTES)];
            readValues(ch, values, file);
            try {
                return new VolFile(new DensityGrid(nx, ny, nz, values), min, max);
            } catch (IllegalArgumentException e) {
                throw new ImageFormatException(file, e.getMessage());
            }
        }
    }

    private static void readValues(FileChannel ch, float[] values, Path file) throws IOException {
        ByteBuffer buf = ByteBuffer.allocate((int) Math.min(4L * values.length, CHUNK_BYTES)).order(ByteOrder.LITTLE_ENDIAN);
        int at = 0;
        while (at < values.length) {
            buf.clear().limit((int) Math.min(4L * (values.length - at), buf.capacity()));
            readFully(ch, buf, file);
            buf.flip();
            int n = buf.remaining() / Float.BYTES;
            buf.asFloatBuffer().get(values, at, n);
            at += n;
        }
    }

    private static void readFully(FileChannel ch, ByteBuffer buf, Path file) throws IOException {
        while (buf.hasRemaining()) {
            if (ch.read(buf) < 0) {
                throw new ImageFormatException(file, "truncated: the file ended while reading it", new EOFException());
            }
        }
    }
}
