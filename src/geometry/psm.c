/* PSM in the camera's post-perspective space (PPS) [KOZ] (GPU Gems ch. 14).
 *
 * The (optionally slid-back) camera's M_c = P_c V_c maps the world to PPS,
 * where the light becomes the homogeneous point L_h = (q_h, w_l): M_c (-d, 0)
 * for a directional light, M_c (l, 1) for a point light.  w_l > 0: an
 * ordinary light at q = q_h / w_l; w_l = 0: a light at infinity in PPS (the
 * light is perpendicular to the view); w_l < 0: the light is behind the
 * camera and its rays run "through infinity" ([KOZ] §14.2.1, Fig. 14-4).
 *
 * One formula handles the three cases continuously.  With q̂ = q_h/|q_h|,
 * τ = w_l/|q_h| and the light camera's axis a = (-q̂ + τ k)/N (N its norm),
 * the light camera's rows over a PPS point (X, w_c) are
 *
 *     x = e1·X - w_c c1,   y = e2·X - w_c c2,   z = a·X,   w = β a·X + w_c,
 *     β = τ N,
 *
 * which is the perspective from q along a divided by w_l (so it stays
 * finite and turns into the orthographic view at w_l = 0).  z/w = u/(1+βu),
 * u = a·x, increases along every light ray; for w_l < 0 (β < 0) it is
 * Kozlov's inverse projection (near < 0 < far): a caster behind the camera
 * (w_c < 0) lies beyond the light (1 + βu < 0), its w = w_c (1 + βu) is
 * positive again, and its depth comes before the receivers'.
 *
 * The axis: [KOZ] §14.2.2 takes the axis of the minimal cone around the
 * receivers' points with apex at the light ("unit cube clipping": the
 * receivers' body, here H = V ∩ S, not the whole unit cube).  We compute it
 * as the smallest spherical cap around the light-to-point directions with
 * Welzl's move-to-front scheme (as Gärtner's smallest enclosing ball,
 * expected linear time).  At τ = 0 all directions coincide: the orthographic
 * rows (axis -q̂) are the exact limit. */
#include <float.h>

#include "geometry/geometry_internal.h"

/* |w_l|/|q_h| below this: the PPS light is at infinity (orthographic rows).
 * The general rows lose ~1e-16/τ relative precision, 1e-7 at the switch,
 * and differ from the limit by O(τ): the switch is continuous to ~1e-7. */
#define SW_PSM_TAU_ORTHO 1e-9
/* cos of the widest angle a receiver may make with the light camera's mean
 * direction.  A light just behind the far face of the unit cube ([KOZ]
 * §14.2.2, Q -> 1) legitimately needs almost 90°: only the truly
 * impossible 90° and beyond is refused. */
#define SW_PSM_MIN_COS 1e-12
/* The thinnest frustum PSM maps: tan of the half-angles (vertical and
 * horizontal) and the depth ratio (far - near)/near of the view range at
 * least this (a slide-back is the caller's choice; sw_psm_covers checks
 * what it gives).  PPS scales the frustum's thin direction by 1/t,
 * so the light lands ~1/t from the unit cube and the light camera's rows
 * cancel terms ~1/t apart to give O(1) map coordinates: the rounding grows
 * like eps/t^2.  Over the coverage sweep (robust_coverage 20000 7) every
 * PSM map out of coverage had t <= 1.8e-5 (up to 4e-5 depth windows out
 * or points behind the light camera); 1e-4 keeps a factor 5 from there.
 * Uniform and LiSPSM maps do not go through PPS and stay available. */
#define SW_PSM_FRUSTUM_MIN 1e-4

/* ---- smallest enclosing cone (spherical cap) ------------------------------
 * Welzl's move-to-front scheme on unit vectors, as Gärtner's smallest
 * enclosing ball: expected linear time; the points must lie in an open
 * hemisphere (checked by the caller through the cap's cos radius). */
typedef struct sw_cap { swarp_vec3 c; double cosr; } sw_cap;

/* The cosine slack of a cap's membership test for the rounding of unit
 * vectors (a few eps each, summed over a dot product), with a margin. */
#define SW_CAP_SLACK 1e-13

