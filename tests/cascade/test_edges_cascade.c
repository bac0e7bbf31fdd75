#define _POSIX_C_SOURCE 200809L
/* Argument checks and edge branches of the cascade stage's functions (bias,
 * stabilisation, selection): every bad input gives its documented status with the
 * outputs untouched, and the valid results are compared with an independent
 * evaluation (an orthographic map, where the world-space texel is
 * width / resolution and depth is linear in the light's z). */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define SENTINEL (-7.25e33)

/* An orthographic light map looking down -y: x in [-W/2, W/2] -> s, z in
 * [-W/2, W/2] -> t (clip y = -z... any sign), light-space depth along -y:
 * world y = Y0 -> clip z = -1, y = Y0 - D -> +1 (NEG_ONE_TO_ONE). */
static const double W = 20.0, Y0 = 10.0, D = 40.0;
static swarp_bias_map ortho_map(swarp_depth_range depth) {
    swarp_bias_map m;
    memset(&m, 0, sizeof m);
    double* a = m.world_to_clip.m; /* column-major: a[c * 4 + r] */
    a[0 * 4 + 0] = 2.0 / W;        /* clip x = 2 x / W */
    a[2 * 4 + 1] = 2.0 / W;        /* clip y = 2 z / W */
    if (depth == SWARP_DEPTH_ZERO_TO_ONE) { /* clip z = (Y0 - y) / D */
        a[1 * 4 + 2] = -1.0 / D;
        a[3 * 4 + 2] = Y0 / D;
    } else { /* clip z = 2 (Y0 - y) / D - 1 */
        a[1 * 4 + 2] = -2.0 / D;
        a[3 * 4 + 2] = 2.0 * Y0 / D - 1.0;
    }
    a[3 * 4 + 3] = 1.0;
    m.res_s = 1024.0;
    m.res_t = 512.0;
    m.depth = depth;
    return m;
}
static swarp_light sun(void) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){0.0, -1.0, 0.0};
    return l;
}

START_TEST(bias_valid_against_orthographic_closed_form) {
    const swarp_depth_range ranges[2] = {SWARP_DEPTH_NEG_ONE_TO_ONE, SWARP_DEPTH_ZERO_TO_ONE};
    for (int r = 0; r < 2; ++r) {
        swarp_bias_map m = ortho_map(ranges[r]);
        swarp_light l = sun();
        swarp_vec3 p = {1.5, -3.0, 2.0};
        double Lt = SENTINEL, Ls = SENTINEL, Ltt = SENTINEL;
        ck_assert_int_eq(swarp_bias_texel_size(&m, &p, &Lt, &Ls, &Ltt), SWARP_OK);
        ck_assert(tu_rel(Ls, W / 1024.0) < 1e-12 && tu_rel(Ltt, W / 512.0) < 1e-12 && Lt == Ltt);
        /* only one output requested */
        double only = SENTINEL;
        ck_assert_int_eq(swarp_bias_texel_size(&m, &p, NULL, &only, NULL), SWARP_OK);
        ck_assert(only == Ls);
        /* kozlov: p + L (a + b L_texel), L = +y */
        swarp_vec3 q;
        double amount;
        ck_assert_int_eq(swarp_bias_kozlov(&m, &l, &p, 0.01, 2.0, &q, &amount), SWARP_OK);
        ck_assert(tu_rel(amount, 0.01 + 2.0 * W / 512.0) < 1e-12);
        ck_assert(q.x == p.x && q.z == p.z && tu_rel(q.y, p.y + amount) < 1e-12);
        ck_assert_int_eq(swarp_bias_kozlov(&m, &l, &p, 0.01, 2.0, &q, NULL), SWARP_OK);
        /* normal offset: k L_texel (1 - N.L) along N; N tilted 60 degrees */
        swarp_vec3 N = {sin(1.0471975511965976), cos(1.0471975511965976), 0.0};
        ck_assert_int_eq(swarp_bias_normal_offset(&m, &l, &p, &N, 1.5, &q, &amount), SWARP_OK);
        ck_assert(tu_rel(amount, 1.5 * (W / 512.0) * (1.0 - 0.5)) < 1e-12);
        ck_assert(fabs(q.x - (p.x + amount * N.x)) < 1e-12);
        /* the same normal scaled to DBL_MAX: |N| overflows but N is a valid
         * direction, so no SWARP_ERR_ZERO_VECTOR */
        const swarp_vec3 Nhuge = {0.95 * DBL_MAX, 0.95 * DBL_MAX * (N.y / N.x), 0.0}; /* |N| = 1.1 DBL_MAX */
        double amount_huge = SENTINEL;
        ck_assert_int_eq(swarp_bias_normal_offset(&m, &l, &p, &Nhuge, 1.5, &q, &amount_huge), SWARP_OK);
        ck_assert(tu_rel(amount_huge, amount) < 1e-12 && fabs(q.x - (p.x + amount * N.x)) < 1e-12);
        /* back-facing normal: N.L clamped to 0, informational status */
        swarp_vec3 Nb = {0.0, -1.0, 0.0};
        ck_assert_int_eq(swarp_bias_normal_offset(&m, &l, &p, &Nb, 1.0, &q, NULL), SWARP_INFO_BACKFACING);
        ck_assert(tu_rel(q.y, p.y - W / 512.0) < 1e-12);
        /* slope-scaled: c + s L_texel tan(angle), depth bias = world bias
         * times the depth scale (2/D for [-1,1] then *0.5 to window = 1/D) */
        double wb = SENTINEL, db = SENTINEL;
        ck_assert_int_eq(swarp_bias_slope_scaled(&m, &l, &p, &N, 0.02, 1.0, &wb, &db), SWARP_OK);
        ck_assert(tu_rel(wb, 0.02 + (W / 512.0) * tan(1.0471975511965976)) < 1e-12);
        ck_assert(tu_rel(db, wb / D) < 1e-10);
        /* grazing: slope capped at 10 */
        swarp_vec3 Ng = {1.0, 1e-9, 0.0};
        ck_assert_int_eq(swarp_bias_slope_scaled(&m, &l, &p, &Ng, 0.0, 1.0, &wb, NULL), SWARP_OK);
        ck_assert(tu_rel(wb, 10.0 * W / 512.0) < 1e-12);
        ck_assert_int_eq(swarp_bias_slope_scaled(&m, &l, &p, &Nb, 0.0, 1.0, NULL, &db), SWARP_INFO_BACKFACING);
        /* depth per world unit toward the light: 1/D in window depth */
        double dpw = SENTINEL;
        ck_assert_int_eq(swarp_bias_depth_per_world(&m, &l, &p, &dpw), SWARP_OK);
        ck_assert(tu_rel(dpw, 1.0 / D) < 1e-12);
        /* receiver plane tilted: depth changes 0.5 world per world x */
        swarp_vec3 ta = {1.0, 0.5, 0.0}, tb = {0.0, 0.0, 1.0};
        double g[2] = {SENTINEL, SENTINEL};
        ck_assert_int_eq(swarp_bias_receiver_plane(&m, &p, &ta, &tb, g), SWARP_OK);
        /* per texel along s: dx = W/1024 world, dy = 0.5 dx, depth -0.5 dx / D */
        ck_assert(tu_rel(g[0], -0.5 * (W / 1024.0) / D) < 1e-10);
        ck_assert(fabs(g[1]) < 1e-15);
        /* point light: L toward the position */
        swarp_light pl = sun();
        pl.type = SWARP_LIGHT_POINT;
        pl.position = (swarp_vec3){p.x, p.y + 5.0, p.z};
        swarp_vec3 L;
        ck_assert_int_eq(swarp_bias_to_light(&pl, &p, &L), SWARP_OK);
        ck_assert(fabs(L.y - 1.0) < 1e-15 && L.x == 0.0 && L.z == 0.0);
        swarp_light dl = sun();
        dl.type = SWARP_LIGHT_DEFAULT;
        ck_assert_int_eq(swarp_bias_to_light(&dl, &p, &L), SWARP_OK);
        ck_assert(L.y == 1.0);
    }
}
END_TEST

