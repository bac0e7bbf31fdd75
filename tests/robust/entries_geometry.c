/* Hard-case / fuzz entries for the geometry stage: the one call swarp_setup
 * (and swarp_setup_range), the body B (swarp_body_points) and the box
 * polyhedron, with the hard edges: light within 1e-9 rad of parallel
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
    if (!(l < INFINITY) || l < 1e-150) { /* a direction of 1e308 or 1e-300 is valid: the square
                                                        overflowed to inf (mid = eye: a false finding) */
        double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
        if (m > 0 && m < INFINITY) a = v3(a.x / m, a.y / m, a.z / m), l = sqrt(dot(a, a));
    }
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
    cam->z_near = swr_num_in(c, 1e-6, 2, brk_n, 2);
    cam->z_far = cam->z_near * swr_num_in(c, 1.5, 1e7, brk_r, 2);
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
     * ±y the warp runs along (σ = sign(y·v), src/geometry/follow.c; a user or
     * pseudo-near n keeps a strong warp there, so the map flips by 180°)
     * and whether z_1 > z_0 (n_opt finite, ~1e16, or +inf: uniform) */
    if (fmin(ang, PI_ - ang) <= 1.000001e-9) s->degenerate_light = 1;
    L->direction = tilt(unit(cam->dir), ang);
    if (swr_one_in(c, 64)) L->direction = v3(0, 0, 0);
    if (swr_one_in(c, 3)) L->direction = v3(swr_num_in(c, -1, 1, NULL, 0), swr_num_in(c, -1, -0.1, NULL, 0), swr_num_in(c, -1, 1, NULL, 0));
    uint8_t pk = swr_u8(c) % 6;
    swarp_vec3 d = unit(cam->dir);
    if (pk == 0) L->position = cam->eye; /* at the eye */
    else if (pk == 1) L->position = v3(cam->eye.x + cam->z_near * d.x, cam->eye.y + cam->z_near * d.y, cam->eye.z + cam->z_near * d.z);
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
        /* the words after min_depth: skip_measure (0 or 1) and the last
         * reserved word; the same bytes are drawn as when both were
         * reserved, so the seed corpus keeps its inputs */
        const int k = swr_u8(c) % 4;
        const uint32_t rv = swr_reserved(c);
        if (k == 0) o->skip_measure = rv;
        if (k == 1) o->_reserved[0] = rv;
    }
    /* one field with an edge or invalid value (NaN, inf, 0, -0, huge, ...) */
    if (swr_one_in(c, 3)) {
        double* fields[] = {&cam->eye.x, &cam->dir.y, &cam->fovy, &cam->aspect, &cam->z_near, &cam->z_far,
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
    /* A point light at l: the map is the light's view of B, the angle of
     * p - l about the axis, and B spans ext(B)/|p - l| rad of it.  The
     * coordinates of l carry their rounding, eps |l| (camera-relative:
     * l - eye rounds by that much, and so do the look-at rows' dot products
     * with l), which turns p - l by eps |l| / |p - l| rad: eps |l| / ext(B)
     * of the map's span.  The condition is |l| / ext(B) >= |l| / ext(box)
     * (B lies in the box; the box's extent gives the lower bound, never a
     * loosening beyond the true condition).  A point light 3.4e68 from a
     * 44-unit box: condition 8e66;
     * in the directed modes a point of B got the light-view coordinate
     * y = -5e38, so src/geometry/setup.c's resolution test (sw_world_resolves)
     * refused the map, SWARP_ERR_DEGENERATE; WARP_UNIFORM to nearest. */
    if (s->light.type == SWARP_LIGHT_POINT && fin3(&s->light.position)) {
        const swarp_vec3 lp = s->light.position;
        double lmag = fmax(fabs(lp.x), fmax(fabs(lp.y), fabs(lp.z)));
        double ext = fmax(s->box.max.x - s->box.min.x, fmax(s->box.max.y - s->box.min.y, s->box.max.z - s->box.min.z));
        if (ext > 0 && swr_isfin(ext) && lmag > 0) swr_cond(c, lmag / ext);
    }
}

/* what the arguments call for; `parts` says which ones the function reads */
#define X_CAM 1
#define X_LIGHT 2
#define X_BOX 4
#define X_OPT 8
#define X_GEOM 16 /* the statuses only the geometry can tell */
#define X_ALL 31
static void expect_parts(swr_ctx* c, const scene_args* s, int uses_cam_range, int parts) {
    const swarp_camera* cam = &s->cam;
    if (parts & X_CAM) {
    if (!fin3(&cam->eye) || !fin3(&cam->dir) || !fin3(&cam->up) || !fin(cam->fovy) || !fin(cam->aspect) ||
        (uses_cam_range && (!fin(cam->z_near) || !fin(cam->z_far))))
        swr_expect(c, SWARP_ERR_NON_FINITE);
    if (fin(cam->fovy) && !(cam->fovy > 0 && cam->fovy < PI_)) swr_expect(c, SWARP_ERR_FOV);
    if (fin(cam->aspect) && !(cam->aspect > 0)) swr_domain(c, SWARP_ERR_OUT_OF_RANGE), swr_domain(c, SWARP_ERR_FOV),
        swr_domain(c, SWARP_ERR_INVALID_ARGUMENT);
    if (uses_cam_range && fin(cam->z_near) && fin(cam->z_far) && !(cam->z_near > 0 && cam->z_far > cam->z_near))
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
        /* sin(angle(dir, up)) on the documented 1e-9 bound (dir drawn 1e-9
         * from up): DEGENERATE or not is decided by rounding */
        if (mu > 0 && fabs(sqrt(dot(cr, cr) / (dot(dn, dn) * dot(un, un))) / 1e-9 - 1) < 1e-9) c->rounding_edge = 1;
    }
    for (int i = 0; i < 4; ++i)
        if (cam->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    }
    if (parts & X_LIGHT) {
    for (int i = 0; i < 4; ++i)
        if (s->light._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
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
    }
    if (parts & X_BOX) {
    if (!fin3(&s->box.min) || !fin3(&s->box.max)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (s->box.min.x > s->box.max.x || s->box.min.y > s->box.max.y || s->box.min.z > s->box.max.z)
        swr_expect(c, SWARP_ERR_BOX_INVERTED);
    }
    if ((parts & X_OPT) && s->use_opt) {
        const swarp_setup_options* o = &s->opt;
        if ((int)o->technique < 0 || (int)o->technique > 3 || (int)o->param < 0 || (int)o->param > 6 ||
            (int)o->center < 0 || (int)o->center > 2 || (int)o->depth_range < 0 || (int)o->depth_range > 3)
            swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        if (o->_reserved[0]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        if (o->skip_measure > 1) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        if (isnan(o->min_depth)) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (o->min_depth < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        if (!fin(o->n_user) || !fin(o->pseudo_near) || !fin(o->pseudo_far) || !fin(o->slideback))
            swr_domain(c, SWARP_ERR_NON_FINITE);
        swr_domain(c, SWARP_ERR_OUT_OF_RANGE); /* n_user, pseudo planes, slide-back, map sizes */
    }
    if (!(parts & X_GEOM)) return;
    /* what only the geometry can tell */
    static const swarp_status dom[] = {SWARP_ERR_BODY_EMPTY, SWARP_ERR_LIGHT_INSIDE_BODY, SWARP_ERR_BOX_DEGENERATE,
                                       SWARP_ERR_DEGENERATE};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
    if (s->degenerate_light) c->rounding_edge = 1;
    /* PSM with a directional light perpendicular to the view (γ = 90°, the
     * drawn angle pi/2): the light is at infinity in post-perspective space
     * (τ = w_l/|q_h| = 0, src/geometry/psm.c), and SWARP_INFO_PSM_INVERSE (w_l < 0,
     * the light behind the viewer) is the sign of rounding noise there.  The
     * matrices are continuous across it (orthographic rows for |τ| < 1e-9);
     * the status is a documented threshold decision. */
    if (s->use_opt && s->opt.technique == SWARP_TECHNIQUE_PSM && ((int)s->light.type == 0 || (int)s->light.type == 1) &&
        fin3(&s->light.direction) && fin3(&s->cam.dir)) {
        swarp_vec3 a = unit(s->cam.dir), b = unit(s->light.direction);
        if (fabs(dot(a, b)) < 1e-12) c->rounding_edge = 1;
    }
}

static void expect_scene(swr_ctx* c, const scene_args* s, int uses_cam_range) {
    expect_parts(c, s, uses_cam_range, X_ALL);
}

static swarp_vec4 xf(const swarp_mat4* m, swarp_vec3 p) {
    swarp_vec4 o;
    o.x = m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12];
    o.y = m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13];
    o.z = m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14];
    o.w = m->m[3] * p.x + m->m[7] * p.y + m->m[11] * p.z + m->m[15];
    return o;
}

/* A point of B the focused matrix does not map into the unit square: PSM
 * (its inverse projection maps B differently) and, for a spot light on or
 * inside B, the points nearer to it than its near plane (distance along its
 * axis below light_near), left out of the map as
 * SWARP_INFO_LIGHT_NEAR_CLIPPED documents (the status may be hidden by the
 * more important SWARP_INFO_WARP_UNIFORM). */
static int setup_point_unmapped(const scene_args* s, swarp_status st, const swarp_setup_result* r, const swarp_vec3* p) {
    if ((s->use_opt && s->opt.technique == SWARP_TECHNIQUE_PSM) || st == SWARP_INFO_PSM_INVERSE) return 1;
    if (s->light.type == SWARP_LIGHT_POINT && (st == SWARP_INFO_LIGHT_NEAR_CLIPPED || st == SWARP_INFO_WARP_UNIFORM)) {
        swarp_vec4 lv = xf(&r->light_view, *p);
        double lmag = fabs(r->light_view.m[2] * p->x) + fabs(r->light_view.m[6] * p->y) + fabs(r->light_view.m[10] * p->z) +
                      fabs(r->light_view.m[14]);
        if (-lv.z < r->light_near + 64 * DBL_EPSILON * lmag) return 1;
    }
    return 0;
}

/* How well the focused matrix m resolves p: for each output coordinate
 * u_k = q_k/w, the sizes of the terms summed (sum_j |m_kj p_j| + |m_k3|,
 * and |u_k| times those of w) over |w|.  The outputs are within [-1, 1] on
 * B, so this is the condition number of u_k: a relative rounding eps of the
 * matrix or of p moves u_k by eps k[k]. */
static void setup_point_k(const swarp_mat4* m, const swarp_vec3* p, double k[3]) {
    swarp_vec4 q = xf(m, *p);
    const double qk[3] = {q.x, q.y, q.z};
    double sw = fabs(m->m[3] * p->x) + fabs(m->m[7] * p->y) + fabs(m->m[11] * p->z) + fabs(m->m[15]);
    for (int r = 0; r < 3; ++r) {
        double sr = fabs(m->m[r] * p->x) + fabs(m->m[4 + r] * p->y) + fabs(m->m[8 + r] * p->z) + fabs(m->m[12 + r]);
        k[r] = (sr + fabs(qk[r] / q.w) * sw) / fabs(q.w);
    }
}

/* The light view's rotation rows are unit vectors: their entries carry an
 * absolute rounding of a few eps however small they are, so a light-space
 * coordinate l_j = r_j·(p - o) (o the view's origin) moves by eps |p - o|,
 * and the map coordinate u_k = X_k/W (rows of light_proj at l) by eps
 * |p - o| sum_j |proj_kj - u_k proj_3j| / |W|: its condition number with
 * respect to the light's direction.  Large where the fit is much finer than
 * the distance from the origin: a 1e-9 slab seen edge-on 30 units away
 * (entries of 2e9 that FE_UPWARD moved by 9e-7, k = 6e10), a far point
 * light. */
static double setup_point_k_rot(const swarp_setup_result* r, const swarp_vec3* p) {
    const double* V = r->light_view.m;
    swarp_vec3 o = v3(-(V[12] * V[0] + V[13] * V[1] + V[14] * V[2]), -(V[12] * V[4] + V[13] * V[5] + V[14] * V[6]),
                      -(V[12] * V[8] + V[13] * V[9] + V[14] * V[10]));
    swarp_vec3 d = v3(p->x - o.x, p->y - o.y, p->z - o.z);
    swarp_vec4 l = xf(&r->light_view, *p), X = xf(&r->light_proj, v3(l.x, l.y, l.z));
    const double* P = r->light_proj.m;
    const double Xk[3] = {X.x, X.y, X.z};
    double k = 0;
    for (int row = 0; row < 3; ++row) {
        double u = Xk[row] / X.w, g = 0;
        for (int j = 0; j < 3; ++j) g += fabs(P[4 * j + row] - u * P[4 * j + 3]);
        k = fmax(k, sqrt(dot(d, d)) * g / fabs(X.w));
    }
    return k;
}

/* The outputs' conditioning: the fit's scale 2/E and translation come from
 * light-space coordinates of B resolved to eps times their terms (k/2 of
 * them) over its extent E, e.g. a light grazing a flat 1e6-offset box (E
 * 3e-9 against terms of 8.5: matrix entries 2e9 that the rounding mode
 * moves by 2e-6).  Depth as well as x and y: a
 * directional light 1.9e-9 off the normal of a flat box (z = -50) sees B's
 * depths within 5e-8, fitted to [-1, 1] by a translation of 1e9 that
 * FE_TOWARDZERO moved by 9e-9 (k_z 1e9).  Plus the
 * light view's rotation (setup_point_k_rot).  PSM maps only the receivers
 * and the casters in front of them: its points with w resolved from 0 and
 * inside the map count (e.g. a flat box grazed at
 * 1.7e-12 rad by camera and light).  k_rows: the rounding of the view's
 * rows in units of eps (1 for swarp_setup's frame; a followed frame's up is
 * a projection's direction, eps/s, follow_up_cond). */
static void setup_b_cond_rows(swr_ctx* c, const scene_args* s, swarp_status st, const swarp_setup_result* r, const swarp_vec3* pts,
                              size_t count, double k_rows) {
    int psm = (s->use_opt && s->opt.technique == SWARP_TECHNIQUE_PSM) || st == SWARP_INFO_PSM_INVERSE;
    const double* m = r->matrix.m;
    for (size_t i = 0; i < count && i < SWARP_BODY_MAX_POINTS; ++i) {
        const swarp_vec3* p = &pts[i];
        if (!fin3(p) || (!psm && setup_point_unmapped(s, st, r, p))) continue;
        swarp_vec4 q = xf(&r->matrix, *p);
        double sw = fabs(m[3] * p->x) + fabs(m[7] * p->y) + fabs(m[11] * p->z) + fabs(m[15]);
        if (!(q.w > 64 * DBL_EPSILON * sw)) continue;
        if (psm && !(fabs(q.x / q.w) <= 1 + 1e-6 && fabs(q.y / q.w) <= 1 + 1e-6)) continue;
        double k[3];
        setup_point_k(&r->matrix, p, k);
        swr_cond(c, fmax(fmax(k[0], fmax(k[1], k[2])), k_rows * setup_point_k_rot(r, p)));
    }
}
static void setup_b_cond(swr_ctx* c, const scene_args* s, swarp_status st, const swarp_setup_result* r, const swarp_vec3* pts,
                         size_t count) {
    setup_b_cond_rows(c, s, st, r, pts, count, 1.0);
}

/* How far outside S a point of B may lie: 1e-9 of the box's coordinates,
 * and for a point light 1e-9 of its position's, as swarp_body_from_h's
 * entry (gtol): B = conv(H ∪ {l}) ∩ S is clipped with the on-plane
 * tolerance SWARP_POLY_EPS_REL of the clipped polyhedron's scale, which is
 * |l| for a far light, so a vertex that far outside a face is on it
 * (the default mode too: a light
 * at y = 1e7, an edge of conv(H ∪ {l}) leaving S through the face
 * z = -27.01 at a slope of 5.8e-6, cut by the face y = -0.986 one unit on,
 * 5.9e-6 outside; merge distance 1e-5). */
static double b_in_box_tol(const scene_args* s) {
    double t = 1e-9 * (fabs(s->box.min.x) + fabs(s->box.max.x) + fabs(s->box.min.y) + fabs(s->box.max.y) + fabs(s->box.min.z) +
                       fabs(s->box.max.z) + 1);
    const swarp_vec3 l = s->light.position;
    if ((int)s->light.type == 2 && fin3(&l)) t = fmax(t, 1e-9 * fmax(fabs(l.x), fmax(fabs(l.y), fabs(l.z))));
    return t;
}

static void check_setup_result(swr_ctx* c, const scene_args* s, swarp_status st, const swarp_setup_result* r,
                               const swarp_vec3* pts, size_t count, int have_pts) {
    /* B of one or two points: the view frustum and the box (or the spot's
     * pyramid) only touch, in a corner or along an edge; whether they touch
     * or miss each other (SWARP_ERR_BODY_EMPTY, documented) is decided by the
     * rounding of the clips (fenv: a 1e6-world box corner at depth 5e-4,
     * empty under FE_DOWNWARD only). */
    if (r->point_count <= 2) c->rounding_edge = 1;
    for (int i = 0; i < 16; ++i) {
        swr_rec(c, "light_view", r->light_view.m[i]);
        swr_rec(c, "light_proj", r->light_proj.m[i]);
        swr_rec(c, "matrix", r->matrix.m[i]);
    }
    /* n_eye, n_light: "+inf uniform" (documented for the uniform technique
     * and for SWARP_INFO_WARP_UNIFORM).  Recorded as the warp strengths
     * e = (view_far - view_near)/n (0: uniform), not as n: the map depends
     * on 1/n continuously (src/geometry/lispsm.c: w = 1 + (y - y_min)/n, the uniform
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
            /* the statuses that bound the coverage outrank WARP_UNIFORM */
            SWR_CHECK(c, n != INFINITY || uniform || st == SWARP_INFO_WARP_UNIFORM || st == SWARP_INFO_LIGHT_NEAR_CLIPPED ||
                             st == SWARP_INFO_CASTERS_CLAMPED,
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
    /* raised after the product check above, which keeps its own tolerance;
     * without have_pts, pts is B from a call in the default environment
     * (e_setup_common), used for the conditioning only */
    setup_b_cond(c, s, st, r, pts, count);
    if (!have_pts) return;
    SWR_CHECK(c, count == r->point_count, "out_count %zu, point_count %u", count, r->point_count);
    /* B lies in the scene box and the focused matrix maps it into the unit
     * cube (PSM's inverse projection maps it differently: not checked) */
    double tol_box = b_in_box_tol(s);
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
        if (setup_point_unmapped(s, st, r, p)) continue;
        swarp_vec4 q = xf(&r->matrix, *p);
        if (!(q.w > 0)) {
            /* w > 0 on every mapped point of B, also for a point light on
             * the boundary of B (at the eye, on the near plane, on a face of
             * a flat box); the points the documentation leaves out are
             * skipped above (setup_point_unmapped) */
            swr_fail(c, "focus: point %zu of B has w = %g (point light %s)", i, q.w,
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
            double k[3];
            setup_point_k(&r->matrix, p, k);
            tol = fmax(tol, 1e-6 + 64 * DBL_EPSILON * fmax(k[0], k[1]));
        }
        if (!(fabs(x) <= 1 + tol && fabs(y) <= 1 + tol)) {
            /* the hard edges included: 1e5..1e6 offsets, lights
             * (anti)parallel to the view, grazing lights, near ~ far and
             * 1e-15 frusta, within the conditioning tolerance above */
            swr_fail(c, "focus: point %zu of B maps to (%g, %g), outside [-1, 1]^2 (offset %g%s)", i, x, y, cmax,
                      s->degenerate_light ? ", light (anti)parallel" : "");
            return;
        }
    }
}

static void setup_capacity_edge(swr_ctx* c, const scene_args* s, int range, double near, double far, size_t cap);
static void body_sweep_cut_cond(swr_ctx* c, const scene_args* s, double near, double far, const swarp_vec3* pts, size_t n);
static double vmax(swarp_vec3 v);
static double box_scale(const swarp_aabb* b);
/* A view frustum whose smallest feature (its depth far - near, the near
 * quad's sides) is within 2 merge distances of the clipper,
 * SWARP_POLY_EPS_REL of the coordinates' scale (documented: it never leaves
 * two vertices closer): its corners merge or not by rounding, and H
 * collapses to a flat polygon whose face planes are noise, so B is empty or
 * not, and its vertex count, are decided by rounding (e.g. a 6e-7 deep
 * frustum at 1e6, merge distance 1e-6; or 1.8e-7 deep at 1e5, B of 11
 * vertices to nearest, 8, 12 and 10 in the directed modes).  Computed as
 * body_points does, in world coordinates. */
static int frustum_below_merge(const scene_args* s, double near, double far) {
    if (!(fin(near) && fin(far) && far > near && fin(s->cam.fovy) && fin(s->cam.aspect) && s->cam.aspect > 0)) return 0;
    double ty = tan(0.5 * s->cam.fovy), sep = fmin(far - near, 2 * near * ty * fmin(s->cam.aspect, 1.0));
    double X = fmax(fmax(vmax(s->cam.eye), box_scale(&s->box)), vmax(s->cam.eye) + far * ty * fmax(1.0, s->cam.aspect));
    return isfinite(X) && sep <= 2 * SWARP_POLY_EPS_REL * X;
}
static void e_setup_common(swr_ctx* c, int range) {
    scene_args s;
    gen_setup_scene(c, &s);
    double near = s.cam.z_near, far = s.cam.z_far;
    if (range) {
        near = s.cam.z_near * swr_num(c, 1, 10, NULL, 0);
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
    if (!n_pts && cap < SWARP_BODY_MAX_POINTS && (st == SWARP_ERR_CAPACITY || !swarp_status_is_error(st))) {
        setup_capacity_edge(c, &s, range, near, far, cap);
        if (frustum_below_merge(&s, near, far)) c->rounding_edge = 1; /* B's count is the merges' */
    }
    if (st == SWARP_ERR_CAPACITY) { /* the needed count may be written */
        SWR_CHECK(c, swr_untouched(pts, sizeof pts) && swr_untouched(&r, sizeof r), "CAPACITY but outputs written");
        if (!n_cnt) SWR_CHECK(c, count > cap && count <= SWARP_BODY_MAX_POINTS, "CAPACITY with needed %zu, capacity %zu", count, cap);
        swr_fill(&count, sizeof count);
    }
    if (!swr_verdict(c, st, 3, (void*)&r, sizeof r, (void*)pts, sizeof pts, (void*)&count, sizeof count)) return;
    if (st == SWARP_INFO_WARP_UNIFORM) SWR_CHECK(c, r.n_eye == INFINITY || r.n_eye > 0, "uniform with n_eye %g", r.n_eye);
    size_t n_body = n_cnt ? r.point_count : count;
    if (n_pts) { /* B for the conditioning: the same call in the default environment */
        swarp_setup_result r2;
        n_body = 0;
        if (range)
            (void)swarp_setup_range(&s.cam, &s.light, &s.box, near, far, s.use_opt ? &s.opt : NULL, &r2, pts, SWARP_BODY_MAX_POINTS, &n_body);
        else
            (void)swarp_setup(&s.cam, &s.light, &s.box, s.use_opt ? &s.opt : NULL, &r2, pts, SWARP_BODY_MAX_POINTS, &n_body);
    }
    check_setup_result(c, &s, st, &r, pts, n_body, !n_pts);
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
                /* long double: for points near DBL_MAX the sum of three terms overflows
                   a double (h = inf of finite points); a record beyond DBL_MAX is kept as h/4
                   (a power of two: the same comparison) */
                long double h = -INFINITY;
                for (size_t i = 0; i < n; ++i)
                    h = fmaxl(h, ((long double)a * pts[i].x + (long double)b * pts[i].y + (long double)d * pts[i].z) * inv);
                if (fabsl(h) > DBL_MAX) h *= 0.25L;
                if (n) swr_rec(c, "h_B(u)", (double)h);
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
    double near = s.cam.z_near, far = s.cam.z_far;
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
    /* a frustum below the clipper's merge distance: B empty or not by rounding */
    if (frustum_below_merge(&s, near, far)) c->rounding_edge = 1;
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
    double tol = b_in_box_tol(&s);
    rec_point_set(c, pts, count < SWARP_BODY_MAX_POINTS ? count : SWARP_BODY_MAX_POINTS);
    body_sweep_cut_cond(c, &s, near, far, pts, count < SWARP_BODY_MAX_POINTS ? count : SWARP_BODY_MAX_POINTS);
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

/* ------------------------------------------------------------------------ */
/* polyhedra, the bodies H and B, focusing, the LiSPSM warp, setup_points   */
/* (the remaining geometry entry points, in the table-driven shape of swr.h) */
/* ------------------------------------------------------------------------ */
SWR_WEAK(swarp_poly_from_camera_range)
SWR_WEAK(swarp_poly_from_camera)
SWR_WEAK(swarp_poly_from_inverse_matrix)
SWR_WEAK(swarp_poly_clip)
SWR_WEAK(swarp_poly_clip_aabb)
SWR_WEAK(swarp_body_h)
SWR_WEAK(swarp_body_from_h)
SWR_WEAK(swarp_body_receivers)
SWR_WEAK(swarp_body_adjusted_range)
SWR_WEAK(swarp_focus_light_view)
SWR_WEAK(swarp_focus_fit)
SWR_WEAK(swarp_warp_lispsm)
SWR_WEAK(swarp_setup_points)

static double plane_at(const swarp_plane* p, swarp_vec3 v) { return p->a * v.x + p->b * v.y + p->c * v.z + p->d; }
static double vmax(swarp_vec3 v) { return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z))); }
static double poly_scale(const swarp_polyhedron* P) {
    double s = 0;
    for (uint32_t i = 0; i < P->vertex_count && i < SWARP_POLY_MAX_VERTICES; ++i) s = fmax(s, vmax(P->vertices[i]));
    return s;
}
static double box_scale(const swarp_aabb* b) { return fmax(vmax(b->min), vmax(b->max)); }
/* tolerance of a geometric predicate on coordinates of magnitude s:
 * 1e-9 relative (the library merges vertices closer than 1e-12 s) */
static double gtol(double s) { return 1e-9 * s + 1e-300; }
/* a frustum 1e6 times wider than high (valid: aspect > 0) reaches
 * coordinates far tan(fovy/2) aspect: its clips sit on thresholds that the
 * rounding decides, so the fenv test leaves it out (rounding_edge).  H, B
 * and the receivers stay inside S because body_h builds such an H as S
 * clipped by V's planes, at S's scale. */
static int wide(const swarp_camera* cam) { return cam->aspect >= 1e6 || cam->aspect <= 1e-6; }

/* A valid polyhedron (header: counts within the maxima, face indices valid,
 * outward unit normals, every vertex on the inner side of every face plane,
 * each face's vertices on its plane); records up to 32 vertices. */
static void check_poly(swr_ctx* c, const swarp_polyhedron* P, const char* what, double tol) {
    SWR_CHECK(c, P->vertex_count <= SWARP_POLY_MAX_VERTICES && P->face_count <= SWARP_POLY_MAX_FACES,
              "%s: %u vertices, %u faces", what, P->vertex_count, P->face_count);
    if (P->vertex_count > SWARP_POLY_MAX_VERTICES || P->face_count > SWARP_POLY_MAX_FACES) return;
    /* recorded: what does not depend on the order of the vertices (a SET; the
     * order may change with the rounding) nor on near-duplicates: the
     * support function in 26 directions (rec_point_set; it includes the
     * per-axis min and max).  The per-axis MEAN recorded before moved by
     * 3 % of B when a clip's vertex on a face plane came out as one vertex
     * or as two 1e-12 apart with the rounding mode (the same body). */
    for (uint32_t i = 0; i < P->vertex_count; ++i)
        SWR_CHECK(c, fin3(&P->vertices[i]), "%s: vertex %u not finite", what, i);
    rec_point_set(c, P->vertices, P->vertex_count);
    for (uint32_t f = 0; f < P->face_count; ++f) {
        const swarp_plane* pl = &P->planes[f];
        double nl = sqrt(pl->a * pl->a + pl->b * pl->b + pl->c * pl->c);
        SWR_CHECK(c, fabs(nl - 1) <= 1e-9, "%s: face %u normal length %.17g", what, f, nl);
        SWR_CHECK(c, P->face_vertex_count[f] <= SWARP_POLY_MAX_FACE_VERTICES, "%s: face %u has %u vertices", what, f,
                  P->face_vertex_count[f]);
        for (uint32_t k = 0; k < P->face_vertex_count[f] && k < SWARP_POLY_MAX_FACE_VERTICES; ++k) {
            uint32_t v = P->face_vertices[f][k];
            SWR_CHECK(c, v < P->vertex_count, "%s: face %u index %u", what, f, v);
            if (v >= P->vertex_count) continue;
            double dev = fabs(plane_at(pl, P->vertices[v]));
            SWR_CHECK_ACC(c, dev <= tol, "%s: vertex %u off face %u by %g (tol %g)", what, v, f, dev, tol);
        }
        for (uint32_t v = 0; v < P->vertex_count; ++v) {
            double out = plane_at(pl, P->vertices[v]);
            SWR_CHECK_ACC(c, out <= tol, "%s: vertex %u outside face %u by %g (tol %g)", what, v, f, out, tol);
        }
    }
}
/* every vertex of P on the inner side of every plane of Q (P inside the convex Q) */
static void check_inside(swr_ctx* c, const swarp_polyhedron* P, const swarp_polyhedron* Q, double tol, const char* what) {
    for (uint32_t f = 0; f < Q->face_count && f < SWARP_POLY_MAX_FACES; ++f)
        for (uint32_t v = 0; v < P->vertex_count && v < SWARP_POLY_MAX_VERTICES; ++v) {
            double out = plane_at(&Q->planes[f], P->vertices[v]);
            SWR_CHECK_ACC(c, out <= tol, "%s: vertex %u outside plane %u by %g (tol %g)", what, v, f, out, tol);
        }
}
static void check_in_box(swr_ctx* c, const swarp_polyhedron* P, const swarp_aabb* b, double tol, const char* what) {
    for (uint32_t v = 0; v < P->vertex_count && v < SWARP_POLY_MAX_VERTICES; ++v) {
        swarp_vec3 p = P->vertices[v];
        SWR_CHECK_ACC(c, p.x >= b->min.x - tol && p.x <= b->max.x + tol && p.y >= b->min.y - tol && p.y <= b->max.y + tol &&
                             p.z >= b->min.z - tol && p.z <= b->max.z + tol,
                      "%s: vertex %u (%.17g %.17g %.17g) outside the box", what, v, p.x, p.y, p.z);
    }
}
/* view depth (p - eye) . dir/|dir|, in long double */
static double depth_of(const swarp_camera* cam, swarp_vec3 p) {
    long double dl = sqrtl((long double)cam->dir.x * cam->dir.x + (long double)cam->dir.y * cam->dir.y +
                           (long double)cam->dir.z * cam->dir.z);
    return (double)((((long double)p.x - cam->eye.x) * cam->dir.x + ((long double)p.y - cam->eye.y) * cam->dir.y +
                     ((long double)p.z - cam->eye.z) * cam->dir.z) / dl);
}
static void check_depths(swr_ctx* c, const swarp_polyhedron* P, const swarp_camera* cam, double near, double far,
                         double tol, const char* what) {
    for (uint32_t v = 0; v < P->vertex_count && v < SWARP_POLY_MAX_VERTICES; ++v) {
        double z = depth_of(cam, P->vertices[v]);
        SWR_CHECK_ACC(c, z >= near - tol && z <= far + tol, "%s: vertex %u at view depth %.17g outside [%.17g, %.17g]", what,
                      v, z, near, far);
    }
}
/* A polyhedron built by the library from a scene (H, the frustum or the
 * box), for the functions that take one; rarely a corrupted one (a caller's
 * bad struct: counts above the maxima, an index past the vertices, a NaN
 * vertex) with the status it calls for. */
/* The library leaves a polyhedron's unused slots unspecified (it may copy
 * a stack temporary whole); the corruptions below and poly_scale read past
 * the counts, so the generated polyhedron keeps only its used slots, the
 * rest zero (valgrind: uninitialised reads otherwise). */
static void poly_keep_used(swarp_polyhedron* P) {
    swarp_polyhedron T = *P;
    memset(P, 0, sizeof *P);
    P->vertex_count = T.vertex_count, P->face_count = T.face_count;
    for (uint32_t i = 0; i < T.vertex_count && i < SWARP_POLY_MAX_VERTICES; ++i) P->vertices[i] = T.vertices[i];
    for (uint32_t f = 0; f < T.face_count && f < SWARP_POLY_MAX_FACES; ++f) {
        P->planes[f] = T.planes[f];
        P->face_vertex_count[f] = T.face_vertex_count[f];
        for (uint32_t k = 0; k < T.face_vertex_count[f] && k < SWARP_POLY_MAX_FACE_VERTICES; ++k)
            P->face_vertices[f][k] = T.face_vertices[f][k];
    }
}

static void gen_poly(swr_ctx* c, const scene_args* s, swarp_polyhedron* P) {
    memset(P, 0, sizeof *P);
    uint8_t k = swr_u8(c) % 4;
    swarp_status st = SWARP_ERR_INVALID_ARGUMENT;
    if (k == 0 && swarp_body_h) st = swarp_body_h(&s->cam, s->cam.z_near, s->cam.z_far, &s->box, P);
    if (k == 1 && swarp_poly_from_camera) st = swarp_poly_from_camera(&s->cam, P);
    if (swarp_status_is_error(st) && swarp_poly_from_aabb) st = swarp_poly_from_aabb(&s->box, P);
    if (swarp_status_is_error(st)) { /* a unit box */
        swarp_aabb b = {{0, 0, 0}, {1, 1, 1}};
        if (swarp_poly_from_aabb) swarp_poly_from_aabb(&b, P);
    }
    poly_keep_used(P);
    if (swr_one_in(c, 48)) { /* corrupt */
        uint8_t how = swr_u8(c) % 4;
        if (how == 0) P->vertex_count = SWARP_POLY_MAX_VERTICES + 1 + swr_u8(c);
        if (how == 1) P->face_count = SWARP_POLY_MAX_FACES + 1;
        if (how == 2 && P->face_count) P->face_vertices[0][0] = (uint8_t)(P->vertex_count + swr_u8(c) % 8);
        if (how == 3 && P->face_count) P->face_vertex_count[0] = SWARP_POLY_MAX_FACE_VERTICES + 1;
        if (how <= 1 || P->face_count) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT);
    } else if (swr_one_in(c, 48) && P->vertex_count) {
        P->vertices[swr_u8(c) % P->vertex_count].y = NAN;
        swr_expect(c, SWARP_ERR_NON_FINITE);
    }
}

static void e_poly_camera_common(swr_ctx* c, int range) {
    scene_args s;
    gen_setup_scene(c, &s);
    double near = s.cam.z_near, far = s.cam.z_far;
    if (range) {
        static const double brk[] = {1e-6, 0.0};
        near = swr_num(c, 1e-6, 10, brk, 2);
        far = swr_one_in(c, 16) ? near : near * swr_num(c, 1.01, 1e7, NULL, 0);
        FIN(c, near);
        FIN(c, far);
        if (fin(near) && fin(far) && !(near > 0 && far > near)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    }
    const swarp_camera* pc = swr_in(c, &s.cam);
    swarp_polyhedron P;
    swarp_polyhedron* po = swr_out(c, &P, sizeof P, SWR_REQ);
    expect_parts(c, &s, !range, X_CAM);
    swr_domain(c, SWARP_ERR_DEGENERATE); /* up all but parallel to dir */
    {   /* documented: a corner beyond the double range is SWARP_ERR_OUT_OF_RANGE (long double:
           the bound itself must not overflow; /16 leaves room for the corners' rounding) */
        long double ty = tanl(0.5L * s.cam.fovy), tx = ty * s.cam.aspect;
        long double reach = (long double)vmax(s.cam.eye) + (long double)far * sqrtl(1 + tx * tx + ty * ty);
        if (fin(far) && fin(s.cam.fovy) && fin(s.cam.aspect) && reach > DBL_MAX / 16) swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
    }
    scene_cond(c, &s, near, far);
    swr_args(c, "eye (%.17g %.17g %.17g) dir (%.17g %.17g %.17g) up (%g %g %g) fovy %.17g aspect %.17g near %.17g far %.17g",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, s.cam.up.x, s.cam.up.y, s.cam.up.z,
             s.cam.fovy, s.cam.aspect, near, far);
    swarp_status st = range ? SWR_CALL(c, swarp_poly_from_camera_range(pc, near, far, po))
                            : SWR_CALL(c, swarp_poly_from_camera(pc, po));
    if (!swr_done(c, st)) return;
    /* the frustum's own scale: a huge aspect (1e76 is valid) makes it wide */
    double tol = gtol(fmax(vmax(s.cam.eye) + far, poly_scale(&P))) + 64 * DBL_EPSILON * c->cond * near;
    check_poly(c, &P, "V", tol);
    /* 8 corners; fewer where near-coincident ones merge (SWARP_POLY_EPS_REL) */
    SWR_CHECK(c, P.vertex_count >= 1 && P.vertex_count <= 8, "frustum with %u vertices", P.vertex_count);
    check_depths(c, &P, &s.cam, near, far, tol, "V");
    /* the point on the view axis halfway through is inside V */
    swarp_vec3 d = unit(s.cam.dir);
    double zm = 0.5 * near + 0.5 * far; /* near + far overflows for near, far ~ 1e308 (valid) */
    swarp_vec3 mid = v3(s.cam.eye.x + zm * d.x, s.cam.eye.y + zm * d.y, s.cam.eye.z + zm * d.z);
    for (uint32_t f = 0; f < P.face_count && f < SWARP_POLY_MAX_FACES; ++f)
        SWR_CHECK_ACC(c, plane_at(&P.planes[f], mid) <= tol, "the view axis at depth %g is outside face %u", zm, f);
}
static void e_poly_from_camera_range(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_poly_from_camera_range);
    e_poly_camera_common(c, 1);
}
static void e_poly_from_camera(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_poly_from_camera);
    e_poly_camera_common(c, 0);
}

