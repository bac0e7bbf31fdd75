/* The measured error of returned matrices (swarp_measure_points,
 * swarp_measure_max), checked three ways:
 * - against [RHS] (2.3)/(2.4)/(2.7)/(2.8), written here from the paper, where
 *   they are exact: an overhead light, points on the view axis, bisector
 *   receivers (projection aliasing 1);
 * - against finite differences of the pixel and texel positions themselves
 *   (central differences, singular value by brute force over directions)
 *   for random cameras, lights, techniques, points and normals;
 * - against the properties that define the quantities (sigma between
 *   max(m_s, m_t) and hypot(m_s, m_t); 1/resolution scaling; the maximum over
 *   H not exceeded by random points of H; a much denser sampling agreeing). */
#include <check.h>
#include <fenv.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define W 1920u
#define H 1080u
#define MAPRES 2048u
#define PI 3.14159265358979323846

static swarp_camera level_camera(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = (swarp_vec3){0, 10, 0};
    c.dir = (swarp_vec3){0, 0, -1};
    c.up = (swarp_vec3){0, 1, 0};
    c.fovy = 60.0 * PI / 180.0;
    c.aspect = (double)W / H;
    c.z_near = 1.0;
    c.z_far = 100.0;
    return c;
}

static swarp_light sun(double x, double y, double z) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){x, y, z};
    return l;
}

static const swarp_measure_res RES = {W, H, MAPRES, MAPRES};

static swarp_status setup(const swarp_camera* c, const swarp_light* l, const swarp_aabb* box,
                          swarp_technique t, swarp_setup_result* r) {
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = t;
    o.map_width = o.map_height = MAPRES;
    o.screen_width = W;
    o.screen_height = H;
    return swarp_setup(c, l, box, &o, r, NULL, 0, NULL);
}

/* [RHS] (2.3)/(2.4); n' = +inf gives (2.7)/(2.8) */
static void lloyd(double z, double n, double f, double np, double theta, double* mx, double* mz) {
    if (isinf(np)) {
        *mx = (double)W / MAPRES * f / z;
        *mz = (double)H / MAPRES * (f - n) / (2.0 * tan(theta)) / z;
        return;
    }
    *mx = (double)W / MAPRES * f * (np + z - n) / (z * (np + f - n));
    *mz = (double)H / MAPRES * (f - n) / (2.0 * tan(theta)) * (np + z - n) * (np + z - n) /
          (z * np * (np + f - n));
}

START_TEST(overhead_light_view_axis_equals_lloyd) {
    static const swarp_technique techs[] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM};
    const swarp_camera c = level_camera();
    const swarp_light l = sun(0, -1, 0);
    /* S holds all of V: H = V, its footprint from above the trapezoid the
     * model's map covers */
    const swarp_aabb box = {{-300, -100, -150}, {300, 100, 10}};
    swarp_setup_result r;
    ck_assert(!swarp_status_is_error(setup(&c, &l, &box, techs[_i], &r)));
    ck_assert_double_eq_tol(r.view_near, 1.0, 1e-12);
    ck_assert_double_eq_tol(r.view_far, 100.0, 1e-10);
    swarp_vec3 p[7], n[7];
    for (int k = 0; k < 7; ++k) {
        const double z = r.view_near * pow(r.view_far / r.view_near, k / 6.0);
        p[k] = (swarp_vec3){0, 10, -z};
        n[k] = (swarp_vec3){0, 1, 1}; /* halfway between -dir and the light */
    }
    swarp_texel_error e[7];
    ck_assert_int_eq(swarp_measure_points(&c, &r.matrix, &RES, p, n, 7, e), SWARP_OK);
    for (int k = 0; k < 7; ++k) {
        double mx, mz;
        lloyd(-p[k].z, r.view_near, r.view_far, r.n_eye, 0.5 * c.fovy, &mx, &mz);
        ck_assert_msg(tu_rel(e[k].m_s, mx) < 1e-12 && tu_rel(e[k].m_t, mz) < 1e-12,
                      "tech %d z %g: m_s %.17g vs (2.3) %.17g, m_t %.17g vs (2.4) %.17g", _i,
                      -p[k].z, e[k].m_s, mx, e[k].m_t, mz);
        ck_assert(e[k].flags & SWARP_TEXEL_INSIDE);
    }
}
END_TEST

