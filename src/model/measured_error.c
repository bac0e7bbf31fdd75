/* The measured aliasing error of a returned matrix: at a receiver point X
 * with normal N, D = J_scr J_tex^-1 maps one texel step on the receiver to
 * the screen displacement it covers.  [RHS] (2.3)-(2.8) are the closed forms
 * of |D e_s| and |D e_t| for an overhead light on the view axis with bisector
 * receivers; here D is evaluated from the camera and the matrix themselves,
 * at any point, for any light, so the figure reported is the figure of the
 * matrix returned. */
#include "geometry/geometry_internal.h"

/* J_tex is treated as singular below this ratio |det J| / (|J|_F^2 / 2): its
 * condition number is then above about 2e12, and D = J_scr J_tex^-1 keeps
 * fewer than four significant digits in double; the point is reported with
 * sigma = +inf (the map does not resolve the receiver there). */
#define SW_JTEX_SINGULAR_REL 1e-12

/* A unit normal N whose component orthogonal to r is below this fraction is
 * taken as parallel to r, and w_x is built from the camera's up vector
 * instead (r - (r.N)N has then lost all but a few bits to cancellation). */
#define SW_NORMAL_PARALLEL_R 1e-6

/* A point counts as inside the map when |x|, |y| <= w (1 + SW_INSIDE_REL):
 * the boundary of H is fitted to the map's edge, where the fit's rounding
 * leaves |x / w| a few units of 1e-16 above 1. */
#define SW_INSIDE_REL 1e-12

/* Defaults of swarp_measure_max: the vertices of H, a 7 x 7 NDC lattice at
 * 5 depths and 24 compass-search steps from the worst vertex, the worst
 * near-face point and the two worst local maxima of the lattice.  The
 * maximum of these projective maps' error over the convex H lies at or near
 * a vertex, on the near face (the screen's 1/z), or inside one lattice cell
 * of the worst sample, which the search resolves to a small fraction of a
 * cell; tests/model/test_measured_error.c states the difference from a 33 x
 * 33 x 65 lattice with the same search (within 3 %, in practice equal). */
#define SW_MEASURE_GRID 7u
#define SW_MEASURE_DEPTHS 5u
#define SW_MEASURE_REFINE 24u

/* The camera's projection at one point, as the screen sees it. */
typedef struct sw_screen {
    swarp_vec3 eye, f, r, u;
    double sx, sy; /* pixels per unit of (x/z, y/z): W / (2 tanΘ a), H / (2 tanΘ) */
} sw_screen;

static void sw_screen_make(const swarp_camera* cam, const swarp_measure_res* res, sw_screen* s) {
    sw_camera_basis(cam, &s->f, &s->r, &s->u);
    s->eye = cam->eye;
    const double t = tan(sw_half_fovy(cam->fovy));
    s->sx = (double)res->screen_width / (2.0 * t * cam->aspect);
    s->sy = (double)res->screen_height / (2.0 * t);
}

/* The receiver's tangent frame (w_x, w_z) of the definition above. */
static void sw_receiver_tangents(const sw_screen* s, swarp_vec3 n, swarp_vec3* wx, swarp_vec3* wz) {
    swarp_vec3 t = sw_sub(s->r, sw_scale(n, sw_dot(s->r, n)));
    if (!(sw_len_fast(t) > SW_NORMAL_PARALLEL_R)) t = sw_sub(s->u, sw_scale(n, sw_dot(s->u, n)));
    sw_normalize_fast(t, wx);
    *wz = sw_cross(n, *wx);
}

/* d(pixel x, y)/d(w) of the perspective division by the planar depth
 * z = d.f:  d(a/z) = (da z - a dz)/z^2, a = d.r (d.u). */
static void sw_screen_jacobian(const sw_screen* s, swarp_vec3 d, double z, swarp_vec3 w,
                               double col[2]) {
    const double dz = sw_dot(w, s->f);
    col[0] = s->sx * (sw_dot(w, s->r) * z - sw_dot(d, s->r) * dz) / (z * z);
    col[1] = s->sy * (sw_dot(w, s->u) * z - sw_dot(d, s->u) * dz) / (z * z);
}

/* d(texel s, t)/d(w) of clip (x/w, y/w), c the point's clip coordinates:
 * d(x/w) = (dx w - x dw)/w^2, with (dx, dy, dw) = M (w, 0). */
static void sw_map_jacobian(const swarp_mat4* m, const swarp_measure_res* res, swarp_vec4 c,
                            swarp_vec3 w, double col[2]) {
    const swarp_vec4 dc = sw_xform4(m, (swarp_vec4){w.x, w.y, w.z, 0.0});
    const double w2 = c.w * c.w;
    col[0] = 0.5 * (double)res->map_width * (dc.x * c.w - c.x * dc.w) / w2;
    col[1] = 0.5 * (double)res->map_height * (dc.y * c.w - c.y * dc.w) / w2;
}