/* Every bad input of every bias function: its status, outputs untouched. */
START_TEST(bias_bad_inputs_untouched) {
    const swarp_bias_map good = ortho_map(SWARP_DEPTH_NEG_ONE_TO_ONE);
    const swarp_light sl = sun();
    const swarp_vec3 p = {1.5, -3.0, 2.0}, N = {0.0, 1.0, 0.0}, ta = {1.0, 0.0, 0.0}, tb = {0.0, 0.0, 1.0};
    swarp_bias_map maps[8];
    swarp_status map_st[8];
    int nm = 0;
    maps[nm] = good;
    maps[nm]._reserved[2] = 1;
    map_st[nm++] = SWARP_ERR_RESERVED_NONZERO;
    maps[nm] = good;
    maps[nm]._reserved0 = 1;
    map_st[nm++] = SWARP_ERR_RESERVED_NONZERO;
    maps[nm] = good;
    maps[nm].depth = (swarp_depth_range)9;
    map_st[nm++] = SWARP_ERR_UNKNOWN_ENUM;
    maps[nm] = good;
    maps[nm].world_to_clip.m[5] = NAN;
    map_st[nm++] = SWARP_ERR_NON_FINITE;
    maps[nm] = good;
    maps[nm].res_s = INFINITY;
    map_st[nm++] = SWARP_ERR_RESOLUTION;
    maps[nm] = good;
    maps[nm].res_t = 0.0;
    map_st[nm++] = SWARP_ERR_RESOLUTION;
    maps[nm] = good;
    maps[nm].res_t = NAN;
    map_st[nm++] = SWARP_ERR_RESOLUTION;
    maps[nm] = good;
    maps[nm].res_s = -1.0;
    map_st[nm++] = SWARP_ERR_RESOLUTION;

    swarp_light lights[6];
    swarp_status light_st[6];
    int nl = 0;
    lights[nl] = sl;
    lights[nl]._reserved[0] = 3;
    light_st[nl++] = SWARP_ERR_RESERVED_NONZERO;
    lights[nl] = sl;
    lights[nl]._reserved0 = 3;
    light_st[nl++] = SWARP_ERR_RESERVED_NONZERO;
    lights[nl] = sl;
    lights[nl].type = (swarp_light_type)7;
    light_st[nl++] = SWARP_ERR_UNKNOWN_ENUM;
    lights[nl] = sl;
    lights[nl].direction.y = NAN;
    light_st[nl++] = SWARP_ERR_NON_FINITE;
    lights[nl] = sl;
    lights[nl].type = SWARP_LIGHT_POINT;
    lights[nl].position.x = INFINITY;
    light_st[nl++] = SWARP_ERR_NON_FINITE;
    lights[nl] = sl;
    lights[nl].direction = (swarp_vec3){0, 0, 0};
    light_st[nl++] = SWARP_ERR_ZERO_VECTOR;

    double o[4];
    swarp_vec3 q;
#define RESET() (tu_fill(o, 4, SENTINEL), tu_fill(&q.x, 3, SENTINEL))
#define UNTOUCHED() (tu_untouched(o, 4, SENTINEL) && tu_untouched(&q.x, 3, SENTINEL))
#define EXPECT(call, want)                                                   \
    do {                                                                     \
        RESET();                                                             \
        swarp_status st_ = (call);                                           \
        ck_assert_msg(st_ == (want), "%s: %s, want %s", #call,               \
                      swarp_status_name(st_), swarp_status_name(want));      \
        ck_assert_msg(UNTOUCHED(), "%s wrote its outputs", #call);           \
    } while (0)

    for (int i = 0; i < nm; ++i) {
        const swarp_bias_map* m = &maps[i];
        swarp_status w = map_st[i];
        EXPECT(swarp_bias_texel_size(m, &p, &o[0], &o[1], &o[2]), w);
        EXPECT(swarp_bias_kozlov(m, &sl, &p, 0.1, 1.0, &q, &o[0]), w);
        EXPECT(swarp_bias_normal_offset(m, &sl, &p, &N, 1.0, &q, &o[0]), w);
        EXPECT(swarp_bias_slope_scaled(m, &sl, &p, &N, 0.1, 1.0, &o[0], &o[1]), w);
        EXPECT(swarp_bias_depth_per_world(m, &sl, &p, &o[0]), w);
        EXPECT(swarp_bias_receiver_plane(m, &p, &ta, &tb, o), w);
    }
    for (int i = 0; i < nl; ++i) {
        const swarp_light* l = &lights[i];
        swarp_status w = light_st[i];
        EXPECT(swarp_bias_to_light(l, &p, &q), w);
        EXPECT(swarp_bias_kozlov(&good, l, &p, 0.1, 1.0, &q, &o[0]), w);
        EXPECT(swarp_bias_normal_offset(&good, l, &p, &N, 1.0, &q, &o[0]), w);
        EXPECT(swarp_bias_slope_scaled(&good, l, &p, &N, 0.1, 1.0, &o[0], &o[1]), w);
        EXPECT(swarp_bias_depth_per_world(&good, l, &p, &o[0]), w);
    }
    /* NULL pointers */
    EXPECT(swarp_bias_texel_size(NULL, &p, &o[0], NULL, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_texel_size(&good, NULL, &o[0], NULL, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_texel_size(&good, &p, NULL, NULL, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_to_light(NULL, &p, &q), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_to_light(&sl, NULL, &q), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_to_light(&sl, &p, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_kozlov(NULL, &sl, &p, 0, 0, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_kozlov(&good, NULL, &p, 0, 0, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_kozlov(&good, &sl, NULL, 0, 0, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_kozlov(&good, &sl, &p, 0, 0, NULL, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_normal_offset(NULL, &sl, &p, &N, 1, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_normal_offset(&good, NULL, &p, &N, 1, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_normal_offset(&good, &sl, NULL, &N, 1, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_normal_offset(&good, &sl, &p, NULL, 1, &q, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_normal_offset(&good, &sl, &p, &N, 1, NULL, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_slope_scaled(NULL, &sl, &p, &N, 0, 1, &o[0], NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_slope_scaled(&good, NULL, &p, &N, 0, 1, &o[0], NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, NULL, &N, 0, 1, &o[0], NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, NULL, 0, 1, &o[0], NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &N, 0, 1, NULL, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_depth_per_world(NULL, &sl, &p, &o[0]), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_depth_per_world(&good, NULL, &p, &o[0]), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_depth_per_world(&good, &sl, NULL, &o[0]), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_depth_per_world(&good, &sl, &p, NULL), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_receiver_plane(NULL, &p, &ta, &tb, o), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_receiver_plane(&good, NULL, &ta, &tb, o), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_receiver_plane(&good, &p, NULL, &tb, o), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_receiver_plane(&good, &p, &ta, NULL, o), SWARP_ERR_NULL_POINTER);
    EXPECT(swarp_bias_receiver_plane(&good, &p, &ta, &tb, NULL), SWARP_ERR_NULL_POINTER);
    /* non-finite and out-of-range scalars, points, normals, tangents */
    const swarp_vec3 bad = {NAN, 0, 0}, zero = {0, 0, 0};
    EXPECT(swarp_bias_texel_size(&good, &bad, &o[0], NULL, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_to_light(&sl, &bad, &q), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_kozlov(&good, &sl, &p, NAN, 1, &q, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_kozlov(&good, &sl, &p, 0, INFINITY, &q, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_kozlov(&good, &sl, &p, -1.0, 0.0, &q, NULL), SWARP_ERR_OUT_OF_RANGE);
    EXPECT(swarp_bias_kozlov(&good, &sl, &p, DBL_MAX, DBL_MAX, &q, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_normal_offset(&good, &sl, &p, &N, NAN, &q, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_normal_offset(&good, &sl, &p, &bad, 1, &q, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_normal_offset(&good, &sl, &p, &N, -1, &q, NULL), SWARP_ERR_OUT_OF_RANGE);
    EXPECT(swarp_bias_normal_offset(&good, &sl, &p, &zero, 1, &q, NULL), SWARP_ERR_ZERO_VECTOR);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &N, NAN, 1, &o[0], NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &N, 0, NAN, &o[0], NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &bad, 0, 1, &o[0], NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &N, -1, 1, &o[0], NULL), SWARP_ERR_OUT_OF_RANGE);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &N, 0, -1, &o[0], NULL), SWARP_ERR_OUT_OF_RANGE);
    EXPECT(swarp_bias_slope_scaled(&good, &sl, &p, &zero, 0, 1, &o[0], NULL), SWARP_ERR_ZERO_VECTOR);
    EXPECT(swarp_bias_depth_per_world(&good, &sl, &bad, &o[0]), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_receiver_plane(&good, &bad, &ta, &tb, o), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_receiver_plane(&good, &p, &bad, &tb, o), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_receiver_plane(&good, &p, &ta, &bad, o), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_receiver_plane(&good, &p, &zero, &tb, o), SWARP_ERR_ZERO_VECTOR);
    EXPECT(swarp_bias_receiver_plane(&good, &p, &ta, &zero, o), SWARP_ERR_ZERO_VECTOR);
    /* edge-on receiver: both tangents map to the same texel direction */
    const swarp_vec3 ta2 = {2.0, 5.0, 0.0};
    EXPECT(swarp_bias_receiver_plane(&good, &p, &ta, &ta2, o), SWARP_ERR_DEGENERATE);
    /* a point light at p: no direction */
    swarp_light at_p = sl;
    at_p.type = SWARP_LIGHT_POINT;
    at_p.position = p;
    EXPECT(swarp_bias_to_light(&at_p, &p, &q), SWARP_ERR_ZERO_VECTOR);
    EXPECT(swarp_bias_kozlov(&good, &at_p, &p, 0.1, 1, &q, NULL), SWARP_ERR_ZERO_VECTOR);

    /* a perspective map: points behind its centre of projection (w <= 0) */
    swarp_bias_map persp = good;
    memset(persp.world_to_clip.m, 0, sizeof persp.world_to_clip.m);
    double* a = persp.world_to_clip.m;
    a[0] = 1.0;                 /* x */
    a[2 * 4 + 1] = 1.0;         /* y = z */
    a[1 * 4 + 2] = -1.0;        /* z = -y - 1 ... */
    a[3 * 4 + 2] = -1.0;
    a[1 * 4 + 3] = -1.0;        /* w = -y: in front for y < 0 */
    const swarp_vec3 behind = {0.0, 2.0, 0.0};
    EXPECT(swarp_bias_texel_size(&persp, &behind, &o[0], NULL, NULL), SWARP_ERR_BEHIND_PROJECTION);
    EXPECT(swarp_bias_depth_per_world(&persp, &sl, &behind, &o[0]), SWARP_ERR_BEHIND_PROJECTION);
    EXPECT(swarp_bias_receiver_plane(&persp, &behind, &ta, &tb, o), SWARP_ERR_BEHIND_PROJECTION);
    EXPECT(swarp_bias_slope_scaled(&persp, &sl, &behind, &N, 0, 1, &o[0], NULL), SWARP_ERR_BEHIND_PROJECTION);
    /* slope-scaled: the biased point crosses the centre of projection */
    const swarp_vec3 near_c = {0.0, -0.5, 0.0};
    EXPECT(swarp_bias_slope_scaled(&persp, &sl, &near_c, &N, 5.0, 0.0, &o[0], &o[1]), SWARP_ERR_BEHIND_PROJECTION);
    /* a singular map (rank 3) */
    swarp_bias_map sing = good;
    memset(sing.world_to_clip.m + 8, 0, 4 * sizeof(double)); /* column 2 (z) zero */
    EXPECT(swarp_bias_texel_size(&sing, &p, &o[0], NULL, NULL), SWARP_ERR_SINGULAR);
    EXPECT(swarp_bias_kozlov(&sing, &sl, &p, 0.1, 1.0, &q, NULL), SWARP_ERR_SINGULAR);
    /* huge coordinates: the biased point overflows */
    /* a texel of 2e4 world units times k = DBL_MAX: the offset overflows */
    swarp_bias_map coarse = good;
    coarse.res_s = coarse.res_t = 1e-3;
    const swarp_vec3 Nx = {1.0, 0.0, 0.0};
    EXPECT(swarp_bias_normal_offset(&coarse, &sl, &p, &Nx, DBL_MAX, &q, NULL), SWARP_ERR_NON_FINITE);
    EXPECT(swarp_bias_slope_scaled(&coarse, &sl, &p, &Nx, 0.0, DBL_MAX, &o[0], &o[1]), SWARP_ERR_NON_FINITE);
#undef EXPECT
#undef RESET
#undef UNTOUCHED
}
END_TEST

static swarp_camera camera(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = (swarp_vec3){0.0, 5.0, 0.0};
    c.dir = (swarp_vec3){0.0, 0.0, -1.0};
    c.up = (swarp_vec3){0.0, 1.0, 0.0};
    c.fovy = 1.0;
    c.aspect = 1.5;
    c.z_near = 0.5;
    c.z_far = 200.0;
    return c;
}

/* swarp_stabilize_directional: NONE focuses exactly on the body's light-space
 * box (its corners map to the clip square's edges), LEVELS snaps the centre
 * to whole texels and reports levels above range, and every bad argument
 * gives its status with the matrix and report untouched. */
START_TEST(stabilize_directional_edges) {
    const swarp_camera cam = camera();
    const swarp_vec3 ld = {0.0, -1.0, 0.0}; /* straight down: helper axis x */
    const swarp_vec3 body[4] = {{-3, 0, -1}, {4, 0, -1}, {-3, 0, -9}, {4, 2, -9}};
    swarp_mat4 m;
    swarp_stabilize_report rep;
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, NULL, &m, &rep), SWARP_OK);
    /* every body point inside [-1, 1]^2 and the extremes on the border */
    double xmin = 1e9, xmax = -1e9;
    for (int i = 0; i < 4; ++i) {
        swarp_vec4 h;
        ck_assert_int_eq(swarp_mat4_transform(&m, &body[i], &h), SWARP_OK);
        ck_assert(fabs(h.x) <= 1 + 1e-12 && fabs(h.y) <= 1 + 1e-12 && fabs(h.z) <= 1 + 1e-12);
        xmin = fmin(xmin, h.x);
        xmax = fmax(xmax, h.x);
    }
    ck_assert(fabs(xmin + 1) < 1e-12 && fabs(xmax - 1) < 1e-12);
    /* LEVELS with a tiny level_max_size: every level is above the range */
    o.mode = SWARP_STABILIZE_LEVELS;
    o.level_max_size = 1e-3;
    o.depth = SWARP_DEPTH_ZERO_TO_ONE;
    swarp_aabb scene = {{-50, -1, -50}, {50, 30, 50}};
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, &scene, 512, &o, &m, &rep),
                     SWARP_INFO_LEVEL_ABOVE_RANGE);
    ck_assert(rep.level_x > 64 && rep.level_y > 64);
    /* snapped: the centre offset is a whole number of texels */
    ck_assert(fabs(rep.offset_x / rep.texel_size_x - nearbyint(rep.offset_x / rep.texel_size_x)) < 1e-9);
    /* the scene box extends depth toward the light: its top (y = 30) maps to 0 */
    swarp_vec3 top = {0, 30, 0};
    swarp_vec4 h;
    ck_assert_int_eq(swarp_mat4_transform(&m, &top, &h), SWARP_OK);
    ck_assert(fabs(h.z) < 1e-12);
    /* a light along +z: the helper axis y; a flat body across the light */
    const swarp_vec3 lz = {0.0, 0.0, -1.0};
    const swarp_vec3 flat[3] = {{0, 0, -5}, {1, 0, -5}, {0, 1, -5}};
    o.mode = SWARP_STABILIZE_LEVELS;
    o.level_max_size = 0.0;
    o.depth = SWARP_DEPTH_DEFAULT;
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1, 10, &lz, flat, 3, NULL, 256, &o, &m, &rep), SWARP_OK);
    ck_assert(swarp_mat4_transform(&m, &flat[0], &h) == SWARP_OK && fabs(h.z) < 1e-12); /* centred in depth */
    /* SPHERE needs no body */
    o.mode = SWARP_STABILIZE_SPHERE;
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1, 10, &ld, NULL, 0, NULL, 256, &o, &m, &rep), SWARP_OK);

    /* bad arguments */
    swarp_mat4 out;
    swarp_stabilize_report r2;
#define BAD(call, want)                                                                      \
    do {                                                                                     \
        tu_fill(out.m, 16, SENTINEL);                                                        \
        tu_fill(&r2.sphere_center.x, 3, SENTINEL);                                           \
        swarp_status st_ = (call);                                                           \
        ck_assert_msg(st_ == (want), "%s: %s", #call, swarp_status_name(st_));              \
        ck_assert(tu_untouched(out.m, 16, SENTINEL) && tu_untouched(&r2.sphere_center.x, 3, SENTINEL)); \
    } while (0)
    BAD(swarp_stabilize_directional(NULL, 1, 10, &ld, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_directional(&cam, 1, 10, NULL, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, NULL, NULL, &r2), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, NULL, 0, NULL, 512, NULL, &out, &r2), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 0, NULL, 512, NULL, &out, &r2), SWARP_ERR_NULL_POINTER);
    swarp_stabilize_options b;
    memset(&b, 0, sizeof b);
    b._reserved[3] = 1;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_RESERVED_NONZERO);
    memset(&b, 0, sizeof b);
    b._reserved0 = 1;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_RESERVED_NONZERO);
    memset(&b, 0, sizeof b);
    b.mode = (swarp_stabilize_mode)9;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_UNKNOWN_ENUM);
    memset(&b, 0, sizeof b);
    b.depth = (swarp_depth_range)9;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_UNKNOWN_ENUM);
    memset(&b, 0, sizeof b);
    b.origin.z = NAN;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_NON_FINITE);
    memset(&b, 0, sizeof b);
    b.level_max_size = INFINITY;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_NON_FINITE);
    b.level_max_size = -1.0;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 512, &b, &out, &r2), SWARP_ERR_OUT_OF_RANGE);
    BAD(swarp_stabilize_directional(&cam, NAN, 10, &ld, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_NON_FINITE);
    BAD(swarp_stabilize_directional(&cam, 10, 1, &ld, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_NEAR_FAR);
    const swarp_vec3 nan_d = {NAN, 0, 0}, zero = {0, 0, 0};
    BAD(swarp_stabilize_directional(&cam, 1, 10, &nan_d, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_NON_FINITE);
    BAD(swarp_stabilize_directional(&cam, 1, 10, &zero, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_ZERO_VECTOR);
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, NULL, 1, NULL, &out, &r2), SWARP_ERR_RESOLUTION);
    const swarp_vec3 badbody[2] = {{0, 0, 0}, {INFINITY, 0, 0}};
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, badbody, 2, NULL, 512, NULL, &out, &r2), SWARP_ERR_NON_FINITE);
    swarp_aabb bs = scene;
    bs.max.y = NAN;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, &bs, 512, NULL, &out, &r2), SWARP_ERR_NON_FINITE);
    bs = scene;
    bs.min.x = 100;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, &bs, 512, NULL, &out, &r2), SWARP_ERR_OUT_OF_RANGE);
    bs = scene;
    bs.min.y = 100;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, &bs, 512, NULL, &out, &r2), SWARP_ERR_OUT_OF_RANGE);
    bs = scene;
    bs.min.z = 100;
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, body, 4, &bs, 512, NULL, &out, &r2), SWARP_ERR_OUT_OF_RANGE);
    /* NONE with a body that is a line in light space: no extent to fit */
    const swarp_vec3 line[2] = {{0, 0, -1}, {0, 3, -1}};
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, line, 2, NULL, 512, NULL, &out, &r2), SWARP_ERR_DEGENERATE);
    /* a body near DBL_MAX: the matrix overflows */
    const swarp_vec3 huge[2] = {{-1e308, 0, -1e308}, {1e308, 0, 1e308}};
    BAD(swarp_stabilize_directional(&cam, 1, 10, &ld, huge, 2, NULL, 512, NULL, &out, &r2), SWARP_ERR_OVERFLOW);
    /* camera errors come first */
    swarp_camera bc = cam;
    bc.fovy = 4.0;
    BAD(swarp_stabilize_directional(&bc, 1, 10, &ld, body, 4, NULL, 512, NULL, &out, &r2), SWARP_ERR_FOV);
