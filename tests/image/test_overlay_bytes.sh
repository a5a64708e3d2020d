#!/bin/sh
# test_overlay_bytes.sh: the overlay's PNG is cropped and compressed (issue
# 27).
#
#   test_overlay_bytes.sh PROG RAYGL2POV DIR
#
# PROG (hud_ortho: two lines of bitmap text, one near the top and one near
# the bottom of the frame) draws at 640x480; its overlay was a full-frame
# stored RGBA PNG of 1,231,344 bytes. Now the box the text covers (its
# height, about 300 pixels wide), deflated: a few kilobytes. Fails above
# 16 KiB, or when the image is still the frame's size.
set -u
prog=$1
r2p=$2
dir=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$dir"
mkdir -p "$dir" || exit 1
"$prog" --trace "$dir/h.raygl" --png "$dir/gl.png" --size 640x480 >"$dir/program.log" 2>&1 ||
    fail "the program exited with $?"
"$r2p" "$dir/h.raygl" -o "$dir/pov" --quiet || fail "raygl2pov"
n=0
for f in "$dir"/pov/textures/rgl-tex-*.png; do
    [ -f "$f" ] || fail "no overlay image"
    n=$((n + 1))
    bytes=$(wc -c <"$f")
    # The PNG's IHDR: width and height, big-endian, at bytes 16 and 20.
    size=$(od -An -tu1 -j16 -N8 "$f" | awk '{ printf "%dx%d", $3 * 256 + $4, $7 * 256 + $8 }')
    echo "overlay $size, $bytes bytes"
    [ "$bytes" -le 16384 ] || fail "the overlay's PNG has $bytes bytes (at most 16384)"
    [ "$size" != 640x480 ] || fail "the overlay is not cropped ($size)"
done
[ "$n" -eq 1 ] || fail "expected one overlay image, found $n"
echo "overlay-bytes: PASS"
