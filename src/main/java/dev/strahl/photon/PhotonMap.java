package dev.strahl.photon;

import dev.strahl.integrator.Parallel;
import java.util.Arrays;

/**
 * The photons of one iteration in a hashed uniform grid, for radius and k-nearest-neighbour
 * queries. Space is cut into cubic cells of a given size (the iteration's gather radius); cell
 * (i, j, k) of the photons' bounding box goes to bucket h(i + nx·(j + ny·k)) of a power-of-two
 * table with at least twice as many buckets as photons, h being Fibonacci hashing (Knuth, TAOCP
 * vol. 3, §6.4: multiply by 2⁶⁴/φ, keep the top bits). Photons are counting-sorted by bucket
 * into one flat float array ({@link PhotonList} layout), so a bucket's photons are contiguous.
 * A radius query visits the distinct buckets of the cells that the query's bounding cube
 * overlaps — with cells as large as the radius at most 3×3×3 — and tests each photon's
 * distance; cells that share a bucket are visited once, and photons of other cells in a bucket
 * are rejected by the distance test, so hash collisions cost time, never correctness.
 *
 * <p>The build is deterministic: the bucket of each photon is computed in parallel chunks, the
 * counting sort is sequential and stable, so the order depends only on the input order.
 * Immutable after {@link #build}; queries are thread-safe given one {@link Search} per thread.
 */
final class PhotonMap {
    /** Cells per axis at most, so that cell coordinates and the linear cell index stay exact. */
    static final int MAX_CELLS_PER_AXIS = 1 << 20;
    /** A query overlapping more cells than this scans every photon instead (huge radii only). */
    static final int MAX_QUERY_CELLS = 64;
    private static final int BUILD_CHUNK = 1 << 14;
    private static final long FIBONACCI = 0x9E3779B97F4A7C15L;
    private static final int STRIDE = PhotonList.STRIDE;

    /** What a radius query reports: photon index (into {@link #data()}) and squared distance. */
    @FunctionalInterface
    interface Visitor {
        void visit(int photon, double dist2);
    }

    private final float[] data;
    private final int[] start;          // bucket b holds photons start[b] .. start[b+1]-1
    private final int size;
    private final int shift;            // 64 - log2(bucket count)
    private final double minX, minY, minZ, maxX, maxY, maxZ;
    private final double cellSize, invCell;
    private final int nx, ny, nz;

    private PhotonMap(float[] data, int[] start, int size, int shift, double[] box, double cellSize, int[] dims) {
        this.data = data;
        this.start = start;
        this.size = size;
        this.shift = shift;
        this.minX = box[0];
        this.minY = box[1];
        this.minZ = box[2];
        this.maxX = box[3];
        this.maxY = box[4];
        this.maxZ = box[5];
        this.cellSize = cellSize;
        this.invCell = 1 / cellSize;
        this.nx = dims[0];
        this.ny = dims[1];
        this.nz = dims[2];
    }

    /** A map without photons. */
    static PhotonMap empty() {
        return build(new PhotonList(1), 1, Parallel.sequential(null));
    }

    /**
     * Builds the map of {@code photons} (copied; the list may be reused afterwards) with cells of
     * edge {@code cellSize} (enlarged if the photons' extent would need more than
     * {@value #MAX_CELLS_PER_AXIS} cells per axis). The per-photon hashing runs through
     * {@code parallel}; the result does not depend on how it schedules the chunks.
     */
    static PhotonMap build(PhotonList photons, double cellSize, Parallel parallel) {
        if (!(cellSize > 0) || !Double.isFinite(cellSize)) {
            throw new IllegalArgumentException("cell size must be positive and finite, got " + cellSize);
        }
        int n = photons.size();
        float[] src = photons.data();
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int i = 0, o = 0; i < n; i++, o += STRIDE) {
            for (int a = 0; a < 3; a++) {
                box[a] = Math.min(box[a], src[o + a]);
                box[a + 3] = Math.max(box[a + 3], src[o + a]);
            }
        }
        if (n == 0) {
            Arrays.fill(box, 0);
        }
        double extent = Math.max(box[3] - box[0], Math.max(box[4] - box[1], box[5] - box[2]));
        double cell = Math.max(cellSize, extent / (MAX_CELLS_PER_AXIS - 1));
        int[] dims = new int[3];
        for (int a = 0; a < 3; a++) {
            dims[a] = Math.min(MAX_CELLS_PER_AXIS, (int) ((box[a + 3] - box[a]) / cell) + 1);
        }
        int bits = Math.max(4, 64 - Long.numberOfLeadingZeros(Math.max(1, 2L * n - 1)));
        int shift = 64 - bits;
        int buckets = 1 << bits;

