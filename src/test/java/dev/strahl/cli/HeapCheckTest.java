package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

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
                .hasMessage("a 8000x8000 image needs 3.3 GiB for its film and image buffers, but the Java heap has 1000.0 MiB free"
                        + " of at most 1.0 GiB; render a smaller image or give Java more memory (java -Xmx...)");
    }

    @Test
    void theFreeHeapCountsNotJustItsMaximum() {
        assertThatThrownBy(() -> HeapCheck.checkFilm(4096, 4096, 2 * GIB, 1900L << 20)).hasMessageContaining("148.0 MiB free");
    }

    @Test
    void bytesAreWrittenInBinaryUnits() {
        assertThat(HeapCheck.bytes(512)).isEqualTo("512 bytes");
        assertThat(HeapCheck.bytes(1536)).isEqualTo("1.5 KiB");
        assertThat(HeapCheck.bytes(3L << 30)).isEqualTo("3.0 GiB");
    }
}
