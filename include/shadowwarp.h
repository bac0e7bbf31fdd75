/*
 * shadowwarp.h -- libshadowwarp, the one public header.
 *
 * libshadowwarp computes the matrices and parameters of warped, partitioned
 * and filtered shadow maps -- uniform, LiSPSM and PSM light matrices,
 * cascades with their atlas, flicker reduction and bias, and the shading
 * maths of VSM-family filters -- together with the analytic error model that
 * says how good a choice is.  It is a library of pure functions: the engine
 * renders; this library tells it with which matrices.
 *
 * THE SHORT MANUAL
 * ----------------
 * Storage order   Matrices are swarp_mat4 {double m[16]} in COLUMN-MAJOR order
 *                 (m[col*4 + row]), exactly like OpenGL and cglm: m[12..14] is
 *                 the translation.  Vectors are columns; p' = M p.
 * Handedness      Right-handed world (like OpenGL and cglm).  View space looks
 *                 down -z; "view depth" z is the positive distance along the
 *                 view direction.
 * Depth ranges    Clip-space depth is a runtime choice (swarp_depth_range):
 *                 [-1, 1] (OpenGL, the default) or [0, 1] (D3D, Vulkan, Metal),
 *                 and reversed-Z [1, 0] for the light's map.  An engine's own
 *                 camera matrices (any of these, infinite far, left-handed)
 *                 become a swarp_camera with swarp_camera_from_matrices.
 * Units           Lengths in the caller's world units.  Angles in RADIANS in
 *                 the C API (swtool takes degrees on its command line).
 *                 Resolutions in texels / pixels.
 * Errors          Every function that can fail returns swarp_status.  0 is
 *                 SWARP_OK.  Errors (1..999) leave every output untouched.
 *                 Informational results (1000..1999) mean "success, but note
 *                 this" (e.g. a warp that faded to uniform); outputs are
 *                 written.  swarp_status_string() gives a readable message,
 *                 swarp_status_is_error() tells the ranges apart.  Numbers are
 *                 fixed forever.  A successful call never writes NaN; the only
 *                 non-finite value ever written is +INFINITY for a warp
 *                 parameter n' together with SWARP_INFO_WARP_UNIFORM (n' = inf
 *                 IS the uniform shadow map; the error model accepts it), and
 *                 +INFINITY as the minimum of an empty depth buffer with
 *                 SWARP_INFO_MINDEPTH_EMPTY (experimental min-depth functions).
 * Memory, threads No function allocates, keeps global state, does I/O or
 *                 reads the locale.  Everything is reentrant and thread-safe.
 *                 Output arrays follow (T* out, size_t capacity, size_t*
 *                 out_count): too small a capacity gives SWARP_ERR_CAPACITY
 *                 with the needed count written to *out_count.
 * Options         Option structs follow "zero means default": a zeroed struct
 *                 is a valid request; enum value 0 is always ..._DEFAULT; the
 *                 uint32_t _reserved[] tail must be zero
 *                 (SWARP_ERR_RESERVED_NONZERO otherwise).
 * ABI             Plain structs of doubles and 32-bit enums; no unions,
 *                 bitfields, bool or alignment attributes.  Every enum has a
 *                 _FORCE_I32 sentinel.
 * Stability       Sections 1-7 below and the status list (section 9) are
 *                 the stable API.  Section 8 is experimental: it is declared
 *                 only when the caller defines SWARP_EXPERIMENTAL_API before
 *                 including this header, and its functions and structs may
 *                 still change in a minor release.  The library always
 *                 exports both parts; the statuses of both are in the one
 *                 status list.
 * Papers          Comments cite the papers by tag and equation, e.g.
 *                 [RHS] (3.4):  [RHS] Stingl, "Robust Hard Shadows";
 *                 [GMNPR] Zhang et al., "Generalized Minimum-Norm Perspective
 *                 Shadow Maps"; [KOZ] Kozlov, "Perspective Shadow Maps: Care
 *                 and Feeding"; [LIXEL] Chong & Gortler, "A Lixel for every
 *                 Pixel"; [VSM] Lauritzen, "Rendering Antialiased Shadows
 *                 using Warped Variance Shadow Maps".
 *
 * This header includes only the C standard library and compiles as C99 and
 * as C++.
 *
 * STEP BY STEP: THE CALLS IN THE ORDER AN ENGINE MAKES THEM
 * ---------------------------------------------------------
 * 1. One shadow map per frame (directional light, LiSPSM with n_opt):
 *
 *      swarp_camera cam = {0};   // eye, dir, up, fovy (full, radians), aspect, near, far
 *      swarp_light light = {0};  // type 0 = directional; direction = where light travels
 *      swarp_aabb scene = {0};   // box S around every caster and receiver
 *      swarp_setup_options opt = {0};   // zero = LiSPSM (measured n'), 2048 x 2048 map, depth [-1, 1]
 *      swarp_setup_result r;
 *      swarp_status s = swarp_setup(&cam, &light, &scene, &opt, &r, NULL, 0, NULL);
 *      if (swarp_status_is_error(s))      // r untouched: keep the last frame's matrix
 *          log(swarp_status_string(s));
 *      float m[16];
 *      swarp_mat4_to_float(&r.matrix, m); // world -> light clip space: render the
 *                                         // casters with it; receivers project with
 *                                         // it and divide by w
 *
 * 2. Cascades (split frusta in one atlas, here flicker-free for a moving camera):
 *
 *      swarp_cascade_options co = {0};    // zero = 4 PSSM splits (lambda 0.5),
 *                                         // LiSPSM per split, 2048 x 2048 tiles
 *      co.setup.technique = SWARP_TECHNIQUE_UNIFORM;  // stabilisation needs uniform maps
 *      co.stabilize.mode = SWARP_STABILIZE_SPHERE;
 *      swarp_cascade_result cr;
 *      swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
 *      size_t n;
 *      s = swarp_cascade_setup(&cam, &light, &scene, &co, &cr, sp,
 *                              SWARP_CASCADE_MAX_SPLITS, &n);
 *      // split i: render into sp[i].tile.viewport_* with sp[i].matrix; the
 *      // receiver shader picks i by view depth against cr.splits
 *      // (swarp_cascade_select_depth), samples with sp[i].atlas_matrix, blends
 *      // across borders (swarp_cascade_blend) and biases with
 *      // sp[i].depth_per_world or swarp_bias_normal_offset.  The GLSL twins of
 *      // these functions are in shaders/splits.glsl, those of the filters of
 *      // section 7 in shaders/filtering.glsl.
 *
 * 3. The plan (experimental; when the scene, the budget or the hardware
 *    changes, not per frame):
 *
 *      #define SWARP_EXPERIMENTAL_API   // before #include "shadowwarp.h"
 *      swarp_scene_needs needs = {0};
 *      needs.camera = cam; needs.light = light; needs.scene_box = scene;
 *      needs.camera_moves = 1;
 *      swarp_budget budget = {0};        // zero = 1 screen pixel per texel, 2048 maps
 *      swarp_plan_result plan;
 *      s = swarp_plan(&needs, &budget, &plan);
 *      char text[SWARP_PLAN_EXPLAIN_MAX];
 *      size_t len;
 *      swarp_plan_explain(&plan, text, sizeof text, &len);  // why this chain
 *      // then configure step 1 or 2 with plan.warp, plan.scheme,
 *      // plan.split_count, plan.stabilize and plan.filter.
 *
 * CONTENTS
 * --------
 *   1. Boundary types, swarp_status  6. Cascades: split schemes, atlas,
 *   2. Camera, light, scene box         stabilisation, bias, the one call
 *   3. Status messages, matrix       7. Filtering: VSM, LVSM, EVSM, MSM, PCF
 *      helpers, version              8. Experimental (SWARP_EXPERIMENTAL_API):
 *   4. One shadow map: swarp_setup      polyhedra and bodies, light frames
 *      and its steps; closed-form       that follow, lixel maps, planner,
 *      warp parameters                  cube maps, min-depth near plane
 *   5. Error: measured, and Lloyd's  9. Status codes: every swarp_status
 *      m_x, m_z                         value with its message
 */

#ifndef SHADOWWARP_H
#define SHADOWWARP_H

#include <stddef.h>
#include <stdint.h>

#define SWARP_VERSION_MAJOR 0
#define SWARP_VERSION_MINOR 2
#define SWARP_VERSION_PATCH 0
#define SWARP_VERSION_NUMBER \
    (SWARP_VERSION_MAJOR * 10000 + SWARP_VERSION_MINOR * 100 + SWARP_VERSION_PATCH)
#define SWARP_STRINGIFY_(x) #x
#define SWARP_STRINGIFY(x) SWARP_STRINGIFY_(x)
#define SWARP_VERSION_STRING                                       \
    SWARP_STRINGIFY(SWARP_VERSION_MAJOR) "." SWARP_STRINGIFY(      \
        SWARP_VERSION_MINOR) "." SWARP_STRINGIFY(SWARP_VERSION_PATCH)

#if defined(SWARP_STATIC)
#  define SWARP_API
#elif defined(_WIN32)
#  if defined(SWARP_BUILDING)
#    define SWARP_API __declspec(dllexport)
#  else
#    define SWARP_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) && defined(SWARP_BUILDING)
#  define SWARP_API __attribute__((visibility("default")))
#else
#  define SWARP_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================== */
/* 1. Boundary types                                                        */
/* ======================================================================== */

typedef struct swarp_vec3 { double x, y, z; } swarp_vec3;
typedef struct swarp_vec4 { double x, y, z, w; } swarp_vec4;
/** Column-major 4x4 matrix: element (row r, column c) is m[c*4 + r]. */
typedef struct swarp_mat4 { double m[16]; } swarp_mat4;
/** Plane a*x + b*y + c*z + d = 0; (a, b, c) is the normal (any length > 0). */
typedef struct swarp_plane { double a, b, c, d; } swarp_plane;

/** The status every function returns: 0 (SWARP_OK), an error (1..999) or an
 *  informational result (1000..1999).  Its values are the enumerators of
 *  enum swarp_status_code, listed with their messages in the last section
 *  of this header (9).  It is a 32-bit integer rather than the enum itself
 *  so that the list can close the header (C needs an enum complete before
 *  a prototype may return it) and so that its size is fixed whatever the
 *  compiler's enum options (-fshort-enums). */
typedef int32_t swarp_status;

/** Clip-space depth convention of a projection matrix. */
typedef enum swarp_depth_range {
    SWARP_DEPTH_DEFAULT = 0,          /**< = SWARP_DEPTH_NEG_ONE_TO_ONE */
    SWARP_DEPTH_NEG_ONE_TO_ONE = 1,   /**< OpenGL: z_ndc in [-1, 1] */
    SWARP_DEPTH_ZERO_TO_ONE = 2,      /**< D3D, Vulkan, Metal: z_ndc in [0, 1] */
    /** Reversed-Z: z_ndc in [0, 1] with the light's NEAR plane at 1 and its
     *  far plane at 0 (depth test GREATER, clear to 0).  float32 depth is
     *  densest near 0, which reversed-Z puts at the far end, where 1/w
     *  compresses depth most (docs/engines.md has the table).  Accepted
     *  wherever the light's clip depth appears: every light-matrix builder
     *  (swarp_setup, swarp_focus_fit, stabilisation, swarp_cascade_setup,
     *  swarp_cube_faces, swarp_lixel_factor), the atlas (window depth
     *  d = z_ndc, so d = 1 - d of the [0, 1] map), the bias functions (their
     *  depth biases are what to SUBTRACT from the receiver's d: negative
     *  here, which raises the receiver toward the light under the GREATER
     *  test), swarp_cascade_select_best and swarp_poly_from_inverse_matrix. */
    SWARP_DEPTH_REVERSED_ZERO_TO_ONE = 3,
    SWARP_DEPTH_RANGE_FORCE_I32 = 0x7FFFFFFF
} swarp_depth_range;

/* ======================================================================== */
/* 2. Camera, light and scene box                                           */
/* ======================================================================== */

/** The viewer.  dir and up need not be unit length; up must not be parallel
 *  to dir: every entry point refuses sin(angle(dir, up)) < 1e-9 with
 *  SWARP_ERR_DEGENERATE (no right vector survives the rounding).  fovy is the FULL vertical field of view in radians, in (0, pi);
 *  Θ = fovy/2 in the papers.  aspect = width/height > 0; 0 < near < far. */
typedef struct swarp_camera {
    swarp_vec3 eye;
    swarp_vec3 dir;
    swarp_vec3 up;
    double fovy;
    double aspect;
    double z_near;
    double z_far;
    uint32_t _reserved[4];
} swarp_camera;

typedef enum swarp_light_type {
    SWARP_LIGHT_DEFAULT = 0,      /**< = SWARP_LIGHT_DIRECTIONAL */
    SWARP_LIGHT_DIRECTIONAL = 1,  /**< uses direction */
    SWARP_LIGHT_POINT = 2,        /**< uses position (and cone_angle) */
    SWARP_LIGHT_TYPE_FORCE_I32 = 0x7FFFFFFF
} swarp_light_type;

/** A light.  direction is the direction light TRAVELS (from the light toward
 *  the scene, e.g. (0,-1,0) for the sun at zenith); any length > 0.
 *  cone_angle: point light spot half-angle in radians, in (0, pi/2); 0 means
 *  an omni light (no light frustum L).  Fields the type does not use (a
 *  directional light's position and cone, an omni light's direction) are
 *  not checked. */
typedef struct swarp_light {
    swarp_light_type type;
    uint32_t _reserved0;
    swarp_vec3 direction;
    swarp_vec3 position;
    double cone_angle;
    uint32_t _reserved[4];
} swarp_light;

/** The scene box S: the axis-aligned bounds of every shadow caster and
 *  receiver, world units, min <= max componentwise. */
typedef struct swarp_aabb { swarp_vec3 min, max; } swarp_aabb;

/* ======================================================================== */
/* 3. Status messages, matrix helpers and version                          */
/* ======================================================================== */

/** @brief Readable message for a status; never NULL ("unknown status" for
 *  numbers not in the list).  The string is static. */
SWARP_API const char* swarp_status_string(swarp_status status);
/** @brief Symbolic name of a status ("SWARP_ERR_CAPACITY"); never NULL. */
SWARP_API const char* swarp_status_name(swarp_status status);
/** @brief 1 if status is an error (1..999 or unknown), 0 for SWARP_OK and
 *  informational results (1000..1999). */
SWARP_API int swarp_status_is_error(swarp_status status);

/** @brief SWARP_VERSION_NUMBER of the library actually linked. */
SWARP_API int swarp_version_number(void);
/** @brief SWARP_VERSION_STRING of the library actually linked. */
SWARP_API const char* swarp_version_string(void);

/** @brief Convert a matrix to float for the GPU (column-major kept).
 *  @param[in] m  matrix; @param[out] out 16 floats.
 *  @return SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (an element is NaN/Inf
 *  or overflows float; out untouched), SWARP_OK. */
SWARP_API swarp_status swarp_mat4_to_float(const swarp_mat4* m, float out[16]);

/** @brief r = a * b (column-major). r may alias a or b. */
SWARP_API swarp_status swarp_mat4_mul(const swarp_mat4* a, const swarp_mat4* b, swarp_mat4* r);

/** Largest condition number swarp_mat4_invert accepts: 2^47 (about 1.4e14),
 *  where kappa * DBL_EPSILON = 1/32 and the inverse keeps only a few correct
 *  bits.  kappa = |a'|_inf |a'^-1|_inf (row-sum norms) of a' = R a C, the
 *  matrix with every row and then every column scaled by a power of two to a
 *  largest entry in [1, 2): badly scaled but well-conditioned matrices
 *  (diag(1e30, 1, 1, 1e-30)) are accepted. */
#define SWARP_MAT4_MAX_CONDITION 0x1p47

/** @brief r = inverse(a), Gauss-Jordan with partial pivoting in double.
 *  @param[in] a matrix; @param[out] r its inverse (may alias a).
 *  @return SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (an element of a is
 *  NaN/Inf), SWARP_ERR_SINGULAR (a pivot is 0 or below 1e-300 of the largest
 *  element, the inverse overflows, or the computed condition number exceeds
 *  SWARP_MAT4_MAX_CONDITION: numerically singular; r untouched), SWARP_OK. */
SWARP_API swarp_status swarp_mat4_invert(const swarp_mat4* a, swarp_mat4* r);

/** @brief Apply a matrix to a point (w = 1) and return the homogeneous result. */
SWARP_API swarp_status swarp_mat4_transform(const swarp_mat4* m, const swarp_vec3* p, swarp_vec4* out);

/* ------------------------------------------------------------------------ */
/* A camera from an engine's view and projection matrices                   */
/* ------------------------------------------------------------------------ */

/** How the 16 numbers of an engine's matrices are laid out and which way its
 *  view space looks.  The numbers of a row-vector matrix stored row by row
 *  (p' = p M: DirectXMath, D3DX, Unreal's FMatrix) are the numbers of the
 *  column-vector matrix M^T stored column by column, so those engines pass
 *  their matrices as they are with ..._RH or ..._LH; only a column-vector
 *  matrix written row by row (HLSL row_major constant buffers, Eigen
 *  RowMajor) needs ..._TRANSPOSED. */
typedef enum swarp_matrix_convention {
    SWARP_MATRIX_DEFAULT = 0,           /**< = SWARP_MATRIX_RH */
    /** Right-handed view space looking down -z, element (r, c) at m[c*4 + r]
     *  of the column-vector matrix: OpenGL, cglm, glm, Godot, Filament,
     *  Unity's worldToCameraMatrix/projectionMatrix, DirectXMath ...RH. */
    SWARP_MATRIX_RH = 1,
    /** Left-handed view space looking down +z, same storage: DirectXMath
     *  and D3DX ...LH, Unreal. */
    SWARP_MATRIX_LH = 2,
    SWARP_MATRIX_RH_TRANSPOSED = 3,     /**< RH, element (r, c) at m[r*4 + c] */
    SWARP_MATRIX_LH_TRANSPOSED = 4,     /**< LH, element (r, c) at m[r*4 + c] */
    SWARP_MATRIX_CONVENTION_FORCE_I32 = 0x7FFFFFFF
} swarp_matrix_convention;

/** What swarp_camera_from_matrices recognised in the projection. */
typedef struct swarp_camera_from_info {
    uint32_t reversed_z;   /**< 1: depth falls from near to far (near at the top of the range) */
    uint32_t infinite_far; /**< 1: the far plane is at infinity (z_far from the scene box) */
    double off_center_x;   /**< NDC shift of the frustum's centre (P[0][2]/P[3][2]): 0 for */
    double off_center_y;   /**<   a symmetric frustum; TAA jitter, VR and tiles shift it */
} swarp_camera_from_info;

/** Largest stray term swarp_camera_from_matrices ignores: an entry a
 *  perspective projection has zero (x from y, z from x or y, w from x, y or
 *  1, a clip-space translation) may move NDC by at most this over the
 *  frustum.  float32 matrices round their entries at 6e-8 relative; 1e-6 of
 *  the NDC range is below one texel of a 65536-texel map. */
#define SWARP_CAMERA_STRAY_NDC 1e-6
/** Rows of the view matrix's 3x3 part must be orthonormal to this (a
 *  float32 rotation is to about 1e-7); the camera itself is solved exactly
 *  (eye = -R^-1 t), so the tolerance only decides what is a rotation. */
#define SWARP_CAMERA_RIGID_TOL 1e-5

/** @brief The swarp_camera of an engine's view and projection matrices.
 *
 *  The projection must be a perspective one: w = -k z_view (k > 0 after the
 *  convention's handedness), x and y scaled (a flipped axis, like Vulkan's y
 *  flip, leaves the frustum unchanged and is accepted) and possibly shifted,
 *  z_ndc = -A + B/d at view depth d.  depth_range says which clip depth the
 *  graphics API uses ([-1, 1]: SWARP_DEPTH_NEG_ONE_TO_ONE or DEFAULT; [0, 1]:
 *  SWARP_DEPTH_ZERO_TO_ONE or SWARP_DEPTH_REVERSED_ZERO_TO_ONE): the matrix
 *  alone cannot tell them apart (every forward matrix is valid in both, with
 *  other planes).  Whether depth runs forward or reversed is read from the
 *  sign of B; z_near and z_far are the depths whose NDC are the ends of the
 *  range.  A far end that depth reaches only at infinity (A = -1 forward,
 *  A = 0 reversed [0, 1], to SWARP_CAMERA_STRAY_NDC) is an infinite far
 *  plane: the view is then bounded by the scene box as [RHS] §3.3.1 bounds
 *  it, z_far = the largest view depth of the box's corners (H = V ∩ S lies
 *  in S), and the status is SWARP_INFO_CAMERA_FAR_FROM_SCENE.  An off-centre
 *  frustum (P[0][2], P[1][2] != 0) becomes the smallest symmetric frustum
 *  containing it: tan(fovy/2) = (1 + |c_y|) / |s_y|, aspect likewise.
 *
 *  @param[in] view        world -> view (rigid: a rotation and a translation)
 *  @param[in] projection  view -> clip
 *  @param[in] convention  storage and handedness of both matrices
 *  @param[in] depth_range the API's clip depth ([-1, 1] or [0, 1])
 *  @param[in] scene       box S of casters and receivers; needed only when
 *                         the far plane is infinite (may be NULL otherwise;
 *                         checked when given)
 *  @param[out] out_cam    eye, dir, up, fovy, aspect, z_near, z_far
 *  @param[out] out_info   what was recognised (may be NULL)
 *  @return SWARP_OK, SWARP_INFO_CAMERA_FAR_FROM_SCENE; errors leave outputs
 *          untouched: SWARP_ERR_NULL_POINTER, SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_SINGULAR (view's 3x3 part or the
 *          projection's x, y or depth scale zero), SWARP_ERR_CAMERA_MIRRORED,
 *          SWARP_ERR_CAMERA_VIEW_NOT_RIGID, SWARP_ERR_CAMERA_NOT_PERSPECTIVE
 *          (orthographic included), SWARP_ERR_NEAR_FAR (near <= 0, or the
 *          far plane behind the eye), SWARP_ERR_CAMERA_FAR_UNBOUNDED, the
 *          scene box's errors (SWARP_ERR_BOX_INVERTED, ...), and
 *          SWARP_ERR_BODY_EMPTY (an infinite view whose scene box lies
 *          wholly nearer than z_near). */
SWARP_API swarp_status swarp_camera_from_matrices(const swarp_mat4* view, const swarp_mat4* projection,
                                                  swarp_matrix_convention convention,
                                                  swarp_depth_range depth_range, const swarp_aabb* scene,
                                                  swarp_camera* out_cam, swarp_camera_from_info* out_info);

/* ======================================================================== */
/* 4. One shadow map: swarp_setup and its steps                             */
/* ======================================================================== */

/* ------------------------------------------------------------------------ */
/* The measured error: what the results report (functions in section 5)   */
/* ------------------------------------------------------------------------ */

/** Screen and map resolutions the measured error refers to; each > 0
 *  (SWARP_ERR_RESOLUTION).  map_height 0 means map_height = map_width. */
typedef struct swarp_measure_res {
    uint32_t screen_width, screen_height; /**< pixels */
    uint32_t map_width, map_height;       /**< texels */
} swarp_measure_res;

/** What a point's measurement says beside its numbers (bit set). */
typedef enum swarp_texel_flag {
    SWARP_TEXEL_INSIDE = 1u,     /**< the point projects into the map: w > 0, |x|, |y| <= w */
    SWARP_TEXEL_BEHIND_EYE = 2u, /**< planar depth <= 0: not on screen; m_s = m_t = sigma = 0 */
    SWARP_TEXEL_SINGULAR = 4u,   /**< the map's Jacobian is singular there (w <= 0 or its
                                      determinant vanishes): m_s = m_t = sigma = +inf */
    SWARP_TEXEL_FLAG_FORCE_U32 = 0x7FFFFFFF
} swarp_texel_flag;

/** The aliasing error of a world->light-clip matrix at one receiver point X
 *  with unit normal N.  Tangents w_x = normalize(r - (r.N)N) (r the camera's
 *  right vector; the camera's up vector when N is parallel to r) and
 *  w_z = N x w_x span the receiver; J_scr = d(pixel x, y)/d(w_x, w_z) (planar
 *  depth, screen resolution), J_tex = d(texel s, t)/d(w_x, w_z) (the matrix
 *  with its division by w, map resolution), D = J_scr J_tex^-1 (screen pixels
 *  per texel step).  m_s = |D e_s|, m_t = |D e_t| generalise [RHS]'s m_x, m_z
 *  (2.3)/(2.4), which they equal for an overhead light on the view axis with
 *  bisector receivers; sigma is D's largest singular value (the worst
 *  direction): sigma >= max(m_s, m_t), sigma <= hypot(m_s, m_t).  Above 1 the
 *  map undersamples the screen there. */
