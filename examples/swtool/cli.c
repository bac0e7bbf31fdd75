#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* ---- every option of every command, one spelling and one format -------- */

typedef struct sw_optdef {
    const char* name;
    int has_arg;        /* required_argument or no_argument */
    const char* format; /* of the value, for --help */
    const char* what;
} sw_optdef;

static const sw_optdef cli_options[] = {
    {"eye", required_argument, "X,Y,Z", "camera position (world)"},
    {"dir", required_argument, "X,Y,Z", "camera view direction"},
    {"up", required_argument, "X,Y,Z", "camera up vector"},
    {"fovy", required_argument, "DEG", "full vertical field of view, degrees"},
    {"aspect", required_argument, "A", "width / height"},
    {"near", required_argument, "N", "view near distance"},
    {"far", required_argument, "F|inf", "view far distance (inf: bounded by --box)"},
    {"view", required_argument, "16 NUMBERS", "engine camera: world -> view matrix"},
    {"proj", required_argument, "16 NUMBERS", "engine camera: view -> clip projection"},
    {"proj-convention", required_argument, "rh|lh|rh-t|lh-t", "storage and handedness of --view/--proj"},
    {"proj-depth", required_argument, "gl|zo", "the engine API's clip depth: gl [-1,1], zo [0,1]"},
    {"light-dir", required_argument, "X,Y,Z", "directional light: the direction light travels"},
    {"light-pos", required_argument, "X,Y,Z", "point light position"},
    {"light", required_argument, "X,Y,Z,W", "post-projective (homogeneous) light position"},
    {"box", required_argument, "X0,Y0,Z0,X1,Y1,Z1", "scene box S: min corner, max corner"},
    {"map", required_argument, "N|WxH", "shadow-map resolution, texels (N = NxN)"},
    {"screen", required_argument, "WxH", "screen resolution, pixels"},
    {"technique", required_argument, "NAME", "warp technique"},
    {"depth", required_argument, "gl|zo|rev", "light's clip depth: gl [-1,1], zo [0,1], rev reversed-Z [1,0]"},
    {"reps", required_argument, "N", "timing repetitions (the median is printed)"},
    {"min-depth", required_argument, "D", "[RHS] 4.3 measured minimum view depth"},
    {"prev-view", required_argument, "16 NUMBERS", "previous frame's light_view (column-major)"},
    {"prev-proj", required_argument, "16 NUMBERS", "previous frame's light_proj (column-major)"},
    {"prev-range", required_argument, "NEAR,FAR,NP", "previous frame's view range and n'"},
    {"prev-dir", required_argument, "X,Y,Z", "previous frame's camera direction"},
    {"splits", required_argument, "K", "split count"},
    {"scheme", required_argument, "NAME", "split scheme"},
    {"stabilize", required_argument, "none|sphere|levels[:N]", "stabilisation mode"},
    {"origin", required_argument, "X,Y,Z", "stabilisation origin"},
    {"kernel", required_argument, "W", "filter kernel world size"},
    {"curve", no_argument, NULL, "print the error curve"},
    {"samples", required_argument, "N", "curve samples"},
    {"warp-per-split", required_argument, "first[:N0]|N0,N1,..", "n' per split"},
    {"warp", required_argument, "none|lispsm", "warp of every split"},
    {"matrix", required_argument, "16 NUMBERS", "world -> light clip matrix, column-major"},
    {"points", required_argument, "FILE", "points file, lines 'x y z nx ny nz' (- = stdin)"},
    {"gamma", required_argument, "DEG", "angle between light and view direction, degrees"},
    {"np", required_argument, "X", "pseudo-near plane, fraction of the depth range"},
    {"fp", required_argument, "X", "pseudo-far plane, fraction of the depth range"},
    {"gammas", required_argument, "DEG,DEG,..", "light angles of the report"},
    {"steps", required_argument, "N", "frames of the walk"},
    {"speed", required_argument, "S", "camera motion per frame"},
    {"turn", required_argument, "RAD", "total camera turn"},
    {"levels", required_argument, "N", "stabilisation levels"},
    {"moves", no_argument, NULL, "the camera moves (planner)"},
    {"clamp", no_argument, NULL, "depth clamping is allowed (planner)"},
    {"soft", required_argument, "W", "soft shadows of width W (planner)"},
    {"bleed", required_argument, "none|low|high|extreme", "light-bleeding risk (planner)"},
    {"plane", required_argument, "A,B,C,D", "plane of interest a x + b y + c z + d = 0"},
    {"plane2", required_argument, "A,B,C,D", "second plane of interest"},
    {"plane3", required_argument, "A,B,C,D", "third plane of interest"},
    {"plane4", required_argument, "A,B,C,D", "fourth plane of interest"},
    {"max-error", required_argument, "E", "error budget, screen pixels per texel"},
    {"atlas", required_argument, "N", "atlas size limit, texels"},
    {"max-passes", required_argument, "N", "shadow-pass limit"},
    {"time-ms", required_argument, "MS", "time budget"},
    {"pass-ms", required_argument, "MS", "cost of one shadow pass"},
    {"blur-ms", required_argument, "MS", "cost of one blur pass"},
    {"force", required_argument, "WARP", "evaluate this chain instead of planning"},
    {"out-dir", required_argument, "DIR", "write the report's files under DIR"},
    {"demo-data", required_argument, "FILE", "demo measurements to fold in"},
    {"clone-data", required_argument, "FILE", "demo geometry-cloning TSV to fold in"},
    {"z1", required_argument, "Z", "cube-map near distance Z_1"},
    {"point", required_argument, "X,Y,Z", "point to look up"},
    {"min", required_argument, "D", "minimum linear view depth"},
    {"file", required_argument, "FILE", "raw float32 linear depths, row-major"},
    {"size", required_argument, "WxH", "size of --file, pixels"},
    {"margin", required_argument, "M", "safety margin of the adjusted near plane"},
    {"twist-line", required_argument, "9 NUMBERS", "line A, B and a point below it"},
    {"scale", required_argument, "S", "lixels per viewer pixel"},
    {"extent", required_argument, "E", "half-size of the plane square"},
    {"plane-depth", required_argument, "D", "depth of the plane in the factorisation"},
    {"json", no_argument, NULL, "print one JSON object"},
    {"help", no_argument, NULL, "print this help and exit"},
};
#define CLI_OPTION_COUNT (sizeof cli_options / sizeof cli_options[0])
/* getopt_long's val of option i: above every char, so that a mistake's
 * optopt tells a known option (>= CLI_VAL0) from an unknown one (0) */
