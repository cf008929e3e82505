"""The reference's Python tutorials run with geomesh's module in place of the reference's, the
import line changed only, side by side with the reference on the same machine.

    python3 bench/python_tutorials.py [t1 t2 ...]

Each tutorial runs twice in a directory of its own (`-nopopup`): once as shipped with the
reference's module (from bench/.venv-bench), once with `import gmsh` replaced by `import
geomesh as gmsh` (the module of build/python, with the system's /usr/bin/python3). For every
mesh file both runs wrote, the node counts are compared: within 15% is a match. Prints one
line per tutorial and the totals.
"""

import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from compare import ROOT, ensure_reference

TOLERANCE = 0.15


def node_count(path):
    """Nodes of an MSH file, 4.1 or 2.2, ASCII or binary: the first number after $Nodes."""
    with open(path, "rb") as f:
        data = f.read()
    start = data.find(b"$Nodes")
    if start < 0:
        return None
    numbers = data[start + 6:start + 200].split()
    # 4.1: numEntityBlocks numNodes ...; 2.2: numNodes.
    header = data[:data.find(b"$EndMeshFormat")].split()
    version = float(header[1]) if len(header) > 1 else 2.2
    return int(numbers[1] if version >= 4 else numbers[0])


def run(python, script, work, env=None):
    start = time.perf_counter()
    result = subprocess.run([python, str(script), "-nopopup"], cwd=work, capture_output=True,
                            text=True, env=env, timeout=600)
    return result.returncode, time.perf_counter() - start, result.stderr


def main(names):
    reference_python = ensure_reference()
    tutorials = reference_python.parent.parent / "share" / "doc" / "gmsh" / "tutorials" / "python"
    scripts = sorted(tutorials.glob("t*.py"), key=lambda p: int(re.sub(r"\D", "", p.stem) or 0))
    if names:
        scripts = [s for s in scripts if s.stem in names]
    env = {"PYTHONPATH": str(ROOT / "build" / "python"), "PATH": "/usr/bin:/bin"}
    ran = matched = compared = 0
    for script in scripts:
        with tempfile.TemporaryDirectory() as ref_top, tempfile.TemporaryDirectory() as our_top:
            # The tutorials read their data files from the folder above their own.
            ref_dir, our_dir = Path(ref_top) / "python", Path(our_top) / "python"
            data_files = [d for d in tutorials.parent.glob("*")
                          if d.is_file() and d.suffix not in (".py", ".geo")]
            for top, work in ((ref_top, ref_dir), (our_top, our_dir)):
                work.mkdir()
                for data in data_files:
                    (Path(top) / data.name).write_bytes(data.read_bytes())
            (ref_dir / script.name).write_text(script.read_text())
            ported = our_dir / script.name
            ported.write_text(re.sub(r"^import gmsh$", "import geomesh as gmsh",
                                     script.read_text(), flags=re.MULTILINE))
            ref_status, ref_time, _ = run(str(reference_python), ref_dir / script.name, ref_dir)
            our_status, our_time, our_err = run("/usr/bin/python3", ported, our_dir, env)
            ran += our_status == 0
            rows = []
            for mesh in sorted(ref_dir.glob("*.msh")):
                ours = our_dir / mesh.name
                if not ours.exists():
                    rows.append(f"{mesh.name}: not written")
                    continue
                a, b = node_count(ours), node_count(mesh)
                if not a or not b:
                    continue
                compared += 1
                ok = abs(a - b) <= TOLERANCE * b
                matched += ok
                rows.append(f"{mesh.name} {a}/{b} nodes {'match' if ok else 'differs'}")
            status = "ok" if our_status == 0 else "FAILED: " + our_err.strip().splitlines()[-1]
            print(f"{script.stem}: {status} ({our_time:.2f} s vs {ref_time:.2f} s); "
                  + ("; ".join(rows) if rows else "no mesh file"), flush=True)
    print(f"{ran} of {len(scripts)} tutorials run; {matched} of {compared} mesh files within "
          f"{TOLERANCE:.0%} of the reference's node count")


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    main(sys.argv[1:])
