#!/usr/bin/env bash
# Makes docs/images/editor.png, the README's picture of the editor, with the built rmfx under Xvfb:
#   bash docs/make-editor-screenshot.sh [BUILD_DIR]      (default: build)
# HDRLighting after 30 frames of 0.5 s (the light adaptation has settled), with the viewer of its
# star target open; the whole window, the effect 1:1 at its top-left corner.
set -euo pipefail
cd "$(dirname "$0")/.."
rmfx="${1:-build}/rmfx"
command -v xvfb-run >/dev/null || { echo "make-editor-screenshot: needs xvfb-run (bash scripts/setup.sh)" >&2; exit 1; }
xvfb-run -a -s "-screen 0 1280x800x24" "$rmfx" edit effects/hdr_lighting.xml --size 384x384 --frames 30 --dt 0.5 \
  --view star --screenshot docs/images/editor.png
echo "wrote docs/images/editor.png"
