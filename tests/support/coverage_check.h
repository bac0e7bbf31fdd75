/* coverage_check: the promise of a successful swarp_setup, swarp_setup_range
 * or cascade split, checked against V ∩ S found by brute force (header only).
 *
 * Independent of the library's clipper and of its body B: the receivers are
 * points of the view frustum V (a lateral grid and random samples over
 * [near, far], and random points of the bounding box of V ∩ S, all formed in
 * long double from the camera's own parameters) that lie inside the scene
 * box S; for a spot light only those inside its cone.  At each receiver X:
 *
 *   map    X maps into the map: w > 0 and |x/w|, |y/w| <= 1 + CC_TOL_MAP;
 *   depth  every point of S on the segment from X toward the light (to the
 *          light itself, or for a directional light until the ray leaves S)
 *          has w > 0 and a depth inside the depth range to CC_TOL_DEPTH of
 *          its width; pancaking: the receiver inside, the casters at most
 *          the far end of the range (the renderer clamps them to the near);
 *   ray    directional light: those points land where X does, to
 *          CC_TOL_RAY (one light ray, one texel);
 *
 * SWARP_INFO_CASTERS_CLAMPED: the casters are held to the pancaking rule
 * (the status documents casters beyond 1e10 times the receivers' size
 * along the light as clamped to the near plane);
 * a spot light reporting SWARP_INFO_LIGHT_NEAR_CLIPPED may leave out the
 * points nearer its apex, along its axis, than SW_LIGHT_NEAR_MIN_REL (1e-4)
 * of B's farthest depth (docs/geometry.md), bounded here from above by the
 * farthest corner of S or of V, whichever is nearer.
 *
 * The matrix is evaluated in long double at the long double points, so the
 * check measures the map, not the rounding of the check. */
#ifndef COVERAGE_CHECK_H
#define COVERAGE_CHECK_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "shadowwarp.h"

/* 1e-6 of the map's half width: the accuracy the fit promises
 * (docs/quality.md, SW_REL_RESOLVE in src/geometry/setup.c). */
#define CC_TOL_MAP 1e-6
/* 1e-6 of the depth window's width, for the same reason. */
#define CC_TOL_DEPTH 1e-6
/* 2e-6 NDC: 1e-6 of the map's width, 1/500 of a texel of a 2048 map. */
#define CC_TOL_RAY 2e-6
/* the region a LIGHT_NEAR_CLIPPED spot may leave out, relative to B's
 * farthest depth along the axis (the library's SW_LIGHT_NEAR_MIN_REL), and
 * never less than 192 eps of the coordinates' magnitude (its floor: the
 * rounding of D = a·p - a·l) */
#define CC_NEAR_CLIP_REL 1e-4
#define CC_NEAR_CLIP_EPS (192 * (cc_real)DBL_EPSILON)

typedef long double cc_real;
typedef struct cc_v3 { cc_real x, y, z; } cc_v3;

