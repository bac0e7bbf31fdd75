/* swtool bench-report: the accuracy/cost report of every technique.
 *
 * For every configuration (γ = 90, 60, 45, 30, 20, 10, 5, 0 and 150 degrees;
 * far/near = 100, 1000, 1e4; map 1024 and 2048; screen 1024x768) and every
 * technique (uniform; LiSPSM n_opt, n_repar, λ_GMNPR, pseudo-near/far; PSM
 * with the inverse projection when the light is behind; PSSM with 1, 2, 4,
 * 8, 16 splits unwarped, stabilised, or warped with n_opt; a lixel map on a
 * floor plane; the planner's own choice) it prints / writes: predicted max
 * m_x, m_z and their product ([RHS] (2.3)-(2.8) generalised, docs/planning.md),
 * the library time of the technique's setup (median and p99 over --reps
 * calls, measured in this run), shadow passes and texels.
 *
 *   swtool bench-report [--reps N] [--out-dir DIR] [--json] [--demo-data F] [--clone-data F]
 *
 * --out-dir writes DIR/accuracy-cost.md and DIR/plots/accuracy-cost.dat (and
 * accuracy-cost-front.dat, the Pareto fronts) for docs/plots/regen_accuracy_cost.sh.
 * Without the demo (no OSMesa) its measured columns read "n/a".
 * --clone-data F: the TSV of `demo-check --test bench-clone --bench-out F` (geometry
 * cloning against K + 1 passes, [RHS] §3.3.6), folded in as a table shaped
 * like [RHS] Tables 7.1/7.2; a file holding "# unavailable<TAB>reason" instead
 * (no OSMesa context) gives the section with that reason and no numbers.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"

#define BR_NG 9
#define BR_NF 3
#define BR_NM 2
static const double br_gammas[BR_NG] = {90, 60, 45, 30, 20, 10, 5, 0, 150};
static const double br_fns[BR_NF] = {100, 1000, 1e4};
static const unsigned br_maps[BR_NM] = {1024, 2048};

typedef struct br_tech {
    const char* name;
    int family; /* 1 one map, 2 PSSM unwarped, 3 PSSM stabilised, 4 PSSM warped, 5 lixel,
                 * 6 planner, 7 log splits, 8 log splits warped */
    swarp_plan_warp warp;
    swarp_plan_scheme scheme;
    uint32_t K;
    swarp_plan_stabilize stab;
    int lixel, planner;
} br_tech;

