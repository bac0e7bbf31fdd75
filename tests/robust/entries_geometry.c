/* Hard-case / fuzz entries for the geometry stage: the one call swarp_setup
 * (and swarp_setup_range), the body B (swarp_body_points) and the box
 * polyhedron, with the edges of issue 9: light within 1e-9 rad of parallel
 * and antiparallel to the view, near = 1e-6 and far/near up to 1e7,
 * coordinates offset by 1e6, boxes of zero extent on one or more axes, the
 * camera on a box face, edge or corner, point lights on the near plane and at
 * the eye.  Properties: finite matrices, matrix = light_proj light_view, the
 * focused matrix maps every point of B into the unit cube (x, y in [-1, 1],
 * w > 0), n' > 0 (or +inf with SWARP_INFO_WARP_UNIFORM), finite predicted
 * errors, B inside the scene box. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_setup)
SWR_WEAK(swarp_setup_range)
SWR_WEAK(swarp_body_points)
SWR_WEAK(swarp_poly_from_aabb)

#define SKIP_IF_MISSING(c, f) \
    do {                      \
        if (!(f)) {           \
            (c)->skipped = 1; \
            return;           \
        }                     \
    } while (0)
#define PI_ 3.14159265358979323846

static int fin(double x) { return swr_isfin(x); }
static int fin3(const swarp_vec3* v) { return fin(v->x) && fin(v->y) && fin(v->z); }
static swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static double dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static swarp_vec3 cross(swarp_vec3 a, swarp_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static swarp_vec3 unit(swarp_vec3 a) {
    double l = sqrt(dot(a, a));
    return l > 0 ? v3(a.x / l, a.y / l, a.z / l) : a;
}
/* rotate d toward a perpendicular by angle a */
static swarp_vec3 tilt(swarp_vec3 d, double a) {
    swarp_vec3 p = fabs(d.y) < 0.9 ? v3(0, 1, 0) : v3(1, 0, 0);
    p = unit(cross(d, p));
    return v3(d.x * cos(a) + p.x * sin(a), d.y * cos(a) + p.y * sin(a), d.z * cos(a) + p.z * sin(a));
}

typedef struct scene_args {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
    swarp_setup_options opt;
    int use_opt;
    int degenerate_light; /* light exactly (anti)parallel: the fallback is decided by rounding */
    int light_at_eye;     /* point light at the eye or on the near plane */
} scene_args;

