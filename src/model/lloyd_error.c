/* Core: Lloyd's perspective aliasing error metric [RHS] (2.3)-(2.8).
 *
 *   m_x(z, n') = res_ix/res_s f (n' + z - n) / (z (n' + f - n))                    (2.3)
 *   m_z(z, n') = res_iy/res_t (f - n)/(2 tan Theta) (n' + z - n)^2 / (z n' (n' + f - n))  (2.4)
 *   n' = n : (2.5), (2.6) (PSM);   n' -> inf : (2.7), (2.8) (uniform).
 *
 * Both are evaluated as products of ratios that stay near 1 for large n',
 * so n' = 1e300 is as accurate as n' = 10, and n' = +INFINITY takes the
 * closed-form limits (2.7)/(2.8) instead of a large number.
 *
 * Why no sampling is needed for the maxima: with a = n' - n,
 *   m_x ~ (a + z)/z = 1 + a/z        is monotone in z,
 *   m_z ~ (a + z)^2/z = a^2/z + 2a + z  is convex in z (a^2/z convex, rest linear),
 * so on [n, f] both attain their maximum at z = n or z = f.
 */
#include "common/swarp_internal.h"

#define SW_HALF_PI (0.5 * SWARP_PI)

_Static_assert(offsetof(swarp_error_config, _reserved) == 7 * sizeof(double),
               "swarp_error_config layout");
_Static_assert(sizeof(swarp_error_config) == 7 * sizeof(double) + 16, "swarp_error_config size");

/* ---- checks -------------------------------------------------------------- */