static void e_poly_from_inverse_matrix(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_poly_from_inverse_matrix);
    swarp_mat4 M;
    static const double brk[] = {0.0, 1.0, -1.0};
    double off = swr_offset(c);
    for (int i = 0; i < 16; ++i) M.m[i] = swr_num_in(c, -2, 2, brk, 3) + (i % 5 == 0 ? 3.0 : 0.0);
    uint8_t kind = swr_u8(c) % 4;
    if (kind == 0) M.m[3] = M.m[7] = M.m[11] = 0, M.m[15] = 1; /* affine (an ortho inverse) */
    if (kind == 1) M.m[3] = M.m[7] = 0, M.m[11] = swr_num_in(c, -0.5, 0.5, brk, 1), M.m[15] = 1; /* projective */
    M.m[12] += off, M.m[14] += off;
    if (swr_one_in(c, 16)) M.m[swr_u8(c) % 16] = swr_num(c, -10, 10, brk, 3);
    int32_t dr = swr_enum(c, 3);
    const swarp_mat4* pm = swr_in(c, &M);
    swarp_polyhedron P;
    swarp_polyhedron* po = swr_out(c, &P, sizeof P, SWR_REQ);
    int finite = 1;
    for (int i = 0; i < 16; ++i) finite &= fin(M.m[i]);
    if (!finite) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (dr < 0 || dr > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    /* the 8 corners, independently (long double); reversed-Z (3) has the
     * same NDC depth set {0, 1} as [0, 1], its near face at 1 */
    swarp_vec3 corner[8];
    double z0 = dr == 2 || dr == 3 ? 0.0 : -1.0, scale = 0;
    int pos = 0, neg = 0, mixed;
    double wmin = INFINITY, wmax = 0;
    for (int k = 0; k < 8; ++k) {
        long double x = (k & 1) ? 1 : -1, y = (k & 2) ? 1 : -1, z = (k & 4) ? 1 : z0, q[4];
        for (int r = 0; r < 4; ++r) q[r] = M.m[r] * x + M.m[4 + r] * y + M.m[8 + r] * z + M.m[12 + r];
        pos += q[3] > 0, neg += q[3] < 0; /* all corners on one side of w = 0: a finite frustum */
        wmin = fmin(wmin, fabsl(q[3])), wmax = fmax(wmax, fabsl(q[3]));
        corner[k] = v3((double)(q[0] / q[3]), (double)(q[1] / q[3]), (double)(q[2] / q[3]));
        scale = fmax(scale, vmax(corner[k]));
    }
    mixed = pos != 8 && neg != 8;
    if (finite && mixed) swr_expect(c, SWARP_ERR_DEGENERATE);
    swr_args(c, "M = %.17g %.17g %.17g %.17g / %.17g %.17g %.17g %.17g / %.17g %.17g %.17g %.17g / %.17g %.17g %.17g %.17g (columns) dr %d",
             M.m[0], M.m[1], M.m[2], M.m[3], M.m[4], M.m[5], M.m[6], M.m[7], M.m[8], M.m[9], M.m[10], M.m[11], M.m[12], M.m[13],
             M.m[14], M.m[15], (int)dr);
    swr_domain(c, SWARP_ERR_DEGENERATE); /* w = 0 by a hair, singular matrices */
    swr_domain(c, SWARP_ERR_NON_FINITE); /* a corner overflows */
    if (!swr_done(c, SWR_CALL(c, swarp_poly_from_inverse_matrix(pm, (swarp_depth_range)dr, po)))) return;
    /* corners near w = 0 are far away and resolved only to eps (w_max / w_min) */
    swr_cond(c, wmax / wmin);
    double tol = gtol(scale) + 64 * DBL_EPSILON * c->cond * scale;
    check_poly(c, &P, "frustum", tol);
    SWR_CHECK(c, P.vertex_count <= 8, "%u vertices", P.vertex_count);
    for (uint32_t v = 0; v < P.vertex_count && v < 8; ++v) { /* each vertex is a corner */
        double best = INFINITY;
        for (int k = 0; k < 8; ++k) {
            swarp_vec3 e = v3(P.vertices[v].x - corner[k].x, P.vertices[v].y - corner[k].y, P.vertices[v].z - corner[k].z);
            best = fmin(best, vmax(e));
        }
        SWR_CHECK_ACC(c, best <= 1e3 * tol, "vertex %u is %g from every corner of the NDC cube's image", v, best);
    }
}

