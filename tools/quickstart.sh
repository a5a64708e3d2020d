#!/bin/sh
# The README's first command, on a fresh Debian 12 machine: installs the
# packages (tools/deps.sh), builds RayGL without its test suite in
# build-quickstart/, installs it, then runs the main job with the
# installed RayGL only: the example program built with `pkg-config raygl`,
# recorded, its trace translated by raygl2pov and a frame rendered by
# POV-Ray into out/frames/frame-00002.png.
#
# Usage: tools/quickstart.sh [--prefix DIR]
#   /usr/local by default: as root or through sudo; ldconfig runs, and
#   PATH, pkg-config, man and the dynamic linker find it as they are.
#   --prefix DIR (absolute, e.g. "$HOME/.local"): no root needed for the
#   install; prints the environment lines a shell needs to use it.
#
# Its own build folder, build-quickstart/ (-Dtests=false: the 8 targets
# the install needs, not the 250 of the test suite), so that it and
# tools/test.sh (build/ and build-asan/, with their own options) never
# reconfigure or rebuild each other's. tools/uninstall.sh undoes the
# install. Each step prints one line; its output goes to a log, printed
# in full when the step fails.
set -eu
cd "$(dirname "$0")/.."
usage() { echo "usage: tools/quickstart.sh [--prefix DIR]" >&2; exit 2; }
prefix=/usr/local
while [ $# -gt 0 ]; do
    case $1 in
    --prefix) [ $# -ge 2 ] || usage; prefix=$2; shift 2 ;;
    --prefix=*) prefix=${1#--prefix=}; shift ;;
    -h | --help) usage ;;
    *) echo "quickstart: unknown option $1" >&2; usage ;;
    esac
done
case $prefix in
/*) ;;
*) echo "quickstart: --prefix $prefix: not an absolute path" >&2; exit 2 ;;
esac
prefix=${prefix%/}
[ -n "$prefix" ] || prefix=/

build=build-quickstart
start=$(date +%s)
say() { echo "quickstart: $*"; }
# step LOG WHAT COMMAND...: says WHAT, runs COMMAND into LOG; on a failure
# prints LOG whole and stops.
step() {
    log=$1 what=$2
    shift 2
    say "$what"
    "$@" >"$log" 2>&1 || {
        rc=$?
        echo "quickstart: failed (exit $rc): $*" >&2
        echo "quickstart: its output ($log):" >&2
        cat "$log" >&2
        exit 1
    }
}

step deps.log "Debian packages (tools/deps.sh; log deps.log)" tools/deps.sh
if grep -q '^deps: ' deps.log; then
    grep '^deps: ' deps.log | sed 's/^/quickstart: /'
else
    say "packages installed (deps.log)"
fi

# An earlier build-quickstart/ keeps what it built and takes this prefix.
if [ -f "$build/meson-private/coredata.dat" ]; then
    step "$build.setup.log" "configuring $build/ for $prefix (log $build.setup.log)" \
        meson setup --reconfigure "$build" --prefix "$prefix" -Dtests=false
else
    step "$build.setup.log" "configuring $build/ for $prefix (log $build.setup.log)" \
        meson setup "$build" --prefix "$prefix" -Dtests=false
fi
step "$build.build.log" "building RayGL (log $build.build.log)" ninja -C "$build"
libdir=$(meson introspect "$build" --buildoptions |
    python3 -c 'import json, sys; print(next(o["value"] for o in json.load(sys.stdin) if o["name"] == "libdir"))')

# Installing as root runs ldconfig (tools/install-ldconfig.sh).
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    d=$prefix
    while [ ! -d "$d" ]; do d=$(dirname "$d"); done
    [ -w "$d" ] && { [ ! -d "$prefix/bin" ] || [ -w "$prefix/bin" ]; } || SUDO="sudo"
fi
step "$build.install.log" "installing into $prefix${SUDO:+ (with sudo)} (log $build.install.log)" \
    $SUDO meson install -C "$build" --no-rebuild

# A prefix outside the system's search paths needs these; /usr/local is
# in all of them on Debian (ld.so.conf.d, pkg-config's and man's paths).
envlines=""
case $prefix in
/usr/local | /usr) ;;
*)
    envlines="export PATH=\"$prefix/bin:\$PATH\"
export LD_LIBRARY_PATH=\"$prefix/$libdir\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}\"
export PKG_CONFIG_PATH=\"$prefix/$libdir/pkgconfig\${PKG_CONFIG_PATH:+:\$PKG_CONFIG_PATH}\"
export MANPATH=\"$prefix/share/man:\${MANPATH:-}\""
    eval "$envlines"
    ;;
esac

# The main job, with the installed files only.
[ "$(command -v raygl2pov)" = "$prefix/bin/raygl2pov" ] ||
    { echo "quickstart: raygl2pov on PATH is not $prefix/bin/raygl2pov" >&2; exit 1; }
mkdir -p out
# shellcheck disable=SC2046
step out/cube.build.log "building examples/cube.c with pkg-config raygl: out/cube" \
    cc examples/cube.c -o out/cube $(pkg-config --cflags --libs raygl) -lm
# The example is a GLUT program; Xvfb gives it a window on machines with
# no display. RAYGL_TRACE names the trace.
step out/cube.log "recording 3 frames of out/cube: out/cube.raygl" \
    env RAYGL_TRACE=out/cube.raygl xvfb-run -a -s "-screen 0 1024x768x24" out/cube --frames 3
rm -rf out/frames
# What raygl2pov says of the translation is for the user: shown as it is.
say "translating out/cube.raygl: out/frames/ (raygl2pov)"
raygl2pov out/cube.raygl -o out/frames
step out/povray.log "rendering out/frames/frame-00002.ini with POV-Ray (log out/povray.log)" \
    povray out/frames/frame-00002.ini
[ -s out/frames/frame-00002.png ] || { cat out/povray.log >&2; echo "quickstart: POV-Ray wrote no out/frames/frame-00002.png" >&2; exit 1; }

say "done in $(($(date +%s) - start)) s"
say "RayGL is installed in $prefix: raygl, raygl2pov, raygl-render, raygl-compare,"
say "man raygl2pov, pkg-config raygl; ${SUDO:+sudo }tools/uninstall.sh removes it"
say "the trace: out/cube.raygl (raygl2pov --dump out/cube.raygl | less: every call)"
say "the ray-traced frame: out/frames/frame-00002.png"
if [ -n "$envlines" ]; then
    say "to use $prefix, add these lines to your shell's profile (~/.profile):"
    printf '%s\n' "$envlines"
fi
