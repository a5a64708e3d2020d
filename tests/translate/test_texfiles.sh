#!/bin/sh
# test_texfiles.sh: texture images in raygl2pov's output folder (issue 5).
#
#   test_texfiles.sh RAYGL2POV MKTEXTRACE
#
# Four frames use two images: exactly two textures/rgl-tex-*.png files (apart
# from the frames' PNGs, issue 11), each named in
# the scenes that use it, no temporary file left; -j 1 and -j 4 give the
# same names and bytes; a second run into the same folder keeps the files
# (not rewritten) and the scenes' bytes.
set -u
r2p=$1
mk=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$mk" "$work/tex.raygl" || fail "mktextrace"
"$r2p" "$work/tex.raygl" -o "$work/a" -j 4 --quiet || fail "raygl2pov -j 4"
"$r2p" "$work/tex.raygl" -o "$work/b" -j 1 --quiet || fail "raygl2pov -j 1"
n=$(ls "$work/a/textures" | grep -c '^rgl-tex-[0-9a-f]*\.png$')
[ "$n" -eq 2 ] || fail "expected 2 images, found $n: $(ls "$work/a")"
[ "$(ls -A "$work/a" "$work/a/textures" | grep -c '^\.')" -eq 0 ] ||
    fail "temporary files left: $(ls -A "$work/a" "$work/a/textures")"
for f in "$work"/a/textures/rgl-tex-*.png; do
    name=$(basename "$f")
    grep -q "\"textures/$name\"" "$work"/a/frame-*.pov || fail "$name named by no scene"
    cmp -s "$f" "$work/b/textures/$name" || fail "$name differs between -j 4 and -j 1"
done
first=$(grep -l image_map "$work/a/frame-00000.pov" >/dev/null && grep -o 'rgl-tex-[0-9a-f]*\.png' "$work/a/frame-00000.pov" | sort -u)
last=$(grep -o 'rgl-tex-[0-9a-f]*\.png' "$work/a/frame-00003.pov" | sort -u)
[ -n "$first" ] && [ -n "$last" ] && [ "$first" != "$last" ] || fail "frames 0 and 3 should name different images"
[ "$(grep -o 'rgl-tex-[0-9a-f]*\.png' "$work/a/frame-00002.pov" | sort -u)" = "$first" ] ||
    fail "frame 2 (carried state) should name frame 0's image"
before=$(ls -i "$work"/a/textures/rgl-tex-*.png)
cp "$work/a/frame-00001.pov" "$work/f1"
"$r2p" "$work/tex.raygl" -o "$work/a" --quiet || fail "second run"
[ "$(ls -i "$work"/a/textures/rgl-tex-*.png)" = "$before" ] || fail "images rewritten by a second run"
cmp -s "$work/a/frame-00001.pov" "$work/f1" || fail "scene changed on a second run"
echo "texfiles: PASS"
