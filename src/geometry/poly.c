/* Convex polyhedra with a fixed capacity: construction from a box, a camera
 * or an inverse view-projection matrix, and clipping by planes.  The
 * intersection body B of [RHS] §3.1.1 is built from these operations. */
#include "geometry/geometry_internal.h"

_Static_assert(sizeof(swarp_polyhedron) == SWARP_POLY_SIZE, "swarp_polyhedron size");
_Static_assert(SWARP_POLY_MAX_VERTICES <= 255, "face indices are uint8_t");

/* ---- the camera's frame ------------------------------------------------------
 * (the argument checks are src/common/check.c) */

void sw_camera_basis(const swarp_camera* cam, swarp_vec3* f, swarp_vec3* r, swarp_vec3* u) {
    swarp_vec3 ff = {0, 0, -1}, uu, rr = {1, 0, 0};
    sw_normalize_fast(cam->dir, &ff);
    sw_normalize_fast(sw_cross(ff, cam->up), &rr);
    uu = sw_cross(rr, ff);
    *f = ff;
    *r = rr;
    *u = uu;
}

/* ---- construction ---------------------------------------------------------- */

/* The floor of a polyhedron's scale: keeps the relative epsilons
 * (SWARP_POLY_EPS_REL times the scale) > 0 for a polyhedron at the origin. */
#define SW_POLY_SCALE_MIN 1e-300

/* Largest absolute coordinate (at least the extent): the scale the relative
 * epsilons refer to.  Never 0 for a non-empty polyhedron of non-zero size;
 * SW_POLY_SCALE_MIN keeps eps > 0 for a polyhedron at the origin. */
double sw_poly_scale(const swarp_polyhedron* p) {
    double s = 0.0;
    for (uint32_t i = 0; i < p->vertex_count; ++i) {
        const swarp_vec3* v = &p->vertices[i];
        double ax = fabs(v->x), ay = fabs(v->y), az = fabs(v->z);
        s = ax > s ? ax : s; /* branch-free max */
        s = ay > s ? ay : s;
        s = az > s ? az : s;
    }
    return s > SW_POLY_SCALE_MIN ? s : SW_POLY_SCALE_MIN;
}

/* Renumber every face loop through remap, drop repeated neighbours and faces
 * left with fewer than 3 vertices (compacted in place: row nf <= f, and within
 * a row m <= k), mark the vertices still used and return the face count.
 * Shared by the near-duplicate merge after clipping and the final tidy-up. */
static uint32_t sw_remap_faces(swarp_polyhedron* p, const uint8_t* remap, uint8_t* used) {
    uint32_t nf = 0;
    for (uint32_t f = 0; f < p->face_count; ++f) {
        uint32_t n = p->face_vertex_count[f], m = 0;
        const uint8_t* src = p->face_vertices[f];
        uint8_t* loop = p->face_vertices[nf];
        for (uint32_t k = 0; k < n; ++k) {
            uint8_t id = remap[src[k]];
            if (m > 0 && loop[m - 1] == id) continue;
            loop[m++] = id;
        }
        while (m > 1 && loop[m - 1] == loop[0]) --m;
        if (m < 3) continue;
        p->face_vertex_count[nf] = m;
        p->planes[nf] = p->planes[f];
        for (uint32_t k = 0; k < m; ++k) used[loop[k]] = 1;
        ++nf;
    }
    p->face_count = nf;
    return nf;
}

/* A loop less than this across (centred) is scaled to size 1 before
 * Newell's products: theirs are then at least 1e-200 (normal doubles, full
 * precision) for every loop above 1e-100, and a smaller one is scaled. */
#define SW_NEWELL_TINY 1e-100

/* Newell normal of a loop (robust for non-planar or tiny loops). */
static swarp_vec3 sw_newell(const swarp_vec3* v, const uint8_t* idx, uint32_t n) {
    swarp_vec3 nn = {0, 0, 0};
    swarp_vec3 c = {0, 0, 0};
    for (uint32_t i = 0; i < n; ++i) c = sw_add(c, v[idx[i]]);
    c = sw_scale(c, 1.0 / n); /* centred: no cancellation for large worlds */
    /* a loop 1e-160 across (the corners of a matrix with w ~ 1e160) has
     * products of 1e-320: subnormal, with too few digits for a direction,
     * and its unit normal would come out inf; such a loop is scaled to size
     * 1 first (SW_NEWELL_TINY).  (A loop 1e300 across overflows to inf: the
     * face is dropped as collapsed.) */
    double m = 0.0, inv = 1.0;
    for (uint32_t i = 0; i < n; ++i) {
        swarp_vec3 a = sw_sub(v[idx[i]], c);
        m = sw_max(m, sw_max(fabs(a.x), sw_max(fabs(a.y), fabs(a.z))));
    }
    const int scaled = m < SW_NEWELL_TINY && m > 0.0;
    if (scaled) inv = m;
    for (uint32_t i = 0; i < n; ++i) {
        swarp_vec3 a = sw_sub(v[idx[i]], c), b = sw_sub(v[idx[i + 1 == n ? 0 : i + 1]], c);
        if (scaled) a = sw_v3(a.x / inv, a.y / inv, a.z / inv), b = sw_v3(b.x / inv, b.y / inv, b.z / inv);
        nn.x += (a.y - b.y) * (a.z + b.z);
        nn.y += (a.z - b.z) * (a.x + b.x);
        nn.z += (a.x - b.x) * (a.y + b.y);
    }
    return nn;
}

/* Merge vertices closer than eps, drop repeated indices in loops and faces
 * with fewer than 3 distinct vertices, drop unreferenced vertices when there
 * are faces.  Keeps the SWARP_POLY_EPS_REL promise after every operation. */
void sw_poly_finalize(swarp_polyhedron* p, uint32_t first_new, double scale) {
    const double eps = SWARP_POLY_EPS_REL * (scale > 0.0 ? scale : sw_poly_scale(p));
    uint8_t remap[SWARP_POLY_MAX_VERTICES];
    uint32_t nv = 0;
    if (first_new > p->vertex_count) first_new = p->vertex_count;
    for (uint32_t i = 0; i < first_new; ++i) remap[i] = (uint8_t)i;
    nv = first_new;
    for (uint32_t i = first_new; i < p->vertex_count; ++i) {
        swarp_vec3 v = p->vertices[i];
        uint32_t j = 0;
        for (; j < nv; ++j) {
            swarp_vec3 w = p->vertices[j];
            if (fabs(v.x - w.x) <= eps && fabs(v.y - w.y) <= eps && fabs(v.z - w.z) <= eps) break;
        }
        if (j == nv) p->vertices[nv++] = v;
        remap[i] = (uint8_t)j;
    }
    p->vertex_count = nv;
    uint32_t nf = 0;
    uint8_t used[SWARP_POLY_MAX_VERTICES];
    memset(used, 0, nv);
    nf = sw_remap_faces(p, remap, used);
    if (nf > 0) { /* vertices of a solid or flat polyhedron are face corners */
        uint32_t k = 0;
        for (uint32_t i = 0; i < nv; ++i) {
            if (used[i]) {
                remap[i] = (uint8_t)k;
                p->vertices[k++] = p->vertices[i];
            }
        }
        if (k != nv) {
            for (uint32_t f = 0; f < nf; ++f)
                for (uint32_t j = 0; j < p->face_vertex_count[f]; ++j)
                    p->face_vertices[f][j] = remap[p->face_vertices[f][j]];
            p->vertex_count = k;
        }
    }
}