/* the plane for a clip: random, through a vertex, through the eye, zero or non-finite */
static swarp_plane gen_plane(swr_ctx* c, const scene_args* s, const swarp_polyhedron* P) {
    swarp_vec3 n = unit(v3(swr_num_in(c, -1, 1, NULL, 0), swr_num_in(c, -1, 1, NULL, 0), swr_num_in(c, -1, 1, NULL, 0)));
    uint8_t k = swr_u8(c) % 8;
    swarp_vec3 through = s->cam.eye;                                           /* k 0: through the eye */
    if (k >= 1 && k <= 3 && P->vertex_count && P->vertex_count <= SWARP_POLY_MAX_VERTICES)
        through = P->vertices[swr_u8(c) % P->vertex_count];                    /* through a vertex */
    if (k == 4 && P->face_count && P->face_count <= SWARP_POLY_MAX_FACES) {    /* a face's own plane, maybe flipped */
        swarp_plane q = P->planes[swr_u8(c) % P->face_count];
        if (swr_one_in(c, 2)) q.a = -q.a, q.b = -q.b, q.c = -q.c, q.d = -q.d;
        return q;
    }
    if (k >= 5) through = v3(s->box.min.x + swr_num_in(c, 0, 1, NULL, 0) * (s->box.max.x - s->box.min.x), s->box.min.y,
                             s->box.min.z + swr_num_in(c, 0, 1, NULL, 0) * (s->box.max.z - s->box.min.z));
    double len = swr_num_in(c, 1e-3, 1e3, NULL, 0);
    swarp_plane q = {n.x * len, n.y * len, n.z * len, -len * dot(n, through)};
    if (swr_one_in(c, 32)) q.a = q.b = q.c = 0;
    if (swr_one_in(c, 16)) {
        double* f[] = {&q.a, &q.b, &q.c, &q.d};
        *f[swr_u8(c) % 4] = swr_num(c, -1, 1, NULL, 0);
    }
    return q;
}

/* in -> out in place (out may equal in) or into a separate polyhedron;
 * error => the output untouched (in place: still equal to in) */
static int clip_call(swr_ctx* c, const swarp_polyhedron* in, swarp_polyhedron* out, int in_place, const swarp_plane* pl,
                     const swarp_aabb* box, int n_in, int n_x, int n_out) {
    if (in_place) *out = *in;
    else swr_fill(out, sizeof *out);
    const swarp_polyhedron* pin = n_in ? NULL : in_place ? out : in;
    swarp_polyhedron* po = n_out ? NULL : out;
    swarp_status st = pl ? SWR_CALL(c, swarp_poly_clip(pin, n_x ? NULL : pl, po))
                         : SWR_CALL(c, swarp_poly_clip_aabb(pin, n_x ? NULL : box, po));
    int ok = swr_verdict(c, st, 0);
    if (swarp_status_is_error(st))
        SWR_CHECK(c, in_place ? memcmp(out, in, sizeof *in) == 0 : swr_untouched(out, sizeof *out),
                  "error %s but the output was written%s", swarp_status_name(st), in_place ? " (in place)" : "");
    return ok;
}

/* The condition of the cut of the segment u-w by the plane pn (see the
 * derivation in e_poly_clip_common), recorded when it crosses. */
static void clip_cut_cond(swr_ctx* c, const swarp_plane* pn, const swarp_polyhedron* in, uint32_t iu, uint32_t iw) {
    if (iu >= in->vertex_count || iw >= in->vertex_count) return;
    const swarp_vec3 u = in->vertices[iu], w = in->vertices[iw];
    const double du = plane_at(pn, u), dv = plane_at(pn, w);
    if (!((du <= 0 && dv >= 0) || (du >= 0 && dv <= 0)) || du == dv) return;
    const double T = fmax(fabs(pn->a * u.x) + fabs(pn->b * u.y) + fabs(pn->c * u.z), fabs(pn->a * w.x) + fabs(pn->b * w.y) + fabs(pn->c * w.z)) + fabs(pn->d);
    const double len = vmax(v3(w.x - u.x, w.y - u.y, w.z - u.z));
    swr_cond(c, T * len / (fabs(du - dv) * fmax(poly_scale(in), 1e-300)));
}

