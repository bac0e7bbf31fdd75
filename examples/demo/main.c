/* main.c -- the libshadowwarp OSMesa demo: renders the built-in scene with
 * each technique and writes the pictures of [RHS] chapter 5 as PNGs.
 *
 *   demo                         default gallery into ./out/ + summary table
 *   demo --technique lispsm ...  one technique, all its pictures
 *   demo --test NAME             headless checks used by meson test
 *                                (exit 77 when no OSMesa context)
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ctx.h"
#include "demo.h"
#include "plan.h"

#define DEG (3.14159265358979323846 / 180.0)
/* --technique planned: the chain swarp_plan chose (plan.c), the gallery's
 * first entry */
#define TECH_PLANNED DEMO_TECH_COUNT

typedef struct options {
    int technique;   /**< -1 = gallery */
    int splits;
    demo_scheme scheme;
    double scheme_lambda;
    demo_filter filter;
    double light_elev, light_azim; /**< degrees */
    int have_light_dir;
    swarp_vec3 light_dir;
    const char* camera;
    int frames;
    int w, h, map;
    const char* out;
    const char* obj;
    const char* test;
    float blend, grid, offset;
    double pseudo_near, pseudo_far;
    double scheme_np, scheme_fp;
    demo_select select;
    int camera_given;
    int mindepth;
    double path[6 * 256]; /**< --camera FILE: eye and dir per frame */
    int path_count;
    int plan_only;              /**< --plan: print the plan and stop */
    const char* label_override; /**< run_technique's label (the planned entry) */
    const char* bench_out;      /**< --bench-out: bench-clone's rows as TSV */
    int sheets_only;            /**< --sheets: only the comparison sheets (sheets.c) */
    int no_sheets;              /**< --no-sheets: the gallery without them */
} options;

static void usage(void) {
    printf(
        "usage: demo [options]\n"
        "  (no options)            default gallery into ./out/ and a summary table, then the\n"
        "                          comparison sheets (blur_sheet, cube_sheet, cube_sheet_behind)\n"
        "  --sheets                only the sheets: projective blur vs PCF [KOZ] 14.3.2, PSM vs\n"
        "                          cube map [KOZ] 14.2.2 (camera and measured near; sun in front\n"
        "                          and behind); --no-sheets: the gallery without them\n"
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
        "  --out DIR               output directory (default ./out)\n"
        "  --test images|iou|measure|select|clone|mindepth|flicker|planned|blur\n"
        "                          headless checks (exit 0 pass, 1 fail, 77 skip)\n"
        "  --test bench-clone      time K + 1 passes against geometry cloning (1 + 1), K = 4, 8, 16\n"
        "                          (median of --frames, default 15; --bench-out FILE: rows as TSV)\n");
}

static int parse_options(int argc, char** argv, options* o) {
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
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        const char* val = i + 1 < argc ? argv[i + 1] : NULL;
#define NEED()                                                    \
    do {                                                          \
        if (!val) {                                               \
            fprintf(stderr, "demo: %s needs a value\n", a);       \
            return -1;                                            \
        }                                                         \
        ++i;                                                      \
    } while (0)
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage();
            exit(0);
        } else if (!strcmp(a, "--technique")) {
            NEED();
            o->technique = !strcmp(val, "planned") ? TECH_PLANNED : demo_technique_parse(val);
            if (o->technique < 0) {
                fprintf(stderr, "demo: unknown technique %s\n", val);
                return -1;
            }
        } else if (!strcmp(a, "--splits")) {
            NEED();
            o->splits = atoi(val);
            if (o->splits < 1 || o->splits > DEMO_MAX_SPLITS) {
                fprintf(stderr, "demo: --splits must be 1..%d\n", DEMO_MAX_SPLITS);
                return -1;
            }
        } else if (!strcmp(a, "--scheme")) {
            NEED();
            int s = demo_scheme_parse(val, &o->scheme_lambda, &o->scheme_np, &o->scheme_fp);
            if (s < 0) {
                fprintf(stderr, "demo: unknown scheme %s\n", val);
                return -1;
            }
            o->scheme = (demo_scheme)s;
        } else if (!strcmp(a, "--filter")) {
            NEED();
            int k = demo_filter_parse(val);
            if (k < 0) {
                fprintf(stderr, "demo: unknown filter %s (none pcf2 pcf3 pcf5 poisson vsm evsm projblur)\n", val);
                return -1;
            }
            o->filter = (demo_filter)k;
        } else if (!strcmp(a, "--light-angle")) {
            NEED();
            int n = sscanf(val, "%lf,%lf", &o->light_elev, &o->light_azim);
            if (n < 1 || !(o->light_elev > 0 && o->light_elev <= 90)) {
                fprintf(stderr, "demo: --light-angle E[,A] with 0 < E <= 90\n");
                return -1;
            }
        } else if (!strcmp(a, "--light-dir")) {
            NEED();
            swarp_vec3 d;
            if (sscanf(val, "%lf,%lf,%lf", &d.x, &d.y, &d.z) != 3 ||
                !(d.x * d.x + d.y * d.y + d.z * d.z > 0)) {
                fprintf(stderr, "demo: --light-dir X,Y,Z (not zero)\n");
                return -1;
            }
            o->light_dir = d;
            o->have_light_dir = 1;
        } else if (!strcmp(a, "--camera")) {
            NEED();
            o->camera = val;
            o->camera_given = 1;
        } else if (!strcmp(a, "--frames")) {
            NEED();
            o->frames = atoi(val);
        } else if (!strcmp(a, "--size")) {
            NEED();
            if (sscanf(val, "%dx%d", &o->w, &o->h) != 2 || o->w < 16 || o->h < 16 ||
                o->w > 8192 || o->h > 8192) {
                fprintf(stderr, "demo: --size WxH (16..8192)\n");
                return -1;
            }
        } else if (!strcmp(a, "--map")) {
            NEED();
            o->map = atoi(val);
            if (o->map < 16 || o->map > 8192) {
                fprintf(stderr, "demo: --map 16..8192\n");
                return -1;
            }
        } else if (!strcmp(a, "--grid")) {
            NEED();
            o->grid = (float)atof(val);
        } else if (!strcmp(a, "--blend")) {
            NEED();
            o->blend = (float)atof(val);
        } else if (!strcmp(a, "--select")) {
            NEED();
            if (!strcmp(val, "depth")) o->select = DEMO_SELECT_DEPTH;
            else if (!strcmp(val, "best")) o->select = DEMO_SELECT_BEST;
            else {
                fprintf(stderr, "demo: --select depth|best\n");
                return -1;
            }
        } else if (!strcmp(a, "--pseudo")) {
            NEED();
            if (sscanf(val, "%lf,%lf", &o->pseudo_near, &o->pseudo_far) != 2 ||
                !(o->pseudo_near >= 0 && o->pseudo_far >= 0 && o->pseudo_near + o->pseudo_far < 1)) {
                fprintf(stderr, "demo: --pseudo NP,FP with NP, FP >= 0, NP + FP < 1\n");
                return -1;
            }
        } else if (!strcmp(a, "--offset")) {
            NEED();
            o->offset = (float)atof(val);
            if (!(o->offset >= 0 && o->offset <= 16)) {
                fprintf(stderr, "demo: --offset 0..16 texels\n");
                return -1;
            }
        } else if (!strcmp(a, "--plan")) {
            o->plan_only = 1;
        } else if (!strcmp(a, "--mindepth")) {
            o->mindepth = 1;
        } else if (!strcmp(a, "--obj")) {
            NEED();
            o->obj = val;
        } else if (!strcmp(a, "--sheets")) {
            o->sheets_only = 1;
        } else if (!strcmp(a, "--no-sheets")) {
            o->no_sheets = 1;
        } else if (!strcmp(a, "--bench-out")) {
            NEED();
            o->bench_out = val;
        } else if (!strcmp(a, "--out")) {
            NEED();
            o->out = val;
        } else if (!strcmp(a, "--test")) {
            NEED();
            o->test = val;
        } else {
            fprintf(stderr, "demo: unknown option %s (try --help)\n", a);
            return -1;
        }
#undef NEED
    }
    return 0;
}

/* --camera FILE: up to 256 lines "ex ey ez dx dy dz"; the first is the
 * starting camera, --frames walks through them. */
