package dev.strahl.io;

import dev.strahl.io.ply.PlyFiles;
import dev.strahl.io.ply.PlyHeader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Tuple;

/**
 * Fuzzing inputs for the scene parsers, as jqwik arbitraries: files generated from a small
 * grammar of each format (valid statements with hostile values mixed with junk), and the shipped
 * scenes mutated (bytes flipped, inserted, deleted, duplicated; tokens and numbers replaced).
 */
final class FuzzInputs {
    private FuzzInputs() {}

    /** Numbers as they appear in files, from ordinary to hostile. */
    static Arbitrary<String> number() {
        return Arbitraries.frequencyOf(
                Tuple.of(6, Arbitraries.doubles().between(-10, 10).map(d -> Double.toString(d))),
                Tuple.of(3, Arbitraries.integers().between(-5, 20).map(i -> Integer.toString(i))),
                Tuple.of(2, Arbitraries.doubles().map(d -> Double.toString(d))),
                Tuple.of(3, Arbitraries.of("NaN", "nan", "-NaN", "Infinity", "-Infinity", "inf", "1e309", "-1e309", "1e-400", "4.9e-324",
                        "3.4028235e38", "3.5e38", "1e18", "1.1e18", "1.7976931348623157E308", "-0", "-0.0", "0x1p3", "1_000", "+5", "5.",
                        ".5", "1e", "e5", "--1", "1..2", "1,5", "", "00000000000000000000001", "9".repeat(400), "1e99999999999",
                        "0.1e-2147483648", "٣", "1\u00a0")));
    }

    /** OBJ face-vertex references. */
    static Arbitrary<String> index() {
        Arbitrary<String> i = Arbitraries.frequencyOf(
                Tuple.of(8, Arbitraries.integers().between(1, 12).map(n -> Integer.toString(n))),
                Tuple.of(2, Arbitraries.integers().between(-12, -1).map(n -> Integer.toString(n))),
                Tuple.of(1, Arbitraries.of("0", "-0", "2147483648", "-2147483649", "99999999999999999999", "x", "", "1.5", "+1")));
        return Arbitraries.frequencyOf(
                Tuple.of(6, i),
                Tuple.of(2, Combinators.combine(i, i).as((a, b) -> a + "/" + b)),
                Tuple.of(2, Combinators.combine(i, i).as((a, b) -> a + "//" + b)),
                Tuple.of(2, Combinators.combine(i, i, i).as((a, b, c) -> a + "/" + b + "/" + c)),
                Tuple.of(1, Arbitraries.of("/", "//", "1/2/3/4", "///", "1/")));
    }

    private static Arbitrary<String> numbers(int min, int max) {
        return number().list().ofMinSize(min).ofMaxSize(max).map(l -> String.join(" ", l));
    }

    private static Arbitrary<String> junk() {
        return Arbitraries.strings().withCharRange(' ', '~').withChars('\t', '\u00e9', '\u0000', '\\', '\ufeff', '\r')
                .ofMaxLength(30);
    }

    private static Arbitrary<String> name() {
        return Arbitraries.of("red", "white", "light", "Material.001", "a b", "", "cornell-box.mtl", "missing.mtl", "../cornell-box.mtl",
                "/dev/null", "nul\u0000l", "\u00e9t\u00e9", "x".repeat(300), "*", ".", "..");
    }

    static Arbitrary<byte[]> randomObj() {
        Arbitrary<String> line = Arbitraries.frequencyOf(
                Tuple.of(10, numbers(0, 5).map(s -> "v " + s)),
                Tuple.of(3, numbers(0, 4).map(s -> "vn " + s)),
                Tuple.of(2, numbers(0, 4).map(s -> "vt " + s)),
                Tuple.of(10, index().list().ofMaxSize(7).map(l -> "f " + String.join(" ", l))),
                Tuple.of(2, name().map(n -> "usemtl " + n)),
                Tuple.of(2, name().map(n -> "mtllib " + n)),
                Tuple.of(1, Arbitraries.of("g group", "o object", "s 1", "s off", "# comment", "", "l 1 2", "p 1", "curv 0 1 1 2",
                        "v 1 2 3 \\", "f 1 2 \\", "\\", "mtllib", "usemtl", "\ufeffv 0 0 0")),
                Tuple.of(2, junk()));
        return lines(line, 80);
    }

