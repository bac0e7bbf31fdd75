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
