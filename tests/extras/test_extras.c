#define _POSIX_C_SOURCE 200809L
/* Extras: [KOZ] §14.2.2 cube-map faces in post-projective space (Listing 14-1)
 * and the [RHS] §4.3 min-depth near plane (Listing A.2). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

static uint64_t next_u64(uint64_t* s) { return tu_splitmix64(s); }
static double uni(uint64_t* s, double a, double b) { return tu_uniform(s, a, b); }

/* ---- [KOZ] §14.2.2 ------------------------------------------------------------ */

static const double normals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

static swarp_vec4 ndc_of(const swarp_mat4* m, swarp_vec3 p) {
    swarp_vec4 h;
    swarp_mat4_transform(m, &p, &h);
    swarp_vec4 r = {h.x / h.w, h.y / h.w, h.z / h.w, h.w};
    return r;
}
static double dot3(swarp_vec3 a, const double* b) { return a.x * b[0] + a.y * b[1] + a.z * b[2]; }
static double dotv(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* a random light: outside the cube (|coord| up to 6) or inside, homogeneous
 * with a random w of either sign (w < 0: inverse-projection variant) */
static swarp_vec4 rand_light(uint64_t* s, int inside, int negative_w, swarp_vec3* P) {
    double lim = inside ? 0.95 : 6.0;
    do {
        P->x = uni(s, -lim, lim), P->y = uni(s, -lim, lim), P->z = uni(s, -lim, lim);
    } while (!inside && fabs(P->x) <= 1.05 && fabs(P->y) <= 1.05 && fabs(P->z) <= 1.05);
    double w = uni(s, 0.1, 10.0) * (negative_w ? -1.0 : 1.0);
    swarp_vec4 L = {P->x * w, P->y * w, P->z * w, w};
    return L;
}

START_TEST(cube_face_count_matches_position) {
    uint64_t s = 0xc0be0001;
    for (int k = 0; k < 4000; ++k) {
        int inside = k % 4 == 0;
        swarp_vec3 P;
        swarp_vec4 L = rand_light(&s, inside, k % 3 == 0, &P);
        swarp_cube_face f[SWARP_CUBE_MAX_FACES];
        size_t n = 0;
        ck_assert_int_eq(swarp_cube_faces(&L, NULL, f, SWARP_CUBE_MAX_FACES, &n), SWARP_OK);
        /* each axis with the light beyond one of its faces loses that face */
        size_t want = 6 - (fabs(P.x) >= 1) - (fabs(P.y) >= 1) - (fabs(P.z) >= 1);
        ck_assert_uint_eq(n, want);
        if (inside)
            ck_assert_uint_eq(n, 6);
        else
            ck_assert(n >= 3 && n <= 5);
        for (size_t i = 0; i < n; ++i) {
            ck_assert(f[i].distance > 0);
            ck_assert(i == 0 || f[i].face > f[i - 1].face);
            ck_assert_uint_eq(f[i].inverse, (uint32_t)(k % 3 == 0));
        }
    }
    /* the example of [KOZ] Fig. 14-10: light beyond the far face, toward the camera */
    swarp_vec4 L = {0, 0, 3, 1};
    size_t n = 0;
    swarp_cube_face f[6];
    ck_assert_int_eq(swarp_cube_faces(&L, NULL, f, 6, &n), SWARP_OK);
    ck_assert_uint_eq(n, 5);
    /* a light on a face plane: that face is edge-on and dropped */
    swarp_vec4 E = {1, 0, 0, 1};
    ck_assert_int_eq(swarp_cube_faces(&E, NULL, f, 6, &n), SWARP_OK);
    ck_assert_uint_eq(n, 5);
}
END_TEST

START_TEST(cube_face_frustum_is_the_face_pyramid) {
    uint64_t s = 0xc0be0002;
    for (int k = 0; k < 1000; ++k) {
        swarp_vec3 P;
        swarp_vec4 L = rand_light(&s, k % 3 == 0, k % 2 == 0, &P);
        swarp_cube_options opt;
        memset(&opt, 0, sizeof opt);
        opt.z1 = uni(&s, 1e-3, 0.2);
        opt.depth_range = (k % 4 < 2) ? SWARP_DEPTH_NEG_ONE_TO_ONE : SWARP_DEPTH_ZERO_TO_ONE;
        double zlo = opt.depth_range == SWARP_DEPTH_ZERO_TO_ONE ? 0.0 : -1.0;
        swarp_cube_face f[6];
        size_t n = 0;
        ck_assert_int_eq(swarp_cube_faces(&L, &opt, f, 6, &n), SWARP_OK);
        for (size_t i = 0; i < n; ++i) {
            const double* N = normals[f[i].face];
            double d = 1.0 - dot3(P, N);
            ck_assert_double_eq_tol(f[i].distance, d, 1e-12 * (1 + fabs(d)));
            /* the face's corners land on the NDC corners, at the far plane
             * (regular) or at depth Z_1 (inverse, [KOZ]: Z_n = -Z_1, Z_f = Z_1) */
            for (int c = 0; c < 4; ++c) {
                double su = (c & 1) ? 1 : -1, sv = (c & 2) ? 1 : -1;
                swarp_vec3 C = {N[0] + su * f[i].right.x + sv * f[i].up.x,
                                N[1] + su * f[i].right.y + sv * f[i].up.y,
                                N[2] + su * f[i].right.z + sv * f[i].up.z};
                swarp_vec4 q = ndc_of(&f[i].view_proj, C);
                ck_assert_double_eq_tol(q.x, su, 1e-9);
                ck_assert_double_eq_tol(q.y, sv, 1e-9);
                double far_z = f[i].inverse ? (zlo == 0.0 ? 0.5 * (1 + opt.z1) : opt.z1) : 1.0;
                ck_assert_double_eq_tol(q.z, far_z, 1e-9);
                /* the same corner pulled towards P to Z_1 of the way: the near cube */
                swarp_vec3 Cn = {P.x + opt.z1 * (C.x - P.x), P.y + opt.z1 * (C.y - P.y),
                                 P.z + opt.z1 * (C.z - P.z)};
                q = ndc_of(&f[i].view_proj, Cn);
                double near_z = f[i].inverse ? 1.0 : zlo;
                ck_assert_double_eq_tol(q.z, near_z, 1e-9);
                ck_assert_double_eq_tol(q.x, su, 1e-9);
            }
        }
        /* every point of the cube is in exactly one face frustum (up to shared
         * edges), and Listing 14-1's lookup agrees with that face's matrix */
        int bad = 0;
        for (int j = 0; j < 50; ++j) {
            swarp_vec3 V = {uni(&s, -1, 1), uni(&s, -1, 1), uni(&s, -1, 1)};
            int strict = 0, loose = 0, hit = -1;
            swarp_vec4 hq = {0, 0, 0, 0};
            for (size_t i = 0; i < n; ++i) {
                swarp_vec4 q = ndc_of(&f[i].view_proj, V);
                if (!(q.w > 0)) continue; /* behind the face camera */
                if (fabs(q.x) < 1 - 1e-9 && fabs(q.y) < 1 - 1e-9) ++strict, hit = (int)i, hq = q;
                if (fabs(q.x) <= 1 + 1e-9 && fabs(q.y) <= 1 + 1e-9) ++loose;
            }
            bad += strict > 1 || loose < 1;
            if (hit < 0) continue; /* on a shared edge */
            uint32_t face = 99;
            swarp_vec3 S;
            double depth = 0;
            swarp_status st = swarp_cube_lookup(&L, &opt, &V, &face, &S, &depth);
            bad += !(st == SWARP_OK || st == SWARP_INFO_CUBE_NEAR_CLIPPED);
            bad += face != f[hit].face;
            /* the texture coordinate is the cube point the face maps V to */
            bad += fabs(dot3(S, normals[face]) - 1.0) > 1e-9;
            bad += fabs(dotv(S, f[hit].right) - hq.x) > 1e-9;
            bad += fabs(dotv(S, f[hit].up) - hq.y) > 1e-9;
            bad += fabs(depth - hq.z) > 1e-9 * (1 + fabs(depth));
            /* S, V and P are collinear: S - P parallel to V - P, same direction */
            swarp_vec3 a = {S.x - P.x, S.y - P.y, S.z - P.z}, b = {V.x - P.x, V.y - P.y, V.z - P.z};
            swarp_vec3 c = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
            bad += sqrt(dotv(c, c)) > 1e-9 * sqrt(dotv(a, a)) * sqrt(dotv(b, b)) || dotv(a, b) <= 0;
        }
        ck_assert_int_eq(bad, 0);
    }
}
END_TEST

/* Depth of the listing by another algebraic form: NDC depth is affine in 1/a,
 * -1 (or 0) at a = Z_n and 1 at a = Z_f. */
static double depth_ref(double a, double zn, double zf, int zero_to_one) {
    double t = (1.0 / zn - 1.0 / a) / (1.0 / zn - 1.0 / zf);
    return zero_to_one ? t : 2.0 * t - 1.0;
}

START_TEST(cube_lookup_listing_14_1) { /* [KOZ] Listing 14-1 */
    /* [KOZ] Fig. 14-12 style: light beyond the far face */
    swarp_vec4 L = {0, 0, 3, 1};
    swarp_vec3 V = {0, 0, 0}, S;
    uint32_t face = 99;
    double depth = 0;
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, &V, &face, &S, &depth), SWARP_OK);
    ck_assert_uint_eq(face, SWARP_CUBE_FACE_NEG_Z);
    ck_assert_double_eq_tol(S.z, -1.0, 1e-15);
    ck_assert_double_eq_tol(S.x, 0.0, 1e-15);
    /* a = |V - P| / d = 3/4, Z_n = Z_1 = 0.01 (default), Z_f = 1 */
    ck_assert_double_eq_tol(depth, depth_ref(0.75, 0.01, 1.0, 0), 1e-13);
    /* the same through an inverse projection: w < 0, Z_n = -Z_1, Z_f = Z_1 */
    swarp_vec4 Li = {0, 0, -3, -1}; /* same P = (0, 0, 3) */
    swarp_cube_options o;
    memset(&o, 0, sizeof o);
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    o.z1 = 0.05;
    ck_assert_int_eq(swarp_cube_lookup(&Li, &o, &V, &face, &S, &depth), SWARP_OK);
    ck_assert_double_eq_tol(depth, depth_ref(0.75, -0.05, 0.05, 1), 1e-13);
    ck_assert_double_eq_tol(depth, 0.5 * (1.0 + 0.05 / 0.75), 1e-13); /* D3D form of [KOZ] */
    /* inverse: farther from P is nearer the light (smaller depth); regular: the opposite */
    swarp_vec3 V2 = {0, 0, -0.5};
    double d2 = 0, d1 = 0;
    ck_assert_int_eq(swarp_cube_lookup(&Li, &o, &V2, NULL, NULL, &d2), SWARP_OK);
    ck_assert(d2 < depth);
    ck_assert_int_eq(swarp_cube_lookup(&L, &o, &V, NULL, NULL, &d1), SWARP_OK);
    ck_assert_int_eq(swarp_cube_lookup(&L, &o, &V2, NULL, NULL, &d2), SWARP_OK);
    ck_assert(d2 > d1);
    /* point light inside: a point in the near cube is reported as clipped */
    swarp_vec4 In = {0.2, 0.1, -0.3, 1};
    swarp_vec3 Vn = {0.2005, 0.1, -0.3};
    ck_assert_int_eq(swarp_cube_lookup(&In, NULL, &Vn, &face, &S, &depth), SWARP_INFO_CUBE_NEAR_CLIPPED);
    ck_assert_uint_eq(face, SWARP_CUBE_FACE_POS_X);
    ck_assert(depth < -1.0);
}
END_TEST