#define CLI_VAL0 256

static const sw_optdef* cli_find(const char* name) {
    for (size_t i = 0; i < CLI_OPTION_COUNT; ++i)
        if (strcmp(cli_options[i].name, name) == 0) return &cli_options[i];
    return NULL;
}

int cli_fail(const sw_args* a, const char* option, const char* fmt, ...) {
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (option)
        fprintf(stderr, "swtool %s: %s: %s\n", a->argv[0], option, msg);
    else
        fprintf(stderr, "swtool %s: %s\n", a->argv[0], msg);
    if (a->json) {
        json_begin();
        json_kv_str("status", "SWTOOL_ERR_USAGE");
        json_kv_str("message", msg);
        if (option) json_kv_str("option", option);
        json_end();
    }
    return CLI_EXIT_USAGE;
}

/* The option text as typed, up to '=', equals --name: abbreviations, which
 * getopt_long would accept, are refused so that adding an option never
 * changes what an existing command line means. */
static int cli_spelled_out(const char* typed, const char* name) {
    size_t n = strlen(name);
    return strncmp(typed, "--", 2) == 0 && strncmp(typed + 2, name, n) == 0 &&
           (typed[2 + n] == '\0' || typed[2 + n] == '=');
}

static int cli_record(sw_args* a, const char* name, const char* value) {
    for (int i = 0; i < a->given_count; ++i)
        if (strcmp(a->given[i].name, name) == 0)
            return cli_fail(a, NULL, "--%s given twice%s%s%s%s%s: give each option at most once", name,
                            a->given[i].value ? " ('" : "", a->given[i].value ? a->given[i].value : "",
                            value ? "' and '" : "", value ? value : "", a->given[i].value ? "')" : "");
    if (a->given_count >= CLI_MAX_GIVEN) return cli_fail(a, NULL, "too many options");
    a->given[a->given_count].name = name;
    a->given[a->given_count].value = value;
    ++a->given_count;
    if (strcmp(name, "help") == 0) a->help = 1;
    return CLI_GO;
}

static int cli_mistake(sw_args* a, int c, const char* typed) {
    const char* known = optopt >= CLI_VAL0 ? cli_options[optopt - CLI_VAL0].name : NULL;
    if (c == ':' && known) {
        const sw_optdef* d = &cli_options[optopt - CLI_VAL0];
        return cli_fail(a, NULL, "--%s needs a value (%s)", d->name, d->format);
    }
    if (known && strchr(typed, '=')) return cli_fail(a, NULL, "--%s takes no value, got '%s'", known, typed);
    return cli_fail(a, NULL, "unknown option '%s' (swtool %s --help lists the options)", typed, a->argv[0]);
}

int cli_parse(sw_args* a) {
    struct option longopts[CLI_OPTION_COUNT + 1];
    for (size_t i = 0; i < CLI_OPTION_COUNT; ++i)
        longopts[i] = (struct option){cli_options[i].name, cli_options[i].has_arg, NULL, (int)(CLI_VAL0 + i)};
    longopts[CLI_OPTION_COUNT] = (struct option){NULL, 0, NULL, 0};
    /* --json decides how every outcome, a mistake found below included, is
     * printed, so it is known before parsing */
    for (int i = 1; i < a->argc; ++i)
        if (strcmp(a->argv[i], "--json") == 0) a->json = 1;
    opterr = 0;
    optind = 1;
    for (;;) {
        int before = optind;
        /* '+': stop at the first non-option (reported below, not reordered);
         * ':': a missing value returns ':' */
        int c = getopt_long(a->argc, a->argv, "+:h", longopts, NULL);
        if (c == -1) break;
        const char* typed = before < a->argc ? a->argv[before] : "";
        if (c == 'h') c = (int)(CLI_VAL0 + CLI_OPTION_COUNT - 1);
        if (c == '?' || c == ':') return cli_mistake(a, c, typed);
        const sw_optdef* d = &cli_options[c - CLI_VAL0];
        if (strcmp(typed, "-h") != 0 && !cli_spelled_out(typed, d->name))
            return cli_fail(a, NULL, "'%s': spell the option out (--%s)", typed, d->name);
        int rc = cli_record(a, d->name, d->has_arg ? optarg : NULL);
        if (rc != CLI_GO) return rc;
    }
    if (optind < a->argc)
        return cli_fail(a, NULL, "unexpected argument '%s' (every value belongs to an option)", a->argv[optind]);
    return CLI_GO;
}

