// filtering.hlsl -- the HLSL twins of libshadowwarp's filter stage, the
// functions of filtering.glsl (beside it) line for line (src/filter/*.c,
// docs/filtering.md).  HLSL spells fma(a, b, c) for float as mad(a, b, c)
// (fused where the hardware fuses), mix as lerp; pcf_poisson takes a
// Texture2D and a SamplerComparisonState (define FILTER_HLSL_WITH_SAMPLERS).
// Tested for real: tests/filter/filter_hlsl.hlsl (the driver) is compiled
// with glslangValidator -D (HLSL -> SPIR-V), turned into GLSL by spirv-cross
// and run by tests/filter/filter_glsl.c against the C library like the GLSL
// file.
//
// Conventions as in the C API: t is the receiver depth, visibility is the lit
// fraction P(X >= t) of the filter region.

#ifndef LVSM_MAX_LAYERS
#define LVSM_MAX_LAYERS 8
#endif

// ---- VSM: [VSM] (3.1)-(3.4) ----------------------------------------------

float2 vsm_moments(float x) { return float2(x, x * x); }                  // (3.1)

// (3.2)-(3.3).  Written as 1 / (1 + (d/sigma)^2) so that no intermediate can
// overflow even for EVSM moments near the format's largest value: M_1^2 <= M_2
// always holds, and (d/sigma)^2 overflows only where the bound is 0 anyway.
float vsm_chebyshev(float2 M, float t, float min_variance) {
    if (t <= M.x) return 1.0;
    float sigma2 = max(mad(-M.x, M.x, M.y), min_variance);
    if (sigma2 <= 0.0) return 0.0;
    float r = (t - M.x) / sqrt(sigma2);
    return 1.0 / (1.0 + r * r);
}

float vsm_reduce_bleeding(float p, float amount) {                   // section 3.4
    return clamp((p - amount) / (1.0 - amount), 0.0, 1.0);
}

// ---- layered VSM: [VSM] (4.2), sections 4.1.1, 4.1.3 ----------------------
// splits[0..n] strictly increasing, n <= LVSM_MAX_LAYERS.

float2 lvsm_interval(float splits[LVSM_MAX_LAYERS + 1], int n, int i, float delta) {
    float p = (i == 0) ? splits[0] : splits[i] - delta;
    float q = (i == n - 1) ? splits[n] : splits[i + 1] + delta;
    return float2(p, q);
}

float lvsm_warp(float t, float2 pq) {                                   // (4.2)
    return clamp((t - pq.x) / (pq.y - pq.x), 0.0, 1.0);
}

float2 lvsm_moments(float t, float2 pq) {
    float f = lvsm_warp(t, pq);
    return float2(f, f * f);
}

int lvsm_layer_uniform(float t, float s_0, float s_n, int n) {
    float f = (t - s_0) / (s_n - s_0) * float(n);
    return clamp(int(floor(f)), 0, n - 1);
}

int lvsm_layer_find(float splits[LVSM_MAX_LAYERS + 1], int n, float t) {
    int lo = 0, hi = n;   // largest j with splits[j] <= t
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (splits[mid] <= t) lo = mid; else hi = mid;
    }
    return lo;
}

// Chebyshev on layer i's warped moments, variance floor scaled by the slope.
float lvsm_layer_vis(float2 M, float2 pq, float t, float min_variance) {
    float s = 1.0 / (pq.y - pq.x);
    return vsm_chebyshev(M, lvsm_warp(t, pq), min_variance * s * s);
}

// lm[i]: the filtered moments of layer i (in a shader: lvsm.Sample(s, float3(uv, i)).xy).
float lvsm_visibility(float2 lm[LVSM_MAX_LAYERS], float splits[LVSM_MAX_LAYERS + 1], int n,
                      float delta, float band, float t, float min_variance) {
    int j = (t < splits[0]) ? 0 : (t > splits[n] ? n - 1 : lvsm_layer_find(splits, n, t));
    int lo = j, hi = j;
    float w = 0.0;
    if (band > 0.0 && t >= splits[0] && t <= splits[n]) {
        if (j > 0 && t - splits[j] < band) {
            lo = j - 1;
            w = (t - (splits[j] - band)) / (2.0 * band);
        } else if (j + 1 < n && splits[j + 1] - t < band) {
            hi = j + 1;
            w = (t - (splits[j + 1] - band)) / (2.0 * band);
        }
        w = clamp(w, 0.0, 1.0);
    }
    float v = lvsm_layer_vis(lm[hi], lvsm_interval(splits, n, hi, delta), t, min_variance);
    if (lo != hi)
        v = lerp(lvsm_layer_vis(lm[lo], lvsm_interval(splits, n, lo, delta), t, min_variance), v, w);
    return clamp(v, 0.0, 1.0);
}

