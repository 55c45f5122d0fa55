#!/usr/bin/env bash
# `impactsph sweep` stopped and started again: four elastic-wave runs at 1 mm, one at a time (about
# 0.3 s, 0.5 s, 5 s and 0.5 s on one core). SIGTERM to the sweep while the third runs must stop that run
# with a checkpoint and end the sweep (exit 130) without starting the fourth; the same command then skips
# the two complete runs (their summary.json is not touched), continues the third from its checkpoint to the
# same final state as an uninterrupted run, and runs the fourth.
# Usage: sweep_resume.sh IMPACTSPH CASES_DIR OUT_DIR
set -euo pipefail
exe=$1 cases=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL: $*" >&2; for f in "$out"/log1.txt "$out"/log2.txt; do [ -f "$f" ] && cat "$f" >&2; done; exit 1; }
cat > "$out/resume.toml" <<TOML
[sweep]
name = "resume"
case = "$cases/elastic-wave/case.toml"
set = ["output.vtu=false"]

[axes]
spacing = ["1 mm"]
"time.end" = ["2 us", "4 us", "30 us", "5 us"]
TOML
runs="$out/runs"
third="$runs/spacing-1mm__time.end-30us"

"$exe" sweep "$out/resume.toml" --out "$runs" --jobs 1 > "$out/log1.txt" 2>&1 &
pid=$!
# Wait until the third run has stepped past 0.5 us (its second row in totals.csv: its stop handlers are
# installed by then), well before its end at 30 us.
for _ in $(seq 1 1200); do
  [ -f "$third/totals.csv" ] && [ "$(wc -l < "$third/totals.csv")" -ge 3 ] && break
  kill -0 "$pid" 2>/dev/null || fail "the sweep ended before its third run had stepped"
  sleep 0.05
done
[ -f "$third/totals.csv" ] || fail "the third run never started"
kill -TERM "$pid"
# A run still to do must not keep the stopped sweep waiting: it ends once the run in flight has stopped.
for _ in $(seq 1 1200); do kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
kill -0 "$pid" 2>/dev/null && { kill -KILL "$pid"; fail "the stopped sweep had not ended 60 s after its run stopped"; }
rc=0; wait "$pid" || rc=$?
[ "$rc" -eq 130 ] || fail "a stopped sweep should exit 130, got $rc"
grep -q "stopped spacing-1mm__time.end-30us" "$out/log1.txt" || fail "the third run was not reported stopped"
[ -f "$third/checkpoint.bin" ] || fail "the stopped run left no checkpoint"
grep -q '"completed": false' "$third/summary.json" || fail "the stopped run's summary.json does not say it is incomplete"
for r in spacing-1mm__time.end-4us spacing-1mm__time.end-2us; do
  grep -q '"completed": true' "$runs/$r/summary.json" || fail "$r did not complete before the stop"
done
sum1=$(md5sum "$runs"/spacing-1mm__time.end-4us/summary.json "$runs"/spacing-1mm__time.end-2us/summary.json)

"$exe" sweep "$out/resume.toml" --out "$runs" --jobs 1 > "$out/log2.txt" 2>&1 || fail "the resumed sweep failed"
grep -q "2 complete already, 2 to run (1 continued from a checkpoint)" "$out/log2.txt" || fail "the resumed sweep did not skip the complete runs"
grep -q "start  spacing-1mm__time.end-30us (from its checkpoint)" "$out/log2.txt" || fail "the cut-off run was not continued"
[ "$(md5sum "$runs"/spacing-1mm__time.end-4us/summary.json "$runs"/spacing-1mm__time.end-2us/summary.json)" = "$sum1" ] ||
  fail "a complete run was run again"
grep -q '"completed": true' "$third/summary.json" || fail "the continued run did not complete"
grep -q "(restart)" "$third/log.txt" && fail "the restart banner should be silenced by --quiet"

# The same run without a stop: the bodies' final state must be the same bits (restart is exact).
"$exe" run "$cases/elastic-wave/case.toml" --spacing "1 mm" --set output.vtu=false --set "time.end=30 us" \
  --out "$out/straight" --threads 1 --quiet > /dev/null
extract() { python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(s["steps"], [(b["velocity_m_s"], b["kinetic_energy_J"]) for b in s["bodies"]])' "$1"; }
[ "$(extract "$third/summary.json")" = "$(extract "$out/straight/summary.json")" ] ||
  fail "the continued run ended elsewhere than an uninterrupted one: $(extract "$third/summary.json") vs $(extract "$out/straight/summary.json")"

# The table: a header with the axes and the costs, and one complete row per run.
head -1 "$runs/sweep.csv" | grep -q "^run,spacing,time.end,status,particles,steps,wall_time_s,particle_steps_per_s,mean_neighbours,energy_drift,correction_fallbacks" ||
  fail "unexpected sweep.csv header: $(head -1 "$runs/sweep.csv")"
[ "$(grep -c ',done,900,' "$runs/sweep.csv")" -eq 4 ] || fail "sweep.csv should have 4 complete rows of 900 particles: $(cat "$runs/sweep.csv")"
grep -q "^| spacing-1mm__time.end-30us | 1 mm | 30 us | done | 900 | [0-9]* |" "$runs/sweep.md" || fail "sweep.md lacks the third run: $(cat "$runs/sweep.md")"
echo "sweep resume: OK"
