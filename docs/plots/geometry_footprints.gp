# The shadow map's footprint on the ground for three lights and two
# techniques (data from tests/geometry_plot_data.c).
#   gnuplot -e "datafile='...'; outfile='...'" docs/plots/geometry_footprints.gp
set terminal pngcairo size 1500,1000 font ",10"
set output outfile
set multiplot layout 2,3 title "Shadow-map texel grid on the ground (every 1/8 of the map), view frustum footprint (red), points of B (dots); camera at (0, 4, 0) looking along -z"
set size ratio -1
set xrange [-45:45]
set yrange [-65:8]
set xlabel "world x"
set ylabel "world z"
set key off
titles = "'uniform, overhead light' 'uniform, {/Symbol g} = 30 deg into the light' 'uniform, light 20 deg from behind the camera' 'LiSPSM n_{opt}, overhead light' 'LiSPSM n_{opt}, {/Symbol g} = 30 deg into the light' 'LiSPSM n_{opt}, light 20 deg from behind the camera'"
do for [p=0:5] {
  set title word(titles, p+1)
  plot datafile index p with lines lc rgb "#4060a0" lw 0.8, \
       datafile index 6+p with lines lc rgb "#d02020" lw 2, \
       datafile index 12+p with points pt 7 ps 0.6 lc rgb "#202020"
}
unset multiplot
