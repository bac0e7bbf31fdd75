/* Geometry stage: polyhedra, the body B [RHS] §3.1.1, focusing [RHS] (3.1),
 * the LiSPSM warp [RHS] §3.2.1 / (3.2) / §4.1, PSM [KOZ] and the one call.
 * Properties over seeded random configurations plus hand-made cases. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "geometry/geometry_internal.h" /* sw_normalize_fast: every direction of the stage goes through it */
#include "test_util.h"

#define PI 3.14159265358979323846

/* Under AddressSanitizer (about 20x slower) the full-circle continuity sweep
 * keeps the 0.01° steps only within 10° of parallel and antiparallel and
 * takes every 10th step elsewhere, so the suite stays within seconds. */
#define DEG (PI / 180.0)

/* ---- PRNG (splitmix64) ---------------------------------------------------- */
typedef struct rng { uint64_t s; } rng;
static uint64_t rng_next(rng* r) { return tu_splitmix64(&r->s); }
static double rnd(rng* r, double a, double b) { return tu_uniform(&r->s, a, b); }
static swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static swarp_vec3 add(swarp_vec3 a, swarp_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static swarp_vec3 sub(swarp_vec3 a, swarp_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static swarp_vec3 scl(swarp_vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static double dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static swarp_vec3 cross(swarp_vec3 a, swarp_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double len(swarp_vec3 a) { return sqrt(dot(a, a)); }
static swarp_vec3 unit(swarp_vec3 a) { return scl(a, 1.0 / len(a)); }
static swarp_vec3 rnd_unit(rng* r) {
    for (;;) {
        swarp_vec3 v = v3(rnd(r, -1, 1), rnd(r, -1, 1), rnd(r, -1, 1));
        double l = len(v);
        if (l > 0.1 && l <= 1.0) return scl(v, 1.0 / l);
    }
}

/* clip coordinates of a world point (x/w, y/w, z/w, w) */
static void clip(const swarp_mat4* m, swarp_vec3 p, double out[4]) {
    double h[4];
    for (int r = 0; r < 4; ++r) h[r] = m->m[r] * p.x + m->m[4 + r] * p.y + m->m[8 + r] * p.z + m->m[12 + r];
    out[0] = h[0] / h[3];
    out[1] = h[1] / h[3];
    out[2] = h[2] / h[3];
    out[3] = h[3];
}

/* Rounding bound of evaluating a world-space matrix on a world point and
 * dividing by w (the standard dot-product bound, 64 ulps): what no matrix can
 * avoid in large worlds or near a perspective's apex. */
static double clip_round(const swarp_mat4* m, swarp_vec3 p) {
    double S[4], h[4];
    for (int r = 0; r < 4; ++r) {
        S[r] = fabs(m->m[r] * p.x) + fabs(m->m[4 + r] * p.y) + fabs(m->m[8 + r] * p.z) + fabs(m->m[12 + r]);
        h[r] = m->m[r] * p.x + m->m[4 + r] * p.y + m->m[8 + r] * p.z + m->m[12 + r];
    }
    double e = 0;
    for (int k = 0; k < 3; ++k) e = fmax(e, (S[k] + fabs(h[k] / h[3]) * S[3]) / fabs(h[3]));
    return 64 * 2.2e-16 * e;
}

/* Independent point-in-frustum: view depth in [near, far] and inside the
 * side planes, computed from the camera directly (not from poly.c). */
static int in_frustum(const swarp_camera* c, double near, double far, swarp_vec3 p, double tol) {
    swarp_vec3 f = unit(c->dir), r = unit(cross(f, c->up)), u = cross(r, f);
    swarp_vec3 q = sub(p, c->eye);
    double z = dot(q, f), x = dot(q, r), y = dot(q, u);
    double ty = tan(0.5 * c->fovy), tx = ty * c->aspect;
    return z >= near - tol && z <= far + tol && fabs(x) <= tx * z + tol && fabs(y) <= ty * z + tol;
}
static int in_box(const swarp_aabb* b, swarp_vec3 p, double tol) {
    return p.x >= b->min.x - tol && p.x <= b->max.x + tol && p.y >= b->min.y - tol && p.y <= b->max.y + tol &&
           p.z >= b->min.z - tol && p.z <= b->max.z + tol;
}
/* a random point of the frustum [near, far] (uniform in the NDC-like box) */
static swarp_vec3 rnd_in_frustum(rng* R, const swarp_camera* c, double near, double far) {
    swarp_vec3 f = unit(c->dir), r = unit(cross(f, c->up)), u = cross(r, f);
    double ty = tan(0.5 * c->fovy), tx = ty * c->aspect;
    double z = rnd(R, near, far);
    double x = rnd(R, -1, 1) * tx * z, y = rnd(R, -1, 1) * ty * z;
    return add(c->eye, add(scl(f, z), add(scl(r, x), scl(u, y))));
}

typedef struct config {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
} config;

static void dump_config(const config* c) {
    fprintf(stderr,
            "config: eye %.17g,%.17g,%.17g dir %.17g,%.17g,%.17g up %.17g,%.17g,%.17g fovy %.17g aspect %.17g "
            "near %.17g far %.17g\n  light type %d dir %.17g,%.17g,%.17g pos %.17g,%.17g,%.17g cone %.17g\n"
            "  box %.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
            c->cam.eye.x, c->cam.eye.y, c->cam.eye.z, c->cam.dir.x, c->cam.dir.y, c->cam.dir.z, c->cam.up.x,
            c->cam.up.y, c->cam.up.z, c->cam.fovy, c->cam.aspect, c->cam.z_near, c->cam.z_far, (int)c->light.type,
            c->light.direction.x, c->light.direction.y, c->light.direction.z, c->light.position.x,
            c->light.position.y, c->light.position.z, c->light.cone_angle, c->box.min.x, c->box.min.y,
            c->box.min.z, c->box.max.x, c->box.max.y, c->box.max.z);
}
#define CHECK(cond, ...)                          \
    do {                                          \
        if (!(cond)) {                            \
            dump_config(c);                       \
            ck_assert_msg(cond, __VA_ARGS__);     \
        }                                         \
    } while (0)

static void rnd_config(rng* R, config* c, double offset) {
    memset(c, 0, sizeof *c);
    swarp_vec3 ctr = v3(rnd(R, -50, 50) + offset, rnd(R, -50, 50), rnd(R, -50, 50) - offset);
    swarp_vec3 he = v3(rnd(R, 1, 100), rnd(R, 1, 100), rnd(R, 1, 100));
    if (rng_next(R) % 8 == 0) he.y = 0.0; /* flat scene box */
    c->box.min = sub(ctr, he);
    c->box.max = add(ctr, he);
    c->cam.eye = add(ctr, v3(he.x * rnd(R, -1.5, 1.5), he.y * rnd(R, -1.5, 1.5) + rnd(R, -2, 2),
                             he.z * rnd(R, -1.5, 1.5)));
    swarp_vec3 to_ctr = sub(ctr, c->cam.eye);
    /* mostly looking roughly toward the box, sometimes anywhere */
    c->cam.dir = (rng_next(R) % 4 == 0) ? rnd_unit(R) : unit(add(unit(to_ctr), scl(rnd_unit(R), 0.7)));
    do c->cam.up = rnd_unit(R);
    while (len(cross(c->cam.up, c->cam.dir)) < 0.1);
    c->cam.fovy = rnd(R, 20, 100) * DEG;
    c->cam.aspect = rnd(R, 0.5, 2.5);
    c->cam.z_near = rnd(R, 0.05, 2);
    c->cam.z_far = c->cam.z_near * exp(rnd(R, log(10.0), log(2000.0)));
    int kind = (int)(rng_next(R) % 4);
    if (kind <= 1) {
        c->light.type = SWARP_LIGHT_DIRECTIONAL;
        c->light.direction = rnd_unit(R);
    } else {
        c->light.type = SWARP_LIGHT_POINT;
        /* outside the box, so one perspective map can see B */
        swarp_vec3 dirl = rnd_unit(R);
        double rad = len(he) + 5.0 + rnd(R, 0, 200);
        c->light.position = add(ctr, scl(dirl, rad));
        if (kind == 3) {
            c->light.cone_angle = rnd(R, 10, 80) * DEG;
            c->light.direction = unit(add(scl(dirl, -1.0), scl(rnd_unit(R), 0.3)));
        }
    }
}

/* inside the spot cone (everything for directional and omni lights) */
static int lit_by(const config* c, swarp_vec3 p) {
    if (c->light.type != SWARP_LIGHT_POINT || c->light.cone_angle == 0) return 1;
    swarp_vec3 a = unit(c->light.direction), q = sub(p, c->light.position);
    return acos(fmin(1.0, dot(q, a) / len(q))) < c->light.cone_angle;
}

static const swarp_technique techniques[] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM,
                                             SWARP_TECHNIQUE_PSM};
#define N_TECHNIQUES 3

static double box_scale(const swarp_aabb* b) {
    double s = 0;
    const double* p = &b->min.x;
    for (int i = 0; i < 6; ++i) s = fmax(s, fabs(p[i]));
    return s;
}

static int in_clip(const double c[4], swarp_depth_range dr, double tol) {
    double zlo = dr == SWARP_DEPTH_ZERO_TO_ONE ? 0.0 : -1.0;
    return c[3] > 0 && fabs(c[0]) <= 1 + tol && fabs(c[1]) <= 1 + tol && c[2] >= zlo - tol && c[2] <= 1 + tol;
}

/* stats shared by the random sweep */
typedef struct sweep_stats {
    long ok, empty, inside, total, extr_checked, cover_checked, inverse;
} sweep_stats;

/* Runs every property of the geometry stage (docs/geometry.md) on one
 * configuration and technique. */
/* variant v picks the LiSPSM parameterisation and centre, pancaking and the
 * PSM slide-back, so the sweep covers every option */
static void check_config_v(rng* R, const config* c, swarp_technique tech, swarp_depth_range dr, sweep_stats* st,
                           int v) {
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = tech;
    o.depth_range = dr;
    o.param = (swarp_warp_param)(v % 5); /* default, nopt, nrepar, gmnpr, pseudo */
    if (o.param == SWARP_WARP_PARAM_PSEUDO) o.pseudo_near = 0.1, o.pseudo_far = 0.2;
    o.center = (swarp_warp_center)((v / 5) % 3);
    if (tech == SWARP_TECHNIQUE_PSM && v % 7 == 3) o.psm_slideback = 1;
    if (v % 6 == 5) o.pancake = 1; /* depth range over the receivers only */
    swarp_setup_result res;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t np = 0;
    swarp_status s = swarp_setup(&c->cam, &c->light, &c->box, &o, &res, pts, SWARP_BODY_MAX_POINTS, &np);
    st->total++;
    double scale = fmax(box_scale(&c->box), len(c->cam.eye));
    double tol = 1e-9 * fmax(scale, 1.0);
    if (s == SWARP_ERR_BODY_EMPTY) {
        st->empty++;
        /* independent: no sampled point of V lies in S (and in the spot's
         * cone L: a spot that lights nothing visible also has an empty B) */
        for (int k = 0; k < 200; ++k) {
            swarp_vec3 p = rnd_in_frustum(R, &c->cam, c->cam.z_near, c->cam.z_far);
            int lit = 1;
            if (c->light.type == SWARP_LIGHT_POINT && c->light.cone_angle > 0) {
                swarp_vec3 a = unit(c->light.direction), q = sub(p, c->light.position);
                lit = acos(fmin(1.0, dot(q, a) / len(q))) < c->light.cone_angle * 0.999;
            }
            CHECK(!(lit && in_box(&c->box, p, -tol)), "BODY_EMPTY but a lit point of V lies in S");
        }
        return;
    }
    if (s == SWARP_ERR_LIGHT_INSIDE_BODY) {
        CHECK(c->light.type == SWARP_LIGHT_POINT, "LIGHT_INSIDE_BODY for a directional light, tech %d", (int)tech);
        st->inside++;
        return;
    }
    CHECK(!swarp_status_is_error(s), "setup failed: %s", swarp_status_name(s));
    st->ok++;
    if (s == SWARP_INFO_PSM_INVERSE) st->inverse++;
    for (int i = 0; i < 16; ++i) ck_assert(isfinite(res.matrix.m[i]));
    ck_assert(np >= 1 && np <= SWARP_BODY_MAX_POINTS);
    ck_assert(res.max_mx > 0 && isfinite(res.max_mx) && res.max_mz > 0 && isfinite(res.max_mz));
    ck_assert(res.view_near >= c->cam.z_near && res.view_far <= c->cam.z_far && res.view_near < res.view_far);
    ck_assert(res.n_eye > 0);
    /* B ⊆ S */
    for (size_t i = 0; i < np; ++i) CHECK(in_box(&c->box, pts[i], tol), "B point outside S");
    /* Clip-space tolerance: 1e-9, plus the rounding of evaluating a
     * world-space matrix on world coordinates (|p| eps / extent of B), which
     * no matrix can avoid for a tiny B far from the origin. */
    double ext = 0;
    for (size_t i = 1; i < np; ++i) ext = fmax(ext, len(sub(pts[i], pts[0])));
    double ctol0 = 1e-9 + 64 * 2.2e-16 * scale / fmax(ext, 1e-300);
    double ctol = ctol0;
    /* tightness: B touches the x and y bounds */
    /* (PSM: unit cube clipping fits the receivers H, [KOZ] §14.2.2) */
    swarp_polyhedron Ht;
    ck_assert_int_eq(swarp_body_h(&c->cam, c->cam.z_near, c->cam.z_far, &c->box, &Ht), SWARP_OK); /* as swarp_setup */
    const swarp_vec3* tp = tech == SWARP_TECHNIQUE_PSM ? Ht.vertices : pts;
    size_t ntp = tech == SWARP_TECHNIQUE_PSM ? Ht.vertex_count : np;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < ntp; ++i) {
        double cc[4];
        clip(&res.matrix, tp[i], cc);
        if (c->light.type == SWARP_LIGHT_POINT && cc[3] <= 0) continue;
        ctol = fmax(ctol, 1e-9 + clip_round(&res.matrix, tp[i]));
        for (int k = 0; k < 2; ++k) lo[k] = fmin(lo[k], cc[k]), hi[k] = fmax(hi[k], cc[k]);
    }
    /* (PSM fits the receivers a spot lights, H ∩ L, whose vertices this test
     * does not rebuild: for spots its coverage checks remain) */
    int spot = c->light.type == SWARP_LIGHT_POINT && c->light.cone_angle > 0;
    if (s != SWARP_INFO_LIGHT_NEAR_CLIPPED && !(spot && tech == SWARP_TECHNIQUE_PSM))
        for (int k = 0; k < 2; ++k) {
            CHECK(fabs(lo[k] + 1) < ctol && fabs(hi[k] - 1) < ctol, "not tight: axis %d [%.17g, %.17g] %s tech %d", k,
                          lo[k], hi[k], swarp_status_name(s), (int)tech);
        }
    /* coverage: vertices of H and random points of V ∩ S */
    swarp_polyhedron H;
    ck_assert_int_eq(swarp_body_h(&c->cam, c->cam.z_near, c->cam.z_far, &c->box, &H), SWARP_OK);
    for (uint32_t i = 0; i < H.vertex_count; ++i) {
        ck_assert(in_frustum(&c->cam, c->cam.z_near, c->cam.z_far, H.vertices[i], tol));
        ck_assert(in_box(&c->box, H.vertices[i], tol));
        if (!lit_by(c, H.vertices[i])) continue;
        double cc[4];
        clip(&res.matrix, H.vertices[i], cc);
        CHECK(in_clip(cc, dr, fmax(ctol0, 1e-9 + clip_round(&res.matrix, H.vertices[i]))), "H vertex outside the map: %g %g %g w=%g (%s)", cc[0], cc[1], cc[2],
                      cc[3], swarp_status_name(s));
    }
    int got = 0;
    swarp_vec3 samples[24];
    for (int k = 0; k < 400 && got < 24; ++k) {
        swarp_vec3 p = rnd_in_frustum(R, &c->cam, c->cam.z_near, c->cam.z_far);
        if (!in_box(&c->box, p, 0.0) || !lit_by(c, p)) continue;
        samples[got++] = p;
        double cc[4];
        clip(&res.matrix, p, cc);
        CHECK(in_clip(cc, dr, fmax(ctol0, 1e-9 + clip_round(&res.matrix, p))), "point of V∩S outside the map: %g %g %g w=%g", cc[0], cc[1], cc[2],
                      cc[3]);
        st->cover_checked++;
    }
    /* extrusion: points of S between a point of H and the light are in B
     * and in the map (the casters) */
    for (int k = 0; k < got; ++k) {
        swarp_vec3 h = samples[k];
        double ch[4];
        clip(&res.matrix, h, ch);
        swarp_vec3 toward;
        double tmax;
        if (c->light.type == SWARP_LIGHT_POINT) {
            toward = sub(c->light.position, h);
            tmax = 1.0;
        } else {
            toward = scl(unit(c->light.direction), -1.0);
            tmax = 2.0 * len(sub(c->box.max, c->box.min));
        }
        for (int j = 0; j < 4; ++j) {
            swarp_vec3 p = add(h, scl(toward, rnd(R, 0, tmax)));
            if (!in_box(&c->box, p, 0.0)) continue;
            if (c->light.type == SWARP_LIGHT_POINT && c->light.cone_angle > 0) {
                swarp_vec3 a = unit(c->light.direction), q = sub(p, c->light.position);
                double ang = acos(fmin(1.0, dot(q, a) / len(q)));
                if (ang > c->light.cone_angle) continue; /* outside L */
            }
            double cc[4];
            clip(&res.matrix, p, cc);
            if (o.pancake) { /* casters may lie before the depth range: the renderer clamps them */
                double zlo = dr == SWARP_DEPTH_ZERO_TO_ONE ? 0.0 : -1.0;
                if (cc[2] < zlo) cc[2] = zlo;
            }
            double ptol = fmax(ctol0, 1e-9 + clip_round(&res.matrix, p));
            CHECK(in_clip(cc, dr, ptol), "caster between H and the light outside the map: %g %g %g (%s)",
                          cc[0], cc[1], cc[2], swarp_status_name(s));
            /* depth order: the caster is nearer the light than the receiver
             * it shadows (for PSM with the light behind the camera too) */
            CHECK(cc[2] <= ch[2] + ptol + clip_round(&res.matrix, h), "depth order wrong: caster %.17g receiver %.17g (%s, tech %d)", cc[2], ch[2],
                  swarp_status_name(s), (int)tech);
            st->extr_checked++;
        }
    }
}

static void check_config(rng* R, const config* c, swarp_technique tech, swarp_depth_range dr, sweep_stats* st) {
    check_config_v(R, c, tech, dr, st, 0);
}

/* sw_normalize_fast: the unit vector for every finite non-zero direction,
 * subnormal and near DBL_MAX included, and 0 with *out untouched
 * for a zero or non-finite one -- a NaN component must not slip through the
 * scaled path (fmax ignores NaN, so a scaled norm can be 1 with NaN
 * components). */
START_TEST(normalize_fast_range_and_nan) {
    const swarp_vec3 in[] = {{0x1p-1074, 0, 0}, {3e-320, -4e-320, 0}, {DBL_MAX, DBL_MAX, 0}, {1, 2, 2}};
    const swarp_vec3 want[] = {{1, 0, 0}, {0.6, -0.8, 0}, {0.70710678118654752, 0.70710678118654752, 0}, {1.0 / 3, 2.0 / 3, 2.0 / 3}};
    for (int i = 0; i < 4; ++i) {
        swarp_vec3 u;
        ck_assert(sw_normalize_fast(in[i], &u));
        /* 3e-320 and 4e-320 are subnormals: rounded to 2^-1074 steps, 0.6 to 1e-5 */
        const double tol = i == 1 ? 1e-5 : 4 * DBL_EPSILON;
        ck_assert_msg(fabs(u.x - want[i].x) <= tol && fabs(u.y - want[i].y) <= tol && fabs(u.z - want[i].z) <= tol,
                      "case %d: (%.17g %.17g %.17g)", i, u.x, u.y, u.z);
    }
    const swarp_vec3 bad[] = {{0, 0, 0}, {NAN, 1e-300, 0}, {1e-300, 0, NAN}, {INFINITY, 0, 0}, {NAN, 1, 0}};
    for (int i = 0; i < 5; ++i) {
        swarp_vec3 u = {7, 7, 7};
        ck_assert_msg(!sw_normalize_fast(bad[i], &u), "bad case %d accepted", i);
        ck_assert(u.x == 7 && u.y == 7 && u.z == 7);
    }
}
END_TEST

START_TEST(random_configurations_all_properties) {
    rng R = {0x5EED0001ull + (uint64_t)_i};
    sweep_stats st = {0};
    int n = getenv("SWARP_STRESS") ? 30000 : 1400;
    for (int i = 0; i < n; ++i) {
        config c;
        rnd_config(&R, &c, (i % 10 == 0) ? 1e5 : 0.0);
        for (int t = 0; t < N_TECHNIQUES; ++t)
            check_config_v(&R, &c, techniques[t], (i & 1) ? SWARP_DEPTH_ZERO_TO_ONE : SWARP_DEPTH_NEG_ONE_TO_ONE, &st,
                           i);
    }
    /* the sweep must exercise the properties, not skip them */
    ck_assert_msg(st.ok > st.total / 2, "too few successful setups: %ld of %ld", st.ok, st.total);
    ck_assert_msg(st.inside * 100 < st.total, "too many LIGHT_INSIDE_BODY: %ld", st.inside);
    ck_assert(st.cover_checked > 10 * st.ok && st.extr_checked > st.ok);
    ck_assert_msg(st.inverse > 50, "the PSM inverse projection was hardly exercised: %ld", st.inverse);
    fprintf(stderr, "sweep %d: %ld setups, %ld ok, %ld empty, %ld light inside, %ld coverage, %ld extrusion points, %ld PSM inverse\n",
            _i, st.total, st.ok, st.empty, st.inside, st.cover_checked, st.extr_checked, st.inverse);
}
END_TEST

/* ---- model agreement: finite differences of the matrix vs [RHS] (2.3)-(2.8) */
static swarp_camera overhead_camera(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = v3(0, 10, 0);
    c.dir = v3(0, 0, -1);
    c.up = v3(0, 1, 0);
    c.fovy = 60 * DEG;
    c.aspect = 1920.0 / 1080.0;
    c.z_near = 1;
    c.z_far = 100;
    return c;
}

/* map position (texels) of a world point */
static void texel(const swarp_mat4* m, swarp_vec3 p, double res, double out[2]) {
    double c[4];
    clip(m, p, c);
    out[0] = 0.5 * res * c[0];
    out[1] = 0.5 * res * c[1];
}

START_TEST(model_agreement_overhead) {
    const swarp_technique techs[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_PSM};
    swarp_camera cam = overhead_camera();
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = v3(0, -1, 0);
    swarp_aabb box = {{-300, -100, -150}, {300, 100, 50}}; /* contains V: H = V */
    const double res = 2048, sw = 1920, sh = 1080;
    for (int t = 0; t < 3; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techs[t];
        o.param = SWARP_WARP_PARAM_NOPT; /* the closed form the model describes */
        o.map_width = o.map_height = (uint32_t)res;
        o.screen_width = (uint32_t)sw;
        o.screen_height = (uint32_t)sh;
        swarp_setup_result r;
        swarp_status s = swarp_setup(&cam, &light, &box, &o, &r, NULL, 0, NULL);
        ck_assert_msg(!swarp_status_is_error(s), "%s", swarp_status_name(s));
        ck_assert_double_eq_tol(r.view_near, 1.0, 1e-12);
        ck_assert_double_eq_tol(r.view_far, 100.0, 1e-9);
        if (techs[t] == SWARP_TECHNIQUE_LISPSM) ck_assert_double_eq_tol(r.n_eye, 1.0 + 10.0, 1e-9); /* n + sqrt(nf) */
        if (techs[t] == SWARP_TECHNIQUE_PSM) ck_assert_double_eq_tol(r.n_eye, 1.0, 1e-12);
        if (techs[t] == SWARP_TECHNIQUE_UNIFORM) ck_assert(isinf(r.n_eye));
        swarp_error_config cfg;
        memset(&cfg, 0, sizeof cfg);
        cfg.z_near = r.view_near;
        cfg.z_far = r.view_far;
        cfg.theta = 0.5 * cam.fovy;
        cfg.res_ix = sw;
        cfg.res_iy = sh;
        cfg.res_s = res;
        cfg.res_t = res;
        double worst = 0;
        for (int k = 0; k <= 60; ++k) {
            double z = 1.0 * pow(100.0, k / 60.0);
            if (z > 99.9) z = 99.9;
            if (z < 1.05) z = 1.05;
            swarp_vec3 p = add(cam.eye, scl(cam.dir, z));
            double h = 1e-4 * z;
            double a[2], b[2];
            /* along the view vector: m_z */
            texel(&r.matrix, add(p, scl(cam.dir, -h)), res, a);
            texel(&r.matrix, add(p, scl(cam.dir, h)), res, b);
            double dt = hypot(b[0] - a[0], b[1] - a[1]) / (2 * h); /* texels per world unit */
            double pixel_z = 2 * z * tan(cfg.theta) / sh;         /* world units per pixel */
            double mz_meas = (1.0 / dt) / pixel_z;
            double mz_model;
            ck_assert_int_eq(swarp_error_mz(&cfg, z, r.n_eye, &mz_model), SWARP_OK);
            /* across the view: m_x (camera right is world +x) */
            texel(&r.matrix, add(p, v3(-h, 0, 0)), res, a);
            texel(&r.matrix, add(p, v3(h, 0, 0)), res, b);
            double dx = hypot(b[0] - a[0], b[1] - a[1]) / (2 * h);
            double pixel_x = 2 * z * tan(cfg.theta) * cam.aspect / sw;
            double mx_meas = (1.0 / dx) / pixel_x, mx_model;
            ck_assert_int_eq(swarp_error_mx(&cfg, z, r.n_eye, &mx_model), SWARP_OK);
            double ez = fabs(mz_meas / mz_model - 1), ex = fabs(mx_meas / mx_model - 1);
            worst = fmax(worst, fmax(ez, ex));
            ck_assert_msg(ez < 0.01, "tech %d z %g: m_z measured %.6g model %.6g", (int)techs[t], z, mz_meas, mz_model);
            ck_assert_msg(ex < 0.01, "tech %d z %g: m_x measured %.6g model %.6g", (int)techs[t], z, mx_meas, mx_model);
        }
        /* the reported maxima are the model's maxima over [near, far] */
        double mx_max, mz_max;
        ck_assert_int_eq(swarp_error_max(&cfg, r.n_eye, &mx_max, &mz_max), SWARP_OK);
        ck_assert_double_eq_tol(r.max_mx, mx_max, 1e-12 * mx_max);
        ck_assert_double_eq_tol(r.max_mz, mz_max, 1e-12 * mz_max);
        fprintf(stderr, "model agreement tech %d: worst relative deviation %.2e\n", (int)techs[t], worst);
    }
}
END_TEST

/* ---- continuity: the light rotates through the whole circle in the plane
 * of the view direction and the camera's up vector, in 0.01° steps, through
 * parallel (light from behind) and antiparallel (looking into the light). */
static double mat_jump(const swarp_mat4* a, const swarp_mat4* b) {
    double na = 0, nb = 0, d = 0;
    for (int i = 0; i < 16; ++i) na += a->m[i] * a->m[i], nb += b->m[i] * b->m[i];
    na = sqrt(na), nb = sqrt(nb);
    for (int i = 0; i < 16; ++i) d = fmax(d, fabs(a->m[i] / na - b->m[i] / nb));
    return d;
}

static swarp_vec3 rotation_light(swarp_vec3 f, swarp_vec3 u, double deg) {
    double ang = deg * DEG;
    /* 90°: light travels along the view (from behind the camera);
     * 270°: light travels against the view (into the camera) */
    return add(scl(u, -cos(ang)), scl(f, sin(ang)));
}

START_TEST(continuity_light_rotation) {
    const swarp_technique techs[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_PSM};
    swarp_camera cam = overhead_camera();
    cam.dir = unit(v3(0, -0.2, -1)); /* looking slightly down onto the scene */
    swarp_aabb box = {{-300, -5, -150}, {300, 40, 50}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    swarp_vec3 f = unit(cam.dir), r = unit(cross(f, cam.up)), u = cross(r, f);
    for (int t = 0; t < 3; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techs[t];
        o.param = SWARP_WARP_PARAM_NOPT; /* the measured default is piecewise continuous only */
        o.skip_measure = 1; /* the matrix is what must be continuous; 10^5 measurements add nothing */
        swarp_setup_result prev, cur;
        double worst = 0, worst_deg = 0, worst_refined = 0;
        int have_prev = 0, parallel_seen = 0, uniform_seen = 0, refined = 0, prev_k = 0, prev_zone = 0,
            zone_steps = 0;
        const int steps = 36000;
        for (int k = 0; k <= steps; ++k) {
            if (SW_UNDER_ASAN && k % 10 != 0 && abs(k - 9000) > 1000 && abs(k - 27000) > 1000) continue;
            light.direction = rotation_light(f, u, k * 0.01);
            swarp_status s = swarp_setup(&cam, &light, &box, &o, &cur, NULL, 0, NULL);
            ck_assert_msg(!swarp_status_is_error(s), "tech %d at %.2f°: %s", (int)techs[t], k * 0.01,
                          swarp_status_name(s));
            for (int i = 0; i < 16; ++i) ck_assert(isfinite(cur.matrix.m[i]));
            if (s == SWARP_INFO_LIGHT_PARALLEL || s == SWARP_INFO_WARP_UNIFORM) parallel_seen++;
            if (techs[t] == SWARP_TECHNIQUE_LISPSM && isinf(cur.n_eye)) uniform_seen++;
            /* Within the blend zone (sin γ < SWARP_FOCUS_BLEND_SIN at
             * either end of the step) the stateless rule turns the map to
             * B's minimum-area rectangle, which is not continuous (see
             * docs/geometry.md: swarp_setup_follow is the continuous
             * frame); continuity is asserted everywhere else. */
            const double sin_g = len(cross(f, unit(light.direction)));
            const int in_zone = sin_g < SWARP_FOCUS_BLEND_SIN || prev_zone;
            prev_zone = sin_g < SWARP_FOCUS_BLEND_SIN;
            if (have_prev && in_zone) zone_steps++;
            if (have_prev && !in_zone) {
                int dk = k - prev_k; /* 1, or 10 between the ASan windows */
                double j = mat_jump(&prev.matrix, &cur.matrix) / dk;
                if (j > worst) worst = j, worst_deg = k * 0.01;
                if (j > 0.01) {
                    /* steep: refine the step 100 times.  A continuous change
                     * shrinks with the step, a jump (flip) does not. */
                    swarp_setup_result a = prev, b;
                    double sub = 0;
                    for (int m = 1; m <= 100; ++m) {
                        light.direction = rotation_light(f, u, prev_k * 0.01 + m * dk * 0.0001);
                        ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &box, &o, &b, NULL, 0, NULL)));
                        sub = fmax(sub, mat_jump(&a.matrix, &b.matrix) / dk);
                        a = b;
                    }
                    refined++;
                    worst_refined = fmax(worst_refined, sub / j);
                    ck_assert_msg(sub < 0.2 * j, "tech %d: change %g at %.2f° does not shrink when refined (%g)",
                                  (int)techs[t], j, k * 0.01, sub);
                }
            }
            prev = cur;
            prev_k = k;
            have_prev = 1;
        }
        fprintf(stderr,
                "continuity tech %d: largest normalised change per 0.01° step %.3g at %.2f°; %d steep steps refined, "
                "worst sub-step/step ratio %.3g\n",
                (int)techs[t], worst, worst_deg, refined, worst_refined);
        /* no flips: a flip changes normalised entries by O(1) */
        ck_assert_msg(worst < 0.5, "tech %d: jump %g at %.2f°", (int)techs[t], worst, worst_deg);
        if (techs[t] != SWARP_TECHNIQUE_PSM) ck_assert_msg(worst < 0.01, "tech %d: change %g", (int)techs[t], worst);
        if (techs[t] != SWARP_TECHNIQUE_PSM) ck_assert(parallel_seen > 0);
        ck_assert(zone_steps > 0 && zone_steps < steps / 4); /* the exemption is the zone, not the sweep */
        if (techs[t] == SWARP_TECHNIQUE_LISPSM) ck_assert(uniform_seen > 0);
    }
}
END_TEST