typedef struct swarp_texel_error {
    double m_s;     /**< screen pixels per texel step along the map's s (clip x) axis */
    double m_t;     /**< screen pixels per texel step along the map's t (clip y) axis */
    double sigma;   /**< largest singular value of D */
    uint32_t flags; /**< swarp_texel_flag bits */
    uint32_t _pad;  /**< written as zero */
} swarp_texel_error;

/** Maximum of the measured error over a receiver region. */
typedef struct swarp_measured_error {
    double max_m_s;     /**< largest m_s over the samples */
    double max_m_t;     /**< largest m_t over the samples */
    double max_sigma;   /**< largest sigma over the samples (+inf: the map is singular
                             somewhere in the region) */
    swarp_vec3 at;      /**< the sample where max_sigma occurs */
    uint32_t samples;   /**< points of the region evaluated (0: not measured) */
    uint32_t outside;   /**< of them, points that do not project into the map */
} swarp_measured_error;

/** Sampling of swarp_measure_max; zero means default. */
typedef struct swarp_measure_options {
    uint32_t grid;        /**< NDC samples per screen axis (default 7, >= 2) */
    uint32_t depths;      /**< depth samples, geometric in [z_near, z_far] (default 9, >= 2) */
    uint32_t refine;      /**< compass-search steps from each seed (default 24) */
    uint32_t _reserved;   /**< must be zero */
} swarp_measure_options;


typedef enum swarp_warp_param {
    SWARP_WARP_PARAM_DEFAULT = 0,   /**< = SWARP_WARP_PARAM_MEASURED */
    SWARP_WARP_PARAM_NOPT = 1,      /**< n_opt [RHS] (3.2), z_0, z_1 from B */
    SWARP_WARP_PARAM_NREPAR = 2,    /**< n_repar(η(γ, Θ)) [RHS] (3.3)-(3.4) */
    SWARP_WARP_PARAM_GMNPR = 3,     /**< λ_GMNPR [GMNPR] (8) times d */
    SWARP_WARP_PARAM_PSEUDO = 4,    /**< pseudo-near/far n_opt [RHS] (4.2) */
    SWARP_WARP_PARAM_USER = 5,      /**< caller's n' (eye units) */
    SWARP_WARP_PARAM_MEASURED = 6,  /**< the n' (n_opt's neighbourhood up to n' = +inf,
                                         uniform) whose matrix has the smallest measured
                                         max sigma over H (swarp_setup, swarp_setup_range,
                                         every cascade split): a bounded golden-section
                                         search in t = n_opt / (n_opt + n') in [0, 1] on H's
                                         vertices and interior points, started at n_opt;
                                         the chosen matrix is never worse than n_opt's nor
                                         than uniform on that set, and with the measurement
                                         on (not skip_measure) also on the full
                                         swarp_measure_max.  Where no region is known
                                         (swarp_setup_points, swarp_warp_lispsm) it is
                                         n_opt.  docs/parameters.md */
    SWARP_WARP_PARAM_FORCE_I32 = 0x7FFFFFFF
} swarp_warp_param;

typedef enum swarp_warp_center {
    SWARP_WARP_CENTER_DEFAULT = 0,        /**< = VIEW_VECTOR */
    SWARP_WARP_CENTER_VIEW_VECTOR = 1,    /**< [RHS] §4.1: C_start from s on the view vector */
    SWARP_WARP_CENTER_NEAREST_VERTEX = 2, /**< [WS06]: C_start from the nearest vertex e */
    SWARP_WARP_CENTER_FORCE_I32 = 0x7FFFFFFF
} swarp_warp_center;

typedef enum swarp_technique {
    SWARP_TECHNIQUE_DEFAULT = 0, /**< = SWARP_TECHNIQUE_LISPSM */
    SWARP_TECHNIQUE_UNIFORM = 1, /**< focused uniform map [RHS] §3.1 */
    SWARP_TECHNIQUE_LISPSM = 2,  /**< LiSPSM [RHS] §3.2.1, parameter per swarp_warp_param */
    SWARP_TECHNIQUE_PSM = 3,     /**< PSM in the camera's post-perspective space [KOZ] */
    SWARP_TECHNIQUE_FORCE_I32 = 0x7FFFFFFF
} swarp_technique;

/** Options of swarp_setup; a zeroed struct is a valid request. */
typedef struct swarp_setup_options {
    swarp_technique technique;
    swarp_warp_param param;        /**< LiSPSM parameter (default: measured, SWARP_WARP_PARAM_MEASURED) */
    swarp_warp_center center;      /**< LiSPSM projection centre (default [RHS] §4.1) */
    swarp_depth_range depth_range; /**< default [-1, 1] */
    uint32_t map_width, map_height;       /**< texels; 0: 2048 (height 0: = width) */
    uint32_t screen_width, screen_height; /**< pixels; 0: 1920 x 1080 */
    uint32_t pancake;       /**< 1: light depth range over the receivers H only ("pancaking") */
    uint32_t psm_slideback; /**< PSM, light behind the camera: 1 = virtual slide-back instead
                                 of Kozlov's inverse projection */
    uint32_t _pad0, _pad1;  /**< must be zero */
    double n_user;          /**< SWARP_WARP_PARAM_USER: n' in eye units */
    double pseudo_near;     /**< SWARP_WARP_PARAM_PSEUDO: n_p in [0, 1) */
    double pseudo_far;      /**< SWARP_WARP_PARAM_PSEUDO: f_p in [0, 1) */
    double slideback;       /**< PSM: extra slide-back distance (world units, >= 0) that
                                 keeps the near-plane quad [KOZ] Fig. 14-6 */
    double min_depth;       /**< [RHS] §4.3 measured minimum LINEAR view depth of the
                                 frame (e.g. from the last frame's depth buffer); 0 = not
                                 given.  swarp_setup (and swarp_cascade_setup
                                 unstabilised) replace the camera's near by
                                 max(near, min_depth (1 - 1e-3)) before the adjusted
                                 near/far of §3.3.1 (swarp_mindepth_near with the default
                                 margin); min_depth >= far, or +INFINITY (nothing seen),
                                 keeps the near.  Ignored by swarp_setup_range/_points
                                 (explicit range).  >= 0 */
    uint32_t skip_measure;  /**< 1: do not measure the returned matrix (result.measured
                                 stays zero, samples = 0); 0: measure (the default) */
    uint32_t _reserved[1];  /**< must be zero */
} swarp_setup_options;

/** Results of swarp_setup.  matrix = light_proj · light_view maps world
 *  space to the light's clip space (x, y in [-1, 1], depth per the depth
 *  range; divide by w). */
typedef struct swarp_setup_result {
    swarp_mat4 light_view;
    swarp_mat4 light_proj;
    swarp_mat4 matrix;
    double n_eye;      /**< n' used, eye units ((3.2) scaled by (f - n)/d); +inf uniform;
                            PSM: near + slide-back */
    double n_light;    /**< n in the warp's light-space units; +inf uniform */
    double view_near;  /**< the view depth range used (adjusted [RHS] §3.3.1 in swarp_setup) */
    double view_far;
    double gamma;      /**< angle between view direction and light axis, radians */
    double max_mx;     /**< Lloyd's model: max m_x over [view_near, view_far], [RHS] (2.3),
                            for an overhead light on the view axis (exact only there) */
    double max_mz;     /**< Lloyd's model: max m_z, [RHS] (2.4), same frame */
    double light_near; /**< light depth range covered (world units along the light; PSM: */
    double light_far;  /**<   post-perspective units), informational */
    uint32_t point_count; /**< number of points of B */
    uint32_t _pad;
    swarp_measured_error measured; /**< the measured error of matrix over H with bisector
                                        receivers (swarp_measure_max with the options' screen
                                        and map); zero when skip_measure is set or for
                                        swarp_setup_points (no scene) */
    uint32_t _reserved[4];
} swarp_setup_result;

/** @brief The one call: H = V ∩ S, adjusted near/far [RHS] §3.3.1, B
 *  [RHS] §3.1.1, light view with light-space alignment, the technique's
 *  warp ([RHS] §3.2.1 / [KOZ]), focusing [RHS] (3.1) and the error model's
 *  prediction [RHS] (2.3)-(2.8).  No allocation.
 *  @param[in] cam, light, scene  (scene: the box S of casters and receivers)
 *  @param[in] opts     NULL or zeroed for defaults
 *  @param[out] out     matrices and report
 *  @param[out] out_points  the points of B (NULL: not wanted); capacity
 *                      SWARP_BODY_MAX_POINTS always suffices
 *  @param[out] out_count   number of points of B (may be NULL)
 *  @return SWARP_OK or an informational status (SWARP_INFO_WARP_UNIFORM,
 *          SWARP_INFO_PSM_INVERSE, SWARP_INFO_LIGHT_PARALLEL,
 *          SWARP_INFO_LIGHT_NEAR_CLIPPED (B clipped at a point light's near plane, 1e-4 of
 *          its farthest depth), SWARP_INFO_CASTERS_CLAMPED (S reaches more than 1e10 times
 *          H toward the light: casters beyond rely on depth clamping), SWARP_INFO_FLAT_EXTENT);
 *          SWARP_ERR_DEGENERATE also for PSM when its map would not project along the
 *          light in double, and for PSM on a frustum thinner than 1e-4 (tan(fovy/2),
 *          tan(fovy/2)*aspect or (far - near)/near below it: PPS rounds like eps/t^2);
 *          SWARP_ERR_BODY_EMPTY (camera looks away from the box),
 *          SWARP_ERR_LIGHT_INSIDE_BODY, SWARP_ERR_BOX_INVERTED,
 *          SWARP_ERR_BOX_DEGENERATE, SWARP_ERR_CAPACITY, and the argument
 *          errors (NULL, NON_FINITE, FOV, NEAR_FAR, ZERO_VECTOR, DEGENERATE,
 *          UNKNOWN_ENUM, RESERVED_NONZERO, OUT_OF_RANGE); SWARP_ERR_DEGENERATE
 *          also when the map is finer than world coordinates resolve (B far
 *          below the rounding of coordinates of size |eye|: its world-space
 *          matrix cannot be evaluated in double).  Computed relative to the
 *          eye (the translation is folded into light_view and matrix). */
SWARP_API swarp_status swarp_setup(const swarp_camera* cam, const swarp_light* light,
                                   const swarp_aabb* scene, const swarp_setup_options* opts,
                                   swarp_setup_result* out, swarp_vec3* out_points,
                                   size_t capacity, size_t* out_count);

/** @brief swarp_setup for an explicit view depth range [near, far] (a split
 *  frustum), used as given (no adjustment).  cam->z_near/far are ignored.
 *  @return as swarp_setup. */
SWARP_API swarp_status swarp_setup_range(const swarp_camera* cam, const swarp_light* light,
                                         const swarp_aabb* scene, double z_near, double z_far,
                                         const swarp_setup_options* opts, swarp_setup_result* out,
                                         swarp_vec3* out_points, size_t capacity,
                                         size_t* out_count);

/** @brief The light matrices for given points of B (count <=
 *  SWARP_BODY_MAX_POINTS) and the view depth range [near, far] they refer
 *  to.  receivers (may be NULL): the points of H, used for pancaking, the
 *  nearest vertex e ([WS06] centre) and PSM's unit cube clipping.
 *  @return as swarp_setup; SWARP_ERR_INVALID_ARGUMENT for count 0 or above
 *          the maximum. */
SWARP_API swarp_status swarp_setup_points(const swarp_camera* cam, const swarp_light* light,
                                          const swarp_vec3* points, size_t count,
                                          const swarp_vec3* receivers, size_t receiver_count,
                                          double z_near, double z_far,
                                          const swarp_setup_options* opts,
                                          swarp_setup_result* out);

/* ---- the steps of swarp_setup, each callable on its own ---------------- */

/** Worst case of points of B written by swarp_body_points / swarp_setup. */
#define SWARP_BODY_MAX_POINTS 128

/** @brief The points of B (its vertices) for the view depths [near, far].
 *  @param[out] out capacity points; SWARP_BODY_MAX_POINTS always suffices.
 *  @param[out] out_count number of points (also on SWARP_ERR_CAPACITY).
 *  @return SWARP_OK, SWARP_ERR_BODY_EMPTY, SWARP_ERR_BOX_DEGENERATE,
 *          SWARP_ERR_CAPACITY, and the argument errors of the camera, light
 *          and box (SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR, SWARP_ERR_ZERO_VECTOR,
 *          SWARP_ERR_DEGENERATE (up parallel to dir), SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE): the statuses
 *          of the experimental swarp_body_h and swarp_body_from_h. */
SWARP_API swarp_status swarp_body_points(const swarp_camera* cam, double z_near, double z_far,
                                         const swarp_light* light, const swarp_aabb* scene,
                                         swarp_vec3* out, size_t capacity, size_t* out_count);

/** @brief Adjusted near/far [RHS] §3.3.1 ([ZSN07]): min and max view depth
 *  over the points of H = V ∩ S (view frustum cam->z_near..cam->z_far).
 *  @return SWARP_OK, SWARP_ERR_BODY_EMPTY, SWARP_ERR_BOX_DEGENERATE, and the
 *          argument errors of the camera and box (SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR,
 *          SWARP_ERR_ZERO_VECTOR, SWARP_ERR_DEGENERATE,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE): the statuses
 *          of the experimental swarp_body_h. */
SWARP_API swarp_status swarp_body_adjusted_range(const swarp_camera* cam, const swarp_aabb* scene,
                                                 double* out_near, double* out_far);

/*
 * Light-space alignment ([RHS] §3.2.1, [WS06]): the light view looks along
 * the light (directional: the direction light travels; point light: the
 * axis a given by the caller, usually the spot axis or the direction to the
 * centre of B) and its up vector (+y) is the view direction v projected on
 * the plane perpendicular to that axis, v_perp = v - (v·a) a, |v_perp| =
 * sin γ.  Continuous fallback near γ = 0 and γ = 180°: the up vector is
 * normalize(v_perp + w(sin γ) r_perp), r the camera's right vector and
 * w(s) = SWARP_FOCUS_BLEND_WEIGHT (1 - s/SWARP_FOCUS_BLEND_SIN)^2 for
 * s < SWARP_FOCUS_BLEND_SIN (0 above): no threshold switch, the basis turns
 * smoothly through the right vector when the light passes parallel or
 * antiparallel to the view in the plane of v and the camera's up vector.
 * (Every continuous tangent field on the sphere has a zero: this one's lies
 * off that plane, on the v-r great circle, at γ ≈ 5.6° (sin γ ≈ 0.097); see
 * docs/geometry.md; the experimental swarp_setup_follow has no such point.)
 * SWARP_INFO_LIGHT_PARALLEL reports that the blend is active.
 */
#define SWARP_FOCUS_BLEND_SIN 0.17364817766693033 /* sin 10° */
#define SWARP_FOCUS_BLEND_WEIGHT 0.5

/** @brief Light view matrix (right-handed, looks down -z) with light-space
 *  alignment.  [RHS] §3.2.1
 *  @param[in] cam    the viewer (its dir and up give the alignment)
 *  @param[in] light  the light
 *  @param[in] axis   point lights: the direction the light view looks along
 *                    (any length > 0); NULL means light->direction (spot)
 *                    or, for an omni light, the direction to cam->eye.
 *                    Ignored for directional lights.
 *  @param[out] out_view  light view; origin at cam->eye (directional) or at
 *                    the light position (point light).
 *  @return SWARP_OK, SWARP_INFO_LIGHT_PARALLEL, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_ZERO_VECTOR, SWARP_ERR_OVERFLOW
 *          (an origin so far out, |origin| near DBL_MAX, that its distance
 *          along an axis of the view, the matrix's translation, exceeds
 *          DBL_MAX), ... */
SWARP_API swarp_status swarp_focus_light_view(const swarp_camera* cam, const swarp_light* light,
                                              const swarp_vec3* axis, swarp_mat4* out_view);

/** @brief The focusing matrix A_fit.  [RHS] (3.1)
 *  Maps the bounding box of the points transformed by m (with perspective
 *  division) to x, y in [-1, 1] and z in [-1, 1] (SWARP_DEPTH_NEG_ONE_TO_ONE)
 *  or [0, 1] (SWARP_DEPTH_ZERO_TO_ONE); (3.1) is the [0, 1] case.
 *  @param[in] m          transform applied to the points first (e.g. P·L)
 *  @param[in] points     world-space points (xy extent), count >= 1
 *  @param[in] z_points   points whose depth extent is used (NULL: points).
 *                        Pancaking passes the receivers (H) here.
 *  @param[out] out_A_fit the fit; a flat extent (below 1e-12 of its
 *                        coordinates: rounding noise) gets the widest other
 *                        extent as its width, or, all flat, width 1 (1e-6
 *                        of the coordinates beyond 1e6) (status).
 *  @return SWARP_OK, SWARP_INFO_FLAT_EXTENT (an extent was zero),
 *          SWARP_ERR_NULL_POINTER, SWARP_ERR_INVALID_ARGUMENT (count 0, or
 *          z_points given with z_count 0), SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_DEGENERATE (a point maps to
 *          w <= 0). */
SWARP_API swarp_status swarp_focus_fit(const swarp_mat4* m, const swarp_vec3* points, size_t count,
                                       const swarp_vec3* z_points, size_t z_count,
                                       swarp_depth_range depth_range, swarp_mat4* out_A_fit);


/** Options of the LiSPSM warp; zero means default. */
typedef struct swarp_warp_options {
    swarp_warp_param param;
    swarp_warp_center center;
    double n_user;       /**< SWARP_WARP_PARAM_USER: n' in eye units (> 0; +inf = uniform) */
    double pseudo_near;  /**< n_p of (4.2), fraction in [0, 1) */
    double pseudo_far;   /**< f_p of (4.2), fraction in [0, 1), n_p + f_p < 1 */
    uint32_t _reserved[4];
} swarp_warp_options;

/** What the warp used (outputs of swarp_warp_lispsm). */
typedef struct swarp_warp_info {
    double n_light;   /**< n in light-space units (distance C to near plane of P); +inf = uniform */
    double n_eye;     /**< n' in eye units: n_light (f - n) / d, what the error model takes */
    double d;         /**< extent of B along the warp axis (light-space y) */
    double z_0, z_1;  /**< eye depths of the near and far ends of P's axis */
    double gamma;     /**< angle between view and light axis, radians [0, pi] */
    uint32_t _reserved[4];
} swarp_warp_info;

/** @brief The LiSPSM warp P for the points of B in light view space.
 *  [RHS] §3.2.1, (3.2), §4.1; [WS06].
 *  P is a perspective along light-space +y with projection centre C, written
 *  in the normalised form w = 1 + (y - y_min)/n, so n = +inf is exactly the
 *  identity-like uniform map (continuous fade as γ -> 0).  Follow it with
 *  swarp_focus_fit(P·L, ...).  n (out_info->n_light) is at least 1e-6 times
 *  the largest |y| of B in light space: below that the matrix cannot carry
 *  the 1 of w next to the rounding of y (w would reach 0 on B), so a smaller
 *  parameter is raised to this bound (w >= 1 on B to ~1e-9 relative).
 *  @param[in] light_view  L from swarp_focus_light_view
 *  @param[in] cam         the viewer (eye, dir, fovy)
 *  @param[in] near, far   the view depth range the warp refers to (adjusted
 *                         or split range; 0 < near < far)
 *  @param[in] points      points of B (world), count >= 1
 *  @param[in] nearest     the nearest vertex e of H to the eye (used by
 *                         SWARP_WARP_CENTER_NEAREST_VERTEX; NULL: the point
 *                         s on the view vector at depth near, [RHS] §4.1)
 *  @param[in] opts        NULL or zeroed for defaults
 *  @param[out] out_P      the warp (applied after L)
 *  @param[out] out_info   may be NULL
 *  @return SWARP_OK, SWARP_INFO_WARP_UNIFORM (n = inf: θ -> 0 or η = -1),
 *          SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR,
 *          SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,
 *          SWARP_ERR_OUT_OF_RANGE (n_user, pseudo fractions),
 *          SWARP_ERR_DEGENERATE (a point of B at w <= 0 under light_view, or
 *          a warp that cannot be represented), SWARP_ERR_SINGULAR (a
 *          light_view that is not a rigid look-at and not invertible; a
 *          look-at is inverted exactly). */
SWARP_API swarp_status swarp_warp_lispsm(const swarp_mat4* light_view, const swarp_camera* cam,
                                         double z_near, double z_far, const swarp_vec3* points,
                                         size_t count, const swarp_vec3* nearest,
                                         const swarp_warp_options* opts,
                                         swarp_mat4* out_P, swarp_warp_info* out_info);

/* ---- closed-form warp parameters ----------------------------------------- */
/*
 * Naming: the warp parameter n (or n') is the distance from the projection
 * centre C of the warping frustum P to its near plane [RHS] §3.2.1.  n = n_e
 * (the eye's near distance, overhead light) is PSM; n -> inf is uniform.
 *
 * Huge values, one rule for every parameter below: the exactly degenerate
 * input (z_1 == z_0, eta == -1) gives +INFINITY; a value that is finite in
 * exact arithmetic but exceeds DBL_MAX is written as DBL_MAX.  Both come with
 * SWARP_INFO_WARP_UNIFORM.  The [GMNPR] λ functions are finite on all of
 * [0, pi/2]: their θ == 0 also writes DBL_MAX.  Angles are radians.
 */

/** @brief LiSPSM n_opt, general form.  [RHS] (3.2) (from [WS06])
 *  n_opt = d / (sqrt(z_1/z_0) - 1), evaluated as
 *  d (z_0 + sqrt(z_0 z_1)) / (z_1 - z_0) (no cancellation for z_1 ~ z_0).
 *  For an overhead light (d = f - n, z_0 = n, z_1 = f) it is the n' that makes
 *  Lloyd's m_z(n) = m_z(f) ([RHS] (2.4)); n_opt / d is [GMNPR]'s λ_LiSPSM(π/2).
 *  @param[in] d   extent of the warping frustum P along light-space z (> 0),
 *                 world units
 *  @param[in] z_0 eye-space depth where the error peaks near (> 0)
 *  @param[in] z_1 eye-space depth where the error peaks far (>= z_0)
 *  @param[out] out_n_opt  n_opt, world units; +INFINITY when z_1 == z_0
 *  @return SWARP_OK; SWARP_INFO_WARP_UNIFORM when z_1 == z_0 (n_opt = inf) or
 *          the value overflows (DBL_MAX); SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_OUT_OF_RANGE (d <= 0, z_0 <= 0,
 *          z_1 < z_0). */
SWARP_API swarp_status swarp_warp_nopt(double d, double z_0, double z_1, double* out_n_opt);

/** @brief n_opt with pseudo-near and pseudo-far planes.  [RHS] (4.2)
 *  Read as n_opt = d/(z_1 - z_0) * (z_0 + sqrt((z_0 + n_p (z_1 - z_0))
 *  (z_1 - f_p (z_1 - z_0)))) (papers README); reduces to (3.2) at
 *  n_p = f_p = 0.  For an overhead light (d = z_1 - z_0) it equalises m_z at
 *  the pseudo-near depth z_0 + n_p (z_1 - z_0) and the pseudo-far depth
 *  z_1 - f_p (z_1 - z_0).
 *  @param[in] d, z_0, z_1  as swarp_warp_nopt
 *  @param[in] n_p, f_p  in [0, 1], n_p + f_p < 1: the pseudo planes as
 *                   fractions of the depth range measured from near and from
 *                   far (NOT eye-space distances; compare swarp_split_pseudo)
 *  @param[out] out_n_opt  n_opt, world units
 *  @return as swarp_warp_nopt; SWARP_ERR_NON_FINITE / SWARP_ERR_OUT_OF_RANGE
 *          for n_p, f_p. */
SWARP_API swarp_status swarp_warp_nopt_pseudo(double d, double z_0, double z_1, double n_p,
                                              double f_p, double* out_n_opt);

/** @brief Lloyd's warp strength η(γ, Θ).  [RHS] (3.3)
 *  Piecewise in γ with γ_a = Θ/3, γ_b = Θ, γ_c = Θ + 0.3 (π/2 - Θ),
 *  η_b = -0.2, η_c = 0; continuous in γ.
 *  @param[in] gamma angle between light direction and view direction, radians,
 *               in [0, pi/2] (callers fold γ > pi/2 to pi - γ)
 *  @param[in] theta half the field of view Θ, radians, in (0, pi/2)
 *  @param[out] out_eta η in [-1, 0]
 *  @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_FOV (theta), SWARP_ERR_OUT_OF_RANGE (gamma). */
SWARP_API swarp_status swarp_warp_eta(double gamma, double theta, double* out_eta);

/** @brief Width W_lz of the view frustum along the light-space z axis for a
 *  directional light.  [RHS] (3.5)
 *  W_lz = W_e cos γ + W_s sin(Θ + γ) + [γ <= Θ] W_s (1 - cos(Θ - γ)),
 *  W_s = (f_e - n_e)/cos Θ.  Overhead light (γ = π/2): W_lz = f_e - n_e.
 *  @param[in] gamma in [0, pi/2] radians; @param[in] theta Θ in (0, pi/2)
 *  @param[in] n_e, f_e eye near/far (0 < n_e < f_e), world units
 *  @param[in] W_e width of the eye's near plane (> 0), world units; in the
 *             2D side view of [RHS] Fig. 3.7 this is 2 n_e tan Θ
 *  @param[out] out_W_lz  W_lz, world units
 *  @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV, SWARP_ERR_OUT_OF_RANGE (gamma,
 *          W_e), SWARP_ERR_OVERFLOW. */
