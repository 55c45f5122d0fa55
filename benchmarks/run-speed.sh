#!/bin/bash
# One run of the 8 mm plate, by an earlier build (BEFORE) and by this one (AFTER) in turn on the same machine:
# the time to the same run's answer, each build with its own defaults (integrator, step factor, early stop).
# Writes OUT.md from the two runs' summary.json.
#
#   BEFORE=/path/to/impactsph-of-c5bc829 BEFORE_COMMIT=c5bc829 BEFORE_CASE=<its cases/plate-8mm/case.toml> \
#     SPEED=151.6 SPACING=1 bash benchmarks/run-speed.sh
#
# Settings (environment): SPEED (m/s, default 151.6), SPACING (mm, default 1), THREADS (default 2), BEFORE_CASE
# (the case file the earlier build reads, default cases/plate-8mm/case.toml), BEFORE_SETS (its extra --set, one
# string: e.g. the coarse rim that this build's case file holds), RUNS (runs/run-speed), OUT
# (docs/speed/run-speed-<SPACING>mm), NOTE (what else ran on the machine), REPORT_ONLY=1 (no runs: the report
# from RUNS). A run whose summary.json says it completed is kept.
set -euo pipefail
cd "$(dirname "$0")/.."
BEFORE=${BEFORE:?set BEFORE to an impactsph binary built at an earlier commit}
BEFORE_COMMIT=${BEFORE_COMMIT:?set BEFORE_COMMIT to the commit BEFORE was built at}
BEFORE_CASE=${BEFORE_CASE:-cases/plate-8mm/case.toml}
BEFORE_SETS=${BEFORE_SETS:-}
AFTER=${AFTER:-build/impactsph}
AFTER_COMMIT=${AFTER_COMMIT:-$(git rev-parse --short HEAD)}
SPEED=${SPEED:-151.6}
SPACING=${SPACING:-1}
THREADS=${THREADS:-2}
RUNS=${RUNS:-runs/run-speed}
OUT=${OUT:-docs/speed/run-speed-${SPACING}mm}
NOTE=${NOTE:-not recorded}
OUT=${OUT%.md}

one() {  # one LABEL EXE CASE SETS
  local dir="$RUNS/$1-$SPEED"
  if [ "${REPORT_ONLY:-0}" = 1 ]; then return; fi
  if [ -f "$dir/summary.json" ] && grep -q '"completed": true' "$dir/summary.json"; then
    echo "run-speed: $dir done before, kept"
    return
  fi
  local extra=()
  if [ -n "$4" ]; then extra=(--set "$4"); fi
  "$2" run "$3" --spacing "${SPACING}mm" --threads "$THREADS" -q --set output.vtu=false "${extra[@]}" \
    --set "projectile.velocity=$SPEED m/s" --out "$dir"
}
one before "$BEFORE" "$BEFORE_CASE" "$BEFORE_SETS"
one after "$AFTER" cases/plate-8mm/case.toml ""

python3 - "$RUNS" "$SPEED" "$SPACING" "$THREADS" "$OUT" "$BEFORE_COMMIT" "$AFTER_COMMIT" "$NOTE" "$BEFORE_SETS" <<'EOF'
import datetime, json, os, sys
runs, speed, spacing, threads, out, before_commit, after_commit, note, before_sets = sys.argv[1:]
rows = {}
for label in ("before", "after"):
    s = json.load(open(os.path.join(runs, f"{label}-{speed}", "summary.json")))
    obs = s.get("observables", {})
    rows[label] = s, obs
model = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "unknown")
with open(out + ".md", "w") as f:
    f.write(f"# One run of the 8 mm plate at {spacing} mm, {speed} m/s: before and after\n\n")
    f.write(f"Written by `BEFORE=<impactsph built at {before_commit}> BEFORE_COMMIT={before_commit} SPEED={speed} "
            f"SPACING={spacing} THREADS={threads}" + (f" BEFORE_SETS='{before_sets}'" if before_sets else "") +
            f" NOTE=\"{note}\" bash benchmarks/run-speed.sh` "
            f"({datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}); do not edit by hand.\n\n")
    f.write("Each build runs `impactsph run cases/plate-8mm/case.toml` (the earlier build: the case file as it stood "
            f"at its commit) with its own defaults, {threads} threads, in turn on the same machine.\n\n")
    f.write(f"| machine | {model}, {os.cpu_count()} cores |\n|---|---|\n| also running | {note} |\n\n")
    f.write("| build | commit | solver | particles | mean neighbours | steps | simulated [us] | stopped early | "
            "perforated | residual [m/s] | wall [s] | particle-steps/s |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for label, commit in (("before", before_commit), ("after", after_commit)):
        s, obs = rows[label]
        f.write(f"| {label} | {commit} | {s['solver']} | {s['particles']} | {s['mean_neighbours']:.1f} | {s['steps']} | "
                f"{1e6 * s['simulated_time_s']:.0f} | {s.get('stopped_early', 'no')} | "
                f"{'yes' if obs.get('perforated') else 'no'} | {obs.get('residual_velocity', float('nan')):.1f} | "
                f"{s['wall_time_s']:.0f} | {s['particle_steps_per_second']:.3g} |\n")
    b, a = rows["before"][0], rows["after"][0]
    same = bool(rows["before"][1].get("perforated")) == bool(rows["after"][1].get("perforated"))
    f.write(f"\n**The run takes {a['wall_time_s'] / b['wall_time_s']:.2f} of its former wall time "
            f"({b['wall_time_s'] / a['wall_time_s']:.2f}x faster)**, " +
            ("with the same verdict." if same else "**with a different verdict**.") + "\n")
print(f"wrote {out}.md")
EOF
