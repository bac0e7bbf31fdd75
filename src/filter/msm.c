/* Moment shadow maps with four power moments, Hamburger form.
 * Peters & Klein 2015, "Moment Shadow Mapping", I3D '15, Algorithm 3 (the
 * Hamburger 4MSM bound) and its moment bias; depths in [0, 1] with the bias
 * target (1/2, 1/2, 1/2, 1/2) of the [0, 1] formulation.  Written from the
 * algorithm's maths, not from any shader. */
#include <float.h>

#include "filter/filter_internal.h"

/* A Cholesky pivot that is a cancellation of terms of size S is rounding
 * noise once it falls below ~64 eps S (a few ulps of each of the 3-4 terms
 * that were summed, with room); then the Hankel matrix is singular and the
 * distribution has fewer atoms. */
#define SW_MSM_CANCEL_EPS (64.0 * DBL_EPSILON)

SWARP_API swarp_status swarp_msm_moments(double z, double out_b[4]) {
    if (!out_b) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(z)) return SWARP_ERR_NON_FINITE;
    if (z < 0.0 || z > 1.0) return SWARP_ERR_OUT_OF_RANGE;
    double z2 = z * z;
    out_b[0] = z;
    out_b[1] = z2;
    out_b[2] = z2 * z;
    out_b[3] = z2 * z2;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_msm_bias(const double b[4], double alpha, double out_b[4]) {
    if (!b || !out_b) return SWARP_ERR_NULL_POINTER;
    for (int i = 0; i < 4; ++i)
        if (!sw_finite(b[i])) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(alpha)) return SWARP_ERR_NON_FINITE;
    if (alpha < 0.0 || alpha > 1.0) return SWARP_ERR_OUT_OF_RANGE;
    double r[4];
    for (int i = 0; i < 4; ++i) r[i] = (1.0 - alpha) * b[i] + alpha * 0.5;
    memcpy(out_b, r, sizeof r);
    return SWARP_OK;
}

/* An atom recovered from rounded moments sits within ~sqrt(eps)-relative
 * noise of the true depth; one closer than 1e-6 of the atom spacing to z_f is
 * taken to BE at z_f (the receiver's own depth counts as lit, as in PCF). */
#define SW_MSM_ATOM_SNAP 1e-6

/* Visibility of a discrete distribution: lit mass at depths >= z_f. */
static double sw_lit_mass(const double* x, const double* w, int n, double z_f, double snap) {
    double v = 0.0;
    for (int i = 0; i < n; ++i)
        if (x[i] >= z_f - snap) v += w[i];
    return v;
}

static double sw_clamp01(double v) { return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v); }

/* Depth scales beyond 2^this are brought to ~1 before the bound: the
 * squares and products of the moments of a larger scale would overflow. */
#define SW_MSM_SCALE_EXP 100
/* |q1| beyond this: q1^2 could overflow, the discriminant is formed
 * relative to q1^2. */
#define SW_MSM_Q1_BIG 1e100
/* A root at infinity (c3 -> 0) is represented by this huge finite value;
 * the bound's formulas then take their limits, and its square stays
 * finite. */
#define SW_MSM_ROOT_INF 1e150

/* The bound is invariant under depth scaling z -> 2^-k z (b_i -> 2^-ik
 * b_i, z_f -> 2^-k z_f; the thresholds are relative).  A depth scale 2^k
 * beyond 2^100 (z_f = 1e300, or b_2 = 1e300) would overflow the squares
 * and products: scaled to ~1 first, exactly (powers of two); moments that
 * then underflow are negligible at that scale, which gives the right limit
 * (e.g. z_f far behind every depth: 0). */
static void sw_msm_rescale(const double b[4], double* z_f, double s[4]) {
    int k = ilogb(*z_f);
    for (int i = 0; i < 4; ++i) {
        int ki = ilogb(b[i]) / (i + 1);
        if (b[i] != 0.0 && ki > k) k = ki;
    }
    if (*z_f == 0.0 && k == ilogb(0.0)) k = 0;
    for (int i = 0; i < 4; ++i) s[i] = b[i];
    if (k > SW_MSM_SCALE_EXP) {
        for (int i = 0; i < 4; ++i) s[i] = ldexp(s[i], -(i + 1) * k);
        *z_f = ldexp(*z_f, -k);
    }
}

/* Two atoms (D33 singular): the roots of the degree-2 orthogonal polynomial
 * x^2 - L32 x + (L32 b1 - b2), weights from the first moment. */
static swarp_status sw_msm_two_atoms(double b1, double b2, double L32, double z_f, double* out_visibility) {
    double q1 = -L32, q0 = L32 * b1 - b2;
    /* s = sqrt(q1^2 - 4 q0), as |q1| sqrt(1 - 4 q0/q1^2) once q1^2 could
     * overflow (moments that are no distribution's, e.g. b_3 = 1e300 with
     * b_4 ~ 1e-5, give L32 ~ 1e300, and q1^2 - 4 q0 would be Inf - Inf) */
    double s;
    if (fabs(q1) > SW_MSM_Q1_BIG) {
        double u = 1.0 - 4.0 * ((q0 / q1) / q1);
        s = fabs(q1) * sqrt(u > 0.0 ? u : 0.0);
    } else {
        double disc = q1 * q1 - 4.0 * q0;
        s = sqrt(disc > 0.0 ? disc : 0.0);
    }
    double x[2] = {0.5 * (-q1 - s), 0.5 * (-q1 + s)};
    double w[2];
    if (x[1] - x[0] > 0.0) {
        w[1] = (b1 - x[0]) / (x[1] - x[0]);
        w[1] = sw_clamp01(w[1]);
        w[0] = 1.0 - w[1];
    } else {
        w[0] = 1.0;
        w[1] = 0.0;
    }
    double v = sw_lit_mass(x, w, 2, z_f, SW_MSM_ATOM_SNAP * (x[1] - x[0]));
    if (!sw_finite(v) || !sw_finite(x[0]) || !sw_finite(x[1]))
        return SWARP_ERR_NON_FINITE; /* not moments of any distribution */
    *out_visibility = sw_clamp01(v);
    return SWARP_INFO_FILTER_MSM_DEGENERATE;
}

