/* Layered variance shadow maps: layer warp, overlaps, layer lookup,
 * transition band and shading.  [VSM] §4.1, (4.2), §4.1.1, §4.1.3. */
#include "filter/filter_internal.h"

/* [VSM] §4.1.1: layer i widened by +-delta, the outermost ends kept. */
static void sw_layer_pq(const double* splits, uint32_t n_layers, uint32_t i, double delta,
                        double* p, double* q) {
    *p = (i == 0) ? splits[0] : splits[i] - delta;
    *q = (i + 1 == n_layers) ? splits[n_layers] : splits[i + 1] + delta;
}

SWARP_API swarp_status swarp_lvsm_layer_interval(const double* splits, uint32_t n_layers,
                                                 uint32_t i, double delta, double* out_p,
                                                 double* out_q) {
    if (!out_p || !out_q) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_lvsm_check_splits(splits, n_layers);
    if (st != SWARP_OK) return st;
    if (!sw_finite(delta)) return SWARP_ERR_NON_FINITE;
    if (i >= n_layers) return SWARP_ERR_OUT_OF_RANGE;
    if (delta < 0.0 || !(delta < sw_min_layer(splits, n_layers))) return SWARP_ERR_FILTER_OVERLAP;
    double p, q;
    sw_layer_pq(splits, n_layers, i, delta, &p, &q);
    *out_p = p;
    *out_q = q;
    return SWARP_OK;
}

/* [VSM] (4.2): phi_i(t) = clamp((t - p_i) / (q_i - p_i), 0, 1). */
static double sw_phi(double t, double p, double q) {
    if (t <= p) return 0.0;
    if (t >= q) return 1.0;
    double r = (t - p) / (q - p);
    return r > 1.0 ? 1.0 : r;
}

