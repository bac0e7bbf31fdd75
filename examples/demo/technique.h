/* technique.h -- one technique rendered for one view: the pictures of
 * [RHS] chapter 5, the measurement against Lloyd's model and the timing. */
#ifndef DEMO_TECHNIQUE_H
#define DEMO_TECHNIQUE_H

#include "options.h"

/* depth bins of the measured-vs-predicted table */
#define DEMO_MEASURE_ROWS 16

typedef struct demo_tech_result {
    demo_technique tech;
    char label[48];
    int ok;
    double setup_us;
    int passes;
    double shadow_ms[DEMO_MAX_SPLITS];
    double shadow_ms_total, main_ms;
    double texels;
    demo_measured measured; /**< the measured error over the render's receivers */
    demo_measure_row rows[DEMO_MEASURE_ROWS];
    int nrows;
    double max_mx, max_mz;
    int gl_errors;
    double min_nonblank; /**< smallest non-blank fraction of the pictures */
    demo_image shaded, sampling, grid, splits, light;
    const char* source;
    int own_view; /**< rendered from another camera than the sheet's */
    demo_shadow sh; /**< the configuration that was rendered */
} demo_tech_result;

/** Sets up technique t (K = splits) for view v from the command line's
 *  request, renders the shadow and main passes and measures m_x, m_z; with
 *  `write` also every picture, written as o->out/LABEL_WHAT.png.  0 on
 *  success, -2 when the library's setup refused the technique, -1 on any
 *  other failure. */
int demo_run_technique(const demo_options* o, demo_renderer* r, const demo_view* v,
                       const swarp_aabb* box, demo_technique t, int splits, int write,
                       demo_tech_result* res);
/** Frees the pictures of res. */
void demo_tech_result_free(demo_tech_result* r);
/** The measured error of r's render against the library's on stdout. */
void demo_print_measured(const demo_tech_result* r);
/** Lloyd's model along the view vector against the render, per depth bin,
 *  on stdout. */
void demo_print_measure(const demo_tech_result* r);
/** Reads the w x h colour buffer into a new image. */
int demo_read_picture(demo_renderer* r, int w, int h, demo_image* im);
/** Writes im as o->out/LABEL_WHAT.png. */
int demo_write_png(const demo_options* o, const char* label, const char* what,
                   const demo_image* im);

#endif
