#!/usr/bin/env bash
# Builds the libFuzzer targets (build preset "fuzz" of the "asan" configuration: clang, ASan + UBSan,
# the same build the sanitizer suite runs from) and runs each for FUZZ_SECONDS (default 60),
# FUZZ_JOBS (default 2) at a time, on a working corpus under build-asan/fuzz-corpus/<target>/, seeded
# from the repository's workspaces, shaders and replay manifests. Prints per target executions,
# exec/s, corpus size, new coverage and the outcome, writes build-asan/fuzz-summary.tsv, and
# exits non-zero on any crash, leak, timeout or out-of-memory, keeping the input that caused it.
#   FUZZ_SECONDS=600 scripts/fuzz.sh             longer runs
#   FUZZ_TARGETS="workspace" scripts/fuzz.sh     some targets only
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${FUZZ_SECONDS:-60}
build=build-asan
jobs=${FUZZ_JOBS:-2}
summary=$build/fuzz-summary.tsv

cmake --preset asan >/dev/null
cmake --build --preset fuzz

# Per target: -max_len (bytes), -timeout (s per input), -rss_limit_mb. Workspaces carry the
# shaders they name, so theirs are the longest inputs.
declare -A max_len=([workspace]=131072 [shader_preprocessor]=16384 [replay_manifest]=16384 [variable_value_writer]=32768
                  [rfx_import]=65536 [d3d_asm]=16384 [reshade_preprocessor]=16384)
declare -A timeout=([workspace]=10 [shader_preprocessor]=10 [replay_manifest]=10 [variable_value_writer]=10 [rfx_import]=10 [d3d_asm]=10 [reshade_preprocessor]=10)
rss_limit_mb=2048

# A workspace file followed by the files it names as "//@@ NAME" parts (fuzz/FuzzInputFiles.h):
# shader text in full (with the files it includes), images and models (generated media too) empty.
bundle_workspace() {
  local xml=$1 dir name
  dir=$(dirname "$xml")
  cat "$xml"
  { grep -o 'file="[^"]*"' "$xml" || true; } | sed 's/^file="//; s/"$//' | sort -u | while read -r name; do
    printf '\n//@@ %s\n' "$name"
    case "$name" in
      *.glsl | *.frag | *.vert)
        [ -f "$dir/$name" ] || continue
        cat "$dir/$name"
        bundle_includes "$dir/$name" "$(dirname "$name")"
        ;;
    esac
  done
}

# The files a shader includes (one level), as parts named relative to `prefix`.
bundle_includes() {
  local shader=$1 prefix=$2 include
  { grep -o '#include "[^"]*"' "$shader" || true; } | sed 's/^#include "//; s/"$//' | sort -u | while read -r include; do
    [ -f "$(dirname "$shader")/$include" ] || continue
    printf '\n//@@ %s/%s\n' "$prefix" "$include"
    cat "$(dirname "$shader")/$include"
  done
}

seed() {  # seed TARGET FILE NAME: adds a seed to the target's working corpus
  cp "$2" "$build/fuzz-corpus/$1/seed-$3"
}

