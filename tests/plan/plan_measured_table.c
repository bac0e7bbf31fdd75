/* The table of docs/planning.md §9: for the scenes of the accuracy/cost grid
 * (γ × f/n, a ground slab box, 1920x1080, 2048² maps, budget 2 pixels per
 * texel) the planner's chain, its model maximum and the measured maximum of
 * the chain's matrices (swarp_plan_evaluate), and what ranking all 96
 * candidates by measured error would cost (CPU time, this machine).
 *
 *   build/tests/plan/plan_measured_table
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "shadowwarp.h"
#include "plan_helpers.h"

#define PI 3.14159265358979323846

static double cpu_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The camera 2 above the ground looking along -z; the light at gamma to
 * the view, slightly to the side; a ground slab box to past the far plane. */
static swarp_scene_needs grid_scene(double gamma_deg, double fn) {
    swarp_scene_needs n;
    memset(&n, 0, sizeof n);
    n.camera = plan_test_camera(fn);
    n.camera.aspect = 16.0 / 9.0;
    const double g = gamma_deg * PI / 180.0;
    n.light.type = SWARP_LIGHT_DIRECTIONAL;
    n.light.direction = (swarp_vec3){0.3 * cos(g), -sin(g), cos(g)};
    n.scene_box = (swarp_aabb){{-fn, -1.0, -1.2 * fn}, {fn, 6.0, 3.0}};
    n.screen_width = 1920;
    n.screen_height = 1080;
    return n;
}

/* Candidate i of the planner's documented order (docs/planning.md §1). */
static swarp_plan_chain candidate(int i) {
    static const swarp_plan_warp single[6] = {
        SWARP_PLAN_WARP_UNIFORM,      SWARP_PLAN_WARP_LISPSM_NOPT,   SWARP_PLAN_WARP_LISPSM_NREPAR,
        SWARP_PLAN_WARP_LISPSM_GMNPR, SWARP_PLAN_WARP_LISPSM_PSEUDO, SWARP_PLAN_WARP_PSM};
    static const swarp_plan_warp split[3] = {SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_WARP_LISPSM_NOPT,
                                             SWARP_PLAN_WARP_LISPSM_NREPAR};
    swarp_plan_chain c;
    memset(&c, 0, sizeof c);
    if (i < 6) {
        c.warp = single[i];
        c.scheme = SWARP_PLAN_SCHEME_NONE;
        c.split_count = 1;
    } else {
        c.split_count = (uint32_t)(2 + (i - 6) / 6);
        c.scheme = (i - 6) % 6 < 3 ? SWARP_PLAN_SCHEME_PRACTICAL : SWARP_PLAN_SCHEME_LOG;
        c.warp = split[(i - 6) % 3];
    }
    return c;
}

int main(void) {
    static const double gammas[] = {90.0, 60.0, 30.0, 150.0};
    static const double fns[] = {100.0, 1000.0, 10000.0};
    printf("| γ | f/n | chain | model max(m_x, m_z) | measured max(m_s, m_t) | measured/model | "
           "measured <= 2 | measured max σ | "
           "swarp_plan | evaluate (chain) | evaluate × 96 |\n");
    printf("|---:|---:|---|---:|---:|---:|---|---:|---:|---:|---:|\n");
    for (size_t gi = 0; gi < sizeof gammas / sizeof gammas[0]; ++gi)
        for (size_t fi = 0; fi < sizeof fns / sizeof fns[0]; ++fi) {
            swarp_scene_needs n = grid_scene(gammas[gi], fns[fi]);
            swarp_budget b;
            memset(&b, 0, sizeof b);
            b.max_error = 2.0;
            struct swarp_plan p, q;
            double t0 = cpu_seconds();
            for (int r = 0; r < 100; ++r) (void)swarp_plan(&n, &b, &p);
            const double t_plan = (cpu_seconds() - t0) / 100.0;
            swarp_plan_chain c;
            memset(&c, 0, sizeof c);
            c.warp = p.warp;
            c.scheme = p.scheme;
            c.split_count = p.split_count;
            c.stabilize = p.stabilize;
            t0 = cpu_seconds();
            for (int r = 0; r < 10; ++r) (void)swarp_plan_evaluate(&n, &b, &c, &q);
            const double t_eval = (cpu_seconds() - t0) / 10.0;
            t0 = cpu_seconds();
            for (int i = 0; i < 96; ++i) {
                swarp_plan_chain ci = candidate(i);
                struct swarp_plan e;
                (void)swarp_plan_evaluate(&n, &b, &ci, &e);
            }
            const double t_all = cpu_seconds() - t0;
            /* like with like: the model's max(m_x, m_z) against the
             * matrices' max(m_s, m_t) (sigma, the worst direction, is
             * larger by up to sqrt 2) */
            const double m = fmax(q.measured.max_m_s, q.measured.max_m_t);
            printf("| %.0f | %.0f | %s, K %u %s | %.3g | %.3g | %.2f | %s | %.3g | %.0f µs | %.2f ms | %.1f ms |\n",
                   gammas[gi], fns[fi], swarp_plan_warp_name(q.warp), q.split_count,
                   swarp_plan_scheme_name(q.scheme), q.max_error, m, m / q.max_error,
                   m <= b.max_error ? "yes" : "no", q.measured.max_sigma, t_plan * 1e6, t_eval * 1e3, t_all * 1e3);
        }
    return 0;
}
