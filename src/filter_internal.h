/* Internal helpers of the filter stage (VSM, LVSM, EVSM, MSM, PCF).
 * Not installed, not exported. */
#ifndef SWARP_FILTER_INTERNAL_H
#define SWARP_FILTER_INTERNAL_H

#include "swarp_internal.h"

/* Chebyshev's one-tailed bound [VSM] (3.3) on (M_1, M_2) with a variance
 * floor, no argument checks (callers checked).  Returns a value in [0, 1]. */
static inline double sw_chebyshev(double M_1, double M_2, double t, double min_variance) {
    double mu = M_1;
    if (t <= mu) return 1.0; /* receiver in front of the mean: bound is trivial */
    /* [VSM] (3.2) sigma^2 = M_2 - M_1^2; the fused multiply-add rounds once,
     * so exact moments give an exact variance (no rounding of M_1^2). */
    double sigma2 = fma(-M_1, M_1, M_2);
    if (!(sigma2 >= min_variance)) sigma2 = min_variance;
    double d = t - mu;
    double denom = sigma2 + d * d;
    if (!(denom > 0.0)) return 0.0; /* sigma2 = 0 and t > mu: fully occluded */
    double p = sigma2 / denom;
    return p < 0.0 ? 0.0 : (p > 1.0 ? 1.0 : p);
}

/* Validates N + 1 strictly increasing finite splits. */
static inline swarp_status sw_check_splits(const double* splits, uint32_t n_layers) {
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
