"""Single-scattering albedo of a GGX microfacet reflector with F = 1 (separable Smith G), by midpoint
quadrature over the hemisphere of wi. Checks strahl's Conductor (ConductorTest).

Run: python3 docs/anchors/ggx_albedo.py     (numpy only)
"""
import numpy as np


def d(mz, a):
    a2 = a * a
    t = mz * mz * (a2 - 1) + 1
    return np.where(mz > 0, a2 / (np.pi * t * t), 0)


def g1(z, a):
    c2 = z * z
    s2 = np.maximum(0, 1 - c2)
    return 1 / (1 + (np.sqrt(1 + a * a * s2 / c2) - 1) / 2)


def albedo(theta_o_deg, a, n=800):
    to = np.radians(theta_o_deg) + 1e-12
    wo = np.array([np.sin(to), 0, np.cos(to)])
    ti = (np.arange(n) + 0.5) / n * np.pi / 2
    pi = (np.arange(2 * n) + 0.5) / (2 * n) * 2 * np.pi
    t, p = np.meshgrid(ti, pi, indexing="ij")
    wi = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], -1)
    h = wi + wo
    h /= np.linalg.norm(h, axis=-1, keepdims=True)
    f = d(h[..., 2], a) * g1(wo[2], a) * g1(wi[..., 2], a) / (4 * wo[2] * wi[..., 2])
    dw = np.sin(t) * (np.pi / 2 / n) * (2 * np.pi / (2 * n))
    return float(np.sum(f * wi[..., 2] * dw))


if __name__ == "__main__":
    for theta in (0, 30, 60):
        for a in (0.1, 0.5, 1.0):
            print(f"theta_o = {theta:2d} deg, alpha = {a}: albedo = {albedo(theta, a):.5f}")
