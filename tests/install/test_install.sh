#!/bin/sh
# test_install.sh: `meson install --destdir` of this build (its own
# install log untouched), then the installed files used as the README says
# for a prefix outside the system's paths: a program built with
# `pkg-config raygl` and the drop-in header, run with LD_LIBRARY_PATH, its
# trace read by the installed raygl2pov, the man pages found with MANPATH.
#
#   test_install.sh BUILD-DIR PREFIX LIBDIR B_SANITIZE CC
set -u
[ $# -eq 5 ] || { echo "usage: $0 BUILD-DIR PREFIX LIBDIR B_SANITIZE CC" >&2; exit 2; }
build=$1 prefix=$2 libdir=$3 sanitize=$4 cc=$5
fail() { echo "install-tree: FAIL: $*"; exit 1; }
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
dest=$t/dest
root=$dest$prefix
lib=$root/$libdir

# The build folder's install state is its user's (stage.sh): it must be
# the same afterwards.
. "$(dirname "$0")/stage.sh"
log=$build/meson-logs/install-log.txt
before=$t/log-before
if [ -e "$log" ]; then cp -p "$log" "$before"; else : >"$t/no-log"; fi
shadow=$t/build
stage_install "$build" "$shadow" "$dest" ||
    { cat "$shadow.install.log"; fail "meson install --destdir failed"; }
if [ -e "$t/no-log" ]; then
    [ ! -e "$log" ] || fail "the staged install made $log"
else
    cmp -s "$before" "$log" || fail "the staged install changed $log"
fi
grep -q "^$dest$prefix/bin/raygl2pov\$" "$shadow/meson-logs/install-log.txt" ||
    fail "the test's own install log does not list $dest$prefix/bin/raygl2pov"

for f in bin/raygl bin/raygl2pov bin/raygl2gltf bin/raygl-render bin/raygl-compare \
    share/man/man1/raygl2gltf.1 include/raygl.h include/raygl/gl.h include/raygl/cmdtable.h \
    "$libdir/libraygl.so" "$libdir/libraygl.so.0" "$libdir/pkgconfig/raygl.pc" \
    "$libdir/raygl/libraygl-preload.so" \
    share/man/man1/raygl.1 share/man/man1/raygl2pov.1 share/man/man1/raygl-render.1 \
    share/man/man1/raygl-compare.1 share/raygl/raygl-blender.py; do
    [ -e "$root/$f" ] || fail "$prefix/$f not installed"
done
# The installed raygl-render finds Blender's import script in
# PREFIX/share/raygl (a task that gets as far as reading render.list).
"$root/bin/raygl-render" "$t" --engine blender --blender /bin/true --task 0 >"$t/out" 2>&1
grep -q "render.list: cannot read" "$t/out" ||
    fail "installed raygl-render --engine blender: $(cat "$t/out")"
for f in bin/raygl bin/raygl2pov bin/raygl-render bin/raygl-compare; do
    [ -x "$root/$f" ] || fail "$prefix/$f is not executable"
done
# Only libraries with a SONAME in libdir itself: ldconfig and Debian's
# packaging expect that; the preload library lives in libdir/raygl/.
for so in "$lib"/*.so*; do
    [ -L "$so" ] && continue
    readelf -d "$so" | grep -q '(SONAME)' || fail "$so has no SONAME but is in libdir"
done
# The installed script names the library relative to its own folder, so a
# moved prefix still works: that path must lead to the staged library.
rel=$(sed -n "s/^preload=\${RAYGL_PRELOAD_LIB:-\$(beside '\(.*\)')}\$/\1/p" "$root/bin/raygl")
[ "$rel" = "../$libdir/raygl/libraygl-preload.so" ] && [ -f "$root/bin/$rel" ] ||
    fail "bin/raygl names '$rel', not ../$libdir/raygl/libraygl-preload.so"

# The environment the README gives for a prefix of one's own; the staged
# tree stands in for it (its .pc file's prefix moved to where it is).
PATH=$root/bin:$PATH
LD_LIBRARY_PATH=$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
PKG_CONFIG_PATH=$lib/pkgconfig
MANPATH=$root/share/man:
export PATH LD_LIBRARY_PATH PKG_CONFIG_PATH MANPATH
unset RAYGL_TRACE RAYGL_RECORD
pc="pkg-config --define-variable=prefix=$root"
libs=$($pc --libs raygl) || fail "pkg-config --libs raygl failed"
case " $libs " in *" -L$lib "*) ;; *) fail "pkg-config --libs raygl: '$libs' has no -L$lib" ;; esac
cat >"$t/app.c" <<'C'
/* An OpenGL program recorded through the drop-in header: no GL context,
 * so the forwarded calls do nothing, but they are recorded. */
#include <GL/gl.h>

int main(int argc, char **argv)
{
    if (argc != 2 || rayglRecordOpen(argv[1]) != 0)
        return 1;
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    rayglFrameEnd();
    rayglRecordClose();
    return rayglRecordStatus() == RAYGL_FAILED;
}
C
san=""
[ "$sanitize" = none ] || san="-fsanitize=$sanitize"
# shellcheck disable=SC2046,SC2086
"$cc" $san -include raygl/gl.h "$t/app.c" -o "$t/app" $($pc --cflags --libs raygl) ||
    fail "$cc -include raygl/gl.h with pkg-config raygl failed"
(cd "$t" && ./app app.raygl) || fail "the program built against the installed libraygl failed"
ldd "$t/app" | grep -q "libraygl.so.0 => $lib/" || fail "the program did not load $lib/libraygl.so.0"
command -v raygl2pov | grep -qx "$root/bin/raygl2pov" || fail "raygl2pov on PATH is not the installed one"
raygl2pov "$t/app.raygl" --dump >"$t/dump.txt" 2>&1 || { cat "$t/dump.txt"; fail "installed raygl2pov --dump failed"; }
grep -q 'glClearColor' "$t/dump.txt" || { cat "$t/dump.txt"; fail "glClearColor not in the trace"; }
raygl2gltf -q "$t/app.raygl" -o "$t/glb" 2>&1 && ls "$t/glb"/*.glb >/dev/null 2>&1 ||
    fail "installed raygl2gltf wrote no .glb"
raygl --version >/dev/null || fail "installed raygl --version failed"
if command -v man >/dev/null; then
    for m in raygl raygl2pov raygl2gltf raygl-render raygl-compare; do
        # raygl-render.1 is a .so link: man -w names the page it sources.
        man -w $m | grep -q "^$root/share/man/man1/" || fail "MANPATH: man -w $m gives $(man -w $m)"
    done
fi
echo "install-tree: $prefix installed to $dest and used from there"
