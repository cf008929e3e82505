#!/usr/bin/env python3
"""geomesh from Python: tutorial t1's plate meshed, then measured with NumPy.

geomesh.run runs a .geo script as the command does (here `geomesh t1.geo -2`, writing no
file) and returns the mesh. Its nodes are an (N, 3) array that views the mesh's own memory;
elements() gives, per element type, the node indices of each element (from 0), so that
`nodes[triangles]` holds every triangle's three corners.

Run from the repository's root, after scripts/setup.sh has built the module:
    PYTHONPATH=build/python python3 tutorials/python_first_mesh.py
"""
import pathlib

import numpy as np

import geomesh

script = pathlib.Path(__file__).with_name("t1.geo")
mesh = geomesh.run(script, dim=2, verbosity=1)  # 1: errors only; the script's Printf shows

nodes = mesh.nodes
corners = nodes[mesh.elements()["triangle"]]  # (triangles, 3 corners, xyz)
sides = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
area = 0.5 * np.linalg.norm(sides, axis=1).sum()

print(f"{len(nodes)} nodes, {len(corners)} triangles")
print(f"area from NumPy: {area:.6f}; geomesh's summary: {mesh.summary()['area']:.6f}")
for dim, tag, name, entities in mesh.physical_groups:
    print(f"physical group {name!r} (dimension {dim}, tag {tag}): entities {entities}")

# write() saves in the format the file name says; a .png (or .svg) is a picture of the whole
# mesh, drawn without any display: here, into the current directory.
mesh.write("python_first_mesh.png")
