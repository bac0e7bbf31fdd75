#define _POSIX_C_SOURCE 200809L
/* Splits stage: atlas and kernel scale [RHS] §3.3.5 (3.9), flicker reduction
 * [RHS] §3.5, bias [KOZ] §14.2.3, cascades [RHS] §3.3-3.4, §4.1-4.2. */
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
static uint64_t rng_next(void) { return tu_splitmix64(&rng_state); }
static double rng_uniform(double a, double b) { return tu_uniform(&rng_state, a, b); }

#define PI 3.14159265358979323846

static swarp_vec3 rand_unit(void) {
    for (;;) {
        swarp_vec3 v = v3(rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1));
        double l = vlen(v);
        if (l > 0.1 && l <= 1.0) return vscale(v, 1.0 / l);
    }
}
/* homogeneous transform, written out independently of the library */
static void xform(const swarp_mat4* m, swarp_vec3 p, double out[4]) {
    for (int r = 0; r < 4; ++r)
        out[r] = m->m[r] * p.x + m->m[4 + r] * p.y + m->m[8 + r] * p.z + m->m[12 + r];
}

static swarp_camera make_camera(swarp_vec3 eye, swarp_vec3 dir, double fovy, double aspect,
                                double n, double f) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = eye;
    c.dir = dir;
    c.up = fabs(vnorm(dir).y) > 0.95 ? v3(1, 0, 0) : v3(0, 1, 0);
    c.fovy = fovy;
    c.aspect = aspect;
    c.z_near = n;
    c.z_far = f;
    return c;
}

/* frustum slice corners computed here (not with the library's helper) */
static void corners(const swarp_camera* c, double n, double f, swarp_vec3 out[8]) {
    swarp_vec3 fw = vnorm(c->dir), r = vnorm(vcross(fw, c->up)), u = vcross(r, fw);
    double t = tan(c->fovy / 2);
    int k = 0;
    for (int s = 0; s < 2; ++s)
        for (int i = 0; i < 4; ++i) {
            double z = s ? f : n;
            double x = (i & 1 ? 1 : -1) * z * t * c->aspect, y = (i & 2 ? 1 : -1) * z * t;
            out[k++] = vadd(vadd(vadd(c->eye, vscale(fw, z)), vscale(r, x)), vscale(u, y));
        }
}

/* ======================================================================= */
/* Atlas [RHS] §3.3.5, (3.9)                                               */
/* ======================================================================= */

START_TEST(atlas_tiles_partition_the_atlas) {
    /* Fig. 3.16: grids of 2x2, 3x3, 4x4; tiles disjoint, inside the atlas, and
     * clip_to_atlas maps the clip square onto exactly the tile rectangle. */
    for (uint32_t m = 1; m <= SWARP_ATLAS_MAX_SPLITS; ++m) {
        for (int dr = 1; dr <= 2; ++dr) {
            swarp_atlas_info info;
            swarp_atlas_tile tiles[SWARP_ATLAS_MAX_SPLITS];
            size_t count = 0;
            const uint32_t res = 1024;
            ck_assert_int_eq(swarp_atlas_layout(m, res, (swarp_depth_range)dr, &info, tiles,
                                                SWARP_ATLAS_MAX_SPLITS, &count),
                             SWARP_OK);
            ck_assert_uint_eq(count, m);
            uint32_t g = m == 1 ? 1 : m <= 4 ? 2 : m <= 9 ? 3 : 4;
            ck_assert_uint_eq(info.grid, g);
            ck_assert(info.l_sc == 1.0 / g);
            ck_assert(info.atlas_res == (double)g * res);
            for (uint32_t i = 0; i < m; ++i) {
                const swarp_atlas_tile* t = &tiles[i];
                ck_assert(t->viewport_width == res && t->viewport_height == res);
                ck_assert(t->viewport_x >= 0 && t->viewport_x + res <= info.atlas_res);
                ck_assert(t->viewport_y >= 0 && t->viewport_y + res <= info.atlas_res);
                for (uint32_t j = 0; j < i; ++j) /* disjoint */
                    ck_assert(fabs(tiles[j].viewport_x - t->viewport_x) >= res ||
                              fabs(tiles[j].viewport_y - t->viewport_y) >= res);
                /* a homogeneous clip point with w != 1 */
                for (int c = 0; c < 4; ++c) {
                    double x = c & 1 ? 1 : -1, y = c & 2 ? 1 : -1, w = 2.5;
                    double zc = (dr == 1 ? -1.0 : 0.0) * w; /* near plane */
                    double h[4];
                    xform(&t->clip_to_atlas, v3(x * w, y * w, zc), h);
                    /* xform adds column 3 once: the clip w is 1 there, so
                     * scale the input by hand instead */
                    (void)h;
                    double in[4] = {x * w, y * w, zc, w}, o[4];
                    for (int r = 0; r < 4; ++r) {
                        o[r] = 0;
                        for (int k = 0; k < 4; ++k) o[r] += t->clip_to_atlas.m[k * 4 + r] * in[k];
                    }
                    double u = o[0] / o[3], v = o[1] / o[3], d = o[2] / o[3];
                    double eu = (t->viewport_x + (x > 0 ? res : 0)) / info.atlas_res;
                    double ev = (t->viewport_y + (y > 0 ? res : 0)) / info.atlas_res;
                    ck_assert_double_eq_tol(u, eu, 1e-15);
                    ck_assert_double_eq_tol(v, ev, 1e-15);
                    ck_assert_double_eq_tol(d, 0.0, 1e-15);
                }
            }
        }
    }
}
END_TEST

START_TEST(atlas_lsc_and_kernel_scale) {
    /* [RHS] (3.9) l_sc table, literally */
    for (uint32_t m = 1; m <= 16; ++m) {
        double l;
        ck_assert_int_eq(swarp_atlas_lsc(m, &l), SWARP_OK);
        double e = m == 1 ? 1.0 : (m <= 4 ? 0.5 : (m <= 9 ? 1.0 / 3.0 : 0.25));
        ck_assert(l == e);
    }
    double s[2];
    ck_assert_int_eq(swarp_atlas_kernel_scale(0.3, 4, -10, 30, 5, 25, s), SWARP_OK);
    ck_assert_double_eq_tol(s[0], 0.3 * 0.5 * 2.0 / 40.0, 1e-17);
    ck_assert_double_eq_tol(s[1], 0.3 * 0.5 * 2.0 / 20.0, 1e-17);
    /* defining property: the kernel's world size is r_l in every split.  In
     * atlas texture coordinates a split of world width W spans l_sc, so s/2
     * atlas units are (s/2)/l_sc * W world units. */
    rng_state = 11;
    for (int it = 0; it < 200; ++it) {
        uint32_t m = 1 + (uint32_t)(rng_next() % 16);
        double r_l = rng_uniform(0.01, 2.0), lo = rng_uniform(-1e5, 1e5), W = rng_uniform(1, 1e4);
        double l;
        swarp_atlas_lsc(m, &l);
        ck_assert_int_eq(swarp_atlas_kernel_scale(r_l, m, lo, lo + W, lo, lo + 2 * W, s), SWARP_OK);
        ck_assert_double_eq_tol(s[0] / 2.0 / l * W, r_l, 1e-9 * r_l);
        ck_assert_double_eq_tol(s[1] / 2.0 / l * 2 * W, r_l, 1e-9 * r_l);
    }
}
END_TEST

