/* Plane-stabilised light matrices: [LIXEL] Chong & Gortler, "A Lixel for
 * every Pixel".  The matrix M_l, its restriction to a set of rays C (Fig. 6),
 * its factorisation into viewport x projection, and the multi-plane
 * selection of §3.  The five-point solver is in lixel_solve.c. */
#include "lixel_internal.h"

_Static_assert(sizeof(swarp_lixel_options) == sizeof(double) + 16, "swarp_lixel_options size");
_Static_assert(sizeof(swarp_lixel_info) == 5 * sizeof(swarp_vec4) + 8 + sizeof(double) + 16,
               "swarp_lixel_info size");
_Static_assert(sizeof(swarp_lixel_rect) == 24, "swarp_lixel_rect size");
_Static_assert(sizeof(swarp_lixel_restrict_options) == 3 * sizeof(double) + 8 + 16,
               "swarp_lixel_restrict_options size");

/* |pi'_z| relative to the whole image-space plane below this: the plane
 * contains the eye (it images to a line).  A plane 1e-10 of the near
 * distance away from the eye still works, but carries few digits. */
#define LX_EYE_EPS 1e-10
/* Normalised w of a corner point above this: the ray hits P in front of the
 * eye (w <= this: behind, or so far that 1/w overflows the scene, ~1e12). */
#define LX_FRONT_EPS 1e-12
/* |n.d| (unit vectors) below this: the directional light grazes the plane. */
#define LX_PARALLEL_EPS 1e-10
/* Light-to-plane distance below this fraction of the light-to-corner
 * distance: the point light lies on the plane. */
#define LX_ON_PLANE_EPS 1e-10
/* |n.v| (unit vectors) below this: the plane is parallel to the view
 * direction (horizon through the image centre). */
#define LX_VIEW_PARALLEL_EPS 1e-9
/* A vertex of C with q below this fraction of |row 4| |X| is outside. */
#define LX_Q_EPS 1e-12

static swarp_status check_light(const swarp_light* light, swarp_vec4* L, swarp_vec3* d_unit) {
    if (!sw_reserved_zero(light->_reserved, 4) || light->_reserved0 != 0) return SWARP_ERR_RESERVED_NONZERO;
    swarp_light_type t = light->type == SWARP_LIGHT_DEFAULT ? SWARP_LIGHT_DIRECTIONAL : light->type;
    if (t == SWARP_LIGHT_DIRECTIONAL) {
        if (!sw_finite3(&light->direction)) return SWARP_ERR_NON_FINITE;
        if (!sw_normalize(light->direction, d_unit)) return SWARP_ERR_ZERO_VECTOR;
        /* the centre of projection is the point at infinity of the rays */
        *L = lx_v4(d_unit->x, d_unit->y, d_unit->z, 0.0);
        return SWARP_OK;
    }
    if (t == SWARP_LIGHT_POINT) {
        if (!sw_finite3(&light->position)) return SWARP_ERR_NON_FINITE;
        *L = lx_v4(light->position.x, light->position.y, light->position.z, 1.0);
        *d_unit = sw_v3(0.0, 0.0, 0.0);
        return SWARP_OK;
    }
    return SWARP_ERR_UNKNOWN_ENUM;
}

/* Viewer pixels: x_pix = (x_ndc + 1) g/2 - 1/2 (pixel centres at integers). */
static void viewport_pixels(double g, double h, swarp_mat4* Vp) {
    sw_identity(Vp);
    Vp->m[0] = 0.5 * g;
    Vp->m[5] = 0.5 * h;
    Vp->m[12] = 0.5 * g - 0.5;
    Vp->m[13] = 0.5 * h - 0.5;
}

static swarp_vec4 xform_col(const swarp_mat4* m, double x, double y, double z, double w) {
    return sw_xform4(m, lx_v4(x, y, z, w));
}

/* The point of P whose viewer pixel is (x, y): the ray of (2) is the line
 * where (row0 - x row3).X = 0 and (row1 - y row3).X = 0 (rows of V); with
 * pi.X = 0 it is their common null vector.  Done projectively, so a hit at
 * or beyond infinity (Fig. 5) needs no special case, and without V^-1 or
 * the image-space depth (which loses digits far from the eye).  The sign
 * makes the viewer's q = row3.X positive: then X.w > 0 means the hit is in
 * front of the eye, X.w < 0 behind it, X.w = 0 on the horizon. */
