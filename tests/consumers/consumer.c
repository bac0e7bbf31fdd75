/* The smallest program an engine would write against an INSTALLED
 * libshadowwarp: header from the include dir, library from the lib dir.
 * Built by tests/consumers/run.sh via pkg-config, CMake and as a meson
 * subproject.  Exits 0 and prints one line when everything links and runs. */
#include <shadowwarp.h>
#include <stdio.h>
#include <string.h>

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
    printf("consumer ok: libshadowwarp %s\n", swarp_version_string());
    return 0;
}
