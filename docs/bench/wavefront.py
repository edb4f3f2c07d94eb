#!/usr/bin/env python3
"""Issue 28, stage 2: the Cornell Box's samples per second of Mitsuba 3 `llvm_ad_rgb`, strahl's scalar
path loop and strahl's wavefront, side by side on this machine (A B A B).

Each of --rounds rounds runs, one after the other:
  1. Mitsuba 3 `llvm_ad_rgb` on the Cornell Box as docs/bench/anchors.py measures it (its own Python
     process: one warm-up render, then --mitsuba-runs timed renders of --spp samples per pixel;
     512x512, unbounded depth, --threads threads; the median);
  2. strahl in one JVM with the Vector API module (docs/bench/WavefrontPairs.java): one warm-up render
     of each, then --pairs renders of the scalar loop and the wavefront in turn, 512x512 at
     --strahl-spp, --threads threads (the medians).
Prints each round's figures and the ratios strahl / Mitsuba of the round; writes --out (JSON) with
every figure, the machine's load (uptime) before each round, CPU model and JVM.

Usage (from the repository root, after `mvn -B -q -DskipTests package`):
    python3 docs/bench/wavefront.py --out wavefront.json
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import types

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import anchors  # noqa: E402  (the Mitsuba driver)


def load():
    return open('/proc/loadavg').read().split()[:3]


def strahl(args):
    cmd = [args.java, '--add-modules', 'jdk.incubator.vector', '-cp', args.jar, os.path.join(HERE, 'WavefrontPairs.java'),
           os.path.join(REPO, 'scenes', 'cornell-box.json'), '512', str(args.strahl_spp), str(args.pairs), str(args.threads),
           ','.join(args.modes)]
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO)
    if p.returncode != 0:
        sys.exit('wavefront: strahl failed: ' + (p.stderr.strip().splitlines() or ['?'])[-1])
    return json.loads(p.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--out', default='wavefront.json')
    ap.add_argument('--java', default='java')
    ap.add_argument('--jar', default=os.path.join(REPO, 'target', 'strahl.jar'))
    ap.add_argument('--rounds', type=int, default=3)
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--spp', type=int, default=64, help='spp per Mitsuba run')
    ap.add_argument('--mitsuba-runs', type=int, default=3)
    ap.add_argument('--strahl-spp', type=int, default=16)
    ap.add_argument('--pairs', type=int, default=3, help='strahl renders of each mode per round')
    ap.add_argument('--modes', nargs='*', default=['off', 'on'], help='strahl.wavefront values (on:N sets the batch)')
    args = ap.parse_args()
    margs = types.SimpleNamespace(threads=args.threads, spp=args.spp, scalar_spp=8, mitsuba_runs=args.mitsuba_runs)
    rounds = []
    for r in range(args.rounds):
        before = load()
        m = anchors.mitsuba('llvm_ad_rgb', margs)
        s = strahl(args)
        msps = m['samples_per_second']['median'] if m else None
        row = {'load_before': before, 'mitsuba_llvm_ad_rgb': m, 'strahl': s, 'load_after': load()}
        if msps:
            row['ratios'] = {mode: s[mode]['samples_per_second']['median'] / msps for mode in s}
        rounds.append(row)
        print(f'round {r + 1} (load {" ".join(before)}): Mitsuba llvm_ad_rgb {msps / 1e3 if msps else float("nan"):.0f} k/s; '
              + '; '.join(f'strahl {mode} {s[mode]["samples_per_second"]["median"] / 1e3:.0f} k/s'
                          + (f' ({row["ratios"][mode]:.2f}x)' if msps else '') for mode in s), flush=True)
    summary = {}
    for mode in args.modes:
        ratios = [row['ratios'][mode] for row in rounds if 'ratios' in row]
        if ratios:
            summary[mode] = {'median': statistics.median(ratios), 'min': min(ratios), 'max': max(ratios), 'rounds': len(ratios)}
            print(f'strahl {mode} / Mitsuba llvm_ad_rgb: median {summary[mode]["median"]:.2f} (min {summary[mode]["min"]:.2f}, '
                  f'max {summary[mode]["max"]:.2f})')
    jv = subprocess.run([args.java, '-version'], capture_output=True, text=True).stderr.strip().splitlines()
    with open(args.out, 'w') as f:
        json.dump({'machine': {'cpu': anchors.cpu_model(), 'jvm': jv}, 'rounds': rounds, 'ratio_to_mitsuba_llvm': summary}, f, indent=1)


if __name__ == '__main__':
    main()
