#define _POSIX_C_SOURCE 200809L
/* Edge cases of the model stage at the ends of the double range: the
 * condition test of swarp_mat4_invert and
 * the overflow/underflow-safe forms of n_opt, n_repar, psi and F at
 * magnitudes beyond 1e100.  References are evaluated independently in long
 * double (64-bit mantissa, 15-bit exponent: no intermediate overflow for
 * double inputs) from the papers' printed forms, not from the library's
 * rearranged ones. */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define SENTINEL (-7.25e33)

static double at(const swarp_mat4* m, int r, int c) { return m->m[c * 4 + r]; }
static void set(swarp_mat4* m, int r, int c, double v) { m->m[c * 4 + r] = v; }
static swarp_mat4 identity(void) {
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    for (int i = 0; i < 4; ++i) set(&m, i, i, 1.0);
    return m;
}

/* |A X - I| in long double, relative to |A| |X| (backward-style residual) */
static long double residual(const swarp_mat4* a, const swarp_mat4* x) {
    long double worst = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            long double s = 0, sa = 0;
            for (int k = 0; k < 4; ++k) {
                s += (long double)at(a, r, k) * at(x, k, c);
                sa += fabsl((long double)at(a, r, k) * at(x, k, c));
            }
            long double d = fabsl(s - (r == c)) / (sa > 0 ? sa : 1);
            if (d > worst) worst = d;
        }
    return worst;
}

/* [[1, 1], [1, 1 + delta]] in the upper-left block: kappa_inf ~ 4 / delta,
 * inverse 1/delta [[1 + delta, -1], [-1, 1]] (exact algebra) */
static swarp_mat4 near_singular(double delta) {
    swarp_mat4 m = identity();
    set(&m, 0, 1, 1.0);
    set(&m, 1, 0, 1.0);
    set(&m, 1, 1, 1.0 + delta);
    return m;
}

START_TEST(invert_refuses_numerically_singular) {
    /* kappa ~ 2^51 (> SWARP_MAT4_MAX_CONDITION = 2^47): the old 1e-300 pivot
     * test accepted it and returned an inverse with ~2 correct bits */
    swarp_mat4 a = near_singular(0x1p-49), r;
    tu_fill(r.m, 16, SENTINEL);
    ck_assert_int_eq(swarp_mat4_invert(&a, &r), SWARP_ERR_SINGULAR);
    ck_assert(tu_untouched(r.m, 16, SENTINEL));
    /* kappa ~ 2^42 < 2^47: accepted, inverse within kappa eps of the exact one */
    a = near_singular(0x1p-40);
    ck_assert_int_eq(swarp_mat4_invert(&a, &r), SWARP_OK);
    const double d = 0x1p-40, kappa = 4.0 / d;
    const double want[2][2] = {{(1 + d) / d, -1 / d}, {-1 / d, 1 / d}};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) ck_assert_double_le(tu_rel(at(&r, i, j), want[i][j]), 8 * kappa * DBL_EPSILON);
}
END_TEST

/* An exactly rank-deficient matrix (one column twice another) under every
 * rounding mode: the old test let directed rounding leave a pivot of a few
 * eps and "inverted" it. */
START_TEST(invert_rank_deficient_every_rounding_mode) {
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    uint64_t s = 0xED6E5C0DEull;
    int refused = 0, total = 0;
    for (int n = 0; n < 500; ++n) {
        swarp_mat4 a, r;
        for (int i = 0; i < 16; ++i) a.m[i] = tu_uniform(&s, -10, 10);
        int ca = (int)(tu_splitmix64(&s) % 4), cb = (ca + 1 + (int)(tu_splitmix64(&s) % 3)) % 4;
        for (int i = 0; i < 4; ++i) set(&a, i, cb, 2.0 * at(&a, i, ca) * (n % 2 ? 1.0 : 3.0 / 8.0));
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; ++m) {
            tu_fill(r.m, 16, SENTINEL);
            fesetround(modes[m]);
            swarp_status st = swarp_mat4_invert(&a, &r);
            fesetround(FE_TONEAREST);
            ++total;
            if (st == SWARP_ERR_SINGULAR && tu_untouched(r.m, 16, SENTINEL)) ++refused;
        }
    }
    ck_assert_int_eq(refused, total);
}
END_TEST

/* Badly scaled but well conditioned: rows and columns scaled by 1e+-30, a
 * translation by 1e6 with a near = 1e-6 projection.  kappa_inf unscaled is
 * up to 1e60; the equilibrated condition is small and the inverse accurate. */
