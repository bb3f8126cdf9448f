#!/usr/bin/env bash
# Records the corpus: every GL hack of Debian's xscreensaver-gl and xscreensaver-gl-extra, and the games, each a capture in OUTDIR.
#
# Usage: scripts/corpus-captures.sh OUTDIR [--quick]
#
# Installs the packages (apt-get, when one is missing), lists every executable the two
# xscreensaver packages put under /usr/libexec/xscreensaver/ (dpkg -L: nothing is chosen by
# hand) and records each with `nprgl record --style none` (the program's own stream) under a
# private Xvfb, in a window of its own, for a fixed number of frames:
#   - a hack: frames 1-12 (CORPUS_FRAMES) in a 640x480 window (CORPUS_GEOMETRY);
#   - a game: the 12 frames ending at the frame where it shows its 3D scene (its launch line
#     below: arguments, keys sent with xdotool, frame, display size);
#   - --quick, the small regression set: every 4th hack in alphabetical order (the 1st, 5th,
#     9th...; 32 of the 125), frames 1-4 in a 320x240 window, no games.
# A program is stopped (SIGTERM) once nprgl has written the screenshot of the frame after the
# last one recorded; one that does not get there within its time limit (CORPUS_LIMIT, 120 s
# for a hack, 600 s for a game) is killed and reported as hung. The hacks and games animate by
# the clock: the picture is whatever moment the run reached, and from then on only the
# capture is used.
#
# Rules (by what a file is, documented here and in the report):
#   - a file that is not an ELF executable is not a GL program: mapscroller.pl is the helper
#     script mapscroller runs to fetch its map tiles (skipped);
#   - xscreensaver-gl-visual prints the GL visual xscreensaver should use and draws nothing
#     (skipped);
#   - every other hack runs with `-window -geometry WxH` and no argument of its own, with
#     /usr/libexec/xscreensaver first in PATH as xscreensaver runs them (mapscroller starts
#     mapscroller.pl by name; offline, it fetches no map tiles and ends).
#
# Writes only inside OUTDIR: OUTDIR/NAME.nprgl (a program that forks a drawing child also
# leaves OUTDIR/NAME.PID.nprgl), OUTDIR/logs/, OUTDIR/work/ (screenshots, homes) and
#   OUTDIR/programs.tsv  name, kind, first, last, display size, screenshot prefix, keys, env,
#                        then the command (tab-separated; scripts/corpus.sh runs them live)
#   OUTDIR/manifest.tsv  name, kind, status (ok, failed, skipped), first, last, frames in the
#                        capture, seconds, reason
# and prints the programs that failed to record, with the reason. Exit status 0 when every
# program was tried (failures are results), 1 on bad usage or a missing build.
set -Eeuo pipefail
# Once, after a game's recording, the script ended with status 1 and no word: say where.
trap 'echo "corpus-captures: stopped at line $LINENO by a failing command: $BASH_COMMAND" >&2' ERR

usage() {
    echo "usage: $0 OUTDIR [--quick]" >&2
    exit 1
}
[ $# -ge 1 ] || usage
out=$1
quick=0
shift
for arg in "$@"; do
    case $arg in
        --quick) quick=1 ;;
        *) usage ;;
    esac
done

root=$(cd "$(dirname "$0")/.." && pwd)
build=${NPRGL_BUILD:-$root/build}
nprgl=$build/bin/nprgl
if [ ! -x "$nprgl" ]; then
    echo "corpus-captures: no $nprgl (run scripts/build.sh, or set NPRGL_BUILD)" >&2
    exit 1
fi
if [ -z "$out" ] || [ "$(realpath -m "$out")" = / ]; then
    echo "corpus-captures: refusing to write into '$out'" >&2
    exit 1
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
mkdir -p "$out/logs" "$out/work"

# The packages: the two xscreensaver GL packages and the games the project already uses.
pkgs=(xscreensaver-gl xscreensaver-gl-extra openarena neverball extremetuxracer crack-attack
    foobillardplus billard-gl gl-117 xvfb xdotool x11-utils)
if [ "${CORPUS_NO_INSTALL:-0}" != 1 ] && ! dpkg -s "${pkgs[@]}" >/dev/null 2>&1; then
    sudo=""
    if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${pkgs[@]}"
fi

if [ "$quick" = 1 ]; then
    frames=${CORPUS_FRAMES:-4}
    geometry=${CORPUS_GEOMETRY:-320x240}
