package dev.strahl.files;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The one way strahl writes a file (images, checkpoints, statistics): into a temporary file in
 * the target's directory, flushed to the disk, then renamed over the target. Readers see either
 * the old file or the complete new one; a crash, a full disk or an exception from the writer
 * never leaves a truncated file in the target's place, and the temporary file is deleted on
 * every failure that the JVM survives.
 */
public final class AtomicFile {

    /** Writes a file's content to a stream. */
    @FunctionalInterface
    public interface Content {
        /**
         * Writes the whole content.
         *
         * @param out the stream into the temporary file; flushed and closed by {@link AtomicFile}
         * @throws IOException if writing fails: the target is then left as it was
         */
        void writeTo(OutputStream out) throws IOException;
    }

    /** Temporary files being written right now, so that a hard exit can remove them. */
    private static final Set<Path> IN_FLIGHT = ConcurrentHashMap.newKeySet();

    private AtomicFile() {
    }

    /**
     * Deletes the temporary files of writes still in progress, for a program that is about to
     * end at once ({@link Runtime#halt}) and so would leave them behind. The targets are
     * untouched: they keep their old content, or do not exist.
     */
    public static void abandonWritesInProgress() {
        for (Path tmp : IN_FLIGHT) {
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException | SecurityException e) {
                // best effort on the way out; a hidden .tmp file is all that can remain
            }
        }
    }

    /**
     * Writes {@code out} atomically, replacing any existing file.
     *
     * @param out     the file to write
     * @param content writes the file's bytes; it should not close the stream
     * @throws IOException if the directory does not exist, {@code out} is a directory, or writing
     *                     fails; {@code out} is then unchanged
     */
    public static void write(Path out, Content content) throws IOException {
        Objects.requireNonNull(content, "content");
        Path target = Objects.requireNonNull(out, "out").toAbsolutePath();
        Path dir = target.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IOException("output directory does not exist: " + dir);
        }
        if (Files.isDirectory(target)) {
            // a rename would silently replace an empty directory
            throw new IOException("cannot write " + out + ": it is a directory");
        }
        Path tmp = null;
        try {
            FileChannel channel = null;
            for (int attempt = 0; channel == null; attempt++) {
                Path candidate = tempName(dir, target.getFileName().toString());
                try {
                    channel = FileChannel.open(candidate, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                    tmp = candidate;
                    IN_FLIGHT.add(tmp);
                } catch (FileAlreadyExistsException e) {
                    if (attempt == 99) {
                        throw e;
                    }
                }
            }
            try (FileChannel ch = channel) {
                OutputStream os = new BufferedOutputStream(Channels.newOutputStream(ch), 1 << 16);
                content.writeTo(os);
                os.flush();
                ch.force(true);                // the bytes are on the disk before the name points to them
            }
            move(tmp, target);
            IN_FLIGHT.remove(tmp);
        } catch (Throwable t) {
            if (tmp != null) {
                try {
                    Files.deleteIfExists(tmp);
                } catch (IOException e) {
                    t.addSuppressed(e);
                }
                IN_FLIGHT.remove(tmp);
            }
            throw t;
        }
    }

    /**
     * ".name&lt;random&gt;.tmp", hidden and recognisable, the naming of
     * {@code Files.createTempFile(dir, "." + name, ".tmp")}. Not createTempFile itself: it creates
     * the file with permissions rw------- on POSIX systems, which the rename would pass on to the
     * target; CREATE_NEW gives the usual permissions (0666 minus the umask).
     */
    static Path tempName(Path dir, String name) {
        if (name.length() > 200) {
            name = name.substring(0, 200);   // room for the suffix within the usual 255-byte name limit
        }
        return dir.resolve("." + name + Long.toUnsignedString(ThreadLocalRandom.current().nextLong()) + ".tmp");
    }

    private static void move(Path tmp, Path target) throws IOException {
        try {
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