static int cli_in(const char* name, const char* const* list) {
    for (const char* const* k = list; k && *k; ++k)
        if (strcmp(name, *k) == 0) return 1;
    return 0;
}

static void cli_usage_text(FILE* f, const sw_args* a, const char* const* k1, const char* const* k2) {
    fprintf(f, "usage: swtool %s [OPTION...]\n%s\n\noptions (--opt VALUE or --opt=VALUE; each at most once):\n",
            a->argv[0], a->summary ? a->summary : "");
    for (size_t i = 0; i < CLI_OPTION_COUNT; ++i) {
        const sw_optdef* d = &cli_options[i];
        int always = strcmp(d->name, "json") == 0 || strcmp(d->name, "help") == 0;
        if (!always && !cli_in(d->name, k1) && !cli_in(d->name, k2)) continue;
        char left[64];
        snprintf(left, sizeof left, "--%s%s%s", d->name, d->format ? " " : "", d->format ? d->format : "");
        fprintf(f, "  %-34s %s\n", left, d->what);
    }
    fprintf(f, "\nExit status: 0 success, 1 library error, 2 command-line mistake.\n"
               "docs/swtool.md and swtool(1) document every command.\n");
}

int cli_usage(const sw_args* a, const char* const* known, const char* const* known2) {
    if (!a->json) {
        cli_usage_text(stdout, a, known, known2);
        return CLI_EXIT_OK;
    }
    char* text = NULL;
    size_t len = 0;
    FILE* f = open_memstream(&text, &len);
    if (!f) return CLI_EXIT_LIBRARY;
    cli_usage_text(f, a, known, known2);
    fclose(f);
    json_begin();
    json_kv_status(SWARP_OK);
    json_kv_str("usage", text);
    json_end();
    free(text);
    return CLI_EXIT_OK;
}

int cli_accept(const sw_args* a, const char* const* known) {
    if (a->help) return cli_usage(a, known, NULL);
    for (int i = 0; i < a->given_count; ++i) {
        const char* n = a->given[i].name;
        if (strcmp(n, "json") == 0 || cli_in(n, known)) continue;
        return cli_fail(a, NULL, "swtool %s takes no --%s (swtool %s --help lists its options)", a->argv[0], n,
                        a->argv[0]);
    }
    return CLI_GO;
}

const char* cli_opt(const sw_args* a, const char* name) {
    for (int i = 0; i < a->given_count; ++i)
        if (strcmp(a->given[i].name, name) == 0) return a->given[i].value;
    return NULL;
}

int cli_flag(const sw_args* a, const char* name) {
    for (int i = 0; i < a->given_count; ++i)
        if (strcmp(a->given[i].name, name) == 0) return 1;
    return 0;
}

/* ---- values ------------------------------------------------------------- */

static int parse_double(const char* s, double* out) {
    char* end = NULL;
    errno = 0;
    double v = strtod(s, &end);
    /* ERANGE on underflow still gives the nearest double (or a subnormal); only
     * overflow, which strtod turns into +-HUGE_VAL, is a mistake */
    if (end == s || *end != '\0' || (errno == ERANGE && isinf(v))) return 0;
    *out = v;
    return 1;
}

int cli_double(const sw_args* a, const char* name, double def, double* out) {
    const char* s = cli_opt(a, name);
    if (!s) {
        *out = def;
        return 1;
    }
    if (!parse_double(s, out)) {
        char opt[64];
        snprintf(opt, sizeof opt, "--%s", name);
        cli_fail(a, opt, "expects a number, got '%s'", s);
        return 0;
    }
    return 1;
}

int cli_double_req(const sw_args* a, const char* name, double* out) {
    if (!cli_opt(a, name)) {
        cli_fail(a, NULL, "--%s is required (%s)", name, cli_find(name) ? cli_find(name)->format : "value");
        return 0;
    }
    return cli_double(a, name, 0.0, out);
}

static int parse_uint(const char* s, unsigned* out) {
    char* end = NULL;
    errno = 0;
    unsigned long v = strtoul(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v > 0xFFFFFFFFul || s[0] == '-' || s[0] == '+' ||
        s[0] == ' ')
        return 0;
    *out = (unsigned)v;
    return 1;
}