/* Largest singular value of the 2x2 matrix [a b; c d]:
 * sigma^2 = (F + sqrt(F^2 - 4 det^2)) / 2, F the squared Frobenius norm,
 * written with two lengths so that F^2 - 4 det^2 = ((a-d)^2 + (b+c)^2)((a+d)^2 + (b-c)^2)
 * never cancels below zero. */
static double sw_sigma_max(double a, double b, double c, double d) {
    const double p = sw_len_fast(sw_v3(a - d, b + c, 0.0)), q = sw_len_fast(sw_v3(a + d, b - c, 0.0));
    return 0.5 * (p + q);
}

/* What of D does not depend on the matrix: the receiver's tangents and
 * J_scr at x (d = x - eye, z its planar depth > 0). */
static void sw_receiver_screen(const sw_screen* s, swarp_vec3 d, double z, swarp_vec3 n_unit,
                               sw_receiver* rc) {
    sw_receiver_tangents(s, n_unit, &rc->wx, &rc->wz);
    sw_screen_jacobian(s, d, z, rc->wx, rc->js[0]);
    sw_screen_jacobian(s, d, z, rc->wz, rc->js[1]);
}

/* D = J_scr J_tex^-1 (d[row][column], columns along the texel steps s, t)
 * at the receiver rc, whose clip coordinates under m are c.  Returns 0
 * where J_tex is singular (d untouched). */
static int sw_receiver_d(const swarp_mat4* m, const swarp_measure_res* res, const sw_receiver* rc,
                         swarp_vec4 c, double d[2][2]) {
    double jt[2][2]; /* [column][row]: column 0 along w_x, 1 along w_z */
    sw_map_jacobian(m, res, c, rc->wx, jt[0]);
    sw_map_jacobian(m, res, c, rc->wz, jt[1]);
    const double det = jt[0][0] * jt[1][1] - jt[1][0] * jt[0][1];
    const double fro = jt[0][0] * jt[0][0] + jt[0][1] * jt[0][1] + jt[1][0] * jt[1][0] +
                       jt[1][1] * jt[1][1];
    if (!(c.w > 0.0) || !(fabs(det) > SW_JTEX_SINGULAR_REL * 0.5 * fro) || !sw_finite(det)) return 0;
    /* J_tex^-1 = [jt11 -jt10; -jt01 jt00] / det (rows s, t of the texel
     * step; columns w_x, w_z), D = J_scr J_tex^-1 */
    const double i00 = jt[1][1] / det, i01 = -jt[1][0] / det;
    const double i10 = -jt[0][1] / det, i11 = jt[0][0] / det;
    const double (*js)[2] = rc->js;
    d[0][0] = js[0][0] * i00 + js[1][0] * i10, d[0][1] = js[0][0] * i01 + js[1][0] * i11;
    d[1][0] = js[0][1] * i00 + js[1][1] * i10, d[1][1] = js[0][1] * i01 + js[1][1] * i11;
    return 1;
}

static void sw_measure_one(const sw_screen* s, const swarp_mat4* m, const swarp_measure_res* res,
                           swarp_vec3 x, swarp_vec3 n_unit, swarp_texel_error* out) {
    swarp_texel_error e = {0.0, 0.0, 0.0, 0u, 0u};
    const swarp_vec3 dx = sw_sub(x, s->eye);
    const double z = sw_dot(dx, s->f);
    const swarp_vec4 c = sw_xform_point(m, x);
    const double edge = c.w * (1.0 + SW_INSIDE_REL);
    if (c.w > 0.0 && fabs(c.x) <= edge && fabs(c.y) <= edge) e.flags |= SWARP_TEXEL_INSIDE;
    if (!(z > 0.0)) {
        e.flags |= SWARP_TEXEL_BEHIND_EYE;
        *out = e;
        return;
    }
    sw_receiver rc;
    sw_receiver_screen(s, dx, z, n_unit, &rc);
    double d[2][2];
    if (!sw_receiver_d(m, res, &rc, c, d)) {
        e.m_s = e.m_t = e.sigma = INFINITY;
        e.flags |= SWARP_TEXEL_SINGULAR;
        *out = e;
        return;
    }
    e.m_s = sw_len_fast(sw_v3(d[0][0], d[1][0], 0.0));
    e.m_t = sw_len_fast(sw_v3(d[0][1], d[1][1], 0.0));
    e.sigma = sw_sigma_max(d[0][0], d[0][1], d[1][0], d[1][1]);
    *out = e;
}

static swarp_status sw_check_measure_res(const swarp_measure_res* res, swarp_measure_res* out) {
    if (!res) return SWARP_ERR_NULL_POINTER;
    swarp_measure_res r = *res;
    if (r.map_height == 0) r.map_height = r.map_width;
    if (!r.screen_width || !r.screen_height || !r.map_width) return SWARP_ERR_RESOLUTION;
    *out = r;
    return SWARP_OK;
}

