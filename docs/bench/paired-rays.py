#!/usr/bin/env python3
"""Paired, interleaved `strahl bench` ray runs of two jars on the same meshes (1 thread, a fresh
JVM each, alternating which goes first); prints each pair's rates and the median of the pairs'
ratios NEW/OLD per mesh and ray set. On a shared machine only the ratios mean something.

    python3 docs/bench/paired-rays.py OLD.jar NEW.jar PAIRS MESH [MESH ...] [--rays N] [--java JAVA]
        [--new-java JAVA]    (the same jar twice and --new-java: one JDK against another)
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

ap = argparse.ArgumentParser()
ap.add_argument('old')
ap.add_argument('new')
ap.add_argument('pairs', type=int)
ap.add_argument('meshes', nargs='+')
ap.add_argument('--rays', type=int, default=1 << 18)
ap.add_argument('--runs', type=int, default=3)
ap.add_argument('--java', default='java')
ap.add_argument('--new-java', help='run NEW.jar with this java (default: --java)')
args = ap.parse_args()

ratios, rates = {}, {}
with tempfile.TemporaryDirectory() as tmp:
    for i in range(args.pairs):
        got = {}
        for side in (['old', 'new'] if i % 2 == 0 else ['new', 'old']):
            jar = args.old if side == 'old' else args.new
            java = args.new_java if side == 'new' and args.new_java else args.java
            out = os.path.join(tmp, 'b.json')
            cmd = [java, '-jar', jar, 'bench', '--no-cornell', '--threads', '1', '--runs', str(args.runs),
                   '--rays', str(args.rays), '--json', out]
            for m in args.meshes:
                cmd += ['--mesh', m]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            with open(out) as fh:
                r = json.load(fh)
            got[side] = {(m['name'], x['set']): x['rays_per_second']['median'] for m in r['meshes'] for x in m['rays']}
            for m in r['meshes']:
                got[side][(m['name'], 'build')] = m['bvh_build_triangles_per_second']['median']
        for key in got['old']:
            ratios.setdefault(key, []).append(got['new'][key] / got['old'][key])
            rates.setdefault(key, []).append((got['old'][key], got['new'][key]))
        print(f'pair {i + 1}: ' + ', '.join(f'{k[0]} {k[1]} {v[-1]:.3f}' for k, v in ratios.items()), flush=True)
print('median ratio NEW/OLD (old, new medians in M/s):')
for key, v in ratios.items():
    old = statistics.median(a for a, _ in rates[key]) / 1e6
    new = statistics.median(b for _, b in rates[key]) / 1e6
    print(f'  {key[0]:28s} {key[1]:10s} {statistics.median(v):.3f}  ({old:.2f} -> {new:.2f}; ratios {", ".join(f"{x:.2f}" for x in v)})')
