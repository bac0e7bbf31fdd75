#!/bin/sh
# Regenerates the two plots of docs/parameters.md from CSV that swtool writes:
#   docs/img/rhs_fig2_8.png   [RHS] Fig. 2.8: m_x, m_z of uniform, LiSPSM, PSM (n = 1, f = 40)
#   docs/img/gmnpr_fig6.png   [GMNPR] Fig. 6: F of LiSPSM and GMNPR (n = 1, f = 100, phi = pi/6)
# Usage: sh docs/plots/regen_parameters.sh   (builds swtool into ./build if needed;
#        SWTOOL=/path/to/swtool overrides).  Needs gnuplot-nox.
set -eu
cd "$(dirname "$0")/../.."
SWTOOL=${SWTOOL:-build/examples/swtool/swtool}
if [ ! -x "$SWTOOL" ]; then
    [ -d build ] || meson setup build >/dev/null
    ninja -C build >/dev/null
fi
DATA=$(mktemp -d)
trap 'rm -rf "$DATA"' EXIT

# [RHS] Fig. 2.8: Theta = 30 deg, 1024x768 screen, 1024^2 map (swtool's defaults), overhead light
for t in uniform lispsm psm; do
    "$SWTOOL" curve --near 1 --far 40 --fovy 60 --gamma 90 --technique "$t" --samples 400 \
        > "$DATA/fig2_8_$t.csv"
done
# [GMNPR] Fig. 6: phi = pi/6 (fovy 60), theta above and below phi
for th in 90 70 50 35 25 15 5; do
    for t in lispsm gmnpr; do
        "$SWTOOL" curve --near 1 --far 100 --fovy 60 --gamma "$th" --technique "$t" --samples 400 \
            > "$DATA/fig6_${t}_$th.csv"
    done
done
gnuplot -e "data='$DATA'" docs/plots/parameters.gp
echo "wrote docs/img/rhs_fig2_8.png docs/img/gmnpr_fig6.png"