static swarp_status sw_check_measure_inputs(const swarp_camera* cam, const swarp_mat4* matrix,
                                            const swarp_measure_res* res, swarp_measure_res* r) {
    if (!cam || !matrix) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_camera_shape(cam);
    if (st != SWARP_OK) return st;
    if (!sw_mat_finite(matrix)) return SWARP_ERR_NON_FINITE;
    return sw_check_measure_res(res, r);
}

SWARP_API swarp_status swarp_measure_points(const swarp_camera* cam, const swarp_mat4* matrix,
                                            const swarp_measure_res* res,
                                            const swarp_vec3* points, const swarp_vec3* normals,
                                            size_t count, swarp_texel_error* out) {
    swarp_measure_res r;
    swarp_status st = sw_check_measure_inputs(cam, matrix, res, &r);
    if (st != SWARP_OK) return st;
    if (count == 0) return SWARP_OK;
    if (!points || !normals || !out) return SWARP_ERR_NULL_POINTER;
    for (size_t i = 0; i < count; ++i) {
        if (!sw_finite3(&points[i]) || !sw_finite3(&normals[i])) return SWARP_ERR_NON_FINITE;
        swarp_vec3 n;
        if (!sw_normalize(normals[i], &n)) return SWARP_ERR_ZERO_VECTOR;
    }
    sw_screen s;
    sw_screen_make(cam, &r, &s);
    swarp_status result = SWARP_OK;
    for (size_t i = 0; i < count; ++i) {
        swarp_vec3 n;
        sw_normalize(normals[i], &n);
        sw_measure_one(&s, matrix, &r, points[i], n, &out[i]);
        if (out[i].flags & SWARP_TEXEL_SINGULAR) result = SWARP_INFO_MEASURE_SINGULAR;
    }
    return result;
}

/* ---- the maximum over H = V ∩ S ----------------------------------------- */

typedef struct sw_region {
    sw_screen s;
    double t_x, t_y;      /* tanΘ a, tanΘ: NDC -> view-plane offsets */
    double lz0, lz1;      /* log of the planar depth range */
    double z0, z1;        /* the planar depth range grown by SW_BOX_SLACK_REL */
    int flat;             /* axis in which S is flat (H a polygon), -1 if none */
    double flat_at;       /* S's coordinate along that axis */
    swarp_aabb box, slack;  /* S, and S with the slack of its face points */
    swarp_light light;    /* direction normalised */
    const swarp_mat4* m;
    swarp_measure_res res;
} sw_region;

typedef struct sw_best {
    swarp_measured_error acc; /* running maxima and counts */
    double u[3];              /* NDC x, y and log z of the worst sample */
} sw_best;

/* S grown by SW_BOX_SLACK_REL of its extent on each side: the vertices of
 * H lie on S's faces, where the rounding of the point rebuilt from its
 * (NDC, depth) coordinates would otherwise drop them. */
#define SW_BOX_SLACK_REL 1e-9

static swarp_aabb sw_box_with_slack(const swarp_aabb* b) {
    const swarp_vec3 e = sw_scale(sw_sub(b->max, b->min), SW_BOX_SLACK_REL);
    const swarp_aabb out = {sw_sub(b->min, e), sw_add(b->max, e)};
    return out;
}

static int sw_in_box(const swarp_aabb* b, swarp_vec3 p) {
    return p.x >= b->min.x && p.x <= b->max.x && p.y >= b->min.y && p.y <= b->max.y &&
           p.z >= b->min.z && p.z <= b->max.z;
}

static double sw_axis(swarp_vec3 v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }

static void sw_set_axis(swarp_vec3* v, int k, double a) {
    if (k == 0) v->x = a;
    else if (k == 1) v->y = a;
    else v->z = a;
}

/* The point of V at NDC (x, y) and planar depth exp(lz).  For a flat S the
 * point is where the ray through NDC (x, y) meets S's plane (lz unused),
 * with its coordinate along the flat axis set to the plane's exactly: a
 * point rebuilt from a depth would lie on the plane only by rounding, and
 * whether it counted would depend on the rounding mode.  Rays parallel to
 * the plane, or meeting it outside the depth range, give NaN (outside S). */
static swarp_vec3 sw_region_point(const sw_region* g, const double u[3]) {
    swarp_vec3 dir = sw_add(g->s.f, sw_add(sw_scale(g->s.r, u[0] * g->t_x),
                                           sw_scale(g->s.u, u[1] * g->t_y)));
    if (g->flat < 0) return sw_add(g->s.eye, sw_scale(dir, exp(u[2])));
    const double z = (g->flat_at - sw_axis(g->s.eye, g->flat)) / sw_axis(dir, g->flat);
    if (!(z >= g->z0 && z <= g->z1)) return sw_v3(NAN, NAN, NAN);
    swarp_vec3 x = sw_add(g->s.eye, sw_scale(dir, z));
    sw_set_axis(&x, g->flat, g->flat_at);
    return x;
}