START_TEST(atlas_bad_inputs) {
    swarp_atlas_tile tiles[SWARP_ATLAS_MAX_SPLITS], sent[SWARP_ATLAS_MAX_SPLITS];
    memset(tiles, 0xA5, sizeof tiles);
    memcpy(sent, tiles, sizeof tiles);
    swarp_atlas_info info, isent;
    memset(&info, 0x5A, sizeof info);
    isent = info;
    size_t count = 777;
    ck_assert_int_eq(swarp_atlas_layout(0, 512, 0, &info, tiles, 16, &count), SWARP_ERR_ATLAS_SPLITS);
    ck_assert_int_eq(swarp_atlas_layout(17, 512, 0, &info, tiles, 16, &count), SWARP_ERR_ATLAS_SPLITS);
    ck_assert_int_eq(swarp_atlas_layout(4, 0, 0, &info, tiles, 16, &count), SWARP_ERR_RESOLUTION);
    ck_assert_int_eq(swarp_atlas_layout(4, 512, (swarp_depth_range)7, &info, tiles, 16, &count),
                     SWARP_ERR_UNKNOWN_ENUM);
    ck_assert_int_eq(swarp_atlas_layout(4, 512, 0, &info, NULL, 16, &count), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_atlas_layout(4, 512, 0, &info, tiles, 16, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_uint_eq(count, 777);
    ck_assert_int_eq(swarp_atlas_layout(9, 512, 0, &info, tiles, 8, &count), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(count, 9);
    ck_assert_mem_eq(tiles, sent, sizeof tiles);
    ck_assert_mem_eq(&info, &isent, sizeof info);
    double s[2] = {-7, -7};
    ck_assert_int_eq(swarp_atlas_kernel_scale(1, 4, 1, 1, 0, 1, s), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_atlas_kernel_scale(-1, 4, 0, 1, 0, 1, s), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_atlas_kernel_scale(NAN, 4, 0, 1, 0, 1, s), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_atlas_kernel_scale(1, 0, 0, 1, 0, 1, s), SWARP_ERR_ATLAS_SPLITS);
    ck_assert_int_eq(swarp_atlas_kernel_scale(1, 4, 0, INFINITY, 0, 1, s), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_atlas_kernel_scale(1, 4, 0, 1, 0, 1, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(s[0] == -7 && s[1] == -7);
    double l = -3;
    ck_assert_int_eq(swarp_atlas_lsc(0, &l), SWARP_ERR_ATLAS_SPLITS);
    ck_assert_int_eq(swarp_atlas_lsc(4, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(l == -3);
}
END_TEST

/* ======================================================================= */
/* Stabilisation [RHS] §3.5                                                */
/* ======================================================================= */

/* Smallest sphere through 2, 3 or 4 points (circumsphere of the simplex);
 * returns 0 when degenerate. */
static int circum(const swarp_vec3* p, int k, swarp_vec3* c, double* r) {
    if (k == 2) {
        *c = vscale(vadd(p[0], p[1]), 0.5);
        *r = vlen(vsub(p[0], *c));
        return 1;
    }
    swarp_vec3 a = vsub(p[1], p[0]), b = vsub(p[2], p[0]);
    if (k == 3) {
        swarp_vec3 axb = vcross(a, b);
        double d = 2 * vdot(axb, axb);
        if (d < 1e-18 * vdot(a, a) * vdot(b, b)) return 0;
        swarp_vec3 t = vadd(vscale(vcross(axb, a), vdot(b, b)), vscale(vcross(b, axb), vdot(a, a)));
        *c = vadd(p[0], vscale(t, 1.0 / d));
        *r = vlen(vsub(p[0], *c));
        return 1;
    }
    swarp_vec3 e = vsub(p[3], p[0]);
    double det = vdot(a, vcross(b, e));
    if (fabs(det) < 1e-12 * vlen(a) * vlen(b) * vlen(e)) return 0;
    swarp_vec3 t = vadd(vadd(vscale(vcross(b, e), vdot(a, a)), vscale(vcross(e, a), vdot(b, b))),
                        vscale(vcross(a, b), vdot(e, e)));
    *c = vadd(p[0], vscale(t, 1.0 / (2 * det)));
    *r = vlen(vsub(p[0], *c));
    return 1;
}

/* Brute-force minimal enclosing sphere of 8 points: the smallest of all
 * spheres through 2, 3 or 4 of them that contains all 8 (the minimal sphere
 * is always such a sphere). */
static double brute_min_sphere(const swarp_vec3 pts[8], swarp_vec3* best_c) {
    double best = INFINITY;
    int idx[4];
    for (int k = 2; k <= 4; ++k) {
        for (int m = 0; m < 256; ++m) {
            if (__builtin_popcount(m) != k) continue;
            int n = 0;
            for (int i = 0; i < 8; ++i)
                if (m & (1 << i)) idx[n++] = i;
            swarp_vec3 s[4];
            for (int i = 0; i < k; ++i) s[i] = pts[idx[i]];
            swarp_vec3 c;
            double r;
            if (!circum(s, k, &c, &r) || r >= best) continue;
            int ok = 1;
            for (int i = 0; i < 8 && ok; ++i) ok = vlen(vsub(pts[i], c)) <= r * (1 + 1e-12);
            if (ok) {
                best = r;
                *best_c = c;
            }
        }
    }
    return best;
}

START_TEST(stabilize_min_sphere_is_exact_and_beats_centroid) {
    rng_state = 2024;
    double saved_sum = 0;
    for (int it = 0; it < 300; ++it) {
        swarp_camera cam = make_camera(v3(rng_uniform(-100, 100), rng_uniform(-100, 100), rng_uniform(-100, 100)),
                                       rand_unit(), rng_uniform(0.2, 2.6), rng_uniform(0.3, 3.0), 0.1, 1000);
        double n = rng_uniform(0.1, 50), f = n * rng_uniform(1.01, 100);
        swarp_vec3 c, bc = v3(0, 0, 0), pts[8];
        double r, rc;
        ck_assert_int_eq(swarp_stabilize_sphere(&cam, n, f, &c, &r, &rc), SWARP_OK);
        corners(&cam, n, f, pts);
        double br = brute_min_sphere(pts, &bc);
        ck_assert_double_eq_tol(r, br, 1e-9 * br);
        ck_assert_double_eq_tol(vlen(vsub(c, bc)), 0.0, 1e-6 * br);
        /* centroid sphere: centre = mean of corners, radius = max distance */
        swarp_vec3 m = v3(0, 0, 0);
        for (int i = 0; i < 8; ++i) m = vadd(m, vscale(pts[i], 0.125));
        double mr = 0;
        for (int i = 0; i < 8; ++i) mr = fmax(mr, vlen(vsub(pts[i], m)));
        ck_assert_double_eq_tol(rc, mr, 1e-9 * mr);
        ck_assert(r <= rc * (1 + 1e-12));
        saved_sum += 1 - (r / rc) * (r / rc);
    }
    ck_assert(saved_sum > 0); /* it saves area on average */
}
END_TEST

/* Texel coordinates (s, t) of a world point under a matrix that takes
 * origin-relative coordinates. */
static void texel_of(const swarp_mat4* m, swarp_vec3 p_rel, double res, double st[2]) {
    double h[4];
    xform(m, p_rel, h);
    st[0] = (h[0] / h[3] * 0.5 + 0.5) * res;
    st[1] = (h[1] / h[3] * 0.5 + 0.5) * res;
}
static double frac_dist(double x) { return fabs(x - nearbyint(x)); }

/* A camera wandering by small random moves and rotations (sub-texel to several
 * texels): 1000 steps.  mode SPHERE or LEVELS.  Returns the number of level
 * changes seen. */
static int run_walk(swarp_stabilize_mode mode, double world_offset, int expect_integer) {
    const uint32_t res = 1024;
    const double n = 1, f = 60;
    swarp_vec3 base = v3(world_offset + 3, 10, world_offset - 7);
    swarp_camera cam = make_camera(base, v3(0.3, -0.4, -1), 0.9, 1.5, n, f);
    swarp_vec3 light = v3(0.4, -1, 0.25);
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    o.mode = mode;
    o.origin = v3(world_offset, 0, world_offset); /* caller's local origin */
    swarp_vec3 P = vadd(base, v3(5, -3, -20));    /* fixed world point */
    double prev[2] = {0, 0}, prev_tx = 0, prev_ty = 0;
    uint32_t prev_level = 0, prev_level_y = 0;
    int level_changes = 0, non_integer = 0;
    for (int it = 0; it < 1000; ++it) {
        /* texel ~ 2*60*1.2/1024 ~ 0.1..0.2 world units: moves up to 0.6 */
        cam.eye = vadd(cam.eye, v3(rng_uniform(-0.6, 0.6), rng_uniform(-0.2, 0.2), rng_uniform(-0.6, 0.6)));
        swarp_vec3 fw = vnorm(cam.dir), rt = vnorm(vcross(fw, v3(0, 1, 0)));
        double a = rng_uniform(-0.01, 0.01);
        cam.dir = vnorm(vadd(fw, vscale(rt, a)));
        cam.dir.y = fmax(-0.7, fmin(-0.2, cam.dir.y + rng_uniform(-0.005, 0.005)));
        swarp_vec3 body[8];
        corners(&cam, n, f, body);
        swarp_mat4 M;
        swarp_stabilize_report rep;
        swarp_status st = swarp_stabilize_directional(&cam, n, f, &light, body, 8, NULL, res, &o, &M, &rep);
        ck_assert(st == SWARP_OK || st == SWARP_INFO_LEVEL_ABOVE_RANGE);
        /* the map covers the split: every body corner inside the clip square */
        for (int i = 0; i < 8; ++i) {
            double h[4];
            xform(&M, vsub(body[i], o.origin), h);
            ck_assert(fabs(h[0]) <= 1 + 1e-12 && fabs(h[1]) <= 1 + 1e-12);
            ck_assert(h[2] >= -1 - 1e-12 && h[2] <= 1 + 1e-12);
        }
        double stc[2];
        texel_of(&M, vsub(P, o.origin), res, stc);
        if (it > 0) {
            int same_level = mode == SWARP_STABILIZE_SPHERE ||
                             (rep.level_x == prev_level && rep.level_y == prev_level_y);
            if (same_level) {
                if (expect_integer) {
                    ck_assert_msg(frac_dist(stc[0] - prev[0]) < 1e-6, "s moved by %.9g", stc[0] - prev[0]);
                    ck_assert_msg(frac_dist(stc[1] - prev[1]) < 1e-6, "t moved by %.9g", stc[1] - prev[1]);
                    ck_assert(rep.texel_size_x == prev_tx && rep.texel_size_y == prev_ty);
                } else if (frac_dist(stc[0] - prev[0]) > 1e-3) {
                    ++non_integer;
                }
            } else {
                ++level_changes;
                ck_assert(rep.texel_size_x != prev_tx || rep.texel_size_y != prev_ty);
            }
        }
        prev[0] = stc[0];
        prev[1] = stc[1];
        prev_tx = rep.texel_size_x;
        prev_ty = rep.texel_size_y;
        prev_level = rep.level_x;
        prev_level_y = rep.level_y;
    }
    if (!expect_integer) ck_assert_int_gt(non_integer, 500);
    return level_changes;
}

START_TEST(stabilize_sphere_whole_texels_1000_moves) {
    rng_state = 77;
    run_walk(SWARP_STABILIZE_SPHERE, 0.0, 1);
    /* large world: camera ~3e5 from the world origin, origin near the camera */
    rng_state = 78;
    run_walk(SWARP_STABILIZE_SPHERE, 3e5, 1);
}
END_TEST

START_TEST(stabilize_levels_whole_texels_between_level_changes) {
    rng_state = 79;
    int changes = run_walk(SWARP_STABILIZE_LEVELS, 0.0, 1);
    ck_assert_int_lt(changes, 500); /* the scale is quantised: mostly constant */
    rng_state = 80;
    run_walk(SWARP_STABILIZE_LEVELS, 1e6, 1);
}
END_TEST

START_TEST(stabilize_none_does_flicker) {
    /* the same walk without stabilisation moves texels by fractions: the
     * assertions above are not vacuous */
    rng_state = 81;
    run_walk(SWARP_STABILIZE_NONE, 0.0, 0);
}
END_TEST

START_TEST(stabilize_sphere_size_constant_and_levels_quantised) {
    swarp_camera cam = make_camera(v3(0, 5, 0), v3(0, -0.3, -1), 1.0, 1.0, 1, 100);
    swarp_vec3 light = v3(0, -1, 0.1), body[8];
    corners(&cam, 1, 100, body);
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    o.mode = SWARP_STABILIZE_SPHERE;
    swarp_mat4 M;
    swarp_stabilize_report rep;
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1, 100, &light, NULL, 0, NULL, 2048, &o, &M, &rep), SWARP_OK);
    /* world size of the map = 2 r res/(res - 1) */
    /* rounded up by at most 2^-20 relative */
    ck_assert(rep.texel_size_x * 2048 >= 2 * rep.sphere_radius * 2048 / 2047.0);
    ck_assert_double_eq_tol(rep.texel_size_x * 2048, 2 * rep.sphere_radius * 2048 / 2047.0,
                            2 * rep.sphere_radius * 2048 / 2047.0 * 1e-6);
    ck_assert(rep.texel_size_x == rep.texel_size_y);
    ck_assert(rep.area_saved > 0 && rep.area_saved < 1);
    o.mode = SWARP_STABILIZE_LEVELS;
    o.levels = 16;
    ck_assert_int_eq(swarp_stabilize_directional(&cam, 1, 100, &light, body, 8, NULL, 2048, &o, &M, &rep), SWARP_OK);
    double step = 2 * rep.sphere_radius / 16;
    ck_assert_double_eq_tol(rep.texel_size_x * 2048, rep.level_x * step, 1e-9);
    ck_assert_double_eq_tol(rep.texel_size_y * 2048, rep.level_y * step, 1e-9);
    ck_assert(rep.level_x >= 1 && rep.level_x <= 16);
}
END_TEST

/* An orthographic light map built here independently: basis (u, v, w) from a
 * random light direction, half sizes hx, hy, depth range [t0, t1] along d. */
typedef struct ortho_map {
    swarp_bias_map map;
    swarp_vec3 u, v, d;
    double hx, hy, t0, t1;
} ortho_map;

static ortho_map make_ortho(swarp_vec3 d, swarp_vec3 centre, double hx, double hy, double t0,
                            double t1, double res_s, double res_t) {
    ortho_map o;
    memset(&o, 0, sizeof o);
    o.d = vnorm(d);
    o.u = vnorm(vcross(o.d, fabs(o.d.z) < 0.9 ? v3(0, 0, 1) : v3(1, 0, 0)));
    o.v = vcross(o.u, o.d);
    o.hx = hx;
    o.hy = hy;
    o.t0 = t0;
    o.t1 = t1;
    swarp_vec3 rows[3] = {vscale(o.u, 1 / hx), vscale(o.v, 1 / hy), vscale(o.d, 2 / (t1 - t0))};
    double tr[3] = {-vdot(o.u, centre) / hx, -vdot(o.v, centre) / hy,
                    -2 * vdot(o.d, centre) / (t1 - t0) - (t1 + t0) / (t1 - t0)};
    for (int r = 0; r < 3; ++r) {
        o.map.world_to_clip.m[0 + r] = ((double*)&rows[r])[0];
        o.map.world_to_clip.m[4 + r] = ((double*)&rows[r])[1];
        o.map.world_to_clip.m[8 + r] = ((double*)&rows[r])[2];
        o.map.world_to_clip.m[12 + r] = tr[r];
    }
    o.map.world_to_clip.m[15] = 1;
    o.map.res_s = res_s;
    o.map.res_t = res_t;
    o.map.depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
    return o;
}

START_TEST(stabilize_snap_matrix_whole_texels) {
    /* a caller's ortho map with fixed scale and orientation, sliding with
     * the camera: after snapping, a fixed point moves by whole texels */
    rng_state = 91;
    for (int rep = 0; rep < 20; ++rep) {
        swarp_vec3 origin = v3(rng_uniform(-1e6, 1e6), 0, rng_uniform(-1e6, 1e6));
        swarp_vec3 P = vadd(origin, v3(rng_uniform(-50, 50), rng_uniform(-5, 5), rng_uniform(-50, 50)));
        double prev[2] = {0, 0};
        for (int it = 0; it < 50; ++it) {
            swarp_vec3 c = vadd(origin, v3(rng_uniform(-30, 30), 0, rng_uniform(-30, 30)));
            ortho_map o = make_ortho(v3(0.3, -1, 0.2), vsub(c, origin), 80, 60, -100, 100, 2048, 1024);
            swarp_mat4 M;
            /* the matrix takes origin-relative points here: snap about 0 */
            double st[2], st0[2];
            swarp_vec3 zero = v3(0, 0, 0);
            ck_assert_int_eq(swarp_stabilize_snap_matrix(&o.map.world_to_clip, 2048, 1024, &zero, &M), SWARP_OK);
            texel_of(&M, vsub(P, origin), 2048, st);
            st[1] = st[1] / 2048 * 1024;
            texel_of(&o.map.world_to_clip, vsub(P, origin), 2048, st0);
            ck_assert(fabs(st[0] - st0[0]) <= 0.5 + 1e-9); /* moved by at most half a texel */
            if (it > 0) {
                ck_assert(frac_dist(st[0] - prev[0]) < 1e-6);
                ck_assert(frac_dist(st[1] - prev[1]) < 1e-6);
            }
            prev[0] = st[0];
            prev[1] = st[1];
        }
    }
    /* a warped (projective) map has no uniform grid */
    swarp_mat4 P4, out;
    memset(&P4, 0, sizeof P4);
    P4.m[0] = P4.m[5] = 1;
    P4.m[10] = -1.02;
    P4.m[11] = -1;
    P4.m[14] = -2.02;
    memset(&out, 0x11, sizeof out);
    swarp_mat4 outs = out;
    swarp_vec3 o0 = v3(0, 0, 0);
    ck_assert_int_eq(swarp_stabilize_snap_matrix(&P4, 512, 512, &o0, &out), SWARP_ERR_STABILIZE_WARPED);
    ck_assert_int_eq(swarp_stabilize_snap_matrix(&P4, 0, 512, &o0, &out), SWARP_ERR_RESOLUTION);
    ck_assert_int_eq(swarp_stabilize_snap_matrix(NULL, 512, 512, &o0, &out), SWARP_ERR_NULL_POINTER);
    ck_assert_mem_eq(&out, &outs, sizeof out);
}
END_TEST

START_TEST(stabilize_bad_inputs) {
    swarp_camera cam = make_camera(v3(0, 5, 0), v3(0, -0.3, -1), 1.0, 1.0, 1, 100);
    swarp_vec3 light = v3(0, -1, 0.1), body[8];
    corners(&cam, 1, 100, body);
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    swarp_mat4 M, Ms;
    memset(&M, 0x7F, sizeof M);
    Ms = M;
    swarp_stabilize_report rep, reps;
    memset(&rep, 0x3C, sizeof rep);
    reps = rep;
#define BAD(expr, code) ck_assert_int_eq((expr), (code))
    BAD(swarp_stabilize_directional(NULL, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, NULL, 0, NULL, 512, &o, &M, &rep), SWARP_ERR_NULL_POINTER);
    BAD(swarp_stabilize_directional(&cam, 100, 1, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_NEAR_FAR);
    BAD(swarp_stabilize_directional(&cam, 0, 1, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_NEAR_FAR);
    BAD(swarp_stabilize_directional(&cam, NAN, 1, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_NON_FINITE);
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, body, 8, NULL, 1, &o, &M, &rep), SWARP_ERR_RESOLUTION);
    swarp_vec3 zero = v3(0, 0, 0);
    BAD(swarp_stabilize_directional(&cam, 1, 100, &zero, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_ZERO_VECTOR);
    o.mode = (swarp_stabilize_mode)9;
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_UNKNOWN_ENUM);
    o.mode = 0;
    o._reserved[2] = 1;
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[2] = 0;
    o.level_max_size = -1;
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_OUT_OF_RANGE);
    o.level_max_size = 0;
    swarp_camera bad = cam;
    bad.fovy = PI;
    BAD(swarp_stabilize_directional(&bad, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_FOV);
    bad = cam;
    bad.up = bad.dir;
    BAD(swarp_stabilize_directional(&bad, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_DEGENERATE);
    bad = cam;
    bad._reserved[0] = 3;
    BAD(swarp_stabilize_directional(&bad, 1, 100, &light, body, 8, NULL, 512, &o, &M, &rep), SWARP_ERR_RESERVED_NONZERO);
    swarp_vec3 nanbody[2] = {v3(0, 0, 0), v3(NAN, 0, 0)};
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, nanbody, 2, NULL, 512, &o, &M, &rep), SWARP_ERR_NON_FINITE);
    /* a single point (no extent) without stabilisation cannot be focused */
    BAD(swarp_stabilize_directional(&cam, 1, 100, &light, body, 1, NULL, 512, &o, &M, &rep), SWARP_ERR_DEGENERATE);
    ck_assert_mem_eq(&M, &Ms, sizeof M);
    ck_assert_mem_eq(&rep, &reps, sizeof rep);
    swarp_vec3 c = v3(9, 9, 9);
    double r = 9;
    BAD(swarp_stabilize_sphere(&cam, 5, 5, &c, &r, NULL), SWARP_ERR_NEAR_FAR);
    BAD(swarp_stabilize_sphere(&cam, 1, 5, NULL, &r, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(c.x == 9 && r == 9);
    BAD(swarp_stabilize_light_view(&zero, &M), SWARP_ERR_ZERO_VECTOR);
    ck_assert_mem_eq(&M, &Ms, sizeof M);
#undef BAD
}
END_TEST

/* ======================================================================= */
/* Bias [KOZ] §14.2.3                                                      */
/* ======================================================================= */

START_TEST(bias_texel_size_uniform_equals_footprint) {
    rng_state = 5;
    for (int it = 0; it < 500; ++it) {
        swarp_vec3 c = v3(rng_uniform(-1e5, 1e5), rng_uniform(-1e3, 1e3), rng_uniform(-1e5, 1e5));
        double hx = rng_uniform(1, 500), hy = rng_uniform(1, 500);
        double rs = floor(rng_uniform(64, 4096)), rt = floor(rng_uniform(64, 4096));
        ortho_map o = make_ortho(rand_unit(), c, hx, hy, -300, 400, rs, rt);
        swarp_vec3 p = vadd(c, v3(rng_uniform(-hx, hx), rng_uniform(-50, 50), rng_uniform(-hy, hy)));
        double L, Ls, Lt;
        ck_assert_int_eq(swarp_bias_texel_size(&o.map, &p, &L, &Ls, &Lt), SWARP_OK);
        /* analytic footprint of a uniform map: width / resolution */
        ck_assert_double_eq_tol(Ls, 2 * hx / rs, 1e-7 * Ls);
        ck_assert_double_eq_tol(Lt, 2 * hy / rt, 1e-7 * Lt);
        ck_assert(L == fmax(Ls, Lt));
    }
}
END_TEST

START_TEST(bias_texel_size_perspective_map_is_exact) {
    /* A perspective light map (a warped map's shape): at view depth z the
     * texel at constant depth is 2 z tan(fovy/2) aspect / res wide anywhere in
     * the map, not only at the centre. */
    rng_state = 6;
    for (int it = 0; it < 300; ++it) {
        double fovy = rng_uniform(0.3, 2.0), aspect = rng_uniform(0.5, 2), n = rng_uniform(0.5, 5),
               f = n * rng_uniform(5, 500);
        double t = tan(fovy / 2), res = 1024;
        swarp_bias_map map;
        memset(&map, 0, sizeof map);
        double *m = map.world_to_clip.m; /* gluPerspective, eye at 0 looking down -z */
        m[0] = 1 / (t * aspect);
        m[5] = 1 / t;
        m[10] = -(f + n) / (f - n);
        m[11] = -1;
        m[14] = -2 * f * n / (f - n);
        map.res_s = map.res_t = res;
        double z = rng_uniform(n, f);
        swarp_vec3 p = v3(rng_uniform(-0.9, 0.9) * z * t * aspect, rng_uniform(-0.9, 0.9) * z * t, -z);
        double Ls, Lt;
        ck_assert_int_eq(swarp_bias_texel_size(&map, &p, NULL, &Ls, &Lt), SWARP_OK);
        ck_assert_double_eq_tol(Ls, 2 * z * t * aspect / res, 1e-8 * Ls);
        ck_assert_double_eq_tol(Lt, 2 * z * t / res, 1e-8 * Lt);
    }
}
END_TEST

START_TEST(bias_kozlov_moves_toward_light_by_amount) {
    rng_state = 7;
    for (int it = 0; it < 300; ++it) {
        swarp_vec3 c = v3(rng_uniform(-1e4, 1e4), 0, rng_uniform(-1e4, 1e4));
        ortho_map o = make_ortho(rand_unit(), c, 100, 100, -300, 300, 2048, 2048);
        swarp_light L;
        memset(&L, 0, sizeof L);
        int point = it & 1;
        L.type = point ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
        L.direction = rand_unit();
        L.position = vadd(c, vscale(rand_unit(), 500));
        swarp_vec3 p = vadd(c, v3(rng_uniform(-50, 50), rng_uniform(-50, 50), rng_uniform(-50, 50)));
        double a = rng_uniform(0, 0.1), b = rng_uniform(0, 3), amount, Lt;
        swarp_vec3 q;
        ck_assert_int_eq(swarp_bias_kozlov(&o.map, &L, &p, a, b, &q, &amount), SWARP_OK);
        swarp_bias_texel_size(&o.map, &p, &Lt, NULL, NULL);
        ck_assert_double_eq_tol(amount, a + b * Lt, 1e-12);
        ck_assert_double_eq_tol(vlen(vsub(q, p)), amount, 1e-9);
        if (point) /* distance to the light shrinks by exactly the amount */
            ck_assert_double_eq_tol(vlen(vsub(L.position, p)) - vlen(vsub(L.position, q)), amount, 1e-8);
        else /* advance against the light's travel direction */
            ck_assert_double_eq_tol(-vdot(vsub(q, p), vnorm(L.direction)), amount, 1e-9);
    }
}
END_TEST

START_TEST(bias_normal_offset_and_slope) {
    ortho_map o = make_ortho(v3(0, -1, 0), v3(0, 0, 0), 64, 64, -100, 100, 1024, 1024);
    /* the map's t axis: d = (0,-1,0) */
    swarp_light L;
    memset(&L, 0, sizeof L);
    L.type = SWARP_LIGHT_DIRECTIONAL;
    L.direction = v3(0, -1, 0);
    swarp_vec3 p = v3(3, 1, -2), q;
    const double texel = 128.0 / 1024;
    double amount;
    /* N facing the light: no offset */
    swarp_vec3 up = v3(0, 1, 0);
    ck_assert_int_eq(swarp_bias_normal_offset(&o.map, &L, &p, &up, 2, &q, &amount), SWARP_OK);
    ck_assert_double_eq_tol(amount, 0, 1e-15);
    /* N at 60 degrees: N.L = 1/2 -> offset k texel / 2 along N */
    swarp_vec3 n60 = v3(sin(PI / 3), cos(PI / 3), 0);
    ck_assert_int_eq(swarp_bias_normal_offset(&o.map, &L, &p, &n60, 2, &q, &amount), SWARP_OK);
    ck_assert_double_eq_tol(amount, 2 * texel * 0.5, 1e-12);
    ck_assert_double_eq_tol(vlen(vsub(q, vadd(p, vscale(n60, amount)))), 0, 1e-12);
    /* back-facing: full offset, reported */
    swarp_vec3 down = v3(0, -1, 0);
    ck_assert_int_eq(swarp_bias_normal_offset(&o.map, &L, &p, &down, 2, &q, &amount), SWARP_INFO_BACKFACING);
    ck_assert_double_eq_tol(amount, 2 * texel, 1e-12);
    /* slope-scaled: c + s texel tan(60 deg); depth: window depth per world unit
     * of this ortho map is 1/(t1 - t0) */
    double wb, db, dpw;
    ck_assert_int_eq(swarp_bias_slope_scaled(&o.map, &L, &p, &n60, 0.01, 1.5, &wb, &db), SWARP_OK);
    ck_assert_double_eq_tol(wb, 0.01 + 1.5 * texel * tan(PI / 3), 1e-12);
    ck_assert_double_eq_tol(db, wb / 200.0, 1e-14);
    ck_assert_int_eq(swarp_bias_depth_per_world(&o.map, &L, &p, &dpw), SWARP_OK);
    ck_assert_double_eq_tol(dpw, 1.0 / 200.0, 1e-15);
    o.map.depth = SWARP_DEPTH_ZERO_TO_ONE; /* same matrix read as [0,1] */
    ck_assert_int_eq(swarp_bias_depth_per_world(&o.map, &L, &p, &dpw), SWARP_OK);
    ck_assert_double_eq_tol(dpw, 2.0 / 200.0, 1e-15);
}
END_TEST

START_TEST(bias_receiver_plane_gradient) {
    /* For an ortho map and a plane N.x = N.p, the depth along t = d.x changes
     * by -(N.u)/(N.d) per world unit along u; per texel (2 hx/res world) and
     * in window depth (1/(t1 - t0) per world unit). */
    rng_state = 8;
    for (int it = 0; it < 300; ++it) {
        swarp_vec3 c = v3(rng_uniform(-1e3, 1e3), 0, rng_uniform(-1e3, 1e3));
        double hx = rng_uniform(10, 100), hy = rng_uniform(10, 100);
        ortho_map o = make_ortho(rand_unit(), c, hx, hy, -500, 500, 1024, 512);
        swarp_vec3 N = rand_unit();
        if (fabs(vdot(N, o.d)) < 0.2) continue;
        swarp_vec3 p = vadd(c, vscale(rand_unit(), 5));
        swarp_vec3 ta = vnorm(vcross(N, rand_unit())), tb = vcross(N, ta);
        ta = vadd(vscale(ta, 2.0), vscale(tb, 0.3)); /* any spanning pair */
        double g[2];
        ck_assert_int_eq(swarp_bias_receiver_plane(&o.map, &p, &ta, &tb, g), SWARP_OK);
        double dtdx = -vdot(N, o.u) / vdot(N, o.d), dtdy = -vdot(N, o.v) / vdot(N, o.d);
        double e_s = dtdx * (2 * hx / 1024) / 1000.0, e_t = dtdy * (2 * hy / 512) / 1000.0;
        ck_assert_double_eq_tol(g[0], e_s, 1e-9 * (1 + fabs(e_s)));
        ck_assert_double_eq_tol(g[1], e_t, 1e-9 * (1 + fabs(e_t)));
    }
    /* edge-on plane: degenerate */
    ortho_map o = make_ortho(v3(0, -1, 0), v3(0, 0, 0), 10, 10, -10, 10, 256, 256);
    swarp_vec3 p = v3(0, 0, 0), ta = v3(1, 0, 0), tb = v3(1, 5, 0);
    double g[2] = {-9, -9};
    ck_assert_int_eq(swarp_bias_receiver_plane(&o.map, &p, &ta, &tb, g), SWARP_ERR_DEGENERATE);
    ck_assert(g[0] == -9 && g[1] == -9);
}
END_TEST

START_TEST(bias_bad_inputs) {
    ortho_map o = make_ortho(v3(0, -1, 0), v3(0, 0, 0), 10, 10, -10, 10, 256, 256);
    swarp_light L;
    memset(&L, 0, sizeof L);
    L.direction = v3(0, -1, 0);
    swarp_vec3 p = v3(1, 1, 1), q = v3(-5, -5, -5), n = v3(0, 1, 0);
    double x = -5, y = -5;
    swarp_bias_map bm = o.map;
    bm.res_s = 0;
    ck_assert_int_eq(swarp_bias_texel_size(&bm, &p, &x, NULL, NULL), SWARP_ERR_RESOLUTION);
    bm = o.map;
    bm.depth = (swarp_depth_range)5;
    ck_assert_int_eq(swarp_bias_texel_size(&bm, &p, &x, NULL, NULL), SWARP_ERR_UNKNOWN_ENUM);
    bm = o.map;
    bm._reserved[3] = 1;
    ck_assert_int_eq(swarp_bias_texel_size(&bm, &p, &x, NULL, NULL), SWARP_ERR_RESERVED_NONZERO);
    bm = o.map;
    memset(bm.world_to_clip.m, 0, sizeof bm.world_to_clip.m);
    bm.world_to_clip.m[15] = 1;
    ck_assert_int_eq(swarp_bias_texel_size(&bm, &p, &x, NULL, NULL), SWARP_ERR_SINGULAR);
    bm = o.map;
    bm.world_to_clip.m[3] = NAN;
    ck_assert_int_eq(swarp_bias_texel_size(&bm, &p, &x, NULL, NULL), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_bias_texel_size(&o.map, &p, NULL, NULL, NULL), SWARP_ERR_NULL_POINTER);
    /* behind a perspective map's centre of projection */
    swarp_bias_map pm;
    memset(&pm, 0, sizeof pm);
    pm.world_to_clip.m[0] = pm.world_to_clip.m[5] = 1;
    pm.world_to_clip.m[10] = -1.02;
    pm.world_to_clip.m[11] = -1;
    pm.world_to_clip.m[14] = -2.02;
    pm.res_s = pm.res_t = 64;
    swarp_vec3 behind = v3(0, 0, 5);
    ck_assert_int_eq(swarp_bias_texel_size(&pm, &behind, &x, NULL, NULL), SWARP_ERR_BEHIND_PROJECTION);
    ck_assert(x == -5);
    ck_assert_int_eq(swarp_bias_kozlov(&o.map, &L, &p, -1, 0, &q, NULL), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_bias_kozlov(&o.map, &L, &p, NAN, 0, &q, NULL), SWARP_ERR_NON_FINITE);
    swarp_light bl = L;
    bl.type = (swarp_light_type)9;
    ck_assert_int_eq(swarp_bias_kozlov(&o.map, &bl, &p, 0, 0, &q, NULL), SWARP_ERR_UNKNOWN_ENUM);
    bl = L;
    bl.direction = v3(0, 0, 0);
    ck_assert_int_eq(swarp_bias_kozlov(&o.map, &bl, &p, 0, 0, &q, NULL), SWARP_ERR_ZERO_VECTOR);
    bl = L;
    bl.type = SWARP_LIGHT_POINT;
    bl.position = p;
    ck_assert_int_eq(swarp_bias_kozlov(&o.map, &bl, &p, 0, 0, &q, NULL), SWARP_ERR_ZERO_VECTOR);
    swarp_vec3 z0 = v3(0, 0, 0);
    ck_assert_int_eq(swarp_bias_normal_offset(&o.map, &L, &p, &z0, 1, &q, NULL), SWARP_ERR_ZERO_VECTOR);
    ck_assert_int_eq(swarp_bias_normal_offset(&o.map, &L, &p, &n, -1, &q, NULL), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_bias_slope_scaled(&o.map, &L, &p, &n, -1, 0, &x, &y), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_bias_slope_scaled(&o.map, &L, &p, &n, 0, 0, NULL, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_bias_depth_per_world(&o.map, &L, &p, NULL), SWARP_ERR_NULL_POINTER);
    double g[2] = {-5, -5};
    ck_assert_int_eq(swarp_bias_receiver_plane(&o.map, &p, &z0, &n, g), SWARP_ERR_ZERO_VECTOR);
    ck_assert(q.x == -5 && q.y == -5 && q.z == -5 && x == -5 && y == -5 && g[0] == -5);
}
END_TEST


/* ======================================================================= */
/* Split selection and blending [RHS] §3.3.3                               */
/* ======================================================================= */

/* practical split scheme [RHS] (3.8), written here independently */
static void practical(double n, double f, double lambda, int m, double* out) {
    for (int i = 0; i <= m; ++i)
        out[i] = (1 - lambda) * (n + (f - n) * i / m) + lambda * n * pow(f / n, (double)i / m);
    out[0] = n;
    out[m] = f;
}

START_TEST(select_best_never_worse_than_depth) {
    rng_state = 31;
    int overlap_points = 0, better = 0;
    for (int it = 0; it < 60; ++it) {
        const int m = 2 + (int)(rng_next() % 7);
        const double n = rng_uniform(0.5, 2), f = n * rng_uniform(50, 500);
        swarp_camera cam = make_camera(v3(rng_uniform(-1e3, 1e3), 20, rng_uniform(-1e3, 1e3)),
                                       v3(rng_uniform(-1, 1), rng_uniform(-0.5, 0.1), rng_uniform(-1, 1)),
                                       rng_uniform(0.5, 1.5), rng_uniform(1, 2), n, f);
        /* include lights from behind the viewer (Fig. 3.13) */
        swarp_vec3 light = it % 3 == 0 ? vadd(vnorm(cam.dir), vscale(rand_unit(), 0.2)) : rand_unit();
        double splits[10];
        practical(n, f, 0.5, m, splits);
        swarp_bias_map maps[10];
        swarp_stabilize_options o;
        memset(&o, 0, sizeof o);
        for (int i = 0; i < m; ++i) {
            swarp_vec3 body[8];
            corners(&cam, splits[i], splits[i + 1], body);
            memset(&maps[i], 0, sizeof maps[i]);
            maps[i].res_s = maps[i].res_t = 1024;
            ck_assert_int_eq(swarp_stabilize_directional(&cam, splits[i], splits[i + 1], &light, body, 8,
                                                         NULL, 1024, &o, &maps[i].world_to_clip, NULL),
                             SWARP_OK);
        }
        swarp_vec3 fw = vnorm(cam.dir), r = vnorm(vcross(fw, cam.up)), u = vcross(r, fw);
        for (int k = 0; k < 200; ++k) {
            double z = n * pow(f / n, rng_uniform(0, 1));
            double t = tan(cam.fovy / 2);
            swarp_vec3 p = vadd(vadd(vadd(cam.eye, vscale(fw, z)), vscale(r, rng_uniform(-1, 1) * z * t * cam.aspect)),
                                vscale(u, rng_uniform(-1, 1) * z * t));
            uint32_t i_d, i_b;
            swarp_status st = swarp_cascade_select_depth(splits, (size_t)m, z, &i_d);
            ck_assert_int_eq(st, SWARP_OK);
            ck_assert(splits[i_d] <= z && (z < splits[i_d + 1] || (int)i_d == m - 1));
            double Lb, Ld;
            st = swarp_cascade_select_best(maps, (size_t)m, &p, i_d, &i_b, &Lb);
            ck_assert_int_eq(st, SWARP_OK); /* the depth split always covers p */
            ck_assert_int_eq(swarp_bias_texel_size(&maps[i_d], &p, &Ld, NULL, NULL), SWARP_OK);
            ck_assert(Lb <= Ld);
            /* brute force: no covering split has a smaller texel */
            int covering = 0;
            for (int i = 0; i < m; ++i) {
                double h[4];
                xform(&maps[i].world_to_clip, p, h);
                if (fabs(h[0]) <= h[3] && fabs(h[1]) <= h[3] && fabs(h[2]) <= h[3]) {
                    double L;
                    swarp_bias_texel_size(&maps[i], &p, &L, NULL, NULL);
                    ck_assert(L >= Lb);
                    ++covering;
                }
            }
            if (covering > 1) ++overlap_points;
            if (Lb < Ld) ++better;
        }
    }
    ck_assert_int_gt(overlap_points, 100); /* the property was exercised */
    ck_assert_int_gt(better, 10);          /* and best-resolution did win */
}
END_TEST

START_TEST(view_depth_of_world_points) {
    rng_state = 33;
    for (int it = 0; it < 100; ++it) {
        swarp_camera cam = make_camera(v3(rng_uniform(-1e5, 1e5), 3, rng_uniform(-1e5, 1e5)), rand_unit(), 1, 1, 1, 100);
        double z = rng_uniform(1, 100), x = rng_uniform(-5, 5);
        swarp_vec3 side = vnorm(vcross(cam.dir, cam.up));
        swarp_vec3 p = vadd(vadd(cam.eye, vscale(vnorm(cam.dir), z)), vscale(side, x));
        double d;
        ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &d), SWARP_OK);
        ck_assert_double_eq_tol(d, z, 1e-9 * 1e5);
    }
    swarp_camera cam = make_camera(v3(0, 0, 0), v3(0, 0, -1), 1, 1, 1, 100);
    swarp_vec3 p = v3(0, 0, -3);
    double d = -1;
    cam.dir = v3(0, 0, 0);
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &d), SWARP_ERR_ZERO_VECTOR);
    p.x = NAN;
    cam.dir = v3(0, 0, -1);
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, &p, &d), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_view_depth(&cam, NULL, &d), SWARP_ERR_NULL_POINTER);
    ck_assert(d == -1);
}
END_TEST

START_TEST(blend_weight_continuous_and_banded) {
    double splits[5] = {1, 4, 10, 30, 100};
    const double band = 0.2;
    for (int k = 0; k <= 20000; ++k) {
        double z = 1 + 99.0 * k / 20000.0;
        uint32_t i;
        double w;
        ck_assert_int_eq(swarp_cascade_blend(splits, 4, z, band, &i, &w), SWARP_OK);
        ck_assert(w >= 0 && w <= 1);
        double start = splits[i + 1] - band * (splits[i + 1] - splits[i]);
        if (i == 3 || z <= start) ck_assert(w == 1.0);
        else ck_assert_double_eq_tol(w, (splits[i + 1] - z) / (splits[i + 1] - start), 1e-12);
    }
    /* continuity of the mixed result across each border: just before, split i
     * has weight ~0 (so i+1 has ~1); just after, split i+1 has weight 1 */
    for (int b = 1; b < 4; ++b) {
        uint32_t i;
        double w;
        swarp_cascade_blend(splits, 4, nextafter(splits[b], 0), band, &i, &w);
        ck_assert_uint_eq(i, (uint32_t)b - 1);
        ck_assert_double_eq_tol(w, 0, 1e-12);
        swarp_cascade_blend(splits, 4, splits[b], band, &i, &w);
        ck_assert_uint_eq(i, (uint32_t)b);
        ck_assert(w == 1.0);
    }
    uint32_t i = 99;
    double w = -1;
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 150, band, &i, &w), SWARP_INFO_OUTSIDE_SPLITS);
    ck_assert_uint_eq(i, 3);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 0.5, 0, &i, &w), SWARP_INFO_OUTSIDE_SPLITS);
    ck_assert_uint_eq(i, 0);
    ck_assert(w == 1.0);
}
END_TEST

