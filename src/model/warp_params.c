/* Core: the closed-form warp parameters.
 *
 *   [RHS] (3.2)  n_opt = d / (sqrt(z_1/z_0) - 1)                (LiSPSM, [WS06])
 *   [RHS] (4.2)  n_opt with pseudo-near / pseudo-far planes
 *   [RHS] (3.3)  Lloyd's warp strength eta(gamma, Theta)
 *   [RHS] (3.5)  W_lz, the view frustum's width along light-space z
 *   [RHS] (3.4)  n_repar(eta)
 *   [GMNPR] (2)  psi, offset (the paper's varphi) and the aliasing function F
 *   [GMNPR] (4)  lambda_1, lambda_2;  (7), (8) lambda_GMNPR;  (9) lambda_LiSPSM
 *   GLPR         lambda with F linear in z, derived from [GMNPR] (2)
 *
 * Policy for huge results (one rule for every warp parameter here): the
 * exactly degenerate input (z_1 == z_0, eta == -1, theta == 0) gives
 * +INFINITY, which IS the uniform map; a value that is finite in exact
 * arithmetic but does not fit a double is clamped to DBL_MAX.  Both are
 * reported with SWARP_INFO_WARP_UNIFORM (numerically the warp is uniform).
 */
#include <float.h>

#include "common/swarp_internal.h"

#define SW_HALF_PI (0.5 * SWARP_PI)

/* ---- shared argument checks -------------------------------------------- */

/* Angle theta (light/view angle) in the closed interval [0, pi/2]. */
static int sw_angle_closed(double a) { return a >= 0.0 && a <= SW_HALF_PI; }
/* Half field of view in the open interval (0, pi/2). */
static int sw_half_fov_ok(double a) { return a > 0.0 && a < SW_HALF_PI; }

/* Writes a warp parameter that may have overflowed: see the policy above. */
static swarp_status sw_put_warp(double v, swarp_status ok_status, double* out) {
    if (!sw_finite(v) || v > DBL_MAX) {
        *out = DBL_MAX;
        return SWARP_INFO_WARP_UNIFORM;
    }
    *out = v;
    return ok_status;
}

/* a * b / c for finite a, b and c != 0, with one rounding into the
 * subnormal range or to overflow at the end: the mantissas are multiplied
 * (|m| in [0.5, 1)) and the exponents added, so no intermediate overflows or
 * underflows when the result itself is representable.  Used where the
 * factors of a warp parameter span more than the double range (extreme
 * inputs beyond 1e+-100, docs/quality.md). */
static double sw_mul_div(double a, double b, double c) {
    int ea, eb, ec;
    double ma = frexp(a, &ea), mb = frexp(b, &eb), mc = frexp(c, &ec);
    return ldexp(ma * mb / mc, ea + eb - ec);
}

/* ---- [RHS] (3.2) and (4.2) --------------------------------------------- */

/* sw_nopt_core for z_0 < 2^-900 z_1, all in mantissa/exponent form (sw_xd):
 * there z_0 4^-k is subnormal or nearly, n_p (z_1 - z_0) 4^-k underflows for
 * subnormal n_p, and z_0 + sqrt(.) sqrt(.) is no longer dominated by normal
 * numbers (in plain doubles n_opt of z_0 = 5e-324, n_p = 5e-324 would be
 * 8% off).  The pseudo-far
 * depth is written z_0 + (1 - f_p) dz, equal to z_1 - f_p dz in exact
 * arithmetic, without its cancellation for f_p near 1 (1 - f_p is exact for
 * f_p >= 1/2).  Off the hot path: only extreme depth ratios get here. */
static swarp_status sw_nopt_tiny_near(double d, double z_0, double dz, double n_p, double f_p,
                                      double* out_n_opt) {
    sw_xd z0 = sw_xd_of(z_0), dzx = sw_xd_of(dz);
    sw_xd rn = sw_xd_sqrt(sw_xd_add(z0, sw_xd_mul(sw_xd_of(n_p), dzx)));
    sw_xd rf = sw_xd_sqrt(sw_xd_add(z0, sw_xd_mul(sw_xd_of(1.0 - f_p), dzx)));
    sw_xd ratio = sw_xd_div(sw_xd_add(z0, sw_xd_mul(rn, rf)), dzx);
    return sw_put_warp(sw_xd_get(sw_xd_mul(sw_xd_of(d), ratio)), SWARP_OK, out_n_opt);
}

/* (3.2) rewritten without the cancellation in sqrt(z_1/z_0) - 1:
 *   d / (sqrt(z_1/z_0) - 1) = d sqrt(z_0) / (sqrt(z_1) - sqrt(z_0))
 *                           = d (z_0 + sqrt(z_0 z_1)) / (z_1 - z_0),
 * and z_1 - z_0 is exact when z_1 ~ z_0 (Sterbenz).  This is also (4.2)
 * at n_p = f_p = 0, so both share sw_nopt_core. */
