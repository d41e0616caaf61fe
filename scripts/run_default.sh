#!/usr/bin/env bash
# The newcomer's first command: set up, build, and run the main job on the bundled default
# surface (a genus-2 "eight", tests/data/eight.off).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh" >/dev/null
"$here/build/vcg_core/meromorph" info "$here/tests/data/eight.off"
