#!/bin/sh
# e2e.sh: the end-to-end table (issue 16): from a GL program to a PNG, for
# several triangle counts, each step's time, peak memory and bytes.
#
#   bench/e2e.sh [--build DIR] [--sizes 10k,250k,1M] [--runs 3] [--size 640x480]
#                [--large-size 320x240] [--large-from 1M]
#                [--quality 9] [--povray-args ARGS] [--no-context] [--keep DIR]
#                [--out FILE] [--plain PATH] [--rec PATH] [--raygl2pov PATH]
#                [--povray PATH] [--runstat PATH]
#
# The program is bench/e2e_torus.c: one lit torus with a colour per vertex,
# drawn as GL_TRIANGLE_STRIP rings of glColor3f/glNormal3f/glVertex3f into
# an OSMesa context (--size, default 640x480; --no-context: none, so GL's
# calls cost nothing and the recorder's own cost stands out). Per size and
# per run, in this order:
#
#   1. the program alone (e2e_torus_plain) and recorded (e2e_torus_rec, the
#      same source built with the drop-in header raygl/gl.h): wall time,
#      CPU time (user + system) and peak RSS of each; recording's cost is
#      the recorded run less the plain run of the same round (the two run
#      back to back, so a busy machine hurts both alike)
#   2. raygl2pov -j 1 on the trace: wall, CPU, peak RSS; bytes of the trace
#      and of everything raygl2pov wrote (.pov, .ini, texture PNGs)
#   3. POV-Ray on frame-00000.ini at --size, +Q<quality>, no antialiasing,
#      no display: its own Parse Time and Trace Time (wall seconds) and the
#      CPU seconds it prints under each, the process's wall, CPU and peak
#      RSS. From --large-from triangles on (default 1M) POV-Ray renders at
#      --large-size instead (default 320x240, a quarter of the pixels;
#      --large-size 640x480 for one size throughout), so that three runs
#      of 1M stay within minutes: its render time grows with the number of
#      meshes the SDL holds (bench/README.md)
#
# Times and memory come from bench/e2e_runstat (wait4: microseconds, the
# child's peak RSS). Each figure is the median of --runs runs (recording's
# cost: the median of the per-round differences). Prints a Markdown table,
# one column per size, on stdout (and to --out FILE); progress on stderr.
# Figures only: never pass/fail (the bench-smoke test checks only that
# every cell holds a number).
#
# Binaries default to those of --build (default: build/ in the current
# folder); POV-Ray to povray on the PATH. --keep DIR keeps each size's
# last trace, scene, PNG and logs, and every run's figures, in DIR/<size>/.
# Exit 0, 1 when a step fails (naming it and its log), 2 on bad usage.
set -eu

me=e2e.sh
usage() {
    echo "$me: $1" >&2
    echo "usage: $me [--build DIR] [--sizes LIST] [--runs N] [--size WxH] [--large-size WxH] [--large-from N] [--quality Q] [--povray-args ARGS] [--no-context] [--keep DIR] [--out FILE] [--plain PATH] [--rec PATH] [--raygl2pov PATH] [--povray PATH] [--runstat PATH]" >&2
    exit 2
}
fail() {
    echo "$me: $1" >&2
    exit 1
}

build=build sizes=10k,250k,1M runs=3 size=640x480 large_size=320x240 large_from=1M quality=9
povargs='' nocontext='' keep='' out='' plain='' rec='' r2p='' povray='' runstat=''
while [ $# -gt 0 ]; do
    case $1 in
    --no-context) nocontext=--no-context; shift; continue ;;
    --build | --sizes | --runs | --size | --large-size | --large-from | --quality | --povray-args | --keep | --out | --plain | \
        --rec | --raygl2pov | --povray | --runstat)
        [ $# -ge 2 ] || usage "$1 needs a value" ;;
    -h | --help) usage "the end-to-end table" ;;
    *) usage "$1: unknown option" ;;
    esac
    case $1 in
    --build) build=$2 ;;
    --sizes) sizes=$2 ;;
    --runs) runs=$2 ;;
    --size) size=$2 ;;
    --large-size) large_size=$2 ;;
    --large-from) large_from=$2 ;;
    --quality) quality=$2 ;;
    --povray-args) povargs=$2 ;;
    --keep) keep=$2 ;;
    --out) out=$2 ;;
    --plain) plain=$2 ;;
    --rec) rec=$2 ;;
    --raygl2pov) r2p=$2 ;;
    --povray) povray=$2 ;;
    --runstat) runstat=$2 ;;
    esac
    shift 2
