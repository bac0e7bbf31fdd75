#define _POSIX_C_SOURCE 200809L
/* Hard-case / fuzz entries for the planner: swarp_plan, swarp_plan_evaluate,
 * swarp_plan_explain.  Needs and budgets are mostly zero (defaults) with
 * edge values in a few fields: a camera looking along the light, points
 * lights at the eye, scene boxes that are flat, offsets of 1e6, budgets of
 * 1e-9 pixels, one pass.  Properties: splits strictly increasing from near
 * to far, shadow passes = K + lixel maps, max_error = max(max_mx, max_mz),
 * meets_budget agrees with the budget and the status, every value finite
 * (n' may be +inf: uniform), explain's text NUL-terminated with the length
 * it reports. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_plan)
SWR_WEAK(swarp_plan_evaluate)
SWR_WEAK(swarp_plan_explain)


static int fin(double x) { return swr_isfin(x); }

static void gen_needs(swr_ctx* c, swarp_scene_needs* n, swarp_budget* b) {
    memset(n, 0, sizeof *n);
    memset(b, 0, sizeof *b);
    if (!swr_one_in(c, 3)) { /* a camera */
        double off = swr_offset(c);
        n->camera.eye.x = off + swr_num_in(c, -10, 10, NULL, 0);
        n->camera.eye.y = swr_num_in(c, 0.5, 20, NULL, 0);
        n->camera.eye.z = off + swr_num_in(c, -10, 10, NULL, 0);
        n->camera.dir.x = swr_num_in(c, -1, 1, NULL, 0);
        n->camera.dir.y = swr_num_in(c, -1, 0.2, NULL, 0);
        n->camera.dir.z = swr_num_in(c, -1, 1, NULL, 0);
        n->camera.up.y = 1;
        n->camera.fovy = swr_num_in(c, 0.2, 2.5, NULL, 0);
        n->camera.aspect = swr_num_in(c, 0.5, 2.5, NULL, 0);
        static const double brk_n[] = {1e-6, 1.0};
        n->camera.z_near = swr_num_in(c, 1e-6, 2, brk_n, 2);
        n->camera.z_far = n->camera.z_near * swr_num_in(c, 2, 1e7, NULL, 0);
        if (swr_one_in(c, 4)) { /* the scene box around the camera, sometimes flat */
            n->scene_box.min.x = n->camera.eye.x - swr_num_in(c, 1, 100, NULL, 0);
            n->scene_box.min.y = swr_num_in(c, -5, 0, NULL, 0);
            n->scene_box.min.z = n->camera.eye.z - swr_num_in(c, 1, 100, NULL, 0);
            n->scene_box.max.x = n->camera.eye.x + swr_num_in(c, 1, 100, NULL, 0);
            n->scene_box.max.y = swr_one_in(c, 3) ? n->scene_box.min.y : swr_num_in(c, 0, 30, NULL, 0);
            n->scene_box.max.z = n->camera.eye.z + swr_num_in(c, 1, 100, NULL, 0);
        }
    }
    if (!swr_one_in(c, 3)) { /* a light, sometimes along the view */
        n->light.type = (swarp_light_type)swr_enum(c, 3);
        n->light.direction.x = swr_num_in(c, -1, 1, NULL, 0);
        n->light.direction.y = swr_num_in(c, -1, -0.05, NULL, 0);
        n->light.direction.z = swr_num_in(c, -1, 1, NULL, 0);
        if (swr_one_in(c, 6)) n->light.direction = n->camera.dir;
        n->light.position = n->camera.eye;
        if (!swr_one_in(c, 4)) n->light.position.y += swr_num_in(c, 1, 100, NULL, 0);
    }
    n->screen_width = swr_one_in(c, 2) ? 0 : swr_u32(c) % 5000;
    n->screen_height = swr_one_in(c, 2) ? 0 : swr_u32(c) % 5000;
    n->camera_moves = swr_u8(c) % 2;
    n->soft_shadows = swr_u8(c) % 2;
    n->soft_width = swr_one_in(c, 2) ? 0 : swr_num_in(c, 1, 32, NULL, 0);
    n->bleed_risk = (swarp_plan_bleed)swr_enum(c, 5);
    n->allow_depth_clamp = swr_u8(c) % 2;
    n->plane_count = swr_one_in(c, 20) ? 5 : swr_u8(c) % 3;
    for (uint32_t i = 0; i < SWARP_PLAN_MAX_PLANES; ++i) {
        n->planes[i].b = 1;
        n->planes[i].d = swr_num_in(c, -1, 1, NULL, 0);
    }
    {
        /* the fourth reserved word became plan_by: a draw for it lands in
         * the last reserved word (the stream of draws is unchanged) */
        uint32_t k = swr_u8(c) % 4;
        n->_reserved[k < 3 ? k : 2] = swr_reserved(c);
    }
    /* the sweeps compare across rounding modes and against a snapshot: they
     * run the model's rule, whose every decision is rounding-independent
     * (the measured search compares measurements with the budget, a
     * threshold rounding can decide; tests/plan covers that path) */
    n->plan_by = SWARP_PLAN_BY_MODEL;
    static const double brk_e[] = {1e-9, 1.0, 100.0};
    b->max_error = swr_one_in(c, 3) ? 0 : swr_num_in(c, 1e-9, 100, brk_e, 3);
    b->map_resolution = swr_one_in(c, 2) ? 0 : 64u << (swr_u8(c) % 8);
    b->atlas_limit = swr_one_in(c, 2) ? 0 : 256u << (swr_u8(c) % 7);
    b->max_passes = swr_one_in(c, 2) ? 0 : swr_u8(c) % 34;
    b->time_budget_ns = swr_one_in(c, 2) ? 0 : swr_num_in(c, 1e3, 1e8, NULL, 0);
    b->pass_cost_ns = swr_one_in(c, 2) ? 0 : swr_num_in(c, 1e3, 1e7, NULL, 0);
    /* the budget has no reserved words left: the draws stay, so the
     * stream of the other fields is unchanged */
    (void)swr_u8(c);
    (void)swr_reserved(c);
    /* one field with an edge or invalid value */
    if (swr_one_in(c, 3)) {
        double* fields[] = {&n->camera.eye.x, &n->camera.fovy, &n->camera.z_near, &n->camera.z_far, &n->light.direction.y,
                            &n->soft_width, &b->max_error, &b->time_budget_ns, &b->pass_cost_ns, &n->scene_box.max.x};
        double* f = fields[swr_u8(c) % (sizeof fields / sizeof fields[0])];
        *f = swr_num(c, *f - 1, *f + 1, f, 1);
    }
}

