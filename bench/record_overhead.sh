#!/bin/sh
# record_overhead.sh: what recording costs in CPU time, before and after a
# change, in one run: builds libraygl from git REF (default main) in a
# scratch folder and runs bench_record from BUILD_DIR with it as `before`
# (interleaved with plain GL, this tree's libraygl and apitrace; no GL
# context and OSMesa). Extra arguments go to bench_record (--frames,
# --reps, --calls, --no-apitrace).
#
#   bench/record_overhead.sh BUILD_DIR [REF] [bench_record options]
set -eu
build=$(cd "$1" && pwd)
ref=${2:-main}
[ $# -ge 2 ] && shift 2 || shift $#
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-recbench.XXXXXX")
trap 'rm -rf "$work"' EXIT
git -C "$src" archive "$ref" | tar -x -C "$work"
meson setup "$work/build" "$work" >"$work/setup.log" 2>&1 ||
    { cat "$work/setup.log" >&2; exit 1; }
lib=$(ninja -C "$work/build" -t targets all | grep -o '^record/libraygl\.so\.[0-9.]*[0-9]' | head -1)
ninja -C "$work/build" ${lib:-} >"$work/build.log" 2>&1 ||
    { tail -20 "$work/build.log" >&2; exit 1; }
ninja -C "$build" bench/bench_record >/dev/null
echo "before: libraygl of $ref ($(git -C "$src" rev-parse --short "$ref")); raygl: $build"
"$build/bench/bench_record" --before "$work/build/record" "$@"
