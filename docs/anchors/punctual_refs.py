#!/usr/bin/env python3
"""Mitsuba 3 reference of strahl's punctual-light golden test (PunctualGoldenTest).

    python3 docs/anchors/punctual_refs.py [OUTPUT_DIR] [SPP]   (default: src/test/resources/golden, 4096)

Needs mitsuba (3.9.1, variant llvm_ad_rgb) and numpy. Writes punctual_128.pfm: the scene of
src/test/resources/golden/punctual.json -- a grey floor (albedo 0.6, 4x4 at y = 0) and a diffuse
ball (albedo (0.7, 0.3, 0.2), radius 0.5 at (0, 0.5, 0)) lit by
  - a point light at (1, 1.5, 1), intensity (4, 4, 3) W/sr (Mitsuba `point`: the same quantity),
  - a spot light at (-1.2, 1.6, 0.6) along (0.5, -1.6, -0.3), intensity (6, 3, 1), with a hard edge
    at 25 degrees: strahl's innerCone = outerCone = 25 (glTF's falloff is then a step), Mitsuba's
    `spot` with beam_width = cutoff_angle = 25 (its own falloff, linear in the angle between the
    two, is then the same step),
  - a directional light travelling along (-0.5, -1, -0.3), irradiance (0.5, 0.6, 0.8) W/m^2
    (Mitsuba `directional`: the same quantity),
and nothing else (black environment). Camera (0, 1.5, 4.5) -> (0, 0.3, 0), 40 degrees vertical;
path tracer with unbounded depth, box pixel filter, 128x128, independent sampler, seed 1.
"""
import os
import sys

import mitsuba as mi
import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "golden")
SPP = int(sys.argv[2]) if len(sys.argv) > 2 else 4096


def write_pfm(path, img):
    img = np.asarray(img, dtype="<f4")[:, :, :3]
    h, w = img.shape[:2]
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(img[::-1]).tobytes())
    print(f"{path}: mean {img.mean(axis=(0, 1))}")


def diffuse(albedo):
    return {"type": "diffuse", "reflectance": {"type": "rgb", "value": albedo}}


def main():
    mi.set_variant("llvm_ad_rgb")
    os.makedirs(OUT, exist_ok=True)
    T = mi.ScalarTransform4f
    spot_from = np.array([-1.2, 1.6, 0.6])
    spot_dir = np.array([0.5, -1.6, -0.3])
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1},
        "sensor": {"type": "perspective", "fov": 40, "fov_axis": "y",
                   "to_world": T().look_at(origin=[0, 1.5, 4.5], target=[0, 0.3, 0], up=[0, 1, 0]),
                   "film": {"type": "hdrfilm", "width": 128, "height": 128, "rfilter": {"type": "box"},
                            "pixel_format": "rgb"},
                   "sampler": {"type": "independent", "sample_count": SPP}},
        # Mitsuba's rectangle is [-1, 1]^2 in z = 0 facing +z: scaled by 2 and turned to face +y.
        "floor": {"type": "rectangle", "to_world": T().rotate([1, 0, 0], -90).scale([2, 2, 1]),
                  "bsdf": diffuse([0.6, 0.6, 0.6])},
        "ball": {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "bsdf": diffuse([0.7, 0.3, 0.2])},
        "point": {"type": "point", "position": [1, 1.5, 1], "intensity": {"type": "rgb", "value": [4, 4, 3]}},
        "spot": {"type": "spot", "cutoff_angle": 25, "beam_width": 25,
                 "to_world": T().look_at(origin=spot_from.tolist(), target=(spot_from + spot_dir).tolist(), up=[0, 1, 0]),
                 "intensity": {"type": "rgb", "value": [6, 3, 1]}},
        "sun": {"type": "directional", "direction": [-0.5, -1, -0.3],
                "irradiance": {"type": "rgb", "value": [0.5, 0.6, 0.8]}},
    })
    write_pfm(os.path.join(OUT, "punctual_128.pfm"), mi.render(scene, seed=1))
    print("mitsuba", mi.__version__, "spp", SPP)


if __name__ == "__main__":
    main()
