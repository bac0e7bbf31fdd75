#define _POSIX_C_SOURCE 200809L
/* The planner (src/plan/plan.c, docs/planning.md).
 *
 *  1. the generalised error model: equal to the core's [RHS] (2.3)/(2.4)
 *     at γ = 90°, equal to a dense sampling of the frustum (written here in
 *     a different form: the perspective map u(p) differentiated numerically)
 *     at any γ, light-space extent = W_lz [RHS] (3.5) for γ >= Θ, warp
 *     parameters equal to the core's closed forms called here;
 *  2. a table of 40 scenes with hand-derived expected choices;
 *  3. optimality against a brute-force enumeration written here, over 10^3
 *     random scenes and budgets;
 *  4. monotonicity: a tighter error budget never gives a cheaper plan;
 *  5. bad input: each its status, outputs untouched; explain() text.
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"
#include "plan_helpers.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* ---- small PRNG (splitmix64) -------------------------------------------- */
static uint64_t rng_state;
static uint64_t rng_next(void) { return tu_splitmix64(&rng_state); }
static double rng_unit(void) { return tu_uniform(&rng_state, 0.0, 1.0); }
static double rng_range(double a, double b) { return tu_uniform(&rng_state, a, b); }
static double rng_log(double a, double b) { return exp(rng_range(log(a), log(b))); }

/* ---- scene helpers -------------------------------------------------------- */

/* Camera at (0, 2, 0) looking along -z (up +y), fovy 60°, aspect 4/3,
 * near 1, far = fn; directional light at angle gamma to the view: the
 * direction TO the light is cosγ·view + sinγ·up. */
static swarp_scene_needs scene(double gamma_deg, double fn) {
    swarp_scene_needs n;
    memset(&n, 0, sizeof n);
    n.camera = plan_test_camera(fn);
    double g = gamma_deg * DEG;
    n.light.type = SWARP_LIGHT_DIRECTIONAL;
    n.light.direction = (swarp_vec3){0.0, -sin(g), cos(g)};
    return n;
}

static swarp_budget budget_of(double max_error) {
    swarp_budget b;
    memset(&b, 0, sizeof b);
    b.max_error = max_error;
    return b;
}

/* ---- 1. the error model ----------------------------------------------------- */

/* Dense sampling of one split: the frustum cross-section in the plane of
 * light and view (z in [n, f], |y| <= z tanΘ), the light-space coordinate
 * t = z sinγ + y cosγ, the perspective map u(p) = (1/n' - 1/p) /
 * (1/n' - 1/(n'+W)) differentiated numerically; x: the warping frustum's
 * half-width c·p must cover the view frustum's half-width z tanΘ_x. */
static void sampled_split_error(double gamma, double theta, double aspect, double n, double f,
                                double n_l, double res_ix, double res_iy, double r,
                                double* out_mx, double* out_mz, double* out_W) {
    enum { NZ = 41, NY = 21 };
    double g = gamma > PI / 2 ? PI - gamma : gamma;
    double tmin = INFINITY, tmax = -INFINITY;
    double tt = tan(theta), ttx = aspect * tt;
    for (int i = 0; i < NZ; ++i) {
        double z = n + (f - n) * i / (NZ - 1);
        for (int k = 0; k < NY; ++k) {
            double y = -z * tt + 2.0 * z * tt * k / (NY - 1);
            double t = z * sin(g) + y * cos(g);
            if (t < tmin) tmin = t;
            if (t > tmax) tmax = t;
        }
    }
    double W = tmax - tmin;
    int uniform = !isfinite(n_l);
    double c = 0.0; /* max half-width / p */
    if (!uniform)
        for (int i = 0; i < NZ; ++i) {
            double z = n + (f - n) * i / (NZ - 1);
            for (int k = 0; k < NY; ++k) {
                double y = -z * tt + 2.0 * z * tt * k / (NY - 1);
                double p = n_l + z * sin(g) + y * cos(g) - tmin;
                if (z * ttx / p > c) c = z * ttx / p;
            }
        }
    double mx = 0.0, mz = 0.0;
    for (int i = 0; i < NZ; ++i) {
        double z = n + (f - n) * i / (NZ - 1);
        for (int k = 0; k < NY; ++k) {
            double y = -z * tt + 2.0 * z * tt * k / (NY - 1);
            double t = z * sin(g) + y * cos(g);
            double texel_t, texel_x;
            if (uniform) {
                texel_t = W / r;
                texel_x = 2.0 * f * ttx / r;
            } else {
                double p = n_l + t - tmin;
                double h = 1e-5 * p;
                double den = 1.0 / n_l - 1.0 / (n_l + W);
                double du = ((1.0 / n_l - 1.0 / (p + h)) - (1.0 / n_l - 1.0 / (p - h))) / den;
                texel_t = (2.0 * h / du) / r;
                texel_x = 2.0 * c * p / r;
            }
            double ez = texel_t / (2.0 * z * tt / res_iy);
            double ex = texel_x / (2.0 * z * ttx / res_ix);
            if (ez > mz) mz = ez;
            if (ex > mx) mx = ex;
        }
    }
    *out_mx = mx;
    *out_mz = mz;
    *out_W = W;
}

START_TEST(model_equals_core_lloyd_at_overhead_light) {
    /* γ = 90°: the generalised model must be [RHS] (2.3)/(2.4) exactly, as
     * evaluated by the core's swarp_error_split_max. */
    static const swarp_plan_warp warps[] = {SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_WARP_LISPSM_NOPT,
                                            SWARP_PLAN_WARP_PSM, SWARP_PLAN_WARP_LISPSM_GMNPR};
    double fns[] = {2.0, 100.0, 1000.0, 1e4, 1e6};
    for (size_t fi = 0; fi < 5; ++fi)
        for (size_t wi = 0; wi < 4; ++wi)
            for (uint32_t K = 1; K <= 16; K *= 2) for (int sch = 0; sch < 2; ++sch) {
                if (K > 1 && warps[wi] == SWARP_PLAN_WARP_PSM) continue;
                if (K > 1 && warps[wi] == SWARP_PLAN_WARP_LISPSM_GMNPR) continue;
                if (K == 1 && sch == 1) continue;
                swarp_scene_needs n = scene(90.0, fns[fi]);
                swarp_budget b = budget_of(1.0);
                swarp_plan_scheme scheme = K == 1 ? SWARP_PLAN_SCHEME_NONE
                                           : sch ? SWARP_PLAN_SCHEME_PRACTICAL : SWARP_PLAN_SCHEME_LOG;
                swarp_plan_chain c = chain_of(warps[wi], scheme, K);
                swarp_plan_result p;
                ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_OK);
                swarp_error_config cfg;
                memset(&cfg, 0, sizeof cfg);
                cfg.z_near = 1.0;
                cfg.z_far = fns[fi];
                cfg.theta = 30.0 * DEG;
                cfg.res_ix = 1024;
                cfg.res_iy = 768;
                cfg.res_s = cfg.res_t = p.map_resolution;
                double smx[16], smz[16], mx, mz;
                swarp_status s = swarp_error_split_max(&cfg, p.splits, p.n_prime, K, smx, smz, &mx, &mz);
                ck_assert(!swarp_status_is_error(s));
                for (uint32_t i = 0; i < K; ++i) {
                    ck_assert_double_eq_tol(p.split_max_mx[i], smx[i], 1e-9 * smx[i]);
                    ck_assert_double_eq_tol(p.split_max_mz[i], smz[i], 1e-9 * smz[i]);
                }
                ck_assert_double_eq_tol(p.max_mx, mx, 1e-9 * mx);
                ck_assert_double_eq_tol(p.max_mz, mz, 1e-9 * mz);
                /* warp parameters at the overhead light: n_opt = n + sqrt(n f)
                 * ([WSP04] form), PSM n' = n ([RHS] (2.5)), uniform inf */
                for (uint32_t i = 0; i < K; ++i) {
                    double c0 = p.splits[i], c1 = p.splits[i + 1];
                    if (warps[wi] == SWARP_PLAN_WARP_UNIFORM) ck_assert(isinf(p.n_prime[i]));
                    if (warps[wi] == SWARP_PLAN_WARP_LISPSM_NOPT)
                        ck_assert_double_eq_tol(p.n_prime[i], c0 + sqrt(c0 * c1), 1e-9 * c1);
                    if (warps[wi] == SWARP_PLAN_WARP_PSM)
                        ck_assert_double_eq_tol(p.n_prime[i], c0, 1e-9 * c1);
                }
            }
}
END_TEST

