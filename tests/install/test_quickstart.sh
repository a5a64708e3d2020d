#!/bin/sh
# test_quickstart.sh: tools/quickstart.sh with stand-ins for deps.sh,
# meson, ninja, pkg-config, cc, xvfb-run, raygl2pov and povray (issue 27).
# It builds in build-quickstart/ with -Dtests=false and never names build/
# (tools/test.sh's, there already); an existing build-quickstart/ is
# reconfigured; it prints a line a step and the result's path, not what
# the tools print (the stand-in povray prints 900 banner lines, as POV-Ray
# does); a failing step stops it with that step's output in full.
#
#   test_quickstart.sh SOURCE-DIR
set -u
[ $# -eq 1 ] || { echo "usage: $0 SOURCE-DIR" >&2; exit 2; }
src=$1
fail() { echo "quickstart: FAIL: $*"; exit 1; }
t=$(mktemp -d) || exit 1
{ [ -n "$t" ] && [ "$t" != / ] && [ -d "$t" ]; } || exit 1
trap 'rm -rf "$t"' EXIT
log=$t/log
prefix=$t/prefix
mkdir -p "$t/tree/tools" "$t/tree/examples" "$t/bin" || exit 1
cp "$src/tools/quickstart.sh" "$t/tree/tools/" && : >"$t/tree/examples/cube.c" || exit 1

# Each stand-in logs its call to $STUB_LOG; STUB_FAIL=NAME makes NAME fail
# after printing 300 lines.
stub() { # NAME BODY
    {
        echo '#!/bin/sh'
        echo "echo \"$1 \$*\" >>\"\$STUB_LOG\""
        echo "if [ \"\${STUB_FAIL:-}\" = $1 ]; then i=0; while [ \$i -lt 300 ]; do echo \"$1 line \$i\"; i=\$((i + 1)); done; exit 3; fi"
        printf '%s\n' "$2"
    } >"$3"
    chmod +x "$3"
}
stub deps 'echo "deps: all 40 packages are installed"' "$t/tree/tools/deps.sh"
stub meson 'case $1 in
setup) dir=$2; [ "$dir" = --reconfigure ] && dir=$3
    mkdir -p "$dir/meson-private" && touch "$dir/meson-private/coredata.dat" ;;
introspect) echo "[{\"name\": \"libdir\", \"value\": \"lib/x86_64-linux-gnu\"}]" ;;
install) mkdir -p "$STUB_PREFIX/bin" && cp "$STUB_R2P" "$STUB_PREFIX/bin/raygl2pov" ;;
esac' "$t/bin/meson"
stub ninja 'i=0; while [ $i -lt 251 ]; do echo "[$i/251] Compiling"; i=$((i + 1)); done' "$t/bin/ninja"
stub pkg-config 'echo "-I/x -lraygl"' "$t/bin/pkg-config"
stub cc 'while [ $# -gt 0 ]; do [ "$1" = -o ] && printf "#!/bin/sh\necho cube\n" >"$2" && chmod +x "$2"; shift; done' "$t/bin/cc"
stub xvfb-run 'while [ $# -gt 0 ]; do case $1 in -a) shift ;; -s) shift 2 ;; *) break ;; esac; done; exec "$@"' "$t/bin/xvfb-run"
stub raygl2pov 'mkdir -p out/frames && : >out/frames/frame-00002.ini
echo "raygl2pov: out/cube.raygl: a note the user reads"' "$t/r2p"
stub povray 'i=0; while [ $i -lt 900 ]; do echo "Persistence of Vision(tm) Ray Tracer banner line $i"; i=$((i + 1)); done
printf png >out/frames/frame-00002.png' "$t/bin/povray"

run() { # NAME [VAR=VALUE...]: quickstart in the tree, build/ there already
    name=$1
    shift
    rm -f "$log"
    mkdir -p "$t/tree/build/meson-private" && touch "$t/tree/build/meson-private/coredata.dat"
    env PATH="$t/bin:$PATH" STUB_LOG="$log" STUB_PREFIX="$prefix" STUB_R2P="$t/r2p" "$@" \
        sh "$t/tree/tools/quickstart.sh" --prefix "$prefix" >"$t/$name.out" 2>&1
    echo $? >"$t/$name.rc"
}
run fresh
[ "$(cat "$t/fresh.rc")" = 0 ] || { cat "$t/fresh.out"; fail "fresh: exit $(cat "$t/fresh.rc")"; }
grep -q "^meson setup build-quickstart --prefix $prefix -Dtests=false\$" "$log" ||
    { cat "$log"; fail "not set up in build-quickstart/ with -Dtests=false"; }
grep -q '^ninja -C build-quickstart$' "$log" || { cat "$log"; fail "not built in build-quickstart/"; }
grep -q ' build$\| build ' "$log" && { cat "$log"; fail "build/, tools/test.sh's, was named"; }
grep -q 'banner\|Compiling' "$t/fresh.out" && { cat "$t/fresh.out"; fail "the tools' own output was printed"; }
n=$(wc -l <"$t/fresh.out")
[ "$n" -le 25 ] || { cat "$t/fresh.out"; fail "$n lines printed"; }
grep -q '^quickstart: the ray-traced frame: out/frames/frame-00002.png$' "$t/fresh.out" &&
    grep -q '^raygl2pov: out/cube.raygl: a note the user reads$' "$t/fresh.out" ||
    { cat "$t/fresh.out"; fail "the result's path or raygl2pov's note not printed"; }

run again
grep -q "^meson setup --reconfigure build-quickstart --prefix $prefix -Dtests=false\$" "$log" ||
    { cat "$log"; fail "an existing build-quickstart/ is not reconfigured"; }

run broken STUB_FAIL=ninja
[ "$(cat "$t/broken.rc")" = 1 ] || { cat "$t/broken.out"; fail "a failing build: exit $(cat "$t/broken.rc")"; }
[ "$(grep -c '^ninja line ' "$t/broken.out")" -eq 300 ] && grep -q '^quickstart: failed (exit 3): ninja -C build-quickstart$' "$t/broken.out" ||
    { cat "$t/broken.out"; fail "a failing step's output not printed in full"; }
grep -q '^meson install' "$log" && fail "installed after a failed build"
echo "quickstart: build folder, output and failures checked"
