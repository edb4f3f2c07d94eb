#!/usr/bin/env python3
"""Mitsuba 3 variance anchor for the five Cornell Box variants.

For every variant and every requested sampler this script renders N independent
runs (different seeds) at a fixed spp with Mitsuba's `path` integrator
(max_depth -1, rr_depth 5, box filter), writes each run as a PFM, and computes
the per-sample variance:

    V_abs = spp * mean_{pixels, channels} s2(p, c)
    V_rel = spp * mean_{pixels, channels} s2(p, c) / (m(p, c)^2 + 0.01)

where s2 is the unbiased (ddof=1) variance of the pixel value across the N runs
and m is a mean image (`..._rel_pooled` in summary.json uses the mean of every
run of every sampler of that variant, saved as <variant>/mean_pooled.pfm;
`..._rel_own` the mean of the runs of that sampler).  Uncertainties are
delete-one jackknife standard errors over runs.  Outputs go to --out:
<variant>/<sampler>/run_seed####.pfm, <variant>/mean_pooled.pfm, PNG previews,
<variant>/meshes/*.ply (the per-material meshes Mitsuba loads) and summary.json.
Renders are deterministic for a given seed, sampler and Mitsuba variant.

The scene is built from the OBJ/MTL files with the conventions of
docs/conventions.md (see NOTES.md next to this script).

Usage (defaults shown):
    python3 mitsuba_cornell.py --variants Original Empty-RG Mirror Sphere Glossy \
        --samplers independent multijitter ldsampler --spp 64 --runs 32 \
        --res 128 --mi-variant llvm_ad_rgb --threads 2 \
        --out /work/staging/anchors/out
"""
import argparse
import json
import math
import os
import platform
import shlex
import struct
import sys
import time

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DATA = os.path.join(REPO, 'src', 'test', 'resources', 'cornell')     # the public-domain Williams College files
VARIANTS = ['Original', 'Empty-RG', 'Mirror', 'Sphere', 'Glossy']
CAMERAS = {  # origin, target (up = +Y, vertical fov 40 deg) -- DESIGN.md section 3
    'Original': ((0, 1, 3.9), (0, 1, 0)),
    'Empty-RG': ((0, 1, 3.9), (0, 1, 0)),
    'Mirror':   ((0, 1, 3.9), (0, 1, 0)),
    'Sphere':   ((0, 0.8, 3.9), (0, 0.8, 0)),
    'Glossy':   ((0, 0.8, 3.9), (0, 0.8, 0)),
}
VFOV = 40.0
REF_ORIGINAL_128 = os.path.join(REPO, 'src', 'test', 'resources', 'golden', 'cornell-original_maxdepth-inf_128.pfm')


def light_pixel_mask(variant, res):
    """Pixels whose square touches the bounding box (dilated by one pixel) of the directly seen
    emitter triangles, projected with the DESIGN.md camera model. Diagnostic only: edge pixels of
    the light carry most of the absolute variance (coverage noise of a 17-radiance emitter)."""
    groups, mtllib = parse_obj(os.path.join(DATA, f'CornellBox-{variant}.obj'))
    mats = parse_mtl(os.path.join(DATA, mtllib))
    o, t = (np.array(x, float) for x in CAMERAS[variant])
    f = (t - o) / np.linalg.norm(t - o)
    r = np.cross(f, [0, 1, 0]); r /= np.linalg.norm(r)
    u = np.cross(r, f)
    tt = math.tan(math.radians(VFOV) / 2)
    mask = np.zeros((res, res), bool)
    for (mname, _), (pos, _) in groups.items():
        if max(mats[mname]['Ke']) <= 0:
            continue
        d = pos.reshape(-1, 3) - o
        z = d @ f
        px = ((d @ r) / z / tt + 1) * res / 2
        py = (1 - (d @ u) / z / tt) * res / 2
        x0, x1 = int(math.floor(px.min())) - 1, int(math.ceil(px.max())) + 1
        y0, y1 = int(math.floor(py.min())) - 1, int(math.ceil(py.max())) + 1
        mask[max(y0, 0):min(y1, res), max(x0, 0):min(x1, res)] = True
    return mask