static int load_camera_path(options* o) {
    FILE* f = fopen(o->camera, "r");
    if (!f) return 0; /* not a file: a preset name */
    char line[256];
    o->path_count = 0;
    while (o->path_count < 256 && fgets(line, sizeof line, f)) {
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

/* Camera presets over the default scene (y up, ground at y = 0). */
static int camera_preset(const char* name, int w, int h, swarp_camera* c) {
    memset(c, 0, sizeof *c);
    c->up.y = 1;
    c->fovy = 60 * DEG;
    c->aspect = (double)w / h;
    c->near = 1;
    c->far = 800;
    if (!strcmp(name, "default")) {
        c->eye = (swarp_vec3){8, 28, 395};
        c->dir = (swarp_vec3){-0.02, -0.11, -1};
    } else if (!strcmp(name, "measure")) {
        /* horizontal view, the setting of Lloyd's error model */
        c->eye = (swarp_vec3){0, 20, 390};
        c->dir = (swarp_vec3){0, 0, -1};
        c->far = 600;
    } else if (!strcmp(name, "street")) {
        c->eye = (swarp_vec3){0, 2, 385};
        c->dir = (swarp_vec3){0, 0.05, -1};
    } else if (!strcmp(name, "high")) {
        c->eye = (swarp_vec3){-220, 160, 390};
        c->dir = (swarp_vec3){220, -160, -480};
        c->far = 1000;
    } else if (!strcmp(name, "room")) {
        c->eye = (swarp_vec3){-52, 12, 48};
        c->dir = (swarp_vec3){-23, -11, -40};
        c->near = 0.5;
        c->far = 600;
    } else if (!strcmp(name, "path")) {
        /* a camera path file: presets' defaults, eye/dir set by the caller */
        c->eye = (swarp_vec3){0, 20, 390};
        c->dir = (swarp_vec3){0, 0, -1};
    } else {
        fprintf(stderr, "demo: unknown camera preset %s\n", name);
        return -1;
    }
    return 0;
}

static int setup_camera(const options* o, swarp_camera* c) {
    if (o->path_count == 0) return camera_preset(o->camera, o->w, o->h, c);
    if (camera_preset("path", o->w, o->h, c)) return -1;
    c->eye = (swarp_vec3){o->path[0], o->path[1], o->path[2]};
    c->dir = (swarp_vec3){o->path[3], o->path[4], o->path[5]};
    return 0;
}

static void light_from_options(const options* o, swarp_light* l) {
    memset(l, 0, sizeof *l);
    l->type = SWARP_LIGHT_DIRECTIONAL;
    if (o->have_light_dir) {
        l->direction = o->light_dir;
    } else {
        double e = o->light_elev * DEG, a = o->light_azim * DEG;
        /* the light comes FROM azimuth a (0 = from +z, behind the default
         * camera) at elevation e, and travels the other way */
        l->direction = (swarp_vec3){-cos(e) * sin(a), -sin(e), -cos(e) * cos(a)};
        if (o->light_elev >= 90) l->direction = (swarp_vec3){0, -1, 0};
    }
}

/* View v of the command line: --camera (or the explicit eye/dir) at --size
 * with the --light-angle / --light-dir sun.  Non-zero: a bad camera. */
static int options_view(const options* o, demo_view* v) {
    memset(v, 0, sizeof *v);
    v->w = o->w;
    v->h = o->h;
    if (setup_camera(o, &v->cam)) return -1;
    light_from_options(o, &v->light);
    return 0;
}

/* View v of preset `camera` at --size with the --light-angle / --light-dir sun. */
static int preset_view(const options* o, const char* camera, demo_view* v) {
    memset(v, 0, sizeof *v);
    v->w = o->w;
    v->h = o->h;
    if (camera_preset(camera, v->w, v->h, &v->cam)) return -1;
    light_from_options(o, &v->light);
    demo_view_update(v);
    return 0;
}

/* demo_shadow_setup of technique t with K maps (practical scheme, lambda
 * 0.5) for view v at --map. */
static int setup_for(const options* o, const demo_view* v, const swarp_aabb* box, demo_technique t,
                     int splits, demo_shadow* sh) {
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = t;
    req.splits = splits;
    req.scheme_lambda = 0.5;
    req.map_res = o->map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    return demo_shadow_setup(&v->cam, &v->light, box, &req, sh);
}

static int mkdir_p(const char* dir) {
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char* p = tmp + 1; *p; ++p)
        if (*p == '/') {
            *p = 0;
            if (mkdir(tmp, 0755) && errno != EEXIST) return -1;
            *p = '/';
        }
    if (mkdir(tmp, 0755) && errno != EEXIST) return -1;
    return 0;
}

/* ------------------------------------------------------------------------ */
/* one technique: every picture, the measurement and the timing             */
/* ------------------------------------------------------------------------ */
typedef struct tech_result {
    demo_technique tech;
    char label[48];
    int ok;
    double setup_us;
    int passes;
    double shadow_ms[DEMO_MAX_SPLITS];
    double shadow_ms_total, main_ms;
    double texels;
    demo_measure_row rows[16];
    int nrows;
    double max_mx, max_mz;
    int gl_errors;
    double min_nonblank; /**< smallest non-blank fraction of the pictures */
    demo_image shaded, sampling, grid, splits, light;
    const char* source;
    int own_view; /**< rendered from another camera than the sheet's */
    demo_shadow sh; /**< the configuration that was rendered */
} tech_result;

static int cmp_d(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static double time_setup(const demo_view* v, const swarp_aabb* box,
                         const demo_shadow_request* req, demo_shadow* sh) {
    enum { REPS = 101 };
    double t[REPS];
    for (int i = 0; i < REPS; ++i) {
        double t0 = demo_now_ms();
        if (demo_shadow_setup(&v->cam, &v->light, box, req, sh)) return -1;
        t[i] = (demo_now_ms() - t0) * 1e3;
    }
    qsort(t, REPS, sizeof t[0], cmp_d);
    return t[REPS / 2];
}

static int read_picture(demo_renderer* r, int w, int h, demo_image* im) {
    if (demo_image_alloc(im, w, h)) return -1;
    demo_render_read_color(r, w, h, im->px);
    return 0;
}

static int light_view_picture(demo_renderer* r, const demo_view* v, const demo_shadow* sh,
                              demo_image* out) {
    /* one tile per map (Fig. 5.5): the scene as the light sees it, the view
     * (split) frustum in black, the view vector in blue in the first tile */
    int k = sh->count, cols = (int)ceil(sqrt((double)k));
    int rows = (k + cols - 1) / cols;
    int side = v->h < v->w ? v->h : v->w;
    int tile = side / (cols > rows ? cols : rows);
    if (demo_image_alloc(out, tile * cols, tile * rows)) return -1;
    const uint8_t white[3] = {255, 255, 255};
    demo_image_fill(out, 0, 0, out->w, out->h, white);
    int errors = 0;
    for (int i = 0; i < k; ++i) {
        demo_shadow one = *sh;
        one.count = 1;
        one.light[0] = sh->light[i];
        demo_main_params p;
        memset(&p, 0, sizeof p);
        float ident[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        memcpy(p.view, ident, sizeof ident);
        if (swarp_mat4_to_float(&sh->light[i], p.proj) != SWARP_OK) return -1;
        p.light_dir[0] = (float)v->light.direction.x;
        p.light_dir[1] = (float)v->light.direction.y;
        p.light_dir[2] = (float)v->light.direction.z;
        p.mode = DEMO_MODE_UNSHADOWED;
        p.vw = tile;
        p.vh = tile;
        errors += demo_render_main(r, &one, &p, NULL);
        demo_image t;
        if (read_picture(r, tile, tile, &t)) return -1;
        const uint8_t black[3] = {0, 0, 0};
        /* split frustum for cascades, the whole view for lixel maps */
        int whole = sh->select == DEMO_SELECT_LIXEL;
        demo_draw_frustum(&t, &sh->light[i], v, whole ? sh->near : sh->split[i],
                          whole ? sh->far : sh->split[i + 1], black, i == 0);
        char lab[32];
        snprintf(lab, sizeof lab, "map %d", i);
        if (k > 1) demo_image_label(&t, 6, 6, 1, lab);
        demo_image_blit(out, (i % cols) * tile, (i / cols) * tile, &t);
        demo_image_free(&t);
    }
    return errors;
}

static int write_png(const options* o, const char* label, const char* what, const demo_image* im) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s_%s.png", o->out, label, what);
    return demo_image_write_png(im, path);
}

static int run_technique(const options* o, demo_renderer* r, const demo_view* v,
                         const swarp_aabb* box, demo_technique t, int splits, int write,
                         tech_result* res) {
    memset(res, 0, sizeof *res);
    res->tech = t;
    if (o->label_override)
        snprintf(res->label, sizeof res->label, "%s", o->label_override);
    else if (demo_technique_is_split((demo_technique)t))
        snprintf(res->label, sizeof res->label, "%s%d", demo_technique_name(t), splits);
    else
        snprintf(res->label, sizeof res->label, "%s", demo_technique_name(t));
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = t;
    req.splits = splits;
    req.scheme = o->scheme;
    req.scheme_lambda = o->scheme_lambda;
    req.pseudo_near = o->pseudo_near;
    req.pseudo_far = o->pseudo_far;
    req.scheme_np = o->scheme_np;
    req.scheme_fp = o->scheme_fp;
    req.select = o->select;
    req.map_res = o->map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    demo_shadow sh;
    res->setup_us = time_setup(v, box, &req, &sh);
    if (res->setup_us < 0) return -2;
    res->source = sh.source;
    res->sh = sh;
    res->passes = sh.count + 1;
    res->texels = (double)sh.count * o->map * o->map;
    res->gl_errors += demo_render_shadow(r, &sh, o->filter, res->shadow_ms);
    for (int i = 0; i < sh.count; ++i) res->shadow_ms_total += res->shadow_ms[i];

    demo_main_params p;
    memset(&p, 0, sizeof p);
    memcpy(p.view, v->view, sizeof p.view);
    memcpy(p.proj, v->proj, sizeof p.proj);
    p.light_dir[0] = (float)v->light.direction.x;
    p.light_dir[1] = (float)v->light.direction.y;
    p.light_dir[2] = (float)v->light.direction.z;
    p.filter = o->filter;
    p.blend = sh.count > 1 ? o->blend : 0.0f;
    p.grid = o->grid;
    p.normal_offset = o->offset;
    p.vw = v->w;
    p.vh = v->h;
    /* shaded view, then the measurement from the same pass's float targets */
    p.mode = DEMO_MODE_SHADED;
    res->gl_errors += demo_render_main(r, &sh, &p, &res->main_ms);
    if (read_picture(r, v->w, v->h, &res->shaded)) return -1;
    float* tex = malloc(sizeof(float) * 4 * (size_t)v->w * v->h);
    float* pos = malloc(sizeof(float) * 4 * (size_t)v->w * v->h);
    if (!tex || !pos) {
        free(tex);
        free(pos);
        return -1;
    }
    demo_render_read_aux(r, tex, pos);
    /* measured against Lloyd's model only where the model describes the
     * configuration (not for lixel or cube-face maps) */
    res->nrows = sh.model_applies ? demo_measure(v, &sh, o->map, tex, pos, res->rows, 16) : 0;
    free(tex);
    free(pos);
    res->max_mx = sh.predicted_max_mx;
    res->max_mz = sh.predicted_max_mz;
    if (write) {
        p.mode = DEMO_MODE_SAMPLING;
        p.blend = 0;
        res->gl_errors += demo_render_main(r, &sh, &p, NULL);
        if (read_picture(r, v->w, v->h, &res->sampling)) return -1;
        p.mode = DEMO_MODE_SPLITS;
        res->gl_errors += demo_render_main(r, &sh, &p, NULL);
        if (read_picture(r, v->w, v->h, &res->splits)) return -1;
        p.mode = DEMO_MODE_GRID;
        res->gl_errors += demo_render_main(r, &sh, &p, NULL);
        if (read_picture(r, v->w, v->h, &res->grid)) return -1;
        int e = light_view_picture(r, v, &sh, &res->light);
        if (e < 0) return -1;
        res->gl_errors += e;

        demo_image third;
        int body_faces = 0;
        int e3 = demo_third_person(r, v, &sh, box, &p, &third, &body_faces);
        if (e3 < 0) return -1;
        res->gl_errors += e3;
        if (body_faces < 4) {
            /* a body B is a polyhedron: the library gave none to draw */
            fprintf(stderr, "demo: %s: no body B drawn in the third-person view\n", res->label);
            ++res->gl_errors;
        }
        char title[160];
        snprintf(title, sizeof title, "%s: m_x, m_z along the view vector", res->label);
        demo_image graph;
        if (demo_error_graph(v, &sh, o->map, res->rows, res->nrows, title, &graph)) return -1;
        demo_image_label(&res->shaded, 8, 8, 2, res->label);
        demo_image_label(&res->sampling, 8, 8, 2, res->label);
        demo_image_sampling_legend(&res->sampling, 20, v->h - 44, v->w / 2 > 420 ? 420 : v->w / 2);
        demo_image_label(&res->splits, 8, 8, 2, res->label);
        demo_image_label(&res->grid, 8, 8, 2, res->label);
        char gl[64];
        snprintf(gl, sizeof gl, "grid: %g texels per cell", (double)o->grid);
        demo_image_label(&res->grid, 8, 40, 1, gl);
        demo_image_label(&res->light, 8, res->light.h - 20, 1, res->label);
        const demo_image* all[7] = {&res->shaded, &res->sampling, &res->splits, &res->grid,
                                    &res->light, &graph, &third};
        res->min_nonblank = 1.0;
        for (int k = 0; k < 7; ++k) {
            double nb = demo_image_nonblank(all[k]);
            if (nb < res->min_nonblank) res->min_nonblank = nb;
        }
        int w = 0;
        w |= write_png(o, res->label, "shaded", &res->shaded);
        w |= write_png(o, res->label, "sampling", &res->sampling);
        w |= write_png(o, res->label, "splits", &res->splits);
        w |= write_png(o, res->label, "grid", &res->grid);
        w |= write_png(o, res->label, "light", &res->light);
        w |= write_png(o, res->label, "error", &graph);
        w |= write_png(o, res->label, "third", &third);
        demo_image_free(&graph);
        demo_image_free(&third);
        if (w) return -1;
    }
    res->ok = 1;
    return 0;
}

static void free_result(tech_result* r) {
    demo_image_free(&r->shaded);
    demo_image_free(&r->sampling);
    demo_image_free(&r->splits);
    demo_image_free(&r->grid);
    demo_image_free(&r->light);
}

static void print_measure(const tech_result* r) {
    printf("  measured vs predicted along the view vector (%s):\n", r->label);
    printf("  %9s %5s %9s %9s %7s %9s %9s %7s %6s\n", "z", "split", "meas m_x", "pred m_x",
           "ratio", "meas m_z", "pred m_z", "ratio", "n");
    for (int i = 0; i < r->nrows; ++i) {
        const demo_measure_row* q = &r->rows[i];
        printf("  %9.2f %5d %9.4f %9.4f %7.3f %9.4f %9.4f %7.3f %6d\n", q->z, q->split, q->mx,
               q->pred_mx, q->ratio_mx, q->mz, q->pred_mz, q->ratio_mz, q->samples);
    }
}

static int make_sheet(const options* o, tech_result* all, int n_all) {
    /* rows: techniques seen from the same camera; columns: shaded, sampling
     * rate, texel grid, splits */
    tech_result* res[DEMO_TECH_COUNT + 1];
    int n = 0;
    for (int i = 0; i < n_all; ++i)
        if (!all[i].own_view) res[n++] = &all[i];
    if (n == 0) return 0;
    int cw = 320, ch = (int)lround(320.0 * res[0]->shaded.h / res[0]->shaded.w);
    int hdr = 28;
    demo_image sheet;
    if (demo_image_alloc(&sheet, 4 * cw, hdr + n * ch)) return -1;
    const uint8_t white[3] = {255, 255, 255}, black[3] = {0, 0, 0};
    demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, white);
    const char* cols[4] = {"shaded", "sampling rate (Listing A.3)", "texel grid (Listing A.4)",
                           "split colours (5.1)"};
    for (int c = 0; c < 4; ++c) demo_image_text(&sheet, c * cw + 8, 8, 2, cols[c], black);
    for (int i = 0; i < n; ++i) {
        demo_image* src[4] = {&res[i]->shaded, &res[i]->sampling, &res[i]->grid, &res[i]->splits};
        for (int c = 0; c < 4; ++c) {
            demo_image small;
            if (demo_image_resize(src[c], cw, ch, &small)) return -1;
            demo_image_blit(&sheet, c * cw, hdr + i * ch, &small);
            demo_image_free(&small);
        }
        demo_image_label(&sheet, 6, hdr + i * ch + 6, 2, res[i]->label);
    }
    int rc = write_png(o, "sheet", "techniques", &sheet);
    demo_image_free(&sheet);
    return rc;
}

static int load_scene(const options* o, demo_scene* s) {
    if (o->obj) return demo_scene_obj(s, o->obj);
    return demo_scene_default(s);
}

static demo_ctx* open_context(void) {
    int maj = 0, min = 0;
    demo_ctx* ctx = demo_ctx_create(&maj, &min);
    if (!ctx) {
        fprintf(stderr, "demo: OSMesa could not create a core-profile context\n");
        return NULL;
    }
    if (demo_gl_load()) {
        demo_ctx_destroy(ctx);
        return NULL;
    }
    printf("OpenGL %s on %s (core %d.%d requested)\n", (const char*)glGetString(GL_VERSION),
           (const char*)glGetString(GL_RENDERER), maj, min);
    return ctx;
}

typedef struct gallery_report {
    double min_nonblank;          /**< smallest non-blank fraction of any picture */
    int produced[DEMO_TECH_COUNT + 1]; /**< 1: all pictures of technique t written */
    int have_plan;                /**< plan is valid */
    demo_plan plan;               /**< the plan of the view */
    int planned_passes;           /**< shadow passes the planned entry rendered (-1: none) */
} gallery_report;

/* What the view calls for (issue 8): its camera, light and scene box; the
 * camera moves only along --frames or a camera path; soft shadows when a
 * filter is chosen.  No planes of interest: a swarp_plane is unbounded, and
 * the room corner's floor (y = 0.3) is then the whole ground, which the
 * planner rightly gives a lixel map -- but the demo's lixel maps cover only
 * the room's rectangles and its shader cannot pick between lixel maps and a
 * cascade, so it could not render that plan (docs/demo.md).  Budget: 1
 * pixel per texel (the planner's default), --map, at most DEMO_MAX_SPLITS
 * passes. */
static int plan_view(const options* o, const demo_view* v, const swarp_aabb* box, demo_plan* out) {
    int moves = o->frames > 0 || o->path_count > 1;
    return demo_plan_make(&v->cam, &v->light, box, v->w, v->h, o->map, DEMO_MAX_SPLITS, moves,
                          o->filter, NULL, 0, out);
}

static int run_gallery(const options* o, int single, gallery_report* rep) {
    demo_view v;
    if (options_view(o, &v)) return 2;
    demo_view_update(&v);
    demo_scene scene;
    if (load_scene(o, &scene)) return 2;
    if (mkdir_p(o->out)) {
        fprintf(stderr, "demo: cannot create %s\n", o->out);
        demo_scene_free(&scene);
        return 2;
    }
    demo_ctx* ctx = open_context();
    if (!ctx) {
        demo_scene_free(&scene);
        return 2;
    }
    double t_start = demo_now_ms();
    demo_renderer r;
    int rc = 0;
    if (demo_render_init(&r, &scene, o->w, o->h, o->map, DEMO_MAX_SPLITS)) {
        demo_ctx_destroy(ctx);
        demo_scene_free(&scene);
        return 2;
    }
    printf("scene: %zu triangles, box (%.0f %.0f %.0f)-(%.0f %.0f %.0f); %dx%d, map %d^2\n",
           scene.count / 3, scene.box.min.x, scene.box.min.y, scene.box.min.z, scene.box.max.x,
           scene.box.max.y, scene.box.max.z, o->w, o->h, o->map);
    demo_plan plan;
    int have_plan = 0;
    if (!single || o->technique == TECH_PLANNED) {
        if (plan_view(o, &v, &scene.box, &plan) == 0) {
            have_plan = 1;
            demo_plan_print(&plan, stdout);
            if (rep) {
                rep->have_plan = 1;
                rep->plan = plan;
            }
        } else {
            rc = 1;
        }
    }
    if (rep) rep->planned_passes = -1;
    tech_result res[DEMO_TECH_COUNT + 1];
    int n = 0;
    /* the planned chain first, then every technique */
    for (int ti = 0; ti <= DEMO_TECH_COUNT; ++ti) {
        int t = ti == 0 ? TECH_PLANNED : ti - 1;
        if (single && t != o->technique) continue;
        if (t == TECH_PLANNED && !have_plan) continue;
        /* the planned entry: the plan's technique with its scheme and
         * filter (plan.c maps them), under the label "planned" */
        options q = *o;
        demo_technique tt = (demo_technique)t;
        const char* name = demo_technique_name(tt);
        if (t == TECH_PLANNED) {
            tt = plan.technique;
            name = "planned";
            q.scheme = plan.scheme;
            q.scheme_lambda = plan.scheme_lambda;
            q.pseudo_near = plan.pseudo_near;
            q.pseudo_far = plan.pseudo_far;
            q.filter = plan.filter;
            q.label_override = "planned";
        }
        if (!demo_technique_available(tt)) {
            if (single) {
                fprintf(stderr, "demo: %s is not available in this build yet\n", name);
                rc = 2;
            } else {
                printf("%-14s not available in this build yet (library stage not merged)\n", name);
            }
            continue;
        }
        int splits = t == TECH_PLANNED ? plan.splits
                     : demo_technique_is_split((demo_technique)t) ? o->splits : 1;
        /* the lixel maps are for the room corner: without an explicit
         * --camera the gallery looks at it with the room preset (and keeps
         * it off the same-view sheet) */
        demo_view lv = v;
        int own_view = t == DEMO_TECH_LIXEL && !o->camera_given && !o->obj;
        if (own_view) {
            if (camera_preset("room", o->w, o->h, &lv.cam)) return 2;
            demo_view_update(&lv);
        }
        int e = run_technique(&q, &r, own_view ? &lv : &v, &scene.box, tt, splits, 1, &res[n]);
        if (e == -2 && !single) {
            /* the library refused the technique itself (not implemented in
             * the linked library): say so and go on */
            printf("%-14s skipped: the library's setup refused it (see above)\n", name);
            free_result(&res[n]);
            continue;
        }
        if (e) {
            fprintf(stderr, "demo: %s failed\n", name);
            free_result(&res[n]);
            rc = 1;
            continue;
        }
        res[n].own_view = own_view;
        printf("%-14s done: %s/%s_*.png (matrices from %s%s%s%s)\n", res[n].label, o->out,
               res[n].label, res[n].source, own_view ? "; room camera" : "",
               res[n].sh.status != SWARP_OK ? "; " : "",
               res[n].sh.status != SWARP_OK ? swarp_status_name(res[n].sh.status) : "");
        if (t == TECH_PLANNED) {
            printf("planned        rendered %d shadow passes (%s, filter %s) over [%.3g, %.3g]; "
                   "the plan asks for %u over [%.3g, %.3g]\n",
                   res[n].passes - 1, demo_technique_name(tt), demo_filter_name(q.filter),
                   res[n].sh.near, res[n].sh.far, plan.plan.shadow_passes, plan.plan.near,
                   plan.plan.far);
            if (rep) rep->planned_passes = res[n].passes - 1;
        }
        if (single) {
            printf("  timing: setup %.2f us (median of 101 calls);", res[n].setup_us);
            for (int k = 0; k < res[n].passes - 1; ++k)
                printf(" shadow pass %d %.2f ms;", k, res[n].shadow_ms[k]);
            printf(" main pass %.2f ms; %d passes, %.0f texels\n", res[n].main_ms, res[n].passes,
                   res[n].texels);
            print_measure(&res[n]);
        }
        if (res[n].gl_errors) rc = 1;
        if (rep) {
            if (res[n].min_nonblank < rep->min_nonblank) rep->min_nonblank = res[n].min_nonblank;
            rep->produced[t] = 1;
        }
        ++n;
    }
    if (n > 0 && !single && make_sheet(o, res, n)) rc = 1;
    if (n > 0) {
        printf("\nsummary (%dx%d, map %d^2, camera %s, filter %s; %s)\n", o->w, o->h, o->map,
               o->camera, demo_filter_name(o->filter),
               "predicted m from the library's error model");
        printf("%-14s %9s %6s %10s %9s %9s %10s %10s %9s %9s\n", "technique", "setup_us",
               "passes", "texels", "shadow_ms", "main_ms", "meas_mz_mx", "pred_mz_mx",
               "meas/pred", "gl_err");
        for (int i = 0; i < n; ++i) {
            /* the worst (largest) measured m_z and its prediction */
            double mm = 0, pm = NAN;
            for (int k = 0; k < res[i].nrows; ++k)
                if (res[i].rows[k].mz > mm) {
                    mm = res[i].rows[k].mz;
                    pm = res[i].rows[k].pred_mz;
                }
            if (res[i].nrows > 0)
                printf("%-14s %9.2f %6d %10.0f %9.2f %9.2f %10.3f %10.3f %9.3f %9d\n",
                       res[i].label, res[i].setup_us, res[i].passes, res[i].texels,
                       res[i].shadow_ms_total, res[i].main_ms, mm, pm, mm / pm, res[i].gl_errors);
            else
                printf("%-14s %9.2f %6d %10.0f %9.2f %9.2f %10s %10s %9s %9d\n", res[i].label,
                       res[i].setup_us, res[i].passes, res[i].texels, res[i].shadow_ms_total,
                       res[i].main_ms, "-", "-", "-", res[i].gl_errors);
        }
        printf("(meas_mz_mx: the largest measured m_z along the view vector, pred_mz_mx the\n"
               " library's m_z there, '-' where Lloyd's model does not describe the maps;\n"
               " timings: glFinish-bracketed, llvmpipe)\n");
    }
    for (int i = 0; i < n; ++i) free_result(&res[i]);
    printf("total %.1f s\n", (demo_now_ms() - t_start) / 1e3);
    demo_render_free(&r);
    demo_ctx_destroy(ctx);
    demo_scene_free(&scene);
    return rc;
}

static int run_frames(const options* o, double* out_max_drift) {
    demo_view v;
    if (options_view(o, &v)) return 2;
    demo_scene scene;
    if (load_scene(o, &scene)) return 2;
    demo_ctx* ctx = open_context();
    if (!ctx) {
        demo_scene_free(&scene);
        return 2;
    }
    demo_renderer r;
    if (demo_render_init(&r, &scene, o->w, o->h, o->map, DEMO_MAX_SPLITS)) {
        demo_ctx_destroy(ctx);
        demo_scene_free(&scene);
        return 2;
    }
    int t = o->technique < 0 ? DEMO_TECH_UNIFORM : o->technique;
    int rc = 0;
    /* flicker: a fixed world point's position inside its texel.  Texels
     * that slide under the scene (unstabilised maps) change the fraction
     * from frame to frame; snapped maps ([RHS] §3.5) keep it. */
    const swarp_vec3 probe = {5, 0, v.cam.eye.z - 80};
    double prev_frac[2] = {NAN, NAN};
    int prev_map = -1;
    for (int f = 0; f < o->frames; ++f) {
        if (o->path_count > 0) {
            /* a camera path file: one "ex ey ez dx dy dz" line per frame,
             * looped */
            const double* k = o->path + 6 * (f % o->path_count);
            v.cam.eye = (swarp_vec3){k[0], k[1], k[2]};
            v.cam.dir = (swarp_vec3){k[3], k[4], k[5]};
        } else {
            /* fly down the boulevard, turning slowly */
            v.cam.eye.z -= 2.5;
            double yaw = 0.15 * sin(0.05 * f);
            v.cam.dir = (swarp_vec3){sin(yaw), -0.06, -cos(yaw)};
        }
        demo_view_update(&v);
        tech_result res;
        if (run_technique(o, &r, &v, &scene.box, (demo_technique)t, o->splits, 0, &res)) {
            rc = 1;
            break;
        }
        /* the probe's map by eye depth and its texel coordinates */
        double dz = (probe.x - v.cam.eye.x) * v.cam.dir.x + (probe.y - v.cam.eye.y) * v.cam.dir.y +
                    (probe.z - v.cam.eye.z) * v.cam.dir.z;
        dz /= sqrt(v.cam.dir.x * v.cam.dir.x + v.cam.dir.y * v.cam.dir.y + v.cam.dir.z * v.cam.dir.z);
        uint32_t mi = 0;
        swarp_cascade_select_depth(res.sh.split, (size_t)res.sh.count, dz, &mi);
        swarp_vec4 h;
        swarp_mat4_transform(&res.sh.light[mi], &probe, &h);
        double ts = (h.x / h.w * 0.5 + 0.5) * res.sh.viewport[mi][0];
        double tt = (h.y / h.w * 0.5 + 0.5) * res.sh.viewport[mi][1];
        double frac[2] = {ts - floor(ts), tt - floor(tt)};
        double drift = NAN;
        if ((int)mi == prev_map) {
            double a = fabs(frac[0] - prev_frac[0]), b = fabs(frac[1] - prev_frac[1]);
            a = fmin(a, 1 - a);
            b = fmin(b, 1 - b);
            drift = fmax(a, b);
        }
        prev_frac[0] = frac[0];
        prev_frac[1] = frac[1];
        prev_map = (int)mi;
        if (out_max_drift && !isnan(drift) && drift > *out_max_drift) *out_max_drift = drift;
        printf("frame %d/%d: setup %.2f us, %d shadow passes %.2f ms, main %.2f ms, gl errors %d, "
               "probe in map %u, sub-texel drift %.4f texel\n",
               f + 1, o->frames, res.setup_us, res.passes - 1, res.shadow_ms_total, res.main_ms,
               res.gl_errors, mi, drift);
        fflush(stdout);
        if (res.gl_errors) rc = 1;
        free_result(&res);
    }
    demo_render_free(&r);
    demo_ctx_destroy(ctx);
    demo_scene_free(&scene);
    return rc;
}

/* ------------------------------------------------------------------------ */
/* headless tests (meson test)                                              */
/* ------------------------------------------------------------------------ */
enum { EXIT_SKIP = 77 };

/* 2-D convex hull (monotone chain) of n points; returns the hull size. */
static int hull2(double (*p)[2], int n, double (*out)[2]) {
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && (p[j][0] < p[j - 1][0] ||
                                  (p[j][0] == p[j - 1][0] && p[j][1] < p[j - 1][1]));
             --j) {
            double t0 = p[j][0], t1 = p[j][1];
            p[j][0] = p[j - 1][0];
            p[j][1] = p[j - 1][1];
            p[j - 1][0] = t0;
            p[j - 1][1] = t1;
        }
    int k = 0;
#define CROSS(o, a, b) (((a)[0] - (o)[0]) * ((b)[1] - (o)[1]) - ((a)[1] - (o)[1]) * ((b)[0] - (o)[0]))
    for (int i = 0; i < n; ++i) {
        while (k >= 2 && CROSS(out[k - 2], out[k - 1], p[i]) <= 0) --k;
        out[k][0] = p[i][0];
        out[k][1] = p[i][1];
        ++k;
    }
    for (int i = n - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && CROSS(out[k - 2], out[k - 1], p[i]) <= 0) --k;
        out[k][0] = p[i][0];
        out[k][1] = p[i][1];
        ++k;
    }
    return k - 1;
}

