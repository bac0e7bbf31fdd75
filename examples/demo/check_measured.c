/* check_measured.c -- demo-check --test measured: the measured error of
 * docs/accuracy.md taken from the render against the library's at the same
 * receivers, for every technique and four suns of the default camera. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "checks.h"

/* The render's maximum against swarp_measure_points' maximum over the same
 * pixels: the summary's measured/predicted (docs/demo.md). */
#define CHECK_MAX_RATIO_TOL 0.10
/* Per pixel the central difference of float texel coordinates against the
 * analytic double value.  The rounding of s, t (ulp 2^-14 texels below
 * 1024) over a difference of 2 sigma_min(T) = 2 / sigma gives a relative
 * error up to about 3e-5 sigma: 0.9 % at the largest sigma of this check
 * (PSM, about 290 pixels per texel at 320 x 180); the truncation of the
 * central difference is second order in one pixel and far smaller. */
#define CHECK_PIXEL_P99_TOL 0.01

/* One technique on view v: prints the figures and returns 1 on failure. */
static int check_one(const demo_options* o, demo_renderer* r, const demo_view* v,
                     const swarp_aabb* box, demo_technique t, const char* sun) {
    demo_tech_result res;
    if (demo_run_technique(o, r, v, box, t, 4, 0, &res)) {
        printf("measured %-8s %-12s FAIL (setup or render)\n", sun, demo_technique_name(t));
        return 1;
    }
    const demo_measured* m = &res.measured;
    double ratio = m->render_sigma / m->points_sigma;
    /* a screen of receivers to compare: at least 5 % of the pixels */
    int bad = res.gl_errors != 0 || m->pixels < v->w * v->h / 20;
    bad |= !(fabs(ratio - 1) <= CHECK_MAX_RATIO_TOL);
    bad |= !(m->pixel_dev_p99 <= CHECK_PIXEL_P99_TOL);
    /* sigma is the largest singular value: max(m_s, m_t) <= sigma <=
     * hypot(m_s, m_t) pixel by pixel, hence for the maxima too */
    bad |= !(m->render_sigma >= fmax(m->render_m_s, m->render_m_t) * (1 - 1e-12));
    bad |= !(m->render_sigma <= hypot(m->render_m_s, m->render_m_t) * (1 + 1e-12));
    printf("measured %-8s %-12s %s: %d pixels, max sigma render %.4g, points %.4g (ratio %.4f), "
           "per pixel p99 %.2e max %.2e; H %s%.4g\n",
           sun, res.label, bad ? "FAIL" : "ok", m->pixels, m->render_sigma, m->points_sigma,
           ratio, m->pixel_dev_p99, m->pixel_dev_max, res.sh.have_measured ? "" : "(none) ",
           res.sh.have_measured ? res.sh.measured.max_sigma : NAN);
    demo_tech_result_free(&res);
    return bad;
}

int demo_check_measured(const demo_options* o) {
    /* the default sun, behind the camera, toward it (duelling frusta), and
     * overhead: elevation, azimuth in degrees */
    static const struct {
        const char* name;
        double elev, azim;
    } suns[4] = {{"default", 35, 115}, {"behind", 35, 10}, {"duel", 20, 180}, {"overhead", 90, 0}};
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 1, &scene, &r)) return 1;
    int fails = 0;
    for (int s = 0; s < 4; ++s) {
        demo_options q = *o;
        q.have_light_dir = 0;
        q.light_elev = suns[s].elev;
        q.light_azim = suns[s].azim;
        q.filter = DEMO_FILTER_NONE;
        demo_view v;
        if (demo_preset_view(&q, "default", &v)) {
            fails = 1;
            break;
        }
        for (int t = 0; t < DEMO_TECH_COUNT; ++t)
            fails += check_one(&q, &r, &v, &scene.box, (demo_technique)t, suns[s].name);
    }
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}