static void e_poly_clip_common(swr_ctx* c, int with_box) {
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_polyhedron in, out;
    gen_poly(c, &s, &in);
    swarp_plane pl = gen_plane(c, &s, &in);
    swarp_aabb box = s.box;
    if (with_box) { /* a box around part of it, sometimes flat or a point */
        double sc = fmax(poly_scale(&in), 1);
        box.min.x += 0.3 * (box.max.x - box.min.x);
        if (swr_one_in(c, 4)) box.max.y = box.min.y;
        if (swr_one_in(c, 8)) box.max = box.min;
        if (swr_one_in(c, 16)) box.min.z = box.max.z + 1;
        if (swr_one_in(c, 32)) box.max.x = swr_num(c, -sc, sc, NULL, 0);
    }
    int in_place = swr_one_in(c, 6);
    int n_in = swr_null(c), n_x = swr_null(c), n_out = !in_place && swr_null(c);
    if (n_in || n_x || n_out) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (with_box) {
        if (!fin3(&box.min) || !fin3(&box.max)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (!(box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z))
            swr_expect(c, SWARP_ERR_BOX_INVERTED);
    } else {
        if (!fin(pl.a) || !fin(pl.b) || !fin(pl.c) || !fin(pl.d)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (pl.a == 0 && pl.b == 0 && pl.c == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    }
    swr_domain(c, SWARP_ERR_CAPACITY);
    swr_args(c, "aspect %g in %u vertices scale %g plane (%.17g %.17g %.17g %.17g) box (%.17g %.17g %.17g)-(%.17g %.17g %.17g) in place %d",
             s.cam.aspect, in.vertex_count, poly_scale(&in), pl.a, pl.b, pl.c, pl.d, box.min.x, box.min.y, box.min.z, box.max.x,
             box.max.y, box.max.z, in_place);
    if (!clip_call(c, &in, &out, in_place, with_box ? NULL : &pl, &box, n_in, n_x, n_out)) return;
    /* the plane scaled by its largest normal coefficient (a power-free division, exact enough):
       a coefficient near DBL_MAX is valid input, and |n|^2 of the raw plane overflows to inf,
       which made inf/inf = NaN distances here (the library result itself was fine) */
    swarp_plane pn = pl;
    if (!with_box) {
        double m = fmax(fabs(pl.a), fmax(fabs(pl.b), fabs(pl.c)));
        if (m > 0) pn.a = pl.a / m, pn.b = pl.b / m, pn.c = pl.c / m, pn.d = pl.d / m;
    }
    double sc = fmax(poly_scale(&in), with_box ? box_scale(&box) : fabs(pn.d) / sqrt(pn.a * pn.a + pn.b * pn.b + pn.c * pn.c));
    double tol = gtol(sc);
    if (wide(&s.cam)) c->rounding_edge = 1;
    check_poly(c, &out, "clip", tol);
    check_inside(c, &out, &in, tol, "clip result in the input");
    if (with_box) {
        check_in_box(c, &out, &box, tol, "clip result in the box");
        return;
    }
    double nl = sqrt(pn.a * pn.a + pn.b * pn.b + pn.c * pn.c);
    /* Condition of the new vertices: an edge u -> v crossing the plane is
     * cut at t = d_u / (d_u - d_v), d = n.p + d computed from terms of total
     * magnitude T = |a x| + |b y| + |c z| + |d|, each d rounded by ~eps T;
     * t moves by eps T / |d_u - d_v| and the cut point by that times
     * |v - u|: relative to the polyhedron's scale, cond = T |v - u| /
     * (|d_u - d_v| scale).  Large for an edge whose ends are both within a
     * cancellation of the plane (e.g. d = -9e-4 and 5e-4
     * from terms of 8e3, an edge of 40, the cut moved 4e-8).  A polyhedron
     * without faces (a point set: a segment, in practice) has its crossing
     * pairs cut instead of its edges (poly.c): every pair counts (e.g. a
     * segment 44 long within 1e-7 rad of the plane,
     * cut 6e-8 apart by rounding mode; cond 2e7). */
    for (uint32_t f = 0; f < in.face_count && f < SWARP_POLY_MAX_FACES; ++f) {
        const uint32_t nv = in.face_vertex_count[f] <= SWARP_POLY_MAX_FACE_VERTICES ? in.face_vertex_count[f] : 0;
        for (uint32_t k = 0; k < nv; ++k) clip_cut_cond(c, &pn, &in, in.face_vertices[f][k], in.face_vertices[f][(k + 1) % nv]);
    }
    if (in.face_count == 0)
        for (uint32_t u = 0; u < in.vertex_count && u < SWARP_POLY_MAX_VERTICES; ++u)
            for (uint32_t w = 0; w < u; ++w) clip_cut_cond(c, &pn, &in, u, w);
    int all_in = 1, all_out = in.vertex_count > 0;
    for (uint32_t v = 0; v < out.vertex_count && v < SWARP_POLY_MAX_VERTICES; ++v)
        SWR_CHECK_ACC(c, plane_at(&pn, out.vertices[v]) / nl <= tol, "clip: vertex %u on the removed side by %g", v,
                      plane_at(&pn, out.vertices[v]) / nl);
    for (uint32_t v = 0; v < in.vertex_count && v < SWARP_POLY_MAX_VERTICES; ++v) {
        double e = plane_at(&pn, in.vertices[v]) / nl;
        all_in &= e < -tol;
        all_out &= e > tol;
    }
    if (all_in) SWR_CHECK(c, out.vertex_count == in.vertex_count, "a plane missing the polyhedron changed it (%u -> %u vertices)",
                          in.vertex_count, out.vertex_count);
    if (all_out) SWR_CHECK(c, out.vertex_count == 0, "a plane with the polyhedron on its removed side left %u vertices",
                           out.vertex_count);
}
static void e_poly_clip(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_poly_clip);
    e_poly_clip_common(c, 0);
}
static void e_poly_clip_aabb(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_poly_clip_aabb);
    e_poly_clip_common(c, 1);
}


static void e_body_h(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_body_h);
    scene_args s;
    gen_setup_scene(c, &s);
    double near = s.cam.z_near, far = swr_one_in(c, 16) ? near : s.cam.z_far;
    FIN(c, near);
    FIN(c, far);
    if (fin(near) && fin(far) && !(near > 0 && far > near)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_aabb* pb = swr_in(c, &s.box);
    swarp_polyhedron H;
    swarp_polyhedron* po = swr_out(c, &H, sizeof H, SWR_REQ);
    expect_parts(c, &s, 0, X_CAM | X_BOX | X_GEOM);
    scene_cond(c, &s, near, far);
    swr_args(c, "eye (%.17g %.17g %.17g) dir (%.17g %.17g %.17g) fovy %.17g aspect %.17g near %.17g far %.17g box (%.17g %.17g %.17g)-(%.17g %.17g %.17g)",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, s.cam.fovy, s.cam.aspect, near, far,
             s.box.min.x, s.box.min.y, s.box.min.z, s.box.max.x, s.box.max.y, s.box.max.z);
    if (!swr_done(c, SWR_CALL(c, swarp_body_h(pc, near, far, pb, po)))) return;
    double tol = gtol(fmax(box_scale(&s.box), vmax(s.cam.eye) + far)) + 64 * DBL_EPSILON * c->cond * near;
    if (wide(&s.cam)) c->rounding_edge = 1;
    check_poly(c, &H, "H", tol);
    SWR_CHECK(c, H.vertex_count > 0, "H empty with %s", swarp_status_name(c->status));
    check_in_box(c, &H, &s.box, tol, "H in S");
    check_depths(c, &H, &s.cam, near, far, tol, "H in V");
}

static void e_body_from_h(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_body_from_h);
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_polyhedron H, B;
    gen_poly(c, &s, &H);
    const swarp_polyhedron* ph = swr_in(c, &H);
    const swarp_light* pl = swr_in(c, &s.light);
    const swarp_aabb* pb = swr_in(c, &s.box);
    swarp_polyhedron* po = swr_out(c, &B, sizeof B, SWR_REQ);
    expect_parts(c, &s, 0, X_LIGHT | X_BOX | X_GEOM);
    swr_domain(c, SWARP_ERR_CAPACITY);
    swr_args(c, "aspect %g H %u vertices, %u faces, light %d dir (%g %g %g) pos (%.17g %.17g %.17g) cone %g box (%.17g %.17g %.17g)-(%.17g %.17g %.17g)",
             s.cam.aspect, H.vertex_count, H.face_count, (int)s.light.type, s.light.direction.x, s.light.direction.y, s.light.direction.z,
             s.light.position.x, s.light.position.y, s.light.position.z, s.light.cone_angle, s.box.min.x, s.box.min.y,
             s.box.min.z, s.box.max.x, s.box.max.y, s.box.max.z);
    if (!swr_done(c, SWR_CALL(c, swarp_body_from_h(ph, pl, pb, po)))) return;
    double tol = gtol(fmax(box_scale(&s.box), fmax(poly_scale(&H), vmax(s.light.position))));
    if (wide(&s.cam)) c->rounding_edge = 1;
    /* B within the clipper's merge distance, SWARP_POLY_EPS_REL of the
     * clipped body's scale X (H swept by T = 2 diag(S) for a directional
     * light, conv(H ∪ {l}) for a point light): the box planes classify
     * every vertex within that distance as on them, so B is the sweep cut
     * or not, or empty (BODY_EMPTY), by rounding, as frustum_below_merge
     * for H (e.g. a box 45 x 5e43 x 70 at 7.7e5, X =
     * 1e44, merge distance 1e32 against a B 3e7 across; SWARP_OK to
     * nearest, BODY_EMPTY under FE_UPWARD).  A B of one point is one. */
    {
        const long double dx = (long double)s.box.max.x - s.box.min.x, dy = (long double)s.box.max.y - s.box.min.y,
                          dz = (long double)s.box.max.z - s.box.min.z;
        long double X = fmaxl(box_scale(&s.box), poly_scale(&H));
        if ((int)s.light.type == 2) X = fmaxl(X, vmax(s.light.position));
        else X = fmaxl(X, poly_scale(&H) + fminl(2 * sqrtl(dx * dx + dy * dy + dz * dz), 0.25L * DBL_MAX));
        long double E = 0;
        double lo[3], hi[3];
        for (int k = 0; k < 3; ++k) lo[k] = INFINITY, hi[k] = -INFINITY;
        for (uint32_t i = 0; i < B.vertex_count && i < SWARP_POLY_MAX_VERTICES; ++i) {
            const double v[3] = {B.vertices[i].x, B.vertices[i].y, B.vertices[i].z};
            for (int k = 0; k < 3; ++k) lo[k] = fmin(lo[k], v[k]), hi[k] = fmax(hi[k], v[k]);
        }
        for (int k = 0; k < 3; ++k) E = fmaxl(E, (long double)hi[k] - lo[k]);
        if (B.vertex_count > 0 && E <= 2 * SWARP_POLY_EPS_REL * X) c->rounding_edge = 1;
    }
    check_poly(c, &B, "B", tol);
    check_in_box(c, &B, &s.box, tol, "B in S");
    /* a directional or omni light: H (clipped to S) lies inside B */
    int t = (int)s.light.type;
    if (t != 2 || s.light.cone_angle == 0) {
        swarp_polyhedron HS;
        if (swarp_poly_clip_aabb && swarp_poly_clip_aabb(&H, &s.box, &HS) == SWARP_OK)
            check_inside(c, &HS, &B, tol, "H inside B");
    }
}

static void e_body_receivers(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_body_receivers);
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_polyhedron H, R;
    gen_poly(c, &s, &H);
    const swarp_polyhedron* ph = swr_in(c, &H);
    const swarp_light* pl = swr_in(c, &s.light);
    swarp_polyhedron* po = swr_out(c, &R, sizeof R, SWR_REQ);
    expect_parts(c, &s, 0, X_LIGHT | X_GEOM);
    swr_domain(c, SWARP_ERR_CAPACITY);
    if (!swr_done(c, SWR_CALL(c, swarp_body_receivers(ph, pl, po)))) return;
    double tol = gtol(fmax(poly_scale(&H), vmax(s.light.position)));
    if (wide(&s.cam)) c->rounding_edge = 1;
    check_poly(c, &R, "receivers", tol);
    check_inside(c, &R, &H, tol, "receivers inside H");
    int t = (int)s.light.type;
    if (t != 2 || s.light.cone_angle == 0)
        SWR_CHECK(c, R.vertex_count == H.vertex_count, "no cone but %u of %u vertices of H", R.vertex_count, H.vertex_count);
}

static void e_body_adjusted_range(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_body_adjusted_range);
    scene_args s;
    gen_setup_scene(c, &s);
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_aabb* pb = swr_in(c, &s.box);
    double n, f;
    double* pn = swr_out(c, &n, sizeof n, SWR_REQ);
    double* pf = swr_out(c, &f, sizeof f, SWR_REQ);
    expect_parts(c, &s, 1, X_CAM | X_BOX | X_GEOM);
    scene_cond(c, &s, s.cam.z_near, s.cam.z_far);
    swr_args(c, "eye (%.17g %.17g %.17g) dir (%.17g %.17g %.17g) up (%g %g %g) fovy %.17g aspect %.17g near %.17g far %.17g box (%.17g %.17g %.17g)-(%.17g %.17g %.17g)",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, s.cam.up.x, s.cam.up.y, s.cam.up.z, s.cam.fovy,
             s.cam.aspect, s.cam.z_near, s.cam.z_far, s.box.min.x, s.box.min.y, s.box.min.z, s.box.max.x, s.box.max.y, s.box.max.z);
    if (!swr_done(c, SWR_CALL(c, swarp_body_adjusted_range(pc, pb, pn, pf)))) return;
    swr_rec(c, "near", n);
    swr_rec(c, "far", f);
    /* inside the camera's range and inside the box corners' depth range */
    double zlo = INFINITY, zhi = -INFINITY;
    for (int k = 0; k < 8; ++k) {
        swarp_vec3 p = v3((k & 1) ? s.box.max.x : s.box.min.x, (k & 2) ? s.box.max.y : s.box.min.y,
                          (k & 4) ? s.box.max.z : s.box.min.z);
        double z = depth_of(&s.cam, p);
        zlo = fmin(zlo, z), zhi = fmax(zhi, z);
    }
    double tol = gtol(fmax(box_scale(&s.box), vmax(s.cam.eye)) + s.cam.z_far);
    if (wide(&s.cam)) c->rounding_edge = 1;
    SWR_CHECK(c, n > 0 && n <= f, "adjusted range [%.17g, %.17g]", n, f);
    SWR_CHECK_ACC(c, n >= s.cam.z_near - tol && f <= s.cam.z_far + tol, "adjusted [%.17g, %.17g] outside the camera's [%.17g, %.17g]",
                  n, f, s.cam.z_near, s.cam.z_far);
    SWR_CHECK_ACC(c, n >= zlo - tol && f <= zhi + tol, "adjusted [%.17g, %.17g] outside the box's depths [%.17g, %.17g]", n, f,
                  zlo, zhi);
}

/* row r of the upper 3x3 of a column-major matrix */
static swarp_vec3 row3(const swarp_mat4* m, int r) { return v3(m->m[r], m->m[4 + r], m->m[8 + r]); }

/* unit() scaled first: sqrt(dot(a, a)) overflows (to 0 after the divide) for
 * |a| near DBL_MAX and underflows for subnormal a; both are valid axes. */
static swarp_vec3 unit_scaled(swarp_vec3 a) {
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(m > 0) || !isfinite(m)) return a;
    return unit(v3(a.x / m, a.y / m, a.z / m));
}

/* The condition of B's cuts of its sweep by the faces of S.  B is H's
 * sweep toward the light clipped by S (src/geometry/body.c), in world coordinates:
 * for a directional light the edges from each vertex h of H to h - T u (u
 * the light's unit direction, T = 2 diag(S)), for a point light from h to
 * l.  An edge h-w crossing the face x_k = f is cut where the distance
 * d = x_k - f, rounded to eps (max(|h_k|, |w_k|) + |f|) = eps T_k, vanishes:
 * d changes by |d_h - d_w| over the edge's length, so the cut moves along
 * it by eps T_k len / |d_h - d_w|, relative to B's scale X: condition
 * T_k len / (|d_h - d_w| X), the per-edge condition of swarp_poly_clip's
 * entry (clip_cut_cond).  Large where the light grazes the face: a slab
 * 1e-9 thick at y = -10 with the light 2.4e-10 rad off its plane, an edge
 * from H's vertex on the bottom face rising through the top face 4 units
 * on (e.g. h_y = -10 one ulp up or down by rounding
 * mode, the cut moved 7.9e-6 along the edge, 1.7e-7 of B's 45; condition
 * 1.6e9).  Recorded for the cuts that are vertices of B (within the cut's
 * own rounding; an edge inside the sweep is cut too, but is no vertex), H
 * from swarp_body_h in the default environment (the clipper's H). */
static void body_sweep_cut_cond(swr_ctx* c, const scene_args* s, double near, double far, const swarp_vec3* pts, size_t n) {
    const int t = (int)s->light.type;
    if (!n || !swarp_body_h || (t == 2 ? !fin3(&s->light.position) : !(fin3(&s->light.direction) && vmax(s->light.direction) > 0)))
        return;
    const swarp_aabb* b = &s->box;
    swarp_polyhedron H;
    if (swarp_body_h(&s->cam, near, far, b, &H) != SWARP_OK) return;
    double X = 0;
    for (size_t i = 0; i < n; ++i) X = fmax(X, vmax(pts[i]));
    const double ex = b->max.x - b->min.x, ey = b->max.y - b->min.y, ez = b->max.z - b->min.z;
    const double T = 2 * sqrt(ex * ex + ey * ey + ez * ez);
    const swarp_vec3 u = unit_scaled(s->light.direction);
    if (!(X > 0) || !isfinite(X) || !isfinite(T)) return;
    const double lo[3] = {b->min.x, b->min.y, b->min.z}, hi[3] = {b->max.x, b->max.y, b->max.z};
    for (uint32_t i = 0; i < H.vertex_count && i < SWARP_POLY_MAX_VERTICES; ++i) {
        const swarp_vec3 h = H.vertices[i];
        const swarp_vec3 w = t == 2 ? s->light.position : v3(h.x - T * u.x, h.y - T * u.y, h.z - T * u.z);
        const double hv[3] = {h.x, h.y, h.z}, wv[3] = {w.x, w.y, w.z};
        const double len = vmax(v3(w.x - h.x, w.y - h.y, w.z - h.z));
        for (int k = 0; k < 6; ++k) {
            const double f = k < 3 ? lo[k] : hi[k - 3];
            const int a = k % 3;
            const double dh = hv[a] - f, dw = wv[a] - f;
            if (!(dh * dw < 0)) continue; /* crossing strictly: an end on the face is no cut */
            const double Tk = fmax(fabs(hv[a]), fabs(wv[a])) + fabs(f);
            const double cond = Tk * len / (fabs(dh - dw) * X);
            if (!isfinite(cond)) continue;
            const double sc = dh / (dh - dw);
            const swarp_vec3 q = v3(h.x + sc * (w.x - h.x), h.y + sc * (w.y - h.y), h.z + sc * (w.z - h.z));
            const double slack = 64 * DBL_EPSILON * cond * X + gtol(X);
            for (size_t j = 0; j < n; ++j)
                if (vmax(v3(pts[j].x - q.x, pts[j].y - q.y, pts[j].z - q.z)) <= slack) {
                    swr_cond(c, cond);
                    break;
                }
        }
    }
}