/* Bisector receiver: N halfway between the directions to the eye and to the
 * light, where cos ψ_e / cos ψ_l of [RHS] (2.2) is 1.  A point light at the
 * point itself, or the eye and light directions opposite, leave no bisector:
 * the view direction's reverse is used (the receiver faces the eye). */
static swarp_vec3 sw_bisector(const sw_region* g, swarp_vec3 x) {
    swarp_vec3 e, l, n;
    if (!sw_normalize_fast(sw_sub(g->s.eye, x), &e)) e = sw_scale(g->s.f, -1.0);
    if (g->light.type == SWARP_LIGHT_POINT) {
        if (!sw_normalize_fast(sw_sub(g->light.position, x), &l)) l = e;
    } else {
        l = sw_scale(g->light.direction, -1.0);
    }
    if (!sw_normalize_fast(sw_add(e, l), &n)) n = e;
    return n;
}

/* Evaluates the sample at u; returns its sigma, or -1 outside S. */
static double sw_sample(const sw_region* g, const double u[3], sw_best* b) {
    const swarp_vec3 x = sw_region_point(g, u);
    if (!sw_in_box(&g->slack, x)) return -1.0;
    swarp_texel_error e;
    sw_measure_one(&g->s, g->m, &g->res, x, sw_bisector(g, x), &e);
    swarp_measured_error* a = &b->acc;
    a->samples++;
    if (!(e.flags & SWARP_TEXEL_INSIDE)) a->outside++;
    if (e.m_s > a->max_m_s) a->max_m_s = e.m_s;
    if (e.m_t > a->max_m_t) a->max_m_t = e.m_t;
    if (e.sigma > a->max_sigma || a->samples == 1) {
        a->max_sigma = e.sigma;
        a->at = x;
        b->u[0] = u[0], b->u[1] = u[1], b->u[2] = u[2];
    }
    return e.sigma;
}

/* Lattices up to this many points keep every sample's sigma on the stack
 * (32 KiB) to find their local maxima; larger ones seed from the worst
 * sample alone (they are dense enough for one seed). */
#define SW_SEED_LATTICE_MAX 4096u
/* Local maxima of the lattice refined besides the worst vertex and the
 * worst near-face point: the error of a projective map over H can have a
 * few separate peaks (a near corner, a far corner on a box face), each
 * needing its own search; beyond the second the lattice's local maxima are
 * the shoulders of those peaks (over the test's 300 random configurations a
 * third and fourth seed never raise the maximum). */
#define SW_SEEDS 2

typedef struct sw_seeds {
    double u[SW_SEEDS][3];
    double sigma[SW_SEEDS];
    int count;
} sw_seeds;

static void sw_seed_add(sw_seeds* s, const double u[3], double sigma) {
    int i = s->count < SW_SEEDS ? s->count++ : SW_SEEDS - 1;
    if (i == SW_SEEDS - 1 && s->count == SW_SEEDS && !(sigma > s->sigma[i])) return;
    for (; i > 0 && sigma > s->sigma[i - 1]; --i) {
        s->sigma[i] = s->sigma[i - 1];
        s->u[i][0] = s->u[i - 1][0], s->u[i][1] = s->u[i - 1][1], s->u[i][2] = s->u[i - 1][2];
    }
    s->sigma[i] = sigma;
    s->u[i][0] = u[0], s->u[i][1] = u[1], s->u[i][2] = u[2];
}

static void sw_lattice_u(const sw_region* g, uint32_t n, uint32_t k, uint32_t ix, uint32_t iy, uint32_t iz,
                         double u[3]) {
    u[0] = -1.0 + 2.0 * ix / (n - 1);
    u[1] = -1.0 + 2.0 * iy / (n - 1);
    u[2] = k > 1 ? g->lz0 + (g->lz1 - g->lz0) * iz / (k - 1) : g->lz0;
}

/* 1 when sample (ix, iy, iz) is at least its 6 lattice neighbours (points
 * outside S hold -1) */
static int sw_lattice_peak(const double* v, uint32_t n, uint32_t k, uint32_t ix, uint32_t iy, uint32_t iz) {
    const double c = v[(iz * n + iy) * n + ix];
    if (!(c >= 0.0)) return 0;
    if (ix > 0 && v[(iz * n + iy) * n + ix - 1] > c) return 0;
    if (ix + 1 < n && v[(iz * n + iy) * n + ix + 1] > c) return 0;
    if (iy > 0 && v[(iz * n + iy - 1) * n + ix] > c) return 0;
    if (iy + 1 < n && v[(iz * n + iy + 1) * n + ix] > c) return 0;
    if (iz > 0 && v[((iz - 1) * n + iy) * n + ix] > c) return 0;
    if (iz + 1 < k && v[((iz + 1) * n + iy) * n + ix] > c) return 0;
    return 1;
}

