package dev.strahl.denoise.net;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The U-Net of Intel Open Image Denoise's RT filter (its "base" network), with the weights of a
 * {@link TensorArchive}. Every convolution is 3x3 with a ReLU; channel counts come from the
 * weights (OIDN 2.5's default networks: 32, 48, 64, 80, 96 on the way down):
 * <pre>
 * input (C) ─ enc_conv0 ─ enc_conv1 ─ pool ─────────────────────────────────── pool1
 *   pool1 ─ enc_conv2 ─ pool ─ pool2 ─ enc_conv3 ─ pool ─ pool3 ─ enc_conv4 ─ pool ─ pool4
 *   pool4 ─ enc_conv5a ─ enc_conv5b ─ up ─ [· pool3] ─ dec_conv4a ─ dec_conv4b ─ up
 *         ─ [· pool2] ─ dec_conv3a ─ dec_conv3b ─ up ─ [· pool1] ─ dec_conv2a ─ dec_conv2b ─ up
 *         ─ [· input] ─ dec_conv1a ─ dec_conv1b ─ dec_conv0 (3 channels)
 * </pre>
 * ([a · b]: the channels of a, then those of b; pool: 2x2 max; up: nearest 2x.) Four poolings,
 * so the input's size must be a multiple of {@link #ALIGNMENT}. OIDN gives the network's
 * receptive field as 174 pixels: an output pixel depends on inputs at most 87 pixels away, so
 * tiles that overlap by {@link #OVERLAP} give the same values as one whole image.
 */
final class UNet {
    /** Four 2x2 poolings: sizes are multiples of 16. */
    static final int ALIGNMENT = 16;
    /** Half of OIDN's receptive field of this network (174 pixels), rounded up to the alignment. */
    static final int OVERLAP = 96;

    /** The layers in the order they run, each with the layers whose outputs it reads (pooled or upsampled as run() does). */
    private static final String[][] LAYERS = {
        {"enc_conv0", "input"}, {"enc_conv1", "enc_conv0"}, {"enc_conv2", "enc_conv1"}, {"enc_conv3", "enc_conv2"},
        {"enc_conv4", "enc_conv3"}, {"enc_conv5a", "enc_conv4"}, {"enc_conv5b", "enc_conv5a"},
        {"dec_conv4a", "enc_conv5b", "enc_conv3"}, {"dec_conv4b", "dec_conv4a"},
        {"dec_conv3a", "dec_conv4b", "enc_conv2"}, {"dec_conv3b", "dec_conv3a"},
        {"dec_conv2a", "dec_conv3b", "enc_conv1"}, {"dec_conv2b", "dec_conv2a"},
        {"dec_conv1a", "dec_conv2b", "input"}, {"dec_conv1b", "dec_conv1a"}, {"dec_conv0", "dec_conv1b"},
    };

    final int inputChannels;
    private final Map<String, Conv3x3> convs = new LinkedHashMap<>();

    /**
     * The network of an archive, checked: every layer's weights [out][in][3][3] and bias [out]
     * present, each layer's inputs the channels of what feeds it, 3 output channels.
     *
     * @throws TensorArchiveException naming the archive and the first layer that does not fit
     */
    UNet(TensorArchive archive, String source, int inputChannels) throws TensorArchiveException {
        this.inputChannels = inputChannels;
        Map<String, Integer> channels = new LinkedHashMap<>();
        channels.put("input", inputChannels);
        for (String[] layer : LAYERS) {
            String name = layer[0];
            TensorArchive.Tensor weight = archive.tensors().get(name + ".weight");
            if (weight == null || weight.dims().length != 4) {
                throw new TensorArchiveException(source + ": no 4-dimensional tensor '" + name + ".weight'");
            }
            int in = 0;
            for (int i = 1; i < layer.length; i++) {
                in += channels.get(layer[i]);
            }
            int out = weight.dim(0);
            archive.tensor(name + ".weight", out, in, 3, 3);
            float[] bias = archive.tensor(name + ".bias", out).data();
            if (name.equals("dec_conv0") && out != 3) {
                throw new TensorArchiveException(source + ": dec_conv0 has " + out + " output channels, expected 3");
            }
            convs.put(name, new Conv3x3(name, in, out, weight.data(), bias));
            channels.put(name, out);
        }
    }

    /**
     * Runs the network.
     *
     * @param input {@link #inputChannels} channels, height and width multiples of {@link #ALIGNMENT}
     * @return its 3 output channels, the same size
     */
    FeatureMap run(FeatureMap input) {
        return run(input, Conv3x3.LANES);
    }

    /** {@link #run(FeatureMap)} on the Vector API path or the scalar twin (the same bits; for tests). */
    FeatureMap run(FeatureMap input, boolean lanes) {
        if (input.channels != inputChannels || input.height % ALIGNMENT != 0 || input.width % ALIGNMENT != 0) {
            throw new IllegalArgumentException("the network takes " + inputChannels + " channels, sizes multiples of " + ALIGNMENT
                    + "; got " + input.channels + " channels, " + input.width + "x" + input.height);
        }
        FeatureMap x = conv("enc_conv0", lanes, input);
        FeatureMap pool1 = Resample.pool(conv("enc_conv1", lanes, x));
        FeatureMap pool2 = Resample.pool(conv("enc_conv2", lanes, pool1));
        FeatureMap pool3 = Resample.pool(conv("enc_conv3", lanes, pool2));
        FeatureMap pool4 = Resample.pool(conv("enc_conv4", lanes, pool3));
        x = Resample.upsample(conv("enc_conv5b", lanes, conv("enc_conv5a", lanes, pool4)));
        x = Resample.upsample(conv("dec_conv4b", lanes, conv("dec_conv4a", lanes, x, pool3)));
        x = Resample.upsample(conv("dec_conv3b", lanes, conv("dec_conv3a", lanes, x, pool2)));
        x = Resample.upsample(conv("dec_conv2b", lanes, conv("dec_conv2a", lanes, x, pool1)));
        x = conv("dec_conv1a", lanes, x, input);               // the upsampled maps (64 channels at full size) are garbage now
        return conv("dec_conv0", lanes, conv("dec_conv1b", lanes, x));
    }

    private FeatureMap conv(String name, boolean lanes, FeatureMap... sources) {
        Conv3x3 conv = convs.get(name);
        FeatureMap dst = new FeatureMap(conv.outputs, sources[0].height, sources[0].width);
        conv.apply(lanes, sources, dst);
        return dst;
    }

    /** The layers, in order (for tests). */
    List<Conv3x3> layers() {
        return new ArrayList<>(convs.values());
    }
}