SWARP_API swarp_status swarp_warp_wlz(double gamma, double theta, double n_e, double f_e,
                                      double W_e, double* out_W_lz);

/** @brief Re-parameterised LiSPSM n_repar(η).  [RHS] (3.4), second case read
 *  as η·sqrt(α) + 1 (papers README).  η = -1 gives +INFINITY with
 *  SWARP_INFO_WARP_UNIFORM; η = 0 gives W_lz/(sqrt(α) - 1) (n_opt);
 *  η = 1 gives W_lz/(α - 1) (PSM).
 *  @param[in] eta in [-1, 1]; @param[in] alpha f_e/n_e > 1
 *  @param[in] W_lz > 0, world units (swarp_warp_wlz)
 *  @param[out] out_n  n_repar, world units (light space: the warp frustum's
 *              depth is W_lz)
 *  @return SWARP_OK; SWARP_INFO_WARP_UNIFORM (η = -1, or overflow: DBL_MAX);
 *          SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE. */
SWARP_API swarp_status swarp_warp_nrepar(double eta, double alpha, double W_lz, double* out_n);

/*
 * [GMNPR] uses λ = P_n / (P_f - P_n): the warp parameter for a warping frustum
 * whose depth range is normalised to 1.  θ is the angle between light and
 * view direction (γ in [RHS]), φ the half field of view (Θ in [RHS]).
 * Eq. (2) has two cases, θ in [φ, π/2] and θ in [0, φ]; they agree at θ = φ.
 * Common checks: NaN/Inf -> SWARP_ERR_NON_FINITE; n <= 0 or f <= n ->
 * SWARP_ERR_NEAR_FAR; φ outside (0, π/2) -> SWARP_ERR_FOV; θ or λ outside
 * their domain -> SWARP_ERR_OUT_OF_RANGE; NULL output -> SWARP_ERR_NULL_POINTER.
 */

/** @brief ψ(λ, θ) of [GMNPR] eq. (2).  λ > 0, θ in (0, pi/2], φ in (0, pi/2),
 *  0 < n < f.
 *  @return SWARP_OK, the common checks, SWARP_ERR_OVERFLOW (λ or θ so small
 *  that ψ exceeds DBL_MAX). */
SWARP_API swarp_status swarp_gmnpr_psi(double lambda, double theta, double phi, double n,
                                       double f, double* out_psi);
/** @brief φ(λ, θ) of [GMNPR] eq. (2) (the offset inside (z + φ)^2).  Named
 *  "offset" here to keep it apart from the half field of view φ.  Same domain
 *  and statuses as swarp_gmnpr_psi. */
SWARP_API swarp_status swarp_gmnpr_offset(double lambda, double theta, double phi, double n,
                                          double f, double* out_offset);
/** @brief Aliasing function F(λ, θ, z) = ψ (z + φ(λ,θ))^2 / z.  [GMNPR] (2)
 *  @param[in] z eye-space depth in [n, f] (SWARP_ERR_OUT_OF_RANGE outside).
 *  Other parameters and statuses as swarp_gmnpr_psi. */
SWARP_API swarp_status swarp_gmnpr_F(double lambda, double theta, double phi, double n,
                                     double f, double z, double* out_F);
/** @brief λ_1(θ) and λ_2(θ) of [GMNPR] (4), for analysis (either may be <= 0
 *  off its own case).  λ_1 is read with tanφ/tanθ (papers README).
 *  θ in (0, pi/2]; both outputs required.
 *  @return SWARP_OK, the common checks, SWARP_ERR_OVERFLOW. */
SWARP_API swarp_status swarp_gmnpr_lambda12(double theta, double phi, double n, double f,
                                            double* out_lambda_1, double* out_lambda_2);
/** @brief λ_GMNPR(θ) of [GMNPR] (8), with λ_2* of (7) for θ < φ.
 *  θ in [0, pi/2]; finite and positive for θ > 0, continuous at θ = φ,
 *  growing without bound as θ -> 0; never Inf or NaN: θ = 0 (and θ so
 *  small that λ overflows) gives DBL_MAX with SWARP_INFO_WARP_UNIFORM.
 *  @return SWARP_OK (θ >= φ), SWARP_INFO_GMNPR_ADJUSTED (0 < θ < φ),
 *  SWARP_INFO_WARP_UNIFORM, the common checks. */
SWARP_API swarp_status swarp_gmnpr_lambda(double theta, double phi, double n, double f,
                                          double* out_lambda);
/** @brief λ_LiSPSM(θ) of [GMNPR] (9): P_n = (n + sqrt(fn))/sin θ over the
 *  normalised depth P_f - P_n.  θ in [0, pi/2]; θ = 0 gives DBL_MAX (finite)
 *  with SWARP_INFO_WARP_UNIFORM.  At θ = π/2 it equals n_opt/(f - n).
 *  @return SWARP_OK, SWARP_INFO_WARP_UNIFORM, the common checks. */
SWARP_API swarp_status swarp_gmnpr_lambda_lispsm(double theta, double phi, double n, double f,
                                                 double* out_lambda);
/** @brief λ_GLPR: the λ that makes F(λ, θ, z) linear in z (GLPR, [GMNPR] §3,
 *  derived from (2): F linear in z <=> φ(λ, θ) = 0).  For θ > φ:
 *  λ = n (1 - tanφ/tanθ) / (f - n + (f + n) tanφ/tanθ), which is n/(f - n)
 *  (PSM) at θ = π/2; a solution below the smallest subnormal (n subnormal
 *  with f >> n, or θ just above φ) is written as DBL_TRUE_MIN with SWARP_OK.
 *  For θ <= φ there is no positive solution: λ_GMNPR(θ) is
 *  written instead with SWARP_INFO_GLPR_NO_SOLUTION (θ = 0: DBL_MAX with
 *  SWARP_INFO_WARP_UNIFORM).  Derivation in docs/parameters.md.
 *  @return SWARP_OK, SWARP_INFO_GLPR_NO_SOLUTION, SWARP_INFO_WARP_UNIFORM,
 *  the common checks. */
SWARP_API swarp_status swarp_gmnpr_lambda_glpr(double theta, double phi, double n, double f,
                                               double* out_lambda);

/* ======================================================================== */
/* 5. Error: the measured error of a matrix, and Lloyd's model              */
/* ======================================================================== */

/** @brief The measured error of matrix at caller-given receiver points and
 *  normals (e.g. world positions and normals read back from the G-buffer).
 *  Analytic, in double; the camera's near/far are not used (any planar depth
 *  > 0 is on screen).
 *  @param[in] cam     the camera the screen belongs to (checked as in swarp_setup
 *                     except near/far)
 *  @param[in] matrix  world -> light clip (swarp_setup_result.matrix, a split's matrix)
 *  @param[in] res     screen and map resolutions
 *  @param[in] points, normals  count points and their normals (any length > 0)
 *  @param[out] out    count results
 *  @return SWARP_OK; SWARP_INFO_MEASURE_SINGULAR (some point has
 *          SWARP_TEXEL_SINGULAR: its values are +inf); SWARP_ERR_NULL_POINTER
 *          (NULL with count > 0), SWARP_ERR_NON_FINITE (a matrix element, point
 *          or normal), SWARP_ERR_ZERO_VECTOR (a zero normal), SWARP_ERR_RESOLUTION,
 *          and the camera's errors.  On error out is untouched. */
SWARP_API swarp_status swarp_measure_points(const swarp_camera* cam, const swarp_mat4* matrix,
                                            const swarp_measure_res* res,
                                            const swarp_vec3* points, const swarp_vec3* normals,
                                            size_t count, swarp_texel_error* out);

/** @brief The largest measured error of matrix over H = V ∩ S, V the view
 *  frustum between planar depths z_near and z_far (a split's range, or the
 *  adjusted range of swarp_setup_result.view_near/view_far), with bisector
 *  receivers: N = normalize(e + l), e and l the unit directions from the
 *  point to the eye and to the light (the receiver for which projection
 *  aliasing vanishes, leaving the perspective aliasing of the parameterisation).
 *  Sampling: the vertices of H, a grid x grid NDC lattice at depths geometric
 *  in [z_near, z_far] (points outside S skipped) and a finer lattice on the
 *  near face, then from the worst vertex, the two worst local maxima of the
 *  lattice and the worst near-face point refine steps of a deterministic compass
 *  search over (NDC x, NDC y, log z), halving the step each time it finds no
 *  larger sigma; a flat S (H a polygon) is sampled on its plane (docs/accuracy.md
 *  states the sampling and its error).  No allocation; the result is deterministic.
 *  @return SWARP_OK; SWARP_INFO_MEASURE_SINGULAR (max_sigma = +inf);
 *          SWARP_ERR_BODY_EMPTY (no sample of V lies in S); the errors of
 *          swarp_measure_points, SWARP_ERR_NEAR_FAR (not 0 < z_near < z_far),
 *          the light's and box's errors as in swarp_setup, SWARP_ERR_OUT_OF_RANGE
 *          (grid or depths 1), SWARP_ERR_RESERVED_NONZERO.  On error out is
 *          untouched. */
SWARP_API swarp_status swarp_measure_max(const swarp_camera* cam, double z_near, double z_far,
                                         const swarp_light* light, const swarp_aabb* scene,
                                         const swarp_mat4* matrix, const swarp_measure_res* res,
                                         const swarp_measure_options* opts,
                                         swarp_measured_error* out);

/* ---- Lloyd's model [RHS] (2.3)-(2.8): the overhead light on the view axis -- */



/** Inputs of Lloyd's error metric [RHS] (2.3)-(2.8).  res_ix x res_iy is the
 *  image resolution (pixels; the paper has res_ix >= res_iy), res_s x res_t
 *  the shadow-map resolution (texels); each must be finite and > 0
 *  (SWARP_ERR_RESOLUTION).  theta is Θ, half the field of view, radians in
 *  (0, pi/2) (SWARP_ERR_FOV).  near/far are the range [n, f] the curve refers
 *  to (SWARP_ERR_NEAR_FAR unless 0 < near < far).  _reserved must be zero. */
typedef struct swarp_error_config {
    double z_near;
    double z_far;
    double theta;
    double res_ix;
    double res_iy;
    double res_s;
    double res_t;
    uint32_t _reserved[4];
} swarp_error_config;

/** @brief m_x(z, n') [RHS] (2.3); n' = n gives (2.5) (PSM); n' = +INFINITY
 *  gives the closed-form uniform limit (2.7).
 *  @param[in] cfg  see swarp_error_config
 *  @param[in] z    eye-space depth in [near, far]
 *  @param[in] n_prime  warp parameter n' in (0, +INFINITY] (+INFINITY =
 *                  uniform), world units
 *  @param[out] out_mx  m_x (dimensionless: screen pixels per shadow texel)
 *  @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_RESERVED_NONZERO,
 *          SWARP_ERR_NON_FINITE (NaN anywhere, n' = -inf), SWARP_ERR_FOV,
 *          SWARP_ERR_RESOLUTION, SWARP_ERR_NEAR_FAR, SWARP_ERR_OUT_OF_RANGE
 *          (z outside [near, far], n' <= 0), SWARP_ERR_OVERFLOW. */
SWARP_API swarp_status swarp_error_mx(const swarp_error_config* cfg, double z, double n_prime,
                                      double* out_mx);
/** @brief m_z(z, n') [RHS] (2.4); n' = n gives (2.6); n' = +INFINITY gives
 *  (2.8).  Parameters and statuses as swarp_error_mx (both are evaluated
 *  without intermediate under/overflow; a true value below DBL_TRUE_MIN/2,
 *  e.g. with res_ix or res_iy near DBL_TRUE_MIN, is returned as 0). */
SWARP_API swarp_status swarp_error_mz(const swarp_error_config* cfg, double z, double n_prime,
                                      double* out_mz);
/** @brief Exact maxima of m_x and m_z over [near, far].  m_x ∝ 1 + a/z is
 *  monotone and m_z ∝ a^2/z + 2a + z (a = n' - n) is convex in z, so the
 *  maximum is at an end point: no sampling.  Either output pointer may be
 *  NULL.  Statuses as swarp_error_mx (no z). */
SWARP_API swarp_status swarp_error_max(const swarp_error_config* cfg, double n_prime,
                                       double* out_max_mx, double* out_max_mz);
/** @brief The piecewise curve of a partitioned frustum ([RHS] Fig. 3.15, 3.18):
 *  split i covers [splits[i], splits[i+1]] with its own warp n_primes[i] and
 *  a full map of res_s x res_t (the metric evaluated with n = splits[i],
 *  f = splits[i+1]).  splits has m + 1 strictly increasing entries, the first
 *  > 0 (cfg->z_near/far are ignored).  Evaluates at each z[k] in
 *  [splits[0], splits[m]] (a z on a border belongs to the split that starts
 *  there; splits[m] to the last split).  out_mx or out_mz may be NULL; z may
 *  be NULL when count is 0.
 *  @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_RESERVED_NONZERO,
 *  SWARP_ERR_NON_FINITE, SWARP_ERR_FOV, SWARP_ERR_RESOLUTION,
 *  SWARP_ERR_SPLIT_COUNT (m = 0), SWARP_ERR_NEAR_FAR (splits[0] <= 0),
 *  SWARP_ERR_NOT_INCREASING, SWARP_ERR_OUT_OF_RANGE (a z outside, an
 *  n' <= 0), SWARP_ERR_OVERFLOW.  On error no output is written. */
SWARP_API swarp_status swarp_error_split_curve(const swarp_error_config* cfg,
                                               const double* splits,
                                               const double* n_primes, size_t m,
                                               const double* z, size_t count,
                                               double* out_mx, double* out_mz);
/** @brief Exact per-split and overall maxima of the piecewise curve.
 *  out_split_max_mx/mz may be NULL or hold m values; out_max_mx/mz may be NULL.
 *  Statuses as swarp_error_split_curve. */
SWARP_API swarp_status swarp_error_split_max(const swarp_error_config* cfg,
                                             const double* splits,
                                             const double* n_primes, size_t m,
                                             double* out_split_max_mx,
                                             double* out_split_max_mz,
                                             double* out_max_mx, double* out_max_mz);

/* ======================================================================== */
/* 6. Cascades: split schemes, atlas, stabilisation, bias, the one call     */
/* ======================================================================== */
/* ---- split schemes ------------------------------------------------------- */
/** Largest split count m the schemes accept; they write m + 1 values, so an
 *  array of SWARP_SPLIT_MAX_COUNT + 1 doubles always suffices. */
#define SWARP_SPLIT_MAX_COUNT 64

/*
 * Every scheme writes the m + 1 distances C_0 = n < C_1 < ... < C_m = f
 * (C_0 and C_m exactly n and f) into out[0..m] and m + 1 into *out_count.
 * Statuses: SWARP_OK; SWARP_ERR_NULL_POINTER (out_count NULL, or out NULL
 * with capacity > 0); SWARP_ERR_NON_FINITE; SWARP_ERR_NEAR_FAR (n <= 0,
 * f <= n); SWARP_ERR_OUT_OF_RANGE (lambda outside [0, 1], pseudo planes
 * outside); SWARP_ERR_SPLIT_COUNT (m = 0 or m > SWARP_SPLIT_MAX_COUNT);
 * SWARP_ERR_CAPACITY (capacity < m + 1: *out_count = m + 1, out untouched;
 * so out = NULL, capacity = 0 asks for the count); SWARP_ERR_DEGENERATE
 * ([n, f] too narrow in double precision for m distinct distances).
 */

/** @brief Uniform split scheme C_i = n + (f - n) i/m.  [RHS] (3.6) */
SWARP_API swarp_status swarp_split_uniform(double n, double f, uint32_t m, double* out,
                                           size_t capacity, size_t* out_count);
/** @brief Logarithmic scheme C_i = n (f/n)^(i/m).  [RHS] (3.7) */
SWARP_API swarp_status swarp_split_log(double n, double f, uint32_t m, double* out,
                                       size_t capacity, size_t* out_count);
/** @brief Practical scheme C_i = (1 - λ) C_i^uni + λ C_i^log, λ in [0, 1]
 *  (0 uniform, 1 logarithmic; PSSM uses 0.5).  [RHS] (3.8) */
SWARP_API swarp_status swarp_split_practical(double n, double f, double lambda, uint32_t m,
                                             double* out, size_t capacity,
                                             size_t* out_count);
/** @brief Pseudo-near/far practical scheme.  [RHS] (4.1): the practical scheme
 *  over [n_p, f_p] (EYE-SPACE distances, n <= n_p < f_p <= f) for
 *  C_1..C_{m-1}; C_0 = n and C_m = f are kept so the splits still cover the
 *  whole view.  n_p = n, f_p = f gives swarp_split_practical. */
SWARP_API swarp_status swarp_split_pseudo(double n, double f, double n_p, double f_p,
                                          double lambda, uint32_t m, double* out,
                                          size_t capacity, size_t* out_count);

/* ---- texture atlas and filter kernel, [RHS] §3.3.5, (3.9) --------------- */

/** Most splits an atlas layout holds ([RHS] Fig. 3.16c: a 4 x 4 grid). */
#define SWARP_ATLAS_MAX_SPLITS 16

/** Whole-atlas facts of a layout.  grid x grid tiles of tile_res x tile_res
 *  texels; atlas_res = grid * tile_res; l_sc = 1/grid ([RHS] (3.9)). */
typedef struct swarp_atlas_info {
    uint32_t split_count; /**< m */
    uint32_t grid;        /**< 1 (m = 1), 2 (m <= 4), 3 (m <= 9), 4 (m <= 16) */
    double tile_res;      /**< texels per tile side */
    double atlas_res;     /**< texels per atlas side */
    double l_sc;          /**< [RHS] (3.9): 1, 1/2, 1/3, 1/4 */
    uint32_t _reserved[4];
} swarp_atlas_info;

/** One split's place in the atlas.  Tiles are numbered row by row starting
 *  at texture coordinate (0, 0) (x = i mod grid, y = i / grid), the order
 *  of [RHS] Fig. 3.16.  viewport_* are glViewport()-style texel numbers.
 *  clip_to_atlas maps the split's clip coordinates (x, y, z, w) to
 *  homogeneous atlas coordinates (u w, v w, d w, w): after the divide u, v
 *  are atlas texture coordinates in [u0, u0 + l_sc] x [v0, v0 + l_sc] and d
 *  the window depth in [0, 1] (whatever the clip depth range; under
 *  reversed-Z d = z_ndc, the light's near plane at 1 and far plane at 0). */
typedef struct swarp_atlas_tile {
    double viewport_x, viewport_y;          /**< lower-left texel */
    double viewport_width, viewport_height; /**< texels */
    swarp_mat4 clip_to_atlas;
} swarp_atlas_tile;

/** @brief Atlas layout for m splits ([RHS] §3.3.5, Fig. 3.16).
 *  m = 1 uses the whole texture (grid 1, l_sc = 1); 2..4 a 2 x 2 grid,
 *  5..9 a 3 x 3 grid, 10..16 a 4 x 4 grid.
 *  @param m          number of splits, 1..SWARP_ATLAS_MAX_SPLITS
 *  @param tile_res   texels per tile side (> 0, at most 2^24)
 *  @param depth      clip depth convention of the split matrices
 *  @param[out] out_info  layout facts (may be NULL)
 *  @param[out] out_tiles m tiles; capacity >= m
 *  @param[out] out_count m (also written with SWARP_ERR_CAPACITY)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_ATLAS_SPLITS,
 *          SWARP_ERR_RESOLUTION, SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_CAPACITY. */
SWARP_API swarp_status swarp_atlas_layout(uint32_t m, uint32_t tile_res, swarp_depth_range depth,
                                          swarp_atlas_info* out_info, swarp_atlas_tile* out_tiles,
                                          size_t capacity, size_t* out_count);

/** @brief l_sc of [RHS] (3.9) for m splits: 1 (m = 1), 1/2, 1/3, 1/4. */
SWARP_API swarp_status swarp_atlas_lsc(uint32_t m, double* out_l_sc);

/** @brief PCF kernel scale of one split, [RHS] (3.9):
 *  s_i = r_l l_sc (2/(max_x - min_x), 2/(max_y - min_y)).
 *  min/max are the split's focus box in light space (the box of (3.1)), in
 *  world units for a uniform map.  s_i is in the split's clip units scaled by
 *  l_sc; s_i/2 is the extent of r_l in atlas texture coordinates, so a kernel
 *  of s_i has the same world size r_l in every split.
 *  @param r_l  kernel size in world units (>= 0)
 *  @param m    split count (selects l_sc)
 *  @param min_x, max_x, min_y, max_y  max > min
 *  @param[out] out_s  s_i (x, y)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE (r_l < 0, max <= min), SWARP_ERR_ATLAS_SPLITS,
 *          SWARP_ERR_OVERFLOW (a scale beyond DBL_MAX: width ~ r_l/DBL_MAX). */
SWARP_API swarp_status swarp_atlas_kernel_scale(double r_l, uint32_t m, double min_x,
                                                double max_x, double min_y, double max_y,
                                                double out_s[2]);

/* ---- flicker reduction, [RHS] §3.5 (ZZB09) ------------------------------ */

typedef enum swarp_stabilize_mode {
    SWARP_STABILIZE_DEFAULT = 0, /**< = SWARP_STABILIZE_NONE */
    SWARP_STABILIZE_NONE = 1,    /**< light-aligned focus on the body box, no snapping */
    SWARP_STABILIZE_SPHERE = 2,  /**< exact solution: minimal sphere of the split frustum */
    SWARP_STABILIZE_LEVELS = 3,  /**< approximate solution: quantised scale */
    SWARP_STABILIZE_MODE_FORCE_I32 = 0x7FFFFFFF
} swarp_stabilize_mode;

/** Options of the stabilised light matrix.  Zero means default. */
typedef struct swarp_stabilize_options {
    swarp_stabilize_mode mode;
    uint32_t levels;       /**< LEVELS: number of scale levels; 0 = 64 [RHS] §3.5 */
    swarp_vec3 origin;     /**< world origin of snapping AND of the output matrix */
    double level_max_size; /**< LEVELS: world size of level `levels`; 0 = diameter of
                                the split frustum's minimal sphere */
    swarp_depth_range depth;
    uint32_t _reserved0;
    uint32_t _reserved[4];
} swarp_stabilize_options;

/** What the stabiliser did. */
typedef struct swarp_stabilize_report {
    swarp_vec3 sphere_center;     /**< exact minimal enclosing sphere of the split frustum */
    double sphere_radius;
    double centroid_radius;       /**< sphere about the 8 corners' centroid */
    double area_saved;            /**< 1 - (r_min / r_centroid)^2: map area the exact
                                       sphere saves against the centroid sphere */
    double texel_size_x;          /**< world size of one texel along light-space x */
    double texel_size_y;
    double offset_x, offset_y;    /**< light-space centre of the map relative to origin,
                                       whole multiples of the texel size */
    uint32_t level_x, level_y;    /**< LEVELS: quantised level (1..); else 0 */
    uint32_t _reserved[4];
} swarp_stabilize_report;

/** @brief Exact minimal enclosing sphere of the split frustum [n_i, f_i] of a
 *  camera (closed form: by the frustum's two mirror symmetries the centre
 *  lies on the view axis at depth min(f_i, (n_i + f_i)(1 + k^2)/2), k^2 =
 *  tan^2(fovy/2)(1 + aspect^2)), and the centroid sphere engines use.
 *  [RHS] §3.5 exact solution (ZZB09).
 *  @param cam      camera (near/far ignored; the split range is n_i, f_i)
 *  @param n_i, f_i split range, 0 < n_i < f_i
 *  @param[out] out_center world centre; @param[out] out_radius radius
 *  (> 0: at least the smallest positive double, for a range of a few
 *  subnormals); @param[out] out_centroid_radius may be NULL (>= radius)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV, SWARP_ERR_ZERO_VECTOR,
 *          SWARP_ERR_OUT_OF_RANGE (aspect <= 0), SWARP_ERR_DEGENERATE (up
 *          parallel to dir), SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OVERFLOW
 *          (the sphere's radius or centre exceeds DBL_MAX, e.g. f tan(fovy/2)
 *          aspect > DBL_MAX). */
SWARP_API swarp_status swarp_stabilize_sphere(const swarp_camera* cam, double n_i, double f_i,
                                              swarp_vec3* out_center, double* out_radius,
                                              double* out_centroid_radius);

