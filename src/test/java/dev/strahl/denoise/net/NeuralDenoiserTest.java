package dev.strahl.denoise.net;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.codec.exr.ExrReader;
import dev.strahl.codec.ChannelImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * The network against Intel Open Image Denoise itself: noisy renders with their albedo and
 * normal, denoised by pyoidn 2.5.1 with each of the three networks
 * (docs/denoise/oidn_fixtures.py wrote src/test/resources/denoise/), must come out the same per
 * pixel within {@link #TOLERANCE} relative to the pixel's value plus {@link #FLOOR}.
 *
 * <p>The tolerance: OIDN and strahl compute the same network in single precision but sum in
 * different orders, and OIDN's pow/log/exp are not Java's; the largest difference measured over
 * both fixtures and all three networks is 9.6e-6. 1e-4 leaves room for other CPUs' rounding and
 * still fails every mistake of {@link #aSmallMistakeBreaksTheMatch}: the colour 0.1 % off
 * (differences up to 1.0e-3), the albedo one pixel to the side (1.4), normals given unmapped
 * (0.57), the largest weight of dec_conv1b 1 % larger (3.0e-4), all of enc_conv0's or
 * dec_conv0's weights 0.1 % larger (3.8e-3, 9.2e-3). (A single weight one half-ulp off stays
 * inside it: 1.7e-5.)
 */
class NeuralDenoiserTest {
    static final double TOLERANCE = 1e-4;
    static final double FLOOR = 1e-3;

    record Fixture(int width, int height, float[] color, float[] albedo, float[] normal, ChannelImage all) {
        float[] oidn(String prefix) {
            return all.select(prefix + ".R", prefix + ".G", prefix + ".B").data();
        }
    }

    static Fixture fixture(String name) throws IOException {
        ChannelImage all = ExrReader.read(Path.of("src/test/resources/denoise", name));
        return new Fixture(all.width(), all.height(), all.select("R", "G", "B").data(),
                all.select("albedo.R", "albedo.G", "albedo.B").data(), all.select("normal.X", "normal.Y", "normal.Z").data(), all);
    }

    /** The largest |strahl - oidn| / (|oidn| + FLOOR) over all pixels and channels. */
    static double worst(float[] strahl, float[] oidn) {
        double worst = 0;
        for (int i = 0; i < oidn.length; i++) {
            worst = Math.max(worst, Math.abs(strahl[i] - oidn[i]) / (Math.abs(oidn[i]) + FLOOR));
        }
        return worst;
    }

    @ParameterizedTest(name = "{0} {1}")
    @CsvSource({"cornell-box-64.exr, oidn", "cornell-box-64.exr, oidn_alb", "cornell-box-64.exr, oidn_hdr",
        "cornell-glossy-37x53.exr, oidn", "cornell-glossy-37x53.exr, oidn_alb", "cornell-glossy-37x53.exr, oidn_hdr"})
    void matchesOidnPerPixel(String file, String network) throws IOException {
        Fixture f = fixture(file);
        float[] albedo = network.equals("oidn_hdr") ? null : f.albedo();
        float[] normal = network.equals("oidn") ? f.normal() : null;
        float[] strahl = NeuralDenoiser.create().denoise(f.width(), f.height(), f.color(), albedo, normal);
        double worst = worst(strahl, f.oidn(network));
        System.out.printf(Locale.ROOT, "%s %s: worst relative difference %.3g%n", file, network, worst);
        assertThat(worst).isLessThan(TOLERANCE);
    }

    /** Mistakes the tolerance must catch, on the 64x64 fixture with albedo and normal. */
    @Test
    void aSmallMistakeBreaksTheMatch() throws IOException {
        Fixture f = fixture("cornell-box-64.exr");
        float[] oidn = f.oidn("oidn");
        NeuralDenoiser d = NeuralDenoiser.create();
        int w = f.width(), h = f.height();
        UNet net = NeuralDenoiser.network("rt_hdr_alb_nrm", 9);
        assertThat(worst(d.denoise(net, w, h, f.color(), f.albedo(), f.normal()), oidn)).isLessThan(TOLERANCE);

        float[] brighter = f.color().clone();                     // the exposure undone 0.1 % wrong
        for (int i = 0; i < brighter.length; i++) {
            brighter[i] *= 1.001f;
        }
        float[] shifted = new float[f.albedo().length];           // albedo one pixel to the right
        System.arraycopy(f.albedo(), 0, shifted, 3, shifted.length - 3);
        float[] raw = f.normal().clone();                         // normals given to the network in [-1, 1]
        for (int i = 0; i < raw.length; i++) {
            raw[i] = 2 * raw[i] - 1;
        }
        double[] mutants = {
            worst(d.denoise(net, w, h, brighter, f.albedo(), f.normal()), oidn),
            worst(d.denoise(net, w, h, f.color(), shifted, f.normal()), oidn),
            worst(d.denoise(net, w, h, f.color(), f.albedo(), raw), oidn),
            worst(d.denoise(withWeights("dec_conv1b.weight", 1, 1.01f), w, h, f.color(), f.albedo(), f.normal()), oidn),
            worst(d.denoise(withWeights("enc_conv0.weight", Integer.MAX_VALUE, 1.001f), w, h, f.color(), f.albedo(), f.normal()), oidn),
            worst(d.denoise(withWeights("dec_conv0.weight", Integer.MAX_VALUE, 1.001f), w, h, f.color(), f.albedo(), f.normal()), oidn),
        };
        System.out.println("mutants: " + java.util.Arrays.toString(mutants));
        for (double m : mutants) {
            assertThat(m).isGreaterThan(TOLERANCE);
        }
    }

    /** rt_hdr_alb_nrm with the {@code count} largest values of one tensor multiplied by {@code factor}. */
    static UNet withWeights(String tensor, int count, float factor) throws IOException {
        byte[] bytes;
        try (var in = NeuralDenoiser.class.getResourceAsStream("rt_hdr_alb_nrm.tza")) {
            bytes = in.readAllBytes();
        }
        TensorArchive archive = TensorArchive.read("rt_hdr_alb_nrm.tza", bytes);
        float[] data = archive.tensors().get(tensor).data();
        Integer[] order = new Integer[data.length];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        java.util.Arrays.sort(order, (a, b) -> Float.compare(Math.abs(data[b]), Math.abs(data[a])));
        for (int i = 0; i < Math.min(count, order.length); i++) {
            data[order[i]] *= factor;
        }
        return new UNet(archive, "changed", 9);
    }

    @Test
    void missingOrDamagedWeightsAreOneLine() {
        assertThatThrownBy(() -> NeuralDenoiser.network("rt_missing", 9)).isInstanceOf(java.io.UncheckedIOException.class)
                .hasMessage("strahl's denoiser: the weights rt_missing.tza are missing from the strahl jar"
                        + " (dev/strahl/denoise/net/)");
        // the first 1000 bytes of rt_hdr.tza, a test resource beside the real ones
        assertThatThrownBy(() -> NeuralDenoiser.network("cut-short", 3)).isInstanceOf(java.io.UncheckedIOException.class)
                .hasMessage("strahl's denoiser: damaged weights: cut-short.tza: truncated: the tensor table is at"
                        + " offset 1829504, the file has 1000 bytes");
    }

    @Test
    void theSameBitsWithAndWithoutTheVectorApi() {
        assertThat(Conv3x3.LANES).as("surefire adds jdk.incubator.vector").isTrue();
        UNet net = NeuralDenoiser.network("rt_hdr_alb_nrm", 9);
        FeatureMap in = LayersTest.random(9, 48, 80, 11);
        assertThat(net.run(in, true).data).isEqualTo(net.run(in, false).data);
    }

    @Test
    void theSameBitsOnOneThreadAsOnAll() throws Exception {
        Fixture f = fixture("cornell-glossy-37x53.exr");
        float[] all = NeuralDenoiser.create().denoise(f.width(), f.height(), f.color(), f.albedo(), f.normal());
        java.util.concurrent.ForkJoinPool one = new java.util.concurrent.ForkJoinPool(1);
        try {
            float[] single = one.submit(() -> NeuralDenoiser.create().denoise(f.width(), f.height(), f.color(), f.albedo(), f.normal())).get();
            assertThat(single).isEqualTo(all);
        } finally {
            one.shutdown();
        }
    }

    @Test
    void tilesGiveTheSameBitsAsOneWholeImage() {
        int w = 300, h = 170;                           // 304x176 padded: 5 x 1 tiles of 256
        SplittableRandom r = new SplittableRandom(5);
        float[] color = new float[3 * w * h];
        float[] albedo = new float[color.length];
        float[] normal = new float[color.length];
        for (int i = 0; i < color.length; i++) {
            int x = i / 3 % w;
            int y = i / 3 / w;
            color[i] = (float) ((x / 40 + y / 30) % 3 * r.nextExponential() * 0.5);
            albedo[i] = (x / 50 + y / 25) % 4 * 0.25f;
            normal[i] = (float) Math.cos(x * 0.05 + y * 0.07 + i % 3);
        }
        float[] whole = new NeuralDenoiser(304).denoise(w, h, color, albedo, normal);
        float[] tiled = new NeuralDenoiser(NeuralDenoiser.MIN_TILE).denoise(w, h, color, albedo, normal);
        assertThat(tiled).isEqualTo(whole);
    }
}
