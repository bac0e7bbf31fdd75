#define _POSIX_C_SOURCE 200809L
/* swarp_cascade_setup's options: stabilised cascades keep constant split ranges
 * ([RHS] §3.5), spot lights' receivers H_i ∩ L, [RHS] §3.4 "arbitrary
 * warping" (per split / derived from the first split), and the [RHS] §4.3
 * measured min depth as an input of the setup call. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"
#include "test_vec.h"

/* ---- small seeded PRNG (splitmix64) ------------------------------------ */
static uint64_t rng_state;
static double rng_uniform(double a, double b) { return tu_uniform(&rng_state, a, b); }
static swarp_vec3 rand_unit(void) {
    for (;;) {
        swarp_vec3 v = v3(rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1));
        double l = sqrt(vdot(v, v));
        if (l > 0.1 && l <= 1.0) return vscale(v, 1.0 / l);
    }
}
/* homogeneous transform, written out independently of the library */
static void xform(const swarp_mat4* m, swarp_vec3 p, double out[4]) {
    for (int r = 0; r < 4; ++r)
        out[r] = m->m[r] * p.x + m->m[4 + r] * p.y + m->m[8 + r] * p.z + m->m[12 + r];
}
static void texel_of(const swarp_mat4* m, swarp_vec3 p_rel, double res, double st[2]) {
    double h[4];
    xform(m, p_rel, h);
    st[0] = (h[0] / h[3] * 0.5 + 0.5) * res;
    st[1] = (h[1] / h[3] * 0.5 + 0.5) * res;
}
static double frac_dist(double x) { return fabs(x - nearbyint(x)); }

static swarp_camera make_camera(swarp_vec3 eye, swarp_vec3 dir, double fovy, double aspect, double n,
                                double f) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = eye;
    c.dir = dir;
    c.up = v3(0, 1, 0);
    c.fovy = fovy;
    c.aspect = aspect;
    c.z_near = n;
    c.z_far = f;
    return c;
}

/* ======================================================================= */
/* 1. Stabilised cascades split a constant range [RHS] §3.5               */
/* ======================================================================= */

/* The demo's walk: a ground slab the view leaves through its far side, so
 * the adjusted far (§3.3.1) changes every frame; small random moves and
 * rotations on top (sub-texel to several texels).  For a fixed world point
 * the texel coordinates of every split may only change by whole numbers;
 * SPHERE: the texel's world size is bit-identical in every frame; LEVELS:
 * it changes only with the quantised level. */
static void walk(swarp_stabilize_mode mode, double world_offset) {
    rng_state = 0xC0FFEE + (uint64_t)mode;
    const uint32_t res = 1024, K = 4;
    const swarp_vec3 off = v3(world_offset, 0, world_offset);
    swarp_aabb box;
    box.min = vadd(v3(-600, -2, -600), off);
    box.max = vadd(v3(600, 30, 600), off);
    swarp_camera cam = make_camera(vadd(v3(0, 8, 0), off), v3(0.1, -0.12, -1), 0.9, 1.6, 0.5, 900);
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = v3(0.3, -1, 0.2);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = K;
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.setup.map_width = res;
    o.stabilize.mode = mode;
    o.stabilize.origin = off;
    const swarp_vec3 P = vadd(v3(7, 0.5, -60), off); /* fixed world point */
    double prev[SWARP_CASCADE_MAX_SPLITS][2], prev_texel[SWARP_CASCADE_MAX_SPLITS];
    double prev_scale[SWARP_CASCADE_MAX_SPLITS][2];
    double first_splits[SWARP_CASCADE_MAX_SPLITS + 1];
    double adj_far_min = INFINITY, adj_far_max = -INFINITY;
    int compared = 0, level_changes = 0;
    const int steps = 500;
    for (int it = 0; it < steps; ++it) {
        /* walk forward 0.4 per frame plus jitter, and turn a little */
        cam.eye = vadd(cam.eye, v3(rng_uniform(-0.05, 0.05), rng_uniform(-0.02, 0.02), -0.4 + rng_uniform(-0.05, 0.05)));
        cam.dir = vnorm(vadd(cam.dir, vscale(rand_unit(), 0.002)));
        double an, af;
        ck_assert_int_eq(swarp_body_adjusted_range(&cam, &box, &an, &af), SWARP_OK);
        adj_far_min = fmin(adj_far_min, af);
        adj_far_max = fmax(adj_far_max, af);
        swarp_cascade_result r;
        swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
        size_t k;
        swarp_status st = swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, K, &k);
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        /* the split range is the camera's own, the same every frame */
        ck_assert(r.view_near == cam.z_near && r.view_far == cam.z_far);
        if (it == 0) memcpy(first_splits, r.splits, sizeof first_splits);
        ck_assert(memcmp(first_splits, r.splits, (K + 1) * sizeof(double)) == 0);
        for (uint32_t i = 0; i < K; ++i) {
            double stc[2];
            texel_of(&sp[i].matrix, vsub(P, o.stabilize.origin), res, stc);
            /* the world size of a texel per axis: the rows x, y of the
             * (light-aligned, uniform) matrix; LEVELS quantises each axis
             * on its own, so texel_size (their max) alone cannot tell */
            const double sc[2] = {sqrt(sp[i].matrix.m[0] * sp[i].matrix.m[0] + sp[i].matrix.m[4] * sp[i].matrix.m[4] +
                                       sp[i].matrix.m[8] * sp[i].matrix.m[8]),
                                  sqrt(sp[i].matrix.m[1] * sp[i].matrix.m[1] + sp[i].matrix.m[5] * sp[i].matrix.m[5] +
                                       sp[i].matrix.m[9] * sp[i].matrix.m[9])};
            if (it > 0) {
                const int same = sc[0] == prev_scale[i][0] && sc[1] == prev_scale[i][1];
                if (mode == SWARP_STABILIZE_SPHERE) ck_assert(sp[i].texel_size == prev_texel[i] && same);
                if (same) {
                    ++compared;
                    ck_assert_msg(frac_dist(stc[0] - prev[i][0]) < 1e-6 && frac_dist(stc[1] - prev[i][1]) < 1e-6,
                                  "mode %d split %u step %d: texel moved by (%.6f, %.6f)", (int)mode, i, it,
                                  stc[0] - prev[i][0], stc[1] - prev[i][1]);
                } else {
                    ++level_changes;
                }
            }
            prev[i][0] = stc[0];
            prev[i][1] = stc[1];
            prev_texel[i] = sp[i].texel_size;
            prev_scale[i][0] = sc[0];
            prev_scale[i][1] = sc[1];
        }
    }
    /* the walk did move the adjusted far (what made the texels drift) */
    ck_assert_msg(adj_far_max - adj_far_min > 1.0, "adjusted far moved only %g", adj_far_max - adj_far_min);
    if (mode == SWARP_STABILIZE_SPHERE) ck_assert_int_eq(compared, (int)K * (steps - 1));
    /* LEVELS: the level changes now and then, most steps compare */
    if (mode == SWARP_STABILIZE_LEVELS) ck_assert_msg(compared > 9 * level_changes, "%d vs %d", compared, level_changes);
}

