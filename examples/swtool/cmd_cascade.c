/* swtool cascade / stabwalk: cascades (z-partitioning), stabilisation and
 * the data behind the pictures of docs/splits.md.  [RHS] §3.3-3.5. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* "none" | "sphere" | "levels" | "levels:N" */
static int parse_stabilize(const char* s, swarp_stabilize_mode* mode, uint32_t* levels) {
    *levels = 0;
    if (!s || strcmp(s, "none") == 0) {
        *mode = SWARP_STABILIZE_NONE;
        return 1;
    }
    if (strcmp(s, "sphere") == 0) {
        *mode = SWARP_STABILIZE_SPHERE;
        return 1;
    }
    if (strncmp(s, "levels", 6) == 0) {
        *mode = SWARP_STABILIZE_LEVELS;
        if (s[6] == '\0') return 1;
        if (s[6] != ':') return 0;
        char* end = NULL;
        long v = strtol(s + 7, &end, 10);
        if (end == s + 7 || *end || v < 1 || v > 1000000) return 0;
        *levels = (uint32_t)v;
        return 1;
    }
    return 0;
}

/* "uniform" | "log" | "practical[:L]" | "pseudo:NP,FP[,L]" */
static int parse_scheme(const char* s, swarp_split_options* o) {
    if (!s) return 1;
    if (strcmp(s, "uniform") == 0) {
        o->scheme = SWARP_SCHEME_UNIFORM;
        return 1;
    }
    if (strcmp(s, "log") == 0) {
        o->scheme = SWARP_SCHEME_LOG;
        return 1;
    }
    if (strcmp(s, "measured") == 0) { /* scene mode: the splits by measurement */
        o->scheme = SWARP_SCHEME_MEASURED;
        return 1;
    }
    if (strcmp(s, "practical") == 0 || strcmp(s, "pssm") == 0) {
        o->scheme = SWARP_SCHEME_PRACTICAL;
        o->lambda = 0.5;
        return 1;
    }
    if (strncmp(s, "practical:", 10) == 0) {
        o->scheme = SWARP_SCHEME_PRACTICAL;
        return cli_parse_list(s + 10, &o->lambda, 1);
    }
    if (strncmp(s, "pseudo:", 7) == 0) {
        double v[3];
        o->scheme = SWARP_SCHEME_PSEUDO;
        o->lambda = 0.5;
        if (cli_parse_list(s + 7, v, 2)) {
            o->pseudo_near = v[0];
            o->pseudo_far = v[1];
            return 1;
        }
        if (cli_parse_list(s + 7, v, 3)) {
            o->pseudo_near = v[0];
            o->pseudo_far = v[1];
            o->lambda = v[2];
            return 1;
        }
    }
    return 0;
}

/* 8 corners of the camera's frustum slice [n, f] */
static void walk_corners(const swarp_camera* c, double n, double f, swarp_vec3 out[8]) {
    double l = sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z);
    swarp_vec3 fw = {c->dir.x / l, c->dir.y / l, c->dir.z / l};
    swarp_vec3 r = {fw.y * c->up.z - fw.z * c->up.y, fw.z * c->up.x - fw.x * c->up.z,
                    fw.x * c->up.y - fw.y * c->up.x};
    double rl = sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    r.x /= rl, r.y /= rl, r.z /= rl;
    swarp_vec3 u = {r.y * fw.z - r.z * fw.y, r.z * fw.x - r.x * fw.z, r.x * fw.y - r.y * fw.x};
    double t = tan(c->fovy / 2);
    for (int k = 0; k < 8; ++k) {
        double z = k < 4 ? n : f, x = (k & 1 ? 1 : -1) * z * t * c->aspect, y = (k & 2 ? 1 : -1) * z * t;
        out[k].x = c->eye.x + fw.x * z + r.x * x + u.x * y;
        out[k].y = c->eye.y + fw.y * z + r.y * x + u.y * y;
        out[k].z = c->eye.z + fw.z * z + r.z * x + u.z * y;
    }
}

/* swtool stabwalk: texel coordinates of a fixed world point while the camera
 * walks and turns slowly, for each stabilisation mode. */
