#!/usr/bin/env bash
# The reliability gate: builds geomesh with clang, AddressSanitizer, UndefinedBehaviorSanitizer
# (LeakSanitizer included) and libFuzzer instrumentation into build-check/, runs every test
# there, then fuzzes the script front end and the MSH reader for a bounded number of runs,
# seeded with the project's scripts. Any sanitizer report, crash or hang fails.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-check

if [ ! -f "$build/build.ninja" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DGEOMESH_WERROR=ON -DGEOMESH_SANITIZE=ON -DGEOMESH_FUZZ=ON
fi
cmake --build "$build"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/tests/fuzz/lsan.supp
ctest --test-dir "$build" --output-on-failure -j2 --timeout 900

runs=${GEOMESH_FUZZ_RUNS:-20000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/scripts" "$work/msh" "$work/obj" "$work/run"
cp "$root"/tests/golden/scripts/*.geo "$root"/tutorials/*.geo "$work/scripts/"
# Seed meshes for the reader, in every layout it reads: 4.1 and 2.2, ASCII and binary, whole
# and partitioned.
for format in msh41 msh22; do
  for bin in "" -bin; do
    "$build/bin/geomesh" "$root/tests/golden/scripts/square.geo" -2 -v 0 -format $format $bin \
      -clscale 4 -o "$work/msh/square-$format$bin.msh"
    "$build/bin/geomesh" "$root/tests/golden/scripts/clscale.geo" -2 -v 0 -format $format $bin \
      -clscale 8 -o "$work/msh/groups-$format$bin.msh"
    "$build/bin/geomesh" "$root/tests/golden/scripts/square.geo" -2 -v 0 -format $format $bin \
      -clscale 4 -part 3 -o "$work/msh/parts-$format$bin.msh"
  done
done
# Seed surface meshes for the OBJ reader: a square and a plate with a hole.
"$build/bin/geomesh" "$root/tests/golden/scripts/square.geo" -2 -v 0 -clscale 4 \
  -o "$work/obj/square.obj"
"$build/bin/geomesh" "$root/tutorials/t1.geo" -2 -v 0 -o "$work/obj/plate.obj"
cd "$work/run"  # scripts may write files (Printf > "file"): keep them here
"$build/bin/fuzz_script" -seed=1 -runs="$runs" -timeout=10 -rss_limit_mb=4096 \
  -max_len=4096 "$work/scripts"
"$build/bin/fuzz_msh_reader" -seed=1 -runs=$((runs * 10)) -timeout=10 -rss_limit_mb=4096 \
  -max_len=16384 "$work/msh"
"$build/bin/fuzz_obj_reader" -seed=1 -runs=$((runs * 5)) -timeout=10 -rss_limit_mb=4096 \
  -max_len=8192 "$work/obj"
echo "fuzzing: $runs runs of the script front end, $((runs * 10)) of the MSH reader," \
  "$((runs * 5)) of the OBJ reader, no crash"