static swarp_status sw_nopt_core(double d, double z_0, double z_1, double n_p, double f_p,
                                 double* out_n_opt) {
    double dz = z_1 - z_0; /* exact for subnormals and (Sterbenz) for z_1 ~ z_0 */
    if (dz == 0.0) {
        *out_n_opt = INFINITY; /* duelling frusta: uniform is optimal [RHS] §3.2.1 */
        return SWARP_INFO_WARP_UNIFORM;
    }
    /* The ratio (z_0 + root) / dz is homogeneous of degree 0 in the depths,
     * so they are scaled by s = 2^(-2k) (exact) to put z_1 s in [1, 4): the
     * subnormal depths and depths near DBL_MAX neither lose bits nor
     * overflow (d / dz unscaled overflows for z_1 = 4e-319).  sqrt(z s) =
     * sqrt(z) 2^-k keeps the root exact even where z_0 s would be subnormal. */
    int e = ilogb(z_1);
    int k = (e - (e & 1)) / 2; /* floor(e / 2): scaling z by 4^j changes k by exactly j */
    double sh = ldexp(1.0, -k);
    double dz_s = (dz * sh) * sh; /* dz >= ulp(z_1): normal after scaling */
    /* pseudo-near and pseudo-far as scaled eye-space depths */
    double z_0s = (z_0 * sh) * sh, z_1s = (z_1 * sh) * sh;
    if (z_0s < 0x1p-900) return sw_nopt_tiny_near(d, z_0, dz, n_p, f_p, out_n_opt);
    double rn = n_p == 0.0 ? sqrt(z_0) * sh : sqrt(z_0s + n_p * dz_s);
    double rf = f_p == 0.0 ? sqrt(z_1) * sh : sqrt(z_1s - f_p * dz_s);
    double ratio = (z_0s + rn * rf) / dz_s; /* in [~sqrt(z_0/z_1), 2^54] */
    double n_opt = d * ratio;               /* over/underflows only when the value does */
    return sw_put_warp(n_opt, SWARP_OK, out_n_opt);
}

static swarp_status sw_nopt_check(double d, double z_0, double z_1) {
    if (!sw_finite(d) || !sw_finite(z_0) || !sw_finite(z_1)) return SWARP_ERR_NON_FINITE;
    if (!(d > 0.0) || !(z_0 > 0.0) || !(z_1 >= z_0)) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* [RHS] (3.2) */
SWARP_API swarp_status swarp_warp_nopt(double d, double z_0, double z_1, double* out_n_opt) {
    if (!out_n_opt) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_nopt_check(d, z_0, z_1);
    if (s != SWARP_OK) return s;
    return sw_nopt_core(d, z_0, z_1, 0.0, 0.0, out_n_opt);
}

/* [RHS] (4.2), read as in the papers README:
 *   n_opt = d/(z_1 - z_0) (z_0 + sqrt((z_0 + n_p (z_1 - z_0)) (z_1 - f_p (z_1 - z_0)))).
 * For an overhead light (d = z_1 - z_0) this is the n' that equalises Lloyd's
 * m_z at the pseudo-near depth and at the pseudo-far depth (docs/parameters.md). */
SWARP_API swarp_status swarp_warp_nopt_pseudo(double d, double z_0, double z_1, double n_p,
                                              double f_p, double* out_n_opt) {
    if (!out_n_opt) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_nopt_check(d, z_0, z_1);
    if (s != SWARP_OK) return s;
    if (!sw_finite(n_p) || !sw_finite(f_p)) return SWARP_ERR_NON_FINITE;
    if (!(n_p >= 0.0 && n_p <= 1.0) || !(f_p >= 0.0 && f_p <= 1.0) || !(n_p + f_p < 1.0))
        return SWARP_ERR_OUT_OF_RANGE;
    return sw_nopt_core(d, z_0, z_1, n_p, f_p, out_n_opt);
}

/* ---- [RHS] (3.3), (3.5), (3.4) ------------------------------------------ */

/* Lloyd's breakpoints and levels of [RHS] (3.3). */
#define SW_ETA_B (-0.2)
#define SW_ETA_C 0.0
/* [RHS] (3.3): the breakpoint gamma_c lies this fraction of the way from
 * Theta to pi/2. */
#define SW_ETA_GAMMA_C_FRACTION 0.3
/* Below this angle tan(x) = x to 1e-16 (x (1 + x^2/3 + ...)). */
#define SW_TAN_LINEAR 1e-8

/* [RHS] (3.3) */
SWARP_API swarp_status swarp_warp_eta(double gamma, double theta, double* out_eta) {
    if (!out_eta) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(gamma) || !sw_finite(theta)) return SWARP_ERR_NON_FINITE;
    if (!sw_half_fov_ok(theta)) return SWARP_ERR_FOV;
    if (!sw_angle_closed(gamma)) return SWARP_ERR_OUT_OF_RANGE;
    double gamma_a = theta / 3.0;
    double gamma_b = theta;
    double gamma_c = theta + SW_ETA_GAMMA_C_FRACTION * (SW_HALF_PI - theta);
    double eta;
    if (gamma <= gamma_a)
        eta = -1.0;
    else if (gamma <= gamma_b)
        /* the ratio in [0, 1] first: (0.8 (gamma - gamma_a)) / ... rounds
         * 0.8 x 4.9e-324 up to 4.9e-324 for subnormal angles (eta 0, not -0.2) */
        eta = -1.0 + (SW_ETA_B + 1.0) * ((gamma - gamma_a) / (gamma_b - gamma_a));
    else if (gamma <= gamma_c) /* sin(90 deg * t), t in (0, 1] */
        eta = SW_ETA_B + (SW_ETA_C - SW_ETA_B) * sin(SW_HALF_PI * (gamma - gamma_b) / (gamma_c - gamma_b));
    else
        eta = SW_ETA_C;
    *out_eta = eta;
    return SWARP_OK;
}

