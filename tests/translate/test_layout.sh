#!/bin/sh
# test_layout.sh: the translator's layout rules (docs/design.md "Layers").
#
#   test_layout.sh SOURCE_ROOT
#
# Reads the table of parts and the parts each may include from
# docs/design.md (the block after "part      may include"), then checks:
#   - every folder of translate/ is a part of the table, and nothing sits
#     in translate/ itself but meson.build;
#   - every #include "X" in a part names a header of that part or of a part
#     it may include (format: format/'s headers; the generated writer_list.h
#     is the driver's), and <GL/...> only where the table says GL;
#   - no two headers or sources of the product (format/, record/,
#     translate/, compare/, include/, examples/) share a name, so a bare
#     include is unambiguous;
#   - cli/ writes no SDL (no POV-Ray keyword in its strings);
#   - translate/ builds at least six static libraries;
#   - no function of the product is longer than 200 lines, no source file
#     longer than 1,500 (STYLE.md: one concept per file);
#   - interp.h's map names every file of gl/, scene.h every writer;
#   - every function a part's header declares is used.
# The build enforces the include rules too (translate/meson.build: each
# part's include directory reaches only the parts it may use); this test
# keeps the table, the sources and the build saying the same.
set -u
root=${1:?usage: test_layout.sh SOURCE_ROOT}
tr=$root/translate
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
ok() { echo "ok: $*"; }

rules=$(awk '/^part +may include/ { on = 1; next } on && /^```/ { exit } on && NF { print }' \
    "$root/docs/design.md")
[ -n "$rules" ] || { echo "FAIL: no table of parts in docs/design.md"; exit 1; }
parts=$(echo "$rules" | awk '{ print $1 }')
allowed() { echo "$rules" | awk -v p="$1" '$1 == p { $1 = ""; print }'; }

# Every folder is a part; the root holds only the build file.
for d in "$tr"/*/; do
    p=$(basename "$d")
    echo "$parts" | grep -qx "$p" || fail "translate/$p/ is not in docs/design.md's table"
done
for f in "$tr"/*; do
    [ -d "$f" ] || [ "$(basename "$f")" = meson.build ] || fail "translate/$(basename "$f"): outside every part"
done

# Which part each header belongs to.
owners=$(
    for p in $parts; do
        [ -d "$tr/$p" ] || continue
        for h in "$tr/$p"/*.h "$tr/$p"/*.def; do
            [ -f "$h" ] && echo "$(basename "$h") $p"
        done
    done
    for h in "$root"/format/*.h "$root"/format/*.def; do
        echo "$(basename "$h") format"
    done
    echo "writer_list.h driver"
)
owner() { echo "$owners" | awk -v h="$1" '$1 == h { print $2; exit }'; }

nincl=0
for p in $parts; do
    [ -d "$tr/$p" ] || { fail "part $p of the table has no folder"; continue; }
    may=" $p $(allowed "$p") "
    for f in "$tr/$p"/*.c "$tr/$p"/*.h "$tr/$p"/*.def; do
        [ -f "$f" ] || continue
        for h in $(sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$f"); do
            nincl=$((nincl + 1))
            q=$(owner "$(basename "$h")")
            if [ -z "$q" ]; then
                fail "$p/$(basename "$f") includes \"$h\", no header of a part"
            elif [ "$h" != "$(basename "$h")" ]; then
                fail "$p/$(basename "$f") includes \"$h\" by a path: parts include by name"
            else
                case $may in *" $q "*) ;; *) fail "$p/$(basename "$f") includes $h (part $q): $p may include$(allowed "$p")" ;; esac
            fi
        done
        if grep -qE '^[ \t]*#[ \t]*include[ \t]*<GL/' "$f"; then
            case $may in *" GL "*) ;; *) fail "$p/$(basename "$f") includes a GL header" ;; esac
        fi
    done
done
[ "$nincl" -gt 100 ] && ok "$nincl includes in translate/ follow the table" ||
    fail "only $nincl includes found: the scan is broken"

# One name, one file.
dups=$(cd "$root" && find format record translate compare include examples -name '*.[ch]' \
    -printf '%f\n' 2>/dev/null | sort | uniq -d)
[ -z "$dups" ] && ok "no two product sources or headers share a name" ||
    fail "names in several folders: $(echo $dups)"

# The command line writes no SDL.
sdl='light_source|global_settings|#declare|#include \\"|area_light|radiosity\{|pigment\{|texture\{|finish\{|Antialias=|Quality=|Library_Path'
if grep -nE "\"[^\"]*($sdl)" "$tr"/cli/*.c; then
    fail "cli/ writes SDL (above)"
else
    ok "cli/ writes no SDL"
fi

nlib=$(cat "$tr"/meson.build "$tr"/*/meson.build | grep -c "static_library(")
[ "$nlib" -ge 6 ] && ok "translate/ builds $nlib static libraries" ||
    fail "translate/ builds $nlib static libraries (at least 6)"

