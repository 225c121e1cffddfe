#!/usr/bin/env bash
# Builds the WebAssembly decoder web/dist/drm_decoder.js with emscripten
# (em++; Debian's emscripten package) from the codec's sources, under the
# shared build lock. Incremental: objects stay in web/build/. Prints the
# output's size and its gzip size.
#   bash scripts/build-web.sh          build (2 jobs)
#   bash scripts/build-web.sh clean    remove web/build and web/dist
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
web="$root/web"
jobs="${DRM_WEB_JOBS:-2}"

if ! command -v em++ >/dev/null; then
  echo "build-web: em++ not found (install emscripten: apt-get install emscripten)" >&2
  exit 1
fi
# Debian's emscripten runs its JavaScript tools with the system's node
# modules (acorn, for the minifier) from /usr/share/nodejs.
if [ -d /usr/share/nodejs ]; then
  export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
fi

if [ "${1:-}" = clean ]; then
  exec flock /tmp/drm-build.lock make -C "$web/wasm" clean
fi

start=$(date +%s)
# Up to date: no need to wait for the lock.
if make -q -C "$web/wasm" --no-print-directory 2>/dev/null; then
  echo "build-web: up to date"
else
  flock /tmp/drm-build.lock make -C "$web/wasm" -j"$jobs" --no-print-directory
fi
end=$(date +%s)

out="$web/dist/drm_decoder.js"
bytes=$(stat -c %s "$out")
gz=$(gzip -9 -c "$out" | wc -c)
echo "build-web: $out: $bytes bytes ($gz gzipped), $((end - start)) s"
