#!/usr/bin/env bash
# The first GPU run in one command (issue 17): build the CUDA build, cross-check it against the reference,
# time its phases, and write one Markdown summary. Run from anywhere; it works in the repository root.
#
#   bash gpu/device-check.sh            on a machine with an NVIDIA GPU: build (or reuse), check, measure
#   bash gpu/device-check.sh plan       print what it would run, and exit
#   bash gpu/device-check.sh prepare    on a machine WITHOUT a GPU: build the two programs the check needs
#                                       (CUDA on, portable host code, sm_90) and bundle their shared
#                                       libraries, so that a bare GPU machine can run them (carry them in)
#
# Without a GPU (nvidia-smi -L lists none, or IMPACTSPH_DEVICE_CHECK_FORCE_NO_DEVICE=1) it prints a line with
# "no device" and the plan, builds nothing and exits 0.
#
# With one it runs, each step under `timeout` and all of them within BUDGET_S (480 s) of the start:
#   1. build: reuse $BUILD_DIR/verification/crosscheck and $BUILD_DIR/benchmarks/bench_gpu when they are
#      there (carried in from `prepare`); else configure (CUDA on, Release, this GPU's architecture) and
#      build those two targets with all cores;
#   2. `ctest -L cuda` (the CUDA build against the reference, verification/CMakeLists.txt), when the build
#      folder is a CMake tree of this checkout; with carried binaries the same four crosschecks run directly;
#   3. the CUDA build against the reference in double and float on the elastic wave, the coarse plate and
#      the ceramic tile (verification/crosscheck --build cuda);
#   4. bench_gpu's BM_CudaPhases, float and double, at 103823 and 1e6 particles.
# A failing step is recorded and the next one runs; the exit status is 1 when a step failed, else 0.
# The summary goes to $OUT/device-check.md (when OUT is set) and gpu/device-check/summary.md; the logs to
# $BUILD_DIR/device-check-logs and, packed, to $OUT/device-check-logs.tar.gz.
#
# Environment: BUILD_DIR (build-device), JOBS (all cores), BUDGET_S (480), CUDA_ARCH (from nvidia-smi,
# else 90), OUT. IMPACTSPH_DEVICE_CHECK_DRY_RUN=host runs the device branch on a machine without a GPU
# against the host build (--build host, 20 steps, BM_GpuHostStep at 8000 particles) to test this script;
# its summary goes only to the log folder and to $OUT.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
ROOT=$PWD
MODE=${1:-run}
BUILD_DIR=${BUILD_DIR:-build-device}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
BUDGET_S=${BUDGET_S:-480}
DRY=${IMPACTSPH_DEVICE_CHECK_DRY_RUN:-}
OUT_DIR=${OUT:-}
XC="$BUILD_DIR/verification/crosscheck"
BENCH="$BUILD_DIR/benchmarks/bench_gpu"

