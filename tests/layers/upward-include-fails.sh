#!/usr/bin/env bash
# Shows that the layers' DAG (runtime/layers.txt) holds both ways it is enforced, for an include of
# a layer above (graph including gl) and of a layer beside, which the graph layer does not use
# (graph including io, which lies below graph in the old chain's order but not in graph's closure):
# added to a graph-layer file, each
#   1. makes scripts/check-layers.py fail, naming the file, line and both layers, and
#   2. does not compile with the graph layer's include path (build/layers/graph/), while the same
#      file compiles with the include path of a layer that uses both (so the path alone refused it).
# Also: a layer that declares a layer none of its files includes fails the check.
# Usage: upward-include-fails.sh SOURCE_DIR BINARY_DIR CXX
set -euo pipefail
source_dir=$1 binary_dir=$2 cxx=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fresh_tree() {
  rm -rf "$work/tree"
  mkdir -p "$work/tree/scripts"
  cp "$source_dir/scripts/check-layers.py" "$work/tree/scripts/"
  cp -r "$source_dir/runtime" "$work/tree/runtime"
}

# refused INCLUDE LAYER RELATION USER: the check and the compiler refuse INCLUDE (of LAYER, RELATION
# to graph) in a graph file; USER is a layer whose include path holds both.
refused() {
  local include=$1 layer=$2 relation=$3 user=$4
  fresh_tree
  printf '#include "%s"\n' "$include" >>"$work/tree/runtime/graph/PassGraph.cpp"
  local line out
  line=$(wc -l <"$work/tree/runtime/graph/PassGraph.cpp")
  if out=$(python3 "$work/tree/scripts/check-layers.py" --root "$work/tree"); then
    echo "check-layers.py passed a graph file that includes the $layer layer"; exit 1
  fi
  local expected="runtime/graph/PassGraph.cpp:$line: \"$include\" is in the '$layer' layer, $relation this file's 'graph' layer, which uses only core, model (runtime/layers.txt)"
  grep -qF "$expected" <<<"$out" || { echo "check-layers.py failed without saying: $expected"; echo "$out"; exit 1; }
  echo "check-layers.py: $out"

  printf '#include "graph/PassGraph.h"\n#include "%s"\n' "$include" >"$work/refused.cpp"
  if "$cxx" -std=c++20 -fsyntax-only -I"$binary_dir/layers/graph" "$work/refused.cpp" 2>"$work/compile.log"; then
    echo "a graph-layer file including $include compiled"; exit 1
  fi
  grep -qF "$include" "$work/compile.log" || { echo "the compile failed for another reason:"; cat "$work/compile.log"; exit 1; }
  echo "compiler: $(grep -m1 -F "$include" "$work/compile.log")"
  "$cxx" -std=c++20 -fsyntax-only -I"$binary_dir/layers/$user" "$work/refused.cpp" || {
    echo "the same file does not compile in the $user layer either, so the test proves nothing"; exit 1; }
  echo "the same file compiles with the $user layer's include path: the include path alone refused it"
}

fresh_tree
python3 "$work/tree/scripts/check-layers.py" --root "$work/tree" >/dev/null || {
  echo "the untouched copy already fails the check"; exit 1; }

refused gl/GlContext.h gl above gl
refused io/file/AtomicFile.h io beside validation

# A declaration the files do not bear out: graph declaring io, which none of its files includes.
fresh_tree
sed -i 's/^graph: core model$/graph: core model io/' "$work/tree/runtime/layers.txt"
grep -q '^graph: core model io$' "$work/tree/runtime/layers.txt" || { echo "layers.txt has no line 'graph: core model'"; exit 1; }
if out=$(python3 "$work/tree/scripts/check-layers.py" --root "$work/tree"); then
  echo "check-layers.py passed graph declaring io, which no graph file includes"; exit 1
fi
expected="'graph' declares 'io', but no file of runtime/graph/ includes it"
grep -qF "$expected" <<<"$out" || { echo "check-layers.py failed without saying: $expected"; echo "$out"; exit 1; }
echo "check-layers.py: $out"