START_TEST(select_bad_inputs) {
    double splits[5] = {1, 4, 10, 30, 100}, bad[3] = {1, 1, 2}, nan3[3] = {1, NAN, 3};
    uint32_t i = 42;
    double w = -3;
    ck_assert_int_eq(swarp_cascade_select_depth(NULL, 4, 5, &i), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_select_depth(splits, 0, 5, &i), SWARP_ERR_SPLIT_COUNT);
    ck_assert_int_eq(swarp_cascade_select_depth(bad, 2, 5, &i), SWARP_ERR_NOT_INCREASING);
    ck_assert_int_eq(swarp_cascade_select_depth(nan3, 2, 5, &i), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_select_depth(splits, 4, INFINITY, &i), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 5, 1.0, &i, &w), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 5, -0.1, &i, &w), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_blend(splits, 4, 5, 0.1, &i, NULL), SWARP_ERR_NULL_POINTER);
    swarp_bias_map maps[2];
    memset(maps, 0, sizeof maps);
    for (int k = 0; k < 2; ++k) {
        maps[k].world_to_clip.m[0] = maps[k].world_to_clip.m[5] = maps[k].world_to_clip.m[10] = 1;
        maps[k].world_to_clip.m[15] = 1;
        maps[k].res_s = maps[k].res_t = 64;
    }
    swarp_vec3 p = v3(0, 0, 0), far = v3(5, 0, 0);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 2, &p, 2, &i, &w), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 0, &p, 0, &i, &w), SWARP_ERR_SPLIT_COUNT);
    maps[1]._reserved[0] = 1;
    ck_assert_int_eq(swarp_cascade_select_best(maps, 2, &p, 0, &i, &w), SWARP_ERR_RESERVED_NONZERO);
    ck_assert_int_eq(swarp_cascade_select_best(maps, 2, &far, 0, &i, &w), SWARP_ERR_RESERVED_NONZERO);
    ck_assert(i == 42 && w == -3);
    maps[1]._reserved[0] = 0;
    ck_assert_int_eq(swarp_cascade_select_best(maps, 2, &far, 1, &i, &w), SWARP_INFO_OUTSIDE_SPLITS);
    ck_assert_uint_eq(i, 1);
}
END_TEST