/** @brief Light-space basis of a directional light used by the stabiliser:
 *  rows of out_view are u (right), v (up), w = -light direction, each unit;
 *  out_view maps origin-relative world coordinates to light view space (a
 *  right-handed view looking along the light).  It depends on the light
 *  direction only, never on the camera, so texels keep their orientation.
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_ZERO_VECTOR. */
SWARP_API swarp_status swarp_stabilize_light_view(const swarp_vec3* light_dir, swarp_mat4* out_view);

/** @brief Stabilised (flicker-free) uniform light matrix of one split for a
 *  directional light.  [RHS] §3.5 (ZZB09).
 *  SPHERE: the map covers the split frustum's exact minimal sphere (constant
 *  world size 2 r res/(res - 1), rounded up to 2^-20 relative so ulp-level
 *  wobble of n_i, f_i leaves it bit-identical); LEVELS: the light-space box of body_points
 *  with each axis' size rounded up to a multiple of level_max_size/levels;
 *  NONE: that box unquantised and unsnapped.  SPHERE and LEVELS snap the
 *  light-space map centre to whole texels relative to opt->origin, in double,
 *  so a world point's texel coordinates change by whole numbers only and
 *  jitter does not grow with the distance from the world origin.
 *  Depth covers the sphere / body and, toward the light, the scene box.
 *  out_matrix maps ORIGIN-RELATIVE world coordinates (p - origin) to clip
 *  space (large-world rendering); for origin = 0 it is the ordinary matrix.
 *  @param cam        camera; @param n_i, f_i split range (0 < n_i < f_i)
 *  @param light_dir  direction the light travels (non-zero)
 *  @param body_points world points of the split's body B_i (LEVELS, NONE:
 *                     count >= 1 required; SPHERE: may be NULL, 0)
 *  @param scene      scene box (may be NULL): extends depth toward the light
 *  @param res        map resolution in texels (>= 2)
 *  @param opt        options (may be NULL = defaults)
 *  @param[out] out_matrix  the light matrix; @param[out] out_report may be NULL
 *  @return SWARP_OK, SWARP_INFO_LEVEL_ABOVE_RANGE, SWARP_INFO_CASTERS_CLAMPED
 *          (the scene box reaches more than 1e10 times the map's size toward
 *          the light: the depth window stops there and casters beyond rely on
 *          depth clamping; outranks LEVEL_ABOVE_RANGE), SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV,
 *          SWARP_ERR_ZERO_VECTOR, SWARP_ERR_RESOLUTION, SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE,
 *          SWARP_ERR_DEGENERATE, SWARP_ERR_OVERFLOW (finite arguments but a
 *          matrix entry or texel size beyond DBL_MAX: coordinates near
 *          DBL_MAX, or an extent tiny against the coordinates). */
SWARP_API swarp_status swarp_stabilize_directional(const swarp_camera* cam, double n_i, double f_i,
                                                   const swarp_vec3* light_dir,
                                                   const swarp_vec3* body_points, size_t body_count,
                                                   const swarp_aabb* scene, uint32_t res,
                                                   const swarp_stabilize_options* opt,
                                                   swarp_mat4* out_matrix,
                                                   swarp_stabilize_report* out_report);

/** @brief Offset snapping for a caller's own uniform light matrix ([RHS]
 *  §3.5, the offset problem): shifts the clip-space translation by less than
 *  half a texel so that `origin` lands on a texel corner.  While the matrix's
 *  scale and orientation stay the same (e.g. quantised with LEVELS), every
 *  world point then moves by whole texels between frames.  Done in double on
 *  (origin-relative) coordinates.
 *  @param[in] m  world -> clip matrix of a uniform map (last row 0 0 0 w)
 *  @param res_s, res_t  map resolution in texels (> 0)
 *  @param[in] origin  snapping origin (world)
 *  @param[out] out  the snapped matrix (may alias m)
 *  @return SWARP_OK, SWARP_ERR_STABILIZE_WARPED (m is projective: a warped
 *          map has no uniform texel grid), SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_RESOLUTION, SWARP_ERR_SINGULAR
 *          (w = 0). */
SWARP_API swarp_status swarp_stabilize_snap_matrix(const swarp_mat4* m, double res_s, double res_t,
                                                   const swarp_vec3* origin, swarp_mat4* out);

/* ---- bias, [KOZ] §14.2.3 ------------------------------------------------ */

/** A shadow map as the bias functions see it: the final world -> clip matrix
 *  (uniform or warped, per split), its resolution and clip depth range.
 *  "Depth units" below are WINDOW depth d in [0, 1] (the value stored in the
 *  depth texture): d = (z_ndc + 1)/2 for [-1, 1], d = z_ndc for [0, 1] and
 *  reversed-Z.  A depth bias is d(p) - d(p moved toward the light), the
 *  amount to subtract from the receiver's d before the compare: positive
 *  for the LESS test of [-1, 1] and [0, 1], negative for reversed-Z's
 *  GREATER test (as a rasteriser's depth bias is negated there). */
typedef struct swarp_bias_map {
    swarp_mat4 world_to_clip;
    double res_s;  /**< texels along clip x */
    double res_t;  /**< texels along clip y */
    swarp_depth_range depth;
    uint32_t _reserved0;
    uint32_t _reserved[4];
} swarp_bias_map;

/** @brief World-space size of the texel at p ([KOZ] §14.2.3): p is mapped to
 *  the map, shifted by one texel along s (and t) at constant depth and
 *  mapped back; the lengths of the world displacements are L_s and L_t.
 *  Exact for warped maps at any point (finite one-texel step, no centre-of-
 *  map approximation).  L_texel = max(L_s, L_t).
 *  @param[out] out_L_texel, out_L_s, out_L_t (each may be NULL, not all)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_RESOLUTION, SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_SINGULAR,
 *          SWARP_ERR_BEHIND_PROJECTION. */
SWARP_API swarp_status swarp_bias_texel_size(const swarp_bias_map* map, const swarp_vec3* p,
                                             double* out_L_texel, double* out_L_s, double* out_L_t);

/** @brief Unit vector from p toward the light (the L of [KOZ] §14.2.3):
 *  -direction for a directional light, (position - p)/|.| for a point light.
 *  @param[in] light, p; @param[out] out_L unit vector
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,
 *          SWARP_ERR_ZERO_VECTOR (zero direction, point light at p). */
SWARP_API swarp_status swarp_bias_to_light(const swarp_light* light, const swarp_vec3* p,
                                           swarp_vec3* out_L);

/** @brief [KOZ] §14.2.3 world-space bias: P_biased = P + L (a + b L_texel),
 *  L the unit vector toward the light, L_texel from swarp_bias_texel_size.
 *  The point moves toward the light by exactly a + b L_texel world units.
 *  @param a  constant bias, world units; @param b  bias per texel size
 *  (dimensionless); a + b L_texel must be >= 0 (else SWARP_ERR_OUT_OF_RANGE)
 *  @param[out] out_p  biased point; @param[out] out_amount may be NULL
 *  @return as swarp_bias_texel_size, plus SWARP_ERR_OUT_OF_RANGE,
 *          SWARP_ERR_ZERO_VECTOR (point light at p). */
SWARP_API swarp_status swarp_bias_kozlov(const swarp_bias_map* map, const swarp_light* light,
                                         const swarp_vec3* p, double a, double b,
                                         swarp_vec3* out_p, double* out_amount);

/** @brief Normal-offset bias: P' = P + N k L_texel (1 - N.L), N the unit
 *  normal, L the unit vector to the light, N.L clamped to [0, 1] (a back-
 *  facing normal gives SWARP_INFO_BACKFACING and the full offset k L_texel).
 *  @param k  offset in texels (>= 0)
 *  @param[out] out_p; @param[out] out_amount offset length in world units
 *  (may be NULL).
 *  @return SWARP_OK, SWARP_INFO_BACKFACING, SWARP_ERR_OUT_OF_RANGE (k < 0),
 *          SWARP_ERR_ZERO_VECTOR (normal), and the errors of
 *          swarp_bias_texel_size and swarp_bias_to_light. */
SWARP_API swarp_status swarp_bias_normal_offset(const swarp_bias_map* map, const swarp_light* light,
                                                const swarp_vec3* p, const swarp_vec3* normal,
                                                double k, swarp_vec3* out_p, double* out_amount);

/** @brief Constant plus slope-scaled depth bias, given in WORLD units and
 *  converted to the map's depth units at p:
 *  world bias  = c + s L_texel tan(acos(N.L))  (tan clamped to 10; the depth
 *  step of a receiver tilted by the angle between N and L across one texel),
 *  depth bias  = window-depth difference between p and p moved by the world
 *  bias toward the light (exact for warped maps; linear for uniform maps).
 *  @param c  constant, world units (>= 0); @param s slope scale (>= 0)
 *  @param[out] out_world_bias, out_depth_bias (either may be NULL, not both)
 *  @return as swarp_bias_normal_offset. */
SWARP_API swarp_status swarp_bias_slope_scaled(const swarp_bias_map* map, const swarp_light* light,
                                               const swarp_vec3* p, const swarp_vec3* normal,
                                               double c, double s, double* out_world_bias,
                                               double* out_depth_bias);

/** @brief Window depth per world unit toward the light at p: the factor that
 *  turns a world-space bias into the depth units of this split's map (minus
 *  the derivative of d along L at p, so > 0 for a forward map looking along
 *  the light and < 0 under reversed-Z, exactly the forward value negated).
 *  Uniform maps: constant per split.
 *  @param[out] out_depth_per_world window depth units per world unit
 *  @return SWARP_OK, SWARP_ERR_BEHIND_PROJECTION, and the argument errors of
 *          swarp_bias_texel_size and swarp_bias_to_light. */
SWARP_API swarp_status swarp_bias_depth_per_world(const swarp_bias_map* map, const swarp_light* light,
                                                  const swarp_vec3* p, double* out_depth_per_world);

/** @brief Receiver-plane depth bias: the depth gradient (dd/ds, dd/dt) in
 *  window depth per TEXEL of the receiver plane at p spanned by the world
 *  tangents tangent_a, tangent_b (e.g. dFdx/dFdy of the world position, or
 *  two edges of the triangle).  Exact derivative of the (possibly
 *  projective) map at p (under reversed-Z the gradient of the reversed d:
 *  the [0, 1] gradient negated).  A PCF tap offset by (ds, dt) texels compares
 *  against d + dd/ds ds + dd/dt dt.  GLSL twin in shaders/splits.glsl.
 *  @return as swarp_bias_texel_size; SWARP_ERR_DEGENERATE when the plane is
 *          seen edge-on by the light (its texel-space image is a line): the
 *          tangents' texel-space images parallel to 1e-12, or their
 *          determinant within its own rounding bound (the double evaluation
 *          of M p and M T cannot tell the plane from an edge-on one, e.g.
 *          a point far from the map's centre of projection). */
SWARP_API swarp_status swarp_bias_receiver_plane(const swarp_bias_map* map, const swarp_vec3* p,
                                                 const swarp_vec3* tangent_a,
                                                 const swarp_vec3* tangent_b, double out_grad[2]);

/* ---- cascades: split selection and blending, [RHS] §3.3.3 --------------- */

/** @brief View depth of a world point: (p - eye) . dir/|dir|, the z that
 *  swarp_cascade_select_depth and swarp_cascade_blend take (in a shader:
 *  -view_space_position.z).
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_ZERO_VECTOR, SWARP_ERR_OVERFLOW (the depth exceeds
 *          DBL_MAX: p and eye near opposite ends of the double range). */
SWARP_API swarp_status swarp_cascade_view_depth(const swarp_camera* cam, const swarp_vec3* p,
                                                double* out_depth);

/** @brief Split selection by eye depth (PSSM, ZSXL06; [RHS] §3.3.3):
 *  the i with splits[i] <= view_depth < splits[i+1] (a depth on a border
 *  belongs to the split that starts there; the far end to the last split).
 *  GLSL twin in shaders/splits.glsl.
 *  @param splits   m + 1 strictly increasing eye-space distances
 *  @param m        split count (1..SWARP_SPLIT_MAX_COUNT)
 *  @param view_depth  positive distance along the view direction
 *  @param[out] out_index
 *  @return SWARP_OK; SWARP_INFO_OUTSIDE_SPLITS (depth before the first or
 *          after the last split: the nearest split is written);
 *          SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE, SWARP_ERR_SPLIT_COUNT,
 *          SWARP_ERR_NOT_INCREASING. */
SWARP_API swarp_status swarp_cascade_select_depth(const double* splits, size_t m, double view_depth,
                                                  uint32_t* out_index);

/** @brief Split selection by best resolution (ZZB09; [RHS] §3.3.3): among
 *  the splits whose map covers p (w > 0, |x|, |y| <= w, depth inside the clip
 *  range) the one with the smallest world texel size L_texel at p (exact,
 *  swarp_bias_texel_size; ties go to the lower index).  GLSL twin in
 *  shaders/splits.glsl.
 *  @param maps  m split maps (world -> clip, resolution, depth range)
 *  @param fallback_index  written with SWARP_INFO_OUTSIDE_SPLITS when no map
 *                         covers p (pass the depth selection), < m
 *  @param[out] out_index; @param[out] out_L_texel (may be NULL; the chosen
 *  split's L_texel, 0 for the fallback)
 *  @return SWARP_OK, SWARP_INFO_OUTSIDE_SPLITS, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_SPLIT_COUNT, SWARP_ERR_OUT_OF_RANGE
 *          (fallback_index >= m), and the map errors of swarp_bias_texel_size. */
SWARP_API swarp_status swarp_cascade_select_best(const swarp_bias_map* maps, size_t m,
                                                 const swarp_vec3* p, uint32_t fallback_index,
                                                 uint32_t* out_index, double* out_L_texel);

/** @brief Cascade blend weight in a transition band: the last `band` fraction
 *  of each split's depth range (except the last split's) fades linearly into
 *  the next split.  Writes the depth-selected split i and the weight w of
 *  split i; the shader mixes shadow_i w + shadow_{i+1} (1 - w).  w = 1
 *  outside the bands, w -> 0 at the border, so the result is continuous.
 *  GLSL twin in shaders/splits.glsl.
 *  @param band  fraction of each split's length, in [0, 1) (0: hard switch)
 *  @return as swarp_cascade_select_depth; SWARP_ERR_OUT_OF_RANGE for band. */
SWARP_API swarp_status swarp_cascade_blend(const double* splits, size_t m, double view_depth,
                                           double band, uint32_t* out_index, double* out_weight);

/* ---- cascades: split distances and the configuration's error curve ----- */

typedef enum swarp_split_scheme {
    SWARP_SCHEME_DEFAULT = 0,   /**< swarp_cascade_setup unstabilised: = MEASURED;
                                     stabilised, and swarp_cascade_splits (no scene):
                                     PRACTICAL with lambda 0.5 (PSSM, ZSXL06) */
    SWARP_SCHEME_UNIFORM = 1,   /**< [RHS] (3.6) */
    SWARP_SCHEME_LOG = 2,       /**< [RHS] (3.7) */
    SWARP_SCHEME_PRACTICAL = 3, /**< [RHS] (3.8), lambda as given (0 = uniform) */
    SWARP_SCHEME_PSEUDO = 4,    /**< [RHS] (4.1): practical over [n_p, f_p] */
    SWARP_SCHEME_MEASURED = 5,  /**< swarp_cascade_setup only: the practical lambda in
                                     [0, 1] whose splits' worst measured sigma is least
                                     (golden-section search, 6 steps, plus lambda 0.5,
                                     0.95 and 1, on a cheap sampling; the choice measured in
                                     full); lambda ignored.  docs/splits.md */
    SWARP_SCHEME_FORCE_I32 = 0x7FFFFFFF
} swarp_split_scheme;

/** How to split [n, f].  Zero means default (4 splits, SWARP_SCHEME_DEFAULT). */
typedef struct swarp_split_options {
    uint32_t count;            /**< m, 1..SWARP_SPLIT_MAX_COUNT; 0 = 4 */
    swarp_split_scheme scheme;
    double lambda;             /**< PRACTICAL, PSEUDO: in [0, 1] */
    double pseudo_near;        /**< PSEUDO (and the warp of the FIRST split): n_p as a
                                    fraction of f - n measured from n, [0, 1) */
    double pseudo_far;         /**< PSEUDO (and the warp of the LAST split): f_p as a
                                    fraction of f - n measured from f; n_p + f_p < 1 */
    uint32_t _reserved[4];
} swarp_split_options;

/** @brief Split distances C_0 = n < C_1 < ... < C_m = f of a scheme, on the
 *  (adjusted, [RHS] §3.3.1) range [n, f], through the core schemes
 *  swarp_split_uniform/log/practical/pseudo.  PSEUDO converts the fractions
 *  to distances n + n_p (f - n) and f - f_p (f - n) for (4.1).
 *  @param[out] out  m + 1 distances; capacity >= m + 1 (SWARP_ERR_CAPACITY
 *  with the count written otherwise)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_NEAR_FAR, SWARP_ERR_SPLIT_COUNT, SWARP_ERR_OUT_OF_RANGE,
 *          SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,
 *          SWARP_ERR_CAPACITY, SWARP_ERR_INVALID_ARGUMENT (SWARP_SCHEME_MEASURED:
 *          it needs the camera, light and scene of swarp_cascade_setup).
 *          SWARP_SCHEME_DEFAULT here is PRACTICAL with lambda 0.5. */
SWARP_API swarp_status swarp_cascade_splits(double n, double f, const swarp_split_options* opt,
                                            double* out, size_t capacity, size_t* out_count);

/** @brief Warp parameter n' of each split for LiSPSM with an overhead light
 *  in the error model's frame: n_opt of [RHS] (3.2) with d = C_{i+1} - C_i,
 *  z_0 = C_i, z_1 = C_{i+1}; the first split uses the pseudo-near fraction
 *  and the last the pseudo-far fraction of (4.2) ([RHS] §4.2), when given.
 *  @param[out] out_n_primes m values.
 *  @return SWARP_OK and the errors of swarp_warp_nopt_pseudo. */
SWARP_API swarp_status swarp_cascade_nopt(const double* splits, size_t m, double pseudo_near,
                                          double pseudo_far, double* out_n_primes);

/** Worst-case sample count of swarp_cascade_error_curve. */
#define SWARP_CASCADE_CURVE_MAX(m, samples_per_split) ((m) * (samples_per_split))

/** @brief The error curve of a whole configuration ([RHS] §3.3.4, Fig. 3.15,
 *  3.18) through the core's piecewise model swarp_error_split_curve: for
 *  each split `samples_per_split` depths from C_i (the value just after the
 *  border: a border belongs to the split that starts there) up to the left
 *  limit at C_{i+1} (the last sample is nextafter(C_{i+1}, 0), f itself for
 *  the last split).  out_mx or out_mz may be NULL.
 *  @param samples_per_split >= 2
 *  @return SWARP_OK, SWARP_ERR_CAPACITY (count written), SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_OUT_OF_RANGE, and the errors of swarp_error_split_curve. */
SWARP_API swarp_status swarp_cascade_error_curve(const swarp_error_config* cfg,
                                                 const double* splits, const double* n_primes,
                                                 size_t m, size_t samples_per_split,
                                                 double* out_z, double* out_mx, double* out_mz,
                                                 size_t capacity, size_t* out_count);

/* ---- cascades: the one call, [RHS] §3.3-3.4 ----------------------------- */

/** Most splits swarp_cascade_setup computes (the largest atlas, Fig. 3.16c). */
#define SWARP_CASCADE_MAX_SPLITS 16

/** Warp strength of the splits 1.. of a cascade ([RHS] §3.4 "arbitrary
 *  warping": "adjust the warping strength for each split independently or
 *  based upon the variable first split according to the currently used split
 *  scheme"). */
typedef enum swarp_cascade_warp {
    SWARP_CASCADE_WARP_DEFAULT = 0,    /**< = EACH */
    SWARP_CASCADE_WARP_EACH = 1,       /**< every split its own: n_user[i] when given, else
                                            the setup's parameter on the split (n_opt ...) */
    SWARP_CASCADE_WARP_FROM_FIRST = 2, /**< split 0 as EACH (its n'_0); every split i >= 1
                                            with n_user[i] == 0 gets
                                            n'_i = n'_0 * nu_i / nu_0,  nu_i = C_i + sqrt(C_i C_{i+1})
                                            (n_opt of [RHS] (3.2) for the split's own range in
                                            the overhead frame, swarp_cascade_nopt): the first
                                            split's strength relative to its optimum carried
                                            through the scheme (log scheme: n'_0 (C_i / C_0)) */
    SWARP_CASCADE_WARP_FORCE_I32 = 0x7FFFFFFF
} swarp_cascade_warp;

/** Options of swarp_cascade_setup; a zeroed struct is a valid request
 *  (4 PSSM splits, LiSPSM n_opt per split, 2048² tiles, no stabilisation). */
typedef struct swarp_cascade_options {
    swarp_setup_options setup;         /**< technique and parameters for every split;
                                            map_width = atlas tile size.  param PSEUDO:
                                            pseudo_near/far are fractions of the whole
                                            adjusted range; pseudo-near acts on the FIRST
                                            split only, pseudo-far on the LAST ([RHS] §4.2) */
    swarp_split_options split;         /**< scheme and count (count 1..16) */
    swarp_stabilize_options stabilize; /**< mode != NONE needs technique UNIFORM and a
                                            directional light; its depth field is
                                            ignored (setup.depth_range is used).
                                            SPHERE and LEVELS split the camera's own
                                            near..z_far: no adjustment and no min_depth,
                                            since [RHS] §3.5 needs constant split
                                            ranges (the adjusted far moves with the
                                            camera and the texels would drift) */
    double kernel_world_size;          /**< r_l of [RHS] (3.9), world units; 0 = 1 */
    double n_user[SWARP_CASCADE_MAX_SPLITS]; /**< per-split warp: n' in eye units for
                                            split i (+INFINITY = uniform); 0 = use setup
                                            (or, FROM_FIRST, derived from split 0) */
    swarp_cascade_warp warp_per_split; /**< how splits 1.. get their warp strength */
    uint32_t _reserved[3];             /**< must be zero */
} swarp_cascade_options;

/** One split of a cascade. */
typedef struct swarp_cascade_split {
    double z_near, z_far;          /**< C_i, C_{i+1}: eye-space depth range */
    swarp_mat4 matrix;         /**< world -> split clip space (stabilised: takes p - origin) */
    swarp_mat4 atlas_matrix;   /**< tile.clip_to_atlas * matrix: world -> atlas texture
                                    coordinates (homogeneous; divide by w) */
    swarp_atlas_tile tile;     /**< viewport in texels and clip -> atlas matrix */
    double n_eye;              /**< warp parameter n' used (eye units); +inf uniform */
    double kernel_scale[2];    /**< s_i of [RHS] (3.9) for kernel_world_size */
    double max_mx, max_mz;     /**< Lloyd's model's maxima over [z_near, z_far], [RHS]
                                    (2.3)-(2.8) (overhead light, view axis) */
    double mx_start, mz_start; /**< values at C_i: just after the border into this split */
    double mx_end, mz_end;     /**< values at C_{i+1} with this split's map (just before) */
    double texel_size;         /**< stabilised: world texel size; else 0 */
    double depth_per_world;    /**< window depth per world unit toward the light at the
                                    centroid of B_i (swarp_bias_depth_per_world): converts
                                    a world-space bias to this split's depth units
                                    (constant over the split for uniform maps;
                                    negative under reversed-Z) */
    swarp_status status;       /**< this split's own (informational) status */
    uint32_t point_count;      /**< points of B_i */
    swarp_measured_error measured; /**< the measured error of matrix over the split frustum
                                        ∩ S (swarp_measure_max); zero with skip_measure */
    uint32_t _reserved[4];
} swarp_cascade_split;

/** Whole-cascade facts. */
typedef struct swarp_cascade_result {
    uint32_t split_count;
    uint32_t _pad;
    double view_near, view_far;  /**< adjusted near/far [RHS] §3.3.1 */
    double splits[SWARP_CASCADE_MAX_SPLITS + 1]; /**< C_0 .. C_m */
    double max_mx, max_mz;       /**< Lloyd's model's maxima of the whole configuration */
    swarp_atlas_info atlas;
    swarp_measured_error measured; /**< the worst split's measured error (max_m_s, max_m_t,
                                        max_sigma and at of the splits' maxima; samples and
                                        outside summed) */
    uint32_t _reserved[4];
} swarp_cascade_result;