/* Algorithm 3 proper: solve B c = (1, z_f, z_f^2) with the LDL^T factors,
 * the roots z_2 <= z_3 of c1 + c2 z + c3 z^2, and the sharp lower bound G
 * of the occluded fraction from the three-atom representation through z_f
 * (weights by Lagrange interpolation of the moments 1, b1, b2 on the
 * atoms). */
static swarp_status sw_msm_three_atoms(double b1, double b2, double D22, double L32, double D33, double z_f,
                                       double* out_visibility) {
    /* forward (L), diagonal (D), back (L^T) */
    double y1 = 1.0;
    double y2 = z_f - b1 * y1;
    double y3 = z_f * z_f - b2 * y1 - L32 * y2;
    y2 /= D22;
    y3 /= D33;
    double c3 = y3;
    double c2 = y2 - L32 * c3;
    double c1 = y1 - b1 * c2 - b2 * c3;
    /* stable form: no cancellation between -c2 and the root of the
     * discriminant */
    double disc = c2 * c2 - 4.0 * c3 * c1;
    if (disc < 0.0) disc = 0.0; /* real in exact arithmetic: B is positive definite */
    double qq = -0.5 * (c2 + (c2 >= 0.0 ? sqrt(disc) : -sqrt(disc)));
    const double big = SW_MSM_ROOT_INF;
    double r1 = (qq != 0.0 && fabs(c3) * big > fabs(qq)) ? qq / c3 : (qq * c3 >= 0.0 ? big : -big);
    double r2 = (fabs(qq) * big > fabs(c1)) ? c1 / qq : (c1 * qq >= 0.0 ? big : -big);
    double z2 = r1 < r2 ? r1 : r2, z3 = r1 < r2 ? r2 : r1;
    double G;
    if (z_f <= z2) {
        G = 0.0;
    } else if (z_f <= z3) {
        G = (z_f * z3 - b1 * (z_f + z3) + b2) / ((z3 - z2) * (z_f - z2));
    } else {
        G = 1.0 - (z2 * z3 - b1 * (z2 + z3) + b2) / ((z_f - z2) * (z_f - z3));
    }
    if (!sw_finite(G)) G = (z_f > z3) ? 1.0 : 0.0; /* limits of the formulas */
    if (!sw_finite(G)) return SWARP_ERR_NON_FINITE;
    *out_visibility = sw_clamp01(1.0 - G);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_msm_visibility(const double b[4], double z_f,
                                            double* out_visibility) {
    if (!b || !out_visibility) return SWARP_ERR_NULL_POINTER;
    for (int i = 0; i < 4; ++i)
        if (!sw_finite(b[i])) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(z_f)) return SWARP_ERR_NON_FINITE;
    if (b[1] < 0.0 || b[3] < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    double s[4];
    sw_msm_rescale(b, &z_f, s);
    const double b1 = s[0], b2 = s[1], b3 = s[2], b4 = s[3];
    /* Squares and products of the moments must stay finite (they do after
     * the scaling: |b_i| <= 2^(i + 1) there). */
    if (!sw_finite(b1 * b1) || !sw_finite(b2 * b2) || !sw_finite(b1 * b2) ||
        !sw_finite(z_f * z_f))
        return SWARP_ERR_NON_FINITE;

    /* LDL^T of the Hankel matrix B = [1 b1 b2; b1 b2 b3; b2 b3 b4]. */
    double D22 = b2 - b1 * b1;
    if (D22 <= SW_MSM_CANCEL_EPS * (b2 + b1 * b1)) {
        /* One atom at b1: lit in front of it (and at it), occluded behind.
         * b1 is an average of rounded depths; the spread this branch allows
         * is sqrt(D22) <~ sqrt(2 * 64 eps) |b1| ~ 1.7e-7 |b1|, so a receiver
         * that close to b1 is at the atom. */
        double snap = sqrt(2.0 * SW_MSM_CANCEL_EPS) * fabs(b1);
        *out_visibility = (z_f <= b1 + snap) ? 1.0 : 0.0;
        return SWARP_INFO_FILTER_MSM_DEGENERATE;
    }
    double L32 = (b3 - b1 * b2) / D22;
    double D33 = b4 - b2 * b2 - L32 * L32 * D22;
    if (D33 <= SW_MSM_CANCEL_EPS * (b4 + b2 * b2 + L32 * L32 * D22))
        return sw_msm_two_atoms(b1, b2, L32, z_f, out_visibility);
    return sw_msm_three_atoms(b1, b2, D22, L32, D33, z_f, out_visibility);
}
