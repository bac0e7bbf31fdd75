# Model (max of m_x, m_z, [RHS] (2.3)-(2.8)) against the measured maximum
# sigma of the returned matrix over H; driven by measured_vs_model.sh.
set terminal pngcairo size 900,700 font ",11"
set output outfile
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "measured: max sigma over H (screen pixels per texel step)"
set ylabel "predicted by the model: max(max m_x, max m_z)"
set key top left
set grid
set title "Lloyd's model against the measured error of the returned matrix (500 configurations)"
plot datafile using ($1==0 ? $3 : 1/0):2 with points pt 7 ps 0.5 lc rgb "#1b9e77" title "uniform", \
     datafile using ($1==1 ? $3 : 1/0):2 with points pt 7 ps 0.5 lc rgb "#d95f02" title "LiSPSM (n_{opt})", \
     datafile using ($1==2 ? $3 : 1/0):2 with points pt 7 ps 0.5 lc rgb "#7570b3" title "PSM", \
     x with lines lc rgb "black" dt 2 title "predicted = measured"