/* B's vertex count (SWARP_ERR_CAPACITY against the caller's capacity)
 * decided by rounding: a face of H parallel to a directional light to
 * within its rounding, |n·u| <= 64 eps (n and u unit vectors rounded to a
 * few eps: the light exactly in the plane of a frustum face, e.g. along the
 * camera's right axis, which lies in the top and bottom planes), is swept
 * or kept by the sign of the rounding (src/geometry/body.c, sw_face_is_front).  The
 * body is the same set either way, but its vertex list differs by that
 * face's vertices: kept, they lie on edges of B (e.g. 16
 * vertices under FE_TONEAREST, 14 under the directed modes, n·u = -6e-18
 * and 4e-17).  So the status is a rounding edge when the capacity is
 * within G of B's count, G the number of vertices of those faces.  H is
 * recomputed here (swarp_body_h, world coordinates: the face normals are
 * the library's to a few eps), the count from a full-capacity call in the
 * default environment. */
static void setup_capacity_edge(swr_ctx* c, const scene_args* s, int range, double near, double far, size_t cap) {
    int t = (int)s->light.type;
    if ((t != 0 && t != 1) || !fin3(&s->light.direction) || !(vmax(s->light.direction) > 0)) return;
    swarp_polyhedron H;
    if (!swarp_body_h || swarp_body_h(&s->cam, near, far, &s->box, &H) != SWARP_OK) return;
    swarp_vec3 u = unit_scaled(s->light.direction);
    uint8_t on[SWARP_POLY_MAX_VERTICES];
    memset(on, 0, sizeof on);
    size_t G = 0;
    for (uint32_t f = 0; f < H.face_count && f < SWARP_POLY_MAX_FACES; ++f) {
        const swarp_plane* q = &H.planes[f];
        if (!(fabs(q->a * u.x + q->b * u.y + q->c * u.z) <= 64 * DBL_EPSILON)) continue;
        for (uint32_t k = 0; k < H.face_vertex_count[f] && k < SWARP_POLY_MAX_FACE_VERTICES; ++k) {
            uint8_t v = H.face_vertices[f][k];
            if (v < SWARP_POLY_MAX_VERTICES && !on[v]) on[v] = 1, ++G;
        }
    }
    if (!G) return;
    swarp_setup_result r2;
    swarp_vec3 bp[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status st = range ? swarp_setup_range(&s->cam, &s->light, &s->box, near, far, s->use_opt ? &s->opt : NULL, &r2, bp,
                                                SWARP_BODY_MAX_POINTS, &n)
                            : swarp_setup(&s->cam, &s->light, &s->box, s->use_opt ? &s->opt : NULL, &r2, bp, SWARP_BODY_MAX_POINTS, &n);
    if (swarp_status_is_error(st)) return;
    if (n <= cap + G && cap <= n + G) c->rounding_edge = 1;
}

static void e_focus_light_view(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_focus_light_view);
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_vec3 axis = unit(v3(swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0)));
    if (swr_one_in(c, 32)) axis = v3(0, 0, 0);
    int n_axis = swr_one_in(c, 2);
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_light* pl = swr_in(c, &s.light);
    swarp_mat4 V;
    swarp_mat4* po = swr_out(c, &V, sizeof V, SWR_REQ);
    expect_parts(c, &s, 0, X_CAM | X_LIGHT);
    int t = (int)s.light.type, point = t == 2;
    if (point && !n_axis) {
        if (!fin3(&axis)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (axis.x == 0 && axis.y == 0 && axis.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    }
    swr_domain(c, SWARP_ERR_ZERO_VECTOR); /* omni light at the eye */
    swr_domain(c, SWARP_ERR_DEGENERATE);
    swr_domain(c, SWARP_ERR_NEAR_FAR);
    swr_domain(c, SWARP_ERR_OVERFLOW); /* documented: an origin ~DBL_MAX, translation beyond DBL_MAX */
    if (!swr_done(c, SWR_CALL(c, swarp_focus_light_view(pc, pl, n_axis ? NULL : &axis, po)))) return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "view", V.m[i]);
    /* a rigid motion: orthonormal rows, det +1, last row 0 0 0 1 */
    swarp_vec3 r0 = row3(&V, 0), r1 = row3(&V, 1), r2 = row3(&V, 2);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            swarp_vec3 ra = row3(&V, a), rb = row3(&V, b);
            SWR_CHECK(c, fabs(dot(ra, rb) - (a == b)) <= 1e-12, "rows %d, %d: dot %.17g", a, b, dot(ra, rb));
        }
    SWR_CHECK(c, dot(cross(r0, r1), r2) > 0, "left-handed light view");
    SWR_CHECK(c, V.m[3] == 0 && V.m[7] == 0 && V.m[11] == 0 && V.m[15] == 1, "last row not 0 0 0 1");
    /* it looks along the light (down -z) from its origin */
    swarp_vec3 look = point ? (n_axis ? (s.light.cone_angle > 0 ? s.light.direction
                                                               : v3(s.cam.eye.x - s.light.position.x, s.cam.eye.y - s.light.position.y,
                                                                    s.cam.eye.z - s.light.position.z))
                                      : axis)
                            : s.light.direction;
    swarp_vec3 o = point ? s.light.position : s.cam.eye;
    look = unit_scaled(look);
    SWR_CHECK_ACC(c, fabs(dot(r2, look) + 1) <= 1e-9, "the light view's -z is not the light axis (dot %.17g)", -dot(r2, look));
    swarp_vec4 q = xf(&V, o);
    SWR_CHECK_ACC(c, vmax(v3(q.x, q.y, q.z)) <= gtol(vmax(o)) + 1e-12, "the origin maps to (%g %g %g)", q.x, q.y, q.z);
    /* light-space alignment [RHS] §3.2.1: away from the blend zone the up
     * vector is the view direction projected on the plane normal to the axis */
    swarp_vec3 vd = unit(s.cam.dir);
    double cg = dot(vd, look);
    swarp_vec3 vp = v3(vd.x - cg * look.x, vd.y - cg * look.y, vd.z - cg * look.z);
    if (sqrt(dot(vp, vp)) > 0.2) SWR_CHECK_ACC(c, dot(unit(vp), r1) >= 1 - 1e-9, "up is not the projected view direction (dot %.17g)",
                                          dot(unit(vp), r1));
}

static void e_focus_fit(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_focus_fit);
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    double sx = swr_num_in(c, 1e-3, 1e3, NULL, 0), sy = swr_num_in(c, 1e-3, 1e3, NULL, 0);
    m.m[0] = sx, m.m[5] = sy, m.m[10] = 1, m.m[15] = 1;
    if (swr_one_in(c, 2)) m.m[11] = -1, m.m[15] = 0; /* perspective: w = -z */
    m.m[12] = swr_offset(c);
    m.m[1] = swr_num_in(c, -1, 1, NULL, 0); /* a shear */
    size_t n = swr_one_in(c, 16) ? 0 : 1 + swr_u8(c) % 16, nz = swr_u8(c) % 8;
    swarp_vec3 pts[16], zp[8];
    double off = swr_offset(c);
    swarp_vec3 ctr = v3(off + swr_num_in(c, -10, 10, NULL, 0), swr_num_in(c, -10, 10, NULL, 0), -swr_num_in(c, 1e-3, 1e3, NULL, 0));
    double ext = swr_num_in(c, 0, 10, NULL, 0) * (swr_one_in(c, 8) ? 0 : 1);
    for (size_t i = 0; i < 16; ++i)
        pts[i] = v3(ctr.x + ext * swr_num_in(c, -1, 1, NULL, 0), ctr.y + ext * swr_num_in(c, -1, 1, NULL, 0),
                    ctr.z + (swr_one_in(c, 4) ? 0 : fmin(ext, -ctr.z / 2) * swr_num_in(c, -1, 1, NULL, 0)));
    for (size_t i = 0; i < 8; ++i) zp[i] = pts[swr_u8(c) % 16], zp[i].z *= swr_num_in(c, 0.5, 2, NULL, 0);
    if (swr_one_in(c, 16)) pts[swr_u8(c) % 16].x = swr_num(c, -1, 1, NULL, 0);
    if (swr_one_in(c, 16)) m.m[swr_u8(c) % 16] = swr_num(c, -1, 1, NULL, 0);
    int32_t dr = swr_enum(c, 3);
    int n_z = swr_one_in(c, 2);
    if (n_z) nz = 0;
    const swarp_mat4* pm = swr_in(c, &m);
    const swarp_vec3* pp = swr_in(c, pts);
    swarp_mat4 A;
    swarp_mat4* po = swr_out(c, &A, sizeof A, SWR_REQ);
    int finite = 1, behind = 0;
    for (int i = 0; i < 16; ++i) finite &= fin(m.m[i]);
    for (size_t i = 0; i < n + nz; ++i) {
        const swarp_vec3* p = i < n ? &pts[i] : &zp[i - n];
        finite &= fin3(p);
        if (fin3(p) && !(xf(&m, *p).w > 0)) behind = 1;
    }
    if (!finite) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (dr < 0 || dr > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM); /* 3: reversed-Z */
    /* count 0, or z_points with z_count 0: SWARP_ERR_INVALID_ARGUMENT (not
     * in the header's @return list: a documentation finding) */
    if (n == 0 || (!n_z && nz == 0)) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT), swr_domain(c, SWARP_ERR_NULL_POINTER);
    if (finite && behind) swr_expect(c, SWARP_ERR_DEGENERATE);
    swr_domain(c, SWARP_ERR_DEGENERATE), swr_domain(c, SWARP_ERR_NON_FINITE);
    if (!swr_done(c, SWR_CALL(c, swarp_focus_fit(pm, pp, n, n_z ? NULL : zp, nz, (swarp_depth_range)dr, po)))) return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "A_fit", A.m[i]);
    /* every point maps into the unit square (and depth range), the extremes onto its edges */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, cmax = 0, emax[3] = {0, 0, 0};
    double ulo[3] = {INFINITY, INFINITY, INFINITY}, uhi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double zlo = dr == 2 || dr == 3 ? 0 : -1; /* reversed-Z: [0, 1] turned over, same bounds */
    for (size_t i = 0; i < n + (n_z ? n : nz); ++i) {
        int is_z = i >= n;
        const swarp_vec3* p = !is_z ? &pts[i] : n_z ? &pts[i - n] : &zp[i - n];
        swarp_vec4 q = xf(&m, *p);
        swarp_vec3 u = v3(q.x / q.w, q.y / q.w, q.z / q.w);
        cmax = fmax(cmax, vmax(u));
        swarp_vec4 a = xf(&A, u);
        double r[3] = {a.x / a.w, a.y / a.w, a.z / a.w};
        for (int k = is_z ? 2 : 0; k < (is_z ? 3 : 2); ++k) lo[k] = fmin(lo[k], r[k]), hi[k] = fmax(hi[k], r[k]);
        const double uk[3] = {u.x, u.y, u.z};
        for (int k = 0; k < 3; ++k) emax[k] = fmax(emax[k], fabs(uk[k])), ulo[k] = fmin(ulo[k], uk[k]), uhi[k] = fmax(uhi[k], uk[k]);
    }
    /* The fit's translation is -(lo + hi)/(hi - lo) and its scale 2/(hi - lo):
     * an extent E of coordinates computed with an absolute rounding error
     * eps R is resolved to eps R/E, so cond = R/E per axis, where R bounds
     * the rounding of u_k = q_k/w: (sum_j |m_kj p_j| + |m_k3|)/|w| for q_k
     * plus |u_k| (sum_j |m_3j p_j| + |m_33|)/|w| for the division by w --
     * not |u_k|, which is small when a shear cancels a 1e6 offset.  The
     * extents are those the library fits: x, y over the points, z over the
     * z_points when given (the z_points' x, y widened the extent the
     * condition was measured on: x at -3e6 over 0.35, and y at -4.5e5 over
     * 0.008, drifted 1.3e-9 and 7e-9 with cond 1e7 and 5e7 measured as
     * 3e4). */
    {
        double flo[3] = {INFINITY, INFINITY, INFINITY}, fhi[3] = {-INFINITY, -INFINITY, -INFINITY}, R[3] = {0, 0, 0};
        /* the coordinates u_k depends on (rows k and w of m) are the same
         * for all the axis' points: E = 0 exactly, in every mode */
        int same[3] = {1, 1, 1};
        for (size_t i = 0; i < n + (n_z ? n : nz); ++i) {
            int is_z = i >= n;
            const swarp_vec3* p = !is_z ? &pts[i] : n_z ? &pts[i - n] : &zp[i - n];
            const swarp_vec3* p0 = !is_z ? &pts[0] : n_z ? &pts[0] : &zp[0];
            const double pa[3] = {p->x, p->y, p->z}, pb[3] = {p0->x, p0->y, p0->z};
            swarp_vec4 q = xf(&m, *p);
            const double qk[4] = {q.x, q.y, q.z, q.w};
            double t[4];
            for (int r = 0; r < 4; ++r)
                t[r] = fabs(m.m[r] * p->x) + fabs(m.m[4 + r] * p->y) + fabs(m.m[8 + r] * p->z) + fabs(m.m[12 + r]);
            for (int k = is_z ? 2 : 0; k < (is_z ? 3 : 2); ++k) {
                double u = qk[k] / q.w;
                flo[k] = fmin(flo[k], u), fhi[k] = fmax(fhi[k], u);
                R[k] = fmax(R[k], (t[k] + fabs(u) * t[3]) / fabs(q.w));
                for (int j = 0; j < 3; ++j)
                    if ((m.m[4 * j + k] != 0 || m.m[4 * j + 3] != 0) && memcmp(&pa[j], &pb[j], sizeof pa[j]) != 0) same[k] = 0;
            }
        }
        /* row k of m a power of two times row w (a perspective m with
         * z' = z, w = -z): u_k = q_k/w is that constant exactly */
        for (int k = 0; k < 3; ++k) {
            double sc = 0;
            for (int j = 0; j < 4 && sc == 0; ++j)
                if (m.m[4 * j + 3] != 0) sc = m.m[4 * j + k] / m.m[4 * j + 3];
            int e2, pow2 = sc != 0 && isfinite(sc) && fabs(frexp(sc, &e2)) == 0.5;
            for (int j = 0; j < 4 && pow2; ++j) pow2 = m.m[4 * j + k] == sc * m.m[4 * j + 3];
            if (pow2) same[k] = 1;
        }
        double wide_k = 0;
        for (int k = 0; k < 3; ++k) wide_k = fmax(wide_k, fhi[k] - flo[k]);
        for (int k = 0; k < 3; ++k) {
            double E = fhi[k] - flo[k], slack = 1024 * DBL_EPSILON * R[k];
            if (E > 0) swr_cond(c, R[k] / E);
            /* an extent within 1024 ulps of R of zero (then width 1 or the
             * widest, FLAT_EXTENT) or of the library's flat bound
             * 1e-12 max(|lo|, |hi|, widest) (focus.c, SW_FIT_FLAT_REL): which
             * side is up to the rounding -- unless E is exact (same, or
             * every term zero) */
            double mag = fmax(fmax(fabs(flo[k]), fabs(fhi[k])), wide_k);
            if (!same[k] && R[k] > 0 && (E <= slack || fabs(E - 1e-12 * mag) <= slack)) c->rounding_edge = 1;
        }
    }
    for (int k = 0; k < 3; ++k) {
        double w0 = k == 2 ? zlo : -1;
        double tol = 1e-9 + 64 * DBL_EPSILON * emax[k] * fmax(fabs(A.m[k * 5]), 1);
        SWR_CHECK_ACC(c, lo[k] >= w0 - tol && hi[k] <= 1 + tol, "axis %d: points map to [%.17g, %.17g]", k, lo[k], hi[k]);
        if (hi[k] - lo[k] > 1e-6 && c->status == SWARP_OK)
            SWR_CHECK_ACC(c, fabs(lo[k] - w0) <= tol && fabs(hi[k] - 1) <= tol, "axis %d: the fit [%.17g, %.17g] is not tight", k,
                          lo[k], hi[k]);
    }
    (void)cmax;
}

