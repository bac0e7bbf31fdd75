/* swtool params: every closed-form warp parameter of the core stage for one
 * configuration; plus the technique table shared with `curve` and `report`. */
#include <math.h>
#include <string.h>

#include "cli.h"
#include "core_tech.h"

/* ---- techniques ----------------------------------------------------------- */

static const char* const tech_names[TECH_COUNT] = {"uniform", "psm", "lispsm", "repar", "gmnpr", "glpr"};

const char* tech_name(sw_tech t) { return ((unsigned)t < (unsigned)TECH_COUNT) ? tech_names[t] : "?"; }

int tech_parse(const char* s, sw_tech* out) {
    for (int i = 0; i < TECH_COUNT; ++i)
        if (strcmp(s, tech_names[i]) == 0) {
            *out = (sw_tech)i;
            return 1;
        }
    return 0;
}

/* [GMNPR] lambda is P_n over a warp-frustum depth normalised to 1; the error
 * model's n' is over the depth f - n of the overhead light, so n' = lambda (f - n).
 * n_repar lives in light space where the warp frustum's depth is W_lz, so
 * n' = n_repar (f - n) / W_lz (exact for the overhead light, W_lz = f - n). */
static double lambda_to_nprime(double lambda, double n, double f) {
    double v = lambda * (f - n);
    return isfinite(v) ? v : INFINITY; /* DBL_MAX * (f - n): uniform */
}

swarp_status tech_eval(sw_tech t, double n, double f, double theta, double gamma,
                       sw_tech_result* r) {
    swarp_status s = SWARP_OK;
    double v = 0.0;
    switch (t) {
        case TECH_UNIFORM:
            r->param_name = "n'";
            r->param = r->n_prime = INFINITY;
            r->status = SWARP_INFO_WARP_UNIFORM;
            return SWARP_OK;
        case TECH_PSM:
            r->param_name = "n'";
            r->param = r->n_prime = n;
            r->status = SWARP_OK;
            return SWARP_OK;
        case TECH_LISPSM:
            r->param_name = "lambda_LiSPSM";
            s = swarp_gmnpr_lambda_lispsm(gamma, theta, n, f, &v);
            break;
        case TECH_GMNPR:
            r->param_name = "lambda_GMNPR";
            s = swarp_gmnpr_lambda(gamma, theta, n, f, &v);
            break;
        case TECH_GLPR:
            r->param_name = "lambda_GLPR";
            s = swarp_gmnpr_lambda_glpr(gamma, theta, n, f, &v);
            break;
        case TECH_REPAR: {
            double eta = 0, W_lz = 0;
            r->param_name = "n_repar";
            if ((s = swarp_warp_eta(gamma, theta, &eta)) != SWARP_OK) return s;
            /* W_e: the near plane's height 2 n tan(Theta) in the side view */
            if ((s = swarp_warp_wlz(gamma, theta, n, f, 2.0 * n * tan(theta), &W_lz)) != SWARP_OK)
                return s;
            s = swarp_warp_nrepar(eta, f / n, W_lz, &v);
            if (swarp_status_is_error(s)) return s;
            r->param = v;
            r->n_prime = isinf(v) ? INFINITY : v * ((f - n) / W_lz);
            if (!isfinite(r->n_prime)) r->n_prime = INFINITY;
            r->status = s;
            return SWARP_OK;
        }
        default:
            return SWARP_ERR_UNKNOWN_ENUM;
    }
    if (swarp_status_is_error(s)) return s;
    r->param = v;
    r->n_prime = lambda_to_nprime(v, n, f);
    r->status = s;
    return SWARP_OK;
}

/* ---- swtool params ---------------------------------------------------------- */

typedef struct item {
    const char* key;
    const char* eq;
    double value;
    swarp_status status;
} item;