int cli_uint(const sw_args* a, const char* name, unsigned def, unsigned* out) {
    const char* s = cli_opt(a, name);
    if (!s) {
        *out = def;
        return 1;
    }
    if (!parse_uint(s, out)) {
        char opt[64];
        snprintf(opt, sizeof opt, "--%s", name);
        cli_fail(a, opt, "expects a whole number 0..4294967295, got '%s'", s);
        return 0;
    }
    return 1;
}

int cli_parse_list(const char* s, double* out, int n) {
    char buf[1024];
    size_t len = strlen(s);
    if (len >= sizeof buf) return 0;
    memcpy(buf, s, len + 1);
    int k = 0;
    /* empty fields ("1,,2", a trailing comma) are mistakes: strtok_r would
     * skip them silently */
    if (len == 0 || buf[0] == ',' || buf[len - 1] == ',' || strstr(buf, ",,")) return 0;
    char* save = NULL;
    for (char* tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (k >= n || !parse_double(tok, &out[k])) return 0;
        ++k;
    }
    return k == n;
}

int cli_list(const sw_args* a, const char* name, int n, const char* what, double* out) {
    const char* s = cli_opt(a, name);
    if (!s) return 1;
    if (!cli_parse_list(s, out, n)) {
        char opt[64];
        snprintf(opt, sizeof opt, "--%s", name);
        cli_fail(a, opt, "expects %d comma-separated numbers (%s), got '%s'", n, what, s);
        return 0;
    }
    return 1;
}

int cli_vec3(const sw_args* a, const char* name, int required, swarp_vec3* out) {
    const char* s = cli_opt(a, name);
    if (!s) {
        if (required) cli_fail(a, NULL, "--%s X,Y,Z is required", name);
        return !required;
    }
    double v[3];
    if (!cli_list(a, name, 3, "X,Y,Z", v)) return 0;
    out->x = v[0];
    out->y = v[1];
    out->z = v[2];
    return 1;
}

static int parse_size(const char* s, unsigned* w, unsigned* h) {
    const char* x = strchr(s, 'x');
    if (!x || x == s || x - s >= 16) return 0;
    char first[16];
    memcpy(first, s, (size_t)(x - s));
    first[x - s] = '\0';
    return parse_uint(first, w) && parse_uint(x + 1, h) && *w > 0 && *h > 0;
}

int cli_size(const sw_args* a, const char* name, unsigned defw, unsigned defh, unsigned* w, unsigned* h) {
    const char* s = cli_opt(a, name);
    if (!s) {
        *w = defw;
        *h = defh;
        return 1;
    }
    if (!parse_size(s, w, h)) {
        char opt[64];
        snprintf(opt, sizeof opt, "--%s", name);
        cli_fail(a, opt, "expects WxH (two whole numbers > 0, e.g. 1920x1080), got '%s'", s);
        return 0;
    }
    return 1;
}

int cli_map(const sw_args* a, unsigned def, unsigned* w, unsigned* h) {
    const char* s = cli_opt(a, "map");
    if (!s) {
        *w = *h = def;
        return 1;
    }
    if (parse_size(s, w, h)) return 1;
    if (parse_uint(s, w) && *w > 0) {
        *h = *w;
        return 1;
    }
    cli_fail(a, "--map", "expects N or WxH (whole numbers > 0, e.g. 2048 or 2048x1024), got '%s'", s);
    return 0;
}

int cli_map_square(const sw_args* a, unsigned def, unsigned* r) {
    unsigned w, h;
    if (!cli_map(a, def, &w, &h)) return 0;
    if (w != h) {
        cli_fail(a, "--map", "swtool %s needs a square map (N or NxN), got '%s'", a->argv[0], cli_opt(a, "map"));
        return 0;
    }
    *r = w;
    return 1;
}

int cli_box(const sw_args* a, int required, swarp_aabb* out) {
    double v[6];
    if (!cli_opt(a, "box")) {
        if (required) cli_fail(a, NULL, "--box X0,Y0,Z0,X1,Y1,Z1 is required (the scene box: min, max)");
        return !required;
    }
    if (!cli_list(a, "box", 6, "X0,Y0,Z0,X1,Y1,Z1: min corner, max corner", v)) return 0;
    out->min = (swarp_vec3){v[0], v[1], v[2]};
    out->max = (swarp_vec3){v[3], v[4], v[5]};
    return 1;
}

int cli_depth(const sw_args* a, swarp_depth_range* out) {
    const char* d = cli_opt(a, "depth");
    if (!d || strcmp(d, "gl") == 0) {
        *out = SWARP_DEPTH_NEG_ONE_TO_ONE;
        return 1;
    }
    if (strcmp(d, "zo") == 0) {
        *out = SWARP_DEPTH_ZERO_TO_ONE;
        return 1;
    }
    if (strcmp(d, "rev") == 0) {
        *out = SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
        return 1;
    }
    cli_fail(a, "--depth", "expects gl ([-1, 1]), zo ([0, 1]) or rev (reversed-Z: near 1, far 0), got '%s'", d);
    return 0;
}

