#!/bin/sh
# test_man.sh DOCS PAGE...: every man page of RayGL renders on its own and
# says what it should.
#
# Each PAGE (a file name in DOCS) must exist, stand alone (no .so: `man -l`
# resolves it from the current folder, not the man path), carry a .TH line
# naming it with a YYYY-MM-DD date, render with groff -ww and
# `man -l --warnings` without one line on standard error (neither tool
# fails on a warning by its exit status), point to the TRANSLATION section
# of raygl2pov(1) and docs/mapping.md, and never say that something is
# "not translated yet" (docs/mapping.md is the reference for that). Only
# raygl2pov(1) lists what is translated exactly, approximately and not at
# all; the other pages point to it. No alternating-font macro (.BR, .IB,
# ...) may join two words: its arguments are set with no space between
# (".BR \-\-frames . A PNG" shows "APNG").
docs=$1
shift
fail=0
err() {
    echo "$docs/$1: $2" >&2
    fail=1
}
# Neighbouring arguments of .BR .RB .BI .IB .IR .RI that end and start
# with a letter or digit (after font escapes; a named character such as
# \(mu is neither).
runon='
/^\.(BR|RB|BI|IB|IR|RI)[ \t]/ {
    line = substr($0, 4)
    n = 0
    while (length(line) > 0) {
        sub(/^[ \t]+/, "", line)
        if (line == "")
            break
        if (substr(line, 1, 1) == "\"") {
            a = ""
            i = 2
            while (i <= length(line)) {
                c = substr(line, i, 1)
                if (c == "\"" && substr(line, i + 1, 1) == "\"") { a = a "\""; i += 2; continue }
                if (c == "\"") { i++; break }
                a = a c
                i++
            }
            line = substr(line, i)
        } else {
            match(line, /^[^ \t]+/)
            a = substr(line, 1, RLENGTH)
            line = substr(line, RLENGTH + 1)
        }
        gsub(/\\\([^ ][^ ]/, "#", a)
        gsub(/\\\[[^]]*\]/, "#", a)
        arg[++n] = a
    }
    for (k = 1; k < n; k++) {
        left = arg[k]
        while (left ~ /\\f[A-Z]$/ || left ~ /\\&$/)
            sub(/\\f[A-Z]$|\\&$/, "", left)
        right = arg[k + 1]
        while (right ~ /^\\f[A-Z]/ || right ~ /^\\&/)
            sub(/^\\f[A-Z]|^\\&/, "", right)
        if (left ~ /[A-Za-z0-9]$/ && right ~ /^[A-Za-z0-9]/)
            printf "line %d: %s and %s run together: %s\n", FNR, arg[k], arg[k + 1], $0
    }
}'
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
for page in "$@"; do
    f=$docs/$page
    if [ ! -f "$f" ]; then
        err "$page" "missing"
        continue
    fi
    if grep -q '^\.so' "$f"; then
        err "$page" "a .so redirect: man -l cannot follow it"
    fi
    name=$(basename "$page" .1 | tr 'a-z' 'A-Z')
    th=$(grep -m1 '^\.TH' "$f")
    if ! printf '%s\n' "$th" | grep -Eq "^\.TH $name 1 \"[0-9]{4}-[0-9]{2}-[0-9]{2}\" "; then
        err "$page" "its .TH line is not '.TH $name 1 \"YYYY-MM-DD\" ...': $th"
    fi
    if grep -iq 'not translated yet\|not yet translated' "$f"; then
        err "$page" "says 'not translated yet': docs/mapping.md says what is translated"
    fi
    if ! grep -q 'TRANSLATION' "$f" || ! grep -q 'docs/mapping\.md' "$f"; then
        err "$page" "does not point to raygl2pov(1) TRANSLATION and docs/mapping.md"
    fi
    if [ "$page" != raygl2pov.1 ] &&
        grep -Eiq 'exact[:(]|exact \(|approximate[:(]|approximate \(|not at all[:(]|not at all \(' "$f"; then
        err "$page" "lists what is translated: only raygl2pov(1) TRANSLATION does, point to it"
    fi
    awk "$runon" "$f" >"$tmp/runon"
    if [ -s "$tmp/runon" ]; then
        err "$page" "words run together: $(head -n 3 "$tmp/runon" | tr '\n' ' ')"
    fi
    if command -v groff >/dev/null 2>&1; then
        groff -man -ww -z "$f" 2>"$tmp/groff" || err "$page" "groff failed"
        if [ -s "$tmp/groff" ]; then
            err "$page" "groff -ww: $(head -n 3 "$tmp/groff" | tr '\n' ' ')"
        fi
    fi
    if command -v man >/dev/null 2>&1; then
        # From an empty folder: a relative .so or include must not resolve
        # by luck.
        (cd "$tmp" && MANWIDTH=80 man -l --warnings "$f") >"$tmp/out" 2>"$tmp/man" ||
            err "$page" "man -l failed"
        if [ -s "$tmp/man" ]; then
            err "$page" "man -l --warnings: $(head -n 3 "$tmp/man" | tr '\n' ' ')"
        fi
        if ! grep -q "^$name(1)" "$tmp/out"; then
            err "$page" "man -l shows no $name(1) header"
        fi
    fi
done
[ "$fail" -eq 0 ] || exit 1
if ! command -v groff >/dev/null 2>&1 && ! command -v man >/dev/null 2>&1; then
    echo "neither groff nor man found (tools/deps.sh installs them): pages not rendered" >&2
    exit 77
fi
echo "ok: $# pages"