/* ======================================================================= */
/* Split schemes and the configuration's error curve [RHS] §3.3.2-3.4      */
/* ======================================================================= */

START_TEST(splits_cover_range_without_gap_or_overlap) {
    rng_state = 41;
    const swarp_split_scheme schemes[5] = {SWARP_SCHEME_DEFAULT, SWARP_SCHEME_UNIFORM, SWARP_SCHEME_LOG,
                                           SWARP_SCHEME_PRACTICAL, SWARP_SCHEME_PSEUDO};
    for (int it = 0; it < 400; ++it) {
        swarp_split_options o;
        memset(&o, 0, sizeof o);
        o.scheme = schemes[it % 5];
        o.count = 1 + (uint32_t)(rng_next() % SWARP_SPLIT_MAX_COUNT);
        o.lambda = rng_uniform(0, 1);
        if (o.scheme == SWARP_SCHEME_PSEUDO) {
            o.pseudo_near = rng_uniform(0, 0.3);
            o.pseudo_far = rng_uniform(0, 0.3);
        }
        double n = rng_uniform(0.01, 10), f = n * rng_uniform(1.5, 1e5);
        double c[SWARP_SPLIT_MAX_COUNT + 1];
        size_t cnt;
        ck_assert_int_eq(swarp_cascade_splits(n, f, &o, c, SWARP_SPLIT_MAX_COUNT + 1, &cnt), SWARP_OK);
        uint32_t m = o.count;
        ck_assert_uint_eq(cnt, m + 1);
        ck_assert(c[0] == n && c[m] == f); /* whole range, exactly */
        for (uint32_t i = 0; i < m; ++i) ck_assert(c[i + 1] > c[i]);
        /* independent evaluation of (3.6)-(3.8), (4.1) at the inner splits */
        double lam = o.scheme == SWARP_SCHEME_DEFAULT ? 0.5
                     : o.scheme == SWARP_SCHEME_UNIFORM ? 0.0
                     : o.scheme == SWARP_SCHEME_LOG ? 1.0 : o.lambda;
        double a = n, b = f;
        if (o.scheme == SWARP_SCHEME_PSEUDO) {
            a = n + o.pseudo_near * (f - n);
            b = f - o.pseudo_far * (f - n);
        }
        double e[SWARP_SPLIT_MAX_COUNT + 1];
        practical(a, b, lam, (int)m, e);
        for (uint32_t i = 1; i < m; ++i) ck_assert_double_eq_tol(c[i], e[i], 1e-12 * e[i]);
        /* every depth of [n, f] lies in exactly one split (half-open, last
         * closed), and depth selection finds it */
        for (int k = 0; k < 50; ++k) {
            double z = k == 0 ? n : k == 1 ? f : k < 2 + (int)m ? c[k - 1] : n * pow(f / n, rng_uniform(0, 1));
            if (z > f) z = f;
            int owners = 0;
            uint32_t own = 0;
            for (uint32_t i = 0; i < m; ++i)
                if ((z >= c[i] && z < c[i + 1]) || (i == m - 1 && z == f)) {
                    ++owners;
                    own = i;
                }
            ck_assert_int_eq(owners, 1);
            uint32_t sel;
            ck_assert_int_eq(swarp_cascade_select_depth(c, m, z, &sel), SWARP_OK);
            ck_assert_uint_eq(sel, own);
        }
    }
}
END_TEST

