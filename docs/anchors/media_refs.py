#!/usr/bin/env python3
"""Mitsuba 3 references of strahl's participating-media golden tests (MediaGoldenTest), 128 x 128.

    python3 docs/anchors/media_refs.py scenes  [OUT]            strahl's scene files and smoke.vol only
    python3 docs/anchors/media_refs.py refs    [OUT] [SPP] [NAME...]  + Mitsuba's references NAME_128.pfm
    python3 docs/anchors/media_refs.py noise   DIR [SPP] [RUNS] [NAME...]  Mitsuba at SPP (default 1024), RUNS seeds:
                                                                 NAME_SPP_sK.pfm, to measure its own error
    python3 docs/anchors/media_refs.py grid    [OUT]            Mitsuba's gridvolume looked up at points:
                                                                 grid-lookups.txt (GridConventionTest)
    python3 docs/anchors/media_refs.py compare REF.pfm IMG.pfm...  relMSE, means and worst block against REF
    python3 docs/anchors/media_refs.py nullcheck [SPP]         Mitsuba's volpath with a null box around the
                                                                 room's light or below it (docs/media.md)
        OUT defaults to src/test/resources/golden/media, SPP of the references to 16384.
        Needs mitsuba 3.9.1 (variant llvm_ad_rgb; scalar_rgb for the lookups) and numpy.

strahl's scene files and Mitsuba's scenes are written from the same numbers below, so the two
cannot drift. Every scene goes through strahl's scene-file interface for media (docs/media.md):

  fog.json        a Cornell-like room (2 x 2 x 2, open towards the camera, light (17, 12, 4) in the
                  ceiling, a tall and a short box) whose inside, light included, is a `null` box of
                  homogeneous fog (sigmaT 0.6, albedo 0.85, g 0.5); the camera looks in from outside
  tint.json       a glass sphere (ior 1.5) filled with an absorbing medium (sigmaT (1, 0.375, 0.104)
                  x scale 2.4, albedo 0) on a grey floor, under a sky and an area light
  subsurface.json the same sphere filled with a scattering medium (sigmaT (8, 10, 14), albedo
                  (0.97, 0.9, 0.75), g 0.3): random-walk subsurface scattering inside a dielectric shell
  smoke.json      a 12 x 10 x 8 density grid (smoke.vol, written here) in a `null` box above a floor,
                  scale 25, albedo 0.9, g 0.3, under a constant sky and a directional sun

Mitsuba: volpath (max_depth -1, rr_depth 5), box pixel filter, independent sampler; diffuse surfaces
are `twosided` (strahl's are two-sided), glass is `dielectric` with int_ior 1.5, ext_ior 1 exactly,
meshes are OBJ files with face normals, the grid is a `gridvolume` mapped onto its bounds by
to_world = translate(min) . scale(max - min).
"""
import json
import os
import struct
import sys
import tempfile

import numpy as np

OUT_DEFAULT = os.path.join("src", "test", "resources", "golden", "media")
SIZE = 128

# ---- the scenes, as data ---------------------------------------------------------------------

WHITE, RED, GREEN = [0.725, 0.71, 0.68], [0.63, 0.065, 0.05], [0.14, 0.45, 0.091]


def quad(p0, p1, p2, p3):
    """Four corners, counter-clockwise seen from the front (normal = (p1 - p0) x (p2 - p0))."""
    return [p0, p1, p2, p3], [[0, 1, 2], [0, 2, 3]]


