/* splits_glsl: compiles shaders/splits.glsl (the GLSL twins of the
 * splits stage) with OSMesa and evaluates every function in a compute shader
 * on seeded random cases against one real cascade from swarp_cascade_setup
 * (4 splits, LiSPSM, light partly from behind so maps overlap); compares
 * with the C library evaluated on the same float-rounded inputs.
 * Exit 0 = pass, 1 = mismatch or GLSL error, 77 = skipped (no GL 4.3+). */
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

#ifndef SPLITS_GLSL_PATH
#error "SPLITS_GLSL_PATH must name shaders/splits.glsl"
#endif

#define REC_IN 24
#define REC_OUT 8
#define N_CASES 4096
#define K 4
#define SCENE_FLOATS (24 + 2 * 16 * SWARP_CASCADE_MAX_SPLITS)

/* The driver: one invocation per case, kind in inp[b]. */
static const char* k_main =
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer In { float inp[]; };\n"
    "layout(std430, binding = 1) writeonly buffer Out { float outp[]; };\n"
    "layout(std430, binding = 2) readonly buffer Scene { float sc[]; };\n"
    "mat4 scene_mat(int base) {\n"
    "  mat4 m; for (int c = 0; c < 4; ++c) for (int r = 0; r < 4; ++r) m[c][r] = sc[base + c * 4 + r];\n"
    "  return m;\n"
    "}\n"
    "void main() {\n"
    "  uint b = gl_GlobalInvocationID.x * 24u, o = gl_GlobalInvocationID.x * 8u;\n"
    "  int kind = int(inp[b]);\n"
    "  for (int k = 0; k < 8; ++k) outp[o + uint(k)] = 0.0;\n"
    "  float splits[SWARP_SPLITS_MAX + 1];\n"
    "  for (int i = 0; i <= SWARP_SPLITS_MAX; ++i) splits[i] = sc[i];\n"
    "  int count = int(sc[17]); vec2 res = vec2(sc[18], sc[19]); bool zo = sc[20] > 0.5;\n"
    "  mat4 L[SWARP_SPLITS_MAX], Li[SWARP_SPLITS_MAX];\n"
    "  for (int i = 0; i < SWARP_SPLITS_MAX; ++i) { L[i] = scene_mat(24 + 16 * i); Li[i] = scene_mat(24 + 16 * (SWARP_SPLITS_MAX + i)); }\n"
    "  if (kind == 0) {\n"
    "    int bi; float w = swarp_cascade_blend(splits, count, inp[b+1u], inp[b+2u], bi);\n"
    "    outp[o] = float(swarp_select_split_depth(splits, count, inp[b+1u]));\n"
    "    outp[o+1u] = float(bi); outp[o+2u] = w;\n"
    "  } else if (kind == 1) {\n"
    "    vec3 p = vec3(inp[b+1u], inp[b+2u], inp[b+3u]);\n"
    "    outp[o] = float(swarp_select_split_best(L, Li, count, res, zo, p, int(inp[b+4u])));\n"
    "  } else if (kind == 2) {\n"
    "    int i = int(inp[b+1u]);\n"
    "    vec3 p = vec3(inp[b+2u], inp[b+3u], inp[b+4u]), tl = vec3(inp[b+5u], inp[b+6u], inp[b+7u]);\n"
    "    vec3 n = vec3(inp[b+10u], inp[b+11u], inp[b+12u]);\n"
    "    vec3 q = swarp_bias_kozlov(L[i], Li[i], res, p, tl, inp[b+8u], inp[b+9u]);\n"
    "    vec3 r = swarp_bias_normal_offset(L[i], Li[i], res, p, n, tl, inp[b+13u]);\n"
    "    outp[o] = q.x - p.x; outp[o+1u] = q.y - p.y; outp[o+2u] = q.z - p.z;\n"
    "    outp[o+3u] = r.x - p.x; outp[o+4u] = r.y - p.y; outp[o+5u] = r.z - p.z;\n"
    "    outp[o+6u] = swarp_texel_world(L[i], Li[i], res, p);\n"
    "  } else if (kind == 3) {\n"
    "    vec2 g = swarp_receiver_plane_gradient(vec3(inp[b+1u], inp[b+2u], inp[b+3u]), vec3(inp[b+4u], inp[b+5u], inp[b+6u]));\n"
    "    outp[o] = g.x; outp[o+1u] = g.y;\n"
    "  }\n"
    "}\n";