    static Arbitrary<byte[]> randomMtl() {
        Arbitrary<String> key = Arbitraries.of("Kd", "Ks", "Ke", "Ka", "kd", "KD", "Tf", "Ns", "Ni", "illum", "d", "Tr");
        Arbitrary<String> line = Arbitraries.frequencyOf(
                Tuple.of(3, name().map(n -> "newmtl " + n)),
                Tuple.of(12, Combinators.combine(key, numbers(0, 5)).as((k, n) -> k + " " + n)),
                Tuple.of(1, Arbitraries.of("Kd spectral a.spd", "Ks xyz 1 1 1", "map_Kd tex.png", "bump b.png", "newmtl", "# c", "",
                        "illum 2.5", "illum -1", "illum 11", "Ni 0", "Ni -1", "Ns -0")),
                Tuple.of(2, junk()));
        return lines(line, 40);
    }

    static Arbitrary<byte[]> randomJson() {
        Arbitrary<String> scalar = Arbitraries.frequencyOf(
                Tuple.of(5, number().filter(s -> s.matches("-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?"))),
                Tuple.of(2, Arbitraries.of("\"diffuse\"", "\"mirror\"", "\"dielectric\"", "\"glossy\"", "\"sphere\"", "\"obj\"",
                        "\"cornell-box.obj\"", "\"missing.obj\"", "\"m\"", "\"\"", "true", "false", "null", "\"\\u0000\"", "\"\\ud800\"",
                        "NaN", "1e999", "-")),
                Tuple.of(2, numbers(1, 4).filter(s -> s.matches("[-0-9. eE+]*")).map(s -> "[" + s.trim().replace(' ', ',') + "]")));
        Arbitrary<String> key = Arbitraries.of("shapes", "materials", "camera", "environment", "type", "center", "radius", "material",
                "file", "albedo", "emission", "reflectance", "ior", "diffuse", "specular", "exponent", "lookFrom", "lookAt", "up", "fov",
                "m", "lamps", "");
        Arbitrary<String> value = Arbitraries.lazyOf(
                () -> scalar,
                () -> scalar,
                () -> Combinators.combine(key, Arbitraries.lazy(FuzzInputs::jsonValue)).as((k, v) -> "\"" + k + "\": " + v)
                        .list().ofMaxSize(5).map(l -> "{" + String.join(", ", l) + "}"),
                () -> Arbitraries.lazy(FuzzInputs::jsonValue).list().ofMaxSize(4).map(l -> "[" + String.join(", ", l) + "]"));
        return Combinators.combine(key, value).as((k, v) -> "\"" + k + "\": " + v).list().ofMaxSize(5)
                .map(l -> ("{" + String.join(",\n", l) + "}\n").getBytes(StandardCharsets.UTF_8));
    }

