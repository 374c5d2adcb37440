#!/usr/bin/env python3
"""Writes the maze and obstacle courses of the bot benchmark suite (courses/bench/, issue 5): mazes A-E
like the original report's, a tree field and water with a bank shot off a wall. Deterministic (seeded);
run from the repository root. courses/bench/README.md describes what each course tests."""
import json
import math
import random

WALL_T, WALL_H, WALL_E = 0.1, 0.15, 0.7
PHYS = {"gravity": 9.81, "kineticFriction": 0.1, "staticFriction": 0.2, "maxSpeed": 5, "model": "classic"}


def dump(c, path):
    lines = ["{"]
    keys = list(c)
    for n, k in enumerate(keys):
        end = "," if n + 1 < len(keys) else ""
        if k == "obstacles":
            lines.append('  "obstacles": [')
            for m, o in enumerate(c[k]):
                lines.append("    " + json.dumps(o, separators=(", ", ": ")) + ("," if m + 1 < len(c[k]) else ""))
            lines.append("  ]" + end)
        else:
            lines.append('  "%s": %s%s' % (k, json.dumps(c[k], separators=(", ", ": ")), end))
    lines.append("}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def wall(a, b, t=WALL_T, h=WALL_H):
    return {"type": "wall", "from": [round(a[0], 3), round(a[1], 3)], "to": [round(b[0], 3), round(b[1], 3)],
            "thickness": t, "height": h, "restitution": WALL_E}


def rim(x0, y0, x1, y1):
    return [wall((x0, y0), (x1, y0)), wall((x1, y0), (x1, y1)), wall((x1, y1), (x0, y1)), wall((x0, y1), (x0, y0))]


def maze(cols, rows, seed):
    """A perfect maze (randomised depth-first search): the set of open passages between cells."""
    rnd = random.Random(seed)
    seen, stack, open_ = {(0, 0)}, [(0, 0)], set()
    while stack:
        c, r = stack[-1]
        nbrs = [(c + dc, r + dr) for dc, dr in ((1, 0), (-1, 0), (0, 1), (0, -1))
                if 0 <= c + dc < cols and 0 <= r + dr < rows and (c + dc, r + dr) not in seen]
        if not nbrs:
            stack.pop()
            continue
        n = rnd.choice(nbrs)
        open_.add(frozenset(((c, r), n)))
        seen.add(n)
        stack.append(n)
    return open_


def maze_walls(cols, rows, size, x0, y0, open_):
    """Inner walls on the edges between cells that are not connected, collinear runs merged."""
    walls = []
    for c in range(1, cols):  # vertical edges x = x0 + c*size
        run = None
        for r in range(rows + 1):
            closed = r < rows and frozenset(((c - 1, r), (c, r))) not in open_
            if closed and run is None:
                run = r
            if not closed and run is not None:
                walls.append(wall((x0 + c * size, y0 + run * size), (x0 + c * size, y0 + r * size)))
                run = None
    for r in range(1, rows):  # horizontal edges y = y0 + r*size
        run = None
        for c in range(cols + 1):
            closed = c < cols and frozenset(((c, r - 1), (c, r))) not in open_
            if closed and run is None:
                run = c
            if not closed and run is not None:
                walls.append(wall((x0 + run * size, y0 + r * size), (x0 + c * size, y0 + r * size)))
                run = None
    return walls


def cell_path(cols, rows, open_, goal):
    """Cells from (0, 0) to goal through the maze (breadth first)."""
    prev, queue = {(0, 0): None}, [(0, 0)]
    for cur in queue:
        c, r = cur
        for n in ((c + 1, r), (c - 1, r), (c, r + 1), (c, r - 1)):
            if n not in prev and frozenset((cur, n)) in open_:
                prev[n] = cur
                queue.append(n)
    path, cur = [], goal
    while cur is not None:
        path.append(cur)
        cur = prev[cur]
    return path[::-1], prev


def maze_course(name, cols, rows, size, seed, terrain, physics, trees=0, goal=None):
    w, h = cols * size, rows * size
    x0, y0 = -w / 2, -h / 2
    open_ = maze(cols, rows, seed)
    if goal is None:
        _, prev = cell_path(cols, rows, open_, (0, 0))
        depth = {}
        for cell in prev:
            d, cur = 0, cell
            while prev[cur] is not None:
                cur, d = prev[cur], d + 1
            depth[cell] = d
        goal = max(depth, key=lambda k: (depth[k], k))
    path, _ = cell_path(cols, rows, open_, goal)
    centre = lambda cell: (x0 + (cell[0] + 0.5) * size, y0 + (cell[1] + 0.5) * size)
    obstacles = rim(x0, y0, x0 + w, y0 + h) + maze_walls(cols, rows, size, x0, y0, open_)
    # Trees in the corridors of the solution, off the cell centres, so the ball must pass beside them.
    rnd = random.Random(seed + 1)
    inner = path[1:-1]
    for k in range(trees):
        cell = inner[(k + 1) * len(inner) // (trees + 1)]
        cx, cy = centre(cell)
        a = rnd.uniform(0, 2 * math.pi)
        obstacles.append({"type": "tree", "position": [round(cx + 0.25 * size * math.cos(a), 3),
                                                       round(cy + 0.25 * size * math.sin(a), 3)],
                          "radius": 0.15, "height": 2.5, "restitution": 0.6})
    sx, sy = centre(path[0])
    hx, hy = centre(path[-1])
    m = 0.3
    return {"format": 1, "name": name, "terrain": {"height": terrain},
            "bounds": {"min": [x0 - m, y0 - m], "max": [x0 + w + m, y0 + h + m]}, "physics": physics,
            "start": [sx, sy], "hole": {"position": [hx, hy], "radius": 0.1, "rule": "rest"}, "zones": [],
            "obstacles": obstacles}, len(path)


def write(course, file, path_cells=None):
    dump(course, "courses/bench/" + file)
    print(file, "walls", sum(o["type"] == "wall" for o in course["obstacles"]),
          "trees", sum(o["type"] == "tree" for o in course["obstacles"]), "path cells", path_cells)


FLAT = "0.1"
# A: very hard: a 6 x 4 maze of 1.6 m cells, a long winding solution, four trees on it.
c, n = maze_course("Maze A (very hard)", 6, 4, 1.6, 11, FLAT, PHYS, trees=4)
write(c, "maze-a.json", n)
# B: a 4 x 3 maze of 2 m cells, with hills and two pools in dead ends / beside the way, and without.
B_HILLS = ("0.25 + 0.1*sin(1.1*x)*cos(0.9*y) - 0.45*exp(-((x-1)^2+(y+2)^2)/0.6)"
           " - 0.45*exp(-((x+3)^2+(y-2)^2)/0.6)")
c, n = maze_course("Maze B (hills and water)", 4, 3, 2.0, 5, B_HILLS, PHYS)
write(c, "maze-b-hills.json", n)
c, n = maze_course("Maze B (flat)", 4, 3, 2.0, 5, FLAT, PHYS)
write(c, "maze-b.json", n)

# C: very easy: one big box between start and hole in a walled field; and with three hills and two pools.
def maze_c(name, terrain):
    return {"format": 1, "name": name, "terrain": {"height": terrain},
            "bounds": {"min": [-5.3, -3.3], "max": [5.3, 3.3]}, "physics": PHYS,
            "start": [-4, 0], "hole": {"position": [4, 0], "radius": 0.1, "rule": "rest"}, "zones": [],
            "obstacles": rim(-5, -3, 5, 3) + [
                {"type": "box", "min": [-0.75, -1.5, -0.5], "max": [0.75, 1.5, 0.6], "rotationDeg": 0, "restitution": 0.6}]}


write(maze_c("Maze C (very easy)", FLAT), "maze-c.json")
C_HILLS = ("0.3 + 0.25*exp(-((x+2.5)^2+(y-1.8)^2)/0.8) + 0.25*exp(-((x-2.2)^2+(y+1.9)^2)/0.8)"
           " + 0.2*exp(-((x-2.8)^2+(y-2)^2)/0.6) - 0.5*exp(-((x+2.2)^2+(y+1.6)^2)/1.0)"
           " - 0.5*exp(-((x-2.2)^2+(y-0.9)^2)/0.8)")
write(maze_c("Maze C (hills and pools)", C_HILLS), "maze-c-hills.json")

# D: a small maze of walls round a big mountain in the middle (1 m high: only fast balls get over it).
d_walls = rim(-4, -4, 4, 4) + [
    wall((2.2, -4), (2.2, -1.0)),     # the right-hand corridor is closed off near the start ...
    wall((1.3, 0), (4, 0)),           # ... and across the right side: the way is round the left
    wall((-4, -1.5), (-2.4, -1.5)),   # staggered baffles in the left corridor
    wall((-1.4, 1.2), (-2.8, 1.2)),
    wall((-1.0, 2.6), (-1.0, 4)),
]
dump_d = {"format": 1, "name": "Maze D (mountain)", "terrain": {"height": "0.1 + 1.0*exp(-(x^2+y^2)/3)"},
          "bounds": {"min": [-4.3, -4.3], "max": [4.3, 4.3]}, "physics": PHYS,
          "start": [3.2, -3.2], "hole": {"position": [3.0, 3.0], "radius": 0.1, "rule": "rest"}, "zones": [],
          "obstacles": d_walls}
write(dump_d, "maze-d.json")

# E: medium: a 5 x 3 maze of 1.8 m cells (many walls).
c, n = maze_course("Maze E (medium)", 5, 3, 1.8, 3, FLAT, PHYS)
write(c, "maze-e.json", n)

# Tree field: 40 trunks scattered over gentle hills between start and hole.
rnd = random.Random(17)
trees = []
while len(trees) < 40:
    x, y = rnd.uniform(-4.5, 4.5), rnd.uniform(-2.6, 2.6)
    if math.hypot(x + 5, y) < 1.0 or math.hypot(x - 5, y - 0.5) < 1.0:
        continue
    if any(math.hypot(x - t["position"][0], y - t["position"][1]) < 0.55 for t in trees):
        continue
    trees.append({"type": "tree", "position": [round(x, 3), round(y, 3)], "radius": round(rnd.uniform(0.1, 0.2), 3),
                  "height": 2.5, "restitution": 0.6})
write({"format": 1, "name": "Tree field", "terrain": {"height": "0.2 + 0.05*sin(0.8*x)*cos(1.1*y)"},
       "bounds": {"min": [-6, -3], "max": [6, 3]}, "physics": PHYS,
       "start": [-5.2, 0], "hole": {"position": [5.2, 0.5], "radius": 0.1, "rule": "rest"}, "zones": [],
       "obstacles": trees}, "tree-field.json")

# Water and a bank shot: a pond across the direct line up to a wall along the top edge; the ball
# goes round by the dry strip along the wall, or banks off it in one stroke.
write({"format": 1, "name": "Bank shot", "terrain": {"height": "0.15 - 0.5*exp(-(x^2/1.2 + (y+2.5)^4/300))"},
       "bounds": {"min": [-5, -3], "max": [5, 3]}, "physics": dict(PHYS, kineticFriction=0.08),
       "start": [-3.5, -1.5], "hole": {"position": [3.5, -1.5], "radius": 0.1, "rule": "rest"}, "zones": [],
       "obstacles": [wall((-4.8, 2.5), (4.8, 2.5), h=0.2)]}, "water-bank.json")
