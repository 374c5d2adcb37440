#!/usr/bin/env python3
"""Writes a classic (Playforia) .track file of our own design with every special block that the
importer plays: downhill tiles, a teleport with two exits, a magnet and a repeller, a one-way
column, bouncy and sticky blocks, water, sand, ice and diagonal wall ends (docs/classic-tracks.md).
It is the track of docs/screenshots/classic-special-blocks.png; no downloaded track is used.

usage: tools/demo-classic-track.py OUT_DIR   (then: minigolf import-tracks OUT_DIR --out IMPORTED)
"""
import os
import sys

LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
W, H = 49, 25


def element(shape, first, second):
    return ("B", shape, first, second)


def special(s, background=0):
    return ("C", s, background)


def main(out):
    grass = element(0, 0, 0)
    m = [[grass] * W for _ in range(H)]

    def fill(x0, x1, y0, y1, tile):
        for y in range(y0, y1 + 1):
            for x in range(x0, x1 + 1):
                m[y][x] = tile

    block = element(0, 16, 16)
    fill(0, 48, 0, 0, block); fill(0, 48, 24, 24, block); fill(0, 0, 0, 24, block); fill(48, 48, 0, 24, block)
    m[12][4] = special(0); m[12][44] = special(1)                          # start, hole
    fill(8, 13, 3, 8, element(0, 6, 6)); fill(8, 13, 16, 21, element(0, 4, 4))  # downhill east, north
    fill(16, 18, 10, 14, element(0, 12, 12)); fill(33, 35, 9, 15, element(0, 1, 1))  # water, sand
    fill(20, 24, 2, 5, element(0, 3, 3))                                   # ice
    m[20][15] = special(8); m[4][30] = special(9); m[20][30] = special(9)  # blue teleport start, exits
    m[6][37] = special(20); m[18][37] = special(21)                        # magnet, repeller
    fill(40, 40, 1, 23, element(0, 21, 21))                                # one-way east
    fill(26, 27, 8, 9, element(0, 18, 18)); fill(26, 27, 15, 16, element(0, 17, 17))  # bouncy, sticky
    m[7][26] = element(4, 16, 0); m[17][27] = element(6, 16, 0)
    fill(21, 21, 9, 15, block); m[8][21] = element(5, 16, 0); m[16][21] = element(7, 16, 0)
    data = "".join(t[0] + LETTERS[t[1]] + LETTERS[t[2]] + (LETTERS[t[3]] if t[0] == "B" else "")
                   for row in m for t in row)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "Demo-Special_blocks.track"), "w") as f:
        f.write("V 2\nA classic28\nN Special blocks\nC 1\nT " + data + "\nI 100,600,2,3\nS fttt14\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
