#define _POSIX_C_SOURCE 200809L
/* Benchmark of the cascade setup: PSSM(K) + LiSPSM + per-split bodies for a
 * directional light, K = 1, 2, 4, 8, 16.  Prints median and p99 of the time
 * per call over many repetitions and the number of heap allocations made
 * inside the library during the timed calls (malloc/calloc/realloc/free are
 * wrapped at link time: -Wl,--wrap=...).  Not a test: `meson test
 * --benchmark` runs it and the numbers go to docs/performance.md. */
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
static int cmp_double(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

#define REPS 2000
#define BATCH 8

typedef int (*bench_fn)(void* ctx, int k);

/* median and p99 in microseconds per call; returns allocations seen */
static long run(bench_fn fn, void* ctx, double* med, double* p99) {
    static double t[REPS];
    for (int w = 0; w < 200; ++w) fn(ctx, w); /* warm-up */
    g_allocs = 0;
    for (int r = 0; r < REPS; ++r) {
        double t0 = now_ns();
        for (int b = 0; b < BATCH; ++b) fn(ctx, r * BATCH + b);
        t[r] = (now_ns() - t0) / BATCH / 1000.0;
    }
    long a = g_allocs;
    qsort(t, REPS, sizeof t[0], cmp_double);
    *med = t[REPS / 2];
    *p99 = t[(REPS * 99) / 100];
    return a;
}
