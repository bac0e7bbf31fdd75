/* The planner: the cheapest chain of shadow-map effects whose predicted error
 * meets the caller's budget, with a reason for every choice.
 *
 *   error model   Lloyd's m_x, m_z [RHS] (2.3)-(2.8) generalised to a light
 *                 at angle γ to the view (sw_split_error below; reduces to
 *                 (2.3)/(2.4) at γ = 90°, light-space extent = W_lz of
 *                 [RHS] (3.5) for γ >= Θ)            docs/planning.md §2
 *   warp params   core: [RHS] (3.2), (3.3)-(3.5), (4.2), [GMNPR] (8)
 *   split schemes core: [RHS] (3.7), (3.8)
 *   cost model    passes × per-pass time + prefilter blur passes,
 *                 default per-pass time fitted to [RHS] Table 7.1  §3
 *   selection     fewest passes that meet the budget, then lower error,
 *                 then the simpler (earlier) candidate              §4
 *
 * Everything is closed form: a plan evaluates 96 candidate chains with at
 * most 16 splits each and two error evaluations per split (the maxima of the
 * generalised curves lie at the split ends), a few microseconds.
 */
#include <float.h>
#include <stddef.h>

#include "common/swarp_internal.h"
#include "common/decimal.h"

/* ---- constants (docs/planning.md says where each comes from) ------------ */

/* Default per-pass time: the linear fit of [RHS] Table 7.1 (Sights of Paris):
 * 1+1 passes 143 fps, 4+1 90 fps, 8+1 60 fps, 16+1 36 fps give 1.39 ms per
 * additional shadow pass (the three slopes are 1.37, 1.39 and 1.39 ms). */
#define SW_DEFAULT_PASS_NS 1.39e6
/* Prefilter blur pass (separable, one direction over one map): assumed a
 * quarter of a geometry pass until the demo measures it. */
#define SW_DEFAULT_BLUR_FRACTION 0.25
/* 64-level approximate stabilisation [RHS] §3.5: the focus extent rounds up
 * to the next level; with levels 1/64 of the extent apart the texels grow by
 * at most 1/64 (an assumption: [RHS] gives the level count only). */
#define SW_STABLE_FACTOR (1.0 + 1.0 / 64.0)
/* Pseudo-near and pseudo-far as fractions of the depth range: [RHS] Fig. 4.2
 * used n_p ≈ f_p ≈ 30 of a [1, 300] range, i.e. 0.1 each. */
#define SW_PSEUDO_NP 0.1
#define SW_PSEUDO_FP 0.1
/* Kernels up to this width (texels) are cheaper as PCF (w² taps, no
 * prefilter passes, no light bleeding) than as a prefiltered moment map. */
#define SW_PCF_MAX_WIDTH 4.0
#define SW_DEFAULT_SOFT_WIDTH 3.0
#define SW_LVSM_LAYERS 4u       /* [VSM] Fig. 4.2 used a 4-layer LVSM */
#define SW_EVSM_C_POS 40.0      /* exponents that stay finite in fp32 [VSM] §4.2 */
#define SW_EVSM_C_NEG 5.0
/* Lixel planes: the light must reach the plane at more than 5° elevation,
 * else the plane's light image degenerates ([LIXEL] §4 bad cases). */
#define SW_LIXEL_MIN_ELEVATION_SIN 0.08715574274765817 /* sin 5° */
/* Two errors closer than this relative amount are a tie (then the simpler
 * candidate wins); far above rounding, far below any meaningful difference. */
#define SW_ERR_TIE_REL 1e-9
/* The largest resolution / pass count accepted (sanity limits). */
#define SW_MAX_RES 65536u
#define SW_MAX_PASSES 32u

/* Largest texel_cost_ns: a pass of the largest map (65536² texels) then
 * stays within SWARP_PLAN_MAX_COST_NS, so every predicted cost is finite. */
#define SW_MAX_TEXEL_NS (SWARP_PLAN_MAX_COST_NS / (65536.0 * 65536.0))

/* ---- resolved inputs ------------------------------------------------------ */

typedef struct sw_pin {
    swarp_camera cam;           /* the camera as given (or the default) */
    swarp_light light;          /* the light as given (or the default) */
    swarp_aabb box;             /* the scene box (bounded only) */
    int bounded;                /* the needs give a scene box */
    swarp_vec3 eye, view, up;   /* view and up unit length */
    double theta;               /* Θ = fovy / 2 */
    double aspect;
    double z_near, z_far;           /* adjusted range */
    int near_far_adjusted;
    swarp_vec3 to_light;        /* unit, from the scene toward the light */
    int point_light;
    swarp_vec3 light_pos;
    double gamma;               /* angle(view, to_light) in [0, pi] */
    double gamma_f;             /* folded to [0, pi/2] */
    double res_ix, res_iy;      /* screen */
    int moves, soft;
    double soft_width;
    swarp_plan_bleed bleed;
    int allow_clamp;
    int by_model;               /* SWARP_PLAN_BY_MODEL: no matrices built */
    uint32_t plane_count;
    swarp_plane planes[SWARP_PLAN_MAX_PLANES];
    /* budget */
    double max_error;
    uint32_t map_res, atlas_limit, max_passes;
    double time_budget, pass_ns, blur_ns;
    double overhead_ns, texel_ns;   /* calibrated model (cost_model LINEAR) */
    swarp_plan_cost_model cost_model;
} sw_pin;

static int sw_all_zero(const void* p, size_t n) {
    const unsigned char* b = (const unsigned char*)p;
    for (size_t i = 0; i < n; ++i)
        if (b[i]) return 0;
    return 1;
}

/* The caller's camera, checked by the common camera check
 * (src/common/check.c), as the planner's view frame: unit view and up,
 * Θ = fovy / 2, the camera's own depth range. */
static swarp_status sw_resolve_camera(const swarp_camera* c, sw_pin* in) {
    swarp_status s = sw_check_camera(c);
    if (s != SWARP_OK) return s;
    swarp_vec3 v, u;
    if (!sw_normalize(c->dir, &v) || !sw_normalize(c->up, &u)) return SWARP_ERR_ZERO_VECTOR;
    in->eye = c->eye;
    in->view = v;
    in->up = u;
    in->theta = 0.5 * c->fovy;
    in->aspect = c->aspect;
    in->z_near = c->z_near;
    in->z_far = c->z_far;
    in->cam = *c;
    return SWARP_OK;
}

/* The caller's light, checked by the common light check: a point light's
 * position, or the unit direction toward a directional light. */
static swarp_status sw_resolve_light(const swarp_light* l, sw_pin* in) {
    swarp_status s = sw_check_light(l);
    if (s != SWARP_OK) return s;
    if (l->type == SWARP_LIGHT_POINT) {
        in->point_light = 1;
        in->light_pos = l->position;
    } else {
        swarp_vec3 d;
        if (!sw_normalize(l->direction, &d)) return SWARP_ERR_ZERO_VECTOR;
        in->point_light = 0;
        in->to_light = sw_scale(d, -1.0);
    }
    in->light = *l;
    return SWARP_OK;
}

/* Camera and light, each all zero for the documented default: camera 2
 * units above the ground looking along -z (fovy 60°, aspect 4/3, [1, 100]),
 * the sun at zenith. */
static swarp_status sw_resolve_view(const swarp_scene_needs* needs, sw_pin* in) {
    swarp_status s;
    if (sw_all_zero(&needs->camera, sizeof needs->camera)) {
        in->eye = sw_v3(0.0, 2.0, 0.0);
        in->view = sw_v3(0.0, 0.0, -1.0);
        in->up = sw_v3(0.0, 1.0, 0.0);
        in->theta = SWARP_PI / 6.0;
        in->aspect = 4.0 / 3.0;
        in->z_near = 1.0;
        in->z_far = 100.0;
        memset(&in->cam, 0, sizeof in->cam);
        in->cam.eye = in->eye;
        in->cam.dir = in->view;
        in->cam.up = in->up;
        in->cam.fovy = 2.0 * in->theta;
        in->cam.aspect = in->aspect;
        in->cam.z_near = in->z_near;
        in->cam.z_far = in->z_far;
    } else if ((s = sw_resolve_camera(&needs->camera, in)) != SWARP_OK) {
        return s;
    }
    if (sw_all_zero(&needs->light, sizeof needs->light)) {
        in->point_light = 0;
        in->to_light = sw_v3(0.0, 1.0, 0.0);
        memset(&in->light, 0, sizeof in->light);
        in->light.type = SWARP_LIGHT_DIRECTIONAL;
        in->light.direction = sw_v3(0.0, -1.0, 0.0);
    } else if ((s = sw_resolve_light(&needs->light, in)) != SWARP_OK) {
        return s;
    }
    return SWARP_OK;
}

/* The scene needs besides camera and light: the box (all zero: unbounded,
 * else the common box check), flags, filter width, bleed, planes, screen. */
static swarp_status sw_check_needs(const swarp_scene_needs* needs) {
    const swarp_aabb* box = &needs->scene_box;
    if (!sw_all_zero(box, sizeof *box)) {
        swarp_status s = sw_check_box(box);
        if (s != SWARP_OK) return s;
    }
    if (!sw_finite(needs->soft_width)) return SWARP_ERR_NON_FINITE;
    if (needs->camera_moves > 1 || needs->soft_shadows > 1 || needs->allow_depth_clamp > 1)
        return SWARP_ERR_OUT_OF_RANGE;
    if (needs->soft_width != 0.0 && !(needs->soft_width >= 1.0)) return SWARP_ERR_OUT_OF_RANGE;
    if ((uint32_t)needs->bleed_risk > (uint32_t)SWARP_PLAN_BLEED_EXTREME ||
        (uint32_t)needs->plan_by > (uint32_t)SWARP_PLAN_BY_MODEL)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (needs->plane_count > SWARP_PLAN_MAX_PLANES) return SWARP_ERR_PLAN_TOO_MANY_PLANES;
    for (uint32_t i = 0; i < needs->plane_count; ++i) {
        const swarp_plane* p = &needs->planes[i];
        if (!sw_finite(p->a) || !sw_finite(p->b) || !sw_finite(p->c) || !sw_finite(p->d))
            return SWARP_ERR_NON_FINITE;
        if (p->a == 0.0 && p->b == 0.0 && p->c == 0.0) return SWARP_ERR_ZERO_VECTOR;
    }
    if (needs->screen_width > SW_MAX_RES || needs->screen_height > SW_MAX_RES)
        return SWARP_ERR_RESOLUTION;
    return SWARP_OK;
}

