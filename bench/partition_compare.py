#!/usr/bin/env python3
"""Partitions one tetrahedral mesh with geomesh and with the reference implementation (Gmsh
from PyPI, in the virtual environment compare.py makes) and compares, for each partition
count, the load imbalance (largest partition over the mean, minus one), the edge cut (faces
between tetrahedra of different partitions: the cut edges of the dual graph METIS splits)
and the wall time. Both partition the same file, which geomesh meshes first.

    python3 bench/partition_compare.py                 # 8 and 32 partitions, about 1M tets
    python3 bench/partition_compare.py --parts 4 16 --size 0.03
"""
import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare  # noqa: E402  (the reference's virtual environment)

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "bench" / "scripts" / "partition_cube.geo"

# Run inside the reference's Python: reads a partitioned file and prints tets, imbalance, cut.
STATISTICS = r"""
import sys, gmsh, numpy as np
gmsh.initialize(); gmsh.option.setNumber("General.Verbosity", 1)
gmsh.open(sys.argv[1])
parts = gmsh.model.getNumberOfPartitions()
faces, owner, load = [], [], np.zeros(parts + 1, dtype=np.int64)
for dim, tag in gmsh.model.getEntities(3):
    p = gmsh.model.getPartitions(dim, tag)
    if len(p) != 1:
        continue
    for etype, _, nodes in zip(*gmsh.model.mesh.getElements(dim, tag)):
        if etype != 4:
            continue
        t = nodes.reshape(-1, 4)
        load[p[0]] += len(t)
        for f in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
            faces.append(np.sort(t[:, f], axis=1))
            owner.append(np.full(len(t), p[0]))
faces, owner = np.vstack(faces), np.concatenate(owner)
order = np.lexsort(faces.T[::-1])
faces, owner = faces[order], owner[order]
same = np.all(faces[1:] == faces[:-1], axis=1)
cut = int(np.sum(same & (owner[1:] != owner[:-1])))
tets = int(load.sum())
print(parts, tets, load[1:].max() / (tets / parts) - 1, cut)
gmsh.finalize()
"""


def run(cmd, cwd):
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"failed: {' '.join(map(str, cmd))}\n{proc.stdout}{proc.stderr}")
    return time.perf_counter() - start


def statistics(python, path):
    out = subprocess.run([str(python), "-c", STATISTICS, str(path)], capture_output=True,
                         text=True, check=True).stdout.split()
    return int(out[0]), int(out[1]), float(out[2]), int(out[3])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--geomesh", default=str(ROOT / "build" / "bin" / "geomesh"))
    parser.add_argument("--parts", type=int, nargs="+", default=[8, 32])
    parser.add_argument("--size", type=float, default=None, help="mesh size (default: the script's)")
    args = parser.parse_args()
    python = compare.ensure_reference(("gmsh", "numpy"))
    reference = [str(python), "-c", "import sys, gmsh; gmsh.initialize(['gmsh'] + sys.argv[1:], "
                 "run=True); gmsh.finalize()"]
    failed = False
    with tempfile.TemporaryDirectory() as work:
        mesh = Path(work) / "cube.msh"
        size = ["-setnumber", "size", str(args.size)] if args.size else []
        run([args.geomesh, str(SCRIPT), "-3", *size, "-o", str(mesh)], work)
        print(f"{'parts':>5} {'tool':>9} {'tets':>9} {'imbalance':>10} {'cut faces':>10} {'time s':>7}")
        for n in args.parts:
            results = {}
            # The reference partitions a mesh file in batch only when told -0.
            for tool, cmd in (("geomesh", [args.geomesh]), ("reference", reference + ["-0"])):
                out = Path(work) / f"{tool}_{n}.msh"
                seconds = run([*cmd, str(mesh), "-part", str(n), "-o", str(out)], work)
                parts, tets, imbalance, cut = statistics(python, out)
                results[tool] = (imbalance, cut)
                print(f"{parts:>5} {tool:>9} {tets:>9} {100 * imbalance:>9.2f}% {cut:>10} {seconds:>7.2f}")
            ours, ref = results["geomesh"], results["reference"]
            ratio = ours[1] / ref[1] if ref[1] else float("inf")
            ok = ours[0] < 0.03 and ratio <= 1.10
            failed |= not ok
            print(f"      cut ratio geomesh/reference {ratio:.3f}: {'ok' if ok else 'FAIL'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
