package dev.strahl.codec.exr;

/**
 * The compression methods of the EXR format, by their code in the {@code compression} attribute,
 * with the number of scan lines each packs into one chunk. strahl reads NONE, RLE, ZIPS, ZIP and
 * PIZ (all lossless) and writes NONE, RLE, ZIPS and ZIP; the others are named so that a file using
 * one is refused with its name.
 */
public enum ExrCompression {
    NONE(0, 1, true),
    RLE(1, 1, true),
    ZIPS(2, 1, true),
    ZIP(3, 16, true),
    PIZ(4, 32, true),
    PXR24(5, 16, false),
    B44(6, 32, false),
    B44A(7, 32, false),
    DWAA(8, 32, false),
    DWAB(9, 256, false),
    HTJ2K256(10, 256, false),
    HTJ2K32(11, 32, false),
    LJ2K(12, 0, false),                  // newer than the layout document strahl follows: lines per
    ZSTD(13, 0, false);                  // chunk not known (0); only ever named in a refusal

    private final int code;
    private final int linesPerChunk;
    private final boolean readable;

    ExrCompression(int code, int linesPerChunk, boolean readable) {
        this.code = code;
        this.linesPerChunk = linesPerChunk;
        this.readable = readable;
    }

    /** @return the value of the {@code compression} attribute */
    public int code() {
        return code;
    }

    /** @return scan lines per chunk (the last chunk of an image may hold fewer); 0 where strahl does not know it */
    public int linesPerChunk() {
        return linesPerChunk;
    }

    /** @return true if {@link ExrReader} decodes it */
    public boolean readable() {
        return readable;
    }

    /**
     * @param code the attribute's value
     * @return the method, or null for a code no OpenEXR version defines (as far as strahl knows)
     */
    public static ExrCompression ofCode(int code) {
        for (ExrCompression c : values()) {
            if (c.code == code) {
                return c;
            }
        }
        return null;
    }
}
