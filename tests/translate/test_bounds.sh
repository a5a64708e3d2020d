#!/bin/sh
# test_bounds.sh: raygl2pov on hostile traces (issue 12).
#
#   test_bounds.sh RAYGL2POV MKHOSTILE
#
# 1. Display-list bombs (mkhostile.c) finish under a 1 GiB address-space
#    cap and a time limit, write their frame, and say when it was cut, in
#    the messages and in the .pov; an honest trace that draws one texture
#    10240 times is not cut, and --dump shows it counted once; two frames that fill every budget just
#    short of a cut fit too, and give the same bytes with -j 2 (one heavy
#    frame at a time); a heavy frame translated twice (heavy-redo) is
#    not held up by its own turn.
# 2. Damage: a damaged list body gives exit 1 and names the part the frame
#    was written without; every one-byte change of a small trace with
#    lists either leaves every frame as it was with exit 0, or exits 1 and
#    says so (never a silent loss, never a damage message with exit 0).
# 3. A damaged snapshot image costs no frame of the translation.
# 4. A trace that was not closed (cut between frames or inside one) is
#    said once as a note, exit status 0.
set -u
abs() { (cd "$(dirname "$1")" && echo "$(pwd)/$(basename "$1")"); }
r2p=$(abs "$1")
mk=$(abs "$2")
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-bounds.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
ok() { echo "ok: $*"; }

"$mk" "$work" >"$work/spans" || { echo "mkhostile failed"; exit 1; }
span() { sed -n "s/^$1 //p" "$work/spans"; }

# Sanitizer builds reserve terabytes of address space: no cap there.
capped=true
if ldd "$r2p" 2>/dev/null | grep -q 'libasan\|libtsan'; then
    capped=false
    echo "note: sanitizer build: list bombs run without the address-space cap"
fi

# ---- 1. list bombs
# name, the budget line expected ("" when the call cap stops it first)
while read -r b want; do
    rm -rf "$work/o"
    (
        [ "$capped" = false ] || ulimit -v 1048576
        exec timeout 120 "$r2p" "$work/$b.raygl" -o "$work/o" -j 1
    ) >"$work/out" 2>"$work/err"
    rc=$?
    if [ "$rc" -ne 0 ]; then
        fail "$b: exit $rc under a 1 GiB cap: $(tail -n 3 "$work/err")"
        continue
    fi
    [ -s "$work/o/frame-00000.pov" ] || fail "$b: no frame-00000.pov"
    if [ -n "$want" ]; then
        grep -q "raygl2pov: .*$b.raygl: frame 0: cut at @0x[0-9a-f]* (in a display list): over the frame budget of $want; the rest of the frame is not translated" "$work/err" ||
            fail "$b: no cut note for '$want': $(cat "$work/err")"
        grep -q "^// Incomplete: cut at @0x[0-9a-f]* (in a display list): over the frame budget of $want" \
            "$work/o/frame-00000.pov" || fail "$b: the .pov does not say it was cut"
        [ "$(grep -c 'cut at' "$work/err")" -eq 1 ] || fail "$b: the cut said more than once"
    else
        grep -q "cut at" "$work/err" && fail "$b: cut, but within the budget"
        grep -q "Incomplete" "$work/o/frame-00000.pov" && fail "$b: marked incomplete"
    fi
    ok "$b: translated under the cap${want:+, cut at $want}"
done <<EOF
bomb-3
bomb-30 4194304 vertices
bomb-300 4194304 vertices
bomb-lines 1048576 lines and points
bomb-solid 262144 solids
bomb-empty 67108864 commands run
bomb-texture 268435456 texture bytes
bomb-slices 268435456 texture bytes
honest-texture
bomb-names 67108864 commands run
bomb-calls300 16777216 vertices assembled
bomb-calls
fill-all
EOF
# fill-all's two frames are each as heavy as a frame may be: with -j 2
# they take turns (interp_set_heavy) and give the same bytes as -j 1.
mv "$work/o" "$work/o1"
"$r2p" "$work/fill-all.raygl" -o "$work/o" -j 2 >/dev/null 2>&1
rc=$?
for f in frame-00000.pov frame-00001.pov; do
    cmp -s "$work/o/$f" "$work/o1/$f" || fail "fill-all: $f differs with -j 2 (exit $rc)"
