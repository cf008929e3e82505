#!/usr/bin/env python3
"""Runs benchmark scripts with geomesh and with the reference implementation (Gmsh from PyPI,
installed into a virtual environment this script creates), on the same machine in the same
run, and reports wall times, peak memory, mesh sizes, throughput and ratios.

    python3 bench/compare.py                       # every case
    python3 bench/compare.py square_uniform        # one case

3D cases run the reference twice, its default (Delaunay) and HXT (`-algo hxt`), and report
tetrahedra, nodes and the tetrahedra's gamma as geomesh's `-check` of each file gives it.
"""
import argparse
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VENV = ROOT / "bench" / ".venv-bench"
GEOMESH = ROOT / "build" / "bin" / "geomesh"
SCRIPTS = ROOT / "bench" / "scripts"

# name: (script, arguments, what is measured)
CASES = {
    "square_uniform": ("square_uniform.geo", ["-2"], "2D"),
    "square_uniform_small": ("square_uniform.geo", ["-2", "-setnumber", "lc", "0.01"], "2D"),
    "plate_holes": ("plate_holes.geo", ["-2"], "2D"),
    "many_points": ("many_points.geo", ["-0"], "script"),
    # A STEP part against a built-in square of about the same triangle count: what meshing
    # CAD surfaces costs over plane ones.
    "cad_part": ("cad_part.geo", ["-2"], "2D"),
    "square_like_cad_part": ("square_uniform.geo", ["-2", "-setnumber", "lc", "0.0035"], "2D"),
    "cube_uniform": ("cube_uniform.geo", ["-3"], "3D"),
    "cube_uniform_small": ("cube_uniform.geo", ["-3", "-setnumber", "lc", "0.05"], "3D"),
}

# The reference's runs of a 3D case: (row name, extra arguments).
REFERENCE_3D = (("ref-del", []), ("ref-hxt", ["-algo", "hxt"]))

# MSH element type of a 4-node tetrahedron.
TETRAHEDRON = 4

# Cases whose script reads a file that another script makes: (script, what it writes). Both
# are copied to the work directory and the maker runs there, once, with geomesh.
PREPARED = {"cad_part": ("cad_part_model.geo", "cad_part.step")}


def ensure_reference(modules=("gmsh",)):
    """The Python of the benchmarks' virtual environment (made on first use), with the
    reference module and the other `modules` installed. Every bench script shares it."""
    python = VENV / "bin" / "python"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
    probe = subprocess.run([str(python), "-c", "import " + ", ".join(modules)], capture_output=True)
    if probe.returncode != 0:
        subprocess.run([str(python), "-m", "pip", "install", "-q", *modules], check=True)
    return python


def reference_command(python):
    """The command that runs the reference like its executable: arguments follow it."""
    return [str(python), "-c",
            "import sys, gmsh; gmsh.initialize(['gmsh'] + sys.argv[1:], run=True); gmsh.finalize()"]


def measure(cmd, cwd):
    """Runs cmd inside a fresh Python child so that its peak RSS is its own."""
    wrapper = (
        "import resource, subprocess, sys, time, json\n"
        "t = time.perf_counter()\n"
        "p = subprocess.run(sys.argv[1:], capture_output=True, text=True)\n"
        "w = time.perf_counter() - t\n"
        "r = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0\n"
        "print(json.dumps({'rc': p.returncode, 'wall': w, 'rss': r, 'out': p.stdout + p.stderr}))\n"
    )
    proc = subprocess.run([sys.executable, "-c", wrapper] + cmd, cwd=cwd, capture_output=True, text=True)
    data = json.loads(proc.stdout)
    if data["rc"] != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} failed:\n{data['out'][-2000:]}")
    return data["wall"], data["rss"], data["out"]


def stage_seconds(log, stage):
    """Wall time of a meshing stage ('2D') from either program's log, if it reports one."""
    m = re.search(r"Done meshing " + stage + r" \(Wall ([0-9.eE+-]+)s", log)
    if m:
        return float(m.group(1))
    m = re.search(r"Meshing " + stage + r".*?\(([0-9.eE+-]+) s", log)
    return float(m.group(1)) if m else None


