package dev.strahl.render;

/**
 * A buffer (arbitrary output variable) kept beside the image: the feature buffers a denoiser is
 * guided by ({@link #ALBEDO}, {@link #NORMAL}, {@link #DEPTH}), and the sample count of every pixel
 * ({@link #SPP}). The feature buffers are each the mean over a pixel's samples, like the image, and
 * the same bits for any thread count. They come from a tracer of their own that follows the camera
 * ray through perfect mirrors and smooth glass to the first other surface (rough surfaces count as
 * that surface); it draws no random number from the image's, so the image is the same bits with
 * and without feature buffers. Any of them makes the render trace one more ray per camera sample
 * (plus one per specular bounce); the sample count costs nothing while rendering.
 */
public enum Aov {
    /**
     * The reflectance of the first non-specular surface the camera ray meets, tinted by the
     * mirrors on the way (black where the ray leaves the scene).
     */
    ALBEDO("albedo"),
    /** That surface's shading normal in world space, facing the ray (zero where the ray leaves the scene). */
    NORMAL("normal"),
    /** The distance along the camera ray to its first hit, in scene units (0 where it leaves the scene). */
    DEPTH("depth"),
    /**
     * The number of samples each pixel took: the same everywhere, except with a noise threshold
     * ({@link RenderSettings#withNoiseThreshold}), where it shows where the samples went.
     */
    SPP("spp");

    private final String id;

    Aov(String id) {
        this.id = id;
    }

    /**
     * The name on the command line, in scene files and in output file names.
     *
     * @return "albedo", "normal", "depth" or "spp"
     */
    public String id() {
        return id;
    }

    /**
     * Whether this is a feature buffer traced beside each camera sample (albedo, normal, depth),
     * which the film keeps sums of; not the sample count.
     *
     * @return true for {@link #ALBEDO}, {@link #NORMAL} and {@link #DEPTH}
     */
    public boolean traced() {
        return this != SPP;
    }

    /**
     * The buffer of a name.
     *
     * @param id "albedo", "normal", "depth" or "spp"
     * @return the buffer
     * @throws IllegalArgumentException for any other name
     */
    public static Aov of(String id) {
        for (Aov a : values()) {
            if (a.id.equals(id)) {
                return a;
            }
        }
        throw new IllegalArgumentException("unknown feature buffer '" + id + "': use albedo, normal, depth or spp");
    }
}
