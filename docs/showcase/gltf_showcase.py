#!/usr/bin/env python3
"""Writes scenes/gltf-showcase.glb, the README's glTF picture, with numpy and the standard library only.

A GLB with: a node hierarchy (a turned group of three objects), one sphere mesh used by two nodes
(an instance), a gold metal, a red rough plastic, a glass sphere (KHR_materials_transmission +
KHR_materials_ior), a floor with a sampled checker texture (embedded PNG in a buffer view, REPEAT,
KHR_texture_transform scale), an emissive panel (KHR_materials_emissive_strength) as the light and
a perspective camera.

    python3 docs/showcase/gltf_showcase.py
    java -jar target/strahl.jar render scenes/gltf-showcase.glb -o docs/images/gltf-showcase.png --width 560 --height 350 --spp 96
"""
import json
import math
import struct
import zlib
from pathlib import Path

import numpy as np

bin_data = bytearray()
gltf = {"asset": {"version": "2.0", "generator": "strahl docs/showcase/gltf_showcase.py"},
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_emissive_strength",
                           "KHR_texture_transform"],
        "buffers": [], "bufferViews": [], "accessors": [], "meshes": [], "materials": [], "nodes": [],
        "images": [], "samplers": [], "textures": [], "cameras": []}


def view(data: bytes) -> int:
    while len(bin_data) % 4:
        bin_data.append(0)
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(bin_data), "byteLength": len(data)})
    bin_data.extend(data)
    return len(gltf["bufferViews"]) - 1


def accessor(array: np.ndarray, kind: str) -> int:
    comp = 5126 if array.dtype == np.float32 else 5125
    gltf["accessors"].append({"bufferView": view(array.tobytes()), "componentType": comp,
                              "count": len(array), "type": kind})
    return len(gltf["accessors"]) - 1


_shared = {}


def mesh(positions, normals, uvs, indices, material) -> int:
    key = id(positions)                                # meshes of the same arrays share their accessors
    if key not in _shared:
        attributes = {"POSITION": accessor(np.asarray(positions, np.float32), "VEC3"),
                      "NORMAL": accessor(np.asarray(normals, np.float32), "VEC3")}
        if uvs is not None:
            attributes["TEXCOORD_0"] = accessor(np.asarray(uvs, np.float32), "VEC2")
        _shared[key] = (attributes, accessor(np.asarray(indices, np.uint32).ravel(), "SCALAR"))
    attributes, index = _shared[key]
    gltf["meshes"].append({"primitives": [{"attributes": attributes, "indices": index, "material": material}]})
    return len(gltf["meshes"]) - 1


def material(**m) -> int:
    gltf["materials"].append(m)
    return len(gltf["materials"]) - 1


def node(**n) -> int:
    gltf["nodes"].append(n)
    return len(gltf["nodes"]) - 1


def sphere(radius, rings=48, segments=96):
    pos, nrm, idx = [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            nrm.append(n)
            pos.append(tuple(radius * c for c in n))
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            if i > 0:                              # no zero-area triangles at the poles
                idx.append((a, a + 1, b))
            if i < rings - 1:
                idx.append((a + 1, b + 1, b))
    return pos, nrm, idx


def box(h):
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            base = len(pos)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0, 0, 0]
                p[axis], p[u], p[v] = sign * h, a * h, b * h
                pos.append(p)
                nrm.append(n)
            idx += [(base, base + 1, base + 2), (base, base + 2, base + 3)] if sign > 0 else \
                   [(base, base + 2, base + 1), (base, base + 3, base + 2)]
    return pos, nrm, idx


