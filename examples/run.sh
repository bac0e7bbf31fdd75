#!/bin/sh
# The main job on the built-in default: installs what the build and the demo
# need if it is missing (tests/install-deps.sh build demo: no test tools),
# builds with one job per core, runs the OSMesa demo's default gallery (PNGs
# into ./out/, a summary table and the comparison sheets), then swtool's
# report.  Arguments go to the demo
# (e.g. sh examples/run.sh --technique lispsm --size 1280x720).
set -eu
cd "$(dirname "$0")/.."
sh tests/install-deps.sh build demo
# ninja's default runs cores + 2 jobs; on a shared machine that is more
# than it has
jobs="$(nproc 2>/dev/null || echo 1)"
[ -d build ] || meson setup build --buildtype=release >/dev/null
ninja -C build -j "$jobs" >/dev/null
if [ -x ./build/examples/demo/demo ]; then
    # without arguments the demo ends with the comparison sheets
    # (projective blur vs PCF, single-map PSM vs the cube map: docs/demo.md)
    ./build/examples/demo/demo "$@"
else
    echo "run.sh: the demo was not built (OSMesa, libpng, cglm or stb missing); swtool only"
fi
./build/examples/swtool/swtool report
