/* Coverage sweep: a success status means the map covers.  Its own seeded
 * generator over the input space the header declares valid (ordinary
 * scenes and the extreme classes: fovy and aspect at their limits, far
 * within 1e-9 of near, boxes with a face at 1e13..DBL_MAX, point and spot
 * lights near or at the eye, eyes 1e5..1e6 from the origin) calls
 * swarp_setup, swarp_setup_range and swarp_cascade_setup with every
 * technique; every non-error result is checked by coverage_check.h against
 * V ∩ S found by brute force in long double (not through the library's
 * clipper).  Prints each violation with its inputs in %a; exit 1 on any.
 *
 *   coverage [COUNT [SEED [K]]]  COUNT scenes (default 300), SEED (default 1);
 *                                K: replay only scene K of that sequence
 *
 * Also checks swarp_setup's view range lies in the camera's [near, far]. */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coverage_check.h"
#include "shadowwarp.h"
#include "test_util.h"

typedef struct cv_case {
    long index; /* in the seeded sequence: `coverage COUNT SEED index` replays it */
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
    swarp_setup_options o;
} cv_case;

static double cv_u(uint64_t* s, double a, double b) { return a + (b - a) * (double)cc_unif(s); }
static double cv_log(uint64_t* s, double a, double b) { return a * pow(b / a, (double)cc_unif(s)); }
static swarp_vec3 cv_dir(uint64_t* s) {
    swarp_vec3 d;
    do d = (swarp_vec3){cv_u(s, -1, 1), cv_u(s, -1, 1), cv_u(s, -1, 1)};
    while (d.x * d.x + d.y * d.y + d.z * d.z < 1e-2);
    return d;
}

/* the camera: ordinary, or one of the extreme classes */
static void cv_camera(uint64_t* s, swarp_camera* c) {
    memset(c, 0, sizeof *c);
    const unsigned k = (unsigned)(cc_next(s) % 8);
    const double off = k == 7 ? cv_log(s, 1e5, 1e6) : 0.0;
    c->eye = (swarp_vec3){cv_u(s, -20, 20) + off, cv_u(s, 0, 20), cv_u(s, -20, 20) - off};
    c->dir = cv_dir(s);
    c->up = (swarp_vec3){0, 1, 0};
    if (fabs(c->dir.y) > 0.99 * sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z))
        c->up = (swarp_vec3){1, 0, 0};
    c->fovy = cv_u(s, 0.3, 2.0);
    c->aspect = cv_u(s, 0.5, 2.5);
    c->z_near = cv_log(s, 1e-2, 2);
    c->z_far = c->z_near * cv_log(s, 10, 1e4);
    if (k == 1) c->fovy = cv_log(s, 1e-9, 1e-3);
    if (k == 2) c->aspect = cc_next(s) & 1 ? cv_log(s, 1e-9, 1e-3) : cv_log(s, 1e3, 1e6);
    if (k == 3) c->z_far = c->z_near * (1 + cv_log(s, 1e-9, 1e-4));
    if (k == 4) c->fovy = cv_u(s, 2.5, 3.1);
}

/* the box around the camera's region; sometimes one face "unbounded" */
static void cv_box(uint64_t* s, const swarp_camera* c, swarp_aabb* b) {
    const double r = cv_log(s, 5, 300);
    const swarp_vec3 e = c->eye;
    b->min = (swarp_vec3){e.x - r * cv_u(s, 0.2, 1.5), -cv_u(s, 0.5, 5), e.z - r * cv_u(s, 0.2, 1.5)};
    b->max = (swarp_vec3){e.x + r * cv_u(s, 0.2, 1.5), cv_u(s, 1, 30), e.z + r * cv_u(s, 0.2, 1.5)};
    if (cc_next(s) % 5 == 0) {
        static const double big[] = {1e12, 1e13, 1e19, FLT_MAX, DBL_MAX};
        double* f = (cc_next(s) & 1) ? &b->max.x : &b->min.x;
        const int axis = (int)(cc_next(s) % 3);
        f[axis] = (f == &b->max.x ? 1 : -1) * big[cc_next(s) % 5];
    }
}

static void cv_light(uint64_t* s, const swarp_camera* c, const swarp_aabb* b, swarp_light* l) {
    memset(l, 0, sizeof *l);
    const unsigned k = (unsigned)(cc_next(s) % 6);
    l->direction = cv_dir(s);
    if (k < 3) {
        l->type = SWARP_LIGHT_DIRECTIONAL;
        if (l->direction.y > 0) l->direction.y = -l->direction.y;
        return;
    }
    l->type = SWARP_LIGHT_POINT;
    const double h = fmin(b->max.y, 1e3);
    l->position = (swarp_vec3){c->eye.x + cv_u(s, -50, 50), h + cv_log(s, 1, 500), c->eye.z + cv_u(s, -50, 50)};
    if (k == 4) { /* near or at the eye */
        const double r = cc_next(s) & 1 ? 0.0 : cv_log(s, 1e-3, 1);
        l->position = (swarp_vec3){c->eye.x + r * cv_u(s, -1, 1), c->eye.y + r * cv_u(s, -1, 1),
                                   c->eye.z + r * cv_u(s, -1, 1)};
        l->direction = c->dir;
    }
    if (k >= 4) l->cone_angle = cv_u(s, 0.2, 1.4);
}

