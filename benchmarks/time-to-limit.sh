#!/bin/bash
# Time to a ballistic limit (issue 18): the same `impactsph ballistic-limit` search on the 8 mm plate, run
# by an earlier build (BEFORE) and by this one (AFTER) in turn on the same machine, each to a bracket of
# TOL m/s. With the same physics (the same bits) and the same overrides both searches make the same runs
# with the same verdicts, and the ratio of their wall times is the speed-up of the step; with BEFORE_SETS
# different from SETS (e.g. one resolution against the rim) it is the time to the answer of the whole change,
# and the report names any speed whose verdict differs. With BEFORE the same build and AFTER_ARGS another
# solver, it times the two solvers on one scene. Writes OUT.md (OUT without .md) from the searches'
# ballistic.json and the wall time of each search.
#
#   BEFORE=/path/to/impactsph-of-901a706 BEFORE_COMMIT=901a706 bash benchmarks/time-to-limit.sh
#   BEFORE=build/impactsph BEFORE_COMMIT=$(git rev-parse --short HEAD) AFTER_ARGS='--backend gpu --precision float' \
#     RUNS=runs/time-to-limit-solvers OUT=docs/speed/time-to-limit-2mm-port-vs-reference bash benchmarks/time-to-limit.sh
#
# BEFORE=none runs the AFTER search alone, where the earlier build's search would take longer than there is
# time for; NO_BEFORE (required then) says why, and the report gives the one search's time, no ratio.
#
# A search that is stopped (Ctrl-C: each run writes its checkpoint) continues where it stopped when the script
# is run again with the same settings, and its wall time is the sum of the invocations' (elapsed_parts in its
# folder, with the machine each ran on); an invocation that was killed outright leaves no part and is not counted.
#
# Settings (environment): SPACING (mm, default 2), FROM / TO (m/s, 120 / 180), TOL (m/s, 3), JOBS (2),
# SETS (extra --set arguments, one string, e.g. the coarse rim), BEFORE_SETS (the earlier build's, default SETS;
# empty: none, for a before search at one resolution against an after search with the rim), AFTER_ARGS /
# BEFORE_ARGS (further arguments of each build's search, e.g. its solver: AFTER_ARGS='--backend gpu --precision
# float'; default none), RUNS (runs/time-to-limit), OUT (docs/speed/time-to-limit-<SPACING>mm), NOTE (what else
# ran on the machine), BRACKET_NOTE (why FROM and TO are where they are, where they are not the default 120 / 180,
# e.g. set from a coarser spacing's limit), BEFORE_CASE (the case file the earlier build reads, default
# cases/plate-8mm/case.toml: the file as it stood at BEFORE_COMMIT where this one has keys that build does not
# know, e.g. from `git worktree add`), REPORT_ONLY=1 (no search: the report from RUNS and the wall times
# recorded there).
set -euo pipefail
cd "$(dirname "$0")/.."
BEFORE=${BEFORE:?set BEFORE to an impactsph binary built at an earlier commit with the same physics}
if [ "$BEFORE" = none ]; then
  BEFORE_COMMIT=none
  NO_BEFORE=${NO_BEFORE:?with BEFORE=none, set NO_BEFORE to why no earlier build searched}
else
  BEFORE_COMMIT=${BEFORE_COMMIT:?set BEFORE_COMMIT to the commit BEFORE was built at}
  NO_BEFORE=
fi
AFTER=${AFTER:-build/impactsph}
AFTER_COMMIT=${AFTER_COMMIT:-$(git rev-parse --short HEAD)}
SPACING=${SPACING:-2}
FROM=${FROM:-120}
TO=${TO:-180}
TOL=${TOL:-3}
JOBS=${JOBS:-2}
SETS=${SETS:-}
BEFORE_SETS=${BEFORE_SETS-$SETS}
AFTER_ARGS=${AFTER_ARGS:-}
BEFORE_ARGS=${BEFORE_ARGS:-}
BEFORE_CASE=${BEFORE_CASE:-cases/plate-8mm/case.toml}
RUNS=${RUNS:-runs/time-to-limit}
OUT=${OUT:-docs/speed/time-to-limit-${SPACING}mm}
NOTE=${NOTE:-nothing else}

for exe in "$BEFORE" "$AFTER"; do
  [ "$exe" = none ] && continue
  [ -x "$exe" ] || { echo "time-to-limit: no executable $exe" >&2; exit 2; }
