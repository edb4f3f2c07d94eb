package dev.strahl.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.texture.Channel;
import dev.strahl.texture.ImageTexture;
import dev.strahl.color.Srgb;
import dev.strahl.texture.UvTransform;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The texture API's factors ({@link Texture#scaled}, {@link Texture#times}), one-channel textures
 * ({@link Texture#channel}) and the uv rotation: what the materials read from them.
 */
class TextureFactorsTest {
    @TempDir
    Path dir;

    /** A 1×1 RGB image of the given 8-bit channels. */
    private Path png(String name, int r, int g, int b) throws Exception {
        BufferedImage img = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, (r << 16) | (g << 8) | b);
        Path f = dir.resolve(name);
        ImageIO.write(img, "png", f.toFile());
        return f;
    }

    @Test
    void aColourFactorMultipliesTheDecodedTexelsAndEachChannelsNumber() throws Exception {
        Texture t = Texture.image(png("c.png", 200, 100, 50)).scaled(new Rgb(0.5, 0.25, 0.75));
        MutableRgb c = new MutableRgb();
        t.colour().rgb(0.5, 0.5, c);
        assertThat(c.r).isCloseTo(0.5 * Srgb.toLinear(200 / 255.0), within(1e-6));      // decoded first, then multiplied
        assertThat(c.g).isCloseTo(0.25 * Srgb.toLinear(100 / 255.0), within(1e-6));
        assertThat(c.b).isCloseTo(0.75 * Srgb.toLinear(50 / 255.0), within(1e-6));
        Texture data = t.linear();
        assertThat(data.scalar(Channel.G).value(0.5, 0.5)).isCloseTo(0.25 * 100 / 255.0, within(1e-6));
        assertThat(data.scalar(Channel.B).value(0.5, 0.5)).isCloseTo(0.75 * 50 / 255.0, within(1e-6));
        double lum = 0.2126 * 200 / 255.0 + 0.7152 * 100 / 255.0 + 0.0722 * 50 / 255.0;
        assertThat(data.scalar(Channel.LUMINANCE).value(0.5, 0.5)).as("a luminance read: the factor's luminance")
                .isCloseTo(new Rgb(0.5, 0.25, 0.75).luminance() * lum, within(1e-6));
    }

    @Test
    void factorsMultiplyWhiteIsNoFactorAndAConstantFoldsIt() throws Exception {
        Texture image = Texture.image(png("w.png", 255, 255, 255));
        assertThat(image.scaled(Rgb.WHITE)).isSameAs(image);
        assertThat(image.times(1)).isSameAs(image);
        assertThat(image.scaled(new Rgb(0.5, 1, 2)).scaled(new Rgb(2, 0.5, 0.25))).isEqualTo(image.scaled(new Rgb(1, 0.5, 0.5)));
        assertThat(image.times(0.5)).isNotEqualTo(image).isEqualTo(image.scaled(Rgb.gray(0.5)));
        assertThat(image.times(0.5).toString()).contains("x (0.5, 0.5, 0.5)");
        assertThat(Texture.constant(new Rgb(0.5, 0.5, 1)).scaled(new Rgb(1, 0.5, 0.25))).isEqualTo(Texture.constant(new Rgb(0.5, 0.25, 0.25)));
        assertThatThrownBy(() -> image.times(-1)).hasMessageContaining("factor");
        assertThatThrownBy(() -> image.scaled(new Rgb(1, -0.5, 1))).hasMessageContaining("factor");
    }

    @Test
    void aChannelIsALinearNumberThatAFactorAfterwardsMultiplies() throws Exception {
        Texture t = Texture.image(png("ch.png", 200, 100, 50));
        assertThat(t.channel(0).scalar(Channel.LUMINANCE).value(0.5, 0.5)).isCloseTo(200 / 255.0, within(1e-6));
        assertThat(t.channel(2).times(0.5).scalar(Channel.LUMINANCE).value(0.5, 0.5)).isCloseTo(0.5 * 50 / 255.0, within(1e-6));
        assertThat(t.channel(3).scalar(Channel.LUMINANCE).value(0.5, 0.5)).as("no alpha: 1").isEqualTo(1);
        assertThat(t.scaled(Rgb.gray(0.5)).alpha()).as("alpha drops a colour factor").isEqualTo(t.alpha());
        MutableRgb c = new MutableRgb();
        t.channel(1).colour().rgb(0.5, 0.5, c);
        assertThat(c.r).as("one channel is grey as a colour, never sRGB-decoded").isCloseTo(100 / 255.0, within(1e-7));
        assertThat(c.toRgb()).isEqualTo(Rgb.gray(c.r));
        assertThat(Texture.constant(new Rgb(0.1, 0.2, 0.3)).channel(1)).isEqualTo(Texture.constant(0.2));
        assertThatThrownBy(() -> t.channel(4)).hasMessageContaining("channel");
    }

    @Test
    void scaleRotationAndOffsetAreKeptByEachOther() throws Exception {
        Texture t = Texture.image(png("r.png", 1, 2, 3)).withUvRotation(0.5).withUvScale(2, 3).withUvOffset(0.25, 0.125);
        ImageTexture image = (ImageTexture) t.colour();
        assertThat(image.transform()).isEqualTo(new UvTransform(2, 3, 0.25, 0.125, 0.5));
        assertThat(((ImageTexture) t.withUvRotation(0).colour()).transform()).isEqualTo(UvTransform.of(2, 3, 0.25, 0.125));
    }
}