static int inside_hull(double (*h)[2], int n, double x, double y) {
    for (int i = 0; i < n; ++i) {
        double q[2] = {x, y};
        if (CROSS(h[i], h[(i + 1) % n], q) < 0) return 0;
    }
    return 1;
}
#undef CROSS

static int test_iou(const options* o, demo_ctx* ctx) {
    (void)ctx;
    demo_scene scene;
    swarp_aabb caster;
    if (demo_scene_box(&scene, &caster)) return 1;
    demo_view v;
    memset(&v, 0, sizeof v);
    v.w = o->w;
    v.h = o->h;
    v.cam.eye = (swarp_vec3){0, 30, 45};
    v.cam.dir = (swarp_vec3){0, -0.75, -1};
    v.cam.up = (swarp_vec3){0, 1, 0};
    v.cam.fovy = 50 * DEG;
    v.cam.aspect = (double)v.w / v.h;
    v.cam.near = 1;
    v.cam.far = 150;
    v.light.type = SWARP_LIGHT_DIRECTIONAL;
    demo_view_update(&v);
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 1;
    const demo_technique techs[8] = {DEMO_TECH_UNIFORM, DEMO_TECH_LISPSM, DEMO_TECH_PSSM,
                                     DEMO_TECH_PSM, DEMO_TECH_PSSM_LISPSM, DEMO_TECH_PSSM_STABLE,
                                     DEMO_TECH_GMNPR, DEMO_TECH_PSM_CUBE};
    /* two lights: the first lies behind the viewer as PSM sees it (the
     * camera looks steeply down, the sun is high: SWARP_INFO_PSM_INVERSE,
     * Kozlov's inverse projection, [KOZ] §14.2.1), the second, low and
     * ahead, in front of it (the ordinary PSM) */
    const swarp_vec3 lights[2] = {{0.45, -1, 0.3}, {0.2, -0.5, 1}};
    int fails = 0, ran = 0;
    float* tex = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    float* pos = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    for (int li = 0; li < 2; ++li) {
        v.light.direction = lights[li];
        /* the geometric shadow: the box's corners projected along the light
         * onto y = 0, and their convex hull */
        double pts[8][2], hull[10][2];
        const swarp_vec3 ld = v.light.direction;
        for (int i = 0; i < 8; ++i) {
            double x = (i & 1) ? caster.max.x : caster.min.x;
            double y = (i & 2) ? caster.max.y : caster.min.y;
            double z = (i & 4) ? caster.max.z : caster.min.z;
            double t = -y / ld.y;
            pts[i][0] = x + t * ld.x;
            pts[i][1] = z + t * ld.z;
        }
        int nh = hull2(pts, 8, hull);
        for (int k = 0; k < 8 && tex && pos; ++k) {
            if (!demo_technique_available(techs[k])) {
                printf("iou %-12s not in this build\n", demo_technique_name(techs[k]));
                ++fails;
                continue;
            }
            demo_shadow sh;
            if (setup_for(o, &v, &scene.box, techs[k], 4, &sh)) {
                ++fails;
                continue;
            }
            int errs = demo_render_shadow(&r, &sh, DEMO_FILTER_PCF2, NULL);
            demo_main_params p;
            memset(&p, 0, sizeof p);
            memcpy(p.view, v.view, sizeof p.view);
            memcpy(p.proj, v.proj, sizeof p.proj);
            p.light_dir[0] = (float)ld.x;
            p.light_dir[1] = (float)ld.y;
            p.light_dir[2] = (float)ld.z;
            p.filter = DEMO_FILTER_PCF2;
            p.mode = DEMO_MODE_SHADED;
            p.vw = v.w;
            p.vh = v.h;
            errs += demo_render_main(&r, &sh, &p, NULL);
            demo_render_read_aux(&r, tex, pos);
            long inter = 0, uni = 0, ground = 0;
            for (size_t i = 0; i < (size_t)v.w * v.h; ++i) {
                const float* q = pos + 4 * i;
                if (q[3] < 0 || fabsf(q[1]) > 1e-3f) continue; /* not ground */
                ++ground;
                int rendered = q[3] < 0.5f;
                int geometric = inside_hull(hull, nh, q[0], q[2]);
                inter += rendered && geometric;
                uni += rendered || geometric;
            }
            double iou = uni ? (double)inter / uni : 0;
            int ok = iou >= 0.95 && errs == 0 && uni > 200;
            printf("iou %-12s light %s: %.4f (%ld shadow pixels of %ld ground pixels, gl errors "
                   "%d%s%s) %s\n",
                   demo_technique_name(techs[k]), li ? "2" : "1", iou, uni,
                   ground, errs, sh.status != SWARP_OK ? ", " : "",
                   sh.status != SWARP_OK ? swarp_status_name(sh.status) : "", ok ? "ok" : "FAIL");
            fails += !ok;
            ++ran;
        }
    }
    free(tex);
    free(pos);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails || !ran ? 1 : 0;
}