START_TEST(model_equals_geometry_setup_at_overhead_light) {
    /* The geometry stage builds the real light matrices from the body B and
     * reports (2.3)/(2.4) at its own n'; with a scene box holding the whole
     * view and the sun at zenith, its numbers must be the planner's, split by
     * split, for uniform, LiSPSM n_opt and PSM. */
    static const swarp_plan_warp warps[3] = {SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_WARP_LISPSM_NOPT,
                                             SWARP_PLAN_WARP_PSM};
    static const swarp_technique techs[3] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM,
                                             SWARP_TECHNIQUE_PSM};
    double fns[3] = {10.0, 100.0, 1000.0};
    for (int fi = 0; fi < 3; ++fi)
        for (int wi = 0; wi < 3; ++wi)
            for (uint32_t K = 1; K <= 4; K *= 2) {
                if (K > 1 && wi == 2) continue;
                double fn = fns[fi];
                swarp_scene_needs n = scene(90.0, fn);
                swarp_budget b = budget_of(1.0);
                swarp_plan_chain c = chain_of(warps[wi], K > 1 ? SWARP_PLAN_SCHEME_LOG : SWARP_PLAN_SCHEME_NONE, K);
                swarp_plan_result p;
                ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_OK);
                swarp_aabb box = {{-2.0 * fn, -2.0 * fn, -1.05 * fn}, {2.0 * fn, 2.0 * fn, 1.0}};
                swarp_setup_options o;
                memset(&o, 0, sizeof o);
                o.technique = techs[wi];
                o.param = SWARP_WARP_PARAM_NOPT; /* the planner's model is n_opt's */
                o.map_width = 2048;
                o.screen_width = 1024;
                o.screen_height = 768;
                for (uint32_t i = 0; i < K; ++i) {
                    swarp_setup_result r;
                    swarp_status s = swarp_setup_range(&n.camera, &n.light, &box, p.splits[i], p.splits[i + 1],
                                                       &o, &r, NULL, 0, NULL);
                    ck_assert_msg(!swarp_status_is_error(s), "%s", swarp_status_name(s));
                    ck_assert_double_eq_tol(r.max_mx, p.split_max_mx[i], 1e-6 * p.split_max_mx[i]);
                    ck_assert_double_eq_tol(r.max_mz, p.split_max_mz[i], 1e-6 * p.split_max_mz[i]);
                }
            }
}
END_TEST

START_TEST(model_equals_dense_sampling_any_gamma) {
    rng_state = 0x5eed0001ull;
    static const swarp_plan_warp warps[] = {
        SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_WARP_LISPSM_NREPAR,
        SWARP_PLAN_WARP_LISPSM_GMNPR, SWARP_PLAN_WARP_LISPSM_PSEUDO, SWARP_PLAN_WARP_PSM};
    for (int it = 0; it < 150; ++it) {
        double gdeg = rng_range(0.0, 180.0);
        double fn = rng_log(1.5, 1e4);
        swarp_scene_needs n = scene(gdeg, fn);
        n.camera.fovy = rng_range(20.0, 100.0) * DEG;
        n.camera.aspect = rng_range(0.8, 2.0);
        n.screen_width = 200 + (uint32_t)(rng_next() % 2000);
        n.screen_height = 200 + (uint32_t)(rng_next() % 2000);
        swarp_budget b = budget_of(1.0);
        b.map_resolution = 256u << (rng_next() % 5);
        swarp_plan_warp w = warps[rng_next() % 6];
        uint32_t K = 1;
        swarp_plan_scheme sc = SWARP_PLAN_SCHEME_NONE;
        if (w == SWARP_PLAN_WARP_UNIFORM || w == SWARP_PLAN_WARP_LISPSM_NOPT ||
            w == SWARP_PLAN_WARP_LISPSM_NREPAR) {
            K = 1 + (uint32_t)(rng_next() % 6);
            if (K > 1) sc = (rng_next() & 1) ? SWARP_PLAN_SCHEME_LOG : SWARP_PLAN_SCHEME_PRACTICAL;
        }
        swarp_plan_chain c = chain_of(w, sc, K);
        swarp_plan_result p;
        ck_assert(!swarp_status_is_error(swarp_plan_evaluate(&n, &b, &c, &p)));
        double theta = 0.5 * n.camera.fovy;
        for (uint32_t i = 0; i < K; ++i) {
            double smx, smz, W;
            sampled_split_error(gdeg * DEG, theta, n.camera.aspect, p.splits[i], p.splits[i + 1],
                                p.n_prime[i], n.screen_width, n.screen_height, p.map_resolution,
                                &smx, &smz, &W);
            /* the maxima sit on frustum corners, which the grid contains; the
             * numerical derivative is good to ~1e-9 */
            ck_assert_double_eq_tol(p.split_max_mx[i], smx, 1e-6 * smx);
            ck_assert_double_eq_tol(p.split_max_mz[i], smz, 1e-6 * smz);
            /* for γ >= Θ (folded) the light-space extent is W_lz [RHS] (3.5) */
            double gf = gdeg * DEG > PI / 2 ? PI - gdeg * DEG : gdeg * DEG;
            if (gf >= theta) {
                double wlz;
                ck_assert(!swarp_status_is_error(swarp_warp_wlz(
                    gf, theta, p.splits[i], p.splits[i + 1], 2.0 * p.splits[i] * tan(theta), &wlz)));
                ck_assert_double_eq_tol(W, wlz, 1e-9 * wlz);
                /* n_opt: [RHS] (3.2) with d = W, z_0 = n, z_1 = n + W sinγ */
                if (w == SWARP_PLAN_WARP_LISPSM_NOPT) {
                    double want;
                    swarp_warp_nopt(wlz, p.splits[i], p.splits[i] + wlz * sin(gf), &want);
                    ck_assert_double_eq_tol(p.n_prime[i], want, 1e-9 * want);
                }
            }
        }
    }
}
END_TEST

START_TEST(duelling_frusta_fade_every_warp_to_uniform) {
    /* γ = 0: n_opt, n_repar, GMNPR and pseudo-near/far all give n' = inf,
     * so their error equals the uniform map's; PSM does not fade. */
    swarp_scene_needs n = scene(0.0, 100.0);
    swarp_budget b = budget_of(1.0);
    swarp_plan_result pu, pw;
    swarp_plan_chain cu = chain_of(SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1);
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &cu, &pu), SWARP_OK);
    for (int w = SWARP_PLAN_WARP_LISPSM_NOPT; w <= SWARP_PLAN_WARP_LISPSM_PSEUDO; ++w) {
        swarp_plan_chain cw = chain_of((swarp_plan_warp)w, SWARP_PLAN_SCHEME_NONE, 1);
        ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &cw, &pw), SWARP_OK);
        ck_assert_double_eq_tol(pw.max_error, pu.max_error, 1e-12 * pu.max_error);
    }
    /* and the uniform error is (2.7): res_ix/res_s f/n */
    ck_assert_double_eq_tol(pu.max_mx, 1024.0 / 2048.0 * 100.0, 1e-9);
}
END_TEST

/* ---- 2. the expectations table ---------------------------------------------- */

typedef struct expect {
    const char* name;
    double gamma_deg, fn, max_error;
    uint32_t map, atlas, max_passes;
    double time_budget, pass_cost;
    uint32_t moves, soft;
    double width;
    swarp_plan_bleed bleed;
    uint32_t clamp;
    int planes; /* 0 none, 1 floor y=0, 2 floor + wall x=-5, 3 plane y=2 (camera on it) */
    int light_kind; /* 0 directional from gamma, 1 from below, 2 point light above */
    int box;        /* 0 none, 1 box limiting depth to [0, 10], 2 box behind the camera */
    /* expectations (0 / -1: not checked) */
    int status;
    uint32_t K;
    swarp_plan_warp warp;
    swarp_plan_scheme scheme;
    swarp_plan_stabilize stab;
    swarp_plan_filter filter;
    int inverse, depth_clamp, lixel_count, plane0_reason;
    uint32_t must_reasons;
} expect;

#define W_U SWARP_PLAN_WARP_UNIFORM
#define W_NOPT SWARP_PLAN_WARP_LISPSM_NOPT
#define W_PSM SWARP_PLAN_WARP_PSM
#define S_NONE SWARP_PLAN_SCHEME_NONE
#define S_LOG SWARP_PLAN_SCHEME_LOG
#define ST_NONE SWARP_PLAN_STABILIZE_NONE
#define ST_64 SWARP_PLAN_STABILIZE_APPROX64
#define F_NONE SWARP_PLAN_FILTER_NONE

/* Reasoning shared by the rows (screen 1024x768, map 2048, Θ = 30°, so
 * res_ix/res_s = 0.5 and res_iy/res_t = 0.375; docs/planning.md §6):
 *  - overhead light, log splits with n_opt: every split has the same ratio
 *    a = (f/n)^(1/K) and n' = c0(1 + sqrt a); (2.3) at z = c0 gives
 *    m_x = 0.5 a (1+√a)/(√a + a) = 0.5 √a, (2.4) is smaller; so m_x <= E needs
 *    a <= (2E)², K >= ln(f/n) / ln((2E)²).  E = 1: K = ceil(ln(f/n)/ln 4):
 *    f/n = 100 -> 4, 1000 -> 5, 1e4 -> 7.  One map (K = 1): m_x = 0.5·10 = 5
 *    at f/n = 100.
 *  - duelling frusta (γ = 0): every LiSPSM warp fades to n' = inf (z_1 = z_0
 *    in (3.2), η = -1 in (3.3) for γ <= Θ/3, λ_GMNPR(0) = inf), so uniform
 *    wins every tie; uniform log splits give m_x = 0.5 a ((2.7) at z = c0),
 *    m_z = 0.375 a (the t-extent is the far width 2 c1 tanΘ): E = 1 needs
 *    a <= 2: K = ceil(ln(f/n)/ln 2): 100 -> 7, 1000 -> 10, 1e4 -> 14.
 *  - PSM at the overhead light: m_x = 0.5 (2.5), m_z max at z = f:
 *    0.375 (f - n)/(2 tan 30°)/n (2.6) = 0.325 for f/n = 2; n_opt gives
 *    m_x = 0.5 √2 = 0.707: PSM is the most accurate one map at f/n = 2.
 *  - a moving camera admits only uniform chains, stabilised, with texels
 *    1/64 larger: m_x = 0.5 a 65/64 <= 1 needs a <= 1.969: f/n = 100 -> K = 7.
 */
