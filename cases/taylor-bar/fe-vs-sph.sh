#!/usr/bin/env bash
# The Taylor bars of cases/ by finite elements (impactsph taylor-fe, verification/fe2d) and by SPH
# (impactsph run), beside the experiment: cases/taylor-bar/fe-vs-sph/report.md, one table per bar and one
# plot of the final profiles (profiles.png), written by fe_vs_sph.py from the runs' files kept in
# cases/taylor-bar/fe-vs-sph/runs/ (summary.json and profile.csv of each; an SPH run's profile is its last
# frame's outer particles). A run whose files are kept is not run again (remove its folder to rerun it).
#
#   bash cases/taylor-bar/fe-vs-sph.sh                    # FE at 8/16/32 across, SPH at 0.5/0.4/0.3 mm, every bar
#   SPH=skip bash cases/taylor-bar/fe-vs-sph.sh           # the finite elements only; SPH runs kept earlier stay
#   SPH_SPACINGS="0.5" bash cases/taylor-bar/fe-vs-sph.sh # SPH at these spacings only
#   CASES="cases/taylor-bar/case.toml" bash cases/taylor-bar/fe-vs-sph.sh
#
# The bars: every cases/*/case.toml whose [observables] names a taylor_bar (CASES overrides). Cost, measured
# on this project's two shared cores: the finite elements about 6 minutes for both bars (the bilinear's 32
# across 4.4 minutes of it); the SPH (the case's numerics) 74 s (bilinear) and 100 s (copper) at 0.5 mm on
# one thread; at 0.4 and 0.3 mm, by the particle-steps (h^-4: 2.4 and 7.7 times 0.5 mm's), about 3-4 and
# 10-13 minutes a bar, so about 35 minutes of SPH for both bars at all three spacings. THREADS (default 2)
# threads per SPH run; BUILD (default build) the build folder; RUNS (default runs/fe-vs-sph) where the runs
# write their frames.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
RUNS=${RUNS:-runs/fe-vs-sph}
SPH=${SPH:-run}
SPH_SPACINGS=${SPH_SPACINGS:-"0.5 0.4 0.3"}
MESHES=${MESHES:-"8 16 32"}
THREADS=${THREADS:-2}
OUT=cases/taylor-bar/fe-vs-sph
if [[ -z ${CASES:-} ]]; then
  CASES=$(grep -l '^taylor_bar *=' cases/*/case.toml)
fi
mkdir -p "$OUT/runs" "$OUT/expected"

for case in $CASES; do
  name=$(basename "$(dirname "$case")")
  cp "$(dirname "$case")/expected.toml" "$OUT/expected/$name.toml"
  for n in $MESHES; do
    run=$name-fe-$n
    if [[ ! -f $OUT/runs/$run/summary.json ]]; then
      echo "$run: running"
      nice -n 15 "$BUILD/impactsph" taylor-fe "$case" --elements-across "$n" --out "$RUNS/$run" --quiet > /dev/null
      mkdir -p "$OUT/runs/$run"
      cp "$RUNS/$run"/{summary.json,profile.csv} "$OUT/runs/$run/"
    fi
  done
  [[ $SPH == skip ]] && continue
  for s in $SPH_SPACINGS; do
    run=$name-sph-$s
    if [[ ! -f $OUT/runs/$run/summary.json ]]; then
      echo "$run: running"
      nice -n 15 "$BUILD/impactsph" run "$case" --spacing "${s}mm" --threads "$THREADS" --quiet --out "$RUNS/$run" \
        > /dev/null
      mkdir -p "$OUT/runs/$run"
      python3 cases/taylor-bar/fe_vs_sph.py profile "$RUNS/$run" "$OUT/runs/$run/profile.csv"
      cp "$RUNS/$run/summary.json" "$OUT/runs/$run/"
    fi
  done
done
python3 cases/taylor-bar/fe_vs_sph.py report "$OUT"
echo "report: $OUT/report.md"