say() { printf '[device-check] %s\n' "$*"; }
now() { printf '%s' "${EPOCHREALTIME:-$(date +%s.%N)}"; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }
# A path as the summary shows it: relative to the repository root, never this machine's absolute path.
case $BUILD_DIR in /*) BUILD_ABS=$BUILD_DIR ;; *) BUILD_ABS=$ROOT/$BUILD_DIR ;; esac
rel() {
  case $1 in
    "$ROOT"/*) printf '%s' "${1#"$ROOT"/}" ;;
    "$BUILD_ABS"/*) printf '<BUILD_DIR>/%s' "${1#"$BUILD_ABS"/}" ;;
    "$BUILD_ABS") printf '<BUILD_DIR>' ;;
    /*) printf '<%s>' "$(basename "$1")" ;;
    *) printf '%s' "$1" ;;
  esac
}

# ---------------------------------------------------------------------------------------------------------
# What is run. Cross-checks: precision | what | the CTest test of label cuda that runs the same | arguments.
# The tolerances are those of verification/CMakeLists.txt (double: fields 1e-9; float: the observables);
# the double tile has no field tolerance (its fragmentation amplifies round-off, gpu/README.md), only the
# rod's residual velocity within 2 %.
CROSSCHECKS=(
  "double|elastic wave 1 mm, whole run|crosscheck.cuda_double_elastic_wave|cases/elastic-wave/case.toml --spacing 1mm --to-end --field-tol 1e-9"
  "float|elastic wave 1 mm, whole run|crosscheck.cuda_float_elastic_wave|cases/elastic-wave/case.toml --spacing 1mm --to-end --precision float --wave-tol 5e-3"
  "double|plate-8mm 2.5 mm, 100 steps|crosscheck.cuda_double_plate_100_steps|cases/plate-8mm/case.toml --spacing 2.5mm --steps 100 --field-tol 1e-9"
  "float|plate-8mm 2.5 mm, whole run|-|cases/plate-8mm/case.toml --spacing 2.5mm --to-end --precision float --residual-tol 2e-2"
  "double|ceramics 1 mm (JH-2, SRAD, variable h), whole run|crosscheck.cuda_double_ceramics|verification/data/ceramics.toml --to-end --field-tol 1e-9"
  "double|ceramic-tile 1.5875 mm, whole run|-|cases/ceramic-tile/case.toml --spacing 1.5875mm --to-end --residual-tol 2e-2"
  "float|ceramic-tile 1.5875 mm, whole run|-|cases/ceramic-tile/case.toml --spacing 1.5875mm --to-end --precision float --residual-tol 2e-2"
)
# Benchmarks: label | --benchmark_filter.
BENCHES=(
  "float, 103823 particles|^BM_CudaPhases<gpu::Precision::Float>/103823/"
  "double, 103823 particles|^BM_CudaPhases<gpu::Precision::Double>/103823/"
  "float, 1e6 particles|^BM_CudaPhases<gpu::Precision::Float>/1000000/"
  "double, 1e6 particles|^BM_CudaPhases<gpu::Precision::Double>/1000000/"
)
BUILD_BACKEND=cuda
if [ "$DRY" = host ]; then
  BUILD_BACKEND=host
  BENCHES=("float, 8000 particles (host build, dry run)|^BM_GpuHostStep<gpu::Precision::Float>/8000/0/"
           "double, 8000 particles (host build, dry run)|^BM_GpuHostStep<gpu::Precision::Double>/8000/0/")
fi
# Per-step limits in seconds (each also bounded by what is left of BUDGET_S).
LIMIT_BUILD=330 LIMIT_CTEST=150 LIMIT_XC=90 LIMIT_BENCH=75

xc_args() {  # the crosscheck arguments of entry $1 (the dry run: 20 steps, too few to measure the wave)
  local a=$1
  if [ "$DRY" = host ]; then
    a=${a//--to-end/--steps 20}
    a=${a//--wave-tol 5e-3/}
  fi
  printf '%s --build %s' "$a" "$BUILD_BACKEND"
}

print_plan() {
  local e p what test args b
  echo "  build:  reuse $XC and $BENCH if present (carried in from 'bash gpu/device-check.sh prepare'), else"
  echo "          cmake -S . -B $BUILD_DIR -DCMAKE_BUILD_TYPE=Release -DIMPACTSPH_CUDA=ON -DIMPACTSPH_CUDA_ARCHITECTURES=<this GPU, e.g. 90>"
  echo "          cmake --build $BUILD_DIR -j $JOBS --target crosscheck bench_gpu"
  echo "  cuda:   ctest --test-dir $BUILD_DIR -L cuda -V --no-tests=error (carried binaries: the same crosschecks directly)"
  for e in "${CROSSCHECKS[@]}"; do
    IFS='|' read -r p what test args <<<"$e"
    echo "  check:  OMP_NUM_THREADS=$JOBS $XC $(xc_args "$args")    # $p, $what"
  done
  for e in "${BENCHES[@]}"; do
    IFS='|' read -r what b <<<"$e"
    echo "  bench:  $BENCH --benchmark_filter='$b' --benchmark_out=<log>.json --benchmark_out_format=json    # $what"
  done
  echo "  each step under timeout, all within ${BUDGET_S} s; summary to \$OUT/device-check.md and gpu/device-check/summary.md"
}

# ---------------------------------------------------------------------------------------------------------
# prepare: on a machine without a GPU, build what the device check runs so that a bare GPU machine (no
# Eigen, GSL, toml++, Google Benchmark there) can run it: host code for any x86-64 (IMPACTSPH_NATIVE off),
# kernels for sm_90, and the shared libraries other than the C library's next to them.
prepare() {
  local arch=${CUDA_ARCH:-90} exe lib
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DIMPACTSPH_CUDA=ON -DIMPACTSPH_NATIVE=OFF \
        -DIMPACTSPH_CUDA_ARCHITECTURES="$arch" || return 1
  cmake --build "$BUILD_DIR" -j "$JOBS" --target crosscheck bench_gpu || return 1
  rm -rf "${BUILD_DIR:?}/lib" && mkdir -p "$BUILD_DIR/lib" || return 1
  for exe in "$XC" "$BENCH"; do
    while read -r lib; do
      case $(basename "$lib") in
        libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|libresolv.so*|ld-linux*) ;;  # the C library: the target's own
        *) cp -L "$lib" "$BUILD_DIR/lib/" || return 1 ;;
      esac
    done < <(ldd "$exe" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }')
  done
  say "prepared: $(du -shc "$XC" "$BENCH" "$BUILD_DIR/lib" | tail -1 | cut -f1) to carry"
  say "run on the GPU machine with carry = [\"$BUILD_DIR/verification/crosscheck\", \"$BUILD_DIR/benchmarks/bench_gpu\", \"$BUILD_DIR/lib\"]"
  say "and the command: bash gpu/device-check.sh"
}

case $MODE in
  run) ;;
  plan) print_plan; exit 0 ;;
  prepare) prepare; exit $? ;;
  *) echo "usage: bash gpu/device-check.sh [run|plan|prepare]" >&2; exit 2 ;;
esac

# ---------------------------------------------------------------------------------------------------------
# Is there a device?
DEVICE_LIST=""
if [ "${IMPACTSPH_DEVICE_CHECK_FORCE_NO_DEVICE:-0}" != 1 ] && command -v nvidia-smi >/dev/null 2>&1; then
  DEVICE_LIST=$(timeout 30 nvidia-smi -L 2>/dev/null | grep '^GPU ' || true)
fi
if [ -z "$DEVICE_LIST" ] && [ "$DRY" != host ]; then
  say "no device: nvidia-smi -L lists no GPU here; nothing built or run. With one it would run:"
  print_plan
  if [ -n "$OUT_DIR" ]; then
    mkdir -p "$OUT_DIR" && { echo "# Device check: no device"; echo; echo "nvidia-smi -L listed no GPU; nothing was built or run."; } \
      >"$OUT_DIR/device-check.md"
  fi
  exit 0
fi

T_START=$(now)
LOG_DIR="$BUILD_DIR/device-check-logs"
mkdir -p "$LOG_DIR" || exit 2
FAILED=0
STEP_NAME=() STEP_STATUS=() STEP_TIME=() STEP_LOG=()
remaining() { awk -v s="$T_START" -v b="$BUDGET_S" -v n="$(now)" 'BEGIN { printf "%d", b - (n - s) }'; }
record() {  # name status seconds log
  STEP_NAME+=("$1") STEP_STATUS+=("$2") STEP_TIME+=("$3") STEP_LOG+=("$4")
  case $2 in PASS*) ;; *) FAILED=1 ;; esac
  say "$1: $2 (${3} s)"
}
# run_step NAME LIMIT LOG COMMAND...: the command under timeout, its output to LOG. Sets RC.
RC=0
run_step() {
  local name=$1 limit=$2 log=$3 left t0 status
  shift 3
  left=$(remaining)
  if [ "$left" -lt 10 ]; then
    RC=125
    record "$name" "NOT RUN (time budget of ${BUDGET_S} s spent)" 0 "-"
    return
  fi
  [ "$limit" -gt "$left" ] && limit=$left
  say "$name: running (limit ${limit} s)"
  printf '$ %s\n' "$*" >"$log"
  t0=$(now)
  timeout -k 10 "$limit" "$@" >>"$log" 2>&1
  RC=$?
  case $RC in
    0) status=PASS ;;
    124|137) status="FAIL (timed out after ${limit} s)" ;;
    77) status="FAIL (exit 77: no CUDA device seen, or built without CUDA)" ;;
    *) status="FAIL (exit $RC)" ;;
  esac
  record "$name" "$status" "$(since "$t0")" "$(rel "$log")"
  if [ "$RC" -ne 0 ]; then tail -n 15 "$log" | sed 's/^/    | /'; fi
}

# Environment of the programs: all cores for the reference's OpenMP loops; the carried libraries first.
RUN_ENV=(env "OMP_NUM_THREADS=$JOBS")
if [ -d "$BUILD_DIR/lib" ]; then RUN_ENV+=("LD_LIBRARY_PATH=$BUILD_ABS/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"); fi

# ---------------------------------------------------------------------------------------------------------
# The device.
GPU_INFO="none (dry run on the host: no GPU measured)"
GPU_NAME="" DRIVER="" CUDA_DRIVER="" ARCH_FOUND=""
if [ -n "$DEVICE_LIST" ]; then
  GPU_INFO=$(nvidia-smi --query-gpu=name,driver_version,memory.total,compute_cap --format=csv,noheader 2>/dev/null | head -1)
  # An older nvidia-smi without compute_cap refuses the whole query.
  [ -z "$GPU_INFO" ] && GPU_INFO=$(nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>/dev/null | head -1)
  GPU_NAME=$(printf '%s' "$GPU_INFO" | cut -d, -f1 | sed 's/^ *//')
  DRIVER=$(printf '%s' "$GPU_INFO" | cut -d, -f2 | sed 's/^ *//')
  ARCH_FOUND=$(printf '%s' "$GPU_INFO" | cut -d, -f4 | tr -d ' .')
  CUDA_DRIVER=$(nvidia-smi 2>/dev/null | sed -n 's/.*CUDA Version: *\([0-9.]*\).*/\1/p' | head -1)
