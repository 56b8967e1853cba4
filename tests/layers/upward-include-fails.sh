#!/usr/bin/env bash
# Shows that the layering holds both ways it is enforced (issue 16): an include of the gl layer
# added to a graph-layer file
#   1. makes scripts/check-layers.py fail, naming the file, line and both layers, and
#   2. does not compile with the graph layer's include path (build/layers/graph/).
# Usage: upward-include-fails.sh SOURCE_DIR BINARY_DIR CXX
set -euo pipefail
source_dir=$1 binary_dir=$2 cxx=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/tree/scripts"
cp "$source_dir/scripts/check-layers.py" "$work/tree/scripts/"
cp -r "$source_dir/runtime" "$work/tree/runtime"
python3 "$work/tree/scripts/check-layers.py" --root "$work/tree" >/dev/null || {
  echo "the untouched copy already fails the check"; exit 1; }
printf '#include "gl/GlContext.h"\n' >>"$work/tree/runtime/graph/PassGraph.cpp"
line=$(wc -l <"$work/tree/runtime/graph/PassGraph.cpp")
if out=$(python3 "$work/tree/scripts/check-layers.py" --root "$work/tree"); then
  echo "check-layers.py passed a graph file that includes the gl layer"; exit 1
fi
expected="runtime/graph/PassGraph.cpp:$line: \"gl/GlContext.h\" is in the 'gl' layer, above this file's 'graph' layer"
grep -qF "$expected" <<<"$out" || { echo "check-layers.py failed without saying: $expected"; echo "$out"; exit 1; }
echo "check-layers.py: $out"

printf '#include "graph/PassGraph.h"\n#include "gl/GlContext.h"\n' >"$work/upward.cpp"
if "$cxx" -std=c++20 -fsyntax-only -I"$binary_dir/layers/graph" "$work/upward.cpp" 2>"$work/compile.log"; then
  echo "a graph-layer file including gl/GlContext.h compiled"; exit 1
fi
grep -q "gl/GlContext.h" "$work/compile.log" || { echo "the compile failed for another reason:"; cat "$work/compile.log"; exit 1; }
echo "compiler: $(grep -m1 'gl/GlContext.h' "$work/compile.log")"
"$cxx" -std=c++20 -fsyntax-only -I"$binary_dir/layers/gl" "$work/upward.cpp" || {
  echo "the same file does not compile in the gl layer either, so the test proves nothing"; exit 1; }
echo "the same file compiles with the gl layer's include path: the include path alone refused it"
