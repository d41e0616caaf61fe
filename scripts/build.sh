#!/usr/bin/env bash
# Sets up the machine (scripts/setup.sh), then configures and builds meromorph into build/.
# Extra arguments go to CMake (for example -DMEROMORPH_BUILD_MESHLAB_PLUGIN=ON).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh"
cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$here/build" --parallel "$(nproc)"