# ----------------------------------------------------------------------------
# OBJ / MTL
# ----------------------------------------------------------------------------
def strip_comment(line):
    i = line.find('#')
    return (line if i < 0 else line[:i]).strip()


def parse_mtl(path):
    mats, cur = {}, None
    with open(path) as f:
        for raw in f:
            line = strip_comment(raw)
            if not line:
                continue
            tok = line.split()
            key = tok[0]
            if key == 'newmtl':
                cur = {'Kd': [0.0] * 3, 'Ks': [0.0] * 3, 'Ke': [0.0] * 3,
                       'Ns': 0.0, 'Ni': 1.0, 'illum': 2}
                mats[tok[1]] = cur
            elif cur is None:
                continue
            elif key in ('Kd', 'Ks', 'Ke'):
                vals = [float(x) for x in tok[1:4]]
                if len(vals) == 1:
                    vals = vals * 3
                cur[key] = vals
            elif key in ('Ns', 'Ni'):
                cur[key] = float(tok[1])
            elif key == 'illum':
                cur['illum'] = int(tok[1])
    return mats


def parse_obj(path):
    """Returns {(material, has_vn): (positions[T,3,3], normals[T,3,3] or None)}.

    Faces belong to the last `usemtl`; polygons are fan-triangulated (v0, vi, vi+1).
    """
    V, N = [], []
    groups = {}
    mtl, mtllib = None, None
    with open(path) as f:
        for raw in f:
            line = strip_comment(raw)
            if not line:
                continue
            tok = line.split()
            key = tok[0]
            if key == 'v':
                V.append([float(x) for x in tok[1:4]])
            elif key == 'vn':
                N.append([float(x) for x in tok[1:4]])
            elif key == 'usemtl':
                mtl = tok[1]
            elif key == 'mtllib':
                mtllib = tok[1]
            elif key == 'f':
                vi, ni = [], []
                for c in tok[1:]:
                    parts = c.split('/')
                    a = int(parts[0])
                    vi.append(a - 1 if a > 0 else len(V) + a)
                    if len(parts) >= 3 and parts[2]:
                        b = int(parts[2])
                        ni.append(b - 1 if b > 0 else len(N) + b)
                has_n = len(ni) == len(vi)
                g = groups.setdefault((mtl, has_n), ([], []))
                for k in range(1, len(vi) - 1):
                    g[0].append([V[vi[0]], V[vi[k]], V[vi[k + 1]]])
                    if has_n:
                        g[1].append([N[ni[0]], N[ni[k]], N[ni[k + 1]]])
    out = {}
    for key, (p, n) in groups.items():
        out[key] = (np.asarray(p, np.float32), np.asarray(n, np.float32) if key[1] else None)
    return out, mtllib


def write_ply(path, pos, nrm):
    """Binary PLY, three vertices per triangle (no sharing), optional vertex normals."""
    T = pos.shape[0]
    verts = pos.reshape(-1, 3)
    if nrm is not None:
        verts = np.concatenate([verts, nrm.reshape(-1, 3)], axis=1)
    header = ['ply', 'format binary_little_endian 1.0', f'element vertex {3 * T}',
              'property float x', 'property float y', 'property float z']
    if nrm is not None:
        header += ['property float nx', 'property float ny', 'property float nz']
    header += [f'element face {T}', 'property list uchar int vertex_indices', 'end_header']
    faces = np.zeros(T, dtype=[('n', 'u1'), ('i', '<i4', (3,))])
    faces['n'] = 3
    faces['i'] = np.arange(3 * T, dtype=np.int32).reshape(T, 3)
    tmp = path + '.tmp'
    with open(tmp, 'wb') as f:
        f.write(('\n'.join(header) + '\n').encode('ascii'))
        f.write(verts.astype('<f4').tobytes())
        f.write(faces.tobytes())
    os.replace(tmp, path)