int cmd_params(sw_args* a) {
    static const char* const known[] = {"near", "far", "fovy", "gamma", "np", "fp", NULL};
    double n, f, fovy_deg, gamma_deg, n_p = 0.0, f_p = 0.0;
    CLI_ACCEPT(a, known);
    if (!cli_double_req(a, "near", &n) || !cli_double_req(a, "far", &f) ||
        !cli_double_req(a, "fovy", &fovy_deg) || !cli_double_req(a, "gamma", &gamma_deg) ||
        !cli_double(a, "np", 0.0, &n_p) || !cli_double(a, "fp", 0.0, &f_p))
        return CLI_EXIT_USAGE;
    if (!(gamma_deg >= 0.0 && gamma_deg <= 180.0))
        return cli_fail(a, "--gamma", "expects degrees in [0, 180], got '%s'", cli_opt(a, "gamma"));
    double theta = 0.5 * fovy_deg * SW_DEG;
    /* the light/view angle matters only up to its supplement */
    double gamma = (gamma_deg > 90.0 ? 180.0 - gamma_deg : gamma_deg) * SW_DEG;
    int pseudo = cli_opt(a, "np") != NULL || cli_opt(a, "fp") != NULL;

    item it[16];
    int k = 0;
    swarp_status s;
    double W_lz = 0, eta = 0, v = 0, l1 = 0, l2 = 0;
    double W_e = 2.0 * n * tan(theta);
    if ((s = swarp_warp_wlz(gamma, theta, n, f, W_e, &W_lz)) != SWARP_OK)
        return cli_report_status(a, s, "W_lz [RHS] (3.5)");
    it[k++] = (item){"W_lz", "[RHS] (3.5), W_e = 2 n tan(Theta)", W_lz, s};
    if ((s = swarp_warp_eta(gamma, theta, &eta)) != SWARP_OK)
        return cli_report_status(a, s, "eta [RHS] (3.3)");
    it[k++] = (item){"eta", "[RHS] (3.3)", eta, s};
    it[k++] = (item){"alpha", "[RHS] (3.4), f/n", f / n, SWARP_OK};
    s = swarp_warp_nrepar(eta, f / n, W_lz, &v);
    if (swarp_status_is_error(s)) return cli_report_status(a, s, "n_repar [RHS] (3.4)");
    it[k++] = (item){"n_repar", "[RHS] (3.4)", v, s};
    s = swarp_warp_nopt(W_lz, n, f, &v);
    if (swarp_status_is_error(s)) return cli_report_status(a, s, "n_opt [RHS] (3.2)");
    it[k++] = (item){"n_opt", "[RHS] (3.2), d = W_lz, z_0 = n, z_1 = f", v, s};
    if (pseudo) {
        s = swarp_warp_nopt_pseudo(W_lz, n, f, n_p, f_p, &v);
        if (swarp_status_is_error(s)) return cli_report_status(a, s, "n_opt pseudo [RHS] (4.2)");
        it[k++] = (item){"n_opt_pseudo", "[RHS] (4.2), d = W_lz", v, s};
        it[k++] = (item){"z_pseudo_near", "n + n_p (f - n)", n + n_p * (f - n), SWARP_OK};
        it[k++] = (item){"z_pseudo_far", "f - f_p (f - n)", f - f_p * (f - n), SWARP_OK};
    }
    int have_l12 = gamma > 0.0;
    if (have_l12) {
        s = swarp_gmnpr_lambda12(gamma, theta, n, f, &l1, &l2);
        if (swarp_status_is_error(s)) return cli_report_status(a, s, "lambda_1/2 [GMNPR] (4)");
        it[k++] = (item){"lambda_1", "[GMNPR] (4)", l1, s};
        it[k++] = (item){"lambda_2", "[GMNPR] (4)", l2, s};
    }
    s = swarp_gmnpr_lambda(gamma, theta, n, f, &v);
    if (swarp_status_is_error(s)) return cli_report_status(a, s, "lambda_GMNPR [GMNPR] (8)");
    it[k++] = (item){"lambda_GMNPR", "[GMNPR] (7), (8)", v, s};
    s = swarp_gmnpr_lambda_lispsm(gamma, theta, n, f, &v);
    if (swarp_status_is_error(s)) return cli_report_status(a, s, "lambda_LiSPSM [GMNPR] (9)");
    it[k++] = (item){"lambda_LiSPSM", "[GMNPR] (9)", v, s};
    s = swarp_gmnpr_lambda_glpr(gamma, theta, n, f, &v);
    if (swarp_status_is_error(s)) return cli_report_status(a, s, "lambda_GLPR");
    it[k++] = (item){"lambda_GLPR", "[GMNPR] (2), F linear in z", v, s};

    /* what each technique means for the error model */
    sw_tech_result tr[TECH_COUNT];
    for (int t = 0; t < TECH_COUNT; ++t)
        if ((s = tech_eval((sw_tech)t, n, f, theta, gamma, &tr[t])) != SWARP_OK)
            return cli_report_status(a, s, tech_name((sw_tech)t));

    if (a->json) {
        json_begin();
        json_kv_status(SWARP_OK);
        json_key("input");
        json_open_obj();
        json_kv_num("near", n);
        json_kv_num("far", f);
        json_kv_num("fovy_deg", fovy_deg);
        json_kv_num("theta", theta);
        json_kv_num("gamma_deg", gamma_deg);
        json_kv_num("gamma", gamma);
        if (pseudo) {
            json_kv_num("np", n_p);
            json_kv_num("fp", f_p);
        }
        json_close_obj();
        for (int i = 0; i < k; ++i) {
            json_key(it[i].key);
            json_open_obj();
            json_kv_num("value", it[i].value);
            json_kv_str("status", swarp_status_name(it[i].status));
            json_kv_str("ref", it[i].eq);
            json_close_obj();
        }
        json_key("n_prime");
        json_open_obj();
        for (int t = 0; t < TECH_COUNT; ++t) json_kv_num(tech_name((sw_tech)t), tr[t].n_prime);
        json_close_obj();
        json_end();
        return 0;
    }
    printf("swtool params: n = %g, f = %g, fovy = %g deg (Theta = %g deg), gamma = %g deg\n", n, f,
           fovy_deg, 0.5 * fovy_deg, gamma / SW_DEG);
    printf("%-15s %-24s %-28s %s\n", "parameter", "value", "status", "equation");
    for (int i = 0; i < k; ++i)
        printf("%-15s %-24.17g %-28s %s\n", it[i].key, it[i].value, swarp_status_name(it[i].status),
               it[i].eq);
    printf("\nerror-model n' (docs/parameters.md: n' = lambda (f - n); n_repar (f - n) / W_lz):\n");
    for (int t = 0; t < TECH_COUNT; ++t)
        printf("  %-8s n' = %.17g\n", tech_name((sw_tech)t), tr[t].n_prime);
    return 0;
}
