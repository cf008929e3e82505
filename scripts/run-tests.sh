#!/usr/bin/env bash
# Sets up geomesh if needed, then runs the whole test suite: every test in the release build,
# then the reliability gate (sanitizer build and a bounded fuzzing run: scripts/run-checks.sh).
# GEOMESH_QUICK=1 skips the gate.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
ctest --test-dir "$root/build" --output-on-failure -j2 --timeout 600
if [ "${GEOMESH_QUICK:-0}" != "1" ]; then
  "$root/scripts/run-checks.sh"
fi