/* ---- the map's rotation near parallel light ---------------------------------
 * Within the blend zone the light view's up is B's minimum-area rectangle
 * side.  Independent evaluation: the area of B's light-plane bounding
 * rectangle by brute force over 3600 rotations (0.025° apart over the 90°
 * a rectangle repeats in); the chosen rotation's area, computed from the
 * returned light view's own rows, is at most the brute-force minimum (the
 * exact minimum lies between two sampled angles, so it can only be lower).
 * Defining property: the rectangle area is minimal.  γ below 7.9°: from
 * sin γ = 0.8 sin 10° (7.99°) the up eases into v_perp (SW_MIN_AREA_EASE). */
static double light_plane_rect_area(swarp_vec3 x, swarp_vec3 y, const swarp_vec3* B, size_t nb) {
    double lx = INFINITY, hx = -INFINITY, ly = INFINITY, hy = -INFINITY;
    for (size_t i = 0; i < nb; ++i) {
        double px = dot(B[i], x), py = dot(B[i], y);
        lx = fmin(lx, px), hx = fmax(hx, px), ly = fmin(ly, py), hy = fmax(hy, py);
    }
    return (hx - lx) * (hy - ly);
}

/* the ground receivers' worst σ of a matrix: a 1 m grid on the floor of the
 * box, inside the view frustum and the map, normal +y */
