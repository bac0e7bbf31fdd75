/* Internal helpers of the geometry stage (poly, body, focus, warp, psm,
 * setup).  Not installed, not exported. */
#ifndef SWARP_GEOMETRY_INTERNAL_H
#define SWARP_GEOMETRY_INTERNAL_H

#include "common/swarp_internal.h"

static inline double sw_max(double a, double b) { return a > b ? a : b; }
static inline double sw_min(double a, double b) { return a < b ? a : b; }

/* The argument checks (sw_check_camera, sw_check_light, sw_check_box, ...)
 * are src/common/check.c, declared in common/swarp_internal.h. */

/* Orthonormal camera basis: f (forward), r (right), u (up). */
void sw_camera_basis(const swarp_camera* cam, swarp_vec3* f, swarp_vec3* r, swarp_vec3* u);

/* Internal polyhedron operations (no argument checks). */
void sw_poly_from_corners(const swarp_vec3 c[8], swarp_polyhedron* out);
/* V for [near, far] of a camera its caller has checked (shape, 0 < near < far):
 * the checks of swarp_poly_from_camera_range are not repeated */
swarp_status sw_poly_from_frustum(const swarp_camera* cam, double near, double far, swarp_polyhedron* out);
/* the same frustum's 6 planes (outward unit normals; left, right, bottom,
 * top, near, far) */
void sw_frustum_planes(const swarp_camera* cam, double near, double far, swarp_plane pl[6]);
swarp_status sw_poly_clip(const swarp_polyhedron* in, swarp_vec3 n, double d,
                          swarp_polyhedron* out);
swarp_status sw_poly_clip_box(const swarp_polyhedron* in, const swarp_aabb* box,
                              swarp_polyhedron* out);
/* the same with the planes in a given order (plane k: axis k / 2, the max
 * side when k is odd) */
swarp_status sw_poly_clip_box_order(const swarp_polyhedron* in, const swarp_aabb* box, const uint8_t order[6],
                                    swarp_polyhedron* out);
double sw_poly_scale(const swarp_polyhedron* p);
/* merge near-duplicate vertices (vertices from index first_new on are
 * compared with all earlier ones; those before are known to be apart),
 * drop degenerate faces and unreferenced vertices */
void sw_poly_finalize(swarp_polyhedron* p, uint32_t first_new, double scale /* 0: compute */);
/* copy only the used parts */
void sw_poly_copy(const swarp_polyhedron* in, swarp_polyhedron* out);
/* out := p with every byte beyond the counts zero (p may equal out) */
void sw_poly_publish(const swarp_polyhedron* p, swarp_polyhedron* out);
/* a caller's polyhedron: vertex and face counts within capacity
 * (SWARP_ERR_INVALID_ARGUMENT) ... */
swarp_status sw_poly_check_counts(const swarp_polyhedron* in);
/* ... then finite vertices (SWARP_ERR_NON_FINITE), loops within capacity
 * and indices below vertex_count (SWARP_ERR_INVALID_ARGUMENT) */
swarp_status sw_poly_check_contents(const swarp_polyhedron* in);
/* both: a caller's polyhedron, counts within capacity, indices valid, finite */
swarp_status sw_poly_validate(const swarp_polyhedron* in);

/* H = V ∩ S and B without argument checks. */
swarp_status sw_body_h(const swarp_camera* cam, double near, double far, const swarp_aabb* box,
                       swarp_polyhedron* H);
swarp_status sw_body_from_h(const swarp_polyhedron* H, const swarp_light* light,
                            const swarp_aabb* box, swarp_polyhedron* B);
/* the same for an H the clipper built (its face loops are tidy); *clamped:
 * casters beyond SW_SWEEP_REL_MAX times H's size toward a directional
 * light were left out of B (SWARP_INFO_CASTERS_CLAMPED) */
swarp_status sw_body_from_h_clipped(const swarp_polyhedron* H, const swarp_light* light, const swarp_aabb* box,
                                    swarp_polyhedron* B, int* clamped);
/* H = V ∩ S with the eye at the origin (H_rel camera-relative) and its view
 * depth range: the adjusted near/far of swarp_setup (body.c) */
swarp_status sw_body_h_eye(const swarp_camera* cam, double near, double far, const swarp_aabb* box,
                           swarp_polyhedron* H_rel, double* zmin, double* zmax);
/* p + t (vertices and planes) */
void sw_poly_translate(swarp_polyhedron* p, swarp_vec3 t);
/* P ∩ L for a spot light (the square pyramid around its cone), in place */
swarp_status sw_clip_light_pyramid(swarp_polyhedron* P, const swarp_light* light);
/* min/max of dot(p - eye, f) over the vertices */
void sw_depth_range_of(const swarp_polyhedron* P, swarp_vec3 eye, swarp_vec3 f, double* mn,
                       double* mx);

/* Light view (look-at) from origin along forward with the aligned up. */
swarp_status sw_light_origin_axis(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* axis,
                                  swarp_vec3* origin, swarp_vec3* forward);
/* SWARP_ERR_ZERO_VECTOR, SWARP_ERR_OVERFLOW (translation beyond DBL_MAX;
 * *out untouched on error), SWARP_INFO_LIGHT_PARALLEL, SWARP_OK */
swarp_status sw_light_view(const swarp_camera* cam, swarp_vec3 origin, swarp_vec3 forward,
                           swarp_mat4* out);
/* sw_light_view whose rotation near parallel light (the blend zone of
 * SWARP_FOCUS_BLEND_SIN) minimises the area of B's light-plane bounding
 * rectangle (B: nb points; NULL or nb < 3: the aligned up) */
