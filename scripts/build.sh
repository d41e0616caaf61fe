#!/usr/bin/env bash
# Sets up the machine (scripts/setup.sh), then configures and builds meromorph into build/.
# Extra arguments go to CMake (for example -DMEROMORPH_BUILD_MESHLAB_PLUGIN=ON).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh"
cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$here/build" --parallel "$(nproc)"
# With the Python package built: `import meromorph` for Debian's python3, through a .pth file in
# the user's site folder that names build/python (nothing is copied; a rebuild is what it loads).
if [ -d "$here/build/python/meromorph" ]; then
  site=$(/usr/bin/python3 -m site --user-site)
  mkdir -p "$site"
  echo "$here/build/python" >"$site/meromorph-build.pth"
fi
