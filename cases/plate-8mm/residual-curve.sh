#!/usr/bin/env bash
# The 8 mm plate's residual velocities at the case's spacing (1 mm) against the experiments' Recht-Ipson
# curve (p = 2, a = m_p/(m_p + m_plug) = 0.909, v_bl = 152.5 m/s; cases/plate-8mm/README.md), and the
# Recht-Ipson fit of the simulated points. Runs the sweep cases/sweeps/plate-8mm-residual-1mm.toml (F Table 1
# scenarios 1-6, the case as it stands), then writes OUT/report.md, residual_curve.dat, residual_curve.gp and
# residual_curve.png from the runs' summary.json files: nothing typed in.
#
#   bash cases/plate-8mm/residual-curve.sh                 # run what is missing (about an hour on 2 cores), report
#   REPORT_ONLY=1 bash cases/plate-8mm/residual-curve.sh
#
# Environment: BUILD_DIR (default build), RUNS (the sweep's folder, default runs/plate-8mm-residual-1mm),
# OUT (default cases/plate-8mm/report-residual-1mm), JOBS (default 2), SWEEP (the sweep file, default
# cases/sweeps/plate-8mm-residual-1mm.toml; cases/sweeps/plate-8mm-residual-1mm-rim.toml is the same with the
# plate's coarse rim, as the material file's calibration runs), EXTRA_RUNS (more run folders or
# summary.json files of the same case and spacing, e.g. the runs that bracket the ballistic limit: every
# run enters the table, and the highest speed that did not perforate and the lowest that did give the
# simulated limit, at which the fit "v_bl fixed" is held).
#
# Each run of RUNS that has a summary.json is kept as OUT/summaries/<run folder>.json, and the report reads
# the runs of RUNS together with the kept ones, so a report regenerated later (REPORT_ONLY=1, runs/ gone or
# holding only some of the sweep) still has every row it had: a run in RUNS replaces its kept copy.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${BUILD_DIR:-build}
RUNS=${RUNS:-runs/plate-8mm-residual-1mm}
OUT=${OUT:-cases/plate-8mm/report-residual-1mm}
JOBS=${JOBS:-2}
SWEEP=${SWEEP:-cases/sweeps/plate-8mm-residual-1mm.toml}
[[ -f "$SWEEP" ]] || { echo "residual-curve: no sweep file $SWEEP (SWEEP names one in cases/sweeps/)" >&2; exit 2; }
mkdir -p "$OUT"

if [[ -z "${REPORT_ONLY:-}" ]]; then
  "$BUILD_DIR/impactsph" sweep "$SWEEP" --jobs "$JOBS" --out "$RUNS"
fi

python3 - "$RUNS" "$OUT" "$(git rev-parse --short HEAD)" "$SWEEP" ${EXTRA_RUNS:-} <<'PY'
import glob, json, math, os, shutil, subprocess, sys
sys.path.insert(0, 'cases/plate-8mm')
from plate_runs import read_run, recht_ipson, summary_path

runs, out, commit, sweep, extra = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
V_BL_EXPERIMENT = 152.5  # m/s, F section 7: the experiments' ballistic limit of the 8 mm plate
P_EXPERIMENT = 2.0       # Recht-Ipson exponent of a blunt projectile pushing out a plug (validation data)

kept_dir = os.path.join(out, 'summaries')
os.makedirs(kept_dir, exist_ok=True)
for path in glob.glob(os.path.join(runs, '*', 'summary.json')):
    shutil.copyfile(path, os.path.join(kept_dir, os.path.basename(os.path.dirname(path)) + '.json'))
paths = sorted(glob.glob(os.path.join(kept_dir, '*.json'))) + [summary_path(p) for p in extra]
rows = []
for path in paths:
    if not os.path.isfile(path):
        sys.exit('residual-curve: %s is missing (run the sweep, or drop it from EXTRA_RUNS)' % path)
    r = read_run(path)
    if r is None:
        print('residual-curve: %s has no observables; left out' % path)
        continue
    if path.startswith(kept_dir):
        r['source'] = path
    rows.append(r)
if not rows:
    sys.exit('residual-curve: no finished runs in %s' % runs)
rows.sort(key=lambda r: r['v0'])
stopped = [r for r in rows if not r['completed']]  # stopped before their end: listed apart, not in the table
rows = [r for r in rows if r['completed']]
spacings = sorted({round(r['spacing'], 6) for r in rows})
if len(spacings) != 1:
    sys.exit('residual-curve: the runs have different spacings %s' % spacings)

mp = rows[0]['mp']
full_plug = 7850.0 * math.pi * 0.010 ** 2 * 0.008 * 1e3  # g, a 20 mm disc through the 8 mm plate
a_exp = mp * 1e3 / (mp * 1e3 + full_plug)

