#!/usr/bin/env bash
# Usage: resources/batch-compress.sh [--stop-on-error] DIR OUTDIR
#
# Compresses every mesh in DIR (.ply .obj .off .stl, not recursive) to
# OUTDIR/NAME.drm through MeshLab (meshlabserver with drm's io plugin, the
# plugin's default options: 12 bits, auto predictor), with every attribute
# of the mesh a .drm file keeps. Prints a line per file
# and a summary with bits per vertex; a file that cannot be compressed (for
# example a NaN coordinate) is reported, the others are still compressed,
# the failures are listed at the end and the exit code is 1
# (--stop-on-error: stop at the first). Existing files in OUTDIR are
# replaced only by complete new ones.
batch_name=batch-compress
# shellcheck source=resources/batch-common.sh
source "$(dirname "${BASH_SOURCE[0]}")/batch-common.sh"

batch_help="compresses every .ply/.obj/.off/.stl in DIR to OUTDIR/NAME.drm"
batch_arguments "$@"
batch_display "$@"
batch_setup "${batch_args[0]}" "${batch_args[1]}"

shopt -s nullglob nocaseglob
inputs=("$batch_in"/*.ply "$batch_in"/*.obj "$batch_in"/*.off "$batch_in"/*.stl)
shopt -u nocaseglob
[ ${#inputs[@]} -gt 0 ] || batch_fail "no .ply, .obj, .off or .stl files in $batch_in"

declare -A taken=()
for in in "${inputs[@]}"; do
  base=$(basename "$in")
  out="$batch_out/${base%.*}.drm"
  # bunny.ply and bunny.obj would both become bunny.drm.
  [ -z "${taken[$out]:-}" ] || batch_fail "$base and ${taken[$out]} would both be written to $(basename "$out")"
  taken[$out]=$base
  batch_convert "$in" "$out" "${batch_attributes[@]}"
done
batch_summary