static double ground_sigma(const swarp_camera* cam, const swarp_aabb* box, const swarp_mat4* M,
                           const swarp_measure_res* mr, int* count) {
    swarp_vec3 f = unit(cam->dir), r = unit(cross(f, cam->up)), u = cross(r, f);
    double th = tan(0.5 * cam->fovy), mx = 0.0;
    *count = 0;
    for (double px = box->min.x; px <= box->max.x; px += 1.0)
        for (double pz = box->min.z; pz <= box->max.z; pz += 1.0) {
            swarp_vec3 p = v3(px, box->min.y, pz), d = sub(p, cam->eye), n = v3(0, 1, 0);
            double z = dot(d, f);
            if (z < cam->z_near || z > cam->z_far || fabs(dot(d, u)) > z * th ||
                fabs(dot(d, r)) > z * th * cam->aspect)
                continue;
            swarp_texel_error e;
            ck_assert(!swarp_status_is_error(swarp_measure_points(cam, M, mr, &p, &n, 1, &e)));
            if (!(e.flags & SWARP_TEXEL_INSIDE)) continue;
            ++*count;
            mx = fmax(mx, e.sigma);
        }
    return mx;
}

/* camera 2 m above the floor of a 200 x 30 x 200 m box, fovy 60°, 4:3,
 * looking just below the horizon; the light at gamma_deg from the view
 * direction (anti: travelling toward the camera, the sun ahead) */
