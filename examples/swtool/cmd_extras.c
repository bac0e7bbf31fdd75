/* swtool cube, swtool mindepth: the extras that need no renderer
 * ([KOZ] §14.2.2 cube-map faces; [RHS] §4.3 min-depth near plane). */
#define _POSIX_C_SOURCE 200809L
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

static const char* const cube_face_names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};

int cmd_cube(sw_args* a) {
    static const char* const known[] = {"light", "z1", "depth", "point", NULL};
    CLI_ACCEPT(a, known);
    double L4[4];
    swarp_cube_options opt;
    memset(&opt, 0, sizeof opt);
    swarp_vec3 V = {0, 0, 0};
    int have_point = cli_opt(a, "point") != NULL;
    if (!cli_opt(a, "light"))
        return cli_fail(a, NULL, "--light X,Y,Z,W (post-projective, homogeneous) is required");
    if (!cli_list(a, "light", 4, "X,Y,Z,W: post-projective, homogeneous", L4) ||
        !cli_double(a, "z1", 0.0, &opt.z1) || !cli_vec3(a, "point", 0, &V) || !cli_depth(a, &opt.depth_range))
        return CLI_EXIT_USAGE;
    swarp_vec4 L = {L4[0], L4[1], L4[2], L4[3]};
    swarp_cube_face faces[SWARP_CUBE_MAX_FACES];
    size_t n = 0;
    swarp_status s = swarp_cube_faces(&L, &opt, faces, SWARP_CUBE_MAX_FACES, &n);
    if (s != SWARP_OK) return cli_report_status(a, s, "swarp_cube_faces [KOZ] 14.2.2");
    uint32_t face = 0;
    swarp_vec3 S = {0, 0, 0};
    double depth = 0;
    swarp_status ps = SWARP_OK;
    if (have_point) {
        ps = swarp_cube_lookup(&L, &opt, &V, &face, &S, &depth);
        if (swarp_status_is_error(ps)) return cli_report_status(a, ps, "swarp_cube_lookup [KOZ] Listing 14-1");
    }
    if (a->json) {
        json_begin();
        json_kv_status(SWARP_OK);
        json_kv_arr("light_point", (double[]){L.x / L.w, L.y / L.w, L.z / L.w}, 3);
        json_kv_num("inverse", L.w < 0 ? 1 : 0);
        json_key("faces");
        json_open_arr();
        for (size_t i = 0; i < n; ++i) {
            json_open_obj();
            json_kv_str("face", cube_face_names[faces[i].face]);
            json_kv_num("distance", faces[i].distance);
            json_kv_mat("view", &faces[i].view);
            json_kv_mat("proj", &faces[i].proj);
            json_kv_mat("view_proj", &faces[i].view_proj);
            json_close_obj();
        }
        json_close_arr();
        if (have_point) {
            json_key("lookup");
            json_open_obj();
            json_kv_str("status", swarp_status_name(ps));
            json_kv_str("face", cube_face_names[face]);
            json_kv_arr("texcoord", (double[]){S.x, S.y, S.z}, 3);
            json_kv_num("depth", depth);
            json_close_obj();
        }
        json_end();
        return 0;
    }
    printf("light P = (%g, %g, %g)%s, %zu faces (Z_1 = %g)\n", L.x / L.w, L.y / L.w, L.z / L.w,
           L.w < 0 ? " [inverse projection: w < 0]" : "", n, opt.z1 > 0 ? opt.z1 : 0.01);
    for (size_t i = 0; i < n; ++i) {
        printf("face %s  d = %.17g\n", cube_face_names[faces[i].face], faces[i].distance);
        print_matrix_rows("  ", "view_proj", &faces[i].view_proj);
    }
    if (have_point)
        printf("point (%g, %g, %g): face %s, texcoord (%.17g, %.17g, %.17g), depth %.17g  %s\n", V.x, V.y, V.z,
               cube_face_names[face], S.x, S.y, S.z, depth, ps == SWARP_OK ? "" : swarp_status_name(ps));
    return 0;
}

/* Reads the W x H float32 depths of --file into a new buffer; NULL after
 * reporting the mistake.  The file must be a regular file holding exactly
 * W H 4 bytes: the size is checked (for overflow too) before anything is
 * allocated, so a wrong --size cannot make swtool allocate or read more
 * than the file holds. */
