/* Shadow bias in world units and its conversion to each map's depth units.
 * [KOZ] §14.2.3: world-space texel size L_texel and P + L (a + b L_texel);
 * normal offset, slope-scaled and receiver-plane depth bias. */
#include "cascade/cascade_internal.h"
#include "common/depth_range.h"

#include <float.h>

_Static_assert(sizeof(swarp_bias_map) == sizeof(swarp_mat4) + 2 * sizeof(double) + 8 + 16,
               "swarp_bias_map size");

/* w below this (relative to the matrix scale) means the point sits on or
 * behind the light's centre of projection: no texel there. */
#define SW_BIAS_W_EPS 1e-300

/* Largest tan of the receiver slope used by the slope-scaled bias: ~84
 * degrees; beyond, the bias would grow without bound (grazing receivers). */
#define SW_BIAS_MAX_SLOPE 10.0
/* A receiver plane whose two tangents image parallel to within this angle
 * (rad, relative |det| in texel space) is edge-on (swarp_bias_receiver_plane). */
#define SW_BIAS_EDGE_ON_EPS 1e-12

static swarp_status sw_map_check(const swarp_bias_map* map) {
    if (!sw_reserved_zero(map->_reserved, 4) || map->_reserved0 != 0)
        return SWARP_ERR_RESERVED_NONZERO;
    if (!sw_light_depth_range_ok(map->depth)) return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_mat_finite(&map->world_to_clip)) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(map->res_s) || !sw_finite(map->res_t) || !(map->res_s > 0.0) ||
        !(map->res_t > 0.0))
        return SWARP_ERR_RESOLUTION;
    return SWARP_OK;
}

/* Window depth per unit of NDC depth: d = (z_ndc + 1)/2 for [-1, 1] and
 * d = z_ndc for [0, 1] and reversed-Z.  Reversed-Z needs no sign here: its
 * clip z is already w - z of the forward [0, 1] map (common/depth_range.h),
 * so every derivative of d below changes sign by itself.  The depth biases
 * are d(p) - d(p moved toward the light), the amount to SUBTRACT from the
 * receiver's depth before the compare: > 0 under a LESS test ([-1, 1],
 * [0, 1]) and < 0 under reversed-Z's GREATER test, where subtracting it
 * raises the receiver's depth toward the light's (near = 1) side, the
 * direction that removes acne in either convention. */
static double sw_window_scale(swarp_depth_range d) { return sw_depth_zero_based(d) ? 1.0 : 0.5; }

static swarp_status sw_light_check(const swarp_light* light) {
    if (!sw_reserved_zero(light->_reserved, 4) || light->_reserved0 != 0)
        return SWARP_ERR_RESERVED_NONZERO;
    if (light->type != SWARP_LIGHT_DEFAULT && light->type != SWARP_LIGHT_DIRECTIONAL &&
        light->type != SWARP_LIGHT_POINT)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (light->type == SWARP_LIGHT_POINT ? !sw_finite3(&light->position)
                                         : !sw_finite3(&light->direction))
        return SWARP_ERR_NON_FINITE;
    return SWARP_OK;
}

static swarp_status sw_to_light(const swarp_light* light, swarp_vec3 p, swarp_vec3* L) {
    swarp_vec3 v = light->type == SWARP_LIGHT_POINT ? sw_sub(light->position, p)
                                                    : sw_scale(light->direction, -1.0);
    return sw_normalize(v, L) ? SWARP_OK : SWARP_ERR_ZERO_VECTOR;
}

/* p -> clip, requiring w > 0 */
static swarp_status sw_project(const swarp_mat4* M, swarp_vec3 p, swarp_vec4* h) {
    *h = sw_xform_point(M, p);
    if (!sw_finite(h->x) || !sw_finite(h->y) || !sw_finite(h->z) || !sw_finite(h->w))
        return SWARP_ERR_NON_FINITE;
    if (!(h->w > SW_BIAS_W_EPS)) return SWARP_ERR_BEHIND_PROJECTION;
    return SWARP_OK;
}