static void e_warp_lispsm(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_warp_lispsm);
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_mat4 L;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    if (!swarp_focus_light_view || swarp_status_is_error(swarp_focus_light_view(&s.cam, &s.light, NULL, &L)) ||
        !swarp_body_points ||
        swarp_status_is_error(swarp_body_points(&s.cam, s.cam.z_near, s.cam.z_far, &s.light, &s.box, pts, SWARP_BODY_MAX_POINTS, &n))) {
        /* a plain overhead light and a few points in front of the camera */
        s.cam = (swarp_camera){{0, 5, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 1.5, 1, 100, {0, 0, 0, 0}};
        L = (swarp_mat4){{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 5, 1}}; /* looks down -y */
        n = 1 + swr_u8(c) % 8;
        for (size_t i = 0; i < n; ++i) pts[i] = v3(swr_num_in(c, -50, 50, NULL, 0), swr_num_in(c, 0, 5, NULL, 0), -swr_num_in(c, 1, 100, NULL, 0));
    }
    double near = s.cam.z_near, far = s.cam.z_far;
    if (swr_one_in(c, 16)) far = swr_one_in(c, 2) ? near : NAN;
    if (swr_one_in(c, 32)) n = 0;
    if (swr_one_in(c, 32) && n) pts[swr_u8(c) % n].z = swr_num(c, -1, 1, NULL, 0);
    swarp_warp_options o;
    memset(&o, 0, sizeof o);
    o.param = (swarp_warp_param)swr_enum(c, 6);
    o.center = (swarp_warp_center)swr_enum(c, 3);
    static const double brk_u[] = {0.0, INFINITY, 1e-9};
    o.n_user = swr_num(c, 1e-3, 1e3, brk_u, 3);
    static const double brk01[] = {0.0, 0.5, 1.0};
    o.pseudo_near = swr_num(c, 0, 0.6, brk01, 3);
    o.pseudo_far = swr_num(c, 0, 0.6, brk01, 3);
    o._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use_o = !swr_one_in(c, 4), use_near = swr_one_in(c, 3);
    swarp_vec3 nearest = n ? pts[0] : s.cam.eye;
    const swarp_mat4* pL = swr_in(c, &L);
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_vec3* pp = swr_in(c, pts);
    swarp_mat4 P;
    swarp_warp_info info;
    swarp_mat4* pP = swr_out(c, &P, sizeof P, SWR_REQ);
    swarp_warp_info* pi = swr_out(c, &info, sizeof info, SWR_OPT);
    expect_parts(c, &s, 0, X_CAM);
    FIN(c, near);
    FIN(c, far);
    if (fin(near) && fin(far) && !(near > 0 && far > near)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    for (size_t i = 0; i < n; ++i) FIN(c, pts[i].z);
    if (n == 0) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT), swr_domain(c, SWARP_ERR_NULL_POINTER);
    if (use_o) {
        if ((int)o.param < 0 || (int)o.param > 6 || (int)o.center < 0 || (int)o.center > 2) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        for (int i = 0; i < 4; ++i)
            if (o._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        if ((int)o.param == 5 && !(o.n_user > 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE), swr_domain(c, SWARP_ERR_NON_FINITE);
        if ((int)o.param == 4 && !(o.pseudo_near >= 0 && o.pseudo_far >= 0 && o.pseudo_near + o.pseudo_far < 1))
            swr_expect(c, SWARP_ERR_OUT_OF_RANGE), swr_domain(c, SWARP_ERR_NON_FINITE);
        /* n_p + f_p < 1 on the rounded sum, as swarp_warp_nopt_pseudo's and
         * swarp_cascade_splits' entries: n_p = 0.5 + 1e-9 and f_p = 0.5 -
         * 1e-9 with an exact sum of 1 - 2^-54 give 1 to nearest (a tie, to
         * even: refused) and 1 - 2^-53 downward (accepted), so within an ulp
         * of 1 the rounding mode decides the status.  The exact gap in long
         * double (within 2^-64); a
         * sum of 1 or more is refused in every mode. */
        if ((int)o.param == 4 && swr_isfin(o.pseudo_near) && swr_isfin(o.pseudo_far)) {
            const long double gap = 1.0L - o.pseudo_near - o.pseudo_far;
            if (gap > 0 && gap <= 2 * DBL_EPSILON) c->rounding_edge = 1;
        }
        swr_domain(c, SWARP_ERR_OUT_OF_RANGE), swr_domain(c, SWARP_ERR_NON_FINITE);
    }
    swr_domain(c, SWARP_ERR_DEGENERATE);
    swr_domain(c, SWARP_ERR_OUT_OF_RANGE); /* n_opt of a degenerate body */
    if (s.degenerate_light) c->rounding_edge = 1;
    scene_cond(c, &s, near, far);
    /* B without extent along the warp axis (L's y) beyond the rounding of
     * its light-space y: the library warps when d = y_max - y_min > 0 (and
     * above 1e-12 of B's light-space size), and y is a sum of terms that
     * may be far larger than y (B 1e6 from the origin, near L's origin:
     * y ~ 1e-6 from terms of 1e6).  Each y is off by up to ~7 eps of its
     * terms in a directed mode, so when the exact extent is within 64 eps
     * of them the rounding decides between uniform and a full warp (e.g. two
     * points on one light ray, d = 0 to nearest,
     * 2 ulps of 1e6 under FE_UPWARD, P's entries 2 vs 8.6e9). */
    if (n >= 1 && n <= SWARP_BODY_MAX_POINTS) {
        long double ylo = INFINITY, yhi = -INFINITY, noise = 0;
        for (size_t i = 0; i < n; ++i) {
            const long double p[4] = {pts[i].x, pts[i].y, pts[i].z, 1};
            long double hy = 0, hw = 0, ty = 0, tw = 0;
            for (int k = 0; k < 4; ++k) {
                hy += (long double)L.m[4 * k + 1] * p[k], ty += fabsl((long double)L.m[4 * k + 1] * p[k]);
                hw += (long double)L.m[4 * k + 3] * p[k], tw += fabsl((long double)L.m[4 * k + 3] * p[k]);
            }
            if (!(hw != 0) || !isfinite((double)hy)) {
                noise = -1;
                break;
            }
            const long double y = hy / hw;
            ylo = fminl(ylo, y), yhi = fmaxl(yhi, y);
            noise = fmaxl(noise, (ty + fabsl(y) * tw) / fabsl(hw));
        }
        int same = 1; /* one point (or copies of it): d = 0 in every mode */
        for (size_t i = 1; i < n; ++i) same &= memcmp(&pts[i], &pts[0], sizeof pts[0]) == 0;
        if (!same && noise > 0 && yhi - ylo <= 64 * DBL_EPSILON * noise) c->rounding_edge = 1;
        /* Away from that edge the same rounding is B's conditioning: each y
         * is off by a few eps of its terms, so d = y_max - y_min by ~eps
         * noise, and P is a function of d (A = (2 + d/n)/d, w = 1 +
         * (y - y_min)/n with n = n' d / (far - near) for the caller's n';
         * n_opt, (4.2) and λ d scale with d too): P's entries move by
         * eps noise / d relative.  cond = noise / d, numerically singular
         * (> 1/(64 eps)) exactly on the edge above (e.g. seven points at 1e6,
         * light-space y of 1.4 from terms of
         * 1.6e6, d = 0.0061 moved by 1 ulp of 1e6 with the rounding mode,
         * P's w row by 2e-8 relative; cond 2.6e8). */
        if (!same && noise > 0 && yhi > ylo) swr_cond(c, (double)(noise / (yhi - ylo)));
    }
    if (!swr_done(c, SWR_CALL(c, swarp_warp_lispsm(pL, pc, near, far, pp, n, use_near ? &nearest : NULL, use_o ? &o : NULL, pP,
                                                  pi))))
        return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "P", P.m[i]);
    if (pi) {
        /* n_light, n_eye (+inf uniform) recorded as the warp strength
         * d / n_light = (far - near) / n_eye (0: uniform), as in swarp_setup's
         * entry: the map depends on 1/n continuously (w = 1 + (y - y_min)/n,
         * y - y_min in [0, d]); next to the uniform limit n is as large as
         * the rounding noise makes it (e.g. n_eye = 8.5e10
         * for a depth range of 1.4e5, n_light = 2e7 for d = 34, a strength
         * of 1.7e-6, moved by 4e-6 relative with the rounding mode: the
         * same map to 1e-11), while compared as n they differ beyond the
         * tolerance. */
        const double nn[2] = {info.n_light, info.n_eye}, rng[2] = {info.d, far - near};
        for (int k = 0; k < 2; ++k) {
            SWR_CHECK(c, nn[k] == nn[k] && nn[k] != -INFINITY, "%s = %g", k ? "n_eye" : "n_light", nn[k]);
            if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = nn[k] == INFINITY ? 0.0 : rng[k] / nn[k];
        }
        swr_rec(c, "d", info.d);
        swr_rec(c, "gamma", info.gamma);
        SWR_CHECK(c, info.n_light > 0 && info.n_eye > 0 && info.d >= 0, "n %g n' %g d %g", info.n_light, info.n_eye, info.d);
        SWR_CHECK(c, info.gamma >= 0 && info.gamma <= PI_, "gamma %g", info.gamma);
        /* gamma = angle between the view direction and the light view's axis (-z) */
        /* unit_scaled: a valid view direction of 1e-200 (or 1e300) has no
         * representable squared length (unit() left it unscaled: cg = 0) */
        double cg = dot(unit_scaled(s.cam.dir), v3(-L.m[2], -L.m[6], -L.m[10]));
        SWR_CHECK_ACC(c, fabs(cos(info.gamma) - cg) <= 1e-9, "cos gamma %.17g, view . light axis %.17g", cos(info.gamma), cg);
    }
    /* the warp is a perspective with its centre outside B: w = 1 + (y - y_min)/n >= 1 on B */
    for (size_t i = 0; i < n; ++i) {
        swarp_vec4 l = xf(&L, pts[i]);
        swarp_vec4 q = xf(&P, v3(l.x / l.w, l.y / l.w, l.z / l.w));
        /* w is evaluated here in double through L and P: at 1e6 offsets
         * with a strong warp (P's w row 5e4) the rounding of l alone moves w
         * by 1e-5, and under directed rounding (the fenv test) those errors
         * add up instead of cancelling.  The bound is the evaluation's
         * condition number, 64 eps of it, as for every other check
         * (swr_close_cond). */
        double kw = fabs(P.m[15]);
        for (int k = 0; k < 3; ++k)
            kw += fabs(P.m[4 * k + 3]) * (fabs(L.m[k] * pts[i].x) + fabs(L.m[4 + k] * pts[i].y) +
                                          fabs(L.m[8 + k] * pts[i].z) + fabs(L.m[12 + k]));
        const double wtol = 1e-9 + 64 * DBL_EPSILON * kw;
        SWR_CHECK_ACC(c, q.w >= 1 - wtol, "point %zu of B (%.17g %.17g %.17g) has w = %.17g under the warp (P w row %g %g %g %g; %s)", i,
                      pts[i].x, pts[i].y, pts[i].z, q.w, P.m[3], P.m[7], P.m[11], P.m[15], swarp_status_name(c->status));
    }
}

/* PSM fits its map in the camera's post-perspective space (PPS) [KOZ]
 * §14.2: X = P_c V_c p for the (slid-back) camera, so with q = p - eye', the
 * depth d = f·q + delta and t_x, t_y the half-view tangents, B's PPS
 * coordinates are x = (r·q)/(t_x d), y = (u·q)/(t_y d), z = a - b/d
 * (a = (f' + n')/(f' - n'), b = 2 f' n'/(f' - n'), n' = near + delta,
 * f' = far + delta).  q is formed from world coordinates and carries eps M
 * of rounding (M: the largest of p's and the eye's coordinates), so each PPS
 * coordinate carries eps M times its derivative in q -- at most
 * (1/t_x + |x|)/d for x, (1/t_y + |y|)/d for y, b/d^2 for z -- plus a few
 * eps of its own size from the projection and the divide by w (|a - b/d|
 * for z: the constant a is rounded in with it).  Against B's
 * extent in PPS (a point light with it: the light's cone is formed from
 * differences with its PPS position) that is the condition number of what
 * the fit, the light's cone and its axis are computed from.  B far beyond
 * the far plane squeezes its PPS depths into b Δd/d^2 (e.g. B 1.7e6 deep with
 * far = 301, the PPS z of
 * B and the light within 4.4e-11 of 1.01, cond 2.3e10; light_proj's y row
 * moved by 1.5e-5 relative with the rounding mode). */
typedef struct {
    swarp_vec3 eye, f, r, u;
    long double delta, a, b, tx, ty;
} pps_cam;

/* p's PPS coordinates v (z without the constant a) and their rounding R (in
 * units of eps, see psm_pps_cond); 0 behind the slid-back eye */
static int pps_point(const pps_cam* k, swarp_vec3 p, long double v[3], long double R[3]) {
    const long double qx = (long double)p.x - k->eye.x, qy = (long double)p.y - k->eye.y, qz = (long double)p.z - k->eye.z;
    const long double d = qx * k->f.x + qy * k->f.y + qz * k->f.z + k->delta;
    if (!(d > 0)) return 0;
    const long double M = fmaxl(fmaxl(fmaxl(fabsl(p.x), fabsl(p.y)), fabsl(p.z)),
                                fmaxl(fmaxl(fabsl(k->eye.x), fabsl(k->eye.y)), fabsl(k->eye.z)));
    const long double x = (qx * k->r.x + qy * k->r.y + qz * k->r.z) / (k->tx * d),
                      y = (qx * k->u.x + qy * k->u.y + qz * k->u.z) / (k->ty * d), z = -k->b / d;
    v[0] = x, v[1] = y, v[2] = z;
    R[0] = M * (1 / k->tx + fabsl(x)) / d + fabsl(x);
    R[1] = M * (1 / k->ty + fabsl(y)) / d + fabsl(y);
    R[2] = M * k->b / (d * d) + fabsl(k->a + z);
    return 1;
}

static void psm_pps_cond(swr_ctx* c, const scene_args* s, const swarp_vec3* pts, size_t n, const swarp_vec3* H, size_t nh) {
    const swarp_camera* cam = &s->cam;
    const double near = cam->z_near, far = cam->z_far;
    if (!(s->use_opt && s->opt.technique == SWARP_TECHNIQUE_PSM) || n == 0 || n > SWARP_BODY_MAX_POINTS) return;
    if (!(near > 0 && far > near && isfinite(far)) || !fin3(&cam->eye) || !fin(cam->fovy) || !fin(cam->aspect) ||
        !fin(s->opt.slideback))
        return;
    pps_cam k;
    k.eye = cam->eye;
    k.f = unit_scaled(cam->dir), k.r = unit_scaled(cross(k.f, cam->up)), k.u = cross(k.r, k.f);
    k.delta = s->opt.slideback;
    if (s->opt.psm_slideback && k.delta == 0) { /* src/geometry/psm.c: automatic slide-back */
        long double zmin = INFINITY;
        for (size_t i = 0; i < n; ++i) zmin = fminl(zmin, dot(v3(pts[i].x - cam->eye.x, pts[i].y - cam->eye.y, pts[i].z - cam->eye.z), k.f));
        if (zmin < near) k.delta = near - zmin;
    }
    const long double nn = near + k.delta, fa = far + k.delta;
    k.b = 2 * fa * nn / (fa - nn), k.a = (fa + nn) / (fa - nn);
    k.ty = tanl(0.5L * cam->fovy), k.tx = k.ty * cam->aspect;
    if (!(k.ty > 0 && k.tx > 0 && isfinite((double)k.b))) return;
    const int point = (int)s->light.type == SWARP_LIGHT_POINT && fin3(&s->light.position);
    long double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, R[3] = {0, 0, 0};
    for (size_t i = 0; i < n + (size_t)point; ++i) {
        long double v[3], e[3];
        if (!pps_point(&k, i < n ? pts[i] : s->light.position, v, e)) continue;
        for (int j = 0; j < 3; ++j) {
            lo[j] = fminl(lo[j], v[j]), hi[j] = fmaxl(hi[j], v[j]);
            R[j] = fmaxl(R[j], e[j]);
        }
    }
    for (int j = 0; j < 3; ++j)
        if (hi[j] > lo[j] && isfinite((double)(R[j] / (hi[j] - lo[j])))) swr_cond(c, (double)(R[j] / (hi[j] - lo[j])));
    /* The light's cone [KOZ] §14.2.2 is the smallest cap around the
     * directions from the light to the receivers H (B without H), formed in
     * PPS: a receiver at PPS distance δ from the light has its direction
     * rounded to eps (R_light + R_receiver)/δ, and the cap (the map's axis
     * and opening) moves with it (e.g. a vertex of B near a point light 2
     * units from the eye at 3e6,
     * the cap's centre 5e-5 different by rounding mode). */
    long double vl[3], el[3];
    if (!point || !pps_point(&k, s->light.position, vl, el)) return;
    const swarp_vec3* rc = H && nh ? H : pts;
    const size_t nrc = H && nh ? nh : n;
    for (size_t i = 0; i < nrc && i < SWARP_BODY_MAX_POINTS; ++i) {
        long double v[3], e[3];
        if (!pps_point(&k, rc[i], v, e)) continue;
        const long double dx = v[0] - vl[0], dy = v[1] - vl[1], dz = v[2] - vl[2], dist = sqrtl(dx * dx + dy * dy + dz * dz);
        const long double noise = sqrtl(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) + sqrtl(el[0] * el[0] + el[1] * el[1] + el[2] * el[2]);
        if (dist > 0 && isfinite((double)(noise / dist))) swr_cond(c, (double)(noise / dist));
    }
}

static void e_setup_points(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_setup_points);
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS + 1], rcv[SWARP_BODY_MAX_POINTS];
    size_t n = 0, nr = 0;
    /* the box only bounds the points here: a valid one */
    if (!fin3(&s.box.min) || !fin3(&s.box.max) || s.box.min.x > s.box.max.x || s.box.min.y > s.box.max.y ||
        s.box.min.z > s.box.max.z)
        s.box = (swarp_aabb){{-10, -10, -10}, {10, 10, 10}};
    if (!swarp_body_points ||
        swarp_status_is_error(swarp_body_points(&s.cam, s.cam.z_near, s.cam.z_far, &s.light, &s.box, pts, SWARP_BODY_MAX_POINTS, &n))) {
        n = 1 + swr_u8(c) % 12; /* points in the box */
        for (size_t i = 0; i < n; ++i)
            pts[i] = v3(s.box.min.x + swr_num_in(c, 0, 1, NULL, 0) * (s.box.max.x - s.box.min.x),
                        s.box.min.y + swr_num_in(c, 0, 1, NULL, 0) * (s.box.max.y - s.box.min.y),
                        s.box.min.z + swr_num_in(c, 0, 1, NULL, 0) * (s.box.max.z - s.box.min.z));
    }
    if (swr_one_in(c, 2)) {
        swarp_polyhedron H;
        if (swarp_body_h && swarp_body_h(&s.cam, s.cam.z_near, s.cam.z_far, &s.box, &H) == SWARP_OK) {
            nr = H.vertex_count;
            memcpy(rcv, H.vertices, nr * sizeof rcv[0]);
        }
    }
    if (swr_one_in(c, 32)) n = swr_one_in(c, 2) ? 0 : SWARP_BODY_MAX_POINTS + 1;
    const swarp_light* pl = swr_in(c, &s.light);
    const swarp_vec3* pp = swr_in(c, pts);
    swarp_setup_result r;
    const swarp_camera* pc = swr_in(c, &s.cam);
    swarp_setup_result* pr = swr_out(c, &r, sizeof r, SWR_REQ);
    expect_parts(c, &s, 0, X_CAM | X_LIGHT | X_OPT | X_GEOM);
    if (!fin(s.cam.z_near) || !fin(s.cam.z_far)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (!(s.cam.z_near > 0 && s.cam.z_far > s.cam.z_near)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    if (n == 0 || n > SWARP_BODY_MAX_POINTS) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT), swr_domain(c, SWARP_ERR_NULL_POINTER);
    scene_cond(c, &s, s.cam.z_near, s.cam.z_far);
    psm_pps_cond(c, &s, pts, n, nr ? rcv : NULL, nr);
    swr_args(c, "n %zu p0 (%g %g %g) nr %zu near %g far %g tech %d param %d n_user %g pseudo %g %g slideback %g", n, pts[0].x, pts[0].y,
             pts[0].z, nr, s.cam.z_near, s.cam.z_far, s.use_opt ? (int)s.opt.technique : -1, (int)s.opt.param, s.opt.n_user,
             s.opt.pseudo_near, s.opt.pseudo_far, s.opt.slideback);
    swarp_status st = SWR_CALL(c, swarp_setup_points(pc, pl, pp, n, nr ? rcv : NULL, nr, s.cam.z_near, s.cam.z_far,
                                                    s.use_opt ? &s.opt : NULL, pr));
    if (!swr_done(c, st)) return;
    check_setup_result(c, &s, st, &r, pts, n, 1);
}