/* independent: positions, then central differences */
static void pixel_of(const swarp_camera* c, swarp_vec3 x, double out[2]) {
    double f[3] = {c->dir.x, c->dir.y, c->dir.z}, u[3] = {c->up.x, c->up.y, c->up.z};
    double lf = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; ++i) f[i] /= lf;
    double r[3] = {f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0]};
    double lr = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int i = 0; i < 3; ++i) r[i] /= lr;
    double v[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    double d[3] = {x.x - c->eye.x, x.y - c->eye.y, x.z - c->eye.z};
    double z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    double t = tan(c->fovy / 2);
    out[0] = W * 0.5 * (1 + (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) / (z * t * c->aspect));
    out[1] = H * 0.5 * (1 + (d[0] * v[0] + d[1] * v[1] + d[2] * v[2]) / (z * t));
}

static void texel_of(const swarp_mat4* m, swarp_vec3 x, double out[2]) {
    double c[4];
    for (int i = 0; i < 4; ++i)
        c[i] = m->m[i] * x.x + m->m[4 + i] * x.y + m->m[8 + i] * x.z + m->m[12 + i];
    out[0] = MAPRES * 0.5 * (1 + c[0] / c[3]);
    out[1] = MAPRES * 0.5 * (1 + c[1] / c[3]);
}

static swarp_vec3 axpy(swarp_vec3 x, double a, swarp_vec3 d) {
    return (swarp_vec3){x.x + a * d.x, x.y + a * d.y, x.z + a * d.z};
}

/* m_s, m_t, sigma by central differences, sigma by brute force */
static void fd_measure(const swarp_camera* c, const swarp_mat4* m, swarp_vec3 x, swarp_vec3 wx,
                       swarp_vec3 wz, double h, double out[3]) {
    double js[2][2], jt[2][2], a[2], b[2];
    const swarp_vec3 w[2] = {wx, wz};
    for (int k = 0; k < 2; ++k) {
        pixel_of(c, axpy(x, h, w[k]), a);
        pixel_of(c, axpy(x, -h, w[k]), b);
        js[0][k] = (a[0] - b[0]) / (2 * h), js[1][k] = (a[1] - b[1]) / (2 * h);
        texel_of(m, axpy(x, h, w[k]), a);
        texel_of(m, axpy(x, -h, w[k]), b);
        jt[0][k] = (a[0] - b[0]) / (2 * h), jt[1][k] = (a[1] - b[1]) / (2 * h);
    }
    /* solve J_tex X = e_s, e_t by Cramer's rule; D e = J_scr X */
    const double det = jt[0][0] * jt[1][1] - jt[0][1] * jt[1][0];
    double D[2][2];
    for (int col = 0; col < 2; ++col) {
        const double e0 = col == 0, e1 = col == 1;
        const double x0 = (e0 * jt[1][1] - jt[0][1] * e1) / det;
        const double x1 = (jt[0][0] * e1 - jt[1][0] * e0) / det;
        D[0][col] = js[0][0] * x0 + js[0][1] * x1;
        D[1][col] = js[1][0] * x0 + js[1][1] * x1;
    }
    out[0] = hypot(D[0][0], D[1][0]);
    out[1] = hypot(D[0][1], D[1][1]);
    double best = 0;
    for (int i = 0; i < 20000; ++i) {
        const double ph = PI * i / 20000.0;
        best = fmax(best, hypot(D[0][0] * cos(ph) + D[0][1] * sin(ph),
                                D[1][0] * cos(ph) + D[1][1] * sin(ph)));
    }
    out[2] = best;
}

