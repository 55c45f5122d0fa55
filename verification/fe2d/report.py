#!/usr/bin/env python3
"""Writes REPORT_DIR/report.md and profiles.png from the finite-element runs kept in REPORT_DIR/runs (each a
summary.json, profile.csv and history.csv of `impactsph taylor-fe`, run by verification/fe2d/report.sh) and
the cases' expected answers copied into REPORT_DIR/expected. Every figure of the report is read from those
files.

    python3 verification/fe2d/report.py verification/reports/fe2d
"""
import csv
import json
import math
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

BARS = {
    "bilinear": ("cases/taylor-bar-bilinear", "taylor-bar-bilinear"),
    "copper": ("cases/taylor-bar", "taylor-bar"),
}


def load_runs(folder):
    runs = {}
    for summary in sorted((folder / "runs").glob("*/summary.json")):
        run = json.loads(summary.read_text())
        with open(summary.parent / "history.csv") as f:
            run["history"] = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
        run["name"] = summary.parent.name
        runs[run["name"]] = run
    return runs


def quantity_mm(text):
    """A length of an expected.toml ("21.55 mm") in mm."""
    value, unit = text.split()
    if unit != "mm":
        raise ValueError(f"expected a length in mm, got {text!r}")
    return float(value)


def expected(folder, case):
    return tomllib.loads((folder / "expected" / f"{case}.toml").read_text())


def mm(run, key):
    return 1e3 * run["observables"][key]


def meshes(runs, bar):
    """The plain runs of a bar (no option but the mesh), coarsest first."""
    found = []
    for name, run in runs.items():
        parts = name.split("-")
        if len(parts) == 2 and parts[0] == bar and parts[1].isdigit():
            found.append(run)
    return sorted(found, key=lambda r: r["elements_across"])


def run_order(name):
    """Runs by bar, then by mesh, then by option: copper-8 before copper-16."""
    return [(0, int(part)) if part.isdigit() else (1, part) for part in name.split("-")]


def pct(value, reference):
    return f"{100 * (value / reference - 1):+.2f} %"


def command(run):
    """The run's command line as summary.json holds it, from the program name on."""
    words = run["command_line"][1:]
    quoted = [w if all(c.isalnum() or c in "-_./=:" for c in w) else f"'{w}'" for w in words]
    return "impactsph " + " ".join(quoted)


def options(run):
    """The run's options beyond the case, the mesh and the output (`--hourglass 0.02`), as summary.json holds
    them."""
    words, kept, skip = run["command_line"][3:], [], False
    for w in words:
        if skip:
            skip = False
        elif w in ("--elements-across", "--out"):
            skip = True
        elif w not in ("--quiet", "-q"):
            kept.append(w if all(c.isalnum() or c in "-_./=:" for c in w) else f"'{w}'")
    return " ".join(kept)


# Changes below this share of the value are within what the end time's phase of the bars' elastic ringing
# moves (the copper's length by about +-0.02 mm between 64 and 80 us, history.csv): no order is read from them.
RINGING = 1e-3


def order(values):
    """Observed order and Richardson extrapolation of the last three values (meshes halving): the changes d1,
    d2, p = log2(|d1 / d2|) and f + d2 / (2^p - 1); p and the extrapolation None where the changes differ in
    sign, or the order is below 0.5 and the last change below RINGING of the value."""
    f1, f2, f3 = values[-3:]
    d1, d2 = f2 - f1, f3 - f2
    if d1 == 0 or d2 == 0 or (d1 > 0) != (d2 > 0):
        return d1, d2, None, None
    p = math.log2(abs(d1 / d2))
    if p < 0.5:
        return d1, d2, (None if abs(d2) < RINGING * abs(f3) else p), None
    return d1, d2, p, f3 + d2 / (2 ** p - 1)


def peak_strain(run):
    return run["peak_plastic_strain"]


def energy_cells(run):
    e = run["energy"]
    return (f"{100 * run['totals']['energy_drift_relative']:+.3f} % | {100 * e['peak_hourglass_over_internal']:.2f} % | "
            f"{100 * e['wall_J'] / run['totals']['initial_energy_J']:.2f} %")


