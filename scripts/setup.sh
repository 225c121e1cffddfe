#!/usr/bin/env bash
# Installs everything drm needs on Debian bookworm, fetches MeshLab 2020.09's
# headers and vcglib from Debian's `meshlab` source package into third_party/,
# and makes the Debian roots of MeshLab 2022.02 and 2025.07.
# Idempotent: a second run only checks and returns in a few seconds.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
meshlab_src_version="2020.09+dfsg1-2"
meshlab_dir="$here/third_party/meshlab-$meshlab_src_version"

packages=(
  build-essential cmake ninja-build pkg-config git
  libgtest-dev libeigen3-dev
  libflann-dev liblz4-dev   # the codec's kd-tree index (header-only; its headers include lz4.h)
  meshlab qtbase5-dev libqt5opengl5-dev libglew-dev
  xvfb xauth dpkg-dev imagemagick xdotool x11-apps
  qt5-image-formats-plugins   # MeshLab reads TGA, TIFF and WebP textures (duck.obj's duckCM.tga)
  debootstrap   # scripts/meshlab-root.sh: Debian roots of newer MeshLab releases
  util-linux   # setpriv: the file-permission tests run as the user nobody
  assimp-testmodels   # tests/others_files: another project's test models, broken ones included
  clang libfuzzer-14-dev libclang-rt-14-dev
  libdraco-dev draco libmeshoptimizer-dev libopenctm-dev libzstd-dev   # drm-peer-bench only
  python3-matplotlib python3-numpy   # tools/bench/make_plots.py, make_big_mesh.py, measure_scale.py
  python3-dev python3-pybind11 pybind11-dev python3-pytest   # the Python package (python/) and its tests
  python3-setuptools python3-venv python3-pip   # pip install --no-build-isolation . (tests/install)
  python3-distributed   # drm.batch on a Dask cluster (dask-scheduler, dask-worker, dask-ssh)
  emscripten chromium   # web/: the WebAssembly decoder, and its viewer's test in headless Chromium
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else echo "setup: need root or sudo to install: $*" >&2; exit 1
  fi
}

# Node.js and npm for web/ (Debian's nodejs and npm unless a Node.js with
# its own npm is installed already).
command -v npm > /dev/null || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# MeshLab's headers and the vcglib it was built with exist only in the source
# package. Fetch it with apt's own configuration turned into deb-src entries in
# a private folder, so /etc/apt is never touched.
if [ ! -f "$meshlab_dir/vcglib/vcg/complex/complex.h" ]; then
  echo "setup: fetching MeshLab $meshlab_src_version sources (headers + vcglib)"
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir -p "$tmp/sources.list.d" "$tmp/lists/partial" "$tmp/archives"
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    sed -E 's/^Types:.*/Types: deb-src/' "$f" > "$tmp/sources.list.d/$(basename "$f")"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    grep -E '^deb ' "$f" | sed -E 's/^deb /deb-src /' > "$tmp/sources.list.d/$(basename "$f").list" || true
  done
  apt_opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$tmp/sources.list.d"
            -o "Dir::State::Lists=$tmp/lists" -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
            -o APT::Sandbox::User=root)
  as_root apt-get "${apt_opts[@]}" update -qq
  (cd "$tmp/archives" && as_root apt-get "${apt_opts[@]}" source --download-only -qq "meshlab=$meshlab_src_version")
  mkdir -p "$here/third_party"
  rm -rf "$meshlab_dir"
  (cd "$tmp/archives" && dpkg-source --no-check -x "meshlab_$meshlab_src_version.dsc" "$meshlab_dir" >/dev/null)
  [ -f "$meshlab_dir/vcglib/vcg/complex/complex.h" ] || { echo "setup: vcglib missing from the source package" >&2; exit 1; }
fi
# MeshLab 2022.02 and 2025.07, the releases people install today, each in a
# Debian root with its compiler, Qt and sources (scripts/meshlab-root.sh;
# cached outside the clone). DRM_SKIP_MESHLAB_RELEASES=1 leaves them out.
if [ "${DRM_SKIP_MESHLAB_RELEASES:-0}" != 1 ]; then
  for release in 2022.02 2025.07; do
    bash "$here/scripts/meshlab-root.sh" make "$release"
  done
fi
echo "setup: ok (MeshLab sources in ${meshlab_dir#$here/})"
