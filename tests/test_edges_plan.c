#define _POSIX_C_SOURCE 200809L
/* swarp_plan_explain's numbers do not depend on the caller's rounding mode
 * (issue 9, fenv finding): values just below a decimal rounding boundary
 * (0.5325 is 0.53249999999999997... in binary) are printed as the exact
 * binary value rounds, in every mode; the reference is glibc's printf, which
 * converts the exact binary value (round-to-nearest, no ties here). */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

static void explain(const swarp_plan_result* p, int mode, char* text, size_t cap) {
    size_t n = 0;
    fesetround(mode);
    swarp_status st = swarp_plan_explain(p, text, cap, &n);
    fesetround(FE_TONEAREST);
    ck_assert_int_eq(st, SWARP_OK);
    ck_assert_uint_eq(n, strlen(text) + 1);
}

START_TEST(explain_text_independent_of_rounding_mode) {
    swarp_scene_needs needs;
    swarp_budget budget;
    memset(&needs, 0, sizeof needs);
    memset(&budget, 0, sizeof budget);
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&needs, &budget, &p)));
    /* values on the wrong side of a boundary after one directed rounding */
    p.near = 0.5325;       /* "0.532" (the old code printed 0.533 in every mode but downward) */
    p.far = 2.675;         /* "2.67" */
    p.max_mx = 4.4445e-5;  /* "4.44e-05" */
    p.max_mz = 1.0005e-3;  /* "0.00100": 0.0010004999999999999... */
    p.error_area = 99.95;  /* "100": 99.9500000000000028... rounds up */
    p.texels = 1.2345e8;   /* "1.23e+08" */
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    char ref[SWARP_PLAN_EXPLAIN_MAX], got[SWARP_PLAN_EXPLAIN_MAX];
    explain(&p, FE_TONEAREST, ref, sizeof ref);
    for (int m = 1; m < 4; ++m) {
        explain(&p, modes[m], got, sizeof got);
        ck_assert_msg(strcmp(ref, got) == 0, "mode %d:\n%s\nvs\n%s", m, got, ref);
    }
    /* the digits are the exact value's (printf converts exactly) */
    char want[64];
    snprintf(want, sizeof want, "%.3g", p.near);
    ck_assert_str_eq(want, "0.532");
    ck_assert_msg(strstr(ref, "depth range [0.532, 2.67]") != NULL, "%s", ref);
    snprintf(want, sizeof want, "max m_x %.2e", p.max_mx);
    ck_assert_msg(strstr(ref, want) != NULL, "%s not in %s", want, ref);
    ck_assert_msg(strstr(ref, "m_z 0.00100") != NULL, "%s", ref);
    snprintf(want, sizeof want, "%.2e texels", p.texels);
    ck_assert_msg(strstr(ref, want) != NULL, "%s not in %s", want, ref);
    /* a rounding that carries into the next decade is formatted in that
     * decade: one ulp below 100 prints as 100 exactly does ("100", not
     * "100.0"), and one ulp below 1e7 as "1.00e+07" */
    p.near = nextafter(100.0, 0.0);
    p.far = nextafter(1e7, 0.0);
    for (int m = 0; m < 4; ++m) {
        explain(&p, modes[m], got, sizeof got);
        ck_assert_msg(strstr(got, "depth range [100, 1.00e+07]") != NULL, "mode %d: %s", m, got);
    }
    p.near = 100.0;
    p.far = 1e7;
    explain(&p, FE_TONEAREST, got, sizeof got);
    ck_assert_msg(strstr(got, "depth range [100, 1.00e+07]") != NULL, "%s", got);
}
END_TEST

/* Random values in every decade: the text is the same in every mode and
 * every number printed in scientific form matches printf's %.2e (away from
 * exact ties, which these random doubles never are). */
