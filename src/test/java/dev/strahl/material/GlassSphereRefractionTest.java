package dev.strahl.material;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.math.Frame;
import org.joml.Vector3d;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A ray refracted into a glass sphere and out again leaves where Snell's law says. For a ray
 * parallel to the z axis at height h above the axis of a unit sphere: it enters at incidence
 * θ1 = asin(h), refracts to θ2 = asin(h/η), crosses a chord of length 2·cosθ2 and leaves at the
 * same angles, deviated in total by 2(θ1 − θ2) towards the axis.
 */
class GlassSphereRefractionTest {

    @ParameterizedTest(name = "h = {0}, eta = {1}")
    @CsvSource({"0.3, 1.5", "0.7, 1.5", "0.5, 2.5", "0.9, 1.33"})
    void rayThroughASphereLeavesWhereSnellsLawSays(double h, double eta) {
        Geometry geometry = new MeshGeometry().addSphere(new Vector3d(), 1, 0).build();
        Dielectric glass = new Dielectric(eta);
        Ray ray = new Ray();
        ray.o.set(0, h, -5);
        ray.d.set(0, 0, 1);
        ray.tMax = Double.POSITIVE_INFINITY;
        Vector3d exitPoint = new Vector3d();
        for (int crossing = 0; crossing < 2; crossing++) {
            Hit hit = new Hit().reset();
            assertThat(geometry.intersect(0, ray, hit, false)).isTrue();
            SurfacePoint sp = new SurfacePoint();
            geometry.surface(ray, hit, sp);
            exitPoint.set(sp.p);
            Frame frame = new Frame().set(sp.n);
            Vector3d wo = frame.toLocal(new Vector3d(ray.d).negate(), new Vector3d());
            BsdfSample bs = new BsdfSample();
            // uc just below 1 picks transmission whenever it is possible.
            assertThat(glass.sample(wo, Math.nextDown(1.0), 0.5, 0.5, bs)).isTrue();
            assertThat(bs.wi.z * wo.z).as("transmitted, not reflected").isNegative();
            Vector3d wi = frame.toWorld(bs.wi, new Vector3d());
            sp.spawnOrigin(wi, ray.o);
            ray.d.set(wi);
            ray.tMax = Double.POSITIVE_INFINITY;
        }
        double theta1 = Math.asin(h);
        double theta2 = Math.asin(h / eta);
        double deviation = 2 * (theta1 - theta2);
        // Exit point: rotate the entry point's polar angle by π − 2θ2 about the x axis.
        double entryAngle = Math.atan2(h, -Math.sqrt(1 - h * h));          // angle in the (z, y) plane
        double exitAngle = entryAngle - (Math.PI - 2 * theta2);
        assertThat(exitPoint.z).isCloseTo(Math.cos(exitAngle), within(1e-5));
        assertThat(exitPoint.y).isCloseTo(Math.sin(exitAngle), within(1e-5));
        // Direction: deviated by 2(θ1 − θ2) towards the axis (downwards for h > 0). The tolerances
        // allow for the 1e-6 offset of spawned rays, which moves the exit point that much.
        assertThat(ray.d.z).isCloseTo(Math.cos(deviation), within(1e-5));
        assertThat(ray.d.y).isCloseTo(-Math.sin(deviation), within(1e-5));
        assertThat(ray.d.x).isCloseTo(0, within(1e-12));
    }
}
