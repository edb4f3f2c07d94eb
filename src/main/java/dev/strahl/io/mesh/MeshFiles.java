package dev.strahl.io.mesh;

import dev.strahl.io.obj.MtlMaterial;
import dev.strahl.io.obj.ObjModel;
import dev.strahl.io.obj.ObjReader;
import dev.strahl.io.ply.PlyReader;
import dev.strahl.scene.Material;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Transform;
import dev.strahl.scene.TriangleMesh;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Mesh files as parts of a scene: an OBJ with its MTL materials, or a PLY. */
public final class MeshFiles {
    /** The material of a PLY mesh: Lambertian, albedo 0.8 (the MTL default Kd). */
    public static final Material DEFAULT_MATERIAL = Material.diffuse("default", MtlMaterial.DEFAULT_KD);

    private MeshFiles() {}

    /** Whether the file's extension names a mesh format read here. */
    public static boolean isMeshFile(Path file) {
        String name = lowerCaseName(file);
        return name.endsWith(".obj") || name.endsWith(".ply");
    }

    /** The file name in lower case, "" for a path without one. */
    public static String lowerCaseName(Path file) {
        return file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
    }

    /**
     * Adds the triangles of an OBJ file (with their MTL materials, or all of {@code material} if it
     * is not null) or a PLY file (of {@code material}, or {@link #DEFAULT_MATERIAL}) to a scene
     * under construction, moved by {@code transform}. The readers' warnings become notes that
     * start with {@code "warning: "}.
     */
    public static void add(Path file, Material material, Transform transform, Scene.Builder builder) throws SceneException {
        String name = lowerCaseName(file);
        if (name.endsWith(".ply")) {
            PlyReader.PlyModel model = PlyReader.read(file);
            model.warnings().forEach(w -> builder.note("warning: " + w));
            builder.addMesh(moved(file, model.mesh(), transform), material != null ? material : DEFAULT_MATERIAL);
        } else if (name.endsWith(".obj")) {
            ObjModel model = ObjReader.read(file);
            model.warnings().forEach(w -> builder.note("warning: " + w));
            TriangleMesh mesh = moved(file, model.mesh(), transform);
            if (material != null) {
                builder.addMesh(mesh, material);
                return;
            }
            List<Material> palette = new ArrayList<>(model.materials().size());
            for (MtlMaterial m : model.materials()) {
                palette.add(m.toMaterial(builder::note));
            }
            builder.addMesh(mesh, model.triangleMaterial(), palette);
        } else {
            throw new SceneException(file, "unknown mesh format (expected .obj or .ply)");
        }
    }

    private static TriangleMesh moved(Path file, TriangleMesh mesh, Transform transform) throws SceneException {
        try {
            return transform.apply(mesh);
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, e.getMessage());
        }
    }
}
