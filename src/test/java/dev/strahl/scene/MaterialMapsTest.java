package dev.strahl.scene;

import dev.strahl.texture.TextureLookup;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.strahl.image.Rgb;
import dev.strahl.light.Emission;
import dev.strahl.color.MutableRgb;
import dev.strahl.texture.Channel;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The material maps' API: textured emission, normal maps, alpha cut-outs and {@link Texture#alpha()}. */
class MaterialMapsTest {
    @TempDir
    Path dir;

    /** A 2×1 image: left texel (r, g, b, a0), right texel white with alpha a1 (ARGB if withAlpha). */
    private Path png(String name, boolean withAlpha, int a0, int a1) throws Exception {
        BufferedImage img = new BufferedImage(2, 1, withAlpha ? BufferedImage.TYPE_INT_ARGB : BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, (a0 << 24) | 0x336699);
        img.setRGB(1, 0, (a1 << 24) | 0xffffff);
        Path f = dir.resolve(name);
        ImageIO.write(img, "png", f.toFile());
        return f;
    }

    @Test
    void alphaReadsTheAlphaChannelAndOneWhereThereIsNone() throws Exception {
        Texture rgba = Texture.image(png("a.png", true, 0, 255));
        Texture rgb = Texture.image(png("b.png", false, 255, 255));
        assertThat(rgba.hasAlpha()).isTrue();
        assertThat(rgb.hasAlpha()).isFalse();
        assertThat(Texture.constant(0.3).hasAlpha()).isFalse();
        // Texel centres at u = 1/4 and 3/4 (clamped so the bilinear lookup reads one texel).
        TextureLookup a = rgba.alpha().clamped().scalar(Channel.LUMINANCE);
        assertEquals(0, a.value(0.1, 0.5), 1e-6);
        assertEquals(1, a.value(0.9, 0.5), 1e-6);
        assertEquals(0.5, a.mean().r(), 1e-6, "an alpha texture's mean is its alpha's");
        TextureLookup none = rgb.alpha().scalar(Channel.LUMINANCE);
        assertEquals(1, none.value(0.1, 0.5), 0);
        assertThat(Texture.constant(0.2).alpha()).isEqualTo(Texture.constant(1));
        MutableRgb c = new MutableRgb();
        rgba.alpha().clamped().colour().rgb(0.9, 0.5, c);
        assertThat(c.toRgb()).as("an alpha texture used as a colour is grey").isEqualTo(Rgb.gray(1));
    }

    @Test
    void texturedEmissionIsTextureTimesStrength() throws Exception {
        Texture t = Texture.image(png("e.png", false, 255, 255)).linear().clamped();
        Material m = Material.diffuse("lamp", Rgb.gray(0.5)).withEmission(t, 4);
        assertThat(m.isEmissive()).isTrue();
        Emission e = m.surface().emissionTable();
        MutableRgb le = new MutableRgb();
        e.eval(new Vector2d(0.1, 0.5), le);
        assertEquals(4 * 0x33 / 255.0, le.r, 1e-6);
        assertEquals(4 * 0x99 / 255.0, le.b, 1e-6);
        e.eval(new Vector2d(0.9, 0.5), le);
        assertEquals(4, le.g, 1e-6);
        assertEquals(4 * (0x66 / 255.0 + 1) / 2, m.emission().g(), 1e-6, "emission() is the strength times the texture's mean");
        // A constant texture is plain emission.
        assertThat(Material.diffuse("d", Rgb.gray(0.5)).withEmission(Texture.constant(new Rgb(1, 2, 3)), 2))
                .isEqualTo(Material.diffuse("d", Rgb.gray(0.5)).withEmission(new Rgb(2, 4, 6)));
        Material p = Material.principled("p").emission(t, 3).build();
        p.surface().emissionTable().eval(new Vector2d(0.9, 0.5), le);
        assertEquals(3, le.r, 1e-6);
        assertThatThrownBy(() -> Material.diffuse("d", Rgb.gray(0.5)).withEmission(t, -1))
                .hasMessageContaining("emission strength must be >= 0, got -1.0 for material 'd'");
    }

    @Test
    void normalMapAndCutoutGoIntoTheWorldsMaps() throws Exception {
        Texture t = Texture.image(png("n.png", true, 0, 255));
        Material plain = Material.diffuse("d", Rgb.gray(0.5));
        assertThat(plain.surface().maps()).as("no maps: no table entry").isNull();
        Material m = plain.withNormalMap(t, 0.5).withAlphaCutout(t.alpha(), 0.25);
        assertThat(m.surface().maps().normalScale()).isEqualTo(0.5);
        assertThat(m.surface().maps().cutoff()).isEqualTo(0.25);
        assertThat(m.surface().maps().cutAway(new Vector2d(0.25, 0.5))).isTrue();
        assertThat(m.surface().maps().cutAway(new Vector2d(0.75, 0.5))).isFalse();
        assertThat(m.images()).as("one image, read linear for both").hasSize(1);
        assertThat(m).isNotEqualTo(plain).isEqualTo(plain.withNormalMap(t, 0.5).withAlphaCutout(t.alpha(), 0.25));
        assertThat(m.toString()).contains("normalMap=").contains("alpha=");
        assertThatThrownBy(() -> plain.withAlphaCutout(t, 1.5)).hasMessageContaining("alpha cutoff must lie in [0, 1], got 1.5");
        assertThatThrownBy(() -> plain.withNormalMap(t, Double.NaN)).hasMessageContaining("normal map scale must be finite");
    }
}