static int test_measure(const options* o) {
    /* overhead light, horizontal camera: Lloyd's model's own setting */
    options q = *o;
    demo_view v;
    memset(&v, 0, sizeof v);
    v.w = o->w;
    v.h = o->h;
    if (camera_preset("measure", v.w, v.h, &v.cam)) return 1;
    q.light_elev = 90;
    q.have_light_dir = 0;
    light_from_options(&q, &v.light);
    demo_view_update(&v);
    demo_scene scene;
    if (demo_scene_default(&scene)) return 1;
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 1;
    /* the issue asks for uniform, LiSPSM and PSSM(4); the other techniques
     * the error model describes are checked too */
    const demo_technique techs[8] = {DEMO_TECH_UNIFORM, DEMO_TECH_LISPSM, DEMO_TECH_PSSM,
                                     DEMO_TECH_REPAR,   DEMO_TECH_GMNPR,  DEMO_TECH_PSEUDO,
                                     DEMO_TECH_PSM,     DEMO_TECH_PSSM_LISPSM};
    int fails = 0, ran = 0;
    for (int k = 0; k < 8; ++k) {
        if (!demo_technique_available(techs[k])) {
            printf("measure %-12s not in this build\n", demo_technique_name(techs[k]));
            ++fails;
            continue;
        }
        tech_result res;
        q.filter = DEMO_FILTER_NONE;
        if (run_technique(&q, &r, &v, &scene.box, techs[k], 4, 0, &res)) {
            ++fails;
            continue;
        }
        print_measure(&res);
        int bad = res.gl_errors != 0 || res.nrows < 4;
        int compared = 0;
        double worst = 0;
        for (int i = 0; i < res.nrows; ++i) {
            const demo_measure_row* m = &res.rows[i];
            if (isnan(m->pred_mz)) continue;
            ++compared;
            worst = fmax(worst, fabs(m->ratio_mz - 1));
            if (!(fabs(m->ratio_mz - 1) <= 0.10)) bad = 1;
        }
        printf("measure %-12s %s (%d depth bins compared with the library's m_z, worst |ratio - 1| "
               "%.4f)\n", res.label, bad ? "FAIL" : compared ? "ok" : "no depth bin to compare",
               compared, worst);
        fails += bad;
        ran += compared > 0;
        free_result(&res);
    }
    demo_render_free(&r);
    demo_scene_free(&scene);
    if (fails) return 1;
    return ran ? 0 : EXIT_SKIP;
}

