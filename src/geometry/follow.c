/* Coherent light frames over time: the light frame of swarp_setup_follow
 * follows the previous frame's continuously along any path of the light and
 * the camera (docs/geometry.md, "Continuity over the whole sphere").
 *
 * Why state: the light-space alignment of [RHS] §3.2.1 wants the light
 * view's up vector along v_perp (the view direction projected perpendicular
 * to the light axis a).  As a function of a alone that is a tangent field on
 * the sphere, and every continuous tangent field on the sphere vanishes
 * somewhere (hairy-ball theorem), so every stateless rule (swarp_setup's
 * included) has a point where the map turns abruptly.  With the previous
 * frame as state the rule only needs to move the frame a bounded amount per
 * unit of motion:
 *
 *   h  = previous up projected perpendicular to the new axis a (transport),
 *   t  = ±v̂ (the target line; the sign that agrees with h),
 *   h' = h turned about a toward t by at most κ Δ,
 *        Δ = angle(previous axis, a) + angle(previous view dir, view dir).
 *
 * LiSPSM then warps along the frame's y axis, oriented by σ = sign(y·v),
 * with the strength of γ_eff = asin|y·v| (lispsm.c): exactly [RHS]'s warp
 * when y = ±v̂, exactly uniform where y ⟂ v_perp, where σ may change sign
 * without a jump (the warp is uniform there).  swarp_setup uses the same
 * oriented warp: its blended frame near parallel can have y·v < 0 too, and
 * the first followed frame must continue it without a jump. */
#include <float.h>

#include "geometry/geometry_internal.h"

/* Rows of a previous light frame must be unit and orthogonal within this:
 * swarp_setup writes them to ~1e-16; 1e-6 only rejects what is not a
 * light frame at all (a matrix from elsewhere, a float round trip keeps
 * ~1e-7). */
#define SW_FOLLOW_ORTHO_TOL 1e-6

/* 1e-9 rad: far above the rounding of unit vectors (~1e-16), far below
 * anything visible (a 1e9-texel map would turn by one texel).  The
 * directions compared are projections normal to the axis, unit vectors
 * divided by their length s (sin of the angle to the axis, down to 1e-8),
 * so their rounding is a few eps/s: up to 2e-8 rad, above this bound, and
 * with this bound alone whether a frame followed with Δ ~ 0 "lagged" (a
 * light 1e-7 from the view: φ of 1e-9 to 3e-9) would be the rounding's
 * choice.  The bound used is this plus
 * SW_FOLLOW_ALIGNED_EPS eps/s of both projections (sw_follow_aligned_tol):
 * at most 7e-7 rad, below what the follow bound allows for rounding (1e-6,
 * tests/robust). */
#define SW_FOLLOW_ALIGNED 1e-9
#define SW_FOLLOW_ALIGNED_EPS 16.0

double sw_follow_aligned_tol(double s_h, double s_t) {
    return SW_FOLLOW_ALIGNED + SW_FOLLOW_ALIGNED_EPS * DBL_EPSILON * (1.0 / s_h + 1.0 / s_t);
}

double sw_follow_angle(swarp_vec3 a, swarp_vec3 b) {
    return atan2(sw_len_fast(sw_cross(a, b)), sw_dot(a, b));
}

swarp_vec3 sw_follow_turn(swarp_vec3 h, swarp_vec3 t, swarp_vec3 a, double budget, double aligned, int* lag) {
    swarp_vec3 c = sw_cross(h, t);
    double phi = atan2(sw_len_fast(c), sw_dot(h, t)); /* in [0, pi/2] as t·h >= 0 */
    *lag = 0;
    /* within `aligned` (sw_follow_aligned_tol) the frame is aligned:
     * rounding of a frame followed with Δ = 0 must not count as lagging */
    if (!(phi > budget) || phi < aligned) return t;
    *lag = 1;
    double k = sw_dot(a, c) < 0.0 ? -1.0 : 1.0; /* turn direction about a */
    swarp_vec3 ah = sw_cross(a, h);
    return sw_add(sw_scale(h, cos(budget)), sw_scale(ah, k * sin(budget)));
}

/* unit vector perpendicular to a (h projected), 0 if h is (nearly) along
 * a; *len: the projection's length (sin of the angle between h and a) */
static int sw_perp_unit_len(swarp_vec3 h, swarp_vec3 a, swarp_vec3* out, double* len) {
    swarp_vec3 p = sw_sub(h, sw_scale(a, sw_dot(h, a)));
    *len = sw_len_fast(p);
    /* below SW_FOLLOW_PERP_MIN the direction is rounding noise of a
     * previous axis 90° or more away: no usable transport (a teleport) */
    if (!(*len > SW_FOLLOW_PERP_MIN)) return 0;
    return sw_normalize_fast(p, out);
}
static int sw_perp_unit(swarp_vec3 h, swarp_vec3 a, swarp_vec3* out) {
    double len;
    return sw_perp_unit_len(h, a, out, &len);
}

