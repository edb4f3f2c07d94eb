package dev.strahl.io.json;

import dev.strahl.image.Rgb;
import dev.strahl.io.gltf.GltfReader;
import dev.strahl.io.mesh.MeshFiles;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Texture;
import dev.strahl.scene.Transform;
import dev.strahl.scene.TriangleMesh;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A scene file as data: what {@link JsonSceneReader} parses (and the tests' SceneFileWriter writes),
 * key for key, before anything is loaded or built. Two descriptions are equal when they say the
 * same, so that a file written and read back can be compared with the original.
 *
 * @param camera      the camera, or null to frame the scene
 * @param settings    the film and integrator keys
 * @param materials   the named materials, in file order
 * @param groups      the groups of shapes (not rendered by themselves) that instances show, by name, in file order
 * @param shapes      the shapes, in file order
 * @param environment the environment, or null for the default
 * @param lights      the punctual lights ({@link SceneLights}), in file order
 * @param media       the participating media, the camera's and each shape's ({@link SceneFileMedia})
 */
record SceneDescription(Camera camera, SceneSettings settings, Map<String, MaterialSpec> materials, Map<String, List<ShapeSpec>> groups,
                        List<ShapeSpec> shapes, EnvironmentSpec environment, List<SceneLights.Light> lights, SceneFileMedia.Media media) {

    SceneDescription {
        Objects.requireNonNull(settings, "settings");
        materials = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(materials));
        groups = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(groups));
        shapes = List.copyOf(shapes);
        lights = List.copyOf(lights);
        media = Objects.requireNonNull(media, "media");
    }

    SceneDescription(Camera camera, SceneSettings settings, Map<String, MaterialSpec> materials, List<ShapeSpec> shapes,
                     EnvironmentSpec environment) {
        this(camera, settings, materials, Map.of(), shapes, environment, List.of(), SceneFileMedia.Media.NONE);
    }

    /**
     * The environment as the file gives it: a constant radiance, or a map file (relative to the
     * scene file's folder unless absolute) with its scale and rotation about +Y in degrees.
     */
    record EnvironmentSpec(Rgb radiance, String file, double scale, double rotate) {
        EnvironmentSpec {
            if ((radiance == null) == (file == null)) {
                throw new IllegalArgumentException("an environment is a radiance or a map file");
            }
        }
    }

    /**
     * An image standing in for a colour or a number: its file as written (relative to the scene
     * file's folder unless absolute), the scale of its texture coordinates, and whether a colour
     * image stores linear values (no sRGB decoding).
     */
    record TextureRef(String file, double scaleU, double scaleV, boolean linear) {}

    /** A colour, or a texture standing in for it (then {@code value} is what a missing file leaves). */
    record ColorParam(Rgb value, TextureRef texture) {
        static ColorParam of(Rgb value) {
            return new ColorParam(value, null);
        }

        Texture resolve(TextureLoader loader, String key) throws SceneException {
            Texture t = texture == null ? null : loader.load(texture, key);
            return t != null ? t : Texture.constant(value);
        }
    }

    /** A number, or a texture standing in for it (then {@code value} is what a missing file leaves). */
    record NumberParam(double value, TextureRef texture) {
        static NumberParam of(double value) {
            return new NumberParam(value, null);
        }

        Texture resolve(TextureLoader loader, String key) throws SceneException {
            Texture t = texture == null ? null : loader.load(texture, key);
            return t != null ? t : Texture.constant(value);
        }
    }

    /** A material as the file gives it: its type and that type's keys. */
    sealed interface MaterialSpec permits Diffuse, Mirror, Dielectric, Glossy, Conductor, Principled, Null {
        Material toMaterial(String name, TextureLoader textures) throws SceneException;
    }

    record Diffuse(ColorParam albedo, Rgb emission) implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) throws SceneException {
            if (albedo.texture() == null) {
                return Material.emissive(name, albedo.value(), emission);
            }
            return Material.diffuse(name, albedo.resolve(textures, "materials." + name + ".albedo")).withEmission(emission);
        }
    }

    /** An invisible surface: a medium's boundary. */
    record Null() implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) {
            return Material.nullSurface(name);
        }
    }

    record Mirror(Rgb reflectance) implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) {
            return Material.mirror(name, reflectance);
        }
    }

    record Dielectric(double ior, NumberParam alpha) implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) throws SceneException {
            if (alpha.texture() == null && alpha.value() == 0) {
                return Material.dielectric(name, ior);
            }
            return Material.dielectric(name, ior, alpha.resolve(textures, "materials." + name + ".alpha"));
        }
    }

    record Glossy(Rgb diffuse, Rgb specular, double exponent, Rgb emission) implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) {
            return Material.glossy(name, diffuse, specular, exponent).withEmission(emission);
        }
    }

    /** A conductor: a preset's name, or eta and k. */
    record Conductor(String preset, Rgb eta, Rgb k, NumberParam alpha) implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) throws SceneException {
            Texture a = alpha.resolve(textures, "materials." + name + ".alpha");
            return preset != null ? Material.conductor(name, preset, a) : Material.conductor(name, eta, k, a);
        }
    }

    /** The glTF metallic–roughness material. */
    record Principled(ColorParam baseColor, NumberParam metallic, NumberParam roughness, NumberParam specular, ColorParam specularColor,
                      NumberParam transmission, double ior, Rgb emission, double emissionStrength) implements MaterialSpec {
        @Override
        public Material toMaterial(String name, TextureLoader textures) throws SceneException {
            String key = "materials." + name + ".";
            return Material.principled(name)
                    .baseColor(baseColor.resolve(textures, key + "baseColor"))
                    .metallic(metallic.resolve(textures, key + "metallic"))
                    .roughness(roughness.resolve(textures, key + "roughness"))
                    .specular(specular.resolve(textures, key + "specular"))
                    .specularColor(specularColor.resolve(textures, key + "specularColor"))
                    .transmission(transmission.resolve(textures, key + "transmission"))
                    .ior(ior)
                    .emission(emission, emissionStrength)
                    .build();
        }
    }

    /** A shape as the file gives it; {@code material} names an entry of {@code materials}. */
    sealed interface ShapeSpec permits SphereShape, MeshShape, TrianglesShape, InstanceShape {
        Transform transform();
    }

    /** A group moved by a transform (only in {@code shapes}: groups do not nest). */
    record InstanceShape(String group, Transform transform) implements ShapeSpec {}

    /** An analytic sphere. */
    record SphereShape(Vector3dc center, double radius, String material, Transform transform) implements ShapeSpec {
        SphereShape {
            center = new Vector3d(center);
        }
    }

    /**
     * An OBJ, PLY or glTF file ({@code "type": "gltf"}, never with a material), as written (relative to the scene file's folder unless absolute); with
     * a material name, every triangle is of that material, without one an OBJ uses its MTL
     * materials and a PLY the grey default.
     */
    record MeshShape(String file, String material, Transform transform) implements ShapeSpec {}

    /** Triangles given in the file: flat x, y, z arrays and three vertex indices per triangle. */
    record TrianglesShape(float[] positions, int[] indices, float[] normals, float[] uvs, String material, Transform transform)
            implements ShapeSpec {
        TrianglesShape {
            positions = positions.clone();
            indices = indices.clone();
            normals = normals == null ? null : normals.clone();
            uvs = uvs == null ? null : uvs.clone();
        }

        TriangleMesh mesh() {
            return new TriangleMesh(positions, indices, normals, uvs);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof TrianglesShape t && Arrays.equals(positions, t.positions) && Arrays.equals(indices, t.indices)
                    && Arrays.equals(normals, t.normals) && Arrays.equals(uvs, t.uvs) && material.equals(t.material)
                    && transform.equals(t.transform);
        }

        @Override
        public int hashCode() {
            return Objects.hash(Arrays.hashCode(positions), Arrays.hashCode(indices), Arrays.hashCode(normals), Arrays.hashCode(uvs), material,
                    transform);
        }

        @Override
        public String toString() {
            return "TrianglesShape[" + indices.length / 3 + " triangles, material " + material + ", " + transform + "]";
        }
    }

    /**
     * Loads the mesh files (relative to {@code folder}) and builds the scene. The reader has
     * checked every reference and value, so only the mesh files themselves can still fail.
     */
    Scene build(Path file, Path folder) throws SceneException {
        Map<String, Material> byName = new LinkedHashMap<>();
        List<String> notes = new ArrayList<>();
        TextureLoader textures = new TextureLoader(file, folder, notes);
        for (var e : materials.entrySet()) {
            byName.put(e.getKey(), e.getValue().toMaterial(e.getKey(), textures));
        }
        Scene.Builder builder = Scene.builder();
        notes.forEach(builder::note);
        SceneFileMedia.define(media, builder, file, folder);
        for (var g : groups.entrySet()) {
            builder.beginGroup(g.getKey());
            for (ShapeSpec shape : g.getValue()) {
                try {
                    add(shape, builder, byName, folder);
                } catch (IllegalArgumentException e) {
                    throw new SceneException(file, "'groups." + g.getKey() + "': " + e.getMessage());
                }
            }
            builder.endGroup();
        }
        boolean gltfCamera = false;
        for (int i = 0; i < shapes.size(); i++) {
            ShapeSpec shape = shapes.get(i);
            SceneFileMedia.boundary(media, i, builder);
            if (shape instanceof MeshShape m && GltfReader.isGltfFile(Path.of(m.file()))) {
                // a glTF asset's camera and lights are used only where the scene has none of its own
                GltfReader.Asset asset = GltfReader.add(folder.resolve(m.file()), m.transform(), builder);
                if (camera == null && asset.camera() != null && !gltfCamera) {
                    builder.camera(asset.camera());
                    gltfCamera = true;
                }
                if (environment == null && lights.isEmpty() && byName.values().stream().noneMatch(Material::isEmissive)) {
                    GltfReader.addLights(asset, builder);
                }
            } else {
                add(shape, builder, byName, folder);
            }
        }
        SceneLights.addTo(lights, builder);
        if (camera != null) {
            builder.camera(camera);
        }
        if (environment != null && environment.radiance() != null) {
            builder.environment(environment.radiance());
        } else if (environment != null) {
            Path map = folder.resolve(environment.file());
            try {
                builder.environmentMap(EnvironmentMaps.read(map), environment.scale(), environment.rotate());
            } catch (IllegalArgumentException e) {
                throw new SceneException(map, e.getMessage());
            }
        }
        return SceneFile.build(file, builder);
    }

    /** Adds a shape that is not a glTF file: into the open group, or into the scene itself. */
    private static void add(ShapeSpec shape, Scene.Builder builder, Map<String, Material> byName, Path folder) throws SceneException {
        if (shape instanceof SphereShape s) {
            builder.addSphere(s.center(), s.radius(), byName.get(s.material()), s.transform());
        } else if (shape instanceof InstanceShape i) {
            builder.addInstance(i.group(), i.transform());
        } else if (shape instanceof MeshShape m) {
            Material material = m.material() == null ? null : byName.get(m.material());
            MeshFiles.add(folder.resolve(m.file()), material, m.transform(), builder);
        } else {
            TrianglesShape t = (TrianglesShape) shape;
            builder.addMesh(t.mesh(), byName.get(t.material()), t.transform());
        }
    }
}
