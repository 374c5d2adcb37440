"""Shared pieces of the hole generators (generate_rounds.py, generate_worlds.py): rails along a
polyline, boxes, trees, bounds round an outline, the slope check, a course dict and the JSON writer
that keeps one obstacle or zone per line. Import from the repository root's tools/ folder."""
import json
import math

RAIL = {"thickness": 0.08, "height": 0.1, "restitution": 0.75}
PHYSICS = {"gravity": 9.81, "kineticFriction": 0.1, "staticFriction": 0.2, "maxSpeed": 5, "model": "classic"}
CUP = 0.06  # cup radius (m): capture rule with Penner's pace scaled to this cup (1.46 m/s over the centre)


def height_function(expr):
    """The course expression as a Python function (the grammar's ^ is Python's **)."""
    names = {k: getattr(math, k) for k in ("sin", "cos", "tan", "asin", "acos", "atan", "exp", "log", "sqrt", "atan2", "pow")}
    names.update(abs=abs, min=min, max=max, pi=math.pi, e=math.e)
    code = compile(expr.replace("^", "**"), "<height>", "eval")
    return lambda x, y: eval(code, {"__builtins__": {}}, dict(names, x=x, y=y))


def rails(points, closed=True, height=None, piece=0.25):
    """Walls along a polyline (corners shared, so they close). A wall's top runs straight between the
    heights at its ends, so on uneven ground (height given) each side is cut into pieces of at most
    `piece` metres that follow the ground."""
    n = len(points)
    walls = []
    for i in range(n if closed else n - 1):
        a, b = points[i], points[(i + 1) % n]
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        k = 1 if height is None else max(1, int(math.ceil(length / piece)))
        for j in range(k):
            p = [round(a[0] + (b[0] - a[0]) * j / k, 4), round(a[1] + (b[1] - a[1]) * j / k, 4)]
            q = [round(a[0] + (b[0] - a[0]) * (j + 1) / k, 4), round(a[1] + (b[1] - a[1]) * (j + 1) / k, 4)]
            walls.append(dict({"type": "wall", "from": p, "to": q}, **RAIL))
    return walls


def box(cx, cy, sx, sy, z0, z1, turn=0, restitution=0.8):
    return {"type": "box", "min": [round(cx - sx / 2, 4), round(cy - sy / 2, 4), z0],
            "max": [round(cx + sx / 2, 4), round(cy + sy / 2, 4), z1], "rotationDeg": turn, "restitution": restitution}


def tree(x, y, r=0.09, height=2.2):
    return {"type": "tree", "position": [x, y], "radius": r, "height": height, "restitution": 0.6}


def rect_bounds(points, margin=0.3):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return {"min": [round(min(xs) - margin, 3), round(min(ys) - margin, 3)],
            "max": [round(max(xs) + margin, 3), round(max(ys) + margin, 3)]}


def steepest(height, outline, step=0.02):
    """The steepest gradient over the lane's bounding box (central differences on a grid)."""
    f = height_function(height)
    xs = [p[0] for p in outline]
    ys = [p[1] for p in outline]
    worst = 0.0
    x = min(xs)
    while x <= max(xs):
        y = min(ys)
        while y <= max(ys):
            gx = (f(x + 1e-4, y) - f(x - 1e-4, y)) / 2e-4
            gy = (f(x, y + 1e-4) - f(x, y - 1e-4)) / 2e-4
            worst = max(worst, math.hypot(gx, gy))
            y += step
        x += step
    return worst


# A ball at rest on a slope steeper than about 1 (the classic model accelerates it sideways by
# g(s - mu_k), so the ground under it falls faster than free fall) keeps taking off and landing in
# place; no hole has a slope near that.
MAX_SLOPE = 0.8


def course(name, height, outline, start, hole, obstacles=(), zones=(), physics=None, world=None, bounds=None,
           slope_region=None, push_zones=(), teleports=()):
    """A course dict: rails round `outline` (following uneven ground), the capture rule, and the
    optional `world` (a themed world's id, written after the name). The slope check covers the
    outline's box, or `slope_region` (a polygon: only where the ball can roll) when given. Push zones
    and teleports (docs/course-format.md) are written only when there are some."""
    flat = all(c not in height for c in "xy")
    region = slope_region or outline
    if not flat:
        worst = steepest(height, region) if slope_region is None else steepest_inside(height, region)
        if worst > MAX_SLOPE:
            raise SystemExit("%s: slope %.2f is steeper than %.2f" % (name, worst, MAX_SLOPE))
    c = {"format": 1, "name": name}
    if world:
        c["world"] = world
    c.update({"terrain": {"height": height}, "bounds": bounds or rect_bounds(outline),
              "physics": physics or PHYSICS, "start": list(start),
              "hole": {"position": list(hole), "radius": CUP, "rule": "capture"},
              "zones": list(zones), "obstacles": rails(outline, height=None if flat else height_function(height)) + list(obstacles)})
    if push_zones:
        c["pushZones"] = list(push_zones)
    if teleports:
        c["teleports"] = list(teleports)
    return c


def inside(poly, x, y):
    """Whether (x, y) lies inside the polygon (even-odd rule)."""
    result = False
    n = len(poly)
    for i in range(n):
        (ax, ay), (bx, by) = poly[i], poly[(i + 1) % n]
        if (ay > y) != (by > y) and x < ax + (bx - ax) * (y - ay) / (by - ay):
            result = not result
    return result


def steepest_inside(height, poly, step=0.02):
    """The steepest gradient at grid points inside the polygon."""
    f = height_function(height)
    xs = [p[0] for p in poly]
    ys = [p[1] for p in poly]
    worst = 0.0
    x = min(xs)
    while x <= max(xs):
        y = min(ys)
        while y <= max(ys):
            if inside(poly, x, y):
                gx = (f(x + 1e-4, y) - f(x - 1e-4, y)) / 2e-4
                gy = (f(x, y + 1e-4) - f(x, y - 1e-4)) / 2e-4
                worst = max(worst, math.hypot(gx, gy))
            y += step
        x += step
    return worst


def lane(x0, x1, half):
    return [(x0, -half), (x1, -half), (x1, half), (x0, half)]


def dump(c, path):
    lines = ["{"]
    keys = list(c)
    for n, k in enumerate(keys):
        end = "," if n + 1 < len(keys) else ""
        if k in ("obstacles", "zones", "pushZones", "teleports") and c[k]:
            lines.append('  "%s": [' % k)
            for m, o in enumerate(c[k]):
                lines.append("    " + json.dumps(o, separators=(", ", ": ")) + ("," if m + 1 < len(c[k]) else ""))
            lines.append("  ]" + end)
        else:
            lines.append('  "%s": %s%s' % (k, json.dumps(c[k], separators=(", ", ": ")), end))
    lines.append("}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def round_file(name, chosen, path, holes_dir="../holes"):
    """A round file listing (stem, course, par) entries, courses under holes_dir relative to the round."""
    entries = ["    {\"course\": \"%s/%s.json\", \"par\": %d}" % (holes_dir, stem, par) for stem, _, par in chosen]
    with open(path, "w") as f:
        f.write("{\n  \"format\": 1,\n  \"name\": %s,\n  \"holes\": [\n%s\n  ]\n}\n" % (json.dumps(name), ",\n".join(entries)))
