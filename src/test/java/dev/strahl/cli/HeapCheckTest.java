package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.codec.ImageLimits;
import dev.strahl.denoise.net.NeuralDenoiser;
import dev.strahl.film.Film;
import org.junit.jupiter.api.Test;

class HeapCheckTest {
    private static final long GIB = 1L << 30;

    @Test
    void aFilmThatFitsPasses() {
        HeapCheck.checkFilm(4096, 4096, 2 * GIB, 100L << 20);       // ~0.9 GiB of 1.9 GiB free
    }

    @Test
    void aFilmThatDoesNotFitSaysHowMuchItNeedsAndWhatTheHeapHas() {
        long need = HeapCheck.filmBytes(8000, 8000);
        assertThat(need).isEqualTo(Film.bytesNeeded(8000, 8000) + 28L * 8000 * 8000);
        assertThatThrownBy(() -> HeapCheck.checkFilm(8000, 8000, GIB, 24L << 20))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("a 8000x8000 image needs 3.8 GiB for its film and image buffers, but the Java heap has 1000.0 MiB free"
                        + " of at most 1.0 GiB; render a smaller image or give Java more memory (java -Xmx...)");
    }

    @Test
    void theFreeHeapCountsNotJustItsMaximum() {
        assertThatThrownBy(() -> HeapCheck.checkFilm(4096, 4096, 2 * GIB, 1900L << 20)).hasMessageContaining("148.0 MiB free");
    }

    @Test
    void garbageIsCollectedBeforeAFilmIsRefusedAndOnlyThen() {
        int[] collections = {0};
        long[] used = {1900L << 20};
        Runnable collect = () -> {
            collections[0]++;
            used[0] = 100L << 20;               // most of what was in use was garbage
        };
        HeapCheck.checkFilm(4096, 4096, 2 * GIB, () -> used[0], collect);
        assertThat(collections[0]).as("did not fit at first: one collection, then it fits").isEqualTo(1);

        HeapCheck.checkFilm(4096, 4096, 2 * GIB, () -> used[0], collect);
        assertThat(collections[0]).as("fits at once: no collection").isEqualTo(1);

        assertThatThrownBy(() -> HeapCheck.checkFilm(8000, 8000, GIB, () -> 24L << 20, collect))
                .as("still too large after the collection: refused with what the heap has then")
                .hasMessageContaining("1000.0 MiB free");
        assertThat(collections[0]).isEqualTo(2);
    }

    @Test
    void theRunningHeapIsChecked() {
        HeapCheck.checkFilm(16, 16);
        assertThatThrownBy(() -> HeapCheck.checkFilm(30000, 30000)).hasMessageStartingWith("a 30000x30000 image needs ");
    }

    @Test
    void bytesAreWrittenInBinaryUnits() {
        assertThat(ImageLimits.bytes(512)).isEqualTo("512 bytes");
        assertThat(ImageLimits.bytes(1536)).isEqualTo("1.5 KiB");
        assertThat(ImageLimits.bytes(3L << 30)).isEqualTo("3.0 GiB");
    }

    /** Feature buffers add their 56 bytes of sums per pixel to the film and their images; the denoiser its working buffers. */
    @Test
    void featureBuffersAndTheDenoiserAreCounted() {
        int w = 1024, h = 512;                         // whole tiles: the film's bytes are per pixel
        long pixels = (long) w * h;
        long plain = HeapCheck.renderBytes(w, h, false, false);
        assertThat(HeapCheck.renderBytes(w, h, true, false) - plain).isEqualTo((56 + HeapCheck.FEATURE_BYTES_PER_PIXEL) * pixels);
        assertThat(HeapCheck.renderBytes(w, h, true, true) - HeapCheck.renderBytes(w, h, true, false))
                .isEqualTo(Math.max(HeapCheck.DENOISE_BYTES_PER_PIXEL * pixels, NeuralDenoiser.create().bytesNeeded(w, h)));
        // the network's tile: 680 bytes a pixel of the whole (padded) image while it fits in one tile, more than the filter's
        assertThat(HeapCheck.denoiseBytes(100, 60)).isEqualTo(680L * 112 * 64 + 24 * 6000);
        // a large image: the filter's buffers, the network's tiles being bounded
        assertThat(HeapCheck.denoiseBytes(8192, 8192)).isEqualTo(HeapCheck.DENOISE_BYTES_PER_PIXEL * 8192 * 8192);
        assertThat(Film.bytesNeeded(w, h, true) - Film.bytesNeeded(w, h, false)).as("the film's feature sums").isEqualTo(56 * pixels);
        // 4096² fits in 2 GiB without feature buffers, not with them and the denoiser
        HeapCheck.checkRender(4096, 4096, false, false, 2 * GIB, () -> 0, () -> { });
        assertThatThrownBy(() -> HeapCheck.checkRender(4096, 4096, true, true, 2 * GIB, () -> 0, () -> { }))
                .hasMessageStartingWith("a 4096x4096 image needs ");
    }
}