swarp_status sw_light_view_body(const swarp_camera* cam, swarp_vec3 origin, swarp_vec3 forward, const swarp_vec3* B,
                                size_t nb, swarp_mat4* out);
void sw_look_at(swarp_vec3 origin, swarp_vec3 forward_unit, swarp_vec3 up_unit, swarp_mat4* out);
/* the look-at's translation is finite (an origin near DBL_MAX can overflow
 * it: SWARP_ERR_OVERFLOW) */
int sw_look_at_finite(const swarp_mat4* m);
/* the inverse of a rigid look-at (transpose, -R^T t), and the rigidity test */
void sw_rigid_inverse(const swarp_mat4* L, swarp_mat4* out);
int sw_is_rigid(const swarp_mat4* m);
/* fit without checks; returns status (OK, INFO_FLAT_EXTENT, ERR_DEGENERATE);
 * pad (may be NULL): how far each of x/w, y/w, z/w may lie beyond the
 * points' extent (sw_world_rounding_pad) */
swarp_status sw_focus_fit(const swarp_mat4* m, const swarp_vec3* pts, size_t n,
                          const swarp_vec3* zpts, size_t zn, swarp_depth_range dr,
                          const double pad[3], swarp_mat4* out);
/* The rounding a world-space matrix m' = A m T(-eye) adds, at the
 * camera-relative points pts, in the coordinates x/w, y/w, z/w of m (the
 * fit A is affine in them): pad[k] (largest over the points) */
void sw_world_rounding_pad(const swarp_mat4* m, const swarp_vec3* pts, size_t n, swarp_vec3 eye, double pad[3]);

/* LiSPSM warp for points already validated; M maps world to the light space
 * the warp works in (affine light view, or the post-perspective space of a
 * point light: then M_inv is its inverse, used for the eye depths). */
swarp_status sw_warp_lispsm(const swarp_mat4* M, const swarp_mat4* M_inv, const swarp_camera* cam,
                            double near, double far, const swarp_vec3* points, size_t count,
                            const swarp_vec3* nearest, const swarp_warp_options* o, swarp_mat4* out_P,
                            swarp_warp_info* out_info);
static inline swarp_vec3 sw_project(const swarp_mat4* m, swarp_vec3 p) {
    swarp_vec4 h = sw_xform_point(m, p);
    return sw_v3(h.x / h.w, h.y / h.w, h.z / h.w);
}
/* A reference axis for a vector perpendicular to the unit n: the first of
 * x, y, z with |n_k| below this.  One always is (three components of 0.6 or
 * more would make |n| >= 1.04), so ref x n is at least 0.8 long. */
#define SW_REF_AXIS_MAX 0.6

struct sw_follow; /* follow.c, below */
/* PSM [KOZ] for the one call (psm.c); fills light_view, light_proj,
 * matrix, n_eye, n_light, gamma, light_near/far of res. */
swarp_status sw_psm_setup(const swarp_camera* cam, const swarp_light* light, const swarp_vec3* B, size_t nb,
                          const swarp_polyhedron* B_poly, const swarp_vec3* H, size_t nh, double near, double far,
                          const swarp_setup_options* o, const struct sw_follow* fw, swarp_setup_result* res);

/* ---- coherent light frames (follow.c) -----------------------------------
 * The previous frame's light frame for swarp_setup_follow: directional and
 * point lights: the light view's axis and up (world); PSM: the light
 * camera's axis (sign free) and right vector in post-perspective space. */
typedef struct sw_follow {
    swarp_vec3 axis; /* unit */
    swarp_vec3 up;   /* unit, perpendicular to axis */
    swarp_vec3 view; /* the previous view direction (unit) */
} sw_follow;
/* A previous direction projected normal to the new axis is rounding noise
 * below this length (sin of its angle to the axis; a unit vector's rounding
 * is ~1e-16, so its direction would be off by eps/length): the previous
 * axis turned by about 90° or more, nothing to follow. */
#define SW_FOLLOW_PERP_MIN 1e-8
/* h (unit, perpendicular to a) turned about a toward t (unit, perpendicular
 * to a, t·h >= 0) by at most budget radians; *lag = 1 when it stopped short
 * by more than `aligned` radians (sw_follow_aligned_tol) */
swarp_vec3 sw_follow_turn(swarp_vec3 h, swarp_vec3 t, swarp_vec3 a, double budget, double aligned, int* lag);
/* the angle below which h and t count as aligned when they are projections
 * normal to the axis of lengths s_h, s_t (their rounding: eps/s) */
double sw_follow_aligned_tol(double s_h, double s_t);
/* the angle between two unit vectors, accurate at 0 and pi */
double sw_follow_angle(swarp_vec3 a, swarp_vec3 b);
/* the light view from origin along forward whose up follows fw */
swarp_status sw_follow_light_view(const swarp_camera* cam, swarp_vec3 origin, swarp_vec3 forward,
                                  const sw_follow* fw, swarp_mat4* out);
/* LiSPSM along the light frame's y axis, oriented by σ = sign(y·v) (the
 * one call's warp; with y = v̂ it is sw_warp_lispsm); P applies after M */
swarp_status sw_warp_lispsm_oriented(const swarp_mat4* M, const swarp_mat4* M_inv, const swarp_camera* cam, double near,
                            double far, const swarp_vec3* points, size_t count, const swarp_vec3* nearest,
                            const swarp_warp_options* o, swarp_mat4* out_P, swarp_warp_info* out_info);
/* the previous frame of a result, checked (previous_cam may be NULL) */
swarp_status sw_follow_from_result(const swarp_setup_result* previous, const swarp_camera* cam,
                                   const swarp_camera* previous_cam, swarp_technique tech, sw_follow* out);

#endif
