#define _POSIX_C_SOURCE 200809L
/* Edge cases of the filter stage at the ends of the double range: EVSM's documented exponent status on
 * overflow, and Lloyd's minimum split gap far from the origin. */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define SENTINEL (-7.25e33)

/* e^{2c|x|} overflowing is SWARP_ERR_FILTER_EXPONENT (documented), not
 * SWARP_ERR_NON_FINITE (which blames a NaN/Inf input); outputs untouched. */
START_TEST(evsm_overflow_is_exponent_error) {
    double m[4];
    tu_fill(m, 4, SENTINEL);
    ck_assert_int_eq(swarp_evsm_moments(2.0, 354.0, 1.0, m), SWARP_ERR_FILTER_EXPONENT); /* e^{1416} */
    ck_assert_int_eq(swarp_evsm_moments(-3.0, 1.0, 200.0, m), SWARP_ERR_FILTER_EXPONENT); /* e^{1200} */
    ck_assert(tu_untouched(m, 4, SENTINEL));
    /* the boundary of the documented domain: c = 354 with x = 1 is finite */
    ck_assert_int_eq(swarp_evsm_moments(1.0, 354.0, 354.0, m), SWARP_OK);
    ck_assert(fabs(m[1] / exp(708.0) - 1.0) < 1e-13);
    double M[4] = {1, 1, -1, 1}, v = SENTINEL;
    ck_assert_int_eq(swarp_evsm_visibility(M, 10.0, 100.0, 1.0, 0.0, &v), SWARP_ERR_FILTER_EXPONENT);
    ck_assert_int_eq(swarp_evsm_visibility(M, -10.0, 1.0, 100.0, 0.0, &v), SWARP_ERR_FILTER_EXPONENT);
    ck_assert(tu_untouched(&v, 1, SENTINEL));
    /* NaN input stays NON_FINITE */
    tu_fill(m, 4, SENTINEL);
    ck_assert_int_eq(swarp_evsm_moments(NAN, 5.0, 5.0, m), SWARP_ERR_NON_FINITE);
    ck_assert(tu_untouched(m, 4, SENTINEL));
}
END_TEST

/* smallest gap between consecutive splits, in ulps of the largest split */
static double min_gap_ulps(const double* s, uint32_t n) {
    double mag = fmax(fabs(s[0]), fabs(s[n]));
    double ulp = nextafter(mag, INFINITY) - mag, g = INFINITY;
    for (uint32_t i = 0; i < n; ++i) g = fmin(g, (s[i + 1] - s[i]) / ulp);
    return g;
}

/* Depths 1e6 .. 1e6 + 0.0045: 1e-9 of the range (4.5e-12) is below one ulp
 * of 1e6 (1.2e-10).  Samples piled on two depths pull the inner splits
 * together; the documented minimum gap (>= 2 ulps of the splits, >= 1e-9 of
 * the range) must survive the way back to depth units. */
START_TEST(lloyd_gap_far_from_origin) {
    uint64_t s = 0x11A7ull;
    const double s0 = 1e6, range = 0.0045;
    int runs = 0;
    for (int n = 0; n < 200; ++n) {
        uint32_t layers = 2 + (uint32_t)(tu_splitmix64(&s) % 6);
        double in[16], out[16], mu[64], s2[64];
        for (uint32_t i = 0; i <= layers; ++i) in[i] = s0 + range * i / layers;
        in[layers] = s0 + range;
        double a = s0 + tu_uniform(&s, 0, range), b = a + (n % 3) * 1e-10;
        for (int j = 0; j < 64; ++j) {
            mu[j] = (j % 2) ? a : b;
            s2[j] = (j % 5 == 0) ? 1e-24 : 0.0; /* sigma ~ 1e-12: below an ulp */
        }
        swarp_lloyd_options o;
        memset(&o, 0, sizeof o);
        o.weight_clamp_lo = 1.0; /* every sample counts */
        swarp_lloyd_report rep;
        swarp_status st = swarp_lvsm_lloyd(mu, s2, 64, &o, in, layers, out, &rep);
        ck_assert(!swarp_status_is_error(st));
        ck_assert(out[0] == in[0] && out[layers] == in[layers]);
        ck_assert_msg(min_gap_ulps(out, layers) >= 2.0, "layers %u: min gap %g ulps", layers,
                      min_gap_ulps(out, layers));
        for (uint32_t i = 0; i < layers; ++i) ck_assert(out[i + 1] - out[i] >= 1e-9 * range);
        ++runs;
    }
    ck_assert_int_eq(runs, 200);
}
END_TEST

