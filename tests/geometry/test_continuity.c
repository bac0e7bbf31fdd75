/* Continuity over the whole sphere of light directions (docs/geometry.md,
 * "Continuity over the whole sphere"): swarp_setup_follow fed back its own
 * previous result along many light paths in 0.01° steps, through parallel and
 * antiparallel to the view, for uniform, LiSPSM (n_opt; n_repar and λ_GMNPR on
 * a subset) and PSM.  Also: previous = NULL is swarp_setup bit for bit, an
 * aligned previous frame gives exactly [RHS]'s LiSPSM (turned 180° for y = -v̂),
 * bad previous frames get their status with the outputs untouched, and the
 * stateless rule's singular point lies where the header and docs say.
 *
 * SWARP_CONT_TABLE=1 prints the per-path table of docs/geometry.md
 * (docs/plots/continuity_table.sh; SWARP_CONT_PATH=i: only path i). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* Under AddressSanitizer (about 20x slower) the walks take every 20th step
 * (the follow rule then sees 0.2° steps, still continuous: the refinement
 * checks run on the steep ones); the 0.01° walks run in the normal build. */

/* Check's ck_assert writes its location to a pipe on every call (15 million
 * writes for the walks): the hot loops use this, which only calls Check on
 * failure */
#define REQUIRE(cond, ...)                    \
    do {                                      \
        if (!(cond)) ck_abort_msg(__VA_ARGS__); \
    } while (0)

static swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static swarp_vec3 add(swarp_vec3 a, swarp_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static swarp_vec3 scl(swarp_vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static double dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static swarp_vec3 cross(swarp_vec3 a, swarp_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double len(swarp_vec3 a) { return sqrt(dot(a, a)); }
static swarp_vec3 unit(swarp_vec3 a) { return scl(a, 1.0 / len(a)); }

/* largest change of an entry of the matrices scaled to unit Frobenius norm
 * (the same measure as test_geometry.c's continuity test) */
static double mat_jump(const swarp_mat4* a, const swarp_mat4* b) {
    double na = 0, nb = 0, d = 0;
    for (int i = 0; i < 16; ++i) na += a->m[i] * a->m[i], nb += b->m[i] * b->m[i];
    na = sqrt(na), nb = sqrt(nb);
    for (int i = 0; i < 16; ++i) d = fmax(d, fabs(a->m[i] / na - b->m[i] / nb));
    return d;
}

static void clip(const swarp_mat4* m, swarp_vec3 p, double out[4]) {
    double h[4];
    for (int r = 0; r < 4; ++r) h[r] = m->m[r] * p.x + m->m[4 + r] * p.y + m->m[8 + r] * p.z + m->m[12 + r];
    out[0] = h[0] / h[3];
    out[1] = h[1] / h[3];
    out[2] = h[2] / h[3];
    out[3] = h[3];
}

/* the scene of test_geometry.c's continuity test: a camera looking slightly
 * down onto a wide, low box it stands in */
static swarp_camera scene_camera(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = v3(0, 10, 0);
    c.dir = unit(v3(0, -0.2, -1));
    c.up = v3(0, 1, 0);
    c.fovy = 60 * DEG;
    c.aspect = 1920.0 / 1080.0;
    c.z_near = 1;
    c.z_far = 100;
    return c;
}
static const swarp_aabb scene_box = {{-300, -5, -150}, {300, 40, 50}};

typedef struct basis { swarp_vec3 v, r, u; } basis;
static basis cam_basis(const swarp_camera* c) {
    basis b;
    b.v = unit(c->dir);
    b.r = unit(cross(b.v, c->up));
    b.u = cross(b.r, b.v);
    return b;
}

/* ---- the light paths --------------------------------------------------------
 * All in the camera's basis (v view, r right, u up); k is the step index
 * (0.01° of the path parameter per step). */
typedef enum path_kind { PATH_GREAT, PATH_AROUND_V, PATH_AROUND_R, PATH_SPIRAL } path_kind;
typedef struct path {
    path_kind kind;
    double param; /* great: azimuth of the circle about v; around v: offset
                     (negative: around -v); around r: polar angle from r */
    int steps;
    int stride; /* 0 or 1: every step; n: every n-th (0.01° n) */
} path;

static swarp_vec3 path_dir(const path* p, const basis* b, double k) {
    double t = k * 0.01 * DEG;
    switch (p->kind) {
        case PATH_GREAT: { /* through v (t = 0) and -v (t = 180°) */
            swarp_vec3 w = add(scl(b->u, cos(p->param * DEG)), scl(b->r, sin(p->param * DEG)));
            return add(scl(b->v, cos(t)), scl(w, sin(t)));
        }
        case PATH_AROUND_V: {
            double d = fabs(p->param) * DEG;
            swarp_vec3 c = p->param < 0 ? scl(b->v, -1.0) : b->v;
            swarp_vec3 w = add(scl(b->u, cos(t)), scl(b->r, sin(t)));
            return add(scl(c, cos(d)), scl(w, sin(d)));
        }
        case PATH_AROUND_R: {
            double d = p->param * DEG;
            swarp_vec3 w = add(scl(b->v, cos(t)), scl(b->u, sin(t)));
            return add(scl(b->r, cos(d)), scl(w, sin(d)));
        }
        case PATH_SPIRAL: { /* v to -v, three turns about v */
            double s = k / p->steps;
            double psi = PI * s, phi = 3.0 * 2.0 * PI * s;
            swarp_vec3 w = add(scl(b->u, cos(phi)), scl(b->r, sin(phi)));
            return add(scl(b->v, cos(psi)), scl(w, sin(psi)));
        }
    }
    return b->v;
}

static void path_name(const path* p, char* buf, size_t n) {
    switch (p->kind) {
        case PATH_GREAT: snprintf(buf, n, "great circle through v, azimuth %g°", p->param); break;
        case PATH_AROUND_V:
            snprintf(buf, n, "circle %g° around %s", fabs(p->param), p->param < 0 ? "-v" : "v");
            break;
        case PATH_AROUND_R: snprintf(buf, n, "circle %g° from r (around r)", p->param); break;
        case PATH_SPIRAL: snprintf(buf, n, "spiral v -> -v, 3 turns"); break;
    }
}

/* ---- the walk ---------------------------------------------------------------- */
typedef struct walk_stats {
    double worst;      /* largest normalised change per step */
    double worst_at;   /* its step (path parameter, degrees) */
    double worst_ratio;/* largest refined sub-step / step ratio */
    int refined;       /* steep steps refined */
    int flips;         /* of them, not shrinking (stateless table only) */
    long calls, lag, uniform, parallel, checked;
} walk_stats;

/* point_mode = 1: the light is an omni point light 1000 units from the eye,
 * opposite the path's direction (outside the box: its light axis, toward
 * the centre of B, turns with the path) */
static int point_mode = 0;
static void set_light(swarp_light* light, const swarp_camera* cam, swarp_vec3 d) {
    memset(light, 0, sizeof *light);
    light->type = point_mode ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
    light->direction = d;
    light->position = add(cam->eye, scl(d, -1000.0));
}

/* a step this steep (normalised change per 0.01° step) is refined 100× */
#define STEEP 2e-3

/* stateless = 1: swarp_setup instead (for the comparison table only) */
static int stateless_mode = 0;
static swarp_status follow(const swarp_camera* cam, const swarp_light* light, const swarp_setup_options* o,
                           const swarp_setup_result* prev, swarp_setup_result* out, swarp_vec3* pts,
                           size_t* npts) {
    if (stateless_mode) return swarp_setup(cam, light, &scene_box, o, out, pts, SWARP_BODY_MAX_POINTS, npts);
    return swarp_setup_follow(cam, light, &scene_box, o, NULL, prev, out, pts, SWARP_BODY_MAX_POINTS, npts);
}

/* coverage and tightness on the walk: every vertex of H = V ∩ S (the view
 * range used) maps inside the clip volume; the fitted points (B, for PSM H)
 * lie inside it too (depth included) and touch x, y = ±1 */
static void check_properties(const swarp_camera* cam, const swarp_setup_result* r, const swarp_vec3* pts,
                             size_t npts, swarp_technique tech, const char* where) {
    swarp_polyhedron H;
    REQUIRE(swarp_body_h(cam, r->view_near, r->view_far, &scene_box, &H) == SWARP_OK, "%s: H", where);
    double tol = 1e-9;
    for (uint32_t i = 0; i < H.vertex_count; ++i) {
        double c[4];
        clip(&r->matrix, H.vertices[i], c);
        REQUIRE(c[3] > 0 && fabs(c[0]) <= 1 + tol && fabs(c[1]) <= 1 + tol && fabs(c[2]) <= 1 + tol,
                      "%s: H vertex %u maps to %g %g %g (w %g)", where, i, c[0], c[1], c[2], c[3]);
    }
    const swarp_vec3* fp = tech == SWARP_TECHNIQUE_PSM ? H.vertices : pts;
    size_t nf = tech == SWARP_TECHNIQUE_PSM ? H.vertex_count : npts;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < nf; ++i) {
        double c[4];
        clip(&r->matrix, fp[i], c);
        for (int k = 0; k < 2; ++k) lo[k] = fmin(lo[k], c[k]), hi[k] = fmax(hi[k], c[k]);
        /* B (casters and receivers) inside the depth range too */
        REQUIRE(c[3] > 0 && fabs(c[2]) <= 1 + 1e-9, "%s: fitted point %zu at depth %g (w %g)", where, i, c[2], c[3]);
    }
    for (int k = 0; k < 2; ++k)
        REQUIRE(fabs(lo[k] + 1) < 1e-9 && fabs(hi[k] - 1) < 1e-9, "%s: axis %d spans [%.12g, %.12g]", where, k,
                      lo[k], hi[k]);
}

/* A steep step from `from` (state at step k0) over dk steps with change j:
 * refined 100 times, following through the sub-steps, then the steepest
 * sub-step refined 100 times again, up to three levels (10^-6 of the step);
 * j is the whole step's change.
 * A continuous change shrinks with the step: the largest sub-step change
 * falls below 0.2 j at some level (it stays at j only if all of it happens
 * within 10^-6 of the step).  A jump (flip) does not shrink at any level.
 * Returns the smallest (largest sub-step change)/j over the levels. */
static double refine(const path* p, const basis* b, const swarp_camera* cam, const swarp_setup_options* o,
                     const swarp_setup_result* from, int k0, int dk, double j) {
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    swarp_setup_result start = *from;
    double t0 = k0, h = dk / 100.0, best = INFINITY;
    for (int level = 0; level < 3; ++level) {
        swarp_setup_result a = start, c, worst_start = start;
        double sub = 0, worst_t = t0;
        for (int m = 1; m <= 100; ++m) {
            set_light(&light, cam, path_dir(p, b, t0 + m * h));
            { swarp_status fs = follow(cam, &light, o, &a, &c, NULL, NULL); REQUIRE(!swarp_status_is_error(fs), "refinement step failed: %s tech %d at %g", swarp_status_name(fs), (int)o->technique, t0 + m * h); }
            double js = mat_jump(&a.matrix, &c.matrix);
            if (js > sub) sub = js, worst_start = a, worst_t = t0 + (m - 1) * h;
            a = c;
        }
        best = fmin(best, sub / j);
        if (best < 0.2) break;
        start = worst_start;
        t0 = worst_t;
        h /= 100.0;
    }
    return best;
}

static void walk(const path* p, swarp_technique tech, swarp_warp_param param, walk_stats* st) {
    swarp_camera cam = scene_camera();
    basis b = cam_basis(&cam);
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.skip_measure = 1; /* the matrices' continuity, not their measurement */
    o.technique = tech;
    o.param = param;
    memset(st, 0, sizeof *st);
    swarp_setup_result prev, cur;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t npts = 0;
    char name[96], where[160];
    path_name(p, name, sizeof name);
    int have_prev = 0, prev_k = 0;
    int stride = getenv("SWARP_CONT_STRIDE") ? atoi(getenv("SWARP_CONT_STRIDE")) : SW_UNDER_ASAN ? 20 : 1;
    if (p->stride > 1) stride *= p->stride;
    if (stride < 1) stride = 1;
    for (int k = 0; k <= p->steps; ++k) {
        if (k % stride != 0 && k != p->steps) continue;
        set_light(&light, &cam, path_dir(p, &b, k));
        swarp_status s = follow(&cam, &light, &o, have_prev ? &prev : NULL, &cur, pts, &npts);
        snprintf(where, sizeof where, "tech %d param %d, %s, step %.2f°", (int)tech, (int)param, name, k * 0.01);
        REQUIRE(!swarp_status_is_error(s), "%s: %s", where, swarp_status_name(s));
        for (int i = 0; i < 16; ++i) REQUIRE(isfinite(cur.matrix.m[i]), "%s: not finite", where);
        st->calls++;
        if (s == SWARP_INFO_FOLLOW_LAG) st->lag++;
        if (s == SWARP_INFO_WARP_UNIFORM) st->uniform++;
        if (fabs(dot(light.direction, b.v)) > cos(1.0 * DEG)) st->parallel++;
        if (have_prev) {
            int dk = k - prev_k;
            double j = mat_jump(&prev.matrix, &cur.matrix) / dk;
            if (j > st->worst) st->worst = j, st->worst_at = k * 0.01;
            if (j > STEEP) {
                double ratio = refine(p, &b, &cam, &o, &prev, prev_k, dk, j * dk);
                st->refined++;
                st->worst_ratio = fmax(st->worst_ratio, ratio);
                if (ratio >= 0.2) st->flips++;
                REQUIRE(ratio < 0.2 || stateless_mode, "%s: change %g does not shrink when refined (ratio %g)", where,
                        j, ratio);
            }
        }
        if (k % 97 == 0 && !stateless_mode) {
            check_properties(&cam, &cur, pts, npts, tech, where);
            st->checked++;
        }
        prev = cur;
        prev_k = k;
        have_prev = 1;
    }
}

/* ---- the walks over the whole sphere ----------------------------------------- */
static const path paths[] = { /* 90° around v: the light perpendicular to the view */
    {PATH_GREAT, 0, 36000, 1},      {PATH_GREAT, 15, 36000, 1},   {PATH_GREAT, 30, 36000, 1},
    {PATH_GREAT, 45, 36000, 1},     {PATH_GREAT, 60, 36000, 1},   {PATH_GREAT, 75, 36000, 1},
    {PATH_GREAT, 90, 36000, 1},     {PATH_GREAT, 105, 36000, 1},  {PATH_GREAT, 120, 36000, 1},
    {PATH_GREAT, 135, 36000, 1},    {PATH_GREAT, 150, 36000, 1},  {PATH_GREAT, 165, 36000, 1},
    {PATH_AROUND_V, 0.5, 36000, 1}, {PATH_AROUND_V, 3, 36000, 1}, {PATH_AROUND_V, 10, 36000, 1},
    {PATH_AROUND_V, 30, 36000, 1},  {PATH_AROUND_V, 90, 36000, 1}, {PATH_AROUND_V, -0.5, 36000, 1}, {PATH_AROUND_V, -3, 36000, 1},
    {PATH_AROUND_V, -10, 36000, 1}, {PATH_AROUND_V, -30, 36000, 1}, {PATH_AROUND_R, 89, 36000, 1},
    {PATH_AROUND_R, 80, 36000, 1},  {PATH_AROUND_R, 60, 36000, 1}, {PATH_SPIRAL, 0, 72000, 1},
};
#define N_PATHS ((int)(sizeof paths / sizeof paths[0]))

typedef struct variant { swarp_technique tech; swarp_warp_param param; int subset; } variant;
/* LiSPSM (n_opt) and PSM walk all paths; uniform (the same light frame as
 * LiSPSM), n_repar and λ_GMNPR a subset: the great circles at 0° and 90°
 * (through the camera's up and right), the 3° circles and the spiral.
 * SWARP_STRESS=1 walks all paths for all of them. */
static const variant variants[] = {
    {SWARP_TECHNIQUE_UNIFORM, SWARP_WARP_PARAM_DEFAULT, 1}, {SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_NOPT, 0},
    {SWARP_TECHNIQUE_PSM, SWARP_WARP_PARAM_DEFAULT, 0},     {SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_NREPAR, 1},
    {SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_GMNPR, 1},
};
static int in_subset(const path* p) {
    return (p->kind == PATH_GREAT && (p->param == 0 || p->param == 90)) ||
           (p->kind == PATH_AROUND_V && fabs(p->param) == 3) || p->kind == PATH_SPIRAL;
}

/* Largest normalised change per 0.01° step.  Uniform and LiSPSM: the frame
 * turns by at most (κ + 1)Δ per step; test_geometry.c's single circle (no
 * lag) requires 0.01, the catch-up at κ after passing the view axis reaches
 * 0.012 (λ_GMNPR), hence 0.02 — a flip changes entries by O(1).  PSM: near
 * Q -> 1 the minimal cone's axis is steep but continuous (docs/geometry.md,
 * known limitations); as in test_geometry.c, < 0.5 and every steep step
 * must shrink when refined. */
#define MAX_STEP 0.02
#define MAX_STEP_PSM 0.5

static const swarp_technique all_techs_walk[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM,
                                                  SWARP_TECHNIQUE_PSM};

START_TEST(whole_sphere_walk) {
    const variant* va = &variants[_i];
    if (getenv("SWARP_CONT_TABLE") || (getenv("SWARP_CONT_VARIANT") && atoi(getenv("SWARP_CONT_VARIANT")) != _i))
        return;
    double worst = 0;
    long calls = 0, lag = 0;
    for (int i = 0; i < N_PATHS; ++i) {
        if (va->subset && !getenv("SWARP_STRESS") && !in_subset(&paths[i])) continue;
        walk_stats st;
        walk(&paths[i], va->tech, va->param, &st);
        char name[96];
        path_name(&paths[i], name, sizeof name);
        ck_assert_msg(st.worst < (va->tech == SWARP_TECHNIQUE_PSM ? MAX_STEP_PSM : MAX_STEP), "tech %d param %d, %s: change %g per step at %.2f°", (int)va->tech,
                      (int)va->param, name, st.worst, st.worst_at);
        ck_assert(st.checked > 0);
        worst = fmax(worst, st.worst);
        calls += st.calls;
        lag += st.lag;
    }
    fprintf(stderr, "whole-sphere walk tech %d param %d: %ld calls, largest change per 0.01° step %.3g, %ld lagging\n",
            (int)va->tech, (int)va->param, calls, worst, lag);
}
END_TEST

/* ---- point lights: the spiral and the great circle through v and r ---------- */
START_TEST(point_light_walk) {
    if (getenv("SWARP_CONT_TABLE")) return;
    /* 0.04° steps (the 0.01° walks above cover the frame logic; these add
     * the point light's own axis, the direction to the centre of B) */
    const path pp[2] = {{PATH_SPIRAL, 0, 72000, 4}, {PATH_GREAT, 90, 36000, 4}};
    point_mode = 1;
    for (int t = 0; t < 3; ++t)
        for (int i = 0; i < 2; ++i) {
            walk_stats st;
            walk(&pp[i], all_techs_walk[t], all_techs_walk[t] == SWARP_TECHNIQUE_LISPSM ? SWARP_WARP_PARAM_NOPT : SWARP_WARP_PARAM_DEFAULT, &st);
            fprintf(stderr, "point light, tech %d, path %d: largest change per step %.3g, %d refined, %ld lagging\n",
                    (int)all_techs_walk[t], i, st.worst, st.refined, st.lag);
            ck_assert_msg(st.worst < (all_techs_walk[t] == SWARP_TECHNIQUE_PSM ? MAX_STEP_PSM : MAX_STEP),
                          "point light tech %d path %d: %g at %.2f°", (int)all_techs_walk[t], i, st.worst, st.worst_at);
        }
    point_mode = 0;
}
END_TEST

/* ---- previous = NULL is swarp_setup, bit for bit ---------------------------- */
typedef struct rng { uint64_t s; } rng;
static double rnd(rng* r, double a, double b) { return tu_uniform(&r->s, a, b); }
static swarp_vec3 rnd_unit(rng* r) {
    for (;;) {
        swarp_vec3 v = v3(rnd(r, -1, 1), rnd(r, -1, 1), rnd(r, -1, 1));
        double l = len(v);
        if (l > 0.1 && l <= 1.0) return scl(v, 1.0 / l);
    }
}
static void rnd_config(rng* R, swarp_camera* cam, swarp_light* light) {
    *cam = scene_camera();
    cam->eye = v3(rnd(R, -100, 100), rnd(R, 1, 30), rnd(R, -100, 40));
    cam->dir = rnd_unit(R);
    if (fabs(cam->dir.y) > 0.95) cam->dir.y *= 0.5;
    cam->fovy = rnd(R, 20, 90) * DEG;
    memset(light, 0, sizeof *light);
    int kind = (int)rnd(R, 0, 4);
    light->type = kind == 0 ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
    light->direction = rnd_unit(R);
    light->position = v3(rnd(R, -200, 200), rnd(R, 200, 400), rnd(R, -200, 200));
}

static const swarp_technique all_techs[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM, SWARP_TECHNIQUE_PSM};

START_TEST(null_previous_is_setup_bitwise) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    rng R = {0xF0110001ull};
    int ok = 0;
    for (int i = 0; i < 600; ++i) {
        swarp_camera cam;
        swarp_light light;
        rnd_config(&R, &cam, &light);
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.skip_measure = 1; /* the matrices' continuity, not their measurement */
        o.technique = all_techs[i % 3];
        o.param = (swarp_warp_param)(i / 3 % 4);
        /* the measured search (the default) picks among discrete candidates:
         * continuous only piecewise (docs/parameters.md); n_opt is walked */
        if (o.param == SWARP_WARP_PARAM_DEFAULT) o.param = SWARP_WARP_PARAM_NOPT;
        swarp_setup_result a, b;
        swarp_vec3 pa[SWARP_BODY_MAX_POINTS], pb[SWARP_BODY_MAX_POINTS];
        size_t na = 7, nb = 7;
        memset(&a, 0x5A, sizeof a), memset(&b, 0x5A, sizeof b);
        memset(pa, 0x5A, sizeof pa), memset(pb, 0x5A, sizeof pb);
        swarp_status sa = swarp_setup(&cam, &light, &scene_box, &o, &a, pa, SWARP_BODY_MAX_POINTS, &na);
        swarp_status sb = swarp_setup_follow(&cam, &light, &scene_box, &o, NULL, NULL, &b, pb, SWARP_BODY_MAX_POINTS, &nb);
        ck_assert_int_eq(sa, sb);
        ck_assert(na == nb);
        ck_assert(memcmp(&a, &b, sizeof a) == 0);
        ck_assert(memcmp(pa, pb, sizeof pa) == 0);
        ok += !swarp_status_is_error(sa);
    }
    ck_assert_msg(ok > 300, "too few successful setups: %d", ok);
}
END_TEST

/* ---- an aligned previous frame gives exactly [RHS]'s LiSPSM ------------------
 * previous = swarp_setup's own result for the same configuration (Δ = 0)
 * with sin γ >= 0.3 (no blend): the followed frame is the aligned one and the
 * result equals swarp_setup's.  The same frame turned by 180° about the light
 * axis (rows 0 and 1 negated; PSM: its light camera's rows) is followed as
 * y = -v̂: σ = -1, and the result is swarp_setup's map turned 180°,
 * diag(-1, -1, 1, 1) times its matrix. */
static double rel_diff(const swarp_mat4* a, const swarp_mat4* b) {
    double n = 0, d = 0;
    for (int i = 0; i < 16; ++i) n = fmax(n, fabs(a->m[i])), d = fmax(d, fabs(a->m[i] - b->m[i]));
    return d / n;
}
static void turn180(swarp_mat4* m) { /* diag(-1, -1, 1, 1) · m */
    for (int c = 0; c < 4; ++c) m->m[c * 4 + 0] = -m->m[c * 4 + 0], m->m[c * 4 + 1] = -m->m[c * 4 + 1];
}

START_TEST(aligned_previous_is_lispsm) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    rng R = {0xF0110002ull};
    int checked = 0, turned = 0;
    for (int i = 0; i < 900; ++i) {
        swarp_camera cam;
        swarp_light light;
        rnd_config(&R, &cam, &light);
        if (light.type != SWARP_LIGHT_DIRECTIONAL) continue;
        double cg = dot(unit(cam.dir), light.direction);
        if (sqrt(fmax(0.0, 1 - cg * cg)) < 0.3) continue;
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.skip_measure = 1; /* the matrices' continuity, not their measurement */
        o.technique = all_techs[i % 3];
        o.param = (swarp_warp_param)(1 + i / 3 % 3); /* n_opt, n_repar, λ_GMNPR */
        swarp_setup_result ref, fol;
        swarp_status s = swarp_setup(&cam, &light, &scene_box, &o, &ref, NULL, 0, NULL);
        if (swarp_status_is_error(s)) continue;
        swarp_status sf = swarp_setup_follow(&cam, &light, &scene_box, &o, &cam, &ref, &fol, NULL, 0, NULL);
        ck_assert_msg(!swarp_status_is_error(sf), "%d: %s", i, swarp_status_name(sf));
        ck_assert_msg(rel_diff(&ref.matrix, &fol.matrix) < 1e-9, "%d tech %d: aligned follow differs by %g", i,
                      (int)o.technique, rel_diff(&ref.matrix, &fol.matrix));
        ck_assert(sf != SWARP_INFO_FOLLOW_LAG);
        checked++;
        /* the same frame turned 180° about the light axis */
        swarp_setup_result prev = ref;
        if (o.technique == SWARP_TECHNIQUE_PSM) turn180(&prev.light_proj);
        else
            for (int c = 0; c < 3; ++c) prev.light_view.m[c * 4] *= -1, prev.light_view.m[c * 4 + 1] *= -1;
        sf = swarp_setup_follow(&cam, &light, &scene_box, &o, NULL, &prev, &fol, NULL, 0, NULL);
        ck_assert(!swarp_status_is_error(sf));
        swarp_mat4 want = ref.matrix;
        turn180(&want);
        ck_assert_msg(rel_diff(&want, &fol.matrix) < 1e-9, "%d tech %d param %d: turned follow differs by %g", i,
                      (int)o.technique, (int)o.param, rel_diff(&want, &fol.matrix));
        ck_assert(fabs(fol.n_eye - ref.n_eye) <= 1e-9 * fabs(ref.n_eye) || (isinf(fol.n_eye) && isinf(ref.n_eye)));
        turned++;
    }
    ck_assert_msg(checked > 150 && turned == checked, "checked %d", checked);
}
END_TEST