static void expect_needs(swr_ctx* c, const swarp_scene_needs* n, const swarp_budget* b) {
    const double* d = &n->camera.eye.x; /* eye, dir, up, fovy, aspect, near, far */
    for (int i = 0; i < 13; ++i)
        if (!fin(d[i])) swr_expect(c, SWARP_ERR_NON_FINITE);
    /* the light fields its type uses: direction (a point light's only as a
     * spot's axis), a point light's position */
    const swarp_light* l = &n->light;
    const int point = l->type == SWARP_LIGHT_POINT;
    if (((!point || l->cone_angle != 0) && (!fin(l->direction.x) || !fin(l->direction.y) || !fin(l->direction.z))) ||
        (point && !fin(l->position.y)))
        swr_expect(c, SWARP_ERR_NON_FINITE);
    if (!fin(n->soft_width) || !fin(n->scene_box.max.x) || !fin(b->max_error) || !fin(b->time_budget_ns) ||
        !fin(b->pass_cost_ns))
        swr_expect(c, SWARP_ERR_NON_FINITE);
    for (int i = 0; i < 3; ++i)
        if (n->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    if ((int)n->light.type < 0 || (int)n->light.type > 2 || (int)n->bleed_risk < 0 || (int)n->bleed_risk > 4)
        swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    if (n->plane_count > SWARP_PLAN_MAX_PLANES) swr_expect(c, SWARP_ERR_PLAN_TOO_MANY_PLANES);
    if (b->max_passes > 32) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (b->time_budget_ns > SWARP_PLAN_MAX_COST_NS || b->pass_cost_ns > SWARP_PLAN_MAX_COST_NS)
        swr_expect(c, SWARP_ERR_OUT_OF_RANGE); /* documented limit */
    /* the documented argument errors the harness does not predict exactly */
    static const swarp_status dom[] = {SWARP_ERR_ZERO_VECTOR, SWARP_ERR_DEGENERATE, SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR,
                                       SWARP_ERR_OUT_OF_RANGE, SWARP_ERR_RESOLUTION, SWARP_ERR_PLAN_EMPTY_VIEW,
                                       SWARP_ERR_NON_FINITE, SWARP_ERR_BOX_INVERTED, SWARP_ERR_BOX_DEGENERATE};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
}

static void check_plan(swr_ctx* c, swarp_status st, const swarp_budget* b, const swarp_plan_result* p, int evaluate) {
    uint32_t K = p->split_count;
    SWR_CHECK(c, K >= 1 && K <= SWARP_PLAN_MAX_SPLITS, "split_count %u", K);
    if (!(K >= 1 && K <= SWARP_PLAN_MAX_SPLITS)) return;
    swr_rec(c, "near", p->z_near);
    swr_rec(c, "far", p->z_far);
    swr_rec(c, "max_error", p->max_error);
    swr_rec(c, "cost_ns", p->cost_ns);
    swr_rec(c, "gamma", p->gamma);
    for (uint32_t i = 0; i <= K; ++i) swr_rec(c, "split", p->splits[i]);
    for (uint32_t i = 0; i < K; ++i) {
        /* n' (+inf = uniform, documented) recorded as the warp strength
         * (split length)/n', 0 for uniform: the map depends on 1/n'
         * continuously, and next to the uniform limit n' is as large as the
         * rounding noise makes it (4e6 vs 4e7, or DBL_MAX vs +inf when the
         * caller's directed rounding turns the overflow into DBL_MAX), all
         * the same map; compared as n' they differ by 100 % (as in
         * swarp_setup's entry, entries_geometry.c). */
        if (c->n_rec < SWR_MAX_REC)
            c->rec[c->n_rec++] = p->n_prime[i] == INFINITY ? 0.0 : (p->splits[i + 1] - p->splits[i]) / p->n_prime[i];
        SWR_CHECK(c, p->n_prime[i] > 0, "n_prime[%u] = %g", i, p->n_prime[i]);
        swr_rec(c, "split_max_mx", p->split_max_mx[i]);
        swr_rec(c, "split_max_mz", p->split_max_mz[i]);
    }
    SWR_CHECK(c, p->splits[0] == p->z_near && p->splits[K] == p->z_far, "splits [%g .. %g], near/far %g %g", p->splits[0],
              p->splits[K], p->z_near, p->z_far);
    for (uint32_t i = 0; i < K; ++i) SWR_CHECK(c, p->splits[i + 1] > p->splits[i], "splits not increasing at %u", i);
    SWR_CHECK(c, p->max_error == fmax(p->max_mx, p->max_mz), "max_error %g, max(m_x, m_z) %g", p->max_error,
              fmax(p->max_mx, p->max_mz));
    SWR_CHECK(c, p->shadow_passes == K + p->lixel_count, "passes %u, K + lixel %u", p->shadow_passes, K + p->lixel_count);
    SWR_CHECK(c, p->gamma >= 0 && p->gamma <= 3.14159265358979324, "gamma %g", p->gamma);
    double budget = b && b->max_error > 0 ? b->max_error : 1.0;
    /* the error the plan was judged by: measured when it says so, else the model's */
    const int by_measure = !evaluate && (p->reasons & SWARP_PLAN_WHY_RANKED_MEASURED);
    const double judged = by_measure ? fmax(p->measured.max_m_s, p->measured.max_m_t) : p->max_error;
    if (by_measure) SWR_CHECK(c, p->built == 1, "ranked by measurement but built %u", p->built);
    if (p->meets_budget) SWR_CHECK(c, judged <= budget, "meets_budget with error %g > %g", judged, budget);
    if (!evaluate) SWR_CHECK(c, (st == SWARP_INFO_PLAN_BUDGET_UNMET) == !p->meets_budget || st == SWARP_INFO_PLAN_POINT_LIGHT,
                             "%s with meets_budget %u", swarp_status_name(st), p->meets_budget);
}

/* The error budget is a threshold the planner compares a computed error with
 * (err <= max_error: the chain meets the budget, the search stops at the
 * fewest splits that meet it).  When a candidate's error lies within
 * rounding of the budget, the caller's rounding mode decides whether it meets
 * it, and with it the number of splits (e.g. a uniform map with far = 2 near
 * (1 + 1 ulp), a 1024-pixel screen and a 2048 map: m_x = r_x f / n =
 * 1 + 2e-16 against the default budget 1, exactly 1 under FE_DOWNWARD).
 * Distance bound: the planner's error of a chain is a product and quotient
 * of some 30 rounded factors (r_x, f / n, sin(γ ± Θ) / cos Θ, p_hi / n',
 * n' from the core), none of them cancelling beyond the subtraction
 * z sin(γ-Θ) - t_lo, which is exactly 0 at its minimum and multiplied by
 * 1/n' <= 1/n elsewhere; each rounding moves it by at most 1 ulp in a
 * directed mode, so the errors of two rounding modes differ by well under
 * 64 eps relative (measured: <= 5 ulps).  The chains the search rejected
 * before the chosen one are the ones with fewer splits (same order as the
 * planner's candidate list, src/plan/plan.c sw_candidate); the chosen chain
 * itself is on the edge when its error is.  Evaluated in the default
 * environment (outside SWR_CALL). */
static int plan_on_budget_edge(const swarp_scene_needs* n, const swarp_budget* b, const swarp_plan_result* p, swarp_status st) {
    const double budget = b && b->max_error > 0 ? b->max_error : 1.0, delta = 64 * DBL_EPSILON * budget;
    if (fabs(p->max_error - budget) <= delta) return 1;
    /* BUDGET_UNMET: the run in which that chain met the budget (status OK,
     * with at most as many splits) sees it among its own rejected or chosen
     * chains; the fenv test leaves the case out when either run flags it */
    if (st == SWARP_INFO_PLAN_BUDGET_UNMET) return 0;
    static const swarp_plan_warp single[] = {SWARP_PLAN_WARP_UNIFORM,      SWARP_PLAN_WARP_LISPSM_NOPT,
                                             SWARP_PLAN_WARP_LISPSM_NREPAR, SWARP_PLAN_WARP_LISPSM_GMNPR,
                                             SWARP_PLAN_WARP_LISPSM_PSEUDO, SWARP_PLAN_WARP_PSM};
    static const swarp_plan_warp split[] = {SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_WARP_LISPSM_NOPT,
                                            SWARP_PLAN_WARP_LISPSM_NREPAR};
    const int moves = n && n->camera_moves; /* the planner keeps uniform chains only */
    for (uint32_t K = 1; K < p->split_count; ++K) {
        for (size_t v = 0; v < 6; ++v) { /* K = 1: six warps; K > 1: two schemes x three warps */
            swarp_plan_chain ch;
            memset(&ch, 0, sizeof ch);
            ch.split_count = K;
            ch.warp = K == 1 ? single[v] : split[v % 3];
            ch.scheme = K == 1 ? SWARP_PLAN_SCHEME_NONE : v < 3 ? SWARP_PLAN_SCHEME_PRACTICAL : SWARP_PLAN_SCHEME_LOG;
            if (moves && ch.warp != SWARP_PLAN_WARP_UNIFORM) continue;
            ch.matrices = SWARP_PLAN_MATRICES_NONE; /* the model's error decides the edge */
            swarp_plan_result e;
            if (swarp_status_is_error(swarp_plan_evaluate(n, b, &ch, &e))) continue;
            if (fabs(e.max_error - budget) <= delta) return 1;
        }
    }
    return 0;
}

static void e_plan(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_plan);
    swarp_scene_needs n;
    swarp_budget b;
    gen_needs(c, &n, &b);
    int n_n = swr_one_in(c, 8), n_b = swr_one_in(c, 8), n_o = swr_null(c);
    if (n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!n_n || !n_b) expect_needs(c, n_n ? &(swarp_scene_needs){0} : &n, n_b ? &(swarp_budget){0} : &b);
    swarp_plan_result p;
    swr_fill(&p, sizeof p);
    swarp_status st = SWR_CALL(c, swarp_plan(n_n ? NULL : &n, n_b ? NULL : &b, n_o ? NULL : &p));
    if (!swr_verdict(c, st, 1, (void*)&p, sizeof p)) return;
    check_plan(c, st, n_b ? NULL : &b, &p, 0);
    if (swarp_plan_evaluate && p.split_count >= 1 && p.split_count <= SWARP_PLAN_MAX_SPLITS &&
        plan_on_budget_edge(n_n ? NULL : &n, n_b ? NULL : &b, &p, st))
        c->rounding_edge = 1;
}

