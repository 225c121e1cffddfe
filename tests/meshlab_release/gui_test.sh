#!/usr/bin/env bash
# Drives the real MeshLab GUI of a newer release with drm's plugins:
#   gui_test.sh PROJECT_DIR PLUGIN_DIR RELEASE OUT_DIR [--screenshots DOCS_IMAGE_DIR]
#
# Runs on the host as root. MeshLab RELEASE runs inside its Debian root
# (scripts/meshlab-root.sh) under Xvfb, with the plugins of PLUGIN_DIR in a
# per-user plugin folder (XDG_DATA_HOME in OUT_DIR: nothing in the root's
# system folders or in ~ is touched), and xdotool types and clicks as a user
# does:
#   1. MeshLab opens fandisk.drm given on its command line (the log line
#      "drm: opened fandisk.drm: 6475 vertices, 12946 faces" on stderr);
#   2. File > Export Mesh As... (Ctrl+Shift+E) saves it as fandisk-gui.drm
#      through the save-attributes dialog; the host's `drm info` must read
#      6475 vertices and 12946 faces from it and `drm decode` must decode it;
#   3. Filters > Color Creation and Processing > Colorize Faces by Distance
#      Rank runs on it and writes its legend to the log;
#   4. a second MeshLab opens the textured duck.drm and finds its texture.
# With --screenshots, DOCS_IMAGE_DIR gets meshlab-RELEASE-export-dialog.png,
# meshlab-RELEASE-rank-colours.png and meshlab-RELEASE-duck.png.
# OUT_DIR must lie inside PROJECT_DIR (the root sees the project at /drm);
# it holds the files, MeshLab's stderr and, on failure, failure.png.
# Exits 0 only when every check passed.
#
# The same script runs inside the root with --in-root (the GUI part).
set -uo pipefail

# Expected counts of the meshes (tests/data/README.md).
fandisk_counts="6475 vertices, 12946 faces"
duck_counts="2108 vertices, 4212 faces"
# The whole GUI part, start-ups included, ends within this many seconds.
gui_limit=300

