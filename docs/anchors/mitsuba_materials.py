#!/usr/bin/env python3
"""Mitsuba 3 references of strahl's material golden tests (MaterialGoldenTest), 128 x 128.

    python3.11 docs/anchors/mitsuba_materials.py [OUTPUT_DIR] [SPP]
        (default: src/test/resources/golden/materials, 4096; mitsuba 3.9.1, llvm_ad_rgb, numpy)

Writes, next to each other, the inputs, strahl's scene files and Mitsuba's renders of them (the
scene files are written from the same numbers as Mitsuba's scenes, so the two cannot drift):

  stripes.hdr            128x64 latitude-longitude map (flat RGBE, exact mantissas): a blue sky
                         getting darker towards the zenith, vertical stripes of 8 texels just above
                         the horizon (bright / dark, a hue per quarter of the width, so mirroring or
                         a rotation shows) and a brown ground. No sun: its glints would make the
                         low-spp renders of the test too noisy to pin alpha to 10 %
  checker.png            64x64 8-bit sRGB: 8x8 checks, red towards the left, blue towards the right,
                         a green band along the top 8 rows (a vertical flip shows)
  floor.obj              the textured floor for Mitsuba (vt 0..2: the texture repeats twice)
  conductors.json / _128.pfm   GGX spheres, gold (top row) and aluminium (bottom row), alpha
                         0.05, 0.2, 0.5 from left to right (roughconductor, ggx, visible normals)
  glass.json / _128.pfm  two rough glass spheres, alpha 0.1 (left) and 0.3 (right), ior 1.5
                         (roughdielectric, ggx)
  texture.json / _128.pfm      a grey diffuse sphere on the checker floor (diffuse + bitmap,
                         bilinear, repeat)

Every scene is lit by stripes.hdr only (envmap, no rotation, scale 1); path tracer, unbounded depth,
box pixel filter, independent sampler, seed 1.
"""
import json
import os
import struct
import sys
import zlib

import mitsuba as mi
import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "golden", "materials")
SPP = int(sys.argv[2]) if len(sys.argv) > 2 else 4096
W, H = 128, 64
GOLD = ([0.143036, 0.375307, 1.44205], [3.983, 2.38556, 1.60336])          # strahl's presets =
ALUMINIUM = ([1.6575, 0.880405, 0.521244], [9.22381, 6.2695, 4.837])      # Mitsuba's Au, Al (scalar_rgb)
CONDUCTOR_ALPHAS = [0.05, 0.2, 0.5]
GLASS_ALPHAS = [0.1, 0.3]