static swarp_status sw_check_budget(const swarp_budget* budget) {
    if (!sw_finite(budget->max_error) || !sw_finite(budget->time_budget_ns) ||
        !sw_finite(budget->pass_cost_ns) || !sw_finite(budget->blur_pass_cost_ns) ||
        !sw_finite(budget->pass_overhead_ns) || !sw_finite(budget->texel_cost_ns))
        return SWARP_ERR_NON_FINITE;
    if (budget->pass_overhead_ns < 0.0 || budget->texel_cost_ns < 0.0 ||
        budget->pass_overhead_ns > SWARP_PLAN_MAX_COST_NS || budget->texel_cost_ns > SW_MAX_TEXEL_NS)
        return SWARP_ERR_OUT_OF_RANGE;
    if (budget->max_error < 0.0 || budget->time_budget_ns < 0.0 || budget->pass_cost_ns < 0.0 ||
        budget->blur_pass_cost_ns < 0.0 || budget->max_passes > SW_MAX_PASSES)
        return SWARP_ERR_OUT_OF_RANGE;
    /* the documented limit keeps every cost finite: a pass cost near
     * DBL_MAX times K passes would overflow to inf */
    if (budget->time_budget_ns > SWARP_PLAN_MAX_COST_NS || budget->pass_cost_ns > SWARP_PLAN_MAX_COST_NS ||
        budget->blur_pass_cost_ns > SWARP_PLAN_MAX_COST_NS)
        return SWARP_ERR_OUT_OF_RANGE;
    if (budget->map_resolution > SW_MAX_RES || budget->atlas_limit > SW_MAX_RES)
        return SWARP_ERR_RESOLUTION;
    return SWARP_OK;
}

/* "Zero means default" for the needs and the budget (the header's values). */
static void sw_resolve_defaults(const swarp_scene_needs* needs, const swarp_budget* budget, sw_pin* in) {
    in->res_ix = needs->screen_width ? (double)needs->screen_width : (double)SW_PLAN_DEFAULT_SCREEN_W;
    in->res_iy = needs->screen_height ? (double)needs->screen_height : (double)SW_PLAN_DEFAULT_SCREEN_H;
    in->moves = (int)needs->camera_moves;
    in->soft = (int)needs->soft_shadows;
    in->soft_width = needs->soft_width > 0.0 ? needs->soft_width : SW_DEFAULT_SOFT_WIDTH;
    in->bleed = needs->bleed_risk == SWARP_PLAN_BLEED_DEFAULT ? SWARP_PLAN_BLEED_NONE
                                                               : needs->bleed_risk;
    in->allow_clamp = (int)needs->allow_depth_clamp;
    in->by_model = needs->plan_by == SWARP_PLAN_BY_MODEL;
    in->plane_count = needs->plane_count;
    for (uint32_t i = 0; i < needs->plane_count; ++i) in->planes[i] = needs->planes[i];

    in->max_error = budget->max_error > 0.0 ? budget->max_error : 1.0;
    in->map_res = budget->map_resolution ? budget->map_resolution : SW_DEFAULT_MAP_RES;
    in->atlas_limit = budget->atlas_limit ? budget->atlas_limit : 8192u;
    in->max_passes = budget->max_passes ? budget->max_passes : 16u;
    in->time_budget = budget->time_budget_ns;
    in->pass_ns = budget->pass_cost_ns > 0.0 ? budget->pass_cost_ns : SW_DEFAULT_PASS_NS;
    in->blur_ns = budget->blur_pass_cost_ns; /* 0: a fraction of the pass (sw_blur_ns) */
    in->overhead_ns = budget->pass_overhead_ns;
    in->texel_ns = budget->texel_cost_ns;
    if (in->overhead_ns > 0.0 || in->texel_ns > 0.0)
        in->cost_model = SWARP_PLAN_COST_LINEAR;
    else
        in->cost_model = budget->pass_cost_ns > 0.0 ? SWARP_PLAN_COST_PER_PASS : SWARP_PLAN_COST_UNCALIBRATED;
}

/* One shadow pass of an r x r map (docs/planning.md §3): the calibrated
 * model overhead + r² per-texel when the caller gave it, else the per-pass
 * constant.  Both terms are bounded (sw_check_budget), so the sum is finite. */
static double sw_pass_ns(const sw_pin* in, uint32_t r) {
    if (in->cost_model == SWARP_PLAN_COST_LINEAR)
        return in->overhead_ns + (double)r * (double)r * in->texel_ns;
    return in->pass_ns;
}

/* One separable blur pass over an r x r map: the caller's, else a quarter
 * of the shadow pass at that resolution (SW_DEFAULT_BLUR_FRACTION). */
static double sw_blur_ns(const sw_pin* in, uint32_t r) {
    return in->blur_ns > 0.0 ? in->blur_ns : SW_DEFAULT_BLUR_FRACTION * sw_pass_ns(in, r);
}

/* Relative width a box flat across the view gets (f = n, or narrower than
 * this): far above the rounding of the depths of its corners, so the box's
 * own depth extent, which is rounding, does not decide the model. */
#define SW_FLAT_RANGE_REL 1e-6

/* Widens a range [n, f] narrowed by a flat box to SW_FLAT_RANGE_REL n,
 * inside the camera's own [near, far] (the documented range, which the
 * adjustment only narrows).  The camera's range is valid (near < far), and
 * the error model is finite down to a range one ulp wide, so the result
 * f > n needs no widening beyond it: a camera range narrower than the
 * floor is used as it is. */
static void sw_widen_flat_range(double near, double far, double* n, double* f) {
    const double grow = 1.0 + SW_FLAT_RANGE_REL;
    if (*f >= *n * grow) return;
    *f = fmin(*n * grow, far);
    /* the box flat at the far plane: the width goes below it instead */
    if (!(*f > *n)) *n = fmax(*f / grow, near);
    if (!(*f > *n)) *n = near;
}

/* [RHS] §3.3.1 adjusted near/far, conservatively: the depth range of the
 * box corners along the view direction clipped to [near, far] (contains
 * the depth range of H = V ∩ S, so nothing visible is lost). */
static swarp_status sw_adjust_near_far(const swarp_aabb* box, sw_pin* in) {
    double dmin = INFINITY, dmax = -INFINITY;
    for (int k = 0; k < 8; ++k) {
        swarp_vec3 c = sw_v3((k & 1) ? box->max.x : box->min.x,
                             (k & 2) ? box->max.y : box->min.y,
                             (k & 4) ? box->max.z : box->min.z);
        double d = sw_dot(sw_sub(c, in->eye), in->view);
        if (d < dmin) dmin = d;
        if (d > dmax) dmax = d;
    }
    if (dmax < in->z_near || dmin > in->z_far) return SWARP_ERR_PLAN_EMPTY_VIEW;
    double n = dmin > in->z_near ? dmin : in->z_near;
    double f = dmax < in->z_far ? dmax : in->z_far;
    sw_widen_flat_range(in->z_near, in->z_far, &n, &f);
    if (n != in->z_near || f != in->z_far) in->near_far_adjusted = 1;
    in->z_near = n;
    in->z_far = f;
    return SWARP_OK;
}

/* The light's angle γ to the view.  A point light is planned as a
 * directional light from the light toward the centre of the (adjusted)
 * view frustum ([RHS] §3.2.2 treats a narrow point light as directional). */
static swarp_status sw_resolve_gamma(sw_pin* in) {
    if (in->point_light) {
        /* relative to the eye first: light - (eye + c v) would round the
         * centre at the eye's magnitude (1e6 worlds: 1e-10) and turn a
         * light at the eye (exactly γ = π) by 1e-14 rad with the caller's
         * rounding mode; (light - eye) is exact there and small nearby */
        swarp_vec3 to = sw_sub(sw_sub(in->light_pos, in->eye), sw_scale(in->view, 0.5 * (in->z_near + in->z_far)));
        if (!sw_normalize(to, &in->to_light)) return SWARP_ERR_DEGENERATE;
    }
    /* γ = atan2(|v × l|, v · l), not acos(v · l): acos is ill-conditioned
     * next to 0 and π (d acos/dc = -1/sin γ), where a light along the view
     * (or a point light at the eye) puts γ; an ulp of c there would move γ
     * by sqrt(eps) ~ 1.5e-8 and the planner's n' and errors with it.
     * atan2 of the two components is accurate to an ulp everywhere. */
    in->gamma = atan2(sw_len(sw_cross(in->view, in->to_light)), sw_dot(in->view, in->to_light));
    in->gamma_f = in->gamma > 0.5 * SWARP_PI ? SWARP_PI - in->gamma : in->gamma;
    return SWARP_OK;
}