fi
CUDA_ARCH=${CUDA_ARCH:-${ARCH_FOUND:-90}}
case $CUDA_ARCH in *[!0-9]*|"") CUDA_ARCH=90 ;; esac
say "device: ${DEVICE_LIST:-$GPU_INFO}"

# ---------------------------------------------------------------------------------------------------------
# 1. Build, or reuse what was carried in.
NVCC=$(command -v nvcc || true)
[ -z "$NVCC" ] && [ -x /usr/local/cuda/bin/nvcc ] && NVCC=/usr/local/cuda/bin/nvcc
BUILD_NOTE="" CTEST_OK=0
cache_home() { sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$BUILD_DIR/CMakeCache.txt" 2>/dev/null; }
if [ -x "$XC" ] && [ -x "$BENCH" ] && [ "$(cache_home)" != "$ROOT" ]; then
  BUILD_NOTE="reused the binaries in $(rel "$BUILD_DIR") (built beforehand and carried in; not rebuilt)"
  missing=$("${RUN_ENV[@]}" ldd "$XC" "$BENCH" 2>&1 | grep 'not found' | sort -u | tr -s ' \t' ' ' || true)
  if [ -n "$missing" ]; then record "build (carried binaries: libraries)" "FAIL (missing:$missing)" 0 "-"
  else record "build (carried binaries)" "PASS (reused, not rebuilt)" 0 "-"; fi
else
  GEN=()
  if [ ! -f "$BUILD_DIR/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then GEN=(-G Ninja); fi
  CONF=(cmake -S . -B "$BUILD_DIR" "${GEN[@]}" -DCMAKE_BUILD_TYPE=Release -DIMPACTSPH_CUDA=ON
        "-DIMPACTSPH_CUDA_ARCHITECTURES=$CUDA_ARCH")
  [ -n "$NVCC" ] && CONF+=("-DCMAKE_CUDA_COMPILER=$NVCC")
  [ "$DRY" = host ] && CONF=(cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release)
  run_step "configure" 120 "$LOG_DIR/configure.log" "${CONF[@]}"
  if [ "$RC" -eq 0 ]; then
    run_step "build (crosscheck, bench_gpu; -j $JOBS)" "$LIMIT_BUILD" "$LOG_DIR/build.log" \
      cmake --build "$BUILD_DIR" -j "$JOBS" --target crosscheck bench_gpu
    [ "$RC" -eq 0 ] && CTEST_OK=1
    BUILD_NOTE="built here in $(rel "$BUILD_DIR"): CUDA on, Release, sm_$CUDA_ARCH (targets crosscheck, bench_gpu)"
  else
    BUILD_NOTE="configure failed (a missing package? see the log); 'bash gpu/device-check.sh prepare' on a machine with the packages builds the binaries to carry in"
  fi
fi
HAVE_BIN=0  # carried binaries, or a build that succeeded just now (not what a failed build left behind)
[ -x "$XC" ] && [ -x "$BENCH" ] && { [ "$CTEST_OK" -eq 1 ] || [ "$(cache_home)" != "$ROOT" ]; } && HAVE_BIN=1

# ---------------------------------------------------------------------------------------------------------
# 2. ctest -L cuda, split into one log per test.
CTEST_SUMMARY=""
if [ "$CTEST_OK" -eq 1 ]; then
  run_step "ctest -L cuda" "$LIMIT_CTEST" "$LOG_DIR/ctest-cuda.log" \
    ctest --test-dir "$BUILD_DIR" -L cuda -V --no-tests=error --timeout "$LIMIT_XC"
  awk -v dir="$LOG_DIR" '
    /^ *Start +[0-9]+: / { s = $0; sub(/^ *Start +/, "", s); n = s; sub(/:.*/, "", n); sub(/^[0-9]+: /, "", s); name[n] = s; next }
    /^[0-9]+: / { n = $0; sub(/:.*/, "", n); if (n in name) { l = $0; sub(/^[0-9]+: /, "", l); print l > (dir "/ctest." name[n] ".log") } }
  ' "$LOG_DIR/ctest-cuda.log"
  CTEST_SUMMARY=$(grep -E 'Test +#[0-9]+: ' "$LOG_DIR/ctest-cuda.log" | sed -E 's/^ *[0-9]+\/[0-9]+ +//; s/ +\.+ */ /; s/ +/ /g')
  # A skipped CUDA test on a machine with a device means the CUDA build did not see it: a failure.
  if [ "$DRY" != host ] && grep -qE 'Test +#[0-9]+: .*(Skipped|\*\*\*Not Run)' "$LOG_DIR/ctest-cuda.log"; then
    record "ctest -L cuda: skipped tests" "FAIL (a cuda test was skipped on a machine with a GPU)" 0 "$(rel "$LOG_DIR/ctest-cuda.log")"
  fi
elif [ "$HAVE_BIN" -eq 1 ]; then
  record "ctest -L cuda" "PASS (replaced: carried binaries have no CMake tree here; the label's crosschecks run directly below)" 0 "-"
else
  record "ctest -L cuda" "NOT RUN (no build)" 0 "-"
fi

# ---------------------------------------------------------------------------------------------------------
# 3. Cross-checks. Figures from a crosscheck log: the largest field differences over the run, the case's
# observables, the wall times, the verdict.
xc_figures() {  # log -> "disp L2/max|vel|dens|stress|observables|timing|verdict"
  awk '
    /^  (displacement|velocity|density|stress) (L2|max) / { v[$1 " " $2] = $3 }
    /^  (residual velocity|final length|wave speed):/ { s = $0; sub(/^  /, "", s); obs = obs (obs ? "; " : "") s }
    /^  .* FAIL$/ { s = $0; sub(/^  /, "", s); gsub(/  +/, " ", s); bad = bad (bad ? "; " : "") s }
    /^wall time of the steps:/ { t = $0; sub(/^wall time of the steps: /, "", t) }
    /^cross-check:/ { h = $0; sub(/^cross-check: /, "", h) }
    /^(PASS|FAIL): / { verdict = $0 }
    END {
      printf "%s / %s|%s / %s|%s / %s|%s / %s|%s|%s|%s|%s\n", v["displacement L2"], v["displacement max"],
             v["velocity L2"], v["velocity max"], v["density L2"], v["density max"], v["stress L2"], v["stress max"],
             obs (bad ? " FAILED: " bad : ""), t, verdict, h
    }' "$1"
}
XC_ROWS=()
k=0
for e in "${CROSSCHECKS[@]}"; do
  k=$((k + 1))
  IFS='|' read -r prec what test args <<<"$e"
  name="crosscheck $prec, $what"
  log="$LOG_DIR/xc-$k.log"
  source="direct"
  if [ "$CTEST_OK" -eq 1 ] && [ "$test" != "-" ] && [ -s "$LOG_DIR/ctest.$test.log" ]; then
    cp "$LOG_DIR/ctest.$test.log" "$log"
    source="ctest $test"
    line=$(grep -E "Test +#[0-9]+: $test " "$LOG_DIR/ctest-cuda.log" | head -1)
    secs=$(printf '%s' "$line" | sed -E 's/.* ([0-9.]+) sec.*/\1/')
    case $line in
      *Passed*) st="PASS (in ctest -L cuda)" ;;
      *Skipped*) if [ "$DRY" = host ]; then st="PASS (skipped in ctest -L cuda: no device, dry run)"; else st="FAIL (skipped in ctest -L cuda)"; fi ;;
      *) st="FAIL (in ctest -L cuda: ${line##*\*\*\*})" ;;
    esac
    record "$name" "$st" "${secs:-0}" "$(rel "$log")"
  elif [ "$HAVE_BIN" -eq 1 ]; then
    read -ra argv <<<"$(xc_args "$args")"
    run_step "$name" "$LIMIT_XC" "$log" "${RUN_ENV[@]}" "$XC" "${argv[@]}"
    st=${STEP_STATUS[-1]} secs=${STEP_TIME[-1]}
  else
    record "$name" "NOT RUN (no build)" 0 "-"
    continue
  fi
  [ -f "$log" ] && XC_ROWS+=("$prec|$what|$st|${secs:-?}|$source|$(xc_figures "$log")")
