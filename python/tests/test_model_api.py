"""Models built from Python with geomesh.model.geo / occ, meshed and read back."""

import math

import numpy as np
import pytest

import geomesh
from conftest import SQUARE

geo = geomesh.model.geo
occ = geomesh.model.occ


# Each test starts from an empty model with default options, and leaves none behind.
pytestmark = pytest.mark.usefixtures("api_session")


def unit_square(size=0.1):
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
    points = [geo.addPoint(x, y, 0, size) for x, y in corners]
    lines = [geo.addLine(points[k], points[(k + 1) % 4]) for k in range(4)]
    loop = geo.addCurveLoop(lines)
    surface = geo.addPlaneSurface([loop])
    geo.synchronize()
    return lines, surface


def coordinates():
    tags, coords, parametric = geomesh.model.mesh.getNodes()
    assert tags.dtype == np.int64 and coords.dtype == np.float64
    assert parametric.size == 0 and coords.shape == (3 * len(tags),)
    assert np.array_equal(tags, np.arange(1, len(tags) + 1))
    return coords.reshape(-1, 3)


def elements_of_type(code, dim=-1):
    types, element_tags, node_tags = geomesh.model.mesh.getElements(dim)
    assert len(types) == len(element_tags) == len(node_tags)
    if code not in types:
        return np.zeros((0, 0), dtype=np.int64)
    k = types.index(code)
    nodes = node_tags[k]
    return nodes.reshape(len(element_tags[k]), -1) - 1  # 0-based indices into coordinates()


def triangle_area(xyz, triangles):
    corners = xyz[triangles]
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    return 0.5 * np.linalg.norm(cross, axis=1).sum()


def hexahedron_volume(xyz, hexahedra):
    # Each hexahedron of an extruded square is a box: the product of its edge lengths.
    corners = xyz[hexahedra]
    edge = lambda a, b: np.linalg.norm(corners[:, b] - corners[:, a], axis=1)  # noqa: E731
    return (edge(0, 1) * edge(0, 3) * edge(0, 4)).sum()


def test_built_in_square_matches_its_script(write_script):
    lines, surface = unit_square()
    assert len(set(lines)) == 4 and surface == 1
    group = geomesh.model.addPhysicalGroup(2, [surface], name="plate")
    assert group == 1
    assert (2, 1) in geomesh.model.getEntities() and geomesh.model.getEntities(2) == [(2, 1)]
    geomesh.model.mesh.generate(2)
    xyz = coordinates()
    triangles = elements_of_type(2, dim=2)
    assert abs(triangle_area(xyz, triangles) - 1) < 1e-12
    types, _, _ = geomesh.model.mesh.getElements(1)
    assert types == [1]
    # The same square as a script (the shared one, at this size).
    scripted = geomesh.run(write_script(SQUARE, "square.geo"), dim=2, numbers={"lc": 0.1},
                           verbosity=2)
    assert abs(len(xyz) - len(scripted.nodes)) <= 0.2 * len(scripted.nodes)


def test_element_tags_number_the_whole_mesh():
    unit_square()
    geomesh.model.mesh.generate(2)
    _, all_tags, _ = geomesh.model.mesh.getElements()
    joined = np.concatenate(all_tags)
    assert np.array_equal(np.sort(joined), np.arange(1, len(joined) + 1))
    _, surface_tags, _ = geomesh.model.mesh.getElements(2, 1)
    assert set(surface_tags[0]) <= set(joined)


def test_extruded_square_gives_hexahedra():
    lines, surface = unit_square()
    for line in lines:
        geo.mesh.setTransfiniteCurve(line, 6)
    geo.mesh.setTransfiniteSurface(surface)
    geo.mesh.setRecombine(2, surface)
    made = geo.extrude([(2, surface)], 0, 0, 1, numElements=[5], recombine=True)
    assert made[1][0] == 3 and len(made) == 6  # top, volume, four sides
    geo.synchronize()
    geomesh.model.mesh.generate(3)
    types, element_tags, _ = geomesh.model.mesh.getElements(3)
    assert types == [5] and len(element_tags[0]) == 5 * 5 * 5
    assert abs(hexahedron_volume(coordinates(), elements_of_type(5, dim=3)) - 1) < 1e-12


def test_occ_box_minus_cylinder():
    geomesh.option.setNumber("Mesh.MeshSizeMax", 0.1)
    box = occ.addBox(0, 0, 0, 1, 1, 1)
    cylinder = occ.addCylinder(0.5, 0.5, 0, 0, 0, 1, 0.2)
    out, out_map = occ.cut([(3, box)], [(3, cylinder)])
    assert out == [(3, box)] and len(out_map) == 2
    occ.synchronize()
    geomesh.model.mesh.generate(3)
    volume = geomesh.current_mesh().summary()["volume"]
    assert volume == pytest.approx(1 - math.pi * 0.2**2, rel=0.01)


def test_occ_fragment_maps_every_input():
    a = occ.addBox(0, 0, 0, 1, 1, 1)
    b = occ.addBox(0.5, 0, 0, 1, 1, 1)
    c = occ.addSphere(3, 0, 0, 0.5)
    out, out_map = occ.fragment([(3, a), (3, b)], [(3, c)])
    assert len(out) == 4 and len(out_map) == 3
    assert len(out_map[0]) == 2 and len(out_map[1]) == 2 and len(out_map[2]) == 1
    assert set(out_map[0]) & set(out_map[1])  # the common part belongs to both
    occ.synchronize()
    assert len(geomesh.model.getEntities(3)) == 4