/* Below this sine of the angle between --dir and --up no right vector
 * survives the rounding; the library refuses the same (swarp_camera). */
#define SW_CLI_PARALLEL_SIN 1e-9

int cli_camera(const sw_args* a, int required_eye_dir, swarp_camera* cam) {
    double fovy_deg = cam->fovy / SW_DEG;
    if (!cli_vec3(a, "eye", required_eye_dir, &cam->eye) || !cli_vec3(a, "dir", required_eye_dir, &cam->dir) ||
        !cli_vec3(a, "up", 0, &cam->up) || !cli_double(a, "fovy", fovy_deg, &fovy_deg) ||
        !cli_double(a, "aspect", cam->aspect, &cam->aspect) || !cli_double(a, "near", cam->z_near, &cam->z_near) ||
        !cli_double(a, "far", cam->z_far, &cam->z_far))
        return 0;
    cam->fovy = fovy_deg * SW_DEG;
    const swarp_vec3 d = cam->dir, u = cam->up;
    swarp_vec3 c = {d.y * u.z - d.z * u.y, d.z * u.x - d.x * u.z, d.x * u.y - d.y * u.x};
    double lc = sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
    double ld = sqrt(d.x * d.x + d.y * d.y + d.z * d.z), lu = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    if (ld > 0 && lu > 0 && isfinite(ld * lu) && !(lc > SW_CLI_PARALLEL_SIN * ld * lu)) {
        cli_fail(a, "--dir", "%.17g,%.17g,%.17g is parallel to --up %.17g,%.17g,%.17g%s: the camera has no right "
                 "vector", d.x, d.y, d.z, u.x, u.y, u.z, cli_opt(a, "up") ? "" : " (the default)");
        return 0;
    }
    return 1;
}

/* ---- a camera given as engine matrices, an infinite far plane ---------- */

static int cli_convention(const sw_args* a, swarp_matrix_convention* out) {
    static const struct {
        const char* name;
        swarp_matrix_convention c;
    } names[] = {{"rh", SWARP_MATRIX_RH}, {"lh", SWARP_MATRIX_LH}, {"rh-t", SWARP_MATRIX_RH_TRANSPOSED},
                 {"lh-t", SWARP_MATRIX_LH_TRANSPOSED}};
    const char* s = cli_opt(a, "proj-convention");
    if (!s) {
        *out = SWARP_MATRIX_RH;
        return 1;
    }
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (strcmp(s, names[i].name) == 0) {
            *out = names[i].c;
            return 1;
        }
    cli_fail(a, "--proj-convention", "expects rh, lh, rh-t or lh-t (right-/left-handed, -t: row-major), got '%s'", s);
    return 0;
}

/* The camera's own view and an infinite-far OpenGL projection, column-major,
 * right-handed: x_ndc = sx x/-z, y_ndc = sy y/-z, z_ndc = 1 - 2 n/-z
 * (A = -1: the far end reached only at infinity). */
static void cli_infinite_matrices(const swarp_camera* cam, swarp_mat4* V, swarp_mat4* P) {
    swarp_vec3 f = cam->dir, u = cam->up;
    double lf = sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
    f = (swarp_vec3){f.x / lf, f.y / lf, f.z / lf};
    swarp_vec3 s = {f.y * u.z - f.z * u.y, f.z * u.x - f.x * u.z, f.x * u.y - f.y * u.x};
    double ls = sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    s = (swarp_vec3){s.x / ls, s.y / ls, s.z / ls};
    u = (swarp_vec3){s.y * f.z - s.z * f.y, s.z * f.x - s.x * f.z, s.x * f.y - s.y * f.x};
    const swarp_vec3 e = cam->eye;
    memset(V, 0, sizeof *V);
    memset(P, 0, sizeof *P);
    const swarp_vec3 rows[3] = {s, u, {-f.x, -f.y, -f.z}};
    for (int r = 0; r < 3; ++r) {
        V->m[r] = rows[r].x, V->m[4 + r] = rows[r].y, V->m[8 + r] = rows[r].z;
        V->m[12 + r] = -(rows[r].x * e.x + rows[r].y * e.y + rows[r].z * e.z);
    }
    V->m[15] = 1.0;
    const double sy = 1.0 / tan(0.5 * cam->fovy);
    P->m[0] = sy / cam->aspect;
    P->m[5] = sy;
    P->m[10] = -1.0;
    P->m[11] = -1.0;
    P->m[14] = -2.0 * cam->z_near;
}

