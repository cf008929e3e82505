#!/usr/bin/env bash
# `pip install .` into a new virtual environment, then the module's tests and the command
# from that environment: what a user who installs geomesh with pip gets. Run by ctest
# (python_wheel); the wheel is built in build-python/, beside build/, so that ccache serves the
# objects build/ compiled.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
venv=${1:-$root/build/wheel-venv}
python=${GEOMESH_WHEEL_PYTHON:-/usr/bin/python3}

rm -rf "$venv"
"$python" -m venv "$venv"
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_INPUT=1
"$venv/bin/python" -m pip install -q "$root" pytest pillow

# The installed package, not the build tree's, from outside the repository.
cd "$venv"
"$venv/bin/python" -c 'import geomesh, sys; sys.exit(0 if "site-packages" in geomesh.__file__ else 1)'
"$venv/bin/geomesh" -version
"$venv/bin/geomesh" "$root/tutorials/t1.geo" -2 -o "$venv/t1.msh" -v 2
test -s "$venv/t1.msh"
PYTHONDONTWRITEBYTECODE=1 "$venv/bin/python" -m pytest -q -p no:cacheprovider "$root/python/tests"
