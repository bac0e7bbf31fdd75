/* Light space and focusing: the light view with light-space alignment
 * ([RHS] §3.2.1, [WS06]) and its continuous fallback near γ = 0, and the
 * focusing matrix A_fit of [RHS] (3.1). */
#include <float.h>

#include "common/depth_range.h"
#include "geometry/geometry_internal.h"

/* u·o for a unit u: the terms of an origin near DBL_MAX overflow although
 * the sum may not; then it is summed at a quarter scale (exact: powers of
 * two), and is +-inf only when |u·o| itself exceeds DBL_MAX. */
static double sw_look_at_dot(swarp_vec3 u, swarp_vec3 o) {
    double d = sw_dot(u, o);
    if (sw_finite(d)) return d;
    double q = sw_dot(u, sw_scale(o, 0.25));
    return fabs(q) <= 0.25 * DBL_MAX ? 4.0 * q : q * INFINITY;
}

/* Right-handed look-at: the view looks down -z, +y is up_unit (already
 * perpendicular to forward_unit), origin maps to 0. */
void sw_look_at(swarp_vec3 origin, swarp_vec3 f, swarp_vec3 up, swarp_mat4* out) {
    swarp_vec3 s = sw_cross(f, up); /* right */
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    sw_set(&m, 0, 0, s.x), sw_set(&m, 0, 1, s.y), sw_set(&m, 0, 2, s.z);
    sw_set(&m, 1, 0, up.x), sw_set(&m, 1, 1, up.y), sw_set(&m, 1, 2, up.z);
    sw_set(&m, 2, 0, -f.x), sw_set(&m, 2, 1, -f.y), sw_set(&m, 2, 2, -f.z);
    sw_set(&m, 0, 3, -sw_look_at_dot(s, origin));
    sw_set(&m, 1, 3, -sw_look_at_dot(up, origin));
    sw_set(&m, 2, 3, sw_look_at_dot(f, origin));
    sw_set(&m, 3, 3, 1.0);
    *out = m;
}

int sw_look_at_finite(const swarp_mat4* m) {
    return sw_finite(m->m[12]) && sw_finite(m->m[13]) && sw_finite(m->m[14]);
}

/* The inverse of a rigid look-at L (rows R, translation t): R^T and -R^T t.
 * Exact where a general inversion rounds, and defined for every finite L:
 * a general inversion of P0 L for a point light 1e308 away (translations
 * near DBL_MAX) reports the matrix singular. */
void sw_rigid_inverse(const swarp_mat4* L, swarp_mat4* out) {
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) sw_set(&m, r, c, sw_at(L, c, r));
    for (int r = 0; r < 3; ++r)
        sw_set(&m, r, 3,
               -(sw_at(L, 0, r) * sw_at(L, 0, 3) + sw_at(L, 1, r) * sw_at(L, 1, 3) + sw_at(L, 2, r) * sw_at(L, 2, 3)));
    sw_set(&m, 3, 3, 1.0);
    *out = m;
}
/* Rows of a rigid look-at are orthonormal to the rounding of unit vectors
 * (~1e-16); 1e-9 accepts those and rejects any matrix that is not rigid
 * (a scale or a shear by more than that). */
#define SW_RIGID_TOL 1e-9

/* Is m a rigid motion (rows of its 3x3 orthonormal to SW_RIGID_TOL, last
 * row 0 0 0 1): a look-at of swarp_focus_light_view? */
int sw_is_rigid(const swarp_mat4* m) {
    if (sw_at(m, 3, 0) != 0.0 || sw_at(m, 3, 1) != 0.0 || sw_at(m, 3, 2) != 0.0 || sw_at(m, 3, 3) != 1.0) return 0;
    for (int a = 0; a < 3; ++a)
        for (int b = a; b < 3; ++b) {
            double d = sw_at(m, a, 0) * sw_at(m, b, 0) + sw_at(m, a, 1) * sw_at(m, b, 1) + sw_at(m, a, 2) * sw_at(m, b, 2);
            if (!(fabs(d - (a == b)) <= SW_RIGID_TOL)) return 0;
        }
    return 1;
}

/* The aligned up vector: normalize(v_perp + w(sin γ) r_perp), see the
 * header (SWARP_FOCUS_BLEND_SIN).  Returns 1 when the blend is active. */
