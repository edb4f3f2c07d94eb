package dev.strahl.testing;

import dev.strahl.world.World;
import dev.strahl.accel.Aggregate;
import dev.strahl.accel.Bvh;
import dev.strahl.accel.TraversalStack;
import dev.strahl.camera.CameraRays;
import dev.strahl.image.Image;
import dev.strahl.io.ImageWriters;
import dev.strahl.codec.PfmReader;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.scene.Scene;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Golden-image comparison. The image is cut into regions, one per visible planar face of the
 * scene (a wall, a face of a box, the light): a pixel belongs to a face when every one of its
 * 4×4 sub-pixel rays hits that face. Each region's mean luminance must match the reference
 * within a relative tolerance, and the whole image's relative MSE must stay under a bound.
 */
public final class Golden {
    /** Regions smaller than this are too noisy to judge alone; they still count in the relMSE. */
    public static final int MIN_REGION_PIXELS = 24;

    private Golden() {}

    /** A reference image from src/test/resources/golden. */
    public static Image reference(String fileName) {
        try {
            Path p = Path.of(Golden.class.getResource("/golden/" + fileName).toURI());
            return PfmReader.read(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** One region: its name and the pixel indices (y·width + x) that belong to it. */
    public record Region(String name, int[] pixels) {}

    /** The face regions of the scene as seen by its camera at the given size. */
    public static List<Region> faceRegions(Scene scene, int width, int height) {
        return regions(scene, width, height, true);
    }

    /**
     * One region per material as the scene's camera sees it at the given size: a pixel belongs to
     * a material when every one of its 4×4 sub-pixel rays hits a surface of that material (a sphere
     * of its own material is one region, whatever its normals).
     */
    public static List<Region> materialRegions(Scene scene, int width, int height) {
        return regions(scene, width, height, false);
    }

    private static List<Region> regions(Scene scene, int width, int height, boolean faces) {
        int sub = 4;
        CameraRays rays = Meshes.rays(scene.camera(), width * sub, height * sub);
        Aggregate bvh = World.of(scene).bvh();
        Ray ray = new Ray();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        TraversalStack stack = Bvh.newStack();
        Map<String, List<Integer>> byFace = new LinkedHashMap<>();
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                String face = null;
                boolean uniform = true;
                for (int k = 0; k < sub * sub && uniform; k++) {
                    rays.generate(x * sub + k % sub + 0.5, y * sub + k / sub + 0.5, ray);
                    hit.reset();
                    String f = "background";
                    if (bvh.intersect(ray, hit, stack, false)) {
                        World.of(scene).geometry().surface(ray, hit, sp);
                        f = faces ? faceName(scene, sp) : scene.materials().get(sp.material).name();
                    }
                    if (face == null) {
                        face = f;
                    } else if (!face.equals(f)) {
                        uniform = false;
                    }
                }
                if (uniform && !face.equals("background")) {
                    byFace.computeIfAbsent(face, k -> new ArrayList<>()).add(y * width + x);
                }
            }
        }
        List<Region> regions = new ArrayList<>();
        byFace.forEach((name, px) -> regions.add(new Region(name, px.stream().mapToInt(Integer::intValue).toArray())));
        return regions;
    }

    /** Material and normal rounded to a tenth, so both triangles of a slightly bent quad form one face. */
    private static String faceName(Scene scene, SurfacePoint sp) {
        String material = scene.materials().get(sp.material).name();
        return String.format(Locale.ROOT, "%s(%d,%d,%d)", material,
                Math.round(sp.ng.x * 10), Math.round(sp.ng.y * 10), Math.round(sp.ng.z * 10));
    }

    /** Mean luminance of an image over a region. */
    public static double meanLuminance(Image img, Region region) {
        double s = 0;
        float[] rgb = img.rgb();
        for (int p : region.pixels()) {
            s += 0.2126 * rgb[3 * p] + 0.7152 * rgb[3 * p + 1] + 0.0722 * rgb[3 * p + 2];
        }
        return s / region.pixels().length;
    }

    /** The reference with one region's pixels scaled by {@code factor}: a "mutant" the check must reject. */
    public static Image scaleRegion(Image img, Region region, double factor) {
        float[] rgb = img.rgb();
        for (int p : region.pixels()) {
            for (int c = 0; c < 3; c++) {
                rgb[3 * p + c] *= (float) factor;
            }
        }
        return new Image(img.width(), img.height(), rgb);
    }

    /**
     * Fails with a list of the regions that differ by more than {@code relTolerance} in mean
     * luminance, or if relMSE exceeds {@code maxRelMse}. On failure the images are written to
     * target/golden-failures/ for a person to look at.
     */
    public static void assertClose(Image img, Image ref, List<Region> regions, double relTolerance, double maxRelMse, String name) {
        String failures = differences(img, ref, regions, relTolerance, maxRelMse);
        if (!failures.isEmpty()) {
            writeFailure(img, ref, name);
            throw new AssertionError(name + " differs from its reference:" + failures);
        }
    }

    /** What {@link #assertClose} would complain about, one line per difference; empty if nothing. */
    public static String differences(Image img, Image ref, List<Region> regions, double relTolerance, double maxRelMse) {
        StringBuilder failures = new StringBuilder();
        for (Region r : regions) {
            if (r.pixels().length < MIN_REGION_PIXELS) {
                continue;
            }
            double a = meanLuminance(img, r);
            double b = meanLuminance(ref, r);
            double rel = (a - b) / b;
            if (!(Math.abs(rel) <= relTolerance)) {
                failures.append(String.format(Locale.ROOT, "%n  region %s (%d px): %.5f vs reference %.5f (%+.2f %%)",
                        r.name(), r.pixels().length, a, b, 100 * rel));
            }
        }
        double relMse = img.relMse(ref);
        if (!(relMse <= maxRelMse)) {
            failures.append(String.format(Locale.ROOT, "%n  relMSE %.3g > %.3g", relMse, maxRelMse));
        }
        return failures.toString();
    }

    /** The largest relative region difference, for reports. */
    public static double worstRegionError(Image img, Image ref, List<Region> regions) {
        double worst = 0;
        for (Region r : regions) {
            if (r.pixels().length >= MIN_REGION_PIXELS) {
                worst = Math.max(worst, Math.abs(meanLuminance(img, r) / meanLuminance(ref, r) - 1));
            }
        }
        return worst;
    }

    /**
     * Σ_c |Σ img − Σ ref| / Σ_c Σ ref over the pixels of block (bx, by) of size {@code block}, only
     * those in {@code region} if it is not null: the block's mean colour error relative to its
     * luminance (summed over r, g, b). NaN if the block holds fewer than block²/2 region pixels.
     */
    public static double blockError(Image img, Image ref, int block, int bx, int by, Region region) {
        boolean[] in = region == null ? null : mask(img, region);
        return blockError(img, ref, block, bx, by, in);
    }

    private static double blockError(Image img, Image ref, int block, int bx, int by, boolean[] in) {
        double diff = 0, sum = 0;
        int n = 0;
        double[] a = new double[3], b = new double[3];
        for (int y = by * block; y < (by + 1) * block; y++) {
            for (int x = bx * block; x < (bx + 1) * block; x++) {
                if (in != null && !in[y * img.width() + x]) {
                    continue;
                }
                n++;
                for (int c = 0; c < 3; c++) {
                    a[c] += img.get(x, y, c);
                    b[c] += ref.get(x, y, c);
                }
            }
        }
        if (2 * n < block * block) {
            return Double.NaN;
        }
        for (int c = 0; c < 3; c++) {
            diff += Math.abs(a[c] - b[c]);
            sum += b[c];
        }
        return diff / sum;
    }

    private static boolean[] mask(Image img, Region region) {
        boolean[] in = new boolean[img.width() * img.height()];
        for (int p : region.pixels()) {
            in[p] = true;
        }
        return in;
    }

    /** A block of a region and its error ({@link #blockError}). */
    public record BlockError(int bx, int by, double error) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "block (%d, %d): %.2f %%", bx, by, 100 * error);
        }
    }

    /**
     * The worst {@link #blockError} over the image's blocks (all pixels if {@code region} is null,
     * else the blocks at least half inside it); (−1, −1, 0) if there is none.
     */
    public static BlockError worstBlock(Image img, Image ref, int block, Region region) {
        boolean[] in = region == null ? null : mask(img, region);
        BlockError worst = new BlockError(-1, -1, 0);
        for (int by = 0; by < img.height() / block; by++) {
            for (int bx = 0; bx < img.width() / block; bx++) {
                double e = blockError(img, ref, block, bx, by, in);
                if (e > worst.error()) {
                    worst = new BlockError(bx, by, e);
                }
            }
        }
        return worst;
    }

    /** Writes the render, the reference and their difference ×10 to target/golden-failures/NAME-*. */
    public static void writeFailure(Image img, Image ref, String name) {
        try {
            Path dir = Files.createDirectories(Path.of("target", "golden-failures"));
            ImageWriters.write(img, dir.resolve(name + "-render.pfm"));
            ImageWriters.write(img, dir.resolve(name + "-render.png"));
            ImageWriters.write(ref, dir.resolve(name + "-reference.png"));
            float[] a = img.rgb(), b = ref.rgb(), d = new float[a.length];
            for (int i = 0; i < a.length; i++) {
                d[i] = Math.abs(a[i] - b[i]) * 10;
            }
            ImageWriters.write(new Image(img.width(), img.height(), d), dir.resolve(name + "-difference-x10.png"));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