/** @brief Cascaded (z-partitioned) shadow maps with any geometry technique.
 *  [RHS] §3.3-3.4, §4.1-4.2, §3.3.5, (3.9), §3.5.
 *  Adjusted near/far ([RHS] §3.3.1), split distances (swarp_cascade_splits),
 *  per split its body B_i and light matrix through swarp_setup_range (the
 *  split frustum instead of the view frustum, [RHS] §3.4; LiSPSM with the
 *  robust projection centre of §4.1 unless setup.center says otherwise),
 *  the atlas place and kernel scale, the stabilised matrix if asked for,
 *  and the error model's values per split.  With one split the result is
 *  swarp_setup's, bit for bit.  opts->setup is checked as swarp_setup checks its
 *  options, on every path (stabilised too).
 *  @param[in] cam, light, scene  as swarp_setup
 *  @param[in] opts   NULL or zeroed for defaults
 *  @param[out] out   whole-cascade facts
 *  @param[out] out_splits  one entry per split; capacity >= count
 *  @param[out] out_count   split count (also with SWARP_ERR_CAPACITY)
 *  o.warp_per_split FROM_FIRST: [RHS] §3.4 arbitrary warping, see
 *  swarp_cascade_warp.  o.setup.min_depth: [RHS] §4.3 measured min depth, as
 *  in swarp_setup (not for stabilised cascades).  o.split.scheme DEFAULT
 *  (unstabilised) or MEASURED: the split positions are the practical
 *  scheme's on the adjusted range (after min_depth) with the λ whose worst
 *  split measures least (SWARP_SCHEME_MEASURED, docs/splits.md); MEASURED
 *  with stabilisation is SWARP_ERR_INVALID_ARGUMENT (its ranges must not
 *  move with the view), DEFAULT with stabilisation is PRACTICAL λ = 0.5.
 *  @return SWARP_OK or the first informational status of a split
 *          (SWARP_INFO_SPLIT_NO_SCENE: LEVELS, a split of the constant
 *          range misses the scene box and its map covers the split frustum);
 *          SWARP_ERR_STABILIZE_WARPED, SWARP_ERR_STABILIZE_LIGHT,
 *          SWARP_ERR_INVALID_ARGUMENT (MEASURED stabilised),
 *          SWARP_ERR_SPLIT_COUNT (count > 16), SWARP_ERR_SPLIT_EMPTY,
 *          SWARP_ERR_CAPACITY, and the errors of swarp_setup,
 *          swarp_cascade_splits and swarp_stabilize_directional (with
 *          stabilisation: SWARP_ERR_OVERFLOW when the split's sphere or
 *          matrix exceeds DBL_MAX). */
SWARP_API swarp_status swarp_cascade_setup(const swarp_camera* cam, const swarp_light* light,
                                           const swarp_aabb* scene,
                                           const swarp_cascade_options* opts,
                                           swarp_cascade_result* out,
                                           swarp_cascade_split* out_splits, size_t capacity,
                                           size_t* out_count);

/* ======================================================================== */
/* 7. Filtering: VSM, layered VSM, EVSM, MSM, PCF and PCSS                  */
/* ======================================================================== */
/*
 * Filtered shadows: the maths an engine mirrors in its shaders (GLSL twins in
 * shaders/filtering.glsl, derivations in docs/filtering.md).  Depths are light-space depths; "t" is the depth of the
 * receiver being shaded, and visibility is the lit fraction P(X >= t) of the
 * filter region (a texel at exactly the receiver depth counts as lit).
 */

/* ---- variance shadow maps ------------------------------------------------ */

/** @brief Moments of one depth sample, [VSM] (3.1): out = (x, x^2).
 *  Filtering (averaging) these over a region gives M_1 = E[x], M_2 = E[x^2].
 *  Also the moments of a warped depth: pass the warped value.
 *  @param[in] x  depth (any finite value; VSMs usually store [0, 1])
 *  @param[out] out_moments  (M_1, M_2)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE. */
SWARP_API swarp_status swarp_vsm_moments(double x, double out_moments[2]);

/** @brief Chebyshev's one-tailed bound p_max(t), [VSM] (3.2)-(3.3):
 *  mu = M_1, sigma2 = max(M_2 - M_1^2, min_variance),
 *  p_max = sigma2 / (sigma2 + (t - mu)^2) for t > mu, and 1 for t <= mu.
 *  @param[in] moments  filtered (M_1, M_2), same depth units as t
 *  @param[in] t  receiver depth
 *  @param[in] min_variance  >= 0, depth units squared: the clamp that hides
 *             rounding of M_2 - M_1^2 (it also makes flat lit regions stay lit)
 *  @param[out] out_p_max  in [0, 1]: an upper bound of the lit fraction
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE (min_variance < 0). */
SWARP_API swarp_status swarp_vsm_chebyshev(const double moments[2], double t, double min_variance,
                                           double* out_p_max);

/** @brief Light-bleeding reduction by clamping ([VSM] §3.4, ref. [10] there),
 *  a separate step after the bound: out = linstep(amount, 1, p) =
 *  clamp((p - amount) / (1 - amount), 0, 1).  It darkens every penumbra: tails
 *  of the bound below `amount` vanish, the rest is stretched to [0, 1].
 *  @param[in] p  visibility in [0, 1]; @param[in] amount in [0, 1)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE. */
SWARP_API swarp_status swarp_vsm_reduce_bleeding(double p, double amount, double* out_p);

/* ---- layered VSM --------------------------------------------------------- */

/** Worst case layer count of the LVSM functions (splits hold N + 1 values). */
#define SWARP_LVSM_MAX_LAYERS 64

/* Splits, wherever an LVSM function takes them: N + 1 finite, strictly
 * increasing values with s_N - s_0 finite; otherwise SWARP_ERR_NON_FINITE,
 * SWARP_ERR_NOT_INCREASING or SWARP_ERR_OUT_OF_RANGE (range overflows). */

/** @brief Depth interval [p_i, q_i] of layer i with overlaps, [VSM] §4.1.1:
 *  L_0 = [s_0, s_1 + delta], L_i = [s_i - delta, s_{i+1} + delta],
 *  L_{N-1} = [s_{N-1} - delta, s_N] (layers counted from 0 here).
 *  @param[in] splits  N + 1 strictly increasing split depths s_0..s_N
 *  @param[in] n_layers N in 1..SWARP_LVSM_MAX_LAYERS; @param[in] i in 0..N-1
 *  @param[in] delta  overlap, 0 <= delta < thinnest layer
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_FILTER_LAYER_COUNT, SWARP_ERR_OUT_OF_RANGE (i >= N),
 *          SWARP_ERR_NOT_INCREASING, SWARP_ERR_FILTER_OVERLAP. */
SWARP_API swarp_status swarp_lvsm_layer_interval(const double* splits, uint32_t n_layers,
                                                 uint32_t i, double delta, double* out_p,
                                                 double* out_q);

/** @brief Layer warp phi_i(t), [VSM] (4.2): 0 for t <= p, (t - p)/(q - p)
 *  inside, 1 for t >= q.
 *  @param[in] p, q  layer interval, p < q
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE (q <= p). */
SWARP_API swarp_status swarp_lvsm_warp(double t, double p, double q, double* out_phi);

/** @brief Moments of a warped depth for layer [p, q]: (phi, phi^2), [VSM]
 *  (4.2) then (3.1).  Same statuses as swarp_lvsm_warp. */
SWARP_API swarp_status swarp_lvsm_moments(double t, double p, double q, double out_moments[2]);

/** @brief The layer holding depth t for the uniform scheme s_i = s_0 +
 *  (s_N - s_0) i / N, in closed form ([VSM] §4.1.3).  A depth on a split
 *  belongs to the layer that starts there; t outside [s_0, s_N] gives the
 *  first/last layer and SWARP_INFO_FILTER_DEPTH_CLAMPED.
 *  @return SWARP_OK, SWARP_INFO_FILTER_DEPTH_CLAMPED, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_FILTER_LAYER_COUNT,
 *          SWARP_ERR_NOT_INCREASING (s_N <= s_0). */
SWARP_API swarp_status swarp_lvsm_layer_uniform(double t, double s_0, double s_N,
                                                uint32_t n_layers, uint32_t* out_layer);

/** @brief The layer holding depth t for given split points (binary search of
 *  the monotonic split sequence, [VSM] §4.1.3).  Conventions and statuses as
 *  swarp_lvsm_layer_uniform; splits must be strictly increasing, and
 *  SWARP_ERR_OUT_OF_RANGE when the range s_N - s_0 overflows a double. */
SWARP_API swarp_status swarp_lvsm_layer_find(double t, const double* splits, uint32_t n_layers,
                                             uint32_t* out_layer);

/** @brief Transition band between adjacent layers ([VSM] §4.1.3): for t
 *  within `band` of an inner split s_j the visibility is
 *  (1 - w) V_{j-1} + w V_j with w = (t - (s_j - band)) / (2 band) rising
 *  linearly across the band; elsewhere lo = hi = the layer of t and w = 0.
 *  band = 0 switches blending off.
 *  @param[in] band  half width, 0 <= band < half the thinnest layer
 *  @param[out] out_layer_lo, out_layer_hi, out_w_hi
 *  @return as swarp_lvsm_layer_find, plus SWARP_ERR_FILTER_BAND. */
SWARP_API swarp_status swarp_lvsm_transition(double t, const double* splits, uint32_t n_layers,
                                             double band, uint32_t* out_layer_lo,
                                             uint32_t* out_layer_hi, double* out_w_hi);

/** @brief Full LVSM shading of a receiver at depth t ([VSM] §4.1): pick the
 *  layer (and its neighbour in a transition band), warp t with the layer's
 *  overlapped interval (4.2), apply Chebyshev (3.3) to the layer's filtered
 *  warped moments and blend.  The minimum variance is given in depth units
 *  and scaled by 1/(q - p)^2 into each layer's warped space.
 *  @param[in] layer_moments  2 N values: filtered (M_1, M_2) of layer i at
 *             [2i], [2i+1], made with swarp_lvsm_moments and the intervals of
 *             swarp_lvsm_layer_interval(splits, N, i, delta)
 *  @param[in] band  transition half width, 0 <= band <= delta
 *  @return SWARP_OK, SWARP_INFO_FILTER_DEPTH_CLAMPED, and the errors of the
 *          functions above (SWARP_ERR_FILTER_BAND for band > delta). */
SWARP_API swarp_status swarp_lvsm_visibility(const double* layer_moments, const double* splits,
                                             uint32_t n_layers, double delta, double band,
                                             double t, double min_variance,
                                             double* out_visibility);

/** @brief Second-occluder depth estimate mu + sigma ([VSM] §4.1.2), exact
 *  (= max(a, b)) for two depths at coverage 1/2.  sigma2 < 0 (rounding of a
 *  filtered VSM) counts as 0.
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE. */
SWARP_API swarp_status swarp_lvsm_second_occluder(double mu, double sigma2, double* out_depth);

/** Options of swarp_lvsm_lloyd; zero means default. */
typedef struct swarp_lloyd_options {
    uint32_t max_iterations; /**< bound on relaxation steps; 0 = 100 */
    uint32_t _pad0;          /**< must be 0 */
    double weight_clamp_lo;  /**< weights are clamp(sigma2, lo, hi); 0 = no low clamp */
    double weight_clamp_hi;  /**< 0 = no high clamp; else >= weight_clamp_lo */
    double tolerance;        /**< converged when no split moves more than this
                                  (depth units); 0 = 1e-9 (s_N - s_0) */
    uint32_t _reserved[4];
} swarp_lloyd_options;

/** What swarp_lvsm_lloyd did. */
typedef struct swarp_lloyd_report {
    uint32_t iterations; /**< relaxation steps taken (teleports included) */
    uint32_t teleports;  /**< empty clusters repaired by teleportation */
    uint32_t converged;  /**< 1 if the last step moved no split more than tolerance */
    uint32_t _pad0;
    double max_shift;    /**< largest split movement in the last step */
} swarp_lloyd_report;

/** @brief Layer placement by weighted Lloyd relaxation, [VSM] §4.1.2: 1-D
 *  weighted k-means whose K = N - 1 "means" are the inner split points
 *  s_1..s_{N-1}.  Sample j has position mu_j + sigma_j (second-occluder
 *  estimate, clamped to [s_0, s_N]) and weight clamp(sigma2_j, lo, hi); each
 *  sample joins its nearest split point (ties to the lower one), each split
 *  moves to the weighted mean of its samples.  Teleportation: a cluster with
 *  zero total weight is removed (its two adjacent layers merge) and the
 *  heaviest cluster is split in two at its weighted mean -/+ its weighted
 *  standard deviation.  s_0 and s_N stay fixed; splits are kept strictly
 *  increasing (minimum gap max(1e-9 (s_N - s_0), 2 ulp(max(|s_0|, |s_N|))),
 *  at least one ulp when the range holds too few doubles for that).
 *  Deterministic, no allocation.
 *  @param[in] mu, sigma2  count samples of an unwarped VSM (e.g. 2x2 filtered)
 *  @param[in] opt  may be NULL (all defaults)
 *  @param[in] splits_in  N + 1 strictly increasing initial splits
 *  @param[out] splits_out N + 1 relaxed splits (may alias splits_in)
 *  @param[out] out_report may be NULL
 *  @return SWARP_OK (converged), SWARP_INFO_FILTER_NOT_CONVERGED,
 *          SWARP_INFO_FILTER_NO_WEIGHT, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_FILTER_NO_SAMPLES,
 *          SWARP_ERR_FILTER_LAYER_COUNT, SWARP_ERR_NOT_INCREASING,
 *          SWARP_ERR_OUT_OF_RANGE (bad clamps or tolerance),
 *          SWARP_ERR_RESERVED_NONZERO. */
SWARP_API swarp_status swarp_lvsm_lloyd(const double* mu, const double* sigma2, size_t count,
                                        const swarp_lloyd_options* opt,
                                        const double* splits_in, uint32_t n_layers,
                                        double* splits_out, swarp_lloyd_report* out_report);

/* ---- exponential VSM ----------------------------------------------------- */

/** Storage format of the moments in the texture. */
typedef enum swarp_texel_format {
    SWARP_TEXEL_DEFAULT = 0, /**< = SWARP_TEXEL_FP32 */
    SWARP_TEXEL_FP16 = 1,    /**< IEEE binary16: 10 mantissa bits, max 65504 */
    SWARP_TEXEL_FP32 = 2,    /**< IEEE binary32 */
    SWARP_TEXEL_FORMAT_FORCE_I32 = 0x7FFFFFFF
} swarp_texel_format;

/** @brief Largest safe EVSM exponent c for a texel format ([VSM] §4.2): for
 *  depths x in [0, 1] the largest moment is e^{2c}, so c = (ln F_max - m)/2
 *  where F_max = (2 - 2^-p) 2^e_max is the format's largest finite value
 *  (computed from p mantissa bits and e_max) and m = 4 u (u = 2^-(p+1), the
 *  unit roundoff) leaves room for a few ulps of GPU exp() error.  Averaging
 *  (filtering) never exceeds the largest texel, so filtered moments stay
 *  finite too.  fp32 gives c ~ 44.36, fp16 c ~ 5.545.
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_UNKNOWN_ENUM. */
SWARP_API swarp_status swarp_evsm_max_exponent(swarp_texel_format format, double* out_c);

/** @brief EVSM moments of depth x ([VSM] §4.2): positive warp e^{c_pos x}
 *  and negative warp -e^{-c_neg x}, each with its square:
 *  out = (e^{c_pos x}, e^{2 c_pos x}, -e^{-c_neg x}, e^{-2 c_neg x}).
 *  @param[in] c_pos, c_neg  in (0, 354]: e^{2c} finite in double, so every
 *                 depth in [0, 1] has finite moments
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (x, c_pos or
 *          c_neg NaN/Inf), SWARP_ERR_FILTER_EXPONENT (c_pos or c_neg <= 0 or
 *          > 354, or a moment e^{2c|x|} overflows for this x, |x| > 1). */
SWARP_API swarp_status swarp_evsm_moments(double x, double c_pos, double c_neg,
                                          double out_moments[4]);

/** @brief EVSM visibility ([VSM] §4.2): Chebyshev (3.3) on the positive and
 *  on the negative warp, then the minimum of both upper bounds.  The minimum
 *  variance is given in depth units and mapped into each warp by its
 *  derivative at t: min_variance (c e^{+-c t})^2.
 *  @param[in] moments  filtered moments laid out as swarp_evsm_moments
 *  @return as swarp_evsm_moments (SWARP_ERR_FILTER_EXPONENT also when
 *          e^{c|t|} overflows for the receiver depth t), plus
 *          SWARP_ERR_OUT_OF_RANGE (min_variance < 0) and SWARP_ERR_NON_FINITE
 *          (a moment, t or min_variance NaN/Inf; finite moments of any
 *          magnitude and a floor min_variance (c e^{c t})^2 beyond DBL_MAX
 *          give a bound in [0, 1]). */
SWARP_API swarp_status swarp_evsm_visibility(const double moments[4], double t, double c_pos,
                                             double c_neg, double min_variance,
                                             double* out_visibility);

/* ---- moment shadow maps -------------------------------------------------- */

/** Moment bias Peters & Klein 2015 ("Moment Shadow Mapping", I3D) use for
 *  moments stored with 16 bits each; double or fp32 storage tolerates less. */
#define SWARP_MSM_ALPHA_DEFAULT 3.0e-5

/** @brief The four power moments of a depth z in [0, 1]: (z, z^2, z^3, z^4)
 *  (Peters & Klein 2015, §3; the optimised quantisation transform is a GPU
 *  storage detail and not part of this).
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE (z outside [0, 1]). */
SWARP_API swarp_status swarp_msm_moments(double z, double out_b[4]);

/** @brief Moment bias (Peters & Klein 2015, Algorithm 3 step 1):
 *  b' = (1 - alpha) b + alpha (1/2, 1/2, 1/2, 1/2), a blend toward the
 *  moments of half the mass at 0 and half at 1, which keeps the Hankel matrix
 *  positive definite after quantisation.
 *  @param[in] alpha in [0, 1]
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE. */
SWARP_API swarp_status swarp_msm_bias(const double b[4], double alpha, double out_b[4]);

/** @brief Hamburger 4-moment shadow bound (Peters & Klein 2015, Algorithm 3):
 *  solve B c = (1, z_f, z_f^2) with the Hankel matrix B of (1, b_1..b_4)
 *  (Cholesky), take the roots z_2 <= z_3 of c_1 + c_2 z + c_3 z^2, and the
 *  sharp lower bound G of the occluded fraction from the three-atom
 *  distribution at (z_f, z_2, z_3).  Visibility = 1 - G, clamped to [0, 1].
 *  When B is singular to rounding (one or two distinct depths, no bias) the
 *  distribution is determined by its moments and the exact discrete answer
 *  is returned with SWARP_INFO_FILTER_MSM_DEGENERATE.
 *  @param[in] b  filtered (and usually biased) moments
 *  @param[in] z_f  receiver depth
 *  Moments with b_2 < b_1^2 (rounding) count as a single depth at b_1; in
 *  the degenerate branch a receiver within ~1e-7 (relative) of a recovered
 *  depth counts as at it, hence lit (recovered depths carry rounding).
 *  @return SWARP_OK, SWARP_INFO_FILTER_MSM_DEGENERATE, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE (a NaN/Inf input, or recovered depths that
 *          overflow; moments and z_f of any magnitude are first rescaled by a
 *          power of two, the bound being invariant under depth scaling),
 *          SWARP_ERR_OUT_OF_RANGE
 *          (b_2 < 0 or b_4 < 0: not moments of any distribution). */
SWARP_API swarp_status swarp_msm_visibility(const double b[4], double z_f,
                                            double* out_visibility);

/* ---- PCF and PCSS -------------------------------------------------------- */

/** Worst case point count of swarp_pcf_poisson_disk. */
#define SWARP_PCF_MAX_SAMPLES 256

/** @brief Poisson-disk sample set in the unit disk for PCF ([RHS] §3.6,
 *  after Fernando's PCSS), deterministic from a seed: Mitchell's best
 *  candidate (each new point is the candidate farthest from the points so
 *  far) with a splitmix64 generator.  Writes count points as x, y pairs.
 *  @param[in] seed  any value; the same seed gives the same set everywhere
 *  @param[in] count 1..SWARP_PCF_MAX_SAMPLES points
 *  @param[in] candidates  candidates per point, 0 = 32
 *  @param[out] out_xy  2 * count doubles; capacity counts POINTS
 *  @param[out] out_count  count (or the needed count with SWARP_ERR_CAPACITY)
 *  @param[out] out_min_distance  smallest pairwise distance (0 for count = 1)
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_OUT_OF_RANGE,
 *          SWARP_ERR_CAPACITY. */
SWARP_API swarp_status swarp_pcf_poisson_disk(uint64_t seed, uint32_t count, uint32_t candidates,
                                              double* out_xy, size_t capacity,
                                              size_t* out_count, double* out_min_distance);

/** @brief PCSS blocker-search width ([RHS] §3.6, Fernando 2005): by similar
 *  triangles between the light of width w_light (measured on the light's
 *  near plane, e.g. in shadow-map UV) and the receiver at depth d_r,
 *  w_search = w_light (d_r - n_light) / d_r.
 *  @param[in] n_light  light near-plane distance, 0 < n_light <= d_r
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE. */
SWARP_API swarp_status swarp_pcss_search_width(double w_light, double n_light, double d_r,
                                               double* out_w_search);

/** @brief PCSS penumbra width w = (d_r - d_b) w_light / d_b ([RHS] §3.6,
 *  Fernando 2005), d_b the average blocker depth, d_r the receiver depth
 *  (both distances from the light), in the units of w_light.
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_OUT_OF_RANGE (w_light < 0),
 *          SWARP_ERR_FILTER_BLOCKER (d_b <= 0 or d_b > d_r),
 *          SWARP_ERR_OVERFLOW (the width exceeds DBL_MAX). */
SWARP_API swarp_status swarp_pcss_penumbra(double d_r, double d_b, double w_light,
                                           double* out_w_penumbra);

/** @brief PCSS filter width on the shadow map's near plane: the penumbra at
 *  the receiver projected back, w_filter = w_penumbra n_light / d_r.
 *  @return as swarp_pcss_search_width. */
SWARP_API swarp_status swarp_pcss_filter_width(double w_penumbra, double n_light, double d_r,
                                               double* out_w_filter);

/* ======================================================================== */
/* 8. Experimental API (define SWARP_EXPERIMENTAL_API to use it)            */
/* ======================================================================== */
/*
 * Not yet promised: the declarations below may change in a minor release.
 * The library exports them in every build; a caller that wants them
 * defines SWARP_EXPERIMENTAL_API before including this header.  The types
 * the stable structs above need are all declared above.
 */
#ifdef SWARP_EXPERIMENTAL_API

/* ---- 9.1 convex polyhedra and the intersection bodies H and B ----------- */
/*
 * A convex polyhedron with a fixed capacity (no allocation).  Vertices are a
 * point set; each face is a loop of vertex indices, counter-clockwise seen
 * from outside, with its plane (outward unit normal, a*x+b*y+c*z+d = 0,
 * outside where the expression is > 0).  Degenerate polyhedra are valid: a
 * flat one (a polygon) has two opposite faces over the same vertices, a
 * point has one vertex and no face, an empty one has no vertex.
 *
 * Clipping never leaves two vertices closer than SWARP_POLY_EPS_REL times the
 * polyhedron's scale (largest absolute coordinate, so the tolerance follows
 * double precision for large worlds): 1e-12 is ~4000 ulps of a coordinate,
 * far above rounding noise and far below any feature worth keeping.
 *
 * Capacity: V ∩ S has at most 12 faces and 20 vertices; the bodies B built
 * from it stay far below the maxima (docs/geometry.md gives the counts).
 * sizeof(swarp_polyhedron) == SWARP_POLY_SIZE bytes (7 432 bytes).
 */
#define SWARP_POLY_MAX_VERTICES SWARP_BODY_MAX_POINTS /* 128 */
#define SWARP_POLY_MAX_FACES 64
#define SWARP_POLY_MAX_FACE_VERTICES 32
#define SWARP_POLY_EPS_REL 1e-12
#define SWARP_POLY_SIZE                                                          \
    (8 + SWARP_POLY_MAX_VERTICES * 24 + SWARP_POLY_MAX_FACES * 32 +               \
     SWARP_POLY_MAX_FACES * 4 + SWARP_POLY_MAX_FACES * SWARP_POLY_MAX_FACE_VERTICES)

typedef struct swarp_polyhedron {
    uint32_t vertex_count;
    uint32_t face_count;
    swarp_vec3 vertices[SWARP_POLY_MAX_VERTICES];
    swarp_plane planes[SWARP_POLY_MAX_FACES];          /**< outward, unit normal */
    uint32_t face_vertex_count[SWARP_POLY_MAX_FACES];
    uint8_t face_vertices[SWARP_POLY_MAX_FACES][SWARP_POLY_MAX_FACE_VERTICES];
} swarp_polyhedron;

/** @brief The box as a polyhedron (8 vertices, 6 faces; fewer if flat).
 *  @param[in] box min <= max componentwise, finite.
 *  @param[out] out the polyhedron.
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_BOX_INVERTED. */
SWARP_API swarp_status swarp_poly_from_aabb(const swarp_aabb* box, swarp_polyhedron* out);

/** @brief The camera's view frustum V between view depths near and far
 *  (world units along cam->dir; cam->z_near/far are ignored, so a split
 *  frustum [RHS] §3.3 is the same call).  A face narrower than the
 *  clipper's tolerance (SWARP_POLY_EPS_REL of the corners' scale; the near
 *  face of a needle frustum) is held at 2 tolerances from the axis: a
 *  superset of V by at most that, never a welded (thinner) one.
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR, SWARP_ERR_ZERO_VECTOR,
 *          SWARP_ERR_DEGENERATE (up parallel to dir),
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE (aspect <= 0, or a
 *          corner beyond the double range: |eye| + far·|(1, tan, aspect·tan)|
 *          over DBL_MAX). */
