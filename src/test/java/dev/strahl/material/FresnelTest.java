package dev.strahl.material;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Fresnel reflectance and Snell refraction against closed forms from optics, not against the code's own formulas. */
class FresnelTest {
    private static final double[] ETAS = {1.0001, 1.2, 1.33, 1.5, 1.9, 2.42, 1 / 1.5};

    /** Unit direction at polar angle θ (radians) in the xz-plane, azimuth φ = 0, on the side of {@code sign}. */
    private static Vector3d direction(double theta, double sign) {
        return new Vector3d(Math.sin(theta), 0, sign * Math.cos(theta));
    }

    @ParameterizedTest
    @ValueSource(doubles = {1.2, 1.33, 1.5, 2.42, 0.75})
    void normalIncidenceIsSquaredIndexContrast(double eta) {
        double expected = Math.pow((eta - 1) / (eta + 1), 2);
        assertThat(Fresnel.dielectric(1, eta)).isCloseTo(expected, within(1e-15));
        assertThat(Fresnel.dielectric(-1, eta)).as("from inside").isCloseTo(expected, within(1e-15));
    }

    @Test
    void glassReflectsFourPercentAtNormalIncidence() {
        assertThat(Fresnel.dielectric(1, 1.5)).isCloseTo(0.04, within(1e-15));
    }

    /**
     * At Brewster's angle tanθB = η the reflected ray is perpendicular to the refracted one
     * (θi + θt = 90°), r∥ = 0, and with r⊥ = −sin(θi − θt)/sin(θi + θt) = −sin(θi − θt),
     * F = r⊥²/2 = sin²(θi − θt)/2.
     */
    @ParameterizedTest
    @ValueSource(doubles = {1.33, 1.5, 2.42})
    void brewsterAngleReflectsOnlyThePerpendicularPolarisation(double eta) {
        double thetaB = Math.atan(eta);
        double thetaT = Math.PI / 2 - thetaB;
        assertThat(Math.sin(thetaB)).as("Snell holds at θt = 90° − θB").isCloseTo(eta * Math.sin(thetaT), within(1e-15));
        double expected = 0.5 * Math.pow(Math.sin(thetaB - thetaT), 2);
        assertThat(Fresnel.dielectric(Math.cos(thetaB), eta)).isCloseTo(expected, within(1e-14));
        // From inside the Brewster angle is θt, with tanθ = 1/η.
        assertThat(Fresnel.dielectric(-Math.cos(thetaT), eta)).as("from inside").isCloseTo(expected, within(1e-14));
    }

    /** The sine/tangent forms of Fresnel's equations (Born &amp; Wolf §1.5.2), independent of the cosine form coded. */
    @Test
    void matchesFresnelEquationsInSineAndTangentForm() {
        for (double eta : new double[] {1.33, 1.5, 2.42}) {
            for (int k = 1; k < 90; k++) {
                double thetaI = Math.toRadians(k);
                double thetaT = Math.asin(Math.sin(thetaI) / eta);
                double rPerp = -Math.sin(thetaI - thetaT) / Math.sin(thetaI + thetaT);
                double rPar = Math.tan(thetaI - thetaT) / Math.tan(thetaI + thetaT);
                double expected = 0.5 * (rPerp * rPerp + rPar * rPar);
                assertThat(Fresnel.dielectric(Math.cos(thetaI), eta)).as("η = %s, θi = %s°", eta, k)
                        .isCloseTo(expected, within(1e-13));
            }
        }
    }

    @ParameterizedTest
    @ValueSource(doubles = {1.33, 1.5, 2.42})
    void totalInternalReflectionBeyondTheCriticalAngleFromInside(double eta) {
        double critical = Math.asin(1 / eta);
        for (double theta = critical + 1e-9; theta < Math.PI / 2; theta += 0.01) {
            assertThat(Fresnel.dielectric(-Math.cos(theta), eta)).as("θ = %s", theta).isEqualTo(1.0);
            assertThat(Fresnel.refract(direction(theta, -1), eta, new Vector3d())).isFalse();
        }
        assertThat(Fresnel.dielectric(-Math.cos(critical - 1e-3), eta)).as("just inside the critical angle").isLessThan(1);
        assertThat(Fresnel.refract(direction(critical - 1e-3, -1), eta, new Vector3d())).isTrue();
        // From outside there is no total reflection.
        assertThat(Fresnel.dielectric(Math.cos(Math.toRadians(89.9)), eta)).isLessThan(1);
    }

