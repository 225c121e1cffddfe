#!/usr/bin/env bash
# Sets up, builds, and runs drm's main job on a bundled mesh: encode to .drm,
# decode, verify, and print a summary. Usage: scripts/demo.sh [MESH]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mesh="${1:-$here/resources/bunny-lres.ply}"
[ -f "$mesh" ] || mesh="$here/resources/fandisk.ply"
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"
drm="${DRM_BUILD_DIR:-$here/build}/bin/drm"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
name=$(basename "$mesh" .ply)
echo "== encode $mesh"
"$drm" encode "$mesh" "$out/$name.drm"
echo "== decode"
"$drm" decode "$out/$name.drm" "$out/$name.decoded.ply"
echo "== verify (encode, decode, compare)"
"$drm" verify "$mesh"
echo "== summary"
"$drm" bench "$mesh"
