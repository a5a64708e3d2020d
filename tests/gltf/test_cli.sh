#!/bin/sh
# test_cli.sh: raygl2pov --format gltf from the command line: the frames
# and names of the POV-Ray output, the raygl2gltf alias, settings files,
# same trace => same bytes (-j 1 and -j 2), the look's options as glTF
# keeps them (--area-lights and --radiosity as extras, --include said to
# be left out), POV-Ray-only options and bad values rejected (exit 2, one
# line), an unwritable folder (exit 1, nothing half-written), hostile frame
# names kept inside the folder.
#
#   test_cli.sh RAYGL2POV MKTRACES
set -u
r2p=$(realpath "$1") mktraces=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failed=0
ok() { echo "ok: $*"; }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
run() { "$r2p" "$@" >"$work/out" 2>"$work/err"; rc=$?; }
expect_rc() {
    [ "$rc" -eq "$1" ] && ok "$2 (exit $1)" || fail "$2: exit $rc, expected $1: $(cat "$work/err")"
}
one_line() {
    [ "$(grep -vc '^Try ' "$work/err")" -eq 1 ] && grep -q -e "$1" "$work/err" && ok "message: $1" ||
        fail "message '$1': $(cat "$work/err")"
}

"$mktraces" "$work" || exit 1
good="$work/good.raygl"

# ---- the same frames and names as the POV-Ray output
run "$good" -q -o pov
expect_rc 0 "POV-Ray output"
run "$good" -q --format gltf -o glb
expect_rc 0 "glTF output"
(cd pov && ls *.pov | sed 's/\.pov$//' | sort) >pov.names
(cd glb && ls | sed 's/\.glb$//' | sort) >glb.names
cmp -s pov.names glb.names && [ -s glb.names ] && ok "same names: $(tr '\n' ' ' <glb.names)" ||
    fail "names differ: $(tr '\n' ' ' <pov.names) / $(tr '\n' ' ' <glb.names)"