static int sw_in_cap(const sw_cap* k, swarp_vec3 r) {
    /* slack SW_CAP_SLACK in the cosine: rounding of unit vectors; plus the
     * rounding of the centre, eps/|a + b| = eps/(2 cos r) rad for the cap of
     * a pair (the sum of two unit vectors all but opposite), which moves
     * c·r by up to that.  Without it, for receivers spanning almost 180° in
     * PPS (cos r = 4e-5) a point 1e-9 from a support falls outside the
     * pair's cap by 5e-12 or not as the rounding falls, and the circle
     * through the three, 3e13 times as sensitive, turns the axis by
     * milliradians. */
    const double slack = SW_CAP_SLACK + (k->cosr > 0.0 ? 4.0 * DBL_EPSILON / k->cosr : 0.0);
    return sw_dot(k->c, r) >= k->cosr - slack;
}
static sw_cap sw_cap2(swarp_vec3 a, swarp_vec3 b) {
    sw_cap k = {a, 1.0};
    if (sw_normalize_fast(sw_add(a, b), &k.c)) k.cosr = sw_dot(k.c, a);
    else k.cosr = -1.0; /* antipodal: no cap smaller than a hemisphere */
    return k;
}
/* The tangential part of the unit vector r at the unit vector a, and the
 * height h = 1 - r·a = |v|^2/(1 + r·a) of r below a's tangent plane.  v
 * carries a rounding relative to its own length (the norm's rounding of r
 * lies along a and drops out), h too (no cancellation in 1 - r·a). */
static swarp_vec3 sw_cap_tangent(swarp_vec3 a, swarp_vec3 r, double* h) {
    const double ra = sw_dot(r, a);
    const swarp_vec3 v = sw_sub(r, sw_scale(a, ra));
    *h = sw_dot(v, v) / (1.0 + ra);
    return v;
}
/* The cap whose circle passes through a, b and c.  Its centre is a + u
 * normalised, u in a's tangent plane with (a + u)·(b - a) = 0, i.e.
 * u·v_b = h_b, and u·v_c = h_c (v, h: sw_cap_tangent).  Solved there, u is
 * resolved to eps of its size, whatever the radius.  The plane normal
 * (b - a) x (c - a) is not: the rounding of a unit vector's norm (eps,
 * radial) moves b - a along a by eps, which tilts the normal by eps/|b - a|,
 * 1/sin(r) times what the directions' own (tangential) rounding does: for
 * two vertices 6e-6 apart on a cap of 0.007 rad a tilt of 4e-11 rad of the
 * axis, which the PSM row offsets (e·q̂)/τ magnify by 1/τ. */
static sw_cap sw_cap3(swarp_vec3 a, swarp_vec3 b, swarp_vec3 c) {
    sw_cap k;
    double hb, hc;
    const swarp_vec3 vb = sw_cap_tangent(a, b, &hb), vc = sw_cap_tangent(a, c, &hc);
    /* u = (h_b (v_c x a) + h_c (a x v_b))/det, det = a·(v_b x v_c): u·v_b =
     * h_b, u·v_c = h_c, and u ⊥ a even when v_b, v_c are all but parallel
     * (a, b, c near one great circle: a cap of almost 90°) */
    const double det = sw_dot(a, sw_cross(vb, vc));
    const swarp_vec3 u = sw_scale(sw_add(sw_scale(sw_cross(vc, a), hb), sw_scale(sw_cross(a, vb), hc)), 1.0 / det);
    if (!(det != 0.0) || !sw_normalize_fast(sw_add(a, u), &k.c)) { /* on one great circle: the widest pair */
        sw_cap k1 = sw_cap2(a, b), k2 = sw_cap2(a, c), k3 = sw_cap2(b, c);
        k = k1;
        if (k2.cosr < k.cosr) k = k2;
        if (k3.cosr < k.cosr) k = k3;
        return k;
    }
    /* the centre a + u lies on a's side: the smaller of the circle's caps */
    k.cosr = sw_dot(k.c, a);
    return k;
}
static sw_cap sw_min_cap(const swarp_vec3* r, size_t n) {
    sw_cap k = {r[0], 1.0};
    for (size_t i = 1; i < n; ++i) {
        if (sw_in_cap(&k, r[i])) continue;
        k.c = r[i], k.cosr = 1.0;
        for (size_t j = 0; j < i; ++j) {
            if (sw_in_cap(&k, r[j])) continue;
            k = sw_cap2(r[i], r[j]);
            for (size_t m = 0; m < j; ++m)
                if (!sw_in_cap(&k, r[m])) k = sw_cap3(r[i], r[j], r[m]);
        }
    }
    return k;
}

/* A unit vector perpendicular to n that varies smoothly with n: the PPS x
 * axis projected, blended with the y axis near the (unavoidable) singular
 * direction n = ±x, as in the light view (SWARP_FOCUS_BLEND_SIN). */
static swarp_vec3 sw_perp_ref(swarp_vec3 n) {
    swarp_vec3 x = sw_v3(1, 0, 0), y = sw_v3(0, 1, 0);
    swarp_vec3 px = sw_sub(x, sw_scale(n, n.x));
    double s = sw_len_fast(px);
    if (s < SWARP_FOCUS_BLEND_SIN) {
        double t = 1.0 - s / SWARP_FOCUS_BLEND_SIN;
        swarp_vec3 py = sw_sub(y, sw_scale(n, n.y));
        px = sw_add(px, sw_scale(py, SWARP_FOCUS_BLEND_WEIGHT * t * t));
    }
    swarp_vec3 b = {0, 0, 1};
    if (!sw_normalize_fast(px, &b)) sw_normalize_fast(sw_cross(n, sw_v3(0, 0, 1)), &b);
    return b;
}

