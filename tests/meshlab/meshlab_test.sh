#!/usr/bin/env bash
# Runs one case of the MeshLab plugin tests:
#   meshlab_test.sh SOURCE_DIR PREFIX PLUGIN_DIR DRM COMPARE_MESHES CASE
#
# The plugins run inside Debian's real MeshLab 2020.09: meshlabserver from a
# private prefix (scripts/meshlab-user-install.sh), under xvfb-run because it
# needs an X display. Their output is held to the `drm` tool's (DRM) with
# compare_meshes: identical positions, faces and face colours.
# meshlabserver exits 0 after a failed save and 255 after a failed open or
# filter; anything from 128 to 254 is a signal, i.e. a crash.
set -uo pipefail
shopt -s nullglob
src=$1
prefix=$2
plugins=$3
drm=$4
compare=$5
case_name=$6
data="$src/tests/data"
server="$prefix/bin/meshlabserver"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

fail() { echo "FAIL [$case_name]: $*" >&2; exit 1; }

# xrun COMMAND...: xvfb-run -a COMMAND, returning COMMAND's own exit
# status: xvfb-run exits 5, whatever the command did, when it fails to
# remove its temporary folder afterwards (seen under load).
xrun() {
    local status="$work/xrun.status" code
    rm -f "$status"
    xvfb-run -a env XRUN_STATUS="$status" bash -c '"$@"; echo $? >"$XRUN_STATUS"' xrun "$@"
    code=$?
    if [ -s "$status" ]; then code=$(cat "$status"); fi
    return "$code"
}

# server EXPECTED_CODE ARGS...: runs meshlabserver, output in server.txt.
server() {
    local expected=$1
    shift
    xrun "$server" "$@" >server.txt 2>&1
    local code=$?
    if [ "$code" -ge 128 ] && [ "$code" -ne 255 ]; then
        fail "meshlabserver $* crashed (exit $code): $(tail -5 server.txt)"
    fi
    [ "$code" -eq "$expected" ] || fail "meshlabserver $* exited $code, expected $expected: $(tail -5 server.txt)"
}

# same A B [OPTIONS]: compare_meshes must say IDENTICAL; prints its verdict.
same() {
    "$compare" "$@" >compare.txt 2>&1 || fail "compare_meshes $*: $(cat compare.txt)"
    echo "$case_name: $(basename "$1") vs $(basename "$2"): $(cat compare.txt)"
}

# as_user COMMAND...: runs COMMAND as an ordinary user (nobody, through
# setpriv, when we are root: root may write any file, so refusals are only
# visible as someone else), in the current folder, which it may write.
# need_user (below) first checks that this can work.
as_user() {
    if [ "$(id -u)" -ne 0 ]; then
        "$@"
        return
    fi
    HOME="$work/home" TMPDIR="$work/home" XDG_RUNTIME_DIR="$work/home" \
        setpriv --reuid=nobody --regid="$(id -gn nobody)" --clear-groups "$@"
}

# need_user: exits 77 (skip), saying why, where as_user cannot work: root
# without setpriv or a user nobody, or nobody unable to reach $server.
need_user() {
    [ "$(id -u)" -eq 0 ] || return 0
    command -v setpriv >/dev/null || { echo "SKIPPED [$case_name]: root, and no setpriv to run as a non-root user" >&2; exit 77; }
    id nobody >/dev/null 2>&1 || { echo "SKIPPED [$case_name]: root, and no user nobody to run as" >&2; exit 77; }
    setpriv --reuid=nobody --regid="$(id -gn nobody)" --clear-groups test -x "$server" || {
        echo "SKIPPED [$case_name]: nobody cannot run $server (a private folder on its path?)" >&2
        exit 77
    }
}

