#!/usr/bin/env python3
"""Anchor figures for `strahl bench --anchors FILE.json`, measured side by side on this machine.

1. Mitsuba 3 renders the Cornell Box (CornellBox-Original, 512x512, `path` integrator with
   max_depth -1 and rr_depth 5, independent sampler, box filter, the camera of
   scenes/cornell-box.json) on --threads threads; samples/s = 512*512*spp / wall seconds of
   `mi.render` including the read-back, median of --mitsuba-runs timed runs after one warm-up
   render (which compiles the LLVM kernels). The scene dictionary is the one of
   docs/anchors/cornell/mitsuba_cornell.py. Each back end runs in its own Python process.
   `llvm_ad_rgb` needs Debian's libllvm19; if it cannot be loaded the script says so and goes on
   with `scalar_rgb` alone.
2. `strahl bench --export-rays DIR` writes the triangles and the three ray sets of every mesh
   (the Cornell Box, the three generated meshes and, with --data, the Stanford meshes: the very rays bench traces: same seeds, same
   count), and Embree 4, through the `embreex` package, traces them one ray at a time
   (`rtcIntersect1` / `rtcOccluded1` in embreex's Cython loop, one thread): rays/s per core,
   median of --runs. Embree's BVH build is timed as creating the scene, adding the mesh and the
   commit that the first query triggers (Embree's own threads, all cores). Also measured: the
   binding's floor, rays that miss the scene's box, so that readers can see how much of a
   per-ray figure is embreex's loop rather than Embree's traversal.

Writes --out (JSON): the figures under mitsuba.<variant>.samples_per_second and
embree.meshes.<mesh>.<set>.rays_per_second (median/min/max/runs), with versions and machine.

3. With --alternate N (issue 28, stage 1: the ray kernels side by side): N rounds of Embree on every
   mesh, then `strahl bench` on the same rays (--no-cornell: the rays only, one thread, --strahl-runs
   runs; --strahl-arg passes more, e.g. --strahl-arg=--simd --strahl-arg=off), A B A B. The figures
   of every round are under alternating.rounds, and per mesh and set the ratio strahl/Embree of
   each round (a pair run minutes apart, so that the machine's drift cancels) with its median, min
   and max under alternating.ratios, of rays per second of wall time and of the tracing thread's CPU
   time (on a shared machine the second leaves out what other processes take from the core);
   embree.meshes then holds the medians over the rounds, for `strahl bench --anchors`. Also
   recorded: the CPU's vector flags, strahl's JVM and ray kernel.

Usage (from the repository root, after `mvn -B -q -DskipTests package`):
    python3 docs/bench/anchors.py --out anchors.json
    java -jar target/strahl.jar bench --anchors anchors.json
"""
import argparse
import glob
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))


def stat(values):
    return {'median': statistics.median(values), 'min': min(values), 'max': max(values), 'runs': len(values)}


# ----------------------------------------------------------------------------
# Mitsuba (one process per variant: a process keeps the first variant's JIT state)
# ----------------------------------------------------------------------------
def mitsuba_child(variant, threads, spp, runs, res):
    sys.path.insert(0, os.path.join(REPO, 'docs', 'anchors', 'cornell'))
    import mitsuba as mi
    import drjit as dr
    mi.set_variant(variant)
    dr.set_thread_count(threads)
    import mitsuba_cornell as mc
    mc.mi = mi
    with tempfile.TemporaryDirectory() as meshes:
        sd, _ = mc.build_scene_dict('Original', spp, 'independent', res, meshes)
        scene = mi.load_dict(sd)
        np.array(mi.render(scene, seed=0, spp=spp))                  # warm-up (kernel compilation)
        rates, means = [], None
        for run in range(runs):
            t0 = time.perf_counter()
            img = np.array(mi.render(scene, seed=run + 1, spp=spp))
            rates.append(res * res * spp / (time.perf_counter() - t0))
            means = img.reshape(-1, img.shape[-1])[:, :3].mean(axis=0).tolist()
    return {'version': mi.__version__, 'drjit_version': dr.__version__, 'variant': variant, 'threads': threads,
            'spp': spp, 'width': res, 'height': res, 'samples_per_second': stat(rates), 'image_mean': means}


