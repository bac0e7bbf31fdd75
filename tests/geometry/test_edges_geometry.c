#define _POSIX_C_SOURCE 200809L
/* Public geometry functions the robustness sweep does not call, and the
 * edges of the ones it does: swarp_poly_clip_aabb, swarp_body_from_h, swarp_focus_light_view
 * with point lights, swarp_warp_lispsm's options.  Valid results against an
 * independent evaluation (box intersections by hand, the extrusion's
 * bounding box, the view axis, (4.2) through swarp_warp_nopt_pseudo), bad
 * input with its status and outputs untouched. */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

static swarp_polyhedron poly_sentinel(void) {
    swarp_polyhedron p;
    memset(&p, 0xA5, sizeof p);
    return p;
}
static int poly_untouched(const swarp_polyhedron* p) {
    swarp_polyhedron s = poly_sentinel();
    return memcmp(p, &s, sizeof s) == 0;
}
static void bbox(const swarp_polyhedron* p, double lo[3], double hi[3]) {
    for (int k = 0; k < 3; ++k) lo[k] = INFINITY, hi[k] = -INFINITY;
    for (uint32_t i = 0; i < p->vertex_count; ++i) {
        const double v[3] = {p->vertices[i].x, p->vertices[i].y, p->vertices[i].z};
        for (int k = 0; k < 3; ++k) lo[k] = fmin(lo[k], v[k]), hi[k] = fmax(hi[k], v[k]);
    }
}

/* every face plane of F has a unit normal (and, with check_d, a finite d) */
static void assert_unit_planes(const swarp_polyhedron* F, int check_d) {
    for (uint32_t f = 0; f < F->face_count; ++f) {
        const swarp_plane* q = &F->planes[f];
        const double nl = sqrt(q->a * q->a + q->b * q->b + q->c * q->c);
        ck_assert_msg(fabs(nl - 1) <= 1e-9 && (!check_d || isfinite(q->d)), "face %u normal length %g d %g", f, nl, q->d);
    }
}

START_TEST(poly_clip_aabb_edges) {
    uint64_t s = 0xB0C5ull;
    for (int n = 0; n < 300; ++n) {
        swarp_aabb a, b;
        double* pa = &a.min.x;
        double* pb = &b.min.x;
        for (int k = 0; k < 3; ++k) {
            double x0 = tu_uniform(&s, -10, 10), x1 = tu_uniform(&s, -10, 10);
            pa[k] = fmin(x0, x1), pa[k + 3] = fmax(x0, x1) + 0.5;
            x0 = tu_uniform(&s, -10, 10), x1 = tu_uniform(&s, -10, 10);
            pb[k] = fmin(x0, x1), pb[k + 3] = fmax(x0, x1) + 0.5;
        }
        swarp_polyhedron P, out;
        ck_assert_int_eq(swarp_poly_from_aabb(&a, &P), SWARP_OK);
        ck_assert_int_eq(swarp_poly_clip_aabb(&P, &b, &out), SWARP_OK);
        /* the intersection of two boxes is the box of the max of mins, min of maxes */
        int empty = 0;
        double lo_w[3], hi_w[3];
        for (int k = 0; k < 3; ++k) {
            lo_w[k] = fmax(pa[k], pb[k]);
            hi_w[k] = fmin(pa[k + 3], pb[k + 3]);
            if (!(hi_w[k] > lo_w[k] + 1e-9)) empty |= !(hi_w[k] >= lo_w[k]);
        }
        if (empty) {
            ck_assert_uint_eq(out.vertex_count, 0);
            continue;
        }
        double lo[3], hi[3];
        bbox(&out, lo, hi);
        for (int k = 0; k < 3; ++k) ck_assert(fabs(lo[k] - lo_w[k]) < 1e-9 && fabs(hi[k] - hi_w[k]) < 1e-9);
        /* out may equal in */
        ck_assert_int_eq(swarp_poly_clip_aabb(&P, &b, &P), SWARP_OK);
        ck_assert_uint_eq(P.vertex_count, out.vertex_count);
    }
    swarp_aabb box = {{-1, -1, -1}, {1, 1, 1}};
    swarp_polyhedron P, out = poly_sentinel();
    ck_assert_int_eq(swarp_poly_from_aabb(&box, &P), SWARP_OK);
    swarp_aabb inv = box;
    inv.min.y = 2.0;
    ck_assert_int_eq(swarp_poly_clip_aabb(&P, &inv, &out), SWARP_ERR_BOX_INVERTED);
    swarp_aabb nan_b = box;
    nan_b.max.z = NAN;
    ck_assert_int_eq(swarp_poly_clip_aabb(&P, &nan_b, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_poly_clip_aabb(NULL, &box, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_poly_clip_aabb(&P, NULL, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_poly_clip_aabb(&P, &box, NULL), SWARP_ERR_NULL_POINTER);
    swarp_polyhedron bad = P;
    bad.vertex_count = SWARP_POLY_MAX_VERTICES + 1;
    ck_assert_int_eq(swarp_poly_clip_aabb(&bad, &box, &out), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert(poly_untouched(&out));
}
END_TEST

static swarp_light sun(double x, double y, double z) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){x, y, z};
    return l;
}

START_TEST(body_from_h_edges) {
    /* H a box inside the scene, the light straight down: B is H extruded up
     * to the scene's top, i.e. the box [H.x] x [H.ymin, scene.ymax] x [H.z] */
    const swarp_aabb scene = {{-50, -2, -50}, {50, 30, 50}}, hb = {{-3, 0, -8}, {4, 5, -1}};
    swarp_polyhedron H, B;
    ck_assert_int_eq(swarp_poly_from_aabb(&hb, &H), SWARP_OK);
    const swarp_light down = sun(0, -1, 0);
    ck_assert_int_eq(swarp_body_from_h(&H, &down, &scene, &B), SWARP_OK);
    double lo[3], hi[3];
    bbox(&B, lo, hi);
    const double want_lo[3] = {-3, 0, -8}, want_hi[3] = {4, 30, -1};
    for (int k = 0; k < 3; ++k) ck_assert(fabs(lo[k] - want_lo[k]) < 1e-9 && fabs(hi[k] - want_hi[k]) < 1e-9);
    /* a point light above: B = conv(H + l) within S, its top is l itself */
    swarp_light pl;
    memset(&pl, 0, sizeof pl);
    pl.type = SWARP_LIGHT_POINT;
    pl.position = (swarp_vec3){0.5, 20, -4};
    ck_assert_int_eq(swarp_body_from_h(&H, &pl, &scene, &B), SWARP_OK);
    bbox(&B, lo, hi);
    ck_assert(fabs(hi[1] - 20) < 1e-9 && fabs(lo[1]) < 1e-9);

    swarp_polyhedron out = poly_sentinel();
    ck_assert_int_eq(swarp_body_from_h(NULL, &down, &scene, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_body_from_h(&H, NULL, &scene, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_body_from_h(&H, &down, NULL, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_body_from_h(&H, &down, &scene, NULL), SWARP_ERR_NULL_POINTER);
    swarp_light bl = down;
    bl._reserved[1] = 1;
    ck_assert_int_eq(swarp_body_from_h(&H, &bl, &scene, &out), SWARP_ERR_RESERVED_NONZERO);
    bl = down;
    bl.type = (swarp_light_type)4;
    ck_assert_int_eq(swarp_body_from_h(&H, &bl, &scene, &out), SWARP_ERR_UNKNOWN_ENUM);
    bl = down;
    bl.direction.x = NAN;
    ck_assert_int_eq(swarp_body_from_h(&H, &bl, &scene, &out), SWARP_ERR_NON_FINITE);
    bl = down;
    bl.direction = (swarp_vec3){0, 0, 0};
    ck_assert_int_eq(swarp_body_from_h(&H, &bl, &scene, &out), SWARP_ERR_ZERO_VECTOR);
    bl = pl;
    bl.cone_angle = 2.0;
    bl.direction = (swarp_vec3){0, -1, 0};
    ck_assert_int_eq(swarp_body_from_h(&H, &bl, &scene, &out), SWARP_ERR_OUT_OF_RANGE);
    swarp_aabb bs = scene;
    bs.min.x = 60;
    ck_assert_int_eq(swarp_body_from_h(&H, &down, &bs, &out), SWARP_ERR_BOX_INVERTED);
    bs = scene;
    bs.max.y = INFINITY;
    ck_assert_int_eq(swarp_body_from_h(&H, &down, &bs, &out), SWARP_ERR_NON_FINITE);
    /* malformed polyhedra (not documented in the header: reported) */
    swarp_polyhedron bad = H;
    bad.vertex_count = SWARP_POLY_MAX_VERTICES + 1;
    ck_assert_int_eq(swarp_body_from_h(&bad, &down, &scene, &out), SWARP_ERR_INVALID_ARGUMENT);
    bad = H;
    bad.face_count = SWARP_POLY_MAX_FACES + 1;
    ck_assert_int_eq(swarp_body_from_h(&bad, &down, &scene, &out), SWARP_ERR_INVALID_ARGUMENT);
    bad = H;
    bad.face_vertex_count[0] = SWARP_POLY_MAX_FACE_VERTICES + 1;
    ck_assert_int_eq(swarp_body_from_h(&bad, &down, &scene, &out), SWARP_ERR_INVALID_ARGUMENT);
    bad = H;
    bad.face_vertices[2][1] = (uint8_t)H.vertex_count;
    ck_assert_int_eq(swarp_body_from_h(&bad, &down, &scene, &out), SWARP_ERR_INVALID_ARGUMENT);
    bad = H;
    bad.vertices[3].z = NAN;
    ck_assert_int_eq(swarp_body_from_h(&bad, &down, &scene, &out), SWARP_ERR_NON_FINITE);
    bad = H;
    bad.vertex_count = 0;
    bad.face_count = 0;
    ck_assert_int_eq(swarp_body_from_h(&bad, &down, &scene, &out), SWARP_ERR_BODY_EMPTY);
    ck_assert(poly_untouched(&out));
}
END_TEST

static swarp_camera camera(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = (swarp_vec3){0, 10, 0};
    c.dir = (swarp_vec3){0, -0.2, -1};
    c.up = (swarp_vec3){0, 1, 0};
    c.fovy = 1.0;
    c.aspect = 1.5;
    c.z_near = 1.0;
    c.z_far = 100.0;
    return c;
}

/* the light view looks down -z: its third row is minus the unit axis */
static void check_axis(const swarp_mat4* v, swarp_vec3 a) {
    double l = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    ck_assert(fabs(v->m[2] + a.x / l) < 1e-12 && fabs(v->m[6] + a.y / l) < 1e-12 && fabs(v->m[10] + a.z / l) < 1e-12);
}

START_TEST(focus_light_view_point_lights) {
    const swarp_camera cam = camera();
    swarp_light pl;
    memset(&pl, 0, sizeof pl);
    pl.type = SWARP_LIGHT_POINT;
    pl.position = (swarp_vec3){20, 50, -30};
    swarp_mat4 v;
    /* omni light, no axis: looks at the eye */
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &pl, NULL, &v)));
    check_axis(&v, (swarp_vec3){0 - 20, 10 - 50, 0 + 30});
    /* the light's position maps to the origin */
    swarp_vec4 h;
    ck_assert_int_eq(swarp_mat4_transform(&v, &pl.position, &h), SWARP_OK);
    ck_assert(fabs(h.x) < 1e-12 && fabs(h.y) < 1e-12 && fabs(h.z) < 1e-12);
    /* explicit axis */
    const swarp_vec3 axis = {0.1, -2.0, 0.3};
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &pl, &axis, &v)));
    check_axis(&v, axis);
    /* spot: its direction */
    swarp_light spot = pl;
    spot.cone_angle = 0.5;
    spot.direction = (swarp_vec3){-0.3, -1, 0.2};
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &spot, NULL, &v)));
    check_axis(&v, spot.direction);

    swarp_mat4 out;
    tu_fill(out.m, 16, -7.25e33);
    const swarp_vec3 nan_axis = {NAN, 1, 0}, zero = {0, 0, 0};
    ck_assert_int_eq(swarp_focus_light_view(&cam, &pl, &nan_axis, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_focus_light_view(&cam, &pl, &zero, &out), SWARP_ERR_ZERO_VECTOR);
    swarp_light at_eye = pl;
    at_eye.position = cam.eye; /* omni light at the eye: no direction to look along */
    ck_assert_int_eq(swarp_focus_light_view(&cam, &at_eye, NULL, &out), SWARP_ERR_ZERO_VECTOR);
    ck_assert_int_eq(swarp_focus_light_view(NULL, &pl, NULL, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_focus_light_view(&cam, NULL, NULL, &out), SWARP_ERR_NULL_POINTER);
    ck_assert(tu_untouched(out.m, 16, -7.25e33));
    ck_assert_int_eq(swarp_focus_light_view(&cam, &pl, NULL, NULL), SWARP_ERR_NULL_POINTER);
}
END_TEST

START_TEST(warp_lispsm_options) {
    const swarp_camera cam = camera();
    const swarp_light l = sun(0.3, -1, 0.2);
    const swarp_aabb scene = {{-200, -5, -300}, {200, 30, 60}};
    swarp_mat4 L, P;
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &l, NULL, &L)));
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t np = 0;
    ck_assert(!swarp_status_is_error(
        swarp_body_points(&cam, 1.0, 100.0, &l, &scene, pts, SWARP_BODY_MAX_POINTS, &np)));
    swarp_warp_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_PSEUDO;
    o.pseudo_near = 0.1;
    o.pseudo_far = 0.2;
    swarp_warp_info info;
    ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1.0, 100.0, pts, np, NULL, &o, &P, &info), SWARP_OK);
    /* n in light units is (4.2) of the warp's own d, z_0, z_1 */
    double want;
    ck_assert_int_eq(swarp_warp_nopt_pseudo(info.d, info.z_0, info.z_1, 0.1, 0.2, &want), SWARP_OK);
    ck_assert_msg(tu_rel(info.n_light, want) < 1e-9, "n %.17g vs (4.2) %.17g", info.n_light, want);

    swarp_mat4 out;
    swarp_warp_info oi;
    tu_fill(out.m, 16, -7.25e33);
    tu_fill(&oi.n_light, 1, -7.25e33);
#define BAD(want_status)                                                                          \
    do {                                                                                          \
        ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1.0, 100.0, pts, np, NULL, &o, &out, &oi), \
                         (want_status));                                                          \
        ck_assert(tu_untouched(out.m, 16, -7.25e33) && tu_untouched(&oi.n_light, 1, -7.25e33));   \
    } while (0)
    o.pseudo_near = NAN;
    BAD(SWARP_ERR_NON_FINITE);
    o.pseudo_near = 0.1;
    o.pseudo_far = INFINITY;
    BAD(SWARP_ERR_NON_FINITE);
    o.pseudo_far = 0.9;
    BAD(SWARP_ERR_OUT_OF_RANGE);
    o.pseudo_far = -0.1;
    BAD(SWARP_ERR_OUT_OF_RANGE);
    o.pseudo_far = 0.2;
    o.center = (swarp_warp_center)7;
    BAD(SWARP_ERR_UNKNOWN_ENUM);
    o.center = SWARP_WARP_CENTER_DEFAULT;
    o.param = (swarp_warp_param)9;
    BAD(SWARP_ERR_UNKNOWN_ENUM);
    o.param = SWARP_WARP_PARAM_DEFAULT;
    o._reserved[0] = 1;
    BAD(SWARP_ERR_RESERVED_NONZERO);
#undef BAD
}
END_TEST

/* ---- the caller's rounding mode (as tests/robust/fenv.c) -----------------
 * Each test runs the library under FE_UPWARD / FE_DOWNWARD / FE_TOWARDZERO
 * and compares with the default mode: the outputs must agree within 1e-9 of
 * their largest magnitude (the scenes are well conditioned). */
static const int tu_modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
static double mat_rel_diff(const swarp_mat4* a, const swarp_mat4* b) {
    double scale = 0.0, d = 0.0;
    for (int i = 0; i < 16; ++i) scale = fmax(scale, fmax(fabs(a->m[i]), fabs(b->m[i])));
    for (int i = 0; i < 16; ++i) d = fmax(d, fabs(a->m[i] - b->m[i]));
    return scale > 0 ? d / scale : d;
}

/* [WS06] nearest vertex e: H cut by the near plane has several vertices at
 * exactly the near depth; picking one by comparing rounded depths made the
 * WS06 centre (and light_proj, by 60 %) depend on the rounding mode. */