static int sw_aligned_up(const swarp_camera* cam, swarp_vec3 a, swarp_vec3* up) {
    swarp_vec3 v, r, cu;
    sw_camera_basis(cam, &v, &r, &cu);
    swarp_vec3 v_perp = sw_sub(v, sw_scale(a, sw_dot(v, a)));
    double s = sw_len_fast(v_perp); /* sin γ */
    int blend = s < SWARP_FOCUS_BLEND_SIN;
    swarp_vec3 u = v_perp;
    if (blend) {
        double t = 1.0 - s / SWARP_FOCUS_BLEND_SIN;
        double w = SWARP_FOCUS_BLEND_WEIGHT * t * t; /* C1 at s = SWARP_FOCUS_BLEND_SIN */
        swarp_vec3 r_perp = sw_sub(r, sw_scale(a, sw_dot(r, a)));
        u = sw_add(v_perp, sw_scale(r_perp, w));
    }
    if (!sw_normalize_fast(u, up)) {
        /* the field's single zero (measure zero): any perpendicular works */
        swarp_vec3 ref = fabs(a.x) < SW_REF_AXIS_MAX ? sw_v3(1, 0, 0) : sw_v3(0, 1, 0);
        sw_normalize_fast(sw_cross(a, ref), up);
    }
    /* exact perpendicularity for the look-at */
    sw_normalize_fast(sw_sub(*up, sw_scale(a, sw_dot(*up, a))), up);
    return blend;
}

/* ---- the map's rotation about the light axis near parallel light ---------
 * Within the blend zone (sin γ < SWARP_FOCUS_BLEND_SIN) the view direction
 * gives the light plane no useful axis: perspective aliasing along v_perp
 * is negligible there (LiSPSM fades to uniform as γ -> 0, [RHS] §3.2.1),
 * and what is left is how much of the map B's footprint fills.  A uniform
 * focused map (A_fit of [RHS] (3.1)) spends one texel on (extent_x /
 * res_s) x (extent_y / res_t) of the light plane: the texel area is the
 * area of B's bounding rectangle in the light plane over the texel count,
 * minimal for the minimum-area enclosing rectangle.  That rectangle has one
 * side on an edge of the convex hull of B's projection (Freeman and
 * Shapira 1975), found exactly by rotating calipers over the hull. */

/* Points of B projected on the light plane, at most SWARP_BODY_MAX_POINTS. */
#define SW_HULL_MAX SWARP_BODY_MAX_POINTS

/* z-component of (b - a) x (c - a): > 0 for a left turn a -> b -> c */
static double sw_turn(const double a[2], const double b[2], const double c[2]) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Andrew's monotone chain: the convex hull of p[0..n) counter-clockwise in
 * h (collinear points dropped); returns its vertex count (< 3: no area).
 * p is sorted in place (insertion sort: n <= SW_HULL_MAX, and equal keys
 * keep their order, so the hull is a function of the input alone). */
