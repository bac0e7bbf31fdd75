/* gallery.c -- the demo's default run: every technique on one view, the
 * techniques sheet, the summary table, then the comparison sheets. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "modes.h"
#include "technique.h"

static int make_sheet(const demo_options* o, demo_tech_result* all, int n_all) {
    /* rows: techniques seen from the same camera; columns: shaded, sampling
     * rate, texel grid, splits */
    demo_tech_result* res[DEMO_TECH_COUNT + 1];
    int n = 0;
    for (int i = 0; i < n_all; ++i)
        if (!all[i].own_view) res[n++] = &all[i];
    if (n == 0) return 0;
    int cw = 320, ch = (int)lround(320.0 * res[0]->shaded.h / res[0]->shaded.w);
    int hdr = 28;
    demo_image sheet;
    if (demo_image_alloc(&sheet, 4 * cw, hdr + n * ch)) return -1;
    const uint8_t white[3] = {255, 255, 255}, black[3] = {0, 0, 0};
    demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, white);
    const char* cols[4] = {"shaded", "sampling rate (Listing A.3)", "texel grid (Listing A.4)",
                           "split colours (5.1)"};
    for (int c = 0; c < 4; ++c) demo_image_text(&sheet, c * cw + 8, 8, 2, cols[c], black);
    for (int i = 0; i < n; ++i) {
        demo_image* src[4] = {&res[i]->shaded, &res[i]->sampling, &res[i]->grid, &res[i]->splits};
        for (int c = 0; c < 4; ++c) {
            demo_image small;
            if (demo_image_resize(src[c], cw, ch, &small)) return -1;
            demo_image_blit(&sheet, c * cw, hdr + i * ch, &small);
            demo_image_free(&small);
        }
        demo_image_label(&sheet, 6, hdr + i * ch + 6, 2, res[i]->label);
    }
    int rc = demo_write_png(o, "sheet", "techniques", &sheet);
    demo_image_free(&sheet);
    return rc;
}

/* What the view calls for: its camera, light and scene box; the
 * camera moves only along --frames or a camera path; soft shadows when a
 * filter is chosen.  No planes of interest: a swarp_plane is unbounded, and
 * the room corner's floor (y = 0.3) is then the whole ground, which the
 * planner rightly gives a lixel map -- but the demo's lixel maps cover only
 * the room's rectangles and its shader cannot pick between lixel maps and a
 * cascade, so it could not render that plan (docs/demo.md).  Budget: 2
 * pixels per texel (DEMO_PLAN_MAX_ERROR, plan.c), --map, at most
 * DEMO_MAX_SPLITS passes. */
static int plan_view(const demo_options* o, const demo_view* v, const swarp_aabb* box,
                     demo_plan* out) {
    int moves = o->frames > 0 || o->path_count > 1;
    return demo_plan_make(&v->cam, &v->light, box, v->w, v->h, o->map, DEMO_MAX_SPLITS, moves,
                          o->filter, NULL, 0, out);
}

/* The gallery while it runs: the view, the scene and its renderer, the
 * plan, the results so far and the exit status. */
typedef struct gallery {
    const demo_options* o;
    int single;                /**< only o->technique */
    demo_gallery_report* rep;  /**< may be NULL */
    demo_view v;
    demo_scene scene;
    demo_ctx* ctx;
    demo_renderer r;
    demo_plan plan;
    int have_plan;
    double planned_near;       /**< near plane of the planned view (min-depth), 0: the camera's */
    demo_tech_result res[DEMO_TECH_COUNT + 1];
    int n;
    int rc;
    double t_start;
} gallery;

/* The view, the scene, the output directory, the context and the renderer;
 * prints the scene line.  0, or 2 with everything released. */