# ---------------------------------------------------------------------------
# Inside the root: Xvfb, MeshLab and xdotool.
# ---------------------------------------------------------------------------
in_root() {
    local work=$1 shots=$2
    cd "$work" || exit 1
    local xvfb_pid="" meshlab_pid="" main=""

    # On failure, the screen with every dialog open goes to failure.png.
    fail() {
        echo "FAIL: $*" >&2
        [ -n "$xvfb_pid" ] && screenshot failure $(dialogs)
        exit 1
    }
    # Every process started here ends with the script, however it ends.
    stop_meshlab() {
        [ -n "$meshlab_pid" ] || return 0
        kill "$meshlab_pid" 2>/dev/null
        for _ in $(seq 50); do kill -0 "$meshlab_pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$meshlab_pid" 2>/dev/null
        wait "$meshlab_pid" 2>/dev/null
        meshlab_pid=""
    }
    cleanup() {
        stop_meshlab
        if [ -n "$xvfb_pid" ]; then
            kill "$xvfb_pid" 2>/dev/null
            wait "$xvfb_pid" 2>/dev/null
        fi
    }
    trap cleanup EXIT
    trap 'exit 1' TERM INT

    # MeshLab's settings, caches and user plugin folder live in the work
    # folder; its plugin folder holds our two plugins and nothing else.
    export HOME=$work/home XDG_DATA_HOME=$work/home/data XDG_CONFIG_HOME=$work/home/config
    export XDG_CACHE_HOME=$work/home/cache XDG_RUNTIME_DIR=$work/home/runtime
    local plugin_folder=$XDG_DATA_HOME/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/$release
    mkdir -p "$XDG_CONFIG_HOME" "$XDG_CACHE_HOME" "$XDG_RUNTIME_DIR"
    chmod 700 "$XDG_RUNTIME_DIR"
    # Installed as a user installs them (README), into that folder.
    bash /drm/scripts/meshlab-extra-plugins-install.sh "$release" "$work/plugins" ||
        fail "scripts/meshlab-extra-plugins-install.sh failed"
    [ -f "$plugin_folder/libio_drm.so" ] && [ -f "$plugin_folder/libfilter_drm.so" ] ||
        fail "the install script did not fill $plugin_folder"

    for tool in meshlab Xvfb xdotool xwd; do
        command -v "$tool" >/dev/null ||
            fail "no $tool in the root: add its package to build_packages in scripts/meshlab-root.sh and install it there"
    done

    # Xvfb picks a free display itself (-displayfd); the root runs in a
    # network namespace of its own, so its X sockets are its own too.
    # -noreset: an X server resets when its last client leaves, and a client
    # connecting meanwhile (MeshLab, right after xdotool) finds no display.
    Xvfb -displayfd 3 -screen 0 1280x900x24 -nolisten tcp -noreset 3>display.txt >xvfb.log 2>&1 &
    xvfb_pid=$!
    for _ in $(seq 100); do [ -s display.txt ] && break; sleep 0.1; done
    if [ ! -s display.txt ]; then
        kill "$xvfb_pid" 2>/dev/null
        xvfb_pid=""
        fail "Xvfb did not start: $(tail -3 xvfb.log)"
    fi
    export DISPLAY=:$(head -1 display.txt)
    # Wait until a client gets an answer from the display Xvfb named.
    for _ in $(seq 100); do xdotool getdisplaygeometry >/dev/null 2>&1 && break; sleep 0.1; done
    xdotool getdisplaygeometry >/dev/null 2>&1 || fail "Xvfb on $DISPLAY answers no client: $(tail -3 xvfb.log)"
    # The pointer rests in a corner, away from tooltips.
    xdotool mousemove 5 895

    # wait_log SECONDS TEXT FILE: waits until FILE (MeshLab's stderr) holds TEXT.
    wait_log() {
        local deadline=$((SECONDS + $1))
        while [ "$SECONDS" -lt "$deadline" ]; do
            grep -qF -- "$2" "$3" 2>/dev/null && return 0
            kill -0 "$meshlab_pid" 2>/dev/null || fail "MeshLab ended while waiting for '$2' (stderr: $3)"
            sleep 0.2
        done
        return 1
    }
    # window_named SECONDS REGEX: prints the visible window whose title
    # matches REGEX, waiting for it up to SECONDS.
    window_named() {
        local deadline=$((SECONDS + $1)) w
        while [ "$SECONDS" -lt "$deadline" ]; do
            w=$(xdotool search --onlyvisible --name "$2" 2>/dev/null | head -1)
            [ -n "$w" ] && { echo "$w"; return 0; }
            sleep 0.2
        done
        return 1
    }
    # gone SECONDS REGEX: waits until no visible window matches REGEX.
    gone() {
        local deadline=$((SECONDS + $1))
        while [ "$SECONDS" -lt "$deadline" ]; do
            [ -z "$(xdotool search --onlyvisible --name "$2" 2>/dev/null)" ] && return 0
            sleep 0.2
        done
        return 1
    }
    # There is no window manager: keys go to the window given the X input
    # focus, so every keystroke is preceded by focusing its window.
    keys_to() {
        local w=$1
        shift
        xdotool windowfocus "$w"
        sleep 0.3
        xdotool key --delay 150 "$@"
    }
    # dialogs: the visible windows with a title other than MeshLab's own
    # (its main window and its menus and docks are titled MeshLab...).
    dialogs() {
        local w
        for w in $(xdotool search --onlyvisible --name . 2>/dev/null); do
            case "$(xdotool getwindowname "$w" 2>/dev/null)" in
            MeshLab*) ;;
            *) echo "$w" ;;
            esac
        done
    }
    # titles: the titles of the visible windows, for messages.
    titles() {
        xdotool search --onlyvisible --name . getwindowname %@ 2>/dev/null | sort -u | grep -v '^MeshLab_' | paste -sd ';'
    }
    # screenshot NAME [WINDOW...]: shot-NAME.xwd of the screen, and one
    # shot-NAME-N.xwd per WINDOW with its position in shot-NAME.overlays.
    # Qt draws dialogs in 32-bit windows, which `xwd -root` leaves black on
    # Xvfb's 24-bit screen: the host pastes them over the screen picture.
    screenshot() {
        local name=$1 n=0 w geometry
        shift
        rm -f "shot-$name"*
        xwd -root -silent >"shot-$name.xwd" || echo "cannot take screenshot $name" >&2
        : >"shot-$name.overlays"
        for w in "$@"; do
            n=$((n + 1))
            xwd -id "$w" -silent >"shot-$name-$n.xwd" || continue
            geometry=$(xdotool getwindowgeometry --shell "$w" | tr '\n' ' ')
            echo "shot-$name-$n.xwd $(eval "$geometry"; echo "$X $Y")" >>"shot-$name.overlays"
        done
    }

    # start_meshlab FILE COUNTS: MeshLab with FILE on its command line;
    # returns once its log says the plugin opened FILE with COUNTS, its
    # window filling the screen.
    start_meshlab() {
        local file=$1 counts=$2 log
        log="meshlab-${file%.drm}.stderr"
        meshlab "$file" >"meshlab-${file%.drm}.stdout" 2>"$log" &
        meshlab_pid=$!
        # A plugin that fails to load stops start-up with a modal warning.
        local deadline=$((SECONDS + 60))
        until grep -qF "drm: opened $file: $counts" "$log" 2>/dev/null; do
            [ -z "$(xdotool search --onlyvisible --name '^Error while loading plugins' 2>/dev/null)" ] ||
                fail "MeshLab could not load a plugin: its warning is in failure.png"
            kill -0 "$meshlab_pid" 2>/dev/null ||
                fail "MeshLab ended at start-up on display $DISPLAY (Xvfb $(kill -0 "$xvfb_pid" 2>/dev/null && echo running || echo gone)): $(grep -v '^LOG' "$log" | tail -3)"
            [ "$SECONDS" -lt "$deadline" ] ||
                fail "MeshLab did not log 'drm: opened $file: $counts' within 60 s (stderr: $log; windows: $(titles))"
            sleep 0.2
        done
        echo "ok: MeshLab $release opened $file: $(grep -F "drm: opened $file:" "$log" | sed 's/^LOG: [0-9]* drm: opened [^:]*: //' | cut -c1-90)..."
        main=$(window_named 20 "^MeshLab $release") || fail "no MeshLab $release main window"
        # Without a window manager the window keeps Qt's default size; Qt
        # may still set that size after the window appears, so the resize is
        # repeated until it holds over two looks a second apart.
        local held=0 geometry
        for _ in $(seq 20); do
            geometry=$(xdotool getwindowgeometry --shell "$main" | tr '\n' ' ')
            case "$geometry" in
            *"X=0 Y=0 WIDTH=1280 HEIGHT=900 "*) held=$((held + 1)) ;;
            *) held=0; xdotool windowmove "$main" 0 0 windowsize "$main" 1280 900 ;;
            esac
            [ "$held" -ge 2 ] && break
            sleep 1
        done
        [ "$held" -ge 2 ] || fail "the MeshLab window does not keep the screen's size ($geometry)"
        sleep 1
    }

    # --- fandisk: open, export through the dialogs, colorize -------------
    start_meshlab fandisk.drm "$fandisk_counts"
    local log=meshlab-fandisk.stderr dialog
    rm -f fandisk-gui.drm

    # File > Export Mesh As... (MeshLab's shortcut Ctrl+Shift+E), then a
    # Qt file dialog (its name field holds the current name, selected).
    keys_to "$main" ctrl+shift+e
    dialog=$(window_named 20 '^Save "') || fail "Ctrl+Shift+E (File > Export Mesh As...) opened no file dialog"
    keys_to "$dialog" ctrl+a
    xdotool type --delay 20 "$work/fandisk-gui.drm"
    xdotool key Return
    # The save-attributes dialog: attribute boxes and the plugin's
    # parameters; OK is its default button.
    dialog=$(window_named 20 "^Choose Saving Options for: 'fandisk'") ||
        fail "no save-attributes dialog after naming fandisk-gui.drm"
    if [ "$shots" = 1 ]; then
        # Room for the parameters' help texts, then its Help box (bottom
        # left, 170 px in, 36 px up) shows them beside each parameter.
        xdotool windowsize "$dialog" 760 560
        sleep 1
        eval "$(xdotool getwindowgeometry --shell "$dialog")"
        xdotool mousemove --window "$dialog" 170 $((HEIGHT - 36)) click 1
        xdotool mousemove 5 895
        sleep 1
        screenshot export-dialog "$dialog"
    fi
    keys_to "$dialog" Return
    wait_log 30 "drm: saved fandisk-gui.drm: $fandisk_counts" "$log" ||
        fail "no 'drm: saved fandisk-gui.drm: $fandisk_counts' in the log after OK (windows: $(titles))"
    wait_log 10 "Saved Mesh $work/fandisk-gui.drm" "$log" || fail "MeshLab did not log 'Saved Mesh' for fandisk-gui.drm"
    gone 10 "^Choose Saving Options" || fail "the save-attributes dialog stayed open"
    [ -z "$(xdotool search --onlyvisible --name 'Error' 2>/dev/null)" ] || fail "MeshLab shows an error window after saving"
    echo "ok: File > Export Mesh As... saved fandisk-gui.drm: $(grep -F 'drm: saved fandisk-gui.drm:' "$log" | sed 's/^LOG: [0-9]* drm: saved [^:]*: //' | cut -c1-90)..."

    # Filters > Color Creation and Processing > Colorize Faces by Distance
    # Rank by keyboard: Alt+L opens Filters with its first enabled item
    # ("Show current filter script") active; the sixth submenu below is
    # Color Creation and Processing, whose filters are sorted by name (ours
    # is the third). The dock's title tells whether the path was right.
    keys_to "$main" alt+l
    sleep 1
    xdotool key --delay 150 Down Down Down Down Down Down Right
    sleep 1
    xdotool key --delay 150 Down Down Return
    dialog=$(window_named 20 '^Colorize Faces by Distance Rank$') ||
        fail "Filters > Color Creation and Processing did not open 'Colorize Faces by Distance Rank' (windows: $(titles))"
    # Apply holds the dock's focus.
    keys_to "$dialog" Return
    wait_log 60 "Colorize Faces by Distance Rank in " "$log" || fail "the filter did not finish within 60 s"
    grep -q "^LOG: [0-9] Distance ranks of fandisk" "$log" || fail "no 'Distance ranks of fandisk' line in the log"
    grep -qF "<b>Faces per colour</b> (12946 faces)" "$log" || fail "no legend 'Faces per colour (12946 faces)' in the log"
    local bucket
    for bucket in "start&nbsp;triangle" "rank&nbsp;1" "rank&nbsp;2" "rank&nbsp;3" "rank&nbsp;4+"; do
        grep "Faces per colour" "$log" | grep -qF "</span>&nbsp;$bucket&nbsp;" || fail "the legend has no '$bucket' row"
    done
    grep -q "^LOG: [0-9] Rank codes (0 = boundary edge): " "$log" || fail "no rank histogram in the log"
    echo "ok: Filters > Color Creation and Processing > Colorize Faces by Distance Rank ran; legend and histogram in the log"
    # The dock's Close button (bottom left) uncovers the mesh.
    eval "$(xdotool getwindowgeometry --shell "$dialog")"
    xdotool mousemove --window "$dialog" $((WIDTH / 4)) $((HEIGHT - 22)) click 1
    xdotool mousemove 5 895
    gone 10 '^Colorize Faces by Distance Rank$' || fail "the filter dock did not close"
    sleep 2
    [ "$shots" = 1 ] && screenshot rank-colours
    stop_meshlab

    # --- duck: a textured .drm opens with its texture ---------------------
    start_meshlab duck.drm "$duck_counts"
    grep -F "drm: opened duck.drm:" meshlab-duck.stderr | grep -q "corner-texcoords" ||
        fail "the plugin opened duck.drm without its texture coordinates"
    ! grep -F "texture files not found" meshlab-duck.stderr ||
        fail "the duck's texture was not found beside duck.drm"
    echo "ok: duck.drm opened with its texture ($(grep -o 'corner-texcoords [0-9]* B' meshlab-duck.stderr | head -1), textures found)"
    [ "$shots" = 1 ] && screenshot duck
    stop_meshlab
    exit 0
}

