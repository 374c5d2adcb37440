#!/usr/bin/env python3
"""Writes the bundled rounds: the 18 holes of "Meadowbrook" in courses/holes/ and the round files
courses/rounds/meadowbrook-18.json (all 18) and courses/rounds/meadowbrook-9.json (the front nine).

Every hole is a real minigolf lane: rails (walls) round it, the `capture` hole rule (a well-paced
putt drops), and one idea of its own. Par and the hole-in-one check live in
src/test/java/minigolf/game/RoundFilesTest.java. Deterministic; run from the repository root:

    python3 tools/generate_rounds.py
"""
import os

from holes_lib import *  # noqa: F401,F403 (RAIL, rails, box, tree, course, lane, dump, round_file, ...)


holes = []  # (file stem, course, par)

# 1. A straight lane over a gentle crown: the pace over the hump decides.
holes.append(("01-first-tee", course("First Tee", "0.1 + 0.06*exp(-(x-0.5)^2/0.6) + 0.01*x",
                                     lane(-4, 4, 0.6), (-3.4, 0), (3.3, 0.15)), 2))

# 2. Dogleg left: the cup is round the corner; bank off the far rail.
dog = [(-4, -2.6), (2.2, -2.6), (2.2, 1.2), (1.0, 1.2), (1.0, -1.4), (-4, -1.4)]
holes.append(("02-dogleg", course("Dogleg", "0.1", dog, (-3.4, -2.0), (1.6, -0.2)), 2))

# 3. The windmill's tower in the middle of the lane; narrow gaps either side, walls funnel to them.
holes.append(("03-windmill", course("Windmill", "0.1", lane(-4, 4, 0.85), (-3.4, 0.3), (3.3, 0),
                                    [{"type": "model", "file": "models/windmill.obj", "position": [0, 0, 0.1],
                                      "rotationDeg": 90, "scale": 1, "restitution": 0.5},
                                     box(3.0, 0.55, 0.08, 0.6, 0.0, 0.2), box(3.0, -0.55, 0.08, 0.6, 0.0, 0.2)]), 3))

# 4. A bunker in front of the cup: go round it, or through it hard.
holes.append(("04-bunker", course("Bunker", "0.1 + 0.005*y", lane(-3.5, 3.5, 1.0), (-3.0, 0), (2.8, 0),
                                  zones=[{"shape": {"type": "circle", "center": [1.8, 0], "radius": 0.6},
                                          "kineticFriction": 0.6, "staticFriction": 0.7},
                                         {"shape": {"type": "rect", "min": [-0.5, 0.5], "max": [0.5, 1.0]},
                                          "kineticFriction": 0.6, "staticFriction": 0.7}]), 3))

# 5. Island green: the cup on an island ringed by a pond, no way round on the ground: chip over the
# water (the loft), onto the island and putt, par 3. The ace is a chip from the tee that lands on
# the island's bank and runs in (32 degrees, 4.85 m/s; under 1% of chips straight at the cup hole).
ring = "exp(-(sqrt((x-1.8)^2+y^2)-0.9)^2/0.09)"
holes.append(("05-island", course("Island Green", "0.1 - 0.2*%s" % ring, lane(-1.6, 3.5, 1.5),
                                  (-1.0, 0), (1.8, 0)), 3))

# 6. Tree slalom on a gentle slope down towards the cup.
trees6 = [tree(-1.8, 0.25), tree(-1.0, -0.3), tree(-0.2, 0.3), tree(0.6, -0.25), tree(1.4, 0.2), tree(2.2, -0.2)]
holes.append(("06-tree-slalom", course("Tree Slalom", "0.3 - 0.02*x", lane(-4, 4, 0.8), (-3.4, 0), (3.3, 0), trees6), 2))

# 7. Volcano: the cup on top of a cone; too soft rolls back, too hard runs off the far side.
holes.append(("07-volcano", course("Volcano", "0.1 + 0.32*exp(-((x-1.2)^2+y^2)/1.1)", lane(-3.5, 3.5, 1.4),
                                   (-3.0, 0), (1.2, 0)), 3))

# 8. Funnel: two walls narrow the lane to a gap just wide enough for the ball, on a gentle downslope;
# too hard and it rattles off the walls, too soft and it never reaches the neck.
funnel = rails([(-0.6, 0.8), (1.2, 0.09)], False) + rails([(-0.6, -0.8), (1.2, -0.09)], False)
holes.append(("08-funnel", course("Funnel", "0.25 - 0.02*x", lane(-3.5, 3.5, 0.8), (-3.0, 0.4), (2.4, -0.1), funnel), 3))

# 9. Zigzag: two staggered inner walls make an S; bank through it.
holes.append(("09-zigzag", course("Zigzag", "0.1", lane(-4, 4, 1.2), (-3.4, -0.7), (3.3, 0.7),
                                  rails([(-1.5, -1.2), (-1.5, 0.5)], False) + rails([(1.3, 1.2), (1.3, -0.5)], False)), 3))

