/* Cascades (z-partitioning) combined with any geometry technique: split
 * selection, blending, per-split matrices and the configuration's error
 * curve.  [RHS] §3.3-3.4, §4.1-4.2. */
#include "splits_internal.h"

static swarp_status sw_check_splits(const double* splits, size_t m) {
    if (!splits) return SWARP_ERR_NULL_POINTER;
    if (m < 1 || m > SWARP_SPLIT_MAX_COUNT) return SWARP_ERR_SPLIT_COUNT;
    for (size_t i = 0; i <= m; ++i)
        if (!sw_finite(splits[i])) return SWARP_ERR_NON_FINITE;
    for (size_t i = 0; i < m; ++i)
        if (!(splits[i + 1] > splits[i])) return SWARP_ERR_NOT_INCREASING;
    return SWARP_OK;
}

/* Depth selection without checks: the split containing z, clamped. */
static uint32_t sw_select_depth(const double* splits, size_t m, double z, int* outside) {
    *outside = (z < splits[0] || z > splits[m]);
    uint32_t i = 0;
    /* m <= 64: a linear scan is as fast as a bisection and mirrors the GLSL */
    while (i + 1 < m && z >= splits[i + 1]) ++i;
    return i;
}

SWARP_API swarp_status swarp_cascade_select_depth(const double* splits, size_t m, double view_depth,
                                                  uint32_t* out_index) {
    if (!out_index) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_splits(splits, m);
    if (st != SWARP_OK) return st;
    if (!sw_finite(view_depth)) return SWARP_ERR_NON_FINITE;
    int outside;
    *out_index = sw_select_depth(splits, m, view_depth, &outside);
    return outside ? SWARP_INFO_OUTSIDE_SPLITS : SWARP_OK;
}

SWARP_API swarp_status swarp_cascade_blend(const double* splits, size_t m, double view_depth,
                                           double band, uint32_t* out_index, double* out_weight) {
    if (!out_index || !out_weight) return SWARP_ERR_NULL_POINTER;
    swarp_status st = sw_check_splits(splits, m);
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
    const double zlo = map->depth == SWARP_DEPTH_ZERO_TO_ONE ? 0.0 : -h.w;
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
    if (o.count == 0) o.count = 4;
    if (o.scheme == SWARP_SCHEME_DEFAULT) {
        o.scheme = SWARP_SCHEME_PRACTICAL;
        o.lambda = 0.5; /* PSSM's choice, [RHS] §3.3.2 */
    }
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
    swarp_status st = sw_check_splits(splits, m);
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
    swarp_status st = sw_check_splits(splits, m);
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
            else
                z = a + (b - a) * (double)j / (double)(samples_per_split - 1);
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
