#!/bin/sh
# Installs the Debian 12 packages RayGL needs to build, test, render and
# package (README "Dependencies" says what each is for). Runs apt-get
# directly as root, through sudo otherwise; does nothing when every
# package is installed already (tools/test.sh calls it on every run).
set -eu
PACKAGES="gcc pkg-config meson ninja-build python3 khronos-api libgl-dev libglu1-mesa-dev freeglut3-dev
libosmesa6-dev libpng-dev zlib1g-dev povray xvfb xauth locales slurm-wlm munge parallel ffmpeg
libegl-dev libx11-dev mesa-utils xscreensaver-gl man-db groff-base binutils
build-essential debhelper dpkg-dev fakeroot lintian nodejs chromium"
# Blender with numpy: raygl-render --engine blender and suite blender
# (Blender 3.4's glTF importer needs numpy; about 27 MB to download).
PACKAGES="$PACKAGES blender python3-numpy"
# Debian's npm, unless a nodejs that bundles its own (and conflicts with
# Debian's npm package) is installed already.
command -v npm >/dev/null 2>&1 || PACKAGES="$PACKAGES npm"
# The glTF tests' validator and three.js (npm packages gltf-validator and
# three, pinned in tools/node/package-lock.json; three.js renders .glb
# frames in chromium for suite gltf-image), installed into
# tools/node/node_modules.
node_tools() {
    dir="$(dirname "$0")/node"
    [ -d "$dir/node_modules/gltf-validator" ] && [ -d "$dir/node_modules/three" ] && return 0
    command -v npm >/dev/null 2>&1 || return 0
    (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
}
# shellcheck disable=SC2086
if status=$(dpkg-query -W -f '${db:Status-Abbrev}\n' $PACKAGES 2>/dev/null) &&
    ! printf '%s\n' "$status" | grep -qv '^ii'; then
    echo "deps: all $(echo $PACKAGES | wc -w) packages are installed"
    node_tools
    exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $PACKAGES
node_tools