SWARP_API swarp_status swarp_poly_from_camera_range(const swarp_camera* cam, double z_near,
                                                    double z_far, swarp_polyhedron* out);
/** @brief The camera's view frustum V between cam->z_near and cam->z_far. */
SWARP_API swarp_status swarp_poly_from_camera(const swarp_camera* cam, swarp_polyhedron* out);

/** @brief The frustum whose clip cube is mapped to world space by an inverse
 *  view-projection matrix (the 8 corners of the NDC cube, depth per
 *  depth_range: near face at NDC -1, 0, or 1 for reversed-Z, whose far
 *  face is at 0; an infinite reversed far plane maps to w = 0: DEGENERATE).
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_DEGENERATE (a corner maps to
 *          infinity: w <= 0). */
SWARP_API swarp_status swarp_poly_from_inverse_matrix(const swarp_mat4* inv_view_proj,
                                                      swarp_depth_range depth_range,
                                                      swarp_polyhedron* out);

/** @brief Keep the part of a convex polyhedron where a*x+b*y+c*z+d <= 0
 *  (the plane's normal points to the side removed).  out may equal in.
 *  @return SWARP_OK (possibly empty: vertex_count 0), SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_ZERO_VECTOR (zero normal),
 *          SWARP_ERR_CAPACITY (a maximum above would be exceeded). */
SWARP_API swarp_status swarp_poly_clip(const swarp_polyhedron* in, const swarp_plane* plane,
                                       swarp_polyhedron* out);

/** @brief in ∩ box (six clips).  out may equal in.
 *  @return as swarp_poly_clip; SWARP_ERR_BOX_INVERTED. */
SWARP_API swarp_status swarp_poly_clip_aabb(const swarp_polyhedron* in, const swarp_aabb* box,
                                            swarp_polyhedron* out);

/** @brief H = V ∩ S for the view depths [near, far].  [RHS] §3.1.1
 *  @return SWARP_OK, SWARP_ERR_BODY_EMPTY (the frustum misses the box,
 *          e.g. the camera looks away from it), SWARP_ERR_BOX_DEGENERATE,
 *          and the statuses of swarp_poly_from_camera_range. */
SWARP_API swarp_status swarp_body_h(const swarp_camera* cam, double z_near, double z_far,
                                    const swarp_aabb* scene, swarp_polyhedron* out_H);

/** @brief B from H.  [RHS] §3.1.1 (Fig. 3.2).  Directional light: H extruded
 *  against the light direction until it leaves S, then ∩ S.  Point light:
 *  conv(H ∪ {l}) ∩ S ∩ L, where L (cone_angle > 0) is the square pyramid
 *  with apex l, axis light->direction and half-angle cone_angle that
 *  circumscribes the spot cone (the spot's shadow-map frustum).
 *  @return SWARP_OK, SWARP_ERR_BODY_EMPTY, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_ZERO_VECTOR, SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE (cone angle, or B
 *          swept through a box reaching beyond DBL_MAX/4 leaves the double range). */
SWARP_API swarp_status swarp_body_from_h(const swarp_polyhedron* H, const swarp_light* light,
                                         const swarp_aabb* scene, swarp_polyhedron* out_B);


/** @brief The receivers a light can reach: H ∩ L for a spot light (L the
 *  square pyramid around its cone, as in swarp_body_from_h), H itself for
 *  directional and omni lights.  Pass its vertices as the receivers of
 *  swarp_setup_points (pancaking, PSM unit cube clipping).  out may equal H.
 *  @return SWARP_OK, SWARP_ERR_BODY_EMPTY (the cone misses H), and the
 *          statuses of swarp_body_from_h's argument checks. */
SWARP_API swarp_status swarp_body_receivers(const swarp_polyhedron* H, const swarp_light* light,
                                            swarp_polyhedron* out);


/* ---- 9.2 light frames that follow the previous frame -------------------- */
/*
 * Continuity over the whole sphere of light directions (docs/geometry.md,
 * "Continuity over the whole sphere").  No stateless rule can give the light
 * view an up vector that is continuous in the light direction everywhere
 * (hairy-ball theorem): swarp_setup's rule is singular where
 * SWARP_FOCUS_BLEND_SIN says.  swarp_setup_follow takes the previous frame's
 * result and keeps the light frame coherent along ANY path of the light
 * (and of the camera):
 *
 *   h   = the previous up (light_view row 1; PSM: the light camera's right
 *         in post-perspective space) projected onto the plane perpendicular
 *         to the new light axis a;
 *   t   = ±v̂, v̂ = v_perp/|v_perp| ([RHS] §3.2.1 light-space alignment; PSM:
 *         the post-perspective x axis projected perpendicular to the light
 *         camera's axis), the sign that agrees with h;
 *   h' = h turned about a toward t by at most SWARP_FOLLOW_KAPPA · Δ, where
 *         Δ = angle(previous axis, a) + angle(previous view dir, view dir)
 *         (PSM: the angle the post-perspective axis turned).
 *
 * The frame changes per call by O(Δ), whatever the path; wherever the target
 * moves slower than κ·Δ (sin γ > 1/κ along a smooth path, γ ≥ 14.5° for
 * κ = 4) it is exactly the aligned frame.  LiSPSM then warps along the
 * frame's y axis with orientation σ = sign(y·v) and the strength of
 * γ_eff = asin|y·v| (as swarp_setup's warp does with its own frame), so it
 * is exactly [RHS]'s LiSPSM when aligned and fades to uniform where
 * y ⟂ v_perp (SWARP_INFO_FOLLOW_LAG says the frame lags).
 * The followed map may be turned 180° about the light axis relative to
 * swarp_setup's (y = -v̂); it is the same LiSPSM map, rotated.
 */
#define SWARP_FOLLOW_KAPPA 4.0

/** @brief swarp_setup with a light frame that follows the previous frame's
 *  continuously (no flips anywhere on the sphere of light directions).
 *  @param[in] cam, light, scene, opts  as swarp_setup
 *  @param[in] previous_cam  the camera of the previous frame (its view
 *                     direction lets the frame realign as the camera turns);
 *                     NULL: the same as cam (only the light's motion counts)
 *  @param[in] previous  the previous frame's result of swarp_setup or
 *                     swarp_setup_follow with the SAME technique and light
 *                     type; NULL: exactly swarp_setup's result (bit for bit).
 *                     Read: light_view's rotation rows; PSM also light_proj,
 *                     view_near, view_far and n_eye (with previous_cam's, or
 *                     cam's, fovy and aspect) to recover its light camera
 *  @param[out] out, out_points, out_count  as swarp_setup
 *  @return as swarp_setup, plus SWARP_INFO_FOLLOW_LAG (the frame is still
 *          turning toward the aligned one); SWARP_ERR_NON_FINITE (NaN/Inf in
 *          the rows of previous that are read), SWARP_ERR_ZERO_VECTOR (a zero
 *          row), SWARP_ERR_FOLLOW_FRAME (rows not orthonormal within 1e-6 or
 *          left-handed, or a PSM result whose ranges are invalid).  Outputs untouched on
 *          error.  [RHS] §3.2.1, [KOZ] §14.2.2 */
SWARP_API swarp_status swarp_setup_follow(const swarp_camera* cam, const swarp_light* light,
                                          const swarp_aabb* scene, const swarp_setup_options* opts,
                                          const swarp_camera* previous_cam,
                                          const swarp_setup_result* previous,
                                          swarp_setup_result* out, swarp_vec3* out_points,
                                          size_t capacity, size_t* out_count);

/** @brief swarp_focus_light_view whose up vector follows a previous light
 *  view continuously (the rule of swarp_setup_follow: the previous up turned
 *  toward ±v̂ by at most SWARP_FOLLOW_KAPPA times the angle the light axis
 *  and the view direction turned).  [RHS] §3.2.1
 *  @param[in] cam, light, axis  as swarp_focus_light_view
 *  @param[in] previous_cam   the previous frame's camera (NULL: cam)
 *  @param[in] previous_view  the previous light view (its rotation rows are
 *                            read); NULL: exactly swarp_focus_light_view
 *  @param[out] out_view      the light view
 *  @return as swarp_focus_light_view (SWARP_INFO_LIGHT_PARALLEL only with
 *          previous_view NULL), SWARP_INFO_FOLLOW_LAG, SWARP_ERR_ZERO_VECTOR,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_FOLLOW_FRAME (rows not a rigid
 *          right-handed frame within 1e-6), SWARP_ERR_OVERFLOW (as
 *          swarp_focus_light_view: a translation beyond DBL_MAX). */
SWARP_API swarp_status swarp_focus_light_view_follow(const swarp_camera* cam, const swarp_light* light,
                                                     const swarp_vec3* axis, const swarp_camera* previous_cam,
                                                     const swarp_mat4* previous_view, swarp_mat4* out_view);

/* ---- 9.3 lixel maps: plane-stabilised light matrices [LIXEL] ------------ */
/*
 * Plane-stabilised light matrices, [LIXEL] Chong & Gortler.  M_l maps world
 * points to LIGHT-IMAGE coordinates [x_l q, y_l q, z_l q, q] where (x_l, y_l)
 * are lixel coordinates (lixel centres at integers, like the viewer pixels
 * (0,0) .. (g-1, h-1)).  On the plane of interest P every point has the same
 * (x, y) in the viewer image (pixels) and in the light image (lixels).
 * The viewer-image pixel of a clip-space point is
 *   x_pix = (x_ndc + 1) g/2 - 1/2,  y_pix = (y_ndc + 1) h/2 - 1/2
 * (pixel centres at integers, pixel 0 centred half a pixel inside the edge).
 */

/** Options of swarp_lixel_matrix (zero means default). */
typedef struct swarp_lixel_options {
    /** Where the raised point p^4-hat lies on the ray from the corner point
     *  toward the light ([LIXEL] Fig. 2), as a fraction t in [0, 1):
     *  point light p-hat = (1-t) p + t l; directional light p-hat =
     *  p - t |p - eye| d/|d|.  0 = default 0.5.  It fixes the light-image
     *  near plane (z = -1) only; (x, y) do not depend on it. */
    double raise;
    uint32_t _reserved[4];
} swarp_lixel_options;

/** Optional details of swarp_lixel_matrix. */
typedef struct swarp_lixel_info {
    swarp_vec4 corners[4];     /**< p^1..p^4 homogeneous (w <= 0: behind / at infinity) */
    swarp_vec4 raised;         /**< p-hat, homogeneous, w = 1 */
    uint32_t raised_index;     /**< which corner (0..3) was raised; 3 (= p^4) when in front */
    uint32_t corners_in_front; /**< how many corner rays hit P in front of the eye */
    double conditioning;       /**< swarp_lixel_solve5's measure, (0, 1] */
    uint32_t _reserved[4];
} swarp_lixel_info;

/** @brief The 4x4 projective matrix fixed (up to scale) by five point
 *  correspondences M src[i] ~ dst[i] (no four coplanar).  [LIXEL] §2, via
 *  [Fau93]: both sets are mapped to the projective basis, in double, after a
 *  similarity normalisation of each set, with partial pivoting.
 *  @param[in] src five homogeneous points (w = 0 allowed: points at infinity)
 *  @param[in] dst five homogeneous image points
 *  @param[out] out_M the matrix, scaled so its largest |element| is 1
 *  @param[out] out_conditioning may be NULL: the smallest |det| of four of
 *         the five normalised points of either set, in [0, 1]; 0 = coplanar
 *  @return SWARP_OK; SWARP_INFO_LIXEL_ILL_CONDITIONED (conditioning < 1e-6
 *          or a constraint residual above 1e-9: the matrix is written);
 *          SWARP_ERR_LIXEL_COPLANAR (conditioning < 1e-13, or the finite
 *          points of a set within 64 eps |c| of their median centre c in
 *          median: two of them coincide to rounding), SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_solve5(const swarp_vec4 src[5], const swarp_vec4 dst[5],
                                          swarp_mat4* out_M, double* out_conditioning);

/** @brief Plane-stabilised light matrix M_l.  [LIXEL] (1), (2), (7)-(10)
 *  Rays through the corner pixels (2) hit P in p^1..p^4 (homogeneous, so a
 *  quad across infinity, Fig. 5, is fine); a corner in front of the eye (p^4
 *  when possible) is raised toward the light (Fig. 2); the light maps to
 *  [0,0,1,0] (1), p^1..p^3 to their own pixel with z = 1, the raised point
 *  with z = -1 ((7)-(10), (9) read as [(g-1)q, (h-1)q, 1q, q]).  The sign
 *  of the matrix is chosen so that q > 0 exactly on the part of P in front
 *  of the viewer (on P, q_l = c q_v with c > 0).
 *  @param[in] M_v viewer view-projection (world -> clip, OpenGL style)
 *  @param g, h viewer image width and height in pixels (>= 2)
 *  @param[in] light point (position) or directional (direction of travel)
 *  @param[in] plane the plane of interest P (normal non-zero)
 *  @param[in] opt may be NULL (defaults)
 *  @param[out] out_M_l world -> light image (lixels), largest |element| 1
 *  @param[out] out_info may be NULL
 *  @return SWARP_OK; informational SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY,
 *  _PLANE_PARALLEL_VIEW, _LIGHT_BEHIND_PLANE, _ILL_CONDITIONED (most
 *  important first: ill-conditioned, parallel, across infinity, behind);
 *  errors SWARP_ERR_LIXEL_PLANE_THROUGH_EYE, _LIGHT_ON_PLANE,
 *  _LIGHT_PARALLEL_PLANE, _PLANE_NOT_VISIBLE, SWARP_ERR_LIXEL_COPLANAR (the
 *  five constraint points of (1), (7)-(10) nearly coplanar: the solver's
 *  conditioning < 1e-13, reached only in near-degenerate configurations),
 *  SWARP_ERR_SINGULAR (M_v), SWARP_ERR_RESOLUTION, SWARP_ERR_ZERO_VECTOR, SWARP_ERR_OUT_OF_RANGE
 *  (raise), SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,
 *  SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_matrix(const swarp_mat4* M_v, uint32_t g, uint32_t h,
                                          const swarp_light* light, const swarp_plane* plane,
                                          const swarp_lixel_options* opt, swarp_mat4* out_M_l,
                                          swarp_lixel_info* out_info);

/** Integer light-image rectangle [x0, x1] x [y0, y1] (lixel centres,
 *  inclusive): width = x1 - x0 + 1 lixels. */
typedef struct swarp_lixel_rect {
    int32_t x0, y0, x1, y1;
    uint32_t width, height;
} swarp_lixel_rect;

/** Options of swarp_lixel_restrict (zero means default). */
typedef struct swarp_lixel_restrict_options {
    double scale_x;   /**< lixels per pixel along light-image x (0 = 1; < 1: fewer lixels) */
    double scale_y;   /**< lixels per pixel along y (0 = 1) */
    double twist;     /**< 2D rotation (radians, counter-clockwise) applied before
                           the bounding box; see swarp_lixel_twist_for_line */
    uint32_t max_size;/**< largest width or height accepted (0 = 16384) */
    /** Non-zero: keep only the rays that hit P inside the viewer's frustum
     *  ([LIXEL] §3, C_floor "within the viewer's frustum"): C's image is
     *  clipped to the viewer's pixel centres [0, view_width - 1] x
     *  [0, view_height - 1] first (on P the light image IS the viewer
     *  image); rays of C with q <= 0 are then allowed (clipped away).
     *  Needs M_l straight from swarp_lixel_matrix with g = view_width,
     *  h = view_height.  0 = no clipping. */
    uint32_t view_width;
    uint32_t view_height;
    uint32_t _reserved0;
    uint32_t _reserved[4];
} swarp_lixel_restrict_options;

#define SWARP_LIXEL_DEFAULT_MAX_SIZE 16384u

/** @brief Light-image restriction (Fig. 6): the smallest axis-aligned
 *  rectangle with integer corners enclosing the light image of the convex set
 *  of rays C, and M_l := A_l M_l where A_l = translate(-x0, -y0) ·
 *  scale(scale_x, scale_y) · rotate(twist) (rows x, y only).  [LIXEL] §2
 *  "Less of the plane".
 *  @param[in] M_l from swarp_lixel_matrix
 *  @param[in] C vertices of the convex polygon of rays: world points (w = 1,
 *         any light) or directions from a point light (w = 0); any w != 0 is
 *         divided out
 *  @param n number of vertices (>= 1)
 *  @param[in] opt may be NULL
 *  @param[out] out_rect the rectangle in the twisted/scaled image BEFORE
 *         the translation (so x0, y0 tell where it was)
 *  @param[out] out_A_l the 2D affine map as a 4x4 (may be NULL)
 *  @param[out] out_M_l A_l · M_l: lixel (0, 0) is the lower-left of the rectangle
 *  @return SWARP_OK; SWARP_ERR_LIXEL_RAY_OUTSIDE (a vertex has q <= 0,
 *  without view clipping), SWARP_ERR_LIXEL_EMPTY (nothing of C in view),
 *  SWARP_ERR_LIXEL_RECT_TOO_LARGE, SWARP_ERR_OUT_OF_RANGE (scale < 0, or
 *  an entry of A_l M_l would exceed DBL_MAX, e.g. scale near DBL_MAX),
 *  SWARP_ERR_INVALID_ARGUMENT (n = 0), SWARP_ERR_RESERVED_NONZERO,
 *  SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_restrict(const swarp_mat4* M_l, const swarp_vec4* C, size_t n,
                                            const swarp_lixel_restrict_options* opt,
                                            swarp_lixel_rect* out_rect, swarp_mat4* out_A_l,
                                            swarp_mat4* out_M_l);

/** @brief Twist angle that makes the light image of the world line through a
 *  and b horizontal, with the light image of `below` (a point on the side
 *  that should stay inside, e.g. on the floor in front of the wall) at
 *  smaller y.  [LIXEL] §3 (twist in A_floor).
 *  @param[in] M_l from swarp_lixel_matrix (before restriction)
 *  @param[in] a, b two world points of the line (q > 0 in M_l)
 *  @param[in] below a world point on the side that should map below the line
 *  @param[out] out_twist radians, for swarp_lixel_restrict_options.twist
 *  @return SWARP_OK; SWARP_ERR_LIXEL_TWIST_LINE (the line images to a point,
 *  `below` images onto the line -- within 1e-12 of the image coordinates,
 *  where its side is rounding noise -- or a point has q <= 0),
 *  SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_twist_for_line(const swarp_mat4* M_l, const swarp_vec3* a,
                                                  const swarp_vec3* b, const swarp_vec3* below,
                                                  double* out_twist);

/** @brief Factor M_l (after restriction, lixels 0..width-1 x 0..height-1)
 *  into M_l' = GLV · GLP for standard clipping.  [LIXEL] §2 ('M_l = GLV GLP')
 *  GLP is world -> clip (use it as the light's view-projection; w > 0 on
 *  the wanted side); GLV is the viewport NDC -> lixels
 *  (x = (x_ndc + 1) width/2 - 1/2) with depth passed through.  The depth
 *  row is remapped affinely (allowed by the paper's footnote): the raised
 *  point p-hat lands on the near plane (NDC -1, 0, or 1 under reversed-Z)
 *  and P at the fraction plane_depth of the depth range from the near
 *  plane (default 0.5; NDC 1 - plane_depth reversed), so geometry slightly
 *  behind P is not clipped.  (x, y, q) of M_l' equal those of M_l.
 *  @param[in] M_l restricted light matrix (lixels; depth as built by
 *         swarp_lixel_matrix: p-hat at z = -1, P at z = +1)
 *  @param width, height the map size in lixels (swarp_lixel_rect)
 *  @param depth_range clip depth convention (DEFAULT = [-1, 1])
 *  @param plane_depth in [0, 1): 0 = default 0.5
 *  @param[out] out_GLV viewport, NDC -> lixels
 *  @param[out] out_GLP world -> clip
 *  @return SWARP_OK; SWARP_ERR_RESOLUTION, SWARP_ERR_OUT_OF_RANGE
 *  (plane_depth outside [0, 1), or an entry of GLP would exceed DBL_MAX:
 *  possible once max|M_l| > DBL_MAX/3), SWARP_ERR_UNKNOWN_ENUM,
 *  SWARP_ERR_NON_FINITE (M_l or plane_depth not finite),
 *  SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_factor(const swarp_mat4* M_l, uint32_t width, uint32_t height,
                                          swarp_depth_range depth_range, double plane_depth,
                                          swarp_mat4* out_GLV, swarp_mat4* out_GLP);

/** Worst case of swarp_lixel_split: each output has at most n + 1 vertices. */
#define SWARP_LIXEL_SPLIT_MAX(n) ((n) + 1)

/** @brief Split the convex polygon of rays C_tot by the floor/wall line
 *  ([LIXEL] §3): C_floor holds the rays that hit the floor in front of the
 *  wall (on the side its normal points to), C_wall the others (they hit the
 *  wall above the line when the light is in the room).  The cut is the plane
 *  through the light and the floor/wall line.  Vertices as in
 *  swarp_lixel_restrict (all points or all directions; directions need a
 *  point light).
 *  @param[in] light the light (point or directional)
 *  @param[in] floor_plane, wall_plane the two planes of interest (normal of
 *         the wall pointing into the room)
 *  @param[in] C_tot n >= 3 vertices of the convex polygon of rays, in order
 *  @param[out] out_floor, out_wall capacity each; counts written (either
 *         may be 0 when C_tot lies on one side)
 *  @return SWARP_OK; SWARP_ERR_CAPACITY (needed counts written),
 *  SWARP_ERR_DEGENERATE (floor parallel to wall, or light on the line),
 *  SWARP_ERR_ZERO_VECTOR, SWARP_ERR_INVALID_ARGUMENT, SWARP_ERR_NON_FINITE,
 *  SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_split(const swarp_light* light, const swarp_plane* floor_plane,
                                         const swarp_plane* wall_plane, const swarp_vec4* C_tot,
                                         size_t n, swarp_vec4* out_floor, size_t floor_capacity,
                                         size_t* out_floor_count, swarp_vec4* out_wall,
                                         size_t wall_capacity, size_t* out_wall_count);

/** @brief Which shadow map to use for a world point ([LIXEL] §3, the CPU
 *  reference of the shader in docs/lixel.md): the first i whose clip matrix
 *  GLP[i] puts p inside (w > 0, |x| <= w, |y| <= w), else count (the
 *  conventional fallback map).
 *  @param[in] GLP count clip matrices (swarp_lixel_factor), in the order the
 *         shader tries them (e.g. floor, wall); may be NULL when count = 0
 *  @param count number of plane maps
 *  @param[in] p world point
 *  @param[out] out_index 0 .. count-1, or count for the fallback map
 *  @return SWARP_OK; SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_select(const swarp_mat4* GLP, size_t count, const swarp_vec3* p,
                                          uint32_t* out_index);

/* ---- 9.4 the planner ---------------------------------------------------- */
/*
 * The planner: from what the scene needs and what the caller can spend, the
 * cheapest chain (warp, splits, stabilisation, inverse projection, lixel
 * planes, filter) whose predicted error meets the budget, with a reason for
 * every choice and every effect left out.  docs/planning.md explains the
 * error and cost models, the candidates and the selection rule.
 *
 * Error model (docs/planning.md §2): Lloyd's metric [RHS] (2.3)-(2.8),
 * generalised from the overhead light to a light at angle γ to the view in
 * the plane spanned by light and view direction.  It reduces to (2.3)/(2.4)
 * exactly at γ = 90°, and its light-space extent is W_lz of [RHS] (3.5) for
 * γ >= Θ.  It is a model of the view axis in the overhead-light frame, not
 * of the matrices: swarp_plan_evaluate also builds the chain's matrices
 * (swarp_cascade_setup, options as docs/planning.md §9 maps the chain) and
 * reports their n' and measured error (swarp_measure_max) beside it.
 * Cost model (§3): per shadow pass overhead + texels × per-texel time
 * (calibrated: swarp_plan_cost_fit on measured passes), else a per-pass
 * constant (the caller's, or the uncalibrated default fitted to [RHS]
 * Table 7.1), + prefilter blur passes.
 * Selection (§4): by default the model proposes and the matrices decide:
 * the proposed chain is built and measured, and the model is re-calibrated
 * by that chain's measured/model ratio until the measurement meets the budget.
 */

/** Most shadow-map splits the planner considers (PSSM K = 1..16, [RHS] §3.3.5). */
#define SWARP_PLAN_MAX_SPLITS 16
/** Most planes of interest a swarp_scene_needs can declare. */
#define SWARP_PLAN_MAX_PLANES 4
/** Worst case of swarp_plan_explain()'s text, bytes including the NUL. */
#define SWARP_PLAN_EXPLAIN_MAX 4608

