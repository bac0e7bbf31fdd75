/* demo.h -- what the views, the techniques, the measurement, the pictures
 * and the checks of the demo share. */
#ifndef DEMO_DEMO_H
#define DEMO_DEMO_H

#include "image.h"
#include "render.h"
#include "scene.h"
#include "shadow.h"

typedef struct demo_view {
    swarp_camera cam;
    swarp_light light;
    float view[16], proj[16]; /**< cglm matrices of cam */
    int w, h;
} demo_view;

/** Fills view/proj from cam (cglm lookat + perspective). */
void demo_view_update(demo_view* v);

/** Main-pass parameters for view v with the gallery's defaults (grid 8,
 *  normal offset 1 texel). */
void demo_main_params_for(const demo_view* v, demo_mode mode, demo_filter filter, float blend,
                          demo_main_params* p);
/** Median of a[0..n) (sorts a); NAN for n <= 0. */
double demo_median(double* a, int n);

/** One row of the measured-vs-predicted table. */
typedef struct demo_measure_row {
    double z;                     /**< eye depth (bin centre, median of samples) */
    double mx, mz;                /**< measured screen pixels per texel (x, z) */
    double pred_mx, pred_mz;      /**< library's m_x, m_z at z (NAN if unavailable) */
    double ratio_mx, ratio_mz;    /**< median of the per-sample measured/predicted */
    int split;                    /**< the map the samples were shaded from */
    int samples;
} demo_measure_row;

/** Measures m_x and m_z along the view vector (centre column of the
 *  picture, ground pixels) from the read-back texel coordinates.  Writes up
 *  to cap rows (depth bins); returns their number. */
int demo_measure(const demo_view* v, const demo_shadow* sh, int map_res, const float* tex,
                 const float* pos, demo_measure_row* rows, int cap);

/** The measured error of docs/accuracy.md over the visible pixels of one
 *  render, maximum against maximum over the same receivers. */
typedef struct demo_measured {
    int pixels;                 /**< receiver pixels compared */
    /* the render: D = (d(s, t)/d(pixel x, y))^-1 from the read-back texel
     * coordinates of neighbouring pixels (central differences) */
    double render_m_s, render_m_t, render_sigma; /**< maxima over the pixels */
    swarp_vec3 render_at;       /**< world point of render_sigma */
    double render_cos_light;    /**< cos psi_l (receiver normal, light) there */
    /* swarp_measure_points at the same pixels' world points and facet
     * normals with the matrix of the map that shaded them */
    double points_m_s, points_m_t, points_sigma; /**< maxima over the pixels */
    swarp_vec3 points_at;
    double pixel_dev_p99;       /**< 99th percentile over the pixels of
                                     |render sigma / points sigma - 1| */
    double pixel_dev_max;       /**< its maximum */
} demo_measured;

/** Measures the render of sh (float targets tex, pos, nrm of
 *  demo_render_read_aux / _normals): every pixel whose four neighbours lie
 *  on the same plane and in the same map, faces the light
 *  (cos psi_l >= DEMO_MEASURE_MIN_COS_LIGHT) and projects into its map.
 *  0 on success, -1 on a library error. */
int demo_measure_render(const demo_view* v, const demo_shadow* sh, const float* tex,
                        const float* pos, const float* nrm, demo_measured* out);

/** The error graph along the view vector (Fig. 5.8): library m_x (orange),
 *  m_z (blue), split markers, measured points.  */
int demo_error_graph(const demo_view* v, const demo_shadow* sh, int map_res,
                     const demo_measure_row* rows, int nrows, const char* title,
                     demo_image* out);

/** Draws the view frustum (or split frustum [d0, d1]) seen through light
 *  matrix m into an image of the light view. */
void demo_draw_frustum(demo_image* im, const swarp_mat4* m, const demo_view* v, double d0,
                       double d1, const uint8_t rgb[3], int view_vector);

/** [RHS] §4.3: the minimum linear depth the viewer sees. */
typedef struct demo_mindepth_result {
    double gpu_min;          /**< by the GPU 2x2 min chain (Listing A.2), read back */
    double cpu_pyramid_min;  /**< swarp_mindepth_pyramid on the read-back buffer */
    double cpu_direct_min;   /**< swarp_mindepth_direct on the same buffer */
    double adjusted_near;    /**< swarp_mindepth_near(n, f, gpu_min) */
    int levels;              /**< chain passes down to 1x1 */
    double depth_pass_ms, chain_ms, readback_ms, cpu_pyramid_ms, cpu_direct_ms;
    int gl_errors;
} demo_mindepth_result;

/** Measures the minimum depth of view v three ways and the adjusted near
 *  plane.  0 on success. */
int demo_mindepth(demo_renderer* r, const demo_view* v, demo_mindepth_result* out);

/** The third-person visualisation view ([RHS] §5.2-5.3) of configuration
 *  sh: rendered with split colours from an outside camera, overlays drawn,
 *  the bodies B (per split for cascades) from the library for `scene`.
 *  *out_body_faces (may be NULL): faces of the bodies drawn.  Returns the
 *  number of GL errors (-1 on failure). */
int demo_third_person(demo_renderer* r, const demo_view* v, const demo_shadow* sh,
                      const swarp_aabb* scene, const demo_main_params* base, demo_image* out,
                      int* out_body_faces);

/** sheets.c: [KOZ] §14.3.2 projective blur against PCF 3x3 on view v
 *  (out_dir/blur_sheet.png).  0 on success. */
int demo_sheet_blur(demo_renderer* r, const demo_view* v, const demo_scene* scene, int map,
                    const char* out_dir);
/** sheets.c: single-map PSM against PSM with cube-map faces ([KOZ] §14.2.2,
 *  Figs. 14-9/14-10) with the camera's and the measured near plane, for v's
 *  sun (cube_sheet.png) and for `behind` (cube_sheet_behind.png). */
int demo_sheet_cube(demo_renderer* r, const demo_view* v, const demo_scene* scene, int map,
                    const swarp_light* behind, const char* out_dir);

#endif
