package dev.strahl.io.gltf;

import dev.strahl.io.text.HeapBudget;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Transform;
import dev.strahl.scene.TriangleMesh;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.joml.Matrix3d;
import org.joml.Matrix4d;
import org.joml.Vector3d;

/**
 * Reads a glTF 2.0 asset ({@code .gltf} with its {@code .bin} and image files or {@code data:}
 * URIs, or a {@code .glb}) into a scene under construction: the default scene's node hierarchy
 * with every mesh instance flattened into world space (the memory the copies take is noted), the
 * materials as {@code principled}, and what the asset says about its camera and lights, for the
 * caller to use or not. Errors name the file and the JSON path of the element at fault.
 */
public final class GltfReader {
    /**
     * What an asset brings besides its surfaces.
     *
     * @param camera      its first perspective camera, placed, or null
     * @param aspectRatio the camera's width / height, or 0 when it does not say
     * @param lights      its punctual lights, placed
     */
    public record Asset(Camera camera, double aspectRatio, List<GltfLights.Light> lights) {}

    private GltfReader() {}

    /** Whether the file's extension names a glTF asset. */
    public static boolean isGltfFile(Path file) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".gltf") || name.endsWith(".glb");
    }

    /**
     * Adds the asset's triangles, moved by {@code placement}, to {@code builder} with the
     * reader's notes; returns its camera and lights (also moved), which this method does not add.
     */
    public static Asset add(Path file, Transform placement, Scene.Builder builder) throws SceneException {
        GltfDocument doc = GltfDocument.read(file);
        GltfNodes nodes = GltfNodes.walk(doc, placement.matrix());
        GltfMaterials materials = new GltfMaterials(doc);
        GltfMeshes meshes = new GltfMeshes(doc, materials);
        java.util.Set<String> definedGroups = new java.util.HashSet<>();
        Map<Integer, List<GltfNodes.Placed>> uses = new HashMap<>();
        for (GltfNodes.Placed p : nodes.meshes) {
            uses.computeIfAbsent(p.element(), k -> new ArrayList<>()).add(p);
        }
        // A mesh placed more than once is instanced (one group, its triangles once), unless it emits
        // light or a placement shears it (an instance's transform is made of steps): then it is copied.
        Map<Integer, String> groups = new HashMap<>();
        long triangles = 0;
        for (var e : uses.entrySet()) {
            long count = 0;
            for (GltfMeshes.Primitive prim : meshes.mesh(e.getKey())) {
                count += prim.indices().length / 3;
            }
            boolean instanced = e.getValue().size() > 1 && count > 0 && !emits(meshes.mesh(e.getKey()), materials)
                    && e.getValue().stream().allMatch(p -> GltfInstances.steps(p.world()) != null);
            if (instanced) {
                groups.put(e.getKey(), file.getFileName() + " mesh " + e.getKey() + " #" + GROUPS.incrementAndGet());
            }
            triangles += instanced ? count : count * e.getValue().size();
        }
        String tooMany = HeapBudget.tooMany(triangles);
        if (tooMany != null) {
            throw new SceneException(file, tooMany);
        }
        long copyBytes = 0;
        int copies = 0, instances = 0;
        for (GltfNodes.Placed p : nodes.meshes) {
            List<GltfMeshes.Primitive> prims = meshes.mesh(p.element());
            if (prims.isEmpty()) {
                continue;
            }
            List<Material> palette = new ArrayList<>();
            Map<Integer, Integer> slot = new HashMap<>();
            for (GltfMeshes.Primitive prim : prims) {
                if (!slot.containsKey(prim.material())) {
                    slot.put(prim.material(), palette.size());
                    palette.add(materials.material(prim.material()));
                }
            }
            String group = groups.get(p.element());
            if (group != null) {
                if (!defined(group, definedGroups)) {
                    builder.beginGroup(group);
                    Instance shape = flatten(prims, new Matrix4d(), slot);
                    builder.addMesh(shape.mesh, shape.materialOfTriangle, palette).endGroup();
                }
                builder.addInstance(group, GltfInstances.steps(p.world()));
                instances++;
                continue;
            }
            Instance instance;
            try {
                instance = flatten(prims, p.world(), slot);
            } catch (IllegalArgumentException e) {
                throw new SceneException(file, "nodes[" + p.node() + "]: mesh " + p.element() + " in world space: " + e.getMessage());
            }
            if (instance.mesh.triangleCount() == 0) {
                continue;
            }
            builder.addMesh(instance.mesh, instance.materialOfTriangle, palette);
            if (uses.get(p.element()).size() > 1) {
                copies++;
                copyBytes += instance.bytes;
            }
        }
        if (instances > 0) {
            doc.notes.add(groups.size() + " mesh" + (groups.size() == 1 ? " is" : "es are") + " used by several nodes: " + instances + " instances");
        }
        if (copies > 0) {
            doc.notes.add("meshes that emit light or are sheared are copied per node: " + copies
                    + " copies (" + String.format("%.1f", copyBytes / 1048576.0) + " MiB)");
        }
        GltfCameras.Found camera = GltfCameras.first(doc, nodes);
        List<GltfLights.Light> lights = GltfLights.placed(doc, nodes);
        doc.notes.forEach(builder::note);
        return new Asset(camera == null ? null : camera.camera(), camera == null ? 0 : camera.aspectRatio(), lights);
    }

    /**
     * Adds the asset's punctual lights (KHR_lights_punctual) to {@code builder}: point and spot
     * lights of radiant intensity colour × intensity, directional lights of that irradiance.
     */
    public static void addLights(Asset asset, Scene.Builder builder) {
        for (GltfLights.Light l : asset.lights()) {
            switch (l.kind()) {
                case POINT:
                    builder.pointLight(l.position(), l.power());
                    break;
                case SPOT:
                    builder.spotLight(l.position(), l.direction(), l.power(), l.inner(), l.outer());
                    break;
                default:
                    builder.directionalLight(l.direction(), l.power());
                    break;
            }
        }
    }

    /** Names for the groups of instanced meshes, unique in the process (an asset may be added twice). */
    private static final java.util.concurrent.atomic.AtomicLong GROUPS = new java.util.concurrent.atomic.AtomicLong();

    private static boolean defined(String group, java.util.Set<String> defined) {
        return !defined.add(group);
    }

    private static boolean emits(List<GltfMeshes.Primitive> prims, GltfMaterials materials) throws SceneException {
        for (GltfMeshes.Primitive prim : prims) {
            if (materials.material(prim.material()).isEmissive()) {
                return true;
            }
        }
        return false;
    }

    private record Instance(TriangleMesh mesh, int[] materialOfTriangle, long bytes) {}

    /** The primitives of one mesh, concatenated and moved into world space (normals by the inverse transpose). */
    private static Instance flatten(List<GltfMeshes.Primitive> prims, Matrix4d world, Map<Integer, Integer> slot) {
        int vertices = 0;
        int indexCount = 0;
        boolean anyNormals = false;
        boolean anyUvs = false;
        for (GltfMeshes.Primitive p : prims) {
            vertices += p.positions().length / 3;
            indexCount += p.indices().length;
            anyNormals |= p.normals() != null;
            anyUvs |= p.uvs() != null;
        }
        float[] positions = new float[3 * vertices];
        float[] normals = anyNormals ? new float[3 * vertices] : null;
        float[] uvs = anyUvs ? new float[2 * vertices] : null;
        int[] indices = new int[indexCount];
        int[] materialOf = new int[indexCount / 3];
        Matrix3d normalMatrix = new Matrix3d(world).invert().transpose();
        boolean flip = world.determinant3x3() < 0;      // a mirroring turns the winding (§3.7.4)
        Vector3d v = new Vector3d();
        int base = 0;
        int at = 0;
        for (GltfMeshes.Primitive p : prims) {
            int n = p.positions().length / 3;
            for (int i = 0; i < n; i++) {
                world.transformPosition(v.set(p.positions()[3 * i], p.positions()[3 * i + 1], p.positions()[3 * i + 2]));
                put(positions, base + i, v);
                if (normals != null) {
                    if (p.normals() == null) {
                        put(normals, base + i, v.set(Double.NaN, Double.NaN, Double.NaN));
                    } else {
                        normalMatrix.transform(v.set(p.normals()[3 * i], p.normals()[3 * i + 1], p.normals()[3 * i + 2]));
                        double length = v.length();
                        put(normals, base + i, length > 0 && Double.isFinite(length) ? v.div(length) : v.set(Double.NaN, Double.NaN, Double.NaN));
                    }
                }
                if (uvs != null) {
                    uvs[2 * (base + i)] = p.uvs() == null ? Float.NaN : p.uvs()[2 * i];
                    uvs[2 * (base + i) + 1] = p.uvs() == null ? Float.NaN : p.uvs()[2 * i + 1];
                }
            }
            int[] idx = p.indices();
            int material = slot.get(p.material());
            for (int t = 0; t < idx.length; t += 3) {
                indices[at + t] = base + idx[t];
                indices[at + t + 1] = base + idx[flip ? t + 2 : t + 1];
                indices[at + t + 2] = base + idx[flip ? t + 1 : t + 2];
                materialOf[(at + t) / 3] = material;
            }
            at += idx.length;
            base += n;
        }
        long bytes = 4L * (positions.length + (normals == null ? 0 : normals.length) + (uvs == null ? 0 : uvs.length) + indices.length);
        return new Instance(new TriangleMesh(positions, indices, normals, uvs), materialOf, bytes);
    }

    private static void put(float[] a, int vertex, Vector3d v) {
        a[3 * vertex] = (float) v.x;
        a[3 * vertex + 1] = (float) v.y;
        a[3 * vertex + 2] = (float) v.z;
    }
}