START_TEST(cube_bad_inputs) {
    swarp_cube_face f[6], sent[6];
    memset(sent, 0xAB, sizeof sent);
    memcpy(f, sent, sizeof f);
    size_t n = 777;
    swarp_vec4 L = {0, 0, 3, 1};
    swarp_cube_options o;
    memset(&o, 0, sizeof o);
#define UNTOUCHED() ck_assert(memcmp(f, sent, sizeof f) == 0)
    ck_assert_int_eq(swarp_cube_faces(NULL, NULL, f, 6, &n), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cube_faces(&L, NULL, f, 6, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cube_faces(&L, NULL, NULL, 6, &n), SWARP_ERR_NULL_POINTER);
    swarp_vec4 bad = {NAN, 0, 0, 1};
    ck_assert_int_eq(swarp_cube_faces(&bad, NULL, f, 6, &n), SWARP_ERR_NON_FINITE);
    swarp_vec4 inf = {1, 0, 0, 0};
    ck_assert_int_eq(swarp_cube_faces(&inf, NULL, f, 6, &n), SWARP_ERR_CUBE_LIGHT_AT_INFINITY);
    swarp_vec4 far = {1, 0, 0, 1e-300};
    ck_assert_int_eq(swarp_cube_faces(&far, NULL, f, 6, &n), SWARP_ERR_CUBE_LIGHT_AT_INFINITY);
    o.z1 = 1.0;
    ck_assert_int_eq(swarp_cube_faces(&L, &o, f, 6, &n), SWARP_ERR_OUT_OF_RANGE);
    o.z1 = -0.1;
    ck_assert_int_eq(swarp_cube_faces(&L, &o, f, 6, &n), SWARP_ERR_OUT_OF_RANGE);
    o.z1 = NAN;
    ck_assert_int_eq(swarp_cube_faces(&L, &o, f, 6, &n), SWARP_ERR_NON_FINITE);
    o.z1 = 0;
    o.depth_range = (swarp_depth_range)7;
    ck_assert_int_eq(swarp_cube_faces(&L, &o, f, 6, &n), SWARP_ERR_UNKNOWN_ENUM);
    o.depth_range = SWARP_DEPTH_DEFAULT;
    o._reserved[4] = 1;
    ck_assert_int_eq(swarp_cube_faces(&L, &o, f, 6, &n), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[4] = 0;
    ck_assert_uint_eq(n, 777);
    UNTOUCHED();
    ck_assert_int_eq(swarp_cube_faces(&L, &o, f, 4, &n), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(n, 5);
    UNTOUCHED();
    n = 0;
    ck_assert_int_eq(swarp_cube_faces(&L, &o, NULL, 0, &n), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(n, 5);
    /* lookup: the light itself, and a point behind an outside light */
    uint32_t face = 99;
    swarp_vec3 S = {7, 7, 7}, V = {0, 0, 3}, behind = {0, 0, 9};
    double depth = 7;
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, &V, &face, &S, &depth), SWARP_ERR_CUBE_POINT_UNCOVERED);
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, &behind, &face, &S, &depth), SWARP_ERR_CUBE_POINT_UNCOVERED);
    swarp_vec3 nanp = {NAN, 0, 0};
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, &nanp, &face, &S, &depth), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, NULL, &face, &S, &depth), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cube_lookup(&inf, NULL, &behind, &face, &S, &depth), SWARP_ERR_CUBE_LIGHT_AT_INFINITY);
    ck_assert(face == 99 && S.x == 7 && depth == 7);
