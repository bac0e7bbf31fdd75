/* The convex intersection body B of [RHS] §3.1.1 (Fig. 3.2, [WS06]) and the
 * adjusted near/far of [RHS] §3.3.1 ([ZSN07]).
 *
 *   H = V ∩ S
 *   directional light:  B = (H swept against the light direction) ∩ S
 *   point light:        B = conv(H ∪ {l}) ∩ S ∩ L
 *
 * The sweep H + {t u : t >= 0} (u = -light direction) is built explicitly as
 * conv(H ∪ (H + T u)) with T longer than the diagonal of S: faces of H that
 * face u move to H + T u, the others stay, and each silhouette edge between
 * the two kinds becomes a quad.  Clipping by S then cuts it where the
 * extrusion leaves S, exactly "extrude each point of H until it leaves S,
 * then ∩ S".  conv(H ∪ {l}) is built the same way with the faces visible
 * from l replaced by triangles to l.  A flat H (flat scene box) is handled
 * as a polygon in its plane. */
#include "geometry/geometry_internal.h"
#include <float.h>

/* Faces of H whose plane passes within this many scale units of the light
 * position count as not visible from it (the light lies on their plane). */
#define SW_BODY_VISIBLE_EPS_REL 1e-12
/* A directional light whose direction makes a cosine below this with a
 * flat H's normal grazes its plane: the rounding of unit vectors (a few
 * eps), so B is built in the plane (sw_flat_extend). */
#define SW_BODY_GRAZING_COS 1e-15
/* The longest sweep relative to H's size: B's vertices stay within 1e10
 * times H's extent of it, where the clipper (SWARP_POLY_EPS_REL = 1e-12 of
 * the polyhedron's scale) still resolves H to 1e-2 of its size and the fit
 * (SW_FIT_FLAT_REL, focus.c) does not call H's lateral extent flat beside
 * B's length.  Casters farther toward the light are left out of B (the
 * caller reports SWARP_INFO_CASTERS_CLAMPED: a renderer with depth
 * clamping draws them at the near plane, where they still shadow every
 * receiver behind them, as with pancaking). */
#define SW_SWEEP_REL_MAX 1e10
/* The longest sweep kept at 2 diag(S), relative to H's size: the swept
 * copies within 1e6 times H's size, where the clipper's tolerance is 1e-6
 * of H's size at most (the fit's own accuracy, SW_REL_RESOLVE in setup.c);
 * ordinary scenes (S up to 1e5 times the receivers) keep that sweep. */
#define SW_SWEEP_DIAG_REL 1e6
/* How far past S's face the exit bound takes the copies, relative to H's
 * coordinates: 1e3 times the clipper's tolerance SWARP_POLY_EPS_REL. */
#define SW_SWEEP_MARGIN_REL 1e-9
/* The longest sweep H + T u: finite for |H| below DBL_MAX/2; a sweep that
 * stays inside S longer than that leaves the double range (B's vertices
 * checked: SWARP_ERR_OUT_OF_RANGE). */
#define SW_SWEEP_T_MAX (0.25 * DBL_MAX)

static int sw_face_is_front(swarp_plane p, swarp_vec3 u) {
    double c = p.a * u.x + p.b * u.y + p.c * u.z;
    if (c != 0.0) return c > 0.0;
    /* exactly parallel: tie-break on the normal so that of two opposite
     * faces (a flat H) exactly one is "front" */
    if (p.a != 0.0) return p.a > 0.0;
    if (p.b != 0.0) return p.b > 0.0;
    return p.c > 0.0;
}

static swarp_vec3 sw_plane_n(swarp_plane p) { return sw_v3(p.a, p.b, p.c); }

/* Is H flat (all vertices on the plane of face 0)? */
static int sw_poly_is_flat(const swarp_polyhedron* H) {
    if (H->face_count == 0) return 1;
    const double eps = SWARP_POLY_EPS_REL * 4.0 * sw_poly_scale(H);
    swarp_plane p = H->planes[0];
    for (uint32_t i = 0; i < H->vertex_count; ++i) {
        double d = p.a * H->vertices[i].x + p.b * H->vertices[i].y + p.c * H->vertices[i].z + p.d;
        if (fabs(d) > eps) return 0;
    }
    return 1;
}

/* A flat polyhedron (two opposite faces) from a convex loop of points. */
static swarp_status sw_poly_flat_from_loop(const swarp_vec3* pts, uint32_t n, swarp_vec3 normal,
                                           swarp_polyhedron* out) {
    if (n > SWARP_POLY_MAX_FACE_VERTICES || n > SWARP_POLY_MAX_VERTICES) return SWARP_ERR_CAPACITY;
    out->vertex_count = n;
    for (uint32_t i = 0; i < n; ++i) out->vertices[i] = pts[i];
    if (n < 3) {
        out->face_count = 0;
        return SWARP_OK;
    }
    double d = -sw_dot(normal, pts[0]);
    out->face_count = 2;
    out->planes[0] = (swarp_plane){normal.x, normal.y, normal.z, d};
    out->planes[1] = (swarp_plane){-normal.x, -normal.y, -normal.z, -d};
    out->face_vertex_count[0] = out->face_vertex_count[1] = n;
    for (uint32_t i = 0; i < n; ++i) {
        out->face_vertices[0][i] = (uint8_t)i;
        out->face_vertices[1][i] = (uint8_t)(n - 1 - i);
    }
    return SWARP_OK;
}

/* In-plane version for a flat H: the loop of face 0 (CCW about its normal n).
 * Directional (point == NULL): hull of the polygon and its translate by T u.
 * Point light: hull of the polygon and the point. */
