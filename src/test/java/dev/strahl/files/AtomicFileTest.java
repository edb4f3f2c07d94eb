package dev.strahl.files;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The one write path for every file: whole new content or the old file, never a part, never a stray temporary file. */
class AtomicFileTest {
    @TempDir
    Path dir;

    @Test
    void writesAndReplaces() throws IOException {
        Path f = dir.resolve("a.bin");
        AtomicFile.write(f, os -> os.write("first".getBytes(StandardCharsets.UTF_8)));
        AtomicFile.write(f, os -> os.write("second".getBytes(StandardCharsets.UTF_8)));
        assertThat(Files.readString(f)).isEqualTo("second");
        assertThat(names()).containsExactly("a.bin");
    }

    @Test
    void aFailureKeepsTheOldContentAndRemovesTheTemporaryFile() throws IOException {
        Path f = dir.resolve("a.bin");
        AtomicFile.write(f, os -> os.write(1));
        IOException full = new IOException("No space left on device");
        assertThatThrownBy(() -> AtomicFile.write(f, os -> {
            os.write(new byte[300_000]);
            throw full;
        })).isSameAs(full);
        assertThat(Files.readAllBytes(f)).containsExactly(1);
        assertThat(names()).containsExactly("a.bin");
    }

    @Test
    void refusesAMissingDirectoryAndADirectoryAsTarget() throws IOException {
        assertThatThrownBy(() -> AtomicFile.write(dir.resolve("no/a.bin"), os -> os.write(1)))
                .isInstanceOf(IOException.class).hasMessageContaining("output directory does not exist");
        Path d = Files.createDirectory(dir.resolve("d"));
        assertThatThrownBy(() -> AtomicFile.write(d, os -> os.write(1))).isInstanceOf(IOException.class)
                .hasMessageContaining("is a directory");
        assertThat(d).isEmptyDirectory();
    }

    @Test
    void abandoningWritesInProgressRemovesTheirTemporaryFilesOnly() throws Exception {
        Path done = dir.resolve("done.bin");
        AtomicFile.write(done, os -> os.write(7));
        CountDownLatch writing = new CountDownLatch(1);
        CountDownLatch abandoned = new CountDownLatch(1);
        Thread writer = new Thread(() -> {
            try {
                AtomicFile.write(dir.resolve("slow.bin"), os -> {
                    os.write(new byte[100_000]);
                    os.flush();
                    writing.countDown();
                    try {
                        abandoned.await(10, TimeUnit.SECONDS);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                });
            } catch (IOException expected) {
                // its temporary file is gone, so the rename fails: as after a hard exit, nothing is left
            }
        });
        writer.start();
        assertThat(writing.await(10, TimeUnit.SECONDS)).isTrue();
        assertThat(names()).hasSize(2).anySatisfy(n -> assertThat(n).startsWith(".slow.bin").endsWith(".tmp"));
        AtomicFile.abandonWritesInProgress();
        assertThat(names()).containsExactly("done.bin");
        abandoned.countDown();
        writer.join(10_000);
        assertThat(names()).containsExactly("done.bin");
        assertThat(Files.readAllBytes(done)).containsExactly(7);
    }

    private java.util.List<String> names() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