/* PCSS penumbra w_light (d_r - d_b)/d_b without intermediate overflow or
 * underflow (a representable width is not NON_FINITE, and a subnormal
 * w_light gives 129 DBL_TRUE_MIN, not a product rounded to 100); an unrepresentable width is
 * SWARP_ERR_OVERFLOW with the output untouched. */
START_TEST(pcss_penumbra_extreme_scales) {
    double w = -1;
    ck_assert_int_eq(swarp_pcss_penumbra(12.0, 8.0, DBL_MAX / 2, &w), SWARP_OK); /* 4 (DBL_MAX/2)/8 */
    ck_assert(w == DBL_MAX / 4);
    ck_assert_int_eq(swarp_pcss_penumbra(1.296, 0.01, DBL_TRUE_MIN, &w), SWARP_OK);
    long double ref = (1.296L - 0.01L) / 0.01L; /* in units of DBL_TRUE_MIN: 128.6 */
    ck_assert(fabsl(w / DBL_TRUE_MIN - ref) <= 1.0L);
    w = 7.25;
    ck_assert_int_eq(swarp_pcss_penumbra(1.88, 0.015, DBL_MAX, &w), SWARP_ERR_OVERFLOW);
    ck_assert(w == 7.25);
}
END_TEST

/* MSM bound at extreme depth scales: z_f = +-1e300 against moments in
 * [0, 1] (z_f^2 overflowed: NON_FINITE) gives the limits 0 / 1; moments that
 * are no distribution's with b_3 = 1e300 (q1^2 overflowed in the two-atom
 * branch) give a visibility in [0, 1]; scaling all depths by 2^200 changes
 * nothing (the bound is scale-invariant and the scaling is exact). */
START_TEST(msm_visibility_extreme_scales) {
    const double z[2] = {0.2, 0.7}, w[2] = {0.4, 0.6};
    double b[4] = {0, 0, 0, 0}, bs[4];
    for (int j = 0; j < 2; ++j)
        for (int i = 0, p = 1; i < 4; ++i, ++p) b[i] += w[j] * pow(z[j], p);
    double v = -1;
    ck_assert(!swarp_status_is_error(swarp_msm_visibility(b, 1e300, &v)));
    ck_assert(v == 0.0);
    ck_assert(!swarp_status_is_error(swarp_msm_visibility(b, -1e300, &v)));
    ck_assert(v == 1.0);
    for (int i = 0; i < 4; ++i) bs[i] = ldexp(b[i], 200 * (i + 1));
    for (double zf = 0.1; zf < 1.0; zf += 0.2) {
        double v1 = -1, v2 = -2;
        swarp_status s1 = swarp_msm_visibility(b, zf, &v1), s2 = swarp_msm_visibility(bs, ldexp(zf, 200), &v2);
        ck_assert_int_eq(s1, s2);
        ck_assert(v1 == v2);
    }
    double bad[4] = {0.042471952366984977, 0.0036077334757268816, 1e300, 2.6031481663760731e-05};
    v = -1;
    ck_assert(!swarp_status_is_error(swarp_msm_visibility(bad, 0.8457120933991441, &v)));
    ck_assert(v >= 0.0 && v <= 1.0);
}
END_TEST

/* LVSM: a variance floor that overflows in warped units (min_variance near
 * DBL_MAX, or a layer 1e-300 wide) made the Chebyshev bound Inf/Inf = NaN ->
 * NON_FINITE; the bound's limit is 1 (a huge variance hides nothing). */
