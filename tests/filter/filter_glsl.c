/* filter_glsl: compiles shaders/filtering.glsl (the GLSL twins of the
 * filter stage) with OSMesa and evaluates every texture-free function in a
 * compute shader on seeded random cases; compares with the C library.
 *
 * The inputs are rounded to float first and the C library evaluates exactly
 * those float values in double, so a difference is the shader's float
 * arithmetic (or a bug in the twin).  Tolerances: see check_case().
 * Exit 0 = pass, 1 = mismatch or GLSL error, 77 = skipped (no GL 4.3+
 * context: compute shaders need it).
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_harness.h"
#include "shadowwarp.h"
#include "test_util.h"

#ifndef FILTER_GLSL_PATH
#error "FILTER_GLSL_PATH must name shaders/filtering.glsl"
#endif

#define REC_IN 32
#define REC_OUT 8
#define N_CASES 4096

/* The driver: one invocation per case, kind in in[0]. */
static const char* k_main =
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer In { float inp[]; };\n"
    "layout(std430, binding = 1) writeonly buffer Out { float outp[]; };\n"
    "void main() {\n"
    "  uint b = gl_GlobalInvocationID.x * 32u, o = gl_GlobalInvocationID.x * 8u;\n"
    "  int kind = int(inp[b]);\n"
    "  for (int k = 0; k < 8; ++k) outp[o + uint(k)] = 0.0;\n"
    "  if (kind == 0) {\n"
    "    float p = vsm_chebyshev(vec2(inp[b+1u], inp[b+2u]), inp[b+3u], inp[b+4u]);\n"
    "    outp[o] = p; outp[o+1u] = vsm_reduce_bleeding(p, inp[b+5u]);\n"
    "    vec2 m = vsm_moments(inp[b+3u]); outp[o+2u] = m.x; outp[o+3u] = m.y;\n"
    "  } else if (kind == 1) {\n"
    "    vec2 pq = vec2(inp[b+2u], inp[b+3u]);\n"
    "    outp[o] = lvsm_warp(inp[b+1u], pq); vec2 m = lvsm_moments(inp[b+1u], pq);\n"
    "    outp[o+1u] = m.x; outp[o+2u] = m.y;\n"
    "  } else if (kind == 2 || kind == 3) {\n"
    "    int n = int(inp[b+1u]);\n"
    "    float s[LVSM_MAX_LAYERS + 1];\n"
    "    for (int i = 0; i <= LVSM_MAX_LAYERS; ++i) s[i] = (i <= n) ? inp[b+6u+uint(i)] : 0.0;\n"
    "    float t = inp[b+4u];\n"
    "    if (kind == 2) {\n"
    "      outp[o] = float(lvsm_layer_find(s, n, t));\n"
    "      outp[o+1u] = float(lvsm_layer_uniform(t, s[0], s[n], n));\n"
    "      vec2 pq = lvsm_interval(s, n, int(inp[b+5u]), inp[b+2u]); outp[o+2u] = pq.x; outp[o+3u] = pq.y;\n"
    "    } else {\n"
    "      vec2 lm[LVSM_MAX_LAYERS];\n"
    "      for (int i = 0; i < LVSM_MAX_LAYERS; ++i) lm[i] = (i < n) ? vec2(inp[b+15u+2u*uint(i)], inp[b+16u+2u*uint(i)]) : vec2(0.0);\n"
    "      outp[o] = lvsm_visibility(lm, s, n, inp[b+2u], inp[b+3u], t, inp[b+5u]);\n"
    "    }\n"
    "  } else if (kind == 4) {\n"
    "    vec2 r = lloyd_sample(vec2(inp[b+1u], inp[b+2u]), inp[b+3u], inp[b+4u]);\n"
    "    outp[o] = r.x; outp[o+1u] = r.y;\n"
    "  } else if (kind == 5) {\n"
    "    vec4 m = evsm_moments(inp[b+1u], inp[b+2u], inp[b+3u]);\n"
    "    outp[o] = m.x; outp[o+1u] = m.y; outp[o+2u] = m.z; outp[o+3u] = m.w;\n"
    "    vec4 fm = vec4(inp[b+6u], inp[b+7u], inp[b+8u], inp[b+9u]);\n"
    "    outp[o+4u] = evsm_visibility(fm, inp[b+4u], inp[b+2u], inp[b+3u], inp[b+5u]);\n"
    "  } else if (kind == 6) {\n"
    "    vec4 m = msm_moments(inp[b+1u]);\n"
    "    outp[o] = m.x; outp[o+1u] = m.y; outp[o+2u] = m.z; outp[o+3u] = m.w;\n"
    "    vec4 bb = msm_bias(vec4(inp[b+4u], inp[b+5u], inp[b+6u], inp[b+7u]), inp[b+2u]);\n"
    "    outp[o+4u] = msm_visibility(bb, inp[b+3u]); outp[o+5u] = bb.x; outp[o+6u] = bb.w;\n"
    "  } else if (kind == 7) {\n"
    "    outp[o] = pcss_search_width(inp[b+1u], inp[b+2u], inp[b+3u]);\n"
    "    outp[o+1u] = pcss_penumbra(inp[b+3u], inp[b+4u], inp[b+1u]);\n"
    "    outp[o+2u] = pcss_filter_width(pcss_penumbra(inp[b+3u], inp[b+4u], inp[b+1u]), inp[b+2u], inp[b+3u]);\n"
    "  }\n"
    "}\n";

