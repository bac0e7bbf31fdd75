/* Internal helpers shared by the stages: small double-precision vector and
 * matrix routines and argument checks.  Not installed, not exported. */
#ifndef SWARP_INTERNAL_H
#define SWARP_INTERNAL_H

#include <math.h>
#include <string.h>

#ifndef SWARP_EXPERIMENTAL_API /* the library defines every declaration */
#define SWARP_EXPERIMENTAL_API 1
#endif
#include "shadowwarp.h"

/* Every exported definition carries SWARP_API; the build defines
 * SWARP_BUILDING so it expands to default visibility. */

#define SWARP_PI 3.14159265358979323846

/* ---- extended exponent ------------------------------------------------- */
/* x = m 2^e with |m| in [0.5, 1) (or m = 0): a double with an int exponent,
 * for products and quotients whose factors span more than the double range
 * (extreme inputs beyond 1e+-100, docs/quality.md) while the result is
 * representable.  Each operation rounds the mantissa once, like a double;
 * sw_xd_get rounds once more into the subnormal range or to +-inf. */
typedef struct sw_xd {
    double m;
    int e;
} sw_xd;

static inline sw_xd sw_xd_of(double x) {
    sw_xd r;
    r.m = frexp(x, &r.e);
    return r;
}
static inline sw_xd sw_xd_norm(double m, int e) {
    int k;
    sw_xd r;
    r.m = frexp(m, &k);
    r.e = r.m == 0.0 ? 0 : e + k;
    return r;
}
static inline double sw_xd_get(sw_xd a) { return ldexp(a.m, a.e); }
static inline sw_xd sw_xd_mul(sw_xd a, sw_xd b) { return sw_xd_norm(a.m * b.m, a.e + b.e); }
static inline sw_xd sw_xd_div(sw_xd a, sw_xd b) { return sw_xd_norm(a.m / b.m, a.e - b.e); }
static inline sw_xd sw_xd_scale(sw_xd a, int k) { return sw_xd_norm(a.m, a.e + k); }
/* a + b: the smaller is aligned to the larger's exponent (beyond 2^-110 it
 * cannot change the rounded sum). */
static inline sw_xd sw_xd_add(sw_xd a, sw_xd b) {
    if (b.m == 0.0) return a;
    if (a.m == 0.0) return b;
    if (a.e < b.e) {
        sw_xd t = a;
        a = b;
        b = t;
    }
    int d = a.e - b.e;
    if (d > 110) return a;
    return sw_xd_norm(a.m + ldexp(b.m, -d), a.e);
}
/* sqrt(a) for a >= 0: the exponent made even first, so sqrt(m) is one rounding. */
static inline sw_xd sw_xd_sqrt(sw_xd a) {
    if (a.m == 0.0) return a;
    double m = a.m;
    int e = a.e;
    if (e & 1) {
        m *= 2.0;
        e -= 1;
    }
    return sw_xd_norm(sqrt(m), e / 2);
}

/* ---- checks ------------------------------------------------------------ */
static inline int sw_finite(double x) { return isfinite(x) != 0; }
static inline int sw_finite3(const swarp_vec3* v) {
    return sw_finite(v->x) && sw_finite(v->y) && sw_finite(v->z);
}
static inline int sw_reserved_zero(const uint32_t* r, size_t n) {
    for (size_t i = 0; i < n; ++i)
        if (r[i] != 0) return 0;
    return 1;
}

