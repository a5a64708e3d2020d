#!/bin/sh
# test_testsh.sh: tools/test.sh with stand-ins for meson, ninja, deps.sh
# and test-deb.sh. It installs the packages first; it configures build/
# and build-asan/ with its own options even where build/ exists already
# (a developer's, without -Dwerror); it counts the packages' test like
# a suite in CI and not elsewhere; a failing deps.sh is one failure.
#
#   test_testsh.sh SOURCE-DIR
set -u
[ $# -eq 1 ] || { echo "usage: $0 SOURCE-DIR" >&2; exit 2; }
src=$1
fail() { echo "test-sh: FAIL: $*"; exit 1; }
t=$(mktemp -d) || exit 1
# Every path below is under $t: never let an empty $t point at /.
{ [ -n "$t" ] && [ "$t" != / ] && [ -d "$t" ]; } || exit 1
trap 'rm -rf "$t"' EXIT
log=$t/log
mkdir -p "$t/tree/tools" "$t/bin" || exit 1
cp "$src/tools/test.sh" "$t/tree/tools/" || exit 1

# The stand-ins log each call to $STUB_LOG.
printf '%s\n' '#!/bin/sh' 'echo deps >>"$STUB_LOG"' 'exit ${STUB_DEPS_RC:-0}' \
    >"$t/tree/tools/deps.sh"
printf '%s\n' '#!/bin/sh' 'echo test-deb >>"$STUB_LOG"' 'exit ${STUB_DEB_RC:-0}' \
    >"$t/tree/tools/test-deb.sh"
printf '%s\n' '#!/bin/sh' 'echo "ninja $*" >>"$STUB_LOG"' >"$t/bin/ninja"
# meson: `setup` makes the dir's coredata (a reconfigure fails when
# STUB_RECONF_RC says so); `test -C DIR` writes 2 OK, 1 SKIP and
# STUB_FAILS FAILs to DIR's test log.
cat >"$t/bin/meson" <<'STUB_MESON'
#!/bin/sh
echo "meson $*" >>"$STUB_LOG"
case $1 in
setup)
    shift
    for a; do case $a in -*) ;; *) dir=$a ;; esac; done
    case " $* " in *" --reconfigure "*) [ "${STUB_RECONF_RC:-0}" -eq 0 ] || exit 1 ;; esac
    mkdir -p "$dir/meson-private" && touch "$dir/meson-private/coredata.dat" ;;
test)
    mkdir -p "$3/meson-logs"
    {
        echo '{"result": "OK"}'
        echo '{"result": "SKIP"}'
        echo '{"result": "OK"}'
        n=0
        while [ $n -lt "${STUB_FAILS:-0}" ]; do
            echo '{"result": "FAIL"}'
            n=$((n + 1))
        done
    } >"$3/meson-logs/testlog.json" ;;
esac
STUB_MESON
chmod +x "$t/tree/tools/deps.sh" "$t/tree/tools/test-deb.sh" "$t/bin/meson" "$t/bin/ninja" || exit 1

# run NAME [VAR=VALUE...]: tools/test.sh in a tree whose build/ an earlier
# meson setup made; its output in $t/NAME.out, its status in $t/NAME.rc.
run() {
    name=$1
    shift
    rm -rf "$t/tree/build" "$t/tree/build-asan" "$log"
    mkdir -p "$t/tree/build/meson-private" && touch "$t/tree/build/meson-private/coredata.dat"
    env PATH="$t/bin:$PATH" STUB_LOG="$log" CI= RAYGL_TEST_DEB= "$@" \
        sh "$t/tree/tools/test.sh" >"$t/$name.out" 2>&1
    echo $? >"$t/$name.rc"
}
last() { tail -n 1 "$t/$1.out"; }
expect() { # NAME STATUS LAST-LINE
    [ "$(cat "$t/$1.rc")" = "$2" ] && [ "$(last "$1")" = "$3" ] ||
        { cat "$t/$1.out"; fail "$1: exit $(cat "$t/$1.rc"), '$(last "$1")'; expected exit $2, '$3'"; }
}

run plain
expect plain 0 "4 passed, 0 failed"
[ "$(head -n 1 "$log")" = deps ] || fail "plain: deps.sh is not run first"
grep -q '^meson setup --reconfigure build .*-Db_sanitize=none.* -Dwerror=true' "$log" ||
    { cat "$log"; fail "the existing build/ is not reconfigured with -Dwerror=true"; }
grep -q '^meson setup build-asan .*-Db_sanitize=address,undefined.* -Dwerror=true' "$log" ||
    { cat "$log"; fail "build-asan is not set up with its options"; }
grep -q '^test-deb' "$log" && fail "plain: the packages' test ran outside CI"
grep -q 'test-deb: SKIP' "$t/plain.out" || fail "plain: no line says the packages' test is skipped"

run ci CI=true
expect ci 0 "5 passed, 0 failed"
grep -q '^test-deb' "$log" || fail "ci: the packages' test did not run"
run asked RAYGL_TEST_DEB=1 STUB_DEB_RC=77
expect asked 0 "4 passed, 0 failed"
run debfail CI=true STUB_DEB_RC=1
expect debfail 1 "4 passed, 1 failed"
run testfail STUB_FAILS=2
expect testfail 1 "4 passed, 4 failed"

run wipe STUB_RECONF_RC=1
expect wipe 0 "4 passed, 0 failed"
grep -q '^meson setup --wipe build .*-Dwerror=true' "$log" ||
    { cat "$log"; fail "a build/ that cannot be reconfigured is not wiped"; }

run nodeps STUB_DEPS_RC=1
expect nodeps 1 "0 passed, 1 failed"
grep -q '^meson' "$log" && fail "nodeps: meson ran after deps.sh failed"
echo "test-sh: options, counting and deps.sh checked"