/* ---- bad previous frames: a specific status, outputs untouched -------------- */
static void expect_bad(const swarp_setup_result* prev, const swarp_camera* prev_cam, swarp_technique tech,
                       swarp_status want, const char* what) {
    swarp_camera cam = scene_camera();
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = unit(v3(0.3, -1, 0.2));
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.skip_measure = 1; /* the matrices' continuity, not their measurement */
    o.technique = tech;
    swarp_setup_result out;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n;
    const double sentinel = -12345.678;
    tu_fill((double*)&out, sizeof out / sizeof(double), sentinel);
    tu_fill((double*)pts, 3 * SWARP_BODY_MAX_POINTS, sentinel);
    memcpy(&n, &sentinel, sizeof n);
    swarp_status s = swarp_setup_follow(&cam, &light, &scene_box, &o, prev_cam, prev, &out, pts, SWARP_BODY_MAX_POINTS, &n);
    ck_assert_msg(s == want, "%s (tech %d): %s, want %s", what, (int)tech, swarp_status_name(s), swarp_status_name(want));
    ck_assert_msg(tu_untouched((double*)&out, sizeof out / sizeof(double), sentinel), "%s: out touched", what);
    ck_assert_msg(tu_untouched((double*)pts, 3 * SWARP_BODY_MAX_POINTS, sentinel), "%s: points touched", what);
    ck_assert_msg(memcmp(&n, &sentinel, sizeof n) == 0, "%s: count touched", what);
}