/* After clipping: merge each new on-plane vertex into an earlier on-plane
 * vertex closer than eps (Euclidean).  Only these can be that close: every
 * other kept vertex lies more than the classification tolerance (>= eps)
 * off the plane.  Loops are then rewritten and unreferenced vertices
 * dropped, only when something merged. */
static void sw_poly_merge_on_plane(swarp_polyhedron* p, const uint8_t* on, uint32_t n_on, uint32_t first_new,
                                   double eps) {
    /* into[a]: the on-plane slot that slot a merges into (a itself when it
     * stays).  Merges are rare, so the whole-vertex remap is only built
     * when one happened. */
    uint8_t into[SWARP_POLY_MAX_VERTICES];
    int merged = 0;
    const double eps2 = eps * eps;
    if (n_on > 0) into[0] = 0;
    for (uint32_t a = 1; a < n_on; ++a) {
        into[a] = (uint8_t)a;
        if (on[a] < first_new) continue; /* old vertices are apart already */
        swarp_vec3 v = p->vertices[on[a]];
        for (uint32_t b = 0; b < a; ++b) {
            if (into[b] != b) continue; /* merged itself: compare with survivors only */
            swarp_vec3 w = p->vertices[on[b]];
            double dx = v.x - w.x;
            if (fabs(dx) > eps) continue; /* the usual case: apart in x already */
            double dy = v.y - w.y, dz = v.z - w.z;
            if (dx * dx + dy * dy + dz * dz <= eps2) {
                into[a] = (uint8_t)b;
                merged = 1;
                break;
            }
        }
    }
    if (!merged) return;
    uint8_t remap[SWARP_POLY_MAX_VERTICES];
    for (uint32_t i = 0; i < p->vertex_count; ++i) remap[i] = (uint8_t)i;
    for (uint32_t a = 0; a < n_on; ++a) remap[on[a]] = on[into[a]];
    uint32_t nf = 0;
    uint8_t used[SWARP_POLY_MAX_VERTICES];
    memset(used, 0, p->vertex_count);
    nf = sw_remap_faces(p, remap, used);
    uint32_t k = 0;
    for (uint32_t i = 0; i < p->vertex_count; ++i) {
        int keep = nf > 0 ? used[i] : (remap[i] == i);
        if (keep) {
            remap[i] = (uint8_t)k;
            p->vertices[k++] = p->vertices[i];
        }
    }
    for (uint32_t f = 0; f < nf; ++f)
        for (uint32_t j = 0; j < p->face_vertex_count[f]; ++j) p->face_vertices[f][j] = remap[p->face_vertices[f][j]];
    p->vertex_count = k;
}

/* No two points closer than eps in every coordinate (the merge test of
 * sw_poly_finalize)? */
static int sw_points_apart(const swarp_vec3* v, uint32_t n, double eps) {
    for (uint32_t i = 1; i < n; ++i)
        for (uint32_t j = 0; j < i; ++j)
            if (fabs(v[i].x - v[j].x) <= eps && fabs(v[i].y - v[j].y) <= eps && fabs(v[i].z - v[j].z) <= eps)
                return 0;
    return 1;
}

/* The 6 faces of a hexahedron given by 8 corners, corner index = x | y<<1 |
 * z<<2.  The plane of each face comes from Newell's normal of its loop; the
 * loops of the table all run the same way round (outward for a right-handed
 * corner order), so one decision orients them all: the face whose centre
 * lies farthest from the centroid along its normal says whether they point
 * away from it (so the corner order's handedness does not matter).  Each
 * face deciding for itself would let rounding decide for the two faces of
 * a hexahedron flat across them (a frustum of aspect 1e-87: the distance
 * is 1e-93 against a rounding of 1e-22) and could orient both the same
 * way, an H with no inside, empty or not by rounding alone. */
void sw_poly_from_corners(const swarp_vec3 c[8], swarp_polyhedron* out) {
    static const uint8_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                        {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    out->vertex_count = 8;
    swarp_vec3 centroid = {0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        out->vertices[i] = c[i];
        centroid = sw_add(centroid, c[i]);
    }
    centroid = sw_scale(centroid, 1.0 / 8.0);
    uint32_t nf = 0;
    double far_dot = 0.0;
    for (int f = 0; f < 6; ++f) {
        const uint8_t* loop = quads[f];
        swarp_vec3 n = sw_newell(out->vertices, loop, 4);
        swarp_vec3 nu = {0, 0, 1};
        /* collapsed face (flat box), or corners near DBL_MAX whose products
         * overflowed to inf - inf = NaN (sw_normalize_fast's scaled branch
         * takes fmax of the components, which skips a NaN: checked here) */
        if (!sw_finite3(&n) || !sw_normalize_fast(n, &nu)) continue;
        swarp_vec3 fc = sw_scale(sw_add(sw_add(c[loop[0]], c[loop[1]]), sw_add(c[loop[2]], c[loop[3]])), 0.25);
        const double dc = sw_dot(nu, sw_sub(fc, centroid));
        if (fabs(dc) > fabs(far_dot)) far_dot = dc;
        out->planes[nf].a = nu.x;
        out->planes[nf].b = nu.y;
        out->planes[nf].c = nu.z;
        out->planes[nf].d = -sw_dot(nu, fc);
        memcpy(out->face_vertices[nf], loop, 4);
        out->face_vertex_count[nf] = 4;
        ++nf;
    }
    if (far_dot < 0.0) /* a left-handed corner order: every loop ran inward */
        for (uint32_t f = 0; f < nf; ++f) {
            swarp_plane* p = &out->planes[f];
            p->a = -p->a, p->b = -p->b, p->c = -p->c, p->d = -p->d;
            uint8_t* l = out->face_vertices[f];
            uint8_t t = l[1];
            l[1] = l[3];
            l[3] = t;
        }
    out->face_count = nf;
    /* a real frustum or box: 6 quads on 8 corners that are all apart, so
     * sw_poly_finalize would merge, drop and renumber nothing */
    if (nf == 6 && sw_points_apart(out->vertices, 8, SWARP_POLY_EPS_REL * sw_poly_scale(out))) return;
    sw_poly_finalize(out, 0, 0.0);
}

SWARP_API swarp_status swarp_poly_from_aabb(const swarp_aabb* box, swarp_polyhedron* out) {
    if (!box || !out) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite3(&box->min) || !sw_finite3(&box->max)) return SWARP_ERR_NON_FINITE;
    if (!(box->min.x <= box->max.x && box->min.y <= box->max.y && box->min.z <= box->max.z))
        return SWARP_ERR_BOX_INVERTED;
    swarp_vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = sw_v3((i & 1) ? box->max.x : box->min.x, (i & 2) ? box->max.y : box->min.y,
                     (i & 4) ? box->max.z : box->min.z);
    sw_poly_from_corners(c, out);
    /* exact axis planes for the box (Newell gives them too, up to rounding) */
    sw_poly_publish(out, out);
    return SWARP_OK;
}