static void cv_print_case(const char* fn, const cv_case* k, swarp_status st, const cc_result* r) {
    const swarp_camera* c = &k->cam;
    printf("FAIL scene %ld %s %s tech %d depth %d pancake %u: ", k->index, fn, swarp_status_name(st), (int)k->o.technique,
           (int)k->o.depth_range, k->o.pancake);
    if (r) cc_print(stdout, r);
    printf("\n  eye %a %a %a dir %a %a %a up %a %a %a fovy %a aspect %a near %a far %a\n", c->eye.x, c->eye.y,
           c->eye.z, c->dir.x, c->dir.y, c->dir.z, c->up.x, c->up.y, c->up.z, c->fovy, c->aspect, c->z_near,
           c->z_far);
    printf("  light type %d dir %a %a %a pos %a %a %a cone %a\n  box %a %a %a  %a %a %a\n", (int)k->light.type,
           k->light.direction.x, k->light.direction.y, k->light.direction.z, k->light.position.x,
           k->light.position.y, k->light.position.z, k->light.cone_angle, k->box.min.x, k->box.min.y, k->box.min.z,
           k->box.max.x, k->box.max.y, k->box.max.z);
}

typedef struct cv_stats { long calls, checked, failed; } cv_stats;

/* one checked map: the promise over V ∩ S for [zn, zf] */
static void cv_check_map(const cv_case* k, const char* fn, double zn, double zf, const swarp_mat4* m,
                         swarp_status st, uint64_t seed, cv_stats* S) {
    if (swarp_status_is_error(st)) return;
    S->checked++;
    const swarp_depth_range dr = k->o.depth_range;
    cc_result r = cc_check(&k->cam, zn, zf, &k->light, &k->box, m, dr, (int)k->o.pancake, st, 7, 9, 60, seed);
    if (!cc_ok(&r)) {
        S->failed++;
        cv_print_case(fn, k, st, &r);
    }
}

static void cv_run(const cv_case* k, uint64_t seed, cv_stats* S) {
    swarp_setup_result res;
    swarp_status st = swarp_setup(&k->cam, &k->light, &k->box, &k->o, &res, NULL, 0, NULL);
    S->calls++;
    cv_check_map(k, "swarp_setup", k->cam.z_near, k->cam.z_far, &res.matrix, st, seed, S);
    if (!swarp_status_is_error(st) && !(res.view_near >= k->cam.z_near && res.view_far <= k->cam.z_far)) {
        S->failed++;
        printf("view range [%a, %a] outside the camera's\n", res.view_near, res.view_far);
        cv_print_case("swarp_setup", k, st, NULL);
    }
    /* an explicit sub-range */
    const double zn = k->cam.z_near * cv_log(&seed, 1, 3), zf = fmin(k->cam.z_far, zn * cv_log(&seed, 1.5, 50));
    if (zf > zn) {
        st = swarp_setup_range(&k->cam, &k->light, &k->box, zn, zf, &k->o, &res, NULL, 0, NULL);
        S->calls++;
        cv_check_map(k, "swarp_setup_range", zn, zf, &res.matrix, st, seed, S);
    }
    swarp_cascade_options co;
    memset(&co, 0, sizeof co);
    co.setup = k->o;
    co.split.count = 1 + (uint32_t)(seed % 4);
    swarp_cascade_result cr;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t n = 0;
    st = swarp_cascade_setup(&k->cam, &k->light, &k->box, &co, &cr, sp, SWARP_CASCADE_MAX_SPLITS, &n);
    S->calls++;
    if (!swarp_status_is_error(st))
        for (size_t i = 0; i < n; ++i)
            cv_check_map(k, "swarp_cascade_setup", sp[i].z_near, sp[i].z_far, &sp[i].matrix, sp[i].status, seed, S);
    /* the stabilised cascades (uniform maps of a directional light) */
    if (k->o.technique != SWARP_TECHNIQUE_UNIFORM || k->light.type != SWARP_LIGHT_DIRECTIONAL || k->o.pancake) return;
    for (int mode = SWARP_STABILIZE_SPHERE; mode <= SWARP_STABILIZE_LEVELS; ++mode) {
        co.stabilize.mode = (swarp_stabilize_mode)mode;
        st = swarp_cascade_setup(&k->cam, &k->light, &k->box, &co, &cr, sp, SWARP_CASCADE_MAX_SPLITS, &n);
        S->calls++;
        if (!swarp_status_is_error(st))
            for (size_t i = 0; i < n; ++i)
                if (sp[i].status != SWARP_INFO_SPLIT_NO_SCENE)
                    cv_check_map(k, mode == SWARP_STABILIZE_SPHERE ? "swarp_cascade_setup SPHERE"
                                                                   : "swarp_cascade_setup LEVELS",
                                 sp[i].z_near, sp[i].z_far, &sp[i].matrix, sp[i].status, seed, S);
    }
}

/* ---- pinned inputs, named by the property they pin ---- */

static swarp_camera cv_pin_camera(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = (swarp_vec3){0, 2, 0};
    c.dir = (swarp_vec3){0, -0.3, -1};
    c.up = (swarp_vec3){0, 1, 0};
    c.fovy = 1, c.aspect = 16.0 / 9, c.z_near = 1, c.z_far = 100;
    return c;
}

static void cv_pin_fail(long* fails, const char* name, const char* what, swarp_status st) {
    ++*fails;
    printf("FAIL %s: %s (%s)\n", name, what, swarp_status_name(st));
}

/* PSM refuses a frustum whose post-perspective space cannot hold the light
 * ray in double (the light at 1/tau ~ 1e9 there: fovy or aspect 1e-9, far
 * within 1e-9 of near); uniform and LiSPSM cover the same frusta, checked
 * independently.  Before the refusal PSM returned SWARP_OK with one light
 * ray spread over 0.119 / 0.0142 / 0.12 NDC. */
