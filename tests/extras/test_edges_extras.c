#define _POSIX_C_SOURCE 200809L
/* Argument checks and edge branches of the extras (cube maps, min depth):
 * bad input gives its documented status with
 * the outputs untouched; valid edge results are checked against the
 * defining property (brute-force minimum, a point on the unit cube). */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define SENTINEL (-7.25e33)

START_TEST(cube_edges) {
    swarp_cube_face faces[6];
    size_t count = 12345;
    swarp_cube_options o;
    memset(&o, 0, sizeof o);
    const swarp_vec4 inside = {0.1, -0.2, 0.3, 1.0};
    /* a light inside the unit cube sees all six faces */
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, faces, 6, &count), SWARP_OK);
    ck_assert_uint_eq(count, 6);
    /* capacity: needed count written, faces untouched */
    swarp_cube_face keep[6];
    memset(faces, 0x5A, sizeof faces);
    memcpy(keep, faces, sizeof faces);
    count = 0;
    ck_assert_int_eq(swarp_cube_faces(&inside, NULL, faces, 5, &count), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(count, 6);
    ck_assert(memcmp(keep, faces, sizeof faces) == 0);
    count = 77;
    o.z1 = INFINITY;
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, faces, 6, &count), SWARP_ERR_NON_FINITE);
    o.z1 = NAN;
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, faces, 6, &count), SWARP_ERR_NON_FINITE);
    o.z1 = 1.0;
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, faces, 6, &count), SWARP_ERR_OUT_OF_RANGE);
    o.z1 = 0.0;
    o._reserved[4] = 1;
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, faces, 6, &count), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[4] = 0;
    o.depth_range = (swarp_depth_range)5;
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, faces, 6, &count), SWARP_ERR_UNKNOWN_ENUM);
    o.depth_range = SWARP_DEPTH_DEFAULT;
    const swarp_vec4 nan_l = {0, NAN, 0, 1}, inf_w = {0, 0, 0, INFINITY};
    ck_assert_int_eq(swarp_cube_faces(&nan_l, &o, faces, 6, &count), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cube_faces(&inf_w, &o, faces, 6, &count), SWARP_ERR_NON_FINITE);
    /* |P| = 1e200 (w tiny): numerically at infinity */
    const swarp_vec4 far_l = {1.0, 0.5, 0.2, 1e-200};
    ck_assert_int_eq(swarp_cube_faces(&far_l, &o, faces, 6, &count), SWARP_ERR_CUBE_LIGHT_AT_INFINITY);
    ck_assert_int_eq(swarp_cube_faces(NULL, &o, faces, 6, &count), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cube_faces(&inside, &o, NULL, 6, &count), SWARP_ERR_NULL_POINTER);
    ck_assert_uint_eq(count, 77);
    ck_assert(memcmp(keep, faces, sizeof faces) == 0);

    /* lookup: the texcoord lies on the unit cube, on the face of its
     * largest coordinate, along the ray from the light through the point */
    uint64_t s = 0xC0BEull;
    for (int n = 0; n < 500; ++n) {
        swarp_vec3 q = {tu_uniform(&s, -3, 3), tu_uniform(&s, -3, 3), tu_uniform(&s, -3, 3)};
        uint32_t face = 99;
        swarp_vec3 S;
        double depth;
        swarp_status st = swarp_cube_lookup(&inside, NULL, &q, &face, &S, &depth);
        ck_assert(st == SWARP_OK || st == SWARP_INFO_CUBE_NEAR_CLIPPED);
        double m = fmax(fabs(S.x), fmax(fabs(S.y), fabs(S.z)));
        ck_assert(fabs(m - 1.0) < 1e-12);
        double c[3] = {S.x, S.y, S.z};
        ck_assert(fabs(fabs(c[face / 2]) - 1.0) < 1e-12);
        /* S - P parallel to q - P, same direction */
        swarp_vec3 a = {S.x - 0.1, S.y + 0.2, S.z - 0.3}, b = {q.x - 0.1, q.y + 0.2, q.z - 0.3};
        double cx = a.y * b.z - a.z * b.y, cy = a.z * b.x - a.x * b.z, cz = a.x * b.y - a.y * b.x;
        ck_assert(fabs(cx) + fabs(cy) + fabs(cz) < 1e-9 * (1 + fabs(b.x) + fabs(b.y) + fabs(b.z)));
        ck_assert(a.x * b.x + a.y * b.y + a.z * b.z > 0);
    }
    /* only the face requested */
    const swarp_vec3 q = {2, 0.1, 0.1};
    uint32_t face = 99;
    ck_assert_int_eq(swarp_cube_lookup(&inside, NULL, &q, &face, NULL, NULL), SWARP_OK);
    ck_assert_uint_eq(face, SWARP_CUBE_FACE_POS_X);
    /* the point at the light: no direction */
    const swarp_vec3 at_light = {0.1, -0.2, 0.3}, nan_q = {NAN, 0, 0};
    swarp_vec3 S = {SENTINEL, SENTINEL, SENTINEL};
    double depth = SENTINEL;
    face = 99;
    ck_assert_int_eq(swarp_cube_lookup(&inside, NULL, &at_light, &face, &S, &depth), SWARP_ERR_CUBE_POINT_UNCOVERED);
    ck_assert_int_eq(swarp_cube_lookup(&inside, NULL, &nan_q, &face, &S, &depth), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cube_lookup(&inside, NULL, NULL, &face, &S, &depth), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cube_lookup(&far_l, NULL, &q, &face, &S, &depth), SWARP_ERR_CUBE_LIGHT_AT_INFINITY);
    ck_assert(face == 99 && tu_untouched(&S.x, 3, SENTINEL) && tu_untouched(&depth, 1, SENTINEL));
}
END_TEST

