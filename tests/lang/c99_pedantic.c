/* The public header compiles as C99 with -Wall -Wextra -Wpedantic -Werror
 * (built with c_std=c99, warning_level=3, werror=true by tests/meson.build),
 * and a C99 caller links and runs. */
#include "shadowwarp.h"

#include <stdio.h>
#include <string.h>

int main(void) {
    swarp_mat4 a, r;
    int i;
    for (i = 0; i < 16; ++i) a.m[i] = (i % 5 == 0) ? 4.0 : 0.0;
    if (swarp_mat4_invert(&a, &r) != SWARP_OK || r.m[0] != 0.25) return 1;
    if (strcmp(swarp_version_string(), SWARP_VERSION_STRING) != 0) return 2;
    if (!swarp_status_is_error(SWARP_ERR_NULL_POINTER) || swarp_status_is_error(SWARP_INFO_WARP_UNIFORM)) return 3;
    printf("C99 caller ok (%s)\n", swarp_version_string());
    return 0;
}