#undef BAD
}
END_TEST

/* swarp_stabilize_snap_matrix and swarp_stabilize_sphere argument checks. */
START_TEST(stabilize_snap_and_sphere_edges) {
    swarp_mat4 m, out;
    memset(&m, 0, sizeof m);
    m.m[0] = 0.1;
    m.m[5] = 0.1;
    m.m[10] = -0.01;
    m.m[15] = 1.0;
    m.m[12] = 0.123456;
    const swarp_vec3 origin = {0, 0, 0};
    /* the origin lands on a whole texel afterwards */
    ck_assert_int_eq(swarp_stabilize_snap_matrix(&m, 1024, 1024, &origin, &out), SWARP_OK);
    double s = (out.m[12] + 1.0) * 0.5 * 1024;
    ck_assert(fabs(s - nearbyint(s)) < 1e-9);
    ck_assert(fabs(out.m[12] - m.m[12]) <= 1.0 / 1024 + 1e-15);
#define BAD(call, want)                                                         \
    do {                                                                        \
        tu_fill(out.m, 16, SENTINEL);                                           \
        ck_assert_int_eq((call), (want));                                      \
        ck_assert(tu_untouched(out.m, 16, SENTINEL));                           \
    } while (0)
    BAD(swarp_stabilize_snap_matrix(NULL, 1024, 1024, &origin, &out), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_snap_matrix(&m, 1024, 1024, NULL, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_stabilize_snap_matrix(&m, 1024, 1024, &origin, NULL), SWARP_ERR_NULL_POINTER);
    const swarp_vec3 nan_o = {NAN, 0, 0};
    BAD(swarp_stabilize_snap_matrix(&m, 1024, 1024, &nan_o, &out), SWARP_ERR_NON_FINITE);
    BAD(swarp_stabilize_snap_matrix(&m, NAN, 1024, &origin, &out), SWARP_ERR_RESOLUTION);
    BAD(swarp_stabilize_snap_matrix(&m, 1024, INFINITY, &origin, &out), SWARP_ERR_RESOLUTION);
    BAD(swarp_stabilize_snap_matrix(&m, 0, 1024, &origin, &out), SWARP_ERR_RESOLUTION);
    BAD(swarp_stabilize_snap_matrix(&m, 1024, -2, &origin, &out), SWARP_ERR_RESOLUTION);
    swarp_mat4 w = m;
    w.m[7] = 0.5;
    BAD(swarp_stabilize_snap_matrix(&w, 1024, 1024, &origin, &out), SWARP_ERR_STABILIZE_WARPED);
    w = m;
    w.m[3] = 0.5;
    BAD(swarp_stabilize_snap_matrix(&w, 1024, 1024, &origin, &out), SWARP_ERR_STABILIZE_WARPED);
    w = m;
    w.m[11] = 0.5;
    BAD(swarp_stabilize_snap_matrix(&w, 1024, 1024, &origin, &out), SWARP_ERR_STABILIZE_WARPED);
    w = m;
    w.m[15] = 0.0;
    BAD(swarp_stabilize_snap_matrix(&w, 1024, 1024, &origin, &out), SWARP_ERR_SINGULAR);
    /* a snap step that overflows the matrix */
    w = m;
    w.m[15] = 1e308;
    w.m[12] = 1e308;
    BAD(swarp_stabilize_snap_matrix(&w, 1e-300, 1024, &origin, &out), SWARP_ERR_NON_FINITE);
#undef BAD
    /* the sphere: minimal, and the centroid one is never smaller */
    const swarp_camera cam = camera();
    swarp_vec3 c = {SENTINEL, SENTINEL, SENTINEL};
    double r = SENTINEL, rc = SENTINEL;
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, 1, 10, &c, &r, NULL), SWARP_OK);
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, 1, 10, &c, &r, &rc), SWARP_OK);
    ck_assert(rc >= r);
    c = (swarp_vec3){SENTINEL, SENTINEL, SENTINEL};
    r = SENTINEL;
    ck_assert_int_eq(swarp_stabilize_sphere(NULL, 1, 10, &c, &r, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, 1, 10, NULL, &r, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, 1, 10, &c, NULL, NULL), SWARP_ERR_NULL_POINTER);
    swarp_camera wide = cam; /* k = tan(1.25) sqrt(1 + aspect^2) > 5: f k overflows */
    wide.fovy = 2.5;
    /* finite inputs, unrepresentable sphere: the documented OVERFLOW */
    ck_assert_int_eq(swarp_stabilize_sphere(&wide, 1, DBL_MAX, &c, &r, NULL), SWARP_ERR_OVERFLOW);
    ck_assert(tu_untouched(&c.x, 3, SENTINEL) && tu_untouched(&r, 1, SENTINEL));
    /* light view: zero and NaN directions, and a vertical light */
    swarp_mat4 v;
    tu_fill(v.m, 16, SENTINEL);
    const swarp_vec3 zero = {0, 0, 0}, nan_d = {0, NAN, 0}, down = {0, -1, 0};
    ck_assert_int_eq(swarp_stabilize_light_view(&zero, &v), SWARP_ERR_ZERO_VECTOR);
    ck_assert_int_eq(swarp_stabilize_light_view(&nan_d, &v), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_stabilize_light_view(NULL, &v), SWARP_ERR_NULL_POINTER);
    ck_assert(tu_untouched(v.m, 16, SENTINEL));
    ck_assert_int_eq(swarp_stabilize_light_view(&down, &v), SWARP_OK);
    /* orthonormal rows */
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double d = v.m[i] * v.m[j] + v.m[4 + i] * v.m[4 + j] + v.m[8 + i] * v.m[8 + j];
            ck_assert(fabs(d - (i == j)) < 1e-15);
        }
}
END_TEST

