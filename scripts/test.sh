#!/usr/bin/env bash
# Set up, build, and run every test of the release build (GoogleTest through CTest, the real
# MeshLab and Blender included); ends with a line of counts. CI runs this, then the sanitized
# suite and the fuzz targets (scripts/sanitize.sh, .ci/run).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh" -DMEROMORPH_BUILD_TESTS=ON -DMEROMORPH_BUILD_MESHLAB_PLUGIN=ON \
  -DMEROMORPH_BUILD_BLENDER_ADDON=ON -DMEROMORPH_BUILD_PYTHON=ON
cd "$here/build"
log="$here/build/ctest.log"
status=0
ctest --output-on-failure --parallel "$(nproc)" 2>&1 | tee "$log" || status=$?
summary=$(grep -E '^[0-9]+% tests passed' "$log" | tail -1)
echo "meromorph: release suite: ${summary:-no summary (the build or ctest failed)}"
exit "$status"
