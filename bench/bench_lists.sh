#!/bin/sh
# bench_lists.sh: a display list of 10,000 triangles called 1,000 times in
# one frame, side by side with the same list called once (issue 5: the
# scene must stay close to a single copy in size, parse time and memory).
#
#   bench/bench_lists.sh BUILD_DIR [RUNS] [RUNS_VERTEX_COLOURS]
#
# bench_lists writes each trace through the raygl API with no GL context;
# raygl2pov translates it; POV-Ray parses and renders it at 16x16 (-D, no
# antialiasing), so its time is the parse. Per configuration, medians of
# RUNS runs (default 5; RUNS_VERTEX_COLOURS, default 3, for the lists with
# a colour per vertex, whose 1,000 copies take POV-Ray half a minute):
#   trace      bytes of the trace
#   r2p s      raygl2pov's wall time
#   sdl        bytes of frame-00000.pov
#   parse s    POV-Ray's "Parse Time"
#   peak MB    POV-Ray's maximum resident set (/usr/bin/time -v)
# Figures only: never pass/fail.
set -eu
build=$(cd "$1" && pwd)
runs=${2:-5}
runs_vc=${3:-3}
[ "$runs" -ge 1 ] && [ "$runs_vc" -ge 1 ] || { echo "usage: $0 BUILD_DIR [RUNS] [RUNS_VERTEX_COLOURS]" >&2; exit 2; }
gen=$build/bench/bench_lists
r2p=$build/translate/raygl2pov
timev=/usr/bin/time
[ -x "$timev" ] || timev=
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-lists.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"

now() { date +%s.%N; }
# median FORMAT < numbers, one a line
median() { sort -g | awk -v f="$1" '{v[NR] = $1} END {if (NR == 0) print "n/a"; else printf f "\n", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

printf '%-16s %6s %10s %8s %10s %9s %8s\n' list calls trace 'r2p s' sdl 'parse s' 'peak MB'
for colours in one vertex; do
    n=$runs
    opt=
    if [ $colours = vertex ]; then
        n=$runs_vc
        opt=--vertex-colours
    fi
    for calls in 1 1000; do
        name=$colours-$calls
        "$gen" --calls $calls --out $name.raygl $opt
        : >r2p.t
        : >parse.t
        : >peak.t
        i=0
        while [ $i -lt "$n" ]; do
            rm -rf $name
            t0=$(now)
            "$r2p" $name.raygl -o $name -q
            t1=$(now)
            awk "BEGIN {print $t1 - $t0}" >>r2p.t
            # From where raygl2pov ran: the .ini's paths are relative to it.
            if [ -n "$timev" ]; then
                "$timev" -v povray $name/frame-00000.ini +W16 +H16 -D +O$name/out.png >$name/pov.log 2>&1
            else
                povray $name/frame-00000.ini +W16 +H16 -D +O$name/out.png >$name/pov.log 2>&1
            fi
            sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' $name/pov.log >>parse.t
            sed -n 's/.*Maximum resident set size (kbytes): \([0-9]*\).*/\1/p' $name/pov.log |
                awk '{print $1 / 1024}' >>peak.t
            i=$((i + 1))
        done
        printf '%-16s %6s %10s %8s %10s %9s %8s\n' "$colours colour" $calls \
            $(wc -c <$name.raygl) $(median %.3f <r2p.t) $(wc -c <$name/frame-00000.pov) \
            $(median %.3f <parse.t) $(median %.1f <peak.t)
    done
done
