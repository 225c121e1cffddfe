#!/usr/bin/env bash
# Usage: scripts/meshlab-user-install.sh PREFIX [PLUGIN_DIR]
#
# A private MeshLab 2020.09 with drm's plugins, for users without root (and
# for the tests): PREFIX/bin/meshlab and PREFIX/bin/meshlabserver.
#
# MeshLab looks for plugins only in
# dirname(realpath(executable))/../lib/x86_64-linux-gnu/meshlab/plugins, so
# the executables are copied (a symlink would resolve back to /usr/bin).
# The core library, the stock plugins and the shaders are symlinked to the
# system's; our two plugins are copied from PLUGIN_DIR (default build/plugins).
# Running it again updates the copies and leaves everything else as it is.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage() {
  echo "usage: $0 PREFIX [PLUGIN_DIR]   (PLUGIN_DIR defaults to $here/build/plugins)"
  echo "  Installs MeshLab 2020.09 with drm's plugins into PREFIX, without root:"
  echo "  then run PREFIX/bin/meshlab, or PREFIX/bin/meshlabserver for scripts."
}
if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  usage
  exit 0
fi
if [ $# -lt 1 ] || [ $# -gt 2 ] || [ "${1#-}" != "$1" ]; then
  usage >&2
  exit 2
fi
prefix=$1
plugins_from=${2:-$here/build/plugins}
system_lib=/usr/lib/x86_64-linux-gnu/meshlab
our_plugins=(libio_drm.so libfilter_drm.so)

fail() { echo "meshlab-user-install: $*" >&2; exit 1; }

for exe in /usr/bin/meshlab /usr/bin/meshlabserver; do
  [ -x "$exe" ] || fail "$exe not found: install Debian's meshlab package (scripts/setup.sh)"
done
[ -f "$system_lib/libmeshlab-common.so" ] || fail "$system_lib/libmeshlab-common.so not found"
for p in "${our_plugins[@]}"; do
  [ -f "$plugins_from/$p" ] || fail "$plugins_from/$p not found: build drm first (scripts/build.sh)"
done

mkdir -p "$prefix/bin" "$prefix/lib/x86_64-linux-gnu/meshlab/plugins" "$prefix/share"
prefix=$(cd "$prefix" && pwd)
lib="$prefix/lib/x86_64-linux-gnu/meshlab"

# Copies, not links: the binaries' RUNPATH ($ORIGIN/../lib/...) then finds
# the prefix's libmeshlab-common.so, and MeshLab the prefix's plugins.
# Written through a temporary name so a running MeshLab is not disturbed.
copy() {
  cmp -s "$1" "$2" 2>/dev/null && return 0
  cp -f "$1" "$2.tmp.$$" && chmod "$3" "$2.tmp.$$" && mv -f "$2.tmp.$$" "$2"
}
copy /usr/bin/meshlab "$prefix/bin/meshlab" 755
copy /usr/bin/meshlabserver "$prefix/bin/meshlabserver" 755

ln -sfn "$system_lib/libmeshlab-common.so" "$lib/libmeshlab-common.so"
for p in "$system_lib"/plugins/*.so; do
  ln -sfn "$p" "$lib/plugins/$(basename "$p")"
done
# Stock plugins removed from the system since the last run.
for p in "$lib"/plugins/*.so; do
  if [ -L "$p" ] && [ ! -e "$p" ]; then rm -f "$p"; fi
done
# Shaders for the GUI's render plugins, found relative to the executable.
if [ -d /usr/share/meshlab ]; then ln -sfn /usr/share/meshlab "$prefix/share/meshlab"; fi

for p in "${our_plugins[@]}"; do
  copy "$plugins_from/$p" "$lib/plugins/$p" 644
done

echo "meshlab-user-install: MeshLab with drm plugins in $prefix (run $prefix/bin/meshlab or $prefix/bin/meshlabserver)"
