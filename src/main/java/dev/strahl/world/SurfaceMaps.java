package dev.strahl.world;

import dev.strahl.geometry.SurfacePoint;
import dev.strahl.color.MutableRgb;
import dev.strahl.texture.TextureLookup;
import org.joml.Vector2dc;
import org.joml.Vector3d;

/**
 * What a material changes about its surface beyond scattering and emission: a tangent-space
 * normal map and an alpha cut-out. Either may be absent (null); a material with neither has no
 * {@code SurfaceMaps} at all (the world's table holds null), so shading and tracing pay one null
 * test for it.
 *
 * @param normal      linear RGB texels n = 2·rgb − 1 in the tangent frame (x along dp/du, y along
 *                    the bitangent, z the shading normal), as glTF's normalTexture; or null
 * @param normalScale glTF's normalTexture.scale: multiplies x and y before normalising
 * @param alpha       the surface is absent where alpha(u, v) &lt; {@code cutoff}; or null
 * @param cutoff      the threshold
 */
public record SurfaceMaps(TextureLookup normal, double normalScale, TextureLookup alpha, double cutoff) {

    /** Checks the numbers. */
    public SurfaceMaps {
        if (!Double.isFinite(normalScale) || !Double.isFinite(cutoff)) {
            throw new IllegalArgumentException("normal map scale and alpha cutoff must be finite, got " + normalScale + ", " + cutoff);
        }
    }

    /**
     * Tilts the shading normal {@code sp.n} by the normal map at {@code sp.uv}. The tangent frame
     * is MikkTSpace's, per triangle: t = dp/du made orthogonal to n (Gram–Schmidt), bitangent
     * b = sign · (n × t) with the mapping's handedness {@code sp.tangentSign}; the map's texel
     * gives m = ((2r − 1)·scale, (2g − 1)·scale, 2b − 1) and n' = normalise(m.x t + m.y b + m.z n).
     * Leaves n as it is where m.x = m.y = 0 (a flat map changes no bit), where dp/du is parallel
     * to n, and where n' would lie on the other side of the geometric normal than n does (a map
     * that tilts the normal below the surface). Allocates nothing: {@code texel} and {@code t} are
     * the caller's scratch.
     */
    public void tiltNormal(SurfacePoint sp, MutableRgb texel, Vector3d t) {
        normal.rgb(sp.uv.x, sp.uv.y, texel);
        double mx = (2 * texel.r - 1) * normalScale, my = (2 * texel.g - 1) * normalScale, mz = 2 * texel.b - 1;
        if (mx == 0 && my == 0) {
            return;
        }
        Vector3d n = sp.n;
        t.set(sp.dpdu).fma(-n.dot(sp.dpdu), n);
        double len = t.length();
        if (!(len > 1e-12 * sp.dpdu.length()) || !Double.isFinite(len)) {
            return;
        }
        t.div(len);
        double sign = sp.tangentSign;
        // b = sign · (n × t)
        double bx = sign * (n.y * t.z - n.z * t.y), by = sign * (n.z * t.x - n.x * t.z), bz = sign * (n.x * t.y - n.y * t.x);
        double x = mx * t.x + my * bx + mz * n.x, y = mx * t.y + my * by + mz * n.y, z = mx * t.z + my * bz + mz * n.z;
        double l = Math.sqrt(x * x + y * y + z * z);
        if (!(l > 0) || !Double.isFinite(l)) {
            return;
        }
        x /= l;
        y /= l;
        z /= l;
        double before = n.dot(sp.ng), after = x * sp.ng.x + y * sp.ng.y + z * sp.ng.z;
        if (after * before <= 0) {
            return;
        }
        n.set(x, y, z);
    }

    /** Whether the surface is absent at (u, v): an alpha cut-out there. */
    public boolean cutAway(Vector2dc uv) {
        return alpha != null && alpha.value(uv.x(), uv.y()) < cutoff;
    }
}
