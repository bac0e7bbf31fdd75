/* swarp_camera_from_matrices: engine matrices (built by cglm in float, and
 * by hand for the reversed-Z and infinite projections cglm does not make)
 * give back the camera they were built from, and the recovered camera's
 * frustum corners land on the corners of the NDC cube through the engine's
 * own matrices (the defining property, evaluated by plain matrix products
 * that share no code with the library).  Non-perspective matrices get their
 * specific statuses with the outputs untouched. */
#include <check.h>
/* every clip-space convention of cglm, not only its configured default */
#define CGLM_CLIPSPACE_INCLUDE_ALL
#include <cglm/cglm.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "shadowwarp.h"
#include "shadowwarp_cglm.h"
#include "test_util.h"
#include "test_vec.h"

/* Float matrices round each entry at FLT_EPSILON/2 relative.  Positions,
 * directions and angles read from them are as exact to a small multiple:
 * 16 FLT_EPSILON.  Far inherits 1/(z_far_ndc + A) ~ f/n amplification. */
#define TOL_F (16.0 * FLT_EPSILON)
/* The defining property is evaluated in double on the same numbers the
 * library read; the corners off the view axis carry the float view rows'
 * departure from the orthonormal frame a swarp_camera is (~FLT_EPSILON),
 * so NDC agrees to TOL_F. */

typedef struct cam_in {
    vec3 eye, dir, up;
    float fovy, aspect, n, f;
} cam_in;

static const cam_in cams[] = {
    {{0, 10, 0}, {0, -0.2f, -1}, {0, 1, 0}, 1.0472f, 1.7778f, 1.0f, 100.0f},
    {{1e4f, -30, 2e4f}, {0.3f, 0.1f, 0.9f}, {0, 1, 0}, 0.5f, 1.0f, 0.5f, 5000.0f},
    {{-3, 2, 7}, {1, 0, 0}, {0, 0, 1}, 2.5f, 0.5f, 0.01f, 10.0f},
    {{5, 5, 5}, {-1, -1, -1}, {0, 1, 0}, 0.2f, 2.4f, 2.0f, 2.5f},
};
#define NCAMS (sizeof cams / sizeof cams[0])

static void to_swarp(mat4 m, swarp_mat4* out) { swarp_cglm_mat4_to_swarp(m, out); }

/* clip = P V p in double on the column-major numbers as given: how the
 * engine's GPU maps a point (LH matrices included: they are column-vector
 * matrices too). */
static void engine_ndc(const swarp_mat4* V, const swarp_mat4* P, swarp_vec3 p, double ndc[3]) {
    double v[4] = {p.x, p.y, p.z, 1.0}, e[4], c[4];
    for (int r = 0; r < 4; ++r) {
        e[r] = 0.0;
        for (int k = 0; k < 4; ++k) e[r] += V->m[k * 4 + r] * v[k];
    }
    for (int r = 0; r < 4; ++r) {
        c[r] = 0.0;
        for (int k = 0; k < 4; ++k) c[r] += P->m[k * 4 + r] * e[k];
    }
    for (int k = 0; k < 3; ++k) ndc[k] = c[k] / c[3];
}

/* corner (sx, sy) of the camera's plane at view depth d: eye + d (f + sx
 * tan(fovy/2) aspect r + sy tan(fovy/2) u) */
static swarp_vec3 corner(const swarp_camera* c, double d, double sx, double sy) {
    swarp_vec3 f = vnorm(c->dir), r = vnorm(vcross(f, c->up)), u = vcross(r, f);
    double ty = tan(0.5 * c->fovy), tx = ty * c->aspect;
    return vadd(c->eye, vscale(vadd(f, vadd(vscale(r, sx * tx), vscale(u, sy * ty))), d));
}

/* The recovered frustum's corners at near and far map to x, y = +-1 (up to
 * a flipped axis) and z = z_near_ndc, z_far_ndc through the engine's
 * matrices. */
static void assert_corners(const swarp_camera* c, const swarp_mat4* V, const swarp_mat4* P, double zn, double zf) {
    const double d[2] = {c->z_near, c->z_far}, z[2] = {zn, zf};
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 4; ++i) {
            double sx = (i & 1) ? 1 : -1, sy = (i & 2) ? 1 : -1, ndc[3];
            engine_ndc(V, P, corner(c, d[k], sx, sy), ndc);
            ck_assert_double_le(fabs(fabs(ndc[0]) - 1.0), TOL_F);
            ck_assert_double_le(fabs(fabs(ndc[1]) - 1.0), TOL_F);
            ck_assert_double_le(fabs(ndc[2] - z[k]), TOL_F);
        }
}