# Functions: from the line with their name to the closing brace at column 0.
long=$(cd "$root" && find format record translate compare -name '*.c' | sort | xargs awk '
/^[A-Za-z_][A-Za-z0-9_ \t*]*[ \t*][A-Za-z_][A-Za-z0-9_]*\(/ && !/;[ \t]*$/ && !/^(typedef|struct|enum|union|static const|const)[ \t].*[=;]/ {
    head = FNR; match($0, /[A-Za-z_][A-Za-z0-9_]*\(/); name = substr($0, RSTART, RLENGTH - 1); next
}
/^\{/ { if (head) { start = head; fname = name }; head = 0; next }
/^\}/ { if (start && FNR - start + 1 > 200) print FILENAME ":" start ": " fname " (" FNR - start + 1 " lines)"; start = 0; next }
/;[ \t]*$/ { if (!start) head = 0 }
')
[ -z "$long" ] && ok "no function over 200 lines" || fail "functions over 200 lines: $long"
big=$(cd "$root" && find format record translate compare -name '*.[ch]' | sort | xargs wc -l |
    awk '$2 != "total" && $1 > 1500 { print $2 " (" $1 " lines)" }')
[ -z "$big" ] && ok "no source file over 1,500 lines" || fail "files over 1,500 lines: $(echo $big)"
# The maps: interp.h names every file of gl/, scene.h every writer.
missing=
for f in "$tr"/gl/*; do
    b=$(basename "$f")
    [ "$b" = interp.h ] || sed -n '1,/\*\//p' "$tr/gl/interp.h" | grep -q "$b" || missing="$missing $b"
done
[ -z "$missing" ] && ok "interp.h's map names every file of gl/" ||
    fail "interp.h's map does not name:$missing"
writers=$(sed -n "s/^writers = \[\(.*\)\]/\1/p" "$tr/meson.build" | tr -d "',")
[ -n "$writers" ] || fail "no writers list in translate/meson.build"
nw=0
for w in $writers; do
    sed -n '1,/\*\//p' "$tr/scene/scene.h" | grep -q "$w/" && nw=$((nw + 1)) ||
        fail "scene.h does not name the writer $w/"
done
[ "$nw" -gt 0 ] && ok "scene.h names the $nw writers"

# Every function a part's header declares is used somewhere (the product,
# its tests, benchmarks or fuzz targets; raygl-compare uses proc/): a
# name seen only in its declaration and its definition is dead.
words=$(cd "$root" && find translate compare tests bench fuzz -name '*.[ch]' | xargs grep -ohwE '[a-z_][a-z0-9_]*' |
    sort | uniq -c | awk '{ print $2, $1 }')
declared=$(cat "$tr"/*/*.h | grep -E '^[a-z_][a-z0-9_ *]*[ *][a-z_][a-z0-9_]*\(' |
    grep -vE '^(static|typedef)' | sed -E 's/^[^(]*[ *]\**([a-z_][a-z0-9_]*)\(.*/\1/' | sort -u)
dead=$(printf '%s\n---\n%s\n' "$words" "$declared" |
    awk '$1 == "---" { names = 1; next } !names { n[$1] = $2; next } (n[$1] + 0) <= 2 { print $1 }')
ndecl=$(echo "$declared" | wc -l)
[ -z "$dead" ] && ok "each of the $ndecl functions the parts' headers declare is used" ||
    fail "declared and defined, never used: $(echo $dead)"

echo "$failed failed"
[ "$failed" -eq 0 ]
