# Shared by batch-compress.sh and batch-decompress.sh (sourced, not run).
# shellcheck shell=bash disable=SC2034,SC2154  # variables shared with the sourcing script
#
# Each file goes through meshlabserver (MeshLab 2020.09 with drm's plugins:
# $MESHLABSERVER, else the meshlabserver on PATH). meshlabserver exits 0
# even when a save fails, so success is judged by the output file: it is
# written under a temporary name, checked to exist and be non-empty, and
# only then renamed, so an older file of the same name never passes for a
# new one and is never replaced by a failed run.
# A file that fails is reported and the batch carries on (as `drm encode -o`
# does); the summary lists the failures and the exit code is then 1. With
# --stop-on-error the batch stops at the first failure instead.
set -euo pipefail

batch_fail() { echo "$batch_name: $*" >&2; exit 1; }

# batch_usage TEXT [CODE]: the usage, on stdout with code 0 (--help), else
# on stderr with code 2.
batch_usage() {
  local code=${2:-2}
  {
    echo "usage: $batch_name [--stop-on-error] DIR OUTDIR"
    echo "  $1"
    echo "  A file that fails is reported and the others are still converted; the failures are"
    echo "  listed at the end and the exit code is 1. --stop-on-error: stop at the first one."
    echo "  meshlabserver: \$MESHLABSERVER, else the one on PATH (MeshLab 2020.09 with drm's plugins:"
    echo "  scripts/meshlab-user-install.sh PREFIX, then MESHLABSERVER=PREFIX/bin/meshlabserver)"
  } >&$((code == 0 ? 1 : 2))
  exit "$code"
}

# batch_display "$@": without an X display, runs the calling script again
# under one xvfb-run for the whole batch (one virtual display, not one per
# file: faster, and fewer chances to race other xvfb-run -a for a number).
# The batch's own exit status is passed back through a file: xvfb-run exits
# 5, whatever the batch did, when it fails to remove its temporary folder
# afterwards (it stops the X server only after that; seen under load).
batch_display() {
  [ -z "${DISPLAY:-}" ] || return 0
  command -v xvfb-run >/dev/null || batch_fail "no DISPLAY and no xvfb-run (apt-get install xvfb xauth)"
  local status code
  status=$(mktemp) || batch_fail "cannot create a temporary file"
  code=0
  xvfb-run -a env BATCH_STATUS_FILE="$status" bash -c 'bash "$0" "$@"; echo $? >"$BATCH_STATUS_FILE"' "$0" "$@" || code=$?
  if [ -s "$status" ]; then code=$(cat "$status"); fi
  rm -f "$status"
  exit "$code"
}

