#!/bin/sh
# The main job on the built-in default: installs what is missing, builds,
# runs the OSMesa demo's default gallery (PNGs into ./out/, a summary table
# and the comparison sheets), then swtool's report.  Arguments go to the demo
# (e.g. sh examples/run.sh --technique lispsm --size 1280x720).
set -eu
cd "$(dirname "$0")/.."
sh tests/install-deps.sh
[ -d build ] || meson setup build --buildtype=release >/dev/null
ninja -C build >/dev/null
if [ -x ./build/examples/demo/demo ]; then
    # without arguments the demo ends with the comparison sheets of issue 10
    # (projective blur vs PCF, single-map PSM vs the cube map: docs/demo.md)
    ./build/examples/demo/demo "$@"
else
    echo "run.sh: the demo was not built (OSMesa, libpng, cglm or stb missing); swtool only"
fi
./build/examples/swtool/swtool report
