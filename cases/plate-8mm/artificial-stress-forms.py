"""The 8 mm plate near its ballistic limit with the artificial stress built from the deviatoric stress (the
case's default, numerics.artificial_stress_of = "deviatoric") and from the whole stress ("total", Gray,
Monaghan and Swift 2001): OUT/report.md, one row per run, from the runs' summary.json and run.json, each run
with its picture.png. The runs are folders with those three files: by default every subfolder of OUT that has
a summary.json (the runs copied from runs/ into OUT, so that the report is regenerated from the repository
alone), or the RUN_DIRs given.

    python3 cases/plate-8mm/artificial-stress-forms.py OUT [RUN_DIR...]

Nothing typed in: every figure comes from a summary.json."""
import json
import os
import shlex
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plate_runs import read_run, user_command  # noqa: E402


def form_of(folder):
    """The artificial stress's form as the run set it (run.json), or the case's default."""
    sets = json.load(open(os.path.join(folder, 'run.json')))['set']
    forms = [s.split('=', 1)[1] for s in sets if s.startswith('numerics.artificial_stress_of=')]
    return forms[-1] if forms else 'deviatoric'


def coarse_rim(folder):
    return any(s.startswith('plate.coarse=') for s in json.load(open(os.path.join(folder, 'run.json')))['set'])


def main():
    if len(sys.argv) < 2:
        sys.exit('usage: python3 cases/plate-8mm/artificial-stress-forms.py OUT [RUN_DIR...]')
    out, dirs = sys.argv[1], sys.argv[2:]
    if not dirs and os.path.isdir(out):
        dirs = sorted(os.path.join(out, d) for d in os.listdir(out)
                      if os.path.isfile(os.path.join(out, d, 'summary.json')))
    if not dirs:
        sys.exit('artificial-stress-forms: no run folders given and none with a summary.json in %s' % out)
    for d in dirs:
        for f in ('summary.json', 'run.json'):
            if not os.path.isfile(os.path.join(d, f)):
                sys.exit('artificial-stress-forms: %s has no %s; give run folders as impactsph run writes them' % (d, f))
    rows = []
    for d in dirs:
        r = read_run(d)
        if r is None:
            sys.exit('artificial-stress-forms: %s stopped before its first output' % d)
        rows.append((r['spacing'], r['v0'], form_of(d), d, r))
    rows.sort(key=lambda x: (-x[0], x[1], x[2]))
    lines = ['# 8 mm plate: the artificial stress from the deviatoric or from the whole stress', '',
             'Written by `python3 cases/plate-8mm/artificial-stress-forms.py %s` from each run\'s summary.json '
             'and run.json (their commands below); do not edit by hand. Projectile at the end: its velocity along '
             'the impact direction when the run ended (negative: turned back). The plate has the coarse rim beyond '
             '30 mm (`plate.coarse`, cases/plate-8mm/README.md "Two resolutions") where the table says so.'
             % ' '.join(sys.argv[1:]), '',
             '| spacing | impact | artificial stress of | rim | perforated | projectile at the end | plug | damage fraction '
             '| end | steps | wall (threads) | energy drift | picture |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for spacing, v0, form, d, r in rows:
        plug = '%.2f g at %.1f m/s' % (r['plug'], r['plug_v']) if r['plug'] > 0 else 'none'
        pic = os.path.relpath(os.path.join(d, 'picture.png'), out)
        lines.append('| %g mm | %g m/s | %s | %s | %s | %.2f m/s%s | %s | %.4f | %.0f us%s | %d | %.0f s (%d) | %.3f %% | '
                     '[picture](%s) |' % (spacing, round(v0, 2), form, 'yes' if coarse_rim(d) else 'no',
                                          'yes' if r['perforated'] else 'no', r['vr'],
                                          ' (not settled)' if r['perforated'] and r['settled'] is None else '', plug, r['damage'],
                                          r['t_end'] * 1e6, '' if r['completed'] else ' (stopped)', r['steps'],
                                          r['wall'], r['threads'], 100 * r['drift'], pic))
    lines += ['', 'Commands:', '']
    for spacing, v0, form, d, r in rows:
        lines.append('- %g mm, %g m/s, %s: `%s`' % (spacing, round(v0, 2), form, user_command(d)))
    searches = os.path.join(out, 'searches')
    names = sorted(n for n in os.listdir(searches) if n.endswith('.json')) if os.path.isdir(searches) else []
    if names:
        lines += ['', 'Ballistic-limit searches (their ballistic.json in searches/; the runs of each bracket above):', '']
    for n in names:
        b = json.load(open(os.path.join(searches, n)))
        lines.append('- %s: %g mm, limit %.1f m/s, bracket %.2f-%.2f m/s: `%s`'
                     % (n, b['spacing_m'] * 1e3, b['limit_m_s'], b['bracket_m_s'][0], b['bracket_m_s'][1],
                        shlex.join(['build/impactsph'] + b['command_line'][1:])))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, 'report.md'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('artificial-stress-forms: wrote %s' % os.path.join(out, 'report.md'))


if __name__ == '__main__':
    main()