static const br_tech br_techs[] = {
    {"uniform focused", 1, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"LiSPSM n_opt", 1, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"LiSPSM n_repar", 1, SWARP_PLAN_WARP_LISPSM_NREPAR, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"LiSPSM GMNPR", 1, SWARP_PLAN_WARP_LISPSM_GMNPR, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"LiSPSM pseudo-near/far", 1, SWARP_PLAN_WARP_LISPSM_PSEUDO, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSM", 1, SWARP_PLAN_WARP_PSM, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(1)", 2, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(2)", 2, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 2, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(4)", 2, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 4, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(8)", 2, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 8, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(16)", 2, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 16, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(1) stabilised", 3, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_APPROX64, 0, 0},
    {"PSSM(2) stabilised", 3, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 2, SWARP_PLAN_STABILIZE_APPROX64, 0, 0},
    {"PSSM(4) stabilised", 3, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 4, SWARP_PLAN_STABILIZE_APPROX64, 0, 0},
    {"PSSM(8) stabilised", 3, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 8, SWARP_PLAN_STABILIZE_APPROX64, 0, 0},
    {"PSSM(16) stabilised", 3, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_PRACTICAL, 16, SWARP_PLAN_STABILIZE_APPROX64, 0, 0},
    {"PSSM(1) + n_opt", 4, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(2) + n_opt", 4, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_PRACTICAL, 2, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(4) + n_opt", 4, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_PRACTICAL, 4, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(8) + n_opt", 4, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_PRACTICAL, 8, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(16) + n_opt", 4, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_PRACTICAL, 16, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(4) log", 7, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_LOG, 4, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(8) log", 7, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_LOG, 8, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(16) log", 7, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_LOG, 16, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(4) log + n_opt", 8, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_LOG, 4, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(8) log + n_opt", 8, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_LOG, 8, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"PSSM(16) log + n_opt", 8, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_LOG, 16, SWARP_PLAN_STABILIZE_NONE, 0, 0},
    {"lixel floor (+ uniform fallback)", 5, SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1, SWARP_PLAN_STABILIZE_NONE, 1, 0},
    {"planner (E = 1)", 6, SWARP_PLAN_WARP_DEFAULT, SWARP_PLAN_SCHEME_DEFAULT, 0, SWARP_PLAN_STABILIZE_DEFAULT, 0, 1},
};
#define BR_NT (sizeof br_techs / sizeof br_techs[0])

typedef struct br_row {
    double mx, mz, area, t_med, t_p99, cost_ms;
    double g_med, g_p99;   /* the technique's real setup (geometry, splits, lixel stages) */
    double g_mx, g_mz;     /* the setup's own (2.3)/(2.4) report, max over splits */
    int g_ok;
    uint32_t passes;
    double texels;
    int ok, lixel_used, inverse;
    char chosen[96];
} br_row;

/* The report's camera: 2 above the floor y = 0 looking level along -z,
 * fovy 60°, aspect 4/3, near 1; the light at γ to the view in the view/up
 * plane (γ > 90°: behind the camera). */
static void br_scene(double gamma_deg, double fn, int floor, swarp_scene_needs* n) {
    memset(n, 0, sizeof *n);
    n->camera.eye = (swarp_vec3){0.0, 2.0, 0.0};
    n->camera.dir = (swarp_vec3){0.0, 0.0, -1.0};
    n->camera.up = (swarp_vec3){0.0, 1.0, 0.0};
    n->camera.fovy = 60.0 * SW_DEG;
    n->camera.aspect = 4.0 / 3.0;
    n->camera.z_near = 1.0;
    n->camera.z_far = fn;
    n->light.type = SWARP_LIGHT_DIRECTIONAL;
    n->light.direction = (swarp_vec3){0.0, -sin(gamma_deg * SW_DEG), cos(gamma_deg * SW_DEG)};
    n->screen_width = 1024;
    n->screen_height = 768;
    if (floor) {
        n->plane_count = 1;
        n->planes[0] = (swarp_plane){0.0, 1.0, 0.0, 0.0};
    }
}

static double br_now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static int br_cmp(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return x < y ? -1 : x > y;
}

/* The technique's real library setup, as an engine would call it: split
 * distances (core), then per split swarp_setup_range (geometry stage:
 * H, B, light view, warp, focus), plus the splits stage's stabiliser for the
 * stabilised rows and the lixel stage's plane matrix for the lixel row; the
 * planner row is swarp_plan itself.  Returns the status of the last call
 * (an error means the row has no setup time). */
static swarp_status br_setup_once(const br_tech* t, const swarp_scene_needs* n, const swarp_aabb* box,
                                  unsigned map, double* out_mx, double* out_mz) {
    double splits[SWARP_PLAN_MAX_SPLITS + 1];
    size_t cnt = 0;
    uint32_t K = t->K ? t->K : 1;
    swarp_status s = SWARP_OK;
    if (K == 1) {
        splits[0] = n->camera.z_near;
        splits[1] = n->camera.z_far;
    } else if (t->scheme == SWARP_PLAN_SCHEME_LOG) {
        s = swarp_split_log(n->camera.z_near, n->camera.z_far, K, splits, SWARP_PLAN_MAX_SPLITS + 1, &cnt);
    } else {
        s = swarp_split_practical(n->camera.z_near, n->camera.z_far, 0.5, K, splits, SWARP_PLAN_MAX_SPLITS + 1, &cnt);
    }
    if (swarp_status_is_error(s)) return s;
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.map_width = map;
    o.screen_width = n->screen_width;
    o.screen_height = n->screen_height;
    switch (t->warp) {
    case SWARP_PLAN_WARP_LISPSM_NOPT: o.technique = SWARP_TECHNIQUE_LISPSM; o.param = SWARP_WARP_PARAM_NOPT; break;
    case SWARP_PLAN_WARP_LISPSM_NREPAR: o.technique = SWARP_TECHNIQUE_LISPSM; o.param = SWARP_WARP_PARAM_NREPAR; break;
    case SWARP_PLAN_WARP_LISPSM_GMNPR: o.technique = SWARP_TECHNIQUE_LISPSM; o.param = SWARP_WARP_PARAM_GMNPR; break;
    case SWARP_PLAN_WARP_LISPSM_PSEUDO:
        o.technique = SWARP_TECHNIQUE_LISPSM;
        o.param = SWARP_WARP_PARAM_PSEUDO;
        o.pseudo_near = o.pseudo_far = 0.1;
        break;
    case SWARP_PLAN_WARP_PSM: o.technique = SWARP_TECHNIQUE_PSM; break;
    default: o.technique = SWARP_TECHNIQUE_UNIFORM; break;
    }
    swarp_vec3 points[SWARP_BODY_MAX_POINTS];
    double mx = 0.0, mz = 0.0;
    for (uint32_t i = 0; i < K; ++i) {
        swarp_setup_result r;
        size_t np = 0;
        s = swarp_setup_range(&n->camera, &n->light, box, splits[i], splits[i + 1], &o, &r, points,
                              SWARP_BODY_MAX_POINTS, &np);
        if (swarp_status_is_error(s)) return s;
        if (r.max_mx > mx) mx = r.max_mx;
        if (r.max_mz > mz) mz = r.max_mz;
        if (t->stab == SWARP_PLAN_STABILIZE_APPROX64) {
            swarp_stabilize_options so;
            memset(&so, 0, sizeof so);
            so.mode = SWARP_STABILIZE_LEVELS;
            swarp_mat4 M;
            s = swarp_stabilize_directional(&n->camera, splits[i], splits[i + 1], &n->light.direction,
                                            points, np, box, map, &so, &M, NULL);
            if (swarp_status_is_error(s)) return s;
        }
    }
    if (t->lixel) {
        /* the viewer's view-projection for the lixel matrix (look-at + perspective) */
        const swarp_camera* c = &n->camera;
        swarp_vec3 f = c->dir, up = c->up;
        double lf = sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
        f = (swarp_vec3){f.x / lf, f.y / lf, f.z / lf};
        swarp_vec3 sd = {f.y * up.z - f.z * up.y, f.z * up.x - f.x * up.z, f.x * up.y - f.y * up.x};
        double ls = sqrt(sd.x * sd.x + sd.y * sd.y + sd.z * sd.z);
        sd = (swarp_vec3){sd.x / ls, sd.y / ls, sd.z / ls};
        swarp_vec3 u = {sd.y * f.z - sd.z * f.y, sd.z * f.x - sd.x * f.z, sd.x * f.y - sd.y * f.x};
        swarp_mat4 V = {{sd.x, u.x, -f.x, 0, sd.y, u.y, -f.y, 0, sd.z, u.z, -f.z, 0,
                         -(sd.x * c->eye.x + sd.y * c->eye.y + sd.z * c->eye.z),
                         -(u.x * c->eye.x + u.y * c->eye.y + u.z * c->eye.z),
                         f.x * c->eye.x + f.y * c->eye.y + f.z * c->eye.z, 1}};
        double tt = 1.0 / tan(0.5 * c->fovy), nn = c->z_near, ff = c->z_far;
        swarp_mat4 P = {{tt / c->aspect, 0, 0, 0, 0, tt, 0, 0, 0, 0, -(ff + nn) / (ff - nn), -1, 0, 0,
                         -2.0 * ff * nn / (ff - nn), 0}};
        swarp_mat4 Mv, Ml;
        swarp_mat4_mul(&P, &V, &Mv);
        s = swarp_lixel_matrix(&Mv, n->screen_width, n->screen_height, &n->light, &n->planes[0], NULL, &Ml, NULL);
        if (swarp_status_is_error(s)) return s;
    }
    *out_mx = mx;
    *out_mz = mz;
    return s;
}

/* One technique in one configuration: the prediction, then the library time
 * of the same call measured reps times (median and p99). */
static int br_measure(const br_tech* t, double gamma_deg, double fn, unsigned map, int reps,
                      double* samples, br_row* r) {
    swarp_scene_needs n;
    swarp_budget b;
    br_scene(gamma_deg, fn, t->lixel, &n);
    memset(&b, 0, sizeof b);
    b.map_resolution = map;
    b.max_error = 1.0;
    swarp_plan_chain c;
    memset(&c, 0, sizeof c);
    c.warp = t->warp;
    c.scheme = t->scheme;
    c.split_count = t->K;
    c.stabilize = t->stab;
    c.matrices = SWARP_PLAN_MATRICES_NONE; /* the row times the model's prediction */
    struct swarp_plan p;
    swarp_status s = t->planner ? swarp_plan(&n, &b, &p) : swarp_plan_evaluate(&n, &b, &c, &p);
    memset(r, 0, sizeof *r);
    if (swarp_status_is_error(s)) return 0;
    for (int i = 0; i < reps; ++i) {
        double t0 = br_now_ns();
        if (t->planner)
            (void)swarp_plan(&n, &b, &p);
        else
            (void)swarp_plan_evaluate(&n, &b, &c, &p);
        samples[i] = br_now_ns() - t0;
    }
    qsort(samples, (size_t)reps, sizeof *samples, br_cmp);
    r->t_med = samples[reps / 2];
    r->t_p99 = samples[(size_t)((reps - 1) * 0.99)];
    r->ok = 1;
    /* the real setup, when the stages exist for it */
    if (!t->planner) {
        swarp_aabb box = {{-2.0 * fn, -2.0 * fn, -1.05 * fn}, {2.0 * fn, 2.0 * fn, 1.0}};
        double gmx = 0.0, gmz = 0.0;
        swarp_status gs = br_setup_once(t, &n, &box, map, &gmx, &gmz);
        if (!swarp_status_is_error(gs)) {
            for (int i = 0; i < reps; ++i) {
                double t0 = br_now_ns();
                (void)br_setup_once(t, &n, &box, map, &gmx, &gmz);
                samples[i] = br_now_ns() - t0;
            }
            qsort(samples, (size_t)reps, sizeof *samples, br_cmp);
            r->g_med = samples[reps / 2];
            r->g_p99 = samples[(size_t)((reps - 1) * 0.99)];
            r->g_mx = gmx;
            r->g_mz = gmz;
            r->g_ok = 1;
        }
    } else {
        r->g_med = r->t_med;
        r->g_p99 = r->t_p99;
        r->g_ok = 1;
    }
    r->mx = p.max_mx;
    r->mz = p.max_mz;
    r->passes = p.shadow_passes;
    r->texels = p.texels;
    r->cost_ms = p.cost_ns * 1e-6;
    r->inverse = (int)p.inverse_projection;
    if (t->lixel) {
        r->lixel_used = p.lixel_count > 0;
        if (r->lixel_used) r->mx = r->mz = p.lixel_error; /* on the floor plane */
    }
    r->area = r->mx * r->mz;
    if (t->planner)
        snprintf(r->chosen, sizeof r->chosen, "%s K=%u %s%s", swarp_plan_warp_name(p.warp),
                 p.split_count, swarp_plan_scheme_name(p.scheme),
                 s == SWARP_INFO_PLAN_BUDGET_UNMET ? " (budget unmet)" : "");
    return 1;
}

static void br_machine(char* out, size_t cap) {
    char model[160] = "unknown CPU";
    FILE* f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[256];
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "model name", 10) == 0) {
                char* c = strchr(line, ':');
                if (c) {
                    c += 2;
                    c[strcspn(c, "\n")] = 0;
                    snprintf(model, sizeof model, "%s", c);
                }
                break;
            }
        fclose(f);
    }
    snprintf(out, cap, "%ld cores (nproc), %s", sysconf(_SC_NPROCESSORS_ONLN), model);
}