static void cv_pin_psm_extreme_frusta(long* fails) {
    swarp_light D;
    memset(&D, 0, sizeof D);
    D.type = SWARP_LIGHT_DIRECTIONAL;
    D.direction = (swarp_vec3){0.3, -1, 0.2};
    const swarp_aabb S0 = {{-50, -1, -200}, {50, 10, 50}};
    for (int which = 0; which < 3; ++which) {
        swarp_camera c = cv_pin_camera();
        if (which == 0) c.fovy = 1e-9;
        if (which == 1) c.aspect = 1e-9;
        if (which == 2) c.z_far = c.z_near * (1 + 1e-9);
        for (int t = 1; t <= 3; ++t) {
            swarp_setup_options o;
            memset(&o, 0, sizeof o);
            o.technique = (swarp_technique)t;
            swarp_setup_result r;
            memset(&r, 0x5a, sizeof r);
            const swarp_setup_result canary = r;
            swarp_status st = swarp_setup(&c, &D, &S0, &o, &r, NULL, 0, NULL);
            if (t == SWARP_TECHNIQUE_PSM) {
                if (st != SWARP_ERR_DEGENERATE) cv_pin_fail(fails, "psm_extreme_frustum_refused", "not refused", st);
                else if (memcmp(&r, &canary, sizeof r) != 0)
                    cv_pin_fail(fails, "psm_extreme_frustum_refused", "output written", st);
                continue;
            }
            if (swarp_status_is_error(st)) {
                cv_pin_fail(fails, "extreme_frustum_uniform_lispsm_covered", "refused", st);
                continue;
            }
            cc_result q = cc_check(&c, c.z_near, c.z_far, &D, &S0, &r.matrix, SWARP_DEPTH_NEG_ONE_TO_ONE, 0, st, 9,
                                   17, 200, 1);
            if (!cc_ok(&q)) {
                cv_pin_fail(fails, "extreme_frustum_uniform_lispsm_covered", "not covered", st);
                cc_print(stdout, &q);
                printf("\n");
            }
        }
    }
}

/* Cascades over a box "unbounded" toward the light (max.y = 1e19, FLT_MAX,
 * DBL_MAX, light straight down): stabilised (SPHERE, LEVELS), the depth
 * window stops 1e10 times the map's size toward the light, unstabilised
 * (NONE) each split's B stops 1e10 times its H's size, and every split says
 * so (SWARP_INFO_CASTERS_CLAMPED; before: SWARP_OK, stabilised with a
 * window 1e19 wide); the receivers and the casters up to there are covered
 * (the pancaking rule beyond).  With the bounded box (max.y = 10) no split
 * is clamped. */
static void cv_pin_stabilized_clamped(long* fails) {
    static const double top[] = {10, 1e19, FLT_MAX, DBL_MAX};
    swarp_light D;
    memset(&D, 0, sizeof D);
    D.type = SWARP_LIGHT_DIRECTIONAL;
    D.direction = (swarp_vec3){0, -1, 0};
    const swarp_camera c = cv_pin_camera();
    for (size_t b = 0; b < sizeof top / sizeof top[0]; ++b)
        for (int mode = SWARP_STABILIZE_NONE; mode <= SWARP_STABILIZE_LEVELS; ++mode) {
            swarp_aabb S = {{-50, -1, -200}, {50, 10, 50}};
            S.max.y = top[b];
            swarp_cascade_options co;
            memset(&co, 0, sizeof co);
            co.setup.technique = SWARP_TECHNIQUE_UNIFORM;
            co.split.count = 4;
            co.stabilize.mode = (swarp_stabilize_mode)mode;
            swarp_cascade_result cr;
            swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
            size_t n = 0;
            swarp_status st = swarp_cascade_setup(&c, &D, &S, &co, &cr, sp, SWARP_CASCADE_MAX_SPLITS, &n);
            if (swarp_status_is_error(st)) {
                cv_pin_fail(fails, "stabilized_unbounded_box_casters_clamped", "refused", st);
                continue;
            }
            for (size_t i = 0; i < n; ++i) {
                const swarp_status want = b == 0 ? SWARP_OK : SWARP_INFO_CASTERS_CLAMPED;
                if (sp[i].status != want && !(b == 0 && sp[i].status == SWARP_INFO_LEVEL_ABOVE_RANGE))
                    cv_pin_fail(fails, "stabilized_unbounded_box_casters_clamped", "split status", sp[i].status);
                cc_result q = cc_check(&c, sp[i].z_near, sp[i].z_far, &D, &S, &sp[i].matrix,
                                       SWARP_DEPTH_NEG_ONE_TO_ONE, 0, sp[i].status, 7, 9, 100, 1);
                if (!cc_ok(&q)) {
                    cv_pin_fail(fails, "stabilized_unbounded_box_casters_clamped", "not covered", sp[i].status);
                    cc_print(stdout, &q);
                    printf("\n");
                }
            }
        }
}

/* Two scenes of the sweep (seed 7) that returned success without covering
 * before their fix, replayed with every entry point and technique:
 * a cascade over a box with min.x = -FLT_MAX (the split's H, built
 * camera-relative and translated back, sat an ulp outside S, the sweep
 * fell back to 2 diag(S) = 7e38 and lost B's swept part: casters 0.2..0.3
 * depth windows out, SWARP_OK), and a frustum of aspect 5.7e4 in a box
 * with max.z = DBL_MAX (H clipped at DBL_MAX's scale: receivers 125 map
 * widths out, SWARP_INFO_FLAT_EXTENT), and PSM at fovy 1e-8 (1369
 * caster samples behind the light camera with SWARP_INFO_PSM_INVERSE; now
 * refused, uniform and LiSPSM cover). */
