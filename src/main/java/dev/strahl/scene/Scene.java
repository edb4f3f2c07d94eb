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
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.joml.Vector3dc;

/**
 * Everything a render needs: geometry with its BVH, materials, lights, camera and the
 * environment radiance. Immutable once built and safe to share between threads and render jobs.
 *
 * <pre>{@code
 * Scene scene = Scene.builder()
 *     .addMesh(Path.of("bunny.ply"), Material.glossy("red", new Rgb(0.6, 0.1, 0.1), Rgb.gray(0.3), 60),
 *              Transform.scaling(8).rotate(30, 0, 1, 0))
 *     .addMesh(new TriangleMesh(floorPositions, floorIndices, null), Material.diffuse("floor", Rgb.gray(0.7)))
 *     .addSphere(new Vector3d(0, 3, 0), 0.5, Material.emissive("lamp", Rgb.gray(0.8), Rgb.gray(20)))
 *     .camera(new Camera(new Vector3d(0, 1, 4), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40))
 *     .build();
 * }</pre>
 *
 * <p>{@link #geometry()}, {@link #bvh()} and {@link #lights()} are the renderer's internal view of
 * the scene; they are public for strahl's own packages and not part of the stable API.
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
    private final SceneSettings settings;

    private Scene(Geometry geometry, Bvh bvh, List<Material> materials, LightSampler lights, Camera camera,
                  Rgb environment, List<String> notes, double bvhBuildSeconds, SceneSettings settings) {
        this.geometry = geometry;
        this.bvh = bvh;
        this.materials = materials;
        this.lights = lights;
        this.camera = camera;
        this.environment = environment;
        this.notes = notes;
        this.bvhBuildSeconds = bvhBuildSeconds;
        this.settings = settings;
    }

    /**
     * Starts a scene built in code.
     *
     * @return an empty builder
     */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * All primitives in flat arrays (internal).
     *
     * @return the geometry
     */
    public Geometry geometry() {
        return geometry;
    }

    /**
     * The bounding volume hierarchy over {@link #geometry()} (internal).
     *
     * @return the BVH
     */
    @SuppressWarnings("exports")
    public Bvh bvh() {
        return bvh;
    }

    /**
     * Materials by index, as referenced by the geometry.
     *
     * @return an unmodifiable list
     */
    public List<Material> materials() {
        return materials;
    }

    /**
     * The area lights over the emissive primitives (internal).
     *
     * @return the light sampler
     */
    @SuppressWarnings("exports")
    public LightSampler lights() {
        return lights;
    }

    /**
     * The camera: the scene's own, or one framing the scene from +Z.
     *
     * @return the camera
     */
    public Camera camera() {
        return camera;
    }

    /**
     * Radiance of rays that leave the scene (constant in every direction).
     *
     * @return the environment radiance
     */
    public Rgb environment() {
        return environment;
    }

    /**
     * Remarks for the user made while building or loading (defaults chosen, input skipped).
     *
     * @return an unmodifiable list
     */
    public List<String> notes() {
        return notes;
    }

    /**
     * How long building the BVH took.
     *
     * @return seconds
     */
    public double bvhBuildSeconds() {
        return bvhBuildSeconds;
    }

    /**
     * What the scene file says about rendering (film size, integrator settings); empty for a
     * scene built in code or loaded from OBJ or PLY.
     *
     * @return the settings, never null
     */
    public SceneSettings settings() {
        return settings;
    }

    /**
     * The same scene seen through another camera; geometry and BVH are shared, not copied.
     *
     * @param newCamera the camera
     * @return a scene sharing everything else with this one
     */
    public Scene withCamera(Camera newCamera) {
        return new Scene(geometry, bvh, materials, lights, Objects.requireNonNull(newCamera), environment, notes, bvhBuildSeconds, settings);
    }

    /** Collects shapes, materials, camera and environment, then builds the BVH once. Not thread-safe. */
    public static final class Builder {
        private final Geometry.Builder geometry = new Geometry.Builder();
        private final List<Material> materials = new ArrayList<>();
        private final Map<Material, Integer> materialIndex = new IdentityHashMap<>();
        private final List<String> notes = new ArrayList<>();
        private Camera camera;
        private Rgb environment;
        private SceneSettings settings = SceneSettings.NONE;
        private int shapeCount;

        private Builder() {}

        private int indexOf(Material m) {
            Objects.requireNonNull(m, "material");
            return materialIndex.computeIfAbsent(m, k -> {
                materials.add(k);
                return materials.size() - 1;
            });
        }

        /**
         * Adds a mesh made of one material.
         *
         * @param mesh     the triangles
         * @param material what they are made of
         * @return this builder
         */
        public Builder addMesh(TriangleMesh mesh, Material material) {
            int[] perTriangle = new int[mesh.triangleCount()];
            return addMesh(mesh, perTriangle, List.of(material));
        }

        /**
         * Adds a mesh made of one material, moved by a transform.
         *
         * @param mesh      the triangles in their own coordinates
         * @param material  what they are made of
         * @param transform applied to every vertex (and normal)
         * @return this builder
         */
        public Builder addMesh(TriangleMesh mesh, Material material, Transform transform) {
            return addMesh(transform.apply(mesh), material);
        }

        /**
         * Adds the mesh in a file: an OBJ with the materials of its MTL files, or a PLY made of
         * {@link SceneLoader#DEFAULT_MATERIAL}.
         *
         * @param file      an {@code .obj} or {@code .ply} file
         * @param transform applied to every vertex (and normal)
         * @return this builder
         * @throws SceneException if the file cannot be read or is malformed
         */
        public Builder addMesh(Path file, Transform transform) throws SceneException {
            SceneLoader.addMeshFile(file, null, transform, this);
            return this;
        }

        /**
         * Adds the mesh in an OBJ or PLY file, all of it made of one material (an OBJ's MTL
         * materials are then not used).
         *
         * @param file      an {@code .obj} or {@code .ply} file
         * @param material  what every triangle is made of
         * @param transform applied to every vertex (and normal)
         * @return this builder
         * @throws SceneException if the file cannot be read or is malformed
         */
        public Builder addMesh(Path file, Material material, Transform transform) throws SceneException {
            SceneLoader.addMeshFile(file, Objects.requireNonNull(material, "material"), transform, this);
            return this;
        }

        /**
         * Adds a mesh whose triangle i is made of {@code palette.get(materialOfTriangle[i])}.
         * Parts of one material that form closed, outward-facing surfaces are marked so that
         * back-face culling may skip their inside.
         *
         * @param mesh               the triangles
         * @param materialOfTriangle per triangle, an index into {@code palette}
         * @param palette            the materials
         * @return this builder
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

        /**
         * Adds an analytic sphere.
         *
         * @param sphere   centre and radius
         * @param material what it is made of (its geometric normal points outwards)
         * @return this builder
         */
        public Builder addSphere(Sphere sphere, Material material) {
            geometry.addSphere(sphere, indexOf(material));
            shapeCount++;
            return this;
        }

        /**
         * Adds an analytic sphere.
         *
         * @param center   the centre
         * @param radius   the radius, positive
         * @param material what it is made of (its geometric normal points outwards)
         * @return this builder
         */
        public Builder addSphere(Vector3dc center, double radius, Material material) {
            return addSphere(new Sphere(center, radius), material);
        }

        /**
         * Adds an analytic sphere moved by a transform.
         *
         * @param sphere    centre and radius in the sphere's own coordinates
         * @param material  what it is made of
         * @param transform a translation, rotation and uniform scaling (nothing that would make an ellipsoid)
         * @return this builder
         * @throws IllegalArgumentException if the transform scales the axes unequally
         */
        public Builder addSphere(Sphere sphere, Material material, Transform transform) {
            return addSphere(transform.apply(sphere), material);
        }

        /**
         * The camera; without one, the scene is framed from +Z with a 40° field of view.
         *
         * @param camera the camera
         * @return this builder
         */
        public Builder camera(Camera camera) {
            this.camera = Objects.requireNonNull(camera);
            return this;
        }

        /**
         * Radiance arriving from every direction where rays leave the scene. Without one, a scene
         * with lights has a black environment and a scene without lights a white one.
         *
         * @param radiance the constant environment radiance
         * @return this builder
         */
        public Builder environment(Rgb radiance) {
            this.environment = Objects.requireNonNull(radiance);
            return this;
        }

        /**
         * What the scene asks for in rendering (a scene file's film and integrator keys).
         *
         * @param settings the settings
         * @return this builder
         */
        public Builder settings(SceneSettings settings) {
            this.settings = Objects.requireNonNull(settings);
            return this;
        }

        /**
         * Adds a remark for the user (e.g. from a loader).
         *
         * @param note one line
         * @return this builder
         */
        public Builder note(String note) {
            notes.add(note);
            return this;
        }

        /**
         * Builds the scene: concatenates the primitives, builds the BVH and collects the lights.
         *
         * @return the scene, immutable
         */
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
            return new Scene(g, bvh, List.copyOf(materials), lights, cam, env, List.copyOf(notes), buildSeconds, settings);
        }
    }
}