static swarp_status sw_flat_extend(const swarp_polyhedron* H, swarp_vec3 u, double T,
                                   const swarp_vec3* point, swarp_polyhedron* out) {
    if (H->face_count == 0) { /* a point or nothing: kept as it is */
        sw_poly_copy(H, out);
        return SWARP_OK;
    }
    const uint8_t* loop = H->face_vertices[0];
    uint32_t k = H->face_vertex_count[0];
    swarp_vec3 n = sw_plane_n(H->planes[0]);
    const double eps = SW_BODY_VISIBLE_EPS_REL * sw_poly_scale(H);
    int cls[SWARP_POLY_MAX_FACE_VERTICES]; /* edge i = (v_i -> v_i+1) front/visible */
    for (uint32_t i = 0; i < k; ++i) {
        swarp_vec3 a = H->vertices[loop[i]], b = H->vertices[loop[i + 1 == k ? 0 : i + 1]];
        swarp_vec3 m = sw_cross(sw_sub(b, a), n); /* outward in-plane edge normal */
        if (point)
            cls[i] = sw_dot(m, sw_sub(*point, a)) > eps * sw_len_fast(m);
        else
            cls[i] = sw_dot(m, u) > 0.0;
    }
    /* The sweep stays in H's plane: u less its normal part (the light
     * grazes the plane within SW_BODY_GRAZING_COS, the caller's test).
     * With u's normal part kept (up to 1e-15), H + T u would move the
     * copies off the plane by T times that, which can round to the plane or
     * an ulp off it (1.5e-11 at x = 1e5) as the rounding falls; B would
     * then be flat (SWARP_INFO_FLAT_EXTENT) or an ulp thick, finer than
     * the coordinates resolve (SWARP_ERR_DEGENERATE).  For an axis plane,
     * n = ±e_k, u's k coordinate becomes 0 exactly and the copies keep H's
     * exactly. */
    if (!point) u = sw_sub(u, sw_scale(n, sw_dot(n, u)));
    swarp_vec3 pts[2 * SWARP_POLY_MAX_FACE_VERTICES + 1];
    uint32_t np = 0;
    for (uint32_t i = 0; i < k; ++i) {
        int p = cls[(i + k - 1) % k], q = cls[i];
        swarp_vec3 v = H->vertices[loop[i]];
        swarp_vec3 vt = point ? *point : sw_add(v, sw_scale(u, T));
        if (point) {
            if (!p && !q) pts[np++] = v;
            else if (!p && q) pts[np++] = v, pts[np++] = vt;
            else if (p && !q) pts[np++] = v;
        } else {
            if (!p && !q) pts[np++] = v;
            else if (p && q) pts[np++] = vt;
            else if (!p && q) pts[np++] = v, pts[np++] = vt;
            else pts[np++] = vt, pts[np++] = v;
        }
    }
    return sw_poly_flat_from_loop(pts, np, n, out);
}

/* The silhouette plane of the edge a -> b of the back face p_k (c_k <= 0;
 * a c_k within the apex tolerance above 0 counts as 0) whose twin lies in
 * the front face p_j (c_j > 0, or 0 with the tie-break of
 * sw_face_is_front): the plane through the edge containing u (or the apex).
 *
 * Fourier–Motzkin elimination of t from H's inequalities p_i(x - t u) <= 0,
 * t >= 0 (of λ from x = (1-λ) h + λ l for the apex) pairs them into
 * -c_k p_j + c_j p_k <= 0: a non-negative combination of two of H's own
 * planes, so H lies inside it whatever the rounding, and it contains u (or
 * l) up to the rounding of the c.  The cross product (a - b) x u of the
 * edge's end points, by contrast, flips when the edge is all but parallel
 * to u (a grazing light) and would cut H.  The combination cancels in turn
 * when p_j and p_k are all but opposite (an all but flat H): its normal is
 * then |n| < SW_SIDE_CANCEL_REL (w_j + w_k), and the cross product is
 * taken.  Weights below SW_SIDE_WEIGHT_TINY are scaled to 1 first: their
 * products must not underflow.  0: no side face (both weights 0, or an
 * edge parallel to u: zero area). */
/* Weights of a silhouette plane below this are scaled to 1 first: their
 * products with unit normals (down to 1e-150 per component) stay normal
 * doubles with full precision. */
#define SW_SIDE_WEIGHT_TINY 1e-150
/* A combined normal shorter than this fraction of the weights has lost
 * three digits or more to cancellation (all but opposite faces): the
 * plane is taken through the edge's end points instead. */
#define SW_SIDE_CANCEL_REL 1e-3

static int sw_side_plane(const swarp_polyhedron* H, uint8_t a, uint8_t b, uint32_t j, double cj, uint32_t k,
                         double ck, swarp_vec3 u, const swarp_vec3* apex, swarp_plane* out) {
    const swarp_plane pj = H->planes[j], pk = H->planes[k];
    double wj = ck < 0.0 ? -ck : 0.0, wk = cj > 0.0 ? cj : 0.0;
    const double m = sw_max(wj, wk);
    if (!(m > 0.0)) return 0;
    if (m < SW_SIDE_WEIGHT_TINY) wj /= m, wk /= m; /* their products with the normals would underflow */
    swarp_vec3 n = sw_v3(wj * pj.a + wk * pk.a, wj * pj.b + wk * pk.b, wj * pj.c + wk * pk.c);
    double len = sw_len_fast(n), d = wj * pj.d + wk * pk.d;
    if (!(len >= SW_SIDE_CANCEL_REL * (wj + wk))) {
        /* all but opposite faces (an all but flat H): the combination is
         * the noise of the two normals; the plane through the end points
         * and u holds the edge and its sweep whatever the noise.  Its side:
         * H's vertices of the back face's loop inside (the farthest one
         * decides), an edge all but parallel to u may flip it. */
        swarp_vec3 va = H->vertices[a], vb = H->vertices[b];
        swarp_vec3 dir = apex ? sw_sub(*apex, va) : u;
        swarp_vec3 nn = sw_cross(sw_sub(va, vb), dir); /* (a - b) x u: outward for CCW b->a->... */
        double lc = sw_len_fast(nn);
        if (lc > 0.0 && sw_finite(lc)) {
            n = nn, len = lc;
            d = -sw_dot(nn, va);
            double far_v = 0.0;
            for (uint32_t i = 0; i < H->face_vertex_count[k]; ++i) {
                const double e = sw_dot(nn, H->vertices[H->face_vertices[k][i]]) + d;
                if (fabs(e) > fabs(far_v)) far_v = e;
            }
            if (far_v > 0.0) n = sw_scale(n, -1.0), d = -d;
        }
    }
    if (!(len > 0.0) || !sw_finite(len)) return 0;
    const double il = 1.0 / len;
    *out = (swarp_plane){n.x * il, n.y * il, n.z * il, d * il};
    return 1;
}