static swarp_vec3 unit(swarp_vec3 v) {
    double l = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return (swarp_vec3){v.x / l, v.y / l, v.z / l};
}
static swarp_vec3 cross(swarp_vec3 a, swarp_vec3 b) {
    return (swarp_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static double dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

START_TEST(random_configurations_match_finite_differences) {
    uint64_t s = 0x5eed0019u;
    int checked = 0;
    for (int cfg = 0; cfg < 300; ++cfg) {
        swarp_camera c = level_camera();
        const double pitch = tu_uniform(&s, -0.5, 0.2), yaw = tu_uniform(&s, -3, 3);
        c.dir = (swarp_vec3){sin(yaw) * cos(pitch), sin(pitch), -cos(yaw) * cos(pitch)};
        c.z_far = c.z_near * pow(10, tu_uniform(&s, 1, 3));
        const double th = tu_uniform(&s, 0, 2 * PI), el = tu_uniform(&s, 0.05, 1.5);
        const swarp_light l = sun(cos(el) * cos(th), -sin(el), cos(el) * sin(th));
        const swarp_aabb box = {{-c.z_far, -1, -c.z_far}, {c.z_far, 30, c.z_far}};
        const swarp_technique t = (swarp_technique)(1 + cfg % 3);
        swarp_setup_result r;
        if (swarp_status_is_error(setup(&c, &l, &box, t, &r))) continue;
        for (int k = 0; k < 4; ++k) {
            const double z = r.view_near * pow(r.view_far / r.view_near, tu_uniform(&s, 0, 1));
            const double ny = tu_uniform(&s, -0.9, 0.9), nx = tu_uniform(&s, -0.9, 0.9);
            swarp_vec3 f = unit(c.dir), rr = unit(cross(f, c.up)), uu = cross(rr, f);
            const double tn = tan(c.fovy / 2);
            swarp_vec3 x = axpy(axpy(axpy(c.eye, z, f), z * nx * tn * c.aspect, rr), z * ny * tn, uu);
            swarp_vec3 n = unit((swarp_vec3){tu_uniform(&s, -1, 1), tu_uniform(&s, -1, 1),
                                             tu_uniform(&s, -1, 1)});
            if (dot(n, (swarp_vec3){c.eye.x - x.x, c.eye.y - x.y, c.eye.z - x.z}) < 0) n = (swarp_vec3){-n.x, -n.y, -n.z};
            swarp_texel_error e;
            swarp_status st = swarp_measure_points(&c, &r.matrix, &RES, &x, &n, 1, &e);
            if (st != SWARP_OK || !(e.flags & SWARP_TEXEL_INSIDE)) continue;
            /* the tangents of the definition, rebuilt here */
            swarp_vec3 wx = unit(axpy(rr, -dot(rr, n), n)), wz = cross(n, wx);
            double fd[3];
            fd_measure(&c, &r.matrix, x, wx, wz, 1e-5 * z, fd);
            ck_assert_msg(tu_rel(e.m_s, fd[0]) < 1e-5 && tu_rel(e.m_t, fd[1]) < 1e-5 &&
                              tu_rel(e.sigma, fd[2]) < 1e-5,
                          "cfg %d tech %d: (%g %g %g) vs fd (%g %g %g)", cfg, t, e.m_s, e.m_t,
                          e.sigma, fd[0], fd[1], fd[2]);
            /* the defining bounds of the largest singular value */
            ck_assert(e.sigma >= fmax(e.m_s, e.m_t) * (1 - 1e-12));
            ck_assert(e.sigma <= hypot(e.m_s, e.m_t) * (1 + 1e-12));
            ++checked;
        }
    }
    ck_assert_int_gt(checked, 600);
}
END_TEST

START_TEST(resolution_scaling_and_flags) {
    const swarp_camera c = level_camera();
    const swarp_light l = sun(0.3, -1, 0.2);
    const swarp_aabb box = {{-300, -100, -150}, {300, 100, 10}};
    swarp_setup_result r;
    ck_assert(!swarp_status_is_error(setup(&c, &l, &box, SWARP_TECHNIQUE_LISPSM, &r)));
    const swarp_vec3 p[3] = {{1, 8, -20}, {0, 10, 5}, {0, 10, -30}};
    const swarp_vec3 n[3] = {{0, 1, 0}, {0, 1, 0}, {1, 0, 0}}; /* the last: N parallel to r */
    swarp_texel_error a[3], b[3];
    const swarp_measure_res twice_map = {W, H, 2 * MAPRES, 0}, twice_screen = {2 * W, 2 * H, MAPRES, 0};
    ck_assert_int_eq(swarp_measure_points(&c, &r.matrix, &RES, p, n, 3, a), SWARP_OK);
    ck_assert_int_eq(swarp_measure_points(&c, &r.matrix, &twice_map, p, n, 3, b), SWARP_OK);
    ck_assert(tu_rel(a[0].sigma, 2 * b[0].sigma) < 1e-14 && tu_rel(a[0].m_t, 2 * b[0].m_t) < 1e-14);
    ck_assert_int_eq(swarp_measure_points(&c, &r.matrix, &twice_screen, p, n, 3, b), SWARP_OK);
    ck_assert(tu_rel(2 * a[0].sigma, b[0].sigma) < 1e-14 && tu_rel(2 * a[0].m_s, b[0].m_s) < 1e-14);
    /* behind the eye: defined zeros and the flag */
    ck_assert(a[1].flags & SWARP_TEXEL_BEHIND_EYE);
    ck_assert(a[1].m_s == 0 && a[1].m_t == 0 && a[1].sigma == 0 && a[1]._pad == 0);
    /* N parallel to r: finite, w_x taken from up */
    ck_assert(isfinite(a[2].sigma) && a[2].sigma > 0);
}
END_TEST

START_TEST(singular_map_reports_infinity) {
    const swarp_camera c = level_camera();
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    m.m[0] = 1, m.m[15] = 1; /* t does not change on the receiver: J_tex singular */
    const swarp_vec3 p = {0, 0, -10}, n = {0, 1, 0};
    swarp_texel_error e;
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, &p, &n, 1, &e), SWARP_INFO_MEASURE_SINGULAR);
    ck_assert(e.flags & SWARP_TEXEL_SINGULAR);
    ck_assert(isinf(e.sigma) && isinf(e.m_s) && isinf(e.m_t));
    m.m[15] = -1; /* w < 0: behind the light's projection */
    m.m[5] = 1;
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, &p, &n, 1, &e), SWARP_INFO_MEASURE_SINGULAR);
    ck_assert(!(e.flags & SWARP_TEXEL_INSIDE) && isinf(e.sigma));
}
END_TEST

