#!/bin/sh
# Regenerates the before/after sampling-rate pictures of docs/before-after.md
# (docs/img/before_after_*.png) and prints the measured maximum σ of each map
# (the library's swarp_measure_max over H with bisector receivers, as the demo
# reports it).  Run from the repository root after building:
#   sh docs/plots/before_after.sh [build-dir]
# "before": LiSPSM with the closed-form n_opt and the view-aligned light basis
# of swarp_focus_light_view (--nprime closed --basis aligned); "n_opt": the
# closed form in the library's basis; "after": the library's default
# (--nprime measured: the measured n', the minimum-area basis near parallel
# light).  The sun at γ = 5° and 150° to the view direction (--light-gamma).
set -eu
B=${1:-build}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
printf '| γ | map | n'"'"' (eye units) | max σ over the picture'"'"'s lit receiver pixels | max σ over H (the library'"'"'s measurement) |\n|---|---|---|---|---|\n'
for g in 5 150; do
    for k in before nopt after; do
        case $k in
        before) a="--nprime closed --basis aligned" ;;
        nopt) a="--nprime closed --basis library" ;;
        after) a="--nprime measured --basis library" ;;
        esac
        # shellcheck disable=SC2086
        "$B/examples/demo/demo" --technique lispsm --camera default --light-gamma "$g" $a \
            --size 480x270 --map 1024 --out "$T/$g$k" >"$T/$g$k.txt"
        cp "$T/$g$k/lispsm_sampling.png" "docs/img/before_after_g${g}_$k.png"
        # the summary row: meas_sig (the render's pixels) and H_sig (the library's over H)
        n=$(sed -n "s/^    n' \([^ ]*\) (eye units.*/\1/p" "$T/$g$k.txt")
        awk -v g="$g" -v k="$k" -v n="$n" '$1 == "lispsm" && NF >= 12 && $2 ~ /^[0-9.]+$/ {
            printf "| %s° | %s | %s | %s | %s |\n", g, k, n, $7, $10 }' "$T/$g$k.txt"
    done
done
