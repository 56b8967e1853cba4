#!/usr/bin/env bash
# Fails when a binary that must build without the shader compilers links glslang or SPIRV-Cross, or
# the workspace parser's tinyxml2: the unit-test executables of the runtime layers that use none of
# them (tests/CMakeLists.txt lists them from runtime/layers.txt: core, model and graph; only io,
# frontend and the layers above link them). Three checks per binary:
#   1. its link command (ninja's, from BUILD_DIR) names no glslang, SPIRV, spirv-cross or tinyxml2
#      library;
#   2. no glslang, SPIRV-Cross or tinyxml2 code is in it (nm: glslang is linked statically, so ldd
#      cannot show it);
#   3. ldd lists no libspirv-cross, libglslang or libtinyxml2.
# Usage: scripts/check-no-glslang.sh BUILD_DIR BINARY...   (BINARY: a path inside BUILD_DIR)
set -euo pipefail
build_dir=$(cd "$1" && pwd)
shift
libraries='(lib)?(glslang|SPIRV|spirv-cross|tinyxml2)[A-Za-z0-9_.-]*\.(a|so)'
status=0
for binary in "$@"; do
  if [ ! -x "$binary" ]; then
    echo "check-no-glslang: $binary: no such executable" >&2
    status=1
    continue
  fi
  path=$(cd "$(dirname "$binary")" && pwd)/$(basename "$binary")
  target=${path#"$build_dir"/}
  link=$(ninja -C "$build_dir" -t commands "$target" | tail -n 1)
  if ! grep -q -- "-o $target" <<<"$link"; then
    echo "check-no-glslang: $binary: ninja in $build_dir has no link command for $target" >&2
    status=1
    continue
  fi
  named=$(grep -oE "$libraries" <<<"$link" | sort -u || true)
  if [ -n "$named" ]; then
    echo "check-no-glslang: $binary is linked with $(echo $named)" >&2
    status=1
    continue
  fi
  code=$(nm -C "$binary" | grep -E ' (glslang|spirv_cross|spvc_|tinyxml2::)' | head -n 3 || true)
  if [ -n "$code" ]; then
    echo "check-no-glslang: $binary holds glslang, SPIRV-Cross or tinyxml2 code:" >&2
    echo "$code" >&2
    status=1
    continue
  fi
  shared=$(ldd "$binary" | awk '{print $1}' | grep -E 'spirv|glslang|tinyxml2' || true)
  if [ -n "$shared" ]; then
    echo "check-no-glslang: $binary loads $(echo $shared)" >&2
    status=1
    continue
  fi
  echo "check-no-glslang: $(basename "$binary"): no glslang, SPIRV-Cross or tinyxml2 in its link command, its code or ldd's list"
done
exit $status
