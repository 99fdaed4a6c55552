#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz for a set time each.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#   scripts/fuzz.sh --replay [TARGET...]
#
# SECONDS per target (default 60); TARGETs by name, with or without the fuzz_ prefix (default:
# all). Configures and builds build-fuzz/ with clang (BISECTMESH_FUZZ=ON: ASan, UBSan, libFuzzer),
# then runs two targets at a time, one process each (no -jobs), each on a fresh working corpus
# build-fuzz/fuzz-run/<target>/corpus seeded from tests/fuzz/corpus/<target>/ (never written to).
# A run longer than 10 s is a timeout. Prints the executions per target and every finding
# (crash-*, timeout-*, oom-*, leak-* files under build-fuzz/fuzz-run/<target>/); exits 1 on any.
# --replay runs every file of the seed corpus once through its target (libFuzzer's replay mode,
# no fuzzing) and exits 1 if any of them crashes or leaks; scripts/sanitize.sh uses it.
#
# Exit status: 0 no finding, 1 findings (or a replay failed), 2 the build failed, 3 no clang.
# Environment: FUZZ_CXX (a clang++ that compiles the library: clang 16 or newer, clang 14 cannot
# capture structured bindings), FUZZ_PARALLEL (targets at once, 1 or 2; default 2).
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$ROOT/build-fuzz
REPLAY=0
if [ "${1:-}" = --replay ]; then REPLAY=1; shift; fi
SECONDS_PER_TARGET=60
if [ $REPLAY = 0 ] && [ $# -gt 0 ]; then SECONDS_PER_TARGET=$1; shift; fi
ALL=(fuzz_read_poly fuzz_read_poly2 fuzz_read_stl fuzz_read_off fuzz_read_msh fuzz_read_vtu
     fuzz_read_inp fuzz_pipeline3d fuzz_pipeline2d)
TARGETS=()
for t in "$@"; do TARGETS+=("fuzz_${t#fuzz_}"); done
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=("${ALL[@]}")
PARALLEL=${FUZZ_PARALLEL:-2}
[ "$PARALLEL" -gt 2 ] && PARALLEL=2   # a shared 2-core machine

find_clang() {
  if [ -n "${FUZZ_CXX:-}" ]; then echo "$FUZZ_CXX"; return; fi
  for c in clang++-19 clang++-18 clang++-17 clang++-16 clang++; do
    if command -v "$c" >/dev/null 2>&1; then
      local major
      major=$("$c" -dumpversion | cut -d. -f1)
      [ "$major" -ge 16 ] && { command -v "$c"; return; }
    fi
  done
}
# clang 16 and its fuzzer runtime, when missing (clang 14 cannot compile the library: lambdas
# capturing structured bindings); the test command does not need them
if [ -z "${FUZZ_CXX:-}" ]; then
  BISECTMESH_EXTRA_PACKAGES="clang-16 libclang-rt-16-dev" "$(dirname "${BASH_SOURCE[0]}")/deps.sh" || true
fi
CLANGXX=$(find_clang)
if [ -z "$CLANGXX" ]; then
  echo "fuzz.sh: no clang++ 16 or newer (Debian: clang-16 libclang-rt-16-dev, which this script installs when it can)" >&2
  exit 3
fi

LAUNCHER=()
command -v ccache >/dev/null 2>&1 && LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
mkdir -p "$BUILD"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_CXX_COMPILER="$CLANGXX" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 "${LAUNCHER[@]}" -DBISECTMESH_FUZZ=ON -DBISECTMESH_MOD_DIR= \
  -DBISECTMESH_PYTHON=OFF -DBISECTMESH_TESTS=OFF -DBISECTMESH_BENCH=OFF -DBISECTMESH_OCC=OFF \
  >"$BUILD/configure.log" 2>&1 || { cat "$BUILD/configure.log"; exit 2; }
cmake --build "$BUILD" -j2 --target "${TARGETS[@]}" || exit 2

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

if [ $REPLAY = 1 ]; then
  status=0
  for t in "${TARGETS[@]}"; do
    files=()
    [ -d "$ROOT/tests/fuzz/corpus/$t" ] && mapfile -t files < <(find "$ROOT/tests/fuzz/corpus/$t" -type f | sort)
    if [ ${#files[@]} -eq 0 ]; then echo "fuzz.sh: $t has no seed corpus"; status=1; continue; fi
    log=$BUILD/replay-$t.log
    if "$BUILD/fuzz/$t" -timeout=10 -rss_limit_mb=2048 "${files[@]}" >"$log" 2>&1; then
      echo "replay $t: ${#files[@]} inputs, ok"
    else
      echo "replay $t: FAILED (log $log)"; tail -30 "$log"; status=1
    fi
  done
  exit $status
fi

run_one() {  # target: fuzzes it, writes its log and leaves findings in its run folder
  local t=$1 dir=$BUILD/fuzz-run/$1
  rm -rf "$dir"
  mkdir -p "$dir/corpus"
  local seeds=()
  [ -d "$ROOT/tests/fuzz/corpus/$t" ] && seeds=("$ROOT/tests/fuzz/corpus/$t")
  "$BUILD/fuzz/$t" "$dir/corpus" "${seeds[@]}" -max_total_time="$SECONDS_PER_TARGET" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$dir/" \
    >"$dir/log" 2>&1
  echo $? >"$dir/rc"
}

echo "fuzz.sh: ${#TARGETS[@]} target(s), ${SECONDS_PER_TARGET} s each, $PARALLEL at a time"
running=0
for t in "${TARGETS[@]}"; do
  if [ "$running" -ge "$PARALLEL" ]; then wait -n; running=$((running - 1)); fi
  run_one "$t" &
  running=$((running + 1))
done
wait

status=0
printf '%-18s %12s %8s %10s  %s\n' target executions exec/s corpus findings
for t in "${TARGETS[@]}"; do
  dir=$BUILD/fuzz-run/$t
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$dir/log" | tail -1 | awk '{print $2}')
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$dir/log" | tail -1 | awk '{print $2}')
  units=$(find "$dir/corpus" -type f | wc -l)
  findings=$(find "$dir" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' \
    -o -name 'leak-*' \) -printf '%f ' | sed 's/ $//')
  rc=$(cat "$dir/rc" 2>/dev/null || echo '?')
  if [ -n "$findings" ] || [ "$rc" != 0 ]; then
    status=1
    findings="${findings:-none saved} (exit $rc; log $dir/log)"
  else
    findings=none
  fi
  printf '%-18s %12s %8s %10s  %s\n' "$t" "${execs:-?}" "${rate:-?}" "$units" "$findings"
done
exit $status
