/* filter_table: brute-force PCF over small synthetic depth images as the
 * reference for the filtered shadow maps of the filter stage.
 *
 *   filter_table table   markdown table: mean and max |filter - PCF| per scene
 *   filter_table plot    columns for docs/plots/filter_edge.gp: visibility
 *                        across a shadow edge with overlapping occluders
 *                        (Fig. 3.4-like) for PCF, VSM, LVSM, EVSM and MSM
 *
 * Every filter sees exactly the PCF kernel: its moments are the box average
 * of the per-texel moments over the same (2R+1)^2 texels, in double.  So the
 * differences are those of the representations, not of texture filtering.
 * Used by docs/filtering.md; registered as a meson test so it keeps working.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"

#define SZ 64         /* image side, texels */
#define R 3           /* kernel radius: 7x7 box */
#define MAX_SURF 8    /* surfaces per scene */
#define MIN_VAR 1e-6  /* VSM variance floor in depth units (typical for [0, 1] depths) */
#define N_LAYERS 4
#define DELTA 0.02    /* LVSM overlap */
#define BAND 0.01     /* LVSM transition half width */

static void check(swarp_status st, const char* what) {
    if (swarp_status_is_error(st)) {
        fprintf(stderr, "filter_table: %s: %s\n", what, swarp_status_string(st));
        exit(1);
    }
}

/* A scene: axis-aligned rectangles of constant depth (fronto-parallel to the
 * light), the last one the ground covering everything. */
typedef struct {
    int x0, y0, x1, y1; /* texel rectangle [x0, x1) x [y0, y1) */
    double depth;
} surf;
typedef struct {
    const char* name;
    int n;
    surf s[MAX_SURF];
} scene;

static double depth_img[SZ][SZ];

static void rasterise(const scene* sc) {
    for (int y = 0; y < SZ; ++y)
        for (int x = 0; x < SZ; ++x) {
            double d = 1.0;
            for (int i = 0; i < sc->n; ++i) {
                const surf* f = &sc->s[i];
                if (x >= f->x0 && x < f->x1 && y >= f->y0 && y < f->y1 && f->depth < d) d = f->depth;
            }
            depth_img[y][x] = d;
        }
}

/* All the filters at one receiver, given the kernel's texel depths. */
enum { F_VSM, F_LVSM_U, F_LVSM_L, F_EVSM32, F_EVSM16, F_MSM, F_COUNT };
static const char* f_names[F_COUNT] = {
    "VSM", "LVSM(4), uniform splits", "LVSM(4), Lloyd splits", "EVSM, c for fp32",
    "EVSM, c for fp16", "MSM, alpha = 3e-5"};

typedef struct {
    double splits_u[N_LAYERS + 1], splits_l[N_LAYERS + 1];
    double delta_l, band_l; /* for the Lloyd splits: kept inside thin layers */
    double c32, c16;
} filt_cfg;

/* Lloyd may place two splits close together: overlap and band must stay
 * below the thinnest layer (and half of it) to be valid. */
static void fit_overlap(filt_cfg* cfg) {
    double thin = 1.0;
    for (int i = 0; i < N_LAYERS; ++i) thin = fmin(thin, cfg->splits_l[i + 1] - cfg->splits_l[i]);
    cfg->delta_l = fmin(DELTA, 0.4 * thin);
    cfg->band_l = fmin(BAND, 0.4 * cfg->delta_l);
}

static void layer_moments(const double* z, int n, const double* splits, double delta, double* lm) {
    for (int i = 0; i < N_LAYERS; ++i) {
        double p, q;
        check(swarp_lvsm_layer_interval(splits, N_LAYERS, (uint32_t)i, delta, &p, &q), "interval");
        lm[2 * i] = lm[2 * i + 1] = 0.0;
        for (int k = 0; k < n; ++k) {
            double m[2];
            check(swarp_lvsm_moments(z[k], p, q, m), "lvsm moments");
            lm[2 * i] += m[0] / n;
            lm[2 * i + 1] += m[1] / n;
        }
    }
}