/* [RHS] (3.5) */
SWARP_API swarp_status swarp_warp_wlz(double gamma, double theta, double n_e, double f_e,
                                      double W_e, double* out_W_lz) {
    if (!out_W_lz) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(gamma) || !sw_finite(theta) || !sw_finite(n_e) || !sw_finite(f_e) ||
        !sw_finite(W_e))
        return SWARP_ERR_NON_FINITE;
    if (!(n_e > 0.0) || !(f_e > n_e)) return SWARP_ERR_NEAR_FAR;
    if (!sw_half_fov_ok(theta)) return SWARP_ERR_FOV;
    if (!sw_angle_closed(gamma) || !(W_e > 0.0)) return SWARP_ERR_OUT_OF_RANGE;
    double W_n = W_e;
    double W_s = (f_e - n_e) / cos(theta); /* length of a side face */
    double Wp_n = W_n * cos(gamma);
    double Wp_s1 = W_s * (1.0 - cos(theta - gamma));
    double Wp_s2 = W_s * sin(theta + gamma);
    double W_lz = Wp_n + Wp_s2 + (gamma <= theta ? Wp_s1 : 0.0);
    if (!sw_finite(W_s)) {
        /* theta within 1e-16 of pi/2 with f_e - n_e beyond ~1e292: W_s
         * overflows while its weight sin(theta + gamma) + (1 - cos(theta -
         * gamma)) can be ~1e-16 (gamma ~ pi/2 too), so W_lz is representable:
         * (f_e - n_e) weight / cos(theta) with one rounding (sw_mul_div).
         * The weight without rounding theta + gamma near pi (28% off):
         * sin(theta + gamma) = sin(theta) cos(gamma) + cos(theta) sin(gamma),
         * two non-negative terms, and 1 - cos(x) = 2 sin^2(x/2). */
        double h = sin(0.5 * (theta - gamma));
        double weight = sin(theta) * cos(gamma) + cos(theta) * sin(gamma) +
                        (gamma <= theta ? 2.0 * h * h : 0.0);
        W_lz = Wp_n + sw_mul_div(f_e - n_e, weight, cos(theta));
    }
    if (!sw_finite(W_lz)) return SWARP_ERR_OVERFLOW;
    *out_W_lz = W_lz;
    return SWARP_OK;
}

/* [RHS] (3.4), second case read as eta*sqrt(alpha) + 1 (papers README). */
SWARP_API swarp_status swarp_warp_nrepar(double eta, double alpha, double W_lz, double* out_n) {
    if (!out_n) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(eta) || !sw_finite(alpha) || !sw_finite(W_lz)) return SWARP_ERR_NON_FINITE;
    if (!(eta >= -1.0 && eta <= 1.0) || !(alpha > 1.0) || !(W_lz > 0.0))
        return SWARP_ERR_OUT_OF_RANGE;
    if (eta == -1.0) {
        *out_n = INFINITY; /* eta = -1 is uniform by construction */
        return SWARP_INFO_WARP_UNIFORM;
    }
    /* W_lz/(alpha - 1) (1 + sqrt(alpha) - eta (alpha - 1))/(eta + 1) with
     * 1/(sqrt(alpha) - 1) = (1 + sqrt(alpha))/(alpha - 1) = r factored out:
     *   eta < 0:  n = W_lz (r - eta) / (eta + 1)
     *   eta >= 0: n = W_lz r / (eta sqrt(alpha) + 1)
     * r - eta and both denominators are sums of non-negative terms (no
     * cancellation; eta + 1 is exact by Sterbenz near -1), r is in
     * [7e-155, 1e16] for every double alpha > 1, and sw_mul_div rounds into
     * the subnormal range or to overflow only at the end: alpha = DBL_MAX or
     * eta = -1 + 1e-16 no longer overflow or underflow in between. */
    double sqrt_alpha = sqrt(alpha);
    double r = (1.0 + sqrt_alpha) / (alpha - 1.0);
    double n;
    if (eta < 0.0)
        n = sw_mul_div(W_lz, r - eta, eta + 1.0);
    else
        n = sw_mul_div(W_lz, r, eta * sqrt_alpha + 1.0);
    return sw_put_warp(n, SWARP_OK, out_n);
}