/* The shortest sw_perp_ref's projection gets before it is normalised: it
 * is blended away from its zero and is at least 0.08 long; 0.05 is the
 * length its rounding (sw_follow_aligned_tol) is bounded with. */
#define SW_PERP_REF_MIN_LEN 0.05

/* swarp_setup_follow: the light camera's right vector e1 follows the
 * previous one (follow.c) toward the stateless e1 (given in *e1: the
 * post-perspective x axis projected perpendicular to the axis, sw_perp_ref),
 * by at most SWARP_FOLLOW_KAPPA times the angle the axis turned; the sign of
 * the target is free (PSM has no preferred orientation).  Returns 0 when
 * the previous right vector lies along the axis (e1 stays the target). */
static int sw_psm_follow_e1(const sw_follow* fw, swarp_vec3 a, swarp_vec3* e1, int* lag) {
    swarp_vec3 h, t = *e1;
    *lag = 0;
    swarp_vec3 ph = sw_sub(fw->up, sw_scale(a, sw_dot(fw->up, a)));
    const double s_h = sw_len_fast(ph);
    /* below SW_FOLLOW_PERP_MIN the projected direction is rounding noise
     * (the previous axis was 90° away: nothing to follow, take the target) */
    if (!(s_h > SW_FOLLOW_PERP_MIN) || !sw_normalize_fast(ph, &h)) return 0;
    /* the axis' sign is free in a previous result: the angle between lines */
    double delta = atan2(sw_len_fast(sw_cross(fw->axis, a)), fabs(sw_dot(fw->axis, a)));
    if (sw_dot(h, t) < 0.0) t = sw_scale(t, -1.0);
    h = sw_follow_turn(h, t, a, SWARP_FOLLOW_KAPPA * delta, sw_follow_aligned_tol(s_h, SW_PERP_REF_MIN_LEN), lag);
    swarp_vec3 p = sw_sub(h, sw_scale(a, sw_dot(h, a)));
    return sw_normalize_fast(p, e1);
}

/* PSM_INVERSE is the more important information */
static swarp_status sw_info_follow(swarp_status info) {
    return info == SWARP_OK ? SWARP_INFO_FOLLOW_LAG : info;
}

/* The camera (possibly slid back by delta) as M_c = P_c V_c, GL depth;
 * P_c is returned too: light_proj is formed from it, not from M_c V_c^-1
 * (see sw_psm_result). */
static void sw_camera_matrix(const swarp_camera* cam, double near, double far, double delta, swarp_mat4* Mc,
                             swarp_mat4* Vc, swarp_mat4* Pc) {
    swarp_vec3 f, r, u;
    sw_camera_basis(cam, &f, &r, &u);
    swarp_vec3 eye = sw_sub(cam->eye, sw_scale(f, delta));
    sw_look_at(eye, f, u, Vc);
    double n = near + delta, fa = far + delta;
    double ty = tan(0.5 * cam->fovy), tx = ty * cam->aspect;
    memset(Pc, 0, sizeof *Pc);
    sw_set(Pc, 0, 0, 1.0 / tx);
    sw_set(Pc, 1, 1, 1.0 / ty);
    sw_set(Pc, 2, 2, -(fa + n) / (fa - n));
    sw_set(Pc, 2, 3, -2.0 * fa * n / (fa - n));
    sw_set(Pc, 3, 2, -1.0);
    sw_mul(Pc, Vc, Mc);
}

/* Is p in front of the light camera QM by more than the rounding of its w
 * (64 eps of the sizes of the terms summed)?  A point on the light's own
 * plane w = 0 -- the light itself, a vertex of B when it lies in the scene
 * box ([RHS] §3.1.1: B = conv(H ∪ {l}) ∩ S) -- has w = 0 up to that
 * rounding, whose sign is the rounding's: taken as a caster its depth z/w
 * (~1e15) would stretch the depth extent until the fit called x and y flat
 * beside it and the map collapsed.  It casts no shadow into the light
 * frustum.
 *
 * wab: the sizes of the terms of QM's w row as the product Q M_c summed
 * them, sum_k |Q_3k| |M_c,kj|.  QM's entries carry eps of those terms, more
 * than eps of the entries themselves where the terms cancel (a scene far
 * from the origin, the light near the eye), so w at p is rounded to eps of
 * sum_j wab_j |p_j| too; with only its own terms as the bound, the light
 * could pass as a caster with w > 0 by rounding alone. */
