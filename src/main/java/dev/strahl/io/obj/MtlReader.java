package dev.strahl.io.obj;

import dev.strahl.image.Rgb;
import dev.strahl.io.text.LineCursor;
import dev.strahl.io.text.TextLines;
import dev.strahl.scene.SceneException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Reads a Wavefront MTL file into {@link MtlMaterial}s.
 *
 * <p>Understood: {@code newmtl NAME} (the rest of the line, so names may contain spaces),
 * {@code Kd}, {@code Ks}, {@code Ke} (one number = grey, or three), {@code Ns}, {@code Ni},
 * {@code illum}, the PBR extension's {@code Pr} and {@code Pm}, and the texture maps
 * {@code map_Kd}, {@code map_Pr} and {@code map_Pm} with their options {@code -s} and {@code -o}
 * (other options are skipped with a warning). Accepted and ignored: {@code Ka} (no ambient term in
 * a path tracer), {@code Tr}, {@code Tf} (transparency is what {@code illum 7} means, DESIGN.md
 * §3), {@code d} (a constant {@code d} below 1 gets one warning per file). Other texture statements
 * ({@code map_Ke}, {@code map_d}, {@code norm}, {@code bump}, {@code disp}, {@code decal},
 * {@code refl}, other {@code map_*}) give one warning per file, any other key one warning per key;
 * keys are matched without regard to case, because exporters disagree on it.
 *
 * <p>Errors (a {@link SceneException} at {@code file:line:}): numbers that do not parse, colours
 * with 2 or more than 3 numbers, negative or non-finite colours, a negative {@code Ns}, an
 * {@code illum} that is not an integer 0..10, material keys before the first {@code newmtl}.
 * {@code Ni} &le; 0 (written by some exporters for opaque materials) is a warning and becomes 1.
 */
public final class MtlReader {

    private MtlReader() {}

    /**
     * The materials of {@code mtl} in file order, keyed by the bytes of their names
     * ({@link TextLines#byteKey}: the name itself for ASCII names, so that {@code usemtl} matches
     * {@code newmtl} byte for byte whatever the encodings of the two files). When a name is
     * defined twice the first definition is kept, as in an OBJ reader's name lookup. A file that
     * is not UTF-8 is read as Latin-1 (old exporters' names), with a note. Warnings are appended to
     * {@code warnings}, each starting with the file name.
     */
    public static Map<String, MtlMaterial> read(Path mtl, List<String> warnings) throws SceneException {
        return TextLines.read(mtl, ObjReader.ERRORS, "MTL", false, warnings, (lines, w) -> read(mtl, lines, w));
    }

    private static Map<String, MtlMaterial> read(Path mtl, TextLines<SceneException> lines, List<String> warnings) throws SceneException {
        Map<String, MtlMaterial> materials = new LinkedHashMap<>();
        Set<String> warnedKeys = new HashSet<>();
        boolean warnedTextures = false;
        boolean warnedDissolve = false;
        Block block = null;
        var cur = new LineCursor<>(mtl, ObjReader.ERRORS);
        for (String line; (line = lines.next()) != null; ) {
            cur.reset(line, lines.lineNumber());
            if (!cur.next()) {
                continue;
            }
            String key = cur.token();
            String lower = key.toLowerCase(Locale.ROOT);
            if (lower.equals("newmtl")) {
                add(block, materials, mtl, warnings);
                String name = cur.rest();
                if (name.isEmpty()) {
                    throw cur.error("newmtl without a material name");
                }
                block = new Block(name, lines.byteKey(name), cur.lineNumber);
                continue;
            }
            if (lower.equals("map_kd") || lower.equals("map_pr") || lower.equals("map_pm")) {
                if (block == null) {
                    throw cur.error(LineCursor.quote(key) + " before any newmtl");
                }
                MtlMaterial.MapRef map = map(key, cur, mtl, warnings);
                switch (lower) {
                    case "map_kd" -> block.mapKd = map;
                    case "map_pr" -> block.mapPr = map;
                    default -> block.mapPm = map;
                }
                continue;
            }
            if (lower.equals("d") && block != null && !warnedDissolve) {
                double d = cur.next() && isNumber(cur.token()) ? cur.number(key) : 1;
                if (d < 1) {
                    warnedDissolve = true;
                    warnings.add(mtl + ": 'd " + d + "' of material " + LineCursor.quote(block.name) + " (line " + cur.lineNumber
                            + "): constant transparency is not rendered; ignored (glass is illum 7)");
                }
                continue;
            }
            if (isTexture(lower)) {
                if (!warnedTextures) {
                    warnedTextures = true;
                    warnings.add(mtl + ": texture statement " + LineCursor.quote(key) + " (line " + cur.lineNumber
                            + ") is not supported (strahl reads map_Kd, map_Pr and map_Pm): ignored, as are the others of this file");
                }
                continue;
            }
            if (!isMaterialKey(lower)) {
                if (warnedKeys.add(key)) {
                    warnings.add(mtl + ": unknown key " + LineCursor.quote(key) + " (line "
                            + cur.lineNumber + "): ignored");
                }
                continue;
            }
            if (block == null) {
                throw cur.error(LineCursor.quote(key) + " before any newmtl");
            }
            readKey(lower, key, cur, block, mtl, warnings);
        }
        add(block, materials, mtl, warnings);
        return materials;
    }

