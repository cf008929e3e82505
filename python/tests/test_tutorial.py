"""The Python tutorial runs as its reader runs it, and prints what it says it prints."""

import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import geomesh


def tutorial_environment():
    """The environment of a tutorial run in another directory: it imports the geomesh these
    tests import."""
    env = dict(os.environ)
    package_parent = str(pathlib.Path(geomesh.__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_parent, env.get("PYTHONPATH")]))
    return env


# A picture differs from the committed one when more than this share of its pixels differ by
# more than the threshold in a channel (as the .geo tutorials' pictures are checked).
CHANNEL_THRESHOLD = 40
DIFFERING_SHARE = 0.005


def assert_picture_is_up_to_date(root, written):
    """The tutorial's picture, as it wrote it, against tutorials/pictures/ (refresh: copy the
    written file there)."""
    image = pytest.importorskip("PIL.Image")
    committed = root / "tutorials" / "pictures" / written.name
    assert committed.exists(), f"tutorials/pictures/{written.name} is missing"
    a = np.asarray(image.open(written).convert("RGB"), dtype=np.int16)
    b = np.asarray(image.open(committed).convert("RGB"), dtype=np.int16)
    assert a.shape == b.shape
    differing = (np.abs(a - b) > CHANNEL_THRESHOLD).any(axis=2).mean()
    assert differing <= DIFFERING_SHARE, (
        f"{written.name}: {differing:.1%} of the pixels differ from tutorials/pictures/; "
        f"copy the picture the tutorial writes there if the change is meant")


def test_python_first_mesh(root, tmp_path):
    result = subprocess.run([sys.executable, str(root / "tutorials" / "python_first_mesh.py")],
                            capture_output=True, text=True, env=tutorial_environment(), check=True,
                            cwd=tmp_path)
    nodes = re.search(r"^(\d+) nodes, (\d+) triangles$", result.stdout, re.MULTILINE)
    assert nodes and int(nodes.group(1)) > 100
    areas = re.search(r"area from NumPy: ([\d.]+); geomesh's summary: ([\d.]+)", result.stdout)
    assert areas and areas.group(1) == areas.group(2)
    assert "physical group" in result.stdout
    assert_picture_is_up_to_date(root, tmp_path / "python_first_mesh.png")


def test_python_square_and_box(root, tmp_path):
    script = root / "tutorials" / "python_square_and_box.py"
    result = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                            env=tutorial_environment(), check=True, cwd=tmp_path)
    for part, kind, measure in (("plate", "triangles", "area"), ("block", "tetrahedra", "volume")):
        counts = re.search(rf"^{part}: (\d+) nodes, (\d+) {kind}$", result.stdout, re.MULTILINE)
        assert counts and int(counts.group(1)) > 500 and int(counts.group(2)) > 1000
        figures = re.search(rf"^{part} {measure}: ([\d.]+) \(exact ([\d.]+)\)$", result.stdout,
                            re.MULTILINE)
        assert figures
        mesh, exact = float(figures.group(1)), float(figures.group(2))
        assert exact <= mesh <= 1.01 * exact  # straight edges leave a little more than the hole
    assert_picture_is_up_to_date(root, tmp_path / "python_square_and_box.png")