// Lloyd relaxation, shader half ([VSM] section 4.1.3): per 2x2-filtered
// unwarped VSM sample, the second-occluder estimate mu + sigma and its weight.
float2 lloyd_sample(float2 M, float w_lo, float w_hi) {
    float sigma2 = max(M.y - M.x * M.x, 0.0);
    float w = max(sigma2, w_lo);
    if (w_hi > 0.0) w = min(w, w_hi);
    return float2(M.x + sqrt(sigma2), w);
}

// ---- EVSM: [VSM] section 4.2 ---------------------------------------------
// c: swarp_evsm_max_exponent() for the texture format, passed as a uniform.

float4 evsm_moments(float x, float c_pos, float c_neg) {
    float p = exp(c_pos * x), n = -exp(-c_neg * x);
    return float4(p, p * p, n, n * n);
}

float evsm_visibility(float4 m, float t, float c_pos, float c_neg, float min_variance) {
    float wp = exp(c_pos * t), wn = -exp(-c_neg * t);
    float kp = c_pos * wp, kn = c_neg * wn;   // warp slopes at t map the floor
    float vp = vsm_chebyshev(m.xy, wp, min_variance * kp * kp);
    float vn = vsm_chebyshev(m.zw, wn, min_variance * kn * kn);
    return min(vp, vn);
}

// ---- MSM: Peters & Klein 2015, Algorithm 3 (Hamburger 4MSM) --------------
// Written from the maths (LDL^T of the Hankel matrix), not from their code.

float4 msm_moments(float z) { float z2 = z * z; return float4(z, z2, z2 * z, z2 * z2); }

float4 msm_bias(float4 b, float alpha) { return lerp(b, float4(0.5, 0.5, 0.5, 0.5), alpha); }

float msm_visibility(float4 b, float zf) {
    float D22 = mad(-b.x, b.x, b.y);
    float L32 = (b.z - b.x * b.y) / D22;
    float D33 = b.w - b.y * b.y - L32 * L32 * D22;
    float y2 = zf - b.x;                       // L y = (1, zf, zf^2)
    float y3 = zf * zf - b.y - L32 * y2;
    float c3 = y3 / D33;                       // then D and L^T
    float c2 = y2 / D22 - L32 * c3;
    float c1 = 1.0 - b.x * c2 - b.y * c3;
    float disc = sqrt(max(c2 * c2 - 4.0 * c3 * c1, 0.0));
    float q = -0.5 * (c2 + (c2 >= 0.0 ? disc : -disc));   // no cancellation
    float r1 = q / c3, r2 = c1 / q;
    float z2 = min(r1, r2), z3 = max(r1, r2);
    float G = (zf <= z2) ? 0.0
            : (zf <= z3) ? (zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2))
                         : 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3));
    return clamp(1.0 - G, 0.0, 1.0);
}

// ---- PCF and PCSS: [RHS] section 3.6 (Fernando 2005) -----------------------
// The Poisson disk comes from swarp_pcf_poisson_disk() as a uniform array.

float pcss_search_width(float w_light, float n_light, float d_r) { return w_light * (d_r - n_light) / d_r; }
float pcss_penumbra(float d_r, float d_b, float w_light) { return (d_r - d_b) * w_light / d_b; }
float pcss_filter_width(float w_penumbra, float n_light, float d_r) { return w_penumbra * n_light / d_r; }

#ifdef FILTER_HLSL_WITH_SAMPLERS
#ifndef PCF_MAX_SAMPLES
#define PCF_MAX_SAMPLES 64
#endif
float pcf_poisson(Texture2D sm, SamplerComparisonState cmp, float3 uvz, float radius,
                  float2 disk[PCF_MAX_SAMPLES], int count) {
    float lit = 0.0;
    for (int i = 0; i < count; ++i) lit += sm.SampleCmpLevelZero(cmp, uvz.xy + radius * disk[i], uvz.z);
    return lit / float(count);
}
#endif
