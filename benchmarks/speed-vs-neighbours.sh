#!/bin/bash
# Speed per core against the neighbour count, for the reference and the gpu port's host build (float and
# double): bench_gpu's BM_Neighbours* (the 8000-particle steel block at h_factor 1.0, 1.2, 1.5, 2.0) on one
# thread, each the median of REPS repetitions. Writes OUT/report.md, speed.dat, speed.gp and speed.png
# (gnuplot), and the benchmark's JSON.
#
#   bash benchmarks/speed-vs-neighbours.sh                          # build/benchmarks/bench_gpu -> docs/speed/
#   BEFORE=/path/to/older/bench_gpu bash benchmarks/speed-vs-neighbours.sh
#
# With BEFORE (a bench_gpu of an earlier commit that has BM_Neighbours*), both are run in turn and the
# report gives each solver's speed against the earlier reference: the ratios issue 18 sets targets on.
# Measure on an idle machine, or say what else ran (NOTE="..."): the figures are wall-time rates of one
# thread.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=${BENCH:-$root/build/benchmarks/bench_gpu}
before=${BEFORE:-}
out=${OUT:-$root/docs/speed}
reps=${REPS:-3}
mkdir -p "$out"
[ -x "$bench" ] || { echo "speed-vs-neighbours: $bench not found; build it with: cmake --build build --target bench_gpu" >&2; exit 1; }
run() {
  echo "speed-vs-neighbours: $1 ($reps repetitions, one thread)" >&2
  OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive "$1" --benchmark_filter='BM_Neighbours' \
    --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
    --benchmark_format=json --benchmark_out="$2" > /dev/null
}
run "$bench" "$out/after.json"
rm -f "$out/before.json"
if [ -n "$before" ]; then run "$before" "$out/before.json"; fi
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
# The commit the earlier binary was built from, when it lies in a checkout (a worktree of that commit).
before_commit=""
if [ -n "$before" ]; then before_commit=$(git -C "$(dirname "$before")" rev-parse --short HEAD 2>/dev/null || echo "a build"); fi
python3 - "$out" "$commit" "$before_commit" "${NOTE:-}" "$(python3 "$root/benchmarks/machine.py")" <<'PY'
import json, os, subprocess, sys
out, commit, before, note, cpu = sys.argv[1:6]

def load(path):
    rows = {}
    with open(path) as f:
        j = json.load(f)
    for b in j['benchmarks']:
        if b.get('aggregate_name') != 'median':
            continue
        name = b['run_name']  # BM_NeighboursReference/8000/120/real_time
        parts = name.split('/')
        solver = {'BM_NeighboursReference': 'reference (double)',
                  'BM_NeighboursGpuHost<gpu::Precision::Float>': 'gpu port host build (float)',
                  'BM_NeighboursGpuHost<gpu::Precision::Double>': 'gpu port host build (double)'}[parts[0]]
        rows[(solver, int(parts[2]))] = (b['neighbours'], b['particle_steps_per_s'])
    return rows, j['context']

after, ctx = load(os.path.join(out, 'after.json'))
prior = load(os.path.join(out, 'before.json'))[0] if before else {}
solvers = ['reference (double)', 'gpu port host build (float)', 'gpu port host build (double)']
hs = sorted({h for (_, h) in after})

with open(os.path.join(out, 'speed.dat'), 'w') as f:
    for s in solvers:
        f.write('# %s: neighbours, particle-steps/s per core\n' % s)
        for h in hs:
            n, v = after[(s, h)]
            f.write('%.3f %.6g\n' % (n, v))
        f.write('\n\n')
    if prior:
        f.write('# reference (double) before: neighbours, particle-steps/s per core\n')
        for h in hs:
            n, v = prior[('reference (double)', h)]
            f.write('%.3f %.6g\n' % (n, v))
        f.write('\n\n')

L = ['# Speed per core against the neighbour count', '',
     'Written by `bash benchmarks/speed-vs-neighbours.sh` (commit %s, %s); do not edit by hand.' % (commit, ctx.get('date', '')),
     'The 8000-particle steel block of benchmarks/block_scene.hpp, whole steps (time step, neighbour list, two',
     'evaluations of the midpoint scheme), one thread, the median of the repetitions. The neighbour count is the',
     'mean number within the kernel support; h_factor 1.0 to 2.0 spans it. Pair-steps/s is particle-steps/s times',
     'neighbours: the cost of one neighbour in one step.', '',
     '| machine | %s, %s cores (one used) |' % (cpu, ctx.get('num_cpus', '?')), '|---|---|',
     '| also running | %s |' % (note or 'nothing stated (set NOTE)'), '']
head = '| solver | h_factor | neighbours | particle-steps/s | pair-steps/s |'
rule = '|---|---|---|---|---|'
if prior:
    head += ' against the earlier reference |'
    rule += '---|'
L += [head, rule]
for s in solvers:
    for h in hs:
        n, v = after[(s, h)]
        row = '| %s | %.2f | %.1f | %.3g | %.3g |' % (s, h / 100, n, v, v * n)
        if prior:
            row += ' %.2fx |' % (v / prior[('reference (double)', h)][1])
        L.append(row)
if prior:
    L += ['', 'The earlier reference (`BEFORE`, built at commit %s, run in turn on the same core):' % before, '', '| h_factor | neighbours | particle-steps/s |', '|---|---|---|']
    for h in hs:
        n, v = prior[('reference (double)', h)]
        L.append('| %.2f | %.1f | %.3g |' % (h / 100, n, v))
L += ['', '![particle-steps/s per core against neighbours](speed.png)', '']
with open(os.path.join(out, 'report.md'), 'w') as f:
    f.write('\n'.join(L))

gp = ['set terminal pngcairo size 900,600', "set output 'speed.png'", 'set logscale xy',
      "set xlabel 'neighbours within the kernel support'", "set ylabel 'particle-steps/s, one core'",
      "set title 'Whole steps of the 8000-particle block, one thread (commit %s)'" % commit, 'set grid', 'set key top right']
plots = ["'speed.dat' index %d with linespoints lw 2 title '%s'" % (k, s) for k, s in enumerate(solvers)]
if prior:
    plots.append("'speed.dat' index 3 with linespoints dt 2 lw 2 title 'reference (double), earlier commit'")
gp.append('plot ' + ', \\\n     '.join(plots))
with open(os.path.join(out, 'speed.gp'), 'w') as f:
    f.write('\n'.join(gp) + '\n')
try:
    subprocess.run(['gnuplot', 'speed.gp'], cwd=out, check=True)
except (OSError, subprocess.CalledProcessError) as e:
    print('speed-vs-neighbours: no PNG (%s); install gnuplot' % e)
print('speed-vs-neighbours: wrote %s/report.md' % out)
PY