static size_t sw_hull_2d(double (*p)[2], size_t n, double (*h)[2]) {
    for (size_t i = 1; i < n; ++i) {
        double q0 = p[i][0], q1 = p[i][1];
        size_t j = i;
        while (j > 0 && (p[j - 1][0] > q0 || (p[j - 1][0] == q0 && p[j - 1][1] > q1))) {
            p[j][0] = p[j - 1][0], p[j][1] = p[j - 1][1];
            --j;
        }
        p[j][0] = q0, p[j][1] = q1;
    }
    size_t k = 0;
    for (size_t i = 0; i < n; ++i) { /* lower chain */
        while (k >= 2 && sw_turn(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
        h[k][0] = p[i][0], h[k][1] = p[i][1], ++k;
    }
    for (size_t i = n - 1, t = k + 1; i-- > 0;) { /* upper chain */
        while (k >= t && sw_turn(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
        h[k][0] = p[i][0], h[k][1] = p[i][1], ++k;
    }
    return k > 1 ? k - 1 : k; /* the last point repeats the first */
}

/* The unit direction e (in the 2-D frame) of a side of the minimum-area
 * rectangle enclosing the hull h[0..k): each edge's rectangle from the
 * extents along the edge and its normal.  O(k^2) for k <= SW_HULL_MAX
 * vertices (a few thousand products) rather than the O(k) caliper walk:
 * the same minimum, and no pointer bookkeeping to get wrong at ties. */
static int sw_min_area_side(double (*h)[2], size_t k, double e_out[2]) {
    double best = INFINITY;
    int found = 0;
    for (size_t i = 0; i < k; ++i) {
        const size_t j = i + 1 == k ? 0 : i + 1;
        double ex = h[j][0] - h[i][0], ey = h[j][1] - h[i][1];
        const double len = hypot(ex, ey);
        if (!(len > 0.0)) continue;
        ex /= len, ey /= len;
        double lo_e = INFINITY, hi_e = -INFINITY, lo_n = INFINITY, hi_n = -INFINITY;
        for (size_t q = 0; q < k; ++q) {
            const double de = h[q][0] * ex + h[q][1] * ey, dn = h[q][1] * ex - h[q][0] * ey;
            lo_e = fmin(lo_e, de), hi_e = fmax(hi_e, de);
            lo_n = fmin(lo_n, dn), hi_n = fmax(hi_n, dn);
        }
        const double area = (hi_e - lo_e) * (hi_n - lo_n);
        if (area < best) best = area, e_out[0] = ex, e_out[1] = ey, found = 1;
    }
    return found && best > 0.0;
}

/* The up vector of the minimum-area rectangle of B's light-plane footprint.
 * Its axis is the side (e or e⊥) most nearly along ±v_perp, so that a
 * warp (LiSPSM warps along +y) keeps the view's depth axis and a footprint
 * whose best rectangle is the view-aligned one keeps that orientation; its
 * sign is the one toward a reference ref (v_perp itself
 * vanishes and reverses at γ = 0): ref = v_perp + w (r_perp + u_perp) with
 * the blend's w, whose zero lies off both the v-r and the v-u plane, the
 * planes a light passing the view axis crosses in the usual walks (the sun
 * ahead as the camera pitches or yaws).  A function of the input alone: the
 * same B and camera give the same map, but not a continuous one (see
 * docs/geometry.md; swarp_setup_follow keeps the frame coherent).  Leaves
 * *up as it is when B projects to fewer than three non-collinear points
 * (no area to minimise). */
static int sw_min_area_up(swarp_vec3 a, swarp_vec3 v_perp, swarp_vec3 ref, const swarp_vec3* B, size_t nb,
                          swarp_vec3* up) {
    if (!B || nb < 3 || nb > SW_HULL_MAX) return 0;
    const swarp_vec3 u0 = *up, x0 = sw_cross(a, u0); /* light-plane frame: x0 right, u0 up */
    double p[SW_HULL_MAX][2], h[SW_HULL_MAX + 1][2];
    for (size_t i = 0; i < nb; ++i) p[i][0] = sw_dot(B[i], x0), p[i][1] = sw_dot(B[i], u0);
    /* centred on the first point: the footprint's size, not B's distance
     * from the origin, sets the rounding of the edge directions */
    const double c0 = p[0][0], c1 = p[0][1];
    for (size_t i = 0; i < nb; ++i) p[i][0] -= c0, p[i][1] -= c1;
    const size_t k = sw_hull_2d(p, nb, h);
    double e[2];
    if (k < 3 || !sw_min_area_side(h, k, e)) return 0;
    /* v_perp in the 2-D frame; the side e⊥ = (-e_1, e_0) */
    const double v0 = sw_dot(v_perp, x0), v1 = sw_dot(v_perp, u0);
    double ax0 = e[0], ax1 = e[1];
    if (fabs(-e[1] * v0 + e[0] * v1) > fabs(e[0] * v0 + e[1] * v1)) ax0 = -e[1], ax1 = e[0];
    if (ax0 * sw_dot(ref, x0) + ax1 * sw_dot(ref, u0) < 0.0) ax0 = -ax0, ax1 = -ax1;
    swarp_vec3 u = sw_add(sw_scale(x0, ax0), sw_scale(u0, ax1));
    swarp_vec3 un;
    if (!sw_normalize_fast(sw_sub(u, sw_scale(a, sw_dot(u, a))), &un)) return 0;
    *up = un;
    return 1;
}

/* The fraction of the blend zone (in sin γ, at its outer edge) over which
 * the rectangle's up eases into v_perp: 20 % (sin γ from 0.8 sin 10° to
 * sin 10°, γ from 7.99° to 10°) keeps most of the zone for the rectangle. */
#define SW_MIN_AREA_EASE 0.2

/* The light view; with B (nb points), near parallel light its rotation
 * about the axis is the minimum-area rule above, else the aligned up. */
swarp_status sw_light_view_body(const swarp_camera* cam, swarp_vec3 origin, swarp_vec3 forward, const swarp_vec3* B,
                                size_t nb, swarp_mat4* out) {
    swarp_vec3 a = {0, 0, -1}, up = {0, 1, 0};
    if (!sw_normalize_fast(forward, &a)) return SWARP_ERR_ZERO_VECTOR;
    int blend = sw_aligned_up(cam, a, &up);
    if (blend) {
        swarp_vec3 v, r, cu;
        sw_camera_basis(cam, &v, &r, &cu);
        const swarp_vec3 v_perp = sw_sub(v, sw_scale(a, sw_dot(v, a)));
        const double t = 1.0 - sw_len_fast(v_perp) / SWARP_FOCUS_BLEND_SIN;
        /* the sign reference: v_perp + w (r_perp + u_perp), w as the blend's */
        swarp_vec3 ru = sw_add(r, cu);
        ru = sw_sub(ru, sw_scale(a, sw_dot(ru, a)));
        const swarp_vec3 ref = sw_add(v_perp, sw_scale(ru, SWARP_FOCUS_BLEND_WEIGHT * t * t));
        const int turned = sw_min_area_up(a, v_perp, ref, B, nb, &up);
        /* toward the zone's edge the rectangle's up turns to v_perp's
         * (the up outside the zone), so that a light leaving the zone
         * does not jump: linear in sin γ over the last SW_MIN_AREA_EASE
         * of the zone, where v_perp is at least 0.8 sin 10° long and
         * within 45° of the rectangle's up (the side nearest ±v_perp,
         * signed toward ref ≈ v_perp there), so the sum never vanishes */
        const double s_g = sw_len_fast(v_perp), e0 = (1.0 - SW_MIN_AREA_EASE) * SWARP_FOCUS_BLEND_SIN;
        swarp_vec3 va, ue;
        if (turned && s_g > e0 && sw_normalize_fast(v_perp, &va)) {
            const double w = (s_g - e0) / (SWARP_FOCUS_BLEND_SIN - e0);
            if (sw_normalize_fast(sw_add(sw_scale(up, 1.0 - w), sw_scale(va, w)), &ue)) up = ue;
        }
    }
    swarp_mat4 m;
    sw_look_at(origin, a, up, &m);
    /* an origin near DBL_MAX: its distance along a row (the translation)
     * can exceed DBL_MAX; the view is not representable */
    if (!sw_look_at_finite(&m)) return SWARP_ERR_OVERFLOW;
    *out = m;
    return blend ? SWARP_INFO_LIGHT_PARALLEL : SWARP_OK;
}

swarp_status sw_light_view(const swarp_camera* cam, swarp_vec3 origin, swarp_vec3 forward, swarp_mat4* out) {
    return sw_light_view_body(cam, origin, forward, NULL, 0, out);
}

/* The light view's origin and the direction it looks along, as
 * swarp_focus_light_view documents them (shared with its follow twin):
 * directional lights look along their direction from the eye; point lights
 * along the caller's axis, else the spot direction, else toward the eye. */
swarp_status sw_light_origin_axis(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* axis,
                                  swarp_vec3* origin, swarp_vec3* forward) {
    if (light->type != SWARP_LIGHT_POINT) {
        *origin = cam->eye;
        *forward = light->direction;
        return SWARP_OK;
    }
    *origin = light->position;
    if (axis) {
        if (!sw_finite3(axis)) return SWARP_ERR_NON_FINITE;
        *forward = *axis;
    } else if (light->cone_angle > 0.0) {
        *forward = light->direction;
    } else {
        *forward = sw_sub(cam->eye, light->position);
    }
    return sw_len_fast(*forward) > 0.0 ? SWARP_OK : SWARP_ERR_ZERO_VECTOR;
}

SWARP_API swarp_status swarp_focus_light_view(const swarp_camera* cam, const swarp_light* light,
                                              const swarp_vec3* axis, swarp_mat4* out_view) {
    if (!cam || !light || !out_view) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    s = sw_check_light(light);
    if (s != SWARP_OK) return s;
    swarp_vec3 origin, forward;
    s = sw_light_origin_axis(cam, light, axis, &origin, &forward);
    if (s != SWARP_OK) return s;
    swarp_mat4 m;
    s = sw_light_view(cam, origin, forward, &m);
    if (swarp_status_is_error(s)) return s;
    *out_view = m;
    return s;
}

/* ---- A_fit ------------------------------------------------------------------ */

/* An extent below this fraction of its coordinates' magnitude or of the
 * widest extent is flat (SWARP_INFO_FLAT_EXTENT).  Coordinates carry a few
 * eps (1e-16) of the magnitudes they were computed from; 1e-12 leaves a
 * factor 1e4 for that, and an aspect ratio of 1e12 is far beyond what a
 * shadow map (or a float depth buffer, 2^-24) resolves. */
#define SW_FIT_FLAT_REL 1e-12
/* The width given to an all-flat B, relative to its coordinates' magnitude
 * where 1 is below their rounding: 1e-6 is 1e10 ulps, far above the noise,
 * and still a point at the map's resolution. */
#define SW_FIT_FLAT_WIDTH_REL 1e-6

static int sw_extent(const swarp_mat4* m, const swarp_vec3* pts, size_t n, double lo[3], double hi[3]) {
    double lx = INFINITY, ly = INFINITY, lz = INFINITY, hx = -INFINITY, hy = -INFINITY, hz = -INFINITY;
    int ok = 1;
    for (size_t i = 0; i < n; ++i) {
        swarp_vec4 h = sw_xform_point(m, pts[i]);
        ok &= h.w > 0.0;
        double iw = 1.0 / h.w, x = h.x * iw, y = h.y * iw, z = h.z * iw;
        lx = x < lx ? x : lx, hx = x > hx ? x : hx; /* branch-free min/max */
        ly = y < ly ? y : ly, hy = y > hy ? y : hy;
        lz = z < lz ? z : lz, hz = z > hz ? z : hz;
    }
    lo[0] = lx, lo[1] = ly, lo[2] = lz;
    hi[0] = hx, hi[1] = hy, hi[2] = hz;
    return ok;
}

/* The world matrix m' = A m T(-eye) of a camera-relative m is rounded
 * where the eye is folded in (its last column: sums of products of size
 * |m_rj| |eye_j|) and in the products before: the same as moving the point
 * by a few eps (|eye_j| + |p_j|) along each axis j.  SW_WORLD_ROUND_EPS
 * eps: the fold's three products and two sums, the products A m and
 * (A P) L (three sums each), and the coordinates' own rounding. */
#define SW_WORLD_ROUND_EPS 16.0

void sw_world_rounding_pad(const swarp_mat4* m, const swarp_vec3* pts, size_t n, swarp_vec3 eye, double pad[3]) {
    pad[0] = pad[1] = pad[2] = 0.0;
    const double ae[3] = {fabs(eye.x), fabs(eye.y), fabs(eye.z)};
    for (size_t i = 0; i < n; ++i) {
        const swarp_vec4 h = sw_xform_point(m, pts[i]);
        const double c[3] = {h.x / h.w, h.y / h.w, h.z / h.w}, p[3] = {pts[i].x, pts[i].y, pts[i].z};
        for (int k = 0; k < 3; ++k) {
            /* first order: d(X/W)/dp_j = (m_kj - (X/W) m_3j) / W */
            double s = 0.0;
            for (int j = 0; j < 3; ++j)
                s += fabs(sw_at(m, k, j) - c[k] * sw_at(m, 3, j)) * (ae[j] + fabs(p[j]));
            s *= SW_WORLD_ROUND_EPS * DBL_EPSILON / fabs(h.w);
            pad[k] = s > pad[k] ? s : pad[k];
        }
    }
}

/* A pad below this fraction of the extent is left out: 1/1000 of the 1e-6
 * of the map the fit promises (SW_REL_RESOLVE), it cannot uncover a point,
 * and ordinary maps (pads of 1e-15) keep their bits. */
#define SW_FIT_PAD_MIN_REL 1e-9

swarp_status sw_focus_fit(const swarp_mat4* m, const swarp_vec3* pts, size_t n, const swarp_vec3* zpts,
                          size_t zn, swarp_depth_range dr, const double pad[3], swarp_mat4* out) {
    double lo[3], hi[3], zlo[3], zhi[3];
    if (!sw_extent(m, pts, n, lo, hi)) return SWARP_ERR_DEGENERATE;
    if (zpts) {
        if (!sw_extent(m, zpts, zn, zlo, zhi)) return SWARP_ERR_DEGENERATE;
        lo[2] = zlo[2];
        hi[2] = zhi[2];
    }
    for (int k = 0; k < 3; ++k)
        if (!sw_finite(lo[k]) || !sw_finite(hi[k])) return SWARP_ERR_DEGENERATE;
    /* A zero extent (flat B seen edge-on, or all depths equal) gets the
     * largest other extent as its width, centred on the value: finite, and
     * the status says so. */
    double w[3], wmax = 0.0;
    for (int k = 0; k < 3; ++k) {
        w[k] = hi[k] - lo[k];
        if (w[k] > wmax) wmax = w[k];
    }
    if (!(wmax > 0.0)) wmax = 1.0;
    swarp_status st = SWARP_OK;
    /* Every extent flat (B one point, to the rounding of its coordinates):
     * the widest extent is itself noise (1 ulp of 5.5 stretched over the
     * map would put B's only point anywhere in it, x = -1.4 say); the width
     * is 1 as documented, or SW_FIT_FLAT_WIDTH_REL of the coordinates where
     * 1 is below their rounding. */
    {
        int flat_all = 1;
        double cmag = 0.0;
        for (int k = 0; k < 3; ++k) {
            double mag = fmax(fmax(fabs(lo[k]), fabs(hi[k])), wmax);
            flat_all &= !(w[k] > SW_FIT_FLAT_REL * mag) || !(w[k] > 0.0);
            cmag = fmax(cmag, fmax(fabs(lo[k]), fabs(hi[k])));
        }
        if (flat_all) wmax = fmax(1.0, SW_FIT_FLAT_WIDTH_REL * cmag);
    }
    for (int k = 0; k < 3; ++k) {
        /* below SW_FIT_FLAT_REL of the value's magnitude, or of the widest
         * extent, the width is rounding noise: fitted, the noise would fill
         * the map and points of B computed along another path (the final
         * matrix) land outside it */
        double mag = fmax(fmax(fabs(lo[k]), fabs(hi[k])), wmax);
        if (!(w[k] > SW_FIT_FLAT_REL * mag) || !(w[k] > 0.0)) {
            double c = 0.5 * (lo[k] + hi[k]);
            lo[k] = c - 0.5 * wmax;
            hi[k] = c + 0.5 * wmax;
            w[k] = wmax;
            st = SWARP_INFO_FLAT_EXTENT;
        }
    }
    /* the points may lie up to pad beyond their extent in the world matrix
     * (its rounding): the map covers that much more */
    for (int k = 0; k < 3 && pad; ++k)
        if (pad[k] > SW_FIT_PAD_MIN_REL * w[k]) {
            lo[k] -= pad[k];
            hi[k] += pad[k];
            w[k] = hi[k] - lo[k];
        }
    swarp_mat4 A;
    memset(&A, 0, sizeof A);
    /* [RHS] (3.1) */
    sw_set(&A, 0, 0, 2.0 / w[0]);
    sw_set(&A, 0, 3, -(hi[0] + lo[0]) / w[0]);
    sw_set(&A, 1, 1, 2.0 / w[1]);
    sw_set(&A, 1, 3, -(hi[1] + lo[1]) / w[1]);
    if (sw_depth_zero_based(dr)) {
        sw_set(&A, 2, 2, 1.0 / w[2]);
        sw_set(&A, 2, 3, -lo[2] / w[2]);
    } else {
        sw_set(&A, 2, 2, 2.0 / w[2]);
        sw_set(&A, 2, 3, -(hi[2] + lo[2]) / w[2]);
    }
    sw_set(&A, 3, 3, 1.0);
    sw_depth_reverse_if(dr, &A);
    if (!sw_mat_finite(&A)) return SWARP_ERR_DEGENERATE;
    *out = A;
    return st;
}

SWARP_API swarp_status swarp_focus_fit(const swarp_mat4* m, const swarp_vec3* points, size_t count,
                                       const swarp_vec3* z_points, size_t z_count,
                                       swarp_depth_range depth_range, swarp_mat4* out_A_fit) {
    if (!m || !points || !out_A_fit) return SWARP_ERR_NULL_POINTER;
    if (count == 0 || (z_points && z_count == 0)) return SWARP_ERR_INVALID_ARGUMENT;
    if (!sw_light_depth_range_ok(depth_range)) return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_mat_finite(m)) return SWARP_ERR_NON_FINITE;
    for (size_t i = 0; i < count; ++i)
        if (!sw_finite3(&points[i])) return SWARP_ERR_NON_FINITE;
    if (z_points)
        for (size_t i = 0; i < z_count; ++i)
            if (!sw_finite3(&z_points[i])) return SWARP_ERR_NON_FINITE;
    return sw_focus_fit(m, points, count, z_points, z_count, depth_range, NULL, out_A_fit);
}