# user_server EXPECTED_CODE ARGS...: server, run by as_user.
user_server() {
    local expected=$1
    shift
    as_user xvfb-run -a "$server" "$@" >server.txt 2>&1
    local code=$?
    if [ "$code" -ge 128 ] && [ "$code" -ne 255 ]; then
        fail "meshlabserver $* (as $(as_user id -un)) crashed (exit $code): $(tail -5 server.txt)"
    fi
    [ "$code" -eq "$expected" ] || fail "meshlabserver $* exited $code, expected $expected: $(tail -5 server.txt)"
}

# parts_add_up LINE: the "T bytes, X bpv = header a B (..) + ..." of a save
# or open summary names parts whose bytes sum to T.
parts_add_up() {
    local total sum
    total=$(echo "$1" | sed -n 's/.*: \([0-9]*\) bytes, [0-9.]* bpv = .*/\1/p')
    [ -n "$total" ] || fail "no 'T bytes, X bpv = ...' in: $1"
    sum=$(echo "$1" | sed 's/.* bpv = //; s/;.*//' | grep -o '[0-9][0-9]* B (' | awk '{ sum += $1 } END { print sum }')
    [ "$sum" = "$total" ] || fail "the parts add up to $sum bytes, not $total: $1"
}

no_temporary_files() {
    local leftovers=("$1"/*.tmp.* "$1"/.*.tmp.*)
    [ ${#leftovers[@]} -eq 0 ] || fail "a temporary file was left in $1: ${leftovers[*]}"
}

[ "$case_name" = install ] || [ -x "$server" ] || fail "$server missing: the meshlab.install test sets it up"

case "$case_name" in
install)
    # Twice: the second run must succeed and change nothing that matters.
    for run in 1 2; do
        bash "$src/scripts/meshlab-user-install.sh" "$prefix" "$plugins" >install.txt 2>&1 ||
            fail "meshlab-user-install.sh (run $run): $(cat install.txt)"
    done
    lib="$prefix/lib/x86_64-linux-gnu/meshlab"
    for exe in meshlab meshlabserver; do
        if [ ! -x "$prefix/bin/$exe" ] || [ -L "$prefix/bin/$exe" ]; then fail "$prefix/bin/$exe is not a copied executable"; fi
    done
    [ -L "$lib/libmeshlab-common.so" ] || fail "libmeshlab-common.so is not linked"
    [ -L "$lib/plugins/libio_base.so" ] || fail "the stock plugins are not linked"
    for p in libio_drm.so libfilter_drm.so; do
        cmp -s "$plugins/$p" "$lib/plugins/$p" || fail "$p is not the freshly built one"
    done
    # The dump lists every filter MeshLab loaded: ours must be there, which
    # also shows MeshLab's plugin sanity checks accepted it.
    server 0 -d "$work/filters.txt"
    [ "$(grep -c "Colorize Faces by Distance Rank" filters.txt)" -eq 1 ] || fail "the filter is not listed exactly once in meshlabserver's filter list"
    grep -qF "Current Plugins Dir is: $(cd "$lib/plugins" && pwd -P)" server.txt || fail "meshlabserver did not use the prefix's plugins: $(head -3 server.txt)"
    bash "$src/scripts/meshlab-user-install.sh" --help >help.txt 2>&1 || fail "meshlab-user-install.sh --help exited $?"
    grep -q "^usage: .*meshlab-user-install.sh PREFIX" help.txt || fail "--help printed no usage: $(cat help.txt)"
    bash "$src/scripts/meshlab-user-install.sh" >/dev/null 2>&1
    [ $? -eq 2 ] || fail "meshlab-user-install.sh without a PREFIX did not exit 2"
    bash "$src/scripts/meshlab-system-install.sh" --help >help.txt 2>&1 || fail "meshlab-system-install.sh --help exited $?"
    grep -q "^usage: " help.txt || fail "meshlab-system-install.sh --help printed no usage: $(cat help.txt)"
    # The filter script says which meshlabserver can run it.
    grep -q "PREFIX/bin/meshlabserver" "$src/resources/colorize-by-rank.mlx" ||
        fail "colorize-by-rank.mlx does not name the private prefix's meshlabserver"
    echo "install: private MeshLab in $prefix, filter listed, --help exits 0"
    ;;
export_import)
    # Meshes with one closed surface, holes, several components, loose
    # triangles. Export through the plugin: the file must be what `drm
    # encode` writes (same default options, same floats read from the PLY).
    # Import through the plugin: the mesh must be what `drm decode` gives.
    for name in fandisk elephant-with-holes blobby-3cc soup; do
        server 0 -l "$name-log.txt" -i "$data/$name.ply" -o "$work/$name-meshlab.drm"
        [ -s "$name-meshlab.drm" ] || fail "$name-meshlab.drm was not written: $(tail -5 server.txt)"
        # The size summary reaches stdout and the -l log, parts adding up.
        saved=$(grep "^drm: saved $name-meshlab.drm: .* bytes, .* bpv = header .* connectivity .* geometry " server.txt) ||
            fail "no size summary on stdout: $(cat server.txt)"
        parts_add_up "$saved"
        grep -qF "$saved" "$name-log.txt" || fail "the size summary is not in the -l log: $(cat "$name-log.txt")"
        [ "$(sed -n 's/.*: \([0-9]*\) bytes, .*/\1/p' <<<"$saved")" = "$(stat -c %s "$name-meshlab.drm")" ] ||
            fail "the summary's total is not the file's size: $saved"
        ! grep -q "^drm: note:" server.txt || fail "a note about lost attributes for a plain mesh: $(grep '^drm: note:' server.txt)"
        "$drm" encode "$data/$name.ply" "$work/$name-cli.drm" >/dev/null || fail "drm encode $name failed"
        cmp "$name-meshlab.drm" "$name-cli.drm" >/dev/null || fail "the plugin's $name.drm differs from drm encode's"
        echo "export_import: $name-meshlab.drm is byte-identical to drm encode's ($(stat -c %s "$name-meshlab.drm") bytes)"
        server 0 -i "$work/$name-meshlab.drm" -o "$work/$name-meshlab.ply"
        [ -s "$name-meshlab.ply" ] || fail "$name-meshlab.ply was not written: $(tail -5 server.txt)"
        grep -q "^drm: opened $name-meshlab.drm: [0-9]* vertices, .* bpv = header " server.txt ||
            fail "no summary of the opened file on stdout: $(cat server.txt)"
        "$drm" decode "$work/$name-meshlab.drm" "$work/$name-cli.ply" >/dev/null || fail "drm decode $name failed"
        same "$work/$name-meshlab.ply" "$work/$name-cli.ply"
    done
    ;;
colorize)
    # The .mlx filter script against `drm ranks` on the same mesh.
    for name in fandisk elephant-with-holes; do
        server 0 -i "$data/$name.ply" -o "$work/$name-ranks.ply" -m fc fq -s "$src/resources/colorize-by-rank.mlx"
        [ -s "$name-ranks.ply" ] || fail "$name-ranks.ply was not written: $(tail -5 server.txt)"
        grep -q "Distance ranks of $name.ply: connectivity [0-9.]* bpv" server.txt || fail "no bpv in the log: $(cat server.txt)"
        grep -q "^Rank codes (0 = boundary edge): " server.txt || fail "no rank histogram in the log"
        # Progress: each stage on a line of its own, not run together.
        grep -qx "drm: ranking" server.txt || fail "no 'drm: ranking' progress line: $(head -20 server.txt)"
        ! grep -q "[a-z]drm: " server.txt || fail "progress words run together: $(grep '[a-z]drm: ' server.txt | head -2)"
        # The legend, as text (meshlabserver prints the log as it is), with
        # the palette's colours, the same as drm ranks lists.
        ! grep -q "<span\|&nbsp;" server.txt || fail "HTML in meshlabserver's output: $(grep '<span' server.txt | head -1)"
        "$drm" ranks "$data/$name.ply" "$work/$name-cli-ranks.ply" >cli-ranks.txt 2>&1 || fail "drm ranks $name failed"
        for bucket in "start triangle" "rank 1" "rank 2" "rank 3" "rank 4+"; do
            hex=$(sed -n "s/^  $bucket  *\(#[0-9a-f]\{6\}\) .*/\1/p" cli-ranks.txt)
            [ -n "$hex" ] || fail "drm ranks lists no colour for $bucket: $(cat cli-ranks.txt)"
            grep -q "^  $bucket  *$hex " server.txt || fail "the filter's legend has no '$bucket $hex': $(grep -A6 'Faces per colour' server.txt)"
        done
        echo "colorize: $(grep -o "Distance ranks of [^;]*" server.txt | head -1)"
        same "$work/$name-ranks.ply" "$work/$name-cli-ranks.ply" --face-colours --face-quality
    done
    # Saving the coloured mesh as .drm says what stays behind.
    server 0 -i "$work/fandisk-ranks.ply" -o "$work/coloured.drm"
    [ -s coloured.drm ] || fail "coloured.drm was not written: $(tail -5 server.txt)"
    grep -q "^drm: note: coloured.drm does not keep the mesh's face colours (not ticked) and face quality (not ticked)" server.txt ||
        fail "no note about the face colours and quality left behind: $(tail -5 server.txt)"
    echo "colorize: $(grep '^drm: note:' server.txt)"
    ;;
colorize_bad_parameter)
    sed 's/name="QuantizationBits" type="RichInt" value="12"/name="QuantizationBits" type="RichInt" value="0"/' \
        "$src/resources/colorize-by-rank.mlx" >bad-bits.mlx
    grep -q 'value="0"' bad-bits.mlx || fail "could not make the bad script"
    server 255 -i "$data/torus.ply" -o "$work/out.ply" -m fc -s "$work/bad-bits.mlx"
    grep -q "Quantization bits must be between 1 and 21, not 0" server.txt || fail "no message with the dialog's label: $(tail -5 server.txt)"
    ! grep -q "QuantizationBits must" server.txt || fail "the message names the internal parameter: $(grep 'QuantizationBits must' server.txt)"
    [ ! -e out.ply ] || fail "out.ply was written after a failed filter"
    echo "colorize_bad_parameter: $(grep -o 'Quantization bits must.*' server.txt | head -1)"
    ;;
