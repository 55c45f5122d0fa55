#!/usr/bin/env bash
# `impactsph ballistic-limit` stopped with two Ctrl-C and started again, on the coarse 8 mm plate of
# cli.ballistic_limit (2.5 mm, 40 us; about 20 s on two cores). The first SIGINT lets the runs in flight
# go on, the second stops them at their next step with a checkpoint: exit 130, ballistic.json says
# "interrupted". The same command then continues both ends from their checkpoints and finishes the
# search; a third time every run is taken from its summary.json and none runs again.
# Usage: ballistic_resume.sh IMPACTSPH CASE OUT_DIR
set -euo pipefail
exe=$1 case=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL: $*" >&2; for f in "$out"/log*.txt; do [ -f "$f" ] && { echo "--- $f" >&2; cat "$f" >&2; }; done; exit 1; }
runs="$out/search"
search=("$exe" ballistic-limit "$case" --from 50 --to 600 --tolerance 100 --jobs 2 --spacing 2.5mm
        --set time.end=40us --set output.vtu=false --out "$runs")
status() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$runs/ballistic.json"; }

"${search[@]}" > "$out/log1.txt" 2>&1 &
pid=$!
# Wait until both ends have written their third row of totals.csv, well before their end at 40 us.
rows() { [ -f "$1/totals.csv" ] && wc -l < "$1/totals.csv" || echo 0; }
for _ in $(seq 1 1200); do
  [ "$(rows "$runs/v_50")" -ge 4 ] && [ "$(rows "$runs/v_600")" -ge 4 ] && break
  kill -0 "$pid" 2>/dev/null || fail "the search ended before its first runs had stepped"
  sleep 0.05
done
kill -INT "$pid"
sleep 0.3
kill -INT "$pid"
rc=0; wait "$pid" || rc=$?
[ "$rc" -eq 130 ] || fail "a search stopped twice should exit 130, got $rc"
[ "$(status)" = interrupted ] || fail "ballistic.json status is '$(status)', not 'interrupted'"
for v in 50 600; do
  [ -f "$runs/v_$v/checkpoint.bin" ] || fail "the stopped run at $v m/s left no checkpoint"
  grep -q '"completed": false' "$runs/v_$v/summary.json" || fail "v_$v/summary.json does not say the run is incomplete"
  grep -q " $v m/s  stopped; its checkpoint is in " "$out/log1.txt" || fail "the stop of the $v m/s run was not reported"
done

"${search[@]}" > "$out/log2.txt" 2>&1 || fail "the continued search failed"
for v in 50 600; do
  grep -Eq "^ +$v m/s +(yes|no) .*\(continued from its checkpoint\)$" "$out/log2.txt" || fail "the $v m/s run was not continued"
done
[ "$(status)" = done ] || fail "ballistic.json status is '$(status)' after the continued search"
grep -q "^ballistic limit: " "$out/log2.txt" || fail "the continued search printed no limit"
cp "$runs/ballistic.csv" "$out/ballistic2.csv"
sums=$(md5sum "$runs"/v_*/summary.json)

"${search[@]}" > "$out/log3.txt" 2>&1 || fail "the third search failed"
ran=$(grep -Ec "^ +[0-9.]+ m/s +(yes|no) " "$out/log3.txt" || true)
reused=$(grep -c "(finished earlier in this folder)$" "$out/log3.txt" || true)
[ "$ran" -ge 4 ] && [ "$ran" -eq "$reused" ] || fail "the third search ran $ran runs, $reused of them taken from summary.json"
[ "$(md5sum "$runs"/v_*/summary.json)" = "$sums" ] || fail "a finished run was run again"
cmp -s "$runs/ballistic.csv" "$out/ballistic2.csv" || fail "ballistic.csv changed when nothing ran"
[ "$(grep "^ballistic limit: " "$out/log3.txt")" = "$(grep "^ballistic limit: " "$out/log2.txt")" ] || fail "another limit from the same runs"
echo "ballistic-limit resume: OK"
