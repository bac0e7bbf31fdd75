/* Flicker reduction for uniform (light-space aligned) maps: the exact
 * solution (minimal sphere, constant world size, texel-snapped offset) and
 * the approximate solution (scale quantised to levels, snapped offset).
 * [RHS] §3.5 after ZZB09. */
#include "cascade/cascade_internal.h"
#include "common/depth_range.h"

#include <float.h>

_Static_assert(sizeof(swarp_stabilize_options) == 8 + 4 * sizeof(double) + 8 + 16,
               "swarp_stabilize_options size");
_Static_assert(sizeof(swarp_stabilize_report) == 10 * sizeof(double) + 8 + 16,
               "swarp_stabilize_report size");

/* [RHS] §3.5 exact solution: the split frustum is mirror-symmetric about two
 * planes through the view axis, so its (unique) minimal enclosing sphere is
 * centred on that axis.  At depth z the squared distances to the near and
 * far corners are (z - n)^2 + (n k)^2 and (f - z)^2 + (f k)^2, k^2 =
 * tan^2(fovy/2)(1 + aspect^2); they are equal at z0 = (n + f)(1 + k^2)/2.
 * The near-minus-far difference grows with z, so for z0 > f the far corner
 * circle alone decides and the centre sits at f. */
static void sw_min_sphere(const sw_cam_frame* fr, double n, double f, double* z_c,
                          double* r, double* r_centroid) {
    /* k = tan_half sqrt(1 + aspect^2) and f k as hypots: aspect ~ 1e167 or
     * DBL_MAX overflows k^2 although the sphere (radius ~ f k) is
     * representable for a small enough f.  For k >= 1, (n + f)(1 + k^2)/2 >= f:
     * the clamp below applies without forming k^2. */
    const double t = fr->tan_half, a = fr->aspect;
    const double k = hypot(t, t * a);
    /* f k directly (f t is subnormal for subnormal f and would keep few
     * bits); only when k itself overflows, f t first */
    const double fk = sw_finite(k) ? f * k : hypot(f * t, (f * t) * a);
    /* z0 = (n + f)(1 + k^2)/2 clamped to f, through its distance to the far
     * plane f - z0 = (f - n)/2 - (n + f) k^2/2, formed from f - n (exact for
     * n, f within a factor 2): with n, f one ulp apart the rounded z0 would
     * equal f and give a radius 0 */
    double d_far = k < 1.0 ? 0.5 * (f - n) - 0.5 * (n + f) * (k * k) : 0.0;
    if (!(d_far > 0.0)) d_far = 0.0;
    *z_c = f - d_far;
    *r = hypot(d_far, fk);
    /* f > n, so the exact radius is > 0; for n, f a few subnormal ulps
     * apart it is below half the smallest subnormal and rounds to 0: a
     * point, not an enclosing sphere.  Rounded up instead, to the smallest
     * positive double. */
    if (!(*r > 0.0)) *r = DBL_TRUE_MIN;
    /* Centroid of the 8 corners is on the axis at (n + f)/2; the far
     * corners are the farther ones.  Never below the minimal radius (it is
     * not, exactly; the rounding-up above may be). */
    if (r_centroid) *r_centroid = fmax(hypot(0.5 * (f - n), fk), *r);
}

