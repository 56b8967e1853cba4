#!/usr/bin/env bash
# On a lent GPU machine (no Debian packages there): the render, the replay, the benchmarks and the
# GL test suite, from a bundle of the programs made here (docs/performance.md, "On a GPU"):
#
#   python3 scripts/device-bundle.py /tmp/bundle build/rmfx build/rmfx-hlsl-worker build/rmfx_bench_* build/tests/rmfx_gl_tests
#   mkdir -p .devbundle && tar cf - -C /tmp bundle | xz -6 -T2 >.devbundle/bundle.tar.xz
#   then, there, with .devbundle, .gl (the GL loaders' .debs) and samples/media carried:
#   bash bench/run-on-device.sh
#
# Everything goes to $OUT (default /tmp/device-out): log.txt and results.tar.gz (the image, replay
# JUnit report and failures, benchmark tables, GL test report). Each part has its own time limit,
# so a failing one leaves time for the others. QUICK=1 runs a few seconds of each (a dry run);
# PARTS picks some of render replay bench accuracy probe gltests health skip sequence storage (the
# last four: rmfx_bench_health_check, rmfx_bench_content_skip, rmfx_bench_sequence and
# rmfx_bench_storage_writes, when bundled).
set -uo pipefail
out=${OUT:-/tmp/device-out}
quick=${QUICK:-0}
mkdir -p "$out/results"
exec > >(tee "$out/log.txt") 2>&1
root=$PWD
part() { echo; echo "=== $1 ($(date +%T))"; }

if [ -d .gl ] && [ "$(id -u)" = 0 ] && ! ldconfig -p | grep -q "libEGL.so.1 "; then
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
fi
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor

