#!/bin/sh
# test_parallel.sh: --sshloginfile with GNU parallel on this machine (":").
#
#   test_parallel.sh RAYGL2POV RAYGL_RENDER MKANIM IMGCMP
#
# Every frame is rendered by `raygl-render DIR --task N` jobs that GNU
# parallel starts, and matches a local render pixel for pixel. Skipped (77)
# when GNU parallel is not installed.
. "$(dirname "$0")/common.sh"

if ! parallel --version 2>/dev/null | grep -q "GNU parallel"; then
    echo "SKIP: GNU parallel is not installed (tools/deps.sh installs it)"
    exit 77
fi
cd "$work" || exit 1
"$mkanim" anim.raygl 5 80 60 || exit 1
echo ":" >hosts
run "$r2p" anim.raygl -o remote --sshloginfile hosts
expect_rc 0 "--sshloginfile hosts"
grep -q "^raygl2pov: 5 frames rendered in .* (.* frames/min, over SSH), 0 already rendered, 0 failed$" \
    "$work/err" && ok "the summary, as for a local render" || fail "summary: $(cat "$work/err")"
run "$r2p" anim.raygl -o local --render -q
expect_rc 0 "local render"
n=$(same_pngs local remote)
[ "$n" -eq 5 ] && ok "5 frames rendered by GNU parallel match the local render" ||
    fail "compared $n frames"
[ "$(wc -l <remote/render.list)" -eq 5 ] || fail "render.list: $(cat remote/render.list)"
# A broken frame: parallel reports it, the others are rendered.
rm -f remote/frame-00003.png
echo "garbage" >remote/frame-00003.pov
run "$r2p" anim.raygl -o remote --frames 0-2 -q
run "$render" remote --sshloginfile hosts
expect_rc 1 "raygl-render --sshloginfile with a broken frame"
grep -q "remote/frame-00003.ini: povray failed" "$work/err" || fail "message: $(cat "$work/err")"
grep -q "^raygl-render: 0 frames rendered in .*, 4 already rendered, 1 failed$" "$work/err" ||
    fail "summary with a broken frame: $(cat "$work/err")"
[ "$fails" -eq 0 ] && echo "parallel: all checks passed" || echo "parallel: $fails check(s) failed"
[ "$fails" -eq 0 ]
