#!/usr/bin/env bash
# The mechanism check of issue 15: how the 8 mm plate fails at 190.7 m/s (F's scenario 8) at each spacing.
# One `impactsph run` per spacing to 160 us (END) with a frame every 4 us, then report-mechanism/report.md from
# the runs' frames, history_plate.csv and observables.csv: nothing typed in.
#
#   bash cases/plate-8mm/mechanism.sh                 # the runs that are missing, then the report
#   SPACINGS="2 1.333" bash cases/plate-8mm/mechanism.sh
#
# Per spacing, at the first failure (the first history row, 2 us apart, with a failed plate particle,
# D >= 0.99) and at separation (the first row of observables.csv with a plug cut off the clamped plate,
# common/case_observables.cpp):
#   - the plug's displacement against the plate: the mean axial position of the plate particles within
#     half the projectile radius of the axis against those of a ring 1.4-1.6 radii out (shear_band.py's
#     plug_displacement), read from the frames and interpolated linearly to the event's time;
#   - the plate's plastic work, sum m w_p over the plate (whole plate: the quarter model times 4);
#   - the share of the energy the plate took (internal + kinetic) that is internal energy but not plastic
#     work: the artificial viscosity's heat and the stored elastic energy, which the code does not separate.
# A failure criterion with a length of its own (the crack band, the non-local fracture energy) claims that
# these do not depend on the spacing. The band table below them takes the material file's criterion: the
# band's width and its energy per unit crack area at the first failures, against Gamma and against what
# the criterion charges a band of that width (band_width_factor or nonlocal_radius). Environment: BUILD_DIR (default
# build), RUNS (default runs/mechanism-190.7), SPACINGS (mm, default "2 1.333 1"), THREADS (default 1),
# OUT (default cases/plate-8mm/report-mechanism), END (the end time, default "160 us"; a run whose plug has
# not come off by then is continued with `impactsph run --restart DIR --end LATER`). A spacing whose
# summary.json exists is not run again. At 1 mm a run takes about 20 minutes on one thread, at 0.7 mm
# about 75 minutes to 160 us.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${BUILD_DIR:-build}
RUNS=${RUNS:-runs/mechanism-190.7}
SPACINGS=${SPACINGS:-"2 1.333 1"}
THREADS=${THREADS:-1}
OUT=${OUT:-cases/plate-8mm/report-mechanism}
END=${END:-160 us}
mkdir -p "$RUNS" "$OUT"
for s in $SPACINGS; do
  [[ -f "$RUNS/${s}mm/summary.json" ]] && continue
  echo "mechanism: 190.7 m/s at $s mm"
  "$BUILD_DIR/impactsph" run cases/plate-8mm/case.toml --spacing "${s}mm" --threads "$THREADS" -q \
    --set "projectile.velocity=190.7 m/s" --set "time.end=$END" --set "time.frame_interval=4 us" \
    --out "$RUNS/${s}mm" > "$RUNS/${s}mm.log" 2>&1
done

python3 - "$RUNS" "$OUT" "$(git rev-parse --short HEAD)" $SPACINGS <<'PY'
import csv, json, math, os, shlex, shutil, sys, tomllib
sys.path.insert(0, 'cases/hard')
sys.path.insert(0, 'cases/plate-8mm')
from isolated_particles import pvd_frames, read_vtu
from shear_band import band_width, failure_work, plug_displacement

runs, out, commit, spacings = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
radius = 10e-3  # m, the projectile's radius (case.toml: diameter 20 mm)


def rows_of(path):
    return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(path))]


def first_time(rows, column):
    """The first time (s) at which `column` is positive, or None."""
    return next((r['time_s'] for r in rows if r[column] > 0), None)


def frame_measures(a, multiplicity):
    """Plug displacement (m), plate plastic work (J), plate internal and kinetic energy (J), one frame."""
    body, mass, wp, e, v = (a[k] for k in ('body_id', 'mass', 'plastic_work', 'internal_energy', 'velocity'))
    plate = [k for k in range(len(body)) if body[k] == 0]
    work = sum(mass[k] * wp[k] for k in plate)
    internal = sum(mass[k] * e[k] for k in plate)
    kinetic = sum(0.5 * mass[k] * sum(c * c for c in v[k]) for k in plate)
    return [plug_displacement(a, radius), multiplicity * work, multiplicity * internal, multiplicity * kinetic]


def at(series, t):
    """The frame measures interpolated linearly to time t (series: [(time, measures)])."""
    for (t0, m0), (t1, m1) in zip(series, series[1:]):
        if t0 <= t <= t1:
            w = (t - t0) / (t1 - t0)
            return [a + w * (b - a) for a, b in zip(m0, m1)]
    return None


