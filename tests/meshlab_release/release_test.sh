#!/usr/bin/env bash
# Runs one case of the plugin tests against a newer MeshLab release:
#   release_test.sh PROJECT_DIR RELEASE DRM COMPARE_MESHES CASE
#
# The plugins built for RELEASE (build-meshlab-RELEASE/plugins, by
# scripts/build-meshlab-plugins.sh) are loaded by MeshLab's own plugin
# manager inside the release's Debian root (scripts/meshlab-root.sh), through
# tests/meshlab_harness, as PyMeshLab loads plugins; MeshLab's stock io_base
# plugin reads and writes PLY and OBJ there. What they write is held to the
# host's `drm` tool (DRM): the same .drm bytes, and with compare_meshes the
# same positions, faces, colours and texture coordinates.
set -uo pipefail
project=$1
release=$2
drm=$3
compare=$4
case_name=$5
data="$project/tests/data"
build="build-meshlab-$release"
# Inside the project, so the root sees it (at /drm).
work="$project/$build/test-work/$case_name"
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1

fail() { echo "FAIL [$release $case_name]: $*" >&2; exit 1; }

[ -f "$project/$build/plugins/libio_drm.so" ] ||
    fail "no plugins for MeshLab $release: run bash scripts/build-meshlab-plugins.sh $release"

# harness EXPECTED_CODE ARGS...: the harness in the root, PROJECT paths
# given as they are on the host; output in harness.txt.
harness() {
    local expected=$1 code
    shift
    local args=()
    for a in "$@"; do args+=("${a//$project//drm}"); done
    bash "$project/scripts/meshlab-root.sh" run "$release" "/drm/$build/bin/meshlab_harness" \
        "/drm/$build/plugins" "${args[@]}" >harness.txt 2>&1
    code=$?
    [ "$code" -lt 128 ] || fail "meshlab_harness $* crashed (exit $code): $(tail -5 harness.txt)"
    [ "$code" -eq "$expected" ] || fail "meshlab_harness $* exited $code, expected $expected: $(grep -v '^LOG' harness.txt | tail -5)"
}

# same A B [OPTIONS]: compare_meshes must say IDENTICAL.
same() {
    "$compare" "$@" >compare.txt 2>&1 || fail "compare_meshes $*: $(cat compare.txt)"
    echo "$release $case_name: $(basename "$1") vs $(basename "$2"): $(cat compare.txt)"
}

# export_matches IN MASK NAME [CLI OPTIONS...]: MeshLab opens IN and saves it
# through the plugin with export MASK; `drm encode IN` with the options must
# write the same bytes.
export_matches() {
    local input=$1 mask=$2 name=$3
    shift 3
    harness 0 convert "$input" "$work/$name.drm" "$mask"
    [ -s "$name.drm" ] || fail "$name.drm was not written: $(tail -5 harness.txt)"
    "$drm" encode "$input" "$work/$name-cli.drm" "$@" >/dev/null 2>cli.txt || fail "drm encode $input $*: $(cat cli.txt)"
    cmp -s "$name.drm" "$name-cli.drm" ||
        fail "$name.drm (MeshLab, mask $mask) differs from drm encode $(basename "$input") $*: $(stat -c %s "$name.drm") vs $(stat -c %s "$name-cli.drm") bytes; $(grep 'drm: saved' harness.txt)"
    echo "$release $case_name: $(basename "$input") mask $mask: $(stat -c %s "$name.drm") bytes, byte for byte as drm encode $*"
}

case "$case_name" in
load)
    # MeshLab's plugin manager accepts both plugins (version and scalar
    # checks) and gives .drm files to ours.
    harness 0 info
    grep -q "^meshlab: $release" harness.txt || fail "not MeshLab $release: $(cat harness.txt)"
    grep -q "^io: IODRM: open DRM (Distance-ranked compressed mesh) save DRM" harness.txt || fail "$(cat harness.txt)"
    grep -q '^filter: FilterDRM: "Colorize Faces by Distance Rank" (python: compute_color_by_distance_rank_per_face, class 8)' harness.txt ||
        fail "$(cat harness.txt)"
    grep -q "^vendor: drm (distance-ranked mesh compression)" harness.txt || fail "$(cat harness.txt)"
    grep '^\(meshlab\|vendor\|io\|filter\):' harness.txt
    ;;
export)
    # Every attribute the export dialog offers, ticked and not, against the
    # CLI on the same file. MeshLab's normals are the ones it computes (none
    # of these files has its own), which the plugin leaves out.
    export_matches "$data/fandisk.ply" default fandisk
    grep -q "drm: note: fandisk.drm leaves out the vertex normals: they are the ones MeshLab computes" harness.txt ||
        fail "no note on the computed normals: $(grep 'drm:' harness.txt)"
    # docs/meshlab.md shows this save's log line.
    doc_line=$(grep -m1 '^drm: saved fandisk.drm: ' "$project/docs/meshlab.md")
    grep -qxF "log: filter: $doc_line" harness.txt ||
        fail "docs/meshlab.md's log line is not what MeshLab logs: $(grep 'drm: saved' harness.txt | head -1)"
    export_matches "$data/fandisk.ply" 0 fandisk-none --attributes none
    # A coloured mesh with no other attribute, made with the CLI.
    "$drm" encode "$data/attributes/vcolors.ply" "$work/vcolors.drm" --attributes colors >/dev/null 2>&1 &&
        "$drm" decode "$work/vcolors.drm" "$work/coloured.ply" >/dev/null 2>&1 || fail "cannot make coloured.ply"
    export_matches "$work/coloured.ply" default coloured
    export_matches "$work/coloured.ply" 0 coloured-none --attributes none
    grep -q "^warning: drm: note: coloured-none.drm does not keep the mesh's vertex colours (not ticked)" harness.txt ||
        fail "no warning on the unticked colours: $(grep 'drm:\|warning' harness.txt)"
    # The textured duck, its texture beside it (MeshLab names a texture it
    # cannot load dummy.png).
    cp "$data/attributes/duck-wedge.ply" "$work/duck.ply"
    convert -size 64x64 xc:orange "$work/duckCM.tga" || fail "cannot make duckCM.tga (ImageMagick)"
    export_matches "$work/duck.ply" default duck
    export_matches "$work/duck.ply" 0 duck-none --attributes none
    # Normals of its own (Blender's), a vertex per corner.
    export_matches "$data/attributes/wuson-piece.ply" default wuson
    ! grep -q "leaves out the vertex normals" harness.txt || fail "wuson's own normals were left out"
    ;;
