// The header compiled as C++17 under <windows.h>'s macros (windows_macros.h).
#include "windows_macros.h"

#include <cstddef>

static_assert(sizeof(swarp_camera) == WM_CAMERA_SIZE, "swarp_camera layout");
static_assert(offsetof(swarp_camera, z_far) == 3 * 24 + 3 * 8, "swarp_camera.z_far offset");
static_assert(sizeof(swarp_error_config) == WM_ERROR_CONFIG_SIZE, "swarp_error_config layout");

int main() {
    swarp_camera cam{};
    cam.z_near = 1.0;
    cam.z_far = 100.0;
    return cam.z_far > cam.z_near ? 0 : 1;
}
