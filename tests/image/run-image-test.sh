#!/bin/sh
# run-image-test.sh: one image test, GL frame against POV-Ray frame.
#
#   run-image-test.sh --name NAME --program PROG --raygl2pov R2P --povray POVRAY
#                     --imgcmp IMGCMP --outdir DIR [--size WxH] [--r2p-opt OPT]...
#                     [--r2p-says nothing|REGEX]... [--figures FILE]
#                     [--no-program-leak-check] [--ini-antialias] [-- IMGCMP-OPTIONS...]
#
# 1. PROG --trace DIR/NAME/NAME.raygl --png DIR/NAME/gl.png [--size WxH]
#    draws one frame with OSMesa, records it and writes the GL image;
# 2. in DIR/NAME: R2P NAME.raygl -o pov [OPT...]   translates the trace
#    (each --r2p-opt adds one raygl2pov option, e.g. --no-shadows); with
#    --r2p-says, what it prints must be nothing, or match (image-test-args.sh);
# 3. in DIR/NAME: POVRAY pov/frame-00000.ini -D -A   renders it (the .ini
#    names the size, the gamma and pov/frame-00000.png);
# 4. IMGCMP [IMGCMP-OPTIONS] --diff DIR/NAME/diff.png gl.png pov/frame-00000.png
#    prints the figures and decides;
# 5. with --figures FILE, check-figures.sh holds the figures to FILE's line
#    for NAME (tests/image/figures.txt: a drop below it fails).
#
# --ini-antialias renders with the .ini's antialiasing (raygl2pov turns it
# on for a frame that accumulated jittered passes) instead of -A.
#
# --no-program-leak-check turns LeakSanitizer off for PROG only: under Xvfb,
# Mesa's GLX driver is unloaded before the leak check runs, so its per-display
# allocations show as leaks from an unknown module that no suppression can
# name. RayGL's recorder is leak-checked by the OSMesa image tests.
#
# Everything stays in DIR/NAME for inspection (diff.png: GL | POV | amplified
# difference). Exit 0 on PASS, 1 on FAIL or on any step that fails, 2 on bad
# usage. Meson passes the paths (tests/image/meson.build).
set -u

usage() {
    echo "usage: $0 --name NAME --program PROG --raygl2pov R2P --povray POVRAY --imgcmp IMGCMP --outdir DIR [--size WxH] [--r2p-opt OPT]... [--r2p-says nothing|REGEX]... [--figures FILE] [--no-program-leak-check] [--ini-antialias] [-- IMGCMP-OPTIONS...]" >&2
    exit 2
}

. "$(dirname "$0")/image-test-args.sh"
program_leak_check=1 pov_aa=-A
while [ $# -gt 0 ]; do
    case $1 in
    --help) usage ;;
    --) shift; break ;;
    --no-program-leak-check) program_leak_check=0; shift; continue ;;
    --ini-antialias) pov_aa=; shift; continue ;;
    esac
    common_option "$@" || usage
    shift 2
done
common_finish

dir=$outdir/$name
# Runs of one test at once (meson test --repeat starts them in parallel)
# share its directory: they take turns.
mkdir -p "$outdir" || exit 1
if command -v flock >/dev/null 2>&1; then
    exec 9>"$outdir/$name.lock"
    flock 9
fi
rm -rf "$dir"
mkdir -p "$dir" || exit 1
fail() {
    echo "image test $name: FAIL: $*"
    exit 1
}
# Prints the end of a step's log when it failed.
show_log() {
    echo "--- last lines of $1:"
    tail -n 25 "$1"
    echo "---"
}

echo "image test $name: $dir"

# 1. The GL frame and its trace.
prog_asan_options=${ASAN_OPTIONS:-}
if [ "$program_leak_check" -eq 0 ]; then
    prog_asan_options="${prog_asan_options:+$prog_asan_options:}detect_leaks=0"
fi
if [ -n "$size" ]; then
    ASAN_OPTIONS=$prog_asan_options "$prog" --trace "$dir/$name.raygl" --png "$dir/gl.png" --size "$size" >"$dir/program.log" 2>&1
