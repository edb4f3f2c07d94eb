package dev.strahl.texture;

/**
 * An affine map of texture coordinates applied before the lookup: rotate by {@code rotation}
 * (radians, counter-clockwise about the origin), then scale by (su, sv), then offset by (ou, ov):
 * u' = su (u cos r − v sin r) + ou, v' = sv (u sin r + v cos r) + ov. With rotation 0 this is
 * MTL's {@code -s} and {@code -o} and a scene file's {@code uvScale}.
 *
 * @param scaleU   su, finite
 * @param scaleV   sv, finite
 * @param offsetU  ou, finite
 * @param offsetV  ov, finite
 * @param rotation r in radians, finite
 */
public record UvTransform(double scaleU, double scaleV, double offsetU, double offsetV, double rotation) {
    /** The identity: (u, v) unchanged. */
    public static final UvTransform IDENTITY = new UvTransform(1, 1, 0, 0, 0);

    /** Checks that every parameter is finite. */
    public UvTransform {
        if (!Double.isFinite(scaleU) || !Double.isFinite(scaleV) || !Double.isFinite(offsetU) || !Double.isFinite(offsetV)
                || !Double.isFinite(rotation)) {
            throw new IllegalArgumentException("texture coordinate transform must be finite, got scale (" + scaleU + ", " + scaleV
                    + "), offset (" + offsetU + ", " + offsetV + "), rotation " + rotation);
        }
    }

    /** Scale then offset, no rotation. */
    public static UvTransform of(double scaleU, double scaleV, double offsetU, double offsetV) {
        return new UvTransform(scaleU, scaleV, offsetU, offsetV, 0);
    }

    /** Whether this is the identity map. */
    public boolean isIdentity() {
        return equals(IDENTITY);
    }
}
