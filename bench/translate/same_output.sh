#!/bin/sh
# same_output.sh: does a changed raygl2pov write the same files as another?
# The check every speed pass of bench/translate/README.md and every move of
# the translator's parts (issue 23) was held to.
#
#   bench/translate/same_output.sh BUILD OTHER_RAYGL2POV
#
# Translates with both binaries, -j 1, into the same output path in turn
# (notes and SDL may name it), and compares every file written and what
# each said: the strips trace (1 and 4 frames, bench_translate
# --write-trace) and the trace of every image test the build has run
# (BUILD/tests/image/out/NAME/NAME.raygl: run `meson test -C BUILD --suite
# image` first), each as POV-Ray SDL and as glTF (--format gltf: the .glb
# bytes). Then the look's options (camera, size, added lights, ray tracing,
# render settings, an include file) on a few lit traces, as SDL, and those
# both formats take as glTF. Prints the runs that differ; exits 1 if any
# does.
set -u
build=${1:?usage: same_output.sh BUILD OTHER_RAYGL2POV}
other=${2:?usage: same_output.sh BUILD OTHER_RAYGL2POV}
new=$build/translate/raygl2pov
tmp=$(mktemp -d /tmp/rgl-same-XXXXXX)
trap 'rm -rf "$tmp"' EXIT INT TERM
mkdir -p "$tmp/traces"
"$build/bench/translate/bench_translate" --write-trace "$tmp/traces/strips1.raygl" --frames 1 >/dev/null &&
    "$build/bench/translate/bench_translate" --write-trace "$tmp/traces/strips4.raygl" >/dev/null ||
    { echo "same_output: cannot write the strips traces" >&2; exit 2; }
for t in "$build"/tests/image/out/*/*.raygl; do
    [ -f "$t" ] && cp "$t" "$tmp/traces/"
done
printf '// a floor\nplane{y,-2 pigment{rgb 0.5}}\n' >"$tmp/floor.inc"

n=0 bad=0
# same TRACE LABEL OPTION...: one run of each binary, compared.
same() {
    t=$1 label=$2
    shift 2
    "$other" -q -j 1 "$t" -o "$tmp/out" "$@" >"$tmp/a.log" 2>&1
    ra=$?
    mkdir -p "$tmp/out" && mv "$tmp/out" "$tmp/a" # a failed run writes no folder
    "$new" -q -j 1 "$t" -o "$tmp/out" "$@" >"$tmp/b.log" 2>&1
    rb=$?
    mkdir -p "$tmp/out" && mv "$tmp/out" "$tmp/b"
    n=$((n + 1))
    # A message naming a temporary file names the process too.
    sed -i 's/\.raygl2pov-[0-9]*-/.raygl2pov-PID-/g' "$tmp/a.log" "$tmp/b.log"
    if [ $ra -ne $rb ] || ! diff -r "$tmp/a" "$tmp/b" >/dev/null 2>&1 ||
        ! cmp -s "$tmp/a.log" "$tmp/b.log"; then
        echo "differs: $label (exit $ra, $rb)"
        bad=$((bad + 1))
    fi
    rm -rf "$tmp/a" "$tmp/b"
}

ntraces=0
for t in "$tmp"/traces/*.raygl; do
    name=$(basename "$t" .raygl)
    ntraces=$((ntraces + 1))
    same "$t" "$name"
    same "$t" "$name (glTF)" --format gltf
done

# The look's options, on the lit traces there are (world coordinates:
# the example's and the lit tests' gluLookAt; eye coordinates elsewhere).
lights="--light=point at=1,2,3 color=1,0.5,0.25"
spot="--light=spot at=0,3,7 to=0,0,0 radius=10 falloff=20"
area="--light=area at=2,4,2 to=0,0,0 size=2,1 samples=3,3"
nlook=0
for name in strips1 example_scene lit_point lit_spot lit_directional tex_lit lights_per_object \
    paper_box; do
    t=$tmp/traces/$name.raygl
    [ -f "$t" ] || continue
    nlook=$((nlook + 1))
    same "$t" "$name --light x3" "$lights" "$spot" "$area"
    same "$t" "$name --camera-* --width" --camera-location 1,3,6 --camera-look-at 0,0,0 \
        --camera-fov 40 --width 320
    same "$t" "$name --camera-orthographic --override-space eye" --camera-orthographic \
        --override-space eye --height 100
    same "$t" "$name --no-gl-lights --light" --no-gl-lights "$spot"
    same "$t" "$name ray tracing" --reflection 0.4 --area-lights 3 --radiosity
    same "$t" "$name --no-shadows" --no-shadows --reflection 1
    same "$t" "$name render settings" --antialias --quality 5
    same "$t" "$name --include" --include "$tmp/floor.inc" "$area"
    same "$t" "$name --vertex-lighting" --vertex-lighting
    same "$t" "$name --light x3 (glTF)" --format gltf "$lights" "$spot"
    same "$t" "$name --camera-* (glTF)" --format gltf --camera-location 1,3,6 \
        --camera-look-at 0,0,0 --camera-fov 40 --width 320
    same "$t" "$name --no-gl-lights (glTF)" --format gltf --no-gl-lights "$spot"
done
echo "$ntraces traces (SDL and glTF), $nlook with the look's options: $n runs, $bad differ"
[ $bad -eq 0 ]
