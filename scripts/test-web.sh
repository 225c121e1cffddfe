#!/usr/bin/env bash
# Tests of the web package (web/): builds the WebAssembly decoder when it
# is missing or stale (scripts/build-web.sh), installs the npm development
# dependencies from web/package-lock.json when node_modules is missing or
# older than the lock file, runs `npm test` (node --test: golden files,
# damaged files, corpus meshes and the three.js loader against the drm
# CLI) and the headless Chromium test of the viewer. Needs build/bin/drm.
#   DRM_CORPUS=DIR             corpus of .ply meshes (default /work/shared/meshes where present)
#   DRM_WEB_SKIP_BROWSER=1     leave out the Chromium test
#   CHROMIUM=PATH              the browser (default /usr/bin/chromium)
#   DRM_VIEWER_SCREENSHOT=F    where the viewer's screenshot goes (default web/build/web-viewer.png)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root/web"

bash "$root/scripts/build-web.sh"

if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  npm ci --no-audit --no-fund --prefer-offline
fi

if [ ! -x "${DRM_CLI:-$root/build/bin/drm}" ]; then
  echo "test-web: build/bin/drm is missing: build the project first (scripts/build.sh)" >&2
  exit 1
fi

npm test

if [ "${DRM_WEB_SKIP_BROWSER:-0}" = 1 ]; then
  echo "test-web: Chromium test left out (DRM_WEB_SKIP_BROWSER=1)"
else
  node test/browser/viewer-chromium.mjs
fi
echo "test-web: all passed"