make_seeds() {
  local t f
  for t in workspace shader_preprocessor replay_manifest variable_value_writer rfx_import d3d_asm reshade_preprocessor; do
    mkdir -p "$build/fuzz-corpus/$t"
  done
  local workspaces replays
  workspaces=$(find effects tests bench -name '*.xml' -not -path 'tests/fuzz-regressions/*' | sort)
  replays=$(grep -l '<replay' $workspaces || true)
  for f in $workspaces; do
    grep -q '<workspace' "$f" || continue
    bundle_workspace "$f" >"$build/fuzz-corpus/workspace/seed-${f//\//_}"
    seed variable_value_writer "$f" "${f//\//_}"
  done
  for f in $replays; do seed replay_manifest "$f" "${f//\//_}"; done
  for f in $(find effects tests bench samples docs -name '*.glsl' -o -name '*.frag' -o -name '*.vert' | sort); do
    { cat "$f"; bundle_includes "$f" shaders; } >"$build/fuzz-corpus/shader_preprocessor/seed-${f//\//_}"
  done
  # The test .rfx files (tests/rfx/), with the files beside them as parts (a model, say).
  mkdir -p "$build/fuzz-corpus/rfx_import"
  for f in tests/rfx/*.rfx; do
    [ -f "$f" ] || continue
    { cat "$f"; for g in tests/rfx/*; do case $g in *.rfx) ;; *) printf '\n//@@ %s\n' "$(basename "$g")"; cat "$g" ;; esac; done; } \
      >"$build/fuzz-corpus/rfx_import/seed-$(basename "$f")"
  done
  # Assembly shaders written for the d3d_asm target (fuzz/seeds/d3d_asm/).
  for f in fuzz/seeds/d3d_asm/*; do
    [ -f "$f" ] && seed d3d_asm "$f" "$(basename "$f")"
  done
  # The ReShade FX fixture effects (runtime/frontend/Test/reshade/), with the headers beside them.
  for f in runtime/frontend/Test/reshade/*.fx; do
    [ -f "$f" ] || continue
    { cat "$f"; for g in runtime/frontend/Test/reshade/*.fxh; do printf '\n//@@ %s\n' "$(basename "$g")"; cat "$g"; done; } \
      >"$build/fuzz-corpus/reshade_preprocessor/seed-$(basename "$f")"
  done
  # Every saved finding seeds its target too.
  for t in tests/fuzz-regressions/*/; do
    t=$(basename "$t")
    [ -d "$build/fuzz-corpus/$t" ] || continue
    for f in tests/fuzz-regressions/$t/*; do
      [ "$(basename "$f")" = README.md ] || seed "$t" "$f" "regression-$(basename "$f")"
    done
  done
}

# A dictionary of the target's syntax plus the names its parser knows (string literals of the source).
make_dictionary() {
  local t=$1 out=$build/fuzz-dict/$1.dict sources=()
  mkdir -p "$build/fuzz-dict"
  case $t in
    workspace | variable_value_writer) sources=(runtime/frontend/workspace/WorkspaceParser.cpp runtime/core/Value.cpp runtime/io/mesh/BuiltinMeshes.cpp) ;;
    rfx_import) sources=(runtime/frontend/rfx/*.cpp runtime/frontend/rfx/detail/*.cpp) ;;
    d3d_asm) sources=(runtime/frontend/shader/D3DAsmParser.cpp runtime/frontend/shader/D3DAsmToHlsl.cpp) ;;
    reshade_preprocessor) sources=(runtime/frontend/reshade/*.cpp) ;;
    replay_manifest) sources=(runtime/frontend/replay/ReplayManifest.cpp runtime/io/image/codecs/ImageCompare.cpp runtime/io/image/ImageComparison.cpp) ;;
  esac
  {
    [ "$t" = shader_preprocessor ] || [ "$t" = d3d_asm ] || [ "$t" = reshade_preprocessor ] || cat fuzz/dictionaries/xml.dict
    [ -f "fuzz/dictionaries/$t.dict" ] && cat "fuzz/dictionaries/$t.dict"
    if [ ${#sources[@]} -gt 0 ]; then
      grep -ho '"[a-zA-Z][a-zA-Z0-9_-]\{0,23\}"' "${sources[@]}" | sort -u
    fi
  } >"$out"
  echo "$out"
}

final_stat() {  # final_stat NAME LOG: a value of libFuzzer's -print_final_stats
  sed -n "s/^stat::$1: *//p" "$2" | tail -1
}

outcome_of() {  # outcome_of STATUS LOG
  if [ "$1" -eq 0 ]; then echo ok
  elif grep -q 'ERROR: libFuzzer: timeout' "$2"; then echo timeout
  elif grep -q 'ERROR: libFuzzer: out-of-memory\|malloc(.*) exceeds limit' "$2"; then echo oom
  elif grep -q 'ERROR: LeakSanitizer' "$2"; then echo leak
  elif grep -q 'runtime error:' "$2"; then echo undefined-behaviour
  elif grep -q 'FuzzPropertyViolation' "$2"; then echo property-violated
  else echo crash
  fi
}