else
    frames=${CORPUS_FRAMES:-12}
    geometry=${CORPUS_GEOMETRY:-640x480}
fi
hack_limit=${CORPUS_LIMIT:-120}
game_limit=${CORPUS_LIMIT:-600}

programs=$out/programs.tsv
manifest=$out/manifest.tsv
: >"$programs"
: >"$manifest"

# One program: NAME KIND LAST SIZE PREFIX KEYS ENV -- COMMAND...  (ENV: "K=V K=V", may be
# empty; KEYS: "FRAME:KEY ..." sent once nprgl has written those frames' screenshots). In
# programs.tsv an empty field is "-" (tabs are whitespace to read: empty fields would vanish).
add_program() {
    local name=$1 kind=$2 last=$3 size=$4 prefix=$5 keys=$6 env=$7
    shift 7
    [ "$1" = "--" ] && shift
    local first=$((last - frames + 1))
    [ "$first" -ge 1 ] || first=1
    local IFS=$'\t'
    echo "$name	$kind	$first	$last	$size	$prefix	${keys:--}	${env:--}	$*" >>"$programs"
}

skip() { # NAME KIND REASON
    printf '%s\t%s\tskipped\t-\t-\t0\t0\t%s\n' "$1" "$2" "$3" >>"$manifest"
}

# Every executable both packages install under /usr/libexec/xscreensaver/, by name.
hacks=()
while IFS= read -r path; do
    [ -f "$path" ] && [ -x "$path" ] || continue
    hacks+=("$path")
done < <(dpkg -L xscreensaver-gl xscreensaver-gl-extra | grep '^/usr/libexec/xscreensaver/[^/]*$' |
    sort -u)
if [ "${#hacks[@]}" -eq 0 ]; then
    echo "corpus-captures: dpkg lists no hacks (are xscreensaver-gl and -extra installed?)" >&2
    exit 1
fi

# As xscreensaver runs them: their own folder first in PATH (mapscroller starts its helper
# mapscroller.pl by name).
hackdir=/usr/libexec/xscreensaver
index=0
for path in "${hacks[@]}"; do
    name=$(basename "$path")
    if ! head -c 4 "$path" | grep -q 'ELF'; then
        skip "$name" hack "not a GL program: not an executable (a helper script of another hack)"
        continue
    fi
    if [ "$name" = xscreensaver-gl-visual ]; then
        skip "$name" hack "not a hack: prints the GL visual for xscreensaver, draws nothing"
        continue
    fi
    index=$((index + 1))
    if [ "$quick" = 1 ] && [ $(((index - 1) % 4)) != 0 ]; then continue; fi
    add_program "$name" hack "$frames" 1280x1024 "$name" "" "PATH=$hackdir:$PATH" -- \
        "$path" -window -geometry "$geometry"
done

if [ "$quick" = 0 ]; then
    # The games, into their 3D scene as tests/compat/test_compat.cpp and docs/compat.md run
    # them. SDL programs draw with their second context (screenshots NAME_ctx2_N.png).
    add_program neverball game 100 1280x1024 neverball_ctx2 "" "" -- \
        /usr/games/neverball -l map-easy/coins.sol
    # Its own renderer 1 (fixed function); quits by itself after 800 engine frames.
    add_program openarena game 250 1280x1024 ioquake3_ctx2 "" "" -- \
        /usr/games/openarena +set r_mode -1 +set r_customwidth 640 +set r_customheight 480 \
        +set r_fullscreen 0 +set cl_renderer opengl1 +set s_initsound 0 +devmap oa_dm1 \
        +wait 800 +quit
    # Five Returns through its menus into a race; OpenAL's null device (no sound card).
    add_program extremetuxracer game 600 640x480 etr_ctx2 \
        "50:Return 100:Return 150:Return 200:Return 250:Return" "ALSOFT_DRIVERS=null" -- \
        /usr/games/etr
    add_program crack-attack game 600 1280x1024 crack-attack "100:Return" \
        "SDL_AUDIODRIVER=dummy" -- /usr/games/crack-attack --solo
    # Crashes by itself without USER; frame 300 is its intro's table.
    add_program foobillardplus game 300 1280x1024 foobillardplus "" "USER=root" -- \
        /usr/games/foobillardplus
    # Its attract mode (the computer plays).
    add_program billard-gl game 450 1280x1024 billard-gl "" "" -- /usr/games/billard-gl
    # Its intro and menu (a 3D aircraft; a mission needs clicks at places of its menu).
    add_program gl-117 game 300 1280x1024 gl-117 "" "" -- /usr/games/gl-117