static double curve_max(const double* v, size_t n) {
    double m = 0;
    for (size_t i = 0; i < n; ++i) m = fmax(m, v[i]);
    return m;
}
static double curve_min(const double* v, size_t n) {
    double m = INFINITY;
    for (size_t i = 0; i < n; ++i) m = fmin(m, v[i]);
    return m;
}

static swarp_error_config fig_cfg(double n, double f) {
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = n;
    cfg.z_far = f;
    cfg.theta = PI / 6; /* Θ = 30°, Fig. 3.15 / 3.18 */
    cfg.res_ix = cfg.res_iy = 1024;
    cfg.res_s = cfg.res_t = 1024;
    return cfg;
}

START_TEST(error_pssm_halves_when_splits_double) {
    /* [RHS] §3.3.4, Fig. 3.15: PSSM (lambda 0.5), uniform maps, overhead
     * light: the maximum error (at the near plane) roughly halves when the
     * split count doubles.  Band: both maxima are set by the first split
     * C_1 = U/m + L_m with U = (f - n)/2 (halves exactly when m doubles) and
     * L_m = n (1 + (f/n)^(1/m))/2 (shrinks by a factor in (0, 1)), so the
     * ratio lies in [1/2 - q/2, 1/2 + q/2] with q = L_m/C_1(m).  For f/n >=
     * 500 and m <= 8, q <= 0.1 (checked below), hence the band [0.45, 0.55]. */
    const double fs[2] = {500, 1000};
    for (int fi = 0; fi < 2; ++fi) {
        const double n = 1, f = fs[fi];
        swarp_error_config cfg = fig_cfg(n, f);
        double prev_mx = 0, prev_mz = 0;
        for (uint32_t m = 2; m <= 16; m *= 2) {
            swarp_split_options o;
            memset(&o, 0, sizeof o);
            o.count = m; /* default scheme: PSSM lambda 0.5 */
            double c[17], np[16];
            size_t cnt;
            ck_assert_int_eq(swarp_cascade_splits(n, f, &o, c, 17, &cnt), SWARP_OK);
            for (uint32_t i = 0; i < m; ++i) np[i] = INFINITY; /* uniform */
            static double z[16 * 64], mx[16 * 64], mz[16 * 64];
            size_t k;
            ck_assert_int_eq(swarp_cascade_error_curve(&cfg, c, np, m, 64, z, mx, mz, 16 * 64, &k), SWARP_OK);
            ck_assert_uint_eq(k, m * 64);
            double cmx = curve_max(mx, k), cmz = curve_max(mz, k);
            /* the maximum sits at the near plane (first sample) */
            ck_assert(mx[0] == cmx && mz[0] == cmz);
            /* the sampled curve includes both ends of every split, and the
             * curves are convex: its maximum is the exact maximum */
            double smx, smz;
            ck_assert_int_eq(swarp_error_split_max(&cfg, c, np, m, NULL, NULL, &smx, &smz), SWARP_OK);
            ck_assert_double_eq_tol(cmx, smx, 1e-12 * smx);
            ck_assert_double_eq_tol(cmz, smz, 1e-12 * smz);
            /* uniform (2.7): m_x max = C_1/n; (2.8): m_z max = (C_1 - n)/(2 tan Θ n) */
            ck_assert_double_eq_tol(cmx, c[1] / n, 1e-9 * cmx);
            ck_assert_double_eq_tol(cmz, (c[1] - n) / (2 * tan(PI / 6) * n), 1e-9 * cmz);
            if (prev_mx > 0) {
                double q = 0.5 * n * (1 + pow(f / n, 2.0 / m)) / prev_mx; /* L_{m/2}/C_1(m/2) */
                ck_assert(q <= 0.1);
                ck_assert_msg(cmx / prev_mx >= 0.45 && cmx / prev_mx <= 0.55, "mx ratio %g", cmx / prev_mx);
                ck_assert_msg(cmz / prev_mz >= 0.45 && cmz / prev_mz <= 0.55, "mz ratio %g", cmz / prev_mz);
            }
            prev_mx = cmx;
            prev_mz = cmz;
        }
    }
}
END_TEST