START_TEST(mindepth_edges) {
    /* pyramid == direct == brute force on odd sizes, with +inf (empty) texels */
    uint64_t s = 0xD3E7ull;
    float buf[37 * 23], scratch[SWARP_MINDEPTH_SCRATCH(37, 23)];
    for (int n = 0; n < 50; ++n) {
        uint32_t w = 1 + (uint32_t)(tu_splitmix64(&s) % 33), h = 1 + (uint32_t)(tu_splitmix64(&s) % 23);
        size_t stride = w + (size_t)(tu_splitmix64(&s) % 5);
        float brute = INFINITY;
        for (size_t i = 0; i < sizeof buf / sizeof buf[0]; ++i) buf[i] = -1.0f; /* padding: never read */
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                float v = (tu_splitmix64(&s) % 4 == 0) ? INFINITY : (float)tu_uniform(&s, 0.5, 100);
                buf[y * stride + x] = v;
                if (v < brute) brute = v;
            }
        if (stride * h > sizeof buf / sizeof buf[0]) continue;
        size_t needed = 0;
        double mp = SENTINEL, md = SENTINEL;
        swarp_status sp = swarp_mindepth_pyramid(buf, w, h, stride, scratch, sizeof scratch / sizeof scratch[0],
                                                 &needed, &mp);
        swarp_status sd = swarp_mindepth_direct(buf, w, h, stride, &md);
        ck_assert_int_eq(sp, sd);
        ck_assert(mp == (double)brute && md == (double)brute);
        ck_assert_int_eq(sp, isinf(brute) ? SWARP_INFO_MINDEPTH_EMPTY : SWARP_OK);
        ck_assert_uint_eq(needed, SWARP_MINDEPTH_SCRATCH(w, h));
    }
    /* all empty: informational, +inf */
    float empty[6] = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
    double m = SENTINEL;
    size_t needed = 0;
    ck_assert_int_eq(swarp_mindepth_direct(empty, 3, 2, 3, &m), SWARP_INFO_MINDEPTH_EMPTY);
    ck_assert(isinf(m));
    m = SENTINEL;
    ck_assert_int_eq(swarp_mindepth_pyramid(empty, 3, 2, 3, scratch, 4, &needed, &m), SWARP_INFO_MINDEPTH_EMPTY);
    ck_assert(isinf(m));
    /* scratch problems: needed count written, the minimum untouched */
    m = SENTINEL;
    needed = 0;
    ck_assert_int_eq(swarp_mindepth_pyramid(empty, 3, 2, 3, NULL, 0, &needed, &m), SWARP_ERR_CAPACITY);
    ck_assert(needed == 2 && tu_untouched(&m, 1, SENTINEL));
    ck_assert_int_eq(swarp_mindepth_pyramid(empty, 3, 2, 3, NULL, 4, &needed, &m), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_mindepth_pyramid(empty, 3, 2, 3, scratch, 1, &needed, &m), SWARP_ERR_CAPACITY);
    ck_assert_int_eq(swarp_mindepth_pyramid(empty, 3, 2, 3, scratch, 4, NULL, &m), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_mindepth_pyramid(empty, 3, 2, 3, scratch, 4, &needed, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_mindepth_direct(empty, 3, 2, 3, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(tu_untouched(&m, 1, SENTINEL));

    /* the adjusted near plane */
    swarp_mindepth_options o;
    memset(&o, 0, sizeof o);
    double nn = SENTINEL;
    o.margin = NAN;
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 10, &o, &nn), SWARP_ERR_NON_FINITE);
    o.margin = 1.0;
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 10, &o, &nn), SWARP_ERR_OUT_OF_RANGE);
    o.margin = -0.1;
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 10, &o, &nn), SWARP_ERR_OUT_OF_RANGE);
    o.margin = 0.0;
    o._reserved[1] = 1;
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 10, &o, &nn), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[1] = 0;
    ck_assert_int_eq(swarp_mindepth_near(1, 100, NAN, &o, &nn), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mindepth_near(1, 100, -INFINITY, &o, &nn), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mindepth_near(NAN, 100, 10, &o, &nn), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mindepth_near(1, INFINITY, 10, &o, &nn), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mindepth_near(1, 0.5, 10, &o, &nn), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_mindepth_near(1, 100, -2, &o, &nn), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 10, &o, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(tu_untouched(&nn, 1, SENTINEL));
    /* margin 0.25: near' = 0.75 min_depth; below n: n kept */
    o.margin = 0.25;
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 10, &o, &nn), SWARP_OK);
    ck_assert(nn == 7.5);
    ck_assert_int_eq(swarp_mindepth_near(1, 100, 1.2, &o, &nn), SWARP_OK);
    ck_assert(nn == 1.0);
    ck_assert_int_eq(swarp_mindepth_near(1, 100, INFINITY, NULL, &nn), SWARP_INFO_MINDEPTH_EMPTY);
    ck_assert(nn == 1.0);
}
END_TEST