static void low_sun_case(double gamma_deg, int anti, swarp_camera* cam, swarp_aabb* box, swarp_light* light) {
    memset(cam, 0, sizeof *cam);
    cam->eye = v3(0, 2, 0);
    cam->dir = unit(v3(0, -0.05, -1));
    cam->up = v3(0, 1, 0);
    cam->fovy = 60 * DEG;
    cam->aspect = 1024.0 / 768.0;
    cam->z_near = 0.5;
    cam->z_far = 300;
    box->min = v3(-100, 0, -100);
    box->max = v3(100, 30, 100);
    swarp_vec3 f = cam->dir, u = unit(cross(cross(f, cam->up), f));
    double g = gamma_deg * DEG;
    memset(light, 0, sizeof *light);
    light->type = SWARP_LIGHT_DIRECTIONAL;
    light->direction = anti ? scl(add(scl(f, cos(g)), scl(u, sin(g))), -1.0) : sub(scl(f, cos(g)), scl(u, sin(g)));
}

START_TEST(parallel_light_rotation_is_min_area) {
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_UNIFORM;
    o.skip_measure = 1;
    uint64_t rng = 0x5eed21b;
    int checked = 0, turned = 0;
    for (int c = 0; c < 200; ++c) {
        swarp_camera cam;
        swarp_aabb box;
        swarp_light light;
        low_sun_case(7.9 * tu_uniform(&rng, 0.0, 1.0), tu_uniform(&rng, 0.0, 1.0) < 0.5, &cam, &box, &light);
        /* a random yaw and box shape: footprints whose best rectangle is not the view-aligned one */
        double yaw = 2 * SWARP_PI * tu_uniform(&rng, 0.0, 1.0);
        swarp_vec3 d = light.direction;
        light.direction = v3(d.x * cos(yaw) + d.z * sin(yaw), d.y, -d.x * sin(yaw) + d.z * cos(yaw));
        cam.dir = unit(v3(cam.dir.x * cos(yaw) + cam.dir.z * sin(yaw), cam.dir.y, -cam.dir.x * sin(yaw) + cam.dir.z * cos(yaw)));
        box.max.x = 20 + 180 * tu_uniform(&rng, 0.0, 1.0);
        box.min.z = -(20 + 180 * tu_uniform(&rng, 0.0, 1.0));
        swarp_setup_result res;
        swarp_vec3 B[SWARP_BODY_MAX_POINTS];
        size_t nb;
        swarp_status st = swarp_setup(&cam, &light, &box, &o, &res, B, SWARP_BODY_MAX_POINTS, &nb);
        ck_assert_msg(st == SWARP_INFO_LIGHT_PARALLEL, "case %d: %s", c, swarp_status_name(st));
        swarp_vec3 a = unit(light.direction), x = v3(res.light_view.m[0], res.light_view.m[4], res.light_view.m[8]),
                   y = v3(res.light_view.m[1], res.light_view.m[5], res.light_view.m[9]);
        double chosen = light_plane_rect_area(x, y, B, nb), best = INFINITY, aligned;
        swarp_vec3 e0 = unit(cross(a, v3(0.37, 0.55, 0.75))), e1 = cross(a, e0);
        for (int k = 0; k < 3600; ++k) {
            double t = k * (0.5 * SWARP_PI / 3600);
            swarp_vec3 ex = add(scl(e0, cos(t)), scl(e1, sin(t))), ey = cross(a, ex);
            best = fmin(best, light_plane_rect_area(ex, ey, B, nb));
        }
        /* 1e-12: the rounding of the rows and of the products above */
        ck_assert_msg(chosen <= best * (1 + 1e-12), "case %d: area %.17g > brute-force minimum %.17g", c, chosen, best);
        /* the view-aligned up v_perp (the rule it replaces, blend aside) is never better */
        swarp_vec3 vp = unit(sub(cam.dir, scl(a, dot(cam.dir, a))));
        aligned = light_plane_rect_area(cross(vp, a), vp, B, nb);
        ck_assert(chosen <= aligned * (1 + 1e-12));
        if (chosen < 0.99 * aligned) turned++;
        checked++;
    }
    ck_assert_int_eq(checked, 200);
    ck_assert_msg(turned > 10, "only %d cases where the rectangle is not the view-aligned one", turned);
}
END_TEST

/* The low sun 5° ahead and behind: the ground receivers' worst σ of the
 * uniform map is no worse than that of the view-aligned basis (up =
 * v_perp), built here independently: L from v_perp, A_fit by
 * swarp_focus_fit over the same B. */
START_TEST(parallel_light_ground_sigma_no_worse_than_view_aligned) {
    swarp_measure_res mr = {1024, 768, 1024, 1024};
    for (int anti = 0; anti < 2; ++anti) {
        swarp_camera cam;
        swarp_aabb box;
        swarp_light light;
        low_sun_case(5.0, anti, &cam, &box, &light);
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = SWARP_TECHNIQUE_UNIFORM;
        o.map_width = 1024;
        o.screen_width = 1024, o.screen_height = 768;
        swarp_setup_result res;
        swarp_vec3 B[SWARP_BODY_MAX_POINTS];
        size_t nb;
        ck_assert_int_eq(swarp_setup(&cam, &light, &box, &o, &res, B, SWARP_BODY_MAX_POINTS, &nb),
                         SWARP_INFO_LIGHT_PARALLEL);
        swarp_vec3 a = unit(light.direction), f = unit(cam.dir);
        swarp_vec3 vp = unit(sub(f, scl(a, dot(f, a)))), sx = cross(a, vp);
        swarp_mat4 L, A, M;
        memset(&L, 0, sizeof L);
        L.m[0] = sx.x, L.m[4] = sx.y, L.m[8] = sx.z;
        L.m[1] = vp.x, L.m[5] = vp.y, L.m[9] = vp.z;
        L.m[2] = -a.x, L.m[6] = -a.y, L.m[10] = -a.z;
        L.m[15] = 1;
        ck_assert_int_eq(swarp_focus_fit(&L, B, nb, NULL, 0, SWARP_DEPTH_DEFAULT, &A), SWARP_OK);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                double acc = 0;
                for (int k = 0; k < 4; ++k) acc += A.m[k * 4 + i] * L.m[j * 4 + k];
                M.m[j * 4 + i] = acc;
            }
        int n0, n1;
        double s_lib = ground_sigma(&cam, &box, &res.matrix, &mr, &n0), s_al = ground_sigma(&cam, &box, &M, &mr, &n1);
        fprintf(stderr, "gamma 5%s: ground sigma %.2f (view-aligned %.2f), %d points\n", anti ? " ahead" : " behind",
                s_lib, s_al, n0);
        ck_assert(n0 > 1000 && n1 == n0);
        /* 1e-9: the two matrices differ by the rounding of their rows */
        ck_assert_msg(s_lib <= s_al * (1 + 1e-9), "ground sigma %g worse than the view-aligned %g", s_lib, s_al);
    }
}
END_TEST

/* Exactly parallel and antiparallel light: finite matrices, no NaN, for
 * every technique (the rectangle rule's reference v_perp is zero there). */
START_TEST(parallel_light_exact_finite) {
    const swarp_technique techs[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_PSM};
    for (int anti = 0; anti < 2; ++anti)
        for (int t = 0; t < 3; ++t) {
            swarp_camera cam;
            swarp_aabb box;
            swarp_light light;
            low_sun_case(0.0, anti, &cam, &box, &light);
            light.direction = anti ? scl(cam.dir, -1.0) : cam.dir;
            swarp_setup_options o;
            memset(&o, 0, sizeof o);
            o.technique = techs[t];
            swarp_setup_result res;
            swarp_status st = swarp_setup(&cam, &light, &box, &o, &res, NULL, 0, NULL);
            ck_assert_msg(!swarp_status_is_error(st), "%d %d: %s", anti, t, swarp_status_name(st));
            for (int i = 0; i < 16; ++i) ck_assert(isfinite(res.matrix.m[i]) && isfinite(res.light_view.m[i]));
            ck_assert(isfinite(res.measured.max_sigma));
            /* the same input gives the same output */
            swarp_setup_result again;
            ck_assert_int_eq(swarp_setup(&cam, &light, &box, &o, &again, NULL, 0, NULL), st);
            ck_assert(memcmp(&again, &res, sizeof res) == 0);
        }
}
END_TEST

/* ---- hard cases --------------------------------------------------------- */
static config base_config(void) {
    config c;
    memset(&c, 0, sizeof c);
    c.cam = overhead_camera();
    c.cam.dir = unit(v3(0, -0.3, -1));
    c.light.type = SWARP_LIGHT_DIRECTIONAL;
    c.light.direction = unit(v3(0.3, -1, 0.2));
    c.box.min = v3(-200, -5, -300);
    c.box.max = v3(200, 30, 60);
    return c;
}

static void all_techniques_ok(const config* c, const char* what) {
    rng R = {42};
    sweep_stats st = {0};
    for (int t = 0; t < 3; ++t)
        for (int d = 1; d <= 2; ++d) check_config(&R, c, techniques[t], (swarp_depth_range)d, &st);
    ck_assert_msg(st.ok == st.total, "%s: %ld of %ld setups failed", what, st.total - st.ok, st.total);
}

START_TEST(hard_far_near_ratio_and_tiny_near) {
    config c = base_config();
    c.cam.z_near = 1e-3;
    c.cam.z_far = 1e3; /* f/n = 1e6 */
    c.box.min = v3(-2000, -5, -2000);
    c.box.max = v3(2000, 30, 2000);
    all_techniques_ok(&c, "f/n = 1e6, near = 1e-3");
    c.cam.z_near = 1e-3;
    c.cam.z_far = 50;
    all_techniques_ok(&c, "near = 1e-3");
}
END_TEST

START_TEST(hard_large_world) {
    for (int k = 0; k < 2; ++k) {
        double off = k ? 1e6 : 1e5;
        config c = base_config();
        swarp_vec3 o = v3(off, 0.25 * off, -off);
        c.cam.eye = add(c.cam.eye, o);
        c.box.min = add(c.box.min, o);
        c.box.max = add(c.box.max, o);
        all_techniques_ok(&c, "offset world");
        c.light.type = SWARP_LIGHT_POINT;
        c.light.position = add(o, v3(50, 400, -100));
        all_techniques_ok(&c, "offset world, point light");
    }
}
END_TEST