START_TEST(stabilized_sphere_constant_range_walk) {
    walk(SWARP_STABILIZE_SPHERE, 0.0);
    walk(SWARP_STABILIZE_SPHERE, 4e5); /* large world, origin-relative */
}
END_TEST

START_TEST(stabilized_levels_constant_range_walk) {
    walk(SWARP_STABILIZE_LEVELS, 0.0);
    walk(SWARP_STABILIZE_LEVELS, 4e5);
}
END_TEST

START_TEST(stabilized_levels_split_beyond_scene) {
    /* the constant range reaches past a small scene: the far splits miss it;
     * their maps cover the split frustum, with an informational status */
    swarp_aabb box = {{-20, -1, -20}, {20, 5, 20}};
    swarp_camera cam = make_camera(v3(0, 3, 10), v3(0, -0.1, -1), 0.9, 1.5, 0.5, 2000);
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = v3(0.2, -1, 0.1);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.stabilize.mode = SWARP_STABILIZE_LEVELS;
    swarp_cascade_result r;
    swarp_cascade_split sp[4];
    size_t k;
    swarp_status st = swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, 4, &k);
    ck_assert_int_eq(st, SWARP_INFO_SPLIT_NO_SCENE);
    ck_assert_int_eq(sp[0].status, SWARP_OK);
    ck_assert_int_eq(sp[3].status, SWARP_INFO_SPLIT_NO_SCENE);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 16; ++j) ck_assert(isfinite(sp[i].matrix.m[j]));
}
END_TEST

/* ======================================================================= */
/* 2. Spot lights: the receivers are H_i ∩ L                              */
/* ======================================================================= */