/* ---- [GMNPR] ------------------------------------------------------------ */
/*
 * Two ratios keep every expression bounded:
 *   t = tan(phi)/tan(theta) in (0, 1]  for theta >= phi   (case 1 of eq. (2))
 *   u = tan(theta)/tan(phi) in [0, 1]  for theta <= phi   (case 2)
 * written with sin/cos so theta = pi/2 (tan huge) and theta -> 0 stay exact.
 * Both cases of (2) agree at theta = phi; the code uses case 1 there.
 */
/* Both are clamped to 1: at theta == phi the rounded tan, cos and sin can
 * give 1 + 2^-52, and then (f - n) + (f + n) t overflowed even in its halved
 * form for f = DBL_MAX (lambda_1 came out 0 instead of ~1e-157). */
static double sw_t_ratio(double theta, double phi) {
    double t = tan(phi) * cos(theta) / sin(theta);
    return t > 1.0 ? 1.0 : t;
}
static double sw_u_ratio(double theta, double phi) {
    double u = sin(theta) / (cos(theta) * tan(phi));
    return u > 1.0 ? 1.0 : u;
}

/* D = f - n + (f + n) tan(phi)/tan(theta): the normalising depth of case 1. */
static double sw_case1_D(double t, double n, double f) { return (f - n) + (f + n) * t; }

/* D / two with two = 1, or 2 when D itself overflows (f near DBL_MAX); the
 * halved form is used only then, since halving subnormal n, f loses bits. */
static double sw_case1_D_half(double t, double n, double f, double* two) {
    double D = sw_case1_D(t, n, f);
    *two = 1.0;
    if (sw_finite(D)) return D;
    *two = 2.0;
    return 0.5 * (f - n) + (0.5 * f + 0.5 * n) * t;
}

static swarp_status sw_gmnpr_frame(double phi, double n, double f) {
    if (!sw_finite(phi) || !sw_finite(n) || !sw_finite(f)) return SWARP_ERR_NON_FINITE;
    if (!(n > 0.0) || !(f > n)) return SWARP_ERR_NEAR_FAR;
    if (!sw_half_fov_ok(phi)) return SWARP_ERR_FOV;
    return SWARP_OK;
}

