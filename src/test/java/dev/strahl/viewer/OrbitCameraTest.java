package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.Camera;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;

class OrbitCameraTest {
    /** The Cornell Box camera. */
    static final Camera CORNELL = new Camera(new Vector3d(0, 1, 3.9), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40);
    /** A tilted camera with an unnormalised up vector that is not perpendicular to the view. */
    static final Camera TILTED = new Camera(new Vector3d(2, 3, -1), new Vector3d(0.5, -0.2, 0.3), new Vector3d(0.1, 2, 0.3), 55);

    private static void assertClose(Vector3dc actual, Vector3dc expected, double eps) {
        assertThat(actual.distance(expected)).as("%s vs %s", actual, expected).isLessThanOrEqualTo(eps);
    }

    @Test
    void startsExactlyAtTheSceneCamera() {
        for (Camera c : new Camera[] {CORNELL, TILTED}) {
            Camera back = OrbitCamera.of(c).toCamera();
            assertClose(back.lookFrom(), c.lookFrom(), 1e-12);
            assertClose(back.lookAt(), c.lookAt(), 0);
            assertThat(back.fovDegrees()).isEqualTo(c.fovDegrees());
        }
    }

    @Test
    void orbitKeepsTheDistanceToTheTargetAndTheTarget() {
        SplittableRandom rnd = new SplittableRandom(5);
        for (Camera c : new Camera[] {CORNELL, TILTED}) {
            OrbitCamera o = OrbitCamera.of(c);
            double d = c.lookFrom().distance(c.lookAt());
            for (int i = 0; i < 1000; i++) {
                o = o.orbit(rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1));
                assertThat(o.eye().distance(o.target())).isCloseTo(d, within(1e-9 * d));
                assertClose(o.target(), c.lookAt(), 0);
                o.toCamera();                // a valid camera every time: never looks along the up vector
            }
        }
    }

    @Test
    void orbitTurnsAboutTheUpAxisAndAFullTurnComesBack() {
        OrbitCamera o = OrbitCamera.of(CORNELL);
        Vector3d quarter = o.orbit(Math.PI / 2, 0).eye();
        assertClose(quarter, new Vector3d(3.9, 1, 0), 1e-12);          // +90° yaw: from +z to +x, same height
        assertClose(o.orbit(2 * Math.PI, 0).eye(), o.eye(), 1e-12);
        assertThat(o.orbit(0, 0.3).eye().y).as("positive pitch raises the camera").isGreaterThan(1);
    }

    @Test
    void pitchStopsShortOfThePoles() {
        OrbitCamera o = OrbitCamera.of(CORNELL).orbit(0, 10);
        assertThat(o.pitch()).isCloseTo(Math.toRadians(OrbitCamera.MAX_PITCH_DEGREES), within(1e-12));
        assertThat(OrbitCamera.of(CORNELL).orbit(0, -10).pitch()).isCloseTo(-Math.toRadians(OrbitCamera.MAX_PITCH_DEGREES), within(1e-12));
        o.toCamera();
    }

    @Test
    void panMovesCameraAndTargetByTheSameVectorInTheImagePlane() {
        for (Camera c : new Camera[] {CORNELL, TILTED}) {
            OrbitCamera o = OrbitCamera.of(c).orbit(0.4, 0.2);
            OrbitCamera p = o.pan(0.25, -0.1);
            Vector3d eyeMove = p.eye().sub(o.eye());
            Vector3d targetMove = new Vector3d(p.target()).sub(o.target());
            assertClose(eyeMove, targetMove, 1e-12);
            Vector3d view = new Vector3d(o.target()).sub(o.eye()).normalize();
            assertThat(eyeMove.dot(view)).as("no movement along the view").isCloseTo(0, within(1e-12));
            double visibleHeight = 2 * o.distance() * Math.tan(Math.toRadians(c.fovDegrees()) / 2);
            assertThat(eyeMove.length()).isCloseTo(visibleHeight * Math.hypot(0.25, 0.1), within(1e-12));
            assertThat(p.distance()).isEqualTo(o.distance());
        }
    }

    @Test
    void panRightMovesTheCameraToItsRight() {
        OrbitCamera p = OrbitCamera.of(CORNELL).pan(0.5, 0.5);
        assertThat(p.eye().x).isGreaterThan(0);       // the Cornell camera looks down -z: its right is +x
        assertThat(p.eye().y).isGreaterThan(1);
    }

    @Test
    void dollyScalesTheDistanceAndNeverReachesOrCrossesTheTarget() {
        OrbitCamera o = OrbitCamera.of(CORNELL);
        assertThat(o.dolly(0.5).distance()).isCloseTo(1.95, within(1e-12));
        assertThat(o.dolly(0.5).eye().z).isCloseTo(1.95, within(1e-12));
        for (int i = 0; i < 200; i++) {
            o = o.dolly(0.1);
            assertThat(o.eye().z).as("the camera stays in front of the target").isGreaterThan(0);
            o.toCamera();
        }
        assertThat(o.distance()).isCloseTo(3.9 * OrbitCamera.MIN_DISTANCE_FACTOR, within(1e-12));
        for (int i = 0; i < 200; i++) {
            o = o.dolly(10);
        }
        assertThat(o.distance()).isCloseTo(3.9 * OrbitCamera.MAX_DISTANCE_FACTOR, within(1e-9));
        assertThatThrownBy(() -> OrbitCamera.of(CORNELL).dolly(0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> OrbitCamera.of(CORNELL).dolly(-2)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void cameraLookingStraightDownCanBeOrbited() {
        Camera down = new Camera(new Vector3d(0, 5, 0), new Vector3d(0, 0, 0), new Vector3d(0, 0, -1), 40);
        OrbitCamera o = OrbitCamera.of(down).orbit(0.5, -0.3);
        assertThat(o.eye().distance(new Vector3d())).isCloseTo(5, within(1e-12));
        o.toCamera();
    }
}
