/* Layer placement for layered VSMs by weighted Lloyd relaxation with the
 * teleportation heuristic.  [VSM] §4.1.2 (and §4.1.3 for the heuristic). */
#include <float.h>

#include "filter/filter_internal.h"

#define SW_LLOYD_DEFAULT_ITERATIONS 100u
/* Default convergence tolerance and minimum split gap, relative to the depth
 * range: 1e-9 is far below any depth a 16- or 32-bit map can resolve
 * (2^-24 ~ 6e-8) yet well above double rounding of a weighted mean (~1e-16). */
#define SW_LLOYD_REL_TOL 1e-9
#define SW_LLOYD_REL_GAP 1e-9
/* A cluster is split by teleportation only if its weighted standard
 * deviation exceeds 1e-6 of the range: the one-pass variance E[u^2] - m^2 in
 * normalised units carries ~eps = 2e-16 of cancellation, i.e. a spurious
 * sd of up to ~1.5e-8, and a cluster that narrow is one depth anyway. */
#define SW_LLOYD_MIN_SPLIT_SD 1e-6

/* Weight of a sample: its variance, optionally clamped ([VSM] §4.1.2). */
static double sw_weight(double sigma2, double lo, double hi) {
    double w = sigma2 > 0.0 ? sigma2 : 0.0;
    if (w < lo) w = lo;
    if (hi > 0.0 && w > hi) w = hi;
    return w;
}

/* Nearest centre in a sorted array; ties go to the lower index. */
static uint32_t sw_nearest(const double* c, uint32_t k, double x) {
    uint32_t lo = 0, hi = k; /* first centre >= x, by bisection */
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (c[mid] < x)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == 0) return 0;
    if (lo == k) return k - 1;
    return (x - c[lo - 1] <= c[lo] - x) ? lo - 1 : lo;
}

/* Keeps centres strictly inside (s_0, s_N), increasing with a minimum gap. */
static void sw_enforce_gap(double* c, uint32_t k, double s_0, double s_N, double gap) {
    for (uint32_t i = 0; i < k; ++i) {
        double lo = (i == 0 ? s_0 : c[i - 1]) + gap;
        if (c[i] < lo) c[i] = lo;
    }
    for (uint32_t i = k; i-- > 0;) {
        double hi = (i + 1 == k ? s_N : c[i + 1]) - gap;
        if (c[i] > hi) c[i] = hi;
    }
}

/* One Lloyd step's end: the new centres nc, kept gap apart inside [0, 1],
 * replace c; returns the largest move. */
static double sw_adopt(double* c, double* nc, uint32_t k, double gap) {
    sw_enforce_gap(nc, k, 0.0, 1.0, gap);
    double shift = 0.0;
    for (uint32_t i = 0; i < k; ++i) {
        double d = fabs(nc[i] - c[i]);
        if (d > shift) shift = d;
        c[i] = nc[i];
    }
    return shift;
}

/* Checks the options (reserved fields, finite, ordered clamps) and the
 * samples; the splits were checked by the caller first. */
