/* The one call for engines: camera + light + scene box + options -> light
 * view, light projection, their product, the points of B, the n' used and
 * the predicted maximum errors.  Built from the separately callable stages:
 *
 *   swarp_setup        H = V ∩ S, adjusted near/far [RHS] §3.3.1, B, then
 *   swarp_setup_range  the same for an explicit view depth range (a split),
 *                      without adjusting it, then
 *   swarp_setup_points the light matrix for given points of B (and of the
 *                      receivers H, for pancaking and the nearest vertex). */
#include <float.h>

#include "geometry/geometry_internal.h"

/* 12 words of enums and counts, 5 doubles, 2 reserved words: the size of
 * 4 doubles and a 4-word reserved tail, which the ABI fixes */
_Static_assert(sizeof(swarp_setup_options) == 12 * 4 + 5 * 8 + 8, "swarp_setup_options size");
_Static_assert(sizeof(swarp_setup_options) == 12 * 4 + 4 * 8 + 16, "swarp_setup_options size kept");
_Static_assert(sizeof(swarp_setup_result) == 3 * 128 + 9 * 8 + 8 + sizeof(swarp_measured_error) + 16, "swarp_setup_result size");
_Static_assert(sizeof(swarp_warp_options) == 8 + 3 * 8 + 16, "swarp_warp_options size");
_Static_assert(sizeof(swarp_warp_info) == 6 * 8 + 16, "swarp_warp_info size");

/* Point lights: points of B nearer to the light than this fraction of the
 * farthest one are cut off by the light's near plane (a perspective map
 * cannot reach its own apex). */
#define SW_LIGHT_NEAR_MIN_REL 1e-4
/* Point lights with pancaking: the receivers' depth range (along the axis)
 * must exceed this times the rounding of a depth in the world matrix (192
 * eps of the world coordinates' magnitude, as D's floor in
 * sw_point_light_view), so that the window holds to the fit's 1e-6 of its
 * width; a thinner one is B's cut instead. */
#define SW_PANCAKE_RESOLVE 1e6
/* Point lights: a single perspective map covers half-angles up to
 * atan(1e3) ≈ 89.94°; beyond that the light is inside B. */
#define SW_LIGHT_MAX_TAN 1e3

/* More important informational statuses win: first those that say a part
 * of the promise (every receiver in the map, every caster between it and
 * the light in the depth range) is bounded rather than exact, then the
 * technique's own reports. */
static swarp_status sw_info_merge(swarp_status a, swarp_status b) {
    static const swarp_status order[] = {SWARP_INFO_LIGHT_NEAR_CLIPPED, SWARP_INFO_CASTERS_CLAMPED,
                                         SWARP_INFO_PSM_INVERSE,        SWARP_INFO_WARP_UNIFORM,
                                         SWARP_INFO_LIGHT_PARALLEL,     SWARP_INFO_FLAT_EXTENT};
    for (size_t i = 0; i < sizeof order / sizeof order[0]; ++i)
        if (a == order[i] || b == order[i]) return order[i];
    return a != SWARP_OK ? a : b;
}

/* The light's view axis for a point light: the spot axis, or the direction
 * to the centre of the points' bounding box. */
static int sw_point_axis(const swarp_light* light, const swarp_vec3* pts, size_t n, swarp_vec3* a) {
    if (light->cone_angle > 0.0) return sw_normalize_fast(light->direction, a);
    swarp_vec3 lo = pts[0], hi = pts[0];
    for (size_t i = 1; i < n; ++i) {
        lo = sw_v3(fmin(lo.x, pts[i].x), fmin(lo.y, pts[i].y), fmin(lo.z, pts[i].z));
        hi = sw_v3(fmax(hi.x, pts[i].x), fmax(hi.y, pts[i].y), fmax(hi.z, pts[i].z));
    }
    swarp_vec3 c = sw_scale(sw_add(lo, hi), 0.5);
    return sw_normalize_fast(sw_sub(c, light->position), a);
}

/* The nearest vertex e of [WS06] (the WS06 warp centre): the vertex of
 * least eye depth.  H is usually cut by the near plane, and then several
 * vertices share that depth exactly: picking one of them would let the
 * rounding of their depths decide, and the centre (P's lateral position,
 * hence the whole map) would jump between them with the caller's rounding
 * mode.  Instead e is the average of the vertices weighted by
 * max(0, 1 - (z_i - z_min) / (SW_NEAREST_TIE_REL · span)), span = the
 * larger of the points' depth extent and their largest coordinate: exactly
 * the nearest vertex when it is alone (every other vertex deeper by more
 * than the band), the middle of the near-plane
 * polygon when the vertices tie, and continuous in the inputs in between.
 * The band is 1e-6 of the span: far above the rounding of the depths (a few
 * eps of |z|), so a rounding change moves e by ~eps/1e-6 = 2e-10 of the
 * polygon's size at most, and far below any real difference in depth.
 * Depths relative to the eye (the points are camera-relative). */
#define SW_NEAREST_TIE_REL 1e-6
static int sw_nearest_vertex(const swarp_vec3* p, size_t n, swarp_vec3 eye, swarp_vec3 v, double world_mag,
                             swarp_vec3* e) {
    double zmin = INFINITY, zmax = -INFINITY, mag = world_mag;
    for (size_t i = 0; i < n; ++i) {
        swarp_vec3 q = sw_sub(p[i], eye);
        double z = sw_dot(q, v);
        zmin = fmin(zmin, z);
        zmax = fmax(zmax, z);
        mag = fmax(mag, fmax(fabs(q.x), fmax(fabs(q.y), fabs(q.z))));
    }
    if (!(zmin <= zmax)) return 0;
    /* the depths carry rounding of eps times the coordinates' magnitude
     * (which exceeds the depth extent of a thin split): the band is 1e-6 of
     * the larger of the two.  The magnitude is the WORLD coordinates' (the
     * caller's world_mag): p is camera-relative, but it was formed as
     * world - eye and carries eps |world| of noise, not eps |p| (a scene at
     * 3e6 has noise of 1e-9 in depths that a band of eps |p| would not
     * cover). */
    double band = SW_NEAREST_TIE_REL * fmax(zmax - zmin, mag);
    swarp_vec3 acc = {0, 0, 0};
    double wsum = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double z = sw_dot(sw_sub(p[i], eye), v);
        double w = band > 0.0 ? fmax(0.0, 1.0 - (z - zmin) / band) : 1.0;
        if (!(w > 0.0)) continue;
        acc = sw_add(acc, sw_scale(sw_sub(p[i], eye), w));
        wsum += w;
    }
    if (!(wsum > 0.0)) return 0;
    *e = sw_add(eye, sw_scale(acc, 1.0 / wsum));
    return 1;
}

/* r = a b for an affine b (last row 0 0 0 1: a look-at, or A_fit's
 * columns): 12 fewer products than sw_mul and no loop overhead; the same
 * sums in the same order as sw_mul (the dropped terms are exact zeros,
 * products with b's 0 0 0 1 row exact), so the values are sw_mul's (a zero
 * may differ in sign). */
static void sw_mul_affine_b(const swarp_mat4* a, const swarp_mat4* b, swarp_mat4* r) {
    swarp_mat4 t;
    const double* A = a->m;
    const double* B = b->m;
    for (int c = 0; c < 3; ++c) {
        const double b0 = B[c * 4], b1 = B[c * 4 + 1], b2 = B[c * 4 + 2];
        t.m[c * 4 + 0] = A[0] * b0 + A[4] * b1 + A[8] * b2;
        t.m[c * 4 + 1] = A[1] * b0 + A[5] * b1 + A[9] * b2;
        t.m[c * 4 + 2] = A[2] * b0 + A[6] * b1 + A[10] * b2;
        t.m[c * 4 + 3] = A[3] * b0 + A[7] * b1 + A[11] * b2;
    }
    const double b0 = B[12], b1 = B[13], b2 = B[14];
    t.m[12] = A[0] * b0 + A[4] * b1 + A[8] * b2 + A[12];
    t.m[13] = A[1] * b0 + A[5] * b1 + A[9] * b2 + A[13];
    t.m[14] = A[2] * b0 + A[6] * b1 + A[10] * b2 + A[14];
    t.m[15] = A[3] * b0 + A[7] * b1 + A[11] * b2 + A[15];
    *r = t;
}

