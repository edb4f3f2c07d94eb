package dev.strahl.texture;

/**
 * Which value of a texel a scalar texture reads. A grey image has R = G = B = its grey value; an
 * image without alpha has A = 1.
 */
public enum Channel {
    R, G, B, A,
    /** Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B of the linear values. */
    LUMINANCE
}
