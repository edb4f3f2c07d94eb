import dev.strahl.codec.PfmReader;
import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.Aov;
import dev.strahl.render.Denoiser;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.Locale;

/**
 * Wall time of one denoise (issue 33's goal for Open Image Denoise's network: a 512x512 image in
 * at most 2 s on the 2 cores here): renders the Cornell Box at SIZE² and SPP with all feature
 * buffers, then denoises the same buffers once (its time printed: the first denoise in a JVM reads the
 * weights and compiles the code), twice more untimed and RUNS times timed, nothing else
 * running in the JVM. KIND: network (Denoiser.create(), the default) or atrous (Denoiser.atrous()).
 * Also prints the process's CPU time per denoise (all threads; on a shared machine the better
 * figure of the work, as the wall time depends on what else runs) and the load average.
 * With {@code files}, it denoises the image and buffers of PFM files instead (the inputs
 * oidnDenoise takes; docs/bench/denoise_time.py alternates the two), with the network.
 *
 *   mvn -B -q -DskipTests package
 *   java -cp target/strahl.jar docs/bench/DenoiseTime.java [size=512] [spp=16] [runs=9] [kind=network]
 *   java --add-modules jdk.incubator.vector -cp target/strahl.jar docs/bench/DenoiseTime.java ...   (the network's Vector API path)
 *   java ... docs/bench/DenoiseTime.java files COLOR.pfm ALBEDO.pfm NORMAL.pfm [runs=5]
 */
public class DenoiseTime {
    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("files")) {
            Image color = PfmReader.read(Path.of(args[1]));
            int runs = args.length > 4 ? Integer.parseInt(args[4]) : 5;
            Image noVariance = new Image(color.width(), color.height(), new float[color.rgb().length]);   // the network does not use it
            time(new RenderBuffers(color, noVariance, PfmReader.read(Path.of(args[2])), PfmReader.read(Path.of(args[3])), null),
                    Denoiser.create(), "network", runs, args[1]);
            return;
        }
        int size = args.length > 0 ? Integer.parseInt(args[0]) : 512;
        int spp = args.length > 1 ? Integer.parseInt(args[1]) : 16;
        int runs = args.length > 2 ? Integer.parseInt(args[2]) : 9;
        String kind = args.length > 3 ? args[3] : "network";
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        RenderSettings settings = RenderSettings.defaults().withSize(size, size).withSamplesPerPixel(spp)
                .withAovs(EnumSet.allOf(Aov.class));
        RenderBuffers buffers;
        try (RenderJob job = RenderJob.start(scene, settings)) {
            buffers = job.awaitBuffers();
        }
        Denoiser denoiser = kind.equals("atrous") ? Denoiser.atrous() : Denoiser.create();
        time(buffers, denoiser, kind, runs, String.format(Locale.ROOT, "%d spp, all feature buffers", spp));
    }

    private static void time(RenderBuffers buffers, Denoiser denoiser, String kind, int runs, String what) {
        int size = buffers.color().width();
        var os = (com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean();
        long firstCpu = os.getProcessCpuTime();
        long first = System.nanoTime();
        denoiser.denoise(buffers);                  // what render --denoise pays: the weights read, the code compiled
        System.out.printf(Locale.ROOT, "first denoise in this JVM: %.3f s, CPU %.3f s%n", (System.nanoTime() - first) * 1e-9,
                (os.getProcessCpuTime() - firstCpu) * 1e-9);
        for (int i = 0; i < 2; i++) {
            denoiser.denoise(buffers);
        }
        double[] seconds = new double[runs];
        double[] cpu = new double[runs];
        for (int i = 0; i < runs; i++) {
            long c0 = os.getProcessCpuTime();
            long t0 = System.nanoTime();
            denoiser.denoise(buffers);
            seconds[i] = (System.nanoTime() - t0) * 1e-9;
            cpu[i] = (os.getProcessCpuTime() - c0) * 1e-9;
        }
        Arrays.sort(seconds);
        Arrays.sort(cpu);
        boolean lanes = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent() && !"false".equals(System.getProperty("strahl.simd"));
        System.out.printf(Locale.ROOT, "%s%s, %dx%d (%s), %d processors: median %.3f s, min %.3f s, max %.3f s over %d runs%n",
                denoiser, kind.equals("atrous") ? "" : lanes ? " (Vector API)" : " (scalar)", size, buffers.color().height(), what,
                Runtime.getRuntime().availableProcessors(), seconds[runs / 2], seconds[0], seconds[runs - 1], runs);
        System.out.printf(Locale.ROOT, "  CPU time of the process per denoise: median %.3f s, min %.3f s, max %.3f s; load average %s%n",
                cpu[runs / 2], cpu[0], cpu[runs - 1], String.format(Locale.ROOT, "%.2f", os.getSystemLoadAverage()));
    }
}