static void e_plan_evaluate(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_plan_evaluate);
    swarp_scene_needs n;
    swarp_budget b;
    gen_needs(c, &n, &b);
    swarp_plan_chain ch;
    memset(&ch, 0, sizeof ch);
    ch.warp = (swarp_plan_warp)swr_enum(c, 7);
    ch.scheme = (swarp_plan_scheme)swr_enum(c, 4);
    ch.split_count = swr_u8(c) % 18;
    ch.stabilize = (swarp_plan_stabilize)swr_enum(c, 3);
    ch._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int n_c = swr_null(c), n_o = swr_null(c);
    if (n_c || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_needs(c, &n, &b);
    if ((int)ch.warp < 0 || (int)ch.warp > 6 || (int)ch.scheme < 0 || (int)ch.scheme > 3 || (int)ch.stabilize < 0 ||
        (int)ch.stabilize > 2)
        swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    for (int i = 0; i < 4; ++i)
        if (ch._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    uint32_t K = ch.split_count ? ch.split_count : 1;
    int none = ch.scheme == SWARP_PLAN_SCHEME_DEFAULT || ch.scheme == SWARP_PLAN_SCHEME_NONE;
    if (K > SWARP_PLAN_MAX_SPLITS || (none && K > 1) || (!none && (int)ch.scheme <= 3 && K == 1))
        swr_expect(c, SWARP_ERR_SPLIT_COUNT);
    swarp_plan_result p;
    swr_fill(&p, sizeof p);
    swarp_status st = SWR_CALL(c, swarp_plan_evaluate(&n, &b, n_c ? NULL : &ch, n_o ? NULL : &p));
    if (!swr_verdict(c, st, 1, (void*)&p, sizeof p)) return;
    SWR_CHECK(c, st != SWARP_INFO_PLAN_BUDGET_UNMET, "evaluate returned BUDGET_UNMET");
    check_plan(c, st, &b, &p, 1);
    SWR_CHECK(c, p.split_count == K, "split_count %u, chain %u", p.split_count, K);
}

static void e_plan_explain(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_plan_explain);
    swarp_plan_result p;
    memset(&p, 0, sizeof p);
    if (swarp_plan) { /* a real plan, or a corrupted one */
        swarp_scene_needs n;
        swarp_budget b;
        gen_needs(c, &n, &b);
        if (swarp_status_is_error(swarp_plan(&n, &b, &p))) memset(&p, 0, sizeof p);
    }
    if (swr_one_in(c, 10)) p.warp = (swarp_plan_warp)swr_enum(c, 9);
    if (swr_one_in(c, 10)) p.filter = (swarp_plan_filter)swr_enum(c, 9);
    if (swr_one_in(c, 10)) p.reasons = swr_u32(c);
    size_t cap = swr_one_in(c, 4) ? swr_u8(c) % 64 : SWARP_PLAN_EXPLAIN_MAX;
    int n_p = swr_null(c), n_out = swr_null(c), n_cnt = swr_null(c);
    if (n_p || n_cnt || (n_out && cap > 0)) swr_expect(c, SWARP_ERR_NULL_POINTER);
    swr_domain(c, SWARP_ERR_UNKNOWN_ENUM);
    swr_domain(c, SWARP_ERR_CAPACITY);
    char text[SWARP_PLAN_EXPLAIN_MAX + 8];
    size_t count;
    swr_fill(text, sizeof text);
    swr_fill(&count, sizeof count);
    swarp_status st = SWR_CALL(c, swarp_plan_explain(n_p ? NULL : &p, n_out ? NULL : text, cap, n_cnt ? NULL : &count));
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, swr_untouched(text, sizeof text), "CAPACITY but text written");
        SWR_CHECK(c, count > cap && count <= SWARP_PLAN_EXPLAIN_MAX, "needed %zu, capacity %zu", count, cap);
        swr_fill(&count, sizeof count);
    }
    if (!swr_verdict(c, st, 2, (void*)text, sizeof text, (void*)&count, sizeof count)) return;
    size_t len = strnlen(text, sizeof text);
    SWR_CHECK(c, len < cap && count == len + 1, "text length %zu, out_count %zu, capacity %zu", len, count, cap);
    SWR_CHECK(c, count <= SWARP_PLAN_EXPLAIN_MAX, "out_count %zu above SWARP_PLAN_EXPLAIN_MAX", count);
    SWR_CHECK(c, swr_untouched(text + count, sizeof text - count), "wrote past the NUL");
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = (double)count;
}

const swr_entry swr_entries_plan[] = {
    {"swarp_plan", "plan", e_plan},
    {"swarp_plan_evaluate", "plan", e_plan_evaluate},
    {"swarp_plan_explain", "plan", e_plan_explain},
    {NULL, NULL, NULL},
};
