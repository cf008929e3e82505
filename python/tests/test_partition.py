"""Partitions from Python: model.mesh.partition, the partition entities and their queries."""

import pytest

import geomesh


def two_squares():
    geomesh.model.occ.addRectangle(0, 0, 0, 1, 1, 1)
    geomesh.model.occ.addRectangle(1, 0, 0, 1, 1, 2)
    geomesh.model.occ.fragment([(2, 1)], [(2, 2)])
    geomesh.model.occ.synchronize()
    geomesh.model.mesh.setSize(geomesh.model.getEntities(0), 0.1)
    geomesh.model.mesh.generate(2)


def test_partition_entities_cover_the_model(api_session):
    two_squares()
    model = geomesh.model
    before = model.getEntities()
    assert model.getNumberOfPartitions() == 0
    assert model.getType(2, 1) == "Plane"
    assert model.getType(1, 1) == "Line"
    geomesh.option.setNumber("Mesh.PartitionCreateTopology", 1)
    model.mesh.partition(3)
    assert model.getNumberOfPartitions() == 3
    after = model.getEntities()
    assert after[: len(before)] == before
    pieces = [e for e in after if model.getPartitions(*e)]
    surfaces = [e for e in pieces if e[0] == 2]
    assert surfaces and all(model.getType(*e) == "Partition surface" for e in surfaces)
    assert {p for e in surfaces for p in model.getPartitions(*e)} == {1, 2, 3}
    assert {model.getParent(*e) for e in surfaces} == {(2, 1), (2, 2)}
    # Each piece of surface is bounded by pieces of curves.
    for e in surfaces:
        boundary = model.getBoundary([e])
        assert boundary and all(b[0] == 1 for b in boundary)
    assert model.getParent(2, 1) == (-1, -1)
    assert model.getPartitions(2, 1) == []

    model.mesh.unpartition()
    assert model.getNumberOfPartitions() == 0
    assert model.getEntities() == before


def test_partition_arguments_are_checked(api_session):
    two_squares()
    with pytest.raises(ValueError, match="numPart"):
        geomesh.model.mesh.partition(0)
    with pytest.raises(ValueError, match="elementTags"):
        geomesh.model.mesh.partition(2, [1, 2], [1, 2])
    with pytest.raises(geomesh.Error):
        geomesh.model.getType(2, 99)
