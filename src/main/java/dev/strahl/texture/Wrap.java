package dev.strahl.texture;

/** How texel indices outside the image are brought back into it (glTF's three sampler modes). */
public enum Wrap {
    /** The image tiles the plane: index i reads i mod n (Mitsuba's default). */
    REPEAT,
    /** The border texels extend outwards: i reads clamp(i, 0, n − 1). */
    CLAMP,
    /** The image tiles the plane mirrored every other time: 0 … n−1, n−1 … 0, 0 … */
    MIRRORED_REPEAT;

    /** The texel index in [0, n) that index {@code i} reads. */
    int index(int i, int n) {
        switch (this) {
            case REPEAT:
                return Math.floorMod(i, n);
            case CLAMP:
                return i < 0 ? 0 : Math.min(i, n - 1);
            default:
                int m = Math.floorMod(i, 2 * n);
                return m < n ? m : 2 * n - 1 - m;
        }
    }
}