/* Cascade selection, blending and the error curve: values against direct
 * evaluation, every bad argument with its status and outputs untouched. */
START_TEST(cascade_select_blend_curve_edges) {
    const double splits[5] = {1.0, 4.0, 16.0, 64.0, 256.0};
    uint32_t idx = 99;
    double w = SENTINEL;
    /* depth selection: brute force */
    uint64_t s = 0xCA5Cull;
    for (int n = 0; n < 1000; ++n) {
        double z = tu_uniform(&s, 0.0, 300.0);
        uint32_t want = 0;
        while (want + 1 < 4 && z >= splits[want + 1]) ++want;
        swarp_status st = swarp_cascade_select_depth(splits, 4, z, &idx);
        ck_assert_uint_eq(idx, want);
        ck_assert_int_eq(st, (z < 1.0 || z > 256.0) ? SWARP_INFO_OUTSIDE_SPLITS : SWARP_OK);
        /* blend: weight 1 outside the last 25 % of the split, then linear to 0 */
        st = swarp_cascade_blend(splits, 4, z, 0.25, &idx, &w);
        ck_assert_uint_eq(idx, want);
        double want_w = 1.0;
        if (want < 3) {
            double border = splits[want + 1], width = 0.25 * (border - splits[want]);
            want_w = fmin(1.0, fmax(0.0, (border - z) / width));
        }
        ck_assert(fabs(w - want_w) < 1e-12);
    }
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 10.0, 0.0, &idx, &w), SWARP_OK);
    ck_assert(w == 1.0);
    const double nan_s[3] = {1, NAN, 3}, flat[3] = {1, 2, 2};
    idx = 99;
    w = SENTINEL;
    ck_assert_int_eq(swarp_cascade_select_depth(splits, 0, 2.0, &idx), SWARP_ERR_SPLIT_COUNT);
    ck_assert_int_eq(swarp_cascade_select_depth(splits, SWARP_SPLIT_MAX_COUNT + 1, 2.0, &idx), SWARP_ERR_SPLIT_COUNT);
    ck_assert_int_eq(swarp_cascade_select_depth(NULL, 2, 2.0, &idx), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_select_depth(nan_s, 2, 2.0, &idx), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_select_depth(flat, 2, 2.0, &idx), SWARP_ERR_NOT_INCREASING);
    ck_assert_int_eq(swarp_cascade_select_depth(splits, 4, NAN, &idx), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_select_depth(splits, 4, 2.0, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 2.0, 1.0, &idx, &w), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 2.0, -0.1, &idx, &w), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 2.0, NAN, &idx, &w), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, INFINITY, 0.1, &idx, &w), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_blend(flat, 2, 2.0, 0.1, &idx, &w), SWARP_ERR_NOT_INCREASING);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 2.0, 0.1, NULL, &w), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 2.0, 0.1, &idx, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(idx == 99 && tu_untouched(&w, 1, SENTINEL));

    /* view depth: the distance along the normalised view direction */
    swarp_camera cam = camera();
    cam.dir = (swarp_vec3){0.0, 0.0, -3.0};
    const swarp_vec3 p = {7.0, 2.0, -11.0};
    double d = SENTINEL;
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &d), SWARP_OK);
    ck_assert(d == 11.0);
    d = SENTINEL;
    swarp_camera bad = cam;
    bad.dir = (swarp_vec3){0, 0, 0};
    ck_assert_int_eq(swarp_cascade_view_depth(&bad, &p, &d), SWARP_ERR_ZERO_VECTOR);
    bad = cam;
    bad.eye.x = NAN;
    ck_assert_int_eq(swarp_cascade_view_depth(&bad, &p, &d), SWARP_ERR_NON_FINITE);
    const swarp_vec3 nan_p = {0, INFINITY, 0}, huge = {0, 0, -DBL_MAX};
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &nan_p, &d), SWARP_ERR_NON_FINITE);
    bad = cam;
    bad.eye.z = DBL_MAX; /* the depth, 2 DBL_MAX, is not representable (documented OVERFLOW) */
    ck_assert_int_eq(swarp_cascade_view_depth(&bad, &huge, &d), SWARP_ERR_OVERFLOW);
    ck_assert_int_eq(swarp_cascade_view_depth(NULL, &p, &d), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, NULL, &d), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(tu_untouched(&d, 1, SENTINEL));

    /* select_best: the finest map covering p; none covering -> the fallback */
    swarp_bias_map maps[3] = {ortho_map(SWARP_DEPTH_NEG_ONE_TO_ONE), ortho_map(SWARP_DEPTH_ZERO_TO_ONE),
                              ortho_map(SWARP_DEPTH_NEG_ONE_TO_ONE)};
    maps[1].res_s = maps[1].res_t = 4096.0; /* finer */
    maps[2].res_s = maps[2].res_t = 8192.0;
    maps[2].world_to_clip.m[12] = 50.0; /* moved away: does not cover */
    const swarp_vec3 q = {1.5, -3.0, 2.0}, outside = {500.0, 0.0, 0.0};
    double L = SENTINEL;
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &q, 0, &idx, &L), SWARP_OK);
    ck_assert_uint_eq(idx, 1);
    ck_assert(tu_rel(L, W / 4096.0) < 1e-12);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &q, 0, &idx, NULL), SWARP_OK);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &outside, 2, &idx, &L), SWARP_INFO_OUTSIDE_SPLITS);
    ck_assert(idx == 2 && L == 0.0);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &outside, 2, &idx, NULL), SWARP_INFO_OUTSIDE_SPLITS);
    idx = 99;
    L = SENTINEL;
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &q, 3, &idx, &L), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 0, &q, 0, &idx, &L), SWARP_ERR_SPLIT_COUNT);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &nan_p, 0, &idx, &L), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_select_best(NULL, 3, &q, 0, &idx, &L), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 3, &q, 0, NULL, &L), SWARP_ERR_NULL_POINTER);
    swarp_bias_map bm[2] = {maps[0], maps[2]};
    bm[1].res_s = -1.0; /* a bad map that does not cover p is still refused */
    ck_assert_int_eq(swarp_cascade_select_best(bm, 2, &q, 0, &idx, &L), SWARP_ERR_RESOLUTION);
    bm[0].res_t = 0.0; /* a bad map that covers p */
    ck_assert_int_eq(swarp_cascade_select_best(bm, 1, &q, 0, &idx, &L), SWARP_ERR_RESOLUTION);
    ck_assert(idx == 99 && tu_untouched(&L, 1, SENTINEL));

    /* error curve: arguments; values equal swarp_error_split_curve's */
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = 1.0;
    cfg.z_far = 256.0;
    cfg.theta = 0.8;
    cfg.res_ix = cfg.res_iy = 1024.0;
    cfg.res_s = cfg.res_t = 2048.0;
    const double np[4] = {2.0, 8.0, INFINITY, 100.0};
    double z[16], mx[16], mz[16];
    size_t count = 0;
    ck_assert(!swarp_status_is_error(swarp_cascade_error_curve(&cfg, splits, np, 4, 4, z, mx, mz, 16, &count)));
    ck_assert_uint_eq(count, 16);
    double mx1, mz1;
    for (int i = 0; i < 16; ++i) {
        ck_assert(!swarp_status_is_error(swarp_error_split_curve(&cfg, splits, np, 4, &z[i], 1, &mx1, &mz1)));
        ck_assert(mx1 == mx[i] && mz1 == mz[i]);
    }
    ck_assert(!swarp_status_is_error(swarp_cascade_error_curve(&cfg, splits, np, 4, 4, z, NULL, NULL, 16, &count)));
    tu_fill(z, 16, SENTINEL);
    count = 7;
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, splits, np, 4, 4, z, mx, mz, 15, &count), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(count, 16);
    count = 7;
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, splits, np, 4, 1, z, mx, mz, 16, &count), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_error_curve(NULL, splits, np, 4, 4, z, mx, mz, 16, &count), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, splits, NULL, 4, 4, z, mx, mz, 16, &count), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, splits, np, 4, 4, NULL, mx, mz, 16, &count), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, splits, np, 4, 4, z, mx, mz, 16, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, flat, np, 2, 4, z, mx, mz, 16, &count), SWARP_ERR_NOT_INCREASING);
    swarp_error_config bc = cfg;
    bc.res_s = -1.0; /* the pre-flight call refuses it before any output */
    ck_assert(swarp_status_is_error(swarp_cascade_error_curve(&bc, splits, np, 4, 4, z, mx, mz, 16, &count)));
    ck_assert(count == 7 && tu_untouched(z, 16, SENTINEL));
}
END_TEST