int cmd_stabwalk(sw_args* a) {
    static const char* const known[] = {"steps", "map", "near", "far", "speed", "turn", "levels", NULL};
    CLI_ACCEPT(a, known);
    unsigned steps, res, levels;
    double n, f, speed, turn;
    if (!cli_uint(a, "steps", 200, &steps) || !cli_map_square(a, 1024, &res) ||
        !cli_uint(a, "levels", 64, &levels) || !cli_double(a, "near", 1, &n) ||
        !cli_double(a, "far", 60, &f) || !cli_double(a, "speed", 0.013, &speed) ||
        !cli_double(a, "turn", 0.02, &turn))
        return CLI_EXIT_USAGE;
    const swarp_stabilize_mode modes[3] = {SWARP_STABILIZE_NONE, SWARP_STABILIZE_SPHERE,
                                           SWARP_STABILIZE_LEVELS};
    const char* names[3] = {"none", "sphere", "levels"};
    swarp_vec3 light = {0.4, -1.0, 0.25};
    swarp_vec3 P = {3.0, 0.0, -25.0};
    if (a->json) {
        json_begin();
        json_key("frames");
        json_open_arr();
    } else {
        printf("# frame  s_none t_none  s_sphere t_sphere  s_levels t_levels  (texels)\n");
    }
    for (unsigned k = 0; k < steps; ++k) {
        swarp_camera cam;
        memset(&cam, 0, sizeof cam);
        double yaw = turn * (double)k / (double)(steps > 1 ? steps - 1 : 1);
        cam.eye.x = speed * k;
        cam.eye.y = 8.0;
        cam.eye.z = -0.5 * speed * k;
        cam.dir.x = sin(yaw);
        cam.dir.y = -0.35;
        cam.dir.z = -cos(yaw);
        cam.up.y = 1.0;
        cam.fovy = 60.0 * SW_DEG;
        cam.aspect = 16.0 / 9.0;
        cam.z_near = n;
        cam.z_far = f;
        swarp_vec3 body[8];
        walk_corners(&cam, n, f, body);
        double st[3][2];
        for (int m = 0; m < 3; ++m) {
            swarp_stabilize_options o;
            memset(&o, 0, sizeof o);
            o.mode = modes[m];
            o.levels = levels;
            swarp_mat4 M;
            swarp_status s = swarp_stabilize_directional(&cam, n, f, &light, body, 8, NULL, res, &o, &M, NULL);
            if (swarp_status_is_error(s)) {
                if (!a->json) return cli_report_status(a, s, "swarp_stabilize_directional");
                /* the frames so far, then the error: still one complete object */
                json_close_arr();
                cli_status_fields(a, s, "swarp_stabilize_directional");
                json_kv_num("failed_frame", k);
                json_kv_str("failed_mode", names[m]);
                json_end();
                return CLI_EXIT_LIBRARY;
            }
            swarp_vec4 h;
            swarp_mat4_transform(&M, &P, &h);
            st[m][0] = (h.x / h.w * 0.5 + 0.5) * res;
            st[m][1] = (h.y / h.w * 0.5 + 0.5) * res;
        }
        if (a->json) {
            json_open_obj();
            json_kv_num("frame", k);
            for (int m = 0; m < 3; ++m) json_kv_arr(names[m], st[m], 2);
            json_close_obj();
        } else {
            printf("%u %.9f %.9f %.9f %.9f %.9f %.9f\n", k, st[0][0], st[0][1], st[1][0], st[1][1],
                   st[2][0], st[2][1]);
        }
    }
    if (a->json) {
        json_close_arr();
        json_kv_status(SWARP_OK);
        json_end();
    }
    return CLI_EXIT_OK;
}

static const char* const cascade_model_known[] = {"near", "far", "fovy", "screen", "map", "splits", "scheme",
                                                  "warp", "stabilize", "curve", "samples", NULL};
static const char* const cascade_scene_known[] = {
    "eye", "dir", "up", "fovy", "aspect", "near", "far", "light-dir", "light-pos", "box", "map", "screen",
    "technique", "depth", "splits", "scheme", "stabilize", "origin", "kernel", "curve", "samples",
    "min-depth", "warp-per-split", "view", "proj", "proj-convention", "proj-depth", NULL};

static int cascade_scheme(const sw_args* a, swarp_split_options* so) {
    if (parse_scheme(cli_opt(a, "scheme"), so)) return 1;
    cli_fail(a, "--scheme", "expects uniform|log|measured|practical[:L]|pseudo:NP,FP[,L], got '%s'", cli_opt(a, "scheme"));
    return 0;
}

