#!/bin/sh
# regen-golden.sh: rewrites tests/translate/golden/ from the current writer.
#
#   tests/translate/regen-golden.sh [BUILD_DIR]     (default: build-tr)
#
# The only way the golden files change. Review `git diff tests/translate/golden`
# like code before committing it.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build-tr}
ninja -C "$build" tests/translate/test_golden
mkdir -p "$here/golden"
"$build/tests/translate/test_golden" --regen "$here/golden"
