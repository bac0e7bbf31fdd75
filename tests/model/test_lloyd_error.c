#define _POSIX_C_SOURCE 200809L
/* Core: Lloyd's error metric [RHS] (2.3)-(2.8), its exact maxima and the
 * piecewise curve of a partitioned frustum ([RHS] Fig. 3.15, 3.18). */
#include <float.h>
#include <stdlib.h>

#include "test_core.h"

/* ---- the paper's formulas, literally ------------------------------------- */
static double lit_mx(const swarp_error_config* c, double n, double f, double z, double np) {
    return c->res_ix / c->res_s * f * ((np + z - n) / (z * (np + f - n))); /* [RHS] (2.3) */
}
static double lit_mz(const swarp_error_config* c, double n, double f, double z, double np) {
    return c->res_iy / c->res_t * (f - n) / (2 * tan(c->theta)) *
           ((np + z - n) * (np + z - n) / (z * np * (np + f - n))); /* [RHS] (2.4) */
}
static double lit_mx_psm(const swarp_error_config* c) { return c->res_ix / c->res_s; } /* [RHS] (2.5) */
static double lit_mz_psm(const swarp_error_config* c, double z) { /* [RHS] (2.6) */
    return c->res_iy / c->res_t * (c->z_far - c->z_near) / (2 * tan(c->theta)) * z / (c->z_near * c->z_far);
}
static double lit_mx_uni(const swarp_error_config* c, double z) { /* [RHS] (2.7) */
    return c->res_ix / c->res_s * c->z_far / z;
}
static double lit_mz_uni(const swarp_error_config* c, double z) { /* [RHS] (2.8) */
    return c->res_iy / c->res_t * (c->z_far - c->z_near) / (2 * tan(c->theta)) / z;
}

static swarp_error_config rand_cfg(uint64_t* s) {
    swarp_error_config c;
    memset(&c, 0, sizeof c);
    c.z_near = tc_logu(s, 1e-2, 1e2);
    c.z_far = c.z_near * tc_logu(s, 1.05, 1e4);
    c.theta = tc_uniform(s, 5, 80) * TC_DEG;
    c.res_ix = floor(tc_uniform(s, 64, 4096));
    c.res_iy = floor(tc_uniform(s, 64, c.res_ix + 1));
    c.res_s = floor(tc_uniform(s, 64, 8192));
    c.res_t = floor(tc_uniform(s, 64, c.res_s + 1));
    return c;
}

START_TEST(mx_mz_match_23_24) {
    uint64_t s = 0x5eed1001;
    for (int k = 0; k < 500; ++k) {
        swarp_error_config c = rand_cfg(&s);
        double z = tc_uniform(&s, c.z_near, c.z_far), np = c.z_near * tc_logu(&s, 1e-2, 1e6);
        double mx = 0, mz = 0;
        ck_assert_int_eq(swarp_error_mx(&c, z, np, &mx), SWARP_OK);
        ck_assert_int_eq(swarp_error_mz(&c, z, np, &mz), SWARP_OK);
        ck_assert_rel(mx, lit_mx(&c, c.z_near, c.z_far, z, np), 1e-12);
        ck_assert_rel(mz, lit_mz(&c, c.z_near, c.z_far, z, np), 1e-12);
    }
}
END_TEST

START_TEST(psm_and_uniform_limits) {
    uint64_t s = 0x5eed1002;
    for (int k = 0; k < 800; ++k) {
        swarp_error_config c = rand_cfg(&s);
        c.z_far = c.z_near * tc_logu(&s, 1.05, 1e3);
        double z = (k % 5 == 0) ? c.z_near : (k % 5 == 1) ? c.z_far : tc_uniform(&s, c.z_near, c.z_far);
        double mx = 0, mz = 0;
        /* n' = n: PSM (2.5), (2.6) */
        ck_assert_int_eq(swarp_error_mx(&c, z, c.z_near, &mx), SWARP_OK);
        ck_assert_int_eq(swarp_error_mz(&c, z, c.z_near, &mz), SWARP_OK);
        ck_assert_rel(mx, lit_mx_psm(&c), 1e-14);
        ck_assert_rel(mz, lit_mz_psm(&c, z), 1e-13);
        /* n' = +inf: the closed-form uniform limit (2.7), (2.8) */
        ck_assert_int_eq(swarp_error_mx(&c, z, INFINITY, &mx), SWARP_OK);
        ck_assert_int_eq(swarp_error_mz(&c, z, INFINITY, &mz), SWARP_OK);
        ck_assert_rel(mx, lit_mx_uni(&c, z), 1e-14);
        ck_assert_rel(mz, lit_mz_uni(&c, z), 1e-14);
        /* n' -> 1e12 tends to it (relative distance ~ (f - n)/n') */
        double bx = 0, bz = 0;
        ck_assert_int_eq(swarp_error_mx(&c, z, 1e12, &bx), SWARP_OK);
        ck_assert_int_eq(swarp_error_mz(&c, z, 1e12, &bz), SWARP_OK);
        double tol = 2.0 * (c.z_far - c.z_near) / 1e12 + 1e-14; /* r1 r2 - 1 <= 2 (f - n)/n' */
        ck_assert_rel(bx, mx, tol);
        ck_assert_rel(bz, mz, tol);
        ck_assert_rel(lit_mx(&c, c.z_near, c.z_far, z, 1e12), mx, tol);
        ck_assert_rel(lit_mz(&c, c.z_near, c.z_far, z, 1e12), mz, tol);
        /* and n' = 1e300 neither overflows nor loses accuracy */
        ck_assert_int_eq(swarp_error_mz(&c, z, 1e300, &bz), SWARP_OK);
        ck_assert_rel(bz, mz, 1e-14);
    }
}
END_TEST

