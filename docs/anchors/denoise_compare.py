#!/usr/bin/env python3
"""Measures strahl's denoiser against high-spp references and against Intel Open Image Denoise
(the oidnDenoise tool of `pip install pyoidn`), for docs/denoising.md.

    python3 docs/anchors/denoise_compare.py WORKDIR [SCENE ...]

SCENE defaults to the five Cornell variants in scenes/. Renders with `java -jar target/strahl.jar`
(set STRAHL to another command), 256x256, into WORKDIR (files already there are reused):
  NAME-ref.pfm      the reference: 1024 spp, seed 7 (for cornell-box: Mitsuba's 8192 spp 512x512
                    reference in $STRAHL_REFS, box-filtered 2x2, when present)
  NAME-256.pfm      the raw image at 256 spp, seed 1
  NAME-16.pfm       16 spp, seed 1, with NAME-16.albedo.pfm, .normal.pfm, .depth.pfm (--aov)
  NAME-16-strahl.pfm  the same 16 spp render denoised by strahl (--denoise), its time from the log
  NAME-16-oidn.pfm  oidnDenoise -d cpu --hdr NAME-16.pfm --alb ... --nrm ... (when on the PATH)
and prints per scene: relMSE of each against the reference (mean over pixels and channels of
(x - ref)^2 / (ref^2 + 0.01)), the worst 16x16 region's mean luminance error in percent (regions
whose reference mean luminance is above 0.01), and the denoising times. Writes NAME-compare.png:
noisy 16 spp | strahl | OIDN | reference (clamped, sRGB).
"""
import os
import re
import shlex
import subprocess
import sys
import time
import zlib
import struct

import numpy as np

STRAHL = shlex.split(os.environ.get("STRAHL", "java -jar target/strahl.jar"))
REFS = os.environ.get("STRAHL_REFS", "")          # a folder with Mitsuba's 512x512 Cornell reference, if you have one
SCENES = ["cornell-box", "cornell-sphere", "cornell-mirror", "cornell-glossy", "cornell-empty-rg"]
SIZE = ["--width", "256", "--height", "256"]


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        data = np.fromfile(f, dtype="<f4" if scale < 0 else ">f4").reshape(h, w, channels)
    return data[::-1].copy()


def write_pfm(path, a):
    h, w, _ = a.shape
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        a[::-1].astype("<f4").tofile(f)


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


def worst_region(a, ref, n=16):
    lum = lambda x: x @ np.array([0.2126, 0.7152, 0.0722])
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


def main():
    work = sys.argv[1]
    scenes = sys.argv[2:] or SCENES
    os.makedirs(work, exist_ok=True)
    have_oidn = subprocess.run(["sh", "-c", "command -v oidnDenoise"], capture_output=True).returncode == 0
    print("| scene | noisy 16 spp | raw 256 spp | strahl 16 spp denoised | OIDN 16 spp | worst 16x16 region: noisy / strahl / OIDN | strahl time | OIDN time |")
    print("|---|---|---|---|---|---|---|---|")
    for name in scenes:
        scene = os.path.join("scenes", name + ".json")
        p = lambda suffix: os.path.join(work, name + suffix)
        if not os.path.exists(p("-ref.pfm")):
            mitsuba = os.path.join(REFS, "cornell-original_maxdepth-inf_8192spp.pfm")
            if name == "cornell-box" and REFS and os.path.exists(mitsuba):
                m = read_pfm(mitsuba)
                write_pfm(p("-ref.pfm"), m.reshape(256, 2, 256, 2, 3).mean(axis=(1, 3)))
            else:
                run(STRAHL + ["render", scene] + SIZE + ["--spp", "1024", "--seed", "7", "-q", "-o", p("-ref.pfm")])
        if not os.path.exists(p("-256.pfm")):
            run(STRAHL + ["render", scene] + SIZE + ["--spp", "256", "--seed", "1", "-q", "-o", p("-256.pfm")])
        if not os.path.exists(p("-16.pfm")):
            run(STRAHL + ["render", scene] + SIZE + ["--spp", "16", "--seed", "1", "-q", "--aov", "albedo,normal,depth", "-o", p("-16.pfm")])
        log = run(STRAHL + ["render", scene] + SIZE + ["--spp", "16", "--seed", "1", "--denoise", "-o", p("-16-strahl.pfm")])
        m = re.search(r"denoised with .* in ([0-9.]+) s", log)
        strahl_time = float(m.group(1)) if m else float("nan")
        ref, noisy, raw, den = (read_pfm(p(s)) for s in ("-ref.pfm", "-16.pfm", "-256.pfm", "-16-strahl.pfm"))
        oidn, oidn_time = None, float("nan")
        if have_oidn:
            t0 = time.perf_counter()
            run(["oidnDenoise", "-d", "cpu", "--hdr", p("-16.pfm"), "--alb", p("-16.albedo.pfm"), "--nrm", p("-16.normal.pfm"),
                 "-o", p("-16-oidn.pfm")])
            oidn_time = time.perf_counter() - t0
            oidn = read_pfm(p("-16-oidn.pfm"))
        fmt = lambda x: "%.2e" % x
        print("| %s | %s | %s | %s | %s | %.1f %% / %.1f %% / %s | %.2f s | %s |" % (
            name, fmt(rel_mse(noisy, ref)), fmt(rel_mse(raw, ref)), fmt(rel_mse(den, ref)),
            fmt(rel_mse(oidn, ref)) if oidn is not None else "-", worst_region(noisy, ref), worst_region(den, ref),
            "%.1f %%" % worst_region(oidn, ref) if oidn is not None else "-", strahl_time,
            "%.2f s (process)" % oidn_time if oidn is not None else "-"))
        panels = [noisy, den, oidn if oidn is not None else np.zeros_like(ref), ref]
        write_png(p("-compare.png"), np.concatenate(panels, axis=1))


if __name__ == "__main__":
    main()
