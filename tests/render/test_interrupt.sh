#!/bin/sh
# test_interrupt.sh: a stop signal leaves complete frames only.
#
#   test_interrupt.sh RAYGL2POV RAYGL_RENDER MKANIM IMGCMP
#
# SIGINT or SIGTERM, to the process or to its group (as Ctrl-C sends it),
# to raygl-render and to raygl2pov --render: afterwards the folder holds
# the scenes, their textures and the frames rendered before, and no
# partial PNG, no POV-Ray .pov-state, no temporary file, no povray left
# running. No race with POV-Ray's start-up: a stand-in povray writes what
# POV-Ray writes (its partial PNG and its .pov-state), says so, and blocks;
# the signal goes only once every started povray has said so. raygl2pov
# while translating: frozen with SIGSTOP at a moment its temporary scenes
# exist, then signalled. Then the real POV-Ray, signalled once its
# .pov-state exists. A stopped render says what is done and that the same
# command renders the rest, as its last line (issue 27); Blender's import
# script's own temporary image is removed too (a stand-in Blender).
. "$(dirname "$0")/common.sh"

cd "$work" || exit 1
"$mkanim" anim.raygl 4 80 60 || { echo "mkanim failed"; exit 1; }
mkdir marks

cat >stand-in-povray <<EOF2
#!/bin/sh
# Writes the partial files POV-Ray writes, marks its start, blocks.
for a; do case \$a in +O*) out=\${a#+O} ;; esac; done
printf 'partial' >"\$out"
printf 'state' >"\${out%.png}.pov-state"
: >"$work/marks/\$\$"
exec sleep 300
EOF2
chmod +x stand-in-povray

# wait_marks N: until N stand-ins have started (at most 60 s).
wait_marks() {
    i=0
    while [ "$(ls marks | wc -l)" -lt "$1" ]; do
        i=$((i + 1))
        [ $i -gt 600 ] && { fail "only $(ls marks | wc -l) of $1 povray started"; return 1; }
        sleep 0.1
    done
}

# check_clean DIR WHAT: only complete frames and their inputs in DIR.
check_clean() {
    left=$(ls -A "$1" | grep -v -E '^(frame-[0-9]+\.(pov|ini|png|glb)|render\.list|textures|raygl-folder\.inc)$')
    [ -z "$left" ] && ok "$2: nothing partial left" || fail "$2: left $(echo $left)"
    for p in "$1"/*.png; do
        [ -e "$p" ] || continue
        "$imgcmp" --tol 255 "$p" "$p" >/dev/null 2>&1 || fail "$2: $p is damaged"
    done
    for m in marks/*; do
        [ -e "$m" ] || continue
        kill -0 "$(basename "$m")" 2>/dev/null && fail "$2: povray $(basename "$m") still runs"
    done
}

# stop SIG TARGET DIR WHAT BEFORE COMMAND...: runs COMMAND (4 frames, -j 2,
# BEFORE of them rendered already) in a group of its own, waits for 2
# stand-ins, sends SIG to the process (TARGET=proc) or its group
# (TARGET=group), and checks DIR and the last line's counts: the 2 renders
# under way when the signal came are the ones stopped, whether the stop or
# the signal itself ended them, and none starts after it.
stop() {
    sig=$1 target=$2 dir=$3 what=$4 before=$5
    shift 5
    counts="$before of 4 frames rendered (0 in this run, $before before), 2 renders stopped and removed; the same command again renders the other $((4 - before))"
    rm -f marks/*
    setsid "$@" >"$work/out" 2>"$work/err" &
    pid=$!
    wait_marks 2 || { kill -KILL -$pid; wait $pid; return; }
    if [ "$target" = group ]; then
        kill -"$sig" -"$pid"
    else
        kill -"$sig" "$pid"
    fi
    wait $pid
    st=$?
    [ "$st" -ne 0 ] && ok "$what: exits $st" || fail "$what: exited 0"
    check_clean "$dir" "$what"
    said=$(tail -n 1 "$work/err")
    [ "$said" = "$(basename "$1"): stopped (SIG$sig): $counts" ] && ok "$what: says so: $said" ||
        fail "$what: last line '$said', not '$(basename "$1"): stopped (SIG$sig): $counts'"
}

"$r2p" anim.raygl -o a -q || fail "translate"
for sig in INT TERM; do
    for target in proc group; do
        stop $sig $target a "raygl-render, SIG$sig to the $target" 0 \
            "$render" a -j 2 --povray "$work/stand-in-povray"
        rm -rf b
        stop $sig $target b "raygl2pov --render, SIG$sig to the $target" 0 \
            "$r2p" anim.raygl -o b -j 2 --render --povray "$work/stand-in-povray"
    done
done
# A frame rendered before the stop stays.
"$render" a --frames 0 -q || fail "render frame 0"
stop INT group a "raygl-render after a finished frame" 1 \
    "$render" a -j 2 --povray "$work/stand-in-povray"
[ -s a/frame-00000.png ] && ok "the finished frame kept" || fail "frame 0 lost"

# Blender: the import script writes its image under the name raygl-render
# gives (--temp) and renames it; a stop while it writes removes it. The
# stand-in writes every file the script would, then blocks.
cat >stand-in-blender <<EOF2
#!/bin/sh
out='' tmp=''
while [ \$# -gt 0 ]; do
    case \$1 in
    --output) out=\$2; shift ;;
    --temp) tmp=\$2; shift ;;
    esac
    shift
done
[ -n "\$tmp" ] || tmp=\${out%/*}/.\${out##*/}.\$\$.tmp.png
printf 'partial' >"\$out"
printf 'half an image' >"\$tmp"
: >"$work/marks/\$\$"
exec sleep 300
EOF2
chmod +x stand-in-blender
"$r2p" anim.raygl -o g --format gltf -q || fail "translate to glTF"
for sig in INT TERM; do
    stop $sig group g "raygl-render --engine blender, SIG$sig to the group" 0 \
        "$render" g -j 2 --engine blender --blender "$work/stand-in-blender"
done

# raygl2pov while translating: frozen (SIGSTOP to its group) at a moment a
# temporary scene exists, then SIGINT and SIGCONT: the temporary files go,
# the scenes already published stay.
"$mkanim" many.raygl 3000 80 60
setsid "$r2p" many.raygl -o tr -j 2 -q >"$work/out" 2>"$work/err" &
pid=$!
i=0
until kill -0 -"$pid" 2>/dev/null || [ $i -gt 500 ]; do i=$((i + 1)); sleep 0.01; done # setsid done
caught=0 i=0
while [ $i -lt 3000 ]; do
    i=$((i + 1))
    kill -STOP -"$pid" 2>/dev/null || break
    if ls -A tr 2>/dev/null | grep -q '^\.raygl2pov-'; then
        caught=1
        kill -INT -"$pid"
        kill -CONT -"$pid"
        break
    fi
    kill -CONT -"$pid"
    case $(ps -o stat= -p "$pid") in Z*) break ;; esac