static swarp_vec4 plane_point(const swarp_vec4 rows[4], swarp_vec4 pi, double x, double y) {
    swarp_vec4 a = lx_unit4(lx_v4(rows[0].x - x * rows[3].x, rows[0].y - x * rows[3].y,
                                   rows[0].z - x * rows[3].z, rows[0].w - x * rows[3].w));
    swarp_vec4 b = lx_unit4(lx_v4(rows[1].x - y * rows[3].x, rows[1].y - y * rows[3].y,
                                   rows[1].z - y * rows[3].z, rows[1].w - y * rows[3].w));
    swarp_vec4 X = lx_unit4(lx_cross4(a, b, pi));
    if (lx_dot4(rows[3], X) < 0.0) X = lx_scale4(X, -1.0);
    return X;
}

SWARP_API swarp_status swarp_lixel_matrix(const swarp_mat4* M_v, uint32_t g, uint32_t h,
                                          const swarp_light* light, const swarp_plane* plane,
                                          const swarp_lixel_options* opt, swarp_mat4* out_M_l,
                                          swarp_lixel_info* out_info) {
    if (!M_v || !light || !plane || !out_M_l) return SWARP_ERR_NULL_POINTER;
    double t = 0.5;
    if (opt) {
        if (!sw_reserved_zero(opt->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
        if (!sw_finite(opt->raise)) return SWARP_ERR_NON_FINITE;
        if (opt->raise < 0.0 || opt->raise >= 1.0) return SWARP_ERR_OUT_OF_RANGE;
        if (opt->raise > 0.0) t = opt->raise;
    }
    if (!sw_mat_finite(M_v)) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(plane->a) || !sw_finite(plane->b) || !sw_finite(plane->c) || !sw_finite(plane->d))
        return SWARP_ERR_NON_FINITE;
    if (g < 2 || h < 2) return SWARP_ERR_RESOLUTION;
    swarp_vec4 L;
    swarp_vec3 d_unit;
    swarp_status st = check_light(light, &L, &d_unit);
    if (st != SWARP_OK) return st;
    double n_len = sw_len(sw_v3(plane->a, plane->b, plane->c));
    if (!(n_len > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    /* the plane as a covector with unit normal */
    swarp_vec4 pi = lx_v4(plane->a / n_len, plane->b / n_len, plane->c / n_len, plane->d / n_len);
    swarp_vec3 n_unit = sw_v3(pi.x, pi.y, pi.z);

    /* V: world -> viewer pixels [x_v q, y_v q, z_v q, q] as in [LIXEL] §2 */
    swarp_mat4 Vp, V, V_inv;
    viewport_pixels((double)g, (double)h, &Vp);
    sw_mul(&Vp, M_v, &V);
    if (!sw_invert(&V, &V_inv)) return SWARP_ERR_SINGULAR;

    /* pi' = V^-t pi: the plane in viewer-image space */
    swarp_vec4 pi_img;
    pi_img.x = lx_dot4(pi, xform_col(&V_inv, 1, 0, 0, 0));
    pi_img.y = lx_dot4(pi, xform_col(&V_inv, 0, 1, 0, 0));
    pi_img.z = lx_dot4(pi, xform_col(&V_inv, 0, 0, 1, 0));
    pi_img.w = lx_dot4(pi, xform_col(&V_inv, 0, 0, 0, 1));
    /* pi'_z = pi . eye (the eye is V^-1 (0,0,1,0)); compared with the plane
     * in units where pixel coordinates are O(1) */
    double pi_scale = hypot(hypot(pi_img.x * g, pi_img.y * h), hypot(pi_img.z, pi_img.w));
    if (!(fabs(pi_img.z) > LX_EYE_EPS * pi_scale)) return SWARP_ERR_LIXEL_PLANE_THROUGH_EYE;

    /* (2): the four corner pixels, hit points p^1..p^4 on P */
    const double px[4] = {0.0, 0.0, (double)g - 1.0, (double)g - 1.0};
    const double py[4] = {0.0, (double)h - 1.0, (double)h - 1.0, 0.0};
    swarp_vec4 rows[4] = {lx_row(&V, 0), lx_row(&V, 1), lx_row(&V, 2), lx_row(&V, 3)};
    swarp_vec4 P[4];
    uint32_t in_front = 0;
    int best = -1;
    for (int i = 0; i < 4; ++i) {
        P[i] = plane_point(rows, pi, px[i], py[i]);
        if (!lx_finite4(P[i])) return SWARP_ERR_SINGULAR;
        if (P[i].w > LX_FRONT_EPS) {
            ++in_front;
            if (best < 0 || P[i].w > P[best].w) best = i;
        }
    }
    if (in_front == 0) return SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE;
    /* Raise p^4 as in the paper when it lies in front (and not absurdly far
     * compared with the best corner); otherwise the corner most in front, so
     * the raised point sits between the light and the visible part of P. */
    int r = (P[3].w > LX_FRONT_EPS && P[3].w >= 1e-3 * P[best].w) ? 3 : best;
    swarp_vec3 p_r = sw_scale(sw_v3(P[r].x, P[r].y, P[r].z), 1.0 / P[r].w);

    /* the light must not lie on P */
    if (L.w == 0.0) {
        if (fabs(sw_dot(n_unit, d_unit)) < LX_PARALLEL_EPS) return SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE;
    } else {
        swarp_vec3 l = sw_v3(L.x, L.y, L.z);
        double dist = fabs(lx_dot4(pi, L));
        if (!(dist > LX_ON_PLANE_EPS * sw_len(sw_sub(l, p_r)))) return SWARP_ERR_LIXEL_LIGHT_ON_PLANE;
    }

    /* the eye (finite for a perspective viewer) */
    swarp_vec4 E = lx_cross4(lx_unit4(rows[0]), lx_unit4(rows[1]), lx_unit4(rows[3]));
    int eye_finite = fabs(E.w) > LX_FRONT_EPS * lx_len4(E);
    swarp_vec3 e = eye_finite ? sw_scale(sw_v3(E.x, E.y, E.z), 1.0 / E.w) : sw_v3(0, 0, 0);

    /* Fig. 2: p-hat on the ray from the light through p^r */
    swarp_vec3 p_hat;
    if (L.w == 0.0) {
        double s = eye_finite ? sw_len(sw_sub(p_r, e)) : sw_len(p_r) + 1.0;
        p_hat = sw_sub(p_r, sw_scale(d_unit, t * s));
    } else {
        p_hat = sw_add(sw_scale(p_r, 1.0 - t), sw_scale(sw_v3(L.x, L.y, L.z), t));
    }

    /* (1), (7)-(10): five correspondences */
    swarp_vec4 src[5], dst[5];
    src[0] = L;
    dst[0] = lx_v4(0.0, 0.0, 1.0, 0.0);
    for (int i = 0; i < 4; ++i) {
        src[i + 1] = P[i];
        dst[i + 1] = lx_v4(px[i], py[i], 1.0, 1.0);
    }
    src[r + 1] = lx_v4(p_hat.x, p_hat.y, p_hat.z, 1.0);
    dst[r + 1].z = -1.0;
    swarp_mat4 M;
    double cond = 0.0;
    swarp_status sst = swarp_lixel_solve5(src, dst, &M, &cond);
    if (swarp_status_is_error(sst)) return sst;

    /* Sign of +-GLP (Fig. 5): on P the two images agree, so q_l = c q_v for
     * every (homogeneous) point of P; make c > 0 so q_l > 0 exactly on the
     * part of P in front of the viewer. */
    double q_l = sw_xform4(&M, P[r]).w, q_v = sw_xform4(&V, P[r]).w;
    if (q_l * q_v < 0.0)
        for (int i = 0; i < 16; ++i) M.m[i] = -M.m[i];
    if (!sw_mat_finite(&M)) return SWARP_ERR_SINGULAR;

    /* informational results, most important first */
    swarp_status info = SWARP_OK;
    swarp_vec4 Xn = xform_col(&V_inv, 0.5 * ((double)g - 1.0), 0.5 * ((double)h - 1.0), -1.0, 1.0);
    swarp_vec4 Xf = xform_col(&V_inv, 0.5 * ((double)g - 1.0), 0.5 * ((double)h - 1.0), 1.0, 1.0);
    swarp_vec3 view = sw_sub(sw_scale(sw_v3(Xf.x, Xf.y, Xf.z), 1.0 / Xf.w),
                             sw_scale(sw_v3(Xn.x, Xn.y, Xn.z), 1.0 / Xn.w));
    swarp_vec3 v_unit;
    int view_parallel = sw_normalize(view, &v_unit) && fabs(sw_dot(v_unit, n_unit)) < LX_VIEW_PARALLEL_EPS;
    double side_eye = eye_finite ? lx_dot4(pi, lx_v4(e.x, e.y, e.z, 1.0)) : 0.0;
    double side_light = L.w == 0.0 ? -sw_dot(n_unit, d_unit) : lx_dot4(pi, L);
    if (sst == SWARP_INFO_LIXEL_ILL_CONDITIONED)
        info = sst;
    else if (view_parallel)
        info = SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW;
    else if (in_front < 4)
        info = SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY;
    else if (side_eye * side_light < 0.0)
        info = SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE;

    *out_M_l = M;
    if (out_info) {
        swarp_lixel_info inf;
        memset(&inf, 0, sizeof inf);
        for (int i = 0; i < 4; ++i) inf.corners[i] = P[i];
        inf.raised = lx_v4(p_hat.x, p_hat.y, p_hat.z, 1.0);
        inf.raised_index = (uint32_t)r;
        inf.corners_in_front = in_front;
        inf.conditioning = cond;
        *out_info = inf;
    }
    return info;
}
