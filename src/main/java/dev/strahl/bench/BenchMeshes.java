package dev.strahl.bench;

import dev.strahl.io.text.LongIntMap;
import dev.strahl.sampling.SplitMix64;
import dev.strahl.scene.TriangleMesh;
import java.util.List;
import java.util.function.Supplier;

/**
 * The benchmark's own meshes, made in code so that {@code strahl bench} runs from a bare clone:
 * at the triangle counts of the scanned models it was first measured on (the Stanford bunny,
 * 69 k; a dragon, 100 k; the bunny subdivided twice, 1.1 M), and with what makes a scanned
 * model's tree hard: bumps at every scale, triangles of uneven size, parts of the surface close
 * to other parts. Deterministic: the same bits on every machine (integer hashing, plain double
 * arithmetic and {@code StrictMath}, whose results Java defines to the last bit).
 */
public final class BenchMeshes {
    private BenchMeshes() {}

    /** A generated mesh with its name in the benchmark's results and how it was made. */
    public record Generated(String name, String description, Supplier<TriangleMesh> mesh) {}

    /** The three meshes {@code bench} measures by default, smallest first. */
    public static List<Generated> defaults() {
        return List.of(
                new Generated("displaced-sphere-69k", "generated: cube sphere, 76² quads per face, fractal displacement",
                        () -> displacedSphere(76)),
                new Generated("torus-knot-100k", "generated: (3, 7) torus knot tube, 1000 × 50 quads, bumped",
                        () -> torusKnot(1000, 50)),
                new Generated("displaced-sphere-1.1m", "generated: cube sphere, 303² quads per face, fractal displacement",
                        () -> displacedSphere(303)));
    }

