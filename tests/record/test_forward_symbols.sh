#!/bin/sh
# test_forward_symbols.sh NM LIBRAYGL: fails when libraygl imports a gl*
# function directly (not glX*): such a call would reach the GL linked first,
# not the one whose context is current (record/forward.h). A new GL call in
# record/ goes in tools/gen_preload.c's forward_extra.
nm=$1 lib=$2
syms=$("$nm" -D --undefined-only "$lib") || { echo "$lib: nm failed" >&2; exit 1; }
bad=$(printf '%s\n' "$syms" | awk '{print $NF}' | grep -E '^gl[A-Z]' | grep -v '^glX')
count=$(printf '%s\n' "$syms" | awk '{print $NF}' | grep -c '^glu[A-Z]')
if [ "$count" -eq 0 ]; then
    echo "$lib: no glu* import: nm output not understood" >&2
    exit 1
fi
if [ -n "$bad" ]; then
    echo "$lib: gl* functions imported directly, not through forward_real.h:" $bad >&2
    exit 1
fi
echo "ok: no direct gl* import"
