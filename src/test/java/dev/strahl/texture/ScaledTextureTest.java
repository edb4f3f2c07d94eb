package dev.strahl.texture;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import org.junit.jupiter.api.Test;

/**
 * A texture times a factor (glTF's factor × texture) and the uv transform's rotation: products
 * texel by texel, channel factors, the mean, no allocation per lookup; scale, rotate, offset in
 * this order with hand-computed coordinates.
 */
class ScaledTextureTest {
    /** A 2×2 RGB image, top row first: top-left red, top-right green, bottom-left blue, bottom-right grey 0.5. */
    private static Bitmap quad() {
        return Bitmap.fromTopDown("quad", 2, 2, 3, new float[] {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f});
    }

    private static final double[][] CENTRES = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};

    @Test
    void theColourIsTheFactorTimesTheTexelChannelByChannel() {
        ImageTexture image = new ImageTexture(quad(), Wrap.CLAMP, UvTransform.IDENTITY, Channel.LUMINANCE);
        Rgb factor = new Rgb(0.5, 0.25, 2);
        ScaledTexture t = new ScaledTexture(image, factor, 0.75);
        MutableRgb texel = new MutableRgb(), scaled = new MutableRgb();
        for (double[] uv : CENTRES) {
            image.rgb(uv[0], uv[1], texel);
            t.rgb(uv[0], uv[1], scaled);
            assertThat(scaled.r).isEqualTo(0.5 * texel.r);
            assertThat(scaled.g).isEqualTo(0.25 * texel.g);
            assertThat(scaled.b).isEqualTo(2 * texel.b);
            assertThat(t.value(uv[0], uv[1])).isEqualTo(0.75 * image.value(uv[0], uv[1]));
        }
        Rgb mean = image.mean();
        assertThat(t.mean()).isEqualTo(new Rgb(0.5 * mean.r(), 0.25 * mean.g(), 2 * mean.b()));
        assertThat(t.bitmap()).isSameAs(image.bitmap());
        assertThat(t.isConstant()).isFalse();
        assertThat(new ScaledTexture(TextureLookup.of(0.5), Rgb.gray(0.5), 0.5).value(0.3, 0.7)).isEqualTo(0.25);
    }

    @Test
    void aFactorMustBeFiniteAndNotNegative() {
        TextureLookup one = TextureLookup.of(1);
        assertThatThrownBy(() -> new ScaledTexture(one, new Rgb(1, -0.5, 1), 1)).hasMessageContaining("factor");
        assertThatThrownBy(() -> new ScaledTexture(one, Rgb.WHITE, -1)).hasMessageContaining("factor");
        assertThatThrownBy(() -> new ScaledTexture(one, Rgb.WHITE, Double.NaN)).hasMessageContaining("factor");
    }

    @Test
    void lookupsAllocateNothing() {
        var mx = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        ScaledTexture t = new ScaledTexture(new ImageTexture(quad(), Wrap.REPEAT, new UvTransform(2, 3, 0.1, 0.2, 0.7), Channel.LUMINANCE),
                new Rgb(0.5, 0.25, 0.125), 0.3);
        MutableRgb c = new MutableRgb();
        double sum = 0;
        for (int i = 0; i < 20_000; i++) {
            t.rgb(i * 0.001, i * 0.0007, c);
            sum += t.value(i * 0.0003, i * 0.0011) + c.g;
        }
        long before = mx.getCurrentThreadAllocatedBytes();
        for (int i = 0; i < 100_000; i++) {
            t.rgb(i * 0.001, i * 0.0007, c);
            sum += t.value(i * 0.0003, i * 0.0011) + c.g;
        }
        assertThat(mx.getCurrentThreadAllocatedBytes() - before).isLessThan(1024);
        assertThat(sum).isPositive();
    }

    @Test
    void aQuarterTurnRotatesTheCoordinatesCounterClockwise() {
        UvTransform quarter = new UvTransform(1, 1, 0, 0, Math.PI / 2);
        // (u, v) → (−v, u): the u axis goes to the v axis
        assertThat(quarter.mapU(1, 0)).isCloseTo(0, within(1e-15));
        assertThat(quarter.mapV(1, 0)).isCloseTo(1, within(1e-15));
        assertThat(quarter.mapU(0.25, 0.75)).isCloseTo(-0.75, within(1e-15));
        assertThat(quarter.mapV(0.25, 0.75)).isCloseTo(0.25, within(1e-15));
        // the texel at (0.25, 0.75) (top-left, red) is what (0.75, 0.75) reads after the quarter turn: (−0.75, 0.75) ≡ (0.25, 0.75)
        ImageTexture t = new ImageTexture(quad(), Wrap.REPEAT, quarter, Channel.LUMINANCE);
        MutableRgb c = new MutableRgb();
        t.rgb(0.75, 0.75, c);
        assertThat(c.r).isCloseTo(1, within(1e-12));
        assertThat(c.g).isCloseTo(0, within(1e-12));
    }

    @Test
    void scaleThenRotateThenOffset() {
        double r = Math.toRadians(30), c = Math.cos(r), s = Math.sin(r);
        UvTransform t = new UvTransform(2, 3, 0.5, -0.25, r);
        double u = 0.2, v = 0.7;
        // scale: (0.4, 2.1); rotate by 30°: (0.4 c − 2.1 s, 0.4 s + 2.1 c); offset
        double expectU = 0.4 * c - 2.1 * s + 0.5, expectV = 0.4 * s + 2.1 * c - 0.25;
        assertThat(t.mapU(u, v)).isCloseTo(expectU, within(1e-12));
        assertThat(t.mapV(u, v)).isCloseTo(expectV, within(1e-12));
        assertThat(expectU).isCloseTo(-0.2036, within(1e-4));          // 0.3464 − 1.05 + 0.5, by hand
        assertThat(expectV).isCloseTo(1.7687, within(1e-4));           // 0.2 + 1.8187 − 0.25, by hand
        UvTransform noTurn = UvTransform.of(2, 3, 0.5, -0.25);
        assertThat(noTurn.mapU(u, v)).isEqualTo(2 * u + 0.5);
        assertThat(noTurn.mapV(u, v)).isEqualTo(3 * v - 0.25);
        assertThat(t).isEqualTo(new UvTransform(2, 3, 0.5, -0.25, r)).isNotEqualTo(noTurn);
        assertThat(t.hashCode()).isEqualTo(new UvTransform(2, 3, 0.5, -0.25, r).hashCode());
        assertThat(UvTransform.of(1, 1, 0, 0).isIdentity()).isTrue();
        assertThat(noTurn.toString()).isEqualTo("UvTransform[scaleU=2.0, scaleV=3.0, offsetU=0.5, offsetV=-0.25, rotation=0.0]");
    }

    @Test
    void aOneChannelTextureIsGreyAsAColour() {
        Bitmap rgb = Bitmap.fromTopDown("c", 1, 1, 3, new float[] {0.2f, 0.4f, 0.8f});
        MutableRgb c = new MutableRgb();
        new ImageTexture(rgb, Wrap.REPEAT, UvTransform.IDENTITY, Channel.R).rgb(0.5, 0.5, c);
        assertThat(c.toRgb()).isEqualTo(Rgb.gray(0.2f));
        assertThat(new ImageTexture(rgb, Wrap.REPEAT, UvTransform.IDENTITY, Channel.G).mean()).isEqualTo(Rgb.gray(0.4f));
    }
}