START_TEST(invert_accepts_badly_scaled) {
    uint64_t s = 0x5CA1Eull;
    for (int n = 0; n < 300; ++n) {
        swarp_mat4 a = identity(), r;
        /* a well-conditioned core: I + small random part */
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) set(&a, i, j, at(&a, i, j) + tu_uniform(&s, -0.2, 0.2));
        double rs[4], cs[4];
        for (int i = 0; i < 4; ++i) {
            rs[i] = pow(10.0, tu_uniform(&s, -30, 30));
            cs[i] = pow(10.0, tu_uniform(&s, -30, 30));
        }
        swarp_mat4 core = a;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) set(&a, i, j, at(&a, i, j) * rs[i] * cs[j]);
        ck_assert_int_eq(swarp_mat4_invert(&a, &r), SWARP_OK);
        /* (R K C)^-1 = C^-1 K^-1 R^-1, K^-1 by Gauss-Jordan in long double */
        long double w[4][8], kmax = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 8; ++j) w[i][j] = j < 4 ? at(&core, i, j) : (j - 4 == i);
        for (int c = 0; c < 4; ++c) {
            int p = c;
            for (int i = c + 1; i < 4; ++i)
                if (fabsl(w[i][c]) > fabsl(w[p][c])) p = i;
            for (int j = 0; j < 8; ++j) {
                long double tmp = w[c][j];
                w[c][j] = w[p][j];
                w[p][j] = tmp;
            }
            for (int j = 7; j >= c; --j) w[c][j] /= w[c][c];
            for (int i = 0; i < 4; ++i)
                if (i != c)
                    for (int j = 7; j >= c; --j) w[i][j] -= w[i][c] * w[c][j];
        }
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) kmax = fmaxl(kmax, fabsl(w[i][j + 4]));
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                long double got = (long double)at(&r, i, j) * cs[i] * rs[j];
                ck_assert_msg(fabsl(got - w[i][j + 4]) <= 1e-10L * kmax, "inverse[%d][%d]", i, j);
            }
    }
    /* translation by (1e6, -3e6, 1e5) times a projection with near 1e-6, far 1e7 */
    const double n = 1e-6, f = 1e7;
    swarp_mat4 P, T = identity(), PT, r;
    memset(&P, 0, sizeof P);
    set(&P, 0, 0, 1.2);
    set(&P, 1, 1, 1.7);
    set(&P, 2, 2, -(f + n) / (f - n));
    set(&P, 2, 3, -2 * f * n / (f - n));
    set(&P, 3, 2, -1.0);
    set(&T, 0, 3, 1e6);
    set(&T, 1, 3, -3e6);
    set(&T, 2, 3, 1e5);
    ck_assert_int_eq(swarp_mat4_mul(&P, &T, &PT), SWARP_OK);
    ck_assert_int_eq(swarp_mat4_invert(&PT, &r), SWARP_OK);
    ck_assert(residual(&PT, &r) < 1e-12L);
    /* diag(FLT_MAX, 1, 1, 1/FLT_MAX): exact inverse */
    swarp_mat4 d = identity();
    set(&d, 0, 0, FLT_MAX);
    set(&d, 3, 3, 1.0 / FLT_MAX);
    ck_assert_int_eq(swarp_mat4_invert(&d, &r), SWARP_OK);
    ck_assert(at(&r, 0, 0) == 1.0 / FLT_MAX && at(&r, 3, 3) == 1.0 / (1.0 / FLT_MAX));
}
END_TEST

/* The references below use long double for its wider exponent range and
 * precision (x86: 64-bit mantissa, 15-bit exponent).  Under valgrind the
 * x87 unit is emulated with doubles, so a reference such as
 * d*sqrt(z_0)*(sqrt(z_1)+sqrt(z_0)) underflows and the comparison would
 * blame the library; those tests check at run time that long double really
 * is wider and skip (saying so) when it is not.  The -Werror and
 * ASan+UBSan runs do the checks. */
/* long_double_is_wide() and REQUIRE_WIDE_LONG_DOUBLE(): test_util.h */

/* [RHS] (3.2) in long double: d / (sqrt(z_1/z_0) - 1) = d sqrt(z_0) / (sqrt(z_1) - sqrt(z_0)) */
static long double ref_nopt(double d, double z0, double z1) {
    long double s0 = sqrtl(z0), s1 = sqrtl(z1);
    return (long double)d * s0 * (s1 + s0) / ((long double)z1 - z0);
}

