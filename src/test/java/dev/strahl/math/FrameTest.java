package dev.strahl.math;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;

/**
 * The shading frame (Duff et al. 2017) must be an orthonormal, right-handed basis (s, t, n) for
 * every unit normal, including the poles where the branchless construction switches sign and
 * normals just beside them, where the older Frisvad construction lost all precision.
 */
class FrameTest {
    private static final double EPS = 1e-12;

    /** Random unit normals, the axes, both poles, signed zeros and normals within 1e-16 .. 1e-2 of a pole. */
    private static List<Vector3d> normals() {
        List<Vector3d> list = new ArrayList<>();
        list.add(new Vector3d(0, 0, 1));
        list.add(new Vector3d(0, 0, -1));
        list.add(new Vector3d(-0.0, -0.0, -1));
        list.add(new Vector3d(1, 0, 0));
        list.add(new Vector3d(0, 1, 0));
        list.add(new Vector3d(-1, 0, 0));
        list.add(new Vector3d(0, -1, 0));
        list.add(new Vector3d(1, 0, -0.0));   // nz = -0.0 takes the negative branch
        list.add(new Vector3d(0, 1, -0.0));
        for (double e : new double[] {1e-16, 1e-12, 1e-8, 1e-6, 1e-4, 1e-2}) {
            for (double sign : new double[] {1, -1}) {
                list.add(new Vector3d(e, 0, sign).normalize());
                list.add(new Vector3d(0, -e, sign).normalize());
                list.add(new Vector3d(e, e, sign).normalize());
                list.add(new Vector3d(-e, 0.5 * e, sign * Math.sqrt(1 - 1.25 * e * e)));
            }
        }
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < 10_000; i++) {
            list.add(new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize());
        }
        return list;
    }

    private static Vector3d axis(Frame frame, double x, double y, double z) {
        return frame.toWorld(new Vector3d(x, y, z), new Vector3d());
    }

    @Test
    void basisIsOrthonormalAndRightHanded() {
        Frame frame = new Frame();
        for (Vector3d n : normals()) {
            frame.set(n);
            Vector3d s = axis(frame, 1, 0, 0), t = axis(frame, 0, 1, 0), z = axis(frame, 0, 0, 1);
            String at = "n = " + n;
            assertThat(s.length()).as("|s|, %s", at).isCloseTo(1, within(EPS));
            assertThat(t.length()).as("|t|, %s", at).isCloseTo(1, within(EPS));
            assertThat(s.dot(t)).as("s·t, %s", at).isCloseTo(0, within(EPS));
            assertThat(s.dot(n)).as("s·n, %s", at).isCloseTo(0, within(EPS));
            assertThat(t.dot(n)).as("t·n, %s", at).isCloseTo(0, within(EPS));
            assertThat(z.distance(n)).as("third axis is n, %s", at).isLessThan(EPS);
            assertThat(s.cross(t, new Vector3d()).distance(n)).as("s × t = n (right-handed), %s", at).isLessThan(EPS);
        }
    }

    @Test
    void normalMapsToLocalZ() {
        Frame frame = new Frame();
        for (Vector3d n : normals()) {
            Vector3d local = frame.set(n).toLocal(n, new Vector3d());
            assertThat(local.distance(0, 0, 1)).as("toLocal(n) for n = %s: %s", n, local).isLessThan(EPS);
        }
    }

    @Test
    void toLocalAndToWorldAreInverse() {
        Frame frame = new Frame();
        SplittableRandom random = new SplittableRandom(6);
        Vector3d local = new Vector3d(), back = new Vector3d();
        for (Vector3d n : normals()) {
            frame.set(n);
            Vector3d w = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            frame.toWorld(frame.toLocal(w, local), back);
            assertThat(back.distance(w)).as("toWorld(toLocal(w)), n = %s", n).isLessThan(EPS * (1 + w.length()));
            frame.toLocal(frame.toWorld(w, local), back);
            assertThat(back.distance(w)).as("toLocal(toWorld(w)), n = %s", n).isLessThan(EPS * (1 + w.length()));
            assertThat(local.length()).as("lengths are kept").isCloseTo(w.length(), within(EPS * (1 + w.length())));
        }
    }

    @Test
    void destMayBeTheInput() {
        Frame frame = new Frame().set(new Vector3d(1, 2, 3).normalize());
        Vector3dc w = new Vector3d(0.3, -0.4, 0.5);
        Vector3d expected = frame.toLocal(w, new Vector3d());
        Vector3d inPlace = new Vector3d(w);
        assertThat(frame.toLocal(inPlace, inPlace)).isEqualTo(expected);
        assertThat(frame.toWorld(inPlace, inPlace).distance(w)).isLessThan(EPS);
    }

    @Test
    void setFromComponentsEqualsSetFromVector() {
        Vector3d n = new Vector3d(-0.2, 0.9, 0.3).normalize();
        Vector3d w = new Vector3d(0.1, 0.2, 0.3);
        Vector3d a = new Frame().set(n).toLocal(w, new Vector3d());
        Vector3d b = new Frame().set(n.x, n.y, n.z).toLocal(w, new Vector3d());
        assertThat(a).isEqualTo(b);
    }
}
