#!/bin/sh
# Regenerates docs/img/geometry_footprints.png from the project's own program
# tests/geometry/geometry_plot_data.c (swarp_setup for 3 lights x 2 techniques).
#   sh docs/plots/geometry_footprints.sh [build-dir]      (default: build)
set -eu
cd "$(dirname "$0")/../.."
BUILD="${1:-build}"
ninja -C "$BUILD" tests/geometry/geometry_plot_data >/dev/null
DATA="$(mktemp)"
trap 'rm -f "$DATA"' EXIT
"$BUILD/tests/geometry/geometry_plot_data" > "$DATA"
gnuplot -e "datafile='$DATA'; outfile='docs/img/geometry_footprints.png'" docs/plots/geometry_footprints.gp
echo "wrote docs/img/geometry_footprints.png"