/* The n x n x k lattice; its local maxima (the worst SW_SEEDS) into seeds. */
static void sw_sample_lattice(const sw_region* g, uint32_t n, uint32_t k, sw_best* b, sw_seeds* seeds) {
    double v[SW_SEED_LATTICE_MAX];
    const int keep = (size_t)n * n * k <= SW_SEED_LATTICE_MAX;
    double best_u[3] = {0.0, 0.0, 0.0}, best = -1.0;
    for (uint32_t iz = 0; iz < k; ++iz)
        for (uint32_t iy = 0; iy < n; ++iy)
            for (uint32_t ix = 0; ix < n; ++ix) {
                double u[3];
                sw_lattice_u(g, n, k, ix, iy, iz, u);
                const double sigma = sw_sample(g, u, b);
                if (keep) v[(iz * n + iy) * n + ix] = sigma;
                if (sigma > best) best = sigma, best_u[0] = u[0], best_u[1] = u[1], best_u[2] = u[2];
            }
    if (!keep) {
        if (best >= 0.0) sw_seed_add(seeds, best_u, best);
        return;
    }
    for (uint32_t iz = 0; iz < k; ++iz)
        for (uint32_t iy = 0; iy < n; ++iy)
            for (uint32_t ix = 0; ix < n; ++ix)
                if (sw_lattice_peak(v, n, k, ix, iy, iz)) {
                    double u[3];
                    sw_lattice_u(g, n, k, ix, iy, iz, u);
                    sw_seed_add(seeds, u, v[(iz * n + iy) * n + ix]);
                }
}

static double sw_clampd(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

/* The compass search stops once its step is below this fraction of a
 * lattice cell: sigma of these maps changes by at most about twice its own
 * value per unit of log z or NDC (the 1/z of the screen and the
 * perspective of the warp), and a cell is at most 2 / (n - 1) NDC and
 * log(f / n) / (k - 1) in log z (<= 2.3 at far/near 10^4, k = 5), so
 * stopping at 2^-10 of a cell leaves the maximum within about 0.45 % of
 * the search's limit even where sigma is steepest (at a smooth interior
 * peak the loss is quadratic in the step, far less), below the sampling's
 * stated 3 %. */
#define SW_REFINE_RES (1.0 / 1024.0)

/* Every seed's search runs to this fraction of a lattice cell; only the
 * worst continues to SW_REFINE_RES.  By then each search sits within 1/32
 * of a cell of its local maximum, where sigma is within a few per mille of
 * the peak at a smooth maximum (the loss is quadratic in the distance) and
 * within the linear bound of SW_REFINE_RES's comment times 32 (14 %) only
 * at a kink; two peaks that close are both within the stated 3 % of the
 * worse one's refined value in the configurations the tests sample, and
 * the finer steps of the other searches (most of their samples) change
 * nothing there. */
#define SW_REFINE_COARSE (1.0 / 32.0)

/* A compass search over (NDC x, NDC y, log z): the neighbours along the
 * axes at the current step, moving to the worst when it is worse, halving
 * the step when none is.  Deterministic; the lattice spacing is the first
 * step, so each halving resolves the maximum to half as much of a cell
 * along each axis.  After a move the neighbour back along the axis of the
 * move is the previous centre, already sampled and lower, and a neighbour
 * clamped onto the centre (a peak on H's boundary, the common case: the
 * near face, an edge of the view) is the centre itself: neither is sampled
 * again. */
typedef struct sw_compass {
    double c[3], h[3], h0, best;
    uint32_t it;               /* iterations taken (at most `steps` in all) */
    int back_axis, back_sgn;   /* the neighbour that is the previous centre */
} sw_compass;

static void sw_compass_start(const sw_region* g, uint32_t n, uint32_t k, const double seed[3], double seed_sigma,
                             sw_compass* q) {
    q->h0 = 2.0 / (n - 1);
    q->h[0] = q->h[1] = q->h0;
    q->h[2] = k > 1 ? (g->lz1 - g->lz0) / (k - 1) : 0.0;
    q->c[0] = seed[0], q->c[1] = seed[1], q->c[2] = seed[2];
    q->best = seed_sigma;
    q->it = 0;
    q->back_axis = -1, q->back_sgn = 0;
}

/* runs the search until its step is below res of a cell or `steps`
 * iterations are spent */
static void sw_compass_run(const sw_region* g, uint32_t steps, double res, sw_compass* q, sw_best* b) {
    const double lo[3] = {-1.0, -1.0, g->lz0}, hi[3] = {1.0, 1.0, g->lz1};
    const int axes = g->flat < 0 ? 3 : 2;
    for (; q->it < steps && q->best < INFINITY && q->h[0] >= res * q->h0; ++q->it) {
        double next[3] = {q->c[0], q->c[1], q->c[2]};
        int moved = 0, move_axis = -1, move_sgn = 0, move_clamped = 0;
        for (int axis = 0; axis < axes; ++axis)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                if (axis == q->back_axis && sgn == q->back_sgn) continue;
                double u[3] = {q->c[0], q->c[1], q->c[2]};
                const double t = q->c[axis] + sgn * q->h[axis];
                u[axis] = sw_clampd(t, lo[axis], hi[axis]);
                if (u[axis] == q->c[axis]) continue; /* clamped onto the centre: the same point */
                const double v = sw_sample(g, u, b);
                if (v > q->best) {
                    q->best = v, next[0] = u[0], next[1] = u[1], next[2] = u[2], moved = 1;
                    move_axis = axis, move_sgn = sgn, move_clamped = u[axis] != t;
                }
            }
        /* a clamped move's way back is shorter than the step: sampled again */
        q->back_axis = moved && !move_clamped ? move_axis : -1;
        q->back_sgn = -move_sgn;
        if (moved) q->c[0] = next[0], q->c[1] = next[1], q->c[2] = next[2];
        else q->h[0] *= 0.5, q->h[1] *= 0.5, q->h[2] *= 0.5;
    }
}

