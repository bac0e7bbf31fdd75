/* PSM in the camera's post-perspective space [KOZ]. */
#include "geometry_internal.h"

swarp_status sw_psm_setup(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B, size_t nb,
                          const swarp_vec3* H, size_t nh, double near, double far,
                          const swarp_setup_options* o, swarp_setup_result* res) {
    (void)cam, (void)light, (void)B, (void)nb, (void)H, (void)nh, (void)near, (void)far, (void)o, (void)res;
    return SWARP_ERR_INVALID_ARGUMENT;
}
