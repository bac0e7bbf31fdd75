#define _POSIX_C_SOURCE 200809L
/* [LIXEL] Chong & Gortler: plane-stabilised light matrices.  The viewer side
 * is evaluated here independently of the library: pixels from the camera's
 * basis vectors and tan(fovy/2), plane points by ray casting, not through
 * M_v or its inverse. */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define M_PI 3.14159265358979323846

/* ---- small PRNG (splitmix64) -------------------------------------------- */
static uint64_t rng_state;
static uint64_t rng_next(void) { return tu_splitmix64(&rng_state); }
static double rnd(double a, double b) { return tu_uniform(&rng_state, a, b); }

typedef struct v3 { double x, y, z; } v3;
static v3 V(double x, double y, double z) { v3 r = {x, y, z}; return r; }
static v3 add(v3 a, v3 b) { return V(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 sub(v3 a, v3 b) { return V(a.x - b.x, a.y - b.y, a.z - b.z); }
static v3 mul(v3 a, double s) { return V(a.x * s, a.y * s, a.z * s); }
static double dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static v3 cross(v3 a, v3 b) { return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static double len(v3 a) { return sqrt(dot(a, a)); }
static v3 unit(v3 a) { return mul(a, 1.0 / len(a)); }
static v3 rnd_unit(void) {
    for (;;) {
        v3 v = V(rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        double l = len(v);
        if (l > 0.1 && l <= 1.0) return mul(v, 1.0 / l);
    }
}

/* ---- the viewer, evaluated from its basis ------------------------------- */
typedef struct cam {
    v3 eye, f, s, u; /* forward, right, up (orthonormal) */
    double tan_half, aspect, z_near, z_far;
    unsigned g, h;
} cam;

static cam make_cam(v3 eye, v3 dir, v3 up, double fovy, double aspect, double near, double far, unsigned g,
                    unsigned h) {
    cam c;
    c.eye = eye;
    c.f = unit(dir);
    c.s = unit(cross(c.f, up));
    c.u = cross(c.s, c.f);
    c.tan_half = tan(0.5 * fovy);
    c.aspect = aspect;
    c.z_near = near;
    c.z_far = far;
    c.g = g;
    c.h = h;
    return c;
}

/* OpenGL lookAt * perspective, written out element by element. */
static swarp_mat4 cam_matrix(const cam* c) {
    double f = 1.0 / c->tan_half, n = c->z_near, fa = c->z_far;
    double P[4][4] = {{f / c->aspect, 0, 0, 0}, {0, f, 0, 0}, {0, 0, (fa + n) / (n - fa), 2 * fa * n / (n - fa)}, {0, 0, -1, 0}};
    double Vw[4][4] = {{c->s.x, c->s.y, c->s.z, -dot(c->s, c->eye)},
                       {c->u.x, c->u.y, c->u.z, -dot(c->u, c->eye)},
                       {-c->f.x, -c->f.y, -c->f.z, dot(c->f, c->eye)},
                       {0, 0, 0, 1}};
    swarp_mat4 m;
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) {
            double acc = 0;
            for (int j = 0; j < 4; ++j) acc += P[r][j] * Vw[j][k];
            m.m[k * 4 + r] = acc;
        }
    return m;
}

/* viewer pixel of a world point (in front of the eye) */
static void cam_pixel(const cam* c, v3 X, double* x, double* y) {
    v3 v = sub(X, c->eye);
    double zc = dot(v, c->f);
    double xn = dot(v, c->s) / (zc * c->tan_half * c->aspect), yn = dot(v, c->u) / (zc * c->tan_half);
    *x = (xn + 1.0) * 0.5 * c->g - 0.5;
    *y = (yn + 1.0) * 0.5 * c->h - 0.5;
}

/* ray through pixel (x, y) hits the plane; returns the ray parameter
 * (> 0: in front) and the point */
static double cam_hit(const cam* c, const swarp_plane* P, double x, double y, v3* X) {
    double xn = (x + 0.5) * 2.0 / c->g - 1.0, yn = (y + 0.5) * 2.0 / c->h - 1.0;
    v3 d = add(c->f, add(mul(c->s, xn * c->tan_half * c->aspect), mul(c->u, yn * c->tan_half)));
    v3 n = V(P->a, P->b, P->c);
    double t = -(dot(n, c->eye) + P->d) / dot(n, d);
    *X = add(c->eye, mul(d, t));
    return t;
}

/* light pixel of a world point: x, y, z and q */
static void light_px(const swarp_mat4* M, v3 X, double* x, double* y, double* z, double* q) {
    double o[4];
    for (int r = 0; r < 4; ++r) o[r] = M->m[r] * X.x + M->m[4 + r] * X.y + M->m[8 + r] * X.z + M->m[12 + r];
    *q = o[3];
    *x = o[0] / o[3];
    *y = o[1] / o[3];
    *z = o[2] / o[3];
}
/* Light pixel with the float matrix.  arith_float = 0: the float matrix
 * evaluated in double on the exact point (isolates what swarp_mat4_to_float
 * loses); 1: everything in float like a GPU. */
static void light_px_f(const float* M, v3 X, int arith_float, double* x, double* y) {
    if (arith_float) {
        float p[3] = {(float)X.x, (float)X.y, (float)X.z};
        float o[4];
        for (int r = 0; r < 4; ++r) o[r] = M[r] * p[0] + M[4 + r] * p[1] + M[8 + r] * p[2] + M[12 + r];
        *x = o[0] / o[3];
        *y = o[1] / o[3];
        return;
    }
    double o[4];
    for (int r = 0; r < 4; ++r)
        o[r] = (double)M[r] * X.x + (double)M[4 + r] * X.y + (double)M[8 + r] * X.z + (double)M[12 + r];
    *x = o[0] / o[3];
    *y = o[1] / o[3];
}

static v3 row3(const swarp_mat4* M, int r) { return V(M->m[r], M->m[4 + r], M->m[8 + r]); }
static int mat_finite(const swarp_mat4* M) {
    for (int i = 0; i < 16; ++i)
        if (!isfinite(M->m[i])) return 0;
    return 1;
}

static swarp_light point_light(v3 p) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_POINT;
    l.position.x = p.x, l.position.y = p.y, l.position.z = p.z;
    return l;
}
static swarp_light dir_light(v3 d) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction.x = d.x, l.direction.y = d.y, l.direction.z = d.z;
    return l;
}
static swarp_plane plane_through(v3 n, v3 X) {
    swarp_plane p = {n.x, n.y, n.z, -dot(n, X)};
    return p;
}

/* A random configuration whose plane is seen by the viewer. */
typedef struct config {
    cam c;
    swarp_mat4 Mv;
    swarp_plane P;
    swarp_light light;
    v3 lpos; /* point light position (if point) */
} config;

static config random_config(double world) {
    config k;
    for (;;) {
        v3 eye = V(rnd(-world, world), rnd(-world, world), rnd(-world, world));
        v3 dir = rnd_unit(), up = rnd_unit();
        if (len(cross(dir, up)) < 0.2) continue;
        double fovy = rnd(20, 120) * M_PI / 180.0, aspect = rnd(0.5, 2.0), near = rnd(0.05, 1.0);
        double far = near * exp(rnd(log(10.0), log(1e4)));
        unsigned g = (unsigned)rnd(64, 2048), h = (unsigned)rnd(64, 2048);
        k.c = make_cam(eye, dir, up, fovy, aspect, near, far, g, h);
        k.Mv = cam_matrix(&k.c);
        /* plane through a visible point at a moderate depth */
        v3 X0;
        swarp_plane dummy = {k.c.f.x, k.c.f.y, k.c.f.z, -dot(k.c.f, add(eye, mul(k.c.f, rnd(1.0, 50.0))))};
        cam_hit(&k.c, &dummy, rnd(0, g - 1), rnd(0, h - 1), &X0);
        v3 n = rnd_unit();
        /* not nearly through the eye: at least 2 degrees of incidence */
        if (fabs(dot(n, unit(sub(X0, eye)))) < 0.035) continue;
        k.P = plane_through(n, X0);
        if (rng_next() & 1) {
            v3 lp = add(X0, V(rnd(-60, 60), rnd(-60, 60), rnd(-60, 60)));
            if (fabs(dot(n, sub(lp, X0))) < 0.5) continue;
            k.lpos = lp;
            k.light = point_light(lp);
        } else {
            v3 d = rnd_unit();
            if (fabs(dot(d, n)) < 0.05) continue;
            k.light = dir_light(d);
            k.lpos = V(0, 0, 0);
        }
        return k;
    }
}

/* max |light pixel - viewer pixel| / max(g, h) over visible plane points,
 * in double and with the float matrix; also checks q > 0 there. */
static void check_exact(const config* k, const swarp_mat4* Ml, int samples, double* err_d, double* err_f,
                        double* err_gpu, int* bad_sign) {
    float Mf[16];
    ck_assert_int_eq(swarp_mat4_to_float(Ml, Mf), SWARP_OK);
    double scale = k->c.g > k->c.h ? k->c.g : k->c.h;
    for (int s = 0; s < samples; ++s) {
        double x = rnd(0, k->c.g - 1), y = rnd(0, k->c.h - 1);
        v3 X;
        double t = cam_hit(&k->c, &k->P, x, y, &X);
        /* visible and within the viewer's depth range */
        if (!(t > k->c.z_near) || t > k->c.z_far) continue;
        double xl, yl, zl, q;
        light_px(Ml, X, &xl, &yl, &zl, &q);
        if (!(q > 0)) ++*bad_sign;
        double e = fmax(fabs(xl - x), fabs(yl - y)) / scale;
        if (!(e <= *err_d)) *err_d = isnan(e) ? INFINITY : fmax(*err_d, e);
        double xf, yf;
        light_px_f(Mf, X, 0, &xf, &yf);
        double ef = fmax(fabs(xf - x), fabs(yf - y)) / scale;
        if (!(ef <= *err_f)) *err_f = isnan(ef) ? INFINITY : fmax(*err_f, ef);
        if (err_gpu) {
            light_px_f(Mf, X, 1, &xf, &yf);
            ef = fmax(fabs(xf - x), fabs(yf - y)) / scale;
            if (!(ef <= *err_gpu)) *err_gpu = isnan(ef) ? INFINITY : fmax(*err_gpu, ef);
        }
    }
}

/* [LIXEL] (3)-(6) hold exactly for every point of P with M_l built from
 * [LIXEL] (1), (7)-(10): 10^4 random configs */
START_TEST(plane_points_same_pixel_in_both_images) {
    rng_state = 0x11CE1u;
    double err_d = 0, err_f = 0, err_gpu = 0;
    int bad_sign = 0, n_ok = 0, n_info = 0;
    for (int it = 0; it < 10000; ++it) {
        config k = random_config(50.0);
        swarp_mat4 Ml;
        swarp_lixel_info info;
        swarp_status st = swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, &info);
        ck_assert_msg(!swarp_status_is_error(st), "config %d: %s", it, swarp_status_name(st));
        ck_assert(mat_finite(&Ml));
        if (st == SWARP_OK) ++n_ok; else ++n_info;
        check_exact(&k, &Ml, 16, &err_d, &err_f, &err_gpu, &bad_sign);
        /* the raised point: z = -1 and q > 0 (in front of the light) */
        double xl, yl, zl, q;
        light_px(&Ml, V(info.raised.x, info.raised.y, info.raised.z), &xl, &yl, &zl, &q);
        ck_assert(q > 0);
        ck_assert_double_eq_tol(zl, -1.0, 1e-7);
    }
    ck_assert_int_eq(bad_sign, 0);
    ck_assert_msg(err_d <= 1e-9, "double max rel error %g", err_d);
    ck_assert_msg(err_f <= 1e-4, "float max rel error %g", err_f);
    /* All-float arithmetic (world coordinates rounded too) is worse near the
     * eye: the rows of M_l are fixed up to scale by the construction, and
     * the light's oblique frustum makes r.X cancel more than the viewer's.
     * Measured here: about 1.5e-4 at points 0.5-3 units from the eye in a
     * world of +-50 units (the viewer's own float error there: ~1e-6).  Not
     * asserted at 1e-4; this bound says it stays a fraction of a pixel. */
    ck_assert_msg(err_gpu <= 1e-3, "all-float max rel error %g", err_gpu);
    ck_assert_int_gt(n_ok, 1000);
    ck_assert_int_gt(n_info, 100);
}
END_TEST

