"""Writing meshes: run(output=...) and Mesh.write, read back by geomesh."""

import geomesh


def test_output_writes_an_msh_file_that_geomesh_reads_back(square, write_script, tmp_path):
    written = tmp_path / "square.msh"
    mesh = geomesh.run(square, dim=2, output=written, verbosity=0)
    assert written.read_text().startswith("$MeshFormat\n4.1 0 8\n")
    merged = geomesh.run(write_script('Merge "square.msh";\n', "merge.geo"), dim=2, verbosity=0)
    # Only the elements of physical groups are saved: not the points' elements.
    saved = {name: n for name, n in mesh.summary()["elements"].items() if name != "point"}
    assert merged.summary()["elements"] == saved
    assert merged.physical_groups == mesh.physical_groups


def test_write_follows_the_file_name(square, tmp_path):
    mesh = geomesh.run(square, dim=2, verbosity=0)
    mesh.write(tmp_path / "square.vtk")
    mesh.write(str(tmp_path / "square.msh"))
    assert (tmp_path / "square.vtk").read_text().startswith("# vtk DataFile")
    assert (tmp_path / "square.msh").read_text().startswith("$MeshFormat")


def test_no_output_writes_nothing(square, tmp_path):
    geomesh.run(square, dim=2, verbosity=0)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["square.geo"]


def test_dim_0_output_is_the_unrolled_geometry(square, tmp_path):
    unrolled = tmp_path / "square.geo_unrolled"
    geomesh.run(square, dim=0, output=unrolled, verbosity=0)
    assert "Plane Surface(1)" in unrolled.read_text()