static int cli_view_proj(const sw_args* a, const swarp_aabb* box, swarp_camera* cam, sw_camera_source* src) {
    static const char* const camera_opts[] = {"eye", "dir", "up", "fovy", "aspect", "near", "far"};
    for (size_t i = 0; i < sizeof camera_opts / sizeof camera_opts[0]; ++i)
        if (cli_opt(a, camera_opts[i])) {
            char opt[32];
            snprintf(opt, sizeof opt, "--%s", camera_opts[i]);
            return cli_fail(a, opt, "the camera is given by --view and --proj: drop --%s", camera_opts[i]);
        }
    if (!cli_opt(a, "view") || !cli_opt(a, "proj"))
        return cli_fail(a, cli_opt(a, "view") ? "--proj" : "--view", "an engine camera needs both --view and --proj");
    swarp_mat4 V, P;
    swarp_matrix_convention conv;
    swarp_depth_range dr = SWARP_DEPTH_NEG_ONE_TO_ONE;
    const char* d = cli_opt(a, "proj-depth");
    if (d && strcmp(d, "zo") == 0) dr = SWARP_DEPTH_ZERO_TO_ONE;
    else if (d && strcmp(d, "gl") != 0)
        return cli_fail(a, "--proj-depth", "expects gl ([-1, 1]) or zo ([0, 1]; forward or reversed), got '%s'", d);
    if (!cli_list(a, "view", 16, "world -> view matrix", V.m) || !cli_list(a, "proj", 16, "projection matrix", P.m) ||
        !cli_convention(a, &conv))
        return CLI_EXIT_USAGE;
    src->from_matrices = 1;
    src->status = swarp_camera_from_matrices(&V, &P, conv, dr, box, cam, &src->info);
    if (swarp_status_is_error(src->status)) return cli_report_status(a, src->status, "swarp_camera_from_matrices");
    src->far_from_box = src->info.infinite_far != 0;
    return CLI_GO;
}

int cli_engine_camera(const sw_args* a, const swarp_aabb* box, swarp_camera* cam, sw_camera_source* src) {
    memset(src, 0, sizeof *src);
    if (cli_opt(a, "view") || cli_opt(a, "proj")) return cli_view_proj(a, box, cam, src);
    if (cli_opt(a, "proj-convention") || cli_opt(a, "proj-depth")) {
        const char* o = cli_opt(a, "proj-convention") ? "--proj-convention" : "--proj-depth";
        return cli_fail(a, o, "describes --view and --proj, which are not given");
    }
    if (!(isinf(cam->z_far) && cam->z_far > 0)) return CLI_GO;
    /* --far inf: the library's bound for an infinite engine far plane, the
     * largest view depth of the scene box (swarp_camera_from_matrices, [RHS]
     * §3.3.1), from the camera's own matrices; eye, dir, up, fovy, aspect
     * and near stay the values given */
    swarp_mat4 V, P;
    swarp_camera bounded;
    cli_infinite_matrices(cam, &V, &P);
    src->status = swarp_camera_from_matrices(&V, &P, SWARP_MATRIX_RH, SWARP_DEPTH_NEG_ONE_TO_ONE, box, &bounded,
                                             &src->info);
    if (swarp_status_is_error(src->status)) return cli_report_status(a, src->status, "swarp_camera_from_matrices");
    cam->z_far = bounded.z_far;
    src->far_from_box = 1;
    return CLI_GO;
}

void json_kv_camera(const swarp_camera* cam, const sw_camera_source* src) {
    json_kv_str("camera_from", src->from_matrices ? "matrices" : "options");
    json_kv_str("camera_far_from", src->far_from_box ? "scene_box" : (src->from_matrices ? "matrices" : "far"));
    json_kv_num("camera_near", cam->z_near);
    json_kv_num("camera_far", cam->z_far);
    if (src->from_matrices) {
        const double e[3] = {cam->eye.x, cam->eye.y, cam->eye.z}, d[3] = {cam->dir.x, cam->dir.y, cam->dir.z},
                     u[3] = {cam->up.x, cam->up.y, cam->up.z};
        json_kv_arr("camera_eye", e, 3);
        json_kv_arr("camera_dir", d, 3);
        json_kv_arr("camera_up", u, 3);
        json_kv_num("camera_fovy_deg", cam->fovy / SW_DEG);
        json_kv_num("camera_aspect", cam->aspect);
        json_kv_num("camera_reversed_z", src->info.reversed_z);
    }
}

void cli_print_camera(const swarp_camera* cam, const sw_camera_source* src) {
    if (src->from_matrices)
        printf("camera      from --view/--proj: eye %.9g,%.9g,%.9g dir %.9g,%.9g,%.9g fovy %.6g deg aspect %.6g%s\n",
               cam->eye.x, cam->eye.y, cam->eye.z, cam->dir.x, cam->dir.y, cam->dir.z, cam->fovy / SW_DEG,
               cam->aspect, src->info.reversed_z ? ", reversed-Z" : "");
    printf("camera far  %.9g (%s)\n", cam->z_far,
           src->far_from_box ? "infinite far plane, bounded by the scene box" : "given");
}

int cli_light(const sw_args* a, int required, swarp_light* light) {
    const char* ld = cli_opt(a, "light-dir");
    const char* lp = cli_opt(a, "light-pos");
    if (ld && lp) {
        cli_fail(a, NULL, "give one of --light-dir X,Y,Z and --light-pos X,Y,Z, not both");
        return 0;
    }
    if (!ld && !lp) {
        if (required) cli_fail(a, NULL, "a light is required: --light-dir X,Y,Z or --light-pos X,Y,Z");
        return !required;
    }
    if (ld) {
        light->type = SWARP_LIGHT_DIRECTIONAL;
        light->position = (swarp_vec3){0, 0, 0};
        return cli_vec3(a, "light-dir", 1, &light->direction);
    }
    light->type = SWARP_LIGHT_POINT;
    light->direction = (swarp_vec3){0, 0, 0};
    return cli_vec3(a, "light-pos", 1, &light->position);
}

