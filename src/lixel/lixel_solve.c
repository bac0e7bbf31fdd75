/* The five-point projective solver of [LIXEL] §2 (via [Fau93]): the 4x4
 * matrix M, up to scale, with M src[i] ~ dst[i] for five points of which no
 * four are coplanar. */
#include <float.h>

#include "lixel/lixel_internal.h"

/* A four-point determinant (of unit vectors, so |det| <= 1 by Hadamard)
 * below this means the points are coplanar to working precision: the
 * matrix would carry no correct digit. */
#define SW_LX_COPLANAR_EPS 1e-13
/* Below this the answer keeps only ~16 + log10(cond) digits: report it. */
#define SW_LX_ILL_EPS 1e-6
/* A constraint residual (unit vectors) above this is reported too. */
#define SW_LX_RESIDUAL_EPS 1e-9
/* A point counts as finite for the normalisation when |w| exceeds this
 * fraction of |(x, y, z)|: coordinates up to 1e9 world units. */
#define SW_LX_FINITE_EPS 1e-9
/* The finite points' median distance from their median centre c at or below
 * this fraction of |c|: coincident to rounding (sw_normalise_set). */
#define SW_LX_CLUSTER_EPS (64.0 * DBL_EPSILON)

/* Determinant by LU with partial pivoting (a is copied). */
static double sw_det4(const double a_in[4][4]) {
    double a[4][4];
    memcpy(a, a_in, sizeof a);
    double det = 1.0;
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (fabs(a[r][c]) > fabs(a[p][c])) p = r;
        if (a[p][c] == 0.0) return 0.0;
        if (p != c) {
            for (int k = 0; k < 4; ++k) {
                double t = a[c][k];
                a[c][k] = a[p][k];
                a[p][k] = t;
            }
            det = -det;
        }
        det *= a[c][c];
        for (int r = c + 1; r < 4; ++r) {
            double f = a[r][c] / a[c][c];
            for (int k = c; k < 4; ++k) a[r][k] -= f * a[c][k];
        }
    }
    return det;
}

static void sw_sort_small(double* v, int n) {
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && v[j] < v[j - 1]; --j) {
            double t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
}

/* Similarity normalisation (Hartley style, but with medians so that one
 * far-away point near the horizon does not squash the others): T maps the
 * median of the finite points to the origin and their median distance to 1.
 * out[i] = T p[i] scaled to unit length.  Returns 0 for a zero point, and
 * when the median distance s is within SW_LX_CLUSTER_EPS |c|: T p = p/s - c/s
 * carries errors of eps |c|/s (and computed points such as the corner hits
 * of swarp_lixel_matrix carry eps |p| of their own), so at least two of the
 * points (those within s of c) coincide to rounding and some four are
 * coplanar; normalised, that rounding would be scaled up to unit size and
 * its determinants decide against SW_LX_COPLANAR_EPS (a 1e-15 rad field of view
 * seeing a floor 2.5e5 from the origin puts the four corner hits 1e-14
 * apart: the conditioning would be 5.6e-21 or 1.2e-13 depending on the
 * caller's rounding mode). */
static int sw_normalise_set(const swarp_vec4 p[5], swarp_vec4 out[5], swarp_mat4* T, swarp_mat4* T_inv) {
    double cx[5], cy[5], cz[5];
    int m = 0;
    for (int i = 0; i < 5; ++i) {
        double l3 = hypot(hypot(p[i].x, p[i].y), p[i].z);
        if (p[i].w != 0.0 && fabs(p[i].w) > SW_LX_FINITE_EPS * l3) {
            cx[m] = p[i].x / p[i].w;
            cy[m] = p[i].y / p[i].w;
            cz[m] = p[i].z / p[i].w;
            ++m;
        }
    }
    double c[3] = {0.0, 0.0, 0.0}, s = 1.0;
    if (m > 0) {
        double sx[5], sy[5], sz[5], d[5];
        memcpy(sx, cx, sizeof sx);
        memcpy(sy, cy, sizeof sy);
        memcpy(sz, cz, sizeof sz);
        sw_sort_small(sx, m);
        sw_sort_small(sy, m);
        sw_sort_small(sz, m);
        c[0] = sx[m / 2];
        c[1] = sy[m / 2];
        c[2] = sz[m / 2];
        double dmax = 0.0;
        for (int i = 0; i < m; ++i) {
            d[i] = sw_len(sw_v3(cx[i] - c[0], cy[i] - c[1], cz[i] - c[2]));
            if (d[i] > dmax) dmax = d[i];
        }
        sw_sort_small(d, m);
        const double cmax = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
        if (m >= 2 && d[m / 2] <= SW_LX_CLUSTER_EPS * cmax) return 0;
        s = d[m / 2] > 0.0 ? d[m / 2] : (dmax > 0.0 ? dmax : 1.0);
    }
    sw_identity(T);
    sw_identity(T_inv);
    for (int k = 0; k < 3; ++k) {
        T->m[k * 5] = 1.0 / s;
        T->m[12 + k] = -c[k] / s;
        T_inv->m[k * 5] = s;
        T_inv->m[12 + k] = c[k];
    }
    for (int i = 0; i < 5; ++i) {
        swarp_vec4 q = sw_xform4(T, p[i]);
        double l = sw_len4(q);
        if (!(l > 0.0) || !sw_finite(l)) return 0;
        out[i] = sw_scale4(q, 1.0 / l);
    }
    return 1;
}

