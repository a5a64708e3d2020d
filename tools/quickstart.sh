#!/bin/sh
# The README's first command, on a fresh Debian 12 machine: installs the
# packages (tools/deps.sh), builds RayGL in build/, installs it, then runs
# the main job with the installed RayGL only: the example program built
# with `pkg-config raygl`, recorded, its trace translated by raygl2pov and
# a frame rendered by POV-Ray into out/frames/frame-00002.png.
#
# Usage: tools/quickstart.sh [--prefix DIR]
#   /usr/local by default: as root or through sudo; ldconfig runs, and
#   PATH, pkg-config, man and the dynamic linker find it as they are.
#   --prefix DIR (absolute, e.g. "$HOME/.local"): no root needed for the
#   install; prints the environment lines a shell needs to use it.
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

tools/deps.sh

# An earlier build/ (tools/test.sh's, say) keeps its options but takes
# this prefix.
if [ -f build/meson-private/coredata.dat ]; then
    meson setup --reconfigure build --prefix "$prefix"
else
    meson setup build --prefix "$prefix"
fi
ninja -C build
libdir=$(meson introspect build --buildoptions |
    python3 -c 'import json, sys; print(next(o["value"] for o in json.load(sys.stdin) if o["name"] == "libdir"))')

# Installing as root runs ldconfig (tools/install-ldconfig.sh).
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    d=$prefix
    while [ ! -d "$d" ]; do d=$(dirname "$d"); done
    [ -w "$d" ] && { [ ! -d "$prefix/bin" ] || [ -w "$prefix/bin" ]; } || SUDO="sudo"
fi
$SUDO meson install -C build --no-rebuild

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
cc examples/cube.c -o out/cube $(pkg-config --cflags --libs raygl) -lm
# The example is a GLUT program; Xvfb gives it a window on machines with
# no display. RAYGL_TRACE names the trace.
RAYGL_TRACE=out/cube.raygl xvfb-run -a -s "-screen 0 1024x768x24" out/cube --frames 3
raygl2pov --dump out/cube.raygl | head -n 20
rm -rf out/frames
raygl2pov out/cube.raygl -o out/frames
povray out/frames/frame-00002.ini
echo "quickstart: RayGL is installed in $prefix (raygl, raygl2pov, raygl-render, raygl-compare;"
echo "quickstart: man raygl2pov; pkg-config raygl). The ray-traced frame is out/frames/frame-00002.png"
if [ -n "$envlines" ]; then
    echo "quickstart: to use $prefix, add these lines to your shell's profile (~/.profile):"
    printf '%s\n' "$envlines"
fi
