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
#   unrecorded               calls passed through unrecorded: counted per
#                            frame (@NotRecorded), reported by raygl2pov
#                            where they can change the picture (--verbose:
#                            all, marked); queries not counted
#   quiet                    a plain GLUT program with stroke text: its
#                            window-system calls counted, freeglut's strokes
#                            recorded; raygl2pov prints nothing, and the
#                            frame (without the text) is exact (POVRAY)
#   nurbs                    3 GLU NURBS surfaces: recorded as the GLU calls,
#                            none of the GL calls GLU draws them with;
#                            translated as meshes
#   nurbs-tess               the same in GLU_NURBS_TESSELLATOR mode: the
#                            callbacks' GL calls recorded as the program's
#   threads                  two threads, two contexts: two streams of 3
#   kill                     SIGKILL mid-frame: the complete frames read
#                            and translate
#   fork exec                a forked child's calls stay out of the trace; a
#                            child that exec's a GL program gets its own file
#   select                   --frames, --every, --signal
#   usage                    --help, --version, errors and exit codes
#   buildtree                build/record/raygl run as it is from another
#                            folder, and through a link on PATH
#   installed BINDIR LIBDIR INSTALLED-RAYGL
#                            the installed raygl in a prefix made by hand,
#                            then moved
#   exit                     --exit: the program ended after its last kept
#                            frame, exit 0, the trace closed
#   exit-glxgears            raygl record --frames 0-2 --exit -- glxgears
#   status                   exit 74 when the trace fails; else the program's
#   signals                  TERM to raygl reaches the program; INT keeps its
#                            default action; stdin reaches the program
#   frames                   raygl record --frames takes raygl2pov's grammar
#                            (lists, :STEP) and keeps the frames raygl2pov
#                            --frames selects
# Cases on capture_prog_dropin (the drop-in header's build; its path after
# OUTDIR):
#   dropin-text              GLUT bitmap and stroke text recorded by the
#                            linked libraygl as the preload records it
#   dropin-record            raygl record of it: one trace, the named one,
#                            complete and closed (the preload stands down)
#   dropin-exit              RAYGL_FRAMES/RAYGL_EXIT and RAYGL_SIGNAL for a
#                            linked program run without raygl record
# Cases through POV-Ray and raygl-compare, with floors (tests/capture/meson.build):
#   glxgears FLOORS...       glxgears (GLX, display lists, lighting)
#   hack NAME FLOORS...      an xscreensaver hack (EGL)
set -u
[ $# -ge 8 ] || { echo "usage: $0 CASE RAYGL PRELOAD PROG RAYGL2POV COMPARE POVRAY OUTDIR" >&2; exit 2; }
case=$1 raygl=$2 preload=$3 prog=$4 r2p=$5 cmp=$6 povray=$7 out=$8
shift 8
here=$(cd "$(dirname "$0")" && pwd) || exit 1
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    */*) printf '%s/%s\n' "$PWD" "$1" ;;
    *) printf '%s\n' "$1" ;;
    esac
}
raygl=$(absolute "$raygl") preload=$(absolute "$preload") prog=$(absolute "$prog")
r2p=$(absolute "$r2p") cmp=$(absolute "$cmp") povray=$(absolute "$povray")
case $case in dropin-*) din=$(absolute "${1:-}") ;; esac
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

# compare_figures NAME LOG: with RAYGL_FIGURES set (meson sets it to
# tests/image/figures.txt), the lowest within and silhouette of the frames
# raygl-compare measured in LOG held to the file's line for NAME.
compare_figures() {
    [ -n "${RAYGL_FIGURES:-}" ] || return 0
    set -- "$1" $(awk '/^frame [0-9]+: [0-9]+x[0-9]+ within / {
        t = $5; sub(/\/255$/, "", t); w = $6; sub(/,$/, "", w); w += 0; s = $11 + 0
        if (n++ == 0 || w < mw) mw = w
        if (n == 1 || s < ms) ms = s
    } END { if (n) printf "%s %.5f %.5f\n", t, mw, ms }' "$2")
    [ $# -eq 4 ] || fail "no figures in $2"
    "$here/../image/check-figures.sh" "$RAYGL_FIGURES" "$@" ||
        fail "the figures do not hold to $RAYGL_FIGURES (above)"
}
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
# The trace was closed: it ends with the END chunk (docs/format.md 2.7).
closed() { # TRACE
    [ "$(tail -c 28 "$1" | od -An -tx1 -N12 | tr -d ' \n')" = c35247430500000008000000 ] ||
        fail "$1 does not end with the END chunk (not closed)"
}
# The pid raygl record's line names (the program's), once it is printed.
program_pid() { # LOG
    i=0
    while [ $i -lt 300 ]; do
        p=$(sed -n 's/^raygl: recording .* (pid \([0-9]*\)) into .*/\1/p' "$1")
        [ -n "$p" ] && { echo "$p"; return 0; }
        sleep 0.1
        i=$((i + 1))
    done
    return 1
}
wait_for() { # FILE: until it exists (30 s at most)
    i=0
    while [ ! -e "$1" ] && [ $i -lt 300 ]; do
        sleep 0.1
        i=$((i + 1))
    done
    [ -e "$1" ]
}
# Until raygl passes signals on and the program records into TRACE:
# raygl's line (printed once its traps are set), then the trace. The trace
# alone is no sign: raygl record creates and removes it while checking its
# folder, before its traps, and a signal then ends raygl itself. LOG is a
# name no earlier run wrote: raygl started with & opens it when it gets
# there, and an old line in it would pass for the new one.
recording() { # LOG TRACE
    program_pid "$1" >/dev/null && wait_for "$2"
}
# Until TRACE, still being written, holds N frames (30 s at most).
has_frames() { # TRACE N
    i=0
    while [ "$(count "$1" '^frame ')" -lt "$2" ] && [ $i -lt 300 ]; do
        sleep 0.1
        i=$((i + 1))
    done
    [ "$(count "$1" '^frame ')" -ge "$2" ]
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
unrecorded)
    record -o t.raygl -- "$prog" --api glut --unrecorded >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    triangles t.raygl 3
    # Counted per frame, the lookup's function too; queries never.
    expect t.raygl '@NotRecorded(name="glIndexi", count=1)' 3
    expect t.raygl '@NotRecorded(name="glIndexMask", count=1)' 3
    # Bitmap text: freeglut's glBitmap calls are recorded as the
    # program's (three characters a frame), the GLUT calls not counted.
    expect t.raygl 'glBitmap(width=8, height=1[34],' 9
    expect t.raygl 'glutBitmap' 0
    # Stroke text: its line strips recorded, the GLUT calls not counted
    # (they were, though their drawing is in the trace).
    record -o st.raygl -- "$prog" --api glut --stroke --frames 1 >prog.log 2>&1 ||
        { cat prog.log; fail "the program failed (stroke text)"; }
    [ "$(count st.raygl 'glBegin(mode=GL_LINE_STRIP)')" -ge 6 ] || fail "stroke text: no line strips recorded"
    expect st.raygl 'glutStroke' 0
    expect t.raygl '@NotRecorded(name="glSampleCoverage", count=1)' 3
    expect t.raygl '@NotRecorded(name="glutInit", count=1)' 1
    expect t.raygl 'glGetError\|glGetIntegerv\|glIsEnabled' 0
    translate t.raygl 3
    log=t-pov.log
    # ... drawn as one image in front of the scene, in every frame.
    [ "$(ls t-pov/textures | grep -c '^rgl-tex-.*\.png$')" -ge 1 ] || fail "no image of the bitmap text written"
    [ "$(grep -l 'no_shadow no_reflection no_radiosity' t-pov/frame-*.pov | wc -l)" -eq 3 ] ||
        fail "the bitmap text is not in every scene"
    # None of them can change these frames: colour-index state, the blend
    # colour with no draw blending by it, the window system. --verbose says
    # each once, marked.
    grep -q 'not recorded' "$log" && { cat "$log"; fail "raygl2pov reports calls that cannot change the picture"; }
    "$r2p" t.raygl -o t-pov -v >v.log 2>&1 || { cat v.log; fail "raygl2pov -v failed"; }
    for want in "glIndexi: 3 calls not recorded, from frame 0" \
        "glSampleCoverage: 3 calls not recorded, from frame 0" \
        "glutInit: 1 call not recorded, from frame 0"; do
        grep -q "t.raygl: $want (cannot change the picture: " v.log || { cat v.log; fail "raygl2pov -v does not say '$want'"; }
    done
    [ "$(grep -c 'glIndexi:' v.log)" -eq 1 ] || fail "glIndexi reported more than once"
    # With snapshots: the counts come before @Snapshot, each frame's last
    # command; the recorder's own glReadBuffer and glPixelTransfer calls
    # are not the program's.
    record --snapshots -o s.raygl -- "$prog" --api glx --unrecorded >prog.log 2>&1 ||
        { cat prog.log; fail "the program failed (snapshots)"; }
    triangles s.raygl 3
    expect s.raygl '@Snapshot(' 3
    expect s.raygl '@NotRecorded(name="glIndexi", count=1)' 3
    expect s.raygl 'glReadBuffer\|glPixelTransfer' 0
    dump s.raygl | awk '/^frame / { if (n++ && last !~ /@Snapshot/) bad = 1 }
        /^  [0-9]/ { last = $0 } END { exit bad || last !~ /@Snapshot/ }' ||
        fail "@Snapshot is not each frame's last command"
    ;;
