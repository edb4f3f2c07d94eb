package dev.strahl.texture;

/**
 * An affine map of texture coordinates applied before the lookup: scale by (su, sv), then rotate
 * by {@code rotation} (radians, counter-clockwise about the origin), then offset by (ou, ov):
 * u' = cos r · su u − sin r · sv v + ou, v' = sin r · su u + cos r · sv v + ov, the matrix
 * T·R·S of glTF's KHR_texture_transform (turned to strahl's bottom-left coordinates by the glTF
 * reader) and of Blender's Mapping node. With rotation 0 this is MTL's {@code -s} and {@code -o}
 * and a scene file's {@code uvScale}. Immutable; the matrix is computed once, so a lookup
 * costs four multiplications.
 */
public final class UvTransform {
    /** The identity: (u, v) unchanged. */
    public static final UvTransform IDENTITY = new UvTransform(1, 1, 0, 0, 0);

    private final double scaleU, scaleV, offsetU, offsetV, rotation;
    /** R·S: u' = m00 u + m01 v + ou, v' = m10 u + m11 v + ov. */
    private final double m00, m01, m10, m11;

    /**
     * Checks that every parameter is finite.
     *
     * @param scaleU   su
     * @param scaleV   sv
     * @param offsetU  ou
     * @param offsetV  ov
     * @param rotation r in radians, counter-clockwise
     */
    public UvTransform(double scaleU, double scaleV, double offsetU, double offsetV, double rotation) {
        if (!Double.isFinite(scaleU) || !Double.isFinite(scaleV) || !Double.isFinite(offsetU) || !Double.isFinite(offsetV)
                || !Double.isFinite(rotation)) {
            throw new IllegalArgumentException("texture coordinate transform must be finite, got scale (" + scaleU + ", " + scaleV
                    + "), offset (" + offsetU + ", " + offsetV + "), rotation " + rotation);
        }
        this.scaleU = scaleU;
        this.scaleV = scaleV;
        this.offsetU = offsetU;
        this.offsetV = offsetV;
        this.rotation = rotation;
        double c = Math.cos(rotation), s = Math.sin(rotation);
        this.m00 = c * scaleU;
        this.m01 = -s * scaleV;
        this.m10 = s * scaleU;
        this.m11 = c * scaleV;
    }

    /** Scale then offset, no rotation. */
    public static UvTransform of(double scaleU, double scaleV, double offsetU, double offsetV) {
        return new UvTransform(scaleU, scaleV, offsetU, offsetV, 0);
    }

    /** u' of (u, v). */
    public double mapU(double u, double v) {
        return rotation == 0 ? scaleU * u + offsetU : m00 * u + m01 * v + offsetU;
    }

    /** v' of (u, v). */
    public double mapV(double u, double v) {
        return rotation == 0 ? scaleV * v + offsetV : m10 * u + m11 * v + offsetV;
    }

    public double scaleU() {
        return scaleU;
    }

    public double scaleV() {
        return scaleV;
    }

    public double offsetU() {
        return offsetU;
    }

    public double offsetV() {
        return offsetV;
    }

    /** The rotation in radians, counter-clockwise. */
    public double rotation() {
        return rotation;
    }

    /** Whether this is the identity map. */
    public boolean isIdentity() {
        return equals(IDENTITY);
    }

    /** Equal parameters, compared as a record compares doubles. */
    @Override
    public boolean equals(Object o) {
        return o instanceof UvTransform t && Double.compare(t.scaleU, scaleU) == 0 && Double.compare(t.scaleV, scaleV) == 0
                && Double.compare(t.offsetU, offsetU) == 0 && Double.compare(t.offsetV, offsetV) == 0 && Double.compare(t.rotation, rotation) == 0;
    }

    @Override
    public int hashCode() {
        int h = Double.hashCode(scaleU);
        h = 31 * h + Double.hashCode(scaleV);
        h = 31 * h + Double.hashCode(offsetU);
        h = 31 * h + Double.hashCode(offsetV);
        return 31 * h + Double.hashCode(rotation);
    }

    /** The parameters in a record's form (a checkpoint's scene digest includes it). */
    @Override
    public String toString() {
        return "UvTransform[scaleU=" + scaleU + ", scaleV=" + scaleV + ", offsetU=" + offsetU + ", offsetV=" + offsetV + ", rotation=" + rotation + "]";
    }
}
