#!/usr/bin/env python3
"""Many small area lights: strahl's light tree against power-based selection and Mitsuba 3.

A grey floor (albedo 0.7, 12 x 12 at y = 0) under a 16 x 16 grid of small square lamps (side
0.08, pitch 0.5, facing down at height 0.35, radiance 25), optionally with a few diffuse boxes and
spheres standing among them (--props). Mitsuba 3.9.1 picks an emitter uniformly; strahl by power
(equal lamps: uniformly too) or by its light tree (the default).

    # the strahl scene file (and the showcase with --props)
    python3 docs/anchors/many_lights.py scene docs/anchors/many-lights/floor.json
    # Mitsuba's converged reference, and its runs at 64 spp (independent sampler, seeds 1..N)
    python3 docs/anchors/many_lights.py reference /tmp/ml/ref.exr --spp 32768
    python3 docs/anchors/many_lights.py mitsuba /tmp/ml/mitsuba --spp 64 --seeds 1 2
    # strahl's runs, then the table (relMSE against the reference, mean luminance)
    for s in 1 2; do for sel in tree power; do
      java -jar target/strahl.jar render docs/anchors/many-lights/floor.json --spp 64 --seed $s \\
          --light-selection $sel -o /tmp/ml/strahl-$sel-$s.pfm -q; done; done
    python3 docs/anchors/many_lights.py compare /tmp/ml/ref.exr /tmp/ml/mitsuba/mitsuba-64spp-*.exr /tmp/ml/strahl-*.pfm

relMSE = mean over pixels and channels of (x - ref)^2 / (ref^2 + 0.01), as everywhere in docs/.
"""
import argparse
import json
import os

import numpy as np

N, PITCH, SIDE, HEIGHT, RADIANCE = 16, 0.5, 0.08, 0.35, 25.0
FLOOR_HALF, FLOOR_ALBEDO, LAMP_ALBEDO = 6.0, 0.7, 0.8
CAMERA = {"lookFrom": [0, 2.6, 5.5], "lookAt": [0, 0, 0.5], "up": [0, 1, 0], "fov": 45}
WIDTH, HEIGHT_PX = 320, 240
# Props: (kind, centre, size, albedo); boxes are axis-aligned with half-extents `size`.
PROPS = [("sphere", [-1.2, 0.25, 0.9], 0.25, [0.8, 0.3, 0.2]),
         ("sphere", [1.4, 0.2, -0.6], 0.2, [0.2, 0.4, 0.8]),
         ("box", [0.3, 0.15, 1.2], [0.3, 0.15, 0.2], [0.8, 0.8, 0.7]),
         ("box", [-0.6, 0.12, -1.5], [0.15, 0.12, 0.6], [0.3, 0.6, 0.3])]


def lamp_centres():
    for i in range(N):
        for j in range(N):
            yield (i - (N - 1) / 2) * PITCH, (j - (N - 1) / 2) * PITCH


def box_triangles(c, e):
    """Positions and outward-wound indices of an axis-aligned box."""
    xs, ys, zs = (c[0] - e[0], c[0] + e[0]), (c[1] - e[1], c[1] + e[1]), (c[2] - e[2], c[2] + e[2])
    pos = [v for x in xs for y in ys for z in zs for v in (x, y, z)]       # corner k = 4x + 2y + z
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    idx = []
    for a, b, c2, d in quads:
        idx += [a, b, c2, a, c2, d]
    return pos, idx


def strahl_scene(props):
    pos, idx = [], []
    h = SIDE / 2
    for x, z in lamp_centres():
        b = len(pos) // 3
        pos += [x - h, HEIGHT, z - h, x + h, HEIGHT, z - h, x + h, HEIGHT, z + h, x - h, HEIGHT, z + h]
        idx += [b, b + 1, b + 2, b, b + 2, b + 3]       # (v1 - v0) x (v2 - v0) points down
    f = FLOOR_HALF
    materials = {"lamp": {"type": "diffuse", "albedo": [LAMP_ALBEDO] * 3, "emission": [RADIANCE] * 3},
                 "floor": {"type": "diffuse", "albedo": [FLOOR_ALBEDO] * 3}}
    shapes = [{"type": "triangles", "positions": [-f, 0, -f, f, 0, -f, f, 0, f, -f, 0, f], "indices": [0, 2, 1, 0, 3, 2],
               "material": "floor"},
              {"type": "triangles", "positions": pos, "indices": idx, "material": "lamp"}]
    if props:
        for k, (kind, c, size, albedo) in enumerate(PROPS):
            materials[f"prop{k}"] = {"type": "diffuse", "albedo": albedo}
            if kind == "sphere":
                shapes.append({"type": "sphere", "center": c, "radius": size, "material": f"prop{k}"})
            else:
                p, i = box_triangles(c, size)
                shapes.append({"type": "triangles", "positions": p, "indices": i, "material": f"prop{k}"})
    return {"camera": CAMERA, "film": {"width": WIDTH, "height": HEIGHT_PX}, "materials": materials, "shapes": shapes}


