#define _POSIX_C_SOURCE 200809L
/* Benchmark (not a test): per-call cost of the core closed forms and of the
 * extras, median and p99 over many repetitions.  `meson test --benchmark`
 * runs it; docs/extras.md quotes the min-depth rows. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "shadowwarp.h"


enum { REPS = 301 };
static volatile double sink;

/* times `inner` calls of body per repetition; prints ns per call */
#define BENCH(name, inner, ...)                                                  \
    do {                                                                         \
        double t[REPS];                                                          \
        for (int r = 0; r < REPS; ++r) {                                         \
            double t0 = now_ns();                                                \
            for (int i = 0; i < (inner); ++i) { __VA_ARGS__; }                        \
            t[r] = (now_ns() - t0) / (inner);                                    \
        }                                                                        \
        qsort(t, REPS, sizeof t[0], cmp_double);                                 \
        printf("%-44s %12.1f %12.1f\n", name, t[REPS / 2], t[(REPS * 99) / 100]); \
    } while (0)

int main(void) {
    printf("libshadowwarp %s core/extras benchmark: ns per call, %d repetitions\n", swarp_version_string(), REPS);
    printf("%-44s %12s %12s\n", "function", "median", "p99");
    double out = 0, a = 0, b = 0;
    BENCH("swarp_warp_nopt", 1000, swarp_warp_nopt(99.0, 1.0, 100.0 + i * 1e-9, &out); sink = out);
    BENCH("swarp_warp_wlz + eta + nrepar", 1000, {
        double W, e;
        swarp_warp_wlz(0.5 + i * 1e-6, 0.5, 1, 100, 1.1, &W);
        swarp_warp_eta(0.5 + i * 1e-6, 0.5, &e);
        swarp_warp_nrepar(e, 100, W, &out);
        sink = out;
    });
    BENCH("swarp_gmnpr_lambda", 1000, swarp_gmnpr_lambda(0.3 + i * 1e-6, 0.5235987755982988, 1, 100, &out); sink = out);
    swarp_error_config cfg = {1, 100, 0.5235987755982988, 1024, 768, 1024, 1024, {0}};
    BENCH("swarp_error_max", 1000, swarp_error_max(&cfg, 11.0 + i * 1e-6, &a, &b); sink = a + b);
    double C[SWARP_SPLIT_MAX_COUNT + 1];
    size_t cnt;
    BENCH("swarp_split_practical (m = 4)", 1000, swarp_split_practical(1, 100 + i * 1e-6, 0.5, 4, C, 65, &cnt); sink = C[2]);
    swarp_vec4 L = {0.3, 0.2, 3.0, 1.0};
    swarp_cube_face faces[6];
    BENCH("swarp_cube_faces (5 faces)", 200, { L.x = 0.3 + i * 1e-6; swarp_cube_faces(&L, NULL, faces, 6, &cnt); sink = faces[0].distance; });
    swarp_vec3 V = {0.1, 0.2, 0.3}, S;
    uint32_t face;
    BENCH("swarp_cube_lookup", 1000, { V.x = 0.1 + i * 1e-6; swarp_cube_lookup(&L, NULL, &V, &face, &S, &out); sink = out; });

    static const unsigned sizes[][2] = {{1024, 768}, {1920, 1080}, {1023, 767}};
    for (int k = 0; k < 3; ++k) {
        unsigned w = sizes[k][0], h = sizes[k][1];
        float* buf = malloc((size_t)w * h * sizeof *buf);
        float* scratch = malloc(SWARP_MINDEPTH_SCRATCH(w, h) * sizeof *scratch);
        if (!buf || !scratch) return 1;
        uint64_t s = 12345;
        for (size_t i = 0; i < (size_t)w * h; ++i) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            buf[i] = 1.0f + (float)(s >> 40) / (float)(1u << 24) * 500.0f;
        }
        char name[64];
        size_t need;
        snprintf(name, sizeof name, "swarp_mindepth_pyramid %ux%u", w, h);
        BENCH(name, 1, swarp_mindepth_pyramid(buf, w, h, w, scratch, SWARP_MINDEPTH_SCRATCH(w, h), &need, &out); sink = out);
        snprintf(name, sizeof name, "swarp_mindepth_direct  %ux%u", w, h);
        BENCH(name, 1, swarp_mindepth_direct(buf, w, h, w, &out); sink = out);
        free(buf);
        free(scratch);
    }
    return 0;
}
