#!/bin/sh
# measure-frames.sh: issue 14's measurement. Runs every multi-frame program
# (tests/programs/real_*.c and proj_*.c, built by meson as
# BUILD/tests/image/framestest_NAME) through tests/image/run-frames-test.sh:
# records it, translates each frame with --no-shadows, renders it with
# POV-Ray and compares it with imgcmp at 95% of pixels within 8/255 and a
# silhouette agreement of 0.95. Prints each failing frame with its figures
# and whether raygl2pov said a note for it, then the share of frames that
# hold.
#
#   tools/measure-frames.sh [BUILD] [OUTDIR]
#
# BUILD defaults to build, OUTDIR to BUILD/measure. Takes minutes: not part
# of meson test. Exit 0 when it ran (whatever the share), 1 when a program
# could not be run, 2 on bad usage.
set -u
[ $# -le 2 ] || { echo "usage: $0 [BUILD] [OUTDIR]" >&2; exit 2; }
src=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
out=${2:-$build/measure}
[ -d "$build/tests/image" ] || { echo "$0: $build: no tests/image (meson setup, ninja first)" >&2; exit 2; }
povray=$(command -v povray) || { echo "$0: povray: not found" >&2; exit 1; }
mkdir -p "$out" || exit 1
build=$(cd "$build" && pwd) && out=$(cd "$out" && pwd) || exit 1
progs=$(find "$build/tests/image" -maxdepth 1 -type f -name 'framestest_*' |
    sed -n 's|.*/framestest_\([A-Za-z0-9_]*\)$|\1|p' | sort)
[ -n "$progs" ] || { echo "$0: $build/tests/image: no framestest_* programs (ninja first)" >&2; exit 1; }
total=0 pass=0 silent=0 broken=0
for p in $progs; do
    "$src/tests/image/run-frames-test.sh" --name "$p" \
        --program "$build/tests/image/framestest_$p" \
        --raygl2pov "$build/translate/raygl2pov" --povray "$povray" \
        --imgcmp "$build/tests/image/imgcmp" --outdir "$out" --r2p-opt --no-shadows \
        -- --tol 8 --min-match 0.95 --check-gamma --min-silhouette 0.95 >"$out/$p.log" 2>&1
    if ! grep -q '^frames .*: [0-9]* of [0-9]* pass$' "$out/$p.log"; then
        echo "$p: did not run:"
        sed 's/^/    /' "$out/$p.log" | tail -5
        broken=$((broken + 1))
        continue
    fi
    while read -r _ n verdict _ within _ sil _ note; do
        total=$((total + 1))
        if [ "$verdict" = PASS ]; then
            pass=$((pass + 1))
        else
            [ "$note" = no ] && silent=$((silent + 1))
            echo "FAIL $p frame ${n%:}: within 8/255 $within, silhouette $sil, note $note"
        fi
    done <<EOT
$(grep '^frame [0-9]*: ' "$out/$p.log")
EOT
done
[ $total -gt 0 ] || { echo "no frame measured"; exit 1; }
awk -v p=$pass -v t=$total -v s=$silent 'BEGIN {
    printf "frames holding 95%% within 8/255 and silhouette 0.95: %d of %d (%.1f%%); failing without a note: %d\n", p, t, 100 * p / t, s }'
[ $broken -eq 0 ]
