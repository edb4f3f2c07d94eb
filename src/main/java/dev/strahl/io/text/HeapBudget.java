package dev.strahl.io.text;

import dev.strahl.codec.ImageLimits;
import java.util.Locale;

/**
 * A lower bound on what a mesh costs once loaded and built, so that a reader can refuse a mesh
 * that cannot fit in the Java heap while it is still reading, before the scene's copies and its
 * BVH are allocated (running out of memory half-way is caught too, but says less).
 */
public final class HeapBudget {
    /**
     * Bytes per triangle that loading and rendering need at the least: the reader's index and
     * material arrays (16), the mesh's and the geometry's copies of them (12 + 12 + 17 + 17), the
     * BVH's primitive references and nodes (about 4 + 16), and the triangle's share of the
     * vertices (about half a vertex: 12 bytes per copy of a position, in four copies, and the
     * reader's vertex map). The bunny (1.1 M triangles) peaks at about 250 bytes per triangle of
     * live heap (330 in use before a collection).
     */
    static final long MIN_BYTES_PER_TRIANGLE = 150;

    /** The heap's maximum, or a smaller one set by tests. */
    public static long limit = 0;

    private HeapBudget() {}

    static long heap() {
        return limit > 0 ? limit : Runtime.getRuntime().maxMemory();
    }

    /** Null if {@code triangles} can fit, else why not (for a {@code file:line:} message). */
    public static String tooMany(long triangles) {
        long need = triangles * MIN_BYTES_PER_TRIANGLE;
        long heap = heap();
        if (need <= heap) {
            return null;
        }
        return String.format(Locale.ROOT, "the mesh needs at least %s (%d triangles so far, at least %d bytes each), more than"
                + " the Java heap's %s: give Java more memory (java -Xmx...)", ImageLimits.bytes(need), triangles, MIN_BYTES_PER_TRIANGLE, ImageLimits.bytes(heap));
    }
}
