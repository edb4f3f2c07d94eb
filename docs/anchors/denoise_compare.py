#!/usr/bin/env python3
"""Measures strahl's denoisers against high-spp references rendered with strahl and against Intel
Open Image Denoise itself (the oidnDenoise tool of `pip install pyoidn`), for docs/denoising.md.

    python3 docs/anchors/denoise_compare.py [--inputs] WORKDIR [SCENE ...]

SCENE defaults to the five Cornell variants in scenes/ and showcase-spheres. Renders with
`java -jar target/strahl.jar` (set STRAHL to another command), SIZE x SIZE (env STRAHL_DENOISE_SIZE,
default 512), into WORKDIR (files already there are reused, so a slow reference is rendered once):
  NAME-ref-a.pfm, NAME-ref-b.pfm  two independent parts of the reference, seeds 101 and 102, of
                    REF_SPP spp each (env STRAHL_REF_SPP, default 2048; NAME-ref-a.spp says how many
                    a part has, when it was rendered with another count). The reference is their
                    mean weighted by spp; their difference estimates its own error: for parts of
                    n_a and n_b spp, the reference's variance is (a - b)^2 n_a n_b / (n_a + n_b)^2.
  NAME-256.pfm      the raw image at 256 spp, seed 1
  NAME-16.pfm       16 spp, seed 1, with NAME-16.albedo.pfm, .normal.pfm, .depth.pfm (--aov)
  NAME-16-network.pfm  the same render denoised by `render --denoise` (Open Image Denoise's network
                    in strahl; renders are deterministic, so it denoises exactly NAME-16.pfm);
                    strahl's lines in NAME-16-network.log
  NAME-16-atrous.pfm   the same with --denoiser atrous
  NAME-16-oidn.pfm  oidnDenoise -d cpu --hdr NAME-16.pfm --alb ... --nrm ... (OIDN 2.5.1's own; the
                    tool on the PATH, else the one pyoidn ships)
and prints per scene a table row: relMSE of each against the converged image (mean over pixels and
channels of (x - ref)^2 / (ref^2 + 0.01), less the reference's own share, "ref": its variance
in the same measure; the render compared is independent of the reference, so the rest estimates
its error against the converged image), the network's relMSE over OIDN's, the worst 16x16
region's mean-luminance error in percent (regions whose reference mean luminance is above 0.01;
"ref" is the largest the reference's own noise gives a region, estimated from the parts), the
largest per-pixel difference between strahl's network and OIDN (relative, + 1e-3), and the
denoising times strahl printed. Writes NAME-compare.png: CROPxCROP crops (env STRAHL_CROP, default 192) at 1:1 of noisy 16 spp |
network | atrous | OIDN | raw 256 spp | reference. --inputs renders and denoises all but the
reference and stops (the reference's parts can then be rendered elsewhere, at the same time).
"""
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import zlib

import numpy as np

STRAHL = shlex.split(os.environ.get("STRAHL", "java -jar target/strahl.jar"))
SIZE = int(os.environ.get("STRAHL_DENOISE_SIZE", "512"))
REF_SPP = int(os.environ.get("STRAHL_REF_SPP", "2048"))
CROP = int(os.environ.get("STRAHL_CROP", "192"))
SCENES = ["cornell-box", "cornell-glossy", "cornell-sphere", "cornell-mirror", "cornell-empty-rg", "showcase-spheres"]
# where the 1:1 crop of the picture starts (row, column), per scene; the centre otherwise
CROPS = {"cornell-box": (200, 100), "cornell-glossy": (200, 130), "cornell-sphere": (190, 140)}


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        data = np.fromfile(f, dtype="<f4" if scale < 0 else ">f4").reshape(h, w, channels)
    return data[::-1].astype(np.float64)


def write_png(path, a):
    a = np.clip(np.nan_to_num(a), 0, 1)
    a = np.where(a <= 0.0031308, 12.92 * a, 1.055 * np.power(a, 1 / 2.4) - 0.055)
    a = (a * 255 + 0.5).astype(np.uint8)
    h, w, _ = a.shape
    raw = b"".join(b"\x00" + a[y].tobytes() for y in range(h))

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def rel_mse(a, ref):
    return float(np.mean((a - ref) ** 2 / (ref ** 2 + 0.01)))


def lum(x):
    return x @ np.array([0.2126, 0.7152, 0.0722])


def worst_region(a, ref, n=16):
    ra, rr = regions(a, n), regions(ref, n)
    keep = rr > 0.01
    return float(100 * np.max(np.abs(ra - rr)[keep] / rr[keep]))


def oidn_tool():
    tool = shutil.which("oidnDenoise")
    if tool:
        return tool
    import pyoidn
    return os.path.join(os.path.dirname(pyoidn.__file__), "oidn", "bin", "oidnDenoise")


def part_spp(path):
    spp = path[:-len(".pfm")] + ".spp"
    return int(open(spp).read()) if os.path.exists(spp) else REF_SPP


