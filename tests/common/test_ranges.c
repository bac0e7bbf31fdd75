/* Valid inputs at the edges of the double range: a clip plane whose offset
 * is DBL_MAX, and a stabilised split frustum far smaller than the rounding
 * of its world coordinates.  Each is checked against an independent
 * evaluation in long double of what the header promises (the kept part of
 * n·x + d <= 0; a map that contains the split frustum), on the exact input
 * that failed before. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

/* ---- the clip plane beyond the double range -------------------------------- */

/* n·v + d in long double for the 8 corners of the unit box: for d near
 * DBL_MAX every value is about d > 0, so the plane removes every corner. */
static int corners_removed(const swarp_plane* pl) {
    int removed = 0;
    for (int i = 0; i < 8; ++i) {
        long double x = (i & 1), y = (i & 2) >> 1, z = (i & 4) >> 2;
        long double v = (long double)pl->a * x + (long double)pl->b * y + (long double)pl->c * z + pl->d;
        removed += v > 0.0L;
    }
    return removed;
}

static swarp_polyhedron unit_box(void) {
    swarp_aabb b = {{0, 0, 0}, {1, 1, 1}};
    swarp_polyhedron p;
    ck_assert_int_eq(swarp_poly_from_aabb(&b, &p), SWARP_OK);
    ck_assert_uint_eq(p.vertex_count, 8);
    return p;
}

/* The plane's normal has length 1 - 2^-53 or so: d / |n| overflows to inf
 * although d = DBL_MAX is finite; the clipper then kept all 8 vertices. */
START_TEST(clip_plane_at_dbl_max_removes_everything) {
    const swarp_polyhedron box = unit_box();
    swarp_plane pl = {-0x1.4c009744b349p-2, 0x1.66640a09a4bcfp-1, 0x1.45cc065b8953p-1, 0x1.fffffffffffffp+1023};
    ck_assert_int_eq(corners_removed(&pl), 8);
    swarp_polyhedron out;
    ck_assert_int_eq(swarp_poly_clip(&box, &pl, &out), SWARP_OK);
    ck_assert_uint_eq(out.vertex_count, 0);
    ck_assert_uint_eq(out.face_count, 0);
    /* the same plane one step inside the range (1.7e308) was right before */
    pl.d = 1.7e308;
    ck_assert_int_eq(corners_removed(&pl), 8);
    ck_assert_int_eq(swarp_poly_clip(&box, &pl, &out), SWARP_OK);
    ck_assert_uint_eq(out.vertex_count, 0);
    /* the mirrored plane keeps everything: n·v - DBL_MAX < 0 for every corner */
    pl.d = -DBL_MAX;
    ck_assert_int_eq(corners_removed(&pl), 0);
    ck_assert_int_eq(swarp_poly_clip(&box, &pl, &out), SWARP_OK);
    ck_assert_uint_eq(out.vertex_count, 8);
    ck_assert_uint_eq(out.face_count, 6);
    ck_assert_int_eq(memcmp(out.vertices, box.vertices, sizeof box.vertices), 0);
}
END_TEST

/* ---- the stabilised sphere far from the world origin ------------------------ */