START_TEST(setup_nearest_vertex_rounding_mode) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){0.3, 0.1, -0.2};
    double dl = sqrt(1.0 + 0.3 * 0.3 + 0.3 * 0.3);
    cam.dir = (swarp_vec3){1.0 / dl, -0.3 / dl, 0.3 / dl};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 1.0;
    cam.aspect = 1.5;
    cam.z_near = 1.0;
    cam.z_far = 300.0;
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){-0.889186, -0.156768, 0.542136};
    swarp_aabb box = {{-20, -10, -40}, {40, 10, 40}};
    for (int flat = 0; flat < 2; ++flat) {
        if (flat) { /* a flat box with the eye 1 ulp above it (the nearest-vertex tie) */
            box.min.y = box.max.y = -10.0;
            cam.eye.y = nextafter(-10.0, 0.0);
        }
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = SWARP_TECHNIQUE_LISPSM;
        o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
        /* the closed form's rounding: the measured search's comparisons may
         * pick another candidate under another rounding mode */
        o.param = SWARP_WARP_PARAM_NOPT;
        swarp_setup_result r0, r;
        swarp_status s0 = swarp_setup(&cam, &l, &box, &o, &r0, NULL, 0, NULL);
        ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
        for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
            fesetround(tu_modes[m]);
            swarp_status s = swarp_setup(&cam, &l, &box, &o, &r, NULL, 0, NULL);
            fesetround(FE_TONEAREST);
            ck_assert_int_eq(s, s0);
            double dp = mat_rel_diff(&r.light_proj, &r0.light_proj), dm = mat_rel_diff(&r.matrix, &r0.matrix);
            ck_assert_msg(dp < 1e-9 && dm < 1e-9, "flat %d mode %zu: light_proj differs by %g, matrix by %g", flat, m, dp, dm);
        }
    }
}
END_TEST

/* The planner's γ next to π (a light travelling along the view): acos of
 * the rounded cosine would move γ by sqrt(eps) ~ 1e-8 with the rounding
 * mode and the predicted errors by 1e-7 relative; atan2(|v × l|, v · l) is
 * exact to an ulp.  A point light at the eye of a 1e6 world: the direction
 * to the frustum centre, rounded at the eye's magnitude, would put γ off π
 * by 1e-14 (max_error by 3e-9 between modes); relative to the eye it is
 * exact.  Independent reference: γ = π - (angle between the directions),
 * evaluated here from the construction. */
START_TEST(plan_gamma_rounding_mode) {
    for (int k = 0; k < 8; ++k) {
        swarp_scene_needs n;
        swarp_budget b;
        memset(&n, 0, sizeof n);
        memset(&b, 0, sizeof b);
        n.camera.eye = (swarp_vec3){1e3 * k, 5.0, -3.0 * k};
        n.camera.dir = (swarp_vec3){0.3 + 0.1 * k, -0.4, 0.7 - 0.05 * k};
        n.camera.up = (swarp_vec3){0, 1, 0};
        n.camera.fovy = 1.0;
        n.camera.aspect = 1.5;
        n.camera.z_near = 0.5;
        n.camera.z_far = 2000.0;
        if (k < 4) {
            n.light.type = SWARP_LIGHT_DIRECTIONAL;
            n.light.direction = n.camera.dir; /* travelling along the view: γ = π */
        } else { /* a point light at the eye of a 1e6 world: γ = π too */
            n.camera.eye.x += 1e6;
            n.camera.eye.z -= 1e6;
            n.light.type = SWARP_LIGHT_POINT;
            n.light.position = n.camera.eye;
        }
        swarp_plan_chain ch;
        memset(&ch, 0, sizeof ch);
        ch.warp = SWARP_PLAN_WARP_LISPSM_NREPAR;
        ch.scheme = SWARP_PLAN_SCHEME_PRACTICAL;
        ch.split_count = 4;
        swarp_plan_result p0, p;
        swarp_status s0 = swarp_plan_evaluate(&n, &b, &ch, &p0);
        ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
        ck_assert_msg(fabs(p0.gamma - 3.14159265358979323846) <= 4 * DBL_EPSILON, "gamma %.17g, want pi", p0.gamma);
        for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
            fesetround(tu_modes[m]);
            swarp_status s = swarp_plan_evaluate(&n, &b, &ch, &p);
            fesetround(FE_TONEAREST);
            ck_assert_int_eq(s, s0);
            ck_assert_msg(fabs(p.gamma - p0.gamma) <= 4 * DBL_EPSILON, "k %d mode %zu: gamma %.17g vs %.17g", k, m,
                          p.gamma, p0.gamma);
            ck_assert_msg(fabs(p.max_error - p0.max_error) <= 1e-9 * p0.max_error, "k %d mode %zu: max_error %.17g vs %.17g",
                          k, m, p.max_error, p0.max_error);
        }
    }
}
END_TEST

/* A tiny n (here the caller's n' = 1e-200) would make P's w row
 * eps y + (1 - eps y_min) lose its 1, so w = 0 at y_min on B.  w = 1 + (y - y_min)/n >= 1 on B is the defining
 * property of the warp; n is raised to 1e-6 max|y| (documented). */
static swarp_vec4 tu_xform(const swarp_mat4* m, swarp_vec3 p) { /* column-major m·(p, 1) */
    swarp_vec4 o;
    o.x = m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12];
    o.y = m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13];
    o.z = m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14];
    o.w = m->m[3] * p.x + m->m[7] * p.y + m->m[11] * p.z + m->m[15];
    return o;
}
START_TEST(warp_lispsm_tiny_n) {
    const swarp_camera cam = camera();
    const swarp_light l = sun(0.3, -1, 0.2);
    const swarp_aabb scene = {{-200, -5, -300}, {200, 30, 60}};
    swarp_mat4 L, P;
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &l, NULL, &L)));
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t np = 0;
    ck_assert(!swarp_status_is_error(
        swarp_body_points(&cam, 1.0, 100.0, &l, &scene, pts, SWARP_BODY_MAX_POINTS, &np)));
    const double n_users[] = {1e-200, 1e-30, 1e-12};
    for (size_t k = 0; k < sizeof n_users / sizeof n_users[0]; ++k) {
        swarp_warp_options o;
        memset(&o, 0, sizeof o);
        o.param = SWARP_WARP_PARAM_USER;
        o.n_user = n_users[k];
        swarp_warp_info info;
        ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1.0, 100.0, pts, np, NULL, &o, &P, &info), SWARP_OK);
        double ymax = 0;
        for (size_t i = 0; i < np; ++i) {
            swarp_vec4 h = tu_xform(&L, pts[i]);
            ymax = fmax(ymax, fabs(h.y / h.w));
        }
        ck_assert_msg(info.n_light >= 1e-6 * ymax * (1 - 1e-12), "n %g below 1e-6 max|y| = %g", info.n_light, 1e-6 * ymax);
        for (size_t i = 0; i < np; ++i) {
            swarp_vec4 h = tu_xform(&L, pts[i]);
            swarp_vec4 q = tu_xform(&P, (swarp_vec3){h.x / h.w, h.y / h.w, h.z / h.w});
            ck_assert_msg(q.w >= 1 - 1e-9, "n_user %g: point %zu has w = %.17g", n_users[k], i, q.w);
        }
    }
}
END_TEST

/* far = DBL_MAX is finite, valid input whose corners overflow: the
 * documented SWARP_ERR_OUT_OF_RANGE (not NON_FINITE, which is for bad
 * input), output untouched; just inside the range the frustum is finite. */
START_TEST(poly_from_camera_overflow) {
    swarp_camera cam = camera();
    swarp_polyhedron P;
    tu_fill(&P.vertices[0].x, 3, -7.25e33);
    ck_assert_int_eq(swarp_poly_from_camera_range(&cam, 0.5, DBL_MAX, &P), SWARP_ERR_OUT_OF_RANGE);
    ck_assert(tu_untouched(&P.vertices[0].x, 3, -7.25e33));
    cam.z_far = DBL_MAX;
    ck_assert_int_eq(swarp_poly_from_camera(&cam, &P), SWARP_ERR_OUT_OF_RANGE);
    ck_assert(tu_untouched(&P.vertices[0].x, 3, -7.25e33));
    ck_assert_int_eq(swarp_poly_from_camera_range(&cam, 0.5, 1e300, &P), SWARP_OK);
    for (uint32_t i = 0; i < P.vertex_count; ++i)
        ck_assert(isfinite(P.vertices[i].x) && isfinite(P.vertices[i].y) && isfinite(P.vertices[i].z));
}
END_TEST

/* A scene box reaching to z = -DBL_MAX (valid) overflows a sweep length
 * of 2 diag(S), which would give inf vertices with SWARP_OK.  B must be
 * finite: here it is H's 7 vertices swept the short way to the box's max
 * faces, all inside the box. */
START_TEST(body_points_box_to_dbl_max) {
    const swarp_camera cam = {{1366439.6125760672, 20.539473778929995, 1366457.5993474743},
                              {0.53707230541157913, -0.62290416505919799, -0.56880905399949},
                              {0, 1, 0}, 1.323016600788782, 1.6748388954771427, 1.3462811061770266,
                              13462811.061770264, {0, 0, 0, 0}};
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){-0.086309469311347087, -0.10000000000000001, -0.12764851323017479};
    const swarp_aabb box = {{1366439.6125760672, -9.3839128190509395, -DBL_MAX},
                            {1366538.0912439211, 20.539473778929995, 1366557.5993474743}};
    swarp_vec3 p[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status s = swarp_body_points(&cam, cam.z_near, cam.z_far, &l, &box, p, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(s), "%s", swarp_status_name(s));
    ck_assert(n >= 1);
    for (size_t i = 0; i < n; ++i) {
        ck_assert_msg(isfinite(p[i].x) && isfinite(p[i].y) && isfinite(p[i].z), "point %zu (%g %g %g)", i, p[i].x, p[i].y, p[i].z);
        ck_assert(p[i].x >= box.min.x - 1e-6 && p[i].x <= box.max.x + 1e-6 && p[i].y >= box.min.y - 1e-6 &&
                  p[i].y <= box.max.y + 1e-6 && p[i].z <= box.max.z + 1e-6);
    }
}
END_TEST

/* ---- valid input at the ends of the double range: setup ---------------- */

static int mat_finite(const swarp_mat4* m) {
    for (int i = 0; i < 16; ++i)
        if (!isfinite(m->m[i])) return 0;
    return 1;
}

/* A subnormal light direction is a valid direction: the view must be
 * finite (normalising by 1/|a| would overflow, inf * 0 = NaN). */
START_TEST(focus_light_view_subnormal_direction_is_finite) {
    swarp_camera cam = {{1, 2, 3}, {0, 0, -1}, {0, 1, 0}, 1.0, 1.5, 1, 100, {0, 0, 0, 0}};
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){4.9406564584124654e-324, 0, 0};
    swarp_mat4 V, F;
    swarp_status st = swarp_focus_light_view(&cam, &l, NULL, &V);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    ck_assert(mat_finite(&V));
    /* it looks along +x: row 2 (-forward) is (-1, 0, 0) */
    ck_assert(fabs(V.m[2] + 1) < 1e-15 && fabs(V.m[6]) < 1e-15 && fabs(V.m[10]) < 1e-15);
    /* the same through the follow twin */
    st = swarp_focus_light_view_follow(&cam, &l, NULL, NULL, &V, &F);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    ck_assert(mat_finite(&F));
}
END_TEST

/* An origin near DBL_MAX whose distance along the view axis exceeds
 * DBL_MAX: the view is not representable, so SWARP_ERR_OVERFLOW and the
 * output untouched. */
START_TEST(focus_light_view_translation_overflow_is_reported) {
    swarp_camera cam = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 1.5, 1, 100, {0, 0, 0, 0}};
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_POINT;
    l.position = (swarp_vec3){-DBL_MAX, -DBL_MAX, 0};
    swarp_vec3 axis = {1, 1, 0};
    swarp_mat4 V, P, S;
    memset(&V, 0xA5, sizeof V);
    S = V;
    ck_assert_int_eq(swarp_focus_light_view(&cam, &l, &axis, &V), SWARP_ERR_OVERFLOW);
    ck_assert(memcmp(&V, &S, sizeof V) == 0);
    /* the follow twin, with a valid previous view */
    swarp_light l0 = l;
    l0.position = (swarp_vec3){0, 10, 0};
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &l0, &axis, &P)));
    ck_assert_int_eq(swarp_focus_light_view_follow(&cam, &l, &axis, NULL, &P, &V), SWARP_ERR_OVERFLOW);
    ck_assert(memcmp(&V, &S, sizeof V) == 0);
    /* representable: an origin at DBL_MAX straight along the axis */
    l.position = (swarp_vec3){0, 0, DBL_MAX};
    axis = (swarp_vec3){0, 0, -1};
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &l, &axis, &V)));
    ck_assert(mat_finite(&V));
}
END_TEST

/* Point light 1e300 from the scene: a general inversion of P0 L calls it
 * singular (SWARP_ERR_SINGULAR, undocumented); the rigid inverse is exact,
 * so the setup succeeds. */
START_TEST(setup_point_light_1e300_away_rigid_inverse) {
    swarp_camera cam = {{0x1.71e732314ff46p+4, 0x1.d359e7729f874p+3, -0x1.71ce7489ccf2p+4},
                        {-0x1.793a0395a490fp-806, -0x1.c0bf34083786ep-1, 0x1.ed0849c0029adp-2},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.ff704895e684cp+0,
                        0x1.11d1e11ac3f0bp+1,
                        0x1p+0,
                        0x1.98878bb1bb0e8p+20,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.1a62633145c07p-53, 0x1.c0bf34083786ep-1, -0x1.ed0849c0029adp-2},
                     {0x1.71e732314ff46p+4, 0x1.7e43c8800759cp+996, -0x1.6a1a5362cce79p+4}, 0x0p+0, {0, 0, 0, 0}};
    swarp_aabb box = {{-0x0.0000000000001p-1022, -0x1.b7139c483011cp-328, -0x1.b4203ac68cfcap+4},
                      {0x1.2d049d7653df6p+6, 0x1.2896faf258974p+4, -0x1.543ba6e46a2cap+4}};
    swarp_setup_result r;
    swarp_status st = swarp_setup(&cam, &l, &box, NULL, &r, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    ck_assert(mat_finite(&r.matrix) && mat_finite(&r.light_view) && mat_finite(&r.light_proj));
}
END_TEST

/* swarp_warp_lispsm with the look-at of a spot light 1e302 above: a rigid
 * view has an exact inverse, so no SWARP_ERR_SINGULAR (undocumented). */
START_TEST(warp_lispsm_far_light_view_rigid_inverse) {
    swarp_camera cam = {{0, 5, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 1.5, 1, 100, {0, 0, 0, 0}};
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_POINT;
    l.position = (swarp_vec3){0, 1e302, 0};
    l.direction = (swarp_vec3){0.1, -1, 0.2};
    l.cone_angle = 0.5;
    swarp_mat4 L, P;
    ck_assert(!swarp_status_is_error(swarp_focus_light_view(&cam, &l, NULL, &L)));
    swarp_vec3 pts[4] = {{-10, 0, -5}, {10, 0, -5}, {-20, 1, -60}, {20, 2, -60}};
    swarp_status st = swarp_warp_lispsm(&L, &cam, 1, 100, pts, 4, NULL, NULL, &P, NULL);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    ck_assert(mat_finite(&P));
}
END_TEST

/* An eye 1e145 from a 40-unit body: relative to the eye its points are all
 * equal, so no map puts them in the unit square: the documented
 * SWARP_ERR_DEGENERATE (the map is finer than the coordinates resolve). */
START_TEST(setup_points_eye_far_from_body_is_degenerate) {
    swarp_camera cam = {{0x1.49af6d2161444p+481, 0x1.898860b8bbd58p+3, -0x1.e848p+19},
                        {0x1.159f5e7fdada8p-1, -0x1.6ec3667adb363p-6, -0x1.ae0b6b71f612ap-1},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.999999999999ap-4,
                        0x1.8p+1,
                        0x1.79bb7e9d955a3p-7,
                        0x1.4524706a02c5dp-3,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {0x1.1765708e644aep-1, 0x1.2b5d695975ae2p-7, 0x1.ad05a0439b166p-1},
                     {0, 0, 0}, 0, {0, 0, 0, 0}};
    swarp_vec3 pts[2] = {{-0x1.e848fe9d2ce6ep+19, -0x1.729dbec5c4df3p+2, -0x1.e844fadc383ebp+19},
                         {-0x1.e84d93f0e5df1p+19, 0x1.8d33911d53ba4p+1, -0x1.e845401f1608dp+19}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_UNIFORM;
    swarp_setup_result r, s;
    memset(&r, 0xA5, sizeof r);
    s = r;
    /* the documented DEGENERATE, or (the body is one point to the rounding
     * of its coordinates: SWARP_INFO_FLAT_EXTENT, a width of 1e-6 of them)
     * a map with B inside */
    swarp_status st = swarp_setup_points(&cam, &l, pts, 2, NULL, 0, cam.z_near, cam.z_far, &o, &r);
    ck_assert_msg(st == SWARP_ERR_DEGENERATE || st == SWARP_INFO_FLAT_EXTENT, "%s", swarp_status_name(st));
    if (st == SWARP_ERR_DEGENERATE) ck_assert(memcmp(&r, &s, sizeof r) == 0);
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) { /* the same body seen from 100 units: mapped into the unit square */
            cam.eye = (swarp_vec3){-1000100, 5, -1000000};
            st = swarp_setup_points(&cam, &l, pts, 2, NULL, 0, cam.z_near, cam.z_far, &o, &r);
            ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        }
        if (st == SWARP_ERR_DEGENERATE) continue;
        for (int i = 0; i < 2; ++i) {
            const swarp_mat4* m = &r.matrix;
            double w = m->m[3] * pts[i].x + m->m[7] * pts[i].y + m->m[11] * pts[i].z + m->m[15];
            double x = (m->m[0] * pts[i].x + m->m[4] * pts[i].y + m->m[8] * pts[i].z + m->m[12]) / w;
            double y = (m->m[1] * pts[i].x + m->m[5] * pts[i].y + m->m[9] * pts[i].z + m->m[13]) / w;
            ck_assert_msg(fabs(x) <= 1 + 1e-6 && fabs(y) <= 1 + 1e-6, "pass %d point %d at (%g, %g)", pass, i, x, y);
        }
    }
}
END_TEST

