/* swtool plan: what the scene needs and what the caller can spend -> the
 * planner's chain with its predicted error, cost and reasons
 * (swarp_plan, docs/planning.md).  --force evaluates one given chain. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

static const char* const plan_known[] = {
    "gamma", "eye", "dir", "up", "light-dir", "light-pos", "fovy", "aspect", "near", "far",
    "screen", "moves", "soft", "bleed", "clamp", "plane", "plane2", "plane3", "plane4",
    "box", "max-error", "map", "atlas", "max-passes", "time-ms", "pass-ms",
    "blur-ms", "force", "splits", "scheme", NULL};

static int parse_bleed(const sw_args* a, const char* s, swarp_plan_bleed* out) {
    static const char* names[] = {"none", "low", "high", "extreme"};
    for (int i = 0; i < 4; ++i)
        if (strcmp(s, names[i]) == 0) {
            *out = (swarp_plan_bleed)(SWARP_PLAN_BLEED_NONE + i);
            return 1;
        }
    cli_fail(a, "--bleed", "expects none|low|high|extreme, got '%s'", s);
    return 0;
}

static int parse_warp(const sw_args* a, const char* s, swarp_plan_warp* out) {
    for (int w = SWARP_PLAN_WARP_UNIFORM; w <= SWARP_PLAN_WARP_PSM; ++w)
        if (strcmp(s, swarp_plan_warp_name((swarp_plan_warp)w)) == 0) {
            *out = (swarp_plan_warp)w;
            return 1;
        }
    cli_fail(a, "--force", "expects uniform|lispsm-nopt|lispsm-nrepar|lispsm-gmnpr|lispsm-pseudo|psm, got '%s'", s);
    return 0;
}

/* Builds needs and budget from the command line; 0 on a parse error. */
static int plan_inputs(const sw_args* a, swarp_scene_needs* n, swarp_budget* b) {
    memset(n, 0, sizeof *n);
    memset(b, 0, sizeof *b);
    double gamma;
    /* the camera of the --gamma convenience: 2 above the ground looking
     * along -z; the light at gamma to the view in the view/up plane */
    n->camera = (swarp_camera){{0.0, 2.0, 0.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}, 60.0 * SW_DEG, 4.0 / 3.0, 1.0,
                               100.0, {0}};
    if (!cli_camera(a, 0, &n->camera) || !cli_double(a, "gamma", 90.0, &gamma)) return 0;
    n->light.type = SWARP_LIGHT_DIRECTIONAL;
    n->light.direction = (swarp_vec3){0.0, -sin(gamma * SW_DEG), cos(gamma * SW_DEG)};
    if (!cli_light(a, 0, &n->light)) return 0;
    if (cli_opt(a, "gamma") && (cli_opt(a, "light-dir") || cli_opt(a, "light-pos"))) {
        cli_fail(a, "--gamma", "places the light itself: give --gamma or a --light-dir/--light-pos, not both");
        return 0;
    }
    unsigned sw, sh;
    if (!cli_size(a, "screen", 1024, 768, &sw, &sh)) return 0;
    n->screen_width = sw;
    n->screen_height = sh;
    n->camera_moves = (uint32_t)cli_flag(a, "moves");
    n->allow_depth_clamp = (uint32_t)cli_flag(a, "clamp");
    if (cli_opt(a, "soft")) {
        n->soft_shadows = 1;
        if (!cli_double(a, "soft", 0.0, &n->soft_width)) return 0;
    }
    const char* bl = cli_opt(a, "bleed");
    if (bl && !parse_bleed(a, bl, &n->bleed_risk)) return 0;
    static const char* plane_opts[4] = {"plane", "plane2", "plane3", "plane4"};
    for (int i = 0; i < 4; ++i) {
        const char* s = cli_opt(a, plane_opts[i]);
        if (!s) continue;
        double v[4];
        if (!cli_list(a, plane_opts[i], 4, "A,B,C,D", v)) return 0;
        n->planes[n->plane_count++] = (swarp_plane){v[0], v[1], v[2], v[3]};
    }
    if (!cli_box(a, 0, &n->scene_box)) return 0;
    unsigned map, atlas, passes;
    double tms, pms, bms;
    if (!cli_double(a, "max-error", 1.0, &b->max_error) || !cli_map_square(a, 2048, &map) ||
        !cli_uint(a, "atlas", 8192, &atlas) || !cli_uint(a, "max-passes", 16, &passes) ||
        !cli_double(a, "time-ms", 0.0, &tms) || !cli_double(a, "pass-ms", 0.0, &pms) ||
        !cli_double(a, "blur-ms", 0.0, &bms))
        return 0;
    b->map_resolution = map;
    b->atlas_limit = atlas;
    b->max_passes = passes;
    b->time_budget_ns = tms * 1e6;
    b->pass_cost_ns = pms * 1e6;
    b->blur_pass_cost_ns = bms * 1e6;
    return 1;
}

