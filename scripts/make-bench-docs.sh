#!/usr/bin/env bash
# Usage: scripts/make-bench-docs.sh [--lock FILE]
#
# Regenerates, in one go, the comparison with other codecs, the scale
# figures and the plots:
#   docs/peers.md, docs/data/peers.csv   build/bin/drm-peer-bench on ../shared/meshes (~5 min)
#   docs/data/scale.csv, batch.csv, peers-big.csv
#                                        tools/bench/measure_scale.py: corpus meshes of
#                                        1K..270K triangles and igea subdivided to 1.1M and
#                                        4.3M, as processes; many files with -j (~15 min)
#   docs/images/peers-connectivity.png, time-per-triangle.png, scale-memory.png
#                                        tools/bench/make_plots.py
#   docs/results.md                      its plots and Scale sections only
#                                        (make_results.py --scale-only; the rest of the file
#                                        is tools/bench/make_results.py's full run)
# Needs a build with drm-peer-bench (scripts/build.sh; the peers' libraries come
# from scripts/setup.sh), python3 with numpy and matplotlib (Debian's), and
# the meshes of ../shared/meshes (or $DRM_MESH_DIR). --lock FILE: take an
# exclusive flock on FILE around each measured run, for a shared machine.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
lock=()
if [ "${1:-}" = "--lock" ]; then
  [ -n "${2:-}" ] || { echo "make-bench-docs: --lock needs a file" >&2; exit 2; }
  lock=(--lock "$2")
fi
meshes=${DRM_MESH_DIR:-../shared/meshes}
# Debian's python3 has numpy and matplotlib; a pyenv or venv python3 first on PATH may not.
python=python3
python3 -c 'import numpy, matplotlib' 2>/dev/null || python=/usr/bin/python3
[ -x build/bin/drm-peer-bench ] || { echo "make-bench-docs: build/bin/drm-peer-bench not built (scripts/setup.sh, scripts/build.sh)" >&2; exit 1; }

mkdir -p docs/data
peer_bench=(build/bin/drm-peer-bench "$meshes" --markdown docs/peers.md --csv docs/data/peers.csv)
if [ ${#lock[@]} -gt 0 ]; then flock "${lock[1]}" "${peer_bench[@]}" >/dev/null; else "${peer_bench[@]}" >/dev/null; fi
"$python" tools/bench/measure_scale.py --meshes "$meshes" "${lock[@]}"
"$python" tools/bench/make_plots.py
"$python" tools/bench/make_results.py --scale-only
echo "make-bench-docs: docs/peers.md, docs/data/*.csv, docs/images/{peers-connectivity,time-per-triangle,scale-memory}.png, docs/results.md (plots, Scale)"
