package dev.strahl.scene;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.Sphere;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.light.Emission;
import dev.strahl.light.Environment;
import dev.strahl.light.PunctualLight;
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
        return SceneParts.textureBytes(materials);
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
        return studioSky ? SceneParts.withStudioNote(notes, framed) : notes;
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
        Environment env = SceneParts.mapOf(map, scale, rotateDegrees);
        return new Scene(world.withEnvironment(env), materials, camera, notes, false, framed);
    }

    /** Collects shapes, materials, camera and environment, then builds the BVH once. Not thread-safe. */
    public static final class Builder {
        private final GeometryBuilder geometry = new GeometryBuilder();
        private final List<Material> materials = new ArrayList<>();
        private final Map<Material, Integer> materialIndex = new IdentityHashMap<>();
        private final List<String> notes = new ArrayList<>();
        private final List<PunctualLight> punctual = new ArrayList<>();
        private final SceneMedia media = new SceneMedia();
        private Camera camera;
        private Environment environment;

        private Builder() {}

        private int indexOf(Material m) {
            Objects.requireNonNull(m, "material");
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
            SceneParts.addMesh(geometry, mesh, materialOfTriangle, palette.stream().mapToInt(this::indexOf).toArray(), notes);
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
         * Radiance arriving from every direction where rays leave the scene. Without an
         * environment, a scene with lights has a black one and a scene without lights strahl's
         * studio sky (a procedural blue sky with a soft sun, built in code).
         *
         * @param radiance the constant environment radiance
         * @return this builder
         */
        public Builder environment(Rgb radiance) {
            this.environment = Environment.constant(Objects.requireNonNull(radiance));
            return this;
        }

        /**
         * A latitude–longitude environment map, oriented as Mitsuba 3's {@code envmap}: +Y is up
         * and the image's top row is the +Y pole; the centre column is seen looking along +Z, the
         * column at a quarter of the width along +X, at three quarters along −X, the left and
         * right edges along −Z. Texel (x, y) sits at u = (x + ½)/W, v = y/(H − 1), bilinear in
         * between. The map is importance-sampled (luminance · sin θ) for next-event estimation.
         * Read one from a file with {@code SceneLoader.readImage}.
         *
         * @param map           linear radiance, at least 1×2 pixels; negative and NaN values count as black
         * @param scale         factor on the radiance, finite and ≥ 0
         * @param rotateDegrees rotation of the map about +Y (right-handed), in degrees
         * @return this builder
         * @throws IllegalArgumentException if the map is too small or the scale or rotation is not finite
         */
        public Builder environmentMap(Image map, double scale, double rotateDegrees) {
            this.environment = SceneParts.mapOf(map, scale, rotateDegrees);
            return this;
        }

        /**
         * Adds a point light (glTF {@code KHR_lights_punctual} "point"): the irradiance it gives a
         * surface at distance d, facing it, is I/d². A delta light: only light sampling finds it.
         * @param position  where it is
         * @param intensity radiant intensity I, W/sr per channel, ≥ 0
         * @return this builder
         * @throws IllegalArgumentException if the position is not finite or the intensity negative
         */
        public Builder pointLight(Vector3dc position, Rgb intensity) {
            punctual.add(PunctualLight.point(position, intensity));
            return this;
        }

        /**
         * Adds a spot light (glTF "spot"): a point light whose intensity I is scaled by glTF's
         * falloff clamp((cd − cos outer) / (cos inner − cos outer), 0, 1)², cd the cosine between
         * {@code direction} and the way from the light to the lit point.
         *
         * @param position          where it is
         * @param direction         its axis, the direction it shines in (any length but zero)
         * @param intensity         radiant intensity I on the axis, W/sr per channel, ≥ 0
         * @param innerConeRadians  full intensity within this angle of the axis, ≥ 0
         * @param outerConeRadians  no light beyond this angle, ≥ inner, &gt; 0 and ≤ π/2
         * @return this builder
         * @throws IllegalArgumentException for angles out of range, a zero direction or a negative intensity
         */
        public Builder spotLight(Vector3dc position, Vector3dc direction, Rgb intensity, double innerConeRadians, double outerConeRadians) {
            punctual.add(PunctualLight.spot(position, direction, intensity, innerConeRadians, outerConeRadians));
            return this;
        }

        /**
         * Adds a directional light (glTF "directional"): parallel light, as from a distant sun.
         * @param direction  the direction the light travels (any length but zero)
         * @param irradiance irradiance E on a surface facing the light, W/m² per channel, ≥ 0
         * @return this builder
         * @throws IllegalArgumentException for a zero direction or a negative irradiance
         */
        public Builder directionalLight(Vector3dc direction, Rgb irradiance) {
            punctual.add(PunctualLight.directional(direction, irradiance));
            return this;
        }

        /**
         * Defines a homogeneous medium (Mitsuba 3's {@code homogeneous} with an {@code hg} phase function).
         *
         * @param name   the medium's name, new
         * @param sigmaT extinction per scene unit in each channel, ≥ 0
         * @param albedo single-scattering albedo σs/σt in each channel, in [0, 1] (0: it only absorbs)
         * @param g      Henyey–Greenstein asymmetry in (−1, 1): positive scatters forwards
         * @return this builder
         * @throws IllegalArgumentException for a value out of range or a name defined before
         */
        public Builder homogeneousMedium(String name, Rgb sigmaT, Rgb albedo, double g) {
            media.homogeneous(name, sigmaT, albedo, g);
            return this;
        }

        /**
         * Defines a medium of extinction {@code scale} × the density grid of a Mitsuba {@code .vol}
         * file (version 3, float32, one channel) filling a box, as Mitsuba 3's {@code gridvolume}:
         * voxel (i, j, k) at ((i + ½)/X, (j + ½)/Y, (k + ½)/Z) of the box, trilinear, clamped at the border.
         *
         * @param name   the medium's name, new
         * @param file   the {@code .vol} file
         * @param min    the box's lower corner, or null (with {@code max}) for the box in the file's header
         * @param max    the box's upper corner
         * @param scale  extinction per unit of density and scene unit, ≥ 0
         * @param albedo single-scattering albedo in each channel, in [0, 1]
         * @param g      Henyey–Greenstein asymmetry in (−1, 1)
         * @return this builder
         * @throws SceneException if the file holds no valid grid (one line naming it)
         */
        public Builder gridMedium(String name, java.nio.file.Path file, Vector3dc min, Vector3dc max, double scale, Rgb albedo, double g)
                throws SceneException {
            media.grid(name, file, min, max, scale, albedo, g);
            return this;
        }

        /**
         * Makes the shapes added from now on boundaries between media: a ray that crosses into one
         * (against its geometric normal) travels on in {@code interior}, one that leaves it in
         * {@code exterior}. {@code (null, null)} ends it: later shapes leave a ray in its medium.
         *
         * @param interior a medium defined before, or null for vacuum
         * @param exterior a medium defined before, or null for vacuum
         * @return this builder
         */
        public Builder mediumBoundary(String interior, String exterior) {
            media.boundary(interior, exterior);
            return this;
        }

        /**
         * The medium the camera is in (default: vacuum).
         *
         * @param name a medium defined before, or null for vacuum
         * @return this builder
         */
        public Builder cameraMedium(String name) {
            media.camera(name);
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
            Emission[] emission = SceneParts.emission(materials);
            boolean studio = environment == null && punctual.isEmpty() && !SceneParts.anyEmits(g, emission);
            Environment env = environment != null ? environment : studio ? StudioSky.environment() : Environment.BLACK;
            World world = World.build(g, SceneParts.bsdfs(materials), emission, SceneParts.maps(materials), env, punctual)
                    .withMedia(media.build(SceneParts.bsdfs(materials)));
            // A bare model (no light) is shown from above at three quarters, a scene with lights (a room) from its open front, +Z.
            Camera cam = camera != null ? camera : studio ? Camera.framing(world.bounds(), 40) : Camera.frontFraming(world.bounds(), 40);
            return new Scene(world, List.copyOf(materials), cam, List.copyOf(notes), studio, camera == null);
        }
    }
}
