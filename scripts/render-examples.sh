#!/usr/bin/env bash
# Renders every scene of examples/ (glint's YAML and JSON, and the pbrt-v4 scenes glint imports) into OUT
# (default build/examples/), going on past a failure, then lists what failed; exits 1 if anything did.
# Run after `make build`:  scripts/render-examples.sh [OUT]
set -uo pipefail
cd "$(dirname "$0")/.."
glint=./build/release/glint
out=${1:-build/examples}
mkdir -p "$out"
failed=()
count=0
for scene in examples/*.yaml examples/*.json examples/*.pbrt; do
  [ -e "$scene" ] || continue
  count=$((count + 1))
  name=$(basename "${scene%.*}")
  if ! "$glint" render "$scene" --quiet -o "$out/$name.png"; then
    failed+=("$scene")
  fi
done
echo "render-examples: $((count - ${#failed[@]})) of $count examples rendered into $out/"
if [ ${#failed[@]} -gt 0 ]; then
  printf 'render-examples: failed: %s\n' "${failed[@]}" >&2
  exit 1
fi