START_TEST(nopt_subnormal_and_huge_depths) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double cases[][3] = {
        {0.19323405592958692, 4.9406564584124654e-324, 4.9406564584124654e-317}, /* the literal form: DBL_MAX */
        {9999.9999999999982, 2.2250738585072009e-308, 2.2250738585072014e-308},  /* the literal form: DBL_MAX */
        {1e-300, 4.0492795740303305e+171, 3.4123093990295732e+178},               /* the literal form: 0 */
        {3.0, 1e300, 1.7e308},
        {2.5, 1e-310, 3e-300},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        double out = SENTINEL;
        ck_assert_int_eq(swarp_warp_nopt(cases[i][0], cases[i][1], cases[i][2], &out), SWARP_OK);
        long double ref = ref_nopt(cases[i][0], cases[i][1], cases[i][2]);
        ck_assert_msg(fabsl(out - ref) <= 1e-14L * ref, "case %zu: %.17g vs %.17Lg", i, out, ref);
        /* (4.2) at n_p = f_p = 0 is (3.2) */
        double pseudo = SENTINEL;
        ck_assert_int_eq(swarp_warp_nopt_pseudo(cases[i][0], cases[i][1], cases[i][2], 0.0, 0.0, &pseudo), SWARP_OK);
        ck_assert(pseudo == out);
    }
    /* degree-0 homogeneity in the depths: scaling z_0, z_1 by 4^j changes
     * nothing (exactly, as long as z_0 4^j stays normal) */
    uint64_t s = 0x40B7ull;
    for (int n = 0; n < 2000; ++n) {
        double d = tu_uniform(&s, 0.1, 100), z0 = tu_uniform(&s, 0.5, 2), z1 = z0 * tu_uniform(&s, 1.0, 1e4);
        int k = 2 * ((int)(tu_splitmix64(&s) % 800) - 400);
        if (z0 * ldexp(1.0, k) < DBL_MIN || !isfinite(z1 * ldexp(1.0, k))) continue;
        double a, b;
        ck_assert_int_eq(swarp_warp_nopt(d, z0, z1, &a), SWARP_OK);
        ck_assert_int_eq(swarp_warp_nopt(d, ldexp(z0, k), ldexp(z1, k), &b), SWARP_OK);
        ck_assert_msg(a == b, "n_opt(%g, %g, %g) = %.17g but scaled by 2^%d: %.17g", d, z0, z1, a, k, b);
    }
}
END_TEST

/* [RHS] (3.4) as printed (second case eta sqrt(alpha) + 1), long double */
static long double ref_nrepar(double eta, double alpha, double W) {
    long double al = alpha, sa = sqrtl(al);
    if (eta < 0) return W / (al - 1) * (1 + sa - eta * (al - 1)) / (eta + 1);
    return W / (al - 1) * (1 + sa) / (eta * sa + 1);
}

START_TEST(nrepar_extreme_alpha) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double cases[][3] = {
        {-0.14846982218324345, 1.7976931348623157e+308, 1.0000000000000002e-06}, /* W/(alpha-1) is subnormal */
        {-0.35601037187359519, 1.7976931348623157e+308, 1.5948425457844012e-06},
        {-1.0 + 0x1p-52, 1e300, 1.0},                                             /* eta (alpha - 1) overflows */
        {-1.0850344206875686e-63, 1.5388407449206508e+185, 1.5336797372969295e-232}, /* the literal form: 0 */
        {0.5, 1.7976931348623157e+308, 3.0},
        {0.0, 1.0 + 0x1p-52, 1e-3},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        double out = SENTINEL;
        ck_assert_int_eq(swarp_warp_nrepar(cases[i][0], cases[i][1], cases[i][2], &out), SWARP_OK);
        long double ref = ref_nrepar(cases[i][0], cases[i][1], cases[i][2]);
        ck_assert_msg(fabsl(out - ref) <= 1e-14L * ref, "case %zu: %.17g vs %.17Lg", i, out, ref);
    }
    /* a value that really exceeds DBL_MAX: DBL_MAX with INFO_WARP_UNIFORM */
    double out;
    ck_assert_int_eq(swarp_warp_nrepar(-1.0 + 0x1p-53, 1.0 + 0x1p-52, 1e280, &out), SWARP_INFO_WARP_UNIFORM);
    ck_assert(out == DBL_MAX);
}
END_TEST

/* [GMNPR] (2) in long double, as printed: t = tan(phi)/tan(theta),
 * psi = 1/(tan(phi) (f - n + (f + n) t) lambda (lambda + 1)) for theta >= phi,
 * 1/(tan(phi) 2 f lambda (lambda + 1) tan(theta)/tan(phi)) otherwise;
 * varphi = (f - n + (f + n) t) lambda + n t - n, or f (2 lambda + 1) t - f;
 * F = psi (z + varphi)^2 / z. */
static long double ref_F(double l_, double th_, double ph_, double n_, double f_, double z_, long double* psi) {
    long double l = l_, th = th_, ph = ph_, n = n_, f = f_, z = z_, t = tanl(ph) / tanl(th), p, o;
    if (th >= ph) {
        p = 1.0L / tanl(ph) / ((f - n + (f + n) * t) * l * (l + 1));
        o = (f - n + (f + n) * t) * l + n * t - n;
    } else {
        p = 1.0L / tanl(ph) / (2 * f * l * (l + 1) * tanl(th) / tanl(ph));
        o = f * (2 * l + 1) * t - f;
    }
    if (psi) *psi = p;
    return p * (z + o) * (z + o) / z;
}