static void gen_setup_scene(swr_ctx* c, scene_args* s) {
    memset(s, 0, sizeof *s);
    double off = swr_offset(c);
    /* the scene box, sometimes flat on one to three axes */
    swarp_vec3 lo = v3(off + swr_num_in(c, -50, 0, NULL, 0), swr_num_in(c, -10, 0, NULL, 0), off + swr_num_in(c, -50, 0, NULL, 0));
    swarp_vec3 ext = v3(swr_num_in(c, 0, 100, NULL, 0), swr_num_in(c, 0, 30, NULL, 0), swr_num_in(c, 0, 100, NULL, 0));
    uint8_t flat = swr_u8(c);
    if (flat % 6 == 0) ext.y = 0;
    if (flat % 18 == 0) ext.x = 0;
    if (flat % 54 == 0) ext.z = 0;
    s->box.min = lo;
    s->box.max = v3(lo.x + ext.x, lo.y + ext.y, lo.z + ext.z);
    if (swr_one_in(c, 40)) { /* inverted */
        double t = s->box.min.x;
        s->box.min.x = s->box.max.x;
        s->box.max.x = t - 1;
    }
    /* the camera: inside, outside, on a face, an edge or a corner */
    swarp_camera* cam = &s->cam;
    uint8_t where = swr_u8(c) % 8;
    double fx = swr_num_in(c, 0, 1, NULL, 0), fy = swr_num_in(c, 0, 1, NULL, 0), fz = swr_num_in(c, 0, 1, NULL, 0);
    if (where == 1) fx = 0;                   /* face */
    if (where == 2) fx = 1, fy = 0;           /* edge */
    if (where == 3) fx = 0, fy = 1, fz = 0;   /* corner */
    cam->eye = v3(s->box.min.x + fx * ext.x, s->box.min.y + fy * ext.y, s->box.min.z + fz * ext.z);
    if (where >= 6) cam->eye.y += swr_num_in(c, 1, 200, NULL, 0); /* above the box */
    cam->dir = unit(v3(swr_num_in(c, -1, 1, NULL, 0), swr_num_in(c, -1, 0.2, NULL, 0), swr_num_in(c, -1, 1, NULL, 0)));
    if (swr_one_in(c, 2)) { /* toward the box (plus a little) */
        swarp_vec3 ctr = v3(0.5 * (s->box.min.x + s->box.max.x), 0.5 * (s->box.min.y + s->box.max.y),
                            0.5 * (s->box.min.z + s->box.max.z));
        swarp_vec3 to = v3(ctr.x - cam->eye.x, ctr.y - cam->eye.y, ctr.z - cam->eye.z);
        if (dot(to, to) > 0) cam->dir = unit(v3(to.x + swr_num_in(c, -0.2, 0.2, NULL, 0) * sqrt(dot(to, to)), to.y, to.z));
    }
    if (swr_one_in(c, 64)) cam->dir = v3(0, 0, 0);
    cam->up = swr_one_in(c, 64) ? cam->dir : v3(0, 1, 0); /* up parallel to dir: DEGENERATE */
    static const double brk_f[] = {1e-6, PI_ - 1e-6, 1.0};
    cam->fovy = swr_num_in(c, 0.1, 2.8, brk_f, 3);
    cam->aspect = swr_num_in(c, 0.3, 3, NULL, 0);
    static const double brk_n[] = {1e-6, 1.0};
    static const double brk_r[] = {1e7, 1.0 + 1e-9};
    cam->near = swr_num_in(c, 1e-6, 2, brk_n, 2);
    cam->far = cam->near * swr_num_in(c, 1.5, 1e7, brk_r, 2);
    cam->_reserved[swr_u8(c) % 4] = swr_reserved(c);
    /* the light: at an angle to the view direction, 1e-9 from (anti)parallel */
    swarp_light* L = &s->light;
    L->type = (swarp_light_type)swr_enum(c, 3);
    static const double angles[] = {0.0, 1e-9, PI_ - 1e-9, PI_, PI_ / 2};
    uint8_t ak = swr_u8(c) % 8;
    double ang = ak < 5 ? angles[ak] : swr_num_in(c, 0, PI_, NULL, 0);
    if (ak == 0 || ak == 3) s->degenerate_light = 1;
    if (ak == 1 || ak == 2) s->degenerate_light = 1;
    /* the drawn angle lands on the ends too (swr_num_in: exactly 0 or pi, or
     * within 1e-9/1e-12 of them): the same degenerate configurations.  At
     * γ = 0 / π the warp axis y is perpendicular to the view, and two
     * documented decisions take the sign of rounding noise there: which of
     * ±y the warp runs along (σ = sign(y·v), src/follow.c; a user or
     * pseudo-near n keeps a strong warp there, so the map flips by 180°)
     * and whether z_1 > z_0 (n_opt finite, ~1e16, or +inf: uniform) */
    if (fmin(ang, PI_ - ang) <= 1.000001e-9) s->degenerate_light = 1;
    L->direction = tilt(unit(cam->dir), ang);
    if (swr_one_in(c, 64)) L->direction = v3(0, 0, 0);
    if (swr_one_in(c, 3)) L->direction = v3(swr_num_in(c, -1, 1, NULL, 0), swr_num_in(c, -1, -0.1, NULL, 0), swr_num_in(c, -1, 1, NULL, 0));
    uint8_t pk = swr_u8(c) % 6;
    swarp_vec3 d = unit(cam->dir);
    if (pk == 0) L->position = cam->eye; /* at the eye */
    else if (pk == 1) L->position = v3(cam->eye.x + cam->near * d.x, cam->eye.y + cam->near * d.y, cam->eye.z + cam->near * d.z);
    else L->position = v3(cam->eye.x + swr_num_in(c, -100, 100, NULL, 0), cam->eye.y + swr_num_in(c, 1, 300, NULL, 0),
                          cam->eye.z + swr_num_in(c, -100, 100, NULL, 0));
    if (pk <= 1) s->degenerate_light = 1;
    if (pk <= 1 && L->type == SWARP_LIGHT_POINT) s->light_at_eye = 1;
    L->cone_angle = swr_one_in(c, 2) ? 0.0 : swr_num_in(c, 0.05, 1.5, NULL, 0);
    L->_reserved[swr_u8(c) % 4] = swr_reserved(c);
    /* options */
    swarp_setup_options* o = &s->opt;
    s->use_opt = !swr_one_in(c, 4);
    o->technique = (swarp_technique)swr_enum(c, 4);
    o->param = (swarp_warp_param)swr_enum(c, 6);
    o->center = (swarp_warp_center)swr_enum(c, 3);
    o->depth_range = (swarp_depth_range)swr_enum(c, 3);
    o->map_width = swr_one_in(c, 2) ? 0 : swr_u32(c) % 8193;
    o->map_height = swr_one_in(c, 2) ? 0 : swr_u32(c) % 8193;
    o->pancake = swr_u8(c) % 2;
    o->psm_slideback = swr_u8(c) % 2;
    o->n_user = swr_num_in(c, 1e-3, 1e3, NULL, 0);
    o->pseudo_near = swr_num_in(c, 0, 0.9, NULL, 0);
    o->pseudo_far = swr_num_in(c, 0, 0.9, NULL, 0);
    o->slideback = swr_one_in(c, 2) ? 0 : swr_num_in(c, 0, 10, NULL, 0);
    {
        /* min_depth took reserved words 2 and 3: the same bytes are drawn
         * (seed corpus and regressions keep their meaning), 2 and 3 dropped */
        const int k = swr_u8(c) % 4;
        const uint32_t rv = swr_reserved(c);
        if (k < 2) o->_reserved[k] = rv;
    }
    /* one field with an edge or invalid value (NaN, inf, 0, -0, huge, ...) */
    if (swr_one_in(c, 3)) {
        double* fields[] = {&cam->eye.x, &cam->dir.y, &cam->fovy, &cam->aspect, &cam->near, &cam->far,
                            &L->direction.x, &L->position.y, &L->cone_angle, &s->box.min.z, &s->box.max.y,
                            &o->n_user, &o->pseudo_near, &o->slideback};
        double* f = fields[swr_u8(c) % (sizeof fields / sizeof fields[0])];
        *f = swr_num(c, *f - 1, *f + 1, f, 1);
    }
    /* [RHS] §4.3 measured min depth (drawn last, so older inputs keep their
     * meaning): mostly not given, sometimes an edge or invalid value */
    if (swr_one_in(c, 4)) {
        static const double brk_md[] = {0.0, 1.0};
        o->min_depth = swr_num(c, 0, 100, brk_md, 2);
    }
}

