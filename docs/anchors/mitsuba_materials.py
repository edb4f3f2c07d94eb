"""Reference renders for the material golden tests (src/test/resources/golden/materials/), made
with Mitsuba 3: a textured diffuse floor (diffuse + bitmap), gold spheres at three GGX roughnesses
(roughconductor, ggx, visible-normal sampling) and a rough glass sphere (roughdielectric, ggx),
under a small area light, 128 x 128, written as PFM (rows bottom to top, linear radiance).

It also writes the texture checker.png the scenes use.

Run: python3.11 docs/anchors/mitsuba_materials.py [spp]      (mitsuba 3, numpy)
"""
import os
import sys

import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")
HERE = os.path.join(os.path.dirname(__file__), "..", "..", "src", "test", "resources", "golden", "materials")
SPP = int(sys.argv[1]) if len(sys.argv) > 1 else 4096
GOLD_ETA = [0.143036, 0.375307, 1.44205]   # strahl's preset "gold" = Mitsuba's Au in scalar_rgb
GOLD_K = [3.983, 2.38556, 1.60336]


def checker():
    """64 x 64: 8 x 8 checks, red towards the left, blue towards the right, bright top row band."""
    img = np.zeros((64, 64, 3), np.uint8)
    for y in range(64):
        for x in range(64):
            on = ((x // 8) + (y // 8)) % 2 == 0
            t = x / 63
            c = np.array([220 * (1 - t) + 20, 60, 220 * t + 20]) if on else np.array([30, 30 + 150 * (y < 8), 30])
            img[y, x] = c
    mi.Bitmap(img, pixel_format=mi.Bitmap.PixelFormat.RGB).write(os.path.join(HERE, "checker.png"))


def scene(kind):
    s = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1},
        "sensor": {
            "type": "perspective", "fov": 40, "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=[0, 1.2, 3.2], target=[0, 0.4, 0], up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": 128, "height": 128, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
            "sampler": {"type": "independent", "sample_count": SPP},
        },
        "light": {
            "type": "obj", "filename": os.path.join(HERE, "light.obj"), "face_normals": True,
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": [40, 40, 40]}},
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}},
        },
        "floor": {
            "type": "obj", "filename": os.path.join(HERE, "floor.obj"),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "bitmap", "filename": os.path.join(HERE, "checker.png"),
                                                        "filter_type": "bilinear", "wrap_mode": "repeat"}},
        },
    }
    if kind == "conductors":
        for i, alpha in enumerate([0.05, 0.2, 0.5]):
            s[f"gold{i}"] = {"type": "sphere", "center": [-0.6 + 0.6 * i, 0.25, 0], "radius": 0.25,
                             "bsdf": {"type": "roughconductor", "distribution": "ggx", "alpha": alpha,
                                      "eta": {"type": "rgb", "value": GOLD_ETA}, "k": {"type": "rgb", "value": GOLD_K}}}
    elif kind == "glass":
        s["glass"] = {"type": "sphere", "center": [0, 0.35, 0], "radius": 0.35,
                      "bsdf": {"type": "roughdielectric", "distribution": "ggx", "alpha": 0.2, "int_ior": 1.5, "ext_ior": 1.0}}
    return s


def write_pfm(path, rgb):
    h, w, _ = rgb.shape
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(rgb[::-1].astype("<f4")).tobytes())


if __name__ == "__main__":
    checker()
    for kind in ("texture", "conductors", "glass"):
        img = np.array(mi.render(mi.load_dict(scene(kind)), spp=SPP, seed=7))[:, :, :3]
        write_pfm(os.path.join(HERE, f"{kind}_128.pfm"), img)
        print(kind, "mean", img.mean(axis=(0, 1)))
