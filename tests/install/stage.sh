# stage.sh: sourced by the install tests. stage_install BUILD SHADOW DEST
# installs BUILD's files under DEST (meson install --destdir) without
# touching BUILD's install state: `meson install` writes the list of what
# it installed (meson-logs/install-log.txt, which `ninja uninstall` and
# tools/uninstall.sh read) into the folder it runs on, and a staged
# install's list names files that are gone once the test ends (issue 27).
# So it runs on SHADOW: BUILD's entries linked, its install data copied
# (the paths in it are relative to the build folder), a log folder of its
# own (SHADOW/meson-logs/install-log.txt). Returns meson's status; its
# output is in SHADOW.install.log.
stage_install() {
    sb=$1 ss=$2 sd=$3
    mkdir -p "$ss/meson-private" "$ss/meson-logs" || return 1
    for e in "$sb"/* "$sb"/.ninja_log "$sb"/.ninja_deps; do
        [ -e "$e" ] || continue
        case ${e##*/} in meson-private | meson-logs) ;; *) ln -s "$e" "$ss/${e##*/}" ;; esac
    done
    cp "$sb/meson-private/install.dat" "$ss/meson-private/" || return 1
    meson install -C "$ss" --no-rebuild --destdir "$sd" >"$ss.install.log" 2>&1
}
