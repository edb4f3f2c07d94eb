package dev.strahl.world;

import dev.strahl.accel.Aggregate;
import dev.strahl.accel.Bvh;
import dev.strahl.accel.TwoLevelBvh;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.InstanceTransforms;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.light.Emission;
import dev.strahl.light.Environment;
import dev.strahl.light.LightSampler;
import dev.strahl.light.PunctualLight;
import dev.strahl.material.Bsdf;
import java.util.List;
import java.util.Objects;
import java.util.function.Function;

/**
 * The scene as the renderer sees it: every primitive in flat arrays with its BVH, the area lights
 * over the emissive primitives, the BSDF and the emitted radiance of every material index (the one
 * emission table, shared by shading and light sampling), and the environment (constant or a map,
 * sampled by the light sampler along with the area lights). Built once
 * per {@code dev.strahl.scene.Scene} and shared read-only by every render job and thread.
 *
 * <p>The API's {@code Scene} holds its world privately; strahl's own packages reach it through
 * {@link #of(Object)}, which the {@code Scene} class installs when it is loaded (the pattern of the
 * JDK's {@code SharedSecrets}). So no public method of the API hands out an internal type, and the
 * module system keeps this package out of reach of library users.
 */
public final class World {
    private static volatile Function<Object, World> sceneAccess;

    private final Geometry geometry;
    private final Aggregate bvh;
    private final LightSampler lights;
    private final Bsdf[] bsdfs;
    private final Emission[] emission;
    private final SurfaceMaps[] maps;
    private final boolean cutouts;
    private final Environment environment;
    private final List<PunctualLight> punctualLights;
    private final double bvhBuildSeconds;
    private final Media media;

    private World(Geometry geometry, Aggregate bvh, Bsdf[] bsdfs, Emission[] emission, SurfaceMaps[] maps, Environment environment,
                  List<PunctualLight> punctual, double bvhBuildSeconds, Media media) {
        this(geometry, bvh, new LightSampler(geometry, emission, environment, punctual), bsdfs, emission, maps, environment, punctual,
                bvhBuildSeconds, media);
    }

    private World(Geometry geometry, Aggregate bvh, LightSampler lights, Bsdf[] bsdfs, Emission[] emission, SurfaceMaps[] maps,
                  Environment environment, List<PunctualLight> punctual, double bvhBuildSeconds, Media media) {
        this.geometry = geometry;
        this.bvh = bvh;
        this.bsdfs = bsdfs;
        this.emission = emission;
        this.maps = maps;
        boolean any = false;
        for (SurfaceMaps m : maps) {
            any |= m != null && m.alpha() != null;
        }
        this.cutouts = any;
        this.environment = environment;
        this.punctualLights = punctual;
        this.bvhBuildSeconds = bvhBuildSeconds;
        this.lights = lights;
        this.media = media;
    }

    /**
     * Teaching option ({@code --accel none}): this world with every ray tested against every
     * primitive instead of the BVH ({@link Aggregate#bruteForce()}); everything else shared.
     */
    public World bruteForce() {
        return new World(geometry, bvh.bruteForce(), lights, bsdfs, emission, maps, environment, punctualLights, bvhBuildSeconds, media);
    }

    /**
     * Teaching option ({@code --light-selection power}): this world with its lights chosen by
     * power alone instead of by the light tree ({@link LightSampler#byPower()}); everything else shared.
     */
    public World lightsByPower() {
        return new World(geometry, bvh, lights.byPower(), bsdfs, emission, maps, environment, punctualLights, bvhBuildSeconds, media);
    }

    /**
     * Builds the BVH over {@code geometry} and the light sampler over its emissive primitives.
     *
     * @param geometry    every primitive, material indices into the tables
     * @param bsdfs       the BSDF of each material index
     * @param emission    the emission of each material index ({@link Emission#BLACK}: not a light)
     * @param maps        the normal map and alpha cut-out of each material index (null: none)
     * @param environment the light of rays that leave the scene
     * @param punctual    point, spot and directional lights
     */
    public static World build(Geometry geometry, Bsdf[] bsdfs, Emission[] emission, SurfaceMaps[] maps, Environment environment,
                              List<PunctualLight> punctual) {
        if (bsdfs.length != emission.length || bsdfs.length != maps.length) {
            throw new IllegalArgumentException(bsdfs.length + " BSDFs for " + emission.length + " emissions and " + maps.length + " maps");
        }
        return build(geometry, List.of(), InstanceTransforms.NONE, bsdfs, emission, maps, environment, punctual);
    }