static int sw_psm_in_front(const swarp_mat4* QM, const double wab[4], swarp_vec3 p) {
    const double t0 = sw_at(QM, 3, 0) * p.x, t1 = sw_at(QM, 3, 1) * p.y, t2 = sw_at(QM, 3, 2) * p.z, t3 = sw_at(QM, 3, 3);
    const double terms = fmax(fabs(t0) + fabs(t1) + fabs(t2) + fabs(t3),
                              wab[0] * fabs(p.x) + wab[1] * fabs(p.y) + wab[2] * fabs(p.z) + wab[3]);
    return t0 + t1 + t2 + t3 > 64.0 * DBL_EPSILON * terms;
}

/* Virtual slide-back [KOZ] Fig. 14-6: the eye moved back by delta, near
 * and far moved with it, so the near plane stays where it was.  Automatic
 * (psm_slideback without a given delta): every point of B in front of the
 * virtual camera. */
static double sw_psm_slideback(const swarp_camera* cam, swarp_vec3 f, const swarp_vec3* B, size_t nb, double near,
                               const swarp_setup_options* o) {
    double delta = o->slideback;
    if (o->psm_slideback && delta == 0.0) {
        double zmin = INFINITY;
        for (size_t i = 0; i < nb; ++i) zmin = sw_min(zmin, sw_dot(sw_sub(B[i], cam->eye), f));
        if (zmin < near) delta = near - zmin;
    }
    return delta;
}

/* The light in PPS, L_h = M_c (l, 1) or M_c (-d, 0), normalised
 * homogeneous: q̂ = q_h/|q_h| and τ = w_l/|q_h| (0: the light at infinity in
 * PPS).  *inverse: w_l < 0, the light behind the camera ([KOZ] §14.2.1). */
static swarp_status sw_psm_light_pps(const swarp_light* light, const swarp_mat4* Mc, swarp_vec3* qn, double* tau,
                                     int* inverse) {
    swarp_vec4 Lw = light->type == SWARP_LIGHT_POINT
                        ? (swarp_vec4){light->position.x, light->position.y, light->position.z, 1.0}
                        : (swarp_vec4){-light->direction.x, -light->direction.y, -light->direction.z, 0.0};
    swarp_vec4 Lh = sw_xform4(Mc, Lw);
    swarp_vec3 qh = sw_v3(Lh.x, Lh.y, Lh.z);
    double qlen = sw_len_fast(qh);
    if (!(qlen > 0.0)) return SWARP_ERR_LIGHT_INSIDE_BODY; /* the light is the eye itself */
    *qn = sw_scale(qh, 1.0 / qlen);
    *tau = Lh.w / qlen;
    *inverse = Lh.w < 0.0;
    return SWARP_OK;
}

/* The receivers' centroid in PPS (reference point of the depth row). */
static swarp_status sw_psm_centroid(const swarp_mat4* Mc, const swarp_vec3* H, size_t nh, swarp_vec3* p0) {
    swarp_vec3 c = {0, 0, 0};
    for (size_t i = 0; i < nh; ++i) {
        swarp_vec4 X = sw_xform_point(Mc, H[i]);
        if (!(X.w > 0.0)) return SWARP_ERR_DEGENERATE;
        c = sw_add(c, sw_v3(X.x / X.w, X.y / X.w, X.z / X.w));
    }
    *p0 = sw_scale(c, 1.0 / (double)nh);
    return SWARP_OK;
}

/* The light camera's frame in PPS and its row offsets (see the top):
 * x = e1·X - w_c cx1, y = e2·X - w_c cx2, z = a·X, w = wa a·X + ww w_c. */
typedef struct sw_psm_rows {
    swarp_vec3 a, e1, e2;
    double cx1, cx2; /* x, y row offsets: (e·q̂)/τ */
    double wa, ww;
} sw_psm_rows;

/* The light camera's roll: e1 the PPS x axis projected perpendicular to the
 * axis (blended near a = ±x), a function of the axis alone, so that the
 * follow rule's budget κΔ (Δ: the axis' turn) covers the target's motion;
 * followed from fw when given (*lag: it stopped short). */
static void sw_psm_roll(const sw_follow* fw, sw_psm_rows* q, int* lag) {
    q->e1 = sw_perp_ref(q->a);
    *lag = 0;
    if (fw && !sw_psm_follow_e1(fw, q->a, &q->e1, lag)) *lag = 0;
    q->e2 = sw_cross(q->a, q->e1);
}

/* The axis of the minimal cone around the light-to-receiver directions
 * R = τ x - q̂ (homogeneous-safe, w_c = 1) [KOZ] §14.2.2. */