static int cascade_stabilize(const sw_args* a, swarp_stabilize_mode* mode, uint32_t* levels) {
    if (parse_stabilize(cli_opt(a, "stabilize"), mode, levels)) return 1;
    cli_fail(a, "--stabilize", "expects none|sphere|levels[:N] (N in 1..1000000), got '%s'", cli_opt(a, "stabilize"));
    return 0;
}

/* swtool cascade: split distances, per-split warp, error maxima, atlas place
 * and (with --curve) the whole configuration's error curve.  The error model
 * is Lloyd's overhead-light frame [RHS] (2.3)-(2.8). */
static int cascade_model(sw_args* a) {
    CLI_ACCEPT(a, cascade_model_known);
    double n, f, fovy;
    unsigned K, res, samples, iw, ih;
    if (!cli_double(a, "near", 1.0, &n) || !cli_double(a, "far", 500.0, &f) ||
        !cli_double(a, "fovy", 60.0, &fovy) || !cli_uint(a, "splits", 4, &K) ||
        !cli_map_square(a, 1024, &res) || !cli_uint(a, "samples", 64, &samples) ||
        !cli_size(a, "screen", 1024, 1024, &iw, &ih))
        return CLI_EXIT_USAGE;
    swarp_split_options so;
    memset(&so, 0, sizeof so);
    so.count = K;
    swarp_stabilize_mode smode;
    uint32_t levels;
    if (!cascade_scheme(a, &so) || !cascade_stabilize(a, &smode, &levels)) return CLI_EXIT_USAGE;
    const char* warp = cli_opt(a, "warp");
    int lispsm = warp && strcmp(warp, "lispsm") == 0;
    if (warp && !lispsm && strcmp(warp, "none") != 0)
        return cli_fail(a, "--warp", "expects none|lispsm, got '%s'", warp);
    if (lispsm && smode != SWARP_STABILIZE_NONE)
        return cli_report_status(a, SWARP_ERR_STABILIZE_WARPED, "--stabilize with --warp lispsm");
    if (K == 0 || K > SWARP_SPLIT_MAX_COUNT) return cli_report_status(a, SWARP_ERR_SPLIT_COUNT, "--splits");

    double c[SWARP_SPLIT_MAX_COUNT + 1], np[SWARP_SPLIT_MAX_COUNT];
    double smx[SWARP_SPLIT_MAX_COUNT], smz[SWARP_SPLIT_MAX_COUNT], mx_all, mz_all;
    size_t cnt;
    swarp_status st = swarp_cascade_splits(n, f, &so, c, SWARP_SPLIT_MAX_COUNT + 1, &cnt);
    if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_cascade_splits");
    if (lispsm) {
        st = swarp_cascade_nopt(c, K, so.scheme == SWARP_SCHEME_PSEUDO ? so.pseudo_near : 0.0,
                                so.scheme == SWARP_SCHEME_PSEUDO ? so.pseudo_far : 0.0, np);
        if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_cascade_nopt");
    } else {
        for (unsigned i = 0; i < K; ++i) np[i] = INFINITY;
    }
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = n;
    cfg.z_far = f;
    cfg.theta = 0.5 * fovy * SW_DEG;
    cfg.res_ix = iw > ih ? iw : ih;
    cfg.res_iy = iw > ih ? ih : iw;
    cfg.res_s = cfg.res_t = res;
    st = swarp_error_split_max(&cfg, c, np, K, smx, smz, &mx_all, &mz_all);
    if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_error_split_max");
    swarp_atlas_info info;
    swarp_atlas_tile tiles[SWARP_ATLAS_MAX_SPLITS];
    int have_atlas = K <= SWARP_ATLAS_MAX_SPLITS;
    if (have_atlas) {
        st = swarp_atlas_layout(K, res, SWARP_DEPTH_DEFAULT, &info, tiles, SWARP_ATLAS_MAX_SPLITS, &cnt);
        if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_atlas_layout");
    }
    const int curve = cli_flag(a, "curve");
    static double z[SWARP_SPLIT_MAX_COUNT * 4096], cmx[SWARP_SPLIT_MAX_COUNT * 4096],
        cmz[SWARP_SPLIT_MAX_COUNT * 4096];
    size_t ncurve = 0;
    if (curve) {
        if (samples < 2 || samples > 4096)
            return cli_fail(a, "--samples", "expects 2..4096, got %u", samples);
        st = swarp_cascade_error_curve(&cfg, c, np, K, samples, z, cmx, cmz,
                                       sizeof z / sizeof z[0], &ncurve);
        if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_cascade_error_curve");
    }
    if (a->json) {
        json_begin();
        json_kv_status(SWARP_OK);
        json_kv_arr("splits", c, K + 1);
        json_kv_num("max_mx", mx_all);
        json_kv_num("max_mz", mz_all);
        if (have_atlas) json_kv_num("l_sc", info.l_sc);
        json_key("split");
        json_open_arr();
        for (unsigned i = 0; i < K; ++i) {
            json_open_obj();
            json_kv_num("near", c[i]);
            json_kv_num("far", c[i + 1]);
            json_kv_num("n_prime", np[i]);
            json_kv_num("max_mx", smx[i]);
            json_kv_num("max_mz", smz[i]);
            if (have_atlas) {
                double vp[4] = {tiles[i].viewport_x, tiles[i].viewport_y, tiles[i].viewport_width,
                                tiles[i].viewport_height};
                json_kv_arr("viewport", vp, 4);
                json_kv_mat("clip_to_atlas", &tiles[i].clip_to_atlas);
            }
            json_close_obj();
        }
        json_close_arr();
        if (curve) {
            json_kv_arr("z", z, ncurve);
            json_kv_arr("mx", cmx, ncurve);
            json_kv_arr("mz", cmz, ncurve);
        }
        json_end();
        return 0;
    }
    if (curve) {
        printf("# z m_x m_z   (%u splits; a border depth belongs to the split that starts there)\n", K);
        for (size_t k = 0; k < ncurve; ++k) printf("%.17g %.17g %.17g\n", z[k], cmx[k], cmz[k]);
        return 0;
    }
    printf("split        near          far      n_prime     max m_x     max m_z   atlas viewport\n");
    for (unsigned i = 0; i < K; ++i) {
        printf("%5u %12.6g %12.6g %12.6g %11.5g %11.5g", i, c[i], c[i + 1], np[i], smx[i], smz[i]);
        if (have_atlas)
            printf("   %g,%g %gx%g", tiles[i].viewport_x, tiles[i].viewport_y, tiles[i].viewport_width,
                   tiles[i].viewport_height);
        printf("\n");
    }
    printf("whole: max m_x %.6g, max m_z %.6g", mx_all, mz_all);
    if (have_atlas) printf("; atlas %gx%g, l_sc %g", info.atlas_res, info.atlas_res, info.l_sc);
    printf("\n");
    return 0;
}