START_TEST(gmnpr_F_and_psi_huge_lambda) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double cases[][6] = {
        /* lambda, theta, phi, n, f, z: the product form of F underflows to 0 */
        {1.6077200186449224e+274, 1.4568674924698055, 1.5607963267948963, 1.0000000000000002, 6044747.6222206205,
         35.312656685534016},
        {1.9580203865100371e+223, 0.85431485665607443, 1.3879348321975787e-196, 502.26804758778741,
         617575060.54135489, 148908274.44003168},
        {1.0000000000000001e-09, 1.5707953267948969, 1.5707953267948969, 9.9999999999999974e-07,
         1.7976931348623151e+302, 6.336943674283251e+301},
        {2.9785264772904756e+216, 0.30288778479810863, 0.30288778479810863, 0.34454779585818335, 3445477.9585818336,
         793889.72832924419},
        {1e200, 0.2, 0.6, 1.0, 100.0, 50.0}, /* case 2 (theta < phi) */
        {1e-200, 0.2, 0.6, 1.0, 100.0, 50.0},
        {3.0, 0.9, 0.5, 1e-3, 1.7e308, 1e308}, /* D = f - n + (f + n) t overflows */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const double* a = cases[i];
        long double psi_ref;
        long double ref = ref_F(a[0], a[1], a[2], a[3], a[4], a[5], &psi_ref);
        double F = SENTINEL, psi = SENTINEL;
        ck_assert_int_eq(swarp_gmnpr_F(a[0], a[1], a[2], a[3], a[4], a[5], &F), SWARP_OK);
        /* the sum z + varphi and the tangents carry a few ulps each */
        ck_assert_msg(fabsl(F - ref) <= 1e-12L * ref, "case %zu: F = %.17g vs %.17Lg", i, F, ref);
        ck_assert_int_eq(swarp_gmnpr_psi(a[0], a[1], a[2], a[3], a[4], &psi), SWARP_OK);
        if (psi_ref >= DBL_MIN)
            ck_assert_msg(fabsl(psi - psi_ref) <= 1e-12L * psi_ref, "case %zu: psi = %.17g vs %.17Lg", i, psi,
                          psi_ref);
        else /* below the normal range: the correctly rounded subnormal, within its spacing */
            ck_assert(fabsl(psi - psi_ref) <= 0x1p-1074L + 1e-12L * psi_ref);
    }
    /* psi does not depend on the offset being representable: lambda = 1e300 */
    double psi = SENTINEL, off = SENTINEL;
    ck_assert_int_eq(swarp_gmnpr_psi(1e300, 0.9, 0.5, 1.0, 1e9, &psi), SWARP_OK);
    ck_assert_int_eq(swarp_gmnpr_offset(1e300, 0.9, 0.5, 1.0, 1e9, &off), SWARP_ERR_OVERFLOW);
    ck_assert(off == SENTINEL);
    long double psi_ref;
    ref_F(1e300, 0.9, 0.5, 1.0, 1e9, 1.0, &psi_ref);
    ck_assert(fabsl(psi - psi_ref) <= 0x1p-1074L + 1e-12L * psi_ref);
}
END_TEST

/* Ordinary inputs: the rearranged F still is psi (z + varphi)^2 / z of the
 * three entry points (a random sweep over both cases of (2)). */
START_TEST(gmnpr_F_matches_psi_offset) {
    uint64_t s = 0xF00Dull;
    for (int k = 0; k < 3000; ++k) {
        double lambda = pow(10.0, tu_uniform(&s, -6, 6)), theta = tu_uniform(&s, 0.01, 1.5707963267948966);
        double phi = tu_uniform(&s, 0.05, 1.5), n = tu_uniform(&s, 0.01, 10), f = n * tu_uniform(&s, 1.5, 1e5);
        double z = tu_uniform(&s, n, f);
        double F, psi, off;
        ck_assert_int_eq(swarp_gmnpr_F(lambda, theta, phi, n, f, z, &F), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_psi(lambda, theta, phi, n, f, &psi), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_offset(lambda, theta, phi, n, f, &off), SWARP_OK);
        long double via = (long double)psi * ((long double)z + off) * ((long double)z + off) / z;
        long double ref = ref_F(lambda, theta, phi, n, f, z, NULL);
        ck_assert_msg(fabsl(F - ref) <= 1e-11L * ref, "F = %.17g vs %.17Lg", F, ref);
        ck_assert(fabsl(F - via) <= 1e-11L * via);
    }
}
END_TEST

/* [RHS] (3.3) at subnormal angles: eta(theta, theta) = -0.2 (to rounding) as
 * for any theta (the linear piece ends at -0.2 at gamma_b = theta); the old
 * order of operations gave 0 for theta = 4.9e-324. */
