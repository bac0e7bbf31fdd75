#define _POSIX_C_SOURCE 200809L
/* Edge cases of the filter stage found by the robustness sweep (issue 9,
 * docs/quality.md "Findings"): EVSM's documented exponent status on
 * overflow, and Lloyd's minimum split gap far from the origin. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
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

int main(void) {
    Suite* s = suite_create("edges_filter");
    TCase* t = tcase_create("findings");
    tcase_add_test(t, evsm_overflow_is_exponent_error);
    tcase_add_test(t, lloyd_gap_far_from_origin);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