done
search() {  # label exe sets args
  local extra=()
  if [ -n "$3" ]; then extra=(--set "$3"); fi
  local args=()
  read -r -a args <<< "$4"
  local dir="$RUNS/$1-${SPACING}mm"
  if [ "${REPORT_ONLY:-0}" = 1 ]; then return; fi
  if [ -f "$dir/elapsed_s" ]; then echo "time-to-limit: $dir done before, kept"; return; fi
  if [ -f "$dir/elapsed_parts" ]; then
    echo "time-to-limit: $dir was stopped before; continuing it (its finished runs are reused, the others go on from their checkpoints)"
  else
    rm -rf "$dir"
    mkdir -p "$dir"
  fi
  local t0 t1 status=0
  t0=$(date +%s.%N)
  "$2" ballistic-limit "$5" --spacing "${SPACING}mm" --from "$FROM" --to "$TO" --tolerance "$TOL" \
    --jobs "$JOBS" --set output.vtu=false "${extra[@]}" "${args[@]}" --out "$dir" | tee -a "$dir/search.log" || status=$?
  t1=$(date +%s.%N)
  # One line an invocation: its wall time (s) and the machine it ran on.
  printf '%s\t%s\n' "$(python3 -c "print(round($t1 - $t0, 1))")" \
    "$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores" >> "$dir/elapsed_parts"
  if [ "$status" != 0 ]; then
    echo "time-to-limit: the search in $dir stopped (exit $status); run this script again with the same settings to continue it" >&2
    exit "$status"
  fi
  python3 -c "import sys; print(round(sum(float(x.split()[0]) for x in open(sys.argv[1])), 1))" "$dir/elapsed_parts" \
    > "$dir/elapsed_s"
}
if [ "$BEFORE" != none ]; then search before "$BEFORE" "$BEFORE_SETS" "$BEFORE_ARGS" "$BEFORE_CASE"; fi
search after "$AFTER" "$SETS" "$AFTER_ARGS" cases/plate-8mm/case.toml

AFTER_SET=""
if [ "$AFTER" != build/impactsph ]; then AFTER_SET="AFTER=<impactsph built at $AFTER_COMMIT> AFTER_COMMIT=$AFTER_COMMIT "; fi
BRACKET_NOTE=${BRACKET_NOTE:-}
export AFTER_SET NO_BEFORE AFTER_ARGS BEFORE_ARGS BRACKET_NOTE BEFORE_CASE
python3 - "$RUNS" "$SPACING" "$OUT" "$BEFORE_COMMIT" "$AFTER_COMMIT" "$NOTE" "$FROM" "$TO" "$TOL" "$JOBS" "$SETS" "$BEFORE_SETS" <<'EOF'
import datetime, json, os, platform, sys
runs, spacing, out, before_commit, after_commit, note, v_from, v_to, tol, jobs, sets, before_sets = sys.argv[1:]
if before_commit == "none":
    before_sets = sets
rows = []
searches = {}
run_rows = {}
no_before = os.environ.get("NO_BEFORE", "")
bracket_note = os.environ.get("BRACKET_NOTE", "")
before_case = os.environ.get("BEFORE_CASE", "cases/plate-8mm/case.toml")
after_args = os.environ.get("AFTER_ARGS", "")
before_args = after_args if before_commit == "none" else os.environ.get("BEFORE_ARGS", "")
parts = {}
builds = (("after", after_commit),) if before_commit == "none" else (("before", before_commit), ("after", after_commit))
for label, commit in builds:
    d = os.path.join(runs, f"{label}-{spacing}mm")
    j = json.load(open(os.path.join(d, "ballistic.json")))
    elapsed = float(open(os.path.join(d, "elapsed_s")).read())
    parts_file = os.path.join(d, "elapsed_parts")
    part_lines = [l.split("\t") for l in open(parts_file).read().splitlines()] if os.path.exists(parts_file) else []
    parts[label] = (len(part_lines), sorted({l[1] for l in part_lines if len(l) > 1}))
    done = sorted(j["runs"], key=lambda r: r["v_impact_m_s"])
    searches[label] = [(r["v_impact_m_s"], r["perforated"]) for r in done]
    run_rows[label] = []
    for r in done:
        summary_file = os.path.join(r.get("dir", ""), "summary.json")
        summary = json.load(open(summary_file)) if os.path.exists(summary_file) else {}
        run_rows[label].append((r["v_impact_m_s"], r["perforated"], r.get("residual_velocity_m_s", float("nan")),
                                summary.get("particles", "(run folder gone)"), summary.get("steps", ""), r["wall_s"]))
    run_wall = sum(r["wall_s"] for r in done)
    rows.append((label, commit, len(done), j["bracket_m_s"], j["limit_m_s"], elapsed, run_wall))
same = searches.get("before") == searches["after"]
model = "unknown"
for line in open("/proc/cpuinfo"):
    if line.startswith("model name"):
        model = line.split(":", 1)[1].strip()
        break
cores = os.cpu_count()
after_env = os.environ.get("AFTER_SET", "")
before_env = (f"BEFORE=none NO_BEFORE=\"{no_before}\" " if before_commit == "none" else
              f"BEFORE=<impactsph built at {before_commit}> BEFORE_COMMIT={before_commit} ")
cmd = (f"{before_env}{after_env}SPACING={spacing} FROM={v_from} "
       f"TO={v_to} TOL={tol} JOBS={jobs}" + (f" SETS='{sets}'" if sets else "") +
       (f" BEFORE_SETS='{before_sets}'" if before_sets != sets else "") +
       (f" AFTER_ARGS='{after_args}'" if after_args else "") +
       (f" BEFORE_ARGS='{before_args}'" if before_args and before_commit != "none" else "") +
       (f" BRACKET_NOTE=\"{bracket_note}\"" if bracket_note else "") +
       (f" BEFORE_CASE=<cases/plate-8mm/case.toml at {before_commit}>" if before_case != "cases/plate-8mm/case.toml" else "") +
       f" NOTE=\"{note}\" bash benchmarks/time-to-limit.sh")


