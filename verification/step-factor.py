#!/usr/bin/env python3
"""The largest stable step factor of each integrator, case by case.

Runs every case of the list below (coarse spacings, so that the whole study fits an afternoon on two cores)
with the leapfrog at rising step factors (numerics.cfl) and with the midpoint rule at its former default and
above, stopping a ladder at its first failure, and writes verification/reports/step-factor/report.md and
runs.json from the runs' summary.json files (nothing typed in).

A run holds at a factor when it reaches its end (or settles) without a divergence, its energy drift
(kinetic + internal + contact work) stays within 0.5 %, and each of its figures lies within 1 % of the same
case's leapfrog run at 0.1 (the time-converged answer; for an elastic case without observables, the final
kinetic energy of each body). The largest factor that holds is reported per case and integrator; the
defaults of docs/time-integration.md are chosen from it with a margin.

    python3 verification/step-factor.py            # run what is missing, then write the report
    REPORT_ONLY=1 python3 verification/step-factor.py
    CASES=plate-298,taylor python3 verification/step-factor.py   # some cases only

Environment: BUILD_DIR (default build) or EXE (an impactsph binary), RUNS (default runs/step-factor), THREADS (default 2). A run is
skipped when its summary.json or its failure log exists (delete the folder to run it again).
"""
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("EXE", os.path.join(ROOT, os.environ.get("BUILD_DIR", "build"), "impactsph"))
RUNS = os.path.join(ROOT, os.environ.get("RUNS", "runs/step-factor"))
THREADS = os.environ.get("THREADS", "2")
OUT = os.path.join(ROOT, "verification", "reports", "step-factor")
DRIFT_LIMIT = 0.005
FIGURE_LIMIT = 0.01
REFERENCE_FACTOR = 0.1

