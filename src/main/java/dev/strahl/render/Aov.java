package dev.strahl.render;

/**
 * A feature buffer (arbitrary output variable) kept beside the image: what a denoiser is guided by.
 * Each is the mean over a pixel's samples, like the image, and the same bits for any thread count.
 * They come from a tracer of their own that follows the camera ray through perfect mirrors and
 * smooth glass to the first other surface (rough surfaces count as that surface); it draws no
 * random number from the image's, so the image is the same bits with and without feature buffers.
 * Any of them makes the render trace one more ray per camera sample (plus one per specular bounce).
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
    DEPTH("depth");

    private final String id;

    Aov(String id) {
        this.id = id;
    }

    /**
     * The name on the command line, in scene files and in output file names.
     *
     * @return "albedo", "normal" or "depth"
     */
    public String id() {
        return id;
    }

    /**
     * The feature buffer of a name.
     *
     * @param id "albedo", "normal" or "depth"
     * @return the buffer
     * @throws IllegalArgumentException for any other name
     */
    public static Aov of(String id) {
        for (Aov a : values()) {
            if (a.id.equals(id)) {
                return a;
            }
        }
        throw new IllegalArgumentException("unknown feature buffer '" + id + "': use albedo, normal or depth");
    }
}
