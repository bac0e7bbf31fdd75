/* Reversed-Z (SWARP_DEPTH_REVERSED_ZERO_TO_ONE) in the functions that read
 * or build the light's clip depth after the light matrix: cascades, the
 * atlas, the bias functions, the best-resolution split selection, the lixel
 * factorisation and the frustum of an inverse matrix.
 *
 * Independent evaluation: reversed-Z is the [0, 1] convention under
 * z_ndc -> 1 - z_ndc (clip z' = w - z, x, y, w unchanged).  So with d the
 * window depth (d = z_ndc in both):
 *   d_rev(p) = 1 - d_zo(p)                      at every point,
 *   dd_rev/dL = -dd_zo/dL                       (depth per world unit),
 *   d_rev(p) - d_rev(q) = -(d_zo(p) - d_zo(q))  (a depth bias, p -> q),
 *   grad d_rev = -grad d_zo                      (receiver plane),
 * and texel sizes, coverage and split choices are unchanged.  Each is
 * asserted against the library's own [0, 1] result, and the reversed map is
 * also checked against the property that defines it: casters between a
 * receiver and the light have a LARGER depth inside [0, 1], the light's near
 * plane is 1, and receiver depth minus the depth bias is the depth of the
 * receiver moved toward the light (a GREATER test then sees it lit). */
#include <check.h>
#include <math.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"
#include "test_vec.h"

/* depths and NDC coordinates of size ~1: a few ulps of the matrix products
 * plus one rounding of 1 - z */
#define TOL 1e-12
/* a depth bias or derivative is a difference of O(1) values scaled by the
 * map: compare relative to its own size */
#define RTOL 1e-9

static void ndc(const swarp_mat4* M, swarp_vec3 p, double out[4]) {
    swarp_vec4 h;
    ck_assert_int_eq(swarp_mat4_transform(M, &p, &h), SWARP_OK);
    out[0] = h.x / h.w, out[1] = h.y / h.w, out[2] = h.z / h.w, out[3] = h.w;
}

