#!/usr/bin/env python3
"""Writes src/main/resources/textures/water-dudv.png: a tileable ripple map for the water shader.

R, G: the slope (du/dv) of a wave field in x and y, 128 = flat; B: the wave height. The field is a
sum of sine waves with integer wave numbers, so the tile repeats without seams. Seeded: the same
file every run. Run from the repository root: python3 tools/make_water_dudv.py
"""
import math
import random
from PIL import Image

SIZE = 128
WAVES = 28

rng = random.Random(20240611)
waves = []
for _ in range(WAVES):
    while True:
        kx, ky = rng.randint(-9, 9), rng.randint(-9, 9)
        k = math.hypot(kx, ky)
        if 2 <= k <= 10:
            break
    # Amplitude falls with wave number (a rough ocean spectrum), random phase.
    waves.append((kx, ky, 1.0 / k ** 1.5, rng.uniform(0, 2 * math.pi)))

height = [[0.0] * SIZE for _ in range(SIZE)]
dx = [[0.0] * SIZE for _ in range(SIZE)]
dy = [[0.0] * SIZE for _ in range(SIZE)]
for j in range(SIZE):
    for i in range(SIZE):
        u, v = 2 * math.pi * i / SIZE, 2 * math.pi * j / SIZE
        h = gx = gy = 0.0
        for kx, ky, a, phase in waves:
            arg = kx * u + ky * v + phase
            h += a * math.sin(arg)
            c = a * math.cos(arg)
            gx += c * kx
            gy += c * ky
        height[j][i], dx[j][i], dy[j][i] = h, gx, gy

def scale(field):
    m = max(abs(x) for row in field for x in row)
    return [[int(round(127.5 + 127 * x / m)) for x in row] for row in field]

r, g, b = scale(dx), scale(dy), scale(height)
img = Image.new("RGB", (SIZE, SIZE))
img.putdata([(r[j][i], g[j][i], b[j][i]) for j in range(SIZE) for i in range(SIZE)])
img.save("src/main/resources/textures/water-dudv.png", optimize=True)
print("wrote src/main/resources/textures/water-dudv.png", SIZE, "x", SIZE)
