#!/usr/bin/env python3
"""Writes t24_scan.stl, the input of tutorial t24: a sphere of radius 2 as a scanner might
give it, 2000 triangles whose vertices lie up to 1% off the sphere (a fixed seed, so the file
is the same every time).

The triangles are those of an icosahedron whose faces are each cut into 10 x 10, pushed out
onto the sphere. Run:  python3 t24_scan.py
"""
import math
import random
import struct

RADIUS, FREQUENCY, NOISE = 2.0, 10, 0.01

golden = (1 + math.sqrt(5)) / 2
corners = [(-1, golden, 0), (1, golden, 0), (-1, -golden, 0), (1, -golden, 0),
           (0, -1, golden), (0, 1, golden), (0, -1, -golden), (0, 1, -golden),
           (golden, 0, -1), (golden, 0, 1), (-golden, 0, -1), (-golden, 0, 1)]
faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

rng = random.Random(24)
points = {}  # a grid point, named by its weights on the corners (shared by neighbouring faces)


def point(face, i, j):
    weights = {}
    for corner, w in zip(face, (FREQUENCY - i - j, i, j)):
        if w > 0:
            weights[corner] = w
    key = tuple(sorted(weights.items()))
    if key not in points:
        x = [sum(w * corners[c][k] for c, w in key) for k in range(3)]
        scale = RADIUS * (1 + NOISE * rng.uniform(-1, 1)) / math.sqrt(sum(v * v for v in x))
        # Rounded to single precision once, so that every facet has the same coordinates.
        points[key] = struct.unpack("<3f", struct.pack("<3f", *(v * scale for v in x)))
    return points[key]


triangles = []
for face in faces:
    for i in range(FREQUENCY):
        for j in range(FREQUENCY - i):
            triangles.append((point(face, i, j), point(face, i + 1, j), point(face, i, j + 1)))
            if i + j + 1 < FREQUENCY:
                triangles.append((point(face, i + 1, j), point(face, i + 1, j + 1),
                                  point(face, i, j + 1)))


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n)) or 1
    return [x / length for x in n]


with open("t24_scan.stl", "wb") as out:
    out.write(b"geomesh tutorial 24: a noisy scan of a sphere of radius 2".ljust(80, b" "))
    out.write(struct.pack("<I", len(triangles)))
    for a, b, c in triangles:
        out.write(struct.pack("<12fH", *normal(a, b, c), *a, *b, *c, 0))
