/* Variance shadow maps: moments, Chebyshev's bound, light-bleeding clamp.
 * [VSM] Lauritzen, "Rendering Antialiased Shadows using Warped Variance
 * Shadow Maps", (3.1)-(3.4). */
#include "filter/filter_internal.h"

_Static_assert(sizeof(swarp_lloyd_options) == 8 + 3 * sizeof(double) + 16, "swarp_lloyd_options size");
_Static_assert(offsetof(swarp_lloyd_options, weight_clamp_lo) == 8, "swarp_lloyd_options layout");
_Static_assert(sizeof(swarp_lloyd_report) == 16 + sizeof(double), "swarp_lloyd_report size");
_Static_assert(sizeof(swarp_texel_format) == 4, "swarp_texel_format is 32 bits");

/* [VSM] (3.1): one sample contributes x and x^2; filtering averages them. */
SWARP_API swarp_status swarp_vsm_moments(double x, double out_moments[2]) {
    if (!out_moments) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(x)) return SWARP_ERR_NON_FINITE;
    double x2 = x * x;
    if (!sw_finite(x2)) return SWARP_ERR_NON_FINITE; /* |x| > 1e154 */
    out_moments[0] = x;
    out_moments[1] = x2;
    return SWARP_OK;
}

/* [VSM] (3.2)-(3.3) p_max(t) = sigma^2 / (sigma^2 + (t - mu)^2), t > mu. */
SWARP_API swarp_status swarp_vsm_chebyshev(const double moments[2], double t, double min_variance,
                                           double* out_p_max) {
    if (!moments || !out_p_max) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(moments[0]) || !sw_finite(moments[1]) || !sw_finite(t) ||
        !sw_finite(min_variance))
        return SWARP_ERR_NON_FINITE;
    if (min_variance < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    double p = sw_chebyshev(moments[0], moments[1], t, min_variance);
    if (!sw_finite(p)) return SWARP_ERR_NON_FINITE; /* defensive: the ratio form stays in [0, 1] */
    *out_p_max = p;
    return SWARP_OK;
}

/* [VSM] §3.4: clamp out light below `amount` (linstep), as its ref. [10]. */
SWARP_API swarp_status swarp_vsm_reduce_bleeding(double p, double amount, double* out_p) {
    if (!out_p) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(p) || !sw_finite(amount)) return SWARP_ERR_NON_FINITE;
    if (p < 0.0 || p > 1.0 || amount < 0.0 || amount >= 1.0) return SWARP_ERR_OUT_OF_RANGE;
    double r = (p - amount) / (1.0 - amount);
    *out_p = r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
    return SWARP_OK;
}
