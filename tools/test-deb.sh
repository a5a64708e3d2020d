#!/bin/sh
# test-deb.sh: the Debian packages, built and used as a user would. Builds
# them (dpkg-buildpackage -us -uc -b) in a temporary copy of the tree,
# checks them with lintian (no error allowed), installs them with apt-get,
# then, with the installed files only: records a small GLUT program with
# `raygl record` and builds it with the drop-in header and
# `pkg-config raygl`, translates both traces, renders with raygl-render
# (POV-Ray), reads `man raygl2pov`. Purges the packages again at the end,
# failed or not, so the machine is left as it was.
#
# Usage: tools/test-deb.sh    (as root; tools/test.sh runs it in CI)
# Exit 0 passed, 1 failed, 77 skipped (the reason on one line).
set -u
cd "$(dirname "$0")/.." || exit 1
src=$PWD
pkgs="raygl libraygl-dev libraygl0"
fail() { echo "test-deb: FAIL: $*"; exit 1; }
skip() { echo "test-deb: SKIP: $*"; exit 77; }

[ "$(id -u)" -eq 0 ] || skip "installing packages needs root"
for t in dpkg-buildpackage lintian apt-get xvfb-run povray pkg-config man cc; do
    command -v $t >/dev/null || fail "$t not found: run tools/deps.sh"
done
for p in $pkgs; do
    # A user's own install is not replaced, nor purged afterwards.
    if dpkg-query -W -f '${db:Status-Abbrev}' "$p" 2>/dev/null | grep -q '^ii'; then
        skip "package $p is installed already"
    fi
done

