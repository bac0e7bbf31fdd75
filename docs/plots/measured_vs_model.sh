#!/bin/sh
# Regenerates docs/img/measured_vs_model.png and prints the table of
# docs/accuracy.md, from tests/model/measured_vs_model.c (500 configurations).
#   sh docs/plots/measured_vs_model.sh [build-dir]      (default: build)
set -eu
cd "$(dirname "$0")/../.."
BUILD="${1:-build}"
ninja -C "$BUILD" tests/model/measured_vs_model >/dev/null
DATA="$(mktemp)"
trap 'rm -f "$DATA"' EXIT
"$BUILD/tests/model/measured_vs_model" plot 500 > "$DATA"
gnuplot -e "datafile='$DATA'; outfile='docs/img/measured_vs_model.png'" docs/plots/measured_vs_model.gp
"$BUILD/tests/model/measured_vs_model" table 500
echo "wrote docs/img/measured_vs_model.png"
