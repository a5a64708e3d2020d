#!/bin/sh
# sdl_parse.sh: what POV-Ray spends parsing raygl2pov's SDL of a large lit
# torus, side by side with a hand-written ideal of the same triangles
# (issue 16: target parse CPU <= 1.15x, peak memory <= 1.25x the ideal).
#
#   bench/sdl_parse.sh BUILD_DIR [RUNS] [TRIS...]
#
# For each size (default 262144 and 1048576 triangles) and colouring (a
# colour per vertex "vc", one colour "1c"): bench_translate --sdl writes
# our SDL of bench_translate's strips frame, bench/sdl/ideal the ideal
# (one mesh2, shared vertices and normals, one texture or the vertex
# colours as one uv-mapped image). POV-Ray parses each (+W32 +H24, -D,
# no antialiasing, +WT1: the render is nothing), RUNS times (default 3),
# ours and the ideal interleaved. Printed: medians of POV-Ray's parse CPU
# time (its "Parse Time ... CPU-seconds") and of its peak memory
# (/usr/bin/time -v), and ours / ideal. Figures only: never pass/fail.
#
# With BASE=OTHER_BUILD_DIR (a build of an earlier commit), that build's
# SDL of the same frame is parsed in the same rounds and printed as a
# "base" row beside ours (its bench_translate needs no --sdl: the frame
# is taken from --keep).
set -eu
[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [RUNS] [TRIS...]" >&2; exit 2; }
build=$(cd "$1" && pwd)
runs=${2:-3}
[ $# -ge 2 ] && shift 2 || shift 1
sizes=${*:-262144 1048576}
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-sdlparse.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"

# median < numbers, one a line
median() { sort -g | awk '{v[NR] = $1} END {if (NR == 0) print "n/a"; else print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# parse FILE.pov LOG: POV-Ray's parse CPU seconds and peak MB appended to LOG
parse() {
    /usr/bin/time -v povray +I"$1" +O"$work/out.png" +W32 +H24 -D -A +WT1 File_Gamma=2.2 \
        >"$work/pov.log" 2>&1 || { echo "sdl_parse.sh: povray failed on $1 (see below)" >&2; tail -5 "$work/pov.log" >&2; exit 1; }
    cpu=$(grep -A1 'Parse Time' "$work/pov.log" | sed -n 's/.* with \([0-9.]*\) CPU-seconds.*/\1/p')
    kb=$(sed -n 's/.*Maximum resident set size (kbytes): *//p' "$work/pov.log")
    echo "$cpu $(awk -v k="$kb" 'BEGIN {print k / 1024}')" >>"$2"
}

base=${BASE:-}
[ -z "$base" ] || base=$(cd "$base" && pwd)
kinds="ours"
[ -z "$base" ] || kinds="base ours"
printf '%-9s %-3s %-4s %9s %9s %6s   %9s %9s %6s   %8s %8s\n' tris col sdl 'parse s' 'ideal s' ratio \
    'peak MB' 'ideal MB' ratio 'SDL' 'ideal'
for n in $sizes; do
    mkdir -p "$n"
    "$build/bench/translate/bench_translate" --frames 1 --tris "$n" --sdl "$work/$n"
    if [ -n "$base" ]; then
        "$base/bench/translate/bench_translate" --frames 1 --tris "$n" --runs 1 --no-printf \
            --povray none --keep "$work/$n" --layout strips >/dev/null
        "$base/bench/translate/bench_translate" --frames 1 --tris "$n" --runs 1 --no-printf \
            --povray none --keep "$work/$n" --layout strips1 >/dev/null
        mv "$n/strips.pov" "$n/base-vc.pov"
        mv "$n/strips1.pov" "$n/base-1c.pov"
    fi
    "$build/bench/sdl/ideal" --tris "$n" "$n/ideal-vc.pov"
    "$build/bench/sdl/ideal" --tris "$n" --one-colour "$n/ideal-1c.pov"
    for c in vc 1c; do
        rm -f "$n/ours-$c.log" "$n/base-$c.log" "$n/ideal-$c.log"
    done
    for r in $(seq "$runs"); do
        for c in vc 1c; do
            for k in $kinds ideal; do
                (cd "$n" && parse "$k-$c.pov" "$k-$c.log")
            done
        done
    done
    for c in vc 1c; do
        is=$(cut -d' ' -f1 "$n/ideal-$c.log" | median)
        im=$(cut -d' ' -f2 "$n/ideal-$c.log" | median)
        isz=$(du -k "$n/ideal-$c.pov" | cut -f1)
        for k in $kinds; do
            os=$(cut -d' ' -f1 "$n/$k-$c.log" | median)
            om=$(cut -d' ' -f2 "$n/$k-$c.log" | median)
            osz=$(du -k "$n/$k-$c.pov" | cut -f1)
            awk -v n="$n" -v c="$c" -v k="$k" -v os="$os" -v is="$is" -v om="$om" -v im="$im" -v a="$osz" -v b="$isz" \
                'BEGIN {printf "%-9s %-3s %-4s %9.3f %9.3f %5.2fx   %9.1f %9.1f %5.2fx   %6.1fMB %6.1fMB\n", n, c, k, os, is, os / is, om, im, om / im, a / 1024, b / 1024}'
        done
    done
    rm -rf "$n"
done
