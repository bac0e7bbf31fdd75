#!/bin/sh
# hlsl_to_glsl.sh IN.hlsl OUT.comp: an HLSL compute shader (entry main) to
# SPIR-V with glslang's HLSL front end, then to GLSL 4.50 with spirv-cross,
# for the OSMesa tests that run the GLSL twins (shaders/*.hlsl beside them).
# -Od: glslang 12's optimised SPIR-V, through spirv-cross 2022 and Mesa
# llvmpipe, ran the second of two identical loops over a copied array wrong
# (splits_hlsl: 45 of 4096 cases of swarp_select_split_depth); unoptimised
# SPIR-V is exact.  Which of the three tools is at fault is not established;
# the shaders a driver compiles keep their own optimiser either way.
set -eu
spv="$2.spv"
glslangValidator -D -V -Od -S comp -e main -o "$spv" "$1" >/dev/null
spirv-cross --version 450 "$spv" --output "$2"
rm -f "$spv"
