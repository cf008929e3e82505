"""Errors: located script errors, meshing failures, wrong arguments; the module stays usable."""

import pytest

import geomesh


def test_a_syntax_error_raises_script_error_with_its_place(write_script, square):
    script = write_script("a = 1;\nb = (a + ;\n", "broken.geo")
    with pytest.raises(geomesh.ScriptError) as caught:
        geomesh.run(script, dim=2, verbosity=0)
    error = caught.value
    assert (error.line, error.column) == (2, 10)
    assert error.file.endswith("broken.geo")
    message = str(error)
    assert message.startswith(f"{error.file}:2:10: error:")
    assert "b = (a + ;" in message and "^" in message  # the source line and the caret
    assert isinstance(error, geomesh.Error) and isinstance(error, Exception)
    assert len(geomesh.run(square, dim=2, verbosity=0).nodes) > 0


def test_an_evaluation_error_is_located_too(write_script):
    script = write_script("Point(1) = {0, 0, 0};\nLine(1) = {1, 7};\n")
    with pytest.raises(geomesh.ScriptError) as caught:
        geomesh.run(script, dim=1, verbosity=0)
    assert caught.value.line == 2


def test_a_meshing_failure_raises_mesh_error(write_script, square):
    # A bow-tie: curves 2 and 4 cross.
    script = write_script(
        "Point(1) = {0,0,0,0.1}; Point(2) = {3,0,0,0.1}; Point(3) = {0,1,0,0.1};\n"
        "Point(4) = {1,2,0,0.1};\n"
        "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
        "Curve Loop(1) = {1,2,3,4};\n"
        "Plane Surface(1) = {1};\n")
    with pytest.raises(geomesh.MeshError) as caught:
        geomesh.run(script, dim=2, verbosity=0)
    error = caught.value
    assert not isinstance(error, geomesh.ScriptError)
    assert "cannot mesh surface 1" in str(error)
    assert (error.line, error.column) == (5, 1)
    assert geomesh.run(script, dim=1, verbosity=0).summary()["elements"]["line"] > 0
    assert len(geomesh.run(square, dim=2, verbosity=0).nodes) > 0


def test_a_missing_file_raises(tmp_path):
    with pytest.raises(Exception):
        geomesh.run(tmp_path / "missing.geo", verbosity=0)


def test_an_unknown_dim_raises_value_error(square):
    with pytest.raises(ValueError, match="dim"):
        geomesh.run(square, dim=4)
    with pytest.raises(ValueError, match="dim"):
        geomesh.run(square, dim=-1)
    with pytest.raises(ValueError, match="dim"):
        geomesh.run(square, dim=2, verbosity=0).elements(dim=5)


def test_wrong_argument_types_raise_type_error(square):
    with pytest.raises(TypeError):
        geomesh.run(3)
    with pytest.raises(TypeError):
        geomesh.run(square, dim="2")
    with pytest.raises(TypeError):
        geomesh.run(square, numbers={"lc": "fine"})
    with pytest.raises(TypeError):
        geomesh.run(square, strings={"name": 1})


def test_error_attributes_default_to_none():
    assert geomesh.ScriptError.line is None
    assert geomesh.MeshError("x").file is None
