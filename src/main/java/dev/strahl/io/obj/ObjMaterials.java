package dev.strahl.io.obj;

import dev.strahl.io.text.LineCursor;
import dev.strahl.scene.SceneException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The materials of one OBJ file while {@link ObjReader} reads it: a slot per distinct
 * {@code usemtl} name (slot 0 holds the faces before any {@code usemtl}), the MTL libraries that
 * {@code mtllib} names, and at the end the material of every slot that faces use. A missing or
 * unreadable library and a name no library defines are warnings; faces then get the default grey
 * diffuse. Problems go to the reader's list of warnings, in the order they are found.
 */
final class ObjMaterials {
    private final Path obj;
    private final List<String> warnings;

    private final List<String> slotNames = new ArrayList<>(List.of(""));
    private final List<String> slotKeys = new ArrayList<>(List.of(""));     // the names' bytes (TextLines.byteKey)
    private final List<Integer> slotLines = new ArrayList<>(List.of(0));
    private final Map<String, Integer> slotByName = new HashMap<>();
    private final List<Integer> usedSlots = new ArrayList<>();
    private boolean[] slotUsed = new boolean[8];
    private int slot;

    private final Map<String, MtlMaterial> library = new HashMap<>();
    private final Set<Path> loadedLibraries = new HashSet<>();
    private boolean libraryMissing;

    ObjMaterials(Path obj, List<String> warnings) {
        this.obj = obj;
        this.warnings = warnings;
    }

    /**
     * {@code usemtl name} at {@code line}: the faces that follow use that name's slot. Names are
     * matched by {@code key}, their bytes in the file ({@code TextLines.byteKey}).
     */
    void use(String name, String key, int line) {
        Integer existing = slotByName.get(key);
        if (existing != null) {
            slot = existing;
            return;
        }
        slot = slotNames.size();
        slotNames.add(name);
        slotKeys.add(key);
        slotLines.add(line);
        slotByName.put(key, slot);
        if (slot == slotUsed.length) {
            slotUsed = Arrays.copyOf(slotUsed, slot * 2);
        }
    }

    /** The slot of the face being read, which from now on counts as used. */
    int faceSlot() {
        if (!slotUsed[slot]) {
            slotUsed[slot] = true;
            usedSlots.add(slot);
        }
        return slot;
    }

    /**
     * {@code mtllib a.mtl b.mtl ...} at {@code line}; a name containing spaces is taken whole when
     * the space-separated parts are not all existing files but the whole rest of the line is one.
     */
    void libraries(String rest, int line) throws SceneException {
        if (rest.isEmpty()) {
            warnings.add(obj + ": mtllib without a file name (line " + line + "): ignored");
            return;
        }
        List<String> names = new ArrayList<>();
        LineCursor<SceneException> split = new LineCursor<>(obj, ObjReader.ERRORS);
        split.reset(rest, line);
        while (split.next()) {
            names.add(split.token());
        }
        if (names.size() > 1 && !names.stream().allMatch(this::isLibraryFile) && isLibraryFile(rest)) {
            names = List.of(rest);
        }
        for (String name : names) {
            load(name, line);
        }
    }

    private boolean isLibraryFile(String name) {
        try {
            return Files.isRegularFile(obj.resolveSibling(name));
        } catch (InvalidPathException | SecurityException e) {
            return false;
        }
    }

    private void load(String name, int line) throws SceneException {
        String where = obj + ": material library " + LineCursor.quote(name) + " (line " + line + ")";
        String consequence = ": its materials are replaced by the default grey diffuse";
        Path path;
        try {
            path = obj.resolveSibling(name);
        } catch (InvalidPathException e) {
            warnings.add(where + " is not a valid file name" + consequence);
            libraryMissing = true;
            return;
        }
        if (!loadedLibraries.add(path.toAbsolutePath().normalize())) {
            return;
        }
        if (!Files.isRegularFile(path)) {
            warnings.add(where + " not found at " + path + consequence);
            libraryMissing = true;
            return;
        }
        if (!Files.isReadable(path)) {
            warnings.add(where + " is not readable" + consequence);
            libraryMissing = true;
            return;
        }
        // A library that exists but is malformed is an error, reported at its own file:line
        for (Map.Entry<String, MtlMaterial> e : MtlReader.read(path, warnings).entrySet()) {
            MtlMaterial m = e.getValue();
            if (library.putIfAbsent(e.getKey(), m) != null) {
                warnings.add(path + ": material '" + m.name() + "' is already defined by an earlier material library: "
                        + "keeping the first definition");
            }
        }
    }

    /**
     * Resolves the used slots: appends to {@code materials} each distinct material that faces use,
     * in order of first use, and returns for every slot the index of its material in that list.
     */
    int[] resolve(List<MtlMaterial> materials) {
        MtlMaterial fallback = MtlMaterial.defaultMaterial();
        Map<MtlMaterial, Integer> materialIndex = new IdentityHashMap<>();
        int[] slotMaterial = new int[slotNames.size()];
        for (int s : usedSlots) {
            MtlMaterial m = s == 0 ? fallback : library.get(slotKeys.get(s));
            if (m == null) {
                m = fallback;
                // After a missing library its warning already explains every unknown name
                if (!libraryMissing) {
                    warnings.add(obj + ": unknown material " + LineCursor.quote(slotNames.get(s)) + " (line "
                            + slotLines.get(s) + "): using the default grey diffuse");
                }
            }
            slotMaterial[s] = materialIndex.computeIfAbsent(m, k -> {
                materials.add(k);
                return materials.size() - 1;
            });
        }
        return slotMaterial;
    }
}