START_TEST(bad_input_specific_status_outputs_untouched) {
    const swarp_camera c = level_camera();
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    m.m[0] = m.m[5] = m.m[10] = m.m[15] = 1;
    const swarp_vec3 p = {0, 0, -10}, n = {0, 1, 0}, zero = {0, 0, 0}, nan3 = {NAN, 0, 0};
    swarp_texel_error e;
    const double canary = -3.75e33;
    tu_fill(&e.m_s, 3, canary);
    ck_assert_int_eq(swarp_measure_points(NULL, &m, &RES, &p, &n, 1, &e), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_points(&c, NULL, &RES, &p, &n, 1, &e), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_points(&c, &m, NULL, &p, &n, 1, &e), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, NULL, &n, 1, &e), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, &p, &n, 1, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, &p, &zero, 1, &e), SWARP_ERR_ZERO_VECTOR);
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, &p, &nan3, 1, &e), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_measure_points(&c, &m, &RES, &nan3, &n, 1, &e), SWARP_ERR_NON_FINITE);
    const swarp_measure_res zero_res[3] = {{0, H, MAPRES, 0}, {W, 0, MAPRES, 0}, {W, H, 0, 0}};
    for (int i = 0; i < 3; ++i)
        ck_assert_int_eq(swarp_measure_points(&c, &m, &zero_res[i], &p, &n, 1, &e), SWARP_ERR_RESOLUTION);
    swarp_mat4 bad = m;
    bad.m[7] = INFINITY;
    ck_assert_int_eq(swarp_measure_points(&c, &bad, &RES, &p, &n, 1, &e), SWARP_ERR_NON_FINITE);
    swarp_camera cb = c;
    cb.fovy = 0;
    ck_assert_int_eq(swarp_measure_points(&cb, &m, &RES, &p, &n, 1, &e), SWARP_ERR_FOV);
    ck_assert(tu_untouched(&e.m_s, 3, canary));
    /* swarp_measure_max */
    swarp_measured_error me;
    tu_fill(&me.max_m_s, 3, canary);
    const swarp_light l = sun(0, -1, 0);
    const swarp_aabb box = {{-300, -100, -150}, {300, 100, 10}}, away = {{-5, -5, 50}, {5, 5, 60}};
    ck_assert_int_eq(swarp_measure_max(&c, 1, 0.5, &l, &box, &m, &RES, NULL, &me), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_measure_max(&c, 1, INFINITY, &l, &box, &m, &RES, NULL, &me), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_measure_max(&c, 1, 100, NULL, &box, &m, &RES, NULL, &me), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_max(&c, 1, 100, &l, &box, &m, &RES, NULL, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_measure_max(&c, 1, 100, &l, &away, &m, &RES, NULL, &me), SWARP_ERR_BODY_EMPTY);
    swarp_measure_options o = {1, 0, 0, 0};
    ck_assert_int_eq(swarp_measure_max(&c, 1, 100, &l, &box, &m, &RES, &o, &me), SWARP_ERR_OUT_OF_RANGE);
    o = (swarp_measure_options){0, 0, 0, 1};
    ck_assert_int_eq(swarp_measure_max(&c, 1, 100, &l, &box, &m, &RES, &o, &me), SWARP_ERR_RESERVED_NONZERO);
    swarp_light lz = sun(0, 0, 0);
    ck_assert_int_eq(swarp_measure_max(&c, 1, 100, &lz, &box, &m, &RES, NULL, &me), SWARP_ERR_ZERO_VECTOR);
    ck_assert(tu_untouched(&me.max_m_s, 3, canary));
}
END_TEST

