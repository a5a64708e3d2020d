#!/bin/sh
# test-figures.sh: the figures file's check fails when it should.
#
#   test-figures.sh UPDATE_FIGURES OUTDIR [IMAGE-PROG FRAMES-PROG R2P POVRAY IMGCMP]
#
# 1. check-figures.sh on fake files: a figure within the margin passes, one
#    below it fails, a better one passes and is reported, a test with no
#    line or another tolerance fails; a margin of a line's own; --frames
#    and --names on lines past a program's frames, of no test, twice, or
#    malformed.
# 2. tools/update-figures.py on a fake log: nothing written without a
#    reason; then new and moved lines take it, the others keep theirs; a
#    line with its own margin moves only beyond it; --raise-only.
# 3. With the programs given: run-image-test.sh and run-frames-test.sh
#    (flat_colors, proj_hud at 0/255) fail on a file whose figures they cannot hold,
#    whose line is missing or that has a line for a frame they do not draw,
#    and pass on one they hold.
set -u
[ $# -eq 2 ] || [ $# -eq 7 ] || {
    echo "usage: $0 UPDATE_FIGURES OUTDIR [IMAGE-PROG FRAMES-PROG R2P POVRAY IMGCMP]" >&2
    exit 2
}
here=$(cd "$(dirname "$0")" && pwd) || exit 1
check=$here/check-figures.sh
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    *) printf '%s/%s\n' "$PWD" "$1" ;;
    esac
}
update=$(absolute "$1") out=$(absolute "$2")
shift 2
paths=
for p in "$@"; do
    paths="$paths $(absolute "$p")"
done
# shellcheck disable=SC2086 # meson's paths have no spaces
set -- $paths
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# expect STATUS PATTERN CMD...: CMD exits STATUS and prints PATTERN (grep -E;
# "" for any output).
expect() {
    st=$1 pat=$2
    shift 2
    "$@" >got.log 2>&1
    rc=$?
    if [ $rc -ne "$st" ]; then
        fail "$* exited $rc, expected $st"
        sed 's/^/    /' got.log
    elif [ -n "$pat" ] && ! grep -Eq -- "$pat" got.log; then
        fail "$* did not say /$pat/"
        sed 's/^/    /' got.log
    fi
}

# 1. The check.
cat >fig.txt <<'EOF'
# a comment, and a blank line

t1 2 0.99000 0.98000 - the first reason
anim 8 0.98900 0.99990 0.02 animated: floors 0.969, 0.9799
f/0 8 0.97000 0.96000 - frames
f/1 8 0.97000 0.96000 - frames
f/2 8 0.97000 0.96000 - frames
EOF
expect 0 '^figures: t1 tol 2 within 0.99000 silhouette 0.98000$' "$check" fig.txt t1 2 0.99000 0.98000
grep -q improved got.log && fail "equal figures reported as improved"
expect 0 '' "$check" fig.txt t1 2 0.98991 0.97991
grep -q 'FAIL\|improved' got.log && fail "a drop within the margin said something"
expect 1 'FAIL: within 2/255 0.98980 is 0.00020 below' "$check" fig.txt t1 2 0.98980 0.98000
expect 1 'FAIL: silhouette 0.90000' "$check" fig.txt t1 2 0.99000 0.90000
expect 0 'improved: within 2/255 0.99500 above' "$check" fig.txt t1 2 0.99500 0.98000
expect 0 'improved: silhouette 1.00000 above' "$check" fig.txt t1 2 0.99000 1.00000
expect 1 'holds figures within 2/255, the test measures within 4/255' "$check" fig.txt t1 4 0.99000 0.98000
expect 1 't2: FAIL: no line in fig.txt' "$check" fig.txt t2 2 1.0 1.0
expect 0 '' "$check" fig.txt anim 8 0.97000 0.98000
expect 0 '' "$check" fig.txt anim 8 0.99900 1.00000
grep -q improved got.log && fail "a line with a margin of its own reported an improvement"
expect 1 'FAIL: within 8/255 0.96800' "$check" fig.txt anim 8 0.96800 0.99990
expect 0 '' "$check" fig.txt f/2 8 0.97000 0.96000
expect 0 '' "$check" --frames fig.txt f 3
expect 1 'a line for frame 2, the program drew 2 frames' "$check" --frames fig.txt f 2
expect 0 '' "$check" --frames fig.txt t1 1
expect 0 '' "$check" --names fig.txt t1 anim f
expect 1 'a line for anim, which is no test' "$check" --names fig.txt t1 f
expect 1 'a line for f/0, which is no test' "$check" --names fig.txt t1 anim
cp fig.txt bad.txt
echo 't1 2 0.99 0.98 - twice' >>bad.txt
echo 'short 2 0.99 0.98 -' >>bad.txt
echo 'big 2 1.5 0.98 - out of range' >>bad.txt
echo 'odd 2 0.9 0.9 x bad margin' >>bad.txt
expect 1 't1 again \(line 3\)' "$check" --names bad.txt t1 anim f short big odd
for p in 'short: fewer than 6 fields|fewer than 6 fields' 'big: figures not in 0..1' 'odd: bad margin x'; do
    grep -Eq "$p" got.log || fail "--names did not say /$p/"