static swarp_status sw_psm_cone_axis(const swarp_mat4* Mc, const swarp_vec3* H, size_t nh, swarp_vec3 qn, double tau,
                                     swarp_vec3* a) {
    swarp_vec3 rd[SWARP_BODY_MAX_POINTS];
    size_t nr = 0;
    for (size_t i = 0; i < nh && nr < SWARP_BODY_MAX_POINTS; ++i) {
        swarp_vec4 X = sw_xform_point(Mc, H[i]);
        if (!(X.w > 0.0)) return SWARP_ERR_DEGENERATE;
        swarp_vec3 x = sw_v3(X.x / X.w, X.y / X.w, X.z / X.w);
        swarp_vec3 R = sw_sub(sw_scale(x, tau), qn);
        if (!sw_normalize_fast(R, &rd[nr])) return SWARP_ERR_LIGHT_INSIDE_BODY; /* receiver at the light */
        ++nr;
    }
    if (nr == 0) return SWARP_ERR_BODY_EMPTY;
    sw_cap cap = sw_min_cap(rd, nr);
    /* a cone of 90° or more: the light sits among the receivers */
    if (!(cap.cosr > SW_PSM_MIN_COS)) return SWARP_ERR_LIGHT_INSIDE_BODY;
    *a = cap.c;
    return SWARP_OK;
}

/* The light camera's rows: orthographic along -q̂ when the light is at
 * infinity in PPS (the limit of the general rows, up to a translation A_fit
 * absorbs), else the perspective from q̂ along the cone axis divided by w_l. */
static swarp_status sw_psm_light_rows(const swarp_mat4* Mc, const swarp_vec3* H, size_t nh, swarp_vec3 qn, double tau,
                                      const sw_follow* fw, sw_psm_rows* q, int* lag) {
    q->cx1 = 0.0, q->cx2 = 0.0;
    q->wa = 0.0, q->ww = 1.0;
    if (fabs(tau) < SW_PSM_TAU_ORTHO) {
        q->a = sw_scale(qn, -1.0);
        sw_psm_roll(fw, q, lag);
        return SWARP_OK;
    }
    swarp_status s = sw_psm_cone_axis(Mc, H, nh, qn, tau, &q->a);
    if (s != SWARP_OK) return s;
    sw_psm_roll(fw, q, lag);
    /* rows: x = e1·R/w_l = e1·X - w_c (e1·q̂)/τ (finite as τ -> 0: the
     * axis tilts away from -q̂ by O(τ); the rounding of e1·q̂ only moves
     * the image, which A_fit absorbs); w = a·R/|q_h| > 0 */
    q->cx1 = sw_dot(q->e1, qn) / tau;
    q->cx2 = sw_dot(q->e2, qn) / tau;
    q->wa = tau;
    q->ww = -sw_dot(q->a, qn);
    return SWARP_OK;
}

/* The light camera Q over PPS from its rows.  Depth z = a·(X - w_c p0), p0
 * the receivers' centroid in PPS: then z/w = (u - u0)/(c0 + τu) has
 * derivative a·R(p0)/(...)^2 > 0, i.e. it increases along every light ray
 * for any position of the origin. */
static void sw_psm_light_camera(const sw_psm_rows* q, swarp_vec3 p0, swarp_mat4* Q) {
    const swarp_vec3 a = q->a, e1 = q->e1, e2 = q->e2;
    const double wa = q->wa;
    memset(Q, 0, sizeof *Q);
    sw_set(Q, 0, 0, e1.x), sw_set(Q, 0, 1, e1.y), sw_set(Q, 0, 2, e1.z), sw_set(Q, 0, 3, -q->cx1);
    sw_set(Q, 1, 0, e2.x), sw_set(Q, 1, 1, e2.y), sw_set(Q, 1, 2, e2.z), sw_set(Q, 1, 3, -q->cx2);
    sw_set(Q, 2, 0, a.x), sw_set(Q, 2, 1, a.y), sw_set(Q, 2, 2, a.z), sw_set(Q, 2, 3, -sw_dot(a, p0));
    sw_set(Q, 3, 0, wa * a.x), sw_set(Q, 3, 1, wa * a.y), sw_set(Q, 3, 2, wa * a.z), sw_set(Q, 3, 3, q->ww);
}

/* The casters that can shadow the receivers, for the depth range ([KOZ]
 * §14.2.2 unit cube clipping): H, and B inside the light frustum over the
 * receivers' window F = A QM (its four side planes pulled back to world
 * space; this also keeps w > 0).  Clipping B, rather than dropping points
 * with w <= 0, keeps the depth range continuous as the light moves.
 * Without B's polyhedron (swarp_setup_points) the points of B in front of
 * the light camera are used. */