    /** Scene files of the right shape with hostile values: they get past the JSON syntax into the scene's checks. */
    static Arbitrary<byte[]> randomScene() {
        Arbitrary<String> num = Arbitraries.of("0", "1", "-1", "0.5", "2", "40", "179.9", "180", "1e308", "1e-308", "1e999", "-1e999",
                "-0", "1e18", "3e38", "123456789012345678901234567890", "0.0000001", "1.5");
        Arbitrary<String> vec = Arbitraries.frequencyOf(
                Tuple.of(6, num.list().ofSize(3).map(l -> "[" + String.join(", ", l) + "]")),
                Tuple.of(1, num.list().ofMaxSize(5).map(l -> "[" + String.join(", ", l) + "]")),
                Tuple.of(1, Arbitraries.of("[0, 1, 0]", "[0, 0, 0]", "\"red\"", "null", "[[1], 2, 3]")));
        Arbitrary<String> anyValue = Arbitraries.oneOf(num, vec, Arbitraries.of("\"m\"", "\"cornell-box.obj\"", "\"\"", "true", "{}"));
        Arbitrary<String> matType = Arbitraries.of("diffuse", "mirror", "dielectric", "glossy", "metal");
        Arbitrary<String> matKey = Arbitraries.of("albedo", "emission", "reflectance", "ior", "diffuse", "specular", "exponent", "rough");
        Arbitrary<String> material = Combinators.combine(matType,
                Combinators.combine(matKey, anyValue).as((k, v) -> "\"" + k + "\": " + v).list().ofMaxSize(3))
                .as((t, kv) -> "{\"type\": \"" + t + "\"" + kv.stream().map(x -> ", " + x).reduce("", String::concat) + "}");
        Arbitrary<String> materials = Combinators.combine(Arbitraries.of("m", "n", "", "m"), material)
                .as((n, m) -> "\"" + n + "\": " + m).list().ofMaxSize(3).map(l -> "{" + String.join(", ", l) + "}");
        Arbitrary<String> sphere = Combinators.combine(vec, num, Arbitraries.of("m", "n", "missing"))
                .as((c, r, m) -> "{\"type\": \"sphere\", \"center\": " + c + ", \"radius\": " + r + ", \"material\": \"" + m + "\"}");
        Arbitrary<String> obj = Arbitraries.of("cornell-box.obj", "cornell-sphere.obj", "missing.obj", "cornell-box.mtl", "", ".", "/dev/null")
                .map(f -> "{\"type\": \"mesh\", \"file\": \"" + f + "\"}");
        Arbitrary<String> transform = Arbitraries.frequencyOf(
                Tuple.of(2, vec.map(v -> "{\"translate\": " + v + "}")),
                Tuple.of(2, Arbitraries.oneOf(vec, num).map(v -> "{\"scale\": " + v + "}")),
                Tuple.of(2, Combinators.combine(vec, num).as((a, d) -> "{\"rotate\": {\"axis\": " + a + ", \"degrees\": " + d + "}}")),
                Tuple.of(1, Arbitraries.of("{}", "{\"shear\": 1}", "[]", "{\"translate\": [1, 2, 3], \"scale\": 2}")))
                .list().ofMaxSize(3).map(l -> "[" + String.join(", ", l) + "]");
        Arbitrary<String> triangles = Combinators.combine(num.list().ofMaxSize(12), Arbitraries.integers().between(-1, 5).list().ofMaxSize(9),
                Arbitraries.of("m", "n", "missing"))
                .as((p, i, m) -> "{\"type\": \"triangles\", \"positions\": [" + String.join(", ", p) + "], \"indices\": "
                        + i + ", \"material\": \"" + m + "\"}");
        Arbitrary<String> moved = Combinators.combine(Arbitraries.oneOf(sphere, obj, triangles), transform)
                .as((shape, t) -> shape.substring(0, shape.length() - 1) + ", \"transform\": " + t + "}");
        Arbitrary<String> shapes = Arbitraries.frequencyOf(Tuple.of(3, sphere), Tuple.of(2, obj), Tuple.of(2, triangles), Tuple.of(2, moved),
                Tuple.of(1, Combinators.combine(Arbitraries.of("cube", "sphere", "mesh", "triangles", "obj"), matKey, anyValue)
                        .as((t, k, v) -> "{\"type\": \"" + t + "\", \"" + k + "\": " + v + "}")))
                .list().ofMaxSize(4).map(l -> "[" + String.join(", ", l) + "]");
        Arbitrary<String> camera = Combinators.combine(Arbitraries.of("lookFrom", "lookAt", "up", "fov", "zoom"), anyValue)
                .as((k, v) -> "\"" + k + "\": " + v).list().ofMaxSize(5).map(l -> "{" + String.join(", ", l) + "}");
        Arbitrary<String> film = Combinators.combine(Arbitraries.of("width", "height", "depth"), Arbitraries.of("1", "2", "0", "-1", "8",
                "1e9", "1.5", "\"x\"")).as((k, v) -> "\"" + k + "\": " + v).list().ofMaxSize(3).map(l -> "{" + String.join(", ", l) + "}");
        Arbitrary<String> integrator = Combinators.combine(Arbitraries.of("type", "spp", "maxDepth", "seed", "lightSamples", "hemisphere",
                        "photons", "photonRadius", "noiseThreshold"),
                Arbitraries.of("\"path\"", "\"direct\"", "\"whitted\"", "\"photon\"", "\"cosine\"", "\"uniform\"", "1", "0", "-1", "-2",
                        "4", "1e10", "2.5", "9223372036854775808")).as((k, v) -> "\"" + k + "\": " + v).list().ofMaxSize(4)
                .map(l -> "{" + String.join(", ", l) + "}");
        return Combinators.combine(materials.optional(), shapes.optional(), camera.optional(), vec.optional(), film.optional(),
                        integrator.optional())
                .as((m, sh, c, env, f, integ) -> {
                    List<String> parts = new ArrayList<>();
                    f.ifPresent(x -> parts.add("\"film\": " + x));
                    integ.ifPresent(x -> parts.add("\"integrator\": " + x));
                    m.ifPresent(x -> parts.add("\"materials\": " + x));
                    sh.ifPresent(x -> parts.add("\"shapes\": " + x));
                    c.ifPresent(x -> parts.add("\"camera\": " + x));
                    env.ifPresent(x -> parts.add("\"environment\": " + x));
                    return ("{\n  " + String.join(",\n  ", parts) + "\n}\n").getBytes(StandardCharsets.UTF_8);
                });
    }

