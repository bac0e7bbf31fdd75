#!/bin/sh
# Regenerates the demo pictures committed under docs/img/ (README gallery and
# docs/demo.md) from the default gallery.  Run from the repository root after
# building: sh docs/plots/demo_gallery.sh [build-dir]
set -eu
B=${1:-build}
T=$(mktemp -d)
"$B/examples/demo/demo" --out "$T" --size 960x540 --map 1024 >/dev/null
# the old pictures go first, so that a picture the gallery no longer makes
# does not stay behind
rm -f docs/img/demo_*.png
# the comparison sheets (the default gallery ends with them): projective blur
# vs PCF, single-map PSM vs the cube map, sun in front of and behind the camera
for n in blur_sheet cube_sheet cube_sheet_behind; do
    cp "$T/$n.png" "docs/img/demo_$n.png"
done
"$B/examples/demo/demo" --out "$T/measure" --camera measure --light-angle 90 --size 960x540 \
    --technique lispsm >/dev/null
for n in sheet_techniques uniform_sampling lispsm_sampling pssm4_sampling psm_sampling \
         lispsm_light pssm4_light pssm-lispsm4_light lispsm_grid pssm4_splits pssm4_error \
         lispsm_error pssm4_third lispsm_third lixel_sampling lixel_shaded pssm4_shaded \
         psm-cube_splits psm-cube_light psm_light; do
    cp "$T/$n.png" "docs/img/demo_$n.png"
done
cp "$T/measure/lispsm_error.png" docs/img/demo_measure_lispsm_error.png
"$B/examples/demo/demo" --mindepth --out "$T/md" --size 960x540 >/dev/null
for k in near adjusted pseudo; do
    cp "$T/md/mindepth_${k}_sampling.png" "docs/img/demo_mindepth_${k}_sampling.png"
done
"$B/examples/demo/demo" --technique lispsm --filter projblur --out "$T/pb" --size 960x540 >/dev/null
cp "$T/pb/lispsm_shaded.png" docs/img/demo_projblur_lispsm_shaded.png
cp "$T/lispsm_shaded.png" docs/img/demo_pcf3_lispsm_shaded.png
rm -rf "$T"
ls docs/img/demo_*.png
