package dev.strahl.io.gltf;

import dev.strahl.codec.Printable;
import dev.strahl.scene.SceneException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;

/**
 * The binary glTF container (.glb): a 12-byte header (magic "glTF", version 2, total length),
 * then chunks of (length, type, data): the JSON chunk first, then at most one BIN chunk; other
 * chunk types are skipped, as the specification asks. Every length is checked against the file.
 *
 * @param json       the file's bytes
 * @param jsonOffset where the JSON chunk's data starts
 * @param jsonLength its length
 * @param bin        the BIN chunk's data, or null
 */
record GlbContainer(byte[] json, int jsonOffset, int jsonLength, ByteBuffer bin) {
    static final int MAGIC = 0x46546C67;            // "glTF" little-endian
    static final int JSON = 0x4E4F534A;             // "JSON"
    static final int BIN = 0x004E4942;              // "BIN\0"

    /** Whether the bytes start as a GLB file does. */
    static boolean isGlb(byte[] bytes) {
        return bytes.length >= 4 && ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).getInt(0) == MAGIC;
    }

    /** Why a file is not a GLB file, quoting its first bytes (escaped: they may be anything). */
    static String wrongMagic(byte[] bytes) {
        if (bytes.length == 0) {
            return "not a GLB file: it is empty";
        }
        boolean json = bytes[0] == '{' || bytes[0] == ' ' || bytes[0] == '\n' || bytes[0] == (byte) 0xEF;
        return "not a GLB file: it starts with '" + Printable.bytes(bytes, 0, 4) + "' instead of the magic 'glTF'"
                + (json ? " (a .gltf JSON file under a .glb name?)" : "");
    }

    static GlbContainer read(Path file, byte[] bytes) throws SceneException {
        ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        if (bytes.length < 12) {
            throw new SceneException(file, "truncated GLB: " + bytes.length + " bytes, the header alone has 12");
        }
        if (b.getInt(0) != MAGIC) {
            throw new SceneException(file, wrongMagic(bytes));
        }
        int version = b.getInt(4);
        if (version != 2) {
            throw new SceneException(file, "GLB version " + Integer.toUnsignedString(version) + " is not supported (only 2)");
        }
        long total = Integer.toUnsignedLong(b.getInt(8));
        if (total > bytes.length) {
            throw new SceneException(file, "truncated GLB: the header says " + total + " bytes, the file has " + bytes.length);
        }
        int jsonOffset = -1;
        int jsonLength = 0;
        ByteBuffer bin = null;
        long pos = 12;
        int chunk = 0;
        while (pos < total) {
            if (pos + 8 > total) {
                throw new SceneException(file, "truncated GLB: chunk " + chunk + "'s header at byte " + pos + " is cut off");
            }
            long length = Integer.toUnsignedLong(b.getInt((int) pos));
            int type = b.getInt((int) pos + 4);
            long data = pos + 8;
            if (data + length > total) {
                throw new SceneException(file, "GLB chunk " + chunk + " (" + typeName(type) + ", " + length + " bytes at byte " + data
                        + ") runs past the end of the file (" + total + " bytes)");
            }
            if (chunk == 0 && type != JSON) {
                throw new SceneException(file, "GLB: the first chunk must be JSON, got " + typeName(type));
            }
            if (type == JSON && chunk == 0) {
                jsonOffset = (int) data;
                jsonLength = (int) length;
            } else if (type == BIN && bin == null && chunk == 1) {
                bin = ByteBuffer.wrap(bytes, (int) data, (int) length).slice().order(ByteOrder.LITTLE_ENDIAN);
            }
            pos = data + length;
            chunk++;
        }
        if (jsonOffset < 0) {
            throw new SceneException(file, "GLB has no JSON chunk");
        }
        return new GlbContainer(bytes, jsonOffset, jsonLength, bin);
    }

    private static String typeName(int type) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 4; i++) {
            int c = (type >>> (8 * i)) & 0xFF;
            if (c >= 0x20 && c < 0x7F) {
                s.append((char) c);
            } else if (c != 0) {
                s.append(String.format("\\x%02x", c));
            }
        }
        return "'" + s + "'";
    }
}