def checker_png(size=64, cells=8) -> bytes:
    y, x = np.mgrid[0:size, 0:size]
    on = ((x * cells // size) + (y * cells // size)) % 2 == 0
    rgb = np.where(on[..., None], [225, 222, 214], [60, 64, 72]).astype(np.uint8)
    raw = b"".join(b"\x00" + row.tobytes() for row in rgb)

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


gold = material(name="gold", pbrMetallicRoughness={"baseColorFactor": [1.0, 0.78, 0.34, 1], "metallicFactor": 1,
                                                    "roughnessFactor": 0.25})
plastic = material(name="red plastic", pbrMetallicRoughness={"baseColorFactor": [0.7, 0.06, 0.04, 1], "metallicFactor": 0,
                                                             "roughnessFactor": 0.45})
glass = material(name="glass", pbrMetallicRoughness={"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0},
                 extensions={"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.5}})
gltf["images"].append({"bufferView": view(checker_png()), "mimeType": "image/png"})
gltf["samplers"].append({"wrapS": 10497, "wrapT": 10497})
gltf["textures"].append({"source": 0, "sampler": 0})
floor_mat = material(name="floor", pbrMetallicRoughness={
    "baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [3, 3]}}},
    "metallicFactor": 0, "roughnessFactor": 0.6})
lamp = material(name="lamp", emissiveFactor=[1, 0.93, 0.82], pbrMetallicRoughness={"baseColorFactor": [0, 0, 0, 1]},
                extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 14}})

p, n, i = sphere(0.5)
ball_gold = mesh(p, n, None, i, gold)
ball_glass = mesh(p, n, None, i, glass)
bp, bn, bi = box(0.42)
cube = mesh(bp, bn, None, bi, plastic)
floor = mesh([(-4, 0, -4), (4, 0, -4), (4, 0, 4), (-4, 0, 4)], [(0, 1, 0)] * 4, [(0, 0), (1, 0), (1, 1), (0, 1)],
             [(0, 2, 1), (0, 3, 2)], floor_mat)
panel = mesh([(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)], [(0, -1, 0)] * 4, None, [(0, 1, 2), (0, 2, 3)], lamp)

s45 = math.sin(math.radians(20))
c45 = math.cos(math.radians(20))
children = [node(name="gold ball", mesh=ball_gold, translation=[-1.15, 0.5, 0]),
            node(name="gold ball again (instance)", mesh=ball_gold, translation=[-0.2, 0.3, -1.5], scale=[0.6, 0.6, 0.6]),
            node(name="glass ball", mesh=ball_glass, translation=[0.15, 0.5, 0.9]),
            node(name="cube", mesh=cube, translation=[1.05, 0.42, 0.05], rotation=[0, s45, 0, c45])]
group = node(name="group", children=children, rotation=[0, math.sin(math.radians(-8)), 0, math.cos(math.radians(-8))])
floor_node = node(name="floor", mesh=floor)
lamp_node = node(name="lamp", mesh=panel, translation=[-1.2, 3.2, 1.6])
gltf["cameras"].append({"type": "perspective", "perspective": {"yfov": math.radians(34), "aspectRatio": 1.6, "znear": 0.05}})
# camera at (0, 1.9, 5.4) looking at (0, 0.45, 0): a rotation about x by −atan(1.45 / 5.4)
tilt = -math.atan2(1.45, 5.4)
cam_node = node(name="camera", camera=0, translation=[0, 1.9, 5.4], rotation=[math.sin(tilt / 2), 0, 0, math.cos(tilt / 2)])
gltf["scenes"] = [{"nodes": [group, floor_node, lamp_node, cam_node]}]
gltf["scene"] = 0
while len(bin_data) % 4:
    bin_data.append(0)
gltf["buffers"].append({"byteLength": len(bin_data)})

js = json.dumps(gltf, separators=(",", ":")).encode()
js += b" " * (-len(js) % 4)
total = 12 + 8 + len(js) + 8 + len(bin_data)
out = Path(__file__).resolve().parents[2] / "scenes" / "gltf-showcase.glb"
out.write_bytes(struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(js), 0x4E4F534A) + js
                + struct.pack("<II", len(bin_data), 0x004E4942) + bytes(bin_data))
print(f"wrote {out} ({total} bytes)")
