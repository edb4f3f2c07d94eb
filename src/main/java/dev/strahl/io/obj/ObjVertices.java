package dev.strahl.io.obj;

import dev.strahl.io.text.LongIntMap;
import java.util.Arrays;

/**
 * The vertices of the mesh an OBJ file makes: each distinct (position, texture coordinate,
 * normal) index triple of its faces, numbered in the order the faces first use it, and the
 * per-vertex arrays of the mesh made from them ({@link #positions}, {@link #normals}, {@link #uvs}).
 */
final class ObjVertices {
    /** A face vertex without texture coordinate or normal. */
    static final int NONE = -1;

    private final LongIntMap vertexIds = new LongIntMap();
    /** The distinct (texture coordinate, normal) index pairs, numbered: a vertex is (position, that number). */
    private final LongIntMap attributeIds = new LongIntMap();
    private int attributeCount;
    private int[] position = new int[1024];
    private int[] normal = new int[1024];
    private int[] texcoord = new int[1024];
    private int count;
    private boolean anyNormal, anyTexcoord;

    /** The number of the vertex of OBJ position {@code p}, texture coordinate {@code tex} and normal {@code nrm} (or {@link #NONE}), new or not. */
    int vertex(int p, int tex, int nrm) {
        int attribute = attributeIds.putIfAbsent(((tex + 1L) << 32) | (nrm + 1L), attributeCount);
        if (attribute < 0) {
            attribute = attributeCount++;
        }
        long key = ((long) p << 32) | attribute;
        int id = vertexIds.putIfAbsent(key, count);
        if (id >= 0) {
            return id;
        }
        if (count == position.length) {
            int n = (int) Math.min(Math.max(count + 1L, count + (count >> 1) + 16L), Integer.MAX_VALUE - 16);
            position = Arrays.copyOf(position, n);
            normal = Arrays.copyOf(normal, n);
            texcoord = Arrays.copyOf(texcoord, n);
        }
        position[count] = p;
        normal[count] = nrm;
        texcoord[count] = tex;
        anyNormal |= nrm != NONE;
        anyTexcoord |= tex != NONE;
        return count++;
    }

    /** The OBJ position index of vertex {@code id}. */
    int position(int id) {
        return position[id];
    }

    /** x, y, z per vertex, from the OBJ positions {@code v} (float triples). */
    float[] positions(float[] v) {
        float[] out = new float[count * 3];
        for (int i = 0; i < count; i++) {
            System.arraycopy(v, position[i] * 3, out, i * 3, 3);
        }
        return out;
    }

    /** The normal per vertex from the OBJ normals {@code vn} (NaN where a vertex has none), or null if no face gives one. */
    float[] normals(float[] vn) {
        if (!anyNormal) {
            return null;
        }
        float[] out = new float[count * 3];
        for (int i = 0; i < count; i++) {
            if (normal[i] == NONE) {
                Arrays.fill(out, i * 3, i * 3 + 3, Float.NaN);
            } else {
                System.arraycopy(vn, normal[i] * 3, out, i * 3, 3);
            }
        }
        return out;
    }

    /** u, v per vertex from the OBJ texture coordinates {@code vt} (NaN where a vertex has none), or null if no face gives one. */
    float[] uvs(float[] vt) {
        if (!anyTexcoord) {
            return null;
        }
        float[] out = new float[count * 2];
        for (int i = 0; i < count; i++) {
            if (texcoord[i] == NONE) {
                out[2 * i] = Float.NaN;
                out[2 * i + 1] = Float.NaN;
            } else {
                System.arraycopy(vt, texcoord[i] * 2, out, i * 2, 2);
            }
        }
        return out;
    }
}