def verdict_difference():
    before, after = dict(searches["before"]), dict(searches["after"])
    if set(before) != set(after):
        return "the two searches' verdicts differ near the limit, so they ran different speeds"
    differ = [v for v in sorted(before) if before[v] != after[v]]
    return ("they ran the same speeds, and the verdicts differ at " +
            ", ".join(f"{v:g} m/s (before: {'perforated' if before[v] else 'held'}, "
                      f"after: {'perforated' if after[v] else 'held'})" for v in differ))


def search_command(extra_sets, extra_args):
    return (f"impactsph ballistic-limit cases/plate-8mm/case.toml --spacing {spacing}mm --from {v_from} --to {v_to} "
            f"--tolerance {tol} --jobs {jobs} --set output.vtu=false" + (f" --set '{extra_sets}'" if extra_sets else "") +
            (f" {extra_args}" if extra_args else ""))


with open(out + ".md", "w") as f:
    f.write(f"# Time to a ballistic limit: the 8 mm plate at {spacing} mm\n\n")
    f.write(f"Written by `{cmd}` ({datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}); "
            "do not edit by hand.\n\n")
    same_command = before_sets == sets and before_args == after_args
    if same_command:
        f.write(f"`{search_command(sets, after_args)}`, run by " + ("this build alone" if no_before else "each build in turn on the same machine") +
                "; the wall time is the whole search's, from its start to its result.\n\n")
    else:
        f.write(f"Before: `{search_command(before_sets, before_args)}`; after: "
                f"`{search_command(sets, after_args)}`; each in turn on the same machine; the wall time is the whole "
                "search's, from its start to its result.\n\n")
    if before_case != "cases/plate-8mm/case.toml" and not no_before:
        f.write(f"The earlier build read the case file as it stood at {before_commit} (this one's has keys that build "
                "does not know); the rest of the scene is the same unless the overrides above say otherwise.\n\n")
    if bracket_note:
        f.write(f"The search starts from {v_from} and {v_to} m/s: {bracket_note}\n\n")
    for label, _ in builds:
        count, machines = parts.get(label, (1, []))
        if count > 1:
            f.write(f"The {label} search was stopped and continued: its wall time is the sum of its {count} "
                    "invocations' (elapsed_parts in its folder)" +
                    (f", which ran on more than one machine ({'; '.join(machines)}).\n\n" if len(machines) > 1 else ".\n\n"))
    f.write(f"| machine | {model}, {cores} cores |\n|---|---|\n| also running | {note} |\n\n")
    f.write("| build | commit | runs | bracket (m/s) | limit (m/s) | search wall time | sum of the runs' wall times |\n")
    f.write("|---|---|---|---|---|---|---|\n")
    for label, commit, n, bracket, limit, elapsed, run_wall in rows:
        f.write(f"| {label} | {commit} | {n} | {bracket[0]:g}-{bracket[1]:g} | {limit:.1f} | {elapsed:.0f} s | "
                f"{run_wall:.0f} s |\n")
    if no_before:
        f.write(f"\nNo earlier build's search, so no ratio: {no_before}\n")
    else:
        b, a = rows[0], rows[1]
        f.write(f"\n**The search takes {a[5] / b[5]:.2f} of its former wall time ({b[5] / a[5]:.2f}x faster).** ")
        if not same_command:
            what = []
            if before_sets != sets:
                what.append("different scenes (the overrides above)")
            if before_args != after_args:
                what.append(f"different arguments (`{before_args or 'none'}` against `{after_args or 'none'}`)")
            f.write("The two searches ran " + " and ".join(what) + ", so the ratio is the time to the answer of the "
                    "one against the other, " + ("the scene's particles and the step together, not the speed of the step alone"
                                                 if before_sets != sets else "each run's whole step included")
                    + (": they ran the same speeds with the same verdicts.\n" if same else
                       "; " + verdict_difference() + ". The runs are listed below.\n"))
        elif same:
            f.write("Both searches ran the same speeds with the same verdicts (the two builds give the same bits), so "
                    "the ratio is the speed of the step alone.\n")
        else:
            f.write("**The two searches did not run the same speeds with the same verdicts**: the builds do not give "
                    "the same bits, and the ratio mixes the speed of the step with a different search.\n")
    f.write("\n| build | impact (m/s) | perforated | residual (m/s) | particles | steps | wall time |\n")
    f.write("|---|---|---|---|---|---|---|\n")
    for label, _ in builds:
        for v, perforated, residual, particles, steps, wall in run_rows[label]:
            f.write(f"| {label} | {v:g} | {'yes' if perforated else 'no'} | {residual:.1f} | {particles} | {steps} | "
                    f"{wall:.0f} s |\n")
print(open(out + ".md").read())
EOF