/* The face among the set cand (bits, not empty) whose loop has the
 * directed edge p -> q; usually cand has that one face only. */
static uint32_t sw_face_with_edge(const swarp_polyhedron* H, uint64_t cand, uint8_t p, uint8_t q) {
#if defined(__GNUC__) || defined(__clang__)
    uint32_t first = (uint32_t)__builtin_ctzll(cand);
#else
    uint32_t first = 0;
    while (first < 63 && !((cand >> first) & 1u)) ++first;
#endif
    if ((cand & (cand - 1)) == 0) return first;
    for (uint32_t g = first; g < 64; ++g) {
        if (!((cand >> g) & 1u)) continue;
        const uint32_t m = H->face_vertex_count[g];
        const uint8_t* l = H->face_vertices[g];
        for (uint32_t k = 0; k < m; ++k)
            if (l[k] == p && l[k + 1 == m ? 0 : k + 1] == q) return g;
    }
    return first;
}

/* Are H's loops tidy (at least 3 vertices, no index repeated next to
 * itself, also across the wrap)?  Then the sweep built from them needs no
 * sw_poly_finalize pass: see sw_extend. */
static int sw_loops_tidy(const swarp_polyhedron* H) {
    for (uint32_t f = 0; f < H->face_count; ++f) {
        const uint32_t n = H->face_vertex_count[f];
        const uint8_t* l = H->face_vertices[f];
        if (n < 3) return 0;
        unsigned same = l[n - 1] == l[0];
        for (uint32_t k = 1; k < n; ++k) same |= l[k - 1] == l[k];
        if (same) return 0;
    }
    return 1;
}

/* The working state of sw_extend: which faces of H face u (or the apex),
 * their weights c, the output index of each vertex and copy, and the front
 * faces' directed edges. */
typedef struct sw_ext {
    int front[SWARP_POLY_MAX_FACES];
    /* c[f]: face f's plane at the apex, or n_f·u (its value at the point at
     * infinity along u): the weights of the silhouette planes */
    double c[SWARP_POLY_MAX_FACES];
    /* id[]: the output index of each vertex of H (slot nv + i: the copy of
     * vertex i, or slot nv: the apex) */
    uint8_t id[SWARP_POLY_MAX_VERTICES];
    /* directed edges of the front faces, as bit sets per start vertex */
    uint64_t front_edge[SWARP_POLY_MAX_VERTICES][SWARP_POLY_MAX_VERTICES / 64];
    /* front_faces[p]: the front faces at vertex p, as a bit set (64 faces) */
    uint64_t front_faces[SWARP_POLY_MAX_VERTICES];
    uint32_t tf; /* output faces so far */
} sw_ext;
_Static_assert(SWARP_POLY_MAX_FACES <= 64, "face sets are 64-bit");

/* Which faces of H face u (the sweep) or see the apex (by more than the
 * visibility tolerance), and their weights.  Returns whether any does. */
static int sw_extend_classify(const swarp_polyhedron* H, swarp_vec3 u, const swarp_vec3* apex, sw_ext* x) {
    int any_front = 0;
    /* the tolerance is only needed for the apex (a pass over H's vertices) */
    const double eps = apex ? SW_BODY_VISIBLE_EPS_REL * sw_poly_scale(H) : 0.0;
    for (uint32_t f = 0; f < H->face_count; ++f) {
        swarp_plane p = H->planes[f];
        if (apex) {
            x->c[f] = p.a * apex->x + p.b * apex->y + p.c * apex->z + p.d;
            x->front[f] = x->c[f] > eps;
        } else {
            x->c[f] = p.a * u.x + p.b * u.y + p.c * u.z;
            x->front[f] = sw_face_is_front(p, u);
        }
        any_front |= x->front[f];
    }
    return any_front;
}

/* The sweep's vertices as sw_poly_finalize would leave them for a tidy H:
 * only those some face uses (a vertex of H on a back face, a translated
 * copy of one on a front face), numbered in the same order.  Returns their
 * count. */
static uint32_t sw_sweep_vertices_used(const swarp_polyhedron* H, swarp_vec3 u, double T, sw_ext* x,
                                       swarp_polyhedron* out) {
    const uint32_t nv = H->vertex_count;
    uint8_t on_back[SWARP_POLY_MAX_VERTICES], on_front[SWARP_POLY_MAX_VERTICES];
    memset(on_back, 0, nv);
    memset(on_front, 0, nv);
    for (uint32_t g = 0; g < H->face_count; ++g) {
        uint8_t* mark = x->front[g] ? on_front : on_back;
        for (uint32_t j = 0; j < H->face_vertex_count[g]; ++j) mark[H->face_vertices[g][j]] = 1;
    }
    uint32_t k = 0;
    for (uint32_t i = 0; i < nv; ++i)
        if (on_back[i]) {
            x->id[i] = (uint8_t)k;
            out->vertices[k++] = H->vertices[i];
        }
    for (uint32_t i = 0; i < nv; ++i)
        if (on_front[i]) {
            x->id[nv + i] = (uint8_t)k;
            out->vertices[k++] = sw_add(H->vertices[i], sw_scale(u, T));
        }
    return k;
}

