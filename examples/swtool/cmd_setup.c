/* swtool setup: the one call for engines (swarp_setup) from the command
 * line.  docs/swtool.md, section "setup". */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"

static int cmp_double(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static double now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* Without --reps the setup is timed until the median is stable: at least
 * SW_SETUP_MIN_REPS calls and SW_SETUP_MIN_NS of them, so the median of a
 * microsecond call is over thousands of samples and a scheduler hiccup moves
 * it by one rank; at most SW_SETUP_MAX_REPS (the slowest valid setup, a
 * clipped body of SWARP_BODY_MAX_POINTS, still ends within seconds). */
#define SW_SETUP_MIN_REPS 51u
#define SW_SETUP_MIN_NS 2e7
#define SW_SETUP_MAX_REPS 100001u

static int setup_technique(const sw_args* a, swarp_setup_options* o) {
    const char* tech = cli_opt(a, "technique");
    if (!tech || strcmp(tech, "lispsm") == 0) {
        o->technique = SWARP_TECHNIQUE_LISPSM;
        o->param = SWARP_WARP_PARAM_NOPT;
    } else if (strcmp(tech, "uniform") == 0) {
        o->technique = SWARP_TECHNIQUE_UNIFORM;
    } else if (strcmp(tech, "repar") == 0) {
        o->technique = SWARP_TECHNIQUE_LISPSM;
        o->param = SWARP_WARP_PARAM_NREPAR;
    } else if (strcmp(tech, "gmnpr") == 0) {
        o->technique = SWARP_TECHNIQUE_LISPSM;
        o->param = SWARP_WARP_PARAM_GMNPR;
    } else if (strcmp(tech, "psm") == 0) {
        o->technique = SWARP_TECHNIQUE_PSM;
    } else {
        cli_fail(a, "--technique", "expects uniform|lispsm|repar|gmnpr|psm, got '%s'", tech);
        return 0;
    }
    return 1;
}

/* swarp_setup_follow: the previous frame's light_view (and for PSM its
 * light_proj and view range) as printed by an earlier `swtool setup --json` */
static int setup_previous(const sw_args* a, const swarp_setup_options* o, swarp_setup_result* prev,
                          swarp_camera* prev_cam) {
    double prv[3];
    const char* pv = cli_opt(a, "prev-view");
    const char* pp = cli_opt(a, "prev-proj");
    const char* pr = cli_opt(a, "prev-range");
    if (!cli_list(a, "prev-view", 16, "column-major light_view", prev->light_view.m) ||
        !cli_list(a, "prev-proj", 16, "column-major light_proj", prev->light_proj.m) ||
        !cli_list(a, "prev-range", 3, "near,far,n_param of the previous output", prv) ||
        !cli_vec3(a, "prev-dir", 0, &prev_cam->dir))
        return 0;
    if (pr) prev->view_near = prv[0], prev->view_far = prv[1], prev->n_eye = prv[2];
    if ((pp || pr || cli_opt(a, "prev-dir")) && !pv) {
        cli_fail(a, NULL, "--prev-proj, --prev-range and --prev-dir need --prev-view");
        return 0;
    }
    if (pv && o->technique == SWARP_TECHNIQUE_PSM && (!pp || !pr)) {
        cli_fail(a, "--prev-view", "PSM follows its light camera: give --prev-proj and --prev-range too");
        return 0;
    }
    return 1;
}

static void setup_print(const sw_args* a, swarp_status s, const swarp_setup_result* r, double median,
                        unsigned reps, double min_depth, const swarp_camera* cam, const sw_camera_source* src) {
    const char* tech = cli_opt(a, "technique");
    if (a->json) {
        json_begin();
        json_kv_status(s);
        json_kv_mat("light_view", &r->light_view);
        json_kv_mat("light_proj", &r->light_proj);
        json_kv_mat("matrix", &r->matrix);
        json_kv_num("n_param", r->n_eye);
        json_kv_num("near", r->view_near);
        json_kv_num("far", r->view_far);
        json_kv_num("max_mx", r->max_mx);
        json_kv_num("max_mz", r->max_mz);
        json_kv_measured(&r->measured);
        json_kv_num("setup_ns", median);
        json_kv_num("setup_reps", reps);
        json_kv_camera(cam, src);
        json_end();
        return;
    }
    printf("status      %s\n", swarp_status_name(s));
    cli_print_camera(cam, src);
    printf("technique   %s\n", tech ? tech : "lispsm");
    printf("n' (eye)    %.9g\n", r->n_eye);
    printf("view range  [%.9g, %.9g] (adjusted, [RHS] 3.3.1%s)\n", r->view_near, r->view_far,
           min_depth > 0 ? "; near from the measured min depth, 4.3" : "");
    printf("gamma       %.6g deg\n", r->gamma / SW_DEG);
    printf("model       max m_x %.6g, max m_z %.6g (Lloyd, overhead light on the view axis)\n", r->max_mx,
           r->max_mz);
    print_measured("", &r->measured);
    printf("points of B %u\n", r->point_count);
    printf("setup       %.0f ns (median of %u calls)\n", median, reps);
    print_matrix_rows("", "matrix", &r->matrix);
}

int cmd_setup(sw_args* a) {
    static const char* const known[] = {"eye",   "dir",    "up",        "fovy",  "aspect", "near",
                                        "far",   "light-dir", "light-pos", "box", "map",    "screen",
                                        "technique", "depth", "reps", "min-depth", "prev-view", "prev-proj",
                                        "prev-range", "prev-dir", "splits", "view", "proj", "proj-convention",
                                        "proj-depth", NULL};
    /* stage: splits -- `setup --splits K` is the cascade (cmd_cascade.c) */
    if (cli_opt(a, "splits") && !a->help) return cmd_cascade(a);
    CLI_ACCEPT(a, known);
    swarp_camera cam = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 60.0 * SW_DEG, 16.0 / 9.0, 1.0, 100.0, {0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    swarp_aabb box;
    unsigned mw, mh, sw, sh, reps = 0;
    double min_depth = 0.0;
    if (!cli_camera(a, !cli_opt(a, "view"), &cam) || !cli_light(a, 1, &light) || !cli_box(a, 1, &box) ||
        !cli_map(a, 2048, &mw, &mh) || !cli_size(a, "screen", 1920, 1080, &sw, &sh) ||
        !cli_uint(a, "reps", 0, &reps) || !cli_double(a, "min-depth", 0.0, &min_depth))
        return CLI_EXIT_USAGE;
    sw_camera_source src;
    int rc = cli_engine_camera(a, &box, &cam, &src);
    if (rc != CLI_GO) return rc;
    if (cli_opt(a, "reps") && (reps == 0 || reps > SW_SETUP_MAX_REPS))
        return cli_fail(a, "--reps", "expects 1..%u, got '%s'", SW_SETUP_MAX_REPS, cli_opt(a, "reps"));
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.min_depth = min_depth; /* [RHS] §4.3 measured min depth; 0 = not given */
    o.map_width = mw;
    o.map_height = mh;
    o.screen_width = sw;
    o.screen_height = sh;
    swarp_setup_result prev;
    memset(&prev, 0, sizeof prev);
    swarp_camera prev_cam = cam;
    if (!setup_technique(a, &o) || !cli_depth(a, &o.depth_range) || !setup_previous(a, &o, &prev, &prev_cam))
        return CLI_EXIT_USAGE;
    const char* pv = cli_opt(a, "prev-view");
    unsigned cap = reps ? reps : SW_SETUP_MAX_REPS;
    double* ns = malloc(sizeof(double) * cap);
    if (!ns) return cli_report_status(a, SWARP_ERR_CAPACITY, "timing buffer");
    swarp_setup_result r;
    swarp_status s = SWARP_OK;
    double total = 0.0;
    unsigned k = 0;
    while (reps ? k < reps : (k < SW_SETUP_MIN_REPS || total < SW_SETUP_MIN_NS) && k < cap) {
        double t0 = now_ns();
        s = pv ? swarp_setup_follow(&cam, &light, &box, &o, &prev_cam, &prev, &r, NULL, 0, NULL)
               : swarp_setup(&cam, &light, &box, &o, &r, NULL, 0, NULL);
        ns[k] = now_ns() - t0;
        total += ns[k++];
        if (swarp_status_is_error(s)) break;
    }
    qsort(ns, k, sizeof(double), cmp_double);
    double median = k % 2 ? ns[k / 2] : 0.5 * (ns[k / 2 - 1] + ns[k / 2]);
    free(ns);
    const char* where = pv ? "swarp_setup_follow" : "swarp_setup";
    if (swarp_status_is_error(s)) return cli_report_status(a, s, where);
    setup_print(a, s, &r, median, k, min_depth, &cam, &src);
    return cli_report_status(a, s, where);
}
