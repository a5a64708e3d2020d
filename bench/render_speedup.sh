#!/bin/sh
# render_speedup.sh: wall time to render a 48-frame trace with -j 1 and with
# -j (all cores), side by side, median of RUNS runs each (default 3).
#
#   bench/render_speedup.sh BUILD_DIR [RUNS] [WIDTH HEIGHT]
#
# The trace is tests/render's animation (mkanim: a cube over a checkered
# floor, 48 frames). Three configurations, run in turn inside each round so
# that a busy machine hurts them alike:
#   j1        raygl2pov --render -j 1: one povray at a time, which threads
#             itself over every core (POV-Ray's +WT = cores / -j)
#   j1-wt1    -j 1 with POV-Ray held to one thread (--povray wrapper adding
#             +WT1): the single-process, single-thread baseline
#   jN        -j <cores>: one povray per core, one thread each (the default)
set -eu
build=$(cd "$1" && pwd)
runs=${2:-3}
w=${3:-320}
h=${4:-240}
r2p=$build/translate/raygl2pov
cores=$(nproc)
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
"$build/tests/render/mkanim" anim.raygl 48 "$w" "$h"
"$r2p" anim.raygl -o frames -q
printf '#!/bin/sh\nexec povray "$@" +WT1\n' >povray-wt1
chmod +x povray-wt1

now() { date +%s.%N; }
median() { sort -n | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
: >t.j1
: >t.j1wt1
: >t.jN
for i in $(seq 1 "$runs"); do
    for c in j1 j1wt1 jN; do
        rm -f frames/*.png
        case $c in
        j1) set -- -j 1 ;;
        j1wt1) set -- -j 1 --povray "$work/povray-wt1" ;;
        jN) set -- -j "$cores" ;;
        esac
        t0=$(now)
        "$r2p" anim.raygl -o frames --render -q "$@"
        t1=$(now)
        awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f\n", b - a}' >>"t.$c"
        n=$(ls frames/*.png | wc -l)
        [ "$n" -eq 48 ] || { echo "only $n PNGs"; exit 1; }
    done
done
m1=$(median <t.j1)
m1s=$(median <t.j1wt1)
mN=$(median <t.jN)
echo "48 frames at ${w}x${h}, $cores cores, median of $runs runs (seconds):"
printf '  -j 1 (povray +WT%d)   %7.2f   runs: %s\n' "$cores" "$m1" "$(tr '\n' ' ' <t.j1)"
printf '  -j 1 (povray +WT1)   %7.2f   runs: %s\n' "$m1s" "$(tr '\n' ' ' <t.j1wt1)"
printf '  -j %d (povray +WT1)   %7.2f   runs: %s\n' "$cores" "$mN" "$(tr '\n' ' ' <t.jN)"
printf 'speed-up of -j %d: %.2fx over -j 1, %.2fx over one single-threaded povray\n' \
    "$cores" "$(awk -v a="$m1" -v b="$mN" 'BEGIN {print a / b}')" "$(awk -v a="$m1s" -v b="$mN" 'BEGIN {print a / b}')"
