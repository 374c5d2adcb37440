#!/usr/bin/env python3
"""Writes src/main/resources/models/windmill-blades.obj: a windmill's hub and four blades, made here.

The blades turn about the model's own x axis (the hub is at the origin): placed as a moving model
obstacle with a "rotate" motion about a horizontal axis, it is the editor's "windmill" (issue 24).
Each blade is a box 0.03 m thick (along x), 0.11 m wide, from 0.04 m to 0.50 m out from the hub.
"""
import math

def box(cx, cy, cz, hx, hy, hz, turn):
    """The 8 corners of a box (half sizes hx, hy, hz) turned by `turn` about x, and its 12 triangles."""
    corners = []
    for dx in (-hx, hx):
        for dy in (-hy, hy):
            for dz in (-hz, hz):
                y, z = cy + dy, cz + dz
                c, s = math.cos(turn), math.sin(turn)
                corners.append((cx + dx, c * y - s * z, s * y + c * z))
    # corner index = 4*ix + 2*iy + iz
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return corners, faces

lines = ["# A windmill's hub and four blades (tools/generate_blades.py); they turn about x.", "o blades"]
vertices, count = [], 0
for k in range(4):
    corners, faces = box(0, 0, 0.27, 0.015, 0.055, 0.23, k * math.pi / 2)
    for c in corners:
        lines.append("v %.6f %.6f %.6f" % c)
    for f in faces:
        lines.append("f %d %d %d %d" % tuple(count + i + 1 for i in f))
    count += 8
corners, faces = box(0, 0, 0, 0.035, 0.045, 0.045, 0)
lines.append("o hub")
for c in corners:
    lines.append("v %.6f %.6f %.6f" % c)
for f in faces:
    lines.append("f %d %d %d %d" % tuple(count + i + 1 for i in f))
with open("src/main/resources/models/windmill-blades.obj", "w") as out:
    out.write("\n".join(lines) + "\n")