START_TEST(hard_flat_box) {
    config c = base_config();
    c.box.min.y = c.box.max.y = 0.0; /* zero height ground */
    all_techniques_ok(&c, "flat box");
    c.light.direction = v3(0, -1, 0);
    all_techniques_ok(&c, "flat box, overhead light");
    c.light.direction = v3(1, 0, 0); /* exactly grazing: B stays in the plane */
    all_techniques_ok(&c, "flat box, grazing light");
    /* the grazing B is the swept polygon: a ground point beyond H in the
     * light's direction lies in B */
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t np = 0;
    ck_assert_int_eq(swarp_body_points(&c.cam, c.cam.z_near, c.cam.z_far, &c.light, &c.box, pts, SWARP_BODY_MAX_POINTS, &np),
                     SWARP_OK);
    double xmin = INFINITY;
    for (size_t i = 0; i < np; ++i) {
        ck_assert(fabs(pts[i].y) < 1e-9);
        xmin = fmin(xmin, pts[i].x);
    }
    ck_assert_double_eq_tol(xmin, c.box.min.x, 1e-9); /* extruded to the box edge toward the light */
    c.light.type = SWARP_LIGHT_POINT;
    c.light.position = v3(-500, 0, -50); /* in the ground plane */
    all_techniques_ok(&c, "flat box, point light in its plane");
}
END_TEST

START_TEST(hard_camera_placement) {
    config c = base_config();
    /* inside the box */
    all_techniques_ok(&c, "camera inside");
    /* on the top face */
    c.cam.eye.y = c.box.max.y;
    all_techniques_ok(&c, "camera on a face");
    /* outside, looking at it */
    c.cam.eye = v3(0, 100, 200);
    c.cam.z_far = 600;
    c.cam.dir = unit(sub(v3(0, 0, -100), c.cam.eye));
    all_techniques_ok(&c, "camera outside");
    /* outside, looking away: H empty, its own status, outputs untouched */
    c.cam.dir = scl(c.cam.dir, -1.0);
    swarp_setup_result r, r0;
    memset(&r, 0x5A, sizeof r);
    r0 = r;
    swarp_vec3 pts[4] = {{1, 2, 3}}, pts0[4];
    memcpy(pts0, pts, sizeof pts);
    size_t np = 77;
    for (int t = 0; t < 3; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techniques[t];
        ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, pts, 4, &np), SWARP_ERR_BODY_EMPTY);
        ck_assert(memcmp(&r, &r0, sizeof r) == 0 && memcmp(pts, pts0, sizeof pts) == 0 && np == 77);
    }
    double n0 = -1, f0 = -1;
    ck_assert_int_eq(swarp_body_adjusted_range(&c.cam, &c.box, &n0, &f0), SWARP_ERR_BODY_EMPTY);
    ck_assert(n0 == -1 && f0 == -1);
}
END_TEST

START_TEST(hard_light_parallel_antiparallel) {
    config c = base_config();
    c.light.direction = c.cam.dir; /* exactly parallel: from behind the camera */
    all_techniques_ok(&c, "light parallel");
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = SWARP_TECHNIQUE_LISPSM;
    o.param = SWARP_WARP_PARAM_NOPT; /* n_opt grows monotonically toward parallel light */
    swarp_setup_result r;
    swarp_status s = swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL);
    ck_assert_int_eq(s, SWARP_INFO_WARP_UNIFORM); /* the warp faded */
    ck_assert(isinf(r.n_eye));
    c.light.direction = scl(c.cam.dir, -1.0); /* antiparallel: duelling frusta */
    all_techniques_ok(&c, "light antiparallel");
    s = swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL);
    ck_assert_int_eq(s, SWARP_INFO_WARP_UNIFORM);
    /* the fade is continuous: n' grows without bound as γ -> 0 */
    double prev = 0;
    for (int k = 1; k <= 6; ++k) {
        double g = pow(10.0, -k);
        c.light.direction = unit(add(c.cam.dir, scl(v3(1, 0, 0), tan(g))));
        ck_assert(!swarp_status_is_error(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL)));
        ck_assert_msg(r.n_eye >= prev, "gamma %g: n %g after %g", g, r.n_eye, prev);
        prev = r.n_eye;
    }
    ck_assert(prev > 1e4);
}
END_TEST

START_TEST(hard_point_light_positions) {
    config c = base_config();
    c.light.type = SWARP_LIGHT_POINT;
    /* omni light inside the view frustum: one perspective map cannot see
     * all around it: specific status, outputs untouched */
    c.light.position = add(c.cam.eye, scl(c.cam.dir, 20));
    swarp_setup_result r, r0;
    memset(&r, 0x33, sizeof r);
    r0 = r;
    for (int t = 0; t < 3; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techniques[t];
        ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL), SWARP_ERR_LIGHT_INSIDE_BODY);
        ck_assert(memcmp(&r, &r0, sizeof r) == 0);
        /* the point count is an output too: untouched on this error */
        swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
        size_t count = 12345;
        ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, pts, SWARP_BODY_MAX_POINTS, &count),
                         SWARP_ERR_LIGHT_INSIDE_BODY);
        ck_assert_uint_eq(count, 12345);
    }
    /* a spot inside the frustum pointing away from the camera: the spot's
     * pyramid keeps B in front of it; the apex region is cut (info) */
    c.light.cone_angle = 40 * DEG;
    c.light.direction = c.cam.dir;
    for (int t = 0; t < 2; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techniques[t];
        swarp_status s = swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL);
        ck_assert_msg(s == SWARP_OK || s == SWARP_INFO_LIGHT_NEAR_CLIPPED || s == SWARP_INFO_LIGHT_PARALLEL ||
                          s == SWARP_INFO_WARP_UNIFORM,
                      "%s", swarp_status_name(s));
        for (int i = 0; i < 16; ++i) ck_assert(isfinite(r.matrix.m[i]));
    }
    /* on the near plane (omni): the body surrounds the light's half space */
    c.light.cone_angle = 0;
    c.light.position = add(c.cam.eye, scl(c.cam.dir, c.cam.z_near));
    for (int t = 0; t < 3; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techniques[t];
        swarp_status s = swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL);
        ck_assert_msg(s == SWARP_ERR_LIGHT_INSIDE_BODY || !swarp_status_is_error(s), "%s", swarp_status_name(s));
        if (!swarp_status_is_error(s))
            for (int i = 0; i < 16; ++i) ck_assert(isfinite(r.matrix.m[i]));
    }
    /* above the scene: fine */
    c.light.position = v3(10, 300, -50);
    all_techniques_ok(&c, "point light above");
}
END_TEST

START_TEST(hard_degenerate_box) {
    config c = base_config();
    swarp_setup_result r;
    c.box.min = c.box.max = v3(0, 0, -10); /* zero-size box */
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_BOX_DEGENERATE);
    c.box.min = v3(0, 0, -10);
    c.box.max = v3(0, 0, 10); /* a segment */
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_BOX_DEGENERATE);
    c.box.max = v3(-1, 5, 10); /* inverted */
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_BOX_INVERTED);
}
END_TEST

/* every double of the inputs, poisoned with NaN, +inf and -inf */
START_TEST(bad_input_non_finite_and_null) {
    const double poison[3] = {NAN, INFINITY, -INFINITY};
    for (int pz = 0; pz < 3; ++pz) {
        for (int which = 0; which < 3; ++which) {
            config base = base_config();
            base.light.type = SWARP_LIGHT_POINT;
            base.light.position = v3(10, 300, -50);
            base.light.cone_angle = 30 * DEG;
            base.light.direction = v3(0, -1, 0);
            size_t nfields = which == 0 ? 13 : (which == 1 ? 7 : 6);
            for (size_t f = 0; f < nfields; ++f) {
                config c = base;
                double* d = which == 0 ? &c.cam.eye.x : (which == 1 ? &c.light.direction.x : &c.box.min.x);
                d[f] = poison[pz];
                swarp_setup_result r, r0;
                memset(&r, 0x7E, sizeof r);
                r0 = r;
                swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
                memset(pts, 0x11, sizeof pts);
                size_t np = 12345;
                swarp_status s = swarp_setup(&c.cam, &c.light, &c.box, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &np);
                ck_assert_msg(s == SWARP_ERR_NON_FINITE, "field %zu of %d: %s", f, which, swarp_status_name(s));
                ck_assert(memcmp(&r, &r0, sizeof r) == 0 && np == 12345);
                for (size_t i = 0; i < SWARP_BODY_MAX_POINTS; ++i) ck_assert(pts[i].x == pts[0].x);
            }
        }
    }
    config c = base_config();
    swarp_setup_result r;
    ck_assert_int_eq(swarp_setup(NULL, &c.light, &c.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_setup(&c.cam, NULL, &c.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, NULL, NULL, &r, NULL, 0, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, NULL, NULL, NULL, 0, NULL), SWARP_ERR_NULL_POINTER);
    /* zero vectors, bad fov, bad near/far, bad enums, reserved fields */
    config b = c;
    b.light.direction = v3(0, 0, 0);
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_ZERO_VECTOR);
    b = c;
    b.cam.dir = v3(0, 0, 0);
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_ZERO_VECTOR);
    b = c;
    b.cam.up = b.cam.dir;
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_DEGENERATE);
    b = c;
    b.cam.fovy = PI;
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_FOV);
    b = c;
    b.cam.z_far = b.cam.z_near;
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_NEAR_FAR);
    b = c;
    b.cam._reserved[2] = 1;
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_RESERVED_NONZERO);
    b = c;
    b.light.type = (swarp_light_type)7;
    ck_assert_int_eq(swarp_setup(&b.cam, &b.light, &b.box, NULL, &r, NULL, 0, NULL), SWARP_ERR_UNKNOWN_ENUM);
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = (swarp_technique)9;
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL), SWARP_ERR_UNKNOWN_ENUM);
    memset(&o, 0, sizeof o);
    o._reserved[0] = 1; /* the last reserved word */
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL), SWARP_ERR_RESERVED_NONZERO);
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_USER;
    o.n_user = -1;
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL), SWARP_ERR_OUT_OF_RANGE);
    o.n_user = NAN;
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, &o, &r, NULL, 0, NULL), SWARP_ERR_NON_FINITE);
    /* capacity: too small gives the needed count and leaves the rest alone */
    swarp_vec3 pts[2];
    size_t np = 0;
    ck_assert_int_eq(swarp_setup(&c.cam, &c.light, &c.box, NULL, &r, pts, 2, &np), SWARP_ERR_CAPACITY);
    ck_assert(np > 2 && np <= SWARP_BODY_MAX_POINTS);
}
END_TEST

/* ---- polyhedra ------------------------------------------------------------ */
static double plane_eval(const swarp_plane* p, swarp_vec3 v) { return p->a * v.x + p->b * v.y + p->c * v.z + p->d; }

/* structural invariants: faces on their planes, planes outward (every vertex
 * inside every plane), loops counter-clockwise, no near-duplicate vertices */
static void check_poly_invariants(const swarp_polyhedron* P) {
    double scale = 0;
    for (uint32_t i = 0; i < P->vertex_count; ++i)
        scale = fmax(scale, fmax(fabs(P->vertices[i].x), fmax(fabs(P->vertices[i].y), fabs(P->vertices[i].z))));
    double tol = 1e-9 * fmax(scale, 1e-300);
    for (uint32_t i = 0; i < P->vertex_count; ++i)
        for (uint32_t j = i + 1; j < P->vertex_count; ++j)
            ck_assert_msg(len(sub(P->vertices[i], P->vertices[j])) > SWARP_POLY_EPS_REL * scale, "near-duplicate");
    for (uint32_t f = 0; f < P->face_count; ++f) {
        const swarp_plane* pl = &P->planes[f];
        ck_assert_double_eq_tol(sqrt(pl->a * pl->a + pl->b * pl->b + pl->c * pl->c), 1.0, 1e-12);
        uint32_t n = P->face_vertex_count[f];
        ck_assert(n >= 3);
        swarp_vec3 nw = {0, 0, 0};
        for (uint32_t k = 0; k < n; ++k) {
            swarp_vec3 a = P->vertices[P->face_vertices[f][k]], b = P->vertices[P->face_vertices[f][(k + 1) % n]];
            ck_assert(fabs(plane_eval(pl, a)) < tol);
            nw = add(nw, cross(a, b));
        }
        ck_assert(dot(nw, v3(pl->a, pl->b, pl->c)) >= -tol * tol); /* CCW seen from outside */
        for (uint32_t i = 0; i < P->vertex_count; ++i) ck_assert(plane_eval(pl, P->vertices[i]) < tol);
    }
}