    /**
     * {@link #build(Geometry, Bsdf[], Emission[], SurfaceMaps[], Environment, List)} with instances:
     * {@code groups} are geometries not rendered by themselves, each shown by the instances that
     * name it, through a two-level BVH ({@link TwoLevelBvh}); without instances the scene's
     * primitives get a plain {@link Bvh}. Groups hold no emitters (the light sampler knows the
     * scene's own primitives only): {@code Scene.Builder} refuses them.
     */
    public static World build(Geometry geometry, List<Geometry> groups, InstanceTransforms instances, Bsdf[] bsdfs, Emission[] emission,
                              SurfaceMaps[] maps, Environment environment, List<PunctualLight> punctual) {
        if (bsdfs.length != emission.length || bsdfs.length != maps.length) {
            throw new IllegalArgumentException(bsdfs.length + " BSDFs for " + emission.length + " emissions and " + maps.length + " maps");
        }
        long start = System.nanoTime();
        Aggregate bvh = instances.count() == 0 ? Bvh.build(geometry) : TwoLevelBvh.build(geometry, groups, instances);
        double seconds = (System.nanoTime() - start) * 1e-9;
        // The BVH hands back the same primitives reordered into its leaves: hits refer to those.
        World world = new World(bvh.geometry(), bvh, bsdfs.clone(), emission.clone(), maps.clone(), Objects.requireNonNull(environment),
                List.copyOf(punctual), seconds, Media.NONE);
        if (instances.count() > 0) {
            requireFloatExtent(world.bounds());
        }
        return world;
    }

    /** Meshes check their vertices as they are added; an instance's transform meets its group only here. */
    private static void requireFloatExtent(Aabb b) {
        double largest = Math.max(Math.max(Math.max(-b.minX, b.maxX), Math.max(-b.minY, b.maxY)), Math.max(-b.minZ, b.maxZ));
        if (!(largest <= Float.MAX_VALUE)) {
            throw new IllegalArgumentException("an instance's transform takes its group beyond float coordinates: bounds " + b);
        }
    }

    /** The world behind an API {@code Scene}. */
    public static World of(Object scene) {
        Objects.requireNonNull(scene, "scene");
        return sceneAccess.apply(scene);
    }

    /** Called once, by the {@code Scene} class as it is loaded. */
    public static void installSceneAccess(Function<Object, World> access) {
        if (sceneAccess != null) {
            throw new IllegalStateException("scene access installed twice");
        }
        sceneAccess = access;
    }

    /** The primitives in the order of the BVH's leaves; primitive ids of hits refer to it. */
    public Geometry geometry() {
        return geometry;
    }

    public Aggregate bvh() {
        return bvh;
    }

    public LightSampler lights() {
        return lights;
    }

    public Environment environment() {
        return environment;
    }

    /** The same world under another environment: geometry, BVH and material tables are shared, the light sampler is new. */
    public World withEnvironment(Environment newEnvironment) {
        return new World(geometry, bvh, bsdfs, emission, maps, Objects.requireNonNull(newEnvironment), punctualLights, bvhBuildSeconds, media);
    }

    /** The same world with participating media (and invisible surfaces) where {@code newMedia} says; everything else is shared. */
    public World withMedia(Media newMedia) {
        return new World(geometry, bvh, lights, bsdfs, emission, maps, environment, punctualLights, bvhBuildSeconds, Objects.requireNonNull(newMedia));
    }

    /** The participating media and invisible surfaces ({@link Media#NONE} in a world of surfaces only). */
    public Media media() {
        return media;
    }

    /** The point, spot and directional lights (sampled by {@link #lights()} too). */
    public List<PunctualLight> punctualLights() {
        return punctualLights;
    }

    public int materialCount() {
        return bsdfs.length;
    }

    public Bsdf bsdf(int material) {
        return bsdfs[material];
    }

