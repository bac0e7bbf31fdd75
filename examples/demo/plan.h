/* plan.h -- the demo's use of the planner (swarp_plan): the needs
 * of the view it renders, the plan with its reasons, and the plan mapped
 * onto the demo's own technique / scheme / filter options. */
#ifndef DEMO_PLAN_H
#define DEMO_PLAN_H

#include <stdio.h>

#include "render.h"
#include "shadow.h"

typedef struct demo_plan {
    struct swarp_plan plan;  /**< the library's plan */
    swarp_status status;     /**< swarp_plan's status */
    /* the plan in the demo's terms */
    demo_technique technique;
    int splits;
    demo_scheme scheme;
    double scheme_lambda;
    double pseudo_near, pseudo_far;
    demo_filter filter;
    int exact;               /**< 1: the demo renders exactly the planned chain */
    char note[256];          /**< where the demo's machinery differs from the plan */
    swarp_scene_needs needs; /**< what was asked (for re-planning with measured costs) */
    swarp_budget budget;
} demo_plan;

/** Plans the shadows of one view: camera, light, scene box, the screen and
 *  map size, whether the camera moves, the filter the user asked for (soft
 *  shadows = a filter other than none) and the planes of interest (NULL,
 *  0: none).  Budget: the planner's default error (1 pixel per texel), the
 *  map resolution, max_passes passes.  0 on success, -1 with a message. */
int demo_plan_make(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* box,
                   int screen_w, int screen_h, int map_res, int max_passes, int camera_moves,
                   demo_filter wanted, const swarp_plane* planes, int plane_count,
                   demo_plan* out);

/** Re-plans p's request with the cost model calibrated from measured
 *  shadow passes (texels[i], pass_ns[i], count of them): the
 *  overhead + per-texel fit of swarp_plan_cost_fit, or, when every pass had
 *  the same map size (the fit cannot tell the terms apart), their mean as
 *  the per-pass cost.  Prints the fit.  0, or -1 with a message. */
int demo_plan_calibrate(const demo_plan* p, const double* texels, const double* pass_ns, size_t count,
                        demo_plan* out, FILE* f);

/** Prints the plan, its reasons (swarp_plan_explain) and how the demo maps
 *  it onto its techniques. */
void demo_plan_print(const demo_plan* p, FILE* f);

#endif
