/* Prints sizeof of every public struct and offsetof of selected fields, one
 * "name size" or "name.field offset" per line, for the Python package's
 * layout test (tests/python/test_shadowwarp.py): ctypes lays the structs out
 * from the header's field lists, the C compiler from the header itself. */
#include <stddef.h>
#include <stdio.h>

#include "shadowwarp.h"

#define S(t) printf("%s %zu\n", #t, sizeof(t))
#define O(t, f) printf("%s.%s %zu\n", #t, #f, offsetof(t, f))

int main(void) {
    S(swarp_vec3); S(swarp_vec4); S(swarp_mat4); S(swarp_plane); S(swarp_camera); S(swarp_light);
    S(swarp_aabb); S(swarp_measure_res); S(swarp_texel_error); S(swarp_measured_error);
    S(swarp_measure_options); S(swarp_setup_options); S(swarp_setup_result); S(swarp_warp_options);
    S(swarp_warp_info); S(swarp_error_config); S(swarp_atlas_info); S(swarp_atlas_tile);
    S(swarp_stabilize_options); S(swarp_stabilize_report); S(swarp_bias_map);
    S(swarp_split_options); S(swarp_cascade_options); S(swarp_cascade_split);
    S(swarp_cascade_result); S(swarp_lloyd_options); S(swarp_lloyd_report); S(swarp_polyhedron);
    S(swarp_lixel_options); S(swarp_lixel_info); S(swarp_lixel_rect);
    S(swarp_lixel_restrict_options); S(swarp_scene_needs); S(swarp_budget); S(swarp_plan_result);
    S(swarp_camera_from_info);
    S(swarp_plan_chain); S(swarp_cube_options); S(swarp_cube_face); S(swarp_mindepth_options);
    O(swarp_camera, fovy); O(swarp_light, direction); O(swarp_light, cone_angle);
    O(swarp_setup_options, n_user); O(swarp_setup_options, slideback); O(swarp_setup_options, min_depth);
    O(swarp_setup_result, matrix); O(swarp_setup_result, n_eye); O(swarp_setup_result, point_count);
    O(swarp_cascade_options, kernel_world_size); O(swarp_cascade_options, warp_per_split);
    O(swarp_cascade_split, tile); O(swarp_cascade_split, status); O(swarp_cascade_result, atlas);
    O(swarp_measured_error, at); O(swarp_measured_error, samples); O(swarp_texel_error, flags);
    O(swarp_setup_result, measured); O(swarp_cascade_split, measured); O(swarp_cascade_result, measured);
    O(swarp_setup_options, skip_measure);
    O(swarp_polyhedron, planes); O(swarp_polyhedron, face_vertices);
    O(swarp_lixel_info, conditioning); O(swarp_scene_needs, soft_width); O(swarp_scene_needs, planes);
    O(swarp_budget, time_budget_ns); O(swarp_plan_result, gamma); O(swarp_plan_result, max_mx);
    O(swarp_plan_result, lixel_error); O(swarp_plan_result, texels); O(swarp_plan_result, plane_count);
    O(swarp_cube_face, view_proj); O(swarp_stabilize_report, level_x); O(swarp_lloyd_report, max_shift);
    return 0;
}