/* The Jacobian of light pixels w.r.t. viewer pixels on P is the identity
 * (central differences; the map is the identity, so no truncation error). */
START_TEST(jacobian_is_identity) {
    rng_state = 0x7AC0B1u;
    for (int it = 0; it < 2000; ++it) {
        config k = random_config(50.0);
        swarp_mat4 Ml;
        ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL)));
        for (int s = 0; s < 4; ++s) {
            double x = rnd(1, k.c.g - 2), y = rnd(1, k.c.h - 2), d = 1e-3;
            v3 X;
            if (!(cam_hit(&k.c, &k.P, x, y, &X) > k.c.z_near)) continue;
            double J[2][2];
            for (int a = 0; a < 2; ++a) {
                v3 Xp, Xm;
                cam_hit(&k.c, &k.P, x + (a == 0 ? d : 0), y + (a == 1 ? d : 0), &Xp);
                cam_hit(&k.c, &k.P, x - (a == 0 ? d : 0), y - (a == 1 ? d : 0), &Xm);
                double xp, yp, xm, ym, z, q;
                light_px(&Ml, Xp, &xp, &yp, &z, &q);
                light_px(&Ml, Xm, &xm, &ym, &z, &q);
                J[0][a] = (xp - xm) / (2 * d);
                J[1][a] = (yp - ym) / (2 * d);
            }
            ck_assert_double_eq_tol(J[0][0], 1.0, 1e-5);
            ck_assert_double_eq_tol(J[1][1], 1.0, 1e-5);
            ck_assert_double_eq_tol(J[0][1], 0.0, 1e-5);
            ck_assert_double_eq_tol(J[1][0], 0.0, 1e-5);
        }
    }
}
END_TEST

/* Fig. 4, miner's lamp: light at the eye -> the light image plane (q = 0,
 * row 4) is parallel to the viewer's, whatever the plane of interest. */
START_TEST(miners_lamp_parallel_image_planes) {
    rng_state = 0x4D1AE5u;
    for (int it = 0; it < 2000; ++it) {
        config k = random_config(50.0);
        k.light = point_light(k.c.eye);
        swarp_mat4 Ml;
        swarp_status st = swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL);
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        v3 r4 = unit(row3(&Ml, 3));
        ck_assert_double_le(len(cross(r4, k.c.f)), 1e-9);
        /* and q grows along the view direction, like the viewer's */
        ck_assert_double_gt(dot(r4, k.c.f), 0.0);
    }
}
END_TEST

/* Fig. 3 generalised: the light image plane is parallel to the plane through
 * l and the line pi = P  /\  {viewer's q = 0}.  So row 4 of M_l vanishes on
 * pi (and on l).  Flatland first: everything in the xy-plane. */
START_TEST(flatland_light_plane_parallel_to_pi_l) {
    cam c = make_cam(V(0, 2, 0), V(1, -0.3, 0), V(0, 1, 0), 50 * M_PI / 180, 1.0, 0.1, 100, 512, 512);
    swarp_mat4 Mv = cam_matrix(&c);
    swarp_plane P = {0, 1, 0, 0};
    v3 l = V(3, 5, 0);
    swarp_light L = point_light(l);
    swarp_mat4 Ml;
    ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&Mv, 512, 512, &L, &P, NULL, &Ml, NULL)));
    /* pi: from the eye along the image plane (direction perpendicular to
     * (1, -0.3)) until it hits y = 0 */
    v3 along = unit(V(0.3, 1, 0));
    v3 pi = add(c.eye, mul(along, -c.eye.y / along.y));
    ck_assert_double_eq_tol(pi.y, 0.0, 1e-12);
    v3 r4 = row3(&Ml, 3);
    v3 blue = unit(sub(l, pi));
    /* the light image line (direction perpendicular to r4 in the xy-plane)
     * is parallel to the dotted blue line from pi to l */
    ck_assert_double_le(fabs(dot(unit(r4), blue)), 1e-12);
    ck_assert_double_le(fabs(r4.z), 1e-12);

    rng_state = 0xF1A71u;
    for (int it = 0; it < 2000; ++it) {
        config k = random_config(50.0);
        ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL)));
        /* two points of pi: on P and on the plane through the eye with normal f */
        v3 n = V(k.P.a, k.P.b, k.P.c);
        v3 u = cross(n, k.c.f);
        if (len(u) < 1e-3) continue; /* P parallel to the image plane: pi at infinity */
        double h1 = -k.P.d, h2 = dot(k.c.f, k.c.eye);
        v3 X = mul(add(mul(cross(k.c.f, u), h1), mul(cross(u, n), h2)), 1.0 / dot(u, u));
        v3 r = row3(&Ml, 3);
        double w = Ml.m[15];
        for (int s = -1; s <= 1; ++s) {
            v3 Y = add(X, mul(unit(u), 10.0 * s));
            double scale = len(r) * (len(Y) + 1.0);
            ck_assert_double_le(fabs(dot(r, Y) + w) / scale, 1e-9);
        }
        if (k.light.type == SWARP_LIGHT_POINT)
            ck_assert_double_le(fabs(dot(r, k.lpos) + w) / (len(r) * (len(k.lpos) + 1.0)), 1e-9);
        else
            ck_assert_double_le(fabs(dot(unit(r), unit(V(k.light.direction.x, k.light.direction.y, k.light.direction.z)))), 1e-9);
    }
}
END_TEST

static void horizon_case(v3 dir, swarp_status want) {
    cam c = make_cam(V(0, 1.7, 0), dir, V(0, 1, 0), 60 * M_PI / 180, 1.5, 0.1, 500, 960, 640);
    swarp_mat4 Mv = cam_matrix(&c);
    swarp_plane P = {0, 1, 0, 0};
    for (int li = 0; li < 2; ++li) {
        swarp_light L = li ? point_light(V(4, 6, -8)) : dir_light(V(0.3, -1, 0.4));
        swarp_mat4 Ml;
        swarp_lixel_info info;
        swarp_status st = swarp_lixel_matrix(&Mv, 960, 640, &L, &P, NULL, &Ml, &info);
        ck_assert_int_eq(st, want);
        ck_assert(mat_finite(&Ml));
        ck_assert_uint_lt(info.corners_in_front, 4);
        config k;
        k.c = c;
        k.P = P;
        double ed = 0, ef = 0;
        int bad = 0;
        rng_state = 99;
        check_exact(&k, &Ml, 4000, &ed, &ef, NULL, &bad);
        ck_assert_int_eq(bad, 0);
        ck_assert_double_le(ed, 1e-9);
        ck_assert_double_le(ef, 1e-4);
        /* floor behind the viewer: q < 0, never in the map */
        double x, y, z, q;
        light_px(&Ml, V(0.5, 0, 30), &x, &y, &z, &q);
        ck_assert_double_lt(q, 0);
        /* a caster between the light and a visible floor point: q > 0 and
         * nearer than the floor (depth grows away from the light) */
        v3 F = V(1, 0, -10), Lp = li ? V(4, 6, -8) : sub(F, mul(V(0.3, -1, 0.4), 20));
        double zf, zc;
        light_px(&Ml, F, &x, &y, &zf, &q);
        ck_assert_double_gt(q, 0);
        light_px(&Ml, add(mul(F, 0.6), mul(Lp, 0.4)), &x, &y, &zc, &q);
        ck_assert_double_gt(q, 0);
        ck_assert_double_lt(zc, zf);
    }
}

/* Fig. 5: the quad straddles infinity (horizon in view). */
START_TEST(quad_across_infinity) {
    horizon_case(V(0, 0.15, -1), SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY);
    horizon_case(V(0, 0, -1), SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW);
}
END_TEST

/* Large world: coordinates around 3e5.  A world point there is only known
 * to DBL_EPSILON |X| (~7e-11 units), which moves its viewer pixel by that
 * times the pixels per unit at its depth t: g / (2 tan(fovy/2) aspect t).
 * The test asks that M_l adds no more than 64 such units of resolution
 * (plus the 1e-9 of the small world): precision is lost in proportion to
 * the coordinates, as for any matrix applied to world coordinates, not
 * faster.  (In the +-50 world the same sweep stays at ~2e-12.) */
START_TEST(large_world_coordinates) {
    rng_state = 0xB16u;
    int n = 0;
    for (int it = 0; it < 1000; ++it) {
        config k = random_config(50.0);
        v3 off = V(1e5, -2e5, 3e5);
        k.c.eye = add(k.c.eye, off);
        k.Mv = cam_matrix(&k.c);
        k.P.d -= dot(V(k.P.a, k.P.b, k.P.c), off);
        if (k.light.type == SWARP_LIGHT_POINT) {
            k.lpos = add(k.lpos, off);
            k.light = point_light(k.lpos);
        }
        swarp_mat4 Ml;
        ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL)));
        double scale = k.c.g > k.c.h ? k.c.g : k.c.h;
        for (int s = 0; s < 8; ++s) {
            double x = rnd(0, k.c.g - 1), y = rnd(0, k.c.h - 1);
            v3 X;
            double t = cam_hit(&k.c, &k.P, x, y, &X);
            if (!(t > k.c.z_near) || t > k.c.z_far) continue;
            double xl, yl, zl, q, xr, yr;
            light_px(&Ml, X, &xl, &yl, &zl, &q);
            cam_pixel(&k.c, X, &xr, &yr);
            ck_assert_double_gt(q, 0);
            double e = fmax(fabs(xl - x), fabs(yl - y)) / scale;
            double px_per_unit = fmax(k.c.g / (2 * k.c.tan_half * k.c.aspect * t), k.c.h / (2 * k.c.tan_half * t));
            double bound = 1e-9 + 64 * DBL_EPSILON * len(X) * px_per_unit / scale;
            (void)xr, (void)yr;
            ck_assert_msg(e <= bound, "large world: %g > %g", e, bound);
            ++n;
        }
    }
    ck_assert_int_gt(n, 3000);
}
END_TEST