/* The front faces' directed edges and the front faces at each vertex. */
static void sw_front_edges(const swarp_polyhedron* H, sw_ext* x) {
    const uint32_t nv = H->vertex_count;
    memset(x->front_edge, 0, nv * sizeof x->front_edge[0]);
    memset(x->front_faces, 0, nv * sizeof x->front_faces[0]);
    for (uint32_t g = 0; g < H->face_count; ++g) {
        if (!x->front[g]) continue;
        uint32_t m = H->face_vertex_count[g];
        for (uint32_t j = 0; j < m; ++j) {
            uint8_t p = H->face_vertices[g][j], q = H->face_vertices[g][j + 1 == m ? 0 : j + 1];
            x->front_edge[p][q >> 6] |= (uint64_t)1 << (q & 63);
            x->front_faces[p] |= (uint64_t)1 << g;
        }
    }
}

/* The back face f of H, kept, and a side face for each of its silhouette
 * edges a -> b (the twin b -> a lies in a front face): the quad
 * b -> a -> a' -> b' of the sweep, or the triangle b -> a -> apex. */
static swarp_status sw_extend_back_face(const swarp_polyhedron* H, uint32_t f, swarp_vec3 u, const swarp_vec3* apex,
                                        sw_ext* x, swarp_polyhedron* out) {
    const uint32_t nv = H->vertex_count, n = H->face_vertex_count[f];
    const uint8_t* l = H->face_vertices[f];
    if (x->tf >= SWARP_POLY_MAX_FACES) return SWARP_ERR_CAPACITY;
    out->planes[x->tf] = H->planes[f];
    out->face_vertex_count[x->tf] = n;
    for (uint32_t k = 0; k < n; ++k) out->face_vertices[x->tf][k] = x->id[l[k]];
    ++x->tf;
    for (uint32_t k = 0; k < n; ++k) {
        uint8_t a = l[k], b = l[k + 1 == n ? 0 : k + 1];
        int twin_front = (x->front_edge[b][a >> 6] >> (a & 63)) & 1u;
        if (!twin_front) continue;
        if (x->tf >= SWARP_POLY_MAX_FACES) return SWARP_ERR_CAPACITY;
        uint8_t* q = out->face_vertices[x->tf];
        uint32_t qn;
        q[0] = x->id[b];
        q[1] = x->id[a];
        if (apex) {
            q[2] = x->id[nv];
            qn = 3;
        } else {
            q[2] = x->id[nv + a];
            q[3] = x->id[nv + b];
            qn = 4;
        }
        /* the plane through the edge containing u (or the apex) */
        const uint32_t g = sw_face_with_edge(H, x->front_faces[a] & x->front_faces[b], b, a);
        if (!sw_side_plane(H, a, b, g, x->c[g], f, x->c[f], u, apex, &out->planes[x->tf])) continue;
        out->face_vertex_count[x->tf] = qn;
        ++x->tf;
    }
    return SWARP_OK;
}

/* The front face f of H moved to H + T u: plane d' = d - n·(T u). */
static swarp_status sw_extend_front_face(const swarp_polyhedron* H, uint32_t f, swarp_vec3 u, double T, sw_ext* x,
                                         swarp_polyhedron* out) {
    const uint32_t nv = H->vertex_count, n = H->face_vertex_count[f];
    const uint8_t* l = H->face_vertices[f];
    if (x->tf >= SWARP_POLY_MAX_FACES) return SWARP_ERR_CAPACITY;
    swarp_plane p = H->planes[f];
    p.d -= T * (p.a * u.x + p.b * u.y + p.c * u.z);
    out->planes[x->tf] = p;
    out->face_vertex_count[x->tf] = n;
    for (uint32_t k = 0; k < n; ++k) out->face_vertices[x->tf][k] = x->id[nv + l[k]];
    ++x->tf;
    return SWARP_OK;
}

/* conv(H ∪ (H + T u)) (apex == NULL) or conv(H ∪ {apex}) for a solid H.
 *
 * For the sweep of a tidy H (the usual case) the result is written already
 * in the form sw_poly_finalize would give it, and *finalized is set
 * (sw_sweep_vertices_used).  Otherwise every vertex of H and of its copy
 * (or the apex) is written and the caller finalizes. */
static swarp_status sw_extend(const swarp_polyhedron* H, swarp_vec3 u, double T, const swarp_vec3* apex,
                              int h_tidy, swarp_polyhedron* out, int* finalized) {
    const uint32_t nv = H->vertex_count;
    sw_ext x;
    *finalized = 0;
    if (!sw_extend_classify(H, u, apex, &x)) { /* apex inside H: the hull is H */
        sw_poly_copy(H, out);
        return SWARP_OK;
    }
    /* vertices: H's, then either the translated copies or the apex */
    uint32_t tv = apex ? nv + 1 : 2 * nv;
    if (tv > SWARP_POLY_MAX_VERTICES) return SWARP_ERR_CAPACITY;
    if (!apex && (h_tidy || sw_loops_tidy(H))) {
        tv = sw_sweep_vertices_used(H, u, T, &x, out);
        *finalized = 1;
    } else {
        for (uint32_t i = 0; i < tv; ++i) x.id[i] = (uint8_t)i;
        for (uint32_t i = 0; i < nv; ++i) out->vertices[i] = H->vertices[i];
        if (apex)
            out->vertices[nv] = *apex;
        else
            for (uint32_t i = 0; i < nv; ++i) out->vertices[nv + i] = sw_add(H->vertices[i], sw_scale(u, T));
    }
    sw_front_edges(H, &x);
    x.tf = 0;
    for (uint32_t f = 0; f < H->face_count; ++f) {
        swarp_status s = SWARP_OK;
        if (!x.front[f])
            s = sw_extend_back_face(H, f, u, apex, &x, out);
        else if (!apex)
            s = sw_extend_front_face(H, f, u, T, &x, out);
        if (s != SWARP_OK) return s;
    }
    out->vertex_count = tv;
    out->face_count = x.tf;
    return SWARP_OK;
}