START_TEST(poly_clip_against_brute_force) {
    rng R = {777};
    for (int t = 0; t < 2000; ++t) {
        swarp_vec3 c = v3(rnd(&R, -10, 10), rnd(&R, -10, 10), rnd(&R, -10, 10));
        swarp_vec3 h = v3(rnd(&R, 0.1, 5), rnd(&R, 0.1, 5), rnd(&R, 0.1, 5));
        swarp_aabb box = {sub(c, h), add(c, h)};
        swarp_polyhedron P;
        ck_assert_int_eq(swarp_poly_from_aabb(&box, &P), SWARP_OK);
        ck_assert_int_eq(P.vertex_count, 8);
        ck_assert_int_eq(P.face_count, 6);
        check_poly_invariants(&P);
        swarp_plane planes[4];
        int np = 1 + (int)(rng_next(&R) % 4);
        for (int k = 0; k < np; ++k) {
            swarp_vec3 n = rnd_unit(&R);
            swarp_vec3 q = add(c, v3(rnd(&R, -1, 1) * h.x, rnd(&R, -1, 1) * h.y, rnd(&R, -1, 1) * h.z));
            planes[k] = (swarp_plane){n.x, n.y, n.z, -dot(n, q)};
            ck_assert_int_eq(swarp_poly_clip(&P, &planes[k], &P), SWARP_OK); /* in place */
            check_poly_invariants(&P);
        }
        /* brute force: a point of the box is in the result iff it satisfies
         * the planes (away from the boundary) */
        for (int m = 0; m < 50; ++m) {
            swarp_vec3 p = add(c, v3(rnd(&R, -1, 1) * h.x, rnd(&R, -1, 1) * h.y, rnd(&R, -1, 1) * h.z));
            double worst = -INFINITY;
            for (int k = 0; k < np; ++k) worst = fmax(worst, plane_eval(&planes[k], p));
            if (fabs(worst) < 1e-6) continue;
            int inside = P.vertex_count > 0 && P.face_count > 0;
            for (uint32_t f = 0; f < P.face_count && inside; ++f)
                if (plane_eval(&P.planes[f], p) > 1e-9) inside = 0;
            ck_assert_int_eq(inside, worst < 0);
        }
        /* every vertex of the result satisfies the planes and the box */
        for (uint32_t i = 0; i < P.vertex_count; ++i) {
            ck_assert(in_box(&box, P.vertices[i], 1e-9));
            for (int k = 0; k < np; ++k) ck_assert(plane_eval(&planes[k], P.vertices[i]) < 1e-9);
        }
    }
}
END_TEST

START_TEST(poly_camera_and_inverse_matrix_agree) {
    rng R = {99};
    for (int t = 0; t < 500; ++t) {
        config c;
        rnd_config(&R, &c, 0);
        swarp_polyhedron A, B;
        ck_assert_int_eq(swarp_poly_from_camera(&c.cam, &A), SWARP_OK);
        check_poly_invariants(&A);
        /* the inverse of an independently built GL view-projection */
        swarp_vec3 f = unit(c.cam.dir), r = unit(cross(f, c.cam.up)), u = cross(r, f);
        swarp_mat4 V = {{r.x, u.x, -f.x, 0, r.y, u.y, -f.y, 0, r.z, u.z, -f.z, 0, -dot(r, c.cam.eye), -dot(u, c.cam.eye),
                         dot(f, c.cam.eye), 1}};
        double ty = tan(0.5 * c.cam.fovy), n = c.cam.z_near, fa = c.cam.z_far;
        swarp_mat4 P = {{1 / (ty * c.cam.aspect), 0, 0, 0, 0, 1 / ty, 0, 0, 0, 0, -(fa + n) / (fa - n), -1, 0, 0,
                         -2 * fa * n / (fa - n), 0}};
        swarp_mat4 VP, inv;
        ck_assert_int_eq(swarp_mat4_mul(&P, &V, &VP), SWARP_OK);
        ck_assert_int_eq(swarp_mat4_invert(&VP, &inv), SWARP_OK);
        ck_assert_int_eq(swarp_poly_from_inverse_matrix(&inv, SWARP_DEPTH_NEG_ONE_TO_ONE, &B), SWARP_OK);
        ck_assert_int_eq(A.vertex_count, 8);
        ck_assert_int_eq(B.vertex_count, 8);
        for (uint32_t i = 0; i < 8; ++i) {
            double best = INFINITY;
            for (uint32_t j = 0; j < 8; ++j) best = fmin(best, len(sub(A.vertices[i], B.vertices[j])));
            ck_assert_msg(best < 1e-6 * fa, "corner %u off by %g", i, best);
            ck_assert(in_frustum(&c.cam, n, fa, A.vertices[i], 1e-9 * fa));
        }
    }
    swarp_polyhedron A;
    memset(&A, 0, sizeof A); /* unused slots are unspecified; memcmp below reads all bytes */
    swarp_plane zero = {0, 0, 0, 1}, nanp = {NAN, 0, 1, 0};
    swarp_aabb box = {{0, 0, 0}, {1, 1, 1}};
    ck_assert_int_eq(swarp_poly_from_aabb(&box, &A), SWARP_OK);
    swarp_polyhedron A0 = A;
    ck_assert_int_eq(swarp_poly_clip(&A, &zero, &A), SWARP_ERR_ZERO_VECTOR);
    ck_assert_int_eq(swarp_poly_clip(&A, &nanp, &A), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_poly_clip(NULL, &zero, &A), SWARP_ERR_NULL_POINTER);
    ck_assert(memcmp(&A, &A0, sizeof A) == 0);
    swarp_aabb inv = {{1, 0, 0}, {0, 1, 1}};
    ck_assert_int_eq(swarp_poly_from_aabb(&inv, &A), SWARP_ERR_BOX_INVERTED);
    ck_assert_int_eq(swarp_poly_clip_aabb(&A0, &inv, &A), SWARP_ERR_BOX_INVERTED);
}
END_TEST

/* [RHS] §3.3.1: adjusted near/far = min/max view depth over V ∩ S */
START_TEST(adjusted_range_brackets_samples) {
    rng R = {2024};
    int checked = 0;
    for (int t = 0; t < 600; ++t) {
        config c;
        rnd_config(&R, &c, 0);
        double n, f;
        swarp_status s = swarp_body_adjusted_range(&c.cam, &c.box, &n, &f);
        if (s == SWARP_ERR_BODY_EMPTY) continue;
        ck_assert_int_eq(s, SWARP_OK);
        ck_assert(n >= c.cam.z_near && f <= c.cam.z_far && n <= f);
        swarp_vec3 v = unit(c.cam.dir);
        double lo = INFINITY, hi = -INFINITY;
        for (int k = 0; k < 3000; ++k) {
            swarp_vec3 p = rnd_in_frustum(&R, &c.cam, c.cam.z_near, c.cam.z_far);
            if (!in_box(&c.box, p, 0)) continue;
            double z = dot(sub(p, c.cam.eye), v);
            lo = fmin(lo, z), hi = fmax(hi, z);
        }
        if (!(lo <= hi)) continue;
        double tol = 1e-9 * c.cam.z_far;
        ck_assert(lo >= n - tol && hi <= f + tol);
        checked++;
    }
    ck_assert(checked > 200);
}
END_TEST

START_TEST(focus_fit_maps_to_the_cube) {
    rng R = {31337};
    for (int t = 0; t < 500; ++t) {
        swarp_vec3 pts[20];
        for (int i = 0; i < 20; ++i) pts[i] = v3(rnd(&R, -50, 50), rnd(&R, -50, 50), rnd(&R, -50, 50));
        swarp_mat4 L = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
        L.m[3] = rnd(&R, -0.001, 0.001); /* a mild perspective, w stays > 0 */
        L.m[7] = rnd(&R, -0.001, 0.001);
        L.m[15] = 1.0;
        for (int d = 1; d <= 2; ++d) {
            swarp_mat4 A, AL;
            ck_assert_int_eq(swarp_focus_fit(&L, pts, 20, NULL, 0, (swarp_depth_range)d, &A), SWARP_OK);
            ck_assert_int_eq(swarp_mat4_mul(&A, &L, &AL), SWARP_OK);
            double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
            for (int i = 0; i < 20; ++i) {
                double cc[4];
                clip(&AL, pts[i], cc);
                for (int k = 0; k < 3; ++k) lo[k] = fmin(lo[k], cc[k]), hi[k] = fmax(hi[k], cc[k]);
            }
            ck_assert_double_eq_tol(lo[0], -1, 1e-12);
            ck_assert_double_eq_tol(hi[0], 1, 1e-12);
            ck_assert_double_eq_tol(lo[1], -1, 1e-12);
            ck_assert_double_eq_tol(hi[1], 1, 1e-12);
            ck_assert_double_eq_tol(lo[2], d == 2 ? 0 : -1, 1e-12);
            ck_assert_double_eq_tol(hi[2], 1, 1e-12);
        }
    }
    swarp_vec3 one = {1, 2, 3};
    swarp_mat4 I = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}, A;
    ck_assert_int_eq(swarp_focus_fit(&I, &one, 1, NULL, 0, SWARP_DEPTH_DEFAULT, &A), SWARP_INFO_FLAT_EXTENT);
    for (int i = 0; i < 16; ++i) ck_assert(isfinite(A.m[i]));
    ck_assert_int_eq(swarp_focus_fit(&I, &one, 1, NULL, 0, (swarp_depth_range)5, &A), SWARP_ERR_UNKNOWN_ENUM);
}
END_TEST

/* ---- light view and the LiSPSM warp called directly ----------------------- */
START_TEST(light_view_alignment) {
    rng R = {4242};
    int blended = 0, aligned = 0;
    for (int t = 0; t < 2000; ++t) {
        config c;
        rnd_config(&R, &c, 0);
        swarp_light light;
        memset(&light, 0, sizeof light);
        light.type = SWARP_LIGHT_DIRECTIONAL;
        light.direction = rnd_unit(&R);
        if (t % 10 == 0) light.direction = scl(unit(c.cam.dir), (t % 20) ? 1.0 : -1.0); /* exactly (anti)parallel */
        swarp_mat4 L;
        swarp_status s = swarp_focus_light_view(&c.cam, &light, NULL, &L);
        ck_assert(s == SWARP_OK || s == SWARP_INFO_LIGHT_PARALLEL);
        /* rigid, right-handed: rows orthonormal, det = +1 */
        swarp_vec3 r0 = v3(L.m[0], L.m[4], L.m[8]), r1 = v3(L.m[1], L.m[5], L.m[9]), r2 = v3(L.m[2], L.m[6], L.m[10]);
        ck_assert_double_eq_tol(dot(r0, r0), 1, 1e-12);
        ck_assert_double_eq_tol(dot(r1, r1), 1, 1e-12);
        ck_assert_double_eq_tol(dot(r0, r1), 0, 1e-12);
        ck_assert_double_eq_tol(dot(cross(r0, r1), r2), 1, 1e-12);
        /* looks along the light: -z row is the light direction */
        swarp_vec3 a = unit(light.direction);
        ck_assert_double_eq_tol(dot(r2, a), -1, 1e-12);
        /* the eye is the origin */
        double e[4];
        clip(&L, c.cam.eye, e);
        ck_assert(fabs(e[0]) + fabs(e[1]) + fabs(e[2]) < 1e-9 * fmax(1, len(c.cam.eye)));
        /* up = the view direction projected (outside the blend zone) */
        swarp_vec3 v = unit(c.cam.dir);
        swarp_vec3 vp = sub(v, scl(a, dot(v, a)));
        if (len(vp) > 0.1737) {
            ck_assert_int_eq(s, SWARP_OK);
            ck_assert_double_eq_tol(dot(r1, unit(vp)), 1, 1e-12);
            aligned++;
        } else {
            ck_assert_int_eq(s, SWARP_INFO_LIGHT_PARALLEL);
            blended++;
        }
    }
    ck_assert(aligned > 1000 && blended > 100);
}
END_TEST

