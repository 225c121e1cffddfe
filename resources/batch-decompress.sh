#!/usr/bin/env bash
# Usage: resources/batch-decompress.sh [--stop-on-error] DIR OUTDIR
#
# Decompresses every .drm file in DIR (not recursive) to OUTDIR/NAME.ply
# (binary PLY, with the colours, normals, quality and texture coordinates
# the file keeps) through MeshLab (meshlabserver with
# drm's io plugin). Prints a line per file and a summary with bits per
# vertex; a file that cannot be read (for example a truncated one) is
# reported, the others are still converted, the failures are listed at the
# end and the exit code is 1 (--stop-on-error: stop at the first).
# Existing files in OUTDIR are replaced only by complete new ones.
batch_name=batch-decompress
# shellcheck source=resources/batch-common.sh
source "$(dirname "${BASH_SOURCE[0]}")/batch-common.sh"

batch_help="decompresses every .drm in DIR to OUTDIR/NAME.ply"
batch_arguments "$@"
batch_display "$@"
batch_setup "${batch_args[0]}" "${batch_args[1]}"

shopt -s nullglob nocaseglob
inputs=("$batch_in"/*.drm)
shopt -u nocaseglob
[ ${#inputs[@]} -gt 0 ] || batch_fail "no .drm files in $batch_in"

for in in "${inputs[@]}"; do
  base=$(basename "$in")
  batch_convert "$in" "$batch_out/${base%.*}.ply" "${batch_attributes[@]}"
done
batch_summary