void sw_depth_range_of(const swarp_polyhedron* P, swarp_vec3 eye, swarp_vec3 f, double* mn, double* mx) {
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t i = 0; i < P->vertex_count; ++i) {
        double z = sw_dot(sw_sub(P->vertices[i], eye), f);
        if (z < lo) lo = z;
        if (z > hi) hi = z;
    }
    *mn = lo;
    *mx = hi;
}

/* A half-angle of the frustum beyond atan(SW_WIDE_TAN) (89.94°): its
 * corners reach far·tan, up to 1e12 far (an aspect of 1e300 is valid), and
 * V clipped by the box works at that scale: the clipper's tolerance (1e-12
 * of it) would swallow the box (H's vertices outside S, off their faces).
 * Such an H is built the other way round (sw_body_h_wide).  The test costs
 * no tan for the usual cameras (fovy <= SW_WIDE_FOVY and aspect <=
 * SW_WIDE_ASPECT).  That shortcut is not exact: tan(3.1/2) = 48.1, so a
 * camera with fovy just below 3.1 and an aspect just below 100 has
 * tan(fovy/2)·aspect up to 4.8e3 > SW_WIDE_TAN and is not classed wide. */
#define SW_WIDE_TAN 1e3
#define SW_WIDE_FOVY 3.1
#define SW_WIDE_ASPECT 1e2
static int sw_frustum_is_wide(const swarp_camera* cam) {
    if (!(cam->aspect > SW_WIDE_ASPECT || cam->fovy > SW_WIDE_FOVY)) return 0;
    const double ty = tan(0.5 * cam->fovy);
    return ty > SW_WIDE_TAN || ty * cam->aspect > SW_WIDE_TAN;
}

/* How far the box that bounds V is opened beyond V's corners, relative to
 * their magnitude: 1e7 times the corners' rounding (a few eps), so the
 * rounding of the corners never cuts a sliver of V that its planes keep,
 * and still far below the map's resolution. */
#define SW_WIDE_BOUND_MARGIN_REL 1e-9

/* S ∩ (the bounding box of V's corners): the same V ∩ S (V lies in its
 * corners' box), but at V's scale when S is far larger (a face at 1e19 or
 * DBL_MAX, an "unbounded" sentinel), where the clipper's tolerance (1e-12
 * of the polyhedron's scale) would be far larger than V.  *empty: the two
 * boxes do not meet.  Corners beyond the double range keep S as it is. */
static void sw_box_within_frustum(const swarp_camera* cam, double near, double far, const swarp_aabb* box,
                                  swarp_aabb* out, int* empty) {
    *out = *box;
    *empty = 0;
    swarp_polyhedron V;
    if (sw_poly_from_frustum(cam, near, far, &V) != SWARP_OK) return;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, mag = 0.0;
    for (uint32_t i = 0; i < V.vertex_count; ++i) {
        const double c[3] = {V.vertices[i].x, V.vertices[i].y, V.vertices[i].z};
        for (int k = 0; k < 3; ++k) lo[k] = fmin(lo[k], c[k]), hi[k] = fmax(hi[k], c[k]), mag = fmax(mag, fabs(c[k]));
    }
    const double m = SW_WIDE_BOUND_MARGIN_REL * mag;
    if (!sw_finite(mag + m)) return;
    double* bl = &out->min.x;
    double* bh = &out->max.x;
    for (int k = 0; k < 3; ++k) {
        bl[k] = fmax(bl[k], lo[k] - m);
        bh[k] = fmin(bh[k], hi[k] + m);
        if (!(bl[k] <= bh[k])) *empty = 1;
    }
}

/* H = S clipped by the 6 planes of V: coordinates of the box's size, S
 * first cut to V's bounding box (sw_box_within_frustum). */
static swarp_status sw_body_h_wide(const swarp_camera* cam, double near, double far, const swarp_aabb* box_in,
                                   swarp_polyhedron* H) {
    swarp_plane pl[6];
    sw_frustum_planes(cam, near, far, pl);
    swarp_aabb bounded;
    int empty = 0;
    sw_box_within_frustum(cam, near, far, box_in, &bounded, &empty);
    if (empty) {
        H->vertex_count = 0; /* sw_body_h: SWARP_ERR_BODY_EMPTY, H not published */
        return SWARP_OK;
    }
    const swarp_aabb* box = &bounded;
    swarp_status s = swarp_poly_from_aabb(box, H);
    if (s != SWARP_OK) return s;
    for (int k = 0; k < 6 && H->vertex_count > 0; ++k) {
        s = sw_poly_clip(H, sw_v3(pl[k].a, pl[k].b, pl[k].c), pl[k].d, H);
        if (s != SWARP_OK) return s;
    }
    return SWARP_OK;
}