/* ---- cube lookups at the ends of the double range ---- */

/* V.x = DBL_MAX makes a = (u . N)/d overflow to inf, so unscaled u/a = 0
 * and S = P (S.x = 0.85, off the cube).  The exit face is +x: S.x = 1. */
START_TEST(cube_lookup_huge_point) {
    const swarp_vec4 L = {0x1.b1ed320f5bd18p-1, -0x1.57d598e777458p-1, 0x1.a04a543f83298p-1, 1.0};
    const swarp_vec3 V = {DBL_MAX, -1.5, 0x1.3b5b5c3b38864p+0};
    uint32_t face = 99;
    swarp_vec3 S;
    double depth;
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, &V, &face, &S, &depth), SWARP_OK);
    ck_assert_uint_eq(face, 0);
    ck_assert(fabs(S.x - 1.0) < 1e-12);
    /* S = P + u/a with a = u.x/d_0 = DBL_MAX/(1 - P.x) to rounding */
    const double a = (DBL_MAX - L.x) / (1.0 - L.x);
    ck_assert(tu_rel(S.y, L.y + (-1.5 - L.y) / a) < 1e-12 && tu_rel(S.z, L.z + (V.z - L.z) / a) < 1e-12);
}
END_TEST

/* The same with the exit face decided by a small component (u.x = 1e-9
 * beside u.y = DBL_MAX): scaling u all the way to [1, 2) would make u.x
 * subnormal (S.y 2e-7 off), so this pins the scaling threshold of the test
 * above from the other side. */
