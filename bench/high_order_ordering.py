#!/usr/bin/env python3
"""Checks that the reference implementation reads geomesh's high-order elements the way geomesh
meant them: for every high-order element type, meshes written by geomesh (MSH 4.1 and 2.2) are
opened with the reference's Python module, and each element's node k must lie where the
reference's own first-order interpolation of the element's corners puts the reference's local
node k (nearer to it than to the place of any other local node; curved edges move nodes a
little, a wrong order moves them by a node spacing or more).

    python3 bench/high_order_ordering.py                   # geomesh runs and sample files
    python3 bench/high_order_ordering.py --no-samples      # geomesh runs only
    python3 bench/high_order_ordering.py --files a.msh b.msh

Meshes come from build/bin/geomesh on small scripts (a disk, a recombined disk, a box, swept
squares and triangles, order 2 to 4, complete and incomplete), and from the io test that
writes one straight element of every type per file (run from --io-tests with
GEOMESH_HIGH_ORDER_SAMPLES set). Prints one line per type and "N passed, N failed".
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare  # noqa: E402  (the benchmarks' shared virtual environment)

ROOT = Path(__file__).resolve().parent.parent
GEOMESH = ROOT / "build" / "bin" / "geomesh"
IO_TESTS = ROOT / "build" / "bin" / "io_tests"


def reexec_in_venv():
    try:
        import gmsh  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:
        python = compare.ensure_reference(("gmsh", "numpy"))
        os.execv(str(python), [str(python), __file__] + sys.argv[1:])


reexec_in_venv()
import gmsh  # noqa: E402
import numpy as np  # noqa: E402

DISK = """lc = {lc};
Point(1) = {{0, 0, 0, lc}}; Point(2) = {{1, 0, 0, lc}}; Point(3) = {{0, 1, 0, lc}};
Point(4) = {{-1, 0, 0, lc}}; Point(5) = {{0, -1, 0, lc}};
Circle(1) = {{2, 1, 3}}; Circle(2) = {{3, 1, 4}}; Circle(3) = {{4, 1, 5}}; Circle(4) = {{5, 1, 2}};
Curve Loop(1) = {{1, 2, 3, 4}}; Plane Surface(1) = {{1}};
{extra}
"""
BOX = """lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
"""
CASES = {
    # name: (script, dimension, orders)
    "disk": (DISK.format(lc=0.4, extra=""), 2, (2, 3, 4)),
    "recombined-disk": (DISK.format(lc=0.4, extra="Recombine Surface{1};"), 2, (2, 3, 4)),
    "box": (BOX + "Extrude {0, 0, 1} { Surface{1}; }\n", 3, (2, 3, 4)),
    "swept-quads": (BOX + "Transfinite Surface{1}; Recombine Surface{1};\n"
                    "Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; }\n", 3, (2, 3, 4)),
    "swept-triangles": (BOX + "Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; }\n", 3,
                        (2,)),
    # Prisms touching the axis of a revolution collapse into pyramids.
    "revolved-triangles": (BOX + "Extrude {{0, 1, 0}, {0, 0, 0}, Pi/2} "
                           "{ Surface{1}; Layers{3}; Recombine; }\n", 3, (2,)),
}


def table_types():
    """MSH numbers of the types of geomesh's element table, from its header."""
    text = (ROOT / "mesh" / "core" / "element_type.h").read_text()
    body = text[text.index("enum class ElementType"):]
    body = body[:body.index("};")]
    return sorted(int(n) for n in re.findall(r"=\s*(\d+)", body))


def run_geomesh(geomesh, workdir, log):
    """Meshes every case at every order, complete and incomplete, in MSH 4.1 and 2.2."""
    files = []
    for name, (script, dim, orders) in CASES.items():
        geo = workdir / f"{name}.geo"
        geo.write_text(script)
        for order in orders:
            for incomplete in (0, 1):
                for version, binary in (("msh41", False), ("msh22", False), ("msh41", True)):
                    out = workdir / (f"{name}-o{order}-i{incomplete}-{version}"
                                     f"{'-bin' if binary else ''}.msh")
                    cmd = [str(geomesh), str(geo), f"-{dim}", "-order", str(order),
                           "-setnumber", "Mesh.SecondOrderIncomplete", str(incomplete),
                           "-format", version, "-o", str(out)] + (["-bin"] if binary else [])
                    proc = subprocess.run(cmd, capture_output=True, text=True)
                    if proc.returncode != 0:
                        last = (proc.stdout + proc.stderr).strip().splitlines()[-1:]
                        log.append(f"geomesh failed on {out.name}: {' '.join(last)}")
                        continue
                    files.append(out)
    return files


def sample_files(io_tests, workdir, log):
    """One straight element of every type per file, written by geomesh's io test."""
    samples = workdir / "samples"
    samples.mkdir(exist_ok=True)
    env = dict(os.environ, GEOMESH_HIGH_ORDER_SAMPLES=str(samples))
    proc = subprocess.run([str(io_tests), "--gtest_filter=MshHighOrderSamples.*"], env=env,
                          capture_output=True, text=True)
    files = sorted(samples.glob("*.msh"))
    if proc.returncode != 0 or not files:
        log.append(f"no sample files from {io_tests} (is MshHighOrderSamples built in?)")
    return files


FAMILIES = {(1, 2): "Line", (2, 3): "Triangle", (2, 4): "Quadrangle", (3, 4): "Tetrahedron",
            (3, 5): "Pyramid", (3, 6): "Prism", (3, 8): "Hexahedron"}


