/* Hard-case / fuzz entries for the filter stage: VSM ([VSM] (3.1)-(3.4)),
 * layered VSM ([VSM] (4.2), §4.1), EVSM (§4.2), moment shadow maps, PCF and
 * PCSS ([RHS] §3.6).  Statuses: NULL, non-finite, out-of-range arguments
 * with a documented status are predicted; other documented domain errors are
 * accepted (swr_allow) with outputs untouched.  Properties: the closed forms
 * (moments, Chebyshev, linstep, warp, PCSS widths) against a direct
 * evaluation; visibilities in [0, 1]; layer indices in range and holding t;
 * Lloyd splits strictly increasing with the ends fixed; Poisson points in the
 * unit disk with the reported minimum distance. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_vsm_moments)
SWR_WEAK(swarp_vsm_chebyshev)
SWR_WEAK(swarp_vsm_reduce_bleeding)
SWR_WEAK(swarp_lvsm_layer_interval)
SWR_WEAK(swarp_lvsm_warp)
SWR_WEAK(swarp_lvsm_moments)
SWR_WEAK(swarp_lvsm_layer_uniform)
SWR_WEAK(swarp_lvsm_layer_find)
SWR_WEAK(swarp_lvsm_transition)
SWR_WEAK(swarp_lvsm_visibility)
SWR_WEAK(swarp_lvsm_second_occluder)
SWR_WEAK(swarp_lvsm_lloyd)
SWR_WEAK(swarp_evsm_max_exponent)
SWR_WEAK(swarp_evsm_moments)
SWR_WEAK(swarp_evsm_visibility)
SWR_WEAK(swarp_msm_moments)
SWR_WEAK(swarp_msm_bias)
SWR_WEAK(swarp_msm_visibility)
SWR_WEAK(swarp_pcf_poisson_disk)
SWR_WEAK(swarp_pcss_search_width)
SWR_WEAK(swarp_pcss_penumbra)
SWR_WEAK(swarp_pcss_filter_width)

#define EPS DBL_EPSILON

static const double brk01[] = {0.0, 1.0, 0.5};

static void e_vsm_moments(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_vsm_moments);
    double x = swr_num(c, -1, 2, brk01, 3);
    double m[2];
    double* po = swr_out(c, m, sizeof m, SWR_REQ);
    FIN(c, x);
    if (swr_isfin(x) && !swr_isfin(x * x)) swr_allow(c, SWARP_ERR_OVERFLOW), swr_allow(c, SWARP_ERR_NON_FINITE);
    swarp_status st = SWR_CALL(c, swarp_vsm_moments(x, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "M_1", m[0]);
    swr_rec(c, "M_2", m[1]);
    /* [VSM] (3.1); x^2 to within its rounding (any rounding mode) */
    SWR_CHECK(c, m[0] == x && fabsl(m[1] - (long double)x * x) <= 2 * EPS * (long double)x * x + DBL_MIN,
              "moments (%.17g, %.17g) of %.17g", m[0], m[1], x);
}

static void e_vsm_chebyshev(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_vsm_chebyshev);
    double mu = swr_num(c, 0, 1, brk01, 3);
    double var = swr_one_in(c, 6) ? 0.0 : swr_num(c, 0, 0.1, NULL, 0);
    double m[2] = {mu, mu * mu + var};
    if (swr_one_in(c, 10)) m[1] = mu * mu - swr_num(c, 0, 1e-9, NULL, 0); /* rounding made it negative */
    const double brk_t[] = {mu, 0.0, 1.0};
    double t = swr_num(c, 0, 1, brk_t, 3);
    double mv = swr_one_in(c, 3) ? 0.0 : swr_num(c, 0, 1e-4, NULL, 0);
    int n_m = swr_null(c), n_o = swr_null(c);
    if (n_m || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    FIN(c, m[0]);
    FIN(c, m[1]);
    FIN(c, t);
    FIN(c, mv);
    if (swr_isfin(mv) && mv < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swr_args(c, "m=(%.17g %.17g) t=%.17g min_var=%.17g", m[0], m[1], t, mv);
    double p;
    swr_fill(&p, sizeof p);
    swarp_status st = SWR_CALL(c, swarp_vsm_chebyshev(n_m ? NULL : m, t, mv, n_o ? NULL : &p));
    if (!swr_verdict(c, st, 1, (void*)&p, sizeof p)) return;
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "p_max", p);
    SWR_CHECK(c, p >= 0 && p <= 1, "p_max = %g outside [0, 1]", p);
    /* [VSM] (3.2)-(3.3) */
    long double s2 = (long double)m[1] - (long double)m[0] * m[0];
    if (s2 < mv) s2 = mv;
    long double d = (long double)t - m[0];
    long double ref = t <= m[0] ? 1.0L : s2 / (s2 + d * d);
    /* M_2 - M_1^2 cancels: an error of eps M_2 in sigma2 is rounding */
    long double dref = (s2 + d * d) > 0 ? 8 * EPS * (fabsl((long double)m[1]) + 1e-300L) / (s2 + d * d) : 1;
    SWR_CHECK_ACC(c, fabsl(p - ref) <= 1e-12L + dref, "p_max = %.17g, (3.3) gives %.17Lg", p, ref);
}