START_TEST(eta_subnormal_angles) {
    for (int k = 1; k < 2000; k += 7) {
        const double th = k * 4.9406564584124654e-324;
        double eta = 5.0;
        ck_assert_int_eq(swarp_warp_eta(th, th, &eta), SWARP_OK);
        ck_assert_msg(fabs(eta + 0.2) <= 4 * DBL_EPSILON, "theta = %g: eta %.17g", th, eta);
        ck_assert_int_eq(swarp_warp_eta(0.0, th, &eta), SWARP_OK);
        ck_assert(eta == -1.0);
    }
}
END_TEST

/* [GMNPR] (4), (7)-(9) in long double as printed (t = tan(phi)/tan(theta)):
 * lambda_1 = (n + sqrt(fn) - n t)/(f - n + (f + n) t) for theta >= phi,
 * lambda_1 = (u (n + sqrt(fn)) - n)/((f - n) u + f + n) otherwise (u = 1/t);
 * lambda_2* = sqrt(fn)/(2f) / tan(theta pi / (4 phi));
 * lambda_LiSPSM = ((n + sqrt(fn))/sin(theta)) / (P_f - P_n). */
static long double ref_lambda_1(long double th, long double ph, long double n, long double f) {
    long double t = tanl(ph) / tanl(th), r = sqrtl(f * n);
    if (th >= ph) return (n + r - n * t) / (f - n + (f + n) * t);
    return ((n + r) / t - n) / ((f - n) / t + f + n);
}
static long double ref_lispsm(long double th, long double ph, long double n, long double f) {
    long double Pn = (n + sqrtl(f * n)) / sinl(th), t = tanl(ph) / tanl(th);
    long double depth = th >= ph ? (f - n + (f + n) * t) * sinl(th) : 2 * f * tanl(ph) * cosl(th);
    return Pn / depth;
}

START_TEST(gmnpr_lambdas_extreme_depths) {
    REQUIRE_WIDE_LONG_DOUBLE();
    /* theta, phi, n, f: subnormal depths, f near DBL_MAX, theta ~ DBL_MIN */
    const double cases[][4] = {
        {1.4779317867858497, 0.50534738244393917, 4.9406564584124654e-324, 4.2141857912270174e-317},
        {0.80206375646367467, 0.52359877559829893, 4.9406564584124654e-324, 3.1805446307091496e-317},
        {0.035267093095253228, 0.035267093095253228, 4.9406564584124654e-324, 5.6406338434709683e-318},
        {0.5235987755982987, 0.5235987755982987, 0.99999999900000003, 1.7976931330646226e+308},
        {1.0496482061068264, 0.0099999999999999985, 0.99999999999999989, 1.7976931348623155e+308},
        {2.2250738585072009e-308, 1.2492253675820186, 168.9258917337595, 22425.738223714543},
        {0.3, 0.6, 1.0, 1.7e308},
        {0.3, 0.6, 0.5, 1.79e308},  /* n/f below 2^-1020, not normalised: (f - n) u + f + n overflows */
        {1.2, 0.6, 0.5, 1.79e308},  /* likewise D = f - n + (f + n) t */
        {1.0, 0.5, 1e308, 1.7e308}, /* n + sqrt(f n) would overflow without the normalisation */
        {0.2, 0.7, 1e308, 1.7e308},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const double* a = cases[i];
        double l1, l2, lg, ll;
        ck_assert_int_eq(swarp_gmnpr_lambda12(a[0], a[1], a[2], a[3], &l1, &l2), SWARP_OK);
        long double r1 = ref_lambda_1(a[0], a[1], a[2], a[3]);
        ck_assert_msg(fabsl(l1 - r1) <= 1e-12L * fabsl(r1), "case %zu: lambda_1 %.17g vs %.17Lg", i, l1, r1);
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(a[0], a[1], a[2], a[3], &ll), SWARP_OK);
        long double rl = ref_lispsm(a[0], a[1], a[2], a[3]);
        ck_assert_msg(fabsl(ll - rl) <= 1e-12L * rl, "case %zu: lambda_LiSPSM %.17g vs %.17Lg", i, ll, rl);
        swarp_status st = swarp_gmnpr_lambda(a[0], a[1], a[2], a[3], &lg);
        ck_assert(st == SWARP_OK || st == SWARP_INFO_GMNPR_ADJUSTED);
        if (a[0] >= a[1]) ck_assert(lg == l1); /* (8), first case */
    }
    /* (7) at a subnormal theta: lambda_1(phi) / tan(theta pi / (4 phi)) */
    const double th = 4.9406564584124654e-324, ph = 1.1877003556401658e-108, n = 200.99237085786692,
                 f = 2769.682718713424;
    double lg;
    ck_assert_int_eq(swarp_gmnpr_lambda(th, ph, n, f, &lg), SWARP_INFO_GMNPR_ADJUSTED);
    long double ref = sqrtl((long double)f * n) / (2.0L * f) / tanl((long double)th * 3.14159265358979323846L / (4.0L * ph));
    ck_assert_msg(fabsl(lg - ref) <= 1e-13L * ref, "lambda_GMNPR %.17g vs %.17Lg", lg, ref);
}
END_TEST

