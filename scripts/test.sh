#!/usr/bin/env bash
# Sets up a Debian bookworm machine, builds everything and runs the whole test
# suite, the web package's tests (scripts/test-web.sh: the WebAssembly
# decoder under Node and the viewer in headless Chromium; DRM_SKIP_WEB=1
# leaves them out), then a bounded libFuzzer run over the decoder and over encode-decode
# round trips and over the mesh file readers (AddressSanitizer and UBSan
# builds with clang, in build-fuzz/;
# DRM_SKIP_FUZZ=1 leaves it out). This is what CI runs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"
build="${DRM_BUILD_DIR:-$here/build}"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
if [ "${DRM_SKIP_WEB:-0}" != 1 ]; then
  DRM_CLI="$build/bin/drm" bash "$here/scripts/test-web.sh"
fi
# fuzz NAME ARGS...: runs tests/fuzz/run_fuzzer.sh; prints libFuzzer's final
# line, or the whole report when it finds something (exit 1).
fuzz() {
  local name=$1 log
  shift
  log=$(mktemp)
  if bash "$here/tests/fuzz/run_fuzzer.sh" "$@" >"$log" 2>&1; then
    echo "fuzz $name: $(grep -E '^Done [0-9]+ runs' "$log" | tail -1)"
    rm -f "$log"
  else
    tail -60 "$log"
    echo "fuzz $name: FAILED (inputs that fail are in build-fuzz/artifacts/)"
    rm -f "$log"
    return 1
  fi
}
if [ "${DRM_SKIP_FUZZ:-0}" != 1 ]; then
  fuzz decoder -runs=20000
  fuzz round-trip --roundtrip -runs=20000
  fuzz readers --readers -runs=20000
fi
