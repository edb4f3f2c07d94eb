#!/usr/bin/env python3
"""Writes the assets of strahl's participating-media showcase (scenes/media-showcase.json and the
pictures of docs/media.md), every one procedural (no downloaded data):

    python3 docs/showcase/make_media_assets.py [OUTPUT_DIR]      (default: scenes/assets)

Needs numpy only. Deterministic: the same bytes every run.

  smoke.vol   a 28 x 44 x 28 density grid (Mitsuba's VOL version 3, float32, one channel; 138 KB):
              a plume that rises from a narrow base, widens, leans and curls, its density broken up
              by three octaves of value noise and fading out towards the top. Header box
              [-0.5, 0, -0.5] .. [0.5, 1.6, 0.5]; the scenes place it with their own "bounds".
  knot.ply    a (2, 3) torus knot tube, 192 x 16 quads (6144 triangles, binary PLY, with
              the tube's normals for smooth shading), about
              1.2 units across: thick and thin at once, what subsurface scattering shows off on.
"""
import os
import struct
import sys

import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("scenes", "assets")


def lattice(ix, iy, iz, octave):
    """A value in [-1, 1] per lattice point: an integer hash (no generator state)."""
    h = (ix * 73856093) ^ (iy * 19349663) ^ (iz * 83492791) ^ (octave * 2654435761)
    h = (h ^ (h >> 13)) * 1274126177
    h = h ^ (h >> 16)
    return (h & 0xFFFF) / 32767.5 - 1


def value_noise(x, y, z, octave):
    x0, y0, z0 = np.floor(x).astype(np.int64), np.floor(y).astype(np.int64), np.floor(z).astype(np.int64)
    fx, fy, fz = x - x0, y - y0, z - z0
    sx, sy, sz = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy), fz * fz * (3 - 2 * fz)
    out = 0
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                w = (sx if dx else 1 - sx) * (sy if dy else 1 - sy) * (sz if dz else 1 - sz)
                out = out + w * lattice(x0 + dx, y0 + dy, z0 + dz, octave)
    return out


def plume(nx=28, ny=44, nz=28):
    z, y, x = np.meshgrid((np.arange(nz) + 0.5) / nz, (np.arange(ny) + 0.5) / ny, (np.arange(nx) + 0.5) / nx, indexing="ij")
    # the plume's axis leans towards +x and curls as it rises; its radius grows
    cx = 0.5 + 0.18 * y ** 1.5 + 0.05 * np.sin(7 * y)
    cz = 0.5 + 0.06 * np.sin(5 * y + 1)
    radius = 0.1 + 0.35 * y
    r = np.sqrt((x - cx) ** 2 + (z - cz) ** 2) / radius
    envelope = np.clip(1 - r, 0, 1) ** 1.5 * np.clip(1.1 - y, 0, 1) ** 0.7
    noise = sum(0.5 ** o * value_noise(x * 5 * 2 ** o, y * 8 * 2 ** o - 3 * y, z * 5 * 2 ** o, o) for o in range(3))
    density = np.clip(envelope * (0.65 + 0.9 * noise), 0, None)
    return (density / density.max()).astype("<f4")          # z, y, x order: x fastest when flattened


def write_vol(path, grid, lo, hi):
    nz, ny, nx = grid.shape
    with open(path, "wb") as f:
        f.write(b"VOL" + bytes([3]) + struct.pack("<iiiii", 1, nx, ny, nz, 1) + struct.pack("<6f", *lo, *hi))
        f.write(np.ascontiguousarray(grid).tobytes())


def knot(segments=192, sides=16, p=2, q=3, tube=0.13):
    def curve(t):
        r = 0.42 + 0.18 * np.cos(q * t)
        return np.array([r * np.cos(p * t), 0.18 * np.sin(q * t), r * np.sin(p * t)])
    verts = []
    for i in range(segments):
        t = 2 * np.pi * i / segments
        c = curve(t)
        tangent = curve(t + 1e-4) - curve(t - 1e-4)
        tangent /= np.linalg.norm(tangent)
        normal = np.cross(tangent, [0, 1, 0])
        normal /= np.linalg.norm(normal)
        binormal = np.cross(tangent, normal)
        for j in range(sides):
            a = 2 * np.pi * j / sides
            out = np.cos(a) * normal + np.sin(a) * binormal        # the tube's own normal: smooth shading
            verts.append(np.concatenate([c + tube * out, out]))
    faces = []
    for i in range(segments):
        for j in range(sides):
            a, b = i * sides + j, i * sides + (j + 1) % sides
            c, d = ((i + 1) % segments) * sides + (j + 1) % sides, ((i + 1) % segments) * sides + j
            faces += [(a, c, d), (a, b, c)]
    return np.array(verts, dtype="<f4"), faces


def write_ply(path, verts, faces):
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\ncomment strahl docs/showcase/make_media_assets.py: a (2, 3) torus knot tube\n"
                 f"element vertex {len(verts)}\nproperty float x\nproperty float y\nproperty float z\n"
                 "property float nx\nproperty float ny\nproperty float nz\n"
                 f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n").encode())
        f.write(verts.tobytes())
        for t in faces:
            f.write(struct.pack("<B3i", 3, *t))


def main():
    os.makedirs(OUT, exist_ok=True)
    write_vol(os.path.join(OUT, "smoke.vol"), plume(), [-0.5, 0, -0.5], [0.5, 1.6, 0.5])
    verts, faces = knot()
    write_ply(os.path.join(OUT, "knot.ply"), verts, faces)
    print("wrote", os.path.join(OUT, "smoke.vol"), "and", os.path.join(OUT, "knot.ply"), f"({len(faces)} triangles)")


if __name__ == "__main__":
    main()
