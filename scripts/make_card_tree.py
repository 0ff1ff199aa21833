#!/usr/bin/python3
"""Writes data/models/card_tree.gltf (+ .bin, leaf.png): a small tree as vegetation assets are
made, a trunk and branches of opaque polygons and a crown of textured, alpha-masked leaf cards.

Run once from the repository root (needs numpy and PIL); the output is committed. Public domain
(CC0), made here."""
import json
import math
import struct

import numpy as np
from PIL import Image

rng = np.random.default_rng(11)
SIDE = 128


def leaf_image():
    """A leaf-shaped mask (pointed ellipse) with a green gradient and a midrib."""
    img = np.zeros((SIDE, SIDE, 4), np.uint8)
    for y in range(SIDE):
        for x in range(SIDE):
            u, v = (x + 0.5) / SIDE * 2 - 1, (y + 0.5) / SIDE * 2 - 1  # v along the leaf
            half_width = 0.55 * (1 - v * v) ** 0.8
            inside = abs(u) < half_width
            shade = 0.55 + 0.35 * (1 - (v + 1) / 2)
            rib = abs(u) < 0.04
            g = 200 * shade
            img[y, x] = (int(70 * shade + (60 if rib else 0)), int(g + (40 if rib else 0)), int(35 * shade),
                         255 if inside else 0)
    return img


def cylinder(a, b, r0, r1, sides=8):
    """A tapered tube from a to b: positions, normals, texture coordinates, indices."""
    a, b = np.array(a, float), np.array(b, float)
    axis = (b - a) / np.linalg.norm(b - a)
    side = np.cross(axis, [0.3, 0.2, 1.0])
    side /= np.linalg.norm(side)
    other = np.cross(axis, side)
    pos, nrm, idx = [], [], []
    for i in range(sides):
        ang = 2 * math.pi * i / sides
        d = math.cos(ang) * side + math.sin(ang) * other
        pos += [a + r0 * d, b + r1 * d]
        nrm += [d, d]
    for i in range(sides):
        j = (i + 1) % sides
        idx += [2 * i, 2 * j, 2 * i + 1, 2 * j, 2 * j + 1, 2 * i + 1]
    return pos, nrm, [(0, 0)] * len(pos), idx


def leaves(count):
    pos, nrm, uv, idx = [], [], [], []
    for _ in range(count):
        while True:
            c = rng.uniform(-1, 1, 3)
            if np.dot(c, c) < 1:
                break
        c = np.array([0, 5.2, 0]) + c * [2.4, 1.9, 2.4]
        along = rng.normal(size=3)
        along[1] -= 0.8  # leaves hang a little
        along /= np.linalg.norm(along)
        across = np.cross(along, rng.normal(size=3))
        across /= np.linalg.norm(across)
        n = np.cross(across, along)
        size = rng.uniform(0.25, 0.4)
        base = len(pos)
        for s, t, u, v in [(-1, -1, 0, 1), (1, -1, 1, 1), (1, 1, 1, 0), (-1, 1, 0, 0)]:
            pos.append(c + size * (s * 0.5 * across + t * along))
            nrm.append(n)
            uv.append((u, v))
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uv, idx


def primitive(parts):
    pos, nrm, uv, idx = [], [], [], []
    for p, n, t, i in parts:
        base = len(pos)
        pos += p
        nrm += n
        uv += t
        idx += [base + k for k in i]
    return (np.array(pos, np.float32), np.array(nrm, np.float32), np.array(uv, np.float32), np.array(idx, np.uint32))


wood = primitive([cylinder((0, 0, 0), (0, 4.2, 0), 0.22, 0.12)] +
                 [cylinder((0, 2.8 + 0.4 * k, 0), (1.6 * math.cos(2.1 * k), 4.6 + 0.3 * k, 1.6 * math.sin(2.1 * k)), 0.08, 0.04)
                  for k in range(5)])
crown = primitive([leaves(900)])

blob, views, accessors = b"", [], []
for prim in (wood, crown):
    for array, kind in zip(prim, ("VEC3", "VEC3", "VEC2", "SCALAR")):
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": array.nbytes})
        accessor = {"bufferView": len(views) - 1, "componentType": 5125 if kind == "SCALAR" else 5126,
                    "count": len(array), "type": kind}
        if len(accessors) % 4 == 0:
            accessor["min"], accessor["max"] = array.min(0).tolist(), array.max(0).tolist()
        accessors.append(accessor)
        blob += array.tobytes()
        blob += b"\0" * (-len(blob) % 4)

gltf = {
    "asset": {"version": "2.0", "generator": "scripts/make_card_tree.py"},
    "buffers": [{"uri": "card_tree.bin", "byteLength": len(blob)}],
    "bufferViews": views, "accessors": accessors,
    "images": [{"uri": "leaf.png"}], "samplers": [{"wrapS": 33071, "wrapT": 33071}],
    "textures": [{"source": 0, "sampler": 0}],
    "materials": [{"name": "bark", "pbrMetallicRoughness": {"baseColorFactor": [0.33, 0.22, 0.13, 1]}},
                  {"name": "leaf", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
                   "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True}],
    "meshes": [{"primitives": [
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0},
        {"attributes": {"POSITION": 4, "NORMAL": 5, "TEXCOORD_0": 6}, "indices": 7, "material": 1}]}],
    "nodes": [{"mesh": 0, "name": "card tree"}], "scenes": [{"nodes": [0]}], "scene": 0,
}
with open("data/models/card_tree.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
with open("data/models/card_tree.bin", "wb") as f:
    f.write(blob)
Image.fromarray(leaf_image(), "RGBA").save("data/models/leaf.png", optimize=True)