static const expect table[] = {
    /* 1 overhead, f/n 100, E = 6: one n_opt map has m_x = 5 <= 6 (uniform: 50);
     * n_repar (η = 0 at 90°) and GMNPR equal n_opt: the tie goes to n_opt. */
    {"overhead-100-one-warped-map", 90, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_ONE_MAP_MEETS | SWARP_PLAN_WHY_WARP_LOWERS_ERROR | SWARP_PLAN_WHY_NO_STABILIZE_STATIC |
         SWARP_PLAN_WHY_NO_FILTER_HARD | SWARP_PLAN_WHY_NO_INVERSE | SWARP_PLAN_WHY_NO_LIXEL_NONE},
    /* 2 overhead, f/n 100, E = 4: no map alone (best 5); K = 2 log n_opt:
     * a = 10, m_x = 0.5 √10 = 1.58 (practical's first split [1, 30.25] is worse) */
    {"overhead-100-two-splits", 90, 100, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 2, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_SPLITS_NEEDED},
    /* 3 overhead, f/n 100, E = 1: K = 4 (a = 3.16, m_x = 0.889; K = 3: 1.08) */
    {"overhead-100-budget-1", 90, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 4, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_SPLITS_NEEDED},
    /* 4 overhead, f/n 1000, E = 1: K = ceil(ln 1000 / ln 4) = 5 */
    {"overhead-1000-budget-1", 90, 1000, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 5, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, 0},
    /* 5 overhead, f/n 1e4, E = 1: K = ceil(ln 1e4 / ln 4) = 7 */
    {"overhead-1e4-budget-1", 90, 1e4, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 7, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, 0},
    /* 6 overhead, f/n 2, E = 1: PSM (0.5) beats n_opt (0.707); light in front */
    {"overhead-2-psm", 90, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_PSM, S_NONE, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_INVERSE},
    /* 7 light 10° behind overhead (γ = 100), f/n 2: folded γ = 80° is still
     * PSM's best case; the light is behind the camera -> inverse projection */
    {"behind-2-psm-inverse", 100, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_PSM, S_NONE, ST_NONE, F_NONE, 1, 0, 0, -1, SWARP_PLAN_WHY_INVERSE_PROJECTION},
    /* 8-10 duelling frusta: splits and no warp, K = ceil(ln(f/n)/ln 2) */
    {"duelling-100", 0, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 7, W_U, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_SPLITS_NEEDED | SWARP_PLAN_WHY_NO_WARP_NO_GAIN},
    {"duelling-1000", 0, 1000, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 10, W_U, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_WARP_NO_GAIN},
    {"duelling-1e4", 0, 1e4, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 14, W_U, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_WARP_NO_GAIN},
    /* 11 duelling 1e4 with 8 passes: unmet; most accurate within 8 is K = 8
     * log uniform (m_x = 0.5·1e4^(1/8) = 1.58), and more passes would meet */
    {"duelling-1e4-8-passes", 0, 1e4, 1, 0, 0, 8, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_INFO_PLAN_BUDGET_UNMET, 8, W_U, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_BUDGET_UNMET | SWARP_PLAN_WHY_PASS_LIMITED},
    /* 12 overhead, f/n 100, map 1024, E = 1: R_x = 1, so n_opt log has
     * m_x = √a > 1 for every K, uniform a > 1, PSM 1 but m_z = 64: unmet;
     * most accurate: K = 16 log n_opt (m_x = 100^(1/32) = 1.155) */
    {"overhead-map-1024-unmet", 90, 100, 1, 1024, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_INFO_PLAN_BUDGET_UNMET, 16, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_BUDGET_UNMET},
    /* 13 time budget 3.5 ms at 1 ms per pass: K = 4 (4 ms) is too slow,
     * fewer splits miss E = 1: unmet (time-limited), most accurate = K 16 */
    {"overhead-time-limited", 90, 100, 1, 0, 0, 0, 3.5e6, 1e6, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_INFO_PLAN_BUDGET_UNMET, 16, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_BUDGET_UNMET | SWARP_PLAN_WHY_TIME_LIMITED},
    /* 14 time budget 5 ms: K = 4 costs 4 ms and meets E = 1 */
    {"overhead-time-ok", 90, 100, 1, 0, 0, 0, 5e6, 1e6, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 4, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, 0},
    /* 15 atlas 2048 with 2048 maps: K = 2..4 get 1024 tiles (R_x = 1,
     * m_x = √a: K = 4 -> 1.778), K 5..9 get 682 (1.5·100^(1/18) >= 1.94),
     * K 10..16 get 512 (>= 2.31), K = 1 n_opt 5: unmet, K = 4 log n_opt */
    {"atlas-shrink-unmet", 90, 100, 1, 2048, 2048, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_INFO_PLAN_BUDGET_UNMET, 4, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_ATLAS_SHRINK | SWARP_PLAN_WHY_BUDGET_UNMET},
    /* 16 moving camera, overhead f/n 100: uniform + stabilised, a <= 1.969 -> K 7 */
    {"moving-overhead", 90, 100, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 7, W_U, S_LOG, ST_64, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_STABILIZE_MOVING | SWARP_PLAN_WHY_NO_WARP_MOVING},
    /* 17 moving camera, duelling f/n 100: same K 7 (m_x = 0.5·1.93·65/64 = 0.98) */
    {"moving-duelling", 0, 100, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 7, W_U, S_LOG, ST_64, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_STABILIZE_MOVING},
    /* 18 static camera: never stabilised */
    {"static-no-stabilise", 45, 100, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_STABILIZE_STATIC},
    /* 19-25 filters: hard -> none; soft narrow (<= 4 texels) -> PCF; wide ->
     * VSM / MSM / EVSM / LVSM by light-bleeding risk (none, low, high, extreme) */
    {"hard-no-filter", 90, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_FILTER_HARD},
    {"soft-3-pcf", 90, 100, 6, 0, 0, 0, 0, 0, 0, 1, 3, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, SWARP_PLAN_FILTER_PCF, 0, 0, 0, -1, SWARP_PLAN_WHY_FILTER_SOFT},
    {"soft-4-pcf", 90, 100, 6, 0, 0, 0, 0, 0, 0, 1, 4, SWARP_PLAN_BLEED_EXTREME, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, SWARP_PLAN_FILTER_PCF, 0, 0, 0, -1, SWARP_PLAN_WHY_FILTER_SOFT},
    {"soft-8-vsm", 90, 100, 6, 0, 0, 0, 0, 0, 0, 1, 8, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, SWARP_PLAN_FILTER_VSM, 0, 0, 0, -1, SWARP_PLAN_WHY_FILTER_SOFT},
    {"soft-8-low-msm", 90, 100, 6, 0, 0, 0, 0, 0, 0, 1, 8, SWARP_PLAN_BLEED_LOW, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, SWARP_PLAN_FILTER_MSM, 0, 0, 0, -1, 0},
    {"soft-8-high-evsm", 90, 100, 6, 0, 0, 0, 0, 0, 0, 1, 8, SWARP_PLAN_BLEED_HIGH, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, SWARP_PLAN_FILTER_EVSM, 0, 0, 0, -1, 0},
    {"soft-8-extreme-lvsm", 90, 100, 6, 0, 0, 0, 0, 0, 0, 1, 8, SWARP_PLAN_BLEED_EXTREME, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, SWARP_PLAN_FILTER_LVSM, 0, 0, 0, -1, 0},
    /* 26-28 depth clamping: only allowed and unwarped (duelling -> uniform) */
    {"clamp-uniform", 0, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
     SWARP_OK, 7, W_U, S_LOG, ST_NONE, F_NONE, 0, 1, 0, -1, SWARP_PLAN_WHY_DEPTH_CLAMP},
    {"clamp-warped-refused", 90, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_CLAMP_WARPED},
    {"clamp-not-allowed", 0, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 7, W_U, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_CLAMP_DISALLOWED},
    /* 29 floor y = 0, camera 2 above looking level (the lower far corners
     * are below the floor), sun at 60° elevation: lixel map, 1 more pass */
    {"floor-lixel", 60, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 1, SWARP_PLAN_PLANE_USED, SWARP_PLAN_WHY_LIXEL_PLANE},
    /* 30 floor lit from below: not lixel-friendly */
    {"floor-lit-from-below", 90, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 0, SWARP_PLAN_PLANE_LIGHT_GRAZING,
     SWARP_PLAN_WHY_NO_LIXEL_SKIPPED},
    /* 31 floor with the sun 3° above the horizon (γ = 3°): grazing */
    {"floor-grazing-light", 3, 100, 100, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 0, SWARP_PLAN_PLANE_LIGHT_GRAZING, 0},
    /* 32 floor but the view ends at depth 1.5 (far corners at y >= 2 - 0.87):
     * the frustum never reaches the floor */
    {"floor-not-visible", 90, 1.5, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 0, SWARP_PLAN_PLANE_NOT_VISIBLE, 0},
    /* 33 plane y = 2 through the eye: no front side */
    {"plane-through-camera", 90, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 0, SWARP_PLAN_PLANE_CAMERA_ON_PLANE, 0},
    /* 34 floor friendly but 1 pass allowed and the chain (1 map, E = 6) uses it */
    {"floor-no-pass-left", 90, 100, 6, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, F_NONE, 0, 0, 0, SWARP_PLAN_PLANE_NO_PASS_LEFT,
     SWARP_PLAN_WHY_NO_LIXEL_SKIPPED},
    /* 35 floor + back wall z = -60 facing the camera, light behind the
     * camera at γ = 120° (to the light: (0, sin 120°, -cos 120°)): the floor
     * is lit at 60° elevation, the wall at 30°, the frustum crosses both
     * (far corners below y = 0 and beyond z = -60): two lixel maps */
    {"floor-and-wall", 120, 100, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 2, SWARP_PLAN_PLANE_USED, 0},
    /* 36 scene box only 10 deep: far 1000 -> 10, f/n 10, one n_opt map has
     * m_x = 0.5 √10 = 1.58 <= 6 */
    {"box-adjusts-far", 90, 1000, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NEAR_FAR_ADJUSTED},
    /* 37 scene box behind the camera: nothing to shadow */
    {"box-behind-camera", 90, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2,
     SWARP_ERR_PLAN_EMPTY_VIEW, 0, 0, 0, 0, 0, -1, -1, -1, -1, 0},
    /* 38 point light 1e6 above the frustum centre: planned as the overhead
     * sun (γ -> 90°): same as row 3, with its informational status */
    {"point-light-overhead", 90, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0,
     SWARP_INFO_PLAN_POINT_LIGHT, 4, W_NOPT, S_LOG, ST_NONE, F_NONE, 0, 0, 0, -1,
     SWARP_PLAN_WHY_POINT_AS_DIRECTIONAL},
    /* 39 light behind at γ = 150, f/n 100, E = 1: PSM is not chosen (folded
     * 30° = Θ: its m_x is 99.5 as one map), so no inverse projection */
    {"behind-150-no-psm", 150, 100, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 0, 0, 0, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_NO_INVERSE},
    /* 40 overhead, f/n 100, generous E = 60: one map; uniform (50) would do,
     * but at the same cost n_opt is more accurate, so the warp is kept */
    {"overhead-generous", 90, 100, 60, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     SWARP_OK, 1, W_NOPT, S_NONE, ST_NONE, F_NONE, 0, 0, 0, -1, SWARP_PLAN_WHY_ONE_MAP_MEETS},
};