quiet)
    record -o q.raygl -- "$prog" --api glut --stroke >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    expect q.raygl '^frame ' 3
    expect q.raygl 'glBegin(mode=GL_TRIANGLES)' 3
    # freeglut's strokes are the program's calls (glutStrokeString is let
    # through uninterposed, uncounted); the window system's calls counted.
    [ "$(count q.raygl 'glBegin(mode=GL_LINE_STRIP)')" -ge 15 ] || fail "the stroke text is not recorded"
    expect q.raygl '@NotRecorded(name="glutStroke' 0
    expect q.raygl '@NotRecorded(name="glutInit", count=1)' 1
    "$r2p" q.raygl -o q-pov >q.log 2>&1 || { cat q.log; fail "raygl2pov failed"; }
    [ ! -s q.log ] || { cat q.log; fail "raygl2pov printed messages for a frame where nothing can differ from what it says"; }
    "$r2p" q.raygl -o q-pov -v >v.log 2>&1 || { cat v.log; fail "raygl2pov -v failed"; }
    grep -q "q.raygl: glutInit: 1 call not recorded, from frame 0 (cannot change the picture: " v.log ||
        { cat v.log; fail "raygl2pov -v does not list glutInit"; }
    # The frame itself (the text aside: its lines are the lines' own
    # approximation) through raygl compare, with the unlit floors: exact,
    # and raygl2pov says nothing of it.
    if [ -x "$povray" ] || command -v "$povray" >/dev/null 2>&1; then
        record --snapshots -o e.raygl -- "$prog" --api glut >prog.log 2>&1 || { cat prog.log; fail "the program failed (snapshots)"; }
        "$r2p" e.raygl -o e-pov >e.log 2>&1 || { cat e.log; fail "raygl2pov failed (snapshots)"; }
        [ ! -s e.log ] || { cat e.log; fail "raygl2pov printed messages for an exact frame"; }
        sh "$raygl" compare e.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" --tol 2 --min-match 0.99 \
            --min-silhouette 0.99 >cmp.log 2>&1
        rc=$?
        cat cmp.log
        [ $rc -eq 0 ] || fail "raygl compare: the frames are not exact (exit $rc)"
    fi
    ;;
