#!/usr/bin/env bash
# Rewrites the golden .drm files and the meshes they must decode to. Run this
# only for an intended format change, and say so in the commit: the golden
# test exists so that no change of the bitstream passes unnoticed.
# The files of older format versions (v1/ to v10/) are frozen, never rewritten: the
# golden test checks that the decoder still reads them.
# Usage: tests/golden/regenerate.sh [path/to/drm]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
drm="${1:-$here/../../build/bin/drm}"
data="$here/../data"
encode() {  # NAME SOURCE OPTIONS...
  local name=$1 source=$2; shift 2
  rm -f "$here/$name.drm" "$here/$name.decoded.ply"
  "$drm" encode "$data/$source" "$here/$name.drm" "$@" >/dev/null
  "$drm" decode "$here/$name.drm" "$here/$name.decoded.ply" >/dev/null
}
encode torus torus.ply                                  # regular, closed: near-zero ranks
encode nefertiti nefertiti.ply --levers none            # open, the paper's method
encode blobby-3cc blobby-3cc.ply --keep-vertex-order    # 3 components with holes, all levers, vertex order kept
encode star-raw star-cgal.ply --geometry raw --bits 8 --predictor parallelogram
encode nefertiti-refine nefertiti.ply --geometry refine  # refine's coarse tree and low bits
encode tray-bottom tray-bottom.ply                       # CAD STL slivers: the front order (format 5) ranks many edges
encode bunny-lres bunny-lres.ply                         # a scan: edges from the parent in the frame along the walk, their tangent signs (format 7)
encode shark-refine mech-holes-shark.ply --geometry refine --refine-bits 2  # refine's coarse tree with format 7's frame
encode blobby-boundary blobby-3cc.ply --levers boundary  # holes, the boundary flags alone (format 10): the fans walked for them only
encode bunny-lres-parts bunny-lres.ply --parts 2          # a scan in two connectivity parts (format 11): the seam, its classes, kept vertices
ls -l "$here"/*.drm
