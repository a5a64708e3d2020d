#!/bin/sh
# test_include_defaults.sh: --include objects get POV-Ray's own defaults
# (issue 27).
#
#   test_include_defaults.sh PROG RAYGL2POV POVRAY IMGCMP DIR
#
# PROG (example_scene: the README's lit scene under a gluLookAt) is
# translated with --include floor.inc, the man page's floor example
# (plane{y,-1 pigment{checker} transform RayGL_World}), and rendered. The
# reference is the same scene with the include (and RayGL_World) moved
# before the scene's `#default` finish, where POV-Ray's built-in defaults
# hold: the two images must be equal. With RayGL's unlit default (ambient
# 0, diffuse 0, emission 1) the floor was flat, its checker's pure colours.
set -u
prog=$1
r2p=$2
povray=$3
imgcmp=$4
dir=$5
fail() { echo "FAIL: $*"; exit 1; }
abs() { case $1 in /*) echo "$1" ;; */*) echo "$PWD/$1" ;; *) echo "$1" ;; esac; }
prog=$(abs "$prog") r2p=$(abs "$r2p") povray=$(abs "$povray") imgcmp=$(abs "$imgcmp")
rm -rf "$dir"
mkdir -p "$dir" || exit 1
cd "$dir" || exit 1
"$prog" --trace e.raygl --png gl.png >program.log 2>&1 || fail "the program exited with $?"
echo 'plane{y,-1 pigment{checker} transform RayGL_World}' >floor.inc
"$r2p" e.raygl -o pov --include floor.inc --no-shadows --quiet || fail "raygl2pov"
pov=pov/frame-00000.pov
grep -q '^#include "include-1-floor.inc"$' "$pov" || fail "no #include line in $pov"
# The reference: the declaration and the include before the first #default.
awk '/^#declare RayGL_World/ || /^#include "include-1-floor.inc"/ { next }
     /^#default\{/ && !done { while ((getline l < "'"$pov"'") > 0)
         if (l ~ /^#declare RayGL_World/ || l ~ /^#include "include-1-floor.inc"/) print l
         done = 1 }
     { print }' "$pov" >pov/ref.pov
[ "$(grep -c 'include-1-floor.inc' pov/ref.pov)" -eq 1 ] || fail "reference scene not made"
"$povray" pov/frame-00000.ini -D -A >povray.log 2>&1 || fail "povray (scene)"
"$povray" pov/frame-00000.ini +Ipov/ref.pov +Opov/ref.png -D -A >povray-ref.log 2>&1 ||
    fail "povray (reference)"
"$imgcmp" --tol 1 --min-match 0.9999 --diff diff.png pov/ref.png pov/frame-00000.png ||
    fail "the included floor differs from POV-Ray's defaults (see $dir/diff.png: reference | scene | difference)"
echo "include-defaults: PASS"
