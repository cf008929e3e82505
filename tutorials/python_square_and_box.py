"""Two parts built from Python instead of a .geo script.

A plate with a round hole, drawn point by point with the built-in kernel (geomesh.model.geo),
meshed in triangles; then a block with a bore through it, made from a box and a cylinder with
the OpenCASCADE kernel (geomesh.model.occ), meshed in tetrahedra. For each, the measure of the
mesh, summed with NumPy from getNodes and getElements, beside the exact one.

    PYTHONPATH=build/python python3 tutorials/python_square_and_box.py
"""

import math

import numpy as np

import geomesh

TRIANGLE, TETRAHEDRON = 2, 4  # MSH element type codes


def mesh_arrays(code, dim):
    """Node coordinates (N, 3) and the elements of one type as 0-based node indices."""
    _, coords, _ = geomesh.model.mesh.getNodes()
    xyz = coords.reshape(-1, 3)
    types, _, node_tags = geomesh.model.mesh.getElements(dim)
    nodes = node_tags[types.index(code)]
    width = {TRIANGLE: 3, TETRAHEDRON: 4}[code]
    return xyz, nodes.reshape(-1, width) - 1


def plate_with_hole(width=2.0, height=1.0, radius=0.25, size=0.05):
    geo = geomesh.model.geo
    corners = [(0, 0), (width, 0), (width, height), (0, height)]
    outline = [geo.addPoint(x, y, 0, size) for x, y in corners]
    sides = [geo.addLine(outline[k], outline[(k + 1) % 4]) for k in range(4)]
    # The hole: four quarter arcs about its centre (an arc spans less than a half turn).
    cx, cy = width / 2, height / 2
    centre = geo.addPoint(cx, cy, 0, size)
    rim = [geo.addPoint(cx + radius * math.cos(a), cy + radius * math.sin(a), 0, size / 2)
           for a in (0, math.pi / 2, math.pi, 3 * math.pi / 2)]
    arcs = [geo.addCircleArc(rim[k], centre, rim[(k + 1) % 4]) for k in range(4)]
    plate = geo.addPlaneSurface([geo.addCurveLoop(sides), geo.addCurveLoop(arcs)])
    geo.synchronize()
    geomesh.model.addPhysicalGroup(1, arcs, name="hole")
    geomesh.model.addPhysicalGroup(2, [plate], name="plate")
    geomesh.model.mesh.generate(2)

    xyz, triangles = mesh_arrays(TRIANGLE, 2)
    corner = xyz[triangles]
    cross = np.cross(corner[:, 1] - corner[:, 0], corner[:, 2] - corner[:, 0])
    area = 0.5 * np.linalg.norm(cross, axis=1).sum()
    exact = width * height - math.pi * radius**2
    print(f"plate: {len(xyz)} nodes, {len(triangles)} triangles")
    print(f"plate area: {area:.4f} (exact {exact:.4f})")


def block_with_bore(radius=0.2, size=0.08):
    occ = geomesh.model.occ
    block = occ.addBox(0, 0, 0, 1, 1, 0.5)
    bore = occ.addCylinder(0.5, 0.5, -0.1, 0, 0, 0.7, radius)
    result, _ = occ.cut([(3, block)], [(3, bore)])
    occ.synchronize()
    geomesh.model.addPhysicalGroup(3, [tag for dim, tag in result], name="block")
    geomesh.option.setNumber("Mesh.MeshSizeMax", size)
    geomesh.model.mesh.generate(3)

    xyz, tets = mesh_arrays(TETRAHEDRON, 3)
    corner = xyz[tets]
    edges = corner[:, 1:] - corner[:, :1]
    volume = np.abs(np.linalg.det(edges)).sum() / 6
    exact = 0.5 * (1 - math.pi * radius**2)
    print(f"block: {len(xyz)} nodes, {len(tets)} tetrahedra")
    print(f"block volume: {volume:.4f} (exact {exact:.4f})")
    # A picture of the block's mesh (the format follows the name: .png, .svg, .msh, ...).
    geomesh.write("python_square_and_box.png")


geomesh.initialize()
geomesh.option.setNumber("General.Verbosity", 2)  # warnings and errors only
plate_with_hole()
geomesh.clear()  # a new, empty model; the options stay
block_with_bore()
geomesh.finalize()