static void e_vsm_reduce_bleeding(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_vsm_reduce_bleeding);
    double p = swr_num(c, 0, 1, brk01, 3), a = swr_num(c, 0, 1, brk01, 3);
    double o;
    double* po = swr_out(c, &o, sizeof o, SWR_REQ);
    FIN(c, p);
    FIN(c, a);
    if (swr_isfin(p) && !(p >= 0 && p <= 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (swr_isfin(a) && !(a >= 0 && a < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swarp_status st = SWR_CALL(c, swarp_vsm_reduce_bleeding(p, a, po));
    if (!swr_done(c, st)) return;
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "p", o);
    long double ref = ((long double)p - a) / (1.0L - a);
    ref = ref < 0 ? 0 : ref > 1 ? 1 : ref;
    SWR_CHECK(c, o >= 0 && o <= 1 && fabsl(o - ref) <= 4 * EPS / (1 - a), "linstep %.17g, want %.17Lg", o, ref);
}

/* N + 1 split depths: uniform, random increasing, sometimes not increasing */
static uint32_t gen_splits(swr_ctx* c, double* s, uint32_t max_n) {
    uint32_t n = swr_one_in(c, 24) ? (swr_one_in(c, 2) ? 0 : SWARP_LVSM_MAX_LAYERS + 1) : 1 + swr_u8(c) % max_n;
    uint32_t k = n <= max_n ? n : max_n;
    double s0 = swr_num(c, 0, 1, brk01, 3), w = swr_num(c, 1e-3, 10, NULL, 0);
    s[0] = s0;
    for (uint32_t i = 1; i <= k; ++i) s[i] = s[i - 1] + w * swr_num_in(c, 0.1, 1, NULL, 0);
    if (swr_one_in(c, 16) && k >= 2) s[1 + swr_u8(c) % k] = s0; /* not increasing */
    return n;
}
static int increasing(const double* s, uint32_t n) {
    for (uint32_t i = 0; i < n; ++i)
        if (!(s[i + 1] > s[i])) return 0;
    return 1;
}
static double thinnest(const double* s, uint32_t n) {
    double t = INFINITY;
    for (uint32_t i = 0; i < n; ++i) t = fmin(t, s[i + 1] - s[i]);
    return t;
}
static void expect_splits(swr_ctx* c, const double* s, uint32_t n, int null_s) {
    if (null_s) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n == 0 || n > SWARP_LVSM_MAX_LAYERS) {
        swr_expect(c, SWARP_ERR_FILTER_LAYER_COUNT);
        return;
    }
    for (uint32_t i = 0; i <= n; ++i) FIN(c, s[i]);
    if (!increasing(s, n)) swr_expect(c, SWARP_ERR_NOT_INCREASING);
    /* the whole range s_N - s_0 must be representable (documented) */
    else if (isfinite(s[0]) && isfinite(s[n]) && !isfinite(s[n] - s[0])) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
}

#define MAXN 8
static void e_lvsm_layer_interval(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_layer_interval);
    double s[MAXN + 1] = {0};
    uint32_t n = gen_splits(c, s, MAXN), i = swr_u8(c) % (MAXN + 1);
    double th = n >= 1 && n <= MAXN ? thinnest(s, n) : 1;
    const double brk[] = {0.0, th};
    double delta = swr_num(c, 0, th, brk, 2);
    int n_s = swr_null(c), n_p = swr_null(c), n_q = swr_null(c);
    if (n_p || n_q) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_splits(c, s, n, n_s);
    FIN(c, delta);
    if (n >= 1 && n <= MAXN && i >= n) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (swr_isfin(delta) && !(delta >= 0 && delta < th)) swr_expect(c, SWARP_ERR_FILTER_OVERLAP);
    if (fabs(delta - th) <= 4 * EPS * th) c->rounding_edge = 1;
    double p, q;
    swr_fill(&p, sizeof p);
    swr_fill(&q, sizeof q);
    swarp_status st = SWR_CALL(c, swarp_lvsm_layer_interval(n_s ? NULL : s, n, i, delta, n_p ? NULL : &p, n_q ? NULL : &q));
    if (!swr_verdict(c, st, 2, (void*)&p, sizeof p, (void*)&q, sizeof q)) return;
    swr_rec(c, "p", p);
    swr_rec(c, "q", q);
    /* [VSM] §4.1.1 */
    double wp = i == 0 ? s[0] : s[i] - delta, wq = i == n - 1 ? s[n] : s[i + 1] + delta;
    double tol = 2 * EPS * (fabs(wp) + fabs(wq) + delta); /* s_i -+ delta rounds */
    SWR_CHECK(c, fabs(p - wp) <= tol && fabs(q - wq) <= tol, "layer %u: [%.17g, %.17g], want [%.17g, %.17g]", i, p, q, wp, wq);
}

static void e_lvsm_warp_or_moments(swr_ctx* c, int moments) {
    double p = swr_num(c, 0, 1, brk01, 3), q = swr_one_in(c, 10) ? p : p + swr_num(c, 1e-6, 2, NULL, 0);
    const double brk[] = {p, q};
    double t = swr_num(c, p - 1, q + 1, brk, 2);
    int nul = swr_null(c);
    if (nul) swr_expect(c, SWARP_ERR_NULL_POINTER);
    FIN(c, t);
    FIN(c, p);
    FIN(c, q);
    if (swr_isfin(p) && swr_isfin(q) && !(q > p)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    double o[2];
    swr_fill(o, sizeof o);
    swarp_status st = moments ? SWR_CALL(c, swarp_lvsm_moments(t, p, q, nul ? NULL : o))
                              : SWR_CALL(c, swarp_lvsm_warp(t, p, q, nul ? NULL : o));
    if (!swr_verdict(c, st, 1, (void*)o, moments ? sizeof o : sizeof o[0])) return;
    long double ref = t <= p ? 0 : t >= q ? 1 : ((long double)t - p) / ((long double)q - p); /* [VSM] (4.2) */
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "phi", o[0]);
    SWR_CHECK(c, o[0] >= 0 && o[0] <= 1 && fabsl(o[0] - ref) <= 4 * EPS, "phi %.17g, want %.17Lg", o[0], ref);
    if (moments) {
        swr_rec(c, "phi^2", o[1]);
        SWR_CHECK(c, fabs(o[1] - o[0] * o[0]) <= 2 * EPS * o[0] * o[0], "second moment %.17g != phi^2", o[1]);
    }
}
static void e_lvsm_warp(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_warp);
    e_lvsm_warp_or_moments(c, 0);
}
static void e_lvsm_moments(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_moments);
    e_lvsm_warp_or_moments(c, 1);
}

/* the layer holding t: s_i <= t < s_{i+1} (last layer closed), clamped */
static uint32_t layer_of(const double* s, uint32_t n, double t) {
    if (t < s[0]) return 0;
    for (uint32_t i = 0; i < n; ++i)
        if (t < s[i + 1]) return i;
    return n - 1;
}

static void e_lvsm_layer_uniform(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_layer_uniform);
    double s0 = swr_num(c, 0, 1, brk01, 3), sN = swr_one_in(c, 12) ? s0 : s0 + swr_num(c, 1e-6, 10, NULL, 0);
    uint32_t n = swr_one_in(c, 24) ? 0 : 1 + swr_u8(c) % 64;
    const double brk[] = {s0, sN, s0 + (sN - s0) / 2, s0 + (sN - s0) / 3};
    double t = swr_num(c, s0 - 1, sN + 1, brk, 4);
    uint32_t L;
    uint32_t* po = swr_out(c, &L, sizeof L, SWR_REQ);
    FIN(c, t);
    FIN(c, s0);
    FIN(c, sN);
    if (n == 0 || n > SWARP_LVSM_MAX_LAYERS) swr_expect(c, SWARP_ERR_FILTER_LAYER_COUNT);
    if (swr_isfin(s0) && swr_isfin(sN) && !(sN > s0)) swr_expect(c, SWARP_ERR_NOT_INCREASING);
    if (swr_isfin(t) && sN > s0) { /* on a split the computed layer is decided by rounding */
        double u = (t - s0) / (sN - s0) * n;
        if (fabs(u - nearbyint(u)) < 1e-9 * (1 + fabs(u))) c->rounding_edge = 1;
        /* The library's splits are s_0 + h j, h = (s_N - s_0)/N, rounded
         * three times (h, h j, the sum) in the caller's mode: each within
         * 3 eps max(|s_0|, |s_N|) of the exact split (|h j| <= |s_N - s_0|
         * <= 2 max).  A t that close to the nearest exact split sits on it as
         * far as rounding can tell (e.g. layers of 0.27 ulp, t 0.18 ulp from
         * s_8). */
        if (n > 0 && isfinite(u) && fabs(u) < 1e9) {
            long double jn = nearbyintl((long double)u), sj = s0 + ((long double)sN - s0) * jn / n;
            if (jn >= 0 && jn <= n && fabsl(t - sj) <= 4 * EPS * fmax(fabs(s0), fabs(sN))) c->rounding_edge = 1;
        }
    }
    swr_args(c, "t %.17g s_0 %.17g s_N %.17g n %u", t, s0, sN, n);
    swarp_status st = SWR_CALL(c, swarp_lvsm_layer_uniform(t, s0, sN, n, po));
    if (!swr_done(c, st)) return;
    c->rec[c->n_rec < SWR_MAX_REC ? c->n_rec++ : 0] = L;
    SWR_CHECK(c, L < n, "layer %u of %u", L, n);
    SWR_CHECK(c, (st == SWARP_INFO_FILTER_DEPTH_CLAMPED) == (t < s0 || t > sN), "%s for t %s [s_0, s_N]",
              swarp_status_name(st), (t < s0 || t > sN) ? "outside" : "inside");
    /* s_i = s_0 + (s_N - s_0) i / N holds t (one layer of slack for rounding at a split) */
    long double lo = s0 + ((long double)sN - s0) * L / n, hi = s0 + ((long double)sN - s0) * (L + 1.0L) / n;
    long double ulp = 4 * EPS * fmaxl(fabsl(s0), fabsl(sN));
    if (t >= s0 && t <= sN)
        SWR_CHECK_ACC(c, t >= lo - ulp && (t <= hi + ulp), "t %.17g not in layer %u [%.17Lg, %.17Lg]", t, L, lo, hi);
}