/* ---- B and H at grazing lights and at the ends of the double range ----- */

/* B of a light all but parallel to faces of H.  A side face through a
 * silhouette edge taken from the cross product of the edge and u tilts at
 * random when the edge is all but parallel to u, and cuts H (a vertex of B
 * 1.9 outside its own face in a box of size 80).  The H below are written
 * out exactly in hex. */
static swarp_polyhedron poly_of(const swarp_vec3* v, uint32_t nv, const swarp_plane* pl, const uint8_t (*loops)[8],
                                const uint32_t* counts, uint32_t nf) {
    swarp_polyhedron p;
    memset(&p, 0, sizeof p);
    p.vertex_count = nv;
    p.face_count = nf;
    for (uint32_t i = 0; i < nv; ++i) p.vertices[i] = v[i];
    for (uint32_t f = 0; f < nf; ++f) {
        p.planes[f] = pl[f];
        p.face_vertex_count[f] = counts[f];
        for (uint32_t k = 0; k < counts[f]; ++k) p.face_vertices[f][k] = loops[f][k];
    }
    return p;
}
static double plane_at(const swarp_plane* p, swarp_vec3 v) { return p->a * v.x + p->b * v.y + p->c * v.z + p->d; }
/* B a valid convex polyhedron holding H (tol: 1e-9 of the coordinates, as tests/robust) */
static void check_body(const swarp_polyhedron* B, const swarp_polyhedron* H, double tol) {
    ck_assert(B->vertex_count > 0);
    for (uint32_t f = 0; f < B->face_count; ++f) {
        for (uint32_t v = 0; v < B->vertex_count; ++v)
            ck_assert_msg(plane_at(&B->planes[f], B->vertices[v]) <= tol, "B: vertex %u outside face %u by %g", v, f,
                          plane_at(&B->planes[f], B->vertices[v]));
        for (uint32_t k = 0; k < B->face_vertex_count[f]; ++k)
            ck_assert_msg(fabs(plane_at(&B->planes[f], B->vertices[B->face_vertices[f][k]])) <= tol, "B: face %u vertex %u off", f, k);
        for (uint32_t v = 0; v < H->vertex_count; ++v)
            ck_assert_msg(plane_at(&B->planes[f], H->vertices[v]) <= tol, "H: vertex %u outside face %u of B by %g", v, f,
                          plane_at(&B->planes[f], H->vertices[v]));
    }
}
START_TEST(body_from_h_grazing) {
    { /* faces of H along u */
        const swarp_vec3 v[8] = {{1000013.2954460557, -8.9844438238526063, 1000047.9719960216},
                                 {1000013.2636823052, -8.9844438238526063, 1000048.0026541286},
                                 {1000013.3525812096, -8.8624380987345592, 1000048.0311916781},
                                 {1000013.3208174591, -8.8624380987345592, 1000048.0618497852},
                                 {1000014.9888504959, -10, 1000049.5887847046},
                                 {1000014.1419592315, -10, 1000048.7651116069},
                                 {1000014.0263221718, -10, 1000048.8767235321},
                                 {1000014.8194869936, -10, 1000049.7522529442}};
        const swarp_plane pl[6] = {{0.69705353393728475, 0.021305661978565271, -0.71670247634091355, 19674.247833837289},
                                   {-0.74093821012435601, 0.021305661978565271, 0.67123515815649182, 69680.84988727828},
                                   {-0.4577813317784053, -0.75198715247401371, -0.47429060162437747, 932094.01629031124},
                                   {0.3125613629799564, 0.89299343697151956, 0.32383346939114305, -636406.645880464},
                                   {-0.57579407390566717, 0.5590869056707003, -0.59655931504141047, 1172394.6856121109},
                                   {0, -1, 0, -10}};
        const uint8_t loops[6][8] = {{0, 2, 4, 5}, {1, 6, 7, 3}, {0, 5, 6, 1}, {2, 3, 7, 4}, {0, 1, 3, 2}, {4, 7, 6, 5}};
        const uint32_t counts[6] = {4, 4, 4, 4, 4, 4};
        const swarp_polyhedron H = poly_of(v, 8, pl, loops, counts, 6);
        const swarp_light l = sun(-0.71951851024007607, -3.4234199473741066e-17, 0.69447326328801262);
        const swarp_aabb box = {{1000000, -10, 999995.49762011471}, {1000100, -8.0801787172850155, 1000095.4976201147}};
        swarp_polyhedron B;
        ck_assert_int_eq(swarp_body_from_h(&H, &l, &box, &B), SWARP_OK);
        check_body(&B, &H, 1e-9 * 1000100.0);
    }
    { /* a sliver H (1.7e-7 thick at 1e5) in a flat box */
        const swarp_vec3 v[6] = {{100048.25590152819, -2.0543779807876397, 99958.893644363838},
                                 {100048.25590152819, -2.0543779807876397, 99958.893644190059},
                                 {100048.25590162282, -2.054377543344311, 99958.893644363838},
                                 {100048.25590162282, -2.054377543344311, 99958.893644190059},
                                 {100040.32603357387, 1.613135543318911, 99958.893644276948},
                                 {100039.53266287014, -2.054377973499284, 99958.893644276948}};
        const swarp_plane pl[5] = {{0.41977270840732089, 0.9076292598172353, -0.0, -41995.662738083891},
                                   {0.97739165452070753, -0.21143687869734071, -0.0, -97786.764738773694},
                                   {0, -1, 0, -2.054377973499284},
                                   {0, 0, -1, 99958.893644276948},
                                   {0, 0, 1, -99958.893644276948}};
        const uint8_t loops[5][8] = {{2, 3, 4}, {0, 1, 3, 2}, {0, 5, 1}, {2, 3, 0, 1, 5, 4}, {0, 1, 2, 3, 4, 5}};
        const uint32_t counts[5] = {3, 4, 3, 6, 6};
        const swarp_polyhedron H = poly_of(v, 6, pl, loops, counts, 5);
        const swarp_light l = sun(-0.97739242680818161, 0.21143330867678684, -1.0000000000000001e-09);
        const swarp_aabb box = {{99967.318617837038, -2.054377973499284, 99958.893644276948},
                                {100048.25590255289, 16.564658620014637, 99958.893644276948}};
        swarp_polyhedron B;
        ck_assert_int_eq(swarp_body_from_h(&H, &l, &box, &B), SWARP_OK);
        check_body(&B, &H, 1e-9 * 100048.25590255289);
    }
    { /* a flat H, u 1e-9 out of its plane: the two faces at a
         silhouette edge are opposite, their combination cancels (the side
         plane comes from the edge then) */
        const swarp_vec3 v[4] = {{999957.33045117056, -2.4299542947557908, 999996.63614671386},
                                 {999979.39726582309, -2.4299542947557908, 999996.63614671386},
                                 {999957.33045117056, 20.09206042700847, 999996.63614671386},
                                 {999979.39726582309, 20.09206042700847, 999996.63614671386}};
        const swarp_plane pl[2] = {{0, 0, -0.99999999999999989, 999996.63614671375}, {0, 0, 1, -999996.63614671386}};
        const uint8_t loops[2][8] = {{0, 2, 3, 1}, {0, 1, 3, 2}};
        const uint32_t counts[2] = {4, 4};
        const swarp_polyhedron H = poly_of(v, 4, pl, loops, counts, 2);
        const swarp_light l = sun(0.7795, -0.626402, -1e-09);
        const swarp_aabb box = {{999957.33045117056, -2.4299542947557908, 999996.63614671386},
                                {999979.39726582309, 20.09206042700847, 999996.63614671386}};
        swarp_polyhedron B;
        ck_assert_int_eq(swarp_body_from_h(&H, &l, &box, &B), SWARP_OK);
        check_body(&B, &H, 1e-9 * 999996.63614671386);
    }
    { /* a flat H 1e-6 across at 1e6 (1e-12 relative): its two faces'
         normals are noise 6e-6 apart, their combination can be the same
         plane for all four side faces (B's vertices 0.05 off them) */
        const swarp_vec3 v[4] = {{1000019.2898066387, -9.6434890779410534, 999987.01980257814},
                                 {1000019.2898077613, -9.6434890779410534, 999987.01980135264},
                                 {1000019.2898066947, -9.6434866056056485, 999987.01980262937},
                                 {1000019.2898078172, -9.6434866056056485, 999987.01980140386}};
        const swarp_plane pl[2] = {{0.73706029448968602, -0.03066388804624055, 0.67513098599950572, -1412197.0306131393},
                                   {-0.73705558950557382, 0.03065810914696479, -0.67513638497871231, 1412197.7243911668}};
        const uint8_t loops[2][8] = {{0, 1, 3, 2}, {0, 2, 3, 1}};
        const uint32_t counts[2] = {4, 4};
        const swarp_polyhedron H = poly_of(v, 4, pl, loops, counts, 2);
        const swarp_light l = sun(-0.737046, 0.030662, -0.675147);
        const swarp_aabb box = {{999989.95603555243, -9.6434878724353403, 999967.10043944884},
                                {1000019.289807965, 0.80153271073714905, 1000001.6590176614}};
        swarp_polyhedron B;
        ck_assert_int_eq(swarp_body_from_h(&H, &l, &box, &B), SWARP_OK);
        check_body(&B, &H, 1e-9 * 1000019.289807965);
    }
    { /* a spot whose direction is (4.9e-324, 0, 0) is valid (not zero): no
         SWARP_ERR_ZERO_VECTOR, though 1/|d| overflows */
        const swarp_aabb hb = {{-2, -8, -40}, {12, -8, 50}}, scene = {{-3, -9, -45}, {13, 10, 56}};
        swarp_polyhedron H, B, R;
        ck_assert_int_eq(swarp_poly_from_aabb(&hb, &H), SWARP_OK);
        swarp_light spot;
        memset(&spot, 0, sizeof spot);
        spot.type = SWARP_LIGHT_POINT;
        spot.position = (swarp_vec3){-30, -8, 5};
        spot.direction = (swarp_vec3){4.9406564584124654e-324, 0, 0};
        spot.cone_angle = 1.34;
        ck_assert_int_eq(swarp_body_from_h(&H, &spot, &scene, &B), SWARP_OK);
        ck_assert_int_eq(swarp_body_receivers(&H, &spot, &R), SWARP_OK);
        ck_assert(R.vertex_count > 0);
        for (uint32_t i = 0; i < R.vertex_count; ++i) ck_assert(isfinite(R.vertices[i].x) && R.vertices[i].x >= -2 - 1e-9);
    }
}
END_TEST

/* H of a frustum 1e308 times wider than high (aspect > 0 is valid).  Its
 * corners reach 1e12 far, and clipping V by the box works at that scale
 * (vertices of H off S's faces by 0.016); H is S clipped by V's planes, at
 * S's scale, so H lies in S. */
START_TEST(body_h_wide_frustum) {
    const struct {
        swarp_vec3 eye, dir;
        double fovy, aspect, z_near, z_far;
        swarp_aabb box;
    } cs[2] = {{{-31.751584031759648, 100.45574252696035, 62.857658427288321},
                {-0.018260733025294202, -0.95564929522641417, -0.29394041940950671},
                2.2465414555918914, 599831027782.41699, 0.11888177530992466, 264256.68945755722,
                {{-31.751584031759648, -6.8721496823754737, -14.170167836906506},
                 {-31.751584031759648, 14.275260174198303, 80.365812504042381}}},
               {{29.676834685905799, -4.030733603187139, 15.120412622492502},
                {-0.25397572117364237, 0.3490883434295603, -0.90201644194323505},
                1.2087456828278447, 1.7976931348623157e+308, 0.36992942317370747, 539.33774063933242,
                {{-2.822924792926608e-87, -6.4778537620193246, -27.39234609960095},
                 {48.621515276744233, 15.709044089674826, 30.299721219030182}}}};
    for (int i = 0; i < 2; ++i) {
        swarp_camera cam;
        memset(&cam, 0, sizeof cam);
        cam.eye = cs[i].eye, cam.dir = cs[i].dir, cam.up = (swarp_vec3){0, 1, 0};
        cam.fovy = cs[i].fovy, cam.aspect = cs[i].aspect, cam.z_near = cs[i].z_near, cam.z_far = cs[i].z_far;
        swarp_polyhedron H;
        ck_assert_int_eq(swarp_body_h(&cam, cam.z_near, cam.z_far, &cs[i].box, &H), SWARP_OK);
        const swarp_aabb* b = &cs[i].box;
        const double tol = 1e-9 * (cam.z_far + 100);
        const double dl = sqrt(cam.dir.x * cam.dir.x + cam.dir.y * cam.dir.y + cam.dir.z * cam.dir.z);
        ck_assert(H.vertex_count > 0);
        for (uint32_t v = 0; v < H.vertex_count; ++v) {
            const swarp_vec3 p = H.vertices[v];
            ck_assert_msg(p.x >= b->min.x - tol && p.x <= b->max.x + tol && p.y >= b->min.y - tol && p.y <= b->max.y + tol &&
                              p.z >= b->min.z - tol && p.z <= b->max.z + tol,
                          "case %d: vertex %u (%.17g %.17g %.17g) outside S", i, v, p.x, p.y, p.z);
            const double z = ((p.x - cam.eye.x) * cam.dir.x + (p.y - cam.eye.y) * cam.dir.y + (p.z - cam.eye.z) * cam.dir.z) / dl;
            ck_assert_msg(z >= cam.z_near - tol && z <= cam.z_far + tol, "case %d: vertex %u at depth %g", i, v, z);
        }
        for (uint32_t f = 0; f < H.face_count; ++f)
            for (uint32_t k = 0; k < H.face_vertex_count[f]; ++k)
                ck_assert_msg(fabs(plane_at(&H.planes[f], H.vertices[H.face_vertices[f][k]])) <= tol, "case %d: off face %u", i, f);
    }
}
END_TEST

/* Magnitudes at the ends of the double range.  A clip plane with
 * coefficients of 1e-321 (valid: not zero) has 1/|n| = inf and must still
 * cut; the frustum of a matrix with w ~ 6e159 is 1e-160 across, and its
 * Newell normals, products of 1e-320, must be scaled to stay finite. */
START_TEST(poly_tiny_magnitudes) {
    const swarp_aabb box = {{-30, -30, -30}, {30, 30, 30}};
    swarp_polyhedron P, Q;
    ck_assert_int_eq(swarp_poly_from_aabb(&box, &P), SWARP_OK);
    /* x + z <= 20.005: subnormals have few digits, the ratio is exact here */
    const swarp_plane pl = {4.575047880489943e-321, 0, 4.575047880489943e-321, -9.1525660892090922e-320};
    const double bound = -pl.d / pl.a;
    ck_assert_int_eq(swarp_poly_clip(&P, &pl, &Q), SWARP_OK);
    ck_assert(Q.vertex_count > 0);
    for (uint32_t v = 0; v < Q.vertex_count; ++v)
        ck_assert_msg(Q.vertices[v].x + Q.vertices[v].z <= bound + 1e-9, "vertex %u: x + z = %g", v, Q.vertices[v].x + Q.vertices[v].z);
    const swarp_mat4 m = {{2.8407183450518398, 1.7568812543004477, -0.56368800435547906, 0, -2, 2.9999999999989999,
                           1.759516522821905, 0, 0.78539816339744828, 0.18619150977600629, 1.4085524255937107,
                           1.0000000000000001e-09, 0, -1.0000000000010001, 0.20909585652742102, -5.7746782753919336e+159}};
    swarp_polyhedron F;
    swarp_status st = swarp_poly_from_inverse_matrix(&m, SWARP_DEPTH_DEFAULT, &F);
    ck_assert_msg(st == SWARP_OK || st == SWARP_ERR_DEGENERATE, "%s", swarp_status_name(st));
    if (st == SWARP_OK) assert_unit_planes(&F, 0);
}
END_TEST

/* The smallest subnormal fovy is a valid field of view; halved it is 0,
 * which the warp parameter must not refuse (SWARP_ERR_FOV is undocumented
 * for a valid fovy). */
