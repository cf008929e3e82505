#!/usr/bin/env python3
"""Checks geomesh's mesh files with the readers of others. Each case script is meshed by
geomesh into MSH and into every format of the FORMATS table; each file is read back with
meshio, with the reference Gmsh (where it reads the format) and with geomesh itself, and the
element counts per type (and, for formats that hold them, the entity tags) are compared with
those of the MSH file as meshio reads it. Prints a table of pass/fail; exits 1 on a failure.

    bench/.venv-bench/bin/python bench/format_readback.py              # every format and case
    bench/.venv-bench/bin/python bench/format_readback.py stl ply-bin  # some formats
    bench/.venv-bench/bin/python bench/format_readback.py --geomesh build-fa/bin/geomesh

It needs meshio and gmsh in the Python that runs it (bench/.venv-bench has both).
"""
import argparse
import collections
import contextlib
import io
import json
import subprocess
import sys
import tempfile
import warnings
from dataclasses import dataclass, field
from pathlib import Path

try:
    import meshio
    import numpy
except ImportError:
    meshio = None

# One row per format and variant; adding a format is adding a row.
#   name       shown in the table; selects rows on the command line
#   ext        extension of the file geomesh writes (-o case.EXT)
#   options    further geomesh options for writing it
#   meshio     meshio's name of the format (its file_format), or None when meshio cannot read it
#   reference  whether the reference Gmsh reads the file (gmsh.merge)
#   content    what the file holds of the mesh: "all" (every saved element), "surface" (the
#              triangles and quadrangles), "triangles" (triangles, each quadrangle split in two)
#   tags       (cell data key in meshio's reading of the file, key in its reading of the MSH
#              file) whose values must match per element type; None when the format has none
#   limits     readers that only take triangle faces ("meshio", "reference"): cases with
#              quadrangle faces are skipped for them
#   geomesh    whether geomesh reads the format back (geomesh FILE -o back.msh)
@dataclass
class Row:
    name: str
    ext: str
    options: list
    meshio: str
    reference: bool
    content: str
    tags: tuple = None
    limits: tuple = ()
    geomesh: bool = True


ENTITY_TAGS = ("CellEntityIds", "gmsh:geometrical")

FORMATS = [
    Row("vtk", "vtk", [], "vtk", True, "all", ENTITY_TAGS),
    # The reference reads no binary legacy VTK file, not even those it writes itself.
    Row("vtk-bin", "vtk", ["-bin"], "vtk", False, "all", ENTITY_TAGS),
    Row("vtu", "vtu", [], "vtu", False, "all", ENTITY_TAGS, geomesh=False),
    Row("vtu-bin", "vtu", ["-bin"], "vtu", False, "all", ENTITY_TAGS, geomesh=False),
    Row("stl", "stl", [], "stl", True, "triangles"),
    Row("stl-bin", "stl", ["-bin"], "stl", True, "triangles"),
    # The reference's PLY reader keeps the first three vertices of every face.
    Row("ply", "ply", [], "ply", True, "surface", limits=("reference",)),
    # The reference's binary PLY reader takes 4-byte float vertices; geomesh writes doubles.
    Row("ply-bin", "ply", ["-bin"], "ply", False, "surface"),
    Row("off", "off", [], "off", True, "surface", limits=("meshio",)),
    # UNV: meshio has no reader; geomesh reads its property table numbers back as entity tags.
    Row("unv", "unv", [], None, True, "all", (None, "gmsh:geometrical")),
    # The reference's Medit reader skips Prisms, Pyramids and QuadrilateralsQ2, so that the 3D
    # case would fail on its side; it reads the 2D cases with the same counts.
    Row("mesh", "mesh", [], "medit", False, "all", ("medit:ref", "gmsh:physical")),
    Row("bdf", "bdf", [], "nastran", True, "all", ("nastran:ref", "gmsh:physical")),
    # meshio's CGNS reader takes a single tetrahedron section only.
    Row("cgns", "cgns", [], None, True, "all"),
    Row("inp", "inp", [], "abaqus", False, "all", geomesh=False),
    Row("su2", "su2", [], "su2", False, "all", geomesh=False),
]

# The meshes written: name -> (script, geomesh options).
CASES = {
    "2d-mixed": ("mixed_2d.geo", ["-2"]),
    "2d-triangles": ("mixed_2d.geo", ["-2", "-setnumber", "recombine", "0"]),
    "3d-mixed": ("mixed_3d.geo", ["-3"]),
}

