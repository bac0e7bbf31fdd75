/* SWARP_DEPTH_REVERSED_ZERO_TO_ONE for the light's clip depth: every
 * builder that accepts it returns the [0, 1] matrix with z/w turned to
 * 1 - z/w (x, y, w unchanged), checked on the points the map must cover,
 * and the defining property: the focused depth range lands on [0, 1] with
 * the nearest point to the light at 1.  The functions downstream of the
 * light matrix (cascades, atlas, bias, lixel factor, inverse frustum) are
 * in tests/cascade/test_depth_reversed_maps.c. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"
#include "test_vec.h"

/* a [0, 1] depth of size ~1 turned over: one rounding of 1 - z on top of
 * the matrix products' few ulps */
#define TOL 1e-12

static void ndc(const swarp_mat4* M, swarp_vec3 p, double out[4]) {
    swarp_vec4 h;
    ck_assert_int_eq(swarp_mat4_transform(M, &p, &h), SWARP_OK);
    out[0] = h.x / h.w, out[1] = h.y / h.w, out[2] = h.z / h.w, out[3] = h.w;
}

/* x, y, w agree; z_rev = 1 - z_zo */
static void assert_reversed(const swarp_mat4* zo, const swarp_mat4* rev, const swarp_vec3* pts, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        double a[4], b[4];
        ndc(zo, pts[i], a);
        ndc(rev, pts[i], b);
        ck_assert_double_le(fabs(a[0] - b[0]), TOL);
        ck_assert_double_le(fabs(a[1] - b[1]), TOL);
        ck_assert_double_le(fabs(a[3] - b[3]), TOL * fabs(a[3]));
        ck_assert_double_le(fabs(b[2] - (1.0 - a[2])), TOL);
    }
}

static swarp_camera camera(void) {
    swarp_camera c = {0};
    c.eye = v3(0, 10, 0);
    c.dir = v3(0, -0.2, -1);
    c.up = v3(0, 1, 0);
    c.fovy = 1.0472;
    c.aspect = 1.7778;
    c.z_near = 1;
    c.z_far = 100;
    return c;
}
static const swarp_aabb scene = {{-200, -5, -300}, {200, 30, 60}};

START_TEST(setup_reversed_is_the_zero_to_one_map_turned_over) {
    const swarp_technique techs[] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_PSM};
    swarp_camera c = camera();
    for (int li = 0; li < 2; ++li) {
        swarp_light L = {0};
        if (li == 0) {
            L.direction = v3(0.3, -1, 0.2);
        } else {
            L.type = SWARP_LIGHT_POINT;
            L.position = v3(20, 300, -50);
        }
        for (size_t t = 0; t < sizeof techs / sizeof techs[0]; ++t) {
            swarp_setup_options o = {0};
            o.technique = techs[t];
            o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
            swarp_setup_result r0, r1;
            swarp_vec3 B[SWARP_BODY_MAX_POINTS];
            size_t nb = 0;
            swarp_status s0 = swarp_setup(&c, &L, &scene, &o, &r0, B, SWARP_BODY_MAX_POINTS, &nb);
            o.depth_range = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
            swarp_status s1 = swarp_setup(&c, &L, &scene, &o, &r1, NULL, 0, NULL);
            ck_assert(!swarp_status_is_error(s0));
            ck_assert_int_eq(s1, s0);
            assert_reversed(&r0.matrix, &r1.matrix, B, nb);
            /* the body B fills the reversed range: its depths span [0, 1] */
            double lo = INFINITY, hi = -INFINITY;
            for (size_t i = 0; i < nb; ++i) {
                double p[4];
                ndc(&r1.matrix, B[i], p);
                lo = fmin(lo, p[2]), hi = fmax(hi, p[2]);
            }
            ck_assert_double_le(fabs(lo), 1e-9);
            ck_assert_double_le(fabs(hi - 1.0), 1e-9);
            if (li == 0 && techs[t] == SWARP_TECHNIQUE_UNIFORM) {
                /* uniform directional: depth falls along the light, the
                 * point of B nearest the light (smallest L.p) at 1 */
                size_t near = 0;
                for (size_t i = 1; i < nb; ++i)
                    if (vdot(B[i], L.direction) < vdot(B[near], L.direction)) near = i;
                double p[4];
                ndc(&r1.matrix, B[near], p);
                ck_assert_double_le(fabs(p[2] - 1.0), 1e-9);
            }
        }
    }
}
END_TEST

