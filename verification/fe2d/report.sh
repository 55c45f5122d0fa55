#!/usr/bin/env bash
# The finite-element Taylor bars of verification/reports/fe2d/report.md: runs `impactsph taylor-fe` on the
# bilinear benchmark and the OFHC copper bar over the meshes, the numerics' sensitivity at 16 elements
# across, the copper without its rate term, and the elastic bar of cases/wall-rebound; keeps each run's
# summary.json, profile.csv and history.csv (and the finest runs' pictures) in the report folder, then writes
# report.md with verification/fe2d/report.py. A run whose summary.json is already in the report folder is not
# run again (remove it to rerun).
#   bash verification/fe2d/report.sh                     # meshes 8, 16, 32 across: about 10 minutes on one core
#   MESHES="8 16 32 64" bash verification/fe2d/report.sh  # about 55 minutes, most of it the 64-across bilinear
# BUILD (default build) is the build folder, RUNS (default runs/fe2d-report) where the runs write.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
RUNS=${RUNS:-runs/fe2d-report}
MESHES=${MESHES:-"8 16 32"}
REPORT=verification/reports/fe2d
mkdir -p "$REPORT/runs" "$REPORT/expected"
cp cases/taylor-bar-bilinear/expected.toml "$REPORT/expected/taylor-bar-bilinear.toml"
cp cases/taylor-bar/expected.toml "$REPORT/expected/taylor-bar.toml"

finest=$(echo $MESHES | tr ' ' '\n' | sort -n | tail -1)
# run NAME CASE ELEMENTS_ACROSS [OPTION...]
run() {
  local name=$1 case=$2 n=$3
  shift 3
  if [[ -f "$REPORT/runs/$name/summary.json" ]]; then
    echo "$name: kept"
    return
  fi
  echo "$name: running"
  nice -n 15 "$BUILD/impactsph" taylor-fe "$case" --elements-across "$n" --out "$RUNS/$name" --quiet "$@"
  mkdir -p "$REPORT/runs/$name"
  cp "$RUNS/$name"/{profile.csv,history.csv,summary.json} "$REPORT/runs/$name/"
  if [[ $n == "$finest" && $# -eq 0 ]]; then cp "$RUNS/$name/picture.png" "$REPORT/picture-$name.png"; fi
}

for n in $MESHES; do
  run "copper-$n" cases/taylor-bar/case.toml "$n"
  run "bilinear-$n" cases/taylor-bar-bilinear/case.toml "$n"
done
run bilinear-16-hourglass-0.02 cases/taylor-bar-bilinear/case.toml 16 --hourglass 0.02
run bilinear-16-hourglass-0.1 cases/taylor-bar-bilinear/case.toml 16 --hourglass 0.1
run bilinear-16-cfl-0.3 cases/taylor-bar-bilinear/case.toml 16 --cfl 0.3
run copper-16-c-0 cases/taylor-bar/case.toml 16 --set 'materials.ofhc-copper.strength.c=0'
run wall-rebound-16 cases/wall-rebound/case.toml 16
python3 verification/fe2d/report.py "$REPORT"
