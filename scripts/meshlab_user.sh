#!/usr/bin/env bash
# MeshLab (Debian's 2020.09) with the meromorph filters, without root and without touching the
# system's MeshLab: a folder of your own holds a copy of the MeshLab program beside a plugins/
# folder (links to the system's plugins and to meromorph's), which is where MeshLab loads plugins
# from; then that MeshLab runs with your arguments.
#
# Usage: scripts/meshlab_user.sh [--plugin PATH] [--home DIR] meshlab|meshlabserver [ARGS...]
#   --plugin: libfilter_meromorph.so (default: the build tree's, build/meshlab_plugin/)
#   --home:   the folder (default: ${XDG_DATA_HOME:-~/.local/share}/meromorph/meshlab)
# Headless: xvfb-run -a scripts/meshlab_user.sh meshlabserver -i in.ply -o out.ply -m vt vq vf \
#             -s meshlab_plugin/examples/conformal_spherical_parameterization.mlx
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
plugin="$here/build/meshlab_plugin/libfilter_meromorph.so"
home="${XDG_DATA_HOME:-$HOME/.local/share}/meromorph/meshlab"
while [ $# -gt 0 ]; do
  case "$1" in
  --plugin) plugin="$(realpath "$2")"; shift 2 ;;
  --home) home="$2"; shift 2 ;;
  *) break ;;
  esac
done
program="${1:-meshlab}"
shift || true
case "$program" in meshlab | meshlabserver) ;; *)
  echo "meshlab_user.sh: the program is meshlab or meshlabserver, not '$program'" >&2; exit 2 ;;
esac
[ -f "$plugin" ] || {
  echo "meshlab_user.sh: no plugin at $plugin (build it: bash scripts/build.sh -DMEROMORPH_BUILD_MESHLAB_PLUGIN=ON)" >&2
  exit 2
}
system_plugins=/usr/lib/x86_64-linux-gnu/meshlab/plugins
mkdir -p "$home/plugins"
# The program is copied, not linked: MeshLab looks for plugins/ beside its own path.
cp -u "/usr/bin/$program" "$home/$program"
for system in "$system_plugins"/*.so; do
  name="$(basename "$system")"
  [ "$name" = libfilter_meromorph.so ] || ln -sfn "$system" "$home/plugins/$name"
done
ln -sfn "$plugin" "$home/plugins/libfilter_meromorph.so"
export LD_LIBRARY_PATH="/usr/lib/x86_64-linux-gnu/meshlab${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
exec "$home/$program" "$@"