        PhotonMap layout = new PhotonMap(null, null, 0, shift, box, cell, dims);
        int[] bucketOf = new int[n];
        int chunks = (n + BUILD_CHUNK - 1) / BUILD_CHUNK;
        parallel.forEach(chunks, (c, worker) -> {
            int end = Math.min(n, (c + 1) * BUILD_CHUNK);
            for (int i = c * BUILD_CHUNK, o = i * STRIDE; i < end; i++, o += STRIDE) {
                bucketOf[i] = layout.bucket(layout.cellX(src[o]), layout.cellY(src[o + 1]), layout.cellZ(src[o + 2]));
            }
        });

        // Stable counting sort by bucket.
        int[] start = new int[buckets + 1];
        for (int i = 0; i < n; i++) {
            start[bucketOf[i] + 1]++;
        }
        for (int b = 0; b < buckets; b++) {
            start[b + 1] += start[b];
        }
        int[] next = Arrays.copyOf(start, buckets);
        float[] data = new float[n * STRIDE];
        for (int i = 0; i < n; i++) {
            System.arraycopy(src, i * STRIDE, data, next[bucketOf[i]]++ * STRIDE, STRIDE);
        }
        return new PhotonMap(data, start, n, shift, box, cell, dims);
    }

    int size() {
        return size;
    }

    /** The edge of a grid cell. */
    double cellSize() {
        return cellSize;
    }

    /** The photons in the map's order ({@link PhotonList} layout); read-only. */
    float[] data() {
        return data;
    }

    /** Reports every photon within {@code radius} (inclusive) of (x, y, z) to the visitor, each once. */
    void forEachWithin(double x, double y, double z, double radius, Search search, Visitor visitor) {
        if (size == 0 || !(radius >= 0)
                || x + radius < minX || x - radius > maxX || y + radius < minY || y - radius > maxY
                || z + radius < minZ || z - radius > maxZ) {
            return;
        }
        double r2 = radius * radius;
        int x0 = cellX(x - radius), x1 = cellX(x + radius);
        int y0 = cellY(y - radius), y1 = cellY(y + radius);
        int z0 = cellZ(z - radius), z1 = cellZ(z + radius);
        long cells = (long) (x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1);
        if (cells > MAX_QUERY_CELLS) {
            scan(0, size, x, y, z, r2, visitor);
            return;
        }
        int[] seen = search.buckets;
        int distinct = 0;
        for (int k = z0; k <= z1; k++) {
            for (int j = y0; j <= y1; j++) {
                for (int i = x0; i <= x1; i++) {
                    int b = bucket(i, j, k);
                    boolean duplicate = false;
                    for (int s = 0; s < distinct && !duplicate; s++) {
                        duplicate = seen[s] == b;
                    }
                    if (!duplicate) {
                        seen[distinct++] = b;
                        scan(start[b], start[b + 1], x, y, z, r2, visitor);
                    }
                }
            }
        }
    }

    private void scan(int from, int to, double x, double y, double z, double r2, Visitor visitor) {
        for (int p = from, o = from * STRIDE; p < to; p++, o += STRIDE) {
            double dx = data[o] - x, dy = data[o + 1] - y, dz = data[o + 2] - z;
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 <= r2) {
                visitor.visit(p, d2);
            }
        }
    }

    /**
     * The (at most) k photons nearest to (x, y, z) within {@code maxRadius}, nearest first (ties
     * by index), into {@code outPhoton} and {@code outDist2}; returns how many were found.
     * Searches balls of growing radius (the cell size, doubled until k photons lie inside, the
     * ball holds every photon, or it reaches maxRadius): the k nearest in a ball that holds k
     * photons are the k nearest overall.
     */
    int nearest(double x, double y, double z, int k, double maxRadius, Search search, int[] outPhoton, double[] outDist2) {
        if (k <= 0 || size == 0 || !(maxRadius >= 0)) {
            return 0;
        }
        double dx = Math.max(Math.abs(x - minX), Math.abs(x - maxX));
        double dy = Math.max(Math.abs(y - minY), Math.abs(y - maxY));
        double dz = Math.max(Math.abs(z - minZ), Math.abs(z - maxZ));
        double farthest = Math.sqrt(dx * dx + dy * dy + dz * dz);
        search.reset(k);
        for (double radius = Math.min(cellSize, maxRadius); ; radius = Math.min(2 * radius, maxRadius)) {
            search.heapSize = 0;
            forEachWithin(x, y, z, radius, search, search);
            if (search.heapSize == k || radius >= maxRadius || radius >= farthest) {
                break;
            }
        }
        return search.drainSorted(outPhoton, outDist2);
    }

    private int cellX(double v) {
        return clampCell(Math.floor((v - minX) * invCell), nx);
    }

    private int cellY(double v) {
        return clampCell(Math.floor((v - minY) * invCell), ny);
    }

    private int cellZ(double v) {
        return clampCell(Math.floor((v - minZ) * invCell), nz);
    }

    private static int clampCell(double c, int n) {
        return c <= 0 ? 0 : c >= n - 1 ? n - 1 : (int) c;     // NaN becomes 0
    }

    private int bucket(int i, int j, int k) {
        long key = i + nx * (j + (long) ny * k);
        return (int) ((key * FIBONACCI) >>> shift);
    }

    /**
     * Per-thread scratch of the queries: the buckets already visited, and the bounded max-heap of
     * the k-nearest search (ordered by distance, then index, so ties are deterministic).
     */
    static final class Search implements Visitor {
        final int[] buckets = new int[MAX_QUERY_CELLS];
        private int[] heapPhoton = new int[16];
        private double[] heapDist2 = new double[16];
        private int heapSize;
        private int k;

        void reset(int capacity) {
            k = capacity;
            if (heapPhoton.length < capacity) {
                heapPhoton = new int[capacity];
                heapDist2 = new double[capacity];
            }
            heapSize = 0;
        }

        @Override
        public void visit(int photon, double dist2) {
            if (heapSize < k) {
                int i = heapSize++;
                heapPhoton[i] = photon;
                heapDist2[i] = dist2;
                siftUp(i);
            } else if (less(photon, dist2, heapPhoton[0], heapDist2[0])) {
                heapPhoton[0] = photon;
                heapDist2[0] = dist2;
                siftDown(0, heapSize);
            }
        }

        /** Empties the heap into the arrays, nearest first; returns the count. */
        int drainSorted(int[] outPhoton, double[] outDist2) {
            int n = heapSize;
            for (int end = n - 1; end > 0; end--) {    // heap sort: the largest goes to the end
                swap(0, end);
                siftDown(0, end);
            }
            System.arraycopy(heapPhoton, 0, outPhoton, 0, n);
            System.arraycopy(heapDist2, 0, outDist2, 0, n);
            heapSize = 0;
            return n;
        }

        private static boolean less(int pa, double da, int pb, double db) {
            return da < db || (da == db && pa < pb);
        }

        private boolean less(int a, int b) {
            return less(heapPhoton[a], heapDist2[a], heapPhoton[b], heapDist2[b]);
        }

        private void siftUp(int i) {
            while (i > 0) {
                int parent = (i - 1) >>> 1;
                if (!less(parent, i)) {
                    return;
                }
                swap(parent, i);
                i = parent;
            }
        }

        private void siftDown(int i, int n) {
            while (true) {
                int l = 2 * i + 1, r = l + 1, largest = i;
                if (l < n && less(largest, l)) {
                    largest = l;
                }
                if (r < n && less(largest, r)) {
                    largest = r;
                }
                if (largest == i) {
                    return;
                }
                swap(i, largest);
                i = largest;
            }
        }

        private void swap(int a, int b) {
            int p = heapPhoton[a];
            heapPhoton[a] = heapPhoton[b];
            heapPhoton[b] = p;
            double d = heapDist2[a];
            heapDist2[a] = heapDist2[b];
            heapDist2[b] = d;
        }
    }
}
