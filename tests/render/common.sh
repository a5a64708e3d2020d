# common.sh: shared by the rendering tests (sourced).
#   $r2p $render $mkanim $imgcmp, $work (removed at exit), fail/ok, $fails
set -u
abs() { (cd "$(dirname "$1")" && echo "$(pwd)/$(basename "$1")"); }
r2p=$(abs "$1")
render=$(abs "$2")
mkanim=$(abs "$3")
imgcmp=$(abs "$4")
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-render.XXXXXX")
cleanup_hooks=""
cleanup() {
    for h in $cleanup_hooks; do "$h"; done
    chmod -R u+w "$work" 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
ok() { echo "ok: $*"; }

# Runs a program; leaves its exit status in $rc, stderr in $work/err.
run() {
    "$@" >"$work/out" 2>"$work/err"
    rc=$?
}
expect_rc() {
    want=$1
    shift
    if [ "$rc" -ne "$want" ]; then
        fail "$* exited $rc, expected $want; stderr:"
        sed 's/^/    /' "$work/err"
    else
        ok "$* exits $want"
    fi
}

# same_pngs A B: every A/*.png has a pixel-identical B/*.png (POV-Ray
# stamps the render time into the file, so bytes may differ).
same_pngs() {
    n=0
    for a in "$1"/*.png; do
        b="$2/$(basename "$a")"
        if ! "$imgcmp" --tol 0 --min-match 1 "$a" "$b" >"$work/cmp" 2>&1; then
            fail "$a differs from $b:"
            sed 's/^/    /' "$work/cmp"
        fi
        n=$((n + 1))
    done
    echo "$n"
}
