#!/usr/bin/env python3
"""Writes scenes/textures/bricks.ppm: a 128 x 128 running-bond brick pattern (binary PPM, sRGB
8-bit), so the textured scene needs no downloaded image. Deterministic: a fixed seed varies the
brick colours a little. Usage: python3 scenes/textures/make_bricks.py [OUT]"""
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
