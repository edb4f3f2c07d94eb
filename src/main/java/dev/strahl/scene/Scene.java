package dev.strahl.scene;

import dev.strahl.accel.Bvh;
import dev.strahl.camera.Camera;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.MeshTopology;
import dev.strahl.geometry.Sphere;
import dev.strahl.geometry.TriangleMesh;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Material;
import dev.strahl.math.Rgb;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Everything a render needs: geometry with its BVH, materials, lights, camera and the
 * environment radiance. Immutable once built and safe to share between threads and render jobs.
 *
 * <pre>{@code
 * Scene scene = Scene.builder()
 *     .addMesh(mesh, Material.diffuse("white", Rgb.gray(0.8)))
 *     .addSphere(new Sphere(new Vector3d(0, 1, 0), 0.5), Material.emissive("lamp", Rgb.gray(0.8), Rgb.gray(10)))
 *     .camera(new Camera(new Vector3d(0, 1, 4), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40))
 *     .build();
 * }</pre>
 */
public final class Scene {
    private final Geometry geometry;
    private final Bvh bvh;
    private final List<Material> materials;
    private final LightSampler lights;
    private final Camera camera;
    private final Rgb environment;
    private final List<String> notes;
    private final double bvhBuildSeconds;

    private Scene(Geometry geometry, Bvh bvh, List<Material> materials, LightSampler lights, Camera camera,
                  Rgb environment, List<String> notes, double bvhBuildSeconds) {
        this.geometry = geometry;
        this.bvh = bvh;
        this.materials = materials;
        this.lights = lights;
        this.camera = camera;
        this.environment = environment;
        this.notes = notes;
        this.bvhBuildSeconds = bvhBuildSeconds;
    }

    public static Builder builder() {
        return new Builder();
    }

    public Geometry geometry() {
        return geometry;
    }

    public Bvh bvh() {
        return bvh;
    }

    /** Materials by index, as referenced by the geometry. */
    public List<Material> materials() {
        return materials;
    }

    public LightSampler lights() {
        return lights;
    }

    public Camera camera() {
        return camera;
    }

    /** Radiance of rays that leave the scene (constant in every direction). */
    public Rgb environment() {
        return environment;
    }

    /** Remarks for the user made while building or loading (defaults chosen, input skipped). */
    public List<String> notes() {
        return notes;
    }

    public double bvhBuildSeconds() {
        return bvhBuildSeconds;
    }

    /** The same scene seen through another camera; geometry and BVH are shared, not copied. */
    public Scene withCamera(Camera newCamera) {
        return new Scene(geometry, bvh, materials, lights, Objects.requireNonNull(newCamera), environment, notes, bvhBuildSeconds);
    }

    /** Collects shapes, materials, camera and environment, then builds the BVH once. */
    public static final class Builder {
        private final Geometry.Builder geometry = new Geometry.Builder();
        private final List<Material> materials = new ArrayList<>();
        private final Map<Material, Integer> materialIndex = new IdentityHashMap<>();
        private final List<String> notes = new ArrayList<>();
        private Camera camera;
        private Rgb environment;
        private int shapeCount;

        private Builder() {}

        private int indexOf(Material m) {
            Objects.requireNonNull(m, "material");
            return materialIndex.computeIfAbsent(m, k -> {
                materials.add(k);
                return materials.size() - 1;
            });
        }

        /** Adds a mesh made of one material. */
        public Builder addMesh(TriangleMesh mesh, Material material) {
            int[] perTriangle = new int[mesh.triangleCount()];
            return addMesh(mesh, perTriangle, List.of(material));
        }

        /**
         * Adds a mesh whose triangle i is made of {@code palette.get(materialOfTriangle[i])}.
         * Parts of one material that form closed, outward-facing surfaces are marked so that
         * back-face culling may skip their inside.
         */
        public Builder addMesh(TriangleMesh mesh, int[] materialOfTriangle, List<Material> palette) {
            if (materialOfTriangle.length != mesh.triangleCount()) {
                throw new IllegalArgumentException("need one material per triangle: " + materialOfTriangle.length + " for " + mesh.triangleCount());
            }
            int[] global = new int[palette.size()];
            for (int i = 0; i < palette.size(); i++) {
                global[i] = indexOf(palette.get(i));
            }
            boolean[] closed = MeshTopology.closedOutwardGroups(mesh.positions(), mesh.indices(), materialOfTriangle, palette.size());
            int[] materialsOut = new int[mesh.triangleCount()];
            byte[] flags = new byte[mesh.triangleCount()];
            for (int t = 0; t < materialsOut.length; t++) {
                int local = materialOfTriangle[t];
                if (local < 0 || local >= palette.size()) {
                    throw new IllegalArgumentException("triangle " + t + " refers to material " + local + " of " + palette.size());
                }
                materialsOut[t] = global[local];
                flags[t] = closed[local] ? Geometry.CLOSED : 0;
            }
            int before = geometry.degenerateCount();
            geometry.addMesh(mesh, materialsOut, flags);
            int skipped = geometry.degenerateCount() - before;
            if (skipped > 0) {
                notes.add("skipped " + skipped + " degenerate triangle" + (skipped == 1 ? "" : "s") + " (zero area)");
            }
            shapeCount++;
            return this;
        }

        public Builder addSphere(Sphere sphere, Material material) {
            geometry.addSphere(sphere, indexOf(material));
            shapeCount++;
            return this;
        }

        /** The camera; without one, the scene is framed from +Z with a 40° field of view. */
        public Builder camera(Camera camera) {
            this.camera = Objects.requireNonNull(camera);
            return this;
        }

        /**
         * Radiance arriving from every direction where rays leave the scene. Without one, a scene
         * with lights has a black environment and a scene without lights a white one.
         */
        public Builder environment(Rgb radiance) {
            this.environment = Objects.requireNonNull(radiance);
            return this;
        }

        /** Adds a remark for the user (e.g. from a loader). */
        public Builder note(String note) {
            notes.add(note);
            return this;
        }

        public Scene build() {
            Geometry g = geometry.build();
            long start = System.nanoTime();
            Bvh bvh = Bvh.build(g);
            double buildSeconds = (System.nanoTime() - start) * 1e-9;
            g = bvh.geometry();                 // the same primitives, reordered into the BVH's leaves
            Rgb[] emission = new Rgb[materials.size()];
            for (int i = 0; i < emission.length; i++) {
                emission[i] = materials.get(i).emission();
            }
            LightSampler lights = new LightSampler(g, emission);
            Rgb env = environment;
            if (env == null) {
                if (lights.isEmpty()) {
                    env = Rgb.WHITE;
                    notes.add("the scene has no light: lighting it with a uniform white environment");
                } else {
                    env = Rgb.BLACK;
                }
            }
            Camera cam = camera != null ? camera : Camera.framing(g.bounds(), 40);
            return new Scene(g, bvh, List.copyOf(materials), lights, cam, env, List.copyOf(notes), buildSeconds);
        }
    }
}