/* Random points of H, their own sigma from swarp_measure_points with the
 * bisector normal built here: none exceeds the reported maximum by more
 * than the sampling's stated error; a 33 x 33 x 65 lattice agrees. */
START_TEST(maximum_over_h_bounds_random_points_and_dense_sampling) {
    uint64_t s = 0x5eed1900u + (uint64_t)_i;
    const swarp_technique techs[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_PSM};
    double worst_dense = 0, worst_random = 0;
    for (int cfg = 0; cfg < 12; ++cfg) {
        swarp_camera c = level_camera();
        const double pitch = tu_uniform(&s, -0.5, 0.1);
        c.dir = (swarp_vec3){0.2, sin(pitch), -cos(pitch)};
        c.z_far = pow(10, tu_uniform(&s, 1.5, 3));
        const double th = tu_uniform(&s, 0, 2 * PI), el = tu_uniform(&s, 0.1, 1.5);
        const swarp_light l = sun(cos(el) * cos(th), -sin(el), cos(el) * sin(th));
        const swarp_aabb box = {{-c.z_far, -1, -c.z_far}, {c.z_far, 30, c.z_far}};
        swarp_setup_result r;
        if (swarp_status_is_error(setup(&c, &l, &box, techs[_i], &r))) continue;
        swarp_measured_error m, dense;
        const swarp_measure_options big = {33, 65, 16, 0};
        swarp_status st = swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, NULL, &m);
        if (st == SWARP_INFO_MEASURE_SINGULAR) continue;
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_int_eq(swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, &big, &dense), SWARP_OK);
        ck_assert(m.samples > 0 && dense.samples > m.samples);
        ck_assert(m.at.y >= box.min.y - 1e-6 && m.at.y <= box.max.y + 1e-6); /* S within its stated slack */
        worst_dense = fmax(worst_dense, dense.max_sigma / m.max_sigma);
        if (getenv("SW_DEBUG")) fprintf(stderr, "cfg %d: default %g at (%g %g %g) n=%u; dense %g at (%g %g %g); near %g far %g\n", cfg, m.max_sigma, m.at.x, m.at.y, m.at.z, m.samples, dense.max_sigma, dense.at.x, dense.at.y, dense.at.z, r.view_near, r.view_far);
        for (int k = 0; k < 500; ++k) {
            swarp_vec3 f = unit(c.dir), rr = unit(cross(f, c.up)), uu = cross(rr, f);
            const double z = r.view_near * pow(r.view_far / r.view_near, tu_uniform(&s, 0, 1));
            const double tn = tan(c.fovy / 2);
            swarp_vec3 x = axpy(axpy(axpy(c.eye, z, f), z * tu_uniform(&s, -1, 1) * tn * c.aspect, rr),
                                z * tu_uniform(&s, -1, 1) * tn, uu);
            if (x.x < box.min.x || x.x > box.max.x || x.y < box.min.y || x.y > box.max.y ||
                x.z < box.min.z || x.z > box.max.z)
                continue; /* not in H */
            swarp_vec3 e = unit((swarp_vec3){c.eye.x - x.x, c.eye.y - x.y, c.eye.z - x.z});
            swarp_vec3 lt = unit((swarp_vec3){-l.direction.x, -l.direction.y, -l.direction.z});
            swarp_vec3 n = unit((swarp_vec3){e.x + lt.x, e.y + lt.y, e.z + lt.z});
            swarp_texel_error te;
            swarp_measure_points(&c, &r.matrix, &RES, &x, &n, 1, &te);
            if (getenv("SW_DEBUG") && te.sigma > m.max_sigma) fprintf(stderr, "  random %g at (%g %g %g) flags %u\n", te.sigma, x.x, x.y, x.z, te.flags);
            worst_random = fmax(worst_random, te.sigma / m.max_sigma);
        }
    }
    /* stated in the header's sampling note: within 3 % of a 33 x 33 x 65 lattice */
    ck_assert_msg(worst_dense <= 1.03, "dense/default %g", worst_dense);
    ck_assert_msg(worst_random <= 1.03, "random/default %g", worst_random);
    fprintf(stderr, "tech %d: dense/default max %.4f, random/default max %.4f\n", _i, worst_dense, worst_random);
}
END_TEST


