package dev.strahl.medium;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.codec.ImageFormatException;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code .vol} reader: a file written in Mitsuba's layout comes back voxel for voxel with its
 * header box, and every kind of bad file is one {@link ImageFormatException} that names the file
 * and says what is wrong — checked from the header before any voxel memory is allocated, so that
 * a header claiming 2³¹ voxels or more than the heap holds is refused at once.
 */
class VolFileTest {
    private static final float[] BOX = {-0.5f, 0, -0.5f, 0.5f, 1, 0.5f};

    @TempDir
    Path dir;

    private Path file(byte[] bytes) throws IOException {
        return Files.write(dir.resolve("smoke.vol"), bytes);
    }

    private static byte[] valid() {
        float[] v = new float[3 * 2 * 4];
        for (int i = 0; i < v.length; i++) {
            v[i] = 0.25f * i;
        }
        return VolFiles.bytes(3, 2, 4, BOX, v);
    }

    private static byte[] withInt(byte[] b, int offset, int value) {
        byte[] c = b.clone();
        ByteBuffer.wrap(c).order(ByteOrder.LITTLE_ENDIAN).putInt(offset, value);
        return c;
    }

    @Test
    void readsTheGridXFastestAndTheHeaderBox() throws IOException {
        VolFile vol = VolFile.read(file(valid()));
        DensityGrid g = vol.grid();
        assertThat(new int[] {g.sizeX(), g.sizeY(), g.sizeZ()}).containsExactly(3, 2, 4);
        assertThat(g.voxel(2, 1, 3)).isEqualTo(0.25 * ((3 * 2 + 1) * 3 + 2));
        assertThat(g.voxel(1, 0, 0)).isEqualTo(0.25);
        assertThat(g.voxel(0, 1, 0)).isEqualTo(0.75);
        assertThat(vol.min()).isEqualTo(new Vector3d(-0.5, 0, -0.5));
        assertThat(vol.max()).isEqualTo(new Vector3d(0.5, 1, 0.5));
        byte[] longer = Arrays.copyOf(valid(), valid().length + 10);
        assertThat(VolFile.read(file(longer)).grid().voxel(2, 1, 3)).as("bytes after the values are ignored").isEqualTo(g.voxel(2, 1, 3));
    }

    @Test
    void badFilesAreOneLineNamingTheFile() throws IOException {
        byte[] v = valid();
        assertRefused(Arrays.copyOf(v, 30), "truncated: 30 bytes");
        assertRefused(Arrays.copyOf(v, v.length - 1), "truncated: a 3x2x4 grid needs 96 bytes after the header, the file holds 95");
        byte[] magic = v.clone();
        magic[0] = 'P';
        assertRefused(magic, "not a Mitsuba volume file: it starts with 'POL'");
        byte[] version = v.clone();
        version[3] = 2;
        assertRefused(version, "VOL version 2");
        assertRefused(withInt(v, 4, 2), "encoding 2");
        assertRefused(withInt(v, 20, 3), "holds 3 channels per voxel; a density grid has one");
        assertRefused(withInt(v, 8, 0), "grid size must be positive, got 0x2x4");
        assertRefused(withInt(v, 16, -4), "grid size must be positive, got 3x2x-4");
        byte[] negative = v.clone();
        ByteBuffer.wrap(negative).order(ByteOrder.LITTLE_ENDIAN).putFloat(VolFile.HEADER_BYTES + 4 * 7, -1);
        assertRefused(negative, "voxel (1, 0, 1) holds -1.0");
        byte[] nan = v.clone();
        ByteBuffer.wrap(nan).order(ByteOrder.LITTLE_ENDIAN).putFloat(VolFile.HEADER_BYTES, Float.NaN);
        assertRefused(nan, "voxel (0, 0, 0) holds NaN");
    }

    @Test
    void hugeHeadersAreRefusedBeforeAllocating() throws IOException {
        byte[] v = valid();
        byte[] huge = withInt(withInt(withInt(v, 8, 2_000_000), 12, 2_000_000), 16, 2_000_000);
        assertRefused(huge, "a 2000000x2000000x2000000 grid is too large to load (8.00e+18 voxels");
        assertRefused(withInt(withInt(v, 8, 1290), 12, 1290), "truncated: a 1290x1290x4 grid needs 26625600 bytes after the header");
        assertThatThrownBy(() -> VolFile.read(dir)).isInstanceOf(ImageFormatException.class).hasMessageContaining("is a directory");
        assertThatThrownBy(() -> VolFile.read(dir.resolve("missing.vol"))).isInstanceOf(IOException.class)
                .isNotInstanceOf(ImageFormatException.class);
    }

    /** A sparse file as long as its header says (nothing written, no disk used), whose grid the test JVM's 2 GiB heap cannot hold. */
    @Test
    void aGridLargerThanTheHeapIsRefusedWithAMessage() throws IOException {
        long maxHeap = Runtime.getRuntime().maxMemory();
        int n = (int) Math.min(1290, Math.ceil(Math.cbrt(maxHeap / 4.0 * 1.2)));
        Path f = dir.resolve("huge.vol");
        Files.write(f, withInt(withInt(withInt(valid(), 8, n), 12, n), 16, n));
        try (var raf = new java.io.RandomAccessFile(f.toFile(), "rw")) {
            raf.setLength(VolFile.HEADER_BYTES + 4L * n * n * n);
        }
        assertThatThrownBy(() -> VolFile.read(f)).isInstanceOf(ImageFormatException.class)
                .hasMessageContaining("a " + n + "x" + n + "x" + n + " grid needs").hasMessageContaining("give Java more memory");
    }

    private void assertRefused(byte[] bytes, String message) throws IOException {
        Path f = file(bytes);
        assertThatThrownBy(() -> VolFile.read(f)).isInstanceOf(ImageFormatException.class)
                .hasMessageStartingWith(f.toString() + ": ").hasMessageContaining(message)
                .satisfies(e -> assertThat(e.getMessage()).doesNotContain("\n"));
    }
}
