package dev.strahl.bench;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Map;
import java.util.TreeMap;

/**
 * The anchor figures {@code strahl bench} compares with: measured side by side on the same
 * machine by {@code docs/bench/anchors.py} (Mitsuba 3 on the Cornell Box, Embree through
 * embreex on the rays {@code bench --export-rays} writes), read from its JSON file with
 * {@code --anchors FILE}. Without a file the constants of {@link #fallback()} stand in: figures
 * measured once on this project's machine, which drift with the machine's speed (see
 * docs/performance.md).
 *
 * <p>The file's figures are the numeric leaves of its objects, named by their dotted path:
 * {@code mitsuba.llvm_ad_rgb.samples_per_second.median}, {@code mitsuba.scalar_rgb.…},
 * {@code embree.meshes.<mesh>.<set>.rays_per_second.median} (set = primary, incoherent or
 * shadow, per core) and {@code embree.meshes.<mesh>.build_triangles_per_second.median}.
 */
public final class BenchAnchors {
    /** Mitsuba 3 LLVM back end, Cornell Box 512², 2 threads, samples/s. */
    static final String MITSUBA_LLVM = "mitsuba.llvm_ad_rgb.samples_per_second.median";
    /** Mitsuba 3 scalar back end, the same. */
    static final String MITSUBA_SCALAR = "mitsuba.scalar_rgb.samples_per_second.median";

    private final Map<String, Double> figures;
    private final String source;

    private BenchAnchors(Map<String, Double> figures, String source) {
        this.figures = figures;
        this.source = source;
    }

    /** The key of Embree's rays/s per core for a ray set of a mesh. */
    static String embreeRays(String mesh, String set) {
        return "embree.meshes." + mesh + "." + set + ".rays_per_second.median";
    }

    /** The key of Embree's BVH build rate (triangles/s, all threads) for a mesh. */
    static String embreeBuild(String mesh) {
        return "embree.meshes." + mesh + ".build_triangles_per_second.median";
    }

    /**
     * The constants used without {@code --anchors}: measured on the project's 2-core machine in
     * an earlier round (Mitsuba 3.9.1, Embree 4), kept so that a bench run without the Python
     * anchors still prints ratios; they are not side by side.
     *
     * @return the constant anchors
     */
    public static BenchAnchors fallback() {
        Map<String, Double> f = new TreeMap<>();
        f.put(MITSUBA_LLVM, 4.0e6);
        f.put(MITSUBA_SCALAR, 1.26e6);
        f.put(embreeRays("bunny_midpoint-sub2_1.1M", "primary"), 11.5e6);
        f.put(embreeRays("bunny_midpoint-sub2_1.1M", "incoherent"), 3.0e6);
        f.put(embreeRays("bun_zipper", "incoherent"), 6.0e6);
        f.put(embreeRays("cornell-box", "incoherent"), 7.5e6);
        f.put(embreeBuild("bunny_midpoint-sub2_1.1M"), 3.7e6);
        return new BenchAnchors(f, "constants (not side by side)");
    }

    /**
     * Reads the anchors file {@code docs/bench/anchors.py} writes.
     *
     * @param file the JSON file
     * @return its figures
     * @throws IOException with a one-line message naming the file and the place, if the file
     *         cannot be read, is not JSON, holds a figure that is not a positive number or no
     *         figure {@code bench} uses
     */
    public static BenchAnchors read(Path file) throws IOException {
        Map<String, Double> f = new TreeMap<>();
        String date = null;
        try (JsonParser p = new JsonFactory().createParser(file.toFile())) {
            Deque<String> path = new ArrayDeque<>();
            String name = null;
            if (p.nextToken() != JsonToken.START_OBJECT) {
                throw new IOException(file + ": " + place(p.currentLocation()) + ": expected a JSON object");
            }
            for (JsonToken t = p.nextToken(); t != null; t = p.nextToken()) {
                switch (t) {
                    case FIELD_NAME -> name = p.currentName();
                    case START_OBJECT -> path.addLast(name == null ? "?" : name);
                    case END_OBJECT -> path.pollLast();
                    case START_ARRAY -> p.skipChildren();
                    case VALUE_NUMBER_INT, VALUE_NUMBER_FLOAT, VALUE_STRING, VALUE_TRUE, VALUE_FALSE, VALUE_NULL -> {
                        String key = (path.isEmpty() ? "" : String.join(".", path) + ".") + name;
                        if (key.equals("date") && t == JsonToken.VALUE_STRING) {
                            date = p.getText();
                        } else if (used(key)) {
                            if (!t.isNumeric() || !(p.getDoubleValue() > 0) || Double.isInfinite(p.getDoubleValue())) {
                                throw new IOException(file + ": " + place(p.currentTokenLocation()) + ": " + key
                                        + " must be a positive number, got " + p.getText());
                            }
                            f.put(key, p.getDoubleValue());
                        }
                    }
                    default -> { }
                }
            }
        } catch (JsonParseException e) {
            throw new IOException(file + ": " + place(e.getLocation()) + ": not valid JSON (" + e.getOriginalMessage() + ")");
        } catch (NoSuchFileException | java.io.FileNotFoundException e) {
            throw new IOException(file + ": no such file");
        }
        if (f.isEmpty()) {
            throw new IOException(file + ": no anchor figures (mitsuba.<variant>.samples_per_second.median, "
                    + "embree.meshes.<mesh>.<set>.rays_per_second.median); write it with docs/bench/anchors.py");
        }
        return new BenchAnchors(f, file + (date != null ? " (" + date + ")" : ""));
    }

    private static boolean used(String key) {
        return key.equals(MITSUBA_LLVM) || key.equals(MITSUBA_SCALAR)
                || key.startsWith("embree.meshes.") && (key.endsWith(".rays_per_second.median") || key.endsWith(".build_triangles_per_second.median"));
    }

    private static String place(JsonLocation at) {
        return at == null ? "?" : "line " + at.getLineNr() + ", column " + at.getColumnNr();
    }

    /** The figure of {@code key}, or NaN if the anchors have none. */
    double get(String key) {
        Double v = figures.get(key);
        return v == null ? Double.NaN : v;
    }

    /** Where the figures come from: the file and its date, or the constants. */
    String source() {
        return source;
    }

    /** Whether the figures were measured side by side (read from a file), not the constants. */
    boolean sideBySide() {
        return !source.startsWith("constants");
    }

    /** How many figures there are. */
    int size() {
        return figures.size();
    }
}