START_TEST(bad_previous_frames) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    swarp_camera cam = scene_camera();
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = unit(v3(0.3, -1, 0.2));
    for (int t = 0; t < 3; ++t) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.skip_measure = 1; /* the matrices' continuity, not their measurement */
        o.technique = all_techs[t];
        swarp_setup_result good, p;
        ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &scene_box, &o, &good, NULL, 0, NULL)));
        p = good, p.light_view.m[5] = NAN;
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_NON_FINITE, "NaN in the up row");
        p = good, p.light_view.m[2] = INFINITY;
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_NON_FINITE, "Inf in the forward row");
        p = good, p.light_view.m[1] = p.light_view.m[5] = p.light_view.m[9] = 0.0;
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_ZERO_VECTOR, "zero up row");
        memset(&p, 0, sizeof p);
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_ZERO_VECTOR, "zeroed result");
        p = good;
        for (int c = 0; c < 3; ++c) p.light_view.m[c * 4 + 1] *= 1.01;
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_FOLLOW_FRAME, "up row of length 1.01");
        p = good;
        for (int c = 0; c < 3; ++c) {
            double x = p.light_view.m[c * 4];
            p.light_view.m[c * 4] = p.light_view.m[c * 4 + 1], p.light_view.m[c * 4 + 1] = x;
        }
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_FOLLOW_FRAME, "left-handed (rows swapped)");
        p = good, p.light_view.m[1] += 0.01;
        expect_bad(&p, NULL, all_techs[t], SWARP_ERR_FOLLOW_FRAME, "rows not orthogonal");
        swarp_camera bad_cam = cam;
        bad_cam.dir = v3(0, 0, 0);
        expect_bad(&good, &bad_cam, all_techs[t], SWARP_ERR_ZERO_VECTOR, "previous camera without direction");
        bad_cam = cam, bad_cam.fovy = NAN;
        expect_bad(&good, &bad_cam, all_techs[t], SWARP_ERR_NON_FINITE, "previous camera fovy NaN");
        if (all_techs[t] == SWARP_TECHNIQUE_PSM) {
            p = good, p.view_far = NAN;
            expect_bad(&p, NULL, all_techs[t], SWARP_ERR_NON_FINITE, "PSM: view_far NaN");
            p = good, p.n_eye = -1.0;
            expect_bad(&p, NULL, all_techs[t], SWARP_ERR_FOLLOW_FRAME, "PSM: negative near");
            p = good, p.light_proj.m[3] = INFINITY;
            expect_bad(&p, NULL, all_techs[t], SWARP_ERR_NON_FINITE, "PSM: Inf in light_proj");
            p = good;
            for (int c = 0; c < 4; ++c) p.light_proj.m[c * 4 + 2] = p.light_proj.m[c * 4 + 3] = 0.0;
            expect_bad(&p, NULL, all_techs[t], SWARP_ERR_ZERO_VECTOR, "PSM: no axis rows");
        }
    }
    /* the usual argument errors come first and are the same as swarp_setup's */
    swarp_setup_result good;
    ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &scene_box, NULL, &good, NULL, 0, NULL)));
    ck_assert_int_eq(swarp_setup_follow(NULL, &light, &scene_box, NULL, NULL, &good, &good, NULL, 0, NULL),
                     SWARP_ERR_NULL_POINTER);
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.skip_measure = 1; /* the matrices' continuity, not their measurement */
    o.technique = (swarp_technique)9;
    ck_assert_int_eq(swarp_setup_follow(&cam, &light, &scene_box, &o, NULL, &good, &good, NULL, 0, NULL),
                     SWARP_ERR_UNKNOWN_ENUM);
}
END_TEST