static void assert_turned_over(const swarp_mat4* zo, const swarp_mat4* rev, swarp_vec3 p) {
    double a[4], b[4];
    ndc(zo, p, a);
    ndc(rev, p, b);
    ck_assert_double_le(fabs(a[0] - b[0]), TOL * (1 + fabs(a[0])));
    ck_assert_double_le(fabs(a[1] - b[1]), TOL * (1 + fabs(a[1])));
    ck_assert_double_le(fabs(a[3] - b[3]), TOL * fabs(a[3]));
    ck_assert_double_le(fabs(b[2] - (1.0 - a[2])), TOL * (1 + fabs(a[2])));
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

/* the point of the camera frustum at view depth z and the fractions fx, fy
 * in [-1, 1] of the half extents there */
static swarp_vec3 frustum_point(const swarp_camera* c, double z, double fx, double fy) {
    swarp_vec3 f = vnorm(c->dir), r = vnorm(vcross(f, c->up)), u = vcross(r, f);
    double ty = tan(0.5 * c->fovy), tx = ty * c->aspect;
    return vadd(c->eye, vadd(vscale(f, z), vadd(vscale(r, fx * tx * z), vscale(u, fy * ty * z))));
}
static int in_box(swarp_vec3 p) {
    return p.x >= scene.min.x && p.x <= scene.max.x && p.y >= scene.min.y && p.y <= scene.max.y &&
           p.z >= scene.min.z && p.z <= scene.max.z;
}

static void run_cascade(swarp_technique t, swarp_stabilize_mode sm, swarp_depth_range d, swarp_cascade_result* r,
                        swarp_cascade_split* sp, size_t* n, const swarp_light* L) {
    swarp_camera c = camera();
    swarp_cascade_options co = {0};
    co.setup.technique = t;
    co.setup.depth_range = d;
    co.stabilize.mode = sm;
    co.split.count = 3;
    swarp_status st = swarp_cascade_setup(&c, L, &scene, &co, r, sp, SWARP_CASCADE_MAX_SPLITS, n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_string(st));
}

START_TEST(cascade_reversed_is_the_zero_to_one_cascade_turned_over) {
    swarp_light L = {0};
    L.direction = v3(0.3, -1, 0.2);
    const swarp_technique techs[] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_UNIFORM};
    const swarp_stabilize_mode modes[] = {SWARP_STABILIZE_NONE, SWARP_STABILIZE_NONE, SWARP_STABILIZE_SPHERE};
    int cases_in_box = 0;
    for (int k = 0; k < 3; ++k) {
        swarp_cascade_result r0, r1;
        swarp_cascade_split s0[SWARP_CASCADE_MAX_SPLITS], s1[SWARP_CASCADE_MAX_SPLITS];
        size_t n0, n1;
        run_cascade(techs[k], modes[k], SWARP_DEPTH_ZERO_TO_ONE, &r0, s0, &n0, &L);
        run_cascade(techs[k], modes[k], SWARP_DEPTH_REVERSED_ZERO_TO_ONE, &r1, s1, &n1, &L);
        ck_assert_uint_eq(n0, n1);
        ck_assert_mem_eq(r0.splits, r1.splits, sizeof r0.splits);
        swarp_camera c = camera();
        for (size_t i = 0; i < n0; ++i) {
            ck_assert_mem_eq(&s0[i].tile.viewport_x, &s1[i].tile.viewport_x, 4 * sizeof(double));
            /* depth per world unit: the [0, 1] value negated */
            ck_assert_double_le(fabs(s1[i].depth_per_world + s0[i].depth_per_world),
                                RTOL * fabs(s0[i].depth_per_world));
            ck_assert_double_gt(s0[i].depth_per_world, 0.0);
            for (int j = 0; j < 27; ++j) {
                const double z = r0.splits[i] + (0.05 + 0.45 * (j / 9)) * (r0.splits[i + 1] - r0.splits[i]);
                swarp_vec3 p = frustum_point(&c, z, (j % 3 - 1) * 0.9, (j / 3 % 3 - 1) * 0.9);
                /* the stabilised matrices take p - origin (origin 0 here) */
                assert_turned_over(&s0[i].matrix, &s1[i].matrix, p);
                assert_turned_over(&s0[i].atlas_matrix, &s1[i].atlas_matrix, p);
                if (!in_box(p)) continue;
                /* the defining property: p (a receiver of V_i ∩ S) and the
                 * casters toward the light inside S lie inside the reversed
                 * range, the casters at a larger depth */
                double dp[4];
                ndc(&s1[i].atlas_matrix, p, dp);
                ck_assert_double_ge(dp[2], -TOL);
                ck_assert_double_le(dp[2], 1 + TOL);
                for (double t = 1.0; t < 400.0; t *= 2.0) {
                    swarp_vec3 q = vadd(p, vscale(vnorm(L.direction), -t));
                    if (!in_box(q)) break;
                    double dq[4];
                    ndc(&s1[i].atlas_matrix, q, dq);
                    ck_assert_double_gt(dq[2], dp[2]);
                    ck_assert_double_le(dq[2], 1 + TOL);
                    ++cases_in_box;
                }
            }
        }
    }
    ck_assert_int_gt(cases_in_box, 50); /* the property was exercised */
}
END_TEST

START_TEST(atlas_reversed_passes_depth_through) {
    swarp_atlas_tile t0[4], t1[4];
    size_t n0, n1;
    ck_assert_int_eq(swarp_atlas_layout(4, 1024, SWARP_DEPTH_ZERO_TO_ONE, NULL, t0, 4, &n0), SWARP_OK);
    ck_assert_int_eq(swarp_atlas_layout(4, 1024, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, NULL, t1, 4, &n1), SWARP_OK);
    ck_assert_uint_eq(n0, n1);
    /* a reversed split matrix's clip point (x, y, w - z, w) lands on the
     * window depth 1 - z/w: the light's near plane (z = 0) at 1 */
    const swarp_vec3 pts[3] = {{0.3, -0.2, 0.0}, {-0.9, 0.4, 0.25}, {0.1, 0.1, 1.0}};
    for (size_t i = 0; i < n0; ++i) {
        ck_assert_mem_eq(&t0[i], &t1[i], sizeof t0[i]);
        for (int k = 0; k < 3; ++k) {
            swarp_vec3 rev = v3(pts[k].x, pts[k].y, 1.0 - pts[k].z); /* w = 1 */
            double a[4];
            ndc(&t1[i].clip_to_atlas, rev, a);
            ck_assert_double_le(fabs(a[2] - (1.0 - pts[k].z)), TOL);
        }
    }
}
END_TEST