START_TEST(spot_cascade_receivers_inside_and_tight) {
    /* A spot light whose cone covers only part of the view: with pancaking
     * the light depth range is fitted to the receivers.  Every point of
     * R_i = H_i ∩ L (computed here through the public body calls) lies in
     * split i's clip volume, and the range is TIGHT on R_i (its min and max
     * depth reach the bounds) -- with the whole H_i as receivers it would
     * not be. */
    rng_state = 77;
    int tested = 0, looser = 0;
    for (int it = 0; it < 40; ++it) {
        swarp_aabb box = {{-400, -1, -400}, {400, 40, 400}};
        swarp_camera cam = make_camera(v3(rng_uniform(-20, 20), rng_uniform(15, 40), rng_uniform(40, 80)),
                                       v3(rng_uniform(-0.2, 0.2), rng_uniform(-0.5, -0.2), -1), 1.0, 1.5, 1.0,
                                       rng_uniform(300, 600));
        swarp_light light;
        memset(&light, 0, sizeof light);
        light.type = SWARP_LIGHT_POINT;
        light.position = v3(rng_uniform(-30, 30), rng_uniform(150, 250), rng_uniform(-120, -60));
        light.direction = vnorm(v3(rng_uniform(-0.2, 0.2), -1, rng_uniform(-0.2, 0.2)));
        light.cone_angle = rng_uniform(0.5, 0.8);
        swarp_cascade_options o;
        memset(&o, 0, sizeof o);
        o.split.count = 3;
        o.setup.technique = it % 2 ? SWARP_TECHNIQUE_LISPSM : SWARP_TECHNIQUE_UNIFORM;
        o.setup.pancake = 1;
        o.setup.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
        swarp_cascade_result r;
        swarp_cascade_split sp[3];
        size_t k;
        swarp_status st = swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, 3, &k);
        if (st == SWARP_ERR_SPLIT_EMPTY) continue; /* the cone misses a split */
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        ++tested;
        for (size_t i = 0; i < k; ++i) {
            static swarp_polyhedron H, R;
            ck_assert_int_eq(swarp_body_h(&cam, sp[i].z_near, sp[i].z_far, &box, &H), SWARP_OK);
            ck_assert_int_eq(swarp_body_receivers(&H, &light, &R), SWARP_OK);
            double lo = INFINITY, hi = -INFINITY, lo_h = INFINITY, hi_h = -INFINITY;
            for (uint32_t j = 0; j < R.vertex_count; ++j) {
                double h[4];
                xform(&sp[i].matrix, R.vertices[j], h);
                ck_assert(h[3] > 0);
                ck_assert_msg(fabs(h[0] / h[3]) <= 1 + 1e-7 && fabs(h[1] / h[3]) <= 1 + 1e-7,
                              "split %zu: receiver outside the map (%g, %g)", i, h[0] / h[3], h[1] / h[3]);
                const double z = h[2] / h[3];
                ck_assert_msg(z >= -1e-7 && z <= 1 + 1e-7, "split %zu: receiver depth %g", i, z);
                lo = fmin(lo, z);
                hi = fmax(hi, z);
            }
            for (uint32_t j = 0; j < H.vertex_count; ++j) {
                double h[4];
                xform(&sp[i].matrix, H.vertices[j], h);
                if (h[3] > 0) lo_h = fmin(lo_h, h[2] / h[3]), hi_h = fmax(hi_h, h[2] / h[3]);
            }
            /* tight: the receivers reach both ends of the depth range */
            ck_assert_msg(fabs(lo) < 1e-6 && fabs(hi - 1) < 1e-6, "split %zu: receivers span [%g, %g]", i, lo, hi);
            /* and H_i itself reaches outside it where the cone cuts H_i */
            if (lo_h < -1e-3 || hi_h > 1 + 1e-3) ++looser;
        }
    }
    ck_assert_int_ge(tested, 20);
    ck_assert_int_ge(looser, 5); /* the test can tell H_i ∩ L from H_i */
}
END_TEST

/* ======================================================================= */
/* 3. Arbitrary warping [RHS] §3.4                                        */
/* ======================================================================= */

/* split distances by (3.6)-(3.8), written here: lambda 1 = log, 0 = uniform */
static double c_i(double n, double f, double lambda, int i, int m) {
    const double t = (double)i / (double)m;
    return lambda * n * pow(f / n, t) + (1.0 - lambda) * (n + (f - n) * t);
}

static void warp_scene(swarp_camera* cam, swarp_light* light, swarp_aabb* box) {
    *box = (swarp_aabb){{-1500, -5, -1500}, {1500, 60, 1500}};
    *cam = make_camera(v3(3, 20, 5), v3(0.2, -0.25, -1), 1.0, 1.6, 0.7, 1000);
    memset(light, 0, sizeof *light);
    light->type = SWARP_LIGHT_DIRECTIONAL;
    light->direction = v3(0.3, -1, -0.4);
}

START_TEST(warp_from_first_log_is_geometric) {
    /* log scheme: every split is the first one scaled by (f/n)^(i/m), so the
     * derived n'_i = n'_0 (f/n)^(i/m) -- evaluated here from the adjusted
     * range alone, not from the split table */
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
    warp_scene(&cam, &light, &box);
    const double n_first[3] = {5.0, 40.0, 0.0}; /* 0: split 0's own n_opt */
    for (int v = 0; v < 3; ++v) {
        for (uint32_t K = 2; K <= 8; K *= 2) {
            swarp_cascade_options o;
            memset(&o, 0, sizeof o);
            o.split.count = K;
            o.split.scheme = SWARP_SCHEME_LOG;
            o.setup.technique = SWARP_TECHNIQUE_LISPSM;
            o.warp_per_split = SWARP_CASCADE_WARP_FROM_FIRST;
            o.n_user[0] = n_first[v];
            swarp_cascade_result r;
            swarp_cascade_split sp[8];
            size_t k;
            swarp_status st = swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, 8, &k);
            ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
            const double n0 = sp[0].n_eye;
            /* n' goes through light units and back: to rounding */
            if (n_first[v] > 0) ck_assert(fabs(n0 - n_first[v]) <= 1e-12 * n_first[v]);
            ck_assert(isfinite(n0) && n0 > 0);
            const double ratio = r.view_far / r.view_near;
            for (uint32_t i = 1; i < K; ++i) {
                const double want = n0 * pow(ratio, (double)i / K);
                ck_assert_msg(fabs(sp[i].n_eye - want) <= 1e-9 * want, "K %u split %u: %.12g vs %.12g", K, i,
                              sp[i].n_eye, want);
            }
            /* the defining property: scaled copies of the first split have
             * the same error maxima ([RHS] (2.3)-(2.4) are scale-free) */
            for (uint32_t i = 1; i < K; ++i) {
                ck_assert(fabs(sp[i].max_mz - sp[0].max_mz) <= 1e-6 * sp[0].max_mz);
                ck_assert(fabs(sp[i].max_mx - sp[0].max_mx) <= 1e-6 * sp[0].max_mx);
            }
        }
    }
}
END_TEST

