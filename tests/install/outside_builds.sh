#!/usr/bin/env bash
# Installs the build into a temporary prefix, then uses it as an outside
# project would:
# - the installed names: headers under include/drmcodec/ (nothing under
#   include/drm/, the kernel's), no file named like Debian's libdrm;
# - the shared library's exports: the API only (at most 300 symbols, no
#   FLANN, no internals);
# - examples/ built with CMake (find_package(drmcodec), shared and static)
#   and with pkg-config, and run;
# - a C and a C++ program that include a kernel-like <drm/drm.h> beside
#   drm's headers, built and run;
# - the Python package: installed where the Python looks for the prefix,
#   importable from there, and installed by pip into a virtual environment.
# Usage: outside_builds.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
here="$source/tests/install"

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for f in include/drmcodec/drmcodec.h include/drmcodec/drmcodec_c.h lib/libdrmcodec.a lib/libdrmcodec.so \
         lib/cmake/drmcodec/drmcodecConfig.cmake lib/pkgconfig/drmcodec.pc bin/drm; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; ls -R "$prefix"; exit 1; }
done
if [ -e "$prefix/include/drm" ]; then echo "installed include/drm/, the kernel's header folder"; exit 1; fi
if ls "$prefix"/lib/libdrm.* > /dev/null 2>&1; then echo "installed a file named like Debian's libdrm"; exit 1; fi
"$prefix/bin/drm" --version > /dev/null 2>&1 || "$prefix/bin/drm" --help > /dev/null

echo "== exports"
nm -D --defined-only "$prefix/lib/libdrmcodec.so" | awk '{print $3}' > "$work/exports"
exported=$(wc -l < "$work/exports")
flann=$(c++filt < "$work/exports" | grep -ci flann || true)
internal=$(c++filt < "$work/exports" | grep -cE 'drm::(weld|checkIndices|encodeConnectivity|VertexIndex|RangeEncoder)' || true)
echo "$exported symbols exported, $flann of FLANN, $internal internal"
[ "$exported" -le 300 ] || { echo "more than 300 exported symbols"; exit 1; }
[ "$flann" -eq 0 ] || { echo "FLANN symbols exported"; exit 1; }
[ "$internal" -eq 0 ] || { echo "internal symbols exported"; exit 1; }
c++filt < "$work/exports" | grep -q '^drm::encode(' || { echo "drm::encode is not exported"; exit 1; }
grep -q '^drmcodec_decode$' "$work/exports" || { echo "drmcodec_decode is not exported"; exit 1; }

echo "== CMake project"
cmake -S "$source/examples" -B "$work/cmake" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" > "$work/cmake.log" ||
  { cat "$work/cmake.log"; exit 1; }
cmake --build "$work/cmake" > "$work/cmake-build.log" || { cat "$work/cmake-build.log"; exit 1; }
"$work/cmake/roundtrip"
"$work/cmake/roundtrip_static"
# The static target names its dependencies as imported targets, no paths.
if grep -q 'liblz4\.so' "$prefix/lib/cmake/drmcodec/drmcodecTargets.cmake"; then
  echo "the exported targets hard-code liblz4's path"; exit 1
fi

echo "== pkg-config"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
pkg-config --exists drmcodec
# shellcheck disable=SC2046
c++ -std=c++14 -o "$work/roundtrip-pc" "$source/examples/roundtrip.cpp" $(pkg-config --cflags --libs drmcodec) \
  -Wl,-rpath,"$(pkg-config --variable=libdir drmcodec)"
"$work/roundtrip-pc"
# The static library's own dependencies, liblz4 through its .pc file.
pkg-config --static --libs drmcodec | grep -q -- '-llz4' || { echo "pkg-config --static lacks -llz4"; exit 1; }
# shellcheck disable=SC2046
c++ -std=c++14 -o "$work/roundtrip-static-pc" "$source/examples/roundtrip.cpp" $(pkg-config --cflags drmcodec) \
  "$(pkg-config --variable=libdir drmcodec)/libdrmcodec.a" $(pkg-config --static --libs-only-other --libs-only-l drmcodec | sed 's/-ldrmcodec//')
"$work/roundtrip-static-pc"

echo "== beside a kernel-like <drm/drm.h>"
libdir="$prefix/lib"
cc -std=c99 -Wall -Wextra -Werror -I "$here/kernel_like" -I "$prefix/include" -o "$work/consumer-c" \
  "$here/consumer.c" -L "$libdir" -ldrmcodec -Wl,-rpath,"$libdir"
"$work/consumer-c"
c++ -std=c++14 -Wall -Wextra -Werror -I "$here/kernel_like" -I "$prefix/include" -o "$work/consumer-cpp" \
  "$here/consumer.cpp" -L "$libdir" -ldrmcodec -Wl,-rpath,"$libdir"
"$work/consumer-cpp"
c++ -std=c++14 -Wall -Wextra -Werror -I "$here/kernel_like" -I "$prefix/include" -o "$work/consumer-cpp-static" \
  "$here/consumer.cpp" "$libdir/libdrmcodec.a" -llz4 -pthread -fopenmp
"$work/consumer-cpp-static"

python=$(sed -n 's/^DRM_PYTHON_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
reldir=$(sed -n 's/^DRM_PYTHON_INSTALL_DIR:STRING=//p' "$build/CMakeCache.txt")
if [ -n "$python" ] && [ -n "$reldir" ]; then
  echo "== Python package from the prefix ($reldir)"
  [ -f "$prefix/$reldir/drm/__init__.py" ] || { echo "the package is not in $prefix/$reldir"; exit 1; }
  # Installed with the prefix /usr/local, the package lies where this
  # Python looks without PYTHONPATH.
  "$python" -c 'import sys; p = "/usr/local/" + sys.argv[1]; sys.exit(0 if p in sys.path else "not on sys.path: " + p)' "$reldir"
  PYTHONPATH="$prefix/$reldir" "$python" -c \
    'import drm, sys; m = drm.load(sys.argv[1]); assert drm.decode(drm.encode(m.vertices, m.faces))[1].shape == m.faces.shape; print("drm", drm.__version__, "from", drm.__file__)' \
    "$source/tests/data/torus.ply"

  echo "== pip install --no-build-isolation"
  "$python" -m venv --system-site-packages "$work/venv"
  DRM_BUILD_DIR="$build" "$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$source" \
    > "$work/pip.log" 2>&1 || { cat "$work/pip.log"; exit 1; }
  (cd "$work" && "$work/venv/bin/python" -c \
    'import drm, sys; assert drm.__file__.startswith(sys.prefix), drm.__file__; print("pip: drm", drm.__version__, "from", drm.__file__)')
  "$work/venv/bin/python" -m drm.batch --help > /dev/null
fi
echo "outside builds: ok"