/** Light-bleeding risk of prefiltered (moment) shadow maps, [VSM] §3.4: how
 *  much occluders overlap at large depth ratios Δx/Δy (eq. (3.4)). */
typedef enum swarp_plan_bleed {
    SWARP_PLAN_BLEED_DEFAULT = 0,  /**< = SWARP_PLAN_BLEED_NONE */
    SWARP_PLAN_BLEED_NONE = 1,     /**< one occluder over a receiver: Chebyshev exact [VSM] §3.2 */
    SWARP_PLAN_BLEED_LOW = 2,      /**< occluders overlap at small depth ratios */
    SWARP_PLAN_BLEED_HIGH = 3,     /**< overlap at large depth ratios ([VSM] Fig. 3.5) */
    SWARP_PLAN_BLEED_EXTREME = 4,  /**< many overlaps at extreme ratios ([VSM] Fig. 4.3) */
    SWARP_PLAN_BLEED_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_bleed;

/** How swarp_plan judges whether a chain meets the error budget. */
typedef enum swarp_plan_by {
    SWARP_PLAN_BY_MEASURED = 0, /**< default: the model proposes, the chain's matrices are built
                                     and measured (max m_s, m_t over H), and the model is
                                     re-calibrated by measured/model until the measurement meets
                                     the budget (docs/planning.md §4; about 1-6 ms) */
    SWARP_PLAN_BY_MODEL = 1,    /**< the model alone (a few µs): docs/planning.md's table */
    SWARP_PLAN_BY_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_by;

/** What the scene calls for.  Zero means default for every field: a zeroed
 *  struct is the default scene (camera at (0,2,0) looking down -z, fovy 60°,
 *  aspect 4/3, near 1, far 100; sun at zenith; no scene box; static camera;
 *  hard shadows; no planes). */
typedef struct swarp_scene_needs {
    swarp_camera camera;      /**< all zero: the default camera above */
    swarp_light light;        /**< all zero: directional light (0,-1,0) */
    swarp_aabb scene_box;     /**< casters and receivers; all zero: unbounded
                                   (no near/far adjustment [RHS] §3.3.1) */
    uint32_t screen_width;    /**< pixels; 0: 1024 */
    uint32_t screen_height;   /**< pixels; 0: 768 */
    uint32_t camera_moves;    /**< 0 static, 1 moves (stabilisation matters only then) */
    uint32_t soft_shadows;    /**< 0 hard, 1 soft (a filter is chosen only then) */
    double soft_width;        /**< filter kernel width in shadow-map texels, >= 1;
                                   0: 3 (only read when soft_shadows) */
    swarp_plan_bleed bleed_risk; /**< decides VSM / MSM / EVSM / LVSM for wide kernels */
    uint32_t allow_depth_clamp;  /**< 1: casters may be clamped to the light's near
                                      plane ("pancaking"), 0: not */
    uint32_t plane_count;     /**< planes of interest in planes[], <= SWARP_PLAN_MAX_PLANES */
    uint32_t _pad0;           /**< must be zero */
    swarp_plane planes[SWARP_PLAN_MAX_PLANES]; /**< candidate lixel planes [LIXEL] */
    swarp_plan_by plan_by;    /**< how swarp_plan judges the error of candidates */
    uint32_t _reserved[3];
} swarp_scene_needs;

/** Largest time_budget_ns, pass_cost_ns and blur_pass_cost_ns swarp_plan()
 *  accepts (1e15 ns, 11.6 days per frame), else SWARP_ERR_OUT_OF_RANGE: the
 *  predicted cost (up to (16 + SWARP_PLAN_MAX_PLANES) passes and their blur
 *  passes) then stays finite. */
#define SWARP_PLAN_MAX_COST_NS 1e15

/** What the caller can spend.  Zero means default for every field. */
typedef struct swarp_budget {
    double max_error;         /**< max screen pixels per texel, max(m_x, m_z) over the
                                   view, > 0; 0: 1.0 */
    uint32_t map_resolution;  /**< texels per side of one map; 0: 2048 */
    uint32_t atlas_limit;     /**< largest texture side for the split atlas
                                   ([RHS] §3.3.5), >= map_resolution not required; 0: 8192 */
    uint32_t max_passes;      /**< most shadow (geometry) passes, 1..32; 0: 16 */
    uint32_t _pad0;           /**< must be zero */
    double time_budget_ns;    /**< frame time for shadows, ns; 0: no time limit */
    double pass_cost_ns;      /**< one shadow pass at map_resolution, measured by the
                                   caller; 0: 1.39e6 (fit to [RHS] Table 7.1) */
    double blur_pass_cost_ns; /**< one separable prefilter blur pass over one map;
                                   0: a quarter of one shadow pass (assumption, docs/planning.md) */
    double pass_overhead_ns;  /**< calibrated cost model: one shadow pass of an r x r map
                                   costs pass_overhead_ns + r² texel_cost_ns (fit them to
                                   measured passes with swarp_plan_cost_fit); both 0: the
                                   per-pass constant pass_cost_ns; >= 0, <= SWARP_PLAN_MAX_COST_NS */
    double texel_cost_ns;     /**< the per-texel term of that model, ns per texel, >= 0,
                                   <= SWARP_PLAN_MAX_COST_NS / 65536² */
} swarp_budget;

typedef enum swarp_plan_warp {
    SWARP_PLAN_WARP_DEFAULT = 0,       /**< = SWARP_PLAN_WARP_UNIFORM */
    SWARP_PLAN_WARP_UNIFORM = 1,       /**< focused uniform map, n' = inf [RHS] §3.1 */
    SWARP_PLAN_WARP_LISPSM_NOPT = 2,   /**< LiSPSM n_opt [RHS] (3.2) */
    SWARP_PLAN_WARP_LISPSM_NREPAR = 3, /**< Lloyd's n_repar [RHS] (3.3)-(3.5) */
    SWARP_PLAN_WARP_LISPSM_GMNPR = 4,  /**< λ_GMNPR [GMNPR] (8) */
    SWARP_PLAN_WARP_LISPSM_PSEUDO = 5, /**< n_opt with pseudo-near/far 0.1, 0.1 [RHS] (4.2) */
    SWARP_PLAN_WARP_PSM = 6,           /**< PSM, n' = n_repar(η = 1) [RHS] (3.4), [KOZ] */
    SWARP_PLAN_WARP_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_warp;

typedef enum swarp_plan_scheme {
    SWARP_PLAN_SCHEME_DEFAULT = 0,     /**< = SWARP_PLAN_SCHEME_NONE */
    SWARP_PLAN_SCHEME_NONE = 1,        /**< one map, no split */
    SWARP_PLAN_SCHEME_PRACTICAL = 2,   /**< PSSM practical, λ = 0.5 [RHS] (3.8) */
    SWARP_PLAN_SCHEME_LOG = 3,         /**< logarithmic [RHS] (3.7) */
    SWARP_PLAN_SCHEME_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_scheme;

typedef enum swarp_plan_stabilize {
    SWARP_PLAN_STABILIZE_DEFAULT = 0,  /**< = SWARP_PLAN_STABILIZE_NONE */
    SWARP_PLAN_STABILIZE_NONE = 1,
    SWARP_PLAN_STABILIZE_APPROX64 = 2, /**< 64 scale levels + texel snap [RHS] §3.5 */
    SWARP_PLAN_STABILIZE_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_stabilize;

typedef enum swarp_plan_filter {
    SWARP_PLAN_FILTER_DEFAULT = 0,     /**< = SWARP_PLAN_FILTER_NONE */
    SWARP_PLAN_FILTER_NONE = 1,        /**< hard shadows */
    SWARP_PLAN_FILTER_PCF = 2,         /**< percentage-closer filtering, no bleeding */
    SWARP_PLAN_FILTER_VSM = 3,         /**< variance shadow map [VSM] (3.1)-(3.3) */
    SWARP_PLAN_FILTER_MSM = 4,         /**< 4-moment shadow map (not in [VSM]) */
    SWARP_PLAN_FILTER_EVSM = 5,        /**< exponential VSM [VSM] §4.2 */
    SWARP_PLAN_FILTER_LVSM = 6,        /**< layered VSM [VSM] §4.1 */
    SWARP_PLAN_FILTER_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_filter;

/* Reason flags (swarp_plan.reasons): one bit per choice made or effect left
 * out; swarp_plan_explain() turns each into a sentence. */
#define SWARP_PLAN_WHY_ONE_MAP_MEETS      (1u << 0)  /**< one map meets the error budget */
#define SWARP_PLAN_WHY_SPLITS_NEEDED      (1u << 1)  /**< fewest splits that meet the budget */
#define SWARP_PLAN_WHY_WARP_LOWERS_ERROR  (1u << 2)  /**< the warp lowers the error at no pass */
#define SWARP_PLAN_WHY_NO_WARP_NO_GAIN    (1u << 3)  /**< no warp lowers the error (duelling frusta) */
#define SWARP_PLAN_WHY_NO_WARP_MOVING     (1u << 4)  /**< camera moves: warps cannot be stabilised */
#define SWARP_PLAN_WHY_STABILIZE_MOVING   (1u << 5)  /**< stabilised because the camera moves */
#define SWARP_PLAN_WHY_NO_STABILIZE_STATIC (1u << 6) /**< camera static: no stabilisation */
#define SWARP_PLAN_WHY_INVERSE_PROJECTION (1u << 7)  /**< PSM with light behind: inverse projection [KOZ] */
#define SWARP_PLAN_WHY_NO_INVERSE         (1u << 8)  /**< no inverse projection (light in front, or not PSM) */
#define SWARP_PLAN_WHY_FILTER_SOFT        (1u << 9)  /**< filter because soft shadows are requested */
#define SWARP_PLAN_WHY_NO_FILTER_HARD     (1u << 10) /**< no filter: hard shadows requested */
#define SWARP_PLAN_WHY_LIXEL_PLANE        (1u << 11) /**< at least one lixel map [LIXEL] */
#define SWARP_PLAN_WHY_NO_LIXEL_NONE      (1u << 12) /**< no plane of interest declared */
#define SWARP_PLAN_WHY_NO_LIXEL_SKIPPED   (1u << 13) /**< a declared plane was left out (see plane_reason) */
#define SWARP_PLAN_WHY_DEPTH_CLAMP        (1u << 14) /**< casters clamped to the light near plane */
#define SWARP_PLAN_WHY_NO_CLAMP_DISALLOWED (1u << 15) /**< clamping not allowed by the needs */
#define SWARP_PLAN_WHY_NO_CLAMP_WARPED    (1u << 16) /**< clamping left out: it breaks warped maps [RHS] §3.1.2 */
#define SWARP_PLAN_WHY_BUDGET_UNMET       (1u << 17) /**< nothing meets the budget: most accurate within the pass limit */
#define SWARP_PLAN_WHY_TIME_LIMITED       (1u << 18) /**< the time budget excluded chains that met the error budget */
#define SWARP_PLAN_WHY_ATLAS_SHRINK       (1u << 19) /**< the atlas limit shrinks each split's map */
#define SWARP_PLAN_WHY_NEAR_FAR_ADJUSTED  (1u << 20) /**< near/far fitted to the scene box [RHS] §3.3.1 */
#define SWARP_PLAN_WHY_POINT_AS_DIRECTIONAL (1u << 21) /**< point light modelled as directional */
#define SWARP_PLAN_WHY_PASS_LIMITED       (1u << 22) /**< the pass limit excluded chains */
#define SWARP_PLAN_WHY_FORCED             (1u << 23) /**< chain given by the caller (swarp_plan_evaluate) */
#define SWARP_PLAN_WHY_RANKED_MEASURED    (1u << 24) /**< candidates ranked by the measured error of their built matrices */

/* Per-plane outcome (swarp_plan.plane_reason[i]). */
#define SWARP_PLAN_PLANE_USED           0u /**< a lixel map covers the plane */
#define SWARP_PLAN_PLANE_CAMERA_ON_PLANE 1u /**< the camera lies on the plane: no front side */
#define SWARP_PLAN_PLANE_LIGHT_GRAZING  2u /**< light from the other side or under 5° elevation */
#define SWARP_PLAN_PLANE_NOT_VISIBLE    3u /**< the plane misses the view frustum */
#define SWARP_PLAN_PLANE_NO_PASS_LEFT   4u /**< the pass limit (or time budget) is used up */
#define SWARP_PLAN_PLANE_LIXEL_REFUSED  5u /**< swarp_lixel_matrix gave another error (e.g. singular) */

/** The cost model a plan's cost_ns comes from (swarp_plan.cost_model). */
typedef enum swarp_plan_cost_model {
    SWARP_PLAN_COST_UNCALIBRATED = 0, /**< default per-pass time 1.39 ms fitted to [RHS]
                                           Table 7.1, the same for every map size */
    SWARP_PLAN_COST_PER_PASS = 1,     /**< the caller's pass_cost_ns, the same for every map size */
    SWARP_PLAN_COST_LINEAR = 2,       /**< the caller's pass_overhead_ns + texels x texel_cost_ns */
    SWARP_PLAN_COST_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_cost_model;

/** The chosen chain.  The model's fields (splits, n_prime, split_max_mx/mz,
 *  max_mx, max_mz, max_error, error_area) are Lloyd's overhead-light model
 *  generalised to γ, on the view axis (screen pixels per texel side): they
 *  equal the matrices' m_s, m_t only on the view axis under an overhead
 *  light (the measured maxima are over all of H, off-axis corners included:
 *  docs/planning.md §9 compares them).  The built_* fields and measured are
 *  what the chain's matrices give (swarp_plan_evaluate only).  Costs per
 *  the cost model of docs/planning.md.
 *  C has one namespace for functions and typedefs, so the type is the struct
 *  tag `struct swarp_plan` (the function is swarp_plan()), with the typedef
 *  swarp_plan_result as a shorter name for the same type. */
typedef struct swarp_plan {
    swarp_plan_warp warp;             /**< the warp of every split */
    swarp_plan_scheme scheme;         /**< split scheme (NONE for one map) */
    uint32_t split_count;             /**< K, 1..SWARP_PLAN_MAX_SPLITS */
    uint32_t map_resolution;          /**< texels per side of each split's map */
    uint32_t atlas_tiles;             /**< atlas tiles per side, ceil(sqrt(K)) */
    swarp_plan_stabilize stabilize;
    uint32_t inverse_projection;      /**< 1: PSM with the light behind the camera [KOZ] */
    uint32_t depth_clamp;             /**< 1: clamp casters to the light near plane */
    double gamma;                     /**< angle view dir / direction to the light, rad in [0, pi] */
    double z_near, z_far;                 /**< the view depth range planned for (after adjustment) */
    double splits[SWARP_PLAN_MAX_SPLITS + 1]; /**< C_0 = near .. C_K = far */
    double n_prime[SWARP_PLAN_MAX_SPLITS];    /**< warp parameter per split in light-space
                                                   units; +INFINITY = uniform */
    double split_max_mx[SWARP_PLAN_MAX_SPLITS]; /**< the model's max m_x per split */
    double split_max_mz[SWARP_PLAN_MAX_SPLITS]; /**< the model's max m_z per split */
    double max_mx, max_mz;            /**< the model's maxima over the whole view */
    double max_error;                 /**< max(max_mx, max_mz), compared with the budget */
    double error_area;                /**< max_mx * max_mz (texel-area error bound); DBL_MAX when the
                                           product exceeds the double range */
    uint32_t lixel_count;             /**< planes with a lixel map */
    uint32_t lixel_planes[SWARP_PLAN_MAX_PLANES]; /**< their indices in needs->planes */
    uint32_t plane_reason[SWARP_PLAN_MAX_PLANES]; /**< SWARP_PLAN_PLANE_* per declared plane */
    double lixel_error;               /**< predicted pixels per texel on a lixel plane */
    swarp_plan_filter filter;
    uint32_t filter_layers;           /**< LVSM layers (4), else 0 */
    double filter_width;              /**< kernel width in texels (0 without filter) */
    double filter_exponent_pos;       /**< EVSM positive exponent c+ (40), else 0 */
    double filter_exponent_neg;       /**< EVSM negative exponent c- (5), else 0 */
    uint32_t shadow_passes;           /**< K + lixel_count */
    uint32_t blur_passes;             /**< prefilter blur passes (2 per map and layer pair) */
    double texels;                    /**< texels of all maps (atlas tiles used + lixel maps) */
    double cost_ns;                   /**< predicted time of all passes */
    uint32_t meets_budget;            /**< 1: error (and time) budget met */
    uint32_t reasons;                 /**< SWARP_PLAN_WHY_* flags */
    uint32_t candidates;              /**< candidate chains evaluated */
    uint32_t plane_count;             /**< planes declared in the needs (plane_reason valid) */
    /* The chain's matrices as an engine builds them: swarp_cascade_setup with
     * the options docs/planning.md §9 maps the chain to (one split: the
     * cascade is swarp_setup itself).  swarp_plan_evaluate fills them, and
     * so does swarp_plan for the chain it chose (SWARP_PLAN_BY_MEASURED, a
     * buildable chain): they are what an engine renders for this plan. */
    uint32_t built;                   /**< 1: the matrices were built, the fields below hold */
    swarp_status built_status;        /**< swarp_cascade_setup's status for the chain (an
                                           error: built = 0, e.g. SWARP_ERR_STABILIZE_LIGHT;
                                           SWARP_OK with built = 0: not asked for) */
    double built_splits[SWARP_PLAN_MAX_SPLITS + 1]; /**< the matrices' C_0 .. C_K
                                           (swarp_cascade_result.splits) */
    double built_n_eye[SWARP_PLAN_MAX_SPLITS]; /**< the n' each split's matrix uses, eye
                                           units, +INFINITY uniform (swarp_cascade_split.n_eye):
                                           the one n' of the chain */
    swarp_measured_error split_measured[SWARP_PLAN_MAX_SPLITS]; /**< each split's measured
                                           error (swarp_cascade_split.measured) */
    swarp_measured_error measured;    /**< the worst split's (swarp_cascade_result.measured):
                                           max_m_s, max_m_t, max_sigma, at */
    swarp_plan_cost_model cost_model; /**< which cost model gave cost_ns (UNCALIBRATED:
                                           the default constant, not measured on this machine) */
    uint32_t _reserved[3];
} swarp_plan_result;

/** What swarp_plan_evaluate builds besides the model's prediction. */
typedef enum swarp_plan_matrices {
    SWARP_PLAN_MATRICES_MEASURED = 0,   /**< the chain's matrices and their measured error
                                             (the default; 0.2-0.55 ms) */
    SWARP_PLAN_MATRICES_UNMEASURED = 1, /**< the matrices only: built_splits, built_n_eye;
                                             measured zero (4-38 µs) */
    SWARP_PLAN_MATRICES_NONE = 2,       /**< the model only (built = 0, built_status
                                             SWARP_OK; a few µs) */
    SWARP_PLAN_MATRICES_FORCE_I32 = 0x7FFFFFFF
} swarp_plan_matrices;

/** A chain to evaluate as it is (swarp_plan_evaluate). */
typedef struct swarp_plan_chain {
    swarp_plan_warp warp;
    swarp_plan_scheme scheme;   /**< NONE requires split_count 1 (0 means 1) */
    uint32_t split_count;       /**< 0: 1 */
    swarp_plan_stabilize stabilize;
    swarp_plan_matrices matrices; /**< what swarp_plan_evaluate builds besides the model */
    uint32_t _reserved[4];
} swarp_plan_chain;

/** @brief Plan the cheapest chain that meets the budget.
 *  Candidates: uniform, LiSPSM (n_opt, n_repar, λ_GMNPR, pseudo-near/far),
 *  PSM (+ inverse projection when the light is behind) as one map; PSSM with
 *  K = 2..16 splits (practical λ = 0.5 or logarithmic) unwarped, with n_opt
 *  or with n_repar per split.  A moving camera admits only unwarped chains
 *  (stabilised, [RHS] §3.5).  The model's rule: the fewest passes whose
 *  predicted max(m_x, m_z) <= the budget (and cost <= time budget); ties go
 *  to the lower error, then to the earlier (simpler) candidate.  With
 *  needs->plan_by = SWARP_PLAN_BY_MEASURED (the default) that rule proposes a
 *  chain, its matrices are built (as swarp_plan_evaluate) and measured; while
 *  the measured max(m_s, m_t) exceeds budget->max_error the rule is applied
 *  again against max_error × model/measured of the last chain (at least 3 %
 *  tighter each round, at most 8 rounds): meets_budget then means the
 *  MEASURED error meets it, and the built_* fields hold the chosen chain's
 *  matrices.  Chains that cannot be built (point light) fall back to the
 *  model.  SWARP_PLAN_BY_MODEL: the rule alone.  If none meets the budget:
 *  the most accurate chain found (measured, or by the model within the pass
 *  limit) and SWARP_INFO_PLAN_BUDGET_UNMET.  Then the filter (soft shadows only), depth
 *  clamping and lixel maps for declared lixel-friendly planes (passes left).
 *  Error model [RHS] (2.3)-(2.8), generalised to any γ (docs/planning.md).
 *  @param[in]  needs   scene; NULL or zeroed fields mean the defaults
 *  @param[in]  budget  budget; NULL or zeroed fields mean the defaults
 *  @param[out] out_plan the plan (untouched on error)
 *  @return SWARP_OK; SWARP_INFO_PLAN_BUDGET_UNMET; SWARP_INFO_PLAN_POINT_LIGHT;
 *          SWARP_ERR_NULL_POINTER (out_plan), SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_ZERO_VECTOR, SWARP_ERR_DEGENERATE (up parallel to dir),
 *          SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR, SWARP_ERR_OUT_OF_RANGE (aspect,
 *          cone, soft_width, max_error, time, costs (negative or above
 *          SWARP_PLAN_MAX_COST_NS), max_passes > 32), SWARP_ERR_BOX_INVERTED, SWARP_ERR_BOX_DEGENERATE
 *          (as swarp_setup; the all-zero box means unbounded),
 *          SWARP_ERR_RESOLUTION (screen or map above 65536),
 *          SWARP_ERR_PLAN_TOO_MANY_PLANES, SWARP_ERR_PLAN_EMPTY_VIEW. */
SWARP_API swarp_status swarp_plan(const swarp_scene_needs* needs, const swarp_budget* budget,
                                  struct swarp_plan* out_plan);

/** @brief Predict one given chain (no choice of warp or splits): the same
 *  error and cost model and the same filter / lixel / clamp decisions as
 *  swarp_plan(), for reports and for callers that force a technique.
 *  meets_budget says whether it meets the budget (by the model); the pass
 *  limit is not enforced on the chain (lixel maps still use only passes left).
 *  Then the chain's matrices, built as an engine builds them
 *  (swarp_cascade_setup with the needs' camera, light and box (an all-zero
 *  box: the view frustum's bounding box), technique and parameter of the
 *  warp, split count, scheme and λ, 64-level stabilisation, pancaking for
 *  depth_clamp, the plan's map_resolution and the screen; docs/planning.md
 *  §9): built_splits, built_n_eye, split_measured and measured are exactly
 *  that cascade's.  Cost: one swarp_cascade_setup with its measurement
 *  (about 60 µs for one map, 30 µs more per split).
 *  @return as swarp_plan (never SWARP_INFO_PLAN_BUDGET_UNMET), plus
 *          SWARP_ERR_SPLIT_COUNT (K > 16, or K > 1 with SCHEME_NONE, or K = 1
 *          with a split scheme) and SWARP_ERR_UNKNOWN_ENUM for the chain
 *          (also its matrices).  A
 *          chain no engine can build (a stabilised warp or point light) is
 *          still predicted: built = 0 and built_status says why. */
SWARP_API swarp_status swarp_plan_evaluate(const swarp_scene_needs* needs,
                                           const swarp_budget* budget,
                                           const swarp_plan_chain* chain,
                                           struct swarp_plan* out_plan);

/** @brief Least-squares fit of the planner's cost model to measured shadow
 *  passes: pass_ns[i] ≈ overhead + texels[i] x per_texel over the count
 *  pairs (texels of the pass's map, its measured time in ns), both terms
 *  >= 0 (a negative least-squares term is set to 0 and the other refitted:
 *  a line through the origin, or the mean time).  Put the results into
 *  swarp_budget.pass_overhead_ns and texel_cost_ns.  No allocation.
 *  @param[in]  texels  texels of each measured pass (> 0, finite), count entries
 *  @param[in]  pass_ns measured time of each pass, ns (>= 0, finite)
 *  @param[in]  count   pairs, >= 2
 *  @param[out] out_overhead_ns, out_texel_cost_ns the fitted terms
 *  @param[out] out_rms_ns  root-mean-square residual of the fit, ns (may be NULL)
 *  @return SWARP_OK; SWARP_ERR_NULL_POINTER; SWARP_ERR_NON_FINITE;
 *          SWARP_ERR_OUT_OF_RANGE (count < 2, texels <= 0, pass_ns < 0, or a
 *          fitted term above the limits swarp_plan accepts);
 *          SWARP_ERR_DEGENERATE (all texel counts equal: the two terms cannot
 *          be told apart).  Outputs untouched on error. */
SWARP_API swarp_status swarp_plan_cost_fit(const double* texels, const double* pass_ns, size_t count,
                                           double* out_overhead_ns, double* out_texel_cost_ns,
                                           double* out_rms_ns);

/** @brief Readable text of a plan: the chain, the predicted error and cost,
 *  and one line per reason flag and per left-out plane.  Locale-independent.
 *  @param[out] out       text, NUL-terminated; may be NULL when capacity is 0
 *  @param[in]  capacity  bytes available in out
 *  @param[out] out_count bytes needed including the NUL (always written)
 *  @return SWARP_OK; SWARP_ERR_CAPACITY (out untouched, *out_count = needed);
 *          SWARP_ERR_NULL_POINTER (plan or out_count, or out with capacity > 0);
 *          SWARP_ERR_UNKNOWN_ENUM (plan's enums). */
SWARP_API swarp_status swarp_plan_explain(const struct swarp_plan* plan, char* out, size_t capacity,
                                          size_t* out_count);

/** @brief Short name of a warp kind ("uniform", "lispsm-nopt", "psm", ...).
 *  @param w the warp kind
 *  @return a static string, never NULL ("?" for values not in the enum). */
SWARP_API const char* swarp_plan_warp_name(swarp_plan_warp w);
/** @brief Short name of a split scheme ("none", "pssm-practical", "pssm-log").
 *  @param s the scheme
 *  @return a static string, never NULL ("?" for values not in the enum). */
SWARP_API const char* swarp_plan_scheme_name(swarp_plan_scheme s);
/** @brief Short name of a filter kind ("none", "pcf", "vsm", "msm", "evsm", "lvsm").
 *  @param f the filter kind
 *  @return a static string, never NULL ("?" for values not in the enum). */
SWARP_API const char* swarp_plan_filter_name(swarp_plan_filter f);

/* ---- 9.5 cube maps in post-projective space, [KOZ] §14.2.2 -------------- */
/*
 * In the camera's post-projective space the view frustum is the unit cube
 * [-1, 1]^3 and (almost) every light is a point P.  The shadow map is a cube
 * map "with displaced centre" whose faces are the unit-cube faces that are
 * BACK-FACING with respect to P (P on the inner side of the face plane, i.e.
 * its distance d_i from P along the outward normal N_i is > 0): 3 to 5 faces
 * for a light outside the cube, all 6 for a light inside.  Face i is rendered
 * by a camera at P looking along N_i whose far plane is the face (distance
 * d_i) and whose near plane is Z_1 d_i: the near planes form a small cube,
 * Z_1 = Z_n/Z_f is the same for every face.
 *
 * The light is given HOMOGENEOUSLY, as the camera's view-projection applied to
 * it: (p, 1) for a point light at p, (-d, 0) for a directional light
 * travelling along d.  w > 0: the ordinary case, depth Z_n = Z_1, Z_f = 1 (in
 * units of d_i).  w < 0 (light behind the camera, [KOZ] §14.2.1): P = xyz/w
 * and the inverse-projection variant Z_n = -Z_1, Z_f = Z_1, which orders
 * depths from the face towards P (light arriving from the far side).
 * w = 0 (light at infinity in post-projective space): SWARP_ERR_CUBE_LIGHT_AT_INFINITY.
 *
 * Face eye spaces look down -z (OpenGL style); their x and y axes are the
 * unit-cube axes listed at SWARP_CUBE_FACE_*, so a point S on face i has
 * NDC (x, y) = (S . right_i, S . up_i) in that face's map.
 */
#define SWARP_CUBE_FACE_POS_X 0u /**< outward normal +x (axes of each face: docs/extras.md) */
#define SWARP_CUBE_FACE_NEG_X 1u
#define SWARP_CUBE_FACE_POS_Y 2u
#define SWARP_CUBE_FACE_NEG_Y 3u
#define SWARP_CUBE_FACE_POS_Z 4u
#define SWARP_CUBE_FACE_NEG_Z 5u
/** At most six faces. */
#define SWARP_CUBE_MAX_FACES 6

/** Options; zero means default. */
typedef struct swarp_cube_options {
    double z1;                     /**< Z_1 = Z_n/Z_f in (0, 1); 0 = default 0.01 */
    swarp_depth_range depth_range; /**< of the face projections; 0 = [-1, 1] */
    uint32_t _reserved[5];         /**< must be zero */
} swarp_cube_options;

/** One cube-map face. */
typedef struct swarp_cube_face {
    uint32_t face;        /**< SWARP_CUBE_FACE_*: the unit-cube face it lies on */
    uint32_t inverse;     /**< 1 for the inverse-projection variant (w < 0) */
    double distance;      /**< d_i: distance from P to the face plane (> 0) */
    swarp_vec3 right;     /**< face eye x axis (post-projective space) */
    swarp_vec3 up;        /**< face eye y axis */
    swarp_vec3 normal;    /**< N_i, the view direction of the face camera */
    swarp_mat4 view;      /**< post-projective space -> face eye space (eye at P) */
    swarp_mat4 proj;      /**< face frustum: the face square at the far plane */
    swarp_mat4 view_proj; /**< proj * view */
} swarp_cube_face;

/** @brief The cube-map faces of [KOZ] §14.2.2 for a light in post-projective
 *  space, with their view, projection and view-projection matrices.
 *  @param[in] ps_light light in post-projective space, homogeneous (see above)
 *  @param[in] opt      options, or NULL for the defaults
 *  @param[out] out     capacity faces (SWARP_CUBE_MAX_FACES always suffices),
 *                      in SWARP_CUBE_FACE_* order
 *  @param[out] out_count number of faces (3..6 unless P lies on a face plane)
 *  @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *  SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE (z1 outside (0, 1)),
 *  SWARP_ERR_UNKNOWN_ENUM (depth_range), SWARP_ERR_CUBE_LIGHT_AT_INFINITY
 *  (w = 0 or P too far for finite matrices), SWARP_ERR_DEGENERATE (no
 *  back-facing face: cannot happen for finite P), SWARP_ERR_CAPACITY
 *  (*out_count = faces needed, out untouched). */
SWARP_API swarp_status swarp_cube_faces(const swarp_vec4* ps_light, const swarp_cube_options* opt,
                                        swarp_cube_face* out, size_t capacity, size_t* out_count);

/** @brief Texture coordinate and depth of a point for the cube map: the
 *  computation of [KOZ] Listing 14-1.  With u = V - P,
 *  a = max_i (u . N_i)/d_i over the back-facing faces, the point is looked up
 *  in face argmax at the cube point S = P + u/a ("vertex position minus light
 *  position", re-centred on the unit cube) and compared against the
 *  projective transform of a with Z_n = Z_1, Z_f = 1 (or -Z_1, Z_1), i.e. the
 *  NDC depth the face's view_proj gives V.
 *  @param[in] ps_light, opt  as swarp_cube_faces
 *  @param[in] ps_point V in post-projective space
 *  @param[out] out_face SWARP_CUBE_FACE_* (may be NULL)
 *  @param[out] out_texcoord S, a point on the unit cube's surface (may be NULL)
 *  @param[out] out_depth NDC depth in opt->depth_range (may be NULL)
 *  @return SWARP_OK; SWARP_INFO_CUBE_NEAR_CLIPPED (a < Z_1: inside the near
 *  cube, the depth is outside the range); the errors of swarp_cube_faces
 *  (but not CAPACITY); SWARP_ERR_CUBE_POINT_UNCOVERED (a <= 0);
 *  SWARP_ERR_OVERFLOW (S or the depth not representable: a light within
 *  ~1e-300 of w = 0 or a point near DBL_MAX). */
SWARP_API swarp_status swarp_cube_lookup(const swarp_vec4* ps_light, const swarp_cube_options* opt,
                                         const swarp_vec3* ps_point, uint32_t* out_face,
                                         swarp_vec3* out_texcoord, double* out_depth);


/* ---- 9.6 the min-depth near plane, [RHS] §4.3 ---------------------------- */
/*
 * The nearest visible depth of the frame, read from a LINEAR depth buffer
 * (view-space distance along the view direction, not radial distance and not
 * the non-linear z-buffer value), becomes the largest near plane that clips
 * nothing the camera saw.  [RHS] reduces the buffer on the GPU with a chain of
 * 2x2 min "mip" passes (Listing A.2) and reads back the last 1x1 level.
 * Depth values: finite and >= 0, or +INFINITY for "nothing here" (cleared).
 */
/** Scratch floats swarp_mindepth_pyramid needs for a w x h buffer. */
#define SWARP_MINDEPTH_SCRATCH(w, h) ((((size_t)(w) + 1u) / 2u) * (((size_t)(h) + 1u) / 2u))

/** @brief Minimum of a linear depth buffer by the 2x2 min pyramid of [RHS]
 *  Listing A.2, on the CPU.  Each level halves the size rounding UP and an
 *  odd last row/column takes the min of the texels that exist (Listing A.2's
 *  wrap addressing with rounded-down sizes would skip them).
 *  @param[in] depth  height rows of width floats, row r at depth + r*row_stride
 *  @param[in] width, height  >= 1; @param[in] row_stride >= width (floats)
 *  @param[out] scratch  SWARP_MINDEPTH_SCRATCH(width, height) floats (may be
 *              NULL when that is 0, i.e. never; 1x1 needs 1)
 *  @param[in] scratch_capacity  floats in scratch
 *  @param[out] out_scratch_needed  written with the need (always)
 *  @param[out] out_min  the minimum (+INFINITY if every value is +INFINITY)
 *  @return SWARP_OK; SWARP_INFO_MINDEPTH_EMPTY (every value +INFINITY);
 *  SWARP_ERR_NULL_POINTER, SWARP_ERR_INVALID_ARGUMENT (width or height 0,
 *  row_stride < width), SWARP_ERR_NON_FINITE (a NaN or -INFINITY),
 *  SWARP_ERR_OUT_OF_RANGE (a negative depth), SWARP_ERR_CAPACITY. */
SWARP_API swarp_status swarp_mindepth_pyramid(const float* depth, uint32_t width, uint32_t height,
                                              size_t row_stride, float* scratch,
                                              size_t scratch_capacity, size_t* out_scratch_needed,
                                              double* out_min);
/** @brief The same minimum by a direct scan (the reference the pyramid is
 *  tested against, and the cheaper choice on the CPU).  Statuses as
 *  swarp_mindepth_pyramid without the scratch ones. */
SWARP_API swarp_status swarp_mindepth_direct(const float* depth, uint32_t width, uint32_t height,
                                             size_t row_stride, double* out_min);

/** Options; zero means default. */
typedef struct swarp_mindepth_options {
    double margin;          /**< relative safety margin in [0, 1); 0 = default 1e-3
                                 (near' = min_depth (1 - margin)) */
    uint32_t _reserved[4];  /**< must be zero */
} swarp_mindepth_options;

/** @brief The adjusted near plane of [RHS] §4.3: the measured minimum depth
 *  less a relative margin, never below the original near and always < far,
 *  so nothing the depth buffer saw is clipped.
 *  @param[in] n, f  the camera's near and far (0 < n < f)
 *  @param[in] min_depth  measured minimum linear depth (>= 0 or +INFINITY)
 *  @param[in] opt  or NULL; @param[out] out_near  the adjusted near plane
 *  @return SWARP_OK; SWARP_INFO_MINDEPTH_EMPTY (min_depth >= f: near kept);
 *  SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR,
 *  SWARP_ERR_OUT_OF_RANGE (min_depth < 0, margin outside [0, 1)),
 *  SWARP_ERR_RESERVED_NONZERO. */
SWARP_API swarp_status swarp_mindepth_near(double n, double f, double min_depth,
                                           const swarp_mindepth_options* opt, double* out_near);

#endif /* SWARP_EXPERIMENTAL_API */

/* ======================================================================== */
/* 9. Status codes (stable)                                                 */
/* ======================================================================== */
/*
 * The values of swarp_status (section 1).  One X-macro list per stage,
 * X(NAME, NUMBER, "message"): swarp_status_string() returns the message,
 * swarp_status_name() the name.  Errors 1..999, informational 1000..1999.
 * Ranges per stage: core 1..99, geometry 100..199, lixel 200..299, filter
 * 300..399, cascades (splits, atlas, stabilisation, bias) 400..499, plan
 * 500..599, extras (cube maps, min depth) 600..699; informational likewise
 * 1000 + ...  Numbers are part of the ABI: never renumber, never reuse.
 * The list is stable API and is declared whether or not
 * SWARP_EXPERIMENTAL_API is defined (the statuses of the experimental
 * functions are in it too).
 */
#define SWARP_STATUS_LIST_CORE(X)                                                   \
    X(SWARP_OK, 0, "ok")                                                            \
    X(SWARP_ERR_NULL_POINTER, 1, "a required pointer argument is NULL")             \
    X(SWARP_ERR_NON_FINITE, 2, "an input value is NaN or infinite")                 \
    X(SWARP_ERR_INVALID_ARGUMENT, 3, "an argument is invalid")                      \
    X(SWARP_ERR_OUT_OF_RANGE, 4, "a value lies outside its documented domain")      \
    X(SWARP_ERR_NEAR_FAR, 5, "near must be > 0 and far must be > near")             \
    X(SWARP_ERR_FOV, 6, "field of view (or half angle) outside its open interval")  \
    X(SWARP_ERR_RESOLUTION, 7, "a resolution is zero, negative or not finite")      \
    X(SWARP_ERR_CAPACITY, 8, "output capacity too small; needed count written")     \
    X(SWARP_ERR_ZERO_VECTOR, 9, "a direction vector has zero length")               \
    X(SWARP_ERR_RESERVED_NONZERO, 10, "a _reserved field is not zero")              \
    X(SWARP_ERR_DEGENERATE, 11, "degenerate configuration")                         \
    X(SWARP_ERR_SPLIT_COUNT, 12, "split count m is 0 (or above SWARP_SPLIT_MAX_COUNT for a split scheme)") \
    X(SWARP_ERR_UNKNOWN_ENUM, 13, "an enum value is not one of the documented ones")\
    X(SWARP_ERR_NOT_INCREASING, 14, "split distances must be strictly increasing")  \
    X(SWARP_ERR_SINGULAR, 15, "a matrix is singular or too ill-conditioned")        \
    X(SWARP_ERR_OVERFLOW, 16, "the result does not fit a finite double (inputs too extreme)") \
    X(SWARP_INFO_WARP_UNIFORM, 1000,                                                \
      "warp faded to uniform (duelling frusta: light parallel to the view)")        \
    X(SWARP_INFO_GMNPR_ADJUSTED, 1001,                                              \
      "theta < phi: lambda_GMNPR uses the adjusted branch lambda_2* of eq. (7)")    \
    X(SWARP_INFO_GLPR_NO_SOLUTION, 1002,                                            \
      "GLPR has no positive lambda here (theta <= phi); lambda_GMNPR was written") \
    X(SWARP_INFO_MEASURE_SINGULAR, 1003,                                            \
      "the map is singular at a measured point: its error is +inf there")

/* geometry: 100..199, 1100..1199 */
#define SWARP_STATUS_LIST_GEOMETRY(X)                                                   \
    X(SWARP_ERR_BODY_EMPTY, 100,                                                        \
      "the view frustum misses the scene box (H = V intersect S is empty)")              \
    X(SWARP_ERR_BOX_INVERTED, 101, "scene box min exceeds max on some axis")            \
    X(SWARP_ERR_BOX_DEGENERATE, 102,                                                    \
      "scene box has zero extent along two or more axes")                               \
    X(SWARP_ERR_LIGHT_INSIDE_BODY, 103,                                                 \
      "point light inside the body B: one perspective map cannot cover it")             \
    X(SWARP_ERR_FOLLOW_FRAME, 104,                                                      \
      "the previous result's light frame is not orthonormal or not from this technique")  \
    X(SWARP_ERR_CAMERA_NOT_PERSPECTIVE, 105,                                            \
      "the projection is not a perspective one (orthographic, or x, y, z mixed or translated)") \
    X(SWARP_ERR_CAMERA_MIRRORED, 106,                                                   \
      "the view matrix mirrors (det < 0) or the projection looks backward for this handedness") \
    X(SWARP_ERR_CAMERA_VIEW_NOT_RIGID, 107,                                             \
      "the view matrix is not a rotation and a translation (scaled, sheared or projective)") \
    X(SWARP_ERR_CAMERA_FAR_UNBOUNDED, 108,                                              \
      "the projection's far plane is at infinity and no scene box bounds the view")      \
    X(SWARP_INFO_LIGHT_PARALLEL, 1100,                                                  \
      "light nearly parallel to the view: light-space up blended toward camera right")  \
    X(SWARP_INFO_FLAT_EXTENT, 1101,                                                     \
      "an extent of the focused body is zero; its width was padded")                    \
    X(SWARP_INFO_PSM_INVERSE, 1102,                                                     \
      "light behind the camera: PSM uses the inverse projection (near < 0 < far)")      \
    X(SWARP_INFO_LIGHT_NEAR_CLIPPED, 1103,                                              \
      "spot light on or inside B: points nearer than its near plane left out")          \
    X(SWARP_INFO_FOLLOW_LAG, 1104,                                                      \
      "followed light frame still turning toward the aligned one (light near the view axis; LiSPSM weaker)") \
    X(SWARP_INFO_CAMERA_FAR_FROM_SCENE, 1105,                                           \
      "infinite far plane: z_far is the farthest view depth of the scene box ([RHS] 3.3.1)") \
    X(SWARP_INFO_CASTERS_CLAMPED, 1106,                                                 \
      "casters over 1e10 times the receivers' size toward the light left out of the depth range (depth clamp)")

/* lixel: 200..299, 1200..1299 */
#define SWARP_STATUS_LIST_LIXEL(X)                                                  \
    X(SWARP_ERR_LIXEL_COPLANAR, 200,                                                \
      "four of the five points are coplanar (or a point is zero): no unique matrix")\
    X(SWARP_ERR_LIXEL_PLANE_THROUGH_EYE, 201,                                       \
      "the plane of interest passes through the viewer's eye")                      \
    X(SWARP_ERR_LIXEL_LIGHT_ON_PLANE, 202, "the point light lies on the plane of interest") \
    X(SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE, 203,                                    \
      "the directional light is parallel to the plane of interest")                 \
    X(SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE, 204,                                       \
      "no corner ray of the viewer hits the plane of interest in front of the eye") \
    X(SWARP_ERR_LIXEL_RAY_OUTSIDE, 205,                                             \
      "a ray of C is outside the light frustum of M_l (q <= 0)")                    \
    X(SWARP_ERR_LIXEL_RECT_TOO_LARGE, 206,                                          \
      "the light-image rectangle exceeds the allowed size (C approaches the line pi)") \
    X(SWARP_ERR_LIXEL_TWIST_LINE, 207,                                              \
      "the twist line projects to a point in the light image")                      \
    X(SWARP_ERR_LIXEL_EMPTY, 208,                                                   \
      "no ray of C hits the plane inside the viewer's frustum")                     \
    X(SWARP_INFO_LIXEL_ILL_CONDITIONED, 1200,                                       \
      "the five-point configuration is ill-conditioned; the matrix may be inaccurate") \
    X(SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY, 1201,                                  \
      "the quad Q straddles infinity (horizon visible); exact on the visible part") \
    X(SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW, 1202,                                   \
      "the plane of interest is parallel to the view direction (horizon through the centre)") \
    X(SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE, 1203,                                    \
      "light and viewer are on opposite sides of the plane of interest")

/* filter: 300..399, 1300..1399 */
#define SWARP_STATUS_LIST_FILTER(X)                                                      \
    X(SWARP_ERR_FILTER_LAYER_COUNT, 300,                                                 \
      "LVSM layer count must be in 1..SWARP_LVSM_MAX_LAYERS")                            \
    X(SWARP_ERR_FILTER_OVERLAP, 301,                                                     \
      "LVSM overlap delta must be >= 0 and smaller than the thinnest layer")             \
    X(SWARP_ERR_FILTER_BAND, 302,                                                        \
      "LVSM transition band must lie in [0, delta] and below half the thinnest layer")   \
    X(SWARP_ERR_FILTER_NO_SAMPLES, 303, "Lloyd relaxation needs at least one sample")    \
    X(SWARP_ERR_FILTER_BLOCKER, 304,                                                     \
      "PCSS blocker depth must be > 0 and not beyond the receiver")                      \
    X(SWARP_ERR_FILTER_EXPONENT, 305,                                                    \
      "EVSM exponent must be > 0 and keep e^(2c) finite in double")                      \
    X(SWARP_INFO_FILTER_NOT_CONVERGED, 1300,                                             \
      "Lloyd relaxation reached its iteration bound before converging; splits written")  \
    X(SWARP_INFO_FILTER_NO_WEIGHT, 1301,                                                 \
      "all Lloyd sample weights are zero: splits written unchanged")                     \
    X(SWARP_INFO_FILTER_MSM_DEGENERATE, 1302,                                            \
      "moment matrix singular (at most two distinct depths): exact discrete form used")  \
    X(SWARP_INFO_FILTER_DEPTH_CLAMPED, 1303,                                             \
      "depth outside [s_0, s_N]: the first or last layer was used")

/* cascades: 400..499, 1400..1499 */
#define SWARP_STATUS_LIST_SPLITS(X)                                                  \
    X(SWARP_ERR_ATLAS_SPLITS, 400, "atlas layouts hold 1..16 splits")                 \
    X(SWARP_ERR_STABILIZE_WARPED, 401,                                               \
      "stabilisation is defined for uniform light-space aligned maps; a warp was requested") \
    X(SWARP_ERR_STABILIZE_LIGHT, 402, "stabilisation needs a directional light")      \
    X(SWARP_ERR_BEHIND_PROJECTION, 403,                                              \
      "the point maps to w <= 0 (behind the centre of projection of the light matrix)") \
    X(SWARP_ERR_SPLIT_EMPTY, 404, "a split frustum does not intersect the scene")    \
    X(SWARP_INFO_LEVEL_ABOVE_RANGE, 1400,                                            \
      "the body is larger than the reference size: quantised level above the level count") \
    X(SWARP_INFO_OUTSIDE_SPLITS, 1401,                                               \
      "the point lies in no split map; the split nearest in eye depth was chosen")   \
    X(SWARP_INFO_BACKFACING, 1402,                                                   \
      "the normal faces away from the light; N.L clamped to 0")                      \
    X(SWARP_INFO_SPLIT_NO_SCENE, 1403,                                               \
      "a stabilised split misses the scene box; its map covers the split frustum")

/* plan: 500..599, 1500..1599 */
#define SWARP_STATUS_LIST_PLAN(X)                                                   \
    X(SWARP_ERR_PLAN_TOO_MANY_PLANES, 500,                                          \
      "plane_count exceeds SWARP_PLAN_MAX_PLANES")                                  \
    X(SWARP_ERR_PLAN_EMPTY_VIEW, 501,                                               \
      "the scene box lies entirely outside the view depth range: nothing to shadow")\
    X(SWARP_INFO_PLAN_BUDGET_UNMET, 1500,                                           \
      "no chain meets the budget; the plan is the most accurate within the pass limit") \
    X(SWARP_INFO_PLAN_POINT_LIGHT, 1501,                                            \
      "point light planned as a directional light toward the view frustum's centre")

/* extras: 600..699, 1600..1699 */
#define SWARP_STATUS_LIST_EXTRAS(X)                                                 \
    X(SWARP_ERR_CUBE_LIGHT_AT_INFINITY, 600,                                        \
      "light at infinity in post-projective space (w = 0): no cube map, use one orthographic map") \
    X(SWARP_ERR_CUBE_POINT_UNCOVERED, 601,                                          \
      "the point is in no cube-map face frustum (it coincides with the light or lies behind it)") \
    X(SWARP_INFO_CUBE_NEAR_CLIPPED, 1601,                                           \
      "the point lies inside the faces' near cube (a < Z_1): the face camera clips it") \
    X(SWARP_INFO_MINDEPTH_EMPTY, 1600,                                              \
      "the depth buffer holds nothing nearer than far: near plane left unchanged")

#define SWARP_STATUS_LIST(X)          \
    SWARP_STATUS_LIST_CORE(X)         \
    SWARP_STATUS_LIST_GEOMETRY(X)     \
    SWARP_STATUS_LIST_LIXEL(X)        \
    SWARP_STATUS_LIST_FILTER(X)       \
    SWARP_STATUS_LIST_SPLITS(X)       \
    SWARP_STATUS_LIST_PLAN(X)         \
    SWARP_STATUS_LIST_EXTRAS(X)

#define SWARP_STATUS_ENUM_ENTRY_(name, value, message) name = value,
enum swarp_status_code {
    SWARP_STATUS_LIST(SWARP_STATUS_ENUM_ENTRY_)
    SWARP_STATUS_FORCE_I32 = 0x7FFFFFFF
};
#undef SWARP_STATUS_ENUM_ENTRY_

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SHADOWWARP_H */
