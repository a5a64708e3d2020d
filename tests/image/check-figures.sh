#!/bin/sh
# check-figures.sh: an image test's figures against the figures file
# (tests/image/figures.txt, docs/testing.md "The figures file").
#
#   check-figures.sh FILE NAME TOL WITHIN SILHOUETTE
#       prints "figures: NAME tol TOL within WITHIN silhouette SILHOUETTE"
#       (tools/update-figures.py reads these lines from a test log), then
#       fails when FILE has no line for NAME, when the line's tolerance is
#       not TOL, or when WITHIN or SILHOUETTE lies more than the line's
#       margin below the line's figure; a figure above the line's passes
#       and is reported as improved.
#   check-figures.sh --frames FILE NAME NFRAMES
#       fails when FILE has a line NAME/K for a frame K >= NFRAMES (the
#       program draws fewer frames than the file says).
#   check-figures.sh --names FILE NAME...
#       fails when a line of FILE is malformed, named twice, or names a
#       test (NAME, or NAME/K for a frame) that is not among the NAMEs.
#
# A line of FILE: NAME TOL WITHIN SILHOUETTE MARGIN REASON...
# MARGIN is "-" for the default below, or the drop allowed for that test
# (animated programs, whose frames vary from run to run: their figures are
# the lowest measured, and one above them is not reported). '#' starts a
# comment line. Exit 0 when the figures hold, 1 when not, 2 on bad usage.
set -u

# The default margin: the image tests' figures came out identical over two
# runs of the normal build and one of the AddressSanitizer build
# (docs/testing.md "The figures file"); 0.0001 is 7 pixels of 320x240, less
# than a thin line or a small lost primitive, more than a refactor's
# rounding moving an edge pixel or two.
default_margin=0.0001

usage() {
    echo "usage: $0 FILE NAME TOL WITHIN SILHOUETTE | --frames FILE NAME NFRAMES | --names FILE NAME..." >&2
    exit 2
}

# The file's well-formed lines and its errors, for every mode: "error TEXT"
# or "line NAME TOL WITHIN SILHOUETTE MARGIN OWN" (OWN 1: a margin of the
# line's own).
parse() {
    awk -v margin="$default_margin" '
    function num01(s) { return s ~ /^(0(\.[0-9]+)?|1(\.0+)?)$/ }
    /^[ \t]*(#|$)/ { next }
    {
        if (NF < 6) { print "error line " NR ": fewer than 6 fields (NAME TOL WITHIN SILHOUETTE MARGIN REASON)"; next }
        if ($1 !~ /^[A-Za-z0-9_-]+(\/[0-9]+)?$/) { print "error line " NR ": bad name " $1; next }
        if ($2 !~ /^[0-9]+$/) { print "error line " NR ": " $1 ": bad tolerance " $2; next }
        if (!num01($3) || !num01($4)) { print "error line " NR ": " $1 ": figures not in 0..1: " $3 " " $4; next }
        m = $5
        own = m != "-"
        if (!own) m = margin
        else if (!num01(m)) { print "error line " NR ": " $1 ": bad margin " $5; next }
        if ($1 in seen) { print "error line " NR ": " $1 " again (line " seen[$1] ")"; next }
        seen[$1] = NR
        print "line", $1, $2, $3, $4, m, own
    }' "$1"
}

[ $# -ge 1 ] || usage
case $1 in
--frames)
    [ $# -eq 4 ] || usage
    file=$2 name=$3 nframes=$4
    [ -r "$file" ] || { echo "figures: $file: cannot read" >&2; exit 2; }
    parse "$file" | awk -v name="$name" -v n="$nframes" -v file="$file" '
    $1 == "line" && index($2, name "/") == 1 {
        k = substr($2, length(name) + 2)
        if (k + 0 >= n + 0) {
            print "figures: " name ": FAIL: " file " has a line for frame " k ", the program drew " n " frames: remove it"
            bad = 1
        }
    }
    END { exit bad }'
    exit $?
    ;;
--names)
    [ $# -ge 2 ] || usage
    file=$2
    shift 2
    [ -r "$file" ] || { echo "figures: $file: cannot read" >&2; exit 2; }
    parse "$file" | awk -v file="$file" -v names="$*" '
    BEGIN { n = split(names, a, " "); for (i = 1; i <= n; i++) known[a[i]] = 1 }
    $1 == "error" { sub(/^error /, ""); print "figures: " file ": " $0; bad = 1; next }
    {
        base = $2
        sub(/\/[0-9]+$/, "", base)
        if (!(base in known)) {
            print "figures: " file ": a line for " $2 ", which is no test of the suite: remove it"
            bad = 1
        }
    }
    END { exit bad }'
    exit $?
    ;;
esac

[ $# -eq 5 ] || usage
file=$1 name=$2 tol=$3 within=$4 sil=$5
echo "figures: $name tol $tol within $within silhouette $sil"
[ -r "$file" ] || { echo "figures: $file: cannot read" >&2; exit 2; }
parse "$file" | awk -v name="$name" -v tol="$tol" -v w="$within" -v s="$sil" -v file="$file" '
function check(what, got, want, m, own) {
    if (got + 0 < want - m - 1e-9) {
        printf "figures: %s: FAIL: %s %s is %.5f below %s'"'"'s %s (margin %s); if the drop is meant, update the file with the reason (tools/update-figures.py)\n", name, what, got, want - got, file, want, m
        bad = 1
    } else if (!own && got + 0 > want + 1e-9)
        printf "figures: %s: improved: %s %s above %s'"'"'s %s: raise it (tools/update-figures.py)\n", name, what, got, file, want
}
$1 == "error" && index($0, " " name ":") { sub(/^error /, ""); print "figures: " file ": " $0; bad = 1 }
$1 == "line" && $2 == name {
    found = 1
    if ($3 != tol) {
        print "figures: " name ": FAIL: " file " holds figures within " $3 "/255, the test measures within " tol "/255: update the line"
        bad = 1
    } else {
        check("within " tol "/255", w, $4, $6, $7)
        check("silhouette", s, $5, $6, $7)
    }
}
END {
    if (!found && !bad) {
        print "figures: " name ": FAIL: no line in " file ": a new test adds its line (tools/update-figures.py)"
        bad = 1
    }
    exit bad
}'