/* the camera equals the one cglm was given, to float rounding */
static void assert_same_camera(const swarp_camera* c, const cam_in* in) {
    swarp_vec3 eye = v3(in->eye[0], in->eye[1], in->eye[2]);
    /* the direction cglm's look used: center = eye + dir, rounded to float */
    float center[3];
    for (int k = 0; k < 3; ++k) center[k] = in->eye[k] + in->dir[k];
    swarp_vec3 f = vnorm(vsub(v3(center[0], center[1], center[2]), eye));
    swarp_vec3 up = v3(in->up[0], in->up[1], in->up[2]);
    swarp_vec3 u = vnorm(vsub(up, vscale(f, vdot(up, f))));
    double scale = fmax(1.0, vlen(eye));
    ck_assert_double_le(vlen(vsub(c->eye, eye)), TOL_F * scale * 64.0);
    ck_assert_double_le(vlen(vsub(vnorm(c->dir), f)), TOL_F);
    ck_assert_double_le(vlen(vsub(vnorm(vsub(c->up, vscale(vnorm(c->dir), vdot(c->up, vnorm(c->dir))))), u)), TOL_F);
    ck_assert_double_le(tu_rel(c->fovy, in->fovy), TOL_F);
    ck_assert_double_le(tu_rel(c->aspect, in->aspect), TOL_F);
    ck_assert_double_le(tu_rel(c->z_near, in->n), TOL_F * in->f / in->n);
    ck_assert_double_le(tu_rel(c->z_far, in->f), TOL_F * in->f / in->n);
}

typedef void (*persp_fn)(float, float, float, float, mat4);
typedef void (*look_fn)(vec3, vec3, vec3, mat4);

/* the view and projection cglm builds for camera `in`, as swarp matrices */
static void cglm_pair(const cam_in* in, look_fn look, persp_fn persp, swarp_mat4* V, swarp_mat4* P) {
    mat4 v, p;
    vec3 eye, dir, up;
    glm_vec3_copy((float*)in->eye, eye);
    glm_vec3_copy((float*)in->dir, dir);
    glm_vec3_copy((float*)in->up, up);
    look(eye, dir, up, v);
    persp(in->fovy, in->aspect, in->n, in->f, p);
    to_swarp(v, V);
    to_swarp(p, P);
}

static void cglm_round_trip(look_fn look, persp_fn persp, swarp_matrix_convention conv, swarp_depth_range dr,
                            double zn, double zf) {
    for (size_t i = 0; i < NCAMS; ++i) {
        const cam_in* in = &cams[i];
        swarp_mat4 V, P;
        cglm_pair(in, look, persp, &V, &P);
        swarp_camera c;
        swarp_camera_from_info info;
        ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, conv, dr, NULL, &c, &info), SWARP_OK);
        ck_assert_uint_eq(info.reversed_z, 0);
        ck_assert_uint_eq(info.infinite_far, 0);
        assert_same_camera(&c, in);
        assert_corners(&c, &V, &P, zn, zf);
        /* the transposed numbers with the _TRANSPOSED convention: the same camera, bit for bit */
        swarp_mat4 Vt, Pt;
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) Vt.m[r * 4 + k] = V.m[k * 4 + r], Pt.m[r * 4 + k] = P.m[k * 4 + r];
        swarp_camera ct;
        swarp_matrix_convention tconv = conv == SWARP_MATRIX_LH ? SWARP_MATRIX_LH_TRANSPOSED : SWARP_MATRIX_RH_TRANSPOSED;
        ck_assert_int_eq(swarp_camera_from_matrices(&Vt, &Pt, tconv, dr, NULL, &ct, NULL), SWARP_OK);
        ck_assert_mem_eq(&ct, &c, sizeof c);
    }
}

START_TEST(cglm_rh_gl_depth_round_trips) {
    cglm_round_trip(glm_look_rh, glm_perspective_rh_no, SWARP_MATRIX_DEFAULT, SWARP_DEPTH_DEFAULT, -1.0, 1.0);
}
END_TEST

START_TEST(cglm_rh_zero_to_one_round_trips) {
    cglm_round_trip(glm_look_rh, glm_perspective_rh_zo, SWARP_MATRIX_RH, SWARP_DEPTH_ZERO_TO_ONE, 0.0, 1.0);
}
END_TEST

