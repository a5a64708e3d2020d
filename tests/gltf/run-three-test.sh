#!/bin/sh
# run-three-test.sh: one three.js image test, GL frame against the frame's
# .glb rendered by three.js in headless Chromium (suite gltf-image).
#
#   run-three-test.sh NAME PROG RAYGL2POV NODE RENDER_JS CHROMIUM IMGCMP OUTDIR
#                     [-- IMGCMP-OPTIONS...]
#
# 1. PROG --trace OUTDIR/NAME/NAME.raygl --png OUTDIR/NAME/gl.png: one frame
#    drawn with OSMesa, recorded, and GL's image;
# 2. RAYGL2POV NAME.raygl --format gltf -o glb: the frame as glb/frame-00000.glb;
# 3. NODE RENDER_JS --chromium CHROMIUM glb/frame-00000.glb three.png:
#    three.js renders it with the file's camera at the GL viewport's size;
# 4. IMGCMP [IMGCMP-OPTIONS] --diff diff.png gl.png three.png decides.
#
# Exit 77 (skip) only when node, Chromium or tools/node/node_modules/three
# is missing (tools/deps.sh installs all three; CI has them). Everything
# stays in OUTDIR/NAME for inspection. Exit 0 PASS, 1 FAIL, 2 bad usage.
set -u
[ $# -ge 8 ] || { echo "usage: $0 NAME PROG RAYGL2POV NODE RENDER_JS CHROMIUM IMGCMP OUTDIR [-- IMGCMP-OPTIONS...]" >&2; exit 2; }
name=$1 prog=$2 r2p=$3 node=$4 render=$5 chromium=$6 imgcmp=$7 outdir=$8
shift 8
[ "${1:-}" = -- ] && shift
case $name in */*|.*|'') echo "$0: bad test name '$name'" >&2; exit 2 ;; esac

if [ "$node" = none ] || ! [ -x "$node" ]; then
    echo "SKIP: no node (tools/deps.sh installs nodejs)"; exit 77
fi
if [ "$chromium" = none ] || ! [ -x "$chromium" ]; then
    echo "SKIP: no chromium (tools/deps.sh installs it)"; exit 77
fi
if ! [ -f "$(dirname "$render")/node_modules/three/build/three.module.js" ]; then
    echo "SKIP: three.js is not installed (npm ci in $(dirname "$render"); tools/deps.sh does it)"; exit 77
fi

dir=$outdir/$name
mkdir -p "$outdir" || exit 1
if command -v flock >/dev/null 2>&1; then
    exec 9>"$outdir/$name.lock"
    flock 9
fi
rm -rf "$dir"
mkdir -p "$dir" || exit 1
fail() { echo "three.js image test $name: FAIL: $*"; exit 1; }
log() { echo "--- last lines of $1:"; tail -n 15 "$1"; echo "---"; }
echo "three.js image test $name: $dir"

"$prog" --trace "$dir/$name.raygl" --png "$dir/gl.png" >"$dir/program.log" 2>&1 ||
    { log "$dir/program.log"; fail "the program failed"; }
"$r2p" -q "$dir/$name.raygl" --format gltf -o "$dir/glb" >"$dir/raygl2pov.log" 2>&1 ||
    { log "$dir/raygl2pov.log"; fail "raygl2pov --format gltf failed"; }
[ -s "$dir/glb/frame-00000.glb" ] || fail "raygl2pov wrote no glb/frame-00000.glb"
RAYGL_THREE_VERBOSE=1 "$node" "$render" --chromium "$chromium" "$dir/glb/frame-00000.glb" "$dir/three.png" \
    >"$dir/three.log" 2>&1 || { log "$dir/three.log"; fail "render-three.js failed"; }
cat "$dir/three.log"
"$imgcmp" "$@" --diff "$dir/diff.png" "$dir/gl.png" "$dir/three.png" ||
    fail "see $dir/diff.png (GL | three.js | difference)"
echo "three.js image test $name: PASS"