# ----------------------------------------------------------------------------
# MTL -> Mitsuba BSDF (DESIGN.md section 3)
# ----------------------------------------------------------------------------
def rgb(v):
    return {'type': 'rgb', 'value': [float(x) for x in v]}


def bsdf_for(m):
    """Returns (mitsuba dict, human-readable description)."""
    kd, ks = np.array(m['Kd']), np.array(m['Ks'])
    illum = m['illum']
    if illum == 5:
        return ({'type': 'twosided', 'bsdf': {'type': 'conductor', 'material': 'none',
                                               'specular_reflectance': rgb(ks)}},
                f'twosided(conductor material=none, specular_reflectance={ks.tolist()})'
                ' = perfect mirror, Fresnel 1')
    if illum == 7:
        return ({'type': 'dielectric', 'int_ior': float(m['Ni']), 'ext_ior': 1.0},
                f"dielectric int_ior={m['Ni']} ext_ior=1.0 (one-sided by nature, no absorption)")
    if illum <= 2 and ks.max() == 0:
        return ({'type': 'twosided', 'bsdf': {'type': 'diffuse', 'reflectance': rgb(kd)}},
                f'twosided(diffuse reflectance={kd.tolist()})')
    if illum == 2 and ks.max() > 0:
        s = (kd + ks).max()
        if s > 1:
            kd, ks = kd / s, ks / s
        alpha = math.sqrt(2.0 / (m['Ns'] + 2.0))
        # f = Kd'/pi + Ks' * f_beckmann(alpha, F=1)
        #   = (1-w) * [Kd'/(1-w)]/pi + w * [Ks'/w] * f_beckmann      with w = max(Ks')
        w = float(ks.max())
        kd_b, ks_b = kd / (1 - w), ks / w
        d = {'type': 'twosided', 'bsdf': {
            'type': 'blendbsdf', 'weight': w,
            'bsdf_0': {'type': 'diffuse', 'reflectance': rgb(kd_b)},
            'bsdf_1': {'type': 'roughconductor', 'material': 'none', 'distribution': 'beckmann',
                       'alpha': alpha, 'specular_reflectance': rgb(ks_b)}}}
        desc = (f'twosided(blendbsdf weight={w:.6f}: (1-w)*diffuse({np.round(kd_b, 6).tolist()}) + '
                f'w*roughconductor(beckmann, alpha={alpha:.6f}, material=none, '
                f'specular_reflectance={np.round(ks_b, 6).tolist()})) '
                f'== Kd\'={np.round(kd, 6).tolist()} Lambert + Ks\'={np.round(ks, 6).tolist()} Beckmann, F=1'
                + (f' (Kd, Ks divided by max(Kd+Ks)={s:.4f})' if s > 1 else ''))
        return d, desc
    raise ValueError(f'unsupported MTL illum {illum}')