colorize_non_manifold)
    # Three faces on one edge: the filter ranks the cut mesh, as drm ranks does.
    server 0 -i "$data/bad/fin.off" -o "$work/fin-ranks.ply" -m fc fq -s "$src/resources/colorize-by-rank.mlx"
    [ -s fin-ranks.ply ] || fail "fin-ranks.ply was not written: $(tail -5 server.txt)"
    grep -q "cut and restored exactly: [0-9]* vertex copies" server.txt || fail "no word on the repair: $(tail -5 server.txt)"
    "$drm" ranks "$data/bad/fin.off" "$work/fin-cli-ranks.ply" >/dev/null 2>&1 || fail "drm ranks fin.off failed"
    same "$work/fin-ranks.ply" "$work/fin-cli-ranks.ply" --face-colours --face-quality
    echo "colorize_non_manifold: $(grep -o 'cut and restored.*' server.txt | head -1 | cut -c1-160)"
    ;;
corrupt_drm)
    "$drm" encode "$data/torus.ply" "$work/good.drm" >/dev/null || fail "drm encode failed"
    head -c 200 good.drm >truncated.drm
    head -c 3000 /dev/urandom >garbage.drm
    : >empty.drm
    # Flip a byte in the middle: the decoder must refuse it or decode
    # something, never crash.
    cp good.drm flipped.drm
    printf '\xff' | dd of=flipped.drm bs=1 seek=$(( $(stat -c %s good.drm) / 2 )) conv=notrunc 2>/dev/null
    for f in truncated garbage empty; do
        server 255 -i "$work/$f.drm" -o "$work/$f.ply"
        grep -q "^drm: error: cannot open $f.drm: " server.txt || fail "$f.drm: no message: $(tail -5 server.txt)"
        [ ! -e "$f.ply" ] || fail "$f.ply was written"
        echo "corrupt_drm: $(grep '^drm: error:' server.txt | head -1)"
    done
    xrun "$server" -i "$work/flipped.drm" -o "$work/flipped.ply" >server.txt 2>&1
    code=$?
    [ "$code" -eq 0 ] || [ "$code" -eq 255 ] || fail "flipped.drm: meshlabserver exited $code: $(tail -5 server.txt)"
    echo "corrupt_drm: flipped byte -> exit $code: $(grep '^drm: error:' server.txt | head -1)"
    ;;