SCRIPTS = {
    # Two squares side by side: triangles on the left, recombined quadrangles on the right.
    "mixed_2d.geo": """
DefineConstant[recombine = 1];
lc = 0.2;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {2, 0, 0, lc};
Point(4) = {2, 1, 0, lc}; Point(5) = {1, 1, 0, lc}; Point(6) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
If (recombine)
  Recombine Surface{2};
EndIf
Physical Surface("left") = {1};
Physical Surface("right") = {2};
Physical Curve("outline") = {1, 5, 6, 7, 3, 4};
""",
    # Hexahedra (layered extrusion of a transfinite square), prisms (layered extrusion of a
    # triangulated square) and tetrahedra above the prisms (unstructured).
    "mixed_3d.geo": """
lc = 0.25;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 4; Transfinite Surface{1}; Recombine Surface{1};
hex[] = Extrude{0, 0, 1}{Surface{1}; Layers{3}; Recombine;};
Point(101) = {2, 0, 0, lc}; Point(102) = {3, 0, 0, lc}; Point(103) = {3, 1, 0, lc};
Point(104) = {2, 1, 0, lc};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
prism[] = Extrude{0, 0, 0.5}{Surface{101}; Layers{2}; Recombine;};
tet[] = Extrude{0, 0, 0.5}{Surface{prism[0]};};
Physical Volume("hexahedra") = {hex[1]};
Physical Volume("prisms") = {prism[1]};
Physical Volume("tetrahedra") = {tet[1]};
Physical Surface("bottom") = {1, 101};
""",
}


ROOT = Path(__file__).resolve().parent.parent
GEOMESH = ROOT / "build" / "bin" / "geomesh"
SURFACE_TYPES = ("triangle", "quad")

# The reference's element type numbers, as meshio names the types.
GMSH_TYPES = {15: "vertex", 1: "line", 2: "triangle", 3: "quad", 4: "tetra", 5: "hexahedron",
              6: "wedge", 7: "pyramid", 8: "line3", 9: "triangle6", 10: "quad9", 11: "tetra10",
              12: "hexahedron27", 13: "wedge18", 16: "quad8", 17: "hexahedron20",
              18: "wedge15", 19: "pyramid13"}

REFERENCE_COUNTS = """
import json, sys, gmsh
gmsh.initialize(["gmsh", "-v", "0"])
gmsh.merge(sys.argv[1])
counts = {}
for t, tags in zip(*gmsh.model.mesh.getElements()[:2]):
    counts[int(t)] = counts.get(int(t), 0) + len(tags)
print(json.dumps(counts))
gmsh.finalize()
"""


@dataclass
class Content:
    """What a mesh file holds, as compared: element counts per type, node count, tags."""
    counts: dict
    nodes: int
    tags: collections.Counter = field(default_factory=collections.Counter)


def run(cmd, cwd):
    proc = subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} failed:\n{proc.stdout}{proc.stderr}")
    return proc.stdout


def meshio_content(path, file_format=None, tag_key=None):
    # meshio's notes and warnings (its STL reader tries the binary layout first) would break
    # the table.
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()), \
            warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mesh = meshio.read(path, file_format=file_format)
    counts = collections.Counter()
    tags = collections.Counter()
    used = set()
    for i, block in enumerate(mesh.cells):
        counts[block.type] += len(block.data)
        if block.type in SURFACE_TYPES:
            used.update(block.data.flatten().tolist())
        if tag_key:
            for tag in numpy.asarray(mesh.cell_data[tag_key][i]).reshape(-1):
                tags[(block.type, int(tag))] += 1
    return Content(dict(counts), len(mesh.points), tags), len(used)


def expected(msh, surface_nodes, content):
    """What a format of `content` holds of the MSH file's mesh."""
    if content == "all":
        return Content(dict(msh.counts), msh.nodes, msh.tags)
    tri = msh.counts.get("triangle", 0)
    quad = msh.counts.get("quad", 0)
    if content == "triangles":
        counts = {"triangle": tri + 2 * quad}
    else:
        counts = {k: n for k, n in (("triangle", tri), ("quad", quad)) if n}
    return Content(counts, surface_nodes)


