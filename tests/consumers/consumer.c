/* The smallest program an engine would write against an INSTALLED
 * libshadowwarp: header from the include dir, library from the lib dir.
 * Built by tests/consumers/run.sh via pkg-config, CMake and as a meson
 * subproject.  Exits 0 and prints one line when everything links and runs.
 * It does not define SWARP_EXPERIMENTAL_API: the stable API alone must
 * build and work, the one-call setup included. */
#include <shadowwarp.h>
#include <stdio.h>
#include <string.h>

#if defined(SWARP_POLY_MAX_FACES) || defined(SWARP_PLAN_MAX_SPLITS)
#error "experimental declarations visible without SWARP_EXPERIMENTAL_API"
#endif

/* one directional shadow map, as in the header's step-by-step */
static int one_map(void) {
    swarp_camera cam = {{0, 2, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 16.0 / 9.0, 0.5, 100.0, {0}};
    swarp_light light = {SWARP_LIGHT_DIRECTIONAL, 0, {0.3, -1.0, 0.2}, {0, 0, 0}, 0.0, {0}};
    swarp_aabb scene = {{-50, 0, -120}, {50, 10, 10}};
    swarp_setup_result r;
    float m[16];
    if (swarp_status_is_error(swarp_setup(&cam, &light, &scene, NULL, &r, NULL, 0, NULL))) return 1;
    return swarp_mat4_to_float(&r.matrix, m) != SWARP_OK;
}

int main(void) {
    swarp_mat4 a, inv, prod;
    for (int i = 0; i < 16; ++i) a.m[i] = (i % 5 == 0) ? 2.0 : 0.0; /* 2 * I */
    a.m[12] = 3.0;                                                 /* translation */
    if (swarp_mat4_invert(&a, &inv) != SWARP_OK) return 2;
    if (swarp_mat4_mul(&a, &inv, &prod) != SWARP_OK) return 3;
    for (int i = 0; i < 16; ++i) {
        double want = (i % 5 == 0) ? 1.0 : 0.0;
        double d = prod.m[i] - want;
        if (d > 1e-12 || d < -1e-12) return 4;
    }
    if (swarp_version_number() != SWARP_VERSION_NUMBER) return 5;
    if (strcmp(swarp_status_name(SWARP_ERR_CAPACITY), "SWARP_ERR_CAPACITY") != 0) return 6;
    if (one_map() != 0) return 7;
    printf("consumer ok: libshadowwarp %s\n", swarp_version_string());
    return 0;
}