static void bias_maps(swarp_bias_map* m0, swarp_bias_map* m1, swarp_light* L, int point) {
    swarp_camera c = camera();
    memset(L, 0, sizeof *L);
    if (point) {
        L->type = SWARP_LIGHT_POINT;
        L->position = v3(20, 300, -50);
    } else {
        L->direction = v3(0.3, -1, 0.2);
    }
    swarp_setup_options o = {0};
    o.technique = point ? SWARP_TECHNIQUE_UNIFORM : SWARP_TECHNIQUE_LISPSM;
    swarp_setup_result r0, r1;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    ck_assert(!swarp_status_is_error(swarp_setup(&c, L, &scene, &o, &r0, NULL, 0, NULL)));
    o.depth_range = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
    ck_assert(!swarp_status_is_error(swarp_setup(&c, L, &scene, &o, &r1, NULL, 0, NULL)));
    memset(m0, 0, sizeof *m0);
    memset(m1, 0, sizeof *m1);
    m0->world_to_clip = r0.matrix, m1->world_to_clip = r1.matrix;
    m0->res_s = m1->res_s = 2048;
    m0->res_t = m1->res_t = 1024;
    m0->depth = SWARP_DEPTH_ZERO_TO_ONE;
    m1->depth = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
}

START_TEST(bias_reversed_flips_the_depth_signs) {
    swarp_camera c = camera();
    for (int point = 0; point < 2; ++point) {
        swarp_bias_map m0, m1;
        swarp_light L;
        bias_maps(&m0, &m1, &L, point);
        for (int j = 0; j < 9; ++j) {
            swarp_vec3 p = frustum_point(&c, 3.0 + 9.0 * j, 0.3 * (j % 3 - 1), -0.5);
            const swarp_vec3 N = vnorm(v3(0.2, 1, 0.1 * j));
            double T0, T1;
            ck_assert_int_eq(swarp_bias_texel_size(&m0, &p, &T0, NULL, NULL), SWARP_OK);
            ck_assert_int_eq(swarp_bias_texel_size(&m1, &p, &T1, NULL, NULL), SWARP_OK);
            ck_assert_double_le(fabs(T1 - T0), RTOL * T0);
            double k0, k1;
            ck_assert_int_eq(swarp_bias_depth_per_world(&m0, &L, &p, &k0), SWARP_OK);
            ck_assert_int_eq(swarp_bias_depth_per_world(&m1, &L, &p, &k1), SWARP_OK);
            ck_assert_double_gt(k0, 0.0);
            ck_assert_double_le(fabs(k1 + k0), RTOL * k0);
            double w0, w1, db0, db1;
            swarp_status s0 = swarp_bias_slope_scaled(&m0, &L, &p, &N, 0.01, 1.5, &w0, &db0);
            swarp_status s1 = swarp_bias_slope_scaled(&m1, &L, &p, &N, 0.01, 1.5, &w1, &db1);
            ck_assert_int_eq(s0, SWARP_OK);
            ck_assert_int_eq(s1, SWARP_OK);
            ck_assert_double_le(fabs(w1 - w0), RTOL * w0);
            ck_assert_double_le(fabs(db1 + db0), RTOL * db0);
            /* defining property, evaluated by transforming the moved point:
             * d(p) - bias = d(p + w L), which under GREATER is a larger
             * depth than the receiver's own: the acne comparison passes */
            swarp_vec3 Lu;
            ck_assert_int_eq(swarp_bias_to_light(&L, &p, &Lu), SWARP_OK);
            double dp[4], dq[4];
            ndc(&m1.world_to_clip, p, dp);
            ndc(&m1.world_to_clip, vadd(p, vscale(Lu, w1)), dq);
            ck_assert_double_lt(db1, 0.0);
            ck_assert_double_le(fabs((dp[2] - db1) - dq[2]), TOL + RTOL * fabs(db1));
            ck_assert_double_gt(dp[2] - db1, dp[2]);
            /* the receiver plane's gradient negates too */
            const swarp_vec3 ta = vcross(N, v3(1, 0, 0)), tb = vcross(N, ta);
            double g0[2], g1[2];
            ck_assert_int_eq(swarp_bias_receiver_plane(&m0, &p, &ta, &tb, g0), SWARP_OK);
            ck_assert_int_eq(swarp_bias_receiver_plane(&m1, &p, &ta, &tb, g1), SWARP_OK);
            for (int a = 0; a < 2; ++a) ck_assert_double_le(fabs(g1[a] + g0[a]), RTOL * (fabs(g0[a]) + 1e-300));
        }
    }
}
END_TEST