static float* mindepth_read(const sw_args* a, const char* file, unsigned w, unsigned h) {
    if ((size_t)w > SIZE_MAX / sizeof(float) / h) {
        cli_fail(a, "--size", "%ux%u floats do not fit in memory addresses", w, h);
        return NULL;
    }
    size_t count = (size_t)w * h, bytes = count * sizeof(float);
    FILE* fp = fopen(file, "rb");
    struct stat st;
    if (!fp || fstat(fileno(fp), &st) != 0) {
        if (fp) fclose(fp);
        cli_fail(a, "--file", "cannot open '%s'", file);
        return NULL;
    }
    if (!S_ISREG(st.st_mode) || (uintmax_t)st.st_size != (uintmax_t)bytes) {
        fclose(fp);
        if (!S_ISREG(st.st_mode))
            cli_fail(a, "--file", "'%s' is not a regular file (its size must be known: W H 4 bytes)", file);
        else
            cli_fail(a, "--file", "'%s' holds %jd bytes; --size %ux%u needs %zu (W H float32)", file,
                     (intmax_t)st.st_size, w, h, bytes);
        return NULL;
    }
    float* buf = malloc(bytes);
    size_t got = buf ? fread(buf, sizeof *buf, count, fp) : 0;
    fclose(fp);
    if (!buf || got != count) {
        free(buf);
        cli_fail(a, "--file", "cannot read %zu floats from '%s'", count, file);
        return NULL;
    }
    return buf;
}

/* Raw little-endian float32 file of W x H linear depths (row-major), e.g. a
 * glReadPixels of a linear depth target. */
int cmd_mindepth(sw_args* a) {
    static const char* const known[] = {"near", "far", "min", "file", "size", "margin", NULL};
    CLI_ACCEPT(a, known);
    double n, f, margin = 0.0, mn = 0.0;
    unsigned w = 0, h = 0;
    const char* file = cli_opt(a, "file");
    if (!cli_double_req(a, "near", &n) || !cli_double_req(a, "far", &f) ||
        !cli_double(a, "margin", 0.0, &margin) || !cli_size(a, "size", 0, 0, &w, &h))
        return CLI_EXIT_USAGE;
    if (file && cli_opt(a, "min")) return cli_fail(a, NULL, "give --min D or --file FILE --size WxH, not both");
    if (!file && !cli_double_req(a, "min", &mn)) return CLI_EXIT_USAGE;
    if (file && !cli_opt(a, "size")) return cli_fail(a, "--file", "needs --size WxH");
    if (!file && cli_opt(a, "size")) return cli_fail(a, "--size", "is the size of --file, which is not given");
    double direct = NAN;
    size_t scratch_n = 0;
    swarp_status s;
    if (file) {
        float* buf = mindepth_read(a, file, w, h);
        if (!buf) return CLI_EXIT_USAGE;
        /* SWARP_MINDEPTH_SCRATCH <= count / 4 + w + h: no overflow once count fits */
        float* scratch = malloc(SWARP_MINDEPTH_SCRATCH(w, h) * sizeof *scratch);
        if (!scratch) {
            free(buf);
            return cli_report_status(a, SWARP_ERR_CAPACITY, "scratch buffer");
        }
        s = swarp_mindepth_pyramid(buf, w, h, w, scratch, SWARP_MINDEPTH_SCRATCH(w, h), &scratch_n, &mn);
        if (!swarp_status_is_error(s)) s = swarp_mindepth_direct(buf, w, h, w, &direct);
        free(buf), free(scratch);
        if (swarp_status_is_error(s)) return cli_report_status(a, s, "min-depth reduction [RHS] Listing A.2");
    }
    swarp_mindepth_options opt;
    memset(&opt, 0, sizeof opt);
    opt.margin = margin;
    double near_adj = 0;
    s = swarp_mindepth_near(n, f, mn, &opt, &near_adj);
    if (swarp_status_is_error(s)) return cli_report_status(a, s, "adjusted near [RHS] 4.3");
    if (a->json) {
        json_begin();
        json_kv_status(s);
        json_kv_num("min_depth", mn);
        if (file) json_kv_num("min_depth_direct", direct);
        json_kv_num("near", n);
        json_kv_num("adjusted_near", near_adj);
        json_end();
        return 0;
    }
    printf("min depth %.9g%s -> adjusted near %.9g (near %g, far %g)%s%s\n", mn,
           file ? " (2x2 min pyramid, [RHS] Listing A.2)" : "", near_adj, n, f, s == SWARP_OK ? "" : "  ",
           s == SWARP_OK ? "" : swarp_status_name(s));
    return 0;
}