# 10. Pinball: turned bumpers (lively boxes) between tee and cup.
bumpers = [box(-1.2, 0.4, 0.3, 0.3, 0.0, 0.25, 45, 0.9), box(-0.2, -0.45, 0.3, 0.3, 0.0, 0.25, 30, 0.9),
           box(0.8, 0.3, 0.3, 0.3, 0.0, 0.25, 15, 0.9), box(1.8, -0.2, 0.3, 0.3, 0.0, 0.25, 60, 0.9)]
holes.append(("10-pinball", course("Pinball", "0.1", lane(-3.5, 3.5, 1.1), (-3.0, 0), (2.9, 0.1), bumpers), 3))

# 11. Saddle: a cross-slope that changes sign half way; the putt curves one way then the other.
holes.append(("11-saddle", course("Saddle", "0.25 + 0.03*y*x/(1+0.1*x^2)", lane(-3.5, 3.5, 1.2), (-3.0, 0.5),
                                  (2.9, -0.3)), 2))

# 12. Two tiers: the cup sits on the upper tier behind a steep step.
holes.append(("12-two-tiers", course("Two Tiers", "0.1 + 0.18*(0.5+atan(5*(x-0.5))/pi)", lane(-3.5, 3.5, 0.9),
                                     (-3.0, -0.3), (2.6, 0.3)), 2))

# 13. Castle: the cup inside a keep of boxes with one gate facing sideways.
keep = [box(1.65, 0.55, 0.4, 0.1, 0.0, 0.3), box(2.35, 0.55, 0.4, 0.1, 0.0, 0.3),  # the gate between them, facing north
        box(2.0, -0.55, 1.1, 0.1, 0.0, 0.3), box(2.55, 0.0, 0.1, 1.2, 0.0, 0.3), box(1.45, 0.0, 0.1, 1.2, 0.0, 0.3)]
holes.append(("13-castle", course("Castle", "0.1", lane(-3.5, 3.5, 1.3), (-3.0, 0), (2.1, 0), keep), 3))

# 14. Waves: rolling waves across the lane, pace on the last downslope.
holes.append(("14-waves", course("Waves", "0.2 + 0.05*sin(2.4*x) + 0.01*cos(3*y)", lane(-4, 4, 0.8),
                                 (-3.4, 0), (3.2, 0)), 2))

# 15. Ice rink: a slick strip in the middle, sand behind the cup.
holes.append(("15-ice-rink", course("Ice Rink", "0.1", lane(-4, 4, 0.8), (-3.4, 0.2), (3.0, -0.2),
                                    zones=[{"shape": {"type": "polygon", "points": [[-2, -0.8], [1.5, -0.8], [2.0, 0.8], [-1.5, 0.8]]},
                                            "kineticFriction": 0.02, "staticFriction": 0.05},
                                           {"shape": {"type": "rect", "min": [3.3, -0.8], "max": [4, 0.8]},
                                            "kineticFriction": 0.7, "staticFriction": 0.8}]), 2))

# 16. The bowl: the cup off the centre of a bowl; the ball rocks to and fro past it.
holes.append(("16-bowl", course("The Bowl", "0.1 + 0.25*(1-exp(-((x-1)^2+y^2)/2))", lane(-3.0, 3.0, 1.4), (-2.5, 0.8),
                                (1.5, -0.3)), 2))

# 17. Lake shore: a lake on the direct line; round it on the banked shore, or not at all.
lake = "0.18 - 0.35*exp(-(x^2+(y+0.3)^2)/0.9)"
holes.append(("17-lake-shore", course("Lake Shore", lake, lane(-3.5, 3.5, 1.6), (-3.0, -0.3), (2.8, -0.3),
                                      [tree(0.0, 1.25, 0.12), tree(-0.6, 1.35, 0.1)]), 3))

# 18. Grand finale: the windmill, trees and a pond on a long falling lane.
finale = "0.35 - 0.03*x - 0.3*exp(-((x-1.6)^2+(y+0.7)^2)/0.3)"
holes.append(("18-finale", course("Grand Finale", finale, lane(-5, 5, 1.3), (-4.4, 0), (4.2, 0.2),
                                  [{"type": "model", "file": "models/windmill.obj", "position": [-1.5, 0, 0.38],
                                    "rotationDeg": 90, "scale": 0.7, "restitution": 0.5},
                                   tree(1.0, 0.6), tree(2.6, -0.1), tree(3.3, 0.9)]), 3))

os.makedirs("courses/holes", exist_ok=True)
os.makedirs("courses/rounds", exist_ok=True)
for stem, c, _ in holes:
    dump(c, "courses/holes/%s.json" % stem)


round_file("Meadowbrook 18", holes, "courses/rounds/meadowbrook-18.json")
round_file("Meadowbrook Front Nine", holes[:9], "courses/rounds/meadowbrook-9.json")
print("%d holes, par %d (18) and %d (front nine)" % (len(holes), sum(h[2] for h in holes), sum(h[2] for h in holes[:9])))
