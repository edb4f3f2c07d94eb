#!/usr/bin/env python3
"""strahl's side of the Cornell per-sample variance comparison (see NOTES.md next to this file).

Renders each variant N times with strahl (seeds seed0 .. seed0+N-1, 128x128, 64 spp, unbounded
depth, the DESIGN.md cameras: the same set-up as mitsuba_cornell.py), writes every run as a PFM,
and computes V_abs and V_rel with the statistics code of mitsuba_cornell.py and the SAME mean
image M (the Mitsuba runs' <variant>/mean_pooled.pfm, 6144 spp). Prints the ratio to Mitsuba's
figures from its summary.json.

    python3 docs/anchors/cornell/strahl_cornell.py --jar target/strahl.jar --runs 32 \
        --mitsuba-out /work/staging/anchors/out --out /tmp/strahl-variance [--sampler independent]

--reuse keeps the PFMs already in --out and renders only the missing runs.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_cornell as mc  # noqa: E402  (statistics and PFM reading only; Mitsuba is not imported)


def render_runs(jar, variant, seeds, spp, res, threads, vdir, sampler):
    """All missing runs of one variant in one JVM (StrahlRuns.java: the same images as
    `strahl render --seed s --width res --height res --spp spp --max-depth -1 --look-from ..
    --look-at .. --fov 40 -o run.pfm`, checked bit for bit, without a JVM start per run)."""
    (ox, oy, oz), (tx, ty, tz) = mc.CAMERAS[variant]
    cmd = ['java'] + (['-Dstrahl.sampler=independent'] if sampler == 'independent' else []) + ['-cp', jar, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'StrahlRuns.java'),
           os.path.join(mc.DATA, f'CornellBox-{variant}.obj'), f'{ox},{oy},{oz}', f'{tx},{ty},{tz}',
           str(mc.VFOV), str(res), str(spp), str(seeds[0]), str(len(seeds)), str(threads), vdir]
    subprocess.run(cmd, check=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--jar', default='target/strahl.jar')
    ap.add_argument('--variants', nargs='+', default=mc.VARIANTS, choices=mc.VARIANTS)
    ap.add_argument('--runs', type=int, default=32)
    ap.add_argument('--seed0', type=int, default=1)
    ap.add_argument('--spp', type=int, default=64)
    ap.add_argument('--res', type=int, default=128)
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--sampler', choices=['stratified', 'independent'], default='stratified',
                    help="strahl's sampler: the default stratified one, or independent streams "
                         "(-Dstrahl.sampler=independent), like Mitsuba's default 'independent' sampler")
    ap.add_argument('--mitsuba-out', default='/work/staging/anchors/out',
                    help="mitsuba_cornell.py's --out: mean_pooled.pfm per variant and summary.json")
    ap.add_argument('--out', default='/tmp/strahl-variance')
    ap.add_argument('--reuse', action='store_true', help='keep the PFMs already in --out, render only the missing ones')
    args = ap.parse_args()

    with open(os.path.join(args.mitsuba_out, 'summary.json')) as f:
        mitsuba = json.load(f)
    result = {}
    for variant in args.variants:
        vdir = os.path.join(args.out, variant)
        os.makedirs(vdir, exist_ok=True)
        t0 = time.perf_counter()
        seeds = list(range(args.seed0, args.seed0 + args.runs))
        files = [os.path.join(vdir, f'run_seed{seed:04d}.pfm') for seed in seeds]
        if not args.reuse:
            for f in files:
                if os.path.exists(f):
                    os.remove(f)
        render_runs(args.jar, variant, seeds, args.spp, args.res, args.threads, vdir, args.sampler)
        seconds = time.perf_counter() - t0
        runs = np.stack([mc.read_pfm(p) for p in files]).astype(np.float64)
        M = mc.read_pfm(os.path.join(args.mitsuba_out, variant, 'mean_pooled.pfm')).astype(np.float64)
        mask = mc.light_pixel_mask(variant, args.res)
        s = mc.stats_for(runs, args.spp, M, mask)
        s['mean_vs_mitsuba_pooled_lum'] = float((runs.mean(axis=0) @ mc.LUM).mean() / (M @ mc.LUM).mean() - 1)
        s['seconds'] = seconds
        result[variant] = s
        line = [f'{variant:9s} N={s["n_runs"]}',
                f'V_abs {s["var_per_sample_abs"]:.4g} ± {s["var_per_sample_abs_se"]:.2g}',
                f'V_rel {s["var_per_sample_rel_pooled"]:.4g} ± {s["var_per_sample_rel_pooled_se"]:.2g}',
                f'mean {s["mean_vs_mitsuba_pooled_lum"]:+.4f}']
        mv = mitsuba['variants'].get(variant, {})
        for sampler in ('independent', 'multijitter'):
            m = mv.get('samplers', mv).get(sampler) if isinstance(mv, dict) else None
            if m:
                line.append(f'{sampler}: x{s["var_per_sample_abs"] / m["var_per_sample_abs"]:.2f} abs, '
                            f'x{s["var_per_sample_rel_pooled"] / m["var_per_sample_rel_pooled"]:.2f} rel')
        print(' | '.join(line), flush=True)
    with open(os.path.join(args.out, 'summary.json'), 'w') as f:
        json.dump(result, f, indent=1)


if __name__ == '__main__':
    main()