/* ---- the stateless rule's singular point is where the docs say --------------
 * swarp_setup's up = normalize(v_perp + w(sin γ) r_perp) vanishes on the
 * great circle through v and r where sin γ = w(sin γ) cos γ (v_perp and
 * r_perp are antiparallel there): γ from v toward r and γ from -v toward -r.  Found here by bisection of that scalar
 * equation; the header and docs/geometry.md say γ ≈ 5.6°, sin γ ≈ 0.097.
 * swarp_setup's up row turns by 180° across it within 1e-6°; the followed
 * frame on the same walk in 0.01° steps turns by less than 0.1° per step. */
static double blend_root(void) {
    double lo = 1e-9, hi = 10 * DEG;
    for (int i = 0; i < 200; ++i) {
        double g = 0.5 * (lo + hi), s = sin(g);
        double t = 1 - s / SWARP_FOCUS_BLEND_SIN;
        double f = s - SWARP_FOCUS_BLEND_WEIGHT * t * t * cos(g);
        if (f < 0) lo = g;
        else hi = g;
    }
    return 0.5 * (lo + hi);
}
static swarp_vec3 up_row(const swarp_mat4* m) { return v3(m->m[1], m->m[5], m->m[9]); }

START_TEST(stateless_singular_point_where_documented) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    double g = blend_root();
    ck_assert_msg(fabs(g / DEG - 5.6) < 0.05 && fabs(sin(g) - 0.097) < 0.0005, "root at %.4f°, sin %.5f", g / DEG,
                  sin(g));
    swarp_camera cam = scene_camera();
    basis b = cam_basis(&cam);
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.skip_measure = 1; /* the matrices' continuity, not their measurement */
    o.technique = SWARP_TECHNIQUE_UNIFORM;
    for (int anti = 0; anti < 2; ++anti) {
        /* the zeros: γ from v toward r, and γ from -v toward -r */
        swarp_vec3 c = anti ? scl(b.v, -1.0) : b.v;
        b.r = scl(b.r, anti ? -1.0 : 1.0);
        swarp_setup_result r0, r1;
        const double eps = 1e-6 * DEG;
        light.direction = add(scl(c, cos(g - eps)), scl(b.r, sin(g - eps)));
        ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &scene_box, &o, &r0, NULL, 0, NULL)));
        light.direction = add(scl(c, cos(g + eps)), scl(b.r, sin(g + eps)));
        ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &scene_box, &o, &r1, NULL, 0, NULL)));
        double flip = dot(up_row(&r0.light_view), up_row(&r1.light_view));
        ck_assert_msg(flip < -0.99, "%s: up rows across the root agree (%g)", anti ? "antiparallel" : "parallel", flip);
        /* ... and nowhere else on that circle near the axis: 0.5° away the
         * stateless frame is steady */
        light.direction = add(scl(c, cos(g + 0.5 * DEG)), scl(b.r, sin(g + 0.5 * DEG)));
        ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &scene_box, &o, &r0, NULL, 0, NULL)));
        light.direction = add(scl(c, cos(g + 0.51 * DEG)), scl(b.r, sin(g + 0.51 * DEG)));
        ck_assert(!swarp_status_is_error(swarp_setup(&cam, &light, &scene_box, &o, &r1, NULL, 0, NULL)));
        ck_assert(dot(up_row(&r0.light_view), up_row(&r1.light_view)) > 0.999);
        /* the followed frame through the same point, 0.01° steps from 3° before to 3° after */
        swarp_setup_result prev, cur;
        int have = 0;
        for (int k = -300; k <= 300; ++k) {
            double gk = g + k * 0.01 * DEG;
            light.direction = add(scl(c, cos(gk)), scl(b.r, sin(gk)));
            ck_assert(!swarp_status_is_error(
                swarp_setup_follow(&cam, &light, &scene_box, &o, NULL, have ? &prev : NULL, &cur, NULL, 0, NULL)));
            if (have)
                ck_assert_msg(dot(up_row(&prev.light_view), up_row(&cur.light_view)) > cos(0.1 * DEG),
                              "followed frame turns by %g° at step %d",
                              acos(dot(up_row(&prev.light_view), up_row(&cur.light_view))) / DEG, k);
            prev = cur, have = 1;
        }
    }
}
END_TEST

