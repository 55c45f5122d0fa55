#!/usr/bin/env bash
# The 8 mm plate at one resolution and at two (issue 18): the plate within a radius of the axis at the case's
# spacing and its rim at RATIO times coarser ([bodies.coarse], docs/case-files.md), for each radius of
# RADII, at each impact speed of VELOCITIES; with LIMIT="FROM TO" also the ballistic limit of each form
# (`impactsph ballistic-limit`, 3 m/s, one run at a time). Then OUT/report.md from the runs' summary.json
# and ballistic.json files: residual velocity of each form and its difference from one resolution, plug,
# particle count, steps and wall time, the limits and the time to each. Nothing typed in.
#
#   bash cases/plate-8mm/two-resolutions.sh                      # 1 mm, 298 and 175 m/s, radius 30 mm
#   SPACING=2mm RADII="30 45" VELOCITIES="298 175 160" LIMIT="140 170" bash cases/plate-8mm/two-resolutions.sh
#   REPORT_ONLY=1 SPACING=2mm bash cases/plate-8mm/two-resolutions.sh
#
# Environment: BUILD_DIR (default build), SPACING (default 1mm), VELOCITIES (default "298 175", m/s),
# RADII (default "30", mm), RATIO (default 2), LIMIT (default none: "FROM TO" in m/s),
# RUNS (default runs/plate-8mm-two-resolutions-SPACING), OUT (default
# cases/plate-8mm/report-two-resolutions-SPACING), TIMING (default none: an end time such as 40us, for which
# each form runs again at the first of VELOCITIES, one after the other, for the report's wall-time
# comparison under the same load; run it with the machine otherwise as it will be for all forms).
# Runs that finished are kept; one thread each, in turn.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${BUILD_DIR:-build}
SPACING=${SPACING:-1mm}
VELOCITIES=${VELOCITIES:-298 175}
RADII=${RADII:-30}
RATIO=${RATIO:-2}
LIMIT=${LIMIT:-}
RUNS=${RUNS:-runs/plate-8mm-two-resolutions-$SPACING}
OUT=${OUT:-cases/plate-8mm/report-two-resolutions-$SPACING}
mkdir -p "$OUT" "$RUNS"

coarse() { echo "plate.coarse={ratio=$RATIO, region=\"outside-cylinder\", axis=\"z\", axis_point=[\"0 mm\",\"0 mm\",\"0 mm\"], radius=\"$1 mm\"}"; }
finished() { [[ -f "$1" ]] && python3 -c "import json,sys; sys.exit(0 if json.load(open('$1')).get('completed', True) else 1)"; }

