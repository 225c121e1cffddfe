#!/usr/bin/env bash
# Builds drm's MeshLab plugins for MeshLab RELEASE (2022.02 or 2025.07)
# inside that release's Debian root (scripts/meshlab-root.sh makes it), with
# the root's compiler and Qt and the release's own headers and vcglib:
#   build-meshlab-RELEASE/plugins/libio_drm.so, libfilter_drm.so
#   build-meshlab-RELEASE/bin/meshlab_harness   (tests/meshlab_harness)
# Usage: build-meshlab-plugins.sh RELEASE...   (default: both)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
releases=("$@")
[ ${#releases[@]} -gt 0 ] || releases=(2022.02 2025.07)
for release in "${releases[@]}"; do
  bash "$here/scripts/meshlab-root.sh" make "$release"
  echo "build-meshlab-plugins: MeshLab $release -> build-meshlab-$release/plugins/"
  bash "$here/scripts/meshlab-root.sh" run "$release" bash -c '
    set -eo pipefail
    build=/drm/build-meshlab-$1
    cmake -S /drm -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDRM_PLUGINS_ONLY=ON \
      -DDRM_MESHLAB_RELEASE="$1" >/dev/null
    # A failed build fails this script: the plugins of an earlier build are
    # never taken for new ones. Progress lines ("[ 42%] ...") are left out.
    cmake --build "$build" -j"$(nproc)" -- --no-print-directory 2>&1 | { grep -v "^\[" || true; }
    test -f "$build/plugins/libio_drm.so" && test -f "$build/plugins/libfilter_drm.so" &&
      test -x "$build/bin/meshlab_harness"
  ' bash "$release"
done
