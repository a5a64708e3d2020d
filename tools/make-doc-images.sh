#!/bin/sh
# make-doc-images.sh: the docs' pictures (docs/img/*.png), each two frames
# side by side, from the README example's scene (examples/scene.h) drawn
# once with OSMesa by the image-test program tests/programs/example_scene.c:
#
#   example-gl-pov.png   the OpenGL frame | the ray-traced frame (defaults)
#   shadows.png          --no-shadows | the default (the lights cast shadows)
#   reflection.png       the default | --reflection 0.3
#   area-lights.png      the default | --area-lights 6 (soft shadows)
#
# Usage: tools/make-doc-images.sh [BUILD-DIR]   (default: build; it must
# have been built with the image tests, which need OSMesa and POV-Ray).
# The option pictures are antialiased; the OpenGL one and its ray-traced
# twin are not, as GL draws it. Prints each picture's path and size.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
prog=$build/tests/image/imgtest_example_scene
r2p=$build/translate/raygl2pov
imgcmp=$build/tests/image/imgcmp
for f in "$prog" "$r2p" "$imgcmp"; do
    [ -x "$f" ] || { echo "make-doc-images: $f missing: build first (ninja -C $build)" >&2; exit 1; }
done
command -v povray >/dev/null || { echo "make-doc-images: povray not found" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/img
"$prog" --trace "$work/scene.raygl" --png "$work/gl.png" --size 320x240

# render NAME [raygl2pov options]: the frame as $work/NAME.png
render() {
    name=$1
    shift
    "$r2p" "$work/scene.raygl" -o "$work/$name" "$@" >/dev/null
    (cd "$work/$name" && povray frame-00000.ini -D >povray.log 2>&1) ||
        { cat "$work/$name/povray.log" >&2; exit 1; }
    cp "$work/$name/frame-00000.png" "$work/$name.png"
}
# pair LEFT RIGHT OUT: LEFT | RIGHT into docs/img/OUT.png
pair() {
    "$imgcmp" --tol 255 --min-match 0 --pair "docs/img/$3.png" "$work/$1.png" "$work/$2.png" >/dev/null
    echo "docs/img/$3.png ($(wc -c <"docs/img/$3.png") bytes)"
}

render pov
pair gl pov example-gl-pov
render noshadows --no-shadows --antialias
render shadows --antialias
pair noshadows shadows shadows
render reflection --reflection 0.3 --antialias
pair shadows reflection reflection
render area --area-lights 6 --antialias
pair shadows area area-lights