#undef UNTOUCHED
}
END_TEST

/* ---- [RHS] §4.3 ------------------------------------------------------------ */

START_TEST(mindepth_pyramid_equals_true_min) { /* [RHS] Listing A.2 */
    uint64_t s = 0xde9701;
    static float buf[80 * 90];
    static float scratch[SWARP_MINDEPTH_SCRATCH(80, 80)];
    for (int k = 0; k < 1000; ++k) {
        uint32_t w = 1 + (uint32_t)(next_u64(&s) % 67), h = 1 + (uint32_t)(next_u64(&s) % 67);
        size_t stride = w + (size_t)(next_u64(&s) % 5);
        double truth = INFINITY;
        for (size_t i = 0; i < stride * h; ++i) buf[i] = -1.0f; /* padding: must be ignored */
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                float v = (next_u64(&s) % 10 == 0) ? INFINITY : (float)uni(&s, 0.1, 1000.0);
                buf[y * stride + x] = v;
                truth = fmin(truth, (double)v);
            }
        /* half the time, plant the minimum on the last (odd) row/column */
        if (k % 2 == 0) {
            float m = (float)uni(&s, 0.01, 0.09);
            buf[(h - 1) * stride + (w - 1)] = m;
            truth = m;
        }
        double pm = -1, dm = -1;
        size_t need = 0;
        swarp_status want = isinf(truth) ? SWARP_INFO_MINDEPTH_EMPTY : SWARP_OK;
        ck_assert_int_eq(swarp_mindepth_pyramid(buf, w, h, stride, scratch, sizeof scratch / sizeof scratch[0],
                                                &need, &pm), want);
        ck_assert_int_eq(swarp_mindepth_direct(buf, w, h, stride, &dm), want);
        ck_assert_uint_eq(need, ((w + 1) / 2) * ((h + 1) / 2));
        ck_assert(pm == truth && dm == truth);
        /* the adjusted near plane never clips what the buffer saw */
        double n = 0.005, f = 2000.0, nn = 0; /* every depth the buffer holds is >= near */
        swarp_status st = swarp_mindepth_near(n, f, pm, NULL, &nn);
        ck_assert(st == SWARP_OK || st == SWARP_INFO_MINDEPTH_EMPTY);
        ck_assert(nn >= n && nn < f);
        int clipped = 0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) clipped += buf[y * stride + x] < nn;
        ck_assert_int_eq(clipped, 0);
    }
}
END_TEST

