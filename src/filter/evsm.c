/* Exponential variance shadow maps: positive and negative exponential warps,
 * the minimum of both Chebyshev bounds, and the largest exponent a texel
 * format can store.  [VSM] §4.2 (after Salvi's exponential shadow maps). */
#include <float.h>

#include "filter/filter_internal.h"

/* The largest exponent whose e^{2c} is still finite in double: ln(DBL_MAX)/2
 * ~ 354.9; anything above cannot even be evaluated here. */
#define SW_EVSM_C_MAX_DOUBLE 354.0

/* IEEE parameters of the formats: p explicit mantissa bits, e_max. */
static int sw_format_params(swarp_texel_format f, int* p, int* e_max) {
    switch (f) {
        case SWARP_TEXEL_DEFAULT:
        case SWARP_TEXEL_FP32:
            *p = 23;
            *e_max = 127;
            return 1;
        case SWARP_TEXEL_FP16:
            *p = 10;
            *e_max = 15;
            return 1;
        default:
            return 0;
    }
}

SWARP_API swarp_status swarp_evsm_max_exponent(swarp_texel_format format, double* out_c) {
    if (!out_c) return SWARP_ERR_NULL_POINTER;
    int p, e_max;
    if (!sw_format_params(format, &p, &e_max)) return SWARP_ERR_UNKNOWN_ENUM;
    /* F_max = (2 - 2^-p) 2^e_max, the largest finite value of the format. */
    double F_max = (2.0 - ldexp(1.0, -p)) * ldexp(1.0, e_max);
    /* Depths in [0, 1]: the largest moment is e^{2c}.  The margin 4u in the
     * exponent, u = 2^-(p+1), is a relative margin of ~4 ulps for the GPU's
     * exp() and the rounding of the product 2 c x. */
    double u = ldexp(1.0, -(p + 1));
    *out_c = 0.5 * (log(F_max) - 4.0 * u);
    return SWARP_OK;
}

static swarp_status sw_check_c(double c_pos, double c_neg) {
    if (!sw_finite(c_pos) || !sw_finite(c_neg)) return SWARP_ERR_NON_FINITE;
    if (!(c_pos > 0.0) || !(c_neg > 0.0) || c_pos > SW_EVSM_C_MAX_DOUBLE ||
        c_neg > SW_EVSM_C_MAX_DOUBLE)
        return SWARP_ERR_FILTER_EXPONENT;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_evsm_moments(double x, double c_pos, double c_neg,
                                          double out_moments[4]) {
    if (!out_moments) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(x)) return SWARP_ERR_NON_FINITE;
    swarp_status st = sw_check_c(c_pos, c_neg);
    if (st != SWARP_OK) return st;
    double e_pos = exp(c_pos * x);  /* positive warp e^{c x} */
    double e_neg = exp(-c_neg * x); /* magnitude of the negative warp -e^{-c x} */
    double m[4] = {e_pos, e_pos * e_pos, -e_neg, e_neg * e_neg};
    /* |x| too large for c: e^{2c|x|} overflows, the documented exponent
     * error (x itself is finite, so NON_FINITE would blame the input) */
    for (int i = 0; i < 4; ++i)
        if (!sw_finite(m[i])) return SWARP_ERR_FILTER_EXPONENT;
    memcpy(out_moments, m, sizeof m);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_evsm_visibility(const double moments[4], double t, double c_pos,
                                             double c_neg, double min_variance,
                                             double* out_visibility) {
    if (!moments || !out_visibility) return SWARP_ERR_NULL_POINTER;
    for (int i = 0; i < 4; ++i)
        if (!sw_finite(moments[i])) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(t) || !sw_finite(min_variance)) return SWARP_ERR_NON_FINITE;
    swarp_status st = sw_check_c(c_pos, c_neg);
    if (st != SWARP_OK) return st;
    if (min_variance < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    double w_pos = exp(c_pos * t), w_neg = -exp(-c_neg * t);
    if (!sw_finite(w_pos) || !sw_finite(w_neg)) return SWARP_ERR_FILTER_EXPONENT; /* e^{c|t|} overflows */
    /* the variance floor mapped through each warp's slope at t */
    double k_pos = c_pos * w_pos, k_neg = c_neg * w_neg;
    /* the floor min_variance k^2 is formed inside (ratio form when it overflows) */
    double v_pos = sw_chebyshev_k(moments[0], moments[1], w_pos, min_variance, k_pos);
    double v_neg = sw_chebyshev_k(moments[2], moments[3], w_neg, min_variance, k_neg);
    double v = v_pos < v_neg ? v_pos : v_neg; /* both are upper bounds: keep the tighter */
    if (!sw_finite(v)) return SWARP_ERR_NON_FINITE; /* defensive: the ratio form stays in [0, 1] */
    *out_visibility = v;
    return SWARP_OK;
}