    /** Small PLY meshes in every encoding and with several types, as mutation seeds. */
    static List<byte[]> plySeeds() {
        List<byte[]> seeds = new ArrayList<>();
        PlyHeader.Type[] coordinate = {PlyHeader.Type.FLOAT, PlyHeader.Type.DOUBLE, PlyHeader.Type.SHORT};
        PlyHeader.Type[] count = {PlyHeader.Type.UCHAR, PlyHeader.Type.INT, PlyHeader.Type.USHORT};
        PlyHeader.Type[] index = {PlyHeader.Type.INT, PlyHeader.Type.UINT, PlyHeader.Type.USHORT};
        int i = 0;
        for (PlyHeader.Format format : PlyHeader.Format.values()) {
            for (int k = 0; k < 3; k++, i++) {
                seeds.add(PlyFiles.write(format, PlyFiles.randomMesh(i, 8 + 4 * k, 6 + 5 * k, coordinate[k], count[k], index[(k + i) % 3], k != 1)));
            }
        }
        return seeds;
    }

    /** PLY headers from the grammar (hostile counts, types, orders) followed by a random body. */
    static Arbitrary<byte[]> randomPly() {
        Arbitrary<String> type = Arbitraries.of("char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8",
                "int16", "uint16", "int32", "uint32", "float32", "float64", "long", "");
        Arbitrary<String> count = Arbitraries.of("0", "1", "3", "8", "12", "-1", "4294967296", "2147483647", "999999999999", "x", "1e3");
        Arbitrary<String> property = Arbitraries.frequencyOf(
                Tuple.of(5, Combinators.combine(type, Arbitraries.of("x", "y", "z", "nx", "ny", "nz", "red", "confidence", "x")).as((t, n) -> "property " + t + " " + n)),
                Tuple.of(3, Combinators.combine(type, type, Arbitraries.of("vertex_indices", "vertex_index", "texcoord"))
                        .as((c, t, n) -> "property list " + c + " " + t + " " + n)),
                Tuple.of(1, Arbitraries.of("property", "property list uchar", "property float", "comment x", "obj_info y")));
        Arbitrary<String> element = Combinators.combine(Arbitraries.of("vertex", "face", "edge", "material", "vertex"), count,
                property.list().ofMaxSize(7)).as((n, c, props) -> "element " + n + " " + c + "\n" + String.join("\n", props));
        Arbitrary<String> format = Arbitraries.of("ascii 1.0", "binary_little_endian 1.0", "binary_big_endian 1.0", "ascii 2.0", "binary 1.0",
                "ascii");
        Arbitrary<byte[]> body = Arbitraries.frequencyOf(
                Tuple.of(2, Arbitraries.bytes().array(byte[].class).ofMaxSize(400)),
                Tuple.of(2, number().list().ofMaxSize(120).map(l -> String.join(" ", l).getBytes(StandardCharsets.US_ASCII))));
        return Combinators.combine(format, element.list().ofMaxSize(4), body, Arbitraries.of("end_header\n", "end_header\r\n",
                "end_header", "end_header \n", "")).as((f, els, b, end) -> {
                    byte[] head = ("ply\nformat " + f + "\n" + String.join("\n", els) + "\n" + end).getBytes(StandardCharsets.US_ASCII);
                    byte[] all = java.util.Arrays.copyOf(head, head.length + b.length);
                    System.arraycopy(b, 0, all, head.length, b.length);
                    return all;
                });
    }