/* The map coordinates of B must be resolved by its camera-relative
 * coordinates to this fraction of the map (the map spans 2): 1e-6, the
 * accuracy asked of the fit (docs/quality.md).  The bound it is compared
 * with is first order and worst case (every rounding of a coordinate adding
 * up); a 1e-9 rad light on a 1-unit body (the warp axis stretched 1e9
 * times) reaches 5e-7 and still maps B inside the map to 1e-6.  Refused are
 * bodies whose map is finer than their coordinates relative to the eye:
 * an eye 1e145 from a 40-unit body, a 1e-9 sliver 1e6 away. */
#define SW_REL_RESOLVE 1e-6

/* The per-point form of the light-view resolution test of sw_world_resolves
 * (see there): at each point the map coordinates' rounding, eps times the
 * sizes summed into X, Y and W, against SW_REL_RESOLVE of W. */
static int sw_light_resolves(const swarp_mat4* proj, const swarp_mat4* L, const swarp_vec3* p, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        const double px = p[i].x, py = p[i].y, pz = p[i].z;
        double l[3], mag[3];
        for (int j = 0; j < 3; ++j) {
            const double a0 = sw_at(L, j, 0) * px, a1 = sw_at(L, j, 1) * py, a2 = sw_at(L, j, 2) * pz, a3 = sw_at(L, j, 3);
            l[j] = a0 + a1 + a2 + a3;
            mag[j] = fabs(a0) + fabs(a1) + fabs(a2) + fabs(a3);
        }
        double X = sw_at(proj, 0, 3), Y = sw_at(proj, 1, 3), W = sw_at(proj, 3, 3);
        for (int j = 0; j < 3; ++j) {
            X += sw_at(proj, 0, j) * l[j];
            Y += sw_at(proj, 1, j) * l[j];
            W += sw_at(proj, 3, j) * l[j];
        }
        const double x = X / W, y = Y / W;
        double cx = 0.0, cy = 0.0;
        for (int j = 0; j < 3; ++j) {
            cx += fabs(sw_at(proj, 0, j) - x * sw_at(proj, 3, j)) * mag[j];
            cy += fabs(sw_at(proj, 1, j) - y * sw_at(proj, 3, j)) * mag[j];
        }
        if (!(DBL_EPSILON * fmax(cx, cy) <= SW_REL_RESOLVE * fabs(W))) return 0;
    }
    return 1;
}

/* Can the world-space matrix (m · T(-eye), applied to p + eye) be evaluated
 * in double at the camera-relative points p?  Its w carries rounding of
 * about eps times the sizes of the terms summed; when that reaches w itself
 * (a map of a body far below the resolution of world coordinates of size
 * |eye|: B a 1e-21 sliver at 25 units, or a 1e-9 rad grazing light
 * stretching a 1e6-offset scene 1e10 times) the map is meaningless in world
 * coordinates.  64 eps of margin. */
static int sw_world_resolves(const swarp_mat4* m, const swarp_mat4* proj, const swarp_mat4* L, const swarp_vec3* p,
                             size_t n, swarp_vec3 eye) {
    const double ax = fabs(eye.x), ay = fabs(eye.y), az = fabs(eye.z);
    const double m30 = sw_at(m, 3, 0), m31 = sw_at(m, 3, 1), m32 = sw_at(m, 3, 2), m33 = sw_at(m, 3, 3);
    double wmin = INFINITY, p1 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double px = fabs(p[i].x), py = fabs(p[i].y), pz = fabs(p[i].z);
        double w = m30 * p[i].x + m31 * p[i].y + m32 * p[i].z + m33;
        double k = fabs(m30) * (px + 2.0 * ax) + fabs(m31) * (py + 2.0 * ay) + fabs(m32) * (pz + 2.0 * az) + fabs(m33);
        if (!(w > 64.0 * DBL_EPSILON * k)) return 0;
        wmin = w < wmin ? w : wmin;
        p1 = fmax(p1, px + py + pz);
    }
    /* The light-view coordinates l = L p carry rounding of eps times the
     * sizes summed, mag_j = |L_j0 p_x| + |L_j1 p_y| + |L_j2 p_z| + |L_j3|
     * (the camera-relative point, src: sw_rel_camera, and a point light's
     * distance in the translation).  Moved by that, the map coordinate
     * x = X/W (X, W rows of light_proj at l) moves by
     * eps sum_j |proj_xj - x proj_wj| mag_j / W.  Beyond SW_REL_RESOLVE of
     * the map (half its width is 1) the map is finer than the coordinates
     * resolve B: an eye 1e145 from a 40-unit body (its points all equal
     * relative to the eye) would be "mapped" to x = 1e4, a spot light 2e154
     * above a 50-unit body to x = -2.1.  First a bound for all points at once (L's rows
     * are unit: mag_j <= |p|_1 + |L_j3|; B maps into |x| <= 1, 2 allowed):
     * it passes for every ordinary scene, and the per-point test (about
     * 15 % of swarp_setup's time) runs only where it does not. */
    double sx = 0.0, sy = 0.0;
    for (int j = 0; j < 3; ++j) {
        const double mj = p1 + fabs(sw_at(L, j, 3)), wj = 2.0 * fabs(sw_at(proj, 3, j));
        sx += (fabs(sw_at(proj, 0, j)) + wj) * mj;
        sy += (fabs(sw_at(proj, 1, j)) + wj) * mj;
    }
    if (DBL_EPSILON * fmax(sx, sy) <= SW_REL_RESOLVE * wmin) return 1;
    return sw_light_resolves(proj, L, p, n);
}

/* L^-1 -> (P0 L)^-1 = L^-1 P0^-1: P0 maps (x, y, z, w) to (x, y, w, -z), so
 * P0^-1 maps (X, Y, Z, W) to (X, Y, -W, Z): the columns of L^-1 become
 * [c0, c1, c3, -c2] (exact) */
static void sw_p0_inverse_after(swarp_mat4* m) {
    for (int r = 0; r < 4; ++r) {
        double c2 = sw_at(m, r, 2), c3 = sw_at(m, r, 3);
        sw_set(m, r, 2, c3);
        sw_set(m, r, 3, -c2);
    }
}

/* PSM's matrices (a post-perspective space, maybe the inverse projection:
 * w < 0 on B is fine) get the coarse form of sw_world_resolves' test: B's
 * extent against the rounding of its camera-relative coordinates, eps |p|.
 * Beyond it (an eye at -DBL_MAX from a 1e4 body) light_proj · light_view
 * overflows (inf - inf) though matrix is finite. */
static int sw_rel_resolves(const swarp_vec3* p, size_t n) {
    double mag = 0.0, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n; ++i) {
        const double c[3] = {p[i].x, p[i].y, p[i].z};
        for (int k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], c[k]), hi[k] = fmax(hi[k], c[k]);
            mag = fmax(mag, fabs(c[k]));
        }
    }
    double ext = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    return DBL_EPSILON * mag <= SW_REL_RESOLVE * ext;
}

/* ---- the light matrix for the points of B ----------------------------------
 * cam, light, B, H are camera-relative (sw_rel_camera); eye is the world eye,
 * which only the world-space resolution test needs. */

/* The light space M (world to the space the warp works in) and its inverse:
 * M = L for a directional light; M = P0 L for a point light. */
typedef struct sw_light_space {
    swarp_mat4 L, P0, M, M_inv;
    int point; /* P0 is a perspective */
} sw_light_space;

/* [RHS] §3.2.2 a point light: the view L from the light toward B (the spot
 * axis or B's centre), and P0 (x, y, z) -> (x/D, y/D, 1/D), D = -z, which
 * turns it into a directional light travelling toward -z.  Every point must
 * lie in front of the light within the widest perspective a map can have;
 * res->light_near/far: the light depth range allowed. */