START_TEST(setup_range_subnormal_fovy_is_valid) {
    swarp_camera cam = {{0x1.86c4978ef9536p+16, -0x1.7e12ad692e853p+1, 0x1.8683be8199ed1p+16},
                        {-0x1.c6ae222b55f79p-1, 0x1.06ee28b51c309p-4, -0x1.d22cb9b34eeb2p-2},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x0.0000000000001p-1022,
                        0x1.9c43c695bc526p+0,
                        0x1.22d8dc3f15a5ap-14,
                        0x1.8b97c10ffc18dp+5,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.c6ae222b55f79p-1, 0x1.06ee28b51c309p-4, -0x1.d22cb9b34eeb2p-2},
                     {0, 0, 0}, 0, {0, 0, 0, 0}};
    swarp_aabb box = {{0x1.869952dda13bdp+16, -0x1.7e12ad692e853p+1, 0x1.867e7b2560306p+16},
                      {0x1.86c4978ef9536p+16, 0x1.9c6f29668f0aap+4, 0x1.869fdceae757ep+16}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_NREPAR;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.pancake = 1;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    o.map_height = 811;
    swarp_setup_result r;
    swarp_status st = swarp_setup_range(&cam, &l, &box, 0x1.cfcb70fa39a15p-13, 0x1.280f1e4189b74p-1, &o, &r, NULL, 0, NULL);
    /* a fovy of 5e-324 rad: the frustum is far narrower than its
     * coordinates resolve, the documented DEGENERATE (or a map) */
    ck_assert_msg(st == SWARP_ERR_DEGENERATE || !swarp_status_is_error(st), "%s", swarp_status_name(st));
}
END_TEST

/* near = DBL_MIN: α = z_1/z_0 of [RHS] (3.4) overflows, and n_repar must
 * still accept the valid arguments (no SWARP_ERR_NON_FINITE). */
START_TEST(setup_nrepar_near_dbl_min_is_valid) {
    swarp_camera cam = {{-0x1.1c9549fe5c6c1p+4, -0x1.f792bb36cd1f9p-1, 0x1.18d1b543d373ep+5},
                        {0x1.a2ef07efc7027p-1, 0x1.9e45c0e4a9906p-4, -0x1.21c0d5e1e81edp-1},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.a6fbae82b6eefp+0,
                        0x1.0d03d4f03839fp+1,
                        0x1p-1022,
                        0x1.71df582e33329p+15,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {0x1.3f72c8ee79cap-2, -0x1.ffd84f5e70dbdp-1, 0x1.500aff69a3bd6p-1},
                     {0, 0, 0}, 0, {0, 0, 0, 0}};
    swarp_aabb box = {{-0x1.1c9549fe5c6c1p+4, -0x1.b3a9e9d4033b9p+0, -0x1.124c623a923d2p+5},
                      {0x1.1dfc04dd52f24p+6, 0x1.69653482278b7p+3, 0x1.3e85ed0e8e98ap+5}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_LISPSM;
    o.param = SWARP_WARP_PARAM_NREPAR;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.map_width = 697;
    o.pancake = 1;
    swarp_setup_result r;
    swarp_status st = swarp_setup(&cam, &l, &box, &o, &r, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    ck_assert(mat_finite(&r.matrix) && r.n_eye > 0);
}
END_TEST

/* A spot light straight above the eye with a horizontal axis: s (on the
 * view vector at the near depth) lies in the light's plane, and its
 * x/D = 1e17 taken as the uniform warp's x translation would swamp B's x in
 * the map (all points at x = 1.2).  The fit must stay tight on B. */
START_TEST(setup_points_uniform_warp_centre_keeps_fit_tight) {
    swarp_camera cam = {{-0x1.e848247b8083p+19, 0x1.96ed5aa033d04p+2, -0x1.e84c2c75ac433p+19},
                        {0x1.d02ea0429890ap-2, -0x1.e82c012416c1ep-4, 0x1.c446ceb05efc7p-1},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.d52e17ddcc899p-1,
                        0x1.76afb27592d01p+1,
                        0x1.9aaee41c21907p+0,
                        0x1.90043a8556c02p+4,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.c785fd9e89c53p-1, -0x1.0d3e0ba095613p-57, 0x1.d383b06670932p-2},
                     {-0x1.e848247b8083p+19, 0x1.3f4f1c1891c7fp+7, -0x1.e84c2c75ac433p+19}, 0x1.7ea6c495c137fp+0, {0, 0, 0, 0}};
    swarp_vec3 pt[6] = {{-0x1.e848247b8083p+19, -0x1.f5f6145520c98p+0, -0x1.e848c6b2e6ccp+19},
                        {-0x1.e848247b8083p+19, 0x1.96ed5aa033d02p+2, -0x1.e848a2c821459p+19},
                        {-0x1.e84821da81143p+19, -0x1.f5f6145520c98p+0, -0x1.e848c80c421ffp+19},
                        {-0x1.e8480136c66f2p+19, 0x1.96ed5aa033d02p+2, -0x1.e848b4e153dfcp+19},
                        {-0x1.e848247b8083p+19, 0x1.96ed5aa033d02p+2, -0x1.e848f99ba2d63p+19},
                        {-0x1.e848247b8083p+19, -0x1.f5f6145520c98p+0, -0x1.e848cd2bbb3p+19}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_PSEUDO;
    o.center = SWARP_WARP_CENTER_VIEW_VECTOR;
    o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    o.map_width = 6555;
    o.pseudo_near = 0x1.664ad2a28c6f8p-2;
    o.pseudo_far = 0x0.0000000000001p-1022;
    swarp_setup_result r;
    swarp_status st = swarp_setup_points(&cam, &l, pt, 6, NULL, 0, cam.z_near, cam.z_far, &o, &r);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    double xlo = INFINITY, xhi = -INFINITY;
    for (int i = 0; i < 6; ++i) {
        const double* m = r.matrix.m;
        double w = m[3] * pt[i].x + m[7] * pt[i].y + m[11] * pt[i].z + m[15];
        double x = (m[0] * pt[i].x + m[4] * pt[i].y + m[8] * pt[i].z + m[12]) / w;
        double y = (m[1] * pt[i].x + m[5] * pt[i].y + m[9] * pt[i].z + m[13]) / w;
        ck_assert_msg(fabs(x) <= 1 + 1e-6 && fabs(y) <= 1 + 1e-6, "point %d at (%g, %g)", i, x, y);
        xlo = fmin(xlo, x), xhi = fmax(xhi, x);
    }
    ck_assert(xlo < -1 + 1e-6 && xhi > 1 - 1e-6); /* the fit is tight */
}
END_TEST

/* PSM with the eye 1e289 from a 50-unit body: relative to the eye the body
 * is one point, and light_proj · light_view overflows (inf - inf) while
 * matrix is finite: the documented DEGENERATE, not a map with SWARP_INFO. */
START_TEST(setup_points_psm_eye_far_from_body_is_degenerate) {
    swarp_camera cam = {{0x1.aac211d559113p+959, 0x1.74fe32580155ep+1, 0x1.5d2432787951p+0},
                        {-0x1.e6807cfbc537ep-1, -0x1.268e4e5a6a742p-2, -0x1.eb24e534fe96cp-4},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.3c95715169bb5p+1,
                        0x1.3ed4427b72df2p-1,
                        0x1.4732188490c3bp+0,
                        0x1.00fa989f66b5ep+2,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.e6807cfab1e6ap-1, -0x1.268e4e5a6a742p-2, -0x1.eb24e5792c5ap-4},
                     {0, 0, 0}, 0, {0, 0, 0, 0}};
    swarp_vec3 pt[3] = {{0x1.9884397165cdcp+2, 0x1.53a5e2ab1c218p-1, -0x1.211ae2314cea2p+4},
                        {0x1.cc86f78ba8c9cp+2, 0x1.8f9befc060f4ep+1, -0x1.b13f54738cb48p+4},
                        {0x1.17a47874e096p-1, 0x1.55fd9c258512dp+2, 0x1.9e6558e8d9249p+4}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.map_width = 4943;
    swarp_setup_result r, s;
    memset(&r, 0xA5, sizeof r);
    s = r;
    ck_assert_int_eq(swarp_setup_points(&cam, &l, pt, 3, NULL, 0, cam.z_near, cam.z_far, &o, &r), SWARP_ERR_DEGENERATE);
    ck_assert(memcmp(&r, &s, sizeof r) == 0);
}
END_TEST

/* The adjusted range of a camera range one ulp wide
 * ([0.99999999999999989, 1]): H's depths can round above far, and the
 * adjusted range must still be clamped to [near, far]. */
START_TEST(body_adjusted_range_one_ulp) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){11.509831960162812, -7.2106133800437053, 0.34703178313814753};
    cam.dir = (swarp_vec3){-0.26106181297126391, -0.88646162764194136, 0.38214200570803103};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 1.7508506598448992, cam.aspect = 3, cam.z_near = 0.99999999999999989, cam.z_far = 1;
    const swarp_aabb box = {{-9.9561291108274386, -10, -5.6886195800143984}, {78.505664793093032, 9.8170292419075551, 3.1276577551680216}};
    double n = 0, f = 0;
    ck_assert_int_eq(swarp_body_adjusted_range(&cam, &box, &n, &f), SWARP_OK);
    ck_assert_msg(n > 0 && n <= f && n >= cam.z_near && f <= cam.z_far, "[%.17g, %.17g]", n, f);
}
END_TEST

/* The frustum of a matrix with an entry of DBL_MAX has corners near 1e308;
 * their Newell products overflow to inf - inf = NaN, and no NaN normal may
 * be returned as a face. */
START_TEST(poly_inverse_matrix_huge_corners) {
    const swarp_mat4 m = {{1.9999999999989999, -1.1416761360720704, -1.9634786958989037, 0, 0.12766934452880419,
                           1.9716232880096882, -1.7976931348623157e+308, 0.43955323912948341, -1.6191533742741608,
                           0.060677882451510623, 5, -1.706102236203459, -0.51801303466671111, 0.77630261907177101,
                           0.71652301741605839, 3.4483558380081316}};
    swarp_polyhedron F;
    swarp_status st = swarp_poly_from_inverse_matrix(&m, SWARP_DEPTH_ZERO_TO_ONE, &F);
    ck_assert_msg(st == SWARP_OK || st == SWARP_ERR_DEGENERATE, "%s", swarp_status_name(st));
    if (st == SWARP_OK) assert_unit_planes(&F, 1);
}
END_TEST

/* A spot light 0.27 above a flat box, the eye in the box's plane: s (on the
 * view vector at the near depth) lies on the light's plane (D ~ 1e-11); its
 * x/D = 5e10 taken as the warp's lateral centre would bring a shear that
 * puts B's x below its rounding (a point at x = 1.00004).  B must map into
 * the unit square. */
