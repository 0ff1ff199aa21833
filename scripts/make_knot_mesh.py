#!/usr/bin/python3
"""Writes data/models/knot.obj: a (2,3) torus knot tube, the default scene's mesh.

Run once from the repository root; the output is committed. Public domain (CC0), made here."""
import math

P, Q = 2, 3
SEGMENTS, SIDES = 120, 12
R, r, TUBE = 1.0, 0.4, 0.18


def curve(t):
    phi = t * 2 * math.pi
    rad = R + r * math.cos(Q * phi)
    return (rad * math.cos(P * phi), r * math.sin(Q * phi) + 0.0, rad * math.sin(P * phi))


def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def norm(a):
    n = math.sqrt(sum(x * x for x in a))
    return tuple(x / n for x in a)


lines = ["# (2,3) torus knot tube, made by scripts/make_knot_mesh.py, CC0"]
for i in range(SEGMENTS):
    t = i / SEGMENTS
    c = curve(t)
    tangent = norm(sub(curve(t + 1e-4), curve(t - 1e-4)))
    side = norm(cross(tangent, (0.0, 1.0, 0.0)))
    up = cross(side, tangent)
    for j in range(SIDES):
        a = 2 * math.pi * j / SIDES
        n = tuple(math.cos(a) * s + math.sin(a) * u for s, u in zip(side, up))
        p = tuple(ci + TUBE * ni for ci, ni in zip(c, n))
        lines.append("v %.4f %.4f %.4f" % p)
for i in range(SEGMENTS):
    for j in range(SIDES):
        a = i * SIDES + j + 1
        b = ((i + 1) % SEGMENTS) * SIDES + j + 1
        c = ((i + 1) % SEGMENTS) * SIDES + (j + 1) % SIDES + 1
        d = i * SIDES + (j + 1) % SIDES + 1
        lines.append("f %d %d %d %d" % (a, b, c, d))
with open("data/models/knot.obj", "w") as f:
    f.write("\n".join(lines) + "\n")