nurbs)
    record -o t.raygl -- "$prog" --api glx --nurbs >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    expect t.raygl '^frame ' 3
    expect t.raygl 'gluNurbsSurface(nurb=#' 3
    expect t.raygl 'gluEndSurface(nurb=#' 3
    # GLU's own drawing stays out: the guard around the GLU calls.
    expect t.raygl 'glMap2f(\|glEvalMesh2(\|glEvalCoord2f(\|glBegin(\|glVertex' 0
    translate t.raygl 3
    for f in t-pov/frame-*.pov; do
        grep -q '^mesh2{' "$f" || fail "$f: the surface drew nothing"
    done
    ;;
nurbs-tess)
    record -o t.raygl -- "$prog" --api glx --nurbs-tess >prog.log 2>&1 || { cat prog.log; fail "the program failed"; }
    expect t.raygl '^frame ' 3
    expect t.raygl 'gluNurbsSurface(nurb=#' 3
    # The callbacks draw: their calls are the program's, recorded.
    [ "$(count t.raygl 'glVertex3fv(')" -ge 12 ] || fail "the callbacks' vertices are not recorded"
    expect t.raygl 'glMap2f(\|glEvalMesh2(' 0
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
    ppid=$(program_pid prog.log) || { kill $pid; fail "raygl printed no pid"; }
    wait_for hung || { kill $pid; fail "the program never reached its last frame"; }
    kill -9 "$ppid"
    wait $pid
    [ $? -eq 137 ] || fail "raygl record did not exit with the program's 128+9"
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
    # One signal while the program draws frames 20 ms apart: exactly the
    # next frame is kept, not those after it.
    (exec env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o sig.raygl --signal USR1 -- "$prog" \
        --api glx --frames 1000 --delay-ms 20 --until enough >sig.log 2>&1) &
    pid=$!
    # The handler is set before the first frame, which creates the trace;
    # the signal goes to raygl, which passes it on.
    recording sig.log sig.raygl || { kill $pid; cat sig.log; fail "no trace under --signal"; }
    kill -USR1 $pid
    # Told to end once the kept frame is in the trace, the program draws
    # one more: a frame after it, however slow this machine.
    has_frames sig.raygl 1 || { : >enough; wait $pid; cat sig.log; fail "no frame kept after the signal"; }
    : >enough
    wait $pid
    rc=$?
    [ $rc -eq 0 ] || { cat sig.log; fail "the program failed under --signal: exit $rc"; }
    triangles sig.raygl 1
    translate sig.raygl 1
    ;;