/* The shader's map selection against the library's CPU references, pixel
 * by pixel: swarp_cascade_select_depth and swarp_cascade_select_best for
 * PSSM(4), swarp_lixel_select for the lixel maps.  A few pixels may differ
 * where float (GPU) and double (CPU) disagree right on a border. */
static int test_select(const options* o) {
    demo_view v;
    memset(&v, 0, sizeof v);
    v.w = o->w;
    v.h = o->h;
    demo_scene scene;
    if (demo_scene_default(&scene)) return 1;
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 1;
    float* tex = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    float* pos = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    int fails = 0;
    /* the cube cases: four suns (elevation, azimuth), the light in the
     * camera's post-projective space in front (w > 0) and behind (w < 0,
     * Kozlov's inverse-projection faces); 0, 0 = --light-angle */
    struct {
        demo_technique t;
        demo_select sel;
        const char* camera;
        double elev, azim;
    } cases[7] = {{DEMO_TECH_PSSM, DEMO_SELECT_DEPTH, "default", 0, 0},
                  {DEMO_TECH_PSSM, DEMO_SELECT_BEST, "high", 0, 0},
                  {DEMO_TECH_LIXEL, DEMO_SELECT_LIXEL, "room", 0, 0},
                  {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 0, 0},
                  {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 60, 20},
                  {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 20, 200},
                  {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 80, 300}};
    const double band = 0.2; /* blend band of the depth case */
    for (int c = 0; c < 7 && tex && pos; ++c) {
        if (camera_preset(cases[c].camera, v.w, v.h, &v.cam)) return 1;
        options lo = *o;
        if (cases[c].elev > 0) {
            lo.have_light_dir = 0;
            lo.light_elev = cases[c].elev;
            lo.light_azim = cases[c].azim;
        }
        light_from_options(&lo, &v.light);
        demo_view_update(&v);
        demo_shadow_request req;
        memset(&req, 0, sizeof req);
        req.technique = cases[c].t;
        req.splits = 4;
        req.scheme_lambda = 0.5;
        req.select = cases[c].sel;
        req.map_res = o->map;
        req.screen_w = v.w;
        req.screen_h = v.h;
        demo_shadow sh;
        if (demo_shadow_setup(&v.cam, &v.light, &scene.box, &req, &sh)) {
            ++fails;
            continue;
        }
        int errs = demo_render_shadow(&r, &sh, DEMO_FILTER_PCF2, NULL);
        demo_main_params p;
        memset(&p, 0, sizeof p);
        memcpy(p.view, v.view, sizeof p.view);
        memcpy(p.proj, v.proj, sizeof p.proj);
        p.light_dir[1] = -1;
        p.mode = DEMO_MODE_SHADED;
        p.blend = (float)band;
        p.vw = v.w;
        p.vh = v.h;
        errs += demo_render_main(&r, &sh, &p, NULL);
        demo_render_read_aux(&r, tex, pos);
        long wn = 0, wdiff = 0, wband = 0;
        swarp_bias_map maps[DEMO_MAX_SPLITS];
        for (int i = 0; i < sh.count; ++i) {
            memset(&maps[i], 0, sizeof maps[i]);
            maps[i].world_to_clip = sh.light[i];
            maps[i].res_s = sh.viewport[i][0];
            maps[i].res_t = sh.viewport[i][1];
            maps[i].depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
        }
        long n = 0, diff = 0;
        int hist[DEMO_MAX_SPLITS] = {0};
        for (size_t k = 0; k < (size_t)v.w * v.h; ++k) {
            if (pos[4 * k + 3] < 0) continue; /* sky */
            swarp_vec3 q = {pos[4 * k], pos[4 * k + 1], pos[4 * k + 2]};
            double z = tex[4 * k + 3];
            uint32_t depth_i = 0, want = 0;
            swarp_status st = swarp_cascade_select_depth(sh.split, (size_t)sh.count, z, &depth_i);
            if (sh.select == DEMO_SELECT_DEPTH) {
                want = depth_i;
                /* the blend weight against swarp_cascade_blend */
                uint32_t bi;
                double bw;
                if (!swarp_status_is_error(
                        swarp_cascade_blend(sh.split, (size_t)sh.count, z, band, &bi, &bw)) &&
                    bi == depth_i) {
                    double got_w = 1.0 - 2.0 * (tex[4 * k + 2] - floorf(tex[4 * k + 2]));
                    ++wn;
                    wband += bw < 1.0;
                    wdiff += fabs(got_w - bw) > 2e-3;
                }
            } else if (sh.select == DEMO_SELECT_BEST) {
                st = swarp_cascade_select_best(maps, (size_t)sh.count, &q, depth_i, &want, NULL);
            } else if (sh.select == DEMO_SELECT_CUBE) {
                /* [KOZ] Listing 14-1 on the CPU: the face of V, mapped to
                 * the index of that face's map */
                swarp_vec4 hv;
                swarp_mat4_transform(&sh.cube_camera, &q, &hv);
                swarp_vec3 V = {hv.x / hv.w, hv.y / hv.w, hv.z / hv.w};
                uint32_t face = 99;
                st = swarp_cube_lookup(&sh.cube_light, NULL, &V, &face, NULL, NULL);
                want = 99;
                for (int i = 0; i < sh.count; ++i)
                    if (sh.cube_face[i] == face) want = (uint32_t)i;
            } else {
                st = swarp_lixel_select(sh.light, (size_t)(sh.count - 1), &q, &want);
            }
            if (swarp_status_is_error(st)) continue;
            int got = (int)tex[4 * k + 2];
            ++n;
            if (got >= 0 && got < DEMO_MAX_SPLITS) hist[got]++;
            diff += got != (int)want;
        }
        double frac = n ? (double)diff / n : 1;
        int used = 0;
        for (int i = 0; i < sh.count; ++i) used += hist[i] > 0;
        /* every map must actually be chosen somewhere, or the test says
         * nothing about the selection */
        int ok = errs == 0 && n > 1000 && frac <= 0.005 && used >= 2;
        if (sh.select == DEMO_SELECT_DEPTH) {
            printf("blend  pssm   depth: %ld pixels (%ld in blend bands), %ld blend weights differ "
                   "from swarp_cascade_blend by > 2e-3\n", wn, wband, wdiff);
            ok = ok && wn > 1000 && wband > 500 && (double)wdiff / (double)wn <= 0.005;
        }
        if (sh.select == DEMO_SELECT_CUBE) {
            /* all faces drawn, and a cube map has 3 to 5 faces for a sun */
            ok = ok && sh.count >= 3 && sh.count <= 5;
            printf("cube light %2.0f,%3.0f: P w %+.3f, %d faces:", lo.light_elev, lo.light_azim,
                   sh.cube_light.w, sh.count);
            static const char* const face_name[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
            for (int i = 0; i < sh.count; ++i)
                printf(" %s%s", face_name[sh.cube_face[i] % 6],
                       sh.cube_light.w < 0 ? " (inverse)" : "");
            printf("\n");
        }
        printf("select %-6s %-5s: %ld pixels, %ld differ from the library (%.3f%%), %d maps used %s\n",
               demo_technique_name(cases[c].t),
               cases[c].sel == DEMO_SELECT_DEPTH  ? "depth"
               : cases[c].sel == DEMO_SELECT_BEST ? "best"
               : cases[c].sel == DEMO_SELECT_CUBE ? "cube"
                                                  : "lixel",
               n, diff, 100 * frac, used, ok ? "ok" : "FAIL");
        fails += !ok;
    }
    free(tex);
    free(pos);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}

/* Geometry cloning against K passes ([RHS] §3.3.6, Listing A.1): the same
 * depth in every texel of every layer (the same triangles rasterised with
 * the same matrices) and the same shadow mask (the `lit` value the main pass
 * writes for every pixel), bit for bit.  A control swaps the matrices of
 * maps 0 and 1 for the clone and must see differing pixels, so the
 * comparison can fail. */
static int test_clone(const options* o) {
    demo_scene scene;
    if (demo_scene_default(&scene)) return 1;
    demo_renderer r;
    if (demo_render_init(&r, &scene, o->w, o->h, o->map, DEMO_MAX_SPLITS)) return 1;
    size_t n = (size_t)o->map * o->map, npx = (size_t)o->w * o->h;
    float* a = malloc(sizeof(float) * n);
    float* multi_depth = malloc(sizeof(float) * n * DEMO_MAX_SPLITS);
    float* pos_multi = malloc(sizeof(float) * 4 * npx);
    float* pos_clone = malloc(sizeof(float) * 4 * npx);
    int fails = 0;
    const struct {
        demo_technique t;
        int k;
        const char* camera;
    } cases[6] = {{DEMO_TECH_PSSM, 4, "default"},         {DEMO_TECH_PSSM, 8, "default"},
                  {DEMO_TECH_PSSM, 16, "default"},        {DEMO_TECH_PSSM_LISPSM, 4, "default"},
                  {DEMO_TECH_PSSM_LISPSM, 8, "high"},     {DEMO_TECH_PSSM_STABLE, 4, "street"}};
    for (int c = 0; c < 6 && a && multi_depth && pos_multi && pos_clone; ++c) {
        demo_view v;
        demo_shadow sh;
        if (preset_view(o, cases[c].camera, &v) ||
            setup_for(o, &v, &scene.box, cases[c].t, cases[c].k, &sh)) {
            ++fails;
            continue;
        }
        demo_main_params p;
        demo_main_params_for(&v, DEMO_MODE_SHADED, DEMO_FILTER_PCF3, 0.1f, &p);
        /* K passes: every layer read back, then the main pass's mask */
        int errs = demo_render_shadow(&r, &sh, DEMO_FILTER_PCF3, NULL);
        for (int i = 0; i < sh.count; ++i) errs += demo_render_read_depth(&r, i, multi_depth + n * (size_t)i);
        errs += demo_render_main(&r, &sh, &p, NULL);
        demo_render_read_aux(&r, NULL, pos_multi);
        /* one pass by cloning: the same again */
        long differ = 0, covered = 0;
        errs += demo_render_shadow_single(&r, &sh, NULL);
        for (int i = 0; i < sh.count; ++i) {
            errs += demo_render_read_depth(&r, i, a);
            const float* m = multi_depth + n * (size_t)i;
            for (size_t k = 0; k < n; ++k) {
                covered += m[k] < 1.0f;
                differ += a[k] != m[k];
            }
        }
        errs += demo_render_main(&r, &sh, &p, NULL);
        demo_render_read_aux(&r, NULL, pos_clone);
        long mask_px = 0, mask_diff = 0, shadowed = 0;
        for (size_t k = 0; k < npx; ++k) {
            if (pos_multi[4 * k + 3] < 0) continue; /* sky */
            ++mask_px;
            shadowed += pos_multi[4 * k + 3] < 0.5f;
            mask_diff += memcmp(&pos_multi[4 * k + 3], &pos_clone[4 * k + 3], sizeof(float)) != 0;
        }
        int ok = errs == 0 && differ == 0 && covered > (long)n / 4 && mask_diff == 0 &&
                 shadowed > 100;
        printf("clone %-11s K=%-2d %-7s: %ld texels with geometry, %ld differ from the K-pass maps; "
               "shadow mask %ld pixels (%ld shadowed), %ld differ; gl errors %d %s\n",
               demo_technique_name(cases[c].t), cases[c].k, cases[c].camera, covered, differ,
               mask_px, shadowed, mask_diff, errs, ok ? "ok" : "FAIL");
        fails += !ok;
        if (c == 0) {
            /* control: maps 0 and 1 swapped for the clone only */
            demo_shadow sw = sh;
            sw.light[0] = sh.light[1];
            sw.light[1] = sh.light[0];
            errs = demo_render_shadow_single(&r, &sw, NULL);
            errs += demo_render_main(&r, &sh, &p, NULL);
            demo_render_read_aux(&r, NULL, pos_clone);
            long cdiff = 0;
            for (size_t k = 0; k < npx; ++k)
                cdiff += pos_multi[4 * k + 3] >= 0 &&
                         memcmp(&pos_multi[4 * k + 3], &pos_clone[4 * k + 3], sizeof(float)) != 0;
            int cok = errs == 0 && cdiff > 100;
            printf("clone control (maps 0 and 1 swapped): %ld mask pixels differ (must be > 100) %s\n",
                   cdiff, cok ? "ok" : "FAIL");
            fails += !cok;
        }
    }
    if (!a || !multi_depth || !pos_multi || !pos_clone) ++fails;
    free(a);
    free(multi_depth);
    free(pos_multi);
    free(pos_clone);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}

/* The machine line of the timing tables: cores, CPU, GL renderer. */
static void machine_line(char* out, size_t cap) {
    char model[160] = "unknown CPU";
    FILE* f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[256];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
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
    snprintf(out, cap, "%ld cores (nproc), %s; %s, OpenGL %s", sysconf(_SC_NPROCESSORS_ONLN), model,
             (const char*)glGetString(GL_RENDERER), (const char*)glGetString(GL_VERSION));
}

/* K + 1 passes against geometry cloning (1 + 1), K = 4, 8, 16, PSSM(K) +
 * LiSPSM on the default view: per frame the shadow passes and the main
 * pass, both glFinish-bracketed, both variants of one K in the same frame
 * loop (alternating which goes first) so load changes hit them alike;
 * medians over --frames (default 15).  Shaped like [RHS] Tables 7.1/7.2;
 * --bench-out FILE also writes the rows as TSV for swtool bench-report. */
static int bench_clone(const options* o) {
    demo_view v;
    if (preset_view(o, "default", &v)) return 1;
    demo_scene scene;
    if (demo_scene_default(&scene)) return 1;
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 1;
    const int F = o->frames > 0 ? o->frames : 15;
    double* t = malloc(sizeof(double) * 6 * (size_t)F);
    char machine[512];
    machine_line(machine, sizeof machine);
    FILE* tsv = NULL;
    if (o->bench_out && !(tsv = fopen(o->bench_out, "w"))) {
        fprintf(stderr, "demo: cannot write %s\n", o->bench_out);
        free(t);
        demo_render_free(&r);
        demo_scene_free(&scene);
        return 2;
    }
    if (tsv) {
        fprintf(tsv, "# demo --test bench-clone: geometry cloning vs K + 1 passes ([RHS] 3.3.6, Tables 7.1/7.2)\n");
        fprintf(tsv, "# machine\t%s\n", machine);
        fprintf(tsv, "# setup\t%dx%d\t%d\t%d\t%zu\n", v.w, v.h, o->map, F, scene.count / 3);
        fprintf(tsv, "# K\tvariant\tpasses\tshadow_ms\tmain_ms\tframe_ms\n");
    }
    printf("geometry cloning vs K + 1 passes: PSSM(K) + LiSPSM, default view, %dx%d, %d^2 maps, %zu "
           "triangles;\nmedian of %d frames, glFinish-bracketed ms; %s\n",
           v.w, v.h, o->map, scene.count / 3, F, machine);
    printf("%-40s %-9s %10s %10s %10s %7s %13s\n", "applied techniques", "3D passes", "shadow_ms",
           "main_ms", "frame_ms", "fps", "shadow ratio");
    int fails = 0;
    const int ks[3] = {4, 8, 16};
    for (int c = 0; c < 3 && t; ++c) {
        demo_shadow sh;
        if (setup_for(o, &v, &scene.box, DEMO_TECH_PSSM_LISPSM, ks[c], &sh)) {
            ++fails;
            continue;
        }
        demo_main_params p;
        demo_main_params_for(&v, DEMO_MODE_SHADED, DEMO_FILTER_PCF3, 0.1f, &p);
        int errs = 0;
        /* t: [shadow, main, frame] x [K passes, clone] x F */
        for (int f = 0; f < F; ++f) {
            for (int j = 0; j < 2; ++j) {
                int clone = (j + f) % 2;
                double s = 0, m = 0;
                if (clone) {
                    errs += demo_render_shadow_single(&r, &sh, &s);
                } else {
                    double ms[DEMO_MAX_SPLITS];
                    errs += demo_render_shadow(&r, &sh, DEMO_FILTER_PCF3, ms);
                    for (int i = 0; i < sh.count; ++i) s += ms[i];
                }
                errs += demo_render_main(&r, &sh, &p, &m);
                t[(0 * 2 + clone) * F + f] = s;
                t[(1 * 2 + clone) * F + f] = m;
                t[(2 * 2 + clone) * F + f] = s + m;
            }
        }
        double med[3][2];
        for (int q = 0; q < 3; ++q)
            for (int cl = 0; cl < 2; ++cl) med[q][cl] = demo_median(t + (q * 2 + cl) * F, F);
        for (int cl = 0; cl < 2; ++cl) {
            char name[64], passes[16];
            snprintf(name, sizeof name, "%sPSSM(%d) + LiSPSM", cl ? "Geometry Cloning " : "", ks[c]);
            snprintf(passes, sizeof passes, cl ? "1 + 1" : "%d + 1", ks[c]);
            printf("%-40s %-9s %10.2f %10.2f %10.2f %7.2f %13.2f\n", name, passes, med[0][cl], med[1][cl],
                   med[2][cl], 1000.0 / med[2][cl], med[0][cl] / med[0][0]);
            if (tsv)
                fprintf(tsv, "%d\t%s\t%s\t%.4f\t%.4f\t%.4f\n", ks[c], cl ? "clone" : "passes", passes,
                        med[0][cl], med[1][cl], med[2][cl]);
        }
        if (errs) {
            printf("K=%d: %d GL errors FAIL\n", ks[c], errs);
            ++fails;
        }
    }
    if (!t) ++fails;
    if (tsv && fclose(tsv)) ++fails;
    free(t);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}

/* Eye depth of every pixel of view v (INFINITY for sky) from the main
 * pass's float target: what the depth buffer saw. */
static int eye_depths(demo_renderer* r, const demo_view* v, const demo_shadow* sh, float* tex,
                      float* pos, float* out) {
    demo_main_params p;
    demo_main_params_for(v, DEMO_MODE_SHADED, DEMO_FILTER_NONE, 0, &p);
    int errs = demo_render_main(r, sh, &p, NULL);
    demo_render_read_aux(r, tex, pos);
    for (size_t k = 0; k < (size_t)v->w * v->h; ++k)
        out[k] = pos[4 * k + 3] < 0 ? INFINITY : tex[4 * k + 3];
    return errs;
}

/* Pixels whose eye depth differs (relative rel; sky against geometry counts). */
static long depth_changes(const float* a, const float* b, size_t n, double rel) {
    long d = 0;
    for (size_t k = 0; k < n; ++k) {
        if (isinf(a[k]) || isinf(b[k])) d += isinf(a[k]) != isinf(b[k]);
        else d += fabs((double)a[k] - b[k]) > rel * fabs((double)a[k]);
    }
    return d;
}

/* [RHS] §4.3: the minimum the GPU chain found equals the library's CPU
 * reductions bit for bit, the adjusted near plane lies in [camera near, min],
 * and re-rendering with it changes no pixel's depth (it clips nothing the
 * depth buffer saw), while a control near plane 5 % beyond the minimum
 * changes some. */
static int check_mindepth(const options* o, demo_renderer* r, const demo_scene* scene,
                          const demo_view* v, const demo_mindepth_result* md, int clip_check) {
    int same = md->gpu_min == md->cpu_pyramid_min && md->gpu_min == md->cpu_direct_min;
    int safe = md->adjusted_near <= md->gpu_min && md->adjusted_near >= v->cam.near;
    int ok = same && safe && md->gl_errors == 0;
    if (!same || !safe || md->gl_errors)
        printf("  FAIL: %s%s%s\n", same ? "" : "GPU and CPU minima differ; ",
               safe ? "" : "adjusted near clips what the camera saw; ", md->gl_errors ? "GL errors" : "");
    if (!clip_check || !ok) return ok ? 0 : 1;
    size_t npx = (size_t)v->w * v->h;
    float* tex = malloc(sizeof(float) * 4 * npx);
    float* pos = malloc(sizeof(float) * 4 * npx);
    float* d[3] = {malloc(sizeof(float) * npx), malloc(sizeof(float) * npx), malloc(sizeof(float) * npx)};
    demo_shadow sh;
    int errs = 0;
    if (!tex || !pos || !d[0] || !d[1] || !d[2] || setup_for(o, v, &scene->box, DEMO_TECH_UNIFORM, 1, &sh)) {
        ok = 0;
    } else {
        errs += demo_render_shadow(r, &sh, DEMO_FILTER_NONE, NULL);
        const double nears[3] = {v->cam.near, md->adjusted_near, 1.05 * md->gpu_min};
        for (int k = 0; k < 3; ++k) {
            demo_view vk = *v;
            vk.cam.near = nears[k];
            demo_view_update(&vk);
            errs += eye_depths(r, &vk, &sh, tex, pos, d[k]);
        }
        long adj = depth_changes(d[0], d[1], npx, 1e-4), ctl = depth_changes(d[0], d[2], npx, 1e-4);
        ok = errs == 0 && adj == 0 && ctl > 100;
        printf("  re-rendered with the adjusted near %.4f: %ld pixels change depth (must be 0); "
               "control near %.4f (min + 5%%): %ld change (must be > 100) %s\n",
               md->adjusted_near, adj, nears[2], ctl, ok ? "ok" : "FAIL");
    }
    free(tex);
    free(pos);
    for (int k = 0; k < 3; ++k) free(d[k]);
    return ok ? 0 : 1;
}

/* [RHS] §4.3 / Figs. 7.8-7.9: the min-depth near plane measured on the GPU
 * and on the CPU, and the sampling rate of LiSPSM with the camera's near
 * plane, the adjusted near plane and the pseudo-near plane side by side.
 * The test runs the checks of check_mindepth for the cameras default,
 * street, high and measure (or --camera). */
static int run_mindepth(const options* o, int test) {
    demo_view v;
    memset(&v, 0, sizeof v);
    v.w = o->w;
    v.h = o->h;
    demo_scene scene;
    if (load_scene(o, &scene)) return 2;
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 2;
    const char* cams[4] = {"default", "street", "high", "measure"};
    int ncam = test && !o->camera_given ? 4 : 1;
    int rc = 0;
    demo_mindepth_result md;
    for (int c = 0; c < ncam; ++c) {
        const char* cam = ncam > 1 ? cams[c] : o->camera_given ? o->camera : "street";
        if (camera_preset(cam, v.w, v.h, &v.cam)) return 2;
        light_from_options(o, &v.light);
        demo_view_update(&v);
        if (demo_mindepth(&r, &v, &md)) rc = 1;
        printf("min depth of the view, camera %s (near %.3g, far %.3g):\n", cam, v.cam.near, v.cam.far);
        printf("  GPU 2x2 min chain (%d passes) %.6f   [depth pass %.2f ms, chain + 1-texel read-back %.2f ms]\n",
               md.levels, md.gpu_min, md.depth_pass_ms, md.chain_ms);
        printf("  CPU swarp_mindepth_pyramid    %.6f   [full read-back %.2f ms, reduction %.3f ms]\n",
               md.cpu_pyramid_min, md.readback_ms, md.cpu_pyramid_ms);
        printf("  CPU swarp_mindepth_direct     %.6f   [reduction %.3f ms]\n", md.cpu_direct_min,
               md.cpu_direct_ms);
        printf("  adjusted near plane (swarp_mindepth_near) %.6f\n", md.adjusted_near);
        rc |= check_mindepth(o, &r, &scene, &v, &md, test);
    }
    if (!test && rc == 0) {
        /* sampling rate: camera near | adjusted near | pseudo-near */
        if (mkdir_p(o->out)) return 2;
        const char* names[3] = {"near", "adjusted", "pseudo"};
        for (int k = 0; k < 3; ++k) {
            demo_view vk = v;
            if (k == 1) vk.cam.near = md.adjusted_near;
            demo_view_update(&vk);
            options q = *o;
            q.pseudo_near = k == 2 ? 0.05 : 0;
            q.pseudo_far = 0;
            tech_result res;
            demo_technique t = k == 2 ? DEMO_TECH_PSEUDO : DEMO_TECH_LISPSM;
            q.out = o->out;
            char label[64];
            snprintf(label, sizeof label, "mindepth_%s", names[k]);
            if (run_technique(&q, &r, &vk, &scene.box, t, 1, 0, &res)) {
                rc = 1;
                continue;
            }
            demo_main_params p;
            memset(&p, 0, sizeof p);
            memcpy(p.view, vk.view, sizeof p.view);
            memcpy(p.proj, vk.proj, sizeof p.proj);
            p.light_dir[0] = (float)vk.light.direction.x;
            p.light_dir[1] = (float)vk.light.direction.y;
            p.light_dir[2] = (float)vk.light.direction.z;
            p.mode = DEMO_MODE_SAMPLING;
            p.filter = o->filter;
            p.normal_offset = o->offset;
            p.vw = vk.w;
            p.vh = vk.h;
            res.gl_errors += demo_render_main(&r, &res.sh, &p, NULL);
            demo_image im;
            if (read_picture(&r, vk.w, vk.h, &im)) return 2;
            char cap[160];
            snprintf(cap, sizeof cap, "LiSPSM, %s: near %.2f, predicted max m_z %.2f",
                     k == 0 ? "camera near" : k == 1 ? "adjusted near [RHS] 4.3" : "pseudo-near 0.05 (4.2)",
                     res.sh.near, res.sh.predicted_max_mz);
            demo_image_label(&im, 8, 8, 1, cap);
            demo_image_sampling_legend(&im, 20, vk.h - 44, vk.w / 2 > 420 ? 420 : vk.w / 2);
            rc |= write_png(o, label, "sampling", &im) ? 1 : 0;
            printf("  %-28s view range [%.3f, %.1f], n' %.3f, predicted max m_x %.3f, m_z %.3f -> %s/%s_sampling.png\n",
                   cap, res.sh.near, res.sh.far, res.sh.n_prime[0], res.sh.predicted_max_mx,
                   res.sh.predicted_max_mz, o->out, label);
            if (res.gl_errors) rc = 1;
            demo_image_free(&im);
            free_result(&res);
        }
    }
    demo_render_free(&r);
    demo_scene_free(&scene);
    return rc;
}

/* [KOZ] §14.3.2 projective blur (--filter projblur): on the ground, the raw
 * colour part of the shadow map (1 receiver, 0 caster; blur switched off)
 * projected as a texture agrees with the ordinary depth compare, and the
 * blurred one has a penumbra (lit strictly between 0.05 and 0.95) several
 * times wider than the raw texture's one-texel bilinear edge. */
static int test_blur(const options* o) {
    demo_view v;
    if (preset_view(o, "default", &v)) return 1;
    demo_scene scene;
    if (demo_scene_default(&scene)) return 1;
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 1;
    size_t npx = (size_t)v.w * v.h;
    float* pos[3] = {malloc(sizeof(float) * 4 * npx), malloc(sizeof(float) * 4 * npx),
                     malloc(sizeof(float) * 4 * npx)};
    int ok = 0;
    demo_shadow sh;
    if (pos[0] && pos[1] && pos[2] && !setup_for(o, &v, &scene.box, DEMO_TECH_UNIFORM, 1, &sh)) {
        /* 0: depth compare, 1 nearest tap; 1: raw colour part; 2: blurred */
        const demo_filter f[3] = {DEMO_FILTER_NONE, DEMO_FILTER_PROJBLUR, DEMO_FILTER_PROJBLUR};
        int errs = 0;
        for (int k = 0; k < 3; ++k) {
            r.blur_off = k == 1;
            errs += demo_render_shadow(&r, &sh, f[k], NULL);
            demo_main_params p;
            demo_main_params_for(&v, DEMO_MODE_SHADED, f[k], 0, &p);
            errs += demo_render_main(&r, &sh, &p, NULL);
            demo_render_read_aux(&r, NULL, pos[k]);
        }
        r.blur_off = 0;
        long ground = 0, agree = 0, soft_raw = 0, soft_blur = 0, shadowed = 0;
        for (size_t k = 0; k < npx; ++k) {
            const float* q = pos[0] + 4 * k;
            if (q[3] < 0 || fabsf(q[1]) > 1e-3f) continue; /* sky, not the ground */
            float depth = q[3], raw = pos[1][4 * k + 3], blur = pos[2][4 * k + 3];
            ++ground;
            shadowed += depth < 0.5f;
            agree += (depth > 0.5f) == (raw > 0.5f);
            soft_raw += raw > 0.05f && raw < 0.95f;
            soft_blur += blur > 0.05f && blur < 0.95f;
        }
        double fa = ground ? (double)agree / ground : 0;
        ok = errs == 0 && ground > 1000 && shadowed > 100 && fa >= 0.98 && soft_blur > 3 * soft_raw &&
             soft_blur > 100;
        printf("blur: %ld ground pixels (%ld shadowed by the depth compare); raw colour part agrees "
               "on %.2f%% (>= 98%%); penumbra pixels: raw %ld, blurred %ld (> 3x raw) %s\n",
               ground, shadowed, 100 * fa, soft_raw, soft_blur, ok ? "ok" : "FAIL");
    }
    for (int k = 0; k < 3; ++k) free(pos[k]);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return ok ? 0 : 1;
}

/* [RHS] §3.5: a fixed ground point keeps its place inside its texel while
 * the camera moves and turns (stabilised cascades), and does not without
 * stabilisation (the control that shows the check can fail). */
static int test_flicker(const options* o) {
    options q = *o;
    q.frames = 8;
    q.splits = 4;
    double drift_stable = 0, drift_plain = 0;
    q.technique = DEMO_TECH_PSSM_STABLE;
    int rc = run_frames(&q, &drift_stable);
    q.technique = DEMO_TECH_PSSM;
    rc |= run_frames(&q, &drift_plain);
    int ok = rc == 0 && drift_stable < 1e-4 && drift_plain > 1e-2;
    printf("flicker: largest sub-texel drift per frame: pssm-stable %.6f, pssm %.6f %s\n",
           drift_stable, drift_plain, ok ? "ok" : "FAIL");
    return ok ? 0 : 1;
}

static int test_images(const options* o) {
    /* the gallery at small size: every picture exists and is not blank */
    options q = *o;
    gallery_report rep;
    memset(&rep, 0, sizeof rep);
    rep.min_nonblank = 1.0;
    int rc = run_gallery(&q, 0, &rep);
    double nonblank = rep.min_nonblank;
    if (rc) return rc == 2 ? 1 : rc;
    int fails = 0, checked = 0;
    const char* what[7] = {"shaded", "sampling", "splits", "grid", "light", "error", "third"};
    int produced = 0;
    for (int t = 0; t < DEMO_TECH_COUNT; ++t) {
        if (!rep.produced[t]) {
            if (demo_technique_available((demo_technique)t))
                printf("note: %s was refused by the library's setup\n",
                       demo_technique_name((demo_technique)t));
            continue;
        }
        ++produced;
        char label[48];
        if (demo_technique_is_split((demo_technique)t))
            snprintf(label, sizeof label, "%s%d", demo_technique_name((demo_technique)t), q.splits);
        else
            snprintf(label, sizeof label, "%s", demo_technique_name((demo_technique)t));
        for (int k = 0; k < 7; ++k) {
            char path[1200];
            snprintf(path, sizeof path, "%s/%s_%s.png", q.out, label, what[k]);
            FILE* f = fopen(path, "rb");
            long size = 0;
            if (f) {
                fseek(f, 0, SEEK_END);
                size = ftell(f);
                fclose(f);
            }
            if (!f || size < 1000) {
                printf("missing or tiny: %s\n", path);
                ++fails;
            }
            ++checked;
        }
    }
    /* a picture counts as blank when fewer than 1% of its pixels differ
     * from its first pixel */
    printf("images: %d files checked, %d bad; least non-blank picture: %.1f%% of pixels\n",
           checked, fails, 100 * nonblank);
    if (nonblank < 0.01) ++fails;
    if (produced < 2) ++fails;
    return fails ? 1 : 0;
}

/* --plan: what the view calls for, printed, nothing rendered (no GL). */
static int print_plan_only(const options* o) {
    demo_view v;
    if (options_view(o, &v)) return 2;
    demo_scene scene;
    if (load_scene(o, &scene)) return 2;
    demo_plan plan;
    int rc = plan_view(o, &v, &scene.box, &plan) ? 1 : 0;
    if (rc == 0) demo_plan_print(&plan, stdout);
    demo_scene_free(&scene);
    return rc;
}

/* issue 8: --technique planned renders exactly the passes the plan asks
 * for, and the printed plan carries one "why:" line per reason flag. */
static int test_planned(const options* o) {
    options q = *o;
    q.technique = TECH_PLANNED;
    gallery_report rep;
    memset(&rep, 0, sizeof rep);
    rep.min_nonblank = 1.0;
    int rc = run_gallery(&q, 1, &rep);
    if (rc) return rc == 2 ? 1 : rc;
    if (!rep.have_plan) {
        printf("planned: no plan FAIL\n");
        return 1;
    }
    const struct swarp_plan* pl = &rep.plan.plan;
    char* text = NULL;
    size_t size = 0;
    FILE* mem = open_memstream(&text, &size);
    if (!mem) return 1;
    demo_plan_print(&rep.plan, mem);
    fclose(mem);
    int whys = 0, flags = 0;
    for (const char* s = text; (s = strstr(s, "\n  why: ")) != NULL; ++s) ++whys;
    for (uint32_t b = pl->reasons; b; b &= b - 1) ++flags;
    /* every plan says why it took (or left out) the splits, the
     * stabilisation and the filter at least */
    int ok = rep.planned_passes == (int)pl->shadow_passes && rep.plan.exact && whys == flags &&
             flags >= 3 && strstr(text, "cost: ") != NULL && rep.min_nonblank >= 0.01;
    printf("planned: %d shadow passes rendered, plan %u; %d reason lines printed, %d reason flags; "
           "mapped exactly: %s %s\n",
           rep.planned_passes, pl->shadow_passes, whys, flags, rep.plan.exact ? "yes" : "no",
           ok ? "ok" : "FAIL");
    free(text);
    return ok ? 0 : 1;
}

/* The two comparison sheets of issue 10 (sheets.c): projective blur vs PCF,
 * and single-map PSM vs the cube map with the sun in front of the camera
 * (--light-angle) and behind it (the same elevation, azimuth 10). */
static int run_sheets(const options* o) {
    if (mkdir_p(o->out)) {
        fprintf(stderr, "demo: cannot create %s\n", o->out);
        return 2;
    }
    demo_ctx* ctx = open_context();
    if (!ctx) return 2;
    demo_view v;
    memset(&v, 0, sizeof v);
    v.w = o->w;
    v.h = o->h;
    demo_scene scene;
    demo_renderer r;
    int rc = 2;
    if (setup_camera(o, &v.cam) == 0 && load_scene(o, &scene) == 0) {
        light_from_options(o, &v.light);
        demo_view_update(&v);
        if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS) == 0) {
            double t0 = demo_now_ms();
            printf("\ncomparison sheets (%s camera):\n", o->camera);
            rc = demo_sheet_blur(&r, &v, &scene, o->map, o->out);
            options b = *o;
            b.have_light_dir = 0;
            b.light_azim = 10;
            swarp_light behind;
            light_from_options(&b, &behind);
            rc |= demo_sheet_cube(&r, &v, &scene, o->map, &behind, o->out);
            printf("sheets %.1f s\n", (demo_now_ms() - t0) / 1e3);
            demo_render_free(&r);
        }
        demo_scene_free(&scene);
    }
    demo_ctx_destroy(ctx);
    return rc;
}

