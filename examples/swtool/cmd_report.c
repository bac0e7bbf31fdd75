/* swtool report: the project's main job until the renderer lands.  For the
 * default configuration (n = 1, f = 100, Theta = 30 deg, 1024^2 map,
 * 1024x768 screen) and gamma = 90, 60, 45, 30, 20, 10, 5 degrees: each
 * technique's parameter and the exact maxima of Lloyd's m_x and m_z
 * ([RHS] (2.3)-(2.8)).  How a parameter becomes the model's n' is in
 * docs/parameters.md ("From a technique to n'"). */
#include <math.h>
#include <stdlib.h>

#include "cli.h"
#include "core_tech.h"

#define REPORT_MAX_GAMMAS 32

/* comma-separated degrees, 1..REPORT_MAX_GAMMAS values */
static int parse_gammas(const char* s, double* out, int* count) {
    for (int k = 1; k <= REPORT_MAX_GAMMAS; ++k)
        if (cli_parse_list(s, out, k)) {
            *count = k;
            return 1;
        }
    return 0;
}

int cmd_report(sw_args* a) {
    static const char* const known[] = {"near", "far", "fovy", "screen", "map", "gammas", NULL};
    double n, f, fovy_deg;
    unsigned sw, sh, mw, mh;
    double gammas[REPORT_MAX_GAMMAS] = {90, 60, 45, 30, 20, 10, 5};
    int ng = 7;
    CLI_ACCEPT(a, known);
    if (!cli_double(a, "near", 1.0, &n) || !cli_double(a, "far", 100.0, &f) ||
        !cli_double(a, "fovy", 60.0, &fovy_deg) || !cli_size(a, "screen", 1024, 768, &sw, &sh) ||
        !cli_map(a, 1024, &mw, &mh))
        return CLI_EXIT_USAGE;
    const char* gl = cli_opt(a, "gammas");
    if (gl && !parse_gammas(gl, gammas, &ng))
        return cli_fail(a, "--gammas", "expects 1..%d comma-separated degrees, got '%s'", REPORT_MAX_GAMMAS, gl);
    for (int g = 0; g < ng; ++g)
        if (!(gammas[g] >= 0.0 && gammas[g] <= 180.0))
            return cli_fail(a, "--gammas", "expects degrees in [0, 180], got %g", gammas[g]);
    double theta = 0.5 * fovy_deg * SW_DEG;
    swarp_error_config cfg = {n, f, theta, sw, sh, mw, mh, {0}};

    typedef struct row {
        double gamma_deg;
        sw_tech tech;
        sw_tech_result r;
        double max_mx, max_mz;
    } row;
    row rows[REPORT_MAX_GAMMAS * TECH_COUNT];
    int nr = 0;
    for (int g = 0; g < ng; ++g) {
        double gamma = (gammas[g] > 90.0 ? 180.0 - gammas[g] : gammas[g]) * SW_DEG;
        for (int t = 0; t < TECH_COUNT; ++t) {
            row* r = &rows[nr++];
            r->gamma_deg = gammas[g];
            r->tech = (sw_tech)t;
            swarp_status s = tech_eval((sw_tech)t, n, f, theta, gamma, &r->r);
            if (s != SWARP_OK) return cli_report_status(a, s, tech_name((sw_tech)t));
            s = swarp_error_max(&cfg, r->r.n_prime, &r->max_mx, &r->max_mz);
            if (s != SWARP_OK) return cli_report_status(a, s, "error maxima [RHS] (2.3)-(2.8)");
        }
    }

    if (a->json) {
        json_begin();
        json_kv_status(SWARP_OK);
        json_key("config");
        json_open_obj();
        json_kv_num("near", n);
        json_kv_num("far", f);
        json_kv_num("fovy_deg", fovy_deg);
        json_kv_num("theta", theta);
        json_kv_num("res_ix", sw);
        json_kv_num("res_iy", sh);
        json_kv_num("res_s", mw);
        json_kv_num("res_t", mh);
        json_close_obj();
        json_kv_str("n_prime_mapping",
                    "uniform inf; psm n; lambda techniques lambda*(f-n); repar n_repar*(f-n)/W_lz");
        json_key("rows");
        json_open_arr();
        for (int i = 0; i < nr; ++i) {
            json_open_obj();
            json_kv_num("gamma_deg", rows[i].gamma_deg);
            json_kv_str("technique", tech_name(rows[i].tech));
            json_kv_str("param_name", rows[i].r.param_name);
            json_kv_num("param", rows[i].r.param);
            json_kv_str("param_status", swarp_status_name(rows[i].r.status));
            json_kv_num("n_prime", rows[i].r.n_prime);
            json_kv_num("max_m_x", rows[i].max_mx);
            json_kv_num("max_m_z", rows[i].max_mz);
            json_close_obj();
        }
        json_close_arr();
        json_end();
        return 0;
    }
    printf("libshadowwarp %s report: n = %g, f = %g, Theta = %g deg, screen %ux%u, map %ux%u\n",
           swarp_version_string(), n, f, 0.5 * fovy_deg, sw, sh, mw, mh);
    printf("Lloyd's error model [RHS] (2.3)-(2.8), exact maxima over [n, f] (1 = one texel per pixel).\n");
    printf("n' = lambda (f - n) for the [GMNPR] lambdas, n_repar (f - n) / W_lz for n_repar "
           "(exact for an overhead light; docs/parameters.md).\n");
    for (int i = 0; i < nr; ++i) {
        const row* r = &rows[i];
        if (r->tech == 0)
            printf("\ngamma = %g deg\n  %-8s %-14s %12s %12s %12s %12s  %s\n", r->gamma_deg, "tech",
                   "parameter", "value", "n'", "max m_x", "max m_z", "note");
        const char* note = r->r.status == SWARP_OK ? "" : swarp_status_name(r->r.status);
        printf("  %-8s %-14s %12.6g %12.6g %12.5g %12.5g  %s\n", tech_name(r->tech), r->r.param_name,
               r->r.param, r->r.n_prime, r->max_mx, r->max_mz, note);
    }
    return 0;
}