/* ---- cases -------------------------------------------------------------- */
static uint64_t rng = 2024;
static double urand(double lo, double hi) { return tu_uniform(&rng, lo, hi); }
static double fl(double x) { return (double)(float)x; } /* what the shader sees */

static float in_buf[N_CASES * REC_IN], out_buf[N_CASES * REC_OUT];

/* Random discrete distribution's averaged moments through f. */
static void dist_moments(int k, double* out, int nm, void (*f)(double, double*, const void*),
                         const void* ctx, double lo, double hi) {
    int n = 1 + (int)urand(0, 4.999);
    double W = 0;
    for (int j = 0; j < nm; ++j) out[j] = 0;
    for (int i = 0; i < n; ++i) {
        double x = urand(lo, hi), w = urand(0.1, 1.0), m[4];
        f(x, m, ctx);
        for (int j = 0; j < nm; ++j) out[j] += w * m[j];
        W += w;
    }
    for (int j = 0; j < nm; ++j) out[j] = fl(out[j] / W);
    (void)k;
}
static void f_vsm(double x, double* m, const void* c) { (void)c; swarp_vsm_moments(x, m); }
static void f_msm(double x, double* m, const void* c) { (void)c; swarp_msm_moments(x, m); }
static void f_evsm(double x, double* m, const void* c) {
    const double* cc = c;
    swarp_evsm_moments(x, cc[0], cc[1], m);
}

static void make_case(int i, double* in) {
    memset(in, 0, REC_IN * sizeof(double));
    int kind = i % 8;
    in[0] = kind;
    switch (kind) {
        case 0:
            dist_moments(i, in + 1, 2, f_vsm, NULL, 0.0, 1.0);
            in[3] = fl(urand(-0.1, 1.1));
            in[4] = fl((i & 8) ? 1e-4 : 1e-6);
            in[5] = fl(urand(0.0, 0.5));
            break;
        case 1:
            in[2] = fl(urand(0.0, 0.6));
            in[3] = fl(in[2] + urand(0.05, 0.4));
            in[1] = fl(urand(-0.1, 1.1));
            break;
        case 2:
        case 3: {
            int n = 1 + (int)urand(0, (kind == 2) ? 7.999 : 3.999);
            in[1] = n;
            double s = 0.0;
            for (int j = 0; j <= n; ++j) {
                in[6 + j] = fl(s);
                s += (kind == 2 && (i & 16)) ? 1.0 / n : urand(0.1, 0.4);
            }
            if (kind == 2 && (i & 16))
                for (int j = 0; j <= n; ++j) in[6 + j] = fl(j / (double)n);
            double thin = 1e9;
            for (int j = 0; j < n; ++j) thin = fmin(thin, in[7 + j] - in[6 + j]);
            in[2] = fl(urand(0.0, 0.4) * thin);           /* delta */
            in[3] = fl(urand(0.0, 0.9) * fmin(in[2], 0.49 * thin)); /* band <= delta */
            /* t away from the splits by 1e-4 so float and double agree on the layer */
            double t;
            int tries = 0;
            do {
                t = fl(urand(in[6] - 0.05, in[6 + n] + 0.05));
                int near = 0;
                for (int j = 0; j <= n; ++j)
                    if (fabs(t - in[6 + j]) < 1e-4 || fabs(fabs(t - in[6 + j]) - in[3]) < 1e-4) near = 1;
                if (!near) break;
            } while (++tries < 100);
            in[4] = t;
            in[5] = (kind == 2) ? (double)(int)urand(0, n - 0.001) : fl(1e-6);
            if (kind == 3) {
                double lm[8];
                for (int j = 0; j < n; ++j) {
                    double p, q;
                    double sp[9];
                    for (int m = 0; m <= n; ++m) sp[m] = in[6 + m];
                    swarp_lvsm_layer_interval(sp, (uint32_t)n, (uint32_t)j, in[2], &p, &q);
                    /* a distribution in [s_0, s_N]: 1-5 depths, warped */
                    int nd = 1 + (int)urand(0, 4.999);
                    double W = 0, m1 = 0, m2 = 0;
                    for (int d = 0; d < nd; ++d) {
                        double x = urand(in[6], in[6 + n]), w = urand(0.1, 1.0), mm[2];
                        swarp_lvsm_moments(x, p, q, mm);
                        m1 += w * mm[0];
                        m2 += w * mm[1];
                        W += w;
                    }
                    lm[2 * j] = fl(m1 / W);
                    lm[2 * j + 1] = fl(m2 / W);
                }
                for (int j = 0; j < 2 * n; ++j) in[15 + j] = lm[j];
            }
            break;
        }
        case 4: {
            double M[2];
            dist_moments(i, M, 2, f_vsm, NULL, 0.0, 1.0);
            in[1] = M[0];
            in[2] = M[1];
            in[3] = fl((i & 8) ? 1e-3 : 0.0);
            in[4] = fl((i & 16) ? 2e-2 : 0.0);
            break;
        }
        case 5: {
            double c[2] = {fl(urand(1.0, 30.0)), fl(urand(1.0, 5.54))};
            in[1] = fl(urand(0.0, 1.0));
            in[2] = c[0];
            in[3] = c[1];
            in[4] = fl(urand(0.0, 1.0));
            in[5] = fl(1e-6);
            dist_moments(i, in + 6, 4, f_evsm, c, 0.0, 1.0);
            break;
        }
        case 6: {
            in[1] = fl(urand(0.0, 1.0));
            in[2] = fl(SWARP_MSM_ALPHA_DEFAULT);
            in[3] = fl(urand(0.0, 1.0));
            dist_moments(i, in + 4, 4, f_msm, NULL, 0.0, 1.0);
            break;
        }
        case 7:
            in[1] = fl(urand(0.01, 2.0));
            in[2] = fl(urand(0.1, 1.0));
            in[3] = fl(urand(in[2], 20.0));
            in[4] = fl(urand(0.5 * in[3], in[3]));
            break;
    }
}

