package dev.strahl.scene;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.MeshTopology;
import dev.strahl.geometry.Sphere;
import dev.strahl.image.Rgb;
import dev.strahl.material.Bsdf;
import dev.strahl.world.World;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.joml.Vector3dc;

/**
 * Everything a render needs: shapes with their materials, the lights among them, a camera and the
 * environment radiance. Immutable once built (the BVH is built then, once) and safe to share
 * between threads and render jobs. Build one in code with {@link #builder()}, or load a file with
 * {@code dev.strahl.io.SceneLoader}.
 *
 * <pre>{@code
 * Scene scene = Scene.builder()
 *     .addMesh(floor, Material.diffuse("floor", Rgb.gray(0.7)))
 *     .addMesh(cube, Material.glossy("red", new Rgb(0.6, 0.1, 0.1), Rgb.gray(0.3), 60), Transform.rotation(30, 0, 1, 0))
 *     .addSphere(new Vector3d(0, 3, 0), 0.5, Material.emissive("lamp", Rgb.gray(0.8), Rgb.gray(20)))
 *     .camera(new Camera(new Vector3d(0, 1, 4), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40))
 *     .build();
 * }</pre>
 */
public final class Scene {
    static {
        World.installSceneAccess(scene -> ((Scene) scene).world);
    }

    private final World world;
    private final List<Material> materials;
    private final Camera camera;
    private final List<String> notes;

    private Scene(World world, List<Material> materials, Camera camera, List<String> notes) {
        this.world = world;
        this.materials = materials;
        this.camera = camera;
        this.notes = notes;
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
     * The materials, each once, in the order they were first used.
     *
     * @return an unmodifiable list
     */
    public List<Material> materials() {
        return materials;
    }

    /**
     * Bytes held by the texture images of the scene's materials, each image once (a file used
     * by many materials is loaded once; an sRGB image read as colour counts its decoded copy).
     *
     * @return 0 without image textures
     */
    public long textureBytes() {
        java.util.Set<dev.strahl.texture.Bitmap> seen = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
        long bytes = 0;
        for (Material m : materials) {
            for (dev.strahl.texture.Bitmap b : m.images()) {
                if (seen.add(b)) {
                    bytes += b.byteSize();
                }
            }
        }
        return bytes;
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
     * Remarks for the user made while building or loading (defaults chosen, input skipped);
     * warnings start with {@code "warning: "}.
     *
     * @return an unmodifiable list
     */
    public List<String> notes() {
        return notes;
    }

    /**
     * The same scene seen through another camera; geometry and BVH are shared, not copied.
     *
     * @param newCamera the camera
     * @return a scene sharing everything else with this one
     */
    public Scene withCamera(Camera newCamera) {
        return new Scene(world, materials, Objects.requireNonNull(newCamera), notes);
    }

    /** Collects shapes, materials, camera and environment, then builds the BVH once. Not thread-safe. */
    public static final class Builder {
        private final GeometryBuilder geometry = new GeometryBuilder();
        private final List<Material> materials = new ArrayList<>();
        private final Map<Material, Integer> materialIndex = new IdentityHashMap<>();
        private final List<String> notes = new ArrayList<>();
        private Camera camera;
        private Rgb environment;

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
            return addMesh(mesh, new int[mesh.triangleCount()], List.of(material));
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
            boolean[] closed = MeshTopology.closedOutwardGroups(mesh.positionsUnsafe(), mesh.indicesUnsafe(), materialOfTriangle, palette.size());
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
            geometry.addMesh(mesh.positionsUnsafe(), mesh.indicesUnsafe(), mesh.normalsUnsafe(), mesh.uvsUnsafe(), materialsOut, flags);
            int skipped = geometry.degenerateCount() - before;
            if (skipped > 0) {
                notes.add("skipped " + skipped + " degenerate triangle" + (skipped == 1 ? "" : "s") + " (zero area)");
            }
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
            geometry.addSphere(new Sphere(center, radius), indexOf(material));
            return this;
        }

        /**
         * Adds an analytic sphere moved by a transform.
         *
         * @param center    the centre in the sphere's own coordinates
         * @param radius    the radius, positive
         * @param material  what it is made of
         * @param transform a translation, rotation and uniform scaling (nothing that would make an ellipsoid)
         * @return this builder
         * @throws IllegalArgumentException if the transform scales the axes unequally
         */
        public Builder addSphere(Vector3dc center, double radius, Material material, Transform transform) {
            Sphere moved = transform.apply(new Sphere(center, radius));
            return addSphere(moved.center(), moved.radius(), material);
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
         * Adds a remark for the user (e.g. from a loader); start a warning with {@code "warning: "}.
         *
         * @param note one line
         * @return this builder
         */
        public Builder note(String note) {
            notes.add(Objects.requireNonNull(note));
            return this;
        }

        /**
         * Builds the scene: concatenates the primitives, builds the BVH and collects the lights.
         *
         * @return the scene, immutable
         */
        public Scene build() {
            Geometry g = geometry.build();
            Bsdf[] bsdfs = new Bsdf[materials.size()];
            Rgb[] emission = new Rgb[materials.size()];
            for (int i = 0; i < bsdfs.length; i++) {
                bsdfs[i] = materials.get(i).bsdf();
                emission[i] = materials.get(i).emission();
            }
            Rgb env = environment;
            if (env == null) {
                env = anyEmits(g, emission) ? Rgb.BLACK : Rgb.WHITE;
                if (env == Rgb.WHITE) {
                    notes.add("the scene has no light: lighting it with a uniform white environment");
                }
            }
            World world = World.build(g, bsdfs, emission, env);
            Aabb bounds = world.bounds();
            Camera cam = camera != null ? camera : Camera.framing(bounds, 40);
            return new Scene(world, List.copyOf(materials), cam, List.copyOf(notes));
        }

        private static boolean anyEmits(Geometry g, Rgb[] emission) {
            for (int prim = 0; prim < g.primitiveCount(); prim++) {
                if (!emission[g.material(prim)].isBlack()) {
                    return true;
                }
            }
            return false;
        }
    }
}
