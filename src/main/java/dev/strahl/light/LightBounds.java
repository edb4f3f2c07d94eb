package dev.strahl.light;

import dev.strahl.geometry.Aabb;

/**
 * What the light tree knows of a set of emitters (Conty Estevez &amp; Kulla 2018): where they are
 * (a box), which way they face (a cone of normals around axis w with half-angle θo, each emitting
 * at most θe beyond its normal: θe = π/2 for a Lambertian surface) and how bright they are
 * (φ, the sum of their intensities along their normals, W/sr: area × mean(Le) for a triangle).
 * Mutable; used while the tree is built, then flattened into its node array.
 */
final class LightBounds {
    final Aabb box = new Aabb();
    double wx, wy = 0, wz = 1;
    /** cos θo; +∞ for an empty set (no cone yet). */
    double cosO = Double.POSITIVE_INFINITY;
    /** cos θe, the largest spread of any member. */
    double cosE = 1;
    double phi;

    /** A one-sided emitter facing n (unit) inside {@code box}, spreading θe beyond it. */
    static LightBounds facing(Aabb box, double nx, double ny, double nz, double cosO, double cosE, double phi) {
        LightBounds b = new LightBounds();
        b.box.include(box);
        b.wx = nx;
        b.wy = ny;
        b.wz = nz;
        b.cosO = cosO;
        b.cosE = cosE;
        b.phi = phi;
        return b;
    }

    /** An emitter that emits in every direction (a sphere, a point light): the whole sphere of normals. */
    static LightBounds everyWay(Aabb box, double phi) {
        return facing(box, 0, 0, 1, -1, 0, phi);
    }

    boolean isEmpty() {
        return cosO == Double.POSITIVE_INFINITY;
    }

    /** The centre of the box along an axis (the split coordinate). */
    double centroid(int axis) {
        return 0.5 * (box.min(axis) + box.max(axis));
    }

    /** Grows these bounds to hold {@code b} as well. */
    LightBounds include(LightBounds b) {
        if (b.isEmpty()) {
            return this;
        }
        if (isEmpty()) {
            box.include(b.box);
            wx = b.wx;
            wy = b.wy;
            wz = b.wz;
            cosO = b.cosO;
            cosE = b.cosE;
            phi = b.phi;
            return this;
        }
        box.include(b.box);
        phi += b.phi;
        cosE = Math.min(cosE, b.cosE);
        includeCone(b.wx, b.wy, b.wz, b.cosO);
        return this;
    }

    /**
     * The smallest cone around both this cone and (v, cos θb): if either holds the other, that
     * one; else the half-angle θo = (θa + θd + θb)/2, θd the angle between the axes, and the axis
     * turned from this one towards v by θo − θa in their common plane (Rodrigues' rotation).
     */
    private void includeCone(double vx, double vy, double vz, double cosB) {
        double thetaA = Math.acos(clampCos(cosO)), thetaB = Math.acos(clampCos(cosB));
        double cx = wy * vz - wz * vy, cy = wz * vx - wx * vz, cz = wx * vy - wy * vx;
        double sinD = Math.sqrt(cx * cx + cy * cy + cz * cz);
        double thetaD = Math.atan2(sinD, wx * vx + wy * vy + wz * vz);
        if (Math.min(thetaD + thetaB, Math.PI) <= thetaA) {
            return;
        }
        if (Math.min(thetaD + thetaA, Math.PI) <= thetaB) {
            wx = vx;
            wy = vy;
            wz = vz;
            cosO = cosB;
            return;
        }
        double thetaO = 0.5 * (thetaA + thetaD + thetaB);
        if (thetaO >= Math.PI || sinD == 0) {
            cosO = -1;
            return;
        }
        // k = (w × v)/|w × v| is perpendicular to w, so the rotation is w cos θr + (k × w) sin θr.
        double kx = cx / sinD, ky = cy / sinD, kz = cz / sinD;
        double thetaR = thetaO - thetaA, c = Math.cos(thetaR), s = Math.sin(thetaR);
        double nx = wx * c + (ky * wz - kz * wy) * s;
        double ny = wy * c + (kz * wx - kx * wz) * s;
        double nz = wz * c + (kx * wy - ky * wx) * s;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        wx = nx / len;
        wy = ny / len;
        wz = nz / len;
        cosO = Math.cos(thetaO);
    }

    private static double clampCos(double c) {
        return Math.max(-1, Math.min(1, c));
    }

    /**
     * The measure of the directions these emitters light, M_Ω = 2π(1 − cos θo) + π/2·(2θw sin θo
     * − cos(θo − 2θw) − 2θo sin θo + cos θo) with θw = min(θo + θe, π): the cone itself plus its
     * cosine-weighted fringe (Conty Estevez &amp; Kulla 2018, eq. 1). π for one Lambertian
     * triangle, 2π·(1 + ...) up to 4π for an emitter of every direction.
     */
    double orientationMeasure() {
        double thetaO = Math.acos(clampCos(cosO)), thetaE = Math.acos(clampCos(cosE));
        double thetaW = Math.min(thetaO + thetaE, Math.PI);
        double sinO = Math.sqrt(Math.max(0, 1 - cosO * cosO));
        return 2 * Math.PI * (1 - cosO)
                + Math.PI / 2 * (2 * thetaW * sinO - Math.cos(thetaO - 2 * thetaW) - 2 * thetaO * sinO + cosO);
    }

    /**
     * The split cost of these bounds as one child of a node with box {@code parent} split along
     * {@code axis}: φ · M_Ω · surface area, times the node's longest extent over its extent
     * along the axis (thin slices of a long node cost more; the paper's regularisation).
     */
    double cost(Aabb parent, int axis) {
        if (isEmpty()) {
            return 0;
        }
        double longest = Math.max(parent.extent(0), Math.max(parent.extent(1), parent.extent(2)));
        return phi * orientationMeasure() * box.area() * (longest / parent.extent(axis));
    }
}