non_manifold_export)
    # A non-manifold mesh saves (byte-identical to drm encode) and opens
    # again as drm decode gives it.
    server 0 -i "$data/bad/fin.off" -o "$work/fin-meshlab.drm"
    [ -s fin-meshlab.drm ] || fail "fin-meshlab.drm was not written: $(tail -5 server.txt)"
    "$drm" encode "$data/bad/fin.off" "$work/fin-cli.drm" >/dev/null 2>&1 || fail "drm encode fin.off failed"
    cmp fin-meshlab.drm fin-cli.drm >/dev/null || fail "the plugin's fin.drm differs from drm encode's"
    server 0 -i "$work/fin-meshlab.drm" -o "$work/fin-meshlab.ply"
    "$drm" decode "$work/fin-meshlab.drm" "$work/fin-cli.ply" >/dev/null || fail "drm decode fin.drm failed"
    same "$work/fin-meshlab.ply" "$work/fin-cli.ply"
    # A mesh no file can hold (a NaN coordinate) is refused with the reason;
    # an existing file is untouched.
    echo "previous contents" >out.drm
    server 0 -i "$data/bad/nan.ply" -o "$work/out.drm"
    grep -q "has NOT been saved" server.txt || fail "meshlabserver did not report the failed save: $(tail -5 server.txt)"
    grep -q "^drm: error: cannot save out.drm: .*finite" server.txt || fail "no message naming the coordinate: $(tail -5 server.txt)"
    [ "$(cat out.drm)" = "previous contents" ] || fail "the existing out.drm was overwritten"
    no_temporary_files "$work"
    echo "non_manifold_export: fin.off saved and reopened as drm does; nan.ply: $(grep '^drm: error:' server.txt | cut -c1-120)..."
    ;;