/* Check every input, resolve the defaults, then the adjusted range and γ. */
static swarp_status sw_resolve(const swarp_scene_needs* needs, const swarp_budget* budget,
                               sw_pin* in) {
    static const swarp_scene_needs zero_needs; /* const: not mutable state */
    static const swarp_budget zero_budget;
    if (!needs) needs = &zero_needs;
    if (!budget) budget = &zero_budget;
    memset(in, 0, sizeof *in);

    if (!sw_reserved_zero(needs->_reserved, 3) || needs->_pad0 != 0 || budget->_pad0 != 0)
        return SWARP_ERR_RESERVED_NONZERO;
    swarp_status s;
    if ((s = sw_resolve_view(needs, in)) != SWARP_OK) return s;
    if ((s = sw_check_needs(needs)) != SWARP_OK) return s;
    if ((s = sw_check_budget(budget)) != SWARP_OK) return s;
    sw_resolve_defaults(needs, budget, in);
    in->bounded = !sw_all_zero(&needs->scene_box, sizeof needs->scene_box);
    in->box = needs->scene_box;
    if (in->bounded && (s = sw_adjust_near_far(&needs->scene_box, in)) != SWARP_OK)
        return s;
    return sw_resolve_gamma(in);
}

/* ---- the generalised error model ------------------------------------------ */
/*
 * In the plane spanned by the view direction and the light direction, a view
 * point at depth z and lateral offset y (|y| <= z tanΘ) lands on the shadow
 * map's light-space z axis at t = z sinγ + y cosγ; over the frustum [n, f]
 * t spans [t_lo, t_hi] with t_hi = f sin(γ+Θ)/cosΘ and
 * t_lo = min(n, f) · sin(γ-Θ)/cosΘ, so W = t_hi - t_lo (= W_lz of [RHS] (3.5)
 * for γ >= Θ).  The warp is a perspective along t with its centre n' before
 * t_lo: p = n' + t - t_lo.  Texel sizes and the pixel size 2 z tanΘ / res give
 *   m_z(z) = res_iy/res_t · W / (2 z tanΘ) · (p_hi(z)/n')² / ((n' + W)/n')
 *   m_x(z) = res_ix/res_s · max_{z'∈{n,f}} z' p_hi(z) / (p_lo(z') z)
 * with p_hi/p_lo the largest/smallest p at depth z.  At γ = 90° these are
 * exactly [RHS] (2.4) and (2.3); n' = inf gives (2.8) (with W) and (2.7).
 * Both are convex (m_z ∝ (a + b z)²/z) or monotone (m_x ∝ a/z + b) in z, so
 * the maxima are at z = n or z = f.  Written with 1/n' so that n' = inf
 * (uniform) and n' = DBL_MAX (core's clamp) need no special case.
 */
typedef struct sw_split_geo {
    double sp, sm;   /* sin(γ ± Θ) / cosΘ */
    double t_lo, W;
} sw_split_geo;

static sw_split_geo sw_geo(double gamma_f, double theta, double n, double f) {
    sw_split_geo g;
    double ct = cos(theta);
    g.sp = sin(gamma_f + theta) / ct;
    g.sm = sin(gamma_f - theta) / ct;
    double tn = n * g.sm, tf = f * g.sm;
    g.t_lo = tn < tf ? tn : tf;
    g.W = f * g.sp - g.t_lo;
    return g;
}

static void sw_split_error(const sw_split_geo* g, double theta, double n, double f, double n_l,
                           double r_x, double r_y, double* out_mx, double* out_mz) {
    double inv = sw_finite(n_l) ? 1.0 / n_l : 0.0;
    double tt = tan(theta);
    double zs[2] = {n, f};
    double cx = 0.0; /* max z' / (p_lo(z') / n') */
    for (int k = 0; k < 2; ++k) {
        double a_lo = zs[k] * g->sm - g->t_lo;
        if (a_lo < 0.0) a_lo = 0.0; /* rounding only: t_lo is the minimum */
        double v = zs[k] / (1.0 + a_lo * inv);
        if (v > cx) cx = v;
    }
    double mx = 0.0, mz = 0.0;
    for (int k = 0; k < 2; ++k) {
        double z = zs[k];
        double ph = 1.0 + (z * g->sp - g->t_lo) * inv; /* p_hi / n' */
        double ex = r_x * cx * ph / z;
        double ez = r_y * g->W / (2.0 * z * tt) * ph * ph / (1.0 + g->W * inv);
        if (ex > mx) mx = ex;
        if (ez > mz) mz = ez;
    }
    *out_mx = mx;
    *out_mz = mz;
}

/* Warp parameter of one split [c0, c1] in light-space units (+inf uniform).
 * Returns a core error status if the core refuses (never expected). */
static swarp_status sw_warp_param(swarp_plan_warp w, const sw_split_geo* g, double gamma_f,
                                  double theta, double c0, double c1, double* out) {
    double z1 = c0 + g->W * sin(gamma_f); /* WS06: eye depth one extent d along light z */
    if (z1 < c0) z1 = c0;
    double v = INFINITY, eta = 0.0, lambda = 0.0;
    swarp_status s = SWARP_OK;
    switch (w) {
    case SWARP_PLAN_WARP_UNIFORM: v = INFINITY; break;
    case SWARP_PLAN_WARP_LISPSM_NOPT: s = swarp_warp_nopt(g->W, c0, z1, &v); break; /* [RHS] (3.2) */
    case SWARP_PLAN_WARP_LISPSM_PSEUDO: /* [RHS] (4.2) */
        s = swarp_warp_nopt_pseudo(g->W, c0, z1, SW_PSEUDO_NP, SW_PSEUDO_FP, &v);
        break;
    case SWARP_PLAN_WARP_LISPSM_NREPAR: /* [RHS] (3.3), (3.4) with W for W_lz */
        s = swarp_warp_eta(gamma_f, theta, &eta);
        if (!swarp_status_is_error(s)) s = swarp_warp_nrepar(eta, c1 / c0, g->W, &v);
        break;
    case SWARP_PLAN_WARP_PSM: /* n_repar(η = 1): n' = n_e for the overhead light */
        s = swarp_warp_nrepar(1.0, c1 / c0, g->W, &v);
        break;
    case SWARP_PLAN_WARP_LISPSM_GMNPR: /* [GMNPR] (8): λ = P_n / (P_f - P_n) */
        s = swarp_gmnpr_lambda(gamma_f, theta, c0, c1, &lambda);
        if (!swarp_status_is_error(s)) v = sw_finite(lambda) ? lambda * g->W : INFINITY;
        break;
    default: return SWARP_ERR_UNKNOWN_ENUM;
    }
    if (swarp_status_is_error(s)) return s;
    if (!(v > 0.0)) return SWARP_ERR_DEGENERATE;
    *out = v;
    return SWARP_OK;
}

/* ---- candidates ----------------------------------------------------------- */

#define SW_SINGLE_WARPS 6
#define SW_SPLIT_VARIANTS 6
#define SW_CANDIDATES (SW_SINGLE_WARPS + (SWARP_PLAN_MAX_SPLITS - 1) * SW_SPLIT_VARIANTS)

/* Candidate i in the fixed order that breaks ties (simpler first). */
static swarp_plan_chain sw_candidate(uint32_t i) {
    static const swarp_plan_warp single[SW_SINGLE_WARPS] = {
        SWARP_PLAN_WARP_UNIFORM,      SWARP_PLAN_WARP_LISPSM_NOPT,   SWARP_PLAN_WARP_LISPSM_NREPAR,
        SWARP_PLAN_WARP_LISPSM_GMNPR, SWARP_PLAN_WARP_LISPSM_PSEUDO, SWARP_PLAN_WARP_PSM};
    static const swarp_plan_warp split_warp[3] = {
        SWARP_PLAN_WARP_UNIFORM, SWARP_PLAN_WARP_LISPSM_NOPT, SWARP_PLAN_WARP_LISPSM_NREPAR};
    swarp_plan_chain c;
    memset(&c, 0, sizeof c);
    if (i < SW_SINGLE_WARPS) {
        c.warp = single[i];
        c.scheme = SWARP_PLAN_SCHEME_NONE;
        c.split_count = 1;
    } else {
        uint32_t j = i - SW_SINGLE_WARPS;
        c.split_count = 2 + j / SW_SPLIT_VARIANTS;
        uint32_t v = j % SW_SPLIT_VARIANTS;
        c.scheme = v < 3 ? SWARP_PLAN_SCHEME_PRACTICAL : SWARP_PLAN_SCHEME_LOG;
        c.warp = split_warp[v % 3];
    }
    c.stabilize = SWARP_PLAN_STABILIZE_DEFAULT;
    return c;
}

/* ---- filter decision (depends on the needs only) -------------------------- */

typedef struct sw_filter {
    swarp_plan_filter kind;
    uint32_t layers;
    double width, c_pos, c_neg;
    uint32_t blur_per_map; /* separable blur passes per map */
} sw_filter;

static sw_filter sw_choose_filter(const sw_pin* in) {
    sw_filter f;
    memset(&f, 0, sizeof f);
    f.kind = SWARP_PLAN_FILTER_NONE;
    if (!in->soft) return f;
    f.width = in->soft_width;
    if (in->soft_width <= SW_PCF_MAX_WIDTH) {
        f.kind = SWARP_PLAN_FILTER_PCF; /* taps in the lighting pass, no bleeding */
        return f;
    }
    f.blur_per_map = 2; /* separable prefilter: one pass per axis */
    switch (in->bleed) {
    case SWARP_PLAN_BLEED_LOW: f.kind = SWARP_PLAN_FILTER_MSM; break;
    case SWARP_PLAN_BLEED_HIGH:
        f.kind = SWARP_PLAN_FILTER_EVSM;
        f.c_pos = SW_EVSM_C_POS;
        f.c_neg = SW_EVSM_C_NEG;
        break;
    case SWARP_PLAN_BLEED_EXTREME:
        f.kind = SWARP_PLAN_FILTER_LVSM;
        f.layers = SW_LVSM_LAYERS;
        f.blur_per_map = 2 * (SW_LVSM_LAYERS / 2); /* two layers per RGBA texture */
        break;
    default: f.kind = SWARP_PLAN_FILTER_VSM; break; /* exact for one planar occluder */
    }
    return f;
}

