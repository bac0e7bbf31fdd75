/* Internal helpers of the filter stage (VSM, LVSM, EVSM, MSM, PCF).
 * Not installed, not exported. */
#ifndef SWARP_FILTER_INTERNAL_H
#define SWARP_FILTER_INTERNAL_H

#include "common/swarp_internal.h"

#include <float.h>

/* sigma2 / (sigma2 + d^2) for finite sigma2 >= 0 and d > 0, in [0, 1].
 * When d^2 overflows (d ~ 1e154 with sigma2 ~ DBL_MAX: the bound is 0.18,
 * not 0) or underflows, the ratio is taken on d = m 2^e scaled to m in
 * [0.5, 1): sigma2 2^-2e / (sigma2 2^-2e + m^2), the same value with one
 * more exact scaling; a scaled sigma2 beyond DBL_MAX makes the bound 1. */
static inline double sw_chebyshev_ratio(double sigma2, double d) {
    double d2 = d * d, denom = sigma2 + d2;
    double p;
    if (d2 >= DBL_MIN && isfinite(denom)) {
        p = sigma2 / denom;
    } else {
        int e;
        double m = frexp(d, &e);
        double s = ldexp(sigma2, -2 * e);
        if (!isfinite(s)) return 1.0;
        p = s / (s + m * m);
    }
    return p < 0.0 ? 0.0 : (p > 1.0 ? 1.0 : p);
}

/* Chebyshev's one-tailed bound [VSM] (3.3) on (M_1, M_2) with the variance
 * floor min_variance k^2 (k: the slope of a warp that maps the floor into
 * warped units, 1 for plain VSM), no argument checks (callers checked:
 * M_1, M_2, t, min_variance >= 0 and k finite).  Returns a value in [0, 1].
 * Written in ratio form so that no intermediate overflows where the bound
 * itself is well defined: t - mu and (t - mu)^2 beyond DBL_MAX, and a floor
 * min_variance k^2 beyond DBL_MAX (EVSM: k = c e^{c t}). */
static inline double sw_chebyshev_k(double M_1, double M_2, double t, double min_variance,
                                    double k) {
    double mu = M_1;
    if (t <= mu) return 1.0; /* receiver in front of the mean: bound is trivial */
    /* [VSM] (3.2) sigma^2 = M_2 - M_1^2; the fused multiply-add rounds once,
     * so exact moments give an exact variance (no rounding of M_1^2).  It is
     * <= DBL_MAX or -inf (M_1^2 beyond DBL_MAX: not a variance, the floor
     * applies). */
    double sigma2 = fma(-M_1, M_1, M_2);
    double floor_v = min_variance > 0.0 ? (min_variance * k) * k : 0.0;
    if (!isfinite(floor_v)) {
        /* floor beyond DBL_MAX >= sigma2: floor/(floor + d^2) = 1/(1 + r^2),
         * r = d/(sqrt(min_variance) |k|), with d halved (t - mu may overflow) */
        double r = (((0.5 * t - 0.5 * mu) / sqrt(min_variance)) / fabs(k)) * 2.0;
        return 1.0 / (1.0 + r * r);
    }
    if (!(sigma2 >= floor_v)) sigma2 = floor_v;
    double d = t - mu;
    if (!isfinite(d)) /* t and mu near +-DBL_MAX: the same ratio on halves */
        return sw_chebyshev_ratio(0.25 * sigma2, 0.5 * t - 0.5 * mu);
    return sw_chebyshev_ratio(sigma2, d);
}

static inline double sw_chebyshev(double M_1, double M_2, double t, double min_variance) {
    return sw_chebyshev_k(M_1, M_2, t, min_variance, 1.0);
}

/* Validates N + 1 strictly increasing finite splits. */
static inline swarp_status sw_lvsm_check_splits(const double* splits, uint32_t n_layers) {
    if (!splits) return SWARP_ERR_NULL_POINTER;
    if (n_layers < 1 || n_layers > SWARP_LVSM_MAX_LAYERS) return SWARP_ERR_FILTER_LAYER_COUNT;
    for (uint32_t i = 0; i <= n_layers; ++i)
        if (!sw_finite(splits[i])) return SWARP_ERR_NON_FINITE;
    for (uint32_t i = 0; i < n_layers; ++i)
        if (!(splits[i + 1] > splits[i])) return SWARP_ERR_NOT_INCREASING;
    /* widths and the whole range must be representable (|s| up to ~1e307) */
    if (!sw_finite(splits[n_layers] - splits[0])) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* Thinnest layer width of valid splits. */
static inline double sw_min_layer(const double* splits, uint32_t n_layers) {
    double w = splits[1] - splits[0];
    for (uint32_t i = 1; i < n_layers; ++i) {
        double d = splits[i + 1] - splits[i];
        if (d < w) w = d;
    }
    return w;
}

#endif