/* ---- degenerate inputs: own status, outputs untouched ------------------- */
static void sentinel(swarp_mat4* m) { tu_fill(m->m, 16, 7.25); }
static int is_sentinel(const swarp_mat4* m) { return tu_untouched(m->m, 16, 7.25); }

START_TEST(degenerate_inputs_have_own_status) {
    cam c = make_cam(V(0, 2, 0), V(0.2, -0.5, -1), V(0, 1, 0), 60 * M_PI / 180, 1.0, 0.1, 100, 256, 256);
    swarp_mat4 Mv = cam_matrix(&c), Ml;
    swarp_plane floor = {0, 1, 0, 0};
    swarp_light L = point_light(V(3, 5, 1));
    /* plane through the eye */
    swarp_plane thru = plane_through(unit(V(0.3, 1, 0.2)), c.eye);
    sentinel(&Ml);
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &L, &thru, NULL, &Ml, NULL), SWARP_ERR_LIXEL_PLANE_THROUGH_EYE);
    ck_assert(is_sentinel(&Ml));
    /* light on the plane */
    swarp_light on = point_light(V(3, 0, 1));
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &on, &floor, NULL, &Ml, NULL), SWARP_ERR_LIXEL_LIGHT_ON_PLANE);
    ck_assert(is_sentinel(&Ml));
    /* directional light parallel to the plane */
    swarp_light par = dir_light(V(1, 0, 0.5));
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &par, &floor, NULL, &Ml, NULL),
                     SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE);
    ck_assert(is_sentinel(&Ml));
    /* plane not seen at all (viewer looks up, floor below) */
    cam up = make_cam(V(0, 2, 0), V(0, 1, -0.2), V(0, 0, -1), 40 * M_PI / 180, 1.0, 0.1, 100, 256, 256);
    swarp_mat4 Mup = cam_matrix(&up);
    ck_assert_int_eq(swarp_lixel_matrix(&Mup, 256, 256, &L, &floor, NULL, &Ml, NULL), SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE);
    ck_assert(is_sentinel(&Ml));
    /* plane parallel to the view direction: informational, exact */
    cam hz = make_cam(V(0, 2, 0), V(0, 0, -1), V(0, 1, 0), 60 * M_PI / 180, 1.0, 0.1, 100, 256, 256);
    swarp_mat4 Mhz = cam_matrix(&hz);
    ck_assert_int_eq(swarp_lixel_matrix(&Mhz, 256, 256, &L, &floor, NULL, &Ml, NULL), SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW);
    ck_assert(mat_finite(&Ml));
    /* light below the floor, viewer above */
    swarp_light below = point_light(V(1, -3, -2));
    cam steep = make_cam(V(0, 2, 0), V(0.2, -1, -1), V(0, 1, 0), 60 * M_PI / 180, 1.0, 0.1, 100, 256, 256);
    swarp_mat4 Mst = cam_matrix(&steep);
    ck_assert_int_eq(swarp_lixel_matrix(&Mst, 256, 256, &L, &floor, NULL, &Ml, NULL), SWARP_OK);
    ck_assert_int_eq(swarp_lixel_matrix(&Mst, 256, 256, &below, &floor, NULL, &Ml, NULL), SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE);
    /* bad arguments */
    sentinel(&Ml);
    swarp_plane zero = {0, 0, 0, 1};
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &L, &zero, NULL, &Ml, NULL), SWARP_ERR_ZERO_VECTOR);
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 1, 256, &L, &floor, NULL, &Ml, NULL), SWARP_ERR_RESOLUTION);
    ck_assert_int_eq(swarp_lixel_matrix(NULL, 256, 256, &L, &floor, NULL, &Ml, NULL), SWARP_ERR_NULL_POINTER);
    swarp_plane nan_p = {0, NAN, 0, 0};
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &L, &nan_p, NULL, &Ml, NULL), SWARP_ERR_NON_FINITE);
    swarp_light zd = dir_light(V(0, 0, 0));
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &zd, &floor, NULL, &Ml, NULL), SWARP_ERR_ZERO_VECTOR);
    swarp_light bad_t = L;
    bad_t.type = (swarp_light_type)7;
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &bad_t, &floor, NULL, &Ml, NULL), SWARP_ERR_UNKNOWN_ENUM);
    swarp_lixel_options o;
    memset(&o, 0, sizeof o);
    o._reserved[2] = 1;
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &L, &floor, &o, &Ml, NULL), SWARP_ERR_RESERVED_NONZERO);
    o._reserved[2] = 0;
    o.raise = 1.0;
    ck_assert_int_eq(swarp_lixel_matrix(&Mv, 256, 256, &L, &floor, &o, &Ml, NULL), SWARP_ERR_OUT_OF_RANGE);
    swarp_mat4 sing;
    memset(&sing, 0, sizeof sing);
    ck_assert_int_eq(swarp_lixel_matrix(&sing, 256, 256, &L, &floor, NULL, &Ml, NULL), SWARP_ERR_SINGULAR);
    ck_assert(is_sentinel(&Ml));
    /* the raise option moves the near plane only: (x, y) unchanged */
    swarp_mat4 Ma, Mb;
    o.raise = 0.9;
    ck_assert_int_eq(swarp_lixel_matrix(&Mst, 256, 256, &L, &floor, &o, &Ma, NULL), SWARP_OK);
    ck_assert_int_eq(swarp_lixel_matrix(&Mst, 256, 256, &L, &floor, NULL, &Mb, NULL), SWARP_OK);
    double xa, ya, za, qa, xb, yb, zb, qb;
    light_px(&Ma, V(5, 3, -7), &xa, &ya, &za, &qa);
    light_px(&Mb, V(5, 3, -7), &xb, &yb, &zb, &qb);
    ck_assert_double_eq_tol(xa, xb, 1e-9 * 256);
    ck_assert_double_eq_tol(ya, yb, 1e-9 * 256);
    ck_assert_double_ne(za, zb);
}
END_TEST

/* ---- the five-point solver ---------------------------------------------- */
static swarp_vec4 mv4(const double* M, swarp_vec4 p) {
    swarp_vec4 o;
    o.x = M[0] * p.x + M[4] * p.y + M[8] * p.z + M[12] * p.w;
    o.y = M[1] * p.x + M[5] * p.y + M[9] * p.z + M[13] * p.w;
    o.z = M[2] * p.x + M[6] * p.y + M[10] * p.z + M[14] * p.w;
    o.w = M[3] * p.x + M[7] * p.y + M[11] * p.z + M[15] * p.w;
    return o;
}

START_TEST(solve5_recovers_a_known_matrix) {
    rng_state = 0x5015Eu;
    for (int it = 0; it < 10000; ++it) {
        double M0[16];
        for (int i = 0; i < 16; ++i) M0[i] = rnd(-1, 1);
        for (int i = 0; i < 4; ++i) M0[i * 5] += 2.5;
        swarp_vec4 src[5], dst[5];
        for (int i = 0; i < 5; ++i) {
            double w = (it % 3 == 0 && i == 0) ? 0.0 : 1.0; /* a point at infinity */
            src[i].x = rnd(-10, 10), src[i].y = rnd(-10, 10), src[i].z = rnd(-10, 10), src[i].w = w;
            swarp_vec4 d = mv4(M0, src[i]);
            double k = rnd(0.2, 3) * ((rng_next() & 1) ? 1 : -1); /* arbitrary homogeneous scale */
            dst[i].x = d.x * k, dst[i].y = d.y * k, dst[i].z = d.z * k, dst[i].w = d.w * k;
        }
        swarp_mat4 M;
        double cond;
        swarp_status st = swarp_lixel_solve5(src, dst, &M, &cond);
        if (st == SWARP_ERR_LIXEL_COPLANAR) continue; /* random near-coplanar: allowed */
        ck_assert(!swarp_status_is_error(st));
        if (st != SWARP_OK) continue;
        /* M ~ M0 up to scale */
        double a = 0, b = 0;
        int imax = 0;
        for (int i = 0; i < 16; ++i)
            if (fabs(M0[i]) > fabs(M0[imax])) imax = i;
        a = M.m[imax] / M0[imax];
        for (int i = 0; i < 16; ++i) b = fmax(b, fabs(M.m[i] - a * M0[i]));
        ck_assert_msg(b <= 1e-9 * fabs(a) * fabs(M0[imax]) / cond, "it %d: %g (cond %g)", it, b, cond);
    }
}
END_TEST

