// Compile check of shaders/filtering.hlsl with its sampler part
// (FILTER_HLSL_WITH_SAMPLERS): pcf_poisson called once, as a shader would.
#define FILTER_HLSL_WITH_SAMPLERS
#include "../../shaders/filtering.hlsl"

Texture2D shadow_map : register(t0);
SamplerComparisonState shadow_cmp : register(s0);
RWStructuredBuffer<float> result : register(u0);

[numthreads(1, 1, 1)]
void main() {
    float2 disk[PCF_MAX_SAMPLES];
    for (int i = 0; i < PCF_MAX_SAMPLES; ++i) disk[i] = float2(0.01 * i, -0.01 * i);
    result[0] = pcf_poisson(shadow_map, shadow_cmp, float3(0.5, 0.5, 0.3), 0.02, disk, 16);
}
