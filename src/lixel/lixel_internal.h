/* Internal helpers of the lixel stage ([LIXEL] Chong & Gortler): the
 * 4-vector part of the vocabulary of common/swarp_internal.h (points and
 * covectors in homogeneous coordinates). */
#ifndef SWARP_LIXEL_INTERNAL_H
#define SWARP_LIXEL_INTERNAL_H

#include "common/swarp_internal.h"

static inline double sw_dot4(swarp_vec4 a, swarp_vec4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
static inline double sw_len4(swarp_vec4 a) { return hypot(hypot(a.x, a.y), hypot(a.z, a.w)); }
static inline swarp_vec4 sw_v4(double x, double y, double z, double w) {
    swarp_vec4 v = {x, y, z, w};
    return v;
}
static inline swarp_vec4 sw_scale4(swarp_vec4 a, double s) { return sw_v4(a.x * s, a.y * s, a.z * s, a.w * s); }
static inline int sw_finite4(swarp_vec4 a) { return sw_finite(a.x) && sw_finite(a.y) && sw_finite(a.z) && sw_finite(a.w); }
/* Row r of a column-major matrix as a covector. */
static inline swarp_vec4 sw_row4(const swarp_mat4* m, int r) {
    return sw_v4(m->m[r], m->m[4 + r], m->m[8 + r], m->m[12 + r]);
}
static inline void sw_set_row4(swarp_mat4* m, int r, swarp_vec4 v) {
    m->m[r] = v.x;
    m->m[4 + r] = v.y;
    m->m[8 + r] = v.z;
    m->m[12 + r] = v.w;
}

static inline double sw_det3(double a, double b, double c, double d, double e, double f, double g, double h,
                             double i) {
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}
/* The point X with a.X = b.X = c.X = 0 (generalised cross product: signed
 * 3x3 minors).  Zero when the covectors are dependent. */
static inline swarp_vec4 sw_cross4(swarp_vec4 a, swarp_vec4 b, swarp_vec4 c) {
    swarp_vec4 X;
    X.x = sw_det3(a.y, a.z, a.w, b.y, b.z, b.w, c.y, c.z, c.w);
    X.y = -sw_det3(a.x, a.z, a.w, b.x, b.z, b.w, c.x, c.z, c.w);
    X.z = sw_det3(a.x, a.y, a.w, b.x, b.y, b.w, c.x, c.y, c.w);
    X.w = -sw_det3(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z);
    return X;
}
static inline swarp_vec4 sw_unit4(swarp_vec4 a) {
    double l = sw_len4(a);
    return l > 0.0 ? sw_scale4(a, 1.0 / l) : a;
}

#endif
