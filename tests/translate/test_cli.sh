#!/bin/sh
# test_cli.sh: raygl2pov as a user meets it.
#
#   test_cli.sh RAYGL2POV MKTRACES TEST_NUMFMT
#
# Bad usage exits 2; a damaged trace exits 1 with the file and offset named
# and every intact frame written; an unwritable folder exits 1 and leaves no
# half-written file, and a read-only textures/ is named as such; hostile rayglFrameBegin names stay inside the output
# folder; -j N and a comma-decimal locale give the same bytes as -j 1;
# --dump and --frames do what they say.
set -u
abs() { (cd "$(dirname "$1")" && echo "$(pwd)/$(basename "$1")"); }
r2p=$(abs "$1")
mktraces=$(abs "$2")
numfmt=$(abs "$3")
work=$(mktemp -d "${TMPDIR:-/tmp}/rgl-cli.XXXXXX")
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
ok() { echo "ok: $*"; }

# Runs raygl2pov; leaves its exit status in $rc and its stderr in $work/err.
run() {
    "$r2p" "$@" >"$work/out" 2>"$work/err"
    rc=$?
}
expect_rc() {
    want=$1
    shift
    if [ "$rc" -ne "$want" ]; then
        fail "$* exited $rc, expected $want; stderr:"
        sed 's/^/    /' "$work/err"
    else
        ok "$* exits $want"
    fi
}

mkdir -p "$work/traces" "$work/sandbox/a/b"
"$mktraces" "$work/traces" || { echo "mktraces failed"; exit 1; }
good=$work/traces/good.raygl

# ---- usage
run; expect_rc 2 "no arguments"
grep -q "no trace given" "$work/err" || fail "no-argument message"
run "$good"; expect_rc 2 "no -o"
run "$good" -o "$work/x" --bogus; expect_rc 2 "unknown option"
grep -q "unknown option '--bogus'" "$work/err" || fail "unknown-option message"
run "$good" -o "$work/x" -j 0; expect_rc 2 "-j 0"
run "$good" -o "$work/x" --frames 5-2; expect_rc 2 "backwards range"
run "$good" -o "$work/x" --frames 1,x; expect_rc 2 "bad frame list"
run "$good" other.raygl -o "$work/x"; expect_rc 2 "two traces"
run "$good" -o; expect_rc 2 "-o without a value"
printf 'quiet\n# comment\nframes = 9-1\n' >"$work/look.conf"
run "$good" -o "$work/x" --settings "$work/look.conf"; expect_rc 2 "settings file with a bad line"
grep -q "look.conf:3: frames '9-1': range 9-1 runs backwards" "$work/err" || fail "settings-file message names FILE:LINE"
run "$good" -o "$work/x" --settings "$work/missing.conf"; expect_rc 2 "missing settings file"
run "$good" -o "$work/x" --frames 1-5:0; expect_rc 2 "--frames step 0"
run --help; expect_rc 0 "--help"
grep -q "^Usage: raygl2pov TRACE -o DIR" "$work/out" || fail "--help text"
run --version; expect_rc 0 "--version"
[ -e "$work/x" ] && fail "a usage error created the output folder"

# ---- a good trace
cd "$work/sandbox/a/b" || exit 1
run "$good" -o out -j 1
expect_rc 0 "good trace"
for f in frame-00000 frame-00001 frame-00002 frame-00003 frame-00004 x passwd a_b_c x-00008 frame-00009; do
    [ -s "out/$f.pov" ] && [ -s "out/$f.ini" ] || fail "out/$f.pov or .ini missing"
done
n=$(ls out | wc -l)
[ "$n" -eq 21 ] || fail "expected 21 files in out, found $n: $(ls out | tr '\n' ' ')"
# Every .ini reads the folder check first (POV-Ray reads INI paths from
# the current folder: run from elsewhere, it says where to run from).
[ -s out/raygl-folder.inc ] && grep -q '^Include_Header=raygl-folder.inc$' out/x.ini &&
    grep -q 'file_exists(concat("out/", input_file_name))' out/raygl-folder.inc ||
    fail "the folder check: $(cat out/x.ini out/raygl-folder.inc)"
# Nothing escapes the output folder.
found=$(cd "$work/sandbox" && find . -newer "$good" -type f | grep -v '^\./a/b/out/' || true)
[ -z "$found" ] && ok "nothing written outside the output folder" ||
    fail "written outside the output folder: $found"
[ -e /etc/passwd.pov ] && fail "/etc/passwd.pov exists"
grep -q "x.pov is taken by an earlier frame; writing x-00008.pov" "$work/err" ||
    fail "no message about the name used twice"
