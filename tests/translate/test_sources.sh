#!/bin/sh
# test_sources.sh: no floating-point value goes through printf in translate/.
#
# printf's %f/%g/%e/%a follow LC_NUMERIC (de_DE writes 0,5), so every number
# in the output goes through numfmt. This scans the translator's sources for
# a float conversion in any format string, and checks that the writer and
# the formatter do not call the printf family at all.
dir=${1:?usage: test_sources.sh TRANSLATE_DIR}
status=0
if grep -rnE --include='*.c' --include='*.h' '"[^"]*%[-+ #0-9.*]*[lL]?[fFeEgGaA][^"]*"' "$dir"; then
    echo "test_sources: a float conversion in a format string (above)"
    status=1
fi
for f in text/numfmt.c pov/povwrite.c pov/povwrite_mesh2.c gltf/gltfwrite.c text/outbuf.c text/dedup.c scene/scene.c scene/mat4.c; do
    if grep -nE '\b(s?n?printf|v?s?n?printf|fprintf|vfprintf|strtod)\s*\(' "$dir/$f"; then
        echo "test_sources: $f calls printf (above)"
        status=1
    fi
done
[ $status -eq 0 ] && echo "test_sources: no float formatting through printf"
exit $status