    private static boolean isTexture(String lowerKey) {
        return lowerKey.startsWith("map_") || switch (lowerKey) {
            case "bump", "disp", "decal", "refl", "norm" -> true;
            default -> false;
        };
    }

    private static boolean isMaterialKey(String lowerKey) {
        return switch (lowerKey) {
            case "kd", "ks", "ke", "ka", "ns", "ni", "illum", "d", "tr", "tf", "pr", "pm" -> true;
            default -> false;
        };
    }

    private static void readKey(String lower, String key, LineCursor<SceneException> cur, Block block, Path mtl,
            List<String> warnings) throws SceneException {
        switch (lower) {
            case "kd" -> block.kd = colour(key, cur, mtl, warnings, block.kd);
            case "ks" -> block.ks = colour(key, cur, mtl, warnings, block.ks);
            case "ke" -> block.ke = colour(key, cur, mtl, warnings, block.ke);
            case "ns" -> {
                double ns = single(key, cur);
                if (!(ns >= 0) || !Double.isFinite(ns)) {
                    throw cur.error("'Ns' must be a finite number >= 0, got " + ns);
                }
                block.ns = ns;
            }
            case "ni" -> {
                double ni = single(key, cur);
                if (!Double.isFinite(ni)) {
                    throw cur.error("'Ni' must be finite, got " + ni);
                }
                if (ni > 0) {
                    block.ni = ni;
                } else {
                    warnings.add(mtl + ": 'Ni " + ni + "' of material " + LineCursor.quote(block.name) + " (line "
                            + cur.lineNumber + ") is not an index of refraction: using " + MtlMaterial.DEFAULT_NI);
                    block.ni = MtlMaterial.DEFAULT_NI;
                }
            }
            case "pr", "pm" -> {
                double x = single(key, cur);
                if (!(x >= 0 && x <= 1)) {
                    throw cur.error(LineCursor.quote(key) + " must lie in [0, 1], got " + x);
                }
                if (lower.equals("pr")) {
                    block.pr = x;
                } else {
                    block.pm = x;
                }
            }
            case "illum" -> {
                double illum = single(key, cur);
                if (!(illum >= 0 && illum <= MtlMaterial.MAX_ILLUM && illum == Math.rint(illum))) {
                    throw cur.error("'illum' must be an integer 0.." + MtlMaterial.MAX_ILLUM + ", got " + illum);
                }
                block.illum = (int) illum;
            }
            default -> { } // Ka, d, Tr, Tf: accepted, not used (see the class comment)
        }
    }

    /** Texture options and the number of arguments each takes (-s, -o and -t take one to three numbers). */
    private static final Map<String, Integer> MAP_OPTIONS = Map.ofEntries(Map.entry("-blendu", 1), Map.entry("-blendv", 1),
            Map.entry("-bm", 1), Map.entry("-boost", 1), Map.entry("-cc", 1), Map.entry("-clamp", 1), Map.entry("-imfchan", 1),
            Map.entry("-mm", 2), Map.entry("-texres", 1), Map.entry("-type", 1));

    /**
     * {@code map_Kd [options] file}: the options {@code -s u [v [w]]} and {@code -o u [v [w]]} are
     * applied, the others skipped with a warning; the file is the rest of the line, relative to the
     * MTL file's folder.
     */
    private static MtlMaterial.MapRef map(String key, LineCursor<SceneException> cur, Path mtl, List<String> warnings) throws SceneException {
        double[] scale = {1, 1, 1};
        double[] offset = {0, 0, 0};
        if (!cur.next()) {
            throw cur.error(LineCursor.quote(key) + " needs a file name");
        }
        while (cur.token().startsWith("-") && cur.token().length() > 1 && !Character.isDigit(cur.token().charAt(1))) {
            String option = cur.token().toLowerCase(Locale.ROOT);
            boolean more;
            if (option.equals("-s") || option.equals("-o") || option.equals("-t")) {
                double[] into = option.equals("-s") ? scale : option.equals("-o") ? offset : new double[3];
                int n = 0;
                while ((more = cur.next()) && n < 3 && isNumber(cur.token())) {
                    into[n++] = cur.number(key);
                }
                if (n == 0) {
                    throw cur.error(LineCursor.quote(key + " " + option) + " needs 1 to 3 numbers");
                }
                if (option.equals("-t")) {
                    warnings.add(mtl + ": option '-t' of " + LineCursor.quote(key) + " (line " + cur.lineNumber + ") is not supported: ignored");
                }
            } else {
                Integer arguments = MAP_OPTIONS.get(option);
                if (arguments == null) {
                    throw cur.error("unknown option " + LineCursor.quote(option) + " of " + LineCursor.quote(key));
                }
                warnings.add(mtl + ": option " + LineCursor.quote(option) + " of " + LineCursor.quote(key) + " (line " + cur.lineNumber
                        + ") is not supported: ignored");
                for (int i = 0; i < arguments; i++) {
                    if (!cur.next()) {
                        throw cur.error(LineCursor.quote(key + " " + option) + " needs " + arguments + " argument" + (arguments == 1 ? "" : "s"));
                    }
                }
                more = cur.next();
            }
            if (!more) {
                throw cur.error(LineCursor.quote(key) + " needs a file name after its options");
            }
        }
        String first = cur.token();
        String rest = cur.rest();
        String name = rest.isEmpty() ? first : first + " " + rest;
        Path file;
        try {
            Path folder = mtl.toAbsolutePath().getParent();
            file = folder.resolve(name.replace('\\', '/'));
        } catch (java.nio.file.InvalidPathException e) {
            throw cur.error(LineCursor.quote(key) + ": not a valid file name: " + LineCursor.quote(name));
        }
        if (!Double.isFinite(scale[0]) || !Double.isFinite(scale[1]) || !Double.isFinite(offset[0]) || !Double.isFinite(offset[1])) {
            throw cur.error(LineCursor.quote(key) + ": -s and -o must be finite");
        }
        return new MtlMaterial.MapRef(file, scale[0], scale[1], offset[0], offset[1]);
    }

