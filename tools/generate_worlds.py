#!/usr/bin/env python3
"""Writes the three themed worlds of 18 holes each: courses/worlds/<world>/NN-name.json and the
rounds courses/rounds/<world>-18.json (see docs/worlds.md). Every hole has a clear route for a
beginner (two or three safe putts), a risky line for a good player (a bank, a gap, a carry), and
one idea of its own; par is set by design and checked by `minigolf par-check` (docs/worlds.md).
Deterministic; run from the repository root:

    python3 tools/generate_worlds.py
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from holes_lib import RAIL, PHYSICS, box, course, dump, lane, rails, round_file, tree  # noqa: E402

SAND = 0.55, 0.65      # kinetic, static friction of sand traps (and snow banks)
ICE = 0.025, 0.05      # of ice


def zone(shape, friction):
    return {"shape": shape, "kineticFriction": friction[0], "staticFriction": friction[1]}


def circle(cx, cy, r):
    return {"type": "circle", "center": [cx, cy], "radius": r}


def rect(x0, y0, x1, y1):
    return {"type": "rect", "min": [x0, y0], "max": [x1, y1]}


def polygon(points):
    return {"type": "polygon", "points": [list(p) for p in points]}


def outside(outline, friction=SAND, margin=0.3):
    """A zone covering the bounds round `outline` but not the lane itself: a polygon from the bounds'
    corners, a bridge in to the outline and round it the other way (the even-odd rule leaves the lane
    out). Drawn as the world's sand or snow; the rails keep the ball out of it unless it is chipped."""
    xs = [p[0] for p in outline]
    ys = [p[1] for p in outline]
    x0, y0, x1, y1 = min(xs) - margin, min(ys) - margin, max(xs) + margin, max(ys) + margin
    ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    start = min(range(len(outline)), key=lambda i: (outline[i][0] - x0) ** 2 + (outline[i][1] - y0) ** 2)
    inner = [outline[(start - k) % len(outline)] for k in range(len(outline) + 1)]
    return zone(polygon(ring + inner), friction)


def wall(points, thickness=0.08, height=0.1, restitution=0.75):
    """An inner wall along an open polyline (the rails' look)."""
    out = []
    for i in range(len(points) - 1):
        out.append({"type": "wall", "from": list(points[i]), "to": list(points[i + 1]), "thickness": thickness,
                    "height": height, "restitution": restitution})
    return out


def pocket(x0, y0, x1, y1):
    """Two walls that shield a cup: one from (x0, y0) to (x0, y1), one from (x0, y1) to (x1, y1). With a
    rail beyond x1 the cup can only be reached from that side: a one-stroke ace needs a bank off it."""
    return wall([(x0, y0), (x0, y1), (x1, y1)])


def pillar(x, y, r, height=0.6, restitution=0.6):
    """A round post or tower the ball bounces off (a tree obstacle: a vertical cylinder)."""
    return tree(x, y, r, height) | {"restitution": restitution}


SAIL_HUB = (0.0, -0.36, 1.75)  # the sails' hub in models/windmill-tower.obj (tools/generate_windmill.py)
SAIL_PERIOD = 8.0  # seconds a turn of the sails


def still_windmill(x, y, z, turn=90, scale=1.0):
    """A windmill whose sails stand still (one model obstacle)."""
    return [{"type": "model", "file": "models/windmill.obj", "position": [x, y, z], "rotationDeg": turn, "scale": scale,
             "restitution": 0.5}]


def windmill(x, y, z, turn=90, scale=1.0):
    """A windmill whose sails turn (a list of two obstacles): the tower standing at (x, y, z), turned
    `turn` degrees about z, and its sails turning once every SAIL_PERIOD seconds about the axle (the
    model's y axis through the hub). The sails sweep 0.8 m and more above the tower's foot: a rolling
    ball never meets them, a chip may."""
    t = math.radians(turn)
    hx, hy, hz = SAIL_HUB
    hub = [round(x + scale * (hx * math.cos(t) - hy * math.sin(t)), 6) + 0.0,  # + 0.0: no "-0.0" in the files
           round(y + scale * (hx * math.sin(t) + hy * math.cos(t)), 6) + 0.0, round(z + scale * hz, 6)]
    axis = [round(-math.sin(t), 6) + 0.0, round(math.cos(t), 6) + 0.0, 0]
    tower = {"type": "model", "file": "models/windmill-tower.obj", "position": [x, y, z], "rotationDeg": turn,
             "scale": scale, "restitution": 0.5}
    sails = moving({"type": "model", "file": "models/windmill-sails.obj", "position": hub, "rotationDeg": turn,
                    "scale": scale, "restitution": 0.5}, rotate(hub, SAIL_PERIOD, axis))
    return [tower, sails]


def bumper(x, y, r=0.09, restitution=1.5):
    """A lively post that sends the ball off faster than it came (never past maxSpeed)."""
    return {"type": "bumper", "position": [x, y], "radius": r, "height": 0.1, "restitution": restitution}


def one_way(a, b, pass_to, restitution=0.6):
    """A one-way gate from a to b: the ball passes towards `pass_to` ("left"/"right", seen from a to b)."""
    return {"type": "gate", "from": list(a), "to": list(b), "height": 0.1, "passTo": pass_to, "restitution": restitution}


def moving(body, motion):
    """An obstacle carried by a motion (docs/course-format.md, "Moving obstacles")."""
    return dict(body, motion=motion)


def rotate(pivot, period, axis=(0, 0, 1), phase=0):
    return {"type": "rotate", "pivot": list(pivot), "axis": list(axis), "period": period, "phase": phase}


def slide(path, period, phase=0):
    return {"type": "slide", "path": [list(p) for p in path], "period": period, "phase": phase, "closed": False}


