/* Cascades (z-partitioning) combined with any geometry technique: split
 * selection, blending, per-split matrices and the configuration's error
 * curve.  [RHS] §3.3-3.4, §4.1-4.2. */
#include <float.h>

#include "cascade/cascade_internal.h"
#include "geometry/geometry_internal.h"

/* m split distances C_0 < ... < C_m, 1 <= m <= SWARP_SPLIT_MAX_COUNT */
static swarp_status sw_check_split_distances(const double* splits, size_t m) {
    if (!splits) return SWARP_ERR_NULL_POINTER;
    if (m < 1 || m > SWARP_SPLIT_MAX_COUNT) return SWARP_ERR_SPLIT_COUNT;
    return sw_check_increasing(splits, m);
}

/* Depth selection without checks: the split containing z, clamped. */
static uint32_t sw_select_depth(const double* splits, size_t m, double z, int* outside) {
    *outside = (z < splits[0] || z > splits[m]);
    uint32_t i = 0;
    /* m <= 64: a linear scan is as fast as a bisection and mirrors the GLSL */
    while (i + 1 < m && z >= splits[i + 1]) ++i;
    return i;
}

SWARP_API swarp_status swarp_cascade_view_depth(const swarp_camera* cam, const swarp_vec3* p,
                                                double* out_depth) {
    if (!cam || !p || !out_depth) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite3(&cam->eye) || !sw_finite3(&cam->dir) || !sw_finite3(p)) return SWARP_ERR_NON_FINITE;
    /* Scale dir by its largest component first: its length overflows for
     * components near DBL_MAX, and any non-zero finite dir is valid. */
    const swarp_vec3 d = cam->dir;
    const double dmax = fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
    swarp_vec3 f;
    if (!(dmax > 0.0) || !sw_normalize(sw_v3(d.x / dmax, d.y / dmax, d.z / dmax), &f))
        return SWARP_ERR_ZERO_VECTOR;
    double z = sw_dot(sw_sub(*p, cam->eye), f);
    if (!sw_finite(z)) {
        /* p - eye (or the sum) overflowed for coordinates near DBL_MAX:
         * again at a quarter scale (|p/4 - eye/4| <= DBL_MAX/2 per
         * component, the sum below DBL_MAX); a depth beyond DBL_MAX is not
         * representable: SWARP_ERR_OVERFLOW, never NON_FINITE for finite
         * arguments */
        const double q = sw_dot(sw_sub(sw_scale(*p, 0.25), sw_scale(cam->eye, 0.25)), f);
        if (!(fabs(q) <= 0.25 * DBL_MAX)) return SWARP_ERR_OVERFLOW;
        z = 4.0 * q;
    }
    *out_depth = z;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_cascade_select_depth(const double* splits, size_t m, double view_depth,
                                                  uint32_t* out_index) {
    if (!out_index) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_split_distances(splits, m);
    if (st != SWARP_OK) return st;
    if (!sw_finite(view_depth)) return SWARP_ERR_NON_FINITE;
    int outside;
    *out_index = sw_select_depth(splits, m, view_depth, &outside);
    return outside ? SWARP_INFO_OUTSIDE_SPLITS : SWARP_OK;
}

SWARP_API swarp_status swarp_cascade_blend(const double* splits, size_t m, double view_depth,
                                           double band, uint32_t* out_index, double* out_weight) {
    if (!out_index || !out_weight) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_split_distances(splits, m);
    if (st != SWARP_OK) return st;
    if (!sw_finite(view_depth) || !sw_finite(band)) return SWARP_ERR_NON_FINITE;
    if (!(band >= 0.0 && band < 1.0)) return SWARP_ERR_OUT_OF_RANGE;
    int outside;
    const uint32_t i = sw_select_depth(splits, m, view_depth, &outside);
    double w = 1.0;
    if (i + 1 < m && band > 0.0) {
        const double border = splits[i + 1];
        const double width = band * (border - splits[i]);
        w = (border - view_depth) / width;
        if (w > 1.0) w = 1.0;
        if (w < 0.0) w = 0.0;
    }
    *out_index = i;
    *out_weight = w;
    return outside ? SWARP_INFO_OUTSIDE_SPLITS : SWARP_OK;
}

/* Does the map cover p?  w > 0, |x|, |y| <= w and depth inside the range. */
static int sw_covers(const swarp_bias_map* map, swarp_vec3 p) {
    swarp_vec4 h = sw_xform_point(&map->world_to_clip, p);
    if (!(h.w > 0.0)) return 0;
    /* [0, 1] and reversed-Z both keep clip z in [0, w] */
    const int zero_based = map->depth == SWARP_DEPTH_ZERO_TO_ONE || map->depth == SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
    const double zlo = zero_based ? 0.0 : -h.w;
    return fabs(h.x) <= h.w && fabs(h.y) <= h.w && h.z >= zlo && h.z <= h.w;
}

SWARP_API swarp_status swarp_cascade_select_best(const swarp_bias_map* maps, size_t m,
                                                 const swarp_vec3* p, uint32_t fallback_index,
                                                 uint32_t* out_index, double* out_L_texel) {
    if (!maps || !p || !out_index) return SWARP_ERR_NULL_POINTER;
    if (m < 1 || m > SWARP_SPLIT_MAX_COUNT) return SWARP_ERR_SPLIT_COUNT;
    if (fallback_index >= m) return SWARP_ERR_OUT_OF_RANGE;
    if (!sw_finite3(p)) return SWARP_ERR_NON_FINITE;
    uint32_t best = 0;
    double best_L = INFINITY;
    for (size_t i = 0; i < m; ++i) {
        if (!sw_covers(&maps[i], *p)) {
            /* still validate the map so bad input never passes silently */
            double dummy;
            swarp_status st = swarp_bias_texel_size(&maps[i], p, &dummy, NULL, NULL);
            if (swarp_status_is_error(st) && st != SWARP_ERR_BEHIND_PROJECTION) return st;
            continue;
        }
        double L;
        swarp_status st = swarp_bias_texel_size(&maps[i], p, &L, NULL, NULL);
        if (st != SWARP_OK) return st;
        if (L < best_L) {
            best_L = L;
            best = (uint32_t)i;
        }
    }
    if (!(best_L < INFINITY)) {
        *out_index = fallback_index;
        if (out_L_texel) *out_L_texel = 0.0;
        return SWARP_INFO_OUTSIDE_SPLITS;
    }
    *out_index = best;
    if (out_L_texel) *out_L_texel = best_L;
    return SWARP_OK;
}

