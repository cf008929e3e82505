#!/usr/bin/env bash
# Regenerates tutorials/pictures/NAME.png, 640x480, for every tutorial with a golden
# expectation (tests/golden/tutorials/NAME.expected), meshed with the arguments listed there,
# as the test TutorialPicture.IsUpToDate renders it.
#
#     scripts/tutorial-pictures.sh [path/to/geomesh]     (default: build/bin/geomesh)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
geomesh=${1:-$root/build/bin/geomesh}
if [[ ! -x $geomesh ]]; then
  echo "tutorial-pictures.sh: no geomesh at '$geomesh' (build it, or give its path)" >&2
  exit 1
fi
mkdir -p "$root/tutorials/pictures"

for expected in "$root"/tests/golden/tutorials/*.expected; do
  name=$(basename "$expected" .expected)
  if grep -Eq '^exit: *[1-9]' "$expected"; then continue; fi
  read -r -a args <<<"$(sed -n 's/^args: *//p' "$expected")"
  picture=$root/tutorials/pictures/$name.png
  "$geomesh" "$root/tutorials/$name.geo" "${args[@]}" -v 1 -o "$picture" \
    -setnumber Print.Width 640 -setnumber Print.Height 480
  echo "$name: $(stat -c %s "$picture") bytes"
done

# The Python tutorials write their own pictures (800x600, the default size) into the current
# directory; they need the module of the build next to the geomesh given.
python_package=$(dirname "$geomesh")/../python
if [[ -d $python_package/geomesh ]]; then
  work=$(mktemp -d)
  for tutorial in "$root"/tutorials/python_*.py; do
    name=$(basename "$tutorial" .py)
    (cd "$work" && PYTHONPATH=$python_package /usr/bin/python3 "$tutorial" > /dev/null)
    cp "$work/$name.png" "$root/tutorials/pictures/$name.png"
    echo "$name: $(stat -c %s "$root/tutorials/pictures/$name.png") bytes"
  done
  rm -rf "$work"
fi
