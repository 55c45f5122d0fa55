"""The 8 mm plate's runs as the report scripts of this folder read them (limit-vs-spacing.sh,
residual-curve.sh): one run's summary.json as a flat record, and the Recht-Ipson residual-velocity curve
v_r = a (v_i^p - v_bl^p)^(1/p) (docs/ballistic-limit.md). Imported from the repository root."""
import json
import math
import os
import shlex


def summary_path(p):
    """A run folder or its summary.json -> the summary.json."""
    return p if p.endswith('.json') else os.path.join(p, 'summary.json')


def read_run(path):
    """The run's figures from its summary.json (a folder or the file), or None when it has no observables
    (a run stopped before its first output). Speeds in m/s, masses in g, times in s, spacing in mm."""
    s = json.load(open(summary_path(path)))
    if 'observables' not in s:
        return None
    proj = [b for b in s['bodies'] if b['name'] == 'projectile'][0]
    p0 = s['totals']['initial_momentum_kg_m_s']
    o = s['observables']
    return dict(v0=math.sqrt(sum(c * c for c in p0)) / proj['initial_mass_kg'],  # only the projectile moves at t = 0
                vr=o['residual_velocity'], perforated=o['perforated'],
                plug=o.get('plug_mass', 0.0) * 1e3, plug_v=o.get('plug_velocity', 0.0),
                mp=proj['specified']['mass_kg'], spacing=s['spacing_m'] * 1e3,
                damage=o.get('damage_fraction', 0.0), settled=o.get('settled_time'),
                completed=bool(s.get('completed')), t_end=s['simulated_time_s'],
                drift=s['totals']['energy_drift_relative'], wall=s['wall_time_s'],
                threads=s['hardware']['threads'], steps=s['steps'], particles=s['particles'],
                neighbours=s['mean_neighbours'], command_line=shlex.join(s['command_line']),
                source=os.path.dirname(summary_path(path)))


def recht_ipson(a, p, v_bl, v):
    """The residual velocity of the Recht-Ipson curve at impact speed v (0 below the limit)."""
    return a * (v ** p - v_bl ** p) ** (1.0 / p) if v > v_bl else 0.0


def recht_ipson_p2_limit(points):
    """v_bl of the p = 2 curve through the two slowest of the perforating (v_i, v_r) points, or None:
    v_r = a sqrt(v^2 - v_bl^2), so v_bl^2 = (v1^2 - k v2^2) / (1 - k), k = (v_r1 / v_r2)^2."""
    perf = sorted(points)
    if len(perf) < 2 or not (0 < perf[0][1] < perf[1][1]):
        return None
    (v1, r1), (v2, r2) = perf[0], perf[1]
    k = (r1 / r2) ** 2
    vb2 = (v1 * v1 - k * v2 * v2) / (1 - k)
    return vb2 ** 0.5 if 0 < vb2 < v1 * v1 else None


def repository_path(path):
    """A case file's absolute path as run.json keeps it (on the machine of the run) -> its path from the
    repository root (cases/...), the same wherever the report is regenerated."""
    at = path.rfind('/cases/')
    return path[at + 1:] if at >= 0 else os.path.relpath(path)


def user_command(path):
    """The command that made a run, as a user types it: `build/impactsph` for the program, and for a run
    continued with --restart the first command rebuilt from its run.json (case, spacing, threads, sets)
    followed by the restart. path: the run folder or its summary.json, with run.json beside it."""
    folder = os.path.dirname(summary_path(path))
    argv = json.load(open(summary_path(path)))['command_line']
    argv = ['build/impactsph'] + argv[1:]
    if '--restart' not in argv:
        return shlex.join(argv)
    r = json.load(open(os.path.join(folder, 'run.json')))
    out = argv[argv.index('--restart') + 1]
    first = ['build/impactsph', 'run', repository_path(r['case_file'])]
    first += ['--spacing', r['spacing']] if r['spacing'] else []  # empty: the case file's spacing
    first += ['--threads', str(r['threads'])]
    for x in r['set']:
        first += ['--set', x]
    return '%s, continued with %s' % (shlex.join(first + ['--out', out]), shlex.join(argv))