/* theta > phi with n subnormal and f >> n: the GLPR solution n (1 - t)/D
 * (about 6e-333 here) exists but is below DBL_TRUE_MIN -> DBL_TRUE_MIN with
 * SWARP_OK, not the lambda_GMNPR fallback with SWARP_INFO_GLPR_NO_SOLUTION
 * (which would say there is no solution). */
START_TEST(glpr_lambda_below_true_min) {
    double lam = -1;
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(0.14180588291489093, 1.000001e-06, DBL_TRUE_MIN, 783214767.65697455, &lam),
                     SWARP_OK);
    ck_assert(lam == DBL_TRUE_MIN);
    /* representable: unchanged, the closed form n (1 - t)/(f - n + (f + n) t) */
    double th = 0.9, ph = 0.3, n = 1.0, f = 100.0, t = tan(ph) / tan(th);
    ck_assert_int_eq(swarp_gmnpr_lambda_glpr(th, ph, n, f, &lam), SWARP_OK);
    ck_assert(fabs(lam - n * (1 - t) / (f - n + (f + n) * t)) <= 1e-14 * lam);
}
END_TEST

/* A subnormal or tiny near plane with an ordinary far one: f/n overflows
 * double (Inf, then 0 * Inf = NaN, if formed) though every split is
 * representable, so no scheme may return SWARP_ERR_DEGENERATE. */
START_TEST(split_schemes_huge_ratio) {
    double out[5];
    size_t cnt = 0;
    ck_assert_int_eq(swarp_split_uniform(DBL_MIN, 1e9, 4, out, 5, &cnt), SWARP_OK);
    ck_assert(cnt == 5 && out[2] == 0.5e9);
    const double n = DBL_TRUE_MIN, f = 6e8;
    ck_assert_int_eq(swarp_split_log(n, f, 4, out, 5, &cnt), SWARP_OK);
    for (int i = 1; i < 4; ++i) {
        long double ref = (long double)n * powl((long double)f / n, i / 4.0L); /* (f/n) fits long double */
        ck_assert(fabsl(out[i] - ref) <= 1e-12L * ref);
    }
    ck_assert_int_eq(swarp_split_practical(n, f, 0.5, 4, out, 5, &cnt), SWARP_OK);
    for (int i = 1; i < 4; ++i) {
        long double ref = 0.5L * n * powl((long double)f / n, i / 4.0L) + 0.5L * (n + (f - (long double)n) * i / 4.0L);
        ck_assert(fabsl(out[i] - ref) <= 1e-12L * ref);
    }
}
END_TEST

/* res_iy/res_t below DBL_TRUE_MIN/2 while m_z itself is representable
 * (~1e-317): the product is kept as mantissa * 2^e, not flushed to 0. */
START_TEST(error_tiny_resolution_no_spurious_underflow) {
    REQUIRE_WIDE_LONG_DOUBLE();
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = 10.0;
    cfg.z_far = 1e8 + 10.0;
    cfg.theta = 0.5;
    cfg.res_ix = 1e-320;
    cfg.res_iy = 1e-320;
    cfg.res_s = 1e4;
    cfg.res_t = 1e4;
    double mz = -1, mx = -1;
    ck_assert_int_eq(swarp_error_mz(&cfg, cfg.z_far, cfg.z_near, &mz), SWARP_OK);
    /* (2.6) at z = f, n' = n: k_z (n' + f - n)^2/(f n' (n' + f - n)) = k_z / n */
    long double kz = (long double)cfg.res_iy / 1e4L * ((long double)cfg.z_far - 10.0L) / (2.0L * tanl(0.5L));
    long double ref = kz / 10.0L;
    ck_assert(mz > 0 && fabsl(mz - ref) <= 1e-12L * ref + DBL_TRUE_MIN);
    /* (2.5) at z = n: res_ix/res_s f/n (n + 0)/(n + f - n) = res_ix/res_s ~ 5e-324 -> rounds to
     * DBL_TRUE_MIN; with res_s = 1e4 (1e-324 < DBL_TRUE_MIN/2) it is 0 */
    cfg.res_s = 2e3;
    ck_assert_int_eq(swarp_error_mx(&cfg, cfg.z_near, cfg.z_near, &mx), SWARP_OK);
    ck_assert(mx == DBL_TRUE_MIN);
    cfg.res_s = 1e4;
    ck_assert_int_eq(swarp_error_mx(&cfg, cfg.z_near, cfg.z_near, &mx), SWARP_OK);
    ck_assert(mx == 0.0);
}
END_TEST

/* ---- closed forms whose literal evaluation over- or underflows ---------- */