START_TEST(error_lispsm_log_flatter_than_lispsm_pssm) {
    /* [RHS] §3.4.1, Fig. 3.18: LiSPSM (n_opt per split) with logarithmic
     * splits has a flatter m_z than with PSSM(lambda 0.5): smaller max/min
     * over the whole range. */
    const double n = 1, f = 500;
    swarp_error_config cfg = fig_cfg(n, f);
    double ratio[2];
    for (int s = 0; s < 2; ++s) {
        swarp_split_options o;
        memset(&o, 0, sizeof o);
        o.count = 4;
        o.scheme = s ? SWARP_SCHEME_LOG : SWARP_SCHEME_PRACTICAL;
        o.lambda = 0.5;
        double c[5], np[4];
        size_t cnt;
        ck_assert_int_eq(swarp_cascade_splits(n, f, &o, c, 5, &cnt), SWARP_OK);
        ck_assert_int_eq(swarp_cascade_nopt(c, 4, 0, 0, np), SWARP_OK);
        for (int i = 0; i < 4; ++i) /* overhead n_opt = n_i + sqrt(n_i f_i) */
            ck_assert_double_eq_tol(np[i], c[i] + sqrt(c[i] * c[i + 1]), 1e-9 * np[i]);
        static double z[4 * 200], mz[4 * 200];
        size_t k;
        ck_assert_int_eq(swarp_cascade_error_curve(&cfg, c, np, 4, 200, z, NULL, mz, 800, &k), SWARP_OK);
        ratio[s] = curve_max(mz, k) / curve_min(mz, k);
    }
    ck_assert_msg(ratio[1] < ratio[0], "log %g pssm %g", ratio[1], ratio[0]);
}
END_TEST

START_TEST(error_curve_samples_borders) {
    double c[4] = {1, 5, 20, 100}, np[3] = {INFINITY, 12, INFINITY};
    swarp_error_config cfg = fig_cfg(1, 100);
    double z[30], mx[30], mz[30];
    size_t k;
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, c, np, 3, 10, z, mx, mz, 30, &k), SWARP_OK);
    for (int i = 0; i < 3; ++i) {
        ck_assert(z[i * 10] == c[i]); /* just after the border: the new split */
        if (i < 2) ck_assert(z[i * 10 + 9] == nextafter(c[i + 1], 0)); /* left limit */
        /* just after the border == the split's own model at its near plane */
        swarp_error_config sc = cfg;
        sc.z_near = c[i];
        sc.z_far = c[i + 1];
        double ex, ez;
        swarp_error_mx(&sc, c[i], np[i], &ex);
        swarp_error_mz(&sc, c[i], np[i], &ez);
        ck_assert_double_eq_tol(mx[i * 10], ex, 1e-12 * ex);
        ck_assert_double_eq_tol(mz[i * 10], ez, 1e-12 * ez);
    }
    ck_assert(z[29] == 100);
    /* capacity and bad input leave outputs alone */
    double zs[30];
    memcpy(zs, z, sizeof z);
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, c, np, 3, 10, z, mx, mz, 29, &k), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(k, 30);
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, c, np, 3, 1, z, mx, mz, 30, &k), SWARP_ERR_OUT_OF_RANGE);
    double bad_np[3] = {INFINITY, -1, 2};
    ck_assert(swarp_status_is_error(swarp_cascade_error_curve(&cfg, c, bad_np, 3, 10, z, mx, mz, 30, &k)));
    ck_assert_mem_eq(z, zs, sizeof z);
}
END_TEST

START_TEST(splits_bad_inputs) {
    double c[5] = {-1, -1, -1, -1, -1}, cs[5];
    memcpy(cs, c, sizeof c);
    size_t cnt = 99;
    swarp_split_options o;
    memset(&o, 0, sizeof o);
    ck_assert_int_eq(swarp_cascade_splits(0, 10, &o, c, 5, &cnt), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_cascade_splits(10, 10, &o, c, 5, &cnt), SWARP_ERR_NEAR_FAR);
    ck_assert_int_eq(swarp_cascade_splits(1, NAN, &o, c, 5, &cnt), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 5, NULL), SWARP_ERR_NULL_POINTER);
    o.scheme = (swarp_split_scheme)17;
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 5, &cnt), SWARP_ERR_UNKNOWN_ENUM);
    o.scheme = SWARP_SCHEME_PRACTICAL;
    o.lambda = 1.5;
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 5, &cnt), SWARP_ERR_OUT_OF_RANGE);
    o.lambda = 0.5;
    o.scheme = SWARP_SCHEME_PSEUDO;
    o.pseudo_near = 0.6;
    o.pseudo_far = 0.5;
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 5, &cnt), SWARP_ERR_OUT_OF_RANGE);
    o.pseudo_near = o.pseudo_far = 0;
    o.count = 65;
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 5, &cnt), SWARP_ERR_SPLIT_COUNT);
    o.count = 0;
    o._reserved[1] = 4;
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 5, &cnt), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[1] = 0;
    ck_assert_uint_eq(cnt, 99);
    ck_assert_int_eq(swarp_cascade_splits(1, 10, &o, c, 4, &cnt), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(cnt, 5);
    ck_assert_mem_eq(c, cs, sizeof c);
    double np[2] = {-3, -3}, s2[3] = {1, 2, 2};
    ck_assert_int_eq(swarp_cascade_nopt(s2, 2, 0, 0, np), SWARP_ERR_NOT_INCREASING);
    ck_assert(np[0] == -3);
}
END_TEST