def fit(points, v_bl=None):
    """Least squares of a (v^p - v_bl^p)^(1/p): a in closed form for each (p, v_bl), p and v_bl by a
    fine grid then a local refinement. Returns (a, p, v_bl, rms)."""
    def best_a(p, vb):
        g = [recht_ipson(1.0, p, vb, v) for v, _ in points]
        gg = sum(x * x for x in g)
        if gg == 0:
            return None
        a = sum(x * y for x, (_, y) in zip(g, points)) / gg
        rms = math.sqrt(sum((a * x - y) ** 2 for x, (_, y) in zip(g, points)) / len(points))
        return a, rms
    lo_v = min(v for v, _ in points)
    best = None
    vbs = [v_bl] if v_bl is not None else [lo_v * (0.5 + 0.5 * k / 400) for k in range(400)]
    for vb in vbs:
        for k in range(1, 400):
            p = 1.0 + 4.0 * k / 400
            r = best_a(p, vb)
            if r and (best is None or r[1] < best[3]):
                best = (r[0], p, vb, r[1])
    a, p, vb, rms = best
    step_p, step_v = 0.01, (0.0 if v_bl is not None else lo_v * 0.00125)
    for _ in range(60):
        improved = False
        for dp, dv in ((step_p, 0), (-step_p, 0), (0, step_v), (0, -step_v)):
            if (dp == 0 and dv == 0) or p + dp <= 0.5 or vb + dv <= 0 or vb + dv >= lo_v:
                continue
            r = best_a(p + dp, vb + dv)
            if r and r[1] < rms:
                a, p, vb, rms = r[0], p + dp, vb + dv, r[1]
                improved = True
        if not improved:
            step_p, step_v = step_p / 2, step_v / 2
    return a, p, vb, rms

held = [r['v0'] for r in rows if not r['perforated']]
through = [r['v0'] for r in rows if r['perforated']]
limit = None
if held and through and max(held) < min(through):
    limit = (max(held), min(through))
points = [(r['v0'], r['vr']) for r in rows if r['perforated'] and r['settled']]
fit_fixed = fit(points, 0.5 * (limit[0] + limit[1])) if limit and len(points) >= 2 else None
fit_free = fit(points) if len(points) >= 3 else None

cmd = 'bash cases/plate-8mm/residual-curve.sh'
if sweep != 'cases/sweeps/plate-8mm-residual-1mm.toml':
    cmd = 'SWEEP=%s %s' % (sweep, cmd)
if out.rstrip('/') != 'cases/plate-8mm/report-residual-1mm':
    cmd = 'OUT=%s %s' % (out, cmd)
if runs.rstrip('/') != 'runs/plate-8mm-residual-1mm':
    cmd = 'RUNS=%s %s' % (runs, cmd)
if extra:
    cmd = 'EXTRA_RUNS="%s" %s' % (' '.join(extra), cmd)
L = ['# 8 mm plate: residual velocities at %g mm' % spacings[0], '',
     'Generated by `%s` at commit %s from the runs\' summary.json files (the sweep %s, `impactsph sweep '
     '%s`, its runs kept in summaries/%s). Reference: the experiments\' Recht-Ipson curve, p = 2, '
     'a = m_p/(m_p + m_plug) = %.3f (m_p = %.1f g, a full 20 mm plug %.2f g), v_bl = %.1f m/s.'
     % (cmd, commit, runs, sweep, ', and EXTRA_RUNS' if extra else '', a_exp, mp * 1e3, full_plug, V_BL_EXPERIMENT), '',
     '| impact | perforated | residual | Recht-Ipson (experiments) | gap | plug | plug speed | failed mass | '
     'settled at | energy drift | steps | wall |',
     '|---|---|---|---|---|---|---|---|---|---|---|---|']
for r in rows:
    ref = recht_ipson(a_exp, P_EXPERIMENT, V_BL_EXPERIMENT, r['v0'])
    undecided = not r['perforated'] and not r['settled'] and r['vr'] > 1.0
    verdict = 'not yet (moving on, no plug cut off)' if undecided else 'yes' if r['perforated'] else 'no'
    if ref > 0 and (r['perforated'] or undecided):
        gap = '%+.1f %%' % (100 * (r['vr'] - ref) / ref)
    elif r['perforated']:
        gap = 'perforates; the experiments hold'
    else:
        gap = 'holds, as the experiments' if ref == 0 else 'holds; the experiments perforate'
    L.append('| %.1f m/s | %s | %.2f m/s | %.1f m/s | %s | %s | %s | %.4f | %s | %.3f %% | %d | %.0f s, %d thread%s |' % (
        r['v0'], verdict, r['vr'], ref, gap,
        '%.2f g' % r['plug'] if r['perforated'] else '', '%.2f m/s' % r['plug_v'] if r['perforated'] else '',
        r['damage'], '%.0f us' % (r['settled'] * 1e6) if r['settled'] else
        ('not settled by %.0f us' % (r['t_end'] * 1e6) if r['completed'] else
         'not settled: stopped by hand at %.0f us' % (r['t_end'] * 1e6)),
        100 * r['drift'], r['steps'], r['wall'], r['threads'], '' if r['threads'] == 1 else 's'))
