#!/bin/sh
# test_uninstall.sh: tools/uninstall.sh on a staged install of this build
# (stage.sh: the build's own install log untouched).
#
#   test_uninstall.sh BUILD-DIR PREFIX LIBDIR UNINSTALL-SH
#
# It removes every installed file, RayGL's own folders and those the
# install made, runs ldconfig as root (a stand-in on PATH records it);
# run again, with nothing left to remove, it fails (meson's own uninstall
# says "Deleted: 0" and exits 0); without the rights to remove the files
# it fails and says to run it as root, with or without sudo; a build
# folder that installed nothing is named.
set -u
[ $# -eq 4 ] || { echo "usage: $0 BUILD-DIR PREFIX LIBDIR UNINSTALL-SH" >&2; exit 2; }
build=$1 prefix=$2 libdir=$3 un=$4
fail() { echo "uninstall: FAIL: $*"; exit 1; }
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
chmod 755 "$t"
. "$(dirname "$0")/stage.sh"
dest=$t/dest
shadow=$t/build
mkdir "$dest" || exit 1 # not the install's: it stays
stage_install "$build" "$shadow" "$dest" || { cat "$shadow.install.log"; fail "staged install failed"; }
root=$dest$prefix
[ -f "$root/bin/raygl2pov" ] && [ -d "$root/$libdir/raygl" ] && [ -d "$root/include/raygl" ] &&
    [ -d "$root/share/raygl" ] || fail "the staged install lacks what this test removes"
mkdir "$t/stub"
printf '#!/bin/sh\necho ran >>"%s"\n' "$t/ldconfig.ran" >"$t/stub/ldconfig"
chmod +x "$t/stub/ldconfig"

# Without the rights to remove them (as nobody, where root can switch; a
# copy of the script, which a source tree in a private folder hides).
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null 2>&1; then
    cp "$un" "$t/uninstall.sh" && chmod 644 "$t/uninstall.sh" || fail "copy $un"
    setpriv --reuid=65534 --regid=65534 --clear-groups env PATH="$t/stub:$PATH" sh "$t/uninstall.sh" "$shadow" \
        >"$t/out" 2>&1
    rc=$?
    [ $rc -eq 1 ] || { cat "$t/out"; fail "without the rights: exit $rc, expected 1"; }
    grep -q "cannot remove" "$t/out" && grep -q "run it as root: sudo tools/uninstall.sh $shadow, or in a root shell tools/uninstall.sh $shadow" "$t/out" ||
        { cat "$t/out"; fail "without the rights: no hint to run it as root"; }
    [ -f "$root/bin/raygl2pov" ] || fail "without the rights: a file went"
    [ ! -e "$t/ldconfig.ran" ] || fail "ldconfig ran as nobody"
fi

PATH="$t/stub:$PATH" sh "$un" "$shadow" >"$t/out" 2>&1
rc=$?
[ $rc -eq 0 ] || { cat "$t/out"; fail "exit $rc"; }
[ -d "$dest" ] || fail "$dest, made before the install, was removed"
left=$(cd "$dest" && find . -mindepth 1 | head -n 5)
[ -z "$left" ] || { cat "$t/out"; fail "left under $dest: $left"; }
grep -q '^uninstall: removed [1-9][0-9]* files and [1-9][0-9]* folders' "$t/out" ||
    { cat "$t/out"; fail "no summary line"; }
if [ "$(id -u)" -eq 0 ]; then
    [ "$(cat "$t/ldconfig.ran" 2>/dev/null)" = ran ] || fail "ldconfig did not run (as root)"
    grep -q '; ldconfig run$' "$t/out" || { cat "$t/out"; fail "ldconfig not said"; }
fi

# Nothing left to remove: a failure, saying so.
PATH="$t/stub:$PATH" sh "$un" "$shadow" >"$t/out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "nothing removed: none of the [0-9]* paths listed in $shadow/meson-logs/install-log.txt is there" "$t/out" ||
    { cat "$t/out"; fail "a second run: exit $rc"; }

# A folder nothing was installed from.
mkdir -p "$t/empty"
sh "$un" "$t/empty" >"$t/out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "no install log: nothing was installed from $t/empty" "$t/out" ||
    { cat "$t/out"; fail "a build folder without an install: exit $rc"; }
echo "uninstall: staged install of $prefix removed, then refused twice"