static void eval_filters(const double* z, int n, double t, const filt_cfg* cfg, double* out,
                         double* pcf_out) {
    double M[2] = {0, 0}, B[4] = {0, 0, 0, 0}, E32[4] = {0, 0, 0, 0}, E16[4] = {0, 0, 0, 0};
    int lit = 0;
    for (int k = 0; k < n; ++k) {
        double m[4];
        if (z[k] >= t) ++lit;
        check(swarp_vsm_moments(z[k], m), "vsm moments");
        M[0] += m[0] / n;
        M[1] += m[1] / n;
        check(swarp_msm_moments(z[k], m), "msm moments");
        for (int j = 0; j < 4; ++j) B[j] += m[j] / n;
        check(swarp_evsm_moments(z[k], cfg->c32, cfg->c32, m), "evsm moments");
        for (int j = 0; j < 4; ++j) E32[j] += m[j] / n;
        check(swarp_evsm_moments(z[k], cfg->c16, cfg->c16, m), "evsm moments");
        for (int j = 0; j < 4; ++j) E16[j] += m[j] / n;
    }
    *pcf_out = (double)lit / n;
    check(swarp_vsm_chebyshev(M, t, MIN_VAR, &out[F_VSM]), "vsm");
    double lm[2 * N_LAYERS];
    layer_moments(z, n, cfg->splits_u, DELTA, lm);
    check(swarp_lvsm_visibility(lm, cfg->splits_u, N_LAYERS, DELTA, BAND, t, MIN_VAR,
                                &out[F_LVSM_U]), "lvsm");
    layer_moments(z, n, cfg->splits_l, cfg->delta_l, lm);
    check(swarp_lvsm_visibility(lm, cfg->splits_l, N_LAYERS, cfg->delta_l, cfg->band_l, t, MIN_VAR,
                                &out[F_LVSM_L]), "lvsm lloyd");
    check(swarp_evsm_visibility(E32, t, cfg->c32, cfg->c32, MIN_VAR, &out[F_EVSM32]), "evsm");
    check(swarp_evsm_visibility(E16, t, cfg->c16, cfg->c16, MIN_VAR, &out[F_EVSM16]), "evsm");
    double Bb[4];
    check(swarp_msm_bias(B, SWARP_MSM_ALPHA_DEFAULT, Bb), "msm bias");
    check(swarp_msm_visibility(Bb, t, &out[F_MSM]), "msm");
}

/* Lloyd splits from the 2x2-filtered unwarped VSM of the image ([VSM] §4.1.3). */
static void lloyd_splits(const double* img, int w, int h, double* splits) {
    static double mu[SZ * SZ], s2[SZ * SZ];
    size_t n = 0;
    for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x + 1 < w; ++x) {
            double a = img[y * w + x], b = img[y * w + x + 1], c = img[(y + 1) * w + x],
                   d = img[(y + 1) * w + x + 1];
            double m1 = 0.25 * (a + b + c + d), m2 = 0.25 * (a * a + b * b + c * c + d * d);
            mu[n] = m1;
            s2[n++] = m2 - m1 * m1;
        }
    double init[N_LAYERS + 1];
    for (int i = 0; i <= N_LAYERS; ++i) init[i] = (double)i / N_LAYERS;
    swarp_lloyd_report rep;
    check(swarp_lvsm_lloyd(mu, s2, n, NULL, init, N_LAYERS, splits, &rep), "lloyd");
    fprintf(stderr, "Lloyd: %u iterations, %u teleports, converged %u\n", rep.iterations,
            rep.teleports, rep.converged);
}

static void init_cfg(filt_cfg* cfg) {
    for (int i = 0; i <= N_LAYERS; ++i) cfg->splits_u[i] = (double)i / N_LAYERS;
    check(swarp_evsm_max_exponent(SWARP_TEXEL_FP32, &cfg->c32), "c32");
    check(swarp_evsm_max_exponent(SWARP_TEXEL_FP16, &cfg->c16), "c16");
}

static const scene scenes[] = {
    {"planes", 2, {{0, 0, 32, SZ, 0.3}, {0, 0, SZ, SZ, 0.7}}},
    {"steps", 4,
     {{0, 0, 40, SZ, 0.45}, {0, 20, SZ, 28, 0.2}, {40, 0, SZ, SZ, 0.8}, {0, 0, SZ, SZ, 0.95}}},
    {"overlap", 3, {{0, 0, 24, SZ, 0.2}, {0, 0, 44, SZ, 0.5}, {0, 0, SZ, SZ, 0.9}}},
    {"overlap, many", 6,
     {{6, 6, 30, 40, 0.15},
      {20, 14, 50, 36, 0.3},
      {10, 30, 58, 52, 0.42},
      {36, 4, 60, 60, 0.6},
      {0, 0, 54, 58, 0.75},
      {0, 0, SZ, SZ, 0.97}}},
};
#define N_SCENES ((int)(sizeof scenes / sizeof scenes[0]))

