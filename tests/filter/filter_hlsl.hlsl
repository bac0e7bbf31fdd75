// The HLSL driver of filter_glsl's cases: the GLSL driver of
// tests/filter/filter_glsl.c (k_main) written in HLSL around
// shaders/filtering.hlsl.  Built by meson: glslangValidator -D -V (SPIR-V),
// spirv-cross --version 450 (GLSL), then run by filter_glsl PATH.
#include "../../shaders/filtering.hlsl"

[[vk::binding(0)]] StructuredBuffer<float> inp : register(t0);
[[vk::binding(1)]] RWStructuredBuffer<float> outp : register(u1);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint b = id.x * 32u, o = id.x * 8u;
    int kind = int(inp[b]);
    for (int k = 0; k < 8; ++k) outp[o + uint(k)] = 0.0;
    if (kind == 0) {
        float p = vsm_chebyshev(float2(inp[b + 1u], inp[b + 2u]), inp[b + 3u], inp[b + 4u]);
        outp[o] = p;
        outp[o + 1u] = vsm_reduce_bleeding(p, inp[b + 5u]);
        float2 m = vsm_moments(inp[b + 3u]);
        outp[o + 2u] = m.x;
        outp[o + 3u] = m.y;
    } else if (kind == 1) {
        float2 pq = float2(inp[b + 2u], inp[b + 3u]);
        outp[o] = lvsm_warp(inp[b + 1u], pq);
        float2 m = lvsm_moments(inp[b + 1u], pq);
        outp[o + 1u] = m.x;
        outp[o + 2u] = m.y;
    } else if (kind == 2 || kind == 3) {
        int n = int(inp[b + 1u]);
        float s[LVSM_MAX_LAYERS + 1];
        for (int i = 0; i <= LVSM_MAX_LAYERS; ++i) s[i] = (i <= n) ? inp[b + 6u + uint(i)] : 0.0;
        float t = inp[b + 4u];
        if (kind == 2) {
            outp[o] = float(lvsm_layer_find(s, n, t));
            outp[o + 1u] = float(lvsm_layer_uniform(t, s[0], s[n], n));
            float2 pq = lvsm_interval(s, n, int(inp[b + 5u]), inp[b + 2u]);
            outp[o + 2u] = pq.x;
            outp[o + 3u] = pq.y;
        } else {
            float2 lm[LVSM_MAX_LAYERS];
            for (int i = 0; i < LVSM_MAX_LAYERS; ++i)
                lm[i] = (i < n) ? float2(inp[b + 15u + 2u * uint(i)], inp[b + 16u + 2u * uint(i)]) : float2(0.0, 0.0);
            outp[o] = lvsm_visibility(lm, s, n, inp[b + 2u], inp[b + 3u], t, inp[b + 5u]);
        }
    } else if (kind == 4) {
        float2 r = lloyd_sample(float2(inp[b + 1u], inp[b + 2u]), inp[b + 3u], inp[b + 4u]);
        outp[o] = r.x;
        outp[o + 1u] = r.y;
    } else if (kind == 5) {
        float4 m = evsm_moments(inp[b + 1u], inp[b + 2u], inp[b + 3u]);
        outp[o] = m.x;
        outp[o + 1u] = m.y;
        outp[o + 2u] = m.z;
        outp[o + 3u] = m.w;
        float4 fm = float4(inp[b + 6u], inp[b + 7u], inp[b + 8u], inp[b + 9u]);
        outp[o + 4u] = evsm_visibility(fm, inp[b + 4u], inp[b + 2u], inp[b + 3u], inp[b + 5u]);
    } else if (kind == 6) {
        float4 m = msm_moments(inp[b + 1u]);
        outp[o] = m.x;
        outp[o + 1u] = m.y;
        outp[o + 2u] = m.z;
        outp[o + 3u] = m.w;
        float4 bb = msm_bias(float4(inp[b + 4u], inp[b + 5u], inp[b + 6u], inp[b + 7u]), inp[b + 2u]);
        outp[o + 4u] = msm_visibility(bb, inp[b + 3u]);
        outp[o + 5u] = bb.x;
        outp[o + 6u] = bb.w;
    } else if (kind == 7) {
        outp[o] = pcss_search_width(inp[b + 1u], inp[b + 2u], inp[b + 3u]);
        outp[o + 1u] = pcss_penumbra(inp[b + 3u], inp[b + 4u], inp[b + 1u]);
        outp[o + 2u] = pcss_filter_width(pcss_penumbra(inp[b + 3u], inp[b + 4u], inp[b + 1u]), inp[b + 2u], inp[b + 3u]);
    }
}
