#!/usr/bin/env python3
"""Meshes the unit cube (scripts/cube_uniform.geo) at sizes giving about 10k, 50k, 200k, 1M
and 5M tetrahedra with geomesh on one and on two threads and with the reference's HXT mesher
on one thread, and prints, per size and program: tetrahedra, 3D stage seconds, tets/s of the
stage, wall seconds and peak memory, the speed-up of geomesh's 3D stage on two threads, and
at the end the exponent of 3D stage time against tetrahedra fitted on log-log (n log n shows
as about 1.05-1.1).

    python3 bench/volume_scaling.py                        # every size
    python3 bench/volume_scaling.py --max-tets 1500000     # up to about 1M tetrahedra
    python3 bench/volume_scaling.py --no-reference         # geomesh only
"""
import argparse
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare  # noqa: E402  (measurement helpers and the reference's virtual environment)

SCRIPT = compare.SCRIPTS / "cube_uniform.geo"

# (tetrahedra aimed at, lc), lc measured with geomesh (the reference makes fewer tetrahedra
# at the same lc, HXT fewest). The count moves in steps with the number of segments per edge.
SIZES = ((10_000, 0.085), (50_000, 0.0473), (200_000, 0.0295), (1_000_000, 0.017),
         (5_000_000, 0.00995))


def programs(geomesh, reference, with_reference):
    """(label, command, extra arguments) of each program run at every size."""
    runs = [("geomesh-nt1", [str(geomesh)], ["-nt", "1"]),
            ("geomesh-nt2", [str(geomesh)], ["-nt", "2"])]
    if with_reference:
        runs.append(("ref-hxt-nt1", reference, ["-algo", "hxt", "-nt", "1"]))
    return runs


def fitted_exponent(points):
    """Slope of log(seconds) against log(tetrahedra), least squares; None below two points."""
    xy = [(math.log(n), math.log(t)) for n, t in points if n > 0 and t and t > 0]
    if len(xy) < 2:
        return None
    mx = sum(x for x, _ in xy) / len(xy)
    my = sum(y for _, y in xy) / len(xy)
    sxx = sum((x - mx) ** 2 for x, _ in xy)
    return sum((x - mx) * (y - my) for x, y in xy) / sxx if sxx > 0 else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--geomesh", default=str(compare.GEOMESH), help="the geomesh executable")
    parser.add_argument("--no-reference", action="store_true", help="skip the reference's HXT runs")
    parser.add_argument("--max-tets", type=int, default=None,
                        help="run only the sizes aimed at no more than N tetrahedra")
    parser.add_argument("--keep", action="store_true", help="keep the mesh files in build/bench")
    args = parser.parse_args()
    geomesh = Path(args.geomesh).resolve()
    if not geomesh.exists():
        sys.exit(f"build geomesh first ({geomesh} is missing): bash scripts/setup.sh")
    reference = compare.reference_command(compare.ensure_reference()) if not args.no_reference else None
    work = compare.ROOT / "build" / "bench"
    work.mkdir(parents=True, exist_ok=True)
    sizes = [(n, lc) for n, lc in SIZES if args.max_tets is None or n <= args.max_tets]
    runs = programs(geomesh, reference, not args.no_reference)
    print(f"{'aim':>9} {'lc':>8} {'program':12} {'tets':>9} {'3D s':>8} {'tets/s':>9} "
          f"{'wall s':>8} {'peak MiB':>9} {'nt2 speed-up':>12}")
    points = {label: [] for label, _, _ in runs}
    for aim, lc in sizes:
        stages = {}
        for label, cmd, extra in runs:
            out = work / f"volume_scaling-{label}.msh"
            row = compare.run_volume(cmd, SCRIPT, ["-3", "-setnumber", "lc", str(lc)] + extra,
                                     out, work, geomesh, with_quality=False)
            if not args.keep:
                out.unlink()
            stages[label] = row["stage"]
            points[label].append((row["tets"], row["stage"]))
            speedup = ""
            if label == "geomesh-nt2" and row["stage"] and stages.get("geomesh-nt1"):
                speedup = f"{stages['geomesh-nt1'] / row['stage']:11.2f}x"
            stage = f"{row['stage']:8.3f}" if row["stage"] is not None else "       -"
            print(f"{aim:9d} {lc:8.5f} {label:12} {row['tets']:9d} {stage} {row['rate']:9.0f} "
                  f"{row['wall']:8.3f} {row['rss']:9.1f} {speedup:>12}", flush=True)
    for label, pts in points.items():
        k = fitted_exponent(pts)
        text = f"{k:.3f}" if k is not None else "- (fewer than two sizes)"
        print(f"{label:12} 3D stage time ~ tets^k: k = {text}")


if __name__ == "__main__":
    main()
