#!/usr/bin/env bash
# Usage: scripts/make-figures.sh [MESH_DIR]
#
# Regenerates docs/images/rank-*.png, pictures in the style of the paper's
# Figure 1: each face coloured by the distance rank that created it, drawn
# by `drm render --by-rank` (software rendering, no display needed). One
# mesh of each kind the README talks about, from MESH_DIR (default
# ../shared/meshes next to the project, or $DRM_MESH_DIR):
#   torus-2k   regular (every vertex of valence 6): rank 1 but for bands of 2
#   fandisk    CAD model: mostly rank 1, rank 2 scattered
#   venus      irregular scan: ranks 2, 3 and 4+ sprinkled everywhere
#   adis16480  STL tessellation of a CAD part: long slivers, rank 4+ common
# Needs a build (build/bin/drm, or $DRM_BUILD_DIR/bin/drm). Touches nothing
# but docs/images/rank-*.png, each replaced only when its render succeeds.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
meshes=${1:-${DRM_MESH_DIR:-$here/../shared/meshes}}
drm=${DRM_BUILD_DIR:-$here/build}/bin/drm
out=$here/docs/images
[ -x "$drm" ] || { echo "make-figures: $drm not found; build first (scripts/build.sh)" >&2; exit 1; }

# mesh, view: the view that shows each mesh best. venus stands on +Z and
# faces +X, so from below (-Y, Z up) it is an upright profile.
figures=(
  "torus-2k iso"
  "fandisk iso"
  "venus bottom"
  "adis16480 iso"
)
mkdir -p "$out"
for figure in "${figures[@]}"; do
  read -r name view <<<"$figure"
  mesh=$meshes/$name.ply
  [ -f "$mesh" ] || { echo "make-figures: $mesh not found (give the mesh folder as argument)" >&2; exit 1; }
  "$drm" render "$mesh" "$out/rank-$name.png" --by-rank --view "$view" --size 800x600 >/dev/null
  size=$(wc -c <"$out/rank-$name.png")
  echo "docs/images/rank-$name.png: $((size / 1024)) KB"
  # The pictures live in the repository: say so if one grows past 300 KB.
  [ "$size" -le 307200 ] || echo "make-figures: rank-$name.png is over 300 KB" >&2
done
