#!/usr/bin/env bash
# Fails when a binary that must run without GL links a GL, EGL or windowing library: the unit-test
# executables (every build/tests/rmfx_*_tests but rmfx_gl_tests) and the fuzzers. Two checks per binary:
#   1. its own NEEDED entries (what rmfx's build linked) hold none of them;
#   2. of what `ldd` lists (the whole closure), any such library arrives only through Debian's
#      OpenImageIO, whose OpenCV links libGLX and X11 for its own optional OpenGL interop; rmfx
#      calls none of it. One reached any other way fails.
# Usage: scripts/check-no-gl.sh BINARY...
set -euo pipefail
pattern='lib(GL|GLX|GLdispatch|EGL|GLES|OpenGL|epoxy|glfw|X11|X11-xcb|xcb[a-z0-9-]*|wayland-[a-z]*|gbm|drm)\.so'
status=0
for binary in "$@"; do
  if [ ! -x "$binary" ]; then
    echo "check-no-gl: $binary: no such executable" >&2
    status=1
    continue
  fi
  direct=$(readelf -d "$binary" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  bad_direct=$(grep -E "$pattern" <<<"$direct" || true)
  if [ -n "$bad_direct" ]; then
    echo "check-no-gl: $binary links $(echo $bad_direct) directly" >&2
    status=1
    continue
  fi
  closure=$(ldd "$binary" | awk '{print $1}' | grep -E "$pattern" | sort -u || true)
  via_oiio=""
  if grep -q '^libOpenImageIO\.so' <<<"$direct"; then
    oiio=$(ldd "$binary" | awk '$1 ~ /^libOpenImageIO\.so/ {print $3}')
    via_oiio=$(ldd "$oiio" | awk '{print $1}' | grep -E "$pattern" | sort -u || true)
  fi
  others=$(comm -23 <(echo "$closure" | sed '/^$/d') <(echo "$via_oiio" | sed '/^$/d'))
  if [ -n "$others" ]; then
    echo "check-no-gl: $binary reaches $(echo $others) other than through OpenImageIO" >&2
    status=1
  elif [ -n "$closure" ]; then
    echo "check-no-gl: $(basename "$binary"): links no GL or windowing library; ldd lists $(echo $closure | wc -w) only through OpenImageIO → OpenCV ($(echo $closure))"
  else
    echo "check-no-gl: $(basename "$binary"): no GL or windowing library, directly or in ldd's closure"
  fi
done
exit $status
