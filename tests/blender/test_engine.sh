#!/bin/sh
# test_engine.sh: the render driver with Blender (--engine blender).
#
#   test_engine.sh RAYGL2POV RAYGL_RENDER MKANIM IMGCMP BLENDER
#
# raygl2pov --format gltf --render renders every .glb with Blender, 2 at
# once, into complete PNGs; a second run renders nothing, a changed .glb
# renders again and the same frame renders to the same pixels (fixed
# seed); a damaged .glb is reported with the frame and the script's reason
# while the others render (exit 1); a missing Blender and wrong usage fail
# clearly; lines and points, which Cycles does not draw, are noted with
# the frame; SIGINT while Blender renders leaves no partial file and no
# Blender running; the Slurm script and a task render with Blender; GNU parallel
# (':' is this machine) when installed. Skipped (77) without Blender.
blender=$5
if [ "$blender" = none ] || ! command -v "$blender" >/dev/null 2>&1; then
    echo "SKIP: no blender (apt-get install blender python3-numpy)"
    exit 77
fi
. "$(dirname "$0")/../render/common.sh"

cd "$work" || exit 1
"$mkanim" anim.raygl 4 80 60 || { echo "mkanim failed"; exit 1; }
opts="--engine blender --samples 4"

# ---- every frame, 2 at once
run "$r2p" anim.raygl -o f --format gltf --render -j 2 --samples 4
expect_rc 0 "--format gltf --render -j 2"
n=$(ls f/*.png 2>/dev/null | wc -l)
[ "$n" -eq 4 ] && ok "4 PNGs" || fail "expected 4 PNGs, found $n: $(ls f)"
grep -q "4 frames rendered in .* 2 at once), 0 already rendered, 0 failed" "$work/err" &&
    ok "summary" || fail "summary: $(cat "$work/err")"
ls -a f | grep -q 'partial\|tmp' && fail "partial files left: $(ls -a f)"
grep -q "note" "$work/err" && fail "a note for frames with no lines or points: $(cat "$work/err")"
"$imgcmp" --tol 0 --min-match 1 f/frame-00000.png f/frame-00003.png >/dev/null 2>&1 &&
    fail "frames 0 and 3 of the animation are the same picture"
cp f/frame-00002.png keep.png

# ---- resumable: nothing again (the folder's .glb frames choose Blender);
# a changed .glb renders again, to the same pixels
run "$render" f
expect_rc 0 "raygl-render f"
grep -q "0 frames rendered .* 4 already rendered" "$work/err" && ok "nothing rendered twice" ||
    fail "second run: $(cat "$work/err")"
sleep 0.01
touch f/frame-00002.glb
run "$render" f $opts
expect_rc 0 "raygl-render after a .glb changed"
grep -q "1 frame rendered .* 3 already rendered" "$work/err" && ok "the changed frame only" ||
    fail "changed frame: $(cat "$work/err")"
"$imgcmp" --tol 0 --min-match 1 keep.png f/frame-00002.png >"$work/cmp" 2>&1 &&
    ok "same frame, same pixels" || fail "a second render differs: $(cat "$work/cmp")"

# ---- a damaged frame: named, with the script's reason; the others render
cp -r f bad
rm bad/*.png
echo "not a glb" >bad/frame-00001.glb
run "$render" bad -j 2 $opts
expect_rc 1 "raygl-render with a damaged .glb"
grep -q "bad/frame-00001.glb: blender failed (exit status 1): not a binary glTF file (no glTF magic) (log: bad/frame-00001.log)" \
    "$work/err" && ok "the frame and the reason" || fail "failure message: $(cat "$work/err")"
[ -s bad/frame-00000.png ] && [ -s bad/frame-00002.png ] && [ -s bad/frame-00003.png ] &&
    ok "the other frames rendered" || fail "the other frames: $(ls bad)"
[ -e bad/frame-00001.png ] && fail "a PNG for the damaged frame"
grep -q "3 frames rendered .* 1 failed" "$work/err" || fail "failure summary: $(cat "$work/err")"
ls -a bad | grep -q 'partial\|tmp' && fail "partial files left: $(ls -a bad)"

# ---- SIGINT while Blender renders: no partial file, no Blender left
cp -r f stop
rm stop/*.png
"$render" stop -j 2 $opts >stop.log 2>&1 &
pid=$!
i=0
while ! grep -qs "Blender" stop/.*.partial.log && [ $i -lt 600 ]; do
    i=$((i + 1))
    sleep 0.1
done
kids=$(ps -o pid= --ppid "$pid")
kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" -ne 0 ] && ok "stopped raygl-render exits $rc" || fail "stopped raygl-render exited 0"
left=$(ls -A stop | grep -v -E '^(frame-[0-9]+\.(glb|png)|render\.list)$')
[ -z "$left" ] && ok "stopped: nothing partial left" || fail "stopped: left $(echo $left)"
for k in $kids; do
    kill -0 "$k" 2>/dev/null && fail "blender $k still runs after the stop"
done

# ---- points and lines, which Cycles does not draw: a note with the frame
mkdir pts
python3 - f/frame-00000.glb pts/frame-00000.glb <<'EOF2'
import json, struct, sys
d = open(sys.argv[1], "rb").read()
n = struct.unpack("<I", d[12:16])[0]
j = json.loads(d[20:20 + n])
j["meshes"][0]["primitives"][0]["mode"] = 0
t = json.dumps(j).encode()
t += b" " * (-len(t) % 4)
rest = d[20 + n:]
out = struct.pack("<III", 0x46546C67, 2, 20 + len(t) + len(rest)) + struct.pack("<II", len(t), 0x4E4F534A) + t + rest
open(sys.argv[2], "wb").write(out)
EOF2
run "$render" pts $opts
expect_rc 0 "a frame with points"
grep -q "pts/frame-00000.glb: note: 0 line and 1 point primitive(s) not drawn (Cycles renders no loose edges or vertices)" \
    "$work/err" && ok "points noted" || fail "no note for points: $(cat "$work/err")"

# ---- a missing Blender; wrong usage
run "$render" f --blender "$work/no-such-blender" --engine blender
expect_rc 1 "--blender pointing nowhere"
grep -q "no-such-blender: Blender not found (install Blender" "$work/err" && ok "Blender missing" ||
    fail "missing blender: $(cat "$work/err")"
run "$r2p" anim.raygl -o p --render --engine blender
expect_rc 2 "--engine blender with POV-Ray scenes"
grep -q "engine blender renders glTF frames: add --format gltf" "$work/err" ||
    fail "message: $(cat "$work/err")"
run "$r2p" anim.raygl -o p --format gltf --render --engine povray
expect_rc 2 "--engine povray with --format gltf"
run "$render" f --engine cycles
expect_rc 2 "--engine cycles"
grep -q "engine 'cycles': expected povray or blender" "$work/err" || fail "message: $(cat "$work/err")"
run "$render" f --samples 0
expect_rc 2 "--samples 0"

# ---- the cluster paths: the Slurm script's task renders with Blender
run "$render" f $opts --samples 6 --slurm
expect_rc 0 "--slurm"
grep -q "exec .* 'f' --task .* --engine blender --samples 6" f/render.slurm &&
    ok "the Slurm task renders with Blender" || fail "render.slurm: $(grep exec f/render.slurm)"
rm f/frame-00001.png
run "$render" f --task 1 --engine blender --samples 4
expect_rc 0 "--task 1"
[ -s f/frame-00001.png ] && ok "the task's PNG" || fail "no PNG from --task 1"
if command -v parallel >/dev/null 2>&1; then
    echo ":" >hosts
    rm f/frame-00000.png f/frame-00003.png
    run "$render" f $opts --sshloginfile hosts
    expect_rc 0 "--sshloginfile ':'"
    [ -s f/frame-00000.png ] && [ -s f/frame-00003.png ] && ok "GNU parallel rendered" ||
        fail "GNU parallel: $(ls f); $(cat "$work/err")"
    grep -q "2 frames rendered .* 2 already rendered" "$work/err" || fail "summary: $(cat "$work/err")"
else
    echo "note: GNU parallel not installed, its path not tested"
fi

[ "$fails" -eq 0 ] || { echo "$fails failure(s)"; exit 1; }
echo "PASS"