static void print_json(const struct swarp_plan* p, swarp_status s, const char* text) {
    json_begin();
    json_kv_status(s);
    json_kv_str("warp", swarp_plan_warp_name(p->warp));
    json_kv_str("scheme", swarp_plan_scheme_name(p->scheme));
    json_kv_num("split_count", p->split_count);
    json_kv_num("map_resolution", p->map_resolution);
    json_kv_num("atlas_tiles", p->atlas_tiles);
    json_kv_str("stabilize", p->stabilize == SWARP_PLAN_STABILIZE_APPROX64 ? "approx64" : "none");
    json_kv_num("inverse_projection", p->inverse_projection);
    json_kv_num("depth_clamp", p->depth_clamp);
    json_kv_num("gamma_deg", p->gamma / SW_DEG);
    json_kv_num("near", p->z_near);
    json_kv_num("far", p->z_far);
    json_kv_arr("splits", p->splits, p->split_count + 1);
    json_kv_arr("n_prime", p->n_prime, p->split_count);
    json_kv_arr("split_max_mx", p->split_max_mx, p->split_count);
    json_kv_arr("split_max_mz", p->split_max_mz, p->split_count);
    json_kv_num("max_mx", p->max_mx);
    json_kv_num("max_mz", p->max_mz);
    json_kv_num("max_error", p->max_error);
    json_kv_num("error_area", p->error_area);
    double planes[SWARP_PLAN_MAX_PLANES], reasons[SWARP_PLAN_MAX_PLANES];
    for (uint32_t i = 0; i < p->lixel_count; ++i) planes[i] = p->lixel_planes[i];
    for (uint32_t i = 0; i < p->plane_count; ++i) reasons[i] = p->plane_reason[i];
    json_kv_arr("lixel_planes", planes, p->lixel_count);
    json_kv_arr("plane_reason", reasons, p->plane_count);
    json_kv_num("lixel_error", p->lixel_error);
    json_kv_str("filter", swarp_plan_filter_name(p->filter));
    json_kv_num("filter_width", p->filter_width);
    json_kv_num("filter_layers", p->filter_layers);
    json_kv_num("filter_exponent_pos", p->filter_exponent_pos);
    json_kv_num("filter_exponent_neg", p->filter_exponent_neg);
    json_kv_num("shadow_passes", p->shadow_passes);
    json_kv_num("blur_passes", p->blur_passes);
    json_kv_num("texels", p->texels);
    json_kv_num("cost_ns", p->cost_ns);
    json_kv_num("meets_budget", p->meets_budget);
    json_kv_num("reasons", p->reasons);
    json_kv_num("candidates", p->candidates);
    json_kv_str("explain", text);
    json_end();
}

int cmd_plan(sw_args* a) {
    CLI_ACCEPT(a, plan_known);
    swarp_scene_needs n;
    swarp_budget b;
    if (!plan_inputs(a, &n, &b)) return CLI_EXIT_USAGE;
    struct swarp_plan p;
    swarp_status s;
    const char* force = cli_opt(a, "force");
    if (!force && (cli_opt(a, "splits") || cli_opt(a, "scheme")))
        return cli_fail(a, cli_opt(a, "splits") ? "--splits" : "--scheme",
                        "describes the chain of --force; the planner chooses its own");
    if (force) {
        swarp_plan_chain c;
        memset(&c, 0, sizeof c);
        unsigned K;
        if (!parse_warp(a, force, &c.warp) || !cli_uint(a, "splits", 1, &K)) return CLI_EXIT_USAGE;
        c.split_count = K;
        const char* sch = cli_opt(a, "scheme");
        c.scheme = K > 1 ? SWARP_PLAN_SCHEME_LOG : SWARP_PLAN_SCHEME_NONE;
        if (sch && strcmp(sch, "practical") == 0) c.scheme = SWARP_PLAN_SCHEME_PRACTICAL;
        else if (sch && strcmp(sch, "log") != 0)
            return cli_fail(a, "--scheme", "expects log|practical, got '%s'", sch);
        s = swarp_plan_evaluate(&n, &b, &c, &p);
    } else {
        s = swarp_plan(&n, &b, &p);
    }
    if (swarp_status_is_error(s)) return cli_report_status(a, s, force ? "swarp_plan_evaluate" : "swarp_plan");
    char text[SWARP_PLAN_EXPLAIN_MAX];
    size_t cnt = 0;
    swarp_status es = swarp_plan_explain(&p, text, sizeof text, &cnt);
    if (swarp_status_is_error(es)) return cli_report_status(a, es, "swarp_plan_explain");
    if (a->json) {
        print_json(&p, s, text);
        return 0;
    }
    printf("status: %s\n%s", swarp_status_name(s), text);
    return 0;
}
