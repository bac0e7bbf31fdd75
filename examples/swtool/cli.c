#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char* cli_opt(const sw_args* a, const char* name) {
    for (int i = 1; i + 1 < a->argc; ++i)
        if (a->argv[i][0] == '-' && a->argv[i][1] == '-' && strcmp(a->argv[i] + 2, name) == 0)
            return a->argv[i + 1];
    return NULL;
}

int cli_flag(const sw_args* a, const char* name) {
    for (int i = 1; i < a->argc; ++i)
        if (a->argv[i][0] == '-' && a->argv[i][1] == '-' && strcmp(a->argv[i] + 2, name) == 0) return 1;
    return 0;
}

static int parse_double(const char* s, double* out) {
    char* end = NULL;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE) return 0;
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
        fprintf(stderr, "swtool: --%s expects a number, got '%s'\n", name, s);
        return 0;
    }
    return 1;
}

int cli_double_req(const sw_args* a, const char* name, double* out) {
    if (!cli_opt(a, name)) {
        fprintf(stderr, "swtool: --%s is required\n", name);
        return 0;
    }
    return cli_double(a, name, 0.0, out);
}

int cli_uint(const sw_args* a, const char* name, unsigned def, unsigned* out) {
    const char* s = cli_opt(a, name);
    if (!s) {
        *out = def;
        return 1;
    }
    char* end = NULL;
    errno = 0;
    unsigned long v = strtoul(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v > 0xFFFFFFFFul || s[0] == '-') {
        fprintf(stderr, "swtool: --%s expects a whole number, got '%s'\n", name, s);
        return 0;
    }
    *out = (unsigned)v;
    return 1;
}

int cli_parse_list(const char* s, double* out, int n) {
    char buf[512];
    size_t len = strlen(s);
    if (len >= sizeof buf) return 0;
    memcpy(buf, s, len + 1);
    int k = 0;
    char* save = NULL;
    for (char* tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (k >= n || !parse_double(tok, &out[k])) return 0;
        ++k;
    }
    return k == n;
}

int cli_vec3(const sw_args* a, const char* name, int required, swarp_vec3* out) {
    const char* s = cli_opt(a, name);
    if (!s) {
        if (required) fprintf(stderr, "swtool: --%s x,y,z is required\n", name);
        return !required;
    }
    double v[3];
    if (!cli_parse_list(s, v, 3)) {
        fprintf(stderr, "swtool: --%s expects x,y,z, got '%s'\n", name, s);
        return 0;
    }
    out->x = v[0];
    out->y = v[1];
    out->z = v[2];
    return 1;
}

int cli_size(const sw_args* a, const char* name, unsigned defw, unsigned defh, unsigned* w, unsigned* h) {
    const char* s = cli_opt(a, name);
    if (!s) {
        *w = defw;
        *h = defh;
        return 1;
    }
    unsigned ww = 0, hh = 0;
    char tail = 0;
    if (sscanf(s, "%ux%u%c", &ww, &hh, &tail) != 2 || ww == 0 || hh == 0) {
        fprintf(stderr, "swtool: --%s expects WxH, got '%s'\n", name, s);
        return 0;
    }
    *w = ww;
    *h = hh;
    return 1;
}

int cli_check_known(const sw_args* a, const char* const* known) {
    for (int i = 1; i < a->argc; ++i) {
        const char* s = a->argv[i];
        if (s[0] != '-' || s[1] != '-') continue;
        /* a negative number as a value is not an option */
        if (s[2] >= '0' && s[2] <= '9') continue;
        if (strcmp(s + 2, "json") == 0) continue;
        int ok = 0;
        for (const char* const* k = known; *k; ++k)
            if (strcmp(s + 2, *k) == 0) ok = 1;
        if (!ok) {
            fprintf(stderr, "swtool %s: unknown option '%s'\n", a->argv[0], s);
            return 0;
        }
    }
    return 1;
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

int cli_report_status(const sw_args* a, swarp_status s, const char* what) {
    if (a->json && swarp_status_is_error(s)) {
        json_begin();
        json_kv_status(s);
        json_kv_str("where", what);
        json_end();
    } else if (s != SWARP_OK) {
        fprintf(stderr, "swtool %s: %s: %s (%s)\n", a->argv[0], what, swarp_status_string(s),
                swarp_status_name(s));
    }
    return swarp_status_is_error(s) ? 1 : 0;
}
