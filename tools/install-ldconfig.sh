#!/bin/sh
# Run by `meson install`: refreshes the dynamic linker's cache after an
# install to the real file system as root, so that programs linked with
# libraygl start without LD_LIBRARY_PATH (/usr/local/lib/<triplet> is in
# Debian's ld.so.conf). Nothing to do for a staged install (DESTDIR, as in
# the Debian package build: dpkg's trigger runs ldconfig) or a user's
# prefix (not in the cache: LD_LIBRARY_PATH, see the README).
[ "${MESON_INSTALL_DESTDIR_PREFIX:-}" = "${MESON_INSTALL_PREFIX:-}" ] || exit 0
[ "$(id -u)" -eq 0 ] || exit 0
command -v ldconfig >/dev/null 2>&1 || PATH=$PATH:/sbin:/usr/sbin
exec ldconfig
