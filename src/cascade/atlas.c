/* Texture atlas layouts and the PCF kernel scale per split.
 * [RHS] §3.3.5 (Fig. 3.16) and [RHS] (3.9). */
#include "common/swarp_internal.h"
#include "common/depth_range.h"

_Static_assert(sizeof(swarp_atlas_info) == 8 + 3 * sizeof(double) + 16, "swarp_atlas_info size");
_Static_assert(sizeof(swarp_atlas_tile) == 4 * sizeof(double) + sizeof(swarp_mat4),
               "swarp_atlas_tile size");

/* Largest tile side accepted: 2^24 texels keeps every texel number an exact
 * integer in float as well as in double. */
#define SW_ATLAS_MAX_TILE_RES 16777216u

/* Grid side of the layout that holds m splits: [RHS] Fig. 3.16 (4, 9, 16). */
static uint32_t sw_atlas_grid(uint32_t m) {
    if (m == 1) return 1;
    if (m <= 4) return 2;
    if (m <= 9) return 3;
    return 4;
}

SWARP_API swarp_status swarp_atlas_lsc(uint32_t m, double* out_l_sc) {
    if (!out_l_sc) return SWARP_ERR_NULL_POINTER;
    if (m < 1 || m > SWARP_ATLAS_MAX_SPLITS) return SWARP_ERR_ATLAS_SPLITS;
    /* [RHS] (3.9): l_sc = 1/2 for 1 < m <= 4, 1/3 up to 9, 1/4 up to 16;
     * m = 1 has the whole texture: l_sc = 1. */
    *out_l_sc = 1.0 / (double)sw_atlas_grid(m);
    return SWARP_OK;
}

SWARP_API swarp_status swarp_atlas_layout(uint32_t m, uint32_t tile_res, swarp_depth_range depth,
                                          swarp_atlas_info* out_info, swarp_atlas_tile* out_tiles,
                                          size_t capacity, size_t* out_count) {
    if (!out_count) return SWARP_ERR_NULL_POINTER;
    if (m < 1 || m > SWARP_ATLAS_MAX_SPLITS) return SWARP_ERR_ATLAS_SPLITS;
    if (tile_res == 0 || tile_res > SW_ATLAS_MAX_TILE_RES) return SWARP_ERR_RESOLUTION;
    if (!sw_light_depth_range_ok(depth)) return SWARP_ERR_UNKNOWN_ENUM;
    if (capacity < m) {
        *out_count = m;
        return SWARP_ERR_CAPACITY;
    }
    if (!out_tiles) return SWARP_ERR_NULL_POINTER;

    const uint32_t grid = sw_atlas_grid(m);
    const double l_sc = 1.0 / (double)grid;
    /* window depth d from clip z: d = a z + b w.  [0, 1] and reversed-Z pass
     * z through: a reversed split matrix already has z = w at the light's
     * near plane and 0 at its far plane, so d = 1 - d_forward there. */
    const int zero_one = sw_depth_zero_based(depth);
    const double dz_a = zero_one ? 1.0 : 0.5, dz_b = zero_one ? 0.0 : 0.5;

    for (uint32_t i = 0; i < m; ++i) {
        swarp_atlas_tile t;
        const uint32_t col = i % grid, row = i / grid;
        t.viewport_x = (double)col * tile_res;
        t.viewport_y = (double)row * tile_res;
        t.viewport_width = t.viewport_height = (double)tile_res;
        /* u = u0 + l_sc (x/w + 1)/2  =>  u w = (l_sc/2) x + (u0 + l_sc/2) w */
        const double u0 = (double)col * l_sc, v0 = (double)row * l_sc;
        sw_identity(&t.clip_to_atlas);
        sw_set(&t.clip_to_atlas, 0, 0, 0.5 * l_sc);
        sw_set(&t.clip_to_atlas, 0, 3, u0 + 0.5 * l_sc);
        sw_set(&t.clip_to_atlas, 1, 1, 0.5 * l_sc);
        sw_set(&t.clip_to_atlas, 1, 3, v0 + 0.5 * l_sc);
        sw_set(&t.clip_to_atlas, 2, 2, dz_a);
        sw_set(&t.clip_to_atlas, 2, 3, dz_b);
        out_tiles[i] = t;
    }
    if (out_info) {
        swarp_atlas_info info;
        memset(&info, 0, sizeof info);
        info.split_count = m;
        info.grid = grid;
        info.tile_res = (double)tile_res;
        info.atlas_res = (double)grid * (double)tile_res;
        info.l_sc = l_sc;
        *out_info = info;
    }
    *out_count = m;
    return SWARP_OK;
}

/* num * 2/(hi - lo) without spurious overflow: the width of two finite
 * coordinates can exceed DBL_MAX (then num/(hi/2 - lo/2), halves exact for
 * such magnitudes), and 2/width can overflow for a subnormal width while
 * num * 2/width does not: divide mantissas, add exponents, round once. */
static double sw_kernel_axis(double num, double lo, double hi) {
    double w = hi - lo;
    int e_n, e_w, extra = 1;
    if (!sw_finite(w)) {
        w = 0.5 * hi - 0.5 * lo;
        extra = 0;
    }
    double m_n = frexp(num, &e_n), m_w = frexp(w, &e_w);
    return ldexp(m_n / m_w, e_n - e_w + extra);
}

SWARP_API swarp_status swarp_atlas_kernel_scale(double r_l, uint32_t m, double min_x,
                                                double max_x, double min_y, double max_y,
                                                double out_s[2]) {
    if (!out_s) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(r_l) || !sw_finite(min_x) || !sw_finite(max_x) || !sw_finite(min_y) ||
        !sw_finite(max_y))
        return SWARP_ERR_NON_FINITE;
    if (m < 1 || m > SWARP_ATLAS_MAX_SPLITS) return SWARP_ERR_ATLAS_SPLITS;
    if (r_l < 0.0 || !(max_x > min_x) || !(max_y > min_y)) return SWARP_ERR_OUT_OF_RANGE;
    const double l_sc = 1.0 / (double)sw_atlas_grid(m);
    /* [RHS] (3.9): s_i = r_l l_sc (2/(max_x - min_x), 2/(max_y - min_y)) */
    double s_x = sw_kernel_axis(r_l * l_sc, min_x, max_x);
    double s_y = sw_kernel_axis(r_l * l_sc, min_y, max_y);
    /* finite inputs, scale beyond DBL_MAX (a width near DBL_TRUE_MIN) */
    if (!sw_finite(s_x) || !sw_finite(s_y)) return SWARP_ERR_OVERFLOW;
    out_s[0] = s_x;
    out_s[1] = s_y;
    return SWARP_OK;
}
