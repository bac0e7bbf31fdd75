#!/bin/sh
# Regenerates the reversed-Z table of docs/engines.md (printed to stdout).
# Run from the top of the tree after `meson setup build && ninja -C build`.
set -eu
ninja -C build tests/geometry/depth_precision >/dev/null
./build/tests/geometry/depth_precision
