// The HLSL driver of splits_glsl's cases: the GLSL driver of
// tests/cascade/splits_glsl.c (k_main) written in HLSL around
// shaders/splits.hlsl.  Built by meson: glslangValidator -D -V (SPIR-V),
// spirv-cross --version 450 (GLSL), then run by splits_glsl PATH.
#include "../../shaders/splits.hlsl"

[[vk::binding(0)]] StructuredBuffer<float> inp : register(t0);
[[vk::binding(1)]] RWStructuredBuffer<float> outp : register(u1);
[[vk::binding(2)]] StructuredBuffer<float> sc : register(t2);

float4x4 scene_mat(int base) {
    float4x4 m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[r][c] = sc[base + c * 4 + r];
    return m;
}

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint b = id.x * 24u, o = id.x * 8u;
    int kind = int(inp[b]);
    for (int k = 0; k < 8; ++k) outp[o + uint(k)] = 0.0;
    float splits[SWARP_SPLITS_MAX + 1];
    for (int i = 0; i <= SWARP_SPLITS_MAX; ++i) splits[i] = sc[i];
    int count = int(sc[17]);
    float2 res = float2(sc[18], sc[19]);
    bool zo = sc[20] > 0.5;
    float4x4 L[SWARP_SPLITS_MAX], Li[SWARP_SPLITS_MAX];
    for (int j = 0; j < SWARP_SPLITS_MAX; ++j) {
        L[j] = scene_mat(24 + 16 * j);
        Li[j] = scene_mat(24 + 16 * (SWARP_SPLITS_MAX + j));
    }
    if (kind == 0) {
        int bi;
        float w = swarp_cascade_blend(splits, count, inp[b + 1u], inp[b + 2u], bi);
        outp[o] = float(swarp_select_split_depth(splits, count, inp[b + 1u]));
        outp[o + 1u] = float(bi);
        outp[o + 2u] = w;
    } else if (kind == 1) {
        float3 p = float3(inp[b + 1u], inp[b + 2u], inp[b + 3u]);
        outp[o] = float(swarp_select_split_best(L, Li, count, res, zo, p, int(inp[b + 4u])));
    } else if (kind == 2) {
        int i = int(inp[b + 1u]);
        float3 p = float3(inp[b + 2u], inp[b + 3u], inp[b + 4u]), tl = float3(inp[b + 5u], inp[b + 6u], inp[b + 7u]);
        float3 n = float3(inp[b + 10u], inp[b + 11u], inp[b + 12u]);
        float3 q = swarp_bias_kozlov(L[i], Li[i], res, p, tl, inp[b + 8u], inp[b + 9u]);
        float3 r = swarp_bias_normal_offset(L[i], Li[i], res, p, n, tl, inp[b + 13u]);
        outp[o] = q.x - p.x;
        outp[o + 1u] = q.y - p.y;
        outp[o + 2u] = q.z - p.z;
        outp[o + 3u] = r.x - p.x;
        outp[o + 4u] = r.y - p.y;
        outp[o + 5u] = r.z - p.z;
        outp[o + 6u] = swarp_texel_world(L[i], Li[i], res, p);
    } else if (kind == 3) {
        float2 g = swarp_receiver_plane_gradient(float3(inp[b + 1u], inp[b + 2u], inp[b + 3u]),
                                                 float3(inp[b + 4u], inp[b + 5u], inp[b + 6u]));
        outp[o] = g.x;
        outp[o + 1u] = g.y;
    }
}
