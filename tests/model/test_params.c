#define _POSIX_C_SOURCE 200809L
/* Core: closed-form warp parameters ([RHS] (3.2)-(3.5), (4.2); [GMNPR] (2), (4),
 * (7)-(9), GLPR).  Every closed form is checked against an independent
 * evaluation (the paper's formula written literally, numerical root finding,
 * geometry) and against the property that defines it. */
#include <float.h>
#include <stdlib.h>

#include "test_core.h"

/* ---- independent evaluations, written from the papers as printed -------- */

/* [RHS] (2.4) literally, without resolution factors. */
static double lit_mz(double n, double f, double z, double np) {
    return (np + z - n) * (np + z - n) / (z * np * (np + f - n));
}

/* [RHS] (3.2) literally. */
static double lit_nopt(double d, double z0, double z1) { return d / (sqrt(z1 / z0) - 1.0); }

/* [GMNPR] (2) literally, with tp = tan(phi)/tan(theta). */
static double lit_psi(double l, double th, double ph, double n, double f) {
    double tp = tan(ph) / tan(th);
    if (th >= ph) return 1.0 / tan(ph) / ((f - n + (f + n) * tp) * l * (l + 1.0));
    return 1.0 / tan(ph) / (2.0 * f * l * (l + 1.0) * tan(th) / tan(ph));
}
static double lit_off(double l, double th, double ph, double n, double f) {
    double tp = tan(ph) / tan(th);
    if (th >= ph) return (f - n + (f + n) * tp) * l + n * tp - n;
    return f * (2.0 * l + 1.0) * tp - f;
}
static double lit_F(double l, double th, double ph, double n, double f, double z) {
    double o = lit_off(l, th, ph, n, f);
    return lit_psi(l, th, ph, n, f) * (z + o) * (z + o) / z;
}

/* [GMNPR] (9) literally. */
static double lit_lambda_lispsm(double th, double ph, double n, double f) {
    double tp = tan(ph) / tan(th);
    double a = (n + sqrt(f * n)) / sin(th);
    if (th >= ph) return a / ((n * tp + f - n + f * tp) * sin(th));
    return a / (2.0 * f * tan(ph) * cos(th));
}

/* [RHS] (3.3) written in degrees, as printed. */
static double lit_eta_deg(double g, double T) {
    double ga = T / 3.0, gb = T, gc = T + 0.3 * (90.0 - T), eb = -0.2, ec = 0.0;
    if (g <= ga) return -1.0;
    if (g <= gb) return -1.0 + (eb + 1.0) * (g - ga) / (gb - ga);
    if (g <= gc) return eb + (ec - eb) * sin(90.0 * TC_DEG * (g - gb) / (gc - gb));
    return ec;
}

/* random frame: 0 < n < f, ratio f/n in [1.05, 1e4], phi in [5, 80] deg */
static void rand_frame(uint64_t* s, double* n, double* f, double* phi) {
    *n = tc_logu(s, 1e-2, 1e2);
    *f = *n * tc_logu(s, 1.05, 1e4);
    *phi = tc_uniform(s, 5.0, 80.0) * TC_DEG;
}

/* ---- [RHS] (3.2) ----------------------------------------------------------- */

START_TEST(nopt_equalises_mz_at_near_and_far_overhead) {
    uint64_t s = 0x5eed0001;
    swarp_error_config cfg = {0};
    cfg.theta = 30 * TC_DEG;
    cfg.res_ix = 1024, cfg.res_iy = 768, cfg.res_s = 1024, cfg.res_t = 1024;
    for (int k = 0; k < 500; ++k) {
        double n = tc_logu(&s, 1e-3, 1e3), f = n * tc_logu(&s, 1.01, 1e6);
        double n_opt = 0;
        /* overhead light: the warp frustum's depth d is the view depth f - n */
        ck_assert_int_eq(swarp_warp_nopt(f - n, n, f, &n_opt), SWARP_OK);
        ck_assert_rel(n_opt, lit_nopt(f - n, n, f), 1e-12);
        /* the defining property, literal (2.4) and the library's m_z */
        ck_assert_rel(lit_mz(n, f, n, n_opt), lit_mz(n, f, f, n_opt), 1e-12);
        cfg.z_near = n, cfg.z_far = f;
        double mz_n = 0, mz_f = 0;
        ck_assert_int_eq(swarp_error_mz(&cfg, n, n_opt, &mz_n), SWARP_OK);
        ck_assert_int_eq(swarp_error_mz(&cfg, f, n_opt, &mz_f), SWARP_OK);
        ck_assert_rel(mz_n, mz_f, 1e-12);
        /* numerical root of m_z(n) - m_z(f) by bisection on log n' */
        if (k % 10 == 0) {
            double lo = log(1e-12), hi = log(1e15);
            for (int it = 0; it < 200; ++it) {
                double mid = 0.5 * (lo + hi), np = exp(mid);
                if (lit_mz(n, f, n, np) < lit_mz(n, f, f, np))
                    lo = mid;
                else
                    hi = mid;
            }
            ck_assert_rel(n_opt, exp(0.5 * (lo + hi)), 1e-10);
        }
    }
}
END_TEST

