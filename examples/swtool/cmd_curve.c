/* swtool curve: Lloyd's m_x, m_z ([RHS] (2.3)-(2.8)) along the view depth for
 * one technique, optionally on a partitioned frustum ([RHS] Fig. 3.15/3.18),
 * and [GMNPR]'s F (2) for the lambda techniques. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core_tech.h"

#define CURVE_MAX_SAMPLES 100000u

/* "uniform" | "log" | "practical" (L = 0.5) | "practical:L" -> lambda of [RHS] (3.8),
 * the spelling of `cascade --scheme` */
static int parse_scheme(const char* s, double* lambda) {
    if (strcmp(s, "uniform") == 0) {
        *lambda = 0.0;
        return 1;
    }
    if (strcmp(s, "log") == 0) {
        *lambda = 1.0;
        return 1;
    }
    if (strcmp(s, "practical") == 0) {
        *lambda = 0.5;
        return 1;
    }
    if (strncmp(s, "practical:", 10) == 0) {
        char* end = NULL;
        double v = strtod(s + 10, &end);
        if (end == s + 10 || *end != '\0') return 0;
        *lambda = v;
        return 1;
    }
    return 0;
}

/* split holding z, same rule as the library: a border belongs to the split
 * that starts there, splits[m] to the last one */
static size_t split_of(const double* c, size_t m, double z) {
    size_t i = 0;
    while (i + 1 < m && z >= c[i + 1]) ++i;
    return i;
}