# batch_arguments "$@": sets batch_stop_on_error and batch_args (DIR OUTDIR).
batch_arguments() {
  batch_stop_on_error=0
  batch_args=()
  local arg
  for arg in "$@"; do
    case "$arg" in
      -h|--help) batch_usage "$batch_help" 0 ;;
      --stop-on-error) batch_stop_on_error=1 ;;
      -*) echo "$batch_name: unknown option $arg" >&2; batch_usage "$batch_help" ;;
      *) batch_args+=("$arg") ;;
    esac
  done
  [ ${#batch_args[@]} -eq 2 ] || batch_usage "$batch_help"
}

# batch_setup DIR OUTDIR: checks the arguments and finds meshlabserver.
batch_setup() {
  [ -d "$1" ] || batch_fail "$1 is not a folder"
  mkdir -p "$2" || batch_fail "cannot create $2"
  # Absolute paths: meshlabserver changes its working folder to each file's
  # while it loads and saves, so nothing should depend on ours.
  batch_in=$(cd "$1" && pwd)
  batch_out=$(cd "$2" && pwd)
  batch_server=${MESHLABSERVER:-$(command -v meshlabserver || true)}
  if [ -z "$batch_server" ] || [ ! -x "$batch_server" ]; then
    batch_fail "meshlabserver not found: set MESHLABSERVER or install MeshLab 2020.09 (scripts/setup.sh)"
  fi
  # meshlabserver needs an X display even without a window: batch_display
  # has given the whole batch one where there was none.
  batch_files=0
  batch_bytes_in=0
  batch_bytes_out=0
  batch_vertices=0
  batch_drm_bytes=0
  batch_failures=()
}

# What meshlabserver saves besides positions and faces (its -m): every
# attribute a .drm file keeps, where the mesh has it (without -m it saves
# none). Vertex normals MeshLab computed itself are left out by the plugin.
batch_attributes=(-m vc vn vq vt fc fq wt)

batch_size() { stat -L -c %s "$1"; }  # -L: the size of what a symlink points to

# batch_convert IN OUT [MESHLABSERVER OPTIONS...]: one file; stops the batch
# with meshlabserver's own explanation when OUT does not come out.
batch_convert() {
  local in=$1 out=$2
  shift 2
  local tmp log status=0 target
  # Replacing OUT as drm does: through a symbolic link to its target, and
  # only a file the user may write; the new file keeps the old one's mode
  # (and owner, where permitted).
  target=$(realpath -m -- "$out")
  if [ -e "$target" ] && [ ! -w "$target" ]; then
    batch_failed "$in" "cannot write $(basename "$out"): the file is read-only for you"
    return 0
  fi
  tmp="$(dirname "$target")/.batch-$$-$(basename "$target")"  # same extension: it picks the plugin
  log=$(mktemp)
  rm -f "$tmp"
  "$batch_server" -i "$in" -o "$tmp" "$@" >"$log" 2>&1 || status=$?
  if [ ! -s "$tmp" ]; then
    rm -f "$tmp"
    local reason
    reason=$(grep -E '^drm: error: ' "$log" | sed 's/^drm: error: //' | head -3 || true)
    if [ -z "$reason" ] && grep -q 'does not correspond to any supported format\|^Error encountered while opening file' "$log"; then
      reason="this meshlabserver does not know the file type; are drm's plugins installed? ($batch_server)"
    fi
    [ -n "$reason" ] || reason=$(grep -iE 'error|fail|not been saved|not possible' "$log" | head -5 || true)
    [ -n "$reason" ] || reason="no output (meshlabserver said: $(tail -3 "$log" | tr '\n' ' '))"
    rm -f "$log"
    reason=${reason//"$(basename "$tmp")"/"$(basename "$out")"}  # the user knows the final name
    if [ "$status" -ge 128 ] && [ "$status" -ne 255 ]; then reason="meshlabserver crashed (exit $status). $reason"; fi
    batch_failed "$in" "$reason"
    return 0
  fi
  # The plugin's size line: "drm: saved NAME: V vertices, ..." (or opened).
  local vertices
  vertices=$(sed -n 's/^drm: \(saved\|opened\) [^:]*: \([0-9]*\) vertices, .*/\2/p' "$log" | head -1)
  rm -f "$log"
  if [ -e "$target" ]; then
    chown --reference="$target" "$tmp" 2>/dev/null || chgrp --reference="$target" "$tmp" 2>/dev/null || true
    chmod --reference="$target" "$tmp"
  fi
  mv -f "$tmp" "$target"
  sync "$(dirname "$target")" 2>/dev/null || true  # the rename lives in the folder
  local size_in size_out
  size_in=$(batch_size "$in")
  size_out=$(batch_size "$out")
  local drm_bytes=$size_out
  case "$in" in *.drm|*.DRM) drm_bytes=$size_in ;; esac
  batch_files=$((batch_files + 1))
  batch_bytes_in=$((batch_bytes_in + size_in))
  batch_bytes_out=$((batch_bytes_out + size_out))
  local bpv="bits per vertex unknown"
  if [ -n "$vertices" ] && [ "$vertices" -gt 0 ]; then
    batch_vertices=$((batch_vertices + vertices))
    batch_drm_bytes=$((batch_drm_bytes + drm_bytes))
    bpv="$(batch_bpv "$drm_bytes" "$vertices") bits per vertex"
  fi
  printf '%s -> %s: %d -> %d bytes (%s), %s vertices, %s\n' "$(basename "$in")" "$(basename "$out")" "$size_in" \
    "$size_out" "$(batch_ratio "$size_in" "$size_out")" "${vertices:-?}" "$bpv"
}

# batch_bpv BYTES VERTICES: "13.44", the .drm file's bits per vertex.
batch_bpv() {
  awk -v b="$1" -v v="$2" 'BEGIN { if (v == 0) print "-"; else printf "%.2f", 8 * b / v }'
}

# batch_failed IN REASON: reports a file that failed; stops the batch with
# --stop-on-error, else remembers it for the summary.
batch_failed() {
  local reason
  reason=$(echo "$2" | tr '\n' ' ' | sed 's/ *$//')
  if [ "$batch_stop_on_error" -eq 1 ]; then batch_fail "stopped at $(basename "$1"): $reason"; fi
  echo "$batch_name: failed: $(basename "$1"): $reason" >&2
  batch_failures+=("$(basename "$1"): $reason")
}

# "4.1:1" or "1:3.2" style: how much smaller or larger the output is.
batch_ratio() {
  awk -v a="$1" -v b="$2" 'BEGIN { if (b == 0) print "-"; else if (a >= b) printf "%.1f:1", a / b; else printf "1:%.1f", b / a }'
}

# batch_summary: the totals, then the failures; exits 1 if any file failed.
batch_summary() {
  local bpv="-"
  if [ "$batch_vertices" -gt 0 ]; then bpv=$(batch_bpv "$batch_drm_bytes" "$batch_vertices"); fi
  printf '%s: %d files, %d -> %d bytes (%s), %s bits per vertex (.drm bytes over %d vertices), output in %s\n' \
    "$batch_name" "$batch_files" "$batch_bytes_in" "$batch_bytes_out" \
    "$(batch_ratio "$batch_bytes_in" "$batch_bytes_out")" "$bpv" "$batch_vertices" "$batch_out"
  if [ ${#batch_failures[@]} -gt 0 ]; then
    echo "$batch_name: ${#batch_failures[@]} file(s) failed:"
    local failure
    for failure in "${batch_failures[@]}"; do echo "  $failure"; done
    exit 1
  fi
}
