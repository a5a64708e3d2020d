# image-test-args.sh: what run-image-test.sh and run-frames-test.sh share,
# sourced by both: the options every image test takes, their checks, and
# absolute paths for the steps that run in the test's directory.
#
# common_option OPT VALUE: takes one of --name --program --raygl2pov --povray
# --imgcmp --outdir --size --r2p-opt --r2p-says --figures (the caller then
# shifts 2); returns 1 on an unknown option, exits 2 on a bad value.
#
# --r2p-says nothing: raygl2pov must print nothing (a program whose frames are
# exact: nothing said in vain); --r2p-says REGEX (repeatable): it must print
# a line matching the extended regular expression (a message that must
# still be said where it matters). r2p_says_check LOG... checks them.
#
# --figures FILE: the figures measured are checked against FILE
# (check-figures.sh); meson passes tests/image/figures.txt.
name='' prog='' r2p='' povray='' imgcmp='' outdir='' size='' r2p_opts='' r2p_says='' figures=''
common_option() {
    case $1 in
    --name|--program|--raygl2pov|--povray|--imgcmp|--outdir|--size|--r2p-opt|--r2p-says|--figures) ;;
    *) echo "$0: unknown argument $1" >&2; return 1 ;;
    esac
    [ $# -ge 2 ] || return 1
    case $1 in
    --name) name=$2 ;;
    --program) prog=$2 ;;
    --raygl2pov) r2p=$2 ;;
    --povray) povray=$2 ;;
    --imgcmp) imgcmp=$2 ;;
    --outdir) outdir=$2 ;;
    --size) size=$2 ;;
    --figures) figures=$2 ;;
    --r2p-opt)
        case $2 in
        *[!A-Za-z0-9.,=-]*) echo "$0: --r2p-opt '$2': letters, digits, '.', ',', '=' and '-' only" >&2; exit 2 ;;
        esac
        r2p_opts="$r2p_opts $2" ;;
    --r2p-says)
        r2p_says="$r2p_says$2
" ;;
    esac
}

# r2p_says_check LOG...: prints why and returns 1 when the logs of raygl2pov
# break a --r2p-says (nothing: every log empty; REGEX: a line of one of
# them matches).
r2p_says_check() {
    printf '%s' "$r2p_says" | {
        bad=0
        while IFS= read -r want; do
            if [ "$want" = nothing ]; then
                for log in "$@"; do
                    if [ -s "$log" ]; then
                        echo "raygl2pov printed a message for a test that must say nothing ($log):"
                        sed -n '1,10p' "$log" | sed 's/^/    /'
                        bad=1
                    fi
                done
            elif ! cat "$@" | grep -Eq -- "$want"; then
                echo "raygl2pov did not say what matches '$want'"
                bad=1
            fi
        done
        exit $bad
    }
}

# common_finish: every required option given (else usage), a plain test name,
# and the paths made absolute (a bare program name is left to PATH).
absolute() {
    case $1 in
    /*) printf '%s\n' "$1" ;;
    */*) printf '%s/%s\n' "$PWD" "$1" ;;
    *) printf '%s\n' "$1" ;;
    esac
}
common_finish() {
    [ -n "$name" ] && [ -n "$prog" ] && [ -n "$r2p" ] && [ -n "$povray" ] &&
        [ -n "$imgcmp" ] && [ -n "$outdir" ] || usage
    case $name in
    *[!A-Za-z0-9_-]*|'') echo "$0: --name '$name': letters, digits, '_' and '-' only" >&2; exit 2 ;;
    esac
    prog=$(absolute "$prog")
    r2p=$(absolute "$r2p")
    povray=$(absolute "$povray")
    imgcmp=$(absolute "$imgcmp")
    [ -z "$figures" ] || figures=$(absolute "$figures")
    case $outdir in
    /*) ;;
    *) outdir=$PWD/$outdir ;;
    esac
}

# figures_of LOG: "TOL WITHIN SILHOUETTE" from imgcmp's output in LOG, or
# nothing when it printed no figures.
figures_of() {
    sed -n 's|^within \([0-9]*\)/255: \([0-9.]*\) .*|\1 \2|p' "$1" | head -n 1 | tr '\n' ' '
    sed -n 's/^silhouette: \([0-9.]*\) .*/\1/p' "$1" | head -n 1
}
