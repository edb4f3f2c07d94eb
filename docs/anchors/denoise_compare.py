#!/usr/bin/env python3
"""Measures strahl's denoisers against high-spp references rendered with strahl and against Intel
Open Image Denoise itself (the oidnDenoise tool of `pip install pyoidn`), for docs/denoising.md.

    python3 docs/anchors/denoise_compare.py WORKDIR [SCENE ...]

SCENE defaults to the five Cornell variants in scenes/ and showcase-spheres. Renders with
`java -jar target/strahl.jar` (set STRAHL to another command), SIZE x SIZE (env STRAHL_DENOISE_SIZE,
default 512), into WORKDIR (files already there are reused):
  NAME-ref-a.pfm, NAME-ref-b.pfm  two independent halves of the reference, REF_SPP each (env
                    STRAHL_REF_SPP, default 2048), seeds 101 and 102; the reference is their mean,
                    and half their difference estimates its own error (printed as "ref noise": the
                    relMSE the reference's noise alone adds to every figure)
  NAME-256.pfm      the raw image at 256 spp, seed 1
  NAME-16.pfm       16 spp, seed 1, with NAME-16.albedo.pfm, .normal.pfm, .depth.pfm (--aov)
  NAME-16-network.pfm  the same render denoised by `render --denoise` (Open Image Denoise's network
                    in strahl; renders are deterministic, so it denoises exactly NAME-16.pfm)
  NAME-16-atrous.pfm   the same with --denoiser atrous
  NAME-16-oidn.pfm  oidnDenoise -d cpu --hdr NAME-16.pfm --alb ... --nrm ... (OIDN 2.5.1's own)
and prints per scene a table row: relMSE of each against the reference (mean over pixels and
channels of (x - ref)^2 / (ref^2 + 0.01)), the worst 16x16 region's mean-luminance error in percent
(regions whose reference mean luminance is above 0.01), the largest per-pixel difference between
strahl's network and OIDN (relative, + 1e-3), and the denoising times strahl printed. Writes
NAME-compare.png: 256x256 crops at 1:1 of noisy 16 spp | network | atrous | OIDN | reference.
"""
import os
import re
import shlex
import struct
import subprocess
import sys
import zlib

import numpy as np

STRAHL = shlex.split(os.environ.get("STRAHL", "java -jar target/strahl.jar"))
SIZE = int(os.environ.get("STRAHL_DENOISE_SIZE", "512"))
REF_SPP = int(os.environ.get("STRAHL_REF_SPP", "2048"))
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
    h, w, _ = ref.shape
    ra = lum(a)[: h // n * n, : w // n * n].reshape(h // n, n, w // n, n).mean(axis=(1, 3))
    rr = lum(ref)[: h // n * n, : w // n * n].reshape(h // n, n, w // n, n).mean(axis=(1, 3))
    keep = rr > 0.01
    return float(100 * np.max(np.abs(ra - rr)[keep] / rr[keep]))


def run(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), out.stderr))
    return out.stderr


def denoise_time(log):
    m = re.search(r"denoised with .* in ([0-9.]+) s", log)
    return float(m.group(1)) if m else float("nan")


def main():
    work = sys.argv[1]
    scenes = sys.argv[2:] or SCENES
    os.makedirs(work, exist_ok=True)
    size = ["--width", str(SIZE), "--height", str(SIZE)]
    print("%dx%d, references %d spp (two halves of %d); relMSE, then worst 16x16 region in %%" % (SIZE, SIZE, 2 * REF_SPP, REF_SPP))
    print("| scene | noisy 16 spp | raw 256 spp | **network** 16 spp | OIDN 16 spp | atrous 16 spp | worst region: noisy / network / OIDN / atrous"
          " | network vs OIDN, largest pixel difference | ref noise | network time | atrous time |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name in scenes:
        scene = os.path.join("scenes", name + ".json")
        p = lambda suffix: os.path.join(work, name + suffix)
        for half, seed in (("a", 101), ("b", 102)):
            if not os.path.exists(p("-ref-%s.pfm" % half)):
                run(STRAHL + ["render", scene] + size + ["--spp", str(REF_SPP), "--seed", str(seed), "-q", "-o", p("-ref-%s.pfm" % half)])
        if not os.path.exists(p("-256.pfm")):
            run(STRAHL + ["render", scene] + size + ["--spp", "256", "--seed", "1", "-q", "-o", p("-256.pfm")])
        if not os.path.exists(p("-16.pfm")):
            run(STRAHL + ["render", scene] + size + ["--spp", "16", "--seed", "1", "-q", "--aov", "albedo,normal,depth", "-o", p("-16.pfm")])
        t_net = denoise_time(run(STRAHL + ["render", scene] + size + ["--spp", "16", "--seed", "1", "--denoise", "-o", p("-16-network.pfm")]))
        t_atrous = denoise_time(run(STRAHL + ["render", scene] + size + ["--spp", "16", "--seed", "1", "--denoise", "--denoiser", "atrous",
                                                "-o", p("-16-atrous.pfm")]))
        run(["oidnDenoise", "-d", "cpu", "--hdr", p("-16.pfm"), "--alb", p("-16.albedo.pfm"), "--nrm", p("-16.normal.pfm"), "-o", p("-16-oidn.pfm")])
        a, b = read_pfm(p("-ref-a.pfm")), read_pfm(p("-ref-b.pfm"))
        ref = (a + b) / 2
        ref_noise = float(np.mean(((a - b) / 2) ** 2 / (ref ** 2 + 0.01)))
        noisy, raw, net, atrous, oidn = (read_pfm(p(s)) for s in ("-16.pfm", "-256.pfm", "-16-network.pfm", "-16-atrous.pfm", "-16-oidn.pfm"))
        diff = float(np.max(np.abs(net - oidn) / (np.abs(oidn) + 1e-3)))
        fmt = lambda x: "%.2e" % x
        print("| %s | %s | %s | **%s** | %s | %s | %.1f / %.1f / %.1f / %.1f | %.1e | %s | %.2f s | %.2f s |" % (
            name, fmt(rel_mse(noisy, ref)), fmt(rel_mse(raw, ref)), fmt(rel_mse(net, ref)), fmt(rel_mse(oidn, ref)), fmt(rel_mse(atrous, ref)),
            worst_region(noisy, ref), worst_region(net, ref), worst_region(oidn, ref), worst_region(atrous, ref), diff, fmt(ref_noise),
            t_net, t_atrous))
        y, x = CROPS.get(name, ((SIZE - 256) // 2, (SIZE - 256) // 2))
        crop = lambda im: im[y:y + 256, x:x + 256]
        write_png(p("-compare.png"), np.concatenate([crop(i) for i in (noisy, net, atrous, oidn, ref)], axis=1))


if __name__ == "__main__":
    main()
