/* options.c -- the command line shared by the demo and demo-check: the
 * options, their defaults and their ranges, and the camera path file. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

void demo_options_usage(void) {
    printf(
        "  --technique T           uniform lispsm repar gmnpr pseudo psm pssm pssm-lispsm\n"
        "                          pssm-stable lixel planned (the chain swarp_plan chooses)\n"
        "  --plan                  print the plan for the view (swarp_plan) and stop\n"
        "  --pseudo NP,FP          pseudo-near/far fractions for 'pseudo' (default 0.05,0)\n"
        "  --splits K              maps for the pssm techniques (1..16, default 4)\n"
        "  --scheme S              practical[:LAMBDA] | uniform | log | pseudo:NP,FP[,LAMBDA]\n"
        "                          (default practical:0.5; NP, FP fractions of the range, (4.1))\n"
        "  --filter F              none | pcf2 | pcf3 | pcf5 | poisson | vsm | evsm | projblur\n"
        "                          (default pcf3; projblur: [KOZ] 14.3.2 on the ground)\n"
        "  --light-angle E[,A]     sun elevation E and azimuth A in degrees (default 35,115)\n"
        "  --light-dir X,Y,Z       direction the light travels (instead of --light-angle)\n"
        "  --light-gamma G         the light travels at G degrees (0 < G < 180) to the view\n"
        "                          direction, turned from it toward the ground (the sun behind\n"
        "                          the camera for small G, ahead of it for G > 90)\n"
        "  --nprime closed|measured  LiSPSM n': the technique's closed form (default: lispsm\n"
        "                          n_opt, repar n_repar, gmnpr, pseudo) or the library's default,\n"
        "                          chosen by the measured error (SWARP_WARP_PARAM_MEASURED)\n"
        "  --basis library|aligned light-space basis of uniform/lispsm: swarp_setup's (default;\n"
        "                          the minimum-area rotation near parallel light) or the\n"
        "                          view-aligned one of swarp_focus_light_view\n"
        "  --camera P|FILE         default | measure | street | high | room, or a path file of\n"
        "                          \"ex ey ez dx dy dz\" lines (one per frame)\n"
        "  --frames N              fly N frames along the boulevard (prints progress)\n"
        "  --size WxH              picture size (default 960x540)\n"
        "  --map RES               texels per map side (default 1024)\n"
        "  --grid N                texels per cell in the texel-grid picture (default 8)\n"
        "  --blend F               split blend band, fraction of a split (default 0.1)\n"
        "  --select depth|best     split selection: eye depth or best resolution (ZZB09)\n"
        "  --offset K              normal-offset bias in texels (default 1)\n"
        "  --obj FILE              a Wavefront OBJ instead of the built-in scene\n"
        "  --mindepth              [RHS] 4.3: min depth on GPU and CPU, LiSPSM sampling with the\n"
        "                          camera / adjusted / pseudo near plane (camera street)\n"
        "  --out DIR               output directory (default ./out)\n");
}

/* The defaults the usage text promises. */
static void options_defaults(demo_options* o) {
    memset(o, 0, sizeof *o);
    o->technique = -1;
    o->splits = 4;
    o->scheme = DEMO_SCHEME_PRACTICAL;
    o->scheme_lambda = 0.5;
    o->filter = DEMO_FILTER_PCF3;
    o->light_elev = 35;
    o->light_azim = 115;
    o->camera = "default";
    o->w = 960;
    o->h = 540;
    o->map = 1024;
    o->out = "out";
    o->blend = 0.1f;
    o->offset = 1.0f;
    o->pseudo_near = 0.05;
    o->pseudo_far = 0.0;
    o->grid = 8;
}

/* The parsers below return 1 when option a was theirs (its value, if any,
 * consumed), 0 when it was not, -1 (message on stderr) when it was bad. */
#define NEED()                                                \
    do {                                                      \
        if (!val) {                                           \
            fprintf(stderr, "demo: %s needs a value\n", a);   \
            return -1;                                        \
        }                                                     \
    } while (0)
