/* plan.c -- the demo's default run asks the planner (swarp_plan)
 * what the scene calls for and renders only that: see plan.h. */
#include "plan.h"

#include <string.h>

/* the kernel width (texels) each demo filter stands for: the soft-shadow
 * width the needs declare */
static double filter_width(demo_filter f) {
    switch (f) {
    case DEMO_FILTER_PCF2: return 2;
    case DEMO_FILTER_PCF5:
    case DEMO_FILTER_POISSON: return 5;
    default: return 3; /* pcf3, the 3x3-filtered moments, projblur */
    }
}

/* The demo's error budget: at most 2 screen pixels per texel step (σ of
 * docs/accuracy.md).  With the 3-texel filter kernels the demo renders, a
 * shadow edge is then at most about 6 pixels wide, which reads as a soft
 * edge rather than as blocks; the planner's default of 1 pixel per texel
 * cannot be met over the boulevard's 800 m with 1024^2 maps at any split
 * count (16 log splits from the min-depth near plane still measure 1.76:
 * each split's nearest receivers set its error, and more splits shrink
 * every split's range but not that).  2 is met by 5 LiSPSM splits. */
#define DEMO_PLAN_MAX_ERROR 2.0

/* The needs of the view and the budget, in the planner's terms. */
static void plan_request(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* box,
                         int screen_w, int screen_h, int map_res, int max_passes,
                         int camera_moves, demo_filter wanted, const swarp_plane* planes,
                         int plane_count, swarp_scene_needs* needs, swarp_budget* budget) {
    memset(needs, 0, sizeof *needs);
    needs->camera = *cam;
    needs->light = *light;
    needs->scene_box = *box;
    needs->screen_width = (uint32_t)screen_w;
    needs->screen_height = (uint32_t)screen_h;
    needs->camera_moves = camera_moves ? 1u : 0u;
    needs->soft_shadows = wanted != DEMO_FILTER_NONE;
    needs->soft_width = needs->soft_shadows ? filter_width(wanted) : 0;
    /* the demo's depth pass pancakes casters only for the lixel and cube
     * maps; the planner keeps clamping out of warped maps anyway */
    needs->allow_depth_clamp = 0;
    if (plane_count > SWARP_PLAN_MAX_PLANES) plane_count = SWARP_PLAN_MAX_PLANES;
    for (int i = 0; i < plane_count; ++i) needs->planes[i] = planes[i];
    needs->plane_count = (uint32_t)(plane_count > 0 ? plane_count : 0);
    memset(budget, 0, sizeof *budget);
    budget->max_error = DEMO_PLAN_MAX_ERROR;
    budget->map_resolution = (uint32_t)map_res;
    budget->max_passes = (uint32_t)max_passes;
}

static int plan_and_map(const swarp_scene_needs* needs_in, const swarp_budget* budget_in, demo_filter wanted,
                        demo_plan* out);

int demo_plan_make(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* box,
                   int screen_w, int screen_h, int map_res, int max_passes, int camera_moves,
                   demo_filter wanted, const swarp_plane* planes, int plane_count,
                   demo_plan* out) {
    swarp_scene_needs needs;
    swarp_budget budget;
    plan_request(cam, light, box, screen_w, screen_h, map_res, max_passes, camera_moves, wanted,
                 planes, plane_count, &needs, &budget);
    return plan_and_map(&needs, &budget, wanted, out);
}

int demo_plan_calibrate(const demo_plan* p, const double* texels, const double* pass_ns, size_t count,
                        demo_plan* out, FILE* f) {
    swarp_budget b = p->budget;
    double a = 0.0, t = 0.0, rms = 0.0;
    swarp_status s = swarp_plan_cost_fit(texels, pass_ns, count, &a, &t, &rms);
    if (s == SWARP_OK) {
        b.pass_overhead_ns = a;
        b.texel_cost_ns = t;
        fprintf(f, "cost model fitted to %zu measured shadow passes: %.3f ms + %.4g ns per texel "
                   "(rms %.3f ms)\n", count, a * 1e-6, t, rms * 1e-6);
    } else if (s == SWARP_ERR_DEGENERATE) {
        double sum = 0.0;
        for (size_t i = 0; i < count; ++i) sum += pass_ns[i];
        b.pass_cost_ns = sum / (double)count;
        fprintf(f, "cost model from %zu measured shadow passes, all at %.0f texels: %.3f ms per pass "
                   "(the per-texel term needs passes at two map sizes)\n", count, texels[0],
                b.pass_cost_ns * 1e-6);
    } else {
        fprintf(stderr, "demo: swarp_plan_cost_fit: %s\n", swarp_status_string(s));
        return -1;
    }
    demo_filter wanted = p->needs.soft_shadows ? (p->filter == DEMO_FILTER_NONE ? DEMO_FILTER_PCF3 : p->filter)
                                               : DEMO_FILTER_NONE;
    return plan_and_map(&p->needs, &b, wanted, out);
}

