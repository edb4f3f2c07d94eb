#!/usr/bin/env python3
"""Writes the Radiance HDR fixtures of strahl's HdrReader tests with OpenCV's encoder.

    python3 docs/anchors/hdr_fixtures.py [OUTPUT_DIR]      (default: src/test/resources/hdr)

Needs opencv-python-headless and numpy. Each pixel's value is m * 2^(e - 136) for mantissas
m_r, m_g, m_b and an exponent e given by formulas of (x, y) that HdrFixturesTest recomputes (with
the largest mantissa in 128..255, so the encoding is exactly those bytes); odd rows of the wide
images are constant, so that the run-length code has runs as well as literals.

  opencv-rle.hdr     37x6, new-style run-length encoded scanlines (OpenCV's default)
  opencv-flat.hdr    the same pixels, flat (IMWRITE_HDR_COMPRESSION_NONE)
  opencv-narrow.hdr  5x4: narrower than 8 pixels, so flat whatever is asked
"""
import os
import sys

import cv2
import numpy as np

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("src", "test", "resources", "hdr")


def mantissas(x, y):
    """(m_r, m_g, m_b, e) of pixel (x, y); (0, 0, 0, 0) is black."""
    if (x + y) % 11 == 5:
        return 0, 0, 0, 0
    if y % 2 == 1:
        return 200, 100, 50, 130
    return 128 + (x * 37 + y * 11) % 128, (x * 13 + y * 7) % 256, (x * 5 + y * 3) % 128, 118 + (x + 3 * y) % 20


def image(w, h):
    rgb = np.zeros((h, w, 3), dtype=np.float32)
    for y in range(h):
        for x in range(w):
            r, g, b, e = mantissas(x, y)
            if e:
                rgb[y, x] = [np.ldexp(float(m), e - 136) for m in (r, g, b)]
    return rgb[:, :, ::-1].copy()          # OpenCV takes BGR


def write(name, img, params=()):
    path = os.path.join(OUT, name)
    assert cv2.imwrite(path, img, list(params)), path
    print(f"{path}: {os.path.getsize(path)} bytes")


def main():
    os.makedirs(OUT, exist_ok=True)
    write("opencv-rle.hdr", image(37, 6))
    write("opencv-flat.hdr", image(37, 6), (cv2.IMWRITE_HDR_COMPRESSION, cv2.IMWRITE_HDR_COMPRESSION_NONE))
    write("opencv-narrow.hdr", image(5, 4))
    print("OpenCV", cv2.__version__, "numpy", np.__version__, "python", sys.version.split()[0])


if __name__ == "__main__":
    main()