/* ---- the table of docs/geometry.md (SWARP_CONT_TABLE=1; not a check) -------
 * per path: stateless swarp_setup (LiSPSM n_opt) vs swarp_setup_follow
 * (uniform, LiSPSM n_opt, PSM): largest normalised change per 0.01° step;
 * for the stateless walk also the steps that do not shrink when refined to
 * 10^-6 of the step (flips); for the followed LiSPSM walk the share of
 * steps where the frame still turns toward v̂ (SWARP_INFO_FOLLOW_LAG). */
START_TEST(print_table) {
    if (!getenv("SWARP_CONT_TABLE")) return;
    printf("| path | stateless LiSPSM: largest step (flips) | stateless PSM | follow uniform | follow LiSPSM "
           "| follow PSM | follow LiSPSM lagging |\n|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < N_PATHS; ++i) {
        if (getenv("SWARP_CONT_PATH") && atoi(getenv("SWARP_CONT_PATH")) != i) continue;
        walk_stats sl, sp, fu, fl, fp;
        stateless_mode = 1;
        walk(&paths[i], SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_NOPT, &sl);
        walk(&paths[i], SWARP_TECHNIQUE_PSM, SWARP_WARP_PARAM_DEFAULT, &sp);
        stateless_mode = 0;
        walk(&paths[i], SWARP_TECHNIQUE_UNIFORM, SWARP_WARP_PARAM_DEFAULT, &fu);
        walk(&paths[i], SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_NOPT, &fl);
        walk(&paths[i], SWARP_TECHNIQUE_PSM, SWARP_WARP_PARAM_DEFAULT, &fp);
        char name[96];
        path_name(&paths[i], name, sizeof name);
        printf("| %s | %.3g (%d) | %.3g (%d) | %.3g | %.3g | %.3g | %.0f %% |\n", name, sl.worst, sl.flips, sp.worst,
               sp.flips, fu.worst, fl.worst, fp.worst, 100.0 * (double)fl.lag / (double)fl.calls);
        fflush(stdout);
    }
}
END_TEST