def build_scene_dict(variant, spp, sampler, res, mesh_dir):
    obj = os.path.join(DATA, f'CornellBox-{variant}.obj')
    groups, mtllib = parse_obj(obj)
    mats = parse_mtl(os.path.join(DATA, mtllib))
    os.makedirs(mesh_dir, exist_ok=True)
    origin, target = CAMERAS[variant]
    scene = {
        'type': 'scene',
        'integrator': {'type': 'path', 'max_depth': -1, 'rr_depth': 5, 'hide_emitters': False},
        'sensor': {
            'type': 'perspective', 'fov': VFOV, 'fov_axis': 'y',
            'to_world': mi.ScalarTransform4f().look_at(origin=list(origin), target=list(target),
                                                       up=[0, 1, 0]),
            'film': {'type': 'hdrfilm', 'width': res, 'height': res, 'rfilter': {'type': 'box'},
                     'pixel_format': 'rgb', 'component_format': 'float32'},
            'sampler': {'type': sampler, 'sample_count': spp},
        },
    }
    mapping = {}
    for (mname, has_n), (pos, nrm) in sorted(groups.items(), key=lambda kv: (kv[0][0], kv[0][1])):
        m = mats[mname]
        fname = os.path.join(mesh_dir, f"{mname}{'_vn' if has_n else ''}.ply")
        write_ply(fname, pos, nrm)
        bsdf, desc = bsdf_for(m)
        shape = {'type': 'ply', 'filename': fname, 'bsdf': bsdf,
                 # without vn: flat (geometric) normals; Mitsuba would otherwise compute smooth ones
                 'face_normals': not has_n}
        ke = np.array(m['Ke'])
        if ke.max() > 0:
            shape['emitter'] = {'type': 'area', 'radiance': rgb(ke)}
            desc += f' + area emitter radiance={ke.tolist()} (one-sided, along geometric normal)'
        scene[f"shape_{mname}{'_vn' if has_n else ''}"] = shape
        mapping[f"{mname}{' (vn)' if has_n else ''}"] = {
            'illum': m['illum'], 'triangles': int(pos.shape[0]), 'mitsuba': desc}
    return scene, mapping


# ----------------------------------------------------------------------------
# images
# ----------------------------------------------------------------------------
def write_pfm(path, img):
    """img: (H, W, 3) top row first. PFM: 'PF', little-endian (scale -1), bottom row first."""
    h, w, _ = img.shape
    tmp = path + '.tmp'
    with open(tmp, 'wb') as f:
        f.write(f'PF\n{w} {h}\n-1.0\n'.encode('ascii'))
        f.write(np.ascontiguousarray(np.flipud(img).astype('<f4')).tobytes())
    os.replace(tmp, path)


def read_pfm(path):
    with open(path, 'rb') as f:
        assert f.readline().strip() == b'PF'
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype='<f4' if scale < 0 else '>f4')
    return np.flipud(data.reshape(h, w, 3)).astype(np.float64)


def write_png(path, img):
    x = np.clip(np.nan_to_num(img, nan=0.0), 0.0, 1.0)
    x = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    mi.Bitmap(np.ascontiguousarray((x * 255 + 0.5).astype(np.uint8))).write(path)


# ----------------------------------------------------------------------------
# statistics
# ----------------------------------------------------------------------------
def per_sample_var(runs, spp, denom_mean=None):
    """runs: (N, H, W, 3). Returns (abs, rel) per-sample variance estimates."""
    s2 = runs.var(axis=0, ddof=1) * spp
    m = runs.mean(axis=0) if denom_mean is None else denom_mean
    return float(s2.mean()), float((s2 / (m * m + 0.01)).mean())


def jackknife(runs, spp, denom_mean=None):
    n = runs.shape[0]
    est = np.array([per_sample_var(np.delete(runs, i, axis=0), spp, denom_mean) for i in range(n)])
    se = np.sqrt((n - 1) / n * ((est - est.mean(axis=0)) ** 2).sum(axis=0))
    return se  # (se_abs, se_rel)