typedef struct ld3 {
    long double x, y, z;
} ld3;
static ld3 ld_unit(ld3 a) {
    long double l = sqrtl(a.x * a.x + a.y * a.y + a.z * a.z);
    return (ld3){a.x / l, a.y / l, a.z / l};
}
static ld3 ld_cross(ld3 a, ld3 b) {
    return (ld3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/* Largest |x|, |y| (NDC) and depth outside [-1, 1] of the 8 corners of the
 * split frustum [n, f] under m, where m takes origin-relative coordinates
 * and origin = eye: the corners relative to the eye are
 * z (f + sx tan(fovy/2) aspect r + sy tan(fovy/2) u), z in {n, f},
 * evaluated in long double from the camera's definition (not through the
 * library's frame). */
static void split_corners_ndc(const swarp_camera* cam, double n, double f, const swarp_mat4* m,
                              long double* max_xy, long double* max_depth_excess) {
    ld3 fw = ld_unit((ld3){cam->dir.x, cam->dir.y, cam->dir.z});
    ld3 r = ld_unit(ld_cross(fw, (ld3){cam->up.x, cam->up.y, cam->up.z}));
    ld3 u = ld_cross(r, fw);
    long double ty = tanl(0.5L * cam->fovy), tx = ty * cam->aspect;
    *max_xy = 0.0L;
    *max_depth_excess = 0.0L;
    for (int i = 0; i < 8; ++i) {
        long double z = (i & 4) ? f : n, sx = (i & 1) ? 1 : -1, sy = (i & 2) ? 1 : -1;
        ld3 p = {z * (fw.x + sx * tx * r.x + sy * ty * u.x), z * (fw.y + sx * tx * r.y + sy * ty * u.y),
                 z * (fw.z + sx * tx * r.z + sy * ty * u.z)};
        long double h[4];
        for (int k = 0; k < 4; ++k)
            h[k] = m->m[k] * p.x + m->m[4 + k] * p.y + m->m[8 + k] * p.z + m->m[12 + k];
        *max_xy = fmaxl(*max_xy, fmaxl(fabsl(h[0] / h[3]), fabsl(h[1] / h[3])));
        *max_depth_excess = fmaxl(*max_depth_excess, fabsl(h[2] / h[3]) - 1.0L);
    }
}

/* eye (8.2e6, 8.2e6, 8.2e6), origin = eye, split [2e-12, 6e-10]: the
 * origin-relative coordinates of the split are exactly what the caller
 * renders with, yet the map put its corners at |ndc| 1.31 (the sphere's
 * centre went through world coordinates, whose ulp 1.9e-9 exceeds the
 * split).  The map must contain the split frustum: |x|, |y| <= 1 and depth
 * in [-1, 1].  Tolerance 1e-12: the corners lie on or inside the sphere and
 * the padding res/(res - 1) covers the half-texel snap exactly, so the
 * bound is tight; what is left is the rounding of the radius, of the
 * centre's depth and of the 16 matrix entries, a few eps each (1e-12 is
 * about 4500 eps), against a failure of 0.31. */
START_TEST(stabilized_sphere_covers_split_relative_to_distant_origin) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){8.2e6, 8.2e6, 8.2e6};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 1.0;
    cam.aspect = 16.0 / 9.0;
    cam.z_near = 1.0;
    cam.z_far = 100.0;
    const swarp_vec3 dirs[3] = {{0, -0.3, -1}, {1, 0.2, 0.1}, {-0.4, -1, 0.7}};
    const swarp_vec3 lights[3] = {{0.3, -1, 0.2}, {0, -1, 0}, {1, -0.1, 0.3}};
    const uint32_t res[2] = {2048, 16};
    int cases = 0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 2; ++c) {
                cam.dir = dirs[a];
                swarp_stabilize_options o;
                memset(&o, 0, sizeof o);
                o.mode = SWARP_STABILIZE_SPHERE;
                o.origin = cam.eye;
                swarp_mat4 m;
                swarp_stabilize_report rep;
                ck_assert_int_eq(swarp_stabilize_directional(&cam, 2e-12, 6e-10, &lights[b], NULL, 0, NULL,
                                                             res[c], &o, &m, &rep),
                                 SWARP_OK);
                long double xy, dz;
                split_corners_ndc(&cam, 2e-12, 6e-10, &m, &xy, &dz);
                ck_assert_msg(xy <= 1.0L + 1e-12L, "dir %d light %d res %u: |ndc| %.17Lg", a, b, res[c], xy);
                ck_assert_msg(dz <= 1e-12L, "dir %d light %d res %u: depth excess %.3Lg", a, b, res[c], dz);
                /* not vacuous: the map is about the sphere's size, so a
                 * corner reaches most of the way to the edge */
                ck_assert(xy > 0.5L);
                ++cases;
            }
    ck_assert_int_eq(cases, 18);
}
END_TEST

static Suite* suite(void) {
    Suite* s = suite_create("ranges");
    TCase* t = tcase_create("all");
    tcase_add_test(t, clip_plane_at_dbl_max_removes_everything);
    tcase_add_test(t, stabilized_sphere_covers_split_relative_to_distant_origin);
    suite_add_tcase(s, t);
    return s;
}

int main(void) { return tu_run_suite(suite()); }