usage)
    sh "$raygl" --help >help.log 2>&1 || fail "--help failed"
    grep -q '^usage: raygl record' help.log || fail "--help prints no usage"
    # code N CMD...: CMD exits with N; what it printed is in err.log.
    code() {
        want=$1
        shift
        "$@" >err.log 2>&1
        got=$?
        [ "$got" -eq "$want" ] || { cat err.log; fail "$*: exit $got, expected $want"; }
    }
    line() { [ "$(wc -l <err.log)" -eq 1 ] && grep -q "^raygl: $1" err.log || { cat err.log; fail "message for $2"; }; }
    code 2 sh "$raygl"
    code 2 sh "$raygl" frobnicate && line 'unknown command frobnicate' verb
    code 2 sh "$raygl" record && line 'record: no program' 'no program'
    code 2 sh "$raygl" record --bogus -- true && line 'record: unknown option --bogus' option
    code 2 sh "$raygl" record --frames 3-1 -- true && line 'record: --frames 3-1' range
    code 2 sh "$raygl" record --frames x -- true && line 'record: --frames x' 'bad range'
    code 2 sh "$raygl" record --every 0 -- true && line 'record: --every 0' every
    code 2 sh "$raygl" record --signal NOPE -- true && line 'record: --signal NOPE' signal
    code 2 sh "$raygl" record --signal KILL -- true && line 'record: --signal KILL' sigkill
    code 2 sh "$raygl" record -o && line 'record: -o needs' '-o'
    # Not found 127, not executable 126, as env, timeout and xargs say.
    code 127 sh "$raygl" record -- /nonexistent/prog && line 'record: /nonexistent/prog: program not found' missing
    code 127 sh "$raygl" record -- no-such-program-anywhere && line 'record: no-such-program-anywhere: program not found' 'missing on PATH'
    printf '#!/bin/sh\n' >noexec && chmod 644 noexec
    code 126 sh "$raygl" record -- ./noexec && line 'record: ./noexec: not executable' 'not executable'
    mkdir -p pathdir && cp noexec pathdir/noexec-on-path
    code 126 env PATH="$PWD/pathdir:$PATH" sh "$raygl" record -- noexec-on-path &&
        line "record: $PWD/pathdir/noexec-on-path: not executable" 'not executable on PATH'
    code 126 sh "$raygl" record -- /tmp && line 'record: /tmp: is a folder' 'a folder as program'
    for want in 127 126; do # what env says of the same
        case $want in 127) p=/nonexistent/prog ;; 126) p=./noexec ;; esac
        env "$p" >/dev/null 2>&1
        [ $? -eq $want ] || fail "env $p does not exit $want here: the test's premise"
    done
    mkdir d
    code 1 sh "$raygl" record -o d -- true && line 'record: d is a folder' folder
    code 1 env RAYGL_PRELOAD_LIB=/nonexistent.so sh "$raygl" record -- true &&
        line 'record: /nonexistent.so: the preload library is missing' preload
    # -V and --version print what raygl-compare's do: NAME VERSION.
    v=$("$cmp" -V) && [ -n "$v" ] || fail "raygl-compare -V"
    for o in -V --version; do
        code 0 sh "$raygl" $o
        [ "$(cat err.log)" = "raygl ${v#raygl-compare }" ] ||
            fail "raygl $o printed '$(cat err.log)', expected 'raygl ${v#raygl-compare }'"
    done
    # A trace that cannot be written is refused before the program runs.
    code 1 sh "$raygl" record -o missing/x.raygl -- sh -c ': >ran' &&
        line 'record: missing/x.raygl: folder missing does not exist$' 'missing folder'
    [ ! -e ran ] || fail "the program ran although its trace had no folder"
    mkdir ro && chmod 555 ro
    if ! (: >ro/probe) 2>/dev/null; then # root writes there anyway
        code 1 sh "$raygl" record -o ro/x.raygl -- sh -c ': >ran' &&
            line 'record: ro/x.raygl: cannot be written in ro' 'read-only folder'
        [ ! -e ran ] || fail "the program ran although its trace could not be written"
    fi
    mkfifo fifo
    code 1 sh "$raygl" record -o fifo -- sh -c ': >ran' && line 'record: fifo: not a regular file$' fifo
    [ -p fifo ] && [ ! -e ran ] || fail "a fifo given as -o was removed, or the program ran"
    # --exit needs a last frame.
    for sel in '' '--every 2' '--frames 3-'; do
        code 2 sh "$raygl" record $sel --exit -- true && line 'record: --exit needs a last frame' "--exit $sel"
    done
    code 0 env ${san:+LD_PRELOAD=$san} sh "$raygl" record -q --frames 2 --exit -o none.raygl -- true
    code 0 env ${san:+LD_PRELOAD=$san} sh "$raygl" record -q --signal USR1 --exit -o none.raygl -- true
    # The program's own exit status comes back; a program that draws
    # nothing leaves no trace.
    code 3 env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o none.raygl -- sh -c 'exit 3'
    [ ! -e none.raygl ] || fail "a program that drew nothing left a trace"
    line "recording sh (pid [0-9]*) into $out/none.raygl\$" 'the trace named'
    code 0 env ${san:+LD_PRELOAD=$san} sh "$raygl" record --signal SIGUSR2 -o none.raygl -- true &&
        line "recording true (pid \([0-9]*\)) into $out/none.raygl (kill -USR2 \1 records the next frame)\$" 'signal line'
    code 0 env ${san:+LD_PRELOAD=$san} sh "$raygl" record -q -o none.raygl -- true
    [ ! -s err.log ] || fail "-q printed $(cat err.log)"
    ;;