static inline cc_v3 cc_v(cc_real x, cc_real y, cc_real z) { cc_v3 r = {x, y, z}; return r; }
static inline cc_v3 cc_of(swarp_vec3 a) { return cc_v(a.x, a.y, a.z); }
static inline cc_v3 cc_add(cc_v3 a, cc_v3 b) { return cc_v(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline cc_v3 cc_sub(cc_v3 a, cc_v3 b) { return cc_v(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline cc_v3 cc_mul(cc_v3 a, cc_real s) { return cc_v(a.x * s, a.y * s, a.z * s); }
static inline cc_real cc_dot(cc_v3 a, cc_v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline cc_v3 cc_cross(cc_v3 a, cc_v3 b) {
    return cc_v(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* unit vector, scaled first so that subnormal or huge inputs normalise */
static inline cc_v3 cc_unit(cc_v3 a) {
    cc_real m = fmaxl(fabsl(a.x), fmaxl(fabsl(a.y), fabsl(a.z)));
    if (!(m > 0)) return a;
    a = cc_mul(a, 1.0L / m);
    return cc_mul(a, 1.0L / sqrtl(cc_dot(a, a)));
}

/* the view frustum's frame and half-extents, from the camera alone */
typedef struct cc_frustum { cc_v3 eye, f, r, u; cc_real tx, ty; } cc_frustum;
static inline cc_frustum cc_frustum_of(const swarp_camera* cam) {
    cc_frustum F;
    F.eye = cc_of(cam->eye);
    F.f = cc_unit(cc_of(cam->dir));
    F.r = cc_unit(cc_cross(F.f, cc_of(cam->up)));
    F.u = cc_cross(F.r, F.f);
    F.ty = tanl(0.5L * cam->fovy);
    F.tx = F.ty * cam->aspect;
    return F;
}
static inline cc_v3 cc_frustum_point(const cc_frustum* F, cc_real sx, cc_real sy, cc_real z) {
    cc_v3 d = cc_add(F->f, cc_add(cc_mul(F->r, sx * F->tx), cc_mul(F->u, sy * F->ty)));
    return cc_add(F->eye, cc_mul(d, z));
}
static inline int cc_in_frustum(const cc_frustum* F, cc_v3 p, cc_real zn, cc_real zf) {
    cc_v3 q = cc_sub(p, F->eye);
    cc_real z = cc_dot(q, F->f);
    if (!(z >= zn && z <= zf)) return 0;
    return fabsl(cc_dot(q, F->r)) <= z * F->tx && fabsl(cc_dot(q, F->u)) <= z * F->ty;
}
static inline int cc_in_box(const swarp_aabb* b, cc_v3 p) {
    return p.x >= b->min.x && p.x <= b->max.x && p.y >= b->min.y && p.y <= b->max.y && p.z >= b->min.z &&
           p.z <= b->max.z;
}

/* the segment from p along unit dir t in [0, tmax] clipped to S: *t1 */
static inline int cc_ray_box_exit(const swarp_aabb* b, cc_v3 p, cc_v3 d, cc_real tmax, cc_real* t1) {
    const cc_real pc[3] = {p.x, p.y, p.z}, dc[3] = {d.x, d.y, d.z};
    const double lo[3] = {b->min.x, b->min.y, b->min.z}, hi[3] = {b->max.x, b->max.y, b->max.z};
    cc_real t = tmax;
    for (int k = 0; k < 3; ++k) {
        if (dc[k] > 0) t = fminl(t, (hi[k] - pc[k]) / dc[k]);
        else if (dc[k] < 0) t = fminl(t, (lo[k] - pc[k]) / dc[k]);
    }
    *t1 = t;
    return t >= 0;
}

typedef struct cc_result {
    int receivers;     /* receivers checked */
    double map_excess; /* worst max(|x|, |y|) - 1 (>0: outside) */
    double depth_excess; /* worst distance outside the depth window, in its widths */
    double ray_spread; /* worst NDC distance between a receiver and a caster on its light ray */
    int behind;        /* points with w <= 0 */
    cc_v3 worst;       /* the receiver of the worst violation */
} cc_result;

typedef struct cc_map {
    const swarp_mat4* m;
    double dlo, dhi; /* the depth window */
    int pancake, directional;
} cc_map;

static inline int cc_eval(const swarp_mat4* m, cc_v3 p, cc_real out[3]) {
    const double* a = m->m;
    cc_real X = a[0] * p.x + a[4] * p.y + a[8] * p.z + (cc_real)a[12];
    cc_real Y = a[1] * p.x + a[5] * p.y + a[9] * p.z + (cc_real)a[13];
    cc_real Z = a[2] * p.x + a[6] * p.y + a[10] * p.z + (cc_real)a[14];
    cc_real W = a[3] * p.x + a[7] * p.y + a[11] * p.z + (cc_real)a[15];
    if (!(W > 0)) return 0;
    out[0] = X / W, out[1] = Y / W, out[2] = Z / W;
    return 1;
}

/* the light as the check sees it: direction toward the light from p, and
 * how far the light is (INFINITY: directional) */
typedef struct cc_light { int point, spot; cc_v3 l, d, axis; cc_real cos_cone, clip_d; } cc_light;

static inline cc_light cc_light_of(const swarp_light* L, const swarp_aabb* S, const cc_frustum* F, cc_real zn,
                                   cc_real zf, int near_clipped) {
    cc_light c;
    c.point = L->type == SWARP_LIGHT_POINT;
    c.spot = c.point && L->cone_angle > 0;
    c.l = cc_of(L->position);
    c.d = cc_unit(cc_of(L->direction));
    c.axis = c.d;
    c.cos_cone = c.spot ? cosl(L->cone_angle) : -2;
    c.clip_d = 0;
    if (c.spot && near_clipped) {
        /* B's farthest depth along the axis is at most that of V ∩ S (B
         * adds only the part toward the light), so at most the smaller of
         * the farthest corners of S and of V */
        cc_real dS = 0, dV = 0, mag = fmaxl(fabsl(c.l.x), fmaxl(fabsl(c.l.y), fabsl(c.l.z)));
        for (int i = 0; i < 8; ++i) {
            cc_v3 k = cc_v((i & 1) ? S->max.x : S->min.x, (i & 2) ? S->max.y : S->min.y, (i & 4) ? S->max.z : S->min.z);
            dS = fmaxl(dS, cc_dot(cc_sub(k, c.l), c.axis));
            cc_v3 v = cc_frustum_point(F, (i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? zf : zn);
            dV = fmaxl(dV, cc_dot(cc_sub(v, c.l), c.axis));
            mag = fmaxl(mag, fmaxl(fabsl(v.x), fmaxl(fabsl(v.y), fabsl(v.z))));
        }
        /* B lies in the hull of V and the light: its magnitude is at most mag */
        c.clip_d = fmaxl(CC_NEAR_CLIP_REL * fminl(dS, dV), CC_NEAR_CLIP_EPS * mag);
    }
    return c;
}
/* a spot lights p: inside its cone */
static inline int cc_lit(const cc_light* c, cc_v3 p) {
    if (!c->spot) return 1;
    cc_v3 q = cc_sub(p, c->l);
    cc_real len = sqrtl(cc_dot(q, q));
    return len > 0 && cc_dot(q, c->axis) >= c->cos_cone * len;
}
static inline int cc_clipped(const cc_light* c, cc_v3 p) {
    return c->clip_d > 0 && cc_dot(cc_sub(p, c->l), c->axis) < c->clip_d;
}

static inline void cc_note(cc_result* r, double* field, double v, cc_v3 x) {
    if (v > *field) {
        *field = v;
        r->worst = x;
    }
}

/* the three properties at receiver x */
static inline void cc_check_receiver(const cc_map* M, const cc_light* L, const swarp_aabb* S, cc_v3 x,
                                     cc_result* r) {
    if (!cc_lit(L, x) || cc_clipped(L, x)) return;
    cc_real px[3];
    r->receivers++;
    if (!cc_eval(M->m, x, px)) {
        r->behind++;
        r->worst = x;
        return;
    }
    const double width = M->dhi - M->dlo;
    cc_note(r, &r->map_excess, (double)(fmaxl(fabsl(px[0]), fabsl(px[1])) - 1), x);
    cc_note(r, &r->depth_excess, (double)(fmaxl(M->dlo - px[2], px[2] - M->dhi) / width), x);
    cc_v3 dir;
    cc_real tmax;
    if (L->point) {
        dir = cc_sub(L->l, x);
        tmax = sqrtl(cc_dot(dir, dir));
        if (!(tmax > 0)) return;
        dir = cc_mul(dir, 1 / tmax);
    } else {
        dir = cc_mul(L->d, -1);
        tmax = INFINITY;
    }
    cc_real t1;
    if (!cc_ray_box_exit(S, x, dir, tmax, &t1) || !(t1 > 0)) return;
    static const double frac[] = {1e-9, 1e-6, 1e-4, 1e-3, 0.01, 0.05, 0.1, 0.25, 0.4, 0.6, 0.8, 0.95, 1.0};
    for (size_t k = 0; k < sizeof frac / sizeof frac[0]; ++k) {
        cc_v3 c = cc_add(x, cc_mul(dir, t1 * frac[k]));
        if (!cc_in_box(S, c) || cc_clipped(L, c)) continue;
        if (L->point && frac[k] == 1.0 && t1 == tmax) continue; /* the light itself */
        cc_real pc[3];
        if (!cc_eval(M->m, c, pc)) {
            r->behind++;
            r->worst = x;
            continue;
        }
        double ex = M->pancake ? (double)((pc[2] - M->dhi) / width)
                               : (double)(fmaxl(M->dlo - pc[2], pc[2] - M->dhi) / width);
        cc_note(r, &r->depth_excess, ex, x);
        if (M->directional)
            cc_note(r, &r->ray_spread, (double)fmaxl(fabsl(pc[0] - px[0]), fabsl(pc[1] - px[1])), x);
    }
}

static inline uint64_t cc_next(uint64_t* s) {
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static inline cc_real cc_unif(uint64_t* s) { return (cc_real)(cc_next(s) >> 11) * 0x1p-53L; }

/* a view depth in [zn, zf]: linear or geometric by the sample's index */
static inline cc_real cc_depth(cc_real zn, cc_real zf, cc_real t, int geometric) {
    if (geometric && zn > 0) return fminl(zf, zn * powl(zf / zn, t));
    return fminl(zf, zn + (zf - zn) * t);
}

/* Every check over V ∩ S for the view range [zn, zf] of cam; lat: lateral
 * grid size, nd: depths, nr: random samples (seeded by seed). */
static inline cc_result cc_check(const swarp_camera* cam, double zn, double zf, const swarp_light* light,
                                 const swarp_aabb* S, const swarp_mat4* m, swarp_depth_range dr, int pancake,
                                 swarp_status status, int lat, int nd, int nr, uint64_t seed) {
    cc_result r = {0, -INFINITY, -INFINITY, 0.0, 0, {0, 0, 0}};
    const cc_frustum F = cc_frustum_of(cam);
    const cc_light L = cc_light_of(light, S, &F, zn, zf, status == SWARP_INFO_LIGHT_NEAR_CLIPPED);
    cc_map M = {m, dr == SWARP_DEPTH_ZERO_TO_ONE ? 0.0 : -1.0, 1.0, pancake || status == SWARP_INFO_CASTERS_CLAMPED,
                light->type != SWARP_LIGHT_POINT};
    /* the frustum's lateral grid at nd depths, linear and geometric */
    for (int g = 0; g < 2; ++g)
        for (int k = 0; k < nd; ++k) {
            cc_real z = cc_depth(zn, zf, (cc_real)k / (nd - 1), g);
            for (int i = 0; i < lat; ++i)
                for (int j = 0; j < lat; ++j) {
                    cc_v3 p = cc_frustum_point(&F, -1 + 2.0L * i / (lat - 1), -1 + 2.0L * j / (lat - 1), z);
                    if (cc_in_box(S, p)) cc_check_receiver(&M, &L, S, p, &r);
                }
        }
    /* random points of V, and of the box around V ∩ S (its corners too) */
    cc_real lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < 8; ++c) {
        cc_v3 p = cc_frustum_point(&F, (c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? zf : zn);
        const cc_real pc[3] = {p.x, p.y, p.z};
        for (int k = 0; k < 3; ++k) lo[k] = fminl(lo[k], pc[k]), hi[k] = fmaxl(hi[k], pc[k]);
    }
    const double smin[3] = {S->min.x, S->min.y, S->min.z}, smax[3] = {S->max.x, S->max.y, S->max.z};
    for (int k = 0; k < 3; ++k) lo[k] = fmaxl(lo[k], smin[k]), hi[k] = fminl(hi[k], smax[k]);
    uint64_t s = seed;
    for (int i = 0; i < nr; ++i) {
        cc_v3 p = cc_frustum_point(&F, 2 * cc_unif(&s) - 1, 2 * cc_unif(&s) - 1, cc_depth(zn, zf, cc_unif(&s), i & 1));
        if (cc_in_box(S, p)) cc_check_receiver(&M, &L, S, p, &r);
    }
    if (lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2])
        for (int i = 0; i < nr + 8; ++i) {
            cc_v3 p;
            if (i < 8)
                p = cc_v((i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]);
            else
                p = cc_v(lo[0] + (hi[0] - lo[0]) * cc_unif(&s), lo[1] + (hi[1] - lo[1]) * cc_unif(&s),
                         lo[2] + (hi[2] - lo[2]) * cc_unif(&s));
            if (cc_in_frustum(&F, p, zn, zf) && cc_in_box(S, p)) cc_check_receiver(&M, &L, S, p, &r);
        }
    return r;
}

/* the promise holds: within every tolerance, nothing behind the map */
static inline int cc_ok(const cc_result* r) {
    return r->behind == 0 && r->map_excess <= CC_TOL_MAP && r->depth_excess <= CC_TOL_DEPTH &&
           r->ray_spread <= CC_TOL_RAY;
}
static inline void cc_print(FILE* f, const cc_result* r) {
    fprintf(f, "receivers %d map_excess %.3g depth_excess %.3g ray_spread %.3g behind %d at (%.17Lg, %.17Lg, %.17Lg)",
            r->receivers, r->map_excess, r->depth_excess, r->ray_spread, r->behind, r->worst.x, r->worst.y,
            r->worst.z);
}

#endif