/* ---- evaluation of one chain ---------------------------------------------- */

typedef struct sw_eval {
    uint32_t K, r, tiles;
    double splits[SWARP_PLAN_MAX_SPLITS + 1];
    double n_prime[SWARP_PLAN_MAX_SPLITS];
    double smx[SWARP_PLAN_MAX_SPLITS], smz[SWARP_PLAN_MAX_SPLITS];
    double mx, mz, err, cost;
    double rank;   /* the error candidates are ranked by: the model's err, or measured */
    swarp_plan_stabilize stab;
    int ok;
} sw_eval;

static uint32_t sw_tiles(uint32_t K) {
    uint32_t t = 1;
    while (t * t < K) ++t;
    return t;
}

static void sw_evaluate(const sw_pin* in, const sw_filter* flt, const swarp_plan_chain* c,
                        sw_eval* e) {
    memset(e, 0, sizeof *e);
    uint32_t K = c->split_count ? c->split_count : 1;
    e->K = K;
    e->tiles = sw_tiles(K);
    uint32_t r = in->atlas_limit / e->tiles;
    if (r > in->map_res) r = in->map_res;
    if (r < 1) r = 1;
    e->r = r;
    size_t cnt = 0;
    swarp_status s = SWARP_OK;
    if (K == 1) {
        e->splits[0] = in->z_near;
        e->splits[1] = in->z_far;
    } else if (c->scheme == SWARP_PLAN_SCHEME_LOG) {
        s = swarp_split_log(in->z_near, in->z_far, K, e->splits, SWARP_PLAN_MAX_SPLITS + 1, &cnt);
    } else {
        s = swarp_split_practical(in->z_near, in->z_far, SW_DEFAULT_PSSM_LAMBDA, K, e->splits,
                                  SWARP_PLAN_MAX_SPLITS + 1, &cnt);
    }
    if (swarp_status_is_error(s)) return;
    e->stab = c->stabilize;
    if (e->stab == SWARP_PLAN_STABILIZE_DEFAULT)
        e->stab = (in->moves && c->warp == SWARP_PLAN_WARP_UNIFORM) ? SWARP_PLAN_STABILIZE_APPROX64
                                                                    : SWARP_PLAN_STABILIZE_NONE;
    double grow = e->stab == SWARP_PLAN_STABILIZE_APPROX64 ? SW_STABLE_FACTOR : 1.0;
    double r_x = in->res_ix / (double)r * grow, r_y = in->res_iy / (double)r * grow;
    e->mx = e->mz = 0.0;
    for (uint32_t i = 0; i < K; ++i) {
        double c0 = e->splits[i], c1 = e->splits[i + 1];
        if (!(c1 > c0)) return;
        sw_split_geo g = sw_geo(in->gamma_f, in->theta, c0, c1);
        double n_l;
        if (swarp_status_is_error(sw_warp_param(c->warp, &g, in->gamma_f, in->theta, c0, c1, &n_l)))
            return;
        e->n_prime[i] = n_l;
        sw_split_error(&g, in->theta, c0, c1, n_l, r_x, r_y, &e->smx[i], &e->smz[i]);
        if (!sw_finite(e->smx[i]) || !sw_finite(e->smz[i])) return;
        if (e->smx[i] > e->mx) e->mx = e->smx[i];
        if (e->smz[i] > e->mz) e->mz = e->smz[i];
    }
    e->err = e->mx > e->mz ? e->mx : e->mz;
    e->rank = e->err; /* swarp_plan replaces it by the measured error */
    e->cost = (double)K * sw_pass_ns(in, r) + (double)(K * flt->blur_per_map) * sw_blur_ns(in, r);
    e->ok = 1;
}

/* ---- lixel planes ---------------------------------------------------------- */

/* Smallest near/far ratio of the depth range in the lixel check's
 * view-projection (below). */
#define SW_LIXEL_CHECK_MIN_NEAR_RATIO 0x1p-20

/* The viewer's view-projection (OpenGL clip space, right-handed look-at),
 * for the lixel stage's own check below.  Its depth row
 * -(f+n)/(f-n) z - 2fn/(f-n) tends to the w row -z as n/f -> 0: V^-1 loses
 * log2(f/n) bits, and below n/f ~ eps the two rows are equal or one ulp apart
 * by the rounding of (f+n)/(f-n), V singular or not by the caller's rounding
 * mode (near 1e-31, far 2e5: a lixel map under directed rounding only).
 * The lixel matrix does not depend
 * on the depth range: it is made of the rays through the corner pixels
 * (rows 0, 1, 3 of V, [LIXEL] (2)) and the eye; the depth row enters only
 * V^-1, through which the lixel stage images the plane for its through-eye
 * test (|pi'_z| ~ |h| / 2n of an O(1) whole, h the eye's distance to the
 * plane, which sw_plane_check already requires above 1e-9 f: >= 5e-4 at
 * n = 2^-20 f, far above LX_EYE_EPS) and the view direction (n-free).  So the
 * check uses n' = max(n, 2^-20 f): exact (a power of two), the same matrix as
 * before for n/f >= 2^-20, and V^-1 keeps >= 30 bits below. */
static void sw_view_projection(const sw_pin* in, swarp_mat4* out) {
    swarp_vec3 f = in->view, s = sw_v3(1.0, 0.0, 0.0), u;
    (void)sw_normalize(sw_cross(f, in->up), &s); /* checked non-parallel */
    u = sw_cross(s, f);
    swarp_mat4 V, P;
    sw_identity(&V);
    sw_set(&V, 0, 0, s.x); sw_set(&V, 0, 1, s.y); sw_set(&V, 0, 2, s.z);
    sw_set(&V, 1, 0, u.x); sw_set(&V, 1, 1, u.y); sw_set(&V, 1, 2, u.z);
    sw_set(&V, 2, 0, -f.x); sw_set(&V, 2, 1, -f.y); sw_set(&V, 2, 2, -f.z);
    sw_set(&V, 0, 3, -sw_dot(s, in->eye));
    sw_set(&V, 1, 3, -sw_dot(u, in->eye));
    sw_set(&V, 2, 3, sw_dot(f, in->eye));
    memset(&P, 0, sizeof P);
    const double fa = in->z_far, n = fmax(in->z_near, SW_LIXEL_CHECK_MIN_NEAR_RATIO * fa);
    const double t = 1.0 / tan(in->theta);
    sw_set(&P, 0, 0, t / in->aspect);
    sw_set(&P, 1, 1, t);
    sw_set(&P, 2, 2, -(fa + n) / (fa - n));
    sw_set(&P, 2, 3, -2.0 * fa * n / (fa - n));
    sw_set(&P, 3, 2, -1.0);
    sw_mul(&P, &V, out);
}

/* Is the plane lixel-friendly ([LIXEL] §3-§5): seen from its front by the
 * camera, lit from the same side above 5° elevation, crossing the view
 * frustum, and accepted by the lixel stage's swarp_lixel_matrix (which
 * refuses planes through the eye, lights on or parallel to the plane and
 * planes out of view, and notes a light behind the plane)?  Returns
 * SWARP_PLAN_PLANE_USED when it is. */
static uint32_t sw_lixel_accepts(const sw_pin* in, const swarp_plane* pl) {
    swarp_mat4 M_v, M_l;
    sw_view_projection(in, &M_v);
    swarp_light light;
    memset(&light, 0, sizeof light);
    if (in->point_light) {
        light.type = SWARP_LIGHT_POINT;
        light.position = in->light_pos;
    } else {
        light.type = SWARP_LIGHT_DIRECTIONAL;
        light.direction = sw_scale(in->to_light, -1.0);
    }
    swarp_status s = swarp_lixel_matrix(&M_v, (uint32_t)in->res_ix, (uint32_t)in->res_iy, &light, pl,
                                        NULL, &M_l, NULL);
    switch (s) {
    case SWARP_ERR_LIXEL_PLANE_THROUGH_EYE: return SWARP_PLAN_PLANE_CAMERA_ON_PLANE;
    case SWARP_ERR_LIXEL_LIGHT_ON_PLANE:
    case SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE:
    case SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE: return SWARP_PLAN_PLANE_LIGHT_GRAZING;
    case SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE: return SWARP_PLAN_PLANE_NOT_VISIBLE;
    default: return swarp_status_is_error(s) ? SWARP_PLAN_PLANE_LIXEL_REFUSED : SWARP_PLAN_PLANE_USED;
    }
}

/* The eight corners of the view frustum over the planned range [z_near, z_far]. */
static void sw_view_corners(const sw_pin* in, swarp_vec3 out[8]) {
    swarp_vec3 right = sw_v3(1.0, 0.0, 0.0);
    (void)sw_normalize(sw_cross(in->view, in->up), &right); /* checked non-parallel */
    swarp_vec3 up = sw_cross(right, in->view);
    double ty = tan(in->theta), tx = ty * in->aspect;
    double ds[2] = {in->z_near, in->z_far};
    for (int k = 0; k < 8; ++k) {
        double z = ds[k >> 2];
        swarp_vec3 p = sw_add(in->eye, sw_scale(in->view, z));
        p = sw_add(p, sw_scale(right, ((k & 1) ? 1.0 : -1.0) * z * tx));
        out[k] = sw_add(p, sw_scale(up, ((k & 2) ? 1.0 : -1.0) * z * ty));
    }
}