int main(int argc, char** argv) {
    options o;
    if (parse_options(argc, argv, &o)) return 2;
    if (load_camera_path(&o) < 0) return 2;
    if (o.test) {
        /* skip cleanly when OSMesa cannot give us a context */
        int maj, min;
        demo_ctx* probe = demo_ctx_create(&maj, &min);
        if (!probe) {
            printf("SKIP: OSMesa cannot create a core-profile context\n");
            return EXIT_SKIP;
        }
        demo_ctx_destroy(probe);
        if (!strcmp(o.test, "images")) return test_images(&o);
        if (!strcmp(o.test, "planned")) return test_planned(&o);
        demo_ctx* ctx = open_context();
        if (!ctx) return EXIT_SKIP;
        int rc;
        if (!strcmp(o.test, "iou")) rc = test_iou(&o, ctx);
        else if (!strcmp(o.test, "measure")) rc = test_measure(&o);
        else if (!strcmp(o.test, "select")) rc = test_select(&o);
        else if (!strcmp(o.test, "clone")) rc = test_clone(&o);
        else if (!strcmp(o.test, "mindepth")) rc = run_mindepth(&o, 1);
        else if (!strcmp(o.test, "flicker")) rc = test_flicker(&o);
        else if (!strcmp(o.test, "blur")) rc = test_blur(&o);
        else if (!strcmp(o.test, "bench-clone")) rc = bench_clone(&o);
        else {
            fprintf(stderr, "demo: unknown test %s\n", o.test);
            rc = 2;
        }
        demo_ctx_destroy(ctx);
        return rc;
    }
    if (o.plan_only) return print_plan_only(&o);
    if (o.frames > 0 && o.technique == TECH_PLANNED) {
        fprintf(stderr, "demo: --technique planned renders the gallery view, not --frames\n");
        return 2;
    }
    if (o.frames > 0) return run_frames(&o, NULL);
    if (o.mindepth) {
        demo_ctx* ctx = open_context();
        if (!ctx) return 2;
        int rc = run_mindepth(&o, 0);
        demo_ctx_destroy(ctx);
        return rc;
    }
    if (o.sheets_only) return run_sheets(&o);
    int rc = run_gallery(&o, o.technique >= 0, NULL);
    /* the default gallery ends with the comparison sheets */
    if (rc == 0 && o.technique < 0 && !o.no_sheets) rc = run_sheets(&o);
    return rc;
}