/* ---- JSON ------------------------------------------------------------- */
static int json_need_comma[64];
static int json_depth;
static int json_after_key;

static void json_sep(void) {
    if (json_after_key) {
        json_after_key = 0;
        return;
    }
    if (json_depth > 0 && json_need_comma[json_depth]) fputs(", ", stdout);
    if (json_depth > 0) json_need_comma[json_depth] = 1;
}
static void json_push(char c) {
    json_sep();
    putchar(c);
    if (json_depth < 63) ++json_depth;
    json_need_comma[json_depth] = 0;
}
static void json_pop(char c) {
    putchar(c);
    if (json_depth > 0) --json_depth;
}
void json_begin(void) {
    json_depth = 0;
    json_after_key = 0;
    json_push('{');
}
void json_end(void) {
    json_pop('}');
    putchar('\n');
}
void json_open_obj(void) { json_push('{'); }
void json_close_obj(void) { json_pop('}'); }
void json_open_arr(void) { json_push('['); }
void json_close_arr(void) { json_pop(']'); }
void json_str(const char* s) {
    json_sep();
    putchar('"');
    for (; *s; ++s) {
        if (*s == '"' || *s == '\\') putchar('\\');
        if ((unsigned char)*s < 0x20)
            printf("\\u%04x", (unsigned)(unsigned char)*s);
        else
            putchar(*s);
    }
    putchar('"');
}
void json_key(const char* key) {
    json_str(key);
    fputs(": ", stdout);
    json_after_key = 1;
}
void json_num(double v) {
    json_sep();
    if (isfinite(v))
        printf("%.17g", v);
    else
        fputs("null", stdout);
}
void json_kv_num(const char* key, double v) {
    json_key(key);
    json_num(v);
}
void json_kv_str(const char* key, const char* s) {
    json_key(key);
    json_str(s);
}
void json_kv_status(swarp_status s) {
    json_kv_str("status", swarp_status_name(s));
    json_kv_str("message", swarp_status_string(s));
}
void json_kv_arr(const char* key, const double* v, size_t n) {
    json_key(key);
    json_open_arr();
    for (size_t i = 0; i < n; ++i) json_num(v[i]);
    json_close_arr();
}
void json_kv_mat(const char* key, const swarp_mat4* m) { json_kv_arr(key, m->m, 16); }

void json_kv_measured(const swarp_measured_error* e) {
    json_key("measured");
    json_open_obj();
    json_kv_num("max_m_s", e->max_m_s);
    json_kv_num("max_m_t", e->max_m_t);
    json_kv_num("max_sigma", e->max_sigma);
    json_kv_arr("at", (const double[]){e->at.x, e->at.y, e->at.z}, 3);
    json_kv_num("samples", e->samples);
    json_kv_num("outside", e->outside);
    json_close_obj();
}

void print_matrix_rows(const char* indent, const char* label, const swarp_mat4* m) {
    printf("%s%s (rows of the matrix; the JSON and C arrays are column-major):\n", indent, label);
    for (int row = 0; row < 4; ++row)
        printf("%s  %14.8g %14.8g %14.8g %14.8g\n", indent, m->m[row], m->m[4 + row], m->m[8 + row],
               m->m[12 + row]);
}

void print_measured(const char* indent, const swarp_measured_error* e) {
    if (e->samples == 0) {
        printf("%smeasured    not measured\n", indent);
        return;
    }
    printf("%smeasured    max m_s %.6g, max m_t %.6g, max sigma %.6g at (%.6g, %.6g, %.6g); %u samples, %u "
           "outside the map\n",
           indent, e->max_m_s, e->max_m_t, e->max_sigma, e->at.x, e->at.y, e->at.z, e->samples, e->outside);
}

/* ---- library statuses and the inputs they depend on --------------------- */

typedef struct sw_blame {
    swarp_status status;
    const char* options; /* space-separated, without dashes */
} sw_blame;

/* The options each error status can come from (the library's checks,
 * include/shadowwarp.h); a status not listed depends on every input. */