buildtree)
    # build/record/raygl as it is (no sh, no RAYGL_PRELOAD_LIB or
    # RAYGL_COMPARE) from another folder: the library and raygl-compare are
    # found beside it in the build tree; through a link on PATH as well.
    [ -x "$raygl" ] || fail "$raygl is not executable"
    mkdir elsewhere bin && cd elsewhere || exit 1
    ln -s "$raygl" ../bin/raygl
    unset RAYGL_PRELOAD_LIB RAYGL_COMPARE LD_LIBRARY_PATH # as a user's shell has them
    env ${san:+LD_PRELOAD=$san} "$raygl" record -o t.raygl -- "$prog" --api glx >prog.log 2>&1 ||
        { cat prog.log; fail "raygl record from another folder failed"; }
    triangles t.raygl 3
    [ "$("$raygl" compare -V)" = "$("$cmp" -V)" ] || fail "raygl compare did not run $cmp"
    env ${san:+LD_PRELOAD=$san} PATH="$out/bin:$PATH" raygl record -o l.raygl -- "$prog" --api glx >prog.log 2>&1 ||
        { cat prog.log; fail "raygl record through a link on PATH failed"; }
    triangles l.raygl 3
    ;;
installed)
    # The installed raygl finds the library and raygl-compare from its own
    # place: a prefix laid out as meson installs it (the library in
    # LIBDIR/raygl/), then moved.
    bindir=$1 libdir=$2 inst=$(absolute "$3")
    case $bindir$libdir in /*) skip "bindir or libdir outside the prefix: not relocatable" ;; esac
    mkdir -p "p/$bindir" "p/$libdir/raygl" elsewhere || exit 1
    cp "$inst" "p/$bindir/raygl" && cp "$cmp" "p/$bindir/raygl-compare" && cp "$preload" "p/$libdir/raygl/" || exit 1
    mv p moved && cd elsewhere || exit 1
    unset RAYGL_PRELOAD_LIB RAYGL_COMPARE LD_LIBRARY_PATH # as a user's shell has them
    env ${san:+LD_PRELOAD=$san} "$out/moved/$bindir/raygl" record -o t.raygl -- "$prog" --api glx >prog.log 2>&1 ||
        { cat prog.log; fail "the moved raygl record failed"; }
    triangles t.raygl 3
    [ "$("$out/moved/$bindir/raygl" compare -V)" = "$("$cmp" -V)" ] || fail "the moved raygl compare failed"
    ;;
exit)
    # A program that would draw 1000 frames (--done: it drew them all) is
    # ended after the last kept one; raygl exits 0 with the trace closed.
    long="--frames 1000 --delay-ms 10 --done finished"
    record -o e.raygl --frames 0-2 --exit -- "$prog" --api glx $long >prog.log 2>&1 ||
        { cat prog.log; fail "--frames 0-2 --exit: exit $?"; }
    [ ! -e finished ] || fail "--exit did not end the program"
    triangles e.raygl 3
    closed e.raygl
    translate e.raygl 3
    # With --every the end comes after the last step (frames 0, 3, 6 of 0-7).
    record -o every.raygl --frames 0-7 --every 3 --exit -- "$prog" --api glx $long >prog.log 2>&1 ||
        { cat prog.log; fail "--every --exit: exit $?"; }
    triangles every.raygl 3
    closed every.raygl
    # GLUT's frame end (glutSwapBuffers), one frame.
    record -o glut.raygl --frames 1 --exit -- "$prog" --api glut $long >prog.log 2>&1 ||
        { cat prog.log; fail "GLUT --exit: exit $?"; }
    triangles glut.raygl 1
    closed glut.raygl
    # A program that ignores SIGTERM gets SIGKILL after the grace period:
    # still 0, the trace still whole.
    record -o stubborn.raygl --frames 1 --exit -- "$prog" --api glx --ignore-term $long >prog.log 2>&1 ||
        { cat prog.log; fail "--exit on a program ignoring SIGTERM: exit $?"; }
    triangles stubborn.raygl 1
    closed stubborn.raygl
    [ ! -e finished ] || fail "the program ignoring SIGTERM was not killed"
    # --signal --exit: the frame after the signal, then the end.
    (exec env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o sig.raygl --signal USR1 --exit -- "$prog" \
        --api glx $long >sig.log 2>&1) &
    pid=$!
    recording sig.log sig.raygl || { kill $pid; cat sig.log; fail "no trace under --signal --exit"; }
    kill -USR1 $pid
    wait $pid
    rc=$?
    [ $rc -eq 0 ] || { cat sig.log; fail "--signal --exit: exit $rc"; }
    triangles sig.raygl 1
    closed sig.raygl
    [ ! -e finished ] || fail "--signal --exit did not end the program"
    # A program that ends before the last frame: its own status.
    code=0
    record -o short.raygl --frames 0-9 --exit -- sh -c '"$0" --api glx --frames 3; exit 4' "$prog" >prog.log 2>&1 ||
        code=$?
    [ $code -eq 4 ] || { cat prog.log; fail "a program ending before the last frame: exit $code, expected 4"; }
    triangles short.raygl 3
    closed short.raygl
    ;;
exit-glxgears)
    command -v glxgears >/dev/null 2>&1 || skip "glxgears not installed (mesa-utils)"
    # The README's command, from the build tree as it is: glxgears runs
    # until stopped, --exit stops it (timeout only guards the test).
    unset RAYGL_PRELOAD_LIB RAYGL_COMPARE LD_LIBRARY_PATH # as a user's shell has them
    env ${san:+LD_PRELOAD=$san} timeout 60 "$raygl" record --frames 0-2 --exit -- glxgears >prog.log 2>&1
    rc=$?
    [ $rc -eq 0 ] || { cat prog.log; fail "raygl record exited with $rc (124: glxgears still running after 60 s)"; }
    expect glxgears.raygl '^frame ' 3
    closed glxgears.raygl
    ;;
status)
    # The trace cannot be created at the first drawing (its folder went
    # away after raygl's check): 74, whatever the program's own status.
    mkdir gone
    record -o gone/t.raygl -- sh -c 'rmdir gone && "$0" --api glx' "$prog" >prog.log 2>&1
    rc=$?
    [ $rc -eq 74 ] || { cat prog.log; fail "a trace that could not be created: exit $rc, expected 74"; }
    grep -q '^raygl: recording stopped: .*gone/t.raygl: No such file or directory$' prog.log ||
        { cat prog.log; fail "no line naming the trace and the reason"; }
    # Recording stops (the recorder's third allocation fails): 74 too.
    env ${san:+LD_PRELOAD=$san} RAYGL_TEST_FAIL_ALLOC=3 sh "$raygl" record -o alloc.raygl -- \
        sh -c '"$0" --api glx --frames 5; exit 3' "$prog" >prog.log 2>&1
    rc=$?
    [ $rc -eq 74 ] || { cat prog.log; fail "recording stopped early: exit $rc, expected 74"; }
    grep -q '^raygl: recording stopped: allocation failed' prog.log || { cat prog.log; fail "no failure line"; }
    # Otherwise the program's status, a signal's 128+N included.
    record -o ok.raygl -- sh -c '"$0" --api glx; exit 5' "$prog" >prog.log 2>&1
    rc=$?
    [ $rc -eq 5 ] || { cat prog.log; fail "the program's status 5 came back as $rc"; }
    triangles ok.raygl 3
    closed ok.raygl
    record -o term.raygl -- sh -c '"$0" --api glx && kill -TERM $$' "$prog" >prog.log 2>&1
    rc=$?
    [ $rc -eq 143 ] || { cat prog.log; fail "a program killed by SIGTERM came back as $rc"; }
    grep -q '^Terminated' prog.log || { cat prog.log; fail "the signal was not named"; }
    ;;
signals)
    # raygl waits for the program: TERM sent to raygl reaches it.
    long="--frames 1000 --delay-ms 10 --done finished"
    (exec env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o term.raygl -- "$prog" --api glx $long >term.log 2>&1) &
    pid=$!
    ppid=$(program_pid term.log) || { kill $pid; fail "raygl printed no pid"; }
    wait_for term.raygl || { kill $pid; fail "no trace"; }
    kill -TERM $pid
    wait $pid
    rc=$?
    [ $rc -eq 143 ] || { cat term.log; fail "raygl exited with $rc after TERM, expected 143"; }
    ! kill -0 "$ppid" 2>/dev/null || { kill -9 "$ppid"; fail "the program outlived raygl"; }
    [ ! -e finished ] || fail "the program ran to its end"
    # Started in the background here, so sh ignores SIGINT for it; raygl
    # gives the program SIGINT's default action back (as a Ctrl-C finds it
    # without raygl).
    (exec env ${san:+LD_PRELOAD=$san} sh "$raygl" record -o int.raygl -- "$prog" --api glx $long >int.log 2>&1) &
    pid=$!
    ppid=$(program_pid int.log) || { kill $pid; fail "raygl printed no pid"; }
    wait_for int.raygl || { kill $pid; fail "no trace"; }
    kill -INT "$ppid"
    wait $pid
    rc=$?
    [ $rc -eq 130 ] || { kill -9 "$ppid"; cat int.log; fail "raygl exited with $rc after the program's SIGINT, expected 130"; }
    # stdin reaches the program.
    echo hello | record -q -o none.raygl -- sh -c 'read -r x && echo "$x" >got' >stdin.log 2>&1 ||
        { cat stdin.log; fail "the program reading stdin failed"; }
    [ "$(cat got)" = hello ] || fail "the program read '$(cat got)' from stdin, not hello"
    ;;
glxgears)
    command -v glxgears >/dev/null 2>&1 || skip "glxgears not installed (mesa-utils)"
    # glxgears runs until stopped: --exit stops it after frame 4 (timeout
    # only guards the test).
    record -o gears.raygl --frames 2-4 --exit --snapshots -- timeout 60 glxgears -geometry 300x300 >prog.log 2>&1 ||
        { cat prog.log; fail "raygl record exited with $?"; }
    expect gears.raygl '^frame ' 3
    closed gears.raygl
    expect gears.raygl 'glCallList(list=1)' 3
    # Through `raygl compare` (raygl-compare, from RAYGL_COMPARE).
    sh "$raygl" compare gears.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" "$@" -- --no-shadows >cmp.log 2>&1
    rc=$?
    cat cmp.log
    [ $rc -eq 0 ] || fail "raygl-compare exited with $rc"
    [ "$(grep -c '^frame [0-9]*: 300x300 within' cmp.log)" -eq 3 ] || fail "not 3 frames compared"
    compare_figures capture-glxgears cmp.log
    ;;
hack)
    name=$1
    shift
    hack=/usr/libexec/xscreensaver/$name
    [ -x "$hack" ] || skip "$hack not installed (xscreensaver-gl)"
    record -o hack.raygl --frames 10-12 --exit --snapshots -- timeout 60 "$hack" -window -geometry 320x240 >prog.log 2>&1 ||
        { cat prog.log; fail "raygl record exited with $?"; }
    expect hack.raygl '^frame ' 3
    closed hack.raygl
    expect hack.raygl '@Snapshot(x=0, y=0, width=320, height=240' 3
    "$cmp" hack.raygl -o cmp --raygl2pov "$r2p" --povray "$povray" "$@" -- --no-shadows >cmp.log 2>&1
    rc=$?
    cat cmp.log
    [ $rc -eq 0 ] || fail "raygl-compare exited with $rc"
    compare_figures "capture-hack-$name" cmp.log
    ;;
frames)
    # Each LIST: raygl record and raygl2pov --frames both take it or both
    # refuse it (exit 2) ...
    "$prog" --api glx --frames 1 >/dev/null 2>&1
    record -q -o all.raygl -- "$prog" --api glx --frames 12 >prog.log 2>&1 || { cat prog.log; fail "full run"; }
    for l in 3 0-2 5- 1,4 1,4, 0-11:3 2-:4 1,3-5,9- 0-3:2,8 007 3-3 \
        '' , ,3 3,,4 x 3-1 1-5:0 1: :2 1-2-3 -3 3:2:1 '1 2' 1.5 +3 3- -- 1-x 99999999999999999999; do
        sh "$raygl" record -q --frames "$l" -o none.raygl -- true >rec.log 2>&1
        a=$?
        "$r2p" all.raygl --dump --frames "$l" >r2p.log 2>&1
        b=$?
        [ $a -eq 2 ] || a=0
        [ $b -eq 2 ] || b=0
        [ $a -eq $b ] || { cat rec.log r2p.log; fail "--frames '$l': raygl record says $a, raygl2pov $b"; }
    done
    # ... and the frames kept are those raygl2pov selects (frame k's first
    # vertex is at x = -0.8 + 0.1 k); --every N is :N on each item.
    xs() { "$r2p" "$@" --dump | sed -n 's/.*glVertex2f(x=\(-*[0-9.e-]*\), y=-0.8).*/\1/p' | tr '\n' ' '; }
    for sel in '1,4' '0-11:3' '2-:4' '1,3-5,9-' '0-3:2,8' '0-5 --every 2' '1,6-9 --every 3' '--every 5'; do
        case $sel in
        --every*) l='' e=${sel#--every } ;;
        *' --every '*) l=${sel%% *} e=${sel##* } ;;
        *) l=$sel e='' ;;
        esac
        set -- ${l:+--frames "$l"} ${e:+--every "$e"}
        record -q -o sel.raygl "$@" -- "$prog" --api glx --frames 12 >prog.log 2>&1 || { cat prog.log; fail "--frames $sel"; }
        if [ -n "$e" ]; then
            want=$(xs all.raygl --frames "$(echo "${l:-0-}" | sed "s/\(,\|\$\)/:$e\1/g; s/:$e:$e/:$e/g")")
        else
            want=$(xs all.raygl --frames "$l")
        fi
        got=$(xs sel.raygl)
        [ -n "$want" ] && [ "$got" = "$want" ] || fail "--frames $sel kept x = $got, raygl2pov selects $want"
    done
    # --exit ends after the last frame of the list.
    record -q -o e.raygl --frames 1,3-4 --exit -- "$prog" --api glx --frames 1000 --delay-ms 10 --done finished \
        >prog.log 2>&1 || { cat prog.log; fail "--frames 1,3-4 --exit"; }
    [ ! -e finished ] || fail "--frames 1,3-4 --exit did not end the program"
    triangles e.raygl 3
    closed e.raygl
    sh "$raygl" record --frames 1,3- --exit -- true >rec.log 2>&1
    [ $? -eq 2 ] && grep -q 'record: --exit needs a last frame' rec.log || { cat rec.log; fail "--frames 1,3- --exit"; }
    ;;
