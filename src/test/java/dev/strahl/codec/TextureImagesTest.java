package dev.strahl.codec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.IndexColorModel;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** PNG and JPEG files written with ImageIO in every colour type and depth, read back sample by sample. */
class TextureImagesTest {
    private static final int W = 7;
    private static final int H = 5;

    @TempDir
    Path dir;

    /** The sample of band b at (x, y) for a depth of `bits`: spread over the whole range, different per band. */
    private static int sample(int x, int y, int b, int bits) {
        int max = (1 << bits) - 1;
        return (int) (((long) (x * 131 + y * 977 + b * 4099) * 2654435761L >>> 7) % (max + 1));
    }

    private Path png(BufferedImage img, String name) throws IOException {
        Path f = dir.resolve(name);
        assertThat(ImageIO.write(img, "png", f.toFile())).as("ImageIO wrote %s", name).isTrue();
        return f;
    }

    /** A component image (grey or RGB, with or without alpha) of 8 or 16 bits filled with {@link #sample}. */
    private static BufferedImage component(boolean colour, boolean alpha, int bits) {
        ColorSpace cs = ColorSpace.getInstance(colour ? ColorSpace.CS_sRGB : ColorSpace.CS_GRAY);
        int type = bits == 16 ? DataBuffer.TYPE_USHORT : DataBuffer.TYPE_BYTE;
        ComponentColorModel cm = new ComponentColorModel(cs, alpha, false, alpha ? Transparency.TRANSLUCENT : Transparency.OPAQUE, type);
        WritableRaster r = cm.createCompatibleWritableRaster(W, H);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int b = 0; b < r.getNumBands(); b++) {
                    r.setSample(x, y, b, sample(x, y, b, bits));
                }
            }
        }
        return new BufferedImage(cm, r, false, null);
    }

    @ParameterizedTest(name = "{0} alpha={1} {2}-bit")
    @CsvSource({"false, false, 8", "false, false, 16", "false, true, 8", "false, true, 16", "true, false, 8", "true, false, 16",
        "true, true, 8", "true, true, 16"})
    void everyPngColourTypeAndDepthReadsExactly(boolean colour, boolean alpha, int bits) throws IOException {
        Path f = png(component(colour, alpha, bits), "c.png");
        ChannelImage img = TextureImages.read(f);
        List<String> names = colour ? (alpha ? List.of("R", "G", "B", "A") : List.of("R", "G", "B")) : (alpha ? List.of("Y", "A") : List.of("Y"));
        assertThat(img.channels()).containsExactlyElementsOf(names);
        assertThat(img.width()).isEqualTo(W);
        assertThat(img.height()).isEqualTo(H);
        int max = (1 << bits) - 1;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int b = 0; b < names.size(); b++) {
                    float v = img.get(x, y, b);
                    assertThat(v).isBetween(0f, 1f);
                    assertThat(Math.round(v * max)).as("(%d, %d) band %d", x, y, b).isEqualTo(sample(x, y, b, bits));
                    assertThat(v).isEqualTo(sample(x, y, b, bits) / (float) max);
                }
            }
        }
    }

    @Test
    void sixteenBitSamplesKeepAllTheirBits() throws IOException {
        BufferedImage grey = new BufferedImage(65536 / 256, 256, BufferedImage.TYPE_USHORT_GRAY);
        for (int k = 0; k < 65536; k++) {
            grey.getRaster().setSample(k % 256, k / 256, 0, k);
        }
        ChannelImage img = TextureImages.read(png(grey, "all16.png"));
        for (int k = 0; k < 65536; k++) {
            assertThat(Math.round(img.data()[k] * 65535)).isEqualTo(k);
        }
    }

    @ParameterizedTest(name = "{0} entries, alpha={1}")
    @CsvSource({"256, false", "256, true", "16, false", "4, true", "2, false"})
    void paletteImagesExpandToRgbOrRgba(int entries, boolean alpha) throws IOException {
        byte[] r = new byte[entries];
        byte[] g = new byte[entries];
        byte[] b = new byte[entries];
        byte[] a = new byte[entries];
        for (int i = 0; i < entries; i++) {
            r[i] = (byte) (i * 37 + 11);
            g[i] = (byte) (255 - i * 5);
            b[i] = (byte) (i * 101);
            a[i] = (byte) (alpha ? (i * 61) % 256 : 255);
        }
        int bits = Integer.numberOfTrailingZeros(entries);
        IndexColorModel palette = alpha ? new IndexColorModel(bits, entries, r, g, b, a) : new IndexColorModel(bits, entries, r, g, b);
        BufferedImage img = entries == 256 ? new BufferedImage(W, H, BufferedImage.TYPE_BYTE_INDEXED, palette)
                : new BufferedImage(W, H, BufferedImage.TYPE_BYTE_BINARY, palette);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                img.getRaster().setSample(x, y, 0, (x + 3 * y) % entries);
            }
        }
        ChannelImage read = TextureImages.read(png(img, "p.png"));
        assertThat(read.channels()).containsExactlyElementsOf(alpha ? List.of("R", "G", "B", "A") : List.of("R", "G", "B"));
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = (x + 3 * y) % entries;
                assertThat(read.get(x, y, 0)).isEqualTo((r[i] & 0xff) / 255f);
                assertThat(read.get(x, y, 1)).isEqualTo((g[i] & 0xff) / 255f);
                assertThat(read.get(x, y, 2)).isEqualTo((b[i] & 0xff) / 255f);
                if (alpha) {
                    assertThat(read.get(x, y, 3)).isEqualTo((a[i] & 0xff) / 255f);
                }
            }
        }
    }

    @ParameterizedTest
    @CsvSource({"1", "2", "4"})
    void lowBitDepthGreyReadsAsGreyScaledToOne(int bits) throws IOException {
        int levels = 1 << bits;
        byte[] ramp = new byte[levels];
        for (int i = 0; i < levels; i++) {
            ramp[i] = (byte) (i * 255 / (levels - 1));
        }
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_BYTE_BINARY, new IndexColorModel(bits, levels, ramp, ramp, ramp));
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                img.getRaster().setSample(x, y, 0, (x + y) % levels);
            }
        }
        Path f = png(img, "g.png");
        assertThat(Files.readAllBytes(f)[25]).as("PNG colour type 0: ImageIO wrote grey, not a palette").isZero();
        assertThat(Files.readAllBytes(f)[24]).as("bit depth").isEqualTo((byte) bits);
        ChannelImage read = TextureImages.read(f);
        assertThat(read.channels()).containsExactly("Y");
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                float expected = ((x + y) % levels) / (float) (levels - 1);
                for (int c = 0; c < read.channelCount(); c++) {
                    assertThat(read.get(x, y, c)).as("(%d, %d) %s", x, y, read.channels()).isEqualTo(expected);
                }
            }
        }
    }

    @ParameterizedTest
    @CsvSource({"true", "false"})
    void jpegReadsItsColourOrGreyFromTheRaster(boolean colour) throws IOException {
        // flat 16x16 blocks (a whole block of subsampled chroma) survive JPEG within a few steps
        BufferedImage img = new BufferedImage(32, 32, colour ? BufferedImage.TYPE_3BYTE_BGR : BufferedImage.TYPE_BYTE_GRAY);
        int[][] colours = {{200, 30, 40}, {10, 180, 90}, {50, 60, 220}, {128, 128, 128}};
        for (int y = 0; y < 32; y++) {
            for (int x = 0; x < 32; x++) {
                int[] c = colours[(x / 16) + 2 * (y / 16)];
                img.getRaster().setPixel(x, y, colour ? c : new int[] {c[0]});
            }
        }
        Path f = dir.resolve("t.jpg");
        assertThat(ImageIO.write(img, "jpeg", f.toFile())).isTrue();
        ChannelImage read = TextureImages.read(f);
        assertThat(read.channels()).containsExactlyElementsOf(colour ? List.of("R", "G", "B") : List.of("Y"));
        for (int y = 0; y < 32; y++) {
            for (int x = 0; x < 32; x++) {
                int[] c = colours[(x / 16) + 2 * (y / 16)];
                if (x % 16 < 4 || x % 16 >= 12 || y % 16 < 4 || y % 16 >= 12) {
                    continue;                      // near a block edge, chroma upsampling mixes the neighbour in
                }
                for (int b = 0; b < read.channelCount(); b++) {
                    assertThat(read.get(x, y, b) * 255).as("(%d, %d) band %d", x, y, b).isCloseTo(c[b], org.assertj.core.data.Offset.offset(8f));
                }
            }
        }
    }

    // ---- bad files ---------------------------------------------------------------------------

    @Test
    void truncatedAndCorruptFilesAreOneLineNamingTheFile() throws IOException {
        BufferedImage big = component(true, false, 8);
        BufferedImage noisy = new BufferedImage(64, 64, BufferedImage.TYPE_3BYTE_BGR);
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 64; x++) {
                noisy.setRGB(x, y, sample(x, y, 0, 24));
            }
        }
        byte[] png = Files.readAllBytes(png(noisy, "n.png"));
        Path jpgFile = dir.resolve("n.jpg");
        ImageIO.write(noisy, "jpeg", jpgFile.toFile());
        byte[] jpg = Files.readAllBytes(jpgFile);
        for (byte[] bad : List.of(Arrays.copyOf(png, png.length / 2), Arrays.copyOf(png, 40), Arrays.copyOf(jpg, jpg.length / 2),
                Arrays.copyOf(jpg, 200), Arrays.copyOf(png, 8), new byte[0], "hello".getBytes(java.nio.charset.StandardCharsets.US_ASCII))) {
            Path f = Files.write(dir.resolve("bad.png"), bad);
            assertThatThrownBy(() -> TextureImages.read(f)).as("%d bytes", bad.length).isInstanceOf(ImageFormatException.class)
                    .hasMessageStartingWith(f + ": ").hasMessageNotContaining("\n");
        }
        Path half = Files.write(dir.resolve("half.jpg"), Arrays.copyOf(jpg, jpg.length / 2));
        assertThatThrownBy(() -> TextureImages.read(half)).hasMessageStartingWith(half + ": corrupt or truncated JPEG image");
        Path none = Files.write(dir.resolve("none.png"), "hello".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        assertThatThrownBy(() -> TextureImages.read(none)).hasMessage(none + ": not a PNG or JPEG image (strahl reads PNG and JPEG textures)");
        assertThat(big).isNotNull();
    }

    @Test
    void otherFormatsAreNamed() throws IOException {
        Path gif = dir.resolve("t.gif");
        ImageIO.write(new BufferedImage(4, 4, BufferedImage.TYPE_BYTE_INDEXED), "gif", gif.toFile());
        assertThatThrownBy(() -> TextureImages.read(gif)).isInstanceOf(ImageFormatException.class)
                .hasMessage(gif + ": a GIF image: strahl reads PNG and JPEG textures");
        Path bmp = dir.resolve("t.bmp");
        ImageIO.write(new BufferedImage(4, 4, BufferedImage.TYPE_3BYTE_BGR), "bmp", bmp.toFile());
        assertThatThrownBy(() -> TextureImages.read(bmp)).hasMessage(bmp + ": a BMP image: strahl reads PNG and JPEG textures");
    }

    @Test
    void anAbsurdSizeInTheHeaderIsRefusedBeforeDecoding() throws IOException {
        byte[] png = Files.readAllBytes(png(component(true, true, 16), "ok.png"));
        ByteBuffer.wrap(png).putInt(16, 200_000).putInt(20, 300_000);     // IHDR width, height (the JDK does not check the CRC)
        Path f = Files.write(dir.resolve("huge.png"), png);
        assertThatThrownBy(() -> TextureImages.read(f)).isInstanceOf(ImageFormatException.class)
                .hasMessageStartingWith(f + ": a 200000x300000 image with 4 channel(s) is too large to load");
    }

    @Test
    void aMissingFileIsTheUsualIoException() {
        assertThatThrownBy(() -> TextureImages.read(dir.resolve("gone.png"))).isInstanceOf(java.nio.file.NoSuchFileException.class);
    }
}
