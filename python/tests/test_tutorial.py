"""The Python tutorial runs as its reader runs it, and prints what it says it prints."""

import os
import re
import subprocess
import sys


def test_python_first_mesh(root):
    result = subprocess.run([sys.executable, str(root / "tutorials" / "python_first_mesh.py")],
                            capture_output=True, text=True, env=dict(os.environ), check=True)
    nodes = re.search(r"^(\d+) nodes, (\d+) triangles$", result.stdout, re.MULTILINE)
    assert nodes and int(nodes.group(1)) > 100
    areas = re.search(r"area from NumPy: ([\d.]+); geomesh's summary: ([\d.]+)", result.stdout)
    assert areas and areas.group(1) == areas.group(2)
    assert "physical group" in result.stdout


def test_python_square_and_box(root):
    script = root / "tutorials" / "python_square_and_box.py"
    result = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                            env=dict(os.environ), check=True)
    for part, kind, measure in (("plate", "triangles", "area"), ("block", "tetrahedra", "volume")):
        counts = re.search(rf"^{part}: (\d+) nodes, (\d+) {kind}$", result.stdout, re.MULTILINE)
        assert counts and int(counts.group(1)) > 500 and int(counts.group(2)) > 1000
        figures = re.search(rf"^{part} {measure}: ([\d.]+) \(exact ([\d.]+)\)$", result.stdout,
                            re.MULTILINE)
        assert figures
        mesh, exact = float(figures.group(1)), float(figures.group(2))
        assert exact <= mesh <= 1.01 * exact  # straight edges leave a little more than the hole