    static final List<String> PLY_WORDS = List.of("ply\n", "format ", "ascii", "binary_little_endian", "binary_big_endian", "1.0",
            "element ", "vertex", "face", "property ", "list ", "uchar", "int", "uint", "float", "double", "vertex_indices", "x", "nx",
            "end_header\n", "comment ", "\n", " ", "4294967295", "-1", "0", "NaN", "1e39", "99999999");

    private static Arbitrary<String> jsonValue() {
        return Arbitraries.frequencyOf(
                Tuple.of(4, Arbitraries.of("1", "0", "-1", "0.5", "1e999", "\"diffuse\"", "\"sphere\"", "\"obj\"", "\"cornell-box.obj\"",
                        "\"m\"", "null", "true", "[0, 1, 0]", "[1, 1]", "[0.8, 0.8, 0.8]", "[]", "{}")),
                Tuple.of(1, Combinators.combine(Arbitraries.of("type", "center", "radius", "material", "file", "albedo"),
                        Arbitraries.of("\"sphere\"", "[0,0,0]", "1", "\"m\"", "\"cornell-box.obj\"", "[0.5,0.5,0.5]"))
                        .as((k, v) -> "{\"" + k + "\": " + v + "}")));
    }

    private static Arbitrary<byte[]> lines(Arbitrary<String> line, int maxLines) {
        return line.list().ofMaxSize(maxLines).map(l -> (String.join("\n", l) + "\n").getBytes(StandardCharsets.UTF_8));
    }

    // ---- mutation ------------------------------------------------------------------------------

