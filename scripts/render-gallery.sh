#!/usr/bin/env bash
# Renders every scene of examples/ into docs/gallery/ (the pictures of docs/gallery.md), plus the
# paper's fig. 8 series: the same scene at 1, 4, 16 and 64 samples per pixel, and random and regular
# against jittered at 4. Run after `make build`:  scripts/render-gallery.sh
set -euo pipefail
cd "$(dirname "$0")/.."
glint=./build/release/glint
out=docs/gallery
mkdir -p "$out"
for scene in examples/*.yaml; do
  name=$(basename "$scene" .yaml)
  # 64 samples per pixel: enough for the path-traced scenes to read clearly, at the scenes' own sizes.
  "$glint" render "$scene" --spp 64 --quiet -o "$out/$name.png"
done
# The series' 64-spp jittered picture is the example's own render above (its sampler is jittered).
for spp in 1 4 16; do
  "$glint" render examples/fig08-sampling.yaml --spp "$spp" --sampler jittered --quiet -o "$out/fig08-$spp-jittered.png"
done
"$glint" render examples/fig08-sampling.yaml --spp 4 --sampler random --quiet -o "$out/fig08-4-random.png"
"$glint" render examples/fig08-sampling.yaml --spp 4 --sampler regular --quiet -o "$out/fig08-4-regular.png"