START_TEST(cube_lookup_huge_and_small_components) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const swarp_vec4 L = {0x1.01820f73113bdp+0, 0x1.9e53434cb75dfp+0, -0x1.c81789dcf401p-1, 0x1.01820f776338ep+0};
    const swarp_vec3 V = {0x1.0000000001198p+0, DBL_MAX, 0x1.12e0be826d695p-30};
    uint32_t face = 99;
    swarp_vec3 S;
    ck_assert_int_eq(swarp_cube_lookup(&L, NULL, &V, &face, &S, NULL), SWARP_OK);
    ck_assert_uint_eq(face, 0);
    /* long double reference (its exponent range holds u.y / a) */
    const long double Py = (long double)L.y / L.w;
    const long double d0 = 1.0L - (double)(L.x / L.w); /* the library's d_0, from the double P.x */
    const long double a = ((long double)V.x - (double)(L.x / L.w)) / d0;
    ck_assert(fabsl(S.x - 1.0L) < 1e-9L);
    ck_assert_msg(fabsl((S.y - (Py + ((long double)V.y - Py) / a)) / S.y) < 1e-12L, "S.y %.17g", S.y);
}
END_TEST

/* The face matrices must not depend on the caller's rounding mode beyond a
 * few eps of their scale: with Z_1 = 1 - 1e-9, alpha = (f + n)/(f - n)
 * formed from n = Z_1 d would lose 1e-7 relative under FE_UPWARD (hence the
 * ratio form), and for a light at 3e6 the product proj view cancels
 * d (R.P) - (R.P)(Z.P) to -R.P, moving 1e-9 of the matrix with the mode
 * (hence the closed form). */
static void cube_faces_in_mode(const swarp_vec4* L, const swarp_cube_options* o, int mode, swarp_cube_face* f,
                               size_t* n) {
    fesetround(mode);
    swarp_status st = swarp_cube_faces(L, o, f, SWARP_CUBE_MAX_FACES, n);
    fesetround(FE_TONEAREST);
    ck_assert_int_eq(st, SWARP_OK);
}
START_TEST(cube_faces_rounding_mode) {
    static const swarp_vec4 lights[2] = {{-0.8573087920171597, 2.0285826279546053, -2.2679433718553126, 1.0034271873637741},
                                         {2999999.9999999995, 2934658.0867776205, -1000000, 1}};
    static const double z1s[2] = {1 - 1e-9, 0.756044};
    static const int modes[3] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int j = 0; j < 2; ++j) {
        swarp_cube_options o = {0};
        o.z1 = z1s[j];
        swarp_cube_face f0[SWARP_CUBE_MAX_FACES], f1[SWARP_CUBE_MAX_FACES];
        size_t n0, n1;
        cube_faces_in_mode(&lights[j], &o, FE_TONEAREST, f0, &n0);
        for (int m = 0; m < 3; ++m) {
            cube_faces_in_mode(&lights[j], &o, modes[m], f1, &n1);
            ck_assert_uint_eq(n0, n1);
            for (size_t i = 0; i < n0; ++i) {
                double sc = 0;
                for (int e = 0; e < 16; ++e) sc = fmax(sc, fabs(f0[i].view_proj.m[e]));
                for (int e = 0; e < 16; ++e)
                    ck_assert_msg(fabs(f1[i].view_proj.m[e] - f0[i].view_proj.m[e]) <= 16 * DBL_EPSILON * sc,
                                  "light %d mode %d face %zu view_proj[%d] %.17g, default %.17g", j, m, i, e,
                                  f1[i].view_proj.m[e], f0[i].view_proj.m[e]);
            }
        }
    }
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_extras");
    TCase* t = tcase_create("extras");
    tcase_add_test(t, cube_edges);
    tcase_add_test(t, mindepth_edges);
    suite_add_tcase(s, t);
    t = tcase_create("cube_lookup_extreme");
    tcase_add_test(t, cube_lookup_huge_point);
    tcase_add_test(t, cube_lookup_huge_and_small_components);
    suite_add_tcase(s, t);
    t = tcase_create("cube_faces_rounding_mode");
    tcase_add_test(t, cube_faces_rounding_mode);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