/* The bounding sphere where k^2 = tan^2(fovy/2)(1 + aspect^2) overflows
 * (aspect 1e167) but the sphere is representable (so no NON_FINITE), and n, f
 * one ulp apart with a vanishing fovy (a rounded centre can land on f,
 * radius 0; the true radius is (f - n)/2). */
START_TEST(stabilize_sphere_extreme_aspect_and_thin_range) {
    swarp_camera cam = camera();
    cam.aspect = 1e167;
    swarp_vec3 c;
    double r = -1, rc = -1;
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, 4.0, 3e7, &c, &r, &rc), SWARP_OK);
    long double t = tanl(cam.fovy / 2.0L), ref = 3e7L * t * sqrtl(1.0L + 1e334L);
    ck_assert(fabsl(r - ref) <= 1e-12L * ref);
    ck_assert(rc >= r);
    cam = camera();
    cam.fovy = DBL_TRUE_MIN;
    double n = 0.36532155520849535, f = nextafter(n, 1.0);
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, n, f, &c, &r, NULL), SWARP_OK);
    ck_assert(r == 0.5 * (f - n));
}
END_TEST

/* Atlas kernel scale r_l l_sc 2/(max - min) without spurious overflow: a
 * width -DBL_MAX..DBL_MAX (difference overflows) and a subnormal width with a
 * small r_l (2/width overflows) are representable (were NON_FINITE); a truly
 * unrepresentable scale is the documented SWARP_ERR_OVERFLOW. */