/* max sigma over a flat H (S with min.y == max.y: H is a polygon on the
 * plane y = y0), by brute force written here: rays through a 401 x 401 NDC
 * grid meet the plane, points with planar depth in [zn, zf] inside S's x/z
 * range are measured with bisector receivers by swarp_measure_points. */
static double flat_brute_max(const swarp_camera* c, const swarp_light* l, const swarp_aabb* box,
                             const swarp_mat4* m, double zn, double zf, int* hits) {
    const swarp_vec3 f = unit(c->dir), rr = unit(cross(f, c->up)), uu = cross(rr, f);
    const double ty = tan(c->fovy / 2), tx = ty * c->aspect, y0 = box->min.y;
    double worst = 0;
    *hits = 0;
    for (int i = 0; i <= 400; ++i)
        for (int j = 0; j <= 400; ++j) {
            const double a = (-1 + i / 200.0) * tx, b = (-1 + j / 200.0) * ty;
            const swarp_vec3 d = axpy(axpy(f, a, rr), b, uu);
            if (d.y == 0) continue;
            const double z = (y0 - c->eye.y) / d.y; /* planar depth: d.f = 1 */
            if (!(z >= zn && z <= zf)) continue;
            swarp_vec3 x = axpy(c->eye, z, d);
            x.y = y0;
            if (x.x < box->min.x || x.x > box->max.x || x.z < box->min.z || x.z > box->max.z) continue;
            const swarp_vec3 e = unit((swarp_vec3){c->eye.x - x.x, c->eye.y - x.y, c->eye.z - x.z});
            const swarp_vec3 lt = unit((swarp_vec3){-l->direction.x, -l->direction.y, -l->direction.z});
            const swarp_vec3 n = unit((swarp_vec3){e.x + lt.x, e.y + lt.y, e.z + lt.z});
            swarp_texel_error te;
            swarp_measure_points(c, m, &RES, &x, &n, 1, &te);
            worst = fmax(worst, te.sigma);
            ++*hits;
        }
    return worst;
}

/* A flat scene box (min.y == max.y) makes H a polygon.  The maximum over it
 * agrees with a brute-force sampling of the polygon (within the sampling's
 * stated 3 %, both ways: the default finds the peak, and the brute force's
 * 0.005-NDC grid resolves it to far better than that), the plane is really
 * sampled (not only H's vertices), and the result does not depend on the
 * rounding mode: the points lie on the plane by construction, not by
 * rounding.  Tolerance across modes 1e-6 relative: the points move by a few
 * ulps of their coordinates (1e-10 of the scene at 1e6 from the origin) and
 * sigma is of condition O(1) in them; a lattice point kept or dropped by
 * rounding changes the maximum by per cents. */