/* The searches from every seed to SW_REFINE_COARSE, then the worst (the
 * first of equals) on to SW_REFINE_RES. */
static void sw_refine_seeds(const sw_region* g, sw_compass* q, int nq, uint32_t steps, sw_best* b) {
    int worst = -1;
    for (int i = 0; i < nq; ++i) {
        sw_compass_run(g, steps, SW_REFINE_COARSE, &q[i], b);
        if (worst < 0 || q[i].best > q[worst].best) worst = i;
    }
    if (worst >= 0) sw_compass_run(g, steps, SW_REFINE_RES, &q[worst], b);
}

/* H's vertices on V's faces (the side planes at NDC +-1, the near and far
 * planes) lie there exactly; rebuilt from world coordinates their
 * (NDC, log z) carry rounding of a few ulps, which would put a vertex just
 * inside in one rounding mode and on the face in another (and the search
 * from it would sample a different set of neighbours).  Coordinates within
 * this fraction of the range of an end are that end: a move of at most
 * 1e-9 of the range, far below the sampling's stated error. */
#define SW_FACE_SNAP_REL 1e-9

static double sw_snap_clamp(double v, double lo, double hi) {
    const double tol = SW_FACE_SNAP_REL * (hi - lo);
    return v <= lo + tol ? lo : (v >= hi - tol ? hi : v);
}

/* The vertices of H: where the maximum of a projective map's error over a
 * convex region usually lies (at a corner of V cut by S); each is a
 * sample and the worst a seed.  Returns 0 when H is empty. */
static int sw_sample_vertices(const sw_region* g, const swarp_camera* cam, double z_near,
                              double z_far, double seed[3], double* seed_sigma, sw_best* b) {
    swarp_polyhedron v, h;
    if (swarp_poly_from_camera_range(cam, z_near, z_far, &v) != SWARP_OK) return 0;
    if (swarp_poly_clip_aabb(&v, &g->box, &h) != SWARP_OK) return 0;
    *seed_sigma = -1.0;
    for (uint32_t i = 0; i < h.vertex_count; ++i) {
        const swarp_vec3 d = sw_sub(h.vertices[i], g->s.eye);
        const double z = sw_dot(d, g->s.f);
        if (!(z > 0.0)) continue;
        const double u[3] = {sw_snap_clamp(sw_dot(d, g->s.r) / (z * g->t_x), -1.0, 1.0),
                             sw_snap_clamp(sw_dot(d, g->s.u) / (z * g->t_y), -1.0, 1.0),
                             sw_snap_clamp(log(z), g->lz0, g->lz1)};
        const double sigma = sw_sample(g, u, b);
        if (sigma > *seed_sigma) *seed_sigma = sigma, seed[0] = u[0], seed[1] = u[1], seed[2] = u[2];
    }
    return h.vertex_count > 0;
}

/* The near face of H (planar depth z_near) on a finer NDC lattice of
 * (n - 1) * 4 / 3 + 1 points per axis (9 x 9 at n = 7): the screen's 1/z
 * puts the largest sigma of a warped map on or near that face, where a
 * LiSPSM peak can be narrower than the solid lattice's cells; its worst
 * sample is refined as a seed of its own. */
static void sw_sample_near_face(const sw_region* g, uint32_t n, double seed[3], double* seed_sigma,
                                sw_best* b) {
    const uint32_t m = (n - 1) * 4 / 3 + 1;
    for (uint32_t iy = 0; iy < m; ++iy)
        for (uint32_t ix = 0; ix < m; ++ix) {
            const double u[3] = {-1.0 + 2.0 * ix / (m - 1), -1.0 + 2.0 * iy / (m - 1), g->lz0};
            const double v = sw_sample(g, u, b);
            if (v > *seed_sigma) *seed_sigma = v, seed[0] = u[0], seed[1] = u[1], seed[2] = u[2];
        }
}

