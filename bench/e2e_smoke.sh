#!/bin/sh
# e2e_smoke.sh: the bench-smoke test. Runs bench/e2e.sh at 2000 triangles,
# one run, 64x48, with an OSMesa context and with none, and fails unless
# each table has the rows issue 16 asks for (recording, translation,
# POV-Ray's parse and render, each step's peak memory, the bytes of trace
# and SDL) and every cell of every row is a number. The figures themselves
# are never checked.
#
#   e2e_smoke.sh E2E_SH OUT_DIR --plain P --rec P --raygl2pov P --povray P --runstat P
set -u
e2e=$1 dir=$2
shift 2
mkdir -p "$dir" || exit 1
fail=0
for ctx in osmesa none; do
    opt=
    [ $ctx = osmesa ] || opt=--no-context
    table=$dir/table-$ctx.md
    rm -f "$table"
    if ! sh "$e2e" --sizes 2000 --runs 1 --size 64x48 $opt --keep "$dir/keep-$ctx" --out "$table" "$@" \
        >"$dir/e2e-$ctx.log" 2>&1; then
        cat "$dir/e2e-$ctx.log" >&2
        echo "e2e_smoke.sh: e2e.sh failed ($ctx)" >&2
        fail=1
        continue
    fi
    for label in 'triangles drawn' 'program alone: CPU s' 'program recorded: CPU s' \
        'program recorded: peak MB' 'recording cost: CPU s' 'trace bytes' \
        'raygl2pov -j 1: wall s' 'raygl2pov -j 1: peak MB' 'SDL bytes (all files written)' \
        'POV-Ray parse s' 'POV-Ray parse CPU s' 'POV-Ray render s' 'POV-Ray render CPU s' 'POV-Ray: peak MB' 'trace to PNG: wall s'; do
        grep -q "^| $label" "$table" || { echo "e2e_smoke.sh: $table: no row '$label'" >&2; fail=1; }
    done
    # Every row below the header: a label, then one numeric cell per size.
    bad=$(awk -F'|' '
        /^\| figure \|/ { head = 1; next }
        head && /^\|---/ { rows = 1; next }
        rows && /^\|/ {
            n++
            if (NF != 4) { print "row " n " has " NF - 2 " cells: " $0; next }
            c = $3; gsub(/ /, "", c)
            if (c !~ /^[-+]?[0-9]+(\.[0-9]+)?$/) print "not a number: " $0
        }
        END { if (n < 20) print "only " n " rows" }' "$table")
    if [ -n "$bad" ]; then
        echo "e2e_smoke.sh: $table:" >&2
        echo "$bad" >&2
        fail=1
    fi
done
[ $fail -eq 0 ] && echo "e2e_smoke.sh: both tables complete"
exit $fail