static swarp_scene_needs needs_of(const expect* e) {
    swarp_scene_needs n = scene(e->gamma_deg, e->fn);
    n.camera_moves = e->moves;
    n.soft_shadows = e->soft;
    n.soft_width = e->width;
    n.bleed_risk = e->bleed;
    n.allow_depth_clamp = e->clamp;
    if (e->planes == 1 || e->planes == 2) {
        n.plane_count = 1;
        n.planes[0] = (swarp_plane){0.0, 1.0, 0.0, 0.0};
    }
    if (e->planes == 2) {
        n.plane_count = 2;
        n.planes[1] = (swarp_plane){0.0, 0.0, 1.0, 60.0};
    }
    if (e->planes == 3) {
        n.plane_count = 1;
        n.planes[0] = (swarp_plane){0.0, 1.0, 0.0, -2.0};
    }
    if (e->light_kind == 1) n.light.direction = (swarp_vec3){0.0, 1.0, 0.0};
    if (e->light_kind == 2) {
        n.light.type = SWARP_LIGHT_POINT;
        n.light.direction = (swarp_vec3){0.0, 0.0, 0.0};
        n.light.position = (swarp_vec3){0.0, 2.0 + 1e6, -50.5};
    }
    if (e->box == 1) {
        n.scene_box.min = (swarp_vec3){-50.0, -1.0, -10.0};
        n.scene_box.max = (swarp_vec3){50.0, 5.0, 0.0};
    }
    if (e->box == 2) {
        n.scene_box.min = (swarp_vec3){-50.0, -1.0, 5.0};
        n.scene_box.max = (swarp_vec3){50.0, 5.0, 50.0};
    }
    return n;
}

START_TEST(expectations_table) {
    ck_assert_uint_ge(sizeof table / sizeof table[0], 30);
    const expect* e = &table[_i];
    swarp_scene_needs n = needs_of(e);
    n.plan_by = SWARP_PLAN_BY_MODEL; /* the model's selection rule (docs/planning.md's table) */
    swarp_budget b = budget_of(e->max_error);
    b.map_resolution = e->map;
    b.atlas_limit = e->atlas;
    b.max_passes = e->max_passes;
    b.time_budget_ns = e->time_budget;
    b.pass_cost_ns = e->pass_cost;
    swarp_plan_result p;
    swarp_status s = swarp_plan(&n, &b, &p);
    ck_assert_msg(s == (swarp_status)e->status, "%s: status %s", e->name, swarp_status_name(s));
    if (swarp_status_is_error(s)) return;
    if (e->K) ck_assert_msg(p.split_count == e->K, "%s: K %u", e->name, p.split_count);
    if (e->warp) ck_assert_msg(p.warp == e->warp, "%s: warp %s", e->name, swarp_plan_warp_name(p.warp));
    if (e->scheme) ck_assert_msg(p.scheme == e->scheme, "%s: scheme %s", e->name, swarp_plan_scheme_name(p.scheme));
    if (e->stab) ck_assert_msg(p.stabilize == e->stab, "%s: stabilize %d", e->name, p.stabilize);
    if (e->filter) ck_assert_msg(p.filter == e->filter, "%s: filter %s", e->name, swarp_plan_filter_name(p.filter));
    if (e->inverse >= 0) ck_assert_msg((int)p.inverse_projection == e->inverse, "%s: inverse", e->name);
    if (e->depth_clamp >= 0) ck_assert_msg((int)p.depth_clamp == e->depth_clamp, "%s: clamp", e->name);
    if (e->lixel_count >= 0) ck_assert_msg((int)p.lixel_count == e->lixel_count, "%s: lixel %u", e->name, p.lixel_count);
    if (e->plane0_reason >= 0)
        ck_assert_msg((int)p.plane_reason[0] == e->plane0_reason, "%s: plane reason %u", e->name, p.plane_reason[0]);
    ck_assert_msg((p.reasons & e->must_reasons) == e->must_reasons, "%s: reasons %x lack %x", e->name,
                  p.reasons, e->must_reasons & ~p.reasons);
    /* invariants of every plan */
    ck_assert_uint_eq(p.shadow_passes, p.split_count + p.lixel_count);
    ck_assert_int_eq(p.meets_budget, s != SWARP_INFO_PLAN_BUDGET_UNMET);
    if (p.meets_budget) ck_assert(p.max_error <= b.max_error);
    ck_assert(isfinite(p.max_error) && isfinite(p.cost_ns) && isfinite(p.texels));
    /* no effect the scene does not call for */
    if (!e->moves) ck_assert_int_eq(p.stabilize, SWARP_PLAN_STABILIZE_NONE);
    if (!e->soft) ck_assert_int_eq(p.filter, SWARP_PLAN_FILTER_NONE);
    if (p.gamma <= PI / 2) ck_assert_uint_eq(p.inverse_projection, 0);
    if (!e->planes) ck_assert_uint_eq(p.lixel_count, 0);
    if (e->filter == SWARP_PLAN_FILTER_EVSM) {
        ck_assert_double_eq(p.filter_exponent_pos, 40.0);
        ck_assert_double_eq(p.filter_exponent_neg, 5.0);
        /* within the filter stage's safe exponent for fp32 moments [VSM] §4.2 */
        double c_max = 0.0;
        ck_assert_int_eq(swarp_evsm_max_exponent(SWARP_TEXEL_FP32, &c_max), SWARP_OK);
        ck_assert(p.filter_exponent_pos <= c_max && p.filter_exponent_neg <= c_max);
    }
    if (e->filter == SWARP_PLAN_FILTER_LVSM) ck_assert_uint_eq(p.filter_layers, 4);
    if (e->filter == SWARP_PLAN_FILTER_PCF) ck_assert_uint_eq(p.blur_passes, 0);
}
END_TEST

START_TEST(defaults_are_the_documented_scene) {
    /* NULL needs and budget: camera looking level, sun at zenith, f/n 100,
     * E = 1, map 2048.  The model alone meets E with row 3 of the table
     * (K = 4 log n_opt); its matrices measure above E off the view axis, so
     * the measured search takes more splits, whose matrices meet it. */
    swarp_plan_result p, m;
    ck_assert_int_eq(swarp_plan(NULL, NULL, &p), SWARP_OK);
    swarp_plan_chain c4 = chain_of(SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_SCHEME_LOG, 4);
    ck_assert_int_eq(swarp_plan_evaluate(NULL, NULL, &c4, &m), SWARP_OK);
    ck_assert_double_eq_tol(m.max_mx, 0.5 * sqrt(pow(100.0, 0.25)), 1e-9);
    ck_assert(m.max_error <= 1.0);
    ck_assert(fmax(m.measured.max_m_s, m.measured.max_m_t) > 1.0);
    ck_assert_uint_gt(p.split_count, 4);
    ck_assert_uint_eq(p.meets_budget, 1);
    ck_assert(fmax(p.measured.max_m_s, p.measured.max_m_t) <= 1.0);
    ck_assert_double_eq_tol(p.gamma, PI / 2, 1e-12);
    ck_assert_int_eq(p.cost_model, SWARP_PLAN_COST_UNCALIBRATED);
    swarp_scene_needs zn;
    swarp_budget zb;
    memset(&zn, 0, sizeof zn);
    memset(&zb, 0, sizeof zb);
    swarp_plan_result q;
    ck_assert_int_eq(swarp_plan(&zn, &zb, &q), SWARP_OK);
    ck_assert_int_eq(memcmp(&p, &q, sizeof p), 0); /* deterministic, zero = NULL */
    /* default pass cost: 1.39 ms, fitted to [RHS] Table 7.1 */
    ck_assert_double_eq_tol(p.cost_ns, p.split_count * 1.39e6, 1.0);
}
END_TEST