fi

# Records one line of programs.tsv.
record() {
    local name=$1 kind=$2 first=$3 last=$4 size=$5 prefix=$6 keys=$7 env=$8
    shift 8
    [ "$keys" != - ] || keys=""
    [ "$env" != - ] || env=""
    local limit=$hack_limit
    [ "$kind" = game ] && limit=$game_limit
    local work=$out/work/$name
    rm -rf "$work"
    mkdir -p "$work/shots" "$work/home"
    rm -f "$out/$name.nprgl" "$out/$name".*.nprgl
    local shotframes="$((last + 1))" step
    for step in $keys; do shotframes="${step%%:*},$shotframes"; done
    local log=$out/logs/$name.record.log
    local envs=("HOME=$work/home" "WITH_DISPLAY_SIZE=$size")
    # shellcheck disable=SC2206
    [ -z "$env" ] || envs+=($env)
    local t0=$SECONDS
    env "${envs[@]}" timeout -k 10 $((limit + 60)) "$root/scripts/with-display.sh" 3<&- \
        "$root/scripts/corpus-run.sh" "$work/status" "$limit" "$work/shots" "$prefix" \
        "$((last + 1))" "$keys" -- \
        "$nprgl" record --style none --frames "$first-$last" -o "$out/$name.nprgl" \
        --screenshot "frames=$shotframes;dir=$work/shots" -- "$@" >"$log" 2>&1 || true
    local secs=$((SECONDS - t0))
    local outcome="none" rc="-"
    [ -s "$work/status" ] && read -r outcome rc _ <"$work/status"
    local count=0
    if [ -f "$out/$name.nprgl" ]; then
        # "frames: N  (context 1: A, context 2: B)": the longest context's frames.
        # A capture nprgl info cannot read counts 0 frames (and is reported below) rather
        # than ending the script.
        count=$({ "$nprgl" info "$out/$name.nprgl" 2>/dev/null || true; } |
            sed -n 's/^frames: *//p' | grep -o '[0-9][0-9]*' | sort -n | tail -n1 || true)
        count=${count:-0}
    fi
    local status=ok reason="-"
    case $outcome in
        reached | reached-killed) ;;
        ended)
            if [ "$count" -lt "$last" ]; then
                status=failed
                reason="ended by itself (status $rc) after $count frames"
            fi
            ;;
        hung)
            status=failed
            reason="hung: no frame $((last + 1)) in ${limit}s (killed; $count frames captured)"
            ;;
        *)
            status=failed
            reason="the run did not finish (timeout or display failure; see logs/$name.record.log)"
            ;;
    esac
    if [ "$status" = ok ] && [ "$count" -lt "$last" ]; then
        status=failed
        reason="the capture holds $count frames, fewer than $last"
    fi
    if [ "$status" = ok ] && ! "$nprgl" info "$out/$name.nprgl" >/dev/null 2>&1; then
        status=failed
        reason="the capture cannot be read (nprgl info)"
    fi
    if grep -q "nprgl: error" "$log"; then
        local err
        err=$(grep -m1 "nprgl: error" "$log" | tr '\t' ' ' | cut -c1-200)
        [ "$status" = ok ] && reason="logged: $err" || reason="$reason; logged: $err"
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$kind" "$status" "$first" "$last" \
        "$count" "$secs" "$reason" >>"$manifest"
    printf 'corpus-captures: %-18s %-7s %3s frames %4ss %s\n' "$name" "$status" "$count" "$secs" \
        "$([ "$reason" = - ] || echo "$reason")"
}

# fd 3: the programs get the script's stdin, not the list.
while IFS=$'\t' read -r -u 3 -a row; do
    record "${row[@]}"
done 3<"$programs"
rm -rf "$out/work"/*/home

failed=$(awk -F'\t' '$3 == "failed"' "$manifest")
ok=$(awk -F'\t' '$3 == "ok"' "$manifest" | wc -l)
echo "corpus-captures: $ok programs recorded into $out"
if [ -n "$failed" ]; then
    echo "corpus-captures: failed to record:"
    echo "$failed" | awk -F'\t' '{ printf "  %-18s %s\n", $1, $8 }'
fi
awk -F'\t' '$3 == "skipped" { printf "corpus-captures: skipped %s: %s\n", $1, $8 }' "$manifest"
