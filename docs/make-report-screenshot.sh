#!/usr/bin/env bash
# Makes docs/images/replay-report.png, docs/replay.md's picture of `rmfx replay --report`, with the
# built rmfx and headless Chromium (scripts/setup.sh installs it):
#   bash docs/make-report-screenshot.sh [BUILD_DIR]      (default: build)
# A deliberately changed effect: HDRLighting's references are stored with every target
# (--update --all-targets), then the replay runs with the star's Chromatic_Aberration raised from
# 0.5 to 1, and the report of that replay is photographed at +1 EV.
set -euo pipefail
cd "$(dirname "$0")/.."
rmfx="$(realpath "${1:-build}/rmfx")"
browser="${RMFX_BROWSER:-chromium}"
command -v "$browser" >/dev/null || { echo "make-report-screenshot: needs $browser (bash scripts/setup.sh)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
manifest() {
  cat >"$work/manifest.xml" <<XML
<replay version="1">
  <case name="hdr_lighting" workspace="$PWD/effects/hdr_lighting.xml" size="256x256" frames="8" dt="0.25">
    <set name="Chromatic_Aberration" value="$1"/>
    <compare reference="refs/hdr_lighting.exr" error="itp" mean="0.05" percentile="99" percentile-max="1"/>
  </case>
  <case name="hdr_lighting_no_effects" workspace="$PWD/effects/hdr_lighting.xml" size="256x256" effects="">
    <compare reference="refs/hdr_lighting_no_effects.exr" error="itp" mean="0.5"/>
  </case>
</replay>
XML
}
manifest 0.5
(cd "$work" && "$rmfx" replay manifest.xml --update --all-targets -q)
manifest 1
(cd "$work" && "$rmfx" replay manifest.xml --report report -q) || true  # the change fails the replay, as intended
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$work/profile" \
  --window-size=1280,1000 --virtual-time-budget=10000 --screenshot="$PWD/docs/images/replay-report.png" \
  "file://$work/report/index.html#ev=1&op=reinhard" 2>/dev/null
echo "wrote docs/images/replay-report.png"