static double max_err[8][8];

/* Compares one case; returns 0 on mismatch.  Tolerances (fp32 shader vs
 * double reference on the same float inputs, u = 2^-24):
 *  - closed forms without cancellation (moments, warps, widths, mu + sigma,
 *    weights): 16 u relative (+ tiny absolute for values near 0);
 *  - Chebyshev values (VSM, LVSM, EVSM): the shader's M_2 - M_1^2 loses
 *    ~2 u M_2 / sigma^2 relative, so 1e-6 + 64 u M_2 / sigma^2 absolute,
 *    with sigma^2 floored by the variance floor (what bounds the conditioning);
 *  - MSM: the Hankel solve in float is ill-conditioned (the reason for the
 *    bias) and has no simple a-priori bound; with the default bias the float
 *    answer was measured within 7.2e-4 of the double one on these cases, and
 *    5e-3 is asserted (a wrong formula is off by O(0.1..1));
 *  - layer indices: exact (t is kept 1e-4 away from splits and band edges). */
static int check_case(int i, const double* in, const float* out) {
    const double u = 0x1.0p-24;
    int kind = (int)in[0];
    double e[8];
    int ne = 0;
    double tol[8];
#define REL(x) (16 * u * fabs((double)(x)) + 1e-30)
    switch (kind) {
        case 0: {
            double M[2] = {in[1], in[2]}, p, r;
            swarp_vsm_chebyshev(M, in[3], in[4], &p);
            swarp_vsm_reduce_bleeding(p, in[5], &r);
            double s2 = fmax(M[1] - M[0] * M[0], in[4]);
            double ct = 1e-6 + 64 * u * M[1] / s2;
            e[0] = fabs(out[0] - p); tol[0] = ct;
            e[1] = fabs(out[1] - r); tol[1] = ct / (1 - in[5]);
            e[2] = fabs(out[2] - in[3]); tol[2] = 0;
            e[3] = fabs(out[3] - in[3] * in[3]); tol[3] = REL(in[3] * in[3]);
            ne = 4;
            break;
        }
        case 1: {
            double w, m[2];
            swarp_lvsm_warp(in[1], in[2], in[3], &w);
            swarp_lvsm_moments(in[1], in[2], in[3], m);
            e[0] = fabs(out[0] - w); tol[0] = REL(1) * 4;
            e[1] = fabs(out[1] - m[0]); tol[1] = REL(1) * 4;
            e[2] = fabs(out[2] - m[1]); tol[2] = REL(1) * 8;
            ne = 3;
            break;
        }
        case 2: {
            uint32_t n = (uint32_t)in[1], lf, lu;
            double sp[9];
            for (uint32_t j = 0; j <= n; ++j) sp[j] = in[6 + j];
            swarp_lvsm_layer_find(in[4], sp, n, &lf);
            e[0] = fabs(out[0] - lf); tol[0] = 0;
            ne = 1;
            int uniform = (i & 16) != 0;
            if (uniform) {
                swarp_lvsm_layer_uniform(in[4], sp[0], sp[n], n, &lu);
                e[1] = fabs(out[1] - lu); tol[1] = 0;
                ne = 2;
            }
            double p, q;
            swarp_lvsm_layer_interval(sp, n, (uint32_t)in[5], in[2], &p, &q);
            e[ne] = fabs(out[2] - p); tol[ne++] = REL(p) + 4 * u;
            e[ne] = fabs(out[3] - q); tol[ne++] = REL(q) + 4 * u;
            break;
        }
        case 3: {
            uint32_t n = (uint32_t)in[1];
            double sp[9], lm[8], v;
            for (uint32_t j = 0; j <= n; ++j) sp[j] = in[6 + j];
            for (uint32_t j = 0; j < 2 * n; ++j) lm[j] = in[15 + j];
            swarp_lvsm_visibility(lm, sp, n, in[2], in[3], in[4], in[5], &v);
            /* conditioning of the worst layer involved (all, to be simple) */
            double cond = 0;
            for (uint32_t j = 0; j < n; ++j) {
                double p, q;
                swarp_lvsm_layer_interval(sp, n, j, in[2], &p, &q);
                double s = 1 / (q - p);
                double s2 = fmax(lm[2 * j + 1] - lm[2 * j] * lm[2 * j], in[5] * s * s);
                cond = fmax(cond, lm[2 * j + 1] / s2);
            }
            e[0] = fabs(out[0] - v); tol[0] = 1e-5 + 64 * u * cond;
            ne = 1;
            break;
        }
        case 4: {
            double s2 = fmax(in[2] - in[1] * in[1], 0.0), x;
            swarp_lvsm_second_occluder(in[1], s2, &x);
            double w = fmax(s2, in[3]);
            if (in[4] > 0) w = fmin(w, in[4]);
            /* sqrt of a cancelled difference: 16 u M_2 / sigma absolute */
            e[0] = fabs(out[0] - x); tol[0] = REL(x) + 16 * u * in[2] / fmax(sqrt(s2), 1e-4);
            e[1] = fabs(out[1] - w); tol[1] = 16 * u * in[2] + 1e-12;
            ne = 2;
            break;
        }
        case 5: {
            double m[4], v;
            swarp_evsm_moments(in[1], in[2], in[3], m);
            for (int j = 0; j < 4; ++j) {
                /* exp in float: a few ulps of e^{c x}, and c x is itself rounded */
                e[j] = fabs(out[j] - m[j]);
                tol[j] = (64 * u * (1 + 2 * in[2] + 2 * in[3])) * fabs(m[j]);
            }
            double fm[4] = {in[6], in[7], in[8], in[9]};
            swarp_evsm_visibility(fm, in[4], in[2], in[3], in[5], &v);
            double wp = exp(in[2] * in[4]), wn = exp(-in[3] * in[4]);
            double s2p = fmax(fm[1] - fm[0] * fm[0], in[5] * pow(in[2] * wp, 2));
            double s2n = fmax(fm[3] - fm[2] * fm[2], in[5] * pow(in[3] * wn, 2));
            /* plus the warped receiver's own rounding: 64 u c relative in wp,
             * which moves t - mu by that much */
            double dtp = 64 * u * (1 + in[2]) * wp, dtn = 64 * u * (1 + in[3]) * wn;
            e[4] = fabs(out[4] - v);
            tol[4] = 1e-5 + 64 * u * fmax(fm[1] / s2p, fm[3] / s2n) + 2 * fmax(dtp / sqrt(s2p), dtn / sqrt(s2n));
            ne = 5;
            break;
        }
        case 6: {
            double m[4], bb[4], v;
            swarp_msm_moments(in[1], m);
            for (int j = 0; j < 4; ++j) {
                e[j] = fabs(out[j] - m[j]);
                tol[j] = REL(m[j]);
            }
            double b[4] = {in[4], in[5], in[6], in[7]};
            swarp_msm_bias(b, in[2], bb);
            swarp_msm_visibility(bb, in[3], &v);
            e[4] = fabs(out[4] - v); tol[4] = 5e-3;
            e[5] = fabs(out[5] - bb[0]); tol[5] = REL(1);
            e[6] = fabs(out[6] - bb[3]); tol[6] = REL(1);
            ne = 7;
            break;
        }
        case 7: {
            double ws, wp, wf;
            swarp_pcss_search_width(in[1], in[2], in[3], &ws);
            swarp_pcss_penumbra(in[3], in[4], in[1], &wp);
            swarp_pcss_filter_width(wp, in[2], in[3], &wf);
            e[0] = fabs(out[0] - ws); tol[0] = REL(in[1]) * 2;
            e[1] = fabs(out[1] - wp); tol[1] = REL(in[1] * in[3] / in[4]) * 2;
            e[2] = fabs(out[2] - wf); tol[2] = REL(in[1] * in[3] / in[4]) * 2;
            ne = 3;
            break;
        }
    }
    int ok = 1;
    for (int j = 0; j < ne; ++j) {
        if (e[j] > max_err[kind][j]) max_err[kind][j] = e[j];
        if (!(e[j] <= tol[j])) {
            fprintf(stderr, "filter_glsl: case %d kind %d output %d: |glsl - C| = %g > %g\n", i,
                    kind, j, e[j], tol[j]);
            ok = 0;
        }
    }
    return ok;
}