START_TEST(cglm_lh_zero_to_one_round_trips) {
    cglm_round_trip(glm_look_lh, glm_perspective_lh_zo, SWARP_MATRIX_LH, SWARP_DEPTH_ZERO_TO_ONE, 0.0, 1.0);
}
END_TEST

START_TEST(cglm_lh_gl_depth_round_trips) {
    cglm_round_trip(glm_look_lh, glm_perspective_lh_no, SWARP_MATRIX_LH, SWARP_DEPTH_NEG_ONE_TO_ONE, -1.0, 1.0);
}
END_TEST

/* A right-handed view in double, and a projection with rows 2 and 3 given
 * (z_clip = a z + b, w = -z): the hand-made reversed and infinite ones. */
static void hand_matrices(double fovy, double aspect, double a, double b, double w_sign, swarp_mat4* V,
                          swarp_mat4* P) {
    mat4 v;
    vec3 eye = {3, 4, 5}, dir = {0.2f, -0.3f, -1}, up = {0, 1, 0};
    glm_look_rh(eye, dir, up, v);
    to_swarp(v, V);
    memset(P, 0, sizeof *P);
    double t = tan(0.5 * fovy);
    P->m[0] = 1.0 / (t * aspect);
    P->m[5] = 1.0 / t;
    P->m[10] = a;
    P->m[14] = b;
    P->m[11] = w_sign;
}

START_TEST(reversed_infinite_far_is_bounded_by_the_scene_box) {
    /* reversed-Z [0, 1], infinite far: z_clip = n, w = -z: z_ndc = n/d, 1 at near, 0 at infinity */
    const double n = 0.1;
    swarp_mat4 V, P;
    hand_matrices(1.0, 1.5, 0.0, n, -1.0, &V, &P);
    swarp_camera c;
    swarp_camera_from_info info;
    tu_fill((double*)&c, sizeof c / sizeof(double), 7.0);
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_REVERSED_ZERO_TO_ONE, NULL,
                                                &c, &info),
                     SWARP_ERR_CAMERA_FAR_UNBOUNDED);
    ck_assert(tu_untouched((double*)&c, sizeof c / sizeof(double), 7.0));
    swarp_aabb S = {{-50, -10, -400}, {60, 20, 30}};
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_ZERO_TO_ONE, &S, &c, &info),
                     SWARP_INFO_CAMERA_FAR_FROM_SCENE);
    ck_assert_uint_eq(info.reversed_z, 1);
    ck_assert_uint_eq(info.infinite_far, 1);
    ck_assert_double_le(tu_rel(c.z_near, n), 1e-15);
    ck_assert_double_le(tu_rel(c.fovy, 1.0), 1e-15);
    ck_assert_double_le(tu_rel(c.aspect, 1.5), 1e-15);
    /* brute force: the farthest of the box's corners along the view direction */
    swarp_vec3 f = vnorm(v3(0.2f, -0.3f, -1)), eye = v3(3, 4, 5);
    double far = -INFINITY;
    for (int i = 0; i < 8; ++i) {
        swarp_vec3 q = v3(i & 1 ? S.max.x : S.min.x, i & 2 ? S.max.y : S.min.y, i & 4 ? S.max.z : S.min.z);
        far = fmax(far, vdot(vsub(q, eye), f));
    }
    ck_assert_double_le(tu_rel(c.z_far, far), 1e-6);
    /* near corners at NDC depth 1, far corners at n/far (the engine's depth there) */
    assert_corners(&c, &V, &P, 1.0, n / c.z_far);
    /* the camera works in the one call */
    swarp_light L = {0};
    L.direction = v3(0.3, -1, 0.2);
    swarp_setup_result r;
    ck_assert(!swarp_status_is_error(swarp_setup(&c, &L, &S, NULL, &r, NULL, 0, NULL)));
    /* a scene wholly nearer than the near plane: nothing to bound the view with */
    swarp_aabb behind = {{2, 3, 6}, {4, 5, 8}};
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_ZERO_TO_ONE, &behind, &c, NULL),
                     SWARP_ERR_BODY_EMPTY);
}
END_TEST