# The hostile name reaches the SDL only as an escaped comment.
grep -q '^// rayglFrameBegin name: ../../x.pov$' out/x.pov || fail "frame name comment"
grep -q 'fopen' out/frame-00009.pov && fail "name text outside a comment"
# The .ini renders from the folder raygl2pov ran in.
grep -q '^Input_File_Name=x.pov$' out/x.ini && grep -q '^Output_File_Name=out/x.png$' out/x.ini &&
    grep -q '^Library_Path=out$' out/x.ini && grep -q '^File_Gamma=2.2$' out/x.ini ||
    fail ".ini paths: $(cat out/x.ini)"
grep -q '^Width=64$' out/frame-00003.ini && grep -q '^Height=48$' out/frame-00003.ini ||
    fail "the snapshot's viewport does not size frame 3"
# The carried frame uses frame 0's perspective camera.
grep -q 'camera{perspective' out/frame-00002.pov || fail "carried state: no perspective camera"
grep -q 'rgb<0.3,0.3,0.3>' out/frame-00002.pov || fail "carried state: background"
grep -q 'rgb<0.5,0,0>' out/frame-00003.pov || fail "snapshot: clear colour"
ls -a out | grep -q '\.tmp$' && fail "temporary files left"

# ---- -j N gives the same bytes; so does a comma-decimal locale
# (Same folder name, since the .ini files name it.)
mkdir -p "$work/j4" "$work/de"
(cd "$work/j4" && "$r2p" "$good" -o out -j 4 2>"$work/err")
rc=$?
expect_rc 0 "-j 4"
diff -r out "$work/j4/out" >/dev/null && ok "-j 4 output = -j 1 output" ||
    fail "-j 4 differs from -j 1"
mkdir -p "$work/locale"
if command -v localedef >/dev/null 2>&1 &&
    localedef -i de_DE -f UTF-8 "$work/locale/de_DE.UTF-8" >/dev/null 2>&1; then
    (cd "$work/de" && LOCPATH=$work/locale LC_ALL=de_DE.UTF-8 "$r2p" "$good" -o out -j 2 2>"$work/err")
    rc=$?
    expect_rc 0 "de_DE locale"
    diff -r out "$work/de/out" >/dev/null && ok "de_DE output = C output" ||
        fail "de_DE output differs"
    LOCPATH=$work/locale "$numfmt" --locale
    case $? in 0) ok "numfmt under de_DE" ;; *) fail "numfmt under de_DE" ;; esac
else
    # No locale data on this machine: test_sources.sh still checks that no
    # float goes through printf.
    echo "skipped: cannot generate a de_DE locale with localedef"
fi

# ---- --frames and --dump
run "$good" -o sub --frames 1,3-4
expect_rc 0 "--frames 1,3-4"
[ "$(ls sub | tr '\n' ' ')" = "frame-00001.ini frame-00001.pov frame-00003.ini frame-00003.pov frame-00004.ini frame-00004.pov raygl-folder.inc " ] ||
    fail "--frames wrote: $(ls sub | tr '\n' ' ')"
run "$good" --frames 40-
expect_rc 2 "--frames without -o or --dump"
run "$good" -o none --frames 40-
expect_rc 1 "--frames selecting nothing"
run "$good" --dump --frames 3
expect_rc 0 "--dump"
grep -q '^frame 3: stream 1, number 1, flags 0x1 live-context, snapshot #1' "$work/out" ||
    fail "--dump frame header: $(head -3 "$work/out")"
grep -q '^    [0-9]* @0x[0-9a-f]* glViewport(' "$work/out" || fail "--dump snapshot commands"
grep -q '^  [0-9]* @0x[0-9a-f]* glRectf(' "$work/out" || fail "--dump frame commands"

# ---- damaged traces
size=$(wc -c <"$good")
head -c $((size - 300)) "$good" >"$work/traces/cut.raygl"
run "$work/traces/cut.raygl" -o cut
expect_rc 0 "truncated trace (a recording stopped while writing: not damage)"
grep -q "raygl2pov: $work/traces/cut.raygl: trace not closed" "$work/err" ||
    fail "truncation message names the file: $(cat "$work/err")"
[ -s cut/frame-00000.pov ] && [ -s cut/frame-00004.pov ] || fail "intact frames of the cut trace"
# One flipped byte inside frame 1's commands: frame 1 is reported, the rest written.
off=$("$r2p" "$good" --dump --frames 1 | sed -n 's/^frame 1: .*, @0x\([0-9a-f]*\),.*/\1/p')
[ -n "$off" ] || fail "no offset for frame 1 in --dump"
cp "$good" "$work/traces/flip.raygl"
printf '\377' | dd of="$work/traces/flip.raygl" bs=1 seek=$((0x$off + 40)) conv=notrunc 2>/dev/null
run "$work/traces/flip.raygl" -o flip
expect_rc 1 "flipped byte"
grep -q "frame 1" "$work/err" || fail "flipped byte: frame 1 not named: $(cat "$work/err")"
[ -e flip/frame-00001.pov ] && fail "the damaged frame 1 was written"
[ -s flip/frame-00000.pov ] && [ -s flip/frame-00002.pov ] && [ -s flip/x.pov ] ||
    fail "intact frames around the damaged one"
