/* Internal helpers of the cascade stage (cascade, stabilise, bias, atlas). */
#ifndef SWARP_CASCADE_INTERNAL_H
#define SWARP_CASCADE_INTERNAL_H

#include "common/swarp_internal.h"

/* Orthonormal camera frame: f forward, r right, u up (right-handed view). */
typedef struct sw_cam_frame {
    swarp_vec3 eye, f, r, u;
    double tan_half; /* tan(fovy/2) */
    double aspect;
} sw_cam_frame;

/* Validates a camera except near/far with the common camera check (the
 * caller checks its own range) and builds its frame.  Returns a status;
 * *out written only on SWARP_OK. */
static inline swarp_status sw_cam_frame_make(const swarp_camera* cam, sw_cam_frame* out) {
    if (!cam) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    sw_cam_frame fr;
    swarp_vec3 up;
    if (!sw_normalize(cam->dir, &fr.f) || !sw_normalize(cam->up, &up)) return SWARP_ERR_ZERO_VECTOR;
    /* |f x up| >= SW_CAMERA_MIN_UP_SIN (checked) up to rounding */
    if (!sw_normalize(sw_cross(fr.f, up), &fr.r)) return SWARP_ERR_DEGENERATE;
    fr.u = sw_cross(fr.r, fr.f);
    fr.eye = cam->eye;
    fr.tan_half = tan(0.5 * cam->fovy);
    fr.aspect = cam->aspect;
    *out = fr;
    return SWARP_OK;
}

/* The 8 corners of the frustum slice [n, f] of a camera frame, near 0..3
 * then far 4..7, each (-x,-y), (+x,-y), (+x,+y), (-x,+y). */
static inline void sw_frustum_corners(const sw_cam_frame* fr, double n, double f,
                                      swarp_vec3 out[8]) {
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 2; ++k) {
        const double z = k ? f : n;
        const double hy = z * fr->tan_half, hx = hy * fr->aspect;
        for (int c = 0; c < 4; ++c) {
            swarp_vec3 p = sw_add(fr->eye, sw_scale(fr->f, z));
            p = sw_add(p, sw_scale(fr->r, sx[c] * hx));
            p = sw_add(p, sw_scale(fr->u, sy[c] * hy));
            out[k * 4 + c] = p;
        }
    }
}

/* the common depth-range check as a predicate */
static inline int sw_depth_range_ok(swarp_depth_range d) { return sw_check_depth_range(d) == SWARP_OK; }

#endif