START_TEST(focus_fit_reversed_puts_the_nearest_point_at_one) {
    uint64_t seed = 23;
    swarp_vec3 pts[40];
    for (int i = 0; i < 40; ++i)
        pts[i] = v3(tu_uniform(&seed, -5, 5), tu_uniform(&seed, -5, 5), tu_uniform(&seed, -30, -2));
    swarp_mat4 I, A0, A1;
    memset(&I, 0, sizeof I);
    I.m[0] = I.m[5] = I.m[10] = I.m[15] = 1.0;
    ck_assert_int_eq(swarp_focus_fit(&I, pts, 40, NULL, 0, SWARP_DEPTH_ZERO_TO_ONE, &A0), SWARP_OK);
    ck_assert_int_eq(swarp_focus_fit(&I, pts, 40, NULL, 0, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, &A1), SWARP_OK);
    assert_reversed(&A0, &A1, pts, 40);
    /* brute force: swarp_focus_fit's near end is the smallest depth
     * coordinate of m p ([RHS] (3.1): the projection before it has depth
     * growing away from the light), reversed-Z puts it at 1, the largest at 0 */
    size_t imax = 0, imin = 0;
    for (size_t i = 1; i < 40; ++i) {
        if (pts[i].z > pts[imax].z) imax = i;
        if (pts[i].z < pts[imin].z) imin = i;
    }
    double p[4];
    ndc(&A1, pts[imin], p);
    ck_assert_double_le(fabs(p[2] - 1.0), TOL);
    ndc(&A1, pts[imax], p);
    ck_assert_double_le(fabs(p[2]), TOL);
}
END_TEST

START_TEST(stabilized_and_cube_maps_reverse_too) {
    swarp_camera c = camera();
    swarp_vec3 dir = v3(0.3, -1, 0.2);
    swarp_stabilize_options o = {0};
    o.mode = SWARP_STABILIZE_SPHERE;
    o.depth = SWARP_DEPTH_ZERO_TO_ONE;
    swarp_mat4 m0, m1;
    ck_assert(!swarp_status_is_error(swarp_stabilize_directional(&c, 1, 30, &dir, NULL, 0, &scene, 2048, &o, &m0, NULL)));
    o.depth = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
    ck_assert(!swarp_status_is_error(swarp_stabilize_directional(&c, 1, 30, &dir, NULL, 0, &scene, 2048, &o, &m1, NULL)));
    const swarp_vec3 pts[4] = {{0, 0, -10}, {5, 3, -20}, {-7, 1, -28}, {0, 10, -1}};
    assert_reversed(&m0, &m1, pts, 4);

    swarp_vec4 Lp = {0.3, 2.0, -0.4, 1.0};
    swarp_cube_options co = {0};
    co.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    swarp_cube_face f0[6], f1[6];
    size_t n0, n1;
    ck_assert(!swarp_status_is_error(swarp_cube_faces(&Lp, &co, f0, 6, &n0)));
    co.depth_range = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
    ck_assert(!swarp_status_is_error(swarp_cube_faces(&Lp, &co, f1, 6, &n1)));
    ck_assert_uint_eq(n0, n1);
    const swarp_vec3 q[3] = {{0.1, -0.5, 0.2}, {-0.7, 0.3, 0.9}, {0.5, 0.5, -0.5}};
    for (size_t k = 0; k < n0; ++k) {
        swarp_mat4 P0 = f0[k].proj, P1 = f1[k].proj;
        ck_assert_mem_eq(&f0[k].view, &f1[k].view, sizeof f0[k].view);
        /* points in front of the face camera: view space z < 0 */
        swarp_vec3 e[3] = {{0.1, 0.2, -0.5}, {-0.3, 0.1, -0.9}, {0.2, -0.2, -0.05}};
        assert_reversed(&P0, &P1, e, 3);
        /* and world points in front of the face: P + a N + b R + c U, a > 0 */
        swarp_vec3 P = v3(Lp.x / Lp.w, Lp.y / Lp.w, Lp.z / Lp.w), w[2];
        w[0] = vadd(P, vadd(vscale(f0[k].normal, 0.5), vscale(f0[k].right, 0.1)));
        w[1] = vadd(P, vadd(vscale(f0[k].normal, 0.9), vscale(f0[k].up, -0.3)));
        assert_reversed(&f0[k].view_proj, &f1[k].view_proj, w, 2);
    }
    for (int i = 0; i < 3; ++i) {
        uint32_t fa, fb;
        swarp_vec3 ta, tb;
        double da, db;
        co.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
        swarp_status sa = swarp_cube_lookup(&Lp, &co, &q[i], &fa, &ta, &da);
        co.depth_range = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
        swarp_status sb = swarp_cube_lookup(&Lp, &co, &q[i], &fb, &tb, &db);
        ck_assert_int_eq(sa, sb);
        ck_assert_uint_eq(fa, fb);
        ck_assert_double_le(fabs(db - (1.0 - da)), TOL);
    }
}
END_TEST

START_TEST(an_enum_beyond_the_list_is_refused) {
    swarp_camera c = camera();
    swarp_light L = {0};
    L.direction = v3(0.3, -1, 0.2);
    swarp_setup_options o = {0};
    o.depth_range = (swarp_depth_range)4;
    swarp_setup_result r;
    ck_assert_int_eq(swarp_setup(&c, &L, &scene, &o, &r, NULL, 0, NULL), SWARP_ERR_UNKNOWN_ENUM);
}
END_TEST

int main(void) {
    Suite* s = suite_create("depth_reversed");
    TCase* tc = tcase_create("depth_reversed");
    tcase_add_test(tc, setup_reversed_is_the_zero_to_one_map_turned_over);
    tcase_add_test(tc, focus_fit_reversed_puts_the_nearest_point_at_one);
    tcase_add_test(tc, stabilized_and_cube_maps_reverse_too);
    tcase_add_test(tc, an_enum_beyond_the_list_is_refused);
    suite_add_tcase(s, tc);
    return tu_run_suite(s) ? 1 : 0;
}