START_TEST(flat_box_sampled_on_its_plane_rounding_stable) {
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    const double off = _i ? 1e6 : 0.0;
    swarp_camera c = level_camera();
    c.eye = (swarp_vec3){off, 10, off};
    c.dir = (swarp_vec3){0.3, -0.35, -1};
    const swarp_light l = sun(0.4, -0.7, -0.3);
    const swarp_aabb box = {{off - 150, 0, off - 150}, {off + 150, 0, off + 150}};
    swarp_setup_result r;
    ck_assert(!swarp_status_is_error(setup(&c, &l, &box, SWARP_TECHNIQUE_LISPSM, &r)));
    swarp_measured_error m;
    ck_assert_int_eq(swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, NULL, &m), SWARP_OK);
    ck_assert_msg(m.samples > 100, "only %u samples on the plane", m.samples);
    ck_assert(m.at.y == 0.0);
    int hits;
    const double brute = flat_brute_max(&c, &l, &box, &r.matrix, r.view_near, r.view_far, &hits);
    ck_assert_int_gt(hits, 1000);
    fprintf(stderr, "flat H (offset %g): default %.6g (%u samples), brute force %.6g (%d points)\n", off,
            m.max_sigma, m.samples, brute, hits);
    ck_assert_msg(brute <= 1.03 * m.max_sigma && m.max_sigma <= 1.03 * brute, "default %g brute %g",
                  m.max_sigma, brute);
    /* the lattice and the vertices with one search step: which points count
     * (the compass search's later path may differ where neighbours tie to
     * an ulp, its maximum does not) */
    const swarp_measure_options one_step = {0, 0, 1, 0};
    swarp_measured_error lattice;
    ck_assert_int_eq(swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, &one_step, &lattice), SWARP_OK);
    ck_assert_int_gt(lattice.samples, 200); /* 19 x 19 rays, about 3/4 of them meet the polygon */
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; ++i) {
        swarp_measured_error mm;
        swarp_measured_error lm;
        fesetround(modes[i]);
        const swarp_status st = swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, NULL, &mm);
        const swarp_status lst = swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, &one_step, &lm);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_int_eq(lst, SWARP_OK);
        /* every lattice point and vertex kept in one mode is kept in all */
        ck_assert_int_eq(lm.samples, lattice.samples);
        ck_assert(fabs(mm.at.x - m.at.x) <= 1e-9 * 300 && fabs(mm.at.z - m.at.z) <= 1e-9 * 300 && mm.at.y == 0.0);
        ck_assert_msg(fabs(mm.max_sigma - m.max_sigma) <= 1e-6 * m.max_sigma, "mode %zu: %.17g vs %.17g", i,
                      mm.max_sigma, m.max_sigma);
    }
}
END_TEST

/* The results carry the measurement of their own matrix: swarp_setup's
 * measured equals swarp_measure_max of the returned matrix over
 * [view_near, view_far] (measured camera-relative inside, so to rounding);
 * skip_measure leaves it zero; every cascade split carries its own, the
 * cascade the worst; a 1-split cascade carries swarp_setup's bit for bit. */
START_TEST(results_carry_the_measurement_of_their_matrix) {
    swarp_camera c = level_camera();
    c.eye = (swarp_vec3){3, 2, -4};
    c.dir = (swarp_vec3){0.2, -0.25, -1};
    const swarp_light l = sun(0.3, -1, 0.2);
    const swarp_aabb box = {{-100, -1, -250}, {100, 15, 60}};
    swarp_setup_result r;
    ck_assert(!swarp_status_is_error(setup(&c, &l, &box, SWARP_TECHNIQUE_LISPSM, &r)));
    swarp_measured_error m;
    ck_assert_int_eq(swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, NULL, &m), SWARP_OK);
    ck_assert_uint_gt(r.measured.samples, 100);
    ck_assert_msg(tu_rel(r.measured.max_sigma, m.max_sigma) < 1e-6, "%.17g vs %.17g", r.measured.max_sigma,
                  m.max_sigma);
    ck_assert(tu_rel(r.measured.max_m_s, m.max_m_s) < 1e-6 && tu_rel(r.measured.max_m_t, m.max_m_t) < 1e-6);
    /* the worst point is a point of H: in S and in front of the eye */
    ck_assert(r.measured.at.y >= box.min.y - 1e-6 && r.measured.at.y <= box.max.y + 1e-6);
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.map_width = o.map_height = MAPRES;
    o.screen_width = W;
    o.screen_height = H;
    o.skip_measure = 1;
    swarp_setup_result q;
    ck_assert(!swarp_status_is_error(swarp_setup(&c, &l, &box, &o, &q, NULL, 0, NULL)));
    static const swarp_measured_error zero;
    ck_assert(memcmp(&q.measured, &zero, sizeof zero) == 0);
    ck_assert(memcmp(&q.matrix, &r.matrix, sizeof q.matrix) == 0); /* measuring changes nothing else */
    /* cascades */
    swarp_cascade_options co;
    memset(&co, 0, sizeof co);
    co.setup.map_width = co.setup.map_height = MAPRES;
    co.setup.screen_width = W;
    co.setup.screen_height = H;
    co.split.count = 4;
    swarp_cascade_result cr;
    swarp_cascade_split sp[4];
    size_t n = 0;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&c, &l, &box, &co, &cr, sp, 4, &n)));
    ck_assert_uint_eq(n, 4);
    double worst = 0;
    uint32_t samples = 0;
    for (size_t i = 0; i < n; ++i) {
        swarp_measured_error mi;
        ck_assert_int_eq(swarp_measure_max(&c, sp[i].z_near, sp[i].z_far, &l, &box, &sp[i].matrix, &RES, NULL, &mi),
                         SWARP_OK);
        ck_assert(memcmp(&mi, &sp[i].measured, sizeof mi) == 0);
        worst = fmax(worst, mi.max_sigma);
        samples += mi.samples;
    }
    ck_assert(cr.measured.max_sigma == worst && cr.measured.samples == samples);
    /* splits resolve the near field: the cascade's worst is below the single map's */
    ck_assert(cr.measured.max_sigma < r.measured.max_sigma);
    co.split.count = 1;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&c, &l, &box, &co, &cr, sp, 4, &n)));
    ck_assert(memcmp(&sp[0].measured, &r.measured, sizeof r.measured) == 0);
}
END_TEST

