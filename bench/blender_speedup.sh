#!/bin/sh
# blender_speedup.sh: wall time to render a trace's .glb frames with
# Blender (raygl2pov --format gltf --render), -j 1 against -j <cores>,
# median of RUNS runs each (default 3), and the time per frame.
#
#   bench/blender_speedup.sh BUILD_DIR [RUNS] [FRAMES] [WIDTH HEIGHT] [SAMPLES]
#
# The trace is tests/render's animation (mkanim), FRAMES frames (default
# 8) at WIDTH x HEIGHT (default 160x120), SAMPLES Cycles samples (default
# 16). The two configurations run in turn inside each round, so that a
# busy machine hurts them alike:
#   j1   one Blender at a time, Cycles on every core (--threads = cores)
#   jN   one Blender per core, one thread each (the default)
# Each Blender run starts Blender (about 2-3 s here), imports and renders:
# running several at once hides the start-up.
set -eu
build=$(cd "$1" && pwd)
runs=${2:-3}
frames=${3:-8}
w=${4:-160}
h=${5:-120}
samples=${6:-16}
r2p=$build/translate/raygl2pov
cores=$(nproc)
command -v blender >/dev/null || { echo "blender_speedup: blender not installed" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
"$build/tests/render/mkanim" anim.raygl "$frames" "$w" "$h"
"$r2p" anim.raygl -o frames --format gltf -q

now() { date +%s.%N; }
median() { sort -n | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
: >t.j1
: >t.jN
for i in $(seq 1 "$runs"); do
    for c in j1 jN; do
        rm -f frames/*.png
        case $c in
        j1) j=1 ;;
        jN) j=$cores ;;
        esac
        t0=$(now)
        "$build/translate/raygl-render" frames --engine blender --samples "$samples" -j "$j" -q
        t1=$(now)
        awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f\n", b - a}' >>"t.$c"
        n=$(ls frames/*.png | wc -l)
        [ "$n" -eq "$frames" ] || { echo "only $n PNGs"; exit 1; }
    done
done
m1=$(median <t.j1)
mN=$(median <t.jN)
echo "$frames frames at ${w}x${h}, $samples samples, $cores cores, median of $runs runs (seconds):"
printf '  -j 1 (Cycles on %d threads)   %7.2f   runs: %s  (%.2f s/frame)\n' "$cores" "$m1" \
    "$(tr '\n' ' ' <t.j1)" "$(awk -v a="$m1" -v n="$frames" 'BEGIN {print a / n}')"
printf '  -j %d (1 thread each)          %7.2f   runs: %s  (%.2f s/frame)\n' "$cores" "$mN" \
    "$(tr '\n' ' ' <t.jN)" "$(awk -v a="$mN" -v n="$frames" 'BEGIN {print a / n}')"
printf 'speed-up of -j %d: %.2fx over -j 1\n' "$cores" "$(awk -v a="$m1" -v b="$mN" 'BEGIN {print a / b}')"
uptime