swarp_status sw_follow_light_view(const swarp_camera* cam, swarp_vec3 origin, swarp_vec3 forward,
                                  const sw_follow* fw, swarp_mat4* out) {
    swarp_vec3 a, v, r, u, h, t;
    if (!sw_normalize_fast(forward, &a)) return SWARP_ERR_ZERO_VECTOR;
    sw_camera_basis(cam, &v, &r, &u);
    double s_h, s_t;
    int have_h = sw_perp_unit_len(fw->up, a, &h, &s_h);
    int have_t = sw_perp_unit_len(v, a, &t, &s_t); /* v̂: the aligned up [RHS] §3.2.1 */
    double delta = sw_follow_angle(fw->axis, a) + sw_follow_angle(fw->view, v);
    int lag = 0;
    if (have_t && have_h) {
        if (sw_dot(h, t) < 0.0) t = sw_scale(t, -1.0); /* ±v̂: the line, not the vector */
        h = sw_follow_turn(h, t, a, SWARP_FOLLOW_KAPPA * delta, sw_follow_aligned_tol(s_h, s_t), &lag);
    } else if (have_t) {
        h = t; /* the previous up is useless (axis turned by ~90° or more) */
    } else if (!have_h) {
        /* view and previous up both along a: the stateless frame */
        return sw_light_view(cam, origin, a, out);
    } /* else: the light is exactly on the view axis, no target: keep h */
    /* exact perpendicularity for the look-at */
    if (!sw_perp_unit(h, a, &h)) return sw_light_view(cam, origin, a, out);
    swarp_mat4 m;
    sw_look_at(origin, a, h, &m);
    if (!sw_look_at_finite(&m)) return SWARP_ERR_OVERFLOW; /* as sw_light_view */
    *out = m;
    return lag ? SWARP_INFO_FOLLOW_LAG : SWARP_OK;
}

swarp_status sw_warp_lispsm_oriented(const swarp_mat4* M, const swarp_mat4* M_inv, const swarp_camera* cam, double near,
                            double far, const swarp_vec3* points, size_t count, const swarp_vec3* nearest,
                            const swarp_warp_options* o, swarp_mat4* out_P, swarp_warp_info* out_info) {
    /* the sign of y·v (row 1 of M is the light view's up row, also for a
     * point light, whose P0 keeps x and y); the sign needs no unit v */
    const swarp_vec3 v = cam->dir;
    double vy = sw_at(M, 1, 0) * v.x + sw_at(M, 1, 1) * v.y + sw_at(M, 1, 2) * v.z;
    if (vy >= 0.0) return sw_warp_lispsm(M, M_inv, cam, near, far, points, count, nearest, o, out_P, out_info);
    /* σ = -1: warp along -y, i.e. in the frame turned by 180° about the
     * light axis (R = diag(-1, -1, 1, 1), R = R^-1), then turned back:
     * P = R P' R.  Where y ⟂ v the warp is uniform, and R U R = U for the
     * uniform warp up to the translation A_fit removes, so σ may flip there. */
    swarp_mat4 R, Mr, Mr_inv, Pr, RP;
    sw_identity(&R);
    sw_set(&R, 0, 0, -1.0);
    sw_set(&R, 1, 1, -1.0);
    sw_mul(&R, M, &Mr);
    sw_mul(M_inv, &R, &Mr_inv);
    swarp_status s = sw_warp_lispsm(&Mr, &Mr_inv, cam, near, far, points, count, nearest, o, &Pr, out_info);
    if (swarp_status_is_error(s)) return s;
    sw_mul(&R, &Pr, &RP);
    sw_mul(&RP, &R, out_P);
    return s;
}

/* The light camera of a previous PSM result in post-perspective space:
 * light_proj = A_fit·Q·P_c, so A_fit·Q = light_proj·P_c^-1 with P_c the
 * (slid-back) camera projection of that frame (near + δ = n_eye).  Rows 2
 * and 3 of A_fit·Q are multiples of the axis a, row 0 is a multiple of the
 * right vector e1 plus one of a (psm.c). */