#define BAD(...)                          \
    do {                                  \
        fprintf(stderr, __VA_ARGS__);     \
        return -1;                        \
    } while (0)

/* Options without a value. */
static int parse_flag(const char* a, demo_options* o) {
    if (!strcmp(a, "--plan")) o->plan_only = 1;
    else if (!strcmp(a, "--mindepth")) o->mindepth = 1;
    else if (!strcmp(a, "--sheets")) o->sheets_only = 1;
    else if (!strcmp(a, "--no-sheets")) o->no_sheets = 1;
    else return 0;
    return 1;
}

/* The shadow configuration: technique, splits, scheme and selection. */
static int parse_shadow_option(const char* a, const char* val, demo_options* o) {
    if (!strcmp(a, "--technique")) {
        NEED();
        o->technique = !strcmp(val, "planned") ? DEMO_TECH_PLANNED : demo_technique_parse(val);
        if (o->technique < 0) BAD("demo: unknown technique %s\n", val);
    } else if (!strcmp(a, "--splits")) {
        NEED();
        o->splits = atoi(val);
        if (o->splits < 1 || o->splits > DEMO_MAX_SPLITS)
            BAD("demo: --splits must be 1..%d\n", DEMO_MAX_SPLITS);
    } else if (!strcmp(a, "--scheme")) {
        NEED();
        int s = demo_scheme_parse(val, &o->scheme_lambda, &o->scheme_np, &o->scheme_fp);
        if (s < 0) BAD("demo: unknown scheme %s\n", val);
        o->scheme = (demo_scheme)s;
    } else if (!strcmp(a, "--select")) {
        NEED();
        if (!strcmp(val, "depth")) o->select = DEMO_SELECT_DEPTH;
        else if (!strcmp(val, "best")) o->select = DEMO_SELECT_BEST;
        else BAD("demo: --select depth|best\n");
    } else if (!strcmp(a, "--nprime")) {
        NEED();
        if (!strcmp(val, "closed")) o->nprime_measured = 0;
        else if (!strcmp(val, "measured")) o->nprime_measured = 1;
        else BAD("demo: --nprime closed|measured\n");
    } else if (!strcmp(a, "--basis")) {
        NEED();
        if (!strcmp(val, "library")) o->basis_aligned = 0;
        else if (!strcmp(val, "aligned")) o->basis_aligned = 1;
        else BAD("demo: --basis library|aligned\n");
    } else if (!strcmp(a, "--pseudo")) {
        NEED();
        if (sscanf(val, "%lf,%lf", &o->pseudo_near, &o->pseudo_far) != 2 ||
            !(o->pseudo_near >= 0 && o->pseudo_far >= 0 && o->pseudo_near + o->pseudo_far < 1))
            BAD("demo: --pseudo NP,FP with NP, FP >= 0, NP + FP < 1\n");
    } else {
        return 0;
    }
    return 1;
}

/* The main pass: filter, bias, blend band and the texel-grid picture. */
static int parse_shading_option(const char* a, const char* val, demo_options* o) {
    if (!strcmp(a, "--filter")) {
        NEED();
        int k = demo_filter_parse(val);
        if (k < 0)
            BAD("demo: unknown filter %s (none pcf2 pcf3 pcf5 poisson vsm evsm projblur)\n", val);
        o->filter = (demo_filter)k;
    } else if (!strcmp(a, "--offset")) {
        NEED();
        o->offset = (float)atof(val);
        if (!(o->offset >= 0 && o->offset <= 16)) BAD("demo: --offset 0..16 texels\n");
    } else if (!strcmp(a, "--grid")) {
        NEED();
        o->grid = (float)atof(val);
    } else if (!strcmp(a, "--blend")) {
        NEED();
        o->blend = (float)atof(val);
    } else {
        return 0;
    }
    return 1;
}