static void cv_pin_replayed_scenes(long* fails) {
    cv_case k[3];
    memset(k, 0, sizeof k);
    k[0].cam = (swarp_camera){{0x1.3e41a526bbad8p+2, 0x1.39d84a2dba63ep+4, 0x1.c6743fec50108p+3},
                              {0x1.9852cc59943ccp-1, 0x1.736a770effd8p-3, -0x1.1bc268991af6p-3},
                              {0, 1, 0},
                              0x1.dcec17f764a76p+0,
                              0x1.34960f1dedd29p+1,
                              0x1.2d29c41c58567p-4,
                              0x1.f23e5129af2dap+8,
                              {0}};
    k[0].light.type = SWARP_LIGHT_DIRECTIONAL;
    k[0].light.direction = (swarp_vec3){-0x1.02d5d43af6134p-2, -0x1.cafaf5f624096p-1, 0x1.404c06a3742p-4};
    k[0].box = (swarp_aabb){{-0x1.fffffep+127, -0x1.f55cb45860535p-1, -0x1.2fc30878fb484p+6},
                            {0x1.8abaa5ecb1781p+7, 0x1.d3c84ce1a01eep+1, 0x1.a19e146f9666bp+5}};
    k[1].cam = (swarp_camera){{0x1.b074634a61004p+3, 0x1.9cae86f7044efp+3, -0x1.13edd590f16e8p+4},
                              {0x1.7dc335e84b43p-4, 0x1.d280921171ebp-4, 0x1.6ab9f2ec3d478p-3},
                              {0, 1, 0},
                              0x1.9961599115a3dp+0,
                              0x1.bc20d3d52b549p+15,
                              0x1.095b63c2ece45p-1,
                              0x1.8c19e7f3d92a2p+11,
                              {0}};
    k[1].light.type = SWARP_LIGHT_DIRECTIONAL;
    k[1].light.direction = (swarp_vec3){0x1.6ffb18e800ae8p-1, -0x1.95937d2bc7ecep-1, 0x1.2655e164bf4cp-3};
    k[1].box = (swarp_aabb){{-0x1.17d2541844b44p+3, -0x1.12d50fc6eb118p+1, -0x1.944155966c4a4p+4},
                            {0x1.5d2cabc3b3b8cp+5, 0x1.3565fb858ae71p+3, 0x1.fffffffffffffp+1023}};
    k[2].cam = (swarp_camera){{-0x1.3fc129435f6b6p+4, 0x1.49364aa118896p+3, -0x1.2f4f1fa3b6df9p+4},
                              {-0x1.9d9f70aa4ef7ap-1, 0x1.adf9a793672bcp-2, -0x1.d2644779d7568p-2},
                              {0, 1, 0},
                              0x1.4faea3629e66ap-27,
                              0x1.cb986a31ad311p+0,
                              0x1.1bd51d0dd5287p-4,
                              0x1.2774d531c11adp+9,
                              {0}};
    k[2].light.type = SWARP_LIGHT_DIRECTIONAL;
    k[2].light.direction = (swarp_vec3){-0x1.ab6b45ef7cd58p-2, -0x1.32d03deea701cp-2, 0x1.4293382522a4cp-2};
    k[2].box = (swarp_aabb){{-0x1.1b2decf4bfd6p+5, -0x1.f458abfd7ac6cp+0, -0x1.af244a2d132fp+4},
                            {-0x1.a2aab569ad3acp+2, 0x1.a2c55fde41707p+4, -0x1.5a6fccfbea867p+3}};
    for (int i = 0; i < 3; ++i)
        for (int t = 1; t <= 3; ++t)
            for (int dr = 1; dr <= 2; ++dr) {
                k[i].index = -1 - i;
                k[i].o.technique = (swarp_technique)t;
                k[i].o.depth_range = (swarp_depth_range)dr;
                cv_stats S = {0, 0, 0};
                cv_run(&k[i], 12345, &S);
                if (S.failed) cv_pin_fail(fails, "replayed_scene_success_means_covered", "not covered", SWARP_OK);
                const int psm_refuses = i == 2 && t == SWARP_TECHNIQUE_PSM;
                if (psm_refuses && S.checked != 0) cv_pin_fail(fails, "replayed_psm_fovy_1e-8_refused", "computed", SWARP_OK);
                if (!psm_refuses && S.checked == 0) cv_pin_fail(fails, "replayed_scene_success_means_covered", "all refused", SWARP_OK);
            }
}

/* one pinned spot scene with pancaking: uniform and LiSPSM, both depth
 * ranges, SWARP_INFO_LIGHT_NEAR_CLIPPED and covered (the spot looks along
 * the view) */
