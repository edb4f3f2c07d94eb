package dev.strahl.io.ply;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;

/**
 * A file read through one large heap buffer that the PLY reader parses in place: {@link #fill}
 * moves the unread bytes to the front and reads until the buffer is full, so that a record never
 * needs more than one bounds check and the file is read in a few hundred system calls.
 */
final class PlyInput {
    final ByteBuffer buf;
    private final FileChannel channel;
    /** File offset of the buffer's first byte. */
    private long bufferStart;
    private boolean eof;

    PlyInput(FileChannel channel, int capacity) {
        this.channel = channel;
        this.buf = ByteBuffer.allocate(capacity);
        buf.flip();
    }

    /**
     * Moves the unread bytes to the front of the buffer and reads until it is full or the file
     * ends; true if at least {@code n} bytes are then available.
     */
    boolean fill(int n) throws IOException {
        bufferStart += buf.position();
        buf.compact();
        while (buf.hasRemaining() && !eof) {
            if (channel.read(buf) < 0) {
                eof = true;
            }
        }
        buf.flip();
        return buf.remaining() >= n;
    }

    /** True if {@code n} bytes are available, reading more if needed. */
    boolean request(int n) throws IOException {
        return buf.remaining() >= n || fill(n);
    }

    /** File offset of the buffer position. */
    long offset() {
        return bufferStart + buf.position();
    }

    /** Size of the whole file in bytes. */
    long fileSize() throws IOException {
        return channel.size();
    }
}
