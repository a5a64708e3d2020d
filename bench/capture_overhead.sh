#!/bin/sh
# capture_overhead.sh: glxgears frames per second without and with
# `raygl record` (every frame recorded, no snapshots), under Xvfb with
# Mesa's software GL, in alternating pairs so that a busy machine hurts
# both alike; prints each run and the medians.
#
#   bench/capture_overhead.sh BUILD_DIR [PAIRS] [SECONDS]
#
# glxgears prints its rate every 5 seconds; a run lasts SECONDS (default
# 16) and its figure is the mean of the reports after the first (which
# includes start-up). Needs xvfb-run and glxgears (mesa-utils).
set -eu
build=$(cd "$1" && pwd)
pairs=${2:-3}
secs=${3:-16}
command -v xvfb-run >/dev/null && command -v glxgears >/dev/null ||
    { echo "capture_overhead: needs xvfb-run and glxgears" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-capbench.XXXXXX")
trap 'rm -rf "$work"' EXIT

cat >"$work/pairs.sh" <<EOF
set -u
fps() { # the mean of glxgears' reports after the first
    awk '/frames in/ { n++; if (n > 1) { s += \$(NF-1); k++ } } END { if (k) printf "%.1f\\n", s / k; else print "nan" }'
}
i=0
while [ \$i -lt $pairs ]; do
    plain=\$(timeout $secs glxgears 2>&1 | fps)
    rec=\$(RAYGL_PRELOAD_LIB=$build/record/libraygl-preload.so \\
        timeout $secs sh $build/record/raygl record -o $work/gears.raygl -- glxgears 2>&1 | fps)
    size=\$(wc -c <$work/gears.raygl)
    echo "pair \$((i + 1)): plain \$plain fps, recorded \$rec fps (trace \$size bytes)"
    echo "\$plain \$rec" >>$work/figures
    i=\$((i + 1))
done
EOF
xvfb-run -a -s "-screen 0 1024x768x24" sh "$work/pairs.sh"
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else printf "%.1f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
p=$(cut -d' ' -f1 "$work/figures" | median)
r=$(cut -d' ' -f2 "$work/figures" | median)
echo "median: plain $p fps, recorded $r fps ($(awk -v p="$p" -v r="$r" 'BEGIN { printf "%+.1f%%", (r - p) / p * 100 }'))"