static int gallery_open(gallery* g) {
    const demo_options* o = g->o;
    if (demo_options_view(o, &g->v)) return 2;
    demo_view_update(&g->v);
    if (demo_load_scene(o, &g->scene)) return 2;
    if (demo_mkdir_p(o->out)) {
        fprintf(stderr, "demo: cannot create %s\n", o->out);
        demo_scene_free(&g->scene);
        return 2;
    }
    g->ctx = demo_open_context();
    if (!g->ctx) {
        demo_scene_free(&g->scene);
        return 2;
    }
    g->t_start = demo_now_ms();
    if (demo_render_init(&g->r, &g->scene, o->w, o->h, o->map, DEMO_MAX_SPLITS)) {
        demo_ctx_destroy(g->ctx);
        demo_scene_free(&g->scene);
        return 2;
    }
    const demo_scene* s = &g->scene;
    printf("scene: %zu triangles, box (%.0f %.0f %.0f)-(%.0f %.0f %.0f); %dx%d, map %d^2\n",
           s->count / 3, s->box.min.x, s->box.min.y, s->box.min.z, s->box.max.x, s->box.max.y,
           s->box.max.z, o->w, o->h, o->map);
    return 0;
}

static void gallery_close(gallery* g) {
    for (int i = 0; i < g->n; ++i) demo_tech_result_free(&g->res[i]);
    printf("total %.1f s\n", (demo_now_ms() - g->t_start) / 1e3);
    demo_render_free(&g->r);
    demo_ctx_destroy(g->ctx);
    demo_scene_free(&g->scene);
}

/* The plan of the view, printed (the gallery's first entry renders it). */
static void gallery_plan(gallery* g) {
    if (g->single && g->o->technique != DEMO_TECH_PLANNED) return;
    /* the near plane from the GPU min-depth reduction ([RHS] §4.3): no
     * split then starts in front of the nearest visible surface */
    demo_view pv = g->v;
    demo_mindepth_result md;
    if (demo_mindepth(&g->r, &g->v, &md) == 0 && md.adjusted_near > pv.cam.z_near &&
        md.adjusted_near < pv.cam.z_far) {
        printf("near plane from the min-depth reduction ([RHS] 4.3): %.4g (camera %.4g, nearest depth %.4g)\n",
               md.adjusted_near, pv.cam.z_near, md.gpu_min);
        pv.cam.z_near = md.adjusted_near;
        demo_view_update(&pv);
        g->planned_near = md.adjusted_near;
    }
    if (plan_view(g->o, &pv, &g->scene.box, &g->plan) != 0) {
        g->rc = 1;
        return;
    }
    g->have_plan = 1;
    demo_plan_print(&g->plan, stdout);
    if (g->rep) {
        g->rep->have_plan = 1;
        g->rep->plan = g->plan;
    }
}

/* The options entry t renders with: the planned entry is the plan's
 * technique with its scheme and filter (plan.c maps them), under the label
 * "planned"; the name printed for it goes to *name. */
static demo_technique entry_options(const gallery* g, int t, demo_options* q, const char** name) {
    *q = *g->o;
    demo_technique tt = (demo_technique)t;
    *name = demo_technique_name(tt);
    if (t != DEMO_TECH_PLANNED) return tt;
    *name = "planned";
    q->scheme = g->plan.scheme;
    q->scheme_lambda = g->plan.scheme_lambda;
    q->pseudo_near = g->plan.pseudo_near;
    q->pseudo_far = g->plan.pseudo_far;
    q->filter = g->plan.filter;
    q->label_override = "planned";
    return g->plan.technique;
}

/* The lines that say what entry t (rendered as technique tt with options
 * q) produced; with `single` also its timing and measurement. */
