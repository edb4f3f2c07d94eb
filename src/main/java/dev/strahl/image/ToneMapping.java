package dev.strahl.image;

import java.util.Locale;

/**
 * How linear radiance becomes a display value in PNG output and the viewer, after the exposure
 * scale and before the sRGB encoding. Linear outputs (PFM, EXR) are never tone-mapped.
 */
public enum ToneMapping {
    /** Clamp to [0, 1]: values above 1 saturate to white. The default, so PNGs compare as before. */
    CLAMP,
    /**
     * Krzysztof Narkowicz's fit of the ACES filmic curve (2016), per channel:
     * f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), clamped to [0, 1].
     */
    ACES,
    /**
     * Troy Sobotka's AgX, in Benjamin Wrensch's minimal form (2023): an inset matrix, log2 encoding
     * over [−12.47, 4.03] stops, a sixth-order fit of the default contrast sigmoid, the inverse
     * matrix and a 2.2 power. Highlights desaturate towards white instead of clipping in hue.
     */
    AGX;

    /**
     * The name on the command line and in the viewer.
     *
     * @return "clamp", "aces" or "agx"
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * The tone mapping of a name.
     *
     * @param id "clamp", "aces" or "agx", in any case
     * @return the tone mapping
     * @throws IllegalArgumentException for any other name
     */
    public static ToneMapping of(String id) {
        for (ToneMapping t : values()) {
            if (t.id().equalsIgnoreCase(id)) {
                return t;
            }
        }
        throw new IllegalArgumentException("unknown tone mapping '" + id + "': use clamp, aces or agx");
    }
}
