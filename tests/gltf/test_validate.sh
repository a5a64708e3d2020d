#!/bin/sh
# test_validate.sh: every .glb the glTF tests write passes the Khronos
# glTF-Validator with no error and no warning.
#
#   test_validate.sh NODE VALIDATE_JS RAYGL2POV XVFB_RUN TEST_GLTF MKTRACES MKTEXTRACE
#                    [PROGRAM...]
#
# The .glb files: test_gltf's hand-built scenes, the translator tests'
# traces (mktraces, mktextrace), and each PROGRAM (tests/programs, OSMesa;
# glut_* under XVFB_RUN) recorded and translated with --format gltf. NODE
# or XVFB_RUN may be "none". Exit 77 (skip) only when node is missing; a
# validator that cannot be installed fails.
set -u
node=$1 validate=$2 r2p=$3 xvfb=$4 unit=$5 mktraces=$6 mktextrace=$7
shift 7
if [ "$node" = none ] || ! [ -x "$node" ]; then
    echo "SKIP: node not found: the glTF validator needs nodejs (tools/deps.sh installs it)"
    exit 77
fi
tools=$(dirname "$validate")
if ! [ -d "$tools/node_modules/gltf-validator" ]; then
    echo "installing the validator: npm ci in $tools"
    (cd "$tools" && npm ci --no-audit --no-fund --loglevel=error) ||
        { echo "FAIL: cannot install gltf-validator (npm ci in $tools)"; exit 1; }
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

mkdir "$work/glb"
"$unit" "$work/glb" >"$work/unit.log" 2>&1 || fail "test_gltf: $(tail -n 3 "$work/unit.log")"
"$mktraces" "$work" || fail "mktraces"
"$mktextrace" "$work/tex.raygl" || fail "mktextrace"
for t in good tex; do
    "$r2p" -q "$work/$t.raygl" --format gltf -o "$work/glb" --name-pattern "$t-{index}" \
        2>"$work/err" || fail "raygl2pov $t.raygl: $(cat "$work/err")"
done
for prog in "$@"; do
    name=$(basename "$prog" | sed 's/^imgtest_//')
    run="" leak=${ASAN_OPTIONS:-}
    case $name in glut_*)
        [ "$xvfb" = none ] && { echo "no xvfb-run: $name left out"; continue; }
        # under ASan: Mesa's GLX driver is unloaded before the leak check
        # (tests/image/run-image-test.sh, --no-program-leak-check)
        leak="${leak:+$leak:}detect_leaks=0"
        run="$xvfb -a" ;;
    esac
    # shellcheck disable=SC2086
    ASAN_OPTIONS=$leak $run "$prog" --trace "$work/$name.raygl" --png "$work/$name.png" >"$work/err" 2>&1 ||
        { fail "$name: $(tail -n 2 "$work/err")"; continue; }
    "$r2p" -q "$work/$name.raygl" --format gltf -o "$work/glb" --name-pattern "$name-{index}" \
        2>"$work/err" || fail "raygl2pov $name: $(cat "$work/err")"
done
n=$(ls "$work/glb" | grep -c '\.glb$')
[ "$n" -ge $((5 + $#)) ] || fail "only $n .glb files written"
if "$node" "$validate" "$work"/glb/*.glb >"$work/report" 2>&1; then
    echo "ok: $n .glb files valid (no error, no warning):"
    ls "$work/glb" | tr '\n' ' '
    echo
else
    cat "$work/report"
    fail "the validator found errors or warnings"
fi
[ "$failed" -eq 0 ]
