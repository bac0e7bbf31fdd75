/* LiSPSM: the perspective warping frustum P around B in light space
 * ([RHS] §3.2.1, (3.2)-(3.4), §4.1, (4.2); [WS06]; [GMNPR] (8)).
 *
 * Light space is the light view of swarp_focus_light_view: x right, y the
 * aligned up vector (the view direction projected, the warp axis), z toward
 * the light.  P looks along +y from the projection centre
 * C = C_start - n ŷ, C_start = (c_x, y_min, c_z), and is written in the
 * normalised homogeneous form
 *
 *     w = 1 + ε (y - y_min),  ε = 1/n,
 *     x' = x - c_x,   y' = A (y - y_min) - 1,   z' = -(z - c_z),
 *     A = (2 + ε d)/d,  d = y_max - y_min,
 *
 * which is n times the textbook perspective with near n and far n + d along
 * y (y'/w runs from -1 at y_min to 1 at y_max) and becomes the uniform
 * (orthographic) map exactly at ε = 0: the warp fades continuously as
 * n -> inf.  The map's coordinates are (x'/w, y'/w), its depth z'/w; a light
 * ray (fixed x, y) keeps its w, so depth order along it is kept. */
#include <float.h>

#include "geometry/geometry_internal.h"

/* An extent of B along the warp axis below this fraction of B's light-space
 * size is flat (as SW_FIT_FLAT_REL of the fit, focus.c). */
#define SW_WARP_FLAT_REL 1e-12

/* The smallest n, relative to the largest |y| of B in light space.  P's w
 * row evaluates ε y + (1 - ε y_min) on raw light-space y: each term carries a
 * rounding error of about ε |y| u (u = 2^-53), so w = 1 + ε (y - y_min) keeps
 * a relative accuracy of 2 u max|y| / n.  With n >= 1e-6 max|y| that is
 * <= 2.3e-10 (w >= 1 on B to 1e-9 with the rounding of y itself); a smaller
 * n (n below the rounding of y: the 1 of w is lost, w = 0 at y_min) is a
 * warp the matrix cannot represent.  The warp is then already a full
 * perspective at the resolution of the map, so raising n to this bound
 * changes nothing visible. */
#define SW_WARP_N_MIN_REL 1e-6

static void sw_warp_matrix(double eps, double ymin, double d, double cx, double cz, swarp_mat4* P) {
    double A = (2.0 + eps * d) / d;
    memset(P, 0, sizeof *P);
    sw_set(P, 0, 0, 1.0);
    sw_set(P, 0, 3, -cx);
    sw_set(P, 1, 1, A);
    sw_set(P, 1, 3, -A * ymin - 1.0);
    sw_set(P, 2, 2, -1.0);
    sw_set(P, 2, 3, cz);
    sw_set(P, 3, 1, eps);
    sw_set(P, 3, 3, 1.0 - eps * ymin);
}

