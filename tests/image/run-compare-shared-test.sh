#!/bin/sh
# run-compare-shared-test.sh: a damaged snapshot image costs only the
# comparison of the frames that share it (issue 12.3).
#
#   run-compare-shared-test.sh RAYGL_COMPARE RAYGL2POV POVRAY MKHOSTILE OUTDIR
#
# mkhostile's snapshots.raygl: four frames, frame 0 with its own snapshot
# image, frames 1-3 sharing one. Intact: all four compared, exit 0. The
# shared image damaged: frame 0 still compared, one message for the image
# naming its three frames, exit 1; raygl2pov still translates all four.
set -u
[ $# -eq 5 ] || { echo "usage: $0 RAYGL_COMPARE RAYGL2POV POVRAY MKHOSTILE OUTDIR" >&2; exit 2; }
cmp=$1 r2p=$2 povray=$3 mk=$4 out=$5
fail() { echo "compare-shared test: FAIL: $*"; exit 1; }
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    */*) printf '%s/%s\n' "$PWD" "$1" ;;
    *) printf '%s\n' "$1" ;;
    esac
}
cmp=$(absolute "$cmp") r2p=$(absolute "$r2p") povray=$(absolute "$povray") mk=$(absolute "$mk")
rm -rf "$out"
mkdir -p "$out" || exit 1
cd "$out" || exit 1
"$mk" . >spans || fail "mkhostile"
set -- $(sed -n 's/^shared-image //p' spans)
[ $# -eq 2 ] || fail "no shared image span"

"$cmp" snapshots.raygl -o ok --raygl2pov "$r2p" --povray "$povray" >ok.log 2>&1
[ $? -eq 0 ] || { cat ok.log; fail "intact trace"; }
[ "$(grep -c '^frame [0-3]: 8x6 within' ok.log)" -eq 4 ] || { cat ok.log; fail "four frames compared"; }

cp snapshots.raygl damaged.raygl
b=$(od -An -tu1 -j $(($1 + 4)) -N1 snapshots.raygl | tr -d ' ')
printf "\\$(printf %o $((b ^ 0x55)))" | dd of=damaged.raygl bs=1 seek=$(($1 + 4)) conv=notrunc 2>/dev/null
"$cmp" damaged.raygl -o dmg --raygl2pov "$r2p" --povray "$povray" >dmg.out 2>dmg.err
rc=$?
[ "$rc" -eq 1 ] || { cat dmg.out dmg.err; fail "damaged shared image: exit $rc, expected 1"; }
grep -q '^frame 0: 8x6 within' dmg.out || { cat dmg.out; fail "frame 0 not compared"; }
grep -q '^frame [1-3]' dmg.out && { cat dmg.out; fail "a frame of the damaged image compared"; }
[ "$(grep -c '@Snapshot image' dmg.err)" -eq 1 ] || { cat dmg.err; fail "the image not said once"; }
grep -q '^raygl-compare: damaged.raygl: frame 1, @Snapshot image #2 @0x[0-9a-f]*: checksum mismatch: .*: 3 frames from 1 to 3 not compared$' dmg.err ||
    { cat dmg.err; fail "message"; }
"$r2p" damaged.raygl -o r2p >r2p.log 2>&1
[ $? -eq 0 ] && [ -s r2p/frame-00003.pov ] || { cat r2p.log; fail "raygl2pov lost a frame to the snapshot"; }
echo "compare-shared test: ok"