static void entry_report(gallery* g, int t, demo_technique tt, const demo_options* q,
                         const demo_tech_result* res) {
    const demo_plan* plan = &g->plan;
    printf("%-14s done: %s/%s_*.png (matrices from %s%s%s%s)\n", res->label, g->o->out,
           res->label, res->source, res->own_view ? "; room camera" : "",
           res->sh.status != SWARP_OK ? "; " : "",
           res->sh.status != SWARP_OK ? swarp_status_name(res->sh.status) : "");
    if (t == DEMO_TECH_PLANNED) {
        printf("planned        rendered %d shadow passes (%s, filter %s) over [%.3g, %.3g]; "
               "the plan asks for %u over [%.3g, %.3g]\n",
               res->passes - 1, demo_technique_name(tt), demo_filter_name(q->filter),
               res->sh.z_near, res->sh.z_far, plan->plan.shadow_passes, plan->plan.z_near,
               plan->plan.z_far);
        if (g->rep) g->rep->planned_passes = res->passes - 1, g->rep->planned = res->sh;
    }
    if (g->single) {
        printf("  timing: setup %.2f us (median of 101 calls);", res->setup_us);
        for (int k = 0; k < res->passes - 1; ++k)
            printf(" shadow pass %d %.2f ms;", k, res->shadow_ms[k]);
        printf(" main pass %.2f ms; %d passes, %.0f texels\n", res->main_ms, res->passes,
               res->texels);
        demo_print_measured(res);
        demo_print_measure(res);
    }
}

/* Entry t of the gallery (DEMO_TECH_PLANNED or a technique): rendered,
 * reported, kept in g->res.  0, or 2 when the room camera is missing. */
static int gallery_entry(gallery* g, int t) {
    const demo_options* o = g->o;
    demo_options q;
    const char* name;
    demo_technique tt = entry_options(g, t, &q, &name);
    if (!demo_technique_available(tt)) {
        if (g->single) {
            fprintf(stderr, "demo: %s is not available in this build yet\n", name);
            g->rc = 2;
        } else {
            printf("%-14s not available in this build yet (library stage not merged)\n", name);
        }
        return 0;
    }
    int splits = t == DEMO_TECH_PLANNED                   ? g->plan.splits
                 : demo_technique_is_split((demo_technique)t) ? o->splits
                                                              : 1;
    /* the lixel maps are for the room corner: without an explicit
     * --camera the gallery looks at it with the room preset (and keeps
     * it off the same-view sheet) */
    demo_view lv = g->v;
    int own_view = t == DEMO_TECH_LIXEL && !o->camera_given && !o->obj;
    if (own_view) {
        if (demo_camera_preset("room", o->w, o->h, &lv.cam)) return 2;
        demo_view_update(&lv);
    }
    if (t == DEMO_TECH_PLANNED && g->planned_near > 0.0) {
        lv.cam.z_near = g->planned_near; /* the view the plan was made for */
        demo_view_update(&lv);
    }
    demo_tech_result* res = &g->res[g->n];
    int e = demo_run_technique(&q, &g->r, &lv, &g->scene.box, tt, splits, 1, res);
    if (e == -2 && !g->single) {
        /* the library refused the technique itself (not implemented in
         * the linked library): say so and go on */
        printf("%-14s skipped: the library's setup refused it (see above)\n", name);
        demo_tech_result_free(res);
        return 0;
    }
    if (e) {
        fprintf(stderr, "demo: %s failed\n", name);
        demo_tech_result_free(res);
        g->rc = 1;
        return 0;
    }
    res->own_view = own_view;
    entry_report(g, t, tt, &q, res);
    if (res->gl_errors) g->rc = 1;
    if (g->rep) {
        if (res->min_nonblank < g->rep->min_nonblank) g->rep->min_nonblank = res->min_nonblank;
        g->rep->produced[t] = 1;
    }
    ++g->n;
    return 0;
}

/* The summary table: per entry the setup time, passes, texels, timings and
 * the measured error of docs/accuracy.md, maximum against maximum: the
 * render's (texel coordinates read back) over its receiver pixels, the
 * library's swarp_measure_points over the same pixels, and the library's
 * maximum over H with bisector receivers (the result's `measured`). */
