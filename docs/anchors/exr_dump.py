#!/usr/bin/env python3
"""Reads EXR files with the OpenEXR library and prints what it sees, for strahl's cross-check test
(ExrOpenExrCrossCheckTest), which writes files with strahl's ExrWriter and compares.

    python3 docs/anchors/exr_dump.py FILE.exr [FILE.exr ...]

Per file: a line "file NAME WIDTH HEIGHT COMPRESSION_CODE", then one line per channel:
"channel NAME TYPE HEX...", TYPE being HALF, FLOAT or UINT and HEX the samples' bits (4 hex digits
for HALF, 8 otherwise), rows from the top. For FLOAT channels a line "as-half NAME HEX..." follows:
numpy's IEEE conversion of the same samples to half, to check strahl's own float-to-half rounding.
"""
import sys

import numpy as np
import OpenEXR

TYPES = {np.dtype(np.float16): ("HALF", np.uint16, 4), np.dtype(np.float32): ("FLOAT", np.uint32, 8),
         np.dtype(np.uint32): ("UINT", np.uint32, 8)}


def hexes(values, dtype, digits):
    return " ".join(format(int(v), "0%dx" % digits) for v in values.view(dtype).ravel())


def main():
    for path in sys.argv[1:]:
        with OpenEXR.File(path, separate_channels=True) as f:
            header = f.header()
            (x0, y0), (x1, y1) = header["dataWindow"]
            print("file", path, int(x1 - x0 + 1), int(y1 - y0 + 1), int(header["compression"].value))
            for name, channel in sorted(f.channels().items()):
                pixels = channel.pixels
                kind, dtype, digits = TYPES[pixels.dtype]
                print("channel", name, kind, hexes(pixels, dtype, digits))
                if kind == "FLOAT":
                    print("as-half", name, hexes(pixels.astype(np.float16), np.uint16, 4))


if __name__ == "__main__":
    main()