/* The camera's frame, then the split range [n, f] checked (in that order). */
static swarp_status sw_frame_and_range(const swarp_camera* cam, double n, double f,
                                       sw_cam_frame* fr) {
    swarp_status st = sw_cam_frame_make(cam, fr);
    if (st != SWARP_OK) return st;
    if (!sw_finite(n) || !sw_finite(f)) return SWARP_ERR_NON_FINITE;
    if (!(n > 0.0) || !(f > n)) return SWARP_ERR_NEAR_FAR;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_stabilize_sphere(const swarp_camera* cam, double n_i, double f_i,
                                              swarp_vec3* out_center, double* out_radius,
                                              double* out_centroid_radius) {
    if (!cam || !out_center || !out_radius) return SWARP_ERR_NULL_POINTER;
    sw_cam_frame fr;
    swarp_status st = sw_frame_and_range(cam, n_i, f_i, &fr);
    if (st != SWARP_OK) return st;
    double z_c, r, rc;
    sw_min_sphere(&fr, n_i, f_i, &z_c, &r, &rc);
    const swarp_vec3 c = sw_add(fr.eye, sw_scale(fr.f, z_c));
    /* finite inputs, sphere beyond DBL_MAX (f tan(fovy/2) aspect, or eye +
     * f dir, too large): not representable */
    if (!sw_finite3(&c) || !sw_finite(r) || !sw_finite(rc)) return SWARP_ERR_OVERFLOW;
    *out_center = c;
    *out_radius = r;
    if (out_centroid_radius) *out_centroid_radius = rc;
    return SWARP_OK;
}

/* |d.y| above this (the light within ~8 degrees of vertical): the helper
 * axis of sw_light_basis is world x, not world y, which would be nearly
 * parallel to d. */
#define SW_STABILIZE_VERTICAL 0.99

/* Light basis from the light direction alone: forward d, right u, up v,
 * like a look-at with a fixed helper axis (world y, or world x when the light
 * is near vertical). */
static int sw_light_basis(const swarp_vec3* light_dir, swarp_vec3* u, swarp_vec3* v,
                          swarp_vec3* d) {
    if (!sw_normalize(*light_dir, d)) return 0;
    swarp_vec3 helper = fabs(d->y) > SW_STABILIZE_VERTICAL ? sw_v3(1, 0, 0) : sw_v3(0, 1, 0);
    if (!sw_normalize(sw_cross(*d, helper), u)) return 0;
    *v = sw_cross(*u, *d);
    return 1;
}

SWARP_API swarp_status swarp_stabilize_light_view(const swarp_vec3* light_dir, swarp_mat4* out_view) {
    if (!light_dir || !out_view) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite3(light_dir)) return SWARP_ERR_NON_FINITE;
    swarp_vec3 u, v, d;
    if (!sw_light_basis(light_dir, &u, &v, &d)) return SWARP_ERR_ZERO_VECTOR;
    swarp_mat4 m;
    sw_identity(&m);
    const swarp_vec3 rows[3] = {u, v, sw_scale(d, -1.0)};
    for (int r = 0; r < 3; ++r) {
        sw_set(&m, r, 0, rows[r].x);
        sw_set(&m, r, 1, rows[r].y);
        sw_set(&m, r, 2, rows[r].z);
    }
    *out_view = m;
    return SWARP_OK;
}

/* Map half-width that still covers an extent `e` after the centre moved by up
 * to half a texel: with texel = 2 h / res we need h - texel/2 >= e/2, i.e.
 * h >= (e/2) res/(res - 1). */
static double sw_padded_half(double e, double res) { return 0.5 * e * res / (res - 1.0); }

/* Bits of the binade kept by sw_round_up_coarse. */
#define SW_STABILIZE_COARSE_BITS 20

/* Round up to a multiple of 2^-20 of the value's binade: the exact
 * solution's size then stays bit-identical when the split range wobbles by a
 * few ulps (e.g. an adjusted near/far recomputed each frame), at a cost of
 * at most one part in 10^6 of the map. */
static double sw_round_up_coarse(double h) {
    int e;
    (void)frexp(h, &e);
    const double step = ldexp(1.0, e - SW_STABILIZE_COARSE_BITS);
    return ceil(h / step) * step;
}

/* Quantise a padded full size up to a whole number of level steps. */
static double sw_quantise(double size, double step, uint32_t* level) {
    double k = ceil(size / step);
    /* !(k >= 1), not k < 1: a NaN (step 0 or inf) must not reach the
     * uint32_t cast below (undefined behaviour; UBSan in the fuzz build) */
    if (!(k >= 1.0)) k = 1.0;
    *level = k > 4294967295.0 ? 4294967295u : (uint32_t)k;
    return k * step;
}

/* ZZB09's empirical number of scale levels, [RHS] §3.5. */
#define SW_STABILIZE_DEFAULT_LEVELS 64