work=$(mktemp -d /tmp/raygl-deb.XXXXXX) || fail "mktemp failed"
installed=no
cleanup() {
    if [ $installed = yes ]; then
        # shellcheck disable=SC2086
        apt-get purge -y -q -o DPkg::Lock::Timeout=300 $pkgs >>"$work/apt.log" 2>&1 ||
            echo "test-deb: purging $pkgs failed (see apt-get)"
    fi
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' HUP INT TERM

# The tree as git sees it (tracked and new files, not build dirs); a tree
# that is no git checkout is copied less its build dirs.
mkdir "$work/src"
if git -C "$src" rev-parse --git-dir >/dev/null 2>&1; then
    git -C "$src" ls-files -z --cached --others --exclude-standard |
        (cd "$src" && xargs -0 cp --parents -t "$work/src") || fail "copying the tree failed"
else
    tar -C "$src" --exclude='./build*' --exclude=./out -cf - . | tar -C "$work/src" -xf - ||
        fail "copying the tree failed"
fi

# noddebs: no -dbgsym packages, nothing here uses them.
if ! (cd "$work/src" && DEB_BUILD_OPTIONS=noddebs dpkg-buildpackage -us -uc -b) >"$work/build.log" 2>&1; then
    tail -n 30 "$work/build.log"
    fail "dpkg-buildpackage failed"
fi
for p in $pkgs; do
    set -- "$work/${p}_"*.deb
    [ -f "$1" ] || fail "no package $p built"
done
if ! lintian --fail-on error "$work"/*.changes >"$work/lintian.log" 2>&1; then
    cat "$work/lintian.log"
    fail "lintian reports errors"
fi
sed 's/^/test-deb: lintian: /' "$work/lintian.log"

installed=yes
if ! apt-get install -y -q --no-install-recommends -o DPkg::Lock::Timeout=300 \
    "$work"/raygl_*.deb "$work"/libraygl-dev_*.deb "$work"/libraygl0_*.deb >"$work/apt.log" 2>&1; then
    tail -n 20 "$work/apt.log"
    fail "apt-get install of the packages failed"
fi

triplet=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
libdir=/usr/lib/$triplet
# Only the packages' files: a RayGL installed in /usr/local (the quick
# start) comes first in PATH, pkg-config's path, the linker's and man's.
unset RAYGL_PRELOAD_LIB RAYGL_COMPARE RAYGL_TRACE
export PKG_CONFIG_LIBDIR="$libdir/pkgconfig":/usr/share/pkgconfig MANPATH=/usr/share/man
t=$work/t
mkdir "$t" || fail "cannot make $t"
cd "$t" || fail "cannot enter $t"

libs=$(pkg-config --libs raygl) || fail "pkg-config --libs raygl failed"
case " $libs " in *" -lraygl "*) ;; *) fail "pkg-config --libs raygl: '$libs' has no -lraygl" ;; esac
[ "$(pkg-config --variable=prefix raygl)" = /usr ] || fail "raygl.pc: prefix is not /usr"
# /lib is /usr/lib on a merged-/usr system; ldconfig may name either.
ldconfig -p | grep -Eq " => (/usr)?/lib/$triplet/libraygl\.so\.0\$" || fail "libraygl.so.0 is not in ldconfig's cache"
man raygl2pov 2>/dev/null | grep -q 'raygl2pov' || fail "man raygl2pov shows nothing"
for m in raygl raygl-render raygl-compare; do
    man -w $m >/dev/null 2>&1 || fail "no man page $m"
done

# The program, as it would be written for OpenGL: three frames of a lit teapot.
cat >prog.c <<'C'
#include <stdlib.h>
#include <GL/glut.h>

static int frames;

static void display(void)
{
    static const GLfloat pos[] = {1, 2, 3, 0};
    glClearColor(0.2f, 0.3f, 0.4f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, 4.0 / 3, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 1, 5, 0, 0, 0, 0, 1, 0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glRotatef(frames * 20.0f, 0, 1, 0);
    glutSolidTeapot(1);
    glutSwapBuffers();
    if (++frames == 3)
        exit(0);
}

static void idle(void)
{
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(160, 120);
    glutCreateWindow("test-deb");
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
C
cc prog.c -o plain -lglut -lGLU -lGL || fail "cc of the plain program failed"
# shellcheck disable=SC2046
cc -include raygl/gl.h prog.c -o dropin $(pkg-config --cflags --libs raygl) ||
    fail "cc with raygl/gl.h and pkg-config raygl failed"
# The packaged libraygl, even where a /usr/local one comes first.
LD_LIBRARY_PATH=$libdir RAYGL_TRACE=dropin.raygl xvfb-run -a -s '-screen 0 320x240x24' ./dropin >dropin.log 2>&1 ||
    { cat dropin.log; fail "the drop-in program failed"; }
xvfb-run -a -s '-screen 0 320x240x24' /usr/bin/raygl record -o plain.raygl -- ./plain >record.log 2>&1 ||
    { cat record.log; fail "/usr/bin/raygl record failed"; }
for tr in dropin plain; do
    n=$(/usr/bin/raygl2pov $tr.raygl --dump 2>&1 | grep -c 'glutSolidTeapot')
    [ "$n" -eq 3 ] || fail "$tr.raygl: $n glutSolidTeapot calls recorded, not 3"
    /usr/bin/raygl2pov $tr.raygl -o $tr-frames >/dev/null || fail "/usr/bin/raygl2pov $tr.raygl failed"
done
/usr/bin/raygl-render plain-frames >render.log 2>&1 || { cat render.log; fail "/usr/bin/raygl-render failed"; }
for f in 0 1 2; do
    [ -s plain-frames/frame-0000$f.png ] || fail "raygl-render made no plain-frames/frame-0000$f.png"
done
cd / || fail "cannot leave $t"
# shellcheck disable=SC2086
apt-get purge -y -q -o DPkg::Lock::Timeout=300 $pkgs >>"$work/apt.log" 2>&1 || fail "apt-get purge $pkgs failed"
installed=no
for p in $pkgs; do
    if dpkg-query -W -f '${db:Status-Abbrev}' "$p" 2>/dev/null | grep -q '^[ir]'; then
        fail "package $p is still there after the purge"
    fi
done
echo "test-deb: $pkgs built, lintian clean, installed, used, purged"
