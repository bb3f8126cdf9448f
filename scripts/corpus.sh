#!/usr/bin/env bash
# The corpus benchmark in one command from a fresh clone: installs, builds, records every Debian GL hack and the games, compares each in replica and the default style, runs each live under every preset, writes docs/compat.md.
#
# Usage: scripts/corpus.sh [OUTDIR] [--quick] [--no-record] [--no-compare] [--no-live]
#                          [--no-install] [--no-build] [--no-doc] [--live-resume]
#   OUTDIR      where captures and results go (default: build/corpus in this clone)
#   --quick     the small regression set of scripts/corpus-captures.sh (32 hacks, 4 frames)
#   --no-record, --no-compare, --no-live  skip a step, keeping what an earlier run left in
#               OUTDIR (captures and manifest, results/, live.tsv) for the report
#   --no-install, --no-build  skip scripts/install-deps.sh, scripts/build.sh (a clone set up)
#   --no-doc    write the report to OUTDIR/compat.md only, not docs/compat.md
#   --live-resume  keep OUTDIR/live.tsv and run live only the programs it does not have yet
#               (the live step takes hours on the whole corpus; a stopped run goes on)
# CORPUS_LIVE_GAME_FRAMES=N runs the games live for N frames (default: to their scene's frame).
# CORPUS_COMPARE_FRAMES=N compares only the last N recorded frames of each capture.
#
# Steps:
#   1. scripts/install-deps.sh, scripts/build.sh (NPRGL_BUILD, default build/ in the clone);
#   2. scripts/corpus-captures.sh OUTDIR: the captures (OUTDIR/manifest.tsv says which);
#   3. per capture, over its recorded frames: `nprgl compare --style replica` and
#      `nprgl compare` (the default style), each with --json and -o (diff pictures), and
#      `nprgl replay --stats` (the default style's styled/left counts), and the GL features
#      its stream uses (scripts/corpus-features.py), into OUTDIR/results/;
#   4. live: each program run natively (stopped after a few seconds: its status when
#      stopped, or when it ends by itself), then under `nprgl --preset P` for every preset
#      `nprgl styles` lists, until nprgl's screenshot of its frame (a hack's 5th, a game's
#      scene frame) exists, then stopped as natively; a crash (status unlike native's), a
#      hang (no frame within the limit) or an nprgl error is a failure (OUTDIR/live.tsv);
#   5. scripts/corpus-report.py writes docs/compat.md (and OUTDIR/compat.md) from them.
# Writes only in OUTDIR, the build directory and docs/compat.md.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=""
quick=0 record=1 compare=1 live=1 install=1 build_it=1 doc=1 resume=0
for arg in "$@"; do
    case $arg in
        --quick) quick=1 ;;
        --no-record) record=0 ;;
        --no-compare) compare=0 ;;
        --no-live) live=0 ;;
        --no-install) install=0 ;;
        --no-build) build_it=0 ;;
        --no-doc) doc=0 ;;
        --live-resume) resume=1 ;;
        -*)
            echo "usage: $0 [OUTDIR] [--quick] [--no-record] [--no-compare] [--no-live]" \
                "[--no-install] [--no-build] [--no-doc] [--live-resume]" >&2
            exit 1
            ;;
        *) out=$arg ;;
    esac
done
build=${NPRGL_BUILD:-$root/build}
out=${out:-$build/corpus}
if [ "$(realpath -m "$out")" = / ]; then
    echo "corpus: refusing to write into /" >&2
    exit 1
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
nprgl=$build/bin/nprgl
log() { echo "corpus: $*" >&2; }

if [ "$install" = 1 ]; then
    "$root/scripts/install-deps.sh"
fi
if [ "$build_it" = 1 ]; then
    "$root/scripts/build.sh" "$build"
fi

if [ ! -x "$nprgl" ]; then
    log "no $nprgl (build first, or set NPRGL_BUILD to a build directory)"
    exit 1
fi

captures_args=("$out")
[ "$quick" = 0 ] || captures_args+=(--quick)
[ "$install" = 1 ] || export CORPUS_NO_INSTALL=1
if [ "$record" = 1 ]; then
    NPRGL_BUILD=$build "$root/scripts/corpus-captures.sh" "${captures_args[@]}"
elif [ ! -s "$out/manifest.tsv" ]; then
    log "--no-record: $out holds no captures (no manifest.tsv)"
    exit 1
fi

# --- compare ---------------------------------------------------------------------------------
results=$out/results
mkdir -p "$results"
compare_limit=${CORPUS_COMPARE_LIMIT:-1800}
if [ "$compare" = 1 ] && ! "$nprgl" compare --help >/dev/null 2>&1; then
    log "this nprgl has no 'compare' command: fidelity columns will be empty"