/* The view: sun, camera, sizes, scene and where the outputs go. */
static int parse_view_option(const char* a, const char* val, demo_options* o) {
    if (!strcmp(a, "--light-angle")) {
        NEED();
        int n = sscanf(val, "%lf,%lf", &o->light_elev, &o->light_azim);
        if (n < 1 || !(o->light_elev > 0 && o->light_elev <= 90))
            BAD("demo: --light-angle E[,A] with 0 < E <= 90\n");
    } else if (!strcmp(a, "--light-dir")) {
        NEED();
        swarp_vec3 d;
        if (sscanf(val, "%lf,%lf,%lf", &d.x, &d.y, &d.z) != 3 ||
            !(d.x * d.x + d.y * d.y + d.z * d.z > 0))
            BAD("demo: --light-dir X,Y,Z (not zero)\n");
        o->light_dir = d;
        o->have_light_dir = 1;
    } else if (!strcmp(a, "--light-gamma")) {
        NEED();
        o->light_gamma = atof(val);
        if (!(o->light_gamma > 0 && o->light_gamma < 180))
            BAD("demo: --light-gamma G with 0 < G < 180 degrees\n");
        o->have_light_gamma = 1;
    } else if (!strcmp(a, "--camera")) {
        NEED();
        o->camera = val;
        o->camera_given = 1;
    } else if (!strcmp(a, "--size")) {
        NEED();
        if (sscanf(val, "%dx%d", &o->w, &o->h) != 2 || o->w < 16 || o->h < 16 || o->w > 8192 ||
            o->h > 8192)
            BAD("demo: --size WxH (16..8192)\n");
    } else if (!strcmp(a, "--map")) {
        NEED();
        o->map = atoi(val);
        if (o->map < 16 || o->map > 8192) BAD("demo: --map 16..8192\n");
    } else {
        return 0;
    }
    return 1;
}

/* What is run and where its outputs go. */
static int parse_run_option(const char* a, const char* val, demo_options* o) {
    const char** slot = !strcmp(a, "--obj")         ? &o->obj
                        : !strcmp(a, "--out")       ? &o->out
                        : !strcmp(a, "--test")      ? &o->test
                        : !strcmp(a, "--bench-out") ? &o->bench_out
                                                    : NULL;
    if (!strcmp(a, "--frames")) {
        NEED();
        o->frames = atoi(val);
        return 1;
    }
    if (!slot) return 0;
    NEED();
    *slot = val;
    return 1;
}
#undef NEED
#undef BAD

int demo_options_parse(int argc, char** argv, void (*usage)(void), demo_options* o) {
    options_defaults(o);
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        const char* val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage();
            exit(0);
        }
        if (parse_flag(a, o)) continue;
        int k = parse_shadow_option(a, val, o);
        if (k == 0) k = parse_shading_option(a, val, o);
        if (k == 0) k = parse_view_option(a, val, o);
        if (k == 0) k = parse_run_option(a, val, o);
        if (k < 0) return -1;
        if (k == 0) {
            fprintf(stderr, "demo: unknown option %s (try --help)\n", a);
            return -1;
        }
        ++i; /* the value */
    }
    return 0;
}

/* --camera FILE: up to DEMO_MAX_PATH lines "ex ey ez dx dy dz"; the first is the
 * starting camera, --frames walks through them. */
int demo_options_load_path(demo_options* o) {
    FILE* f = fopen(o->camera, "r");
    if (!f) return 0; /* not a file: a preset name */
    char line[256];
    o->path_count = 0;
    while (o->path_count < DEMO_MAX_PATH && fgets(line, sizeof line, f)) {
        double* k = o->path + 6 * o->path_count;
        if (line[0] == '#') continue;
        if (sscanf(line, "%lf %lf %lf %lf %lf %lf", k, k + 1, k + 2, k + 3, k + 4, k + 5) == 6 &&
            k[3] * k[3] + k[4] * k[4] + k[5] * k[5] > 0)
            ++o->path_count;
    }
    fclose(f);
    if (o->path_count == 0) {
        fprintf(stderr, "demo: %s holds no \"ex ey ez dx dy dz\" line\n", o->camera);
        return -1;
    }
    return 1;
}
