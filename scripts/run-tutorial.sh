#!/usr/bin/env bash
# Sets up geomesh if needed, then meshes the first tutorial in 2D into t1.msh.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
"$root/build/bin/geomesh" "$root/tutorials/t1.geo" -2 -o t1.msh
