#!/usr/bin/env python3
"""Reads Radiance HDR files with OpenCV and prints the pixels, for strahl's cross-check test
(HdrOpenCvCrossCheckTest), which writes files with strahl's HdrWriter and compares.

    python3 docs/anchors/hdr_dump.py FILE.hdr [FILE.hdr ...]

Per file one line: "file NAME WIDTH HEIGHT HEX...", the float32 bits of r, g, b per pixel, rows from
the top.
"""
import sys

import cv2
import numpy as np


def main():
    for path in sys.argv[1:]:
        bgr = cv2.imread(path, cv2.IMREAD_UNCHANGED)
        if bgr is None:
            print("unreadable", path)
            continue
        rgb = np.ascontiguousarray(bgr[:, :, ::-1].astype(np.float32))
        h, w = rgb.shape[:2]
        print("file", path, w, h, " ".join(format(int(v), "08x") for v in rgb.view(np.uint32).ravel()))


if __name__ == "__main__":
    main()
