#!/bin/bash
# Whole steps on the 103823-particle steel block (47^3, 53 neighbours), the block issue 18 sets its targets
# on: the reference, the gpu port's host build in float and double (cluster pairs, the default), and with
# BEFORE the reference of an earlier build. The binaries are run in turn, ROUNDS times for each thread
# count of THREADS, so that a drift of the machine's speed falls on all of them alike; the report gives
# every run, the medians and the ratios round by round. Writes OUT/block.md and OUT/block-runs.json.
#
#   bash benchmarks/block-speed.sh                                  # build/benchmarks/bench_gpu -> docs/speed/
#   BEFORE=/path/to/older/bench_gpu BEFORE_NOTE="980c694, ..." NOTE="idle" bash benchmarks/block-speed.sh
#
# Each run takes one step before the clock starts (the first allocations and lists), then steps for
# MIN_TIME seconds or more. Measure on an idle machine, or say what else ran (NOTE="...").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=${BENCH:-$root/build/benchmarks/bench_gpu}
before=${BEFORE:-}
out=${OUT:-$root/docs/speed}
rounds=${ROUNDS:-3}
threads=${THREADS:-"1 2"}
min_time=${MIN_TIME:-3}
mkdir -p "$out"
[ -x "$bench" ] || { echo "block-speed: $bench not found; build it with: cmake --build build --target bench_gpu" >&2; exit 1; }
if [ -n "$before" ] && [ ! -x "$before" ]; then echo "block-speed: BEFORE=$before is not an executable bench_gpu" >&2; exit 1; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ref='BM_ReferenceStep/103823/0/real_time'
flt='BM_GpuHostStep<gpu::Precision::Float>/103823/0/1/real_time'
dbl='BM_GpuHostStep<gpu::Precision::Double>/103823/0/1/real_time'
run() {  # label binary filter threads round
  local file="$tmp/$1.$4.$5.json"
  echo "block-speed: round $5, $4 thread(s): $1" >&2
  OMP_NUM_THREADS=$4 OMP_WAIT_POLICY=passive "$2" --benchmark_filter="^$3\$" --benchmark_min_time="$min_time" \
    --benchmark_format=json --benchmark_out="$file" > /dev/null
}
for r in $(seq 1 "$rounds"); do
  for t in $threads; do
    if [ -n "$before" ]; then run before "$before" "$ref" "$t" "$r"; fi
    run reference "$bench" "$ref" "$t" "$r"
    run float "$bench" "$flt" "$t" "$r"
    run double "$bench" "$dbl" "$t" "$r"
  done
done
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null | head -1)
[ -n "$dirty" ] && commit="$commit with uncommitted changes"
python3 - "$tmp" "$out" "$commit" "${NOTE:-}" "${BEFORE_NOTE:-$before}" "$rounds" "$threads" "$min_time" \
  "$(python3 "$root/benchmarks/machine.py")" <<'PY'
import glob, json, os, statistics, sys
tmp, out, commit, note, before_note, rounds, threads, min_time, cpu = sys.argv[1:10]
runs = []
for path in sorted(glob.glob(os.path.join(tmp, '*.json'))):
    label, t, r = os.path.basename(path)[:-5].split('.')
    with open(path) as f:
        j = json.load(f)
    b = j['benchmarks'][0]
    runs.append({'label': label, 'threads': int(t), 'round': int(r), 'particle_steps_per_s': b['particle_steps_per_s'],
                 'cpu_s_per_step': b['cpu_s_per_step'], 'neighbours': b['neighbours'], 'iterations': b['iterations']})
    ctx = j['context']
with open(os.path.join(out, 'block-runs.json'), 'w') as f:
    json.dump({'commit': commit, 'context': ctx, 'runs': runs}, f, indent=1)

names = {'before': 'reference, earlier build', 'reference': 'reference', 'float': 'gpu port host build (float)',
         'double': 'gpu port host build (double)'}
labels = [l for l in ['before', 'reference', 'float', 'double'] if any(x['label'] == l for x in runs)]
rate = {(x['label'], x['threads'], x['round']): x['particle_steps_per_s'] for x in runs}
ts = sorted({x['threads'] for x in runs})
rs = sorted({x['round'] for x in runs})
nb = statistics.mean(x['neighbours'] for x in runs)
L = ['# Whole steps on the 103823-particle block', '',
     'Written by `bash benchmarks/block-speed.sh` (commit %s, %s); do not edit by hand.' % (commit, ctx.get('date', '')),
     'The steel block of benchmarks/block_scene.hpp at 47^3 particles, %.1f neighbours within the support:' % nb,
     'whole steps (time step, neighbour list, two evaluations of the midpoint scheme), one step taken before the',
     'clock starts, then at least %s s of steps. The binaries ran in turn, in %s round(s) for each thread count, with' % (min_time, rounds),
     '`OMP_WAIT_POLICY=passive`. Particle-steps/s are wall-time rates; "per core" divides by the threads.', '',
     '| machine | %s, %s cores |' % (cpu, ctx.get('num_cpus', '?')), '|---|---|',
     '| also running | %s |' % (note or 'nothing stated (set NOTE)'), '']
if 'before' in labels:
    L += ['The earlier build: %s.' % before_note, '']
L += ['## Medians', '', '| solver | threads | particle-steps/s (median) | per core | runs (particle-steps/s) |', '|---|---|---|---|---|']
med = {}
for l in labels:
    for t in ts:
        v = [rate[(l, t, r)] for r in rs if (l, t, r) in rate]
        med[(l, t)] = statistics.median(v)
        L.append('| %s | %d | %.3g | %.3g | %s |' % (names[l], t, med[(l, t)], med[(l, t)] / t, ', '.join('%.3g' % x for x in v)))
L += ['', '## Ratios', '', 'Each ratio is taken within a round (the two binaries ran minutes apart at most), then the median and',
      'the range over the rounds.', '', '| ratio | threads | median | range over rounds |', '|---|---|---|---|']
pairs = [('reference', 'before'), ('float', 'before'), ('double', 'before'), ('float', 'reference'), ('double', 'reference')]
for a, b in pairs:
    if a not in labels or b not in labels:
        continue
    for t in ts:
        q = [rate[(a, t, r)] / rate[(b, t, r)] for r in rs if (a, t, r) in rate and (b, t, r) in rate]
        L.append('| %s / %s | %d | %.2fx | %.2f-%.2fx |' % (names[a], names[b], t, statistics.median(q), min(q), max(q)))
L.append('')
with open(os.path.join(out, 'block.md'), 'w') as f:
    f.write('\n'.join(L))
print('block-speed: wrote %s/block.md' % out)
PY