static uint64_t rng = 4711;
static double urand(double lo, double hi) { return tu_uniform(&rng, lo, hi); }
static double fl(double x) { return (double)(float)x; } /* what the shader sees */

static float in_buf[N_CASES * REC_IN], out_buf[N_CASES * REC_OUT], scene_buf[SCENE_FLOATS];
static double cases[N_CASES][REC_IN];
static swarp_bias_map maps[K];      /* the float-rounded split matrices, in double */
static swarp_mat4 inv[K];
static double splits_f[K + 1];
static const double RES = 1024.0;

/* a world point covered by split i: a random NDC point mapped back */
static void point_in_split(int i, double p[3]) {
    swarp_vec4 q;
    swarp_vec3 ndc = {urand(-0.9, 0.9), urand(-0.9, 0.9), urand(-0.9, 0.9)};
    swarp_mat4_transform(&inv[i], &ndc, &q);
    for (int k = 0; k < 3; ++k) p[k] = fl((&q.x)[k] / q.w);
}

static void make_case(int c, double* in) {
    memset(in, 0, sizeof(double) * REC_IN);
    int kind = c % 4;
    in[0] = kind;
    if (kind == 0) {
        /* depths away from the borders by 1e-4 relative (float rounding) */
        double z;
        int near_border;
        do {
            z = fl(splits_f[0] * pow(splits_f[K] / splits_f[0], urand(-0.05, 1.05)));
            near_border = 0;
            for (int i = 0; i <= K; ++i) near_border |= fabs(z - splits_f[i]) < 1e-4 * splits_f[i];
        } while (near_border);
        in[1] = z;
        in[2] = fl(urand(0, 0.5));
    } else if (kind == 1) {
        point_in_split((int)urand(0, K - 1e-9), in + 1);
        in[4] = (int)urand(0, K - 1e-9);
    } else if (kind == 2) {
        int i = (int)urand(0, K - 1e-9);
        in[1] = i;
        point_in_split(i, in + 2);
        double tl[3] = {urand(-1, 1), urand(0.2, 1), urand(-1, 1)}, n[3] = {urand(-1, 1), urand(-1, 1), urand(-1, 1)};
        double lt = sqrt(tl[0] * tl[0] + tl[1] * tl[1] + tl[2] * tl[2]), ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k) {
            in[5 + k] = fl(tl[k] / lt);
            in[10 + k] = fl(n[k] / ln);
        }
        in[8] = fl(urand(0, 0.05));
        in[9] = fl(urand(0, 2));
        in[13] = fl(urand(0, 3));
    } else {
        for (int k = 0; k < 6; ++k) in[1 + k] = fl(urand(-2, 2));
        /* well-conditioned: the two texel-space directions at least ~20 deg apart */
        double det = in[1] * in[5] - in[4] * in[2];
        if (fabs(det) < 0.35 * hypot(in[1], in[2]) * hypot(in[4], in[5])) in[5] = fl(in[5] + (det >= 0 ? 2 : -2));
    }
}

static double max_err[4][8];
static int best_hist[K + 1]; /* how often each split was the best one */

