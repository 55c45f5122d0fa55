#!/usr/bin/env bash
# A plate's ballistic limit against the particle spacing, for the Weldox material file's failure
# criterion (the crack band, cases/materials/weldox-460e.toml) and for F's critical plastic strain 0.3
# (F eq 4.9), and with no failure at all (`no-damage`: the limit the plate's SPH discretisation gives when
# no particle fails, which bounds what any failure constant can reach). A model name ending in `-as` runs
# the same with the artificial stress against the tensile instability (numerics.artificial_stress = 0.3,
# deviatoric form; common/artificial_stress.hpp). One `impactsph ballistic-limit`
# search per criterion and spacing, then
# cases/PLATE/report-limit-vs-spacing/report.md and limit_vs_spacing.png (the limit against the
# spacing, the experiment's limit from cases/PLATE/expected.toml as a line with its +-3 % band where the
# case has one) from the searches' ballistic.json files: nothing typed in.
#
#   bash cases/plate-8mm/limit-vs-spacing.sh            # run the searches that are missing, then report
#   REPORT_ONLY=1 bash cases/plate-8mm/limit-vs-spacing.sh
#   PLATE=plate-12mm bash cases/plate-8mm/limit-vs-spacing.sh   # the 12 mm plate from its committed searches
#
# Environment: PLATE (the case folder, default plate-8mm), BUILD_DIR (default build), RUNS (default
# runs/limit-vs-spacing for the 8 mm plate, runs/limit-vs-spacing-PLATE otherwise), OUT (the report's
# folder, default cases/PLATE/report-limit-vs-spacing), CALIBRATION (default
# runs/weldox-calibration-*: the folders of the material file's calibration command, tabulated when
# present), BRACKET_RUNS (limits from runs made by hand, "model:DIR,DIR" per word: the highest speed
# that held and the lowest that perforated), SEARCH_FILES (searches made before, "model:PATH" per word,
# PATH a ballistic.json: the 12 mm plate's default is its committed reports), SEARCHES (default below:
# "criterion spacing_mm from_m_s to_m_s tolerance_m_s" per line; none for the 12 mm plate), JOBS
# (default 2), EXTRA_SETS (overrides given to every search, one KEY=VALUE per line, e.g. another
# artificial stress form or fracture energy; the report names them). CALIBRATION may also name
# ballistic.json files (committed copies; a glob such as DIR/calibration-*.json). Runs made by hand that
# all perforated give no limit: the slowest of them is drawn as a bound from above. A search whose
# ballistic.json exists is not run again (delete its folder, or give RUNS a new name after changing the
# code). A 2 mm search of the 8 mm plate takes a few minutes on two cores, a 1.333 mm one about half an
# hour; at 1 mm the calibration command of the material file is the search (about 25 minutes a round).
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-2}
EXE=$BUILD_DIR/impactsph
PLATE=${PLATE:-plate-8mm}
CASE=cases/$PLATE/case.toml
[[ -f "$CASE" ]] || { echo "limit-vs-spacing: no $CASE (PLATE names a folder of cases/)" >&2; exit 2; }
OUT=${OUT:-cases/$PLATE/report-limit-vs-spacing}
ARTIFICIAL_STRESS='numerics.artificial_stress=0.3'
F49='weldox-460e.damage={ kind = "critical-plastic-strain", critical_plastic_strain = 0.3 }'
NO_DAMAGE='weldox-460e.damage={ kind = "none" }'
SEARCH_FILES_GIVEN=${SEARCH_FILES+given}   # the caller named the searches (the report's command then names them)
if [[ "$PLATE" == plate-8mm ]]; then
  RUNS=${RUNS:-runs/limit-vs-spacing}
  SEARCHES=${SEARCHES-"fracture-energy 2 100 190 3
critical-strain 2 100 190 3
no-damage 2 150 195 3
fracture-energy 1.333 100 190 3
no-damage 1.333 120 190 3"}
  SEARCH_FILES=${SEARCH_FILES:-}
else
  RUNS=${RUNS:-runs/limit-vs-spacing-$PLATE}
  SEARCHES=${SEARCHES:-}
fi
if [[ "$PLATE" == plate-12mm ]]; then
  SEARCH_FILES=${SEARCH_FILES-"fracture-energy:cases/plate-12mm/report-2mm-crack-band/ballistic.json
fracture-energy:cases/plate-12mm/report-1mm-crack-band/ballistic.json
critical-strain-78523bb:cases/plate-12mm/report-2mm/ballistic.json"}
fi
CALIBRATION=${CALIBRATION:-runs/weldox-calibration-*}
mkdir -p "$RUNS" "$OUT"

if [[ -z "${REPORT_ONLY:-}" ]]; then
  while read -r model spacing from to tol; do
    [[ -z "$model" ]] && continue
    dir="$RUNS/$model-${spacing}mm"
    [[ -f "$dir/ballistic.json" ]] && continue
    extra=()
    [[ "${model%-as}" == "critical-strain" ]] && extra=(--set "$F49")
    [[ "${model%-as}" == "no-damage" ]] && extra=(--set "$NO_DAMAGE")
    [[ "$model" == *-as ]] && extra+=(--set "$ARTIFICIAL_STRESS")
    while IFS= read -r override; do
      [[ -n "$override" ]] && extra+=(--set "$override")
    done <<< "${EXTRA_SETS:-}"
    echo "limit-vs-spacing: $model at $spacing mm, $from to $to m/s"
    "$EXE" ballistic-limit "$CASE" --spacing "${spacing}mm" --from "$from" --to "$to" --tolerance "$tol" \
      --jobs "$JOBS" --quiet --set output.vtu=false "${extra[@]}" --out "$dir" > "$dir.log" 2>&1 ||
      echo "limit-vs-spacing: $model at $spacing mm did not bracket the limit (see $dir.log)"
  done <<< "$SEARCHES"
fi

COMMAND="bash cases/plate-8mm/limit-vs-spacing.sh"
[[ "$PLATE" != plate-8mm ]] && COMMAND="PLATE=$PLATE $COMMAND"
[[ "$OUT" != "cases/$PLATE/report-limit-vs-spacing" ]] && COMMAND="OUT=$OUT RUNS=$RUNS SEARCHES=... $COMMAND"
[[ -n "${EXTRA_SETS:-}" ]] && COMMAND="EXTRA_SETS=... $COMMAND"
[[ -n "${BRACKET_RUNS:-}" ]] && COMMAND="BRACKET_RUNS=\"$BRACKET_RUNS\" $COMMAND"
[[ -n "$SEARCH_FILES_GIVEN" && -n "${SEARCH_FILES:-}" ]] && COMMAND="SEARCH_FILES=\"$(echo $SEARCH_FILES)\" $COMMAND"
[[ "$CALIBRATION" == *.json ]] && COMMAND="CALIBRATION=$CALIBRATION $COMMAND"
[[ -n "${REPORT_ONLY:-}" ]] && COMMAND="REPORT_ONLY=1 $COMMAND"
COMMAND="$COMMAND" SEARCH_FILES="${SEARCH_FILES:-}" python3 - "$RUNS" "$OUT" "$(git rev-parse --short HEAD)" \
  "$CALIBRATION" "$PLATE" <<'PY'
import glob, json, os, shlex, subprocess, sys, tomllib
sys.path.insert(0, 'cases/plate-8mm')
from plate_runs import read_run, recht_ipson_p2_limit, user_command

runs, out, commit, calibration, plate = sys.argv[1:6]
# The experiment's ballistic limit (m/s) where the case states one in its expected.toml, else None.
experiment = None
expected_file = os.path.join('cases', plate, 'expected.toml')
if os.path.isfile(expected_file):
    value = tomllib.load(open(expected_file, 'rb')).get('ballistic_limit', {}).get('value')
    if value:
        number, unit = value.split()
        if unit != 'm/s':
            sys.exit('limit-vs-spacing: %s: ballistic_limit.value "%s": expected a speed in m/s' % (expected_file, value))
        experiment = float(number)
title_plate = plate.replace('plate-', '').replace('mm', ' mm')
rows = []
for item in os.environ.get('SEARCH_FILES', '').split():
    model, path = item.split(':', 1)
    b = json.load(open(path))
    b['report'] = os.path.dirname(path)
    rows.append((model, b['spacing_m'] * 1e3, b, sum(r.get('wall_s', 0.0) for r in b['runs'])))
for name in sorted(os.listdir(runs)):
    path = os.path.join(runs, name, 'ballistic.json')
    if not os.path.isfile(path):
        continue
    b = json.load(open(path))
    model = name.rsplit('-', 1)[0]
    wall = sum(r.get('wall_s', 0.0) for r in b['runs'])
    rows.append((model, b['spacing_m'] * 1e3, b, wall))
# BRACKET_RUNS: limits from single runs made by hand ("model:DIR,DIR,..." per word, DIR a run folder):
# the highest speed that held and the lowest that perforated, read from each run's summary.json.
for item in os.environ.get('BRACKET_RUNS', '').split():
    model, dirs = item.split(':', 1)
    b = {'runs': [], 'status': 'done', 'command_line': []}
    for d in dirs.split(','):
        r = read_run(d)
        b['spacing_m'] = r['spacing'] * 1e-3
        b['runs'].append({'v_impact_m_s': r['v0'], 'perforated': r['perforated'], 'residual_velocity_m_s': r['vr'],
                          'plug_mass_kg': r['plug'] * 1e-3, 'plug_velocity_m_s': r['plug_v'],
                          'settled_time_s': r['settled'], 'wall_s': r['wall']})
        b['command_line'].append(user_command(d))
    held = [r['v_impact_m_s'] for r in b['runs'] if not r['perforated']]
    through = [r['v_impact_m_s'] for r in b['runs'] if r['perforated']]
    b['command_line'] = ' ; '.join(b['command_line'])
    if held and through and max(held) < min(through):
        b['bracket_m_s'] = [max(held), min(through)]
        b['limit_m_s'] = 0.5 * (max(held) + min(through))
    else:
        b['status'] = ('every run perforated' if not held else 'no run perforated' if not through
                       else 'verdicts not monotonic')
    rows.append((model, b['spacing_m'] * 1e3, b, sum(r['wall_s'] for r in b['runs'])))
rows.sort(key=lambda r: (r[0], -r[1]))
if not rows:
    sys.exit('limit-vs-spacing: no searches in %s and none in SEARCH_FILES: nothing to report' % runs)

def recht_ipson_p2(b):
    """v_bl of the p = 2 Recht-Ipson curve through the search's two slowest perforating runs (m/s), or None."""
    return recht_ipson_p2_limit([(r['v_impact_m_s'], r['residual_velocity_m_s']) for r in b['runs'] if r.get('perforated')])

against = 'against %.1f m/s' % experiment if experiment else 'against the experiment'
lines = ['# %s plate: the ballistic limit against the spacing' % title_plate, '',
         'Generated by `%s` at commit %s from the searches in %s '
         '(`impactsph ballistic-limit`, one per criterion and spacing; each search\'s command line is below the '
         'table). `nonlocal` is the non-local fracture energy of cases/materials/weldox-460e.toml (the plate cases\' '
         'criterion since it was built for issue 15), `fracture-energy` the crack band that came before it '
         '(band_width_factor = 2.6), '
         '`critical-strain` F\'s eq 4.9 with eps_c = 0.3 set over it, `no-damage` no failure model at all; a name ending in '
         '`-as` is the same with the artificial stress (`numerics.artificial_stress=0.3`), which the case file has '
         'set by default since the fracture energy was calibrated under it. A search taken from a report (SEARCH_FILES) names '
         'its report after its command line; a name ending in a commit was run with the code of that commit, before '
         'the crack band and the artificial stress. %s' % (os.environ['COMMAND'], commit, runs,
         'The experiment: %.1f m/s (%s).' % (experiment, expected_file) if experiment else
         'The case states no experimental ballistic limit (%s has none): the limits are a prediction.' % expected_file),
         '', '![limit against spacing](limit_vs_spacing.png)', '',
         '| criterion | spacing | limit | bracket | %s | Recht-Ipson p = 2 through the two slowest perforating runs | runs | wall s (sum of runs) |',
         '|---|---|---|---|---|---|---|---|']
lines[-2] = lines[-2] % against
extra_sets = [x for x in os.environ.get('EXTRA_SETS', '').splitlines() if x.strip()]
if extra_sets:
    lines[2] += (' Every search of this report ran with these overrides on top of the case and material files of '
                 'its time (EXTRA_SETS), so its figures are the case file\'s only where the case and material files '
                 'hold the same values: %s.' % ', '.join('`%s`' % x for x in extra_sets))
def relative(v):
    return '%+.1f %%' % (100 * (v / experiment - 1)) if experiment else ''
def estimate_cell(b):
    e = recht_ipson_p2(b)
    return ('%.1f m/s (%s)' % (e, relative(e)) if experiment else '%.1f m/s' % e) if e else ''
for model, s, b, wall in rows:
    if b.get('limit_m_s') is None:
        lines.append('| %s | %.3g mm | not bracketed (%s) | | | %s | %d | %.0f |' % (
            model, s, b.get('status', '?'), estimate_cell(b), len(b['runs']), wall))
        continue
    lo, hi = b['bracket_m_s']
    unfinished = '' if b.get('status') == 'done' else ' (search %s: the bracket so far)' % b.get('status')
    lines.append('| %s | %.3g mm | %.1f m/s%s | %.2f-%.2f m/s | %s | %s | %d | %.0f |' % (
        model, s, b['limit_m_s'], unfinished, lo, hi, relative(b['limit_m_s']), estimate_cell(b),
        len(b['runs']), wall))
lines += ['', 'Perforating runs (impact speed: residual velocity; plug mass and speed):', '']
for model, s, b, wall in rows:
    perf = [r for r in b['runs'] if r.get('perforated')]
    items = ['%.2f: %.1f m/s%s (%.1f g at %.1f m/s)' % (
        r['v_impact_m_s'], r['residual_velocity_m_s'], '' if r.get('settled_time_s') else ', not settled by the end',
        r['plug_mass_kg'] * 1e3, r['plug_velocity_m_s']) for r in perf]
    lines.append('- %s at %.3g mm: %s' % (model, s, '; '.join(items) if items else 'none'))
lines += ['', 'Searches:', '']
for model, s, b, wall in rows:
    cl = b['command_line'] if isinstance(b['command_line'], str) else shlex.join(b['command_line'])
    lines.append('- %s at %.3g mm: `%s`%s' % (model, s, cl, ' (report: %s)' % b['report'] if 'report' in b else ''))
if calibration.endswith('.json') and not glob.glob(calibration):
    sys.exit('limit-vs-spacing: CALIBRATION=%s: no such file (a ballistic.json or a glob of them, or folders '
             'holding one)' % calibration)
cal = sorted(glob.glob(calibration if calibration.endswith('.json') else os.path.join(calibration, 'ballistic.json')))
if cal:
    lines += ['', 'The calibration command of cases/materials/weldox-460e.toml (1 mm, 149.5 and 155.5 m/s) at the '
              'Gammas tried, from %s:' % calibration, '',
              '| overrides | status | runs (impact speed: perforated, residual velocity, plug, wall) |', '|---|---|---|']
    for path in cal:
        b = json.load(open(path))
        items = ['%.2f: %s, %.0f s' % (r['v_impact_m_s'], r['error'], r['wall_s']) if 'error' in r else
                 '%.2f: %s, %.1f m/s, %.1f g, %.0f s' % (r['v_impact_m_s'], 'yes' if r.get('perforated') else 'no',
                                                        r['residual_velocity_m_s'], 1e3 * r['plug_mass_kg'], r['wall_s'])
                 for r in b['runs'] if 'v_impact_m_s' in r]
        lines.append('| %s | %s | %s |' % (', '.join('`%s`' % x for x in b['set']), b['status'], '; '.join(items)))
open(os.path.join(out, 'report.md'), 'w').write('\n'.join(lines) + '\n')

def upper_bound(b):
    """The slowest run where every run perforated and no limit was found (the limit lies below it), else None."""
    if b.get('limit_m_s') is not None or not b['runs'] or not all(r.get('perforated') for r in b['runs']):
        return None
    return min(r['v_impact_m_s'] for r in b['runs'])


def bracket_columns(b):
    """limit, bracket low and high (m/s) of a bracketed search, else None."""
    return (b['limit_m_s'], *b['bracket_m_s']) if b.get('limit_m_s') is not None else None


def estimate_columns(b):
    e = recht_ipson_p2(b)
    return (e,) if e else None


def bound_columns(b):
    u = upper_bound(b)
    return (u,) if u else None


data = os.path.join(out, 'limit_vs_spacing.dat')
with open(data, 'w') as f:
    # Per kind of point, one gnuplot index block per model (the plot below counts them in this order).
    for title, columns in (('%s', bracket_columns),
                           ('%s, Recht-Ipson p = 2 through the two slowest perforating runs', estimate_columns),
                           ('%s, every run perforated: the slowest of them (the limit lies below)', bound_columns)):
        for model in sorted({r[0] for r in rows}):
            f.write('# ' + title % model + '\n')
            for m, s, b, wall in rows:
                if m == model and columns(b):
                    f.write(' '.join(['%.4f' % s] + ['%.3f' % v for v in columns(b)]) + '\n')
            f.write('\n\n')
models = sorted({r[0] for r in rows})
plots = []
if experiment:
    plots = ['%.1f*0.97 with filledcurves y1=%.1f*1.03 fc rgb "#dddddd" title "experiment +-3 %%"' % (experiment, experiment),
             '%.1f with lines dt 2 lc rgb "black" title "experiment %.1f m/s"' % (experiment, experiment)]
limits = [b['limit_m_s'] for m, s, b, wall in rows if b.get('limit_m_s')] + ([experiment] if experiment else [])
limits += [upper_bound(b) for m, s, b, wall in rows if upper_bound(b)]
low, high = 20 * int(min(limits) / 20 - 1), 20 * int(max(limits) / 20 + 2)
for k, model in enumerate(models):
    plots.append('"%s" index %d using 1:2:3:4 with yerrorlines pt 7 lc %d title "%s"' % (os.path.basename(data), k, k + 1, model))
    plots.append('"%s" index %d using 1:2 with points pt 6 ps 1.5 lc %d title "%s, Recht-Ipson p = 2 estimate"' % (
        os.path.basename(data), len(models) + k, k + 1, model))
    if any(m == model and upper_bound(b) for m, s, b, wall in rows):
        plots.append('"%s" index %d using 1:2 with points pt 11 ps 2 lc %d title "%s, every run perforated: limit below"' % (
            os.path.basename(data), 2 * len(models) + k, k + 1, model))
script = '\n'.join([
    'set terminal pngcairo size 800,560',
    'set output "limit_vs_spacing.png"',
    'set xlabel "particle spacing [mm]"', 'set ylabel "ballistic limit [m/s]"',
    'set title "%s Weldox 460 E plate, 197 g blunt projectile"' % title_plate,
    'set xrange [0:2.2]', 'set yrange [%d:%d]' % (low, high), 'set key bottom left', 'set grid',
    'plot ' + ', '.join(plots)]) + '\n'
open(os.path.join(out, 'limit_vs_spacing.gp'), 'w').write(script)
try:
    subprocess.run(['gnuplot', 'limit_vs_spacing.gp'], cwd=out, check=True)
except (OSError, subprocess.CalledProcessError) as e:
    print('limit-vs-spacing: no PNG (%s); install gnuplot' % e)
print('limit-vs-spacing: wrote %s/report.md' % out)
PY
