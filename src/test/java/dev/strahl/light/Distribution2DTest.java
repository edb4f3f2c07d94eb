package dev.strahl.light;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.testing.ChiSquare;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/** The piecewise-constant 2D distribution: chi-square of its samples, empty rows and cells, edges. */
class Distribution2DTest {
    private static final double ALPHA = ChiSquare.sidak(0.01, 2);
    /** The unit square as its own chart. */
    private static final ChiSquare.Chart UNIT_SQUARE = new ChiSquare.Chart() {
        @Override
        public boolean toChart(double x, double y, Vector2d dest) {
            dest.set(x, y);
            return x >= 0 && x <= 1 && y >= 0 && y <= 1;
        }

        @Override
        public double fromChart(double s, double t, Vector2d dest) {
            dest.set(s, t);
            return 1;
        }
    };

    @Test
    void samplesFollowTheDensityWithEmptyRowsAndCells() {
        int nu = 7, nv = 5;
        float[] w = new float[nu * nv];
        for (int j = 0; j < nv; j++) {
            for (int i = 0; i < nu; i++) {
                w[j * nu + i] = j == 2 || i == 3 ? 0 : (float) (1 + i * j + (i == 5 && j == 4 ? 40 : 0));
            }
        }
        Distribution2D d = new Distribution2D(nu, nv, w);
        double[] uv = new double[2];
        ChiSquare.test2d((u1, u2, dest) -> {
            double pdf = d.sample(u1, u2, uv);
            assertThat(pdf).isPositive().isCloseTo(d.pdf(uv[0], uv[1]), within(1e-9 * pdf));
            dest.set(uv[0], uv[1]);
            return true;
        }, d::pdf, UNIT_SQUARE, 2 * nu, 2 * nv, 500_000, 9).assertAccepted(ALPHA);
    }

    @Test
    void theEndsOfTheUnitIntervalStayInside() {
        Distribution2D d = new Distribution2D(3, 2, new float[] {0, 1, 0, 0, 0, 0});
        double[] uv = new double[2];
        for (double u : new double[] {0, 1e-17, 0.5, Math.nextDown(1.0)}) {
            assertThat(d.sample(u, u, uv)).isPositive();
            assertThat(uv[0]).isBetween(1.0 / 3, 2.0 / 3);
            assertThat(uv[1]).isBetween(0.0, 0.5);
        }
    }

    @Test
    void refusesBadWeights() {
        assertThatThrownBy(() -> new Distribution2D(2, 1, new float[] {0, 0})).hasMessageContaining("zero");
        assertThatThrownBy(() -> new Distribution2D(2, 1, new float[] {1, Float.NaN})).hasMessageContaining("NaN");
        assertThatThrownBy(() -> new Distribution2D(2, 2, new float[] {1})).hasMessageContaining("2x2");
    }
}