static void cv_pin_spot_pancake(long* fails, const char* name, const swarp_camera* c, swarp_light* l,
                                const swarp_aabb* b) {
    l->type = SWARP_LIGHT_POINT;
    l->direction = c->dir;
    for (int t = SWARP_TECHNIQUE_UNIFORM; t <= SWARP_TECHNIQUE_LISPSM; ++t)
        for (int dr = 1; dr <= 2; ++dr) {
            swarp_setup_options o;
            memset(&o, 0, sizeof o);
            o.technique = (swarp_technique)t;
            o.depth_range = (swarp_depth_range)dr;
            o.pancake = 1;
            swarp_setup_result r;
            swarp_status st = swarp_setup(c, l, b, &o, &r, NULL, 0, NULL);
            if (st != SWARP_INFO_LIGHT_NEAR_CLIPPED) {
                cv_pin_fail(fails, name, "status", st);
                continue;
            }
            cc_result q = cc_check(c, c->z_near, c->z_far, l, b, &r.matrix, (swarp_depth_range)dr, 1, st, 9, 17, 400, 1);
            if (!cc_ok(&q)) {
                cv_pin_fail(fails, name, "not covered", st);
                cc_print(stdout, &q);
                printf("\n");
            }
        }
}

/* Pancaking with a spot light near the eye: the receivers H are cut at the
 * light's near plane like B, so the depth window starts at their section
 * by the plane.  Three scenes of the sweep (seed 7; a spot 0.43..0.76 from
 * the eye along the view axis, one of them 5.2e5 from the origin) whose
 * receivers just behind the plane were 1.3..31 depth windows in front of
 * the window when H's vertices in front of the plane were only dropped
 * (SWARP_INFO_LIGHT_NEAR_CLIPPED, uniform and LiSPSM); each is checked
 * with both techniques and both depth ranges. */
static void cv_pin_spot_pancake_receivers(long* fails) {
    swarp_camera c[3];
    swarp_light l[3];
    swarp_aabb b[3];
    memset(c, 0, sizeof c);
    memset(l, 0, sizeof l);
    c[0] = (swarp_camera){{0x1.f2ee0e3ded528p+1, 0x1.50881f9d3749ep+3, 0x1.82e4630993ac8p+3},
                          {0x1.801b343693a18p-1, -0x1.ad1c11efcdd6ep-1, -0x1.3631b28249a3p-4},
                          {0, 1, 0}, 0x1.f5719d2d6b6eap+0, 0x1.1282b46c75954p+1, 0x1.e77b962b82c75p-6,
                          0x1.2565ce2054218p+8, {0}};
    l[0].position = (swarp_vec3){0x1.00db2b047760bp+2, 0x1.3fd2edc49ee5bp+3, 0x1.86eec50541ea1p+3};
    l[0].cone_angle = 0x1.af5cbabea2926p-2;
    b[0] = (swarp_aabb){{-0x1.daf285078fe66p+5, -0x1.1f1368480b79p+2, -0x1.6a37255f9896cp+2},
                        {0x1.2a68f54f8cf5ep+5, 0x1.934ca9c0a7feep+4, 0x1.8a42761f7fb42p+4}};
    c[1] = (swarp_camera){{0x1.7cf245d70bb5p+3, 0x1.1e45b8c933816p+4, -0x1.3ff35140896bp+2},
                          {0x1.a9f620adb0b14p-2, -0x1.fce7fe997df04p-2, 0x1.67d10fe92519cp-1},
                          {0, 1, 0}, 0x1.d804f93b869a4p+0, 0x1.e13dfdd9ffce7p+0, 0x1.42d3cdfed459cp-6,
                          0x1.a4ab0c78d7592p+3, {0}};
    l[1].position = (swarp_vec3){0x1.76fc8073c04a5p+3, 0x1.1820dbaab5723p+4, -0x1.176c46cbc1ca8p+2};
    l[1].cone_angle = 0x1.1e7802dd609cep+0;
    b[1] = (swarp_aabb){{-0x1.3b20456fcab71p+6, -0x1.991fea1d35eabp+1, -0x1.0edac30c170eep+7},
                        {0x1.df01611be19dfp+7, 0x1.dc7598dd110dcp+4, 0x1.6f8a9564c19c9p+6}};
    c[2] = (swarp_camera){{0x1.fc81c7bf0c68p+18, 0x1.cec0682beef48p+3, -0x1.fc819f5f279c3p+18},
                          {0x1.da604e03c3c9ep-1, -0x1.c09850cc4bafp-3, 0x1.8a8ca6df40858p-3},
                          {0, 1, 0}, 0x1.10a364133432cp+0, 0x1.3f9bb299a21ecp+1, 0x1.57c17f60681fbp-4,
                          0x1.fbbd8c3197807p+5, {0}};
    l[2].position = (swarp_vec3){0x1.fc81e0ed7dc22p+18, 0x1.cfcb67df2e22cp+3, -0x1.fc81aa6428237p+18};
    l[2].cone_angle = 0x1.603cb332ecb7cp-2;
    b[2] = (swarp_aabb){{0x1.fc7d726f33e86p+18, -0x1.2b1fe85d4bcbcp+2, -0x1.fc8a2e5ccbc1ep+18},
                        {0x1.fc8811adcb8d9p+18, 0x1.337e416b76a9ap+4, -0x1.fc7eba54a1bc2p+18}};
    for (int i = 0; i < 3; ++i) cv_pin_spot_pancake(fails, "spot_pancake_receivers_in_depth_range", &c[i], &l[i], &b[i]);
}

/* Pancaking with a spot at the eye and far within 2.1e-9 of near: the
 * receivers' depth range along the axis (1.9e-11, 2.7e-11) is far below what
 * the world matrix resolves (1e6 times 192 eps of the coordinates' ~20), so
 * the window is B's cut.  Two scenes of the sweep (seed 7; one under a box
 * with max.z = 1e19) whose receivers were up to 7.5e-5 and 1.8e-5 of the
 * window outside it when it was H's range alone. */
