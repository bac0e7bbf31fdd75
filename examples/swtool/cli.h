/* swtool's small command-line and JSON helpers, shared by the subcommands. */
#ifndef SWTOOL_CLI_H
#define SWTOOL_CLI_H

#include <stdio.h>

/* swtool drives every stage, the experimental ones (follow, lixel, plan,
 * cube, min depth) included */
#ifndef SWARP_EXPERIMENTAL_API
#define SWARP_EXPERIMENTAL_API 1
#endif
#include "shadowwarp.h"

typedef struct sw_args {
    int argc;
    char** argv; /* argv[0] is the subcommand name */
    int json;    /* --json given */
} sw_args;

/* Value after "--name", or NULL.  Marks nothing; unknown options are the
 * subcommand's business (cli_check_known). */
const char* cli_opt(const sw_args* a, const char* name);
int cli_flag(const sw_args* a, const char* name);
/* Each returns 1 on success; on a parse error prints to stderr and returns 0.
 * When the option is absent *out = def (or, if required, an error). */
int cli_double(const sw_args* a, const char* name, double def, double* out);
int cli_double_req(const sw_args* a, const char* name, double* out);
int cli_uint(const sw_args* a, const char* name, unsigned def, unsigned* out);
int cli_vec3(const sw_args* a, const char* name, int required, swarp_vec3* out);
/* "WxH" */
int cli_size(const sw_args* a, const char* name, unsigned defw, unsigned defh, unsigned* w, unsigned* h);
/* Comma-separated list of exactly n doubles. */
int cli_parse_list(const char* s, double* out, int n);
/* Fails (returns 0, message on stderr) if an argument "--x" is not in the
 * NULL-terminated list of known option names (without dashes).  --json is
 * always known. */
int cli_check_known(const sw_args* a, const char* const* known);

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

/* Prints the status to stderr (table mode) or as JSON; returns the process
 * exit code for it (0 for OK and informational, 1 for errors). */
int cli_report_status(const sw_args* a, swarp_status s, const char* what);

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