/* ---- vec3 -------------------------------------------------------------- */
static inline swarp_vec3 sw_v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static inline swarp_vec3 sw_add(swarp_vec3 a, swarp_vec3 b) { return sw_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline swarp_vec3 sw_sub(swarp_vec3 a, swarp_vec3 b) { return sw_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline swarp_vec3 sw_scale(swarp_vec3 a, double s) { return sw_v3(a.x * s, a.y * s, a.z * s); }
static inline double sw_dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline swarp_vec3 sw_cross(swarp_vec3 a, swarp_vec3 b) {
    return sw_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* hypot-based length: no overflow for large-world coordinates */
static inline double sw_len(swarp_vec3 a) { return hypot(hypot(a.x, a.y), a.z); }
/* Returns 0 (and leaves *out alone) for a zero or non-finite vector. */
static inline int sw_normalize(swarp_vec3 a, swarp_vec3* out) {
    double l = sw_len(a);
    if (l == INFINITY && sw_finite3(&a)) {
        /* a finite vector whose length overflows (components near DBL_MAX)
         * is a valid direction: divided by its largest component first
         * (exact up to one rounding) */
        const double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
        a = sw_v3(a.x / m, a.y / m, a.z / m);
        l = sw_len(a);
    }
    if (!(l > 0.0) || !sw_finite(l)) return 0;
    /* divide, not multiply by 1/l: for a subnormal length 1/l overflows */
    swarp_vec3 n = sw_v3(a.x / l, a.y / l, a.z / l);
    if (!sw_finite3(&n)) return 0;
    *out = n;
    return 1;
}

/* Two lengths, one vocabulary.  sw_len / sw_normalize use hypot: correct
 * for every finite vector, for the values the library reports or compares
 * with a threshold.  sw_len_fast / sw_normalize_fast take the square root
 * of the sum of squares where that cannot overflow or underflow (squared
 * length in (1e-290, 1e290)), about 4x cheaper on the geometry stage's
 * inner loops (clipping, the body's sweep), and fall back to a scaled form
 * outside that range; within it the two differ by at most one rounding. */

/* sqrt of the sum of squares inside the safe range, sw_len outside it. */
static inline double sw_len_fast(swarp_vec3 a) {
    double s = a.x * a.x + a.y * a.y + a.z * a.z;
    if (s > 1e-290 && s < 1e290) return sqrt(s);
    return sw_len(a);
}
/* Unit vector of a; 0 (and *out untouched) for a zero or non-finite a.
 * Outside the safe range a is first divided by its largest component: a
 * subnormal a (|a| = 5e-324, where 1/|a| overflows and inf * 0 would give
 * NaN components) and an a near DBL_MAX (|a| overflows) are valid
 * directions and get a unit vector. */
static inline int sw_normalize_fast(swarp_vec3 a, swarp_vec3* out) {
    double s = a.x * a.x + a.y * a.y + a.z * a.z;
    if (s > 1e-290 && s < 1e290) {
        *out = sw_scale(a, 1.0 / sqrt(s));
        return 1;
    }
    /* a NaN component fails the range test above too, and fmax would skip it */
    if (!sw_finite3(&a)) return 0;
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(m > 0.0)) return 0;
    swarp_vec3 b = sw_v3(a.x / m, a.y / m, a.z / m); /* a component is ±1: no overflow */
    *out = sw_scale(b, 1.0 / sqrt(sw_dot(b, b)));
    return 1;
}
/* Θ = fovy/2 for the error model and the parameters: the smallest
 * subnormal fovy (valid, > 0) halves to 0, which they would refuse as a
 * field of view (SWARP_ERR_FOV); it is kept at the smallest positive double
 * instead. */
static inline double sw_half_fovy(double fovy) {
    double t = 0.5 * fovy;
    return t > 0.0 ? t : 0x1p-1074;
}

/* ---- mat4 (column-major, m[c*4 + r]) ------------------------------------- */
static inline double sw_at(const swarp_mat4* m, int r, int c) { return m->m[c * 4 + r]; }
static inline void sw_set(swarp_mat4* m, int r, int c, double v) { m->m[c * 4 + r] = v; }
static inline void sw_identity(swarp_mat4* m) {
    memset(m, 0, sizeof *m);
    m->m[0] = m->m[5] = m->m[10] = m->m[15] = 1.0;
}
static inline void sw_mul(const swarp_mat4* a, const swarp_mat4* b, swarp_mat4* r) {
    swarp_mat4 t;
    for (int c = 0; c < 4; ++c)
        for (int rr = 0; rr < 4; ++rr) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += sw_at(a, rr, k) * sw_at(b, k, c);
            t.m[c * 4 + rr] = s;
        }
    *r = t;
}
static inline swarp_vec4 sw_xform4(const swarp_mat4* m, swarp_vec4 p) {
    swarp_vec4 o;
    o.x = m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12] * p.w;
    o.y = m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13] * p.w;
    o.z = m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14] * p.w;
    o.w = m->m[3] * p.x + m->m[7] * p.y + m->m[11] * p.z + m->m[15] * p.w;
    return o;
}
static inline swarp_vec4 sw_xform_point(const swarp_mat4* m, swarp_vec3 p) {
    swarp_vec4 h = {p.x, p.y, p.z, 1.0};
    return sw_xform4(m, h);
}
static inline int sw_mat_finite(const swarp_mat4* m) {
    for (int i = 0; i < 16; ++i)
        if (!sw_finite(m->m[i])) return 0;
    return 1;
}
/* Gauss-Jordan with partial pivoting; returns 0 when singular. */
int sw_invert(const swarp_mat4* a, swarp_mat4* out);

/* ==== input checks (src/common/check.c) =================================
 * The one set of argument checks and named thresholds of the entry points,
 * and the defaults they resolve ("zero means default").  Each check returns
 * SWARP_OK or the status the header documents for the first bad field. */

