#!/usr/bin/env python3
"""Writes the assets of strahl's showcase scenes, every one procedural (no downloaded data):

    python3 docs/showcase/make_assets.py [OUTPUT_DIR]      (default: scenes/assets)

Needs numpy only (the HDR and PNG encoders are below). Deterministic: the same bytes every run.

  sky.hdr        512x256 latitude-longitude sky (Radiance RGBE, flat scanlines), oriented as strahl
                 and Mitsuba 3 read it: top row +Y, centre column along +Z. A blue gradient sky
                 (darker towards the zenith), a hazy horizon, a green-brown ground, and a sun of
                 about 1.5 degrees radius at azimuth -50 degrees (from +Z towards +X) and elevation
                 28 degrees, radiance about 1200: small and bright, what importance sampling is for.
  checker.png    512x512 8-bit sRGB checkerboard (8x8 squares, warm grey and dark grey, a thin
                 lighter groove between squares) for a textured floor.
  tiles.png      256x256 8-bit sRGB terracotta tiles with a little per-tile variation (hash of the
                 tile index, no random generator state).
"""
import os
import struct
import sys
import zlib

import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("scenes", "assets")


def sky(w=512, h=256):
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    theta = np.pi * y / (h - 1)
    phi = 2 * np.pi * (x + 0.5) / w
    d = np.stack([np.sin(phi) * np.sin(theta), np.cos(theta), -np.cos(phi) * np.sin(theta)], axis=-1)
    up = d[..., 1]
    t = np.clip(up, 0, 1)
    zenith = np.array([0.10, 0.22, 0.55])
    horizon = np.array([0.62, 0.70, 0.80])
    skyc = zenith + (horizon - zenith) * ((1 - t) ** 3)[..., None]
    ground = np.array([0.09, 0.085, 0.05]) + np.array([0.35, 0.38, 0.40]) * np.exp(np.minimum(up, 0) * 20)[..., None]
    c = np.where((up >= 0)[..., None], skyc, ground)
    az, el = np.radians(-50), np.radians(28)
    s = np.array([np.sin(az) * np.cos(el), np.sin(el), np.cos(az) * np.cos(el)])
    alpha = np.degrees(np.arccos(np.clip(d @ s, -1, 1)))
    disk = 1200 * np.clip((1.5 - alpha) / 0.3 + 0.5, 0, 1)          # 1.5 degrees, a soft 0.3-degree rim
    glow = 1.5 * np.exp(-(alpha / 8) ** 2) * (up > -0.05)
    c = c + (disk + glow)[..., None] * np.array([1.0, 0.93, 0.82])
    return c


def write_hdr(path, img):
    h, w, _ = img.shape
    m = img.max(axis=2)
    e = np.zeros((h, w), dtype=np.int32)
    mant, exp = np.frexp(m)
    nz = m > 1e-32
    e[nz] = exp[nz]
    scale = np.where(nz, np.ldexp(1.0, 8 - e), 0)                    # m in [0.5, 1) -> 128..255
    rgbe = np.zeros((h, w, 4), dtype=np.uint8)
    rgbe[..., :3] = np.clip(np.floor(img * scale[..., None]), 0, 255).astype(np.uint8)
    rgbe[..., 3] = np.where(nz, e + 128, 0).astype(np.uint8)
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\n# strahl docs/showcase/make_assets.py\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {h} +X {w}\n".encode())
        f.write(rgbe.tobytes())
    print(f"{path}: {os.path.getsize(path)} bytes")


def write_png(path, rgb8):
    h, w, _ = rgb8.shape
    raw = b"".join(b"\x00" + rgb8[y].tobytes() for y in range(h))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)
    print(f"{path}: {os.path.getsize(path)} bytes")


def checker(n=512, squares=8):
    y, x = np.mgrid[0:n, 0:n]
    s = n // squares
    odd = ((x // s + y // s) % 2).astype(bool)
    img = np.where(odd[..., None], np.array([200, 190, 170]), np.array([70, 68, 66]))
    groove = ((x % s) < 2) | ((y % s) < 2)
    img[groove] = [150, 145, 135]
    return img.astype(np.uint8)


def tiles(n=256, count=8):
    y, x = np.mgrid[0:n, 0:n]
    s = n // count
    tx, ty = x // s, y // s
    h = ((tx * 73856093) ^ (ty * 19349663)) % 1000 / 1000.0        # a hash per tile, no RNG state
    base = np.stack([170 + 40 * h, 80 + 25 * h, 50 + 15 * h], axis=-1)
    grout = ((x % s) < 3) | ((y % s) < 3)
    base[grout] = [200, 195, 185]
    return np.clip(base, 0, 255).astype(np.uint8)


def main():
    os.makedirs(OUT, exist_ok=True)
    write_hdr(os.path.join(OUT, "sky.hdr"), sky())
    write_png(os.path.join(OUT, "checker.png"), checker())
    write_png(os.path.join(OUT, "tiles.png"), tiles())


if __name__ == "__main__":
    main()
