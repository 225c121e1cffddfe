#!/usr/bin/env bash
# Rewrites the golden .drm files and the meshes they must decode to. Run this
# only for an intended format change, and say so in the commit: the golden
# test exists so that no change of the bitstream passes unnoticed.
# earlier-versions/ holds files of pre-release format versions, never
# rewritten: the golden test checks that the reader refuses each.
# Usage: tests/golden/regenerate.sh [path/to/drm]
#        tests/golden/regenerate.sh --check path/to/drm
# --check (ctest golden.encoder_writes_the_golden_files) rewrites nothing:
# it encodes each golden file's mesh again, with the same options, into a
# temporary folder and fails naming every file the encoder now writes
# differently. The decoder's side is test_golden.cpp; this is the
# encoder's, for changes meant to leave the files as they are (a faster
# encoder, a refactoring).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
check=0
if [ "${1:-}" = "--check" ]; then check=1; shift; fi
drm="${1:-$here/../../build/bin/drm}"
data="$here/../data"
out="$here"
if [ $check = 1 ]; then
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
differ=()
encode() {  # NAME SOURCE OPTIONS...
  local name=$1 source=$2; shift 2
  rm -f "$out/$name.drm" "$out/$name.decoded.ply"
  "$drm" encode "$data/$source" "$out/$name.drm" "$@" >/dev/null
  if [ $check = 1 ]; then
    cmp -s "$out/$name.drm" "$here/$name.drm" || differ+=("$name.drm ($source $*)")
  else
    "$drm" decode "$out/$name.drm" "$out/$name.decoded.ply" >/dev/null
  fi
}
# The ranks' files ask for the ranks (--connectivity ranks): left to the
# encoder, several would come out topological.
encode torus torus.ply --connectivity ranks              # regular, closed: near-zero ranks
encode nefertiti nefertiti.ply --levers none --connectivity ranks  # open, the paper's method
encode blobby-3cc blobby-3cc.ply --keep-vertex-order --connectivity ranks  # 3 components with holes, all levers, vertex order kept
encode star-raw star-cgal.ply --geometry raw --bits 8 --predictor parallelogram
encode nefertiti-refine nefertiti.ply --geometry refine  # refine's coarse tree and low bits
encode tray-bottom tray-bottom.ply --connectivity ranks  # CAD STL slivers: the front order ranks many edges
encode bunny-lres bunny-lres.ply --connectivity ranks    # a scan: edges from the parent in the frame along the walk, their tangent signs
encode shark-refine mech-holes-shark.ply --geometry refine --refine-bits 2  # refine's coarse tree with the frame along the walk
encode blobby-boundary blobby-3cc.ply --levers boundary --connectivity ranks  # holes, the boundary flags alone: the fans walked for them only
encode bunny-lres-parts bunny-lres.ply --parts 2 --connectivity ranks  # a scan in two connectivity parts: the seam, its classes, kept vertices
encode tray-bottom-topological tray-bottom.ply           # CAD STL slivers, left to the encoder: the topological coder
encode blobby-3cc-topological blobby-3cc.ply --connectivity topological --keep-vertex-order  # 3 components with holes, topological, vertex order kept
encode fins-topological fins-and-bowtie.ply --connectivity topological  # a cut mesh: copies named at their originals' grid points, two originals on one point
if [ $check = 1 ]; then
  if [ ${#differ[@]} -gt 0 ]; then
    printf 'the encoder now writes %s differently from tests/golden\n' "${differ[@]}" >&2
    echo "regenerate.sh rewrites them; only for an intended format change (see above)" >&2
    exit 1
  fi
  echo "the encoder writes all $(ls "$out"/*.drm | wc -l) golden files byte for byte"
  exit 0
fi
ls -l "$here"/*.drm
