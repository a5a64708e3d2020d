#!/bin/sh
# measure-frames.sh: issue 14's and issue 22's measurement. Runs every
# multi-frame program (tests/programs/real_*.c, proj_*.c and the
# conformance-style conf_*.c of several frames, built by meson as
# BUILD/tests/image/framestest_NAME) through tests/image/run-frames-test.sh,
# and every single-frame conformance-style program (conf_*.c, built as
# BUILD/tests/image/imgtest_conf_*) through tests/image/run-image-test.sh:
# records it, translates each frame alone with --no-shadows, renders it with
# POV-Ray and compares it with imgcmp at 95% of pixels within 8/255 and a
# silhouette agreement of 0.95. Prints each failing frame with its figures
# and whether raygl2pov said a note for it, a table of every program (frames,
# passing, failing with and without a note, the worst within 8/255 and
# silhouette), then the share of frames that hold and the number that fail
# without a note (issue 22's aims: 98% and 0). A failing frame whose only
# note is NOTE_DEPTH ("depth test off or not GL_LESS", said of nearly every
# 2D draw) is counted apart too: that note seldom explains the difference.
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
frames=$(find "$build/tests/image" -maxdepth 1 -type f -name 'framestest_*' |
    sed -n 's|.*/framestest_\([A-Za-z0-9_]*\)$|\1|p' | sort)
singles=$(find "$build/tests/image" -maxdepth 1 -type f -name 'imgtest_conf_*' |
    sed -n 's|.*/imgtest_\(conf_[A-Za-z0-9_]*\)$|\1|p' | sort)
[ -n "$frames$singles" ] || { echo "$0: $build/tests/image: no framestest_* or imgtest_conf_* programs (ninja first)" >&2; exit 1; }
floors="--tol 8 --min-match 0.95 --check-gamma --min-silhouette 0.95"
notes='approximated\|not translated\|left out'
depth_note='approximated: depth test off or not GL_LESS'
# note_kind LOG: none, depth (NOTE_DEPTH alone) or other.
note_kind() {
    if ! grep -q "$notes" "$1"; then
        echo none
    elif grep "$notes" "$1" | grep -vq "$depth_note"; then
        echo other
    else
        echo depth
    fi
}
broken=0
# Every frame measured, one line each:
# PROGRAM FRAME PASS|FAIL WITHIN SILHOUETTE yes|no none|depth|other
: >"$out/frames.txt"
for p in $frames; do
    # shellcheck disable=SC2086 # floors: words on purpose
    "$src/tests/image/run-frames-test.sh" --name "$p" \
        --program "$build/tests/image/framestest_$p" \
        --raygl2pov "$build/translate/raygl2pov" --povray "$povray" \
        --imgcmp "$build/tests/image/imgcmp" --outdir "$out" --r2p-opt --no-shadows \
        -- $floors >"$out/$p.log" 2>&1
    if ! grep -q '^frames .*: [0-9]* of [0-9]* pass$' "$out/$p.log"; then
        echo "$p: did not run:"
        sed 's/^/    /' "$out/$p.log" | tail -5
        broken=$((broken + 1))
        continue
    fi
    grep '^frame [0-9]*: ' "$out/$p.log" | while read -r _ n verdict _ within _ sil _ note; do
        n=${n%:}
        echo "$p $n $verdict $within $sil $note $(note_kind "$out/$p/raygl2pov-$(printf %05d "$n").log")"
    done >>"$out/frames.txt"
done
for p in $singles; do
    # Lit conformance programs are rendered as their tests are (no shadows);
    # the unlit ones are the same either way.
    # shellcheck disable=SC2086 # floors: words on purpose
    "$src/tests/image/run-image-test.sh" --name "$p" \
        --program "$build/tests/image/imgtest_$p" \
        --raygl2pov "$build/translate/raygl2pov" --povray "$povray" \
        --imgcmp "$build/tests/image/imgcmp" --outdir "$out" --r2p-opt --no-shadows \
        -- $floors >"$out/$p.log" 2>&1
    if ! grep -q "^image test $p: \\(PASS\\|FAIL (see\\)" "$out/$p.log"; then
        echo "$p: did not run:"
        sed 's/^/    /' "$out/$p.log" | tail -5
        broken=$((broken + 1))
        continue
    fi
    verdict=FAIL
    grep -q "^image test $p: PASS" "$out/$p.log" && verdict=PASS
    note=no
    grep -q "$notes" "$out/$p/raygl2pov.log" && note=yes
    within=$(sed -n 's|^within 8/255: \([0-9.]*\) .*|\1|p' "$out/$p.log")
    sil=$(sed -n 's/^silhouette: \([0-9.]*\) .*/\1/p' "$out/$p.log")
    echo "$p 0 $verdict ${within:-0} ${sil:-0} $note $(note_kind "$out/$p/raygl2pov.log")" >>"$out/frames.txt"
done
[ -s "$out/frames.txt" ] || { echo "no frame measured"; exit 1; }
awk '$3 == "FAIL" { printf "FAIL %s frame %s: within 8/255 %s, silhouette %s, note %s\n", $1, $2, $4, $5, $6 }' \
    "$out/frames.txt"
awk '
{
    if (!($1 in n)) { order[++np] = $1; worst_w[$1] = 2; worst_s[$1] = 2 }
    n[$1]++
    if ($3 == "PASS") pass[$1]++
    else if ($6 == "yes") { noted[$1]++; if ($7 == "depth") depth[$1]++ }
    else silent[$1]++
    if ($4 + 0 < worst_w[$1]) worst_w[$1] = $4 + 0
    if ($5 + 0 < worst_s[$1]) worst_s[$1] = $5 + 0
}
END {
    printf "%-30s %6s %5s %6s %6s %7s %9s %10s\n", "program", "frames", "pass", "noted", "depth", "silent", "within 8", "silhouette"
    for (i = 1; i <= np; i++) {
        p = order[i]
        printf "%-30s %6d %5d %6d %6d %7d %9.5f %10.5f\n", p, n[p], pass[p], noted[p], depth[p], silent[p], worst_w[p], worst_s[p]
        t += n[p]; tp += pass[p]; tn += noted[p]; ts += silent[p]; td += depth[p]
        if (p ~ /^conf_/) { c += n[p]; cp += pass[p]; cs += silent[p]; cd += depth[p] }
        else { r += n[p]; rp += pass[p]; rs += silent[p]; rd += depth[p] }
    }
    if (r) printf "real-style and other multi-frame programs: %d of %d frames hold (%.1f%%), %d fail without a note, %d with NOTE_DEPTH alone\n", rp, r, 100 * rp / r, rs, rd
    if (c) printf "conformance-style (conf_*): %d of %d frames hold (%.1f%%), %d fail without a note, %d with NOTE_DEPTH alone\n", cp, c, 100 * cp / c, cs, cd
    printf "frames holding 95%% within 8/255 and silhouette 0.95: %d of %d (%.1f%%); failing with a note: %d (%d with NOTE_DEPTH alone); failing without a note: %d\n", tp, t, 100 * tp / t, tn, td, ts
}' "$out/frames.txt"
[ $broken -eq 0 ]