LEAPFROG_LADDER = [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
MIDPOINT_LADDER = [0.2, 0.4, 0.6, 0.8, 1.0]

# name, case file, extra arguments, figures compared: (summary.json observable or "kinetic" for the bodies'
# final kinetic energies, how it is judged: "relative" within 1 % of the reference, "impact" within 1 % of the
# impact speed, "verdict" the same, "energy" within 1 % of the energy in play)
RELATIVE, IMPACT, VERDICT, ENERGY, REPORTED = "relative", "impact", "verdict", "energy", "reported"
KINETIC = [("kinetic", ENERGY)]
PLATE = [("perforated", VERDICT), ("residual_velocity", IMPACT)]
TAYLOR = [("final_length", RELATIVE), ("impact_face_diameter", RELATIVE)]
CASES = [
    ("elastic-wave", "cases/elastic-wave/case.toml", ["--spacing", "1mm"], KINETIC),
    ("elastic-wave-interface", "cases/elastic-wave-interface/case.toml", [], KINETIC),
    ("hugoniot", "cases/hugoniot-4340/case.toml", ["--spacing", "0.25mm"], KINETIC),
    ("wall-rebound", "cases/wall-rebound/case.toml", ["--spacing", "0.5mm"], KINETIC),
    ("taylor", "cases/taylor-bar/case.toml", ["--spacing", "0.8467mm"], TAYLOR),
    ("taylor-bilinear", "cases/taylor-bar-bilinear/case.toml", ["--spacing", "0.8mm"], TAYLOR),
    ("plate-298", "cases/plate-8mm/case.toml", ["--spacing", "2mm"], PLATE),
    ("plate-160", "cases/plate-8mm/case.toml", ["--spacing", "2mm", "--set", "projectile.velocity=160 m/s"],
     [("perforated", VERDICT)]),
    ("plate-12mm", "cases/plate-12mm/case.toml", ["--spacing", "2mm"], PLATE),
    ("plate-oblique", "cases/plate-8mm-oblique/case.toml", ["--spacing", "2mm", "--set", "time.end=60 us"],
     [("residual_velocity", IMPACT)]),
    ("tile", "cases/ceramic-tile/case.toml", ["--spacing", "1.5875mm"],
     [("residual_velocity", IMPACT), ("residual_mass", REPORTED)]),
    ("hard-fragments", "cases/hard/fragments.toml", [], KINETIC),
    ("hard-hypervelocity", "cases/hard/hypervelocity-al-4kms.toml", [], KINETIC),
    ("hard-oblique-45", "cases/hard/oblique-45-1000.toml", [], KINETIC),
    ("hard-shear-block", "cases/hard/shear-block.toml", [], KINETIC),
    ("hard-single-fragments", "cases/hard/single-particle-fragments.toml", [], KINETIC),
    ("hard-tension-block", "cases/hard/tension-block.toml", [], KINETIC),
]


def run_dir(name, integrator, factor):
    return os.path.join(RUNS, f"{name}-{integrator}-{factor:g}")


def run(case, integrator, factor):
    name, case_file, extra, _ = case
    out = run_dir(name, integrator, factor)
    summary = os.path.join(out, "summary.json")
    failed = out + ".failed"
    if os.path.exists(summary) or os.path.exists(failed):
        return
    os.makedirs(RUNS, exist_ok=True)
    cmd = [EXE, "run", case_file, *extra, "--out", out, "--threads", THREADS, "--quiet", "--set", "output.vtu=false",
           "--set", "output.picture=false", "--set", f"numerics.integrator={integrator}", "--set",
           f"numerics.cfl={factor:g}"]
    print(f"step-factor: {name} {integrator} {factor:g}", flush=True)
    start = time.time()
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if p.returncode != 0:
        with open(failed, "w") as f:
            f.write(f"exit {p.returncode} after {time.time() - start:.1f} s\n{' '.join(cmd)}\n{p.stdout}\n{p.stderr}")


def load(case, integrator, factor):
    out = run_dir(case[0], integrator, factor)
    summary = os.path.join(out, "summary.json")
    if os.path.exists(summary):
        with open(summary) as f:
            return json.load(f)
    if os.path.exists(out + ".failed"):
        with open(out + ".failed") as f:
            text = f.read()
        reason = next((l.strip() for l in text.splitlines() if l.startswith("error")), text.splitlines()[0])
        return {"failed": reason}
    return None


def figures(summary, specs):
    """{label: (value, how it is judged)}"""
    out = {}
    for name, how in specs:
        if name == "kinetic":
            for b in summary["bodies"]:
                out[f"{b['name']} kinetic energy"] = (b["kinetic_energy_J"], how)
        else:
            v = summary["observables"].get(name)
            out[name] = (float(v) if v is not None else None, how)
    return out


def judge(case, s, ref):
    """(holds, why) of a run against the case's reference run."""
    if s is None:
        return None, "not run"
    if "failed" in s:
        return False, s["failed"]
    if not s.get("completed", False):
        return False, "stopped before its end"
    drift = s["totals"]["energy_drift_relative"]
    if abs(drift) > DRIFT_LIMIT:
        return False, f"energy drift {100 * drift:.2f} %"
    if ref is None or "failed" in ref:
        return True, "no reference"
    f, r = figures(s, case[3]), figures(ref, case[3])
    for k, (v, how) in f.items():
        rv = r[k][0]
        if v is None or rv is None:
            continue
        if how == VERDICT:
            if v != rv:
                return False, f"{k} differs"
            continue
        if how == IMPACT:
            scale = ref_impact_speed(case)
        elif how == REPORTED:
            continue
        elif how == ENERGY:
            scale = max(abs(rv), sum(b["kinetic_energy_J"] + b["internal_energy_J"] for b in ref["bodies"]))
        else:
            scale = max(abs(rv), 1e-12)
        if abs(v - rv) > FIGURE_LIMIT * scale:
            return False, f"{k} {100 * (v - rv) / scale:+.2f} % of {'the impact speed' if how == IMPACT else 'it'}"
    return True, ""


def ref_impact_speed(case):
    """The projectile's impact speed of a case (m/s): its --set, or its case file's velocity."""
    for k, a in enumerate(case[2]):
        if a.startswith("projectile.velocity="):
            return float(a.split("=")[1].split()[0])
    import re
    with open(os.path.join(ROOT, case[1])) as f:
        text = f.read()
    block = text[text.index('name = "projectile"'):] if 'name = "projectile"' in text else text
    return float(re.search(r'velocity\s*=\s*"([0-9.]+)\s*m/s"', block).group(1))


def ladder(case, integrator, factors):
    """Runs the ladder up to the first factor that does not hold."""
    for f in factors:
        run(case, integrator, f)
        ok, _ = judge(case, load(case, integrator, f), load(case, "leapfrog", REFERENCE_FACTOR))
        if ok is False:
            break


def fmt(x, digits=4):
    return "-" if x is None else f"{x:.{digits}g}"


def report(cases):
    rows, summary_rows, data = [], [], {}
    for case in cases:
        ref = load(case, "leapfrog", REFERENCE_FACTOR)
        best = {}
        for integrator, factors in (("leapfrog", [REFERENCE_FACTOR] + LEAPFROG_LADDER), ("midpoint", MIDPOINT_LADDER)):
            for f in factors:
                s = load(case, integrator, f)
                if s is None:
                    continue
                ok, why = judge(case, s, ref)
                if ok and (integrator not in best or f > best[integrator][0]):
                    best[integrator] = (f, s)
                data.setdefault(case[0], []).append({"integrator": integrator, "factor": f, "holds": ok, "why": why,
                                                     "summary": s})
                if "failed" in s:
                    rows.append(f"| {case[0]} | {integrator} | {f:g} | - | - | - | no: {why} |")
                    continue
                figs = ", ".join(f"{k} {fmt(v)}" for k, (v, _) in figures(s, case[3]).items())
                evals = s["steps"] * (1 if integrator == "leapfrog" else 2)
                rows.append(f"| {case[0]} | {integrator} | {f:g} | {s['steps']} ({evals}) | "
                            f"{100 * s['totals']['energy_drift_relative']:.3f} % | {figs} | "
                            f"{'yes' if ok else 'no: ' + why} |")
        lf, mp = best.get("leapfrog"), best.get("midpoint")
        ratio = "-"
        if lf and mp:
            ratio = f"{(2 * mp[1]['steps']) / lf[1]['steps']:.2f}"
        summary_rows.append(f"| {case[0]} | {fmt(lf[0] if lf else None)} | {fmt(mp[0] if mp else None)} | {ratio} |")
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "runs.json"), "w") as f:
        json.dump(data, f, indent=1)
    lines = [
        "# The largest stable step factor, case by case",
        "",
        f"Written by `python3 verification/step-factor.py` ({time.strftime('%Y-%m-%d')}); do not edit by hand. Each case "
        "runs at a coarse spacing with both integrators (numerics.integrator) at rising step factors "
        "(numerics.cfl, C in dt = C min h/(c + |v|)); a ladder stops at its first failure. A run holds when it "
        f"reaches its end without a divergence, its energy drift stays within {100 * DRIFT_LIMIT:g} % and each "
        f"figure lies within {100 * FIGURE_LIMIT:g} % of the same case's leapfrog run at {REFERENCE_FACTOR:g} (the "
        "time-converged answer; a residual velocity within 1 % of the impact speed, a verdict the same, a residual "
        "mass reported only (at the tile's coarse spacing the rod is 39 particles of the quarter model, each 5 % "
        "of its residual mass), a body's "
        "kinetic energy within 1 % of the energy in play). Near the ballistic limit (plate-160) the residual "
        "velocity is not a measure of the step: it moves by several m/s between any two steps, so only the "
        "verdict is judged there.",
        "",
        "## Summary",
        "",
        "| case | leapfrog: largest factor that holds | midpoint: largest factor that holds | evaluations, midpoint / leapfrog, each at its largest |",
        "|---|---|---|---|",
        *summary_rows,
        "",
        "## Every run",
        "",
        "| case | integrator | factor | steps (evaluations) | energy drift | figures | holds |",
        "|---|---|---|---|---|---|---|",
        *rows,
        "",
    ]
    with open(os.path.join(OUT, "report.md"), "w") as f:
        f.write("\n".join(lines))
    print(f"step-factor: wrote {os.path.relpath(os.path.join(OUT, 'report.md'), ROOT)}")


def main():
    only = os.environ.get("CASES")
    cases = [c for c in CASES if not only or c[0] in only.split(",")]
    if not os.environ.get("REPORT_ONLY"):
        if not os.access(EXE, os.X_OK):
            sys.exit(f"step-factor: no executable {EXE}; build first (bash scripts/impactsph.sh build)")
        for case in cases:
            run(case, "leapfrog", REFERENCE_FACTOR)
            ladder(case, "leapfrog", LEAPFROG_LADDER)
            ladder(case, "midpoint", MIDPOINT_LADDER)
    report(cases)


if __name__ == "__main__":
    main()