batch)
    export MESHLABSERVER="$server"
    mkdir in
    cp "$data/fandisk.ply" "$data/torus.ply" "$data/nefertiti.ply" in/
    bash "$src/resources/batch-compress.sh" in packed >batch.txt 2>&1 || fail "batch-compress: $(cat batch.txt)"
    cat batch.txt
    grep -q "^batch-compress: 3 files" batch.txt || fail "no summary line"
    grep -q "^fandisk.ply -> fandisk.drm: .* 6475 vertices, [0-9.]* bits per vertex" batch.txt ||
        fail "no bits per vertex for fandisk: $(cat batch.txt)"
    grep -q "^batch-compress: 3 files, .* [0-9.]* bits per vertex (.drm bytes over [0-9]* vertices)" batch.txt ||
        fail "no bits per vertex in the summary: $(cat batch.txt)"
    bash "$src/resources/batch-decompress.sh" packed unpacked >batch.txt 2>&1 || fail "batch-decompress: $(cat batch.txt)"
    cat batch.txt
    grep -q "^batch-decompress: 3 files" batch.txt || fail "no summary line"
    for name in fandisk torus nefertiti; do
        "$drm" decode "packed/$name.drm" "$work/$name-cli.ply" >/dev/null || fail "drm decode $name.drm failed"
        same "$work/unpacked/$name.ply" "$work/$name-cli.ply"
    done
    # A coloured mesh keeps its colours both ways, as drm encode does.
    mkdir coloured
    "$drm" encode "$data/attributes/vcolors.ply" "$work/vcolors.drm" --attributes colors >/dev/null &&
        "$drm" decode "$work/vcolors.drm" "$work/coloured/vcolors.ply" >/dev/null || fail "cannot make a coloured mesh"
    bash "$src/resources/batch-compress.sh" coloured coloured-packed >batch.txt 2>&1 || fail "batch-compress: $(cat batch.txt)"
    "$drm" encode "$work/coloured/vcolors.ply" "$work/vcolors-cli.drm" >/dev/null || fail "drm encode vcolors.ply failed"
    cmp -s coloured-packed/vcolors.drm vcolors-cli.drm ||
        fail "batch-compress lost what drm encode keeps: $("$drm" info coloured-packed/vcolors.drm | grep -A3 attribute)"
    bash "$src/resources/batch-decompress.sh" coloured-packed coloured-unpacked >batch.txt 2>&1 ||
        fail "batch-decompress: $(cat batch.txt)"
    "$drm" decode coloured-packed/vcolors.drm "$work/vcolors-cli.ply" >/dev/null || fail "drm decode vcolors.drm failed"
    same "$work/coloured-unpacked/vcolors.ply" "$work/vcolors-cli.ply" --vertex-colours
    # Opening and saving print the codec's stages, each once.
    server 0 -i "$work/coloured/vcolors.ply" -o "$work/progress.drm"
    grep -qx "drm: coding vertices\|drm: ranking" server.txt || fail "no progress lines: $(cat server.txt)"
    [ -z "$(grep '^drm: [a-z ]*$' server.txt | sort | uniq -d)" ] || fail "a stage printed twice: $(grep '^drm: ' server.txt)"
    # A failing file is reported, the others still converted, the failures
    # listed at the end, exit 1 (as drm encode -o does).
    cp "$data/bad/nan.ply" in/
    bash "$src/resources/batch-compress.sh" in packed2 >batch.txt 2>&1
    code=$?
    cat batch.txt
    [ "$code" -eq 1 ] || fail "batch-compress with nan.ply exited $code: $(cat batch.txt)"
    grep -q "^batch-compress: failed: nan.ply: cannot save nan.drm: " batch.txt || fail "unclear failure: $(cat batch.txt)"
    [ ! -e packed2/nan.drm ] || fail "packed2/nan.drm exists"
    for name in fandisk torus nefertiti; do
        cmp -s "packed/$name.drm" "packed2/$name.drm" || fail "packed2/$name.drm was not written past the failure"
    done
    grep -q "^batch-compress: 3 files, " batch.txt || fail "the summary does not count the 3 good files: $(cat batch.txt)"
    grep -q "^batch-compress: 1 file(s) failed:" batch.txt || fail "no list of failures: $(cat batch.txt)"
    grep -q "^  nan.ply: cannot save nan.drm: " batch.txt || fail "nan.ply not listed: $(cat batch.txt)"
    leftovers=(packed2/.batch-*)
    [ ${#leftovers[@]} -eq 0 ] || fail "a temporary file was left: ${leftovers[*]}"
    # --stop-on-error stops at the first failure (names sort: fandisk, nan, ...).
    bash "$src/resources/batch-compress.sh" --stop-on-error in packed3 >batch.txt 2>&1
    code=$?
    [ "$code" -eq 1 ] || fail "batch-compress --stop-on-error exited $code: $(cat batch.txt)"
    grep -q "^batch-compress: stopped at nan.ply: cannot save nan.drm: " batch.txt || fail "unclear stop: $(cat batch.txt)"
    [ ! -e packed3/nefertiti.drm ] || fail "--stop-on-error carried on past nan.ply"
    head -c 100 packed/torus.drm >packed/torus.drm.part && mv packed/torus.drm.part packed/broken.drm
    bash "$src/resources/batch-decompress.sh" packed unpacked2 >batch.txt 2>&1
    code=$?
    cat batch.txt
    [ "$code" -eq 1 ] || fail "batch-decompress with broken.drm exited $code: $(cat batch.txt)"
    grep -q "^batch-decompress: failed: broken.drm: cannot open broken.drm: " batch.txt || fail "unclear failure: $(cat batch.txt)"
    [ -s unpacked2/torus.ply ] || fail "torus.ply was not decompressed past broken.drm"
    grep -q "^  broken.drm: cannot open broken.drm: " batch.txt || fail "broken.drm not listed: $(cat batch.txt)"
    bash "$src/resources/batch-compress.sh" --help >help.txt 2>&1 || fail "batch-compress.sh --help exited $?"
    grep -q "^usage: batch-compress \[--stop-on-error\] DIR OUTDIR" help.txt || fail "no usage: $(cat help.txt)"
    echo "batch: failures carry on and are listed: $(grep -h '^  ' batch.txt | cut -c1-100)"
    ;;
replace_files)
    need_user
    # Saving over existing files as an ordinary user: the mode stays, a
    # symbolic link is written through, a file the user may not write is
    # refused with a message and left alone (MeshLab's own PLY export
    # refuses it too).
    mkdir -p home out
    cp "$data/torus.ply" in.ply
    echo old >out/private.drm && chmod 600 out/private.drm
    echo old >out/real.drm && chmod 640 out/real.drm && ln -s real.drm out/link.drm
    echo old >out/locked.drm && chmod 444 out/locked.drm
    [ "$(id -u)" -ne 0 ] || chown -R nobody:"$(id -gn nobody)" home out in.ply
    chmod 755 "$work"
    "$drm" encode in.ply expected.drm >/dev/null || fail "drm encode failed"
    user_server 0 -i "$work/in.ply" -o "$work/out/private.drm"
    cmp -s out/private.drm expected.drm || fail "private.drm was not replaced: $(tail -5 server.txt)"
    [ "$(stat -c %a out/private.drm)" = 600 ] || fail "private.drm became mode $(stat -c %a out/private.drm)"
    user_server 0 -i "$work/in.ply" -o "$work/out/link.drm"
    [ -L out/link.drm ] || fail "the link link.drm was replaced by a file"
    cmp -s out/real.drm expected.drm || fail "the link's target was not written: $(tail -5 server.txt)"
    [ "$(stat -c %a out/real.drm)" = 640 ] || fail "real.drm became mode $(stat -c %a out/real.drm)"
    user_server 0 -i "$work/in.ply" -o "$work/out/locked.drm"
    grep -q "^drm: error: cannot save locked.drm: cannot write .*locked.drm: the file is read-only for you" server.txt ||
        fail "no refusal of the read-only file: $(tail -5 server.txt)"
    grep -q "has NOT been saved" server.txt || fail "meshlabserver did not report the failed save: $(tail -5 server.txt)"
    refusal=$(grep -o 'the file is read-only.*' server.txt | head -1)
    [ "$(cat out/locked.drm)" = old ] || fail "the read-only locked.drm was replaced"
    [ "$(stat -c %a out/locked.drm)" = 444 ] || fail "locked.drm's mode changed"
    # The same through MeshLab's own PLY writer, for comparison.
    echo old >out/locked.ply && chmod 444 out/locked.ply
    [ "$(id -u)" -ne 0 ] || chown nobody out/locked.ply
    user_server 0 -i "$work/in.ply" -o "$work/out/locked.ply"
    [ "$(cat out/locked.ply)" = old ] || fail "MeshLab's PLY export replaced a read-only file (so refusing is not its convention)"
    no_temporary_files "$work/out"
    # The batch scripts replace files the same way.
    mkdir -p batch-in batch-out
    cp "$data/torus.ply" "$data/fandisk.ply" "$data/nefertiti.ply" batch-in/
    echo old >batch-out/fandisk.drm && chmod 600 batch-out/fandisk.drm
    echo old >batch-out/real.drm && ln -s real.drm batch-out/nefertiti.drm
    echo old >batch-out/torus.drm && chmod 444 batch-out/torus.drm
    [ "$(id -u)" -ne 0 ] || chown -R nobody:"$(id -gn nobody)" batch-in batch-out
    MESHLABSERVER="$server" as_user bash "$src/resources/batch-compress.sh" batch-in batch-out >batch.txt 2>&1
    code=$?
    [ "$code" -eq 1 ] || fail "batch-compress onto a read-only torus.drm exited $code: $(cat batch.txt)"
    grep -q "^  torus.ply: cannot write torus.drm: the file is read-only for you" batch.txt || fail "no refusal listed: $(cat batch.txt)"
    [ "$(cat batch-out/torus.drm)" = old ] || fail "the batch replaced the read-only torus.drm"
    [ "$(stat -c %a batch-out/fandisk.drm)" = 600 ] || fail "the batch made fandisk.drm mode $(stat -c %a batch-out/fandisk.drm)"
    [ -L batch-out/nefertiti.drm ] || fail "the batch replaced the link nefertiti.drm by a file"
    [ "$(head -c 3 batch-out/real.drm)" != old ] || fail "the batch did not write through the link"
    no_temporary_files "$work/batch-out"
    leftovers=(batch-out/.batch-*)
    [ ${#leftovers[@]} -eq 0 ] || fail "a temporary file was left: ${leftovers[*]}"
    echo "replace_files (as $(as_user id -un)): mode 600 and 640 kept, link written through, read-only refused: $refusal; the batch scripts alike"
    ;;
attributes)
    # A coloured and a textured mesh out through the plugin's export (the
    # boxes ticked with -m) and back in through its import; MeshLab's PLY
    # export of the reopened mesh must carry what `drm decode` gives.
    attr="$data/attributes"
    server 0 -i "$attr/vcolors.ply" -o "$work/coloured.drm" -m vc vt
    [ -s coloured.drm ] || fail "coloured.drm was not written: $(tail -5 server.txt)"
    ! grep -q "does not keep the mesh's vertex colours (not ticked)" server.txt || fail "vc was ticked: $(grep '^drm: note:' server.txt)"
    # MeshLab's own OBJ importer aborts on duck.obj (an assertion in vcglib's
    # ImporterOBJ): the same duck as PLY with wedge texture coordinates.
    server 0 -i "$attr/duck-wedge.ply" -o "$work/textured.drm" -m wt
    [ -s textured.drm ] || fail "textured.drm was not written: $(tail -5 server.txt)"
    "$drm" info coloured.drm --json >info.txt || fail "drm info coloured.drm failed"
    if grep -q '"attributes": \[\]' info.txt; then
        echo "attributes: SKIP the round trip: this build's codec writes no attribute sections"
        exit 77
    fi
    grep -q '"colors"' info.txt || fail "coloured.drm has no colour section: $(cat info.txt)"
    "$drm" info textured.drm --json >info.txt || fail "drm info textured.drm failed"
    grep -q '"corner-texcoords"' info.txt || fail "textured.drm has no corner texture coordinates: $(cat info.txt)"
    server 0 -i "$work/coloured.drm" -o "$work/coloured-meshlab.ply" -m vc vt
    "$drm" decode coloured.drm coloured-cli.ply >/dev/null || fail "drm decode coloured.drm failed"
    same "$work/coloured-meshlab.ply" "$work/coloured-cli.ply" --vertex-colours --vertex-texcoords
    server 0 -i "$work/textured.drm" -o "$work/textured-meshlab.ply" -m wt
    # The texture image is not in tests/data: the plugin says it is missing
    # beside the .drm file (MeshLab looks there, as for PLY and OBJ).
    grep -q "texture files not found beside the file: .*duckCM.tga" server.txt ||
        fail "no word on the missing duckCM.tga: $(grep 'drm' server.txt | tail -5)"
    grep -a -q "^comment TextureFile .*duckCM.tga" textured-meshlab.ply ||
        fail "the reopened duck lost its texture name: $(head -c 300 textured-meshlab.ply)"
    "$drm" decode textured.drm textured-cli.ply >/dev/null || fail "drm decode textured.drm failed"
    same "$work/textured-meshlab.ply" "$work/textured-cli.ply" --wedge-texcoords
    ;;
*)
    fail "unknown case"
    ;;
esac