if [[ -z "${REPORT_ONLY:-}" ]]; then
  forms=(uniform)
  for r in $RADII; do forms+=("r$r"); done
  for form in "${forms[@]}"; do
    extra=()
    [[ $form != uniform ]] && extra=(--set "$(coarse "${form#r}")")
    for v in $VELOCITIES; do
      dir="$RUNS/$form-$v"
      finished "$dir/summary.json" && continue
      echo "two-resolutions: $form at $v m/s, spacing $SPACING -> $dir"
      "$BUILD_DIR/impactsph" run cases/plate-8mm/case.toml --spacing "$SPACING" --threads 1 -q \
        --set "projectile.velocity=$v m/s" --set output.vtu=false "${extra[@]}" --out "$dir" > "$dir.log" 2>&1
    done
    if [[ -n "$LIMIT" ]]; then
      dir="$RUNS/limit-$form"
      python3 -c "import json,sys; sys.exit(0 if json.load(open('$dir/ballistic.json')).get('status') == 'done' else 1)" \
        2>/dev/null && continue
      read -r from to <<< "$LIMIT"
      echo "two-resolutions: ballistic limit, $form, spacing $SPACING -> $dir"
      "$BUILD_DIR/impactsph" ballistic-limit cases/plate-8mm/case.toml --spacing "$SPACING" --from "$from" --to "$to" \
        --tolerance 3 --jobs 1 -q --set output.vtu=false "${extra[@]}" --out "$dir" > "$dir.log" 2>&1
    fi
  done
  if [[ -n "${TIMING:-}" ]]; then
    v=${VELOCITIES%% *}
    for form in "${forms[@]}"; do
      extra=()
      [[ $form != uniform ]] && extra=(--set "$(coarse "${form#r}")")
      dir="$RUNS/timing-$form"
      finished "$dir/summary.json" && continue
      echo "two-resolutions: timing, $form at $v m/s to $TIMING, spacing $SPACING -> $dir"
      "$BUILD_DIR/impactsph" run cases/plate-8mm/case.toml --spacing "$SPACING" --threads 1 -q \
        --set "projectile.velocity=$v m/s" --set output.vtu=false --set "time.end=$TIMING" "${extra[@]}" \
        --out "$dir" > "$dir.log" 2>&1
    done
  fi
fi

python3 - "$RUNS" "$OUT" "$(git rev-parse --short HEAD)" "$RATIO" <<'PY'
import glob, json, os, sys
sys.path.insert(0, 'cases/plate-8mm')
from plate_runs import read_run

runs, out, commit, ratio = sys.argv[1:5]
rows = {}   # speed -> form -> run
for path in sorted(glob.glob(os.path.join(runs, '*', 'summary.json'))):
    name = os.path.basename(os.path.dirname(path))
    if name.startswith('limit-') or name.startswith('timing-'):
        continue
    r = read_run(path)
    if r is None or not r['completed']:
        continue
    form, v = name.rsplit('-', 1)
    s = json.load(open(path))
    plate = [b for b in s['bodies'] if b['name'] == 'plate'][0]
    r['coarse'] = plate['generated'].get('coarse_particles', 0)
    rows.setdefault(float(v), {})[form] = r
if not rows:
    sys.exit('two-resolutions: no finished runs in %s' % runs)
forms = sorted({f for p in rows.values() for f in p if f != 'uniform'}, key=lambda f: float(f[1:]))
name = lambda f: 'one resolution' if f == 'uniform' else 'rim beyond %s mm coarse' % f[1:]
spacing = next(iter(next(iter(rows.values())).values()))['spacing']
L = ['# 8 mm plate at one resolution and at two (spacing %g mm)' % spacing, '',
     'Generated by `bash cases/plate-8mm/two-resolutions.sh` at commit %s from the runs\' summary.json and '
     'ballistic.json files (%s). The case as it stands at spacing %g mm, and with `[bodies.coarse]` on the '
     'plate: its rim beyond a radius of the impact axis at %s times the spacing (the command line of each run '
     'is in its summary.json). One thread per run; wall times are of runs that may have shared the machine.'
     % (commit, runs, spacing, ratio), '',
     '| impact | plate | residual | against one resolution | plug | particles (coarse) | steps | wall | energy drift |',
     '|---|---|---|---|---|---|---|---|---|']
for v in sorted(rows, reverse=True):
    p = rows[v]
    ref = p.get('uniform')
    for f in ['uniform'] + forms:
        if f not in p:
            continue
        r = p[f]
        diff = '%+.2f %%' % (100 * (r['vr'] / ref['vr'] - 1)) if ref and f != 'uniform' and ref['vr'] > 0 else ''
        plug = '%.2f g at %.1f m/s' % (r['plug'], r['plug_v']) if r['perforated'] else 'none'
        L.append('| %g m/s | %s | %.2f m/s | %s | %s | %d (%d) | %d | %.0f s | %.3f %% |' % (
            v, name(f), r['vr'], diff, plug, r['particles'], r['coarse'], r['steps'], r['wall'], 100 * r['drift']))
limits = []
for f in ['uniform'] + forms:
    path = os.path.join(runs, 'limit-' + f, 'ballistic.json')
    if not os.path.exists(path):
        continue
    b = json.load(open(path))
    if b.get('status') != 'done':
        continue  # still running
    limits.append((f, b, sum(r['wall_s'] for r in b['runs'])))
if limits:
    L += ['', '## Ballistic limit', '', '| plate | bracket | limit | runs | time to the limit (its runs\' wall times, one at a time) |',
          '|---|---|---|---|---|']
    for f, b, wall in limits:
        lo, hi = b['bracket_m_s']
        L.append('| %s | %.2f - %.2f m/s | %.1f m/s | %d | %.1f min |' % (
            name(f), lo, hi, b['limit_m_s'], len(b['runs']), wall / 60))
timings = []
for path in sorted(glob.glob(os.path.join(runs, 'timing-*', 'summary.json'))):
    t = json.load(open(path))
    if t.get('completed'):
        timings.append((os.path.basename(os.path.dirname(path))[len('timing-'):], t))
if timings:
    base = dict(timings).get('uniform')
    L += ['', '## Wall time under the same load', '',
          'Each form at %g m/s to %.0f us, one thread, run one after the other with the machine as it was for all '
          'of them (TIMING in two-resolutions.sh).' % (read_run(os.path.join(runs, 'timing-' + timings[0][0]))['v0'],
                                                        1e6 * timings[0][1]['simulated_time_s']), '',
          '| plate | particles | steps | wall | particle-steps/s | mean neighbours | wall against one resolution |',
          '|---|---|---|---|---|---|---|']
    for f, t in sorted(timings, key=lambda ft: (ft[0] != 'uniform', ft[0])):
        ratio = '%.2f' % (t['wall_time_s'] / base['wall_time_s']) if base else ''
        L.append('| %s | %d | %d | %.0f s | %.3g | %.1f | %s |' % (
            name(f), t['particles'], t['steps'], t['wall_time_s'], t['particles'] * t['steps'] / t['wall_time_s'],
            t['mean_neighbours'], ratio))
L += ['', 'Target (issue 18): the residual velocity at 298 and 175 m/s within 1 % of the run at one resolution.', '',
      'The fine part of a two-resolution plate is its one-resolution lattice point for point: the rim is that '
      'lattice with its complete blocks of 2 x 2 x 2 cells merged (fcc0d45), so a difference from one resolution '
      'is the coarse rim\'s own. At spacing dx the rim\'s cells are 2 dx, 8 mm / (2 dx) of them through the plate. '
      'A rim beyond 56 mm coarsens little more than the clamped ring (beyond 57 mm).']
calibration = sorted(v for v, p in rows.items() if 'uniform' in p and 'weldox-calibration' in p['uniform']['command_line'])
if calibration:
    L[-1] += (' The one-resolution runs at %s m/s are the calibration runs of the Weldox fracture energy (their '
              'summary.json copied from cases/plate-8mm/report-calibrated/fracture-energy-1mm-V; one thread).'
              % ' and '.join('%g' % v for v in calibration))
L.append('')
open(os.path.join(out, 'report.md'), 'w').write('\n'.join(L))
print('\n'.join(L))
PY
