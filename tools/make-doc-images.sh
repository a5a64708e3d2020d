#!/bin/sh
# make-doc-images.sh: the docs' pictures (docs/img/*.png), each two frames
# side by side, from the README example's scene (examples/example_scene.h) drawn
# once with OSMesa by the image-test program tests/programs/example_scene.c:
#
#   example-gl-pov.png   the OpenGL frame | the ray-traced frame (defaults)
#   shadows.png          --no-shadows | the default (the lights cast shadows)
#   reflection.png       the default | --reflection 0.3
#   area-lights.png      the default | --area-lights 6 (soft shadows)
#
# and, when Blender and ffmpeg are installed, three frames side by side,
# GL | POV-Ray (--no-shadows, as GL draws none) | Blender (raygl2pov
# --format gltf --render: Cycles, 16 samples), of three image-test
# programs: the README's scene, a textured floor and the paper's box:
#
#   gl-pov-blender-scene.png, gl-pov-blender-texture.png,
#   gl-pov-blender-box.png
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

if ! command -v blender >/dev/null || ! command -v ffmpeg >/dev/null; then
    echo "make-doc-images: blender or ffmpeg not installed: no GL | POV-Ray | Blender pictures" >&2
    exit 0
fi
r2p_abs=$(cd "$(dirname "$r2p")" && pwd)/$(basename "$r2p")
# three PROGRAM OUT: GL | POV-Ray | Blender of one image-test program
three() {
    d=$work/three-$1
    mkdir -p "$d"
    "$build/tests/image/imgtest_$1" --trace "$d/t.raygl" --png "$d/gl.png" >/dev/null
    (cd "$d" && "$r2p_abs" t.raygl -o pov --no-shadows -q &&
        povray pov/frame-00000.ini -D >povray.log 2>&1 &&
        "$r2p_abs" t.raygl -o glb --format gltf --render --samples 16 -q) ||
        { echo "make-doc-images: $1 failed (see $d)" >&2; exit 1; }
    # A 4-pixel grey line after each of the first two.
    ffmpeg -nostdin -loglevel error -y -i "$d/gl.png" -i "$d/pov/frame-00000.png" \
        -i "$d/glb/frame-00000.png" -filter_complex \
        "[0]pad=iw+4:ih:0:0:color=gray[a];[1]pad=iw+4:ih:0:0:color=gray[b];[a][b][2]hstack=inputs=3" \
        -frames:v 1 -pix_fmt rgb24 "docs/img/$2.png"
    echo "docs/img/$2.png ($(wc -c <"docs/img/$2.png") bytes)"
}
three example_scene gl-pov-blender-scene
three tex_lit gl-pov-blender-texture
three paper_box gl-pov-blender-box