static swarp_status sw_check_warp_options(const swarp_warp_options* o) {
    if (!sw_reserved_zero(o->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
    if ((uint32_t)o->param > (uint32_t)SWARP_WARP_PARAM_MEASURED) return SWARP_ERR_UNKNOWN_ENUM;
    if ((uint32_t)o->center > (uint32_t)SWARP_WARP_CENTER_NEAREST_VERTEX) return SWARP_ERR_UNKNOWN_ENUM;
    if (o->param == SWARP_WARP_PARAM_USER) {
        if (isnan(o->n_user)) return SWARP_ERR_NON_FINITE;
        if (!(o->n_user > 0.0)) return SWARP_ERR_OUT_OF_RANGE; /* +inf allowed: uniform */
    }
    if (o->param == SWARP_WARP_PARAM_PSEUDO) {
        if (!sw_finite(o->pseudo_near) || !sw_finite(o->pseudo_far)) return SWARP_ERR_NON_FINITE;
        if (!(o->pseudo_near >= 0.0 && o->pseudo_far >= 0.0 && o->pseudo_near + o->pseudo_far < 1.0))
            return SWARP_ERR_OUT_OF_RANGE;
    }
    return SWARP_OK;
}

/* Does the eye depth grow along P's axis, z_1 > z_0, by more than the
 * rounding of the depths (zerr: 16 eps of the sizes of their terms,
 * sw_eye_depth, and 64 eps of z_1)?  z_0 and z_1 are equal in exact
 * arithmetic when C_start is the nearest vertex at the y_max end and the
 * other end lies before the near plane (both are near then): n_opt of
 * their rounding noise (z_1 - z_0 = 1e-14 for depths of 0.03 reconstructed
 * from a point light's space 300 units across) would be anything from 1e15
 * to +inf (uniform) as the rounding falls, and the status SWARP_OK or
 * SWARP_INFO_WARP_UNIFORM with it.  Within the rounding the warp is
 * uniform, as such an n nearly is. */
static int sw_z_grows(double z0, double z1, double zerr) {
    return z1 - z0 > fmax(64.0 * DBL_EPSILON * fabs(z1), 16.0 * DBL_EPSILON * zerr);
}

/* The warp parameter n in light units for the chosen parameterisation.
 * gamma in [0, pi] is the angle between view and light axis. */
static swarp_status sw_warp_n(const swarp_warp_options* o, double d, double z0, double z1, double zerr, double gamma,
                              double theta, double near, double far, double* n_light) {
    double g = gamma > 0.5 * SWARP_PI ? SWARP_PI - gamma : gamma; /* fold to [0, pi/2] */
    if (g < 0.0) g = 0.0;
    swarp_status s;
    double n = INFINITY;
    switch (o->param) {
        case SWARP_WARP_PARAM_DEFAULT:
        case SWARP_WARP_PARAM_MEASURED: /* no region here: the search's start, n_opt */
        case SWARP_WARP_PARAM_NOPT:
            if (!sw_z_grows(z0, z1, zerr)) break;
            s = swarp_warp_nopt(d, z0, z1, &n); /* [RHS] (3.2) */
            if (swarp_status_is_error(s)) return s;
            break;
        case SWARP_WARP_PARAM_PSEUDO:
            if (!sw_z_grows(z0, z1, zerr)) break;
            s = swarp_warp_nopt_pseudo(d, z0, z1, o->pseudo_near, o->pseudo_far, &n); /* [RHS] (4.2) */
            if (swarp_status_is_error(s)) return s;
            break;
        case SWARP_WARP_PARAM_NREPAR: {
            /* [RHS] (3.3)-(3.4) with α = z_1/z_0 (the paper: "n_e and f_e ...
             * can be seen as z_0 and z_1") and W_lz = d, so η = 0 is n_opt */
            double eta;
            s = swarp_warp_eta(g, theta, &eta);
            if (swarp_status_is_error(s)) return s;
            if (!sw_z_grows(z0, z1, zerr) || eta <= -1.0) break;
            /* α = z_1/z_0 overflows for a z_0 near DBL_MIN (near = 2e-308,
             * valid): the largest double is the same limit for (3.4), where
             * inf would make n non-finite */
            s = swarp_warp_nrepar(eta, fmin(z1 / z0, DBL_MAX), d, &n);
            if (swarp_status_is_error(s)) return s;
            break;
        }
        case SWARP_WARP_PARAM_GMNPR: {
            /* [GMNPR] (8): λ = P_n / (P_f - P_n); P's depth range is d */
            double lambda;
            if (!(g > 0.0)) break;
            s = swarp_gmnpr_lambda(g, theta, near, far, &lambda);
            if (swarp_status_is_error(s)) return s;
            n = lambda * d;
            break;
        }
        case SWARP_WARP_PARAM_USER:
            n = o->n_user * d / (far - near); /* eye units -> light units */
            break;
        default:
            return SWARP_ERR_UNKNOWN_ENUM;
    }
    if (isnan(n) || !(n > 0.0)) return SWARP_ERR_DEGENERATE;
    *n_light = n;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_warp_lispsm(const swarp_mat4* light_view, const swarp_camera* cam, double near,
                                         double far, const swarp_vec3* points, size_t count,
                                         const swarp_vec3* nearest, const swarp_warp_options* opts,
                                         swarp_mat4* out_P, swarp_warp_info* out_info) {
    if (!light_view || !cam || !points || !out_P) return SWARP_ERR_NULL_POINTER;
    swarp_warp_options o;
    memset(&o, 0, sizeof o);
    if (opts) o = *opts;
    swarp_status s = sw_check_warp_options(&o);
    if (s != SWARP_OK) return s;
    s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    if (!sw_mat_finite(light_view)) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(near) || !sw_finite(far)) return SWARP_ERR_NON_FINITE;
    if (!(near > 0.0 && far > near)) return SWARP_ERR_NEAR_FAR;
    if (count == 0) return SWARP_ERR_INVALID_ARGUMENT;
    for (size_t i = 0; i < count; ++i)
        if (!sw_finite3(&points[i])) return SWARP_ERR_NON_FINITE;
    if (nearest && !sw_finite3(nearest)) return SWARP_ERR_NON_FINITE;
    swarp_mat4 P, L_inv;
    swarp_warp_info info;
    /* a look-at (swarp_focus_light_view's): its exact rigid inverse; a
     * general inversion reports light views 1e300 from the origin singular */
    if (sw_is_rigid(light_view)) sw_rigid_inverse(light_view, &L_inv);
    else if (!sw_invert(light_view, &L_inv)) return SWARP_ERR_SINGULAR;
    for (size_t i = 0; i < count; ++i) {
        swarp_vec4 h = sw_xform_point(light_view, points[i]);
        if (!(h.w > 0.0)) return SWARP_ERR_DEGENERATE;
    }
    s = sw_warp_lispsm(light_view, &L_inv, cam, near, far, points, count, nearest, &o, &P, &info);
    if (swarp_status_is_error(s)) return s;
    *out_P = P;
    if (out_info) *out_info = info;
    return s;
}

/* Eye depth of the light-space point q = (x, y, z) of M-space, or NAN.
 * *err: the sizes of the terms the depth is summed from (the point's
 * coordinates as M_inv reconstructs them over w, and the eye's), along v:
 * the depth is rounded to a few eps of it */
static double sw_eye_depth(const swarp_mat4* M_inv, const swarp_camera* cam, swarp_vec3 v, double x, double y,
                           double z, double* err) {
    swarp_vec4 h = {x, y, z, 1.0};
    swarp_vec4 w = sw_xform4(M_inv, h);
    *err = 0.0;
    if (!(w.w > 0.0)) return NAN;
    swarp_vec3 p = sw_v3(w.x / w.w, w.y / w.w, w.z / w.w);
    const double hv[4] = {x, y, z, 1.0}, pk[3] = {p.x, p.y, p.z}, ek[3] = {cam->eye.x, cam->eye.y, cam->eye.z},
                 vk[3] = {v.x, v.y, v.z};
    double tw = 0.0;
    for (int j = 0; j < 4; ++j) tw += fabs(sw_at(M_inv, 3, j) * hv[j]);
    for (int k = 0; k < 3; ++k) {
        double tk = 0.0;
        for (int j = 0; j < 4; ++j) tk += fabs(sw_at(M_inv, k, j) * hv[j]);
        *err += fabs(vk[k]) * ((tk + fabs(pk[k]) * tw) / w.w + fabs(ek[k]));
    }
    return sw_dot(sw_sub(p, cam->eye), v);
}

/* B in light space: its extent [ymin, ymax] along the warp axis y, the
 * largest |x|, |y| (size) and the smallest w of its points. */
static void sw_warp_extent_y(const swarp_mat4* M, const swarp_vec3* points, size_t count, double* ymin_out,
                             double* ymax_out, double* size_out, double* wmin_out) {
    double ymin = INFINITY, ymax = -INFINITY, size = 0.0;
    double wmin = INFINITY;
    for (size_t i = 0; i < count; ++i) {
        swarp_vec4 h = sw_xform_point(M, points[i]);
        double y = h.y / h.w, ax = fabs(h.x / h.w), ay = fabs(y);
        if (y < ymin) ymin = y;
        if (y > ymax) ymax = y;
        wmin = h.w < wmin ? h.w : wmin;
        size = ax > size ? ax : size;
        size = ay > size ? ay : size;
    }
    *ymin_out = ymin, *ymax_out = ymax, *size_out = size, *wmin_out = wmin;
}

/* γ: the angle between the view direction v and the light axis (-z of the
 * light view; for a point light the axis of its view), and the angle the
 * parameter functions see, γ_eff with sin γ_eff = |y·v|: the view
 * direction's component along the warp axis y.  With y = v̂ (light-space
 * alignment) it is γ folded to [0, pi/2]; where the frame is turned away
 * from v̂ (the blend near parallel, or a followed frame of
 * swarp_setup_follow) the warp is as strong as the view's slope along its
 * own axis, like n_opt's z_0, z_1, and uniform where y ⟂ v. */
static void sw_warp_gamma(const swarp_mat4* M, swarp_vec3 v, const swarp_warp_options* o, double* gamma,
                          double* gamma_eff) {
    double vx = sw_at(M, 0, 0) * v.x + sw_at(M, 0, 1) * v.y + sw_at(M, 0, 2) * v.z;
    double vy = sw_at(M, 1, 0) * v.x + sw_at(M, 1, 1) * v.y + sw_at(M, 1, 2) * v.z;
    double vz = sw_at(M, 2, 0) * v.x + sw_at(M, 2, 1) * v.y + sw_at(M, 2, 2) * v.z;
    double va = -vz; /* v along the light axis */
    /* point light: M = P0·L, P0's w row is -z of L (a unit row: one of its
     * entries is non-zero; a directional M = L has 0 0 0 1).  The whole row
     * is tested: a point light whose axis has no world-z component (L's z
     * row (x, y, 0): eye, light and view in one z plane) has a z entry that
     * is 0 up to rounding (-0 or 1e-17), and testing it alone would pick
     * the directional γ = 90° or the point light's angle by that rounding */
    if (sw_at(M, 3, 0) != 0.0 || sw_at(M, 3, 1) != 0.0 || sw_at(M, 3, 2) != 0.0) {
        va = sw_at(M, 3, 0) * v.x + sw_at(M, 3, 1) * v.y + sw_at(M, 3, 2) * v.z;
    }
    *gamma = atan2(hypot(vx, vy), va);
    *gamma_eff = (o->param == SWARP_WARP_PARAM_NREPAR || o->param == SWARP_WARP_PARAM_GMNPR)
                     ? atan2(fabs(vy), hypot(vx, va))
                     : *gamma; /* unused by n_opt, (4.2) and the caller's n */
}

/* The nearest a light-space w of C_start may be to the light, relative to
 * the smallest w of B: SW_LIGHT_NEAR_MIN_REL of setup.c, the nearest a
 * point of B may be.  Directional lights (w = 1) never fall below it. */
#define SW_WARP_CENTER_W_MIN_REL 1e-4

/* C_start (light space) moved into B's light-space box laterally.  A point
 * light's space (x/D, y/D, 1/D) is only defined in front of the light: a
 * C_start behind the light's plane, or SW_WARP_CENTER_W_MIN_REL times
 * nearer to it than every point of B (s on the plane through the light, D
 * ~ 1e-11: x/D = 5e10, which shears B's x below its rounding), is no
 * centre; moved into B's box the map stays a LiSPSM of B.  c_h: C_start
 * homogeneous. */
static void sw_warp_center_in_box(const swarp_mat4* M, const swarp_vec3* points, size_t count, swarp_vec4 c_h,
                                  swarp_vec3* c_ls) {
    double xmin = INFINITY, xmax = -INFINITY, zmin = INFINITY, zmax = -INFINITY;
    for (size_t i = 0; i < count; ++i) {
        swarp_vec3 q = sw_project(M, points[i]);
        xmin = fmin(xmin, q.x), xmax = fmax(xmax, q.x);
        zmin = fmin(zmin, q.z), zmax = fmax(zmax, q.z);
    }
    c_ls->x = fmin(fmax(c_ls->x, xmin), xmax);
    c_ls->z = fmin(fmax(c_ls->z, zmin), zmax);
    if (!sw_finite(c_ls->x)) c_ls->x = 0.5 * (xmin + xmax);
    if (!sw_finite(c_ls->z)) c_ls->z = 0.5 * (zmin + zmax);
    /* C_start on the light's plane, w = 0 exactly (the point light at
     * s = eye + near v): x/w and z/w are +-inf by the sign of that zero,
     * which the rounding picks, and 0/0 = NaN would pass through fmax as
     * B's minimum.  The side is the numerator's, whatever the zero's sign;
     * the middle of B's box where the numerator is zero too (s at the
     * light: no direction at all). */
    if (c_h.w == 0.0) {
        c_ls->x = c_h.x > 0.0 ? xmax : c_h.x < 0.0 ? xmin : 0.5 * (xmin + xmax);
        c_ls->z = c_h.z > 0.0 ? zmax : c_h.z < 0.0 ? zmin : 0.5 * (zmin + zmax);
    }
}

/* C_start in light space: [RHS] §4.1 takes s on the view vector at the
 * depth of the nearest vertex e (the given near); [WS06] takes e itself. */
static swarp_vec3 sw_warp_center(const swarp_mat4* M, const swarp_camera* cam, swarp_vec3 v, double near,
                                 const swarp_vec3* nearest, const swarp_warp_options* o, const swarp_vec3* points,
                                 size_t count, double wmin) {
    swarp_vec3 c_ws = sw_add(cam->eye, sw_scale(v, near));
    if (o->center == SWARP_WARP_CENTER_NEAREST_VERTEX && nearest) c_ws = *nearest;
    swarp_vec4 c_h = sw_xform_point(M, c_ws);
    swarp_vec3 c_ls = sw_v3(c_h.x / c_h.w, c_h.y / c_h.w, c_h.z / c_h.w);
    if (!(c_h.w >= SW_WARP_CENTER_W_MIN_REL * wmin)) sw_warp_center_in_box(M, points, count, c_h, &c_ls);
    return c_ls;
}

/* The warp parameter n in light units: that of the parameterisation,
 * raised to SW_WARP_N_MIN_REL of B's light-space y; +inf (uniform) for a B
 * flat along the axis (d = 0). */
static swarp_status sw_warp_n_light(const swarp_warp_options* o, double d, double ymin, double ymax, double z0,
                                    double z1, double zerr, double gamma_eff, double theta, double near, double far,
                                    double* n_light) {
    *n_light = INFINITY;
    if (!(d > 0.0)) return SWARP_OK;
    swarp_status s = sw_warp_n(o, d, z0, z1, zerr, gamma_eff, theta, near, far, n_light);
    if (s != SWARP_OK) return s;
    double n_min = SW_WARP_N_MIN_REL * fmax(fabs(ymin), fabs(ymax));
    if (*n_light < n_min) *n_light = n_min;
    return SWARP_OK;
}

swarp_status sw_warp_lispsm(const swarp_mat4* M, const swarp_mat4* M_inv, const swarp_camera* cam, double near,
                            double far, const swarp_vec3* points, size_t count, const swarp_vec3* nearest,
                            const swarp_warp_options* o, swarp_mat4* out_P, swarp_warp_info* out_info) {
    swarp_vec3 v, r, u;
    sw_camera_basis(cam, &v, &r, &u);
    double ymin, ymax, size, wmin;
    sw_warp_extent_y(M, points, count, &ymin, &ymax, &size, &wmin);
    double d = ymax - ymin;
    /* B flat across the warp axis (its extent there is rounding noise of
     * its coordinates): no warp, P normalises nothing, the fit pads the
     * flat extent (SWARP_INFO_FLAT_EXTENT).  Dividing by the noise would
     * stretch it over the whole map. */
    if (!(d > SW_WARP_FLAT_REL * size)) d = 0.0;
    double gamma, gamma_eff;
    sw_warp_gamma(M, v, o, &gamma, &gamma_eff);
    swarp_vec3 c_ls = sw_warp_center(M, cam, v, near, nearest, o, points, count, wmin);
    /* z_0, z_1 of (3.2): eye depths of the two ends of P's axis, C_start and
     * (c_x, y_max, c_z) ([WS06] calcNoptGeneral).  z_0 is kept at or beyond
     * near: the part of B nearer than the view's near plane receives nothing. */
    double e0, e1;
    double z0 = sw_eye_depth(M_inv, cam, v, c_ls.x, ymin, c_ls.z, &e0);
    double z1 = sw_eye_depth(M_inv, cam, v, c_ls.x, ymax, c_ls.z, &e1);
    const double zerr = e0 + e1;
    if (!sw_finite(z0) || !sw_finite(z1)) z0 = z1 = near; /* axis leaves the light's space: uniform */
    z0 = fmax(z0, near);
    double theta = sw_half_fovy(cam->fovy);
    double n_light;
    swarp_status st = SWARP_OK;
    swarp_status s = sw_warp_n_light(o, d, ymin, ymax, z0, z1, zerr, gamma_eff, theta, near, far, &n_light);
    if (s != SWARP_OK) return s;
    double eps = (d > 0.0 && sw_finite(n_light)) ? 1.0 / n_light : 0.0;
    if (eps == 0.0) {
        n_light = INFINITY;
        st = SWARP_INFO_WARP_UNIFORM;
    }
    /* n' in eye units must exist too (far - near of 1e300: it overflows) */
    if (eps != 0.0 && !sw_finite(n_light * (far - near) / d)) return SWARP_ERR_DEGENERATE;
    swarp_mat4 P;
    /* The centre's lateral position only matters for a perspective warp:
     * uniform (eps = 0), the x, z translations are A_fit's business, and
     * C_start itself may be meaningless there (a point light whose plane
     * through the light holds s: x/D = 1e17 would swamp B's x in the map) */
    if (eps == 0.0) c_ls.x = c_ls.z = 0.0;
    sw_warp_matrix(eps, ymin, d > 0.0 ? d : 1.0, c_ls.x, c_ls.z, &P);
    if (!sw_mat_finite(&P)) return SWARP_ERR_DEGENERATE;
    *out_P = P;
    if (out_info) {
        memset(out_info, 0, sizeof *out_info);
        out_info->n_light = n_light;
        out_info->n_eye = (d > 0.0 && sw_finite(n_light)) ? n_light * (far - near) / d : INFINITY;
        out_info->d = d;
        out_info->z_0 = z0;
        out_info->z_1 = z1;
        out_info->gamma = gamma;
    }
    return st;
}
