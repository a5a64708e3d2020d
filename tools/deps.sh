#!/bin/sh
# Installs the Debian 12 packages RayGL needs to build, test, render and
# package (README "Dependencies" says what each is for). Runs apt-get
# directly as root, through sudo otherwise; does nothing when every
# package is installed already (tools/test.sh calls it on every run).
set -eu
PACKAGES="gcc pkg-config meson ninja-build python3 khronos-api libgl-dev libglu1-mesa-dev freeglut3-dev
libosmesa6-dev libpng-dev zlib1g-dev povray xvfb xauth locales slurm-wlm munge parallel ffmpeg
libegl-dev libx11-dev mesa-utils xscreensaver-gl man-db groff-base binutils
build-essential debhelper dpkg-dev fakeroot lintian"
# shellcheck disable=SC2086
if status=$(dpkg-query -W -f '${db:Status-Abbrev}\n' $PACKAGES 2>/dev/null) &&
    ! printf '%s\n' "$status" | grep -qv '^ii'; then
    echo "deps: all $(echo $PACKAGES | wc -w) packages are installed"
    exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $PACKAGES
