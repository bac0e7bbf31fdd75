#!/bin/sh
# Regenerates docs/img/splits_stabilize.png: texel coordinates of a fixed
# world point while the camera walks and turns, with and without
# stabilisation ([RHS] §3.5).  Run from the repository root after a build:
#   docs/plots/splits_stabilize.sh [builddir]
set -eu
B=${1:-build}
D=$(mktemp)
trap 'rm -f "$D"' EXIT
"$B/examples/swtool/swtool" stabwalk --steps 300 --map 1024 --speed 0.01 --turn 0.03 > "$D"
gnuplot <<GP
set terminal pngcairo size 1000,760 font "sans,11"
set output "docs/img/splits_stabilize.png"
stats "$D" u 2 every ::0::0 nooutput
s0n = STATS_min
stats "$D" u 4 every ::0::0 nooutput
s0s = STATS_min
stats "$D" u 6 every ::0::0 nooutput
s0l = STATS_min
frac(x) = x - floor(x)
set multiplot layout 2,1 title "Texel coordinate s of a fixed world point while the camera walks and turns (1024^2 map)"
set grid
set key left top
set xlabel "frame"
set ylabel "s - s(frame 0)  [texels]"
plot "$D" u 1:(\$2-s0n) w l lw 2 t "no stabilisation", \
     "$D" u 1:(\$4-s0s) w steps lw 2 t "exact (minimal sphere + snap)", \
     "$D" u 1:(\$6-s0l) w steps lw 2 dt 2 t "approximate (64 levels + snap)"
set ylabel "fractional part of s  [texels]"
set key top right opaque box
set yrange [-0.05:1.05]
plot "$D" u 1:(frac(\$2)) w p pt 7 ps 0.4 t "no stabilisation", \
     "$D" u 1:(frac(\$4)) w l lw 2 t "exact", \
     "$D" u 1:(frac(\$6)) w l lw 2 dt 2 t "approximate (jumps only when the level changes)"
unset multiplot
GP