/* Checks shared by psi, offset and F: theta in (0, pi/2], lambda > 0 finite. */
static swarp_status sw_gmnpr_args(double lambda, double theta, double phi, double n, double f) {
    if (!sw_finite(lambda) || !sw_finite(theta)) return SWARP_ERR_NON_FINITE;
    swarp_status s = sw_gmnpr_frame(phi, n, f);
    if (s != SWARP_OK) return s;
    if (!(theta > 0.0 && theta <= SW_HALF_PI) || !(lambda > 0.0)) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* prod(num) / prod(den) for finite factors (den non-zero): mantissas
 * multiplied, exponents added, one rounding into the subnormal range or to
 * overflow at the end.  [GMNPR] (2) multiplies up to six factors (lambda^2,
 * tan, f, z) that overflow or underflow in pairs for lambda beyond 1e150
 * while psi and F stay representable. */
static sw_xd sw_ratio_xd(const double* num, int n_num, const double* den, int n_den) {
    sw_xd r = sw_xd_of(1.0);
    for (int i = 0; i < n_num; ++i) r = sw_xd_mul(r, sw_xd_of(num[i]));
    for (int i = 0; i < n_den; ++i) r = sw_xd_div(r, sw_xd_of(den[i]));
    return r;
}
static double sw_ratio(const double* num, int n_num, const double* den, int n_den) {
    return sw_xd_get(sw_ratio_xd(num, n_num, den, n_den));
}

/* The exponent 2k that sw_normalise_nf-like scaling by 4^-k would use to
 * bring f into [1, 4), or 0 when that would push n into the subnormals. */
static int sw_depth_shift(double n, double f) {
    int e = ilogb(f);
    int k = (e - (e & 1)) / 2; /* floor(e / 2) */
    if (k > 0 && ldexp(n, -2 * k) < DBL_MIN) return 0;
    return 2 * k;
}

/* Appends lambda (lambda + 1) to a list of denominators as lambda, lambda + 1
 * for lambda < 1 and as lambda, lambda, 1 + 1/lambda above (lambda + 1
 * rounds to +inf for lambda = DBL_MAX under FE_UPWARD); returns the count. */
static int sw_put_ll(double lambda, double* den) {
    if (lambda < 1.0) {
        den[0] = lambda;
        den[1] = lambda + 1.0;
        return 2;
    }
    den[0] = den[1] = lambda;
    den[2] = 1.0 + 1.0 / lambda;
    return 3;
}

/* psi and offset of (2) without checks; each flag is 0 on overflow.
 * psi = 1/(tan(phi) D lambda (lambda + 1)) (case 1) or
 * 1/(2 f lambda (lambda + 1) tan(theta)) (case 2), as a ratio of factors so
 * that lambda (lambda + 1) overflowing does not make psi 0.  psi is of degree
 * -1 and varphi of degree 1 in (n, f): both are evaluated on depths scaled
 * exactly by 2^-sh into [1, 4) and scaled back by 2^sh in the exponent, so
 * subnormal depths keep their bits (D of n = 5e-324, f = 2e-317 had ~10) and
 * varphi ~ D lambda neither overflows nor underflows in between. */
static void sw_gmnpr_psi_offset(double lambda, double theta, double phi, double n, double f,
                                double* psi, int* psi_ok, double* offset, int* offset_ok) {
    double p, o, den[6];
    const double one = 1.0;
    int sh = sw_depth_shift(n, f);
    n = ldexp(n, -sh);
    f = ldexp(f, -sh);
    if (theta >= phi) {
        double t = sw_t_ratio(theta, phi), two;
        double Dh = sw_case1_D_half(t, n, f, &two);
        den[0] = tan(phi);
        den[1] = Dh;
        den[2] = two;
        p = sw_xd_get(sw_xd_scale(sw_ratio_xd(&one, 1, den, 3 + sw_put_ll(lambda, den + 3)), -sh));
        /* varphi = D lambda + n t - n with D = two Dh */
        sw_xd v = sw_xd_mul(sw_xd_mul(sw_xd_of(Dh), sw_xd_of(two)), sw_xd_of(lambda));
        v = sw_xd_add(sw_xd_add(v, sw_xd_of(n * t)), sw_xd_of(-n));
        o = sw_xd_get(sw_xd_scale(v, sh));
    } else {
        /* 1/(tan(phi) 2 f lambda (lambda+1) tan(theta)/tan(phi)) = 1/(2 f ll tan(theta)) */
        double u = sw_u_ratio(theta, phi);
        den[0] = 2.0;
        den[1] = f;
        den[2] = tan(theta);
        p = sw_xd_get(sw_xd_scale(sw_ratio_xd(&one, 1, den, 3 + sw_put_ll(lambda, den + 3)), -sh));
        /* varphi = f ((2 lambda + 1)/u - 1), 2 lambda + 1 = 2 (lambda + 1/2) */
        sw_xd q = sw_xd_div(sw_xd_scale(sw_xd_of(lambda + 0.5), 1), sw_xd_of(u));
        sw_xd v = sw_xd_mul(sw_xd_of(f), sw_xd_add(q, sw_xd_of(-1.0)));
        o = sw_xd_get(sw_xd_scale(v, sh));
    }
    *psi = p;
    *psi_ok = sw_finite(p);
    *offset = o;
    *offset_ok = sw_finite(o);
}

/* F = psi (z + varphi)^2 / z of (2) without checks; 0 when it overflows.
 * The square (z + varphi)^2 ~ lambda^2 is never formed: for lambda >= 1,
 * a = (z + varphi)/lambda stays bounded and
 *   F = a^2 / ((1 + 1/lambda) tan(phi) D z)          (case 1),
 *   F = a^2 / ((1 + 1/lambda) 2 f tan(theta) z)      (case 2);
 * for lambda < 1, zo = z + varphi itself is bounded and
 *   F = zo^2 / (lambda (lambda + 1) tan(phi) D z)    (likewise case 2).
 * In case 1, z + varphi = D lambda + c with c = (z - n) + n t >= 0 (no
 * cancellation); in case 2 it is (z - f) + f (2 lambda + 1)/u >= z. */
static int sw_gmnpr_F_value(double lambda, double theta, double phi, double n, double f, double z,
                            double* out_F) {
    double a, two = 1.0, den[7];
    int n_den;
    if (theta >= phi) {
        /* with D = two Dh: F = (a/two)^2 two / (... Dh ...) */
        double t = sw_t_ratio(theta, phi);
        double Dh = sw_case1_D_half(t, n, f, &two);
        double c = ((z - n) + n * t) / two;
        den[0] = tan(phi);
        den[1] = Dh;
        n_den = 2;
        a = lambda >= 1.0 ? Dh + c / lambda : Dh * lambda + c;
    } else {
        double u = sw_u_ratio(theta, phi);
        den[0] = 2.0;
        den[1] = f;
        den[2] = tan(theta);
        n_den = 3;
        a = lambda >= 1.0 ? (z - f) / lambda + sw_mul_div(f, 2.0 + 1.0 / lambda, u)
                          : (z - f) + sw_mul_div(f, 2.0 * lambda + 1.0, u);
    }
    den[n_den++] = z;
    if (lambda >= 1.0) {
        den[n_den++] = 1.0 + 1.0 / lambda; /* a = zo / lambda */
    } else {
        den[n_den++] = lambda; /* a = zo */
        den[n_den++] = lambda + 1.0;
    }
    if (!sw_finite(a) || !(a > 0.0)) return 0;
    const double num[3] = {a, a, two};
    double F = sw_ratio(num, 3, den, n_den);
    if (!sw_finite(F)) return 0;
    *out_F = F;
    return 1;
}

/* [GMNPR] (2): psi (want_offset 0) or varphi (1), both from one
 * evaluation; OVERFLOW when the one asked for is above DBL_MAX or below the
 * subnormals. */
static swarp_status sw_gmnpr_psi_or_offset(double lambda, double theta, double phi, double n, double f,
                                           int want_offset, double* out) {
    if (!out) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_gmnpr_args(lambda, theta, phi, n, f);
    if (s != SWARP_OK) return s;
    double psi, offset;
    int psi_ok, offset_ok;
    sw_gmnpr_psi_offset(lambda, theta, phi, n, f, &psi, &psi_ok, &offset, &offset_ok);
    if (!(want_offset ? offset_ok : psi_ok)) return SWARP_ERR_OVERFLOW;
    *out = want_offset ? offset : psi;
    return SWARP_OK;
}

/* [GMNPR] (2), psi */
SWARP_API swarp_status swarp_gmnpr_psi(double lambda, double theta, double phi, double n,
                                       double f, double* out_psi) {
    return sw_gmnpr_psi_or_offset(lambda, theta, phi, n, f, 0, out_psi);
}

/* [GMNPR] (2), varphi */
SWARP_API swarp_status swarp_gmnpr_offset(double lambda, double theta, double phi, double n,
                                          double f, double* out_offset) {
    return sw_gmnpr_psi_or_offset(lambda, theta, phi, n, f, 1, out_offset);
}

/* [GMNPR] (2), F = psi (z + varphi)^2 / z, evaluated by sw_gmnpr_F_value so
 * large lambda (psi ~ 1/lambda^2, varphi ~ lambda) and huge f, z neither
 * overflow nor underflow in between (the direct product underflows to 0 for
 * lambda ~ 1e274). */
SWARP_API swarp_status swarp_gmnpr_F(double lambda, double theta, double phi, double n,
                                     double f, double z, double* out_F) {
    if (!out_F) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(z)) return SWARP_ERR_NON_FINITE;
    swarp_status s = sw_gmnpr_args(lambda, theta, phi, n, f);
    if (s != SWARP_OK) return s;
    if (!(z >= n && z <= f)) return SWARP_ERR_OUT_OF_RANGE;
    /* F is homogeneous of degree 0 in (n, f, z): the same exact 4^-k
     * scaling as sw_normalise_nf, so subnormal depths keep their bits */
    {
        int e = ilogb(f);
        int k = (e - (e & 1)) / 2;
        double sc = ldexp(1.0, -k);
        double n_s = (n * sc) * sc, z_s = (z * sc) * sc;
        if (!(k > 0 && n_s < DBL_MIN)) {
            n = n_s;
            z = z_s;
            f = (f * sc) * sc;
        }
    }
    double F;
    if (!sw_gmnpr_F_value(lambda, theta, phi, n, f, z, &F)) return SWARP_ERR_OVERFLOW;
    *out_F = F;
    return SWARP_OK;
}