SWR_WEAK(swarp_cascade_setup)

/* [RHS] §3.3-3.4: the cascade's one call.  Properties: split_count splits,
 * C_0 = view_near < C_1 < ... < C_m = view_far, each split's [near, far] =
 * [C_i, C_{i+1}], the configuration's maxima = the largest split maxima,
 * finite matrices, tiles inside the atlas. */
/* The conditioning of a split's map: at the world points the map sends to
 * its corners, edge midpoints and centre (clip x, y in {-1, 0, 1}, depth 0
 * and 0.5), the terms of each clip coordinate over |w|.  The fit's scale and
 * translation come from light-space coordinates resolved to eps of such
 * terms against B's extent, so this is the condition number of the matrix
 * elements (a split at a 3e6 offset, a light grazing a flat box). */
static double split_map_cond(const swarp_mat4* m) {
    swarp_mat4 inv;
    if (swarp_status_is_error(swarp_mat4_invert(m, &inv))) return 0;
    double k = 0;
    for (int i = 0; i < 18; ++i) {
        double hx = i % 3 - 1.0, hy = (i / 3) % 3 - 1.0, hz = i < 9 ? 0.0 : 0.5;
        double h[4];
        for (int r = 0; r < 4; ++r) h[r] = inv.m[r] * hx + inv.m[4 + r] * hy + inv.m[8 + r] * hz + inv.m[12 + r];
        if (!(h[3] != 0)) continue;
        swarp_vec3 p = v3(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
        if (!fin3(&p)) continue;
        swarp_vec4 q = xf(m, p);
        if (!(fabs(q.w) > 0)) continue;
        double sw = fabs(m->m[3] * p.x) + fabs(m->m[7] * p.y) + fabs(m->m[11] * p.z) + fabs(m->m[15]);
        for (int row = 0; row < 3; ++row) {
            double sr = fabs(m->m[row] * p.x) + fabs(m->m[4 + row] * p.y) + fabs(m->m[8 + row] * p.z) + fabs(m->m[12 + row]);
            k = fmax(k, (sr + sw) / fabs(q.w));
        }
    }
    return k;
}

/* A box as thin along an axis as the clipper's tolerance for "on a
 * plane", SWARP_POLY_EPS_REL of the clipped polyhedron's scale (between
 * the box's own scale and that of B's sweep: T = 2 diag(S) more for a
 * directional light, the light's position for a point light): clipping by
 * its second face of that axis classifies the first face's vertices as on
 * it or inside by the rounding of their distance (a few eps of the
 * coordinates, 16 eps / 1e-12 = 3.6e-3 of the tolerance), and B collapses
 * onto the first face or keeps its 1e-12-thin extent, its depth range
 * 1e-6 different at 1e6 (e.g. a
 * box 1.00001e-6 thick at 1.00007e6, tolerance 1.00007e-6; the depth row of
 * split 0 moved 7e-7 relative under FE_UPWARD).  A documented threshold
 * (the header's "never leaves two vertices closer"); an exactly flat box
 * (extent 0) is on its plane in every mode. */
static int box_at_merge_distance(const scene_args* s) {
    const swarp_aabb* b = &s->box;
    if (!fin3(&b->min) || !fin3(&b->max)) return 0;
    const long double e[3] = {(long double)b->max.x - b->min.x, (long double)b->max.y - b->min.y, (long double)b->max.z - b->min.z};
    const long double X0 = box_scale(b);
    long double X1 = X0;
    if ((int)s->light.type == 2) X1 = fmaxl(X1, vmax(s->light.position));
    else X1 += 2 * sqrtl(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const long double slack = 16 * DBL_EPSILON / SWARP_POLY_EPS_REL;
    for (int k = 0; k < 3; ++k)
        if (e[k] > 0 && e[k] >= SWARP_POLY_EPS_REL * X0 * (1 - slack) && e[k] <= SWARP_POLY_EPS_REL * X1 * (1 + slack)) return 1;
    return 0;
}

static void e_cascade_setup(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_setup);
    scene_args s;
    gen_setup_scene(c, &s);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    if (s.use_opt) o.setup = s.opt;
    o.split.count = swr_one_in(c, 16) ? 17 + swr_u8(c) % 4 : swr_u8(c) % 9;
    o.split.scheme = (swarp_split_scheme)swr_enum(c, 5);
    static const double brk01[] = {0.0, 1.0, 0.5};
    o.split.lambda = swr_num(c, 0, 1, brk01, 3);
    o.split.pseudo_near = swr_num_in(c, 0, 0.3, brk01, 1);
    o.split.pseudo_far = swr_num_in(c, 0, 0.3, brk01, 1);
    o.split._reserved[swr_u8(c) % 4] = swr_reserved(c);
    if (swr_one_in(c, 4)) { /* stabilised: needs UNIFORM and a directional light */
        o.stabilize.mode = (swarp_stabilize_mode)swr_enum(c, 4);
        if (swr_one_in(c, 2)) o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
        o.stabilize.origin = v3(swr_offset(c), 0, swr_offset(c));
    }
    o.kernel_world_size = swr_one_in(c, 2) ? 0 : swr_num(c, 0, 10, brk01, 1);
    for (int i = 0; i < 4; ++i) o.n_user[swr_u8(c) % SWARP_CASCADE_MAX_SPLITS] = swr_one_in(c, 2) ? 0 : swr_num(c, 0, 100, brk01, 1);
    o.warp_per_split = (swarp_cascade_warp)swr_enum(c, 3);
    o._reserved[swr_u8(c) % 3] = swr_reserved(c);
    int use_o = !swr_one_in(c, 6);
    uint32_t K = use_o && o.split.count ? o.split.count : 4;
    size_t cap = swr_one_in(c, 10) ? swr_u8(c) % 8 : SWARP_CASCADE_MAX_SPLITS;
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_light* pl = swr_in(c, &s.light);
    const swarp_aabb* pb = swr_in(c, &s.box);
    swarp_cascade_result r;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t count;
    swarp_cascade_result* pr = swr_out(c, &r, sizeof r, SWR_REQ);
    swarp_cascade_split* psp = swr_out(c, sp, sizeof sp, cap ? SWR_REQ : SWR_OPT);
    size_t* pcount = swr_out(c, &count, sizeof count, SWR_REQ);
    s.opt = o.setup; /* what the call sees (technique may be UNIFORM now) */
    s.use_opt = use_o;
    expect_scene(c, &s, 1);
    if (use_o) {
        for (int i = 0; i < 3; ++i)
            if (o._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        for (int i = 0; i < 4; ++i)
            if (o.split._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        if ((int)o.warp_per_split < 0 || (int)o.warp_per_split > 2 || (int)o.split.scheme < 0 || (int)o.split.scheme > 5 ||
            (int)o.stabilize.mode < 0 || (int)o.stabilize.mode > 3)
            swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        if (o.split.count > SWARP_CASCADE_MAX_SPLITS) swr_expect(c, SWARP_ERR_SPLIT_COUNT);
        if (!fin(o.kernel_world_size) || !fin(o.split.lambda)) swr_domain(c, SWARP_ERR_NON_FINITE);
        static const swarp_status dom[] = {SWARP_ERR_OUT_OF_RANGE, SWARP_ERR_STABILIZE_WARPED, SWARP_ERR_STABILIZE_LIGHT,
                                           SWARP_ERR_RESOLUTION};
        for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
        /* documented (the errors of swarp_stabilize_directional): the
         * stabilised sphere or matrix beyond DBL_MAX (far 1e306, aspect
         * DBL_MAX) */
        if ((int)o.stabilize.mode != 0) swr_domain(c, SWARP_ERR_OVERFLOW);
        /* SWARP_SCHEME_MEASURED with stabilisation (ranges that must not move) */
        if ((int)o.split.scheme == 5 && (int)o.stabilize.mode != 0) swr_domain(c, SWARP_ERR_INVALID_ARGUMENT);
    }
    if (K <= SWARP_CASCADE_MAX_SPLITS && cap < K) swr_expect(c, SWARP_ERR_CAPACITY);
    if (!psp && cap == 0) swr_domain(c, SWARP_ERR_CAPACITY);
    swr_domain(c, SWARP_ERR_SPLIT_EMPTY), swr_domain(c, SWARP_ERR_NEAR_FAR), swr_domain(c, SWARP_ERR_NON_FINITE);
    scene_cond(c, &s, s.cam.z_near, s.cam.z_far);
    if (box_at_merge_distance(&s)) c->rounding_edge = 1;
    swr_args(c, "K %u scheme %d stabilize %d warp_per_split %d technique %d param %d center %d depth %d reserved: cam %u %u %u %u light %u %u %u %u %u setup %u %u split %u %u %u %u cascade %u %u %u use_o %d",
             K, (int)o.split.scheme, (int)o.stabilize.mode, (int)o.warp_per_split, (int)o.setup.technique, (int)o.setup.param,
             (int)o.setup.center, (int)o.setup.depth_range, s.cam._reserved[0], s.cam._reserved[1], s.cam._reserved[2],
             s.cam._reserved[3], s.light._reserved0, s.light._reserved[0], s.light._reserved[1], s.light._reserved[2],
             s.light._reserved[3], o.setup.skip_measure, o.setup._reserved[0], o.split._reserved[0], o.split._reserved[1],
             o.split._reserved[2], o.split._reserved[3], o._reserved[0], o._reserved[1], o._reserved[2], use_o);
    swarp_status st = SWR_CALL(c, swarp_cascade_setup(pc, pl, pb, use_o ? &o : NULL, pr, psp, cap, pcount));
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, count == K, "CAPACITY with count %zu, K %u", count, K);
        swr_fill(&count, sizeof count);
    }
    if (!swr_done(c, st)) return;
    SWR_CHECK(c, count == K && r.split_count == K, "count %zu, split_count %u, K %u", count, r.split_count, K);
    if (count != K || K > SWARP_CASCADE_MAX_SPLITS) return;
    swr_rec(c, "view_near", r.view_near), swr_rec(c, "view_far", r.view_far);
    SWR_CHECK(c, r.splits[0] == r.view_near && r.splits[K] == r.view_far, "C_0 %.17g C_m %.17g, view [%.17g, %.17g]", r.splits[0],
              r.splits[K], r.view_near, r.view_far);
    double mx = 0, mz = 0;
    for (uint32_t i = 0; i < K; ++i) {
        const swarp_cascade_split* q = &sp[i];
        SWR_CHECK(c, r.splits[i + 1] > r.splits[i], "splits not increasing at %u", i);
        SWR_CHECK(c, q->z_near == r.splits[i] && q->z_far == r.splits[i + 1], "split %u [%g, %g], C [%g, %g]", i, q->z_near, q->z_far,
                  r.splits[i], r.splits[i + 1]);
        for (int e = 0; e < 16; ++e) swr_rec(c, "matrix", q->matrix.m[e]), swr_rec(c, "atlas_matrix", q->atlas_matrix.m[e]);
        /* n' recorded as the split's warp strength (far - near)/n' (0: a
         * uniform split, n' = +inf, documented per split), as swarp_setup's
         * entry records it (see check_setup_result): the split's map depends
         * on 1/n' continuously (w = 1 + (y - y_min)/n'), and next to the
         * uniform limit n' is as large as the rounding makes it.  Compared as
         * n' (no options: n' = 3.2e8, 4.9e8 and
         * 1.4e9 for splits 1-3, moved 1e-8 relative by the rounding mode)
         * it failed the tolerance while the splits' matrices agreed to it. */
        if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = q->n_eye == INFINITY ? 0.0 : (q->z_far - q->z_near) / q->n_eye;
        SWR_CHECK(c, q->n_eye > 0, "split %u n_eye %g", i, q->n_eye);
        swr_rec(c, "max_mx", q->max_mx), swr_rec(c, "max_mz", q->max_mz);
        SWR_CHECK(c, !swarp_status_is_error(q->status), "split %u status %s", i, swarp_status_name(q->status));
        mx = fmax(mx, q->max_mx), mz = fmax(mz, q->max_mz);
        double atlas = r.atlas.atlas_res;
        SWR_CHECK(c, q->tile.viewport_x >= 0 && q->tile.viewport_y >= 0 && q->tile.viewport_x + q->tile.viewport_width <= atlas &&
                         q->tile.viewport_y + q->tile.viewport_height <= atlas,
                  "tile %u outside the atlas", i);
    }
    /* raised after the checks, for the fenv comparison (e.g. matrix
     * translations moved 1e-6..5e-4 of the outputs
     * by the rounding mode, within this conditioning) */
    for (uint32_t i = 0; i < K; ++i) swr_cond(c, split_map_cond(&sp[i].matrix));
    /* the configuration's maxima are the largest of the splits' */
    SWR_CHECK(c, r.max_mx == mx && r.max_mz == mz, "max_mx %.17g max_mz %.17g, splits' %.17g %.17g", r.max_mx, r.max_mz, mx, mz);
    if (K < SWARP_CASCADE_MAX_SPLITS) SWR_CHECK(c, swr_untouched(sp + K, sizeof sp - K * sizeof sp[0]), "wrote past count");
}

/* ------------------------------------------------------------------------ */
/* coherent light frames over time (src/geometry/follow.c)                           */
/* ------------------------------------------------------------------------ */
SWR_WEAK(swarp_setup_follow)
SWR_WEAK(swarp_focus_light_view_follow)

/* The previous frame: the scene with the light turned by an angle (0, 1e-9,
 * small, large) and the camera turned too; its camera and light in *p. */
static void gen_previous_scene(swr_ctx* c, const scene_args* s, scene_args* p) {
    *p = *s;
    static const double brk[] = {0.0, 1e-9, 1e-6};
    double dl = swr_one_in(c, 4) ? swr_num_in(c, 0, PI_, brk, 3) : swr_num_in(c, 0, 0.05, brk, 3);
    double dc = swr_one_in(c, 2) ? 0 : swr_num_in(c, 0, 0.05, brk, 3);
    if (fin3(&s->light.direction) && vmax(s->light.direction) > 0) p->light.direction = tilt(unit(s->light.direction), dl);
    p->light.position.x += swr_num_in(c, -1, 1, NULL, 0) * dl;
    if (fin3(&s->cam.dir) && vmax(s->cam.dir) > 0) p->cam.dir = tilt(unit(s->cam.dir), dc);
}
/* A previous light view whose rotation rows are broken: NaN, a zero row, not
 * orthonormal, left-handed; the status each calls for. */
static void corrupt_rows(swr_ctx* c, swarp_mat4* V) {
    if (!swr_one_in(c, 12)) return;
    int r = swr_u8(c) % 3;
    switch (swr_u8(c) % 4) {
        case 0: V->m[4 * (swr_u8(c) % 3) + r] = NAN, swr_expect(c, SWARP_ERR_NON_FINITE); break;
        case 1: V->m[r] = V->m[4 + r] = V->m[8 + r] = 0, swr_expect(c, SWARP_ERR_ZERO_VECTOR), swr_domain(c, SWARP_ERR_FOLLOW_FRAME); break;
        case 2: V->m[r] *= 1.1, V->m[4 + r] *= 1.1, V->m[8 + r] *= 1.1, swr_expect(c, SWARP_ERR_FOLLOW_FRAME); break;
        default: V->m[r] = -V->m[r], V->m[4 + r] = -V->m[4 + r], V->m[8 + r] = -V->m[8 + r], swr_expect(c, SWARP_ERR_FOLLOW_FRAME); break;
    }
}
static double angle_between(swarp_vec3 a, swarp_vec3 b) {
    a = unit(a), b = unit(b);
    return 2 * atan2(sqrt(dot(v3(a.x - b.x, a.y - b.y, a.z - b.z), v3(a.x - b.x, a.y - b.y, a.z - b.z))),
                     sqrt(dot(v3(a.x + b.x, a.y + b.y, a.z + b.z), v3(a.x + b.x, a.y + b.y, a.z + b.z))));
}
/* The follow rule's bound: the new up (row 1) is the previous up, projected
 * normal to the new axis, turned by at most SWARP_FOLLOW_KAPPA (angle the
 * axis turned + angle the view direction turned) */
static void check_follow_bound(swr_ctx* c, const swarp_mat4* V, const swarp_mat4* P, swarp_vec3 dir_prev, swarp_vec3 dir) {
    swarp_vec3 a = v3(-V->m[2], -V->m[6], -V->m[10]), ap = v3(-P->m[2], -P->m[6], -P->m[10]);
    swarp_vec3 up = v3(V->m[1], V->m[5], V->m[9]), upp = v3(P->m[1], P->m[5], P->m[9]);
    double k = dot(upp, a);
    swarp_vec3 h = v3(upp.x - k * a.x, upp.y - k * a.y, upp.z - k * a.z);
    if (sqrt(dot(h, h)) < 1e-3) return; /* the previous up along the new axis: no direction to keep */
    double delta = angle_between(ap, a) + angle_between(dir_prev, dir);
    double turned = angle_between(h, up);
    SWR_CHECK_ACC(c, turned <= SWARP_FOLLOW_KAPPA * delta + 1e-6, "the up vector turned %.9g rad, the bound is %g x %.9g", turned,
                  SWARP_FOLLOW_KAPPA, delta);
}

/* The condition of a followed light frame's up vector (src/geometry/follow.c,
 * sw_follow_light_view): it is t = v_perp/|v_perp| (the view direction
 * projected normal to the light axis a, [RHS] §3.2.1) when the frame
 * follows the target, else h = the previous up projected normal to a,
 * turned by the budget (SWARP_INFO_FOLLOW_LAG) or kept (v along a).  a and v
 * carry a rounding of eps (normalized), so the projection carries an
 * absolute eps and its direction eps/|projection|: cond = 1/sin(angle).  The
 * library uses a projection only above 1e-8 (cond <= 1e8).  Near γ = 0
 * the stateless light view blends (cond bounded); the follow rule does not:
 * e.g. an omni light 3e-4 from an eye at 1e6 looking back along the view, sin γ = 2e-8, rows drifted 3e-9. */
static void follow_cond(swr_ctx* c, const swarp_mat4* V, const swarp_mat4* P, swarp_vec3 dir) {
    swarp_vec3 a = v3(-V->m[2], -V->m[6], -V->m[10]), upp = v3(P->m[1], P->m[5], P->m[9]), v = unit_scaled(dir);
    double kv = dot(v, a), kh = dot(upp, a);
    double sv = sqrt(dot(v3(v.x - kv * a.x, v.y - kv * a.y, v.z - kv * a.z), v3(v.x - kv * a.x, v.y - kv * a.y, v.z - kv * a.z)));
    double sh = sqrt(dot(v3(upp.x - kh * a.x, upp.y - kh * a.y, upp.z - kh * a.z), v3(upp.x - kh * a.x, upp.y - kh * a.y, upp.z - kh * a.z)));
    int have_t = sv > 1e-8, have_h = sh > 1e-8;
    /* a projection within its rounding (a few eps absolute, 64 eps here) of
     * the library's 1e-8: whether it is used (the up jumps) is up to the
     * rounding */
    if (fabs(sv - 1e-8) <= 64 * DBL_EPSILON || fabs(sh - 1e-8) <= 64 * DBL_EPSILON) c->rounding_edge = 1;
    if (have_t && c->status != SWARP_INFO_FOLLOW_LAG) swr_cond(c, 1 / sv);
    else if (have_h) swr_cond(c, 1 / sh);
}

/* The rounding of a followed frame's rows in units of eps (src/geometry/follow.c):
 * the up row is the direction of a projection normal to the axis a, of t
 * (the view direction's, length s_t) when the frame follows the target,
 * else of h (the previous up's, s_h: lagging, or kept); a and the unit
 * vectors projected carry eps each, so the direction eps/s.  Whether the
 * frame followed t is read from the result (its up along ±t), as the
 * status may carry another info.  The right row is up x axis.  (e.g. a
 * directional light 1e-7 off the view direction over a flat
 * box in the eye's plane, s_t = 1e-7; B's light-space y extent is 1e-7 of
 * its length, and the up row's 6e-11 of rounding moved light_proj's y scale
 * by 1.4e-4 relative.) */
static double follow_up_cond(const swarp_mat4* V, const swarp_mat4* P, swarp_vec3 dir) {
    swarp_vec3 a = v3(-V->m[2], -V->m[6], -V->m[10]), upp = v3(P->m[1], P->m[5], P->m[9]), v = unit_scaled(dir);
    swarp_vec3 up = v3(V->m[1], V->m[5], V->m[9]);
    double kv = dot(v, a), kh = dot(upp, a);
    swarp_vec3 t = v3(v.x - kv * a.x, v.y - kv * a.y, v.z - kv * a.z), h = v3(upp.x - kh * a.x, upp.y - kh * a.y, upp.z - kh * a.z);
    double st = sqrt(dot(t, t)), sh = sqrt(dot(h, h));
    /* the library's cut-off for a usable projection (1e-8) */
    if (st > 1e-8 && fabs(dot(up, t)) >= st * (1 - 1e-6)) return 1 / st;
    if (sh > 1e-8) return 1 / sh;
    return 1;
}

static void e_setup_follow(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_setup_follow);
    scene_args s, p;
    gen_setup_scene(c, &s);
    gen_previous_scene(c, &s, &p);
    const swarp_setup_options* po = s.use_opt ? &s.opt : NULL;
    swarp_setup_result prev;
    int have_prev = !swr_one_in(c, 4) && !swarp_status_is_error(swarp_setup(&p.cam, &p.light, &p.box, po, &prev, NULL, 0, NULL));
    int use_pcam = swr_one_in(c, 2);
    if (have_prev) corrupt_rows(c, &prev.light_view);
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_light* pl = swr_in(c, &s.light);
    const swarp_aabb* pb = swr_in(c, &s.box);
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t count;
    swarp_setup_result* pr = swr_out(c, &r, sizeof r, SWR_REQ);
    swarp_vec3* pp = swr_out(c, pts, sizeof pts, SWR_NONULL);
    size_t* pn = swr_out(c, &count, sizeof count, SWR_NONULL);
    expect_scene(c, &s, 1);
    swr_domain(c, SWARP_ERR_CAPACITY), swr_domain(c, SWARP_ERR_FOLLOW_FRAME); /* PSM: a previous light camera out of range */
    scene_cond(c, &s, s.cam.z_near, s.cam.z_far);
    swr_args(c, "eye=(%.17g %.17g %.17g) dir=(%g %g %g) near=%g far=%g light %d dir=(%g %g %g) pos=(%.9g %.9g %.9g) cone %g box=(%.17g %.17g %.17g)-(%.17g %.17g %.17g) tech %d prev %d pcam %d",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, s.cam.z_near, s.cam.z_far, (int)s.light.type,
             s.light.direction.x, s.light.direction.y, s.light.direction.z, s.light.position.x, s.light.position.y,
             s.light.position.z, s.light.cone_angle, s.box.min.x, s.box.min.y, s.box.min.z, s.box.max.x, s.box.max.y, s.box.max.z,
             s.use_opt ? (int)s.opt.technique : -1, have_prev, use_pcam);
    swarp_status st = SWR_CALL(c, swarp_setup_follow(pc, pl, pb, po, use_pcam ? &p.cam : NULL, have_prev ? &prev : NULL, pr, pp,
                                                    SWARP_BODY_MAX_POINTS, pn));
    if (!swr_done(c, st)) return;
    check_setup_result(c, &s, st, &r, pts, count, 1);
    /* a followed frame's rows (PSM follows its previous map otherwise) */
    if (have_prev && !(s.use_opt && s.opt.technique == SWARP_TECHNIQUE_PSM) && st != SWARP_INFO_PSM_INVERSE)
        setup_b_cond_rows(c, &s, st, &r, pts, count, follow_up_cond(&r.light_view, &prev.light_view, s.cam.dir));
    if (!have_prev) { /* "NULL: exactly swarp_setup's result (bit for bit)" */
        swarp_setup_result q;
        memset(&q, 0, sizeof q);
        swarp_status sq = SWR_CALL(c, swarp_setup(&s.cam, &s.light, &s.box, po, &q, NULL, 0, NULL));
        SWR_CHECK(c, sq == st && memcmp(&q.matrix, &r.matrix, sizeof q.matrix) == 0 && q.n_eye == r.n_eye,
                  "previous NULL: %s and a matrix other than swarp_setup's (%s)", swarp_status_name(st), swarp_status_name(sq));
    } else if (!(s.use_opt && s.opt.technique == SWARP_TECHNIQUE_PSM) && st != SWARP_INFO_PSM_INVERSE) {
        check_follow_bound(c, &r.light_view, &prev.light_view, use_pcam ? p.cam.dir : s.cam.dir, s.cam.dir);
    }
}

