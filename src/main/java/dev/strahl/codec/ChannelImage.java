package dev.strahl.codec;

import dev.strahl.image.Image;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;

/**
 * A decoded image with any number of named channels, as every image reader of strahl returns it
 * ({@code ExrReader}, {@link HdrReader}, {@link TextureImages}).
 *
 * <p><b>Layout.</b> {@code data} holds the samples interleaved by pixel, rows from the TOP of the
 * image down, each row left to right: the sample of channel {@code c} at column {@code x}, row
 * {@code y} is {@code data[(y * width + x) * channels.size() + c]}. Samples are linear floats
 * exactly as the file stores them (no sRGB decoding, no exposure, no clamping; integer formats are
 * scaled to [0, 1]). Channel names are the file's (EXR: {@code "R"}, {@code "albedo.R"},
 * {@code "Z"}, ... in the file's order, which is sorted by name) or, for formats without names,
 * {@code Y} (grey), {@code Y, A}, {@code R, G, B} or {@code R, G, B, A}.
 *
 * <p>The record owns {@code data}: it is not copied in or out (images are large), so a caller
 * that changes the array changes the image. Equality is that of records: the same array.
 *
 * @param width    width in pixels, positive
 * @param height   height in pixels, positive
 * @param channels the channel names, distinct, at least one
 * @param data     width · height · channels.size() samples, laid out as above
 */
public record ChannelImage(int width, int height, List<String> channels, float[] data) {

    /** Checks the sizes against each other. */
    public ChannelImage {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        channels = List.copyOf(channels);
        if (channels.isEmpty()) {
            throw new IllegalArgumentException("an image needs at least one channel");
        }
        if (new HashSet<>(channels).size() != channels.size()) {
            throw new IllegalArgumentException("channel names must be distinct, got " + channels);
        }
        Objects.requireNonNull(data, "data");
        if (data.length != (long) width * height * channels.size()) {
            throw new IllegalArgumentException("expected " + (long) width * height * channels.size() + " samples for " + width + "x"
                    + height + " with " + channels.size() + " channel(s), got " + data.length);
        }
    }

    /** @return the number of channels, the stride between pixels in {@link #data()} */
    public int channelCount() {
        return channels.size();
    }

    /**
     * @param name a channel name
     * @return its index, or -1 if the image has no such channel
     */
    public int channel(String name) {
        return channels.indexOf(name);
    }

    /**
     * One sample.
     *
     * @param x column, from 0 at the left
     * @param y row, from 0 at the top
     * @param c channel index
     * @return the sample
     */
    public float get(int x, int y, int c) {
        return data[(y * width + x) * channels.size() + c];
    }

    /**
     * A new image of the named channels, in the order given.
     *
     * @param names channel names of this image
     * @return the new image (its own array)
     * @throws IllegalArgumentException if a name is not a channel of this image
     */
    public ChannelImage select(String... names) {
        int[] from = new int[names.length];
        for (int i = 0; i < names.length; i++) {
            from[i] = channel(names[i]);
            if (from[i] < 0) {
                throw new IllegalArgumentException("no channel '" + names[i] + "' (the channels are " + String.join(", ", channels) + ")");
            }
        }
        return gather(List.of(names), from, Float.NaN);
    }

    /** @return true if {@link #rgb()} works: the image has R, G and B channels, or Y */
    public boolean hasColour() {
        return channels.containsAll(List.of("R", "G", "B")) || channels.contains("Y");
    }

    /**
     * The colour as linear RGB: the channels R, G, B, or Y (grey) copied to all three.
     *
     * @return a three-channel image named R, G, B
     * @throws IllegalArgumentException if {@link #hasColour()} is false
     */
    public ChannelImage rgb() {
        return gather(List.of("R", "G", "B"), colourSources(false), Float.NaN);
    }

    /**
     * The colour and alpha: as {@link #rgb()}, plus the A channel, or 1 (opaque) where there is none.
     *
     * @return a four-channel image named R, G, B, A
     * @throws IllegalArgumentException if {@link #hasColour()} is false
     */
    public ChannelImage rgba() {
        return gather(List.of("R", "G", "B", "A"), colourSources(true), 1f);
    }

    /**
     * The colour as the API's image type.
     *
     * @return {@link #rgb()} as an {@link Image}
     * @throws IllegalArgumentException if {@link #hasColour()} is false
     */
    public Image toImage() {
        return new Image(width, height, rgb().data);
    }

    private int[] colourSources(boolean alpha) {
        int[] from;
        if (channels.containsAll(List.of("R", "G", "B"))) {
            from = new int[] {channel("R"), channel("G"), channel("B")};
        } else if (channels.contains("Y")) {
            int y = channel("Y");
            from = new int[] {y, y, y};
        } else {
            throw new IllegalArgumentException("no colour channels (R, G, B or Y); the channels are " + String.join(", ", channels));
        }
        if (alpha) {
            from = Arrays.copyOf(from, 4);
            from[3] = channel("A");          // -1: filled with the default
        }
        return from;
    }

    /** Copies channel {@code from[i]} to channel i of a new image; -1 fills it with {@code fill}. */
    private ChannelImage gather(List<String> names, int[] from, float fill) {
        int n = channels.size();
        int m = from.length;
        long pixels = (long) width * height;
        float[] out = new float[Math.toIntExact(pixels * m)];
        for (long p = 0; p < pixels; p++) {
            int src = (int) (p * n);
            int dst = (int) (p * m);
            for (int i = 0; i < m; i++) {
                out[dst + i] = from[i] < 0 ? fill : data[src + from[i]];
            }
        }
        return new ChannelImage(width, height, new ArrayList<>(names), out);
    }
}