static void e_lvsm_layer_find(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_layer_find);
    double s[MAXN + 1] = {0};
    uint32_t n = gen_splits(c, s, MAXN);
    uint32_t k = n <= MAXN ? n : MAXN;
    const double brk[] = {s[0], s[k], s[k / 2]};
    double t = swr_num(c, s[0] - 1, s[k] + 1, brk, 3);
    int n_s = swr_null(c), n_o = swr_null(c);
    if (n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_splits(c, s, n, n_s);
    FIN(c, t);
    uint32_t L;
    swr_fill(&L, sizeof L);
    swarp_status st = SWR_CALL(c, swarp_lvsm_layer_find(t, n_s ? NULL : s, n, n_o ? NULL : &L));
    if (!swr_verdict(c, st, 1, (void*)&L, sizeof L)) return;
    c->rec[c->n_rec < SWR_MAX_REC ? c->n_rec++ : 0] = L;
    SWR_CHECK(c, L == layer_of(s, n, t), "layer %u, want %u", L, layer_of(s, n, t));
    SWR_CHECK(c, (st == SWARP_INFO_FILTER_DEPTH_CLAMPED) == (t < s[0] || t > s[n]), "%s", swarp_status_name(st));
}

static void e_lvsm_transition(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_transition);
    double s[MAXN + 1] = {0};
    uint32_t n = gen_splits(c, s, MAXN);
    uint32_t k = n <= MAXN ? n : MAXN;
    double th = k >= 1 ? thinnest(s, k) : 1;
    const double brk_b[] = {0.0, th / 2};
    double band = swr_num(c, 0, th / 2, brk_b, 2);
    const double brk[] = {s[0], s[k], s[k / 2], s[k / 2] - band, s[k / 2] + band};
    double t = swr_num(c, s[0] - 1, s[k] + 1, brk, 5);
    int n_s = swr_null(c), n_lo = swr_null(c), n_hi = swr_null(c), n_w = swr_null(c);
    if (n_lo || n_hi || n_w) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_splits(c, s, n, n_s);
    FIN(c, t);
    FIN(c, band);
    if (swr_isfin(band) && !(band >= 0 && band < th / 2)) swr_expect(c, SWARP_ERR_FILTER_BAND);
    if (fabs(band - th / 2) <= 4 * EPS * th) c->rounding_edge = 1; /* thinnest layer computed by the library */
    swr_args(c, "n %u s_0 %.17g s_k/2 %.17g s_k %.17g band %.17g t %.17g", n, s[0], s[k / 2], s[k], band, t);
    uint32_t lo, hi;
    double w;
    swr_fill(&lo, sizeof lo);
    swr_fill(&hi, sizeof hi);
    swr_fill(&w, sizeof w);
    swarp_status st = SWR_CALL(c, swarp_lvsm_transition(t, n_s ? NULL : s, n, band, n_lo ? NULL : &lo, n_hi ? NULL : &hi,
                                                       n_w ? NULL : &w));
    if (!swr_verdict(c, st, 3, (void*)&lo, sizeof lo, (void*)&hi, sizeof hi, (void*)&w, sizeof w)) return;
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "w", w);
    c->rec[c->n_rec < SWR_MAX_REC ? c->n_rec++ : 0] = lo;
    SWR_CHECK(c, lo < n && hi < n && (hi == lo || hi == lo + 1), "layers %u %u of %u", lo, hi, n);
    SWR_CHECK(c, w >= 0 && w <= 1, "w = %g", w);
    if (hi == lo) SWR_CHECK(c, w == 0, "one layer but w = %g", w);
}

/* Visibility of layer i in long double from its ends p, q (the library's
 * formulas: [VSM] (4.2) warp, (3.2) variance, the floor mapped by the warp's
 * slope 1/(q - p), Chebyshev's bound) */
static long double lvsm_layer_vis_ref(const double* mom, uint32_t i, long double t, long double p, long double q, long double mv) {
    long double phi = t <= p ? 0 : t >= q ? 1 : (t - p) / (q - p), mu = mom[2 * i];
    if (phi <= mu) return 1;
    long double s2 = mom[2 * i + 1] - mu * mu, fl = mv > 0 ? mv / ((q - p) * (q - p)) : 0;
    if (!(s2 >= fl)) s2 = fl;
    long double d = phi - mu, v = s2 / (s2 + d * d);
    return v < 0 ? 0 : v > 1 ? 1 : v;
}
/* The layer ends p_i = s_i - delta, q_i = s_{i+1} + delta are formed at the
 * magnitude of the splits, each rounded to eps |s| in the caller's mode;
 * the warp phi = (t - p)/(q - p) and the floor min_var/(q - p)^2 carry that
 * divided by the width q - p (s_0 = 1e7, a width of 5e-4: 4e10 eps per
 * rounding of an end; cases 12182, 28001).  The condition of v (absolute:
 * v in [0, 1]) with respect to that rounding: v in long double with every
 * end moved by +-eps of its magnitude, max |dv| / eps.  lo, hi, w as the
 * library's transition (§4.1.3). */
