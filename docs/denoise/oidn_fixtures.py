#!/usr/bin/env python3
"""Writes the fixtures of strahl's network tests: small noisy renders with their feature buffers,
and what Intel Open Image Denoise (pip install pyoidn==2.5.1.0) makes of them.

    mvn -B -q -DskipTests package
    python3 docs/denoise/oidn_fixtures.py [OUTPUT_DIR]      (default: src/test/resources/denoise)

Renders with `java -jar target/strahl.jar` (STRAHL overrides the command), then denoises with
pyoidn.denoise(color, albedo, normal, hdr=True) at OIDN's default quality ("high"), on the CPU.
Each fixture is one OpenEXR file, every channel FLOAT (ZIP), read back by NeuralDenoiserTest:
  R G B                the noisy colour             albedo.R/G/B, normal.X/Y/Z  its feature buffers
  oidn.R/G/B           OIDN with albedo and normal  (network rt_hdr_alb_nrm)
  oidn_alb.R/G/B       OIDN with albedo only        (rt_hdr_alb)
  oidn_hdr.R/G/B       OIDN with the colour alone   (rt_hdr)
Fixtures:
  cornell-box-64.exr      64x64 (one tile, a multiple of 16), 16 spp, seed 1
  cornell-glossy-37x53.exr  37x53 (padded to 48x64 inside the network), 8 spp, seed 2, and
                          pixels that OIDN sanitises: colour NaN and -1, a firefly of 1e4, albedo
                          2 and -0.5, normal NaN and (3, -3, 0)
"""
import os
import shlex
import subprocess
import sys
import tempfile

import numpy as np
import OpenEXR
import pyoidn

STRAHL = shlex.split(os.environ.get("STRAHL", "java -jar target/strahl.jar"))
OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "denoise")


def render(scene, width, height, spp, seed, tmp):
    path = os.path.join(tmp, "render.exr")
    subprocess.run(STRAHL + ["render", scene, "--width", str(width), "--height", str(height), "--spp", str(spp),
                             "--seed", str(seed), "--aov", "albedo,normal", "--exr-type", "float", "-o", path],
                   check=True, capture_output=True)
    with OpenEXR.File(path, separate_channels=True) as f:
        ch = f.channels()
        rgb = lambda names: np.stack([np.asarray(ch[n].pixels, dtype=np.float32) for n in names], axis=-1)
        return (rgb(["R", "G", "B"]), rgb(["albedo.R", "albedo.G", "albedo.B"]),
                rgb(["normal.X", "normal.Y", "normal.Z"]))


def write(name, color, albedo, normal):
    color, albedo, normal = (np.ascontiguousarray(a, dtype=np.float32) for a in (color, albedo, normal))
    outputs = {
        "oidn": pyoidn.denoise(color, albedo, normal, hdr=True),
        "oidn_alb": pyoidn.denoise(color, albedo, None, hdr=True),
        "oidn_hdr": pyoidn.denoise(color, None, None, hdr=True),
    }
    channels = {}
    for prefix, image, names in [("", color, "RGB"), ("albedo.", albedo, "RGB"), ("normal.", normal, "XYZ")] + \
            [(k + ".", v, "RGB") for k, v in outputs.items()]:
        for i, n in enumerate(names):
            channels[prefix + n] = np.ascontiguousarray(image[..., i], dtype=np.float32)
    path = os.path.join(OUT, name)
    header = {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}
    with OpenEXR.File(header, channels) as f:
        f.write(path)
    print("%s: %dx%d, %d bytes; OIDN output mean %s" % (path, color.shape[1], color.shape[0], os.path.getsize(path),
                                                      outputs["oidn"].reshape(-1, 3).mean(axis=0)))


def main():
    os.makedirs(OUT, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        write("cornell-box-64.exr", *render("scenes/cornell-box.json", 64, 64, 16, 1, tmp))
        color, albedo, normal = render("scenes/cornell-glossy.json", 37, 53, 8, 2, tmp)
        color[10, 5] = [np.nan, 0.5, 0.5]
        color[20, 30] = [-1.0, 0.2, 0.3]
        color[30, 12] = [1e4, 2e4, 5e3]
        albedo[11, 6] = [2.0, -0.5, 0.5]
        normal[12, 7] = [np.nan, 0.0, 1.0]
        normal[13, 8] = [3.0, -3.0, 0.0]
        write("cornell-glossy-37x53.exr", color, albedo, normal)
    print("pyoidn", pyoidn.__version__ if hasattr(pyoidn, "__version__") else "2.5.1.0", "numpy", np.__version__)


if __name__ == "__main__":
    main()
