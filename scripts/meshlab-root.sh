#!/usr/bin/env bash
# Debian roots holding a newer MeshLab, to build and test drm's plugins against
# the MeshLab people install today:
#   2025.07  Debian sid       2022.02  Debian trixie
#
#   meshlab-root.sh make RELEASE        make the root (idempotent; cached)
#   meshlab-root.sh path RELEASE        print the root's folder
#   meshlab-root.sh run RELEASE CMD...  run CMD inside the root, the project
#                                       bind-mounted at /drm, in private mount
#                                       and network namespaces (nothing to
#                                       unmount after; no network)
#
# A root holds Debian's MeshLab binary with its libmeshlab-common.so, the
# compiler and Qt it was built with, and that release's source tarball
# (headers and vcglib) unpacked in /opt/meshlab-src. Roots live outside the
# clone, in $DRM_MESHLAB_ROOTS (default /var/cache/drm/meshlab-roots), so a
# fresh clone reuses them. Needs root (debootstrap, chroot, mount).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
roots="${DRM_MESHLAB_ROOTS:-/var/cache/drm/meshlab-roots}"

suite_of() {
  case "$1" in
    2025.07) echo sid ;;
    2022.02) echo trixie ;;
    *) echo "meshlab-root: unknown MeshLab release '$1' (known: 2022.02, 2025.07)" >&2; exit 2 ;;
  esac
}

# The Debian archive this machine's apt already uses (first URIs/deb line).
mirror() {
  local uri
  uri=$(grep -hE '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2}' | grep -v security | head -1 || true)
  [ -n "$uri" ] || uri=$(grep -hE '^deb ' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null | awk '{print $2}' | grep -v security | head -1 || true)
  echo "${uri:-http://deb.debian.org/debian}"
}

need_root() {
  [ "$(id -u)" -eq 0 ] || { echo "meshlab-root: making and entering Debian roots needs root (debootstrap, chroot)" >&2; exit 1; }
}

# Packages inside the root. meshlab with its recommends: without them half of
# MeshLab's own plugins fail to load (libgomp, muparser, qhull).
build_packages=(g++ make cmake qtbase5-dev qtbase5-dev-tools libqt5opengl5-dev libglew-dev
                libeigen3-dev libflann-dev liblz4-dev xz-utils xvfb xauth x11-apps xdotool)

