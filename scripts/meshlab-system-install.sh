#!/usr/bin/env bash
# Usage: sudo scripts/meshlab-system-install.sh [PLUGIN_DIR]
#        sudo scripts/meshlab-system-install.sh --remove
#
# Installs drm's MeshLab plugins (libio_drm.so, libfilter_drm.so) into the
# system MeshLab's plugin folder. PLUGIN_DIR defaults to the build for the
# installed MeshLab's release (Debian's meshlab package): build/plugins for
# 2020.09, build-meshlab-RELEASE/plugins for later ones (MeshLab loads only
# plugins built for its own release). --remove takes them out again. Running
# it twice changes nothing the second time. Without root:
# scripts/meshlab-extra-plugins-install.sh (2021.05 on) or
# scripts/meshlab-user-install.sh PREFIX (2020.09).
# MESHLAB_PLUGIN_DIR overrides the target folder (for a MeshLab elsewhere).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
target=${MESHLAB_PLUGIN_DIR:-/usr/lib/x86_64-linux-gnu/meshlab/plugins}
our_plugins=(libio_drm.so libfilter_drm.so)

fail() { echo "meshlab-system-install: $*" >&2; exit 1; }

if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  echo "usage: sudo $0 [PLUGIN_DIR | --remove]   (PLUGIN_DIR defaults to the build for the installed MeshLab)"
  echo "  Installs drm's plugins into the system MeshLab ($target); --remove takes them out."
  echo "  Without root: scripts/meshlab-extra-plugins-install.sh (MeshLab 2021.05 on), or"
  echo "  scripts/meshlab-user-install.sh PREFIX (MeshLab 2020.09)."
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

installed=$(dpkg-query -W -f='${Version}' meshlab 2>/dev/null || true)
case "${installed:0:7}" in
  ""|2020.09) default_plugins="$here/build/plugins" ;;
  *) default_plugins="$here/build-meshlab-${installed:0:7}/plugins" ;;
esac
plugins_from=${1:-$default_plugins}
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
