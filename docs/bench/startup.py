#!/usr/bin/env python3
"""Start-up cost of the command line's SIMD launcher: wall time of `java -jar JAR ARGS` as users run it
(the launcher starts a second JVM with the Vector API module) against the same command in one JVM
(-Dstrahl.simd=false: no second JVM), and optionally another jar (e.g. before the launcher), run
alternately ROUNDS times; prints median, min and max per variant and the medians' difference.

    python3 docs/bench/startup.py JAR ROUNDS [--old OLD.jar] [-- ARGS...]     (default ARGS: --version)
"""
import argparse
import statistics
import subprocess
import time

ap = argparse.ArgumentParser()
ap.add_argument('jar')
ap.add_argument('rounds', type=int)
ap.add_argument('--old')
ap.add_argument('--java', default='java')
ap.add_argument('args', nargs='*', default=['--version'])
a = ap.parse_args()

variants = {'launcher (two JVMs, SIMD)': [a.java, '-jar', a.jar],
            'one JVM (-Dstrahl.simd=false)': [a.java, '-Dstrahl.simd=false', '-jar', a.jar]}
if a.old:
    variants['old jar'] = [a.java, '-jar', a.old]
times = {k: [] for k in variants}
for i in range(a.rounds):
    order = list(variants) if i % 2 == 0 else list(reversed(variants))
    for k in order:
        t0 = time.perf_counter()
        subprocess.run(variants[k] + a.args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times[k].append(time.perf_counter() - t0)
for k, v in times.items():
    print(f'{k:32s} median {statistics.median(v) * 1000:6.0f} ms  [{min(v) * 1000:.0f}, {max(v) * 1000:.0f}]  ({len(v)} runs)')
m = {k: statistics.median(v) for k, v in times.items()}
ks = list(m)
print(f'launcher cost (median difference): {(m[ks[0]] - m[ks[1]]) * 1000:.0f} ms')
