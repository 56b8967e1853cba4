#!/usr/bin/env bash
# Builds rmfx_bench_effects and runs it the way docs/performance.md reports: 5 repetitions of
# every case, aggregates only (median, min, max, …), at least 1 s per repetition. Prints the
# Google Benchmark report, then the summary as Markdown tables, and writes both (JSON and .md)
# to the output folder.
#
#   bench/run-effects-bench.sh [--size=N|WxH] [more rmfx_bench_effects / Google Benchmark flags]
#
# Then, where Mesa is the GL driver, the interpreter-against-hand-loop case once more on Mesa's
# no-op driver (GALLIUM_NOOP=1: every GL call goes through Mesa's state tracker, nothing is drawn),
# which isolates the CPU cost of issuing the calls from the driver's drawing work.
#
# Environment: BUILD_DIR (default build/), OUT_DIR (default $BUILD_DIR/bench-effects),
# REPETITIONS (5), MIN_TIME (1 second), NOOP_RUN (1; 0 skips the no-op run). The machine may be
# shared: the load is printed before and after; compare runs only at a similar load.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${BUILD_DIR:-$source_dir/build}
out_dir=${OUT_DIR:-$build_dir/bench-effects}
repetitions=${REPETITIONS:-5}
min_time=${MIN_TIME:-1}

if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S "$source_dir" --preset default -B "$build_dir"
fi
cmake --build "$build_dir" -j2 --target rmfx_bench_effects
mkdir -p "$out_dir"

stamp=$(date +%Y%m%d-%H%M%S)
echo "CPU threads: $(nproc); load before: $(uptime)"
"$build_dir/rmfx_bench_effects" \
  --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true \
  --benchmark_min_time="$min_time" \
  --benchmark_out="$out_dir/effects-$stamp.json" --benchmark_out_format=json \
  --markdown="$out_dir/effects-$stamp.md" "$@"
echo "load after: $(uptime)"
echo "written: $out_dir/effects-$stamp.md and .json"

if [ "${NOOP_RUN:-1}" != 0 ]; then
  echo
  echo "== the same interpreter / hand loop comparison on Mesa's no-op driver (GALLIUM_NOOP=1)"
  GALLIUM_NOOP=1 "$build_dir/rmfx_bench_effects" --benchmark_filter='^overhead/' \
    --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true \
    --benchmark_out="$out_dir/effects-$stamp-noop.json" --benchmark_out_format=json \
    --markdown="$out_dir/effects-$stamp-noop.md" "$@"
  echo "written: $out_dir/effects-$stamp-noop.md and .json"
fi