START_TEST(select_best_reversed_chooses_the_same_split) {
    swarp_light L = {0};
    L.direction = v3(0.3, -1, 0.2);
    swarp_cascade_result r0, r1;
    swarp_cascade_split s0[SWARP_CASCADE_MAX_SPLITS], s1[SWARP_CASCADE_MAX_SPLITS];
    size_t n0, n1;
    run_cascade(SWARP_TECHNIQUE_UNIFORM, SWARP_STABILIZE_NONE, SWARP_DEPTH_ZERO_TO_ONE, &r0, s0, &n0, &L);
    run_cascade(SWARP_TECHNIQUE_UNIFORM, SWARP_STABILIZE_NONE, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, &r1, s1, &n1, &L);
    swarp_bias_map m0[SWARP_CASCADE_MAX_SPLITS], m1[SWARP_CASCADE_MAX_SPLITS];
    for (size_t i = 0; i < n0; ++i) {
        memset(&m0[i], 0, sizeof m0[i]);
        memset(&m1[i], 0, sizeof m1[i]);
        m0[i].world_to_clip = s0[i].matrix, m1[i].world_to_clip = s1[i].matrix;
        m0[i].res_s = m0[i].res_t = m1[i].res_s = m1[i].res_t = 1024;
        m0[i].depth = SWARP_DEPTH_ZERO_TO_ONE;
        m1[i].depth = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
    }
    swarp_camera c = camera();
    uint32_t seen = 0, outside = 0;
    for (int j = 0; j < 60; ++j) {
        /* view depths past the far end too: no map covers those */
        swarp_vec3 p = frustum_point(&c, 1.5 + 2.5 * j, 0.8 * sin(j), 0.8 * cos(3.0 * j));
        uint32_t i0 = 99, i1 = 99;
        double T0, T1;
        swarp_status a = swarp_cascade_select_best(m0, n0, &p, 0, &i0, &T0);
        swarp_status b = swarp_cascade_select_best(m1, n1, &p, 0, &i1, &T1);
        ck_assert_int_eq(a, b);
        ck_assert_uint_eq(i0, i1);
        if (a == SWARP_OK) seen |= 1u << i0;
        else outside++;
    }
    ck_assert_uint_ge((unsigned)__builtin_popcount(seen), 2); /* several splits chosen */
    ck_assert_uint_gt(outside, 0);                            /* and the coverage test refused some */
}
END_TEST

START_TEST(lixel_factor_reversed_puts_p_hat_at_one) {
    /* M_l = identity: world (x, y, z) is M_l's clip point, p-hat at z = -1
     * and P at z = +1 ([LIXEL] 'M_l = GLV GLP') */
    swarp_mat4 I, V0, P0, V1, P1;
    memset(&I, 0, sizeof I);
    I.m[0] = I.m[5] = I.m[10] = I.m[15] = 1.0;
    const double f = 0.3;
    ck_assert_int_eq(swarp_lixel_factor(&I, 640, 480, SWARP_DEPTH_ZERO_TO_ONE, f, &V0, &P0), SWARP_OK);
    ck_assert_int_eq(swarp_lixel_factor(&I, 640, 480, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, f, &V1, &P1), SWARP_OK);
    ck_assert_mem_eq(&V0, &V1, sizeof V0);
    double a[4];
    ndc(&P1, v3(0.2, -0.4, -1.0), a);
    ck_assert_double_le(fabs(a[2] - 1.0), TOL);
    ndc(&P1, v3(0.2, -0.4, 1.0), a);
    ck_assert_double_le(fabs(a[2] - (1.0 - f)), TOL);
    const swarp_vec3 q[3] = {{0.1, 0.2, 0.0}, {-3, 2, 0.7}, {5, -1, -0.4}};
    for (int k = 0; k < 3; ++k) assert_turned_over(&P0, &P1, q[k]);
}
END_TEST