static int run_table(void) {
    double mean[N_SCENES][F_COUNT], maxe[N_SCENES][F_COUNT];
    long counts[N_SCENES];
    for (int si = 0; si < N_SCENES; ++si) {
        const scene* sc = &scenes[si];
        rasterise(sc);
        filt_cfg cfg;
        init_cfg(&cfg);
        lloyd_splits(&depth_img[0][0], SZ, SZ, cfg.splits_l);
        fit_overlap(&cfg);
        double sum[F_COUNT] = {0}, mx[F_COUNT] = {0};
        long cnt = 0;
        for (int y = R; y < SZ - R; ++y)
            for (int x = R; x < SZ - R; ++x) {
                double z[(2 * R + 1) * (2 * R + 1)];
                int n = 0;
                for (int dy = -R; dy <= R; ++dy)
                    for (int dx = -R; dx <= R; ++dx) z[n++] = depth_img[y + dy][x + dx];
                /* shade every surface covering this texel, visible or hidden */
                for (int i = 0; i < sc->n; ++i) {
                    const surf* f = &sc->s[i];
                    if (!(x >= f->x0 && x < f->x1 && y >= f->y0 && y < f->y1)) continue;
                    double v[F_COUNT], ref;
                    eval_filters(z, n, f->depth, &cfg, v, &ref);
                    for (int k = 0; k < F_COUNT; ++k) {
                        double e = fabs(v[k] - ref);
                        sum[k] += e;
                        if (e > mx[k]) mx[k] = e;
                    }
                    ++cnt;
                }
            }
        for (int k = 0; k < F_COUNT; ++k) {
            mean[si][k] = sum[k] / (double)cnt;
            maxe[si][k] = mx[k];
        }
        counts[si] = cnt;
        fprintf(stderr, "%s: Lloyd splits %.4f %.4f %.4f %.4f %.4f\n", sc->name, cfg.splits_l[0],
                cfg.splits_l[1], cfg.splits_l[2], cfg.splits_l[3], cfg.splits_l[4]);
    }
    printf("| filter |");
    for (int si = 0; si < N_SCENES; ++si) printf(" %s (%ld shading points): mean / max |", scenes[si].name, counts[si]);
    printf("\n|---|");
    for (int si = 0; si < N_SCENES; ++si) printf("---|");
    printf("\n");
    for (int k = 0; k < F_COUNT; ++k) {
        printf("| %s |", f_names[k]);
        for (int si = 0; si < N_SCENES; ++si) printf(" %.4f / %.4f |", mean[si][k], maxe[si][k]);
        printf("\n");
    }
    return 0;
}

/* 1-D cross-section, Fig. 3.4-like: B (depth 0.7) covers x < 160, A (0.1)
 * covers x < 80 above it, C (0.9) is the ground.  Receiver B crosses A's
 * shadow edge at x = 80; receiver C lies under B (truth 0) until B's edge. */
static int run_plot(void) {
    enum { W = 240, RP = 12 };
    double img[W];
    for (int x = 0; x < W; ++x) img[x] = (x < 80) ? 0.1 : (x < 160 ? 0.7 : 0.9);
    filt_cfg cfg;
    init_cfg(&cfg);
    memcpy(cfg.splits_l, cfg.splits_u, sizeof cfg.splits_l); /* the plot shows uniform LVSM */
    fit_overlap(&cfg);
    printf("# x  pcf_B vsm_B lvsm_B evsm_B msm_B  pcf_C vsm_C lvsm_C evsm_C msm_C\n");
    for (int x = RP; x < W - RP; ++x) {
        double z[2 * RP + 1];
        int n = 0;
        for (int d = -RP; d <= RP; ++d) z[n++] = img[x + d];
        double vb[F_COUNT], vc[F_COUNT], rb, rc;
        eval_filters(z, n, 0.7, &cfg, vb, &rb);
        eval_filters(z, n, 0.9, &cfg, vc, &rc);
        printf("%d  %.6f %.6f %.6f %.6f %.6f  %.6f %.6f %.6f %.6f %.6f\n", x, rb, vb[F_VSM],
               vb[F_LVSM_U], vb[F_EVSM32], vb[F_MSM], rc, vc[F_VSM], vc[F_LVSM_U], vc[F_EVSM32],
               vc[F_MSM]);
    }
    return 0;
}

int main(int argc, char** argv) {
    if (argc == 2 && strcmp(argv[1], "table") == 0) return run_table();
    if (argc == 2 && strcmp(argv[1], "plot") == 0) return run_plot();
    fprintf(stderr, "usage: filter_table table|plot\n");
    return 2;
}
