#define _POSIX_C_SOURCE 200809L
/* swarp_plan_explain's numbers do not depend on the caller's rounding mode:
 * values just below a decimal rounding boundary
 * (0.5325 is 0.53249999999999997... in binary) are printed as the exact
 * binary value rounds, in every mode; the reference is glibc's printf, which
 * converts the exact binary value (round-to-nearest, no ties here). */
#include <check.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

static void explain(const swarp_plan_result* p, int mode, char* text, size_t cap) {
    size_t n = 0;
    fesetround(mode);
    swarp_status st = swarp_plan_explain(p, text, cap, &n);
    fesetround(FE_TONEAREST);
    ck_assert_int_eq(st, SWARP_OK);
    ck_assert_uint_eq(n, strlen(text) + 1);
}

START_TEST(explain_text_independent_of_rounding_mode) {
    swarp_scene_needs needs;
    swarp_budget budget;
    memset(&needs, 0, sizeof needs);
    memset(&budget, 0, sizeof budget);
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&needs, &budget, &p)));
    /* values on the wrong side of a boundary after one directed rounding */
    p.z_near = 0.5325;       /* "0.532" (the old code printed 0.533 in every mode but downward) */
    p.z_far = 2.675;         /* "2.67" */
    p.max_mx = 4.4445e-5;  /* "4.44e-05" */
    p.max_mz = 1.0005e-3;  /* "0.00100": 0.0010004999999999999... */
    p.error_area = 99.95;  /* "100": 99.9500000000000028... rounds up */
    p.texels = 1.2345e8;   /* "1.23e+08" */
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    char ref[SWARP_PLAN_EXPLAIN_MAX], got[SWARP_PLAN_EXPLAIN_MAX];
    explain(&p, FE_TONEAREST, ref, sizeof ref);
    for (int m = 1; m < 4; ++m) {
        explain(&p, modes[m], got, sizeof got);
        ck_assert_msg(strcmp(ref, got) == 0, "mode %d:\n%s\nvs\n%s", m, got, ref);
    }
    /* the digits are the exact value's (printf converts exactly) */
    char want[64];
    snprintf(want, sizeof want, "%.3g", p.z_near);
    ck_assert_str_eq(want, "0.532");
    ck_assert_msg(strstr(ref, "depth range [0.532, 2.67]") != NULL, "%s", ref);
    snprintf(want, sizeof want, "max m_x %.2e", p.max_mx);
    ck_assert_msg(strstr(ref, want) != NULL, "%s not in %s", want, ref);
    ck_assert_msg(strstr(ref, "m_z 0.00100") != NULL, "%s", ref);
    snprintf(want, sizeof want, "%.2e texels", p.texels);
    ck_assert_msg(strstr(ref, want) != NULL, "%s not in %s", want, ref);
    /* a rounding that carries into the next decade is formatted in that
     * decade: one ulp below 100 prints as 100 exactly does ("100", not
     * "100.0"), and one ulp below 1e7 as "1.00e+07" */
    p.z_near = nextafter(100.0, 0.0);
    p.z_far = nextafter(1e7, 0.0);
    for (int m = 0; m < 4; ++m) {
        explain(&p, modes[m], got, sizeof got);
        ck_assert_msg(strstr(got, "depth range [100, 1.00e+07]") != NULL, "mode %d: %s", m, got);
    }
    p.z_near = 100.0;
    p.z_far = 1e7;
    explain(&p, FE_TONEAREST, got, sizeof got);
    ck_assert_msg(strstr(got, "depth range [100, 1.00e+07]") != NULL, "%s", got);
}
END_TEST

/* Random values in every decade: the text is the same in every mode and
 * every number printed in scientific form matches printf's %.2e (away from
 * exact ties, which these random doubles never are). */
