#!/usr/bin/env bash
# Configures and builds drm into build/ (the `drm` tool lands at build/bin/drm,
# the MeshLab 2020.09 plugins in build/plugins/), and the plugins for MeshLab
# 2022.02 and 2025.07 into build-meshlab-RELEASE/plugins/
# (DRM_SKIP_MESHLAB_RELEASES=1 leaves those out).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${DRM_BUILD_DIR:-$here/build}"
generator=()
command -v ninja >/dev/null && [ ! -f "$build/Makefile" ] && generator=(-G Ninja)
releases="2022.02;2025.07"
if [ "${DRM_SKIP_MESHLAB_RELEASES:-0}" = 1 ]; then
  releases=""
else
  # The plugins for MeshLab 2022.02 and 2025.07, built inside their Debian
  # roots into build-meshlab-RELEASE/ (one build at a time: never beside the
  # host's).
  bash "$here/scripts/build-meshlab-plugins.sh" 2022.02 2025.07
fi
cmake -S "$here" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE="${DRM_BUILD_TYPE:-RelWithDebInfo}" \
  -DDRM_MESHLAB_RELEASES="$releases" >/dev/null
cmake --build "$build" -j"$(nproc)"