def msh_counts(msh_path):
    """(nodes, {element type: count}) of an MSH 4.1 ASCII file."""
    nodes, counts = 0, {}
    with open(msh_path) as f:
        for line in f:
            if line.startswith("$Nodes"):
                nodes = int(next(f).split()[1])
            elif line.startswith("$Elements"):
                break
        blocks = int(next(f).split()[0])
        for _ in range(blocks):
            _, _, element_type, n = (int(x) for x in next(f).split())
            counts[element_type] = counts.get(element_type, 0) + n
            for _ in range(n):
                next(f)
    return nodes, counts


def triangles(msh_path):
    """Number of 3-node triangles in an MSH 4.1 ASCII file."""
    return msh_counts(msh_path)[1].get(2, 0)


def quality(geomesh, msh_path):
    """(min, mean) gamma of a mesh file, as geomesh's summary of it reports."""
    proc = subprocess.run([str(geomesh), str(msh_path), "-v", "4"], capture_output=True, text=True)
    m = re.search(r"quality \(gamma\) min ([0-9.eE+-]+), mean ([0-9.eE+-]+)", proc.stderr)
    return (float(m.group(1)), float(m.group(2))) if m else (float("nan"), float("nan"))


def check(geomesh, msh_path):
    """(min gamma, mean gamma, problems) of a mesh file by geomesh's `-check`: its summary gives
    the gamma of the highest-dimensional elements (the tetrahedra of a 3D mesh); problems is
    "" when the check finds none, else its first error line and the line after it."""
    proc = subprocess.run([str(geomesh), str(msh_path), "-check"], capture_output=True, text=True)
    log = proc.stdout + proc.stderr
    m = re.search(r"quality \(gamma\) min ([0-9.eE+-]+), mean ([0-9.eE+-]+)", log)
    qmin, qmean = (float(m.group(1)), float(m.group(2))) if m else (float("nan"), float("nan"))
    problems = ""
    if proc.returncode != 0:
        lines = log.splitlines()
        first = next((i for i, line in enumerate(lines) if "rror" in line), None)
        problems = (" / ".join(lines[first:first + 2]) if first is not None
                    else f"-check exited with {proc.returncode}")
    return qmin, qmean, problems


def run_volume(cmd, script_path, extra, out, work, geomesh, with_quality=True):
    """Meshes a 3D case with one program (cmd, then the script, extra and the output) into
    `out` (MSH 4.1 ASCII) and returns its figures: wall and 3D stage seconds, peak MiB,
    tetrahedra, tets/s of the stage, nodes, and (with_quality) gamma min / mean and problems."""
    full = cmd + [str(script_path)] + extra + ["-format", "msh41", "-o", str(out)]
    wall, rss, log = measure(full, work)
    stage = stage_seconds(log, "3D")
    nodes, counts = msh_counts(out)
    tets = counts.get(TETRAHEDRON, 0)
    row = {"wall": wall, "stage": stage, "rss": rss, "tets": tets, "nodes": nodes,
           "rate": tets / stage if tets and stage else 0.0,
           "qmin": float("nan"), "qmean": float("nan"), "problems": ""}
    if with_quality and tets:
        row["qmin"], row["qmean"], row["problems"] = check(geomesh, out)
    return row


def print_volume_header():
    print(f"{'case':24} {'program':10} {'wall s':>8} {'3D s':>8} {'peak MiB':>9} {'tets':>10} "
          f"{'tets/s':>10} {'nodes':>9} {'min gamma':>9} {'mean gamma':>10}")