fi
[ "$compare" = 0 ] || : >"$results/runs.tsv"
# The loops read their lists on fd 3: the programs and nprgl get the script's stdin.
while [ "$compare" = 1 ] && IFS=$'\t' read -r -u 3 name kind status first last _; do
    [ "$status" = ok ] || continue
    capture=$out/$name.nprgl
    # CORPUS_COMPARE_FRAMES=N: only the last N recorded frames (a quicker run).
    keep=${CORPUS_COMPARE_FRAMES:-0}
    if [ "$keep" -gt 0 ] && [ "$((last - keep + 1))" -gt "$first" ]; then
        first=$((last - keep + 1))
    fi
    for style in replica default; do
        rm -rf "${results:?}/$name/$style"
        mkdir -p "$results/$name/$style"
        args=()
        [ "$style" = default ] || args=(--style "$style")
        rc=0
        timeout -k 10 "$compare_limit" "$nprgl" compare "$capture" "${args[@]}" \
            --frames "$first-$last" --json "$results/$name.$style.json" \
            -o "$results/$name/$style" >"$results/$name.$style.txt" 2>&1 || rc=$?
        printf '%s\tcompare-%s\t%s\n' "$name" "$style" "$rc" >>"$results/runs.tsv"
        log "$name: compare $style: $(tail -n1 "$results/$name.$style.txt") (status $rc)"
    done
    python3 "$root/scripts/corpus-features.py" "$nprgl" "$capture" --frames "$first-$last" \
        >"$results/$name.features.txt" 2>/dev/null || true
    rc=0
    timeout -k 10 "$compare_limit" "$nprgl" replay "$capture" --stats --frames "$first-$last" \
        >"$results/$name.stats.txt" \
        2>"$results/$name.stats.log" || rc=$?
    printf '%s\tstats\t%s\n' "$name" "$rc" >>"$results/runs.tsv"
done 3<"$out/manifest.tsv"

# --- live under every preset -----------------------------------------------------------------
live_tsv=$out/live.tsv
if [ "$live" = 1 ]; then
    [ "$resume" = 1 ] && [ -f "$live_tsv" ] || : >"$live_tsv"
    mapfile -t presets < <("$nprgl" styles | awk '/^Presets/ { p = 1; next }
        p && /^    [a-z]/ { print $1 }')
    if [ "${#presets[@]}" -eq 0 ]; then
        log "'nprgl styles' lists no presets"
        exit 1
    fi
    log "live runs under ${#presets[@]} presets: ${presets[*]}"
    live_frames=${CORPUS_LIVE_FRAMES:-5}
    native_hack=${CORPUS_NATIVE_SECONDS:-5}
    native_game=${CORPUS_NATIVE_GAME_SECONDS:-60}
    hack_limit=${CORPUS_LIMIT:-120}
    game_limit=${CORPUS_LIMIT:-600}
    while IFS=$'\t' read -r -u 3 -a row; do
        name=${row[0]} kind=${row[1]} last=${row[3]} size=${row[4]} prefix=${row[5]}
        keys=${row[6]} env=${row[7]}
        [ "$keys" != - ] || keys=""
        [ "$env" != - ] || env=""
        command=("${row[@]:8}")
        if [ "$resume" = 1 ]; then
            # Done: a row for native and every preset. A partial run is run again.
            rows=$(awk -F'\t' -v n="$name" '$1 == n' "$live_tsv" | wc -l)
            [ "$rows" -lt $((${#presets[@]} + 1)) ] || continue
            awk -F'\t' -v n="$name" '$1 != n' "$live_tsv" >"$live_tsv.tmp"
            mv "$live_tsv.tmp" "$live_tsv"
        fi
        work=$out/live/$name
        rm -rf "$work"
        mkdir -p "$work"
        if [ "$kind" = game ]; then
            frame=${CORPUS_LIVE_GAME_FRAMES:-$last} limit=$game_limit native=$native_game
        else
            frame=$live_frames limit=$hack_limit native=$native_hack
        fi
        for preset in native "${presets[@]}"; do
            mkdir -p "$work/$preset/shots" "$work/$preset/home"
            envs=("HOME=$work/$preset/home" "WITH_DISPLAY_SIZE=$size")
            # shellcheck disable=SC2206
            [ -z "$env" ] || envs+=($env)
            to_end=0
            if [ "$preset" = native ]; then
                # No screenshots natively: keys cannot be timed, the run is stopped by time.
                run=(0 "" -- "${command[@]}")
                run_limit=$native
            else
                shotframes=$frame
                for step in $keys; do shotframes="${step%%:*},$shotframes"; done
                run=("$frame" "$keys" -- "$nprgl" --preset "$preset"
                    --screenshot "frames=$shotframes;dir=$work/$preset/shots" -- "${command[@]}")
                run_limit=$limit
                # A program that ends by itself natively (a timed demo) runs to its end
                # styled too: its exit status is then its own, not the stop's.
                native_outcome=$(awk -F'\t' -v n="$name" '$1 == n && $2 == "native" { print $3 }' \
                    "$live_tsv")
                [ "$native_outcome" != ended ] || to_end=1
            fi
            env "${envs[@]}" RUN_TO_END=$to_end timeout -k 10 $((run_limit + 60)) "$root/scripts/with-display.sh" 3<&- \
                "$root/scripts/corpus-run.sh" "$work/$preset/status" "$run_limit" \
                "$work/$preset/shots" "$prefix" "${run[@]}" >"$work/$preset/log" 2>&1 || true
            outcome=none rc=- secs=0
            [ -s "$work/$preset/status" ] && read -r outcome rc secs <"$work/$preset/status"
            errors=$(grep -c "nprgl: error" "$work/$preset/log" || true)
            printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$preset" "$outcome" "$rc" "$secs" \
                "$errors" >>"$live_tsv"
            rm -rf "$work/$preset/home"
        done
        log "$name: live: $(awk -F'\t' -v n="$name" '$1 == n { printf "%s %s/%s ", $2, $3, $4 }' \
            "$live_tsv")"
    done 3<"$out/programs.tsv"
fi

# --- the report ------------------------------------------------------------------------------
report_args=("$out" --output "$out/compat.md")
[ "$doc" = 0 ] || report_args+=(--doc "$root/docs/compat.md")
python3 "$root/scripts/corpus-report.py" "${report_args[@]}"
log "report: $out/compat.md$([ "$doc" = 0 ] || echo " and docs/compat.md")"