static size_t sw_psm_casters(const swarp_vec3* B, size_t nb, const swarp_polyhedron* B_poly, const swarp_vec3* H,
                             size_t nh, const swarp_mat4* A, const swarp_mat4* QM, const double wab[4], int pancake,
                             swarp_vec3* zp) {
    size_t nz = 0;
    for (size_t i = 0; i < nh && nz < SWARP_BODY_MAX_POINTS; ++i) zp[nz++] = H[i];
    if (pancake) return nz;
    if (!B_poly) {
        for (size_t i = 0; i < nb && nz < SWARP_BODY_MAX_POINTS + SWARP_POLY_MAX_VERTICES; ++i)
            if (sw_psm_in_front(QM, wab, B[i])) zp[nz++] = B[i];
        return nz;
    }
    swarp_mat4 F;
    sw_mul(A, QM, &F);
    swarp_polyhedron C;
    sw_poly_copy(B_poly, &C);
    for (int k = 0; k < 4 && C.vertex_count > 0; ++k) {
        int row = k / 2;
        double sg = (k & 1) ? -1.0 : 1.0; /* sg·(row) - w <= 0 */
        swarp_vec3 n = sw_v3(sg * sw_at(&F, row, 0) - sw_at(&F, 3, 0), sg * sw_at(&F, row, 1) - sw_at(&F, 3, 1),
                             sg * sw_at(&F, row, 2) - sw_at(&F, 3, 2));
        double d = sg * sw_at(&F, row, 3) - sw_at(&F, 3, 3);
        if (sw_poly_clip(&C, n, d, &C) != SWARP_OK) break;
    }
    for (uint32_t i = 0; i < C.vertex_count; ++i)
        if (sw_psm_in_front(QM, wab, C.vertices[i])) zp[nz++] = C.vertices[i];
    return nz;
}

/* The result's matrices and figures.  light_proj = A Q P_c with the camera
 * projection itself: recovered as M_c V_c^-1 it would carry the rounding of
 * V_c's translation (the slid-back eye, delta from the camera) times P_c,
 * eps delta absolute in entries that are 0 (a slide-back of 1e12 puts 1e6
 * where 0 belongs, in a sign the rounding picks), and light_proj light_view
 * would be off the matrix by far more than its rounding. */
static void sw_psm_result(const swarp_camera* cam, const swarp_light* light, swarp_vec3 f, const swarp_mat4* A,
                          const swarp_mat4* Q, const swarp_mat4* QM, const swarp_mat4* Vc, const swarp_mat4* Pc,
                          double n_eye, const swarp_vec3* zp, size_t nz, swarp_setup_result* res) {
    swarp_mat4 AQ;
    sw_mul(A, Q, &AQ);
    sw_mul(&AQ, Pc, &res->light_proj);
    res->light_view = *Vc;
    sw_mul(A, QM, &res->matrix);
    res->n_eye = n_eye; /* [RHS] (2.5)-(2.6): n' = n for PSM */
    res->n_light = n_eye;
    res->gamma = 0.0;
    swarp_vec3 ld = {0, 0, 0};
    if (light->type == SWARP_LIGHT_POINT) {
        sw_normalize_fast(sw_sub(cam->eye, light->position), &ld);
    } else {
        sw_normalize_fast(light->direction, &ld);
    }
    res->gamma = acos(sw_max(-1.0, sw_min(1.0, sw_dot(ld, f))));
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < nz; ++i) {
        swarp_vec4 h = sw_xform_point(QM, zp[i]);
        lo = sw_min(lo, h.z / h.w);
        hi = sw_max(hi, h.z / h.w);
    }
    res->light_near = lo;
    res->light_far = hi;
}

/* The map's defining property, checked on the receivers: a receiver h and
 * the point toward the light from it (by B's extent for a directional
 * light, half-way for a point light) must land on the same map point to
 * SW_PSM_RAY_TOL.  Exact in PPS for every frustum, it fails in double where
 * the light sits at 1/τ ~ 1e10 in PPS (fovy or aspect 1e-9, far within
 * 1e-9 of near): the orthographic limit of the rows is off by τ times the
 * casters' PPS distance (unbounded toward the eye plane), the general rows
 * by eps/τ, and the map spreads one light ray over the whole map. */