START_TEST(forced_psm_inverse_projection_only_behind) {
    swarp_budget b = budget_of(1.0);
    swarp_plan_chain c = chain_of(SWARP_PLAN_WARP_PSM, SWARP_PLAN_SCHEME_NONE, 1);
    swarp_plan_result p;
    swarp_scene_needs behind = scene(150.0, 100.0), front = scene(30.0, 100.0);
    ck_assert_int_eq(swarp_plan_evaluate(&behind, &b, &c, &p), SWARP_OK);
    ck_assert_uint_eq(p.inverse_projection, 1);
    ck_assert(p.reasons & SWARP_PLAN_WHY_INVERSE_PROJECTION);
    ck_assert_int_eq(swarp_plan_evaluate(&front, &b, &c, &p), SWARP_OK);
    ck_assert_uint_eq(p.inverse_projection, 0);
    /* the model is symmetric in γ <-> 180° - γ for a directional light */
    swarp_plan_result q;
    ck_assert_int_eq(swarp_plan_evaluate(&behind, &b, &c, &q), SWARP_OK);
    ck_assert_double_eq_tol(p.max_error, q.max_error, 1e-9 * q.max_error);
}
END_TEST

/* ---- 3. optimality against brute force --------------------------------------- */

typedef struct brute_chain {
    swarp_plan_warp warp;
    swarp_plan_scheme scheme;
    uint32_t K;
} brute_chain;

/* Every candidate chain the planner documents, listed here independently
 * (scheme-major, unlike the library's order). */
static size_t brute_chains(brute_chain* out) {
    size_t n = 0;
    for (int w = SWARP_PLAN_WARP_UNIFORM; w <= SWARP_PLAN_WARP_PSM; ++w)
        out[n++] = (brute_chain){(swarp_plan_warp)w, SWARP_PLAN_SCHEME_NONE, 1};
    static const swarp_plan_scheme schemes[2] = {SWARP_PLAN_SCHEME_LOG, SWARP_PLAN_SCHEME_PRACTICAL};
    static const swarp_plan_warp warps[3] = {SWARP_PLAN_WARP_LISPSM_NREPAR, SWARP_PLAN_WARP_UNIFORM,
                                             SWARP_PLAN_WARP_LISPSM_NOPT};
    for (int s = 0; s < 2; ++s)
        for (uint32_t K = 16; K >= 2; --K)
            for (int w = 0; w < 3; ++w) out[n++] = (brute_chain){warps[w], schemes[s], K};
    return n;
}

static void random_scene(swarp_scene_needs* n, swarp_budget* b) {
    memset(n, 0, sizeof *n);
    memset(b, 0, sizeof *b);
    /* random camera frame */
    swarp_vec3 v = {rng_range(-1, 1), rng_range(-1, 1), rng_range(-1, 1)};
    double lv = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (lv < 1e-3) v = (swarp_vec3){0, 0, -1}, lv = 1;
    v = (swarp_vec3){v.x / lv, v.y / lv, v.z / lv};
    swarp_vec3 a = fabs(v.y) < 0.9 ? (swarp_vec3){0, 1, 0} : (swarp_vec3){1, 0, 0};
    /* w = normalised (a - (a.v) v), perpendicular to v */
    double av = a.x * v.x + a.y * v.y + a.z * v.z;
    swarp_vec3 w = {a.x - av * v.x, a.y - av * v.y, a.z - av * v.z};
    double lw = sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
    w = (swarp_vec3){w.x / lw, w.y / lw, w.z / lw};
    n->camera.eye = (swarp_vec3){rng_range(-1e5, 1e5), rng_range(-100, 100), rng_range(-1e5, 1e5)};
    n->camera.dir = v;
    n->camera.up = a;
    n->camera.fovy = rng_range(20.0, 110.0) * DEG;
    n->camera.aspect = rng_range(0.5, 2.5);
    n->camera.z_near = rng_log(0.01, 10.0);
    n->camera.z_far = n->camera.z_near * rng_log(1.2, 1e5);
    double g = rng_unit() < 0.1 ? (rng_unit() < 0.5 ? 0.0 : PI) : rng_range(0.0, PI);
    swarp_vec3 tl = {cos(g) * v.x + sin(g) * w.x, cos(g) * v.y + sin(g) * w.y, cos(g) * v.z + sin(g) * w.z};
    n->light.type = SWARP_LIGHT_DIRECTIONAL;
    n->light.direction = (swarp_vec3){-tl.x, -tl.y, -tl.z};
    n->screen_width = 320 + (uint32_t)(rng_next() % 3500);
    n->screen_height = 240 + (uint32_t)(rng_next() % 2000);
    n->camera_moves = rng_unit() < 0.25;
    n->soft_shadows = rng_unit() < 0.3;
    n->soft_width = n->soft_shadows ? rng_range(1.0, 12.0) : 0.0;
    n->bleed_risk = (swarp_plan_bleed)(rng_next() % 5);
    b->max_error = rng_log(0.2, 200.0);
    b->map_resolution = 256u << (rng_next() % 5);
    static const uint32_t atlases[4] = {0, 2048, 4096, 16384};
    b->atlas_limit = atlases[rng_next() % 4];
    b->max_passes = (uint32_t)(rng_next() % 17); /* 0 = default 16 */
    if (rng_unit() < 0.3) {
        b->pass_cost_ns = rng_log(1e4, 1e7);
        b->time_budget_ns = b->pass_cost_ns * rng_range(0.5, 20.0);
    }
}

START_TEST(optimal_against_brute_force) {
    rng_state = 0x0b7e5eedull;
    brute_chain chains[200];
    size_t nc = brute_chains(chains);
    ck_assert_uint_eq(nc, 96);
    int unmet = 0, met = 0;
    for (int it = 0; it < 1000; ++it) {
        swarp_scene_needs n;
        swarp_budget b;
        random_scene(&n, &b);
        swarp_plan_result p;
        swarp_status s = swarp_plan(&n, &b, &p);
        ck_assert_msg(!swarp_status_is_error(s), "it %d: %s", it, swarp_status_name(s));
        uint32_t max_passes = b.max_passes ? b.max_passes : 16;
        double E = b.max_error;
        /* brute force: every chain's prediction, the rule applied here */
        double best_cost = INFINITY, best_err_at_cost = INFINITY, min_err = INFINITY;
        for (size_t k = 0; k < nc; ++k) {
            if (chains[k].K > max_passes) continue;
            if (n.camera_moves && chains[k].warp != SWARP_PLAN_WARP_UNIFORM) continue;
            swarp_plan_chain c = chain_of(chains[k].warp, chains[k].scheme, chains[k].K);
            c.matrices = SWARP_PLAN_MATRICES_NONE; /* the model decides the choice */
            swarp_plan_result q;
            ck_assert(!swarp_status_is_error(swarp_plan_evaluate(&n, &b, &c, &q)));
            /* the overall maxima are the largest split maxima */
            double smx = 0.0, smz = 0.0;
            for (uint32_t i = 0; i < q.split_count; ++i) {
                smx = fmax(smx, q.split_max_mx[i]);
                smz = fmax(smz, q.split_max_mz[i]);
            }
            ck_assert_double_eq(q.max_mx, smx);
            ck_assert_double_eq(q.max_mz, smz);
            ck_assert_double_eq(q.max_error, fmax(smx, smz));
            ck_assert_double_eq(q.error_area, smx * smz);
            if (q.max_error < min_err) min_err = q.max_error;
            int ok = q.max_error <= E && (b.time_budget_ns == 0.0 || q.cost_ns <= b.time_budget_ns);
            if (!ok) continue;
            if (q.cost_ns < best_cost) {
                best_cost = q.cost_ns;
                best_err_at_cost = q.max_error;
            } else if (q.cost_ns == best_cost && q.max_error < best_err_at_cost) {
                best_err_at_cost = q.max_error;
            }
        }
        ck_assert_uint_le(p.split_count, max_passes);
        if (n.camera_moves) ck_assert_int_eq(p.warp, SWARP_PLAN_WARP_UNIFORM);
        (void)best_err_at_cost;
        if (p.built) {
            /* ranked by measurement: the claim is the measured error's */
            double meas = fmax(p.measured.max_m_s, p.measured.max_m_t);
            if (p.meets_budget) {
                ++met;
                ck_assert_int_eq(s, SWARP_OK);
                ck_assert(meas <= E);
                ck_assert(b.time_budget_ns == 0.0 || p.cost_ns <= b.time_budget_ns);
            } else {
                ++unmet;
                ck_assert_int_eq(s, SWARP_INFO_PLAN_BUDGET_UNMET);
                ck_assert(p.reasons & SWARP_PLAN_WHY_BUDGET_UNMET);
            }
        } else if (isfinite(best_cost)) {
            /* not buildable (point light): the model's rule, as brute force */
            ++met;
            ck_assert_int_eq(s, SWARP_OK);
            ck_assert_uint_eq(p.meets_budget, 1);
            ck_assert_double_eq(p.cost_ns, best_cost); /* no planes: chain cost only */
            ck_assert(p.max_error <= E);
        } else {
            ++unmet;
            ck_assert_int_eq(s, SWARP_INFO_PLAN_BUDGET_UNMET);
            ck_assert_uint_eq(p.meets_budget, 0);
            ck_assert_double_eq_tol(p.max_error, min_err, 1e-9 * min_err);
        }
    }
    /* the random budgets exercise both branches */
    ck_assert_int_gt(met, 200);
    ck_assert_int_gt(unmet, 100);
}
END_TEST

/* ---- the cost model's calibration (swarp_plan_cost_fit) ------------------- */

static double sum_sq(const double* x, const double* y, size_t n, double a, double b) {
    double ss = 0.0;
    for (size_t i = 0; i < n; ++i) ss += (y[i] - a - b * x[i]) * (y[i] - a - b * x[i]);
    return ss;
}