def stats_for(runs, spp, pooled_mean, light_mask):
    n = runs.shape[0]
    a, r_own = per_sample_var(runs, spp)
    _, r_pool = per_sample_var(runs, spp, pooled_mean)
    se_a, se_r_own = jackknife(runs, spp)
    _, se_r_pool = jackknife(runs, spp, pooled_mean)
    h = n // 2
    half = [per_sample_var(runs[:h], spp, pooled_mean), per_sample_var(runs[h:2 * h], spp, pooled_mean)]
    # strahl-style "two runs, half against half": mean over disjoint pairs of (A-B)^2/2 * spp
    pairs = [float(((runs[2 * k] - runs[2 * k + 1]) ** 2 / 2 * spp).mean()) for k in range(h)]
    pairs_rel = [float(((runs[2 * k] - runs[2 * k + 1]) ** 2 / 2 * spp / (pooled_mean ** 2 + 0.01)).mean())
                 for k in range(h)]
    finite = np.isfinite(runs)
    lum = runs @ LUM
    s2 = runs.var(axis=0, ddof=1) * spp
    pooled_black = (pooled_mean @ LUM) <= 0
    return {
        'n_runs': n,
        'var_per_sample_abs': a, 'var_per_sample_abs_se': float(se_a),
        'var_per_sample_rel_pooled': r_pool, 'var_per_sample_rel_pooled_se': float(se_r_pool),
        'var_per_sample_rel_own': r_own, 'var_per_sample_rel_own_se': float(se_r_own),
        'split_halves_abs': [half[0][0], half[1][0]],
        'split_halves_rel_pooled': [half[0][1], half[1][1]],
        'pairwise_abs_per_pair': pairs,
        'pairwise_abs_pair_spread_rel_sd': float(np.std(pairs, ddof=1) / np.mean(pairs)) if h > 1 else None,
        'pairwise_rel_pooled_per_pair': pairs_rel,
        'pairwise_rel_pooled_pair_spread_rel_sd': float(np.std(pairs_rel, ddof=1) / np.mean(pairs_rel)) if h > 1 else None,
        'image_mean_rgb': runs.mean(axis=(0, 1, 2)).tolist(),
        'nonfinite_values': int((~finite).sum()),
        'negative_values': int((runs < 0).sum()),
        'black_pixels_per_run_max': int((lum <= 0).sum(axis=(1, 2)).max()),
        'black_pixels_in_pooled_mean': int(pooled_black.sum()),
        'black_pixels_per_run_max_where_pooled_mean_not_black': int(((lum <= 0) & ~pooled_black).sum(axis=(1, 2)).max()),
        'light_mask_pixels': int(light_mask.sum()),
        'var_per_sample_abs_excl_light_px': float(s2[~light_mask].mean()),
        'var_per_sample_abs_fraction_in_light_px': float(s2[light_mask].sum() / s2.sum()),
        'var_per_sample_rel_pooled_excl_light_px': float((s2 / (pooled_mean ** 2 + 0.01))[~light_mask].mean()),
    }


LUM = np.array([0.2126, 0.7152, 0.0722])