static double lvsm_vis_cond(const double* mom, const double* s, uint32_t k, double delta, double band, double t, double mv) {
    uint32_t j = layer_of(s, k, t), lo = j, hi = j;
    long double w = 0;
    if (band > 0 && t >= s[0] && t <= s[k]) {
        if (j > 0 && t - s[j] < band) lo = j - 1, w = (((long double)t - s[j]) + band) / (2.0L * band);
        else if (j + 1 < k && s[j + 1] - t < band) hi = j + 1, w = (((long double)t - s[j + 1]) + band) / (2.0L * band);
        w = w < 0 ? 0 : w > 1 ? 1 : w;
    }
    long double v0 = 0, kap = 0;
    for (int pass = 0; pass < 10; ++pass) { /* pass 0: unmoved; then the 9 moves (a, b) */
        const int a = pass == 0 ? 0 : (pass - 1) / 3 - 1, b = pass == 0 ? 0 : (pass - 1) % 3 - 1;
        long double v = 0;
        for (uint32_t i = lo; i <= hi; ++i) {
            long double p = i == 0 ? (long double)s[0] : (long double)s[i] - delta;
            long double q = i + 1 == k ? (long double)s[k] : (long double)s[i + 1] + delta;
            p += a * EPS * fabsl(p), q += b * EPS * fabsl(q);
            long double vi = lvsm_layer_vis_ref(mom, i, t, p, q, mv);
            v += lo == hi ? vi : i == lo ? (1 - w) * vi : w * vi;
        }
        if (pass == 0) v0 = v;
        else kap = fmaxl(kap, fabsl(v - v0) / EPS);
    }
    return (double)kap;
}
static void e_lvsm_visibility(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_visibility);
    double s[MAXN + 1] = {0}, mom[2 * MAXN];
    uint32_t n = gen_splits(c, s, MAXN);
    uint32_t k = n <= MAXN ? n : MAXN;
    double th = k >= 1 ? thinnest(s, k) : 1;
    double delta = swr_num(c, 0, th * 0.9, NULL, 0), band = swr_one_in(c, 3) ? 0 : swr_num(c, 0, fmin(delta, th / 2), NULL, 0);
    for (uint32_t i = 0; i < MAXN; ++i) {
        double m1 = swr_num(c, 0, 1, brk01, 3);
        mom[2 * i] = m1;
        mom[2 * i + 1] = m1 * m1 + swr_num(c, 0, 0.05, NULL, 0);
    }
    double t = swr_num(c, s[0] - 1, s[k] + 1, NULL, 0), mv = swr_num(c, 0, 1e-4, NULL, 0);
    int n_m = swr_null(c), n_s = swr_null(c), n_o = swr_null(c);
    if (n_m || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_splits(c, s, n, n_s);
    for (uint32_t i = 0; i < 2 * k; ++i) FIN(c, mom[i]);
    FIN(c, t);
    FIN(c, delta);
    FIN(c, band);
    FIN(c, mv);
    static const swarp_status dom[] = {SWARP_ERR_FILTER_OVERLAP, SWARP_ERR_FILTER_BAND, SWARP_ERR_OUT_OF_RANGE};
    for (size_t i = 0; i < 3; ++i) swr_domain(c, dom[i]);
    if (swr_isfin(mv) && mv < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (fabs(band - delta) <= 4 * EPS * th || fabs(band - th / 2) <= 4 * EPS * th || fabs(delta - th) <= 4 * EPS * th)
        c->rounding_edge = 1; /* on a documented bound the library computes */
    swr_args(c, "n %u s_0 %.17g s_k %.17g delta %.17g band %.17g t %.17g min_var %.17g m_0 %.17g %.17g", n, s[0], s[k],
             delta, band, t, mv, mom[0], mom[1]);
    double v;
    swr_fill(&v, sizeof v);
    swarp_status st = SWR_CALL(c, swarp_lvsm_visibility(n_m ? NULL : mom, n_s ? NULL : s, n, delta, band, t, mv, n_o ? NULL : &v));
    if (!swr_verdict(c, st, 1, (void*)&v, sizeof v)) return;
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "visibility", v);
    SWR_CHECK(c, v >= 0 && v <= 1, "visibility %g outside [0, 1]", v);
    swr_cond(c, lvsm_vis_cond(mom, s, k, delta, band, t, mv));
}

static void e_lvsm_second_occluder(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_second_occluder);
    double mu = swr_num(c, 0, 1, brk01, 3), s2 = swr_num(c, -1e-9, 0.25, brk01, 2);
    double o;
    double* po = swr_out(c, &o, sizeof o, SWR_REQ);
    FIN(c, mu);
    FIN(c, s2);
    swr_args(c, "mu %.17g sigma2 %.17g", mu, s2);
    swarp_status st = SWR_CALL(c, swarp_lvsm_second_occluder(mu, s2, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "depth", o);
    long double ref = (long double)mu + sqrtl(s2 > 0 ? s2 : 0);
    /* mu + sigma cancels for mu < 0 (the sweep's edge values, mu = -1 with
     * sigma2 = 1 + 1e-9): its condition number (|mu| + sigma)/|mu + sigma|,
     * which the check below already allows for, is recorded for the fenv
     * comparison, where a correctly rounded sqrt in another rounding mode moves
     * sigma by an ulp (e.g. 4e-7 relative at condition 4e9) */
    if (ref != 0) swr_cond(c, (double)((fabsl(ref - mu) + fabs(mu)) / fabsl(ref)));
    SWR_CHECK_ACC(c, fabsl(o - ref) <= 4 * EPS * (fabsl(ref) + fabs(mu)), "mu + sigma = %.17g, want %.17Lg", o, ref);
}