bundle=/tmp/rmfx-bundle
rm -rf "$bundle" && mkdir -p "$bundle" && tar xJf .devbundle/bundle.tar.xz -C "$bundle" --strip-components=1
export LD_LIBRARY_PATH=$bundle/lib
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do [ -d "$d" ] && LD_LIBRARY_PATH+=":$d"; done
# The GL tests were built here with /work/main as their source folder and /work/main/build as the build.
if [ "$root" != /work/main ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi
mkdir -p build/tests
for p in rmfx rmfx-hlsl-worker rmfx_bench_effects rmfx_bench_health_check rmfx_bench_content_skip rmfx_bench_sequence rmfx_bench_storage_writes; do
  [ -f "$bundle/bin/$p" ] && cp "$bundle/bin/$p" build/
done
cp "$bundle/bin/rmfx_gl_tests" build/tests/

part "machine"
nvidia-smi -L 2>/dev/null || echo "no nvidia-smi"
nproc

parts=" ${PARTS:-render replay bench accuracy gltests} "
has() { [[ "$parts" == *" $1 "* ]]; }

if has render; then
  part "render (README's first command)"
  timeout 60 build/rmfx render effects/hdr_lighting.xml --frames 30 --dt 0.5 -o "$out/results/hdr_lighting.png"
fi

if has replay; then
  part "replay tests/replay/effects.xml"
  timeout 120 build/rmfx replay tests/replay/effects.xml --out "$out/results/replay-out" --junit "$out/results/replay-junit.xml"
  echo "replay exit status: $?"
fi

if has accuracy; then
  part "rmfx bench bench/variants.xml (accuracy against GPU time)"
  if [ "$quick" = 1 ]; then frames=2 warmup=1; else frames=20 warmup=5; fi
  timeout 150 build/rmfx bench bench/variants.xml --size 512x512 --frames $frames --warmup $warmup --time auto -q \
    --out "$out/results/accuracy"
  echo "bench exit status: $?"
  cat "$out/results/accuracy/accuracy.md" 2>/dev/null
fi

if has probe; then  # bench/device-probes/*.xml: each target of each written as EXR
  part "probes"
  for w in bench/device-probes/*.xml; do
    for t in $(grep -o '<target name="[^"]*"' "$w" | cut -d'"' -f2); do
      timeout 30 build/rmfx render "$w" --target "$t" -o "$out/results/$(basename "$w" .xml)-$t.exr"
    done
  done
fi

if has health; then
  part "rmfx_bench_health_check (render --check against no check, 512x512)"
  if [ "$quick" = 1 ]; then args="--rounds 1 --frames 2"; else args="--rounds 10 --frames 20"; fi
  timeout "${HEALTH_SECONDS:-90}" build/rmfx_bench_health_check $args
  echo "exit status: $?"
  # Passes that do next to nothing: what the counting code costs a draw and a fragment there.
  part "rmfx_bench_health_check on bench/health_trivial_passes.xml"
  timeout 60 build/rmfx_bench_health_check --workspace bench/health_trivial_passes.xml --rounds 3 --frames 20 --pairs 60
  echo "exit status: $?"
fi

if has skip; then
  part "rmfx_bench_content_skip (dark, bright, alternating; 512x512)"
  if [ "$quick" = 1 ]; then args="--rounds 1 --frames 2"; else args="--rounds 10 --frames 20"; fi
  timeout "${SKIP_SECONDS:-120}" build/rmfx_bench_content_skip $args
  echo "exit status: $?"
fi

if has storage; then
  part "rmfx_bench_storage_writes (what counting code costs a 128x128 pass, by variant)"
  if [ "$quick" = 1 ]; then args="--rounds 1 --frames 2"; else args="--rounds 10 --frames 20"; fi
  timeout "${STORAGE_SECONDS:-60}" build/rmfx_bench_storage_writes $args
  echo "exit status: $?"
fi

if has sequence; then
  part "rmfx_bench_sequence (60 frames of 1920x1080 EXR through hdr_lighting, overlap on and off)"
  if [ "$quick" = 1 ]; then args="--frames 3 --size 256x128 --repetitions 1"; else args="--frames 60 --repetitions ${SEQUENCE_REPETITIONS:-3}"; fi
  timeout "${SEQUENCE_SECONDS:-200}" build/rmfx_bench_sequence $args
  echo "exit status: $?"
fi

if has gltests; then
  # One process per suite: a crash (or a stub library called: scripts/device-bundle.py) loses one suite only.
  part "GL test suite"
  if [ "$quick" = 1 ]; then filter='Glare*:CliInput*'; else filter=${GL_TESTS_FILTER:-*}; fi
  deadline=$((SECONDS + ${GL_TESTS_SECONDS:-200}))
  for suite in $(build/tests/rmfx_gl_tests --gtest_list_tests --gtest_filter="$filter" | grep -E '^[A-Za-z0-9_/]+\.$' | tr -d .); do
    left=$((deadline - SECONDS)); [ $left -le 0 ] && { echo "out of time before $suite"; break; }
    timeout $left build/tests/rmfx_gl_tests --gtest_filter="$suite.*" >"$out/results/gl-${suite//\//_}.txt" 2>&1
    status=$?
    echo "$suite: $(grep -c '^\[       OK' "$out/results/gl-${suite//\//_}.txt") passed, exit status $status"
    grep -E "^\[  FAILED  \] [A-Za-z]" "$out/results/gl-${suite//\//_}.txt" | grep -v "tests, listed" | sort -u
    [ $status -gt 1 ] && tail -n 5 "$out/results/gl-${suite//\//_}.txt"
  done
fi

if has bench; then
  part "rmfx_bench_effects (interpreter against the hand-written loop)"
  if [ "$quick" = 1 ]; then reps=1 min=0.01; else reps=${REPETITIONS:-5} min=${MIN_TIME:-0.5}; fi
  for size in ${BENCH_SIZES:-512x512 1920x1080}; do
    timeout "${BENCH_SECONDS:-150}" build/rmfx_bench_effects --size="$size" --benchmark_repetitions=$reps \
      --benchmark_report_aggregates_only=true --benchmark_min_time=$min --markdown="$out/results/effects-$size.md" \
      >"$out/results/effects-$size.txt" 2>&1
    echo "size $size: exit status $?"; cat "$out/results/effects-$size.md"
  done
fi

tar czf "$out/results.tar.gz" -C "$out" results && rm -rf "$out/results"
echo "=== done ($(date +%T))"