def compare_means(runs, base, block=16):
    """Unbiasedness check of `runs` against `base` (both (N, H, W, 3), independent seeds):
    whole-image luminance difference and z-score, and z-scores of block x block luminance means."""
    def blocks(r):
        n, h, w, _ = r.shape
        return (r @ LUM).reshape(n, h // block, block, w // block, block).mean(axis=(2, 4))
    g, gb = (runs @ LUM).mean(axis=(1, 2)), (base @ LUM).mean(axis=(1, 2))
    zg = (g.mean() - gb.mean()) / math.sqrt(g.var(ddof=1) / len(g) + gb.var(ddof=1) / len(gb))
    b, bb = blocks(runs), blocks(base)
    se = np.sqrt(b.var(axis=0, ddof=1) / len(b) + bb.var(axis=0, ddof=1) / len(bb))
    ok = se > 0
    z = (b.mean(axis=0) - bb.mean(axis=0))[ok] / se[ok]
    return {'whole_image_luminance_rel_diff': float(g.mean() / gb.mean() - 1), 'whole_image_z': float(zg),
            f'blocks_{block}px_max_abs_z': float(np.abs(z).max()), f'blocks_{block}px_n_abs_z_gt_4': int((np.abs(z) > 4).sum()),
            'n_blocks': int(ok.sum())}


# ----------------------------------------------------------------------------
def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--variants', nargs='+', default=VARIANTS, choices=VARIANTS)
    ap.add_argument('--samplers', nargs='+', default=['independent', 'multijitter', 'ldsampler'])
    ap.add_argument('--spp', type=int, default=64)
    ap.add_argument('--runs', type=int, default=32, help='independent runs (seeds) per variant and sampler')
    ap.add_argument('--seed0', type=int, default=1, help='seeds are seed0 .. seed0+runs-1')
    ap.add_argument('--res', type=int, default=128)
    ap.add_argument('--mi-variant', default='llvm_ad_rgb')
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--out', default='/work/staging/anchors/out')
    ap.add_argument('--reuse', action='store_true', help='reuse existing run PFMs instead of re-rendering')
    args = ap.parse_args()

    global mi, dr
    import mitsuba as mi
    import drjit as dr
    mi.set_variant(args.mi_variant)
    dr.set_thread_count(args.threads)

    os.makedirs(args.out, exist_ok=True)
    command = ' '.join(shlex.quote(x) for x in [sys.executable, os.path.abspath(__file__)] + sys.argv[1:])
    seeds = list(range(args.seed0, args.seed0 + args.runs))
    summary = {
        'command': command, 'cwd': os.getcwd(),
        'mitsuba_version': mi.__version__, 'drjit_version': dr.__version__,
        'mitsuba_variant': args.mi_variant, 'threads': args.threads,
        'python': platform.python_version(), 'machine': platform.machine(), 'cpus': os.cpu_count(),
        'resolution': [args.res, args.res], 'spp': args.spp, 'seeds': seeds,
        'integrator': {'type': 'path', 'max_depth': -1, 'rr_depth': 5}, 'rfilter': 'box',
        'definitions': {
            'mean_vs_independent': 'unbiasedness check of this sampler against the independent sampler: '
                                   'whole-image luminance and 16x16-pixel block means, z-scores over runs',
            'var_per_sample_abs': 'spp * mean over pixels and RGB channels of the ddof=1 variance across runs',
            'var_per_sample_rel_pooled': 'spp * mean of var/(M^2+0.01), M = mean of ALL runs of ALL samplers '
                                         'of the variant (saved as mean_pooled.pfm; reuse it as the denominator)',
            'var_per_sample_rel_own': 'same, M = mean of the runs of this sampler',
            '*_se': 'delete-one jackknife standard error over runs',
            'pairwise_abs_per_pair': 'the two-run estimate (A-B)^2/2*spp averaged over pixels, one per disjoint pair',
        },
        'variants': {},
    }
    t_all = time.perf_counter()
    for variant in args.variants:
        vdir = os.path.join(args.out, variant)
        scene_info, runs_by_sampler, timing = None, {}, {}
        for sampler in args.samplers:
            sdir = os.path.join(vdir, sampler)
            os.makedirs(sdir, exist_ok=True)
            t0 = time.perf_counter()
            sd, mapping = build_scene_dict(variant, args.spp, sampler, args.res, os.path.join(vdir, 'meshes'))
            scene = mi.load_dict(sd)
            t_load = time.perf_counter() - t0
            scene_info = mapping
            imgs, per_run = [], []
            for seed in seeds:
                path = os.path.join(sdir, f'run_seed{seed:04d}.pfm')
                if args.reuse and os.path.exists(path):
                    imgs.append(read_pfm(path))
                    continue
                t1 = time.perf_counter()
                img = np.array(mi.render(scene, seed=seed, spp=args.spp), dtype=np.float64)
                per_run.append(time.perf_counter() - t1)
                img = img[:, :, :3]
                write_pfm(path, img)
                imgs.append(img)
            runs = np.stack(imgs)
            runs_by_sampler[sampler] = runs
            if per_run:
                steady = per_run[1:] if len(per_run) > 1 else per_run
                timing[sampler] = {
                    'scene_load_s': t_load, 'first_run_s': per_run[0],
                    'median_run_s_after_first': float(np.median(steady)),
                    'total_render_s': float(np.sum(per_run)),
                    'per_run_s': [round(x, 4) for x in per_run],
                    'msamples_per_s_median': args.res * args.res * args.spp / float(np.median(steady)) / 1e6,
                }
            print(f'[{variant:8s} {sampler:11s}] {len(imgs)} runs, '
                  + (f"median {timing[sampler]['median_run_s_after_first']:.3f} s/run, "
                     f"first {timing[sampler]['first_run_s']:.2f} s" if sampler in timing else 'reused'),
                  flush=True)
            # preview of the first run
            write_png(os.path.join(vdir, f'preview_{sampler}_seed{seeds[0]:04d}.png'), runs[0])
        pooled = np.concatenate(list(runs_by_sampler.values())).mean(axis=0)
        write_pfm(os.path.join(vdir, 'mean_pooled.pfm'), pooled)
        write_png(os.path.join(vdir, 'mean_pooled.png'), pooled)
        light_mask = light_pixel_mask(variant, args.res)
        check = None
        if variant == 'Original' and args.res == 128 and os.path.exists(REF_ORIGINAL_128):
            ref = read_pfm(REF_ORIGINAL_128)
            check = {'reference': REF_ORIGINAL_128,
                     'relMSE_pooled_mean_vs_ref': float(((pooled - ref) ** 2 / (ref ** 2 + 0.01)).mean()),
                     'mean_rgb_ratio_pooled_over_ref': (pooled.mean(axis=(0, 1)) / ref.mean(axis=(0, 1))).tolist()}
            for smp, r in runs_by_sampler.items():
                m = r.mean(axis=0)
                check[smp] = {'relMSE_mean_vs_ref': float(((m - ref) ** 2 / (ref ** 2 + 0.01)).mean()),
                              'mean_rgb_ratio_over_ref': (m.mean(axis=(0, 1)) / ref.mean(axis=(0, 1))).tolist()}
            print('    check vs reference:', check, flush=True)
        vsum = {'camera': {'origin': CAMERAS[variant][0], 'target': CAMERAS[variant][1], 'up': [0, 1, 0],
                           'vfov_deg': VFOV},
                'check_against_reference': check,
                'materials': scene_info, 'pooled_spp': int(sum(r.shape[0] for r in runs_by_sampler.values()) * args.spp),
                'samplers': {}}
        for sampler, runs in runs_by_sampler.items():
            st = stats_for(runs, args.spp, pooled, light_mask)
            if sampler != 'independent' and 'independent' in runs_by_sampler:
                st['mean_vs_independent'] = compare_means(runs, runs_by_sampler['independent'])
                print(f'    {sampler:11s} mean vs independent: {st["mean_vs_independent"]}', flush=True)
            st['timing'] = timing.get(sampler)
            st['run_files'] = os.path.join(vdir, sampler, 'run_seed####.pfm')
            vsum['samplers'][sampler] = st
            print(f"    {sampler:11s} V_abs={st['var_per_sample_abs']:.5g} ± {st['var_per_sample_abs_se']:.2g}"
                  f"  V_rel={st['var_per_sample_rel_pooled']:.5g} ± {st['var_per_sample_rel_pooled_se']:.2g}"
                  f"  halves_abs={st['split_halves_abs'][0]:.4g}/{st['split_halves_abs'][1]:.4g}"
                  f"  nonfinite={st['nonfinite_values']} black={st['black_pixels_per_run_max']}", flush=True)
        summary['variants'][variant] = vsum
    summary['wall_time_total_s'] = time.perf_counter() - t_all
    out_json = os.path.join(args.out, 'summary.json')
    with open(out_json + '.tmp', 'w') as f:
        json.dump(summary, f, indent=1)
    os.replace(out_json + '.tmp', out_json)
    print('wrote', out_json, f"({summary['wall_time_total_s']:.1f} s)")


if __name__ == '__main__':
    main()
