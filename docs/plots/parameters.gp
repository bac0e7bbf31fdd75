# gnuplot script for docs/plots/regen_parameters.sh (data = directory of swtool CSV)
set datafile separator ','
set key autotitle columnhead
set grid
set terminal pngcairo size 1200,480 font 'DejaVu Sans,11' noenhanced

# ---- [RHS] Fig. 2.8 --------------------------------------------------------
set output 'docs/img/rhs_fig2_8.png'
set multiplot layout 1,2 title "Lloyd's error model [RHS] (2.3)-(2.8): n = 1, f = 40, Theta = 30 deg, screen 1024x768, map 1024^2"
set xlabel 'view depth z'
set xrange [1:40]
set ylabel 'm_x'
set title 'm_x(z)  (x direction)'
plot data.'/fig2_8_uniform.csv' using 1:2 with lines lw 2 title "uniform (n' = inf)", \
     data.'/fig2_8_lispsm.csv'  using 1:2 with lines lw 2 title "LiSPSM (n' = n_opt)", \
     data.'/fig2_8_psm.csv'     using 1:2 with lines lw 2 title "PSM (n' = n)"
set ylabel 'm_z'
set title 'm_z(z)  (z direction)'
plot data.'/fig2_8_uniform.csv' using 1:3 with lines lw 2 title "uniform (n' = inf)", \
     data.'/fig2_8_lispsm.csv'  using 1:3 with lines lw 2 title "LiSPSM (n' = n_opt)", \
     data.'/fig2_8_psm.csv'     using 1:3 with lines lw 2 title "PSM (n' = n)"
unset multiplot

# ---- [GMNPR] Fig. 6 ---------------------------------------------------------
set terminal pngcairo size 1200,900 font 'DejaVu Sans,11' noenhanced
set output 'docs/img/gmnpr_fig6.png'
set multiplot layout 2,2 title "[GMNPR] aliasing function F(lambda, theta, z) of eq. (2): n = 1, f = 100, phi = pi/6"
set xrange [1:100]
set xlabel 'view depth z'
set key top center
set ylabel 'F'
set title 'LiSPSM, lambda of eq. (9), theta >= phi'
plot for [th in "90 70 50 35"] data.'/fig6_lispsm_'.th.'.csv' using 1:5 with lines lw 2 title 'theta = '.th.' deg'
set logscale y
set ylabel 'F (log scale)'
set title 'LiSPSM, theta < phi'
plot for [th in "25 15 5"] data.'/fig6_lispsm_'.th.'.csv' using 1:5 with lines lw 2 title 'theta = '.th.' deg'
unset logscale y
set ylabel 'F'
set title 'GMNPR, lambda of eq. (8), theta >= phi: F(n) = F(f)'
plot for [th in "90 70 50 35"] data.'/fig6_gmnpr_'.th.'.csv' using 1:5 with lines lw 2 title 'theta = '.th.' deg'
set logscale y
set ylabel 'F (log scale)'
set title 'GMNPR, lambda_2* of eq. (7), theta < phi'
plot for [th in "25 15 5"] data.'/fig6_gmnpr_'.th.'.csv' using 1:5 with lines lw 2 title 'theta = '.th.' deg'
unset multiplot