static void cv_pin_spot_at_eye_thin_pancake(long* fails) {
    swarp_camera c[2];
    swarp_light l[2];
    swarp_aabb b[2];
    memset(c, 0, sizeof c);
    memset(l, 0, sizeof l);
    c[0] = (swarp_camera){{-0x1.1f2398fd1363cp+4, 0x1.c8c332a31a209p+3, 0x1.8120f8b0b0528p+1},
                          {0x1.67e5e560d838p-1, -0x1.a5adcdc29eee8p-1, -0x1.903c72a59fd9p-3},
                          {0, 1, 0}, 0x1.933ab9dc40415p-1, 0x1.cc31c975b823p+0, 0x1.5ade6c59c1b95p-7,
                          0x1.5ade6c63f4807p-7, {0}};
    l[0].cone_angle = 0x1.8c65d6f566cc6p-1;
    b[0] = (swarp_aabb){{-0x1.9bff52dc28d71p+5, -0x1.378d9083b374bp+2, -0x1.6a379ee9d60dep+5},
                        {0x1.3983b9bdd3dfep+5, 0x1.c39ddcb030af9p+4, 0x1.04ecf6d775074p+4}};
    c[1] = (swarp_camera){{-0x1.70d876f23d06p+2, 0x1.2d4931273657cp+4, -0x1.b463e8aa73964p+2},
                          {0x1.18ae73af29f16p-1, 0x1.c33338ad82008p-2, -0x1.069b5b59afed6p-1},
                          {0, 1, 0}, 0x1.3c3968837a013p+0, 0x1.7c0cc78121947p+0, 0x1.b57ebc12795dap-7,
                          0x1.b57ebc2175b6bp-7, {0}};
    l[1].cone_angle = 0x1.09a3fe838afdep-2;
    b[1] = (swarp_aabb){{-0x1.cfad3b4ae2a75p+6, -0x1.c452c33bd4494p+1, -0x1.68a32523bf432p+5},
                        {0x1.d1172838629b3p+7, 0x1.a656beacd7b0ap+4, 0x1.158e460913dp+63}};
    for (int i = 0; i < 2; ++i) {
        l[i].position = c[i].eye;
        cv_pin_spot_pancake(fails, "spot_at_eye_thin_pancake_in_depth_range", &c[i], &l[i], &b[i]);
    }
}

/* PSM refuses a frustum thinner than 1e-4 (tan of either half-angle, or
 * (far - near)/near): its post-perspective space rounds like eps/t^2 there.
 * Two scenes of the sweep (seed 7) that PSM mapped with SWARP_OK before:
 * fovy 4.4e-5 under a box with max.z = DBL_MAX (casters 4.4e-5 depth
 * windows out) and far = near (1 + 1.4e-7) with pancaking (2.4e-6 out);
 * both now SWARP_ERR_DEGENERATE with the output untouched.  At twice the
 * threshold (the pinned camera with tan(fovy/2) = 2e-4, aspect 1, or
 * far = near (1 + 2e-4)) PSM still maps and covers. */
static void cv_pin_psm_thin_frustum(long* fails) {
    cv_case k[2];
    memset(k, 0, sizeof k);
    k[0].cam = (swarp_camera){{-0x1.dc69f8a158c8p-3, 0x1.7d414f0a9c1bap+3, -0x1.7e0387813b7aap+3},
                              {0x1.71627d61168d4p-1, 0x1.06305b458aa1p-2, 0x1.e4a503bad2cdep-1},
                              {0, 1, 0}, 0x1.7574797b75b1fp-15, 0x1.a437ba6cb17d2p-1, 0x1.aa05c84f602d3p-7,
                              0x1.288f01cd85293p+4, {0}};
    k[0].light.direction = (swarp_vec3){-0x1.f733d7dd6ae28p-1, -0x1.6619cc9bf0f8p-2, -0x1.af5bfc3d15298p-3};
    k[0].box = (swarp_aabb){{-0x1.6818747c4c6ebp+4, -0x1.0c2a536590106p-1, -0x1.16f0d6bdcc0e9p+4},
                            {0x1.c10c146c5f379p+3, 0x1.5fd350257c6bdp+4, 0x1.fffffffffffffp+1023}};
    k[0].o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    k[1].cam = (swarp_camera){{-0x1.7e1cab7a0037p+1, 0x1.a6bf3cd2312a6p+1, -0x1.360c8189fd1c2p+4},
                              {-0x1.d3820aa52d0fp-1, 0x1.8f2a889b8fb3p-1, -0x1.c51092e0852p-9},
                              {0, 1, 0}, 0x1.36d34f01ddf08p+0, 0x1.1bf552fcf4ffdp+1, 0x1.429524b595908p-6,
                              0x1.429524e4fe2e2p-6, {0}};
    k[1].light.direction = (swarp_vec3){-0x1.05bb53c1a39dp-2, -0x1.8a38546dec758p-2, 0x1.3abc2b11fdc2ep-1};
    k[1].box = (swarp_aabb){{-0x1.000aab2b4c7c4p+6, -0x1.f6d83b7a47807p+1, -0x1.88b7dae74c4d8p+6},
                            {0x1.7038494445991p+4, 0x1.ede2640be26e3p+2, -0x1.759467133361p+2}};
    k[1].o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    k[1].o.pancake = 1;
    for (int i = 0; i < 2; ++i) {
        k[i].light.type = SWARP_LIGHT_DIRECTIONAL;
        k[i].o.technique = SWARP_TECHNIQUE_PSM;
        swarp_setup_result r;
        memset(&r, 0x5a, sizeof r);
        const swarp_setup_result canary = r;
        swarp_status st = swarp_setup(&k[i].cam, &k[i].light, &k[i].box, &k[i].o, &r, NULL, 0, NULL);
        if (st != SWARP_ERR_DEGENERATE) cv_pin_fail(fails, "psm_thin_frustum_refused", "not refused", st);
        else if (memcmp(&r, &canary, sizeof r) != 0) cv_pin_fail(fails, "psm_thin_frustum_refused", "output written", st);
    }
    swarp_light D;
    memset(&D, 0, sizeof D);
    D.type = SWARP_LIGHT_DIRECTIONAL;
    D.direction = (swarp_vec3){0.3, -1, 0.2};
    const swarp_aabb S0 = {{-50, -1, -200}, {50, 10, 50}};
    for (int which = 0; which < 2; ++which) {
        swarp_camera c = cv_pin_camera();
        if (which == 0) c.fovy = 2 * atan(2e-4), c.aspect = 1;
        if (which == 1) c.z_far = c.z_near * (1 + 2e-4);
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = SWARP_TECHNIQUE_PSM;
        swarp_setup_result r;
        swarp_status st = swarp_setup(&c, &D, &S0, &o, &r, NULL, 0, NULL);
        if (swarp_status_is_error(st)) {
            cv_pin_fail(fails, "psm_above_thin_threshold_covered", "refused", st);
            continue;
        }
        cc_result q = cc_check(&c, c.z_near, c.z_far, &D, &S0, &r.matrix, SWARP_DEPTH_NEG_ONE_TO_ONE, 0, st, 9, 17,
                               400, 1);
        if (!cc_ok(&q)) {
            cv_pin_fail(fails, "psm_above_thin_threshold_covered", "not covered", st);
            cc_print(stdout, &q);
            printf("\n");
        }
    }
}

