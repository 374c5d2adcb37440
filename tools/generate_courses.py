#!/usr/bin/env python3
"""Writes the generated example courses: courses/trees.json, courses/windmill.json and the benchmark
course courses/lake-obstacles.json (the manual's lake with 199 seeded random trees, boxes and walls
plus the windmill mesh: 200 obstacles). Deterministic; run from the repository root."""
import json
import math
import random


def dump(c, path):
    lines = ["{"]
    for k in c:
        if k == "obstacles":
            lines.append('  "obstacles": [')
            for n, o in enumerate(c[k]):
                lines.append("    " + json.dumps(o, separators=(", ", ": ")) + ("," if n + 1 < len(c[k]) else ""))
            lines.append("  ]")
        else:
            lines.append('  "%s": %s,' % (k, json.dumps(c[k], separators=(", ", ": "))))
    lines.append("}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


# Tree field: a jittered 6 x 4 grid of trunks on gentle hills, none on the start or the hole.
random.seed(7)
trees = []
for i in range(6):
    for j in range(4):
        x = -3.6 + i * 1.45 + random.uniform(-0.3, 0.3)
        y = -2.1 + j * 1.4 + random.uniform(-0.3, 0.3)
        if math.hypot(x + 4, y) < 0.8 or math.hypot(x - 4, y - 0.5) < 0.7:
            continue
        trees.append({"type": "tree", "position": [round(x, 3), round(y, 3)], "radius": round(random.uniform(0.08, 0.18), 3),
                      "height": round(random.uniform(1.5, 3), 2), "restitution": 0.6})
dump({"format": 1, "name": "Tree Field", "terrain": {"height": "0.25 + 0.06*sin(0.9*x)*cos(0.8*y)"},
      "bounds": {"min": [-5, -3], "max": [5, 3]},
      "physics": {"gravity": 9.81, "kineticFriction": 0.09, "staticFriction": 0.2, "maxSpeed": 5, "model": "classic"},
      "start": [-4.5, 0], "hole": {"position": [4, 0.5], "radius": 0.1, "rule": "rest"}, "zones": [], "obstacles": trees},
     "courses/trees.json")

# Windmill: the mesh in the middle of the line from start to hole, two low walls beside it.
dump({"format": 1, "name": "Windmill", "terrain": {"height": "0.1"},
      "bounds": {"min": [-5, -3], "max": [5, 3]},
      "physics": {"gravity": 9.81, "kineticFriction": 0.1, "staticFriction": 0.2, "maxSpeed": 5, "model": "classic"},
      "start": [-4, 0], "hole": {"position": [3.5, 0], "radius": 0.1, "rule": "rest"}, "zones": [],
      "obstacles": [
          {"type": "model", "file": "models/windmill.obj", "position": [0, 0, 0.1], "rotationDeg": 90, "scale": 1, "restitution": 0.5},
          {"type": "wall", "from": [-1.5, 1.2], "to": [1.5, 1.2], "thickness": 0.1, "height": 0.12, "restitution": 0.7},
          {"type": "wall", "from": [-1.5, -1.2], "to": [1.5, -1.2], "thickness": 0.1, "height": 0.12, "restitution": 0.7}]},
     "courses/windmill.json")

# Benchmark: the lake course with 199 random obstacles and the windmill (200 in all).
random.seed(2024)


def h(x, y):
    return 0.4 * (0.9 - math.exp(-(x * x + y * y) / 8))


def free(x, y, clear):
    return (math.hypot(x + 3, y) > 0.8 + clear and math.hypot(x - 4, y - 1) > 0.6 + clear and math.hypot(x, y) > 1.3 + clear
            and math.hypot(x - 1.5, y + 3) > 0.9 + clear and abs(x) < 4.7 - clear and abs(y) < 4.7 - clear)


obstacles = [{"type": "model", "file": "models/windmill.obj", "position": [1.5, -3, round(h(1.5, -3) - 0.05, 4)],
              "rotationDeg": 0, "scale": 0.8, "restitution": 0.5}]
while len(obstacles) < 200:
    kind = len(obstacles) % 3
    x, y = random.uniform(-4.7, 4.7), random.uniform(-4.7, 4.7)
    if kind == 0:
        r = random.uniform(0.04, 0.12)
        if not free(x, y, r):
            continue
        obstacles.append({"type": "tree", "position": [round(x, 3), round(y, 3)], "radius": round(r, 3), "height": 2, "restitution": 0.6})
    elif kind == 1:
        s = random.uniform(0.05, 0.15)
        if not free(x, y, s * 1.5):
            continue
        z = h(x, y)
        obstacles.append({"type": "box", "min": [round(x - s, 3), round(y - s, 3), round(z - 0.3, 3)],
                          "max": [round(x + s, 3), round(y + s, 3), round(z + 0.15, 3)],
                          "rotationDeg": round(random.uniform(0, 90), 1), "restitution": 0.7})
    else:
        a = random.uniform(0, math.pi)
        length = random.uniform(0.2, 0.6)
        x2, y2 = x + length * math.cos(a), y + length * math.sin(a)
        if not (free(x, y, 0.05) and free(x2, y2, 0.05) and free((x + x2) / 2, (y + y2) / 2, 0.05)):
            continue
        obstacles.append({"type": "wall", "from": [round(x, 3), round(y, 3)], "to": [round(x2, 3), round(y2, 3)],
                          "thickness": random.choice([0, 0.05]), "height": 0.1, "restitution": 0.7})
dump({"format": 1, "name": "Lake With 200 Obstacles", "terrain": {"height": "0.4*(0.9-exp(-(x^2+y^2)/8))"},
      "bounds": {"min": [-5, -5], "max": [5, 5]},
      "physics": {"gravity": 9.81, "kineticFriction": 0.08, "staticFriction": 0.2, "maxSpeed": 5, "model": "classic"},
      "start": [-3, 0], "hole": {"position": [4, 1], "radius": 0.15, "rule": "rest"}, "zones": [], "obstacles": obstacles},
     "courses/lake-obstacles.json")