START_TEST(explain_random_values_every_mode) {
    swarp_scene_needs needs;
    swarp_budget budget;
    memset(&needs, 0, sizeof needs);
    memset(&budget, 0, sizeof budget);
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&needs, &budget, &p)));
    uint64_t s = 0xE7A1Eull;
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    char ref[SWARP_PLAN_EXPLAIN_MAX], got[SWARP_PLAN_EXPLAIN_MAX], want[64];
    for (int n = 0; n < 400; ++n) {
        /* 3 significant digits plus a few ulps either side of the boundary */
        double v = (tu_splitmix64(&s) % 900 + 100.5) * pow(10.0, (double)(tu_splitmix64(&s) % 600) - 300.0);
        v = nextafter(v, (n & 1) ? INFINITY : 0.0);
        p.max_mx = v;
        explain(&p, FE_TONEAREST, ref, sizeof ref);
        for (int m = 0; m < 3; ++m) {
            explain(&p, modes[m], got, sizeof got);
            ck_assert_msg(strcmp(ref, got) == 0, "v = %.17g, mode %d", v, m);
        }
        double e10 = floor(log10(v));
        if (e10 >= 7 || e10 < -3) {
            snprintf(want, sizeof want, "max m_x %.2e,", v);
            ck_assert_msg(strstr(ref, want) != NULL, "v = %.17g: %s not in %s", v, want, ref);
        }
    }
}
END_TEST

/* ---- planfix pass: regressions from the hard-case sweep (issue 9) ---- */

/* hard_cases --entry swarp_plan / swarp_plan_evaluate (e.g. case 54333): a
 * pass cost near DBL_MAX gave cost_ns = K x pass cost = inf.  Costs above
 * SWARP_PLAN_MAX_COST_NS are refused (documented); at the limit the cost of
 * every chain is finite. */
START_TEST(planfix_plan_cost_limit) {
    const double costs[3] = {DBL_MAX, 1e300, SWARP_PLAN_MAX_COST_NS * 2};
    for (int i = 0; i < 3; ++i) {
        for (int field = 0; field < 3; ++field) {
            swarp_budget b;
            memset(&b, 0, sizeof b);
            double* f = field == 0 ? &b.pass_cost_ns : field == 1 ? &b.blur_pass_cost_ns : &b.time_budget_ns;
            *f = costs[i];
            struct swarp_plan p;
            memset(&p, 0x5a, sizeof p);
            ck_assert_int_eq(swarp_plan(NULL, &b, &p), SWARP_ERR_OUT_OF_RANGE);
            ck_assert_uint_eq(((const unsigned char*)&p)[0], 0x5a);
            swarp_plan_chain ch;
            memset(&ch, 0, sizeof ch);
            ch.scheme = SWARP_PLAN_SCHEME_PRACTICAL, ch.split_count = 16;
            ck_assert_int_eq(swarp_plan_evaluate(NULL, &b, &ch, &p), SWARP_ERR_OUT_OF_RANGE);
        }
    }
    /* at the limit: 16 splits with soft shadows (blur passes) stay finite */
    swarp_scene_needs n;
    memset(&n, 0, sizeof n);
    n.soft_shadows = 1;
    swarp_budget b;
    memset(&b, 0, sizeof b);
    b.pass_cost_ns = b.blur_pass_cost_ns = b.time_budget_ns = SWARP_PLAN_MAX_COST_NS;
    swarp_plan_chain ch;
    memset(&ch, 0, sizeof ch);
    ch.scheme = SWARP_PLAN_SCHEME_PRACTICAL, ch.split_count = 16;
    struct swarp_plan p;
    const swarp_status st = swarp_plan_evaluate(&n, &b, &ch, &p);
    ck_assert(st == SWARP_OK || st == SWARP_INFO_PLAN_POINT_LIGHT);
    ck_assert(isfinite(p.cost_ns) && p.cost_ns >= 16 * SWARP_PLAN_MAX_COST_NS);
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_plan");
    TCase* t = tcase_create("explain");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, explain_text_independent_of_rounding_mode);
    tcase_add_test(t, explain_random_values_every_mode);
    suite_add_tcase(s, t);
    /* planfix pass */
    t = tcase_create("planfix");
    tcase_add_test(t, planfix_plan_cost_limit);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
