#!/bin/bash
# Genus 0 against FLASH (Choi, Lam, Lui 2015; the linear spherical conformal map), on the same
# meshes and the same machine: FLASH's algorithm time in Octave (the file read before its clock
# starts; least of 3) beside `meromorph param`'s whole process (start to exit, reading and writing
# included; least of 7) and beside the map made in a running process as the Blender add-on makes
# it (its ctypes binding and the library it ships, called from Python; the mesh read before the
# clock starts; least of 3, as FLASH: scripts/flash/time_in_process.py). FLASH's code is not
# part of meromorph: pass the folder holding its spherical_conformal_map.m and the files it calls
# (the `mfile` folder of Gary Choi's spherical-conformal-map code). Meshes: closed genus-0 OFF
# files (triangles).
#
# Usage: scripts/compare_flash.sh FLASH_MFILE_DIR MESH.off [MESH.off ...]
# Prints a Markdown table. Installs octave-cli and python3-numpy if missing (apt-get, as root).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
tool="${MEROMORPH:-$here/../build/vcg_core/meromorph}"
addon="${MEROMORPH_ADDON:-$here/../build/blender_addon/stage/meromorph_blender}"
[ $# -ge 2 ] || { sed -n 2,13p "$0"; exit 2; }
flash="$(cd "$1" && pwd)"; shift
[ -f "$flash/spherical_conformal_map.m" ] || { echo "no spherical_conformal_map.m in $flash" >&2; exit 2; }
[ -x "$tool" ] || { echo "build meromorph first (bash scripts/build.sh): $tool" >&2; exit 2; }
[ -f "$addon/library.py" ] || {
  echo "build the Blender add-on first (bash scripts/build.sh -DMEROMORPH_BUILD_BLENDER_ADDON=ON): $addon" >&2
  exit 2
}
# (Debian's python3-numpy is for /usr/bin/python3, whatever python3 is first on the PATH)
if ! command -v octave-cli > /dev/null || ! /usr/bin/python3 -c "import numpy" 2> /dev/null; then
  apt-get update -q && apt-get install -y -q --no-install-recommends octave python3-numpy
fi
scratch="$(mktemp -d)"; trap 'rm -rf "$scratch"' EXIT

least_ms() { # least wall time of N runs of a command, in ms
  # (bash's own clock: `$(date)` around the command added its own start, 2 to 4 ms, to each run)
  local n=$1 best=""; shift
  for _ in $(seq "$n"); do
    local start end
    start=${EPOCHREALTIME/./}; "$@" > /dev/null; end=${EPOCHREALTIME/./}
    local ms=$(( (end - start) / 100 ))
    if [ -z "$best" ] || [ "$ms" -lt "$best" ]; then best=$ms; fi
  done
  echo "$((best / 10)).$((best % 10))"
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.1f", a / b}'; }

echo "| mesh | vertices | FLASH (Octave, algorithm) | meromorph param (whole process) | FLASH / meromorph | meromorph in process (as the Blender add-on) | FLASH / meromorph in process |"
echo "|---|---|---|---|---|---|---|"
for mesh in "$@"; do
  # (Octave 7 prints a harmless "ignoring const execution_exception" line at exit)
  timed=$(octave-cli --no-gui "$here/flash/time_flash.m" "$flash" "$mesh" 3 2>&1 |
    grep -v "ignoring const execution_exception" || true)
  if ! echo "$timed" | grep -q flash_ms; then
    echo "$mesh: FLASH failed:" >&2; echo "$timed" >&2; exit 1
  fi
  vertices=$(echo "$timed" | awk '/vertices/ {print $2}')
  flash_ms=$(echo "$timed" | awk '/flash_ms/ {print $2}')
  ours_ms=$(least_ms 7 "$tool" param "$mesh" -o "$scratch/out.ply" --quiet)
  in_process=$(/usr/bin/python3 "$here/flash/time_in_process.py" "$addon" "$mesh" 3)
  in_process_ms=$(echo "$in_process" | awk '/least_ms/ {print $2}')
  echo "| $(basename "$mesh") | $vertices | $flash_ms ms | $ours_ms ms | $(ratio "$flash_ms" "$ours_ms") | $in_process_ms ms | $(ratio "$flash_ms" "$in_process_ms") |"
done