START_TEST(setup_point_light_centre_on_light_plane_maps_inside) {
    swarp_camera cam = {{0x1.e8489b298e53p+19, -0x1.4e03ed68df875p+2, 0x1.e846d0a22d44ap+19},
                        {0x1.c3aec609db329p-1, 0x0p+0, 0x1.e230911a52e69p-2},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.05a47b3f24a56p+0,
                        0x1.2c4ede2c738fdp+1,
                        0x1.b8c4f5e60e437p+0,
                        0x1.d77cd19ca582p+2,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {0x1.8abb67e310fe8p-4, 0x0p+0, 0x1.fd9def25f410ap-1},
                     {0x1.e848cbc48cd3dp+19, -0x1.3c8ef0cc86af4p+2, 0x1.e846ea93e0f29p+19}, 0x1.30cf338b35632p-3,
                     {0, 0, 0, 0}};
    swarp_aabb box = {{0x1.e848p+19, -0x1.4e03ed68df875p+2, 0x1.e841cp+19},
                      {0x1.e84e2ade088ecp+19, -0x1.4e03ed68df875p+2, 0x1.e84e4p+19}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.center = SWARP_WARP_CENTER_VIEW_VECTOR;
    o.map_width = 1364;
    o.psm_slideback = 1;
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status st = swarp_setup(&cam, &l, &box, &o, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    for (size_t i = 0; i < n; ++i) {
        const double* m = r.matrix.m;
        double w = m[3] * pts[i].x + m[7] * pts[i].y + m[11] * pts[i].z + m[15];
        double x = (m[0] * pts[i].x + m[4] * pts[i].y + m[8] * pts[i].z + m[12]) / w;
        double y = (m[1] * pts[i].x + m[5] * pts[i].y + m[9] * pts[i].z + m[13]) / w;
        ck_assert_msg(fabs(x) <= 1 + 1e-6 && fabs(y) <= 1 + 1e-6, "point %zu at (%.9g, %.9g)", i, x, y);
    }
}
END_TEST

/* A spot light 2e154 above a 50-unit body: its light-view coordinates
 * (the translation 2e154) do not resolve the body, so no map fits it (a
 * point would land at x = -2.1): the documented DEGENERATE. */
START_TEST(setup_point_light_2e154_away_is_degenerate) {
    swarp_camera cam = {{-0x1.6e3746b57bb8cp+21, 0x1.3330e86131c35p+5, -0x1.6e35e263c471ep+21},
                        {-0x1.91a556151761bp-3, -0x1.bdc23e852900dp-1, -0x1.cdff9fb356447p-2},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.ae06408e7d94ep-1,
                        0x1.3333333333333p-2,
                        0x1.fffffffffdcd1p-1,
                        0x1.21626596ca6bap+20,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.91a556151761bp-3, -0x1.bdc23e852900dp-1, -0x1.cdff9fb356447p-2},
                     {-0x1.6e3746b57bb8cp+21, 0x1.99481b8e2d12dp+512, -0x1.6e374a0d1b9e4p+21}, 0x1.3b5949d5d655ap+0,
                     {0, 0, 0, 0}};
    swarp_aabb box = {{-0x1.6e3746b57bb8cp+21, -0x1.3258b0b4fb3ddp+0, -0x1.6e373408d8f68p+21},
                      {-0x1.6e3746b57bb8cp+21, 0x1.051ec67767d45p+2, -0x1.6e35c32c84069p+21}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_UNIFORM;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    o.map_width = 4329;
    o.min_depth = 0x1p-1022;
    swarp_setup_result r, s;
    memset(&r, 0xA5, sizeof r);
    s = r;
    ck_assert_int_eq(swarp_setup(&cam, &l, &box, &o, &r, NULL, 0, NULL), SWARP_ERR_DEGENERATE);
    ck_assert(memcmp(&r, &s, sizeof r) == 0);
}
END_TEST

/* PSM with aspect = DBL_MAX: recovering the previous frame's light camera
 * multiplies by t_x = t_y aspect = inf, and a valid previous result must
 * not be called a zero vector. */
START_TEST(setup_follow_psm_huge_aspect_no_zero_vector) {
    swarp_camera cam = {{0x1.240283d4ef769p+20, -0x1.1a29897f74798p-2, 0x1.23ffb15341e55p+20},
                        {0x1.c8b217d9ea3b4p-2, -0x1.432dc5cd31b8cp-1, -0x1.44e51b6ce2b8dp-1},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.59d7e8f953599p+1,
                        DBL_MAX,
                        0x1.000004807ffd3p+0,
                        0x1.85aab9035386ap+1,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.1c377cef048cep-1, -0x1.fb3d86895eabbp-2, -0x1.a8524d35126a8p-3},
                     {0, 0, 0}, 0, {0, 0, 0, 0}};
    swarp_aabb box = {{0x1.23ff6eaf7d3edp+20, -0x1.42dda5d8d41bap+1, 0x1.23fdbf7fabebap+20},
                      {0x1.240356a61a942p+20, 0x1.f5e554cec5448p-1, 0x1.2400b737d307fp+20}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    swarp_setup_result prev, r;
    swarp_status s0 = swarp_setup(&cam, &l, &box, &o, &prev, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
    swarp_status st = swarp_setup_follow(&cam, &l, &box, &o, NULL, &prev, &r, NULL, 0, NULL);
    /* the light camera's x axis is squashed to nothing by an aspect of
     * DBL_MAX: no usable right vector, the documented FOLLOW_FRAME (or a
     * frame), never an undocumented ZERO_VECTOR for a valid previous */
    ck_assert_msg(st == SWARP_ERR_FOLLOW_FRAME || !swarp_status_is_error(st), "%s", swarp_status_name(st));
}
END_TEST

/* B of three points 1e299 from the eye along y with x, z within 60: every
 * extent of their light-space box is flat (a few ulps); taking the widest
 * of those ulps as the map's width would put a point at x = -1.4.  The
 * points must map inside the unit square. */
START_TEST(setup_points_all_extents_flat_maps_inside) {
    swarp_camera cam = {{0x1.342c37258b8a8p+18, 0x0p+0, 0x1.342050053f726p+18},
                        {0x1.67c56b508176dp-1, 0x1.6d635d0494d02p-3, 0x1.60a745ad68eeap-1},
                        {0x0p+0, 0x1p+0, 0x0p+0},
                        0x1.5b21706d00d62p+1,
                        0x1.2e30a3b5cedf3p-1,
                        0x1.8be73d3c29d7bp-1,
                        0x1.d5a93d9b36be9p+22,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {0x1.67c56b508176dp-1, 0x1.6d635d0494d02p-3, 0x1.60a745ad68eeap-1},
                     {0x1.341337258b8a8p+18, 0x1.2bfffffffffffp+8, 0x1.343950053f726p+18}, 0x1.14503b946358bp+0,
                     {0, 0, 0, 0}};
    swarp_vec3 pt[3] = {{0x1.34213144c5fc2p+18, 0x1.13030ad93bcc6p+996, 0x1.341beeceef41p+18},
                        {0x1.342c782ab0221p+18, 0x1.1744212d7e833p+996, 0x1.341f3aba9402cp+18},
                        {0x1.341dc570f396fp+18, 0x1.3abcedc85cc71p+996, 0x1.341f393f969f3p+18}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    swarp_setup_result r;
    swarp_status st = swarp_setup_points(&cam, &l, pt, 3, NULL, 0, cam.z_near, cam.z_far, &o, &r);
    if (st == SWARP_ERR_DEGENERATE) return;
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    for (int i = 0; i < 3; ++i) {
        const double* m = r.matrix.m;
        double w = m[3] * pt[i].x + m[7] * pt[i].y + m[11] * pt[i].z + m[15];
        double x = (m[0] * pt[i].x + m[4] * pt[i].y + m[8] * pt[i].z + m[12]) / w;
        double y = (m[1] * pt[i].x + m[5] * pt[i].y + m[9] * pt[i].z + m[13]) / w;
        ck_assert_msg(fabs(x) <= 1 + 1e-6 && fabs(y) <= 1 + 1e-6, "point %d at (%g, %g)", i, x, y);
    }
}
END_TEST

/* A frustum flat across two of its faces (aspect 1.5e-87, or near and far
 * one ulp apart) is built from its 8 corners.  Orienting each face away
 * from the centroid by itself fails for the two faces of the flat
 * direction: that distance (1e-93) is below the rounding of the
 * coordinates, so the rounding mode would orient them, often both the same
 * way (an H with no inside, B empty in some modes only).  The faces of a
 * hexahedron are oriented by one decision (sw_poly_from_corners), so the
 * two flat faces are opposite and the status is the same in every mode. */
START_TEST(poly_flat_frustum_faces_opposite_rounding_mode) {
    swarp_camera cam = {{0, 0, 0},
                        {0x1.fa6f1162aabeap-1, 0x1.1fe7f9dd7b870p-3, -0x1.617f1d9118a72p-5},
                        {0, 1, 0},
                        0x1.8333b3ae6f2cfp+0,
                        0x1.81ec6597c7d87p-289, /* 1.5e-87 */
                        0x1.0c6f7a0b5ed8dp-20,
                        0x1.1bc5a524e23e1p+3,
                        {0, 0, 0, 0}};
    for (size_t m = 0; m <= sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        swarp_polyhedron V;
        fesetround(m ? tu_modes[m - 1] : FE_TONEAREST);
        swarp_status s = swarp_poly_from_camera(&cam, &V);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == SWARP_OK, "mode %zu: %s", m, swarp_status_name(s));
        ck_assert_msg(V.face_count == 2, "mode %zu: %u faces", m, V.face_count);
        double d = V.planes[0].a * V.planes[1].a + V.planes[0].b * V.planes[1].b + V.planes[0].c * V.planes[1].c;
        ck_assert_msg(d < -0.999, "mode %zu: the two faces of a flat frustum are not opposite (dot %.17g)", m, d);
    }
}
END_TEST

/* Flat frusta of the kind above, through swarp_setup: the same status and
 * point count in every rounding mode. */
START_TEST(setup_flat_frustum_rounding_mode) {
    swarp_camera cam = {{0x1.86a392f3c81dep+16, 0x1.1947dc1f70c3cp+3, 0x1.869d3b8d5066cp+16},
                        {0x1.fa6f1162aabeap-1, 0x1.1fe7f9dd7b870p-3, -0x1.617f1d9118a72p-5},
                        {0, 1, 0},
                        0x1.8333b3ae6f2cfp+0,
                        0x1.81ec6597c7d87p-289,
                        0x1.0c6f7a0b5ed8dp-20,
                        0x1.1bc5a524e23e1p+3,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.a40175f613d3ap-2, -0x1.05612992fd918p-4, 0x1.d1ce5be4bec4ap-1}, {0, 0, 0}, 0,
                     {0, 0, 0, 0}};
    swarp_aabb box = {{0x1.8681f912c0d82p+16, -0x1.4de8d338d7765p+0, 0x1.86980afb30b80p+16},
                      {0x1.86e5f912c0d82p+16, 0x1.6d8651bc5c6d5p+4, 0x1.86a134df5f3c2p+16}};
    swarp_setup_result r0, r;
    swarp_status s0 = swarp_setup(&cam, &l, &box, NULL, &r0, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_setup(&cam, &l, &box, NULL, &r, NULL, 0, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
        ck_assert_uint_eq(r.point_count, r0.point_count);
    }
}
END_TEST

/* Near and far one ulp apart: the frustum is flat along the view, and B
 * has the same status in every rounding mode. */
START_TEST(body_points_one_ulp_range_rounding_mode) {
    swarp_camera cam = {{-0x1.e8487d98eaea7p+19, 0x1.2007fa164b51fp+0, -0x1.e8498e2844f6dp+19},
                        {0x1.34822d0e88ebap-1, 0x1.73db85a7575ffp-3, 0x1.8de64f57dc779p-1},
                        {0, 1, 0},
                        0x1.a4ae1d521132fp-3,
                        0x1.ceef7d1a0afdbp+0,
                        1.0,
                        0x1.0000000000001p+0, /* one ulp beyond near */
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.119e89a777d34p-1, 0x1.0023847a5e054p-4, 0x1.af918995a9136p-1},
                     {-0x1.e83fd1a439e78p+19, 0x1.76d215f2ba606p+7, -0x1.e85109a6769f5p+19}, 0x1.34098dee17b00p+0, {0, 0, 0, 0}};
    swarp_aabb box = {{-0x1.e8487d98eaea7p+19, -0x1.c00fbb14f25c1p+0, -0x1.e8498e2844f6dp+19},
                      {-0x1.e84128dcb8e1dp+19, 0x1.316fe87ac5c8ap+4, -0x1.e8417b756b3bbp+19}};
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n0 = 0, n = 0;
    swarp_status s0 = swarp_body_points(&cam, cam.z_near, cam.z_far, &l, &box, pts, SWARP_BODY_MAX_POINTS, &n0);
    ck_assert_msg(s0 == SWARP_OK, "%s", swarp_status_name(s0));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_body_points(&cam, cam.z_near, cam.z_far, &l, &box, pts, SWARP_BODY_MAX_POINTS, &n);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
    }
}
END_TEST

/* PSM with an omni light inside the scene box, so the light itself is a
 * vertex of B ([RHS] §3.1.1).  On the light camera's w = 0 plane its w is
 * rounding (+-1e-15); taken into the casters' depth range when the
 * rounding makes w positive (FE_DOWNWARD), a depth of -5e15 would make the
 * fit call x and y flat and collapse the map (SWARP_INFO_FLAT_EXTENT, rows
 * of 1e-17).  Casters count only with w above its rounding (src/geometry/psm.c), so
 * every mode gives the default mode's map. */
START_TEST(setup_points_psm_light_in_b_rounding_mode) {
    swarp_camera cam = {{0x1.e844419ef06e8p+19, 0x1.9c16768fb6f8bp+1, 0x1.e84a3a2358517p+19},
                        {0x1.ef942ece7d0e1p-1, -0x1.b5f06e8950acbp-5, 0x1.f6bc44aa9d276p-3},
                        {0, 1, 0},
                        0x1.21b7777584959p+1,
                        0x1.b3b8a81d40cf2p+0,
                        0x1.b5b590e211506p-1,
                        0x1.8700b559e34d2p+22,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.375370a63a6dap-1, 0x1.59dc28506548fp-6, 0x1.965440804fad1p-1},
                     {0x1.e84534f06a27fp+19, 0x1.47cff0b3f9354p+2, 0x1.e847eeb8c327fp+19}, 0, {0, 0, 0, 0}};
    swarp_aabb box = {{0x1.e844419ef06e8p+19, -0x1.19476db815e78p-2, 0x1.e84233b08336bp+19},
                      {0x1.e84d02b75bbacp+19, 0x1.3ff4866071525p+4, 0x1.e84dfe36cb80fp+19}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    swarp_vec3 B[SWARP_BODY_MAX_POINTS];
    size_t nb = 0;
    ck_assert_int_eq(swarp_body_points(&cam, cam.z_near, cam.z_far, &l, &box, B, SWARP_BODY_MAX_POINTS, &nb), SWARP_OK);
    swarp_polyhedron H;
    ck_assert_int_eq(swarp_body_h(&cam, cam.z_near, cam.z_far, &box, &H), SWARP_OK);
    swarp_setup_result r0, r;
    swarp_status s0 = swarp_setup_points(&cam, &l, B, nb, H.vertices, H.vertex_count, cam.z_near, cam.z_far, &o, &r0);
    ck_assert_msg(s0 == SWARP_OK, "%s", swarp_status_name(s0));
    double scale = 0;
    for (int k = 0; k < 16; ++k) scale = fmax(scale, fabs(r0.light_proj.m[k]));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_setup_points(&cam, &l, B, nb, H.vertices, H.vertex_count, cam.z_near, cam.z_far, &o, &r);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
        for (int k = 0; k < 16; ++k)
            ck_assert_msg(fabs(r.light_proj.m[k] - r0.light_proj.m[k]) <= 1e-9 * scale, "mode %zu: light_proj[%d] %.17g, default %.17g",
                          m, k, r.light_proj.m[k], r0.light_proj.m[k]);
    }
}
END_TEST

/* A light 1e-7 rad from the view direction, followed with Δ = 4e-14.  The
 * target up (the view projected normal to the light, 1e-7 long) is rounded
 * to eps/1e-7 = 2e-9 rad, above a fixed 1e-9 alignment bound: φ is 0.8e-9
 * to nearest and 1.8e-9, 2.9e-9 in the directed modes.  The bound adds
 * 16 eps over each projection's length (src/geometry/follow.c), so every mode calls
 * the frame aligned and gives the same status. */
START_TEST(setup_follow_aligned_rounding_mode) {
    swarp_camera cam = {{-0x1.24a14cfe4aaaap+2, 0x1.5489c2e3efd6p+2, -0x1.ce986f28b59e9p+4},
                        {0x1.d99b26bb2f639p-1, -0x1.0519369f9fb89p-3, 0x1.6e7ff22cc397dp-2},
                        {0, 1, 0},
                        0x1.fffffb789fa69p-1,
                        0x1.7ffffffffffffp+1,
                        0x1.2af58d8f7d9b1p-1,
                        0x1.64631ad1d6dedp+22,
                        {0, 0, 0, 0}};
    swarp_camera pcam = cam;
    pcam.dir = (swarp_vec3){0x1.d99b26bb2f63ap-1, -0x1.0519369f9fb8ap-3, 0x1.6e7ff22cc397ep-2};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {0x1.d99b2585369fbp-1, -0x1.0519369f9fb73p-3, 0x1.6e7ff86eff201p-2}, {0, 0, 0}, 0,
                     {0, 0, 0, 0}};
    swarp_light pl = l;
    pl.direction = (swarp_vec3){0x1.d99b258536981p-1, -0x1.0519369f9fb73p-3, 0x1.6e7ff86eff478p-2};
    swarp_aabb box = {{-0x1.24a14cfe4aaaap+2, -0x1.95f624c87f178p+2, -0x1.ce986f28b59e9p+4},
                      {0x1.41b1265cd4bd9p+6, 0x1.5489c2e3efd6p+2, 0x1.eaa28cc03c1f8p+1}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_LISPSM;
    o.param = SWARP_WARP_PARAM_USER;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    o.pancake = 1;
    o.n_user = 0x1.5aa35b77d4436p+8;
    swarp_setup_result prev, r0, r;
    ck_assert(!swarp_status_is_error(swarp_setup(&pcam, &pl, &box, &o, &prev, NULL, 0, NULL)));
    swarp_status s0 = swarp_setup_follow(&cam, &l, &box, &o, &pcam, &prev, &r0, NULL, 0, NULL);
    ck_assert_msg(s0 == SWARP_OK, "%s", swarp_status_name(s0));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_setup_follow(&cam, &l, &box, &o, &pcam, &prev, &r, NULL, 0, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
    }
}
END_TEST

/* PSM without receivers (B is both), an omni light that is itself a
 * vertex of B.  Its w in the light camera is 0 up to rounding (+1e-16
 * under FE_TOWARDZERO, which would collapse the map around it to
 * SWARP_INFO_FLAT_EXTENT).  A receiver must be in front of the light by
 * more than the rounding of its w (src/geometry/psm.c): the light is refused among
 * the receivers (SWARP_ERR_LIGHT_INSIDE_BODY) in every mode. */
START_TEST(setup_points_psm_light_is_receiver_rounding_mode) {
    swarp_camera cam = {{-0x1.3feeaa7e822a5p+3, -0x1.8e460d304ac5fp+1, 0x1.bae3635bc42bp+3},
                        {0x1.46f2a24266ed7p-1, 0x1.2b5a7869c70afp-3, -0x1.82d8178f3c57ap-1},
                        {0, 1, 0},
                        0x1.815d5207ca13cp+0,
                        0x1.122eb40db70fdp+1,
                        0x1.51346aee57ed1p-13,
                        0x1.19dcc4343ba02p-11,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {0x1.870b46921e48cp-1, 0x1.4a34b5443832ap-57, 0x1.4a7f57e35f4e6p-1},
                     {-0x1.2feeaa7e822a5p+3, 0x1.4adb4810c882fp+3, 0x1.9ef594585ffcp+0}, 0, {0, 0, 0, 0}};
    const swarp_vec3 B[9] = {{-0x1.3febb0ae29d0ap+3, -0x1.8e4a29c073c01p+1, 0x1.bae3f602b342bp+3},
                             {-0x1.3febec46fca2dp+3, -0x1.8e406650bdddfp+1, 0x1.bae43c868cc32p+3},
                             {-0x1.3fe4b75b80ffap+3, -0x1.8e53cc73416e1p+1, 0x1.bae54db129fcp+3},
                             {-0x1.3fe57e9eefb63p+3, -0x1.8e33278b7eb61p+1, 0x1.bae63975cf8d6p+3},
                             {-0x1.3feeaa9e91ccdp+3, -0x1.8e53cc73416e1p+1, 0x1.badce4d4b327fp+3},
                             {-0x1.3feeaa9e91ccdp+3, -0x1.8e4a29c073c01p+1, 0x1.bae1720b81aa3p+3},
                             {-0x1.3feeaa9e91ccdp+3, -0x1.8e406650bdddfp+1, 0x1.bae1eaedea9c6p+3},
                             {-0x1.3feeaa9e91ccdp+3, -0x1.8e33278b7eb61p+1, 0x1.bade790283b27p+3},
                             {-0x1.2feeaa7e822a5p+3, 0x1.4adb4810c882fp+3, 0x1.9ef594585ffcp+0}}; /* the light */
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.slideback = 10.0;
    swarp_setup_result r;
    swarp_status s0 = swarp_setup_points(&cam, &l, B, 9, NULL, 0, cam.z_near, cam.z_far, &o, &r);
    ck_assert_msg(s0 == SWARP_ERR_LIGHT_INSIDE_BODY, "%s", swarp_status_name(s0));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_setup_points(&cam, &l, B, 9, NULL, 0, cam.z_near, cam.z_far, &o, &r);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
    }
}
END_TEST

/* B is a spot light's apex alone (the light position).  Its distance along
 * the light's axis is -7e-15, 0 or +1e-14 by rounding mode, which would
 * read as the light inside B (SWARP_ERR_LIGHT_INSIDE_BODY) or a map divided
 * by D = 0 (SWARP_ERR_DEGENERATE).  A point within the rounding of D of the
 * light is the apex, clipped as any (src/geometry/setup.c): nothing is left of B,
 * SWARP_ERR_BODY_EMPTY in every mode. */
START_TEST(setup_points_b_is_the_spot_apex_rounding_mode) {
    swarp_camera cam = {{-0x1.541efcd5d2f0cp+5, 0x1.2b331b2f89836p+3, 0x1.ddf1ad5d7cd2bp+5},
                        {0x1.62bc7967489eap-1, 0x1.69318c75e827fp-20, -0x1.71325b6e4a4c8p-1},
                        {0, 1, 0},
                        0x1.cb8ac2c969899p+0,
                        0x1.90511331f0508p-1,
                        0x1.fffff97e0f33dp-1,
                        0x1.951a7c46c7bf2p+4,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {1, -1, -1}, {-0x1.7967445a446dcp+4, 0x1.4b331b2f89836p+3, 0x1.1c85efc30d8fcp+3},
                     0x1.f6042193c636ep-1, {0, 0, 0, 0}};
    const swarp_vec3 B[1] = {l.position};
    swarp_setup_result r;
    swarp_status s0 = swarp_setup_points(&cam, &l, B, 1, NULL, 0, cam.z_near, cam.z_far, NULL, &r);
    ck_assert_msg(s0 == SWARP_ERR_BODY_EMPTY, "%s", swarp_status_name(s0));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_setup_points(&cam, &l, B, 1, NULL, 0, cam.z_near, cam.z_far, NULL, &r);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
    }
}
END_TEST