static int plan_and_map(const swarp_scene_needs* needs_in, const swarp_budget* budget_in, demo_filter wanted,
                        demo_plan* out) {
    swarp_scene_needs needs = *needs_in;
    swarp_budget budget = *budget_in;

    demo_plan p;
    memset(&p, 0, sizeof p);
    p.needs = needs;
    p.budget = budget;
    p.status = swarp_plan(&needs, &budget, &p.plan);
    if (swarp_status_is_error(p.status)) {
        fprintf(stderr, "demo: swarp_plan: %s\n", swarp_status_string(p.status));
        return -1;
    }
    const struct swarp_plan* q = &p.plan;
    p.exact = 1;
    size_t nn = 0;
#define NOTE(...) \
    (nn += (size_t)snprintf(p.note + nn, nn < sizeof p.note ? sizeof p.note - nn : 0, __VA_ARGS__))
    /* the chain: warp, split count and scheme, stabilisation */
    p.splits = (int)q->split_count;
    p.scheme = q->scheme == SWARP_PLAN_SCHEME_LOG ? DEMO_SCHEME_LOG : DEMO_SCHEME_PRACTICAL;
    p.scheme_lambda = 0.5; /* [RHS] (3.8), the planner's practical lambda */
    p.pseudo_near = p.pseudo_far = 0.1; /* the planner's pseudo-near/far [RHS] (4.2) */
    if (q->split_count > 1) {
        if (q->stabilize == SWARP_PLAN_STABILIZE_APPROX64) {
            p.technique = DEMO_TECH_PSSM_STABLE;
            if (q->warp != SWARP_PLAN_WARP_UNIFORM) {
                NOTE("stabilised warped splits: the demo stabilises uniform splits only; ");
                p.exact = 0;
            }
        } else if (q->warp == SWARP_PLAN_WARP_UNIFORM) {
            p.technique = DEMO_TECH_PSSM;
        } else {
            p.technique = DEMO_TECH_PSSM_LISPSM;
            if (q->warp != SWARP_PLAN_WARP_LISPSM_NOPT) {
                NOTE("per-split %s: the demo's pssm-lispsm uses n_opt; ",
                     swarp_plan_warp_name(q->warp));
                p.exact = 0;
            }
        }
    } else {
        switch (q->warp) {
        case SWARP_PLAN_WARP_LISPSM_NOPT: p.technique = DEMO_TECH_LISPSM; break;
        case SWARP_PLAN_WARP_LISPSM_NREPAR: p.technique = DEMO_TECH_REPAR; break;
        case SWARP_PLAN_WARP_LISPSM_GMNPR: p.technique = DEMO_TECH_GMNPR; break;
        case SWARP_PLAN_WARP_LISPSM_PSEUDO: p.technique = DEMO_TECH_PSEUDO; break;
        case SWARP_PLAN_WARP_PSM: p.technique = DEMO_TECH_PSM; break;
        default: p.technique = DEMO_TECH_UNIFORM; break;
        }
        if (q->stabilize == SWARP_PLAN_STABILIZE_APPROX64) {
            /* one stabilised map: the demo's stabilised cascade with K = 1 */
            p.technique = DEMO_TECH_PSSM_STABLE;
            if (q->warp != SWARP_PLAN_WARP_UNIFORM) {
                NOTE("stabilised warped map: the demo stabilises uniform maps only; ");
                p.exact = 0;
            }
        }
    }
    if (q->lixel_count > 0) {
        NOTE("%u lixel map(s) planned: the demo renders lixel maps only with its own "
             "room-corner technique, not next to a chain; ", q->lixel_count);
        p.exact = 0;
    }
    /* the filter: none when the plan has none; the user's PCF kernel for PCF */
    switch (q->filter) {
    case SWARP_PLAN_FILTER_PCF:
        p.filter = (wanted == DEMO_FILTER_PCF2 || wanted == DEMO_FILTER_PCF3 ||
                    wanted == DEMO_FILTER_PCF5 || wanted == DEMO_FILTER_POISSON)
                       ? wanted
                       : DEMO_FILTER_PCF3;
        break;
    case SWARP_PLAN_FILTER_VSM: p.filter = DEMO_FILTER_VSM; break;
    case SWARP_PLAN_FILTER_EVSM: p.filter = DEMO_FILTER_EVSM; break;
    case SWARP_PLAN_FILTER_MSM:
    case SWARP_PLAN_FILTER_LVSM:
        p.filter = DEMO_FILTER_EVSM;
        NOTE("filter %s: the demo has no %s, EVSM instead; ", swarp_plan_filter_name(q->filter),
             swarp_plan_filter_name(q->filter));
        p.exact = 0;
        break;
    default: p.filter = DEMO_FILTER_NONE; break;
    }
#undef NOTE
    *out = p;
    return 0;
}

void demo_plan_print(const demo_plan* p, FILE* f) {
    char text[SWARP_PLAN_EXPLAIN_MAX];
    size_t need = 0;
    fprintf(f, "plan (swarp_plan: %s):\n", swarp_status_name(p->status));
    if (swarp_plan_explain(&p->plan, text, sizeof text, &need) == SWARP_OK) {
        /* indent every line of the explanation */
        const char* s = text;
        while (*s) {
            const char* e = strchr(s, '\n');
            size_t len = e ? (size_t)(e - s) : strlen(s);
            fprintf(f, "  %.*s\n", (int)len, s);
            s += len + (e ? 1 : 0);
        }
    } else {
        fprintf(f, "  (swarp_plan_explain failed)\n");
    }
    fprintf(f, "  demo: --technique %s", demo_technique_name(p->technique));
    if (demo_technique_is_split(p->technique))
        fprintf(f, " --splits %d --scheme %s", p->splits,
                p->scheme == DEMO_SCHEME_LOG ? "log" : "practical:0.5");
    if (p->technique == DEMO_TECH_PSEUDO) fprintf(f, " --pseudo 0.1,0.1");
    fprintf(f, " --filter %s%s%s\n", demo_filter_name(p->filter), p->exact ? "" : "; differs: ",
            p->exact ? "" : p->note);
}
