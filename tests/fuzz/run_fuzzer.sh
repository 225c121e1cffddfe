#!/usr/bin/env bash
# Builds the decoder's libFuzzer target (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer) in build-fuzz/ and fuzzes it, starting from
# freshly generated seeds plus the committed ones in tests/fuzz/seeds/.
#
# usage: tests/fuzz/run_fuzzer.sh [--roundtrip] [SECONDS | -runs=N] [more libFuzzer flags...]
#   (default: 60 seconds; one process). --roundtrip runs fuzz_roundtrip
#   (encode a mesh made from the input, decode, compare) instead of
#   fuzz_decode; its corpus is build-fuzz/roundtrip-corpus/.
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
if [ "${1:-}" = "--roundtrip" ]; then target=fuzz_roundtrip; shift; fi
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
locked cmake --build "$build" -j"$jobs" --target fuzz_decode fuzz_roundtrip make_seeds

mkdir -p "$build/seeds" "$build/corpus" "$build/roundtrip-corpus" "$build/artifacts"
common=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/")
if [ "$target" = fuzz_roundtrip ]; then
  exec "$build/bin/fuzz_roundtrip" "${limit[@]}" -max_len=512 "${common[@]}" "$@" "$build/roundtrip-corpus"
fi
"$build/bin/make_seeds" "$build/seeds" --ply-dir "$here/tests/data"
exec "$build/bin/fuzz_decode" "${limit[@]}" -max_len=4096 "${common[@]}" "$@" \
  "$build/corpus" "$build/seeds" "$here/tests/fuzz/seeds"