static uint32_t sw_plane_check(const sw_pin* in, const swarp_plane* pl) {
    swarp_vec3 nrm = sw_v3(pl->a, pl->b, pl->c);
    double len = sw_len(nrm);
    nrm = sw_scale(nrm, 1.0 / len);
    double d = pl->d / len;
    double h = sw_dot(nrm, in->eye) + d;
    /* the camera on the plane (within 1e-9 of the view range): no front side */
    if (fabs(h) <= 1e-9 * in->z_far) return SWARP_PLAN_PLANE_CAMERA_ON_PLANE;
    if (h < 0.0) {
        nrm = sw_scale(nrm, -1.0);
        d = -d;
    }
    if (in->point_light) {
        double hl = sw_dot(nrm, in->light_pos) + d;
        if (!(hl > 0.0)) return SWARP_PLAN_PLANE_LIGHT_GRAZING;
    } else if (!(sw_dot(nrm, in->to_light) > SW_LIXEL_MIN_ELEVATION_SIN)) {
        return SWARP_PLAN_PLANE_LIGHT_GRAZING;
    }
    /* frustum corners: some must lie behind the plane */
    swarp_vec3 corners[8];
    sw_view_corners(in, corners);
    for (int k = 0; k < 8; ++k)
        if (sw_dot(nrm, corners[k]) + d <= 0.0) return sw_lixel_accepts(in, pl);
    return SWARP_PLAN_PLANE_NOT_VISIBLE;
}

/* ---- assembling the plan ---------------------------------------------------- */

static void sw_fill(const sw_pin* in, const sw_filter* flt, const swarp_plan_chain* c,
                    const sw_eval* e, swarp_plan_result* p) {
    memset(p, 0, sizeof *p);
    p->warp = c->warp;
    p->scheme = e->K == 1 ? SWARP_PLAN_SCHEME_NONE : c->scheme;
    p->split_count = e->K;
    p->map_resolution = e->r;
    p->atlas_tiles = e->tiles;
    p->stabilize = e->stab;
    p->gamma = in->gamma;
    p->z_near = in->z_near;
    p->z_far = in->z_far;
    for (uint32_t i = 0; i <= e->K; ++i) p->splits[i] = e->splits[i];
    for (uint32_t i = 0; i < e->K; ++i) {
        p->n_prime[i] = e->n_prime[i];
        p->split_max_mx[i] = e->smx[i];
        p->split_max_mz[i] = e->smz[i];
    }
    p->max_mx = e->mx;
    p->max_mz = e->mz;
    p->max_error = e->err;
    /* each factor is finite, their product can exceed DBL_MAX (m_x, m_z
     * ~ 1e155 for near 1e-300): as a bound it is then written as DBL_MAX,
     * the header's rule for a finite value beyond the double range */
    p->error_area = sw_finite(e->mx * e->mz) ? e->mx * e->mz : DBL_MAX;

    uint32_t R = 0;
    /* inverse projection: PSM only, light behind the camera [KOZ] */
    if (c->warp == SWARP_PLAN_WARP_PSM && in->gamma > 0.5 * SWARP_PI) {
        p->inverse_projection = 1;
        R |= SWARP_PLAN_WHY_INVERSE_PROJECTION;
    } else {
        R |= SWARP_PLAN_WHY_NO_INVERSE;
    }
    R |= in->moves ? SWARP_PLAN_WHY_STABILIZE_MOVING : SWARP_PLAN_WHY_NO_STABILIZE_STATIC;
    if (c->warp == SWARP_PLAN_WARP_UNIFORM)
        R |= in->moves ? SWARP_PLAN_WHY_NO_WARP_MOVING : SWARP_PLAN_WHY_NO_WARP_NO_GAIN;
    else
        R |= SWARP_PLAN_WHY_WARP_LOWERS_ERROR;
    if (!in->allow_clamp) {
        R |= SWARP_PLAN_WHY_NO_CLAMP_DISALLOWED;
    } else if (c->warp != SWARP_PLAN_WARP_UNIFORM) {
        R |= SWARP_PLAN_WHY_NO_CLAMP_WARPED;
    } else {
        p->depth_clamp = 1;
        R |= SWARP_PLAN_WHY_DEPTH_CLAMP;
    }
    p->filter = flt->kind;
    p->filter_layers = flt->layers;
    p->filter_width = flt->width;
    p->filter_exponent_pos = flt->c_pos;
    p->filter_exponent_neg = flt->c_neg;
    R |= in->soft ? SWARP_PLAN_WHY_FILTER_SOFT : SWARP_PLAN_WHY_NO_FILTER_HARD;
    if (e->r < in->map_res) R |= SWARP_PLAN_WHY_ATLAS_SHRINK;
    if (in->near_far_adjusted) R |= SWARP_PLAN_WHY_NEAR_FAR_ADJUSTED;
    if (in->point_light) R |= SWARP_PLAN_WHY_POINT_AS_DIRECTIONAL;

    p->shadow_passes = e->K;
    p->blur_passes = e->K * flt->blur_per_map;
    p->texels = (double)e->K * (double)e->r * (double)e->r;
    p->cost_ns = e->cost;
    p->cost_model = in->cost_model;
    p->meets_budget = e->rank <= in->max_error &&
                      (in->time_budget <= 0.0 || e->cost <= in->time_budget);

    /* lixel maps with the passes (and time) left over */
    p->plane_count = in->plane_count;
    if (in->plane_count == 0) R |= SWARP_PLAN_WHY_NO_LIXEL_NONE;
    double lixel_cost = sw_pass_ns(in, in->map_res) + (double)flt->blur_per_map * sw_blur_ns(in, in->map_res);
    for (uint32_t i = 0; i < in->plane_count; ++i) {
        uint32_t why = sw_plane_check(in, &in->planes[i]);
        if (why == SWARP_PLAN_PLANE_USED) {
            int pass_ok = p->shadow_passes < in->max_passes;
            int time_ok = in->time_budget <= 0.0 || p->cost_ns + lixel_cost <= in->time_budget;
            if (!pass_ok || !time_ok) why = SWARP_PLAN_PLANE_NO_PASS_LEFT;
        }
        p->plane_reason[i] = why;
        if (why == SWARP_PLAN_PLANE_USED) {
            p->lixel_planes[p->lixel_count++] = i;
            p->shadow_passes += 1;
            p->blur_passes += flt->blur_per_map;
            p->texels += (double)in->map_res * (double)in->map_res;
            p->cost_ns += lixel_cost;
            R |= SWARP_PLAN_WHY_LIXEL_PLANE;
        } else {
            R |= SWARP_PLAN_WHY_NO_LIXEL_SKIPPED;
        }
    }
    if (p->lixel_count) {
        /* the light image of the plane is affine to the screen [LIXEL] (10):
         * one texel per max(screen)/map pixels along either axis */
        double big = in->res_ix > in->res_iy ? in->res_ix : in->res_iy;
        p->lixel_error = big / (double)in->map_res;
    }
    p->reasons = R;
}

/* ---- the chain's matrices (swarp_plan_evaluate) --------------------------- */

/* An unbounded scene as an engine gives it to swarp_setup: the bounding box
 * of the view frustum V, grown by this fraction of its size on every side so
 * that V's corners lie strictly inside and H = V ∩ S is V itself (a corner
 * on a face could be clipped away by rounding).  The light's focus grows by
 * at most this fraction, below a texel of a 65536-texel map (1.5e-5). */
#define SW_VIEW_BOX_GROW 1e-6

static swarp_aabb sw_view_box(const sw_pin* in) {
    swarp_vec3 c[8];
    sw_view_corners(in, c);
    swarp_aabb b = {c[0], c[0]};
    for (int k = 1; k < 8; ++k) {
        b.min = sw_v3(fmin(b.min.x, c[k].x), fmin(b.min.y, c[k].y), fmin(b.min.z, c[k].z));
        b.max = sw_v3(fmax(b.max.x, c[k].x), fmax(b.max.y, c[k].y), fmax(b.max.z, c[k].z));
    }
    swarp_vec3 g = sw_scale(sw_sub(b.max, b.min), SW_VIEW_BOX_GROW);
    b.min = sw_sub(b.min, g);
    b.max = sw_add(b.max, g);
    return b;
}

/* The swarp_setup_options of a warp (docs/planning.md §9): the technique and
 * the LiSPSM parameter the planner's model names; PSM keeps Kozlov's inverse
 * projection for a light behind the camera (psm_slideback 0), as the plan's
 * inverse_projection says. */
static void sw_warp_setup_options(swarp_plan_warp w, swarp_setup_options* so) {
    so->technique = SWARP_TECHNIQUE_LISPSM;
    switch (w) {
    case SWARP_PLAN_WARP_LISPSM_NOPT: so->param = SWARP_WARP_PARAM_NOPT; break;
    case SWARP_PLAN_WARP_LISPSM_NREPAR: so->param = SWARP_WARP_PARAM_NREPAR; break;
    case SWARP_PLAN_WARP_LISPSM_GMNPR: so->param = SWARP_WARP_PARAM_GMNPR; break;
    case SWARP_PLAN_WARP_LISPSM_PSEUDO:
        so->param = SWARP_WARP_PARAM_PSEUDO;
        so->pseudo_near = SW_PSEUDO_NP;
        so->pseudo_far = SW_PSEUDO_FP;
        break;
    case SWARP_PLAN_WARP_PSM: so->technique = SWARP_TECHNIQUE_PSM; break;
    default: so->technique = SWARP_TECHNIQUE_UNIFORM; break;
    }
}

/* The cascade options an engine sets for the plan's chain: its warp, split
 * count, scheme with the planner's λ, 64-level stabilisation [RHS] §3.5,
 * pancaking for depth clamping, the tile (map) resolution and the screen. */
