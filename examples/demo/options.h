/* options.h -- the command line of the demo and of demo-check, and the views
 * (camera, sun, scene, GL context) built from it. */
#ifndef DEMO_OPTIONS_H
#define DEMO_OPTIONS_H

#include "ctx.h"
#include "demo.h"

#define DEMO_DEG (3.14159265358979323846 / 180.0)
/* --technique planned: the chain swarp_plan chose (plan.c), the gallery's
 * first entry */
#define DEMO_TECH_PLANNED DEMO_TECH_COUNT
/* exit status of a check that could not run (meson's "skipped") */
#define DEMO_EXIT_SKIP 77
/* --camera FILE: at most this many "ex ey ez dx dy dz" lines */
#define DEMO_MAX_PATH 256

typedef struct demo_options {
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
    const char* test;           /**< demo-check --test NAME */
    float blend, grid, offset;
    double pseudo_near, pseudo_far;
    double scheme_np, scheme_fp;
    demo_select select;
    int camera_given;
    int mindepth;
    double path[6 * DEMO_MAX_PATH]; /**< --camera FILE: eye and dir per frame */
    int path_count;
    int plan_only;              /**< --plan: print the plan and stop */
    const char* label_override; /**< demo_run_technique's label (the planned entry) */
    const char* bench_out;      /**< demo-check --bench-out: bench-clone's rows as TSV */
    int sheets_only;            /**< --sheets: only the comparison sheets (sheets.c) */
    int no_sheets;              /**< --no-sheets: the gallery without them */
    int have_light_gamma;       /**< --light-gamma: the sun placed relative to the camera */
    double light_gamma;         /**< degrees between the view direction and the light's */
    int nprime_measured;        /**< --nprime measured: the library's default n' */
    int basis_aligned;          /**< --basis aligned: the view-aligned light basis */
} demo_options;

/* options.c */
/** The options every mode shares (printed by --help of both programs). */
void demo_options_usage(void);
/** Parses argv into o (defaults first); --help prints `usage` and exits.
 *  0 on success, -1 (message on stderr) on a bad option. */
int demo_options_parse(int argc, char** argv, void (*usage)(void), demo_options* o);
/** --camera FILE: 1 when o->camera names a path file (loaded into o->path),
 *  0 when it is a preset name, -1 when the file holds no camera. */
int demo_options_load_path(demo_options* o);

/* view.c */
/** Camera preset `name` over the default scene at w x h. */
int demo_camera_preset(const char* name, int w, int h, swarp_camera* c);
/** The camera of the command line: the preset, or the path's first line. */
int demo_options_camera(const demo_options* o, swarp_camera* c);
/** The sun of --light-angle / --light-dir. */
void demo_options_light(const demo_options* o, swarp_light* l);
/** View of the command line (cam and light; view/proj not yet filled). */
int demo_options_view(const demo_options* o, demo_view* v);
/** View of preset `camera` at --size with the command line's sun, updated. */
int demo_preset_view(const demo_options* o, const char* camera, demo_view* v);
/** demo_shadow_setup of technique t with `splits` maps (practical scheme,
 *  lambda 0.5) for view v at --map. */
int demo_setup_for(const demo_options* o, const demo_view* v, const swarp_aabb* box,
                   demo_technique t, int splits, demo_shadow* sh);
/** --obj or the built-in scene. */
int demo_load_scene(const demo_options* o, demo_scene* s);
/** The OSMesa core-profile context with the GL entry points loaded, its
 *  version printed; NULL (message on stderr) when there is none. */
demo_ctx* demo_open_context(void);
/** A blank view at --size (no camera, no sun yet). */
void demo_sized_view(const demo_options* o, demo_view* v);
/** The scene (the built-in one when `builtin`, else --obj or the built-in
 *  one) and its renderer at --size and --map.  0, or -1 with both
 *  released. */
int demo_open_renderer(const demo_options* o, int builtin, demo_scene* s, demo_renderer* r);
/** mkdir -p. */
int demo_mkdir_p(const char* dir);

#endif