swarp_status sw_body_h(const swarp_camera* cam, double near, double far, const swarp_aabb* box,
                       swarp_polyhedron* H) {
    /* box first: it is usually the smaller, and clipping the frustum by the
     * box's planes keeps the exact axis planes */
    swarp_polyhedron V;
    /* H lies in S: a far plane beyond every corner of S (say far = 1e308,
     * whose corners overflow) is moved in to twice the deepest corner's
     * view depth, where it still cuts nothing of S; S wholly before the near
     * plane leaves H empty */
    {
        swarp_vec3 f = {0, 0, -1};
        sw_normalize_fast(cam->dir, &f);
        double zbox = -INFINITY;
        for (int i = 0; i < 8; ++i) {
            swarp_vec3 c = sw_v3((i & 1) ? box->max.x : box->min.x, (i & 2) ? box->max.y : box->min.y,
                                 (i & 4) ? box->max.z : box->min.z);
            zbox = sw_max(zbox, sw_dot(sw_sub(c, cam->eye), f));
        }
        if (zbox < near) return SWARP_ERR_BODY_EMPTY; /* S lies wholly before the near plane */
        if (far > 2.0 * zbox) far = 2.0 * zbox;
    }
    swarp_status s;
    if (sw_frustum_is_wide(cam)) {
        s = sw_body_h_wide(cam, near, far, box, H);
        if (s != SWARP_OK) return s;
    } else {
        s = sw_poly_from_frustum(cam, near, far, &V); /* the callers checked cam, near, far */
        if (s != SWARP_OK) return s;
        s = sw_poly_clip_box(&V, box, H);
        if (s != SWARP_OK) return s;
    }
    if (H->vertex_count == 0) return SWARP_ERR_BODY_EMPTY;
    return SWARP_OK;
}

/* H = V ∩ S computed with the eye at the origin (as swarp_setup works, see
 * setup.c: coordinates of the size of H, not of the world) and its view
 * depth range [zmin, zmax]; H_rel is in those camera-relative coordinates. */
swarp_status sw_body_h_eye(const swarp_camera* cam, double near, double far, const swarp_aabb* box,
                           swarp_polyhedron* H_rel, double* zmin, double* zmax) {
    swarp_camera rc = *cam;
    rc.eye = sw_v3(0.0, 0.0, 0.0);
    swarp_aabb rb = {sw_sub(box->min, cam->eye), sw_sub(box->max, cam->eye)};
    if (!sw_finite3(&rb.min) || !sw_finite3(&rb.max)) return SWARP_ERR_NON_FINITE;
    swarp_status s = sw_body_h(&rc, near, far, &rb, H_rel);
    if (s != SWARP_OK) return s;
    swarp_vec3 f, r, u;
    sw_camera_basis(&rc, &f, &r, &u);
    sw_depth_range_of(H_rel, rc.eye, f, zmin, zmax);
    return SWARP_OK;
}

/* The square pyramid L circumscribing the spot cone: 4 planes through l. */
swarp_status sw_clip_light_pyramid(swarp_polyhedron* B, const swarp_light* light) {
    swarp_vec3 a = {0, 0, 1}, e1 = {1, 0, 0}, e2;
    sw_normalize_fast(light->direction, &a); /* subnormal directions are valid (sw_normalize_fast scales them) */
    swarp_vec3 ref = fabs(a.x) < SW_REF_AXIS_MAX ? sw_v3(1, 0, 0)
                   : (fabs(a.y) < SW_REF_AXIS_MAX ? sw_v3(0, 1, 0) : sw_v3(0, 0, 1));
    sw_normalize_fast(sw_cross(ref, a), &e1);
    e2 = sw_cross(a, e1);
    double c = cos(light->cone_angle), s = sin(light->cone_angle);
    swarp_vec3 ns[4] = {sw_sub(sw_scale(e1, c), sw_scale(a, s)), sw_sub(sw_scale(e1, -c), sw_scale(a, s)),
                        sw_sub(sw_scale(e2, c), sw_scale(a, s)), sw_sub(sw_scale(e2, -c), sw_scale(a, s))};
    for (int k = 0; k < 4; ++k) {
        swarp_status st = sw_poly_clip(B, ns[k], -sw_dot(ns[k], light->position), B);
        if (st != SWARP_OK) return st;
    }
    return SWARP_OK;
}

/* The order in which to clip the sweep of H by the planes of S: first the
 * faces the sweep leaves S through, the one it reaches soonest (smallest
 * extent / |u| along its axis) first.  That cut removes the far part of the
 * sweep (T ~ diag(S) long), so the bounds often show that a later plane no
 * longer cuts, and each cut works on a smaller polyhedron.  The faces u
 * points away from cannot cut it (H lies in S) and come last. */
static void sw_sweep_clip_order(swarp_vec3 u, const swarp_aabb* box, uint8_t order[6]) {
    const double uc[3] = {u.x, u.y, u.z};
    const double ext[3] = {box->max.x - box->min.x, box->max.y - box->min.y, box->max.z - box->min.z};
    double key[3];
    uint8_t ax[3] = {0, 1, 2};
    for (int c = 0; c < 3; ++c) key[c] = uc[c] != 0.0 ? ext[c] / fabs(uc[c]) : INFINITY;
    for (int i = 1; i < 3; ++i) /* three keys: insertion sort */
        for (int j = i; j > 0 && key[ax[j]] < key[ax[j - 1]]; --j) {
            uint8_t t = ax[j];
            ax[j] = ax[j - 1];
            ax[j - 1] = t;
        }
    for (int i = 0; i < 3; ++i) {
        const int c = ax[i], exit_max = uc[c] > 0.0;
        order[i] = (uint8_t)(2 * c + exit_max);
        order[3 + i] = (uint8_t)(2 * c + !exit_max);
    }
}

static swarp_status sw_body_from_h_ex(const swarp_polyhedron* H, const swarp_light* light, const swarp_aabb* box,
                                      int h_tidy, swarp_polyhedron* B, int* clamped);

