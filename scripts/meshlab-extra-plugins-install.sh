#!/usr/bin/env bash
# Usage: scripts/meshlab-extra-plugins-install.sh [--remove] [RELEASE [PLUGIN_DIR]]
#
# Installs drm's MeshLab plugins for the current user, without root, into
# MeshLab's per-user plugin folder, which MeshLab 2021.05 and later load at
# start-up (Help > Plugin Info > Load Plugins copies plugins there too):
#   ${XDG_DATA_HOME:-~/.local/share}/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/RELEASE/
# RELEASE (2022.02, 2025.07, ...) defaults to the installed MeshLab's
# (Debian's meshlab package); PLUGIN_DIR to build-meshlab-RELEASE/plugins,
# which scripts/build-meshlab-plugins.sh fills. MeshLab loads a plugin only
# when it was built for its own release, so the plugins must come from that
# release's build. --remove takes them out again. For MeshLab 2020.09, which
# has no such folder, use scripts/meshlab-user-install.sh PREFIX.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
our_plugins=(libio_drm.so libfilter_drm.so)

fail() { echo "meshlab-extra-plugins-install: $*" >&2; exit 1; }

remove=0
if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 0
fi
if [ "${1:-}" = "--remove" ]; then remove=1; shift; fi
[ $# -le 2 ] || fail "usage: $0 [--remove] [RELEASE [PLUGIN_DIR]]"

release=${1:-}
if [ -z "$release" ]; then
  installed=$(dpkg-query -W -f='${Version}' meshlab 2>/dev/null || true)
  [ -n "$installed" ] || fail "no MeshLab package installed: name the release (2022.02, 2025.07)"
  release=${installed:0:7}
fi
case "$release" in
  [0-9][0-9][0-9][0-9].[0-9][0-9]) ;;
  *) fail "'$release' is not a MeshLab release (such as 2025.07)" ;;
esac
[[ "$release" > "2021.04" ]] ||
  fail "MeshLab $release has no per-user plugin folder: use scripts/meshlab-user-install.sh PREFIX"

target="${XDG_DATA_HOME:-$HOME/.local/share}/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/$release"
if [ "$remove" = 1 ]; then
  for p in "${our_plugins[@]}"; do rm -f "$target/$p"; done
  echo "meshlab-extra-plugins-install: removed drm plugins from $target"
  exit 0
fi

plugins_from=${2:-$here/build-meshlab-$release/plugins}
for p in "${our_plugins[@]}"; do
  [ -f "$plugins_from/$p" ] ||
    fail "$plugins_from/$p not found: build the plugins for MeshLab $release first (bash scripts/build-meshlab-plugins.sh $release)"
done
mkdir -p "$target"
for p in "${our_plugins[@]}"; do
  if cmp -s "$plugins_from/$p" "$target/$p"; then continue; fi
  # Through a temporary name, so a running MeshLab never maps a half-written file.
  cp -f "$plugins_from/$p" "$target/$p.tmp.$$"
  chmod 644 "$target/$p.tmp.$$"
  mv -f "$target/$p.tmp.$$" "$target/$p"
done
echo "meshlab-extra-plugins-install: drm plugins for MeshLab $release installed in $target"