static swarp_status sw_point_light_view(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B,
                                        size_t nb, const sw_follow* fw, sw_light_space* ls, swarp_setup_result* res,
                                        swarp_status* info) {
    swarp_vec3 a = {0, 0, -1};
    if (!sw_point_axis(light, B, nb, &a)) return SWARP_ERR_LIGHT_INSIDE_BODY;
    swarp_status s = fw ? sw_follow_light_view(cam, light->position, a, fw, &ls->L)
                        : sw_light_view(cam, light->position, a, &ls->L);
    /* a light ~DBL_MAX from the eye: B's angular size is far below
     * what its coordinates resolve (the documented DEGENERATE) */
    if (s == SWARP_ERR_OVERFLOW) return SWARP_ERR_DEGENERATE;
    if (swarp_status_is_error(s)) return s;
    *info = sw_info_merge(*info, s);
    double dmax = 0.0, bmag = 0.0;
    for (size_t i = 0; i < nb; ++i) {
        swarp_vec4 h = sw_xform_point(&ls->L, B[i]);
        double D = -h.z;
        if (D > dmax) dmax = D;
        bmag = fmax(bmag, fmax(fabs(B[i].x), fmax(fabs(B[i].y), fabs(B[i].z))));
    }
    /* and never below the rounding of D = a·(p - l), computed as a·p - a·l
     * from terms of p and l: 192 eps of the larger max norm (no sum to
     * overflow near DBL_MAX).  A point of B at the light itself (B = {l}: a
     * spot's apex alone) has a D of a few eps of either sign, by rounding;
     * within that band it is the apex (a spot: clipped) or the light is
     * inside B, never a map of D = 0. */
    const swarp_vec3 lp = light->position;
    const double lmag = fmax(fabs(lp.x), fmax(fabs(lp.y), fabs(lp.z)));
    double dmin_allowed = fmax(SW_LIGHT_NEAR_MIN_REL * dmax, 192.0 * DBL_EPSILON * fmax(bmag, lmag));
    for (size_t i = 0; i < nb; ++i) {
        swarp_vec4 h = sw_xform_point(&ls->L, B[i]);
        double D = -h.z;
        if (D < dmin_allowed) {
            if (light->cone_angle > 0.0 && D > -dmin_allowed) { /* the apex of a spot */
                *info = sw_info_merge(*info, SWARP_INFO_LIGHT_NEAR_CLIPPED);
                continue;
            }
            return SWARP_ERR_LIGHT_INSIDE_BODY;
        }
        if (hypot(h.x, h.y) > SW_LIGHT_MAX_TAN * D) return SWARP_ERR_LIGHT_INSIDE_BODY;
    }
    memset(&ls->P0, 0, sizeof ls->P0);
    sw_set(&ls->P0, 0, 0, 1.0);
    sw_set(&ls->P0, 1, 1, 1.0);
    sw_set(&ls->P0, 2, 3, 1.0);
    sw_set(&ls->P0, 3, 2, -1.0);
    res->light_near = fmax(dmin_allowed, 0.0);
    res->light_far = dmax;
    return SWARP_OK;
}

/* The light view (a directional light's along its direction, with the
 * light-space alignment of [RHS] §3.2.1, or the point light's), M and M^-1. */
static swarp_status sw_light_space_of(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B,
                                      size_t nb, const sw_follow* fw, sw_light_space* ls, swarp_setup_result* res,
                                      swarp_status* info) {
    swarp_status s;
    sw_identity(&ls->P0);
    ls->point = light->type == SWARP_LIGHT_POINT;
    if (ls->point) {
        s = sw_point_light_view(cam, light, B, nb, fw, ls, res, info);
        if (s != SWARP_OK) return s;
    } else {
        s = fw ? sw_follow_light_view(cam, cam->eye, light->direction, fw, &ls->L)
               : sw_light_view_body(cam, cam->eye, light->direction, B, nb, &ls->L);
        if (swarp_status_is_error(s)) return s;
        *info = sw_info_merge(*info, s);
    }
    if (ls->point)
        sw_mul(&ls->P0, &ls->L, &ls->M);
    else
        ls->M = ls->L; /* P0 = I: skip the product */
    sw_rigid_inverse(&ls->L, &ls->M_inv);
    if (ls->point) sw_p0_inverse_after(&ls->M_inv);
    return SWARP_OK;
}

/* B cut by the light's near plane D >= light_near (D = -z of the light
 * view L): the polyhedron clipped, so that B keeps every point between the
 * near plane and its far side (the near-plane section becomes its face).
 * Dropping the vertices in front of the plane instead would leave out all
 * of B between the plane and the nearest kept vertex: a spot 0.5 from the
 * eye lost the casters from 0.01 to 4.3 units. */
static size_t sw_clip_light_near_body(const sw_light_space* ls, const swarp_polyhedron* B_poly, double light_near,
                                      swarp_vec3* Bk) {
    swarp_polyhedron C;
    const swarp_vec3 n = sw_v3(sw_at(&ls->L, 2, 0), sw_at(&ls->L, 2, 1), sw_at(&ls->L, 2, 2));
    /* keeps n·p + d <= 0, i.e. -D + light_near <= 0 */
    if (sw_poly_clip(B_poly, n, sw_at(&ls->L, 2, 3) + light_near, &C) != SWARP_OK) return 0;
    for (uint32_t i = 0; i < C.vertex_count; ++i) Bk[i] = C.vertices[i];
    return C.vertex_count;
}

/* The same for B given as points (swarp_setup_points, the cascades): the
 * points behind the plane, and on every segment from one in front of it to
 * one behind it the point on the plane.  B's section by the plane lies in
 * the hull of those (each vertex of the clipped hull is a kept point or
 * the crossing of a hull edge, which is such a segment).  0 when they do
 * not fit SWARP_BODY_MAX_POINTS. */
static int sw_clip_light_near_points(const sw_light_space* ls, const swarp_vec3* B, size_t nb, double light_near,
                                     swarp_vec3* Bk, size_t* nk) {
    double D[SWARP_BODY_MAX_POINTS];
    size_t k = 0;
    nb = nb < SWARP_BODY_MAX_POINTS ? nb : SWARP_BODY_MAX_POINTS;
    for (size_t i = 0; i < nb; ++i) {
        D[i] = -sw_xform_point(&ls->L, B[i]).z;
        if (D[i] >= light_near) Bk[k++] = B[i];
    }
    for (size_t i = 0; i < nb; ++i)
        for (size_t j = 0; j < nb && D[i] >= light_near; ++j) {
            if (D[j] >= light_near) continue;
            if (k >= SWARP_BODY_MAX_POINTS) return 0;
            const double t = (D[i] - light_near) / (D[i] - D[j]); /* in [0, 1): D[j] < light_near <= D[i] */
            Bk[k++] = sw_add(B[i], sw_scale(sw_sub(B[j], B[i]), t));
        }
    *nk = k;
    return 1;
}

/* The points the map must see: a point light cuts B at its near plane
 * (the apex region; B_poly clipped when given, else the point set) into
 * Bk, replaces the receivers H by Bk when the plane cuts them and
 * narrows light_near to the depth actually covered; a directional light
 * uses B and H as they are. */