/* theta == phi with f = DBL_MAX: the rounded tan/cos/sin can give
 * t = 1 + 2^-52, where halving the depth overflows and lambda_1 collapses to
 * 0, and lambda_2 = r/2 with r = sqrt(n/f) < 2^-53 is lost to c - 1/2 unless
 * formed directly.  At t = 1 both are sqrt(n/f)/2 exactly, the reference. */
START_TEST(gmnpr_lambda_theta_eq_phi_huge_far) {
    const double cases[][2] = {{0.01, 1.7023779630233584e-05},
                               {0.50344839343569725, 0.00069428559076514925},
                               {1.1596109125728185, 1.0000000000000002e-06},
                               {1.5414340003159084, 1.1341023648905051e-05}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        double th = cases[i][0], n = cases[i][1], f = DBL_MAX;
        long double ref = 0.5L * sqrtl((long double)n) / sqrtl((long double)f);
        double l1 = SENTINEL, l2 = SENTINEL, l = SENTINEL, ll = SENTINEL;
        ck_assert_int_eq(swarp_gmnpr_lambda12(th, th, n, f, &l1, &l2), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_lambda(th, th, n, f, &l), SWARP_OK);
        ck_assert_int_eq(swarp_gmnpr_lambda_lispsm(th, th, n, f, &ll), SWARP_OK);
        ck_assert_msg(fabsl(l1 - ref) <= 1e-14L * ref, "lambda_1 %g vs %Lg", l1, ref);
        ck_assert_msg(fabsl(l2 - ref) <= 1e-14L * ref, "lambda_2 %g vs %Lg", l2, ref);
        ck_assert_msg(fabsl(l - ref) <= 1e-14L * ref, "lambda %g vs %Lg", l, ref);
        ck_assert_msg(ll > 0.0 && ll < 1e-100, "lambda_LiSPSM %g", ll);
    }
}
END_TEST

/* psi and varphi of [GMNPR] (2) at subnormal depths: D = f - n + (f + n) t
 * formed from subnormals keeps only a few bits, so psi (degree -1) and
 * varphi (degree 1) must be evaluated on depths scaled into [1, 4) (exact
 * power-of-two scaling, undone by their degree).  Case 1 of (2), reference
 * in long double, where the depths are normal. */
static long double ref_case1_D(double theta, double phi, double n, double f, long double* t) {
    *t = tanl(phi) / tanl(theta);
    return ((long double)f - n) + ((long double)f + n) * *t;
}
START_TEST(gmnpr_psi_offset_subnormal_depths) {
    REQUIRE_WIDE_LONG_DOUBLE();
    {
        double lambda = 999999999.99899995, th = 1.3007923168931095, ph = 0.15899265989773426;
        double n = 4.9406564584124654e-324, f = 8.3991159793011913e-323, psi = SENTINEL;
        long double t, D = ref_case1_D(th, ph, n, f, &t);
        long double ref = 1.0L / (tanl(ph) * D * lambda * ((long double)lambda + 1.0L));
        ck_assert_int_eq(swarp_gmnpr_psi(lambda, th, ph, n, f, &psi), SWARP_OK);
        ck_assert_msg(fabsl(psi - ref) <= 1e-13L * ref, "psi %g vs %Lg", psi, ref);
    }
    {
        double lambda = 1.9467611181654738e+105, th = 1.1257702121125834, ph = 0.11637911357491466;
        double n = 4.9406564584124654e-324, f = 1.1645127272478181e-319, off = SENTINEL;
        long double t, D = ref_case1_D(th, ph, n, f, &t);
        long double ref = D * lambda + n * t - n;
        ck_assert_int_eq(swarp_gmnpr_offset(lambda, th, ph, n, f, &off), SWARP_OK);
        ck_assert_msg(fabsl(off - ref) <= 1e-13L * ref, "offset %g vs %Lg", off, ref);
    }
}
END_TEST

/* [RHS] (4.2) with a subnormal near depth and pseudo-near: a scaled form
 * z_0 4^-k, n_p (z_1 - z_0) 4^-k underflows and loses up to 16% of n_opt;
 * the reference is (4.2) written literally in long double, whose exponent
 * range holds every term. */
START_TEST(nopt_pseudo_subnormal_near) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double cases[][5] = {
        {1093.3471348809717, 4.9406564584124654e-324, 9808211.9071743283, 4.9406564584124654e-324,
         0.61457263166602416},
        {9999.9999999999982, 4.9406564584124654e-324, 5955096.6976366295, 4.9406564584124654e-324,
         0.68350289016082955},
        {39.535494428061021, 4.9406564584124654e-324, 0.012631233181843886, 4.9406564584124654e-324,
         0.54391003549150718},
        {3527.7245569144916, 2.2250738585072009e-308, 2589249.6732360446, 4.9406564584124654e-324,
         0.52381102761587361}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const double* a = cases[i];
        long double dz = (long double)a[2] - a[1];
        long double ref = (long double)a[0] / dz *
                          (a[1] + sqrtl((a[1] + a[3] * dz) * ((long double)a[2] - a[4] * dz)));
        double n = SENTINEL;
        ck_assert_int_eq(swarp_warp_nopt_pseudo(a[0], a[1], a[2], a[3], a[4], &n), SWARP_OK);
        ck_assert_msg(fabsl(n - ref) <= 1e-13L * ref, "case %zu: n_opt %.17g vs %.17Lg", i, n, ref);
    }
}
END_TEST