table, bands = [], []
for s in spacings:
    run = os.path.join(runs, s + 'mm')
    summary = json.load(open(os.path.join(run, 'summary.json')))
    plate = summary['bodies'][0]
    multiplicity = round(plate['specified']['mass_kg'] / plate['initial_mass_kg'])
    series, band = [], None
    for t, path in pvd_frames(run):
        a = read_vtu(path)
        series.append((float(t), frame_measures(a, multiplicity)))
        w_fail = failure_work(a) if band is None else math.nan
        if not math.isnan(w_fail):
            band = (float(t), band_width(a, radius)[0], w_fail)
    bands.append(band)
    t_fail = first_time(rows_of(os.path.join(run, 'history_plate.csv')), 'damaged_mass_fraction')
    t_sep = first_time(rows_of(os.path.join(run, 'observables.csv')), 'plug_mass_g')
    table.append((s, summary, t_fail, at(series, t_fail) if t_fail else None, t_sep,
                  at(series, t_sep) if t_sep else None))


def cell(value, fmt, ref):
    if value is None:
        return 'n/a'
    return (fmt % value) + ('' if ref is None else ' (%+.1f %%)' % (100 * (value / ref - 1)))


# Each column against the finest spacing that has its figure (a run stopped before its plug came off has
# a first failure but no separation).
ref_fail = next((row[3] for row in reversed(table) if row[3]), None)
ref_sep = next((row[5] for row in reversed(table) if row[5]), None)
settings = ''.join('%s="%s" ' % (name, value) for name, value, default in (
    ('RUNS', runs, 'runs/mechanism-190.7'), ('OUT', out, 'cases/plate-8mm/report-mechanism'),
    ('SPACINGS', ' '.join(spacings), '2 1.333 1')) if value != default)
lines = ['# 8 mm plate at 190.7 m/s: the failure mechanism against the spacing', '',
         'Generated by `%sbash cases/plate-8mm/mechanism.sh` at commit %s from the runs in %s (each run\'s command '
         'line is below the table). Plug displacement: the mean axial position of the plate within half the '
         'projectile radius of the axis against a ring 1.4-1.6 radii out, from the frames (4 us apart) '
         'interpolated to the event. First failure: the first history row with a failed plate particle; '
         'separation: the first row of observables.csv with a plug cut off. Plastic work and energies are the '
         'whole plate\'s (the quarter model times 4). "Not plastic": internal energy that is not plastic work '
         '(the artificial viscosity\'s heat and stored elastic energy), as a share of the energy the plate took '
         '(internal + kinetic). In brackets: against the finest spacing that has the figure. A run\'s end time '
         'is in its command line (END when it was made; a run stopped early says so).' % (settings, commit, runs), '',
         '| spacing | first failure | plug displacement there | separation | plug displacement there | plastic work '
         'to separation | not plastic at separation | plug | residual at the end (settled at) | energy drift | wall |',
         '|---|---|---|---|---|---|---|---|---|---|---|']
for s, summary, t_fail, m_fail, t_sep, m_sep in table:
    share = m_sep and (m_sep[2] - m_sep[1]) / (m_sep[2] + m_sep[3])
    o = summary['observables']
    settled = o.get('settled_time') or -1
    lines.append('| %s mm | %s | %s | %s | %s | %s | %s | %.1f g | %.1f m/s (%s) | %.3f %% | %.0f s |' % (
        s, cell(t_fail and t_fail * 1e6, '%.0f us', None),
        cell(m_fail and m_fail[0] * 1e3, '%.2f mm', ref_fail and ref_fail[0] * 1e3),
        cell(t_sep and t_sep * 1e6, '%.0f us', None),
        cell(m_sep and m_sep[0] * 1e3, '%.2f mm', ref_sep and ref_sep[0] * 1e3),
        cell(m_sep and m_sep[1], '%.1f J', ref_sep and ref_sep[1]),
        cell(share and 100 * share, '%.1f %%', None), 1e3 * o['plug_mass'], o['residual_velocity'],
        '%.0f us' % (1e6 * settled) if settled > 0 else 'not settled by %.0f us' % (1e6 * summary['simulated_time_s']),
        100 * summary['totals']['energy_drift_relative'], summary['wall_time_s']))
MATERIAL = 'cases/materials/weldox-460e.toml'
material = tomllib.load(open(MATERIAL, 'rb')).get('damage', {})
if material.get('kind') != 'fracture-energy':
    sys.exit('mechanism: %s: damage.kind is "%s"; the band table needs "fracture-energy" (the crack band)'
             % (MATERIAL, material.get('kind')))
gamma_text = material['fracture_energy']
GAMMA_UNITS = {'J/m^2': 1.0, 'kJ/m^2': 1e3, 'MJ/m^2': 1e6}
value, unit = (gamma_text.split() + [''])[:2]
if unit not in GAMMA_UNITS:
    sys.exit('mechanism: %s: damage.fracture_energy "%s": expected a number and one of %s'
             % (MATERIAL, gamma_text, ', '.join(GAMMA_UNITS)))
gamma = float(value) * GAMMA_UNITS[unit]
LENGTH_UNITS = {'m': 1.0, 'mm': 1e-3, 'um': 1e-6}