/* lambda_1 of [GMNPR] (4) with tan(phi)/tan(theta) (the print's tan(phi)/tan(phi)
 * is an extraction error, papers README), multiplied through by
 * u = tan(theta)/tan(phi) so it is finite for every theta in (0, pi/2]:
 *   lambda_1 = (u (n + sqrt(fn)) - n) / ((f - n) u + f + n). */
static double sw_lambda_1(double theta, double phi, double n, double f) {
    double sqrt_fn = sqrt(f) * sqrt(n);
    if (theta >= phi) { /* t form: bounded for theta -> pi/2 */
        double t = sw_t_ratio(theta, phi), two;
        double Dh = sw_case1_D_half(t, n, f, &two); /* D = two Dh: f near DBL_MAX */
        return ((n + sqrt_fn - n * t) / two) / Dh;
    }
    double u = sw_u_ratio(theta, phi);
    double den = (f - n) * u + (f + n);
    if (!sw_finite(den)) /* f near DBL_MAX: both halved */
        return (0.5 * (u * (n + sqrt_fn) - n)) / (0.5 * (f - n) * u + (0.5 * f + 0.5 * n));
    return (u * (n + sqrt_fn) - n) / den;
}

/* lambda_2 of [GMNPR] (4): (f + sqrt(fn))/(2f) tan(theta)/tan(phi) - 1/2,
 * with (f + sqrt(fn))/(2f) = (1 + r)/2, r = sqrt(n/f), written as
 *   ((1 - t) + r) / (2 t)   (theta >= phi)  and  ((u - 1) + u r) / 2:
 * 1 - t and u - 1 are exact near theta = phi (Sterbenz), where the direct
 * c/t - 1/2 loses r < 2^-53 entirely (lambda_2 = 0 for f = DBL_MAX). */
