#!/usr/bin/env python3
"""Writes courses/hostile/*.json: terrains a course designer can make that once trapped the
physics (issue 11): a ridge and pits raised and lowered with the editor's brush falloff
w = (1 - d^2/r^2)^2 up to 80 degrees, a V-shaped valley, a cone's tip, and grid steps (terraces
one node apart). The tests shoot thousands of seeded shots on them; none may reach the time limit."""
import json
import math
import os

OUT = os.path.join(os.path.dirname(__file__), "..", "courses", "hostile")


def brush(d, r):
    return (1 - d * d / (r * r)) ** 2 if d < r else 0.0


def grid(f, lo=-5.0, spacing=0.1, n=101):
    rows = []
    for j in range(n):
        y = lo + j * spacing
        rows.append([round(f(lo + i * spacing, y), 6) for i in range(n)])
    return {"grid": {"origin": [lo, lo], "spacing": spacing, "heights": rows}}


def course(name, terrain, start, hole, mu_k=0.1, mu_s=0.2):
    return {
        "format": 1,
        "name": name,
        "terrain": terrain,
        "bounds": {"min": [-5, -5], "max": [5, 5]},
        "physics": {"gravity": 9.81, "kineticFriction": mu_k, "staticFriction": mu_s, "maxSpeed": 5,
                    "model": "classic"},
        "start": start,
        "hole": {"position": hole, "radius": 0.1, "rule": "rest"},
        "zones": [],
        "obstacles": [],
    }


def ridge(x, y):
    # The editor's default brush (radius 0.6 m) raised along x = 0 until the flanks reach 46 degrees.
    return 0.5 + 0.42 * brush(abs(x), 0.6)


def pits(x, y):
    # Three pits lowered with the brush: about 52, 70 and 80 degrees at their steepest.
    h = 2.0
    for (cx, cy, depth, radius) in [(-2, 2, 0.5, 0.6), (1, -1, 1.2, 0.5), (2.5, 2.5, 1.5, 0.4)]:
        h -= depth * brush(math.hypot(x - cx, y - cy), radius)
    return h


def terraces(x, y):
    # Steps of 0.5 m from one grid node to the next (slope 5, 79 degrees), every 1.5 m.
    return 0.5 + 0.5 * math.floor((x + 5) / 1.5 + 1e-9)


COURSES = {
    "ridge": course("Hostile: editor ridge", grid(ridge), [-4, 0], [4, 3]),
    "pits": course("Hostile: brush pits", grid(pits), [-4, -4], [4, -4]),
    "v-valley": course("Hostile: V-shaped valley", {"height": "abs(x) + 0.1"}, [-4, 0], [4, 3]),
    "cone": course("Hostile: cone", {"height": "(x^2 + y^2)^0.5 + 0.1"}, [-4, 0], [4, 3]),
    "terraces": course("Hostile: grid steps", grid(terraces), [-4.5, 0], [-4.5, 3]),
}

if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    for name, c in COURSES.items():
        with open(os.path.join(OUT, name + ".json"), "w") as f:
            json.dump(c, f, indent=None, separators=(", ", ": "))
            f.write("\n")
    print("wrote", ", ".join(sorted(COURSES)))
