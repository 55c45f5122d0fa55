#!/usr/bin/env python3
"""The Taylor bars by finite elements and by SPH beside the experiment (cases/taylor-bar/fe-vs-sph.sh).

    python3 cases/taylor-bar/fe_vs_sph.py profile SPH_RUN OUT_CSV    # the SPH run's outer surface, last frame
    python3 cases/taylor-bar/fe_vs_sph.py report FOLDER              # FOLDER/report.md and profiles.png

`profile` reads the first and the last frame of an `impactsph run` of a Taylor bar (its particles.pvd) and
writes the outer surface as `height_m,radius_m`: the particles of the bar binned by height in layers one
lattice layer thick (summary.json's lattice spacing along the axis), the outermost centre of each layer,
its radius shifted by R0 - r_max(0) (R0 the bar's radius, r_max(0) the outermost centre at t = 0). That is
the shift of summary.json's impact_face_diameter_shifted, the SPH measure of the material's outer surface
that the finite-element outer nodes are compared with. The bar's axis is z through the case's base at
x = y = 0 (the Taylor cases' quarter models).

`report` reads FOLDER/runs/NAME/{summary.json,profile.csv} (NAME = CASE-fe-N for `impactsph taylor-fe`
at N elements across the radius, CASE-sph-S for `impactsph run` at the spacing S mm) and the cases'
expected answers copied to FOLDER/expected/CASE.toml, and writes one table per bar and one plot of the
final profiles. Every figure is read from those files.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path


def sph_profile(run, out_csv):
    # The VTU reader and the frame list of the other scripts; imported here, so that `report` needs neither.
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'hard'))
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from isolated_particles import read_vtu
    from foot import frames_of

    summary = json.load(open(os.path.join(run, 'summary.json')))
    bar = summary['bodies'][0]
    dz = bar['generated']['lattice_spacing_m'][2]
    radius = 0.5 * bar['specified']['diameter_m']
    frames = frames_of(run)
    first = read_vtu(os.path.join(run, frames[0][1]))
    last = read_vtu(os.path.join(run, frames[-1][1]))

    def radii(frame):
        return [math.hypot(p[0], p[1]) for p in frame['Points']]

    shift = radius - max(radii(first))
    layers = {}
    for p, r in zip(last['Points'], radii(last)):
        k = math.floor(p[2] / dz)
        if k not in layers or r > layers[k][1]:
            layers[k] = (p[2], r)
    with open(out_csv, 'w') as f:
        f.write('height_m,radius_m\n')
        for k in sorted(layers):
            z, r = layers[k]
            f.write(f'{z:.9g},{r + shift:.9g}\n')


# The spacing (mm) at which the SPH is held to the finite elements: within 2 % in length and 4 % in face
# (verification/validation_taylor_bar.cpp).
TARGET_SPACING = 0.3


def run_order(name):
    """Runs by bar, then method, then mesh: taylor-bar-fe-8 before taylor-bar-fe-16."""
    return [(0, float(part)) if part.replace('.', '', 1).isdigit() else (1, part) for part in name.split('-')]


def quantity_mm(text):
    value, unit = text.split()
    if unit != 'mm':
        raise ValueError(f'expected a length in mm, got {text!r}')
    return float(value)


def load(folder):
    runs = {}
    for summary in sorted((folder / 'runs').glob('*/summary.json')):
        run = json.loads(summary.read_text())
        run['name'] = summary.parent.name
        with open(summary.parent / 'profile.csv') as f:
            run['profile'] = [(1e3 * float(r['radius_m']), 1e3 * float(r['height_m'])) for r in csv.DictReader(f)]
        case, kind, size = run['name'].rsplit('-', 2)
        run['case_name'], run['kind'], run['size'] = case, kind, float(size)
        runs[run['name']] = run
    return runs


def pct(value, reference):
    return f'{100 * (value / reference - 1):+.1f} %'


def obs(run, key):
    return 1e3 * run['observables'][key]


def command(run):
    words = run['command_line'][1:]
    quoted = [w if all(c.isalnum() or c in '-_./=:' for c in w) else f"'{w}'" for w in words]
    return 'impactsph ' + ' '.join(quoted)


def bar_section(case, fe, sph, exp):
    """The table of one bar: its reference (experiment or published range), the FE meshes, the SPH spacings."""
    out = [f'## {case} (cases/{case}/case.toml)', '']
    fine = fe[-1] if fe else None
    fe_length, fe_face = (obs(fine, 'final_length'), obs(fine, 'impact_face_diameter')) if fine else (None, None)
    if 'impact_face_diameter' in exp:
        ref_length, ref_face = quantity_mm(exp['final_length']['value']), quantity_mm(exp['impact_face_diameter']['value'])
        out.append(f"Experiment: {ref_length:g} mm long, face {ref_face:g} mm across (expected.toml: "
                   f"\"{exp['final_length']['source']}\").")
        ref_name = 'experiment'
    else:
        ref_length, ref_face = quantity_mm(exp['final_length']['value']), 2 * quantity_mm(exp['foot_radius']['value'])
        out.append(f"Published finite-element answer (middle of the range): {ref_length:g} mm long, foot radius "
                   f"{ref_face / 2:g} mm, face {ref_face:g} mm across ({exp['final_length']['source']}).")
        ref_name = 'published FE'
    out += ['',
            f'| method | mesh | final length [mm] | vs {ref_name} | vs FE finest | face diameter [mm] | vs {ref_name} | '
            'vs FE finest | SPH face: lattice / area [mm] | energy drift | wall [s] |',
            '|---|---|---|---|---|---|---|---|---|---|---|']
    for r in fe:
        length, face = obs(r, 'final_length'), obs(r, 'impact_face_diameter')
        out.append(f"| finite elements | {r['elements_across']} across | {length:.3f} | {pct(length, ref_length)} | "
                   f"{pct(length, fe_length)} | {face:.3f} | {pct(face, ref_face)} | {pct(face, fe_face)} | | "
                   f"{100 * r['totals']['energy_drift_relative']:+.3f} % | {r['wall_time_s']:.0f} |")
    for r in sph:
        length, face = obs(r, 'final_length'), obs(r, 'impact_face_diameter_shifted')
        vs_fe_l = pct(length, fe_length) if fine else '-'
        vs_fe_d = pct(face, fe_face) if fine else '-'
        out.append(f"| SPH | {r['size']:g} mm | {length:.3f} | {pct(length, ref_length)} | {vs_fe_l} | {face:.3f} "
                   f"(shifted) | {pct(face, ref_face)} | {vs_fe_d} | {obs(r, 'impact_face_diameter'):.3f} / "
                   f"{obs(r, 'impact_face_diameter_area'):.3f} | {100 * r['totals']['energy_drift_relative']:+.3f} % | "
                   f"{r['wall_time_s']:.0f} |")
    if not sph:
        out += ['', 'No SPH run is kept for this bar (the script was run with SPH=skip, or its runs have not finished).']
    out.append('')
    if fine and sph:
        finest = min(sph, key=lambda r: r['size'])
        dl = obs(finest, 'final_length') / fe_length - 1
        dd = obs(finest, 'impact_face_diameter_shifted') / fe_face - 1
        line = (f"SPH at {finest['size']:g} mm against the finite elements at {fine['elements_across']} across: "
                f"length {100 * dl:+.1f} %, face {100 * dd:+.1f} %")
        if finest['size'] <= TARGET_SPACING:
            line += (f" (targets at {TARGET_SPACING:g} mm: length 2 %, {'met' if abs(dl) <= 0.02 else '**missed**'}; "
                     f"face 4 %, {'met' if abs(dd) <= 0.04 else '**missed**'}).")
        else:
            line += (f". The targets (2 % in length, 4 % in face) are for {TARGET_SPACING:g} mm, which is not among "
                     "the runs kept here.")
        out.append(line)
        if len(sph) >= 3:
            s = sorted(sph, key=lambda r: -r['size'])[-3:]
            for key, label in (('final_length', 'length'), ('impact_face_diameter_shifted', 'face')):
                v = [obs(r, key) for r in s]
                d1, d2 = v[1] - v[0], v[2] - v[1]
                out.append(f"SPH {label} over {s[0]['size']:g} / {s[1]['size']:g} / {s[2]['size']:g} mm: changes "
                           f"{d1:+.3f} then {d2:+.3f} mm: {'converging' if abs(d2) < abs(d1) else '**not converging**'}.")
        out.append('')
    return out, (ref_length, ref_face)


def plot(folder, bars):
    """profiles.png: per bar, the finest FE mesh's outer nodes against the SPH spacings' outer particles."""
    blocks, panels = [], []
    colours = ['#d62728', '#ff7f0e', '#2ca02c', '#1f77b4']
    for case, (fe, sph, ref) in bars.items():
        plots = []
        tag = case.replace('-', '_')
        if fe:
            r = fe[-1]
            blocks.append(f'$fe_{tag} << EOD\n' + ''.join(f'{x:.6g} {y:.6g}\n' for x, y in r['profile']) + 'EOD')
            plots.append(f"$fe_{tag} u 1:2 w l lw 2.5 lc rgb 'black' t 'finite elements, {r['elements_across']} across'")
        for k, r in enumerate(sorted(sph, key=lambda r: -r['size'])):
            name = f"$sph_{tag}_{k}"
            blocks.append(f'{name} << EOD\n' + ''.join(f'{x:.6g} {y:.6g}\n' for x, y in r['profile']) + 'EOD')
            plots.append(f"{name} u 1:2 w p pt 7 ps 0.7 lc rgb '{colours[k % len(colours)]}' "
                         f"t 'SPH {r['size']:g} mm (outer particles, shifted)'")
        length, face = ref
        blocks.append(f'$ref_{tag} << EOD\n{face / 2:.6g} 0\n0 {length:.6g}\nEOD')
        plots.append(f"$ref_{tag} u 1:2 w p pt 5 ps 1.6 lc rgb '#555555' t 'reference: face radius, length'")
        top = max([y for r in fe + sph for _, y in r['profile']] + [length]) * 1.05
        panels.append((case, top, plots))
    script = ['\n'.join(blocks),
              f"set terminal pngcairo size {560 * max(1, len(panels))},760 noenhanced font 'Sans,11'",
              "set output 'profiles.png'",
              f"set multiplot layout 1,{max(1, len(panels))} title 'Final outer surface: finite elements against SPH "
              "(cases/taylor-bar/fe-vs-sph.sh)'",
              "set xlabel 'radius [mm]'", "set ylabel 'height above the wall [mm]'", "set size ratio -1", "set grid",
              "set key top right font ',9'"]
    for case, top, plots in panels:
        script += [f"set title '{case}'", f"plot [0:9][0:{top:.3g}] " + ', '.join(plots)]
    script += ['unset multiplot', 'unset output', '']
    (folder / 'profiles.gp').write_text('\n'.join(script))
    if shutil.which('gnuplot'):
        subprocess.run(['gnuplot', 'profiles.gp'], cwd=folder, check=True)
    else:
        print('gnuplot is not installed: profiles.png not drawn (profiles.gp is there)', file=sys.stderr)


def report(folder):
    runs = load(folder)
    md = ['# Taylor bars: finite elements against SPH',
          '',
          'Written by `python3 cases/taylor-bar/fe_vs_sph.py report cases/taylor-bar/fe-vs-sph` from the runs that '
          '`bash cases/taylor-bar/fe-vs-sph.sh` keeps in runs/ here (each run\'s command is in the last table). '
          'Finite elements: `impactsph taylor-fe` (verification/fe2d/README.md), its face the end row\'s outermost '
          'node. SPH: `impactsph run` with the case\'s numerics, its face by the shifted measure '
          '(impact_face_diameter_shifted: the outermost wall-layer particle\'s radial travel added to the bar\'s '
          'radius, the measure that follows the same material point as the finite-element node); the lattice and '
          'area measures beside it. Wall times on the machine and threads of each run (summary.json).',
          '']
    bars = {}
    for case in sorted({r['case_name'] for r in runs.values()}):
        fe = sorted([r for r in runs.values() if r['case_name'] == case and r['kind'] == 'fe'],
                    key=lambda r: r['elements_across'])
        sph = sorted([r for r in runs.values() if r['case_name'] == case and r['kind'] == 'sph'],
                     key=lambda r: -r['size'])
        exp = tomllib.loads((folder / 'expected' / f'{case}.toml').read_text())
        section, ref = bar_section(case, fe, sph, exp)
        md += section
        bars[case] = (fe, sph, ref)
    md += ['## Profiles', '',
           'The finest finite-element mesh\'s outer nodes (line) and each SPH run\'s outermost particle per lattice '
           'layer, shifted outward by R0 - r_max(0) as the face measure is (points), at the end time; the reference '
           'length and face radius as squares.', '', '![profiles](profiles.png)', '',
           '## The runs', '', '| run | command | wall [s] |', '|---|---|---|']
    for name, r in sorted(runs.items(), key=lambda item: run_order(item[0])):
        md.append(f"| {name} | `{command(r)}` | {r['wall_time_s']:.0f} |")
    md.append('')
    (folder / 'report.md').write_text('\n'.join(md))
    plot(folder, bars)


def main():
    if len(sys.argv) == 4 and sys.argv[1] == 'profile':
        sph_profile(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3 and sys.argv[1] == 'report':
        report(Path(sys.argv[2]))
    else:
        sys.exit(__doc__)


if __name__ == '__main__':
    main()