/* Everything of the config but near/far (the split functions ignore those). */
static swarp_status sw_cfg_common(const swarp_error_config* c) {
    if (!sw_reserved_zero(c->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
    if (!sw_finite(c->theta)) return SWARP_ERR_NON_FINITE;
    if (!(c->theta > 0.0 && c->theta < SW_HALF_PI)) return SWARP_ERR_FOV;
    if (!(sw_finite(c->res_ix) && c->res_ix > 0.0) || !(sw_finite(c->res_iy) && c->res_iy > 0.0) ||
        !(sw_finite(c->res_s) && c->res_s > 0.0) || !(sw_finite(c->res_t) && c->res_t > 0.0))
        return SWARP_ERR_RESOLUTION;
    return SWARP_OK;
}

static swarp_status sw_near_far(double n, double f) {
    if (!sw_finite(n) || !sw_finite(f)) return SWARP_ERR_NON_FINITE;
    if (!(n > 0.0) || !(f > n)) return SWARP_ERR_NEAR_FAR;
    return SWARP_OK;
}

static swarp_status sw_cfg_full(const swarp_error_config* c) {
    swarp_status s = sw_cfg_common(c);
    if (s != SWARP_OK) return s;
    return sw_near_far(c->z_near, c->z_far);
}

/* n' in (0, +inf]: +INFINITY is the uniform map. */
static swarp_status sw_nprime(double n_prime) {
    if (isnan(n_prime) || n_prime == -INFINITY) return SWARP_ERR_NON_FINITE;
    if (!(n_prime > 0.0)) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* ---- evaluation (no checks) -------------------------------------------- */

/* A product of factors kept as mantissa * 2^e (sw_xd, swarp_internal.h):
 * no intermediate overflows or underflows (a tiny resolution such as
 * res_iy = 1e-320 against (f - n) ~ 1e8 would otherwise underflow to 0 a
 * value that is representable); one ldexp at the end rounds once. */
static void sw_sc_mul(sw_xd* x, double f, int divide) {
    *x = divide ? sw_xd_div(*x, sw_xd_of(f)) : sw_xd_mul(*x, sw_xd_of(f));
}
/* the value, or 0 when not finite (overflow) */
static int sw_sc_value(const sw_xd* x, double* out) {
    double v = sw_xd_get(*x);
    if (!sw_finite(v)) return 0;
    *out = v;
    return 1;
}

/* m_x over the range [n, f]; 0 on overflow. */
static int sw_mx(const swarp_error_config* c, double n, double f, double z, double n_prime,
                 double* out) {
    sw_xd v = sw_xd_of(1.0);
    sw_sc_mul(&v, c->res_ix, 0); /* k_x = res_ix/res_s */
    sw_sc_mul(&v, c->res_s, 1);
    sw_sc_mul(&v, f, 0);
    sw_sc_mul(&v, z, 1);
    if (!isinf(n_prime)) { /* [RHS] (2.3); n' = n gives [RHS] (2.5); else (2.7) */
        double num = n_prime + (z - n), den = n_prime + (f - n);
        if (!sw_finite(den)) { /* n' near DBL_MAX: the same ratio, scaled by 1/4 */
            num = 0.25 * n_prime + 0.25 * (z - n);
            den = 0.25 * n_prime + 0.25 * (f - n);
        }
        sw_sc_mul(&v, num, 0);
        sw_sc_mul(&v, den, 1);
    }
    return sw_sc_value(&v, out);
}

/* m_z over the range [n, f]; 0 on overflow. */
static int sw_mz(const swarp_error_config* c, double n, double f, double z, double n_prime,
                 double* out) {
    /* k_z = res_iy/res_t (f - n)/(2 tan Theta) */
    sw_xd v = sw_xd_of(1.0);
    sw_sc_mul(&v, c->res_iy, 0);
    sw_sc_mul(&v, c->res_t, 1);
    sw_sc_mul(&v, f - n, 0);
    sw_sc_mul(&v, 2.0 * tan(c->theta), 1);
    sw_sc_mul(&v, z, 1); /* [RHS] (2.8): k_z / z */
    if (!isinf(n_prime)) { /* [RHS] (2.4) as k_z * r1 * r2 / z; n' = n gives [RHS] (2.6) */
        double a = n_prime + (z - n), b = n_prime + (f - n), np = n_prime;
        if (!sw_finite(b)) { /* n' near DBL_MAX: the same ratios, scaled by 1/4 */
            a = 0.25 * n_prime + 0.25 * (z - n);
            b = 0.25 * n_prime + 0.25 * (f - n);
            np = 0.25 * n_prime;
        }
        sw_sc_mul(&v, a, 0); /* r1 = a/n' */
        sw_sc_mul(&v, np, 1);
        sw_sc_mul(&v, a, 0); /* r2 = a/(n' + f - n) */
        sw_sc_mul(&v, b, 1);
    }
    return sw_sc_value(&v, out);
}

/* ---- single range --------------------------------------------------------- */

/* One point query m(z) over the config's [near, far], m = sw_mx or sw_mz:
 * a full config, a finite z inside [near, far] and a valid n', then the value
 * (SWARP_ERR_OVERFLOW when it is not finite). */
typedef int (*sw_point_fn)(const swarp_error_config* c, double n, double f, double z,
                           double n_prime, double* out);
static swarp_status sw_point(const swarp_error_config* cfg, double z, double n_prime,
                             sw_point_fn m, double* out) {
    if (!cfg || !out) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_cfg_full(cfg);
    if (s != SWARP_OK) return s;
    if (!sw_finite(z)) return SWARP_ERR_NON_FINITE;
    if ((s = sw_nprime(n_prime)) != SWARP_OK) return s;
    if (!(z >= cfg->z_near && z <= cfg->z_far)) return SWARP_ERR_OUT_OF_RANGE;
    double v;
    if (!m(cfg, cfg->z_near, cfg->z_far, z, n_prime, &v)) return SWARP_ERR_OVERFLOW;
    *out = v;
    return SWARP_OK;
}

/* [RHS] (2.3), (2.5), (2.7) */
SWARP_API swarp_status swarp_error_mx(const swarp_error_config* cfg, double z, double n_prime,
                                      double* out_mx) {
    return sw_point(cfg, z, n_prime, sw_mx, out_mx);
}

/* [RHS] (2.4), (2.6), (2.8) */
SWARP_API swarp_status swarp_error_mz(const swarp_error_config* cfg, double z, double n_prime,
                                      double* out_mz) {
    return sw_point(cfg, z, n_prime, sw_mz, out_mz);
}

/* Maxima over [n, f] at the end points (monotone m_x, convex m_z). */
static int sw_range_max(const swarp_error_config* c, double n, double f, double n_prime,
                        double* max_mx, double* max_mz) {
    double xn, xf, zn, zf;
    if (!sw_mx(c, n, f, n, n_prime, &xn) || !sw_mx(c, n, f, f, n_prime, &xf) ||
        !sw_mz(c, n, f, n, n_prime, &zn) || !sw_mz(c, n, f, f, n_prime, &zf))
        return 0;
    *max_mx = xn > xf ? xn : xf;
    *max_mz = zn > zf ? zn : zf;
    return 1;
}

/* [RHS] (2.3)-(2.8), exact maxima */
SWARP_API swarp_status swarp_error_max(const swarp_error_config* cfg, double n_prime,
                                       double* out_max_mx, double* out_max_mz) {
    if (!cfg) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_cfg_full(cfg);
    if (s != SWARP_OK) return s;
    if ((s = sw_nprime(n_prime)) != SWARP_OK) return s;
    double mx, mz;
    if (!sw_range_max(cfg, cfg->z_near, cfg->z_far, n_prime, &mx, &mz)) return SWARP_ERR_OVERFLOW;
    if (out_max_mx) *out_max_mx = mx;
    if (out_max_mz) *out_max_mz = mz;
    return SWARP_OK;
}

/* ---- partitioned frustum ([RHS] Fig. 3.15, 3.18) ------------------------ */

static swarp_status sw_splits_check(const swarp_error_config* cfg, const double* splits,
                                    const double* n_primes, size_t m) {
    if (!cfg || !splits || !n_primes) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_cfg_common(cfg);
    if (s != SWARP_OK) return s;
    if (m == 0) return SWARP_ERR_SPLIT_COUNT;
    for (size_t i = 0; i <= m; ++i)
        if (!sw_finite(splits[i])) return SWARP_ERR_NON_FINITE;
    if (!(splits[0] > 0.0)) return SWARP_ERR_NEAR_FAR;
    for (size_t i = 0; i < m; ++i)
        if (!(splits[i + 1] > splits[i])) return SWARP_ERR_NOT_INCREASING;
    for (size_t i = 0; i < m; ++i)
        if ((s = sw_nprime(n_primes[i])) != SWARP_OK) return s;
    return SWARP_OK;
}

/* Split holding z: the last i with splits[i] <= z, at most m - 1 (so z on a
 * border belongs to the split that starts there, and z = splits[m] to the
 * last one).  Binary search: m may be large. */
static size_t sw_find_split(const double* splits, size_t m, double z) {
    size_t lo = 0, hi = m - 1;
    while (lo < hi) {
        size_t mid = lo + (hi - lo + 1) / 2;
        if (splits[mid] <= z)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

static int sw_split_eval(const swarp_error_config* cfg, const double* splits,
                         const double* n_primes, size_t m, double z, double* mx, double* mz) {
    size_t i = sw_find_split(splits, m, z);
    return sw_mx(cfg, splits[i], splits[i + 1], z, n_primes[i], mx) &&
           sw_mz(cfg, splits[i], splits[i + 1], z, n_primes[i], mz);
}

/* [RHS] (2.3)-(2.8) per split, [RHS] Fig. 3.15 / 3.18 */
SWARP_API swarp_status swarp_error_split_curve(const swarp_error_config* cfg,
                                               const double* splits,
                                               const double* n_primes, size_t m,
                                               const double* z, size_t count,
                                               double* out_mx, double* out_mz) {
    swarp_status s = sw_splits_check(cfg, splits, n_primes, m);
    if (s != SWARP_OK) return s;
    if (count > 0 && !z) return SWARP_ERR_NULL_POINTER;
    /* pass 1: validate and evaluate everything, write nothing */
    for (size_t k = 0; k < count; ++k) {
        if (!sw_finite(z[k])) return SWARP_ERR_NON_FINITE;
        if (!(z[k] >= splits[0] && z[k] <= splits[m])) return SWARP_ERR_OUT_OF_RANGE;
        double mx, mz;
        if (!sw_split_eval(cfg, splits, n_primes, m, z[k], &mx, &mz)) return SWARP_ERR_OVERFLOW;
    }
    /* pass 2: write (z may alias an output: read z[k] before writing index k) */
    for (size_t k = 0; k < count; ++k) {
        double mx = 0.0, mz = 0.0;
        (void)sw_split_eval(cfg, splits, n_primes, m, z[k], &mx, &mz);
        if (out_mx) out_mx[k] = mx;
        if (out_mz) out_mz[k] = mz;
    }
    return SWARP_OK;
}

/* [RHS] (2.3)-(2.8) per split, exact maxima */
SWARP_API swarp_status swarp_error_split_max(const swarp_error_config* cfg,
                                             const double* splits,
                                             const double* n_primes, size_t m,
                                             double* out_split_max_mx,
                                             double* out_split_max_mz,
                                             double* out_max_mx, double* out_max_mz) {
    swarp_status s = sw_splits_check(cfg, splits, n_primes, m);
    if (s != SWARP_OK) return s;
    double all_mx = 0.0, all_mz = 0.0;
    for (size_t i = 0; i < m; ++i) {
        double mx, mz;
        if (!sw_range_max(cfg, splits[i], splits[i + 1], n_primes[i], &mx, &mz))
            return SWARP_ERR_OVERFLOW;
        if (mx > all_mx) all_mx = mx;
        if (mz > all_mz) all_mz = mz;
    }
    for (size_t i = 0; i < m; ++i) {
        double mx = 0.0, mz = 0.0;
        (void)sw_range_max(cfg, splits[i], splits[i + 1], n_primes[i], &mx, &mz);
        if (out_split_max_mx) out_split_max_mx[i] = mx;
        if (out_split_max_mz) out_split_max_mz[i] = mz;
    }
    if (out_max_mx) *out_max_mx = all_mx;
    if (out_max_mz) *out_max_mz = all_mz;
    return SWARP_OK;
}
