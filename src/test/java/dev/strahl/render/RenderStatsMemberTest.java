package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** A member's figures: the line a person reads is made from the numbers, and bad numbers are refused. */
class RenderStatsMemberTest {

    @Test
    void theLineShowsEveryFigureAndTheMeanTimeOfAUnit() {
        var f = new RenderStats.Member("10.0.0.2:5701", false, 4, 8, 65536, 200_000, 200_008, 2.0, 1);
        assertThat(f.meanUnitSeconds()).isEqualTo(0.25);
        assertThat(f.line()).isEqualTo("10.0.0.2:5701 threads=4 units=8 samples=65536 sent=200000 received=200008 meanUnitSeconds=0.2500 lost=1");
    }

    @Test
    void theCoordinatorSaysSoAndAMemberWithoutUnitsHasNoMeanTime() {
        var f = new RenderStats.Member("127.0.0.1:5702", true, 1, 0, 0, 0, 0, 0, 0);
        assertThat(f.meanUnitSeconds()).isZero();
        assertThat(f.line()).startsWith("127.0.0.1:5702 (coordinator) threads=1 units=0 ").contains("meanUnitSeconds=0.0000");
    }

    @Test
    void negativeCountsNoThreadsOrANanTimeAreRefused() {
        assertThatThrownBy(() -> new RenderStats.Member("a:1", false, 0, 1, 1, 1, 1, 1, 0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new RenderStats.Member("a:1", false, 1, -1, 1, 1, 1, 1, 0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new RenderStats.Member("a:1", false, 1, 1, 1, 1, 1, Double.NaN, 0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new RenderStats.Member("a:1", false, 1, 1, 1, 1, 1, 1, -1)).isInstanceOf(IllegalArgumentException.class);
    }
}
