"""geomesh.run on a square: the mesh as NumPy arrays, and the same figures as the summary."""

import gc

import numpy as np
import pytest

import geomesh


@pytest.fixture
def mesh(square):
    return geomesh.run(square, dim=2, verbosity=0)


def test_nodes_are_an_n_by_3_float_array(mesh):
    nodes = mesh.nodes
    assert nodes.shape == (mesh.summary()["nodes"], 3)
    assert nodes.dtype == np.float64
    assert np.all(nodes[:, 2] == 0)
    assert nodes[:, :2].min() == 0 and nodes[:, :2].max() == 1


def test_nodes_view_the_mesh_without_copy(mesh):
    first, second = mesh.nodes, mesh.nodes
    assert np.shares_memory(first, second)
    assert first.base is not None
    assert not first.flags.writeable
    with pytest.raises(ValueError):
        first[0, 0] = 1.0


def test_a_node_array_keeps_its_mesh_alive(square):
    nodes = geomesh.run(square, dim=2, verbosity=0).nodes
    copy = nodes.copy()
    gc.collect()
    assert np.array_equal(nodes, copy)


def test_node_tags_count_from_one(mesh):
    tags = mesh.node_tags
    assert tags.dtype == np.int64
    assert np.array_equal(tags, np.arange(1, len(mesh.nodes) + 1))


def test_element_counts_are_the_summary_counts(mesh):
    counts = {name: len(array) for name, array in mesh.elements().items()}
    assert counts == mesh.summary()["elements"]
    assert set(counts) >= {"triangle", "line"}


def test_elements_index_the_nodes_from_zero(mesh):
    for name, array in mesh.elements().items():
        assert array.ndim == 2
        assert array.min() >= 0 and array.max() < len(mesh.nodes)
    assert mesh.elements()["triangle"].shape[1] == 3
    assert mesh.elements(dim=1)["line"].shape[1] == 2
    assert set(mesh.elements(dim=2)) == {"triangle"}


def test_area_from_numpy_is_the_summary_area(mesh):
    xyz = mesh.nodes[mesh.elements()["triangle"]]
    area = 0.5 * np.linalg.norm(np.cross(xyz[:, 1] - xyz[:, 0], xyz[:, 2] - xyz[:, 0]), axis=1).sum()
    assert area == pytest.approx(mesh.summary()["area"], rel=1e-12)
    assert area == pytest.approx(1.0, rel=1e-12)


def test_length_from_numpy_is_the_summary_length(mesh):
    xyz = mesh.nodes[mesh.elements(dim=1)["line"]]
    length = np.linalg.norm(xyz[:, 1] - xyz[:, 0], axis=1).sum()
    assert length == pytest.approx(mesh.summary()["length"], rel=1e-12)
    assert length == pytest.approx(4.0, rel=1e-12)


def test_entities_and_physical_groups(mesh):
    assert mesh.entities == [(0, 1), (0, 2), (0, 3), (0, 4), (1, 1), (1, 2), (1, 3), (1, 4), (2, 1)]
    assert mesh.physical_groups == [(1, 10, "walls", [1, 2, 3, 4]), (2, 20, "plate", [1])]


def test_elements_of_one_entity_view_the_mesh(mesh):
    triangles = mesh.elements_of(2, 1)["triangle"]
    assert np.array_equal(triangles, mesh.elements(dim=2)["triangle"])
    assert not triangles.flags.writeable
    assert np.shares_memory(triangles, mesh.elements_of(2, 1)["triangle"])
    lines = sum(len(mesh.elements_of(1, tag)["line"]) for tag in range(1, 5))
    assert lines == mesh.summary()["elements"]["line"]
    with pytest.raises(ValueError):
        mesh.elements_of(2, 99)


def test_summary_figures(mesh):
    summary = mesh.summary()
    assert set(summary) == {"nodes", "elements", "length", "area", "volume", "quality_min",
                            "quality_mean"}
    assert summary["volume"] == 0
    assert 0 < summary["quality_min"] <= summary["quality_mean"] <= 1


def test_numbers_set_the_script_parameters(square, mesh):
    finer = geomesh.run(square, dim=2, numbers={"lc": 0.05}, verbosity=0)
    assert len(finer.nodes) > 4 * len(mesh.nodes)


def test_strings_set_the_script_parameters(write_script):
    script = write_script('DefineConstant[ name = {"a"} ];\nPoint(1) = {0, 0, 0};\n'
                          'Physical Point(name) = {1};\n')
    mesh = geomesh.run(script, dim=0, strings={"name": "corner"}, verbosity=0)
    assert mesh.physical_groups == [(0, 1, "corner", [1])]


def test_dim_0_evaluates_the_geometry_only(square):
    mesh = geomesh.run(square, dim=0, verbosity=0)
    assert mesh.nodes.shape == (0, 3)
    assert mesh.elements() == {}
    assert (2, 1) in mesh.entities


def test_a_3d_tutorial_volume_is_the_summary_volume(root):
    mesh = geomesh.run(root / "tutorials" / "t5.geo", dim=3, verbosity=0)
    tets = mesh.nodes[mesh.elements(dim=3)["tetrahedron"]]
    edges = tets[:, 1:] - tets[:, :1]
    volume = np.abs(np.linalg.det(edges)).sum() / 6
    assert volume == pytest.approx(mesh.summary()["volume"], rel=1e-9)
    assert volume == pytest.approx(10.2, rel=1e-9)


def test_repr_and_version(mesh):
    assert repr(mesh).startswith("<geomesh.Mesh: ")
    assert geomesh.__version__.count(".") == 2