done
expect 1 'odd: bad margin' "$check" bad.txt odd 2 0.9 0.9
expect 2 'usage' "$check" fig.txt t1 2
expect 2 'cannot read' "$check" missing.txt t1 2 0.9 0.9

# 2. The rewrite.
cat >run.log <<'EOF'
figures: t1 tol 2 within 0.98500 silhouette 0.98000
some other output
figures: anim tol 8 within 0.99500 silhouette 0.99990
figures: f/0 tol 8 within 0.97000 silhouette 0.96000
figures: f/1 tol 8 within 0.98000 silhouette 0.96000
figures: new tol 4 within 0.95000 silhouette 1.00000
EOF
cat >run2.log <<'EOF'
figures: f/0 tol 8 within 0.96900 silhouette 0.96000
EOF
cp fig.txt up.txt
expect 1 'give --reason' "$update" --file up.txt run.log run2.log
cmp -s fig.txt up.txt || fail "update-figures.py without --reason changed the file"
expect 0 'f/0: tol 8 within 0.97000 silhouette 0.96000 -> tol 8 within 0.96900' \
    "$update" --file up.txt --reason 'a reason' run.log run2.log
cat >want.txt <<'EOF'
# a comment, and a blank line

anim 8 0.98900 0.99990 0.02 animated: floors 0.969, 0.9799
f/0 8 0.96900 0.96000 - a reason
f/1 8 0.98000 0.96000 - a reason
f/2 8 0.97000 0.96000 - frames
new 4 0.95000 1.00000 - a reason
t1 2 0.98500 0.98000 - a reason
EOF
cmp -s want.txt up.txt || { fail "update-figures.py wrote"; diff want.txt up.txt | sed 's/^/    /'; }
expect 0 'holds the figures' "$update" --file up.txt run.log run2.log
cp fig.txt up.txt
expect 0 '' "$update" --file up.txt --raise-only --reason 'raised' run.log
grep -q '^t1 2 0.99000 0.98000 - the first reason$' up.txt || fail "--raise-only lowered t1"
grep -q '^f/1 8 0.98000 0.96000 - raised$' up.txt || fail "--raise-only did not raise f/1"
grep -q '^anim 8 0.98900 0.99990 0.02 animated' up.txt || fail "--raise-only raised anim"
echo 'figures: anim tol 8 within 0.96000 silhouette 0.99995' >low.log
expect 0 'anim: tol 8 within 0.98900 silhouette 0.99990 -> tol 8 within 0.96000 silhouette 0.99990' \
    "$update" --file up.txt --reason 'lower' low.log
expect 1 'no "figures:" lines' "$update" --file up.txt fig.txt
expect 1 'malformed line' "$update" --file bad.txt run.log

# 3. Through the drivers.
if [ $# -eq 5 ]; then
    iprog=$1 fprog=$2 r2p=$3 povray=$4 imgcmp=$5
    image() {
        "$here/run-image-test.sh" --name flat_colors --program "$iprog" --raygl2pov "$r2p" \
            --povray "$povray" --imgcmp "$imgcmp" --outdir "$out/runs" --figures "$1" \
            -- --tol 2 --min-match 0.99
    }
    frames() {
        "$here/run-frames-test.sh" --name proj_hud --program "$fprog" --raygl2pov "$r2p" \
            --povray "$povray" --imgcmp "$imgcmp" --outdir "$out/runs" --figures "$1" \
            --r2p-opt --no-shadows -- --tol 0
    }
    echo 'flat_colors 2 1.00000 1.00000 0 more than it holds' >high.txt
    expect 1 'flat_colors: FAIL: within 2/255 0\.[0-9]* is 0\.[0-9]* below' image high.txt
    grep -q 'image test flat_colors: FAIL: the figures do not hold' got.log ||
        fail "run-image-test.sh did not fail on the figures"
    echo 'other 2 1.00000 1.00000 - another test' >none.txt
    expect 1 'flat_colors: FAIL: no line' image none.txt
    # The figures it measured, as the file's: passes.
    sed -n 's/^figures: flat_colors tol \([0-9]*\) within \([0-9.]*\) silhouette \([0-9.]*\)$/flat_colors \1 \2 \3 - measured/p' \
        "$out/got.log" >held.txt
    [ -s held.txt ] || fail "run-image-test.sh printed no figures line"
    expect 0 'image test flat_colors: PASS' image held.txt
    : >fhigh.txt
    for k in 0 1 2 3 4 5 6 7; do
        echo "proj_hud/$k 0 1.00000 1.00000 0 more than it holds" >>fhigh.txt
    done
    echo 'proj_hud/99 8 0.5 0.5 - a frame it does not draw' >>fhigh.txt
    # At 0/255 its frames are not exact (at 8/255 they are).
    expect 1 'proj_hud/0: FAIL: within 0/255' frames fhigh.txt
    grep -q 'a line for frame 99' got.log || fail "run-frames-test.sh kept a line past the last frame"
    grep -q 'frames proj_hud: FAIL: the figures do not hold' got.log ||
        fail "run-frames-test.sh did not fail on the figures"
fi

[ $failed -eq 0 ] && echo "figures check: PASS"
exit $failed
