#!/bin/sh
# same_output.sh: does a changed raygl2pov write the same files as another?
# The check every speed pass of bench/translate/README.md was held to.
#
#   bench/translate/same_output.sh BUILD OTHER_RAYGL2POV
#
# Translates with both binaries, -j 1, into the same output path in turn
# (notes and SDL may name it), and compares every file written and what
# each said: the strips trace (1 and 4 frames, bench_translate
# --write-trace) and the trace of every image test the build has run
# (BUILD/tests/image/out/NAME/NAME.raygl: run `meson test -C BUILD --suite
# image` first). Prints the traces that differ; exits 1 if any does.
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
n=0 bad=0
for t in "$tmp"/traces/*.raygl; do
    name=$(basename "$t" .raygl)
    "$other" -q -j 1 "$t" -o "$tmp/out" >"$tmp/a.log" 2>&1
    ra=$?
    mkdir -p "$tmp/out" && mv "$tmp/out" "$tmp/a" # a failed run writes no folder
    "$new" -q -j 1 "$t" -o "$tmp/out" >"$tmp/b.log" 2>&1
    rb=$?
    mkdir -p "$tmp/out" && mv "$tmp/out" "$tmp/b"
    n=$((n + 1))
    if [ $ra -ne $rb ] || ! diff -r "$tmp/a" "$tmp/b" >/dev/null 2>&1 ||
        ! cmp -s "$tmp/a.log" "$tmp/b.log"; then
        echo "differs: $name (exit $ra, $rb)"
        bad=$((bad + 1))
    fi
    rm -rf "$tmp/a" "$tmp/b"
done
echo "$n traces, $bad differ"
[ $bad -eq 0 ]