/* Needle frusta (tan of a half-angle 1e-9 .. 3e-5) of the sweep (seed 7)
 * that returned success without covering, replayed with every entry point
 * (the scene's own technique and options), one per cause:
 *   near_face_kept: V's near quad, below the clipper's weld tolerance of
 *     its far corners, was welded into one corner, so V's side edges leaned
 *     inward (scene 84, LiSPSM, omni light, box min.y = -FLT_MAX: receivers
 *     1.35e-4 map widths out, SWARP_OK; scene 17412, uniform, a spot at the
 *     eye, box max.x = FLT_MAX: receivers 2.1e-3 out and casters 19 depth
 *     windows out, SWARP_INFO_LIGHT_PARALLEL);
 *   world_rounding: a map 2.4e-11 wide at coordinates of 20, finer than
 *     the world matrix's rounding once the eye is folded in (scene 12451,
 *     LiSPSM, a spot at the eye: receivers 5.5e-6 out,
 *     SWARP_INFO_LIGHT_NEAR_CLIPPED);
 *   sweep_to_unbounded_face: the sweep toward the light reached 1e6 times
 *     H's size past a box face at DBL_MAX, where the clipper welded the
 *     needle's silhouette rays (scene 2302, LiSPSM, directional: casters
 *     8.7e-6 depth windows out, SWARP_OK). */