START_TEST(cost_fit_recovers_a_line_and_is_least_squares) {
    /* exact line: overhead 0.4 ms, 2.5 ns per texel */
    double x[5] = {512.0 * 512, 1024.0 * 1024, 2048.0 * 2048, 4096.0 * 4096, 1536.0 * 1536}, y[5];
    for (int i = 0; i < 5; ++i) y[i] = 4e5 + 2.5 * x[i];
    double a = -1, b = -1, rms = -1;
    ck_assert_int_eq(swarp_plan_cost_fit(x, y, 5, &a, &b, &rms), SWARP_OK);
    ck_assert_double_eq_tol(a, 4e5, 1e-6 * 4e5);
    ck_assert_double_eq_tol(b, 2.5, 1e-12 * 2.5);
    ck_assert(rms < 1e-3);
    /* noisy: the defining property of least squares, residuals orthogonal
     * to 1 and x, and any step away raises the sum of squares */
    static const double noise[5] = {3e4, -5e4, 2e4, 1e4, -1e4};
    for (int i = 0; i < 5; ++i) y[i] += noise[i];
    ck_assert_int_eq(swarp_plan_cost_fit(x, y, 5, &a, &b, NULL), SWARP_OK);
    double r0 = 0.0, r1 = 0.0;
    for (int i = 0; i < 5; ++i) {
        r0 += y[i] - a - b * x[i];
        r1 += (y[i] - a - b * x[i]) * x[i];
    }
    ck_assert(fabs(r0) < 1e-6 * 5e4 * 5);
    ck_assert(fabs(r1) < 1e-6 * 5e4 * 5 * 1.7e7);
    double ss = sum_sq(x, y, 5, a, b);
    ck_assert(ss < sum_sq(x, y, 5, a * 1.01, b));
    ck_assert(ss < sum_sq(x, y, 5, a, b * 1.001));
    ck_assert(ss < sum_sq(x, y, 5, a, b * 0.999));
}
END_TEST

START_TEST(cost_fit_keeps_both_terms_non_negative) {
    /* a line through y = -1e5 + 3 x: the free fit's overhead is negative,
     * the constrained optimum is the line through the origin */
    double x[3] = {1e6, 4e6, 1.6e7}, y[3];
    for (int i = 0; i < 3; ++i) y[i] = -1e5 + 3.0 * x[i];
    double a = -1, b = -1;
    ck_assert_int_eq(swarp_plan_cost_fit(x, y, 3, &a, &b, NULL), SWARP_OK);
    ck_assert_double_eq(a, 0.0);
    double sxy = 0, sxx = 0;
    for (int i = 0; i < 3; ++i) { sxy += x[i] * y[i]; sxx += x[i] * x[i]; }
    ck_assert_double_eq_tol(b, sxy / sxx, 1e-12 * b);
    double ss = sum_sq(x, y, 3, a, b);
    ck_assert(ss <= sum_sq(x, y, 3, 0.0, b * 1.0001) && ss <= sum_sq(x, y, 3, 0.0, b * 0.9999));
    ck_assert(ss <= sum_sq(x, y, 3, 1e3, b - 1e3 * 3 / 2.1e7));
    /* time falling with texels: the slope is 0 and the overhead the mean */
    double yd[3] = {3e6, 2e6, 1e6};
    ck_assert_int_eq(swarp_plan_cost_fit(x, yd, 3, &a, &b, NULL), SWARP_OK);
    ck_assert_double_eq(b, 0.0);
    ck_assert_double_eq_tol(a, 2e6, 1e-9 * 2e6);
}
END_TEST

START_TEST(cost_fit_bad_input_leaves_outputs) {
    double x[3] = {1e6, 4e6, 1.6e7}, y[3] = {1e6, 2e6, 5e6};
    double a = 7, b = 8, r = 9;
    ck_assert_int_eq(swarp_plan_cost_fit(NULL, y, 3, &a, &b, &r), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_cost_fit(x, NULL, 3, &a, &b, &r), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_cost_fit(x, y, 3, NULL, &b, &r), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_cost_fit(x, y, 3, &a, NULL, &r), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_cost_fit(x, y, 1, &a, &b, &r), SWARP_ERR_OUT_OF_RANGE);
    double xe[3] = {4e6, 4e6, 4e6};
    ck_assert_int_eq(swarp_plan_cost_fit(xe, y, 3, &a, &b, &r), SWARP_ERR_DEGENERATE);
    double xz[3] = {0.0, 4e6, 1.6e7};
    ck_assert_int_eq(swarp_plan_cost_fit(xz, y, 3, &a, &b, &r), SWARP_ERR_OUT_OF_RANGE);
    double yn[3] = {1e6, -1.0, 5e6};
    ck_assert_int_eq(swarp_plan_cost_fit(x, yn, 3, &a, &b, &r), SWARP_ERR_OUT_OF_RANGE);
    double yi[3] = {1e6, NAN, 5e6};
    ck_assert_int_eq(swarp_plan_cost_fit(x, yi, 3, &a, &b, &r), SWARP_ERR_NON_FINITE);
    double yb[3] = {0.0, 0.0, 1e300}; /* the fit's slope beyond what swarp_plan accepts */
    ck_assert_int_eq(swarp_plan_cost_fit(x, yb, 3, &a, &b, &r), SWARP_ERR_OUT_OF_RANGE);
    ck_assert(a == 7 && b == 8 && r == 9);
}
END_TEST

START_TEST(plan_uses_the_calibrated_cost) {
    swarp_scene_needs n = scene(60.0, 300.0);
    swarp_budget b = budget_of(2.0);
    b.map_resolution = 1024;
    b.pass_overhead_ns = 3e5;
    b.texel_cost_ns = 2.0;
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&n, &b, &p)));
    ck_assert_int_eq(p.cost_model, SWARP_PLAN_COST_LINEAR);
    double r2 = (double)p.map_resolution * p.map_resolution;
    ck_assert_double_eq_tol(p.cost_ns, p.split_count * (3e5 + 2.0 * r2), 1e-9 * p.cost_ns);
    char text[SWARP_PLAN_EXPLAIN_MAX];
    size_t cnt;
    ck_assert_int_eq(swarp_plan_explain(&p, text, sizeof text, &cnt), SWARP_OK);
    ck_assert_ptr_nonnull(strstr(text, "cost model calibrated"));
    /* soft shadows with a wide kernel: the blur pass defaults to a quarter
     * of the calibrated pass at that resolution */
    n.soft_shadows = 1;
    n.soft_width = 8.0;
    ck_assert(!swarp_status_is_error(swarp_plan(&n, &b, &p)));
    r2 = (double)p.map_resolution * p.map_resolution;
    ck_assert_double_eq_tol(p.cost_ns, p.split_count * (3e5 + 2.0 * r2) * (1.0 + 2 * 0.25), 1e-9 * p.cost_ns);
    /* per-pass constant, and the default (uncalibrated) */
    b.pass_overhead_ns = b.texel_cost_ns = 0.0;
    b.pass_cost_ns = 1e6;
    ck_assert(!swarp_status_is_error(swarp_plan(&n, &b, &p)));
    ck_assert_int_eq(p.cost_model, SWARP_PLAN_COST_PER_PASS);
    b.pass_cost_ns = 0.0;
    ck_assert(!swarp_status_is_error(swarp_plan(&n, &b, &p)));
    ck_assert_int_eq(p.cost_model, SWARP_PLAN_COST_UNCALIBRATED);
    ck_assert_int_eq(swarp_plan_explain(&p, text, sizeof text, &cnt), SWARP_OK);
    ck_assert_ptr_nonnull(strstr(text, "cost model uncalibrated"));
    swarp_plan_result bad = p;
    bad.cost_model = (swarp_plan_cost_model)9;
    ck_assert_int_eq(swarp_plan_explain(&bad, text, sizeof text, &cnt), SWARP_ERR_UNKNOWN_ENUM);
    bad.cost_model = SWARP_PLAN_COST_PER_PASS;
    ck_assert_int_eq(swarp_plan_explain(&bad, text, sizeof text, &cnt), SWARP_OK);
    ck_assert_ptr_nonnull(strstr(text, "per-pass time"));
}
END_TEST

/* ---- 4. monotonicity (of the model's rule) ------------------------------------------------------------ */

START_TEST(tighter_error_budget_never_cheaper) {
    rng_state = 0x6d6f6e6full;
    for (int it = 0; it < 150; ++it) {
        swarp_scene_needs n;
        swarp_budget b;
        random_scene(&n, &b);
        /* the model's rule is monotone; the measured search is not (each
         * budget re-calibrates on a different chain: docs/planning.md §4) */
        n.plan_by = SWARP_PLAN_BY_MODEL;
        double prev_cost = -1.0;
        double prev_err = INFINITY;
        for (int k = 0; k < 40; ++k) {
            b.max_error = 300.0 * pow(0.8, k);
            swarp_plan_result p;
            swarp_status s = swarp_plan(&n, &b, &p);
            ck_assert(!swarp_status_is_error(s));
            ck_assert_msg(p.cost_ns >= prev_cost, "it %d k %d: cost %g < %g", it, k, p.cost_ns, prev_cost);
            if (p.cost_ns == prev_cost) ck_assert(p.max_error <= prev_err * (1 + 1e-9));
            prev_cost = p.cost_ns;
            prev_err = p.max_error;
        }
    }
}
END_TEST

/* ---- 5. bad input and text ------------------------------------------------------- */

