/* Core: z-partition split schemes.
 *
 *   [RHS] (3.6)  uniform      C_i = n + (f - n) i/m
 *   [RHS] (3.7)  logarithmic  C_i = n (f/n)^(i/m)
 *   [RHS] (3.8)  practical    C_i = (1 - lambda) uniform_i + lambda log_i   (PSSM [ZSXL06])
 *   [RHS] (4.1)  practical over pseudo-near/far [n_p, f_p], ends kept at n, f
 *
 * All write m + 1 distances with C_0 = n and C_m = f exactly (set, not
 * computed, so the splits cover [n, f] without a gap of one ulp).
 */
#include <float.h>

#include "common/swarp_internal.h"

/* C_i of (3.8) over [a, b] for 0 < i < m.  The logarithmic term is
 * a exp(log(b/a) i/m): one rounding in log, one in exp. */
static double sw_practical_at(double a, double b, double lambda, uint32_t i, uint32_t m) {
    double s = (double)i / (double)m;
    double c_uni = a + (b - a) * s; /* (3.6) */
    if (lambda == 0.0) return c_uni; /* uniform: no log term (0 * Inf below) */
    /* (3.7).  b/a overflows for a subnormal near plane and a far one above
     * ~1e15 (the ratio exceeds DBL_MAX although every C_i is representable):
     * then log b - log a (absolute error ~ eps |log a| <= 1.6e-13 in the
     * exponent, i.e. relative in C_i); likewise (b/a)^s may overflow while
     * a (b/a)^s does not: then exp(log a + L s). */
    double r = b / a;
    double L = (r <= DBL_MAX) ? log(r) : log(b) - log(a);
    double e = exp(L * s);
    double c_log = (e <= DBL_MAX) ? a * e : exp(log(a) + L * s);
    if (lambda == 1.0) return c_log;
    return (1.0 - lambda) * c_uni + lambda * c_log;
}

static swarp_status sw_split_args(double n, double f, double lambda, uint32_t m,
                                  const double* out, size_t capacity, const size_t* out_count) {
    if (!out_count || (!out && capacity > 0)) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(n) || !sw_finite(f) || !sw_finite(lambda)) return SWARP_ERR_NON_FINITE;
    if (!(n > 0.0) || !(f > n)) return SWARP_ERR_NEAR_FAR;
    if (!(lambda >= 0.0 && lambda <= 1.0)) return SWARP_ERR_OUT_OF_RANGE;
    if (m == 0 || m > SWARP_SPLIT_MAX_COUNT) return SWARP_ERR_SPLIT_COUNT;
    return SWARP_OK;
}

/* Fills C_0..C_m into a local array, checks strict increase (a range only a
 * few ulp wide cannot hold m distinct splits), then copies. */
static swarp_status sw_split_write(double n, double f, double a, double b, double lambda,
                                   uint32_t m, double* out, size_t capacity, size_t* out_count) {
    size_t needed = (size_t)m + 1;
    if (capacity < needed) {
        *out_count = needed;
        return SWARP_ERR_CAPACITY;
    }
    double c[SWARP_SPLIT_MAX_COUNT + 1];
    c[0] = n;
    c[m] = f;
    for (uint32_t i = 1; i < m; ++i) c[i] = sw_practical_at(a, b, lambda, i, m);
    for (uint32_t i = 0; i < m; ++i)
        if (!(c[i + 1] > c[i])) return SWARP_ERR_DEGENERATE;
    memcpy(out, c, needed * sizeof c[0]);
    *out_count = needed;
    return SWARP_OK;
}

/* [RHS] (3.6) */
SWARP_API swarp_status swarp_split_uniform(double n, double f, uint32_t m, double* out,
                                           size_t capacity, size_t* out_count) {
    return swarp_split_practical(n, f, 0.0, m, out, capacity, out_count);
}

/* [RHS] (3.7) */
SWARP_API swarp_status swarp_split_log(double n, double f, uint32_t m, double* out,
                                       size_t capacity, size_t* out_count) {
    return swarp_split_practical(n, f, 1.0, m, out, capacity, out_count);
}

/* [RHS] (3.8) */
SWARP_API swarp_status swarp_split_practical(double n, double f, double lambda, uint32_t m,
                                             double* out, size_t capacity,
                                             size_t* out_count) {
    swarp_status s = sw_split_args(n, f, lambda, m, out, capacity, out_count);
    if (s != SWARP_OK) return s;
    return sw_split_write(n, f, n, f, lambda, m, out, capacity, out_count);
}

/* [RHS] (4.1) */
SWARP_API swarp_status swarp_split_pseudo(double n, double f, double n_p, double f_p,
                                          double lambda, uint32_t m, double* out,
                                          size_t capacity, size_t* out_count) {
    swarp_status s = sw_split_args(n, f, lambda, m, out, capacity, out_count);
    if (s != SWARP_OK) return s;
    if (!sw_finite(n_p) || !sw_finite(f_p)) return SWARP_ERR_NON_FINITE;
    if (!(n_p >= n && f_p <= f && n_p < f_p)) return SWARP_ERR_OUT_OF_RANGE;
    return sw_split_write(n, f, n_p, f_p, lambda, m, out, capacity, out_count);
}
