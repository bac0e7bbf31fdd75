// splits.glsl -- GLSL twins of the splits stage of libshadowwarp.
// C references: swarp_cascade_select_depth, swarp_cascade_select_best,
// swarp_cascade_blend, swarp_bias_texel_size, swarp_bias_kozlov,
// swarp_bias_normal_offset, swarp_bias_receiver_plane ([RHS] §3.3.3,
// [KOZ] §14.2.3).  tests/cascade/splits_glsl.c compiles this file with OSMesa and
// compares every function with the C library on seeded random cases.
// No #version line: prepend the one your shaders use (tested as 450 core).
//
// Conventions: splits[0..count] are the eye-space split distances C_0..C_m
// (swarp_cascade_result.splits); light[i] is split i's world -> clip matrix
// (swarp_cascade_split.matrix), light_inv[i] its inverse; res the map
// resolution in texels; zero_to_one selects a [0, 1] clip depth range: pass
// true for SWARP_DEPTH_ZERO_TO_ONE and for SWARP_DEPTH_REVERSED_ZERO_TO_ONE
// alike (reversed-Z keeps clip z in [0, w], near plane at z = w), false for
// [-1, 1].  Nothing else here depends on the depth convention: the
// receiver-plane gradient is that of whatever depth sc.z holds (negated
// under reversed-Z, as swarp_bias_receiver_plane's).

#ifndef SWARP_SPLITS_MAX
#define SWARP_SPLITS_MAX 16
#endif

// By eye depth (PSSM): the i with C_i <= z < C_{i+1}, clamped to [0, count-1].
int swarp_select_split_depth(float splits[SWARP_SPLITS_MAX + 1], int count, float view_depth) {
    int i = 0;
    while (i + 1 < count && view_depth >= splits[i + 1]) ++i;
    return i;
}

// Weight of split i (written to `i`) in the transition band: the last `band`
// fraction of each split's range fades linearly into the next split.
// shadow = mix(shadow_of(i + 1), shadow_of(i), w).
float swarp_cascade_blend(float splits[SWARP_SPLITS_MAX + 1], int count, float view_depth,
                          float band, out int i) {
    i = swarp_select_split_depth(splits, count, view_depth);
    if (i + 1 >= count || band <= 0.0) return 1.0;
    float border = splits[i + 1];
    return clamp((border - view_depth) / (band * (border - splits[i])), 0.0, 1.0);
}

// Does the split map cover the world point?  (h = light * vec4(p, 1))
bool swarp_split_covers(vec4 h, bool zero_to_one) {
    float zlo = zero_to_one ? 0.0 : -h.w;
    return h.w > 0.0 && abs(h.x) <= h.w && abs(h.y) <= h.w && h.z >= zlo && h.z <= h.w;
}

// World size of the texel at p [KOZ] §14.2.3: one texel along s and along t
// at constant depth, mapped back; the larger displacement.  Exact for warped
// maps at any point.
float swarp_texel_world(mat4 light, mat4 light_inv, vec2 res, vec3 p) {
    vec4 h = light * vec4(p, 1.0);
    vec3 ndc = h.xyz / h.w;
    vec4 qs = light_inv * vec4(ndc.x + 2.0 / res.x, ndc.y, ndc.z, 1.0);
    vec4 qt = light_inv * vec4(ndc.x, ndc.y + 2.0 / res.y, ndc.z, 1.0);
    return max(length(qs.xyz / qs.w - p), length(qt.xyz / qt.w - p));
}

// By best resolution (ZZB09): the covering split with the smallest texel at
// p; `fallback` (e.g. the depth selection) when none covers p.
int swarp_select_split_best(mat4 light[SWARP_SPLITS_MAX], mat4 light_inv[SWARP_SPLITS_MAX],
                            int count, vec2 res, bool zero_to_one, vec3 p, int fallback) {
    int best = fallback;
    float best_L = 3.4e38;
    for (int i = 0; i < count; ++i) {
        vec4 h = light[i] * vec4(p, 1.0);
        if (!swarp_split_covers(h, zero_to_one)) continue;
        float L = swarp_texel_world(light[i], light_inv[i], res, p);
        if (L < best_L) {
            best_L = L;
            best = i;
        }
    }
    return best;
}

// [KOZ] §14.2.3: P + L (a + b L_texel), L the unit vector toward the light.
vec3 swarp_bias_kozlov(mat4 light, mat4 light_inv, vec2 res, vec3 p, vec3 to_light, float a, float b) {
    return p + to_light * (a + b * swarp_texel_world(light, light_inv, res, p));
}

// Normal offset: P + N k L_texel (1 - N.L), N.L clamped to [0, 1].
vec3 swarp_bias_normal_offset(mat4 light, mat4 light_inv, vec2 res, vec3 p, vec3 n, vec3 to_light,
                              float k) {
    float ndl = clamp(dot(n, to_light), 0.0, 1.0);
    return p + n * (k * swarp_texel_world(light, light_inv, res, p) * (1.0 - ndl));
}

// Receiver-plane depth bias: (dd/ds, dd/dt) from the screen derivatives of
// the shadow coordinate sc = (s, t, d) in texels, texels, window depth:
// call with dFdx(sc), dFdy(sc).  A PCF tap at offset o (texels) compares
// against sc.z + dot(gradient, o).
vec2 swarp_receiver_plane_gradient(vec3 dx, vec3 dy) {
    float det = dx.x * dy.y - dy.x * dx.y;
    return vec2(dx.z * dy.y - dy.z * dx.y, dx.x * dy.z - dy.x * dx.z) / det;
}
