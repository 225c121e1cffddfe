#!/usr/bin/env bash
# Checks that .drm files do not depend on the compiler or the optimization
# level: builds encode_decode_dump.cpp against the codec sources with gcc and
# clang, each at -O0 and at -O3 -march=native (which lets the compiler use
# FMA and vector units: -ffp-contract=off and exact_math.h must keep every
# rounding the same), and then
#  1. compares what the builds print for the same meshes and options (sizes
#     and hashes of the input, the encoded file and the decoded mesh);
#  2. has every build decode every other build's files: a decoder must
#     rebuild the mesh the writer meant even if the two builds disagree.
#  3. has every build decode the committed golden files (tests/golden).
#
# usage: tests/determinism/check_cross_build.sh [WORK_DIR]   (default /tmp/drm-determinism)
# environment: DRM_BUILD_LOCK (a file to flock around each compile, for
#   machines whose cores are shared).
# Exit status 0 when every build agrees, 1 otherwise.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work="${1:-/tmp/drm-determinism}"

locked() {
  if [ -n "${DRM_BUILD_LOCK:-}" ]; then flock "$DRM_BUILD_LOCK" "$@"; else "$@"; fi
}

# Lines of $1 and $2 that differ, indented, at most 40 (diff's status 1 is
# the expected outcome here, not an error).
show_diff() {
  { diff "$1" "$2" || true; } | sed 's/^/     /' | head -40
}

# name|compiler|flags
builds=(
  "gcc-O0|g++|-O0"
  "gcc-O3-native|g++|-O3 -march=native"
  "clang-O0|clang++|-O0"
  "clang-O3-native|clang++|-O3 -march=native"
)

# Every build compiles one snapshot of the sources: the tree may change while
# this runs, and builds of different sources would differ for that reason
# alone (or, if a header changes between two files of one build, crash).
src="$work/src"
rm -rf "$src"
mkdir -p "$src/tests"
cp -r "$here/codec" "$src/codec"
cp -r "$here/tests/support" "$here/tests/determinism" "$src/tests/"
mkdir -p "$src/tests/data"
cp "$here"/tests/data/*.ply "$src/tests/data/" 2>/dev/null || true
mkdir -p "$src/tests/golden"
cp "$here"/tests/golden/*.drm "$src/tests/golden/"
sources=($(find "$src/codec/src" -name "*.cpp" | sort) "$src/tests/support/test_meshes.cpp" "$src/tests/support/tiny_ply.cpp"
         "$src/tests/determinism/encode_decode_dump.cpp")
names=()
status=0
for build in "${builds[@]}"; do
  IFS='|' read -r name cxx flags <<<"$build"
  names+=("$name")
  dir="$work/$name"
  rm -rf "$dir/files"
  mkdir -p "$dir/files"
  echo "== $name: $cxx $flags"
  start=$(date +%s)
  # The codec's own build flags (codec/CMakeLists.txt): C++17, no FMA
  # contraction, no fast-math. $flags is left unquoted to split into words.
  # shellcheck disable=SC2086
  locked "$cxx" -std=c++17 -ffp-contract=off -fno-fast-math $flags -w \
    -I"$src/codec/include" -I"$src/codec/src" -I"$src/tests/support" \
    "${sources[@]}" -o "$dir/encode_decode_dump" -lpthread
  built=$(date +%s)
  "$dir/encode_decode_dump" --ply-dir "$src/tests/data" --write "$dir/files" >"$dir/output.txt"
  echo "   built in $((built - start)) s, ran in $(($(date +%s) - built)) s: $(wc -l <"$dir/output.txt") lines, $(tail -1 "$dir/output.txt")"
  if grep -q " error: " "$dir/output.txt"; then
    echo "   encode or decode errors:"
    grep " error: " "$dir/output.txt" | sed 's/^/     /'
    status=1
  fi
  if [ "$name" != "${names[0]}" ] && ! cmp -s "$work/${names[0]}/output.txt" "$dir/output.txt"; then
    echo "   DIFFERS from ${names[0]}:"
    show_diff "$work/${names[0]}/output.txt" "$dir/output.txt"
    status=1
  fi
done

echo "== cross decoding: each build decodes each build's files"
for writer in "${names[@]}"; do
  files=("$work/$writer/files"/*.drm)
  "$work/$writer/encode_decode_dump" --decode "${files[@]}" >"$work/$writer/self-decode.txt"
  for reader in "${names[@]}"; do
    [ "$reader" = "$writer" ] && continue
    out="$work/$reader/decodes-$writer.txt"
    "$work/$reader/encode_decode_dump" --decode "${files[@]}" >"$out"
    if cmp -s "$work/$writer/self-decode.txt" "$out"; then
      echo "   $reader reads $writer's ${#files[@]} files as $writer does"
    else
      echo "   $reader reads $writer's files DIFFERENTLY:"
      show_diff "$work/$writer/self-decode.txt" "$out"
      status=1
    fi
  done
done

echo "== golden files: tests/golden/*.drm, committed, decoded by every build"
golden=("$src"/tests/golden/*.drm)
for name in "${names[@]}"; do
  "$work/$name/encode_decode_dump" --decode "${golden[@]}" >"$work/$name/golden.txt"
  if [ "$name" = "${names[0]}" ]; then
    echo "   ${names[0]} decodes ${#golden[@]} golden files"
  elif cmp -s "$work/${names[0]}/golden.txt" "$work/$name/golden.txt"; then
    echo "   $name decodes them as ${names[0]} does"
  else
    echo "   $name decodes them DIFFERENTLY:"
    show_diff "$work/${names[0]}/golden.txt" "$work/$name/golden.txt"
    status=1
  fi
done

if [ "$status" -eq 0 ]; then
  echo "all ${#builds[@]} builds wrote identical files and decoded identical meshes"
fi
exit "$status"