static int check_case(int c, const double* in, const float* outf) {
    double out[REC_OUT], e[8] = {0}, tol[8] = {0};
    for (int j = 0; j < REC_OUT; ++j) out[j] = outf[j];
    int kind = (int)in[0], ne = 0;
    switch (kind) {
        case 0: {
            uint32_t id, ib;
            double w;
            swarp_cascade_select_depth(splits_f, K, in[1], &id);
            swarp_cascade_blend(splits_f, K, in[1], in[2], &ib, &w);
            e[0] = fabs(out[0] - id);
            e[1] = fabs(out[1] - ib);
            e[2] = fabs(out[2] - w);
            tol[2] = 1e-4; /* (border - z)/width in float: a few ulps of ~1 */
            ne = 3;
            break;
        }
        case 1: {
            swarp_vec3 p = {in[1], in[2], in[3]};
            uint32_t ic;
            double Lc;
            swarp_cascade_select_best(maps, K, &p, (uint32_t)in[4], &ic, &Lc);
            best_hist[ic < K ? ic : K]++;
            int g = (int)out[0];
            e[0] = 0;
            if (g != (int)ic) {
                /* accept a float tie: the GLSL choice covers p and its texel
                 * is within float error (4e-3 relative) of the best one */
                double Lg = INFINITY;
                if (g >= 0 && g < K) swarp_bias_texel_size(&maps[g], &p, &Lg, NULL, NULL);
                e[0] = fabs(Lg - Lc) / Lc;
                tol[0] = 4e-3;
            }
            ne = 1;
            break;
        }
        case 2: {
            int i = (int)in[1];
            swarp_vec3 p = {in[2], in[3], in[4]}, n = {in[10], in[11], in[12]}, q, r;
            swarp_light lt;
            memset(&lt, 0, sizeof lt);
            lt.type = SWARP_LIGHT_DIRECTIONAL;
            lt.direction = (swarp_vec3){-in[5], -in[6], -in[7]};
            double L, amount, off;
            swarp_bias_texel_size(&maps[i], &p, &L, NULL, NULL);
            swarp_bias_kozlov(&maps[i], &lt, &p, in[8], in[9], &q, &amount);
            swarp_bias_normal_offset(&maps[i], &lt, &p, &n, in[13], &r, &off);
            /* float: the one-texel step is 2/res in NDC, rounded with the
             * point's own NDC (~eps_f), and mapped back through a matrix of
             * condition ~10..100: 4e-3 relative, plus the world coordinates'
             * own rounding when subtracting p (eps_f |p| each) */
            double pn = fabs(p.x) + fabs(p.y) + fabs(p.z);
            double tL = 4e-3 * L + 8 * FLT_EPSILON * pn;
            const double dq[3] = {q.x - p.x, q.y - p.y, q.z - p.z}, dr[3] = {r.x - p.x, r.y - p.y, r.z - p.z};
            for (int k = 0; k < 3; ++k) {
                e[k] = fabs(out[k] - dq[k]);
                tol[k] = in[9] * tL + 4 * FLT_EPSILON * (amount + pn);
                e[3 + k] = fabs(out[3 + k] - dr[k]);
                tol[3 + k] = in[13] * tL + 4 * FLT_EPSILON * (off + pn);
            }
            e[6] = fabs(out[6] - L);
            tol[6] = tL;
            ne = 7;
            break;
        }
        case 3: {
            /* the C receiver plane on a synthetic affine map whose texel-space
             * derivatives along the world axes x, y are exactly dx, dy */
            swarp_bias_map m;
            memset(&m, 0, sizeof m);
            m.res_s = m.res_t = 2.0; /* texel = NDC unit */
            m.depth = SWARP_DEPTH_ZERO_TO_ONE;
            double* M = m.world_to_clip.m;
            M[0] = in[1]; M[1] = in[2]; M[2] = in[3];   /* column x = dx */
            M[4] = in[4]; M[5] = in[5]; M[6] = in[6];   /* column y = dy */
            M[10] = 1;                                  /* z: keeps M invertible */
            M[15] = 1;
            swarp_vec3 p = {0, 0, 0}, ta = {1, 0, 0}, tb = {0, 1, 0};
            double g[2];
            if (swarp_bias_receiver_plane(&m, &p, &ta, &tb, g) != SWARP_OK) {
                g[0] = g[1] = NAN;
            }
            for (int k = 0; k < 2; ++k) {
                e[k] = fabs(out[k] - g[k]);
                tol[k] = 64 * FLT_EPSILON * (1 + fabs(g[0]) + fabs(g[1])) * 4; /* det >= 0.35 |dx||dy| */
            }
            ne = 2;
            break;
        }
    }
    int ok = 1;
    for (int j = 0; j < ne; ++j) {
        if (e[j] > max_err[kind][j]) max_err[kind][j] = e[j];
        if (!(e[j] <= tol[j])) {
            fprintf(stderr, "splits_glsl: case %d kind %d output %d: |glsl - C| = %g > %g\n", c, kind, j, e[j],
                    tol[j]);
            ok = 0;
        }
    }
    return ok;
}

