#!/bin/sh
# package.outside_project: the build installed into a temporary prefix is usable from outside.
#   outside-project.sh BUILD SOURCE CMAKE NINJA [PYTHON PYTHONDIR]
# 1. cmake --install BUILD --prefix P, and the package's layout checked;
# 2. the installed rmfx renders effects/shader_1.xml at 64x64 into an EXR, loading the installed
#    image codecs module (found from P/bin by the install's folders; LD_DEBUG says which file);
# 3. package/Test/outside/ (find_package(rmfx), rmfx::rmfx) configured with CMAKE_PREFIX_PATH=P,
#    built with Ninja and run: it renders the same workspace through the public API and checks it
#    against the effect's maths and the command's EXR (main.cpp says what it checks);
# 4. where the Python module is built, the installed one imported from P and run with Debian's
#    python3, loading the installed codecs module too.
set -eu
build=$1 source=$2 cmake=$3 ninja=$4 python=${5:-} pythondir=${6:-}
work=$(mktemp -d "${TMPDIR:-/tmp}/rmfx-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
# Nothing chosen by hand: every part must be found from the install itself.
unset RMFX_IMAGE_CODECS RMFX_HLSL_WORKER RMFX_EDITOR || true

fail() { echo "FAIL: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
libdir=$(cd "$prefix" && ls -d lib/cmake/rmfx lib/*/cmake/rmfx 2>/dev/null | head -n 1 | sed 's,/cmake/rmfx$,,')
[ -n "$libdir" ] || fail "no lib*/cmake/rmfx under $prefix"
for file in include/rmfx/run/HeadlessRun.h include/rmfx/compile/RunPreparation.h include/rmfx/core/Result.h \
            "$libdir/librmfx.so" "$libdir/rmfx-image-codecs.so" "$libdir/cmake/rmfx/rmfxConfig.cmake" \
            "$libdir/cmake/rmfx/rmfxConfigVersion.cmake" bin/rmfx libexec/rmfx/rmfx-hlsl-worker; do
  [ -e "$prefix/$file" ] || fail "the install has no $file"
done
if find "$prefix/include" -name Test -o -name '*.cpp' | grep -q .; then fail "the install has test folders or sources under include/"; fi
echo "ok:   installed into $prefix ($libdir)"

# codecs_from LOG: the rmfx-image-codecs.so the process whose LD_DEBUG=files output is LOG loaded.
codecs_from() { sed -n 's,.*file=\(/[^ ]*rmfx-image-codecs\.so\) .*,\1,p' "$1" | head -n 1; }

LD_DEBUG=files LD_DEBUG_OUTPUT="$work/render.ld" "$prefix/bin/rmfx" render "$source/effects/shader_1.xml" \
  --size 64x64 --set Exposure_Level=0.5 -o "$work/command.exr" --quiet || fail "the installed rmfx render"
codecs=$(codecs_from "$work/render.ld".*)
case "$codecs" in "$prefix"/*) echo "ok:   the installed rmfx loaded $codecs" ;; *) fail "the installed rmfx loaded the codecs module '$codecs'" ;; esac

"$cmake" -S "$source/package/Test/outside" -B "$work/outside" -G Ninja -DCMAKE_MAKE_PROGRAM="$ninja" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configuring the outside project"; }
"$cmake" --build "$work/outside" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building the outside project"; }
echo "ok:   the outside project built against the package"
"$work/outside/outside" "$source/effects/shader_1.xml" "$work/command.exr" "$prefix"

if [ -n "$python" ] && [ -n "$pythondir" ]; then
  ls "$prefix/$pythondir"/rmfx/_rmfx.*.so "$prefix/$pythondir"/rmfx/__init__.py "$prefix/$pythondir"/rmfx/dask.py >/dev/null 2>&1 ||
    fail "no Python package rmfx/ in $prefix/$pythondir"
  (cd "$work" && PYTHONPATH="$prefix/$pythondir" LD_DEBUG=files LD_DEBUG_OUTPUT="$work/python.ld" "$python" -c '
import sys, rmfx
assert rmfx.__file__.startswith(sys.argv[1] + "/"), rmfx.__file__
ws = rmfx.load(sys.argv[2])
ws["Exposure_Level"] = 0.5
out = ws.renderer(size=(64, 64)).render()
assert out.shape == (64, 64, 4) and out[..., :3].max() > 0.01, (out.shape, out.max())
print("ok:   the installed Python module", rmfx.__file__, "rendered, mean", out[..., :3].mean())
' "$prefix" "$source/effects/shader_1.xml") || fail "the installed Python module"
  codecs=$(codecs_from "$work/python.ld".*)
  case "$codecs" in "$prefix"/*) echo "ok:   the Python module loaded $codecs" ;; *) fail "the Python module loaded the codecs module '$codecs'" ;; esac
fi
echo "passed"
