package dev.strahl.codec.exr;

/** The pixel types of EXR channels, by their code in the {@code chlist} attribute. */
public enum ExrPixelType {
    /** 32-bit unsigned integer (object ids and the like); read as the float nearest to it. */
    UINT(0, 4),
    /** 16-bit IEEE 754 float ({@link Half}). */
    HALF(1, 2),
    /** 32-bit IEEE 754 float. */
    FLOAT(2, 4);

    private final int code;
    private final int bytes;

    ExrPixelType(int code, int bytes) {
        this.code = code;
        this.bytes = bytes;
    }

    /** @return the code in the channel list */
    public int code() {
        return code;
    }

    /** @return bytes per sample */
    public int bytes() {
        return bytes;
    }

    static ExrPixelType ofCode(int code) {
        for (ExrPixelType t : values()) {
            if (t.code == code) {
                return t;
            }
        }
        return null;
    }
}