START_TEST(solve5_coplanar_and_ill_conditioned) {
    swarp_vec4 src[5] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}, {0, 0, 1, 1}};
    swarp_vec4 dst[5] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    swarp_mat4 M;
    sentinel(&M);
    double cond = 42;
    ck_assert_int_eq(swarp_lixel_solve5(src, dst, &M, &cond), SWARP_ERR_LIXEL_COPLANAR);
    ck_assert(is_sentinel(&M));
    ck_assert_double_eq(cond, 42);
    src[3].z = 1e-9; /* nearly coplanar */
    ck_assert_int_eq(swarp_lixel_solve5(src, dst, &M, &cond), SWARP_INFO_LIXEL_ILL_CONDITIONED);
    ck_assert(mat_finite(&M));
    ck_assert_double_lt(cond, 1e-6);
    src[3].z = 0.7;
    ck_assert_int_eq(swarp_lixel_solve5(src, dst, &M, &cond), SWARP_OK);
    swarp_vec4 z[5] = {{0, 0, 0, 0}, {1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    sentinel(&M);
    ck_assert_int_eq(swarp_lixel_solve5(z, dst, &M, NULL), SWARP_ERR_LIXEL_COPLANAR);
    src[0].x = INFINITY;
    ck_assert_int_eq(swarp_lixel_solve5(src, dst, &M, NULL), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_lixel_solve5(NULL, dst, &M, NULL), SWARP_ERR_NULL_POINTER);
    ck_assert(is_sentinel(&M));
}
END_TEST

/* ---- Fig. 6: restriction, scale and twist -------------------------------- */
static swarp_vec4 P4(v3 p, double w) { swarp_vec4 r = {p.x, p.y, p.z, w}; return r; }

START_TEST(restrict_rectangle_encloses_and_is_tight) {
    rng_state = 0x8EC7u;
    int n_checked = 0;
    for (int it = 0; it < 3000; ++it) {
        config k = random_config(50.0);
        swarp_mat4 Ml;
        ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL)));
        /* C: a few visible points of P; their viewer pixels */
        swarp_vec4 C[6];
        double vx[6], vy[6];
        int m = 0;
        for (int tries = 0; tries < 60 && m < 6; ++tries) {
            double x = rnd(0, k.c.g - 1), y = rnd(0, k.c.h - 1);
            v3 X;
            double t = cam_hit(&k.c, &k.P, x, y, &X);
            if (!(t > k.c.z_near) || t > k.c.z_far) continue;
            C[m] = P4(X, 1.0);
            vx[m] = x, vy[m] = y;
            ++m;
        }
        if (m < 3) continue;
        swarp_lixel_restrict_options o;
        memset(&o, 0, sizeof o);
        int variant = it % 3; /* plain, scaled, twisted+scaled */
        double sx = 1, sy = 1, tw = 0;
        if (variant >= 1) sx = o.scale_x = rnd(0.2, 1.0), sy = o.scale_y = rnd(0.2, 1.0);
        if (variant == 2) tw = o.twist = rnd(-M_PI, M_PI);
        o.max_size = 1u << 20;
        swarp_lixel_rect R;
        swarp_mat4 A, Mr;
        ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, (size_t)m, &o, &R, &A, &Mr), SWARP_OK);
        /* independent: the twisted/scaled viewer pixels of C (on P the light
         * image IS the viewer image) */
        double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
        for (int j = 0; j < m; ++j) {
            double xt = sx * (cos(tw) * vx[j] - sin(tw) * vy[j]), yt = sy * (sin(tw) * vx[j] + cos(tw) * vy[j]);
            lo_x = fmin(lo_x, xt), hi_x = fmax(hi_x, xt), lo_y = fmin(lo_y, yt), hi_y = fmax(hi_y, yt);
            /* after A_l every vertex is inside [0, width-1] x [0, height-1] */
            double x, y, z, q;
            light_px(&Mr, V(C[j].x, C[j].y, C[j].z), &x, &y, &z, &q);
            ck_assert_double_gt(q, 0);
            ck_assert_double_ge(x, -1e-6);
            ck_assert_double_ge(y, -1e-6);
            ck_assert_double_le(x, R.width - 1 + 1e-6);
            ck_assert_double_le(y, R.height - 1 + 1e-6);
            ck_assert_double_eq_tol(x, xt - R.x0, 1e-6 * (R.width + 1));
            ck_assert_double_eq_tol(y, yt - R.y0, 1e-6 * (R.height + 1));
        }
        /* smallest integer rectangle (skip values within 1e-6 of an integer) */
        if (fabs(lo_x - round(lo_x)) > 1e-6) ck_assert_int_eq(R.x0, (int32_t)floor(lo_x));
        if (fabs(hi_x - round(hi_x)) > 1e-6) ck_assert_int_eq(R.x1, (int32_t)ceil(hi_x));
        if (fabs(lo_y - round(lo_y)) > 1e-6) ck_assert_int_eq(R.y0, (int32_t)floor(lo_y));
        if (fabs(hi_y - round(hi_y)) > 1e-6) ck_assert_int_eq(R.y1, (int32_t)ceil(hi_y));
        ck_assert_uint_eq(R.width, (uint32_t)(R.x1 - R.x0 + 1));
        ck_assert_uint_eq(R.height, (uint32_t)(R.y1 - R.y0 + 1));
        /* point light: the same rays as directions give the same rectangle */
        if (k.light.type == SWARP_LIGHT_POINT) {
            swarp_vec4 D[6];
            for (int j = 0; j < m; ++j) D[j] = P4(sub(V(C[j].x, C[j].y, C[j].z), k.lpos), 0.0);
            swarp_lixel_rect R2;
            swarp_mat4 Mr2;
            ck_assert_int_eq(swarp_lixel_restrict(&Ml, D, (size_t)m, &o, &R2, NULL, &Mr2), SWARP_OK);
            ck_assert_int_eq(R2.x0, R.x0);
            ck_assert_int_eq(R2.y1, R.y1);
        }
        ++n_checked;
    }
    ck_assert_int_gt(n_checked, 2000);
}
END_TEST

START_TEST(restrict_bad_inputs) {
    cam c = make_cam(V(0, 1.7, 0), V(0, -0.3, -1), V(0, 1, 0), 60 * M_PI / 180, 1.5, 0.1, 500, 960, 640);
    swarp_mat4 Mv = cam_matrix(&c), Ml, out;
    swarp_plane P = {0, 1, 0, 0};
    swarp_light L = point_light(V(4, 6, -8));
    ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&Mv, 960, 640, &L, &P, NULL, &Ml, NULL)));
    swarp_vec4 C[3] = {{0, 0, -5, 1}, {2, 0, -6, 1}, {0.5, 0, 30, 1}}; /* the last is behind the viewer */
    swarp_lixel_rect R, Rs;
    memset(&Rs, 0x5A, sizeof Rs);
    R = Rs;
    sentinel(&out);
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 3, NULL, &R, NULL, &out), SWARP_ERR_LIXEL_RAY_OUTSIDE);
    ck_assert(is_sentinel(&out));
    ck_assert(memcmp(&R, &Rs, sizeof R) == 0);
    /* a floor point near the line pi (view depth 1e-3): the rectangle
     * explodes (footnote of §2) */
    v3 f = unit(V(0, -0.3, -1));
    v3 side = V(1000, 0, 0);
    /* X = (1000, 0, z) with (X - eye).f = 1e-3 */
    double zz = (1e-3 - dot(sub(side, c.eye), V(f.x, f.y, 0))) / f.z;
    C[2] = P4(V(1000, 0, zz), 1.0);
    swarp_lixel_restrict_options o;
    memset(&o, 0, sizeof o);
    o.max_size = 4096;
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 3, &o, &R, NULL, &out), SWARP_ERR_LIXEL_RECT_TOO_LARGE);
    ck_assert(is_sentinel(&out));
    C[2] = P4(V(1, 0, -8), 1.0);
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 0, NULL, &R, NULL, &out), SWARP_ERR_INVALID_ARGUMENT);
    o.scale_x = -1;
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 3, &o, &R, NULL, &out), SWARP_ERR_OUT_OF_RANGE);
    o.scale_x = 0;
    o._reserved[0] = 3;
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 3, &o, &R, NULL, &out), SWARP_ERR_RESERVED_NONZERO);
    C[1].y = NAN;
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 3, NULL, &R, NULL, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_lixel_restrict(NULL, C, 3, NULL, &R, NULL, &out), SWARP_ERR_NULL_POINTER);
    ck_assert(is_sentinel(&out));
    double tw = 99;
    swarp_vec3 a = {1, 0, -5}, b = {1, 0, -5}, below = {0, 0, -4};
    ck_assert_int_eq(swarp_lixel_twist_for_line(&Ml, &a, &b, &below, &tw), SWARP_ERR_LIXEL_TWIST_LINE);
    ck_assert_double_eq(tw, 99);
}
END_TEST

/* Clipping C to the viewer's frustum ([LIXEL] §3): compared with brute
 * force over sampled rays of C. */
START_TEST(restrict_clipped_to_view_matches_sampling) {
    rng_state = 0xC11Fu;
    int n_done = 0;
    for (int it = 0; it < 600; ++it) {
        config k = random_config(50.0);
        swarp_mat4 Ml;
        ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL)));
        /* C: a quad of P around a visible point, partly out of view */
        v3 X0;
        if (!(cam_hit(&k.c, &k.P, rnd(0, k.c.g - 1), rnd(0, k.c.h - 1), &X0) > k.c.z_near)) continue;
        v3 n = unit(V(k.P.a, k.P.b, k.P.c));
        v3 e1 = unit(cross(n, fabs(n.x) < 0.9 ? V(1, 0, 0) : V(0, 1, 0))), e2 = cross(n, e1);
        double r = rnd(0.5, 20);
        swarp_vec4 C[4];
        v3 Cw[4];
        for (int j = 0; j < 4; ++j) {
            double ang = j * M_PI / 2 + rnd(-0.3, 0.3);
            Cw[j] = add(X0, add(mul(e1, r * cos(ang)), mul(e2, r * sin(ang))));
            C[j] = P4(Cw[j], 1.0);
        }
        swarp_lixel_restrict_options o;
        memset(&o, 0, sizeof o);
        o.view_width = k.c.g, o.view_height = k.c.h, o.max_size = 1u << 20;
        swarp_lixel_rect R;
        swarp_mat4 Mr;
        swarp_status st = swarp_lixel_restrict(&Ml, C, 4, &o, &R, NULL, &Mr);
        ck_assert_msg(st == SWARP_OK, "%s", swarp_status_name(st));
        /* brute force: points of the quad (bilinear samples are inside the
         * convex quad), seen by the viewer, in front */
        double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
        for (int a = 0; a <= 60; ++a)
            for (int b = 0; b <= 60; ++b) {
                double u = a / 60.0, v = b / 60.0;
                v3 X = add(mul(add(mul(Cw[0], 1 - u), mul(Cw[1], u)), 1 - v), mul(add(mul(Cw[3], 1 - u), mul(Cw[2], u)), v));
                if (dot(sub(X, k.c.eye), k.c.f) <= 0) continue;
                double x, y;
                cam_pixel(&k.c, X, &x, &y);
                if (x < 0 || x > k.c.g - 1 || y < 0 || y > k.c.h - 1) continue;
                lo_x = fmin(lo_x, x), hi_x = fmax(hi_x, x), lo_y = fmin(lo_y, y), hi_y = fmax(hi_y, y);
            }
        if (!(hi_x > lo_x)) continue;
        ck_assert_double_le(R.x0, lo_x + 1e-6);
        ck_assert_double_ge(R.x1, hi_x - 1e-6);
        ck_assert_double_le(R.y0, lo_y + 1e-6);
        ck_assert_double_ge(R.y1, hi_y - 1e-6);
        /* and never larger than the viewer's pixel centres */
        ck_assert_int_ge(R.x0, 0);
        ck_assert_int_le(R.x1, (int32_t)k.c.g - 1);
        ck_assert_int_ge(R.y0, 0);
        ck_assert_int_le(R.y1, (int32_t)k.c.h - 1);
        /* tight up to the sampling gap */
        double gap = 0.05 * (k.c.g + k.c.h);
        ck_assert_double_ge(R.x0, lo_x - 1 - gap);
        ck_assert_double_le(R.x1, hi_x + 1 + gap);
        ++n_done;
    }
    ck_assert_int_gt(n_done, 300);
}
END_TEST