/* [RHS] (3.5) with theta and gamma within 1e-12 of pi/2 and f_e beyond
 * 1e292: W_s = (f_e - n_e)/cos(theta) overflows but its weight
 * sin(theta + gamma) is ~1e-12, so W_lz ~ 1e300 fits and must be returned,
 * not SWARP_ERR_OVERFLOW.  The weight must be formed without rounding
 * theta + gamma near pi (rounding it alone is 28% off in the second case). */
START_TEST(wlz_side_face_overflow) {
    REQUIRE_WIDE_LONG_DOUBLE();
    const double cases[][5] = {
        {1.5707963267948966, 1.5707963267933258, 1.5592589912618021e-05, 1.3133597697636303e+300,
         0.24826051966515786},
        {1.5707963267948961, 1.5707963267948963, 3.2926388120750315e+294, 2.5527408468792104e+298,
         694594.81425827008}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const double* a = cases[i];
        long double g = a[0], th = a[1], Ws = ((long double)a[3] - a[2]) / cosl(th);
        long double ref = a[4] * cosl(g) + Ws * sinl(th + g) + (g <= th ? Ws * (1.0L - cosl(th - g)) : 0.0L);
        double w = SENTINEL;
        ck_assert_int_eq(swarp_warp_wlz(a[0], a[1], a[2], a[3], a[4], &w), SWARP_OK);
        ck_assert_msg(isfinite(w) && fabsl(w - ref) <= 1e-13L * ref, "case %zu: W_lz %g vs %Lg", i, w, ref);
    }
}
END_TEST

/* lambda_2 = (f + sqrt(fn))/(2f) tan(theta)/tan(phi) - 1/2 just below
 * DBL_MAX (theta = pi/2, phi = 1.2e-292: tan(phi)/tan(theta) ~ 7e-309):
 * the form ((1 - t) + r)/(2t) must halve before dividing, or
 * (1 + r)/t ~ 2.3e308 overflows on the way to a result below DBL_MAX. */
START_TEST(gmnpr_lambda_2_near_dbl_max) {
    REQUIRE_WIDE_LONG_DOUBLE();
    double th = 0.5 * 3.14159265358979323846, ph = 1.2e-292, n = 1.0, f = 2.0;
    double l1 = SENTINEL, l2 = SENTINEL;
    ck_assert_int_eq(swarp_gmnpr_lambda12(th, ph, n, f, &l1, &l2), SWARP_OK);
    long double ref = 0.5L * (1.0L + sqrtl(0.5L)) * tanl(th) / tanl(ph) - 0.5L;
    ck_assert(ref < DBL_MAX);
    ck_assert_msg(fabsl(l2 - ref) <= 1e-12L * ref, "lambda_2 %g vs %Lg", l2, ref);
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_model");
    TCase* t = tcase_create("mat4_invert");
    tcase_add_test(t, invert_refuses_numerically_singular);
    tcase_add_test(t, invert_rank_deficient_every_rounding_mode);
    tcase_add_test(t, invert_accepts_badly_scaled);
    suite_add_tcase(s, t);
    t = tcase_create("params_extreme");
    tcase_add_test(t, nopt_subnormal_and_huge_depths);
    tcase_add_test(t, nrepar_extreme_alpha);
    tcase_add_test(t, gmnpr_F_and_psi_huge_lambda);
    tcase_add_test(t, gmnpr_F_matches_psi_offset);
    tcase_add_test(t, eta_subnormal_angles);
    tcase_add_test(t, gmnpr_lambdas_extreme_depths);
    tcase_add_test(t, glpr_lambda_below_true_min);
    tcase_add_test(t, split_schemes_huge_ratio);
    tcase_add_test(t, error_tiny_resolution_no_spurious_underflow);
    suite_add_tcase(s, t);
    t = tcase_create("params_no_intermediate_overflow");
    tcase_add_test(t, gmnpr_lambda_theta_eq_phi_huge_far);
    tcase_add_test(t, gmnpr_psi_offset_subnormal_depths);
    tcase_add_test(t, nopt_pseudo_subnormal_near);
    tcase_add_test(t, wlz_side_face_overflow);
    tcase_add_test(t, gmnpr_lambda_2_near_dbl_max);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
