/* Extras: [RHS] §4.3 "Maximizing the near plane distance" -- the minimum of
 * a linear depth buffer by the 2x2 min pyramid of [RHS] Listing A.2 (on the
 * CPU), a direct scan, and the adjusted near plane it implies. */
#include "common/swarp_internal.h"

/* Default relative margin between the measured minimum depth and the new
 * near plane: 1e-3 keeps a float depth buffer's own rounding (~6e-8
 * relative) and the rasteriser's depth interpolation far inside. */
#define SW_MINDEPTH_DEFAULT_MARGIN 1e-3

_Static_assert(sizeof(swarp_mindepth_options) == sizeof(double) + 16, "swarp_mindepth_options size");
_Static_assert(sizeof(swarp_cube_options) == sizeof(double) + 4 + 20, "swarp_cube_options size");

static float sw_minf(float a, float b) { return b < a ? b : a; }

/* Validates the buffer: NaN / -inf -> NON_FINITE, negative -> OUT_OF_RANGE
 * (a min pyramid would otherwise hide a NaN behind the comparison's choice).
 * The same pass gives the direct minimum in *direct_min. */
static swarp_status sw_depth_check(const float* depth, uint32_t w, uint32_t h, size_t stride,
                                   float* direct_min) {
    if (!depth) return SWARP_ERR_NULL_POINTER;
    if (w == 0 || h == 0 || stride < w) return SWARP_ERR_INVALID_ARGUMENT;
    int nan = 0, negative = 0;
    float m = INFINITY;
    for (uint32_t y = 0; y < h; ++y) {
        const float* row = depth + (size_t)y * stride;
        for (uint32_t x = 0; x < w; ++x) {
            float v = row[x];
            nan |= (v != v) | (v == -INFINITY);
            negative |= v < 0.0f;
            m = sw_minf(m, v);
        }
    }
    if (nan) return SWARP_ERR_NON_FINITE;
    if (negative) return SWARP_ERR_OUT_OF_RANGE;
    *direct_min = m;
    return SWARP_OK;
}

/* [RHS] Listing A.2 on the CPU */
SWARP_API swarp_status swarp_mindepth_pyramid(const float* depth, uint32_t width, uint32_t height,
                                              size_t row_stride, float* scratch,
                                              size_t scratch_capacity, size_t* out_scratch_needed,
                                              double* out_min) {
    if (!out_scratch_needed || !out_min) return SWARP_ERR_NULL_POINTER;
    float direct_min;
    swarp_status s = sw_depth_check(depth, width, height, row_stride, &direct_min);
    if (s != SWARP_OK) return s;
    size_t needed = SWARP_MINDEPTH_SCRATCH(width, height);
    if (scratch_capacity < needed || !scratch) {
        *out_scratch_needed = needed;
        return scratch ? SWARP_ERR_CAPACITY : (scratch_capacity ? SWARP_ERR_NULL_POINTER : SWARP_ERR_CAPACITY);
    }
    /* level 1 from the input; then in place: writing index y*w1 + x never
     * passes a texel that a later output still reads (2y*w0 + 2x >= y*w1 + x) */
    const float* src = depth;
    size_t src_stride = row_stride;
    size_t w0 = width, h0 = height;
    if (w0 == 1 && h0 == 1) {
        scratch[0] = depth[0];
    }
    while (w0 > 1 || h0 > 1) {
        size_t w1 = (w0 + 1) / 2, h1 = (h0 + 1) / 2; /* round UP: keep odd edges */
        for (size_t y = 0; y < h1; ++y) {
            size_t y0 = 2 * y, y1 = (2 * y + 1 < h0) ? 2 * y + 1 : 2 * y; /* clamp at the edge */
            for (size_t x = 0; x < w1; ++x) {
                size_t x0 = 2 * x, x1 = (2 * x + 1 < w0) ? 2 * x + 1 : 2 * x;
                /* the four samples of Listing A.2: tex, +y, +x, +xy */
                float m = src[y0 * src_stride + x0];
                m = sw_minf(m, src[y1 * src_stride + x0]);
                m = sw_minf(m, src[y0 * src_stride + x1]);
                m = sw_minf(m, src[y1 * src_stride + x1]);
                scratch[y * w1 + x] = m;
            }
        }
        src = scratch;
        src_stride = w1;
        w0 = w1;
        h0 = h1;
    }
    double mn = (double)scratch[0];
    *out_scratch_needed = needed;
    *out_min = mn;
    return isinf(mn) ? SWARP_INFO_MINDEPTH_EMPTY : SWARP_OK;
}

/* [RHS] §4.3, the reference */
SWARP_API swarp_status swarp_mindepth_direct(const float* depth, uint32_t width, uint32_t height,
                                             size_t row_stride, double* out_min) {
    if (!out_min) return SWARP_ERR_NULL_POINTER;
    float m;
    swarp_status s = sw_depth_check(depth, width, height, row_stride, &m);
    if (s != SWARP_OK) return s;
    *out_min = (double)m;
    return isinf(m) ? SWARP_INFO_MINDEPTH_EMPTY : SWARP_OK;
}

/* [RHS] §4.3: the measured minimum depth as the new near plane */
SWARP_API swarp_status swarp_mindepth_near(double n, double f, double min_depth,
                                           const swarp_mindepth_options* opt, double* out_near) {
    if (!out_near) return SWARP_ERR_NULL_POINTER;
    double margin = SW_MINDEPTH_DEFAULT_MARGIN;
    if (opt) {
        if (!sw_reserved_zero(opt->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
        if (!sw_finite(opt->margin)) return SWARP_ERR_NON_FINITE;
        if (!(opt->margin >= 0.0 && opt->margin < 1.0)) return SWARP_ERR_OUT_OF_RANGE;
        if (opt->margin != 0.0) margin = opt->margin;
    }
    if (!sw_finite(n) || !sw_finite(f) || isnan(min_depth) || min_depth == -INFINITY)
        return SWARP_ERR_NON_FINITE;
    if (!(n > 0.0) || !(f > n)) return SWARP_ERR_NEAR_FAR;
    if (!(min_depth >= 0.0)) return SWARP_ERR_OUT_OF_RANGE;
    if (min_depth >= f) { /* nothing nearer than far (or an empty buffer) */
        *out_near = n;
        return SWARP_INFO_MINDEPTH_EMPTY;
    }
    double near_adj = min_depth * (1.0 - margin); /* < min_depth < f */
    *out_near = near_adj > n ? near_adj : n;
    return SWARP_OK;
}