/* filter_glsl: shaders/filtering.glsl with the driver k_main.  filter_glsl
 * PATH: PATH is a whole compute shader, the HLSL twins
 * (shaders/filtering.hlsl) with their driver (filter_hlsl.hlsl) translated
 * HLSL -> SPIR-V -> GLSL, run on the same cases against the same C results
 * (the sampler part is compiled by glslang itself: test
 * filter_hlsl_samplers). */
int main(int argc, char** argv) {
    const int hlsl = argc > 1;
    const char* path = hlsl ? argv[1] : FILTER_GLSL_PATH;
    OSMesaContext ctx = glh_open(hlsl ? "filter_hlsl" : "filter_glsl");
    if (!ctx) return 77;
    char* lib = glh_read_file(path);
    if (!lib) {
        fprintf(stderr, "filter_glsl: cannot read %s\n", path);
        return 1;
    }
    int rc = 0;
    /* 1. the whole file, samplers included, must compile */
    const char* with_samplers[3] = {"#version 450 core\n#define FILTER_GLSL_WITH_SAMPLERS\n", lib,
                                    "layout(local_size_x = 1) in;\nvoid main() {}\n"};
    GLuint p0 = hlsl ? 1 : glh_compile("filter_glsl", with_samplers, 3, "filtering.glsl (with samplers)");
    if (!p0) rc = 1;
    else if (!hlsl) p_glDeleteProgram(p0);
    /* 2. evaluate the texture-free twins */
    const char* parts[3] = {"#version 450 core\n", lib, k_main};
    GLuint prog = hlsl ? glh_compile("filter_hlsl", (const char* const[]){lib}, 1, path)
                       : glh_compile("filter_glsl", parts, 3, "filtering.glsl + driver");
    if (!prog) {
        free(lib);
        OSMesaDestroyContext(ctx);
        return 1;
    }
    static double cases[N_CASES][REC_IN];
    for (int i = 0; i < N_CASES; ++i) {
        make_case(i, cases[i]);
        for (int j = 0; j < REC_IN; ++j) in_buf[i * REC_IN + j] = (float)cases[i][j];
    }
    GLuint buf[2];
    p_glGenBuffers(2, buf);
    glh_ssbo(buf[0], 0, sizeof in_buf, in_buf, GL_STATIC_DRAW);
    glh_ssbo(buf[1], 1, sizeof out_buf, NULL, GL_DYNAMIC_READ);
    glh_run(prog, N_CASES / 64, buf[1], sizeof out_buf, out_buf);
    int bad = 0;
    for (int i = 0; i < N_CASES; ++i)
        if (!check_case(i, cases[i], out_buf + i * REC_OUT)) ++bad;
    static const char* names[8] = {"vsm", "lvsm warp", "lvsm layer", "lvsm visibility",
                                   "lloyd sample", "evsm", "msm", "pcss"};
    for (int k = 0; k < 8; ++k) {
        printf("%-16s max |glsl - C| per output:", names[k]);
        for (int j = 0; j < 7; ++j) printf(" %.2e", max_err[k][j]);
        printf("\n");
    }
    printf("%d of %d cases outside tolerance\n", bad, N_CASES);
    p_glDeleteBuffers(2, buf);
    p_glDeleteProgram(prog);
    free(lib);
    glh_close(ctx);
    return (rc || bad) ? 1 : 0;
}
