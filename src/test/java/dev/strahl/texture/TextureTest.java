package dev.strahl.texture;

import dev.strahl.color.Srgb;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import org.junit.jupiter.api.Test;

/**
 * Image textures: orientation ((0, 0) is the bottom-left corner), bilinear weights, the three
 * wrap modes, the uv transform, channel selection and the sRGB table.
 */
class TextureTest {
    /** A 2×2 RGB image, top row first as readers give it: top-left red, top-right green, bottom-left blue, bottom-right white. */
    private static Bitmap quad() {
        return Bitmap.fromTopDown("quad", 2, 2, 3, new float[] {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
    }

    private static MutableRgb at(TextureLookup t, double u, double v) {
        MutableRgb c = new MutableRgb();
        t.rgb(u, v, c);
        return c;
    }

    @Test
    void texelCentresReadTheirTexelAndVZeroIsTheBottomRow() {
        TextureLookup t = new ImageTexture(quad(), Wrap.CLAMP, UvTransform.IDENTITY, Channel.LUMINANCE);
        assertThat(at(t, 0.25, 0.25).toRgb()).isEqualTo(new Rgb(0, 0, 1));     // bottom-left: blue
        assertThat(at(t, 0.75, 0.25).toRgb()).isEqualTo(new Rgb(1, 1, 1));     // bottom-right: white
        assertThat(at(t, 0.25, 0.75).toRgb()).isEqualTo(new Rgb(1, 0, 0));     // top-left: red
        assertThat(at(t, 0.75, 0.75).toRgb()).isEqualTo(new Rgb(0, 1, 0));     // top-right: green
    }

    @Test
    void bilinearWeightsBetweenTexelCentres() {
        TextureLookup t = new ImageTexture(quad(), Wrap.CLAMP, UvTransform.IDENTITY, Channel.LUMINANCE);
        MutableRgb c = at(t, 0.5, 0.5);          // the mean of all four
        assertThat(c.r).isCloseTo(0.5, within(1e-12));
        assertThat(c.g).isCloseTo(0.5, within(1e-12));
        assertThat(c.b).isCloseTo(0.5, within(1e-12));
        MutableRgb d = at(t, 0.5, 0.25);         // halfway between blue and white
        assertThat(d.r).isCloseTo(0.5, within(1e-12));
        assertThat(d.b).isCloseTo(1, within(1e-12));
    }

    @Test
    void wrapModes() {
        assertThat(Wrap.REPEAT.index(-1, 4)).isEqualTo(3);
        assertThat(Wrap.REPEAT.index(5, 4)).isEqualTo(1);
        assertThat(Wrap.CLAMP.index(-3, 4)).isEqualTo(0);
        assertThat(Wrap.CLAMP.index(9, 4)).isEqualTo(3);
        assertThat(Wrap.MIRRORED_REPEAT.index(4, 4)).isEqualTo(3);
        assertThat(Wrap.MIRRORED_REPEAT.index(-1, 4)).isEqualTo(0);
        assertThat(Wrap.MIRRORED_REPEAT.index(9, 4)).isEqualTo(1);
        assertThat(Wrap.MIRRORED_REPEAT.index(-5, 4)).isEqualTo(3);
        TextureLookup t = new ImageTexture(quad(), Wrap.REPEAT, UvTransform.IDENTITY, Channel.LUMINANCE);
        assertThat(at(t, 1.25, 3.25).toRgb()).isEqualTo(at(t, 0.25, 0.25).toRgb());
        assertThat(at(t, -0.75, -0.25).toRgb()).isEqualTo(at(t, 0.25, 0.75).toRgb());
    }

    @Test
    void uvTransformScalesThenOffsets() {
        TextureLookup t = new ImageTexture(quad(), Wrap.REPEAT, UvTransform.of(2, 2, 0.5, 0), Channel.LUMINANCE);
        // u' = 2·0.125 + 0.5 = 0.75, v' = 2·0.125 = 0.25: bottom-right
        assertThat(at(t, 0.125, 0.125).toRgb()).isEqualTo(new Rgb(1, 1, 1));
    }

    @Test
    void channelsOfScalarTextures() {
        Bitmap grey = Bitmap.fromTopDown("g", 1, 1, 2, new float[] {0.25f, 0.5f});
        assertThat(new ImageTexture(grey, Wrap.REPEAT, UvTransform.IDENTITY, Channel.G).value(0.3, 0.3)).isEqualTo(0.25);
        assertThat(new ImageTexture(grey, Wrap.REPEAT, UvTransform.IDENTITY, Channel.A).value(0.3, 0.3)).isEqualTo(0.5);
        Bitmap rgb = Bitmap.fromTopDown("c", 1, 1, 3, new float[] {0.2f, 0.4f, 0.8f});
        assertThat(new ImageTexture(rgb, Wrap.REPEAT, UvTransform.IDENTITY, Channel.B).value(0.3, 0.3)).isCloseTo(0.8, within(1e-7));
        assertThat(new ImageTexture(rgb, Wrap.REPEAT, UvTransform.IDENTITY, Channel.A).value(0.3, 0.3)).isEqualTo(1);
        assertThat(new ImageTexture(rgb, Wrap.REPEAT, UvTransform.IDENTITY, Channel.LUMINANCE).value(0.3, 0.3))
                .isCloseTo(0.2126 * 0.2 + 0.7152 * 0.4 + 0.0722 * 0.8, within(1e-7));
    }

    @Test
    void srgbTableMatchesTheFormulaFor8And16BitSamples() {
        for (int k = 0; k <= 255; k++) {
            assertThat((double) Srgb.decode(k / 255f)).as("8-bit %d", k).isCloseTo(Srgb.toLinear(k / 255.0), within(1e-6));
        }
        for (int k = 0; k <= 65535; k += 97) {
            assertThat((double) Srgb.decode(k / 65535f)).as("16-bit %d", k).isCloseTo(Srgb.toLinear(k / 65535.0), within(1e-6));
        }
        assertThat(Srgb.toLinear(0.5)).isCloseTo(0.214041, within(1e-6));
        Bitmap b = Bitmap.fromTopDown("a", 1, 1, 4, new float[] {128 / 255f, 128 / 255f, 128 / 255f, 0.5f});
        Bitmap d = b.srgbDecoded();
        assertThat(d).isSameAs(b.srgbDecoded());
        assertThat(new ImageTexture(d, Wrap.REPEAT, UvTransform.IDENTITY, Channel.A).value(0.5, 0.5)).isEqualTo(0.5);   // alpha stays linear
        assertThat(new ImageTexture(d, Wrap.REPEAT, UvTransform.IDENTITY, Channel.R).value(0.5, 0.5)).isCloseTo(Srgb.toLinear(128 / 255.0), within(1e-7));
    }
}