START_TEST(explain_random_values_every_mode) {
    swarp_scene_needs needs;
    swarp_budget budget;
    memset(&needs, 0, sizeof needs);
    memset(&budget, 0, sizeof budget);
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&needs, &budget, &p)));
    uint64_t s = 0xE7A1Eull;
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    char ref[SWARP_PLAN_EXPLAIN_MAX], got[SWARP_PLAN_EXPLAIN_MAX], want[64];
    for (int n = 0; n < 400; ++n) {
        /* 3 significant digits plus a few ulps either side of the boundary */
        double v = (tu_splitmix64(&s) % 900 + 100.5) * pow(10.0, (double)(tu_splitmix64(&s) % 600) - 300.0);
        v = nextafter(v, (n & 1) ? INFINITY : 0.0);
        p.max_mx = v;
        explain(&p, FE_TONEAREST, ref, sizeof ref);
        for (int m = 0; m < 3; ++m) {
            explain(&p, modes[m], got, sizeof got);
            ck_assert_msg(strcmp(ref, got) == 0, "v = %.17g, mode %d", v, m);
        }
        double e10 = floor(log10(v));
        if (e10 >= 7 || e10 < -3) {
            snprintf(want, sizeof want, "max m_x %.2e,", v);
            ck_assert_msg(strstr(ref, want) != NULL, "v = %.17g: %s not in %s", v, want, ref);
        }
    }
}
END_TEST

/* ---- costs at the ends of the double range ---- */

/* A pass cost near DBL_MAX would make cost_ns = K x pass cost = inf.
 * Costs above SWARP_PLAN_MAX_COST_NS are refused (documented); at the limit
 * the cost of every chain is finite. */
START_TEST(plan_cost_above_limit_refused_at_limit_finite) {
    const double costs[3] = {DBL_MAX, 1e300, SWARP_PLAN_MAX_COST_NS * 2};
    for (int i = 0; i < 3; ++i) {
        for (int field = 0; field < 3; ++field) {
            swarp_budget b;
            memset(&b, 0, sizeof b);
            double* f = field == 0 ? &b.pass_cost_ns : field == 1 ? &b.blur_pass_cost_ns : &b.time_budget_ns;
            *f = costs[i];
            struct swarp_plan p;
            memset(&p, 0x5a, sizeof p);
            ck_assert_int_eq(swarp_plan(NULL, &b, &p), SWARP_ERR_OUT_OF_RANGE);
            ck_assert_uint_eq(((const unsigned char*)&p)[0], 0x5a);
            swarp_plan_chain ch;
            memset(&ch, 0, sizeof ch);
            ch.scheme = SWARP_PLAN_SCHEME_PRACTICAL, ch.split_count = 16;
            ck_assert_int_eq(swarp_plan_evaluate(NULL, &b, &ch, &p), SWARP_ERR_OUT_OF_RANGE);
        }
    }
    /* at the limit: 16 splits with soft shadows (blur passes) stay finite */
    swarp_scene_needs n;
    memset(&n, 0, sizeof n);
    n.soft_shadows = 1;
    swarp_budget b;
    memset(&b, 0, sizeof b);
    b.pass_cost_ns = b.blur_pass_cost_ns = b.time_budget_ns = SWARP_PLAN_MAX_COST_NS;
    swarp_plan_chain ch;
    memset(&ch, 0, sizeof ch);
    ch.scheme = SWARP_PLAN_SCHEME_PRACTICAL, ch.split_count = 16;
    struct swarp_plan p;
    const swarp_status st = swarp_plan_evaluate(&n, &b, &ch, &p);
    ck_assert(st == SWARP_OK || st == SWARP_INFO_PLAN_POINT_LIGHT);
    ck_assert(isfinite(p.cost_ns) && p.cost_ns >= 16 * SWARP_PLAN_MAX_COST_NS);
}
END_TEST

/* ---- the planner's lixel check in every rounding mode ---- */

