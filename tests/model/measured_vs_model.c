/* Model against measured: for configurations of its own generator (light
 * directions over the whole sphere, camera pitch -30..+10 degrees, far/near
 * 10^2..10^4, scene boxes with and without the eye) and the techniques
 * uniform, LiSPSM (n_opt) and PSM, the model's prediction max(max_mx,
 * max_mz) of swarp_setup_result ([RHS] (2.3)-(2.8), overhead light, view
 * axis) against the measured maximum sigma of the returned matrix over H
 * (swarp_measure_max).  Prints data lines for docs/plots/measured_vs_model.sh
 * ("plot") or the summary table of docs/accuracy.md ("table").
 *   measured_vs_model plot|table [configurations]        (default 500) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define PI 3.14159265358979323846
#define MAX_CFG 5000

typedef struct row { double predicted, measured, gamma; } row;

static int cmp(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static int make_config(uint64_t* s, swarp_camera* c, swarp_light* l, swarp_aabb* box) {
    memset(c, 0, sizeof *c);
    memset(l, 0, sizeof *l);
    const double pitch = tu_uniform(s, -30, 10) * PI / 180, yaw = tu_uniform(s, -PI, PI);
    c->eye = (swarp_vec3){tu_uniform(s, -20, 20), tu_uniform(s, 1, 20), tu_uniform(s, -20, 20)};
    c->dir = (swarp_vec3){sin(yaw) * cos(pitch), sin(pitch), -cos(yaw) * cos(pitch)};
    c->up = (swarp_vec3){0, 1, 0};
    c->fovy = tu_uniform(s, 30, 90) * PI / 180;
    c->aspect = 16.0 / 9.0;
    c->z_near = tu_uniform(s, 0.1, 2);
    c->z_far = c->z_near * pow(10, tu_uniform(s, 2, 4));
    /* light direction uniform over the sphere */
    const double zl = tu_uniform(s, -1, 1), al = tu_uniform(s, -PI, PI), rl = sqrt(1 - zl * zl);
    l->type = SWARP_LIGHT_DIRECTIONAL;
    l->direction = (swarp_vec3){rl * cos(al), zl, rl * sin(al)};
    const double e = fmin(c->z_far, 2000);
    const int with_eye = tu_uniform(s, 0, 1) < 0.5;
    box->min = (swarp_vec3){-e, 0, -e};
    box->max = (swarp_vec3){e, with_eye ? c->eye.y + 30 : c->eye.y * 0.5, e};
    return 1;
}

int main(int argc, char** argv) {
    const int table = argc > 1 && strcmp(argv[1], "table") == 0;
    int n = argc > 2 ? atoi(argv[2]) : 500;
    if (n > MAX_CFG) n = MAX_CFG;
    static const swarp_technique tech[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM,
                                            SWARP_TECHNIQUE_PSM};
    static const char* const name[3] = {"uniform", "lispsm", "psm"};
    static row rows[3][MAX_CFG];
    int count[3] = {0, 0, 0};
    uint64_t s = 0x5eed0006u;
    const swarp_measure_res res = {1920, 1080, 2048, 2048};
    for (int i = 0; i < n; ++i) {
        swarp_camera c;
        swarp_light l;
        swarp_aabb box;
        make_config(&s, &c, &l, &box);
        for (int t = 0; t < 3; ++t) {
            swarp_setup_options o;
            memset(&o, 0, sizeof o);
            o.technique = tech[t];
            swarp_setup_result r;
            if (swarp_status_is_error(swarp_setup(&c, &l, &box, &o, &r, NULL, 0, NULL))) continue;
            swarp_measured_error m;
            if (swarp_measure_max(&c, r.view_near, r.view_far, &l, &box, &r.matrix, &res, NULL, &m) !=
                SWARP_OK)
                continue;
            row* w = &rows[t][count[t]++];
            w->predicted = fmax(r.max_mx, r.max_mz);
            w->measured = m.max_sigma;
            w->gamma = r.gamma * 180 / PI;
            if (!table) printf("%d %.9g %.9g %.4g\n", t, w->predicted, w->measured, w->gamma);
        }
    }
    if (!table) return 0;
    printf("| technique | configurations | predicted/measured: median | 10th percentile | worst low | worst high | off by > 1.5x |\n");
    printf("|---|---|---|---|---|---|---|\n");
    for (int t = 0; t < 3; ++t) {
        static double q[MAX_CFG];
        int off = 0;
        for (int k = 0; k < count[t]; ++k) {
            q[k] = rows[t][k].predicted / rows[t][k].measured;
            off += q[k] > 1.5 || q[k] < 1 / 1.5;
        }
        qsort(q, (size_t)count[t], sizeof(double), cmp);
        const int m = count[t];
        if (m == 0) continue;
        printf("| %s | %d | %.3g | %.3g | %.3g | %.3g | %.0f %% |\n", name[t], m, q[m / 2], q[m / 10],
               q[0], q[m - 1], 100.0 * off / m);
    }
    return 0;
}