if stopped:
    L += ['', 'Stopped before they ended, for want of time (the same command runs them again, or continues '
          'them from their checkpoints while the case and material files are unchanged):', '']
    L += ['- %.1f m/s: stopped at %.0f us, the projectile then at %.2f m/s, %s' % (
        r['v0'], r['t_end'] * 1e6, r['vr'], 'plug cut off (%.2f g at %.2f m/s)' % (r['plug'], r['plug_v'])
        if r['plug'] > 0 else 'no plug cut off yet') for r in stopped]
L += ['', 'Residual: the projectile\'s speed along the impact axis when settled (negative: rebound), or at the '
      'end of a run that did not settle (then left out of the fits). Plug: the '
      'mass of the piece cut off the clamped plate, for the whole plate; failed mass: the '
      'plate\'s damaged mass fraction. %d particles, %.1f mean neighbours.' % (rows[0]['particles'], rows[0]['neighbours']), '']
if limit:
    mid = 0.5 * (limit[0] + limit[1])
    L.append('**Ballistic limit from these runs: %.2f m/s** (bracket %.1f-%.1f m/s), %+.1f %% against the '
             'experiments\' %.1f m/s.' % (mid, limit[0], limit[1], 100 * (mid - V_BL_EXPERIMENT) / V_BL_EXPERIMENT,
                                          V_BL_EXPERIMENT))
else:
    L.append('These runs do not bracket the ballistic limit: %s.' % (
        'every one perforated' if not held else 'none perforated' if not through else 'their verdicts are not monotonic'))
L.append('')
if fit_fixed:
    a, p, vb, rms = fit_fixed
    L.append('- Recht-Ipson fit of the perforating runs that settled, v_bl fixed at %.2f m/s: a = %.3f, p = %.2f (rms %.2f m/s).' % (vb, a, p, rms))
if fit_free:
    a, p, vb, rms = fit_free
    L.append('- All three free: a = %.3f, p = %.2f, v_bl = %.2f m/s (rms %.2f m/s).' % (a, p, vb, rms))
L.append('- The experiments\' curve: a = %.3f, p = 2, v_bl = %.1f m/s.' % (a_exp, V_BL_EXPERIMENT))
L += ['', '![residual velocity against impact speed](residual_curve.png)', '', 'Runs:', '']
L += ['- `%s`' % r['source'] for r in rows]
open(os.path.join(out, 'report.md'), 'w').write('\n'.join(L) + '\n')

with open(os.path.join(out, 'residual_curve.dat'), 'w') as f:
    f.write('# impact_m_s residual_m_s perforated plug_g plug_m_s\n')
    for r in rows:
        f.write('%.4f %.4f %d %.4f %.4f\n' % (r['v0'], r['vr'], r['perforated'], r['plug'], r['plug_v']))
v_hi = max(r['v0'] for r in rows) * 1.05
gp = ['set terminal pngcairo size 900,600', 'set output "residual_curve.png"',
      'set xlabel "impact speed (m/s)"', 'set ylabel "residual speed (m/s)"', 'set key top left',
      'set grid', 'set xrange [100:%g]' % v_hi, 'set samples 500',
      'ri(a,p,vb,x) = x > vb ? a*(x**p - vb**p)**(1.0/p) : 0',
      'plot ri(%g,2,%g,x) lw 2 lc rgb "black" title "experiments: Recht-Ipson, p = 2, v_{bl} = %.1f m/s"'
      % (a_exp, V_BL_EXPERIMENT, V_BL_EXPERIMENT)]
if fit_fixed:
    a, p, vb, _ = fit_fixed
    gp[-1] += ', ri(%g,%g,%g,x) dt 2 lw 2 lc rgb "blue" title "fit: a = %.3f, p = %.2f, v_{bl} = %.1f m/s"' % (a, p, vb, a, p, vb)
if fit_free:
    a, p, vb, _ = fit_free
    gp[-1] += ', ri(%g,%g,%g,x) dt 3 lw 2 lc rgb "dark-green" title "fit, all free: a = %.3f, p = %.2f, v_{bl} = %.1f m/s"' % (a, p, vb, a, p, vb)
gp[-1] += (', "residual_curve.dat" using 1:($3 > 0 ? $2 : 1/0) with points pt 7 ps 1.5 lc rgb "red" title '
           '"simulated, %g mm, perforated", "residual_curve.dat" using 1:($3 > 0 ? 1/0 : $2) with points pt 6 ps 1.5 '
           'lc rgb "red" title "simulated, held (rebound)"' % spacings[0])
open(os.path.join(out, 'residual_curve.gp'), 'w').write('\n'.join(gp) + '\n')
subprocess.run(['gnuplot', 'residual_curve.gp'], cwd=out, check=True)
print('\n'.join(L))
PY