static swarp_status sw_check_measure_max(const swarp_camera* cam, double z_near, double z_far,
                                         const swarp_light* light, const swarp_aabb* scene,
                                         const swarp_measure_options* o) {
    if (!light || !scene) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_light(light);
    if (st != SWARP_OK) return st;
    st = sw_check_box(scene);
    if (st != SWARP_OK) return st;
    if (!sw_finite(z_near) || !sw_finite(z_far)) return SWARP_ERR_NON_FINITE;
    if (!(z_near > 0.0 && z_far > z_near)) return SWARP_ERR_NEAR_FAR;
    (void)cam;
    if (o) {
        if (o->_reserved) return SWARP_ERR_RESERVED_NONZERO;
        if (o->grid == 1 || o->depths == 1) return SWARP_ERR_OUT_OF_RANGE;
    }
    return SWARP_OK;
}

/* S is taken as flat along an axis when its extent there is at most this
 * fraction of the far depth: the lattice's depths are at least 1e-3 of the
 * range apart, so a slab that thin is hit only by rounding; it is sampled
 * on its mid-plane instead, which moves a receiver by at most 5e-10 of the
 * depth range (far below the sampling's stated error). */
#define SW_FLAT_REL 1e-9

/* The flat lattice: (n - 1) * m + 1 points along each NDC axis, m the
 * largest integer with m^2 <= k but at least SW_FLAT_GRID_MUL: a flat S
 * gets on its plane at least the samples a 9-depth solid lattice would
 * spend (19^2 = 361 at n = 7 against 441), as a polygon has no depth to
 * spread the lattice over and its peaks are the solid region's peaks on
 * one plane. */
#define SW_FLAT_GRID_MUL 3u
static uint32_t sw_flat_grid(uint32_t n, uint32_t k) {
    uint32_t m = 1;
    while ((m + 1) * (m + 1) <= k) ++m;
    return (n - 1) * (m > SW_FLAT_GRID_MUL ? m : SW_FLAT_GRID_MUL) + 1;
}

static void sw_region_make(const swarp_camera* cam, double z_near, double z_far,
                           const swarp_light* light, const swarp_aabb* scene,
                           const swarp_mat4* m, const swarp_measure_res* r, sw_region* g) {
    sw_screen_make(cam, r, &g->s);
    g->t_y = tan(sw_half_fovy(cam->fovy));
    g->t_x = g->t_y * cam->aspect;
    g->lz0 = log(z_near);
    g->lz1 = log(z_far);
    g->z0 = z_near * (1.0 - SW_BOX_SLACK_REL);
    g->z1 = z_far * (1.0 + SW_BOX_SLACK_REL);
    g->flat = -1;
    g->flat_at = 0.0;
    for (int a = 2; a >= 0; --a) {
        const double lo = sw_axis(scene->min, a), hi = sw_axis(scene->max, a);
        if (hi - lo <= SW_FLAT_REL * z_far) g->flat = a, g->flat_at = 0.5 * (lo + hi);
    }
    g->box = *scene;
    g->slack = sw_box_with_slack(scene);
    g->light = *light;
    if (light->type != SWARP_LIGHT_POINT) sw_normalize(light->direction, &g->light.direction);
    g->m = m;
    g->res = *r;
}

SWARP_API swarp_status swarp_measure_max(const swarp_camera* cam, double z_near, double z_far,
                                         const swarp_light* light, const swarp_aabb* scene,
                                         const swarp_mat4* matrix, const swarp_measure_res* res,
                                         const swarp_measure_options* opts,
                                         swarp_measured_error* out) {
    swarp_measure_res r;
    swarp_status st = sw_check_measure_inputs(cam, matrix, res, &r);
    if (st != SWARP_OK) return st;
    st = sw_check_measure_max(cam, z_near, z_far, light, scene, opts);
    if (st != SWARP_OK) return st;
    if (!out) return SWARP_ERR_NULL_POINTER;
    const uint32_t n = opts && opts->grid ? opts->grid : SW_MEASURE_GRID;
    const uint32_t k = opts && opts->depths ? opts->depths : SW_MEASURE_DEPTHS;
    const uint32_t steps = opts && opts->refine ? opts->refine : SW_MEASURE_REFINE;
    sw_region g;
    sw_region_make(cam, z_near, z_far, light, scene, matrix, &r, &g);
    sw_best b;
    memset(&b, 0, sizeof b);
    double seed[3] = {0.0, 0.0, 0.0}, seed_sigma = -1.0;
    const int have_vertices = sw_sample_vertices(&g, cam, z_near, z_far, seed, &seed_sigma, &b);
    sw_seeds seeds;
    memset(&seeds, 0, sizeof seeds);
    /* a flat S: a 2-D lattice on its plane (sw_region_point) */
    const uint32_t ln = g.flat < 0 ? n : sw_flat_grid(n, k), lk = g.flat < 0 ? k : 1u;
    sw_sample_lattice(&g, ln, lk, &b, &seeds);
    double face_seed[3] = {0.0, 0.0, 0.0}, face_sigma = -1.0;
    if (g.flat < 0) sw_sample_near_face(&g, n, face_seed, &face_sigma, &b);
    if (b.acc.samples == 0) return SWARP_ERR_BODY_EMPTY;
    sw_compass q[SW_SEEDS + 2];
    int nq = 0;
    for (int i = 0; i < seeds.count; ++i) sw_compass_start(&g, ln, lk, seeds.u[i], seeds.sigma[i], &q[nq++]);
    if (face_sigma >= 0.0) sw_compass_start(&g, ln, lk, face_seed, face_sigma, &q[nq++]);
    if (have_vertices && seed_sigma >= 0.0) sw_compass_start(&g, ln, lk, seed, seed_sigma, &q[nq++]);
    sw_refine_seeds(&g, q, nq, steps, &b);
    *out = b.acc;
    return b.acc.max_sigma == INFINITY ? SWARP_INFO_MEASURE_SINGULAR : SWARP_OK;
}

