/* check_gallery.c -- demo-check: the program's own outputs: every picture
 * of the gallery exists and is not blank (images); --technique planned
 * renders the plan's passes and prints its reasons (planned). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checks.h"

int demo_check_images(const demo_options* o) {
    /* the gallery at small size: every picture exists and is not blank */
    demo_options q = *o;
    demo_gallery_report rep;
    memset(&rep, 0, sizeof rep);
    rep.min_nonblank = 1.0;
    int rc = demo_run_gallery(&q, 0, &rep);
    double nonblank = rep.min_nonblank;
    if (rc) return rc == 2 ? 1 : rc;
    int fails = 0, checked = 0;
    const char* what[7] = {"shaded", "sampling", "splits", "grid", "light", "error", "third"};
    int produced = 0;
    for (int t = 0; t < DEMO_TECH_COUNT; ++t) {
        if (!rep.produced[t]) {
            if (demo_technique_available((demo_technique)t))
                printf("note: %s was refused by the library's setup\n",
                       demo_technique_name((demo_technique)t));
            continue;
        }
        ++produced;
        char label[48];
        if (demo_technique_is_split((demo_technique)t))
            snprintf(label, sizeof label, "%s%d", demo_technique_name((demo_technique)t), q.splits);
        else
            snprintf(label, sizeof label, "%s", demo_technique_name((demo_technique)t));
        for (int k = 0; k < 7; ++k) {
            char path[1200];
            snprintf(path, sizeof path, "%s/%s_%s.png", q.out, label, what[k]);
            FILE* f = fopen(path, "rb");
            long size = 0;
            if (f) {
                fseek(f, 0, SEEK_END);
                size = ftell(f);
                fclose(f);
            }
            if (!f || size < 1000) {
                printf("missing or tiny: %s\n", path);
                ++fails;
            }
            ++checked;
        }
    }
    /* a picture counts as blank when fewer than 1% of its pixels differ
     * from its first pixel */
    printf("images: %d files checked, %d bad; least non-blank picture: %.1f%% of pixels\n",
           checked, fails, 100 * nonblank);
    if (nonblank < 0.01) ++fails;
    if (produced < 2) ++fails;
    return fails ? 1 : 0;
}

/* The planned entry's maps are the plan's chain, bit for bit: the split
 * distances and each split's n' equal swarp_plan's built_splits and
 * built_n_eye, and the measured maximum the demo reports (H_sig) is the
 * plan's own measured maximum (one chain, one n', one figure). */
static int planned_is_the_plan(const demo_shadow* sh, const struct swarp_plan* pl) {
    if (!pl->built || sh->count != (int)pl->split_count || !sh->have_measured) return 0;
    for (int i = 0; i <= sh->count; ++i)
        if (memcmp(&sh->split[i], &pl->built_splits[i], sizeof(double)) != 0) return 0;
    for (int i = 0; i < sh->count; ++i)
        if (memcmp(&sh->n_prime[i], &pl->built_n_eye[i], sizeof(double)) != 0) return 0;
    return memcmp(&sh->measured.max_sigma, &pl->measured.max_sigma, sizeof(double)) == 0;
}

/* --technique planned renders exactly the passes the plan asks
 * for, with the plan's splits, n' and measured error, and the printed
 * plan carries one "why:" line per reason flag. */
int demo_check_planned(const demo_options* o) {
    demo_options q = *o;
    q.technique = DEMO_TECH_PLANNED;
    demo_gallery_report rep;
    memset(&rep, 0, sizeof rep);
    rep.min_nonblank = 1.0;
    int rc = demo_run_gallery(&q, 1, &rep);
    if (rc) return rc == 2 ? 1 : rc;
    if (!rep.have_plan) {
        printf("planned: no plan FAIL\n");
        return 1;
    }
    const struct swarp_plan* pl = &rep.plan.plan;
    char* text = NULL;
    size_t size = 0;
    FILE* mem = open_memstream(&text, &size);
    if (!mem) return 1;
    demo_plan_print(&rep.plan, mem);
    fclose(mem);
    int whys = 0, flags = 0;
    for (const char* s = text; (s = strstr(s, "\n  why: ")) != NULL; ++s) ++whys;
    for (uint32_t b = pl->reasons; b; b &= b - 1) ++flags;
    /* every plan says why it took (or left out) the splits, the
     * stabilisation and the filter at least */
    const int same = planned_is_the_plan(&rep.planned, pl);
    int ok = rep.planned_passes == (int)pl->shadow_passes && rep.plan.exact && whys == flags &&
             flags >= 3 && strstr(text, "cost: ") != NULL && rep.min_nonblank >= 0.01 && same;
    printf("planned: splits, n' and measured sigma %s the plan's built chain (sigma %.17g vs %.17g)\n",
           same ? "equal" : "DIFFER from", rep.planned.measured.max_sigma, pl->measured.max_sigma);
    printf("planned: %d shadow passes rendered, plan %u; %d reason lines printed, %d reason flags; "
           "mapped exactly: %s %s\n",
           rep.planned_passes, pl->shadow_passes, whys, flags, rep.plan.exact ? "yes" : "no",
           ok ? "ok" : "FAIL");
    free(text);
    return ok ? 0 : 1;
}
