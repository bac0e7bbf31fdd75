/* modes.h -- what the demo program does: the gallery (with its summary
 * table and the comparison sheets), --plan, --frames and --mindepth.
 * demo-check drives the same modes and checks what they report. */
#ifndef DEMO_MODES_H
#define DEMO_MODES_H

#include "options.h"
#include "plan.h"

typedef struct demo_gallery_report {
    double min_nonblank;          /**< smallest non-blank fraction of any picture */
    int produced[DEMO_TECH_COUNT + 1]; /**< 1: all pictures of technique t written */
    int have_plan;                /**< plan is valid */
    demo_plan plan;               /**< the plan of the view */
    int planned_passes;           /**< shadow passes the planned entry rendered (-1: none) */
    demo_shadow planned;          /**< the maps the planned entry rendered (planned_passes >= 0) */
} demo_gallery_report;

/* gallery.c */
/** The gallery: the planned chain, then every technique (or only
 *  o->technique when `single`), pictures into o->out, the techniques sheet
 *  and the summary table.  rep (may be NULL) collects what was produced.
 *  0 ok, 1 a technique failed, 2 no scene / context. */
int demo_run_gallery(const demo_options* o, int single, demo_gallery_report* rep);
/** The comparison sheets (sheets.c) for the command line's view. */
int demo_run_sheets(const demo_options* o);
/** --plan: the plan of the view printed, nothing rendered (no GL). */
int demo_print_plan_only(const demo_options* o);

/* frames.c */
/** --frames N: flies N frames (or walks the camera path), one line per
 *  frame; *out_max_drift (may be NULL) gets the largest sub-texel drift of
 *  a fixed ground point between frames that shade it from the same map. */
int demo_run_frames(const demo_options* o, double* out_max_drift);

/* mindepth_mode.c */
/** Measures the min depth of view v (GPU chain, both CPU reductions, the
 *  adjusted near plane) and prints it under the heading of camera `cam`.
 *  0 when the measurement ran. */
int demo_mindepth_report(demo_renderer* r, const char* cam, const demo_view* v,
                         demo_mindepth_result* md);
/** 1 when the three minima of md agree bit for bit and the adjusted near
 *  lies in [camera near, min] without GL errors; else prints why not, 0. */
int demo_mindepth_consistent(const demo_view* v, const demo_mindepth_result* md);
/** --mindepth: the report for the command line's camera (default street)
 *  and the LiSPSM sampling pictures with the camera, adjusted and pseudo
 *  near plane. */
int demo_run_mindepth(const demo_options* o);

#endif
