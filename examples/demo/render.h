/* render.h -- the GL passes (render.c). */
#ifndef DEMO_RENDER_H
#define DEMO_RENDER_H

#include <stdint.h>

#include "gl.h"
#include "scene.h"
#include "shadow.h"

typedef enum demo_mode {
    DEMO_MODE_SHADED = 0,  /**< lambert + shadow test */
    DEMO_MODE_SAMPLING,    /**< [RHS] Listing A.3 colour scale */
    DEMO_MODE_SPLITS,      /**< [RHS] (5.1) split colours */
    DEMO_MODE_GRID,        /**< [RHS] Listing A.4 texel grid */
    DEMO_MODE_UNSHADOWED   /**< lambert only (light views) */
} demo_mode;

typedef enum demo_filter {
    DEMO_FILTER_NONE = 0, /**< one nearest tap */
    DEMO_FILTER_PCF2,     /**< hardware 2x2 bilinear compare */
    DEMO_FILTER_PCF3,     /**< 3x3 bilinear taps */
    DEMO_FILTER_PCF5,     /**< 5x5 bilinear taps */
    DEMO_FILTER_POISSON,  /**< 16 bilinear taps on a Poisson disk (swarp_pcf_poisson_disk) */
    DEMO_FILTER_VSM,      /**< variance shadow map, moments 3x3-filtered [VSM] (3.1)-(3.3) */
    DEMO_FILTER_EVSM,     /**< exponential VSM [VSM] §4.2, c from swarp_evsm_max_exponent */
    DEMO_FILTER_PROJBLUR, /**< [KOZ] §14.3.2 projective blur on the ground, pcf3 elsewhere */
    DEMO_FILTER_COUNT
} demo_filter;

typedef struct demo_renderer {
    GLuint vao, vbo;
    int vertex_count;
    GLuint prog_depth, prog_moment, prog_clone, prog_main;
    GLuint shadow_tex, shadow_fbo;
    GLuint moment_tex;         /**< RGBA32F array: VSM / EVSM moments, blur colour (lazy) */
    GLuint blur_tex;           /**< RGBA32F array: projective blur ping-pong (lazy) */
    GLuint prog_receiver, prog_blur;
    float blur_sigma;          /**< projective blur Gaussian sigma, texels */
    double blur_ms;            /**< time of the last blur passes */
    int blur_off;              /**< 1: keep the raw colour part (the blur test) */
    float poisson[32];         /**< 16 unit-disk points (swarp_pcf_poisson_disk) */
    float evsm_c;              /**< EVSM exponent (swarp_evsm_max_exponent, fp32) */
    int map_res, layers;
    unsigned warmed;           /**< shadow programs drawn once untimed (bit per program) */
    GLuint fbo, rb_color, rb_tex, rb_pos, rb_nrm, rb_depth;
    int w, h;
} demo_renderer;

/** Uploads the scene, compiles the programs, allocates a w x h main target
 *  (RGBA8 + three RGBA32F + depth) and a map_res^2 x max_layers depth array.
 *  0 on success. */
int demo_render_init(demo_renderer* r, const demo_scene* s, int w, int h, int map_res,
                     int max_layers);
void demo_render_free(demo_renderer* r);

/** The shadow passes, one per map.  ms_out[i]: glFinish-bracketed time of
 *  pass i (may be NULL).  Returns the number of GL errors seen. */
int demo_render_shadow(demo_renderer* r, const demo_shadow* sh, demo_filter filter,
                       double* ms_out);

/** All maps in ONE pass by geometry cloning ([RHS] §3.3.6, Listing A.1):
 *  a geometry shader emits each triangle into every map's layer and
 *  viewport.  Depth compare maps only.  *ms_out: glFinish-bracketed time. */
int demo_render_shadow_single(demo_renderer* r, const demo_shadow* sh, double* ms_out);
/** Reads layer `layer` of the depth array (map_res^2 floats). */
int demo_render_read_depth(demo_renderer* r, int layer, float* out);

typedef struct demo_main_params {
    float view[16], proj[16];       /**< camera (cglm, column-major) */
    float sel_view[16];             /**< the viewer's view matrix for split selection */
    int has_sel_view;               /**< 0: the camera above is the viewer */
    float light_dir[3];             /**< direction light travels */
    demo_mode mode;
    demo_filter filter;
    float blend;                    /**< split blend band, fraction of a split */
    float grid;                     /**< texels per grid cell (Listing A.4 "size") */
    float normal_offset;            /**< normal-offset bias, texels (swarp_bias_normal_offset) */
    int vw, vh;                     /**< viewport (<= target size) */
} demo_main_params;

/** The main pass into the w x h target.  *ms_out: glFinish-bracketed time.
 *  Returns the number of GL errors seen. */
int demo_render_main(demo_renderer* r, const demo_shadow* sh, const demo_main_params* p,
                     double* ms_out);

/** Read back the colour target (RGBA8, top row first) of vw x vh. */
void demo_render_read_color(demo_renderer* r, int vw, int vh, uint8_t* rgba);
/** Read back the float targets: tex = (s, t in texels, map index + (1 - w)/2
 *  with w the cascade blend weight of that map, eye depth),
 *  pos = (world xyz, lit in [0,1]); bottom row first (GL order). */
void demo_render_read_aux(demo_renderer* r, float* tex, float* pos);
/** Read back the facet normals of the drawn triangles: (unit world normal,
 *  1), (0, 0, 0, 0) where nothing was drawn; bottom row first. */
void demo_render_read_normals(demo_renderer* r, float* nrm);

double demo_now_ms(void);
const char* demo_filter_name(demo_filter f);
int demo_filter_parse(const char* name);

#endif