START_TEST(reversed_and_infinite_finite_forms_give_their_planes) {
    const double n = 0.5, f = 300.0;
    swarp_mat4 V, P;
    swarp_camera c;
    swarp_camera_from_info info;
    /* reversed [0, 1] finite: z_ndc = -A + B/d with 1 at n and 0 at f */
    hand_matrices(0.8, 1.0, n / (f - n), n * f / (f - n), -1.0, &V, &P);
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_ZERO_TO_ONE, NULL, &c, &info),
                     SWARP_OK);
    ck_assert_uint_eq(info.reversed_z, 1);
    ck_assert_double_le(tu_rel(c.z_near, n), 1e-14);
    ck_assert_double_le(tu_rel(c.z_far, f), 1e-14);
    assert_corners(&c, &V, &P, 1.0, 0.0);
    /* OpenGL infinite: A = -1, B = -2n */
    hand_matrices(0.8, 1.0, -1.0, -2.0 * n, -1.0, &V, &P);
    swarp_aabb S = {{-100, -100, -100}, {100, 100, 100}};
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_NEG_ONE_TO_ONE, &S, &c, &info),
                     SWARP_INFO_CAMERA_FAR_FROM_SCENE);
    ck_assert_uint_eq(info.reversed_z, 0);
    ck_assert_uint_eq(info.infinite_far, 1);
    ck_assert_double_le(tu_rel(c.z_near, n), 1e-14);
    /* Lengyel's tweaked infinite matrix, A = eps - 1: depth never reaches 1,
     * still an infinite far plane */
    hand_matrices(0.8, 1.0, -1.0 + FLT_EPSILON, -2.0 * n, -1.0, &V, &P);
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_NEG_ONE_TO_ONE, &S, &c, &info),
                     SWARP_INFO_CAMERA_FAR_FROM_SCENE);
    /* A one float ulp below -1 is a finite far plane where z_ndc = -A + B/d = 1 */
    hand_matrices(0.8, 1.0, -1.0 - FLT_EPSILON, -2.0 * n, -1.0, &V, &P);
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_NEG_ONE_TO_ONE, &S, &c, &info),
                     SWARP_OK);
    ck_assert_double_le(tu_rel(c.z_far, 2.0 * n / FLT_EPSILON), 1e-14);
    /* a far plane well behind the eye is no far plane */
    hand_matrices(0.8, 1.0, -0.5, -2.0 * n, -1.0, &V, &P); /* z_ndc = 0.5 - 2n/d < 1 for every d */
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_NEG_ONE_TO_ONE, &S, &c, &info),
                     SWARP_ERR_NEAR_FAR);
}
END_TEST

START_TEST(off_center_frustum_gives_the_smallest_containing_symmetric_one) {
    mat4 v, p;
    vec3 eye = {0, 2, 0}, dir = {0, 0, -1}, up = {0, 1, 0};
    glm_look_rh(eye, dir, up, v);
    const float l = -0.3f, r = 0.5f, b = -0.2f, t = 0.25f, n = 1.0f, f = 50.0f;
    glm_frustum_rh_no(l, r, b, t, n, f, p);
    swarp_mat4 V, P;
    to_swarp(v, &V);
    to_swarp(p, &P);
    swarp_camera c;
    swarp_camera_from_info info;
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_DEFAULT, NULL, &c, &info), SWARP_OK);
    /* from the planes directly: tan of the half angles max(|l|, |r|)/n, max(|b|, |t|)/n */
    ck_assert_double_le(tu_rel(tan(0.5 * c.fovy), 0.25 / 1.0), TOL_F);
    ck_assert_double_le(tu_rel(tan(0.5 * c.fovy) * c.aspect, 0.5 / 1.0), TOL_F);
    ck_assert_double_le(tu_rel(info.off_center_x, (r + l) / (r - l)), TOL_F);
    ck_assert_double_le(tu_rel(info.off_center_y, (t + b) / (t - b)), TOL_F);
}
END_TEST

START_TEST(vulkan_y_flip_leaves_the_camera_unchanged) {
    swarp_mat4 V, P;
    cglm_pair(&cams[0], glm_look_rh, glm_perspective_rh_zo, &V, &P);
    swarp_camera c0, c1;
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_ZERO_TO_ONE, NULL, &c0, NULL), SWARP_OK);
    P.m[5] = -P.m[5];
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_ZERO_TO_ONE, NULL, &c1, NULL), SWARP_OK);
    ck_assert_mem_eq(&c0, &c1, sizeof c0);
}
END_TEST

/* every bad matrix: its status, and the camera and info untouched */
static void assert_refused(const swarp_mat4* V, const swarp_mat4* P, swarp_matrix_convention conv, swarp_status want) {
    swarp_camera c;
    swarp_camera_from_info info;
    tu_fill((double*)&c, sizeof c / sizeof(double), 3.0);
    tu_fill((double*)&info, sizeof info / sizeof(double), 3.0);
    swarp_aabb S = {{-10, -10, -10}, {10, 10, 10}};
    ck_assert_int_eq(swarp_camera_from_matrices(V, P, conv, SWARP_DEPTH_DEFAULT, &S, &c, &info), want);
    ck_assert(tu_untouched((double*)&c, sizeof c / sizeof(double), 3.0));
    ck_assert(tu_untouched((double*)&info, sizeof info / sizeof(double), 3.0));
}