static swarp_status sw_cut_light_near(const sw_light_space* ls, const swarp_vec3* B, size_t nb,
                                      const swarp_polyhedron* B_poly, const swarp_vec3* H, size_t nh, swarp_vec3* Bk,
                                      const swarp_vec3** Bp, size_t* nbk, const swarp_vec3** Hp, size_t* nhk,
                                      swarp_vec3 eye, swarp_setup_result* res) {
    *Bp = B;
    *Hp = H;
    *nbk = nb < SWARP_BODY_MAX_POINTS ? nb : SWARP_BODY_MAX_POINTS;
    *nhk = !H ? 0 : nh < SWARP_BODY_MAX_POINTS ? nh : SWARP_BODY_MAX_POINTS;
    if (ls->point) {
        size_t k = 0;
        if (B_poly) k = sw_clip_light_near_body(ls, B_poly, res->light_near, Bk);
        else if (!sw_clip_light_near_points(ls, B, nb, res->light_near, Bk, &k)) return SWARP_ERR_CAPACITY;
        *nbk = k;
        *Bp = Bk;
        /* the receivers for pancaking: H when it lies behind the plane;
         * when the plane cuts H, B's cut, which holds H's cut (the
         * receivers just behind the plane are in the depth window; H's own
         * crossings of the plane need not lie in front of a LiSPSM warp
         * fitted to B's, and the remaining vertices alone leave them out) */
        int cut = 0;
        double hlo = INFINITY, hhi = -INFINITY, mag = fmax(fabs(eye.x), fmax(fabs(eye.y), fabs(eye.z)));
        for (size_t i = 0; H && i < *nhk; ++i) {
            const double D = -sw_xform_point(&ls->L, H[i]).z;
            cut |= D < res->light_near;
            hlo = fmin(hlo, D), hhi = fmax(hhi, D);
            mag = fmax(mag, fmax(fabs(eye.x + H[i].x), fmax(fabs(eye.y + H[i].y), fabs(eye.z + H[i].z))));
        }
        /* and when H's depth range is too thin for the world matrix to
         * hold it to the fit's 1e-6 (a spot at the eye, far ~ near) */
        cut |= *nhk > 0 && hhi - hlo < SW_PANCAKE_RESOLVE * 192.0 * DBL_EPSILON * mag;
        *Hp = cut ? Bk : H;
        *nhk = cut ? *nbk : *nhk;
    }
    if (*nbk == 0) return SWARP_ERR_BODY_EMPTY;
    if (ls->point) {
        double dmin = INFINITY;
        for (size_t i = 0; i < *nbk; ++i) dmin = fmin(dmin, -sw_xform_point(&ls->L, (*Bp)[i]).z);
        res->light_near = dmin;
    }
    return SWARP_OK;
}

/* The warp P after M: LiSPSM [RHS] §3.2.1 oriented along the light frame,
 * or the uniform map's z flip (depth grows away from the light). */
static swarp_status sw_warp_step(swarp_technique tech, const swarp_setup_options* o, const sw_light_space* ls,
                                 const swarp_camera* cam, double near, double far, const swarp_vec3* Bp, size_t nbk,
                                 const swarp_vec3* ep, swarp_mat4* P, swarp_warp_info* wi, swarp_status* info) {
    memset(wi, 0, sizeof *wi);
    if (tech == SWARP_TECHNIQUE_LISPSM) {
        const swarp_warp_options w = sw_setup_warp_options(o);
        swarp_status s = sw_warp_lispsm_oriented(&ls->M, &ls->M_inv, cam, near, far, Bp, nbk, ep, &w, P, wi);
        if (swarp_status_is_error(s)) return s;
        *info = sw_info_merge(*info, s);
    } else {
        sw_identity(P);
        sw_set(P, 2, 2, -1.0);
        wi->n_light = wi->n_eye = INFINITY;
    }
    return SWARP_OK;
}

/* Focusing [RHS] (3.1): A_fit fits P M of the points Bp (their depth range:
 * the receivers zp when pancaking), light_proj = A_fit P P0, matrix =
 * light_proj L, which must resolve B in world coordinates. */
static swarp_status sw_focus_step(const sw_light_space* ls, const swarp_mat4* P, const swarp_vec3* Bp, size_t nbk,
                                  const swarp_vec3* zp, size_t nhk, swarp_depth_range dr, swarp_vec3 eye,
                                  swarp_setup_result* res, swarp_status* info) {
    swarp_mat4 PM, A;
    if (ls->point)
        sw_mul(P, &ls->M, &PM);
    else
        sw_mul_affine_b(P, &ls->M, &PM); /* M = L, a look-at */
    /* the world matrix's rounding (the eye folded in, sw_fold_result):
     * x, y over B, depth over the points that set it */
    double pad[3], zpad[3];
    sw_world_rounding_pad(&PM, Bp, nbk, eye, pad);
    if (zp) {
        sw_world_rounding_pad(&PM, zp, nhk, eye, zpad);
        pad[2] = zpad[2];
    }
    swarp_status s = sw_focus_fit(&PM, Bp, nbk, zp, nhk, dr, pad, &A);
    if (swarp_status_is_error(s)) return s;
    *info = sw_info_merge(*info, s);
    swarp_mat4 proj = *P; /* P P0, P0 = I for a directional light */
    if (ls->point) sw_mul(P, &ls->P0, &proj);
    sw_mul(&A, &proj, &res->light_proj);
    res->light_view = ls->L;
    sw_mul_affine_b(&res->light_proj, &ls->L, &res->matrix); /* L: a look-at */
    if (!sw_world_resolves(&res->matrix, &res->light_proj, &ls->L, Bp, nbk, eye)) return SWARP_ERR_DEGENERATE;
    return SWARP_OK;
}

/* A directional light's depth range in light view units (distance along
 * the light) over zs: only the z row of the rigid L is needed, the points
 * are finite. */
static void sw_light_depth_range(const swarp_mat4* L, const swarp_vec3* zs, size_t zn, swarp_setup_result* res) {
    double lo = INFINITY, hi = -INFINITY;
    const double l20 = sw_at(L, 2, 0), l21 = sw_at(L, 2, 1), l22 = sw_at(L, 2, 2), l23 = sw_at(L, 2, 3);
    for (size_t i = 0; i < zn; ++i) {
        double D = -(l20 * zs[i].x + l21 * zs[i].y + l22 * zs[i].z + l23);
        lo = D < lo ? D : lo;
        hi = D > hi ? D : hi;
    }
    res->light_near = lo;
    res->light_far = hi;
}

/* Uniform and LiSPSM maps: light space, the cut at a point light's near
 * plane, the warp, focusing, then the report (n', γ, light depth range). */
static swarp_status sw_setup_lispsm(swarp_technique tech, const swarp_camera* cam, const swarp_light* light,
                                    const swarp_vec3* B, size_t nb, const swarp_polyhedron* B_poly,
                                    const swarp_vec3* H, size_t nh, double near,
                                    double far, const swarp_setup_options* o, swarp_vec3 eye, const sw_follow* fw,
                                    swarp_vec3 v, const swarp_vec3* ep, swarp_setup_result* res, swarp_status* info) {
    sw_light_space ls;
    swarp_status s = sw_light_space_of(cam, light, B, nb, fw, &ls, res, info);
    if (s != SWARP_OK) return s;
    swarp_vec3 Bk[SWARP_BODY_MAX_POINTS + 1];
    const swarp_vec3 *Bp, *Hp;
    size_t nbk, nhk;
    s = sw_cut_light_near(&ls, B, nb, B_poly, H, nh, Bk, &Bp, &nbk, &Hp, &nhk, eye, res);
    if (s != SWARP_OK) return s;
    swarp_mat4 P;
    swarp_warp_info wi;
    s = sw_warp_step(tech, o, &ls, cam, near, far, Bp, nbk, ep, &P, &wi, info);
    if (s != SWARP_OK) return s;
    /* pancaking: the depth range covers the receivers H only; casters
     * nearer the light are clamped to the near plane by the renderer */
    const swarp_vec3* zp = (o->pancake && nhk > 0) ? Hp : NULL;
    s = sw_focus_step(&ls, &P, Bp, nbk, zp, nhk, sw_resolve_depth_range(o->depth_range), eye, res, info);
    if (s != SWARP_OK) return s;
    res->n_light = wi.n_light;
    res->n_eye = wi.n_eye;
    res->gamma = wi.gamma;
    if (tech != SWARP_TECHNIQUE_LISPSM) {
        double vz = sw_at(&ls.M, 2, 0) * v.x + sw_at(&ls.M, 2, 1) * v.y + sw_at(&ls.M, 2, 2) * v.z;
        res->gamma = acos(fmax(-1.0, fmin(1.0, -vz)));
    }
    if (!ls.point) sw_light_depth_range(&ls.L, zp ? zp : Bp, zp ? nhk : nbk, res);
    return SWARP_OK;
}