/* A floor (y = 0) seen by a camera with near/far below eps must get a lixel
 * map or not independently of the caller's rounding mode.  The planner asks swarp_lixel_matrix about a view-projection
 * it builds itself; its depth row -(f+n)/(f-n) z - 2fn/(f-n) tends to the w
 * row -z as n/f -> 0, and below n/f ~ eps the two rows are equal or one ulp
 * apart by the rounding of (f+n)/(f-n), so a check on V would call it
 * singular (LIXEL_REFUSED) or not (USED, 1 more pass).  The lixel matrix is
 * made of the rays (rows 0, 1, 3, [LIXEL] (2)), so the plane is
 * lixel-friendly whatever the depth range: used in every mode, at every
 * near. */
static void plan_floor(double near, int mode, swarp_status* st, swarp_plan_result* p) {
    swarp_scene_needs n;
    swarp_budget b;
    memset(&n, 0, sizeof n);
    memset(&b, 0, sizeof b);
    n.camera.eye = (swarp_vec3){0.3, 2.0, 0.7};
    n.camera.dir = (swarp_vec3){0.0, -0.5, -1.0};
    n.camera.up = (swarp_vec3){0.0, 1.0, 0.0};
    n.camera.fovy = 1.0;
    n.camera.aspect = 1.5;
    n.camera.z_near = near;
    n.camera.z_far = 100.0;
    n.plane_count = 1;
    n.planes[0].b = 1.0; /* the floor y = 0, lit by the default sun (0, -1, 0) */
    b.max_passes = 32;   /* a pass left for the lixel map after 16 splits */
    fesetround(mode);
    *st = swarp_plan(&n, &b, p);
    fesetround(FE_TONEAREST);
}

/* a tiny-near scene with 2 planes and a 2048 atlas, its arguments in hex */
static void plan_two_planes_tiny_near(int mode, swarp_status* st, swarp_plan_result* p) {
    swarp_scene_needs n;
    swarp_budget b;
    memset(&n, 0, sizeof n);
    memset(&b, 0, sizeof b);
    n.camera.eye = (swarp_vec3){-0x1.e848798ad0959p+19, 0x1.0000000000001p-1, -0x1.e847fb7b5d73ap+19};
    n.camera.dir = (swarp_vec3){-0x1.668a2d003baa8p-3, 0x1.9999999999999p-3, 0x1.5a97946040314p-1};
    n.camera.up = (swarp_vec3){0.0, 1.0, 0.0};
    n.camera.fovy = 0x1.69587353f4dbfp+0;
    n.camera.aspect = 2.5;
    n.camera.z_near = 0x1.e0425cee492d8p-101;
    n.camera.z_far = 0x1.52db33ed1aa1bp+18;
    n.bleed_risk = (swarp_plan_bleed)1;
    n.plane_count = 2;
    n.planes[0].b = n.planes[1].b = 1.0;
    n.planes[0].d = -0x1.47f335603d38p-2;
    n.planes[1].d = 0x1.a4c437883f732p-1;
    b.map_resolution = 2048;
    b.atlas_limit = 2048;
    b.max_passes = 24;
    fesetround(mode);
    *st = swarp_plan(&n, &b, p);
    fesetround(FE_TONEAREST);
}

static void same_plan(const swarp_plan_result* a, const swarp_plan_result* r, int mode) {
    ck_assert_msg(a->lixel_count == r->lixel_count, "mode %d: %u lixel maps, %u by default", mode, a->lixel_count,
                  r->lixel_count);
    for (uint32_t i = 0; i < r->plane_count; ++i)
        ck_assert_msg(a->plane_reason[i] == r->plane_reason[i], "mode %d plane %u: reason %u, %u by default", mode, i,
                      a->plane_reason[i], r->plane_reason[i]);
    /* the lixel passes: the chain itself is chosen by a measurement whose
     * rounding at near/far 1e-30 follows the rounding mode */
    ck_assert_uint_eq(a->shadow_passes - a->split_count, r->shadow_passes - r->split_count);
    if (a->split_count == r->split_count && a->map_resolution == r->map_resolution)
        ck_assert_msg(a->cost_ns == r->cost_ns, "mode %d: cost %.17g, %.17g by default", mode, a->cost_ns, r->cost_ns);
}

