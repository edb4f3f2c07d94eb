package dev.strahl.scene;

import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Ray;
import dev.strahl.integrator.Shading;
import dev.strahl.integrator.Tracer;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * What {@link Scene#focusDistance} finds (the viewer's Ctrl+click): the first surface the pinhole ray through the clicked point hits,
 * found as the renderer finds it (the tracer, so an alpha cut-out's cut-away parts and a medium's
 * invisible boundaries are passed through, as the camera sees them), and its distance along the camera's viewing direction (the thin
 * lens's focus distance that makes that point sharp).
 */
final class FocusPicker {
    private FocusPicker() {
    }

    /**
     * @param fx the clicked point's x as a fraction of the image width, 0 at the left
     * @param fy its y as a fraction of the height, 0 at the top
     * @param aspect the image's width / height
     * @return the focus distance, or NaN if the ray hits nothing
     */
    static double focusDistance(Scene scene, Camera camera, double fx, double fy, double aspect) {
        int height = 1000;
        int width = Math.max(1, (int) Math.round(height * aspect));
        CameraRays rays = CameraRays.pinholeOf(camera, width, height);
        Ray ray = new Ray();
        rays.generate(fx * width, fy * height, ray);
        World world = World.of(scene);
        Shading s = new Shading();
        Tracer tracer = new Tracer(world, Shading.bsdfs(world, false), false);
        Vector3d origin = new Vector3d(ray.o);
        for (int pass = 0; ; pass++) {
            if (pass > 1000 || tracer.trace(ray, s) < 0) {
                return Double.NaN;
            }
            if (!world.media().isInvisible(s.sp.material)) {
                break;
            }
            s.spawn(ray, new Vector3d(ray.d));           // a medium's invisible boundary: look through it
        }
        ray.o.set(origin);
        double fxDir = camera.lookAt().x() - camera.lookFrom().x();
        double fyDir = camera.lookAt().y() - camera.lookFrom().y();
        double fzDir = camera.lookAt().z() - camera.lookFrom().z();
        double len = Math.sqrt(fxDir * fxDir + fyDir * fyDir + fzDir * fzDir);
        double along = ((s.sp.p.x - ray.o.x) * fxDir + (s.sp.p.y - ray.o.y) * fyDir + (s.sp.p.z - ray.o.z) * fzDir) / len;
        return along > 0 ? along : Double.NaN;
    }
}
