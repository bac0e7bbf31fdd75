/*
 * shadowwarp_cglm.h -- optional, header-only converters between libshadowwarp's
 * double-precision boundary types and cglm's float types.
 *
 * Never part of the ABI: everything here is static inline, and cglm (with its
 * alignment attributes and build flags) stays out of shadowwarp.h and out of
 * the .pc requirements.  Include it after <cglm/cglm.h> is reachable.
 *
 * Both sides are column-major: cglm's mat4 is float[4][4] indexed [column][row],
 * swarp_mat4 is double m[16] with m[column*4 + row].  No transpose happens.
 */
#ifndef SHADOWWARP_CGLM_H
#define SHADOWWARP_CGLM_H

#include <cglm/cglm.h>

#include "shadowwarp.h"

/** swarp_mat4 (double) -> cglm mat4 (float), element by element. */
static inline void swarp_cglm_mat4_from_swarp(const swarp_mat4* in, mat4 out) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out[c][r] = (float)in->m[c * 4 + r];
}

/** cglm mat4 (float) -> swarp_mat4 (double), exact. */
static inline void swarp_cglm_mat4_to_swarp(mat4 in, swarp_mat4* out) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out->m[c * 4 + r] = (double)in[c][r];
}

/** swarp_vec3 (double) -> cglm vec3 (float). */
static inline void swarp_cglm_vec3_from_swarp(const swarp_vec3* in, vec3 out) {
    out[0] = (float)in->x;
    out[1] = (float)in->y;
    out[2] = (float)in->z;
}

/** cglm vec3 (float) -> swarp_vec3 (double), exact. */
static inline void swarp_cglm_vec3_to_swarp(vec3 in, swarp_vec3* out) {
    out->x = (double)in[0];
    out->y = (double)in[1];
    out->z = (double)in[2];
}

#endif /* SHADOWWARP_CGLM_H */