#define SW_PSM_RAY_TOL 2e-6
/* B's largest extent along an axis */
static double sw_psm_extent(const swarp_vec3* B, size_t nb) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < nb; ++i) {
        const double c[3] = {B[i].x, B[i].y, B[i].z};
        for (int k = 0; k < 3; ++k) lo[k] = fmin(lo[k], c[k]), hi[k] = fmax(hi[k], c[k]);
    }
    return fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
}
static int sw_psm_projects_along_light(const swarp_mat4* m, const swarp_light* light, const swarp_vec3* H, size_t nh,
                                       const swarp_vec3* B, size_t nb) {
    const double ext = sw_psm_extent(B, nb);
    swarp_vec3 d = {0, 0, 0};
    if (light->type != SWARP_LIGHT_POINT) sw_normalize_fast(light->direction, &d);
    for (size_t i = 0; i < nh; ++i) {
        swarp_vec3 q = light->type == SWARP_LIGHT_POINT ? sw_scale(sw_add(H[i], light->position), 0.5)
                                                        : sw_sub(H[i], sw_scale(d, ext));
        swarp_vec4 a = sw_xform_point(m, H[i]), b = sw_xform_point(m, q);
        if (!(a.w != 0.0 && b.w != 0.0)) return 0;
        if (!(fabs(a.x / a.w - b.x / b.w) <= SW_PSM_RAY_TOL && fabs(a.y / a.w - b.y / b.w) <= SW_PSM_RAY_TOL)) return 0;
    }
    return 1;
}

/* The rest of the promise, checked on the map itself: every receiver of H
 * inside the map and its depth window, and the points of B on the segment
 * from each receiver toward the light (at SW_PSM_SEG_FRAC of B's extent for
 * a directional light, of the way for a point light) in front of the light
 * camera and inside the window (pancaking: in front, at most the window's
 * far end).  Exact in PPS, these fail in double at extreme frusta (fovy,
 * aspect or (far - near)/near of 1e-7..1e-4, the light at 1/τ up to 1e7 in
 * PPS): the rows carry eps/τ of rounding, which moves points past the
 * window's ends by up to 1e-5 of its width or behind the light camera.
 * The matrix is evaluated in long double so that the check measures the
 * map, not the rounding of the check; SW_PSM_COVER_TOL is 1/10 of the
 * accuracy the fit promises (1e-6 of the map's and window's width,
 * SW_REL_RESOLVE in setup.c), so a map that passes keeps that promise. */
#define SW_PSM_COVER_TOL 1e-7
static const double SW_PSM_SEG_FRAC[] = {1e-6, 1e-3, 0.01, 0.1, 0.25, 0.5, 0.75, 0.99};
static int sw_psm_eval_ld(const swarp_mat4* m, swarp_vec3 p, long double out[3]) {
    const double* a = m->m;
    const long double X = (long double)a[0] * p.x + (long double)a[4] * p.y + (long double)a[8] * p.z + a[12];
    const long double Y = (long double)a[1] * p.x + (long double)a[5] * p.y + (long double)a[9] * p.z + a[13];
    const long double Z = (long double)a[2] * p.x + (long double)a[6] * p.y + (long double)a[10] * p.z + a[14];
    const long double W = (long double)a[3] * p.x + (long double)a[7] * p.y + (long double)a[11] * p.z + a[15];
    if (!(W > 0)) return 0;
    out[0] = X / W, out[1] = Y / W, out[2] = Z / W;
    return 1;
}
static int sw_psm_in_poly(const swarp_polyhedron* P, swarp_vec3 p, double slack) {
    for (uint32_t k = 0; k < P->face_count; ++k) {
        const swarp_plane* q = &P->planes[k];
        if (q->a * p.x + q->b * p.y + q->c * p.z + q->d > slack) return 0;
    }
    return 1;
}
static int sw_psm_covers(const swarp_mat4* m, const swarp_light* light, const swarp_vec3* H, size_t nh,
                         const swarp_polyhedron* B_poly, double ext, swarp_depth_range dr, int pancake) {
    const long double lo = dr == SWARP_DEPTH_NEG_ONE_TO_ONE ? -1.0L : 0.0L, hi = 1.0L, w = hi - lo;
    const long double tol = SW_PSM_COVER_TOL;
    const int rev = dr == SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
    const double slack = 4.0 * SWARP_POLY_EPS_REL * (B_poly ? sw_poly_scale(B_poly) : 0.0);
    swarp_vec3 d = {0, 0, 0};
    if (light->type != SWARP_LIGHT_POINT) sw_normalize_fast(light->direction, &d);
    for (size_t i = 0; i < nh; ++i) {
        long double h[3];
        if (!sw_psm_eval_ld(m, H[i], h)) return 0;
        if (!(fabsl(h[0]) <= 1 + tol && fabsl(h[1]) <= 1 + tol)) return 0;
        if (!(h[2] >= lo - tol * w && h[2] <= hi + tol * w)) return 0;
        if (!B_poly) continue; /* without B's polyhedron a point of the segment may lie outside S */
        for (size_t k = 0; k < sizeof SW_PSM_SEG_FRAC / sizeof SW_PSM_SEG_FRAC[0]; ++k) {
            const double t = SW_PSM_SEG_FRAC[k];
            const swarp_vec3 q = light->type == SWARP_LIGHT_POINT
                                     ? sw_add(H[i], sw_scale(sw_sub(light->position, H[i]), t))
                                     : sw_sub(H[i], sw_scale(d, t * ext));
            /* only points inside B by more than the clipper's tolerance: one
             * just outside a B thin along the light may lie past the window
             * by far more than its width (a flat B, FLAT_EXTENT) */
            if (!sw_psm_in_poly(B_poly, q, -slack)) continue;
            long double c[3];
            if (!sw_psm_eval_ld(m, q, c)) return 0;
            /* pancaking: casters nearer the light than the window are clamped
             * to its near end, which reversed depth puts at 1 */
            const int near_ok = pancake && !rev ? 1 : c[2] >= lo - tol * w;
            const int far_ok = pancake && rev ? 1 : c[2] <= hi + tol * w;
            if (!near_ok || !far_ok) return 0;
        }
    }
    return 1;
}