typedef void (*mutate_fn)(swarp_scene_needs*, swarp_budget*);
#define MUT(name, ...) static void name(swarp_scene_needs* n, swarp_budget* b) { (void)n; (void)b; __VA_ARGS__; }
MUT(m_eye_nan, n->camera.eye.x = NAN)
MUT(m_dir_zero, n->camera.dir = (swarp_vec3){0, 0, 0})
MUT(m_up_parallel, n->camera.up = (swarp_vec3){0, 0, -3})
MUT(m_fovy_zero, n->camera.fovy = 0.0)
MUT(m_fovy_pi, n->camera.fovy = PI)
MUT(m_near_zero, n->camera.z_near = 0.0)
MUT(m_far_le_near, n->camera.z_far = 0.5)
MUT(m_aspect, n->camera.aspect = -1.0)
MUT(m_cam_reserved, n->camera._reserved[2] = 1)
MUT(m_needs_reserved, n->_reserved[0] = 1)
MUT(m_plan_by, n->plan_by = (swarp_plan_by)2)
MUT(m_needs_pad, n->_pad0 = 1)
MUT(m_budget_overhead_neg, b->pass_overhead_ns = -1.0)
MUT(m_budget_texel_nan, b->texel_cost_ns = NAN)
MUT(m_budget_texel_big, b->texel_cost_ns = 1e6)
MUT(m_budget_pad, b->_pad0 = 1)
MUT(m_light_reserved0, n->light._reserved0 = 1)
MUT(m_light_type, n->light.type = (swarp_light_type)7)
MUT(m_light_zero, n->light.direction = (swarp_vec3){0, 0, 0})
MUT(m_light_inf, n->light.direction.y = INFINITY)
MUT(m_cone, n->light.type = SWARP_LIGHT_POINT; n->light.position = (swarp_vec3){0, 100, 0}; n->light.cone_angle = 2.0)
MUT(m_point_at_centre, n->light.type = SWARP_LIGHT_POINT; n->light.position = (swarp_vec3){0, 2, -50.5})
MUT(m_bleed, n->bleed_risk = (swarp_plan_bleed)9)
MUT(m_planes, n->plane_count = 5)
MUT(m_plane_zero, n->plane_count = 1; n->planes[0] = (swarp_plane){0, 0, 0, 1})
MUT(m_plane_nan, n->plane_count = 1; n->planes[0] = (swarp_plane){0, NAN, 0, 1})
MUT(m_box_inverted, n->scene_box.min = (swarp_vec3){1, 1, 1})
MUT(m_box_nan, n->scene_box.max.z = NAN)
MUT(m_box_behind, n->scene_box.min = (swarp_vec3){-1, -1, 10}; n->scene_box.max = (swarp_vec3){1, 1, 20})
MUT(m_soft_width, n->soft_shadows = 1; n->soft_width = 0.5)
MUT(m_soft_nan, n->soft_width = NAN)
MUT(m_moves, n->camera_moves = 2)
MUT(m_error_neg, b->max_error = -1.0)
MUT(m_error_nan, b->max_error = NAN)
MUT(m_passes, b->max_passes = 33)
MUT(m_map_res, b->map_resolution = 70000)
MUT(m_screen, n->screen_width = 70000)
MUT(m_time_neg, b->time_budget_ns = -1.0)
MUT(m_pass_inf, b->pass_cost_ns = INFINITY)

static const struct {
    mutate_fn fn;
    swarp_status want;
} bad_cases[] = {
    {m_eye_nan, SWARP_ERR_NON_FINITE},
    {m_dir_zero, SWARP_ERR_ZERO_VECTOR},
    {m_up_parallel, SWARP_ERR_DEGENERATE},
    {m_fovy_zero, SWARP_ERR_FOV},
    {m_fovy_pi, SWARP_ERR_FOV},
    {m_near_zero, SWARP_ERR_NEAR_FAR},
    {m_far_le_near, SWARP_ERR_NEAR_FAR},
    {m_aspect, SWARP_ERR_OUT_OF_RANGE},
    {m_cam_reserved, SWARP_ERR_RESERVED_NONZERO},
    {m_needs_reserved, SWARP_ERR_RESERVED_NONZERO},
    {m_plan_by, SWARP_ERR_UNKNOWN_ENUM},
    {m_needs_pad, SWARP_ERR_RESERVED_NONZERO},
    {m_budget_overhead_neg, SWARP_ERR_OUT_OF_RANGE},
    {m_budget_texel_nan, SWARP_ERR_NON_FINITE},
    {m_budget_texel_big, SWARP_ERR_OUT_OF_RANGE},
    {m_budget_pad, SWARP_ERR_RESERVED_NONZERO},
    {m_light_reserved0, SWARP_ERR_RESERVED_NONZERO},
    {m_light_type, SWARP_ERR_UNKNOWN_ENUM},
    {m_light_zero, SWARP_ERR_ZERO_VECTOR},
    {m_light_inf, SWARP_ERR_NON_FINITE},
    {m_cone, SWARP_ERR_OUT_OF_RANGE},
    {m_point_at_centre, SWARP_ERR_DEGENERATE},
    {m_bleed, SWARP_ERR_UNKNOWN_ENUM},
    {m_planes, SWARP_ERR_PLAN_TOO_MANY_PLANES},
    {m_plane_zero, SWARP_ERR_ZERO_VECTOR},
    {m_plane_nan, SWARP_ERR_NON_FINITE},
    {m_box_inverted, SWARP_ERR_BOX_INVERTED},
    {m_box_nan, SWARP_ERR_NON_FINITE},
    {m_box_behind, SWARP_ERR_PLAN_EMPTY_VIEW},
    {m_soft_width, SWARP_ERR_OUT_OF_RANGE},
    {m_soft_nan, SWARP_ERR_NON_FINITE},
    {m_moves, SWARP_ERR_OUT_OF_RANGE},
    {m_error_neg, SWARP_ERR_OUT_OF_RANGE},
    {m_error_nan, SWARP_ERR_NON_FINITE},
    {m_passes, SWARP_ERR_OUT_OF_RANGE},
    {m_map_res, SWARP_ERR_RESOLUTION},
    {m_screen, SWARP_ERR_RESOLUTION},
    {m_time_neg, SWARP_ERR_OUT_OF_RANGE},
    {m_pass_inf, SWARP_ERR_NON_FINITE},
};

START_TEST(bad_input_status_and_untouched) {
    swarp_scene_needs n = scene(90.0, 100.0);
    swarp_budget b = budget_of(1.0);
    bad_cases[_i].fn(&n, &b);
    swarp_plan_result p, sentinel;
    memset(&sentinel, 0xA5, sizeof sentinel);
    p = sentinel;
    swarp_status s = swarp_plan(&n, &b, &p);
    ck_assert_msg(s == bad_cases[_i].want, "case %d: %s", _i, swarp_status_name(s));
    ck_assert_int_eq(memcmp(&p, &sentinel, sizeof p), 0);
    /* evaluate validates the same way */
    swarp_plan_chain c = chain_of(SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1);
    s = swarp_plan_evaluate(&n, &b, &c, &p);
    ck_assert_int_eq(s, bad_cases[_i].want);
    ck_assert_int_eq(memcmp(&p, &sentinel, sizeof p), 0);
}
END_TEST

START_TEST(bad_chain_and_null) {
    swarp_scene_needs n = scene(90.0, 100.0);
    swarp_budget b = budget_of(1.0);
    swarp_plan_result p, sentinel;
    memset(&sentinel, 0x5A, sizeof sentinel);
    p = sentinel;
    ck_assert_int_eq(swarp_plan(&n, &b, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, NULL, &p), SWARP_ERR_NULL_POINTER);
    swarp_plan_chain c = chain_of(SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_LOG, 17);
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_ERR_SPLIT_COUNT);
    c = chain_of(SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 2);
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_ERR_SPLIT_COUNT);
    c = chain_of(SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_LOG, 1);
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_ERR_SPLIT_COUNT);
    c = chain_of((swarp_plan_warp)9, SWARP_PLAN_SCHEME_NONE, 1);
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_ERR_UNKNOWN_ENUM);
    c = chain_of(SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_SCHEME_NONE, 1);
    c._reserved[1] = 1;
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_ERR_RESERVED_NONZERO);
    c._reserved[1] = 0;
    c.matrices = (swarp_plan_matrices)3;
    ck_assert_int_eq(swarp_plan_evaluate(&n, &b, &c, &p), SWARP_ERR_UNKNOWN_ENUM);
    ck_assert_int_eq(memcmp(&p, &sentinel, sizeof p), 0);
}
END_TEST