    /**
     * A sphere of radius about 1 made of the six faces of a cube, each cut into n × n quads (two
     * triangles each: 12 n² in all), pushed out to the sphere and then along the radius by
     * fractal noise of five octaves (amplitude up to about ±0.3). Cube sphere rather than a
     * latitude–longitude one: no slivers at the poles, but triangles still vary in size by about
     * 2× from a face's centre to its corners. Faces share the vertices of the cube's edges, so
     * the surface is closed, as a scanned model's is.
     */
    public static TriangleMesh displacedSphere(int n) {
        int side = n + 1;
        int corners = 6 * side * side;                  // an upper bound: the cube's edges are shared
        float[] positions = new float[corners * 3];
        int[] indices = new int[6 * n * n * 6];
        int[] grid = new int[side * side];              // the vertex of each lattice point of the current face
        LongIntMap vertexAt = new LongIntMap();         // lattice point (x, y, z) in [0, n]³ → its vertex
        int vertices = 0;
        int t = 0;
        int[] lattice = new int[3];
        for (int face = 0; face < 6; face++) {
            int axis = face / 2;
            boolean positive = face % 2 == 0;
            for (int j = 0; j <= n; j++) {
                for (int i = 0; i <= n; i++) {
                    lattice[axis] = positive ? n : 0;
                    lattice[(axis + 1) % 3] = i;
                    lattice[(axis + 2) % 3] = j;
                    long key = ((long) lattice[0] * side + lattice[1]) * side + lattice[2];
                    int vertex = vertexAt.putIfAbsent(key, vertices);
                    if (vertex < 0) {
                        vertex = vertices++;
                        spherePoint(-1 + 2.0 * lattice[0] / n, -1 + 2.0 * lattice[1] / n, -1 + 2.0 * lattice[2] / n, positions, 3 * vertex);
                    }
                    grid[j * side + i] = vertex;
                }
            }
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    int a = grid[j * side + i], b = grid[j * side + i + 1], c = grid[(j + 1) * side + i + 1], d = grid[(j + 1) * side + i];
                    t = quad(indices, t, a, b, c, d, !positive);         // wound outwards on every face
                }
            }
        }
        return new TriangleMesh(java.util.Arrays.copyOf(positions, 3 * vertices), indices, null);
    }

    /** The cube point (x, y, z) pushed out to the unit sphere, then along the radius by the noise. */
    private static void spherePoint(double x, double y, double z, float[] dest, int at) {
        double len = StrictMath.sqrt(x * x + y * y + z * z);
        x /= len;
        y /= len;
        z /= len;
        double r = 1 + 0.3 * fractalNoise(1.5 * x, 1.5 * y, 1.5 * z, 5);
        dest[at] = (float) (r * x);
        dest[at + 1] = (float) (r * y);
        dest[at + 2] = (float) (r * z);
    }

    /**
     * A tube of radius 0.35 around the (p, q) = (3, 7) torus knot x = (2 + cos qφ) cos pφ,
     * y = (2 + cos qφ) sin pφ, z = −sin qφ, cut into {@code segments} rings of {@code sides}
     * quads, its radius bumped by ±20 % noise. The knot's strands pass close to each other, so
     * boxes of distant parts of the tube overlap, as the limbs of a scanned figure do.
     */
    public static TriangleMesh torusKnot(int segments, int sides) {
        float[] positions = new float[segments * sides * 3];
        int[] indices = new int[segments * sides * 6];
        double[] c = new double[3], ahead = new double[3], behind = new double[3];
        int v = 0;
        for (int s = 0; s < segments; s++) {
            double phi = 2 * Math.PI * s / segments, h = 1e-4;
            knot(phi, c);
            knot(phi + h, ahead);
            knot(phi - h, behind);
            // Frenet frame from central differences: tangent T, normal N (towards the curvature), binormal B.
            double[] tangent = normalize(ahead[0] - behind[0], ahead[1] - behind[1], ahead[2] - behind[2]);
            double[] bend = {ahead[0] - 2 * c[0] + behind[0], ahead[1] - 2 * c[1] + behind[1], ahead[2] - 2 * c[2] + behind[2]};
            double[] binormal = normalize(tangent[1] * bend[2] - tangent[2] * bend[1], tangent[2] * bend[0] - tangent[0] * bend[2],
                    tangent[0] * bend[1] - tangent[1] * bend[0]);
            double[] normal = {binormal[1] * tangent[2] - binormal[2] * tangent[1], binormal[2] * tangent[0] - binormal[0] * tangent[2],
                binormal[0] * tangent[1] - binormal[1] * tangent[0]};
            for (int k = 0; k < sides; k++) {
                double theta = 2 * Math.PI * k / sides;
                double ox = StrictMath.cos(theta) * normal[0] + StrictMath.sin(theta) * binormal[0];
                double oy = StrictMath.cos(theta) * normal[1] + StrictMath.sin(theta) * binormal[1];
                double oz = StrictMath.cos(theta) * normal[2] + StrictMath.sin(theta) * binormal[2];
                double r = 0.35 * (1 + 0.2 * fractalNoise(3 * (c[0] + 0.35 * ox), 3 * (c[1] + 0.35 * oy), 3 * (c[2] + 0.35 * oz), 4));
                positions[v++] = (float) (c[0] + r * ox);
                positions[v++] = (float) (c[1] + r * oy);
                positions[v++] = (float) (c[2] + r * oz);
            }
        }
        int t = 0;
        for (int s = 0; s < segments; s++) {
            int next = (s + 1) % segments;
            for (int k = 0; k < sides; k++) {
                int k1 = (k + 1) % sides;
                t = quad(indices, t, s * sides + k, s * sides + k1, next * sides + k1, next * sides + k, false);
            }
        }
        return new TriangleMesh(positions, indices, null);
    }

    private static void knot(double phi, double[] dest) {
        double r = 2 + StrictMath.cos(7 * phi);
        dest[0] = r * StrictMath.cos(3 * phi);
        dest[1] = r * StrictMath.sin(3 * phi);
        dest[2] = -StrictMath.sin(7 * phi);
    }

    /** Two triangles (a, b, c) and (a, c, d) of the quad a b c d, or their mirror images. */
    private static int quad(int[] indices, int t, int a, int b, int c, int d, boolean flip) {
        int second = flip ? d : b, third = flip ? b : d;
        indices[t] = a;
        indices[t + 1] = second;
        indices[t + 2] = c;
        indices[t + 3] = a;
        indices[t + 4] = c;
        indices[t + 5] = third;
        return t + 6;
    }

    private static double[] normalize(double x, double y, double z) {
        double len = StrictMath.sqrt(x * x + y * y + z * z);
        return new double[] {x / len, y / len, z / len};
    }

    /** Sum of {@code octaves} octaves of value noise, each of twice the frequency and half the amplitude; in about [−1, 1]. */
    static double fractalNoise(double x, double y, double z, int octaves) {
        double sum = 0, amplitude = 0.5, frequency = 1;
        for (int o = 0; o < octaves; o++) {
            sum += amplitude * valueNoise(x * frequency, y * frequency, z * frequency, o);
            amplitude *= 0.5;
            frequency *= 2.03;          // not exactly 2: octaves' lattices do not line up
        }
        return sum;
    }

    /** Trilinear value noise with smoothstep weights: lattice values in [−1, 1] from a hash of (cell, octave). */
    private static double valueNoise(double x, double y, double z, int octave) {
        double fx = StrictMath.floor(x), fy = StrictMath.floor(y), fz = StrictMath.floor(z);
        long ix = (long) fx, iy = (long) fy, iz = (long) fz;
        double ux = smooth(x - fx), uy = smooth(y - fy), uz = smooth(z - fz);
        double result = 0;
        for (int corner = 0; corner < 8; corner++) {
            int dx = corner & 1, dy = corner >> 1 & 1, dz = corner >> 2;
            double w = (dx == 1 ? ux : 1 - ux) * (dy == 1 ? uy : 1 - uy) * (dz == 1 ? uz : 1 - uz);
            result += w * lattice(ix + dx, iy + dy, iz + dz, octave);
        }
        return result;
    }

    private static double smooth(double f) {
        return f * f * (3 - 2 * f);
    }

    private static double lattice(long x, long y, long z, int octave) {
        long h = SplitMix64.mix64(SplitMix64.mix64(SplitMix64.mix64(x * 0x9e3779b97f4a7c15L + octave) ^ y) ^ z);
        return SplitMix64.toUnit(h) * 2 - 1;
    }
}
