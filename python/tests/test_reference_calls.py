"""Calls of the reference's Python API beyond building and meshing: transformations, size
fields, embedding, periodicity, discrete surfaces, model queries, the logger, and the display
calls that have nothing to display."""

import math

import numpy as np
import pytest

import geomesh

geo = geomesh.model.geo
occ = geomesh.model.occ
mesh = geomesh.model.mesh


@pytest.fixture(autouse=True)
def fresh_session():
    geomesh.finalize()
    geomesh.initialize(["geomesh", "-nopopup"])
    geomesh.option.setNumber("General.Verbosity", 2)
    yield
    geomesh.finalize()


def square(size=0.2, x=0.0):
    points = [geo.addPoint(x + a, b, 0, size) for a, b in [(0, 0), (1, 0), (1, 1), (0, 1)]]
    lines = [geo.addLine(points[k], points[(k + 1) % 4]) for k in range(4)]
    return geo.addPlaneSurface([geo.addCurveLoop(lines)])


def node_count():
    return len(mesh.getNodes()[0])


def test_translate_rotate_copy_and_remove_points():
    p = geo.addPoint(1, 0, 0)
    geo.translate([(0, p)], 0, 0, 2)
    copies = geo.copy([(0, p)])
    assert len(copies) == 1 and copies[0][0] == 0 and copies[0][1] != p
    geo.rotate(copies, 0, 0, 0, 0, 0, 1, math.pi / 2)
    geo.synchronize()
    assert geomesh.model.getValue(0, p, []) == pytest.approx([1, 0, 2])
    assert geomesh.model.getValue(0, copies[0][1], []) == pytest.approx([0, 1, 2], abs=1e-12)
    geo.remove([(0, p)])
    geo.synchronize()
    assert geomesh.model.getEntities(0) == copies


def test_copied_surface_is_meshed_beside_the_original():
    s = square()
    moved = geo.copy([(2, s)])
    geo.translate(moved, 2, 0, 0)
    geo.synchronize()
    assert len(geomesh.model.getEntities(2)) == 2
    mesh.generate(2)
    xyz = mesh.getNodes()[1].reshape(-1, 3)
    assert xyz[:, 0].max() == pytest.approx(3)


def test_recursive_remove_takes_the_boundary():
    s = square()
    geo.remove([(2, s)], recursive=True)
    geo.synchronize()
    assert geomesh.model.getEntities() == []


def test_revolve_makes_a_volume():
    s = square(x=1.0)
    out = geo.revolve([(2, s)], 0, 0, 0, 0, 1, 0, math.pi / 2)
    geo.synchronize()
    assert (3, out[1][1]) in geomesh.model.getEntities(3)


def test_background_field_sets_the_size():
    def nodes_with(formula):
        geomesh.clear()
        square(size=1.0)
        geo.synchronize()
        field = mesh.field.add("MathEval")
        mesh.field.setString(field, "F", formula)
        mesh.field.setAsBackgroundMesh(field)
        mesh.generate(2)
        return node_count()

    coarse, fine = nodes_with("0.2"), nodes_with("0.05")
    assert fine > 8 * coarse


def test_field_numbers_and_tags():
    square(size=1.0)
    geo.synchronize()
    distance = mesh.field.add("Distance")
    threshold = mesh.field.add("Threshold")
    assert (distance, threshold) == (1, 2)
    mesh.field.setNumbers(distance, "CurvesList", [1])
    mesh.field.setNumber(threshold, "InField", distance)
    for option, value in [("SizeMin", 0.02), ("SizeMax", 0.5), ("DistMin", 0.05), ("DistMax", 0.5)]:
        mesh.field.setNumber(threshold, option, value)
    mesh.field.setAsBackgroundMesh(threshold)
    assert mesh.field.getType(threshold) == "Threshold"
    mesh.generate(2)
    xyz = mesh.getNodes()[1].reshape(-1, 3)
    # Fine along curve 1 (y = 0), coarse away from it.
    assert (xyz[:, 1] < 0.1).sum() > 3 * (xyz[:, 1] > 0.9).sum()
    with pytest.raises(geomesh.Error):
        mesh.field.setNumber(99, "SizeMin", 1)


def test_embedded_point_is_a_node():
    s = square()
    p = geo.addPoint(0.37, 0.41, 0, 0.2)
    geo.synchronize()
    mesh.embed(0, [p], 2, s)
    mesh.generate(2)
    node = mesh.getNodes(0, p)[0]
    assert len(node) == 1
    triangles = mesh.getElements(2, s)[2][0]
    assert node[0] in triangles  # a vertex of the surface's triangles, not a lone node


def plane_x(x, dim, eps=1e-6):
    """The entities of dimension dim in the plane x of the unit box."""
    return geomesh.model.getEntitiesInBoundingBox(
        x - eps, -eps, -eps, x + eps, 1 + eps, 1 + eps, dim)


