#!/bin/sh
# run-blender-test.sh: one image test, GL frame against Blender's frame.
#
#   run-blender-test.sh NAME PROGRAM RAYGL2POV IMGCMP BLENDER OUTDIR SAMPLES
#                       [--r2p-opt OPT]... [IMGCMP-OPTIONS...]
#
# 1. PROGRAM --trace DIR/NAME.raygl --png DIR/gl.png  draws one frame with
#    OSMesa, records it and writes the GL image (DIR = OUTDIR/NAME);
# 2. in DIR: RAYGL2POV NAME.raygl -o glb --format gltf --render
#    --samples SAMPLES [OPT...]  translates it and renders
#    glb/frame-00000.glb with Blender through the render driver
#    (raygl-render --engine blender); each --r2p-opt adds one raygl2pov
#    option (--area-lights, --radiosity: what the look step asks of it);
# 3. IMGCMP compares gl.png and glb/frame-00000.png: the framing (the
#    silhouettes at 2/255 agree to 0.998; DIR/diff.png shows GL | Blender |
#    difference), then the colours with IMGCMP-OPTIONS when given; the time
#    of step 2 is printed.
#
# Exit 0 on PASS, 1 on FAIL, 77 when BLENDER is absent ("none").
set -u
[ $# -ge 7 ] || { echo "usage: $0 NAME PROGRAM RAYGL2POV IMGCMP BLENDER OUTDIR SAMPLES [IMGCMP-OPTIONS...]" >&2; exit 2; }
name=$1 prog=$2 r2p=$3 imgcmp=$4 blender=$5 outdir=$6 samples=$7
shift 7
r2p_opts=
while [ $# -ge 2 ] && [ "$1" = --r2p-opt ]; do
    r2p_opts="$r2p_opts $2" # options without spaces: word splitting is wanted
    shift 2
done
if [ "$blender" = none ] || ! command -v "$blender" >/dev/null 2>&1; then
    echo "SKIP: no blender (apt-get install blender python3-numpy)"
    exit 77
fi
# The steps run in the test's folder: relative paths made absolute.
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    *) printf '%s/%s\n' "$PWD" "$1" ;;
    esac
}
prog=$(absolute "$prog") r2p=$(absolute "$r2p") imgcmp=$(absolute "$imgcmp")
outdir=$(absolute "$outdir")
dir=$outdir/$name
rm -rf "$dir"
mkdir -p "$dir" || exit 1
fail() {
    echo "blender test $name: FAIL: $*"
    exit 1
}
echo "blender test $name: $dir"

"$prog" --trace "$dir/$name.raygl" --png "$dir/gl.png" >"$dir/program.log" 2>&1 ||
    { tail -n 20 "$dir/program.log"; fail "the program failed"; }
t0=$(date +%s%N)
# RAYGL2POV's sibling raygl-render and the import script are found beside
# it; BLENDER is the program the driver runs.
# shellcheck disable=SC2086
(cd "$dir" && "$r2p" "$name.raygl" -o glb --format gltf --render --samples "$samples" -j 1 \
    --blender "$blender" $r2p_opts) >"$dir/render.log" 2>&1 ||
    { tail -n 20 "$dir/render.log"; fail "raygl2pov --format gltf --render failed"; }
t1=$(date +%s%N)
[ -s "$dir/glb/frame-00000.png" ] || fail "no glb/frame-00000.png"
# Milliseconds, reported: performance is measured, never asserted.
echo "blender frame time: $(((t1 - t0) / 1000000)) ms (translate + Blender, $samples samples)"
# The framing: the silhouettes at 2/255 (edges and coverage, whatever the
# colours); then the colours with IMGCMP-OPTIONS, when given.
echo "framing:"
"$imgcmp" --tol 2 --min-match 0 --min-silhouette 0.998 --diff "$dir/diff.png" "$dir/gl.png" \
    "$dir/glb/frame-00000.png" ||
    { echo "blender test $name: FAIL (see $dir/diff.png: GL | Blender | difference)"; exit 1; }
if [ $# -gt 0 ]; then
    echo "colours:"
    "$imgcmp" "$@" "$dir/gl.png" "$dir/glb/frame-00000.png" ||
        { echo "blender test $name: FAIL (see $dir/diff.png: GL | Blender | difference)"; exit 1; }
fi
echo "blender test $name: PASS"
