#!/usr/bin/env bash
# Usage: scripts/make-screenshot.sh [rank-colours] [export-dialog] [rank-legend] [duck-textured]
#
# Regenerates the MeshLab pictures in docs/images (all three by default):
#   meshlab-rank-colours.png   fandisk (the paper's Figure 1(b)) with faces
#                              coloured by distance rank: drm's filter run by
#                              meshlabserver and saved as PLY with face
#                              colours, which the GUI then opens;
#   meshlab-export-dialog.png  File > Export Mesh As... > fandisk.drm: the
#                              save dialog with drm's options, Help ticked;
#   meshlab-rank-legend.png    the filter run from Filters > Color Creation
#                              and Processing > Colorize Faces by Distance
#                              Rank: the coloured mesh and the legend in the
#                              log pane;
#   meshlab-duck-textured.png  ../shared/meshes-attributes/duck.obj encoded by
#                              `drm encode` (texture coordinates with seams,
#                              normals, its material and texture name), then
#                              opened from duck.drm in the GUI with
#                              duckCM.tga beside it: textured as it was.
# Real MeshLab 2020.09 (the GUI, under Xvfb, 1280x900, no window manager),
# driven with xdotool: the clicks are at the places MeshLab 2020.09 puts its
# menus and dialogs on that screen. Needs a build (build/plugins, or
# $DRM_BUILD_DIR/plugins), xvfb-run, xdotool and imagemagick (scripts/
# setup.sh installs them). Touches nothing outside a temporary folder and
# the pictures: MeshLab's settings go to a throwaway HOME.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Second stage, run by xvfb-run below: start MeshLab, act, capture.
if [ "${1:-}" = "--inside-xvfb" ]; then
  which=$2 meshlab=$3 mesh=$4 out=$5 scratch=$6
  "$meshlab" "$mesh" >"$HOME/meshlab-$which.log" 2>&1 &
  pid=$!
  trap 'kill "$pid" 2>/dev/null || true' EXIT
  window=$(timeout 60 xdotool search --sync --onlyvisible --name "^MeshLab 20" | head -1)
  [ -n "$window" ] || { echo "make-screenshot: MeshLab's window did not appear" >&2; exit 1; }
  xdotool windowmove "$window" 0 0 windowsize "$window" 1280 900
  sleep 3
  case "$which" in
  rank-colours)
    # A three-quarter view: drag the trackball a little, zoom in one wheel
    # notch (button 5 zooms in), then move the pointer off the 3D view.
    xdotool mousemove 300 350 mousedown 1 mousemove 340 330 sleep 0.2 mousemove 380 310 sleep 0.2 \
            mousemove 420 300 mouseup 1
    xdotool mousemove 430 420 click 5
    xdotool mousemove 1100 250
    sleep 4
    import -window root "$out"
    ;;
  duck-textured)
    # A three-quarter view of the duck, then move the pointer away.
    xdotool mousemove 600 450 mousedown 1 mousemove 560 430 sleep 0.2 mousemove 520 420 mouseup 1
    xdotool mousemove 1100 250
    sleep 4
    import -window root "$HOME/whole.png"
    convert "$HOME/whole.png" -crop 853x724+0+0 +repage "$out"
    ;;
  rank-legend)
    # Filters > Color Creation and Processing > Colorize Faces by Distance
    # Rank (third in its alphabetical list), Apply, Close.
    xdotool mousemove 120 10 click 1 sleep 1 mousemove 200 211 sleep 0.3 mousemove 300 211 sleep 1.2
    xdotool mousemove 400 211 mousemove 490 62 sleep 0.4 click 1
    timeout 30 xdotool search --sync --onlyvisible --name "^Colorize Faces by Distance Rank" >/dev/null
    sleep 1
    xdotool mousemove 354 444 click 1 sleep 4 mousemove 122 444 click 1
    xdotool mousemove 1100 250
    sleep 2
    import -window root "$out"
    ;;
  export-dialog)
    # File > Export Mesh As..., a .drm name in a scratch folder, then the
    # save dialog with Help ticked; OK, so the file must then exist.
    xdotool mousemove 36 10 click 1 sleep 1 mousemove 106 211 click 1
    sleep 2
    xdotool mousemove 630 563 click --repeat 3 1 sleep 0.3 type --delay 30 "$scratch/fandisk.drm"
    xdotool key Return
    sleep 2
    xdotool mousemove 177 411 click 1 sleep 1.5 mousemove 700 600
    sleep 1
    import -window root "$HOME/whole.png"
    convert "$HOME/whole.png" -crop 687x449+0+0 +repage "$out"
    xdotool mousemove 549 411 click 1
    sleep 3
    [ -s "$scratch/fandisk.drm" ] || { echo "make-screenshot: the export did not write fandisk.drm" >&2; exit 1; }
    ;;
  esac
  exit 0
