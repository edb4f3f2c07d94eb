package dev.strahl.scene;

import dev.strahl.image.Rgb;
import dev.strahl.material.Bsdf;
import dev.strahl.medium.GridMedium;
import dev.strahl.medium.HomogeneousMedium;
import dev.strahl.medium.Medium;
import dev.strahl.medium.VolFile;
import dev.strahl.world.Media;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntSupplier;
import org.joml.Vector3dc;

/**
 * What {@link Scene.Builder} knows of participating media: the media by name, the medium boundary
 * that shapes added now get, and the camera's medium. A material used by shapes of different
 * boundaries gets a material index per boundary (the world keeps a medium interface per material
 * index, so nothing is stored per primitive and nothing looked up per ray but two ints).
 */
final class SceneMedia {
    /** A material under a boundary; the material by identity, as the builder's index of materials. */
    private record Slot(Material material, String interior, String exterior) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Slot s && s.material == material && java.util.Objects.equals(s.interior, interior)
                    && java.util.Objects.equals(s.exterior, exterior);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(material) * 31 + java.util.Objects.hash(interior, exterior);
        }
    }

    private final Map<String, Medium> media = new LinkedHashMap<>();
    private final Map<Slot, Integer> slots = new HashMap<>();
    private final Map<Integer, Slot> boundaryOf = new HashMap<>();
    private String interior, exterior, camera;

    void homogeneous(String name, Rgb sigmaT, Rgb albedo, double g) {
        define(name, new HomogeneousMedium(sigmaT, albedo, g));
    }

    void grid(String name, Path file, Vector3dc min, Vector3dc max, double scale, Rgb albedo, double g) throws SceneException {
        VolFile vol;
        try {
            vol = VolFile.read(file);
        } catch (IOException e) {
            String message = e.getMessage();
            throw new SceneException(file, message != null && message.startsWith(file.toString()) ? message.substring(file.toString().length() + 2)
                    : "cannot read the volume file: " + message, e);
        }
        try {
            define(name, new GridMedium(vol.grid(), min != null ? min : vol.min(), max != null ? max : vol.max(), scale, albedo, g));
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, (min == null ? "the box in the file's header: " : "") + e.getMessage());
        }
    }

    private void define(String name, Medium medium) {
        if (media.containsKey(java.util.Objects.requireNonNull(name, "name"))) {
            throw new IllegalArgumentException("medium '" + name + "' is defined twice");
        }
        media.put(name, medium);
    }

    void boundary(String inside, String outside) {
        this.interior = known(inside);
        this.exterior = known(outside);
    }

    void camera(String name) {
        this.camera = known(name);
    }

    private String known(String name) {
        if (name != null && !media.containsKey(name)) {
            throw new IllegalArgumentException("unknown medium '" + name + "' (define it first; known: " + media.keySet() + ")");
        }
        return name;
    }

    /** Whether shapes added now bound media (else they take the material's plain index). */
    boolean bounding() {
        return interior != null || exterior != null;
    }

    /** The material index of {@code m} under the current boundary, made by {@code add} the first time. */
    int slot(Material m, IntSupplier add) {
        return slots.computeIfAbsent(new Slot(m, interior, exterior), s -> {
            int index = add.getAsInt();
            boundaryOf.put(index, s);
            return index;
        });
    }

    /** The world's table for the material indices so far; {@link Media#NONE} without media and invisible surfaces. */
    Media build(Bsdf[] bsdfs) {
        List<String> names = new ArrayList<>(media.keySet());
        int[] in = new int[bsdfs.length], out = new int[bsdfs.length];
        boolean[] bounds = new boolean[bsdfs.length];
        for (int m = 0; m < bsdfs.length; m++) {
            Slot s = boundaryOf.get(m);
            bounds[m] = s != null;
            in[m] = s == null || s.interior() == null ? -1 : names.indexOf(s.interior());
            out[m] = s == null || s.exterior() == null ? -1 : names.indexOf(s.exterior());
        }
        Media table = new Media(List.copyOf(media.values()), names, in, out, bounds, camera == null ? -1 : names.indexOf(camera), bsdfs);
        return table.any() ? table : Media.NONE;
    }
}
