/* check_options.c -- the options of docs/before-after.md against the
 * library: --light-gamma puts the light at exactly γ to the view direction,
 * --nprime measured gives swarp_setup's default map, and --basis aligned,
 * built from the public steps, is swarp_setup's n_opt map wherever the two
 * bases agree (outside the blend zone, sin γ >= sin 10°) and its own
 * rotation inside it.  CPU only: no pass is rendered. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "checks.h"

/* The matrices compared are built by different call chains from the same
 * doubles (the setup works camera-relative, the steps in world space): they
 * agree to the rounding of world coordinates of a few hundred metres,
 * relative to the largest entry. */
#define SAME_MATRIX_REL 1e-9
/* the light's angle to the view, from a dot product and an acos of unit
 * vectors built in double: exact to the rounding of acos near its argument */
#define GAMMA_TOL_DEG 1e-9

static int fails;
static swarp_aabb scene_box; /* the default scene's S */

static double mat_rel_diff(const swarp_mat4* a, const swarp_mat4* b) {
    double d = 0, m = 0;
    for (int i = 0; i < 16; ++i) {
        d = fmax(d, fabs(a->m[i] - b->m[i]));
        m = fmax(m, fabs(a->m[i]));
    }
    return d / m;
}

static void expect(int ok, const char* what, double got) {
    printf("  %-58s %-4s (%.3g)\n", what, ok ? "ok" : "FAIL", got);
    if (!ok) ++fails;
}

/* The demo's single LiSPSM map of view v with the given --nprime/--basis. */
static int demo_map(const demo_options* o, const demo_view* v, int measured, int aligned, demo_shadow* sh) {
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = DEMO_TECH_LISPSM;
    req.splits = 1;
    req.map_res = o->map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    req.nprime_measured = measured;
    req.basis_aligned = aligned;
    return demo_shadow_setup(&v->cam, &v->light, &scene_box, &req, sh);
}

/* swarp_setup's map for the same view, n_opt or the default n'. */
static int library_map(const demo_options* o, const demo_view* v, swarp_warp_param p, swarp_setup_result* r) {
    swarp_setup_options opt;
    memset(&opt, 0, sizeof opt);
    opt.technique = SWARP_TECHNIQUE_LISPSM;
    opt.param = p;
    opt.map_width = opt.map_height = (uint32_t)o->map;
    opt.screen_width = (uint32_t)v->w;
    opt.screen_height = (uint32_t)v->h;
    return swarp_status_is_error(swarp_setup(&v->cam, &v->light, &scene_box, &opt, r, NULL, 0, NULL));
}

static int check_gamma(const demo_options* o, double gamma_deg) {
    demo_options q = *o;
    q.have_light_gamma = 1;
    q.light_gamma = gamma_deg;
    demo_view v;
    if (demo_preset_view(&q, "default", &v)) return -1;
    const swarp_vec3 d = v.cam.dir, l = v.light.direction;
    const double c = (d.x * l.x + d.y * l.y + d.z * l.z) /
                     (sqrt(d.x * d.x + d.y * d.y + d.z * d.z) * sqrt(l.x * l.x + l.y * l.y + l.z * l.z));
    const double got = acos(fmin(1.0, fmax(-1.0, c))) * 180.0 / 3.14159265358979323846;
    printf("gamma %g deg:\n", gamma_deg);
    expect(fabs(got - gamma_deg) <= GAMMA_TOL_DEG, "--light-gamma: angle of light to view", got);
    expect(l.y < 0, "--light-gamma: the light travels down", l.y);
    demo_shadow closed, aligned, measured;
    swarp_setup_result nopt, dflt;
    if (demo_map(&q, &v, 0, 0, &closed) || demo_map(&q, &v, 0, 1, &aligned) || demo_map(&q, &v, 1, 0, &measured) ||
        library_map(&q, &v, SWARP_WARP_PARAM_NOPT, &nopt) || library_map(&q, &v, SWARP_WARP_PARAM_DEFAULT, &dflt))
        return -1;
    const double dm = mat_rel_diff(&dflt.matrix, &measured.light[0]);
    expect(dm == 0.0, "--nprime measured: swarp_setup's default matrix", dm);
    const double dc = mat_rel_diff(&nopt.matrix, &closed.light[0]);
    expect(dc == 0.0, "--nprime closed: swarp_setup's n_opt matrix", dc);
    const double da = mat_rel_diff(&nopt.matrix, &aligned.light[0]);
    const int outside_zone = sin(gamma_deg * 3.14159265358979323846 / 180.0) >= SWARP_FOCUS_BLEND_SIN;
    if (outside_zone) {
        expect(da <= SAME_MATRIX_REL, "--basis aligned outside the blend zone: setup's n_opt", da);
        const double ds = fabs(aligned.measured.max_sigma - nopt.measured.max_sigma) / nopt.measured.max_sigma;
        expect(ds <= SAME_MATRIX_REL, "--basis aligned: its measured max sigma, setup's", ds);
    } else {
        /* inside the zone the setup turns the map to the minimum-area
         * rectangle; the blended up of the aligned basis is another one */
        expect(da > SAME_MATRIX_REL, "--basis aligned inside the blend zone: another rotation", da);
    }
    return 0;
}

int demo_check_options(const demo_options* o) {
    fails = 0;
    demo_scene s;
    if (demo_scene_default(&s)) return DEMO_EXIT_SKIP;
    scene_box = s.box;
    demo_scene_free(&s);
    if (check_gamma(o, 5.0) || check_gamma(o, 150.0)) {
        printf("FAIL: a setup failed\n");
        return 1;
    }
    printf(fails ? "FAIL: %d\n" : "PASS\n", fails);
    return fails ? 1 : 0;
}
