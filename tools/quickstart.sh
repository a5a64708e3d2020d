#!/bin/sh
# The README's main job, end to end: install, build, record the example
# program, translate its trace, render one frame with POV-Ray to a PNG.
set -eu
cd "$(dirname "$0")/.."
tools/deps.sh
[ -d build ] || meson setup build
ninja -C build
mkdir -p out
# The example is a GLUT program; Xvfb gives it a window on machines with
# no display. RAYGL_TRACE names the trace.
RAYGL_TRACE=out/cube.raygl xvfb-run -a -s "-screen 0 1024x768x24" build/examples/cube --frames 3
build/translate/raygl2pov --dump out/cube.raygl | head -n 20
rm -rf out/frames
build/translate/raygl2pov out/cube.raygl -o out/frames
povray out/frames/frame-00002.ini
echo "quickstart: the ray-traced frame is out/frames/frame-00002.png"
