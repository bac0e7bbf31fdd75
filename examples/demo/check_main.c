/* check_main.c -- demo-check: the demo's headless checks (meson suite demo)
 * and the geometry-cloning benchmark, on the demo's own code.
 *
 *   demo-check --test NAME [demo's options]   exit 0 pass, 1 fail, 77 skip
 */
#include <stdio.h>
#include <string.h>

#include "checks.h"

static void usage(void) {
    printf(
        "usage: demo-check --test NAME [options]\n"
        "  --test images|iou|measure|measured|select|clone|mindepth|flicker|planned|blur|options\n"
        "                          headless checks (exit 0 pass, 1 fail, 77 skip)\n"
        "  --test bench-clone      time K + 1 passes against geometry cloning (1 + 1), K = 4, 8, 16\n"
        "                          (median of --frames, default 15; --bench-out FILE: rows as TSV)\n"
        "the demo's options set the view:\n");
    demo_options_usage();
}

typedef int (*check_fn)(const demo_options*);

/* The checks that need an open context while they run. */
static check_fn check_in_context(const char* name) {
    static const struct {
        const char* name;
        check_fn fn;
    } checks[] = {{"iou", demo_check_iou},         {"measure", demo_check_measure},
                  {"measured", demo_check_measured},
                  {"select", demo_check_select},   {"clone", demo_check_clone},
                  {"mindepth", demo_check_mindepth}, {"flicker", demo_check_flicker},
                  {"blur", demo_check_blur},
                  {"options", demo_check_options},       {"bench-clone", demo_bench_clone}};
    for (size_t i = 0; i < sizeof checks / sizeof checks[0]; ++i)
        if (!strcmp(name, checks[i].name)) return checks[i].fn;
    return NULL;
}

int main(int argc, char** argv) {
    demo_options o;
    if (demo_options_parse(argc, argv, usage, &o)) return 2;
    if (demo_options_load_path(&o) < 0) return 2;
    if (!o.test) {
        usage();
        return 2;
    }
    /* skip cleanly when OSMesa cannot give us a context */
    int maj, min;
    demo_ctx* probe = demo_ctx_create(&maj, &min);
    if (!probe) {
        printf("SKIP: OSMesa cannot create a core-profile context\n");
        return DEMO_EXIT_SKIP;
    }
    demo_ctx_destroy(probe);
    /* these two run the gallery, which opens its own context */
    if (!strcmp(o.test, "images")) return demo_check_images(&o);
    if (!strcmp(o.test, "planned")) return demo_check_planned(&o);
    demo_ctx* ctx = demo_open_context();
    if (!ctx) return DEMO_EXIT_SKIP;
    check_fn fn = check_in_context(o.test);
    int rc = 2;
    if (fn) rc = fn(&o);
    else fprintf(stderr, "demo: unknown test %s\n", o.test);
    demo_ctx_destroy(ctx);
    return rc;
}
