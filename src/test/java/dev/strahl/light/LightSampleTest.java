package dev.strahl.light;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.lang.management.ManagementFactory;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** {@link LightSample#aim}: the direction and distance to a light point, shared by area and punctual lights. */
class LightSampleTest {

    @Test
    void aimGivesTheUnitDirectionTheDistanceAndItsSquare() {
        LightSample ls = new LightSample();
        Vector3d ref = new Vector3d(1, 1, 1);
        assertThat(ls.aim(ref, 3, 4, -3)).isEqualTo(2 * 2 + 3 * 3 + 4 * 4);        // (2, 3, -4) away
        double d = Math.sqrt(29);
        assertThat(ls.distance).isEqualTo(d);
        assertThat(ls.wi.x).isCloseTo(2 / d, within(1e-15));
        assertThat(ls.wi.y).isCloseTo(3 / d, within(1e-15));
        assertThat(ls.wi.z).isCloseTo(-4 / d, within(1e-15));
        assertThat(ls.wi.length()).isCloseTo(1, within(1e-15));
    }

    @Test
    void aimAtTheReferencePointItselfOrANanPointGivesNothingAndChangesNothing() {
        LightSample ls = new LightSample();
        ls.wi.set(0, 0, 1);
        ls.distance = 7;
        assertThat(ls.aim(new Vector3d(1, 2, 3), 1, 2, 3)).isZero();
        assertThat(ls.aim(new Vector3d(1, 2, 3), Double.NaN, 2, 3)).isZero();
        assertThat(ls.wi).isEqualTo(new Vector3d(0, 0, 1));
        assertThat(ls.distance).isEqualTo(7);
    }

    @Test
    void aimAllocatesNothing() {
        var mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        LightSample ls = new LightSample();
        Vector3d ref = new Vector3d(0.5, -0.25, 2);
        double sink = 0;
        for (int pass = 0; pass < 2; pass++) {                    // the first pass warms up the JIT
            long before = mx.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < 50_000; i++) {
                sink += ls.aim(ref, i % 7, i % 11 - 5, 3) + ls.wi.x;
            }
            if (pass == 1) {
                assertThat(mx.getCurrentThreadAllocatedBytes() - before).as("bytes allocated").isLessThan(1024);
            }
        }
        assertThat(sink).isFinite();
    }
}