# Same scene; only the header comment names the other trace.
tail -n +2 flip/frame-00002.pov >"$work/f2a"
tail -n +2 out/frame-00002.pov >"$work/f2b"
cmp -s "$work/f2a" "$work/f2b" || fail "frame 2 differs after damage to frame 1"
run "$work/traces/none.raygl" -o none2
expect_rc 1 "missing trace"
grep -q "none.raygl: cannot read" "$work/err" || fail "missing-trace message"
printf 'not a trace at all' >"$work/traces/text.raygl"
run "$work/traces/text.raygl" -o none3
expect_rc 1 "not a trace"

# ---- unwritable output
: >"$work/afile"
run "$good" -o "$work/afile/sub"
expect_rc 1 "output under a file"
grep -q "afile/sub: cannot create the output folder" "$work/err" || fail "folder message"
# A full disk, as the file size limit: nothing half-written under a final name.
(
    trap '' XFSZ
    ulimit -f 64
    "$r2p" "$work/traces/big.raygl" -o full -j 1 2>"$work/err"
    echo $? >"$work/rc"
)
rc=$(cat "$work/rc")
expect_rc 1 "full disk"
grep -q "cannot write" "$work/err" || fail "full-disk message: $(cat "$work/err")"
[ -z "$(ls -A full | grep -v '^raygl-folder\.inc$')" ] && ok "no file left after the failed write" ||
    fail "left after a failed write: $(ls -A full | tr '\n' ' ')"

# ---- a new user's first hour (issue 11)
mkdir "$work/adir"
run "$work/adir" -o "$work/never"
expect_rc 1 "a folder as trace"
grep -q "adir: cannot read: a folder, not a trace" "$work/err" ||
    fail "folder-as-trace message: $(cat "$work/err")"
printf '# reads itself\nsettings = self.conf\n' >"$work/self.conf"
run "$good" -o "$work/never" --settings "$work/self.conf"
expect_rc 2 "a settings file that reads itself"
[ "$(grep -c 'self.conf' "$work/err")" -eq 1 ] &&
    grep -q "self.conf:2: settings 'self.conf': that settings file is already being read (a cycle)" \
        "$work/err" && ok "the cycle named once, with FILE:LINE" || fail "cycle message: $(cat "$work/err")"
printf 'light = "1,2,3\n' >"$work/quote.conf"
run "$good" -o "$work/never" --settings "$work/quote.conf"
expect_rc 2 "an unterminated quote"
grep -q "quote.conf:1: unterminated quote" "$work/err" && ok "reported as a quote" ||
    fail "quote message: $(cat "$work/err")"
[ ! -e "$work/never" ] && ok "no output folder made by bad usage" || fail "bad usage made its folder"

# ---- textures apart from the frames: deleting the frames' PNGs keeps them
"$(dirname "$mktraces")/mktextrace" "$work/tex.raygl" || fail "mktextrace"
run "$work/tex.raygl" -o "$work/tex" -q
expect_rc 0 "a textured trace"
[ -n "$(ls "$work/tex/textures" 2>/dev/null | grep '^rgl-tex-.*\.png$')" ] &&
    [ -z "$(ls "$work/tex" | grep '\.png$')" ] && ok "texture images in textures/" ||
    fail "texture images: $(ls -R "$work/tex")"
grep -q 'image_map{png "textures/rgl-tex-' "$work/tex/frame-00000.pov" && ok "the scene names textures/" ||
    fail "the scene's image_map: $(grep image_map "$work/tex/frame-00000.pov" | head -1)"

