package dev.strahl.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Sphere;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class TransformTest {
    private static final TriangleMesh TRI = new TriangleMesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2},
            new float[] {0, 0, 1, 0, 0, 1, Float.NaN, Float.NaN, Float.NaN});

    @Test
    void stepsApplyInTheOrderGiven() {
        Vector3d p = Transform.scaling(2).rotate(90, 0, 0, 1).translate(10, 0, 0).applyToPoint(new Vector3d(1, 0, 0), new Vector3d());
        // (1,0,0) -> scale (2,0,0) -> rotate 90° about z (0,2,0) -> translate (10,2,0)
        assertThat(new double[] {p.x, p.y, p.z}).containsExactly(new double[] {10, 2, 0}, within(1e-12));
        Vector3d q = Transform.translation(10, 0, 0).scale(2).applyToPoint(new Vector3d(1, 0, 0), new Vector3d());
        assertThat(q.x).isCloseTo(22, within(1e-12));
    }

    @Test
    void rotationAxesOfAnyLengthGiveTheSameRotation() {
        Vector3d expected = Transform.rotation(90, 0, 1, 0).applyToPoint(new Vector3d(1, 0, 0), new Vector3d());
        for (double length : new double[] {1e-200, 1e200}) {     // their squared lengths under- and overflow
            Vector3d p = Transform.rotation(90, 0, length, 0).applyToPoint(new Vector3d(1, 0, 0), new Vector3d());
            assertThat(new double[] {p.x, p.y, p.z}).containsExactly(new double[] {expected.x, expected.y, expected.z}, within(1e-12));
        }
    }

    @Test
    void stepsThatOverflowAndVerticesMovedBeyondFloatsAreRefused() {
        assertThatThrownBy(() -> Transform.scaling(1e200).scale(1e200)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("beyond the range of numbers");
        assertThatThrownBy(() -> Transform.scaling(1e39).apply(TRI)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("the transform moves vertex 2 (1.0, 0.0, 0.0) to (1.00e+39, 0.00, 0.00), beyond the range of float coordinates");
    }

    @Test
    void rotationIsCounterClockwiseLookingDownTheAxis() {
        Vector3d p = Transform.rotation(90, 0, 1, 0).applyToPoint(new Vector3d(1, 0, 0), new Vector3d());
        assertThat(new double[] {p.x, p.y, p.z}).containsExactly(new double[] {0, 0, -1}, within(1e-12));
    }

    @Test
    void meshNormalsUseTheInverseTransposeAndVerticesWithoutNormalKeepNone() {
        // shear-free but non-uniform: a normal (1,1,0)/√2 of the plane x + y = c under scale (2,1,1) becomes ∝ (1/2, 1, 0)
        TriangleMesh m = new TriangleMesh(new float[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, new int[] {0, 1, 2},
                new float[] {0.70710677f, 0.70710677f, 0, 0, 0, 1, Float.NaN, Float.NaN, Float.NaN});
        TriangleMesh t = Transform.IDENTITY.scale(2, 1, 1).apply(m);
        float[] n = t.normals();
        assertThat(n[0] / n[1]).isCloseTo(0.5f, within(1e-6f));
        assertThat(Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])).isCloseTo(1, within(1e-6));
        assertThat(n[6]).isNaN();
        assertThat(t.positions()).containsExactly(2, 0, 0, 0, 1, 0, 0, 0, 1);
    }

    @Test
    void aMirroringTransformReversesTheWindingSoTheGeometricNormalFollowsTheSurface() {
        TriangleMesh mirrored = Transform.IDENTITY.scale(1, 1, -1).apply(TRI);
        assertThat(mirrored.indices()).containsExactly(0, 2, 1);
        assertThat(Transform.scaling(3).apply(TRI).indices()).containsExactly(0, 1, 2);
        assertThat(Transform.IDENTITY.apply(TRI)).isSameAs(TRI);
    }

    @Test
    void spheresTakeSimilaritiesAndRefuseUnequalScales() {
        Sphere s = Transform.scaling(2).rotate(33, 1, 2, 3).translate(0, 1, 0).apply(new Sphere(new Vector3d(1, 0, 0), 0.5));
        assertThat(s.radius()).isCloseTo(1, within(1e-12));
        assertThat(new Vector3d(s.center()).sub(0, 1, 0).length()).isCloseTo(2, within(1e-9));   // |(2,0,0) rotated| = 2, then +y
        assertThatThrownBy(() -> Transform.IDENTITY.scale(1, 2, 1).apply(new Sphere(new Vector3d(), 1)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("scales its axes by 1.0, 2.0 and 1.0");
        assertThat(Transform.IDENTITY.scale(-2).apply(new Sphere(new Vector3d(1, 0, 0), 1)).radius()).isEqualTo(2);
    }

    @Test
    void degenerateStepsAreRefused() {
        assertThatThrownBy(() -> Transform.scaling(0)).hasMessageContaining("must not be zero");
        assertThatThrownBy(() -> Transform.rotation(10, 0, 0, 0)).hasMessageContaining("axis must not be zero");
        assertThatThrownBy(() -> Transform.translation(Double.NaN, 0, 0)).hasMessageContaining("must be finite");
    }

    @Test
    void equalityIsByStepsAndIdentityIsRecognised() {
        assertThat(Transform.translation(1, 2, 3)).isEqualTo(Transform.IDENTITY.translate(1, 2, 3)).isNotEqualTo(Transform.IDENTITY);
        assertThat(Transform.rotation(360, 0, 1, 0).isIdentity()).isFalse();       // round-off: not exactly
        assertThat(Transform.translation(1, 0, 0).translate(-1, 0, 0).isIdentity()).isTrue();
    }
}