def swing(pivot, axis, amplitude, period, phase=0):
    return {"type": "swing", "pivot": list(pivot), "axis": list(axis), "amplitudeDeg": amplitude, "period": period,
            "phase": phase}


def push(shape, ax, ay):
    """A push zone: the classic game's downhill tiles (m/s^2)."""
    return {"shape": shape, "push": [ax, ay]}


def teleport(entry, exits):
    """An entry shape and its exits [(x, y, direction in degrees or None)]."""
    return {"entry": entry, "exits": [{"position": [x, y], "directionDeg": d} if d is not None else {"position": [x, y]}
                                      for x, y, d in exits]}


def g(x0, y0, sx, sy):
    """A Gaussian bump's shape exp(-((x-x0)^2/sx + (y-y0)^2/sy)) as an expression."""
    return "exp(-((x-%g)^2/%g+(y-%g)^2/%g))" % (x0, sx, y0, sy)


def step(expr, k=6):
    """A smooth step from 0 to 1 as expr goes through 0 (atan; k sets its steepness)."""
    return "(0.5+atan(%g*(%s))/pi)" % (k, expr)


# ---------------------------------------------------------------- Gull Bay (seaside) -------------
SEA = "seaside"


def seaside():
    h = []
    # 1. Harbour Wall: a breakwater juts from the lower rail and hides the cup. Beginners putt past
    # its end and then in; the ace banks off the top rail round it.
    h.append(("01-harbour-wall", course("Harbour Wall", "0.1 + 0.03*exp(-(x+0.8)^2/0.8)", lane(-3.5, 3.5, 0.8),
                                        (-3.0, 0.3), (2.1, -0.5),
                                        wall([(1.6, -0.8), (1.6, 0.2)], 0.12) + [box(1.6, 0.2, 0.16, 0.16, 0.0, 0.18)],
                                        world=SEA), 3))
    # 2. Dune Ridge: a grassy ridge across the lane with a low saddle near the top rail; over the
    # ridge needs pace, through the saddle needs aim.
    ridge = "0.1 + 0.15*exp(-(x-0.2)^2/0.12)*(1-0.85*exp(-(y-0.45)^2/0.05))"
    h.append(("02-dune-ridge", course("Dune Ridge", ridge, lane(-3.5, 3.5, 0.9), (-3.0, -0.3), (2.85, -0.55),
                                      [box(2.2, 0.25, 0.5, 0.12, 0.0, 0.2, 25), box(1.3, -0.3, 0.35, 0.35, 0.0, 0.2, 45, 0.9)]
                                      + pocket(2.5, -0.9, 3.1, -0.15), world=SEA), 3))
    # 3. Tidal Pool: a pool fills the middle of a wide fairway, its banks sloping in. The long way
    # round the top is wide; the bottom shore is short and narrow.
    pool = "0.12 - 0.36*" + g(0.2, -0.1, 1.3, 0.4)
    h.append(("03-tidal-pool", course("Tidal Pool", pool, lane(-4, 4, 1.4), (-3.4, 0), (3.3, 1.15),
                                      [pillar(2.5, 0.6, 0.12, 0.5)] + pocket(3.0, 1.4, 3.75, 0.75), world=SEA), 3))
    # 4. Pot Bunkers: three pots guard the cup; a ball-wide gap between the front two is the ace line.
    pots = [zone(circle(1.55, 0.36, 0.3), SAND), zone(circle(1.55, -0.36, 0.3), SAND), zone(circle(3.0, 0.55, 0.28), SAND),
            zone(circle(3.0, -0.5, 0.25), SAND)]
    h.append(("04-pot-bunkers", course("Pot Bunkers", "0.1 - 0.012*x", lane(-3.5, 3.5, 1.0), (-3.0, 0.0), (2.55, 0.0),
                                       [pillar(0.0, 0.0, 0.1, 0.4)], pots, world=SEA), 2))
    # 5. Sea Breeze: a long lane falling towards the sea (the lower rail); a groyne halfway makes
    # the straight putt a bank, the safe play a lay-up before it.
    h.append(("05-sea-breeze", course("Sea Breeze", "0.25 + 0.07*y + 0.015*sin(1.3*x)", lane(-5, 5, 0.85),
                                      (-4.4, 0.4), (4.2, 0.45),
                                      wall([(0.6, -0.85), (0.6, 0.35)], 0.1) + wall([(3.2, 0.85), (3.2, -0.2)], 0.1), world=SEA), 3))
    # 6. Lighthouse: a round tower stands between tee and cup; the cup is tucked behind it. Go
    # round either side (two putts) or bank off the side rail for the ace.
    # The cup hides in the keeper's yard in the corner beyond the tower, its gate by the end rail.
    h.append(("06-lighthouse", course("Lighthouse", "0.1", lane(-3.0, 3.0, 1.1), (-2.5, 0.0), (2.35, -0.75),
                                      [pillar(1.0, 0.0, 0.35, 0.8, 0.55)] + pocket(2.0, -1.1, 2.7, -0.4), world=SEA), 2))
    # 7. Jetty: the cup at the end of a jetty over the water: rails on the jetty, water each side of
    # its neck. Lay up on the landing, then putt along the jetty.
    jetty = [(-3.5, -1.0), (0.0, -1.0), (0.0, -0.3), (3.2, -0.3), (3.2, 0.3), (0.0, 0.3), (0.0, 1.0), (-3.5, 1.0)]
    sea = "0.1 + 0.02*exp(-(x-1.6)^2/0.2) - 0.4*" + step("x-0.08", 25) + "*" + step("abs(y)-0.42", 25)
    h.append(("07-jetty", course("Jetty", sea, jetty, (-3.0, 0.5), (2.6, 0.13),
                                 [pillar(1.2, 0.06, 0.1, 0.5)] + pocket(2.4, 0.3, 2.75, -0.05),
                                 world=SEA, slope_region=jetty), 3))
    # 8. Switchback: a Z of two doglegs; each corner is a bank.
    z = [(-3.5, -1.5), (1.0, -1.5), (1.0, 0.5), (3.5, 0.5), (3.5, 1.5), (-0.2, 1.5), (-0.2, -0.5), (-3.5, -0.5)]
    h.append(("08-switchback", course("Switchback", "0.1", z, (-3.0, -1.0), (3.0, 1.0),
                                      [pillar(1.0, -0.5, 0.08, 0.3)], [outside(z)], world=SEA), 3))
    # 9. Shell Bowl: the cup sits on the rim of a shallow bowl; too soft falls back in, too firm runs on.
    bowl = "0.12 + 0.22*(1-" + g(0.0, 0.0, 2.2, 1.6) + ")"
    h.append(("09-shell-bowl", course("Shell Bowl", bowl, lane(-2.8, 2.8, 1.5), (-2.3, -0.9), (1.5, 0.8),
                                      [box(0.0, 0.0, 0.3, 0.3, 0.0, 0.3, 45, 0.9)], world=SEA), 2))
    # 10. Rock Pools: four small pools to weave between; the straight line skirts two of them.
    rockpools = "0.1 - 0.2*(" + "+".join([g(-1.2, 0.45, 0.14, 0.14), g(0.0, -0.45, 0.14, 0.14), g(1.2, 0.45, 0.14, 0.14)]) + ")"
    h.append(("10-rock-pools", course("Rock Pools", rockpools, lane(-3.5, 3.5, 1.1), (-3.0, 0.0), (2.8, -0.75),
                                      [pillar(-0.6, 0.0, 0.09, 0.4)] + pocket(2.5, -1.1, 3.05, -0.4), world=SEA), 3))
    # 11. Beach Huts: painted huts stand in the lane as lively bumpers; find the alley between them.
    huts = [box(-1.0, 0.35, 0.45, 0.45, 0.0, 0.35, 0, 0.9), box(0.2, -0.35, 0.45, 0.45, 0.0, 0.35, 0, 0.9),
            box(1.4, 0.35, 0.45, 0.45, 0.0, 0.35, 0, 0.9), box(2.3, -0.3, 0.3, 0.3, 0.0, 0.35, 45, 0.9),
            box(2.5, 0.4, 0.4, 0.4, 0.0, 0.35, 0, 0.9)]
    # A buoy (a bumper) by the lower rail kicks a ball that hugs the rail back into the alley.
    buoys = [bumper(-0.4, -0.62, 0.08)]
    h.append(("11-beach-huts", course("Beach Huts", "0.1", lane(-3.5, 3.5, 0.9), (-3.0, -0.4), (3.05, 0.5), huts + buoys,
                                      world=SEA), 3))
    # 12. Lagoon Carry: a lagoon lies across the lane; a narrow causeway runs along the lower rail,
    # or chip straight over onto the green.
    lagoon = "0.12 - 0.4*exp(-(x-0.3)^2/0.35)*" + step("y+0.4", 4)
    h.append(("12-lagoon-carry", course("Lagoon Carry", lagoon, lane(-3.5, 3.5, 1.0), (-3.0, 0.3), (2.85, 0.65),
                                        [pillar(2.3, -0.3, 0.09, 0.4)] + pocket(2.5, 1.0, 3.2, 0.3), world=SEA,
                                        slope_region=[(-3.5, -1.0), (3.5, -1.0), (3.5, 1.0), (-3.5, 1.0)]), 3))
    # 13. Slipway: a long ramp down to a shelf above the water; the cup is on the shelf, the water
    # beyond the end rail's gap. Pace is everything.
    slip = "0.45 - 0.09*(x+3) + 0.09*(x-1.2)*" + step("x-1.2", 8) + " - 0.5*" + step("x-3.6", 10)
    # A gate on the shelf's edge, off the line to the cup.
    h.append(("13-slipway", course("Slipway", slip, lane(-3.5, 3.3, 0.75), (-3.0, 0.0), (2.75, -0.45),
                                   [box(1.7, -0.3, 0.1, 0.9, 0.0, 0.2), box(1.7, 0.565, 0.1, 0.37, 0.0, 0.2)]
                                   + pocket(2.5, -0.75, 3.0, -0.15), world=SEA,
                                   slope_region=lane(-3.5, 3.3, 0.75)), 3))
    # 14. Breakwater: staggered walls make a chicane; bank through it. A lock gate slides to and fro
    # in the middle opening: half of it is always open, which half depends on the moment.
    chic = wall([(-1.2, -0.9), (-1.2, 0.35)]) + wall([(0.6, 0.9), (0.6, -0.35)]) + wall([(2.0, -0.9), (2.0, 0.2)])
    lock = moving(box(0.6, -0.76, 0.08, 0.28, 0.0, 0.22, 0, 0.5), slide([(0, 0, 0), (0, 0.27, 0)], 3.0))
    h.append(("14-breakwater", course("Breakwater", "0.1", lane(-3.5, 3.5, 0.9), (-3.0, -0.5), (3.0, -0.4), chic + [lock],
                                      world=SEA), 3))
    # 15. Twin Greens: two tiers split by a wall with one gap; the cup is on the upper tier.
    tiers = "0.1 + 0.12*" + step("x-0.8", 5)
    h.append(("15-twin-greens", course("Twin Greens", tiers, lane(-3.0, 3.0, 1.0), (-2.5, 0.5), (2.45, -0.68),
                                       wall([(0.8, 1.0), (0.8, 0.3)]) + wall([(0.8, -0.25), (0.8, -1.0)]) + pocket(2.2, -1.0, 2.7, -0.35),
                                       world=SEA), 3))
    # 16. Sandbar: a strip of sand across the whole lane; roll through it hard or chip over.
    h.append(("16-sandbar", course("Sandbar", "0.1 + 0.01*x", lane(-3.5, 3.5, 0.8), (-3.0, 0.0), (2.95, 0.5),
                                   pocket(2.6, 0.8, 3.2, 0.2), [zone(polygon([(-0.3, -0.8), (0.6, -0.8), (0.9, 0.8), (0.0, 0.8)]), SAND)],
                                   world=SEA), 3))
    # 17. Crab Walk: the green steps up in terraces across the lane; the cup sits high on the left.
    terr = "0.1 + 0.1*" + step("y-0.3", 9) + " + 0.05*" + step("x-1.5", 6)
    h.append(("17-crab-walk", course("Crab Walk", terr, lane(-3.5, 3.5, 1.1), (-3.0, -0.6), (2.95, 0.8),
                                     wall([(-0.5, 0.15), (2.2, 0.15)]) + pocket(2.7, 1.1, 3.2, 0.5), world=SEA), 3))
    # 18. Lighthouse Point: the finale: a long lane with the windmill, a pool and a ridge before the
    # cup at the point.
    fin = "0.3 - 0.025*x - 0.34*" + g(1.7, -0.65, 0.35, 0.2) + " + 0.1*exp(-(x-3.3)^2/0.1)*(1-0.9*exp(-(y-0.6)^2/0.06))"
    h.append(("18-lighthouse-point", course("Lighthouse Point", fin, lane(-5, 5, 1.3), (-4.4, 0.0), (4.3, 0.0),
                                            windmill(-1.5, 0.0, 0.3 + 0.025 * 1.5, 270, 0.7) + [pillar(0.9, 0.6, 0.12, 0.6)],
                                            world=SEA), 3))
    return h


