/* The light's clip depth conventions in one place.  Reversed-Z is the
 * [0, 1] map turned over: z' = w - z, so z'/w = 1 - z/w puts the near plane
 * at 1 and the far plane at 0 with x, y and w unchanged.  Building the
 * [0, 1] matrix and then reversing its depth row is exact in the sense
 * that matters: the [0, 1] fit's bounds land on 1 and 0 to one rounding. */
#ifndef SWARP_DEPTH_RANGE_H
#define SWARP_DEPTH_RANGE_H

#include "common/swarp_internal.h"

/* The conventions the light-matrix builders (focus fit, stabilisation,
 * cube faces) accept: the three of sw_check_depth_range and reversed-Z. */
static inline int sw_light_depth_range_ok(swarp_depth_range d) {
    return sw_check_depth_range(d) == SWARP_OK || d == SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
}
/* NDC depth in [0, 1] (forward or reversed) rather than [-1, 1] */
static inline int sw_depth_zero_based(swarp_depth_range d) {
    return d == SWARP_DEPTH_ZERO_TO_ONE || d == SWARP_DEPTH_REVERSED_ZERO_TO_ONE;
}
/* row 2 := row 3 - row 2: a [0, 1] matrix turned reversed-Z */
static inline void sw_depth_reverse(swarp_mat4* m) {
    for (int c = 0; c < 4; ++c) sw_set(m, 2, c, sw_at(m, 3, c) - sw_at(m, 2, c));
}
/* the same when d is reversed-Z, for a matrix built [0, 1] */
static inline void sw_depth_reverse_if(swarp_depth_range d, swarp_mat4* m) {
    if (d == SWARP_DEPTH_REVERSED_ZERO_TO_ONE) sw_depth_reverse(m);
}

#endif
