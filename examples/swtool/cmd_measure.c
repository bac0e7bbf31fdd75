/* swtool measure: the measured error of a world -> light-clip matrix at
 * receiver points (swarp_measure_points).  docs/swtool.md, "measure". */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* Points held at most: the file is read in blocks of this many. */
#define MEASURE_BLOCK 256

static int read_camera(sw_args* a, swarp_camera* cam) {
    memset(cam, 0, sizeof *cam);
    double fovy_deg = 60.0;
    if (!cli_vec3(a, "eye", 1, &cam->eye) || !cli_vec3(a, "dir", 1, &cam->dir)) return 0;
    cam->up = (swarp_vec3){0, 1, 0};
    if (!cli_vec3(a, "up", 0, &cam->up)) return 0;
    if (!cli_double(a, "fovy", 60.0, &fovy_deg) || !cli_double(a, "aspect", 16.0 / 9.0, &cam->aspect) ||
        !cli_double(a, "near", 1.0, &cam->z_near) || !cli_double(a, "far", 100.0, &cam->z_far))
        return 0;
    cam->fovy = fovy_deg * SW_DEG;
    return 1;
}

/* Reads up to MEASURE_BLOCK lines "x y z nx ny nz"; returns the count, or
 * -1 (with a message naming the line) on a malformed line. */
static int read_block(FILE* f, const char* path, long* line, swarp_vec3* p, swarp_vec3* n) {
    char buf[512];
    int k = 0;
    while (k < MEASURE_BLOCK && fgets(buf, sizeof buf, f)) {
        ++*line;
        char* s = buf;
        while (*s == ' ' || *s == '\t') ++s;
        if (*s == '\n' || *s == '#' || *s == '\0') continue;
        char tail;
        if (sscanf(s, "%lf %lf %lf %lf %lf %lf %c", &p[k].x, &p[k].y, &p[k].z, &n[k].x, &n[k].y,
                   &n[k].z, &tail) != 6) {
            fprintf(stderr, "swtool measure: %s:%ld: expected 'x y z nx ny nz'\n", path, *line);
            return -1;
        }
        ++k;
    }
    return k;
}

static void print_point(const sw_args* a, const swarp_texel_error* e) {
    if (a->json) {
        json_open_obj();
        json_kv_num("m_s", e->m_s);
        json_kv_num("m_t", e->m_t);
        json_kv_num("sigma", e->sigma);
        json_key("inside");
        json_num((e->flags & SWARP_TEXEL_INSIDE) ? 1 : 0);
        json_close_obj();
    } else {
        printf("%14.6g %14.6g %14.6g  %s%s\n", e->m_s, e->m_t, e->sigma,
               (e->flags & SWARP_TEXEL_INSIDE) ? "inside" : "outside",
               (e->flags & SWARP_TEXEL_BEHIND_EYE) ? " behind-eye"
               : (e->flags & SWARP_TEXEL_SINGULAR) ? " singular" : "");
    }
}

static swarp_status measure_file(sw_args* a, FILE* f, const char* path, const swarp_camera* cam,
                                 const swarp_mat4* m, const swarp_measure_res* res, int* bad) {
    swarp_vec3 p[MEASURE_BLOCK], n[MEASURE_BLOCK];
    swarp_texel_error e[MEASURE_BLOCK];
    swarp_status result = SWARP_OK;
    long line = 0;
    int k;
    while ((k = read_block(f, path, &line, p, n)) > 0) {
        swarp_status s = swarp_measure_points(cam, m, res, p, n, (size_t)k, e);
        if (swarp_status_is_error(s)) return s;
        if (s != SWARP_OK) result = s;
        for (int i = 0; i < k; ++i) print_point(a, &e[i]);
    }
    *bad = k < 0;
    return result;
}

int cmd_measure(sw_args* a) {
    static const char* const known[] = {"eye", "dir", "up", "fovy", "aspect", "near", "far",
                                        "matrix", "map", "screen", "points", NULL};
    if (!cli_check_known(a, known)) return 2;
    swarp_camera cam;
    if (!read_camera(a, &cam)) return 2;
    swarp_mat4 m;
    const char* ms = cli_opt(a, "matrix");
    if (!ms || !cli_parse_list(ms, m.m, 16)) {
        fprintf(stderr, "swtool measure: --matrix takes 16 numbers (column-major world -> light clip)\n");
        return 2;
    }
    unsigned map = 2048, sw = 1920, sh = 1080;
    if (!cli_uint(a, "map", 2048, &map) || !cli_size(a, "screen", 1920, 1080, &sw, &sh)) return 2;
    const swarp_measure_res res = {sw, sh, map, map};
    const char* path = cli_opt(a, "points");
    if (!path) {
        fprintf(stderr, "swtool measure: --points FILE is required (lines 'x y z nx ny nz')\n");
        return 2;
    }
    FILE* f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (!f) {
        fprintf(stderr, "swtool measure: cannot open --points '%s'\n", path);
        return 2;
    }
    if (a->json) {
        json_begin();
        json_key("points");
        json_open_arr();
    } else {
        printf("%14s %14s %14s  %s\n", "m_s", "m_t", "sigma", "in map");
    }
    int bad = 0;
    swarp_status s = measure_file(a, f, path, &cam, &m, &res, &bad);
    if (f != stdin) fclose(f);
    if (a->json) {
        json_close_arr();
        json_kv_status(bad ? SWARP_ERR_INVALID_ARGUMENT : s);
        json_end();
    }
    if (bad) return 2;
    if (swarp_status_is_error(s) && !a->json) return cli_report_status(a, s, "swarp_measure_points");
    return swarp_status_is_error(s) ? 1 : 0;
}