/* The sweep length T.  Every copy H + T u must lie outside S, so that the
 * box clip cuts the sweep exactly where it leaves S (S is convex: a ray
 * that left S stays out, so any longer T gives the same B).  2 diag(S) is
 * such a T for every H that meets S.  It is kept while it is at most
 * SW_SWEEP_DIAG_REL times H's size; a longer one would put the swept copies
 * at the scale of S's far faces (1e19 or DBL_MAX for an "unbounded" box),
 * where the clipper's tolerance (SWARP_POLY_EPS_REL of the polyhedron's
 * scale) is larger than H itself.  Then the exit bound: on any axis k that
 * u points along, T_k = (bound_k - h_k) / |u_k| (bound_k: the face u points
 * at, h_k H's extreme coordinate away from it) takes every point of H past
 * that face, and since its coordinate k keeps moving away the ray never
 * re-enters S beyond T_k; this holds for every H, also one a rounding
 * outside S (H built camera-relative and translated back by the eye, as
 * the cascades do: its vertices on S's faces land an ulp either side);
 * twice the least of these (with a margin past the face), and at least H's
 * size (no copy a sliver beside H), capped at SW_SWEEP_REL_MAX times H's
 * size (*clamped).  No longer than that: the copies set the scale of the
 * swept polyhedron, and so the clipper's tolerance when S's faces cut it;
 * copies 1e6 times H's size out (2.9e6 for a needle H 2.9 long and 4e-5
 * wide whose rays leave S 70 away) weld the sides of the needle's sweep at
 * 2.9e-6 and lose the exit points of its silhouette's rays. */
static double sw_sweep_length(const swarp_polyhedron* H, swarp_vec3 u, const swarp_aabb* box, int* clamped) {
    *clamped = 0;
    const double diag = 2.0 * sw_len_fast(sw_sub(box->max, box->min)) + 1e-300; /* inf past DBL_MAX/2 */
    double hlo[3] = {INFINITY, INFINITY, INFINITY}, hhi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < H->vertex_count; ++i) {
        const double v[3] = {H->vertices[i].x, H->vertices[i].y, H->vertices[i].z};
        for (int k = 0; k < 3; ++k) hlo[k] = fmin(hlo[k], v[k]), hhi[k] = fmax(hhi[k], v[k]);
    }
    const double uc[3] = {u.x, u.y, u.z}, lo[3] = {box->min.x, box->min.y, box->min.z},
                 hi[3] = {box->max.x, box->max.y, box->max.z};
    double ext = 0.0, mag = 0.0;
    for (int k = 0; k < 3; ++k) ext = fmax(ext, hhi[k] - hlo[k]), mag = fmax(mag, fmax(fabs(hlo[k]), fabs(hhi[k])));
    /* a point H (extent 0) keeps the scale of its coordinates */
    const double size = fmax(fmax(ext, SWARP_POLY_EPS_REL * mag), DBL_MIN);
    if (diag <= SW_SWEEP_DIAG_REL * size) return diag;
    /* past the face by more than the clipper resolves at H's coordinates:
     * an exit through a face u barely points at (|u_k| ~ 1e-9) is not taken
     * for one that the clip would see as still inside S */
    const double m = 0.5 * SW_SWEEP_MARGIN_REL * fmax(mag, ext);
    double T = INFINITY;
    for (int k = 0; k < 3; ++k) {
        /* halved terms: a box from -DBL_MAX to DBL_MAX has no overflow */
        if (uc[k] > 0.0) T = fmin(T, (0.5 * hi[k] - 0.5 * hlo[k] + m) / (0.5 * uc[k]));
        else if (uc[k] < 0.0) T = fmin(T, (0.5 * hhi[k] - 0.5 * lo[k] + m) / (-0.5 * uc[k]));
    }
    T = fmax(2.0 * T, size);
    const double cap = SW_SWEEP_REL_MAX * size;
    *clamped = T > cap;
    return *clamped ? cap : T;
}

swarp_status sw_body_from_h(const swarp_polyhedron* H, const swarp_light* light, const swarp_aabb* box,
                            swarp_polyhedron* B) {
    int clamped = 0;
    return sw_body_from_h_ex(H, light, box, 0, B, &clamped);
}

/* H built by the clipper (sw_body_h and clips of it): its loops are tidy
 * (no index next to itself, at least 3 entries), see sw_loops_tidy. */
swarp_status sw_body_from_h_clipped(const swarp_polyhedron* H, const swarp_light* light, const swarp_aabb* box,
                                    swarp_polyhedron* B, int* clamped) {
    return sw_body_from_h_ex(H, light, box, 1, B, clamped);
}