# ---------------------------------------------------------------- Red Rock Canyon ----------------
CANYON = "canyon"
REDSAND = 0.6, 0.7


def canyon():
    h = []
    # 1. Trailhead: the lane lies in a shallow trough; a rock pillar blocks the straight line, and the
    # trough's banks curve a ball round it.
    trough = "0.1 + 0.22*y^2*" + step("2.2-x", 4) + " + 0.01*x"
    h.append(("01-trailhead", course("Trailhead", trough, lane(-3.5, 3.5, 0.85), (-3.0, 0.0), (2.9, 0.55),
                                     [pillar(0.4, 0.0, 0.16, 0.6)] + pocket(2.6, 0.85, 3.2, 0.25), world=CANYON), 2))
    # 2. Dry Wash: the wash winds like a snake; the ball follows its floor, a straight putt climbs the bank.
    wash = "0.1 + 0.25*(y-0.45*sin(0.8*x))^2"
    h.append(("02-dry-wash", course("Dry Wash", wash, lane(-3.5, 3.5, 1.0), (-3.0, -0.3), (2.9, 0.33),
                                    [pillar(0.0, 0.05, 0.1, 0.5)] + wall([(2.2, 0.1), (2.2, 0.75)]), world=CANYON), 2))
    # 3. Mesa Top: the cup sits on a round mesa; under-hit balls roll back off its slopes, over-hit ones
    # run off the far side.
    mesa = "0.1 + 0.2*(0.5-atan(6*(sqrt((x-2.0)^2+y^2)-0.75))/pi)"
    h.append(("03-mesa-top", course("Mesa Top", mesa, lane(-3.5, 3.5, 1.2), (-3.0, 0.4), (2.1, -0.1),
                                    [pillar(-0.2, 0.3, 0.12, 0.5)] + wall([(1.3, -0.45), (1.22, 0.0), (1.3, 0.45)]),
                                    world=CANYON), 3))
    # 4. Cactus Garden: a slalom of saguaros; the cup hides behind the last pair.
    cacti = [tree(-1.6, 0.3, 0.1, 1.8), tree(-0.6, -0.35, 0.1, 2.2), tree(0.4, 0.35, 0.1, 1.9), tree(1.4, -0.3, 0.1, 2.0),
             tree(2.3, 0.2, 0.09, 1.7)]
    h.append(("04-cactus-garden", course("Cactus Garden", "0.1 + 0.01*sin(2*x)", lane(-3.5, 3.5, 0.9), (-3.0, 0.0),
                                         (2.9, -0.6), cacti + pocket(2.6, -0.9, 3.2, -0.3), world=CANYON), 3))
    # 5. Red Sand: a wide trap of red sand crosses the lane on a slant; a grass causeway runs along the top rail.
    trap = [zone(polygon([(-1.4, -1.0), (0.6, -1.0), (1.6, 0.45), (-0.4, 0.45)]), REDSAND), zone(circle(2.6, -0.6, 0.3), REDSAND)]
    h.append(("05-red-sand", course("Red Sand", "0.1 - 0.015*y", lane(-3.5, 3.5, 1.0), (-3.0, -0.5), (2.9, -0.6),
                                    [pillar(2.0, 0.45, 0.1, 0.5)] + pocket(2.3, -1.0, 3.1, -0.3), trap, world=CANYON), 3))
    # 6. Slot Canyon: the lane squeezes through a slot barely wider than two balls, then turns.
    slot = [(-3.5, -0.9), (0.4, -0.9), (0.4, -0.12), (1.4, -0.12), (1.4, -1.2), (3.2, -1.2), (3.2, 0.9), (1.4, 0.9),
            (1.4, 0.12), (0.4, 0.12), (0.4, 0.9), (-3.5, 0.9)]
    # A cave mouth in the corner by the slot (a teleport) comes out in the far room, rolling towards the cup.
    cave = teleport(circle(0.0, 0.62, 0.13), [(1.85, 0.55, -90)])
    h.append(("06-slot-canyon", course("Slot Canyon", "0.1", slot, (-3.0, 0.4), (2.6, -0.6),
                                       wall([(2.3, 0.9), (2.3, 0.0)]), [outside(slot, REDSAND)], world=CANYON,
                                       teleports=[cave]), 3))
    # 7. Rattlesnake: an S of two bends; bank off the outside of each.
    s_lane = [(-3.5, -1.4), (0.3, -1.4), (0.3, 0.3), (3.5, 0.3), (3.5, 1.4), (-0.8, 1.4), (-0.8, -0.3), (-3.5, -0.3)]
    h.append(("07-rattlesnake", course("Rattlesnake", "0.1 + 0.02*y", s_lane, (-3.0, -0.85), (3.0, 0.85),
                                       [pillar(-0.25, 0.55, 0.1, 0.4)], [outside(s_lane, REDSAND)], world=CANYON), 3))
    # 8. Stone Arch: two pillars carry an arch (the ball rolls under it) before a ridge; the cup is
    # just over the ridge, off to the side.
    ridge = "0.1 + 0.12*exp(-(x-1.3)^2/0.15)"
    arch = [pillar(0.0, 0.42, 0.12, 0.7), pillar(0.0, -0.42, 0.12, 0.7), box(0.0, 0.0, 0.26, 1.1, 0.38, 0.55)]
    h.append(("08-stone-arch", course("Stone Arch", ridge, lane(-3.0, 3.0, 0.95), (-2.5, 0.3), (2.3, -0.55),
                                      arch + pocket(1.9, -0.95, 2.6, -0.15),
                                      world=CANYON), 2))
    # 9. Butte Bowl: a bowl with a butte in its middle; the cup sits on the bowl's far slope.
    bowl = "0.1 + 0.18*((x/2.6)^2+(y/1.4)^2) + 0.2*" + g(0.0, 0.0, 0.15, 0.15)
    h.append(("09-butte-bowl", course("Butte Bowl", bowl, lane(-2.8, 2.8, 1.4), (-2.3, 0.0), (1.6, 0.5), [],
                                      world=CANYON), 2))
    # 10. Switchback Trail: the trail climbs in two ramps linked by a hairpin.
    hair = [(-3.5, -1.3), (2.6, -1.3), (2.6, 1.3), (-3.5, 1.3), (-3.5, 0.25), (1.6, 0.25), (1.6, -0.25), (-3.5, -0.25)]
    up = step("y", 8)
    climb = "0.1 + 0.04*(x+3.5)*(1-%s) + (0.344 + 0.04*(2.6-x))*%s" % (up, up)
    h.append(("10-switchback-trail", course("Switchback Trail", climb, hair, (-3.0, -0.8), (-2.8, 0.8),
                                            [pillar(0.0, 0.8, 0.1, 0.4)], [outside(hair, REDSAND)], world=CANYON,
                                            slope_region=hair), 3))
    # 11. Boulder Field: tumbled boulders (turned blocks) lie across the lane.
    boulders = [box(-1.3, 0.4, 0.4, 0.35, -0.05, 0.3, 20, 0.7), box(-0.4, -0.35, 0.45, 0.4, -0.05, 0.32, 55, 0.7),
                box(0.6, 0.25, 0.4, 0.45, -0.05, 0.3, 10, 0.7), box(1.5, -0.3, 0.35, 0.35, -0.05, 0.28, 35, 0.7),
                box(2.2, 0.45, 0.3, 0.3, -0.05, 0.25, 70, 0.7)]
    h.append(("11-boulder-field", course("Boulder Field", "0.1", lane(-3.5, 3.5, 1.0), (-3.0, -0.3), (2.95, -0.2),
                                         boulders + [box(2.5, -0.2, 0.3, 0.3, -0.05, 0.3, 45, 0.7)], world=CANYON), 3))
    # 12. Oasis: a spring fills the middle; cacti stand on its shores. Round it on either shore (they
    # lean towards the water), or chip straight over it.
    pool = "0.12 - 0.3*" + g(0.4, 0.0, 1.0, 0.25)
    palms = [tree(0.2, 0.95, 0.1, 2.3), tree(1.9, 0.85, 0.1, 2.6), tree(-0.3, -0.95, 0.1, 2.4), tree(2.3, -0.2, 0.09, 1.8)]
    h.append(("12-oasis", course("Oasis", pool, lane(-3.5, 3.5, 1.2), (-3.0, 0.0), (2.9, 0.87),
                                 palms + pocket(2.6, 1.2, 3.2, 0.55), world=CANYON), 3))
    # 13. Sidewinder: the lane tilts one way, then the other, like a snake's track.
    side = "0.25 + 0.08*y*sin(0.9*x)"
    h.append(("13-sidewinder", course("Sidewinder", side, lane(-4.5, 4.5, 0.8), (-4.0, 0.0), (4.0, -0.35),
                                      [pillar(-0.5, 0.0, 0.1, 0.5), pillar(2.3, 0.0, 0.1, 0.5)] + wall([(3.3, -0.8), (3.3, 0.1)])
                                      + [pillar(3.3, 0.45, 0.1, 0.5)], world=CANYON), 3))
    # 14. River Crossing: a river cuts the canyon; a narrow stone bridge crosses it near the top rail.
    river = "0.12 - 0.35*exp(-(x-0.2)^2/0.12)*" + step("-(y-0.45)", 30)
    bridge = wall([(-0.35, 0.53), (0.75, 0.53)], 0.06, 0.08) + wall([(-0.35, 0.95), (0.75, 0.95)], 0.06, 0.08)
    h.append(("14-river-crossing", course("River Crossing", river, lane(-3.5, 3.5, 1.0), (-3.0, -0.3), (2.8, -0.4),
                                          bridge + wall([(1.2, 0.3), (3.0, 0.3)]),
                                          world=CANYON, slope_region=[(-3.5, 0.55), (3.5, 0.55), (3.5, 1.0), (-3.5, 1.0)]), 3))
    # 15. Funnel Rock: the ground funnels towards a gap between two rocks; the cup waits beyond.
    fun = "0.1 + 0.06*abs(y)^1.5*" + step("0.8-x", 3) + " - 0.01*x"
    h.append(("15-funnel-rock", course("Funnel Rock", fun, lane(-3.0, 3.0, 1.1), (-2.5, 0.7), (2.4, 0.78),
                                       [pillar(1.2, 0.3, 0.18, 0.6), pillar(1.2, -0.3, 0.18, 0.6), pillar(1.75, 0.0, 0.1, 0.5)]
                                       + pocket(2.1, 1.1, 2.7, 0.45), world=CANYON,
                                       slope_region=lane(-3.0, 3.0, 1.1)), 3))
    # 16. Ridge Run: the cup is on a ridge's crest; miss the crest and the ball runs down either flank.
    ridge = "0.1 + 0.2*exp(-y^2/0.18)*" + step("x+1.0", 4)
    h.append(("16-ridge-run", course("Ridge Run", ridge, lane(-3.5, 3.5, 1.0), (-3.0, 0.0), (2.6, 0.05),
                                     [pillar(0.4, 0.0, 0.1, 0.5)], world=CANYON), 3))
    # 17. Sandstorm: dunes roll across the lane and drifts of sand sit in the troughs.
    dunes = "0.15 + 0.06*sin(2.2*x+0.5*y)"
    drifts = [zone(circle(-1.0, 0.3, 0.35), REDSAND), zone(circle(0.45, -0.35, 0.32), REDSAND), zone(circle(1.85, 0.35, 0.3), REDSAND)]
    # Gusts blow across the lane in two bands, one each way (push zones).
    gusts = [push(rect(-2.2, -0.9, -1.5, 0.9), 0.0, 0.7), push(rect(0.9, -0.9, 1.5, 0.9), 0.0, -0.7)]
    h.append(("17-sandstorm", course("Sandstorm", dunes, lane(-3.5, 3.5, 0.9), (-3.0, 0.0), (2.95, -0.45),
                                     wall([(2.5, -0.9), (2.5, 0.2)]), drifts,
                                     world=CANYON, push_zones=gusts), 3))
    # 18. Grand Canyon: the finale: down into the canyon past the windmill, over the river by the
    # bridge, and up to the cup on the far rim. Its sails stand still: with turning sails the medium
    # opponent's games cost up to 50 times the CPU (it plans waits; no long steps under the sails) and
    # par-check cut one of them at its time limit (docs/worlds.md).
    gc = ("0.35 - 0.25*" + step("x+1.2", 3) + " + 0.3*" + step("x-2.8", 3)
          + " - 0.3*exp(-(x-0.9)^2/0.08)*" + step("-(y-0.55)", 30))
    gbridge = wall([(0.45, 0.62), (1.35, 0.62)], 0.06, 0.08) + wall([(0.45, 1.3), (1.35, 1.3)], 0.06, 0.08)
    h.append(("18-grand-canyon", course("Grand Canyon", gc, lane(-5, 5, 1.3), (-4.4, 0.0), (4.2, 0.0),
                                        still_windmill(-2.6, 0.0, 0.35 - 0.25 * 0.13, 90, 0.7) + gbridge
                                        + wall([(4.6, 0.5), (3.7, 0.5), (3.7, -0.5), (4.6, -0.5)]), world=CANYON,
                                        slope_region=[(-5, 0.62), (5, 0.62), (5, 1.3), (-5, 1.3)]), 4))
    return h