/* a setup's screen and map, defaults resolved */
static void sw_measure_res_of(const swarp_setup_options* o, swarp_measure_res* r) {
    sw_setup_map_size(o, &r->map_width, &r->map_height);
    r->screen_width = o->screen_width ? o->screen_width : SW_DEFAULT_SCREEN_W;
    r->screen_height = o->screen_height ? o->screen_height : SW_DEFAULT_SCREEN_H;
}

/* The measurement the results carry: swarp_measure_max over [z_near, z_far]
 * ∩ S at the setup options' screen and map (defaults resolved), with the
 * default sampling.  A region the sampling does not reach (a sliver of H
 * thinner than the lattice and S's slack), or a matrix singular somewhere
 * in it, is reported as such rather than as an error of the setup: zero
 * samples, or max_sigma = +inf. */
void sw_measure_setup(const swarp_camera* cam, double z_near, double z_far, const swarp_light* light,
                      const swarp_aabb* scene, const swarp_mat4* matrix, const swarp_setup_options* o,
                      swarp_measured_error* out) {
    memset(out, 0, sizeof *out);
    if (o->skip_measure) return;
    swarp_measure_res r;
    sw_measure_res_of(o, &r);
    swarp_measured_error m;
    swarp_status s = swarp_measure_max(cam, z_near, z_far, light, scene, matrix, &r, NULL, &m);
    if (s == SWARP_OK || s == SWARP_INFO_MEASURE_SINGULAR) *out = m;
}

/* The cheap set of the warp search: H's vertices, its vertex centroid and
 * the midpoints between the centroid and each vertex, with their bisector
 * receivers; points behind the eye are not receivers and are left out.
 * The receivers and J_scr depend on the eye, the light and the point only,
 * never on the matrix, so they are built once for all the matrices a
 * search compares, and each matrix costs only its J_tex.  Returns the
 * number of receivers written (<= cap). */
size_t sw_measure_set_make(const swarp_camera* cam, const swarp_light* light, const swarp_setup_options* o,
                           const swarp_vec3* h, size_t nh, sw_receiver* out, size_t cap) {
    sw_region g;
    memset(&g, 0, sizeof g);
    swarp_measure_res r;
    sw_measure_res_of(o, &r);
    sw_screen_make(cam, &r, &g.s);
    g.light = *light;
    if (light->type != SWARP_LIGHT_POINT) sw_normalize(light->direction, &g.light.direction);
    swarp_vec3 ctr = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < nh; ++i) ctr = sw_add(ctr, h[i]);
    if (nh) ctr = sw_scale(ctr, 1.0 / (double)nh);
    size_t n = 0;
    for (size_t i = 0; nh && i <= nh && n < cap; ++i) {
        const swarp_vec3 cand[2] = {i < nh ? h[i] : ctr, i < nh ? sw_scale(sw_add(h[i], ctr), 0.5) : ctr};
        for (int k = 0; k < (i < nh ? 2 : 1) && n < cap; ++k) {
            const swarp_vec3 d = sw_sub(cand[k], g.s.eye);
            const double z = sw_dot(d, g.s.f);
            if (!(z > 0.0)) continue;
            out[n].x = cand[k];
            sw_receiver_screen(&g.s, d, z, sw_bisector(&g, cand[k]), &out[n]);
            ++n;
        }
    }
    return n;
}

/* max sigma of matrix over the cheap set, and their mean into *mean; +inf
 * (both) where the map is singular. */
double sw_measure_set_sigma(const swarp_mat4* matrix, const swarp_setup_options* o, const sw_receiver* rc,
                            size_t n, double* mean) {
    swarp_measure_res r;
    sw_measure_res_of(o, &r);
    double worst = 0.0, sum = 0.0;
    *mean = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        double d[2][2];
        const swarp_vec4 c = sw_xform_point(matrix, rc[i].x);
        if (!sw_receiver_d(matrix, &r, &rc[i], c, d)) return INFINITY;
        const double sigma = sw_sigma_max(d[0][0], d[0][1], d[1][0], d[1][1]);
        if (sigma > worst) worst = sigma;
        sum += sigma;
    }
    *mean = n ? sum / (double)n : 0.0;
    return worst;
}
