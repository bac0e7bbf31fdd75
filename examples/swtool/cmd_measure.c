/* swtool measure: the measured error of a world -> light-clip matrix at
 * receiver points (swarp_measure_points).  docs/swtool.md, "measure". */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* Points held at most: the file is read in blocks of this many. */
#define MEASURE_BLOCK 256

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
        if (strchr(s, '\n') == NULL && !feof(f)) {
            fprintf(stderr, "swtool measure: --points %s:%ld: line longer than %zu bytes\n", path, *line,
                    sizeof buf - 1);
            return -1;
        }
        if (sscanf(s, "%lf %lf %lf %lf %lf %lf %c", &p[k].x, &p[k].y, &p[k].z, &n[k].x, &n[k].y,
                   &n[k].z, &tail) != 6) {
            fprintf(stderr, "swtool measure: --points %s:%ld: expected 'x y z nx ny nz'\n", path, *line);
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
                                 const swarp_mat4* m, const swarp_measure_res* res, long* bad_line) {
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
    *bad_line = k < 0 ? line : 0;
    return result;
}

int cmd_measure(sw_args* a) {
    static const char* const known[] = {"eye", "dir", "up", "fovy", "aspect", "near", "far",
                                        "matrix", "map", "screen", "points", NULL};
    CLI_ACCEPT(a, known);
    swarp_camera cam = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 60.0 * SW_DEG, 16.0 / 9.0, 1.0, 100.0, {0}};
    swarp_mat4 m;
    unsigned mw, mh, sw, sh;
    if (!cli_camera(a, 1, &cam) || !cli_map(a, 2048, &mw, &mh) || !cli_size(a, "screen", 1920, 1080, &sw, &sh))
        return CLI_EXIT_USAGE;
    if (!cli_opt(a, "matrix"))
        return cli_fail(a, NULL, "--matrix is required (16 numbers, column-major world -> light clip)");
    if (!cli_list(a, "matrix", 16, "column-major world -> light clip", m.m)) return CLI_EXIT_USAGE;
    const swarp_measure_res res = {sw, sh, mw, mh};
    const char* path = cli_opt(a, "points");
    if (!path) return cli_fail(a, NULL, "--points FILE is required (lines 'x y z nx ny nz'; - = stdin)");
    FILE* f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (!f) return cli_fail(a, "--points", "cannot open '%s'", path);
    if (a->json) {
        json_begin();
        json_key("points");
        json_open_arr();
    } else {
        printf("%14s %14s %14s  %s\n", "m_s", "m_t", "sigma", "in map");
    }
    long bad_line = 0;
    swarp_status s = measure_file(a, f, path, &cam, &m, &res, &bad_line);
    if (f != stdin) fclose(f);
    char where[1100];
    snprintf(where, sizeof where, "--points %s:%ld", path, bad_line);
    if (a->json) {
        json_close_arr();
        if (bad_line) {
            json_kv_str("status", "SWTOOL_ERR_USAGE");
            json_kv_str("message", "a line of the points file is not 'x y z nx ny nz'");
            json_kv_str("option", where);
        } else {
            cli_status_fields(a, s, "swarp_measure_points");
        }
        json_end();
        if (bad_line) return CLI_EXIT_USAGE;
        return swarp_status_is_error(s) ? CLI_EXIT_LIBRARY : CLI_EXIT_OK;
    }
    if (bad_line) return CLI_EXIT_USAGE;
    return cli_report_status(a, s, "swarp_measure_points");
}
