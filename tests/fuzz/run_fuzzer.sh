#!/usr/bin/env bash
# Builds the decoder's libFuzzer target (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer) in build-fuzz/ and fuzzes it, starting from
# freshly generated seeds plus the committed ones in tests/fuzz/seeds/.
#
# usage: tests/fuzz/run_fuzzer.sh [--roundtrip | --readers] [SECONDS | -runs=N] [more libFuzzer flags...]
#   (default: 60 seconds; one process). --roundtrip runs fuzz_roundtrip
#   (encode a mesh made from the input, decode, compare) instead of
#   fuzz_decode; its corpus is build-fuzz/roundtrip-corpus/. --readers runs
#   fuzz_readers (the PLY, OBJ, OFF and STL readers on mutated files, seeded
#   with tests/data's meshes); its corpus is build-fuzz/readers-corpus/.
# environment: DRM_FUZZ_BUILD_DIR (default build-fuzz/), DRM_BUILD_JOBS
#   (default nproc), DRM_BUILD_LOCK (a file to flock around the build, for
#   machines whose cores are shared).
# Crashes land in build-fuzz/artifacts/, new corpus inputs in build-fuzz/corpus/.
# Re-run one input: build-fuzz/bin/fuzz_decode build-fuzz/artifacts/crash-...
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build="${DRM_FUZZ_BUILD_DIR:-$here/build-fuzz}"
jobs="${DRM_BUILD_JOBS:-$(nproc)}"

target=fuzz_decode
case "${1:-}" in
  --roundtrip) target=fuzz_roundtrip; shift ;;
  --readers) target=fuzz_readers; shift ;;
esac
limit=(-max_total_time=60)
if [ $# -gt 0 ]; then
  case "$1" in
    -runs=*) limit=("$1"); shift ;;
    *[!0-9]*|'') ;;
    *) limit=(-max_total_time="$1"); shift ;;
  esac
fi

locked() {
  if [ -n "${DRM_BUILD_LOCK:-}" ]; then flock "$DRM_BUILD_LOCK" "$@"; else "$@"; fi
}

generator=()
command -v ninja >/dev/null && [ ! -f "$build/Makefile" ] && generator=(-G Ninja)
CC=clang CXX=clang++ locked cmake -S "$here" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DDRM_CODEC_ONLY=ON -DDRM_BUILD_FUZZER=ON >/dev/null
locked cmake --build "$build" -j"$jobs" --target fuzz_decode fuzz_roundtrip fuzz_readers make_seeds

mkdir -p "$build/seeds" "$build/corpus" "$build/roundtrip-corpus" "$build/readers-corpus" "$build/readers-seeds" \
  "$build/artifacts"
common=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/")
if [ "$target" = fuzz_roundtrip ]; then
  exec "$build/bin/fuzz_roundtrip" "${limit[@]}" -max_len=512 "${common[@]}" "$@" "$build/roundtrip-corpus"
fi
if [ "$target" = fuzz_readers ]; then
  # A seed is the format byte (0 PLY, 1 OBJ, 2 OFF, 3 STL) then the file;
  # an OBJ's library follows a 0xFF byte.
  for file in "$here"/tests/data/*.ply "$here"/tests/data/attributes/* "$here"/tests/data/bad/*; do
    [ -f "$file" ] && [ "$(stat -c %s "$file")" -le 65536 ] || continue
    case "${file,,}" in
      *.ply) byte='\x00' ;; *.obj) byte='\x01' ;; *.off) byte='\x02' ;; *.stl) byte='\x03' ;; *) continue ;;
    esac
    seed="$build/readers-seeds/$(basename "$file")"
    { printf "$byte"; cat "$file"; } >"$seed"
    mtl="${file%.*}.mtl"
    if [ "$byte" = '\x01' ] && [ -f "$mtl" ]; then { printf '\xff'; cat "$mtl"; } >>"$seed"; fi
  done
  exec "$build/bin/fuzz_readers" "${limit[@]}" -max_len=8192 "${common[@]}" "$@" \
    "$build/readers-corpus" "$build/readers-seeds"
fi
"$build/bin/make_seeds" "$build/seeds" --ply-dir "$here/tests/data"
exec "$build/bin/fuzz_decode" "${limit[@]}" -max_len=4096 "${common[@]}" "$@" \
  "$build/corpus" "$build/seeds" "$here/tests/fuzz/seeds"
