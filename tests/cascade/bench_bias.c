#define _POSIX_C_SOURCE 200809L
/* Benchmark (not a test): per-call cost of the bias functions ([KOZ] §14.2.3,
 * src/cascade/bias.c), median and p99 over many repetitions, for a uniform
 * (orthographic, directional light) map and a projective (spot light) map.
 * Each row also gives the ratio of its median to a baseline timed in the
 * same run: one swarp_mat4_transform (a world point to clip space, what a
 * shader does per fragment).  swarp_mat4_invert is a reference row: the
 * bias functions invert the map once per call, but without the public
 * call's condition estimate, so they cost less than it.  docs/splits.md
 * quotes the table.  Run: `meson test -C build --benchmark bias` or
 * ./build/tests/bench_bias. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "shadowwarp.h"

enum { REPS = 1001, INNER = 200 };
static volatile double sink;

/* times INNER calls of the body per repetition; returns the median (ns per
 * call) and stores the p99 */
#define TIME(med, p99, ...)                                        \
    do {                                                           \
        static double t_[REPS];                                    \
        for (int r = 0; r < REPS; ++r) {                           \
            double t0 = now_ns();                                  \
            for (int i = 0; i < INNER; ++i) { __VA_ARGS__; }       \
            t_[r] = (now_ns() - t0) / INNER;                       \
        }                                                          \
        qsort(t_, REPS, sizeof t_[0], cmp_double);                 \
        (med) = t_[REPS / 2], (p99) = t_[(REPS * 99) / 100];       \
    } while (0)

/* column-major r = a b */
static swarp_mat4 mul(const double a[16], const double b[16]) {
    swarp_mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) {
            double acc = 0;
            for (int j = 0; j < 4; ++j) acc += a[j * 4 + k] * b[c * 4 + j];
            r.m[c * 4 + k] = acc;
        }
    return r;
}

/* view matrix looking from eye along dir (column-major) */
static void look(const double eye[3], const double dir[3], double V[16]) {
    double f[3] = {dir[0], dir[1], dir[2]}, l = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; ++i) f[i] /= l;
    double up[3] = {fabs(f[1]) > 0.9 ? 1.0 : 0.0, fabs(f[1]) > 0.9 ? 0.0 : 1.0, 0.0};
    double s[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]};
    l = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int i = 0; i < 3; ++i) s[i] /= l;
    double u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    memset(V, 0, 16 * sizeof V[0]);
    for (int i = 0; i < 3; ++i) V[i * 4 + 0] = s[i], V[i * 4 + 1] = u[i], V[i * 4 + 2] = -f[i];
    V[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    V[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    V[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    V[15] = 1;
}

typedef struct bench_map {
    const char* name;
    swarp_bias_map map;
    swarp_light light;
} bench_map;

/* a directional light's orthographic map over a 200 x 200 x 200 box */
static bench_map uniform_map(void) {
    bench_map b;
    memset(&b, 0, sizeof b);
    b.name = "uniform (ortho, directional)";
    double eye[3] = {-60, 200, -40}, dir[3] = {0.3, -1.0, 0.2}, V[16], O[16] = {0};
    look(eye, dir, V);
    O[0] = O[5] = 1.0 / 150, O[10] = -2.0 / 400, O[14] = -1, O[15] = 1; /* near 0, far 400 */
    b.map.world_to_clip = mul(O, V);
    b.map.res_s = b.map.res_t = 2048;
    b.map.depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
    b.light.type = SWARP_LIGHT_DIRECTIONAL;
    b.light.direction = (swarp_vec3){0.3, -1.0, 0.2};
    return b;
}

/* a spot light's perspective map: 90 degrees, near 0.5, far 300 */
static bench_map projective_map(void) {
    bench_map b;
    memset(&b, 0, sizeof b);
    b.name = "projective (perspective, spot)";
    double eye[3] = {10, 40, 5}, dir[3] = {-0.2, -1.0, 0.1}, V[16], P[16] = {0}, n = 0.5, f = 300;
    look(eye, dir, V);
    P[0] = P[5] = 1, P[10] = (f + n) / (n - f), P[11] = -1, P[14] = 2 * f * n / (n - f);
    b.map.world_to_clip = mul(P, V);
    b.map.res_s = b.map.res_t = 2048;
    b.map.depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
    b.light.type = SWARP_LIGHT_POINT;
    b.light.position = (swarp_vec3){10, 40, 5};
    b.light.direction = (swarp_vec3){-0.2, -1.0, 0.1};
    b.light.cone_angle = 0.7853981633974483; /* 45 degree half-angle */
    return b;
}

static void row(const char* name, double med, double p99, double base) {
    printf("| %s | %.1f | %.1f | %.1f |\n", name, med, p99, med / base);
}

static void bench(const bench_map* b) {
    const swarp_bias_map* m = &b->map;
    const swarp_light* L = &b->light;
    swarp_vec3 p = {3.0, 1.5, -7.0}, n = {0.1, 1.0, -0.2}, Ta = {1, 0, 0}, Tb = {0, 0.2, 1}, q;
    swarp_vec4 c;
    swarp_mat4 inv;
    double x = 0, y = 0, g[2], bt, med, p99;
    long failures = 0;

    printf("\n%s map, 2048 x 2048, ns per call (%d repetitions x %d calls)\n\n", b->name, REPS, INNER);
    printf("| function | median [ns] | p99 [ns] | median / transform |\n");
    printf("|---|---:|---:|---:|\n");
    TIME(bt, p99, { p.x = 3.0 + i * 1e-9; swarp_mat4_transform(&m->world_to_clip, &p, &c); sink = c.x; });
    row("swarp_mat4_transform (baseline)", bt, p99, bt);
    TIME(med, p99, { swarp_mat4_invert(&m->world_to_clip, &inv); sink = inv.m[i & 15]; });
    row("swarp_mat4_invert (reference)", med, p99, bt);
#define CALL(name, expr)                                                                      \
    do {                                                                                      \
        TIME(med, p99, { p.x = 3.0 + i * 1e-9; failures += swarp_status_is_error(expr); sink = x + q.x; }); \
        row(name, med, p99, bt);                                                          \
    } while (0)
    q.x = 0;
    CALL("swarp_bias_texel_size", swarp_bias_texel_size(m, &p, &x, NULL, NULL));
    CALL("swarp_bias_to_light", swarp_bias_to_light(L, &p, &q));
    CALL("swarp_bias_kozlov", swarp_bias_kozlov(m, L, &p, 0.01, 1.0, &q, &x));
    CALL("swarp_bias_normal_offset", swarp_bias_normal_offset(m, L, &p, &n, 1.0, &q, &x));
    CALL("swarp_bias_slope_scaled", swarp_bias_slope_scaled(m, L, &p, &n, 0.01, 1.0, &x, &y));
    CALL("swarp_bias_depth_per_world", swarp_bias_depth_per_world(m, L, &p, &x));
    CALL("swarp_bias_receiver_plane", swarp_bias_receiver_plane(m, &p, &Ta, &Tb, g));
#undef CALL
    if (failures) printf("\n%ld calls failed\n", failures);
}

int main(void) {
    printf("libshadowwarp %s bias benchmark\n", swarp_version_string());
    bench_map u = uniform_map(), s = projective_map();
    bench(&u);
    bench(&s);
    return 0;
}
