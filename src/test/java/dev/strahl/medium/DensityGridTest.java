package dev.strahl.medium;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/**
 * The grid's convention, Mitsuba 3's {@code gridvolume}: voxel (i, j, k) at ((i + ½)/X, …),
 * trilinear between voxel centres, clamped at the border (checked against Mitsuba 3.9.1 itself by
 * docs/anchors/media_refs.py, whose lookups {@code GridConventionTest} replays).
 */
class DensityGridTest {
    /** A 3×2×2 grid whose voxel (i, j, k) holds 1 + i + 10 j + 100 k: every axis tells apart. */
    static DensityGrid ramp() {
        float[] v = new float[12];
        for (int k = 0; k < 2; k++) {
            for (int j = 0; j < 2; j++) {
                for (int i = 0; i < 3; i++) {
                    v[(k * 2 + j) * 3 + i] = 1 + i + 10 * j + 100 * k;
                }
            }
        }
        return new DensityGrid(3, 2, 2, v);
    }

    @Test
    void voxelCentresHoldTheirValues() {
        DensityGrid g = ramp();
        for (int k = 0; k < 2; k++) {
            for (int j = 0; j < 2; j++) {
                for (int i = 0; i < 3; i++) {
                    assertThat(g.eval((i + 0.5) / 3, (j + 0.5) / 2, (k + 0.5) / 2)).isCloseTo(1 + i + 10 * j + 100 * k, within(1e-12));
                    assertThat(g.voxel(i, j, k)).isEqualTo(1 + i + 10 * j + 100 * k);
                }
            }
        }
        assertThat(g.max()).isEqualTo(113);
    }

    @Test
    void betweenCentresTheValueIsTrilinear() {
        DensityGrid g = ramp();
        // halfway between the centres of voxels 0 and 1 in x, a quarter of the way from j = 0 to 1, three quarters in z
        double u = 1.0 / 3, v = 0.25 + 0.25 * 0.5, w = 0.25 + 0.75 * 0.5;
        assertThat(g.eval(u, v, w)).isCloseTo(1 + 0.5 + 10 * 0.25 + 100 * 0.75, within(1e-12));
        // the field is linear in each coordinate, so any point between the centres gives the linear function
        for (double x = 1 / 6.0; x <= 5 / 6.0; x += 0.05) {
            for (double y = 0.25; y <= 0.75; y += 0.05) {
                assertThat(g.eval(x, y, 0.5)).isCloseTo(1 + (3 * x - 0.5) + 10 * (2 * y - 0.5) + 50, within(1e-9));
            }
        }
    }

    @Test
    void beyondTheOutermostCentresTheValueIsClamped() {
        DensityGrid g = ramp();
        assertThat(g.eval(0, 0.25, 0.25)).isCloseTo(1, within(1e-12));              // the half voxel at the face x = 0
        assertThat(g.eval(0.1, 0, 0)).isCloseTo(1, within(1e-12));
        assertThat(g.eval(1, 1, 1)).isCloseTo(113, within(1e-12));
        assertThat(g.eval(-3, 0.75, 7)).isCloseTo(111, within(1e-12));              // far outside: still the border's value
        assertThat(g.eval(Double.NaN, 0.25, 0.25)).isCloseTo(1, within(1e-12));
        DensityGrid one = new DensityGrid(1, 1, 1, new float[] {4});
        assertThat(one.eval(0.9, 0.1, 0.5)).isEqualTo(4);
    }

    @Test
    void badGridsAreRefused() {
        assertThatThrownBy(() -> new DensityGrid(2, 2, 2, new float[7])).hasMessageContaining("2x2x2");
        assertThatThrownBy(() -> new DensityGrid(0, 2, 2, new float[0])).hasMessageContaining("0x2x2");
        assertThatThrownBy(() -> new DensityGrid(2, 1, 1, new float[] {1, -0.5f})).hasMessageContaining("voxel (1, 0, 0)");
        assertThatThrownBy(() -> new DensityGrid(1, 1, 2, new float[] {1, Float.NaN})).hasMessageContaining("voxel (0, 0, 1)");
        assertThatThrownBy(() -> new DensityGrid(1, 1, 1, new float[] {Float.POSITIVE_INFINITY})).hasMessageContaining("finite");
    }
}