START_TEST(non_perspective_matrices_get_specific_statuses) {
    mat4 o;
    glm_ortho_rh_no(-10, 10, -10, 10, 1, 100, o);
    swarp_mat4 V, P, O, X;
    cglm_pair(&cams[0], glm_look_rh, glm_perspective_rh_no, &V, &P);
    to_swarp(o, &O);
    assert_refused(&V, &O, SWARP_MATRIX_RH, SWARP_ERR_CAMERA_NOT_PERSPECTIVE);
    X = P, X.m[4] = 0.1; /* x from y: sheared */
    assert_refused(&V, &X, SWARP_MATRIX_RH, SWARP_ERR_CAMERA_NOT_PERSPECTIVE);
    X = P, X.m[0] = 0.0; /* no x scale */
    assert_refused(&V, &X, SWARP_MATRIX_RH, SWARP_ERR_SINGULAR);
    X = V, X.m[0] = X.m[4] = X.m[8] = 0.0; /* view without an x row */
    assert_refused(&X, &P, SWARP_MATRIX_RH, SWARP_ERR_SINGULAR);
    X = P, X.m[10] = NAN;
    assert_refused(&V, &X, SWARP_MATRIX_RH, SWARP_ERR_NON_FINITE);
    X = V, X.m[13] = INFINITY;
    assert_refused(&X, &P, SWARP_MATRIX_RH, SWARP_ERR_NON_FINITE);
    X = V, X.m[0] = -X.m[0], X.m[4] = -X.m[4], X.m[8] = -X.m[8]; /* mirrored view */
    assert_refused(&X, &P, SWARP_MATRIX_RH, SWARP_ERR_CAMERA_MIRRORED);
    assert_refused(&V, &P, SWARP_MATRIX_LH, SWARP_ERR_CAMERA_MIRRORED); /* an RH pair read as LH */
    X = V;
    for (int k = 0; k < 12; ++k) X.m[k] *= 2.0; /* scaled view */
    assert_refused(&X, &P, SWARP_MATRIX_RH, SWARP_ERR_CAMERA_VIEW_NOT_RIGID);
    X = V, X.m[3] = 0.01; /* projective bottom row */
    assert_refused(&X, &P, SWARP_MATRIX_RH, SWARP_ERR_CAMERA_VIEW_NOT_RIGID);
    X = P, X.m[14] = -X.m[14]; /* near plane behind the eye */
    assert_refused(&V, &X, SWARP_MATRIX_RH, SWARP_ERR_NEAR_FAR);
    assert_refused(&V, &P, (swarp_matrix_convention)5, SWARP_ERR_UNKNOWN_ENUM);
    swarp_camera c;
    ck_assert_int_eq(swarp_camera_from_matrices(NULL, &P, SWARP_MATRIX_RH, SWARP_DEPTH_DEFAULT, NULL, &c, NULL),
                     SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, (swarp_depth_range)9, NULL, &c, NULL),
                     SWARP_ERR_UNKNOWN_ENUM);
    swarp_aabb inv = {{1, 1, 1}, {0, 0, 0}};
    ck_assert_int_eq(swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_DEFAULT, &inv, &c, NULL),
                     SWARP_ERR_BOX_INVERTED);
}
END_TEST

int main(void) {
    Suite* s = suite_create("camera_from");
    TCase* tc = tcase_create("camera_from");
    tcase_add_test(tc, cglm_rh_gl_depth_round_trips);
    tcase_add_test(tc, cglm_rh_zero_to_one_round_trips);
    tcase_add_test(tc, cglm_lh_zero_to_one_round_trips);
    tcase_add_test(tc, cglm_lh_gl_depth_round_trips);
    tcase_add_test(tc, reversed_infinite_far_is_bounded_by_the_scene_box);
    tcase_add_test(tc, reversed_and_infinite_finite_forms_give_their_planes);
    tcase_add_test(tc, off_center_frustum_gives_the_smallest_containing_symmetric_one);
    tcase_add_test(tc, vulkan_y_flip_leaves_the_camera_unchanged);
    tcase_add_test(tc, non_perspective_matrices_get_specific_statuses);
    suite_add_tcase(s, tc);
    return tu_run_suite(s) ? 1 : 0;
}