/* PSM with a point light: the same light as the uniform and LiSPSM maps
 * see it (sw_point_light_view): refused when it lies inside B, and B cut
 * at its near plane (SWARP_INFO_LIGHT_NEAR_CLIPPED for a spot on or in B).
 * In post-perspective space a caster at the light has w = 0 in the light
 * camera and its depth z/w is unbounded: the depth range cannot cover B
 * up to the light, only up to the near plane. */
static swarp_status sw_psm_point_body(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B,
                                      size_t nb, const swarp_polyhedron* B_poly, swarp_polyhedron* Bc,
                                      swarp_status* info) {
    sw_light_space ls;
    swarp_setup_result tmp;
    swarp_status st = SWARP_OK;
    swarp_status s = sw_point_light_view(cam, light, B, nb, NULL, &ls, &tmp, &st);
    if (s != SWARP_OK) return s;
    if (st == SWARP_INFO_LIGHT_NEAR_CLIPPED) *info = sw_info_merge(*info, st);
    const swarp_vec3 n = sw_v3(sw_at(&ls.L, 2, 0), sw_at(&ls.L, 2, 1), sw_at(&ls.L, 2, 2));
    s = sw_poly_clip(B_poly, n, sw_at(&ls.L, 2, 3) + tmp.light_near, Bc);
    if (s != SWARP_OK) return s;
    return Bc->vertex_count > 0 ? SWARP_OK : SWARP_ERR_BODY_EMPTY;
}

/* The error model [RHS] (2.3)-(2.8) for n' in eye units over [near, far]. */
static swarp_status sw_predict_error(const swarp_camera* cam, const swarp_setup_options* o, double near,
                                     double far, swarp_setup_result* res) {
    swarp_error_config cfg;
    sw_setup_error_config(o, sw_half_fovy(cam->fovy), near, far, &cfg);
    double mx = NAN, mz = NAN;
    swarp_status s = swarp_error_max(&cfg, res->n_eye, &mx, &mz);
    if (swarp_status_is_error(s) || !sw_finite(mx) || !sw_finite(mz)) return SWARP_ERR_DEGENERATE;
    res->max_mx = mx;
    res->max_mz = mz;
    return SWARP_OK;
}

/* The light matrix for the points B of the body (B_poly: B as a polyhedron,
 * for PSM; may be NULL) and the receivers H (may be NULL), without the
 * predicted error.  *out written only on success. */
static swarp_status sw_setup_matrix(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B,
                                    size_t nb, const swarp_polyhedron* B_poly, const swarp_vec3* H, size_t nh,
                                    double near, double far, const swarp_setup_options* o, swarp_vec3 eye,
                                    const sw_follow* fw, swarp_setup_result* out) {
    swarp_status info = SWARP_OK, s;
    const swarp_technique tech = sw_resolve_technique(o->technique);
    swarp_vec3 v, r, u;
    sw_camera_basis(cam, &v, &r, &u);
    /* nearest vertex e of H (the receivers): only the WS06 centre uses it */
    const swarp_vec3* ep = NULL;
    swarp_vec3 e_near;
    if (o->center == SWARP_WARP_CENTER_NEAREST_VERTEX) {
        const swarp_vec3* src = H ? H : B;
        size_t ns = H ? nh : nb;
        const double world_mag = fmax(fabs(eye.x), fmax(fabs(eye.y), fabs(eye.z)));
        if (sw_nearest_vertex(src, ns, cam->eye, v, world_mag, &e_near)) ep = &e_near;
    }
    swarp_setup_result res;
    memset(&res, 0, sizeof res);
    res.view_near = near;
    res.view_far = far;
    const size_t nb_body = nb; /* point_count: B's own points, before a near-plane cut */
    if (tech == SWARP_TECHNIQUE_PSM) {
        swarp_polyhedron Bc;
        if (light->type == SWARP_LIGHT_POINT && B_poly) {
            s = sw_psm_point_body(cam, light, B, nb, B_poly, &Bc, &info);
            if (s != SWARP_OK) return s;
            B = Bc.vertices, nb = Bc.vertex_count, B_poly = &Bc;
        }
        s = sw_psm_setup(cam, light, B, nb, B_poly, H, nh, near, far, o, fw, &res);
        if (swarp_status_is_error(s)) return s;
        if (!sw_rel_resolves(B, nb)) return SWARP_ERR_DEGENERATE;
        info = sw_info_merge(info, s);
    } else {
        s = sw_setup_lispsm(tech, cam, light, B, nb, B_poly, H, nh, near, far, o, eye, fw, v, ep, &res, &info);
        if (s != SWARP_OK) return s;
    }
    if (!sw_mat_finite(&res.matrix) || !sw_mat_finite(&res.light_proj) || !sw_mat_finite(&res.light_view))
        return SWARP_ERR_DEGENERATE;
    res.point_count = (uint32_t)nb_body;
    *out = res;
    return info;
}

/* sw_setup_matrix and the predicted error of its n'. */
static swarp_status sw_setup_points(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B,
                                    size_t nb, const swarp_polyhedron* B_poly, const swarp_vec3* H, size_t nh,
                                    double near, double far, const swarp_setup_options* o, swarp_vec3 eye,
                                    const sw_follow* fw, swarp_setup_result* out) {
    swarp_setup_result res;
    const swarp_status info = sw_setup_matrix(cam, light, B, nb, B_poly, H, nh, near, far, o, eye, fw, &res);
    if (swarp_status_is_error(info)) return info;
    const swarp_status s = sw_predict_error(cam, o, near, far, &res);
    if (s != SWARP_OK) return s;
    *out = res;
    return info;
}

/* ---- camera-relative coordinates -------------------------------------------
 * Everything is computed with the eye at the origin: the box, the light
 * position and the points of B are translated by -eye first, and the
 * translation is folded back into the light view and the matrix at the end
 * (only their last columns change).  In world coordinates of magnitude X
 * (large worlds: 1e5..1e6) every light-space coordinate carries rounding of
 * eps X, which is the whole extent of a small body B (near = 1e-6, or a
 * flat box seen edge-on: a zero extent then looks like rounding noise and
 * the fit would stretch the noise over the map, putting points of B outside
 * it); relative to the eye the coordinates are of the size of B and of its
 * distance from the eye. */
static void sw_rel_camera(const swarp_camera* cam, swarp_camera* rc) {
    *rc = *cam;
    rc->eye = sw_v3(0.0, 0.0, 0.0);
}
static void sw_rel_light(const swarp_light* light, swarp_vec3 eye, swarp_light* rl) {
    *rl = *light;
    /* a directional light's position is not used (and need not be finite) */
    rl->position = light->type == SWARP_LIGHT_POINT ? sw_sub(light->position, eye) : sw_v3(0.0, 0.0, 0.0);
}
static void sw_rel_box(const swarp_aabb* box, swarp_vec3 eye, swarp_aabb* rb) {
    rb->min = sw_sub(box->min, eye);
    rb->max = sw_sub(box->max, eye);
}
/* camera, light and box relative to the eye; 0 when a translated
 * coordinate overflowed (finite inputs near DBL_MAX of opposite signs) */
static int sw_rel_scene(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                        swarp_camera* rc, swarp_light* rl, swarp_aabb* rs) {
    sw_rel_camera(cam, rc);
    sw_rel_light(light, cam->eye, rl);
    sw_rel_box(scene, cam->eye, rs);
    return sw_finite3(&rl->position) && sw_finite3(&rs->min) && sw_finite3(&rs->max);
}
/* m · T(-eye): the last column gets -m[:, 0..2] · eye */
static void sw_fold_eye(swarp_mat4* m, swarp_vec3 eye) {
    for (int r = 0; r < 4; ++r)
        sw_set(m, r, 3,
               sw_at(m, r, 3) - (sw_at(m, r, 0) * eye.x + sw_at(m, r, 1) * eye.y + sw_at(m, r, 2) * eye.z));
}
/* Folds the eye back into light_view and matrix; 0 when a changed entry
 * (their last columns, the rest was checked before) overflowed. */