/* One cascade: 4 PSSM splits, LiSPSM, light partly from behind the viewer. */
static int make_scene(void) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){0, 15, 0};
    cam.dir = (swarp_vec3){0.2, -0.3, -1};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 1.0;
    cam.aspect = 1.5;
    cam.z_near = 0.5;
    cam.z_far = 400;
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){0.1, -0.6, -1};
    swarp_aabb box = {{-500, -5, -500}, {500, 60, 500}};
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = K;
    o.setup.technique = SWARP_TECHNIQUE_LISPSM;
    o.setup.map_width = (uint32_t)RES;
    swarp_cascade_result r;
    swarp_cascade_split sp[K];
    size_t n;
    swarp_status st = swarp_cascade_setup(&cam, &l, &box, &o, &r, sp, K, &n);
    if (swarp_status_is_error(st)) {
        fprintf(stderr, "splits_glsl: swarp_cascade_setup: %s\n", swarp_status_name(st));
        return 0;
    }
    memset(scene_buf, 0, sizeof scene_buf);
    for (int i = 0; i <= K; ++i) {
        scene_buf[i] = (float)r.splits[i];
        splits_f[i] = scene_buf[i];
    }
    scene_buf[17] = K;
    scene_buf[18] = scene_buf[19] = (float)RES;
    scene_buf[20] = 0; /* [-1, 1] depth */
    for (int i = 0; i < K; ++i) {
        memset(&maps[i], 0, sizeof maps[i]);
        for (int j = 0; j < 16; ++j) {
            scene_buf[24 + 16 * i + j] = (float)sp[i].matrix.m[j];
            maps[i].world_to_clip.m[j] = scene_buf[24 + 16 * i + j];
        }
        maps[i].res_s = maps[i].res_t = RES;
        maps[i].depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
        if (swarp_mat4_invert(&maps[i].world_to_clip, &inv[i]) != SWARP_OK) return 0;
        for (int j = 0; j < 16; ++j) scene_buf[24 + 16 * (SWARP_CASCADE_MAX_SPLITS + i) + j] = (float)inv[i].m[j];
    }
    return 1;
}

/* splits_glsl: shaders/splits.glsl with the driver k_main.  splits_glsl
 * PATH: PATH is a whole compute shader, the HLSL twins (shaders/splits.hlsl)
 * with their driver (splits_hlsl.hlsl) translated HLSL -> SPIR-V -> GLSL,
 * run on the same cases against the same C results. */
int main(int argc, char** argv) {
    const int hlsl = argc > 1;
    const char* path = hlsl ? argv[1] : SPLITS_GLSL_PATH;
    OSMesaContext ctx = glh_open(hlsl ? "splits_hlsl" : "splits_glsl");
    if (!ctx) return 77;
    char* lib = glh_read_file(path);
    if (!lib || !make_scene()) {
        fprintf(stderr, "splits_glsl: cannot read %s or build the cascade\n", path);
        free(lib);
        OSMesaDestroyContext(ctx);
        return 1;
    }
    /* the file plus the driver, as a GLSL 4.50 compute shader (or the
     * translated shader, which has its own #version and driver) */
    const char* parts[3] = {"#version 450 core\n", lib, k_main};
    GLuint prog = hlsl ? glh_compile("splits_hlsl", (const char* const[]){lib}, 1, path)
                       : glh_compile("splits_glsl", parts, 3, "splits.glsl + driver");
    if (!prog) {
        free(lib);
        OSMesaDestroyContext(ctx);
        return 1;
    }
    for (int i = 0; i < N_CASES; ++i) {
        make_case(i, cases[i]);
        for (int j = 0; j < REC_IN; ++j) in_buf[i * REC_IN + j] = (float)cases[i][j];
    }
    GLuint buf[3];
    p_glGenBuffers(3, buf);
    glh_ssbo(buf[0], 0, sizeof in_buf, in_buf, GL_STATIC_DRAW);
    glh_ssbo(buf[1], 1, sizeof out_buf, NULL, GL_DYNAMIC_READ);
    glh_ssbo(buf[2], 2, sizeof scene_buf, scene_buf, GL_STATIC_DRAW);
    glh_run(prog, N_CASES / 64, buf[1], sizeof out_buf, out_buf);
    int bad = 0;
    for (int i = 0; i < N_CASES; ++i)
        if (!check_case(i, cases[i], out_buf + i * REC_OUT)) ++bad;
    static const char* names[4] = {"depth/blend", "best split", "bias", "receiver plane"};
    for (int k = 0; k < 4; ++k) {
        printf("%-16s max |glsl - C| per output:", names[k]);
        for (int j = 0; j < 7; ++j) printf(" %.2e", max_err[k][j]);
        printf("\n");
    }
    printf("%d of %d cases outside tolerance\n", bad, N_CASES);
    /* the selection cases must exercise several splits */
    int used = 0;
    printf("best split chosen:");
    for (int i = 0; i < K; ++i) {
        printf(" %d", best_hist[i]);
        used += best_hist[i] > 0;
    }
    printf("\n");
    if (used < 3) {
        fprintf(stderr, "splits_glsl: best-resolution cases hit only %d splits\n", used);
        bad++;
    }
    p_glDeleteBuffers(3, buf);
    p_glDeleteProgram(prog);
    free(lib);
    glh_close(ctx);
    return bad ? 1 : 0;
}