done
[ "$rc" -eq 0 ] && ok "fill-all: -j 2 gives the same bytes"
rm -rf "$work/o1"
# One texture drawn by 10240 triangles is counted once (issue 22): the
# upload read (65536 bytes) and held with its levels (349524), and one
# copy of the levels in the scene (349524); --dump says what it used.
"$r2p" "$work/honest-texture.raygl" -o "$work/o" -j 1 --dump -q >"$work/out" 2>&1
used=$(sed -n 's/^frame 0: budget: .*, texture bytes \([0-9]*\) of 268435456$/\1/p' "$work/out")
if [ -n "$used" ] && [ "$used" -le 1048576 ] &&
    grep -q "^frame 0: budget: .* triangles 10240 of 4194304," "$work/out"; then
    ok "honest-texture: 10240 draws of one texture use $used texture bytes"
else
    fail "honest-texture: budget line: $(grep budget "$work/out")"
fi
# A heavy frame translated twice (a first draw of another projection)
# takes the heavy turn once: the second pass once waited for the turn it
# held itself, for ever.
for j in 1 2; do
    rm -rf "$work/o"
    timeout 120 "$r2p" "$work/heavy-redo.raygl" -o "$work/o" -j $j >/dev/null 2>"$work/err"
    rc=$?
    [ "$rc" -eq 0 ] && [ -s "$work/o/frame-00000.pov" ] && ok "heavy-redo: -j $j, translated" ||
        fail "heavy-redo: -j $j, exit $rc (124: hung): $(tail -n 3 "$work/err")"
done
# A cut is a note: --quiet hides it, and the exit status stays 0.
"$r2p" "$work/bomb-30.raygl" -o "$work/o" -q 2>"$work/err"
rc=$?
[ "$rc" -eq 0 ] && [ ! -s "$work/err" ] && ok "--quiet: a cut frame says nothing" ||
    fail "--quiet on a cut frame: exit $rc, $(cat "$work/err")"

# ---- 2. damage
# Changes byte $2 of file $1 (xor 0x55) into file $3.
flip() {
    cp "$1" "$3"
    b=$(od -An -tu1 -j "$2" -N1 "$1" | tr -d ' ')
    printf "\\$(printf %o $((b ^ 0x55)))" | dd of="$3" bs=1 seek="$2" conv=notrunc 2>/dev/null
}
set -- $(span list-body)
lo=$1 hi=$2
flip "$work/lists.raygl" $((lo + 3)) "$work/v.raygl"
"$r2p" "$work/v.raygl" -o "$work/d" -j 1 >/dev/null 2>"$work/err"
rc=$?
[ "$rc" -eq 1 ] && ok "damaged list body: exit 1" || fail "damaged list body: exit $rc"
for f in 0 1; do
    grep -q "raygl2pov: .*v.raygl: frame $f: written without display list 1 (body #1 unreadable: checksum mismatch)" "$work/err" ||
        fail "damaged list body: frame $f not named: $(cat "$work/err")"
    grep -q "^// Incomplete: written without display list 1 (body #1 unreadable: checksum mismatch)" \
        "$work/d/frame-0000$f.pov" || fail "damaged list body: frame-0000$f.pov does not say so"
done
# --quiet keeps the damage (and the exit status).
"$r2p" "$work/v.raygl" -o "$work/d" -j 1 -q >/dev/null 2>"$work/err"
rc=$?
[ "$rc" -eq 1 ] && grep -q "frame 0: written without display list 1" "$work/err" &&
    ok "--quiet still says what damage took" || fail "--quiet on damage: exit $rc, $(cat "$work/err")"

# Frame 0 damaged: not written; frame 1, which carries its state, is
# written and says what it lacks.
set -- $(span frame-0)
flip "$work/lists.raygl" $(($1 + 20)) "$work/v.raygl"
rm -rf "$work/d"
"$r2p" "$work/v.raygl" -o "$work/d" -j 1 >/dev/null 2>"$work/err"
rc=$?
[ "$rc" -eq 1 ] && grep -q "frame 0 (not written) @0x[0-9a-f]*: checksum mismatch" "$work/err" &&
    grep -q "frame 1: written without the state carried from stream 0's frame 0 (lost to damage)" "$work/err" &&
    [ ! -e "$work/d/frame-00000.pov" ] && [ -s "$work/d/frame-00001.pov" ] &&
    ok "a damaged frame: not written; the frame carrying its state names what it lacks" ||
    fail "damaged frame 0: exit $rc: $(cat "$work/err")"
