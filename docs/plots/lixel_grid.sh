#!/bin/sh
# Regenerates docs/img/lixel_grid.png (docs/lixel.md).  Run from the top of
# the tree after `meson setup build && ninja -C build` (needs libpng-dev).
set -eu
ninja -C build tests/lixel/lixel_grid >/dev/null
./build/tests/lixel/lixel_grid docs/img/lixel_grid.png