static swarp_status sw_check_pq(double t, double p, double q) {
    if (!sw_finite(t) || !sw_finite(p) || !sw_finite(q)) return SWARP_ERR_NON_FINITE;
    if (!(q > p) || !sw_finite(q - p)) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lvsm_warp(double t, double p, double q, double* out_phi) {
    if (!out_phi) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_pq(t, p, q);
    if (st != SWARP_OK) return st;
    *out_phi = sw_phi(t, p, q);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lvsm_moments(double t, double p, double q, double out_moments[2]) {
    if (!out_moments) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_pq(t, p, q);
    if (st != SWARP_OK) return st;
    double phi = sw_phi(t, p, q); /* (4.2) then (3.1) */
    out_moments[0] = phi;
    out_moments[1] = phi * phi;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lvsm_layer_uniform(double t, double s_0, double s_N,
                                                uint32_t n_layers, uint32_t* out_layer) {
    if (!out_layer) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(t) || !sw_finite(s_0) || !sw_finite(s_N)) return SWARP_ERR_NON_FINITE;
    if (n_layers < 1 || n_layers > SWARP_LVSM_MAX_LAYERS) return SWARP_ERR_FILTER_LAYER_COUNT;
    if (!(s_N > s_0) || !sw_finite(s_N - s_0)) return SWARP_ERR_NOT_INCREASING;
    if (t < s_0) {
        *out_layer = 0;
        return SWARP_INFO_FILTER_DEPTH_CLAMPED;
    }
    if (t > s_N) {
        *out_layer = n_layers - 1;
        return SWARP_INFO_FILTER_DEPTH_CLAMPED;
    }
    if (s_N - s_0 < 0x1p-960) {
        /* The layer width h below would be subnormal or 0 (s_N = 5e-324,
         * N = 3: h = 0 put t = s_0 in layer 1).  The layer of t is invariant
         * under scaling t, s_0, s_N by 2^j, and that scaling is exact here:
         * |s_0|, |s_N| <= 2^53 (s_N - s_0) (the width is at least an ulp of
         * both), so 2^j with (s_N - s_0) 2^j in [1, 2) overflows nothing. */
        int j = -ilogb(s_N - s_0);
        t = ldexp(t, j);
        s_0 = ldexp(s_0, j);
        s_N = ldexp(s_N, j);
    }
    double f = (t - s_0) / (s_N - s_0) * (double)n_layers;
    uint32_t j = (uint32_t)floor(f);
    if (j >= n_layers) j = n_layers - 1; /* t == s_N belongs to the last layer */
    /* The closed form rounds; make it agree with s_j = s_0 + (s_N - s_0) j / N
     * evaluated the same way, so a depth exactly on a split is consistent. */
    double h = (s_N - s_0) / (double)n_layers;
    if (j + 1 < n_layers && t >= s_0 + h * (double)(j + 1)) ++j;
    if (j > 0 && t < s_0 + h * (double)j) --j;
    *out_layer = j;
    return SWARP_OK;
}

/* Largest j with splits[j] <= t, in [0, N-1]; t inside [s_0, s_N]. */
static uint32_t sw_find(double t, const double* splits, uint32_t n_layers) {
    uint32_t lo = 0, hi = n_layers; /* invariant: splits[lo] <= t, answer < hi */
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (splits[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static swarp_status sw_layer_of(double t, const double* splits, uint32_t n_layers,
                                uint32_t* layer) {
    if (t < splits[0]) {
        *layer = 0;
        return SWARP_INFO_FILTER_DEPTH_CLAMPED;
    }
    if (t > splits[n_layers]) {
        *layer = n_layers - 1;
        return SWARP_INFO_FILTER_DEPTH_CLAMPED;
    }
    *layer = sw_find(t, splits, n_layers);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lvsm_layer_find(double t, const double* splits, uint32_t n_layers,
                                             uint32_t* out_layer) {
    if (!out_layer) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_lvsm_check_splits(splits, n_layers);
    if (st != SWARP_OK) return st;
    if (!sw_finite(t)) return SWARP_ERR_NON_FINITE;
    uint32_t j;
    st = sw_layer_of(t, splits, n_layers, &j);
    *out_layer = j;
    return st;
}

/* §4.1.3 transition region, linear weight across [s_j - band, s_j + band]. */
static swarp_status sw_transition(double t, const double* splits, uint32_t n_layers, double band,
                                  uint32_t* lo, uint32_t* hi, double* w_hi) {
    uint32_t j;
    swarp_status st = sw_layer_of(t, splits, n_layers, &j);
    *lo = *hi = j;
    *w_hi = 0.0;
    if (band > 0.0 && st == SWARP_OK) {
        /* w = (t - (s - band)) / (2 band) as ((t - s) + band) / (2 band):
         * t - s is exact next to s (Sterbenz), while s - band rounded at the
         * magnitude of s (an ulp of s is ~1e-7 of a band of 1e-9 at s ~ 1,
         * and all of a band below an ulp of s), so w would depend on the
         * caller's rounding mode by up to the whole [0, 1]. */
        if (j > 0 && t - splits[j] < band) { /* just above inner split s_j */
            *lo = j - 1;
            *w_hi = ((t - splits[j]) + band) / (2.0 * band);
        } else if (j + 1 < n_layers && splits[j + 1] - t < band) { /* just below s_{j+1} */
            *hi = j + 1;
            *w_hi = ((t - splits[j + 1]) + band) / (2.0 * band);
        }
        if (*w_hi < 0.0) *w_hi = 0.0;
        if (*w_hi > 1.0) *w_hi = 1.0;
    }
    return st;
}

static swarp_status sw_check_band(const double* splits, uint32_t n_layers, double band) {
    if (!sw_finite(band)) return SWARP_ERR_NON_FINITE;
    if (band < 0.0 || !(band < 0.5 * sw_min_layer(splits, n_layers))) return SWARP_ERR_FILTER_BAND;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lvsm_transition(double t, const double* splits, uint32_t n_layers,
                                             double band, uint32_t* out_layer_lo,
                                             uint32_t* out_layer_hi, double* out_w_hi) {
    if (!out_layer_lo || !out_layer_hi || !out_w_hi) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_lvsm_check_splits(splits, n_layers);
    if (st != SWARP_OK) return st;
    if (!sw_finite(t)) return SWARP_ERR_NON_FINITE;
    st = sw_check_band(splits, n_layers, band);
    if (st != SWARP_OK) return st;
    uint32_t lo, hi;
    double w;
    st = sw_transition(t, splits, n_layers, band, &lo, &hi, &w);
    *out_layer_lo = lo;
    *out_layer_hi = hi;
    *out_w_hi = w;
    return st;
}

/* Chebyshev on layer i's warped moments with the variance floor mapped into
 * the warped space: phi_i has slope 1/(q - p), so variances scale by its square. */
static double sw_layer_vis(const double* layer_moments, const double* splits, uint32_t n_layers,
                           uint32_t i, double delta, double t, double min_variance) {
    double p, q;
    sw_layer_pq(splits, n_layers, i, delta, &p, &q);
    /* The floor in warped units can overflow (min_variance 1e304, or a layer
     * ~1e-300 wide: s^2 = Inf) and Inf/Inf gave NaN.  Warped depths lie in
     * [0, 1], so with d^2 <= 1 a floor >= 2^60 already yields
     * floor/(floor + d^2) = 1 after rounding: capping it there changes no
     * result for moments of warped depths and keeps the bound finite. */
    double floor_w = 0.0;
    if (min_variance > 0.0) {
        double s = 1.0 / (q - p);
        floor_w = (min_variance * s) * s;
        if (!(floor_w <= 0x1p60)) floor_w = 0x1p60;
    }
    return sw_chebyshev(layer_moments[2 * i], layer_moments[2 * i + 1], sw_phi(t, p, q), floor_w);
}

SWARP_API swarp_status swarp_lvsm_visibility(const double* layer_moments, const double* splits,
                                             uint32_t n_layers, double delta, double band,
                                             double t, double min_variance,
                                             double* out_visibility) {
    if (!layer_moments || !out_visibility) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_lvsm_check_splits(splits, n_layers);
    if (st != SWARP_OK) return st;
    if (!sw_finite(t) || !sw_finite(delta) || !sw_finite(band) || !sw_finite(min_variance))
        return SWARP_ERR_NON_FINITE;
    for (uint32_t i = 0; i < 2 * n_layers; ++i)
        if (!sw_finite(layer_moments[i])) return SWARP_ERR_NON_FINITE;
    if (delta < 0.0 || !(delta < sw_min_layer(splits, n_layers))) return SWARP_ERR_FILTER_OVERLAP;
    st = sw_check_band(splits, n_layers, band);
    if (st != SWARP_OK) return st;
    if (band > delta) return SWARP_ERR_FILTER_BAND; /* both layers must contain t */
    if (min_variance < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    uint32_t lo, hi;
    double w;
    st = sw_transition(t, splits, n_layers, band, &lo, &hi, &w);
    double v = sw_layer_vis(layer_moments, splits, n_layers, hi, delta, t, min_variance);
    if (lo != hi) {
        double v_lo = sw_layer_vis(layer_moments, splits, n_layers, lo, delta, t, min_variance);
        v = (1.0 - w) * v_lo + w * v;
    }
    if (!sw_finite(v)) return SWARP_ERR_NON_FINITE;
    *out_visibility = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
    return st;
}

/* [VSM] §4.1.2: mu + sigma recovers max(a, b) at coverage 1/2. */
SWARP_API swarp_status swarp_lvsm_second_occluder(double mu, double sigma2, double* out_depth) {
    if (!out_depth) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(mu) || !sw_finite(sigma2)) return SWARP_ERR_NON_FINITE;
    double d = mu + sqrt(sigma2 > 0.0 ? sigma2 : 0.0);
    if (!sw_finite(d)) return SWARP_ERR_NON_FINITE;
    *out_depth = d;
    return SWARP_OK;
}