/* up must leave a usable right vector r = dir x up: sin(angle(dir, up)) of
 * at least 1e-9.  r then carries a relative rounding error of about
 * eps / 1e-9 = 2e-7 (unit inputs, one cross product), still a direction the
 * frustum corners, the light-space alignment and the warp can be built on;
 * closer to parallel the image plane has no defined orientation. */
#define SW_CAMERA_MIN_UP_SIN 1e-9

/* Defaults of the setup options (swarp_setup, swarp_cascade_setup). */
#define SW_DEFAULT_MAP_RES 2048u    /* map side in texels; also swarp_budget.map_resolution */
#define SW_DEFAULT_SCREEN_W 1920u   /* screen in pixels for the error model */
#define SW_DEFAULT_SCREEN_H 1080u
/* The planner's screen default (swarp_scene_needs): the resolution of [RHS]'s
 * measurements, documented apart from the setup's. */
#define SW_PLAN_DEFAULT_SCREEN_W 1024u
#define SW_PLAN_DEFAULT_SCREEN_H 768u
/* Split count and PSSM weight λ: Zhang et al.'s practical scheme with four
 * splits, [RHS] §3.3.2 (swarp_cascade_splits, swarp_cascade_setup, plan). */
#define SW_DEFAULT_SPLIT_COUNT 4u
#define SW_DEFAULT_PSSM_LAMBDA 0.5

static inline swarp_technique sw_resolve_technique(swarp_technique t) {
    return t == SWARP_TECHNIQUE_DEFAULT ? SWARP_TECHNIQUE_LISPSM : t;
}
static inline swarp_depth_range sw_resolve_depth_range(swarp_depth_range d) {
    return d == SWARP_DEPTH_DEFAULT ? SWARP_DEPTH_NEG_ONE_TO_ONE : d;
}

swarp_status sw_check_depth_range(swarp_depth_range d);
/* reserved, non-finite, fovy in (0, pi), aspect > 0, dir and up non-zero,
 * up not parallel to dir (SW_CAMERA_MIN_UP_SIN); not near/far */
swarp_status sw_check_camera_shape(const swarp_camera* cam);
/* finite, 0 < near < far (SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR) */
swarp_status sw_check_view_range(double near, double far);
/* the shape, then the camera's own near/far */
swarp_status sw_check_camera(const swarp_camera* cam);
/* reserved, type, then only the fields the type uses */
swarp_status sw_check_light(const swarp_light* light);
/* finite, min <= max, at most one zero extent */
swarp_status sw_check_box(const swarp_aabb* box);
swarp_status sw_check_setup_options(const swarp_setup_options* o);
/* *o = *opts (zeroed for NULL), then checked */
swarp_status sw_resolve_setup_options(const swarp_setup_options* opts, swarp_setup_options* o);
/* v[0..m] finite (SWARP_ERR_NON_FINITE) and strictly increasing
 * (SWARP_ERR_NOT_INCREASING): split distances, layer borders */
swarp_status sw_check_increasing(const double* v, size_t m);
/* the LiSPSM fields of the setup options as swarp_warp_options */
swarp_warp_options sw_setup_warp_options(const swarp_setup_options* o);
/* map width and height with the defaults resolved (height 0: = width) */
void sw_setup_map_size(const swarp_setup_options* o, uint32_t* width, uint32_t* height);
/* the error model's configuration of a setup: screen and map with their
 * defaults, Θ = theta, the view range [near, far] */
void sw_setup_error_config(const swarp_setup_options* o, double theta, double near, double far,
                           swarp_error_config* cfg);

/* The measured error a setup result carries (src/model/measured_error.c):
 * zero when o->skip_measure is set or nothing of V ∩ S is sampled. */
void sw_measure_setup(const swarp_camera* cam, double z_near, double z_far, const swarp_light* light,
                      const swarp_aabb* scene, const swarp_mat4* matrix, const swarp_setup_options* o,
                      swarp_measured_error* out);
/* A receiver of the measured warp search's fixed point set: the point,
 * the tangents (w_x, w_z) of its bisector receiver and J_scr there
 * (js[column][row], columns along w_x and w_z): what of D does not depend
 * on the matrix. */
typedef struct sw_receiver {
    swarp_vec3 x, wx, wz;
    double js[2][2];
} sw_receiver;
/* The fixed point set (H's vertices, interior points) as receivers, and
 * the max sigma of a matrix on it (and the mean). */
size_t sw_measure_set_make(const swarp_camera* cam, const swarp_light* light, const swarp_setup_options* o,
                           const swarp_vec3* h, size_t nh, sw_receiver* out, size_t cap);
double sw_measure_set_sigma(const swarp_mat4* matrix, const swarp_setup_options* o, const sw_receiver* rc,
                            size_t n, double* mean);

#endif
