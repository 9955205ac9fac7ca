#!/usr/bin/env bash
# Renders every scene of examples/ into docs/gallery/ (the pictures of docs/gallery.md), plus the
# paper's fig. 8 series: the same scene at 1, 4, 16 and 64 samples per pixel, and random and regular
# against jittered at 4. Run after `make build`:  scripts/render-gallery.sh
# A failure does not stop the others: the script goes on, lists what failed at the end and exits 1.
set -uo pipefail
cd "$(dirname "$0")/.."
glint=./build/release/glint
out=docs/gallery
mkdir -p "$out"
failed=()
render() {  # render SCENE OUTPUT [FLAGS…]
  local scene=$1 image=$2
  shift 2
  "$glint" render "$scene" --quiet -o "$image" "$@" || failed+=("$scene -> $image")
}
for scene in examples/*.yaml; do
  name=$(basename "$scene" .yaml)
  # 64 samples per pixel: enough for the path-traced scenes to read clearly, at the scenes' own sizes.
  render "$scene" "$out/$name.png" --spp 64
done
# The series' 64-spp jittered picture is the example's own render above (its sampler is jittered).
for spp in 1 4 16; do
  render examples/fig08-sampling.yaml "$out/fig08-$spp-jittered.png" --spp "$spp" --sampler jittered
done
render examples/fig08-sampling.yaml "$out/fig08-4-random.png" --spp 4 --sampler random
render examples/fig08-sampling.yaml "$out/fig08-4-regular.png" --spp 4 --sampler regular
# A third-party glTF test model (examples/assets/CREDITS.md; not in examples/ itself, so not rendered
# above). It has no camera and glint's default view, from +z, shows one arrow of six: two views instead,
# each showing three arrows (the quaternion ones from +x +y +z, the matrix ones from the opposite corner).
orientation=examples/assets/gltf/OrientationTest.gltf
render "$orientation" "$out/gltf-orientation-test.png" --width 480 --height 360 --spp 64 \
  --set 'camera.eye=[15,11,17]'
render "$orientation" "$out/gltf-orientation-test-back.png" --width 480 --height 360 --spp 64 \
  --set 'camera.eye=[-15,-11,-17]'
# McGuire's OBJ + MTL Cornell box (examples/assets/CREDITS.md), from its open front.
render examples/assets/cornell-box-obj/CornellBox-Original.obj "$out/obj-cornell-box.png" --width 320 \
  --height 320 --spp 256 --set 'camera.eye=[0,1,3.9]'
# The pbrt-v4 Cornell box (not a .yaml, so not rendered above), as docs/gallery.md shows it beside
# pbrt-v4's own render of the file.
render examples/pbrt-cornell.pbrt "$out/pbrt-cornell-glint.png" --spp 256 --seed 1
if [ ${#failed[@]} -gt 0 ]; then
  printf 'render-gallery: failed: %s\n' "${failed[@]}" >&2
  exit 1
fi
echo "render-gallery: every picture rendered into $out/"