done

case $runs in '' | *[!0-9]*) usage "--runs: a whole number from 1" ;; esac
[ "$runs" -ge 1 ] || usage "--runs: a whole number from 1"
case $quality in [0-9] | 1[01]) ;; *) usage "--quality: 0 to 11 (POV-Ray's +Q)" ;; esac
# wxh OPTION VALUE: VALUE is WxH, two whole numbers, or usage
wxh() {
    case $2 in *x*) ;; *) usage "$1: WxH, not $2" ;; esac
    case ${2%%x*} in '' | *[!0-9]*) usage "$1: WxH, not $2" ;; esac
    case ${2#*x} in '' | *[!0-9]*) usage "$1: WxH, not $2" ;; esac
}
wxh --size "$size"
wxh --large-size "$large_size"
w=${size%x*} h=${size#*x}

# count S: 10k, 250k, 1M, 2000 -> a triangle count in $n, or usage
count() {
    case $1 in
    *[kK]) n=${1%?}; mul=1000 ;;
    *M) n=${1%?}; mul=1000000 ;;
    *) n=$1; mul=1 ;;
    esac
    case $n in '' | *[!0-9]*) usage "$2: $1 is not a count (like 2000, 10k or 1M)" ;; esac
    n=$((n * mul))
}
count "$large_from" --large-from
large_from=$n
tris_list='' labels=''
for s in $(echo "$sizes" | tr ',' ' '); do
    count "$s" --sizes
    [ "$n" -ge 8 ] || usage "--sizes: $s: 8 triangles at least"
    case " $tris_list " in *" $n "*) usage "--sizes: $s given twice" ;; esac
    tris_list="$tris_list $n"
    labels="$labels $s"
done
[ -n "$tris_list" ] || usage "--sizes: no size"

abs() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
[ -n "$plain" ] || plain=$build/bench/e2e_torus_plain
[ -n "$rec" ] || rec=$build/bench/e2e_torus_rec
[ -n "$r2p" ] || r2p=$build/translate/raygl2pov
[ -n "$runstat" ] || runstat=$build/bench/e2e_runstat
if [ -z "$povray" ]; then
    povray=$(command -v povray) || fail "povray not found on the PATH (--povray PATH)"
