#!/usr/bin/env python3
"""Mitsuba 3 reference of strahl's instancing golden test (InstancesGoldenTest).

    python3 docs/anchors/instances_refs.py [OUTPUT_DIR] [SPP]   (default: src/test/resources/golden, 4096)

Needs mitsuba (3.9.1, variant llvm_ad_rgb) and numpy. Writes instances-rock.obj and
instances-slab.obj (generated here, deterministic: a bumpy icosphere of 320 triangles and a box
of 12) when they are missing, and instances_128.pfm: the scene of
src/test/resources/golden/instances.json -- a grey floor (albedo 0.6, 4x4 at y = 0) and a
`shapegroup` of the rock (albedo (0.7, 0.35, 0.2)) and the slab (albedo (0.2, 0.4, 0.7), moved
down by 0.35 inside the group) shown by five `instance`s: translated, rotated, scaled unequally,
one mirrored (scale -0.7 along x); lit by a point light at (1.5, 3, 2) of intensity (6, 6, 5) W/sr
and a constant environment of radiance 0.3. Flat shading (face_normals: strahl uses the
geometric normal of a mesh without normals). Camera (0, 2.2, 5) -> (0, 0.4, 0), 40 degrees
vertical; path tracer with unbounded depth, box pixel filter, 128x128, independent sampler, seed 1.
"""
import math
import os
import sys

import mitsuba as mi
import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "golden")
SPP = int(sys.argv[2]) if len(sys.argv) > 2 else 4096

# (scale xyz, rotation axis, degrees, translation): applied in this order, as strahl's steps.
PLACEMENTS = [
    ((1, 1, 1), (0, 1, 0), 0, (-1.2, 0.5, 0)),
    ((1.5, 0.5, 1), (0, 1, 0), 30, (0.8, 0.3, 0.3)),
    ((-0.7, 0.9, 0.7), (1, 1, 0), 45, (0.2, 0.65, -1.2)),
    ((0.4, 0.4, 0.4), (0, 1, 0), 0, (-0.3, 0.2, 1.2)),
    ((0.5, 1.4, 0.5), (0, 0, 1), -20, (1.6, 0.75, -0.8)),
]


def write_pfm(path, img):
    img = np.asarray(img, dtype="<f4")[:, :, :3]
    h, w = img.shape[:2]
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(img[::-1]).tobytes())
    print(f"{path}: mean {img.mean(axis=(0, 1))}")


def rock(path):
    """An icosphere subdivided twice (320 triangles), radius 0.5 with deterministic bumps, outward winding."""
    t = (1 + math.sqrt(5)) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
         (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(2):
        cache, nf = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                p = [(v[a][k] + v[b][k]) / 2 for k in range(3)]
                n = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / n for x in p))
                cache[key] = len(v) - 1
            return cache[key]
        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    with open(path, "w") as out:
        for i, p in enumerate(v):
            r = 0.5 * (1 + 0.12 * math.sin(5 * p[0] + 3 * p[1]) * math.cos(4 * p[2] + i % 3))
            out.write("v %.6f %.6f %.6f\n" % tuple(r * x for x in p))
        for a, b, c in f:
            out.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def slab(path):
    """A box 0.9 x 0.1 x 0.6 centred at the origin, outward winding."""
    sx, sy, sz = 0.45, 0.05, 0.3
    v = [(x, y, z) for x in (-sx, sx) for y in (-sy, sy) for z in (-sz, sz)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    with open(path, "w") as out:
        for p in v:
            out.write("v %g %g %g\n" % p)
        for a, b, c, d in quads:
            out.write("f %d %d %d\nf %d %d %d\n" % (a + 1, b + 1, c + 1, a + 1, c + 1, d + 1))


def diffuse(albedo):
    return {"type": "diffuse", "reflectance": {"type": "rgb", "value": albedo}}


def main():
    mi.set_variant("llvm_ad_rgb")
    os.makedirs(OUT, exist_ok=True)
    rock_obj, slab_obj = os.path.join(OUT, "instances-rock.obj"), os.path.join(OUT, "instances-slab.obj")
    if not os.path.exists(rock_obj):
        rock(rock_obj)
    if not os.path.exists(slab_obj):
        slab(slab_obj)
    T = mi.ScalarTransform4f
    scene = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1},
        "sensor": {"type": "perspective", "fov": 40, "fov_axis": "y",
                   "to_world": T().look_at(origin=[0, 2.2, 5], target=[0, 0.4, 0], up=[0, 1, 0]),
                   "film": {"type": "hdrfilm", "width": 128, "height": 128, "rfilter": {"type": "box"},
                            "pixel_format": "rgb"},
                   "sampler": {"type": "independent", "sample_count": SPP}},
        "floor": {"type": "rectangle", "to_world": T().rotate([1, 0, 0], -90).scale([2, 2, 1]),
                  "bsdf": diffuse([0.6, 0.6, 0.6])},
        "group": {"type": "shapegroup",
                  "rock": {"type": "obj", "filename": rock_obj, "face_normals": True, "bsdf": diffuse([0.7, 0.35, 0.2])},
                  "slab": {"type": "obj", "filename": slab_obj, "face_normals": True, "bsdf": diffuse([0.2, 0.4, 0.7]),
                           "to_world": T().translate([0, -0.35, 0])}},
        "point": {"type": "point", "position": [1.5, 3, 2], "intensity": {"type": "rgb", "value": [6, 6, 5]}},
        "sky": {"type": "constant", "radiance": {"type": "rgb", "value": [0.3, 0.3, 0.3]}},
    }
    for i, (s, axis, deg, t) in enumerate(PLACEMENTS):
        axis = (np.array(axis, dtype=float) / np.linalg.norm(axis)).tolist()     # Mitsuba's rotate takes the axis as given
        scene[f"instance{i}"] = {"type": "instance", "shapegroup": {"type": "ref", "id": "group"},
                                 "to_world": T().translate(list(t)) @ T().rotate(axis, deg) @ T().scale(list(s))}
    write_pfm(os.path.join(OUT, "instances_128.pfm"), mi.render(mi.load_dict(scene), seed=1))
    print("mitsuba", mi.__version__, "spp", SPP)


if __name__ == "__main__":
    main()