static void e_focus_light_view_follow(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_focus_light_view_follow);
    scene_args s, p;
    gen_setup_scene(c, &s);
    gen_previous_scene(c, &s, &p);
    swarp_mat4 prev;
    memset(&prev, 0, sizeof prev);
    int have_prev = !swr_one_in(c, 4) && swarp_focus_light_view &&
                    !swarp_status_is_error(swarp_focus_light_view(&p.cam, &p.light, NULL, &prev));
    int use_pcam = swr_one_in(c, 2);
    /* a previous view that is not finite (swarp_focus_light_view on an
     * extreme input: a finding of that entry) is not a valid "previous" */
    for (int i = 0; i < 16 && have_prev; ++i) have_prev = fin(prev.m[i]);
    if (have_prev) corrupt_rows(c, &prev);
    const swarp_camera* pc = swr_in(c, &s.cam);
    const swarp_light* pl = swr_in(c, &s.light);
    swarp_mat4 V;
    swarp_mat4* pv = swr_out(c, &V, sizeof V, SWR_REQ);
    expect_parts(c, &s, 0, X_CAM | X_LIGHT);
    swr_domain(c, SWARP_ERR_ZERO_VECTOR), swr_domain(c, SWARP_ERR_DEGENERATE), swr_domain(c, SWARP_ERR_NEAR_FAR);
    swr_domain(c, SWARP_ERR_OVERFLOW); /* documented: an origin ~DBL_MAX, translation beyond DBL_MAX */
    swr_args(c, "eye (%g %g %g) dir (%g %g %g) up (%g %g %g) light %d dir (%g %g %g) pos (%g %g %g) cone %g prev %d rows (%g %g %g / %g %g %g / %g %g %g) pcam %d",
             s.cam.eye.x, s.cam.eye.y, s.cam.eye.z, s.cam.dir.x, s.cam.dir.y, s.cam.dir.z, s.cam.up.x, s.cam.up.y, s.cam.up.z,
             (int)s.light.type, s.light.direction.x, s.light.direction.y, s.light.direction.z, s.light.position.x,
             s.light.position.y, s.light.position.z, s.light.cone_angle, have_prev, prev.m[0], prev.m[4], prev.m[8], prev.m[1],
             prev.m[5], prev.m[9], prev.m[2], prev.m[6], prev.m[10], use_pcam);
    if (!swr_done(c, SWR_CALL(c, swarp_focus_light_view_follow(pc, pl, NULL, use_pcam ? &p.cam : NULL, have_prev ? &prev : NULL, pv))))
        return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "view", V.m[i]);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            SWR_CHECK(c, fabs(dot(row3(&V, a), row3(&V, b)) - (a == b)) <= 1e-12, "rows %d, %d not orthonormal", a, b);
    SWR_CHECK(c, dot(cross(row3(&V, 0), row3(&V, 1)), row3(&V, 2)) > 0, "left-handed light view");
    if (!have_prev) { /* "NULL: exactly swarp_focus_light_view" */
        swarp_mat4 q;
        swarp_status sq = SWR_CALL(c, swarp_focus_light_view(&s.cam, &s.light, NULL, &q));
        SWR_CHECK(c, sq == c->status && memcmp(&q, &V, sizeof q) == 0, "previous NULL: not swarp_focus_light_view's view");
    } else {
        check_follow_bound(c, &V, &prev, use_pcam ? p.cam.dir : s.cam.dir, s.cam.dir);
        follow_cond(c, &V, &prev, s.cam.dir);
    }
}

const swr_entry swr_entries_geometry[] = {
    {"swarp_setup", "geometry", e_setup},
    {"swarp_setup_range", "geometry", e_setup_range},
    {"swarp_body_points", "geometry", e_body_points},
    {"swarp_poly_from_aabb", "geometry", e_poly_from_aabb},
    {"swarp_poly_from_camera_range", "geometry", e_poly_from_camera_range},
    {"swarp_poly_from_camera", "geometry", e_poly_from_camera},
    {"swarp_poly_from_inverse_matrix", "geometry", e_poly_from_inverse_matrix},
    {"swarp_poly_clip", "geometry", e_poly_clip},
    {"swarp_poly_clip_aabb", "geometry", e_poly_clip_aabb},
    {"swarp_body_h", "geometry", e_body_h},
    {"swarp_body_from_h", "geometry", e_body_from_h},
    {"swarp_body_receivers", "geometry", e_body_receivers},
    {"swarp_body_adjusted_range", "geometry", e_body_adjusted_range},
    {"swarp_focus_light_view", "geometry", e_focus_light_view},
    {"swarp_focus_fit", "geometry", e_focus_fit},
    {"swarp_warp_lispsm", "geometry", e_warp_lispsm},
    {"swarp_setup_points", "geometry", e_setup_points},
    {"swarp_cascade_setup", "splits", e_cascade_setup},
    {"swarp_setup_follow", "geometry", e_setup_follow},
    {"swarp_focus_light_view_follow", "geometry", e_focus_light_view_follow},
    {NULL, NULL, NULL},
};
