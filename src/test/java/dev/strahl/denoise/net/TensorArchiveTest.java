package dev.strahl.denoise.net;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The .tza reader: OIDN's shipped weights, small archives written here, and damaged ones refused in one line. */
class TensorArchiveTest {

    static byte[] resource(String name) throws IOException {
        try (InputStream in = NeuralDenoiser.class.getResourceAsStream(name)) {
            return in.readAllBytes();
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"rt_hdr_alb_nrm.tza, 9", "rt_hdr_alb.tza, 6", "rt_hdr.tza, 3"})
    void readsTheShippedWeights(String file, int inputs) throws IOException {
        TensorArchive a = TensorArchive.read(file, resource(file));
        assertThat(a.tensors()).hasSize(32);
        assertThat(a.tensor("enc_conv0.weight", 32, inputs, 3, 3).layout()).isEqualTo("oihw");
        assertThat(a.tensor("dec_conv1a.weight", 64, 64 + inputs, 3, 3).data()).hasSize(64 * (64 + inputs) * 9);
        assertThat(a.tensor("dec_conv0.bias", 3).layout()).isEqualTo("x");
        assertThat(new UNet(a, file, inputs).layers()).hasSize(16);
    }

    @Test
    void halvesAreReadExactly() throws IOException {
        TensorArchive a = TensorArchive.read("rt_hdr_alb_nrm.tza", resource("rt_hdr_alb_nrm.tza"));
        // numpy: np.frombuffer(file, '<f2', count=2, offset=<enc_conv0.bias>) -> [-0.10315, 0.25708]
        assertThat(a.tensor("enc_conv0.bias", 32).data()[0]).isEqualTo(-1.03149414e-01f);
        assertThat(a.tensor("enc_conv0.bias", 32).data()[1]).isEqualTo(2.57080078e-01f);
    }

    @Test
    void readsFloatAndHalfTensors() throws IOException {
        byte[] file = TzaFiles.write(List.of(
                new TzaFiles.Entry("a.weight", new int[] {2, 1, 3, 3}, 'f', floats(18, 0.1f)),
                new TzaFiles.Entry("a.bias", new int[] {2}, 'h', new float[] {0.5f, -2})));
        TensorArchive a = TensorArchive.read("t.tza", file);
        assertThat(a.tensors().keySet()).containsExactly("a.weight", "a.bias");
        assertThat(a.tensor("a.weight", 2, 1, 3, 3).data()).containsExactly(floats(18, 0.1f));
        assertThat(a.tensor("a.bias", 2).data()).containsExactly(0.5f, -2f);
        assertThatThrownBy(() -> a.tensor("a.bias", 3)).isInstanceOf(TensorArchiveException.class)
                .hasMessage("t.tza: tensor 'a.bias' has dimensions [2], expected [3]");
        assertThatThrownBy(() -> a.tensor("b.bias", 2)).hasMessage("t.tza: no tensor 'b.bias'");
    }

    static float[] floats(int n, float step) {
        float[] v = new float[n];
        for (int i = 0; i < n; i++) {
            v[i] = i * step - 1;
        }
        return v;
    }

    /** One tensor "w" [2, 1, 3, 3] of floats: header 12 bytes, data at 64, the table after it. */
    static byte[] one() {
        return TzaFiles.write(List.of(new TzaFiles.Entry("w", new int[] {2, 1, 3, 3}, 'f', floats(18, 0.5f))));
    }