static swarp_status sw_body_from_h_ex(const swarp_polyhedron* H, const swarp_light* light, const swarp_aabb* box,
                                      int h_tidy, swarp_polyhedron* B, int* clamped) {
    *clamped = 0;
    swarp_polyhedron M;
    swarp_status s;
    /* the in-plane construction only when H is flat AND the light lies in
     * its plane (u parallel to it, or l on it); otherwise the solid
     * construction makes a prism / pyramid over the polygon */
    int flat = sw_poly_is_flat(H);
    if (flat && H->face_count > 0) {
        swarp_plane p = H->planes[0];
        if (light->type == SWARP_LIGHT_POINT) {
            const swarp_vec3* l = &light->position;
            double off = p.a * l->x + p.b * l->y + p.c * l->z + p.d;
            flat = fabs(off) <= SW_BODY_VISIBLE_EPS_REL * sw_max(sw_poly_scale(H), sw_len_fast(*l));
        } else {
            swarp_vec3 dd = {0, -1, 0};
            sw_normalize_fast(light->direction, &dd);
            flat = fabs(p.a * dd.x + p.b * dd.y + p.c * dd.z) <= SW_BODY_GRAZING_COS;
        }
    }
    if (light->type == SWARP_LIGHT_POINT) {
        swarp_vec3 l = light->position;
        int finalized = 0;
        s = flat ? sw_flat_extend(H, sw_v3(0, 0, 0), 0.0, &l, &M)
                 : sw_extend(H, sw_v3(0, 0, 0), 0.0, &l, h_tidy, &M, &finalized);
        if (s != SWARP_OK) return s;
        sw_poly_finalize(&M, H->vertex_count, 0.0); /* the apex may sit on a vertex of H */
        s = sw_poly_clip_box(&M, box, B);
        if (s != SWARP_OK) return s;
        if (light->cone_angle > 0.0) {
            s = sw_clip_light_pyramid(B, light);
            if (s != SWARP_OK) return s;
        }
    } else {
        swarp_vec3 u = {0, 0, 1};
        sw_normalize_fast(sw_scale(light->direction, -1.0), &u);
        double T = sw_sweep_length(H, u, box, clamped);
        if (!(T <= SW_SWEEP_T_MAX)) T = SW_SWEEP_T_MAX;
        int finalized = 0;
        s = flat ? sw_flat_extend(H, u, T, NULL, &M) : sw_extend(H, u, T, NULL, h_tidy, &M, &finalized);
        if (s != SWARP_OK) return s;
        /* the translated copies are T > diag(S) or 1e6 times H's size away
         * from H and as far apart as H's vertices: nothing to merge, only
         * faces to tidy (sw_extend has done that for a tidy H) */
        if (!finalized) sw_poly_finalize(&M, M.vertex_count, 0.0);
        uint8_t order[6];
        sw_sweep_clip_order(u, box, order);
        s = sw_poly_clip_box_order(&M, box, order, B);
        if (s != SWARP_OK) return s;
    }
    if (B->vertex_count == 0) return SWARP_ERR_BODY_EMPTY;
    for (uint32_t i = 0; i < B->vertex_count; ++i)
        if (!sw_finite3(&B->vertices[i])) return SWARP_ERR_OUT_OF_RANGE;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_body_h(const swarp_camera* cam, double near, double far, const swarp_aabb* scene,
                                    swarp_polyhedron* out_H) {
    if (!cam || !scene || !out_H) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    if (!sw_finite(near) || !sw_finite(far)) return SWARP_ERR_NON_FINITE;
    if (!(near > 0.0 && far > near)) return SWARP_ERR_NEAR_FAR;
    s = sw_check_box(scene);
    if (s != SWARP_OK) return s;
    swarp_polyhedron H;
    s = sw_body_h(cam, near, far, scene, &H);
    if (s != SWARP_OK) return s;
    sw_poly_publish(&H, out_H);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_body_from_h(const swarp_polyhedron* H, const swarp_light* light,
                                         const swarp_aabb* scene, swarp_polyhedron* out_B) {
    if (!H || !light || !scene || !out_B) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_light(light);
    if (s != SWARP_OK) return s;
    s = sw_check_box(scene);
    if (s != SWARP_OK) return s;
    s = sw_poly_check_counts(H);
    if (s != SWARP_OK) return s;
    if (H->vertex_count == 0) return SWARP_ERR_BODY_EMPTY;
    s = sw_poly_check_contents(H);
    if (s != SWARP_OK) return s;
    swarp_polyhedron B;
    s = sw_body_from_h(H, light, scene, &B);
    if (s != SWARP_OK) return s;
    sw_poly_publish(&B, out_B);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_body_points(const swarp_camera* cam, double near, double far,
                                         const swarp_light* light, const swarp_aabb* scene, swarp_vec3* out,
                                         size_t capacity, size_t* out_count) {
    if (!cam || !light || !scene || !out_count || (!out && capacity > 0)) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_light(light);
    if (s != SWARP_OK) return s;
    swarp_polyhedron H, B;
    s = swarp_body_h(cam, near, far, scene, &H);
    if (s != SWARP_OK) return s;
    s = sw_body_from_h(&H, light, scene, &B);
    if (s != SWARP_OK) return s;
    *out_count = B.vertex_count;
    if (capacity < B.vertex_count) return SWARP_ERR_CAPACITY;
    memcpy(out, B.vertices, B.vertex_count * sizeof(swarp_vec3));
    return SWARP_OK;
}

SWARP_API swarp_status swarp_body_adjusted_range(const swarp_camera* cam, const swarp_aabb* scene,
                                                 double* out_near, double* out_far) {
    if (!cam || !scene || !out_near || !out_far) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_camera(cam);
    if (s != SWARP_OK) return s;
    s = sw_check_box(scene);
    if (s != SWARP_OK) return s;
    /* camera-relative, as swarp_setup: the same adjusted range */
    swarp_polyhedron H;
    double mn, mx;
    s = sw_body_h_eye(cam, cam->z_near, cam->z_far, scene, &H, &mn, &mx);
    if (s != SWARP_OK) return s;
    /* H ⊂ V: clamp rounding to the frustum's own range, near included: for
     * a range one ulp wide the depths of H can round above far, and near
     * would come out above far */
    *out_near = sw_min(sw_max(mn, cam->z_near), cam->z_far);
    *out_far = sw_min(sw_max(mx, *out_near), cam->z_far);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_body_receivers(const swarp_polyhedron* H, const swarp_light* light,
                                            swarp_polyhedron* out) {
    if (!H || !light || !out) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_light(light);
    if (s != SWARP_OK) return s;
    s = sw_poly_validate(H);
    if (s != SWARP_OK) return s;
    if (H->vertex_count == 0) return SWARP_ERR_BODY_EMPTY;
    swarp_polyhedron R;
    sw_poly_copy(H, &R);
    if (light->type == SWARP_LIGHT_POINT && light->cone_angle > 0.0) {
        s = sw_clip_light_pyramid(&R, light);
        if (s != SWARP_OK) return s;
        if (R.vertex_count == 0) return SWARP_ERR_BODY_EMPTY;
    }
    sw_poly_publish(&R, out);
    return SWARP_OK;
}