/* swarp_setup's status under every directed rounding mode is s0, the
 * default mode's */
static void setup_status_in_every_mode(const swarp_camera* cam, const swarp_light* l, const swarp_aabb* box,
                                       const swarp_setup_options* o, swarp_status s0) {
    swarp_setup_result r;
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        swarp_status s = swarp_setup(cam, l, box, o, &r, NULL, 0, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
    }
}

/* A flat box seen from above, the [WS06] centre: C_start is the nearest
 * vertex at the y_max end of P's axis and the y_min end lies before the
 * near plane, so z_0 = z_1 = near exactly and their computed difference is
 * rounding (+-1e-14): n_opt 1e17 or +inf by mode if taken literally.
 * Within their rounding the depths count as equal: uniform
 * (SWARP_INFO_WARP_UNIFORM) in every mode (src/geometry/lispsm.c). */
START_TEST(setup_nopt_equal_depths_rounding_mode) {
    swarp_camera cam = {{-0x1.e8482c636ea16p+19, 0x1.dfe0a6dd51096p+4, -0x1.e84c66bd330b1p+19},
                        {-0x1.2e9f9ca9cb6d5p-2, -0x1.e095edba9856p-1, -0x1.6c1d25ca25f5p-3},
                        {0, 1, 0},
                        0x1.482651f7c581p+0,
                        0x1.3333333333333p-2,
                        0x1.f72a6da6fa3a7p-1,
                        0x1.9b3f5b3c7fefcp+20,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.8da1934e2bb14p-1, -0x1.0e2adc60c52d6p-1, -0x1.5415b29ae66cep-1}, {0, 0, 0},
                     0, {0, 0, 0, 0}};
    swarp_aabb box = {{-0x1.e84cbd77f0a1ap+19, 0, -0x1.e84e4p+19}, {-0x1.e8476731134a4p+19, 0, -0x1.e84bf90e33e54p+19}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_NOPT;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.map_width = 6817;
    swarp_setup_result r0;
    swarp_status s0 = swarp_setup(&cam, &l, &box, &o, &r0, NULL, 0, NULL);
    ck_assert_msg(s0 == SWARP_INFO_WARP_UNIFORM, "%s (n_eye %g)", swarp_status_name(s0), r0.n_eye);
    setup_status_in_every_mode(&cam, &l, &box, &o, s0);
}
END_TEST

/* Telling a point light's P0·L from a directional light's L by the z entry
 * of its w row alone fails when the light axis has no world-z component
 * (eye, light and view in one z plane): that entry is 0, γ would read 90°
 * instead of the angle, and the rounding of that 0 would choose between the
 * two warps.  The map is continuous there: the same scene with the light
 * 1e-7 off that plane must give nearly the same map. */
START_TEST(setup_point_light_axis_in_z_plane_continuous) {
    swarp_camera cam = {{0, 0, 0}, {1, 0.3, 0}, {0, 1, 0}, 1.0, 1.5, 0.5, 50, {0, 0, 0, 0}};
    swarp_aabb box = {{-10, -10, -20}, {40, 10, 20}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {0, -1, 0}, {-5, 40, 0}, 0, {0, 0, 0, 0}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_GMNPR;
    swarp_setup_result r0, r1;
    swarp_status s0 = swarp_setup(&cam, &l, &box, &o, &r0, NULL, 0, NULL);
    l.position.z = 1e-7;
    swarp_status s1 = swarp_setup(&cam, &l, &box, &o, &r1, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(s0) && s0 == s1, "%s, %s", swarp_status_name(s0), swarp_status_name(s1));
    ck_assert_msg(fabs(r0.gamma - r1.gamma) <= 1e-6, "gamma %.17g vs %.17g", r0.gamma, r1.gamma);
    ck_assert_msg(fabs(r0.n_eye - r1.n_eye) <= 1e-5 * r1.n_eye, "n_eye %.17g vs %.17g", r0.n_eye, r1.n_eye);
}
END_TEST

/* As setup_nopt_equal_depths_rounding_mode, with a spot light 300 units
 * away: the depths (0.033) are reconstructed from the light's space and
 * carry the rounding of its 300-unit coordinates, z_1 - z_0 = -2e-14 to
 * +2e-14 by mode (n' 7e13..7e14, or uniform under FE_TOWARDZERO).  The
 * depths' rounding bound takes the sizes of their terms (src/geometry/lispsm.c). */
START_TEST(setup_nopt_equal_depths_point_light_rounding_mode) {
    swarp_camera cam = {{0x1.c879bde18ae3p+3, -0x1.99fb6266c0d47p+2, -0x1.3c740062d85f4p+5},
                        {-0x1.335b0e8d92de4p-1, 0x1.997bb20dee2c9p-1, 0},
                        {0, 1, 0},
                        0x1.8add9fbd0ec51p+0,
                        0x1.74d0307e7f448p-2,
                        0x1.1113ec29e7dd1p-5,
                        0x1.4588bcde709c2p+18,
                        {0, 0, 0, 0}};
    swarp_light l = {SWARP_LIGHT_POINT, 0, {0x1.330c1597e2ae2p-1, -0x1.99127b7243b49p-1, -0x1.6ef040e00ae59p-5},
                     {-0x1.1caaed5660d96p+6, 0x1.67340c0943055p+7, -0x1.171d0018b617dp+7}, 0x1.e25f1b62957dap-1, {0, 0, 0, 0}};
    swarp_aabb box = {{-0x1.2c7b2f5897db8p+2, -0x1.99fb6266c0d47p+2, -0x1.3c740062d85f4p+5},
                      {0x1.c879bde18ae3p+3, 0x1.a5c95de4ec144p+3, -0x1.3c740062d85f4p+5}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_NOPT;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    o.map_height = 3024;
    swarp_setup_result r0;
    swarp_status s0 = swarp_setup(&cam, &l, &box, &o, &r0, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
    setup_status_in_every_mode(&cam, &l, &box, &o, s0);
}
END_TEST

/* PSM's light camera axis is the minimal cone around the receivers' light
 * directions ([KOZ] §14.2.2, src/geometry/psm.c).  Here a cone of 0.007 rad through
 * three directions, two of them 6e-6 apart.  As the normal
 * (b - a) x (c - a) its axis would be tilted by the rounding of the unit
 * vectors' norms, eps/6e-6: 4e-11 rad between rounding modes, moving the
 * row offsets (e·q̂)/τ (τ = 0.0055) by 2e-8 of the largest output.  Solved
 * in the tangent plane, the map is the same in every rounding mode to 1e-9. */
START_TEST(setup_points_psm_small_cone_rounding_mode) {
    const swarp_camera cam = {{0x1.04da202c6b4d6p+5, 0x1.12cb4d5f8af88p+2, 0x1.2ddfb7cc89899p+5},
                              {-0x1.3672bb50dc043p-1, -0x1.1d53626e89fd5p-6, -0x1.970bc56826685p-1},
                              {0, 1, 0},
                              0x1.d65510c8d8838p-4,
                              0x1.365e4e50054f9p+0,
                              0x1.112b975471c98p-1,
                              0x1.52542fe6f6a46p+6,
                              {0, 0, 0, 0}};
    const swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.f29a3d2ef5c5p-2, -0x1.1a6ac18f13acap-6, -0x1.bf1e594a3325cp-1},
                           {-0x1.5768426e7b83ap+5, 0x1.8d554d7e1e037p+7, 0x1.093dff6005ad6p+6}, 0x1.387afe97711c3p+0,
                           {0, 0, 0, 0}};
    const swarp_vec3 pts[12] = {{-0x1.75087d70fa334p+4, -0x1.0522427c4b9eep+1, -0x1.9de332bbfd2dap+4},
                                {-0x1.be2169e04acd4p+3, -0x1.0522427c4b9eep+1, -0x1.0822083ac9fb9p+5},
                                {-0x1.76ad1693abc1ap+4, 0x1.eb9cc5a23f14ap+2, -0x1.a00aab03015cap+4},
                                {-0x1.c16a9c25adeap+3, 0x1.eb9cc5a23f14ap+2, -0x1.0935c45e4c131p+5},
                                {-0x1.d8b26b9851ce4p+3, 0x1.8fc0b95236a2fp+3, -0x1.ea556b883a41p+4},
                                {-0x1.8bc0ba0740347p+4, 0x1.8fc0b95236a2ep+3, -0x1.33195523a4d55p+4},
                                {-0x1.7e89ebd59ee15p+4, 0x1.8fc0b95236a2fp+3, -0x1.7ad620465b21fp+4},
                                {-0x1.7edd8e5561154p+3, -0x1.c56671acabf6cp+0, -0x1.e02f99f660d98p+4},
                                {-0x1.473427291bb54p+3, 0x1.d9dcb807adef7p+2, -0x1.b591c47d48c4p+4},
                                {-0x1.630ab9f29736cp+3, 0x1.8fc0b95236a2fp+3, -0x1.8db42040032bep+4},
                                {-0x1.6153e7f14322p+4, -0x1.e68eb773ccb28p+0, -0x1.8779b52437b4ap+4},
                                {-0x1.7942530cc8812p+4, 0x1.8fc0b95236a2ep+3, -0x1.1f3f2601fc3d6p+4}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.param = SWARP_WARP_PARAM_GMNPR;
    o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    o.map_width = 1107;
    o.map_height = 4936;
    o.n_user = 0x1.2e4e0269776aap+6;
    o.pseudo_near = 0x1.55be0ebf00872p-4;
    o.pseudo_far = 0x1.6d35377d284bp-1;
    swarp_setup_result r0, r;
    const swarp_status s0 = swarp_setup_points(&cam, &l, pts, 12, NULL, 0, cam.z_near, cam.z_far, &o, &r0);
    ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
    const swarp_mat4* m0[3] = {&r0.light_view, &r0.light_proj, &r0.matrix};
    double big = 0;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 16; ++i) big = fmax(big, fabs(m0[k]->m[i]));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        fesetround(tu_modes[m]);
        const swarp_status s = swarp_setup_points(&cam, &l, pts, 12, NULL, 0, cam.z_near, cam.z_far, &o, &r);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
        const swarp_mat4* m1[3] = {&r.light_view, &r.light_proj, &r.matrix};
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < 16; ++i)
                ck_assert_msg(fabs(m1[k]->m[i] - m0[k]->m[i]) <= 1e-9 * big, "mode %zu: matrix %d entry %d = %.17g, default %.17g",
                              m, k, i, m1[k]->m[i], m0[k]->m[i]);
    }
}
END_TEST

/* A polyhedron without faces (what the clipper leaves when a flat polygon
 * collapses onto a line: a segment of 2 vertices) clipped by a plane
 * through it is cut where it crosses the plane: the inner end and the
 * crossing, not the inner end alone. */
START_TEST(poly_clip_cuts_segment_without_faces) {
    swarp_polyhedron P, out;
    memset(&P, 0, sizeof P);
    P.vertex_count = 2;
    P.vertices[0] = (swarp_vec3){-4, 1, 2};
    P.vertices[1] = (swarp_vec3){6, 1, 2};
    const swarp_aabb box = {{-1, 0, 0}, {3, 5, 5}};
    ck_assert_int_eq(swarp_poly_clip_aabb(&P, &box, &out), SWARP_OK);
    double lo[3], hi[3];
    bbox(&out, lo, hi);
    ck_assert_msg(out.vertex_count == 2 && out.face_count == 0, "%u vertices, %u faces", out.vertex_count, out.face_count);
    ck_assert_msg(lo[0] == -1 && hi[0] == 3 && lo[1] == 1 && hi[1] == 1 && lo[2] == 2 && hi[2] == 2,
                  "x [%g, %g] y [%g, %g] z [%g, %g]", lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
}
END_TEST

/* H := the hexahedron with vertices v and face planes pl, the face loops of
 * the two fixtures below (their H written out exactly) in the order of pl */
static void fill_hexahedron(swarp_polyhedron* H, const swarp_vec3 v[8], const swarp_plane pl[6]) {
    static const uint8_t loops[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                        {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    H->vertex_count = 8;
    H->face_count = 6;
    for (int i = 0; i < 8; ++i) H->vertices[i] = v[i];
    for (int f = 0; f < 6; ++f) {
        H->planes[f] = pl[f];
        H->face_vertex_count[f] = 4;
        memcpy(H->face_vertices[f], loops[f], 4);
    }
}

/* A box 70 long and 1e-6 thick in y and z at 1e6, the clipper's merge
 * distance (SWARP_POLY_EPS_REL x 1e6): the sweep of H collapses onto a
 * segment on the box's edge line, which the last clip (x >= min x) must
 * cut although the collapse has no faces (keeping only its inner end would
 * leave the point x = 1000050.14 in one mode and the segment down to the
 * box's min x = 999986.47 in others).  B is that segment in every mode. */
START_TEST(body_from_h_needle_box_rounding_mode) {
    swarp_polyhedron H;
    memset(&H, 0, sizeof H);
    const swarp_vec3 v[8] = {
        {0x1.e84e5ebd62af8p+19, -0x1.540d65876f535p+3, 0x1.e843131a3de9bp+19},
        {0x1.e84e5352e046ap+19, -0x1.540d65876f535p+3, 0x1.e842ddc18f9a1p+19},
        {0x1.e84e49d94acc5p+19, -0x1.35c9bad812c5ep+3, 0x1.e8431792b9d26p+19},
        {0x1.e84e3e6ec8636p+19, -0x1.35c9bad812c5ep+3, 0x1.e842e23a0b82cp+19},
        {0x1.d70fba6c3bc2bp+19, -0x1.186dc509440a9p+19, 0x1.8178a881eddf3p+20},
        {0x1.64e21180eb4a2p+19, -0x1.186dc509440a9p+19, 0x1.daca582a12af9p+18},
        {0x1.061e70a46dfccp+19, 0x1.6430065f494c1p+15, 0x1.97d3f8e9ad348p+20},
        {0x1.27e18f723b086p+18, 0x1.6430065f494c1p+15, 0x1.1a1bcce488026p+19}};
    const swarp_plane pl[6] = {
        {0x1.802c85d9cd9b4p-1, 0x1.c88d233d1f3cep-2, 0x1.f3c7486c3d534p-2, -0x1.2e592d7ae0903p+20},
        {0x1.f084e3ee12574p-2, 0x1.c88d233d1f3cep-2, -0x1.813aa2cd691b8p-1, 0x1.0532f6168c33ap+18},
        {0x1.e339762607a36p-1, -0x1.0bea490e2878ap-2, -0x1.9da323b7f5574p-3, -0x1.6a3fa92b04466p+19},
        {0x1.32f4989e0bb8cp-4, 0x1.fe7e865378121p-1, -0x1.06c085e8fb731p-6, -0x1.cc23dd01dc8b2p+15},
        {0x1.99054947d95d8p-1, 0x1.27453c6bc7d73p-1, -0x1.5e1e86c53b771p-3, -0x1.329e239988163p+19},
        {-0x1.99054947d95d8p-1, -0x1.27453c6bc7d73p-1, 0x1.5e1e86c53b771p-3, 0x1.4b2e1cdfd461p+17}};
    fill_hexahedron(&H, v, pl);
    const swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.72ab062ce7a66p-4, 0x1.588ed75b6c74bp-4, -0x1.fc13b404669e1p-1}, {0x1.e85784c6778a7p+19, 0x1.0bb1d45940732p+6, 0x1.e84059f3bd7edp+19}, 0x1.461c26c225bd8p-3, {0, 0, 0, 0}};
    const swarp_aabb box = {{0x1.e8464f3034f9bp+19, -0x1.3803aa3b83cccp+3, 0x1.e842f6d6baa8dp+19}, {0x1.e84f0c54c443bp+19, -0x1.3803a822a4d8bp+3, 0x1.e842f6d6bcc1bp+19}};
    for (size_t m = 0; m <= sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        swarp_polyhedron B;
        fesetround(m ? tu_modes[m - 1] : FE_TONEAREST);
        const swarp_status s = swarp_body_from_h(&H, &l, &box, &B);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == SWARP_OK, "mode %zu: %s", m, swarp_status_name(s));
        double lo[3], hi[3];
        bbox(&B, lo, hi);
        ck_assert_msg(fabs(lo[0] - box.min.x) <= 1e-9 * box.max.x && fabs(hi[0] - 0x1.e84e44736bccp+19) <= 1e-9 * box.max.x,
                      "mode %zu: B's x from %.17g to %.17g", m, lo[0], hi[0]);
    }
}
END_TEST