START_TEST(inverse_matrix_reversed_gives_the_same_frustum) {
    /* a right-handed [0, 1] perspective by hand (n = 2, f = 50, as cglm's
     * glm_perspective_rh_zo), turned over for reversed-Z */
    const double n = 2, fz = 50, sy = 1.0 / tan(0.4), sx = sy / 1.5;
    swarp_mat4 P0, P1, P0i, P1i;
    memset(&P0, 0, sizeof P0);
    P0.m[0] = sx, P0.m[5] = sy, P0.m[10] = fz / (n - fz), P0.m[11] = -1, P0.m[14] = fz * n / (n - fz);
    P1 = P0;
    for (int col = 0; col < 4; ++col) P1.m[col * 4 + 2] = P0.m[col * 4 + 3] - P0.m[col * 4 + 2];
    ck_assert_int_eq(swarp_mat4_invert(&P0, &P0i), SWARP_OK);
    ck_assert_int_eq(swarp_mat4_invert(&P1, &P1i), SWARP_OK);
    swarp_polyhedron A, B;
    ck_assert_int_eq(swarp_poly_from_inverse_matrix(&P0i, SWARP_DEPTH_ZERO_TO_ONE, &A), SWARP_OK);
    ck_assert_int_eq(swarp_poly_from_inverse_matrix(&P1i, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, &B), SWARP_OK);
    ck_assert_uint_eq(A.vertex_count, 8);
    ck_assert_uint_eq(B.vertex_count, 8);
    /* every vertex is a corner of the frustum: z = -n or -f, |x| = z tan.. */
    for (uint32_t v = 0; v < 8; ++v) {
        swarp_vec3 p = B.vertices[v];
        const double z = -p.z;
        ck_assert(fabs(z - n) <= 1e-12 * fz || fabs(z - fz) <= 1e-9 * fz);
        ck_assert_double_le(fabs(fabs(p.x) - z / sx), 1e-9 * fz);
        ck_assert_double_le(fabs(fabs(p.y) - z / sy), 1e-9 * fz);
        /* and B's vertices are A's, face by face */
        ck_assert_double_le(fabs(B.vertices[v].x - A.vertices[v].x) + fabs(B.vertices[v].y - A.vertices[v].y) +
                                fabs(B.vertices[v].z - A.vertices[v].z),
                            1e-9 * fz);
    }
    /* reversed-Z with an infinite far plane: its far face is at w = 0 */
    swarp_mat4 Pinf, Pinfi;
    memset(&Pinf, 0, sizeof Pinf);
    Pinf.m[0] = sx, Pinf.m[5] = sy, Pinf.m[11] = -1, Pinf.m[14] = n; /* z/w = n/(-z_eye) */
    ck_assert_int_eq(swarp_mat4_invert(&Pinf, &Pinfi), SWARP_OK);
    swarp_polyhedron C;
    memset(&C, 0xA5, sizeof C);
    swarp_polyhedron Cs = C;
    ck_assert_int_eq(swarp_poly_from_inverse_matrix(&Pinfi, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, &C),
                     SWARP_ERR_DEGENERATE);
    ck_assert_mem_eq(&C, &Cs, sizeof C);
}
END_TEST

START_TEST(an_enum_beyond_reversed_is_refused) {
    const swarp_depth_range bad = (swarp_depth_range)4;
    swarp_atlas_tile t[1];
    size_t n = 7;
    ck_assert_int_eq(swarp_atlas_layout(1, 64, bad, NULL, t, 1, &n), SWARP_ERR_UNKNOWN_ENUM);
    ck_assert_uint_eq(n, 7);
    swarp_bias_map m;
    memset(&m, 0, sizeof m);
    m.world_to_clip.m[0] = m.world_to_clip.m[5] = m.world_to_clip.m[10] = m.world_to_clip.m[15] = 1;
    m.res_s = m.res_t = 64;
    m.depth = bad;
    swarp_vec3 p = v3(0, 0, 0);
    double T = -1;
    ck_assert_int_eq(swarp_bias_texel_size(&m, &p, &T, NULL, NULL), SWARP_ERR_UNKNOWN_ENUM);
    ck_assert_double_eq(T, -1);
    swarp_mat4 V, P;
    ck_assert_int_eq(swarp_lixel_factor(&m.world_to_clip, 4, 4, bad, 0, &V, &P), SWARP_ERR_UNKNOWN_ENUM);
    swarp_polyhedron Q;
    ck_assert_int_eq(swarp_poly_from_inverse_matrix(&m.world_to_clip, bad, &Q), SWARP_ERR_UNKNOWN_ENUM);
}
END_TEST

int main(void) {
    Suite* s = suite_create("depth_reversed_maps");
    TCase* tc = tcase_create("depth_reversed_maps");
    tcase_add_test(tc, cascade_reversed_is_the_zero_to_one_cascade_turned_over);
    tcase_add_test(tc, atlas_reversed_passes_depth_through);
    tcase_add_test(tc, bias_reversed_flips_the_depth_signs);
    tcase_add_test(tc, select_best_reversed_chooses_the_same_split);
    tcase_add_test(tc, lixel_factor_reversed_puts_p_hat_at_one);
    tcase_add_test(tc, inverse_matrix_reversed_gives_the_same_frustum);
    tcase_add_test(tc, an_enum_beyond_reversed_is_refused);
    suite_add_tcase(s, tc);
    return tu_run_suite(s) ? 1 : 0;
}