    /** The emission of a material: {@link Emission#BLACK} for a non-emitter. */
    public Emission emission(int material) {
        return emission[material];
    }

    /** The normal map and alpha cut-out of a material, null if it has neither. */
    public SurfaceMaps maps(int material) {
        return maps[material];
    }

    /** Whether any material has an alpha cut-out (else tracing never looks for one). */
    public boolean hasCutouts() {
        return cutouts;
    }

    /** The bounds of every primitive, the instances' included. */
    public Aabb bounds() {
        Aabb box = geometry.bounds();
        if (bvh instanceof TwoLevelBvh two) {
            Aabb[] groupBoxes = new Aabb[two.groupCount()];
            for (int g = 0; g < groupBoxes.length; g++) {
                groupBoxes[g] = two.groupGeometry(g).bounds();
            }
            Aabb moved = new Aabb();
            for (int i = 0; i < two.instances().count(); i++) {
                box.include(two.instances().bounds(i, groupBoxes[two.instances().group(i)], moved));
            }
        }
        return box;
    }

    /**
     * Fills {@code sp} with the surface data of a hit of {@link #bvh()}: as
     * {@link Geometry#surface} for the scene's own primitives; for a hit in an instance, the
     * group's surface at the hit, moved into world coordinates (points and tangents by the
     * instance's matrix, normals by its inverse transpose; a mirror flips the tangent frame's
     * handedness, as it reverses a mirrored mesh's winding). Allocates nothing.
     */
    public void surface(Ray ray, Hit hit, SurfacePoint sp) {
        if (hit.instance < 0) {
            geometry.surface(ray, hit, sp);
            return;
        }
        TwoLevelBvh two = (TwoLevelBvh) bvh;
        InstanceTransforms inst = two.instances();
        int i = hit.instance;
        Geometry group = two.groupGeometry(inst.group(i));
        if (!group.isTriangle(hit.prim)) {
            inst.pointToObject(i, ray.at(hit.t, sp.p));
        }
        group.surfaceAt(hit, sp);
        inst.pointToWorld(i, sp.p);
        inst.normalToWorld(i, sp.ng);
        inst.normalToWorld(i, sp.n);
        inst.vectorToWorld(i, sp.dpdu);
        if (inst.mirrors(i)) {
            sp.tangentSign = -sp.tangentSign;
        }
    }

    /** The instances' placements ({@link InstanceTransforms#NONE} without instances). */
    public InstanceTransforms instances() {
        return bvh instanceof TwoLevelBvh two ? two.instances() : InstanceTransforms.NONE;
    }

    /** Triangles stored: the scene's own and each group's once. */
    public long uniqueTriangles() {
        long n = geometry.triangleCount();
        if (bvh instanceof TwoLevelBvh two) {
            for (int g = 0; g < two.groupCount(); g++) {
                n += two.groupGeometry(g).triangleCount();
            }
        }
        return n;
    }

    /** Triangles as rendered: the scene's own and each instance's group's. */
    public long instancedTriangles() {
        long n = geometry.triangleCount();
        if (bvh instanceof TwoLevelBvh two) {
            for (int i = 0; i < two.instances().count(); i++) {
                n += two.groupGeometry(two.instances().group(i)).triangleCount();
            }
        }
        return n;
    }

    /** Feeds the primitives, the groups and the instances' placements into {@code md} (a checkpoint's tie to its scene). */
    public void digest(java.security.MessageDigest md) {
        geometry.digest(md);
        if (bvh instanceof TwoLevelBvh two) {
            for (int g = 0; g < two.groupCount(); g++) {
                two.groupGeometry(g).digest(md);
            }
            two.instances().digest(md);
        }
    }

    /** How long building the BVH took. */
    public double bvhBuildSeconds() {
        return bvhBuildSeconds;
    }

    /** Bytes held by the primitive and node arrays (each group's once), and the instances' matrices. */
    public long byteSize() {
        long groups = 0;
        if (bvh instanceof TwoLevelBvh two) {
            for (int g = 0; g < two.groupCount(); g++) {
                groups += two.groupGeometry(g).byteSize();
            }
        }
        return geometry.byteSize() + groups + bvh.byteSize();
    }
}
