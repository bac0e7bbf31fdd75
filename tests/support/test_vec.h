/* test_vec: the 3-vector arithmetic the Check suites write out themselves
 * (header only), independent of the library's internal vocabulary so that a
 * test never checks the library against its own helpers. */
#ifndef TEST_VEC_H
#define TEST_VEC_H

#include <math.h>

#include "shadowwarp.h"

static inline swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static inline swarp_vec3 vsub(swarp_vec3 a, swarp_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline swarp_vec3 vadd(swarp_vec3 a, swarp_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline swarp_vec3 vscale(swarp_vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline double vdot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline swarp_vec3 vcross(swarp_vec3 a, swarp_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vlen(swarp_vec3 a) { return sqrt(vdot(a, a)); }
static inline swarp_vec3 vnorm(swarp_vec3 a) { return vscale(a, 1.0 / vlen(a)); }

#endif