open)
    # Files from the CLI opened through the plugin and saved as PLY by
    # MeshLab's own exporter hold what `drm decode` writes.
    for name in fandisk attributes/vcolors attributes/duck-wedge; do
        base=$(basename "$name")
        "$drm" encode "$data/$name.ply" "$work/$base.drm" >/dev/null 2>cli.txt || fail "drm encode $name: $(cat cli.txt)"
        "$drm" decode "$work/$base.drm" "$work/$base-cli.ply" >/dev/null 2>cli.txt || fail "drm decode $base.drm: $(cat cli.txt)"
        harness 0 convert "$work/$base.drm" "$work/$base-meshlab.ply" all
        grep -q "drm: opened $base.drm: " harness.txt || fail "no 'drm: opened' in the log: $(grep -v '^LOG' harness.txt)"
        case $base in
        vcolors) same "$base-meshlab.ply" "$base-cli.ply" --vertex-colours ;;
        duck-wedge) same "$base-meshlab.ply" "$base-cli.ply" --wedge-texcoords ;;
        *) same "$base-meshlab.ply" "$base-cli.ply" ;;
        esac
    done
    ;;
colorize)
    # The filter's colours and ranks (face quality) against `drm ranks`, and
    # its legend in the log.
    for name in fandisk elephant-with-holes; do
        harness 0 colorize "$data/$name.ply" "$work/$name-ranks.ply"
        grep -q "^log: filter: Distance ranks of $name.ply: connectivity [0-9.]* bpv" harness.txt ||
            fail "no bpv in the log: $(grep -v '^LOG' harness.txt)"
        grep -q "^log: filter: <b>Faces per colour</b>" harness.txt || fail "no legend in the log"
        grep -q "^log: filter: Rank codes (0 = boundary edge): " harness.txt || fail "no rank histogram in the log"
        "$drm" ranks "$data/$name.ply" "$work/$name-cli-ranks.ply" >cli-ranks.txt 2>&1 || fail "drm ranks $name failed"
        for bucket in "start triangle" "rank 1" "rank 2" "rank 3" "rank 4+"; do
            hex=$(sed -n "s/^  $bucket  *\(#[0-9a-f]\{6\}\) .*/\1/p" cli-ranks.txt)
            [ -n "$hex" ] || fail "drm ranks lists no colour for $bucket: $(cat cli-ranks.txt)"
            grep "Faces per colour" harness.txt | grep -q "background-color:$hex" ||
                fail "the legend has no swatch $hex for $bucket"
        done
        same "$name-ranks.ply" "$name-cli-ranks.ply" --face-colours --face-quality
    done
    ;;
refusals)
    # Damaged files and bad parameters: an error naming the file, no crash.
    "$drm" encode "$data/fandisk.ply" "$work/good.drm" >/dev/null 2>&1 || fail "drm encode fandisk failed"
    head -c 200 good.drm >truncated.drm
    harness 1 convert "$work/truncated.drm" "$work/out.ply"
    grep -q "^error: cannot open truncated.drm: corrupt file: " harness.txt || fail "$(grep -v '^LOG' harness.txt)"
    echo "$release $case_name: $(grep '^error:' harness.txt)"
    cp good.drm flipped.drm
    printf '\xff' | dd of=flipped.drm bs=1 seek=100 conv=notrunc status=none
    harness 1 convert "$work/flipped.drm" "$work/out.ply"
    grep -q "^error: cannot open flipped.drm: corrupt file: " harness.txt || fail "$(grep -v '^LOG' harness.txt)"
    echo "$release $case_name: $(grep '^error:' harness.txt)"
    harness 1 convert "$data/fandisk.ply" "$work/bad-bits.drm" default QuantizationBits=0
    grep -q "^error: cannot save bad-bits.drm: Quantization bits must be between 1 and " harness.txt ||
        fail "$(grep -v '^LOG' harness.txt)"
    [ ! -e bad-bits.drm ] || fail "bad-bits.drm was written after a refusal"
    echo "$release $case_name: $(grep '^error:' harness.txt)"
    harness 1 colorize "$data/fandisk.ply" "$work/bad.ply" QuantizationBits=99
    grep -q "^error: Colorize Faces by Distance Rank: cannot rank fandisk.ply: Quantization bits must be between" harness.txt ||
        fail "$(grep -v '^LOG' harness.txt)"
    echo "$release $case_name: $(grep '^error:' harness.txt)"
    ;;
*)
    fail "unknown case"
    ;;
esac