START_TEST(lvsm_visibility_huge_variance_floor) {
    const double splits[3] = {0.0, 1.0, 2.0};
    const double mom[4] = {0.2, 0.05, 0.7, 0.5};
    double v = -1;
    ck_assert(!swarp_status_is_error(swarp_lvsm_visibility(mom, splits, 2, 0.1, 0.0, 0.5, DBL_MAX, &v)));
    ck_assert(v == 1.0);
    const double tiny[3] = {0.0, 1e-300, 2e-300};
    v = -1;
    ck_assert(!swarp_status_is_error(swarp_lvsm_visibility(mom, tiny, 2, 1e-301, 0.0, 0.5e-300, 1e-6, &v)));
    ck_assert(v == 1.0);
    /* an ordinary floor still bounds: well behind the mean, small variance */
    v = -1;
    ck_assert(!swarp_status_is_error(swarp_lvsm_visibility(mom, splits, 2, 0.1, 0.0, 0.95, 1e-6, &v)));
    ck_assert(v > 0.0 && v < 1.0);
}
END_TEST

/* ---- visibility forms whose literal evaluation over- or underflows ------ */

/* The references use long double for its 15-bit exponent (d^2 ~ 1e308,
 * DBL_MAX k^2); valgrind emulates it with doubles, so there the tests skip
 * (saying so), as in tests/model/test_edges_model.c.  The -Werror and sanitizer runs check. */
/* long_double_is_wide() and REQUIRE_WIDE_LONG_DOUBLE(): test_util.h */

/* [VSM] (3.3) in long double, floor mv k^2 */
static long double ref_cheb(long double m1, long double m2, long double t, long double mv, long double k) {
    if (t <= m1) return 1.0L;
    long double s2 = m2 - m1 * m1, fl = mv * k * k, d = t - m1;
    if (s2 < fl) s2 = fl;
    return s2 / (s2 + d * d);
}

/* (t - mu)^2 beyond DBL_MAX with sigma^2 ~ DBL_MAX, or the floor ~ DBL_MAX:
 * sigma2 + d^2 overflows, and the literal ratio gives 0 instead of 0.18 or
 * 1; the ratio form keeps p_max. */
START_TEST(vsm_chebyshev_ratio_form) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double cases[][4] = {{0.17778446959859262, 1.7976931348623157e+308, 2.9055173683535986e+154,
                                3.0541408616713719e-05},
                               {0.6186983591797961, 0.38278765965177197, 5.7052227388860677e+150,
                                1.7976931348623157e+308},
                               {0.65672575210955919, 1.7976931348623157e+308, 1.1153642188584194e+150, 0.0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const double* a = cases[i];
        double p = SENTINEL;
        ck_assert_int_eq(swarp_vsm_chebyshev(a, a[2], a[3], &p), SWARP_OK);
        long double ref = ref_cheb(a[0], a[1], a[2], a[3], 1.0L);
        ck_assert_msg(fabsl(p - ref) <= 1e-14L, "case %zu: p_max %.17g vs %.17Lg", i, p, ref);
    }
}
END_TEST

/* EVSM with min_variance = DBL_MAX: the floor min_variance (c e^{c t})^2
 * overflows to Inf, and Inf/Inf = NaN must not surface as
 * SWARP_ERR_NON_FINITE for valid input; the bound is ~1. */
START_TEST(evsm_visibility_huge_floor) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double M[4] = {1, 1, -1, 1}, t = 0.027107479101624476, cp = 4.5366975434941672,
                 cn = 30.967730069323352;
    double v = SENTINEL;
    ck_assert_int_eq(swarp_evsm_visibility(M, t, cp, cn, DBL_MAX, &v), SWARP_OK);
    long double wp = expl(cp * (long double)t), wn = -expl(-cn * (long double)t);
    long double rp = ref_cheb(M[0], M[1], wp, DBL_MAX, cp * wp);
    long double rn = ref_cheb(M[2], M[3], wn, DBL_MAX, cn * wn);
    long double ref = rp < rn ? rp : rn;
    ck_assert_msg(fabsl(v - ref) <= 1e-14L, "visibility %.17g vs %.17Lg", v, ref);
}
END_TEST