/* the conditioning of the geometry: coordinates of magnitude X resolved to
 * eps X against the smallest length of the problem (near) */
static void scene_cond(swr_ctx* c, const scene_args* s, double near, double far) {
    double cmax = fmax(fmax(fabs(s->cam.eye.x), fabs(s->cam.eye.y)), fabs(s->cam.eye.z));
    cmax = fmax(cmax, fmax(fmax(fabs(s->box.min.x), fabs(s->box.min.y)), fabs(s->box.min.z)));
    cmax = fmax(cmax, fmax(fmax(fabs(s->box.max.x), fabs(s->box.max.y)), fabs(s->box.max.z)));
    if (near > 0 && swr_isfin(cmax + far)) swr_cond(c, (cmax + far) / near);
}

static void expect_scene(swr_ctx* c, const scene_args* s, int uses_cam_range) {
    const swarp_camera* cam = &s->cam;
    if (!fin3(&cam->eye) || !fin3(&cam->dir) || !fin3(&cam->up) || !fin(cam->fovy) || !fin(cam->aspect) ||
        (uses_cam_range && (!fin(cam->near) || !fin(cam->far))))
        swr_expect(c, SWARP_ERR_NON_FINITE);
    if (fin(cam->fovy) && !(cam->fovy > 0 && cam->fovy < PI_)) swr_expect(c, SWARP_ERR_FOV);
    if (fin(cam->aspect) && !(cam->aspect > 0)) swr_domain(c, SWARP_ERR_OUT_OF_RANGE), swr_domain(c, SWARP_ERR_FOV),
        swr_domain(c, SWARP_ERR_INVALID_ARGUMENT);
    if (uses_cam_range && fin(cam->near) && fin(cam->far) && !(cam->near > 0 && cam->far > cam->near))
        swr_expect(c, SWARP_ERR_NEAR_FAR);
    if (cam->dir.x == 0 && cam->dir.y == 0 && cam->dir.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    else if (fin3(&cam->dir) && fin3(&cam->up)) {
        /* scale both to a max component of 1 first: tiny vectors are valid */
        double md = fmax(fabs(cam->dir.x), fmax(fabs(cam->dir.y), fabs(cam->dir.z)));
        double mu = fmax(fabs(cam->up.x), fmax(fabs(cam->up.y), fabs(cam->up.z)));
        swarp_vec3 dn = v3(cam->dir.x / md, cam->dir.y / md, cam->dir.z / md);
        swarp_vec3 un = mu > 0 ? v3(cam->up.x / mu, cam->up.y / mu, cam->up.z / mu) : cam->up;
        swarp_vec3 cr = cross(dn, un);
        if (mu == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
        if (dot(cr, cr) <= 1e-24 * dot(dn, dn) * dot(un, un)) {
            swr_expect(c, SWARP_ERR_DEGENERATE);
            swr_domain(c, SWARP_ERR_ZERO_VECTOR);
        }
    }
    for (int i = 0; i < 4; ++i)
        if (cam->_reserved[i] || s->light._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    if (s->light._reserved0) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    int t = (int)s->light.type;
    if (t < 0 || t > 2) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    if (t == 0 || t == 1) {
        if (!fin3(&s->light.direction)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if ((s->light.direction.x == 0 && s->light.direction.y == 0 && s->light.direction.z == 0)) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    }
    if (t == 2 && !(s->light.cone_angle == 0)) { /* a spot light: direction is its axis */
        if (!fin3(&s->light.direction)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if ((s->light.direction.x == 0 && s->light.direction.y == 0 && s->light.direction.z == 0)) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    }
    if (t == 2) {
        if (!fin3(&s->light.position)) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (!fin(s->light.cone_angle)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (!(s->light.cone_angle >= 0 && s->light.cone_angle < PI_ / 2)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    if (!fin3(&s->box.min) || !fin3(&s->box.max)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (s->box.min.x > s->box.max.x || s->box.min.y > s->box.max.y || s->box.min.z > s->box.max.z)
        swr_expect(c, SWARP_ERR_BOX_INVERTED);
    if (s->use_opt) {
        const swarp_setup_options* o = &s->opt;
        if ((int)o->technique < 0 || (int)o->technique > 3 || (int)o->param < 0 || (int)o->param > 5 ||
            (int)o->center < 0 || (int)o->center > 2 || (int)o->depth_range < 0 || (int)o->depth_range > 2)
            swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        for (int i = 0; i < 2; ++i)
            if (o->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        if (isnan(o->min_depth)) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (o->min_depth < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        if (!fin(o->n_user) || !fin(o->pseudo_near) || !fin(o->pseudo_far) || !fin(o->slideback))
            swr_domain(c, SWARP_ERR_NON_FINITE);
        swr_domain(c, SWARP_ERR_OUT_OF_RANGE); /* n_user, pseudo planes, slide-back, map sizes */
    }
    /* what only the geometry can tell */
    static const swarp_status dom[] = {SWARP_ERR_BODY_EMPTY, SWARP_ERR_LIGHT_INSIDE_BODY, SWARP_ERR_BOX_DEGENERATE,
                                       SWARP_ERR_DEGENERATE};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
    if (s->degenerate_light) c->rounding_edge = 1;
    /* PSM with a directional light perpendicular to the view (γ = 90°, the
     * drawn angle pi/2): the light is at infinity in post-perspective space
     * (τ = w_l/|q_h| = 0, src/psm.c), and SWARP_INFO_PSM_INVERSE (w_l < 0,
     * the light behind the viewer) is the sign of rounding noise there.  The
     * matrices are continuous across it (orthographic rows for |τ| < 1e-9);
     * the status is a documented threshold decision. */
    if (s->use_opt && s->opt.technique == SWARP_TECHNIQUE_PSM && (t == 0 || t == 1) && fin3(&s->light.direction) &&
        fin3(&cam->dir)) {
        swarp_vec3 a = unit(cam->dir), b = unit(s->light.direction);
        if (fabs(dot(a, b)) < 1e-12) c->rounding_edge = 1;
    }
}

static swarp_vec4 xf(const swarp_mat4* m, swarp_vec3 p) {
    swarp_vec4 o;
    o.x = m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12];
    o.y = m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13];
    o.z = m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14];
    o.w = m->m[3] * p.x + m->m[7] * p.y + m->m[11] * p.z + m->m[15];
    return o;
}

static void check_setup_result(swr_ctx* c, const scene_args* s, swarp_status st, const swarp_setup_result* r,
                               const swarp_vec3* pts, size_t count, int have_pts) {
    for (int i = 0; i < 16; ++i) {
        swr_rec(c, "light_view", r->light_view.m[i]);
        swr_rec(c, "light_proj", r->light_proj.m[i]);
        swr_rec(c, "matrix", r->matrix.m[i]);
    }
    /* n_eye, n_light: "+inf uniform" (documented for the uniform technique
     * and for SWARP_INFO_WARP_UNIFORM).  Recorded as the warp strengths
     * e = (view_far - view_near)/n (0: uniform), not as n: the map depends
     * on 1/n continuously (src/warp.c: w = 1 + (y - y_min)/n, the uniform
     * map exactly at 1/n = 0), and as the view turns perpendicular to the
     * warp axis (a light (anti)parallel to the view) n_opt -> inf with
     * z_1 - z_0 -> 0: n = 5e15 and n = 1.6e16 there are both "uniform to
     * 1e-13" and give the same map, but compared as n they differ by 200 %.
     * e keeps n's relative precision where the warp is strong (e large,
     * itself the call's scale) and is compared to the map's own precision
     * where it is weak (e small against the other outputs). */
    {
        int uniform = s->use_opt && s->opt.technique == SWARP_TECHNIQUE_UNIFORM;
        const double n2[2] = {r->n_eye, r->n_light};
        for (int k = 0; k < 2; ++k) {
            double n = n2[k];
            SWR_CHECK(c, n == n && n != -INFINITY, "%s = %g", k ? "n_light" : "n_eye", n);
            SWR_CHECK(c, n != INFINITY || uniform || st == SWARP_INFO_WARP_UNIFORM,
                      "%s = +inf with %s (only SWARP_INFO_WARP_UNIFORM may give +inf)", k ? "n_light" : "n_eye",
                      swarp_status_name(st));
            double e = n == INFINITY ? 0.0 : (r->view_far - r->view_near) / n;
            if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = e;
        }
    }
    swr_rec(c, "max_mx", r->max_mx);
    swr_rec(c, "max_mz", r->max_mz);
    swr_rec(c, "view_near", r->view_near);
    swr_rec(c, "view_far", r->view_far);
    SWR_CHECK(c, r->n_eye > 0, "n_eye = %g", r->n_eye);
    SWR_CHECK(c, r->max_mx >= 0 && r->max_mz >= 0, "predicted errors %g %g", r->max_mx, r->max_mz);
    SWR_CHECK(c, r->view_near > 0 && r->view_far > r->view_near, "view range [%g, %g]", r->view_near, r->view_far);
    SWR_CHECK(c, r->point_count <= SWARP_BODY_MAX_POINTS, "point_count %u", r->point_count);
    /* matrix = light_proj light_view, normwise (the product may be formed in
     * another order: element errors relative to the matrix's scale) */
    double mscale = 0;
    for (int i = 0; i < 16; ++i) mscale = fmax(mscale, fabs(r->matrix.m[i]));
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            double acc = 0, mag = 0;
            for (int k = 0; k < 4; ++k) {
                double t = r->light_proj.m[k * 4 + row] * r->light_view.m[col * 4 + k];
                acc += t;
                mag += fabs(t);
            }
            /* tolerance: 1e-9, or 64 eps times the conditioning of the scene */
            double ptol = fmax(1e-9, 64 * DBL_EPSILON * c->cond);
            SWR_CHECK(c, fabs(acc - r->matrix.m[col * 4 + row]) <= ptol * (mag + mscale) + 1e-300,
                      "matrix[%d][%d] = %.17g, light_proj light_view = %.17g", row, col, r->matrix.m[col * 4 + row], acc);
        }
    if (!have_pts) return;
    SWR_CHECK(c, count == r->point_count, "out_count %zu, point_count %u", count, r->point_count);
    /* B lies in the scene box and the focused matrix maps it into the unit
     * cube (PSM's inverse projection maps it differently: not checked) */
    double tol_box = 1e-9 * (fabs(s->box.min.x) + fabs(s->box.max.x) + fabs(s->box.min.y) + fabs(s->box.max.y) +
                             fabs(s->box.min.z) + fabs(s->box.max.z) + 1);
    int psm = s->use_opt && s->opt.technique == SWARP_TECHNIQUE_PSM;
    /* the fit is only as good as the points are resolved: coordinates of
     * magnitude X carry ulp(X) ~ eps X, relative to B's extent that is
     * eps X / extent (1e6 offsets around a 1e-6 frustum: O(1)) */
    double ext = 0, cmax = 0;
    for (size_t i = 0; i < count && i < SWARP_BODY_MAX_POINTS; ++i) {
        ext = fmax(ext, fmax(fabs(pts[i].x - pts[0].x), fmax(fabs(pts[i].y - pts[0].y), fabs(pts[i].z - pts[0].z))));
        cmax = fmax(cmax, fmax(fabs(pts[i].x), fmax(fabs(pts[i].y), fabs(pts[i].z))));
    }
    double fit_tol = 1e-6 + (ext > 0 ? 64 * DBL_EPSILON * cmax / ext : 0);
    for (size_t i = 0; i < count && i < SWARP_BODY_MAX_POINTS; ++i) {
        const swarp_vec3* p = &pts[i];
        SWR_CHECK(c, fin3(p), "point %zu not finite", i);
        SWR_CHECK_ACC(c, p->x >= s->box.min.x - tol_box && p->x <= s->box.max.x + tol_box && p->y >= s->box.min.y - tol_box &&
                             p->y <= s->box.max.y + tol_box && p->z >= s->box.min.z - tol_box && p->z <= s->box.max.z + tol_box,
                      "point %zu of B (%g %g %g) outside the scene box", i, p->x, p->y, p->z);
        if (psm || st == SWARP_INFO_PSM_INVERSE) continue;
        swarp_vec4 q = xf(&r->matrix, *p);
        /* A spot light on or inside B: the points nearer to it than its near
         * plane (distance along its axis below light_near) are left out of
         * the map, as SWARP_INFO_LIGHT_NEAR_CLIPPED documents (the status
         * may be hidden by the more important SWARP_INFO_WARP_UNIFORM). */
        if (s->light.type == SWARP_LIGHT_POINT && (st == SWARP_INFO_LIGHT_NEAR_CLIPPED || st == SWARP_INFO_WARP_UNIFORM)) {
            swarp_vec4 lv = xf(&r->light_view, *p);
            double lmag = fabs(r->light_view.m[2] * p->x) + fabs(r->light_view.m[6] * p->y) +
                          fabs(r->light_view.m[10] * p->z) + fabs(r->light_view.m[14]);
            if (-lv.z < r->light_near + 64 * DBL_EPSILON * lmag) continue;
        }
        if (!(q.w > 0)) {
            /* KNOWN (docs/quality.md): a point light on the boundary of B (at
             * the eye, on the near plane, on a face of a flat box) */
            swr_known(c, "focus: point %zu of B has w = %g (point light %s)", i, q.w,
                      s->light_at_eye ? "at the eye / near plane" : "on B's boundary");
            return;
        }
        double x = q.x / q.w, y = q.y / q.w, tol = fit_tol;
        /* The matrix is a world-space double matrix: each of its elements
         * is rounded (relative eps) and evaluating it at p rounds again, so
         * even an exact result maps p with an error up to eps times the
         * sizes of the terms summed (large offsets times a strongly
         * stretched map of a tiny body), whatever the library does.
         * The tolerance is that condition number (64 eps of it). */
        {
            const swarp_mat4* m = &r->matrix;
            double sw = fabs(m->m[3] * p->x) + fabs(m->m[7] * p->y) + fabs(m->m[11] * p->z) + fabs(m->m[15]);
            double sx = fabs(m->m[0] * p->x) + fabs(m->m[4] * p->y) + fabs(m->m[8] * p->z) + fabs(m->m[12]);
            double sy = fabs(m->m[1] * p->x) + fabs(m->m[5] * p->y) + fabs(m->m[9] * p->z) + fabs(m->m[13]);
            double aw = fabs(q.w);
            double kx = (sx + fabs(x) * sw) / aw, ky = (sy + fabs(y) * sw) / aw;
            tol = fmax(tol, 1e-6 + 64 * DBL_EPSILON * fmax(kx, ky));
        }
        if (!(fabs(x) <= 1 + tol && fabs(y) <= 1 + tol)) {
            /* KNOWN (docs/quality.md, reported to the geometry stage): met at
             * 1e5..1e6 offsets, lights (anti)parallel to the view, lights with
             * a ~1e-17 component (grazing), near ~ far and 1e-15 frusta */
            swr_known(c, "focus: point %zu of B maps to (%g, %g), outside [-1, 1]^2 (offset %g%s)", i, x, y, cmax,
                      s->degenerate_light ? ", light (anti)parallel" : "");
            return;
        }
    }
}

static void e_setup_common(swr_ctx* c, int range) {
    scene_args s;
    gen_setup_scene(c, &s);
    double near = s.cam.near, far = s.cam.far;
    if (range) {
        near = s.cam.near * swr_num(c, 1, 10, NULL, 0);
        far = swr_one_in(c, 16) ? near : near * swr_num(c, 1.01, 1e4, NULL, 0);
    }
    size_t cap = swr_one_in(c, 10) ? swr_u8(c) % 16 : SWARP_BODY_MAX_POINTS;
    int n_cam = swr_null(c), n_l = swr_null(c), n_b = swr_null(c), n_o = swr_null(c);
    int n_pts = swr_one_in(c, 4), n_cnt = swr_one_in(c, 4);
    if (n_cam || n_l || n_b || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_scene(c, &s, !range);
    if (range) {
        if (!fin(near) || !fin(far)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (!(near > 0 && far > near)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    }
    if (!n_pts) swr_domain(c, SWARP_ERR_CAPACITY);
    scene_cond(c, &s, near, far);
    swr_args(c, "eye=(%.17g %.17g %.17g) dir=(%g %g %g) near=%g far=%g light %d dir=(%g %g %g) pos=(%.9g %.9g %.9g) cone %g box=(%g %g %g)-(%g %g %g) tech %d",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, near, far, (int)s.light.type,
             s.light.direction.x, s.light.direction.y, s.light.direction.z, s.light.position.x, s.light.position.y,
             s.light.position.z, s.light.cone_angle, s.box.min.x, s.box.min.y, s.box.min.z,
             s.box.max.x, s.box.max.y, s.box.max.z, s.use_opt ? (int)s.opt.technique : -1);
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t count;
    swr_fill(&r, sizeof r);
    swr_fill(pts, sizeof pts);
    swr_fill(&count, sizeof count);
    swarp_status st;
    if (range)
        st = SWR_CALL(c, swarp_setup_range(n_cam ? NULL : &s.cam, n_l ? NULL : &s.light, n_b ? NULL : &s.box, near, far,
                                          s.use_opt ? &s.opt : NULL, n_o ? NULL : &r, n_pts ? NULL : pts, cap,
                                          n_cnt ? NULL : &count));
    else
        st = SWR_CALL(c, swarp_setup(n_cam ? NULL : &s.cam, n_l ? NULL : &s.light, n_b ? NULL : &s.box,
                                    s.use_opt ? &s.opt : NULL, n_o ? NULL : &r, n_pts ? NULL : pts, cap,
                                    n_cnt ? NULL : &count));
    if (st == SWARP_ERR_CAPACITY) { /* the needed count may be written */
        SWR_CHECK(c, swr_untouched(pts, sizeof pts) && swr_untouched(&r, sizeof r), "CAPACITY but outputs written");
        if (!n_cnt) SWR_CHECK(c, count > cap && count <= SWARP_BODY_MAX_POINTS, "CAPACITY with needed %zu, capacity %zu", count, cap);
        swr_fill(&count, sizeof count);
    }
    if (swarp_status_is_error(st) && st != SWARP_ERR_CAPACITY && !n_cnt && !swr_untouched(&count, sizeof count)) {
        /* KNOWN (docs/quality.md): *out_count written with an error */
        swr_known(c, "%s wrote *out_count = %zu with %s", range ? "swarp_setup_range" : "swarp_setup", count,
                  swarp_status_name(st));
        swr_fill(&count, sizeof count);
    }
    if (!swr_verdict(c, st, 3, (void*)&r, sizeof r, (void*)pts, sizeof pts, (void*)&count, sizeof count)) return;
    if (st == SWARP_INFO_WARP_UNIFORM) SWR_CHECK(c, r.n_eye == INFINITY || r.n_eye > 0, "uniform with n_eye %g", r.n_eye);
    check_setup_result(c, &s, st, &r, pts, n_cnt ? r.point_count : count, !n_pts);
    if (!n_pts) SWR_CHECK(c, swr_untouched(pts + r.point_count, sizeof pts - r.point_count * sizeof pts[0]),
                          "wrote past point_count");
}
static void e_setup(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_setup);
    e_setup_common(c, 0);
}
static void e_setup_range(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_setup_range);
    e_setup_common(c, 1);
}

/* B is a point SET: the order in which the clipper emits the vertices and
 * whether two vertices 1e-12 apart are merged into one (poly.c) follow from
 * comparisons of rounded values, so another rounding mode may list the same
 * body in another order or with one near-duplicate more or less.  Comparing
 * the points index by index (as this entry did) then reports a permutation
 * as a difference of the size of B.  What is recorded instead is B's support
 * function h(u) = max_i u.p_i in 26 fixed directions (the axes, the face and
 * the corner diagonals): it does not depend on the order or on duplicates,
 * and |h_A(u) - h_B(u)| <= d_H(A, B) for unit u, so equal records within the
 * fenv tolerance mean the hulls agree to that Hausdorff distance in these
 * directions (and bit-identical points give bit-identical records: the
 * threads test keeps its meaning).  The count is not recorded (a merged
 * near-duplicate changes it without changing the body). */
static void rec_point_set(swr_ctx* c, const swarp_vec3* pts, size_t n) {
    for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
            for (int d = -1; d <= 1; ++d) {
                if (!a && !b && !d) continue;
                double inv = 1.0 / sqrt((double)(a * a + b * b + d * d));
                double h = -INFINITY;
                for (size_t i = 0; i < n; ++i) h = fmax(h, (a * pts[i].x + b * pts[i].y + d * pts[i].z) * inv);
                if (n) swr_rec(c, "h_B(u)", h);
            }
}

static void e_body_points(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_body_points);
    scene_args s;
    gen_setup_scene(c, &s);
    s.use_opt = 0;
    size_t cap = swr_one_in(c, 10) ? swr_u8(c) % 16 : SWARP_BODY_MAX_POINTS;
    int n_cam = swr_null(c), n_l = swr_null(c), n_b = swr_null(c), n_o = swr_null(c), n_cnt = swr_null(c);
    if (n_cam || n_l || n_b || (n_o && cap > 0) || n_cnt) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_o && cap == 0) swr_domain(c, SWARP_ERR_NULL_POINTER), swr_domain(c, SWARP_ERR_CAPACITY);
    expect_scene(c, &s, 0);
    double near = s.cam.near, far = s.cam.far;
    if (!fin(near) || !fin(far)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (!(near > 0 && far > near)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    swr_domain(c, SWARP_ERR_CAPACITY);
    scene_cond(c, &s, near, far);
    swr_args(c, "eye=(%.17g %.17g %.17g) dir=(%g %g %g) near=%g far=%g light %d dir=(%g %g %g) pos=(%.9g %.9g %.9g) cone %g box=(%g %g %g)-(%g %g %g)",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, near, far, (int)s.light.type,
             s.light.direction.x, s.light.direction.y, s.light.direction.z, s.light.position.x, s.light.position.y,
             s.light.position.z, s.light.cone_angle, s.box.min.x, s.box.min.y, s.box.min.z, s.box.max.x, s.box.max.y, s.box.max.z);
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t count;
    swr_fill(pts, sizeof pts);
    swr_fill(&count, sizeof count);
    swarp_status st = SWR_CALL(c, swarp_body_points(n_cam ? NULL : &s.cam, near, far, n_l ? NULL : &s.light,
                                                   n_b ? NULL : &s.box, n_o ? NULL : pts, cap, n_cnt ? NULL : &count));
    /* How many vertices B has is decided by rounding when two of them are
     * within the 1e-12 merge distance or a vertex lies on a clip plane (see
     * rec_point_set), so a capacity within 2 of the count may give OK in one
     * rounding mode and CAPACITY in another: a threshold decision. */
    if (!n_cnt && (st == SWARP_ERR_CAPACITY || !swarp_status_is_error(st)) && count + 2 >= cap && count <= cap + 2 &&
        cap < SWARP_BODY_MAX_POINTS)
        c->rounding_edge = 1;
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, swr_untouched(pts, sizeof pts), "CAPACITY but points written");
        if (!n_cnt) SWR_CHECK(c, count > cap && count <= SWARP_BODY_MAX_POINTS, "needed %zu, capacity %zu", count, cap);
        swr_fill(&count, sizeof count);
    }
    if (!swr_verdict(c, st, 2, (void*)pts, sizeof pts, (void*)&count, sizeof count)) return;
    SWR_CHECK(c, count <= cap && count <= SWARP_BODY_MAX_POINTS, "count %zu", count);
    double tol = 1e-9 * (fabs(s.box.min.x) + fabs(s.box.max.x) + fabs(s.box.min.y) + fabs(s.box.max.y) +
                         fabs(s.box.min.z) + fabs(s.box.max.z) + 1);
    rec_point_set(c, pts, count < SWARP_BODY_MAX_POINTS ? count : SWARP_BODY_MAX_POINTS);
    for (size_t i = 0; i < count && i < SWARP_BODY_MAX_POINTS; ++i) {
        SWR_CHECK_ACC(c, pts[i].x >= s.box.min.x - tol && pts[i].x <= s.box.max.x + tol && pts[i].y >= s.box.min.y - tol &&
                             pts[i].y <= s.box.max.y + tol && pts[i].z >= s.box.min.z - tol && pts[i].z <= s.box.max.z + tol,
                      "point %zu of B outside the scene box", i);
    }
    SWR_CHECK(c, swr_untouched(pts + count, sizeof pts - count * sizeof pts[0]), "wrote past count");
}

static void e_poly_from_aabb(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_poly_from_aabb);
    scene_args s;
    gen_setup_scene(c, &s);
    int n_b = swr_null(c), n_o = swr_null(c);
    if (n_b || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!fin3(&s.box.min) || !fin3(&s.box.max)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (s.box.min.x > s.box.max.x || s.box.min.y > s.box.max.y || s.box.min.z > s.box.max.z)
        swr_expect(c, SWARP_ERR_BOX_INVERTED);
    swr_domain(c, SWARP_ERR_BOX_DEGENERATE);
    swarp_polyhedron P; /* about 7 KiB, on the stack: entries must be reentrant (threads test) */
    swarp_polyhedron* out = &P;
    swr_fill(out, sizeof *out);
    swarp_status st = SWR_CALL(c, swarp_poly_from_aabb(n_b ? NULL : &s.box, n_o ? NULL : out));
    if (!swr_verdict(c, st, 1, (void*)out, sizeof *out)) return;
    SWR_CHECK(c, out->vertex_count <= 8 && out->face_count <= 6, "%u vertices, %u faces", out->vertex_count, out->face_count);
    for (uint32_t i = 0; i < out->vertex_count && i < 8; ++i) {
        const swarp_vec3* p = &out->vertices[i];
        swr_rec(c, "v.x", p->x);
        swr_rec(c, "v.y", p->y);
        swr_rec(c, "v.z", p->z);
        SWR_CHECK(c, (p->x == s.box.min.x || p->x == s.box.max.x) && (p->y == s.box.min.y || p->y == s.box.max.y) &&
                         (p->z == s.box.min.z || p->z == s.box.max.z),
                  "vertex %u is not a corner of the box", i);
    }
}

const swr_entry swr_entries_geometry[] = {
    {"swarp_setup", "geometry", e_setup},
    {"swarp_setup_range", "geometry", e_setup_range},
    {"swarp_body_points", "geometry", e_body_points},
    {"swarp_poly_from_aabb", "geometry", e_poly_from_aabb},
    {NULL, NULL, NULL},
};
