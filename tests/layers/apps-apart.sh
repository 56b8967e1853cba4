#!/usr/bin/env bash
# The applications stay apart (docs/architecture.md):
#   1. scripts/check-layers.py fails when cli/ (rmfx) includes editor/ (rmfx-edit), naming the
#      file and line, when python/ (import rmfx) includes cli/, and when apps/ includes the gl layer;
#   2. the rmfx binary links no GLFW and no Dear ImGui (ldd), so a render node without a
#      windowing stack runs it; rmfx-edit, where built, does;
#   3. the rmfx binary links no OpenImageIO either: the image codecs module beside it does, loaded
#      when a command reads or writes images (runtime/io/image/ImageCodecs.h).
# Usage: apps-apart.sh SOURCE_DIR RMFX [RMFX_EDIT]
set -euo pipefail
source_dir=$1 rmfx=$2 rmfx_edit=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/tree/scripts"
cp "$source_dir/scripts/check-layers.py" "$work/tree/scripts/"
for d in runtime apps cli editor python; do cp -r "$source_dir/$d" "$work/tree/$d"; done
python3 "$work/tree/scripts/check-layers.py" --root "$work/tree" >/dev/null || {
  echo "the untouched copy already fails the check"; exit 1; }
# refused FILE INCLUDE WHY: check-layers.py fails FILE with INCLUDE appended, saying so at its line.
refused() {
  local file=$1 include=$2 why=$3 line expected out
  printf '#include "%s"\n' "$include" >>"$work/tree/$file"
  line=$(wc -l <"$work/tree/$file")
  if out=$(python3 "$work/tree/scripts/check-layers.py" --root "$work/tree"); then
    echo "check-layers.py passed $file including $include"; exit 1
  fi
  expected="$file:$line: \"$include\": $why"
  grep -qF "$expected" <<<"$out" || { echo "check-layers.py failed without saying: $expected"; echo "$out"; exit 1; }
  echo "check-layers.py: $out"
  cp "$source_dir/$file" "$work/tree/$file"
}
refused cli/ListCommand.cpp editor/Editor.h "cli/ and editor/ are separate programs"
refused python/Module.cpp cli/Commands.h "python/ and cli/ are separate programs"
printf '#include "gl/GlContext.h"\n' >>"$work/tree/apps/OptionValues.cpp"
if out=$(python3 "$work/tree/scripts/check-layers.py" --root "$work/tree"); then
  echo "check-layers.py passed apps/ including the gl layer"; exit 1
fi
echo "check-layers.py: $out"

linked=$(ldd "$rmfx")
if grep -Ei 'glfw|imgui' <<<"$linked"; then
  echo "$rmfx links a windowing library (above): rmfx must run without one"; exit 1
fi
# Dear ImGui may be linked statically: its functions would then be in the binary itself.
symbols=$(nm -C "$rmfx")
if grep -q ' ImGui::' <<<"$symbols"; then
  echo "$rmfx holds Dear ImGui's functions (nm): rmfx must not build the editor in"; exit 1
fi
echo "ldd $rmfx: no GLFW and no ImGui ($(wc -l <<<"$linked") libraries); nm: no ImGui function"
if grep -i openimageio <<<"$linked"; then
  echo "$rmfx links OpenImageIO (above): only the image codecs module may"; exit 1
fi
codecs="$(dirname "$rmfx")/rmfx-image-codecs.so"
grep -qi openimageio <<<"$(ldd "$codecs")" || { echo "$codecs does not link OpenImageIO: is the check looking at the right thing?"; exit 1; }
echo "ldd $rmfx: no OpenImageIO; ldd $codecs: OpenImageIO"
if [ -n "$rmfx_edit" ]; then
  grep -qi glfw <<<"$(ldd "$rmfx_edit")" || { echo "$rmfx_edit does not link GLFW: is the check looking at the right thing?"; exit 1; }
  edit_symbols=$(nm -C "$rmfx_edit")
  grep -q ' ImGui::' <<<"$edit_symbols" || grep -qi imgui <<<"$(ldd "$rmfx_edit")" || {
    echo "$rmfx_edit holds no ImGui: is the check looking at the right thing?"; exit 1; }
  echo "ldd/nm $rmfx_edit: GLFW and ImGui, as the editor must"
fi