START_TEST(explain_text_and_capacity) {
    swarp_scene_needs n = needs_of(&table[28]); /* floor-lixel */
    n.soft_shadows = 1;
    n.soft_width = 8;
    n.bleed_risk = SWARP_PLAN_BLEED_HIGH;
    swarp_budget b = budget_of(1.0);
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&n, &b, &p)));
    size_t need = 0;
    ck_assert_int_eq(swarp_plan_explain(&p, NULL, 0, &need), SWARP_ERR_CAPACITY);
    ck_assert_uint_gt(need, 100);
    ck_assert_uint_le(need, SWARP_PLAN_EXPLAIN_MAX);
    char small[64];
    memset(small, '#', sizeof small);
    size_t cnt = 0;
    ck_assert_int_eq(swarp_plan_explain(&p, small, sizeof small, &cnt), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(cnt, need);
    for (size_t i = 0; i < sizeof small; ++i) ck_assert_int_eq(small[i], '#');
    char text[SWARP_PLAN_EXPLAIN_MAX];
    ck_assert_int_eq(swarp_plan_explain(&p, text, sizeof text, &cnt), SWARP_OK);
    ck_assert_uint_eq(cnt, need);
    ck_assert_uint_eq(strlen(text) + 1, need);
    ck_assert_ptr_nonnull(strstr(text, "evsm"));
    ck_assert_ptr_nonnull(strstr(text, swarp_plan_warp_name(p.warp)));
    ck_assert_ptr_nonnull(strstr(text, "plane 0: lixel map"));
    ck_assert_ptr_nonnull(strstr(text, "no stabilisation: the camera is static"));
    ck_assert_ptr_null(strstr(text, "nan"));
    /* one "why:" line per reason bit */
    int bits = 0, lines = 0;
    for (uint32_t r = p.reasons; r; r &= r - 1) ++bits;
    for (const char* q = text; (q = strstr(q, "why: ")) != NULL; q += 5) ++lines;
    ck_assert_int_eq(bits, lines);
    /* bad arguments */
    ck_assert_int_eq(swarp_plan_explain(NULL, text, sizeof text, &cnt), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_explain(&p, text, sizeof text, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert_int_eq(swarp_plan_explain(&p, NULL, 10, &cnt), SWARP_ERR_NULL_POINTER);
    swarp_plan_result bad = p;
    bad.filter = (swarp_plan_filter)77;
    ck_assert_int_eq(swarp_plan_explain(&bad, text, sizeof text, &cnt), SWARP_ERR_UNKNOWN_ENUM);
    /* the worst case fits the documented bound: 16 splits, 4 planes, every reason */
    bad = p;
    bad.split_count = 16;
    bad.plane_count = 4;
    bad.reasons = 0xFFFFFFFFu;
    for (int i = 0; i < 17; ++i) bad.splits[i] = -1.23456789e-300;
    for (int i = 0; i < 16; ++i) bad.n_prime[i] = bad.split_max_mx[i] = bad.split_max_mz[i] = -1.2345e300;
    /* with the matrices' n' and measured error on every line */
    bad.built = 1;
    bad.measured.samples = 1;
    bad.measured.max_m_s = bad.measured.max_m_t = bad.measured.max_sigma = -1.2345e300;
    bad.measured.at = (swarp_vec3){-1.2345e300, -1.2345e300, -1.2345e300};
    for (int i = 0; i < 16; ++i) {
        bad.built_n_eye[i] = bad.split_measured[i].max_sigma = -1.2345e300;
        bad.split_measured[i].samples = 1;
    }
    ck_assert_int_eq(swarp_plan_explain(&bad, NULL, 0, &cnt), SWARP_ERR_CAPACITY);
    ck_assert_uint_le(cnt, SWARP_PLAN_EXPLAIN_MAX);
    ck_assert_str_eq(swarp_plan_warp_name((swarp_plan_warp)99), "?");
}
END_TEST

START_TEST(plan_is_cheap_and_finite_at_extremes) {
    /* far/near 1e6, coordinates 1e6, γ at 0, Θ/3, Θ, 90°, 180° */
    double gs[] = {0.0, 10.0, 30.0, 90.0, 179.999, 180.0};
    for (int i = 0; i < 6; ++i) {
        swarp_scene_needs n = scene(gs[i], 1e6);
        n.camera.eye = (swarp_vec3){1e6, 1e5, -1e6};
        swarp_budget b = budget_of(0.5);
        swarp_plan_result p;
        swarp_status s = swarp_plan(&n, &b, &p);
        ck_assert(!swarp_status_is_error(s));
        ck_assert(isfinite(p.max_error) && p.max_error > 0.0);
        for (uint32_t k = 0; k < p.split_count; ++k) ck_assert(p.n_prime[k] > 0.0);
    }
}
END_TEST

START_TEST(random_wild_inputs_never_nan) {
    /* any valid input: coordinates to 1e6, fovy in (0, 180°), aspect 1e-3..1e3,
     * near 1e-4.., far/near to 3e6, lights along +-view, planes, boxes, odd
     * resolutions and limits: a non-error status never comes with a
     * non-finite number, and explain() always succeeds */
    rng_state = 0xf022ull;
    int ok = 0;
    for (int it = 0; it < 3000; ++it) {
        swarp_scene_needs n;
        swarp_budget b;
        memset(&n, 0, sizeof n);
        memset(&b, 0, sizeof b);
        n.camera.eye = (swarp_vec3){rng_range(-1e6, 1e6), rng_range(-1e6, 1e6), rng_range(-1e6, 1e6)};
        n.camera.dir = (swarp_vec3){rng_range(-1, 1), rng_range(-1, 1), rng_range(-1, 1)};
        n.camera.up = (swarp_vec3){rng_range(-1, 1), rng_range(-1, 1), rng_range(-1, 1)};
        n.camera.fovy = rng_range(1e-3, PI - 1e-3);
        n.camera.aspect = rng_log(1e-3, 1e3);
        n.camera.z_near = rng_log(1e-4, 1e4);
        n.camera.z_far = n.camera.z_near * rng_log(1.0001, 3e6);
        n.light.type = rng_unit() < 0.2 ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
        n.light.direction = (swarp_vec3){rng_range(-1, 1), rng_range(-1, 1), rng_range(-1, 1)};
        double r = rng_unit();
        if (r < 0.1) n.light.direction = n.camera.dir;
        else if (r < 0.2) n.light.direction = (swarp_vec3){-n.camera.dir.x, -n.camera.dir.y, -n.camera.dir.z};
        n.light.position = (swarp_vec3){rng_range(-1e6, 1e6), rng_range(-1e6, 1e6), rng_range(-1e6, 1e6)};
        n.soft_shadows = rng_unit() < 0.5;
        n.soft_width = n.soft_shadows ? rng_range(1.0, 30.0) : 0.0;
        n.bleed_risk = (swarp_plan_bleed)(rng_next() % 5);
        n.camera_moves = rng_unit() < 0.3;
        n.allow_depth_clamp = rng_unit() < 0.5;
        n.plane_count = (uint32_t)(rng_next() % 5);
        for (uint32_t i = 0; i < n.plane_count; ++i)
            n.planes[i] = (swarp_plane){rng_range(-1, 1), rng_range(-1, 1), rng_range(-1, 1), rng_range(-1e6, 1e6)};
        if (rng_unit() < 0.3) {
            n.scene_box.min = (swarp_vec3){rng_range(-1e6, 1e6), rng_range(-1e6, 1e6), rng_range(-1e6, 1e6)};
            n.scene_box.max = (swarp_vec3){n.scene_box.min.x + rng_range(0, 1e6), n.scene_box.min.y + rng_range(0, 1e6),
                                           n.scene_box.min.z + rng_range(0, 1e6)};
        }
        b.max_error = rng_log(1e-2, 1e2);
        b.map_resolution = (uint32_t)(rng_next() % 65537);
        b.atlas_limit = (uint32_t)(rng_next() % 65537);
        b.max_passes = (uint32_t)(rng_next() % 33);
        swarp_plan_result p;
        swarp_status s = swarp_plan(&n, &b, &p);
        if (swarp_status_is_error(s)) {
            /* only the documented refusals of valid-looking input */
            ck_assert_msg(s == SWARP_ERR_PLAN_EMPTY_VIEW || s == SWARP_ERR_DEGENERATE, "%s", swarp_status_name(s));
            continue;
        }
        ++ok;
        ck_assert(isfinite(p.max_error) && p.max_error > 0.0);
        ck_assert(isfinite(p.cost_ns) && isfinite(p.texels) && isfinite(p.error_area));
        for (uint32_t k = 0; k <= p.split_count; ++k) ck_assert(isfinite(p.splits[k]));
        for (uint32_t k = 0; k < p.split_count; ++k) {
            ck_assert(p.n_prime[k] > 0.0); /* +inf = uniform is allowed */
            ck_assert(isfinite(p.split_max_mx[k]) && isfinite(p.split_max_mz[k]));
        }
        char text[SWARP_PLAN_EXPLAIN_MAX];
        size_t cnt;
        ck_assert_int_eq(swarp_plan_explain(&p, text, sizeof text, &cnt), SWARP_OK);
    }
    ck_assert_int_gt(ok, 1000);
}
END_TEST

static Suite* plan_suite(void) {
    Suite* s = suite_create("plan");
    TCase* tc = tcase_create("plan");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, model_equals_core_lloyd_at_overhead_light);
    tcase_add_test(tc, model_equals_dense_sampling_any_gamma);
    tcase_add_test(tc, model_equals_geometry_setup_at_overhead_light);
    tcase_add_test(tc, duelling_frusta_fade_every_warp_to_uniform);
    tcase_add_loop_test(tc, expectations_table, 0, (int)(sizeof table / sizeof table[0]));
    tcase_add_test(tc, defaults_are_the_documented_scene);
    tcase_add_test(tc, cost_fit_recovers_a_line_and_is_least_squares);
    tcase_add_test(tc, cost_fit_keeps_both_terms_non_negative);
    tcase_add_test(tc, cost_fit_bad_input_leaves_outputs);
    tcase_add_test(tc, plan_uses_the_calibrated_cost);
    tcase_add_test(tc, forced_psm_inverse_projection_only_behind);
    tcase_add_test(tc, optimal_against_brute_force);
    tcase_add_test(tc, tighter_error_budget_never_cheaper);
    tcase_add_loop_test(tc, bad_input_status_and_untouched, 0, (int)(sizeof bad_cases / sizeof bad_cases[0]));
    tcase_add_test(tc, bad_chain_and_null);
    tcase_add_test(tc, explain_text_and_capacity);
    tcase_add_test(tc, plan_is_cheap_and_finite_at_extremes);
    tcase_add_test(tc, random_wild_inputs_never_nan);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) {
    int failed = tu_run_suite(plan_suite());
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
