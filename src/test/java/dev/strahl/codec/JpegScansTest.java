package dev.strahl.codec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The scans of a JPEG, counted before decoding: one for a baseline file, several for a progressive one, and a scan bomb refused. */
class JpegScansTest {
    @TempDir
    Path dir;

    private static byte[] jpeg(boolean progressive) throws IOException {
        BufferedImage image = new BufferedImage(40, 24, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 24; y++) {
            for (int x = 0; x < 40; x++) {
                image.setRGB(x, y, x * 6 << 16 | y * 10 << 8 | (x * y) & 0xff);
            }
        }
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setProgressiveMode(progressive ? ImageWriteParam.MODE_DEFAULT : ImageWriteParam.MODE_DISABLED);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (ImageOutputStream stream = ImageIO.createImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(null, new IIOImage(image, null, null), param);
        }
        writer.dispose();
        return out.toByteArray();
    }

    @Test
    void baselineHasOneScanAndProgressiveSeveral() throws IOException {
        assertThat(JpegScans.count(Files.write(dir.resolve("b.jpg"), jpeg(false)))).isEqualTo(1);
        int progressive = JpegScans.count(Files.write(dir.resolve("p.jpg"), jpeg(true)));
        assertThat(progressive).isBetween(2, 20);
        byte[] p = jpeg(true);
        assertThat(JpegScans.count(Files.write(dir.resolve("cut.jpg"), Arrays.copyOf(p, p.length / 2)))).isBetween(1, progressive);
        assertThat(JpegScans.count(Files.write(dir.resolve("png.jpg"), new byte[] {(byte) 0x89, 'P', 'N', 'G'}))).isZero();
    }

    @Test
    void aFileOfTooManyScansIsRefusedNamingThem() throws IOException {
        byte[] p = jpeg(true);
        int last = -1;
        for (int i = 2; i + 1 < p.length; i++) {
            if ((p[i] & 0xff) == 0xff && (p[i + 1] & 0xff) == 0xda) {
                last = i;
            }
        }
        ByteArrayOutputStream bomb = new ByteArrayOutputStream();
        bomb.write(p, 0, p.length - 2);
        for (int k = 0; k < JpegScans.MAX_SCANS; k++) {
            bomb.write(p, last, p.length - 2 - last);
        }
        bomb.write(p, p.length - 2, 2);
        Path f = Files.write(dir.resolve("bomb.jpg"), bomb.toByteArray());
        int scans = JpegScans.count(f);
        assertThat(scans).isEqualTo(JpegScans.count(Files.write(dir.resolve("p.jpg"), p)) + JpegScans.MAX_SCANS);
        assertThatThrownBy(() -> TextureImages.read(f)).isInstanceOf(ImageFormatException.class)
                .hasMessage(f + ": a 40x24 JPEG image of " + scans + " scans: decoding it would pass over "
                        + String.format(java.util.Locale.ROOT, "%.3g", 40.0 * 24 * scans)
                        + " pixels (strahl decodes at most 256 scans and 5e+09 pixels times scans)");
        assertThat(TextureImages.read(Files.write(dir.resolve("ok.jpg"), p)).width()).isEqualTo(40);
    }
}