def test_periodic_faces_have_matching_nodes():
    occ.addBox(0, 0, 0, 1, 1, 1)
    occ.synchronize()
    left, right = plane_x(0, 2), plane_x(1, 2)
    assert len(left) == 1 and len(right) == 1
    geomesh.model.mesh.setSize(geomesh.model.getEntities(0), 0.4)
    # Finer on the right: without the periodicity its mesh would differ from the left one's.
    geomesh.model.mesh.setSize(plane_x(1, 0), 0.1)
    shift = [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    mesh.setPeriodic(2, [right[0][1]], [left[0][1]], shift)
    mesh.generate(2)
    a = mesh.getNodes(2, left[0][1], includeBoundary=True)[1].reshape(-1, 3)
    b = mesh.getNodes(2, right[0][1], includeBoundary=True)[1].reshape(-1, 3)
    assert len(a) == len(b)
    key = lambda p: (round(p[1], 9), round(p[2], 9))
    assert sorted(map(key, a)) == sorted(map(key, b))


def test_compound_and_algorithm_calls_mesh():
    s1 = square()
    s2 = square(x=1.0)
    geo.synchronize()
    mesh.setCompound(2, [s1, s2])
    mesh.setAlgorithm(2, s1, 1)
    mesh.generate(2)
    assert node_count() > 0


def test_classify_and_create_geometry_on_a_written_stl(tmp_path):
    occ.addBox(0, 0, 0, 1, 1, 1)
    occ.synchronize()
    geomesh.model.mesh.setSize(geomesh.model.getEntities(0), 0.25)
    mesh.generate(2)
    stl = tmp_path / "box.stl"
    geomesh.write(stl)
    geomesh.clear()
    geomesh.merge(stl)
    mesh.classifySurfaces(40 * math.pi / 180, True, False, math.pi)
    assert len(geomesh.model.getEntities(2)) == 6
    mesh.createGeometry()
    surfaces = [tag for _, tag in geomesh.model.getEntities(2)]
    geo.addVolume([geo.addSurfaceLoop(surfaces)])
    geo.synchronize()
    mesh.generate(3)
    types = mesh.getElements(3)[0]
    assert 4 in types  # tetrahedra


def test_boundary_box_and_entities_in_box():
    occ.addBox(0, 0, 0, 1, 2, 3)
    occ.synchronize()
    faces = geomesh.model.getBoundary([(3, 1)])
    assert len(faces) == 6 and all(d == 2 for d, _ in faces)
    points = geomesh.model.getBoundary([(3, 1)], False, False, True)
    assert len(points) == 8 and all(d == 0 and t > 0 for d, t in points)
    # Two faces share one edge: combined, it cancels out.
    two = [(2, abs(t)) for _, t in faces[:2]]
    separate = geomesh.model.getBoundary(two, combined=False)
    combined = geomesh.model.getBoundary(two)
    assert len(separate) == 8 and len(combined) in (6, 8)
    assert geomesh.model.getBoundingBox(3, 1) == pytest.approx((0, 0, 0, 1, 2, 3), abs=1e-6)
    assert geomesh.model.getBoundingBox(-1, -1) == pytest.approx((0, 0, 0, 1, 2, 3), abs=1e-6)
    eps = 1e-6
    corner = geomesh.model.getEntitiesInBoundingBox(-eps, -eps, -eps, eps, eps, eps, 0)
    assert len(corner) == 1
    assert geomesh.model.getValue(0, corner[0][1], []) == pytest.approx([0, 0, 0])
    assert len(geomesh.model.getEntitiesInBoundingBox(-1, -1, -1, 2, 3, 4)) == 8 + 12 + 6 + 1
    assert occ.getBoundingBox(3, 1) == pytest.approx((0, 0, 0, 1, 2, 3), abs=1e-6)
    assert len(occ.getEntities(2)) == 6


def test_closest_entity_and_remove_entities():
    occ.addBox(0, 0, 0, 1, 1, 1)
    occ.addBox(3, 0, 0, 1, 1, 1)
    occ.synchronize()
    closest = occ.getClosestEntities(3.2, 0.5, 0.5, geomesh.model.getEntities(3), 1)[0]
    assert closest == [(3, 2)]
    geomesh.model.removeEntities([(3, 1)], recursive=True)
    assert geomesh.model.getEntities(3) == [(3, 2)]
    assert len(geomesh.model.getEntities(2)) == 6


def test_logger_records_messages():
    geomesh.option.setNumber("General.Verbosity", 5)
    geomesh.logger.start()
    square()
    geo.synchronize()
    mesh.generate(1)
    lines = geomesh.logger.get()
    assert any(line.startswith("Info: ") for line in lines)
    geomesh.logger.stop()
    assert geomesh.logger.get() == []


def test_display_calls_do_nothing():
    geomesh.option.setNumber("General.Verbosity", 5)
    assert geomesh.fltk.isAvailable() == 0
    geomesh.logger.start()
    geomesh.fltk.initialize()
    geomesh.fltk.run()
    geomesh.fltk.wait()
    geomesh.graphics.draw()
    assert any("no graphical interface" in line for line in geomesh.logger.get())
    s = square()
    geo.synchronize()
    geomesh.model.setVisibility([(2, s)], False)
    geomesh.model.setColor([(2, s)], 255, 0, 0)
    geomesh.option.setColor("Geometry.Color.Points", 10, 20, 30)
    assert geomesh.option.getColor("Geometry.Color.Points") == (10, 20, 30, 255)


def test_onelab_parameters_read_back():
    geomesh.onelab.set('[{"type": "number", "name": "P/angle", "values": [40]},'
                       ' {"type": "string", "name": "P/mode", "values": ["fine"]}]')
    assert geomesh.onelab.getNumber("P/angle") == [40]
    assert geomesh.onelab.getString("P/mode") == ["fine"]
    geomesh.onelab.setNumber("P/angle", [50])
    assert geomesh.onelab.getNumber("P/angle") == [50]
    assert geomesh.onelab.getNumber("P/none") == []


def test_unsupported_calls_warn_once():
    geomesh.option.setNumber("General.Verbosity", 5)
    geomesh.logger.start()
    mesh.setSizeCallback(lambda dim, tag, x, y, z, lc: lc)
    mesh.setSizeCallback(lambda dim, tag, x, y, z, lc: lc)
    warnings = [line for line in geomesh.logger.get() if line.startswith("Warning: ")]
    assert len(warnings) == 1 and "setSizeCallback" in warnings[0]
