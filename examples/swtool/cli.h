/* swtool's command-line and JSON helpers, shared by the subcommands.
 *
 * Conventions (docs/swtool.md, swtool(1)): options are long options parsed
 * by getopt_long, `--opt value` and `--opt=value` alike, spelled in full;
 * each option at most once (a repeated option is an error); no positional
 * arguments.  Every command-line mistake exits 2 with a message naming the
 * option; a library error exits 1 and names the call and the inputs it
 * depends on; with --json every outcome is exactly one JSON object with
 * "status". */
#ifndef SWTOOL_CLI_H
#define SWTOOL_CLI_H

#include <stdio.h>

/* swtool drives every stage, the experimental ones (follow, lixel, plan,
 * cube, min depth) included */
#ifndef SWARP_EXPERIMENTAL_API
#define SWARP_EXPERIMENTAL_API 1
#endif
#include "shadowwarp.h"

/* More options than any command takes (plan, the largest, takes 32). */
#define CLI_MAX_GIVEN 64

typedef struct sw_given {
    const char* name;  /* without the dashes */
    const char* value; /* NULL for a flag */
} sw_given;

typedef struct sw_args {
    int argc;
    char** argv;         /* argv[0] is the subcommand name */
    const char* summary; /* the command's one-line description, for --help */
    int json;            /* --json given */
    int help;            /* --help given, or `swtool help CMD` */
    int given_count;
    sw_given given[CLI_MAX_GIVEN];
} sw_args;

/* Exit codes of the conventions above. */
#define CLI_EXIT_OK 0
#define CLI_EXIT_LIBRARY 1
#define CLI_EXIT_USAGE 2
/* cli_accept: go on with the command */
#define CLI_GO (-1)

/* Parses a->argv with getopt_long against every option swtool has; fills
 * a->given.  Returns CLI_GO, or CLI_EXIT_USAGE after reporting the mistake. */
int cli_parse(sw_args* a);
/* The command's own check: every given option must be in the NULL-terminated
 * list `known` (names without dashes; --json and --help are always known).
 * With --help prints the command's usage and returns CLI_EXIT_OK; on an
 * option the command does not take returns CLI_EXIT_USAGE; else CLI_GO. */
int cli_accept(const sw_args* a, const char* const* known);
/* Usage of a command taking the union of two option lists (known2 may be NULL). */
int cli_usage(const sw_args* a, const char* const* known, const char* const* known2);
#define CLI_ACCEPT(a, known)                    \
    do {                                        \
        int cli_rc_ = cli_accept((a), (known)); \
        if (cli_rc_ != CLI_GO) return cli_rc_;  \
    } while (0)

/* Prints "swtool CMD: --option: message" to stderr, or under --json the one
 * object {"status": "SWTOOL_ERR_USAGE", "message", "option"}; returns
 * CLI_EXIT_USAGE.  option may be NULL. */
