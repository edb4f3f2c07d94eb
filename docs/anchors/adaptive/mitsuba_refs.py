#!/usr/bin/env python3
"""Mitsuba 3 references for the adaptive-sampling measurements (docs/integrators.md, "Render until
clean"): strahl's own Cornell scene files (scenes/cornell-sphere.json, scenes/cornell-glossy.json)
rebuilt in Mitsuba -- the room from the scene's OBJ/MTL with the mapping of
../cornell/mitsuba_cornell.py, and the scene file's *analytic* spheres with their materials (the
data set's tessellated spheres, which mitsuba_cornell.py loads, differ from them at the silhouette
and in the caustic) -- rendered in chunks of --spp samples with seeds seed0, seed0+1, ... and
averaged. Each chunk is kept as a PFM, so a run that is stopped can be continued (--chunks raised).

    python3 docs/anchors/adaptive/mitsuba_refs.py scenes/cornell-sphere.json --res 128 --spp 4096 \
        --chunks 8 --out /tmp/adaptive-refs/sphere

writes chunk_seedNNNN.pfm and mean.pfm (the mean of all chunks present) to --out.
"""
import argparse
import glob
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'cornell'))
import mitsuba_cornell as mc  # noqa: E402  (OBJ/MTL parsing, the MTL -> BSDF table, PFM files)


def sphere_bsdf(m):
    """A scene file's sphere material as a Mitsuba BSDF, by the same table as the MTL's."""
    t = m['type']
    if t == 'mirror':
        return mc.bsdf_for({'Kd': [0, 0, 0], 'Ks': m['reflectance'], 'illum': 5, 'Ns': 0, 'Ni': 1})[0]
    if t == 'dielectric':
        return mc.bsdf_for({'Kd': [0, 0, 0], 'Ks': [0, 0, 0], 'illum': 7, 'Ns': 0, 'Ni': m['ior']})[0]
    if t == 'glossy':
        return mc.bsdf_for({'Kd': m.get('diffuse', [0, 0, 0]), 'Ks': m['specular'], 'illum': 2,
                            'Ns': m['exponent'], 'Ni': 1})[0]
    if t == 'diffuse':
        return {'type': 'twosided', 'bsdf': {'type': 'diffuse', 'reflectance': mc.rgb(m['reflectance'])}}
    raise ValueError(f'unsupported sphere material {t}')


def scene_dict(scene_file, res, spp, mesh_dir):
    with open(scene_file) as f:
        desc = json.load(f)
    base = os.path.dirname(os.path.abspath(scene_file))
    cam = desc['camera']
    d = {
        'type': 'scene',
        'integrator': {'type': 'path', 'max_depth': -1, 'rr_depth': 5, 'hide_emitters': False},
        'sensor': {
            'type': 'perspective', 'fov': cam.get('fov', 40), 'fov_axis': 'y',
            'to_world': mi.ScalarTransform4f().look_at(origin=cam['lookFrom'], target=cam['lookAt'], up=cam['up']),
            'film': {'type': 'hdrfilm', 'width': res, 'height': res, 'rfilter': {'type': 'box'},
                     'pixel_format': 'rgb', 'component_format': 'float32'},
            'sampler': {'type': 'independent', 'sample_count': spp},
        },
    }
    os.makedirs(mesh_dir, exist_ok=True)
    for i, shape in enumerate(desc['shapes']):
        if shape['type'] == 'mesh':
            groups, mtllib = mc.parse_obj(os.path.join(base, shape['file']))
            mats = mc.parse_mtl(os.path.join(base, mtllib))
            for (mname, has_n), (pos, nrm) in sorted(groups.items()):
                m = mats[mname]
                fname = os.path.join(mesh_dir, f"{mname}{'_vn' if has_n else ''}.ply")
                mc.write_ply(fname, pos, nrm)
                s = {'type': 'ply', 'filename': fname, 'bsdf': mc.bsdf_for(m)[0], 'face_normals': not has_n}
                if max(m['Ke']) > 0:
                    s['emitter'] = {'type': 'area', 'radiance': mc.rgb(m['Ke'])}
                d[f"mesh_{mname}{'_vn' if has_n else ''}"] = s
        elif shape['type'] == 'sphere':
            d[f'sphere_{i}'] = {'type': 'sphere', 'center': shape['center'], 'radius': shape['radius'],
                                'bsdf': sphere_bsdf(desc['materials'][shape['material']])}
        else:
            raise ValueError(f"unsupported shape {shape['type']}")
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('--res', type=int, default=128)
    ap.add_argument('--spp', type=int, default=4096, help='samples per pixel of one chunk')
    ap.add_argument('--chunks', type=int, default=8)
    ap.add_argument('--seed0', type=int, default=1000)
    ap.add_argument('--mi-variant', default='llvm_ad_rgb')
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--out', required=True)
    args = ap.parse_args()

    global mi
    import mitsuba as mi
    import drjit as dr
    mi.set_variant(args.mi_variant)
    dr.set_thread_count(args.threads)
    os.makedirs(args.out, exist_ok=True)
    scene = mi.load_dict(scene_dict(args.scene, args.res, args.spp, os.path.join(args.out, 'meshes')))
    for k in range(args.chunks):
        seed = args.seed0 + k
        path = os.path.join(args.out, f'chunk_seed{seed:04d}.pfm')
        if os.path.exists(path):
            continue
        t0 = time.perf_counter()
        img = np.array(mi.render(scene, seed=seed, spp=args.spp), dtype=np.float64)[:, :, :3]
        mc.write_pfm(path, img)
        print(f'chunk seed {seed}: {time.perf_counter() - t0:.1f} s', flush=True)
    chunks = [mc.read_pfm(p) for p in sorted(glob.glob(os.path.join(args.out, 'chunk_seed*.pfm')))]
    mean = np.mean(chunks, axis=0)
    mc.write_pfm(os.path.join(args.out, 'mean.pfm'), mean)
    if len(chunks) >= 2:
        half = len(chunks) // 2
        a, b = np.mean(chunks[:half], axis=0), np.mean(chunks[half:2 * half], axis=0)
        # relMSE of one half against the other, / 4 (two halves, each with twice the mean's variance)
        rel = float(np.mean((a - b) ** 2 / (mean * mean + 0.01))) / 4
        print(f'{len(chunks)} chunks x {args.spp} spp; own relMSE of the mean about {rel:.3g}', flush=True)


if __name__ == '__main__':
    main()