else
    ASAN_OPTIONS=$prog_asan_options "$prog" --trace "$dir/$name.raygl" --png "$dir/gl.png" >"$dir/program.log" 2>&1
fi
rc=$?
if [ $rc -ne 0 ]; then
    show_log "$dir/program.log"
    fail "the program exited with $rc"
fi
[ -s "$dir/$name.raygl" ] || fail "the program wrote no trace"
[ -s "$dir/gl.png" ] || fail "the program wrote no GL image"

# 2. Translation, run where POV-Ray will run so that relative paths agree.
# shellcheck disable=SC2086 # r2p_opts: words checked above, split on purpose
(cd "$dir" && "$r2p" "$name.raygl" -o pov $r2p_opts) >"$dir/raygl2pov.log" 2>&1
rc=$?
if [ $rc -ne 0 ]; then
    show_log "$dir/raygl2pov.log"
    fail "raygl2pov exited with $rc"
fi
if [ -s "$dir/raygl2pov.log" ]; then
    echo "raygl2pov said:"
    sed -n '1,20p' "$dir/raygl2pov.log"
fi
r2p_says_check "$dir/raygl2pov.log" || fail "raygl2pov's messages (--r2p-says)"
[ -f "$dir/pov/frame-00000.pov" ] && [ -f "$dir/pov/frame-00000.ini" ] ||
    fail "raygl2pov wrote no pov/frame-00000.pov and .ini (it wrote: $(ls "$dir/pov" 2>/dev/null | tr '\n' ' '))"
nframes=$(ls "$dir/pov" | grep -c '^frame-[0-9]*\.pov$')
[ "$nframes" -eq 1 ] || fail "the program drew one frame, raygl2pov wrote $nframes"

# 3. The POV-Ray frame: no display, no antialiasing (3.7 rejects +A0).
(cd "$dir" && "$povray" pov/frame-00000.ini -D $pov_aa) >"$dir/povray.log" 2>&1
rc=$?
# On a loaded machine POV-Ray may give up starting its worker threads: that
# says nothing of the scene, so it gets one more try (as raygl-render does).
if [ $rc -ne 0 ] && grep -q "Timed out waiting for worker thread startup" "$dir/povray.log"; then
    echo "note: povray timed out starting its threads; trying once more"
    (cd "$dir" && "$povray" pov/frame-00000.ini -D $pov_aa) >"$dir/povray.log" 2>&1
    rc=$?
fi
if [ $rc -ne 0 ]; then
    show_log "$dir/povray.log"
    fail "povray exited with $rc"
fi
[ -s "$dir/pov/frame-00000.png" ] || {
    show_log "$dir/povray.log"
    fail "povray wrote no pov/frame-00000.png (Output_File_Name in the .ini?)"
}
grep 'Warning:' "$dir/povray.log" | sort | uniq -c | sed 's/^/povray: /'

# 4. The comparison.
"$imgcmp" "$@" --diff "$dir/diff.png" "$dir/gl.png" "$dir/pov/frame-00000.png" >"$dir/imgcmp.log" 2>&1
rc=$?
cat "$dir/imgcmp.log"
# 5. The figures against the file's, whatever imgcmp decided, so that a
# test log always holds them (tools/update-figures.py).
frc=0
measured=$(figures_of "$dir/imgcmp.log")
if [ -n "$figures" ] && [ -n "$measured" ]; then
    # shellcheck disable=SC2086 # three words on purpose
    "$(dirname "$0")/check-figures.sh" "$figures" "$name" $measured
    frc=$?
fi
if [ $rc -ne 0 ]; then
    echo "image test $name: FAIL (see $dir/diff.png: GL | POV | difference)"
    exit 1
fi
if [ $frc -ne 0 ]; then
    echo "image test $name: FAIL: the figures do not hold to $figures (above)"
    exit 1
fi
echo "image test $name: PASS"
exit 0