/* ======================================================================= */
/* Cascade setup [RHS] §3.3-3.4, §4.1-4.2                                  */
/* ======================================================================= */

typedef struct scene_cfg {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
} scene_cfg;

static scene_cfg random_scene(int overhead) {
    scene_cfg c;
    memset(&c, 0, sizeof c);
    double W = rng_uniform(50, 2000);
    c.box.min = v3(-W, rng_uniform(-20, 0), -W);
    c.box.max = v3(W, rng_uniform(20, 200), W);
    c.cam = make_camera(v3(rng_uniform(-0.5, 0.5) * W, rng_uniform(2, 30), rng_uniform(-0.5, 0.5) * W),
                        v3(rng_uniform(-1, 1), rng_uniform(-0.6, 0.0), rng_uniform(-1, 1)),
                        rng_uniform(0.6, 1.4), rng_uniform(1, 2), rng_uniform(0.1, 1), 0);
    c.cam.z_far = c.cam.z_near * rng_uniform(100, 5000);
    c.light.type = SWARP_LIGHT_DIRECTIONAL;
    c.light.direction = overhead ? v3(0, -1, 0) : vadd(v3(0, -1, 0), vscale(rand_unit(), 0.8));
    return c;
}

START_TEST(cascade_one_split_equals_single_map_bit_for_bit) {
    rng_state = 51;
    int tested = 0;
    for (int it = 0; it < 200; ++it) {
        scene_cfg c = random_scene(0);
        swarp_cascade_options o;
        memset(&o, 0, sizeof o);
        o.split.count = 1;
        o.setup.technique = (swarp_technique)(1 + it % 3); /* uniform, LiSPSM, PSM */
        o.setup.map_width = 1024;
        swarp_setup_result single;
        size_t np;
        swarp_status s1 = swarp_setup(&c.cam, &c.light, &c.box, &o.setup, &single, NULL, 0, &np);
        swarp_cascade_result r;
        swarp_cascade_split sp[1];
        size_t k;
        swarp_status s2 = swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 1, &k);
        ck_assert_int_eq(s1, s2);
        if (swarp_status_is_error(s1)) continue;
        ++tested;
        ck_assert_uint_eq(k, 1);
        ck_assert_mem_eq(&sp[0].matrix, &single.matrix, sizeof single.matrix);
        ck_assert(memcmp(&sp[0].n_eye, &single.n_eye, sizeof(double)) == 0);
        ck_assert(r.view_near == single.view_near && r.view_far == single.view_far);
        ck_assert(sp[0].z_near == single.view_near && sp[0].z_far == single.view_far);
    }
    ck_assert_int_gt(tested, 100);
}
END_TEST

START_TEST(cascade_splits_cover_bodies_and_range) {
    rng_state = 52;
    int tested = 0;
    for (int it = 0; it < 120; ++it) {
        scene_cfg c = random_scene(0);
        if (it % 3 == 2) { /* point light high above the scene; every other one a wide spot */
            c.light.type = SWARP_LIGHT_POINT;
            c.light.position = v3(rng_uniform(-300, 300), c.box.max.y + rng_uniform(300, 3000), rng_uniform(-300, 300));
            if (it % 2) {
                c.light.direction = v3(0, -1, 0);
                c.light.cone_angle = 1.4;
            }
        }
        if (it % 5 == 4) { /* large world: everything 3e5 away from the origin */
            swarp_vec3 off = v3(3e5, 0, -2e5);
            c.box.min = vadd(c.box.min, off);
            c.box.max = vadd(c.box.max, off);
            c.cam.eye = vadd(c.cam.eye, off);
            c.light.position = vadd(c.light.position, off);
        }
        swarp_cascade_options o;
        memset(&o, 0, sizeof o);
        const uint32_t Ks[4] = {2, 4, 8, 16};
        o.split.count = Ks[it % 4];
        o.setup.technique = it % 2 ? SWARP_TECHNIQUE_LISPSM : SWARP_TECHNIQUE_UNIFORM;
        o.kernel_world_size = 0.5;
        swarp_cascade_result r;
        swarp_cascade_split sp[16];
        size_t k;
        swarp_status st = swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k);
        if (st == SWARP_ERR_BODY_EMPTY) continue;
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        ++tested;
        ck_assert_uint_eq(k, o.split.count);
        /* adjusted near/far [RHS] §3.3.1, covered without gap or overlap */
        double an, af;
        ck_assert_int_eq(swarp_body_adjusted_range(&c.cam, &c.box, &an, &af), SWARP_OK);
        ck_assert(r.view_near == an && r.view_far == af);
        ck_assert(sp[0].z_near == an && sp[k - 1].z_far == af);
        for (size_t i = 0; i + 1 < k; ++i) ck_assert(sp[i].z_far == sp[i + 1].z_near && sp[i].z_far > sp[i].z_near);
        double l_sc = r.atlas.l_sc;
        for (size_t i = 0; i < k; ++i) {
            /* every point of B_i inside the split's clip cube */
            swarp_vec3 B[SWARP_BODY_MAX_POINTS];
            size_t nb;
            ck_assert_int_eq(swarp_body_points(&c.cam, sp[i].z_near, sp[i].z_far, &c.light, &c.box, B,
                                               SWARP_BODY_MAX_POINTS, &nb), SWARP_OK);
            double lo = INFINITY, hi = -INFINITY;
            double e[3] = {sp[i].matrix.m[0], sp[i].matrix.m[4], sp[i].matrix.m[8]};
            double el = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            for (size_t j = 0; j < nb; ++j) {
                double h[4];
                xform(&sp[i].matrix, B[j], h);
                ck_assert(h[3] > 0);
                for (int a = 0; a < 3; ++a) ck_assert_msg(fabs(h[a] / h[3]) <= 1 + 1e-7, "split %zu axis %d: %g", i, a, h[a] / h[3]);
                double x = (e[0] * B[j].x + e[1] * B[j].y + e[2] * B[j].z) / el;
                lo = fmin(lo, x);
                hi = fmax(hi, x);
            }
            /* uniform maps: a world bias of 1 toward the light lowers the
             * window depth by depth_per_world anywhere in the split */
            if (o.setup.technique == SWARP_TECHNIQUE_UNIFORM && c.light.type == SWARP_LIGHT_DIRECTIONAL) {
                swarp_vec3 q = B[nb / 2], L = vscale(vnorm(c.light.direction), -1.0);
                double h0[4], h1[4];
                xform(&sp[i].matrix, q, h0);
                xform(&sp[i].matrix, vadd(q, L), h1);
                double dd = 0.5 * (h0[2] / h0[3] - h1[2] / h1[3]);
                ck_assert_double_eq_tol(sp[i].depth_per_world, dd, 1e-9 * fabs(dd) + 1e-15);
                ck_assert(sp[i].depth_per_world > 0);
            }
            /* uniform maps: kernel scale = (3.9) with the body's light-space x extent */
            if (o.setup.technique == SWARP_TECHNIQUE_UNIFORM && c.light.type == SWARP_LIGHT_DIRECTIONAL)
                ck_assert_double_eq_tol(sp[i].kernel_scale[0], 0.5 * l_sc * 2 / (hi - lo), 1e-7 * sp[i].kernel_scale[0]);
            /* atlas matrix = clip_to_atlas * matrix */
            double p4[4];
            xform(&sp[i].atlas_matrix, B[0], p4);
            double h[4], t[4] = {0, 0, 0, 0};
            xform(&sp[i].matrix, B[0], h);
            for (int r2 = 0; r2 < 4; ++r2)
                for (int q = 0; q < 4; ++q) t[r2] += sp[i].tile.clip_to_atlas.m[q * 4 + r2] * h[q];
            /* rounding: relative to the size of the terms summed (large worlds
             * cancel 1e5-sized terms down to the clip range) */
            for (int r2 = 0; r2 < 4; ++r2) {
                const swarp_mat4* A = &sp[i].atlas_matrix;
                double terms = fabs(A->m[12 + r2]) + fabs(A->m[r2] * B[0].x) + fabs(A->m[4 + r2] * B[0].y) +
                               fabs(A->m[8 + r2] * B[0].z);
                ck_assert_double_eq_tol(p4[r2], t[r2], 1e-13 * terms + 1e-15);
            }
        }
    }
    ck_assert_int_gt(tested, 80);
}
END_TEST

START_TEST(cascade_pseudo_planes_first_and_last_only) {
    rng_state = 53;
    scene_cfg c = random_scene(1);
    c.cam.dir = v3(0, -0.05, -1); /* nearly perpendicular to the overhead light */
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    /* fixed split positions: the per-split warps are compared on the same splits */
    o.split.scheme = SWARP_SCHEME_PRACTICAL;
    o.split.lambda = 0.5;
    o.setup.technique = SWARP_TECHNIQUE_LISPSM;
    swarp_cascade_result r0, r1;
    swarp_cascade_split a[4], b[4];
    size_t k;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r0, a, 4, &k)));
    o.setup.param = SWARP_WARP_PARAM_PSEUDO;
    o.setup.pseudo_near = 0.002;
    o.setup.pseudo_far = 0.1;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r1, b, 4, &k)));
    ck_assert(a[0].n_eye != b[0].n_eye);           /* first split: pseudo-near */
    ck_assert(a[1].n_eye == b[1].n_eye);           /* middle splits: plain n_opt */
    ck_assert(a[2].n_eye == b[2].n_eye);
    ck_assert(a[3].n_eye != b[3].n_eye);           /* last split: pseudo-far */
    /* (4.2): a pseudo-near plane weakens the warp's near end: larger n' */
    ck_assert(b[0].n_eye > a[0].n_eye);
    /* per-split warp strength */
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    o.split.scheme = SWARP_SCHEME_PRACTICAL;
    o.split.lambda = 0.5;
    o.setup.technique = SWARP_TECHNIQUE_LISPSM;
    o.n_user[1] = 37.5;
    o.n_user[2] = INFINITY;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r1, b, 4, &k)));
    ck_assert_double_eq_tol(b[1].n_eye, 37.5, 1e-9);
    ck_assert(b[2].n_eye == INFINITY);
    ck_assert(b[0].n_eye == a[0].n_eye && b[3].n_eye == a[3].n_eye);
}
END_TEST