done

# ---------------------------------------------------------------------------------------------------------
# 4. Benchmarks. Google Benchmark's JSON has one "key": value per line.
BENCH_ROWS=()
bench_figures() {  # json -> lines "name|particle_steps_per_s|neighbours|ms per step|phases|error"
  awk '
    function val(s) { sub(/^[^:]*: */, "", s); sub(/,$/, "", s); gsub(/"/, "", s); return s }
    function flush() { if (name != "") printf "%s|%s|%s|%s|%s|%s\n", name, psps, nb, ms, ph, err; name = psps = nb = ms = ph = err = "" }
    /^ *"benchmarks": / { inb = 1 }
    inb && /^ *"name": / { flush(); name = val($0) }
    inb && /^ *"real_time": / { ms = val($0) }
    inb && /^ *"particle_steps_per_s": / { psps = val($0) }
    inb && /^ *"neighbours": / { nb = val($0) }
    inb && /^ *"[a-z0-9_]+_particle_steps_per_s": / { k = $0; sub(/^ *"/, "", k); sub(/_particle_steps_per_s".*/, "", k)
                                                     ph = ph (ph ? " " : "") sprintf("%s %.3g", k, val($0)) }
    inb && /^ *"error_message": / { err = val($0) }
    END { flush() }' "$1"
}
k=0
for e in "${BENCHES[@]}"; do
  k=$((k + 1))
  IFS='|' read -r what filter <<<"$e"
  name="bench_gpu $what"
  if [ "$HAVE_BIN" -ne 1 ]; then record "$name" "NOT RUN (no build)" 0 "-"; continue; fi
  json="$LOG_DIR/bench-$k.json"
  rm -f "$json"
  run_step "$name" "$LIMIT_BENCH" "$LOG_DIR/bench-$k.log" "${RUN_ENV[@]}" "$BENCH" "--benchmark_filter=$filter" \
    "--benchmark_out=$json" --benchmark_out_format=json --benchmark_counters_tabular=true
  if [ -s "$json" ]; then
    rows=$(bench_figures "$json")
    if [ -z "$rows" ]; then record "$name: results" "FAIL (no benchmark matched $filter)" 0 "$(rel "$json")"; fi
    while IFS= read -r r; do
      [ -z "$r" ] && continue
      if [ -n "${r##*|}" ]; then record "$name: result" "FAIL (benchmark error: ${r##*|})" 0 "$(rel "$json")"; fi
      BENCH_ROWS+=("$what|$r")
    done <<<"$rows"
  fi
done

# ---------------------------------------------------------------------------------------------------------
# Roofline estimate for one particle-step of the block (no sorts: the block hardly moves), from what the
# kernels of gpu/solver_impl.hpp read and write once from DRAM, neighbour fields assumed to hit the cache
# (the cell order is for that). R = bytes of a Real (8 double, 4 float); positions are double in both.
#   gather      (per point)  reads 32 + 15R (order, material, rho, e, bulking, S, damage, x, v, m, h);
#                            writes 32 + 22R (work x, v, rho, P, c, m, h, material, body, damage, S, vol, A)
#   pass 1                   56 + 29R: own slot, row offset, x, v, rho, h, damage, body, c; writes L^-1,
#                            grad rho, grad v, fallback flag, count, viscosity factor; two sum reductions
#   pass 2                   45 + 58R: own fields, A, L^-1, grad v, S, fixed; writes the seven rates
#   one evaluation           165 + 124R, twice a step
#   advance (half, full)     104 + 85R;  check 44 + 11R;  finish 8 + 21R;  time step 4 + 8R;
#   sort criterion (max speed, max displacement) 48 + 7R;  contact power R
#   Verlet lists             4 bytes per entry, read by pass 1 and pass 2 of both evaluations: 16 L, with
#                            L = 1.16 x neighbours (radius 1.05 x the support: 1.05^3 more entries)
# step: B = 538 + 381 R + 16 L bytes. Arithmetic: design.md's 25 kflop per particle-step at 60 neighbours,
# scaled with the neighbours. H200: 4.8 TB/s HBM3e; FP64 34 TFLOP/s without tensor cores (the 67 TFLOP/s
# FP64 of the data sheet is the tensor-core rate, which these kernels do not use), FP32 67 TFLOP/s.
roofline() {  # precision-word neighbours measured -> one line
  awk -v w="$1" -v nb="$2" -v meas="$3" 'BEGIN {
    R = (w ~ /[Dd]ouble/) ? 8 : 4; peak = (R == 8) ? 34e12 : 67e12; L = 1.16 * nb
    B = 538 + 381 * R + 16 * L; fl = 25000 * nb / 60
    mem = 4.8e12 / B; cpu = peak / fl; bound = (mem < cpu) ? mem : cpu
    printf "%.0f B and %.3g kflop per particle-step: memory bound %.3g, compute bound %.3g particle-steps/s; measured %.3g = %.2g %% of the %s bound",
           B, fl / 1e3, mem, cpu, meas, 100 * meas / bound, (mem < cpu) ? "memory" : "compute" }'
}

# ---------------------------------------------------------------------------------------------------------
# The summary.
TOTAL=$(since "$T_START")
COMMIT=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ "$COMMIT" != unknown ] && [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]; then COMMIT="$COMMIT (with local changes)"; fi
SUMMARY="$LOG_DIR/summary.md"
{
  if [ "$DRY" = host ]; then
    echo "# Device check: DRY RUN on a machine without a GPU (host build; nothing here is a GPU figure)"
  else
    echo "# Device check: the CUDA build on ${GPU_NAME:-the GPU}"
  fi
  echo
  echo "Written by \`bash gpu/device-check.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'), commit $COMMIT, in ${TOTAL} s (budget ${BUDGET_S} s)."
  echo "**Overall: $([ "$FAILED" -eq 0 ] && echo PASS || echo FAIL)**."
  echo
  echo "* device: ${DEVICE_LIST:-none}"
  echo "* nvidia-smi: ${GPU_INFO}; driver ${DRIVER:-n/a}, CUDA (driver) ${CUDA_DRIVER:-n/a}"
  echo "* nvcc: $("${NVCC:-nvcc}" --version 2>/dev/null | sed -n 's/.*release \([0-9.]*\).*/\1/p' | head -1)"
  echo "* host: $(nproc) cores, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -1)"
  echo "* build: ${BUILD_NOTE}"
  echo
  echo "## Steps"
  echo
  echo "| step | result | wall s | log |"
  echo "|---|---|---|---|"
  for i in "${!STEP_NAME[@]}"; do
    echo "| ${STEP_NAME[$i]} | ${STEP_STATUS[$i]} | ${STEP_TIME[$i]} | ${STEP_LOG[$i]} |"
  done
  if [ -n "$CTEST_SUMMARY" ]; then
    echo
    echo "ctest -L cuda:"
    echo
    printf '%s\n' "$CTEST_SUMMARY" | sed 's/^/    /'
  fi
  echo
  echo "## CUDA build against the reference (\`verification/crosscheck --build $BUILD_BACKEND\`)"
  echo
  echo "Largest relative difference over the run, L2 over particles / max over particles (relative to the"
  echo "reference's norm and largest value); observables at the end. Tolerances as in verification/CMakeLists.txt."
  echo
  echo "| precision | case | result | wall s | displacement | velocity | density | stress | observables | step times |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for r in "${XC_ROWS[@]}"; do
    IFS='|' read -r prec what st secs src d v rho s obs timing verdict head <<<"$r"
    verdict=${verdict#PASS: }
    verdict=${verdict#FAIL: }
    echo "| $prec | $what (${head:+$head; }$src) | ${st%% (*}; ${verdict:-no verdict} | $secs | $d | $v | $rho | $s | ${obs:--} | ${timing:--} |"
  done
  echo
  echo "## bench_gpu (\`--benchmark_filter\` as in the steps; steel block at 1 mm, h = 1.2 dx)"
  echo
  echo "| run | benchmark | particle-steps/s | mean neighbours | ms per step | per phase, particle-steps/s | error |"
  echo "|---|---|---|---|---|---|---|"
  for r in "${BENCH_ROWS[@]}"; do
    IFS='|' read -r what bname psps nb ms ph err <<<"$r"
    echo "| $what | $bname | $(awk -v x="${psps:-0}" 'BEGIN { printf "%.3g", x }') | $(awk -v x="${nb:-0}" 'BEGIN { printf "%.1f", x }') | $(awk -v x="${ms:-0}" 'BEGIN { printf "%.3f", x }') | ${ph:--} | ${err:--} |"
  done
  echo
  echo "## Roofline (an estimate, not a measurement)"
  echo
  echo "Bytes per particle-step counted from what the kernels of gpu/solver_impl.hpp read and write once from"
  echo "DRAM (neighbour fields assumed to hit the cache; the block does not re-sort): B = 538 + 381 R + 16 L, R the"
  echo "bytes of a Real, L = 1.16 x the mean neighbour count the list entries read by the two passes of both"
  echo "evaluations (gpu/device-check.sh spells out each phase). Arithmetic: 25 kflop per particle-step at 60"
  echo "neighbours (design.md), scaled with the neighbours. H200: 4.8 TB/s HBM3e; FP64 34 TFLOP/s without tensor"
  echo "cores (the data sheet's 67 TFLOP/s FP64 is the tensor-core rate, unused here), FP32 67 TFLOP/s."
  echo
  for r in "${BENCH_ROWS[@]}"; do
    IFS='|' read -r what bname psps nb ms ph err <<<"$r"
    [ -n "$psps" ] && [ -n "$nb" ] && echo "* $what: $(roofline "$bname" "$nb" "$psps")"
  done
  echo
  echo "Logs: $(rel "$LOG_DIR") (and device-check-logs.tar.gz next to this summary in \$OUT)."
} >"$SUMMARY"

if [ "$DRY" != host ]; then
  mkdir -p gpu/device-check && cp "$SUMMARY" gpu/device-check/summary.md
fi
if [ -n "$OUT_DIR" ]; then
  mkdir -p "$OUT_DIR" && cp "$SUMMARY" "$OUT_DIR/device-check.md"
  tar -czf "$OUT_DIR/device-check-logs.tar.gz" -C "$LOG_DIR" . 2>/dev/null || true
fi
say "summary: $( [ "$DRY" = host ] && rel "$SUMMARY" || echo gpu/device-check/summary.md )${OUT_DIR:+ and \$OUT/device-check.md}; total ${TOTAL} s"
say "overall: $([ "$FAILED" -eq 0 ] && echo PASS || echo FAIL)"
exit "$FAILED"