static swarp_status sw_follow_psm(const swarp_setup_result* p, const swarp_camera* pc, sw_follow* out) {
    double N = p->n_eye, F = p->view_far + (p->n_eye - p->view_near);
    if (!sw_finite(N) || !sw_finite(F) || !sw_finite(p->view_near) || !sw_finite(p->view_far))
        return SWARP_ERR_NON_FINITE;
    if (!(N > 0.0 && F > N && p->view_near > 0.0 && N >= p->view_near)) return SWARP_ERR_FOLLOW_FRAME;
    if (!sw_mat_finite(&p->light_proj)) return SWARP_ERR_NON_FINITE;
    double ty = tan(0.5 * pc->fovy), tx = ty * pc->aspect;
    /* P_c^-1 maps (X, Y, Z, W) to (t_x X, t_y Y, -W, (Z + c22 W)/c23): the
     * x, y, z parts of the rows need only t_x, t_y and c23 */
    double c23 = -2.0 * F * N / (F - N);
    swarp_vec3 row[4];
    for (int i = 0; i < 4; ++i) {
        const swarp_mat4* m = &p->light_proj;
        row[i] = sw_v3(sw_at(m, i, 0) * tx, sw_at(m, i, 1) * ty, sw_at(m, i, 3) / c23);
    }
    if (!sw_finite(tx)) {
        /* aspect near DBL_MAX: t_x overflows (the rows would be inf/NaN
         * and the axis a "zero vector").  Only the rows' directions are
         * used: all divided by t_x, (m_i0, m_i1 / aspect, m_i3 / (c23 t_y
         * aspect)). */
        for (int i = 0; i < 4; ++i) {
            const swarp_mat4* m = &p->light_proj;
            row[i] = sw_v3(sw_at(m, i, 0), sw_at(m, i, 1) / pc->aspect, sw_at(m, i, 3) / c23 / ty / pc->aspect);
        }
    }
    swarp_vec3 a = sw_len_fast(row[3]) > sw_len_fast(row[2]) ? row[3] : row[2];
    if (!sw_normalize_fast(a, &a)) return SWARP_ERR_ZERO_VECTOR;
    swarp_vec3 e1;
    if (!sw_perp_unit(row[0], a, &e1)) return SWARP_ERR_FOLLOW_FRAME;
    out->axis = a;
    out->up = e1;
    return SWARP_OK;
}

/* The rotation rows of a previous light view, checked: finite, non-zero,
 * unit, orthogonal, right-handed. */
static swarp_status sw_follow_rows(const swarp_mat4* L, swarp_vec3 rows[3]) {
    for (int i = 0; i < 3; ++i) rows[i] = sw_v3(sw_at(L, i, 0), sw_at(L, i, 1), sw_at(L, i, 2));
    for (int i = 0; i < 3; ++i)
        if (!sw_finite3(&rows[i])) return SWARP_ERR_NON_FINITE;
    for (int i = 0; i < 3; ++i)
        if (!(sw_len_fast(rows[i]) > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    /* a rigid frame: unit rows, orthogonal, right-handed (PSM: the camera's
     * own view, also rigid) */
    for (int i = 0; i < 3; ++i) {
        if (fabs(sw_dot(rows[i], rows[i]) - 1.0) > SW_FOLLOW_ORTHO_TOL) return SWARP_ERR_FOLLOW_FRAME;
        if (fabs(sw_dot(rows[i], rows[(i + 1) % 3])) > SW_FOLLOW_ORTHO_TOL) return SWARP_ERR_FOLLOW_FRAME;
    }
    if (sw_dot(sw_cross(rows[0], rows[1]), rows[2]) < 0.0) return SWARP_ERR_FOLLOW_FRAME;
    return SWARP_OK;
}

swarp_status sw_follow_from_result(const swarp_setup_result* previous, const swarp_camera* cam,
                                   const swarp_camera* previous_cam, swarp_technique tech, sw_follow* out) {
    const swarp_camera* pc = previous_cam ? previous_cam : cam;
    swarp_vec3 rows[3];
    swarp_status st = sw_follow_rows(&previous->light_view, rows);
    if (st != SWARP_OK) return st;
    sw_follow fw;
    swarp_vec3 r, u;
    sw_camera_basis(pc, &fw.view, &r, &u);
    if (tech == SWARP_TECHNIQUE_PSM) {
        swarp_status s = sw_follow_psm(previous, pc, &fw);
        if (s != SWARP_OK) return s;
    } else {
        fw.axis = sw_scale(rows[2], -1.0); /* the look-at's z row is -forward */
        fw.up = rows[1];
    }
    *out = fw;
    return SWARP_OK;
}

/* [RHS] §3.2.1 light-space alignment, followed over time */
SWARP_API swarp_status swarp_focus_light_view_follow(const swarp_camera* cam, const swarp_light* light,
                                                     const swarp_vec3* axis, const swarp_camera* previous_cam,
                                                     const swarp_mat4* previous_view, swarp_mat4* out_view) {
    if (!previous_view) return swarp_focus_light_view(cam, light, axis, out_view);
    if (!cam || !light || !out_view) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    if (previous_cam) {
        s = sw_check_camera_shape(previous_cam);
        if (s != SWARP_OK) return s;
    }
    s = sw_check_light(light);
    if (s != SWARP_OK) return s;
    swarp_vec3 rows[3], r, u;
    s = sw_follow_rows(previous_view, rows);
    if (s != SWARP_OK) return s;
    sw_follow fw;
    sw_camera_basis(previous_cam ? previous_cam : cam, &fw.view, &r, &u);
    fw.axis = sw_scale(rows[2], -1.0);
    fw.up = rows[1];
    swarp_vec3 origin, forward;
    s = sw_light_origin_axis(cam, light, axis, &origin, &forward);
    if (s != SWARP_OK) return s;
    swarp_mat4 m;
    s = sw_follow_light_view(cam, origin, forward, &fw, &m);
    if (swarp_status_is_error(s)) return s;
    *out_view = m;
    return s;
}
