/* Benchmark of swarp_setup (the one call): median and p99 nanoseconds per
 * call for each technique, directional vs point light, and the number of
 * heap allocations made while it runs (counted by interposing malloc &
 * co. in this program; glibc's __libc_* entry points do the work).
 * Asserts nothing; prints a table.  docs/performance.md explains it. */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>

#include "shadowwarp.h"

/* ---- allocation counter (the benchmark's own state, not the library's) */
extern void* __libc_malloc(size_t);
extern void* __libc_calloc(size_t, size_t);
extern void* __libc_realloc(void*, size_t);
static volatile long g_allocs;
void* malloc(size_t n) {
    g_allocs++;
    return __libc_malloc(n);
}
void* calloc(size_t a, size_t b) {
    g_allocs++;
    return __libc_calloc(a, b);
}
void* realloc(void* p, size_t n) {
    g_allocs++;
    return __libc_realloc(p, n);
}

static uint64_t sm_state = 0x12345678ull;
static double rnd(double a, double b) {
    uint64_t z = (sm_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return a + (b - a) * ((z >> 11) * 0x1.0p-53);
}

static double now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}
static int cmp(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

#define NCONF 64
#define REPS 20000

/* `bench_setup --calls N [point|directional] [default]`: only N untimed
 * calls, LiSPSM n_opt without measurement (with `default`: the default
 * measured warp and its measurement), for instruction and cycle counts
 * (perf stat, perf record, callgrind): subtract N = 0. */
int main(int argc, char** argv) {
    long calls = argc >= 3 && strcmp(argv[1], "--calls") == 0 ? atol(argv[2]) : -1;
    int calls_point = argc >= 4 && strcmp(argv[3], "point") == 0;
    int calls_default = argc >= 5 && strcmp(argv[4], "default") == 0;
    /* a walkthrough-like set: camera inside a terrain box, looking around */
    swarp_camera cams[NCONF];
    swarp_vec3 dirs[NCONF];
    swarp_aabb box = {{-500, -10, -500}, {500, 60, 500}};
    for (int i = 0; i < NCONF; ++i) {
        memset(&cams[i], 0, sizeof cams[i]);
        double yaw = rnd(0, 6.283), pitch = rnd(-0.4, 0.1);
        cams[i].eye = (swarp_vec3){rnd(-300, 300), rnd(2, 20), rnd(-300, 300)};
        cams[i].dir = (swarp_vec3){cos(pitch) * sin(yaw), sin(pitch), -cos(pitch) * cos(yaw)};
        cams[i].up = (swarp_vec3){0, 1, 0};
        cams[i].fovy = 60 * 3.14159265358979 / 180;
        cams[i].aspect = 16.0 / 9.0;
        cams[i].z_near = 0.5;
        cams[i].z_far = 400;
        double el = rnd(0.3, 1.5), az = rnd(0, 6.283);
        dirs[i] = (swarp_vec3){-cos(el) * sin(az), -sin(el), cos(el) * cos(az)};
    }
    static const struct {
        const char* name;
        swarp_technique t;
        swarp_warp_param p;
    } techs[] = {{"uniform", SWARP_TECHNIQUE_UNIFORM, SWARP_WARP_PARAM_DEFAULT},
                 {"lispsm (default: measured)", SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_MEASURED},
                 {"lispsm (n_opt)", SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_NOPT},
                 {"lispsm (n_repar)", SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_NREPAR},
                 {"lispsm (gmnpr)", SWARP_TECHNIQUE_LISPSM, SWARP_WARP_PARAM_GMNPR},
                 {"psm", SWARP_TECHNIQUE_PSM, SWARP_WARP_PARAM_DEFAULT}};
    if (calls >= 0) {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = SWARP_TECHNIQUE_LISPSM;
        o.param = calls_default ? SWARP_WARP_PARAM_DEFAULT : SWARP_WARP_PARAM_NOPT;
        o.skip_measure = calls_default ? 0u : 1u;
        swarp_light light;
        memset(&light, 0, sizeof light);
        light.type = calls_point ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
        swarp_setup_result r;
        swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
        size_t np;
        long ok = 0;
        for (long k = 0; k < calls; ++k) {
            const swarp_camera* c = &cams[k % NCONF];
            light.direction = dirs[k % NCONF];
            light.position = (swarp_vec3){c->eye.x - 800 * dirs[k % NCONF].x, 800.0,
                                          c->eye.z - 800 * dirs[k % NCONF].z};
            ok += !swarp_status_is_error(swarp_setup(c, &light, &box, &o, &r, pts, SWARP_BODY_MAX_POINTS, &np));
        }
        printf("%ld of %ld calls ok\n", ok, calls);
        return 0;
    }
    static double ns[REPS];
    printf("swarp_setup, %d configurations, %d calls per row (libshadowwarp %s)\n\n", NCONF, REPS,
           swarp_version_string());
    printf("| technique | light | measured error | median ns | p99 ns | ok calls | heap allocations |\n");
    printf("|---|---|---|---:|---:|---:|---:|\n");
    for (size_t t = 0; t < sizeof techs / sizeof techs[0]; ++t) {
        for (int row = 0; row < 4; ++row) {
            const int point = row & 1, skip = row >> 1;
            swarp_setup_options o;
            memset(&o, 0, sizeof o);
            o.technique = techs[t].t;
            o.param = techs[t].p;
            o.skip_measure = (uint32_t)skip; /* the setup without its measurement, beside it */
            swarp_light light;
            memset(&light, 0, sizeof light);
            swarp_setup_result r;
            swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
            size_t np;
            long ok = 0;
            /* warm-up */
            for (int k = 0; k < 2000; ++k) {
                const swarp_camera* c = &cams[k % NCONF];
                light.type = point ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
                light.direction = dirs[k % NCONF];
                light.position = (swarp_vec3){c->eye.x - 800 * dirs[k % NCONF].x, 800.0,
                                              c->eye.z - 800 * dirs[k % NCONF].z};
                (void)swarp_setup(c, &light, &box, &o, &r, pts, SWARP_BODY_MAX_POINTS, &np);
            }
            long a0 = g_allocs;
            for (int k = 0; k < REPS; ++k) {
                const swarp_camera* c = &cams[k % NCONF];
                light.type = point ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
                light.direction = dirs[k % NCONF];
                light.position = (swarp_vec3){c->eye.x - 800 * dirs[k % NCONF].x, 800.0,
                                              c->eye.z - 800 * dirs[k % NCONF].z};
                double t0 = now_ns();
                swarp_status s = swarp_setup(c, &light, &box, &o, &r, pts, SWARP_BODY_MAX_POINTS, &np);
                ns[k] = now_ns() - t0;
                ok += !swarp_status_is_error(s);
            }
            long allocs = g_allocs - a0;
            qsort(ns, REPS, sizeof ns[0], cmp);
            printf("| %s | %s | %s | %.0f | %.0f | %ld | %ld |\n", techs[t].name, point ? "point" : "directional",
                   skip ? "skipped" : "measured", ns[REPS / 2], ns[(int)(REPS * 0.99)], ok, allocs);
        }
    }
    printf("\n(clock_gettime overhead, about 20-40 ns, is included in every sample)\n");
    return 0;
}