START_TEST(warp_from_first_practical_and_overrides) {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
    warp_scene(&cam, &light, &box);
    rng_state = 91;
    for (int it = 0; it < 30; ++it) {
        const uint32_t K = 2 + (uint32_t)(it % 7);
        const double lambda = rng_uniform(0, 1);
        swarp_cascade_options o;
        memset(&o, 0, sizeof o);
        o.split.count = K;
        o.split.scheme = SWARP_SCHEME_PRACTICAL;
        o.split.lambda = lambda;
        o.setup.technique = SWARP_TECHNIQUE_LISPSM;
        o.warp_per_split = SWARP_CASCADE_WARP_FROM_FIRST;
        o.n_user[0] = rng_uniform(0.5, 30);
        const uint32_t pinned = 1 + (uint32_t)(it % (K - 1)); /* a caller's value wins */
        const double pinned_n = rng_uniform(1, 100);
        if (it % 3 == 0) o.n_user[pinned] = pinned_n;
        swarp_cascade_result r;
        swarp_cascade_split sp[8];
        size_t k;
        swarp_status st = swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, 8, &k);
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        const double n = r.view_near, f = r.view_far;
        /* nu_i = n_opt of (3.2) in the overhead frame, here as
         * d / (sqrt(z_1/z_0) - 1) with d = z_1 - z_0 */
        double nu[9];
        for (uint32_t i = 0; i < K; ++i) {
            const double z0 = c_i(n, f, lambda, (int)i, (int)K), z1 = c_i(n, f, lambda, (int)i + 1, (int)K);
            ck_assert(fabs(z0 - r.splits[i]) <= 1e-9 * z0);
            nu[i] = (z1 - z0) / (sqrt(z1 / z0) - 1.0);
        }
        ck_assert(fabs(sp[0].n_eye - o.n_user[0]) <= 1e-12 * o.n_user[0]);
        for (uint32_t i = 1; i < K; ++i) {
            const double want = (it % 3 == 0 && i == pinned) ? pinned_n : o.n_user[0] * nu[i] / nu[0];
            ck_assert_msg(fabs(sp[i].n_eye - want) <= 1e-9 * want, "it %d split %u: %.12g vs %.12g", it, i,
                          sp[i].n_eye, want);
        }
    }
}
END_TEST

START_TEST(warp_each_default_unchanged_and_bad_inputs) {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
    warp_scene(&cam, &light, &box);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    swarp_cascade_result r0, r1;
    swarp_cascade_split a[4], b[4];
    size_t k;
    /* EACH is the default, bit for bit */
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&cam, &light, &box, &o, &r0, a, 4, &k)));
    o.warp_per_split = SWARP_CASCADE_WARP_EACH;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k)));
    ck_assert(memcmp(&r0, &r1, sizeof r0) == 0 && memcmp(a, b, sizeof a) == 0);
    /* FROM_FIRST: split 0 is EACH's split 0 */
    o.warp_per_split = SWARP_CASCADE_WARP_FROM_FIRST;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k)));
    ck_assert(memcmp(&a[0], &b[0], sizeof a[0]) == 0);
    /* uniform first split: every split uniform */
    o.n_user[0] = INFINITY;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k)));
    for (int i = 0; i < 4; ++i) ck_assert(b[i].n_eye == INFINITY);
    /* bad enum, reserved words: specific status, outputs untouched */
    swarp_cascade_result rs;
    swarp_cascade_split bs[4];
    memset(&r1, 0x5A, sizeof r1);
    memset(b, 0x5A, sizeof b);
    memcpy(&rs, &r1, sizeof rs);
    memcpy(bs, b, sizeof bs);
    o.n_user[0] = 0;
    o.warp_per_split = (swarp_cascade_warp)3;
    ck_assert_int_eq(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k), SWARP_ERR_UNKNOWN_ENUM);
    o.warp_per_split = SWARP_CASCADE_WARP_FROM_FIRST;
    o._reserved[2] = 1;
    ck_assert_int_eq(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[2] = 0;
    /* a warped first split cannot be stabilised */
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.stabilize.mode = SWARP_STABILIZE_SPHERE;
    o.n_user[0] = 10;
    ck_assert_int_eq(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k), SWARP_ERR_STABILIZE_WARPED);
    ck_assert(memcmp(&r1, &rs, sizeof rs) == 0 && memcmp(b, bs, sizeof bs) == 0);
    /* uniform technique, no first n': all uniform, stabilisable */
    o.n_user[0] = 0;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&cam, &light, &box, &o, &r1, b, 4, &k)));
}
END_TEST

/* ======================================================================= */
/* 4. [RHS] §4.3 measured min depth                                        */
/* ======================================================================= */

/* A scene inside the bounding box: the ground y = 0 and a few boxes.  The
 * camera's LINEAR depth buffer by ray casting: the ray through pixel (i, j)
 * is eye + z d with d's component along the view direction 1, so the hit
 * parameter z is the view depth itself. */
typedef struct md_scene {
    swarp_aabb bound;
    swarp_aabb obj[3];
    swarp_camera cam;
    swarp_light light;
} md_scene;