def mesh_table(rows, length_ref, face_ref, face_label, face_scale):
    out = [f"| elements across | elements | steps | wall [s] | final length [mm] | vs {length_ref:g} mm | "
           f"{face_label} [mm] | vs {face_ref:g} mm | peak plastic strain | energy drift | hourglass / internal (peak) | "
           "wall's share |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        length, face = mm(r, "final_length"), face_scale * mm(r, "impact_face_diameter")
        out.append(f"| {r['elements_across']} | {r['elements']} | {r['steps']} | {r['wall_time_s']:.1f} | {length:.4f} | "
                   f"{pct(length, length_ref)} | {face:.4f} | {pct(face, face_ref)} | {peak_strain(r):.2f} | "
                   f"{energy_cells(r)} |")
    return "\n".join(out)


def order_table(rows, items):
    """items: (label, values in mm, reference in mm)."""
    n = [r["elements_across"] for r in rows[-3:]]
    out = [f"| quantity | at {n[0]} / {n[1]} / {n[2]} across [mm] | changes [mm] | observed order | extrapolated [mm] | "
           "extrapolated vs target |",
           "|---|---|---|---|---|---|"]
    for label, values, reference in items:
        d1, d2, p, limit = order(values)
        v = values[-3:]
        if p is None and abs(d2) < RINGING * abs(v[2]):
            p_text = f"none: the last change is below {100 * RINGING:g} % of the value"
        else:
            p_text = "-" if p is None else f"{p:.2f}"
        out.append(f"| {label} | {v[0]:.4f} / {v[1]:.4f} / {v[2]:.4f} | {d1:+.4f}, {d2:+.4f} | {p_text} | "
                   f"{'-' if limit is None else f'{limit:.4f}'} | {'-' if limit is None else pct(limit, reference)} |")
    return "\n".join(out)


def verdict(label, values, reference, tolerance, meshes_across):
    worst = max(abs(v / reference - 1) for v in values)
    gaps = ", ".join(f"{pct(v, reference)} at {n}" for v, n in zip(values, meshes_across))
    if worst <= tolerance:
        return f"- {label}: within {100 * tolerance:g} % of {reference:g} mm at every mesh ({gaps}): **met**."
    return (f"- {label}: **missed**: {gaps} against {reference:g} mm; the target is {100 * tolerance:g} %, the largest "
            f"gap {100 * worst:.2f} %.")


def zero_crossing(run):
    """Time (s) the mean axial velocity of the history first reaches zero, interpolated between rows."""
    h = run["history"]
    for a, b in zip(h, h[1:]):
        if a["axial_velocity_m_s"] < 0 <= b["axial_velocity_m_s"]:
            return a["time_s"] + (b["time_s"] - a["time_s"]) * (-a["axial_velocity_m_s"]) / (
                b["axial_velocity_m_s"] - a["axial_velocity_m_s"])
    return float("nan")


def profile_plot(folder, runs):
    """profiles.png: the outer surface of each plain run, both bars side by side."""
    blocks, plots = [], {"bilinear": [], "copper": []}
    colours = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd"]
    for bar in plots:
        for k, r in enumerate(meshes(runs, bar)):
            with open(folder / "runs" / r["name"] / "profile.csv") as f:
                rows = list(csv.DictReader(f))
            block = f"$p_{bar}_{r['elements_across']}"
            blocks.append(block + " << EOD\n" + "".join(
                f"{1e3 * float(row['radius_m']):.6g} {1e3 * float(row['height_m']):.6g}\n" for row in rows) + "EOD")
            plots[bar].append(f"{block} u 1:2 w l lw 2 lc rgb '{colours[k % len(colours)]}' "
                              f"t '{r['elements_across']} across'")
    script = "\n".join(blocks) + "\n" + "\n".join([
        "set terminal pngcairo size 1100,700 noenhanced font 'Sans,11'",
        "set output 'profiles.png'",
        "set multiplot layout 1,2 title 'Outer surface at the end time by finite elements (verification/fe2d), by mesh'",
        "set xlabel 'radius [mm]'", "set ylabel 'height above the wall [mm]'", "set size ratio -1", "set grid",
        "set key top right",
        "set title 'bilinear benchmark (cases/taylor-bar-bilinear)'",
        "plot [0:8][0:23] " + ", ".join(plots["bilinear"]),
        "set title 'OFHC copper (cases/taylor-bar)'",
        "plot [0:8][0:19] " + ", ".join(plots["copper"]),
        "unset multiplot", "unset output", ""])
    (folder / "profiles.gp").write_text(script)
    if shutil.which("gnuplot"):
        subprocess.run(["gnuplot", "profiles.gp"], cwd=folder, check=True)
    else:
        print("gnuplot is not installed: profiles.png not drawn (profiles.gp is there)", file=sys.stderr)


def main():
    folder = Path(sys.argv[1])
    runs = load_runs(folder)
    bil, cu = meshes(runs, "bilinear"), meshes(runs, "copper")
    eb, ec = expected(folder, "taylor-bar-bilinear"), expected(folder, "taylor-bar")
    length_ref, radius_ref = quantity_mm(eb["final_length"]["value"]), quantity_mm(eb["foot_radius"]["value"])
    exp_length, exp_face = quantity_mm(ec["final_length"]["value"]), quantity_mm(ec["impact_face_diameter"]["value"])
    exp_length_tol, exp_face_tol = ec["final_length"]["tolerance"], ec["impact_face_diameter"]["tolerance"]
    fe_tolerance = 0.01
    cpu = bil[-1]["hardware"]["cpu"] if bil else ""

    md = ["# The Taylor bars by axisymmetric finite elements",
          "",
          "Written by `python3 verification/fe2d/report.py verification/reports/fe2d` from the runs that "
          "`bash verification/fe2d/report.sh` keeps in runs/ here (summary.json, profile.csv, history.csv of each; "
          "each run's command is in the last section). The solver and its equations: "
          "[verification/fe2d/README.md](../../fe2d/README.md); its defaults: "
          f"CFL {bil[-1]['numerics']['cfl']:g}, hourglass stiffness {bil[-1]['numerics']['hourglass_stiffness']:g}, "
          f"bulk viscosity {bil[-1]['numerics']['bulk_viscosity_linear']:g} / "
          f"{bil[-1]['numerics']['bulk_viscosity_quadratic']:g} (linear / quadratic). Wall times on one core of "
          f"{cpu}, shared with other work. The face is the end row's outermost node (the foot radius is half the "
          "face diameter); the energy columns: the balance's drift, the hourglass energy's peak share of the "
          "internal energy, and the kinetic energy the wall took where it stopped the face row's nodes.",
          "",
          "## The bilinear benchmark (cases/taylor-bar-bilinear)",
          "",
          f"Against the middle of the published finite-element range: {length_ref:g} mm long "
          f"({eb['final_length']['source']}), a foot radius of {radius_ref:g} mm ({eb['foot_radius']['source']}). "
          f"Target: within {100 * fe_tolerance:g} % of both at every mesh, converging.",
          "",
          mesh_table(bil, length_ref, radius_ref, "foot radius", 0.5),
          "",
          verdict("final length", [mm(r, "final_length") for r in bil], length_ref, fe_tolerance,
                  [r["elements_across"] for r in bil]),
          verdict("foot radius", [0.5 * mm(r, "impact_face_diameter") for r in bil], radius_ref, fe_tolerance,
                  [r["elements_across"] for r in bil]),
          "",
          "Convergence over the three finest meshes (each halves the elements' size):",
          "",
          order_table(bil, [("final length", [mm(r, "final_length") for r in bil], length_ref),
                            ("foot radius", [0.5 * mm(r, "impact_face_diameter") for r in bil], radius_ref)]),
          "",
          "The numerics at 16 elements across (the hourglass stiffness and the step):",
          "",
          "| run | final length [mm] | foot radius [mm] | energy drift | hourglass / internal (peak) | wall's share |",
          "|---|---|---|---|---|---|"]
    for name in ["bilinear-16", "bilinear-16-hourglass-0.02", "bilinear-16-hourglass-0.1", "bilinear-16-cfl-0.3"]:
        if name in runs:
            r = runs[name]
            md.append(f"| {options(r) or 'the defaults'} | {mm(r, 'final_length'):.4f} | "
                      f"{0.5 * mm(r, 'impact_face_diameter'):.4f} | {energy_cells(r)} |")
    md += ["",
           "## OFHC copper at 190 m/s (cases/taylor-bar)",
           "",
           f"Against the experiment: {exp_length:g} mm long, an impact face of {exp_face:g} mm across "
           f"(cases/taylor-bar/expected.toml: \"{ec['final_length']['source']}\"), whose targets are "
           f"{100 * exp_length_tol:g} % and {100 * exp_face_tol:g} %.",
           "",
           mesh_table(cu, exp_length, exp_face, "face diameter", 1.0),
           ""]
    if "copper-16-c-0" in runs:
        r = runs["copper-16-c-0"]
        md += [f"Without the Johnson-Cook rate term (`--set 'materials.ofhc-copper.strength.c=0'`, 16 across): "
               f"{mm(r, 'final_length'):.4f} mm long ({pct(mm(r, 'final_length'), exp_length)} against the experiment), "
               f"face {mm(r, 'impact_face_diameter'):.4f} mm ({pct(mm(r, 'impact_face_diameter'), exp_face)}).", ""]
    if len(cu) >= 3:
        md += ["Convergence over the three finest meshes:", "",
               order_table(cu, [("final length", [mm(r, "final_length") for r in cu], exp_length),
                                ("face diameter", [mm(r, "impact_face_diameter") for r in cu], exp_face)]),
               ""]
        fine = cu[-1]
        gap_l = mm(fine, "final_length") / exp_length - 1
        gap_d = mm(fine, "impact_face_diameter") / exp_face - 1
        beyond = abs(gap_l) > exp_length_tol or abs(gap_d) > exp_face_tol
        md += [f"At {fine['elements_across']} across the finite elements give {pct(mm(fine, 'final_length'), exp_length)} "
               f"in length and {pct(mm(fine, 'impact_face_diameter'), exp_face)} in face diameter against the "
               "experiment" + (f": **beyond the {100 * exp_length_tol:g} % / {100 * exp_face_tol:g} % targets**. The "
                               "material model that the SPH solves, solved by a second method, misses the experiment: "
                               "that gap is the Johnson-Cook data's (with the total strain rate in its rate term, as "
                               "both solvers take it), not the SPH's, and the SPH copper bar is to be held to the "
                               "finite-element answer, with the experiment shown beside it "
                               "(cases/taylor-bar/fe-vs-sph/report.md)." if beyond else
                               ", within the SPH's targets."),
               ""]
    if "wall-rebound-16" in runs:
        r = runs["wall-rebound-16"]
        t0 = zero_crossing(r)
        md += ["## The elastic bar (cases/wall-rebound, 16 across)", "",
               f"The mean axial velocity crosses zero at {1e6 * t0:.3f} us (from history.csv's rows), the bar leaves the "
               f"wall and ends at {r['final_axial_velocity_m_s']:.3f} m/s (impact 10 m/s); energy drift "
               f"{100 * r['totals']['energy_drift_relative']:+.4f} %. The test against bar theory (L / c_bar, the "
               "wall's force) is verification/analytic_fe2d.cpp (label `analytic`).", ""]
    md += ["## Profiles", "",
           "The outer surface (nodes of the outer column) at the end time, each mesh:", "",
           "![profiles](profiles.png)", ""]
    pictures = sorted(folder.glob("picture-*.png"))
    if pictures:
        md += ["The finest runs' meshes coloured by plastic strain (`picture.png` of `impactsph taylor-fe`):", ""]
        md += [f"![{p.stem}]({p.name})" for p in pictures]
        md.append("")
    md += ["## The runs", "", "| run | command | wall [s] |", "|---|---|---|"]
    for name, r in sorted(runs.items(), key=lambda item: run_order(item[0])):
        md.append(f"| {name} | `{command(r)}` | {r['wall_time_s']:.1f} |")
    md.append("")
    (folder / "report.md").write_text("\n".join(md))
    profile_plot(folder, runs)


if __name__ == "__main__":
    main()
