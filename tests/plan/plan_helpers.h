/* Helpers of the planner's tests (tests/plan/): the reference camera and a
 * chain to evaluate. */
#ifndef PLAN_HELPERS_H
#define PLAN_HELPERS_H

#include <string.h>

#include "shadowwarp.h"

/* The camera of the planner's tests: at (0, 2, 0) looking along -z (up +y),
 * fovy 60°, aspect 4/3, near 1, far fn. */
static inline swarp_camera plan_test_camera(double fn) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){0.0, 2.0, 0.0};
    cam.dir = (swarp_vec3){0.0, 0.0, -1.0};
    cam.up = (swarp_vec3){0.0, 1.0, 0.0};
    cam.fovy = 60.0 * 3.14159265358979323846 / 180.0;
    cam.aspect = 4.0 / 3.0;
    cam.z_near = 1.0;
    cam.z_far = fn;
    return cam;
}

/* A chain: warp, scheme and split count, the rest zero (defaults). */
static inline swarp_plan_chain chain_of(swarp_plan_warp w, swarp_plan_scheme s, uint32_t K) {
    swarp_plan_chain c;
    memset(&c, 0, sizeof c);
    c.warp = w;
    c.scheme = s;
    c.split_count = K;
    return c;
}

#endif