START_TEST(lixel_check_tiny_near_every_mode) {
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    static const double nears[] = {1e-30, 1e-20, 1e-17, 1e-16, 1e-6, 0.1};
    for (size_t k = 0; k < sizeof nears / sizeof nears[0]; ++k) {
        swarp_status st0, st;
        swarp_plan_result r, p;
        plan_floor(nears[k], FE_TONEAREST, &st0, &r);
        ck_assert(!swarp_status_is_error(st0));
        ck_assert_msg(r.plane_reason[0] == SWARP_PLAN_PLANE_USED && r.lixel_count == 1, "near %g: reason %u",
                      nears[k], r.plane_reason[0]);
        for (int m = 1; m < 4; ++m) {
            plan_floor(nears[k], modes[m], &st, &p);
            ck_assert_int_eq(st, st0);
            same_plan(&p, &r, m);
        }
    }
    swarp_status st0, st;
    swarp_plan_result r, p;
    plan_two_planes_tiny_near(FE_TONEAREST, &st0, &r);
    ck_assert_int_eq(st0, SWARP_INFO_PLAN_BUDGET_UNMET);
    ck_assert_uint_eq(r.lixel_count, 2);
    for (int m = 1; m < 4; ++m) {
        plan_two_planes_tiny_near(modes[m], &st, &p);
        ck_assert_int_eq(st, st0);
        same_plan(&p, &r, m);
    }
}
END_TEST

/* A 1e-15 rad field of view (arguments in hex) 2.5e5 off the origin, a point light above the eye, floor
 * planes y = 0.6 and y = -0.86.  The corner rays hit plane 0 at points that
 * coincide to rounding; judging their noise, swarp_lixel_solve5 would give
 * the plane a lixel map in one mode only.  Refused in every mode. */
static void plan_tiny_fov_clustered_corners(int mode, swarp_status* st, swarp_plan_result* p) {
    swarp_scene_needs n;
    swarp_budget b;
    memset(&n, 0, sizeof n);
    memset(&b, 0, sizeof b);
    n.camera.eye = (swarp_vec3){-0x1.f2bf947ae147bp+17, 0x1.c62de479ac6fbp+3, -0x1.f2bcbcf9153bcp+17};
    n.camera.dir = (swarp_vec3){0x1.d70bb60a2c58p-5, -0x1.8efec720d103ep-1, 0x1.0c967c05ce54p-4};
    n.camera.up = (swarp_vec3){0.0, 1.0, 0.0};
    n.camera.fovy = 0x1.203af9ee75616p-50;
    n.camera.aspect = 0x1.09aa7cd0985b6p+1;
    n.camera.z_near = 0x1.f62c71bd39841p-11;
    n.camera.z_far = 0x1.1ab53fc425b8ap+11;
    n.light.type = SWARP_LIGHT_POINT;
    n.light.direction = (swarp_vec3){-0x1.798a04743a5cp-1, -0x1p+0, -0x1.47b21ebbc2078p-1};
    n.light.position = (swarp_vec3){-0x1.f2bf947ae147bp+17, 0x1.ba57e180c63fep+6, -0x1.f2bcbcf9153bcp+17};
    n.screen_width = 1232;
    n.screen_height = 164;
    n.soft_shadows = 1;
    n.bleed_risk = (swarp_plan_bleed)3;
    n.allow_depth_clamp = 1;
    n.plane_count = 2;
    n.planes[0].b = n.planes[1].b = 1.0;
    n.planes[0].d = -0x1.3613411d7a00cp-1;
    n.planes[1].d = 0x1.b75a181419f2ep-1;
    b.max_error = 0x1.6bd64994b739ep+6;
    b.map_resolution = 256;
    b.max_passes = 18;
    b.time_budget_ns = 0x1.ff2388730e836p+24;
    fesetround(mode);
    *st = swarp_plan(&n, &b, p);
    fesetround(FE_TONEAREST);
}

