#!/bin/sh
# test_gltf_notes.sh: the notes raygl2pov says are about the output it
# writes (issue 27). For --format gltf the POV-Ray scene's approximations
# of bitmaps ("show in front") and of additive blending ("keeps 127/128")
# are held, and each frame with bitmaps or pixel rectangles gets exactly
# one note that glTF leaves them out; additive blending one of its own.
# The POV-Ray output of the same traces still says its notes.
#
#   test_gltf_notes.sh HUD_PROG BLEND_PROG RAYGL2POV DIR
#
# HUD_PROG (hud_ortho) draws bitmap text over a scene; BLEND_PROG
# (blend_funcs) draws with glBlendFunc(GL_ONE, GL_ONE) among others.
set -u
hud=$1
blend=$2
r2p=$3
dir=$4
failed=0
ok() { echo "ok: $*"; }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
count() { grep -c -e "$1" "$2"; }
rm -rf "$dir"
mkdir -p "$dir" || exit 1
for p in hud blend; do
    eval "prog=\$$p"
    "$prog" --trace "$dir/$p.raygl" --png "$dir/$p.png" >"$dir/$p.program.log" 2>&1 ||
        { echo "FAIL: $p: the program exited with $?"; exit 1; }
    "$r2p" "$dir/$p.raygl" -o "$dir/$p-pov" 2>"$dir/$p-pov.err" || fail "$p: raygl2pov"
    "$r2p" "$dir/$p.raygl" --format gltf -o "$dir/$p-gltf" 2>"$dir/$p-gltf.err" ||
        fail "$p: raygl2pov --format gltf"
done
pixels='left out of glTF: bitmaps and pixel rectangles'
[ "$(count "$pixels" "$dir/hud-gltf.err")" -eq 1 ] &&
    ok "glTF: one note that bitmaps are left out" ||
    fail "glTF bitmaps: $(cat "$dir/hud-gltf.err")"
[ "$(count 'show in front' "$dir/hud-gltf.err")" -eq 0 ] &&
    ok "glTF: nothing of how bitmaps would show" || fail "glTF: $(cat "$dir/hud-gltf.err")"
[ "$(count "$pixels" "$dir/hud-pov.err")" -eq 0 ] &&
    ok "POV-Ray: bitmaps not said to be left out" || fail "POV-Ray: $(cat "$dir/hud-pov.err")"
[ "$(count '127/128' "$dir/blend-pov.err")" -eq 1 ] &&
    ok "POV-Ray: additive blending's 127/128 said" || fail "POV-Ray blend: $(cat "$dir/blend-pov.err")"
[ "$(count '127/128' "$dir/blend-gltf.err")" -eq 0 ] &&
    [ "$(count 'approximated in glTF: additive blending' "$dir/blend-gltf.err")" -eq 1 ] &&
    ok "glTF: additive blending's own note, not POV-Ray's" ||
    fail "glTF blend: $(cat "$dir/blend-gltf.err")"
[ "$(count "$pixels" "$dir/blend-gltf.err")" -eq 0 ] &&
    ok "glTF: no bitmap note for a frame without bitmaps" || fail "glTF blend: $(cat "$dir/blend-gltf.err")"
[ "$failed" -eq 0 ] && echo "gltf-notes: PASS"
[ "$failed" -eq 0 ]
