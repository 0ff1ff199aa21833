#!/usr/bin/python3
"""Writes data/examples/card_orchard.json: 2,000 instances of data/models/card_tree.gltf as one
`mesh` object with "points": true, in rows on flat ground, each turned and sized at random. The
instanced counterpart of card_trees.json (an ecosystem of the same tree).

Run once from the repository root; the output is committed. Public domain (CC0), made here."""
import json
import math
import random

random.seed(5)
ROWS, PER_ROW, SPACING = 40, 50, 7.0

transforms = []
for row in range(ROWS):
    for i in range(PER_ROW):
        x = (i - (PER_ROW - 1) / 2) * SPACING + random.uniform(-0.8, 0.8)
        z = -row * SPACING + random.uniform(-0.8, 0.8)
        yaw = random.uniform(0, 2 * math.pi)
        s = random.uniform(0.8, 1.3)
        c, n = s * math.cos(yaw), s * math.sin(yaw)
        # Column-major: the turned and scaled axes, then the position.
        transforms.append([round(v, 4) for v in (c, 0, -n, 0, 0, s, 0, 0, n, 0, c, 0, x, 0, z, 1)])

scene = {
    "comment": "Your own plants as points, instanced: 2,000 glTF trees with alpha-masked, textured leaf cards "
               "(data/models/card_tree.gltf) as one mesh object with \"points\": true, in an orchard's rows "
               "(made by scripts/make_card_orchard.py).",
    "camera": {"position": [3.5, 2.2, 12], "target": [-2, 3, -40], "fov_y_deg": 55, "near": 0.2, "far": 600},
    "lights": [{"type": "directional", "direction": [0.5, -0.55, -0.6]}],
    "objects": [
        {"type": "plane", "center": [0, 0, -130], "size": [400, 320], "color": [0.36, 0.42, 0.22]},
        {"type": "mesh", "file": "../models/card_tree.gltf", "points": True, "transforms": transforms},
    ],
}
with open("data/examples/card_orchard.json", "w") as f:
    f.write(json.dumps(scene, separators=(",", ":")).replace('"transforms":[[', '"transforms":[\n[').replace("],[", "],\n["))
    f.write("\n")
