/* Regression tests of issue inputs, named by the property they pin: a
 * success status of swarp_setup means every receiver of V ∩ S is in the map
 * and every caster between it and the light in the depth range (checked by
 * tests/support/coverage_check.h against V ∩ S found by brute force), or the
 * library refuses.  Each input failed before its fix (noted per case). */
#include <float.h>
#include <stdio.h>
#include <string.h>

#include "coverage_check.h"
#include "shadowwarp.h"

static int failures;

static swarp_camera issue_camera(double near) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = (swarp_vec3){0, 2, 0};
    c.dir = (swarp_vec3){0, -0.3, -1};
    c.up = (swarp_vec3){0, 1, 0};
    c.fovy = 1, c.aspect = 16.0 / 9, c.z_near = near, c.z_far = 100;
    return c;
}

/* success means covered; want_error: the input must be refused */
static void success_means_covered(const char* name, swarp_camera c, swarp_light L, swarp_aabb S, int tech) {
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = (swarp_technique)tech;
    swarp_setup_result r;
    swarp_status s = swarp_setup(&c, &L, &S, &o, &r, NULL, 0, NULL);
    if (swarp_status_is_error(s)) return;
    cc_result q = cc_check(&c, c.z_near, c.z_far, &L, &S, &r.matrix, SWARP_DEPTH_NEG_ONE_TO_ONE, 0, s, 9, 17, 200, 1);
    int ok = cc_ok(&q) && r.view_near >= c.z_near && r.view_far <= c.z_far;
    if (!ok) {
        ++failures;
        printf("FAIL %s technique %d: %s ", name, tech, swarp_status_name(s));
        cc_print(stdout, &q);
        printf(" view [%a, %a]\n", r.view_near, r.view_far);
    }
}

int main(void) {
    swarp_light D;
    memset(&D, 0, sizeof D);
    D.type = SWARP_LIGHT_DIRECTIONAL;
    D.direction = (swarp_vec3){0.3, -1, 0.2};
    const swarp_aabb S0 = {{-50, -1, -200}, {50, 10, 50}};
    /* huge box (before: LiSPSM casters out of the depth range from
     * max = 1e12/1e13, all techniques from 1e19): the sweep of H went
     * 2 diag(S) far */
    static const double big[] = {1e12, 1e13, 1e19, FLT_MAX, DBL_MAX};
    for (int k = 0; k < 3; ++k)
        for (int b = 0; b < 5; ++b)
            for (int t = 1; t <= 3; ++t) {
                swarp_aabb S = S0;
                (&S.max.x)[k] = big[b];
                success_means_covered("huge_box_casters_in_depth_range", issue_camera(1), D, S, t);
            }
    /* the light straight down onto an unbounded box: the sweep is that long
     * (before: DBL_MAX cut to DBL_MAX/4 silently; now CASTERS_CLAMPED) */
    swarp_light Dn = D;
    Dn.direction = (swarp_vec3){0, -1, 0};
    for (int b = 0; b < 5; ++b)
        for (int t = 1; t <= 2; ++t) {
            swarp_aabb S = S0;
            S.max.y = big[b];
            success_means_covered("unbounded_sweep_clamped_casters_reported", issue_camera(1), Dn, S, t);
        }
    /* spot near and at the eye (before: light_near 4.32, casters at depth
     * -6.96; at the eye WARP_UNIFORM / OK with casters clipped) */
    swarp_light P;
    memset(&P, 0, sizeof P);
    P.type = SWARP_LIGHT_POINT;
    P.position = (swarp_vec3){0, 2.5, 0.5};
    P.direction = (swarp_vec3){0, -0.3, -1};
    P.cone_angle = 0.7;
    for (int t = 1; t <= 3; ++t) success_means_covered("spot_near_eye_clips_only_near_plane", issue_camera(0.1), P, S0, t);
    P.position = (swarp_vec3){0, 2, 0};
    for (int t = 1; t <= 3; ++t) success_means_covered("spot_at_eye_clips_only_near_plane", issue_camera(0.1), P, S0, t);
    /* PSM, omni light inside the box (before: SWARP_OK, casters at -16) */
    swarp_light O;
    memset(&O, 0, sizeof O);
    O.type = SWARP_LIGHT_POINT;
    O.position = (swarp_vec3){0, 6, -3};
    for (int t = 1; t <= 3; ++t) success_means_covered("omni_inside_box_covered_or_refused", issue_camera(1), O, S0, t);
    {
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = SWARP_TECHNIQUE_PSM;
        swarp_setup_result r;
        swarp_camera c = issue_camera(1);
        swarp_status s = swarp_setup(&c, &O, &S0, &o, &r, NULL, 0, NULL);
        if (s != SWARP_ERR_LIGHT_INSIDE_BODY) {
            ++failures;
            printf("FAIL psm_omni_inside_box_refused: %s\n", swarp_status_name(s));
        }
    }
    /* PSM for extreme frusta (before: a light ray spread 0.12 / 0.014 /
     * 0.12 NDC with SWARP_OK) */
    for (int t = 1; t <= 3; ++t) {
        swarp_camera c = issue_camera(1);
        c.fovy = 1e-9;
        success_means_covered("fovy_1e-9_projects_along_light", c, D, S0, t);
        c = issue_camera(1);
        c.aspect = 1e-9;
        success_means_covered("aspect_1e-9_projects_along_light", c, D, S0, t);
        c = issue_camera(1);
        c.z_far = 1 * (1 + 1e-9);
        success_means_covered("far_near_1e-9_projects_along_light", c, D, S0, t);
    }
    /* a 1-ulp view range (before: view_far 1e-9 past far) */
    for (int t = 1; t <= 2; ++t) {
        swarp_camera c = issue_camera(1);
        c.z_far = nextafter(1.0, 2.0);
        success_means_covered("one_ulp_range_view_range_inside_camera", c, D, S0, t);
    }
    printf("test_covered: %d failures\n", failures);
    return failures ? 1 : 0;
}