static int sw_fold_result(swarp_setup_result* res, swarp_vec3 eye) {
    sw_fold_eye(&res->light_view, eye);
    sw_fold_eye(&res->matrix, eye);
    int ok = 1;
    for (int i = 12; i < 16; ++i) ok &= sw_finite(res->light_view.m[i]) & sw_finite(res->matrix.m[i]);
    return ok;
}

/* The checks every setup entry point makes first, in the common order
 * (camera, light, options; src/common/check.c); *o: the options resolved. */
static swarp_status sw_check_common(const swarp_camera* cam, const swarp_light* light,
                                    const swarp_setup_options* opts, swarp_setup_options* o) {
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    s = sw_check_light(light);
    if (s != SWARP_OK) return s;
    return sw_resolve_setup_options(opts, o);
}

/* Capacity check only: the needed count is written early only together with
 * SWARP_ERR_CAPACITY (the documented exception); on every other error the
 * outputs stay untouched, so the count is written at the very end. */
static swarp_status sw_check_points_capacity(const swarp_polyhedron* B, const swarp_vec3* out_points,
                                             size_t capacity, size_t* out_count) {
    if (out_points && capacity < B->vertex_count) {
        if (out_count) *out_count = B->vertex_count;
        return SWARP_ERR_CAPACITY;
    }
    return SWARP_OK;
}

/* The measured warp search (SWARP_WARP_PARAM_MEASURED).  The warp
 * strength is searched in t = n_opt / (n_opt + n'), which maps n' in
 * (0, +inf] monotonically onto [0, 1): t = 0 is the uniform map, t = 1/2
 * is n_opt [RHS] (3.2).  Over t the error of the warped map changes
 * smoothly (P's entries are rational in n'), and on ordinary scenes has one
 * minimum between the over-warped end (far receivers starve) and the
 * uniform end (near receivers starve); golden-section search finds it
 * without derivatives in a fixed number of setups.  SW_SEARCH_T_MAX keeps
 * n' >= n_opt / 9: stronger warps put the near plane at the light's
 * projection centre and only lose.  SW_SEARCH_STEPS golden steps shrink the
 * bracket to 0.9 * 0.618^10 = 0.007 in t (n' within 3 % around n_opt);
 * every matrix evaluated is a candidate, so non-unimodal errors still
 * return the best evaluated.  With the measurement on, the choice is then
 * checked against the start (n_opt) and the uniform map by the full
 * measurement (sw_search_guard): never worse than either. */
#define SW_SEARCH_T_MAX 0.9
#define SW_SEARCH_STEPS 10
/* Maxima within this fraction of each other are a tie.  Where the
 * maximum hardly depends on n' (it sits on H's near face beside the eye,
 * which no warp resolves better: the light behind the camera) the search
 * would otherwise follow changes of a few 1e-4 of the maximum to an n' that
 * starves the rest of the view; among the tied candidates the one with the
 * smallest mean sigma over the fixed point set is chosen, the map that
 * serves the other receivers best.  1e-3 is far below the measurement's
 * stated 3 % and far above the rounding of sigma (about 1e-13 relative),
 * so a tie is decided the same way under every rounding mode. */
#define SW_SEARCH_TIE_REL 1e-3
/* Means within this fraction are equal and the first evaluated wins: the
 * mean carries rounding of about 1e-13 relative, so near-equal means of
 * different matrices are decided by their order under every rounding mode
 * instead of by the rounding. */
#define SW_SEARCH_MEAN_REL 1e-6
/* the cheap set's capacity: two points per vertex of H plus the centroid */
#define SW_SEARCH_SET_MAX (2 * SWARP_BODY_MAX_POINTS + 1)

typedef struct sw_search_in {
    const swarp_camera* cam;
    const swarp_light* light;
    const swarp_aabb* scene;
    const swarp_polyhedron* B;
    const swarp_polyhedron* H;
    double near, far;
    swarp_vec3 eye;
    const sw_follow* fw;
} sw_search_in;

/* one evaluated matrix: the result, its status, its largest sigma and
 * mean sigma over the fixed point set (+inf for a failed setup) */
typedef struct sw_candidate {
    swarp_setup_result r;
    swarp_status info;
    double cheap_max, cheap_mean;
} sw_candidate;

/* every t evaluated, with its fixed-set maximum and mean */
#define SW_SEARCH_EVALS (SW_SEARCH_STEPS + 4)
typedef struct sw_search {
    const sw_search_in* in;
    swarp_setup_options o; /* param USER, n_user set per candidate */
    double n0;             /* n_opt (eye units), the start */
    sw_receiver rc[SW_SEARCH_SET_MAX];
    size_t nrc;
    sw_candidate start, uniform;
    double t[SW_SEARCH_EVALS], max[SW_SEARCH_EVALS], mean[SW_SEARCH_EVALS];
    int evals;
} sw_search;

static double sw_search_n(const sw_search* q, double t) { return t > 0.0 ? q->n0 * (1.0 - t) / t : INFINITY; }

static void sw_search_score(const sw_search* q, sw_candidate* c) {
    c->cheap_max = c->cheap_mean = INFINITY;
    if (swarp_status_is_error(c->info)) return;
    c->cheap_max = sw_measure_set_sigma(&c->r.matrix, &q->o, q->rc, q->nrc, &c->cheap_mean);
}

/* the matrix at t (its predicted error is left to the chosen one) */
static void sw_search_eval(sw_search* q, double t, sw_candidate* c) {
    const sw_search_in* in = q->in;
    q->o.n_user = sw_search_n(q, t);
    c->info = sw_setup_matrix(in->cam, in->light, in->B->vertices, in->B->vertex_count, in->B, in->H->vertices,
                              in->H->vertex_count, in->near, in->far, &q->o, in->eye, in->fw, &c->r);
    sw_search_score(q, c);
}

static void sw_search_record(sw_search* q, double t, const sw_candidate* c) {
    if (q->evals >= SW_SEARCH_EVALS) return;
    q->t[q->evals] = t, q->max[q->evals] = c->cheap_max, q->mean[q->evals] = c->cheap_mean;
    q->evals++;
}

/* 1 when evaluation i is better than j.  An evaluation whose maximum is
 * within the tie SW_SEARCH_TIE_REL of the lowest maximum evaluated so far
 * is eligible; of two eligible ones the smaller mean (beyond
 * SW_SEARCH_MEAN_REL) is better, an eligible one beats one that is not,
 * and otherwise the smaller maximum is better.  The tie is measured from
 * the one lowest maximum, not pairwise, so a chain of ties cannot drift
 * away from the minimum; on a plateau of the maximum (equal to its
 * rounding) the section search follows the mean instead of the rounding. */
static int sw_search_better(const sw_search* q, int i, int j) {
    double lo = INFINITY;
    for (int k = 0; k < q->evals; ++k) lo = fmin(lo, q->max[k]);
    const double cap = lo * (1.0 + SW_SEARCH_TIE_REL);
    const int ei = q->max[i] <= cap, ej = q->max[j] <= cap;
    if (ei && ej) return q->mean[i] < q->mean[j] * (1.0 - SW_SEARCH_MEAN_REL);
    if (ei != ej) return ei;
    return q->max[i] < q->max[j];
}

/* evaluates t and records it; returns its index */
static int sw_search_try(sw_search* q, double t) {
    sw_candidate c;
    sw_search_eval(q, t, &c);
    sw_search_record(q, t, &c);
    return q->evals - 1;
}

/* golden-section search over t in [0, SW_SEARCH_T_MAX] by sw_search_better */
static void sw_search_golden(sw_search* q) {
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double a = 0.0, b = SW_SEARCH_T_MAX;
    double c = b - g * (b - a), d = a + g * (b - a);
    int ic = sw_search_try(q, c), id = sw_search_try(q, d);
    for (int i = 0; i < SW_SEARCH_STEPS; ++i) {
        if (!sw_search_better(q, id, ic)) {
            b = d, d = c, id = ic;
            c = b - g * (b - a);
            ic = sw_search_try(q, c);
        } else {
            a = c, c = d, ic = id;
            d = a + g * (b - a);
            id = sw_search_try(q, d);
        }
    }
}