def texel(x, y):
    """(m_r, m_g, m_b, e) of texel (x, y): decoded as m * 2^(e - 136)."""
    if 24 <= y < 32:                                               # stripes just above the horizon
        hue = [(240, 80, 60), (80, 230, 90), (70, 110, 250), (240, 220, 60)][x // 32]
        bright = (x // 8) % 2 == 0
        return hue + ((129,) if bright else (125,))
    if y >= 32:                                                    # ground, darker downwards
        return 150, 120, 80, 126 - (y - 32) // 11
    return 90 + 2 * y, 140 + 2 * y, 240, 127 - (23 - y) // 8       # sky


def write_hdr(path):
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\n# strahl docs/anchors/mitsuba_materials.py\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {H} +X {W}\n".encode())
        for y in range(H):
            for x in range(W):
                f.write(bytes(texel(x, y)))


def checker():
    img = np.zeros((64, 64, 3), np.uint8)
    for y in range(64):
        for x in range(64):
            on = ((x // 8) + (y // 8)) % 2 == 0
            t = x / 63
            img[y, x] = [220 * (1 - t) + 20, 60, 220 * t + 20] if on else [30, 30 + 150 * (y < 8), 30]
    return img


def write_png(path, rgb8):
    h, w, _ = rgb8.shape
    raw = b"".join(b"\x00" + rgb8[y].tobytes() for y in range(h))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


FLOOR_Y, FLOOR_R = -0.5, 2.0
FLOOR_P = [[-FLOOR_R, FLOOR_Y, FLOOR_R], [FLOOR_R, FLOOR_Y, FLOOR_R], [FLOOR_R, FLOOR_Y, -FLOOR_R], [-FLOOR_R, FLOOR_Y, -FLOOR_R]]
FLOOR_UV = [[0, 0], [2, 0], [2, 2], [0, 2]]


def write_floor_obj(path):
    with open(path, "w") as f:
        for p in FLOOR_P:
            f.write("v %g %g %g\n" % tuple(p))
        for uv in FLOOR_UV:
            f.write("vt %g %g\n" % tuple(uv))
        f.write("f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")


CAMERAS = {
    "conductors": ([0, 0, 4], [0, 0, 0], 30),
    "glass": ([0, 0.2, 4], [0, 0, 0], 32),
    "texture": ([0, 1.2, 3.5], [0, -0.3, 0], 45),
}


def shapes(kind):
    """[(name, strahl material, mitsuba bsdf, sphere centre, radius)] of a scene's spheres."""
    out = []
    if kind == "conductors":
        for row, (name, (eta, k)) in enumerate([("gold", GOLD), ("aluminium", ALUMINIUM)]):
            for i, a in enumerate(CONDUCTOR_ALPHAS):
                out.append((f"{name}-{i}", {"type": "conductor", "preset": name, "alpha": a},
                            {"type": "roughconductor", "distribution": "ggx", "alpha": a,
                             "eta": {"type": "rgb", "value": eta}, "k": {"type": "rgb", "value": k}},
                            [-0.7 + 0.7 * i, 0.35 - 0.7 * row, 0], 0.3))
    elif kind == "glass":
        for i, a in enumerate(GLASS_ALPHAS):
            out.append((f"glass-{i}", {"type": "dielectric", "ior": 1.5, "alpha": a},
                        {"type": "roughdielectric", "distribution": "ggx", "alpha": a, "int_ior": 1.5, "ext_ior": 1.0},
                        [-0.55 + 1.1 * i, 0, 0], 0.5))
    else:
        out.append(("grey", {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
                    {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0.5, 0.5, 0.5]}}, [0, 0, 0], 0.5))
    return out


def strahl_scene(kind):
    origin, target, fov = CAMERAS[kind]
    s = {"camera": {"lookFrom": origin, "lookAt": target, "up": [0, 1, 0], "fov": fov},
         "film": {"width": 128, "height": 128},
         "materials": {}, "shapes": [],
         "environment": {"type": "envmap", "file": "stripes.hdr", "scale": 1.0, "rotate": 0}}
    for name, material, _, centre, radius in shapes(kind):
        s["materials"][name] = material
        s["shapes"].append({"type": "sphere", "center": centre, "radius": radius, "material": name})
    if kind == "texture":
        s["materials"]["checker"] = {"type": "diffuse", "albedo": {"texture": "checker.png"}}
        s["shapes"].append({"type": "triangles", "material": "checker",
                            "positions": [c for p in FLOOR_P for c in p], "uvs": [c for uv in FLOOR_UV for c in uv],
                            "indices": [0, 1, 2, 0, 2, 3]})
    return s


def to_json(scene):
    """The scene file, a line per top-level key, material and shape."""
    def one(v):
        return json.dumps(v, separators=(", ", ": "))
    lines = []
    for key, value in scene.items():
        if key == "materials":
            inner = ",\n".join(f"    {one(k)}: {one(v)}" for k, v in value.items())
            lines.append(f'  "materials": {{\n{inner}\n  }}')
        elif key == "shapes":
            inner = ",\n".join(f"    {one(v)}" for v in value)
            lines.append(f'  "shapes": [\n{inner}\n  ]')
        else:
            lines.append(f"  {one(key)}: {one(value)}")
    return "{\n" + ",\n".join(lines) + "\n}\n"


def mitsuba_scene(kind):
    origin, target, fov = CAMERAS[kind]
    s = {"type": "scene", "integrator": {"type": "path", "max_depth": -1},
         "sensor": {"type": "perspective", "fov": fov, "fov_axis": "y",
                    "to_world": mi.ScalarTransform4f().look_at(origin=origin, target=target, up=[0, 1, 0]),
                    "film": {"type": "hdrfilm", "width": 128, "height": 128, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                    "sampler": {"type": "independent", "sample_count": SPP}},
         "sky": {"type": "envmap", "filename": os.path.join(OUT, "stripes.hdr")}}
    for name, _, bsdf, centre, radius in shapes(kind):
        s[name] = {"type": "sphere", "center": centre, "radius": radius, "bsdf": bsdf}
    if kind == "texture":
        s["floor"] = {"type": "obj", "filename": os.path.join(OUT, "floor.obj"),
                      "bsdf": {"type": "diffuse", "reflectance": {"type": "bitmap", "filename": os.path.join(OUT, "checker.png"),
                                                                   "filter_type": "bilinear", "wrap_mode": "repeat"}}}
    return s


def write_pfm(path, img):
    img = np.asarray(img, dtype="<f4")[:, :, :3]
    h, w = img.shape[:2]
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(img[::-1]).tobytes())
    print(f"{path}: mean {img.mean(axis=(0, 1))}")


def main():
    mi.set_variant("llvm_ad_rgb" if "llvm_ad_rgb" in mi.variants() else "scalar_rgb")
    os.makedirs(OUT, exist_ok=True)
    write_hdr(os.path.join(OUT, "stripes.hdr"))
    write_png(os.path.join(OUT, "checker.png"), checker())
    write_floor_obj(os.path.join(OUT, "floor.obj"))
    kinds = sys.argv[3:] or ["conductors", "glass", "texture"]
    for kind in kinds:
        with open(os.path.join(OUT, kind + ".json"), "w") as f:
            f.write(to_json(strahl_scene(kind)))
        write_pfm(os.path.join(OUT, f"{kind}_128.pfm"), mi.render(mi.load_dict(mitsuba_scene(kind)), seed=1))
    print("mitsuba", mi.__version__, mi.variant(), "spp", SPP)


if __name__ == "__main__":
    main()
