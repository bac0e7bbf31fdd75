# Visibility across a shadow edge with overlapping occluders (Fig. 3.4-like):
# PCF (reference), VSM, LVSM(4), EVSM and MSM.  Data from
# `filter_table plot` (tests/filter/filter_table.c); driven by filter_edge.sh.
# Usage: gnuplot -e "datafile='...'; outfile='...'" filter_edge.gp
set terminal pngcairo size 1100,800 font "sans,11"
set output outfile
set multiplot layout 2,1 title "Visibility across a shadow edge with overlapping occluders\nA (depth 0.1) covers x < 80 over B (0.7, x < 160) over the ground C (0.9); 25-texel box filter"
set key outside right
set yrange [-0.05:1.05]
set xrange [12:228]
set grid
set arrow 1 from 80, graph 0 to 80, graph 1 nohead dt 3 lc rgb "gray40"
set arrow 2 from 160, graph 0 to 160, graph 1 nohead dt 3 lc rgb "gray40"
set ylabel "visibility of B"
set title "receiver B (depth 0.7): A's shadow edge at x = 80"
plot datafile u 1:2 w l lw 6 lc rgb "gray60" t "PCF (reference)", \
     '' u 1:3 w l lw 2 lc rgb "#d62728" t "VSM", \
     '' u 1:4 w l lw 2 dt 2 lc rgb "#1f77b4" t "LVSM(4)", \
     '' u 1:5 w l lw 2 dt 4 lc rgb "#2ca02c" t "EVSM (fp32 c)", \
     '' u 1:6 w l lw 2 dt 5 lc rgb "#9467bd" t "MSM"
set ylabel "visibility of C"
set xlabel "x (texels)"
set title "receiver C (depth 0.9) under B: truth is 0 until B's edge at x = 160; VSM bleeds A's penumbra (eq. 3.4)"
plot datafile u 1:7 w l lw 6 lc rgb "gray60" t "PCF (reference)", \
     '' u 1:8 w l lw 2 lc rgb "#d62728" t "VSM", \
     '' u 1:9 w l lw 2 dt 2 lc rgb "#1f77b4" t "LVSM(4)", \
     '' u 1:10 w l lw 2 dt 4 lc rgb "#2ca02c" t "EVSM (fp32 c)", \
     '' u 1:11 w l lw 2 dt 5 lc rgb "#9467bd" t "MSM"
unset multiplot