/* Columns of A are the first four points; D[0] = det A, D[i] = det A with
 * column i-1 replaced by the fifth point (Cramer: lambda_i = D[i]/D[0]). */
static void sw_five_dets(const swarp_vec4 q[5], double D[5]) {
    double a[4][4];
    for (int j = 0; j < 5; ++j) {
        for (int c = 0; c < 4; ++c) {
            swarp_vec4 col = (j > 0 && c == j - 1) ? q[4] : q[c];
            a[0][c] = col.x;
            a[1][c] = col.y;
            a[2][c] = col.z;
            a[3][c] = col.w;
        }
        D[j] = sw_det4(a);
    }
}

/* The matrix with columns lambda_i q_i: maps e_i -> q_i and (1,1,1,1) -> q_5. */
static void sw_basis_matrix(const swarp_vec4 q[5], const double D[5], swarp_mat4* B) {
    for (int c = 0; c < 4; ++c) {
        double lambda = D[c + 1] / D[0];
        B->m[c * 4 + 0] = lambda * q[c].x;
        B->m[c * 4 + 1] = lambda * q[c].y;
        B->m[c * 4 + 2] = lambda * q[c].z;
        B->m[c * 4 + 3] = lambda * q[c].w;
    }
}

static double sw_min_abs5(const double D[5]) {
    double m = fabs(D[0]);
    for (int i = 1; i < 5; ++i)
        if (fabs(D[i]) < m) m = fabs(D[i]);
    return m;
}

/* Distance of the unit vector of a from +-(unit vector of b). */
static double sw_parallel_residual(swarp_vec4 a, swarp_vec4 b) {
    double la = sw_len4(a), lb = sw_len4(b);
    if (!(la > 0.0) || !(lb > 0.0)) return 1.0;
    a = sw_scale4(a, 1.0 / la);
    b = sw_scale4(b, 1.0 / lb);
    double dp = sw_len4(sw_v4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w));
    double dm = sw_len4(sw_v4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w));
    return dp < dm ? dp : dm;
}

/* [LIXEL] §2: "a 4 by 4 projective matrix can be uniquely specified (up to
 * scale) by constraining the pre and post transform coordinates of 5
 * geometric points (with no 4 co-planar) ... by solving two appropriate 4 by
 * 4 linear systems" [Fau93]. */
SWARP_API swarp_status swarp_lixel_solve5(const swarp_vec4 src[5], const swarp_vec4 dst[5],
                                          swarp_mat4* out_M, double* out_conditioning) {
    if (!src || !dst || !out_M) return SWARP_ERR_NULL_POINTER;
    for (int i = 0; i < 5; ++i)
        if (!sw_finite4(src[i]) || !sw_finite4(dst[i])) return SWARP_ERR_NON_FINITE;
    swarp_vec4 qs[5], qd[5];
    swarp_mat4 Ts, Ts_inv, Td, Td_inv;
    if (!sw_normalise_set(src, qs, &Ts, &Ts_inv) || !sw_normalise_set(dst, qd, &Td, &Td_inv))
        return SWARP_ERR_LIXEL_COPLANAR;
    double Ds[5], Dd[5];
    sw_five_dets(qs, Ds);
    sw_five_dets(qd, Dd);
    double cond = fmin(sw_min_abs5(Ds), sw_min_abs5(Dd));
    if (!(cond >= SW_LX_COPLANAR_EPS)) return SWARP_ERR_LIXEL_COPLANAR;
    swarp_mat4 A, B, A_inv, M;
    sw_basis_matrix(qs, Ds, &A);
    sw_basis_matrix(qd, Dd, &B);
    if (!sw_invert(&A, &A_inv)) return SWARP_ERR_LIXEL_COPLANAR;
    sw_mul(&B, &A_inv, &M);    /* normalised src -> normalised dst */
    sw_mul(&M, &Ts, &M);       /* original src -> normalised dst */
    sw_mul(&Td_inv, &M, &M);   /* original src -> original dst */
    double amax = 0.0;
    for (int i = 0; i < 16; ++i)
        if (fabs(M.m[i]) > amax) amax = fabs(M.m[i]);
    if (!(amax > 0.0) || !sw_finite(amax)) return SWARP_ERR_LIXEL_COPLANAR;
    for (int i = 0; i < 16; ++i) M.m[i] /= amax;
    if (!sw_mat_finite(&M)) return SWARP_ERR_LIXEL_COPLANAR;
    double res = 0.0;
    for (int i = 0; i < 5; ++i) {
        double r = sw_parallel_residual(sw_xform4(&M, src[i]), dst[i]);
        if (r > res) res = r;
    }
    *out_M = M;
    if (out_conditioning) *out_conditioning = cond;
    return (cond < SW_LX_ILL_EPS || res > SW_LX_RESIDUAL_EPS) ? SWARP_INFO_LIXEL_ILL_CONDITIONED : SWARP_OK;
}