def nonlocal_charge(width, radius):
    """Energy per unit crack area of a band of uniform W, `width` (m) wide, under the non-local criterion of
    averaging radius `radius` (m), against Gamma: 1 / mean (1 - t^2)^3 over |t| < width / (2 R) (the bell
    weight (1 - r^2/R^2)^2 integrated over a plane, common/nonlocal_weight.hpp); a band 2R or wider holds
    W_c b = Gamma b / L."""
    b = width / (2 * radius)
    c = min(b, 1.0)
    integral = c - c ** 3 + 3 * c ** 5 / 5 - c ** 7 / 7  # of (1 - t^2)^3 from 0 to min(b, 1); 16/35 at 1
    return b / integral


if 'nonlocal_radius' in material:
    value_r, unit_r = (material['nonlocal_radius'].split() + [''])[:2]
    if unit_r not in LENGTH_UNITS:
        sys.exit('mechanism: %s: damage.nonlocal_radius "%s": expected a number and one of %s'
                 % (MATERIAL, material['nonlocal_radius'], ', '.join(LENGTH_UNITS)))
    r_nl = float(value_r) * LENGTH_UNITS[unit_r]
    criterion = ('The non-local criterion (the material file\'s nonlocal_radius R = %s) fails a particle once its own '
                 'plastic work density W and the average of W within R both reach W_c = Gamma / L, L = 32 R / 35 = '
                 '%.2f mm, Gamma = %s. A band of uniform W that is b wide then holds Gamma / mean (1 - t^2)^3, '
                 '|t| < b / 2R, per unit crack area, whatever the spacing: "model" below, against Gamma. The '
                 'criterion holds when W x width follows the model at every spacing.'
                 % (material['nonlocal_radius'], 1e3 * 32 * r_nl / 35, gamma_text))
    model = lambda width, h0: nonlocal_charge(width, r_nl)
else:
    k_band = material['band_width_factor']
    criterion = ('The crack band assumes that the band which fails is k h0 wide at every spacing (k = %g, the material '
                 'file\'s band_width_factor; h0 the initial smoothing length), so that a particle failing at the '
                 'plastic work density W = Gamma / (k h0) leaves Gamma = %s per unit crack area: "model" below, '
                 'the band\'s width over k h0.' % (k_band, gamma_text))
    model = lambda width, h0: width / (k_band * h0)
lines += ['', '## The band at the first failures', '',
          criterion + ' Measured by shear_band.py (band_width: the energy width of the plastic work profile across '
          'the band at the projectile\'s radius; failure_work: the median W of the failed plate particles) on the '
          'first frame with a failed particle: the width the band has, and the energy per unit area it holds at '
          'failure, W times that width, against Gamma.', '',
          '| spacing | frame | band width | in h0 | W at failure | W x width | against Gamma | model |',
          '|---|---|---|---|---|---|---|---|']
for (s, summary, *_), band in zip(table, bands):
    if band is None:
        lines.append('| %s mm | no failed particle in the frames | | | | | | |' % s)
        continue
    t, width, w_fail = band
    h0 = summary['smoothing_length_m']
    lines.append('| %s mm | %.0f us | %.2f mm | %.2f | %.1f MJ/m^3 | %.0f kJ/m^2 | %+.1f %% | %+.1f %% |' % (
        s, t * 1e6, width * 1e3, width / h0, w_fail * 1e-6, w_fail * width * 1e-3, 100 * (w_fail * width / gamma - 1),
        100 * (model(width, h0) - 1)))
lines += ['', 'Each run\'s picture.png (drawn when the run finished; its time is in its title): a cut through the '
          'symmetry plane coloured by plastic strain, failed particles marked.', '']
for s, summary, *_ in table:
    src = os.path.join(runs, s + 'mm', 'picture.png')
    if os.path.isfile(src):
        shutil.copyfile(src, os.path.join(out, 'end-%smm.png' % s))
        lines.append('![%s mm](end-%smm.png)' % (s, s))
lines += ['', 'Runs:', '']
def command_of(run_dir, summary):
    """The run's commands as a user types them, from its run.json (a restart's new end time included)."""
    r = json.load(open(os.path.join(run_dir, 'run.json')))
    cmd = ['build/impactsph', 'run', os.path.relpath(r['case_file']), '--spacing', r['spacing'], '--threads',
           str(r['threads'])]
    for x in r['set']:
        cmd += ['--set', x]
    text = '`%s`' % shlex.join(cmd + ['--out', run_dir])
    if r.get('end'):
        text += ', then `%s`' % shlex.join(['build/impactsph', 'run', '--restart', run_dir, '--end', r['end']])
    if not summary.get('completed'):
        text += (', stopped at %.0f us by a signal (its checkpoint and summary written; `impactsph run --restart %s` '
                 'continues it)' % (1e6 * summary['simulated_time_s'], run_dir))
    return text


for s, summary, *_ in table:
    lines.append('- %s mm: %s (%d particles, %d steps, %.1f neighbours)' % (
        s, command_of(os.path.join(runs, s + 'mm'), summary), summary['particles'], summary['steps'],
        summary['mean_neighbours']))
open(os.path.join(out, 'report.md'), 'w').write('\n'.join(lines) + '\n')
print('mechanism: wrote %s/report.md' % out)
PY
