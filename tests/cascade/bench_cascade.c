#define _POSIX_C_SOURCE 200809L
/* Benchmark of the cascade setup: PSSM(K) + LiSPSM + per-split bodies for a
 * directional light, K = 1, 2, 4, 8, 16.  Prints median and p99 of the time
 * per call over many repetitions and the number of heap allocations made
 * inside the library during the timed calls (malloc/calloc/realloc/free are
 * wrapped at link time: -Wl,--wrap=...).  Not a test: `meson test
 * --benchmark` runs it and the numbers go to docs/performance.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "shadowwarp.h"

/* ---- allocation counter ------------------------------------------------- */
static long g_allocs;
void* __real_malloc(size_t n);
void* __real_calloc(size_t a, size_t b);
void* __real_realloc(void* p, size_t n);
void __real_free(void* p);
void* __wrap_malloc(size_t n) { ++g_allocs; return __real_malloc(n); }
void* __wrap_calloc(size_t a, size_t b) { ++g_allocs; return __real_calloc(a, b); }
void* __wrap_realloc(void* p, size_t n) { ++g_allocs; return __real_realloc(p, n); }
void __wrap_free(void* p) { if (p) ++g_allocs; __real_free(p); }

static double now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}
/* CPU time of this thread: on a loaded machine (other jobs on the 2 cores)
 * wall time includes waiting for a core; thread CPU time does not. */
static double cpu_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}
static int cmp_double(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

#define REPS 2000
#define BATCH 8

typedef int (*bench_fn)(void* ctx, int k);

/* median and p99 in microseconds per call, wall clock and thread CPU time;
 * returns the allocations seen */
static long run(bench_fn fn, void* ctx, double* med, double* p99, double* cmed, double* cp99) {
    static double t[REPS], c[REPS];
    for (int w = 0; w < 200; ++w) fn(ctx, w); /* warm-up */
    g_allocs = 0;
    for (int r = 0; r < REPS; ++r) {
        double t0 = now_ns(), c0 = cpu_ns();
        for (int b = 0; b < BATCH; ++b) fn(ctx, r * BATCH + b);
        c[r] = (cpu_ns() - c0) / BATCH / 1000.0;
        t[r] = (now_ns() - t0) / BATCH / 1000.0;
    }
    long a = g_allocs;
    qsort(t, REPS, sizeof t[0], cmp_double);
    qsort(c, REPS, sizeof c[0], cmp_double);
    *med = t[REPS / 2];
    *p99 = t[(REPS * 99) / 100];
    *cmed = c[REPS / 2];
    *cp99 = c[(REPS * 99) / 100];
    return a;
}

/* ---- the configurations -------------------------------------------------- */
typedef struct bench_ctx {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb scene;
    swarp_cascade_options opt;
    long failures;
} bench_ctx;

/* one call per frame; the camera turns a little each frame so no two calls
 * see the same input */
static int bench_cascade(void* p, int k) {
    bench_ctx* c = (bench_ctx*)p;
    swarp_camera cam = c->cam;
    double a = 0.002 * (k % 1000);
    cam.dir.x = sin(a);
    cam.dir.z = -cos(a);
    swarp_cascade_result r;
    swarp_cascade_split s[SWARP_CASCADE_MAX_SPLITS];
    size_t n;
    swarp_status st = swarp_cascade_setup(&cam, &c->light, &c->scene, &c->opt, &r, s,
                                          SWARP_CASCADE_MAX_SPLITS, &n);
    if (swarp_status_is_error(st)) ++c->failures;
    return (int)n;
}

/* `bench_splits --calls N K`: only N untimed calls with K splits, for
 * instruction and cycle counts (perf stat, callgrind): subtract N = 0. */
int main(int argc, char** argv) {
    bench_ctx c;
    memset(&c, 0, sizeof c);
    c.cam.eye = (swarp_vec3){0.0, 20.0, 0.0};
    c.cam.dir = (swarp_vec3){0.0, -0.3, -1.0};
    c.cam.up = (swarp_vec3){0.0, 1.0, 0.0};
    c.cam.fovy = 60.0 * 3.14159265358979323846 / 180.0;
    c.cam.aspect = 16.0 / 9.0;
    c.cam.z_near = 0.5;
    c.cam.z_far = 2000.0;
    c.light.type = SWARP_LIGHT_DIRECTIONAL;
    c.light.direction = (swarp_vec3){0.3, -1.0, 0.2};
    c.scene.min = (swarp_vec3){-1000.0, -10.0, -1000.0};
    c.scene.max = (swarp_vec3){1000.0, 120.0, 1000.0};
    c.opt.setup.technique = SWARP_TECHNIQUE_LISPSM; /* n_opt, [RHS] §4.1 centre */
    c.opt.split.scheme = SWARP_SCHEME_PRACTICAL;     /* PSSM */
    c.opt.split.lambda = 0.5;
    if (argc >= 4 && strcmp(argv[1], "--calls") == 0) {
        long calls = atol(argv[2]);
        c.opt.split.count = (uint32_t)atoi(argv[3]);
        for (long k = 0; k < calls; ++k) bench_cascade(&c, (int)(k % 1000));
        printf("%ld calls, %ld failed\n", calls, c.failures);
        return c.failures ? 1 : 0;
    }

    printf("bench_splits: swarp_cascade_setup, PSSM(K, lambda 0.5) + LiSPSM (n_opt) + per-split bodies,\n");
    printf("directional light, scene box 2000 x 130 x 2000, camera 60 deg 16:9, near 0.5, far 2000.\n");
    printf("%d repetitions of %d calls each; times per call.\n\n", REPS, BATCH);
    printf("| splits K | median [us] | p99 [us] | CPU median [us] | CPU p99 [us] | heap allocations |\n");
    printf("|---:|---:|---:|---:|---:|---:|\n");
    const uint32_t ks[5] = {1, 2, 4, 8, 16};
    for (int i = 0; i < 5; ++i) {
        c.opt.split.count = ks[i];
        double med, p99, cmed, cp99;
        long allocs = run(bench_cascade, &c, &med, &p99, &cmed, &cp99);
        printf("| %u | %.2f | %.2f | %.2f | %.2f | %ld |\n", ks[i], med, p99, cmed, cp99, allocs);
    }
    /* the default cascade: zeroed split options (SWARP_SCHEME_MEASURED, the
     * search over the practical lambda included), 4 splits */
    {
        memset(&c.opt.split, 0, sizeof c.opt.split);
        double med, p99, cmed, cp99;
        long allocs = run(bench_cascade, &c, &med, &p99, &cmed, &cp99);
        printf("| 4, default splits (measured) | %.2f | %.2f | %.2f | %.2f | %ld |\n", med, p99, cmed, cp99, allocs);
    }
    if (c.failures) {
        printf("\n%ld calls failed\n", c.failures);
        return 1;
    }
    return 0;
}