static const sw_blame cli_blames[] = {
    {SWARP_ERR_NEAR_FAR, "near far min-depth min"},
    {SWARP_ERR_FOV, "fovy"},
    {SWARP_ERR_RESOLUTION, "map screen size"},
    {SWARP_ERR_ZERO_VECTOR, "dir up light-dir"},
    {SWARP_ERR_DEGENERATE, "dir up eye light-dir light-pos box plane matrix"},
    {SWARP_ERR_SPLIT_COUNT, "splits"},
    {SWARP_ERR_NOT_INCREASING, "near far splits scheme"},
    {SWARP_ERR_SINGULAR, "matrix dir up light-dir light-pos view proj"},
    {SWARP_ERR_BODY_EMPTY, "box eye dir near far view proj"},
    {SWARP_ERR_BOX_INVERTED, "box"},
    {SWARP_ERR_BOX_DEGENERATE, "box"},
    {SWARP_ERR_LIGHT_INSIDE_BODY, "light-pos box"},
    {SWARP_ERR_FOLLOW_FRAME, "prev-view prev-proj prev-range prev-dir"},
    {SWARP_ERR_CAMERA_NOT_PERSPECTIVE, "fovy aspect near far proj proj-convention"},
    {SWARP_ERR_CAMERA_MIRRORED, "dir up view proj proj-convention"},
    {SWARP_ERR_CAMERA_VIEW_NOT_RIGID, "dir up view proj-convention"},
    {SWARP_ERR_CAMERA_FAR_UNBOUNDED, "far proj box"},
    {SWARP_ERR_ATLAS_SPLITS, "splits"},
    {SWARP_ERR_STABILIZE_WARPED, "stabilize warp technique"},
    {SWARP_ERR_STABILIZE_LIGHT, "stabilize light-pos"},
    {SWARP_ERR_BEHIND_PROJECTION, "light-pos light-dir"},
    {SWARP_ERR_SPLIT_EMPTY, "box splits scheme near far"},
    {SWARP_ERR_PLAN_TOO_MANY_PLANES, "plane plane2 plane3 plane4"},
    {SWARP_ERR_PLAN_EMPTY_VIEW, "box eye dir near far"},
    {SWARP_ERR_CUBE_LIGHT_AT_INFINITY, "light"},
    {SWARP_ERR_CUBE_POINT_UNCOVERED, "light point"},
    {SWARP_ERR_LIXEL_COPLANAR, "plane eye dir light-pos light-dir"},
    {SWARP_ERR_LIXEL_PLANE_THROUGH_EYE, "plane eye"},
    {SWARP_ERR_LIXEL_LIGHT_ON_PLANE, "plane light-pos"},
    {SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE, "plane light-dir"},
    {SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE, "plane eye dir near far"},
    {SWARP_ERR_LIXEL_RAY_OUTSIDE, "plane eye dir"},
    {SWARP_ERR_LIXEL_RECT_TOO_LARGE, "scale extent screen"},
    {SWARP_ERR_LIXEL_TWIST_LINE, "twist-line"},
    {SWARP_ERR_LIXEL_EMPTY, "plane extent eye dir"},
};

static int cli_word_in(const char* name, const char* words) {
    size_t n = strlen(name);
    for (const char* w = words; (w = strstr(w, name)) != NULL; w += n)
        if ((w == words || w[-1] == ' ') && (w[n] == ' ' || w[n] == '\0')) return 1;
    return 0;
}

static int cli_non_finite_text(const char* v) {
    for (const char* c = v; c && *c; ++c)
        if (strncmp(c, "nan", 3) == 0 || strncmp(c, "NAN", 3) == 0 || strncmp(c, "inf", 3) == 0 ||
            strncmp(c, "INF", 3) == 0 || strncmp(c, "Inf", 3) == 0 || strncmp(c, "NaN", 3) == 0)
            return 1;
    return 0;
}

/* Whether given option i is one status s depends on. */
static int cli_blamed(const sw_args* a, int i, swarp_status s) {
    const sw_given* g = &a->given[i];
    if (!g->value) return 0;
    if (s == SWARP_ERR_NON_FINITE) return cli_non_finite_text(g->value);
    for (size_t k = 0; k < sizeof cli_blames / sizeof cli_blames[0]; ++k)
        if (cli_blames[k].status == s) return cli_word_in(g->name, cli_blames[k].options);
    return 1;
}

void cli_status_fields(const sw_args* a, swarp_status s, const char* what) {
    json_kv_status(s);
    json_kv_str("where", what);
    if (!swarp_status_is_error(s)) return;
    json_key("inputs");
    json_open_arr();
    char buf[1200];
    for (int i = 0; i < a->given_count; ++i)
        if (cli_blamed(a, i, s)) {
            snprintf(buf, sizeof buf, "--%s %s", a->given[i].name, a->given[i].value);
            json_str(buf);
        }
    json_close_arr();
}

int cli_report_status(const sw_args* a, swarp_status s, const char* what) {
    if (a->json && swarp_status_is_error(s)) {
        json_begin();
        cli_status_fields(a, s, what);
        json_end();
    } else if (s != SWARP_OK) {
        fprintf(stderr, "swtool %s: %s: %s (%s)", a->argv[0], what, swarp_status_string(s), swarp_status_name(s));
        if (swarp_status_is_error(s)) {
            int any = 0;
            for (int i = 0; i < a->given_count; ++i)
                if (cli_blamed(a, i, s)) {
                    fprintf(stderr, "%s --%s %s", any ? "" : "; from", a->given[i].name, a->given[i].value);
                    any = 1;
                }
            if (!any) fprintf(stderr, "; from the defaults (swtool %s --help)", a->argv[0]);
        }
        fputc('\n', stderr);
    }
    return swarp_status_is_error(s) ? CLI_EXIT_LIBRARY : CLI_EXIT_OK;
}
