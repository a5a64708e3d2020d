#!/bin/sh
# run-compare-test.sh: raygl-compare end to end on a program's snapshots.
#
#   run-compare-test.sh PROG RAYGL_COMPARE RAYGL2POV POVRAY OUTDIR [FLOOR-OPTION...]
#
# 1. PROG (an image-test program) draws one frame with OSMesa under
#    RAYGL_SNAPSHOTS=1, so the trace holds the frame's image;
# 2. raygl-compare translates, renders and compares it with the floors
#    given (the image tests' thresholds), and must pass;
# 3. bad input gives one clear line and exit 1 (not a trace; the snapshot's
#    resource damaged; a frame list without snapshots), bad usage exit 2,
#    and nothing is written outside the output folder; -o NEW/SUB/DIR
#    makes the missing folders;
# 4. run from another folder it finds raygl2pov itself; options (its own
#    and raygl2pov's) and the output folder are checked before rendering;
#    a stop signal leaves no partial file.
# With RAYGL_FIGURES set (meson sets it to tests/image/figures.txt), the
# figures of step 2 are held to the file's line for "compare"
# (check-figures.sh).
set -u
[ $# -ge 5 ] || { echo "usage: $0 PROG RAYGL_COMPARE RAYGL2POV POVRAY OUTDIR [FLOOR-OPTION...]" >&2; exit 2; }
prog=$1 cmp=$2 r2p=$3 povray=$4 out=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd) || exit 1
fail() { echo "compare test: FAIL: $*"; exit 1; }
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    */*) printf '%s/%s\n' "$PWD" "$1" ;;
    *) printf '%s\n' "$1" ;;
    esac
}
prog=$(absolute "$prog")
cmp=$(absolute "$cmp")
r2p=$(absolute "$r2p")
povray=$(absolute "$povray")
rm -rf "$out"
mkdir -p "$out" || exit 1
cd "$out" || exit 1

RAYGL_SNAPSHOTS=1 "$prog" --trace run.raygl --png gl.png >program.log 2>&1 ||
    { cat program.log; fail "the program failed"; }
"$r2p" run.raygl --dump | grep -q '@Snapshot(x=0, y=0, width=320, height=240' ||
    fail "the trace holds no 320x240 snapshot"

"$cmp" run.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" "$@" -- --no-shadows >cmp.log 2>&1
rc=$?
cat cmp.log
[ $rc -eq 0 ] || fail "raygl-compare exited with $rc"
grep -q '^frame 0: 320x240 within .* silhouette ' cmp.log || fail "no figures for frame 0"
if [ -n "${RAYGL_FIGURES:-}" ]; then
    # shellcheck disable=SC2046 # three words on purpose
    "$here/check-figures.sh" "$RAYGL_FIGURES" compare $(sed -n \
        's|^frame 0: [0-9x]* within \([0-9]*\)/255 \([0-9.]*\),.* silhouette \([0-9.]*\) .*|\1 \2 \3|p' cmp.log) ||
        fail "the figures do not hold to $RAYGL_FIGURES (above)"
fi
[ -s cmp/compare-00000.png ] || fail "no cmp/compare-00000.png"
[ -s cmp/pov/frame-00000.png ] || fail "no cmp/pov/frame-00000.png"

# From the build tree, from another folder, with no raygl2pov in PATH: it
# finds its sibling itself (issue 11).
mkdir elsewhere
(cd elsewhere && env PATH=/usr/bin:/bin "$cmp" ../run.raygl -o ../sib --povray "$povray" \
    --frames 0-0:1 -- --no-shadows) >sib.log 2>&1 ||
    { cat sib.log; fail "raygl-compare without --raygl2pov, run from another folder"; }
[ -s sib/compare-00000.png ] || fail "no sib/compare-00000.png"

# -o NEW/SUB/DIR makes the missing folders, as raygl2pov -o does (issue
# 27); a usage error found before rendering removes what it made.
"$cmp" run.raygl -o new/sub/dir --raygl2pov "$r2p" --povray "$povray" -- --no-shadows >nest.log 2>&1 ||
    { cat nest.log; fail "raygl-compare -o new/sub/dir"; }
[ -s new/sub/dir/compare-00000.png ] || fail "no new/sub/dir/compare-00000.png"
mkdir kept
"$cmp" run.raygl -o kept/a/b --raygl2pov "$r2p" -- --bogus >nest.log 2>&1
[ $? -eq 2 ] && [ -d kept ] && [ ! -e kept/a ] || { cat nest.log; fail "-o kept/a/b left kept/a after a usage error"; }

# A floor it cannot meet fails.
"$cmp" run.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" --tol 0 --min-match 1 \
    -- --no-shadows >floor.log 2>&1
[ $? -eq 1 ] && grep -q 'BELOW FLOOR' floor.log || { cat floor.log; fail "an unmeetable floor passed"; }

# Bad input: one line naming the file, exit 1.
printf 'not a trace at all, just text\n' >bad.raygl
"$cmp" bad.raygl -o badout --raygl2pov "$r2p" >bad.log 2>&1
[ $? -eq 1 ] && grep -q '^raygl-compare: bad.raygl: ' bad.log || { cat bad.log; fail "bad trace"; }
[ ! -e badout ] || fail "a bad trace made its output folder"
# The snapshot's image resource damaged (its last byte before the CRC):
# the payload checksum catches it, named with the frame and offset.
size=$(wc -c <run.raygl)
python3 - run.raygl damaged.raygl <<'PY'
import sys
d = bytearray(open(sys.argv[1], 'rb').read())
# The second RESOURCE chunk is the snapshot image (the first is the state).
sync = b'\xc3RGC'
pos, seen = 32, 0
while True:
    i = d.find(sync, pos)
    assert i >= 0
    n = int.from_bytes(d[i + 8:i + 12], 'little')
    if d[i + 4] == 2:
        seen += 1
        if seen == 2:
            d[i + 16 + n - 1] ^= 0xff
            break
    pos = i + 20 + n
open(sys.argv[2], 'wb').write(d)
PY
"$cmp" damaged.raygl -o dmg --raygl2pov "$r2p" >dmg.log 2>&1
[ $? -eq 1 ] && grep -q '^raygl-compare: damaged.raygl: frame 0, @Snapshot image #2 @0x' dmg.log ||
    { cat dmg.log; fail "damaged snapshot"; }
# Truncated inside the last frame: nothing left to compare.
head -c $((size - 100)) run.raygl >cut.raygl
"$cmp" cut.raygl -o cut --raygl2pov "$r2p" >cut.log 2>&1
[ $? -eq 1 ] && grep -q 'no frame holds a usable snapshot (record with `raygl record --snapshots`' cut.log ||
    { cat cut.log; fail "truncated"; }
# Bad usage.
"$cmp" run.raygl >usage.log 2>&1
[ $? -eq 2 ] || fail "no -o is not a usage error"
"$cmp" run.raygl -o x --frames 3-1 >usage.log 2>&1
[ $? -eq 2 ] || fail "--frames 3-1 is not a usage error"
# Checked before rendering: one line naming the option or file, no FAIL
# line, nothing rendered.
"$cmp" run.raygl -o opt --raygl2pov "$r2p" -- --bogus >opt.log 2>&1
[ $? -eq 2 ] && [ "$(wc -l <opt.log)" -eq 1 ] && grep -q '^raygl-compare: after --: raygl2pov: .*bogus' opt.log &&
    [ ! -e opt ] || { cat opt.log; fail "a bad raygl2pov option"; }
"$cmp" run.raygl -o opt --raygl2pov "$r2p" -- -o elsewhere >opt.log 2>&1
[ $? -eq 2 ] && grep -q '^raygl-compare: -o after --: raygl-compare sets it itself' opt.log ||
    { cat opt.log; fail "-o after --"; }
"$cmp" run.raygl -o gl.png --raygl2pov "$r2p" >opt.log 2>&1
[ $? -eq 1 ] && grep -q '^raygl-compare: -o gl.png: not a folder$' opt.log ||
    { cat opt.log; fail "-o naming a file"; }
mkdir povfile && : >povfile/pov
"$cmp" run.raygl -o povfile --raygl2pov "$r2p" >opt.log 2>&1
[ $? -eq 1 ] && grep -q '^raygl-compare: povfile/pov: not a folder' opt.log && ! grep -q FAIL opt.log ||
    { cat opt.log; fail "DIR/pov a file"; }
rm -rf povfile
"$cmp" run.raygl -o opt --raygl2pov ./no-such-raygl2pov >opt.log 2>&1
[ $? -eq 1 ] && grep -q 'no-such-raygl2pov: raygl2pov not found' opt.log ||
    { cat opt.log; fail "a missing raygl2pov"; }
head -c 4096 /dev/urandom >random.raygl
"$cmp" random.raygl -o opt --raygl2pov "$r2p" >opt.log 2>&1
[ $? -eq 1 ] && [ "$(grep -o 'not a RayGL trace' opt.log | wc -l)" -eq 1 ] ||
    { cat opt.log; fail "random bytes"; }
rm -rf opt

# Stopped (SIGINT to its group, as Ctrl-C sends it, and SIGTERM to the
# process) once a stand-in povray has written its partial files: no partial
# or temporary file anywhere under the output folder.
cat >stand-in-povray <<EOF
#!/bin/sh
for a; do case \$a in +O*) out=\${a#+O} ;; esac; done
printf partial >"\$out"
printf state >"\${out%.png}.pov-state"
: >"$PWD/stand-in.started"
exec sleep 300
EOF
chmod +x stand-in-povray
for how in group proc; do
    rm -f stand-in.started
    setsid "$cmp" run.raygl -o stop --raygl2pov "$r2p" --povray "$PWD/stand-in-povray" >stop.log 2>&1 &
    pid=$!
    i=0
    while [ ! -e stand-in.started ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
    [ -e stand-in.started ] || fail "the stand-in povray never started"
    if [ $how = group ]; then kill -INT -$pid; else kill -TERM $pid; fi
    wait $pid
    [ $? -ne 0 ] || fail "stopped raygl-compare exited 0"
    left=$(cd stop && find . -name '.*' ! -name . -o -name '*.pov-state' -o -name '*.tmp' -o -name '*partial*')
    [ -z "$left" ] || fail "stopped ($how): left $left"
done
rm -f stand-in-povray stand-in.started

# Only the expected names in the folder (nothing escaped into it from elsewhere
# and raygl-compare wrote only under its -o folders).
for f in *; do
    case $f in
    run.raygl|gl.png|program.log|cmp.log|cmp|floor.log|bad.raygl|bad.log|damaged.raygl|dmg.log|dmg|cut.raygl|cut.log|cut|usage.log) ;;
    elsewhere|sib|sib.log|opt.log|random.raygl|stop|stop.log|new|nest.log|kept) ;;
    *) fail "unexpected file $f" ;;
    esac
done
echo "compare test: PASS"