swarp_status sw_psm_setup(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B, size_t nb,
                          const swarp_polyhedron* B_poly, const swarp_vec3* H, size_t nh, double near, double far,
                          const swarp_setup_options* o, const sw_follow* fw, swarp_setup_result* res) {
    swarp_depth_range dr = o->depth_range == SWARP_DEPTH_DEFAULT ? SWARP_DEPTH_NEG_ONE_TO_ONE : o->depth_range;
    swarp_status info = SWARP_OK;
    if (!H) H = B, nh = nb;
    swarp_vec3 f, r, u;
    sw_camera_basis(cam, &f, &r, &u);
    const double delta = sw_psm_slideback(cam, f, B, nb, near, o);
    const double ty = tan(0.5 * cam->fovy);
    if (!(fmin(ty, ty * cam->aspect) >= SW_PSM_FRUSTUM_MIN && (far - near) >= SW_PSM_FRUSTUM_MIN * near))
        return SWARP_ERR_DEGENERATE;
    swarp_mat4 Mc, Vc, Pc;
    sw_camera_matrix(cam, near, far, delta, &Mc, &Vc, &Pc);
    swarp_vec3 qn;
    double tau;
    int inverse;
    swarp_status s = sw_psm_light_pps(light, &Mc, &qn, &tau, &inverse);
    if (s != SWARP_OK) return s;
    if (inverse) info = SWARP_INFO_PSM_INVERSE;
    swarp_vec3 p0;
    s = sw_psm_centroid(&Mc, H, nh, &p0);
    if (s != SWARP_OK) return s;
    sw_psm_rows q;
    int lag = 0;
    s = sw_psm_light_rows(&Mc, H, nh, qn, tau, fw, &q, &lag);
    if (s != SWARP_OK) return s;
    if (lag) info = sw_info_follow(info);
    swarp_mat4 Q, QM;
    sw_psm_light_camera(&q, p0, &Q);
    sw_mul(&Q, &Mc, &QM);
    double wab[4];
    for (int j = 0; j < 4; ++j) {
        wab[j] = 0.0;
        for (int k = 0; k < 4; ++k) wab[j] += fabs(sw_at(&Q, 3, k)) * fabs(sw_at(&Mc, k, j));
    }
    /* a receiver on the light's plane w = 0 up to rounding (the light
     * itself, a vertex of B, when B is the receivers: swarp_setup_points
     * without H) is as much "among the receivers" as one behind it: its w
     * is the rounding's sign, and counted in front it would collapse the
     * map around it (SWARP_INFO_FLAT_EXTENT) */
    for (size_t i = 0; i < nh; ++i)
        if (!sw_psm_in_front(&QM, wab, H[i])) return SWARP_ERR_LIGHT_INSIDE_BODY;
    /* x, y over the receivers H ([KOZ] §14.2.2), then depth over the casters */
    swarp_mat4 A;
    s = sw_focus_fit(&QM, H, nh, NULL, 0, dr, NULL, &A);
    if (swarp_status_is_error(s)) return s;
    swarp_vec3 zp[SWARP_BODY_MAX_POINTS + SWARP_POLY_MAX_VERTICES];
    const size_t nz = sw_psm_casters(B, nb, B_poly, H, nh, &A, &QM, wab, o->pancake, zp);
    s = sw_focus_fit(&QM, H, nh, zp, nz, dr, NULL, &A);
    if (swarp_status_is_error(s)) return s;
    if (s != SWARP_OK && info == SWARP_OK) info = s;
    sw_psm_result(cam, light, f, &A, &Q, &QM, &Vc, &Pc, near + delta, zp, nz, res);
    if (!sw_psm_projects_along_light(&res->matrix, light, H, nh, B, nb)) return SWARP_ERR_DEGENERATE;
    if (!sw_psm_covers(&res->matrix, light, H, nh, B_poly, sw_psm_extent(B, nb), dr, o->pancake))
        return SWARP_ERR_DEGENERATE;
    return info;
}