static const char* br_fmt(double v, char* buf, size_t cap) {
    if (!isfinite(v)) snprintf(buf, cap, "inf");
    else if (v >= 1e5 || (v < 1e-3 && v != 0.0)) snprintf(buf, cap, "%.3g", v);
    else snprintf(buf, cap, "%.4g", v);
    return buf;
}

/* The geometry-cloning table ([RHS] §3.3.6 / Listing A.1 against the K + 1
 * pass version) from the demo's TSV: rows "K variant passes shadow_ms
 * main_ms frame_ms" (medians over the frames named in "# setup"). */
static void br_clone_section(FILE* md, const char* path) {
    fprintf(md, "## Geometry cloning vs K + 1 passes (measured in the demo)\n\n");
    FILE* f = fopen(path, "r");
    if (!f) {
        fprintf(md, "Not generated in this run: %s cannot be read.\n\n", path);
        return;
    }
    char line[512], machine[512] = "not stated", size[32] = "?", why[512] = "";
    unsigned map = 0, frames = 0, tris = 0;
    struct {
        unsigned K;
        char variant[16], passes[16];
        double s, m, fr;
    } rows[16];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = 0;
        if (strncmp(line, "# machine\t", 10) == 0) snprintf(machine, sizeof machine, "%s", line + 10);
        else if (strncmp(line, "# unavailable\t", 14) == 0) snprintf(why, sizeof why, "%s", line + 14);
        else if (strncmp(line, "# setup\t", 8) == 0)
            (void)sscanf(line + 8, "%31s %u %u %u", size, &map, &frames, &tris);
        else if (line[0] != '#' && n < 16 &&
                 sscanf(line, "%u\t%15[^\t]\t%15[^\t]\t%lf\t%lf\t%lf", &rows[n].K, rows[n].variant,
                        rows[n].passes, &rows[n].s, &rows[n].m, &rows[n].fr) == 6)
            ++n;
    }
    fclose(f);
    if (why[0] || n == 0) {
        fprintf(md, "Not measured in this run: %s. No numbers are given rather than invented;\n"
                    "run `sh docs/plots/regen_accuracy_cost.sh` where OSMesa gives a GL 4.5 core context.\n\n",
                why[0] ? why : "the demo wrote no rows");
        return;
    }
    fprintf(md, "`demo-check --test bench-clone` (docs/demo.md, \"One pass for all splits\"): PSSM(K) + LiSPSM on the demo's\n"
                "default view, %s pixels, %u² maps, %u triangles. The K + 1 pass version renders K shadow\n"
                "passes and the main pass; geometry cloning ([RHS] §3.3.6, Listing A.1) renders all K maps in\n"
                "one pass (a geometry shader emits each triangle into every split's layer and viewport) and\n"
                "the main pass. Both variants of one K run in the same frame loop, alternating which goes\n"
                "first; every number is the median over %u frames of glFinish-bracketed milliseconds, and\n"
                "the ratios compare against the K + 1 pass row measured in the same run. The shadow masks\n"
                "of both are identical bit for bit (`demo-check --test clone`). Shaped like [RHS] Tables 7.1/7.2\n"
                "(which measured 90 fps for PSSM(4) + LiSPSM with K + 1 passes and 76 fps with cloning on\n"
                "a GeForce 8800 GTX). Machine: %s.\n\n",
            size, map, tris, frames, machine);
    fprintf(md, "| applied techniques | 3D passes | shadow ms | main ms | frame ms | fps | shadow time vs K + 1 | frame time vs K + 1 |\n"
                "|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < n; ++i) {
        double bs = NAN, bf = NAN;
        for (int j = 0; j < n; ++j)
            if (rows[j].K == rows[i].K && strcmp(rows[j].variant, "passes") == 0) {
                bs = rows[j].s;
                bf = rows[j].fr;
            }
        int clone = strcmp(rows[i].variant, "clone") == 0;
        fprintf(md, "| %sPSSM(%u) + LiSPSM | %s | %.2f | %.2f | %.2f | %.1f | %.2f | %.2f |\n",
                clone ? "Geometry Cloning " : "", rows[i].K, rows[i].passes, rows[i].s, rows[i].m,
                rows[i].fr, 1000.0 / rows[i].fr, rows[i].s / bs, rows[i].fr / bf);
    }
    fputc('\n', md);
}