static swarp_status sw_texel_size(const swarp_bias_map* map, swarp_vec3 p, double* L_s,
                                  double* L_t) {
    swarp_mat4 inv;
    if (!sw_invert(&map->world_to_clip, &inv)) return SWARP_ERR_SINGULAR;
    swarp_vec4 h;
    swarp_status st = sw_project(&map->world_to_clip, p, &h);
    if (st != SWARP_OK) return st;
    /* One texel = 2/res in NDC: shift at constant depth and map back.  The
     * shifted point is M^-1 (ndc + d e_k, 1) = ((p, 1) + h_w d b) / h_w up to
     * the homogeneous factor, b = column k of M^-1 (M^-1 h = (p, 1)), so
     *   p' - p = h_w d (b_xyz - p b_w) / (1 + h_w d b_w)
     * exactly: the step itself, not the difference of two points of
     * magnitude |p| (a far point's texel would lose |p| / L_texel ulps to
     * that cancellation, its last digits set by the caller's rounding
     * mode). */
    const double step[2] = {2.0 / map->res_s, 2.0 / map->res_t};
    double L[2];
    for (int k = 0; k < 2; ++k) {
        const double hd = h.w * step[k];
        const double bw = inv.m[k * 4 + 3], den = 1.0 + hd * bw;
        if (!(fabs(den) > SW_BIAS_W_EPS)) return SWARP_ERR_SINGULAR;
        const swarp_vec3 b = sw_v3(inv.m[k * 4], inv.m[k * 4 + 1], inv.m[k * 4 + 2]);
        L[k] = fabs(hd / den) * sw_len(sw_sub(b, sw_scale(p, bw)));
        if (!sw_finite(L[k])) return SWARP_ERR_NON_FINITE;
    }
    *L_s = L[0];
    *L_t = L[1];
    return SWARP_OK;
}

SWARP_API swarp_status swarp_bias_texel_size(const swarp_bias_map* map, const swarp_vec3* p,
                                             double* out_L_texel, double* out_L_s, double* out_L_t) {
    if (!map || !p || (!out_L_texel && !out_L_s && !out_L_t)) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_map_check(map);
    if (st != SWARP_OK) return st;
    if (!sw_finite3(p)) return SWARP_ERR_NON_FINITE;
    double Ls, Lt;
    if ((st = sw_texel_size(map, *p, &Ls, &Lt)) != SWARP_OK) return st;
    if (out_L_texel) *out_L_texel = Ls > Lt ? Ls : Lt;
    if (out_L_s) *out_L_s = Ls;
    if (out_L_t) *out_L_t = Lt;
    return SWARP_OK;
}

/* The checked light and point, then L: the unit vector from p to the light. */
static swarp_status sw_light_at(const swarp_light* light, const swarp_vec3* p, swarp_vec3* L) {
    swarp_status st = sw_light_check(light);
    if (st != SWARP_OK) return st;
    if (!sw_finite3(p)) return SWARP_ERR_NON_FINITE;
    return sw_to_light(light, *p, L);
}

SWARP_API swarp_status swarp_bias_to_light(const swarp_light* light, const swarp_vec3* p,
                                           swarp_vec3* out_L) {
    if (!light || !p || !out_L) return SWARP_ERR_NULL_POINTER;
    swarp_vec3 L;
    swarp_status st = sw_light_at(light, p, &L);
    if (st != SWARP_OK) return st;
    *out_L = L;
    return SWARP_OK;
}

