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

int cmd_setup(sw_args* a) {
    static const char* const known[] = {"eye",   "dir",    "up",        "fovy",  "aspect", "near",
                                        "far",   "light-dir", "light-pos", "box", "map",    "screen",
                                        "technique", "depth", "reps", "min-depth", "prev-view", "prev-proj",
                                        "prev-range", "prev-dir", NULL};
    /* stage: splits -- `setup --splits K` is the cascade (cmd_cascade.c) */
    if (cli_opt(a, "splits")) return cmd_cascade(a);
    if (!cli_check_known(a, known)) return 2;
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    swarp_light light;
    memset(&light, 0, sizeof light);
    swarp_aabb box;
    double fovy_deg = 60.0, boxv[6];
    unsigned map = 2048, sw = 1920, sh = 1080, reps = 1;
    if (!cli_vec3(a, "eye", 1, &cam.eye) || !cli_vec3(a, "dir", 1, &cam.dir)) return 2;
    cam.up = (swarp_vec3){0, 1, 0};
    if (!cli_vec3(a, "up", 0, &cam.up)) return 2;
    if (!cli_double(a, "fovy", 60.0, &fovy_deg) || !cli_double(a, "aspect", 16.0 / 9.0, &cam.aspect) ||
        !cli_double(a, "near", 1.0, &cam.z_near) || !cli_double(a, "far", 100.0, &cam.z_far))
        return 2;
    cam.fovy = fovy_deg * SW_DEG;
    const char* ld = cli_opt(a, "light-dir");
    const char* lp = cli_opt(a, "light-pos");
    if ((ld != NULL) == (lp != NULL)) {
        fprintf(stderr, "swtool setup: give exactly one of --light-dir x,y,z and --light-pos x,y,z\n");
        return 2;
    }
    if (ld) {
        light.type = SWARP_LIGHT_DIRECTIONAL;
        if (!cli_vec3(a, "light-dir", 1, &light.direction)) return 2;
    } else {
        light.type = SWARP_LIGHT_POINT;
        if (!cli_vec3(a, "light-pos", 1, &light.position)) return 2;
    }
    const char* bs = cli_opt(a, "box");
    if (!bs || !cli_parse_list(bs, boxv, 6)) {
        fprintf(stderr, "swtool setup: --box x0,y0,z0,x1,y1,z1 is required\n");
        return 2;
    }
    box.min = (swarp_vec3){boxv[0], boxv[1], boxv[2]};
    box.max = (swarp_vec3){boxv[3], boxv[4], boxv[5]};
    double min_depth = 0.0;
    if (!cli_uint(a, "map", 2048, &map) || !cli_size(a, "screen", 1920, 1080, &sw, &sh) ||
        !cli_uint(a, "reps", 1, &reps) || !cli_double(a, "min-depth", 0.0, &min_depth))
        return 2;
    if (reps == 0) reps = 1;
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.min_depth = min_depth; /* [RHS] §4.3 measured min depth; 0 = not given */
    o.map_width = o.map_height = map;
    o.screen_width = sw;
    o.screen_height = sh;
    const char* tech = cli_opt(a, "technique");
    if (!tech || strcmp(tech, "lispsm") == 0) {
        o.technique = SWARP_TECHNIQUE_LISPSM;
        o.param = SWARP_WARP_PARAM_NOPT;
    } else if (strcmp(tech, "uniform") == 0) {
        o.technique = SWARP_TECHNIQUE_UNIFORM;
    } else if (strcmp(tech, "repar") == 0) {
        o.technique = SWARP_TECHNIQUE_LISPSM;
        o.param = SWARP_WARP_PARAM_NREPAR;
    } else if (strcmp(tech, "gmnpr") == 0) {
        o.technique = SWARP_TECHNIQUE_LISPSM;
        o.param = SWARP_WARP_PARAM_GMNPR;
    } else if (strcmp(tech, "psm") == 0) {
        o.technique = SWARP_TECHNIQUE_PSM;
    } else {
        fprintf(stderr, "swtool setup: --technique uniform|lispsm|repar|gmnpr|psm, got '%s'\n", tech);
        return 2;
    }
    const char* depth = cli_opt(a, "depth");
    if (!depth || strcmp(depth, "gl") == 0) {
        o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    } else if (strcmp(depth, "zo") == 0) {
        o.depth_range = SWARP_DEPTH_ZERO_TO_ONE;
    } else {
        fprintf(stderr, "swtool setup: --depth gl|zo, got '%s'\n", depth);
        return 2;
    }
    /* swarp_setup_follow: the previous frame's light_view (and for PSM its
     * light_proj and view range) as printed by an earlier `swtool setup --json` */
    swarp_setup_result prev;
    memset(&prev, 0, sizeof prev);
    swarp_camera prev_cam = cam;
    const char* pv = cli_opt(a, "prev-view");
    if (pv && !cli_parse_list(pv, prev.light_view.m, 16)) {
        fprintf(stderr, "swtool setup: --prev-view takes 16 numbers (column-major light_view)\n");
        return 2;
    }
    const char* pp = cli_opt(a, "prev-proj");
    if (pp && !cli_parse_list(pp, prev.light_proj.m, 16)) {
        fprintf(stderr, "swtool setup: --prev-proj takes 16 numbers (column-major light_proj)\n");
        return 2;
    }
    const char* pr = cli_opt(a, "prev-range");
    double prv[3];
    if (pr) {
        if (!cli_parse_list(pr, prv, 3)) {
            fprintf(stderr, "swtool setup: --prev-range near,far,n_param of the previous output\n");
            return 2;
        }
        prev.view_near = prv[0], prev.view_far = prv[1], prev.n_eye = prv[2];
    }
    if ((pp || pr || cli_opt(a, "prev-dir")) && !pv) {
        fprintf(stderr, "swtool setup: --prev-proj, --prev-range and --prev-dir need --prev-view\n");
        return 2;
    }
    if (pv && o.technique == SWARP_TECHNIQUE_PSM && (!pp || !pr)) {
        fprintf(stderr, "swtool setup: PSM follows its light camera: give --prev-proj and --prev-range too\n");
        return 2;
    }
    if (!cli_vec3(a, "prev-dir", 0, &prev_cam.dir)) return 2;
    double* ns = malloc(sizeof(double) * reps);
    if (!ns) return 1;
    swarp_setup_result r;
    swarp_status s = SWARP_OK;
    for (unsigned k = 0; k < reps; ++k) {
        double t0 = now_ns();
        s = pv ? swarp_setup_follow(&cam, &light, &box, &o, &prev_cam, &prev, &r, NULL, 0, NULL)
               : swarp_setup(&cam, &light, &box, &o, &r, NULL, 0, NULL);
        ns[k] = now_ns() - t0;
    }
    qsort(ns, reps, sizeof(double), cmp_double);
    double median = reps % 2 ? ns[reps / 2] : 0.5 * (ns[reps / 2 - 1] + ns[reps / 2]);
    free(ns);
    const char* where = pv ? "swarp_setup_follow" : "swarp_setup";
    if (swarp_status_is_error(s)) return cli_report_status(a, s, where);
    if (a->json) {
        json_begin();
        json_kv_status(s);
        json_kv_mat("light_view", &r.light_view);
        json_kv_mat("light_proj", &r.light_proj);
        json_kv_mat("matrix", &r.matrix);
        json_kv_num("n_param", r.n_eye);
        json_kv_num("near", r.view_near);
        json_kv_num("far", r.view_far);
        json_kv_num("max_mx", r.max_mx);
        json_kv_num("max_mz", r.max_mz);
        json_kv_num("setup_ns", median);
        json_end();
    } else {
        printf("status      %s\n", swarp_status_name(s));
        printf("technique   %s\n", tech ? tech : "lispsm");
        printf("n' (eye)    %.9g\n", r.n_eye);
        printf("view range  [%.9g, %.9g] (adjusted, [RHS] 3.3.1%s)\n", r.view_near, r.view_far,
               min_depth > 0 ? "; near from the measured min depth, 4.3" : "");
        printf("gamma       %.6g deg\n", r.gamma / SW_DEG);
        printf("max m_x     %.6g\nmax m_z     %.6g\n", r.max_mx, r.max_mz);
        printf("points of B %u\n", r.point_count);
        printf("setup       %.0f ns (median of %u)\n", median, reps);
        printf("matrix (column-major):\n");
        for (int row = 0; row < 4; ++row)
            printf("  %14.8g %14.8g %14.8g %14.8g\n", r.matrix.m[row], r.matrix.m[4 + row], r.matrix.m[8 + row],
                   r.matrix.m[12 + row]);
    }
    return cli_report_status(a, s, where);
}