static void cv_pin_needle_frusta(long* fails) {
    static const char* const name[4] = {"needle_frustum_near_face_kept_covered", "needle_frustum_near_face_kept_covered",
                                        "needle_map_world_rounding_covered", "needle_sweep_to_unbounded_face_covered"};
    cv_case k[4];
    memset(k, 0, sizeof k);
    k[0].cam = (swarp_camera){{-0x1.14d71672f4cb6p+4, 0x1.d223a795730a8p+2, -0x1.359817f8dc7d8p+4},
                              {-0x1.031a1967d556p-1, -0x1.e14a70bd869cp-6, -0x1.1f0c0346db53p-3},
                              {0, 1, 0}, 0x1.7680755f42385p-30, 0x1.51fd3364ae8d7p+0, 0x1.90f3f525ab4b6p-2,
                              0x1.1946b8a6b0938p+11, {0}};
    k[0].light.type = SWARP_LIGHT_POINT;
    k[0].light.direction = (swarp_vec3){-0x1.249a77540b23p-2, -0x1.069407a67936p-3, 0x1.423e229d441d8p-1};
    k[0].light.position = (swarp_vec3){-0x1.bc4c971a42601p+5, 0x1.478a13259755p+8, -0x1.6533d42c704efp+5};
    k[0].box = (swarp_aabb){{-0x1.203fc8a3b8ddcp+6, -0x1.fffffep+127, -0x1.082f88c79f53cp+6},
                            {0x1.40d322eb1ad2ep+6, 0x1.b9cecc37291ccp+3, 0x1.1320699eba6e7p+6}};
    k[0].o.technique = SWARP_TECHNIQUE_LISPSM;
    k[0].o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    k[1].cam = (swarp_camera){{-0x1.338a11394f544p+2, 0x1.8dde6337c278ap+3, 0x1.fd2554cfe414p+1},
                              {0x1.ad091837bed46p-1, -0x1.7d2a77165a1fep-1, -0x1.24c944570d068p-3},
                              {0, 1, 0}, 0x1.aecb644c4ef0ep-30, 0x1.3c4cc83fe6252p-1, 0x1.081063228cbe8p-5,
                              0x1.3095a45b6890fp+6, {0}};
    k[1].light.type = SWARP_LIGHT_POINT;
    k[1].light.direction = k[1].cam.dir;
    k[1].light.position = k[1].cam.eye;
    k[1].light.cone_angle = 0x1.e8604a86920e4p-1;
    k[1].box = (swarp_aabb){{-0x1.8f9415c6c763bp+3, -0x1.1315fedf2f1cep+1, -0x1.bbf298e3fdfb8p+2},
                            {0x1.fffffep+127, 0x1.5480e5602c98dp+4, 0x1.26cde32808f9ap+4}};
    k[1].o.technique = SWARP_TECHNIQUE_UNIFORM;
    k[1].o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    k[2].cam = (swarp_camera){{-0x1.baf1d09654782p+3, 0x1.152e075ce26ddp+2, 0x1.6bcc4d12e3648p+3},
                              {-0x1.047852ccc1a6p-1, 0x1.7edced72c431cp-1, -0x1.5cf45f34dfc04p-1},
                              {0, 1, 0}, 0x1.d118291c5e358p-30, 0x1.ac1cf86d9e29ep+0, 0x1.1a221ed9658b3p-6,
                              0x1.ce459868e1b6cp-1, {0}};
    k[2].light.type = SWARP_LIGHT_POINT;
    k[2].light.direction = k[2].cam.dir;
    k[2].light.position = k[2].cam.eye;
    k[2].light.cone_angle = 0x1.61b80a34b8d1ep-2;
    k[2].box = (swarp_aabb){{-0x1.339b26b604f26p+5, -0x1.62d8590b8336fp+0, -0x1.ba25e0b43d812p+4},
                            {0x1.271b5670515b4p+3, 0x1.9c95f450fc8f4p+3, 0x1.6d2505d741c88p+4}};
    k[2].o.technique = SWARP_TECHNIQUE_LISPSM;
    k[2].o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    k[3].cam = (swarp_camera){{-0x1.0e98576e10019p+4, 0x1.e63344d7cbb74p+2, 0x1.0e154cf8b7368p+4},
                              {-0x1.9d3582cc0ce4p-6, 0x1.5e6d70dff5938p-1, 0x1.597309244dfe4p-2},
                              {0, 1, 0}, 0x1.cee661241cacbp-16, 0x1.42b274d529724p-1, 0x1.4a521abcaf1c3p-4,
                              0x1.76ba4eecdaf61p+1, {0}};
    k[3].light.type = SWARP_LIGHT_DIRECTIONAL;
    k[3].light.direction = (swarp_vec3){0x1.6b12be69d5df8p-3, -0x1.f486729515c26p-1, -0x1.5e4ac76a8a2d8p-2};
    k[3].box = (swarp_aabb){{-0x1.0f02b48cdabb1p+6, -0x1.11fa1365488f6p+2, 0x1.d23eb70b583dp+0},
                            {0x1.0b3728fc85ea8p+2, 0x1.fffffffffffffp+1023, 0x1.4de3e5f393bc2p+5}};
    k[3].o.technique = SWARP_TECHNIQUE_LISPSM;
    k[3].o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    for (int i = 0; i < 4; ++i) {
        k[i].index = -10 - i;
        swarp_setup_result r;
        const swarp_status st = swarp_setup(&k[i].cam, &k[i].light, &k[i].box, &k[i].o, &r, NULL, 0, NULL);
        if (swarp_status_is_error(st)) cv_pin_fail(fails, name[i], "refused", st);
        cv_stats S = {0, 0, 0};
        cv_run(&k[i], 12345, &S);
        if (S.failed) cv_pin_fail(fails, name[i], "not covered", st);
    }
}

int main(int argc, char** argv) {
    /* under ASan (about 20x slower) the first eighth of the scenes */
    const long count = (argc > 1 ? atol(argv[1]) : 300) / (SW_UNDER_ASAN ? 8 : 1);
    uint64_t s = argc > 2 ? strtoull(argv[2], NULL, 0) : 1;
    const long only = argc > 3 ? atol(argv[3]) : -1;
    cv_stats S = {0, 0, 0};
    for (long i = 0; i < count; ++i) {
        cv_case k;
        k.index = i;
        cv_camera(&s, &k.cam);
        cv_box(&s, &k.cam, &k.box);
        cv_light(&s, &k.cam, &k.box, &k.light);
        memset(&k.o, 0, sizeof k.o);
        k.o.technique = (swarp_technique)(1 + cc_next(&s) % 3);
        k.o.depth_range = cc_next(&s) & 1 ? SWARP_DEPTH_ZERO_TO_ONE : SWARP_DEPTH_NEG_ONE_TO_ONE;
        k.o.pancake = cc_next(&s) % 4 == 0;
        const uint64_t seed = cc_next(&s);
        if (only < 0 || only == i) cv_run(&k, seed, &S);
    }
    long pinned = 0;
    if (only < 0) {
        cv_pin_psm_extreme_frusta(&pinned);
        cv_pin_stabilized_clamped(&pinned);
        cv_pin_replayed_scenes(&pinned);
        cv_pin_spot_pancake_receivers(&pinned);
        cv_pin_spot_at_eye_thin_pancake(&pinned);
        cv_pin_psm_thin_frustum(&pinned);
        cv_pin_needle_frusta(&pinned);
    }
    printf("coverage: %ld scenes, %ld calls, %ld maps checked, %ld violations; pinned inputs: %ld failures\n", count,
           S.calls, S.checked, S.failed, pinned);
    return S.failed || pinned ? 1 : 0;
}