/* Largest tangent of a frustum half-angle used (90° - 1e-12 rad). */
#define SW_FRUSTUM_MAX_TAN 1e12
/* Smallest half-width of a frustum face, in weld tolerances (eps =
 * SWARP_POLY_EPS_REL times the corners' scale): a face side of 4 eps is
 * twice the 2 eps below which the corners would merge, so the box planes
 * that clip V cut it into vertices that stay apart too. */
#define SW_FRUSTUM_MIN_HALF_EPS 2.0

/* The corners; each face's half-widths along r and u are at least hx_min
 * and hy_min (0: the exact frustum), see sw_poly_from_frustum. */
static void sw_frustum_corners_b(const swarp_camera* cam, swarp_vec3 f, swarp_vec3 r, swarp_vec3 u, double tx,
                                 double ty, double near, double far, double hx_min, double hy_min, swarp_vec3 c[8]) {
    for (int i = 0; i < 8; ++i) {
        double z = (i & 4) ? far : near;
        double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
        /* eye + z (f + sx tx r + sy ty u): corners relative to the eye
         * first; a face held at the minima: eye + z f + sx hx r + sy hy u */
        if (z * tx >= hx_min && z * ty >= hy_min) {
            swarp_vec3 d = sw_add(f, sw_add(sw_scale(r, sx * tx), sw_scale(u, sy * ty)));
            c[i] = sw_add(cam->eye, sw_scale(d, z));
        } else {
            const double hx = sw_max(z * tx, hx_min), hy = sw_max(z * ty, hy_min);
            swarp_vec3 d = sw_add(sw_scale(f, z), sw_add(sw_scale(r, sx * hx), sw_scale(u, sy * hy)));
            c[i] = sw_add(cam->eye, d);
        }
    }
}

/* The frustum's 6 planes (outward unit normals) in the order of
 * sw_frustum_loops: left, right, bottom, top, near, far. */
static void sw_frustum_planes_b(const swarp_camera* cam, swarp_vec3 f, swarp_vec3 r, swarp_vec3 u, double tx,
                                double ty, double near, double far, swarp_plane pl[6]) {
    const double kx = 1.0 / sqrt(1.0 + tx * tx), ky = 1.0 / sqrt(1.0 + ty * ty);
    const double fe = sw_dot(f, cam->eye);
    swarp_vec3 n[6];
    double d[6];
    n[0] = sw_scale(sw_add(r, sw_scale(f, tx)), -kx); /* left: -(r + tx f) */
    n[1] = sw_scale(sw_sub(r, sw_scale(f, tx)), kx);  /* right: r - tx f */
    n[2] = sw_scale(sw_add(u, sw_scale(f, ty)), -ky); /* bottom: -(u + ty f) */
    n[3] = sw_scale(sw_sub(u, sw_scale(f, ty)), ky);  /* top: u - ty f */
    for (int k = 0; k < 4; ++k) d[k] = -sw_dot(n[k], cam->eye); /* the side planes pass through the eye */
    n[4] = sw_scale(f, -1.0);
    d[4] = fe + near;
    n[5] = f;
    d[5] = -(fe + far);
    for (int k = 0; k < 6; ++k) pl[k] = (swarp_plane){n[k].x, n[k].y, n[k].z, d[k]};
}

/* The frustum's faces, corner index = x | y<<1 | z<<2 (x: right, y: up,
 * z: far), each loop counter-clockwise seen from outside: the loops
 * sw_poly_from_corners finds for every camera (its basis is always
 * right-handed the same way). */