def run_volume_case(name, script_path, extra, geomesh, reference, work):
    """A 3D case: geomesh and the reference's runs of REFERENCE_3D, each on one thread."""
    programs = [("geomesh", [str(geomesh)], [])]
    programs += [(label, reference, algo) for label, algo in REFERENCE_3D]
    rows = {}
    for program, cmd, algo in programs:
        out = work / f"{name}-{program}.msh"
        row = run_volume(cmd, script_path, extra + algo + ["-nt", "1"], out, work, geomesh)
        rows[program] = row
        st_text = f"{row['stage']:8.3f}" if row["stage"] is not None else "       -"
        print(f"{name:24} {program:10} {row['wall']:8.3f} {st_text} {row['rss']:9.1f} {row['tets']:10d} "
              f"{row['rate']:10.0f} {row['nodes']:9d} {row['qmin']:9.4f} {row['qmean']:10.5f}")
        if row["problems"]:
            print(f"{'':24} {program:10} check: {row['problems']}")
    g = rows["geomesh"]
    for label, _ in REFERENCE_3D:
        r = rows[label]
        speed = r["stage"] / g["stage"] if g["stage"] and r["stage"] else float("nan")
        print(f"{name:24} {label + '/gm':10} {r['wall'] / g['wall']:8.2f}x {speed:7.2f}x "
              f"{r['rss'] / g['rss']:8.2f}x  (wall, 3D stage, memory: reference / geomesh)")


def prepare(name, script, geomesh, work):
    """The script to run for a case: in place, or copied next to the file it reads, made first."""
    if name not in PREPARED:
        return SCRIPTS / script
    maker, made = PREPARED[name]
    for f in (script, maker):
        shutil.copy(SCRIPTS / f, work / f)
    if not (work / made).exists():
        subprocess.run([str(geomesh), maker, "-0", "-o", maker + "_unrolled"], cwd=work,
                       check=True, capture_output=True)
    return work / script


def print_header():
    print(f"{'case':24} {'program':10} {'wall s':>8} {'stage s':>8} {'peak MiB':>9} {'triangles':>10} "
          f"{'tri/s':>10} {'min gamma':>9} {'mean gamma':>10}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="*", default=list(CASES))
    parser.add_argument("--geomesh", default=str(GEOMESH), help="the geomesh executable")
    args = parser.parse_args()
    geomesh = Path(args.geomesh).resolve()
    if not geomesh.exists():
        sys.exit(f"build geomesh first ({geomesh} is missing): bash scripts/setup.sh")
    python = ensure_reference()
    reference = reference_command(python)
    work = ROOT / "build" / "bench"
    work.mkdir(parents=True, exist_ok=True)
    header = None
    speeds = {}
    for name in args.cases:
        script, extra, stage = CASES[name]
        script_path = prepare(name, script, geomesh, work)
        if stage == "3D":
            if header != "3D":
                print_volume_header()
            header = "3D"
            run_volume_case(name, script_path, extra, geomesh, reference, work)
            continue
        if header != "2D":
            print_header()
        header = "2D"
        rows = {}
        for program, cmd in (("geomesh", [str(geomesh)]), ("reference", reference)):
            out = work / f"{name}-{program}.msh"
            full = cmd + [str(script_path)] + extra + ["-nt", "1", "-o", str(out)]
            wall, rss, log = measure(full, work)
            st = stage_seconds(log, stage) if stage != "script" else wall
            tri = triangles(out) if stage == "2D" and out.exists() else 0
            rate = tri / st if tri and st else 0
            qmin, qmean = quality(geomesh, out) if tri else (float("nan"), float("nan"))
            rows[program] = (wall, st, rss, tri, rate)
            st_text = f"{st:8.3f}" if st is not None else "       -"
            print(f"{name:24} {program:10} {wall:8.3f} {st_text} {rss:9.1f} {tri:10d} {rate:10.0f} "
                  f"{qmin:9.4f} {qmean:10.5f}")
        g, r = rows["geomesh"], rows["reference"]
        speed = (r[1] / g[1]) if g[1] and r[1] else float("nan")
        print(f"{name:24} {'ratio':10} {r[0] / g[0]:8.2f}x {speed:7.2f}x {r[2] / g[2]:8.2f}x  (reference / geomesh)")
        speeds[name] = {program: row[4] for program, row in rows.items()}
    if "cad_part" in speeds and "square_like_cad_part" in speeds:
        for program in ("geomesh", "reference"):
            cad, plane = speeds["cad_part"][program], speeds["square_like_cad_part"][program]
            if cad:
                print(f"{'CAD cost':24} {program:10} {plane / cad:8.2f}x  (triangles/s on the square / on the STEP part)")


if __name__ == "__main__":
    main()