dropin-text | dropin-record | dropin-exit)
    [ -x "$din" ] || fail "no drop-in build $din"
    # The drop-in build's frames, recorded by the libraygl it links.
    linked() { env ${san:+LD_PRELOAD=$san} RAYGL_TRACE="$@"; }
    case $case in
    dropin-text)
        # The same program with bitmap and stroke text, recorded through
        # the preload and through the drop-in header: the same commands
        # (their calls not recorded aside; the preload also sees the
        # glViewport of freeglut's default reshape).
        args='--api glut --unrecorded --stroke'
        record -q -o pre.raygl -- "$prog" $args >prog.log 2>&1 || { cat prog.log; fail "the program (preload)"; }
        linked din.raygl "$din" $args >prog.log 2>&1 || { cat prog.log; fail "the drop-in build"; }
        for t in pre din; do
            dump $t.raygl | sed -n 's/^  [0-9][0-9]* @0x[0-9a-f]* //p' |
                grep -v '^@NotRecorded\|^glViewport' >$t.cmds
        done
        expect din.raygl 'glBitmap(width=8, height=1[34],' 9
        [ "$(count din.raygl 'glBegin(mode=GL_LINE_STRIP)')" -ge 18 ] || fail "drop-in: no stroke text"
        cmp -s pre.cmds din.cmds || { diff pre.cmds din.cmds | head -20; fail "the drop-in build records other commands"; }
        expect din.raygl 'glutBitmap\|glutStroke' 0
        translate din.raygl 3
        [ "$(ls din-pov/textures | grep -c '^rgl-tex-.*\.png$')" -ge 1 ] || fail "no image of the bitmap text written"
        ;;
    dropin-record)
        # One recorder: the named trace, every frame, closed; no second
        # trace beside it.
        record -o t.raygl -- "$din" --api glut --frames 5 >prog.log 2>&1 || { cat prog.log; fail "raygl record of the drop-in build"; }
        triangles t.raygl 5
        closed t.raygl
        [ "$(ls | grep -c '\.raygl$')" -eq 1 ] || fail "more than one trace: $(ls | grep '\.raygl$' | tr '\n' ' ')"
        # --exit ends it after the last kept frame, the trace whole.
        record -o e.raygl --frames 1-3 --exit -- "$din" --api glut --frames 1000 --done finished >prog.log 2>&1 ||
            { cat prog.log; fail "--frames 1-3 --exit: exit $?"; }
        [ ! -e finished ] || fail "--exit did not end the drop-in build"
        triangles e.raygl 3
        closed e.raygl
        [ "$(ls | grep -c '\.raygl$')" -eq 2 ] || fail "more traces than named: $(ls | grep '\.raygl$' | tr '\n' ' ')"
        # A trace that cannot be written: 74, from the linked recorder.
        mkdir gone
        record -o gone/t.raygl -- sh -c 'rmdir gone && "$0" --api glut' "$din" >prog.log 2>&1
        rc=$?
        [ $rc -eq 74 ] || { cat prog.log; fail "a trace the drop-in build could not create: exit $rc, expected 74"; }
        ;;
    dropin-exit)
        # RAYGL_EXIT without raygl record: the trace closed after frame 2,
        # then SIGTERM (143), the program stopped early.
        linked x.raygl RAYGL_FRAMES=1-2 RAYGL_EXIT=1 "$din" --api glut --frames 1000 --done finished >prog.log 2>&1
        rc=$?
        [ $rc -eq 143 ] || { cat prog.log; fail "RAYGL_EXIT: exit $rc, expected 143 (SIGTERM)"; }
        [ ! -e finished ] || fail "RAYGL_EXIT did not end the program"
        triangles x.raygl 2
        closed x.raygl
        # A list and RAYGL_EVERY, as raygl record passes them.
        linked l.raygl RAYGL_FRAMES=0,4-9 RAYGL_EVERY=2 "$din" --api glut --frames 10 >prog.log 2>&1 ||
            { cat prog.log; fail "RAYGL_FRAMES=0,4-9 RAYGL_EVERY=2"; }
        triangles l.raygl 4
        # RAYGL_SIGNAL: the frame after the signal.
        (exec env ${san:+LD_PRELOAD=$san} RAYGL_TRACE=s.raygl RAYGL_SIGNAL=10 "$din" --api glut --frames 100 \
            --delay-ms 20 >prog.log 2>&1) &
        pid=$!
        wait_for s.raygl || { kill $pid; fail "no trace under RAYGL_SIGNAL"; }
        kill -USR1 $pid
        wait $pid || fail "the program failed under RAYGL_SIGNAL"
        triangles s.raygl 1
        ;;
    esac
    ;;
*) echo "unknown case $case" >&2; exit 2 ;;
esac
echo "capture test $case: PASS"
