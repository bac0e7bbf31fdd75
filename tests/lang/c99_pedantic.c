/* The public header compiles as C99 with -Wall -Wextra -Wpedantic -Werror
 * (built with c_std=c99, warning_level=3, werror=true by tests/meson.build),
 * and a C99 caller links and runs.  This caller does NOT define
 * SWARP_EXPERIMENTAL_API: it sees the stable API only (tests/lang/
 * cpp_caller.cpp compiles the experimental half), and the one-call setup of
 * the header's step-by-step works with it. */
#include "shadowwarp.h"

#include <stdio.h>
#include <string.h>

/* the experimental section stays hidden without the define */
#if defined(SWARP_POLY_MAX_FACES) || defined(SWARP_FOLLOW_KAPPA) || defined(SWARP_PLAN_MAX_SPLITS) || \
    defined(SWARP_CUBE_MAX_FACES) || defined(SWARP_MINDEPTH_SCRATCH) || defined(SWARP_LIXEL_DEFAULT_MAX_SIZE)
#error "experimental declarations visible without SWARP_EXPERIMENTAL_API"
#endif

static int one_map(void) {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb scene;
    swarp_setup_options opt;
    swarp_setup_result r;
    swarp_status s;
    float m[16];
    memset(&cam, 0, sizeof cam);
    memset(&light, 0, sizeof light);
    memset(&opt, 0, sizeof opt);
    cam.eye.y = 2.0;
    cam.dir.z = -1.0;
    cam.up.y = 1.0;
    cam.fovy = 1.0;
    cam.aspect = 16.0 / 9.0;
    cam.z_near = 0.5;
    cam.z_far = 100.0;
    light.direction.x = 0.3;
    light.direction.y = -1.0;
    light.direction.z = 0.2;
    scene.min.x = -50.0; scene.min.y = 0.0; scene.min.z = -120.0;
    scene.max.x = 50.0; scene.max.y = 10.0; scene.max.z = 10.0;
    s = swarp_setup(&cam, &light, &scene, &opt, &r, NULL, 0, NULL);
    if (swarp_status_is_error(s)) return 1;
    return swarp_mat4_to_float(&r.matrix, m) != SWARP_OK;
}

int main(void) {
    swarp_mat4 a, r;
    int i;
    for (i = 0; i < 16; ++i) a.m[i] = (i % 5 == 0) ? 4.0 : 0.0;
    if (swarp_mat4_invert(&a, &r) != SWARP_OK || r.m[0] != 0.25) return 1;
    if (strcmp(swarp_version_string(), SWARP_VERSION_STRING) != 0) return 2;
    if (!swarp_status_is_error(SWARP_ERR_NULL_POINTER) || swarp_status_is_error(SWARP_INFO_WARP_UNIFORM)) return 3;
    if (one_map() != 0) return 4;
    printf("C99 caller ok (%s)\n", swarp_version_string());
    return 0;
}