START_TEST(warp_lispsm_direct) {
    /* overhead light, level camera, box containing V: n_opt = n + sqrt(n f)
     * in eye units, and P maps B's extent along y to [-1, 1] */
    swarp_camera cam = overhead_camera();
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = v3(0, -1, 0);
    swarp_aabb box = {{-300, -100, -150}, {300, 100, 50}};
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t np = 0;
    ck_assert_int_eq(swarp_body_points(&cam, 1, 100, &light, &box, pts, SWARP_BODY_MAX_POINTS, &np), SWARP_OK);
    size_t need = 0;
    ck_assert_int_eq(swarp_body_points(&cam, 1, 100, &light, &box, pts, 3, &need), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(need, np);
    swarp_mat4 L, P;
    ck_assert_int_eq(swarp_focus_light_view(&cam, &light, NULL, &L), SWARP_OK);
    swarp_warp_info info;
    for (int center = 1; center <= 2; ++center) {
        swarp_warp_options o;
        memset(&o, 0, sizeof o);
        o.center = (swarp_warp_center)center;
        swarp_vec3 e = add(cam.eye, v3(0, 0, -1)); /* a nearest vertex on the near plane axis */
        ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1, 100, pts, np, &e, &o, &P, &info), SWARP_OK);
        ck_assert_double_eq_tol(info.d, 99, 1e-9);
        ck_assert_double_eq_tol(info.z_0, 1, 1e-9);
        ck_assert_double_eq_tol(info.z_1, 100, 1e-9);
        ck_assert_double_eq_tol(info.n_eye, 11, 1e-9);
        ck_assert_double_eq_tol(info.gamma, PI / 2, 1e-12);
        swarp_mat4 PL;
        ck_assert_int_eq(swarp_mat4_mul(&P, &L, &PL), SWARP_OK);
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < np; ++i) {
            double cc[4];
            clip(&PL, pts[i], cc);
            ck_assert(cc[3] > 0);
            lo = fmin(lo, cc[1]), hi = fmax(hi, cc[1]);
        }
        ck_assert_double_eq_tol(lo, -1, 1e-12);
        ck_assert_double_eq_tol(hi, 1, 1e-12);
    }
    /* receivers: H itself for a directional light; H ∩ L for a spot */
    swarp_polyhedron Hh, Rr;
    ck_assert_int_eq(swarp_body_h(&cam, 1, 100, &box, &Hh), SWARP_OK);
    ck_assert_int_eq(swarp_body_receivers(&Hh, &light, &Rr), SWARP_OK);
    ck_assert_uint_eq(Rr.vertex_count, Hh.vertex_count);
    swarp_light spot;
    memset(&spot, 0, sizeof spot);
    spot.type = SWARP_LIGHT_POINT;
    spot.position = v3(0, 60, -50);
    spot.direction = v3(0, -1, 0);
    spot.cone_angle = 20 * DEG;
    ck_assert_int_eq(swarp_body_receivers(&Hh, &spot, &Rr), SWARP_OK);
    for (uint32_t i = 0; i < Rr.vertex_count; ++i) {
        swarp_vec3 q = sub(Rr.vertices[i], spot.position);
        /* inside the pyramid that circumscribes the cone: within atan(√2 tan 20°) */
        ck_assert(acos(fmin(1.0, -q.y / len(q))) <= atan(sqrt(2.0) * tan(20 * DEG)) + 1e-9);
        ck_assert(in_frustum(&cam, 1, 100, Rr.vertices[i], 1e-9));
    }
    spot.direction = v3(0, 1, 0); /* pointing away: lights nothing of H */
    ck_assert_int_eq(swarp_body_receivers(&Hh, &spot, &Rr), SWARP_ERR_BODY_EMPTY);
    /* a caller's n' = +inf is the uniform map */
    swarp_warp_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_USER;
    o.n_user = INFINITY;
    ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1, 100, pts, np, NULL, &o, &P, &info), SWARP_INFO_WARP_UNIFORM);
    ck_assert(P.m[3] == 0 && P.m[7] == 0 && P.m[11] == 0); /* no perspective row */
    /* bad input: untouched */
    swarp_mat4 P0 = P;
    pts[0].x = NAN;
    ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1, 100, pts, np, NULL, NULL, &P, &info), SWARP_ERR_NON_FINITE);
    ck_assert(memcmp(&P, &P0, sizeof P) == 0);
    pts[0].x = 0;
    o.param = (swarp_warp_param)17;
    ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 1, 100, pts, np, NULL, &o, &P, &info), SWARP_ERR_UNKNOWN_ENUM);
    ck_assert_int_eq(swarp_warp_lispsm(&L, &cam, 5, 1, pts, np, NULL, NULL, &P, &info), SWARP_ERR_NEAR_FAR);
}
END_TEST

/* [KOZ] §14.2.1: light behind the camera.  Casters behind the camera and
 * the receivers in front that they shadow land inside the map, and the
 * caster is nearer the light in depth (inverse projection, no slide-back),
 * also with the virtual slide-back option. */
START_TEST(psm_light_behind_camera) {
    swarp_camera cam = overhead_camera();
    cam.dir = unit(v3(0, -0.25, -1));
    swarp_aabb box = {{-100, 0, -120}, {100, 30, 60}}; /* reaches 60 units behind the camera */
    for (int deg = 5; deg <= 80; deg += 5) {
        for (int slide = 0; slide < 2; ++slide) {
            swarp_light light;
            memset(&light, 0, sizeof light);
            light.type = SWARP_LIGHT_DIRECTIONAL;
            /* travels forward and down: comes from behind the camera */
            light.direction = unit(add(scl(v3(0, 0, -1), cos(deg * DEG)), scl(v3(0, -1, 0), sin(deg * DEG))));
            swarp_setup_options o;
            memset(&o, 0, sizeof o);
            o.technique = SWARP_TECHNIQUE_PSM;
            o.psm_slideback = (uint32_t)slide;
            swarp_setup_result r;
            swarp_status s = swarp_setup(&cam, &light, &box, &o, &r, NULL, 0, NULL);
            ck_assert_msg(!swarp_status_is_error(s), "%d°: %s", deg, swarp_status_name(s));
            if (!slide) ck_assert_int_eq(s, SWARP_INFO_PSM_INVERSE);
            int behind = 0;
            rng R = {(uint64_t)deg};
            for (int k = 0; k < 400; ++k) {
                swarp_vec3 h = rnd_in_frustum(&R, &cam, cam.z_near, cam.z_far);
                if (!in_box(&box, h, 0)) continue;
                double ch[4];
                clip(&r.matrix, h, ch);
                ck_assert(in_clip(ch, SWARP_DEPTH_NEG_ONE_TO_ONE, 1e-9));
                /* walk back toward the light through the box */
                for (double t = 1; t < 400; t *= 1.7) {
                    swarp_vec3 p = sub(h, scl(light.direction, t));
                    if (!in_box(&box, p, 0)) break;
                    double cp[4];
                    clip(&r.matrix, p, cp);
                    ck_assert_msg(in_clip(cp, SWARP_DEPTH_NEG_ONE_TO_ONE, 1e-9), "%d°: caster outside the map", deg);
                    ck_assert_msg(cp[2] < ch[2] + 1e-12, "%d°: caster depth %.17g not before receiver %.17g", deg,
                                  cp[2], ch[2]);
                    if (dot(sub(p, cam.eye), unit(cam.dir)) < 0) behind++;
                }
            }
            ck_assert_msg(behind > 10, "%d°: too few casters behind the camera (%d)", deg, behind);
        }
    }
}
END_TEST

/* ---- scenes at the edges of the double range ------------------------------
 * Each scene's arguments are given at full precision; each pins that B maps
 * into the map (or the documented status) where the literal arithmetic
 * over- or underflows or loses B to rounding. */

/* Every point of B maps into the map: w > 0 and |x/w|, |y/w| <= 1 within
 * 1e-6, plus (cond != 0) the rounding of evaluating the world-space double
 * matrix at p (64 eps times its condition number, as tests/robust allows).
 * The scenes below are well conditioned and are checked without that term:
 * an ill-conditioned result (entries up to 1e15) is what the term alone
 * would excuse. */
static void check_b_inside_map_cond(const swarp_setup_result* r, const swarp_vec3* p, size_t n, const char* what,
                                 int cond) {
    for (size_t i = 0; i < n; ++i) {
        const double* m = r->matrix.m;
        double q[4], a[4];
        for (int k = 0; k < 4; ++k) {
            q[k] = m[k] * p[i].x + m[4 + k] * p[i].y + m[8 + k] * p[i].z + m[12 + k];
            a[k] = fabs(m[k] * p[i].x) + fabs(m[4 + k] * p[i].y) + fabs(m[8 + k] * p[i].z) + fabs(m[12 + k]);
        }
        ck_assert_msg(q[3] > 0, "%s: point %zu has w = %g", what, i, q[3]);
        double x = q[0] / q[3], y = q[1] / q[3];
        double kx = (a[0] + fabs(x) * a[3]) / q[3], ky = (a[1] + fabs(y) * a[3]) / q[3];
        double tol = 1e-6 + (cond ? 64 * DBL_EPSILON * fmax(kx, ky) : 0.0);
        ck_assert_msg(fabs(x) <= 1 + tol && fabs(y) <= 1 + tol, "%s: point %zu maps to (%g, %g), tolerance %g", what, i,
                      x, y, tol);
    }
}

static void check_b_inside_map(const swarp_setup_result* r, const swarp_vec3* p, size_t n, const char* what) {
    check_b_inside_map_cond(r, p, n, what, 0);
}

/* A flat box (zero depth in z) and a directional light within 1.2e-16 of its
 * plane: B's extent across the warp axis is rounding noise (1e-15), and a
 * warp dividing by it would put points of B at y = 4.  Flat: uniform across
 * it, the fit pads the extent. */
