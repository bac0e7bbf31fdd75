#define _POSIX_C_SOURCE 200809L
/* Core: split schemes [RHS] (3.6), (3.7), (3.8), (4.1). */
#include <stdlib.h>

#include "test_core.h"

enum { CAP = SWARP_SPLIT_MAX_COUNT + 1 };

static void fill(double* a, size_t k) {
    for (size_t i = 0; i < k; ++i) a[i] = TC_SENTINEL;
}
static int untouched(const double* a, size_t k) {
    for (size_t i = 0; i < k; ++i)
        if (a[i] != TC_SENTINEL) return 0;
    return 1;
}

START_TEST(schemes_cover_range_strictly_increasing) {
    uint64_t s = 0x5eed2001;
    for (int k = 0; k < 800; ++k) {
        double n = tc_logu(&s, 1e-3, 1e3), f = n * tc_logu(&s, 1.001, 1e6);
        uint32_t m = 1 + (uint32_t)(tc_next(&s) % SWARP_SPLIT_MAX_COUNT);
        double lambda = tc_uniform(&s, 0, 1);
        double np = n + (f - n) * tc_uniform(&s, 0, 0.4), fp = f - (f - n) * tc_uniform(&s, 0, 0.4);
        for (int scheme = 0; scheme < 4; ++scheme) {
            double c[CAP];
            size_t cnt = 0;
            swarp_status st = scheme == 0   ? swarp_split_uniform(n, f, m, c, CAP, &cnt)
                              : scheme == 1 ? swarp_split_log(n, f, m, c, CAP, &cnt)
                              : scheme == 2 ? swarp_split_practical(n, f, lambda, m, c, CAP, &cnt)
                                            : swarp_split_pseudo(n, f, np, fp, lambda, m, c, CAP, &cnt);
            ck_assert_int_eq(st, SWARP_OK);
            ck_assert_uint_eq(cnt, (size_t)m + 1);
            ck_assert(c[0] == n && c[m] == f); /* exactly: no gap at either end */
            int bad = 0;
            for (uint32_t i = 0; i < m; ++i) bad += !(c[i + 1] > c[i]);
            ck_assert_int_eq(bad, 0);
        }
    }
}
END_TEST

START_TEST(uniform_log_practical_match_paper) {
    uint64_t s = 0x5eed2002;
    for (int k = 0; k < 800; ++k) {
        double n = tc_logu(&s, 1e-3, 1e3), f = n * tc_logu(&s, 1.01, 1e6);
        uint32_t m = 1 + (uint32_t)(tc_next(&s) % SWARP_SPLIT_MAX_COUNT);
        double lambda = tc_uniform(&s, 0, 1);
        double u[CAP], l[CAP], p[CAP], p0[CAP], p1[CAP];
        size_t cnt;
        ck_assert_int_eq(swarp_split_uniform(n, f, m, u, CAP, &cnt), SWARP_OK);
        ck_assert_int_eq(swarp_split_log(n, f, m, l, CAP, &cnt), SWARP_OK);
        ck_assert_int_eq(swarp_split_practical(n, f, lambda, m, p, CAP, &cnt), SWARP_OK);
        ck_assert_int_eq(swarp_split_practical(n, f, 0.0, m, p0, CAP, &cnt), SWARP_OK);
        ck_assert_int_eq(swarp_split_practical(n, f, 1.0, m, p1, CAP, &cnt), SWARP_OK);
        int bad = 0; /* counted, asserted once: Check is slow per assertion */
        for (uint32_t i = 0; i <= m; ++i) {
            /* [RHS] (3.6) as a weighted mean of the ends; [RHS] (3.7) with pow */
            double eu = n * ((double)(m - i) / m) + f * ((double)i / m);
            double el = n * pow(f / n, (double)i / m);
            bad += tc_rel(u[i], eu) > 1e-14;
            bad += tc_rel(l[i], el) > 1e-12;
            bad += tc_rel(p[i], (1 - lambda) * eu + lambda * el) > 1e-12; /* [RHS] (3.8) */
            bad += p0[i] != u[i]; /* lambda = 0 is uniform */
            bad += p1[i] != l[i]; /* lambda = 1 is logarithmic */
        }
        /* defining properties: equal steps, equal ratios */
        for (uint32_t i = 0; i < m; ++i) {
            bad += !(fabs(u[i + 1] - u[i] - (f - n) / m) <= 1e-12 * f);
            bad += tc_rel(l[i + 1] / l[i], pow(f / n, 1.0 / m)) > 1e-12;
        }
        ck_assert_msg(bad == 0, "n = %.17g f = %.17g m = %u lambda = %.17g: %d mismatches", n, f, m, lambda, bad);
    }
}
END_TEST

START_TEST(pseudo_matches_41_and_reduces_to_practical) {
    uint64_t s = 0x5eed2003;
    for (int k = 0; k < 800; ++k) {
        double n = tc_logu(&s, 1e-3, 1e3), f = n * tc_logu(&s, 1.01, 1e6);
        uint32_t m = 1 + (uint32_t)(tc_next(&s) % SWARP_SPLIT_MAX_COUNT);
        double lambda = tc_uniform(&s, 0, 1);
        double a[CAP], b[CAP];
        size_t ca = 0, cb = 0;
        ck_assert_int_eq(swarp_split_pseudo(n, f, n, f, lambda, m, a, CAP, &ca), SWARP_OK);
        ck_assert_int_eq(swarp_split_practical(n, f, lambda, m, b, CAP, &cb), SWARP_OK);
        ck_assert_uint_eq(ca, cb);
        ck_assert(memcmp(a, b, (m + 1) * sizeof a[0]) == 0);
        /* inner distances follow [RHS] (4.1) over [n_p, f_p] */
        double np = n + (f - n) * tc_uniform(&s, 0, 0.4), fp = f - (f - n) * tc_uniform(&s, 0, 0.4);
        ck_assert_int_eq(swarp_split_pseudo(n, f, np, fp, lambda, m, a, CAP, &ca), SWARP_OK);
        ck_assert(a[0] == n && a[m] == f);
        int bad = 0;
        for (uint32_t i = 1; i < m; ++i) {
            double t = (double)i / m;
            double e = (1 - lambda) * (np + (fp - np) * t) + lambda * (np * pow(fp / np, t));
            bad += tc_rel(a[i], e) > 1e-12;
        }
        ck_assert_int_eq(bad, 0);
    }
}
END_TEST