done
wait $pid
st=$?
if [ $caught -eq 1 ]; then
    [ "$st" -ne 0 ] && ok "translation stopped with temporary files: exits $st" ||
        fail "translation stopped: exited 0"
    left=$(ls -A tr | grep -v -E '^(frame-[0-9]+\.(pov|ini)|raygl-folder\.inc)$')
    [ -z "$left" ] && ok "translation stopped: no temporary file left" ||
        fail "translation stopped: left $(echo $left)"
else
    fail "no moment with a temporary scene seen in $i tries (exit $st)"
fi

# The real POV-Ray: signalled once its state file exists, to the group
# (POV-Ray gets it too) and to raygl-render alone (it stops POV-Ray).
"$mkanim" big.raygl 2 480 360
"$r2p" big.raygl -o real --radiosity --quality 11 --antialias -q
for target in group proc; do
    rm -f real/*.png
    setsid "$render" real -j 2 >"$work/out" 2>"$work/err" &
    pid=$!
    i=0
    until ls -A real | grep -q 'pov-state$'; do
        i=$((i + 1))
        [ $i -gt 1200 ] && { fail "POV-Ray wrote no .pov-state"; break; }
        sleep 0.05
    done
    if [ $target = group ]; then kill -INT -"$pid"; else kill -INT "$pid"; fi
    wait $pid
    [ $? -ne 0 ] && ok "real POV-Ray, SIGINT to the $target: interrupted" ||
        fail "real POV-Ray, SIGINT to the $target: exited 0"
    left=$(ls -A real | grep -v -E '^(frame-[0-9]+\.(pov|ini|png)|render\.list|textures|raygl-folder\.inc)$')
    [ -z "$left" ] && ok "real POV-Ray, SIGINT to the $target: nothing partial left" ||
        fail "real POV-Ray, SIGINT to the $target: left $(echo $left)"
    pgrep -g "$pid" >/dev/null && fail "real POV-Ray, SIGINT to the $target: a process left"
done

[ "$fails" -eq 0 ] && echo "interrupt: all checks passed" || echo "interrupt: $fails check(s) failed"
[ "$fails" -eq 0 ]
