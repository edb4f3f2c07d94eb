#!/usr/bin/env python3
"""Mitsuba 3 references of strahl's environment-map and thin-lens golden tests.

    python3.11 docs/anchors/envcam_refs.py [OUTPUT_DIR] [SPP]   (default: src/test/resources/golden, 4096)

Needs mitsuba (3.9.1, variant llvm_ad_rgb) and numpy. Writes:

  envcam-labelled.hdr   64x32 labelled latitude-longitude map (flat RGBE scanlines, exact mantissas):
                        a different hue in each eighth of the width (with a ramp), brighter towards the top, a
                        dark lower half and a 2x2-texel "sun" at columns 20-21, rows 8-9
  envmap-sphere_128.pfm a diffuse sphere (albedo 0.5) under that map, scale 1.5, rotated 30 degrees
                        about +Y; camera (0, 0.6, 4) -> (0, 0, 0), 70 degrees vertical
  thinlens_128.pfm      three diffuse spheres at different depths under a white sky (radiance 1),
                        thin lens of radius 0.15 focused at 4.5 (on the middle sphere)

Both renders: path tracer, unbounded depth, box pixel filter, 128x128 (the scenes are the JSON
files next to the references: envmap-sphere.json, thinlens.json).
"""
import os
import sys

import mitsuba as mi
import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "golden")
SPP = int(sys.argv[2]) if len(sys.argv) > 2 else 4096
W, H = 64, 32


def texel(x, y):
    """(m_r, m_g, m_b, e) of texel (x, y): decoded as m * 2^(e - 136)."""
    if 20 <= x <= 21 and 8 <= y <= 9:
        return 200, 190, 160, 134                       # the sun: about 50
    eighth = x // 8
    hue = [(230, 60, 40), (50, 220, 70), (40, 90, 240), (240, 220, 40),
           (200, 40, 220), (40, 220, 220), (240, 150, 40), (120, 120, 120)][eighth]
    shade = (x % 8) * 8                                   # a ramp inside each eighth: mirroring shows
    if y >= H // 2:
        return max(hue[0] // 4, 1) + 128, hue[1] // 4 + 64, hue[2] // 4 + 64, 125 - (y - H // 2) // 4
    return hue[0] // 2 + 64 + shade // 2, hue[1] // 2 + 64, hue[2] // 2 + 64, 128 - y // 6


def write_hdr(path):
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {H} +X {W}\n".encode())
        for y in range(H):
            for x in range(W):
                f.write(bytes(texel(x, y)))
    print(f"{path}: {os.path.getsize(path)} bytes")


def write_pfm(path, img):
    img = np.asarray(img, dtype="<f4")[:, :, :3]
    h, w = img.shape[:2]
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(img[::-1]).tobytes())
    print(f"{path}: mean {img.mean(axis=(0, 1))}")


def sensor(origin, target, fov, extra=None):
    s = {"type": "perspective", "fov": fov, "fov_axis": "y",
         "to_world": mi.ScalarTransform4f().look_at(origin=origin, target=target, up=[0, 1, 0]),
         "film": {"type": "hdrfilm", "width": 128, "height": 128, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
         "sampler": {"type": "independent", "sample_count": SPP}}
    if extra:
        s.update(extra)
    return s


def diffuse(albedo):
    return {"type": "diffuse", "reflectance": {"type": "rgb", "value": albedo}}


def main():
    mi.set_variant("llvm_ad_rgb")
    os.makedirs(OUT, exist_ok=True)
    hdr = os.path.join(OUT, "envcam-labelled.hdr")
    write_hdr(hdr)
    integrator = {"type": "path", "max_depth": -1}

    env = mi.load_dict({"type": "scene", "integrator": integrator,
                        "sensor": sensor([0, 0.6, 4], [0, 0, 0], 70),
                        "sky": {"type": "envmap", "filename": hdr, "scale": 1.5,
                                "to_world": mi.ScalarTransform4f().rotate([0, 1, 0], 30)},
                        "ball": {"type": "sphere", "center": [0, 0, 0], "radius": 1, "bsdf": diffuse([0.5, 0.5, 0.5])}})
    write_pfm(os.path.join(OUT, "envmap-sphere_128.pfm"), mi.render(env, seed=1))

    lens = mi.load_dict({"type": "scene", "integrator": integrator,
                         "sensor": sensor([0, 0.3, 4], [0, 0, -0.5], 35,
                                          {"type": "thinlens", "aperture_radius": 0.15, "focus_distance": 4.5}),
                         "sky": {"type": "constant", "radiance": {"type": "rgb", "value": [1, 1, 1]}},
                         "near": {"type": "sphere", "center": [-0.8, 0, 0.8], "radius": 0.4, "bsdf": diffuse([0.8, 0.2, 0.2])},
                         "middle": {"type": "sphere", "center": [0, 0, -0.5], "radius": 0.5, "bsdf": diffuse([0.2, 0.7, 0.2])},
                         "far": {"type": "sphere", "center": [0.9, 0, -2.5], "radius": 0.6, "bsdf": diffuse([0.2, 0.2, 0.8])}})
    write_pfm(os.path.join(OUT, "thinlens_128.pfm"), mi.render(lens, seed=1))
    print("mitsuba", mi.__version__, "spp", SPP)


if __name__ == "__main__":
    main()
