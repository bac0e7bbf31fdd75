/* Prints sizeof and selected offsetof of the public structs, one
 * "name size" or "name.field offset" per line, for the Python binding's
 * layout test (tests/python/test_shadowwarp.py). */
#include <stddef.h>
#include <stdio.h>

#include "shadowwarp.h"

#define S(t) printf("%s %zu\n", #t, sizeof(t))
#define O(t, f) printf("%s.%s %zu\n", #t, #f, offsetof(t, f))

int main(void) {
    S(swarp_vec3); S(swarp_vec4); S(swarp_mat4); S(swarp_aabb); S(swarp_plane);
    S(swarp_camera); S(swarp_light); S(swarp_error_config);
    S(swarp_setup_options); S(swarp_setup_result); S(swarp_split_options);
    S(swarp_lixel_options); S(swarp_lixel_info); S(swarp_scene_needs); S(swarp_budget);
    S(swarp_plan_result);
    O(swarp_setup_options, n_user); O(swarp_setup_options, slideback); O(swarp_setup_options, min_depth);
    O(swarp_setup_result, n_eye); O(swarp_setup_result, point_count);
    O(swarp_lixel_info, conditioning); O(swarp_scene_needs, soft_width); O(swarp_scene_needs, planes);
    O(swarp_budget, time_budget_ns); O(swarp_plan_result, gamma); O(swarp_plan_result, max_mx);
    O(swarp_plan_result, lixel_error); O(swarp_plan_result, texels); O(swarp_plan_result, plane_count);
    return 0;
}