/* Common front part: checks, L (to light) and L_texel = max(L_s, L_t). */
static swarp_status sw_bias_prep(const swarp_bias_map* map, const swarp_light* light,
                                 const swarp_vec3* p, swarp_vec3* L, double* L_texel) {
    swarp_status st = sw_map_check(map);
    if (st != SWARP_OK) return st;
    if ((st = sw_light_at(light, p, L)) != SWARP_OK) return st;
    double Ls, Lt;
    if ((st = sw_texel_size(map, *p, &Ls, &Lt)) != SWARP_OK) return st;
    *L_texel = Ls > Lt ? Ls : Lt;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_bias_kozlov(const swarp_bias_map* map, const swarp_light* light,
                                         const swarp_vec3* p, double a, double b,
                                         swarp_vec3* out_p, double* out_amount) {
    if (!map || !light || !p || !out_p) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(a) || !sw_finite(b)) return SWARP_ERR_NON_FINITE;
    swarp_vec3 L;
    double L_texel;
    swarp_status st = sw_bias_prep(map, light, p, &L, &L_texel);
    if (st != SWARP_OK) return st;
    /* [KOZ] §14.2.3: P_biased = P_orig + L (a + b L_texel) */
    const double amount = a + b * L_texel;
    if (!sw_finite(amount)) return SWARP_ERR_NON_FINITE;
    if (amount < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    swarp_vec3 q = sw_add(*p, sw_scale(L, amount));
    if (!sw_finite3(&q)) return SWARP_ERR_NON_FINITE;
    *out_p = q;
    if (out_amount) *out_amount = amount;
    return SWARP_OK;
}

/* N.L for a unit normal, clamped to [0, 1]; *back = 1 when it was negative. */
static double sw_ndotl(swarp_vec3 N, swarp_vec3 L, int* back) {
    double ndl = sw_dot(N, L);
    *back = ndl < 0.0;
    if (ndl < 0.0) ndl = 0.0;
    if (ndl > 1.0) ndl = 1.0;
    return ndl;
}

/* The front part of the normal-dependent biases: unit normal N (zero ->
 * SWARP_ERR_ZERO_VECTOR), then sw_bias_prep, then the clamped N.L. */
typedef struct sw_bias_frame {
    swarp_vec3 N, L;
    double L_texel, ndl;
    int back; /* N.L was negative */
} sw_bias_frame;
static swarp_status sw_bias_prep_normal(const swarp_bias_map* map, const swarp_light* light,
                                        const swarp_vec3* p, const swarp_vec3* normal,
                                        sw_bias_frame* fr) {
    if (!sw_normalize(*normal, &fr->N)) return SWARP_ERR_ZERO_VECTOR;
    swarp_status st = sw_bias_prep(map, light, p, &fr->L, &fr->L_texel);
    if (st != SWARP_OK) return st;
    fr->ndl = sw_ndotl(fr->N, fr->L, &fr->back);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_bias_normal_offset(const swarp_bias_map* map, const swarp_light* light,
                                                const swarp_vec3* p, const swarp_vec3* normal,
                                                double k, swarp_vec3* out_p, double* out_amount) {
    if (!map || !light || !p || !normal || !out_p) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(k) || !sw_finite3(normal)) return SWARP_ERR_NON_FINITE;
    if (k < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    sw_bias_frame fr;
    swarp_status st = sw_bias_prep_normal(map, light, p, normal, &fr);
    if (st != SWARP_OK) return st;
    /* 1 - N.L as |N - L|^2 / 2 (both unit): N = L (a normal facing the
     * light) gives 0 exactly in every rounding mode, where 1 - N.L leaves
     * 1 - |N|^2, an ulp or two whose sign the caller's rounding mode
     * chooses, times k L_texel (k = 1e95 would move p' by 1e79).  Its error
     * is eps |N - L| instead of eps: better near N = L, the same elsewhere. */
    double one_minus_ndl = 1.0;
    if (!fr.back) {
        const swarp_vec3 D = sw_sub(fr.N, fr.L);
        one_minus_ndl = 0.5 * sw_dot(D, D);
        if (one_minus_ndl > 1.0) one_minus_ndl = 1.0;
    }
    const double amount = k * fr.L_texel * one_minus_ndl;
    swarp_vec3 q = sw_add(*p, sw_scale(fr.N, amount));
    if (!sw_finite(amount) || !sw_finite3(&q)) return SWARP_ERR_NON_FINITE;
    *out_p = q;
    if (out_amount) *out_amount = amount;
    return fr.back ? SWARP_INFO_BACKFACING : SWARP_OK;
}

/* d(p) - d(p + t L): the window-depth difference across a move by t along
 * L.  With h = M p, g = M (L, 0) and z = h_z / h_w, exactly
 *   z(p + t L) - z(p) = t (g_z - z g_w) / (h_w + t g_w),
 * the secant form of the ratio derivative below (sw_ndc_derivative): a
 * small t gives a small difference with the relative accuracy of its
 * factors, where subtracting the two depths (each O(1), rounded to eps)
 * leaves a difference of 1e-13 whose leading digits the caller's rounding
 * mode chooses (6.4e-14 or 1.1e-13 for the same input).
 * BEHIND_PROJECTION when the moved point's w is not positive. */
static swarp_status sw_depth_step(const swarp_bias_map* map, swarp_vec3 p, swarp_vec3 L, double t,
                                  double* out) {
    swarp_vec4 h;
    swarp_status st = sw_project(&map->world_to_clip, p, &h);
    if (st != SWARP_OK) return st;
    const swarp_vec4 l4 = {L.x, L.y, L.z, 0.0};
    const swarp_vec4 g = sw_xform4(&map->world_to_clip, l4);
    const double w1 = h.w + t * g.w;
    if (!sw_finite(w1)) return SWARP_ERR_NON_FINITE;
    if (!(w1 > SW_BIAS_W_EPS)) return SWARP_ERR_BEHIND_PROJECTION;
    const double dz = (g.z - (h.z / h.w) * g.w) / w1;
    *out = -sw_window_scale(map->depth) * (t * dz);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_bias_slope_scaled(const swarp_bias_map* map, const swarp_light* light,
                                               const swarp_vec3* p, const swarp_vec3* normal,
                                               double c, double s, double* out_world_bias,
                                               double* out_depth_bias) {
    if (!map || !light || !p || !normal || (!out_world_bias && !out_depth_bias))
        return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(c) || !sw_finite(s) || !sw_finite3(normal)) return SWARP_ERR_NON_FINITE;
    if (c < 0.0 || s < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    sw_bias_frame fr;
    swarp_status st = sw_bias_prep_normal(map, light, p, normal, &fr);
    if (st != SWARP_OK) return st;
    /* tan of the angle between N and L: depth step per unit of lateral move.
     * sin from |N x L|, not sqrt(1 - (N.L)^2): that loses half the digits
     * when N is almost parallel to L (an error of ~1e-8 in tan that moves
     * with the rounding mode) */
    const double ndl = fr.ndl, sin_nl = sw_len(sw_cross(fr.N, fr.L));
    double slope = SW_BIAS_MAX_SLOPE;
    if (ndl * SW_BIAS_MAX_SLOPE > sin_nl) slope = sin_nl / ndl;
    const double world_bias = c + s * fr.L_texel * slope;
    double depth_bias;
    if ((st = sw_depth_step(map, *p, fr.L, world_bias, &depth_bias)) != SWARP_OK) return st;
    if (!sw_finite(world_bias) || !sw_finite(depth_bias)) return SWARP_ERR_NON_FINITE;
    if (out_world_bias) *out_world_bias = world_bias;
    if (out_depth_bias) *out_depth_bias = depth_bias;
    return fr.back ? SWARP_INFO_BACKFACING : SWARP_OK;
}

/* Exact derivative of NDC (x, y, z)/w along a world direction T at p, in
 * the ratio form d(x/w) = (dx - (x/w) dw)/w, h = M p, dh = M T.  Not
 * dx/w - x dw/w^2: for a far point (|w| > 1e154) 1/w^2 underflows to 0 and
 * the second term vanishes, leaving dx/w alone (a depth derivative of
 * 1e-300 where it is 0). */
static void sw_ndc_derivative(const swarp_mat4* M, const swarp_vec4* h, swarp_vec3 T, double out[3]) {
    swarp_vec4 t4 = {T.x, T.y, T.z, 0.0};
    swarp_vec4 g = sw_xform4(M, t4);
    const double ndc[3] = {h->x / h->w, h->y / h->w, h->z / h->w};
    const double gv[3] = {g.x, g.y, g.z};
    for (int r = 0; r < 3; ++r) out[r] = (gv[r] - ndc[r] * g.w) / h->w;
}

SWARP_API swarp_status swarp_bias_depth_per_world(const swarp_bias_map* map, const swarp_light* light,
                                                  const swarp_vec3* p, double* out_depth_per_world) {
    if (!map || !light || !p || !out_depth_per_world) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_map_check(map);
    if (st != SWARP_OK) return st;
    swarp_vec3 L;
    if ((st = sw_light_at(light, p, &L)) != SWARP_OK) return st;
    swarp_vec4 h;
    if ((st = sw_project(&map->world_to_clip, *p, &h)) != SWARP_OK) return st;
    double dv[3];
    sw_ndc_derivative(&map->world_to_clip, &h, L, dv);
    /* moving toward the light lowers a forward depth: report the decrease
     * (negative under reversed-Z, where the depth rises toward the light) */
    const double f = -sw_window_scale(map->depth) * dv[2];
    if (!sw_finite(f)) return SWARP_ERR_NON_FINITE;
    *out_depth_per_world = f;
    return SWARP_OK;
}

/* v scaled by a power of two (exact) so that its largest |component| is in
 * [1, 2); 0 when v is zero.  The receiver plane and its gradient do not
 * depend on the tangents' lengths nor on a common factor of a row of the
 * 2x2 system, so this only keeps M T and the products below in range. */
static double sw_pow2_scale(double m) { return m > 0.0 ? scalbn(1.0, -ilogb(m)) : 0.0; }
static swarp_vec3 sw_pow2_normalized(swarp_vec3 v) {
    const double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    const int e = m > 0.0 ? ilogb(m) : 0;
    return sw_v3(scalbn(v.x, -e), scalbn(v.y, -e), scalbn(v.z, -e));
}

/* Sum of |terms| of row r of M (v, 1): what the double evaluation of
 * (M v)_r is rounded against (Higham's gamma_4 |M| |v|). */
static double sw_row_mag(const swarp_mat4* M, swarp_vec3 v, double v3, int r) {
    return fabs(M->m[r] * v.x) + fabs(M->m[4 + r] * v.y) + fabs(M->m[8 + r] * v.z) + fabs(M->m[12 + r] * v3);
}

/* Bound on the rounding error of sw_ndc_derivative's u[0], u[1]: the
 * errors of h = M p and g = M T (gamma_4 each: 4 eps, doubled for margin)
 * carried through ndc = h/w and (g - ndc g_w)/w. */
static void sw_ndc_derivative_err(const swarp_mat4* M, swarp_vec3 p, const swarp_vec4* h,
                                  swarp_vec3 T, const double u[3], double err[2]) {
    const double k = 8.0 * DBL_EPSILON, aw = fabs(h->w);
    const double Hw = sw_row_mag(M, p, 1.0, 3), Gw = sw_row_mag(M, T, 0.0, 3);
    const double gw = fabs(M->m[3] * T.x + M->m[7] * T.y + M->m[11] * T.z);
    const double hv[2] = {h->x, h->y};
    for (int r = 0; r < 2; ++r) {
        const double ndc = fabs(hv[r] / h->w);
        const double Hr = sw_row_mag(M, p, 1.0, r), Gr = sw_row_mag(M, T, 0.0, r);
        err[r] = k * ((Gr + ndc * Gw) + gw * ((Hr + ndc * Hw) / aw)) / aw + k * (Hw / aw) * fabs(u[r]);
    }
}

SWARP_API swarp_status swarp_bias_receiver_plane(const swarp_bias_map* map, const swarp_vec3* p,
                                                 const swarp_vec3* tangent_a,
                                                 const swarp_vec3* tangent_b, double out_grad[2]) {
    if (!map || !p || !tangent_a || !tangent_b || !out_grad) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_map_check(map);
    if (st != SWARP_OK) return st;
    if (!sw_finite3(p) || !sw_finite3(tangent_a) || !sw_finite3(tangent_b)) return SWARP_ERR_NON_FINITE;
    if (!(sw_len(*tangent_a) > 0.0) || !(sw_len(*tangent_b) > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    const swarp_mat4* M = &map->world_to_clip;
    swarp_vec4 h;
    if ((st = sw_project(M, *p, &h)) != SWARP_OK) return st;
    /* Rows of the system, in NDC per unit tangent, each scaled by a power of
     * two; then texel space up to the common factor res_max / 2:
     * a = (ks u_x, kt u_y), ks = res_s / res_max, kt = res_t / res_max. */
    const swarp_vec3 T[2] = {sw_pow2_normalized(*tangent_a), sw_pow2_normalized(*tangent_b)};
    const double res_max = fmax(map->res_s, map->res_t);
    const double ks = map->res_s / res_max, kt = map->res_t / res_max;
    double u[2][3], a[2][2], ea[2][2];
    for (int i = 0; i < 2; ++i) {
        double e[2];
        sw_ndc_derivative(M, &h, T[i], u[i]);
        sw_ndc_derivative_err(M, *p, &h, T[i], u[i], e);
        const double sc = sw_pow2_scale(fmax(fabs(u[i][0]), fmax(fabs(u[i][1]), fabs(u[i][2]))));
        if (!sw_finite(sc * u[i][0] + sc * u[i][1] + sc * u[i][2])) return SWARP_ERR_NON_FINITE;
        for (int r = 0; r < 3; ++r) u[i][r] *= sc;
        a[i][0] = ks * u[i][0], a[i][1] = kt * u[i][1];
        ea[i][0] = ks * sc * e[0] + DBL_EPSILON * fabs(a[i][0]);
        ea[i][1] = kt * sc * e[1] + DBL_EPSILON * fabs(a[i][1]);
    }
    /* Solve g . (ds, dt) = dd for both tangents (Isidoro's receiver plane). */
    const double p0 = a[0][0] * a[1][1], p1 = a[1][0] * a[0][1];
    const double det = p0 - p1;
    /* Edge-on: |det| below 1e-12 of the product of the two texel-space
     * lengths (the tangents' images parallel to ~1e-12 rad), or below the
     * rounding bound of det (first order in the rows' errors, plus the
     * products' and the difference's rounding): rounding cannot then tell the
     * plane from an edge-on one, and det's sign and size are noise. */
    const double scale = (fabs(a[0][0]) + fabs(a[0][1])) * (fabs(a[1][0]) + fabs(a[1][1]));
    const double det_err = fabs(a[0][0]) * ea[1][1] + ea[0][0] * fabs(a[1][1]) + fabs(a[1][0]) * ea[0][1] +
                           ea[1][0] * fabs(a[0][1]) + 2.0 * DBL_EPSILON * (fabs(p0) + fabs(p1));
    if (!(fabs(det) > SW_BIAS_EDGE_ON_EPS * scale) || !(fabs(det) > 2.0 * det_err)) return SWARP_ERR_DEGENERATE;
    /* Cramer in the scaled texel space, then back: d = ws u_z per unit of
     * the row, texels = (res_max / 2) a, so g = 2 ws (...) / (det res_max). */
    const double ws = sw_window_scale(map->depth);
    const double q_s = (u[0][2] * a[1][1] - u[1][2] * a[0][1]) / det;
    const double q_t = (a[0][0] * u[1][2] - a[1][0] * u[0][2]) / det;
    const double g_s = 2.0 * ws * (q_s / res_max), g_t = 2.0 * ws * (q_t / res_max);
    if (!sw_finite(g_s) || !sw_finite(g_t)) return SWARP_ERR_NON_FINITE;
    out_grad[0] = g_s;
    out_grad[1] = g_t;
    return SWARP_OK;
}
