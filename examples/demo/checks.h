/* checks.h -- demo-check: the headless checks meson runs (suite demo), each
 * a property of the rendered pictures against the library's CPU answer.
 * Each returns 0 pass, 1 fail, DEMO_EXIT_SKIP when it could not run. */
#ifndef DEMO_CHECKS_H
#define DEMO_CHECKS_H

#include "modes.h"
#include "technique.h"

/* check_maps.c: the maps against geometry and the library */
int demo_check_iou(const demo_options* o);
int demo_check_measure(const demo_options* o);
int demo_check_select(const demo_options* o);
/* check_measured.c: the render's measured error against the library's */
int demo_check_measured(const demo_options* o);
/* check_passes.c: renderer paths that must agree or must differ */
int demo_check_clone(const demo_options* o);
int demo_check_mindepth(const demo_options* o);
int demo_check_blur(const demo_options* o);
int demo_check_flicker(const demo_options* o);
/* check_gallery.c: the program's own outputs */
int demo_check_images(const demo_options* o);
int demo_check_planned(const demo_options* o);
/* check_options.c: --light-gamma, --nprime and --basis against the library */
int demo_check_options(const demo_options* o);
/* bench_clone.c: timings, not a pass/fail check (meson benchmark) */
int demo_bench_clone(const demo_options* o);

#endif
