package dev.strahl.viewer;

import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.Aov;
import dev.strahl.render.Denoiser;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

/**
 * What taking the pass buffers and denoising in the viewer cost the render (docs/viewer.md, Measured): the
 * 512x512 Cornell Box, interleaved rounds; each run prints its time, the time spent in the listener
 * (the copies, while the workers wait) and the CPU time of the render threads and of the denoiser.
 * It is in the viewer's package (it feeds a LiveDenoiser as the controller does), so compile it
 * against the jar rather than running it as a source file:
 *
 *   javac -cp target/strahl.jar -d /tmp/dc docs/showcase/DenoiseCost.java
 *   java -cp target/strahl.jar:/tmp/dc dev.strahl.viewer.DenoiseCost 16 3 aovs:1,snap:1,denoise:1,plain:1,aovs:0,snap:0
 *
 * Arguments: spp, rounds, and the runs of a round as mode:passSize (0 = render's automatic passes); modes:
 * plain (no feature buffers), aovs (all three), snap (aovs + snapshotBuffers() at every pass), denoise (aovs + LiveDenoiser).
 */
public class DenoiseCost {
    static Scene scene;

    public static void main(String[] args) throws Exception {
        scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        int spp = Integer.parseInt(args[0]);
        int rounds = Integer.parseInt(args[1]);
        String[] modes = args[2].split(",");
        run("warmup", "aovs", 4, 1);
        for (int r = 0; r < rounds; r++) {
            for (String m : modes) {
                String[] mp = m.split(":");
                run("round " + r, mp[0], spp, Integer.parseInt(mp[1]));
            }
        }
        // the copy and the denoise alone
        RenderSettings s = RenderSettings.defaults().withSize(512, 512).withSamplesPerPixel(4).withSeed(1).withAovs(EnumSet.allOf(Aov.class));
        try (RenderJob job = RenderJob.start(scene, s)) {
            RenderBuffers b = job.awaitBuffers();
            for (int i = 0; i < 8; i++) {
                long t0 = System.nanoTime();
                job.snapshotBuffers();
                long t1 = System.nanoTime();
                Denoiser.create().denoise(b);
                long t2 = System.nanoTime();
                System.out.printf(Locale.ROOT, "copy %.1f ms, denoise %.0f ms%n", (t1 - t0) * 1e-6, (t2 - t1) * 1e-6);
            }
        }
    }

    static final ThreadMXBean MX = ManagementFactory.getThreadMXBean();

    /** CPU time of the live threads whose names start with one of the prefixes. */
    static long cpu(String... prefixes) {
        long sum = 0;
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            for (String p : prefixes) {
                if (t.getName().startsWith(p)) {
                    long c = MX.getThreadCpuTime(t.getId());
                    sum += Math.max(0, c);
                }
            }
        }
        return sum;
    }

    /** mode: plain (no aovs), aovs, snap (aovs + snapshotBuffers at every pass), denoise (aovs + the viewer's LiveDenoiser). */
    static void run(String label, String mode, int spp, int passSize) throws Exception {
        RenderSettings s = RenderSettings.defaults().withSize(512, 512).withSamplesPerPixel(spp).withSeed(1);
        if (passSize > 0) {
            s = s.withSamplesPerPass(passSize);
        }
        if (!mode.equals("plain")) {
            s = s.withAovs(EnumSet.allOf(Aov.class));
        }
        AtomicReference<RenderJob> ref = new AtomicReference<>();
        CountDownLatch started = new CountDownLatch(1);
        AtomicLong copyNanos = new AtomicLong();
        AtomicLong copyCpu = new AtomicLong();
        AtomicLong renderCpu = new AtomicLong();
        long denoiseCpu0 = cpu("ForkJoinPool.commonPool", "strahl-viewer-denoise");
        FramePresenter presenter = new FramePresenter();
        LiveDenoiser denoiser = LiveDenoiser.of(presenter);
        denoiser.setEnabled(true, false);
        RenderListener l = new RenderListener() {
            @Override
            public void passFinished(RenderStats soFar, Image image) {
                try {
                    started.await();
                } catch (InterruptedException e) {
                    return;
                }
                long t0 = System.nanoTime();
                long c0 = MX.getCurrentThreadCpuTime();
                if (mode.equals("snap")) {
                    ref.get().snapshotBuffers().orElseThrow();
                } else if (mode.equals("denoise")) {
                    denoiser.accept(new RenderController.Frame(image, soFar.samplesPerPixel(), false, 1, ref.get()::snapshotBuffers));
                }
                copyNanos.addAndGet(System.nanoTime() - t0);
                copyCpu.addAndGet(MX.getCurrentThreadCpuTime() - c0);
                renderCpu.set(cpu("strahl-render"));
            }
        };
        RenderStats st;
        try (RenderJob job = RenderJob.start(scene, s, l)) {
            ref.set(job);
            started.countDown();
            st = job.awaitStats();
        }
        // only the denoise runs use those threads; elsewhere an idle pool thread that ended would make the difference negative
        long denoiseCpu = mode.equals("denoise") ? cpu("ForkJoinPool.commonPool", "strahl-viewer-denoise") - denoiseCpu0 : 0;
        Thread.sleep(300);
        System.out.printf(Locale.ROOT, "%s %-8s pass %d: %.2f s, %.3f M samples/s, in listener %.0f ms (%.1f %% of the time; cpu %.0f ms),"
                + " render cpu %.1f s, denoiser cpu %.1f s (%.1f %% of the render's), denoised %d%n", label, mode,
                passSize, st.seconds(), st.samples() / st.seconds() * 1e-6, copyNanos.get() * 1e-6, 100 * copyNanos.get() * 1e-9 / st.seconds(),
                copyCpu.get() * 1e-6, renderCpu.get() * 1e-9, denoiseCpu * 1e-9, 100.0 * denoiseCpu / renderCpu.get(), denoiser.denoisedCount());
        denoiser.close();
        presenter.close();
    }
}