static void sw_chain_options(const sw_pin* in, const swarp_plan_result* p, uint32_t skip_measure,
                             swarp_cascade_options* o) {
    memset(o, 0, sizeof *o);
    sw_warp_setup_options(p->warp, &o->setup);
    o->setup.skip_measure = skip_measure;
    o->setup.map_width = p->map_resolution;
    o->setup.screen_width = (uint32_t)in->res_ix;
    o->setup.screen_height = (uint32_t)in->res_iy;
    o->setup.pancake = p->depth_clamp;
    o->split.count = p->split_count;
    o->split.scheme = p->scheme == SWARP_PLAN_SCHEME_LOG ? SWARP_SCHEME_LOG : SWARP_SCHEME_PRACTICAL;
    o->split.lambda = SW_DEFAULT_PSSM_LAMBDA;
    o->stabilize.mode = p->stabilize == SWARP_PLAN_STABILIZE_APPROX64 ? SWARP_STABILIZE_LEVELS
                                                                       : SWARP_STABILIZE_NONE;
    o->warp_per_split = SWARP_CASCADE_WARP_EACH;
}

/* Builds the plan's chain with swarp_cascade_setup and copies its split
 * distances, n' and measured error (zero when not measured) into the plan
 * (built = 1), or records the cascade's error status (built = 0, the fields
 * stay zero). */
static void sw_build_chain(const sw_pin* in, uint32_t skip_measure, swarp_plan_result* p) {
    swarp_cascade_options o;
    sw_chain_options(in, p, skip_measure, &o);
    const swarp_aabb box = in->bounded ? in->box : sw_view_box(in);
    swarp_cascade_result r;
    swarp_cascade_split sp[SWARP_PLAN_MAX_SPLITS];
    size_t count = 0;
    swarp_status s = swarp_cascade_setup(&in->cam, &in->light, &box, &o, &r, sp, SWARP_PLAN_MAX_SPLITS, &count);
    p->built_status = s;
    if (swarp_status_is_error(s) || count != p->split_count) return;
    for (uint32_t i = 0; i <= p->split_count; ++i) p->built_splits[i] = r.splits[i];
    for (uint32_t i = 0; i < p->split_count; ++i) {
        p->built_n_eye[i] = sp[i].n_eye;
        p->split_measured[i] = sp[i].measured;
    }
    p->measured = r.measured;
    p->built = 1;
}

static int sw_better_error(const sw_eval* a, const sw_eval* b) {
    /* a strictly more accurate than b (beyond the tie tolerance) */
    return a->rank < b->rank * (1.0 - SW_ERR_TIE_REL);
}

/* The error the budget is compared with for a built chain: the measured
 * max(m_s, m_t) over H, the generalisation of the budget's max(m_x, m_z)
 * (swarp_budget.max_error) to the matrices' own axes. */
static double sw_measured_rank(const swarp_measured_error* m) {
    return m->max_m_s > m->max_m_t ? m->max_m_s : m->max_m_t;
}

/* What one search over the candidates found. */
typedef struct sw_search {
    sw_eval best, fallback;
    swarp_plan_chain best_c, fb_c;
    int have_best, have_fb, time_limited, pass_limited;
    uint32_t evaluated;
} sw_search;

/* Selection by the model (docs/planning.md §4) against the error budget
 * max_error: the cheapest chain that meets it, ties to the lower error, then
 * the earlier candidate; and the most accurate chain within the pass limit
 * as the fallback. */
static void sw_run_search(const sw_pin* in, const sw_filter* flt, double max_error, sw_search* S) {
    memset(S, 0, sizeof *S);
    sw_eval cur;
    for (uint32_t i = 0; i < SW_CANDIDATES; ++i) {
        swarp_plan_chain c = sw_candidate(i);
        /* candidates come in order of K and the cost grows strictly with K
         * (pass cost > 0): once a chain meets the budget, no later K can be
         * cheaper, so the search stops there (the usual case stays cheap) */
        if (S->have_best && c.split_count > S->best.K) break;
        /* a moving camera needs stabilisation, which warps do not admit
         * [RHS] §3.5 */
        if (in->moves && c.warp != SWARP_PLAN_WARP_UNIFORM) continue;
        sw_evaluate(in, flt, &c, &cur);
        ++S->evaluated;
        if (!cur.ok) continue;
        int err_ok = cur.err <= max_error;
        if (c.split_count > in->max_passes) {
            if (err_ok) S->pass_limited = 1;
            continue;
        }
        int time_ok = in->time_budget <= 0.0 || cur.cost <= in->time_budget;
        if (err_ok && !time_ok) S->time_limited = 1;
        if (!S->have_fb || sw_better_error(&cur, &S->fallback) ||
            (!sw_better_error(&S->fallback, &cur) && cur.cost < S->fallback.cost)) {
            S->fallback = cur;
            S->fb_c = c;
            S->have_fb = 1;
        }
        if (err_ok && time_ok &&
            (!S->have_best || cur.cost < S->best.cost ||
             (cur.cost == S->best.cost && sw_better_error(&cur, &S->best)))) {
            S->best = cur;
            S->best_c = c;
            S->have_best = 1;
        }
    }
}

/* Rounds of the calibrated search (swarp_plan): each builds and measures
 * one chain (0.2-1 ms).  The effective budget shrinks every round by at
 * least the factor SW_CALIB_MIN_STEP, so each round asks the model for a
 * more accurate chain than the last; the cap bounds the planning time. */
#define SW_CALIB_ROUNDS 8
#define SW_CALIB_MIN_STEP 0.97

/* The chain the calibrated search settled on and what its rounds saw. */
typedef struct sw_calib {
    swarp_plan_chain c;
    sw_eval e;
    swarp_plan_result built;  /* its matrices and measured error */
    int have, meets, time_limited, pass_limited;
    uint32_t evaluated, rounds;
} sw_calib;

/* One round: the model's choice against the effective budget eff, built and
 * measured.  Returns 1 and fills *e, *c, *bp when a chain was found. */
static int sw_calib_round(const sw_pin* in, const sw_filter* flt, double eff, sw_calib* C,
                          sw_eval* e, swarp_plan_chain* c, swarp_plan_result* bp, int* model_met) {
    sw_search S;
    sw_run_search(in, flt, eff, &S);
    C->evaluated += S.evaluated;
    C->time_limited |= S.time_limited;
    C->pass_limited |= S.pass_limited;
    if (!S.have_fb) return 0;
    *model_met = S.have_best;
    *e = S.have_best ? S.best : S.fallback;
    *c = S.have_best ? S.best_c : S.fb_c;
    sw_fill(in, flt, c, e, bp);
    if (!in->by_model) sw_build_chain(in, 0, bp);
    return 1;
}

/* The search with a model calibrated against measurement: the model
 * chooses against an effective budget, the chain's matrices are built and
 * measured (max(m_s, m_t) over H), and while the measurement misses the
 * budget the effective budget is scaled by that chain's model/measured
 * ratio and the model chooses again.  Keeps the first chain whose measured
 * error meets the budget, else the most accurate one measured. */
static void sw_calibrated_search(const sw_pin* in, const sw_filter* flt, sw_calib* C) {
    memset(C, 0, sizeof *C);
    double eff = in->max_error, best_meas = INFINITY;
    sw_eval e;
    swarp_plan_chain c;
    swarp_plan_result bp;
    for (uint32_t round = 0; round < SW_CALIB_ROUNDS; ++round) {
        int model_met = 0;
        if (!sw_calib_round(in, flt, eff, C, &e, &c, &bp, &model_met)) break;
        ++C->rounds;
        if (in->by_model || !bp.built || bp.measured.samples == 0) {
            /* not buildable (a point light, a stabilised warp): the model is
             * all there is for this chain */
            if (!C->have) {
                C->c = c; C->e = e; C->built = bp; C->have = 1; C->meets = model_met;
            }
            break;
        }
        double meas = sw_measured_rank(&bp.measured);
        if (!(meas >= 0.0)) break; /* NaN: not expected */
        e.rank = meas;
        if (!C->have || meas < best_meas) {
            C->c = c; C->e = e; C->built = bp; C->have = 1; C->meets = 0;
            best_meas = meas;
        }
        if (meas <= in->max_error) {
            C->c = c; C->e = e; C->built = bp;
            C->meets = in->time_budget <= 0.0 || e.cost <= in->time_budget;
            break;
        }
        /* the model's fallback is already its most accurate chain */
        if (!model_met || !sw_finite(meas)) break;
        eff = fmin(in->max_error * (e.err / meas), eff * SW_CALIB_MIN_STEP);
    }
}

/* The built fields of plan b (the chosen chain's matrices) into p. */
static void sw_copy_built(const swarp_plan_result* b, swarp_plan_result* p) {
    p->built = b->built;
    p->built_status = b->built_status;
    memcpy(p->built_splits, b->built_splits, sizeof p->built_splits);
    memcpy(p->built_n_eye, b->built_n_eye, sizeof p->built_n_eye);
    memcpy(p->split_measured, b->split_measured, sizeof p->split_measured);
    p->measured = b->measured;
}

SWARP_API swarp_status swarp_plan(const swarp_scene_needs* needs, const swarp_budget* budget,
                                  struct swarp_plan* out_plan) {
    if (!out_plan) return SWARP_ERR_NULL_POINTER;
    sw_pin in;
    swarp_status s = sw_resolve(needs, budget, &in);
    if (s != SWARP_OK) return s;
    sw_filter flt = sw_choose_filter(&in);
    sw_calib C;
    sw_calibrated_search(&in, &flt, &C);
    if (!C.have) return SWARP_ERR_DEGENERATE; /* no candidate computable: not expected */

    swarp_plan_result p;
    swarp_status st;
    sw_fill(&in, &flt, &C.c, &C.e, &p);
    sw_copy_built(&C.built, &p);
    if (p.built) p.reasons |= SWARP_PLAN_WHY_RANKED_MEASURED;
    if (C.meets) {
        p.reasons |= C.e.K == 1 ? SWARP_PLAN_WHY_ONE_MAP_MEETS : SWARP_PLAN_WHY_SPLITS_NEEDED;
        st = in.point_light ? SWARP_INFO_PLAN_POINT_LIGHT : SWARP_OK;
    } else {
        p.meets_budget = 0;
        p.reasons |= SWARP_PLAN_WHY_BUDGET_UNMET;
        if (C.pass_limited) p.reasons |= SWARP_PLAN_WHY_PASS_LIMITED;
        st = SWARP_INFO_PLAN_BUDGET_UNMET;
    }
    if (C.time_limited) p.reasons |= SWARP_PLAN_WHY_TIME_LIMITED;
    p.candidates = C.evaluated;
    *out_plan = p;
    return st;
}