int cli_fail(const sw_args* a, const char* option, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Value of --name, or NULL. */
const char* cli_opt(const sw_args* a, const char* name);
int cli_flag(const sw_args* a, const char* name);
/* Each returns 1 on success; on a mistake it reports it (cli_fail) and
 * returns 0, and the caller returns CLI_EXIT_USAGE.  When the option is
 * absent *out = def, or, for the _req forms and required = 1, a mistake. */
int cli_double(const sw_args* a, const char* name, double def, double* out);
int cli_double_req(const sw_args* a, const char* name, double* out);
int cli_uint(const sw_args* a, const char* name, unsigned def, unsigned* out);
int cli_vec3(const sw_args* a, const char* name, int required, swarp_vec3* out);
/* "WxH", both > 0 */
int cli_size(const sw_args* a, const char* name, unsigned defw, unsigned defh, unsigned* w, unsigned* h);
/* --map: "N" (N x N) or "WxH", the same format in every command */
int cli_map(const sw_args* a, unsigned def, unsigned* w, unsigned* h);
/* --map for a command whose library call takes one resolution: N or NxN */
int cli_map_square(const sw_args* a, unsigned def, unsigned* r);
/* --name: exactly n comma-separated numbers; what names them in the message */
int cli_list(const sw_args* a, const char* name, int n, const char* what, double* out);
/* --box x0,y0,z0,x1,y1,z1 */
int cli_box(const sw_args* a, int required, swarp_aabb* out);
/* --depth gl|zo */
int cli_depth(const sw_args* a, swarp_depth_range* out);
/* The camera options --eye --dir --up --fovy (degrees) --aspect --near --far
 * over the defaults in *cam (fovy in radians there); --eye and --dir are
 * required when required_eye_dir. */
int cli_camera(const sw_args* a, int required_eye_dir, swarp_camera* cam);
/* How the camera came about (for the output). */
typedef struct sw_camera_source {
    int from_matrices;           /* --view/--proj: swarp_camera_from_matrices */
    int far_from_box;            /* the far plane was infinite: z_far bounded by --box */
    swarp_status status;         /* swarp_camera_from_matrices' (SWARP_OK if not called) */
    swarp_camera_from_info info; /* what it recognised */
} sw_camera_source;
/* After cli_camera and cli_box: an engine camera (--view, --proj,
 * --proj-convention, --proj-depth) through swarp_camera_from_matrices, or
 * --far inf bounded by the scene box the way that function bounds an
 * infinite engine far plane.  Returns CLI_GO, or the exit status after
 * reporting a mistake (2) or the library's error (1). */
int cli_engine_camera(const sw_args* a, const swarp_aabb* box, swarp_camera* cam, sw_camera_source* src);
/* The camera keys of the JSON object / the text lines. */
void json_kv_camera(const swarp_camera* cam, const sw_camera_source* src);
void cli_print_camera(const swarp_camera* cam, const sw_camera_source* src);
/* Exactly one of --light-dir and --light-pos (required = 0: at most one;
 * *light is left as given when neither is). */
int cli_light(const sw_args* a, int required, swarp_light* light);
/* Comma-separated list of exactly n doubles. */
int cli_parse_list(const char* s, double* out, int n);

#define SW_DEG (3.14159265358979323846 / 180.0)

/* --- JSON output: one object on stdout; numbers with 17 significant digits,
 *     non-finite numbers as null. ---------------------------------------- */
void json_begin(void);                 /* { */
void json_end(void);                   /* }\n */
void json_key(const char* key);        /* "key": (with comma management) */
void json_num(double v);
void json_str(const char* s);
void json_open_obj(void);              /* { as a value */
void json_close_obj(void);
void json_open_arr(void);              /* [ as a value */
void json_close_arr(void);
void json_kv_num(const char* key, double v);
void json_kv_str(const char* key, const char* s);
void json_kv_status(swarp_status s);  /* "status": "SWARP_OK", "message": ... */
void json_kv_arr(const char* key, const double* v, size_t n);
void json_kv_mat(const char* key, const swarp_mat4* m);
/* "measured": {"max_m_s", "max_m_t", "max_sigma", "at", "samples", "outside"} */
void json_kv_measured(const swarp_measured_error* e);

/* Text output of a matrix: its four rows (m[4 c + r] is row r, column c; the
 * array is column-major, the print is the matrix as written on paper). */
void print_matrix_rows(const char* indent, const char* label, const swarp_mat4* m);
void print_measured(const char* indent, const swarp_measured_error* e);

/* Reports a status of `what` (a library call).  Errors: to stderr (table
 * mode) or as the one JSON object, naming the inputs the status depends on;
 * informational statuses: to stderr in table mode only.  Returns the exit
 * code (0 for OK and informational, 1 for errors). */
int cli_report_status(const sw_args* a, swarp_status s, const char* what);
/* The same fields into a JSON object the caller has open (and closes). */
void cli_status_fields(const sw_args* a, swarp_status s, const char* what);

/* --- subcommands: int cmd_x(sw_args*) returns the exit code ------------- */
int cmd_params(sw_args* a);
int cmd_curve(sw_args* a);
int cmd_report(sw_args* a);
int cmd_measure(sw_args* a);
/* stage: geometry */
int cmd_setup(sw_args* a);

/* stage: lixel */
int cmd_lixel(sw_args* a);

/* stage: splits */
int cmd_stabwalk(sw_args* a);
int cmd_cascade(sw_args* a);

/* stage: plan */
int cmd_plan(sw_args* a);
int cmd_bench_report(sw_args* a);

/* stage: extras */
int cmd_cube(sw_args* a);
int cmd_mindepth(sw_args* a);

#endif
