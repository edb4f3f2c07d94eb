package dev.strahl.testing;

import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.Ray;
import dev.strahl.image.Image;
import dev.strahl.scene.Camera;
import dev.strahl.scene.TriangleMesh;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.ToDoubleFunction;
import org.joml.Vector3d;

/** Meshes made in code for tests. */
public final class Meshes {
    private Meshes() {}

    /**
     * A closed icosphere of the given radius around the origin (subdivided icosahedron, vertices
     * projected onto the sphere), wound outwards or, with {@code inward}, towards the centre.
     */
    public static TriangleMesh icosphere(int subdivisions, double radius, boolean inward) {
        double t = (1 + Math.sqrt(5)) / 2;
        List<double[]> v = new ArrayList<>();
        double[][] base = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (double[] p : base) {
            v.add(normalize(p));
        }
        int[][] faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
            {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        List<int[]> f = new ArrayList<>(List.of(faces));
        for (int s = 0; s < subdivisions; s++) {
            Map<Long, Integer> mid = new HashMap<>();
            List<int[]> next = new ArrayList<>();
            for (int[] tri : f) {
                int a = midpoint(tri[0], tri[1], v, mid);
                int b = midpoint(tri[1], tri[2], v, mid);
                int c = midpoint(tri[2], tri[0], v, mid);
                next.add(new int[] {tri[0], a, c});
                next.add(new int[] {tri[1], b, a});
                next.add(new int[] {tri[2], c, b});
                next.add(new int[] {a, b, c});
            }
            f = next;
        }
        float[] pos = new float[3 * v.size()];
        for (int i = 0; i < v.size(); i++) {
            for (int k = 0; k < 3; k++) {
                pos[3 * i + k] = (float) (v.get(i)[k] * radius);
            }
        }
        int[] idx = new int[3 * f.size()];
        for (int i = 0; i < f.size(); i++) {
            int[] tri = f.get(i);
            idx[3 * i] = tri[0];
            idx[3 * i + 1] = inward ? tri[2] : tri[1];
            idx[3 * i + 2] = inward ? tri[1] : tri[2];
        }
        return new TriangleMesh(pos, idx, null);
    }

    private static int midpoint(int a, int b, List<double[]> v, Map<Long, Integer> cache) {
        long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
        return cache.computeIfAbsent(key, k -> {
            double[] p = v.get(a), q = v.get(b);
            v.add(normalize(new double[] {p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
            return v.size() - 1;
        });
    }

    private static double[] normalize(double[] p) {
        double l = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return new double[] {p[0] / l, p[1] / l, p[2] / l};
    }

    /** Adds a mesh to a geometry under construction, all its triangles with one flag (closed or not). */
    public static GeometryBuilder add(GeometryBuilder builder, TriangleMesh mesh, int[] materials, boolean closed) {
        byte[] flags = new byte[mesh.triangleCount()];
        java.util.Arrays.fill(flags, closed ? Geometry.CLOSED : 0);
        return add(builder, mesh, materials, flags);
    }

    /** Adds a mesh to a geometry under construction with per-triangle flags. */
    public static GeometryBuilder add(GeometryBuilder builder, TriangleMesh mesh, int[] materials, byte[] flags) {
        return builder.addMesh(mesh.positions(), mesh.indices(), mesh.normals(), materials, flags);
    }

    /** The camera's ray generator for a film size. */
    public static CameraRays rays(Camera c, int width, int height) {
        return CameraRays.pinholeOf(c, width, height);
    }

    /**
     * The closed form of a Lambertian floor y = 0 of reflectance {@code albedo} seen by {@code camera}:
     * ρ/π · E(p), E given per point of the floor, integrated over each pixel by 8×8 rays (grey).
     */
    public static Image floorRadiance(Camera camera, int size, double albedo, ToDoubleFunction<Vector3d> irradiance) {
        CameraRays rays = rays(camera, size, size);
        Ray ray = new Ray();
        float[] rgb = new float[size * size * 3];
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                double sum = 0;
                for (int j = 0; j < 8; j++) {
                    for (int i = 0; i < 8; i++) {
                        rays.generate(x + (i + 0.5) / 8, y + (j + 0.5) / 8, ray);
                        double t = -ray.o.y / ray.d.y;
                        sum += irradiance.applyAsDouble(new Vector3d(ray.d).mul(t).add(ray.o));
                    }
                }
                float v = (float) (albedo / Math.PI * sum / 64);
                rgb[3 * (y * size + x)] = rgb[3 * (y * size + x) + 1] = rgb[3 * (y * size + x) + 2] = v;
            }
        }
        return new Image(size, size, rgb);
    }
}