static void e_lvsm_lloyd(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lvsm_lloyd);
    enum { NS = 24 };
    double mu[NS], s2[NS], s[MAXN + 1] = {0}, out[MAXN + 1];
    size_t count = swr_one_in(c, 16) ? 0 : 1 + swr_u8(c) % NS;
    for (int i = 0; i < NS; ++i) {
        mu[i] = swr_num(c, 0, 1, brk01, 3);
        s2[i] = swr_one_in(c, 4) ? 0.0 : swr_num(c, 0, 0.05, NULL, 0);
    }
    uint32_t n = gen_splits(c, s, MAXN);
    uint32_t k = n <= MAXN ? n : MAXN;
    swarp_lloyd_options opt;
    memset(&opt, 0, sizeof opt);
    opt.max_iterations = swr_u8(c) % 4 == 0 ? swr_u8(c) : 0;
    opt.weight_clamp_lo = swr_one_in(c, 3) ? swr_num(c, 0, 0.01, NULL, 0) : 0;
    opt.weight_clamp_hi = swr_one_in(c, 3) ? swr_num(c, 0, 0.1, NULL, 0) : 0;
    opt.tolerance = swr_one_in(c, 3) ? swr_num(c, 0, 1e-3, NULL, 0) : 0;
    opt._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use_opt = !swr_one_in(c, 3), alias = swr_one_in(c, 4);
    int n_mu = swr_null(c), n_s2 = swr_null(c), n_s = swr_null(c), n_o = swr_null(c), n_r = swr_one_in(c, 3);
    if (n_mu || n_s2 || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_splits(c, s, n, n_s);
    if (count == 0) swr_expect(c, SWARP_ERR_FILTER_NO_SAMPLES);
    for (size_t i = 0; i < count; ++i) {
        FIN(c, mu[i]);
        FIN(c, s2[i]);
    }
    if (use_opt) {
        FIN(c, opt.weight_clamp_lo);
        FIN(c, opt.weight_clamp_hi);
        FIN(c, opt.tolerance);
        for (int i = 0; i < 4; ++i)
            if (opt._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        swr_allow(c, SWARP_ERR_OUT_OF_RANGE); /* clamps and tolerance: bounds not all documented */
        if (opt.weight_clamp_lo < 0 || opt.tolerance < 0 || (opt.weight_clamp_hi != 0 && opt.weight_clamp_hi < opt.weight_clamp_lo))
            swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    swr_args(c, "count=%zu n=%u s=(%.17g %.17g %.17g ... %.17g) opt=%d it=%u lo=%g hi=%g tol=%g mu0=%g s2_0=%g", count, n,
             s[0], s[1], s[2], s[k], use_opt, opt.max_iterations, opt.weight_clamp_lo, opt.weight_clamp_hi, opt.tolerance,
             mu[0], s2[0]);
    swarp_lloyd_report rep;
    double* dst = alias ? s : out;
    double keep[MAXN + 1];
    memcpy(keep, s, sizeof keep);
    if (!alias) swr_fill(out, sizeof out);
    swr_fill(&rep, sizeof rep);
    swarp_status st = SWR_CALL(c, swarp_lvsm_lloyd(n_mu ? NULL : mu, n_s2 ? NULL : s2, count, use_opt ? &opt : NULL,
                                                  n_s ? NULL : s, n, n_o ? NULL : dst, n_r ? NULL : &rep));
    if (alias && swarp_status_is_error(st)) SWR_CHECK(c, memcmp(keep, s, sizeof keep) == 0, "aliased splits changed on error");
    /* an iteration: converged or not is decided at the tolerance, and the
     * splits are only defined to within it (fenv test) */
    if (st == SWARP_INFO_FILTER_NOT_CONVERGED) c->rounding_edge = 1;
    {
        double range = fabs(keep[k] - keep[0]), tol_used = use_opt && opt.tolerance > 0 ? opt.tolerance : 1e-9 * range;
        double mag = fmax(fabs(keep[0]), fabs(keep[k]));
        if (mag > 0) c->tol_min = 1e3 * tol_used / mag;
    }
    if (!swr_verdict(c, st, 2, alias ? NULL : (void*)out, sizeof out, (void*)&rep, sizeof rep)) return;
    for (uint32_t i = 0; i <= k; ++i) swr_rec(c, "split", dst[i]);
    SWR_CHECK(c, dst[0] == keep[0] && dst[k] == keep[k], "ends moved: %.17g %.17g", dst[0], dst[k]);
    /* "kept strictly increasing (minimum gap 1e-9 (s_N - s_0))": a gap below
     * one ulp of the splits cannot be kept -- a finding, not a failure, when
     * the range is that narrow (e.g. depths offset by 1e6, docs/quality.md) */
    double ulp = nextafter(fmax(fabs(keep[0]), fabs(keep[k])), INFINITY) - fmax(fabs(keep[0]), fabs(keep[k]));
    int narrow = 1e-9 * (keep[k] - keep[0]) < 4 * ulp;
    for (uint32_t i = 0; i < k; ++i) {
        if (narrow) {
            if (!(dst[i + 1] > dst[i]) && !c->finding) {
                snprintf(c->finding_msg, sizeof c->finding_msg,
                         "lloyd: splits collapse (s_%u = s_%u = %.17g): the 1e-9 gap is below an ulp", i, i + 1, dst[i]);
                c->finding++;
            }
            continue;
        }
        SWR_CHECK(c, dst[i + 1] > dst[i], "relaxed splits not strictly increasing: s_%u = %.17g, s_%u = %.17g", i,
                  dst[i], i + 1, dst[i + 1]);
    }
    if (!n_r) SWR_CHECK(c, rep.converged == (st == SWARP_OK) || st == SWARP_INFO_FILTER_NO_WEIGHT, "report.converged %u with %s",
                        rep.converged, swarp_status_name(st));
}

static void e_evsm_max_exponent(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_evsm_max_exponent);
    int32_t f = swr_enum(c, 3);
    double e;
    double* po = swr_out(c, &e, sizeof e, SWR_REQ);
    if (f < 0 || f > 2) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    swarp_status st = SWR_CALL(c, swarp_evsm_max_exponent((swarp_texel_format)f, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "c", e);
    /* c = (ln F_max - 4u)/2, u = 2^-(p+1): fp16 p = 10, F_max = 65504; fp32
     * p = 23, F_max = (2 - 2^-23) 2^127 -- computed here from p and e_max */
    int p = f == 1 ? 10 : 23, emax = f == 1 ? 15 : 127;
    long double Fmax = (2.0L - ldexpl(1.0L, -p)) * ldexpl(1.0L, emax), u = ldexpl(1.0L, -(p + 1));
    long double want = (logl(Fmax) - 4 * u) / 2;
    SWR_CHECK(c, fabsl(e - want) <= 1e-14L * want, "c = %.17g for format %d, want %.17Lg", e, f, want);
    SWR_CHECK(c, expl(2.0L * e) < Fmax, "e^{2c} = %.17Lg does not fit F_max %.17Lg", expl(2.0L * e), Fmax);
}

static void e_evsm_moments(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_evsm_moments);
    const double brk_c[] = {44.36, 5.545, 0.0};
    double x = swr_num(c, 0, 1, brk01, 3), cp = swr_num(c, 0, 50, brk_c, 3), cn = swr_num(c, 0, 50, brk_c, 3);
    double m[4];
    double* po = swr_out(c, m, sizeof m, SWR_REQ);
    FIN(c, x);
    FIN(c, cp);
    FIN(c, cn);
    if (swr_isfin(cp) && swr_isfin(cn) && swr_isfin(x)) {
        if (!(cp > 0) || !(cn > 0)) swr_expect(c, SWARP_ERR_FILTER_EXPONENT);
        else if (fmaxl(2.0L * cp * x, -2.0L * cn * x) > logl(DBL_MAX) + 1e-12L) {
            /* (the bound is ln DBL_MAX = 709.78..., not 709: e^{709.2} is a
             * finite double, crash-6e110d38ab22e9f6; 1e-12 covers the rounding
             * of c·x and of the squared exponential) */
            /* a moment overflows: documented FILTER_EXPONENT; the library says
             * NON_FINITE (doc/implementation mismatch, docs/quality.md) */
            swr_expect(c, SWARP_ERR_FILTER_EXPONENT);
            swr_domain(c, SWARP_ERR_NON_FINITE);
            c->rounding_edge = 1; /* an overflow: directed rounding gives DBL_MAX */
        } else if (2 * fmax(cp, cn) * fabs(x) > 700 || fmax(cp, cn) > 354) {
            /* the library refuses an exponent whose e^{2c} overflows even when
             * e^{2c|x|} is finite for this x (doc: "e^{2c|x|} finite") */
            swr_domain(c, SWARP_ERR_FILTER_EXPONENT);
            swr_domain(c, SWARP_ERR_NON_FINITE);
            c->rounding_edge = 1;
        }
    }
    swr_args(c, "x=%.17g c_pos=%.17g c_neg=%.17g", x, cp, cn);
    swarp_status st = SWR_CALL(c, swarp_evsm_moments(x, cp, cn, po));
    if (!swr_done(c, st)) return;
    for (int i = 0; i < 4; ++i) swr_rec(c, "moment", m[i]);
    long double r[4] = {expl((long double)cp * x), expl(2.0L * cp * x), -expl(-(long double)cn * x), expl(-2.0L * cn * x)};
    for (int i = 0; i < 4; ++i) /* exp's condition number is |argument| */
        swr_close(c, "EVSM moment", m[i], r[i], 16 * EPS * (1 + 2 * fmax(cp, cn) * fabs(x)), DBL_MIN);
}

/* The condition of EVSM's visibility (absolute: v in [0, 1]) with respect
 * to the rounding of the warped receiver w = +-e^{c t}: the library's w
 * carries eps (c |t| + 2) |w| (c t's rounding times c |t|, exp's own ulp or
 * two), d = w - M_1 that absolute error, and Chebyshev's
 * v = s2/(s2 + d^2) has dv/dd = -2 v (1 - v)/d: kappa = 2 v (1 - v)
 * (c |t| + 2) |w| / |d|, plus 2 (c |t| + 2) v (1 - v) when the floor
 * min_var (c w)^2 is the variance.  A receiver a hair behind a huge warped
 * mean (w ~ 1e11, d ~ 1e-8 w) has v near 1 move by 1e-8 with the rounding
 * mode.  The bound v = min(v+, v-)
 * takes the warp that gives it (both when they are within 1e-6). */
static void evsm_vis_cond(swr_ctx* c, const double m[4], double t, double cp, double cn, double mv) {
    if (!(fabs(t) * fmax(cp, cn) <= 350) || !(cp > 0) || !(cn > 0)) return;
    long double vi[2], ki[2];
    for (int i = 0; i < 2; ++i) {
        const long double cc = i == 0 ? cp : cn, w = i == 0 ? expl(cc * t) : -expl(-cc * t), mu = m[2 * i], e = cc * fabs(t) + 2;
        vi[i] = 1, ki[i] = 0;
        if (w <= mu) continue; /* in front of the mean: v = 1 */
        long double s2 = m[2 * i + 1] - mu * mu, fl = mv * (cc * w) * (cc * w), d = w - mu;
        int floored = !(s2 >= fl);
        if (floored) s2 = fl;
        vi[i] = s2 / (s2 + d * d);
        ki[i] = 2 * vi[i] * (1 - vi[i]) * e * (fabsl(w) / d + floored);
    }
    const long double vmin = fminl(vi[0], vi[1]);
    for (int i = 0; i < 2; ++i)
        if (vi[i] <= vmin + 1e-6L) swr_cond(c, (double)ki[i]);
}

static void e_evsm_visibility(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_evsm_visibility);
    double x = swr_num(c, 0, 1, brk01, 3), cp = swr_num(c, 0.5, 40, NULL, 0), cn = swr_num(c, 0.5, 40, NULL, 0);
    double m[4] = {exp(cp * x), exp(2 * cp * x), -exp(-cn * x), exp(-2 * cn * x)};
    if (swr_one_in(c, 4)) { /* a filtered pair of depths */
        double y = swr_num(c, 0, 1, brk01, 3);
        m[0] = 0.5 * (m[0] + exp(cp * y));
        m[1] = 0.5 * (m[1] + exp(2 * cp * y));
        m[2] = 0.5 * (m[2] - exp(-cn * y));
        m[3] = 0.5 * (m[3] + exp(-2 * cn * y));
    }
    if (swr_one_in(c, 16)) m[swr_u8(c) % 4] = swr_num(c, -10, 10, NULL, 0);
    double t = swr_num(c, 0, 1, brk01, 3), mv = swr_num(c, 0, 1e-4, NULL, 0);
    int n_m = swr_null(c), n_o = swr_null(c);
    if (n_m || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    for (int i = 0; i < 4; ++i) FIN(c, m[i]);
    FIN(c, t);
    FIN(c, cp);
    FIN(c, cn);
    FIN(c, mv);
    if (swr_isfin(mv) && mv < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swr_domain(c, SWARP_ERR_FILTER_EXPONENT);
    if (swr_isfin(cp) && swr_isfin(cn) && (!(cp > 0) || !(cn > 0))) swr_expect(c, SWARP_ERR_FILTER_EXPONENT);
    /* exp(c t) overflows for receiver depths far outside [0, 1]: the library
     * says NON_FINITE there (documented: FILTER_EXPONENT) */
    if (swr_isfin(t) && fabs(t) * fmax(fabs(cp), fabs(cn)) > 350) {
        swr_domain(c, SWARP_ERR_NON_FINITE);
        c->rounding_edge = 1;
    }
    swr_args(c, "m=(%.17g %.17g %.17g %.17g) t=%.17g c_pos=%.17g c_neg=%.17g min_var=%.17g", m[0], m[1], m[2], m[3], t,
             cp, cn, mv);
    /* an exponent far below 1: the warped variance is below the rounding of
     * the moments, the bound is decided by rounding (fenv test) */
    if (fabs(cp) < 1e-3 || fabs(cn) < 1e-3) c->rounding_edge = 1;
    /* The receiver against each mean, w = e^{c t} vs M_1 (t <= mu: v = 1,
     * the documented 0 <-> 1 of a zero variance): the library's w carries
     * c t's rounding times c |t| plus exp's own (an ulp or two), so
     * |w - M_1| <= 4 eps (c |t| + 2) |w| is on the threshold as far as
     * rounding can tell (e.g. t = x, the negative warp one ulp off
     * its mean under FE_DOWNWARD, v 0 instead of 1) */
    if (swr_isfin(t) && cp > 0 && cn > 0 && fabs(t) * fmax(cp, cn) <= 350) {
        const long double w[2] = {expl((long double)cp * t), -expl(-(long double)cn * t)}, ct[2] = {cp * fabs(t), cn * fabs(t)};
        for (int i = 0; i < 2; ++i)
            if (fabsl(w[i] - m[2 * i]) <= 4 * EPS * (ct[i] + 2) * fabsl(w[i])) c->rounding_edge = 1;
    }
    double v;
    swr_fill(&v, sizeof v);
    swarp_status st = SWR_CALL(c, swarp_evsm_visibility(n_m ? NULL : m, t, cp, cn, mv, n_o ? NULL : &v));
    if (!swr_verdict(c, st, 1, (void*)&v, sizeof v)) return;
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "visibility", v);
    SWR_CHECK(c, v >= 0 && v <= 1, "visibility %g outside [0, 1]", v);
    evsm_vis_cond(c, m, t, cp, cn, mv);
}

static void e_msm_moments(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_msm_moments);
    double z = swr_num(c, 0, 1, brk01, 3);
    double b[4];
    double* po = swr_out(c, b, sizeof b, SWR_REQ);
    FIN(c, z);
    if (swr_isfin(z) && !(z >= 0 && z <= 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swarp_status st = SWR_CALL(c, swarp_msm_moments(z, po));
    if (!swr_done(c, st)) return;
    long double p = 1;
    for (int i = 0; i < 4; ++i) {
        p *= z;
        swr_rec(c, "b", b[i]);
        swr_close(c, "z^k", b[i], p, 4 * EPS, DBL_MIN / (4 * EPS));
    }
}

static void e_msm_bias(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_msm_bias);
    double b[4], z = swr_num_in(c, 0, 1, brk01, 3);
    for (int i = 0; i < 4; ++i) b[i] = pow(z, i + 1);
    if (swr_one_in(c, 10)) b[swr_u8(c) % 4] = swr_num(c, -1, 2, NULL, 0);
    const double brk_a[] = {0.0, 1.0, SWARP_MSM_ALPHA_DEFAULT};
    double a = swr_num(c, 0, 1, brk_a, 3);
    int n_b = swr_null(c), n_o = swr_null(c);
    if (n_b || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    for (int i = 0; i < 4; ++i) FIN(c, b[i]);
    FIN(c, a);
    if (swr_isfin(a) && !(a >= 0 && a <= 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    double o[4];
    swr_fill(o, sizeof o);
    swarp_status st = SWR_CALL(c, swarp_msm_bias(n_b ? NULL : b, a, n_o ? NULL : o));
    if (!swr_verdict(c, st, 1, (void*)o, sizeof o)) return;
    for (int i = 0; i < 4; ++i) {
        swr_rec(c, "b'", o[i]);
        long double ref = (1.0L - a) * b[i] + 0.5L * a;
        swr_close(c, "biased moment", o[i], ref, 4 * EPS, fabs(b[i]) + 0.5);
    }
}

static void e_msm_visibility(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_msm_visibility);
    double b[4] = {0, 0, 0, 0};
    int k = 1 + swr_u8(c) % 3; /* mixture of k depths */
    for (int j = 0; j < k; ++j) {
        double z = swr_num_in(c, 0, 1, brk01, 3), p = 1;
        for (int i = 0; i < 4; ++i) {
            p *= z;
            b[i] += p / k;
        }
    }
    double a = swr_one_in(c, 2) ? SWARP_MSM_ALPHA_DEFAULT : 0;
    for (int i = 0; i < 4; ++i) b[i] = (1 - a) * b[i] + 0.5 * a;
    if (swr_one_in(c, 12)) b[swr_u8(c) % 4] = swr_num(c, -1, 2, NULL, 0);
    double zf = swr_num(c, 0, 1, brk01, 3);
    for (int i = 0; i < 4; ++i) /* derived moments can be extreme too (a fuzz input: b_2 = 1.9e-182) */
        if (b[i] != 0 && swr_isfin(b[i]) && (fabs(b[i]) < 1e-100 || fabs(b[i]) > 1e100)) c->extreme = 1;
    int n_b = swr_null(c), n_o = swr_null(c);
    if (n_b || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    for (int i = 0; i < 4; ++i) FIN(c, b[i]);
    FIN(c, zf);
    if (swr_isfin(b[1]) && swr_isfin(b[3]) && (b[1] < 0 || b[3] < 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swr_args(c, "b=(%.17g %.17g %.17g %.17g) z_f=%.17g", b[0], b[1], b[2], b[3], zf);
    /* z_f far outside [0, 1]: the quadratic's roots lose all digits (a
     * finding: default rounding says lit, FE_DOWNWARD says shadowed) */
    if (!(fabs(zf) < 1e6)) c->rounding_edge = 1;
    double v;
    swr_fill(&v, sizeof v);
    swarp_status st = SWR_CALL(c, swarp_msm_visibility(n_b ? NULL : b, zf, n_o ? NULL : &v));
    if (st == SWARP_INFO_FILTER_MSM_DEGENERATE) c->rounding_edge = 1; /* singular to rounding */
    if (!swr_verdict(c, st, 1, (void*)&v, sizeof v)) return;
    c->out_scale = 1; /* a fraction in [0, 1] */
    swr_rec(c, "visibility", v);
    SWR_CHECK(c, v >= 0 && v <= 1, "visibility %g outside [0, 1]", v);
    /* Condition: the bound solves B c = (1, z_f, z_f^2) through the LDL^T
     * pivots D22 = b2 - b1^2 and D33 = b4 - b2^2 - L32^2 D22 of the Hankel
     * matrix B; each pivot is a cancellation of terms of total size S (S22 =
     * b2 + b1^2, S33 = b4 + b2^2 + L32^2 D22), so rounding moves it by ~eps S,
     * i.e. eps S / D relative, and c (hence the atoms z2, z3 and the bound)
     * scales with 1/D: the visibility's relative condition is at least
     * S / D.  Just above the library's degeneracy threshold (D33 > 64 eps
     * S33) that is up to 1/(64 eps): a mixture of depths 1 with the default
     * bias gave D33 = 2e-14, S33 / D33 = 7e13, and the visibility moved by
     * 1e-3 with the rounding mode. */
    if (st == SWARP_OK) {
        const long double b1 = b[0], b2 = b[1], b3 = b[2], b4 = b[3];
        const long double D22 = b2 - b1 * b1, S22 = b2 + b1 * b1;
        if (D22 > 0) {
            const long double L32 = (b3 - b1 * b2) / D22;
            const long double D33 = b4 - b2 * b2 - L32 * L32 * D22, S33 = b4 + b2 * b2 + L32 * L32 * D22;
            swr_cond(c, (double)(S22 / D22));
            if (D33 > 0) swr_cond(c, (double)(S33 / D33));
        }
    }
}

static void e_pcf_poisson_disk(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_pcf_poisson_disk);
    uint64_t seed = swr_u64(c);
    uint32_t count = swr_one_in(c, 16) ? (swr_one_in(c, 2) ? 0 : SWARP_PCF_MAX_SAMPLES + 1) : 1 + swr_u8(c) % 48;
    uint32_t cand = swr_one_in(c, 2) ? 0 : 1 + swr_u8(c) % 16;
    size_t cap = swr_one_in(c, 8) ? swr_u8(c) % 50 : 64;
    int n_xy = swr_null(c), n_c = swr_null(c), n_d = swr_null(c);
    if (n_c || n_d || (n_xy && cap > 0)) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_xy && cap == 0) swr_domain(c, SWARP_ERR_NULL_POINTER); /* NULL with capacity 0: not documented */
    if (count == 0 || count > SWARP_PCF_MAX_SAMPLES) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    int cap_short = count >= 1 && count <= SWARP_PCF_MAX_SAMPLES && cap < count;
    if (cap_short) swr_expect(c, SWARP_ERR_CAPACITY);
    double xy[2 * 64 + 2], md;
    size_t got;
    swr_fill(xy, sizeof xy);
    swr_fill(&got, sizeof got);
    swr_fill(&md, sizeof md);
    swarp_status st = SWR_CALL(c, swarp_pcf_poisson_disk(seed, count, cand, n_xy ? NULL : xy, cap, n_c ? NULL : &got,
                                                        n_d ? NULL : &md));
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, got == count, "CAPACITY with needed %zu, want %u", got, count);
        SWR_CHECK(c, swr_untouched(xy, sizeof xy) && swr_untouched(&md, sizeof md), "CAPACITY but points written");
        swr_fill(&got, sizeof got);
    }
    if (!swr_verdict(c, st, 3, (void*)xy, sizeof xy, (void*)&got, sizeof got, (void*)&md, sizeof md)) return;
    SWR_CHECK(c, got == count, "count %zu, want %u", got, count);
    double best = INFINITY;
    for (uint32_t i = 0; i < count && i < 64; ++i) {
        swr_rec(c, "x", xy[2 * i]);
        swr_rec(c, "y", xy[2 * i + 1]);
        SWR_CHECK(c, xy[2 * i] * xy[2 * i] + xy[2 * i + 1] * xy[2 * i + 1] <= 1 + 1e-12, "point %u outside the unit disk", i);
        for (uint32_t j = 0; j < i; ++j)
            best = fmin(best, hypot(xy[2 * i] - xy[2 * j], xy[2 * i + 1] - xy[2 * j + 1]));
    }
    swr_rec(c, "min distance", md);
    if (count == 1) SWR_CHECK(c, md == 0, "min distance %g for one point", md);
    else SWR_CHECK(c, fabs(md - best) <= 1e-12, "min distance %.17g, measured %.17g", md, best);
    SWR_CHECK(c, swr_untouched(xy + 2 * count, sizeof xy - 2 * count * sizeof xy[0]), "wrote past 2 count");
}

typedef swarp_status (*pcss_fn)(double, double, double, double*);
static void e_pcss(swr_ctx* c, int which) {
    double a = swr_num(c, 0, 10, brk01, 2), b = swr_num(c, 0.01, 100, NULL, 0), d = swr_num(c, 0.01, 200, NULL, 0);
    if (swr_one_in(c, 6)) d = b; /* n_light = d_r, d_b = d_r */
    int nul = swr_null(c);
    if (nul) swr_expect(c, SWARP_ERR_NULL_POINTER);
    FIN(c, a);
    FIN(c, b);
    FIN(c, d);
    swr_args(c, "a=%.17g b=%.17g d=%.17g", a, b, d);
    double o;
    swr_fill(&o, sizeof o);
    swarp_status st;
    long double ref;
    int fin_all = swr_isfin(a) && swr_isfin(b) && swr_isfin(d);
    if (which == 1) { /* penumbra(d_r = d, d_b = b, w_light = a) */
        if (fin_all && a < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        if (fin_all && (!(b > 0) || b > d)) swr_expect(c, SWARP_ERR_FILTER_BLOCKER);
        ref = ((long double)d - b) * a / b;
        if (fin_all && fabsl(ref) > DBL_MAX) swr_expect(c, SWARP_ERR_OVERFLOW); /* documented */
        st = SWR_CALL(c, swarp_pcss_penumbra(d, b, a, nul ? NULL : &o));
    } else { /* search / filter width (w = a, n_light = b, d_r = d) */
        if (fin_all && !(b > 0 && b <= d)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        swr_allow(c, SWARP_ERR_OUT_OF_RANGE); /* w < 0: not documented either way */
        if (which == 0) {
            st = SWR_CALL(c, swarp_pcss_search_width(a, b, d, nul ? NULL : &o));
            ref = (long double)a * ((long double)d - b) / d;
        } else {
            st = SWR_CALL(c, swarp_pcss_filter_width(a, b, d, nul ? NULL : &o));
            ref = (long double)a * b / d;
        }
    }
    if (!swr_verdict(c, st, 1, (void*)&o, sizeof o)) return;
    swr_rec(c, "width", o);
    /* the terms' magnitude in long double: |d| + |b| overflowed double at
     * d = b = DBL_MAX and 0 * Inf made the floor NaN */
    long double terms = fabsl((long double)a) * (fabsl((long double)d) + fabsl((long double)b)) /
                        fminl(fabsl((long double)b), fabsl((long double)d));
    swr_close(c, "PCSS width [RHS] 3.6", o, ref, 8 * EPS, (double)fminl(terms, DBL_MAX) + DBL_MIN);
}
static void e_pcss_search_width(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_pcss_search_width);
    e_pcss(c, 0);
}
static void e_pcss_penumbra(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_pcss_penumbra);
    e_pcss(c, 1);
}
static void e_pcss_filter_width(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_pcss_filter_width);
    e_pcss(c, 2);
}

const swr_entry swr_entries_filter[] = {
    {"swarp_vsm_moments", "filter", e_vsm_moments},
    {"swarp_vsm_chebyshev", "filter", e_vsm_chebyshev},
    {"swarp_vsm_reduce_bleeding", "filter", e_vsm_reduce_bleeding},
    {"swarp_lvsm_layer_interval", "filter", e_lvsm_layer_interval},
    {"swarp_lvsm_warp", "filter", e_lvsm_warp},
    {"swarp_lvsm_moments", "filter", e_lvsm_moments},
    {"swarp_lvsm_layer_uniform", "filter", e_lvsm_layer_uniform},
    {"swarp_lvsm_layer_find", "filter", e_lvsm_layer_find},
    {"swarp_lvsm_transition", "filter", e_lvsm_transition},
    {"swarp_lvsm_visibility", "filter", e_lvsm_visibility},
    {"swarp_lvsm_second_occluder", "filter", e_lvsm_second_occluder},
    {"swarp_lvsm_lloyd", "filter", e_lvsm_lloyd},
    {"swarp_evsm_max_exponent", "filter", e_evsm_max_exponent},
    {"swarp_evsm_moments", "filter", e_evsm_moments},
    {"swarp_evsm_visibility", "filter", e_evsm_visibility},
    {"swarp_msm_moments", "filter", e_msm_moments},
    {"swarp_msm_bias", "filter", e_msm_bias},
    {"swarp_msm_visibility", "filter", e_msm_visibility},
    {"swarp_pcf_poisson_disk", "filter", e_pcf_poisson_disk},
    {"swarp_pcss_search_width", "filter", e_pcss_search_width},
    {"swarp_pcss_penumbra", "filter", e_pcss_penumbra},
    {"swarp_pcss_filter_width", "filter", e_pcss_filter_width},
    {NULL, NULL, NULL},
};
