#!/bin/sh
# The main job on the built-in default: installs what is missing, builds,
# runs the OSMesa demo's default gallery (PNGs into ./out/ and a summary
# table on stdout), then swtool's report.  Arguments go to the demo
# (e.g. sh examples/run.sh --technique lispsm --size 1280x720).
set -eu
cd "$(dirname "$0")/.."
sh tests/install-deps.sh
[ -d build ] || meson setup build --buildtype=release >/dev/null
ninja -C build >/dev/null
if [ -x ./build/examples/demo/demo ]; then
    ./build/examples/demo/demo "$@"
    # issue 10 extras for the default gallery: PSM with cube-map faces next to
    # single-map PSM, and the third-person views (docs/demo-extras.md)
    if [ $# -eq 0 ] && [ -x ./build/examples/demo/demo-extras ]; then
        ./build/examples/demo/demo-extras --part cube --part viz --frames 3 --out out/extras
    fi
else
    echo "run.sh: the demo was not built (OSMesa, libpng, cglm or stb missing); swtool only"
fi
./build/examples/swtool/swtool report