def linear_places(element_type):
    """Matrix B (nodes x corners): the reference's first-order shape functions at its local
    coordinates of each node of the type, and the type's properties."""
    name, dim, order, count, local, corners = gmsh.model.mesh.getElementProperties(element_type)
    local = np.asarray(local).reshape(count, dim)
    points = np.zeros((count, 3))
    points[:, :dim] = local
    linear = gmsh.model.mesh.getElementType(FAMILIES[(dim, corners)], 1)
    _, basis, _ = gmsh.model.mesh.getBasisFunctions(linear, points.ravel().tolist(), "Lagrange")
    return name, order, count, np.asarray(basis).reshape(count, corners)


def check_open_file(path, results):
    """Adds, per type, (elements checked, [problems]) for the file the reference has open."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    position = dict(zip(tags, np.asarray(coords).reshape(-1, 3)))
    for element_type in gmsh.model.mesh.getElementTypes():
        if gmsh.model.mesh.getElementProperties(element_type)[2] < 2:
            continue
        name, order, count, basis = linear_places(element_type)
        entry = results.setdefault(element_type, {"name": name, "elements": 0, "files": set(),
                                                  "problems": []})
        entry["files"].add(path.name)
        _, nodes = gmsh.model.mesh.getElementsByType(element_type)
        nodes = np.asarray(nodes).reshape(-1, count)
        for e, element in enumerate(nodes):
            x = np.array([position[t] for t in element])
            expected = basis @ x[:basis.shape[1]]
            # distance from each node (row) to each place (column)
            gaps = np.linalg.norm(x[:, None, :] - expected[None, :, :], axis=2)
            wrong = [k for k in range(count) if np.argmin(gaps[k]) != k]
            entry["elements"] += 1
            if wrong and len(entry["problems"]) < 5:
                entry["problems"].append(f"{path.name}: element {e + 1}: nodes {wrong} are "
                                         f"nearer to other local nodes' places")


def check_files(files, results, log):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    for path in files:
        gmsh.clear()
        try:
            gmsh.open(str(path))
        except Exception as error:  # the reference cannot read the file
            number = unreadable_type(str(error))
            if number is None:
                log.append(f"the reference cannot open {path.name}: {error}")
            else:
                entry = results.setdefault(number, {"name": f"type {number}", "elements": 0,
                                                    "files": set(), "problems": []})
                entry.setdefault("unreadable", []).append(path.name)
            # After a failed open the reference reads nothing more: start it afresh.
            gmsh.finalize()
            gmsh.initialize()
            gmsh.option.setNumber("General.Terminal", 0)
            continue
        check_open_file(path, results)
    gmsh.finalize()


def unreadable_type(message):
    m = re.search(r"(?:of type|type of element) (\d+)", message)
    return int(m.group(1)) if m else None


def report(results, log):
    passed = failed = untested = unreadable = 0
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    for number in table_types():
        name = gmsh.model.mesh.getElementProperties(number)[0]
        if gmsh.model.mesh.getElementProperties(number)[2] < 2:
            continue
        entry = results.get(number)
        if entry is None:
            untested += 1
            print(f"{name:22s} (type {number:3d}): untested (no mesh holds it)")
        elif entry.get("unreadable") and entry["elements"] == 0:
            # The reference's element factory lacks the type: it cannot read even the files it
            # writes itself (checked for hexahedra of order 4, incomplete).
            unreadable += 1
            print(f"{name:22s} (type {number:3d}): not checked, the reference cannot read this "
                  f"type ({len(entry['unreadable'])} files refused)")
        elif entry["problems"]:
            failed += 1
            print(f"{name:22s} (type {number:3d}): FAILED, {entry['elements']} elements in "
                  f"{len(entry['files'])} files; {entry['problems'][0]}")
            for problem in entry["problems"][1:3]:
                print(f"{'':30s}{problem}")
        else:
            passed += 1
            print(f"{name:22s} (type {number:3d}): ok, {entry['elements']} elements in "
                  f"{len(entry['files'])} files")
    gmsh.finalize()
    for line in log:
        print("note:", line)
    print(f"{passed} passed, {failed} failed"
          + (f", {unreadable} unreadable by the reference" if unreadable else "")
          + (f", {untested} untested" if untested else ""))
    return failed == 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--geomesh", type=Path, default=GEOMESH)
    parser.add_argument("--io-tests", type=Path, default=IO_TESTS)
    parser.add_argument("--no-samples", action="store_true", help="skip the io test's files")
    parser.add_argument("--no-runs", action="store_true", help="skip the geomesh runs")
    parser.add_argument("--files", type=Path, nargs="*", help="check these files only")
    args = parser.parse_args()
    log = []
    with tempfile.TemporaryDirectory(prefix="geomesh-ordering-") as tmp:
        workdir = Path(tmp)
        if args.files:
            files = args.files
        else:
            files = []
            if not args.no_runs:
                if args.geomesh.exists():
                    files += run_geomesh(args.geomesh, workdir, log)
                else:
                    log.append(f"{args.geomesh} does not exist: no geomesh runs")
            if not args.no_samples:
                if args.io_tests.exists():
                    files += sample_files(args.io_tests, workdir, log)
                else:
                    log.append(f"{args.io_tests} does not exist: no sample files")
        results = {}
        check_files(files, results, log)
    return 0 if report(results, log) else 1


if __name__ == "__main__":
    sys.exit(main())
