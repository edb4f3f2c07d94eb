#!/usr/bin/env python3
"""The picture of docs/integrators.md, "Render until clean": the reference, uniform and adaptive
sampling at equal time (linear PFMs of equal_time.py), the adaptive render's samples per pixel
(its .spp.pfm, logarithmic: dark blue at the fewest, yellow at the most) and its per-pixel
absolute error against the reference (x4, grey), each 128x128 shown at 2x.

    python3 docs/anchors/adaptive/figure.py /tmp/adaptive-refs/sphere /tmp/adaptive-eq/sphere05/uniform-0.pfm \
        /tmp/adaptive-eq/sphere05/adaptive-0.pfm docs/images/adaptive-sphere.png
"""
import glob
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'cornell'))
import mitsuba_cornell as mc  # noqa: E402

RAMP = np.array([[0.05, 0.05, 0.3], [0.1, 0.4, 0.8], [0.2, 0.8, 0.6], [0.9, 0.9, 0.2]])


def linear_of(srgb):
    """The linear value write_png turns back into this display value."""
    return np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4)


def spp_colours(spp):
    t = np.log(spp / spp.min()) / max(np.log(spp.max() / spp.min()), 1e-9) * (len(RAMP) - 1)
    i = np.clip(np.floor(t).astype(int), 0, len(RAMP) - 2)
    f = (t - i)[..., None]
    return linear_of(RAMP[i] * (1 - f) + RAMP[i + 1] * f)


def main():
    refdir, uniform, adaptive, out = sys.argv[1:5]
    ref = np.mean([mc.read_pfm(p) for p in sorted(glob.glob(os.path.join(refdir, 'chunk_seed*.pfm')))], axis=0)
    u, a = mc.read_pfm(uniform), mc.read_pfm(adaptive)
    spp = mc.read_pfm(adaptive[:-4] + '.spp.pfm')[..., 0]
    err = lambda x: np.repeat(np.abs(x - ref).mean(axis=2, keepdims=True) * 4, 3, axis=2)
    panels = [ref, u, a, spp_colours(spp), err(u), err(a)]
    gap = np.ones((ref.shape[0], 2, 3))
    row = np.concatenate(sum([[p, gap] for p in panels], [])[:-1], axis=1)
    row = np.repeat(np.repeat(row, 2, axis=0), 2, axis=1)
    import mitsuba as mi
    mi.set_variant('scalar_rgb')
    mc.mi = mi
    mc.write_png(out, row)
    print(f'{out}: spp {spp.min():.0f} .. {spp.max():.0f}, mean {spp.mean():.1f}')


if __name__ == '__main__':
    main()