# ---------------------------------------------------------------- Frostkeep (winter castle) ------
WINTER = "winter"
SNOW = 0.45, 0.55


def block(x0, y0, x1, y1, z1=0.3, restitution=0.7):
    """A stone block (castle masonry) standing from below the ground to z1."""
    return box((x0 + x1) / 2, (y0 + y1) / 2, x1 - x0, y1 - y0, -0.05, z1, 0, restitution)


def winter():
    h = []
    # 1. Gatehouse: a castle wall across the lane with one gate, off the straight line; the cup is
    # just inside, to the other side.
    gate = [block(0.0, -1.0, 0.25, -0.05), block(0.0, 0.3, 0.25, 1.0), pillar(0.125, -0.05, 0.1, 0.45), pillar(0.125, 0.3, 0.1, 0.45)]
    h.append(("01-gatehouse", course("Gatehouse", "0.1", lane(-3.5, 3.5, 1.0), (-3.0, -0.4), (2.9, -0.68),
                                     gate + pocket(2.6, -1.0, 3.2, -0.35),
                                     world=WINTER), 3))
    # 2. Frozen Pond: a sheet of ice lies before the cup; the ball glides, so the pace must be soft;
    # a snowbank behind the cup forgives a little.
    ice = [zone(circle(0.9, 0.0, 1.0), ICE), zone(rect(3.0, -0.8, 3.5, 0.2), SNOW)]
    h.append(("02-frozen-pond", course("Frozen Pond", "0.1 - 0.01*x", lane(-3.5, 3.5, 0.8), (-3.0, 0.3), (2.7, 0.5),
                                       [pillar(0.9, 0.0, 0.12, 0.5)] + pocket(2.4, 0.8, 3.0, 0.2), ice, world=WINTER), 2))
    # 3. Moat: the cup is in a walled courtyard ringed by a moat; the drawbridge leads to the gate.
    moat = "0.12 - 0.35*exp(-(sqrt((x-1.8)^2+y^2)-1.05)^2/0.025)*" + step("abs(y)-0.27", 30)
    court = [block(1.05, -0.75, 1.2, -0.18), block(1.05, 0.18, 1.2, 0.75), block(1.05, 0.6, 2.55, 0.75), block(1.05, -0.75, 2.55, -0.6),
             block(2.4, -0.75, 2.55, 0.75)]
    drawbridge = wall([(0.45, 0.2), (1.1, 0.2)], 0.06, 0.07) + wall([(0.45, -0.2), (1.1, -0.2)], 0.06, 0.07)
    screen = wall([(1.5, -0.2), (1.5, 0.2)])
    h.append(("03-moat", course("Moat", moat, lane(-3.2, 3.3, 1.5), (-2.7, 0.6), (2.1, 0.3), court + drawbridge + screen,
                                world=WINTER, slope_region=[(-3.2, -0.16), (3.3, -0.16), (3.3, 0.16), (-3.2, 0.16)]), 3))
    # 4. Snow Banks: deep snow along both rails and a drift in the middle; the clear path is a
    # narrow S between them.
    banks = [zone(rect(-1.5, 0.35, 0.5, 1.0), SNOW), zone(rect(0.2, -1.0, 2.0, -0.3), SNOW)]
    drift = "0.1 + 0.08*" + g(0.0, -0.2, 0.1, 0.08)
    h.append(("04-snow-banks", course("Snow Banks", drift, lane(-3.5, 3.5, 1.0), (-3.0, 0.0), (2.9, 0.68),
                                      pocket(2.6, 1.0, 3.2, 0.35), banks,
                                      world=WINTER), 2))
    # 5. Round Tower: a tower stands in the lane with the cup in its lee; bank round it.
    h.append(("05-round-tower", course("Round Tower", "0.1", lane(-3.0, 3.0, 1.1), (-2.5, 0.0), (2.35, 0.78),
                                       [pillar(1.0, 0.0, 0.38, 0.9)] + pocket(2.0, 1.1, 2.7, 0.45), world=WINTER), 2))
    # 6. Battlements: a wall of merlons across the lane; three crenels let the ball through, and the
    # cup is straight behind a merlon.
    merlons = [block(0.5, -1.0, 0.7, -0.6), block(0.5, -0.3, 0.7, 0.0), block(0.5, 0.3, 0.7, 0.55), block(0.5, 0.85, 0.7, 1.0)]
    h.append(("06-battlements", course("Battlements", "0.1 + 0.006*x", lane(-3.0, 3.0, 1.0), (-2.5, 0.2), (2.3, -0.15),
                                       merlons, world=WINTER), 3))
    # 7. Ice Slide: a chute of ice runs downhill to a snowy green; the snow stops the ball, the pace
    # must be just enough.
    chute = "0.35 - 0.08*(x+3)*" + step("-(x-0.5)", 5)
    h.append(("07-ice-slide", course("Ice Slide", chute, lane(-3.5, 3.5, 0.7), (-3.0, 0.0), (2.9, -0.35),
                                     [pillar(2.0, 0.15, 0.09, 0.4)] + pocket(2.5, -0.7, 3.2, -0.05),
                                     [zone(rect(-3.5, -0.7, 0.3, 0.7), ICE), zone(rect(3.0, -0.7, 3.5, 0.7), SNOW)],
                                     world=WINTER), 2))
    # 8. Courtyard: an L round the keep; bank off the keep's wall, or play the corner in two.
    ell = [(-3.5, -1.6), (2.2, -1.6), (2.2, 1.6), (1.0, 1.6), (1.0, -0.5), (-3.5, -0.5)]
    h.append(("08-courtyard", course("Courtyard", "0.1", ell, (-3.0, -1.05), (1.6, 1.1),
                                     [block(-1.5, -0.5, -1.2, 0.2, 0.6)], [outside(ell, SNOW)], world=WINTER), 3))
    # 9. Portcullis: a narrow gate between two towers, set at an angle; beyond it the cup lies
    # round a low wall.
    port = wall([(0.0, -1.0), (0.3, -0.12)], 0.14, 0.18) + wall([(0.45, 0.3), (0.75, 1.0)], 0.14, 0.18) + \
        [pillar(0.3, -0.12, 0.1, 0.5), pillar(0.45, 0.3, 0.1, 0.5)] + wall([(2.0, -0.2), (2.0, 1.0)])
    # The portcullis rises and falls in the gate (4 s): time the putt, or bank round the towers.
    grille = moving(box(0.375, 0.09, 0.05, 0.26, 0.1, 0.4, -19.65, 0.5), slide([(0, 0, 0), (0, 0, 0.14)], 4.0))
    h.append(("09-portcullis", course("Portcullis", "0.1", lane(-3.0, 3.2, 1.0), (-2.5, -0.5), (2.6, 0.5), port + [grille],
                                      world=WINTER), 3))
    # 10. Sledge Run: a curving run banked like a toboggan track.
    run = "0.1 + 0.24*(y-0.5*sin(0.7*x+0.6))^2*" + step("2.9-x", 5)
    h.append(("10-sledge-run", course("Sledge Run", run, lane(-4.0, 4.0, 1.0), (-3.5, -0.2), (3.35, -0.68),
                                      [pillar(0.6, 0.35, 0.1, 0.45)] + pocket(3.0, -1.0, 3.7, -0.35), world=WINTER), 3))
    # 11. Frozen Fountain: the cup tops a mound ringed with ice; soft balls slide back, hard ones fly off.
    mound = "0.1 + 0.14*" + g(1.6, 0.0, 0.6, 0.6)
    h.append(("11-frozen-fountain", course("Frozen Fountain", mound, lane(-3.0, 3.0, 1.3), (-2.5, -0.5), (1.6, 0.0), [],
                                           [zone(circle(1.6, 0.0, 0.8), ICE), zone(circle(1.6, 0.0, 0.6), (0.1, 0.2))],
                                           world=WINTER), 3))
    # 12. Armoury: shields (lively blocks) hang across the lane at angles; find the alley.
    shields = [box(-1.2, 0.35, 0.5, 0.1, -0.05, 0.3, 30, 0.9), box(-0.2, -0.4, 0.5, 0.1, -0.05, 0.3, -30, 0.9),
               box(0.8, 0.3, 0.5, 0.1, -0.05, 0.3, 40, 0.9), box(1.8, -0.3, 0.5, 0.1, -0.05, 0.3, -40, 0.9)]
    h.append(("12-armoury", course("Armoury", "0.1", lane(-3.0, 3.2, 0.9), (-2.5, 0.0), (2.65, -0.6),
                                   shields + pocket(2.4, -0.9, 2.9, -0.3),
                                   world=WINTER), 3))
    # 13. Drawbridge: a narrow bridge over the moat with low rails; miss it and the ball is in the water.
    moat2 = "0.12 - 0.4*exp(-(x-0.2)^2/0.3)*" + step("abs(y)-0.36", 30)
    br = wall([(-0.9, 0.3), (1.3, 0.3)], 0.06, 0.07) + wall([(-0.9, -0.3), (1.3, -0.3)], 0.06, 0.07)
    h.append(("13-drawbridge", course("Drawbridge", moat2, lane(-3.0, 3.0, 1.1), (-2.5, 0.6), (2.4, -0.85),
                                      br + pocket(2.15, -1.1, 2.75, -0.5),
                                      world=WINTER, slope_region=[(-3.0, -0.25), (3.0, -0.25), (3.0, 0.25), (-3.0, 0.25)]), 3))
    # 14. Snowdrifts: soft mounds lie across the lane; thread the gaps or ride over them.
    drifts = "0.1 + 0.12*(" + "+".join([g(-1.0, 0.35, 0.15, 0.15), g(0.0, -0.3, 0.18, 0.15), g(1.0, 0.3, 0.15, 0.18),
                                        g(1.9, -0.25, 0.12, 0.12)]) + ")"
    h.append(("14-snowdrifts", course("Snowdrifts", drifts, lane(-3.0, 3.0, 0.9), (-2.5, 0.0), (2.5, 0.6),
                                      pocket(2.3, 0.9, 2.7, 0.3),
                                      world=WINTER), 2))
    # 15. Great Hall: two rows of columns down a long hall; the cup is past the last pair.
    cols = [pillar(x, y, 0.1, 0.8) for x in (-2.0, -0.8, 0.4, 1.6) for y in (-0.4, 0.4)] + [pillar(2.6, 0.0, 0.12, 0.8)]
    h.append(("15-great-hall", course("Great Hall", "0.1", lane(-4.0, 4.0, 1.0), (-3.5, 0.0), (3.35, 0.68),
                                      cols + pocket(3.0, 1.0, 3.7, 0.35),
                                      world=WINTER), 3))
    # 16. Icicle Alley: bands of ice and snow across the lane: fast, slow, fast, slow.
    bands = [zone(rect(x, -0.8, x + 0.6, 0.8), ICE if k % 2 == 0 else SNOW) for k, x in enumerate((-2.2, -1.2, -0.2, 0.8, 1.8))]
    # A one-way gate after the last band: a ball through it stays at the cup's end.
    h.append(("16-icicle-alley", course("Icicle Alley", "0.1 + 0.02*y", lane(-3.5, 3.5, 0.8), (-3.0, 0.0), (3.0, 0.45),
                                        pocket(2.6, 0.8, 3.2, 0.1) + [one_way((2.45, -0.8), (2.45, 0.8), "right")], bands,
                                        world=WINTER), 3))
    # 17. Spiral Stair: terraces climb round a central tower; the cup is on the top landing.
    stair = "0.1 + 0.09*" + step("x+0.6", 7) + " + 0.09*" + step("y-0.2", 7) + "*" + step("x-0.6", 5)
    h.append(("17-spiral-stair", course("Spiral Stair", stair, lane(-3.0, 3.0, 1.2), (-2.5, -0.7), (-0.8, 0.8),
                                        [pillar(0.0, 0.15, 0.35, 0.9)] + wall([(-3.0, 0.35), (-0.35, 0.35)]), world=WINTER), 3))
    # 18. The Keep: the finale: over the drawbridge, round the windmill in the courtyard, up the
    # mound to the cup by the keep's door.
    keep = ("0.12 - 0.4*exp(-(x+1.8)^2/0.15)*" + step("abs(y)-0.34", 30) + " + 0.15*" + g(3.4, 0.0, 0.6, 0.6))
    kbr = wall([(-2.8, 0.28), (-0.8, 0.28)], 0.06, 0.07) + wall([(-2.8, -0.28), (-0.8, -0.28)], 0.06, 0.07)
    h.append(("18-the-keep", course("The Keep", keep, lane(-5.0, 5.0, 1.3), (-4.4, 0.0), (3.6, 0.2),
                                    kbr + windmill(0.8, 0.0, 0.12, 270, 0.7) + [block(4.5, -1.3, 5.0, 1.3, 0.6)], world=WINTER,
                                    slope_region=[(-5.0, -0.23), (5.0, -0.23), (5.0, 0.23), (-5.0, 0.23)]), 4))
    return h


def write(world, title, holes):
    folder = "courses/worlds/%s" % world
    os.makedirs(folder, exist_ok=True)
    for stem, c, _ in holes:
        dump(c, "%s/%s.json" % (folder, stem))
    round_file(title, holes, "courses/rounds/%s-18.json" % world, "../worlds/%s" % world)
    print("%s: %d holes, par %d" % (title, len(holes), sum(p for _, _, p in holes)))


if __name__ == "__main__":
    write(SEA, "Gull Bay", seaside())
    write(CANYON, "Red Rock Canyon", canyon())
    write(WINTER, "Frostkeep", winter())