def mitsuba_scene(spp, props):
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    T = mi.ScalarTransform4f

    def diffuse(a):
        return {"type": "diffuse", "reflectance": {"type": "rgb", "value": a}}

    d = {"type": "scene", "integrator": {"type": "path", "max_depth": -1},
         "sensor": {"type": "perspective", "fov": CAMERA["fov"], "fov_axis": "y",
                    "to_world": T().look_at(origin=CAMERA["lookFrom"], target=CAMERA["lookAt"], up=CAMERA["up"]),
                    "film": {"type": "hdrfilm", "width": WIDTH, "height": HEIGHT_PX, "rfilter": {"type": "box"},
                             "pixel_format": "rgb"},
                    "sampler": {"type": "independent", "sample_count": spp}},
         # Mitsuba's rectangle is [-1, 1]^2 in z = 0 facing +z.
         "floor": {"type": "rectangle", "to_world": T().rotate([1, 0, 0], -90).scale([FLOOR_HALF, FLOOR_HALF, 1]),
                   "bsdf": diffuse([FLOOR_ALBEDO] * 3)}}
    for k, (x, z) in enumerate(lamp_centres()):
        d[f"lamp{k}"] = {"type": "rectangle",
                         "to_world": T().translate([x, HEIGHT, z]).rotate([1, 0, 0], 90).scale([SIDE / 2, SIDE / 2, 1]),
                         "bsdf": diffuse([LAMP_ALBEDO] * 3),
                         "emitter": {"type": "area", "radiance": {"type": "rgb", "value": [RADIANCE] * 3}}}
    if props:
        for k, (kind, c, size, albedo) in enumerate(PROPS):
            if kind == "sphere":
                d[f"prop{k}"] = {"type": "sphere", "center": c, "radius": size, "bsdf": diffuse(albedo)}
            else:
                d[f"prop{k}"] = {"type": "cube", "to_world": T().translate(c).scale(size), "bsdf": diffuse(albedo)}
    return mi.load_dict(d)


def read_image(path):
    if path.endswith(".pfm"):
        with open(path, "rb") as f:
            kind = f.readline().strip()
            w, h = map(int, f.readline().split())
            scale = float(f.readline())
            data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
        return data.reshape(h, w, 3 if kind == b"PF" else 1)[::-1].astype(np.float64)
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    return np.array(mi.Bitmap(path), dtype=np.float64)[:, :, :3]


def rel_mse(a, ref):
    return float(np.mean((a - ref) ** 2 / (ref ** 2 + 0.01)))


def luminance(img):
    return float((img @ np.array([0.2126, 0.7152, 0.0722])).mean())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("command", choices=["scene", "reference", "mitsuba", "compare"])
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--seeds", type=int, nargs="*", default=[1, 2])
    ap.add_argument("--props", action="store_true", help="boxes and spheres among the lamps (the showcase)")
    a = ap.parse_args()
    if a.command == "scene":
        with open(a.paths[0], "w") as f:
            json.dump(strahl_scene(a.props), f, separators=(",", ":"))
            f.write("\n")
    elif a.command == "reference":
        # Passes of 1024 spp (seeds 1000, 1001, ...) averaged: one wavefront of all the samples would not fit in memory.
        import mitsuba as mi
        passes = max(1, a.spp // 1024)
        scene = mitsuba_scene(a.spp // passes, a.props)
        total = sum(np.array(mi.render(scene, seed=1000 + k), dtype=np.float64) for k in range(passes))
        mi.util.write_bitmap(a.paths[0], mi.Bitmap((total / passes).astype(np.float32)))
    elif a.command == "mitsuba":
        import mitsuba as mi
        os.makedirs(a.paths[0], exist_ok=True)
        scene = mitsuba_scene(a.spp, a.props)
        for s in a.seeds:
            mi.util.write_bitmap(os.path.join(a.paths[0], f"mitsuba-{a.spp}spp-{s}.exr"), mi.render(scene, seed=s))
    else:
        ref = read_image(a.paths[0])
        print(f"{'image':48s} {'relMSE':>10s} {'mean lum':>10s} {'vs ref':>8s}")
        print(f"{os.path.basename(a.paths[0]):48s} {'':>10s} {luminance(ref):10.5f}")
        for p in a.paths[1:]:
            img = read_image(p)
            print(f"{os.path.basename(p):48s} {rel_mse(img, ref):10.4g} {luminance(img):10.5f} "
                  f"{100 * (luminance(img) / luminance(ref) - 1):+7.2f}%")


if __name__ == "__main__":
    main()
