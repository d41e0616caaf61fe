#!/usr/bin/env bash
# Set up, build, and run every test (GoogleTest through CTest).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh" -DMEROMORPH_BUILD_TESTS=ON -DMEROMORPH_BUILD_MESHLAB_PLUGIN=ON -DMEROMORPH_BUILD_BLENDER_ADDON=ON
cd "$here/build"
ctest --output-on-failure --parallel "$(nproc)"
# The same suite under AddressSanitizer and UndefinedBehaviorSanitizer, then the fuzz targets
# briefly over the committed corpus.
bash "$here/scripts/sanitize.sh" 10