def regions(x, n=16):
    h, w = x.shape[:2]
    return lum(x)[: h // n * n, : w // n * n].reshape(h // n, n, w // n, n).mean(axis=(1, 3))


def run(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), out.stderr))
    return out.stderr


def denoise_time(log):
    m = re.search(r"denoised with .* in ([0-9.]+) s", log)
    return float(m.group(1)) if m else float("nan")


def main():
    args = sys.argv[1:]
    inputs_only = args[0] == "--inputs"
    if inputs_only:
        args = args[1:]
    work = args[0]
    scenes = args[1:] or SCENES
    os.makedirs(work, exist_ok=True)
    size = ["--width", str(SIZE), "--height", str(SIZE)]
    print("%dx%d; relMSE less the reference's own (its variance: column ref), then the worst 16x16 region's error in %%" % (SIZE, SIZE))
    print("| scene | reference spp | noisy 16 spp | raw 256 spp | **network** 16 spp | OIDN 16 spp | atrous 16 spp | network / OIDN | ref"
          " | worst region: noisy / network / OIDN / atrous / 256 spp / ref | network vs OIDN, largest pixel difference"
          " | network time | atrous time |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name in scenes:
        scene = os.path.join("scenes", name + ".json")
        p = lambda suffix: os.path.join(work, name + suffix)
        for part, seed in (("a", 101), ("b", 102)):
            if not inputs_only and not os.path.exists(p("-ref-%s.pfm" % part)):
                run(STRAHL + ["render", scene] + size + ["--spp", str(REF_SPP), "--seed", str(seed), "-q", "-o", p("-ref-%s.pfm" % part)])
        if not os.path.exists(p("-256.pfm")):
            run(STRAHL + ["render", scene] + size + ["--spp", "256", "--seed", "1", "-q", "-o", p("-256.pfm")])
        if not os.path.exists(p("-16.pfm")):
            run(STRAHL + ["render", scene] + size + ["--spp", "16", "--seed", "1", "-q", "--aov", "albedo,normal,depth", "-o", p("-16.pfm")])
        times = []
        for kind in ("network", "atrous"):
            if not os.path.exists(p("-16-%s.pfm" % kind)):
                log = run(STRAHL + ["render", scene] + size + ["--spp", "16", "--seed", "1", "--denoise", "--denoiser", kind,
                                                             "-o", p("-16-%s.pfm" % kind)])
                with open(p("-16-%s.log" % kind), "w") as f:
                    f.write(log)
            times.append(denoise_time(open(p("-16-%s.log" % kind)).read()) if os.path.exists(p("-16-%s.log" % kind)) else float("nan"))
        if not os.path.exists(p("-16-oidn.pfm")):
            run([oidn_tool(), "-d", "cpu", "--hdr", p("-16.pfm"), "--alb", p("-16.albedo.pfm"), "--nrm", p("-16.normal.pfm"),
                 "-o", p("-16-oidn.pfm")])
        if inputs_only:
            continue
        a, b = read_pfm(p("-ref-a.pfm")), read_pfm(p("-ref-b.pfm"))
        na, nb = part_spp(p("-ref-a.pfm")), part_spp(p("-ref-b.pfm"))
        ref = (na * a + nb * b) / (na + nb)
        share = na * nb / (na + nb) ** 2
        ref_noise = float(np.mean((a - b) ** 2 * share / (ref ** 2 + 0.01)))
        keep = regions(ref) > 0.01
        ref_region = float(100 * np.max(np.abs(regions(a) - regions(b))[keep] * np.sqrt(share) / regions(ref)[keep]))
        images = [read_pfm(p(s)) for s in ("-16.pfm", "-256.pfm", "-16-network.pfm", "-16-oidn.pfm", "-16-atrous.pfm")]
        noisy, raw, net, oidn, atrous = images
        err = [rel_mse(x, ref) - ref_noise for x in images]
        diff = float(np.max(np.abs(net - oidn) / (np.abs(oidn) + 1e-3)))
        fmt = lambda x: "%.2e" % x
        print("| %s | %d | %s | %s | **%s** | %s | %s | %.2f | %s | %.1f / %.1f / %.1f / %.1f / %.1f / %.1f | %.1e | %.2f s | %.2f s |" % (
            name, na + nb, *(fmt(e) for e in err), err[2] / err[3], fmt(ref_noise),
            *(worst_region(x, ref) for x in (noisy, net, oidn, atrous, raw)), ref_region, diff, *times), flush=True)
        y, x = CROPS.get(name, ((SIZE - CROP) // 2, (SIZE - CROP) // 2))
        crop = lambda im: im[y:y + CROP, x:x + CROP]
        write_png(p("-compare.png"), np.concatenate([crop(i) for i in (noisy, net, atrous, oidn, raw, ref)], axis=1))


if __name__ == "__main__":
    main()