START_TEST(atlas_kernel_scale_extreme_widths) {
    double s[2] = {-1, -1};
    ck_assert_int_eq(swarp_atlas_kernel_scale(1.0, 1, -DBL_MAX, DBL_MAX, 0.0, 2.0, s), SWARP_OK);
    ck_assert(s[0] == 1.0 / DBL_MAX && s[1] == 1.0);
    ck_assert_int_eq(swarp_atlas_kernel_scale(1e-300, 1, 0.0, 1e-320, 0.0, 2.0, s), SWARP_OK);
    long double ref = 1e-300L * 2.0L / (long double)1e-320;
    ck_assert(fabsl(s[0] - ref) <= 1e-15L * ref && s[1] == 1e-300);
    s[0] = s[1] = 7.25;
    ck_assert_int_eq(swarp_atlas_kernel_scale(10.0, 1, 0.0, DBL_TRUE_MIN, 0.0, 2.0, s), SWARP_ERR_OVERFLOW);
    ck_assert(s[0] == 7.25 && s[1] == 7.25);
}
END_TEST

/* View depth with a direction whose length overflows (components near
 * DBL_MAX): any non-zero finite dir is valid (no SWARP_ERR_ZERO_VECTOR). */
START_TEST(cascade_view_depth_huge_dir) {
    swarp_camera cam = camera();
    cam.eye = (swarp_vec3){0, 0, 0};
    cam.dir = (swarp_vec3){-DBL_MAX, DBL_MAX, -1.0};
    swarp_vec3 p = {-3.0, 4.0, 100.0};
    double z = -7.0;
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &z), SWARP_OK);
    /* independent: unit dir (-1, 1, -1/DBL_MAX)/sqrt(2), depth (3 + 4)/sqrt(2) */
    ck_assert(fabs(z - 7.0 / sqrt(2.0)) <= 1e-14);
}
END_TEST

/* Error curve samples at subnormal depths: a + (b - a) j/(s - 1) rounds up
 * to b (here a = m, b = 3m, j = 3 of 5: m + 1.5m -> 3m) — the sample must
 * stay in [C_i, C_{i+1}) (not exactly C_1, which is outside split 0). */
START_TEST(cascade_error_curve_subnormal_splits) {
    const double m = DBL_TRUE_MIN;
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = m;
    cfg.z_far = 5 * m;
    cfg.theta = 0.8;
    cfg.res_ix = cfg.res_iy = 1024.0;
    cfg.res_s = cfg.res_t = 2048.0;
    const double splits[3] = {m, 3 * m, 5 * m};
    const double np[2] = {m, 3 * m};
    double z[10];
    size_t count = 0;
    ck_assert(!swarp_status_is_error(swarp_cascade_error_curve(&cfg, splits, np, 2, 5, z, NULL, NULL, 10, &count)));
    ck_assert_uint_eq(count, 10);
    for (size_t g = 0; g < 10; ++g) {
        const size_t i = g / 5;
        ck_assert(z[g] >= splits[i] && (i == 1 ? z[g] <= splits[2] : z[g] < splits[1]));
        if (g) ck_assert(z[g] >= z[g - 1]);
    }
}
END_TEST

/* A tiny split (1e-68) far from the origin along the light (1e6): the flat
 * depth range's one-texel padding is absorbed by the ulp of t (1e-10), so
 * 2/dt would overflow; the range is padded by an ulp at least.  A truly
 * unrepresentable matrix is SWARP_ERR_OVERFLOW, outputs untouched. */
START_TEST(stabilize_directional_tiny_split_far_origin) {
    swarp_camera cam = camera();
    cam.eye = (swarp_vec3){0, 0, 0};
    cam.dir = (swarp_vec3){0, 0, -1};
    cam.up = (swarp_vec3){0, 1, 0};
    const swarp_vec3 light = {0, -1, 0};
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    o.mode = SWARP_STABILIZE_SPHERE;
    o.origin = (swarp_vec3){0, 1e6, 0};
    swarp_mat4 m;
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1e-70, 1e-68, &light, NULL, 0, NULL, 1024, &o, &m, NULL),
                     SWARP_OK);
    for (int i = 0; i < 16; ++i) ck_assert(isfinite(m.m[i]));
    /* the split's centre (0, 0, ~-5e-69), relative to the origin, maps inside */
    const double q[3] = {0, -1e6, -5e-69};
    for (int r = 0; r < 3; ++r) {
        double h = m.m[r] * q[0] + m.m[4 + r] * q[1] + m.m[8 + r] * q[2] + m.m[12 + r];
        ck_assert(fabs(h) <= 1.0 + 1e-9);
    }
    /* eye near DBL_MAX with a tiny split: 1/(map size) times the offset is beyond DBL_MAX */
    cam.eye = (swarp_vec3){DBL_MAX / 2, 0, 0};
    o.origin = (swarp_vec3){-DBL_MAX / 2, 0, 0};
    const swarp_vec3 lx = {1, -1, 0};
    tu_fill(m.m, 16, SENTINEL);
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1e-70, 1e-68, &lx, NULL, 0, NULL, 1024, &o, &m, NULL),
                     SWARP_ERR_OVERFLOW);
    ck_assert(tu_untouched(m.m, 16, SENTINEL));
}
END_TEST


/* ---- the bias and stabilisation at the ends of the double range ---- */
static swarp_bias_map bias_map_of(const double m[16], double rs, double rt, int depth) {
    swarp_bias_map b;
    memset(&b, 0, sizeof b);
    memcpy(b.world_to_clip.m, m, sizeof b.world_to_clip.m);
    b.res_s = rs, b.res_t = rt, b.depth = (swarp_depth_range)depth;
    return b;
}

/* A point 7e37 from the map's origin; the tangents' texel images are
 * exactly parallel (the long double determinant is 0), but the double one
 * can come out above the 1e-12 threshold, a gradient of noise.  The
 * determinant is compared with its rounding bound too: edge-on. */
START_TEST(receiver_plane_edge_on_far_point) {
    const double m[16] = {0x1.ea5fc42df7421p+0, -0x1.30f0d6b387b16p-9, 0x1.e2838fd436291p-2, 0x1.e283840154e3cp-2,
                          -0x1.8f3544dad65fcp+1, 0x1.1ca1cbd83d95fp-10, 0x1.b8d16f3188637p-1, 0x1.b8d164643778dp-1,
                          0x1.29cbb154b003cp+3, 0x1.b9d9c7a64b8ccp-11, 0x1.884ca68e86239p-3, 0x1.884c9cf1929bp-3,
                          -0x1.d3a3330868dc8p+20, 0x1.22cdafb56966ep+11, -0x1.cc2881eaafb65p+18, -0x1.cc2611bdda124p+18};
    const swarp_bias_map b = bias_map_of(m, 0x1.575c6bb53e90fp+12, 0x1.6f1e98a049d2bp+3, 1);
    const swarp_vec3 p = {0x1.011ba7f58c4fap+23, 0x1.9cdce57580045p+125, -0x1.468dad2caffd8p+21};
    const swarp_vec3 ta = {0x1.d7c530a229fecp-2, -0x1.c1ef0782bb1c1p+818, -0x1.061824fecef64p-1};
    const swarp_vec3 tb = {0x1.3e91e27f02dap-1, 0x1.921fb54442d18p+1, -0x1.d9a46fc44a634p-2};
    double g[2] = {SENTINEL, SENTINEL};
    ck_assert_int_eq(swarp_bias_receiver_plane(&b, &p, &ta, &tb, g), SWARP_ERR_DEGENERATE);
    ck_assert(g[0] == SENTINEL && g[1] == SENTINEL);
}
END_TEST

/* res = 2^-1022 makes the texel derivatives subnormal, where the
 * determinant would lose most of its bits (dd/ds 13% off).  The gradient
 * per texel is exactly 2^1022 times the one at res = 1 (a power-of-two
 * scaling is exact): the reference. */