/* ---- PSM's steep, continuous regime (docs/geometry.md section 7) -------------
 * On the great circle through v at azimuth 30°, 30.27°-30.33° from v (the
 * light from behind the camera, the receivers' cone from the post-perspective
 * light nearly a hemisphere), the map's y scale (row 1 over row 0) changes
 * more than twofold: steep.  Yet it is continuous: the largest change per
 * step shrinks in proportion to the step around the steepest point
 * (10^-3° -> 10^-5° -> 10^-7°), it stays finite, and H maps inside the clip
 * volume. */
static double row_norm(const swarp_mat4* m, int r) {
    double n = 0;
    for (int c = 0; c < 4; ++c) n += m->m[c * 4 + r] * m->m[c * 4 + r];
    return sqrt(n);
}
START_TEST(psm_steep_but_continuous) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    const path gc30 = {PATH_GREAT, 30, 36000, 1};
    swarp_camera cam = scene_camera();
    basis b = cam_basis(&cam);
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.skip_measure = 1; /* the matrices' continuity, not their measurement */
    o.technique = SWARP_TECHNIQUE_PSM;
    swarp_light light;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t n;
    double k0 = 3027, h = 0.1, worst[3], lo = INFINITY, hi = 0;
    for (int level = 0; level < 3; ++level) {
        int m = level == 0 ? 60 : 100;
        swarp_setup_result a, c;
        set_light(&light, &cam, path_dir(&gc30, &b, k0));
        ck_assert(!swarp_status_is_error(follow(&cam, &light, &o, NULL, &a, NULL, NULL)));
        double next_k0 = k0;
        worst[level] = 0;
        for (int i = 1; i <= m; ++i) {
            set_light(&light, &cam, path_dir(&gc30, &b, k0 + i * h));
            swarp_status s = follow(&cam, &light, &o, &a, &c, pts, &n);
            REQUIRE(!swarp_status_is_error(s), "%s", swarp_status_name(s));
            for (int e = 0; e < 16; ++e) REQUIRE(isfinite(c.matrix.m[e]), "not finite");
            double j = mat_jump(&a.matrix, &c.matrix);
            if (j > worst[level]) worst[level] = j, next_k0 = k0 + (i - 1) * h;
            if (level == 0) {
                double ratio = row_norm(&c.matrix, 1) / row_norm(&c.matrix, 0);
                lo = fmin(lo, ratio), hi = fmax(hi, ratio);
                if (i % 10 == 0) check_properties(&cam, &c, pts, n, SWARP_TECHNIQUE_PSM, "psm steep");
            }
            a = c;
        }
        k0 = next_k0;
        h *= 0.01;
    }
    fprintf(stderr,
            "PSM steep regime: y/x scale from %.3g to %.3g (x%.2f) within 0.06°; largest change per 1e-3°, 1e-5°, "
            "1e-7° step: %.3g %.3g %.3g\n",
            lo, hi, hi / lo, worst[0], worst[1], worst[2]);
    ck_assert_msg(hi > 2 * lo, "not steep here: y/x scale %g..%g", lo, hi);
    ck_assert_msg(worst[1] < 0.05 * worst[0] && worst[2] < 0.05 * worst[1], "does not shrink: %g %g %g", worst[0],
                  worst[1], worst[2]);
}
END_TEST

/* ---- the camera turns under a fixed light ------------------------------------
 * With previous_cam the frame realigns as the view turns (Δ counts the view's
 * turn): after a 90° yaw in 0.1° steps with the sun 40° from the view it is
 * the aligned frame (up = ±v̂), turning by a bounded amount per step.
 * Without previous_cam only the light's motion counts: the frame keeps its
 * orientation (docs/geometry.md: pass the previous camera). */
