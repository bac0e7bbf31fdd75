/* The table of docs/splits.md: the default cascade's split positions
 * (SWARP_SCHEME_MEASURED) against the practical scheme with λ = 0.5 and
 * 0.95 and the log scheme, by each cascade's worst split measured with
 * swarp_measure_max (default sampling) over its own range.  Camera 2 m
 * above a 200 x 30 x 200 m box, fovy 60°, 1024 x 768 screen, 1024² maps,
 * 4 splits, the light at γ from the view direction; then a summary over
 * random configurations.  Not a test: `build/tests/cascade/splits_measured_table`
 * prints the markdown. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define DEG (3.14159265358979323846 / 180.0)

static double worst(const swarp_camera* cam, const swarp_light* l, const swarp_aabb* box, swarp_split_scheme sch,
                    double lambda, const swarp_setup_options* so, double* splits) {
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    o.setup = *so;
    o.split.scheme = sch;
    o.split.lambda = lambda;
    swarp_cascade_result r;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t n;
    if (swarp_status_is_error(swarp_cascade_setup(cam, l, box, &o, &r, sp, SWARP_CASCADE_MAX_SPLITS, &n))) return -1;
    swarp_measure_res mr = {so->screen_width, so->screen_height, so->map_width, so->map_width};
    double w = 0;
    for (size_t i = 0; i < n; ++i) {
        swarp_measured_error e;
        if (swarp_status_is_error(swarp_measure_max(cam, sp[i].z_near, sp[i].z_far, l, box, &sp[i].matrix, &mr, NULL, &e)))
            return -1;
        w = fmax(w, e.max_sigma);
    }
    if (splits) memcpy(splits, r.splits, (n + 1) * sizeof *splits);
    return w;
}

int main(void) {
    swarp_setup_options so;
    memset(&so, 0, sizeof so);
    so.map_width = 1024, so.screen_width = 1024, so.screen_height = 768;
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){0, 2, 0};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 60 * DEG;
    cam.aspect = 1024.0 / 768.0;
    cam.z_near = 0.5;
    cam.z_far = 300;
    const double pitch = -10 * DEG;
    cam.dir = (swarp_vec3){0, sin(pitch), -cos(pitch)};
    swarp_aabb box = {{-100, 0, -100}, {100, 30, 100}};
    printf("| γ | λ = 0.5 | λ = 0.95 | log | default (measured) | default splits C_1..C_3 |\n");
    printf("|---:|---:|---:|---:|---:|---|\n");
    const double gammas[] = {90, 60, 45, 30, 20, 5, 150};
    for (size_t g = 0; g < sizeof gammas / sizeof gammas[0]; ++g) {
        /* the light at γ from the view direction, turned toward the sky
         * (γ < 90: from behind and above the camera) */
        const double a = gammas[g] * DEG;
        swarp_vec3 f = cam.dir, u = {0, cos(pitch), sin(pitch)}; /* the camera's up */
        swarp_light l;
        memset(&l, 0, sizeof l);
        l.type = SWARP_LIGHT_DIRECTIONAL;
        l.direction = (swarp_vec3){f.x * cos(a) - u.x * sin(a), f.y * cos(a) - u.y * sin(a), f.z * cos(a) - u.z * sin(a)};
        double c[SWARP_CASCADE_MAX_SPLITS + 1];
        double w5 = worst(&cam, &l, &box, SWARP_SCHEME_PRACTICAL, 0.5, &so, NULL);
        double w95 = worst(&cam, &l, &box, SWARP_SCHEME_PRACTICAL, 0.95, &so, NULL);
        double wl = worst(&cam, &l, &box, SWARP_SCHEME_LOG, 0, &so, NULL);
        double wd = worst(&cam, &l, &box, SWARP_SCHEME_DEFAULT, 0, &so, c);
        printf("| %.0f° | %.2f | %.2f | %.2f | %.2f | %.2f, %.2f, %.2f |\n", gammas[g], w5, w95, wl, wd, c[1], c[2], c[3]);
    }
    /* random configurations: camera anywhere over a 1000 m box, far/near 1e2..1e3.5, any light from above */
    uint64_t rng = 0x5b11;
    int n = 0, worse5 = 0, worse95 = 0, worsel = 0;
    double g5 = 0, g95 = 0, gl = 0;
    swarp_setup_options sd;
    memset(&sd, 0, sizeof sd);
    sd.map_width = 2048, sd.screen_width = 1920, sd.screen_height = 1080;
    for (int k = 0; k < 300; ++k) {
        swarp_camera c = cam;
        double yaw = tu_uniform(&rng, 0, 360) * DEG, pit = tu_uniform(&rng, -30, 8) * DEG;
        c.eye = (swarp_vec3){tu_uniform(&rng, -50, 50), tu_uniform(&rng, 1, 30), tu_uniform(&rng, -50, 50)};
        c.dir = (swarp_vec3){cos(pit) * sin(yaw), sin(pit), -cos(pit) * cos(yaw)};
        c.fovy = tu_uniform(&rng, 40, 90) * DEG;
        c.aspect = 16.0 / 9.0;
        c.z_near = tu_uniform(&rng, 0.1, 1);
        c.z_far = c.z_near * pow(10, tu_uniform(&rng, 2, 3.5));
        double th = tu_uniform(&rng, 0, 360) * DEG, el = tu_uniform(&rng, 5, 89) * DEG;
        swarp_light l;
        memset(&l, 0, sizeof l);
        l.type = SWARP_LIGHT_DIRECTIONAL;
        l.direction = (swarp_vec3){cos(el) * cos(th), -sin(el), cos(el) * sin(th)};
        swarp_aabb b = {{-500, 0, -500}, {500, tu_uniform(&rng, 5, 100), 500}};
        double wd = worst(&c, &l, &b, SWARP_SCHEME_DEFAULT, 0, &sd, NULL);
        double w5 = worst(&c, &l, &b, SWARP_SCHEME_PRACTICAL, 0.5, &sd, NULL);
        double w95 = worst(&c, &l, &b, SWARP_SCHEME_PRACTICAL, 0.95, &sd, NULL);
        double wl = worst(&c, &l, &b, SWARP_SCHEME_LOG, 0, &sd, NULL);
        if (wd <= 0 || w5 <= 0 || w95 <= 0 || wl <= 0) continue;
        ++n;
        worse5 += wd > w5, worse95 += wd > w95, worsel += wd > wl;
        g5 += log(w5 / wd), g95 += log(w95 / wd), gl += log(wl / wd);
    }
    printf("\nOver %d random configurations (1920 x 1080 screen, 2048² maps): the default's worst split is on\n"
           "geometric mean %.2fx better than λ = 0.5, %.2fx better than λ = 0.95 and %.2fx better than log;\n"
           "worse than λ = 0.5 in %d, than λ = 0.95 in %d, than log in %d configurations.\n",
           n, exp(g5 / n), exp(g95 / n), exp(gl / n), worse5, worse95, worsel);
    return 0;
}