START_TEST(receiver_plane_subnormal_resolution) {
    const double m[16] = {0x1.5f58af0757c57p-14, 0x1.5cf932bb0245ep-11, 0x1.1de838d1fc287p-24, 0,
                          0x1.a21a5a0a7b1e5p-15, -0x1.c7c2d1c0561f6p-11, -0x1.07fb6c2f9e4cbp-21, 0,
                          0x1.76b35eb81ed38p-16, -0x1.23c917a4ae0c7p-11, 0x1.c71362ed3d6d3p-21, 0,
                          -0x1.3aa3a2efeb74p+6, 0x1.b41c5cb19d1c5p+6, -0x1.c8e6826cdeda3p-1, 1};
    const swarp_vec3 p = {0x1.69031d62d506cp+19, -0x1.c2f56c9859d14p+18, 0x1.b75ec456db31cp+20};
    const swarp_vec3 ta = {0x1.fffffffffffffp-1, 0x1.697773b0003aap-1, 0x1.7a455de9b345p-3};
    const swarp_vec3 tb = {-0x1p+0, 0x1.7e43c8800759cp+996, 0x1.52be0472fb6cp-6};
    const swarp_bias_map tiny = bias_map_of(m, 0x1p-1022, 0x1p-1022, 2), one = bias_map_of(m, 1, 1, 2);
    double g[2], g1[2];
    ck_assert_int_eq(swarp_bias_receiver_plane(&one, &p, &ta, &tb, g1), SWARP_OK);
    ck_assert_int_eq(swarp_bias_receiver_plane(&tiny, &p, &ta, &tb, g), SWARP_OK);
    ck_assert(tu_rel(g[0], ldexp(g1[0], 1022)) < 1e-12 && tu_rel(g[1], ldexp(g1[1], 1022)) < 1e-12);
}
END_TEST

/* A point at y = 1e300 seen along the light: the derivative is ~1e-600 (0
 * in double), but dz/w - z dw/w^2 loses its second term to 1/w^2
 * underflowing and gives 1e-300.  Bound: eps |dh| / |w| ~ 1e-316. */
START_TEST(depth_per_world_far_point) {
    const double m[16] = {0x1.30309f5938d21p-7, -0x1.0d7dbca875d17p-1, 0x1.ea1546fbb8b03p-1, 0x1.e227c7282ec98p-1,
                          -0x1.8cca2fe49c1bap-10, 0x1.35bd4572da0bcp+3, 0x1.3dc80c9bf35aep-4, 0x1.38a412f59a4c4p-4,
                          0x1.af5c080267047p-6, 0x1.7bf001579932bp-1, -0x1.5508a5057da9bp-2, -0x1.4f8460e20cce4p-2,
                          -0x1.9b6216bc4b563p+14, -0x1.6a4df9559ccb8p+19, 0x1.453114c629df5p+18, 0x1.3feec074e392p+18};
    const swarp_bias_map b = bias_map_of(m, 0x1.fffffff768fa1p+10, 1, 2);
    const swarp_vec3 p = {-0x1.73c9c780560fp+7, 0x1.7e43c8800759cp+996, 0x1.e7e831d97529ep+19};
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = (swarp_vec3){0x1.7feb823c5039p-1, -0x1.265a2f6f1167cp+731, -0x1.342a37c5bcff4p-1};
    double k = SENTINEL;
    ck_assert_int_eq(swarp_bias_depth_per_world(&b, &l, &p, &k), SWARP_OK);
    ck_assert_msg(fabs(k) < 1e-310, "depth per world %g", k);
}
END_TEST

/* n, f the two smallest subnormals and a narrow fovy: the exact radius
 * (~(f - n)/2) is below half the smallest subnormal and would round to 0, a
 * point instead of a sphere around the frustum.  It is rounded up to
 * DBL_TRUE_MIN, so the sphere still holds the frustum. */
START_TEST(stabilize_sphere_subnormal_range) {
    swarp_camera cam = camera();
    cam.fovy = 1.000001e-06;
    cam.aspect = 1.2183229238794722;
    swarp_vec3 c;
    double r = -1, rc = -1;
    ck_assert_int_eq(swarp_stabilize_sphere(&cam, DBL_TRUE_MIN, 2 * DBL_TRUE_MIN, &c, &r, &rc), SWARP_OK);
    ck_assert(r > 0 && rc >= r);
}
END_TEST

/* p - eye overflows for coordinates near DBL_MAX, yet the arguments are
 * finite (no SWARP_ERR_NON_FINITE).  A representable depth is computed (at
 * a quarter scale, exact); one beyond DBL_MAX is SWARP_ERR_OVERFLOW, the
 * output untouched. */
START_TEST(cascade_view_depth_opposite_ends) {
    swarp_camera cam = {{-DBL_MAX, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0, 1.0, 1, 100, {0, 0, 0, 0}};
    swarp_vec3 p = {DBL_MAX, 3, 0};
    double z = -1;
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &z), SWARP_OK);
    ck_assert(z == 3.0);
    cam.dir = (swarp_vec3){1, 0, 0};
    cam.up = (swarp_vec3){0, 1, 0};
    z = -1;
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &z), SWARP_ERR_OVERFLOW);
    ck_assert(z == -1);
    /* the sum overflows, the depth does not: 0.9 DBL_MAX (1 + 1 - 1)/sqrt(3) */
    cam.eye = (swarp_vec3){0, 0, 0};
    cam.dir = (swarp_vec3){1, 1, -1};
    p = (swarp_vec3){0.9 * DBL_MAX, 0.9 * DBL_MAX, 0.9 * DBL_MAX};
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &z), SWARP_OK);
    ck_assert(fabs(z - 0.9 * DBL_MAX / sqrt(3.0)) <= 1e-15 * DBL_MAX);
}
END_TEST

/* A normal facing the light exactly (N = -direction) has 1 - N.L = 0, but
 * 1 - |N|^2 can leave an ulp whose sign the rounding mode chooses, times
 * k L_texel with k = 9.6e94: p' would move by 1e79 under FE_UPWARD.
 * p' = p in every mode. */
START_TEST(bias_normal_offset_facing_light_rounding_mode) {
    swarp_bias_map map;
    memset(&map, 0, sizeof map);
    static const double M[16] = {-1.6095275700642623e-06, -0.17352574943382518, 0.20775622705305702, 0,
                                 -0.00010156498946480948, 0.15646124349580809, 0.17362645222110343, 0,
                                 0.00017768440147471388, 0.087861905377747074, 0.10112738100142211, 0,
                                 -0.0050369276228172631, 12.278037160024038, 3.3475387333246336, 1};
    memcpy(map.world_to_clip.m, M, sizeof M);
    map.res_s = 2047.999999997952, map.res_t = 6719.8139204190184, map.depth = SWARP_DEPTH_ZERO_TO_ONE;
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){0.5181262980665744, -0.63590557704866546, -0.37293091554550828};
    const swarp_vec3 p = {63.06489264887616, 2491.254305873008, -4437.8664369381713};
    const swarp_vec3 n = {-light.direction.x, -light.direction.y, -light.direction.z};
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int m = 0; m < 4; ++m) {
        swarp_vec3 q;
        double amount = -1;
        fesetround(modes[m]);
        swarp_status st = swarp_bias_normal_offset(&map, &light, &p, &n, 9.5607029686530707e+94, &q, &amount);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_msg(amount == 0 && q.x == p.x && q.y == p.y && q.z == p.z, "mode %d: amount %g, p' (%g %g %g)", m,
                      amount, q.x, q.y, q.z);
    }
}
END_TEST

/* The depth bias of a tiny world bias (c = s = 1e-12) on an ortho map as
 * d(p) - d(p + t L), two window depths of order 1 rounded to eps, is a
 * difference of 6.4e-14 that reads 8.2e-14, 9.6e-14 or 1.1e-13 with the
 * caller's rounding mode.  The secant form t (g_z - z g_w)/(h_w + t g_w) keeps its factors'
 * relative accuracy: the same to 1e-12 in every mode, and -t g_z / 2 here
 * (ortho, depth [-1, 1] -> window [0, 1]). */