/* ---- 'M_l = GLV GLP' ----------------------------------------------------- */
START_TEST(factor_viewport_times_projection) {
    rng_state = 0xFAC7u;
    for (int it = 0; it < 2000; ++it) {
        config k = random_config(50.0);
        swarp_mat4 Ml;
        swarp_lixel_info info;
        ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, &info)));
        uint32_t W = 1 + (uint32_t)rnd(0, 3000), H = 1 + (uint32_t)rnd(0, 3000);
        swarp_depth_range dr = (it & 1) ? SWARP_DEPTH_ZERO_TO_ONE : SWARP_DEPTH_NEG_ONE_TO_ONE;
        double f = (it % 4 < 2) ? 0.0 : rnd(0.05, 0.95);
        double f_eff = f > 0 ? f : 0.5;
        swarp_mat4 GLV, GLP;
        ck_assert_int_eq(swarp_lixel_factor(&Ml, W, H, dr, f, &GLV, &GLP), SWARP_OK);
        /* rows x, y, q of GLV GLP are those of M_l */
        swarp_mat4 prod;
        ck_assert_int_eq(swarp_mat4_mul(&GLV, &GLP, &prod), SWARP_OK);
        for (int col = 0; col < 4; ++col)
            for (int r = 0; r < 4; ++r)
                if (r != 2) ck_assert_double_eq_tol(prod.m[col * 4 + r], Ml.m[col * 4 + r], 1e-12 * (W + H));
        /* standard clipping: lixel x in [-1/2, W - 1/2] <=> |x_ndc| <= w */
        double xl = rnd(-0.5, W - 0.5), yl = rnd(-0.5, H - 0.5);
        double xn = (2 * xl + 1) / W - 1, yn = (2 * yl + 1) / H - 1;
        ck_assert_double_le(fabs(xn), 1 + 1e-12);
        ck_assert_double_le(fabs(yn), 1 + 1e-12);
        /* GLV maps those NDC back to the lixel */
        ck_assert_double_eq_tol(GLV.m[0] * xn + GLV.m[12], xl, 1e-9 * W);
        ck_assert_double_eq_tol(GLV.m[5] * yn + GLV.m[13], yl, 1e-9 * H);
        /* depth: p-hat on the near plane, P at the fraction f of the range */
        double x, y, z, q;
        light_px(&GLP, V(info.raised.x, info.raised.y, info.raised.z), &x, &y, &z, &q);
        ck_assert_double_gt(q, 0);
        ck_assert_double_eq_tol(z, dr == SWARP_DEPTH_ZERO_TO_ONE ? 0.0 : -1.0, 1e-7);
        for (int s = 0; s < 4; ++s) {
            v3 X;
            double t = cam_hit(&k.c, &k.P, rnd(0, k.c.g - 1), rnd(0, k.c.h - 1), &X);
            if (!(t > k.c.z_near) || t > k.c.z_far) continue;
            light_px(&GLP, X, &x, &y, &z, &q);
            ck_assert_double_gt(q, 0);
            ck_assert_double_eq_tol(z, dr == SWARP_DEPTH_ZERO_TO_ONE ? f_eff : 2 * f_eff - 1, 1e-6);
        }
    }
    swarp_mat4 I, a, b;
    memset(&I, 0, sizeof I);
    I.m[0] = I.m[5] = I.m[10] = I.m[15] = 1;
    sentinel(&a);
    sentinel(&b);
    ck_assert_int_eq(swarp_lixel_factor(&I, 0, 4, SWARP_DEPTH_DEFAULT, 0, &a, &b), SWARP_ERR_RESOLUTION);
    ck_assert_int_eq(swarp_lixel_factor(&I, 4, 4, (swarp_depth_range)9, 0, &a, &b), SWARP_ERR_UNKNOWN_ENUM);
    ck_assert_int_eq(swarp_lixel_factor(&I, 4, 4, SWARP_DEPTH_DEFAULT, 1.0, &a, &b), SWARP_ERR_OUT_OF_RANGE);
    ck_assert_int_eq(swarp_lixel_factor(&I, 4, 4, SWARP_DEPTH_DEFAULT, NAN, &a, &b), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_lixel_factor(NULL, 4, 4, SWARP_DEPTH_DEFAULT, 0, &a, &b), SWARP_ERR_NULL_POINTER);
    ck_assert(is_sentinel(&a) && is_sentinel(&b));
}
END_TEST

/* ---- §3: floor, wall and fallback ---------------------------------------- */
/* Room: floor y = 0, wall z = -10 facing +z; viewer and light in the room. */
START_TEST(floor_wall_split_and_select) {
    cam c = make_cam(V(1, 1.7, 4), V(-0.2, -0.35, -1), V(0, 1, 0), 60 * M_PI / 180, 1.5, 0.1, 100, 960, 640);
    swarp_mat4 Mv = cam_matrix(&c);
    swarp_plane floor_p = {0, 1, 0, 0}, wall_p = {0, 0, 1, 10};
    v3 lp = V(-3, 6, 2);
    swarp_light L = point_light(lp);
    /* C_tot: rays toward a floor strip in front of the viewer and the wall top */
    v3 corners[4] = {V(-8, 0, 3), V(8, 0, 3), V(8, 6, -10), V(-8, 6, -10)};
    swarp_vec4 C_tot[4];
    for (int i = 0; i < 4; ++i) C_tot[i] = P4(sub(corners[i], lp), 0.0);
    swarp_vec4 Cf[5], Cw[5];
    size_t nf = 0, nw = 0;
    ck_assert_int_eq(swarp_lixel_split(&L, &floor_p, &wall_p, C_tot, 4, Cf, 1, &nf, Cw, 5, &nw), SWARP_ERR_CAPACITY);
    ck_assert_uint_eq(nf, 4);
    ck_assert_uint_eq(nw, 4);
    ck_assert_int_eq(swarp_lixel_split(&L, &floor_p, &wall_p, C_tot, 4, Cf, 5, &nf, Cw, 5, &nw), SWARP_OK);
    /* every floor ray hits the floor in front of the wall (z >= -10), every
     * wall ray hits the wall above the floor (y >= 0) */
    for (size_t j = 0; j < nf; ++j) {
        double t = -lp.y / Cf[j].y;
        ck_assert_double_gt(t, 0);
        ck_assert_double_ge(lp.z + t * Cf[j].z, -10 - 1e-9);
    }
    for (size_t j = 0; j < nw; ++j) {
        double t = (-10 - lp.z) / Cw[j].z;
        ck_assert_double_gt(t, 0);
        ck_assert_double_ge(lp.y + t * Cw[j].y, -1e-9);
    }
    /* the two maps, the floor's twisted so the floor/wall line is horizontal */
    swarp_mat4 Mf, Mw, Mf_r, Mw_r, GLP[2], GLV;
    ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&Mv, 960, 640, &L, &floor_p, NULL, &Mf, NULL)));
    ck_assert(!swarp_status_is_error(swarp_lixel_matrix(&Mv, 960, 640, &L, &wall_p, NULL, &Mw, NULL)));
    swarp_vec3 a = {-5, 0, -10}, b = {5, 0, -10}, below = {0, 0, -5};
    swarp_lixel_restrict_options o, ow;
    memset(&o, 0, sizeof o);
    ck_assert_int_eq(swarp_lixel_twist_for_line(&Mf, &a, &b, &below, &o.twist), SWARP_OK);
    /* without view clipping C_floor reaches the line pi beside the viewer */
    swarp_lixel_rect Rf, Rw;
    ck_assert_int_eq(swarp_lixel_restrict(&Mf, Cf, nf, &o, &Rf, NULL, &Mf_r), SWARP_ERR_LIXEL_RECT_TOO_LARGE);
    o.view_width = 960, o.view_height = 640;
    ow = o;
    ow.twist = 0;
    ck_assert_int_eq(swarp_lixel_restrict(&Mf, Cf, nf, &o, &Rf, NULL, &Mf_r), SWARP_OK);
    ck_assert_int_eq(swarp_lixel_restrict(&Mw, Cw, nw, &ow, &Rw, NULL, &Mw_r), SWARP_OK);
    /* fewer lixels than the viewer's 960 x 640 for each plane */
    ck_assert_uint_lt((uint64_t)Rw.width * Rw.height, 960u * 640u);
    /* twisted: the line's image is horizontal, the floor below it */
    double xa, ya, xb, yb, xc, yc, z, q;
    light_px(&Mf_r, V(a.x, a.y, a.z), &xa, &ya, &z, &q);
    light_px(&Mf_r, V(b.x, b.y, b.z), &xb, &yb, &z, &q);
    light_px(&Mf_r, V(below.x, below.y, below.z), &xc, &yc, &z, &q);
    ck_assert_double_eq_tol(ya, yb, 1e-9 * Rf.height);
    ck_assert_double_lt(yc, ya);
    /* the top of the floor map is the line (rounded up to a lixel centre) */
    ck_assert_double_le(fabs(ya - (Rf.height - 1)), 1.0);
    ck_assert_int_eq(swarp_lixel_factor(&Mf_r, Rf.width, Rf.height, SWARP_DEPTH_DEFAULT, 0, &GLV, &GLP[0]), SWARP_OK);
    ck_assert_int_eq(swarp_lixel_factor(&Mw_r, Rw.width, Rw.height, SWARP_DEPTH_DEFAULT, 0, &GLV, &GLP[1]), SWARP_OK);
    /* visible floor points in front of the wall use map 0, visible wall
     * points well above the line map 1: sampled through viewer pixels */
    rng_state = 0x5E1Eu;
    int nfloor = 0, nwall = 0;
    for (int s = 0; s < 4000; ++s) {
        double x = rnd(0, 959), y = rnd(0, 639);
        v3 Xf, Xw;
        double tf = cam_hit(&c, &floor_p, x, y, &Xf), tw = cam_hit(&c, &wall_p, x, y, &Xw);
        int on_floor = tf > 0 && (tw <= 0 || tf < tw);
        v3 X = on_floor ? Xf : Xw;
        /* inside C_tot's footprint only (x in [-8, 8] on both, floor z < 3, wall y < 6) */
        if (fabs(X.x) > 7.5 || (on_floor && X.z > 2.5) || (!on_floor && (X.y > 5.5 || X.y < 0.3))) continue;
        uint32_t idx = 99;
        swarp_vec3 p = {X.x, X.y, X.z};
        ck_assert_int_eq(swarp_lixel_select(GLP, 2, &p, &idx), SWARP_OK);
        if (on_floor) {
            ck_assert_uint_eq(idx, 0);
            /* and there the floor map samples the viewer pixel exactly */
            double xl, yl;
            light_px(&Mf, X, &xl, &yl, &z, &q);
            ck_assert_double_eq_tol(xl, x, 1e-9 * 960);
            ++nfloor;
        } else {
            ck_assert_uint_eq(idx, 1);
            ++nwall;
        }
    }
    ck_assert_int_gt(nfloor, 100);
    ck_assert_int_gt(nwall, 100);
    /* behind the viewer: no plane map, the fallback */
    swarp_vec3 behind = {1, 0.5, 9};
    uint32_t idx = 99;
    ck_assert_int_eq(swarp_lixel_select(GLP, 2, &behind, &idx), SWARP_OK);
    ck_assert_uint_eq(idx, 2);
    /* bad inputs */
    ck_assert_int_eq(swarp_lixel_split(&L, &floor_p, &floor_p, C_tot, 4, Cf, 5, &nf, Cw, 5, &nw), SWARP_ERR_DEGENERATE);
    swarp_light on_line = point_light(V(0, 0, -10));
    ck_assert_int_eq(swarp_lixel_split(&on_line, &floor_p, &wall_p, C_tot, 4, Cf, 5, &nf, Cw, 5, &nw), SWARP_ERR_DEGENERATE);
    swarp_light sun = dir_light(V(0.2, -1, -0.3));
    ck_assert_int_eq(swarp_lixel_split(&sun, &floor_p, &wall_p, C_tot, 4, Cf, 5, &nf, Cw, 5, &nw), SWARP_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(swarp_lixel_split(&L, &floor_p, &wall_p, C_tot, 2, Cf, 5, &nf, Cw, 5, &nw), SWARP_ERR_INVALID_ARGUMENT);
    behind.x = NAN;
    ck_assert_int_eq(swarp_lixel_select(GLP, 2, &behind, &idx), SWARP_ERR_NON_FINITE);
    ck_assert_uint_eq(idx, 2);
}
END_TEST

