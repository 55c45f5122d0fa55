#!/usr/bin/env bash
# cli.run_picture: a run draws picture.png (a PNG, with picture.gp and picture.dat to redraw it) when
# gnuplot is there, says so in one warning line and still succeeds when it is not, and draws nothing with
# output.picture = false; a body at two resolutions is drawn with both. The first part exits 77 (CTest:
# skipped) without gnuplot, after the others ran.
#   run_picture.sh IMPACTSPH CASE OUT
set -euo pipefail
exe=$1 case=$2 out=$3
short=(--spacing 4mm --set time.end=20us --set time.output_interval=2us --set time.frame_interval=20us --quiet)
rm -rf "$out" && mkdir -p "$out"

"$exe" run "$case" "${short[@]}" --set output.picture=false --out "$out/off"
for f in picture.png picture.gp picture.dat; do
  [[ ! -e "$out/off/$f" ]] || { echo "output.picture = false wrote $f"; exit 1; }
done

# Without gnuplot on PATH (the executable is called by its full path): a warning, exit status 0, no PNG.
env PATH=/nonexistent "$exe" run "$case" "${short[@]}" --out "$out/no-gnuplot" 2> "$out/no-gnuplot.err"
grep -q "^warning: picture.png not drawn: gnuplot is not installed" "$out/no-gnuplot.err" ||
  { echo "no warning about gnuplot:"; cat "$out/no-gnuplot.err"; exit 1; }
[[ ! -e "$out/no-gnuplot/picture.png" && -s "$out/no-gnuplot/picture.gp" ]] ||
  { echo "without gnuplot: expected picture.gp and no picture.png"; ls "$out/no-gnuplot"; exit 1; }

# A plate with a coarse rim (two resolutions): the rim's particles are drawn from their own layer with their
# own cells (2 mm half width at 2 mm x 2), not left out of the cut.
env PATH=/nonexistent "$exe" run "$case" --spacing 2mm --set time.end=2us --set time.output_interval=1us \
  --set time.frame_interval=2us --set output.vtu=false --quiet --out "$out/rim" \
  --set 'plate.coarse={ratio=2, region="outside-cylinder", axis="z", axis_point=["0 mm","0 mm","0 mm"], radius="30 mm"}' \
  2> "$out/rim.err" || { echo "the run with a coarse rim failed:"; cat "$out/rim.err"; exit 1; }
rim=$(awk '!/^#/ && NF == 5 && $3 > 1.9 && ($1 > 30 || $1 < -30)' "$out/rim/picture.dat" | wc -l)
(( rim > 0 )) || { echo "the coarse rim is missing from the cut ($out/rim/picture.dat)"; exit 1; }

if ! command -v gnuplot > /dev/null; then
  echo "skipped the drawing: gnuplot is not installed (sudo apt-get install gnuplot-nox)"
  exit 77
fi
"$exe" run "$case" "${short[@]}" --out "$out/on"
png=$out/on/picture.png
[[ -s "$png" && -s "$out/on/picture.gp" && -s "$out/on/picture.dat" ]] || { echo "missing picture files"; ls "$out/on"; exit 1; }
[[ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" == "89504e470d0a1a0a" ]] || { echo "$png is not a PNG"; exit 1; }
ls "$out/on" | grep -q '\.tmp-' && { echo "temporary files left in $out/on"; exit 1; }
echo "picture.png: $(stat -c %s "$png") bytes"