int cmd_curve(sw_args* a) {
    static const char* const known[] = {"near", "far", "fovy", "technique", "gamma", "splits",
                                        "scheme", "samples", "screen", "map", NULL};
    double n, f, fovy_deg, gamma_deg = 90.0, lambda_split = 0.5;
    unsigned m = 1, samples = 201, sw = 1024, sh = 768, mw = 1024, mh = 1024;
    const char* tname = cli_opt(a, "technique");
    const char* scheme = cli_opt(a, "scheme");
    sw_tech tech = TECH_LISPSM;
    CLI_ACCEPT(a, known);
    if (!cli_double_req(a, "near", &n) || !cli_double_req(a, "far", &f) ||
        !cli_double_req(a, "fovy", &fovy_deg) || !cli_double(a, "gamma", 90.0, &gamma_deg) ||
        !cli_uint(a, "splits", 1, &m) || !cli_uint(a, "samples", 201, &samples) ||
        !cli_size(a, "screen", 1024, 768, &sw, &sh) || !cli_map(a, 1024, &mw, &mh))
        return CLI_EXIT_USAGE;
    if (!tname) return cli_fail(a, NULL, "--technique uniform|psm|lispsm|repar|gmnpr|glpr is required");
    if (!tech_parse(tname, &tech))
        return cli_fail(a, "--technique", "expects uniform|psm|lispsm|repar|gmnpr|glpr, got '%s'", tname);
    if (scheme && !parse_scheme(scheme, &lambda_split))
        return cli_fail(a, "--scheme", "expects uniform|log|practical[:L], got '%s'", scheme);
    if (samples < 2 || samples > CURVE_MAX_SAMPLES)
        return cli_fail(a, "--samples", "expects 2..%u, got %u", CURVE_MAX_SAMPLES, samples);
    if (!(gamma_deg >= 0.0 && gamma_deg <= 180.0))
        return cli_fail(a, "--gamma", "expects degrees in [0, 180], got '%s'", cli_opt(a, "gamma"));
    double theta = 0.5 * fovy_deg * SW_DEG;
    double gamma = (gamma_deg > 90.0 ? 180.0 - gamma_deg : gamma_deg) * SW_DEG;

    /* split distances [RHS] (3.8) */
    double c[SWARP_SPLIT_MAX_COUNT + 1];
    size_t cnt = 0;
    swarp_status s = swarp_split_practical(n, f, lambda_split, m, c, SWARP_SPLIT_MAX_COUNT + 1, &cnt);
    if (s != SWARP_OK) return cli_report_status(a, s, "split scheme [RHS] (3.8)");

    /* each split's own warp parameter */
    double n_prime[SWARP_SPLIT_MAX_COUNT], param[SWARP_SPLIT_MAX_COUNT];
    swarp_status pstat[SWARP_SPLIT_MAX_COUNT];
    const char* pname = "";
    for (unsigned i = 0; i < m; ++i) {
        sw_tech_result r;
        if ((s = tech_eval(tech, c[i], c[i + 1], theta, gamma, &r)) != SWARP_OK)
            return cli_report_status(a, s, "warp parameter");
        n_prime[i] = r.n_prime;
        param[i] = r.param;
        pstat[i] = r.status;
        pname = r.param_name;
    }

    /* samples: linear in z, plus both sides of every inner border */
    size_t total = samples + 2u * (m - 1u);
    double* z = malloc(total * sizeof *z);
    double* mx = malloc(total * sizeof *mx);
    double* mz = malloc(total * sizeof *mz);
    double* F = malloc(total * sizeof *F);
    if (!z || !mx || !mz || !F) {
        free(z), free(mx), free(mz), free(F);
        fprintf(stderr, "swtool curve: out of memory\n");
        return 1;
    }
    size_t k = 0;
    unsigned b = 1; /* next inner border */
    for (unsigned i = 0; i < samples; ++i) {
        double zi = (i + 1 == samples) ? f : n + (f - n) * ((double)i / (samples - 1));
        while (b < m && c[b] <= zi) {
            z[k++] = nextafter(c[b], 0.0);
            z[k++] = c[b];
            ++b;
        }
        if (k == 0 || zi > z[k - 1]) z[k++] = zi;
    }
    swarp_error_config cfg = {n, f, theta, sw, sh, mw, mh, {0}};
    s = swarp_error_split_curve(&cfg, c, n_prime, m, z, k, mx, mz);
    if (s != SWARP_OK) {
        free(z), free(mx), free(mz), free(F);
        return cli_report_status(a, s, "error curve [RHS] (2.3)-(2.8)");
    }
    /* [GMNPR] (2) for the lambda techniques (theta > 0 only) */
    int have_F = (tech == TECH_LISPSM || tech == TECH_GMNPR || tech == TECH_GLPR) && gamma > 0.0;
    for (size_t j = 0; j < k; ++j) {
        F[j] = NAN;
        if (!have_F) continue;
        size_t i = split_of(c, m, z[j]);
        double v;
        if (swarp_gmnpr_F(param[i], gamma, theta, c[i], c[i + 1], z[j], &v) == SWARP_OK) F[j] = v;
    }

    if (a->json) {
        json_begin();
        json_kv_status(SWARP_OK);
        json_kv_str("technique", tech_name(tech));
        json_kv_num("gamma_deg", gamma_deg);
        json_kv_num("theta", theta);
        json_kv_str("param_name", pname);
        json_kv_arr("splits", c, m + 1);
        json_kv_arr("param", param, m);
        json_key("param_status");
        json_open_arr();
        for (unsigned i = 0; i < m; ++i) json_str(swarp_status_name(pstat[i]));
        json_close_arr();
        json_kv_arr("n_prime", n_prime, m);
        json_kv_arr("z", z, k);
        json_kv_arr("m_x", mx, k);
        json_kv_arr("m_z", mz, k);
        if (have_F) json_kv_arr("F", F, k);
        json_end();
    } else {
        printf(have_F ? "z,m_x,m_z,split,F\n" : "z,m_x,m_z,split\n");
        for (size_t j = 0; j < k; ++j) {
            printf("%.17g,%.17g,%.17g,%zu", z[j], mx[j], mz[j], split_of(c, m, z[j]));
            if (have_F) {
                if (isfinite(F[j]))
                    printf(",%.17g", F[j]);
                else
                    printf(",");
            }
            printf("\n");
        }
    }
    free(z), free(mx), free(mz), free(F);
    return 0;
}