START_TEST(max_equals_dense_sample_max) {
    uint64_t s = 0x5eed1003;
    for (int k = 0; k < 200; ++k) {
        swarp_error_config c = rand_cfg(&s);
        double np = (k % 4 == 0) ? INFINITY : c.z_near * tc_logu(&s, 0.05, 1e5);
        double max_mx = 0, max_mz = 0, dx = 0, dz = 0;
        ck_assert_int_eq(swarp_error_max(&c, np, &max_mx, &max_mz), SWARP_OK);
        const int N = 20000;
        int bad = 0;
        for (int i = 0; i <= N; ++i) {
            /* geometric spacing (dense near n where the curves are steep) */
            double z = (i == N) ? c.z_far : c.z_near * pow(c.z_far / c.z_near, (double)i / N);
            double vx = 0, vz = 0;
            /* (one assertion per point is too slow under Check: count instead) */
            bad += swarp_error_mx(&c, z, np, &vx) != SWARP_OK;
            bad += swarp_error_mz(&c, z, np, &vz) != SWARP_OK;
            dx = vx > dx ? vx : dx;
            dz = vz > dz ? vz : dz;
        }
        ck_assert_int_eq(bad, 0);
        ck_assert_rel(max_mx, dx, 1e-9);
        ck_assert_rel(max_mz, dz, 1e-9);
        double only = 0;
        ck_assert_int_eq(swarp_error_max(&c, np, NULL, &only), SWARP_OK);
        ck_assert(only == max_mz);
        ck_assert_int_eq(swarp_error_max(&c, np, &only, NULL), SWARP_OK);
        ck_assert(only == max_mx);
    }
}
END_TEST