START_TEST(split_capacity_and_bad_inputs) {
    double c[CAP];
    size_t cnt = 777;
    /* too small a capacity: the needed count, out untouched */
    fill(c, CAP);
    ck_assert_int_eq(swarp_split_practical(1, 100, 0.5, 4, c, 4, &cnt), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(cnt, 5);
    ck_assert(untouched(c, CAP));
    cnt = 777;
    ck_assert_int_eq(swarp_split_log(1, 100, 7, NULL, 0, &cnt), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(cnt, 8);
    cnt = 777;
    ck_assert_int_eq(swarp_split_pseudo(1, 100, 2, 50, 0.5, 3, c, 3, &cnt), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(cnt, 4);
    ck_assert(untouched(c, CAP));
    /* exactly enough is fine */
    ck_assert_int_eq(swarp_split_uniform(1, 100, 4, c, 5, &cnt), SWARP_OK);
    fill(c, CAP);
    cnt = 777;

    typedef struct { double n, f, lambda, np, fp; uint32_t m; swarp_status want; } row;
    const row rows[] = {
        {NAN, 100, 0.5, 2, 50, 4, SWARP_ERR_NON_FINITE},
        {1, INFINITY, 0.5, 2, 50, 4, SWARP_ERR_NON_FINITE},
        {1, 100, NAN, 2, 50, 4, SWARP_ERR_NON_FINITE},
        {0, 100, 0.5, 2, 50, 4, SWARP_ERR_NEAR_FAR},
        {-1, 100, 0.5, 2, 50, 4, SWARP_ERR_NEAR_FAR},
        {100, 100, 0.5, 2, 50, 4, SWARP_ERR_NEAR_FAR},
        {100, 10, 0.5, 2, 50, 4, SWARP_ERR_NEAR_FAR},
        {1, 100, -0.1, 2, 50, 4, SWARP_ERR_OUT_OF_RANGE},
        {1, 100, 1.1, 2, 50, 4, SWARP_ERR_OUT_OF_RANGE},
        {1, 100, 0.5, 2, 50, 0, SWARP_ERR_SPLIT_COUNT},
        {1, 100, 0.5, 2, 50, SWARP_SPLIT_MAX_COUNT + 1, SWARP_ERR_SPLIT_COUNT},
        /* [n, f] too narrow for m distinct doubles */
        {1, 1.0000000000000002, 0.5, 1, 1.0000000000000002, 2, SWARP_ERR_DEGENERATE},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; ++i) {
        const row* r = &rows[i];
        ck_assert_int_eq(swarp_split_practical(r->n, r->f, r->lambda, r->m, c, CAP, &cnt), r->want);
        ck_assert_int_eq(swarp_split_pseudo(r->n, r->f, r->np, r->fp, r->lambda, r->m, c, CAP, &cnt),
                         r->want);
        if (r->lambda == 0.5) {
            ck_assert_int_eq(swarp_split_uniform(r->n, r->f, r->m, c, CAP, &cnt), r->want);
            ck_assert_int_eq(swarp_split_log(r->n, r->f, r->m, c, CAP, &cnt), r->want);
        }
        ck_assert(untouched(c, CAP) && cnt == 777);
    }
    /* pseudo planes outside [n, f] or crossed */
    const double pp[][2] = {{0.5, 50}, {2, 150}, {50, 50}, {60, 50}, {NAN, 50}, {2, INFINITY}};
    for (size_t i = 0; i < 6; ++i) {
        swarp_status want = (isfinite(pp[i][0]) && isfinite(pp[i][1])) ? SWARP_ERR_OUT_OF_RANGE
                                                                         : SWARP_ERR_NON_FINITE;
        ck_assert_int_eq(swarp_split_pseudo(1, 100, pp[i][0], pp[i][1], 0.5, 4, c, CAP, &cnt), want);
        ck_assert(untouched(c, CAP) && cnt == 777);
    }
    ck_assert_int_eq(swarp_split_uniform(1, 100, 4, c, CAP, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_split_log(1, 100, 4, NULL, 5, &cnt), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_split_practical(1, 100, 0.5, 4, NULL, 5, &cnt), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_split_pseudo(1, 100, 2, 50, 0.5, 4, c, CAP, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(untouched(c, CAP) && cnt == 777);
    /* large worlds: far/near = 1e6, coordinates 1e5 */
    ck_assert_int_eq(swarp_split_practical(1e5, 1e11, 0.5, SWARP_SPLIT_MAX_COUNT, c, CAP, &cnt), SWARP_OK);
    ck_assert(c[SWARP_SPLIT_MAX_COUNT] == 1e11);
}
END_TEST

TCase* tcase_split(void) {
    TCase* tc = tcase_create("split");
    tcase_add_test(tc, schemes_cover_range_strictly_increasing);
    tcase_add_test(tc, uniform_log_practical_match_paper);
    tcase_add_test(tc, pseudo_matches_41_and_reduces_to_practical);
    tcase_add_test(tc, split_capacity_and_bad_inputs);
    return tc;
}
