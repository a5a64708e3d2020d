#!/bin/sh
# The whole test suite, as CI runs it (.ci/run), on its own on a fresh
# machine too: installs the packages it needs (tools/deps.sh), then runs
# `meson test` in a normal build (build/) and an AddressSanitizer +
# UndefinedBehaviorSanitizer build (build-asan/), each configured with
# this script's options whatever an earlier `meson setup` chose (one
# without -Dwerror, say; the quick start builds in build-quickstart/, which
# this never touches), then the Debian packages' test
# (tools/test-deb.sh: in CI, or with RAYGL_TEST_DEB=1; it installs and
# purges packages). Prints `N passed, N failed` last and exits non-zero
# on any failure.
set -u
cd "$(dirname "$0")/.." || exit 1
passed=0
failed=0

if ! tools/deps.sh </dev/null >deps.log 2>&1; then
    tail -n 30 deps.log
    echo "tools/deps.sh failed (deps.log): the packages are not installed"
    echo "0 passed, 1 failed"
    exit 1
fi

# configure DIR OPTION...: DIR set up with exactly these options. An
# existing DIR keeps its prefix but takes every option named here; one
# that meson cannot reconfigure (another meson version, damaged) is wiped.
configure() {
    dir=$1
    shift
    if [ -f "$dir/meson-private/coredata.dat" ]; then
        meson setup --reconfigure "$dir" "$@" >"$dir.setup.log" 2>&1 ||
            meson setup --wipe "$dir" "$@" >"$dir.setup.log" 2>&1
    else
        meson setup "$dir" "$@" >"$dir.setup.log" 2>&1
    fi
}

# Options that decide what the suite is: warnings fail the build, tests
# built, the image tests wherever OSMesa and POV-Ray are, no fuzz targets.
common="-Dwerror=true -Dtests=true -Dimage_tests=auto -Dfuzz=false"

run_suite() { # build-dir, meson setup options...
    dir=$1
    # shellcheck disable=SC2086
    if ! configure "$@" $common; then
        tail -n 20 "$dir.setup.log"
        echo "setup of $dir failed ($dir.setup.log)"
        failed=$((failed + 1))
        return
    fi
    if ! ninja -C "$dir" >"$dir.build.log" 2>&1; then
        tail -n 40 "$dir.build.log"
        echo "build in $dir failed"
        failed=$((failed + 1))
        return
    fi
    meson test -C "$dir" --print-errorlogs --num-processes "$(nproc)" || true
    counts=$(python3 - "$dir/meson-logs/testlog.json" <<'PY'
import json, sys
ok = bad = 0
skipped = []
for line in open(sys.argv[1]):
    t = json.loads(line)
    r = t["result"]
    if r in ("OK", "EXPECTEDFAIL", "SKIP"):
        ok += r != "SKIP"
        if r == "SKIP":
            skipped.append(t.get("name", "?"))
    else:
        bad += 1
# A skip is a tool the machine lacks: say which, so that it is never silent.
if skipped:
    print("%d skipped: %s" % (len(skipped), " ".join(skipped)), file=sys.stderr)
print(ok, bad)
PY
) || counts="0 1"
    # shellcheck disable=SC2086
    set -- $counts
    passed=$((passed + $1))
    failed=$((failed + $2))
}
run_suite build -Dbuildtype=debugoptimized -Db_sanitize=none -Db_lundef=true
run_suite build-asan -Dbuildtype=debug -Db_sanitize=address,undefined -Db_lundef=false

# The Debian packages count as one test.
if [ "${CI:-}" = true ] || [ "${RAYGL_TEST_DEB:-0}" = 1 ]; then
    tools/test-deb.sh </dev/null
    case $? in
    0) passed=$((passed + 1)) ;;
    77) ;;
    *) failed=$((failed + 1)) ;;
    esac
else
    echo "test-deb: SKIP: runs in CI (CI=true) or with RAYGL_TEST_DEB=1 (it installs packages)"
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