    private static boolean isNumber(String token) {
        if (token.isEmpty()) {
            return false;
        }
        char c = token.charAt(0);
        return Character.isDigit(c) || c == '.' || ((c == '-' || c == '+') && token.length() > 1
                && (Character.isDigit(token.charAt(1)) || token.charAt(1) == '.'));
    }

    /** A key with exactly one number. */
    private static double single(String key, LineCursor<SceneException> cur) throws SceneException {
        if (!cur.next()) {
            throw cur.error(LineCursor.quote(key) + " needs 1 number, got 0");
        }
        double value = cur.number(key);
        int n = 1;
        while (cur.next()) {
            n++;
        }
        if (n > 1) {
            throw cur.error(LineCursor.quote(key) + " needs 1 number, got " + n);
        }
        return value;
    }

    /**
     * {@code Kd r g b} or {@code Kd v} (grey). The {@code spectral} and {@code xyz} forms are not
     * supported: a warning, and {@code previous} stays.
     */
    private static Rgb colour(String key, LineCursor<SceneException> cur, Path mtl, List<String> warnings, Rgb previous)
            throws SceneException {
        double[] c = new double[3];
        int n = 0;
        while (cur.next()) {
            if (n == 0 && (cur.token().equalsIgnoreCase("spectral") || cur.token().equalsIgnoreCase("xyz"))) {
                warnings.add(mtl + ": '" + key + " " + cur.token() + "' colours are not supported (line "
                        + cur.lineNumber + "): ignored");
                return previous;
            }
            double value = cur.number(key);
            if (!(value >= 0) || !Double.isFinite(value)) {
                throw cur.error("colour component " + LineCursor.quote(cur.token()) + " in "
                        + LineCursor.quote(key) + " must be finite and >= 0");
            }
            if (n < 3) {
                c[n] = value;
            }
            n++;
        }
        if (n == 1) {
            return Rgb.gray(c[0]);
        }
        if (n != 3) {
            throw cur.error(LineCursor.quote(key) + " needs 1 or 3 numbers, got " + n);
        }
        return new Rgb(c[0], c[1], c[2]);
    }

    private static void add(Block block, Map<String, MtlMaterial> materials, Path mtl, List<String> warnings) {
        if (block == null) {
            return;
        }
        if (materials.containsKey(block.key)) {
            warnings.add(mtl + ": material " + LineCursor.quote(block.name) + " (line " + block.line
                    + ") is defined again: keeping the first definition");
            return;
        }
        materials.put(block.key, block.toMaterial());
    }

    /** The keys of one newmtl block as they are read, starting from the defaults. */
    private static final class Block {
        final String name;
        final String key;                  // the name's bytes (TextLines.byteKey)
        final int line;
        Rgb kd = MtlMaterial.DEFAULT_KD;
        Rgb ks = Rgb.BLACK;
        Rgb ke = Rgb.BLACK;
        double ns = MtlMaterial.DEFAULT_NS;
        double ni = MtlMaterial.DEFAULT_NI;
        int illum = MtlMaterial.DEFAULT_ILLUM;
        Double pr, pm;
        MtlMaterial.MapRef mapKd, mapPr, mapPm;

        Block(String name, String key, int line) {
            this.name = name;
            this.key = key;
            this.line = line;
        }

        MtlMaterial toMaterial() {
            return new MtlMaterial(name, kd, ks, ke, ns, ni, illum, pr, pm, mapKd, mapPr, mapPm);
        }
    }
}
