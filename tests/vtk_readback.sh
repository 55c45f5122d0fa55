#!/usr/bin/env bash
# cli.vtk_readback: a short plate run, then verification/vtk_readback.py reads its particles.pvd and every
# frame with VTK's own readers and checks them against summary.json. Exits 77 (CTest: skipped) when the
# Python given has no VTK.
#   vtk_readback.sh IMPACTSPH CASE PYTHON SCRIPT OUT
set -euo pipefail
exe=$1 case=$2 python=$3 script=$4 out=$5
if ! "$python" -c "import vtkmodules.vtkIOXML" 2>/dev/null; then
  echo "skipped: $python cannot import VTK; install it with \`sudo apt-get install python3-vtk9\` (Debian, Ubuntu)"
  exit 77
fi
rm -rf "$out"
"$exe" run "$case" --spacing 4mm --set time.end=30us --set time.output_interval=2us --set time.frame_interval=10us \
  --set output.picture=false --out "$out" --quiet
"$python" "$script" "$out"
# A damaged frame must fail the check: cut the last frame in half.
last=$(ls "$out"/particles_*.vtu | tail -n 1)
truncate -s $(( $(stat -c %s "$last") / 2 )) "$last"
if "$python" "$script" "$out" > "$out.broken.log" 2>&1; then
  echo "vtk_readback.py passed a truncated frame ($last):"; cat "$out.broken.log"; exit 1
fi
grep -q "VTK could not read it" "$out.broken.log" || { echo "unexpected message:"; cat "$out.broken.log"; exit 1; }
echo "a truncated frame is refused: $(head -n 1 "$out.broken.log" | cut -c1-160)"