    /** The shipped scene files with one of the extensions, as mutation seeds. */
    static List<byte[]> shippedFiles(String extension) {
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            List<byte[]> out = new ArrayList<>();
            for (Path p : files.filter(f -> f.toString().endsWith(extension)).sorted().toList()) {
                out.add(Files.readAllBytes(p));
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Seeds mutated by 1 to 10 random edits chosen from a 64-bit choice drawn by jqwik. */
    static Arbitrary<byte[]> mutated(List<byte[]> seeds, List<String> dictionary) {
        return Combinators.combine(Arbitraries.of(seeds), Arbitraries.longs(), Arbitraries.of(1, 1, 1, 1, 2, 2, 2, 3, 3, 5, 10))
                .as((seed, choice, edits) -> mutate(seed, new SplittableRandom(choice), edits, dictionary));
    }

    static byte[] mutate(byte[] seed, SplittableRandom r, int edits, List<String> dictionary) {
        byte[] b = seed.clone();
        for (int e = 0; e < edits; e++) {
            int at = b.length == 0 ? 0 : r.nextInt(b.length + 1);
            b = switch (r.nextInt(10)) {
                case 0 -> flipBit(b, r);
                case 1 -> replace(b, at, 1, new byte[] {(byte) r.nextInt(256)});
                case 2 -> replace(b, at, 0, randomBytes(r, 1 + r.nextInt(8)));
                case 3 -> replace(b, at, Math.min(b.length - at, 1 + r.nextInt(64)), new byte[0]);
                case 4 -> duplicate(b, r);
                case 5 -> replace(b, at, 0, dictionary.get(r.nextInt(dictionary.size())).getBytes(StandardCharsets.UTF_8));
                case 6 -> replaceNumber(b, r);
                case 7 -> Math.min(at, b.length) == b.length ? b : java.util.Arrays.copyOf(b, at);      // truncate
                case 8 -> replace(b, at, 0, special(r));
                default -> replaceToken(b, r, dictionary);
            };
        }
        return b;
    }

    private static byte[] special(SplittableRandom r) {
        return switch (r.nextInt(6)) {
            case 0 -> new byte[] {0};
            case 1 -> new byte[] {(byte) 0xC3, 0x28};               // invalid UTF-8
            case 2 -> new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
            case 3 -> "\\\n".getBytes(StandardCharsets.US_ASCII);
            case 4 -> "\r\n".getBytes(StandardCharsets.US_ASCII);
            default -> new byte[] {'\n'};
        };
    }

    private static byte[] flipBit(byte[] b, SplittableRandom r) {
        if (b.length == 0) {
            return b;
        }
        byte[] c = b.clone();
        c[r.nextInt(c.length)] ^= (byte) (1 << r.nextInt(8));
        return c;
    }

    private static byte[] randomBytes(SplittableRandom r, int n) {
        byte[] x = new byte[n];
        for (int i = 0; i < n; i++) {
            x[i] = (byte) r.nextInt(256);
        }
        return x;
    }

    private static byte[] duplicate(byte[] b, SplittableRandom r) {
        if (b.length == 0) {
            return b;
        }
        int from = r.nextInt(b.length);
        int len = Math.min(b.length - from, 1 + r.nextInt(256));
        int to = r.nextInt(b.length + 1);
        return replace(b, to, 0, java.util.Arrays.copyOfRange(b, from, from + len));
    }

    /** Replaces one number in the text with a hostile one. */
    private static byte[] replaceNumber(byte[] b, SplittableRandom r) {
        String s = new String(b, StandardCharsets.ISO_8859_1);
        var m = java.util.regex.Pattern.compile("-?\\d+(\\.\\d+)?").matcher(s);
        List<int[]> spans = new ArrayList<>();
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        if (spans.isEmpty()) {
            return b;
        }
        int[] span = spans.get(r.nextInt(spans.size()));
        String[] hostile = {"NaN", "1e309", "-1e309", "0", "-1", "-0", "2147483648", "1e18", "3e38", "1e-320", "99999999999999", "x", ""};
        return replace(b, span[0], span[1] - span[0], hostile[r.nextInt(hostile.length)].getBytes(StandardCharsets.US_ASCII));
    }

    /** Replaces one whitespace-separated token with a dictionary entry. */
    private static byte[] replaceToken(byte[] b, SplittableRandom r, List<String> dictionary) {
        String s = new String(b, StandardCharsets.ISO_8859_1);
        var m = java.util.regex.Pattern.compile("[^\\s]+").matcher(s);
        List<int[]> spans = new ArrayList<>();
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        if (spans.isEmpty()) {
            return b;
        }
        int[] span = spans.get(r.nextInt(spans.size()));
        return replace(b, span[0], span[1] - span[0], dictionary.get(r.nextInt(dictionary.size())).getBytes(StandardCharsets.UTF_8));
    }

    private static byte[] replace(byte[] b, int at, int remove, byte[] insert) {
        at = Math.min(at, b.length);
        remove = Math.max(0, Math.min(remove, b.length - at));
        byte[] c = new byte[b.length - remove + insert.length];
        System.arraycopy(b, 0, c, 0, at);
        System.arraycopy(insert, 0, c, at, insert.length);
        System.arraycopy(b, at + remove, c, at + insert.length, b.length - at - remove);
        return c;
    }

    static final List<String> OBJ_WORDS = List.of("v", "vn", "vt", "f", "usemtl", "mtllib", "g", "o", "s", "l", "p", "#", "/", "//",
            "-1", "0", "NaN", "1e309", "missing.mtl", "cornell-box.mtl", "\\", "\n", " ", "99999999999", "f 1 2 3\n", "v 0 0 0\n");
    static final List<String> MTL_WORDS = List.of("newmtl", "Kd", "Ks", "Ke", "Ns", "Ni", "illum", "d", "Tr", "Tf", "map_Kd",
            "spectral", "xyz", "-1", "0", "NaN", "1e309", "11", "2.5", "\n", " ", "#");
    static final List<String> JSON_WORDS = List.of("{", "}", "[", "]", ",", ":", "\"", "null", "true", "false", "1e999", "-", "NaN",
            "\"shapes\"", "\"materials\"", "\"camera\"", "\"type\"", "\"sphere\"", "\"obj\"", "\"mesh\"", "\"triangles\"",
            "\"transform\"", "\"film\"", "\"integrator\"", "\"width\"", "\"spp\"", "\"translate\"", "\"scale\"", "\"rotate\"", "\"file\"", "\"center\"", "\"radius\"",
            "\"material\"", "\"albedo\"", "\"emission\"", "\"lookFrom\"", "\"fov\"", "\"environment\"", "\"mirror\"", "\"glossy\"",
            "\"dielectric\"", "\"ior\"", "\"exponent\"", "\"specular\"", "[0,0,0]", "[1,1]", "0", "-1", "\"missing.obj\"", "\\u0000");
}