make_root() {
  local release=$1 suite dir log apt_opts
  suite=$(suite_of "$release")
  dir="$roots/$suite"
  log="$roots/$suite.log"
  if [ -f "$dir/.drm-root-ready" ] &&
     [ "$(cat "$dir/.drm-packages-done" 2>/dev/null)" = "meshlab ${build_packages[*]}" ] &&
     [ "$(cat "$dir/opt/meshlab-src/.drm-meshlab-version" 2>/dev/null)" = "$(cat "$dir/.drm-root-ready")" ]; then
    echo "meshlab-root: $release ready in $dir"
    return
  fi
  need_root
  command -v debootstrap >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null
  mkdir -p "$roots"
  echo "meshlab-root: making a Debian $suite root for MeshLab $release in $dir (a few minutes, about 2.5 GB; log: $log)"
  : > "$log"
  # Each step leaves a mark, so a run that was stopped resumes where it was.
  if [ ! -f "$dir/.drm-debootstrap-done" ]; then
    rm -rf "$dir"
    debootstrap --variant=minbase "$suite" "$dir" "$(mirror)" >>"$log" 2>&1 || fail_step "debootstrap $suite" "$log"
    touch "$dir/.drm-debootstrap-done"
  fi
  cp /etc/resolv.conf "$dir/etc/resolv.conf"
  echo "deb-src $(mirror) $suite main" > "$dir/etc/apt/sources.list.d/drm-src.list"
  # The archive serves sid's Release file from an older snapshot: its
  # Valid-Until date has passed.
  apt_opts=(-o Acquire::Check-Valid-Until=false -qq)
  # The mark holds the package list: a root made before a package was added
  # to it gets the new one on the next run.
  if [ "$(cat "$dir/.drm-packages-done" 2>/dev/null)" != "meshlab ${build_packages[*]}" ]; then
    chroot "$dir" apt-get "${apt_opts[@]}" update >>"$log" 2>&1 || fail_step "apt-get update" "$log"
    chroot "$dir" env DEBIAN_FRONTEND=noninteractive apt-get "${apt_opts[@]}" install -y meshlab >>"$log" 2>&1 ||
      fail_step "installing meshlab" "$log"
    chroot "$dir" env DEBIAN_FRONTEND=noninteractive apt-get "${apt_opts[@]}" install -y --no-install-recommends \
      "${build_packages[@]}" >>"$log" 2>&1 || fail_step "installing the build packages" "$log"
    echo "meshlab ${build_packages[*]}" > "$dir/.drm-packages-done"
  fi
  # The release's own headers and vcglib. Only the original tarball is served
  # (the .dsc is not), so apt-get source fails after downloading it; Debian's
  # patches touch the build system only.
  # The sources of the MeshLab installed, marked with its version: a root
  # whose MeshLab was upgraded gets that version's sources again.
  local installed
  installed=$(chroot "$dir" dpkg-query -W -f='${Version}' meshlab)
  if [ ! -f "$dir/opt/meshlab-src/src/common/plugins/interfaces/io_plugin.h" ] ||
     [ "$(cat "$dir/opt/meshlab-src/.drm-meshlab-version" 2>/dev/null)" != "$installed" ]; then
    rm -rf "$dir/opt/meshlab-download"
    chroot "$dir" bash -c 'mkdir -p /opt/meshlab-download && cd /opt/meshlab-download &&
      { apt-get -o Acquire::Check-Valid-Until=false -qq source --download-only "meshlab=$1" || true; } &&
      ls meshlab_*.orig.tar.*' bash "$installed" >>"$log" 2>&1 ||
      fail_step "downloading the source tarball of meshlab $installed" "$log"
    # Unpacked beside, then renamed: a stopped run leaves no half folder.
    chroot "$dir" bash -c 'rm -rf /opt/meshlab-src /opt/meshlab-src.new && mkdir -p /opt/meshlab-src.new &&
      tar -xf /opt/meshlab-download/meshlab_*.orig.tar.* -C /opt/meshlab-src.new --strip-components=1 &&
      mv /opt/meshlab-src.new /opt/meshlab-src' >>"$log" 2>&1 ||
      fail_step "unpacking MeshLab's sources" "$log"
    echo "$installed" > "$dir/opt/meshlab-src/.drm-meshlab-version"
  fi
  [ -f "$dir/opt/meshlab-src/src/common/plugins/interfaces/io_plugin.h" ] || fail_step "finding MeshLab's plugin headers" "$log"
  rm -rf "$dir/opt/meshlab-download"
  chroot "$dir" apt-get clean
  chroot "$dir" dpkg-query -W -f='${Version}\n' meshlab > "$dir/.drm-root-ready"
  echo "meshlab-root: $release ready in $dir (meshlab $(cat "$dir/.drm-root-ready"))"
}

fail_step() {
  tail -20 "$2" >&2
  echo "meshlab-root: $1 failed (whole log: $2)" >&2
  exit 1
}

run_in_root() {
  local release=$1 suite dir
  shift
  suite=$(suite_of "$release")
  dir="$roots/$suite"
  [ -f "$dir/.drm-root-ready" ] || { echo "meshlab-root: no root for MeshLab $release; run: bash scripts/meshlab-root.sh make $release" >&2; exit 1; }
  need_root
  mkdir -p "$dir/drm"
  # A private mount namespace: the bind mounts vanish with the command. A
  # private network namespace (no network: nothing run here needs one): X
  # servers listen on abstract sockets, which a chroot does not separate, so
  # an Xvfb in the root cannot meet another X server of the same number.
  unshare --mount --net --propagation private -- bash -c '
    set -e
    dir=$1; here=$2; shift 2
    mount --bind "$here" "$dir/drm"
    mount -t proc proc "$dir/proc"
    mount --bind /dev "$dir/dev"
    exec chroot "$dir" env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      HOME=/root LANG=C.UTF-8 TERM="${TERM:-dumb}" "$@"
  ' bash "$dir" "$here" "$@"
}

case "${1:-}" in
  make) make_root "${2:?RELEASE}" ;;
  path) echo "$roots/$(suite_of "${2:?RELEASE}")" ;;
  run) shift; release=${1:?RELEASE}; shift; run_in_root "$release" "$@" ;;
  *) sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