SWARP_API swarp_status swarp_plan_evaluate(const swarp_scene_needs* needs,
                                           const swarp_budget* budget,
                                           const swarp_plan_chain* chain,
                                           struct swarp_plan* out_plan) {
    if (!out_plan || !chain) return SWARP_ERR_NULL_POINTER;
    if (!sw_reserved_zero(chain->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
    swarp_plan_chain c = *chain;
    if (c.warp == SWARP_PLAN_WARP_DEFAULT) c.warp = SWARP_PLAN_WARP_UNIFORM;
    if ((uint32_t)c.warp > (uint32_t)SWARP_PLAN_WARP_PSM || (uint32_t)c.scheme > (uint32_t)SWARP_PLAN_SCHEME_LOG ||
        (uint32_t)c.stabilize > (uint32_t)SWARP_PLAN_STABILIZE_APPROX64 ||
        (uint32_t)c.matrices > (uint32_t)SWARP_PLAN_MATRICES_NONE)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (c.split_count == 0) c.split_count = 1;
    if (c.scheme == SWARP_PLAN_SCHEME_DEFAULT) c.scheme = SWARP_PLAN_SCHEME_NONE;
    if (c.split_count > SWARP_PLAN_MAX_SPLITS ||
        (c.split_count > 1) != (c.scheme != SWARP_PLAN_SCHEME_NONE))
        return SWARP_ERR_SPLIT_COUNT;
    sw_pin in;
    swarp_status s = sw_resolve(needs, budget, &in);
    if (s != SWARP_OK) return s;
    sw_filter flt = sw_choose_filter(&in);
    sw_eval e;
    sw_evaluate(&in, &flt, &c, &e);
    if (!e.ok) return SWARP_ERR_DEGENERATE;
    swarp_plan_result p;
    sw_fill(&in, &flt, &c, &e, &p);
    /* the warp was not chosen, so no reason about it is claimed */
    p.reasons &= ~(SWARP_PLAN_WHY_WARP_LOWERS_ERROR | SWARP_PLAN_WHY_NO_WARP_NO_GAIN |
                   SWARP_PLAN_WHY_NO_WARP_MOVING);
    p.reasons |= SWARP_PLAN_WHY_FORCED;
    p.candidates = 1;
    if (c.matrices != SWARP_PLAN_MATRICES_NONE)
        sw_build_chain(&in, c.matrices == SWARP_PLAN_MATRICES_UNMEASURED, &p);
    *out_plan = p;
    return in.point_light ? SWARP_INFO_PLAN_POINT_LIGHT : SWARP_OK;
}

/* ---- the cost model's calibration ------------------------------------------ */

SWARP_API swarp_status swarp_plan_cost_fit(const double* texels, const double* pass_ns, size_t count,
                                           double* out_overhead_ns, double* out_texel_cost_ns,
                                           double* out_rms_ns) {
    if (!texels || !pass_ns || !out_overhead_ns || !out_texel_cost_ns) return SWARP_ERR_NULL_POINTER;
    if (count < 2) return SWARP_ERR_OUT_OF_RANGE;
    double mx = 0.0, my = 0.0;
    for (size_t i = 0; i < count; ++i) {
        if (!sw_finite(texels[i]) || !sw_finite(pass_ns[i])) return SWARP_ERR_NON_FINITE;
        if (!(texels[i] > 0.0) || pass_ns[i] < 0.0) return SWARP_ERR_OUT_OF_RANGE;
        mx += texels[i];
        my += pass_ns[i];
    }
    mx /= (double)count;
    my /= (double)count;
    /* the normal equations about the means (centred: no cancellation of
     * Σx² against n x̄² at 1e7-texel maps) */
    double sxx = 0.0, sxy = 0.0, sx2 = 0.0, sxy0 = 0.0;
    for (size_t i = 0; i < count; ++i) {
        double dx = texels[i] - mx;
        sxx += dx * dx;
        sxy += dx * (pass_ns[i] - my);
        sx2 += texels[i] * texels[i];
        sxy0 += texels[i] * pass_ns[i];
    }
    if (!(sxx > 0.0)) return SWARP_ERR_DEGENERATE;
    double b = sxy / sxx, a = my - b * mx;
    /* the least-squares optimum under a, b >= 0 lies on the boundary when
     * the free optimum leaves the quadrant: the problem is convex, so the
     * better of the two one-term fits (a = 0: the line through the origin;
     * b = 0: the mean) is the constrained optimum */
    if (b < 0.0) {
        b = 0.0;
        a = my;
    } else if (a < 0.0) {
        a = 0.0;
        b = sxy0 / sx2;
    }
    if (a > SWARP_PLAN_MAX_COST_NS || b > SW_MAX_TEXEL_NS) return SWARP_ERR_OUT_OF_RANGE;
    if (out_rms_ns) {
        double ss = 0.0;
        for (size_t i = 0; i < count; ++i) {
            double r = pass_ns[i] - (a + b * texels[i]);
            ss += r * r;
        }
        *out_rms_ns = sqrt(ss / (double)count);
    }
    *out_overhead_ns = a;
    *out_texel_cost_ns = b;
    return SWARP_OK;
}

/* ---- names and text --------------------------------------------------------- */

SWARP_API const char* swarp_plan_warp_name(swarp_plan_warp w) {
    switch (w) {
    case SWARP_PLAN_WARP_DEFAULT:
    case SWARP_PLAN_WARP_UNIFORM: return "uniform";
    case SWARP_PLAN_WARP_LISPSM_NOPT: return "lispsm-nopt";
    case SWARP_PLAN_WARP_LISPSM_NREPAR: return "lispsm-nrepar";
    case SWARP_PLAN_WARP_LISPSM_GMNPR: return "lispsm-gmnpr";
    case SWARP_PLAN_WARP_LISPSM_PSEUDO: return "lispsm-pseudo";
    case SWARP_PLAN_WARP_PSM: return "psm";
    default: return "?";
    }
}

SWARP_API const char* swarp_plan_scheme_name(swarp_plan_scheme s) {
    switch (s) {
    case SWARP_PLAN_SCHEME_DEFAULT:
    case SWARP_PLAN_SCHEME_NONE: return "none";
    case SWARP_PLAN_SCHEME_PRACTICAL: return "pssm-practical";
    case SWARP_PLAN_SCHEME_LOG: return "pssm-log";
    default: return "?";
    }
}

SWARP_API const char* swarp_plan_filter_name(swarp_plan_filter f) {
    switch (f) {
    case SWARP_PLAN_FILTER_DEFAULT:
    case SWARP_PLAN_FILTER_NONE: return "none";
    case SWARP_PLAN_FILTER_PCF: return "pcf";
    case SWARP_PLAN_FILTER_VSM: return "vsm";
    case SWARP_PLAN_FILTER_MSM: return "msm";
    case SWARP_PLAN_FILTER_EVSM: return "evsm";
    case SWARP_PLAN_FILTER_LVSM: return "lvsm";
    default: return "?";
    }
}

/* ---- the explanation text (sw_text, sw_puts, sw_putu, sw_putd) ---------- */

static const struct { uint32_t bit; const char* text; } sw_why_text[] = {
    {SWARP_PLAN_WHY_ONE_MAP_MEETS, "one map meets the error budget: no splits"},
    {SWARP_PLAN_WHY_SPLITS_NEEDED, "no cheaper chain meets the error budget: this is the fewest splits that does"},
    {SWARP_PLAN_WHY_WARP_LOWERS_ERROR, "the warp lowers the predicted error at no extra pass"},
    {SWARP_PLAN_WHY_NO_WARP_NO_GAIN, "no warp: none lowers the predicted error here (duelling frusta fade warps to uniform)"},
    {SWARP_PLAN_WHY_NO_WARP_MOVING, "no warp: the camera moves and warped maps cannot be stabilised [RHS] 3.5"},
    {SWARP_PLAN_WHY_STABILIZE_MOVING, "stabilised (64 scale levels + texel snapping) because the camera moves [RHS] 3.5"},
    {SWARP_PLAN_WHY_NO_STABILIZE_STATIC, "no stabilisation: the camera is static"},
    {SWARP_PLAN_WHY_INVERSE_PROJECTION, "inverse projection: PSM with the light behind the camera [KOZ]"},
    {SWARP_PLAN_WHY_NO_INVERSE, "no inverse projection: not PSM, or the light is in front of the camera"},
    {SWARP_PLAN_WHY_FILTER_SOFT, "filter: soft shadows requested (kind by kernel width and light-bleeding risk [VSM] 3.4)"},
    {SWARP_PLAN_WHY_NO_FILTER_HARD, "no filter: hard shadows requested"},
    {SWARP_PLAN_WHY_LIXEL_PLANE, "lixel map for each declared lixel-friendly plane [LIXEL]"},
    {SWARP_PLAN_WHY_NO_LIXEL_NONE, "no lixel map: no plane of interest declared"},
    {SWARP_PLAN_WHY_NO_LIXEL_SKIPPED, "a declared plane got no lixel map (see below)"},
    {SWARP_PLAN_WHY_DEPTH_CLAMP, "casters clamped to the light's near plane (allowed, unwarped chain)"},
    {SWARP_PLAN_WHY_NO_CLAMP_DISALLOWED, "no depth clamping: not allowed by the scene"},
    {SWARP_PLAN_WHY_NO_CLAMP_WARPED, "no depth clamping: it breaks warped maps [RHS] 3.1.2"},
    {SWARP_PLAN_WHY_BUDGET_UNMET, "NOTHING MEETS THE BUDGET: this is the most accurate chain within the pass limit"},
    {SWARP_PLAN_WHY_TIME_LIMITED, "the time budget excluded chains that met the error budget"},
    {SWARP_PLAN_WHY_ATLAS_SHRINK, "the atlas limit shrinks each split's map"},
    {SWARP_PLAN_WHY_NEAR_FAR_ADJUSTED, "near/far fitted to the scene box [RHS] 3.3.1"},
    {SWARP_PLAN_WHY_POINT_AS_DIRECTIONAL, "point light planned as directional toward the view frustum's centre"},
    {SWARP_PLAN_WHY_PASS_LIMITED, "more passes than the limit would have met the error budget"},
    {SWARP_PLAN_WHY_FORCED, "chain given by the caller (evaluated, not chosen)"},
    {SWARP_PLAN_WHY_RANKED_MEASURED, "candidates judged by the measured error of their built matrices (max m_s, m_t over the view)"},
};

static const char* sw_plane_text(uint32_t why) {
    switch (why) {
    case SWARP_PLAN_PLANE_USED: return "lixel map";
    case SWARP_PLAN_PLANE_CAMERA_ON_PLANE: return "left out: the camera lies on the plane";
    case SWARP_PLAN_PLANE_LIGHT_GRAZING: return "left out: lit from the other side or below 5 degrees";
    case SWARP_PLAN_PLANE_NOT_VISIBLE: return "left out: the plane misses the view frustum";
    case SWARP_PLAN_PLANE_NO_PASS_LEFT: return "left out: no pass (or time) left";
    case SWARP_PLAN_PLANE_LIXEL_REFUSED: return "left out: swarp_lixel_matrix refused the configuration";
    default: return "?";
    }
}

/* "<pre>a<mid>b": the explain text's number pairs ("[n, f", "m_x .., m_z ..",
 * "c+ .., c- .."). */
static void sw_putdd(sw_text* t, const char* pre, double a, const char* mid, double b) {
    sw_puts(t, pre);
    sw_putd(t, a);
    sw_puts(t, mid);
    sw_putd(t, b);
}

static void sw_explain(const swarp_plan_result* p, sw_text* t) {
    sw_puts(t, "chain: ");
    sw_puts(t, swarp_plan_warp_name(p->warp));
    if (p->split_count > 1) {
        sw_puts(t, ", ");
        sw_putu(t, p->split_count);
        sw_puts(t, " splits (");
        sw_puts(t, swarp_plan_scheme_name(p->scheme));
        sw_puts(t, ")");
    } else {
        sw_puts(t, ", one map");
    }
    sw_puts(t, ", ");
    sw_putu(t, p->map_resolution);
    sw_puts(t, "^2 texels per map");
    if (p->stabilize == SWARP_PLAN_STABILIZE_APPROX64) sw_puts(t, ", stabilised");
    if (p->inverse_projection) sw_puts(t, ", inverse projection");
    if (p->depth_clamp) sw_puts(t, ", depth clamp");
    sw_puts(t, ", filter ");
    sw_puts(t, swarp_plan_filter_name(p->filter));
    if (p->filter != SWARP_PLAN_FILTER_NONE && p->filter != SWARP_PLAN_FILTER_DEFAULT) {
        sw_puts(t, " (width ");
        sw_putd(t, p->filter_width);
        sw_puts(t, " texels");
        if (p->filter_layers) { sw_puts(t, ", "); sw_putu(t, p->filter_layers); sw_puts(t, " layers"); }
        if (p->filter_exponent_pos > 0.0) {
            sw_putdd(t, ", c+ ", p->filter_exponent_pos, ", c- ", p->filter_exponent_neg);
        }
        sw_puts(t, ")");
    }
    sw_puts(t, "\nlight/view angle gamma ");
    sw_putd(t, p->gamma * 180.0 / SWARP_PI);
    sw_putdd(t, " deg, depth range [", p->z_near, ", ", p->z_far);
    sw_putdd(t, "]\npredicted max m_x ", p->max_mx, ", m_z ", p->max_mz);
    sw_puts(t, " (pixels per texel), area ");
    sw_putd(t, p->error_area);
    sw_puts(t, p->meets_budget ? ": meets the budget\n" : ": does NOT meet the budget\n");
    if (p->built && p->measured.samples > 0) {
        sw_putdd(t, "measured on the matrices: max m_s ", p->measured.max_m_s, ", m_t ", p->measured.max_m_t);
        sw_puts(t, ", sigma ");
        sw_putd(t, p->measured.max_sigma);
        sw_putdd(t, " at (", p->measured.at.x, ", ", p->measured.at.y);
        sw_puts(t, ", ");
        sw_putd(t, p->measured.at.z);
        sw_puts(t, ")\n");
    }
    for (uint32_t i = 0; i < p->split_count && p->split_count > 1; ++i) {
        sw_puts(t, "  split ");
        sw_putu(t, i);
        sw_putdd(t, " [", p->splits[i], ", ", p->splits[i + 1]);
        sw_puts(t, "]: n' ");
        sw_putd(t, p->n_prime[i]);
        sw_putdd(t, ", m_x ", p->split_max_mx[i], ", m_z ", p->split_max_mz[i]);
        if (p->built && p->split_measured[i].samples > 0) {
            sw_puts(t, "; matrix n' ");
            sw_putd(t, p->built_n_eye[i]);
            sw_puts(t, ", sigma ");
            sw_putd(t, p->split_measured[i].max_sigma);
        }
        sw_puts(t, "\n");
    }
    sw_puts(t, "cost: ");
    sw_putu(t, p->shadow_passes);
    sw_puts(t, " shadow passes, ");
    sw_putu(t, p->blur_passes);
    sw_puts(t, " blur passes, ");
    sw_putd(t, p->texels);
    sw_puts(t, " texels, ");
    sw_putd(t, p->cost_ns * 1e-6);
    sw_puts(t, " ms predicted");
    switch (p->cost_model) {
    case SWARP_PLAN_COST_LINEAR: sw_puts(t, " (cost model calibrated: overhead + per-texel)\n"); break;
    case SWARP_PLAN_COST_PER_PASS: sw_puts(t, " (cost model: the caller's per-pass time)\n"); break;
    default: sw_puts(t, " (cost model uncalibrated: 1.39 ms per pass from [RHS] Table 7.1)\n"); break;
    }
    for (size_t i = 0; i < sizeof sw_why_text / sizeof sw_why_text[0]; ++i)
        if (p->reasons & sw_why_text[i].bit) {
            sw_puts(t, "why: ");
            sw_puts(t, sw_why_text[i].text);
            sw_puts(t, "\n");
        }
    for (uint32_t i = 0; i < SWARP_PLAN_MAX_PLANES; ++i) {
        if (i >= p->plane_count) break;
        int used = 0;
        for (uint32_t k = 0; k < p->lixel_count; ++k)
            if (p->lixel_planes[k] == i) used = 1;
        sw_puts(t, "plane ");
        sw_putu(t, i);
        sw_puts(t, ": ");
        sw_puts(t, sw_plane_text(p->plane_reason[i]));
        if (used) {
            sw_puts(t, ", ");
            sw_putd(t, p->lixel_error);
            sw_puts(t, " pixels per texel on the plane");
        }
        sw_puts(t, "\n");
    }
}

SWARP_API swarp_status swarp_plan_explain(const struct swarp_plan* plan, char* out, size_t capacity,
                                          size_t* out_count) {
    if (!plan || !out_count || (!out && capacity > 0)) return SWARP_ERR_NULL_POINTER;
    if ((uint32_t)plan->warp > (uint32_t)SWARP_PLAN_WARP_PSM ||
        (uint32_t)plan->scheme > (uint32_t)SWARP_PLAN_SCHEME_LOG ||
        (uint32_t)plan->filter > (uint32_t)SWARP_PLAN_FILTER_LVSM ||
        (uint32_t)plan->stabilize > (uint32_t)SWARP_PLAN_STABILIZE_APPROX64 ||
        plan->split_count > SWARP_PLAN_MAX_SPLITS || plan->lixel_count > SWARP_PLAN_MAX_PLANES ||
        plan->plane_count > SWARP_PLAN_MAX_PLANES ||
        (uint32_t)plan->cost_model > (uint32_t)SWARP_PLAN_COST_LINEAR)
        return SWARP_ERR_UNKNOWN_ENUM;
    sw_text t = {NULL, 0, 0};
    sw_explain(plan, &t);
    size_t need = t.n + 1;
    if (capacity < need) {
        *out_count = need;
        return SWARP_ERR_CAPACITY;
    }
    sw_text w = {out, 0, 1};
    sw_explain(plan, &w);
    out[w.n] = '\0';
    *out_count = need;
    return SWARP_OK;
}

/* The ABI of the planner's structs (plain doubles and 32-bit fields, no
 * padding surprises across compilers and bindings). */
_Static_assert(sizeof(swarp_plan_chain) == 36, "swarp_plan_chain ABI");
_Static_assert(sizeof(swarp_budget) == 64, "swarp_budget ABI");
_Static_assert(sizeof(swarp_scene_needs) == 432, "swarp_scene_needs ABI");
_Static_assert(sizeof(struct swarp_plan) == 1968, "swarp_plan ABI");
_Static_assert(offsetof(struct swarp_plan, built_splits) == 736, "swarp_plan ABI");
_Static_assert(offsetof(struct swarp_plan, reasons) == 716, "swarp_plan ABI");
_Static_assert(offsetof(swarp_scene_needs, planes) == 288, "swarp_scene_needs ABI");