if [ "${1:-}" = "--in-root" ]; then
    release=$3
    in_root "$2" "$4"
fi

# ---------------------------------------------------------------------------
# On the host: files, the run in the root, the checks of what it wrote.
# ---------------------------------------------------------------------------
usage() {
    echo "usage: gui_test.sh PROJECT_DIR PLUGIN_DIR RELEASE OUT_DIR [--screenshots DOCS_IMAGE_DIR]" >&2
    exit 2
}
[ $# -eq 4 ] || [ $# -eq 6 ] || usage
project=$(realpath "$1")
plugins=$(realpath "$2")
release=$3
out=$(realpath -m "$4")
images=""
if [ $# -eq 6 ]; then
    [ "$5" = "--screenshots" ] || usage
    images=$(realpath -m "$6")
fi
drm="$project/build/bin/drm"
started=$SECONDS

fail() { echo "FAIL [MeshLab $release GUI]: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || fail "needs root (chroot into the MeshLab root)"
case "$out" in
"$project"/?*) ;;
*) fail "OUT_DIR $out is not inside PROJECT_DIR $project (the root sees only the project)" ;;
esac
[ -x "$drm" ] || fail "no $drm: build the project first"
command -v convert >/dev/null || fail "no ImageMagick convert on the host"
root=$(bash "$project/scripts/meshlab-root.sh" path "$release") || exit 1
[ -f "$root/.drm-root-ready" ] || fail "no root for MeshLab $release: bash scripts/meshlab-root.sh make $release"
echo "MeshLab GUI test: MeshLab $(cat "$root/.drm-root-ready") in $root"

# OUT_DIR is emptied at each run: only a folder this script made (its mark
# inside) or a new or empty one.
if [ -d "$out" ] && [ -n "$(ls -A "$out")" ] && [ ! -f "$out/.gui-test" ]; then
    fail "OUT_DIR $out holds files this test did not make: give a new folder"
fi
rm -rf "$out"
mkdir -p "$out/plugins" || fail "cannot make $out"
touch "$out/.gui-test"

# The plugins may be rebuilt meanwhile: copy them until a copy is taken
# while neither changes, so MeshLab never meets a half-written .so.
copied=0
for _ in 1 2 3 4 5; do
    before=$(stat -c '%s %Y' "$plugins/libio_drm.so" "$plugins/libfilter_drm.so" 2>/dev/null) ||
        fail "no libio_drm.so and libfilter_drm.so in $plugins"
    cp "$plugins/libio_drm.so" "$plugins/libfilter_drm.so" "$out/plugins/" || fail "cannot copy the plugins"
    sleep 1
    after=$(stat -c '%s %Y' "$plugins/libio_drm.so" "$plugins/libfilter_drm.so" 2>/dev/null)
    if [ "$before" = "$after" ] && cmp -s "$plugins/libio_drm.so" "$out/plugins/libio_drm.so" &&
        cmp -s "$plugins/libfilter_drm.so" "$out/plugins/libfilter_drm.so"; then
        copied=1
        break
    fi
    sleep 5
done
[ "$copied" = 1 ] || fail "the plugins in $plugins kept changing (a build running?)"

# The meshes, made with the host's CLI. The duck's texture is not in the
# project (786 KB): Debian's assimp-testmodels or the shared mesh set has
# it; otherwise a checkerboard stands in under its name.
data="$project/tests/data"
"$drm" encode "$data/fandisk.ply" "$out/fandisk.drm" >/dev/null 2>"$out/cli.txt" || fail "drm encode fandisk: $(cat "$out/cli.txt")"
cp "$data/attributes/duck.obj" "$data/attributes/duck.mtl" "$out/" || fail "no duck.obj and duck.mtl in $data/attributes"
texture=""
for t in "${DRM_DUCK_TEXTURE:-}" /usr/share/assimp/models/Collada/duckCM.tga "$project/../shared/meshes-attributes/duckCM.tga"; do
    [ -n "$t" ] && [ -f "$t" ] && { texture=$t; break; }
done
if [ -n "$texture" ]; then
    cp "$texture" "$out/duckCM.tga"
    echo "duck texture: $texture"
else
    convert -size 64x64 pattern:checkerboard -scale 800% +level-colors darkorange,khaki "$out/duckCM.tga" ||
        fail "no duckCM.tga found and ImageMagick cannot make one"
    echo "duck texture: no duckCM.tga found (set DRM_DUCK_TEXTURE); a checkerboard stands in"
fi
"$drm" encode "$out/duck.obj" "$out/duck.drm" >/dev/null 2>"$out/cli.txt" || fail "drm encode duck.obj: $(cat "$out/cli.txt")"
"$drm" info "$out/duck.drm" | grep -q "corner-texcoords" || fail "duck.drm holds no texture coordinates"

# The GUI part, inside the root, from a copy of this script in OUT_DIR (the
# root sees the project, not necessarily where this script lives).
cp "${BASH_SOURCE[0]}" "$out/gui_test.sh"
in_root_out="/drm/$(realpath --relative-to="$project" "$out")"
# timeout signals its whole process group: MeshLab and Xvfb end with it.
timeout -k 10 "$gui_limit" bash "$project/scripts/meshlab-root.sh" run "$release" \
    bash "$in_root_out/gui_test.sh" --in-root "$in_root_out" "$release" "$([ -n "$images" ] && echo 1 || echo 0)"
code=$?

# xwd_to_png NAME PNG: the screen picture with its windows pasted over it.
xwd_to_png() {
    local name=$1 png=$2 args=() file x y
    [ -s "$out/shot-$name.xwd" ] || return 1
    while read -r file x y; do
        [ -s "$out/$file" ] && args+=("xwd:$out/$file" -geometry "+$x+$y" -composite)
    done <"$out/shot-$name.overlays"
    convert "xwd:$out/shot-$name.xwd" "${args[@]}" "$png"
}

if [ "$code" -ne 0 ]; then
    xwd_to_png failure "$out/failure.png" && echo "screen at the failure: $out/failure.png" >&2
    [ "$code" -eq 124 ] && fail "the GUI part took over $gui_limit s"
    fail "the GUI part failed (exit $code); MeshLab's stderr and the files: $out"
fi

# What MeshLab wrote through the plugin, read by the host's CLI.
saved="$out/fandisk-gui.drm"
[ -s "$saved" ] || fail "MeshLab wrote no $saved"
"$drm" info "$saved" >"$out/info.txt" 2>&1 || fail "drm info fandisk-gui.drm: $(cat "$out/info.txt")"
vertices=$(awk '$1 == "vertices" {print $2}' "$out/info.txt")
faces=$(awk '$1 == "faces" {print $2}' "$out/info.txt")
[ "$vertices" = 6475 ] && [ "$faces" = 12946 ] ||
    fail "drm info reads $vertices vertices, $faces faces from fandisk-gui.drm (expected 6475, 12946)"
"$drm" decode "$saved" "$out/fandisk-gui.ply" >/dev/null 2>"$out/cli.txt" || fail "drm decode fandisk-gui.drm: $(cat "$out/cli.txt")"
echo "ok: drm info reads fandisk-gui.drm ($(stat -c %s "$saved") bytes): $vertices vertices, $faces faces; drm decode decodes it"

if [ -n "$images" ]; then
    mkdir -p "$images" || fail "cannot make $images"
    for name in export-dialog rank-colours duck; do
        png="$images/meshlab-$release-$name.png"
        xwd_to_png "$name" "$png" || fail "no screenshot $name"
        echo "screenshot: $png"
    done
fi
rm -f "$out"/shot-*.xwd
echo "PASS [MeshLab $release GUI] in $((SECONDS - started)) s"