for f in glb/*; do
    head -c 4 "$f" | grep -q glTF || fail "$f: not a GLB"
done
[ -z "$(ls -A glb | grep -v '\.glb$')" ] && ok "only .glb files (no .ini, no temporary)" ||
    fail "other files: $(ls -A glb | tr '\n' ' ')"

run "$good" -q --format gltf -o sel --frames 0,2 --name-pattern 'f{index:3}'
expect_rc 0 "--frames and --name-pattern"
[ "$(ls sel | tr '\n' ' ')" = "f000.glb f002.glb " ] && ok "selected frames named" ||
    fail "selection: $(ls sel | tr '\n' ' ')"

# ---- same trace, same bytes
run "$good" -q --format gltf -o again -j 2
for f in glb/*.glb; do
    cmp -s "$f" "again/$(basename "$f")" || fail "$f differs between -j 1 and -j 2 runs"
done
ok "deterministic bytes across runs and -j"

# ---- the alias and settings files
ln -s "$r2p" "$work/raygl2gltf"
"$work/raygl2gltf" -q "$good" -o alias --frames 0 2>"$work/err" && [ -f alias/frame-00000.glb ] &&
    ok "raygl2gltf writes .glb" || fail "raygl2gltf: $(ls alias) $(cat "$work/err")"
"$work/raygl2gltf" -q "$good" -o alias2 --frames 0 --format pov 2>"$work/err" &&
    [ -f alias2/frame-00000.pov ] && ok "raygl2gltf --format pov" || fail "alias --format pov"
printf 'format = gltf\nframes = 1\n' >s.conf
run "$good" -q --settings s.conf -o conf
expect_rc 0 "format in a settings file"
[ "$(ls conf)" = "frame-00001.glb" ] && ok "settings file: glTF" || fail "settings: $(ls conf)"

# ---- camera and size re-translation applies
run "$good" -q --format gltf -o cam --frames 0 --camera-fov 20
expect_rc 0 "--camera-fov"
cmp -s cam/frame-00000.glb glb/frame-00000.glb && fail "--camera-fov changed nothing" ||
    ok "--camera-fov changes the camera"

run "$good" -q --format gltf -o size --frames 0 --width 800 --height 200
expect_rc 0 "--width --height"
grep -a -q '"aspectRatio":4,' size/frame-00000.glb && grep -a -q '"imageSize":\[800,200\]' size/frame-00000.glb &&
    ok "--width 800 --height 200: aspect 4, imageSize in extras" || fail "--width/--height not in the file"

# ---- --light adds lights; --no-gl-lights drops the frame's
run "$good" -q --format gltf -o lights --frames 0 --no-gl-lights \
    --light 'spot at=1,2,3 to=0,0,-5 radius=20 falloff=40' \
    --light 'parallel at=0,1,0'
expect_rc 0 "--light with --format gltf"
grep -a -q '"lights":\[{"type":"spot".*{"type":"directional"' lights/frame-00000.glb &&
    ok "--light: a spot and a directional light" || fail "--light: lights not in the file"
grep -a -q '"spot":{"innerConeAngle":0.34906[0-9]*,"outerConeAngle":0.6981317}' lights/frame-00000.glb &&
    ok "--light spot: radius 20, falloff 40 as the cones" || fail "--light spot cones: $(grep -a -o '"spot":{[^}]*}' lights/frame-00000.glb)"
run "$good" -q --format gltf -o nolights --frames 0 --no-gl-lights
grep -a -q 'KHR_lights_punctual' nolights/frame-00000.glb && fail "--no-gl-lights kept lights" ||
    ok "--no-gl-lights: no lights"

# ---- what the look step asks beyond GL's picture, as glTF can keep it
run "$good" -q --format gltf -o soft --frames 0 --area-lights 4 --light 'area at=0,3,0 size=2,1'
expect_rc 0 "--area-lights with --format gltf"
grep -a -q '"rayglShadowRadius":0.75}' soft/frame-00000.glb &&
    ok "--light area 2x1: a soft radius of 0.75 (the GL lights': tests/gltf/test_gltf.c)" ||
    fail "soft shadows: $(grep -a -o '"lights":.*"scene"' soft/frame-00000.glb)"
grep -a -q 'rayglShadow' glb/frame-00000.glb && fail "a light has a size without --area-lights" ||
    ok "no light size by default"
run "$good" -q --format gltf -o rad --frames 0 --radiosity
expect_rc 0 "--radiosity with --format gltf"
grep -a -q '"radiosity":true' rad/frame-00000.glb && ! grep -a -q '"radiosity"' glb/frame-00000.glb &&
    ok "--radiosity: extras.radiosity" || fail "--radiosity not in the file's extras"
printf 'plane{y,-1 pigment{rgb 1}}\n' >floor.inc
run "$good" --format gltf -o inc --frames 0,1 --include floor.inc
expect_rc 0 "--include with --format gltf"
[ "$(grep -c 'include.*POV-Ray SDL.*left out' "$work/err")" -eq 1 ] &&
    ok "--include: said once for the run" || fail "--include's note: $(cat "$work/err")"
cmp -s inc/frame-00000.glb glb/frame-00000.glb && [ -z "$(ls inc | grep -v '\.glb$')" ] &&
    ok "--include: the frames as without it, no file copied" ||
    fail "--include changed the output: $(ls inc)"
run "$good" -q --format gltf -o incq --frames 0 --include floor.inc
[ ! -s "$work/err" ] && ok "--include's note: not with --quiet" || fail "with -q: $(cat "$work/err")"

# ---- bad usage: exit 2, one line
run "$good" --format obj -o bad
expect_rc 2 "--format obj"
one_line "format 'obj': expected pov or gltf"
# (--render renders glTF frames with Blender: tests/blender; POV-Ray
# rendering is what is refused.)
# (--preview is named as typed, not as the --quality it sets: issue 27.)
for opt in "--engine povray --render" "--antialias" "--quality 3" "--no-shadows" \
    "--reflection 0.5" "--preview"; do
    # shellcheck disable=SC2086
    set -- $opt
    run "$good" --format gltf -o bad "$@"
    expect_rc 2 "$1 with --format gltf"
    one_line "$1.*POV-Ray only, not with --format gltf"
done
"$work/raygl2gltf" "$good" -o bad --preview >"$work/out" 2>"$work/err"
rc=$?
expect_rc 2 "raygl2gltf --preview"
one_line ": --preview: POV-Ray only, not with --format gltf"
[ ! -e bad ] && ok "nothing written on bad usage" || fail "bad usage wrote $(ls bad)"

# ---- unwritable output
: >afile
run "$good" --format gltf -o afile/sub
expect_rc 1 "output under a file"
one_line "afile/sub: cannot create the output folder"
# a full disk, as the file size limit: nothing half-written under a final name
(
    trap '' XFSZ
    ulimit -f 64
    "$r2p" "$work/big.raygl" --format gltf -o full -j 1 2>"$work/err"
    echo $? >"$work/rc"
)
rc=$(cat "$work/rc")
expect_rc 1 "full disk"
grep -q "cannot write" "$work/err" || fail "full-disk message: $(cat "$work/err")"
[ -z "$(ls -A full)" ] && ok "no file left after the failed write" ||
    fail "left after a failed write: $(ls -A full | tr '\n' ' ')"

# ---- hostile names stay inside the folder
[ -z "$(find "$work" -name '*.glb' ! -path "$work/glb/*" ! -path "$work/again/*" \
    ! -path "$work/sel/*" ! -path "$work/alias/*" ! -path "$work/conf/*" ! -path "$work/cam/*" \
    ! -path "$work/lights/*" ! -path "$work/nolights/*" ! -path "$work/size/*" \
    ! -path "$work/soft/*" ! -path "$work/rad/*" ! -path "$work/inc/*" ! -path "$work/incq/*")" ] &&
    ok "no .glb outside the output folders" || fail "a .glb escaped its folder"

echo "$failed failed"
[ "$failed" -eq 0 ]