/* The one JSON object: status (an error when a file of --out-dir could not
 * be written, `where` naming it), the machine, the repetitions and a row per
 * configuration and technique. */
static void br_print_json(const sw_args* a, const char* machine, unsigned reps, const char* failed,
                          br_row (*rows)[BR_NM][BR_NG][BR_NT]) {
    (void)a;
    {
        json_begin();
        if (failed) {
            json_kv_str("status", "SWTOOL_ERR_IO");
            json_kv_str("message", "cannot write a file of --out-dir");
            json_kv_str("where", failed);
        } else {
            json_kv_status(SWARP_OK);
        }
        json_kv_str("machine", machine);
        json_kv_num("reps", reps);
        json_key("rows");
        json_open_arr();
        for (int fi = 0; fi < BR_NF; ++fi)
            for (int mi = 0; mi < BR_NM; ++mi)
                for (int gi = 0; gi < BR_NG; ++gi)
                    for (size_t ti = 0; ti < BR_NT; ++ti) {
                        const br_row* r = &rows[fi][mi][gi][ti];
                        json_open_obj();
                        json_kv_num("gamma_deg", br_gammas[gi]);
                        json_kv_num("far_over_near", br_fns[fi]);
                        json_kv_num("map", br_maps[mi]);
                        json_kv_str("technique", br_techs[ti].name);
                        json_kv_num("ok", r->ok);
                        json_kv_num("max_mx", r->mx);
                        json_kv_num("max_mz", r->mz);
                        json_kv_num("area", r->area);
                        json_kv_num("setup_median_ns", r->t_med);
                        json_kv_num("setup_p99_ns", r->t_p99);
                        json_kv_num("library_setup_ok", r->g_ok);
                        json_kv_num("library_setup_median_ns", r->g_med);
                        json_kv_num("library_setup_p99_ns", r->g_p99);
                        json_kv_num("setup_report_max_mx", r->g_mx);
                        json_kv_num("setup_report_max_mz", r->g_mz);
                        json_kv_num("passes", r->passes);
                        json_kv_num("texels", r->texels);
                        json_kv_num("predicted_cost_ms", r->cost_ms);
                        json_close_obj();
                    }
        json_close_arr();
        json_end();
    }

}

