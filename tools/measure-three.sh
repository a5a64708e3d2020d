#!/bin/sh
# measure-three.sh: the figures of docs/mapping-gltf.md "three.js in
# Chromium": for each image-test program, GL's frame against its .glb
# rendered by three.js (tests/gltf/run-three-test.sh), as one Markdown row:
# the share of pixels within 2, 8 and 16 levels, the mean difference and
# the silhouette agreement (at 8 levels).
#
#   tools/measure-three.sh [BUILD_DIR [NAME...]]
#
# BUILD_DIR defaults to build; NAME defaults to the suite gltf-image's
# programs and three that show what glTF cannot carry (smooth_colors,
# tex_env_modulate, example_scene). The programs must be built
# (ninja -C BUILD_DIR tests/image/imgtest_NAME). Output in BUILD_DIR/measure-three/.
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] || set -- paper_box glu_quadrics lists tex_env_replace tex_lit lit_point \
    lit_directional lit_spot lists_colours_lit fog_linear smooth_colors tex_env_modulate example_scene
out=$build/measure-three
cmp=$build/tests/image/imgcmp
echo "| program | within 2/255 | within 8/255 | within 16/255 | mean | silhouette |"
echo "|---|---|---|---|---|---|"
for n in "$@"; do
    "$src/tests/gltf/run-three-test.sh" "$n" "$build/tests/image/imgtest_$n" "$build/translate/raygl2pov" \
        "$(command -v node)" "$src/tools/node/render-three.js" "$(command -v chromium)" "$cmp" "$out" \
        -- --min-match 0 >"$out.log" 2>&1 || { echo "| $n | failed: see $out.log |"; continue; }
    row="| $n"
    for t in 2 8 16; do
        row="$row | $("$cmp" --tol "$t" --min-match 0 "$out/$n/gl.png" "$out/$n/three.png" | awk '/^within/ { print $3 }')"
    done
    row="$row | $("$cmp" --tol 8 --min-match 0 "$out/$n/gl.png" "$out/$n/three.png" |
        awk '/^mean diff/ { m = $3 } /^silhouette/ { s = $2 } END { print m " | " s }')"
    echo "$row |"
done
