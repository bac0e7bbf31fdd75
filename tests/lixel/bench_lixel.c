#define _POSIX_C_SOURCE 200809L
/* Benchmark of the lixel stage ([LIXEL] says computing M_l "is essentially
 * free"): median and p99 time per call over many repetitions.  Not a test:
 * run with `meson test --benchmark` or ./build/tests/bench_lixel. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "shadowwarp.h"

#define REPS 2001
#define INNER 50


static swarp_mat4 viewer(void) {
    /* lookAt((1,1.7,4), dir (-0.2,-0.35,-1)) x perspective(60 deg, 1.5, 0.1, 100) */
    double fx = -0.2, fy = -0.35, fz = -1.0, l = sqrt(fx * fx + fy * fy + fz * fz);
    fx /= l, fy /= l, fz /= l;
    double sx = -fz, sy = 0, sz = fx; /* f x (0,1,0) */
    l = sqrt(sx * sx + sz * sz);
    sx /= l, sz /= l;
    double ux = sy * fz - sz * fy, uy = sz * fx - sx * fz, uz = sx * fy - sy * fx;
    double ex = 1, ey = 1.7, ez = 4, t = tan(3.14159265358979323846 / 6), n = 0.1, fa = 100;
    double P[4][4] = {{1 / (t * 1.5), 0, 0, 0}, {0, 1 / t, 0, 0}, {0, 0, (fa + n) / (n - fa), 2 * fa * n / (n - fa)}, {0, 0, -1, 0}};
    double Vw[4][4] = {{sx, sy, sz, -(sx * ex + sy * ey + sz * ez)},
                       {ux, uy, uz, -(ux * ex + uy * ey + uz * ez)},
                       {-fx, -fy, -fz, fx * ex + fy * ey + fz * ez},
                       {0, 0, 0, 1}};
    swarp_mat4 M;
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) {
            double acc = 0;
            for (int j = 0; j < 4; ++j) acc += P[r][j] * Vw[j][k];
            M.m[k * 4 + r] = acc;
        }
    return M;
}

int main(void) {
    static double tm[REPS], tr[REPS], tf[REPS];
    swarp_mat4 Mv = viewer(), Ml, Mr, GLV, GLP;
    swarp_plane P = {0, 1, 0, 0};
    swarp_light L;
    memset(&L, 0, sizeof L);
    L.type = SWARP_LIGHT_POINT;
    L.position.x = -3, L.position.y = 6, L.position.z = 2;
    swarp_vec4 C[4] = {{-8, 0, 4, 1}, {8, 0, 4, 1}, {8, 0, -10, 1}, {-8, 0, -10, 1}};
    swarp_lixel_restrict_options o;
    memset(&o, 0, sizeof o);
    o.view_width = 720, o.view_height = 480;
    swarp_lixel_rect R;
    volatile double sink = 0;
    for (int r = 0; r < REPS; ++r) {
        double t0 = now_ns();
        for (int i = 0; i < INNER; ++i) {
            Mv.m[12] += 1e-12; /* defeat hoisting */
            swarp_lixel_matrix(&Mv, 720, 480, &L, &P, NULL, &Ml, NULL);
            sink += Ml.m[0];
        }
        double t1 = now_ns();
        for (int i = 0; i < INNER; ++i) {
            swarp_lixel_restrict(&Ml, C, 4, &o, &R, NULL, &Mr);
            sink += Mr.m[0];
        }
        double t2 = now_ns();
        for (int i = 0; i < INNER; ++i) {
            swarp_lixel_factor(&Mr, R.width, R.height, SWARP_DEPTH_DEFAULT, 0, &GLV, &GLP);
            sink += GLP.m[0];
        }
        double t3 = now_ns();
        tm[r] = (t1 - t0) / INNER, tr[r] = (t2 - t1) / INNER, tf[r] = (t3 - t2) / INNER;
    }
    qsort(tm, REPS, sizeof(double), cmp_double);
    qsort(tr, REPS, sizeof(double), cmp_double);
    qsort(tf, REPS, sizeof(double), cmp_double);
    printf("lixel stage, ns per call (%d x %d calls)\n", REPS, INNER);
    printf("%-34s %10s %10s\n", "function", "median", "p99");
    printf("%-34s %10.0f %10.0f\n", "swarp_lixel_matrix", tm[REPS / 2], tm[REPS * 99 / 100]);
    printf("%-34s %10.0f %10.0f\n", "swarp_lixel_restrict (view clip)", tr[REPS / 2], tr[REPS * 99 / 100]);
    printf("%-34s %10.0f %10.0f\n", "swarp_lixel_factor", tf[REPS / 2], tf[REPS * 99 / 100]);
    return sink == 42.0 ? 1 : 0;
}
