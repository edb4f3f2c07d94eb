#!/usr/bin/env python3
"""Adaptive sampling against uniform sampling at equal time (docs/integrators.md, "Render until clean").

Renders a scene with strahl (target/strahl.jar) for the same wall-clock time (--time-limit) with
and without --noise-threshold, alternating A B A B so that a shared machine's load falls on both
alike, and compares each image with a Mitsuba reference (the chunks of mitsuba_refs.py, averaged):

    relMSE  = mean over pixels and channels of (x - ref)^2 / (ref^2 + 0.01)
    mean    = the image's mean luminance over the reference's, minus 1
    worst16 = the largest relative difference of a 16x16 block's mean luminance (blocks darker
              than 0.01 in the reference are left out)

and prints every run, then the medians (min, max) and the ratio of the median relMSEs.

    python3 docs/anchors/adaptive/equal_time.py scenes/cornell-sphere.json /tmp/adaptive-refs/sphere \
        --seconds 20 --threshold 0.05 --reps 3 --out /tmp/adaptive-eq
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'cornell'))
import mitsuba_cornell as mc  # noqa: E402  (PFM files)

REPO = os.path.abspath(os.path.join(HERE, '..', '..', '..'))


def lum(a):
    return 0.2126 * a[..., 0] + 0.7152 * a[..., 1] + 0.0722 * a[..., 2]


def metrics(img, ref, block=16):
    rel = float(np.mean((img - ref) ** 2 / (ref * ref + 0.01)))
    li, lr = lum(img), lum(ref)
    worst = 0.0
    for y in range(0, lr.shape[0], block):
        for x in range(0, lr.shape[1], block):
            r = lr[y:y + block, x:x + block].mean()
            if r >= 0.01:
                d = li[y:y + block, x:x + block].mean() / r - 1
                worst = d if abs(d) > abs(worst) else worst
    return {'relmse': rel, 'mean': float(li.mean() / lr.mean() - 1), 'worst16': worst}


def render(scene, out, seconds, res, threads, seed, threshold):
    stats = out[:-4] + '.json'
    cmd = ['java', '-jar', os.path.join(REPO, 'target', 'strahl.jar'), 'render', scene, '-o', out, '-q',
           '--width', str(res), '--height', str(res), '--threads', str(threads), '--seed', str(seed),
           '--spp', '1000000', '--time-limit', f'{seconds}s', '--stats', stats]
    if threshold > 0:
        cmd += ['--noise-threshold', str(threshold), '--aov', 'spp']
    subprocess.run(cmd, check=True)
    with open(stats) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('refdir', help='a folder of chunk_seed*.pfm from mitsuba_refs.py')
    ap.add_argument('--seconds', type=float, default=20)
    ap.add_argument('--threshold', type=float, default=0.05)
    ap.add_argument('--reps', type=int, default=3)
    ap.add_argument('--res', type=int, default=128)
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--out', required=True)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    chunks = sorted(glob.glob(os.path.join(args.refdir, 'chunk_seed*.pfm')))
    ref = np.mean([mc.read_pfm(p) for p in chunks], axis=0)
    print(f'reference: {len(chunks)} chunks; load {os.getloadavg()[0]:.1f}', flush=True)
    runs = {'uniform': [], 'adaptive': []}
    for rep in range(args.reps):
        for kind in (('adaptive', 'uniform') if rep % 2 else ('uniform', 'adaptive')):
            t = args.threshold if kind == 'adaptive' else 0
            out = os.path.join(args.out, f'{kind}-{rep}.pfm')
            s = render(args.scene, out, args.seconds, args.res, args.threads, 100 + rep, t)
            m = metrics(mc.read_pfm(out), ref)
            m.update(spp_mean=s['spp_mean'], spp_min=s['spp_min'], spp_max=s['spp_max'],
                     converged=s['converged_fraction'], seconds=s['seconds'], load=os.getloadavg()[0])
            runs[kind].append(m)
            print(kind, rep, json.dumps({k: round(v, 5) for k, v in m.items()}), flush=True)
    for kind, ms in runs.items():
        line = []
        for key in ('relmse', 'mean', 'worst16', 'spp_mean', 'converged', 'seconds'):
            v = [m[key] for m in ms]
            line.append(f'{key} {statistics.median(v):.5g} ({min(v):.5g} .. {max(v):.5g})')
        print(kind, 'median (min .. max):', '; '.join(line))
    ratio = statistics.median(m['relmse'] for m in runs['adaptive']) / statistics.median(m['relmse'] for m in runs['uniform'])
    print(f'relMSE adaptive / uniform (medians): {ratio:.3f}')


if __name__ == '__main__':
    main()