static double ray_box(swarp_vec3 o, swarp_vec3 d, const swarp_aabb* b) {
    double t0 = 0, t1 = INFINITY;
    const double oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z};
    const double lo[3] = {b->min.x, b->min.y, b->min.z}, hi[3] = {b->max.x, b->max.y, b->max.z};
    for (int a = 0; a < 3; ++a) {
        if (dd[a] == 0) {
            if (oo[a] < lo[a] || oo[a] > hi[a]) return INFINITY;
            continue;
        }
        double ta = (lo[a] - oo[a]) / dd[a], tb = (hi[a] - oo[a]) / dd[a];
        if (ta > tb) {
            double t = ta;
            ta = tb;
            tb = t;
        }
        t0 = fmax(t0, ta);
        t1 = fmin(t1, tb);
    }
    return t0 <= t1 ? t0 : INFINITY;
}

enum { MD_W = 61, MD_H = 37 }; /* odd sizes: the pyramid's odd rows/columns */

static void render_depth(const md_scene* s, float* buf, swarp_vec3* hits, size_t* nhits) {
    const swarp_camera* c = &s->cam;
    const swarp_vec3 f = vnorm(c->dir), r = vnorm(vcross(f, c->up)), u = vcross(r, f);
    const double ty = tan(0.5 * c->fovy), tx = ty * c->aspect;
    *nhits = 0;
    for (int j = 0; j < MD_H; ++j)
        for (int i = 0; i < MD_W; ++i) {
            const double x = (2.0 * (i + 0.5) / MD_W - 1.0) * tx, y = (2.0 * (j + 0.5) / MD_H - 1.0) * ty;
            const swarp_vec3 d = vadd(f, vadd(vscale(r, x), vscale(u, y)));
            double z = INFINITY;
            if (d.y < 0) { /* the ground inside the bound */
                const double t = -c->eye.y / d.y;
                const swarp_vec3 p = vadd(c->eye, vscale(d, t));
                if (p.x >= s->bound.min.x && p.x <= s->bound.max.x && p.z >= s->bound.min.z && p.z <= s->bound.max.z)
                    z = t;
            }
            for (int b = 0; b < 3; ++b) z = fmin(z, ray_box(c->eye, d, &s->obj[b]));
            /* what the camera can see: inside [near, far] */
            if (!(z >= c->z_near && z <= c->z_far)) z = INFINITY;
            buf[j * MD_W + i] = (float)z;
            if (z < INFINITY) hits[(*nhits)++] = vadd(c->eye, vscale(d, z));
        }
}

static md_scene md_random(void) {
    md_scene s;
    memset(&s, 0, sizeof s);
    const double W = rng_uniform(200, 800);
    s.bound = (swarp_aabb){{-W, -1, -W}, {W, rng_uniform(60, 150), W}}; /* air above the ground */
    s.cam = make_camera(v3(rng_uniform(-50, 50), rng_uniform(5, 40), rng_uniform(-50, 50)),
                        v3(rng_uniform(-1, 1), rng_uniform(-0.7, -0.25), rng_uniform(-1, 1)), rng_uniform(0.6, 1.1),
                        rng_uniform(1.2, 1.8), rng_uniform(0.1, 1.0), rng_uniform(300, 1500));
    for (int b = 0; b < 3; ++b) {
        /* objects ahead of the camera, resting on the ground */
        const swarp_vec3 f = vnorm(s.cam.dir);
        const double dist = rng_uniform(20, 150);
        const swarp_vec3 c = vadd(s.cam.eye, vscale(vnorm(v3(f.x, 0, f.z)), dist));
        const double hw = rng_uniform(2, 10);
        s.obj[b] = (swarp_aabb){{c.x - hw + rng_uniform(-30, 30), 0, c.z - hw + rng_uniform(-30, 30)}, {0, 0, 0}};
        s.obj[b].max = v3(s.obj[b].min.x + 2 * hw, rng_uniform(2, 20), s.obj[b].min.z + 2 * hw);
    }
    s.light.type = SWARP_LIGHT_DIRECTIONAL;
    s.light.direction = vadd(v3(0, -1, 0), vscale(rand_unit(), 0.7));
    return s;
}

