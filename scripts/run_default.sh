#!/usr/bin/env bash
# The newcomer's first command: set up, build the command-line tool, and run the main job on the
# bundled default surface (a genus-2 "eight", tests/data/eight.off): the conformal map onto the
# sphere, written to build/default/ (the surface with texture coordinates, the layered sphere,
# the JSON report).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
echo "meromorph: [1/3] installing what the tool needs (Debian packages, vcglib)"
bash "$here/scripts/setup.sh" core
echo "meromorph: [2/3] building the command-line tool (build/vcg_core/meromorph)"
cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMEROMORPH_BUILD_TESTS=OFF \
  -DMEROMORPH_BUILD_BENCH=OFF >/dev/null
cmake --build "$here/build" --target meromorph --parallel "$(nproc)"
echo "meromorph: [3/3] mapping tests/data/eight.off onto the sphere"
out="$here/build/default"
mkdir -p "$out"
"$here/build/vcg_core/meromorph" param "$here/tests/data/eight.off" -o "$out/eight.uv.ply" \
  --sphere "$out/eight.sphere.ply" --report "$out/eight.report.json" --layer-gap 0.2
echo "meromorph: wrote $out/eight.uv.ply, $out/eight.sphere.ply and $out/eight.report.json"