START_TEST(mindepth_near_plane) {
    double nn = 0;
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 6.0, NULL, &nn), SWARP_OK);
    ck_assert_double_eq_tol(nn, 6.0 * (1 - 1e-3), 1e-15);
    swarp_mindepth_options o;
    memset(&o, 0, sizeof o);
    o.margin = 0.25;
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 6.0, &o, &nn), SWARP_OK);
    ck_assert_double_eq_tol(nn, 4.5, 1e-15);
    /* nearer than near: keep near */
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 0.5, NULL, &nn), SWARP_OK);
    ck_assert(nn == 1.0);
    /* empty buffer or nothing before far */
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, INFINITY, NULL, &nn), SWARP_INFO_MINDEPTH_EMPTY);
    ck_assert(nn == 1.0);
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 100.0, NULL, &nn), SWARP_INFO_MINDEPTH_EMPTY);
    nn = 7;
    ck_assert_int_eq(swarp_mindepth_near(0.0, 100.0, 5, NULL, &nn), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_mindepth_near(10.0, 10.0, 5, NULL, &nn), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, -1, NULL, &nn), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, NAN, NULL, &nn), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mindepth_near(INFINITY, 100.0, 5, NULL, &nn), SWARP_ERR_NON_FINITE);
    o.margin = 1.0;
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 5, &o, &nn), SWARP_ERR_OUT_OF_RANGE);
    o.margin = 0.1;
    o._reserved[3] = 2;
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 5, &o, &nn), SWARP_ERR_RESERVED_NONZERO);
    ck_assert(nn == 7);
    ck_assert_int_eq(swarp_mindepth_near(1.0, 100.0, 5, NULL, NULL), SWARP_ERR_NULL_POINTER);
}
END_TEST

