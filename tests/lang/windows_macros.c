/* The header compiled as C11 under <windows.h>'s macros (windows_macros.h). */
#include "windows_macros.h"

#include <stddef.h>

_Static_assert(sizeof(swarp_camera) == WM_CAMERA_SIZE, "swarp_camera layout");
_Static_assert(offsetof(swarp_camera, z_far) == 3 * 24 + 3 * 8, "swarp_camera.z_far offset");
_Static_assert(sizeof(swarp_error_config) == WM_ERROR_CONFIG_SIZE, "swarp_error_config layout");
_Static_assert(offsetof(swarp_cascade_split, z_far) == 8, "swarp_cascade_split.z_far offset");

int main(void) {
    swarp_camera cam = {{0, 2, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 1.5, 1.0, 100.0, {0, 0, 0, 0}};
    return cam.z_far > cam.z_near && swarp_status_is_error(SWARP_OK) == 0 ? 0 : 1;
}