START_TEST(min_depth_moves_near_out_without_clipping) {
    rng_state = 4343;
    static float buf[MD_W * MD_H], scratch[SWARP_MINDEPTH_SCRATCH(MD_W, MD_H)];
    static swarp_vec3 hits[MD_W * MD_H];
    int tested = 0, moved = 0;
    for (int it = 0; it < 60; ++it) {
        md_scene s = md_random();
        size_t nh, need;
        render_depth(&s, buf, hits, &nh);
        if (nh == 0) continue;
        double md;
        swarp_status ms = swarp_mindepth_pyramid(buf, MD_W, MD_H, MD_W, scratch, sizeof scratch / sizeof scratch[0],
                                                 &need, &md);
        ck_assert_int_eq(ms, SWARP_OK);
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = (swarp_technique)(1 + it % 3); /* uniform, LiSPSM, PSM */
        o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
        swarp_setup_result r0, r1;
        size_t np;
        swarp_status s0 = swarp_setup(&s.cam, &s.light, &s.bound, &o, &r0, NULL, 0, &np);
        if (swarp_status_is_error(s0)) continue;
        o.min_depth = md;
        swarp_status s1 = swarp_setup(&s.cam, &s.light, &s.bound, &o, &r1, NULL, 0, &np);
        ck_assert_msg(!swarp_status_is_error(s1), "%s", swarp_status_name(s1));
        ++tested;
        /* the near plane of [RHS] §4.3, evaluated by its own call */
        double n43;
        ck_assert(!swarp_status_is_error(swarp_mindepth_near(s.cam.z_near, s.cam.z_far, md, NULL, &n43)));
        ck_assert(r1.view_near >= r0.view_near);
        ck_assert(r1.view_near >= n43 || r1.view_near == r0.view_near);
        /* the far end of H is the same, up to the clipping's rounding */
        ck_assert(fabs(r1.view_far - r0.view_far) <= 1e-9 * r0.view_far);
        if (r1.view_near > 1.5 * r0.view_near) ++moved;
        /* nothing the depth buffer saw is clipped: every seen point lies
         * in the view range and inside the light's map and depth range */
        for (size_t h = 0; h < nh; ++h) {
            const double z = vdot(vsub(hits[h], s.cam.eye), vnorm(s.cam.dir));
            ck_assert_msg(z >= r1.view_near, "seen depth %.9g clipped by near %.9g", z, r1.view_near);
            double q[4];
            xform(&r1.matrix, hits[h], q);
            ck_assert(q[3] > 0);
            const double tol = 1e-7;
            ck_assert_msg(fabs(q[0] / q[3]) <= 1 + tol && fabs(q[1] / q[3]) <= 1 + tol, "tech %d: seen point at (%g, %g)",
                          (int)o.technique, q[0] / q[3], q[1] / q[3]);
            ck_assert(q[2] / q[3] >= -tol && q[2] / q[3] <= 1 + tol);
        }
        /* the cascade: splits start at the moved near, seen points inside
         * the map of the split their depth selects */
        swarp_cascade_options co;
        memset(&co, 0, sizeof co);
        co.split.count = 4;
        co.setup = o;
        swarp_cascade_result cr;
        swarp_cascade_split sp[4];
        size_t k;
        swarp_status cs = swarp_cascade_setup(&s.cam, &s.light, &s.bound, &co, &cr, sp, 4, &k);
        if (cs == SWARP_ERR_SPLIT_EMPTY) continue;
        ck_assert_msg(!swarp_status_is_error(cs), "%s", swarp_status_name(cs));
        ck_assert(cr.view_near == r1.view_near && cr.view_far == r1.view_far);
        for (size_t h = 0; h < nh; ++h) {
            const double z = vdot(vsub(hits[h], s.cam.eye), vnorm(s.cam.dir));
            uint32_t i;
            ck_assert_int_eq(swarp_cascade_select_depth(cr.splits, k, z, &i), SWARP_OK);
            double q[4];
            xform(&sp[i].matrix, hits[h], q);
            ck_assert(q[3] > 0 && fabs(q[0] / q[3]) <= 1 + 1e-7 && fabs(q[1] / q[3]) <= 1 + 1e-7);
        }
    }
    ck_assert_int_ge(tested, 30);
    ck_assert_int_ge(moved, tested / 2); /* the measured depth does move the near plane */
}
END_TEST

START_TEST(min_depth_zero_keeps_result) {
    rng_state = 4344;
    for (int it = 0; it < 30; ++it) {
        md_scene s = md_random();
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = (swarp_technique)(1 + it % 3);
        swarp_setup_result r0, r1;
        swarp_vec3 p0[SWARP_BODY_MAX_POINTS], p1[SWARP_BODY_MAX_POINTS];
        size_t n0, n1;
        swarp_status s0 = swarp_setup(&s.cam, &s.light, &s.bound, NULL, &r0, p0, SWARP_BODY_MAX_POINTS, &n0);
        if (swarp_status_is_error(s0)) continue;
        /* not given, nothing seen (+inf), seen nearer than the near plane:
         * the old result bit for bit */
        const double mds[3] = {0.0, INFINITY, 0.5 * s.cam.z_near};
        for (int m = 0; m < 3; ++m) {
            o.min_depth = mds[m];
            o.technique = SWARP_TECHNIQUE_DEFAULT;
            swarp_status s1 = swarp_setup(&s.cam, &s.light, &s.bound, &o, &r1, p1, SWARP_BODY_MAX_POINTS, &n1);
            ck_assert_int_eq(s1, s0);
            ck_assert(memcmp(&r0, &r1, sizeof r0) == 0);
            ck_assert(n0 == n1 && memcmp(p0, p1, n0 * sizeof p0[0]) == 0);
        }
    }
}
END_TEST

START_TEST(min_depth_ignored_by_stabilized_cascades) {
    /* [RHS] §3.5 needs constant split ranges: a measured min depth must not
     * move the splits of a stabilised cascade (documented) */
    rng_state = 4346;
    for (int it = 0; it < 10; ++it) {
        md_scene s = md_random();
        swarp_cascade_options o;
        memset(&o, 0, sizeof o);
        o.split.count = 3;
        o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
        o.stabilize.mode = it % 2 ? SWARP_STABILIZE_SPHERE : SWARP_STABILIZE_LEVELS;
        swarp_cascade_result r0, r1;
        swarp_cascade_split a[3], b[3];
        size_t k;
        swarp_status s0 = swarp_cascade_setup(&s.cam, &s.light, &s.bound, &o, &r0, a, 3, &k);
        ck_assert_msg(!swarp_status_is_error(s0), "%s", swarp_status_name(s0));
        o.setup.min_depth = 0.5 * (s.cam.z_near + s.cam.z_far);
        ck_assert_int_eq(swarp_cascade_setup(&s.cam, &s.light, &s.bound, &o, &r1, b, 3, &k), s0);
        ck_assert(memcmp(&r0, &r1, sizeof r0) == 0 && memcmp(a, b, sizeof a) == 0);
    }
}
END_TEST