int cmd_bench_report(sw_args* a) {
    static const char* const known[] = {"reps", "out-dir", "demo-data", "clone-data", NULL};
    CLI_ACCEPT(a, known);
    unsigned reps;
    if (!cli_uint(a, "reps", 2000, &reps)) return CLI_EXIT_USAGE;
    /* p99 needs 100 samples to be more than the maximum; 10 is the least
     * whose median is not one outlier; 1e6 keeps the run under hours */
    if (reps < 10 || reps > 1000000)
        return cli_fail(a, "--reps", "expects 10..1000000 (the median and p99 are over N calls), got %u", reps);
    const char* dir = cli_opt(a, "out-dir");
    const char* demo_path = cli_opt(a, "demo-data");
    FILE* probe = demo_path ? fopen(demo_path, "r") : NULL;
    if (demo_path && !probe) return cli_fail(a, "--demo-data", "cannot open '%s'", demo_path);
    if (probe) fclose(probe);
    double* samples = malloc(sizeof(double) * reps);
    static br_row rows[BR_NF][BR_NM][BR_NG][BR_NT];
    if (!samples) return cli_report_status(a, SWARP_ERR_CAPACITY, "timing buffer");
    for (int fi = 0; fi < BR_NF; ++fi)
        for (int mi = 0; mi < BR_NM; ++mi)
            for (int gi = 0; gi < BR_NG; ++gi)
                for (size_t ti = 0; ti < BR_NT; ++ti)
                    br_measure(&br_techs[ti], br_gammas[gi], br_fns[fi], br_maps[mi], (int)reps, samples,
                               &rows[fi][mi][gi][ti]);
    free(samples);
    char machine[256];
    br_machine(machine, sizeof machine);

    FILE* md = stdout;
    char path[1024];
    if (dir) {
        snprintf(path, sizeof path, "%s/accuracy-cost.md", dir);
        md = fopen(path, "w");
        if (!md) {
            fprintf(stderr, "swtool bench-report: --out-dir: cannot write %s\n", path);
            if (a->json) br_print_json(a, machine, reps, path, rows);
            return CLI_EXIT_LIBRARY;
        }
    } else if (a->json) {
        br_print_json(a, machine, reps, NULL, rows);
        return CLI_EXIT_OK;
    }
    fprintf(md, "# Accuracy and cost of every technique\n\n"
                "Generated by `sh docs/plots/regen_accuracy_cost.sh` (`swtool bench-report`); do not edit.\n"
                "How the numbers are made: [planning.md](planning.md).\n\n"
                "- Screen 1024x768, fovy 60 deg (Θ = 30 deg), near 1; directional light at γ to the view\n"
                "  (γ = 150: behind the camera). Errors are Lloyd's m_x, m_z (screen pixels per texel side),\n"
                "  maxima over the whole view, predicted by the generalised model (planning.md §2).\n"
                "- PSSM uses the practical scheme (λ = 0.5) [RHS] (3.8), \"log\" the logarithmic one (3.7);\n"
                "  \"stabilised\" = 64-level scale + texel snap (texels\n"
                "  1/64 larger); \"+ n_opt\" = LiSPSM n_opt in every split. PSM rows use the inverse projection\n"
                "  when the light is behind (γ = 150).\n"
                "- Lixel row: error ON the floor plane y = 0 (one lixel map, max(1024, 768)/map pixels per texel);\n"
                "  everything else through the uniform fallback map; \"-\" where the floor is not lixel-friendly\n"
                "  (light below 5 deg elevation).\n"
                "- Setup ns (median, p99 over %u calls, measured in this run; machine: %s): the library\n"
                "  setup an engine calls for the technique: split distances (core (3.7)/(3.8)), then per split\n"
                "  `swarp_setup_range` (geometry stage: H = V ∩ S, B, light view, warp, focus (3.1); scene box\n"
                "  [-2f, 2f] x [-2f, 2f] x [-1.05f, 1], so B holds the whole view), plus\n"
                "  `swarp_stabilize_directional` (LEVELS) per split for the stabilised rows and\n"
                "  `swarp_lixel_matrix` for the lixel row; the planner row times `swarp_plan`. \"-\": the setup\n"
                "  refused the configuration (e.g. PSM with the light in the view direction). Predict ns: the\n"
                "  median time of `swarp_plan_evaluate` for the row (the planner's prediction of one chain).\n"
                "- Passes: shadow (geometry) passes. Predicted ms: passes x 1.39 ms (fit to [RHS] Table 7.1).\n"
                "- Demo columns in these tables: n/a. The demo renders its own scene with its own camera, so\n"
                "  its measurements are in the separate table \"Measured in the demo\" at the end%s.\n\n",
            reps, machine, cli_opt(a, "demo-data") ? "" : " (not generated in this run: no demo binary)");
    char b1[32], b2[32], b3[32], b4[32], b5[32], b6[32];
    /* summary: the planner's choice for E = 1 in every configuration */
    const size_t planner_row = BR_NT - 1;
    fprintf(md, "## Summary: the planner's choice for a budget of 1 pixel per texel\n\n"
                "Chain (warp, splits K, scheme) and its predicted max(m_x, m_z); default pass limit 16.\n\n"
                "| γ |");
    for (int fi = 0; fi < BR_NF; ++fi)
        for (int mi = 0; mi < BR_NM; ++mi) fprintf(md, " f/n %g, map %u |", br_fns[fi], br_maps[mi]);
    fprintf(md, "\n|---:|");
    for (int k = 0; k < BR_NF * BR_NM; ++k) fprintf(md, "---|");
    fputc('\n', md);
    for (int gi = 0; gi < BR_NG; ++gi) {
        fprintf(md, "| %g |", br_gammas[gi]);
        for (int fi = 0; fi < BR_NF; ++fi)
            for (int mi = 0; mi < BR_NM; ++mi) {
                const br_row* r = &rows[fi][mi][gi][planner_row];
                fprintf(md, " %s: %s |", r->chosen, br_fmt(r->mx > r->mz ? r->mx : r->mz, b1, sizeof b1));
            }
        fputc('\n', md);
    }
    fputc('\n', md);
    for (int fi = 0; fi < BR_NF; ++fi)
        for (int mi = 0; mi < BR_NM; ++mi) {
            fprintf(md, "## far/near = %g, map %u x %u\n\n", br_fns[fi], br_maps[mi], br_maps[mi]);
            for (int gi = 0; gi < BR_NG; ++gi) {
                fprintf(md, "### γ = %g deg (f/n %g, map %u)\n\n", br_gammas[gi], br_fns[fi], br_maps[mi]);
                fprintf(md, "| technique | max m_x | max m_z | m_x·m_z | setup median ns | setup p99 ns | predict ns | passes | texels | predicted ms | demo m | demo ms |\n"
                            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
                for (size_t ti = 0; ti < BR_NT; ++ti) {
                    const br_row* r = &rows[fi][mi][gi][ti];
                    const br_tech* t = &br_techs[ti];
                    char name[160];
                    snprintf(name, sizeof name, "%s%s%s%s", t->name, r->inverse ? " + inverse proj." : "",
                             t->planner ? ": " : "", t->planner ? r->chosen : "");
                    if (!r->ok || (t->lixel && !r->lixel_used)) {
                        fprintf(md, "| %s | - | - | - | - | - | - | - | - | - | n/a | n/a |\n", name);
                        continue;
                    }
                    char gm[32] = "-", gp[32] = "-";
                    if (r->g_ok) {
                        snprintf(gm, sizeof gm, "%.0f", r->g_med);
                        snprintf(gp, sizeof gp, "%.0f", r->g_p99);
                    }
                    fprintf(md, "| %s | %s | %s | %s | %s | %s | %.0f | %u | %s | %s | n/a | n/a |\n", name,
                            br_fmt(r->mx, b1, sizeof b1), br_fmt(r->mz, b2, sizeof b2),
                            br_fmt(r->area, b3, sizeof b3), gm, gp, r->t_med, r->passes,
                            br_fmt(r->texels, b4, sizeof b4), br_fmt(r->cost_ms, b5, sizeof b5));
                    (void)b6;
                }
                fputc('\n', md);
            }
        }
    const char* demo_data = cli_opt(a, "demo-data");
    FILE* dd = demo_data ? fopen(demo_data, "r") : NULL;
    if (dd) {
        fprintf(md, "## Measured in the demo\n\n"
                    "`examples/demo` with `--camera measure` (horizontal view from 20 above the ground,\n"
                    "near 1, far 600), 1024x768, light at γ to the view in the view/up plane (γ = 150: behind\n"
                    "the camera), filter pcf3; every technique the demo renders and measures (PSSM:\n"
                    "practical λ = 0.5), with the matrices the demo gets from the library (the geometry stage's\n"
                    "focused setup). meas σ: the largest σ (docs/accuracy.md) the render shows on its\n"
                    "receivers, from the read-back texel coordinates of neighbouring pixels; pred σ: the\n"
                    "library's swarp_measure_points on the same pixels' world points and normals with the\n"
                    "matrix that shaded each (the same quantity: meas/pred near 1, the rest is the GPU's float\n"
                    "texel coordinates, docs/demo.md).  The planner's model ratio is kept for reference.\n"
                    "Times: glFinish-bracketed passes on llvmpipe (%s), one frame.\n\n"
                    "| γ | map | technique | meas σ | pred σ | meas/pred | model ratio (uniform, whole view) | passes | texels | shadow ms | main ms | demo setup µs |\n"
                    "|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
                machine);
        char line[512];
        while (fgets(line, sizeof line, dd)) {
            double g, setup, texels, sms, mms, meas, pred;
            unsigned map, K, passes;
            char tech[32];
            if (line[0] == '#') continue;
            if (sscanf(line, "%lf %u %31s %u %lf %u %lf %lf %lf %lf %lf", &g, &map, tech, &K, &setup,
                       &passes, &texels, &sms, &mms, &meas, &pred) != 11)
                continue;
            char label[48];
            if (strcmp(tech, "pssm") == 0) snprintf(label, sizeof label, "PSSM(%u)", K);
            else if (strcmp(tech, "pssm-lispsm") == 0) snprintf(label, sizeof label, "PSSM(%u) + LiSPSM", K);
            else if (strcmp(tech, "lispsm") == 0) snprintf(label, sizeof label, "LiSPSM n_opt");
            else if (strcmp(tech, "repar") == 0) snprintf(label, sizeof label, "LiSPSM n_repar");
            else if (strcmp(tech, "gmnpr") == 0) snprintf(label, sizeof label, "LiSPSM GMNPR");
            else if (strcmp(tech, "psm") == 0) snprintf(label, sizeof label, g > 90.0 ? "PSM (inverse proj.)" : "PSM");
            else snprintf(label, sizeof label, "%s", tech);
            char ratio[32] = "-";
            if (strcmp(tech, "uniform") == 0) {
                double gf = g > 90.0 ? 180.0 - g : g;
                snprintf(ratio, sizeof ratio, "%.3f",
                         (600.0 * sin((gf + 30.0) * SW_DEG) - sin((gf - 30.0) * SW_DEG)) /
                             (cos(30.0 * SW_DEG) * 599.0) / sin(gf * SW_DEG));
            }
            fprintf(md, "| %g | %u | %s | %s | %s | %.3f | %s | %u | %s | %.2f | %.2f | %.2f |\n", g, map,
                    label, br_fmt(meas, b1, sizeof b1), br_fmt(pred, b2, sizeof b2), meas / pred, ratio,
                    passes, br_fmt(texels, b3, sizeof b3), sms, mms, setup);
        }
        fclose(dd);
        fputc('\n', md);
    }
    const char* clone_data = cli_opt(a, "clone-data");
    if (clone_data) br_clone_section(md, clone_data);
    if (dir) fclose(md);

    /* gnuplot data: f/n = 1000, map 2048; one block per γ (index gi):
     * cost_ms  max_error  family  setup_median_ns  "technique" */
    if (dir) {
        snprintf(path, sizeof path, "%s/plots/accuracy-cost.dat", dir);
        FILE* d = fopen(path, "w");
        snprintf(path, sizeof path, "%s/plots/accuracy-cost-front.dat", dir);
        FILE* fr = fopen(path, "w");
        if (!d || !fr) {
            fprintf(stderr, "swtool bench-report: --out-dir: cannot write the plot data under %s/plots\n", dir);
            if (a->json) br_print_json(a, machine, reps, path, rows);
            if (d) fclose(d);
            if (fr) fclose(fr);
            return CLI_EXIT_LIBRARY;
        }
        const int fi = 1, mi = 1;
        for (int gi = 0; gi < BR_NG; ++gi) {
            fprintf(d, "# gamma %g, f/n %g, map %u\n", br_gammas[gi], br_fns[fi], br_maps[mi]);
            fprintf(fr, "# gamma %g Pareto front (cost_ms max_error)\n", br_gammas[gi]);
            double fx[BR_NT], fy[BR_NT];
            int nf = 0;
            for (size_t ti = 0; ti < BR_NT; ++ti) {
                const br_row* r = &rows[fi][mi][gi][ti];
                if (!r->ok || br_techs[ti].lixel) continue;
                double e = r->mx > r->mz ? r->mx : r->mz;
                fprintf(d, "%.6g %.6g %d %.0f \"%s\"\n", r->cost_ms, e, br_techs[ti].family, r->g_med,
                        br_techs[ti].name);
                if (br_techs[ti].planner) continue; /* the planner's point is one of the others */
                /* non-dominated: no other row at most as costly and more accurate */
                int dominated = 0;
                for (size_t tj = 0; tj < BR_NT; ++tj) {
                    const br_row* q = &rows[fi][mi][gi][tj];
                    if (tj == ti || !q->ok || br_techs[tj].lixel || br_techs[tj].planner) continue;
                    double eq = q->mx > q->mz ? q->mx : q->mz;
                    if (q->cost_ms <= r->cost_ms && eq < e) dominated = 1;
                    if (q->cost_ms < r->cost_ms && eq <= e) dominated = 1;
                }
                if (!dominated) {
                    fx[nf] = r->cost_ms;
                    fy[nf] = e;
                    ++nf;
                }
            }
            /* sort the front by cost */
            for (int i = 1; i < nf; ++i)
                for (int j = i; j > 0 && fx[j] < fx[j - 1]; --j) {
                    double tx = fx[j], ty = fy[j];
                    fx[j] = fx[j - 1];
                    fy[j] = fy[j - 1];
                    fx[j - 1] = tx;
                    fy[j - 1] = ty;
                }
            for (int i = 0; i < nf; ++i) fprintf(fr, "%.6g %.6g\n", fx[i], fy[i]);
            fprintf(d, "\n\n");
            fprintf(fr, "\n\n");
        }
        fclose(d);
        fclose(fr);
    }
    if (a->json) br_print_json(a, machine, reps, NULL, rows);
    return CLI_EXIT_OK;
}