# Damaged texture pixels: the frame that uploads them and the later frame
# that draws with the texture both say so.
set -- $(span tex-pixels)
flip "$work/texframes.raygl" $(($1 + 9)) "$work/v.raygl"
rm -rf "$work/d"
"$r2p" "$work/v.raygl" -o "$work/d" -j 1 >/dev/null 2>"$work/err"
rc=$?
[ "$rc" -eq 1 ] &&
    grep -q "frame 0: written without a texture image (pixels #1 unreadable: checksum mismatch) and 1 more part$" "$work/err" &&
    grep -q "frame 1: written without texture 1 (pixels #1 unreadable)$" "$work/err" &&
    grep -q "^// Incomplete: written without texture 1 (pixels #1 unreadable)" "$work/d/frame-00001.pov" &&
    ok "damaged texture pixels: both frames say what they lack, exit 1" ||
    fail "damaged texture pixels: exit $rc: $(cat "$work/err")"

# Every byte of lists.raygl changed in turn.
cp "$work/lists.raygl" "$work/v.raygl"
rm -rf "$work/d"
"$r2p" "$work/v.raygl" -o "$work/d" -j 1 >/dev/null 2>&1 || fail "lists.raygl: clean run failed"
mv "$work/d" "$work/clean"
size=$(wc -c <"$work/lists.raygl")
silent=0 reported=0 same=0 i=0
words='damage\|unreadable\|checksum\|truncated\|written without\|not a command sequence\|bad id\|runs past'
while [ "$i" -lt "$size" ]; do
    flip "$work/lists.raygl" "$i" "$work/v.raygl"
    rm -rf "$work/d"
    "$r2p" "$work/v.raygl" -o "$work/d" -j 1 >/dev/null 2>"$work/err"
    rc=$?
    if [ "$rc" -gt 1 ]; then
        fail "byte $i: exit $rc: $(cat "$work/err")"
    elif [ "$i" -lt 32 ] && [ "$rc" -eq 1 ] && [ -s "$work/err" ]; then
        reported=$((reported + 1)) # the file header: not a trace, or not one we read
    elif grep -q "$words" "$work/err"; then
        if [ "$rc" -eq 1 ]; then reported=$((reported + 1)); else
            silent=$((silent + 1))
            fail "byte $i: damage reported with exit 0: $(cat "$work/err")"
        fi
    elif [ "$rc" -eq 0 ]; then
        # Nothing said: every frame must be exactly as before.
        if diff -r "$work/clean" "$work/d" >/dev/null 2>&1; then same=$((same + 1)); else
            fail "byte $i: exit 0, nothing said, but the output changed"
        fi
    else
        fail "byte $i: exit 1 with no damage named: $(cat "$work/err")"
    fi
    i=$((i + 1))
done
[ "$silent" -eq 0 ] && ok "lists.raygl, each of $size bytes changed: $reported reported with exit 1, $same harmless (identical output)"

# ---- 3. a damaged snapshot image costs no frame
set -- $(span snapshot-image)
flip "$work/snap.raygl" $(($1 + 5)) "$work/v.raygl"
cp "$work/snap.raygl" "$work/w.raygl"
"$r2p" "$work/w.raygl" -o "$work/s" -j 1 >/dev/null 2>&1
mv "$work/s" "$work/s1"
mv "$work/v.raygl" "$work/w.raygl"
"$r2p" "$work/w.raygl" -o "$work/s" -j 1 >/dev/null 2>"$work/err"
rc=$?
mv "$work/s" "$work/s2"
[ "$rc" -eq 0 ] && diff -r "$work/s1" "$work/s2" >/dev/null &&
    [ -s "$work/s2/frame-00002.pov" ] && ok "damaged snapshot image: every frame translated" ||
    fail "damaged snapshot image: exit $rc, $(cat "$work/err")"

# ---- 4. traces that were not closed
for t in unclosed cut; do
    rm -rf "$work/o"
    "$r2p" "$work/$t.raygl" -o "$work/o" -j 1 >/dev/null 2>"$work/err"
    rc=$?
    [ "$rc" -eq 0 ] || fail "$t: exit $rc"
    [ "$(grep -c 'trace not closed' "$work/err")" -eq 1 ] &&
        grep -q "raygl2pov: .*$t.raygl: trace not closed (the recording was killed or the disk filled): 3 complete frames, the frame in progress is lost$" "$work/err" ||
        fail "$t: note: $(cat "$work/err")"
    [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$t: more than the note: $(cat "$work/err")"
    [ -s "$work/o/frame-00002.pov" ] && [ ! -e "$work/o/frame-00003.pov" ] || fail "$t: frames"
    ok "$t: said once, exit 0, the 3 complete frames written"
done
"$r2p" "$work/lists.raygl" -o "$work/o" >/dev/null 2>"$work/err"
grep -q "not closed" "$work/err" && fail "a closed trace called not closed"

[ "$fails" -eq 0 ] || { echo "test_bounds: $fails failure(s)"; exit 1; }
echo "test_bounds: all passed"