START_TEST(bias_slope_scaled_tiny_depth_bias_rounding_mode) {
    swarp_bias_map map;
    memset(&map, 0, sizeof map);
    static const double M[16] = {-0.26339782772477321, 7.8109187900805884e-05, -0.12499191710449216, 0,
                                 0.28108651663893419,  -4.7057537890308446e-05, -0.1867450211314452, 0,
                                 0.82354795925072888,  4.1043183272972156e-05, 0.023761710318398247, 0,
                                 6.2545625441574257,   -0.0010876431680039475, -4.7977114591666332, 1};
    memcpy(map.world_to_clip.m, M, sizeof M);
    map.res_s = map.res_t = 85.3328, map.depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){0.6, 0.0, -0.8}; /* L = (-0.6, 0, 0.8) */
    const swarp_vec3 p = {1694.1541463288179, -1051.4334426114694, 892.33162665590817};
    const swarp_vec3 n = {-light.direction.x, -light.direction.y, -light.direction.z}; /* tan 0 */
    const double gz = -0.6 * M[2] + 0.8 * M[10], want = -0.5 * 1e-12 * gz;
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int m = 0; m < 4; ++m) {
        double wb = -1, db = -1;
        fesetround(modes[m]);
        swarp_status st = swarp_bias_slope_scaled(&map, &light, &p, &n, 1e-12, 1e-12, &wb, &db);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_msg(fabs(db - want) <= 1e-12 * fabs(want), "mode %d: depth bias %.17g, want %.17g", m, db, want);
    }
}
END_TEST

/* The texel size of a far point (|p| ~ 3e8, L_texel ~ 1e5) of a
 * perspective map as |M^-1 (ndc + step) - p| is a difference of two points
 * of magnitude |p| that the far point's tiny homogeneous w resolves
 * coarsely: 93118.54 in the default mode, 93121.43 under FE_TOWARDZERO.
 * The step form
 * h_w d (b_xyz - p b_w) / (1 + h_w d b_w) (b a column of M^-1) never forms
 * p': within 1e-7 in every mode (2e-9 seen: the inverse's own rounding,
 * the map's condition number is ~2e9). */
START_TEST(bias_texel_size_far_point_rounding_mode) {
    swarp_bias_map map;
    memset(&map, 0, sizeof map);
    static const double M[16] = {-3.9283760701198864, -0.0090772364843252282, -0.4777251719134416, -0.47772466130453467,
                                 -0.81237268617103031, -0.0076317624645193104, 0.8437615463233189, 0.84376064448228938,
                                 4.8694000063363854,  -0.0085962611218823575, -0.24463697745390828, -0.24463671597758885,
                                 -8.9217452228980463, 0.2621702356128402,     -65.324964730467897, -47.402512232774704};
    memcpy(map.world_to_clip.m, M, sizeof M);
    map.res_s = 5101.79, map.res_t = 8192, map.depth = SWARP_DEPTH_DEFAULT;
    const swarp_vec3 p = {-281455272.17089683, -229404308.46017605, -264436279.94170618};
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    double L0[3] = {0};
    for (int m = 0; m < 4; ++m) {
        double L[3] = {-1, -1, -1};
        fesetround(modes[m]);
        swarp_status st = swarp_bias_texel_size(&map, &p, &L[0], &L[1], &L[2]);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        if (m == 0) memcpy(L0, L, sizeof L);
        for (int i = 0; i < 3; ++i)
            ck_assert_msg(fabs(L[i] - L0[i]) <= 1e-7 * L0[0], "mode %d: output %d = %.17g, default %.17g", m, i, L[i], L0[i]);
    }
}
END_TEST

/* A one-point body (flat across the light) at a 1e6 offset: the depth
 * row's zb = -(t_max + t_min)/dt with dt = (t + texel) - (t - texel) would
 * carry ulp(t)/texel ~ 1e-8 of relative error, its sign set by the caller's
 * rounding mode; the depth row is the same to 1e-13 in every mode. */
START_TEST(stabilize_directional_flat_body_rounding_mode) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){999996.0, 7.26264, 999990.0};
    cam.dir = (swarp_vec3){-0.788473, -0.189227, -1.0};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 1.66128;
    cam.aspect = 2.90524;
    const swarp_vec3 ld = {-0.612436, -0.14698, -0.776736};
    const swarp_vec3 body[1] = {{999000.123, 3.7, 998000.456}};
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    o.mode = SWARP_STABILIZE_LEVELS;
    o.levels = 159;
    o.origin = (swarp_vec3){-73917.4, 0, 0};
    o.level_max_size = 4639.08;
    const double n = 1.2384527511974723, f = 4294.3381544657286;
    swarp_mat4 m0, m;
    swarp_status st0 = swarp_stabilize_directional(&cam, n, f, &ld, body, 1, NULL, 6357, &o, &m0, NULL);
    ck_assert(!swarp_status_is_error(st0));
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int k = 0; k < 3; ++k) {
        fesetround(modes[k]);
        swarp_status st = swarp_stabilize_directional(&cam, n, f, &ld, body, 1, NULL, 6357, &o, &m, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, st0);
        for (int i = 0; i < 16; ++i) ck_assert_double_eq_tol(m.m[i], m0.m[i], 1e-13 * fmax(1.0, fabs(m0.m[14])));
    }
}
END_TEST

/* One body point (flat across the light) of a 1e-5 split, 1e6 from the
 * origin: depth is one texel either side of t, and the texel (8.5e-11)
 * lies between half an ulp and an ulp of t.  Whether t -+ texel rounds
 * away from t (2 texels or 2 ulps of depth extent) is the rounding mode's,
 * which would move the depth row by a third.  It is max(texel, ulp(t))
 * either side in every mode. */
START_TEST(stabilize_directional_flat_body_texel_below_ulp_rounding_mode) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){0x1.e846cp+19, 0x1.038c8f6ca65afp+3, 0x1.e8486b1228227p+19};
    cam.dir = (swarp_vec3){-0x1.02d729a675e78p-2, 0x1.fffffffffffffp-1, -0x1p+0};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 0x1.058a54acc4d6ep+0;
    cam.aspect = 0x1.3333333333334p-2;
    const double n = 0x1.fc70371868b8ep-17, f = 0x1.7d5429524e8aap-16;
    const swarp_vec3 ld = {0x1.3e429a4299508p-1, -0x1.d3060e86e9ef8p-2, 0x1.82b51cdb93efcp-1};
    const swarp_vec3 body[1] = {{0x1.e846c00013bf2p+19, 0x1.038c5fc22130ap+3, 0x1.e8486b120e2c7p+19}};
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    o.mode = SWARP_STABILIZE_LEVELS;
    o.origin = (swarp_vec3){1e6, 0, 0};
    o.depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
    swarp_mat4 m0, m;
    const swarp_status st0 = swarp_stabilize_directional(&cam, n, f, &ld, body, 1, NULL, 4878, &o, &m0, NULL);
    ck_assert_msg(!swarp_status_is_error(st0), "%s", swarp_status_name(st0));
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int k = 0; k < 3; ++k) {
        fesetround(modes[k]);
        const swarp_status st = swarp_stabilize_directional(&cam, n, f, &ld, body, 1, NULL, 4878, &o, &m, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, st0);
        for (int i = 2; i < 16; i += 4) /* the depth row */
            ck_assert_msg(fabs(m.m[i] - m0.m[i]) <= 1e-9 * fabs(m0.m[i]), "mode %d: entry %d = %.17g, default %.17g", k, i, m.m[i], m0.m[i]);
    }
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_cascade");
    TCase* t = tcase_create("bias");
    tcase_add_test(t, bias_valid_against_orthographic_closed_form);
    tcase_add_test(t, bias_bad_inputs_untouched);
    suite_add_tcase(s, t);
    t = tcase_create("stabilize");
    tcase_add_test(t, stabilize_directional_edges);
    tcase_add_test(t, stabilize_snap_and_sphere_edges);
    tcase_add_test(t, stabilize_sphere_extreme_aspect_and_thin_range);
    tcase_add_test(t, atlas_kernel_scale_extreme_widths);
    tcase_add_test(t, cascade_select_blend_curve_edges);
    tcase_add_test(t, cascade_view_depth_huge_dir);
    tcase_add_test(t, cascade_error_curve_subnormal_splits);
    tcase_add_test(t, stabilize_directional_tiny_split_far_origin);
    tcase_add_test(t, cascade_view_depth_opposite_ends);
    suite_add_tcase(s, t);
    t = tcase_create("extreme_magnitudes");
    tcase_add_test(t, receiver_plane_edge_on_far_point);
    tcase_add_test(t, receiver_plane_subnormal_resolution);
    tcase_add_test(t, depth_per_world_far_point);
    tcase_add_test(t, stabilize_sphere_subnormal_range);
    tcase_add_test(t, stabilize_directional_flat_body_rounding_mode);
    suite_add_tcase(s, t);
    t = tcase_create("normal_offset_rounding_mode");
    tcase_add_test(t, bias_normal_offset_facing_light_rounding_mode);
    suite_add_tcase(s, t);
    t = tcase_create("bias_and_stabilize_rounding_mode");
    tcase_add_test(t, bias_slope_scaled_tiny_depth_bias_rounding_mode);
    tcase_add_test(t, bias_texel_size_far_point_rounding_mode);
    tcase_add_test(t, stabilize_directional_flat_body_texel_below_ulp_rounding_mode);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
