"""Shared fixtures: the repository's root and small scripts written into a test's folder."""

import pathlib

import pytest

import geomesh

ROOT = pathlib.Path(__file__).resolve().parents[2]

# A unit square whose size `lc` a run may change (numbers={"lc": ...}), with two groups.
SQUARE = """\
DefineConstant[ lc = 0.2 ];
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("walls", 10) = {1, 2, 3, 4};
Physical Surface("plate", 20) = {1};
"""


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def write_script(tmp_path):
    """Writes a script into the test's folder and returns its path."""

    def write(text, name="script.geo"):
        path = tmp_path / name
        path.write_text(text)
        return path

    return write


@pytest.fixture
def square(write_script):
    return write_script(SQUARE, "square.geo")


@pytest.fixture
def api_session():
    """An empty model with default options for the module-level API, finalized afterwards."""
    geomesh.finalize()
    geomesh.initialize()
    geomesh.option.setNumber("General.Verbosity", 2)
    yield
    geomesh.finalize()
