#!/bin/sh
# Regenerates docs/accuracy-cost.md, docs/plots/accuracy-cost*.dat and
# docs/img/pareto.png from `swtool bench-report` (one command: run from the
# repository root after building, e.g. `ninja -C build`).
#   sh docs/plots/regen_accuracy_cost.sh [build-dir] [reps]
set -eu
cd "$(dirname "$0")/../.."
BUILD="${1:-build}"
REPS="${2:-2000}"
SWTOOL="$BUILD/examples/swtool/swtool"
[ -x "$SWTOOL" ] || { echo "regen_accuracy_cost: build swtool first ($SWTOOL)" >&2; exit 1; }
mkdir -p docs/img docs/plots
"$SWTOOL" bench-report --reps "$REPS" --out-dir docs
gnuplot <<'GP'
set terminal pngcairo size 1500,1200 font "DejaVu Sans,10"
set output 'docs/img/pareto.png'
set multiplot layout 3,3 title "Predicted max error vs predicted shadow time (f/n = 1000, map 2048, screen 1024x768, Θ = 30°)\nerror = max(m_x, m_z), Lloyd's metric generalised to γ (docs/planning.md); time = shadow passes × 1.39 ms ([RHS] Table 7.1 fit); line: Pareto front"
set logscale y
set xlabel "predicted shadow time [ms]"
set ylabel "max pixels per texel"
set grid
set key top right font ",8"
set xrange [0:24]
set yrange [0.3:*]
gammas = "90 60 45 30 20 10 5 0 150"
do for [i=0:8] {
  set title sprintf("γ = %s°", word(gammas, i+1))
  plot 'docs/plots/accuracy-cost.dat' index i using 1:($3==1?$2:1/0) with points pt 7 ps 1.2 lc rgb "#d62728" title "one map (uniform, LiSPSM, PSM)", \
       '' index i using 1:($3==2?$2:1/0) with points pt 5 ps 1.0 lc rgb "#1f77b4" title "PSSM", \
       '' index i using 1:($3==3?$2:1/0) with points pt 4 ps 1.3 lc rgb "#17becf" title "PSSM stabilised", \
       '' index i using 1:($3==4?$2:1/0) with points pt 9 ps 1.3 lc rgb "#2ca02c" title "PSSM + n_opt", \
       '' index i using 1:($3==7?$2:1/0) with points pt 13 ps 1.2 lc rgb "#9467bd" title "PSSM log", \
       '' index i using 1:($3==8?$2:1/0) with points pt 11 ps 1.3 lc rgb "#ff7f0e" title "PSSM log + n_opt", \
       '' index i using 1:($3==6?$2:1/0) with points pt 3 ps 2.5 lw 2 lc rgb "#000000" title "planner (E = 1)", \
       'docs/plots/accuracy-cost-front.dat' index i using 1:2 with lines lw 1.5 lc rgb "#555555" title "Pareto front", \
       1 with lines dt 2 lc rgb "#000000" title "1 pixel per texel"
}
unset multiplot
GP
echo "regen_accuracy_cost: wrote docs/accuracy-cost.md, docs/plots/accuracy-cost*.dat, docs/img/pareto.png"
