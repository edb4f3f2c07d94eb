package dev.strahl.examples.embed;

import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.io.ImageWriters;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Transform;
import dev.strahl.scene.TriangleMesh;
import java.nio.file.Files;
import java.nio.file.Path;
import org.joml.Vector3d;

/**
 * Builds a small scene in code (a floor, a tilted box, a glass and a mirror sphere, a spherical
 * lamp), renders it with strahl and writes a PNG: {@code java ... Embed out.png}.
 */
public final class Embed {
    private Embed() {}

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args.length > 0 ? args[0] : "embed.png");
        // README:begin
        // A unit cube from flat arrays: 8 corners, 12 triangles wound outwards.
        float[] corners = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
        int[] triangles = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                           3, 6, 2, 3, 7, 6, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
        TriangleMesh cube = new TriangleMesh(corners, triangles, null);

        Scene scene = Scene.builder()
                .addMesh(new TriangleMesh(new float[] {-3, 0, -3, 3, 0, -3, 3, 0, 3, -3, 0, 3}, new int[] {0, 2, 1, 0, 3, 2}, null),
                        Material.diffuse("floor", Rgb.gray(0.7)))
                .addMesh(cube, Material.glossy("red paint", new Rgb(0.6, 0.1, 0.1), Rgb.gray(0.2), 60),
                        Transform.translation(-0.5, 0, -0.5).scale(0.8).rotate(30, 0, 1, 0).translate(-0.9, 0, -0.3))
                .addSphere(new Vector3d(0.15, 0.45, 0.7), 0.45, Material.dielectric("glass", 1.5))
                .addSphere(new Vector3d(1.45, 0.55, -0.5), 0.55, Material.mirror("chrome", Rgb.gray(0.9)))
                .addSphere(new Vector3d(-0.5, 3.2, 1.5), 1, Material.emissive("lamp", Rgb.gray(0.5), new Rgb(8, 7.2, 6)))
                .environment(new Rgb(0.02, 0.03, 0.05))
                .camera(new Camera(new Vector3d(0, 1.4, 4.2), new Vector3d(0, 0.4, 0), new Vector3d(0, 1, 0), 40))
                .build();

        RenderSettings settings = RenderSettings.defaults().withSize(160, 120).withSamplesPerPixel(32).withSeed(1);
        RenderListener progress = new RenderListener() {
            @Override
            public void passFinished(RenderStats soFar, Image image) {
                System.out.printf("pass %d: %d spp, %.0f samples/s%n", soFar.passes(), soFar.samplesPerPixel(), soFar.samplesPerSecond());
            }
        };
        try (RenderJob job = RenderJob.start(scene, settings, progress)) {
            RenderStats stats = job.awaitStats();
            ImageWriters.write(job.snapshot(), out);      // job.snapshot().rgb() gives the linear floats
            System.out.printf("%d spp in %.2f s -> %s%n", stats.samplesPerPixel(), stats.seconds(), out);
        }
        // README:end
        if (!Files.isRegularFile(out) || Files.size(out) < 1000) {
            throw new IllegalStateException("the example did not write " + out);
        }
    }
}
