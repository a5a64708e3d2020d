#!/bin/sh
# same_output.sh PLAIN RECORDED DIR [PRELOAD]: runs a program built plain
# and built to record (-include raygl/gl.h), or with PRELOAD the plain one
# again under LD_PRELOAD=PRELOAD (what `raygl record` does), and fails
# unless both print the same lines and exit with the same status, and the
# recorded one wrote a trace. Each run works in a directory of its own
# under DIR (runs may be concurrent), kept when it fails.
set -u
plain=$1 recorded=$2 preload=${4:-}
mkdir -p "$3" || exit 1
dir=$(mktemp -d "$3/run.XXXXXX") || exit 1
"$plain" >"$dir/plain.txt" 2>"$dir/plain.err"
ps=$?
if [ -n "$preload" ]; then
    # A preload library built with sanitizers needs their runtimes first.
    san=$(ldd "$preload" | awk '/lib(asan|ubsan)\.so/ {print $3}' | tr '\n' ':')
    RAYGL_TRACE="$dir/recorded.raygl" ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
        LD_PRELOAD="$san$preload" "$recorded" >"$dir/recorded.txt" 2>"$dir/recorded.err"
else
    RAYGL_TRACE="$dir/recorded.raygl" "$recorded" >"$dir/recorded.txt" 2>"$dir/recorded.err"
fi
rs=$?
fail=0
if [ "$ps" -ne "$rs" ]; then
    echo "same_output.sh: exit status $ps plain, $rs recorded" >&2
    fail=1
fi
if ! cmp -s "$dir/plain.txt" "$dir/recorded.txt"; then
    echo "same_output.sh: the recorded run printed something else:" >&2
    diff "$dir/plain.txt" "$dir/recorded.txt" >&2
    fail=1
fi
if [ ! -s "$dir/recorded.raygl" ]; then
    echo "same_output.sh: $dir/recorded.raygl: no trace written" >&2
    fail=1
fi
lines=$(wc -l <"$dir/plain.txt")
echo "$lines lines and exit status $ps, plain and recorded"
[ "$fail" -eq 0 ] && rm -r "$dir"
exit $fail