START_TEST(mindepth_bad_inputs) {
    float buf[12] = {5, 4, 3, 2, 1, 6, 7, 8, 9, 10, 11, 12}, scratch[6];
    double m = 7;
    size_t need = 777;
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 4, scratch, 3, &need, &m), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(need, 4);
    need = 777;
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 4, NULL, 0, &need, &m), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(need, 4);
    ck_assert(m == 7);
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 4, scratch, 6, &need, &m), SWARP_OK);
    ck_assert(m == 1.0);
    m = 7;
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 0, 3, 4, scratch, 6, &need, &m), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 0, 4, scratch, 6, &need, &m), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 3, scratch, 6, &need, &m), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(swarp_mindepth_direct(buf, 4, 3, 3, &m), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(swarp_mindepth_pyramid(NULL, 4, 3, 4, scratch, 6, &need, &m), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 4, scratch, 6, NULL, &m), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_mindepth_direct(buf, 4, 3, 4, NULL), SWARP_ERR_NULL_POINTER);
    buf[7] = NAN;
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 4, scratch, 6, &need, &m), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mindepth_direct(buf, 4, 3, 4, &m), SWARP_ERR_NON_FINITE);
    buf[7] = -INFINITY;
    ck_assert_int_eq(swarp_mindepth_direct(buf, 4, 3, 4, &m), SWARP_ERR_NON_FINITE);
    buf[7] = -0.5f;
    ck_assert_int_eq(swarp_mindepth_pyramid(buf, 4, 3, 4, scratch, 6, &need, &m), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_mindepth_direct(buf, 4, 3, 4, &m), SWARP_ERR_OUT_OF_RANGE);
    ck_assert(m == 7);
    /* 1 x 1 */
    float one = 3.5f, sc1;
    ck_assert_int_eq(swarp_mindepth_pyramid(&one, 1, 1, 1, &sc1, 1, &need, &m), SWARP_OK);
    ck_assert(m == 3.5 && need == 1);
}
END_TEST

int main(void) {
    Suite* s = suite_create("extras");
    TCase* tc = tcase_create("cube");
    tcase_add_test(tc, cube_face_count_matches_position);
    tcase_add_test(tc, cube_face_frustum_is_the_face_pyramid);
    tcase_add_test(tc, cube_lookup_listing_14_1);
    tcase_add_test(tc, cube_bad_inputs);
    suite_add_tcase(s, tc);
    TCase* tm = tcase_create("mindepth");
    tcase_add_test(tm, mindepth_pyramid_equals_true_min);
    tcase_add_test(tm, mindepth_near_plane);
    tcase_add_test(tm, mindepth_bad_inputs);
    suite_add_tcase(s, tm);
    int failed = tu_run_suite(s);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