/* A directional light: the split works on world points. */
START_TEST(split_directional_points) {
    swarp_plane floor_p = {0, 1, 0, 0}, wall_p = {0, 0, 1, 10};
    swarp_light sun = dir_light(V(0.2, -1, -0.5)); /* toward the wall */
    swarp_vec4 C[4] = {{-5, 0, 0, 1}, {5, 0, 0, 1}, {5, 0, -20, 1}, {-5, 0, -20, 1}};
    swarp_vec4 Cf[5], Cw[5];
    size_t nf = 0, nw = 0;
    ck_assert_int_eq(swarp_lixel_split(&sun, &floor_p, &wall_p, C, 4, Cf, 5, &nf, Cw, 5, &nw), SWARP_OK);
    ck_assert_uint_eq(nf, 4);
    ck_assert_uint_eq(nw, 4);
    /* the cut on y = 0 is the line z = -10 itself */
    for (size_t j = 0; j < nf; ++j) ck_assert_double_ge(Cf[j].z, -10 - 1e-12);
    for (size_t j = 0; j < nw; ++j) ck_assert_double_le(Cw[j].z, -10 + 1e-12);
}
END_TEST

/* An orthographic viewer (eye at infinity) works too: exact on P. */
START_TEST(orthographic_viewer) {
    rng_state = 0x0F7u;
    for (int it = 0; it < 2000; ++it) {
        v3 eye = V(rnd(-20, 20), rnd(-20, 20), rnd(-20, 20));
        v3 f = rnd_unit(), up = rnd_unit();
        if (len(cross(f, up)) < 0.2) continue;
        v3 sx = unit(cross(f, up)), uy = cross(sx, f);
        double hw = rnd(1, 30), hh = rnd(1, 30), n = 0.1, fa = 200;
        unsigned g = (unsigned)rnd(64, 1500), h = (unsigned)rnd(64, 1500);
        /* ortho(-hw, hw, -hh, hh, n, fa) * lookAt */
        double O[4][4] = {{1 / hw, 0, 0, 0}, {0, 1 / hh, 0, 0}, {0, 0, -2 / (fa - n), -(fa + n) / (fa - n)}, {0, 0, 0, 1}};
        double Vw[4][4] = {{sx.x, sx.y, sx.z, -dot(sx, eye)}, {uy.x, uy.y, uy.z, -dot(uy, eye)},
                           {-f.x, -f.y, -f.z, dot(f, eye)}, {0, 0, 0, 1}};
        swarp_mat4 Mv;
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) {
                double acc = 0;
                for (int j = 0; j < 4; ++j) acc += O[r][j] * Vw[j][k];
                Mv.m[k * 4 + r] = acc;
            }
        v3 nrm = rnd_unit();
        if (fabs(dot(nrm, f)) < 0.05) continue;
        swarp_plane P = plane_through(nrm, add(eye, mul(f, rnd(5, 50))));
        swarp_light L = (it & 1) ? point_light(add(eye, V(rnd(-30, 30), rnd(-30, 30), rnd(-30, 30)))) : dir_light(rnd_unit());
        swarp_mat4 Ml;
        swarp_status st = swarp_lixel_matrix(&Mv, g, h, &L, &P, NULL, &Ml, NULL);
        if (st == SWARP_ERR_LIXEL_LIGHT_ON_PLANE || st == SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE) continue;
        ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
        for (int k = 0; k < 8; ++k) {
            double x = rnd(0, g - 1), y = rnd(0, h - 1);
            double a = ((x + 0.5) * 2 / g - 1) * hw, b = ((y + 0.5) * 2 / h - 1) * hh;
            v3 o = add(eye, add(mul(sx, a), mul(uy, b)));
            double t = -(dot(nrm, o) + P.d) / dot(nrm, f);
            if (t < n || t > fa) continue;
            v3 X = add(o, mul(f, t));
            double xl, yl, zl, q;
            light_px(&Ml, X, &xl, &yl, &zl, &q);
            /* light on the viewer's side of P or not: q > 0 in front */
            ck_assert_double_gt(q, 0);
            ck_assert_double_le(fmax(fabs(xl - x), fabs(yl - y)) / fmax(g, h), 1e-9);
        }
    }
}
END_TEST

/* Near-degenerate sweep: planes almost through the eye, lights almost on
 * the plane or grazing it, planes almost parallel to the view.  Errors
 * leave the output untouched; every other result is finite with q > 0 on
 * the visible plane points. */
START_TEST(near_degenerate_never_nan) {
    rng_state = 0xDE6u;
    int n_err = 0, n_ok = 0;
    for (int it = 0; it < 4000; ++it) {
        config k = random_config(50.0);
        double eps = pow(10.0, -rnd(3, 15));
        v3 n = V(k.P.a, k.P.b, k.P.c);
        switch (it % 4) {
        case 0: /* plane through the eye, offset eps */
            k.P.d = -dot(n, k.c.eye) + eps * (rng_next() & 1 ? 1 : -1);
            break;
        case 1: /* point light eps off the plane */
        {
            v3 X0 = mul(n, -k.P.d / dot(n, n));
            v3 lp = add(add(X0, mul(unit(cross(n, rnd_unit())), rnd(1, 30))), mul(unit(n), eps));
            k.light = point_light(lp);
            break;
        }
        case 2: /* directional light grazing the plane */
        {
            v3 t = unit(cross(n, rnd_unit()));
            k.light = dir_light(add(t, mul(unit(n), eps)));
            break;
        }
        default: /* plane almost parallel to the view direction */
        {
            v3 t = unit(cross(k.c.f, rnd_unit()));
            n = add(t, mul(k.c.f, eps));
            k.P = plane_through(n, add(k.c.eye, mul(k.c.u, -rnd(0.5, 5))));
            break;
        }
        }
        swarp_mat4 Ml;
        sentinel(&Ml);
        swarp_status st = swarp_lixel_matrix(&k.Mv, k.c.g, k.c.h, &k.light, &k.P, NULL, &Ml, NULL);
        if (swarp_status_is_error(st)) {
            ck_assert(is_sentinel(&Ml));
            ++n_err;
            continue;
        }
        ++n_ok;
        ck_assert(mat_finite(&Ml));
        for (int s = 0; s < 8; ++s) {
            v3 X;
            double xs = rnd(0, k.c.g - 1), ys = rnd(0, k.c.h - 1);
            double t = cam_hit(&k.c, &k.P, xs, ys, &X);
            if (!(t > k.c.z_near) || t > k.c.z_far) continue;
            double x, y, z, q;
            light_px(&Ml, X, &x, &y, &z, &q);
            ck_assert(isfinite(q));
            if (st == SWARP_OK) {
                /* no warning given: then it must still be right */
                ck_assert_double_gt(q, 0);
                double e = fmax(fabs(x - xs), fabs(y - ys)) / fmax(k.c.g, k.c.h);
                ck_assert_msg(e <= 1e-9, "case %d eps %g: error %g", it % 4, eps, e);
            }
        }
    }
    ck_assert_int_gt(n_err, 100);
    ck_assert_int_gt(n_ok, 100);
}
END_TEST

/* @@MORE_TESTS@@ */

/* Finite, valid inputs whose result exceeds DBL_MAX: OUT_OF_RANGE (was
 * NON_FINITE, which says an INPUT was not finite), outputs untouched. */
START_TEST(overflowing_results_are_out_of_range) {
    swarp_mat4 M, V, P;
    for (int i = 0; i < 16; ++i) M.m[i] = (i % 5 == 0) ? DBL_MAX : 0.0;
    sentinel(&V);
    sentinel(&P);
    /* width 1: GLP row 0 = 2 X + 0 Q, 2 DBL_MAX is not representable */
    ck_assert_int_eq(swarp_lixel_factor(&M, 1, 1, SWARP_DEPTH_DEFAULT, 0.0, &V, &P), SWARP_ERR_OUT_OF_RANGE);
    ck_assert(is_sentinel(&V) && is_sentinel(&P));
    for (int i = 0; i < 16; ++i) M.m[i] = (i % 5 == 0) ? 0.25 * DBL_MAX : 0.0;
    ck_assert_int_eq(swarp_lixel_factor(&M, 1, 1, SWARP_DEPTH_DEFAULT, 0.0, &V, &P), SWARP_OK);
    /* restrict: x = x_w + y_w, y = y_w - x_w, rays through the origin image
     * to (0, 0) (a one-lixel rectangle) but scale_x = DBL_MAX with twist
     * pi/4 makes A_l M_l's row 0 = sqrt(2) DBL_MAX */
    swarp_mat4 Ml = {{0}};
    Ml.m[0] = 1;
    Ml.m[4] = 1;
    Ml.m[1] = -1;
    Ml.m[5] = 1;
    Ml.m[10] = 1;
    Ml.m[15] = 1;
    swarp_vec4 C[2] = {{0, 0, 1, 1}, {0, 0, 2, 1}};
    swarp_lixel_restrict_options o;
    memset(&o, 0, sizeof o);
    o.scale_x = DBL_MAX;
    o.twist = M_PI / 4;
    swarp_lixel_rect R, Rs;
    memset(&Rs, 0x5A, sizeof Rs);
    R = Rs;
    sentinel(&P);
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 2, &o, &R, NULL, &P), SWARP_ERR_OUT_OF_RANGE);
    ck_assert(is_sentinel(&P));
    ck_assert(memcmp(&R, &Rs, sizeof R) == 0);
    o.scale_x = 1;
    ck_assert_int_eq(swarp_lixel_restrict(&Ml, C, 2, &o, &R, NULL, &P), SWARP_OK);
}
END_TEST

/* a at 1e97 along x images to the vanishing point of x; b and below
 * lie on a line parallel to x, so the three images are collinear: below is
 * 5e-17 lixel off the line (exact arithmetic), far below the rounding of
 * the image coordinates (~1e-15).  Deciding the side of below by the sign
 * of rel would let the rounding choose: TWIST_LINE (rel == 0) to nearest,
 * twist -2.46 under FE_UPWARD, +0.68 under FE_DOWNWARD.  `below` within
 * LX_TWIST_EPS of the image scale of the line has no side: TWIST_LINE in
 * every mode. */