    /** Stokes relations: the reflectance is the same for the two directions of one ray path, F(θ1, η) = F(θ2, 1/η). */
    @Test
    void reflectanceIsTheSameFromInsideAndOutsideAtMatchedAngles() {
        for (double eta : ETAS) {
            for (int k = 0; k < 90; k++) {
                double theta1 = Math.toRadians(k);
                double theta2 = Math.asin(Math.sin(theta1) / eta);
                if (Double.isNaN(theta2)) {
                    continue;
                }
                assertThat(Fresnel.dielectric(-Math.cos(theta2), eta)).as("η = %s, θ1 = %s°", eta, k)
                        .isCloseTo(Fresnel.dielectric(Math.cos(theta1), eta), within(1e-12));
            }
        }
    }

    @Test
    void reflectanceLiesInTheUnitIntervalEverywhere() {
        for (double eta : ETAS) {
            for (int k = 0; k <= 20_000; k++) {
                double cos = -1 + k / 10_000.0;
                double f = Fresnel.dielectric(cos, eta);
                assertThat(f).as("η = %s, cosθ = %s", eta, cos).isBetween(0.0, 1.0);
            }
            assertThat(Fresnel.dielectric(2, eta)).as("cosθ is clamped").isBetween(0.0, 1.0);
        }
    }

    @Test
    void matchedIndexReflectsNothing() {
        for (int k = 0; k < 90; k++) {
            assertThat(Fresnel.dielectric(Math.cos(Math.toRadians(k)), 1.0)).isCloseTo(0, within(1e-15));
        }
    }

    @Test
    void reflectMirrorsAboutTheNormal() {
        Vector3d w = new Vector3d(0.3, -0.4, Math.sqrt(0.75));
        assertThat(Fresnel.reflect(w, new Vector3d())).isEqualTo(new Vector3d(-0.3, 0.4, Math.sqrt(0.75)));
        // General form 2 (n·w) n − w with n = z.
        Vector3d n = new Vector3d(0, 0, 1);
        Vector3d general = new Vector3d(n).mul(2 * n.dot(w)).sub(w);
        assertThat(Fresnel.reflect(w, new Vector3d()).distance(general)).isLessThan(1e-15);
    }

    /** n1 sinθ1 = n2 sinθ2, the refracted ray on the other side, in the plane of incidence, azimuth opposite. */
    @Test
    void refractObeysSnellsLawFromBothSides() {
        Vector3d wt = new Vector3d();
        for (double eta : new double[] {1.33, 1.5, 2.42}) {
            for (int k = 0; k < 90; k++) {
                for (double phi : new double[] {0, 1, 2.5, 4}) {
                    double theta = Math.toRadians(k);
                    for (double side : new double[] {1, -1}) {
                        Vector3d wi = new Vector3d(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), side * Math.cos(theta));
                        double n1 = side > 0 ? 1 : eta, n2 = side > 0 ? eta : 1;
                        if (n1 * Math.sin(theta) / n2 >= 1) {
                            assertThat(Fresnel.refract(wi, eta, wt)).isFalse();
                            continue;
                        }
                        assertThat(Fresnel.refract(wi, eta, wt)).as("η = %s, θ = %s°, side %s", eta, k, side).isTrue();
                        double sinT = Math.hypot(wt.x, wt.y);
                        assertThat(wt.length()).isCloseTo(1, within(1e-14));
                        assertThat(n2 * sinT).as("Snell").isCloseTo(n1 * Math.sin(theta), within(1e-14));
                        assertThat(Math.signum(wt.z)).as("other side").isEqualTo(-side);
                        // Transmitted tangential part is −wi_tangential / η': same plane, opposite azimuth.
                        assertThat(wt.x * wi.y - wt.y * wi.x).as("in the plane of incidence").isCloseTo(0, within(1e-14));
                        assertThat(wt.x * wi.x + wt.y * wi.y).isLessThanOrEqualTo(1e-15);
                        assertThat(Fresnel.relativeEta(wi.z, eta)).isCloseTo(n2 / n1, within(1e-15));
                    }
                }
            }
        }
    }

    @Test
    void refractingTheRefractedDirectionReturnsTheOriginal() {
        Vector3d wt = new Vector3d(), back = new Vector3d();
        for (int k = 0; k < 90; k++) {
            Vector3d wi = direction(Math.toRadians(k), 1).rotateZ(0.7);
            assertThat(Fresnel.refract(wi, 1.5, wt)).isTrue();
            assertThat(Fresnel.refract(wt, 1.5, back)).isTrue();
            assertThat(back.distance(wi)).as("θ = %s°", k).isLessThan(1e-14);
        }
    }
}