/* A point light 50 units from a 45-unit box and H reaching 1.6e8 (a
 * frustum with a far plane 8e7 away): conv(H ∪ {l}) clipped to the box is
 * the box.  Cuts of the edges from l to H's far vertices interpolated from
 * the far end would be rounded by eps |1.6e8| (B's corners 1e-8 to 3e-8 off
 * the box by rounding mode); cut from the nearer end, they are on the box
 * to rounding in every mode. */
START_TEST(body_from_h_point_light_far_h_rounding_mode) {
    swarp_polyhedron H;
    memset(&H, 0, sizeof H);
    const swarp_vec3 v[8] = {
        {0x1.0a8fa61005eb6p+4, -0x1.053534fe802d9p+4, -0x1.4475af221173p+3},
        {-0x1.173bb3caa177ep+4, -0x1.053534fe802d9p+4, -0x1.39c55cf0c1bc9p+1},
        {0x1.2a6d07f156068p+4, -0x1.ab549cc43f64p+1, -0x1.4d82898a05ce2p+0},
        {-0x1.eebca3d2a2b98p+3, -0x1.ab549cc43f64p+1, 0x1.98a80d694094p+2},
        {0x1.38050afd0a00ep+27, -0x1.1bd53c2d361b4p+26, -0x1.08a7a188270c8p+26},
        {-0x1.529e2bc458643p+27, -0x1.1bd53c2d361b4p+26, 0x1.c9ec9ef41d63bp+22},
        {0x1.5e0166840be68p+27, 0x1.a7294b3863003p+25, 0x1.21bce03e74ad1p+24},
        {-0x1.2ca1d03d567eap+27, 0x1.a7294b3863003p+25, 0x1.6db5a387060ep+26}};
    const swarp_plane pl[6] = {
        {-0x1.66b2497f1faffp-4, 0x1.239988b56a3a6p-1, -0x1.a274108709c0cp-1, 0x1.3c294cf7fb4bbp+1},
        {-0x1.15ff09a869da2p-2, 0x1.239988b56a3a6p-1, -0x1.8d3b580efd014p-1, 0x1.543d16411575fp+1},
        {-0x1.9e37d7aff1632p-3, 0x1.9181dbfd5ec5ap-2, -0x1.cb79ec7e9fdc2p-1, 0x1.57d44f5636438p-1},
        {-0x1.34c6719e1f31cp-3, 0x1.74a733085fb96p-1, -0x1.56832efe45f99p-1, 0x1.17b5db1ddc034p+2},
        {-0x1.715090501ebc8p-3, 0x1.24e764ac70fep-1, -0x1.99aaa711f45cbp-1, 0x1.0ec7be6b09d49p+2},
        {0x1.715090501ebc8p-3, -0x1.24e764ac70fep-1, 0x1.99aaa711f45cbp-1, -0x1.f9310edbe5f47p+23}};
    fill_hexahedron(&H, v, pl);
    const swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.4f83fa8d5bc86p-2, 0x1.21723b5f47f06p-1, -0x1.8395c9b85db87p-1}, {-0x1.aab8928fce347p+5, 0x1.045874a833024p+7, -0x1.ba3af62e6203dp+4}, 0x0p+0, {0, 0, 0, 0}};
    const swarp_aabb box = {{-0x1.6a5bc3a276bd3p+5, -0x1.1c51c26be5628p+3, -0x1.d65bc860f3d92p+4}, {0x1.347b6e5822c8p-2, 0x1.1c1510b2bc14bp+4, 0x1.e81c39d0d9584p+3}};
    const double bmin[3] = {box.min.x, box.min.y, box.min.z}, bmax[3] = {box.max.x, box.max.y, box.max.z};
    for (size_t m = 0; m <= sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        swarp_polyhedron B;
        fesetround(m ? tu_modes[m - 1] : FE_TONEAREST);
        const swarp_status s = swarp_body_from_h(&H, &l, &box, &B);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == SWARP_OK && B.vertex_count == 8, "mode %zu: %s, %u vertices", m, swarp_status_name(s), B.vertex_count);
        for (uint32_t i = 0; i < B.vertex_count; ++i) { /* B is the box: each vertex a corner, to 1e-12 of its size */
            const double p[3] = {B.vertices[i].x, B.vertices[i].y, B.vertices[i].z};
            for (int k = 0; k < 3; ++k)
                ck_assert_msg(fmin(fabs(p[k] - bmin[k]), fabs(p[k] - bmax[k])) <= 1e-12 * 64,
                              "mode %zu: vertex %u coordinate %d = %.17g, box [%.17g, %.17g]", m, i, k, p[k], bmin[k], bmax[k]);
        }
    }
}
END_TEST

/* PSM with a caller's slide-back of 3.8e12 ([KOZ] Fig. 14-6,
 * swarp_setup_options.slideback): light_view is the slid-back camera's
 * view, translation 3.8e12.  Recovering light_proj as M_c V_c^-1 would put
 * eps 3.8e12 = 8e-4 of rounding in entries that are 0 -- times P's rows of
 * 1e11, light_proj light_view off the matrix by 3e-7 of it, differently in
 * each rounding mode.  light_proj is A Q P_c with the projection itself:
 * the product is the matrix to rounding in every mode, and every matrix is
 * the default mode's to 1e-9. */
START_TEST(setup_points_psm_huge_slideback_rounding_mode) {
    const swarp_camera cam = {{-0x1.0199b1f2db084p+5, 0x1.20c81efa3776ep+3, -0x1.d6cf5b2c342b8p+0},
                              {0x1.f561349d08566p-1, 0x1.b6bc97fc98057p-5, -0x1.90359c841832ap-3},
                              {0, 1, 0},
                              0x1.35582c7d4a335p+0,
                              0x1.22757703baa78p+1,
                              0x1.d5514efdd6e0dp+0,
                              0x1.9b62e2d143471p+11,
                              {0, 0, 0, 0}};
    const swarp_light l = {SWARP_LIGHT_DIRECTIONAL, 0, {-0x1.245d312a4e2c4p-1, -0x1.3c8ba678b5b15p-5, 0x1.a3da29393b038p-1},
                           {-0x1.90c8a24036d24p+5, 0x1.23e86fb79e19ap+4, 0x1.f0045029fba19p+5}, 0,
                           {0, 0, 0, 0}};
    const swarp_vec3 pts[16] = {{-0x1.ee67b34c70a5ap+4, 0x1.f6f87991c21c3p+2, -0x1.41b72583c35fcp+2},
                                {-0x1.dc6bf1624fdd8p+4, 0x1.f6f87991c21c3p+2, 0x1.360e1b45fc24p-1},
                                {-0x1.f088312b7aa51p+4, 0x1.4c5ca6e28a906p+3, -0x1.40048641f4a5cp+2},
                                {-0x1.de8c6f4159ddp+4, 0x1.4c5ca6e28a906p+3, 0x1.43a3155471f3cp-1},
                                {-0x1.b7efc1c893a83p+4, 0x1.d07a5db3f3ac2p+3, -0x1.d2aca0e37d02cp+3},
                                {-0x1.b00f36773bb18p+4, 0x1.1757214eb92ecp+2, -0x1.d2aca0e37d02cp+3},
                                {-0x1.d87ec453a3905p+3, -0x1.8074ddb884753p+1, -0x1.d2aca0e37d02cp+3},
                                {-0x1.ffe2b63f416bap+3, 0x1.73a20abe044fap+4, -0x1.d2aca0e37d02cp+3},
                                {0x1.3e2fd9232995p+2, -0x1.8074ddb88475cp+1, -0x1.d2aca0e37d02cp+3},
                                {-0x1.b6e7a4e16af28p+4, 0x1.aece4b5949b77p+2, 0x1.7c3f291d6d384p+1},
                                {-0x1.bbdd117ecfab9p+4, 0x1.759a678a3215bp+3, 0x1.7c3f291d6d384p+1},
                                {-0x1.686603053f21p+3, -0x1.8074ddb884754p+1, 0x1.7c3f291d6d38p+1},
                                {-0x1.8fc9f4f0dcfc6p+3, 0x1.73a20abe044fap+4, 0x1.7c3f291d6d38p+1},
                                {0x1.3e2fd9232995p+2, -0x1.8074ddb88475bp+1, 0x1.7c3f291d6d38p+1},
                                {0x1.3e2fd9232995p+2, 0x1.73a20abe044fap+4, 0x1.7c3f291d6d38p+1},
                                {0x1.3e2fd9232995p+2, 0x1.73a20abe044fap+4, -0x1.d2aca0e37d02ap+3}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.param = SWARP_WARP_PARAM_GMNPR;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    o.map_height = 6056;
    o.pancake = 1;
    o.n_user = 0x1.942401ff5ab05p+9;
    o.pseudo_near = 0x1.ccccccccccccdp-1;
    o.pseudo_far = 0x1.d5241f3838887p-3;
    o.slideback = 0x1.b6ec9acbae3a3p+41;
    swarp_setup_result r0, r;
    const swarp_status s0 = swarp_setup_points(&cam, &l, pts, 16, pts, 16, cam.z_near, cam.z_far, &o, &r0);
    ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
    const swarp_mat4* m0[3] = {&r0.light_view, &r0.light_proj, &r0.matrix};
    double big = 0;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 16; ++i) big = fmax(big, fabs(m0[k]->m[i]));
    for (size_t m = 0; m <= sizeof tu_modes / sizeof tu_modes[0]; ++m) { /* the last: to nearest */
        const int mode = m < sizeof tu_modes / sizeof tu_modes[0] ? tu_modes[m] : FE_TONEAREST;
        fesetround(mode);
        const swarp_status s = swarp_setup_points(&cam, &l, pts, 16, pts, 16, cam.z_near, cam.z_far, &o, &r);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s == s0, "mode %zu: %s, default %s", m, swarp_status_name(s), swarp_status_name(s0));
        /* light_proj light_view = matrix, normwise: rounding of the terms */
        double mscale = 0;
        for (int i = 0; i < 16; ++i) mscale = fmax(mscale, fabs(r.matrix.m[i]));
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row) {
                double acc = 0, mag = 0;
                for (int k = 0; k < 4; ++k) {
                    const double t = r.light_proj.m[k * 4 + row] * r.light_view.m[col * 4 + k];
                    acc += t, mag += fabs(t);
                }
                ck_assert_msg(fabs(acc - r.matrix.m[col * 4 + row]) <= 64 * DBL_EPSILON * (mag + mscale),
                              "mode %zu: matrix[%d][%d] = %.17g, light_proj light_view = %.17g", m, row, col,
                              r.matrix.m[col * 4 + row], acc);
            }
        const swarp_mat4* m1[3] = {&r.light_view, &r.light_proj, &r.matrix};
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < 16; ++i)
                ck_assert_msg(fabs(m1[k]->m[i] - m0[k]->m[i]) <= 1e-9 * big, "mode %zu: matrix %d entry %d = %.17g, default %.17g",
                              m, k, i, m1[k]->m[i], m0[k]->m[i]);
    }
}
END_TEST

/* A box flat in x at 1e5 (min.x = max.x) and a directional light 9e-16 rad
 * off that plane.  The view frustum's edges cut at the box plane x = c, if
 * interpolated, land on c to nearest and 1 ulp (1.5e-11) below it under
 * FE_DOWNWARD; the box clip sets the cut's x to c (src/geometry/poly.c).  The light
 * grazes the plane, so B is H swept in the plane (src/geometry/body.c
 * sw_flat_extend): copies H + T u carrying u's normal part, 5.6e-14, would
 * round to c or an ulp off it by mode, and B off its plane by ulps is a
 * 3e-11 extent the coordinates do not resolve (SWARP_ERR_DEGENERATE).  In
 * the plane it is flat (SWARP_INFO_FLAT_EXTENT) in every mode. */
static void flat_x_box_grazing_light_scene(swarp_camera* cam, swarp_light* l, swarp_aabb* b) {
    memset(cam, 0, sizeof *cam);
    cam->eye = (swarp_vec3){0x1.868ba1b7b7e0ap+16, -0x1.a3f61053e45e4p-2, 0x1.8681f276586bcp+16};
    cam->dir = (swarp_vec3){0x1.203af9ee75616p-50, 0x1.d48237d9a2e68p-1, 0x1.9d01b64f0c798p-2};
    cam->up = (swarp_vec3){0, 1, 0};
    cam->z_near = 0x1.b8f6889236fa2p+0;
    cam->z_far = 0x1.bce3ef5726ac1p+22;
    cam->fovy = 0x1.55cf5c7959d87p+0;
    cam->aspect = 0x1.e58427d2d195cp-1;
    memset(l, 0, sizeof *l);
    l->type = SWARP_LIGHT_DIRECTIONAL;
    l->direction = (swarp_vec3){0x1.0af4fbc0e90a7p-50, 0x1.ffca9e92a086ap-1, 0x1.d38c9c72be88p-6};
    *b = (swarp_aabb){{0x1.868c8f1e3be8ep+16, -0x1.a3f61053e45e4p-2, 0x1.867c201796c76p+16},
                      {0x1.868c8f1e3be8ep+16, 0x1.d97027beb06e7p+4, 0x1.8694fded10315p+16}};
}

START_TEST(body_h_flat_box_cut_on_its_plane_rounding_mode) {
    swarp_camera cam;
    swarp_light l;
    swarp_aabb b;
    flat_x_box_grazing_light_scene(&cam, &l, &b);
    /* camera-relative, as swarp_setup and swarp_cascade_setup clip (the
     * differences are exact: Sterbenz) */
    const swarp_vec3 e = cam.eye;
    cam.eye = (swarp_vec3){0, 0, 0};
    b = (swarp_aabb){{b.min.x - e.x, b.min.y - e.y, b.min.z - e.z}, {b.max.x - e.x, b.max.y - e.y, b.max.z - e.z}};
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int k = 0; k < 4; ++k) {
        swarp_polyhedron H;
        fesetround(modes[k]);
        const swarp_status st = swarp_body_h(&cam, cam.z_near, cam.z_far, &b, &H);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_uint_gt(H.vertex_count, 2);
        for (uint32_t i = 0; i < H.vertex_count; ++i)
            ck_assert_msg(H.vertices[i].x == b.min.x, "mode %d: vertex %u x = %a, the box plane %a", k, i, H.vertices[i].x, b.min.x);
    }
}
END_TEST

START_TEST(cascade_flat_box_grazing_light_rounding_mode) {
    swarp_camera cam;
    swarp_light l;
    swarp_aabb b;
    flat_x_box_grazing_light_scene(&cam, &l, &b);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 7;
    o.split.scheme = SWARP_SCHEME_DEFAULT;
    o.split.lambda = 0x1.8c76e24ce7eebp-1;
    o.split.pseudo_near = 0x1.19799812dea11p-40;
    o.split.pseudo_far = 0x1.69338fe09072p-3;
    o.n_user[4] = 0x1.2028a3e3ab509p+5;
    o.warp_per_split = (swarp_cascade_warp)2;
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.setup.param = (swarp_warp_param)4;
    o.setup.depth_range = (swarp_depth_range)1;
    o.setup.n_user = 0x1.0624dd2f1a9fcp-10;
    swarp_cascade_result r;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t n0 = 0, n = 0;
    const swarp_status st0 = swarp_cascade_setup(&cam, &l, &b, &o, &r, sp, SWARP_CASCADE_MAX_SPLITS, &n0);
    ck_assert_int_eq(st0, SWARP_INFO_FLAT_EXTENT);
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int k = 0; k < 3; ++k) {
        fesetround(modes[k]);
        const swarp_status st = swarp_cascade_setup(&cam, &l, &b, &o, &r, sp, SWARP_CASCADE_MAX_SPLITS, &n);
        fesetround(FE_TONEAREST);
        ck_assert_msg(st == st0, "mode %d: %s, default %s", k, swarp_status_name(st), swarp_status_name(st0));
        ck_assert_uint_eq(n, n0);
    }
}
END_TEST

/* A box flat in x through the eye (min.x = max.x = eye.x) and one ulp
 * thick in y at 3e6, a 1e-5 frustum.  Frustum edges cut at x = eye.x by
 * interpolation would land on the plane or off it by rounding mode (split
 * 0's B two points 4.4e-16 apart, or a segment off the plane: DEGENERATE in
 * one mode, WARP_UNIFORM in another).  The box-plane cut is exact, so the
 * status is the same in every mode. */