def compare(what, got, want, check_nodes=True, check_tags=True):
    problems = []
    if got.counts != want.counts:
        problems.append(f"{what}: counts {got.counts} != {want.counts}")
    if check_nodes and got.nodes != want.nodes:
        problems.append(f"{what}: {got.nodes} nodes != {want.nodes}")
    if check_tags and got.tags != want.tags:
        problems.append(f"{what}: entity tags differ")
    return problems


def reference_counts(path):
    out = run([sys.executable, "-c", REFERENCE_COUNTS, path], cwd=path.parent)
    counts = json.loads(out.strip().splitlines()[-1])
    return {GMSH_TYPES.get(int(t), f"type{t}"): n for t, n in counts.items()}


def check(row, case, work, geomesh):
    """Results for one format and case ({reader: "pass", "FAIL", "skip" or "-"}), problems."""
    script, options = CASES[case]
    msh_content, surface_nodes = meshio_content(work / f"{case}.msh", None,
                                                row.tags[1] if row.tags else None)
    path = work / f"{case}-{row.name}.{row.ext}"
    run([geomesh, script, *options, *row.options, "-o", path.name], cwd=work)
    want = expected(msh_content, surface_nodes, row.content)
    has_quads = msh_content.counts.get("quad", 0) > 0
    results, problems = {}, []

    def record(reader, compared):
        try:
            found = compared()
        except Exception as error:  # a reader that cannot read the file fails
            found = [f"{case} {row.name} {reader}: {error}"]
        results[reader] = "FAIL" if found else "pass"
        problems.extend(found)

    if row.meshio is None:
        results["meshio"] = "-"
    elif "meshio" in row.limits and has_quads:
        results["meshio"] = "skip"
    else:
        def by_meshio():
            got, _ = meshio_content(path, row.meshio, row.tags[0] if row.tags else None)
            return compare(f"{case} {row.name} meshio", got, want, True, bool(row.tags))
        record("meshio", by_meshio)
    if not row.reference:
        results["reference"] = "-"
    elif "reference" in row.limits and has_quads:
        results["reference"] = "skip"
    else:
        record("reference", lambda: compare(f"{case} {row.name} reference",
                                            Content(reference_counts(path), 0), want, False,
                                            False))
    if not row.geomesh:
        results["geomesh"] = "-"
    else:
        def by_geomesh():
            back = work / f"{case}-{row.name}-back.msh"
            run([geomesh, path.name, "-o", back.name], cwd=work)
            got, _ = meshio_content(back, None, "gmsh:geometrical" if row.tags else None)
            return compare(f"{case} {row.name} geomesh", got, want, True, bool(row.tags))
        record("geomesh", by_geomesh)
    return results, problems


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("formats", nargs="*", help="row names (default: every row)")
    parser.add_argument("--geomesh", default=str(GEOMESH), help="the geomesh executable")
    parser.add_argument("--keep", help="write the files to this directory and keep them")
    args = parser.parse_args()
    if meshio is None:
        sys.exit("meshio is missing: run this script with bench/.venv-bench/bin/python")
    rows = [r for r in FORMATS if not args.formats or r.name in args.formats]
    unknown = set(args.formats) - {r.name for r in FORMATS}
    if unknown:
        sys.exit(f"unknown formats: {', '.join(sorted(unknown))}")
    geomesh = Path(args.geomesh).resolve()
    with tempfile.TemporaryDirectory() as temporary:
        work = Path(args.keep or temporary).resolve()
        work.mkdir(parents=True, exist_ok=True)
        for name, text in SCRIPTS.items():
            (work / name).write_text(text)
        for case, (script, options) in CASES.items():
            run([geomesh, script, *options, "-o", f"{case}.msh"], cwd=work)
        return report(rows, work, geomesh)


def report(rows, work, geomesh):
    readers = ("meshio", "reference", "geomesh")
    print(f"{'format':<10}{'case':<14}" + "".join(f"{r:<11}" for r in readers))
    problems = []
    for row in rows:
        for case in CASES:
            try:
                results, found = check(row, case, work, geomesh)
            except RuntimeError as error:  # geomesh could not write the file
                results, found = {r: "FAIL" for r in readers}, [f"{case} {row.name}: {error}"]
            problems.extend(found)
            print(f"{row.name:<10}{case:<14}" + "".join(f"{results[r]:<11}" for r in readers))
    print("\n(-: the reader does not read the format; skip: it reads triangle faces only and "
          "the case has quadrangles)")
    for problem in problems:
        print("FAIL", problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
