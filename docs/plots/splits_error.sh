#!/bin/sh
# Regenerates docs/img/splits_fig315.png ([RHS] Fig. 3.15: PSSM with 2, 4, 8,
# 16 splits, uniform maps) and docs/img/splits_fig318.png ([RHS] Fig. 3.18:
# LiSPSM + PSSM(4) vs LiSPSM + log(4)), overhead light, Θ = 30°, n = 1,
# f = 500, 1024² image and maps.  Data: `swtool cascade --curve`.
# Run from the repository root after a build: docs/plots/splits_error.sh [builddir]
set -eu
B=${1:-build}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
SW="$B/examples/swtool/swtool"
for k in 2 4 8 16; do
    "$SW" cascade --near 1 --far 500 --fovy 60 --splits $k --scheme practical:0.5 --curve --samples 200 > "$T/pssm$k"
done
"$SW" cascade --near 1 --far 500 --fovy 60 --splits 4 --scheme practical:0.5 --warp lispsm --curve --samples 200 > "$T/lpssm"
"$SW" cascade --near 1 --far 500 --fovy 60 --splits 4 --scheme log --warp lispsm --curve --samples 200 > "$T/llog"
gnuplot <<GP
set terminal pngcairo size 1100,480 font "sans,11"
set output "docs/img/splits_fig315.png"
set multiplot layout 1,2 title "PSSM (λ = 0.5), uniform split maps, overhead light, Θ = 30°, n = 1, f = 500  ([RHS] Fig. 3.15)"
set logscale y
set grid
set xlabel "view depth z"
set key top right
set ylabel "m_x"
plot for [k in "2 4 8 16"] "$T/pssm".k u 1:2 w l lw 2 t k." splits"
set ylabel "m_z"
plot for [k in "2 4 8 16"] "$T/pssm".k u 1:3 w l lw 2 t k." splits"
unset multiplot
set output "docs/img/splits_fig318.png"
set multiplot layout 1,2 title "LiSPSM (n_{opt} per split) + 4 splits, overhead light, Θ = 30°, n = 1, f = 500  ([RHS] Fig. 3.18)"
unset logscale y
set yrange [0:*]
set logscale x
set xlabel "view depth z (log scale)"
set ylabel "error"
set title "(a) LiSPSM + PSSM(4), λ = 0.5"
plot "$T/lpssm" u 1:2 w l lw 2 t "m_x", "$T/lpssm" u 1:3 w l lw 2 t "m_z"
set title "(b) LiSPSM + logarithmic(4)"
plot "$T/llog" u 1:2 w l lw 2 t "m_x", "$T/llog" u 1:3 w l lw 2 t "m_z"
unset multiplot
GP