START_TEST(nopt_equals_lambda_lispsm_at_right_angle) {
    uint64_t s = 0x5eed0002;
    for (int k = 0; k < 500; ++k) {
        double n, f, phi, n_opt = 0, lambda = 0;
        rand_frame(&s, &n, &f, &phi);
        ck_assert_int_eq(swarp_warp_nopt(f - n, n, f, &n_opt), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(TC_HALF_PI, phi, n, f, &lambda), SWARP_OK);
        /* [GMNPR] normalises the warp frustum's depth to 1: lambda = n_opt / d */
        ck_assert_rel(n_opt / (f - n), lambda, 1e-12);
        /* and LiSPSM's lambda at pi/2 is GMNPR's lambda_1 there (ideal case) */
        double l1 = 0, l2 = 0;
        ck_assert_int_eq(swarp_gmnpr_lambda12(TC_HALF_PI, phi, n, f, &l1, &l2), SWARP_OK);
        ck_assert_rel(l1, lambda, 1e-12);
    }
}
END_TEST

START_TEST(nopt_degenerate_and_bad_inputs) {
    double out = TC_SENTINEL;
    ck_assert_int_eq(swarp_warp_nopt(3.0, 2.0, 2.0, &out), SWARP_INFO_WARP_UNIFORM);
    ck_assert(isinf(out) && out > 0);
    /* z_1 one ulp above z_0: huge but finite, accurate (no cancellation) */
    double z1 = nextafter(2.0, 3.0);
    ck_assert_int_eq(swarp_warp_nopt(3.0, 2.0, z1, &out), SWARP_OK);
    ck_assert(isfinite(out));
    ck_assert_rel(out, 3.0 * (2.0 + sqrt(2.0 * z1)) / (z1 - 2.0), 1e-15);
    /* overflow is clamped to DBL_MAX and reported as uniform */
    ck_assert_int_eq(swarp_warp_nopt(1e300, 1.0, nextafter(1.0, 2.0), &out), SWARP_INFO_WARP_UNIFORM);
    ck_assert(out == DBL_MAX);

    const double bad[][3] = {{NAN, 1, 2}, {1, INFINITY, 2}, {1, 1, -INFINITY}};
    for (size_t i = 0; i < 3; ++i) {
        out = TC_SENTINEL;
        ck_assert_int_eq(swarp_warp_nopt(bad[i][0], bad[i][1], bad[i][2], &out), SWARP_ERR_NON_FINITE);
        ck_assert(out == TC_SENTINEL);
        ck_assert_int_eq(swarp_warp_nopt_pseudo(bad[i][0], bad[i][1], bad[i][2], 0, 0, &out),
                         SWARP_ERR_NON_FINITE);
        ck_assert(out == TC_SENTINEL);
    }
    const double range[][3] = {{0, 1, 2}, {-1, 1, 2}, {1, 0, 2}, {1, -1, 2}, {1, 2, 1.5}};
    for (size_t i = 0; i < 5; ++i) {
        ck_assert_int_eq(swarp_warp_nopt(range[i][0], range[i][1], range[i][2], &out),
                         SWARP_ERR_OUT_OF_RANGE);
        ck_assert(out == TC_SENTINEL);
    }
    ck_assert_int_eq(swarp_warp_nopt(1, 1, 2, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_warp_nopt_pseudo(1, 1, 2, 0, 0, NULL), SWARP_ERR_NULL_POINTER);
    /* pseudo planes outside [0, 1], or n_p + f_p >= 1, or NaN */
    const double np_fp[][2] = {{-0.1, 0}, {0, -0.1}, {1.1, 0}, {0.5, 0.5}, {0.7, 0.4}};
    for (size_t i = 0; i < 5; ++i) {
        ck_assert_int_eq(swarp_warp_nopt_pseudo(1, 1, 2, np_fp[i][0], np_fp[i][1], &out),
                         SWARP_ERR_OUT_OF_RANGE);
        ck_assert(out == TC_SENTINEL);
    }
    ck_assert_int_eq(swarp_warp_nopt_pseudo(1, 1, 2, NAN, 0, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_warp_nopt_pseudo(1, 1, 2, 0, INFINITY, &out), SWARP_ERR_NON_FINITE);
    ck_assert(out == TC_SENTINEL);
}
END_TEST

/* ---- [RHS] (4.2) ----------------------------------------------------------- */

START_TEST(nopt_pseudo_reduces_to_32_and_equalises_pseudo_planes) {
    uint64_t s = 0x5eed0003;
    for (int k = 0; k < 500; ++k) {
        double z0 = tc_logu(&s, 1e-2, 1e2), z1 = z0 * tc_logu(&s, 1.05, 1e4);
        double d = tc_logu(&s, 1e-3, 1e5);
        double a = 0, b = 0;
        ck_assert_int_eq(swarp_warp_nopt_pseudo(d, z0, z1, 0.0, 0.0, &a), SWARP_OK);
        ck_assert_rel(a, lit_nopt(d, z0, z1), 1e-12);
        ck_assert_int_eq(swarp_warp_nopt(d, z0, z1, &b), SWARP_OK);
        ck_assert_rel(a, b, 1e-15);
        /* overhead light (d = z1 - z0): n_opt equalises m_z at the pseudo planes */
        double n_p = tc_uniform(&s, 0.0, 0.6), f_p = tc_uniform(&s, 0.0, 0.99 - n_p);
        double zpn = z0 + n_p * (z1 - z0), zpf = z1 - f_p * (z1 - z0);
        ck_assert_int_eq(swarp_warp_nopt_pseudo(z1 - z0, z0, z1, n_p, f_p, &a), SWARP_OK);
        ck_assert_rel(lit_mz(z0, z1, zpn, a), lit_mz(z0, z1, zpf, a), 1e-11);
        /* linear in d */
        ck_assert_int_eq(swarp_warp_nopt_pseudo(2.0 * (z1 - z0), z0, z1, n_p, f_p, &b), SWARP_OK);
        ck_assert_rel(b, 2.0 * a, 1e-14);
    }
    double out = 0;
    ck_assert_int_eq(swarp_warp_nopt_pseudo(1, 5, 5, 0.2, 0.2, &out), SWARP_INFO_WARP_UNIFORM);
    ck_assert(isinf(out));
}
END_TEST

/* ---- [RHS] (3.3) ----------------------------------------------------------- */

START_TEST(eta_matches_paper_and_is_continuous) {
    const double thetas[] = {1, 10, 22.5, 30, 45, 60, 89};
    for (size_t i = 0; i < sizeof thetas / sizeof thetas[0]; ++i) {
        double T = thetas[i], prev = -2.0;
        int bad = 0; /* counted, asserted once: Check is slow per assertion */
        for (int k = 0; k <= 9000; ++k) {
            double g = 90.0 * k / 9000.0, eta = 0;
            bad += swarp_warp_eta(g * TC_DEG, T * TC_DEG, &eta) != SWARP_OK;
            bad += !(fabs(eta - lit_eta_deg(g, T)) <= 1e-12);
            bad += !(eta >= -1.0 && eta <= 0.0);
            bad += !(eta >= prev - 1e-15); /* non-decreasing in gamma */
            prev = eta;
        }
        ck_assert_int_eq(bad, 0);
        /* continuity at gamma_a, gamma_b, gamma_c (radians) */
        double t = T * TC_DEG;
        double br[3] = {t / 3.0, t, t + 0.3 * (TC_HALF_PI - t)};
        double at[3] = {-1.0, -0.2, 0.0};
        for (int j = 0; j < 3; ++j) {
            double lo = 0, hi = 0, mid = 0;
            ck_assert_int_eq(swarp_warp_eta(br[j] - 1e-9, t, &lo), SWARP_OK);
            ck_assert_int_eq(swarp_warp_eta(br[j] + 1e-9, t, &hi), SWARP_OK);
            ck_assert_int_eq(swarp_warp_eta(br[j], t, &mid), SWARP_OK);
            ck_assert_double_eq_tol(lo, hi, 1e-7);
            ck_assert_double_eq_tol(mid, at[j], 1e-12);
        }
    }
    double out = TC_SENTINEL;
    ck_assert_int_eq(swarp_warp_eta(-0.01, 0.5, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_eta(TC_HALF_PI + 1e-9, 0.5, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_eta(0.5, 0.0, &out), SWARP_ERR_FOV);
    ck_assert_int_eq(swarp_warp_eta(0.5, TC_HALF_PI, &out), SWARP_ERR_FOV);
    ck_assert_int_eq(swarp_warp_eta(NAN, 0.5, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_warp_eta(0.5, INFINITY, &out), SWARP_ERR_NON_FINITE);
    ck_assert(out == TC_SENTINEL);
    ck_assert_int_eq(swarp_warp_eta(0.5, 0.5, NULL), SWARP_ERR_NULL_POINTER);
}
END_TEST

/* ---- [RHS] (3.5) ----------------------------------------------------------- */

/* Extent along the light-space z axis of the 2D side view of the frustum:
 * eye at the origin looking along +x, corners (n, +-n tanT), (f, +-f tanT),
 * light direction at angle g to the view; project onto its normal. */
static double geom_extent(double g, double T, double n, double f) {
    double px = -sin(g), py = cos(g);
    double xs[4] = {n, n, f, f}, ys[4] = {n * tan(T), -n * tan(T), f * tan(T), -f * tan(T)};
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 4; ++i) {
        double v = xs[i] * px + ys[i] * py;
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
    }
    return hi - lo;
}

START_TEST(wlz_is_the_projected_frustum_width) {
    uint64_t s = 0x5eed0004;
    for (int k = 0; k < 500; ++k) {
        double n = tc_logu(&s, 1e-2, 1e2), f = n * tc_logu(&s, 1.05, 1e4);
        double T = tc_uniform(&s, 5, 80) * TC_DEG, W_e = 2.0 * n * tan(T), W = 0;
        /* overhead light: W_lz = f - n exactly as in the error model */
        ck_assert_int_eq(swarp_warp_wlz(TC_HALF_PI, T, n, f, W_e, &W), SWARP_OK);
        ck_assert_rel(W, f - n, 1e-12);
        /* gamma in [Theta, 90 deg]: (3.5) is the exact projected width */
        double g = tc_uniform(&s, T, TC_HALF_PI);
        ck_assert_int_eq(swarp_warp_wlz(g, T, n, f, W_e, &W), SWARP_OK);
        ck_assert_rel(W, geom_extent(g, T, n, f), 1e-11);
        /* gamma < Theta: with the printed W'_s1 = W_s (1 - cos(Theta - gamma)), (3.5)
         * falls short of the exact width 2 f tan(Theta) cos(gamma) by
         * (f-n)/cos(T) (sin(T-g) + cos(T-g) - 1) (docs/parameters.md) */
        g = tc_uniform(&s, 0.0, T);
        ck_assert_int_eq(swarp_warp_wlz(g, T, n, f, W_e, &W), SWARP_OK);
        double exact = geom_extent(g, T, n, f);
        ck_assert_rel(exact, 2.0 * f * tan(T) * cos(g), 1e-11);
        double excess = (f - n) / cos(T) * (sin(T - g) + cos(T - g) - 1.0);
        ck_assert_double_eq_tol(exact - W, excess, 1e-10 * f);
        /* continuity at gamma = Theta */
        double lo = 0, hi = 0;
        ck_assert_int_eq(swarp_warp_wlz(T - 1e-10, T, n, f, W_e, &lo), SWARP_OK);
        ck_assert_int_eq(swarp_warp_wlz(T + 1e-10, T, n, f, W_e, &hi), SWARP_OK);
        ck_assert_rel(lo, hi, 1e-8);
    }
    double out = TC_SENTINEL;
    ck_assert_int_eq(swarp_warp_wlz(0.5, 0.5, 0.0, 10, 1, &out), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_warp_wlz(0.5, 0.5, 2.0, 1.0, 1, &out), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_warp_wlz(0.5, 0.5, 1, 10, 0.0, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_wlz(-0.5, 0.5, 1, 10, 1, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_wlz(0.5, 1.6, 1, 10, 1, &out), SWARP_ERR_FOV);
    ck_assert_int_eq(swarp_warp_wlz(0.5, 0.5, 1, NAN, 1, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_warp_wlz(0.5, 0.5, 1, 1e308, 1e308, &out), SWARP_ERR_OVERFLOW);
    ck_assert(out == TC_SENTINEL);
    ck_assert_int_eq(swarp_warp_wlz(0.5, 0.5, 1, 10, 1, NULL), SWARP_ERR_NULL_POINTER);
}
END_TEST

/* ---- [RHS] (3.4) ----------------------------------------------------------- */

START_TEST(nrepar_at_minus_one_zero_one) {
    uint64_t s = 0x5eed0005;
    for (int k = 0; k < 500; ++k) {
        double n = tc_logu(&s, 1e-2, 1e2), f = n * tc_logu(&s, 1.05, 1e4);
        double alpha = f / n, W = tc_logu(&s, 1e-2, 1e4), out = 0, ref = 0;
        ck_assert_int_eq(swarp_warp_nrepar(-1.0, alpha, W, &out), SWARP_INFO_WARP_UNIFORM);
        ck_assert(isinf(out) && out > 0);
        /* eta = 0: n_opt of (3.2) with d = W_lz, z_0 = n_e, z_1 = f_e */
        ck_assert_int_eq(swarp_warp_nrepar(0.0, alpha, W, &out), SWARP_OK);
        ck_assert_int_eq(swarp_warp_nopt(W, n, f, &ref), SWARP_OK);
        ck_assert_rel(out, ref, 1e-12);
        ck_assert_rel(out, W / (sqrt(alpha) - 1.0), 1e-12);
        /* eta = 1: W_lz/(alpha - 1); overhead (W_lz = f - n) that is n_e: PSM */
        ck_assert_int_eq(swarp_warp_nrepar(1.0, alpha, W, &out), SWARP_OK);
        ck_assert_rel(out, W / (alpha - 1.0), 1e-12);
        ck_assert_int_eq(swarp_warp_nrepar(1.0, alpha, f - n, &out), SWARP_OK);
        ck_assert_rel(out, n, 1e-12);
        /* the two cases agree at eta = 0 and n_repar decreases with eta */
        double a = 0, b = 0, prev = INFINITY;
        ck_assert_int_eq(swarp_warp_nrepar(-1e-12, alpha, W, &a), SWARP_OK);
        ck_assert_int_eq(swarp_warp_nrepar(+1e-12, alpha, W, &b), SWARP_OK);
        ck_assert_rel(a, b, 1e-9);
        for (int j = -99; j <= 100; ++j) {
            ck_assert_int_eq(swarp_warp_nrepar(j / 100.0, alpha, W, &a), SWARP_OK);
            ck_assert(a < prev && a > 0.0);
            prev = a;
        }
        /* eta -> -1: grows without bound, like 1/(eta + 1) */
        double e = -1.0 + 1e-9;
        ck_assert_int_eq(swarp_warp_nrepar(e, alpha, W, &a), SWARP_OK);
        ck_assert_rel(a, W / (alpha - 1.0) * (1.0 + sqrt(alpha) - e * (alpha - 1.0)) / (e + 1.0), 1e-6);
    }
    double out = TC_SENTINEL;
    ck_assert_int_eq(swarp_warp_nrepar(-1.5, 4, 1, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_nrepar(1.5, 4, 1, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_nrepar(0, 1.0, 1, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_nrepar(0, 4, 0.0, &out), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_warp_nrepar(NAN, 4, 1, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_warp_nrepar(0, INFINITY, 1, &out), SWARP_ERR_NON_FINITE);
    ck_assert(out == TC_SENTINEL);
    ck_assert_int_eq(swarp_warp_nrepar(0, 4, 1, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_warp_nrepar(nextafter(-1.0, 0.0), 4, 1e300, &out), SWARP_INFO_WARP_UNIFORM);
    ck_assert(out == DBL_MAX);
}
END_TEST

/* ---- [GMNPR] (2) ----------------------------------------------------------- */

START_TEST(gmnpr_psi_offset_F_match_eq2) {
    uint64_t s = 0x5eed0006;
    for (int k = 0; k < 800; ++k) {
        double n, f, phi;
        rand_frame(&s, &n, &f, &phi);
        double th = tc_uniform(&s, 1e-3, TC_HALF_PI), l = tc_logu(&s, 1e-4, 1e4);
        double psi = 0, off = 0, F = 0, z = tc_uniform(&s, n, f);
        ck_assert_int_eq(swarp_gmnpr_psi(l, th, phi, n, f, &psi), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_offset(l, th, phi, n, f, &off), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_F(l, th, phi, n, f, z, &F), SWARP_OK);
        ck_assert_rel(psi, lit_psi(l, th, phi, n, f), 1e-12);
        ck_assert_double_eq_tol(off, lit_off(l, th, phi, n, f), 1e-11 * (fabs(off) + f));
        ck_assert_rel(F, lit_F(l, th, phi, n, f, z), 1e-10);
    }
    /* both cases of (2) agree at theta = phi: F is continuous there */
    for (int k = 0; k < 200; ++k) {
        double n, f, phi, a = 0, b = 0;
        rand_frame(&s, &n, &f, &phi);
        double l = tc_logu(&s, 1e-3, 1e3), z = tc_uniform(&s, n, f);
        ck_assert_int_eq(swarp_gmnpr_F(l, phi * (1 - 1e-12), phi, n, f, z, &a), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_F(l, phi * (1 + 1e-12), phi, n, f, z, &b), SWARP_OK);
        ck_assert_rel(a, b, 1e-9);
    }
}
END_TEST

START_TEST(gmnpr_bad_inputs_leave_outputs_untouched) {
    double o = TC_SENTINEL, o2 = TC_SENTINEL;
    typedef struct { double l, th, ph, n, f; swarp_status want; } row;
    const row rows[] = {
        {NAN, 1, 0.5, 1, 100, SWARP_ERR_NON_FINITE},   {1, INFINITY, 0.5, 1, 100, SWARP_ERR_NON_FINITE},
        {1, 1, NAN, 1, 100, SWARP_ERR_NON_FINITE},     {1, 1, 0.5, -INFINITY, 100, SWARP_ERR_NON_FINITE},
        {1, 1, 0.5, 0.0, 100, SWARP_ERR_NEAR_FAR},     {1, 1, 0.5, -1, 100, SWARP_ERR_NEAR_FAR},
        {1, 1, 0.5, 100, 100, SWARP_ERR_NEAR_FAR},     {1, 1, 0.0, 1, 100, SWARP_ERR_FOV},
        {1, 1, TC_HALF_PI, 1, 100, SWARP_ERR_FOV},     {1, 1, -0.5, 1, 100, SWARP_ERR_FOV},
        {1, 0.0, 0.5, 1, 100, SWARP_ERR_OUT_OF_RANGE}, {1, 1.6, 0.5, 1, 100, SWARP_ERR_OUT_OF_RANGE},
        {0.0, 1, 0.5, 1, 100, SWARP_ERR_OUT_OF_RANGE}, {-1, 1, 0.5, 1, 100, SWARP_ERR_OUT_OF_RANGE},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; ++i) {
        const row* r = &rows[i];
        ck_assert_int_eq(swarp_gmnpr_psi(r->l, r->th, r->ph, r->n, r->f, &o), r->want);
        ck_assert_int_eq(swarp_gmnpr_offset(r->l, r->th, r->ph, r->n, r->f, &o), r->want);
        ck_assert_int_eq(swarp_gmnpr_F(r->l, r->th, r->ph, r->n, r->f, 50.0, &o), r->want);
        ck_assert(o == TC_SENTINEL);
        if (r->l == 1) { /* the lambda functions take no lambda */
            swarp_status want = r->want;
            int theta_zero = (r->th == 0.0);
            if (!theta_zero) {
                ck_assert_int_eq(swarp_gmnpr_lambda12(r->th, r->ph, r->n, r->f, &o, &o2), want);
                ck_assert_int_eq(swarp_gmnpr_lambda(r->th, r->ph, r->n, r->f, &o), want);
                ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(r->th, r->ph, r->n, r->f, &o), want);
                ck_assert_int_eq(swarp_gmnpr_lambda_glpr(r->th, r->ph, r->n, r->f, &o), want);
            } else { /* theta = 0 is outside lambda12's domain only */
                ck_assert_int_eq(swarp_gmnpr_lambda12(r->th, r->ph, r->n, r->f, &o, &o2), want);
            }
            ck_assert(o == TC_SENTINEL && o2 == TC_SENTINEL);
        }
    }
    ck_assert_int_eq(swarp_gmnpr_lambda(-1e-9, 0.5, 1, 100, &o), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(NAN, 0.5, 1, 100, &o), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_gmnpr_F(1, 1, 0.5, 1, 100, 0.5, &o), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_gmnpr_F(1, 1, 0.5, 1, 100, 100.5, &o), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_gmnpr_F(1, 1, 0.5, 1, 100, NAN, &o), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_gmnpr_psi(1e-320, 1e-300, 0.5, 1, 100, &o), SWARP_ERR_OVERFLOW);
    ck_assert(o == TC_SENTINEL);
    ck_assert_int_eq(swarp_gmnpr_psi(1, 1, 0.5, 1, 100, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_gmnpr_offset(1, 1, 0.5, 1, 100, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_gmnpr_F(1, 1, 0.5, 1, 100, 50, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_gmnpr_lambda12(1, 0.5, 1, 100, &o, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_gmnpr_lambda(1, 0.5, 1, 100, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(1, 0.5, 1, 100, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(1, 0.5, 1, 100, NULL), SWARP_ERR_NULL_POINTER);
}
END_TEST

/* ---- [GMNPR] (4), (7), (8) ---------------------------------------------------- */

START_TEST(gmnpr_lambda_equalises_F_for_theta_at_least_phi) {
    uint64_t s = 0x5eed0007;
    for (int k = 0; k < 800; ++k) {
        double n, f, phi, l = 0;
        rand_frame(&s, &n, &f, &phi);
        /* sweep including both ends of [phi, pi/2] */
        double th = (k % 3 == 0) ? phi : (k % 3 == 1) ? TC_HALF_PI : tc_uniform(&s, phi, TC_HALF_PI);
        ck_assert_int_eq(swarp_gmnpr_lambda(th, phi, n, f, &l), SWARP_OK);
        ck_assert(l > 0 && isfinite(l));
        /* F(n) = F(f): library F and literal (2) */
        double Fn = 0, Ff = 0;
        ck_assert_int_eq(swarp_gmnpr_F(l, th, phi, n, f, n, &Fn), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_F(l, th, phi, n, f, f, &Ff), SWARP_OK);
        ck_assert_rel(Fn, Ff, 1e-10);
        ck_assert_rel(lit_F(l, th, phi, n, f, n), lit_F(l, th, phi, n, f, f), 1e-10);
        /* and it is the minimum-norm choice: F(n)/F(f) = 1 found by bisection */
        if (k % 10 == 0) {
            double lo = log(1e-12), hi = log(1e6);
            for (int it = 0; it < 200; ++it) {
                double mid = 0.5 * (lo + hi), lm = exp(mid);
                if (lit_F(lm, th, phi, n, f, n) < lit_F(lm, th, phi, n, f, f))
                    lo = mid; /* too small a lambda: warp too strong, far error dominates */
                else
                    hi = mid;
            }
            ck_assert_rel(l, exp(0.5 * (lo + hi)), 1e-9);
        }
        /* [GMNPR] (8): equals lambda_1 of [GMNPR] (4) */
        double l1 = 0, l2 = 0;
        ck_assert_int_eq(swarp_gmnpr_lambda12(th, phi, n, f, &l1, &l2), SWARP_OK);
        ck_assert_rel(l, l1, 1e-13);
    }
}
END_TEST

START_TEST(gmnpr_lambda_continuous_positive_and_unbounded_below_phi) {
    uint64_t s = 0x5eed0008;
    for (int k = 0; k < 300; ++k) {
        double n, f, phi, a = 0, b = 0, c = 0;
        rand_frame(&s, &n, &f, &phi);
        /* continuity at theta = phi: both sides -> lambda_1(phi) = sqrt(fn)/(2f) */
        ck_assert_int_eq(swarp_gmnpr_lambda(phi, phi, n, f, &c), SWARP_OK);
        ck_assert_rel(c, sqrt(f * n) / (2.0 * f), 1e-12);
        ck_assert_int_eq(swarp_gmnpr_lambda(phi * (1 - 1e-10), phi, n, f, &a), SWARP_INFO_GMNPR_ADJUSTED);
        ck_assert_int_eq(swarp_gmnpr_lambda(phi * (1 + 1e-10), phi, n, f, &b), SWARP_OK);
        ck_assert_rel(a, c, 1e-8);
        ck_assert_rel(b, c, 1e-8);
        /* [GMNPR] (7) literally */
        double th = tc_uniform(&s, 1e-6, phi), l = 0;
        ck_assert_int_eq(swarp_gmnpr_lambda(th, phi, n, f, &l), SWARP_INFO_GMNPR_ADJUSTED);
        ck_assert_rel(l, (sqrt(f * n) / (2.0 * f)) / tan(th / (4.0 * phi) * TC_PI), 1e-12);
        /* lambda_2 of (4) meets lambda_1 at phi, and lambda_2 -> -1/2 */
        double l1 = 0, l2 = 0;
        ck_assert_int_eq(swarp_gmnpr_lambda12(phi, phi, n, f, &l1, &l2), SWARP_OK);
        ck_assert_rel(l1, l2, 1e-12);
        ck_assert_int_eq(swarp_gmnpr_lambda12(th, phi, n, f, &l1, &l2), SWARP_OK);
        ck_assert_rel(l2, (f + sqrt(f * n)) / (2 * f) * tan(th) / tan(phi) - 0.5, 1e-10);
        ck_assert_rel(l1, (n + sqrt(f * n) - n * tan(phi) / tan(th)) /
                              (f - n + (f + n) * tan(phi) / tan(th)), 1e-9);
        /* positive, finite, non-increasing in theta on (0, phi], down to denormals */
        double prev = 0.0;
        int bad = 0;
        for (double t = phi; t > 0.0; t *= 0.5) {
            double v = -1;
            swarp_status st = swarp_gmnpr_lambda(t, phi, n, f, &v);
            bad += !(st == SWARP_OK || st == SWARP_INFO_GMNPR_ADJUSTED || st == SWARP_INFO_WARP_UNIFORM);
            bad += !(isfinite(v) && v > 0.0);
            bad += !(v >= prev);
            prev = v;
        }
        ck_assert_int_eq(bad, 0);
        /* grows without bound */
        ck_assert_int_eq(swarp_gmnpr_lambda(1e-200, phi, n, f, &l), SWARP_INFO_GMNPR_ADJUSTED);
        ck_assert(l > 1e190 * c);
    }
    double l = 0;
    /* theta = 0 (duelling frusta): uniform, but still finite (DBL_MAX) */
    ck_assert_int_eq(swarp_gmnpr_lambda(0.0, 0.5, 1, 100, &l), SWARP_INFO_WARP_UNIFORM);
    ck_assert(l == DBL_MAX);
    ck_assert_int_eq(swarp_gmnpr_lambda(4.9e-324, 1.5, 1e-6, 1e6, &l), SWARP_INFO_WARP_UNIFORM);
    ck_assert(l == DBL_MAX);
    /* never NaN, never Inf for theta in [0, pi/2] */
    int bad2 = 0;
    for (int k = 0; k <= 100000; ++k) {
        double th = TC_HALF_PI * k / 100000.0, v = -1;
        swarp_status st = swarp_gmnpr_lambda(th, TC_PI / 6, 1, 100, &v);
        bad2 += swarp_status_is_error(st) || !(isfinite(v) && v > 0);
    }
    ck_assert_int_eq(bad2, 0);
}
END_TEST

/* ---- [GMNPR] (9) ----------------------------------------------------------- */

START_TEST(gmnpr_lambda_lispsm_matches_eq9) {
    uint64_t s = 0x5eed0009;
    for (int k = 0; k < 500; ++k) {
        double n, f, phi, l = 0;
        rand_frame(&s, &n, &f, &phi);
        double th = tc_uniform(&s, 1e-4, TC_HALF_PI);
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(th, phi, n, f, &l), SWARP_OK);
        ck_assert_rel(l, lit_lambda_lispsm(th, phi, n, f), 1e-11);
        /* continuous at phi */
        double a = 0, b = 0;
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(phi * (1 - 1e-12), phi, n, f, &a), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(phi * (1 + 1e-12), phi, n, f, &b), SWARP_OK);
        ck_assert_rel(a, b, 1e-9);
        /* LiSPSM equalises F only in the ideal case theta = pi/2 */
        double Fn = 0, Ff = 0;
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(TC_HALF_PI, phi, n, f, &l), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_F(l, TC_HALF_PI, phi, n, f, n, &Fn), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_F(l, TC_HALF_PI, phi, n, f, f, &Ff), SWARP_OK);
        ck_assert_rel(Fn, Ff, 1e-10);
    }
    double l = 0;
    ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(0.0, 0.5, 1, 100, &l), SWARP_INFO_WARP_UNIFORM);
    ck_assert(l == DBL_MAX);
    ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(4.9e-324, 0.5, 1, 100, &l), SWARP_INFO_WARP_UNIFORM);
    ck_assert(l == DBL_MAX);
}
END_TEST

/* ---- GLPR ------------------------------------------------------------------ */

START_TEST(glpr_makes_F_linear_in_z) {
    uint64_t s = 0x5eed000a;
    for (int k = 0; k < 500; ++k) {
        double n, f, phi, l = 0;
        rand_frame(&s, &n, &f, &phi);
        double th = tc_uniform(&s, phi + 1e-3, TC_HALF_PI);
        ck_assert_int_eq(swarp_gmnpr_lambda_glpr(th, phi, n, f, &l), SWARP_OK);
        ck_assert(l > 0 && isfinite(l));
        /* F(z)/z is the same at every z: F is proportional to z */
        double F0 = 0;
        ck_assert_int_eq(swarp_gmnpr_F(l, th, phi, n, f, n, &F0), SWARP_OK);
        for (int j = 1; j <= 4; ++j) {
            double z = j == 4 ? f : n + (f - n) * j / 4.0, Fz = 0;
            ck_assert_int_eq(swarp_gmnpr_F(l, th, phi, n, f, z, &Fz), SWARP_OK);
            ck_assert_rel(Fz / z, F0 / n, 1e-9);
        }
        /* root of the literal offset by bisection (offset increases with lambda) */
        if (k % 10 == 0) {
            double lo = 0.0, hi = 10.0;
            for (int it = 0; it < 200; ++it) {
                double mid = 0.5 * (lo + hi);
                if (lit_off(mid, th, phi, n, f) < 0)
                    lo = mid;
                else
                    hi = mid;
            }
            ck_assert_double_eq_tol(l, 0.5 * (lo + hi), 1e-12 + 1e-9 * l);
        }
    }
    /* theta = pi/2: PSM, lambda = n/(f - n) */
    double l = 0, g = 0;
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(TC_HALF_PI, TC_PI / 6, 1, 100, &l), SWARP_OK);
    ck_assert_rel(l, 1.0 / 99.0, 1e-14);
    /* theta <= phi: no positive solution; lambda_GMNPR written instead */
    for (double th = TC_PI / 6; th > 1e-6; th *= 0.7) {
        ck_assert_int_eq(swarp_gmnpr_lambda_glpr(th, TC_PI / 6, 1, 100, &l), SWARP_INFO_GLPR_NO_SOLUTION);
        swarp_gmnpr_lambda(th, TC_PI / 6, 1, 100, &g);
        ck_assert(l == g);
        ck_assert(isfinite(l) && l > 0);
    }
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(0.0, TC_PI / 6, 1, 100, &l), SWARP_INFO_WARP_UNIFORM);
    ck_assert(l == DBL_MAX);
    /* just above phi: tiny but positive (strong warp) */
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(nextafter(TC_PI / 6, 1.0), TC_PI / 6, 1, 100, &l), SWARP_OK);
    ck_assert(l > 0 && l < 1e-15);
}
END_TEST

TCase* tcase_params(void) {
    TCase* tc = tcase_create("params");
    tcase_add_test(tc, nopt_equalises_mz_at_near_and_far_overhead);
    tcase_add_test(tc, nopt_equals_lambda_lispsm_at_right_angle);
    tcase_add_test(tc, nopt_degenerate_and_bad_inputs);
    tcase_add_test(tc, nopt_pseudo_reduces_to_32_and_equalises_pseudo_planes);
    tcase_add_test(tc, eta_matches_paper_and_is_continuous);
    tcase_add_test(tc, wlz_is_the_projected_frustum_width);
    tcase_add_test(tc, nrepar_at_minus_one_zero_one);
    tcase_add_test(tc, gmnpr_psi_offset_F_match_eq2);
    tcase_add_test(tc, gmnpr_bad_inputs_leave_outputs_untouched);
    tcase_add_test(tc, gmnpr_lambda_equalises_F_for_theta_at_least_phi);
    tcase_add_test(tc, gmnpr_lambda_continuous_positive_and_unbounded_below_phi);
    tcase_add_test(tc, gmnpr_lambda_lispsm_matches_eq9);
    tcase_add_test(tc, glpr_makes_F_linear_in_z);
    return tc;
}