START_TEST(grazing_light_flat_box_maps_inside) {
    swarp_camera cam = {{2.5527718668437753, -0.80185209559958159, -12.101852857609369},
                        {0.95985551529399782, 0.28049490148609446, 0},
                        {0, 1, 0},
                        0.50105103680853991,
                        1.2815032501546098,
                        1.0000000000000002e-06,
                        10,
                        {0, 0, 0, 0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){-0.95985551529399793, -0.28049490148609452, 1.2246467991473532e-16};
    swarp_aabb box = {{-8.983287324592359, -2.2136621784064827, -12.101852857609369},
                      {80.440514357465887, 21.8681511655824, -12.101852857609369}};
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status st = swarp_setup(&cam, &light, &box, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    check_b_inside_map(&r, pts, n, "grazing light, flat box");
}
END_TEST

/* Eye at a 1e6 offset, near 1, far 2, light within 1e-9 of the view
 * direction: in world coordinates the body's light-space extent is a few
 * ulps of 1e6 (a point of B would map to y = 1.25), so it is computed
 * relative to the eye.  The frustum (aspect 1e-111) is flat and the light
 * 1e-9 rad off its plane, so B (H swept toward the light, 8 points since
 * H's two faces are opposite, src/geometry/poly.c) is 1e-9 thick as the light sees
 * it and the map would stretch that 2e9 times: relative to the eye B maps
 * inside to 1e-6, but the world matrix (the eye folded into its last
 * column) and B's world points, rounded to ulp(1e6) = 1e-10, would move
 * them by 0.2 in the map.  The fit pads the extent by that rounding
 * (sw_world_rounding_pad), so B's world points map inside to 1e-6 with no
 * allowance for the condition number, and the map at the origin differs
 * only in the padded rows: y and depth, whose scales it shrinks (a wider
 * window), while x (unpadded) is the same bit for bit.  An H with its
 * faces oriented alike would give B = H alone (4 points in H's plane,
 * whose rounding the matrix shares). */
START_TEST(large_offset_parallel_light_maps_inside) {
    swarp_camera cam = {{999988.91868873662, 0.23033861672625111, 999986.04749523092},
                        {0.41324454888588158, -0.23278984443987108, -0.88036232946541104},
                        {0, 1, 0},
                        1.448604677345914,
                        1.111418923391395e-111,
                        1,
                        2,
                        {0, 0, 0, 0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){0.4132445497911133, -0.23278984443987108, -0.88036232904049272};
    swarp_aabb box = {{999988.85216095881, -5.837741832916965, 999966.62847703311},
                      {999994.71205076785, 2.1788063412071512, 999989.8870028021}};
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.param = SWARP_WARP_PARAM_NOPT;
    o.center = SWARP_WARP_CENTER_NEAREST_VERTEX;
    o.pancake = 1;
    o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status st = swarp_setup(&cam, &light, &box, &o, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    check_b_inside_map(&r, pts, n, "1e6 offset, light parallel to the view");
    /* the same scene moved to the origin gives the same map (the library
     * works relative to the eye): equal matrices up to the translation, and
     * there B maps inside without the world's rounding */
    swarp_camera c0 = cam;
    c0.eye = (swarp_vec3){0, 0, 0};
    swarp_aabb b0 = {{box.min.x - cam.eye.x, box.min.y - cam.eye.y, box.min.z - cam.eye.z},
                     {box.max.x - cam.eye.x, box.max.y - cam.eye.y, box.max.z - cam.eye.z}};
    swarp_setup_result r0;
    swarp_vec3 p0[SWARP_BODY_MAX_POINTS];
    size_t n0 = 0;
    ck_assert_int_eq(swarp_setup(&c0, &light, &b0, &o, &r0, p0, SWARP_BODY_MAX_POINTS, &n0), st);
    ck_assert_uint_eq(n0, n);
    check_b_inside_map(&r0, p0, n0, "the same scene at the origin");
    /* light_proj = A P: row 0 (x) the same, rows 1 and 2 padded: the same
     * direction, a smaller scale */
    for (int c = 0; c < 3; ++c) {
        ck_assert(r.light_proj.m[4 * c] == r0.light_proj.m[4 * c]);
        for (int row = 1; row < 3; ++row) {
            const double a = r.light_proj.m[4 * c + row], b = r0.light_proj.m[4 * c + row];
            ck_assert_msg((a == 0 && b == 0) || (a * b > 0 && fabs(a) < fabs(b)), "row %d col %d: %g vs %g", row, c,
                          a, b);
        }
    }
}
END_TEST

/* far = DBL_MAX (or 1e308): the frustum's far corners overflow, yet the
 * arguments are valid (no SWARP_ERR_NON_FINITE).  H lies in S, so the far plane only
 * has to lie beyond S: the result equals that of far = 1e4. */
START_TEST(far_dbl_max_equals_finite_far) {
    swarp_camera cam = {{0, 10, 0}, {0, -0.3, -1}, {0, 1, 0}, 1.0, 1.5, 0.5, DBL_MAX, {0, 0, 0, 0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){0.3, -1, 0.2};
    swarp_aabb box = {{-200, -5, -300}, {200, 30, 60}};
    swarp_setup_result r, r4;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status st = swarp_setup(&cam, &light, &box, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    check_b_inside_map(&r, pts, n, "far = DBL_MAX");
    cam.z_far = 1e4;
    ck_assert_int_eq(swarp_setup(&cam, &light, &box, NULL, &r4, NULL, 0, NULL), st);
    ck_assert(fabs(r.view_far - r4.view_far) <= 1e-9 * r4.view_far && r.view_near == r4.view_near);
    /* a box wholly before the near plane: H is empty */
    cam.z_far = DBL_MAX;
    cam.z_near = 1e4;
    ck_assert_int_eq(swarp_setup(&cam, &light, &box, NULL, &r, NULL, 0, NULL), SWARP_ERR_BODY_EMPTY);
}
END_TEST

/* aspect = DBL_MAX: the frustum's corners would overflow (valid arguments
 * must not get SWARP_ERR_NON_FINITE); the half-angle is kept below
 * 90° - 1e-12 rad and B maps inside. */
START_TEST(aspect_dbl_max_maps_inside) {
    swarp_camera cam = {{0, 10, 0}, {0, -0.3, -1}, {0, 1, 0}, 1.0, DBL_MAX, 0.5, 300, {0, 0, 0, 0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){0.3, -1, 0.2};
    swarp_aabb box = {{-200, -5, -300}, {200, 30, 60}};
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status st = swarp_setup(&cam, &light, &box, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    check_b_inside_map(&r, pts, n, "aspect = DBL_MAX");
}
END_TEST

/* A view range of 1e-22..1e-21 at 100 units from the origin: B is far below
 * the resolution of world coordinates (all its points round to the eye) and
 * a world-space matrix (entries 1e22) would map it to w = 0: the documented
 * SWARP_ERR_DEGENERATE, outputs untouched. */
START_TEST(body_below_world_resolution_is_degenerate) {
    swarp_camera cam = {{100, 5, 100}, {1, 0.1, 0.3}, {0, 1, 0}, 1.0, 1.5, 0.5, 300, {0, 0, 0, 0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){0.3, -1, 0.2};
    swarp_aabb box = {{0, 0, 0}, {200, 10, 200}};
    swarp_setup_result r, sentinel;
    memset(&sentinel, 0xA5, sizeof sentinel);
    r = sentinel;
    swarp_status st = swarp_setup_range(&cam, &light, &box, 1e-22, 1e-21, NULL, &r, NULL, 0, NULL);
    ck_assert_msg(st == SWARP_ERR_DEGENERATE, "%s", swarp_status_name(st));
    ck_assert(memcmp(&r, &sentinel, sizeof r) == 0);
    /* a resolvable range at the same place still works */
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    st = swarp_setup_range(&cam, &light, &box, 1.0, 50.0, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    check_b_inside_map(&r, pts, n, "range [1, 50]");
}
END_TEST

/* A spot light at the eye: B's apex is the light itself (w = 0 there).
 * Documented: the points nearer than the light's near plane (distance below
 * light_near) are left out, status SWARP_INFO_LIGHT_NEAR_CLIPPED (or the
 * more important SWARP_INFO_WARP_UNIFORM); every other point is in the map. */
START_TEST(spot_light_at_eye_near_clipped) {
    swarp_camera cam = {{0, 10, 0}, {0, -0.3, -1}, {0, 1, 0}, 1.0, 1.5, 0.5, 300, {0, 0, 0, 0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_POINT;
    light.position = cam.eye;
    light.direction = (swarp_vec3){0, -0.3, -1};
    light.cone_angle = 0.9;
    swarp_aabb box = {{-200, -5, -300}, {200, 30, 60}};
    for (int on_near = 0; on_near < 2; ++on_near) {
        if (on_near) light.position = (swarp_vec3){0, 10 - 0.5 * 0.3 / sqrt(1.09), -0.5 / sqrt(1.09)};
        swarp_setup_result r;
        swarp_vec3 pts[SWARP_BODY_MAX_POINTS], kept[SWARP_BODY_MAX_POINTS];
        size_t n = 0, nk = 0, left = 0;
        swarp_status st = swarp_setup(&cam, &light, &box, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &n);
        ck_assert_msg(st == SWARP_INFO_LIGHT_NEAR_CLIPPED || st == SWARP_INFO_WARP_UNIFORM, "%s",
                      swarp_status_name(st));
        ck_assert(r.light_near > 0);
        for (size_t i = 0; i < n; ++i) {
            const double* v = r.light_view.m;
            double D = -(v[2] * pts[i].x + v[6] * pts[i].y + v[10] * pts[i].z + v[14]);
            if (D < r.light_near) ++left;
            else kept[nk++] = pts[i];
        }
        ck_assert(left >= 1 && nk >= 4);
        check_b_inside_map(&r, kept, nk, on_near ? "spot light on the near plane" : "spot light at the eye");
    }
}
END_TEST

static void add_extreme_scenes(Suite* s) {
    TCase* tc = tcase_create("extreme_scenes");
    tcase_add_test(tc, normalize_fast_range_and_nan);
    tcase_add_test(tc, grazing_light_flat_box_maps_inside);
    tcase_add_test(tc, large_offset_parallel_light_maps_inside);
    tcase_add_test(tc, far_dbl_max_equals_finite_far);
    tcase_add_test(tc, aspect_dbl_max_maps_inside);
    tcase_add_test(tc, body_below_world_resolution_is_degenerate);
    tcase_add_test(tc, spot_light_at_eye_near_clipped);
    suite_add_tcase(s, tc);
}

Suite* geometry_suite(void) {
    Suite* s = suite_create("geometry");
    TCase* tc = tcase_create("properties");
    tcase_set_timeout(tc, 600);
    tcase_add_loop_test(tc, random_configurations_all_properties, 0, 4);
    tcase_add_test(tc, model_agreement_overhead);
    tcase_add_test(tc, continuity_light_rotation);
    tcase_add_test(tc, parallel_light_rotation_is_min_area);
    tcase_add_test(tc, parallel_light_ground_sigma_no_worse_than_view_aligned);
    tcase_add_test(tc, parallel_light_exact_finite);
    tcase_add_test(tc, hard_far_near_ratio_and_tiny_near);
    tcase_add_test(tc, hard_large_world);
    tcase_add_test(tc, hard_flat_box);
    tcase_add_test(tc, hard_camera_placement);
    tcase_add_test(tc, hard_light_parallel_antiparallel);
    tcase_add_test(tc, hard_point_light_positions);
    tcase_add_test(tc, hard_degenerate_box);
    tcase_add_test(tc, bad_input_non_finite_and_null);
    tcase_add_test(tc, poly_clip_against_brute_force);
    tcase_add_test(tc, poly_camera_and_inverse_matrix_agree);
    tcase_add_test(tc, adjusted_range_brackets_samples);
    tcase_add_test(tc, focus_fit_maps_to_the_cube);
    tcase_add_test(tc, light_view_alignment);
    tcase_add_test(tc, warp_lispsm_direct);
    tcase_add_test(tc, psm_light_behind_camera);
    suite_add_tcase(s, tc);
    add_extreme_scenes(s);
    return s;
}

int main(void) {
    int failed = tu_run_suite(geometry_suite());
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