make_seeds
mkdir -p "$build/fuzz-logs"
printf 'target\tseconds\texecutions\texec_per_s\tcorpus_files\tnew_units\tcoverage\tfeatures\tpeak_rss_mb\toutcome\tinput\n' >"$summary"
targets=${FUZZ_TARGETS:-$(find "$build/fuzz" -maxdepth 1 -type f -executable -name 'rmfx_fuzz_*' | sed 's|.*/rmfx_fuzz_||' | sort)}

# fuzz_target T: runs one target; its summary row goes to $build/fuzz-logs/T.row, what it prints to
# $build/fuzz-logs/T.out (targets run side by side, so their reports are printed in order after).
fuzz_target() {
  local t=$1 binary corpus artifacts log dictionary status outcome input coverage features row
  binary=$build/fuzz/rmfx_fuzz_$t
  corpus=$build/fuzz-corpus/$t
  artifacts=$build/fuzz-artifacts/$t/
  log=$build/fuzz-logs/$t.log
  mkdir -p "$corpus" "$artifacts"
  dictionary=$(make_dictionary "$t")
  {
    echo "== fuzz $t: ${seconds}s, $(ls "$corpus" | wc -l) inputs to start from"
    status=0
    "$binary" -max_total_time="$seconds" -print_final_stats=1 -rss_limit_mb=$rss_limit_mb \
      -timeout="${timeout[$t]:-10}" -max_len="${max_len[$t]:-16384}" -dict="$dictionary" \
      -artifact_prefix="$artifacts" "$corpus" >"$log" 2>&1 || status=$?
    outcome=$(outcome_of "$status" "$log")
    input=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
    coverage=$({ grep -o 'cov: [0-9]*' "$log" || true; } | tail -1 | cut -d' ' -f2)
    features=$({ grep -o 'ft: [0-9]*' "$log" || true; } | tail -1 | cut -d' ' -f2)
    row=("$t" "$seconds" "$(final_stat number_of_executed_units "$log")" "$(final_stat average_exec_per_sec "$log")"
         "$(ls "$corpus" | wc -l)" "$(final_stat new_units_added "$log")" "${coverage:-}" "${features:-}"
         "$(final_stat peak_rss_mb "$log")" "$outcome" "${input:-}")
    (IFS=$'\t'; echo "${row[*]}") >"$build/fuzz-logs/$t.row"
    echo "   executions ${row[2]}, ${row[3]} exec/s, corpus ${row[4]} files (${row[5]} new), coverage ${row[6]} edges, ${row[7]} features: $outcome"
    if [ "$outcome" != ok ]; then
      echo "   log: $log"
      grep -m1 -A12 'ERROR:\|runtime error:\|FuzzPropertyViolation' "$log" | sed 's/^/   | /' || true
      if [ -n "$input" ]; then
        echo "   input kept: $input"
        echo "   reproduce:  $binary $input"
        echo "   after the fix, keep it as a regression test: cp $input tests/fuzz-regressions/$t/<what-it-found>"
      fi
    fi
  } >"$build/fuzz-logs/$t.out"
}

echo "fuzzing $(echo $targets | wc -w) targets for ${seconds}s each, $jobs at a time"
running=0
for t in $targets; do
  rm -f "$build/fuzz-logs/$t.row" "$build/fuzz-logs/$t.out"
  fuzz_target "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

failed=0
for t in $targets; do
  cat "$build/fuzz-logs/$t.out" 2>/dev/null || echo "== fuzz $t: no report (the run did not finish)"
  if [ -f "$build/fuzz-logs/$t.row" ]; then
    cat "$build/fuzz-logs/$t.row" >>"$summary"
    [ "$(cut -f10 "$build/fuzz-logs/$t.row")" = ok ] || failed=1
  else
    failed=1
  fi
done
echo "summary: $summary"
column -t -s $'\t' "$summary" || cat "$summary"
exit $failed
