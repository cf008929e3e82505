#!/usr/bin/env python3
"""Meshes .geo scripts with geomesh and with the reference implementation (Gmsh from PyPI, in
the benchmarks' virtual environment) and says, script by script, whether the two meshes match
by the rule the issues use: the same physical groups (dimension and tag) and element types,
measures (length, area, volume of the highest dimension) within 2%, node counts within
0.67-1.5x, no invalid element (minimum SICN above 1e-12) and a mean quality (gamma) of at
least 0.9x the reference's.

    python3 bench/script_compare.py t16.geo t18.geo ...            # meshed with -3
    python3 bench/script_compare.py --dim 2 --timeout 60 a.geo b.geo

Files a script reads (STEP parts, STL, .pos) are found next to it: each script runs in its
own directory. Both meshes are read back with the reference's Python module, so the figures
of both sides come from the same code.
"""
import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from compare import ensure_reference  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
GEOMESH = ROOT / "build" / "bin" / "geomesh"

RUN_REFERENCE = (
    "import sys, gmsh\n"
    "gmsh.initialize(['gmsh'] + sys.argv[1:], run=True)\n"
    "gmsh.finalize()\n"
)

# Reads one MSH file with the reference module and prints its summary as JSON.
SUMMARISE = r"""
import json, sys, gmsh
gmsh.initialize(['gmsh', '-v', '0'])
gmsh.open(sys.argv[1])
out = {'nodes': len(gmsh.model.mesh.getNodes()[0]), 'types': {}, 'measure': {}, 'physicals': []}
for dim, tag in gmsh.model.getPhysicalGroups():
    out['physicals'].append([dim, tag])
top = 0
qualities = {'gamma': [], 'minSICN': []}
for dim in range(4):
    types, tags, _ = gmsh.model.mesh.getElements(dim)
    total = 0.0
    for etype, etags in zip(types, tags):
        name = gmsh.model.mesh.getElementProperties(etype)[0]
        out['types'][name] = out['types'].get(name, 0) + len(etags)
        if dim > 0 and len(etags):
            total += float(sum(gmsh.model.mesh.getElementQualities(etags, 'volume')))
    if dim > 0:
        out['measure'][dim] = total
    if len(types):
        top = dim
types, tags, _ = gmsh.model.mesh.getElements(top)
for etags in tags:
    if top > 0 and len(etags):
        qualities['gamma'] += list(gmsh.model.mesh.getElementQualities(etags, 'gamma'))
        qualities['minSICN'] += list(gmsh.model.mesh.getElementQualities(etags, 'minSICN'))
out['dim'] = top
out['gamma_mean'] = sum(qualities['gamma']) / max(1, len(qualities['gamma']))
out['sicn_min'] = min(qualities['minSICN']) if qualities['minSICN'] else 1.0
print(json.dumps(out))
gmsh.finalize()
"""


def run(cmd, cwd, timeout):
    start = time.perf_counter()
    try:
        proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
        return proc.returncode, time.perf_counter() - start, proc.stdout + proc.stderr
    except subprocess.TimeoutExpired:
        return "timeout", timeout, ""


def summarise(python, path):
    proc = subprocess.run([python, "-c", SUMMARISE, str(path)], capture_output=True, text=True)
    if proc.returncode != 0:
        return None
    return json.loads(proc.stdout.strip().splitlines()[-1])


def differences(mine, ref):
    """What breaks the matching rule, as short phrases (empty when the meshes match)."""
    found = []
    if sorted(map(tuple, mine["physicals"])) != sorted(map(tuple, ref["physicals"])):
        found.append("physical groups %s vs %s" % (mine["physicals"], ref["physicals"]))
    if set(mine["types"]) != set(ref["types"]):
        found.append("types %s vs %s" % (sorted(mine["types"]), sorted(ref["types"])))
    top = str(ref["dim"])
    a, b = mine["measure"].get(top, 0.0), ref["measure"].get(top, 0.0)
    if b > 0 and abs(a - b) > 0.02 * b:
        found.append("measure %.6g vs %.6g" % (a, b))
    ratio = mine["nodes"] / max(1, ref["nodes"])
    # Two empty meshes (a script that only post-processes views) agree.
    if (mine["nodes"] or ref["nodes"]) and not 0.67 <= ratio <= 1.5:
        found.append("nodes %d vs %d (%.2fx)" % (mine["nodes"], ref["nodes"], ratio))
    if ref["dim"] >= 2 and mine["sicn_min"] <= 1e-12:  # SICN is not defined on segments
        found.append("invalid element (min SICN %.3g)" % mine["sicn_min"])
    if mine["gamma_mean"] < 0.9 * ref["gamma_mean"]:
        found.append("mean gamma %.3f vs %.3f" % (mine["gamma_mean"], ref["gamma_mean"]))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scripts", nargs="+", type=Path)
    parser.add_argument("--dim", default="3")
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--geomesh", type=Path, default=GEOMESH)
    args = parser.parse_args()
    python = str(ensure_reference())
    matched = 0
    for script in args.scripts:
        script = script.resolve()
        with tempfile.TemporaryDirectory() as tmp:
            mine_msh, ref_msh = Path(tmp) / "mine.msh", Path(tmp) / "ref.msh"
            flags = ["-" + args.dim, "-o"]
            rc_ref, t_ref, _ = run([python, "-c", RUN_REFERENCE, script.name] + flags + [str(ref_msh)],
                                   script.parent, args.timeout)
            rc_mine, t_mine, log = run([str(args.geomesh), script.name] + flags + [str(mine_msh)],
                                       script.parent, args.timeout * 4)
            ref = summarise(python, ref_msh) if rc_ref == 0 and ref_msh.exists() else None
            mine = summarise(python, mine_msh) if rc_mine == 0 and mine_msh.exists() else None
        if ref is None:
            print("%-24s reference fails (%s)" % (script.name, rc_ref))
            continue
        if mine is None:
            last = [line for line in log.splitlines() if "rror" in line][:1]
            print("%-24s geomesh fails (%s) %s" % (script.name, rc_mine, last[0] if last else ""))
            continue
        found = differences(mine, ref)
        matched += not found
        print("%-24s %s  nodes %d/%d  gamma %.3f/%.3f  time %.2f/%.2f s %s" % (
            script.name, "match" if not found else "DIFFERS", mine["nodes"], ref["nodes"],
            mine["gamma_mean"], ref["gamma_mean"], t_mine, t_ref,
            "" if not found else "; ".join(found)))
    print("%d of %d match" % (matched, len(args.scripts)))


if __name__ == "__main__":
    main()