/* The choice among the evaluated t: the best by sw_search_better, the
 * first evaluated of equals.  Returns its index. */
static int sw_search_choose(const sw_search* q) {
    int pick = 0;
    for (int i = 1; i < q->evals; ++i)
        if (sw_search_better(q, i, pick)) pick = i;
    return pick;
}

/* A lower bound of a reference's maximum over H: its fixed-set maximum
 * and its sigma at the choice's worst point (every point of H bounds the
 * maximum from below). */
static double sw_search_lower_bound(const sw_search* q, const sw_candidate* ref, const sw_candidate* chosen) {
    double lb = ref->cheap_max;
    if (!chosen->r.measured.samples) return lb;
    sw_receiver at[3];
    const size_t n = sw_measure_set_make(q->in->cam, q->in->light, &q->o, &chosen->r.measured.at, 1, at, 3);
    double mean;
    const double s = sw_measure_set_sigma(&ref->r.matrix, &q->o, at, n, &mean);
    return s > lb ? s : lb;
}

/* The full measurement of the choice, checked against the start and the
 * uniform map.  The fixed point set and the choice's worst point lie in
 * H, so a reference's maximum is at least its sigma there: when that is
 * within the tie SW_SEARCH_TIE_REL of the choice's full maximum, the
 * reference cannot be better beyond the tie and is not measured (the
 * common case); otherwise it is, and replaces the choice when lower by
 * more than the tie.  The choice's
 * predicted error is computed last, for the matrix returned (a matrix
 * whose n' the model cannot evaluate gives way to the start, which has it). */
static void sw_search_guard(sw_search* q, sw_candidate* chosen, int measure, swarp_setup_result* out,
                            swarp_status* info) {
    const sw_search_in* in = q->in;
    sw_candidate* refs[2] = {&q->start, &q->uniform};
    if (measure) {
        sw_measure_setup(in->cam, in->near, in->far, in->light, in->scene, &chosen->r.matrix, &q->o,
                         &chosen->r.measured);
        for (int i = 0; i < 2; ++i) {
            sw_candidate* ref = refs[i];
            if (swarp_status_is_error(ref->info) || ref->r.n_eye == chosen->r.n_eye ||
                !(chosen->r.measured.max_sigma * (1.0 - SW_SEARCH_TIE_REL) > sw_search_lower_bound(q, ref, chosen)))
                continue;
            sw_measure_setup(in->cam, in->near, in->far, in->light, in->scene, &ref->r.matrix, &q->o,
                             &ref->r.measured);
            if (ref->r.measured.samples &&
                ref->r.measured.max_sigma < chosen->r.measured.max_sigma * (1.0 - SW_SEARCH_TIE_REL))
                *chosen = *ref;
        }
    }
    if (sw_predict_error(in->cam, &q->o, in->near, in->far, &chosen->r) != SWARP_OK) {
        *chosen = q->start;
        if (measure)
            sw_measure_setup(in->cam, in->near, in->far, in->light, in->scene, &chosen->r.matrix, &q->o,
                             &chosen->r.measured);
    }
    *out = chosen->r;
    if (!measure) memset(&out->measured, 0, sizeof out->measured);
    *info = chosen->info;
}

static swarp_status sw_setup_measured(const sw_search_in* in, const swarp_setup_options* o,
                                      swarp_setup_result* out) {
    sw_search q;
    q.in = in;
    q.o = *o;
    q.o.param = SWARP_WARP_PARAM_NOPT;
    q.o.skip_measure = 1;
    q.evals = 0;
    sw_candidate* st = &q.start;
    st->info = sw_setup_points(in->cam, in->light, in->B->vertices, in->B->vertex_count, in->B, in->H->vertices,
                               in->H->vertex_count, in->near, in->far, &q.o, in->eye, in->fw, &st->r);
    if (swarp_status_is_error(st->info)) return st->info;
    q.n0 = st->r.n_eye;
    if (!(q.n0 < INFINITY) || !(q.n0 > 0.0)) { /* n_opt is uniform already: nothing to search */
        st->r.measured.samples = 0;
        sw_measure_setup(in->cam, in->near, in->far, in->light, in->scene, &st->r.matrix, o, &st->r.measured);
        *out = st->r;
        return st->info;
    }
    q.o.param = SWARP_WARP_PARAM_USER;
    q.o.skip_measure = 0;
    q.nrc = sw_measure_set_make(in->cam, in->light, &q.o, in->H->vertices, in->H->vertex_count, q.rc,
                                SW_SEARCH_SET_MAX);
    sw_search_score(&q, st);
    sw_search_record(&q, 0.5, st); /* n_opt: t = 1/2 */
    sw_search_eval(&q, 0.0, &q.uniform); /* uniform, the bracket's end the golden points never reach */
    sw_search_record(&q, 0.0, &q.uniform);
    sw_search_golden(&q);
    const int pick = sw_search_choose(&q);
    sw_candidate chosen;
    if (q.t[pick] == 0.5) chosen = q.start;
    else if (q.t[pick] == 0.0) chosen = q.uniform;
    else sw_search_eval(&q, q.t[pick], &chosen);
    swarp_status info;
    sw_search_guard(&q, &chosen, !o->skip_measure, out, &info);
    return info;
}

/* cam, light, scene: camera-relative (eye at the origin); eye: the world
 * eye, folded back into the results */
static swarp_status sw_setup_range(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                                   double near, double far, const swarp_polyhedron* Hin,
                                   const swarp_setup_options* o, swarp_vec3 eye, const sw_follow* fw,
                                   swarp_setup_result* out,
                                   swarp_vec3* out_points, size_t capacity, size_t* out_count) {
    swarp_polyhedron Hl, B;
    const swarp_polyhedron* Hp = Hin;
    swarp_status s;
    if (!Hp) {
        s = sw_body_h(cam, near, far, scene, &Hl);
        if (s != SWARP_OK) return s;
        Hp = &Hl;
    }
    int clamped = 0;
    s = sw_body_from_h_clipped(Hp, light, scene, &B, &clamped); /* H from sw_body_h: the clipper's */
    if (s != SWARP_OK) return s;
    s = sw_check_points_capacity(&B, out_points, capacity, out_count);
    if (s != SWARP_OK) return s;
    /* the receivers a spot lights: H ∩ L */
    swarp_polyhedron HL;
    if (light->type == SWARP_LIGHT_POINT && light->cone_angle > 0.0) {
        sw_poly_copy(Hp, &HL);
        s = sw_clip_light_pyramid(&HL, light);
        if (s != SWARP_OK) return s;
        if (HL.vertex_count == 0) return SWARP_ERR_BODY_EMPTY;
        Hp = &HL;
    }
    swarp_setup_result res;
    const sw_search_in in = {cam, light, scene, &B, Hp, near, far, eye, fw};
    swarp_status info;
    if (sw_resolve_technique(o->technique) == SWARP_TECHNIQUE_LISPSM &&
        (o->param == SWARP_WARP_PARAM_DEFAULT || o->param == SWARP_WARP_PARAM_MEASURED)) {
        info = sw_setup_measured(&in, o, &res);
        if (swarp_status_is_error(info)) return info;
    } else {
        info = sw_setup_points(cam, light, B.vertices, B.vertex_count, &B, Hp->vertices, Hp->vertex_count, near,
                               far, o, eye, fw, &res);
        if (swarp_status_is_error(info)) return info;
        /* measured camera-relative (the coordinates B was built in), the
         * worst point folded back with the matrices */
        sw_measure_setup(cam, near, far, light, scene, &res.matrix, o, &res.measured);
    }
    if (!sw_fold_result(&res, eye)) return SWARP_ERR_DEGENERATE;
    if (res.measured.samples) res.measured.at = sw_add(res.measured.at, eye);
    if (clamped) info = sw_info_merge(info, SWARP_INFO_CASTERS_CLAMPED);
    *out = res;
    if (out_points)
        for (uint32_t i = 0; i < B.vertex_count; ++i) out_points[i] = sw_add(B.vertices[i], eye);
    if (out_count) *out_count = B.vertex_count;
    return info;
}

