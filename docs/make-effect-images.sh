#!/usr/bin/env bash
# Renders the images of docs/effects.md from the workspaces in effects/ with the built rmfx:
#   bash docs/make-effect-images.sh [BUILD_DIR]      (default: build)
# Every image is one frame at 384x384 with the workspace's default values unless noted.
set -euo pipefail
cd "$(dirname "$0")/.."
rmfx="${1:-build}/rmfx"
out=docs/images
render() { "$rmfx" render "$@" -q; }

for ws in shader_1 shader_2 shader_3 shader_4 shader_5 shader_6 exercise_1 exercise_2; do
  render effects/$ws.xml --size 384x384 -o "$out/$ws.png"
done

# Automatic exposure after 120 frames (settled), with the 8-bit and the half-float sky.
render effects/auto_exposure.xml --size 384x384 --frames 120 -o "$out/auto_exposure.png"
render effects/auto_exposure.xml --size 384x384 --frames 120 --set Environment_Format=1 -o "$out/auto_exposure_float.png"

# HDRLighting after 30 frames of 0.5 s, so the light adaptation has settled.
lighting="effects/hdr_lighting.xml --size 384x384 --frames 30 --dt 0.5"
render $lighting -o "$out/hdr_lighting.png"
render $lighting --set Star_Type=4 --set Tone_Map_Operator=2 -o "$out/hdr_lighting_sunnycross_photographic.png"
render $lighting --set Tone_Map_Operator=0 --set Bloom_Scale=0 --set Star_Scale=0 --set Blue_Shift=false \
  -o "$out/hdr_lighting_no_tone_map.png"

# HDRLighting with its colour targets in each encoding: float, RGB16, RGB32 / RGB9E5, RGBE8, RGBA8x64.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for e in 0 1 2 3 4 5; do
  render effects/hdr_lighting.xml --size 256x256 --frames 30 --dt 0.5 --set HDR_Encoding=$e -o "$tmp/encoding_$e.png"
done
oiiotool "$tmp"/encoding_{0,1,2,3,4,5}.png --mosaic 3x2 -o "$out/hdr_lighting_encodings.png"

# The article's four exposures side by side (256x256 each).
for e in 0.5 2.5 10 20; do
  render effects/article_pipeline.xml --size 256x256 --set fExposureLevel=$e -o "$tmp/article_$e.png"
done
oiiotool "$tmp/article_0.5.png" "$tmp/article_2.5.png" "$tmp/article_10.png" "$tmp/article_20.png" \
  --mosaic 4x1 -o "$out/article_pipeline.png"
echo "wrote the images of docs/effects.md into $out"