/* --warp-per-split ([RHS] §3.4 arbitrary warping): "first" or "first:N0"
 * derives splits 1.. from the first (SWARP_CASCADE_WARP_FROM_FIRST, n'_0 =
 * N0 or the technique's); a list N0,N1,... gives n' per split (EACH). */
static int parse_warp_per_split(const char* s, unsigned K, swarp_cascade_options* o) {
    if (!s) return 1;
    if (strncmp(s, "first", 5) == 0) {
        o->warp_per_split = SWARP_CASCADE_WARP_FROM_FIRST;
        if (s[5] == '\0') return 1;
        return s[5] == ':' && cli_parse_list(s + 6, &o->n_user[0], 1);
    }
    size_t cnt = 1;
    for (const char* c = s; *c; ++c) cnt += *c == ',';
    if (cnt > K || cnt > SWARP_CASCADE_MAX_SPLITS) return 0;
    o->warp_per_split = SWARP_CASCADE_WARP_EACH;
    return cli_parse_list(s, o->n_user, (int)cnt);
}

/* The scene form: camera, light and scene box as for `swtool setup`, then
 * swarp_cascade_setup. */
static int cascade_scene(sw_args* a) {
    CLI_ACCEPT(a, cascade_scene_known);
    swarp_camera cam = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 60.0 * SW_DEG, 16.0 / 9.0, 1.0, 100.0, {0}};
    swarp_light light;
    memset(&light, 0, sizeof light);
    swarp_cascade_options o;
    memset(&o, 0, sizeof o);
    swarp_aabb box;
    double kernel;
    unsigned map, sw, sh, K, samples;
    if (!cli_camera(a, !cli_opt(a, "view"), &cam) || !cli_light(a, 1, &light) || !cli_box(a, 1, &box) ||
        !cli_map_square(a, 1024, &map) || !cli_size(a, "screen", 1920, 1080, &sw, &sh) ||
        !cli_uint(a, "splits", 4, &K) || !cli_double(a, "kernel", 1.0, &kernel) ||
        !cli_uint(a, "samples", 64, &samples) || !cli_vec3(a, "origin", 0, &o.stabilize.origin) ||
        !cli_double(a, "min-depth", 0.0, &o.setup.min_depth) || !cli_depth(a, &o.setup.depth_range))
        return CLI_EXIT_USAGE;
    sw_camera_source src;
    int rc = cli_engine_camera(a, &box, &cam, &src);
    if (rc != CLI_GO) return rc;
    o.setup.map_width = o.setup.map_height = map;
    o.setup.screen_width = sw;
    o.setup.screen_height = sh;
    const char* tech = cli_opt(a, "technique");
    if (!tech || strcmp(tech, "lispsm") == 0) {
        o.setup.technique = SWARP_TECHNIQUE_LISPSM;
    } else if (strcmp(tech, "uniform") == 0) {
        o.setup.technique = SWARP_TECHNIQUE_UNIFORM;
    } else if (strcmp(tech, "repar") == 0) {
        o.setup.technique = SWARP_TECHNIQUE_LISPSM;
        o.setup.param = SWARP_WARP_PARAM_NREPAR;
    } else if (strcmp(tech, "psm") == 0) {
        o.setup.technique = SWARP_TECHNIQUE_PSM;
    } else {
        return cli_fail(a, "--technique", "expects uniform|lispsm|repar|psm (a cascade), got '%s'", tech);
    }
    o.split.count = K;
    if (!cascade_scheme(a, &o.split)) return CLI_EXIT_USAGE;
    if (o.split.scheme == SWARP_SCHEME_PSEUDO && o.setup.technique == SWARP_TECHNIQUE_LISPSM &&
        o.setup.param == SWARP_WARP_PARAM_DEFAULT) {
        /* [RHS] §4.2: the pseudo planes also shape the first and last warps */
        o.setup.param = SWARP_WARP_PARAM_PSEUDO;
        o.setup.pseudo_near = o.split.pseudo_near;
        o.setup.pseudo_far = o.split.pseudo_far;
    }
    uint32_t levels;
    if (!cascade_stabilize(a, &o.stabilize.mode, &levels)) return CLI_EXIT_USAGE;
    o.stabilize.levels = levels;
    o.kernel_world_size = kernel;
    if (!parse_warp_per_split(cli_opt(a, "warp-per-split"), K, &o))
        return cli_fail(a, "--warp-per-split", "expects first[:N0] or N0,N1,... (n' per split, eye units; 0 = the "
                        "technique's, inf = uniform; at most --splits values), got '%s'", cli_opt(a, "warp-per-split"));
    swarp_cascade_result r;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t n;
    swarp_status st = swarp_cascade_setup(&cam, &light, &box, &o, &r, sp, SWARP_CASCADE_MAX_SPLITS, &n);
    if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_cascade_setup");
    static double z[SWARP_CASCADE_MAX_SPLITS * 4096], cmx[SWARP_CASCADE_MAX_SPLITS * 4096],
        cmz[SWARP_CASCADE_MAX_SPLITS * 4096];
    size_t ncurve = 0;
    const int curve = cli_flag(a, "curve");
    if (curve) {
        if (samples < 2 || samples > 4096)
            return cli_fail(a, "--samples", "expects 2..4096, got %u", samples);
        swarp_error_config cfg;
        memset(&cfg, 0, sizeof cfg);
        cfg.z_near = r.view_near;
        cfg.z_far = r.view_far;
        cfg.theta = 0.5 * cam.fovy;
        cfg.res_ix = sw > sh ? sw : sh;
        cfg.res_iy = sw > sh ? sh : sw;
        cfg.res_s = cfg.res_t = map;
        double np[SWARP_CASCADE_MAX_SPLITS];
        for (size_t i = 0; i < n; ++i) np[i] = sp[i].n_eye;
        swarp_status cs = swarp_cascade_error_curve(&cfg, r.splits, np, n, samples, z, cmx, cmz,
                                                    sizeof z / sizeof z[0], &ncurve);
        if (swarp_status_is_error(cs)) return cli_report_status(a, cs, "swarp_cascade_error_curve");
    }
    if (a->json) {
        json_begin();
        json_kv_status(st);
        json_kv_num("near", r.view_near);
        json_kv_num("far", r.view_far);
        json_kv_arr("splits", r.splits, n + 1);
        json_kv_num("max_mx", r.max_mx);
        json_kv_num("max_mz", r.max_mz);
        json_kv_measured(&r.measured);
        json_kv_num("atlas_res", r.atlas.atlas_res);
        json_kv_num("l_sc", r.atlas.l_sc);
        json_kv_camera(&cam, &src);
        json_key("split");
        json_open_arr();
        for (size_t i = 0; i < n; ++i) {
            json_open_obj();
            json_kv_str("status", swarp_status_name(sp[i].status));
            json_kv_num("near", sp[i].z_near);
            json_kv_num("far", sp[i].z_far);
            json_kv_mat("matrix", &sp[i].matrix);
            json_kv_mat("atlas_matrix", &sp[i].atlas_matrix);
            double vp[4] = {sp[i].tile.viewport_x, sp[i].tile.viewport_y, sp[i].tile.viewport_width,
                            sp[i].tile.viewport_height};
            json_kv_arr("viewport", vp, 4);
            json_kv_arr("kernel_scale", sp[i].kernel_scale, 2);
            json_kv_num("n_prime", sp[i].n_eye);
            json_kv_num("max_mx", sp[i].max_mx);
            json_kv_num("max_mz", sp[i].max_mz);
            json_kv_num("mx_start", sp[i].mx_start);
            json_kv_num("mz_start", sp[i].mz_start);
            json_kv_num("texel_size", sp[i].texel_size);
            json_kv_num("depth_per_world", sp[i].depth_per_world);
            json_kv_measured(&sp[i].measured);
            json_close_obj();
        }
        json_close_arr();
        if (curve) {
            json_kv_arr("z", z, ncurve);
            json_kv_arr("mx", cmx, ncurve);
            json_kv_arr("mz", cmz, ncurve);
        }
        json_end();
        return cli_report_status(a, st, "swarp_cascade_setup");
    }
    if (curve) {
        printf("# z m_x m_z   (%zu splits; a border depth belongs to the split that starts there)\n", n);
        for (size_t k = 0; k < ncurve; ++k) printf("%.17g %.17g %.17g\n", z[k], cmx[k], cmz[k]);
        return cli_report_status(a, st, "swarp_cascade_setup");
    }
    printf("status      %s\n", swarp_status_name(st));
    cli_print_camera(&cam, &src);
    printf("view range  [%.9g, %.9g] (adjusted, [RHS] 3.3.1), %zu splits\n", r.view_near, r.view_far, n);
    printf("atlas       %gx%g texels, l_sc %g\n", r.atlas.atlas_res, r.atlas.atlas_res, r.atlas.l_sc);
    printf("whole       model max m_x %.6g, max m_z %.6g (Lloyd, overhead light on the view axis)\n", r.max_mx,
           r.max_mz);
    print_measured("whole ", &r.measured);
    for (size_t i = 0; i < n; ++i) {
        const swarp_cascade_split* q = &sp[i];
        printf("\nsplit %zu     [%.9g, %.9g]  %s\n", i, q->z_near, q->z_far, swarp_status_name(q->status));
        printf("  n'         %.9g\n", q->n_eye);
        printf("  viewport   %g,%g %gx%g\n", q->tile.viewport_x, q->tile.viewport_y, q->tile.viewport_width,
               q->tile.viewport_height);
        printf("  kernel     %.6g, %.6g  (s_i of [RHS] (3.9) for r_l = %g)\n", q->kernel_scale[0],
               q->kernel_scale[1], kernel > 0 ? kernel : 1.0);
        printf("  max m_x    %.6g  (%.6g just after the border)\n", q->max_mx, q->mx_start);
        printf("  max m_z    %.6g  (%.6g just after the border)\n", q->max_mz, q->mz_start);
        if (q->texel_size > 0) printf("  texel      %.9g world units (stabilised)\n", q->texel_size);
        printf("  depth/world %.6g window depth per world unit toward the light\n", q->depth_per_world);
        print_measured("  ", &q->measured);
        print_matrix_rows("  ", "matrix", &q->matrix);
    }
    return cli_report_status(a, st, "swarp_cascade_setup");
}

/* swtool cascade: the scene form when --eye is given, else the error-model
 * form; `swtool setup --splits K ...` lands here too. */
int cmd_cascade(sw_args* a) {
    if (a->help) return cli_usage(a, cascade_model_known, cascade_scene_known);
    if (cli_opt(a, "eye") || cli_opt(a, "view") || cli_opt(a, "proj")) return cascade_scene(a);
    return cascade_model(a);
}
