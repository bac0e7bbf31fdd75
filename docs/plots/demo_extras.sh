#!/bin/sh
# Regenerates the pictures and tables of docs/demo-extras.md (issue 10's demo
# parts) with demo-extras.  Run from the repository root after building:
#   sh docs/plots/demo_extras.sh [build-dir] [frames]
# Pictures go to docs/img/extras_*.png, the full text output (timing tables)
# to docs/plots/demo-extras.log.  About 5 minutes on the 2-core machine.
set -eu
B=${1:-build}
F=${2:-9}
T=$(mktemp -d)
"$B/examples/demo/demo-extras" --out "$T" --size 960x540 --map 1024 --frames "$F" \
    | tee docs/plots/demo-extras.log
for n in viz_uniform viz_lispsm viz_pssm4 blur_sheet mindepth_sheet cube_sheet cube_sheet_behind \
         cube_faces; do
    cp "$T/$n.png" "docs/img/extras_$n.png"
done
rm -rf "$T"
ls docs/img/extras_*.png
