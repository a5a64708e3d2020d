#!/bin/sh
# Undoes an install of RayGL: removes every file `meson install` listed in
# BUILD-DIR/meson-logs/install-log.txt, then RayGL's own folders
# (PREFIX/include/raygl, LIBDIR/raygl, PREFIX/share/raygl) and the folders
# that install made, once empty, then, as root, runs ldconfig so that the
# dynamic linker's cache forgets libraygl.
#
# Usage: tools/uninstall.sh [BUILD-DIR]
#   BUILD-DIR: the folder RayGL was installed from (default
#   build-quickstart, the quick start's). As root, or through sudo for a
#   system prefix: `sudo tools/uninstall.sh`, or in a root shell (Debian's
#   has no sudo) `tools/uninstall.sh`.
#
# Why not `ninja -C BUILD-DIR uninstall` alone: meson's uninstall exits 0
# when it removes nothing (a log naming files that are gone, "Deleted: 0,
# Failed: 35"), and runs no ldconfig. This script exits 1 then, and when a
# file cannot be removed, saying why.
set -uf
usage() { echo "usage: tools/uninstall.sh [BUILD-DIR]" >&2; exit 2; }
[ $# -le 1 ] || usage
case ${1:-} in -h | --help) usage ;; -*) echo "uninstall: unknown option $1" >&2; usage ;; esac
build=${1:-$(cd "$(dirname "$0")/.." && pwd)/build-quickstart}
log=$build/meson-logs/install-log.txt
if [ ! -f "$log" ]; then
    echo "uninstall: $log: no install log: nothing was installed from $build" >&2
    echo "uninstall: (tools/quickstart.sh installs from build-quickstart/; name another folder: tools/uninstall.sh BUILD-DIR)" >&2
    exit 1
fi

deleted=0 missing=0 failed=0 first_missing='' lib=0
dirs='' own=''
nl='
'
while IFS= read -r f; do
    case $f in '' | '#'*) continue ;; esac
    if [ -d "$f" ] && [ ! -L "$f" ]; then
        dirs=$dirs$f$nl # the log lists a made folder after its files, children first
        continue
    fi
    if [ ! -e "$f" ] && [ ! -L "$f" ]; then
        missing=$((missing + 1))
        [ -n "$first_missing" ] || first_missing=$f
        continue
    fi
    if err=$(rm -f -- "$f" 2>&1) && [ ! -e "$f" ] && [ ! -L "$f" ]; then
        deleted=$((deleted + 1))
        case $f in */libraygl.so*) lib=1 ;; esac
        case ${f%/*} in */raygl) own=${f%/*}$nl$own ;; esac
    else
        failed=$((failed + 1))
        echo "uninstall: $f: cannot remove: ${err:-it is still there}" >&2
    fi
done <"$log"

# RayGL's own folders, then those the install made, each once empty (a
# folder another package put files in stays).
removed_dirs=0
oifs=$IFS
IFS=$nl
for d in $(printf '%s' "$own" | sort -u) $dirs; do
    [ -d "$d" ] && rmdir -- "$d" 2>/dev/null && removed_dirs=$((removed_dirs + 1))
done
IFS=$oifs

if [ $failed -gt 0 ]; then
    echo "uninstall: $failed of the files listed in $log could not be removed (above)" >&2
    if [ "$(id -u)" -ne 0 ]; then
        echo "uninstall: run it as root: sudo tools/uninstall.sh${1:+ $1}, or in a root shell tools/uninstall.sh${1:+ $1}" >&2
    fi
    exit 1
fi
if [ $deleted -eq 0 ]; then
    echo "uninstall: nothing removed: none of the $missing paths listed in $log is there (the first: $first_missing)" >&2
    echo "uninstall: they were removed already, or installed elsewhere (a staged install, with --destdir)" >&2
    exit 1
fi

# The cache still names the removed library until ldconfig runs; as
# install-ldconfig.sh does after an install, root only.
said_ldconfig=''
if [ $lib = 1 ] && [ "$(id -u)" -eq 0 ]; then
    command -v ldconfig >/dev/null 2>&1 || PATH=$PATH:/sbin:/usr/sbin
    if ldconfig; then
        said_ldconfig='; ldconfig run'
    else
        echo "uninstall: ldconfig failed: the linker's cache may still name libraygl" >&2
        exit 1
    fi
fi
echo "uninstall: removed $deleted files and $removed_dirs folders$said_ldconfig"
[ $missing -eq 0 ] || echo "uninstall: $missing paths listed were not there any more (the first: $first_missing)"
exit 0