START_TEST(twist_below_on_line_rounding_mode) {
    static const swarp_mat4 M = {{-0x1.0000000000001p+0, 0x1.099c85c4712c4p-1, 0x1p+1, 0x1.69f95bee07d28p-3,
                                  0x1.86b6cdd9c0fd2p-1, -0x1.008b66862ef8p-4, 0x1p+0, -0x1.1d5b823f2a546p-1,
                                  0x1.060a26630e6p-1, 0x1p+0, 0x1.ad7f29abcaf48p-24, -0x1p+0, -0x1p+0,
                                  0x1.ad4dcf4470a44p-2, 0x1.baafa7678a56p-2, 0x1.0000000000001p+0}};
    const swarp_vec3 a = {0x1.d6852e2ec3bb7p+322, 0x1.28262fa5c3cap+0, -0x1.dd35f529cc9b9p+266},
                     b = {0x1.ea528265acbffp+2, 0x1.4p+3, -0x1.4000000000001p+3}, below = {10, 10, -10};
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int m = 0; m < 4; ++m) {
        double tw = 99;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_twist_for_line(&M, &a, &b, &below, &tw);
        fesetround(FE_TONEAREST);
        ck_assert_msg(st == SWARP_ERR_LIXEL_TWIST_LINE, "mode %d: %s, twist %.17g", m, swarp_status_name(st), tw);
        ck_assert_double_eq(tw, 99);
    }
    /* a point clearly off the line still gets its side, in every mode */
    const swarp_vec3 off = {10, 11, -10};
    double tw0 = 0;
    ck_assert_int_eq(swarp_lixel_twist_for_line(&M, &a, &b, &off, &tw0), SWARP_OK);
    for (int m = 1; m < 4; ++m) {
        double tw = 99;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_twist_for_line(&M, &a, &b, &off, &tw);
        fesetround(FE_TONEAREST);
        ck_assert_int_eq(st, SWARP_OK);
        ck_assert_msg(fabs(tw - tw0) <= 1e-12, "mode %d: twist %.17g, to nearest %.17g", m, tw, tw0);
    }
}
END_TEST

/* The floor x = -1e6, the wall y = 0.41, a light whose x component is 1 ulp
 * off 1e-9: Sigma is 1e-9 (rad) from the floor, on the "light on the floor"
 * bound.  The side = Sigma . F formed as n . F - n . A with F, A of 1e6
 * carries 1e-10 of rounding, enough to flip DEGENERATE and OK between
 * modes; as n . w_f (unit vectors, rounding ~eps) it gives the same status
 * in every mode. */
START_TEST(split_light_floor_bound_rounding_mode) {
    swarp_light light;
    memset(&light, 0, sizeof light);
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = (swarp_vec3){-0x1.12e0be826d695p-30, -0x1.0000000001198p+0, -0x1.97ead56768218p-3};
    const swarp_plane fl = {0x1p+0, 0x0p+0, 0x0p+0, 0x1.e848c4a087066p+19}, wa = {0x0p+0, 0x1p+0, 0x0p+0, -0x1.a7b0afea8fc4p-2};
    const swarp_vec4 C[4] = {{-0x1.e848362b12b0dp+19, -0x1.06e4a586b34eap+1, -0x1.e847719dfaf7bp+19, 1},
                             {-0x1.e848395e45e4p+19, -0x1.06e4a586b34eap+1, -0x1.e8476e6ac7c48p+19, 1},
                             {-0x1.e8483c9179173p+19, -0x1.06e4a586b34eap+1, -0x1.e847719dfaf7bp+19, 1},
                             {-0x1.e848395e45e4p+19, -0x1.06e4a586b34eap+1, -0x1.e84774d12e2aep+19, 1}};
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    swarp_status st0 = SWARP_OK;
    size_t nf0 = 0, nw0 = 0;
    for (int m = 0; m < 4; ++m) {
        swarp_vec4 of[SWARP_LIXEL_SPLIT_MAX(4)], ow[SWARP_LIXEL_SPLIT_MAX(4)];
        size_t nf = 0, nw = 0;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_split(&light, &fl, &wa, C, 4, of, SWARP_LIXEL_SPLIT_MAX(4), &nf, ow,
                                            SWARP_LIXEL_SPLIT_MAX(4), &nw);
        fesetround(FE_TONEAREST);
        if (m == 0) {
            st0 = st, nf0 = nf, nw0 = nw;
            continue;
        }
        ck_assert_msg(st == st0, "mode %d: %s, to nearest %s", m, swarp_status_name(st), swarp_status_name(st0));
        if (st == SWARP_OK) ck_assert(nf == nf0 && nw == nw0);
    }
}
END_TEST

/* swarp_lixel_restrict under FE_UPWARD, FE_DOWNWARD and FE_TOWARDZERO
 * gives the status and the rectangle it gives to nearest */
static void restrict_same_in_every_mode(const swarp_mat4* M, const swarp_vec4* C, size_t n,
                                        const swarp_lixel_restrict_options* o) {
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    swarp_lixel_rect r0;
    memset(&r0, 0, sizeof r0);
    swarp_status st0 = SWARP_OK;
    for (int m = 0; m < 4; ++m) {
        swarp_lixel_rect r;
        swarp_mat4 out;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_restrict(M, C, n, o, &r, NULL, &out);
        fesetround(FE_TONEAREST);
        if (m == 0) {
            st0 = st, r0 = r;
            continue;
        }
        ck_assert_msg(st == st0, "mode %d: %s, to nearest %s", m, swarp_status_name(st), swarp_status_name(st0));
        ck_assert_msg(r.x0 == r0.x0 && r.x1 == r0.x1 && r.y0 == r0.y0 && r.y1 == r0.y1,
                      "mode %d: rect [%d, %d] x [%d, %d], to nearest [%d, %d] x [%d, %d]", m, r.x0, r.x1, r.y0, r.y1, r0.x0,
                      r0.x1, r0.y0, r0.y1);
    }
}

/* M's q row is 1e78 times its x, y rows and C holds one direction
 * (q = 0): the cone's image is a ray from within 1e-76 lixel of the origin
 * toward (0.95, -0.30), a wedge flat to rounding.  The view-clipping corner
 * test compares the corner's side of each edge with the interior vector
 * S's; S lies on the plane of the edges through the direction (its side
 * 1e-77 against rounding 2e-16), so by sign alone FE_UPWARD would count the
 * corner (g - 1, 0) inside (rect x0 -1099 instead of 0, A_l M_l's
 * translation 1e81).  An edge plane holding S (flat cone) keeps only
 * corners on it. */
START_TEST(restrict_flat_cone_rounding_mode) {
    static const swarp_mat4 M = {{0x1.6cde06a370998p-2, -0x1.4bc252de49ddap-1, 0x1.fea9a411e36fep-1, 0x0p+0,
                                  0x1.7228f6f0775d2p-1, -0x1.3f49068b5a344p-2, -0x1p+0, 0x0p+0, -0x1.623fab8bf5c0cp-1,
                                  -0x1.5ba931c9fb568p-2, 0x1.fffffffffffffp-1, 0x0p+0, 0x1.4f7fdedb6a206p-1,
                                  0x1.ea8240547cc4p-1, 0x1.77a253562a9ccp-2, 0x1.0502b38b77194p+259}};
    static const swarp_vec4 C[8] = {{0x1.7b86678bff0c8p+5, -0x1.4a82f7f1b5c88p+4, -0x1.539c7bd5d3c98p+5, 0x0p+0},
                                    {0x1.4bc5e6c5d08bp+6, -0x1.65a6bcf814756p+6, 0x1.8ffffffffffffp+6, 0x1p+0},
                                    {0x1.b5051e73ab038p+3, -0x1.9000000000001p+6, 0x1.9000000000001p+6, 0x1p+0},
                                    {-0x1.99c5b1d5e0e18p+3, -0x1.9000000000001p+6, 0x1.94a188a4f009dp+5, 0x1p+0},
                                    {0x1.c816bb8e718c2p+4, -0x1.0c9a4b2384d2p+6, -0x1.00030e39c3b88p+6, 0x1p+0},
                                    {0x1.10ba7b7a85094p+6, -0x1.2724a9e1d939p+4, 0x1.9000000000001p+6, 0x1p+0},
                                    {0x1.9ea1ab5e3e2f8p+5, -0x1.5e98eb8d84adp+4, -0x1.0b8f1750e991p+5, 0x1p+0},
                                    {0x1.82fda32fb6b6ep+6, -0x1.8628abe0964d6p+6, -0x1.9000000000001p+6, 0x1p+0}};
    swarp_lixel_restrict_options o;
    memset(&o, 0, sizeof o);
    o.scale_x = 0x1.447b0d41021ecp+0;
    o.scale_y = 0x1.27e31f8c4f4dbp+1;
    o.twist = -0x1.080a3d8b45cdp+1;
    o.view_width = 1836;
    o.view_height = 209;
    restrict_same_in_every_mode(&M, C, 8, &o);
}
END_TEST

/* M is affine (q = 0.53 for every point) and two vertices of C lie
 * 1.7e38 and 4.7e31 out along x, on either side: their light images are
 * 1.6e38 and 4e31 lixels out along one direction u = M's first column, and
 * the edge between them images to a line through M (0, 2e-5, -68), 95 lixels
 * from the view's corner (0, 0).  Formed from the two unit image vectors,
 * antipodal to 1e-30, that line cancels in x, y (a + b = (0, 0, 2e-32) to
 * nearest, +-1e-16 noise in the directed modes): the edge's crossings of
 * the sides would land at (0, 0) or nowhere and the triangle read as flat
 * ([-232, 0] x [0, 2379] to nearest, [-232, -86] x [203, 2379] directed).
 * Exactly, the clipped triangle is (0, 0), (95.36, 0), (414, 305.6),
 * (414, 513.1), (0, 116.0): the rect [-232, 35] x [0, 2379], the reference. */
