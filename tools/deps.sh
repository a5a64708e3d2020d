#!/bin/sh
# Installs the Debian 12 packages RayGL needs to build, test and render.
# Runs apt-get directly as root, through sudo otherwise.
set -eu
PACKAGES="gcc pkg-config meson ninja-build python3 khronos-api libgl-dev libglu1-mesa-dev freeglut3-dev
libosmesa6-dev libpng-dev zlib1g-dev povray xvfb xauth locales slurm-wlm munge parallel ffmpeg
libegl-dev libx11-dev mesa-utils xscreensaver-gl man-db groff-base binutils"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $PACKAGES