START_TEST(cascade_error_values_at_borders) {
    rng_state = 54;
    scene_cfg c = random_scene(1);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    o.setup.technique = SWARP_TECHNIQUE_LISPSM;
    o.setup.map_width = 1024;
    o.setup.screen_width = 1280;
    o.setup.screen_height = 720;
    swarp_cascade_result r;
    swarp_cascade_split sp[4];
    size_t k;
    ck_assert(!swarp_status_is_error(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 4, &k)));
    double n_primes[4], z[4 * 50], mx[4 * 50], mz[4 * 50], wmx = 0, wmz = 0;
    for (int i = 0; i < 4; ++i) n_primes[i] = sp[i].n_eye;
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = r.view_near;
    cfg.z_far = r.view_far;
    cfg.theta = c.cam.fovy / 2;
    cfg.res_ix = 1280;
    cfg.res_iy = 720;
    cfg.res_s = cfg.res_t = 1024;
    size_t cnt;
    ck_assert_int_eq(swarp_cascade_error_curve(&cfg, r.splits, n_primes, 4, 50, z, mx, mz, 200, &cnt), SWARP_OK);
    for (int i = 0; i < 4; ++i) {
        /* just after border i: the curve's first sample of split i */
        ck_assert_double_eq_tol(sp[i].mx_start, mx[i * 50], 1e-12 * mx[i * 50]);
        ck_assert_double_eq_tol(sp[i].mz_start, mz[i * 50], 1e-12 * mz[i * 50]);
        ck_assert_double_eq_tol(sp[i].mx_end, mx[i * 50 + 49], 1e-9 * mx[i * 50 + 49]);
        ck_assert_double_eq_tol(sp[i].mz_end, mz[i * 50 + 49], 1e-9 * mz[i * 50 + 49]);
        ck_assert(sp[i].max_mx >= fmax(sp[i].mx_start, sp[i].mx_end) * (1 - 1e-12));
        wmx = fmax(wmx, sp[i].max_mx);
        wmz = fmax(wmz, sp[i].max_mz);
    }
    ck_assert(r.max_mx == wmx && r.max_mz == wmz);
    ck_assert_double_eq_tol(r.max_mx, curve_max(mx, cnt), 1e-9 * r.max_mx);
}
END_TEST

START_TEST(cascade_stabilized_whole_texels) {
    rng_state = 55;
    scene_cfg c = random_scene(0);
    /* a flat box the view frustum leaves through the ground: the adjusted
     * far changes every frame, the exact solution must not care (it splits
     * the camera's own range, [RHS] §3.5) */
    c.box.min = v3(-500, -5, -500);
    c.box.max = v3(500, 40, 500);
    c.cam = make_camera(v3(0, 10, 0), v3(0.2, -0.3, -1), 1.0, 1.5, 0.5, 300);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.split.count = 4;
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.setup.map_width = 1024;
    o.stabilize.mode = SWARP_STABILIZE_SPHERE;
    o.stabilize.origin = v3(1, 2, 3);
    o.setup.depth_range = SWARP_DEPTH_ZERO_TO_ONE; /* the stabilised maps follow it */
    swarp_vec3 P = v3(4, 0, -30);
    double prev[4][2];
    double prev_texel[4];
    int compared = 0;
    for (int it = 0; it < 200; ++it) {
        c.cam.eye = vadd(c.cam.eye, v3(rng_uniform(-0.3, 0.3), rng_uniform(-0.05, 0.05), rng_uniform(-0.3, 0.3)));
        c.cam.dir = vnorm(vadd(c.cam.dir, vscale(rand_unit(), 0.004)));
        swarp_cascade_result r;
        swarp_cascade_split sp[4];
        size_t k;
        swarp_status st = swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 4, &k);
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        ck_assert(r.view_near == c.cam.z_near && r.view_far == c.cam.z_far); /* not adjusted */
        for (int i = 0; i < 4; ++i) {
            if (it == 0) { /* B_i inside the map, depth in [0, 1] */
                swarp_vec3 B[SWARP_BODY_MAX_POINTS];
                size_t nb;
                swarp_status bs = swarp_body_points(&c.cam, sp[i].z_near, sp[i].z_far, &c.light, &c.box, B,
                                                    SWARP_BODY_MAX_POINTS, &nb);
                ck_assert(bs == SWARP_OK || bs == SWARP_ERR_BODY_EMPTY);
                if (bs != SWARP_OK) nb = 0;
                for (size_t j = 0; j < nb; ++j) {
                    double h[4];
                    xform(&sp[i].matrix, vsub(B[j], o.stabilize.origin), h);
                    ck_assert(fabs(h[0]) <= 1 + 1e-9 && fabs(h[1]) <= 1 + 1e-9);
                    ck_assert(h[2] >= -1e-9 && h[2] <= 1 + 1e-9);
                }
            }
            double stc[2];
            texel_of(&sp[i].matrix, vsub(P, o.stabilize.origin), 1024, stc);
            /* the exact solution's size depends on the split range: with the
             * adjusted near/far moving, compare only when it did not change */
            if (it > 0 && sp[i].texel_size == prev_texel[i]) {
                ++compared;
                ck_assert(frac_dist(stc[0] - prev[i][0]) < 1e-6);
                ck_assert(frac_dist(stc[1] - prev[i][1]) < 1e-6);
            }
            prev[i][0] = stc[0];
            prev[i][1] = stc[1];
            prev_texel[i] = sp[i].texel_size;
        }
    }
    ck_assert_int_eq(compared, 4 * 199); /* constant world size in every split */
}
END_TEST

START_TEST(cascade_bad_inputs) {
    rng_state = 56;
    scene_cfg c = random_scene(0);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    swarp_cascade_result r, rs;
    swarp_cascade_split sp[16], sps[16];
    memset(&r, 0x6B, sizeof r);
    memset(sp, 0x6B, sizeof sp);
    rs = r;
    memcpy(sps, sp, sizeof sp);
    size_t k = 1234;
    ck_assert_int_eq(swarp_cascade_setup(NULL, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 16, &k), SWARP_ERR_NULL_POINTER);
    o.split.count = 17;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_SPLIT_COUNT);
    o.split.count = 0;
    o._reserved[0] = 1;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[0] = 0;
    o.kernel_world_size = -1;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_OUT_OF_RANGE);
    o.kernel_world_size = 0;
    o.n_user[3] = NAN;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_NON_FINITE);
    o.n_user[3] = -2;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_OUT_OF_RANGE);
    o.n_user[3] = 0;
    /* stabilisation with a warp, and with a point light */
    o.stabilize.mode = SWARP_STABILIZE_SPHERE;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_STABILIZE_WARPED);
    o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    o.n_user[1] = 20;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_STABILIZE_WARPED);
    o.n_user[1] = 0;
    swarp_light pl = c.light;
    pl.type = SWARP_LIGHT_POINT;
    pl.position = v3(0, 500, 0);
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &pl, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_STABILIZE_LIGHT);
    o.stabilize.mode = (swarp_stabilize_mode)8;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_UNKNOWN_ENUM);
    o.stabilize.mode = 0;
    o.split.scheme = (swarp_split_scheme)99;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_UNKNOWN_ENUM);
    o.split.count = 1; /* the single-map path validates the scheme too */
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_UNKNOWN_ENUM);
    o.split.count = 0;
    o.split.scheme = 0;
    o.stabilize._reserved[2] = 5;
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_RESERVED_NONZERO);
    o.stabilize._reserved[2] = 0;
    /* camera looking away from the scene */
    swarp_camera away = c.cam;
    away.dir = v3(0, 1, 0);
    away.up = v3(1, 0, 0);
    away.eye = v3(0, 1e4, 0);
    ck_assert_int_eq(swarp_cascade_setup(&away, &c.light, &c.box, &o, &r, sp, 16, &k), SWARP_ERR_BODY_EMPTY);
    ck_assert_uint_eq(k, 1234);
    ck_assert_mem_eq(&r, &rs, sizeof r);
    ck_assert_mem_eq(sp, sps, sizeof sp);
    ck_assert_int_eq(swarp_cascade_setup(&c.cam, &c.light, &c.box, &o, &r, sp, 3, &k), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(k, 4);
}
END_TEST
/* ======================================================================= */

static Suite* splits_suite(void) {
    Suite* s = suite_create("splits");
    TCase* t = tcase_create("atlas");
    tcase_add_test(t, atlas_tiles_partition_the_atlas);
    tcase_add_test(t, atlas_lsc_and_kernel_scale);
    tcase_add_test(t, atlas_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("stabilize");
    tcase_add_test(t, stabilize_min_sphere_is_exact_and_beats_centroid);
    tcase_add_test(t, stabilize_sphere_whole_texels_1000_moves);
    tcase_add_test(t, stabilize_levels_whole_texels_between_level_changes);
    tcase_add_test(t, stabilize_none_does_flicker);
    tcase_add_test(t, stabilize_sphere_size_constant_and_levels_quantised);
    tcase_add_test(t, stabilize_snap_matrix_whole_texels);
    tcase_add_test(t, stabilize_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("bias");
    tcase_add_test(t, bias_texel_size_uniform_equals_footprint);
    tcase_add_test(t, bias_texel_size_perspective_map_is_exact);
    tcase_add_test(t, bias_kozlov_moves_toward_light_by_amount);
    tcase_add_test(t, bias_normal_offset_and_slope);
    tcase_add_test(t, bias_receiver_plane_gradient);
    tcase_add_test(t, bias_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("schemes");
    tcase_add_test(t, splits_cover_range_without_gap_or_overlap);
    tcase_add_test(t, error_pssm_halves_when_splits_double);
    tcase_add_test(t, error_lispsm_log_flatter_than_lispsm_pssm);
    tcase_add_test(t, error_curve_samples_borders);
    tcase_add_test(t, splits_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("cascade");
    tcase_add_test(t, cascade_one_split_equals_single_map_bit_for_bit);
    tcase_add_test(t, cascade_splits_cover_bodies_and_range);
    tcase_add_test(t, cascade_pseudo_planes_first_and_last_only);
    tcase_add_test(t, cascade_error_values_at_borders);
    tcase_add_test(t, cascade_stabilized_whole_texels);
    tcase_add_test(t, cascade_bad_inputs);
    suite_add_tcase(s, t);
    t = tcase_create("select");
    tcase_add_test(t, select_best_never_worse_than_depth);
    tcase_add_test(t, blend_weight_continuous_and_banded);
    tcase_add_test(t, view_depth_of_world_points);
    tcase_add_test(t, select_bad_inputs);
    suite_add_tcase(s, t);
    return s;
}

int main(void) {
    int failed = tu_run_suite(splits_suite());
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