/* ---- split distances and the error curve ------------------------------- */

SWARP_API swarp_status swarp_cascade_splits(double n, double f, const swarp_split_options* opt,
                                            double* out, size_t capacity, size_t* out_count) {
    if (!out_count) return SWARP_ERR_NULL_POINTER;
    swarp_split_options o;
    memset(&o, 0, sizeof o);
    if (opt) o = *opt;
    if (!sw_reserved_zero(o._reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
    if (o.count == 0) o.count = SW_DEFAULT_SPLIT_COUNT;
    if (o.scheme == SWARP_SCHEME_DEFAULT) {
        o.scheme = SWARP_SCHEME_PRACTICAL;
        o.lambda = SW_DEFAULT_PSSM_LAMBDA;
    }
    if (o.scheme == SWARP_SCHEME_MEASURED) return SWARP_ERR_INVALID_ARGUMENT; /* needs the scene */
    if (o.scheme != SWARP_SCHEME_UNIFORM && o.scheme != SWARP_SCHEME_LOG &&
        o.scheme != SWARP_SCHEME_PRACTICAL && o.scheme != SWARP_SCHEME_PSEUDO)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_finite(n) || !sw_finite(f) || !sw_finite(o.lambda) || !sw_finite(o.pseudo_near) ||
        !sw_finite(o.pseudo_far))
        return SWARP_ERR_NON_FINITE;
    if (!(n > 0.0) || !(f > n)) return SWARP_ERR_NEAR_FAR;
    if (o.count > SWARP_SPLIT_MAX_COUNT) return SWARP_ERR_SPLIT_COUNT;
    if (!(o.lambda >= 0.0 && o.lambda <= 1.0) || !(o.pseudo_near >= 0.0) ||
        !(o.pseudo_far >= 0.0) || !(o.pseudo_near + o.pseudo_far < 1.0))
        return SWARP_ERR_OUT_OF_RANGE;
    if (capacity < (size_t)o.count + 1) {
        *out_count = (size_t)o.count + 1;
        return SWARP_ERR_CAPACITY;
    }
    if (!out) return SWARP_ERR_NULL_POINTER;
    double tmp[SWARP_SPLIT_MAX_COUNT + 1];
    size_t cnt = 0;
    swarp_status st;
    switch (o.scheme) {
        case SWARP_SCHEME_UNIFORM:
            st = swarp_split_uniform(n, f, o.count, tmp, SWARP_SPLIT_MAX_COUNT + 1, &cnt);
            break;
        case SWARP_SCHEME_LOG:
            st = swarp_split_log(n, f, o.count, tmp, SWARP_SPLIT_MAX_COUNT + 1, &cnt);
            break;
        case SWARP_SCHEME_PRACTICAL:
            st = swarp_split_practical(n, f, o.lambda, o.count, tmp, SWARP_SPLIT_MAX_COUNT + 1, &cnt);
            break;
        default: {
            /* [RHS] (4.1): the practical scheme over the pseudo range */
            const double n_p = n + o.pseudo_near * (f - n), f_p = f - o.pseudo_far * (f - n);
            st = swarp_split_pseudo(n, f, n_p, f_p, o.lambda, o.count, tmp,
                                    SWARP_SPLIT_MAX_COUNT + 1, &cnt);
            break;
        }
    }
    if (swarp_status_is_error(st)) return st;
    memcpy(out, tmp, cnt * sizeof *out);
    *out_count = cnt;
    return st;
}

SWARP_API swarp_status swarp_cascade_nopt(const double* splits, size_t m, double pseudo_near,
                                          double pseudo_far, double* out_n_primes) {
    if (!out_n_primes) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_split_distances(splits, m);
    if (st != SWARP_OK) return st;
    double tmp[SWARP_SPLIT_MAX_COUNT];
    swarp_status info = SWARP_OK;
    for (size_t i = 0; i < m; ++i) {
        /* [RHS] §4.2: pseudo-near only for the first split, pseudo-far only
         * for the last */
        const double n_p = i == 0 ? pseudo_near : 0.0, f_p = i + 1 == m ? pseudo_far : 0.0;
        const double z_0 = splits[i], z_1 = splits[i + 1];
        st = swarp_warp_nopt_pseudo(z_1 - z_0, z_0, z_1, n_p, f_p, &tmp[i]);
        if (swarp_status_is_error(st)) return st;
        if (st != SWARP_OK) info = st;
    }
    memcpy(out_n_primes, tmp, m * sizeof *out_n_primes);
    return info;
}

SWARP_API swarp_status swarp_cascade_error_curve(const swarp_error_config* cfg,
                                                 const double* splits, const double* n_primes,
                                                 size_t m, size_t samples_per_split,
                                                 double* out_z, double* out_mx, double* out_mz,
                                                 size_t capacity, size_t* out_count) {
    if (!cfg || !n_primes || !out_count || !out_z) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_split_distances(splits, m);
    if (st != SWARP_OK) return st;
    if (samples_per_split < 2 || samples_per_split > ((size_t)1 << 24)) return SWARP_ERR_OUT_OF_RANGE;
    const size_t total = m * samples_per_split;
    if (capacity < total) {
        *out_count = total;
        return SWARP_ERR_CAPACITY;
    }
    /* Pre-flight on one depth: every input error shows up here, before any
     * output is written (the chunks below only use depths inside [C_0, C_m]). */
    double pre_mx, pre_mz;
    st = swarp_error_split_curve(cfg, splits, n_primes, m, &splits[0], 1, &pre_mx, &pre_mz);
    if (swarp_status_is_error(st)) return st;
    double z_buf[256];
    swarp_status result = SWARP_OK;
    for (size_t base = 0; base < total; base += 256) {
        const size_t chunk = total - base < 256 ? total - base : 256;
        for (size_t k = 0; k < chunk; ++k) {
            const size_t g = base + k, i = g / samples_per_split, j = g % samples_per_split;
            const double a = splits[i], b = splits[i + 1];
            double z;
            if (j + 1 == samples_per_split)
                z = (i + 1 == m) ? b : nextafter(b, a); /* left limit at the border */
            else {
                z = a + (b - a) * (double)j / (double)(samples_per_split - 1);
                /* with a subnormal b - a the rounding can reach b: keep the
                 * sample inside [C_i, C_i+1) (the border sample is nextafter(b, a)) */
                const double below_b = nextafter(b, a);
                if (z > below_b) z = below_b;
            }
            z_buf[k] = z;
        }
        st = swarp_error_split_curve(cfg, splits, n_primes, m, z_buf, chunk,
                                     out_mx ? out_mx + base : NULL, out_mz ? out_mz + base : NULL);
        if (swarp_status_is_error(st)) return st;
        if (st != SWARP_OK) result = st;
        memcpy(out_z + base, z_buf, chunk * sizeof *out_z);
    }
    *out_count = total;
    return result;
}

/* ---- the one call -------------------------------------------------------- */

_Static_assert(sizeof(swarp_split_options) == 8 + 3 * sizeof(double) + 16, "swarp_split_options size");
_Static_assert(sizeof(swarp_cascade_options) ==
                   sizeof(swarp_setup_options) + sizeof(swarp_split_options) +
                       sizeof(swarp_stabilize_options) + (1 + SWARP_CASCADE_MAX_SPLITS) * sizeof(double) + 16,
               "swarp_cascade_options size");
/* warp_per_split and three reserved words: the size of a 4-word reserved tail */
_Static_assert(sizeof(swarp_cascade_options) ==
                   sizeof(swarp_setup_options) + sizeof(swarp_split_options) +
                       sizeof(swarp_stabilize_options) + (1 + SWARP_CASCADE_MAX_SPLITS) * sizeof(double) +
                       sizeof(swarp_cascade_warp) + 3 * sizeof(uint32_t),
               "swarp_cascade_options fields");

_Static_assert(sizeof(swarp_cascade_split) ==
                   2 * sizeof(double) + 2 * sizeof(swarp_mat4) + sizeof(swarp_atlas_tile) +
                       11 * sizeof(double) + 8 + sizeof(swarp_measured_error) + 16,
               "swarp_cascade_split size");
_Static_assert(sizeof(swarp_cascade_result) == 8 + (4 + SWARP_CASCADE_MAX_SPLITS + 1) * sizeof(double) +
                                                   sizeof(swarp_atlas_info) + sizeof(swarp_measured_error) + 16,
               "swarp_cascade_result size");

/* Largest fraction handed to (4.2) when the pseudo plane lies beyond the
 * first (last) split: (4.2) needs n_p + f_p < 1. */
#define SW_PSEUDO_MAX_FRACTION 0.99

/* [RHS] (3.9) generalised: r_l l_sc times the clip-space length of one world
 * unit along the map's x (y) axis at the point c.  For a uniform map that is
 * the row norm 2/(max - min) of A_fit L exactly; for a warped map it is the
 * derivative of the projective map at c (the body's centroid). */
static void sw_kernel_scale(const swarp_mat4* M, swarp_vec3 c, double r_l, double l_sc, double out[2]) {
    const swarp_vec4 h = sw_xform_point(M, c);
    for (int k = 0; k < 2; ++k) {
        double g[3];
        for (int j = 0; j < 3; ++j) {
            const double row_k = sw_at(M, k, j), row_w = sw_at(M, 3, j);
            const double hk = k == 0 ? h.x : h.y;
            g[j] = (row_k - hk / h.w * row_w) / h.w;
        }
        out[k] = r_l * l_sc * sw_len_fast(sw_v3(g[0], g[1], g[2]));
    }
}

/* Error model values of one split (overhead frame), [RHS] (2.3)-(2.8). */
static swarp_status sw_split_errors(const swarp_camera* cam, const swarp_setup_options* so,
                                    swarp_cascade_split* sp) {
    swarp_error_config cfg;
    sw_setup_error_config(so, sw_half_fovy(cam->fovy), sp->z_near, sp->z_far, &cfg);
    swarp_status st = swarp_error_max(&cfg, sp->n_eye, &sp->max_mx, &sp->max_mz);
    if (swarp_status_is_error(st)) return st;
    if (swarp_status_is_error(st = swarp_error_mx(&cfg, sp->z_near, sp->n_eye, &sp->mx_start))) return st;
    if (swarp_status_is_error(st = swarp_error_mz(&cfg, sp->z_near, sp->n_eye, &sp->mz_start))) return st;
    if (swarp_status_is_error(st = swarp_error_mx(&cfg, sp->z_far, sp->n_eye, &sp->mx_end))) return st;
    if (swarp_status_is_error(st = swarp_error_mz(&cfg, sp->z_far, sp->n_eye, &sp->mz_end))) return st;
    return SWARP_OK;
}

/* One call's resolved options and the state its steps share. */
typedef struct sw_cascade_run {
    const swarp_camera* cam;
    const swarp_light* light;
    const swarp_aabb* scene;
    swarp_cascade_options o;
    swarp_cascade_warp wmode;
    swarp_stabilize_mode smode;
    uint32_t K, tile_res;
    double r_l;               /* r_l of [RHS] (3.9) */
    int any_user, user_warp;  /* some n_user[i] given; one of them a warp (not +inf) */
    int single;               /* one split, unstabilised, no user warp: swarp_setup itself */
    swarp_polyhedron H, Hi, Bi; /* H = V ∩ S; one split's H_i and B_i */
    swarp_vec3 cam_f, cam_r, cam_u;
    swarp_setup_result sr;    /* the current split's setup */
    swarp_vec3 pts_buf[SWARP_BODY_MAX_POINTS];
    const swarp_vec3* pts;    /* the current split's points of B_i */
    size_t npts;
    int measured_splits;      /* SWARP_SCHEME_MEASURED: the split positions searched */
    int search;               /* a candidate of that search: the cheap measurement */
    int measured_stabilized;  /* MEASURED asked for with stabilisation */
} sw_cascade_run;

/* The cascade's own options (the setup's are checked with the camera):
 * reserved fields, enums, count and capacity, kernel size, per-split warps,
 * stabilisation mode; their defaults resolved into *c. */
static swarp_status sw_check_cascade_options(const swarp_cascade_options* opts, swarp_cascade_split* out_splits,
                                             size_t capacity, size_t* out_count, sw_cascade_run* c) {
    memset(&c->o, 0, sizeof c->o);
    if (opts) c->o = *opts;
    const swarp_cascade_options* o = &c->o;
    if (!sw_reserved_zero(o->_reserved, 3)) return SWARP_ERR_RESERVED_NONZERO;
    c->wmode = o->warp_per_split == SWARP_CASCADE_WARP_DEFAULT ? SWARP_CASCADE_WARP_EACH : o->warp_per_split;
    if (c->wmode != SWARP_CASCADE_WARP_EACH && c->wmode != SWARP_CASCADE_WARP_FROM_FIRST)
        return SWARP_ERR_UNKNOWN_ENUM;
    c->K = o->split.count ? o->split.count : SW_DEFAULT_SPLIT_COUNT;
    if (c->K > SWARP_CASCADE_MAX_SPLITS) return SWARP_ERR_SPLIT_COUNT;
    if (capacity < c->K) {
        *out_count = c->K;
        return SWARP_ERR_CAPACITY;
    }
    if (!out_splits) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(o->kernel_world_size)) return SWARP_ERR_NON_FINITE;
    if (o->kernel_world_size < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    c->r_l = o->kernel_world_size > 0.0 ? o->kernel_world_size : 1.0;
    c->any_user = c->user_warp = 0;
    for (uint32_t i = 0; i < SWARP_CASCADE_MAX_SPLITS; ++i) {
        const double nu = o->n_user[i];
        if (isnan(nu) || nu == -INFINITY) return SWARP_ERR_NON_FINITE;
        if (nu < 0.0) return SWARP_ERR_OUT_OF_RANGE;
        if (nu != 0.0 && i < c->K) {
            c->any_user = 1;
            if (nu != INFINITY) c->user_warp = 1;
        }
    }
    if (!sw_reserved_zero(o->stabilize._reserved, 4) || o->stabilize._reserved0 != 0)
        return SWARP_ERR_RESERVED_NONZERO;
    c->smode = o->stabilize.mode == SWARP_STABILIZE_DEFAULT ? SWARP_STABILIZE_NONE : o->stabilize.mode;
    if (c->smode != SWARP_STABILIZE_NONE && c->smode != SWARP_STABILIZE_SPHERE && c->smode != SWARP_STABILIZE_LEVELS)
        return SWARP_ERR_UNKNOWN_ENUM;
    /* [RHS] §3.5: stabilised maps need split ranges that do not move with
     * the view, so DEFAULT is there the fixed practical scheme; searched
     * positions would move every border each frame */
    c->search = 0;
    c->measured_splits = 0;
    /* MEASURED with stabilisation: SWARP_ERR_INVALID_ARGUMENT after every
     * other check (sw_cascade_split_range) */
    c->measured_stabilized = o->split.scheme == SWARP_SCHEME_MEASURED && c->smode != SWARP_STABILIZE_NONE;
    if ((o->split.scheme == SWARP_SCHEME_DEFAULT || o->split.scheme == SWARP_SCHEME_MEASURED) &&
        c->smode == SWARP_STABILIZE_NONE && c->K > 1)
        c->measured_splits = 1;
    if (o->split.scheme == SWARP_SCHEME_MEASURED) {
        /* its start and the checks of swarp_cascade_splits: the practical scheme */
        c->o.split.scheme = SWARP_SCHEME_PRACTICAL;
        c->o.split.lambda = SW_DEFAULT_PSSM_LAMBDA;
    }
    return SWARP_OK;
}

/* Camera, light, setup options, view range and box with the common checks
 * in swarp_setup's order (every path of the cascade, also those that never
 * call swarp_setup, sees the same statuses), then what stabilisation needs. */
static swarp_status sw_check_cascade_scene(const sw_cascade_run* c) {
    swarp_status st;
    if ((st = sw_check_camera_shape(c->cam)) != SWARP_OK) return st;
    if ((st = sw_check_light(c->light)) != SWARP_OK) return st;
    if ((st = sw_check_setup_options(&c->o.setup)) != SWARP_OK) return st;
    if ((st = sw_check_view_range(c->cam->z_near, c->cam->z_far)) != SWARP_OK) return st;
    if ((st = sw_check_box(c->scene)) != SWARP_OK) return st;
    if (c->smode != SWARP_STABILIZE_NONE) {
        /* [RHS] §3.5: both solutions need the uniform texel grid */
        if (c->o.setup.technique != SWARP_TECHNIQUE_UNIFORM || c->user_warp) return SWARP_ERR_STABILIZE_WARPED;
        if (c->light->type != SWARP_LIGHT_DEFAULT && c->light->type != SWARP_LIGHT_DIRECTIONAL)
            return SWARP_ERR_STABILIZE_LIGHT;
    }
    return SWARP_OK;
}

/* One split IS the single map: swarp_setup, bit for bit; the split options
 * are still validated, and one split is [n, f] exactly. */
static swarp_status sw_cascade_single_range(sw_cascade_run* c, swarp_cascade_result* res, swarp_status* st0) {
    size_t cnt;
    swarp_status st = swarp_setup(c->cam, c->light, c->scene, &c->o.setup, &c->sr, c->pts_buf,
                                  SWARP_BODY_MAX_POINTS, &c->npts);
    if (swarp_status_is_error(st)) return st;
    *st0 = st;
    swarp_split_options so = c->o.split;
    so.count = 1;
    swarp_status sst = swarp_cascade_splits(c->sr.view_near, c->sr.view_far, &so, res->splits,
                                            SWARP_CASCADE_MAX_SPLITS + 1, &cnt);
    if (swarp_status_is_error(sst)) return sst;
    res->view_near = res->splits[0] = c->sr.view_near;
    res->view_far = res->splits[1] = c->sr.view_far;
    return SWARP_OK;
}

/* [RHS] §3.3.1 adjusted near/far (exactly as swarp_body_adjusted_range),
 * keeping H = V ∩ S: each split's H_i is H clipped to its depth slab,
 * cheaper than building V_i ∩ S again; then the split distances. */
static swarp_status sw_cascade_split_range(sw_cascade_run* c, swarp_cascade_result* res) {
    const swarp_camera* cam = c->cam;
    swarp_status st;
    /* [RHS] §4.3: a measured min depth moves the near plane out, as in
     * swarp_setup; not for stabilised maps (constant ranges, below) */
    double cam_near = cam->z_near;
    if (c->o.setup.min_depth > 0.0 && c->smode == SWARP_STABILIZE_NONE) {
        st = swarp_mindepth_near(cam->z_near, cam->z_far, c->o.setup.min_depth, NULL, &cam_near);
        if (swarp_status_is_error(st)) return st;
    }
    /* H and the adjusted range camera-relative, as swarp_setup computes
     * them (the same view range); H then back in world coordinates */
    double n_adj, f_adj;
    if ((st = sw_body_h_eye(cam, cam_near, cam->z_far, c->scene, &c->H, &n_adj, &f_adj)) != SWARP_OK) return st;
    sw_poly_translate(&c->H, cam->eye);
    sw_camera_basis(cam, &c->cam_f, &c->cam_r, &c->cam_u);
    n_adj = sw_max(n_adj, cam_near);
    f_adj = sw_min(sw_max(f_adj, n_adj), cam->z_far);
    if (c->smode != SWARP_STABILIZE_NONE) {
        /* [RHS] §3.5: both solutions need constant split ranges, so no
         * view frustum adjustment: split the camera's own [near, far].
         * The adjusted far moves with the camera (by fractions of a unit
         * per frame in a walk), which would move every split border, the
         * sphere and the level size, and the texels would drift. */
        n_adj = cam->z_near;
        f_adj = cam->z_far;
    }
    if (!(f_adj > n_adj)) {
        /* H lies in one view plane: keep a sliver, as swarp_setup does */
        const double pad = fmax(1e-9 * n_adj, 1e-300);
        if (n_adj - pad > cam_near) n_adj -= pad;
        else f_adj += pad;
    }
    swarp_split_options so = c->o.split;
    so.count = c->K;
    size_t cnt;
    st = swarp_cascade_splits(n_adj, f_adj, &so, res->splits, SWARP_CASCADE_MAX_SPLITS + 1, &cnt);
    if (swarp_status_is_error(st)) return st;
    if (c->measured_stabilized) return SWARP_ERR_INVALID_ARGUMENT; /* the ranges must not move with the view */
    res->view_near = n_adj;
    res->view_far = f_adj;
    return SWARP_OK;
}

/* Split i's setup options: its own n_user ([RHS] §3.4 "adjust the warping
 * strength for each split independently"), the first split's strength
 * carried through the scheme (FROM_FIRST), or the pseudo-near/far of
 * [RHS] §4.2 on the outer splits only. */
static swarp_setup_options sw_split_setup_options(const sw_cascade_run* c, uint32_t i, const double* nu,
                                                  const swarp_cascade_split* sp, const swarp_cascade_result* res) {
    const swarp_cascade_split* s = &sp[i];
    swarp_setup_options so = c->o.setup;
    so.skip_measure = 1; /* the cascade measures each split's final matrix itself */
    if (c->o.n_user[i] != 0.0) {
        so.technique = c->o.n_user[i] == INFINITY ? SWARP_TECHNIQUE_UNIFORM : SWARP_TECHNIQUE_LISPSM;
        so.param = SWARP_WARP_PARAM_USER;
        so.n_user = c->o.n_user[i];
    } else if (c->wmode == SWARP_CASCADE_WARP_FROM_FIRST && i > 0) {
        /* [RHS] §3.4 arbitrary warping "based upon the variable first
         * split according to the currently used split scheme":
         * n'_i = n'_0 nu_i / nu_0 (uniform first split: all uniform) */
        const double n0 = sp[0].n_eye, ni = n0 * (nu[i] / nu[0]);
        if (!(n0 < INFINITY) || !(ni < INFINITY)) {
            so.technique = SWARP_TECHNIQUE_UNIFORM;
        } else {
            so.technique = SWARP_TECHNIQUE_LISPSM;
            so.param = SWARP_WARP_PARAM_USER;
            so.n_user = ni;
        }
    } else if (so.param == SWARP_WARP_PARAM_PSEUDO && c->K > 1) {
        /* the fractions of the whole range become fractions of the split's */
        const double whole = res->view_far - res->view_near, len = s->z_far - s->z_near;
        so.pseudo_near = i == 0 ? fmin(c->o.setup.pseudo_near * whole / len, SW_PSEUDO_MAX_FRACTION) : 0.0;
        so.pseudo_far = i + 1 == c->K ? fmin(c->o.setup.pseudo_far * whole / len, SW_PSEUDO_MAX_FRACTION) : 0.0;
    }
    return so;
}

/* B_i of split i from H_i = H within C_i <= (p - eye).f <= C_{i+1} (the
 * outer ends are H's own) and its light matrix (swarp_setup_points); a
 * LEVELS split past the scene maps its own frustum. */
static swarp_status sw_split_body_matrix(sw_cascade_run* c, const swarp_cascade_split* s, uint32_t i,
                                         double f_dot_eye, const swarp_setup_options* so) {
    swarp_status st;
    const swarp_polyhedron* hp = &c->H;
    if (i > 0) {
        if ((st = sw_poly_clip(hp, sw_scale(c->cam_f, -1.0), f_dot_eye + s->z_near, &c->Hi)) != SWARP_OK) return st;
        hp = &c->Hi;
    }
    if (i + 1 < c->K) {
        if ((st = sw_poly_clip(hp, c->cam_f, -f_dot_eye - s->z_far, &c->Hi)) != SWARP_OK) return st;
        hp = &c->Hi;
    }
    if (hp->vertex_count == 0 && c->smode == SWARP_STABILIZE_LEVELS) {
        /* the constant split range ([RHS] §3.5) may reach past the scene:
         * nothing to shadow there, the map covers the split frustum */
        sw_cam_frame fr;
        fr.eye = c->cam->eye;
        fr.f = c->cam_f;
        fr.r = c->cam_r;
        fr.u = c->cam_u;
        fr.tan_half = tan(0.5 * c->cam->fovy);
        fr.aspect = c->cam->aspect;
        sw_frustum_corners(&fr, s->z_near, s->z_far, c->pts_buf);
        c->pts = c->pts_buf;
        c->npts = 8;
        sw_identity(&c->sr.matrix); /* replaced by the stabiliser */
        c->sr.n_eye = INFINITY;
        return SWARP_INFO_SPLIT_NO_SCENE;
    }
    if (hp->vertex_count == 0) return SWARP_ERR_SPLIT_EMPTY;
    int clamped = 0; /* H_i is a clip of the clipper's H: tidy loops */
    st = sw_body_from_h_clipped(hp, c->light, c->scene, &c->Bi, &clamped);
    if (st == SWARP_ERR_BODY_EMPTY) return SWARP_ERR_SPLIT_EMPTY;
    if (st != SWARP_OK) return st;
    if (c->light->type == SWARP_LIGHT_POINT && c->light->cone_angle > 0.0) {
        /* receivers a spot lights: H_i ∩ L (as swarp_setup_range) */
        st = swarp_body_receivers(hp, c->light, &c->Hi);
        if (st == SWARP_ERR_BODY_EMPTY) return SWARP_ERR_SPLIT_EMPTY;
        if (st != SWARP_OK) return st;
        hp = &c->Hi;
    }
    st = swarp_setup_points(c->cam, c->light, c->Bi.vertices, c->Bi.vertex_count, hp->vertices, hp->vertex_count,
                            s->z_near, s->z_far, so, &c->sr);
    if (swarp_status_is_error(st)) return st;
    /* casters past SW_SWEEP_REL_MAX times H_i's size are not in B_i: the
     * depth range holds them only through the renderer's clamp */
    if (clamped) st = SWARP_INFO_CASTERS_CLAMPED;
    c->pts = c->Bi.vertices;
    c->npts = c->Bi.vertex_count;
    return st;
}

/* Split i's light matrix into c->sr (and its points c->pts): the sphere of
 * SPHERE stabilisation alone, PSM's full call (its unit-cube clipping wants
 * B as a polyhedron), or B_i from H_i.  The single map has it already. */
static swarp_status sw_split_matrix(sw_cascade_run* c, const swarp_cascade_split* s, uint32_t i, double f_dot_eye,
                                    const swarp_setup_options* so, swarp_status single_st) {
    if (c->smode == SWARP_STABILIZE_SPHERE) {
        /* no body needed (a split beyond the scene still gets its
         * constant-size map) */
        c->npts = 0;
        sw_identity(&c->sr.matrix); /* replaced below */
        c->sr.n_eye = INFINITY;
        return SWARP_OK;
    }
    if (c->single) return single_st;
    if (so->technique == SWARP_TECHNIQUE_PSM) {
        swarp_status st = swarp_setup_range(c->cam, c->light, c->scene, s->z_near, s->z_far, so, &c->sr, c->pts_buf,
                                            SWARP_BODY_MAX_POINTS, &c->npts);
        c->pts = c->pts_buf;
        if (st == SWARP_ERR_BODY_EMPTY) return SWARP_ERR_SPLIT_EMPTY;
        return st;
    }
    return sw_split_body_matrix(c, s, i, f_dot_eye, so);
}

/* [RHS] §3.5 flicker reduction of split i's matrix (sphere or levels);
 * the whole cascade uses the setup's depth convention. */
static swarp_status sw_split_stabilize(const sw_cascade_run* c, swarp_cascade_split* s, swarp_vec3* sphere_center,
                                       swarp_status* info) {
    swarp_stabilize_report rep;
    memset(&rep, 0, sizeof rep);
    swarp_stabilize_options sto = c->o.stabilize;
    sto.depth = c->o.setup.depth_range;
    swarp_status st = swarp_stabilize_directional(c->cam, s->z_near, s->z_far, &c->light->direction, c->pts, c->npts,
                                                  c->scene, c->tile_res, &sto, &s->matrix, &rep);
    if (swarp_status_is_error(st)) return st;
    if (st != SWARP_OK) {
        s->status = st;
        if (*info == SWARP_OK) *info = st;
    }
    s->texel_size = fmax(rep.texel_size_x, rep.texel_size_y);
    *sphere_center = rep.sphere_center;
    s->n_eye = INFINITY;
    return SWARP_OK;
}

/* Split i's atlas place, kernel scale [RHS] (3.9) and depth per world unit
 * at the centroid of B_i (origin-relative when stabilised), and its error
 * model values. */
static swarp_status sw_split_report(const sw_cascade_run* c, swarp_cascade_split* s, const swarp_atlas_tile* tile,
                                    swarp_vec3 sphere_center, const swarp_atlas_info* atlas) {
    s->tile = *tile;
    sw_mul(&tile->clip_to_atlas, &s->matrix, &s->atlas_matrix);
    swarp_vec3 ctr = sw_v3(0, 0, 0);
    for (size_t k = 0; k < c->npts; ++k) ctr = sw_add(ctr, c->pts[k]);
    ctr = c->npts ? sw_scale(ctr, 1.0 / (double)c->npts) : sphere_center;
    if (c->smode != SWARP_STABILIZE_NONE) ctr = sw_sub(ctr, c->o.stabilize.origin);
    sw_kernel_scale(&s->matrix, ctr, c->r_l, atlas->l_sc, s->kernel_scale);
    /* world bias -> this split's depth units, at the centroid */
    swarp_bias_map bm;
    memset(&bm, 0, sizeof bm);
    bm.world_to_clip = s->matrix;
    bm.res_s = bm.res_t = (double)c->tile_res;
    bm.depth = c->o.setup.depth_range;
    swarp_light lw = *c->light;
    if (c->smode != SWARP_STABILIZE_NONE) lw.position = sw_sub(lw.position, c->o.stabilize.origin);
    if (swarp_bias_depth_per_world(&bm, &lw, &ctr, &s->depth_per_world) != SWARP_OK)
        s->depth_per_world = 0.0; /* point light at the centroid */
    swarp_status st = sw_split_errors(c->cam, &c->o.setup, s);
    if (st != SWARP_OK) return st;
    if (!sw_mat_finite(&s->matrix) || !sw_mat_finite(&s->atlas_matrix) || !sw_finite(s->kernel_scale[0]) ||
        !sw_finite(s->kernel_scale[1]))
        return SWARP_ERR_NON_FINITE;
    return SWARP_OK;
}

/* The search's estimate of a split's measured error: swarp_measure_max on
 * the vertices of H_i and a 2 x 2 lattice at 2 depths with four refinement
 * steps (SW_SEARCH_*), a fraction of the default sampling.  The
 * maximum of these projective maps' error over the convex H_i lies at or
 * near a vertex (swarp_measure_max), so the vertices carry most of it;
 * the chosen positions are measured with the full sampling afterwards. */
#define SW_SEARCH_GRID 2u
#define SW_SEARCH_DEPTHS 2u
#define SW_SEARCH_REFINE 4u
static void sw_split_measure_cheap(const sw_cascade_run* c, swarp_cascade_split* s, const swarp_mat4* m) {
    swarp_measure_res mr;
    mr.screen_width = c->o.setup.screen_width ? c->o.setup.screen_width : SW_DEFAULT_SCREEN_W;
    mr.screen_height = c->o.setup.screen_height ? c->o.setup.screen_height : SW_DEFAULT_SCREEN_H;
    mr.map_width = mr.map_height = c->tile_res;
    swarp_measure_options mo;
    memset(&mo, 0, sizeof mo);
    mo.grid = SW_SEARCH_GRID, mo.depths = SW_SEARCH_DEPTHS, mo.refine = SW_SEARCH_REFINE;
    memset(&s->measured, 0, sizeof s->measured);
    if (swarp_status_is_error(swarp_measure_max(c->cam, s->z_near, s->z_far, c->light, c->scene, m, &mr, &mo,
                                                &s->measured)))
        s->measured.max_sigma = INFINITY; /* counted as a singular split */
}

/* The measured error of split i's final matrix over its frustum ∩ S; the
 * stabilised matrix takes p - origin, so it is measured as matrix ·
 * T(-origin).  The unstabilised single map is swarp_setup's, measured there. */
static void sw_split_measure(const sw_cascade_run* c, swarp_cascade_split* s) {
    if (c->single && c->smode == SWARP_STABILIZE_NONE) {
        s->measured = c->sr.measured;
        return;
    }
    swarp_mat4 m = s->matrix;
    if (c->smode != SWARP_STABILIZE_NONE) {
        swarp_mat4 t;
        sw_identity(&t);
        sw_set(&t, 0, 3, -c->o.stabilize.origin.x);
        sw_set(&t, 1, 3, -c->o.stabilize.origin.y);
        sw_set(&t, 2, 3, -c->o.stabilize.origin.z);
        sw_mul(&s->matrix, &t, &m);
    }
    if (c->search) {
        sw_split_measure_cheap(c, s, &m);
        return;
    }
    sw_measure_setup(c->cam, s->z_near, s->z_far, c->light, c->scene, &m, &c->o.setup, &s->measured);
}

/* The whole cascade's measured error: the worst split's maxima, the samples
 * of all splits. */
static void sw_cascade_measure_merge(const swarp_cascade_split* s, swarp_measured_error* all) {
    const swarp_measured_error* m = &s->measured;
    if (m->samples == 0) return;
    if (all->samples == 0 || m->max_sigma > all->max_sigma) all->max_sigma = m->max_sigma, all->at = m->at;
    all->max_m_s = fmax(all->max_m_s, m->max_m_s);
    all->max_m_t = fmax(all->max_m_t, m->max_m_t);
    all->samples += m->samples;
    all->outside += m->outside;
}

/* Every split: its setup options, light matrix, stabilisation and report;
 * res collects the maxima, *info the first informational status. */
static swarp_status sw_cascade_splits_compute(sw_cascade_run* c, swarp_status single_st, const swarp_atlas_tile* tiles,
                                              swarp_cascade_result* res, swarp_cascade_split* sp,
                                              swarp_status* info) {
    const double f_dot_eye = sw_dot(c->cam_f, c->cam->eye);
    /* FROM_FIRST: nu_i = n_opt of (3.2) for each split's own range, the
     * scale by which the first split's n' is carried to split i */
    double nu[SWARP_CASCADE_MAX_SPLITS];
    swarp_status st;
    if (c->wmode == SWARP_CASCADE_WARP_FROM_FIRST && c->K > 1) {
        st = swarp_cascade_nopt(res->splits, c->K, 0.0, 0.0, nu);
        if (swarp_status_is_error(st)) return st;
    }
    for (uint32_t i = 0; i < c->K; ++i) {
        swarp_cascade_split* s = &sp[i];
        swarp_vec3 sphere_center = sw_v3(0, 0, 0);
        s->z_near = res->splits[i];
        s->z_far = res->splits[i + 1];
        const swarp_setup_options so = sw_split_setup_options(c, i, nu, sp, res);
        st = sw_split_matrix(c, s, i, f_dot_eye, &so, single_st);
        if (swarp_status_is_error(st)) return st;
        s->status = st;
        if (st != SWARP_OK && *info == SWARP_OK) *info = st;
        s->point_count = (uint32_t)c->npts;
        s->matrix = c->sr.matrix;
        s->n_eye = c->sr.n_eye;
        if (c->smode != SWARP_STABILIZE_NONE && (st = sw_split_stabilize(c, s, &sphere_center, info)) != SWARP_OK)
            return st;
        if ((st = sw_split_report(c, s, &tiles[i], sphere_center, &res->atlas)) != SWARP_OK) return st;
        sw_split_measure(c, s);
        sw_cascade_measure_merge(s, &res->measured);
        if (s->max_mx > res->max_mx) res->max_mx = s->max_mx;
        if (s->max_mz > res->max_mz) res->max_mz = s->max_mz;
    }
    return SWARP_OK;
}

/* ---- split positions by measurement --------------------------------------
 * SWARP_SCHEME_MEASURED: the practical scheme's λ ([RHS] (3.8)) that
 * minimises the worst split's measured σ.  The worst split's σ falls with
 * λ where the near split is too long and rises where the far ones are, so
 * it has one minimum in the cases this is meant for.  First the two λ
 * engines use, 0.5 (PSSM) and 0.95 (OGRE's PSSM default), and the end
 * λ = 1 (the log scheme (3.7)); when λ = 1 is the best of the three and
 * no worse than 0.95, the one minimum lies in [0.95, 1] and λ = 1 is kept
 * (on ordinary scenes the nearest split is the worst and log makes it
 * smallest: this is the common case, three evaluations).  Otherwise a
 * golden-section search on [0, 1] (SW_SPLIT_SEARCH_STEPS evaluations)
 * looks for the interior minimum; the choice is never worse than any λ
 * evaluated, under the search's estimate.  Each
 * evaluation is the cascade's own matrices with the cheap measurement of
 * sw_split_measure_cheap; the chosen λ's cascade is then computed and
 * measured as every cascade is.  Deterministic: a fixed sequence of λ. */
#define SW_SPLIT_SEARCH_STEPS 6
#define SW_SPLIT_LAMBDA_OGRE 0.95
/* Two candidates whose estimates differ by less than this fraction are a
 * tie, decided by their order: a cascade's measured σ carries the rounding
 * of the matrices and of the compass search's path (far below 1e-9 in
 * round-to-nearest, but a directed rounding mode can move a search step),
 * and a choice decided by that rounding would make the splits depend on
 * the caller's rounding mode.  1e-6 is far above that and far below any
 * gain worth a different split. */
#define SW_SPLIT_TIE_REL 1e-6

/* A candidate's estimate: how many splits the cheap sampling finds
 * singular (σ = +inf at some sample: a texel-singular point, which a
 * directed rounding mode can produce on H_i's boundary where the full
 * sampling stays finite) and the worst finite split σ.  Fewer singular
 * splits win, then the smaller worst σ. */
typedef struct sw_split_score {
    uint32_t singular;
    double worst;
} sw_split_score;

/* a clearly better than b (not a tie) */
static int sw_split_better(sw_split_score a, sw_split_score b) {
    if (a.singular != b.singular) return a.singular < b.singular;
    return a.worst < b.worst * (1.0 - SW_SPLIT_TIE_REL);
}

/* the estimate of the practical scheme with lambda on [view_near,
 * view_far]; every split singular when a split cannot be set up */
static sw_split_score sw_split_candidate(sw_cascade_run* c, const swarp_atlas_tile* tiles,
                                         const swarp_cascade_result* res, double lambda) {
    sw_split_score sc = {SWARP_CASCADE_MAX_SPLITS + 1, INFINITY};
    swarp_cascade_result r = *res;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    memset(sp, 0, c->K * sizeof sp[0]);
    size_t cnt;
    if (swarp_split_practical(res->view_near, res->view_far, lambda, c->K, r.splits, SWARP_CASCADE_MAX_SPLITS + 1,
                              &cnt) != SWARP_OK)
        return sc;
    memset(&r.measured, 0, sizeof r.measured);
    swarp_status info = SWARP_OK;
    c->search = 1;
    swarp_status st = sw_cascade_splits_compute(c, SWARP_OK, tiles, &r, sp, &info);
    c->search = 0;
    if (st != SWARP_OK) return sc;
    sc.singular = 0;
    sc.worst = 0.0;
    for (uint32_t i = 0; i < c->K; ++i) {
        const double w = sp[i].measured.max_sigma;
        if (w < INFINITY) sc.worst = fmax(sc.worst, w);
        else sc.singular++;
    }
    return sc;
}

/* res->splits of the practical scheme with lambda */
static void sw_split_apply(swarp_cascade_result* res, double lambda, uint32_t K) {
    size_t cnt;
    double tmp[SWARP_CASCADE_MAX_SPLITS + 1];
    if (swarp_split_practical(res->view_near, res->view_far, lambda, K, tmp, SWARP_CASCADE_MAX_SPLITS + 1, &cnt) ==
        SWARP_OK)
        memcpy(res->splits, tmp, cnt * sizeof tmp[0]);
}

/* res->splits of the λ the search chooses (res->splits on entry: λ = 0.5) */
static void sw_split_place_measured(sw_cascade_run* c, const swarp_atlas_tile* tiles, swarp_cascade_result* res) {
    const double phi = 0.5 * (sqrt(5.0) - 1.0); /* golden section */
    double best_l = SW_DEFAULT_PSSM_LAMBDA;
    sw_split_score best = sw_split_candidate(c, tiles, res, best_l);
    sw_split_score e = sw_split_candidate(c, tiles, res, SW_SPLIT_LAMBDA_OGRE);
    if (sw_split_better(e, best)) best = e, best_l = SW_SPLIT_LAMBDA_OGRE;
    const sw_split_score f95 = e;
    e = sw_split_candidate(c, tiles, res, 1.0); /* the log scheme (3.7): the bracket's end */
    if (sw_split_better(e, best)) best = e, best_l = 1.0;
    if (best_l == 1.0 && !sw_split_better(f95, e)) {
        sw_split_apply(res, best_l, c->K);
        return;
    }
    double a = 0.0, b = 1.0, x1 = b - phi * (b - a), x2 = a + phi * (b - a);
    sw_split_score f1 = sw_split_candidate(c, tiles, res, x1), f2 = sw_split_candidate(c, tiles, res, x2);
    for (int k = 2; k < SW_SPLIT_SEARCH_STEPS; ++k) {
        if (!sw_split_better(f2, f1)) {
            b = x2, x2 = x1, f2 = f1, x1 = b - phi * (b - a);
            f1 = sw_split_candidate(c, tiles, res, x1);
        } else {
            a = x1, x1 = x2, f1 = f2, x2 = a + phi * (b - a);
            f2 = sw_split_candidate(c, tiles, res, x2);
        }
    }
    if (sw_split_better(f1, best)) best = f1, best_l = x1;
    if (sw_split_better(f2, best)) best = f2, best_l = x2;
    if (best.singular > SWARP_CASCADE_MAX_SPLITS) return; /* nothing could be set up: keep λ = 0.5 */
    sw_split_apply(res, best_l, c->K);
}

SWARP_API swarp_status swarp_cascade_setup(const swarp_camera* cam, const swarp_light* light,
                                           const swarp_aabb* scene,
                                           const swarp_cascade_options* opts,
                                           swarp_cascade_result* out,
                                           swarp_cascade_split* out_splits, size_t capacity,
                                           size_t* out_count) {
    if (!cam || !light || !scene || !out || !out_count) return SWARP_ERR_NULL_POINTER;
    sw_cascade_run c;
    c.cam = cam;
    c.light = light;
    c.scene = scene;
    swarp_status st = sw_check_cascade_options(opts, out_splits, capacity, out_count, &c);
    if (st != SWARP_OK) return st;
    if ((st = sw_check_cascade_scene(&c)) != SWARP_OK) return st;
    uint32_t map_h;
    sw_setup_map_size(&c.o.setup, &c.tile_res, &map_h); /* the atlas tile: map_width */

    swarp_cascade_result res;
    memset(&res, 0, sizeof res);
    res.split_count = c.K;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    memset(sp, 0, c.K * sizeof sp[0]);
    swarp_atlas_tile tiles[SWARP_ATLAS_MAX_SPLITS];
    size_t cnt;
    st = swarp_atlas_layout(c.K, c.tile_res, c.o.setup.depth_range, &res.atlas, tiles, SWARP_ATLAS_MAX_SPLITS, &cnt);
    if (st != SWARP_OK) return st;

    c.pts = c.pts_buf;
    c.npts = 0;
    c.cam_f = sw_v3(0, 0, -1);
    c.single = (c.K == 1 && c.smode == SWARP_STABILIZE_NONE && !c.any_user);
    swarp_status single_st = SWARP_OK, info = SWARP_OK;
    st = c.single ? sw_cascade_single_range(&c, &res, &single_st) : sw_cascade_split_range(&c, &res);
    if (st != SWARP_OK) return st;
    if (c.measured_splits && !c.single) sw_split_place_measured(&c, tiles, &res);
    if ((st = sw_cascade_splits_compute(&c, single_st, tiles, &res, sp, &info)) != SWARP_OK) return st;
    memcpy(out_splits, sp, c.K * sizeof *sp);
    *out = res;
    *out_count = c.K;
    return info;
}
