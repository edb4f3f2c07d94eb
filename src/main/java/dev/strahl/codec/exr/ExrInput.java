package dev.strahl.codec.exr;

import dev.strahl.codec.ImageFormatException;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * Little-endian reading from an EXR file with bounds checks: every read that would go past the
 * end of the file is an {@link ImageFormatException} that names the byte and what was being read,
 * never an {@link java.io.EOFException} or a buffer exception.
 */
final class ExrInput {
    private static final int WINDOW = 1 << 16;

    private final Path file;
    private final FileChannel channel;
    private final long size;
    private final ByteBuffer window = ByteBuffer.allocate(WINDOW).order(ByteOrder.LITTLE_ENDIAN);
    private long windowStart;
    private long position;

    ExrInput(Path file, FileChannel channel) throws IOException {
        this.file = file;
        this.channel = channel;
        this.size = channel.size();
        window.limit(0);
    }

    Path file() {
        return file;
    }

    long size() {
        return size;
    }

    long position() {
        return position;
    }

    void seek(long to) {
        position = to;
    }

    long remaining() {
        return size - position;
    }

    ImageFormatException error(String message) {
        return new ImageFormatException(file, message);
    }

    ImageFormatException error(long at, String message) {
        return new ImageFormatException(file, "byte " + at + ": " + message);
    }

    private ImageFormatException truncated(String what) {
        return error(position, "the file ends inside " + what + " (it has " + size + " bytes): it is truncated");
    }

    /** Makes {@code n} bytes at the position available in the window, or fails naming {@code what}. */
    private void need(int n, String what) throws IOException {
        if (n > remaining()) {
            throw truncated(what);
        }
        long offset = position - windowStart;
        if (offset >= 0 && offset + n <= window.limit()) {
            return;
        }
        window.clear();
        windowStart = position;
        int want = (int) Math.min(WINDOW, size - position);
        window.limit(want);
        while (window.hasRemaining()) {
            if (channel.read(window, windowStart + window.position()) < 0) {
                throw error(position, "the file ends while being read (it shrank?)");
            }
        }
        window.flip();
    }

    private int at() {
        return (int) (position - windowStart);
    }

    int u8(String what) throws IOException {
        need(1, what);
        int v = window.get(at()) & 0xff;
        position++;
        return v;
    }

    int i32(String what) throws IOException {
        need(4, what);
        int v = window.getInt(at());
        position += 4;
        return v;
    }

    long u64(String what) throws IOException {
        need(8, what);
        long v = window.getLong(at());
        position += 8;
        return v;
    }

    float f32(String what) throws IOException {
        return Float.intBitsToFloat(i32(what));
    }

    void skip(long n, String what) throws IOException {
        if (n > remaining()) {
            throw truncated(what);
        }
        position += n;
    }

    /** {@code n} bytes, after checking that the file holds them (so a huge n allocates nothing). */
    byte[] bytes(int n, String what) throws IOException {
        if (n > remaining()) {
            throw truncated(what);
        }
        byte[] b = new byte[n];
        ByteBuffer dst = ByteBuffer.wrap(b);
        while (dst.hasRemaining()) {
            if (channel.read(dst, position + dst.position()) < 0) {
                throw error(position, "the file ends while being read (it shrank?)");
            }
        }
        position += n;
        return b;
    }

    /**
     * A NUL-terminated UTF-8 string of at most {@code max} bytes before the NUL.
     *
     * @return the string, "" if the first byte is the NUL
     */
    String cstring(int max, String what) throws IOException {
        long start = position;
        byte[] b = new byte[max];
        for (int n = 0; ; n++) {
            int c = u8(what);
            if (c == 0) {
                return new String(b, 0, n, StandardCharsets.UTF_8);
            }
            if (n == max) {
                throw error(start, what + " is longer than " + max + " bytes (or has no terminating NUL byte)");
            }
            b[n] = (byte) c;
        }
    }

    /** Reads chunk data at the current position into {@code dst} (whose length was checked against the file). */
    void readFully(byte[] dst, int length) throws IOException {
        if (length > remaining()) {
            throw truncated("pixel data");
        }
        ByteBuffer b = ByteBuffer.wrap(dst, 0, length);
        while (b.hasRemaining()) {
            if (channel.read(b, position + b.position()) < 0) {
                throw error(position, "the file ends while being read (it shrank?)");
            }
        }
        position += length;
    }
}
