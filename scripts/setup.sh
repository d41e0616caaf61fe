#!/usr/bin/env bash
# Installs what meromorph needs on Debian 12 from Debian's own packages, then fetches the MeshLab
# source package (which carries vcglib and MeshLab's plugin headers) into .cache/.
# Usage: scripts/setup.sh [core|all]   core: what the command-line tool and the C library need;
#        all (default): that, and MeshLab, Blender, Xvfb, GoogleTest and clang for the tests.
# Idempotent: a second run installs nothing and downloads nothing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="$here/.cache"
mkdir -p "$cache"
what="${1:-all}"

sudo_if_needed() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread libopenblas-dev libmetis-dev
  libgfortran-12-dev
  libcli11-dev nlohmann-json3-dev
  dpkg-dev
  python3-dev python3-numpy python3-pybind11
)
if [ "$what" = all ]; then
  packages+=(
    libgtest-dev googletest
    qtbase5-dev libqt5opengl5-dev libglew-dev
    meshlab xvfb xauth
    blender python3-numpy
    python3-dev python3-pybind11 python3-pytest python3-distributed
    clang-format clang libclang-rt-14-dev
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# Source package list: a deb-src entry for the same suite as the binary packages.
src_list=/etc/apt/sources.list.d/meromorph-src.sources
need_update=0
if [ ! -f "$src_list" ]; then
  # The mirror this machine's own binary packages come from (deb822 or one-line format).
  mirror=$(sed -n 's/^URIs:[[:space:]]*\([^[:space:]]*\).*/\1/p' /etc/apt/sources.list.d/*.sources \
             2>/dev/null | grep -v -- '-security' | head -n 1 || true)
  if [ -z "$mirror" ] && [ -f /etc/apt/sources.list ]; then
    mirror=$(awk '$1 == "deb" && $0 !~ /security/ { for (i = 2; i <= NF; ++i) if ($i ~ /:\/\//) { print $i; exit } }' \
               /etc/apt/sources.list)
  fi
  if [ -z "$mirror" ]; then
    echo "meromorph setup: no Debian package source found in /etc/apt to add its source packages from" >&2
    exit 1
  fi
  sudo_if_needed tee "$src_list" >/dev/null <<SRC
Types: deb-src
URIs: $mirror
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  need_update=1
fi

meshlab_src_ok() { [ -d "$cache/meshlab/vcglib/vcg" ] && [ -d "$cache/meshlab/src/common" ]; }

if [ "${#missing[@]}" -gt 0 ] || [ "$need_update" -eq 1 ] || ! meshlab_src_ok; then
  echo "meromorph setup: apt-get update" >&2
  sudo_if_needed apt-get update -qq
fi
if [ "${#missing[@]}" -gt 0 ]; then
  echo "meromorph setup: installing ${missing[*]}" >&2
  sudo_if_needed env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# vcglib + MeshLab plugin headers, matching the installed MeshLab exactly.
if ! meshlab_src_ok; then
  echo "meromorph setup: fetching the meshlab source package" >&2
  work="$cache/meshlab-download"
  rm -rf "$work" && mkdir -p "$work"
  chmod 777 "$work"
  (cd "$work" && apt-get source --download-only meshlab >/dev/null 2>&1)
  orig=$(ls "$work"/meshlab_*.orig.tar.* | head -n 1)
  rm -rf "$cache/meshlab" && mkdir -p "$cache/meshlab"
  tar -xf "$orig" -C "$cache/meshlab" --strip-components=1
  rm -rf "$work"
  meshlab_src_ok || { echo "meromorph setup: the meshlab source package has no vcglib/ or src/common/" >&2; exit 1; }
fi
echo "meromorph setup: ready (vcglib at $cache/meshlab/vcglib)" >&2
