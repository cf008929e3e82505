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