def box(lo, hi):
    """An axis-aligned box, faces outwards."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0], [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    f = [[0, 3, 2], [0, 2, 1],     # z0, facing -z
         [4, 5, 6], [4, 6, 7],     # z1, facing +z
         [0, 4, 7], [0, 7, 3],     # x0, facing -x
         [1, 2, 6], [1, 6, 5],     # x1, facing +x
         [0, 1, 5], [0, 5, 4],     # y0, facing -y
         [3, 7, 6], [3, 6, 2]]     # y1, facing +y
    return v, f


def turned_box(center, size, degrees):
    """A box standing on y = 0, turned about +y."""
    v, f = box([-size[0] / 2, 0, -size[2] / 2], [size[0] / 2, size[1], size[2] / 2])
    a = np.radians(degrees)
    c, s = np.cos(a), np.sin(a)
    return [[c * x + s * z + center[0], y, -s * x + c * z + center[2]] for x, y, z in v], f


def mesh(vf, material, **media):
    return dict(kind="mesh", v=[[float(c) for c in p] for p in vf[0]], f=vf[1], material=material, **media)


def sphere(center, radius, material, **media):
    return dict(kind="sphere", center=center, radius=radius, material=material, **media)


def fog_scene():
    room = [
        mesh(quad([-1, 0, 1], [1, 0, 1], [1, 0, -1], [-1, 0, -1]), "white"),          # floor, up
        mesh(quad([-1, 2, 1], [-1, 2, -1], [1, 2, -1], [1, 2, 1]), "white"),          # ceiling, down
        mesh(quad([-1, 0, -1], [1, 0, -1], [1, 2, -1], [-1, 2, -1]), "white"),        # back wall, +z
        mesh(quad([-1, 0, 1], [-1, 0, -1], [-1, 2, -1], [-1, 2, 1]), "red"),          # left wall, +x
        mesh(quad([1, 0, -1], [1, 0, 1], [1, 2, 1], [1, 2, -1]), "green"),            # right wall, -x
        mesh(quad([-0.25, 1.99, 0.25], [-0.25, 1.99, -0.25], [0.25, 1.99, -0.25], [0.25, 1.99, 0.25]), "light"),
        mesh(turned_box([-0.35, 0, -0.3], [0.6, 1.2, 0.6], 18), "white"),
        mesh(turned_box([0.35, 0, 0.35], [0.6, 0.6, 0.6], -17), "white"),
        # the fog: inside the room, its floor under the room's floor, its top between the light and the ceiling (see
        # docs/media.md: with the light above the top, Mitsuba's shadow rays through the top are blocked by the light)
        mesh(box([-0.99, -0.01, -0.99], [0.99, 1.995, 0.99]), "boundary", interior="fog"),
    ]
    return dict(
        camera=dict(lookFrom=[0, 1, 3.9], lookAt=[0, 1, 0], fov=40),
        materials=dict(white=dict(type="diffuse", albedo=WHITE), red=dict(type="diffuse", albedo=RED),
                       green=dict(type="diffuse", albedo=GREEN),
                       light=dict(type="diffuse", albedo=[0.78, 0.78, 0.78], emission=[17, 12, 4]),
                       boundary=dict(type="null")),
        media=dict(fog=dict(type="homogeneous", sigmaT=0.6, albedo=[0.85, 0.85, 0.85], g=0.5)),
        shapes=room)


def sphere_scene(medium):
    shapes = [
        mesh(quad([-4, 0, 4], [4, 0, 4], [4, 0, -4], [-4, 0, -4]), "floor"),
        mesh(quad([-1.5, 3, 0.5], [-1.5, 3, -0.5], [-0.5, 3, -0.5], [-0.5, 3, 0.5]), "lamp"),
        sphere([0, 0.5, 0], 0.5, "glass", interior="inside"),
    ]
    return dict(
        camera=dict(lookFrom=[0.3, 1.1, 2.6], lookAt=[0, 0.45, 0], fov=38),
        materials=dict(floor=dict(type="diffuse", albedo=[0.6, 0.6, 0.6]),
                       lamp=dict(type="diffuse", albedo=[0, 0, 0], emission=[12, 11, 10]),
                       glass=dict(type="dielectric", ior=1.5)),
        media=dict(inside=medium),
        shapes=shapes, environment=[0.35, 0.4, 0.5])


GRID_LO, GRID_HI, GRID_DIMS = [-0.6, 0.02, -0.4], [0.6, 1.02, 0.4], (12, 10, 8)


def smoke_grid():
    """12 x 10 x 8 densities in [0, 1], x fastest: a lopsided blob (heavier towards -x and the top),
    each voxel scaled by a fixed hash so that the grid has structure at the scale of a voxel."""
    nx, ny, nz = GRID_DIMS
    out = np.zeros((nz, ny, nx), dtype=np.float32)
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                x, y, z = (i + 0.5) / nx, (j + 0.5) / ny, (k + 0.5) / nz
                blob = np.exp(-(((x - 0.4) / 0.3) ** 2 + ((y - 0.6) / 0.35) ** 2 + ((z - 0.5) / 0.3) ** 2))
                h = ((i * 73856093) ^ (j * 19349663) ^ (k * 83492791)) % 1000 / 1000.0
                out[k, j, i] = blob * (0.15 + 0.85 * h) if blob > 0.08 else 0.0
    return out


def write_vol(path, grid, lo, hi):
    nz, ny, nx = grid.shape
    with open(path, "wb") as f:
        f.write(b"VOL" + bytes([3]) + struct.pack("<iiiii", 1, nx, ny, nz, 1) + struct.pack("<6f", *lo, *hi))
        f.write(np.ascontiguousarray(grid, dtype="<f4").tobytes())


def smoke_scene():
    return dict(
        camera=dict(lookFrom=[0.4, 0.9, 2.4], lookAt=[0, 0.5, 0], fov=40),
        materials=dict(floor=dict(type="diffuse", albedo=[0.5, 0.5, 0.5]), boundary=dict(type="null")),
        media=dict(smoke=dict(type="grid", file="smoke.vol", bounds=[GRID_LO, GRID_HI], scale=25, albedo=0.9, g=0.3)),
        shapes=[mesh(quad([-4, 0, 4], [4, 0, 4], [4, 0, -4], [-4, 0, -4]), "floor"),
                mesh(box(GRID_LO, GRID_HI), "boundary", interior="smoke")],
        lights=[dict(type="directional", direction=[-0.6, -1, -0.4], irradiance=[3, 2.8, 2.5])],
        environment=[0.3, 0.4, 0.6])


SCENES = {
    "fog": fog_scene,
    "tint": lambda: sphere_scene(dict(type="homogeneous", sigmaT=[1.0, 0.375, 0.104], scale=2.4, albedo=0)),
    "subsurface": lambda: sphere_scene(dict(type="homogeneous", sigmaT=[8, 10, 14], albedo=[0.97, 0.9, 0.75], g=0.3)),
    "smoke": smoke_scene,
}

# ---- strahl ----------------------------------------------------------------------------------


def strahl_json(scene):
    out = {"camera": dict(scene["camera"], up=[0, 1, 0]), "materials": scene["materials"], "media": scene["media"], "shapes": []}
    for s in scene["shapes"]:
        media = {k: s[k] for k in ("interior", "exterior") if k in s}
        if s["kind"] == "sphere":
            out["shapes"].append(dict(type="sphere", center=s["center"], radius=s["radius"], material=s["material"], **media))
        else:
            out["shapes"].append(dict(type="triangles", positions=[c for p in s["v"] for c in p], indices=[i for t in s["f"] for i in t],
                                      material=s["material"], **media))
    for key in ("lights", "environment"):
        if key in scene:
            out[key] = scene[key]
    # one line per top-level key and per shape, so that the tests' mutants can replace a value as text
    dump = lambda v: json.dumps(v, separators=(", ", ": "))
    lines = []
    for k, v in out.items():
        if k == "shapes":
            lines.append(' "shapes": [\n' + ",\n".join("  " + dump(x) for x in v) + "\n ]")
        else:
            lines.append(f' "{k}": {dump(v)}')
    return "{\n" + ",\n".join(lines) + "\n}"


def write_scenes(out):
    os.makedirs(out, exist_ok=True)
    write_vol(os.path.join(out, "smoke.vol"), smoke_grid(), GRID_LO, GRID_HI)
    for name, make in SCENES.items():
        with open(os.path.join(out, name + ".json"), "w") as f:
            f.write(strahl_json(make()) + "\n")

# ---- Mitsuba ---------------------------------------------------------------------------------


def rgb(v):
    v = [v] * 3 if np.isscalar(v) else v
    return {"type": "rgb", "value": [float(c) for c in v]}


def mitsuba_medium(m, folder):
    import mitsuba as mi
    phase = {"type": "hg", "g": float(m.get("g", 0))}
    if m["type"] == "homogeneous":
        # Mitsuba's rgb texture takes values in [0, 1] only: sigmaT / its largest channel, that channel into the scale
        sigma = np.broadcast_to(np.array(m.get("sigmaT", 1), float), 3)      # strahl's defaults are Mitsuba's
        peak = float(sigma.max()) or 1.0
        return {"type": "homogeneous", "sigma_t": rgb((sigma / peak).tolist()), "scale": float(m.get("scale", 1)) * peak,
                "albedo": rgb(m.get("albedo", 0.75)), "phase": phase}
    lo, hi = np.array(m["bounds"][0], float), np.array(m["bounds"][1], float)
    grid = {"type": "gridvolume", "filename": os.path.join(folder, m["file"]),
            "to_world": mi.ScalarTransform4f().translate(lo.tolist()).scale((hi - lo).tolist())}
    return {"type": "heterogeneous", "sigma_t": grid, "scale": float(m.get("scale", 1)), "albedo": rgb(m.get("albedo", 0.75)),
            "phase": phase}


def mitsuba_bsdf(m):
    if m["type"] == "null":
        return {"type": "null"}
    if m["type"] == "dielectric":
        return {"type": "dielectric", "int_ior": float(m["ior"]), "ext_ior": 1.0}
    return {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": rgb(m["albedo"])}}


def write_obj(path, v, f):
    with open(path, "w") as out:
        for p in v:
            out.write("v %.9g %.9g %.9g\n" % tuple(p))
        for t in f:
            out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def mitsuba_scene(name, spp, folder, tmp):
    import mitsuba as mi
    scene = SCENES[name]()
    cam = scene["camera"]
    media = {k: mitsuba_medium(m, folder) for k, m in scene["media"].items()}
    d = {"type": "scene",
         "integrator": {"type": "volpath", "max_depth": -1, "rr_depth": 5},
         "sensor": {"type": "perspective", "fov": cam["fov"], "fov_axis": "y",
                    "to_world": mi.ScalarTransform4f().look_at(origin=cam["lookFrom"], target=cam["lookAt"], up=[0, 1, 0]),
                    "film": {"type": "hdrfilm", "width": SIZE, "height": SIZE, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                    "sampler": {"type": "independent", "sample_count": spp}}}
    for k, m in media.items():
        d["medium_" + k] = m                  # a top-level key is the object's id, which the shapes refer to
    for i, s in enumerate(scene["shapes"]):
        mat = scene["materials"][s["material"]]
        if s["kind"] == "sphere":
            shape = {"type": "sphere", "center": s["center"], "radius": s["radius"]}
        else:
            path = os.path.join(tmp, f"{name}-{i}.obj")
            write_obj(path, s["v"], s["f"])
            shape = {"type": "obj", "filename": path, "face_normals": True}
        shape["bsdf"] = mitsuba_bsdf(mat)
        if "emission" in mat:
            shape["emitter"] = {"type": "area", "radiance": rgb(mat["emission"])}
        for side in ("interior", "exterior"):
            if side in s:
                shape[side] = {"type": "ref", "id": "medium_" + s[side]}
        d[f"shape{i}"] = shape
    for i, l in enumerate(scene.get("lights", [])):
        d[f"light{i}"] = {"type": "directional", "direction": l["direction"], "irradiance": rgb(l["irradiance"])}
    if "environment" in scene:
        d["sky"] = {"type": "constant", "radiance": rgb(scene["environment"])}
    return mi.load_dict(d)


def write_pfm(path, img):
    img = np.asarray(img, dtype="<f4")[:, :, :3]
    h, w = img.shape[:2]
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(img[::-1]).tobytes())
    print(f"{path}: mean {img.mean(axis=(0, 1))}", flush=True)


def render(out, spp, seeds, suffix, names=None):
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    write_scenes(out)
    with tempfile.TemporaryDirectory() as tmp:
        for name in names or SCENES:
            scene = mitsuba_scene(name, spp, out, tmp)
            for seed in seeds:
                # in passes of at most 1024 spp (the LLVM back end's memory grows with spp x pixels)
                passes = max(1, spp // 1024)
                total = None
                for p in range(passes):
                    img = np.array(mi.render(scene, seed=seed * 1000 + p, spp=spp // passes))
                    total = img if total is None else total + img
                write_pfm(os.path.join(out, suffix(name, seed)), total / passes)


def grid_lookups(out):
    """Mitsuba's gridvolume (the smoke grid on its bounds) at fixed points: voxel centres, points
    between them, points in the half voxel at the faces and outside the box (clamped)."""
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    write_scenes(out)
    lo, hi = np.array(GRID_LO), np.array(GRID_HI)
    vol = mi.load_dict({"type": "gridvolume", "filename": os.path.join(out, "smoke.vol"),
                        "to_world": mi.ScalarTransform4f().translate(lo.tolist()).scale((hi - lo).tolist())})
    rng = np.random.default_rng(29)
    dims = np.array(GRID_DIMS)
    points = [lo + (np.array([i, j, k]) + 0.5) / dims * (hi - lo) for i, j, k in [(0, 0, 0), (11, 9, 7), (4, 6, 3), (7, 2, 5)]]
    points += [lo + u * (hi - lo) for u in rng.uniform(0, 1, (200, 3))]
    points += [lo + u * (hi - lo) for u in rng.uniform(-0.02, 0.06, (20, 3))]         # the half voxel at the low faces
    points += [lo + u * (hi - lo) for u in rng.uniform(0.94, 1.02, (20, 3))]
    it = mi.Interaction3f()
    with open(os.path.join(out, "grid-lookups.txt"), "w") as f:
        f.write("# x y z, and Mitsuba 3.9.1's gridvolume (smoke.vol on its bounds, trilinear, clamp) there\n")
        for p in points:
            it.p = mi.Point3f(*[float(c) for c in p])
            f.write("%.9g %.9g %.9g %.9g\n" % (p[0], p[1], p[2], float(vol.eval_1(it))))
    print("wrote", os.path.join(out, "grid-lookups.txt"), "mitsuba", mi.__version__)


def read_pfm(path):
    with open(path, "rb") as f:
        kind, size, scale = f.readline().strip(), f.readline().split(), float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    w, h = int(size[0]), int(size[1])
    return data.reshape(h, w, 3 if kind == b"PF" else 1)[::-1].astype(np.float64)


def compare(ref_path, paths, block=16):
    """relMSE = mean((x - ref)^2 / (ref^2 + 0.01)) (strahl's Image.relMse), the image means, and the
    worst block's relative difference (r + g + b, as MediaGoldenTest without its floor)."""
    ref = read_pfm(ref_path)
    n = ref.shape[0] // block
    for p in paths:
        img = read_pfm(p)
        rel = np.mean((img - ref) ** 2 / (ref ** 2 + 0.01))
        a, r = (x.reshape(n, block, n, block, 3).sum(axis=(1, 3)) for x in (img, ref))
        worst = (np.abs(a - r).sum(axis=2) / (r.sum(axis=2) + 0.05 * r.sum() / (n * n))).max()
        means = img.mean(axis=(0, 1)) / ref.mean(axis=(0, 1)) - 1
        print(f"{p}: relMSE {rel:.3g}, means {np.round(100 * means, 2)} %, worst {block}x{block} block {100 * worst:.2f} %")


def null_check(spp):
    """Mitsuba's volpath with an invisible (null) box in the room: the box's top below the light
    (shadow rays cross it just before they reach the light), above the light, and below it again
    with the light's own surface null. Prints each image's mean against the room without a box."""
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")

    def room(top=None, null_lamp=False):
        def make():
            sc = fog_scene()
            sc["media"] = {}
            sc["shapes"] = sc["shapes"][:-1]
            if top is not None:
                sc["shapes"].append(mesh(box([-0.99, -0.01, -0.99], [0.99, top, 0.99]), "boundary"))
            if null_lamp:
                sc["materials"]["light"] = dict(sc["materials"]["light"], null=True)
            return sc
        return make

    plain = mitsuba_bsdf

    def bsdf(m):
        return {"type": "null"} if m.get("null") else plain(m)

    globals()["mitsuba_bsdf"] = bsdf
    variants = {"no box": room(), "box top 1.98 (light above it)": room(1.98), "box top 1.9": room(1.9),
                "box top 1.995 (light inside)": room(1.995), "no box, null lamp surface": room(None, True),
                "box top 1.98, null lamp surface": room(1.98, True)}
    with tempfile.TemporaryDirectory() as tmp:
        means = {}
        for name, make in variants.items():
            SCENES["check"] = make
            means[name] = np.array(mi.render(mitsuba_scene("check", spp, tmp, tmp), seed=3)).mean(axis=(0, 1))
        for name, m in means.items():
            base = means["no box, null lamp surface" if "null lamp" in name else "no box"]
            print(f"{name:36s} mean {np.round(m, 5)}  vs no box {np.round(m / base - 1, 4)}")


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else "refs"
    out = sys.argv[2] if len(sys.argv) > 2 else OUT_DEFAULT
    if what == "scenes":
        write_scenes(out)
    elif what == "compare":
        compare(sys.argv[2], sys.argv[3:])
    elif what == "nullcheck":
        null_check(int(sys.argv[2]) if len(sys.argv) > 2 else 256)
    elif what == "grid":
        grid_lookups(out)
    elif what == "refs":
        spp = int(sys.argv[3]) if len(sys.argv) > 3 else 16384
        render(out, spp, [1], lambda name, seed: f"{name}_128.pfm", sys.argv[4:])
    elif what == "noise":
        spp = int(sys.argv[3]) if len(sys.argv) > 3 else 1024
        runs = int(sys.argv[4]) if len(sys.argv) > 4 else 4
        render(out, spp, range(101, 101 + runs), lambda name, seed: f"{name}_{spp}_s{seed}.pfm", sys.argv[5:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