START_TEST(min_depth_bad_inputs) {
    rng_state = 4345;
    md_scene s = md_random();
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    swarp_setup_result r, rs;
    memset(&r, 0x3C, sizeof r);
    rs = r;
    size_t np;
    o.min_depth = NAN;
    ck_assert_int_eq(swarp_setup(&s.cam, &s.light, &s.bound, &o, &r, NULL, 0, &np), SWARP_ERR_NON_FINITE);
    o.min_depth = -1;
    ck_assert_int_eq(swarp_setup(&s.cam, &s.light, &s.bound, &o, &r, NULL, 0, &np), SWARP_ERR_OUT_OF_RANGE);
    o.min_depth = -INFINITY;
    ck_assert_int_eq(swarp_setup(&s.cam, &s.light, &s.bound, &o, &r, NULL, 0, &np), SWARP_ERR_OUT_OF_RANGE);
    o.min_depth = 0;
    o._reserved[0] = 7;
    ck_assert_int_eq(swarp_setup(&s.cam, &s.light, &s.bound, &o, &r, NULL, 0, &np), SWARP_ERR_RESERVED_NONZERO);
    ck_assert(memcmp(&r, &rs, sizeof r) == 0);
    swarp_cascade_options co;
    memset(&co, 0, sizeof co);
    co.split.count = 3;
    co.setup.min_depth = NAN;
    swarp_cascade_result cr;
    swarp_cascade_split sp[3];
    size_t k;
    ck_assert_int_eq(swarp_cascade_setup(&s.cam, &s.light, &s.bound, &co, &cr, sp, 3, &k), SWARP_ERR_NON_FINITE);
    co.setup.min_depth = -2;
    ck_assert_int_eq(swarp_cascade_setup(&s.cam, &s.light, &s.bound, &co, &cr, sp, 3, &k), SWARP_ERR_OUT_OF_RANGE);
}
END_TEST

/* ---- split positions by measurement (SWARP_SCHEME_MEASURED, the default) ----
 * Independent evaluation: every split's returned matrix measured with
 * swarp_measure_max at its default sampling over the split's own range;
 * the worst split of the default cascade is at most that of the practical
 * scheme with λ = 0.5 and with λ = 0.95 on the same inputs (the two λ
 * engines use; the search evaluates both).  Defining properties: the
 * splits run from the adjusted near to far contiguously and strictly
 * increase, the explicit MEASURED scheme is the default, and the same
 * input gives the same bytes. */
static double cascade_worst_measured(const swarp_camera* cam, const swarp_light* l, const swarp_aabb* box,
                                     const swarp_cascade_options* o, swarp_cascade_result* r, swarp_cascade_split* sp) {
    size_t n;
    swarp_status st = swarp_cascade_setup(cam, l, box, o, r, sp, SWARP_CASCADE_MAX_SPLITS, &n);
    if (st == SWARP_ERR_BODY_EMPTY) return -1.0; /* the view misses the box: nothing to split */
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    swarp_measure_res mr = {1920, 1080, 2048, 2048}; /* the setup options' defaults */
    double w = 0.0;
    for (size_t i = 0; i < n; ++i) {
        swarp_measured_error e;
        ck_assert(!swarp_status_is_error(
            swarp_measure_max(cam, sp[i].z_near, sp[i].z_far, l, box, &sp[i].matrix, &mr, NULL, &e)));
        w = fmax(w, e.max_sigma);
    }
    return w;
}