START_TEST(restrict_antipodal_edge_rounding_mode) {
    static const swarp_mat4 M = {{-0x1.355ed3ad362fp-2, -0x1.28bc28e9de454p-2, -0x1.b91a7d7155f9ap-1, 0x0p+0,
                                  0x1.ba5e4cee39e48p-2, 0x1.9c81a4d6aac46p-1, 0x1.2638bf971efbcp-2, 0x0p+0,
                                  0x1.1bc107721c85cp-2, 0x1p+0, -0x1.5dd19d1fd5a58p-2, 0x0p+0, -0x1p+0, 0x1p+0,
                                  0x1.fcb3cda8f8954p-2, 0x1.0ce00ec056f94p-1}};
    static const swarp_vec4 C[3] = {{0x1.c42730b78399ep+4, -0x1.279a78dce8067p+5, 0x1.8ffffffffffffp+6, 0x1p+0},
                                    {-0x1.9881974a870b2p+127, 0x1.6702dfc634aep+6, 0x1.9p+6, 0x1p+0},
                                    {0x1.b1b07b37add8cp+105, 0x1.012c4b096102cp-285, -0x1.1058287de091cp+6, 0x1p+0}};
    swarp_lixel_restrict_options o;
    memset(&o, 0, sizeof o);
    o.scale_x = 0x1.a9bbe10c5a4c8p-1;
    o.scale_y = 0x1.fd75f8a1fcb98p+1;
    o.twist = 0x1.1d7b51fc9922p+0;
    o.view_width = 415;
    o.view_height = 806;
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int m = 0; m < 4; ++m) {
        swarp_lixel_rect r;
        swarp_mat4 out;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_restrict(&M, C, 3, &o, &r, NULL, &out);
        fesetround(FE_TONEAREST);
        ck_assert_msg(st == SWARP_OK, "mode %d: %s", m, swarp_status_name(st));
        ck_assert_msg(r.x0 == -232 && r.x1 == 35 && r.y0 == 0 && r.y1 == 2379,
                      "mode %d: rect [%d, %d] x [%d, %d], exactly [-232, 35] x [0, 2379]", m, r.x0, r.x1, r.y0, r.y1);
    }
}
END_TEST

/* The eye 1.4e6 from the origin looks along the plane z = -999996.6
 * (n . v = 2e-15, far - near = 4.35).  PLANE_PARALLEL_VIEW compares |n . v|
 * with 1e-9; a view direction taken as V^-1's far point minus its near
 * point cancels at the eye's magnitude to 1e-10 of rounding (and gives
 * QUAD_ACROSS_INFINITY under FE_TOWARDZERO), so the direction is the cross
 * product of M_v's rows' x, y, z parts, exact to rounding.  ILL_CONDITIONED (of higher
 * priority) is the solver's conditioning threshold, which rounding decides
 * here; across infinity must not come. */
START_TEST(matrix_parallel_view_rounding_mode) {
    static const swarp_mat4 Mv = {{-0x1.25f7c8cfb36b4p-50, 0x1.7523af7f55577p-2, 0x1.eb47677322518p-2,
                                   0x1.e31794b4f80b1p-2, 0x0p+0, 0x1.8f4cd7c30f5ep-3, -0x1.cb178eaa1ad89p-1,
                                   -0x1.c3710b910b455p-1, 0x1.ebee4c31ec4cap-3, 0x1.bdf609a685cafp-50,
                                   0x1.25940d5e8ab6fp-49, 0x1.20afa17823401p-49, 0x1.d5235cc1b4e39p+17,
                                   0x1.63da1f3da8237p+18, 0x1.d48639d5646c7p+18, 0x1.ccb77e4e1de43p+18}};
    swarp_light L;
    memset(&L, 0, sizeof L);
    L.type = SWARP_LIGHT_DIRECTIONAL;
    L.direction.x = -0x1.9adc28d2c7d1p-3;
    L.direction.y = 0x1.d6937a17f179cp-2;
    L.direction.z = 0x1.b9f36c8117166p-1;
    const swarp_plane P = {0.0, 0.0, 1.0, 0x1.e847932d24a41p+19};
    swarp_lixel_options o;
    memset(&o, 0, sizeof o);
    o.raise = 0x1.d354b0b433194p-1;
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int m = 0; m < 4; ++m) {
        swarp_mat4 M;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_matrix(&Mv, 1102, 2087, &L, &P, &o, &M, NULL);
        fesetround(FE_TONEAREST);
        ck_assert_msg(st == SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW || st == SWARP_INFO_LIXEL_ILL_CONDITIONED,
                      "mode %d: %s", m, swarp_status_name(st));
    }
}
END_TEST

/* A 1e-15 rad field of view seeing the
 * floor y = 0.6 from 2.5e5 off the origin.  The planner's swarp_lixel_matrix
 * call hands solve5 the light, three corner hits that coincide to rounding
 * (1e-14 apart in truth, 1e-10 of noise at 2.5e5) and the raised point; a
 * median normalisation scales the noise up to unit size, and the
 * conditioning would read 5.6e-21 (COPLANAR) or 1.2e-13 (ILL_CONDITIONED, a
 * lixel map) by rounding mode.  Points within 64 eps |c| of their median
 * centre c coincide to rounding: COPLANAR in every mode (the set below is the
 * one FE_DOWNWARD computed); and the same for a cluster built by hand. */
START_TEST(solve5_cluster_coplanar_rounding_mode) {
    static const swarp_vec4 src[5] = {
        {-255359.16000000001, 110.58582116327303, -255353.47635140818, 1.0},
        {-0.7071148453377012, 1.6770163927463192e-06, -0.7070987169360149, 2.769110070550273e-06},
        {-0.70711484533770131, 1.6770163927463189e-06, -0.7070987169360149, 2.7691100705502726e-06},
        {-0.7071148453377012, 1.6770163927463189e-06, -0.70709871693601512, 2.7691100705502726e-06},
        {-255358.65871520335, 55.595718406175805, -255352.90469145074, 1.0}};
    static const swarp_vec4 dst[5] = {
        {0, 0, 1, 0}, {0, 0, 1, 1}, {0, 163, 1, 1}, {1231, 163, 1, 1}, {1231, 0, -1, 1}};
    /* by hand: three points 1, 2 and 3 ulps (2^-34 at 2^18) apart, a fourth
     * and a fifth far from them */
    const double u = 0x1p-34, x0 = 0x1p18;
    const swarp_vec4 src2[5] = {{x0, 3.0, x0, 1.0},         {x0 + u, 0.6, x0, 1.0}, {x0, 0.6, x0 + 2 * u, 1.0},
                                {x0 + 3 * u, 0.6, x0 - u, 1.0}, {x0 + 50.0, 1.0, x0 - 20.0, 1.0}};
    static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (int m = 0; m < 4; ++m) {
        swarp_mat4 M;
        double cond = -1.0;
        fesetround(modes[m]);
        swarp_status st = swarp_lixel_solve5(src, dst, &M, &cond);
        swarp_status st2 = swarp_lixel_solve5(src2, dst, &M, &cond);
        fesetround(FE_TONEAREST);
        ck_assert_msg(st == SWARP_ERR_LIXEL_COPLANAR, "mode %d: %s", m, swarp_status_name(st));
        ck_assert_msg(st2 == SWARP_ERR_LIXEL_COPLANAR, "mode %d, by hand: %s", m, swarp_status_name(st2));
    }
}
END_TEST

/* C is not convex (outside the documented domain, but a caller can pass
 * one; tests/robust draws its vertices at random): two of them 1.4e54 and 4.4e25
 * out image to antipodal directions, the interior vector S lies on the
 * plane of the edge from the direction vertex, and that edge takes the
 * cone's orientation, the sign of the largest (sum_j l_j) . a_m -- a near
 * tie between two vertices of opposite sign, which the rounding would
 * break (three view corners inside, rect [77, 3107] x [-364, 3300], or
 * none, [77, 365] x [-89, 203]).  Both signs beyond rounding give no
 * orientation, the same rectangle in every mode. */
START_TEST(restrict_nonconvex_orientation_rounding_mode) {
    static const swarp_mat4 M = {{0x1.9a0458143e19ep-1, -0x1.43fc5f3f91b6p-1, -0x1.7c5876a1703c8p-2, 0x0p+0,
                                  -0x1.867f298351bep-5, -0x1.1eca8d29333d8p-1, -0x1.0919919050384p-1, 0x0p+0,
                                  0x1.10d43bbb7e17cp-2, -0x1.bd0c8246ecd14p-1, -0x1.263a096734e1cp-1, 0x0p+0,
                                  -0x1.5072f9bad090ep-1, 0x1.fffffffffffffp-1, 0x1.1dd460f0aca5cp-1,
                                  0x1.1e0782dbb9ae7p+0}};
    static const swarp_vec4 C[4] = {{-0x1.82bab446a492p+2, -0x1.9000000000001p+6, -0x1.2c0411dce699p+5, 0x1p+0},
                                    {0x1.dd6fde5fec6dbp+179, 0x1.3eb2a8a5fea7p+2, -0x1.5e3596af1accp+2, 0x1p+0},
                                    {-0x1.22f457f3af67p+85, -0x1.9000000000001p+6, -0x1.23111ca3ec29cp+6, 0x1p+0},
                                    {-0x1.024c1633d818ep+6, -0x1.2c3bb416636fcp+6, -0x1.2cbda23db758p+4, 0x0p+0}};
    swarp_lixel_restrict_options o;
    memset(&o, 0, sizeof o);
    o.scale_x = 0x1.91fd81e1e2014p+1;
    o.scale_y = 0x1.1ba143ffdf2b4p+1;
    o.twist = -0x1.522fbc3cff35p-2;
    o.view_width = 507;
    o.view_height = 1575;
    restrict_same_in_every_mode(&M, C, 4, &o);
}
END_TEST

static Suite* lixel_suite(void) {
    Suite* s = suite_create("lixel");
    TCase* tc = tcase_create("lixel");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, plane_points_same_pixel_in_both_images);
    tcase_add_test(tc, jacobian_is_identity);
    tcase_add_test(tc, miners_lamp_parallel_image_planes);
    tcase_add_test(tc, flatland_light_plane_parallel_to_pi_l);
    tcase_add_test(tc, quad_across_infinity);
    tcase_add_test(tc, large_world_coordinates);
    tcase_add_test(tc, degenerate_inputs_have_own_status);
    tcase_add_test(tc, solve5_recovers_a_known_matrix);
    tcase_add_test(tc, solve5_coplanar_and_ill_conditioned);
    tcase_add_test(tc, restrict_rectangle_encloses_and_is_tight);
    tcase_add_test(tc, restrict_bad_inputs);
    tcase_add_test(tc, restrict_clipped_to_view_matches_sampling);
    tcase_add_test(tc, factor_viewport_times_projection);
    tcase_add_test(tc, floor_wall_split_and_select);
    tcase_add_test(tc, split_directional_points);
    tcase_add_test(tc, orthographic_viewer);
    tcase_add_test(tc, near_degenerate_never_nan);
    tcase_add_test(tc, overflowing_results_are_out_of_range);
    /* the same status and result in every rounding mode */
    tcase_add_test(tc, twist_below_on_line_rounding_mode);
    tcase_add_test(tc, split_light_floor_bound_rounding_mode);
    tcase_add_test(tc, restrict_flat_cone_rounding_mode);
    tcase_add_test(tc, restrict_antipodal_edge_rounding_mode);
    tcase_add_test(tc, matrix_parallel_view_rounding_mode);
    tcase_add_test(tc, solve5_cluster_coplanar_rounding_mode);
    tcase_add_test(tc, restrict_nonconvex_orientation_rounding_mode);
    /* @@MORE_TCASES@@ */
    suite_add_tcase(s, tc);
    return s;
}

int main(void) {
    int failed = tu_run_suite(lixel_suite());
    return failed ? 1 : 0;
}