    static int table(byte[] file) {
        return (int) ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN).getLong(4);
    }

    static void refused(byte[] file, String message) {
        assertThatThrownBy(() -> TensorArchive.read("w.tza", file)).isInstanceOf(TensorArchiveException.class).hasMessage("w.tza: " + message);
    }

    @Test
    void refusesDamagedFilesInOneLine() {
        byte[] good = one();
        int t = table(good);                         // count (4), name length (2), "w", rank (1), dims (16), "oihw", type, offset (8)
        int dims = t + 4 + 2 + 1 + 1;
        refused(Arrays.copyOf(good, 7), "truncated: the header needs bytes 0..12, the file has 7");
        refused(with(good, 0, (byte) 0x42), "not a tensor archive (magic 0x4142, expected 0x41D7)");
        refused(with(good, 2, (byte) 1), "format version 1.0, only version 2 is supported");
        refused(withLong(good, 4, good.length + 1L), "truncated: the tensor table is at offset " + (good.length + 1) + ", the file has "
                + good.length + " bytes");
        refused(withLong(good, 4, -5), "truncated: the tensor table is at offset 18446744073709551611, the file has " + good.length + " bytes");
        refused(withInt(good, t, 1000), "the table claims 1000 tensors, more than its " + (good.length - t - 4) + " bytes can hold");
        refused(Arrays.copyOf(good, good.length - 3), "truncated: the entry of tensor 'w' needs bytes " + (dims) + ".." + (dims + 29)
                + ", the file has " + (good.length - 3));
        refused(with(good, dims + 16, (byte) 'x'), "tensor 'w' has layout 'xihw' (expected x or oihw)");
        refused(with(good, dims + 20, (byte) 'd'), "tensor 'w' has data type 'd' (expected f or h)");
        refused(withInt(good, dims, 2000), "truncated: tensor 'w' [2000, 1, 3, 3] needs 72000 bytes at offset 64, the file has " + good.length);
        refused(withInt(withInt(withInt(good, dims, -1), dims + 4, -1), dims + 8, -1),
                "tensor 'w' has dimension 4294967295");
        refused(withLong(good, dims + 21, good.length - 8L), "truncated: tensor 'w' [2, 1, 3, 3] needs 72 bytes at offset "
                + (good.length - 8) + ", the file has " + good.length);
        byte[] twice = TzaFiles.write(List.of(new TzaFiles.Entry("w", new int[] {1}, 'h', new float[1]),
                new TzaFiles.Entry("w", new int[] {1}, 'h', new float[1])));
        assertThatThrownBy(() -> TensorArchive.read("w.tza", twice)).hasMessage("w.tza: tensor 'w' appears twice");
    }

    @Test
    void tensorsThatOverlapAreRefusedBeforeTheyAreAllocated() {
        byte[] two = TzaFiles.write(List.of(new TzaFiles.Entry("a", new int[] {1}, 'f', new float[1]),
                new TzaFiles.Entry("b", new int[] {1}, 'f', new float[1])));
        int t = table(two);
        int whole = (two.length - 12) / 4;            // floats from the header's end to the file's: each alone fits
        byte[] b = two;
        for (int entry = t + 4; entry < two.length; entry += 18) {      // name length, name, rank, one dim, layout, type, offset
            b = withLong(withInt(b, entry + 4, whole), entry + 10, 12);
        }
        refused(b, "tensor 'b' makes the tensors' data " + 8L * whole + " bytes, more than the file's " + two.length + " (tensors overlap)");
    }

    @Test
    void aHostileNameIsQuotedPrintablyAndShort() {
        String name = "\u001b[2J" + "x".repeat(100);
        byte[] file = TzaFiles.write(List.of(new TzaFiles.Entry(name, new int[] {1}, 'f', new float[1])));
        int type = table(file) + 4 + 2 + name.length() + 1 + 4 + 1;
        refused(with(file, type, (byte) '\n'), "tensor '\\x1b[2J" + "x".repeat(28) + "...' has data type '\\n' (expected f or h)");
    }

    @Test
    void aNetworkThatDoesNotFitIsRefusedByName() throws IOException {
        TensorArchive hdr = TensorArchive.read("rt_hdr.tza", resource("rt_hdr.tza"));
        assertThatThrownBy(() -> new UNet(hdr, "rt_hdr.tza", 9)).isInstanceOf(TensorArchiveException.class)
                .hasMessage("rt_hdr.tza: tensor 'enc_conv0.weight' has dimensions [32, 3, 3, 3], expected [32, 9, 3, 3]");
        List<TzaFiles.Entry> tiny = new java.util.ArrayList<>(TzaFiles.tinyUNet(1));
        assertThat(new UNet(TensorArchive.read("tiny", TzaFiles.write(tiny)), "tiny", 9).layers()).hasSize(16);
        tiny.remove(20);                              // dec_conv3b.weight
        assertThatThrownBy(() -> new UNet(TensorArchive.read("tiny", TzaFiles.write(tiny)), "tiny", 9))
                .hasMessage("tiny: no 4-dimensional tensor 'dec_conv3b.weight'");
    }

    static byte[] with(byte[] file, int at, byte value) {
        byte[] b = file.clone();
        b[at] = value;
        return b;
    }

    static byte[] withInt(byte[] file, int at, int value) {
        byte[] b = file.clone();
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(at, value);
        return b;
    }

    static byte[] withLong(byte[] file, int at, long value) {
        byte[] b = file.clone();
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putLong(at, value);
        return b;
    }
}