fi

shots=("$@")
[ ${#shots[@]} -gt 0 ] || shots=(rank-colours export-dialog rank-legend)
for shot in "${shots[@]}"; do
  case "$shot" in
    rank-colours|export-dialog|rank-legend|duck-textured) ;;
    -h|--help) sed -n '2,22p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "make-screenshot: unknown picture '$shot' (rank-colours, export-dialog, rank-legend, duck-textured)" >&2; exit 2 ;;
  esac
done
build=${DRM_BUILD_DIR:-$here/build}
mesh=$here/tests/data/fandisk.ply
for tool in xvfb-run xdotool import convert; do
  command -v "$tool" >/dev/null || { echo "make-screenshot: $tool missing (scripts/setup.sh installs it)" >&2; exit 1; }
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bash "$here/scripts/meshlab-user-install.sh" "$tmp/prefix" "$build/plugins" >/dev/null

coloured="$tmp/fandisk-ranks.ply"
xvfb-run -a "$tmp/prefix/bin/meshlabserver" -i "$mesh" -o "$coloured" -m fc -s "$here/resources/colorize-by-rank.mlx" \
  >"$tmp/server.log" 2>&1 || true
[ -s "$coloured" ] || { echo "make-screenshot: colouring failed:" >&2; tail -5 "$tmp/server.log" >&2; exit 1; }

mkdir -p "$tmp/home" "$tmp/runtime" "$tmp/scratch" "$here/docs/images"
chmod 700 "$tmp/runtime"
for shot in "${shots[@]}"; do
  input=$mesh
  [ "$shot" != rank-colours ] || input=$coloured
  if [ "$shot" = duck-textured ]; then
    duck="$here/../shared/meshes-attributes"
    [ -f "$duck/duck.obj" ] || { echo "make-screenshot: $duck/duck.obj is missing" >&2; exit 1; }
    mkdir -p "$tmp/duck"
    cp "$duck/duckCM.tga" "$tmp/duck/"
    "$build/bin/drm" encode "$duck/duck.obj" "$tmp/duck/duck.drm" >/dev/null
    input=$tmp/duck/duck.drm
  fi
  rm -f "$tmp/shot.png"
  HOME="$tmp/home" XDG_CONFIG_HOME="$tmp/home/.config" XDG_RUNTIME_DIR="$tmp/runtime" \
    xvfb-run -a -s "-screen 0 1280x900x24" bash "$here/scripts/make-screenshot.sh" --inside-xvfb \
    "$shot" "$tmp/prefix/bin/meshlab" "$input" "$tmp/shot.png" "$tmp/scratch"
  [ -s "$tmp/shot.png" ] || { echo "make-screenshot: no picture of $shot was captured" >&2; exit 1; }
  mv -f "$tmp/shot.png" "$here/docs/images/meshlab-$shot.png"
  echo "make-screenshot: wrote docs/images/meshlab-$shot.png"
done
