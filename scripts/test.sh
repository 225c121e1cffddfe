#!/usr/bin/env bash
# Sets up a Debian bookworm machine, builds everything and runs the whole test
# suite. This is what CI runs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"
build="${DRM_BUILD_DIR:-$here/build}"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