/* The sampling's error over configurations of this test's own generator
 * (pitch -29..+10 degrees, fovy 0.5..1.6, far/near 10^2..10^4, lights over
 * the whole sphere, boxes with the eye; uniform, LiSPSM, PSM): the default
 * against a 33 x 33 x 65 lattice with the same search.  The stated figure
 * (docs/accuracy.md): every configuration within 3 % (the near face's own
 * lattice and search reach the narrow near-plane peaks of LiSPSM maps). */
START_TEST(default_sampling_error_over_random_configurations) {
    uint64_t s = 77;
    /* fewer under ASan and valgrind (about 20x and 50x slower) */
    const int count = SW_UNDER_ASAN || getenv("SWARP_UNDER_VALGRIND") ? 60 : 300;
    int n = 0, within = 0;
    double worst = 1.0;
    for (int i = 0; i < count; ++i) {
        swarp_camera c = level_camera();
        const double pitch = tu_uniform(&s, -0.5, 0.17), yaw = tu_uniform(&s, -3, 3);
        c.eye = (swarp_vec3){0, tu_uniform(&s, 1, 20), 0};
        c.dir = (swarp_vec3){sin(yaw) * cos(pitch), sin(pitch), -cos(yaw) * cos(pitch)};
        c.fovy = tu_uniform(&s, 0.5, 1.6);
        c.z_near = tu_uniform(&s, 0.1, 2);
        c.z_far = c.z_near * pow(10, tu_uniform(&s, 2, 4));
        const double zl = tu_uniform(&s, -1, 1), al = tu_uniform(&s, -3.14, 3.14), rl = sqrt(1 - zl * zl);
        const swarp_light l = sun(rl * cos(al), zl, rl * sin(al));
        const double e = fmin(c.z_far, 2000);
        const swarp_aabb box = {{-e, 0, -e}, {e, c.eye.y + 30, e}};
        swarp_setup_result r;
        if (swarp_status_is_error(setup(&c, &l, &box, (swarp_technique)(1 + i % 3), &r))) continue;
        const swarp_measure_options big = {33, 65, 24, 0};
        swarp_measured_error dense;
        if (swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &RES, &big, &dense) != SWARP_OK)
            continue;
        /* the default can only find less than the dense lattice plus the same search */
        const double q = dense.max_sigma / r.measured.max_sigma;
        worst = fmax(worst, q);
        within += q <= 1.03;
        ++n;
    }
    fprintf(stderr, "default sampling: %d of %d configurations within 3 %% of the dense lattice, worst %.4f\n",
            within, n, worst);
    ck_assert_int_gt(n, count * 9 / 10);
    ck_assert_msg(within == n, "%d of %d within 3 %%", within, n);
    ck_assert_msg(worst <= 1.03, "worst dense/default %.4f", worst);
}
END_TEST

int main(void) {
    Suite* s = suite_create("measured_error");
    TCase* t = tcase_create("measured");
    tcase_set_timeout(t, 120);
    tcase_add_loop_test(t, overhead_light_view_axis_equals_lloyd, 0, 2);
    tcase_add_test(t, random_configurations_match_finite_differences);
    tcase_add_test(t, resolution_scaling_and_flags);
    tcase_add_test(t, singular_map_reports_infinity);
    tcase_add_test(t, bad_input_specific_status_outputs_untouched);
    tcase_add_loop_test(t, maximum_over_h_bounds_random_points_and_dense_sampling, 0, 3);
    tcase_add_loop_test(t, flat_box_sampled_on_its_plane_rounding_stable, 0, 2);
    tcase_add_test(t, results_carry_the_measurement_of_their_matrix);
    tcase_add_test(t, default_sampling_error_over_random_configurations);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