static double sw_lambda_2(double theta, double phi, double n, double f) {
    double r = sqrt(n) / sqrt(f);
    if (theta >= phi) {
        double t = sw_t_ratio(theta, phi);
        return ((0.5 - 0.5 * t) + 0.5 * r) / t; /* halved first: t ~ 1e-308 */
    }
    double u = sw_u_ratio(theta, phi);
    return (0.5 * u - 0.5) + 0.5 * u * r;
}

/* lambda_1, lambda_2, lambda_GMNPR, lambda_LiSPSM and lambda_GLPR are
 * homogeneous of degree 0 in (n, f): scaling both by 4^-k (exact) to put f in
 * [1, 4) changes nothing in exact arithmetic but keeps subnormal depths
 * (n = 4.9e-324, f = 3e-317: sqrt(f) sqrt(n) had ~6 bits) and huge ones at
 * full precision.  Skipped when it would push n into the subnormals. */
static void sw_normalise_nf(double* n, double* f) {
    int e = ilogb(*f);
    int k = (e - (e & 1)) / 2; /* floor(e / 2) */
    double s = ldexp(1.0, -k);
    double n_s = (*n * s) * s;
    if (k > 0 && n_s < DBL_MIN) return;
    *n = n_s;
    *f = (*f * s) * s;
}

/* [GMNPR] (4) */
SWARP_API swarp_status swarp_gmnpr_lambda12(double theta, double phi, double n, double f,
                                            double* out_lambda_1, double* out_lambda_2) {
    if (!out_lambda_1 || !out_lambda_2) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(theta)) return SWARP_ERR_NON_FINITE;
    swarp_status s = sw_gmnpr_frame(phi, n, f);
    if (s != SWARP_OK) return s;
    if (!(theta > 0.0 && theta <= SW_HALF_PI)) return SWARP_ERR_OUT_OF_RANGE;
    sw_normalise_nf(&n, &f);
    double l1 = sw_lambda_1(theta, phi, n, f);
    double l2 = sw_lambda_2(theta, phi, n, f);
    if (!sw_finite(l1) || !sw_finite(l2)) return SWARP_ERR_OVERFLOW;
    *out_lambda_1 = l1;
    *out_lambda_2 = l2;
    return SWARP_OK;
}

