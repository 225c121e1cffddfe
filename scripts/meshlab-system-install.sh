#!/usr/bin/env bash
# Usage: sudo scripts/meshlab-system-install.sh [PLUGIN_DIR]
#        sudo scripts/meshlab-system-install.sh --remove
#
# Installs drm's MeshLab plugins (libio_drm.so, libfilter_drm.so, from
# PLUGIN_DIR, default build/plugins) into the system MeshLab 2020.09's plugin
# folder, the only one /usr/bin/meshlab and meshlabserver search. --remove
# takes them out again. Running it twice changes nothing the second time.
# Without root, use scripts/meshlab-user-install.sh PREFIX instead.
# MESHLAB_PLUGIN_DIR overrides the target folder (for a MeshLab elsewhere).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
target=${MESHLAB_PLUGIN_DIR:-/usr/lib/x86_64-linux-gnu/meshlab/plugins}
our_plugins=(libio_drm.so libfilter_drm.so)

fail() { echo "meshlab-system-install: $*" >&2; exit 1; }

if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  echo "usage: sudo $0 [PLUGIN_DIR | --remove]   (PLUGIN_DIR defaults to $here/build/plugins)"
  echo "  Installs drm's plugins into the system MeshLab ($target); --remove takes them out."
  echo "  Without root: scripts/meshlab-user-install.sh PREFIX."
  exit 0
fi
[ $# -le 1 ] || fail "usage: $0 [PLUGIN_DIR | --remove]"
[ -d "$target" ] || fail "$target not found: install Debian's meshlab package (scripts/setup.sh)"
[ -w "$target" ] || fail "cannot write to $target: needs root (sudo $0 $*), or use scripts/meshlab-user-install.sh PREFIX"

if [ "${1:-}" = "--remove" ]; then
  for p in "${our_plugins[@]}"; do rm -f "$target/$p"; done
  echo "meshlab-system-install: removed drm plugins from $target"
  exit 0
fi

plugins_from=${1:-$here/build/plugins}
for p in "${our_plugins[@]}"; do
  [ -f "$plugins_from/$p" ] || fail "$plugins_from/$p not found: build drm first (scripts/build.sh)"
done
for p in "${our_plugins[@]}"; do
  if cmp -s "$plugins_from/$p" "$target/$p"; then continue; fi
  # Through a temporary name, so a running MeshLab never maps a half-written file.
  install -m 644 "$plugins_from/$p" "$target/$p.tmp.$$"
  mv -f "$target/$p.tmp.$$" "$target/$p"
done
echo "meshlab-system-install: drm plugins installed in $target"