START_TEST(cascade_box_flat_through_eye_rounding_mode) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){-0x1.6e36b23669e25p+21, -0x1.2d6e3383869c7p+1, -0x1.6e36fd9ebc33dp+21};
    cam.dir = (swarp_vec3){-0x1.69d40f542b7c6p-3, 0x0p+0, 0x1.f7f2296a35f6bp-1};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.z_near = 0x1.acd780e92a976p-19;
    cam.z_far = 0x1.85f4d4f17385ep-17;
    cam.fovy = 0x1.765df4734700bp-1;
    cam.aspect = 0x1.0fd0819ec143cp+1;
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.direction = (swarp_vec3){-0x1.9081eed92018fp-3, 0x0p+0, 0x1.f61d38118317cp-1};
    const swarp_aabb b = {{-0x1.6e36b23669e25p+21, -0x1.2d6e3383869c7p+1, -0x1.6e372ca304d5fp+21},
                          {-0x1.6e36b23669e25p+21, -0x1.2d6e3383869c6p+1, -0x1.6e3595ae824bap+21}};
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    o.split.scheme = (swarp_split_scheme)2;
    o.split.lambda = 0x1.d56fe4961391fp-1;
    o.split.pseudo_near = 0x1.3433a53527c0ep-3;
    o.split.pseudo_far = 0x1.4004b18498e3ap-311;
    o.n_user[3] = 0x1.720b27dfbb264p+3;
    swarp_cascade_result r;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t n = 0;
    const swarp_status st0 = swarp_cascade_setup(&cam, &l, &b, &o, &r, sp, SWARP_CASCADE_MAX_SPLITS, &n);
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int k = 0; k < 3; ++k) {
        fesetround(modes[k]);
        const swarp_status st = swarp_cascade_setup(&cam, &l, &b, &o, &r, sp, SWARP_CASCADE_MAX_SPLITS, &n);
        fesetround(FE_TONEAREST);
        ck_assert_msg(st == st0, "mode %d: %s, default %s", k, swarp_status_name(st), swarp_status_name(st0));
    }
}
END_TEST

/* PSM over a slab 1e-7 thick at 3e6 with the eye in it, a light 1e-9 rad
 * off its plane.  The receivers' directions in PPS span 179.995°
 * (cos r = 4e-5): the pair cap's centre carries eps/cos r, so a point
 * 8.8e-10 from a support can fall outside it by rounding alone, and a cap
 * through the three would turn the PSM axis by 3e-3..6e-3 rad with the
 * rounding mode (light_proj's y scale -8006, -8770, -107).  The in-cap test
 * allows the centre's rounding: the same map in every mode. */
START_TEST(setup_psm_hemisphere_cap_rounding_mode) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){-0x1.6e35a0f3725e7p+21, -0x1.ddf9f165dac0bp+2, -0x1.6e36700b3d69dp+21};
    cam.dir = (swarp_vec3){-0x1.b657f7be61dfbp-1, -0x1.2690fdce9e973p-30, 0x1.0892af80c155fp-1};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.z_near = 0x1.a2de39b858b1ep-12;
    cam.z_far = 0x1.6f08f119c527fp+9;
    cam.fovy = 0x1.4343fd88fef7bp+1;
    cam.aspect = 0x1.3333333333333p-2;
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){0x1.649f0f45e1795p-1, 0x1.1ce054ba99b15p-30, -0x1.6f604acd9875bp-1};
    const swarp_aabb b = {{-0x1.6e3712644ca47p+21, -0x1.ddf9f1b7932b2p+2, -0x1.6e36700b3d69dp+21},
                          {-0x1.6e357d3d9dc6fp+21, -0x1.ddf9f14c3360bp+2, -0x1.6e35a69ce8625p+21}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.param = (swarp_warp_param)5;
    o.depth_range = (swarp_depth_range)2;
    o.map_width = 3928;
    o.pancake = 1;
    o.psm_slideback = 1;
    o.n_user = 0x1.0624dd2f1a9fcp-10;
    o.pseudo_near = 0x1.0f9f65dab038cp-2;
    o.pseudo_far = 0x1.fbe9be66e5e07p-2;
    swarp_setup_result r0, r;
    const swarp_status st0 = swarp_setup(&cam, &l, &b, &o, &r0, NULL, 0, NULL);
    ck_assert_msg(!swarp_status_is_error(st0), "%s", swarp_status_name(st0));
    double scale = 0;
    for (int i = 0; i < 16; ++i) scale = fmax(scale, fabs(r0.matrix.m[i]));
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int k = 0; k < 3; ++k) {
        fesetround(modes[k]);
        const swarp_status st = swarp_setup(&cam, &l, &b, &o, &r, NULL, 0, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, st0);
        for (int i = 0; i < 16; ++i)
            /* the map's own conditioning (the harness measures 7.5e9: points
             * 5e-4 from the eye at 3e6, resolved to 1e-6 of their distance);
             * far below the 20 % and 75x a turned axis gives */
            ck_assert_msg(fabs(r.matrix.m[i] - r0.matrix.m[i]) <= 1e-6 * scale, "mode %d: matrix %d = %.17g, default %.17g", k, i,
                          r.matrix.m[i], r0.matrix.m[i]);
    }
}
END_TEST

/* LiSPSM with the [WS06] centre, B's nearest vertex the point light itself
 * (B = conv(H u {l}) n S), so C_start is the light: (0, 0, 1, 0) in its
 * space, x/w = 0/0 and z/w = 1/0 with a zero w whose sign the rounding
 * picks (-0 under FE_DOWNWARD).  Clamping by the sign of w would put the
 * centre at z_max in one mode and z_min in another (z_0 0.013 vs 0.74, n 6 %
 * off, light_proj entries of opposite sign).  A zero w takes the
 * numerator's side, or the middle of B's box (src/geometry/lispsm.c); every mode gives
 * the default mode's map to 1e-9. */
START_TEST(setup_points_centre_at_point_light_rounding_mode) {
    const swarp_camera cam = {{-0x1.552be393132dfp+5, -0x1.b8f2f2c2f3cb8p+2, -0x1.71d45bf1feefp+4},
                              {-0x1.ab668fa63bb28p-2, -0x1.13029b718ea04p-1, 0x1.774b427f1a26dp-1},
                              {0, 1, 0},
                              0x1.6666666666666p+1,
                              0x1.545fc544863e2p+1,
                              0x1.abd391069e2fap-7,
                              0x1.c29181c88137ap+11,
                              {0, 0, 0, 0}};
    const swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.1170d966746bp-1, 0x1.18d6a148562f3p-2, -0x1.997578a44b4f2p-1},
                           {0x1.6442a6dc00435p+5, 0x1.019f8f98990ep+4, -0x1.61d45bf1feefp+4}, 0x1.6e809d551ced9p+0,
                           {0, 0, 0, 0}};
    const swarp_vec3 pts[11] = {{-0x1.23e1df5fd3f5ep+5, -0x1.262a61abd76e8p+3, -0x1.4b6f821093567p+4},
                                {-0x1.5d9c3f7a6afccp+5, -0x1.d6cd71098f5cap+2, -0x1.7f08804671ee7p+4},
                                {-0x1.6d5e49c943255p+5, -0x1.82124fdaa8158p+2, -0x1.7f08804671ee7p+4},
                                {-0x1.51307cf71a88p+5, -0x1.262a61abd76e8p+3, -0x1.7f08804671ee7p+4},
                                {-0x1.9p+5, -0x1.d68bde7d7c1p+1, -0x1.7f08804671ee7p+4},
                                {-0x1.9p+5, -0x1.262a61abd76e8p+3, -0x1.7f08804671ee7p+4},
                                {-0x1.11d5de47485b1p+5, -0x1.d7e4259caeccep+1, -0x1.df0e17facde2cp+3},
                                {-0x1.bfc9c5d15478ap+4, -0x1.262a61abd76e8p+3, -0x1.df0e17facde2cp+3},
                                {-0x1.9p+5, 0x1.396b2b8a57c3ep+2, -0x1.df0e17facde2dp+3},
                                {-0x1.9p+5, -0x1.262a61abd76e8p+3, -0x1.df0e17facde2dp+3},
                                {0x1.6442a6dc00435p+5, 0x1.019f8f98990ep+4, -0x1.61d45bf1feefp+4}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_LISPSM;
    o.param = SWARP_WARP_PARAM_PSEUDO;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.map_width = 7590;
    o.map_height = 4218;
    o.pancake = 1;
    o.n_user = 0x1.daf04d683105bp-2;
    o.pseudo_near = 0x1.1031c249be764p-3;
    o.pseudo_far = 0x1.677d629d6df67p-1;
    o.slideback = 0x1.76897cc63854cp-1;
    swarp_setup_result r0;
    const swarp_status s0 = swarp_setup_points(&cam, &l, pts, 11, NULL, 0, cam.z_near, cam.z_far, &o, &r0);
    ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
    double scale = 0;
    for (int i = 0; i < 16; ++i) scale = fmax(scale, fmax(fabs(r0.light_proj.m[i]), fabs(r0.matrix.m[i])));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        swarp_setup_result r1;
        fesetround(tu_modes[m]);
        const swarp_status s1 = swarp_setup_points(&cam, &l, pts, 11, NULL, 0, cam.z_near, cam.z_far, &o, &r1);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s1 == s0, "mode %zu: %s, default %s", m, swarp_status_name(s1), swarp_status_name(s0));
        for (int i = 0; i < 16; ++i) {
            ck_assert_msg(fabs(r1.light_proj.m[i] - r0.light_proj.m[i]) <= 1e-9 * scale, "mode %zu: light_proj[%d] %.17g, default %.17g", m,
                          i, r1.light_proj.m[i], r0.light_proj.m[i]);
            ck_assert_msg(fabs(r1.matrix.m[i] - r0.matrix.m[i]) <= 1e-9 * scale, "mode %zu: matrix[%d] %.17g, default %.17g", m, i,
                          r1.matrix.m[i], r0.matrix.m[i]);
        }
    }
}
END_TEST

/* PSM, a point light 1 unit above the eye that is a vertex of B
 * (B = conv(H u {l}) n S), the scene 1e5 from the origin.  The light lies
 * on its own plane w = 0; QM = Q M_c's w row carries eps of the product's
 * terms, more than eps of the terms of w at the light, so the bound on w's
 * rounding must be taken from the product's terms: with the smaller bound
 * FE_DOWNWARD gives w positive beyond it, a caster at depth -2.8e15 and x,
 * y flat beside it (SWARP_INFO_FLAT_EXTENT instead of SWARP_OK). */
START_TEST(setup_points_psm_light_vertex_product_rounding_mode) {
    const swarp_camera cam = {{0x1.8696a23881e22p+16, 0x1.2b825212bde47p+4, 0x1.86d331525b447p+16},
                              {0x1.b3a3b09071fdbp-3, 0x1.ad7f29abcaf48p-24, -0x1.947659d5302cdp-1},
                              {0, 1, 0},
                              0x1.999999999999bp-4,
                              0x1.bbc754fd219ddp+0,
                              0x1.94e40d90e483dp+0,
                              0x1.8b9edf66d46bep+21,
                              {0, 0, 0, 0}};
    const swarp_light l = {SWARP_LIGHT_POINT, 0, {-0x1.f7131ffa35bap-5, -0x1.9d2f1e5fd4875p-1, 0x1.b84800175a594p-2},
                           {0x1.8696a23881e22p+16, 0x1.3b825212bde47p+4, 0x1.86a7b736a80d2p+16}, 0, {0, 0, 0, 0}};
    const swarp_vec3 pts[11] = {{0x1.8696e994af93cp+16, 0x1.2a3e237686b78p+4, 0x1.86d1a13967d9fp+16},
                                {0x1.86972d695a407p+16, 0x1.2a3e237686b78p+4, 0x1.86d1b37d33aa1p+16},
                                {0x1.8696e994af7e3p+16, 0x1.2cc68116bf913p+4, 0x1.86d1a139682a3p+16},
                                {0x1.86972d695a2adp+16, 0x1.2cc68116bf913p+4, 0x1.86d1b37d33fa5p+16},
                                {0x1.86a0b03438842p+16, 0x1.fba9ea5456b15p+3, 0x1.869ad1a9d9bbcp+16},
                                {0x1.86a0b03438842p+16, 0x1.141763c9ede33p+4, 0x1.86b79c49f7e51p+16},
                                {0x1.86a0b03438842p+16, 0x1.42ed47de8b05fp+4, 0x1.86b79c49f968dp+16},
                                {0x1.86a02a7f01d1p+16, 0x1.56d050cfab997p+4, 0x1.869dbf542cd79p+16},
                                {0x1.86a0b03438842p+16, 0x1.56d050cfab997p+4, 0x1.869ad1a9d41ecp+16},
                                {0x1.86a0b03438842p+16, 0x1.56d050cfab997p+4, 0x1.869de35519906p+16},
                                {0x1.8696a23881e22p+16, 0x1.3b825212bde47p+4, 0x1.86a7b736a80d2p+16}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_PSM;
    o.param = SWARP_WARP_PARAM_NREPAR;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    o.map_width = 2748;
    o.n_user = 0x1.0966e3d1151bep+3;
    o.pseudo_near = 0x1.0c5b1c759fedbp-1;
    o.pseudo_far = 0x1.a1c5b68ebe16fp-4;
    o.slideback = 0x1.0eaa1069428ap-2;
    swarp_setup_result r0;
    const swarp_status s0 = swarp_setup_points(&cam, &l, pts, 11, pts, 10, cam.z_near, cam.z_far, &o, &r0);
    ck_assert_msg(s0 == SWARP_OK, "%s", swarp_status_name(s0));
    for (size_t m = 0; m < sizeof tu_modes / sizeof tu_modes[0]; ++m) {
        swarp_setup_result r1;
        fesetround(tu_modes[m]);
        const swarp_status s1 = swarp_setup_points(&cam, &l, pts, 11, pts, 10, cam.z_near, cam.z_far, &o, &r1);
        fesetround(FE_TONEAREST);
        ck_assert_msg(s1 == s0, "mode %zu: %s, default %s", m, swarp_status_name(s1), swarp_status_name(s0));
    }
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_geometry");
    TCase* t = tcase_create("geometry");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, poly_clip_aabb_edges);
    tcase_add_test(t, body_from_h_edges);
    tcase_add_test(t, focus_light_view_point_lights);
    tcase_add_test(t, warp_lispsm_options);
    tcase_add_test(t, setup_nearest_vertex_rounding_mode);
    tcase_add_test(t, plan_gamma_rounding_mode);
    tcase_add_test(t, warp_lispsm_tiny_n);
    tcase_add_test(t, poly_from_camera_overflow);
    tcase_add_test(t, body_points_box_to_dbl_max);
    /* valid input at the ends of the double range: setup */
    tcase_add_test(t, focus_light_view_subnormal_direction_is_finite);
    tcase_add_test(t, focus_light_view_translation_overflow_is_reported);
    tcase_add_test(t, setup_point_light_1e300_away_rigid_inverse);
    tcase_add_test(t, warp_lispsm_far_light_view_rigid_inverse);
    tcase_add_test(t, setup_points_eye_far_from_body_is_degenerate);
    tcase_add_test(t, setup_range_subnormal_fovy_is_valid);
    tcase_add_test(t, setup_nrepar_near_dbl_min_is_valid);
    tcase_add_test(t, setup_points_uniform_warp_centre_keeps_fit_tight);
    tcase_add_test(t, setup_points_psm_eye_far_from_body_is_degenerate);
    tcase_add_test(t, setup_point_light_centre_on_light_plane_maps_inside);
    tcase_add_test(t, setup_point_light_2e154_away_is_degenerate);
    tcase_add_test(t, setup_follow_psm_huge_aspect_no_zero_vector);
    tcase_add_test(t, setup_points_all_extents_flat_maps_inside);
    /* B and H at grazing lights and at the ends of the double range */
    tcase_add_test(t, body_from_h_grazing);
    tcase_add_test(t, body_h_wide_frustum);
    tcase_add_test(t, poly_tiny_magnitudes);
    tcase_add_test(t, body_adjusted_range_one_ulp);
    tcase_add_test(t, poly_inverse_matrix_huge_corners);
    /* the same status or map in every rounding mode */
    tcase_add_test(t, poly_flat_frustum_faces_opposite_rounding_mode);
    tcase_add_test(t, setup_flat_frustum_rounding_mode);
    tcase_add_test(t, body_points_one_ulp_range_rounding_mode);
    tcase_add_test(t, setup_points_psm_light_in_b_rounding_mode);
    tcase_add_test(t, setup_follow_aligned_rounding_mode);
    tcase_add_test(t, setup_points_psm_light_is_receiver_rounding_mode);
    tcase_add_test(t, setup_points_b_is_the_spot_apex_rounding_mode);
    tcase_add_test(t, setup_nopt_equal_depths_rounding_mode);
    tcase_add_test(t, setup_point_light_axis_in_z_plane_continuous);
    tcase_add_test(t, setup_nopt_equal_depths_point_light_rounding_mode);
    tcase_add_test(t, setup_points_psm_small_cone_rounding_mode);
    tcase_add_test(t, poly_clip_cuts_segment_without_faces);
    tcase_add_test(t, body_from_h_needle_box_rounding_mode);
    tcase_add_test(t, body_from_h_point_light_far_h_rounding_mode);
    tcase_add_test(t, setup_points_psm_huge_slideback_rounding_mode);
    tcase_add_test(t, body_h_flat_box_cut_on_its_plane_rounding_mode);
    tcase_add_test(t, cascade_flat_box_grazing_light_rounding_mode);
    tcase_add_test(t, cascade_box_flat_through_eye_rounding_mode);
    tcase_add_test(t, setup_psm_hemisphere_cap_rounding_mode);
    tcase_add_test(t, setup_points_centre_at_point_light_rounding_mode);
    tcase_add_test(t, setup_points_psm_light_vertex_product_rounding_mode);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
