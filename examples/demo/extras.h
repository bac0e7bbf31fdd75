/* extras.h -- the demo parts of issue 10 ("the rest of the seeds"), in their
 * own executable demo-extras (extras_main.c) so the gallery's files stay
 * untouched:
 *   extras_viz.c      third-person visualization view [RHS] §5.2-5.3
 *   extras_clone.c    single-pass splits by geometry cloning [RHS] §3.3.6, Listing A.1
 *   extras_blur.c     projective blur of the shadow map's colour part [KOZ] §14.3.2
 *   extras_mindepth.c min-depth near plane from a GPU mip-min chain [RHS] §4.3, Listing A.2
 *   extras_cube.c     PSM with cube-map faces in post-perspective space [KOZ] §14.2.2
 * Everything shadow-mathematical comes from the library (demo_shadow_setup,
 * swarp_body_*, swarp_cube_*, swarp_mindepth_*); these files only render. */
#ifndef DEMO_EXTRAS_H
#define DEMO_EXTRAS_H

#include "demo.h"
#include "extras_gl.h"

typedef struct extras_env {
    int w, h, map, frames;
    const char* out;
    double light_elev, light_azim; /**< degrees, as the gallery's --light-angle */
    demo_filter filter;
    demo_scene scene;
    demo_renderer r;
    demo_view v; /**< the common (first-person) view: the gallery's default camera */
} extras_env;

/** The gallery's "default" camera preset and --light-angle light. */
void extras_camera_preset(const char* name, int w, int h, swarp_camera* c);
void extras_light(double elev_deg, double azim_deg, swarp_light* l);

/** demo_shadow_setup for technique t (K = splits) seen by v. 0 on success. */
int extras_setup(const extras_env* e, const demo_view* v, demo_technique t, int splits,
                 demo_shadow* sh);
/** Main-pass parameters for view v. */
void extras_main_params(const demo_view* v, demo_mode mode, demo_filter filter, float blend,
                        demo_main_params* p);
/** Shadow passes + main pass of sh seen by v; the colour picture into *im
 *  (allocated) when im != NULL.  Returns the number of GL errors. */
int extras_render(extras_env* e, const demo_view* v, const demo_shadow* sh, demo_mode mode,
                  demo_image* im);
/** PNG into e->out/name.png. 0 on success. */
int extras_write(const extras_env* e, const char* name, const demo_image* im);

/** 3-D drawing on a picture seen through world -> clip matrix m (lines
 *  clipped at w > 0).  fill: convex polygon blended with alpha. */
void extras_line3(demo_image* im, const swarp_mat4* m, swarp_vec3 a, swarp_vec3 b, int thick,
                  const uint8_t c[3]);
void extras_fill3(demo_image* im, const swarp_mat4* m, const swarp_vec3* p, int n,
                  const uint8_t c[3], double alpha);
/** A view's world -> clip matrix in double (cglm look + perspective). */
void extras_view_matrix(const demo_view* v, swarp_mat4* out);

double extras_median(double* a, int n);
/** Fixed-width rows of a table shaped like [RHS] Tables 7.1/7.2. */
typedef struct extras_bench_row {
    char name[64];
    char passes[16];
    double shadow_ms, extra_ms, main_ms, frame_ms;
} extras_bench_row;
void extras_print_bench(const char* title, const extras_bench_row* rows, int n);

/* The five parts.  test != 0: the headless check (0 pass, 1 fail). */
int extras_viz(extras_env* e, int test);
int extras_cloning(extras_env* e, int test, extras_bench_row* rows, int* nrows);
int extras_blur(extras_env* e, int test);
int extras_mindepth(extras_env* e, int test);
/** One frame of the GPU min-depth path (depth pre-pass, mip-min chain, 1x1
 *  read-back) for the timing table of extras_clone.c. */
typedef struct extras_md extras_md;
extras_md* extras_md_create(extras_env* e);
void extras_md_destroy(extras_md* x);
/** Milliseconds of the path (glFinish before, the read-back syncs after);
 *  -1 on a GL error.  *out_min: the minimum read back. */
double extras_md_frame(extras_env* e, extras_md* x, const demo_view* v, float* out_min);
int extras_cube(extras_env* e, int test);
/** The adjusted near plane of view v measured on the GPU (extras_mindepth.c):
 *  swarp_mindepth_near of the mip-min chain's minimum; NAN on failure. */
double extras_measured_near(extras_env* e, const demo_view* v);

#endif