static void gallery_summary(const gallery* g) {
    const demo_options* o = g->o;
    printf("\nsummary (%dx%d, map %d^2, camera %s, filter %s; sigma: screen pixels per texel "
           "step, docs/accuracy.md)\n", o->w, o->h, o->map, o->camera, demo_filter_name(o->filter));
    printf("%-14s %9s %6s %10s %9s %9s %9s %9s %9s %9s %9s %6s\n", "technique", "setup_us",
           "passes", "texels", "shadow_ms", "main_ms", "meas_sig", "pred_sig", "meas/pred",
           "H_sig", "meas/H", "gl_err");
    for (int i = 0; i < g->n; ++i) {
        const demo_tech_result* r = &g->res[i];
        const demo_measured* m = &r->measured;
        char hs[32] = "-", hr[32] = "-";
        if (r->sh.have_measured) {
            snprintf(hs, sizeof hs, "%.4g", r->sh.measured.max_sigma);
            snprintf(hr, sizeof hr, "%.3f", m->render_sigma / r->sh.measured.max_sigma);
        }
        printf("%-14s %9.2f %6d %10.0f %9.2f %9.2f %9.4g %9.4g %9.4f %9s %9s %6d\n", r->label,
               r->setup_us, r->passes, r->texels, r->shadow_ms_total, r->main_ms, m->render_sigma,
               m->points_sigma, m->render_sigma / m->points_sigma, hs, hr, r->gl_errors);
    }
    printf("(meas_sig: the largest sigma measured from the render (texel coordinates of\n"
           " neighbouring pixels) over the receiver pixels that face the light; pred_sig: the\n"
           " largest of swarp_measure_points over the same pixels; H_sig: the library's maximum\n"
           " over H with bisector receivers, '-' where the maps have none (lixel, cube faces);\n"
           " timings: glFinish-bracketed, llvmpipe)\n");
}

/* The planner fed with what the gallery measured: the cost model fitted to
 * the shadow passes of every entry but the planned one (so the prediction
 * is not fitted to the time it predicts; alone, --technique planned, it
 * fits its own passes), the view re-planned with it, and its predicted
 * shadow time against the planned entry's measured one. */
static void gallery_calibrate(const gallery* g) {
    if (!g->have_plan) return;
    double tx[(DEMO_TECH_COUNT + 1) * DEMO_MAX_SPLITS], ns[(DEMO_TECH_COUNT + 1) * DEMO_MAX_SPLITS];
    size_t n = 0;
    const demo_tech_result* planned = NULL;
    for (int pass = 0; pass < 2 && n == 0; ++pass)
        for (int i = 0; i < g->n; ++i) {
            const demo_tech_result* r = &g->res[i];
            int is_planned = strcmp(r->label, "planned") == 0;
            if (is_planned) planned = r;
            if ((is_planned && pass == 0) || r->passes < 2) continue;
            for (int k = 0; k < r->passes - 1 && n < sizeof tx / sizeof tx[0]; ++k) {
                tx[n] = r->texels / (double)(r->passes - 1);
                ns[n++] = r->shadow_ms[k] * 1e6;
            }
        }
    if (!planned || n < 2) return;
    demo_plan cal;
    printf("\nplanner fed with the measured passes%s:\n  ", g->n > 1 ? " of the other entries" : " (its own)");
    if (demo_plan_calibrate(&g->plan, tx, ns, n, &cal, stdout) != 0) return;
    const struct swarp_plan* p0 = &g->plan.plan;
    const struct swarp_plan* p1 = &cal.plan;
    printf("  re-planned: %s, %u split(s) (was %s, %u); measured error %.3g (budget %.3g), %s\n",
           swarp_plan_warp_name(p1->warp), p1->split_count, swarp_plan_warp_name(p0->warp), p0->split_count,
           fmax(p1->measured.max_m_s, p1->measured.max_m_t), g->plan.budget.max_error > 0.0 ? g->plan.budget.max_error : 1.0,
           p1->meets_budget ? "meets the budget" : "does NOT meet the budget");
    printf("  shadow time of the rendered plan (%u passes): predicted %.2f ms uncalibrated, %.2f ms "
           "calibrated; measured %.2f ms (calibrated/measured %.2f)\n",
           p0->shadow_passes, p0->cost_ns * 1e-6,
           p1->split_count == p0->split_count ? p1->cost_ns * 1e-6 : NAN, planned->shadow_ms_total,
           p1->split_count == p0->split_count ? p1->cost_ns * 1e-6 / planned->shadow_ms_total : NAN);
    for (uint32_t i = 0; i < p0->split_count && p0->built; ++i)
        printf("  split %u [%.4g, %.4g]: n' %.4g, measured sigma %.3g over %u samples%s\n", i,
               p0->built_splits[i], p0->built_splits[i + 1], p0->built_n_eye[i], p0->split_measured[i].max_sigma,
               p0->split_measured[i].samples,
               p0->split_measured[i].samples == 0 ? " (no receiver of the scene box in this split)" : "");
}

