/* Exported 4x4 helpers: float conversion for the GPU, product, inverse. */
#include <float.h>

#include "common/swarp_internal.h"

/* The ABI promises plain, padding-free structs of doubles. */
_Static_assert(sizeof(swarp_vec3) == 3 * sizeof(double), "swarp_vec3 layout");
_Static_assert(sizeof(swarp_vec4) == 4 * sizeof(double), "swarp_vec4 layout");
_Static_assert(sizeof(swarp_mat4) == 16 * sizeof(double), "swarp_mat4 layout");
_Static_assert(sizeof(swarp_aabb) == 6 * sizeof(double), "swarp_aabb layout");
_Static_assert(sizeof(swarp_plane) == 4 * sizeof(double), "swarp_plane layout");
_Static_assert(sizeof(swarp_status) == 4, "swarp_status is 32 bits");
_Static_assert(offsetof(swarp_camera, fovy) == 9 * sizeof(double), "swarp_camera layout");
_Static_assert(sizeof(swarp_camera) == 13 * sizeof(double) + 16, "swarp_camera size");
_Static_assert(offsetof(swarp_light, direction) == 8, "swarp_light layout");
_Static_assert(sizeof(swarp_light) == 8 + 7 * sizeof(double) + 16, "swarp_light size");
_Static_assert(sizeof(swarp_error_config) == 7 * sizeof(double) + 16, "swarp_error_config size");

SWARP_API swarp_status swarp_mat4_to_float(const swarp_mat4* m, float out[16]) {
    if (!m || !out) return SWARP_ERR_NULL_POINTER;
    for (int i = 0; i < 16; ++i)
        if (!sw_finite(m->m[i]) || fabs(m->m[i]) > FLT_MAX) return SWARP_ERR_NON_FINITE;
    for (int i = 0; i < 16; ++i) out[i] = (float)m->m[i];
    return SWARP_OK;
}

SWARP_API swarp_status swarp_mat4_mul(const swarp_mat4* a, const swarp_mat4* b, swarp_mat4* r) {
    if (!a || !b || !r) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(a) || !sw_mat_finite(b)) return SWARP_ERR_NON_FINITE;
    swarp_mat4 t;
    sw_mul(a, b, &t);
    if (!sw_mat_finite(&t)) return SWARP_ERR_NON_FINITE;
    *r = t;
    return SWARP_OK;
}

/* A pivot below this fraction of the largest entry means the matrix is
 * numerically singular in double (about 2^-1000 of the scale). */
#define SW_INVERT_TINY 1e-300

int sw_invert(const swarp_mat4* a, swarp_mat4* out) {
    double w[4][8];
    double amax = 0.0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            w[r][c] = sw_at(a, r, c);
            w[r][c + 4] = (r == c) ? 1.0 : 0.0;
            if (fabs(w[r][c]) > amax) amax = fabs(w[r][c]);
        }
    if (!(amax > 0.0) || !sw_finite(amax)) return 0;
    const double tiny = amax * SW_INVERT_TINY;
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (fabs(w[r][c]) > fabs(w[p][c])) p = r;
        if (!(fabs(w[p][c]) > tiny)) return 0;
        if (p != c)
            for (int k = 0; k < 8; ++k) {
                double t = w[c][k];
                w[c][k] = w[p][k];
                w[p][k] = t;
            }
        double inv = 1.0 / w[c][c];
        for (int k = 0; k < 8; ++k) w[c][k] *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            double f = w[r][c];
            if (f == 0.0) continue;
            for (int k = 0; k < 8; ++k) w[r][k] -= f * w[c][k];
        }
    }
    swarp_mat4 t;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) sw_set(&t, r, c, w[r][c + 4]);
    if (!sw_mat_finite(&t)) return 0;
    *out = t;
    return 1;
}

/* The condition number kappa_inf = |A|_inf |A^-1|_inf of the equilibrated
 * matrix R A C, R and C diagonal powers of two that bring the largest entry
 * of every row, then of every column, into [1, 2) (exact scalings).  It does
 * not grow with a badly scaled row or column (diag(FLT_MAX, 1, 1, 1) has
 * kappa 1 here, 3.4e38 unscaled, and its inverse is exact), only with true
 * near-dependence.  (R A C)^-1 = C^-1 A^-1 R^-1 reuses the computed inverse. */
static double sw_equilibrated_condition(const swarp_mat4* a, const swarp_mat4* inv) {
    int er[4], ec[4];
    for (int r = 0; r < 4; ++r) {
        double m = 0.0;
        for (int c = 0; c < 4; ++c) m = fmax(m, fabs(sw_at(a, r, c)));
        er[r] = -ilogb(m); /* no zero row: sw_invert refused singular input */
    }
    for (int c = 0; c < 4; ++c) {
        double m = 0.0;
        for (int r = 0; r < 4; ++r) m = fmax(m, fabs(ldexp(sw_at(a, r, c), er[r])));
        ec[c] = -ilogb(m);
    }
    double na = 0.0, ni = 0.0;
    for (int r = 0; r < 4; ++r) {
        double sa = 0.0, si = 0.0;
        for (int c = 0; c < 4; ++c) {
            sa += fabs(ldexp(sw_at(a, r, c), er[r] + ec[c]));
            si += fabs(ldexp(sw_at(inv, r, c), -ec[r] - er[c]));
        }
        na = fmax(na, sa);
        ni = fmax(ni, si);
    }
    return na * ni;
}

SWARP_API swarp_status swarp_mat4_invert(const swarp_mat4* a, swarp_mat4* r) {
    if (!a || !r) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(a)) return SWARP_ERR_NON_FINITE;
    swarp_mat4 inv;
    if (!sw_invert(a, &inv)) return SWARP_ERR_SINGULAR;
    /* Gauss-Jordan's forward error is about kappa eps relative.  Beyond
     * SWARP_MAT4_MAX_CONDITION (2^47, kappa eps = 1/32) the computed inverse
     * has lost all but a few bits, and an exactly singular matrix can show a
     * pivot of a few eps instead of 0 (seen under directed rounding): that
     * is numerically singular.  Below the threshold the computed kappa is
     * within a few percent of the true one (its own error is kappa eps). */
    if (!(sw_equilibrated_condition(a, &inv) <= SWARP_MAT4_MAX_CONDITION)) return SWARP_ERR_SINGULAR;
    *r = inv;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_mat4_transform(const swarp_mat4* m, const swarp_vec3* p, swarp_vec4* out) {
    if (!m || !p || !out) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(m) || !sw_finite3(p)) return SWARP_ERR_NON_FINITE;
    swarp_vec4 o = sw_xform_point(m, *p);
    if (!sw_finite(o.x) || !sw_finite(o.y) || !sw_finite(o.z) || !sw_finite(o.w)) return SWARP_ERR_NON_FINITE;
    *out = o;
    return SWARP_OK;
}