/* H lies in one depth plane (a box face on a view plane, or a view range
 * one ulp wide): the range gets a sliver of 1e-9 of its depth, taken from
 * the side where it stays inside the camera's [near, far] (V ∩ S over the
 * widened range is still H); a camera range narrower than the sliver is
 * used whole.  Widening past the camera's far would report a view range the
 * caller never asked for. */
#define SW_SLIVER_REL 1e-9
static void sw_keep_sliver(double cam_near, double cam_far, double* zn, double* zf) {
    const double pad = fmax(SW_SLIVER_REL * *zn, 1e-300);
    if (*zn - pad >= cam_near) *zn -= pad;
    else if (*zf + pad <= cam_far) *zf += pad;
    else *zn = cam_near, *zf = cam_far;
}

/* swarp_setup, with the previous light frame to follow (NULL: stateless) */
static swarp_status sw_setup_main(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                                  const swarp_setup_options* opts, const sw_follow* fw, swarp_setup_result* out,
                                  swarp_vec3* out_points, size_t capacity, size_t* out_count) {
    if (!cam || !light || !scene || !out) return SWARP_ERR_NULL_POINTER;
    swarp_setup_options o;
    swarp_status s = sw_check_common(cam, light, opts, &o);
    if (s != SWARP_OK) return s;
    if ((s = sw_check_view_range(cam->z_near, cam->z_far)) != SWARP_OK) return s;
    s = sw_check_box(scene);
    if (s != SWARP_OK) return s;
    /* [RHS] §4.3: a measured min depth moves the near plane out (never
     * past what the depth buffer saw); 0 = not given, the camera's own */
    double cam_near = cam->z_near;
    if (o.min_depth > 0.0) {
        s = swarp_mindepth_near(cam->z_near, cam->z_far, o.min_depth, NULL, &cam_near);
        if (swarp_status_is_error(s)) return s;
    }
    swarp_camera rc;
    swarp_light rl;
    swarp_aabb rs;
    if (!sw_rel_scene(cam, light, scene, &rc, &rl, &rs)) return SWARP_ERR_NON_FINITE;
    /* adjusted near/far [RHS] §3.3.1: V ∩ S over [near', far'] is H itself */
    swarp_polyhedron H;
    double zn, zf;
    s = sw_body_h_eye(cam, cam_near, cam->z_far, scene, &H, &zn, &zf);
    if (s != SWARP_OK) return s;
    zn = fmin(fmax(zn, cam_near), cam->z_far);
    zf = fmin(fmax(zf, zn), cam->z_far);
    if (!(zf > zn)) sw_keep_sliver(cam_near, cam->z_far, &zn, &zf);
    return sw_setup_range(&rc, &rl, &rs, zn, zf, &H, &o, cam->eye, fw, out, out_points, capacity, out_count);
}

SWARP_API swarp_status swarp_setup(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                                   const swarp_setup_options* opts, swarp_setup_result* out,
                                   swarp_vec3* out_points, size_t capacity, size_t* out_count) {
    return sw_setup_main(cam, light, scene, opts, NULL, out, out_points, capacity, out_count);
}

/* [RHS] §3.2.1 light-space alignment kept coherent over time (src/follow.c) */
SWARP_API swarp_status swarp_setup_follow(const swarp_camera* cam, const swarp_light* light,
                                          const swarp_aabb* scene, const swarp_setup_options* opts,
                                          const swarp_camera* previous_cam, const swarp_setup_result* previous,
                                          swarp_setup_result* out, swarp_vec3* out_points, size_t capacity,
                                          size_t* out_count) {
    if (!previous) return sw_setup_main(cam, light, scene, opts, NULL, out, out_points, capacity, out_count);
    if (!cam || !light || !scene || !out) return SWARP_ERR_NULL_POINTER;
    swarp_setup_options o;
    swarp_status s = sw_check_common(cam, light, opts, &o);
    if (s != SWARP_OK) return s;
    if (previous_cam) {
        s = sw_check_camera_shape(previous_cam);
        if (s != SWARP_OK) return s;
    }
    const swarp_technique tech = sw_resolve_technique(o.technique);
    sw_follow fw;
    s = sw_follow_from_result(previous, cam, previous_cam, tech, &fw);
    if (s != SWARP_OK) return s;
    return sw_setup_main(cam, light, scene, opts, &fw, out, out_points, capacity, out_count);
}

SWARP_API swarp_status swarp_setup_range(const swarp_camera* cam, const swarp_light* light,
                                         const swarp_aabb* scene, double near, double far,
                                         const swarp_setup_options* opts, swarp_setup_result* out,
                                         swarp_vec3* out_points, size_t capacity, size_t* out_count) {
    if (!cam || !light || !scene || !out) return SWARP_ERR_NULL_POINTER;
    swarp_setup_options o;
    swarp_status s = sw_check_common(cam, light, opts, &o);
    if (s != SWARP_OK) return s;
    if ((s = sw_check_view_range(near, far)) != SWARP_OK) return s;
    s = sw_check_box(scene);
    if (s != SWARP_OK) return s;
    swarp_camera rc;
    swarp_light rl;
    swarp_aabb rs;
    if (!sw_rel_scene(cam, light, scene, &rc, &rl, &rs)) return SWARP_ERR_NON_FINITE;
    return sw_setup_range(&rc, &rl, &rs, near, far, NULL, &o, cam->eye, NULL, out, out_points, capacity, out_count);
}

SWARP_API swarp_status swarp_setup_points(const swarp_camera* cam, const swarp_light* light,
                                          const swarp_vec3* points, size_t count, const swarp_vec3* receivers,
                                          size_t receiver_count, double near, double far,
                                          const swarp_setup_options* opts, swarp_setup_result* out) {
    if (!cam || !light || !points || !out) return SWARP_ERR_NULL_POINTER;
    swarp_setup_options o;
    swarp_status s = sw_check_common(cam, light, opts, &o);
    if (s != SWARP_OK) return s;
    if ((s = sw_check_view_range(near, far)) != SWARP_OK) return s;
    if (count == 0 || count > SWARP_BODY_MAX_POINTS ||
        (receivers && (receiver_count == 0 || receiver_count > SWARP_BODY_MAX_POINTS)))
        return SWARP_ERR_INVALID_ARGUMENT;
    for (size_t i = 0; i < count; ++i)
        if (!sw_finite3(&points[i])) return SWARP_ERR_NON_FINITE;
    if (receivers)
        for (size_t i = 0; i < receiver_count; ++i)
            if (!sw_finite3(&receivers[i])) return SWARP_ERR_NON_FINITE;
    /* camera-relative, as swarp_setup (see sw_rel_camera) */
    swarp_camera rc;
    swarp_light rl;
    sw_rel_camera(cam, &rc);
    sw_rel_light(light, cam->eye, &rl);
    swarp_vec3 Br[SWARP_BODY_MAX_POINTS], Hr[SWARP_BODY_MAX_POINTS];
    for (size_t i = 0; i < count; ++i) Br[i] = sw_sub(points[i], cam->eye);
    for (size_t i = 0; receivers && i < receiver_count; ++i) Hr[i] = sw_sub(receivers[i], cam->eye);
    if (!sw_finite3(&rl.position)) return SWARP_ERR_NON_FINITE;
    for (size_t i = 0; i < count; ++i)
        if (!sw_finite3(&Br[i])) return SWARP_ERR_NON_FINITE;
    for (size_t i = 0; receivers && i < receiver_count; ++i)
        if (!sw_finite3(&Hr[i])) return SWARP_ERR_NON_FINITE;
    swarp_setup_result res;
    s = sw_setup_points(&rc, &rl, Br, count, NULL, receivers ? Hr : NULL, receivers ? receiver_count : 0, near, far,
                        &o, cam->eye, NULL, &res);
    if (swarp_status_is_error(s)) return s;
    if (!sw_fold_result(&res, cam->eye)) return SWARP_ERR_DEGENERATE;
    *out = res;
    return s;
}
