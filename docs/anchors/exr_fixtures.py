#!/usr/bin/env python3
"""Writes the EXR fixtures of strahl's ExrReader tests with the OpenEXR library itself.

    python3 docs/anchors/exr_fixtures.py [OUTPUT_DIR]      (default: src/test/resources/exr)

Needs the OpenEXR Python bindings (pip install OpenEXR; they bundle the C++ library) and numpy.
Every pixel value is a simple formula of (x, y) that ExrFixturesTest recomputes in Java, so the
test checks what strahl reads value by value against what OpenEXR wrote. The values are exact in
their pixel type, so no rounding is involved on either side.

Fixtures (for each readable compression C in none, rle, zips, zip, piz):
  rgba-half-C.exr   7x5, R G B A HALF, data window (0,0)-(6,4), increasing y
  mixed-C.exr       9x37, HALF Y, FLOAT Z, UINT id; data window (-3,10)-(5,46) inside the display
                    window (0,0)-(15,63); decreasing y for zip and piz (several chunks each)
(rgba-half-piz and mixed-piz come out stored raw: PIZ's header does not pay for so few pixels
with values that far apart; they test that path of a PIZ file) and
  piz-mixed.exr       61x45, HALF Y, FLOAT Z, UINT id, smooth enough for PIZ to compress both
                      chunks (32 and 13 lines, odd sizes); data window (10,-7)-(70,37), decreasing y
  piz-wide-range.exr  256x124 HALF Y holding every finite non-negative half once (bits = y*256+x):
                      more than 2^14 distinct values, so PIZ takes its 16-bit wavelet path
  refused-*.exr       files strahl must refuse with a message: DWAA, B44, PXR24 compression,
                      a tiled and a two-part file
"""
import os
import sys

import numpy as np
import OpenEXR

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "exr")

COMPRESSIONS = {
    "none": OpenEXR.NO_COMPRESSION,
    "rle": OpenEXR.RLE_COMPRESSION,
    "zips": OpenEXR.ZIPS_COMPRESSION,
    "zip": OpenEXR.ZIP_COMPRESSION,
    "piz": OpenEXR.PIZ_COMPRESSION,
}

# B of rgba-half: special values, cycled by pixel index y*7+x (all exact halfs)
SPECIAL = [0.0, -0.0, 2.0 ** -24, -(2.0 ** -24), 2.0 ** -14, 65504.0, -65504.0, float("inf"), float("-inf"),
           float("nan"), 1.0, 0.5, 3.0 / 1024, 1000.0]


def rgba_half():
    w, h = 7, 5
    y, x = np.mgrid[0:h, 0:w]
    r = (x + 8 * y).astype(np.float16)                     # 0 .. 38
    g = ((x - 3) * 0.25 + y * 0.125).astype(np.float16)    # quarters and eighths, negative too
    b = np.array([SPECIAL[i % len(SPECIAL)] for i in range(w * h)], dtype=np.float64).reshape(h, w).astype(np.float16)
    a = (1.0 - y / 4.0).astype(np.float16)                 # 1, 0.75, 0.5, 0.25, 0
    return {"R": r, "G": g, "B": b, "A": a}


def mixed():
    w, h = 9, 37
    y, x = np.mgrid[0:h, 0:w]                              # relative to the data window's corner
    yy = (x * y).astype(np.float64) / 16
    lum = yy.astype(np.float16)                            # multiples of 1/16 up to 18: exact
    z = np.ldexp((x + 1).astype(np.float64), (y - 18)).astype(np.float32)
    z = np.where(y % 2 == 1, -z, z).astype(np.float32)     # (x+1)·2^(y−18), sign alternating by row
    ids = ((x * 37 + y) * 65537).astype(np.uint64)
    ids[0, 0] = 4294967295                                 # the largest UINT
    return {"Y": lum, "Z": z, "id": ids.astype(np.uint32)}


def piz_mixed():
    w, h = 61, 45
    y, x = np.mgrid[0:h, 0:w]
    lum = ((x + 2 * y) / 64.0).astype(np.float16)                              # multiples of 1/64: exact
    z = np.ldexp((x + 1).astype(np.float64), (y // 4) - 5).astype(np.float32)  # 6-bit significands
    ids = (x + 61 * y).astype(np.uint32)
    return {"Y": lum, "Z": z, "id": ids}


def write(name, header, channels):
    path = os.path.join(OUT, name)
    with OpenEXR.File(header, channels) as f:
        f.write(path)
    print(f"{path}: {os.path.getsize(path)} bytes")


def main():
    os.makedirs(OUT, exist_ok=True)
    for key, comp in COMPRESSIONS.items():
        write(f"rgba-half-{key}.exr", {"compression": comp, "type": OpenEXR.scanlineimage}, rgba_half())
        header = {
            "compression": comp,
            "type": OpenEXR.scanlineimage,
            "dataWindow": (np.array([-3, 10], dtype=np.int32), np.array([5, 46], dtype=np.int32)),
            "displayWindow": (np.array([0, 0], dtype=np.int32), np.array([15, 63], dtype=np.int32)),
            "lineOrder": OpenEXR.DECREASING_Y if key in ("zip", "piz") else OpenEXR.INCREASING_Y,
        }
        write(f"mixed-{key}.exr", header, mixed())

    write("piz-mixed.exr", {
        "compression": OpenEXR.PIZ_COMPRESSION,
        "type": OpenEXR.scanlineimage,
        "dataWindow": (np.array([10, -7], dtype=np.int32), np.array([70, 37], dtype=np.int32)),
        "lineOrder": OpenEXR.DECREASING_Y,
    }, piz_mixed())

    bits = np.arange(256 * 124, dtype=np.uint16).reshape(124, 256)
    write("piz-wide-range.exr", {"compression": OpenEXR.PIZ_COMPRESSION, "type": OpenEXR.scanlineimage},
          {"Y": bits.view(np.float16)})

    small = {"R": np.full((4, 4), 0.5, dtype=np.float16), "G": np.full((4, 4), 0.25, dtype=np.float16)}
    for key, comp in (("dwaa", OpenEXR.DWAA_COMPRESSION), ("b44", OpenEXR.B44_COMPRESSION),
                      ("pxr24", OpenEXR.PXR24_COMPRESSION)):
        write(f"refused-{key}.exr", {"compression": comp, "type": OpenEXR.scanlineimage}, small)
    tiles = OpenEXR.TileDescription()
    tiles.xSize, tiles.ySize, tiles.mode = 2, 2, OpenEXR.ONE_LEVEL
    write("refused-tiled.exr", {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.tiledimage, "tiles": tiles}, small)
    parts = [OpenEXR.Part({"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}, small, "a"),
             OpenEXR.Part({"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}, small, "b")]
    with OpenEXR.File(parts) as f:
        f.write(os.path.join(OUT, "refused-two-parts.exr"))
    print("OpenEXR", OpenEXR.OPENEXR_VERSION, "numpy", np.__version__, "python", sys.version.split()[0])


if __name__ == "__main__":
    main()
