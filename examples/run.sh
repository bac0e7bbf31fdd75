#!/bin/sh
# The main job on the built-in default: installs what is missing, builds,
# and runs it.  Output goes to stdout (and ./out/ once the demo lands).
set -eu
cd "$(dirname "$0")/.."
sh tests/install-deps.sh
[ -d build ] || meson setup build --buildtype=release >/dev/null
ninja -C build >/dev/null
./build/examples/swtool/swtool report "$@"
