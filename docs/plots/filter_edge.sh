#!/bin/sh
# Regenerates docs/img/filter_edge.png (and prints the table of
# docs/filtering.md) from the project's own program tests/filter/filter_table.c.
#   sh docs/plots/filter_edge.sh [build-dir]      (default: build)
set -eu
cd "$(dirname "$0")/../.."
BUILD="${1:-build}"
ninja -C "$BUILD" tests/filter/filter_table >/dev/null
DATA="$(mktemp)"
trap 'rm -f "$DATA"' EXIT
"$BUILD/tests/filter/filter_table" plot > "$DATA"
gnuplot -e "datafile='$DATA'; outfile='docs/img/filter_edge.png'" docs/plots/filter_edge.gp
echo "wrote docs/img/filter_edge.png"
echo "table for docs/filtering.md:"
"$BUILD/tests/filter/filter_table" table