static swarp_status sw_theta_closed_check(double theta, double phi, double n, double f) {
    if (!sw_finite(theta)) return SWARP_ERR_NON_FINITE;
    swarp_status s = sw_gmnpr_frame(phi, n, f);
    if (s != SWARP_OK) return s;
    if (!sw_angle_closed(theta)) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* The checks shared by the lambda entry points, then (n, f) normalised by
 * sw_normalise_nf (lambda is homogeneous of degree 0 in them). */
static swarp_status sw_lambda_args(const double* out_lambda, double theta, double phi, double* n, double* f) {
    if (!out_lambda) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_theta_closed_check(theta, phi, *n, *f);
    if (s != SWARP_OK) return s;
    sw_normalise_nf(n, f);
    return SWARP_OK;
}

/* lambda_GMNPR without checks; theta in [0, pi/2]. */
static swarp_status sw_lambda_gmnpr(double theta, double phi, double n, double f, double* out) {
    if (theta == 0.0) {
        /* (6): converges to the standard (uniform) shadow map.  The contract of
         * lambda is "never Inf on [0, pi/2]" (the header), so theta = 0 writes the
         * largest finite double, which the error model and the warp treat as
         * uniform exactly like +INFINITY. */
        *out = DBL_MAX;
        return SWARP_INFO_WARP_UNIFORM;
    }
    if (theta >= phi) {
        *out = sw_lambda_1(theta, phi, n, f); /* [GMNPR] (8), first case = lambda_1 */
        return SWARP_OK;
    }
    /* [GMNPR] (7): lambda_2* = lambda_1(phi) / tan(theta pi / (4 phi)), lambda_1(phi) = sqrt(fn)/(2f) */
    double lambda_1_phi = 0.5 * sqrt(n) / sqrt(f);
    double lambda;
    if (theta < SW_TAN_LINEAR * (4.0 * phi / SWARP_PI)) {
        /* tan(x) = x (1 + x^2/3 + ...) = x to 1e-16 for x < 1e-8; as a ratio
         * of factors, since x itself is subnormal for theta ~ 1e-323 and
         * lambda ~ 1e-300 / theta overflows only when it does */
        const double num[3] = {lambda_1_phi, 4.0, phi}, den[2] = {SWARP_PI, theta};
        lambda = sw_ratio(num, 3, den, 2);
    } else {
        lambda = lambda_1_phi / tan(theta * SWARP_PI / (4.0 * phi));
    }
    return sw_put_warp(lambda, SWARP_INFO_GMNPR_ADJUSTED, out);
}

/* [GMNPR] (8) with (7) */
SWARP_API swarp_status swarp_gmnpr_lambda(double theta, double phi, double n, double f,
                                          double* out_lambda) {
    swarp_status s = sw_lambda_args(out_lambda, theta, phi, &n, &f);
    if (s != SWARP_OK) return s;
    return sw_lambda_gmnpr(theta, phi, n, f, out_lambda);
}

/* [GMNPR] (9): P_n = (n + sqrt(fn))/sin(theta) over the normalised depth P_f - P_n. */
SWARP_API swarp_status swarp_gmnpr_lambda_lispsm(double theta, double phi, double n, double f,
                                                 double* out_lambda) {
    swarp_status s = sw_lambda_args(out_lambda, theta, phi, &n, &f);
    if (s != SWARP_OK) return s;
    if (theta == 0.0) {
        *out_lambda = DBL_MAX; /* P_n = inf: duelling frusta; finite, like lambda_GMNPR */
        return SWARP_INFO_WARP_UNIFORM;
    }
    /* lambda = P_n / (P_f - P_n) with P_n = (n + sqrt(fn))/sin(theta) and
     * P_f - P_n = D sin(theta) (theta >= phi; (n t + f - n + f t) sin(theta))
     * or 2 f tan(phi) cos(theta), as one ratio of factors (sw_ratio): P_n
     * alone overflows for theta ~ 1e-308 and the depth for f ~ DBL_MAX while
     * lambda is representable.  The numerator n + sqrt(fn) <= 2f cannot
     * overflow: sw_normalise_nf brought f into [1, 4), or it left f huge
     * only for n < f 2^-1020, where sqrt(fn) < 2^-510 f. */
    const double num[1] = {n + sqrt(f) * sqrt(n)};
    double den[5];
    int n_den;
    if (theta >= phi) {
        double two;
        den[0] = sin(theta);
        den[1] = sin(theta);
        den[2] = sw_case1_D_half(sw_t_ratio(theta, phi), n, f, &two);
        den[3] = two;
        n_den = 4;
    } else {
        den[0] = sin(theta);
        den[1] = 2.0;
        den[2] = f;
        den[3] = tan(phi);
        den[4] = cos(theta);
        n_den = 5;
    }
    return sw_put_warp(sw_ratio(num, 1, den, n_den), SWARP_OK, out_lambda);
}

/* GLPR from [GMNPR] (2), derivation in docs/parameters.md:
 * F = psi (z + varphi)^2 / z = psi (z + 2 varphi + varphi^2 / z) is linear in z
 * exactly when varphi(lambda, theta) = 0.
 *  case 1: D lambda + n t - n = 0  =>  lambda = n (1 - t) / D, with
 *          1 - t = sin(theta - phi) / (sin(theta) cos(phi)) (no cancellation);
 *          positive iff theta > phi; = n/(f - n) (PSM) at theta = pi/2.
 *  case 2: f (2 lambda + 1) t - f = 0  =>  lambda = (u - 1)/2 <= 0: no positive
 *          solution for theta <= phi.  There lambda_GMNPR is written with
 *          SWARP_INFO_GLPR_NO_SOLUTION (theta = 0: +INFINITY, WARP_UNIFORM). */
SWARP_API swarp_status swarp_gmnpr_lambda_glpr(double theta, double phi, double n, double f,
                                               double* out_lambda) {
    swarp_status s = sw_lambda_args(out_lambda, theta, phi, &n, &f);
    if (s != SWARP_OK) return s;
    if (theta > phi) {
        double D = sw_case1_D(sw_t_ratio(theta, phi), n, f);
        double one_minus_t = sin(theta - phi) / (sin(theta) * cos(phi));
        double lambda = n * one_minus_t / D;
        if (lambda > 0.0 && sw_finite(lambda)) {
            *out_lambda = lambda;
            return SWARP_OK;
        }
        /* theta > phi: the positive solution exists (1 - t > 0, D > 0) but
         * lies below the smallest subnormal (n subnormal, f >> n, or theta
         * just above phi): the nearest positive double is DBL_TRUE_MIN */
        if (lambda == 0.0 && n > 0.0 && D > 0.0 && one_minus_t > 0.0) {
            *out_lambda = DBL_TRUE_MIN;
            return SWARP_OK;
        }
    }
    double fallback;
    s = sw_lambda_gmnpr(theta, phi, n, f, &fallback);
    *out_lambda = fallback;
    return s == SWARP_INFO_WARP_UNIFORM ? s : SWARP_INFO_GLPR_NO_SOLUTION;
}