START_TEST(bad_inputs_single_range) {
    swarp_error_config good = {1, 100, TC_PI / 6, 1024, 768, 1024, 1024, {0}};
    double out = TC_SENTINEL, out2 = TC_SENTINEL;
    typedef struct { swarp_error_config c; double z, np; swarp_status want; } row;
    row rows[24];
    int k = 0;
#define ROW(field, value, zz, npp, st)                 \
    do {                                               \
        rows[k].c = good;                              \
        rows[k].c.field = value;                       \
        rows[k].z = zz, rows[k].np = npp, rows[k].want = st; \
        ++k;                                           \
    } while (0)
    ROW(z_near, 0.0, 50, 1, SWARP_ERR_NEAR_FAR);
    ROW(z_near, -1.0, 50, 1, SWARP_ERR_NEAR_FAR);
    ROW(z_near, NAN, 50, 1, SWARP_ERR_NON_FINITE);
    ROW(z_far, 1.0, 1, 1, SWARP_ERR_NEAR_FAR);
    ROW(z_far, INFINITY, 50, 1, SWARP_ERR_NON_FINITE);
    ROW(theta, 0.0, 50, 1, SWARP_ERR_FOV);
    ROW(theta, TC_HALF_PI, 50, 1, SWARP_ERR_FOV);
    ROW(theta, NAN, 50, 1, SWARP_ERR_NON_FINITE);
    ROW(res_ix, 0.0, 50, 1, SWARP_ERR_RESOLUTION);
    ROW(res_iy, -5.0, 50, 1, SWARP_ERR_RESOLUTION);
    ROW(res_s, NAN, 50, 1, SWARP_ERR_RESOLUTION);
    ROW(res_t, INFINITY, 50, 1, SWARP_ERR_RESOLUTION);
    ROW(_reserved[2], 1u, 50, 1, SWARP_ERR_RESERVED_NONZERO);
    ROW(z_near, 1.0, 0.5, 1, SWARP_ERR_OUT_OF_RANGE);
    ROW(z_near, 1.0, 100.5, 1, SWARP_ERR_OUT_OF_RANGE);
    ROW(z_near, 1.0, NAN, 1, SWARP_ERR_NON_FINITE);
    ROW(z_near, 1.0, INFINITY, 1, SWARP_ERR_NON_FINITE);
    ROW(z_near, 1.0, 50, 0.0, SWARP_ERR_OUT_OF_RANGE);
    ROW(z_near, 1.0, 50, -3.0, SWARP_ERR_OUT_OF_RANGE);
    ROW(z_near, 1.0, 50, NAN, SWARP_ERR_NON_FINITE);
    ROW(z_near, 1.0, 50, -INFINITY, SWARP_ERR_NON_FINITE);
    /* n' so small that (n' + z - n)/n' overflows */
    ROW(z_far, 1e300, 1e300, 1e-300, SWARP_ERR_OVERFLOW);
#undef ROW
    for (int i = 0; i < k; ++i) {
        const row* r = &rows[i];
        ck_assert_int_eq(swarp_error_mz(&r->c, r->z, r->np, &out), r->want);
        ck_assert(out == TC_SENTINEL);
        if (r->want != SWARP_ERR_OVERFLOW) {
            ck_assert_int_eq(swarp_error_mx(&r->c, r->z, r->np, &out), r->want);
            ck_assert(out == TC_SENTINEL);
        }
        if (r->z == 50 || r->want == SWARP_ERR_OVERFLOW) { /* statuses not about z */
            ck_assert_int_eq(swarp_error_max(&r->c, r->np, &out, &out2), r->want);
            ck_assert(out == TC_SENTINEL && out2 == TC_SENTINEL);
        }
    }
    ck_assert_int_eq(swarp_error_mx(NULL, 50, 1, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_error_mx(&good, 50, 1, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_error_mz(NULL, 50, 1, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_error_mz(&good, 50, 1, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_error_max(NULL, 1, &out, &out2), SWARP_ERR_NULL_POINTER);
    ck_assert(out == TC_SENTINEL && out2 == TC_SENTINEL);
}
END_TEST

/* ---- partitioned frustum --------------------------------------------------- */

START_TEST(split_curve_is_per_split_metric) {
    uint64_t s = 0x5eed1004;
    for (int k = 0; k < 300; ++k) {
        swarp_error_config c = rand_cfg(&s);
        size_t m = 1 + (size_t)(tc_next(&s) % 8);
        double splits[9], nps[8];
        /* random strictly increasing splits */
        splits[0] = c.z_near;
        for (size_t i = 1; i <= m; ++i) splits[i] = splits[i - 1] * tc_logu(&s, 1.05, 10.0);
        for (size_t i = 0; i < m; ++i)
            nps[i] = (tc_next(&s) % 3 == 0) ? INFINITY : splits[i] * tc_logu(&s, 0.1, 1e3);
        /* cfg near/far are ignored: make them nonsense */
        c.z_near = -7, c.z_far = -9;
        enum { N = 400 };
        double z[N + 18], mx[N + 18], mz[N + 18];
        size_t cnt = 0;
        for (int i = 0; i <= N; ++i)
            z[cnt++] = (i == N) ? splits[m] : splits[0] + (splits[m] - splits[0]) * i / N;
        for (size_t i = 0; i <= m; ++i) z[cnt++] = splits[i]; /* every border */
        /* the left limit at each inner border: a split's far-end value */
        for (size_t i = 1; i < m; ++i) z[cnt++] = nextafter(splits[i], 0.0);
        ck_assert_int_eq(swarp_error_split_curve(&c, splits, nps, m, z, cnt, mx, mz), SWARP_OK);
        double dense_mx = 0, dense_mz = 0;
        for (size_t j = 0; j < cnt; ++j) {
            /* the split that holds z: linear scan, borders go to the split starting there */
            size_t i = 0;
            while (i + 1 < m && z[j] >= splits[i + 1]) ++i;
            swarp_error_config ci = c;
            ci.z_near = splits[i], ci.z_far = splits[i + 1];
            double ex = isinf(nps[i]) ? lit_mx_uni(&ci, z[j]) : lit_mx(&ci, ci.z_near, ci.z_far, z[j], nps[i]);
            double ez = isinf(nps[i]) ? lit_mz_uni(&ci, z[j]) : lit_mz(&ci, ci.z_near, ci.z_far, z[j], nps[i]);
            ck_assert_rel(mx[j], ex, 1e-12);
            ck_assert_rel(mz[j], ez, 1e-12);
            dense_mx = mx[j] > dense_mx ? mx[j] : dense_mx;
            dense_mz = mz[j] > dense_mz ? mz[j] : dense_mz;
        }
        /* exact maxima: per split at the ends, overall = max over splits */
        double smx[8], smz[8], amx = 0, amz = 0;
        ck_assert_int_eq(swarp_error_split_max(&c, splits, nps, m, smx, smz, &amx, &amz), SWARP_OK);
        double bx = 0, bz = 0;
        for (size_t i = 0; i < m; ++i) {
            swarp_error_config ci = c;
            ci.z_near = splits[i], ci.z_far = splits[i + 1];
            double ex = 0, ez = 0;
            ck_assert_int_eq(swarp_error_max(&ci, nps[i], &ex, &ez), SWARP_OK);
            ck_assert(smx[i] == ex && smz[i] == ez);
            bx = ex > bx ? ex : bx;
            bz = ez > bz ? ez : bz;
        }
        ck_assert(amx == bx && amz == bz);
        /* dense samples (borders included) never exceed it and reach it */
        ck_assert(dense_mx <= amx * (1 + 1e-12) && dense_mz <= amz * (1 + 1e-12));
        ck_assert_rel(dense_mx, amx, 1e-9);
        ck_assert_rel(dense_mz, amz, 1e-9);
        /* one split is the single-range metric */
        if (m == 1) {
            swarp_error_config c1 = c;
            c1.z_near = splits[0], c1.z_far = splits[1];
            double ex = 0;
            ck_assert_int_eq(swarp_error_mz(&c1, z[5], nps[0], &ex), SWARP_OK);
            ck_assert(ex == mz[5]);
        }
    }
}
END_TEST

START_TEST(split_curve_border_belongs_to_next_split) {
    swarp_error_config c = {0, 0, TC_PI / 6, 1024, 768, 1024, 1024, {0}};
    const double splits[3] = {1, 10, 100};
    const double nps[2] = {INFINITY, INFINITY};
    const double z[1] = {10};
    double mx = 0, mz = 0;
    ck_assert_int_eq(swarp_error_split_curve(&c, splits, nps, 2, z, 1, &mx, &mz), SWARP_OK);
    /* uniform over [10, 100] at its near end: res f/z = 100/10 */
    ck_assert_rel(mx, 1.0 * 100 / 10, 1e-15);
    ck_assert_rel(mz, 768.0 / 1024 * 90 / (2 * tan(TC_PI / 6)) / 10, 1e-15);
    /* NULL outputs are allowed, count 0 with z NULL too */
    ck_assert_int_eq(swarp_error_split_curve(&c, splits, nps, 2, z, 1, NULL, &mz), SWARP_OK);
    ck_assert_int_eq(swarp_error_split_curve(&c, splits, nps, 2, NULL, 0, NULL, NULL), SWARP_OK);
}
END_TEST

START_TEST(split_bad_inputs_leave_outputs_untouched) {
    swarp_error_config c = {0, 0, TC_PI / 6, 1024, 768, 1024, 1024, {0}};
    double splits[3] = {1, 10, 100}, nps[2] = {5, 50}, z[3] = {1, 50, 100};
    double mx[3], mz[3], smx[2], smz[2], amx = TC_SENTINEL, amz = TC_SENTINEL;
    for (int i = 0; i < 3; ++i) mx[i] = mz[i] = TC_SENTINEL;
    for (int i = 0; i < 2; ++i) smx[i] = smz[i] = TC_SENTINEL;
    const double sent3[3] = {TC_SENTINEL, TC_SENTINEL, TC_SENTINEL};
    const double sent2[2] = {TC_SENTINEL, TC_SENTINEL};
#define CHECK(expr, want)                                                                   \
    do {                                                                                    \
        ck_assert_int_eq((expr), (want));                                                   \
        ck_assert(memcmp(mx, sent3, sizeof mx) == 0 && memcmp(mz, sent3, sizeof mz) == 0);  \
        ck_assert(memcmp(smx, sent2, sizeof smx) == 0 && memcmp(smz, sent2, sizeof smz) == 0); \
        ck_assert(amx == TC_SENTINEL && amz == TC_SENTINEL);                                \
    } while (0)
#define BOTH(want)                                                                 \
    do {                                                                           \
        CHECK(swarp_error_split_curve(&c, splits, nps, 2, z, 3, mx, mz), want);    \
        CHECK(swarp_error_split_max(&c, splits, nps, 2, smx, smz, &amx, &amz), want); \
    } while (0)
    CHECK(swarp_error_split_curve(NULL, splits, nps, 2, z, 3, mx, mz), SWARP_ERR_NULL_POINTER);
    CHECK(swarp_error_split_curve(&c, NULL, nps, 2, z, 3, mx, mz), SWARP_ERR_NULL_POINTER);
    CHECK(swarp_error_split_curve(&c, splits, NULL, 2, z, 3, mx, mz), SWARP_ERR_NULL_POINTER);
    CHECK(swarp_error_split_curve(&c, splits, nps, 2, NULL, 3, mx, mz), SWARP_ERR_NULL_POINTER);
    CHECK(swarp_error_split_max(NULL, splits, nps, 2, smx, smz, &amx, &amz), SWARP_ERR_NULL_POINTER);
    CHECK(swarp_error_split_curve(&c, splits, nps, 0, z, 3, mx, mz), SWARP_ERR_SPLIT_COUNT);
    CHECK(swarp_error_split_max(&c, splits, nps, 0, smx, smz, &amx, &amz), SWARP_ERR_SPLIT_COUNT);
    c._reserved[0] = 3;
    BOTH(SWARP_ERR_RESERVED_NONZERO);
    c._reserved[0] = 0;
    c.theta = 2.0;
    BOTH(SWARP_ERR_FOV);
    c.theta = TC_PI / 6;
    c.res_s = 0;
    BOTH(SWARP_ERR_RESOLUTION);
    c.res_s = 1024;
    splits[1] = NAN;
    BOTH(SWARP_ERR_NON_FINITE);
    splits[1] = 100;
    BOTH(SWARP_ERR_NOT_INCREASING);
    splits[1] = 0.5;
    BOTH(SWARP_ERR_NOT_INCREASING);
    splits[1] = 10;
    splits[0] = 0.0;
    BOTH(SWARP_ERR_NEAR_FAR);
    splits[0] = 1;
    nps[1] = 0.0;
    BOTH(SWARP_ERR_OUT_OF_RANGE);
    nps[1] = NAN;
    BOTH(SWARP_ERR_NON_FINITE);
    nps[1] = 50;
    z[2] = 100.0000001;
    CHECK(swarp_error_split_curve(&c, splits, nps, 2, z, 3, mx, mz), SWARP_ERR_OUT_OF_RANGE);
    z[2] = 0.99;
    CHECK(swarp_error_split_curve(&c, splits, nps, 2, z, 3, mx, mz), SWARP_ERR_OUT_OF_RANGE);
    z[2] = NAN;
    CHECK(swarp_error_split_curve(&c, splits, nps, 2, z, 3, mx, mz), SWARP_ERR_NON_FINITE);
    z[2] = 100;
    /* overflow in the LAST split: nothing written for the earlier ones either */
    double big[3] = {1, 10, 1e300}, tiny[2] = {5, 1e-300}, zb[3] = {1, 5, 1e300};
    CHECK(swarp_error_split_curve(&c, big, tiny, 2, zb, 3, mx, mz), SWARP_ERR_OVERFLOW);
    CHECK(swarp_error_split_max(&c, big, tiny, 2, smx, smz, &amx, &amz), SWARP_ERR_OVERFLOW);
    /* and the good call works */
    ck_assert_int_eq(swarp_error_split_curve(&c, splits, nps, 2, z, 3, mx, mz), SWARP_OK);
    ck_assert(mx[0] != TC_SENTINEL && mz[2] != TC_SENTINEL);
#undef BOTH
#undef CHECK
}
END_TEST

TCase* tcase_error(void) {
    TCase* tc = tcase_create("error");
    tcase_add_test(tc, mx_mz_match_23_24);
    tcase_add_test(tc, psm_and_uniform_limits);
    tcase_add_test(tc, max_equals_dense_sample_max);
    tcase_add_test(tc, bad_inputs_single_range);
    tcase_add_test(tc, split_curve_is_per_split_metric);
    tcase_add_test(tc, split_curve_border_belongs_to_next_split);
    tcase_add_test(tc, split_bad_inputs_leave_outputs_untouched);
    return tc;
}
