/* Shared bits of the core Check suite (test_core.c + test_params.c,
 * test_error.c, test_split.c are one executable). */
#ifndef TEST_CORE_H
#define TEST_CORE_H

#include <check.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

TCase* tcase_params(void);
TCase* tcase_error(void);
TCase* tcase_split(void);

/* splitmix64: the tests' own seeded PRNG. */
static inline uint64_t tc_next(uint64_t* s) { return tu_splitmix64(s); }
/* uniform in [a, b) */
static inline double tc_uniform(uint64_t* s, double a, double b) { return tu_uniform(s, a, b); }
/* log-uniform in [a, b), a > 0 */
static inline double tc_logu(uint64_t* s, double a, double b) {
    return exp(tc_uniform(s, log(a), log(b)));
}

static inline double tc_rel(double a, double b) { return tu_rel(a, b); }

#define TC_PI 3.14159265358979323846
#define TC_HALF_PI (0.5 * TC_PI)
#define TC_DEG (TC_PI / 180.0)

/* Sentinel for "outputs untouched" checks. */
#define TC_SENTINEL (-12345.678)

#define ck_assert_rel(a, b, tol)                                                         \
    do {                                                                                 \
        double ck_a_ = (a), ck_b_ = (b);                                                 \
        ck_assert_msg(tc_rel(ck_a_, ck_b_) <= (tol), "%s = %.17g vs %s = %.17g (rel %g > %g)", \
                      #a, ck_a_, #b, ck_b_, tc_rel(ck_a_, ck_b_), (double)(tol));        \
    } while (0)

#endif
