/* main.c -- the libshadowwarp OSMesa demo: renders the built-in scene with
 * each technique and writes the pictures of [RHS] chapter 5 as PNGs.
 *
 *   demo                         default gallery into ./out/ + summary table
 *   demo --technique lispsm ...  one technique, all its pictures
 *   demo --plan | --frames N | --mindepth | --sheets   the other modes
 *
 * The headless checks meson runs on the same code are demo-check
 * (check_main.c).
 */
#include <stdio.h>
#include <string.h>

#include "modes.h"

static void usage(void) {
    printf(
        "usage: demo [options]\n"
        "  (no options)            default gallery into ./out/ and a summary table, then the\n"
        "                          comparison sheets (blur_sheet, cube_sheet, cube_sheet_behind)\n"
        "  --sheets                only the sheets: projective blur vs PCF [KOZ] 14.3.2, PSM vs\n"
        "                          cube map [KOZ] 14.2.2 (camera and measured near; sun in front\n"
        "                          and behind); --no-sheets: the gallery without them\n");
    demo_options_usage();
    printf("headless checks and the geometry-cloning benchmark: demo-check --help\n");
}

static int run_mindepth_mode(const demo_options* o) {
    demo_ctx* ctx = demo_open_context();
    if (!ctx) return 2;
    int rc = demo_run_mindepth(o);
    demo_ctx_destroy(ctx);
    return rc;
}

int main(int argc, char** argv) {
    demo_options o;
    if (demo_options_parse(argc, argv, usage, &o)) return 2;
    if (o.test || o.bench_out) {
        fprintf(stderr, "demo: the headless checks are demo-check --test NAME (demo-check --help)\n");
        return 2;
    }
    if (demo_options_load_path(&o) < 0) return 2;
    if (o.plan_only) return demo_print_plan_only(&o);
    if (o.frames > 0 && o.technique == DEMO_TECH_PLANNED) {
        fprintf(stderr, "demo: --technique planned renders the gallery view, not --frames\n");
        return 2;
    }
    if (o.frames > 0) return demo_run_frames(&o, NULL);
    if (o.mindepth) return run_mindepth_mode(&o);
    if (o.sheets_only) return demo_run_sheets(&o);
    int rc = demo_run_gallery(&o, o.technique >= 0, NULL);
    /* the default gallery ends with the comparison sheets */
    if (rc == 0 && o.technique < 0 && !o.no_sheets) rc = demo_run_sheets(&o);
    return rc;
}