START_TEST(camera_turns_under_fixed_light) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    swarp_camera cam = scene_camera();
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    basis b0 = cam_basis(&cam);
    light.direction = add(scl(b0.v, cos(40 * DEG)), scl(b0.u, -sin(40 * DEG)));
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.skip_measure = 1; /* the matrices' continuity, not their measurement */
    o.technique = SWARP_TECHNIQUE_LISPSM;
    for (int with_prev_cam = 0; with_prev_cam < 2; ++with_prev_cam) {
        swarp_camera c = cam, pc;
        swarp_setup_result prev, cur;
        ck_assert(!swarp_status_is_error(swarp_setup_follow(&c, &light, &scene_box, &o, NULL, NULL, &prev, NULL, 0, NULL)));
        swarp_vec3 up0 = up_row(&prev.light_view);
        for (int k = 1; k <= 900; ++k) {
            pc = c;
            double yaw = k * 0.1 * DEG; /* about world y */
            c.dir = v3(cam.dir.x * cos(yaw) + cam.dir.z * sin(yaw), cam.dir.y, -cam.dir.x * sin(yaw) + cam.dir.z * cos(yaw));
            swarp_status s = swarp_setup_follow(&c, &light, &scene_box, &o, with_prev_cam ? &pc : NULL, &prev, &cur, NULL, 0,
                                                NULL);
            ck_assert(!swarp_status_is_error(s));
            ck_assert_msg(dot(up_row(&prev.light_view), up_row(&cur.light_view)) > cos((SWARP_FOLLOW_KAPPA + 1) * 0.1 * DEG),
                          "turned too far at step %d", k);
            prev = cur;
        }
        basis b = cam_basis(&c);
        swarp_vec3 a = light.direction, vp = unit(add(b.v, scl(a, -dot(b.v, a))));
        if (with_prev_cam)
            ck_assert_msg(fabs(dot(up_row(&cur.light_view), vp)) > 1 - 1e-12, "not realigned: %.17g",
                          dot(up_row(&cur.light_view), vp));
        else
            ck_assert_msg(dot(up_row(&cur.light_view), up0) > 1 - 1e-12, "the frame moved without previous_cam");
    }
}
END_TEST

/* ---- swarp_focus_light_view_follow ------------------------------------------- */
START_TEST(light_view_follow_twin) {
    if (getenv("SWARP_CONT_TABLE")) return; /* table mode: only print_table */
    rng R = {0xF0110003ull};
    for (int i = 0; i < 300; ++i) { /* previous NULL: swarp_focus_light_view, byte for byte */
        swarp_camera cam;
        swarp_light light;
        rnd_config(&R, &cam, &light);
        swarp_mat4 a, b;
        memset(&a, 0x3C, sizeof a), memset(&b, 0x3C, sizeof b);
        swarp_status sa = swarp_focus_light_view(&cam, &light, NULL, &a);
        swarp_status sb = swarp_focus_light_view_follow(&cam, &light, NULL, NULL, NULL, &b);
        ck_assert_int_eq(sa, sb);
        ck_assert(memcmp(&a, &b, sizeof a) == 0);
    }
    /* through the stateless zero on the v-r circle and on to 30°, 0.01° steps */
    swarp_camera cam = scene_camera();
    basis b = cam_basis(&cam);
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    swarp_mat4 prev, cur;
    for (int k = 0; k <= 3000; ++k) {
        double g = k * 0.01 * DEG;
        light.direction = add(scl(b.v, cos(g)), scl(b.r, sin(g)));
        swarp_status s = swarp_focus_light_view_follow(&cam, &light, NULL, NULL, k ? &prev : NULL, &cur);
        ck_assert(!swarp_status_is_error(s));
        if (k) {
            double c = dot(up_row(&prev), up_row(&cur));
            ck_assert_msg(c > cos(0.1 * DEG), "turns %g° at %.2f°", acos(c) / DEG, k * 0.01);
        }
        prev = cur;
    }
    /* at 30° (sin γ > 1/κ) it is the aligned frame again: up = ±v̂ */
    swarp_vec3 a = light.direction, vp = unit(add(b.v, scl(a, -dot(b.v, a))));
    ck_assert_msg(fabs(dot(up_row(&cur), vp)) > 1 - 1e-12, "not aligned: %.17g", dot(up_row(&cur), vp));
    /* bad previous views: their status, output untouched */
    swarp_mat4 bad = cur, out;
    const double sentinel = -777.0;
    bad.m[5] = NAN;
    tu_fill(out.m, 16, sentinel);
    ck_assert_int_eq(swarp_focus_light_view_follow(&cam, &light, NULL, NULL, &bad, &out), SWARP_ERR_NON_FINITE);
    ck_assert(tu_untouched(out.m, 16, sentinel));
    memset(&bad, 0, sizeof bad);
    ck_assert_int_eq(swarp_focus_light_view_follow(&cam, &light, NULL, NULL, &bad, &out), SWARP_ERR_ZERO_VECTOR);
    ck_assert(tu_untouched(out.m, 16, sentinel));
    bad = cur;
    for (int c = 0; c < 3; ++c) bad.m[c * 4 + 2] *= 0.5;
    ck_assert_int_eq(swarp_focus_light_view_follow(&cam, &light, NULL, NULL, &bad, &out), SWARP_ERR_FOLLOW_FRAME);
    ck_assert(tu_untouched(out.m, 16, sentinel));
    ck_assert_int_eq(swarp_focus_light_view_follow(&cam, &light, NULL, NULL, &cur, NULL), SWARP_ERR_NULL_POINTER);
}
END_TEST

Suite* continuity_suite(void) {
    Suite* s = suite_create("continuity");
    TCase* tc = tcase_create("follow");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, null_previous_is_setup_bitwise);
    tcase_add_test(tc, aligned_previous_is_lispsm);
    tcase_add_test(tc, bad_previous_frames);
    tcase_add_test(tc, stateless_singular_point_where_documented);
    tcase_add_test(tc, light_view_follow_twin);
    tcase_add_test(tc, camera_turns_under_fixed_light);
    tcase_add_test(tc, psm_steep_but_continuous);
    tcase_add_loop_test(tc, whole_sphere_walk, 0, (int)(sizeof variants / sizeof variants[0]));
    tcase_add_test(tc, point_light_walk);
    tcase_add_test(tc, print_table);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) {
    int failed = tu_run_suite(continuity_suite());
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
