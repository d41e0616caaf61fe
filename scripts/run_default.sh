#!/usr/bin/env bash
# The newcomer's first command: set up, build, and run the main job on the bundled default
# surface (a genus-2 "eight", tests/data/eight.off): the conformal map onto the sphere, written to
# build/default/ (the surface with texture coordinates, the layered sphere, the JSON report).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh" >/dev/null
out="$here/build/default"
mkdir -p "$out"
"$here/build/vcg_core/meromorph" param "$here/tests/data/eight.off" -o "$out/eight.uv.ply" \
  --sphere "$out/eight.sphere.ply" --report "$out/eight.report.json" --layer-gap 0.2
echo "wrote $out/eight.uv.ply, $out/eight.sphere.ply and $out/eight.report.json"