static swarp_status sw_lloyd_check(const double* mu, const double* sigma2, size_t count,
                                   const swarp_lloyd_options* opt, swarp_lloyd_options* o) {
    memset(o, 0, sizeof *o);
    if (opt) {
        *o = *opt;
        if (o->_pad0 != 0 || !sw_reserved_zero(o->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
        if (!sw_finite(o->weight_clamp_lo) || !sw_finite(o->weight_clamp_hi) || !sw_finite(o->tolerance))
            return SWARP_ERR_NON_FINITE;
        if (o->weight_clamp_lo < 0.0 || o->weight_clamp_hi < 0.0 || o->tolerance < 0.0 ||
            (o->weight_clamp_hi > 0.0 && o->weight_clamp_hi < o->weight_clamp_lo))
            return SWARP_ERR_OUT_OF_RANGE;
    }
    for (size_t j = 0; j < count; ++j)
        if (!sw_finite(mu[j]) || !sw_finite(sigma2[j])) return SWARP_ERR_NON_FINITE;
    return SWARP_OK;
}

/* The samples in normalised depth u = (x - s_0) / (s_N - s_0) in [0, 1],
 * with weights divided by the largest one (w_max), so no sum can overflow
 * and far-from-origin depths (1e5 and more) keep their digits. */
typedef struct sw_lloyd_samples {
    const double *mu, *sigma2;
    size_t count;
    double lo, hi;          /* weight clamps */
    double w_max;
    double s_0, s_N, range;
} sw_lloyd_samples;

/* The minimum gap in normalised units: 1e-9 of the range, but at least two
 * ulps of the splits' magnitude, else a 1e-9 gap far from the origin
 * (s_0 = 1e6 over a range of 4.5e-3: 1e-9 of it is 4.5e-12, one ulp of 1e6
 * is 1.2e-10) rounds away when the splits go back to depth units and
 * neighbouring splits collapse.  Capped so that k gaps still fit in [0, 1]
 * (a range of only a few ulps: sw_lloyd_write steps apart). */
static double sw_lloyd_gap(const sw_lloyd_samples* S, uint32_t k) {
    const double s_mag = fmax(fabs(S->s_0), fabs(S->s_N));
    const double ulp = nextafter(s_mag, INFINITY) - s_mag;
    double gap = fmax(SW_LLOYD_REL_GAP, 2.0 * ulp / S->range);
    if (gap > 0.5 / (double)(k + 1)) gap = 0.5 / (double)(k + 1);
    return gap;
}

/* [VSM] §4.1.2 assignment step: each sample's second-occluder estimate
 * mu + sigma to its nearest centre, with the weight, weighted sum and
 * weighted sum of squares of each cluster. */
static void sw_lloyd_assign(const sw_lloyd_samples* S, const double* c, uint32_t k, double* W, double* X,
                            double* X2) {
    for (uint32_t i = 0; i < k; ++i) W[i] = X[i] = X2[i] = 0.0;
    for (size_t j = 0; j < S->count; ++j) {
        double w = sw_weight(S->sigma2[j], S->lo, S->hi) / S->w_max;
        if (!(w > 0.0)) continue;
        /* clamped into the range, compared before normalising: mu + sigma
         * may overflow */
        double x_d = S->mu[j] + sqrt(S->sigma2[j] > 0.0 ? S->sigma2[j] : 0.0);
        double x = (x_d <= S->s_0) ? 0.0 : (x_d >= S->s_N ? 1.0 : (x_d - S->s_0) / S->range);
        uint32_t i = sw_nearest(c, k, x);
        W[i] += w;
        X[i] += w * x;
        X2[i] += w * x * x;
    }
}

/* [VSM] §4.1.3 teleportation: the first empty cluster is removed (its two
 * layers merge) and the heaviest cluster is split in two at its mean -+ one
 * standard deviation.  Writes the new centres to nc and returns 1, or
 * returns 0 when no cluster is empty or the heaviest is one depth.  The
 * clusters' total weight is >= 1: the sample of weight w_max contributes
 * w_max / w_max = 1. */
static int sw_lloyd_teleport(const double* W, const double* X, const double* X2, const double* c,
                             uint32_t k, double* nc) {
    uint32_t empty = k, heavy = 0;
    for (uint32_t i = 0; i < k; ++i) {
        if (empty == k && !(W[i] > 0.0)) empty = i;
        if (W[i] > W[heavy]) heavy = i;
    }
    if (empty == k) return 0;
    double m = X[heavy] / W[heavy];
    double var = X2[heavy] / W[heavy] - m * m;
    double sd = var > 0.0 ? sqrt(var) : 0.0;
    if (!(sd > SW_LLOYD_MIN_SPLIT_SD)) return 0; /* one depth cannot be split */
    uint32_t n = 0;
    for (uint32_t i = 0; i < k; ++i) {
        if (i == empty) continue;
        if (i == heavy) {
            nc[n++] = m - sd;
            nc[n++] = m + sd;
        } else {
            nc[n++] = (W[i] > 0.0) ? X[i] / W[i] : c[i];
        }
    }
    /* keep the order: the split pair may pass a neighbour */
    for (uint32_t a = 1; a < k; ++a)
        for (uint32_t b = a; b > 0 && nc[b - 1] > nc[b]; --b) {
            double tmp = nc[b];
            nc[b] = nc[b - 1];
            nc[b - 1] = tmp;
        }
    return 1;
}

/* Lloyd relaxation of the k inner centres c until the largest move is at
 * most tol or max_it iterations have run (NOT_CONVERGED); never converged
 * right after a teleport. */
static swarp_status sw_lloyd_relax(const sw_lloyd_samples* S, double* c, uint32_t k, double gap, double tol,
                                   uint32_t max_it, swarp_lloyd_report* rep) {
    for (;;) {
        if (rep->iterations >= max_it) return SWARP_INFO_FILTER_NOT_CONVERGED;
        ++rep->iterations;
        double W[SWARP_LVSM_MAX_LAYERS], X[SWARP_LVSM_MAX_LAYERS], X2[SWARP_LVSM_MAX_LAYERS];
        double nc[SWARP_LVSM_MAX_LAYERS];
        sw_lloyd_assign(S, c, k, W, X, X2);
        if (sw_lloyd_teleport(W, X, X2, c, k, nc)) {
            rep->max_shift = sw_adopt(c, nc, k, gap);
            ++rep->teleports;
            continue;
        }
        for (uint32_t i = 0; i < k; ++i) nc[i] = (W[i] > 0.0) ? X[i] / W[i] : c[i];
        double shift = sw_adopt(c, nc, k, gap);
        rep->max_shift = shift;
        if (shift <= tol) {
            rep->converged = 1;
            return SWARP_OK;
        }
    }
}

/* Back to depth units.  Untouched splits come back bit-identical
 * (NO_WEIGHT, one layer).  A range of only a few ulps (the capped gap of
 * sw_lloyd_gap) can still round two splits together: step to the next
 * representable value so the splits stay strictly increasing (possible:
 * the input had N + 1 distinct values in range). */
static void sw_lloyd_write(const double* splits_in, uint32_t n_layers, const double* c, double s_0,
                           double s_N, double range, int untouched, double* splits_out) {
    const uint32_t k = n_layers - 1;
    double out[SWARP_LVSM_MAX_LAYERS + 1];
    out[0] = s_0;
    for (uint32_t i = 0; i < k; ++i) out[i + 1] = untouched ? splits_in[i + 1] : s_0 + c[i] * range;
    out[n_layers] = s_N;
    for (uint32_t i = 1; i < n_layers; ++i)
        if (!(out[i] > out[i - 1])) out[i] = nextafter(out[i - 1], s_N);
    for (uint32_t i = n_layers - 1; i > 0; --i)
        if (!(out[i] < out[i + 1])) out[i] = nextafter(out[i + 1], s_0);
    for (uint32_t i = 0; i <= n_layers; ++i) splits_out[i] = out[i];
}

SWARP_API swarp_status swarp_lvsm_lloyd(const double* mu, const double* sigma2, size_t count,
                                        const swarp_lloyd_options* opt,
                                        const double* splits_in, uint32_t n_layers,
                                        double* splits_out, swarp_lloyd_report* out_report) {
    if (!mu || !sigma2 || !splits_out) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_lvsm_check_splits(splits_in, n_layers);
    if (st != SWARP_OK) return st;
    if (count == 0) return SWARP_ERR_FILTER_NO_SAMPLES;
    swarp_lloyd_options o;
    st = sw_lloyd_check(mu, sigma2, count, opt, &o);
    if (st != SWARP_OK) return st;

    sw_lloyd_samples S = {mu, sigma2, count, o.weight_clamp_lo, o.weight_clamp_hi, 0.0,
                          splits_in[0], splits_in[n_layers], 0.0};
    S.range = S.s_N - S.s_0;
    const uint32_t max_it = o.max_iterations ? o.max_iterations : SW_LLOYD_DEFAULT_ITERATIONS;
    const double tol = o.tolerance > 0.0 ? o.tolerance / S.range : SW_LLOYD_REL_TOL;
    const uint32_t k = n_layers - 1; /* inner splits = cluster means */
    const double gap = sw_lloyd_gap(&S, k);
    for (size_t j = 0; j < count; ++j) {
        double w = sw_weight(sigma2[j], S.lo, S.hi);
        if (w > S.w_max) S.w_max = w;
    }

    double c[SWARP_LVSM_MAX_LAYERS];
    for (uint32_t i = 0; i < k; ++i) c[i] = (splits_in[i + 1] - S.s_0) / S.range;

    swarp_lloyd_report rep;
    memset(&rep, 0, sizeof rep);
    swarp_status result = SWARP_OK;
    if (k == 0)
        rep.converged = 1; /* one layer: nothing to place */
    else if (!(S.w_max > 0.0))
        result = SWARP_INFO_FILTER_NO_WEIGHT;
    else
        result = sw_lloyd_relax(&S, c, k, gap, tol, max_it, &rep);
    sw_lloyd_write(splits_in, n_layers, c, S.s_0, S.s_N, S.range, result == SWARP_INFO_FILTER_NO_WEIGHT,
                   splits_out);
    rep.max_shift *= S.range; /* back to depth units too */
    if (out_report) *out_report = rep;
    return result;
}