static const uint8_t sw_frustum_loops[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                               {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};

swarp_status sw_poly_from_frustum(const swarp_camera* cam, double near, double far, swarp_polyhedron* out) {
    swarp_vec3 f, r, u;
    sw_camera_basis(cam, &f, &r, &u);
    /* an aspect of 1e308 asks for a half-angle of 90° - 1e-308 rad: the
     * frustum is kept within 90° - 1e-12 rad, whose corners stay finite
     * (SW_FRUSTUM_MAX_TAN) */
    double ty = fmin(tan(0.5 * cam->fovy), SW_FRUSTUM_MAX_TAN), tx = fmin(ty * cam->aspect, SW_FRUSTUM_MAX_TAN);
    swarp_vec3 c[8];
    sw_frustum_corners_b(cam, f, r, u, tx, ty, near, far, 0.0, 0.0, c);
    double scale = SW_POLY_SCALE_MIN;
    for (int i = 0; i < 8; ++i) {
        if (!sw_finite3(&c[i])) return SWARP_ERR_NON_FINITE;
        scale = sw_max(scale, sw_max(fabs(c[i].x), sw_max(fabs(c[i].y), fabs(c[i].z))));
    }
    const double eps = SWARP_POLY_EPS_REL * scale;
    /* A needle frustum (tan 1e-9, far 1e3 near 1e-2) has a near quad far
     * below the weld tolerance eps of its far corners: welded into one
     * corner, its side edges would lean inward by up to the quad's width,
     * which is most of the needle's width near the eye (V 0.3 % too thin at
     * 600 near depths).  Its faces are held at SW_FRUSTUM_MIN_HALF_EPS eps
     * from the axis instead: a superset of V by at most that much, whose
     * corners the clipper keeps apart.  A direction in which even the far
     * face is below that (aspect 1e-87) stays flat: welded, V is a polygon
     * whose lateral extent is within eps of the true one (the fit calls
     * it flat, SWARP_INFO_FLAT_EXTENT). */
    const double h_min = SW_FRUSTUM_MIN_HALF_EPS * eps;
    if (!(2.0 * near * sw_min(tx, ty) > 2.0 * eps)) {
        const double hx_min = far * tx > h_min ? h_min : 0.0, hy_min = far * ty > h_min ? h_min : 0.0;
        sw_frustum_corners_b(cam, f, r, u, tx, ty, near, far, hx_min, hy_min, c);
        for (int i = 0; i < 8; ++i)
            if (!sw_finite3(&c[i])) return SWARP_ERR_NON_FINITE;
    }
    /* The corners are at least min(2 near tx, 2 near ty, far - near) apart
     * (the near quad's sides; near and far corners differ by far - near
     * along f); above 2 eps (the merge test is eps per coordinate, sqrt(3)
     * eps in distance) nothing merges, and the planes come from the basis
     * directly instead of Newell's normals of the corners.  A frustum
     * thinner than that along f welds its near and far faces into one
     * quad (flat, its lateral extent kept). */
    const double sep = sw_min(2.0 * near * sw_min(tx, ty), far - near);
    if (!(sep > 2.0 * eps)) {
        sw_poly_from_corners(c, out);
        return SWARP_OK;
    }
    sw_frustum_planes_b(cam, f, r, u, tx, ty, near, far, out->planes);
    out->vertex_count = 8;
    for (int i = 0; i < 8; ++i) out->vertices[i] = c[i];
    for (int k = 0; k < 6; ++k) {
        memcpy(out->face_vertices[k], sw_frustum_loops[k], 4);
        out->face_vertex_count[k] = 4;
    }
    out->face_count = 6;
    return SWARP_OK;
}

void sw_frustum_planes(const swarp_camera* cam, double near, double far, swarp_plane pl[6]) {
    swarp_vec3 f, r, u;
    sw_camera_basis(cam, &f, &r, &u);
    double ty = fmin(tan(0.5 * cam->fovy), SW_FRUSTUM_MAX_TAN), tx = fmin(ty * cam->aspect, SW_FRUSTUM_MAX_TAN);
    sw_frustum_planes_b(cam, f, r, u, tx, ty, near, far, pl);
}

SWARP_API swarp_status swarp_poly_from_camera_range(const swarp_camera* cam, double near, double far,
                                                    swarp_polyhedron* out) {
    if (!cam || !out) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    if (!sw_finite(near) || !sw_finite(far)) return SWARP_ERR_NON_FINITE;
    if (!(near > 0.0 && far > near)) return SWARP_ERR_NEAR_FAR;
    /* every input is finite here: a corner that is not (far tan of the
     * half-angles beyond DBL_MAX) is a frustum out of the double range */
    s = sw_poly_from_frustum(cam, near, far, out);
    if (s == SWARP_OK) sw_poly_publish(out, out);
    return s == SWARP_ERR_NON_FINITE ? SWARP_ERR_OUT_OF_RANGE : s;
}

SWARP_API swarp_status swarp_poly_from_camera(const swarp_camera* cam, swarp_polyhedron* out) {
    if (!cam || !out) return SWARP_ERR_NULL_POINTER;
    return swarp_poly_from_camera_range(cam, cam->z_near, cam->z_far, out);
}

SWARP_API swarp_status swarp_poly_from_inverse_matrix(const swarp_mat4* inv, swarp_depth_range dr,
                                                      swarp_polyhedron* out) {
    if (!inv || !out) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(inv)) return SWARP_ERR_NON_FINITE;
    if (sw_check_depth_range(dr) != SWARP_OK && dr != SWARP_DEPTH_REVERSED_ZERO_TO_ONE)
        return SWARP_ERR_UNKNOWN_ENUM;
    /* NDC depth of the near (i & 4 = 0) and far corners: reversed-Z has its
     * near plane at 1 and its far plane at 0, so the same corner numbering
     * (near face first) holds in every convention */
    double z_near_ndc = -1.0, z_far_ndc = 1.0;
    if (dr == SWARP_DEPTH_ZERO_TO_ONE) z_near_ndc = 0.0;
    if (dr == SWARP_DEPTH_REVERSED_ZERO_TO_ONE) z_near_ndc = 1.0, z_far_ndc = 0.0;
    swarp_vec3 c[8];
    double wsign = 0.0;
    for (int i = 0; i < 8; ++i) {
        swarp_vec4 h = {(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? z_far_ndc : z_near_ndc, 1.0};
        swarp_vec4 p = sw_xform4(inv, h);
        /* all corners must lie on the same side of w = 0 (a finite frustum) */
        if (i == 0) wsign = p.w > 0.0 ? 1.0 : -1.0;
        if (!(p.w * wsign > 0.0)) return SWARP_ERR_DEGENERATE;
        c[i] = sw_v3(p.x / p.w, p.y / p.w, p.z / p.w);
        if (!sw_finite3(&c[i])) return SWARP_ERR_DEGENERATE;
    }
    sw_poly_from_corners(c, out);
    sw_poly_publish(out, out);
    return SWARP_OK;
}

/* ---- clipping -------------------------------------------------------------- */

/* Copies only the used parts (the struct is 7 KiB, B uses a few hundred bytes). */
void sw_poly_copy(const swarp_polyhedron* in, swarp_polyhedron* out) {
    out->vertex_count = in->vertex_count;
    out->face_count = in->face_count;
    memcpy(out->vertices, in->vertices, in->vertex_count * sizeof(swarp_vec3));
    memcpy(out->planes, in->planes, in->face_count * sizeof(swarp_plane));
    memcpy(out->face_vertex_count, in->face_vertex_count, in->face_count * sizeof(uint32_t));
    memcpy(out->face_vertices, in->face_vertices, in->face_count * sizeof in->face_vertices[0]);
}

/* Canonical bytes of a finished polyhedron: the counted parts of p moved to
 * out (p may equal out) and every byte beyond the counts written as zero
 * (vertices past vertex_count, planes, loop counts and loops past
 * face_count, and each loop past its own face_vertex_count).  The struct is
 * then a function of its vertices and faces alone, not of the memory it
 * was built in (callers hash, cache and send it); the counts are within the
 * maxima for every polyhedron the library builds or has validated. */
void sw_poly_publish(const swarp_polyhedron* p, swarp_polyhedron* out) {
    const uint32_t nv = p->vertex_count, nf = p->face_count;
    out->vertex_count = nv;
    out->face_count = nf;
    memmove(out->vertices, p->vertices, nv * sizeof out->vertices[0]);
    memset(out->vertices + nv, 0, (SWARP_POLY_MAX_VERTICES - nv) * sizeof out->vertices[0]);
    memmove(out->planes, p->planes, nf * sizeof out->planes[0]);
    memset(out->planes + nf, 0, (SWARP_POLY_MAX_FACES - nf) * sizeof out->planes[0]);
    memmove(out->face_vertex_count, p->face_vertex_count, nf * sizeof out->face_vertex_count[0]);
    memset(out->face_vertex_count + nf, 0, (SWARP_POLY_MAX_FACES - nf) * sizeof out->face_vertex_count[0]);
    for (uint32_t f = 0; f < nf; ++f) {
        const uint32_t k = out->face_vertex_count[f];
        memmove(out->face_vertices[f], p->face_vertices[f], k);
        memset(out->face_vertices[f] + k, 0, SWARP_POLY_MAX_FACE_VERTICES - k);
    }
    memset(out->face_vertices + nf, 0, (SWARP_POLY_MAX_FACES - nf) * sizeof out->face_vertices[0]);
}

/* p + t: vertices moved, plane offsets d' = d - n·t */
void sw_poly_translate(swarp_polyhedron* p, swarp_vec3 t) {
    for (uint32_t i = 0; i < p->vertex_count; ++i) p->vertices[i] = sw_add(p->vertices[i], t);
    for (uint32_t f = 0; f < p->face_count; ++f)
        p->planes[f].d -= p->planes[f].a * t.x + p->planes[f].b * t.y + p->planes[f].c * t.z;
}

/* Vertex classes of a clip (bits, so a face's classes can be OR-ed). */
enum { SW_IN = 1, SW_ON = 2, SW_OUT = 4 };

/* Pseudo-angle in [0, 4) of (x, y): monotone in the true angle, no atan2. */
static double sw_pseudo_angle(double x, double y) {
    double d = fabs(x) + fabs(y);
    if (!(d > 0.0)) return 0.0;
    double t = x / d; /* in [-1, 1] */
    return (y >= 0.0) ? 1.0 - t : 3.0 + t;
}

/* Where the edge i-j crosses the plane (dist: signed distances of its
 * ends, of opposite signs), interpolated from the end nearer to the plane:
 * p = a + (b - a) s with s = dist_a / (dist_a - dist_b) <= 1/2 is rounded by
 * eps (|a| + |p - a|).  From the far end, s ~ 1 and p = b + (a - b) s is
 * rounded by eps |b|: for an edge from a point near the plane to a vertex
 * far beyond it (|b| >> |a|) that error exceeds the clip tolerance, and the
 * cut would leave the plane by an amount and direction the rounding picks. */
static inline swarp_vec3 sw_edge_cut(const swarp_vec3* v, const double* dist, uint8_t i, uint8_t j) {
    const uint8_t ia = fabs(dist[i]) <= fabs(dist[j]) ? i : j, ib = ia == i ? j : i;
    const double s = dist[ia] / (dist[ia] - dist[ib]);
    const swarp_vec3 a = v[ia], b = v[ib];
    return sw_add(a, sw_scale(sw_sub(b, a), s));
}

/* A cut on a box plane (n = ±e_k, unit_normal): its coordinate k is the
 * plane's, -d n_k, exactly.  Interpolated it carries a few ulps of the
 * coordinates (eps |a| + eps |p - a|), so H's cut vertices would lie on the
 * plane or an ulp off it as the rounding falls, and a light grazing that
 * plane would see B either flat (SWARP_INFO_FLAT_EXTENT) or one ulp thick,
 * finer than the coordinates resolve (SWARP_ERR_DEGENERATE).  Set exactly,
 * the cut face lies in the box plane. */
static inline void sw_cut_on_axis_plane(swarp_vec3* p, swarp_vec3 n, double d) {
    if (n.x != 0.0) p->x = -d * n.x;
    else if (n.y != 0.0) p->y = -d * n.y;
    else p->z = -d * n.z;
}

/* The working state of one clip: the plane (unit normal), each input
 * vertex's signed distance and class, and the output's bookkeeping: the
 * output index of each kept input vertex (map), the on-plane output
 * vertices (the cap's corners), the successor of each on the cap (the
 * cap's edges are the in-plane edges of the kept faces, reversed), and the
 * cut point of each strictly crossing edge (keyed by its end points, so
 * both faces of an edge get the very same point). */
typedef struct sw_clip {
    swarp_vec3 n;
    double d;
    int unit_normal; /* n is a unit axis (box planes): no sqrt, no division */
    double dist[SWARP_POLY_MAX_VERTICES];
    uint8_t cls[SWARP_POLY_MAX_VERTICES]; /* SW_IN, SW_ON (within eps of the plane), SW_OUT */
    uint8_t map[SWARP_POLY_MAX_VERTICES];
    uint8_t on_plane[SWARP_POLY_MAX_VERTICES];
    uint32_t n_on;
    uint8_t onf[SWARP_POLY_MAX_VERTICES], nxt[SWARP_POLY_MAX_VERTICES];
    uint32_t n_cap;
    int cap_bad;
    int cap_coincides; /* a kept face lies in the plane, facing along +n */
    uint8_t edge_lo[SWARP_POLY_MAX_VERTICES], edge_hi[SWARP_POLY_MAX_VERTICES], edge_v[SWARP_POLY_MAX_VERTICES];
    uint32_t n_edges;
    uint32_t tv, tf; /* output vertices and faces so far */
} sw_clip;

/* Outcomes of a clip decided before any face is walked. */
enum { SW_CLIP_CUTS = 0, SW_CLIP_KEEPS_ALL, SW_CLIP_CUTS_ALL };

/* Plane coefficients whose largest magnitude m lies outside [TINY, HUGE]
 * are divided by m first: 1/|n| overflows for |n| below 1/DBL_MAX (a valid,
 * non-zero n of 1e-321 would keep what it should cut), and divided by m the
 * normal has a component of magnitude 1, well inside the range where its
 * length is the plain sqrt of the sum of squares.  1e±150 keeps the squares
 * of the coefficients in the normal range. */
#define SW_CLIP_PLANE_TINY 1e-150
#define SW_CLIP_PLANE_HUGE 1e150

/* The plane n·x + d <= 0 with a unit normal (n need not be unit).  *trivial:
 * SW_CLIP_KEEPS_ALL or SW_CLIP_CUTS_ALL when the rescaled offset leaves the
 * double range (the plane is beyond every finite point). */
static swarp_status sw_clip_plane_unit(swarp_vec3 n_raw, double d_raw, swarp_vec3* n, double* d, int* trivial) {
    *trivial = SW_CLIP_CUTS;
    const double m = sw_max(fabs(n_raw.x), sw_max(fabs(n_raw.y), fabs(n_raw.z)));
    if (!(m > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    if (m < SW_CLIP_PLANE_TINY || m > SW_CLIP_PLANE_HUGE) {
        n_raw = sw_v3(n_raw.x / m, n_raw.y / m, n_raw.z / m);
        d_raw /= m;
        if (!sw_finite(d_raw)) { /* the plane beyond the double range: all kept or all cut */
            *trivial = d_raw < 0.0 ? SW_CLIP_KEEPS_ALL : SW_CLIP_CUTS_ALL;
            return SWARP_OK;
        }
    }
    double len = sw_len_fast(n_raw);
    if (!(len > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    *n = sw_scale(n_raw, 1.0 / len);
    *d = d_raw / len;
    /* |d_raw| within a factor len (< 1 by rounding for a unit normal) of
     * DBL_MAX: the offset overflows although the plane is finite.  Its
     * distance |d_raw|/len from the origin exceeds DBL_MAX >= |v| >= |n·v|
     * for every vertex v of Euclidean norm up to DBL_MAX, so every such
     * vertex lies strictly on the side of the sign of d_raw, as for the
     * rescaled planes above (an infinite d would instead give distances
     * inf - inf and an infinite tolerance that keeps everything). */
    if (!sw_finite(*d)) *trivial = d_raw < 0.0 ? SW_CLIP_KEEPS_ALL : SW_CLIP_CUTS_ALL;
    return SWARP_OK;
}

/* A clip that keeps everything (*unchanged, out not written) or nothing. */
static swarp_status sw_clip_trivial(int trivial, swarp_polyhedron* out, int* unchanged) {
    if (trivial == SW_CLIP_KEEPS_ALL) {
        *unchanged = 1;
    } else {
        out->vertex_count = 0;
        out->face_count = 0;
    }
    return SWARP_OK;
}

/* Signed distances and classes of in's vertices (eps: the on-plane
 * tolerance).  Returns SW_CLIP_CUTS, or the trivial outcome when no vertex
 * lies outside, or none inside or on the plane. */
static int sw_clip_classify(const swarp_polyhedron* in, sw_clip* c, double eps) {
    const uint32_t nv = in->vertex_count;
    const swarp_vec3 n = c->n;
    const double d = c->d;
    double* dist = c->dist;
    int any_out = 0, any_in = 0;
    if (c->unit_normal) { /* ±(one coordinate) + d: the same values as the dot with the axis */
        const swarp_vec3* v = in->vertices;
        if (n.x != 0.0)
            for (uint32_t i = 0; i < nv; ++i) dist[i] = n.x * v[i].x + d;
        else if (n.y != 0.0)
            for (uint32_t i = 0; i < nv; ++i) dist[i] = n.y * v[i].y + d;
        else
            for (uint32_t i = 0; i < nv; ++i) dist[i] = n.z * v[i].z + d;
    } else {
        for (uint32_t i = 0; i < nv; ++i) dist[i] = sw_dot(n, in->vertices[i]) + d;
    }
    for (uint32_t i = 0; i < nv; ++i) {
        int o = dist[i] > eps, u = dist[i] < -eps; /* branch-free */
        c->cls[i] = (uint8_t)(SW_ON + 2 * o - u);  /* 4, 2 or 1 */
        any_out |= o;
        any_in |= !o;
    }
    if (!any_out) return SW_CLIP_KEEPS_ALL;
    if (!any_in) return SW_CLIP_CUTS_ALL;
    return SW_CLIP_CUTS;
}

/* The kept (in or on) vertices of in, in order, as t's first vertices. */
static void sw_clip_keep_vertices(const swarp_polyhedron* in, sw_clip* c, swarp_polyhedron* t) {
    uint32_t tv = 0;
    c->n_on = 0;
    c->n_cap = 0;
    c->cap_bad = 0;
    c->cap_coincides = 0;
    c->n_edges = 0;
    c->tf = 0;
    for (uint32_t i = 0; i < in->vertex_count; ++i) {
        if (c->cls[i] != SW_OUT) {
            c->map[i] = (uint8_t)tv;
            t->vertices[tv] = in->vertices[i];
            c->onf[tv] = c->cls[i] == SW_ON;
            c->nxt[tv] = 0xFF;
            if (c->cls[i] == SW_ON) c->on_plane[c->n_on++] = (uint8_t)tv;
            ++tv;
        }
    }
    c->tv = tv;
}

/* The output vertex where the strictly crossing edge i-j meets the plane:
 * cut once per edge and cached, so both faces of the edge share it. */
static swarp_status sw_clip_edge_vertex(const swarp_polyhedron* in, sw_clip* c, swarp_polyhedron* t, uint8_t i,
                                        uint8_t j, uint8_t* v) {
    uint8_t lo = i < j ? i : j, hi = i < j ? j : i;
    uint32_t e = 0;
    for (; e < c->n_edges; ++e)
        if (c->edge_lo[e] == lo && c->edge_hi[e] == hi) break;
    if (e == c->n_edges) {
        const uint32_t tv = c->tv;
        if (tv >= SWARP_POLY_MAX_VERTICES) return SWARP_ERR_CAPACITY;
        t->vertices[tv] = sw_edge_cut(in->vertices, c->dist, lo, hi);
        if (c->unit_normal) sw_cut_on_axis_plane(&t->vertices[tv], c->n, c->d);
        c->edge_lo[e] = lo;
        c->edge_hi[e] = hi;
        c->edge_v[e] = (uint8_t)tv;
        c->onf[tv] = 1;
        c->nxt[tv] = 0xFF;
        c->on_plane[c->n_on++] = (uint8_t)tv;
        c->tv = tv + 1;
        ++c->n_edges;
    }
    *v = c->edge_v[e];
    return SWARP_OK;
}

/* The loop of the cut face fl (fn vertices): its kept vertices and, between
 * them, the cut point of each strictly crossing edge, into loop (*m). */
static swarp_status sw_clip_cut_loop(const swarp_polyhedron* in, sw_clip* c, swarp_polyhedron* t,
                                     const uint8_t* fl, uint32_t fn, uint8_t* loop, uint32_t* m_out) {
    uint32_t m = 0;
    for (uint32_t k = 0; k < fn; ++k) {
        uint8_t i = fl[k], j = fl[k + 1 == fn ? 0 : k + 1];
        if (c->cls[i] != SW_OUT) {
            if (m >= SWARP_POLY_MAX_FACE_VERTICES) return SWARP_ERR_CAPACITY;
            loop[m++] = c->map[i];
        }
        if ((c->cls[i] | c->cls[j]) == (SW_IN | SW_OUT)) { /* strictly crossing */
            uint8_t v;
            swarp_status s = sw_clip_edge_vertex(in, c, t, i, j, &v);
            if (s != SWARP_OK) return s;
            if (m >= SWARP_POLY_MAX_FACE_VERTICES) return SWARP_ERR_CAPACITY;
            loop[m++] = v;
        }
    }
    *m_out = m;
    return SWARP_OK;
}

/* A kept face's in-plane edges p -> q give the cap's edges q -> p. */
static void sw_clip_note_cap_edges(sw_clip* c, const uint8_t* loop, uint32_t m) {
    uint8_t p = loop[m - 1];
    for (uint32_t k = 0; k < m; ++k) {
        const uint8_t q = loop[k];
        if (c->onf[p] & c->onf[q]) {
            c->cap_bad |= c->nxt[q] != 0xFF;
            c->nxt[q] = p;
            ++c->n_cap;
        }
        p = q;
    }
}

/* Every face of in, clipped, into t's faces (those wholly outside, or left
 * with fewer than 3 vertices, dropped). */
static swarp_status sw_clip_faces(const swarp_polyhedron* in, sw_clip* c, swarp_polyhedron* t) {
    for (uint32_t f = 0; f < in->face_count; ++f) {
        uint32_t fn = in->face_vertex_count[f];
        const uint8_t* fl = in->face_vertices[f];
        uint8_t* loop = t->face_vertices[c->tf]; /* tf <= f < SWARP_POLY_MAX_FACES */
        /* most faces lie wholly on one side: only cut faces need the walk
         * over their edges */
        unsigned any = 0;
        for (uint32_t k = 0; k < fn; ++k) any |= c->cls[fl[k]];
        if (any == SW_OUT) continue; /* wholly outside */
        uint32_t m = 0;
        if (!(any & SW_OUT)) { /* wholly kept: no edge crosses */
            for (uint32_t k = 0; k < fn; ++k) loop[k] = c->map[fl[k]];
            m = fn;
        } else {
            swarp_status s = sw_clip_cut_loop(in, c, t, fl, fn, loop, &m);
            if (s != SWARP_OK) return s;
        }
        if (m < 3) continue;
        if (any == SW_ON) { /* the face lies in the clip plane */
            swarp_vec3 fnrm = {in->planes[f].a, in->planes[f].b, in->planes[f].c};
            if (sw_dot(fnrm, c->n) > 0.0) c->cap_coincides = 1;
        }
        if (any & (SW_ON | SW_OUT)) sw_clip_note_cap_edges(c, loop, m);
        t->face_vertex_count[c->tf] = m;
        t->planes[c->tf] = in->planes[f];
        ++c->tf;
    }
    return SWARP_OK;
}

/* A point set (no faces), in practice a collapse onto a line (a flat
 * polygon thinner than eps loses its loops, sw_remap_faces) whose hull is
 * the segment between its ends.  The face walk cuts no edge of it and
 * would keep the inner vertices only: a segment cut by a plane would become
 * a point or stay a segment as the earlier rounding had collapsed it or
 * not.  Each strictly crossing pair is cut (the hull of the kept and the
 * cut points is the clipped hull); a cut within eps of a point kept or cut
 * already adds nothing (for a segment the cuts are all one point). */
static swarp_status sw_clip_point_set(const swarp_polyhedron* in, const sw_clip* c, swarp_polyhedron* t,
                                      double in_scale) {
    const double cut_eps = SWARP_POLY_EPS_REL * in_scale;
    uint32_t tv = c->tv;
    for (uint32_t i = 0; i < in->vertex_count; ++i) {
        if (c->cls[i] != SW_IN) continue;
        for (uint32_t j = 0; j < in->vertex_count; ++j) {
            if (c->cls[j] != SW_OUT) continue;
            swarp_vec3 p = sw_edge_cut(in->vertices, c->dist, (uint8_t)i, (uint8_t)j);
            if (c->unit_normal) sw_cut_on_axis_plane(&p, c->n, c->d);
            uint32_t k = 0;
            for (; k < tv; ++k) {
                const swarp_vec3 w = t->vertices[k];
                if (fabs(p.x - w.x) <= cut_eps && fabs(p.y - w.y) <= cut_eps && fabs(p.z - w.z) <= cut_eps) break;
            }
            if (k < tv) continue;
            if (tv >= SWARP_POLY_MAX_VERTICES) return SWARP_ERR_CAPACITY;
            t->vertices[tv++] = p;
        }
    }
    t->vertex_count = tv;
    t->face_count = 0;
    return SWARP_OK;
}

/* The cap's loop from the in-plane edges, into idx: usually they chain into
 * one cycle through all n_on on-plane vertices.  0 when they do not. */
static int sw_cap_chain(const sw_clip* c, uint8_t* idx) {
    const uint32_t n_on = c->n_on;
    int chained = !c->cap_bad && c->n_cap == n_on;
    if (chained) {
        uint8_t v = c->on_plane[0];
        idx[0] = v;
        for (uint32_t k = 1; k < n_on && chained; ++k) {
            v = c->nxt[v];
            chained = v != 0xFF && v != c->on_plane[0];
            idx[k] = v;
        }
        chained = chained && c->nxt[v] == c->on_plane[0];
    }
    return chained;
}

/* The cap's loop when the edges do not chain (degenerate cuts): the
 * on-plane vertices sorted by angle around their centroid in an in-plane
 * basis (e1, e2) with e1 x e2 = n, counter-clockwise seen along +n. */
static void sw_cap_sort_by_angle(const sw_clip* c, const swarp_polyhedron* t, uint8_t* idx) {
    const uint32_t n_on = c->n_on;
    const swarp_vec3 n = c->n;
    swarp_vec3 ctr = {0, 0, 0};
    for (uint32_t k = 0; k < n_on; ++k) ctr = sw_add(ctr, t->vertices[c->on_plane[k]]);
    ctr = sw_scale(ctr, 1.0 / n_on);
    swarp_vec3 ref = fabs(n.x) < SW_REF_AXIS_MAX ? sw_v3(1, 0, 0)
                   : (fabs(n.y) < SW_REF_AXIS_MAX ? sw_v3(0, 1, 0) : sw_v3(0, 0, 1));
    swarp_vec3 e1 = {1, 0, 0}, e2;
    if (c->unit_normal) /* an axis: ref x n is a unit axis already */
        e1 = sw_cross(ref, n);
    else
        sw_normalize_fast(sw_cross(ref, n), &e1);
    e2 = sw_cross(n, e1);
    double key[SWARP_POLY_MAX_FACE_VERTICES];
    for (uint32_t k = 0; k < n_on; ++k) {
        swarp_vec3 q = sw_sub(t->vertices[c->on_plane[k]], ctr);
        double kk = sw_pseudo_angle(sw_dot(q, e1), sw_dot(q, e2));
        uint32_t j = k;
        while (j > 0 && key[j - 1] > kk) {
            key[j] = key[j - 1];
            idx[j] = idx[j - 1];
            --j;
        }
        key[j] = kk;
        idx[j] = c->on_plane[k];
    }
}

/* The cap: the new face on the clip plane, counter-clockwise seen from
 * outside (along +n); none when a kept face already covers the plane. */
static swarp_status sw_clip_cap(sw_clip* c, swarp_polyhedron* t) {
    if (c->n_on < 3 || c->cap_coincides) return SWARP_OK;
    if (c->n_on > SWARP_POLY_MAX_FACE_VERTICES) return SWARP_ERR_CAPACITY;
    if (c->tf >= SWARP_POLY_MAX_FACES) return SWARP_ERR_CAPACITY;
    uint8_t* idx = t->face_vertices[c->tf];
    if (!sw_cap_chain(c, idx)) sw_cap_sort_by_angle(c, t, idx);
    t->face_vertex_count[c->tf] = c->n_on;
    t->planes[c->tf].a = c->n.x;
    t->planes[c->tf].b = c->n.y;
    t->planes[c->tf].c = c->n.z;
    t->planes[c->tf].d = c->d;
    ++c->tf;
    return SWARP_OK;
}

/* Clips in by n·x + d <= 0 into out (out != in; n need not be unit).  When
 * no vertex lies outside, *unchanged is set and out is not written. */
static swarp_status sw_poly_clip_to(const swarp_polyhedron* in, swarp_vec3 n_raw, double d_raw,
                                    swarp_polyhedron* out, int* unchanged, double scale /* 0: compute */,
                                    int unit_normal /* n is a unit axis (box planes): no sqrt, no division */) {
    *unchanged = 0;
    sw_clip c;
    c.n = n_raw;
    c.d = d_raw;
    c.unit_normal = unit_normal;
    if (!unit_normal) {
        int trivial;
        swarp_status s = sw_clip_plane_unit(n_raw, d_raw, &c.n, &c.d, &trivial);
        if (s != SWARP_OK) return s;
        if (trivial != SW_CLIP_CUTS) return sw_clip_trivial(trivial, out, unchanged);
    }
    if (in->vertex_count == 0) {
        *unchanged = 1;
        return SWARP_OK;
    }
    /* tolerance for "on the plane": see SWARP_POLY_EPS_REL */
    const double in_scale = scale > 0.0 ? scale : sw_poly_scale(in);
    const double eps = SWARP_POLY_EPS_REL * sw_max(in_scale, fabs(c.d));
    const int trivial = sw_clip_classify(in, &c, eps);
    if (trivial != SW_CLIP_CUTS) return sw_clip_trivial(trivial, out, unchanged);
    swarp_polyhedron* t = out; /* built in place (out != in) */
    sw_clip_keep_vertices(in, &c, t);
    const uint32_t n_kept = c.tv;
    swarp_status s = sw_clip_faces(in, &c, t);
    if (s != SWARP_OK) return s;
    if (in->face_count == 0) return sw_clip_point_set(in, &c, t, in_scale);
    s = sw_clip_cap(&c, t);
    if (s != SWARP_OK) return s;
    t->vertex_count = c.tv;
    t->face_count = c.tf;
    sw_poly_merge_on_plane(t, c.on_plane, c.n_on, n_kept, SWARP_POLY_EPS_REL * in_scale);
    return SWARP_OK;
}

/* Keeps n·x + d <= 0; n need not be unit.  in and out may alias. */
swarp_status sw_poly_clip(const swarp_polyhedron* in, swarp_vec3 n, double d, swarp_polyhedron* out) {
    swarp_polyhedron tmp;
    swarp_polyhedron* dst = (out == in) ? &tmp : out;
    int unchanged = 0;
    swarp_status s = sw_poly_clip_to(in, n, d, dst, &unchanged, 0.0, 0);
    if (s != SWARP_OK) return s;
    if (unchanged) {
        if (out != in) sw_poly_copy(in, out);
    } else if (dst != out) {
        sw_poly_copy(dst, out);
    }
    return SWARP_OK;
}

static void sw_poly_bounds(const swarp_polyhedron* p, double lo[3], double hi[3]) {
    double lx = INFINITY, ly = INFINITY, lz = INFINITY, hx = -INFINITY, hy = -INFINITY, hz = -INFINITY;
    for (uint32_t i = 0; i < p->vertex_count; ++i) { /* min/max without branches */
        const swarp_vec3 v = p->vertices[i];
        lx = v.x < lx ? v.x : lx, hx = v.x > hx ? v.x : hx;
        ly = v.y < ly ? v.y : ly, hy = v.y > hy ? v.y : hy;
        lz = v.z < lz ? v.z : lz, hz = v.z > hz ? v.z : hz;
    }
    lo[0] = lx, lo[1] = ly, lo[2] = lz;
    hi[0] = hx, hi[1] = hy, hi[2] = hz;
}

/* min/max of one coordinate (0: x, 1: y, 2: z) over the vertices */
static void sw_poly_axis_bounds(const swarp_polyhedron* p, int c, double* lo, double* hi) {
    double l = INFINITY, h = -INFINITY;
    const uint32_t n = p->vertex_count;
    const swarp_vec3* v = p->vertices;
    if (c == 0)
        for (uint32_t i = 0; i < n; ++i) l = v[i].x < l ? v[i].x : l, h = v[i].x > h ? v[i].x : h;
    else if (c == 1)
        for (uint32_t i = 0; i < n; ++i) l = v[i].y < l ? v[i].y : l, h = v[i].y > h ? v[i].y : h;
    else
        for (uint32_t i = 0; i < n; ++i) l = v[i].z < l ? v[i].z : l, h = v[i].z > h ? v[i].z : h;
    *lo = l;
    *hi = h;
}

swarp_status sw_poly_clip_box_order(const swarp_polyhedron* in, const swarp_aabb* box, const uint8_t order[6],
                                    swarp_polyhedron* out) {
    const swarp_vec3 ns[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    const double ds[6] = {box->min.x, -box->max.x, box->min.y, -box->max.y, box->min.z, -box->max.z};
    const double* bmin = &box->min.x;
    const double* bmax = &box->max.x;
    /* ping-pong between out and a local buffer: no copy per plane; a plane
     * the current bounds do not cross is skipped without a clip */
    swarp_polyhedron buf;
    const swarp_polyhedron* src = in;
    double lo[3], hi[3];
    sw_poly_bounds(in, lo, hi);
    /* after a clip only the bounds of the axis the next plane needs are
     * recomputed (stale ones are still bounds: clipping only shrinks) */
    int stale = 0;
    for (int q = 0; q < 6; ++q) {
        const int k = order[q], c = k / 2;
        if (stale & (1 << c)) {
            sw_poly_axis_bounds(src, c, &lo[c], &hi[c]);
            stale &= ~(1 << c);
        }
        if ((k & 1) ? !(hi[c] > bmax[c]) : !(lo[c] < bmin[c])) continue;
        swarp_polyhedron* dst = (src == out) ? &buf : out;
        int unchanged = 0;
        /* the scale from the bounds: the largest absolute coordinate */
        double sc = SW_POLY_SCALE_MIN;
        for (int a = 0; a < 3; ++a) sc = sw_max(sc, sw_max(fabs(lo[a]), fabs(hi[a])));
        swarp_status s = sw_poly_clip_to(src, ns[k], ds[k], dst, &unchanged, sc, 1);
        if (s != SWARP_OK) return s;
        if (unchanged) continue;
        src = dst;
        if (src->vertex_count == 0) break;
        stale = 7;
    }
    if (src != out) sw_poly_copy(src, out);
    return SWARP_OK;
}

swarp_status sw_poly_clip_box(const swarp_polyhedron* in, const swarp_aabb* box, swarp_polyhedron* out) {
    static const uint8_t order[6] = {0, 1, 2, 3, 4, 5}; /* -x, +x, -y, +y, -z, +z */
    return sw_poly_clip_box_order(in, box, order, out);
}

swarp_status sw_poly_check_counts(const swarp_polyhedron* in) {
    if (in->vertex_count > SWARP_POLY_MAX_VERTICES || in->face_count > SWARP_POLY_MAX_FACES)
        return SWARP_ERR_INVALID_ARGUMENT;
    return SWARP_OK;
}

swarp_status sw_poly_check_contents(const swarp_polyhedron* in) {
    for (uint32_t i = 0; i < in->vertex_count; ++i)
        if (!sw_finite3(&in->vertices[i])) return SWARP_ERR_NON_FINITE;
    for (uint32_t f = 0; f < in->face_count; ++f) {
        if (in->face_vertex_count[f] > SWARP_POLY_MAX_FACE_VERTICES) return SWARP_ERR_INVALID_ARGUMENT;
        for (uint32_t k = 0; k < in->face_vertex_count[f]; ++k)
            if (in->face_vertices[f][k] >= in->vertex_count) return SWARP_ERR_INVALID_ARGUMENT;
    }
    return SWARP_OK;
}

swarp_status sw_poly_validate(const swarp_polyhedron* in) {
    swarp_status s = sw_poly_check_counts(in);
    if (s != SWARP_OK) return s;
    return sw_poly_check_contents(in);
}

SWARP_API swarp_status swarp_poly_clip(const swarp_polyhedron* in, const swarp_plane* plane,
                                       swarp_polyhedron* out) {
    if (!in || !plane || !out) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(plane->a) || !sw_finite(plane->b) || !sw_finite(plane->c) || !sw_finite(plane->d))
        return SWARP_ERR_NON_FINITE;
    swarp_status s = sw_poly_validate(in);
    if (s != SWARP_OK) return s;
    swarp_vec3 n = {plane->a, plane->b, plane->c};
    if (!(sw_len_fast(n) > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    /* compute into a local: outputs stay untouched on error */
    swarp_polyhedron t;
    s = sw_poly_clip(in, n, plane->d, &t);
    if (s != SWARP_OK) return s;
    sw_poly_publish(&t, out);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_poly_clip_aabb(const swarp_polyhedron* in, const swarp_aabb* box,
                                            swarp_polyhedron* out) {
    if (!in || !box || !out) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite3(&box->min) || !sw_finite3(&box->max)) return SWARP_ERR_NON_FINITE;
    if (!(box->min.x <= box->max.x && box->min.y <= box->max.y && box->min.z <= box->max.z))
        return SWARP_ERR_BOX_INVERTED;
    swarp_status s = sw_poly_validate(in);
    if (s != SWARP_OK) return s;
    swarp_polyhedron t;
    s = sw_poly_clip_box(in, box, &t);
    if (s != SWARP_OK) return s;
    sw_poly_publish(&t, out);
    return SWARP_OK;
}
