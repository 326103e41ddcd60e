#!/usr/bin/env python3
"""Writes scenes/textures/bricks.ppm: a 128 x 128 running-bond brick pattern (binary PPM, sRGB
8-bit), and next to it bricks_normal.ppm, a tangent-space normal map of the mortar grooves
((n + 1) / 2, green = +v), and bricks_height.ppm, their height (255 on a brick, 0 in the mortar) for
displacement_texture, so the textured scenes need no downloaded image. Deterministic: a fixed
seed varies the brick colours a little. Usage: python3 scenes/textures/make_bricks.py [OUT]"""
import math
import os
import random
import sys

W, H = 128, 128
BRICK_W, BRICK_H, MORTAR = 32, 16, 2
random.seed(7)
shades = {}
rows = []
for y in range(H):
    row = bytearray()
    course = y // BRICK_H
    for x in range(W):
        shifted = x + (BRICK_W // 2 if course % 2 else 0)
        brick = (course, (shifted // BRICK_W) % (W // BRICK_W))
        in_mortar = y % BRICK_H < MORTAR or shifted % BRICK_W < MORTAR
        if in_mortar:
            row += bytes((200, 195, 185))
        else:
            if brick not in shades:
                shades[brick] = random.uniform(0.8, 1.1)
            s = shades[brick]
            row += bytes(min(255, int(c * s)) for c in (160, 62, 42))
    rows.append(row)
out = sys.argv[1] if len(sys.argv) > 1 else "scenes/textures/bricks.ppm"
with open(out, "wb") as f:
    f.write(b"P6\n%d %d\n255\n" % (W, H))
    for row in rows:
        f.write(row)


def height(x, y):
    """1 on a brick, 0 in the mortar; file row y = 0 is the top (v = 1)."""
    x %= W
    y %= H
    course = y // BRICK_H
    shifted = x + (BRICK_W // 2 if course % 2 else 0)
    return 0.0 if (y % BRICK_H < MORTAR or shifted % BRICK_W < MORTAR) else 1.0


with open(os.path.join(os.path.dirname(out), "bricks_normal.ppm"), "wb") as f:
    f.write(b"P6\n%d %d\n255\n" % (W, H))
    for y in range(H):
        row = bytearray()
        for x in range(W):
            dhdu = (height(x + 1, y) - height(x - 1, y)) * 0.5
            dhdv = (height(x, y - 1) - height(x, y + 1)) * 0.5   # v grows upwards, rows downwards
            n = (-dhdu, -dhdv, 1.0)
            length = math.sqrt(sum(c * c for c in n))
            row += bytes(int(round((c / length * 0.5 + 0.5) * 255)) for c in n)
        f.write(row)


with open(os.path.join(os.path.dirname(out), "bricks_height.ppm"), "wb") as f:
    f.write(b"P6\n%d %d\n255\n" % (W, H))
    for y in range(H):
        f.write(bytes(int(255 * height(x, y)) for x in range(W) for _ in range(3)))
