package dev.strahl.scene;

import dev.strahl.geometry.TriangleMesh;
import dev.strahl.material.Bsdf;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.material.Mirror;
import dev.strahl.material.Material;
import dev.strahl.math.Rgb;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Loads a scene from a file: a strahl scene file ({@code .json}), a Wavefront OBJ with its MTL
 * materials ({@code .obj}) or a PLY mesh ({@code .ply}, ASCII or binary, made of the grey diffuse
 * {@link #DEFAULT_MATERIAL}). An OBJ or PLY has no camera: the scene is framed from +Z.
 */
public final class SceneLoader {
    /** The material of a PLY mesh loaded directly: Lambertian, albedo 0.8 (the MTL default Kd). */
    public static final Material DEFAULT_MATERIAL = Material.diffuse("default", MtlMaterial.DEFAULT_KD);

    private SceneLoader() {}

    /**
     * Loads and builds the scene in {@code file}; the format follows the file's extension, in any case.
     *
     * @param file a {@code .json}, {@code .obj} or {@code .ply} file
     * @return the scene
     * @throws SceneException if the file is missing, unreadable or malformed: the message names
     *                        the file and, where known, the line
     */
    public static Scene load(Path file) throws SceneException {
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (Files.isDirectory(file)) {
            throw new SceneException(file, "is a directory, not a scene file");
        }
        if (!Files.exists(file)) {
            throw new SceneException(file, "file not found");
        }
        if (name.endsWith(".json")) {
            return JsonSceneReader.read(file);
        }
        if (name.endsWith(".obj") || name.endsWith(".ply")) {
            Scene.Builder builder = Scene.builder();
            addMeshFile(file, null, Transform.IDENTITY, builder);
            return builder.build();
        }
        throw new SceneException(file, "unknown scene format (expected .json, .obj or .ply)");
    }

    /**
     * Adds the triangles of an OBJ file (with their MTL materials, or all of {@code material} if it
     * is not null) or a PLY file (of {@code material}, or {@link #DEFAULT_MATERIAL}) to a scene
     * under construction, moved by {@code transform}. The readers' warnings become notes that
     * start with {@code "warning: "}.
     */
    static void addMeshFile(Path file, Material material, Transform transform, Scene.Builder builder) throws SceneException {
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
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
                palette.add(toMaterial(m, builder));
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

    /**
     * Maps MTL parameters to a material following the conventions table: illum 5 is a mirror of
     * reflectance Ks, illum 7 smooth glass of IOR Ni, illum ≤ 2 with Ks > 0 Kd·Lambert + Ks·Beckmann
     * (Ns as Phong exponent), otherwise Lambertian with albedo Kd. Ke > 0 makes any of them emit.
     */
    static Material toMaterial(MtlMaterial m, Scene.Builder builder) {
        Bsdf bsdf;
        if (m.illum() == 5) {
            bsdf = new Mirror(clampToOne(m.ks(), m, "Ks", builder));
        } else if (m.illum() == 7) {
            bsdf = new Dielectric(m.ni());
        } else {
            if (m.illum() > 2) {
                builder.note("material '" + m.name() + "': illum " + m.illum() + " is not supported; rendering it as illum 2");
            }
            bsdf = m.ks().isBlack()
                    ? new Lambert(clampToOne(m.kd(), m, "Kd", builder))
                    : Glossy.fromPhongExponent(m.kd(), m.ks(), m.ns());
        }
        return new Material(m.name(), bsdf, m.ke());
    }

    private static Rgb clampToOne(Rgb c, MtlMaterial m, String key, Scene.Builder builder) {
        if (c.max() <= 1) {
            return c;
        }
        builder.note("material '" + m.name() + "': " + key + " " + c + " reflects more than it receives; clamped to 1");
        return new Rgb(Math.min(c.r(), 1), Math.min(c.g(), 1), Math.min(c.b(), 1));
    }

    /** The one-line error for a file that cannot be read. */
    static SceneException cannotRead(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return new SceneException(file, "file not found");
        }
        if (e instanceof AccessDeniedException) {
            return new SceneException(file, "permission denied");
        }
        return new SceneException(file, "cannot read: " + e.getMessage(), e);
    }
}