def test_occ_planar_shapes():
    geomesh.option.setNumber("Mesh.MeshSizeMax", 0.05)
    rectangle = occ.addRectangle(0, 0, 0, 2, 1)
    disk = occ.addDisk(1, 0.5, 0, 0.3, 0.3)
    out, _ = occ.cut([(2, rectangle)], [(2, disk)])
    assert len(out) == 1
    circle = occ.addCircle(5, 0, 0, 1)
    occ.synchronize()
    assert (1, circle) in geomesh.model.getEntities(1)
    geomesh.model.mesh.generate(2)
    area = geomesh.current_mesh().summary()["area"]
    assert area == pytest.approx(2 - math.pi * 0.09, rel=0.01)


def test_mesh_size_option_coarsens():
    counts = []
    for size in (0.1, 0.2):
        geomesh.clear()
        geomesh.option.setNumber("Mesh.MeshSizeMax", size)
        assert geomesh.option.getNumber("Mesh.MeshSizeMax") == size
        unit_square(size=1)
        geomesh.model.mesh.generate(2)
        counts.append(len(coordinates()))
    assert counts[1] < counts[0]


def test_set_size_at_points():
    unit_square(size=1)
    geomesh.model.mesh.setSize(geomesh.model.getEntities(0), 0.05)
    geomesh.model.mesh.generate(2)
    fine = len(coordinates())
    geomesh.model.mesh.setSize(geomesh.model.getEntities(0), 0.2)
    geomesh.model.mesh.generate(2)
    assert len(coordinates()) < fine


def test_string_options():
    geomesh.option.setString("General.DefaultFileName", "plate.geo")
    assert geomesh.option.getString("General.DefaultFileName") == "plate.geo"
    with pytest.raises(geomesh.Error):
        geomesh.option.getNumber("Mesh.NoSuchOption")


def test_geometry_errors_leave_the_api_usable():
    p = geo.addPoint(0, 0, 0)
    with pytest.raises(geomesh.Error, match="99"):
        geo.addLine(p, 99)
    q = geo.addPoint(1, 0, 0)
    assert geo.addLine(p, q) >= 1
    geo.synchronize()
    assert len(geomesh.model.getEntities(1)) == 1
    with pytest.raises(TypeError):
        geo.addPoint("x", 0, 0)


def test_meshing_failure_raises_mesh_error():
    # A bow-tie: the second and fourth lines cross, which only the mesher finds out.
    corners = [(0, 0), (3, 0), (0, 1), (1, 2)]
    points = [geo.addPoint(x, y, 0, 0.1) for x, y in corners]
    lines = [geo.addLine(points[k], points[(k + 1) % 4]) for k in range(4)]
    geo.addPlaneSurface([geo.addCurveLoop(lines)])
    geo.synchronize()
    with pytest.raises(geomesh.MeshError):
        geomesh.model.mesh.generate(2)
    geomesh.clear()
    unit_square()
    geomesh.model.mesh.generate(2)  # the session meshes again after the failure
    assert len(coordinates()) > 100


def test_finalize_then_initialize_is_empty():
    unit_square()
    assert geomesh.model.getEntities()
    geomesh.finalize()
    assert not geomesh.isInitialized()
    geomesh.initialize()
    assert geomesh.model.getEntities() == []
    assert geo.addPoint(0, 0, 0) == 1


def test_calls_before_initialize_start_a_session():
    geomesh.finalize()
    assert geo.addPoint(0, 0, 0) == 1
    assert geomesh.isInitialized()


def test_written_mesh_merges_back(tmp_path, write_script):
    unit_square()
    geomesh.model.addPhysicalGroup(2, [1], name="plate")
    geomesh.model.mesh.generate(2)
    nodes = len(coordinates())
    triangles = len(elements_of_type(2))
    path = tmp_path / "square.msh"
    geomesh.write(path)
    merged = geomesh.run(write_script('Merge "square.msh";\n', "merge.geo"), dim=2, verbosity=2)
    assert len(merged.nodes) == nodes
    assert len(merged.elements()["triangle"]) == triangles
    geomesh.finalize()
    geomesh.merge(str(path))
    assert len(coordinates()) == nodes


def test_unrolled_geometry_runs_as_a_script(tmp_path):
    unit_square()
    path = tmp_path / "square.geo_unrolled"
    geomesh.write(path)
    text = path.read_text()
    assert "Plane Surface(1)" in text
    script = tmp_path / "again.geo"
    script.write_text(text)
    assert geomesh.run(script, dim=2, verbosity=2).summary()["area"] == pytest.approx(1)


def test_current_mesh_views_stay_valid_after_remeshing():
    unit_square()
    geomesh.model.mesh.generate(2)
    mesh = geomesh.current_mesh()
    before = mesh.nodes
    copy = np.array(before)
    geomesh.option.setNumber("Mesh.MeshSizeMax", 0.05)
    geomesh.model.mesh.generate(2)
    assert np.array_equal(before, copy)  # the old view still reads the mesh it viewed
    assert len(mesh.nodes) > len(before)  # the object reads the session's mesh as it is now
    assert mesh.summary()["area"] == pytest.approx(1)


def test_model_name():
    geomesh.model.add("plate")
    assert geomesh.model.getCurrent() == "plate"
