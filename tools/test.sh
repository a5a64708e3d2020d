#!/bin/sh
# The whole test suite: a normal build and an AddressSanitizer +
# UndefinedBehaviorSanitizer build, each running `meson test`. Prints
# `N passed, N failed` last and exits non-zero on any failure.
set -u
cd "$(dirname "$0")/.."
passed=0
failed=0
run_suite() { # build-dir, meson setup options...
    dir=$1
    shift
    if [ ! -d "$dir" ]; then
        meson setup "$dir" "$@" >/dev/null || { failed=$((failed + 1)); echo "setup of $dir failed"; return; }
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
for line in open(sys.argv[1]):
    r = json.loads(line)["result"]
    if r in ("OK", "EXPECTEDFAIL", "SKIP"):
        ok += r != "SKIP"
    else:
        bad += 1
print(ok, bad)
PY
)
    set -- $counts
    passed=$((passed + $1))
    failed=$((failed + $2))
}
run_suite build -Dwerror=true
run_suite build-asan -Dwerror=true -Db_sanitize=address,undefined -Db_lundef=false \
    -Dbuildtype=debug
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