int demo_run_gallery(const demo_options* o, int single, demo_gallery_report* rep) {
    gallery g;
    memset(&g, 0, sizeof g);
    g.o = o;
    g.single = single;
    g.rep = rep;
    int rc = gallery_open(&g);
    if (rc) return rc;
    gallery_plan(&g);
    if (rep) rep->planned_passes = -1;
    /* the planned chain first, then every technique */
    for (int ti = 0; ti <= DEMO_TECH_COUNT; ++ti) {
        int t = ti == 0 ? DEMO_TECH_PLANNED : ti - 1;
        if (single && t != o->technique) continue;
        if (t == DEMO_TECH_PLANNED && !g.have_plan) continue;
        if (gallery_entry(&g, t)) {
            gallery_close(&g);
            return 2;
        }
    }
    if (g.n > 0 && !single && make_sheet(o, g.res, g.n)) g.rc = 1;
    if (g.n > 0) gallery_summary(&g);
    if (g.n > 0) gallery_calibrate(&g);
    gallery_close(&g);
    return g.rc;
}

/* --plan: what the view calls for, printed, nothing rendered (no GL). */
int demo_print_plan_only(const demo_options* o) {
    demo_view v;
    if (demo_options_view(o, &v)) return 2;
    demo_scene scene;
    if (demo_load_scene(o, &scene)) return 2;
    demo_plan plan;
    int rc = plan_view(o, &v, &scene.box, &plan) ? 1 : 0;
    if (rc == 0) demo_plan_print(&plan, stdout);
    demo_scene_free(&scene);
    return rc;
}

/* The two comparison sheets (sheets.c): projective blur vs PCF,
 * and single-map PSM vs the cube map with the sun in front of the camera
 * (--light-angle) and behind it (the same elevation, azimuth 10). */
int demo_run_sheets(const demo_options* o) {
    if (demo_mkdir_p(o->out)) {
        fprintf(stderr, "demo: cannot create %s\n", o->out);
        return 2;
    }
    demo_ctx* ctx = demo_open_context();
    if (!ctx) return 2;
    demo_view v;
    demo_sized_view(o, &v);
    demo_scene scene;
    demo_renderer r;
    int rc = 2;
    if (demo_options_camera(o, &v.cam) == 0 && demo_load_scene(o, &scene) == 0) {
        demo_options_light(o, &v.light);
        demo_view_update(&v);
        if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS) == 0) {
            double t0 = demo_now_ms();
            printf("\ncomparison sheets (%s camera):\n", o->camera);
            rc = demo_sheet_blur(&r, &v, &scene, o->map, o->out);
            demo_options b = *o;
            b.have_light_dir = 0;
            b.light_azim = 10;
            swarp_light behind;
            demo_options_light(&b, &behind);
            rc |= demo_sheet_cube(&r, &v, &scene, o->map, &behind, o->out);
            printf("sheets %.1f s\n", (demo_now_ms() - t0) / 1e3);
            demo_render_free(&r);
        }
        demo_scene_free(&scene);
    }
    demo_ctx_destroy(ctx);
    return rc;
}
