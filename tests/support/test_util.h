/* test_util: the small helpers the Check suites share (header only).
 * - tu_splitmix64: the tests' own seeded PRNG (splitmix64);
 * - tu_uniform: uniform in [a, b) from the top 53 bits of one draw;
 * - tu_rel: relative difference |a - b| / max(|a|, |b|) (0 when both are 0);
 * - tu_fill / tu_untouched: the "outputs untouched" checks on bad input
 *   (prefill with a sentinel, compare bit for bit afterwards);
 * - tu_run_suite: runs a suite, returns the number of failed tests (only
 *   where <check.h> is included first; the GL tests use the rest without Check). */
#ifndef TEST_UTIL_H
#define TEST_UTIL_H

/* SW_UNDER_ASAN: 1 in an AddressSanitizer build (about 20x slower), where
 * the long sweeps subsample (each test says how). */
#if defined(__SANITIZE_ADDRESS__)
#define SW_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SW_UNDER_ASAN 1
#endif
#endif
#ifndef SW_UNDER_ASAN
#define SW_UNDER_ASAN 0
#endif

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static inline uint64_t tu_splitmix64(uint64_t* s) {
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* uniform in [a, b): the top 53 bits scaled by 2^-53 (exact) */
static inline double tu_uniform(uint64_t* s, double a, double b) {
    return a + (b - a) * ((double)(tu_splitmix64(s) >> 11) * 0x1.0p-53);
}

static inline double tu_rel(double a, double b) {
    double m = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return m == 0.0 ? 0.0 : fabs(a - b) / m;
}

static inline void tu_fill(double* a, size_t n, double sentinel) {
    for (size_t i = 0; i < n; ++i) a[i] = sentinel;
}
/* 1 when all n values are still the sentinel, bit for bit */
static inline int tu_untouched(const double* a, size_t n, double sentinel) {
    for (size_t i = 0; i < n; ++i)
        if (memcmp(&a[i], &sentinel, sizeof(double)) != 0) return 0;
    return 1;
}

/* Long-double references need a wider long double than double (a 15-bit
 * exponent, a longer mantissa); valgrind emulates x87 with doubles, so there
 * the tests that rely on one skip, saying so.  The -Werror and sanitizer
 * runs do the checks. */
static inline int long_double_is_wide(void) {
    volatile long double one = 1.0L, eps = LDBL_EPSILON, tiny = DBL_MIN;
    return one + eps != one && tiny * tiny > 0.0L;
}
#define REQUIRE_WIDE_LONG_DOUBLE()                                                              \
    do {                                                                                       \
        if (!long_double_is_wide()) {                                                          \
            fprintf(stderr, "%s: skipped, long double is not wider than double here\n", __func__); \
            return;                                                                            \
        }                                                                                      \
    } while (0)

#ifdef CHECK_MAJOR_VERSION
static inline int tu_run_suite(Suite* s) {
    SRunner* sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed;
}
#endif

#endif
