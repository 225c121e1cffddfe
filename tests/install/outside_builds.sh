#!/usr/bin/env bash
# Installs the build into a temporary prefix, then builds examples/ against
# that prefix as an outside project would: with CMake (find_package(drm),
# shared and static) and with pkg-config, and runs each program. Also
# checks the installed names (no file that clashes with Debian's libdrm)
# and that the Python module imports from the prefix.
# Usage: outside_builds.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for f in include/drm/drm.h lib/libdrm_codec.a lib/libdrm_codec.so lib/cmake/drm/drmConfig.cmake \
         lib/pkgconfig/drm-codec.pc bin/drm; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; ls -R "$prefix"; exit 1; }
done
if ls "$prefix"/lib/libdrm.* > /dev/null 2>&1; then echo "installed a file named like Debian's libdrm"; exit 1; fi
"$prefix/bin/drm" --version > /dev/null 2>&1 || "$prefix/bin/drm" --help > /dev/null

echo "== CMake project"
cmake -S "$source/examples" -B "$work/cmake" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" > "$work/cmake.log" ||
  { cat "$work/cmake.log"; exit 1; }
cmake --build "$work/cmake" > "$work/cmake-build.log" || { cat "$work/cmake-build.log"; exit 1; }
"$work/cmake/roundtrip"
"$work/cmake/roundtrip_static"

echo "== pkg-config"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
pkg-config --exists drm-codec
# shellcheck disable=SC2046
c++ -std=c++14 -o "$work/roundtrip-pc" "$source/examples/roundtrip.cpp" $(pkg-config --cflags --libs drm-codec) \
  -Wl,-rpath,"$(pkg-config --variable=libdir drm-codec)"
"$work/roundtrip-pc"

if [ -d "$prefix/lib/python3/dist-packages" ]; then
  echo "== Python module from the prefix"
  PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
    'import drm; print("drm", drm.__version__, "from", drm.__file__)'
fi
echo "outside builds: ok"