START_TEST(lixel_check_clustered_corners_every_mode) {
    static const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    swarp_status st0, st;
    swarp_plan_result r, p;
    plan_tiny_fov_clustered_corners(FE_TONEAREST, &st0, &r);
    ck_assert_int_eq(st0, SWARP_INFO_PLAN_BUDGET_UNMET);
    ck_assert_uint_eq(r.plane_reason[0], SWARP_PLAN_PLANE_LIXEL_REFUSED);
    ck_assert_uint_eq(r.lixel_count, 0);
    for (int m = 1; m < 4; ++m) {
        plan_tiny_fov_clustered_corners(modes[m], &st, &p);
        ck_assert_int_eq(st, st0);
        same_plan(&p, &r, m);
    }
}
END_TEST

/* ---- the plan's numbers stay finite and inside the documented range ------- */

static swarp_scene_needs needs_at(double near, double far) {
    swarp_scene_needs n;
    memset(&n, 0, sizeof n);
    n.camera.eye = (swarp_vec3){0, 2, 0};
    n.camera.dir = (swarp_vec3){0, 0, -1};
    n.camera.up = (swarp_vec3){0, 1, 0};
    n.camera.fovy = 1.0;
    n.camera.aspect = 4.0 / 3.0;
    n.camera.z_near = near;
    n.camera.z_far = far;
    n.light.type = SWARP_LIGHT_DIRECTIONAL;
    n.light.direction = (swarp_vec3){0, 0, 1};
    return n;
}

/* every double of a plan a success writes is finite, n' apart (+inf means
 * uniform, header) */
static void plan_finite(const swarp_plan_result* p) {
    const double v[] = {p->gamma, p->z_near, p->z_far, p->max_mx, p->max_mz, p->max_error, p->error_area,
                        p->lixel_error, p->filter_width, p->filter_exponent_pos, p->filter_exponent_neg,
                        p->texels, p->cost_ns};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i) ck_assert_msg(isfinite(v[i]), "field %zu: %g", i, v[i]);
    for (uint32_t i = 0; i < p->split_count; ++i) {
        ck_assert(isfinite(p->splits[i]) && isfinite(p->split_max_mx[i]) && isfinite(p->split_max_mz[i]));
        ck_assert(isfinite(p->n_prime[i]) || p->n_prime[i] == INFINITY);
    }
}

/* near 1e-300 (and the smallest subnormal), far 1e4, light along the view,
 * map_resolution 1 (16), 2 passes: m_x and m_z are finite (about 1e155 and
 * 1e165) but their product is not; error_area was +inf.  It is the product
 * where that is representable and DBL_MAX where not (log of the product
 * above log DBL_MAX: an evaluation that does not overflow). */
START_TEST(plan_error_area_finite_when_product_overflows) {
    const double nears[2] = {1e-300, 4.94e-324};
    const uint32_t res[2] = {1, 16};
    for (int k = 0; k < 2; ++k) {
        swarp_scene_needs n = needs_at(nears[k], 1e4);
        swarp_budget b;
        memset(&b, 0, sizeof b);
        b.map_resolution = res[k];
        b.max_passes = 2;
        swarp_plan_result p;
        ck_assert_int_eq(swarp_plan(&n, &b, &p), SWARP_INFO_PLAN_BUDGET_UNMET);
        plan_finite(&p);
        ck_assert(log(p.max_mx) + log(p.max_mz) > log(DBL_MAX));
        ck_assert(p.error_area == DBL_MAX);
    }
    /* a representable product is the product itself */
    swarp_scene_needs n = needs_at(1.0, 100.0);
    swarp_plan_result p;
    ck_assert(!swarp_status_is_error(swarp_plan(&n, NULL, &p)));
    ck_assert(p.error_area == p.max_mx * p.max_mz);
}
END_TEST

/* The view depth range a plan reports lies inside the camera's [near, far]
 * (the adjustment [RHS] §3.3.1 only narrows it), contains the depth range
 * of the box within the view (computed here from the box corners), is not
 * empty, and the splits run over it.  A 1-ulp camera range with a box
 * around the camera was widened to near (1 + 1e-6), past far. */