START_TEST(measured_splits_no_worse_than_practical) {
    rng_state = 0x21b5;
    const int N = SW_UNDER_ASAN ? 20 : 120;
    int gained = 0, tested = 0;
    for (int c = 0; c < N; ++c) {
        double yaw = rng_uniform(0, 2 * 3.14159265358979323846), pitch = rng_uniform(-0.5, 0.15);
        double n = rng_uniform(0.1, 1.0);
        swarp_camera cam = make_camera(v3(rng_uniform(-50, 50), rng_uniform(1, 30), rng_uniform(-50, 50)),
                                       v3(cos(pitch) * sin(yaw), sin(pitch), -cos(pitch) * cos(yaw)),
                                       rng_uniform(40, 90) * 3.14159265358979323846 / 180, 16.0 / 9.0, n,
                                       n * pow(10, rng_uniform(2, 3.5)));
        swarp_light light;
        memset(&light, 0, sizeof light);
        light.type = SWARP_LIGHT_DIRECTIONAL;
        light.direction = rand_unit();
        if (light.direction.y > -0.1) light.direction.y = -0.1 - light.direction.y; /* from above */
        swarp_aabb box = {{-500, 0, -500}, {500, rng_uniform(5, 100), 500}};
        swarp_cascade_options o;
        memset(&o, 0, sizeof o);
        o.setup.technique = c % 3 == 0 ? SWARP_TECHNIQUE_UNIFORM : SWARP_TECHNIQUE_DEFAULT;
        o.split.count = c % 4 == 0 ? 3 : 4;
        swarp_cascade_result rd, r5, r95, again;
        swarp_cascade_split sd[SWARP_CASCADE_MAX_SPLITS], s5[SWARP_CASCADE_MAX_SPLITS],
            sa[SWARP_CASCADE_MAX_SPLITS];
        double wd = cascade_worst_measured(&cam, &light, &box, &o, &rd, sd);
        if (wd < 0.0) continue;
        tested++;
        /* contiguous, strictly increasing, from the adjusted near to the far */
        ck_assert(rd.splits[0] == rd.view_near && rd.splits[o.split.count] == rd.view_far);
        for (uint32_t i = 0; i < o.split.count; ++i) {
            ck_assert(rd.splits[i] < rd.splits[i + 1]);
            ck_assert(sd[i].z_near == rd.splits[i] && sd[i].z_far == rd.splits[i + 1]);
        }
        /* deterministic; MEASURED is what DEFAULT means */
        swarp_cascade_options om = o;
        om.split.scheme = SWARP_SCHEME_MEASURED;
        size_t k;
        ck_assert(!swarp_status_is_error(swarp_cascade_setup(&cam, &light, &box, &om, &again, sa,
                                                             SWARP_CASCADE_MAX_SPLITS, &k)));
        ck_assert(memcmp(&again, &rd, sizeof rd) == 0 && memcmp(sa, sd, k * sizeof sa[0]) == 0);
        o.split.scheme = SWARP_SCHEME_PRACTICAL;
        o.split.lambda = 0.5;
        double w5 = cascade_worst_measured(&cam, &light, &box, &o, &r5, s5);
        o.split.lambda = 0.95;
        double w95 = cascade_worst_measured(&cam, &light, &box, &o, &r95, s5);
        ck_assert_msg(wd <= w5 && wd <= w95, "case %d: default %.6g, lambda 0.5 %.6g, lambda 0.95 %.6g", c, wd, w5,
                      w95);
        if (wd < 0.95 * fmin(w5, w95)) gained++;
    }
    /* the search does more than pick one of the two */
    ck_assert_int_gt(tested, N / 2);
    ck_assert_msg(gained > tested / 10, "only %d of %d cases better than both", gained, tested);
}
END_TEST

START_TEST(measured_splits_bad_inputs) {
    double out[8];
    size_t cnt = 99;
    swarp_split_options so;
    memset(&so, 0, sizeof so);
    so.scheme = SWARP_SCHEME_MEASURED;
    /* no scene to measure: a specific status, outputs untouched */
    out[0] = -7.0;
    ck_assert_int_eq(swarp_cascade_splits(1, 100, &so, out, 8, &cnt), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert(out[0] == -7.0 && cnt == 99);
    /* DEFAULT without a scene stays the practical λ = 0.5 */
    double ref[8];
    size_t rc;
    so.scheme = SWARP_SCHEME_DEFAULT;
    ck_assert_int_eq(swarp_cascade_splits(1, 100, &so, out, 8, &cnt), SWARP_OK);
    ck_assert_int_eq(swarp_split_practical(1, 100, 0.5, 4, ref, 8, &rc), SWARP_OK);
    ck_assert(cnt == rc && memcmp(out, ref, rc * sizeof ref[0]) == 0);
    /* stabilised: the ranges must not move with the view */
    swarp_camera cam = make_camera(v3(0, 10, 0), v3(0, -0.3, -1), 1.0, 16.0 / 9.0, 0.5, 200);
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = v3(0.3, -1, 0.2);
    swarp_aabb box = {{-100, 0, -100}, {100, 20, 100}};
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.stabilize.mode = SWARP_STABILIZE_SPHERE;
    o.split.scheme = SWARP_SCHEME_MEASURED;
    swarp_cascade_result r;
    swarp_cascade_split sp[4];
    size_t k = 77;
    memset(&r, 0xAB, sizeof r);
    ck_assert_int_eq(swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, 4, &k), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert(k == 77 && r.split_count == 0xABABABABu);
}
END_TEST

int main(void) {
    Suite* s = suite_create("cascade2");
    TCase* t = tcase_create("stabilized");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, stabilized_sphere_constant_range_walk);
    tcase_add_test(t, stabilized_levels_constant_range_walk);
    tcase_add_test(t, stabilized_levels_split_beyond_scene);
    suite_add_tcase(s, t);
    t = tcase_create("spot");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, spot_cascade_receivers_inside_and_tight);
    suite_add_tcase(s, t);
    t = tcase_create("warp");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, warp_from_first_log_is_geometric);
    tcase_add_test(t, warp_from_first_practical_and_overrides);
    tcase_add_test(t, warp_each_default_unchanged_and_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("mindepth");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, min_depth_moves_near_out_without_clipping);
    tcase_add_test(t, min_depth_zero_keeps_result);
    tcase_add_test(t, min_depth_ignored_by_stabilized_cascades);
    tcase_add_test(t, min_depth_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("measured_splits");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, measured_splits_no_worse_than_practical);
    tcase_add_test(t, measured_splits_bad_inputs);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? EXIT_FAILURE : EXIT_SUCCESS;
}
