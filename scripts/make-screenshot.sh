#!/usr/bin/env bash
# Usage: scripts/make-screenshot.sh [OUT.png] [MESH]
#
# Regenerates docs/images/meshlab-rank-colours.png: real MeshLab 2020.09 (the
# GUI, under Xvfb) showing MESH (default tests/data/fandisk.ply, the paper's
# Figure 1(b)) with faces coloured by distance rank. The colours come from
# drm's filter run by meshlabserver and saved as PLY with face colours; the
# GUI then only opens that file. Needs a build (build/plugins, or
# $DRM_BUILD_DIR/plugins), xvfb-run, xdotool and imagemagick's import
# (scripts/setup.sh installs them). Touches nothing outside a temporary
# folder and OUT.png: MeshLab's settings go to a throwaway HOME.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Second stage, run by xvfb-run below: start MeshLab, frame the mesh, capture.
if [ "${1:-}" = "--inside-xvfb" ]; then
  meshlab=$2 mesh=$3 out=$4
  "$meshlab" "$mesh" >"$HOME/meshlab.log" 2>&1 &
  pid=$!
  trap 'kill "$pid" 2>/dev/null || true' EXIT
  window=$(timeout 60 xdotool search --sync --onlyvisible --name "^MeshLab 20" | head -1)
  [ -n "$window" ] || { echo "make-screenshot: MeshLab's window did not appear" >&2; exit 1; }
  xdotool windowmove "$window" 0 0 windowsize "$window" 1280 900
  sleep 3
  # A three-quarter view: drag the trackball a little, zoom in one wheel
  # notch (button 5 zooms in), then move the pointer off the 3D view.
  xdotool mousemove 300 350 mousedown 1 mousemove 340 330 sleep 0.2 mousemove 380 310 sleep 0.2 \
          mousemove 420 300 mouseup 1
  xdotool mousemove 430 420 click 5
  xdotool mousemove 1100 250
  sleep 4
  import -window root "$out"
  exit 0
fi

out=${1:-$here/docs/images/meshlab-rank-colours.png}
mesh=${2:-$here/tests/data/fandisk.ply}
build=${DRM_BUILD_DIR:-$here/build}
for tool in xvfb-run xdotool import; do
  command -v "$tool" >/dev/null || { echo "make-screenshot: $tool missing (scripts/setup.sh installs it)" >&2; exit 1; }
done
[ -f "$mesh" ] || { echo "make-screenshot: $mesh not found" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bash "$here/scripts/meshlab-user-install.sh" "$tmp/prefix" "$build/plugins" >/dev/null

name=$(basename "${mesh%.*}")
coloured="$tmp/$name-ranks.ply"
xvfb-run -a "$tmp/prefix/bin/meshlabserver" -i "$(cd "$(dirname "$mesh")" && pwd)/$(basename "$mesh")" \
  -o "$coloured" -m fc -s "$here/resources/colorize-by-rank.mlx" >"$tmp/server.log" 2>&1 || true
[ -s "$coloured" ] || { echo "make-screenshot: colouring failed:" >&2; tail -5 "$tmp/server.log" >&2; exit 1; }

mkdir -p "$tmp/home" "$tmp/runtime" "$(dirname "$out")"
chmod 700 "$tmp/runtime"
HOME="$tmp/home" XDG_CONFIG_HOME="$tmp/home/.config" XDG_RUNTIME_DIR="$tmp/runtime" \
  xvfb-run -a -s "-screen 0 1280x900x24" bash "$here/scripts/make-screenshot.sh" --inside-xvfb \
  "$tmp/prefix/bin/meshlab" "$coloured" "$tmp/shot.png"
[ -s "$tmp/shot.png" ] || { echo "make-screenshot: no picture was captured" >&2; exit 1; }
mv -f "$tmp/shot.png" "$out"
echo "make-screenshot: wrote $out"