static void plan_range_ok(const swarp_scene_needs* n) {
    swarp_plan_result p;
    swarp_status st = swarp_plan(n, NULL, &p);
    ck_assert_msg(!swarp_status_is_error(st), "%s", swarp_status_name(st));
    plan_finite(&p);
    ck_assert_msg(p.z_near >= n->camera.z_near && p.z_far <= n->camera.z_far,
                  "range [%.17g, %.17g] outside the camera's [%.17g, %.17g]", p.z_near, p.z_far,
                  n->camera.z_near, n->camera.z_far);
    ck_assert(p.z_far > p.z_near);
    ck_assert(p.splits[0] == p.z_near && p.splits[p.split_count] == p.z_far);
    /* depth of the box corners along the view (0, 0, -1) from the eye */
    long double dmin = INFINITY, dmax = -INFINITY;
    for (int k = 0; k < 2; ++k) {
        long double d = -((long double)(k ? n->scene_box.max.z : n->scene_box.min.z) - n->camera.eye.z);
        dmin = fminl(dmin, d), dmax = fmaxl(dmax, d);
    }
    dmin = fmaxl(dmin, n->camera.z_near), dmax = fminl(dmax, n->camera.z_far);
    ck_assert(p.z_near <= dmin && p.z_far >= dmax);
}

START_TEST(plan_range_inside_camera_range) {
    /* a 1-ulp view range, box around the camera */
    swarp_scene_needs n = needs_at(1.0, nextafter(1.0, 2.0));
    n.scene_box = (swarp_aabb){{-50, -1, -200}, {50, 10, 50}};
    plan_range_ok(&n);
    /* a box flat across the view inside the range: widened, but inside */
    n = needs_at(1.0, 100.0);
    n.scene_box = (swarp_aabb){{-50, -1, -5}, {50, 10, -5}};
    plan_range_ok(&n);
    /* flat exactly at the far plane: the width goes below it */
    n.scene_box = (swarp_aabb){{-50, -1, -100}, {50, 10, -100}};
    plan_range_ok(&n);
    /* flat at the near plane of a range narrower than the widening */
    n = needs_at(1.0, 1.0 + 1e-9);
    n.scene_box = (swarp_aabb){{-50, -1, -1}, {50, 10, -1}};
    plan_range_ok(&n);
    /* ranges of 1 .. 10^4 ulps at random scales, box around the camera */
    uint64_t seed = 20;
    for (int i = 0; i < 2000; ++i) {
        double near = exp(tu_uniform(&seed, log(1e-6), log(1e6)));
        double far = near;
        int ulps = 1 + (int)tu_uniform(&seed, 0, 1e4);
        for (int k = 0; k < ulps; ++k) far = nextafter(far, INFINITY);
        n = needs_at(near, far);
        n.scene_box = (swarp_aabb){{-50, -1, -1e7}, {50, 10, 1e7}};
        plan_range_ok(&n);
    }
}
END_TEST

int main(void) {
    Suite* s = suite_create("edges_plan");
    TCase* t = tcase_create("explain");
    tcase_set_timeout(t, 60);
    tcase_add_test(t, explain_text_independent_of_rounding_mode);
    tcase_add_test(t, explain_random_values_every_mode);
    suite_add_tcase(s, t);
    t = tcase_create("cost_limit");
    tcase_add_test(t, plan_cost_above_limit_refused_at_limit_finite);
    suite_add_tcase(s, t);
    t = tcase_create("lixel_check_rounding_mode");
    tcase_add_test(t, lixel_check_tiny_near_every_mode);
    tcase_add_test(t, lixel_check_clustered_corners_every_mode);
    suite_add_tcase(s, t);
    t = tcase_create("plan_range");
    tcase_add_test(t, plan_error_area_finite_when_product_overflows);
    tcase_add_test(t, plan_range_inside_camera_range);
    suite_add_tcase(s, t);
    return tu_run_suite(s) ? 1 : 0;
}
