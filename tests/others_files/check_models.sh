#!/usr/bin/env bash
# Runs every PLY, OBJ, OFF and STL model of another project's test suite
# (Debian's assimp-testmodels: real exporters' files, broken ones included)
# through drm, and checks each against its row of EXPECTED (a TSV file:
# path below the models folder, then `lossless`, or `refused` and a part of
# the message that says what is wrong with the file):
#   lossless: `drm verify` says so; encode and decode to PLY and OBJ succeed,
#             and both decoded files verify lossless too.
#   refused:  encode and verify exit 1 with one "drm: error:" line holding
#             the expected words, and leave no output behind.
# A model the table does not list fails the test, so a new package version
# is looked at. Usage: check_models.sh DRM EXPECTED [MODELS_DIR]
set -uo pipefail
drm=$1
expected=$2
models=${3:-/usr/share/assimp/models}
if [ ! -d "$models" ]; then
    echo "SKIPPED: $models is missing (scripts/setup.sh installs assimp-testmodels)" >&2
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

failures=0 lossless=0 refused=0
fail() { echo "FAIL $1: $2" >&2; failures=$((failures + 1)); }

declare -A want message
while IFS=$'\t' read -r path outcome words; do
    [ -z "$path" ] || [ "${path:0:1}" = "#" ] && continue
    want[$path]=$outcome
    message[$path]=$words
done <"$expected"

while IFS= read -r file; do
    path=${file#"$models"/}
    if [ -z "${want[$path]:-}" ]; then
        fail "$path" "not in $(basename "$expected"): add its expected outcome"
        continue
    fi
    rm -rf "${work:?}"/*
    "$drm" verify "$file" >"$work/verify.txt" 2>"$work/verify.err"
    verify_code=$?
    "$drm" encode "$file" "$work/m.drm" >"$work/encode.txt" 2>"$work/encode.err"
    encode_code=$?
    for code in $verify_code $encode_code; do
        [ "$code" -lt 128 ] || fail "$path" "drm crashed (exit $code): $(cat "$work"/*.err)"
    done
    case ${want[$path]} in
    lossless)
        [ $verify_code -eq 0 ] && grep -q 'lossless$' "$work/verify.txt" ||
            { fail "$path" "verify exited $verify_code: $(tail -1 "$work/verify.txt") $(grep 'error' "$work/verify.err")"; continue; }
        [ $encode_code -eq 0 ] || { fail "$path" "encode exited $encode_code: $(cat "$work/encode.err")"; continue; }
        for format in ply obj; do
            "$drm" decode "$work/m.drm" "$work/back.$format" >/dev/null 2>"$work/decode.err" ||
                { fail "$path" "decode to $format: $(cat "$work/decode.err")"; continue; }
            "$drm" verify "$work/back.$format" >"$work/back.txt" 2>&1 && grep -q 'lossless$' "$work/back.txt" ||
                fail "$path" "the decoded $format does not verify: $(tail -1 "$work/back.txt")"
        done
        lossless=$((lossless + 1))
        ;;
    refused)
        for step in verify encode; do
            code=$([ $step = verify ] && echo $verify_code || echo $encode_code)
            [ "$code" -eq 1 ] || { fail "$path" "$step exited $code, expected 1"; continue; }
            [ "$(grep -c . "$work/$step.err" | tr -d ' ')" -ge 1 ] || fail "$path" "$step printed no error"
            [ "$(grep -c '^drm: error: ' "$work/$step.err")" -eq 1 ] || fail "$path" "$step: $(cat "$work/$step.err")"
            grep -qF -- "${message[$path]}" "$work/$step.err" ||
                fail "$path" "$step says '$(grep '^drm: error' "$work/$step.err")', expected '${message[$path]}'"
        done
        [ ! -e "$work/m.drm" ] || fail "$path" "a refused encode left its output"
        refused=$((refused + 1))
        ;;
    *) fail "$path" "unknown outcome '${want[$path]}' in $(basename "$expected")" ;;
    esac
done < <(find "$models" -type f \( -iname '*.ply' -o -iname '*.obj' -o -iname '*.off' -o -iname '*.stl' \) | sort)

echo "assimp-testmodels: $lossless lossless, $refused refused as expected, $failures failures"
[ $failures -eq 0 ]
