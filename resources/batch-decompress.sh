#!/usr/bin/env bash
# Usage: resources/batch-decompress.sh DIR OUTDIR
#
# Decompresses every .drm file in DIR (not recursive) to OUTDIR/NAME.ply
# (binary PLY, positions and triangles) through MeshLab (meshlabserver with
# drm's io plugin). Prints a line per file and a summary; stops at the first
# file that cannot be read (for example a truncated one), saying why.
# Existing files in OUTDIR are replaced only by complete new ones.
batch_name=batch-decompress
# shellcheck source=resources/batch-common.sh
source "$(dirname "${BASH_SOURCE[0]}")/batch-common.sh"

[ $# -eq 2 ] || batch_usage "decompresses every .drm in DIR to OUTDIR/NAME.ply"
batch_setup "$1" "$2"

shopt -s nullglob nocaseglob
inputs=("$batch_in"/*.drm)
shopt -u nocaseglob
[ ${#inputs[@]} -gt 0 ] || batch_fail "no .drm files in $batch_in"

for in in "${inputs[@]}"; do
  base=$(basename "$in")
  batch_convert "$in" "$batch_out/${base%.*}.ply"
done
batch_summary
