import dev.strahl.image.Image;
import dev.strahl.io.ImageWriters;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
import java.nio.file.Files;
import java.nio.file.Path;
import org.joml.Vector3d;

/**
 * Renders one scene with seeds seed0 .. seed0+runs-1 in one JVM (what `strahl render --seed s`
 * gives for each, without a JVM start per run) and writes run_seedNNNN.pfm into OUTDIR.
 * Run with the executable jar on the class path (strahl_cornell.py does this):
 *   java -cp target/strahl.jar docs/anchors/cornell/StrahlRuns.java SCENE.obj "fx,fy,fz" "tx,ty,tz" FOV RES SPP SEED0 RUNS THREADS OUTDIR
 */
public class StrahlRuns {
    private static Vector3d vec(String s) {
        String[] p = s.split(",");
        return new Vector3d(Double.parseDouble(p[0]), Double.parseDouble(p[1]), Double.parseDouble(p[2]));
    }

    public static void main(String[] a) throws Exception {
        Scene base = SceneLoader.load(Path.of(a[0]));
        Scene scene = base.withCamera(new Camera(vec(a[1]), vec(a[2]), new Vector3d(0, 1, 0), Double.parseDouble(a[3])));
        int res = Integer.parseInt(a[4]), spp = Integer.parseInt(a[5]), seed0 = Integer.parseInt(a[6]);
        int runs = Integer.parseInt(a[7]), threads = Integer.parseInt(a[8]);
        Path out = Path.of(a[9]);
        Files.createDirectories(out);
        for (int seed = seed0; seed < seed0 + runs; seed++) {
            Path file = out.resolve(String.format("run_seed%04d.pfm", seed));
            if (Files.exists(file)) {
                continue;
            }
            RenderSettings settings = RenderSettings.defaults().withSize(res, res).withSamplesPerPixel(spp)
                    .withMaxDepth(-1).withSeed(seed).withThreads(threads);
            try (RenderJob job = RenderJob.start(scene, settings)) {
                Image img = job.awaitCompletion();
                ImageWriters.write(img, file);
            }
        }
    }
}
