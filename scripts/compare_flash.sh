#!/bin/bash
# Genus 0 against FLASH (Choi, Lam, Lui 2015; the linear spherical conformal map), on the same
# meshes and the same machine: FLASH's algorithm time in Octave (the file read before its clock
# starts; least of 3) beside `meromorph param`'s whole process (start to exit, reading and writing
# included; least of 7). FLASH's code is not part of meromorph: pass the folder holding its
# spherical_conformal_map.m and the files it calls (the `mfile` folder of Gary Choi's
# spherical-conformal-map code). Meshes: closed genus-0 OFF files (triangles).
#
# Usage: scripts/compare_flash.sh FLASH_MFILE_DIR MESH.off [MESH.off ...]
# Prints a Markdown table. Installs octave-cli if it is missing (apt-get, as root).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
tool="${MEROMORPH:-$here/../build/vcg_core/meromorph}"
[ $# -ge 2 ] || { sed -n 2,10p "$0"; exit 2; }
flash="$(cd "$1" && pwd)"; shift
[ -f "$flash/spherical_conformal_map.m" ] || { echo "no spherical_conformal_map.m in $flash" >&2; exit 2; }
[ -x "$tool" ] || { echo "build meromorph first (bash scripts/build.sh): $tool" >&2; exit 2; }
if ! command -v octave-cli > /dev/null; then
  apt-get update -q && apt-get install -y -q --no-install-recommends octave
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

echo "| mesh | vertices | FLASH (Octave, algorithm) | meromorph param (whole process) | FLASH / meromorph |"
echo "|---|---|---|---|---|"
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
  echo "| $(basename "$mesh") | $vertices | $flash_ms ms | $ours_ms ms | $(awk -v a="$flash_ms" -v b="$ours_ms" 'BEGIN {printf "%.1f", a / b}') |"
done
