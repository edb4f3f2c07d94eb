package dev.strahl.scene;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.MeshTopology;
import dev.strahl.geometry.Sphere;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.light.Emission;
import dev.strahl.light.Environment;
import dev.strahl.material.Bsdf;
import dev.strahl.world.SurfaceMaps;
import dev.strahl.world.World;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.joml.Vector3dc;

/**
 * Everything a render needs: shapes with their materials, the lights among them, a camera and the
 * environment (a constant radiance or a latitude–longitude map).
 * Lights are emissive materials, punctual lights ({@link Builder#pointLight}, {@link
 * Builder#spotLight}, {@link Builder#directionalLight}) and the environment.
 * A scene without any light gets strahl's studio sky (a procedural sky with a soft sun) and, without
 * a camera, is framed from a raised three-quarter view; {@link #notes()} says so. A scene with
 * lights but no camera is framed from +Z. Immutable once built (the BVH is built then, once) and safe to share
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
    private final boolean studioSky;          // the scene has no light and is lit by the studio sky
    private final boolean framed;             // the scene has no camera and is framed

    private Scene(World world, List<Material> materials, Camera camera, List<String> notes, boolean studioSky, boolean framed) {
        this.world = world;
        this.materials = materials;
        this.camera = camera;
        this.notes = notes;
        this.studioSky = studioSky;
        this.framed = framed;
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
     * The materials in the order they were first used, each once (once per medium boundary, {@link Builder#mediumBoundary}).
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
     * How long building the BVH took, when the scene was built (its share of the time to load a
     * scene; a render's time excludes it).
     *
     * @return seconds
     */
    public double bvhBuildSeconds() {
        return world.bvhBuildSeconds();
    }

    /**
     * The thin lens's focus distance that makes the surface seen at a point of the image sharp:
     * the distance, along {@code camera}'s viewing direction, of the first surface its pinhole ray
     * through that point meets, found as the renderer finds it (the cut-away parts of an alpha
     * cut-out are passed through). The viewer focuses so on Ctrl+click.
     *
     * @param camera the camera looking at this scene
     * @param fx     the point's x as a fraction of the image width, 0 at the left
     * @param fy     its y as a fraction of the height, 0 at the top
     * @param aspect the image's width / height
     * @return the distance, or NaN where the image shows no surface
     */
    public double focusDistance(Camera camera, double fx, double fy, double aspect) {
        return FocusPicker.focusDistance(this, Objects.requireNonNull(camera, "camera"), fx, fy, aspect);
    }

    /**
     * The camera: the scene's own, or one framing the scene (from a raised three-quarter view if
     * the scene has no light, else from +Z).
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
        if (!studioSky) {
            return notes;
        }
        List<String> all = new ArrayList<>(notes);
        all.add(framed ? "the scene has no light and no camera: lighting it with " + StudioSky.DESCRIPTION + " and framing it from "
                + Camera.FRAMING_DESCRIPTION : "the scene has no light: lighting it with " + StudioSky.DESCRIPTION);
        return List.copyOf(all);
    }

    /**
     * The same scene seen through another camera; geometry and BVH are shared, not copied.
     *
     * @param newCamera the camera
     * @return a scene sharing everything else with this one
     */
    public Scene withCamera(Camera newCamera) {
        Objects.requireNonNull(newCamera);
        return new Scene(world, materials, newCamera, notes, studioSky, framed && newCamera.equals(camera));
    }

    /**
     * The same scene under a latitude–longitude environment map (see
     * {@link Builder#environmentMap}); geometry and BVH are shared, not copied.
     *
     * @param map           the map, +Y up, its top row the +Y pole, its centre column seen along +Z
     * @param scale         factor on the map's radiance, finite and ≥ 0
     * @param rotateDegrees rotation of the map about +Y, in degrees
     * @return a scene sharing everything else with this one
     */
    public Scene withEnvironmentMap(Image map, double scale, double rotateDegrees) {
        Environment env = SceneLighting.mapOf(map, scale, rotateDegrees);
        return new Scene(world.withEnvironment(env), materials, camera, notes, false, framed);
    }

    /**
     * Collects shapes, materials, camera, lights and environment, then builds the BVH once. Not
     * thread-safe. (The lights, the environment and the media are set by the methods of package-private bases.)
     */
    public static final class Builder extends SceneMediaSetters {
        private final GeometryBuilder base = new GeometryBuilder();
        private GeometryBuilder geometry = base;      // the scene's own, or the open group's
        private final SceneGroups groups = new SceneGroups();
        private final List<Material> materials = new ArrayList<>();
        private final Map<Material, Integer> materialIndex = new IdentityHashMap<>();
        private final List<String> notes = new ArrayList<>();
        private Camera camera;

        private Builder() {}

        private int indexOf(Material m) {
            Objects.requireNonNull(m, "material");
            if (groups.open() != null && m.isEmissive()) {
                throw new IllegalArgumentException("emissive material '" + m.name() + "' in group '" + groups.open()
                        + "': instanced shapes cannot be lights (place the emitter in the scene itself)");
            }
            return media.bounding() ? media.slot(m, () -> add(m)) : materialIndex.computeIfAbsent(m, this::add);
        }

        private int add(Material m) {
            materials.add(m);
            return materials.size() - 1;
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
         * Starts a group: the shapes added until {@link #endGroup()} are shown only by the instances
         * that name it ({@link #addInstance}), which share its primitives and BVH. Groups do not
         * nest and hold no emissive materials (instanced lights are not supported).
         *
         * @param name the group's name, unique in the scene
         * @return this builder
         * @throws IllegalStateException    if a group is open
         * @throws IllegalArgumentException if the name is taken
         */
        public Builder beginGroup(String name) {
            geometry = groups.begin(name);
            return this;
        }

        /**
         * Ends the open group: shapes go into the scene itself again.
         *
         * @return this builder
         * @throws IllegalStateException if no group is open
         */
        public Builder endGroup() {
            groups.end();
            geometry = base;
            return this;
        }

        /**
         * Shows a group moved by a transform, unequal scales and mirrors included (its spheres become
         * ellipsoids, its normals follow the inverse transpose); its shapes keep their materials.
         *
         * @param group     the name of a group begun before
         * @param transform from the group's coordinates into the scene's
         * @return this builder
         * @throws IllegalStateException    if a group is open (groups do not nest)
         * @throws IllegalArgumentException if no such group was begun
         */
        public Builder addInstance(String group, Transform transform) {
            groups.instance(group, transform);
            return this;
        }

        /**
         * The camera; without one, a scene without lights (a bare model) is framed from a raised
         * three-quarter view (azimuth 40° from +Z towards +X, elevation 25°, looking at the centre
         * of the bounds), a scene with lights (often a room open to the front) from +Z, both with a
         * 40° field of view.
         *
         * @param camera the camera
         * @return this builder
         */
        public Builder camera(Camera camera) {
            this.camera = Objects.requireNonNull(camera);
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
         * Builds the scene: concatenates the primitives, builds the BVHs (each group's once) and collects the lights.
         *
         * @return the scene, immutable
         * @throws IllegalStateException if a group is still open
         */
        public Scene build() {
            if (groups.open() != null) {
                throw new IllegalStateException("group '" + groups.open() + "' is never ended");
            }
            Geometry g = base.build();
            Bsdf[] bsdfs = new Bsdf[materials.size()];
            Emission[] emission = new Emission[materials.size()];
            SurfaceMaps[] maps = new SurfaceMaps[materials.size()];
            for (int i = 0; i < bsdfs.length; i++) {
                Surface surface = materials.get(i).surface();
                bsdfs[i] = surface.bsdf();
                emission[i] = surface.emissionTable();
                maps[i] = surface.maps();
            }
            boolean studio = environment == null && punctual.isEmpty() && !anyEmits(g, emission);
            Environment env = environment != null ? environment : studio ? StudioSky.environment() : Environment.BLACK;
            World world = World.build(g, groups.geometries(), groups.transforms(), bsdfs, emission, maps, env, punctual)
                    .withMedia(media.build(bsdfs));
            // A bare model (no light) is an object: shown from above at three quarters. A scene with
            // its own lights is often a room made to be seen from its open front (the Cornell Box): +Z.
            Camera cam = camera != null ? camera : studio ? Camera.framing(world.bounds(), 40) : Camera.frontFraming(world.bounds(), 40);
            return new Scene(world, List.copyOf(materials), cam, List.copyOf(notes), studio, camera == null);
        }

        private static boolean anyEmits(Geometry g, Emission[] emission) {
            for (int prim = 0; prim < g.primitiveCount(); prim++) {
                if (!emission[g.material(prim)].isBlack()) {
                    return true;
                }
            }
            return false;
        }
    }
}