/* Checks the options and resolves their defaults (mode NONE, 64 levels). */
static swarp_status sw_stabilize_options_resolve(const swarp_stabilize_options* opt,
                                                 swarp_stabilize_options* o) {
    memset(o, 0, sizeof *o);
    if (opt) *o = *opt;
    if (!sw_reserved_zero(o->_reserved, 4) || o->_reserved0 != 0) return SWARP_ERR_RESERVED_NONZERO;
    if (o->mode == SWARP_STABILIZE_DEFAULT) o->mode = SWARP_STABILIZE_NONE;
    if (o->mode != SWARP_STABILIZE_NONE && o->mode != SWARP_STABILIZE_SPHERE &&
        o->mode != SWARP_STABILIZE_LEVELS)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_light_depth_range_ok(o->depth)) return SWARP_ERR_UNKNOWN_ENUM;
    if (o->levels == 0) o->levels = SW_STABILIZE_DEFAULT_LEVELS;
    if (!sw_finite3(&o->origin) || !sw_finite(o->level_max_size)) return SWARP_ERR_NON_FINITE;
    if (o->level_max_size < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* Checks the camera, split range, light, resolution, body and scene box, in
 * that order; the body is needed by every mode but SPHERE. */
static swarp_status sw_stabilize_check(const swarp_camera* cam, double n_i, double f_i,
                                       const swarp_vec3* light_dir, const swarp_vec3* body_points,
                                       size_t body_count, const swarp_aabb* scene, uint32_t res,
                                       swarp_stabilize_mode mode, sw_cam_frame* fr) {
    swarp_status st = sw_frame_and_range(cam, n_i, f_i, fr);
    if (st != SWARP_OK) return st;
    if (!sw_finite3(light_dir)) return SWARP_ERR_NON_FINITE;
    if (res < 2) return SWARP_ERR_RESOLUTION;
    const int need_body = (mode != SWARP_STABILIZE_SPHERE);
    if (need_body && (!body_points || body_count == 0)) return SWARP_ERR_NULL_POINTER;
    if (body_points)
        for (size_t i = 0; i < body_count; ++i)
            if (!sw_finite3(&body_points[i])) return SWARP_ERR_NON_FINITE;
    if (scene && (!sw_finite3(&scene->min) || !sw_finite3(&scene->max))) return SWARP_ERR_NON_FINITE;
    if (scene && (scene->min.x > scene->max.x || scene->min.y > scene->max.y ||
                  scene->min.z > scene->max.z))
        return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

/* The map in light space relative to the origin O: centre (cx, cy),
 * half-widths (hx, hy), depth interval [t_min, t_max] along the light;
 * x = u.(p - O), y = v.(p - O), t = d.(p - O). */
typedef struct sw_stab_map {
    swarp_vec3 u, v, d;
    double cx, cy, hx, hy, t_min, t_max;
} sw_stab_map;

/* [RHS] §3.5 exact solution: the minimal sphere's bounding square, its size
 * padded for the half-texel offset and rounded to a coarse constant.  The
 * centre relative to O is (eye - O) + z_c f, not sphere_center - O: the
 * world centre eye + z_c f rounds at ulp(|eye|), which for a split small
 * against |eye| (z_c 1e-10 at |eye| 1e7) loses the offset along the axis
 * entirely, while eye - O is exact for O near the eye (Sterbenz) and
 * z_c f keeps full relative precision. */
static void sw_stabilize_sphere_map(const swarp_stabilize_report* rep, const sw_cam_frame* fr, double z_c,
                                    swarp_vec3 O, double dres, sw_stab_map* s) {
    const swarp_vec3 c = sw_add(sw_sub(fr->eye, O), sw_scale(fr->f, z_c));
    s->cx = sw_dot(c, s->u);
    s->cy = sw_dot(c, s->v);
    const double tc = sw_dot(c, s->d);
    s->hx = s->hy = sw_round_up_coarse(sw_padded_half(2.0 * rep->sphere_radius, dres));
    s->t_min = tc - rep->sphere_radius;
    s->t_max = tc + rep->sphere_radius;
}

/* The body's light-space bounds; unstabilised (NONE) the map fits them,
 * with LEVELS [RHS] §3.5's approximate solution quantises each padded size
 * up to a whole number of steps (the reference size / levels).  Returns
 * DEGENERATE for a body without extent, INFO_LEVEL_ABOVE_RANGE when a size
 * needs more levels than asked for. */
static swarp_status sw_stabilize_body_map(const swarp_vec3* body_points, size_t body_count,
                                          const swarp_stabilize_options* o, double dres,
                                          swarp_stabilize_report* rep, sw_stab_map* s) {
    double mn[3] = {INFINITY, INFINITY, INFINITY}, mx[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < body_count; ++i) {
        const swarp_vec3 q = sw_sub(body_points[i], o->origin);
        const double c3[3] = {sw_dot(q, s->u), sw_dot(q, s->v), sw_dot(q, s->d)};
        for (int k = 0; k < 3; ++k) {
            if (c3[k] < mn[k]) mn[k] = c3[k];
            if (c3[k] > mx[k]) mx[k] = c3[k];
        }
    }
    s->cx = 0.5 * (mn[0] + mx[0]);
    s->cy = 0.5 * (mn[1] + mx[1]);
    s->t_min = mn[2];
    s->t_max = mx[2];
    const double ex = mx[0] - mn[0], ey = mx[1] - mn[1];
    if (o->mode == SWARP_STABILIZE_NONE) {
        if (!(ex > 0.0) || !(ey > 0.0)) return SWARP_ERR_DEGENERATE;
        s->hx = 0.5 * ex;
        s->hy = 0.5 * ey;
        return SWARP_OK;
    }
    const double ref = o->level_max_size > 0.0 ? o->level_max_size : 2.0 * rep->sphere_radius;
    const double step = ref / (double)o->levels;
    s->hx = 0.5 * sw_quantise(2.0 * sw_padded_half(ex, dres), step, &rep->level_x);
    s->hy = 0.5 * sw_quantise(2.0 * sw_padded_half(ey, dres), step, &rep->level_y);
    if (rep->level_x > o->levels || rep->level_y > o->levels) return SWARP_INFO_LEVEL_ABOVE_RANGE;
    return SWARP_OK;
}

/* How far toward the light the depth interval reaches, relative to the
 * map's own size (its width, height and the body's depth extent): the
 * bound swarp_setup puts on B's sweep (SW_SWEEP_REL_MAX in
 * src/geometry/body.c), for the same reason.  A window 1e10 times the
 * receivers' size leaves them about 1e-6 of their size in double depth
 * (eps times 1e10) and nothing in a float32 buffer; an "unbounded" box
 * face (1e19, FLT_MAX, DBL_MAX) would make it 1e28..inf.  Casters beyond
 * are left out of the window (SWARP_INFO_CASTERS_CLAMPED): a renderer
 * with depth clamping draws them at the near plane, where they still
 * shadow every receiver behind them, as with pancaking. */
#define SW_STAB_CASTER_REL_MAX 1e10

/* The depth interval: extended toward the light to the scene box (casters
 * in front of the split) up to SW_STAB_CASTER_REL_MAX times the map's size
 * (*clamped when a corner lies beyond, or its t overflows), and opened when
 * the body is flat across the light; *dt = t_max - t_min and *t_sum =
 * t_max + t_min. */
static void sw_stabilize_depth(const swarp_aabb* scene, swarp_vec3 O, double texel, sw_stab_map* s,
                               double* dt_out, double* t_sum_out, int* clamped) {
    *clamped = 0;
    if (scene) {
        /* the size by the map's extents: the body's depth extent can be 0
         * (flat across the light), the width never is (hx, hy > 0) */
        const double size = fmax(2.0 * fmax(s->hx, s->hy), s->t_max - s->t_min);
        const double t_lo = s->t_max - SW_STAB_CASTER_REL_MAX * size;
        for (int k = 0; k < 8; ++k) {
            const swarp_vec3 q = sw_v3(k & 1 ? scene->max.x : scene->min.x,
                                       k & 2 ? scene->max.y : scene->min.y,
                                       k & 4 ? scene->max.z : scene->min.z);
            const double t = sw_dot(sw_sub(q, O), s->d);
            if (!(t >= t_lo)) { /* beyond the bound, or -inf / NaN from overflow */
                *clamped = 1;
                s->t_min = fmin(s->t_min, t_lo);
            } else if (t < s->t_min) {
                s->t_min = t;
            }
        }
    }
    double dt = s->t_max - s->t_min, t_sum = s->t_max + s->t_min;
    if (!(s->t_max > s->t_min)) {
        /* A body flat across the light: give depth one texel either side,
         * and at least one ulp of t.  The ulp is taken exactly (the
         * difference of neighbours), not from whether t -+ texel rounds
         * away from t: with the texel between half an ulp and an ulp (a
         * 1e-5 split at a 1e6 origin: texel 8.5e-11, ulp 1.2e-10) that
         * decision would be the rounding mode's, and the depth row 2/dt
         * would move by a third between modes. */
        const double t = s->t_min, ulp_t = nextafter(fabs(t), INFINITY) - fabs(t);
        const double half = fmax(texel, ulp_t);
        s->t_min = t - half;
        s->t_max = t + half;
        /* extent and sum from t and the texel, not from the rounded t -+
         * texel: with the texel far below |t| (a split at a 1e6 offset) that
         * difference carries ulp(t)/texel of relative error, whose sign and
         * size the caller's rounding mode would decide */
        dt = 2.0 * half;
        t_sum = 2.0 * t;
        /* the step is one ulp at least, so t_max > t > t_min in every
         * rounding mode; what is left for this guard is a t at the end of
         * the double range (its ulp is inf) or a subnormal step under DAZ */
        if (!(s->t_max > s->t_min) || !(s->t_min < t) || !(s->t_max > t)) {
            s->t_min = nextafter(t, -INFINITY);
            s->t_max = nextafter(t, INFINITY);
            dt = s->t_max - s->t_min;
            t_sum = s->t_max + s->t_min;
        }
    }
    *dt_out = dt;
    *t_sum_out = t_sum;
}

/* clip = A_fit-style scale/translate of light coordinates ([RHS] (3.1)). */
static void sw_stabilize_matrix(const sw_stab_map* s, double dt, double t_sum, swarp_depth_range depth,
                                swarp_mat4* m) {
    const int zero_one = sw_depth_zero_based(depth);
    const double za = zero_one ? 1.0 / dt : 2.0 / dt;
    const double zb = zero_one ? -s->t_min / dt : -t_sum / dt;
    sw_identity(m);
    const swarp_vec3 rows[3] = {sw_scale(s->u, 1.0 / s->hx), sw_scale(s->v, 1.0 / s->hy), sw_scale(s->d, za)};
    const double trans[3] = {-s->cx / s->hx, -s->cy / s->hy, zb};
    for (int r = 0; r < 3; ++r) {
        sw_set(m, r, 0, rows[r].x);
        sw_set(m, r, 1, rows[r].y);
        sw_set(m, r, 2, rows[r].z);
        sw_set(m, r, 3, trans[r]);
    }
    sw_depth_reverse_if(depth, m);
}

SWARP_API swarp_status swarp_stabilize_directional(const swarp_camera* cam, double n_i, double f_i,
                                                   const swarp_vec3* light_dir,
                                                   const swarp_vec3* body_points, size_t body_count,
                                                   const swarp_aabb* scene, uint32_t res,
                                                   const swarp_stabilize_options* opt,
                                                   swarp_mat4* out_matrix,
                                                   swarp_stabilize_report* out_report) {
    if (!cam || !light_dir || !out_matrix) return SWARP_ERR_NULL_POINTER;
    swarp_stabilize_options o;
    swarp_status st = sw_stabilize_options_resolve(opt, &o);
    if (st != SWARP_OK) return st;
    sw_cam_frame fr;
    st = sw_stabilize_check(cam, n_i, f_i, light_dir, body_points, body_count, scene, res, o.mode, &fr);
    if (st != SWARP_OK) return st;
    sw_stab_map s;
    if (!sw_light_basis(light_dir, &s.u, &s.v, &s.d)) return SWARP_ERR_ZERO_VECTOR;

    swarp_stabilize_report rep;
    memset(&rep, 0, sizeof rep);
    double z_c;
    sw_min_sphere(&fr, n_i, f_i, &z_c, &rep.sphere_radius, &rep.centroid_radius);
    rep.sphere_center = sw_add(fr.eye, sw_scale(fr.f, z_c));
    const double ratio = rep.sphere_radius / rep.centroid_radius;
    rep.area_saved = 1.0 - ratio * ratio;

    const double dres = (double)res;
    swarp_status info = SWARP_OK;
    if (o.mode == SWARP_STABILIZE_SPHERE)
        sw_stabilize_sphere_map(&rep, &fr, z_c, o.origin, dres, &s);
    else
        info = sw_stabilize_body_map(body_points, body_count, &o, dres, &rep, &s);
    if (swarp_status_is_error(info)) return info;
    rep.texel_size_x = 2.0 * s.hx / dres;
    rep.texel_size_y = 2.0 * s.hy / dres;
    if (o.mode != SWARP_STABILIZE_NONE) {
        /* the offset problem: the map centre moves in whole texels only.
         * round(), not nearbyint(): the nearest whole texel whatever the
         * caller's rounding mode (nearbyint rounding upward is ceil, and the
         * map would then miss up to a whole texel of the sphere) */
        s.cx = round(s.cx / rep.texel_size_x) * rep.texel_size_x;
        s.cy = round(s.cy / rep.texel_size_y) * rep.texel_size_y;
    }
    rep.offset_x = s.cx;
    rep.offset_y = s.cy;
    double dt, t_sum;
    int clamped = 0;
    sw_stabilize_depth(scene, o.origin, rep.texel_size_x, &s, &dt, &t_sum, &clamped);
    /* the bound on the coverage outranks the level report */
    if (clamped) info = SWARP_INFO_CASTERS_CLAMPED;
    swarp_mat4 m;
    sw_stabilize_matrix(&s, dt, t_sum, o.depth, &m);
    /* every input was checked finite above: a non-finite matrix or texel size
     * here is a result beyond DBL_MAX (coordinates near DBL_MAX, or 1/extent
     * of a subnormal extent), not representable: the documented OVERFLOW */
    if (!sw_mat_finite(&m) || !sw_finite(rep.texel_size_x) || !sw_finite(rep.texel_size_y))
        return SWARP_ERR_OVERFLOW;
    *out_matrix = m;
    if (out_report) *out_report = rep;
    return info;
}

SWARP_API swarp_status swarp_stabilize_snap_matrix(const swarp_mat4* m, double res_s, double res_t,
                                                   const swarp_vec3* origin, swarp_mat4* out) {
    if (!m || !origin || !out) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(m) || !sw_finite3(origin)) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(res_s) || !sw_finite(res_t) || !(res_s > 0.0) || !(res_t > 0.0))
        return SWARP_ERR_RESOLUTION;
    /* A projective last row (w depends on the point) means a warped map:
     * exactly zero is required, the uniform maps of this library and of
     * every ortho() have it. */
    if (m->m[3] != 0.0 || m->m[7] != 0.0 || m->m[11] != 0.0) return SWARP_ERR_STABILIZE_WARPED;
    const double w = m->m[15];
    if (w == 0.0) return SWARP_ERR_SINGULAR;
    /* texel coordinate of the origin; move it to the nearest whole texel */
    const swarp_vec4 h = sw_xform_point(m, *origin);
    const double s = (h.x / w + 1.0) * 0.5 * res_s, t = (h.y / w + 1.0) * 0.5 * res_t;
    /* round(), not nearbyint(): the nearest corner in every rounding mode */
    const double ds = round(s) - s, dt = round(t) - t;
    swarp_mat4 r = *m;
    r.m[12] += 2.0 * ds / res_s * w;
    r.m[13] += 2.0 * dt / res_t * w;
    if (!sw_mat_finite(&r)) return SWARP_ERR_NON_FINITE;
    *out = r;
    return SWARP_OK;
}
