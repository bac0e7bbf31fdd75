/* bench_filter: cost of the filter-stage functions per call (CPU, double).
 * Not a test: `meson test --benchmark` runs it, it prints a markdown table
 * (median and p99 over repeated batches) and the machine it ran on. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_util.h"
#include "shadowwarp.h"

#define BATCHES 301
#define CALLS 1000


static volatile double sink; /* keeps the calls alive */
static double in_t[CALLS];

typedef void (*bench_fn)(int calls);

static void b_chebyshev(int calls) {
    double M[2] = {0.4, 0.2}, p, acc = 0;
    for (int i = 0; i < calls; ++i) {
        swarp_vsm_chebyshev(M, in_t[i], 1e-6, &p);
        acc += p;
    }
    sink = acc;
}
static const double splits4[5] = {0.0, 0.25, 0.5, 0.75, 1.0};
static const double lm4[8] = {0.1, 0.02, 0.3, 0.12, 0.5, 0.3, 0.6, 0.4};
static void b_lvsm(int calls) {
    double v, acc = 0;
    for (int i = 0; i < calls; ++i) {
        swarp_lvsm_visibility(lm4, splits4, 4, 0.02, 0.01, in_t[i], 1e-6, &v);
        acc += v;
    }
    sink = acc;
}
static void b_evsm(int calls) {
    double m[4] = {3.0, 12.0, -0.3, 0.1}, v, acc = 0;
    for (int i = 0; i < calls; ++i) {
        swarp_evsm_visibility(m, in_t[i], 5.0, 5.0, 1e-6, &v);
        acc += v;
    }
    sink = acc;
}
static void b_msm(int calls) {
    double b[4] = {0.45, 0.25, 0.16, 0.11}, bb[4], v, acc = 0;
    swarp_msm_bias(b, SWARP_MSM_ALPHA_DEFAULT, bb);
    for (int i = 0; i < calls; ++i) {
        swarp_msm_visibility(bb, in_t[i], &v);
        acc += v;
    }
    sink = acc;
}
static void b_penumbra(int calls) {
    double w, acc = 0;
    for (int i = 0; i < calls; ++i) {
        swarp_pcss_penumbra(2.0, 1.0 + in_t[i], 0.1, &w);
        acc += w;
    }
    sink = acc;
}

/* Lloyd on a 64x64 map's 2x2 samples (3969), 4 layers: per call, not per sample. */
static double lloyd_mu[3969], lloyd_s2[3969];
static void b_lloyd(int calls) {
    double out[5], init[5] = {0.0, 0.25, 0.5, 0.75, 1.0};
    for (int i = 0; i < calls; ++i) {
        swarp_lvsm_lloyd(lloyd_mu, lloyd_s2, 3969, NULL, init, 4, out, NULL);
        sink = out[1];
    }
}
static void b_poisson(int calls) {
    double xy[128], md;
    size_t n;
    for (int i = 0; i < calls; ++i) {
        swarp_pcf_poisson_disk((uint64_t)i, 64, 0, xy, 64, &n, &md);
        sink = md;
    }
}

static void run(const char* name, bench_fn f, int calls) {
    static double t[BATCHES];
    f(calls); /* warm-up */
    for (int b = 0; b < BATCHES; ++b) {
        double t0 = now_ns();
        f(calls);
        t[b] = (now_ns() - t0) / calls;
    }
    qsort(t, BATCHES, sizeof t[0], cmp_double);
    printf("| %s | %.1f | %.1f |\n", name, t[BATCHES / 2], t[(int)(BATCHES * 0.99)]);
}

int main(void) {
    uint64_t s = 1;
    for (int i = 0; i < CALLS; ++i) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        in_t[i] = (double)(s >> 11) * 0x1.0p-53;
    }
    /* a step image: 0.2 left, 0.5 middle, 0.9 right */
    size_t n = 0;
    for (int y = 0; y < 63; ++y)
        for (int x = 0; x < 63; ++x) {
            double d[4];
            for (int k = 0; k < 4; ++k) {
                int xx = x + (k & 1);
                d[k] = xx < 20 ? 0.2 : (xx < 40 ? 0.5 : 0.9);
            }
            double m1 = 0.25 * (d[0] + d[1] + d[2] + d[3]);
            double m2 = 0.25 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
            lloyd_mu[n] = m1;
            lloyd_s2[n++] = m2 - m1 * m1;
        }
    char model[256] = "unknown";
    FILE* f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "model name", 10) == 0) {
                char* c = strchr(line, ':');
                if (c) snprintf(model, sizeof model, "%s", c + 2);
                model[strcspn(model, "\n")] = 0;
                break;
            }
        fclose(f);
    }
    printf("bench_filter: %ld online CPUs, %s; %d batches, ns per call\n\n",
           sysconf(_SC_NPROCESSORS_ONLN), model, BATCHES);
    printf("| function | median ns | p99 ns |\n|---|---|---|\n");
    run("swarp_vsm_chebyshev", b_chebyshev, CALLS);
    run("swarp_lvsm_visibility (4 layers, band)", b_lvsm, CALLS);
    run("swarp_evsm_visibility", b_evsm, CALLS);
    run("swarp_msm_visibility", b_msm, CALLS);
    run("swarp_pcss_penumbra", b_penumbra, CALLS);
    run("swarp_lvsm_lloyd (3969 samples of a step image, 126 weighted; 4 layers)", b_lloyd, 2);
    run("swarp_pcf_poisson_disk (64 points)", b_poisson, 2);
    return 0;
}