# A read-only textures/: the error names the image it could not write,
# not the frame's temporary scene (issue 27). Root writes there anyway:
# then as nobody, where setpriv can.
ro=$work/ro
chmod 711 "$work"
mkdir "$ro" && cp "$work/tex.raygl" "$ro/" && chmod 777 "$ro" && chmod 644 "$ro/tex.raygl"
as=''
[ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null 2>&1 &&
    as='setpriv --reuid=65534 --regid=65534 --clear-groups'
$as "$r2p" "$ro/tex.raygl" -o "$ro/out" -q 2>"$work/err" && rm -f "$ro/out/textures/"* &&
    chmod 555 "$ro/out/textures" || fail "read-only textures: setup: $(cat "$work/err")"
if $as sh -c ': >"$1/out/textures/probe"' sh "$ro" 2>/dev/null; then
    ok "read-only textures: SKIP (the folder takes files anyway)"
else
    $as "$r2p" "$ro/tex.raygl" -o "$ro/out" -q >"$work/out" 2>"$work/err"
    rc=$?
    expect_rc 1 "a read-only textures folder"
    grep -q "^raygl2pov: $ro/out/textures/rgl-tex-[0-9a-f]*\.png: cannot write: Permission denied\$" "$work/err" &&
        ok "the message names the texture" || fail "read-only textures message: $(cat "$work/err")"
fi
chmod 755 "$ro/out/textures" 2>/dev/null

# ---- calls not recorded (@NotRecorded): one report per trace, by name;
# only those that can change the picture (names this version records now
# say what is missing), the others with --verbose and --dump
unrec=$work/traces/unrecorded.raygl
p="raygl2pov: $unrec:"
miss="what it does is missing from the trace"
printf '%s\n' "$p gl??31mEvil?: 2 calls not recorded, from frame 1: $miss" \
    "$p glAccum: 1,204 calls not recorded, from frame 0: $miss" \
    "$p glActiveTexture: 1 call not recorded, from frame 2: $miss" \
    "$p glMap1f: 5 calls not recorded, from frame 1: $miss" \
    "$p glRasterPos2i: 1 call not recorded, from frame 0: $miss" \
    "$p glutBitmapCharacter: 7 calls not recorded, from frame 2: the bitmap text is missing (raygl record, which sees freeglut's own calls, records it)" >"$work/unrec.want"
for j in 1 3; do
    run "$unrec" -o "$work/unrec$j" -j $j
    expect_rc 0 "calls not recorded, -j $j"
    grep 'not recorded' "$work/err" >"$work/unrec.got"
    cmp -s "$work/unrec.want" "$work/unrec.got" && ok "calls not recorded reported once, -j $j" ||
        fail "calls not recorded, -j $j: $(diff "$work/unrec.want" "$work/unrec.got")"
done
run "$unrec" -o "$work/unrec4" --frames 1
grep 'not recorded' "$work/err" >"$work/unrec.got"
printf '%s\n' "$p gl??31mEvil?: 2 calls not recorded, from frame 1: $miss" \
    "$p glAccum: 204 calls not recorded, from frame 1: $miss" \
    "$p glMap1f: 5 calls not recorded, from frame 1: $miss" >"$work/unrec.want1"
cmp -s "$work/unrec.want1" "$work/unrec.got" && ok "--frames 1: that frame's calls only" ||
    fail "--frames 1: $(diff "$work/unrec.want1" "$work/unrec.got")"
run "$unrec" -o "$work/unrec5" --quiet
grep -q 'not recorded' "$work/err" && fail "--quiet still reports calls not recorded" ||
    ok "--quiet: no report"
for v in -v --verbose; do
    run "$unrec" -o "$work/unrec6" $v
    grep 'not recorded' "$work/err" >"$work/unrec.got"
    { sed -n 1,3p "$work/unrec.want"
      echo "$p glCompressedTexImage2D: 3 calls not recorded, from frame 0 (cannot change the picture: it acts only on textured draws, which no frame from it on has): compressed texture images: the textures they fill are drawn without them"
      sed -n 4,6p "$work/unrec.want"
      echo "$p glutInit: 1 call not recorded, from frame 0 (cannot change the picture: the window system (windows, menus, input, callbacks, the main loop))"
    } >"$work/unrec.want2"
    cmp -s "$work/unrec.want2" "$work/unrec.got" && ok "$v: every call not recorded, marked" ||
        fail "$v: $(diff "$work/unrec.want2" "$work/unrec.got")"
done
run "$unrec" -o "$work/unrec7" -v -q
grep -q 'not recorded' "$work/err" && fail "-v -q: the later --quiet does not win" || ok "-v -q: quiet"
run "$unrec" --dump
grep -q '@NotRecorded(name="glAccum", count=1000)' "$work/out" && ok "--dump shows @NotRecorded" ||
    fail "--dump: no @NotRecorded"
grep -qx '#   glutInit: 1 call not recorded, from frame 0 (cannot change the picture: the window system (windows, menus, input, callbacks, the main loop))' "$work/out" &&
    grep -qx '#   glCompressedTexImage2D: 3 calls not recorded, from frame 0 (changes the picture only with textured draws): .*' "$work/out" &&
    grep -qx '#   glAccum: 1,204 calls not recorded, from frame 0: what it does is missing from the trace' "$work/out" &&
    ok "--dump: every call not recorded, by what it can change" ||
    fail "--dump: the summary of calls not recorded: $(grep '^#' "$work/out")"

if [ $fails -ne 0 ]; then
    echo "test_cli: $fails failure(s)"
    exit 1
fi
echo "test_cli: all passed"
