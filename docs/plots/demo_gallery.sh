#!/bin/sh
# Regenerates the demo pictures committed under docs/img/ (README gallery and
# docs/demo.md) from the default gallery.  Run from the repository root after
# building: sh docs/plots/demo_gallery.sh [build-dir]
set -eu
B=${1:-build}
T=$(mktemp -d)
"$B/examples/demo/demo" --out "$T" --size 960x540 --map 1024 >/dev/null
"$B/examples/demo/demo" --out "$T/measure" --camera measure --light-angle 90 --size 960x540 \
    --technique uniform >/dev/null
for f in "$T"/*.png; do
    n=$(basename "$f")
    case "$n" in
        sheet_techniques.png|uniform_shaded.png|uniform_sampling.png|uniform_light.png|\
        lispsm_sampling.png|lispsm_light.png|lispsm_grid.png|lispsm_error.png|\
        pssm4_splits.png|pssm4_sampling.png|pssm4_light.png|pssm4_error.png|pssm4_shaded.png|\
        pssm-lispsm4_sampling.png|psm_sampling.png|lixel_shaded.png|uniform_grid.png|uniform_error.png)
            cp "$f" "docs/img/demo_$n" ;;
    esac
done
cp "$T/measure/uniform_error.png" docs/img/demo_measure_uniform_error.png
rm -rf "$T"
ls docs/img/demo_*.png
