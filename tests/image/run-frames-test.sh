#!/bin/sh
# run-frames-test.sh: every frame of a multi-frame program (real.h), GL frame
# against POV-Ray frame.
#
#   run-frames-test.sh --name NAME --program PROG --raygl2pov R2P --povray POVRAY
#                      --imgcmp IMGCMP --outdir DIR [--size WxH] [--r2p-opt OPT]...
#                      [--r2p-says nothing|REGEX]... [--figures FILE] [-- IMGCMP-OPTIONS...]
#
# 1. PROG --trace DIR/NAME/NAME.raygl --png-dir DIR/NAME [--size WxH] draws
#    the frames with OSMesa (DIR/NAME/gl-NNNNN.png);
# 2. for each frame N: R2P NAME.raygl -o pov --frames N [OPT...], so that
#    the notes said are that frame's (raygl2pov says each note once a run);
# 3. POVRAY pov/frame-NNNNN.ini -D -A;
# 4. IMGCMP [IMGCMP-OPTIONS] gl-NNNNN.png pov/frame-NNNNN.png;
# 5. with --figures FILE, check-figures.sh holds each frame's figures to
#    FILE's line NAME/N, and FILE may have no line for a frame past the last.
#
# Prints one line per frame:
#   frame N: PASS|FAIL within W silhouette S note yes|no
# then "frames NAME: P of T pass". With --r2p-says, the frames' messages
# must be nothing or match (image-test-args.sh). Exit 0 when every frame
# passes (and its figures hold), 1 otherwise or when a step fails, 2 on bad
# usage.
set -u
usage() {
    echo "usage: $0 --name NAME --program PROG --raygl2pov R2P --povray POVRAY --imgcmp IMGCMP --outdir DIR [--size WxH] [--r2p-opt OPT]... [--r2p-says nothing|REGEX]... [--figures FILE] [-- IMGCMP-OPTIONS...]" >&2
    exit 2
}
. "$(dirname "$0")/image-test-args.sh"
while [ $# -gt 0 ]; do
    case $1 in
    --) shift; break ;;
    esac
    common_option "$@" || usage
    shift 2
done
common_finish

fail() {
    echo "frames $name: FAIL: $*"
    exit 1
}
dir=$outdir/$name
if ! rm -rf "$dir" || ! mkdir -p "$dir/pov"; then
    fail "cannot create $dir"
fi
echo "frames $name: $dir"

if [ -n "$size" ]; then
    "$prog" --trace "$dir/$name.raygl" --png-dir "$dir" --size "$size" >"$dir/program.log" 2>&1
else
    "$prog" --trace "$dir/$name.raygl" --png-dir "$dir" >"$dir/program.log" 2>&1
fi
rc=$?
[ $rc -eq 0 ] || { sed -n '1,20p' "$dir/program.log"; fail "the program exited with $rc"; }
nframes=0
for png in "$dir"/gl-[0-9]*.png; do
    [ -f "$png" ] && nframes=$((nframes + 1))
done
[ "$nframes" -gt 0 ] || fail "the program wrote no frame"

pass=0
n=0
figures_bad=0
check=$(dirname "$0")/check-figures.sh
while [ $n -lt "$nframes" ]; do
    f=$(printf '%05d' $n)
    # shellcheck disable=SC2086 # r2p_opts: words checked above, split on purpose
    (cd "$dir" && "$r2p" "$name.raygl" -o pov --frames $n $r2p_opts) >"$dir/raygl2pov-$f.log" 2>&1
    rc=$?
    [ $rc -eq 0 ] || { sed -n '1,20p' "$dir/raygl2pov-$f.log"; fail "raygl2pov exited with $rc on frame $n"; }
    note=no
    grep -q 'approximated\|not translated\|left out' "$dir/raygl2pov-$f.log" && note=yes
    (cd "$dir" && "$povray" "pov/frame-$f.ini" -D -A) >"$dir/povray-$f.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ] && grep -q "Timed out waiting for worker thread startup" "$dir/povray-$f.log"; then
        (cd "$dir" && "$povray" "pov/frame-$f.ini" -D -A) >"$dir/povray-$f.log" 2>&1
        rc=$?
    fi
    if [ $rc -ne 0 ] || [ ! -s "$dir/pov/frame-$f.png" ]; then
        sed -n '1,20p' "$dir/povray-$f.log"
        fail "povray exited with $rc on frame $n"
    fi
    "$imgcmp" "$@" --diff "$dir/diff-$f.png" "$dir/gl-$f.png" "$dir/pov/frame-$f.png" \
        >"$dir/imgcmp-$f.log" 2>&1
    rc=$?
    within=$(sed -n 's/^within [0-9]*\/255: \([0-9.]*\).*/\1/p' "$dir/imgcmp-$f.log")
    sil=$(sed -n 's/^silhouette: \([0-9.]*\).*/\1/p' "$dir/imgcmp-$f.log")
    if [ $rc -eq 0 ]; then
        verdict=PASS
        pass=$((pass + 1))
    else
        verdict=FAIL
    fi
    echo "frame $n: $verdict within ${within:-?} silhouette ${sil:-?} note $note"
    if [ $verdict = FAIL ] && [ $note = yes ]; then
        grep 'approximated\|not translated\|left out' "$dir/raygl2pov-$f.log" | sed 's/^/    /'
    fi
    measured=$(figures_of "$dir/imgcmp-$f.log")
    if [ -n "$figures" ] && [ -n "$measured" ]; then
        # shellcheck disable=SC2086 # three words on purpose
        "$check" "$figures" "$name/$n" $measured || figures_bad=1
    fi
    n=$((n + 1))
done
if [ -n "$figures" ]; then
    "$check" --frames "$figures" "$name" "$nframes" || figures_bad=1
fi
echo "frames $name: $pass of $nframes pass"
said=ok
r2p_says_check "$dir"/raygl2pov-[0-9]*.log || said=bad
[ $figures_bad -eq 0 ] || echo "frames $name: FAIL: the figures do not hold to $figures (above)"
[ $pass -eq "$nframes" ] && [ $said = ok ] && [ $figures_bad -eq 0 ]