fi
for v in plain rec r2p runstat povray; do
    eval "p=\$$v"
    case $p in */*) p=$(abs "$p") ;; esac
    [ -x "$p" ] || command -v "$p" >/dev/null || fail "$p: not an executable (build it: ninja -C BUILD bench/e2e_torus_plain bench/e2e_torus_rec bench/e2e_runstat translate/raygl2pov)"
    eval "$v=\$p"
done
[ -z "$out" ] || out=$(abs "$out")
if [ -n "$keep" ]; then
    mkdir -p "$keep" || fail "$keep: cannot create"
    keep=$(cd "$keep" && pwd)
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-e2e.XXXXXX")
trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT TERM

# field NAME FILE: one figure of an e2e_runstat line
field() { sed -n "s/.*\\<$1=\\([-0-9.]*\\).*/\\1/p" "$2"; }
# median FORMAT < numbers, one a line
median() { sort -g | awk -v f="$1" '{ v[NR] = $1 } END { if (NR == 0) print "n/a"; else printf f "\n", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# cpu_of Parse|Trace: the CPU seconds POV-Ray prints on the line after
# that time (on a shared machine they say more than its wall seconds)
cpu_of() { awk -v t="$1 Time:" 'index($0, t) { getline; if (match($0, /with [0-9.]+ CPU/)) print substr($0, RSTART + 5, RLENGTH - 9); exit }' "$d/pov.log"; }
# failrun WHAT: a step of size $tris, run $r, failed; its files (logs,
# trace, scene) are kept, in --keep's folder or else in the work folder.
failrun() {
    if [ -n "$keep" ]; then
        rm -rf "${keep:?}/$tris"
        cp -r "$d" "$keep/$tris"
        where=$keep/$tris
    else
        trap - EXIT
        where=$d
    fi
    fail "$tris triangles, run $r: $1 (files in $where)"
}
# run STEP DIR STAT LOG COMMAND...: runs it in DIR, its figures to STAT
run() {
    step=$1 dir=$2 stat=$3 log=$4
    shift 4
    if ! (cd "$dir" && "$runstat" "$stat" "$@") >"$log" 2>&1; then
        tail -n 5 "$log" >&2
        failrun "$step failed (log: ${log##*/})"
    fi
}

for tris in $tris_list; do
    d=$work/$tris
    mkdir -p "$d"
    r=1
    while [ "$r" -le "$runs" ]; do
        echo "$me: $tris triangles, run $r of $runs" >&2
        rm -rf "$d/sdl" "$d/torus.raygl" "$d/frame.png"
        run "the plain program" "$d" "$d/plain.stat" "$d/plain.log" \
            "$plain" --tris "$tris" --size "$size" $nocontext
        run "the recorded program" "$d" "$d/rec.stat" "$d/rec.log" \
            env RAYGL_TRACE="$d/torus.raygl" "$rec" --tris "$tris" --size "$size" $nocontext
        cmp -s "$d/plain.log" "$d/rec.log" || failrun "the plain and recorded programs printed different lines (plain.log, rec.log)"
        [ -s "$d/torus.raygl" ] || failrun "the recorded program wrote no trace torus.raygl"
        run "raygl2pov" "$d" "$d/r2p.stat" "$d/r2p.log" \
            "$r2p" torus.raygl -o sdl -j 1 -q
        [ -s "$d/sdl/frame-00000.ini" ] || failrun "raygl2pov wrote no sdl/frame-00000.ini"
        sdl_bytes=$(find "$d/sdl" -type f -exec cat {} + | wc -c)
        sdl_files=$(find "$d/sdl" -type f | wc -l)
        pw=$w ph=$h
        if [ "$tris" -ge "$large_from" ]; then
            pw=${large_size%x*} ph=${large_size#*x}
        fi
        echo "$((pw * ph))" >"$d/pov.pixels"
        # The .ini names its paths from the folder raygl2pov ran in.
        # shellcheck disable=SC2086 # --povray-args is split on purpose
        run "POV-Ray" "$d" "$d/pov.stat" "$d/pov.log" \
            "$povray" sdl/frame-00000.ini +W"$pw" +H"$ph" +Q"$quality" -A -D +Oframe.png $povargs
        [ -s "$d/frame.png" ] || failrun "POV-Ray wrote no frame.png (log: pov.log)"
        parse=$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$d/pov.log" | head -n 1)
        trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$d/pov.log" | head -n 1)
        parse_cpu=$(cpu_of Parse)
        trace_cpu=$(cpu_of Trace)
        if [ -z "$parse" ] || [ -z "$trace" ] || [ -z "$parse_cpu" ] || [ -z "$trace_cpu" ]; then
            failrun "no Parse Time or Trace Time with CPU seconds in POV-Ray's statistics (pov.log)"
        fi

        for step in plain rec r2p pov; do
            for f in wall cpu maxrss_kb; do
                field $f "$d/$step.stat" >>"$d/$step.$f"
            done
        done
        for f in wall cpu maxrss_kb; do
            awk -v a="$(field $f "$d/rec.stat")" -v b="$(field $f "$d/plain.stat")" \
                'BEGIN { printf "%.6f\n", a - b }' >>"$d/cost.$f"
        done
        awk -v a="$(field wall "$d/rec.stat")" -v b="$(field wall "$d/r2p.stat")" -v c="$(field wall "$d/pov.stat")" \
            'BEGIN { printf "%.6f\n", a + b + c }' >>"$d/total.wall"
        echo "$parse" >>"$d/pov.parse"
        echo "$trace" >>"$d/pov.trace"
        echo "$parse_cpu" >>"$d/pov.parse_cpu"
        echo "$trace_cpu" >>"$d/pov.trace_cpu"
        wc -c <"$d/torus.raygl" >>"$d/trace.bytes"
        echo "$sdl_bytes" >>"$d/sdl.bytes"
        echo "$sdl_files" >"$d/sdl.files"
        sed -n 's/.* \([0-9]*\) GL calls.*/\1/p' "$d/plain.log" >"$d/calls"
        sed -n 's/.*: \([0-9]*\) triangles.*/\1/p' "$d/plain.log" >"$d/tris"
        r=$((r + 1))
    done
    if [ -n "$keep" ]; then
        rm -rf "${keep:?}/$tris"
        cp -r "$d" "$keep/$tris"
    fi
done

# The table: one row per figure, one column per size.
table=$work/table.md
{
    ctx="OSMesa ${w}x${h}"
    [ -z "$nocontext" ] || ctx="no GL context"
    large=
    for tris in $tris_list; do
        [ "$tris" -lt "$large_from" ] || large=" (${large_size} from $large_from triangles on)"
    done
    echo "Trace to PNG: bench/e2e_torus ($ctx), raygl2pov -j 1, POV-Ray at ${w}x${h}$large +Q$quality -A${povargs:+ $povargs}; medians of $runs run(s)."
    echo
    printf '| figure |'
    for s in $labels; do printf ' %s |' "$s"; done
    echo
    printf '|---|'
    for tris in $tris_list; do printf '%s' '---:|'; done
    echo
    # row LABEL COMMAND: COMMAND prints the cell of size dir $d
    row() {
        label=$1
        shift
        printf '| %s |' "$label"
        for tris in $tris_list; do
            d=$work/$tris
            printf ' %s |' "$("$@")"
        done
        echo
    }
    val() { cat "$d/$1"; }
    bytes() { median %.0f <"$d/$1"; }
    sec() { median %.3f <"$d/$1"; }
    mb() { awk '{ print $1 / 1024 }' "$d/$1" | median %.1f; }
    nscall() { awk -v c="$(cat "$d/calls")" '{ print $1 * 1e9 / c }' "$d/cost.cpu" | median %.1f; }
    row 'triangles drawn' val tris
    row 'GL calls' val calls
    row 'program alone: wall s' sec plain.wall
    row 'program alone: CPU s' sec plain.cpu
    row 'program alone: peak MB' mb plain.maxrss_kb
    row 'program recorded: wall s' sec rec.wall
    row 'program recorded: CPU s' sec rec.cpu
    row 'program recorded: peak MB' mb rec.maxrss_kb
    row 'recording cost: wall s' sec cost.wall
    row 'recording cost: CPU s' sec cost.cpu
    row 'recording cost: CPU ns per GL call (start-up included)' nscall
    row 'recording cost: peak MB' mb cost.maxrss_kb
    row 'trace bytes' bytes trace.bytes
    row 'raygl2pov -j 1: wall s' sec r2p.wall
    row 'raygl2pov -j 1: CPU s' sec r2p.cpu
    row 'raygl2pov -j 1: peak MB' mb r2p.maxrss_kb
    row 'SDL bytes (all files written)' bytes sdl.bytes
    row 'SDL files' val sdl.files
    row 'POV-Ray image pixels' val pov.pixels
    row 'POV-Ray parse s' sec pov.parse
    row 'POV-Ray parse CPU s' sec pov.parse_cpu
    row 'POV-Ray render s' sec pov.trace
    row 'POV-Ray render CPU s (all threads)' sec pov.trace_cpu
    row 'POV-Ray: wall s' sec pov.wall
    row 'POV-Ray: CPU s' sec pov.cpu
    row 'POV-Ray: peak MB' mb pov.maxrss_kb
    row 'trace to PNG: wall s (recorded run + raygl2pov + POV-Ray)' sec total.wall
} >"$table"
cat "$table"
[ -z "$out" ] || cp "$table" "$out" || fail "$out: cannot write"