/* Uniform LVSM layers of a subnormal depth range: the width
 * h = (s_N - s_0)/N rounds to 0, which would put t = s_0 in layer 1.  The
 * range is scaled by a power of two first (exact), so splits are where they
 * belong. */
START_TEST(lvsm_layer_uniform_subnormal_range) {
    uint32_t L = 99;
    ck_assert_int_eq(swarp_lvsm_layer_uniform(0.0, 0.0, DBL_TRUE_MIN, 3, &L), SWARP_OK);
    ck_assert_uint_eq(L, 0);
    ck_assert_int_eq(swarp_lvsm_layer_uniform(-0.0, -0.0, DBL_TRUE_MIN, 46, &L), SWARP_OK);
    ck_assert_uint_eq(L, 0);
    ck_assert_int_eq(swarp_lvsm_layer_uniform(DBL_TRUE_MIN, 0.0, DBL_TRUE_MIN, 3, &L), SWARP_OK);
    ck_assert_uint_eq(L, 2);
    /* s_j = j DBL_TRUE_MIN: a depth on a split belongs to the layer above */
    for (uint32_t j = 0; j < 4; ++j) {
        ck_assert_int_eq(swarp_lvsm_layer_uniform(j * DBL_TRUE_MIN, 0.0, 4 * DBL_TRUE_MIN, 4, &L), SWARP_OK);
        ck_assert_uint_eq(L, j);
    }
    ck_assert_int_eq(swarp_lvsm_layer_uniform(3 * DBL_TRUE_MIN, DBL_TRUE_MIN, 5 * DBL_TRUE_MIN, 8, &L), SWARP_OK);
    ck_assert_uint_eq(L, 4);
}
END_TEST

/* The transition weight w = (t - (s - band)) / (2 band) as written rounds
 * s - band at the magnitude of s: with band below an ulp of s and t = s it
 * gives 0 under round-to-nearest and 1 under FE_DOWNWARD; the exact value
 * is 1/2, and it must be that in every rounding mode. */
START_TEST(lvsm_transition_rounding_mode) {
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    const double s[3] = {1.0, 2.0, 3.0};
    for (size_t k = 0; k < 4; ++k) {
        uint32_t lo = 9, hi = 9;
        double w = SENTINEL, w2 = SENTINEL;
        fesetround(modes[k]);
        swarp_status st = swarp_lvsm_transition(2.0, s, 2, 1e-69, &lo, &hi, &w);
        /* band 1e-9 next to s = 0.5: t = s - band exactly
         * representable to an ulp of 0.5, the weight within 1e-6 of 0 */
        const double s2[3] = {0.25, 0.5, 0.75};
        uint32_t lo2, hi2;
        swarp_status st2 = swarp_lvsm_transition(0.5 - 0x1p-30, s2, 2, 0x1p-30, &lo2, &hi2, &w2);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_uint_eq(lo, 0);
        ck_assert_uint_eq(hi, 1);
        ck_assert_msg(w == 0.5, "mode %zu: w = %.17g, want 1/2", k, w);
        ck_assert_int_eq(st2, SWARP_OK);
        ck_assert_msg(w2 == 0.0, "mode %zu: w = %.17g, want 0", k, w2);
    }
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_filter");
    TCase* t = tcase_create("extreme_scales");
    tcase_add_test(t, evsm_overflow_is_exponent_error);
    tcase_add_test(t, lloyd_gap_far_from_origin);
    tcase_add_test(t, pcss_penumbra_extreme_scales);
    tcase_add_test(t, msm_visibility_extreme_scales);
    tcase_add_test(t, lvsm_visibility_huge_variance_floor);
    suite_add_tcase(s, t);
    t = tcase_create("no_intermediate_overflow");
    tcase_add_test(t, vsm_chebyshev_ratio_form);
    tcase_add_test(t, evsm_visibility_huge_floor);
    tcase_add_test(t, lvsm_layer_uniform_subnormal_range);
    suite_add_tcase(s, t);
    t = tcase_create("transition_rounding_mode");
    tcase_add_test(t, lvsm_transition_rounding_mode);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