def mitsuba(variant, args):
    cmd = [sys.executable, os.path.abspath(__file__), '--mitsuba-child', variant, '--threads', str(args.threads),
           '--mitsuba-runs', str(args.mitsuba_runs), '--spp', str(args.spp if variant.startswith('llvm') else args.scalar_spp)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        last = (p.stderr.strip().splitlines() or ['exit code %d' % p.returncode])[-1]
        print(f'anchors: Mitsuba {variant} failed: {last}', file=sys.stderr)
        return None
    return json.loads(p.stdout.strip().splitlines()[-1])


# ----------------------------------------------------------------------------
# Embree
# ----------------------------------------------------------------------------
def embree_mesh(work, desc, runs):
    from embreex import rtcore_scene as rtcs
    from embreex.mesh_construction import TriangleMesh
    name = desc['mesh']
    tris = np.fromfile(os.path.join(work, name + '.triangles.f32'), dtype='<f4').reshape(-1, 3, 3)
    probe_o, probe_d = np.zeros((1, 3), np.float32), np.ones((1, 3), np.float32)
    builds, scene = [], None
    for run in range(runs + 1):
        t0 = time.perf_counter()
        scene = rtcs.EmbreeScene()
        TriangleMesh(scene, tris)
        scene.run(probe_o, probe_d)                                     # commits the scene
        if run > 0:
            builds.append(len(tris) / (time.perf_counter() - t0))
    out = {'triangles': len(tris), 'spheres_not_traced': desc['spheres'], 'build_triangles_per_second': stat(builds)}
    lo, hi = tris.reshape(-1, 3).min(axis=0), tris.reshape(-1, 3).max(axis=0)
    for s in desc['sets']:
        rays = np.fromfile(os.path.join(work, f"{name}.{s['name']}.f32"), dtype='<f4').reshape(-1, 7)
        o, d = np.ascontiguousarray(rays[:, 0:3]), np.ascontiguousarray(rays[:, 3:6])
        tmax = np.ascontiguousarray(np.minimum(rays[:, 6], np.float32(3e38)))
        query = 'OCCLUDED' if s['any_hit'] else 'INTERSECT'
        scene.run(o[:4096], d[:4096], dists=tmax[:4096].copy(), query=query)   # warm-up
        rates, cpu_rates, hits = [], [], None
        for run in range(runs):
            dist = tmax.copy()
            t0, c0 = time.perf_counter(), time.thread_time()
            res = scene.run(o, d, dists=dist, query=query)
            c1, t1 = time.thread_time(), time.perf_counter()
            rates.append(len(rays) / (t1 - t0))
            cpu_rates.append(len(rays) / (c1 - c0))
            hits = int(np.count_nonzero(res >= 0))
        out[s['name']] = {'query': 'any-hit' if s['any_hit'] else 'closest-hit', 'rays': len(rays), 'hits': hits,
                          'rays_per_second': stat(rates), 'rays_per_cpu_second': stat(cpu_rates)}
    # the binding's floor: the incoherent set's directions from origins beyond the box, pointing away
    rays = np.fromfile(os.path.join(work, f'{name}.incoherent.f32'), dtype='<f4').reshape(-1, 7)
    d = np.ascontiguousarray(np.abs(rays[:, 3:6]) + np.float32(1e-3))
    o = np.ascontiguousarray(np.broadcast_to(hi + (hi - lo) + 1, d.shape).astype(np.float32))
    floor = []
    for run in range(runs):
        t0 = time.perf_counter()
        scene.run(o, d)
        floor.append((time.perf_counter() - t0) / len(d) * 1e9)
    out['binding_floor_ns_per_ray'] = stat(floor)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--out', default='anchors.json')
    ap.add_argument('--java', default='java')
    ap.add_argument('--jar', default=os.path.join(REPO, 'target', 'strahl.jar'))
    ap.add_argument('--data', help='also the Stanford meshes under DIR/meshes, as strahl bench --data (research-only data)')
    ap.add_argument('--rays', type=int, default=1 << 20, help='rays per set (strahl bench: 2^20)')
    ap.add_argument('--runs', type=int, default=5, help='timed Embree runs per figure')
    ap.add_argument('--threads', type=int, default=2, help='Mitsuba render threads')
    ap.add_argument('--spp', type=int, default=64, help='spp per Mitsuba llvm_ad_rgb run')
    ap.add_argument('--scalar-spp', type=int, default=8, help='spp per Mitsuba scalar_rgb run')
    ap.add_argument('--mitsuba-runs', type=int, default=3)
    ap.add_argument('--mitsuba', nargs='*', default=['llvm_ad_rgb', 'scalar_rgb'], help='Mitsuba variants (none: skip)')
    ap.add_argument('--no-embree', action='store_true')
    ap.add_argument('--work', help='keep the exported rays here (default: a temporary directory)')
    ap.add_argument('--alternate', type=int, default=0, help='rounds of Embree then strahl bench on the same rays (A B A B)')
    ap.add_argument('--strahl-runs', type=int, default=5, help='with --alternate: timed runs of each strahl bench figure')
    ap.add_argument('--strahl-arg', action='append', default=[], help='with --alternate: one more argument of strahl bench (repeatable)')
    ap.add_argument('--mitsuba-child', help=argparse.SUPPRESS)
    args = ap.parse_args()

    if args.mitsuba_child:
        print(json.dumps(mitsuba_child(args.mitsuba_child, args.threads, args.spp, args.mitsuba_runs, 512)))
        return 0

    result = {'date': time.strftime('%Y-%m-%dT%H:%M:%SZ', time.gmtime()),
              'command': ' '.join([sys.executable] + sys.argv),
              'machine': {'cpu': cpu_model(), 'cores': os.cpu_count(), 'python': platform.python_version(),
                          'load_average_at_start': os.getloadavg()[0]},
              'mitsuba': {}}
    for variant in args.mitsuba:
        print(f'anchors: Mitsuba {variant}, Cornell Box 512x512, {args.threads} threads', file=sys.stderr)
        m = mitsuba(variant, args)
        if m is not None:
            result['mitsuba'][variant] = m
    if not args.no_embree:
        import embreex
        from importlib.metadata import version
        work = args.work or tempfile.mkdtemp(prefix='strahl-anchors-')
        os.makedirs(work, exist_ok=True)
        print(f'anchors: strahl bench --export-rays {work}', file=sys.stderr)
        data = ['--data', args.data] if args.data else []
        subprocess.run([args.java, '-jar', args.jar, 'bench', '--export-rays', work, '--rays', str(args.rays),
                        *data, '--cornell', os.path.join(REPO, 'scenes', 'cornell-box.json')], check=True,
                       stdout=sys.stderr)
        result['embree'] = {'binding': f"embreex {version('embreex')}, rtcIntersect1/rtcOccluded1 per ray, 1 thread",
                            'rays_per_set': args.rays, 'meshes': {}}
        descs = []
        for f in sorted(glob.glob(os.path.join(work, '*.json'))):
            with open(f) as fh:
                descs.append(json.load(fh))
        if args.alternate > 0:
            result['machine']['cpu_flags'] = cpu_flags()
            result['alternating'] = alternate(args, work, descs, data)
            result['embree']['meshes'] = result['alternating']['embree_medians']
        else:
            for desc in descs:
                print(f"anchors: Embree, {desc['mesh']}", file=sys.stderr)
                result['embree']['meshes'][desc['mesh']] = embree_mesh(work, desc, args.runs)
        if not args.work:
            for f in glob.glob(os.path.join(work, '*')):
                os.remove(f)
            os.rmdir(work)
    result['machine']['load_average_at_end'] = os.getloadavg()[0]
    with open(args.out, 'w') as fh:
        json.dump(result, fh, indent=2)
    print(f'anchors: wrote {args.out}', file=sys.stderr)
    return 0


def alternate(args, work, descs, data):
    """Embree on every mesh, then strahl bench on the same rays, args.alternate times; ratios per round."""
    rounds, strahl_info = [], {}
    for i in range(args.alternate):
        embree = {}
        for desc in descs:
            print(f"anchors: round {i + 1}/{args.alternate}, Embree, {desc['mesh']}", file=sys.stderr)
            embree[desc['mesh']] = embree_mesh(work, desc, args.runs)
        print(f'anchors: round {i + 1}/{args.alternate}, strahl bench', file=sys.stderr)
        out = os.path.join(work, 'strahl-bench.out.json')
        subprocess.run([args.java, '-jar', args.jar, 'bench', '--no-cornell', '--threads', '1', '--runs', str(args.strahl_runs),
                        '--rays', str(args.rays), *data, '--cornell', os.path.join(REPO, 'scenes', 'cornell-box.json'),
                        '--json', out, *args.strahl_arg], check=False, stdout=subprocess.DEVNULL, stderr=sys.stderr)
        with open(out) as fh:
            bench = json.load(fh)
        os.remove(out)
        strahl_info = bench['machine']
        strahl = {m['name']: {x['set']: x for x in m['rays'] if x['threads'] == 1} for m in bench['meshes']}
        rounds.append({'embree': embree, 'strahl': strahl, 'load_average': os.getloadavg()[0]})
    ratios, medians = {}, {}
    for desc in descs:
        name = desc['mesh']
        medians[name] = {k: v for k, v in rounds[0]['embree'][name].items() if not isinstance(v, dict) or 'query' not in v}
        for s in desc['sets']:
            set_name = s['name']
            entry = {}
            for kind in ('rays_per_second', 'rays_per_cpu_second'):
                e = [r['embree'][name][set_name][kind]['median'] for r in rounds]
                j = [r['strahl'].get(name, {}).get(set_name, {}).get(kind, {}).get('median') for r in rounds]
                if None not in j:
                    entry[kind] = dict(stat([b / a for a, b in zip(e, j)]), embree=stat(e), strahl=stat(j))
            if entry:
                ratios.setdefault(name, {})[set_name] = entry
            medians[name][set_name] = dict(rounds[0]['embree'][name][set_name],
                                           rays_per_second=stat([r['embree'][name][set_name]['rays_per_second']['median'] for r in rounds]))
    for name, sets in ratios.items():
        for set_name, entry in sets.items():
            for kind, r in entry.items():
                print(f"anchors: {name:30s} {set_name:10s} {'wall' if kind == 'rays_per_second' else 'CPU ':4s} strahl/Embree"
                      f" {r['median']:.2f} [{r['min']:.2f}, {r['max']:.2f}]  (Embree {r['embree']['median'] / 1e6:.2f} M/s,"
                      f" strahl {r['strahl']['median'] / 1e6:.2f} M/s)", file=sys.stderr)
    return {'rounds': rounds, 'ratios': ratios, 'embree_medians': medians, 'strahl_machine': strahl_info,
            'strahl_arguments': args.strahl_arg}


def cpu_flags():
    try:
        with open('/proc/cpuinfo') as fh:
            for line in fh:
                if line.startswith('flags'):
                    return ' '.join(f for f in line.split(':', 1)[1].split() if f.startswith(('avx', 'fma', 'sse4')))
    except OSError:
        pass
    return ''


def cpu_model():
    try:
        with open('/proc/cpuinfo') as fh:
            for line in fh:
                if line.startswith('model name'):
                    return line.split(':', 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


if __name__ == '__main__':
    sys.exit(main())
