#!/bin/sh
# run-capture-test.sh: `raygl record` on unmodified programs, under Xvfb
# (run by xvfb-run; Mesa's software GL).
#
#   run-capture-test.sh CASE RAYGL PRELOAD CAPTURE_PROG RAYGL2POV RAYGL_COMPARE POVRAY OUTDIR
#
# Cases on capture_prog (each frame: one triangle, 3 glVertex2f):
#   glx egl glut single      each frame end: 3 frames, 9 vertices, translated
#   dlsym glxproc eglproc    each lookup path: the drawing calls recorded
#   dlsym-next               dlsym(RTLD_NEXT) from the program finds what it
#                            links to (the recording functions): libc sees
#                            the program as the caller
#   glut-solid               3 glutSolidTeapot, none of the GL calls
#                            freeglut makes to draw them
#   nurbs                    3 GLU NURBS surfaces: GLU draws them through
#                            evaluators, recorded and translated as meshes
#   threads                  two threads, two contexts: two streams of 3
#   kill                     SIGKILL mid-frame: the complete frames read
#                            and translate
#   fork exec                a forked child's calls stay out of the trace; a
#                            child that exec's a GL program gets its own file
#   select                   --frames, --every, --signal
#   usage                    --help, errors and exit codes
# Cases through POV-Ray and raygl-compare, with floors (tests/capture/meson.build):
#   glxgears FLOORS...       glxgears (GLX, display lists, lighting)
#   hack NAME FLOORS...      an xscreensaver hack (EGL)
set -u
[ $# -ge 8 ] || { echo "usage: $0 CASE RAYGL PRELOAD PROG RAYGL2POV COMPARE POVRAY OUTDIR" >&2; exit 2; }
case=$1 raygl=$2 preload=$3 prog=$4 r2p=$5 cmp=$6 povray=$7 out=$8
shift 8
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    */*) printf '%s/%s\n' "$PWD" "$1" ;;
    *) printf '%s\n' "$1" ;;
    esac
}
raygl=$(absolute "$raygl") preload=$(absolute "$preload") prog=$(absolute "$prog")
r2p=$(absolute "$r2p") cmp=$(absolute "$cmp") povray=$(absolute "$povray")
fail() { echo "capture test $case: FAIL: $*"; exit 1; }
skip() { echo "capture test $case: SKIP: $*"; exit 77; }

[ "$case" = hack ] && out=$out/hack-${1:-} || out=$out/$case
rm -rf "$out"
mkdir -p "$out" && cd "$out" || exit 1
RAYGL_PRELOAD_LIB=$preload
RAYGL_COMPARE=$cmp
export RAYGL_PRELOAD_LIB RAYGL_COMPARE

# A preload library built with sanitizers needs their runtimes loaded first
# in a program that has none (the ASan build); leaks in Mesa, the X
# libraries and the shell are not ours to check here.
san=$(ldd "$preload" | awk '/lib(asan|ubsan)\.so/ {print $3}' | tr '\n' ':')
san=${san%:}
if [ -n "$san" ]; then
    ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
    export ASAN_OPTIONS
fi
# raygl record ARGS..., with the sanitizer runtimes if needed; `exec
# record ...` in a background subshell keeps the program's pid as $!.
record() { env ${san:+LD_PRELOAD=$san} sh "$raygl" record "$@"; }

dump() { "$r2p" "$1" --dump 2>&1; }
count() { # TRACE PATTERN: lines of the dump matching it
    dump "$1" | grep -c -- "$2"
}
expect() { # TRACE PATTERN N
    n=$(count "$1" "$2")
    [ "$n" -eq "$3" ] || fail "$1: $n lines match '$2', expected $3"
}
translate() { # TRACE FRAMES: raygl2pov writes that many scenes
    "$r2p" "$1" -o "${1%.raygl}-pov" >"${1%.raygl}-pov.log" 2>&1 ||
        { cat "${1%.raygl}-pov.log"; fail "raygl2pov $1 failed"; }
    n=$(ls "${1%.raygl}-pov" | grep -c '^frame-.*\.pov$')
    [ "$n" -eq "$2" ] || fail "raygl2pov $1 wrote $n scenes, expected $2"
}
# The program's frames: N frames, 3N vertices, N triangles.
triangles() { # TRACE N
    expect "$1" '^frame ' "$2"
    expect "$1" 'glVertex2f(' $(($2 * 3))
    expect "$1" 'glBegin(mode=GL_TRIANGLES)' "$2"
}

case $case in
glx | egl | glut)
    record -o t.raygl -- "$prog" --api "$case" >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 3
    translate t.raygl 3
    ;;
single)
    record -o t.raygl -- "$prog" --api glx --single >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 3
    expect t.raygl 'glFlush()' 3
    translate t.raygl 3
    ;;
dlsym | dlsym-next | glxproc | eglproc)
    case $case in
    dlsym) args='--api glx --lookup dlsym' ;;
    dlsym-next) args='--api glx --lookup next' ;;
    glxproc) args='--api glx --lookup glx' ;;
    eglproc) args='--api egl --lookup egl' ;;
    esac
    record -o t.raygl -- "$prog" $args >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 3
    translate t.raygl 3
    ;;
glut-solid)
    record -o t.raygl -- "$prog" --api glut --teapot >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    expect t.raygl '^frame ' 3
    expect t.raygl 'glutSolidTeapot(' 3
    # freeglut draws a teapot with vertex arrays (older ones with glBegin):
    # none of it may appear beside the shape.
    expect t.raygl 'glBegin(\|glDrawArrays(\|glDrawElements(\|glVertexPointer(\|glNormalPointer(\|glVertex3f(' 0
    translate t.raygl 3
    ;;
nurbs)
    record -o t.raygl -- "$prog" --api glx --nurbs >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    expect t.raygl '^frame ' 3
    [ "$(count t.raygl 'glMap2f(target=GL_MAP2_VERTEX_3')" -ge 3 ] || fail "no glMap2f per surface"
    [ "$(count t.raygl 'glEvalMesh2(\|glEvalCoord2f(')" -ge 3 ] || fail "no evaluation"
    translate t.raygl 3
    for f in t-pov/frame-*.pov; do
        grep -q '^mesh2{' "$f" || fail "$f: the surface drew nothing"
    done
    ;;
threads)
    record -o t.raygl -- "$prog" --api glx --threads 2 >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 6
    expect t.raygl '^frame .*: stream 1, ' 3
    expect t.raygl '^frame .*: stream 2, ' 3
    # Each thread's own colour went to its own stream.
    dump t.raygl | awk '/^frame / {s = $4} /glColor3f\(r=1, g=0, b=1\)/ {print s}' | sort -u >s1
    dump t.raygl | awk '/^frame / {s = $4} /glColor3f\(r=1, g=0, b=2\)/ {print s}' | sort -u >s2
    [ "$(wc -l <s1)" -eq 1 ] && [ "$(wc -l <s2)" -eq 1 ] && ! cmp -s s1 s2 ||
        fail "the threads' calls are mixed between streams"
    translate t.raygl 6
    ;;
kill)
    (exec env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o t.raygl -- "$prog" --api glx \
        --frames 4 --hang "$out/hung" >prog.log 2>&1) &
    pid=$!
    i=0
    while [ ! -e hung ] && [ $i -lt 300 ]; do
        sleep 0.1
        i=$((i + 1))
    done
    [ -e hung ] || { kill -9 $pid; fail "the program never reached its last frame"; }
    kill -9 $pid
    wait $pid 2>/dev/null
    triangles t.raygl 4
    translate t.raygl 4
    ;;
fork)
    record -o t.raygl -- "$prog" --api glx --fork-child >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 3
    expect t.raygl 'glVertex2f(x=5, y=5)' 0
    [ "$(ls | grep -c '\.raygl$')" -eq 1 ] || fail "the child wrote a trace"
    translate t.raygl 3
    ;;
exec)
    record -o t.raygl -- "$prog" --api glx --exec-child >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 3
    child=$(ls | grep '^t\.[0-9]*\.raygl$')
    [ -n "$child" ] && [ "$(echo "$child" | wc -l)" -eq 1 ] || fail "no trace of the exec'd child: $(ls)"
    triangles "$child" 2
    translate t.raygl 3
    ;;
select)
    record -o range.raygl --frames 2-3 -- "$prog" --api glx --frames 6 >prog.log 2>&1 || fail "--frames run"
    triangles range.raygl 2
    expect range.raygl 'glVertex2f(x=-0.6' 1 # frame 2 moved its first vertex to -0.8 + 0.2
    record -o every.raygl --every 2 -- "$prog" --api glx --frames 5 >prog.log 2>&1 || fail "--every run"
    triangles every.raygl 3
    record -o both.raygl --frames 1- --every 3 -- "$prog" --api glx --frames 7 >prog.log 2>&1 || fail "--frames --every run"
    triangles both.raygl 2
    # One signal while the program draws 100 frames 20 ms apart: exactly
    # the next frame is kept.
    (exec env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o sig.raygl --signal USR1 -- "$prog" \
        --api glx --frames 100 --delay-ms 20 >prog.log 2>&1) &
    pid=$!
    sleep 1
    kill -USR1 $pid
    wait $pid || fail "the program failed under --signal"
    triangles sig.raygl 1
    translate sig.raygl 1
    ;;
usage)
    sh "$raygl" --help >help.log 2>&1 || fail "--help failed"
    grep -q '^usage: raygl record' help.log || fail "--help prints no usage"
    st() { "$@" >err.log 2>&1; echo $?; }
    line() { [ "$(wc -l <err.log)" -eq 1 ] && grep -q "^raygl: $1" err.log || { cat err.log; fail "message for $2"; }; }
    [ "$(st sh "$raygl")" -eq 2 ] || fail "no verb"
    [ "$(st sh "$raygl" frobnicate)" -eq 2 ] && line 'unknown command frobnicate' verb
    [ "$(st sh "$raygl" record)" -eq 2 ] && line 'record: no program' 'no program'
    [ "$(st sh "$raygl" record --bogus -- true)" -eq 2 ] && line 'record: unknown option --bogus' option
    [ "$(st sh "$raygl" record --frames 3-1 -- true)" -eq 2 ] && line 'record: --frames 3-1' range
    [ "$(st sh "$raygl" record --frames x -- true)" -eq 2 ] && line 'record: --frames x' 'bad range'
    [ "$(st sh "$raygl" record --every 0 -- true)" -eq 2 ] && line 'record: --every 0' every
    [ "$(st sh "$raygl" record --signal NOPE -- true)" -eq 2 ] && line 'record: --signal NOPE' signal
    [ "$(st sh "$raygl" record --signal KILL -- true)" -eq 2 ] && line 'record: --signal KILL' sigkill
    [ "$(st sh "$raygl" record -o)" -eq 2 ] && line 'record: -o needs' '-o'
    [ "$(st sh "$raygl" record -- /nonexistent/prog)" -eq 1 ] && line 'record: /nonexistent/prog: program not found' missing
    mkdir d
    [ "$(st sh "$raygl" record -o d -- true)" -eq 1 ] && line 'record: d is a folder' folder
    [ "$(st env RAYGL_PRELOAD_LIB=/nonexistent.so sh "$raygl" record -- true)" -eq 1 ] &&
        line 'record: /nonexistent.so: the preload library is missing' preload
    # The program's own exit status comes back; a program that draws
    # nothing leaves no trace.
    [ "$(st env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o none.raygl -- sh -c 'exit 3')" -eq 3 ] ||
        fail "exit status"
    [ ! -e none.raygl ] || fail "a program that drew nothing left a trace"
    line "recording sh into $out/none.raygl\$" 'the trace named'
    [ "$(st env ${san:+LD_PRELOAD=$san} sh "$raygl" record --signal SIGUSR2 -o none.raygl -- true)" -eq 0 ] &&
        line "recording true into $out/none.raygl (kill -USR2 [0-9]* records the next frame)\$" 'signal line'
    [ "$(st env ${san:+LD_PRELOAD=$san} sh "$raygl" record -q -o none.raygl -- true)" -eq 0 ] &&
        [ ! -s err.log ] || fail "-q printed $(cat err.log)"
    ;;
glxgears)
    command -v glxgears >/dev/null 2>&1 || skip "glxgears not installed (mesa-utils)"
    # glxgears runs until stopped: frames 2 to 4 are kept, then it is
    # stopped (the frames are on disk at their swap).
    record -o gears.raygl --frames 2-4 --snapshots -- timeout 4 glxgears -geometry 300x300 >prog.log 2>&1
    expect gears.raygl '^frame ' 3
    expect gears.raygl 'glCallList(list=1)' 3
    # Through `raygl compare` (raygl-compare, from RAYGL_COMPARE).
    sh "$raygl" compare gears.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" "$@" -- --no-shadows >cmp.log 2>&1
    rc=$?
    cat cmp.log
    [ $rc -eq 0 ] || fail "raygl-compare exited with $rc"
    [ "$(grep -c '^frame [0-9]*: 300x300 within' cmp.log)" -eq 3 ] || fail "not 3 frames compared"
    ;;
hack)
    name=$1
    shift
    hack=/usr/libexec/xscreensaver/$name
    [ -x "$hack" ] || skip "$hack not installed (xscreensaver-gl)"
    record -o hack.raygl --frames 10-12 --snapshots -- timeout 4 "$hack" -window -geometry 320x240 >prog.log 2>&1
    expect hack.raygl '^frame ' 3
    expect hack.raygl '@Snapshot(x=0, y=0, width=320, height=240' 3
    "$cmp" hack.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" "$@" -- --no-shadows >cmp.log 2>&1
    rc=$?
    cat cmp.log
    [ $rc -eq 0 ] || fail "raygl-compare exited with $rc"
    ;;
*) echo "unknown case $case" >&2; exit 2 ;;
esac
echo "capture test $case: PASS"
