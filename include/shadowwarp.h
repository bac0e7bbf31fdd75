/*
 * shadowwarp.h -- libshadowwarp, the one public header.
 *
 * libshadowwarp computes the matrices and parameters of warped, partitioned
 * and filtered shadow maps together with the analytic error model that says
 * how good a choice is.  It is a library of pure functions.
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
 *                 [-1, 1] (OpenGL, the default) or [0, 1] (D3D, Vulkan, Metal).
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
 *                 IS the uniform shadow map; the error model accepts it).
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
 *                 _FORCE_I32 sentinel.  Experimental additions sit behind
 *                 SWARP_EXPERIMENTAL_API.
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
 */
#ifndef SHADOWWARP_H
#define SHADOWWARP_H

#include <stddef.h>
#include <stdint.h>

#define SWARP_VERSION_MAJOR 0
#define SWARP_VERSION_MINOR 1
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
/* Status codes                                                             */
/* ======================================================================== */
/*
 * One X-macro list per stage, X(NAME, NUMBER, "message").  Errors 1..999,
 * informational 1000..1999.  Ranges per stage: core 1..99, geometry 100..199,
 * lixel 200..299, filter 300..399, splits/stabilise/bias 400..499,
 * plan 500..599, seeds' extras 600..699; informational likewise 1000 + ...
 * Numbers are part of the ABI: never renumber, never reuse.
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
    X(SWARP_ERR_SPLIT_COUNT, 12, "split count m must be at least 1")                \
    X(SWARP_ERR_UNKNOWN_ENUM, 13, "an enum value is not one of the documented ones")\
    X(SWARP_ERR_NOT_INCREASING, 14, "split distances must be strictly increasing")  \
    X(SWARP_ERR_SINGULAR, 15, "a matrix is singular or too ill-conditioned")        \
    X(SWARP_INFO_WARP_UNIFORM, 1000,                                                \
      "warp faded to uniform (duelling frusta: light parallel to the view)")        \
    X(SWARP_INFO_GMNPR_ADJUSTED, 1001,                                              \
      "theta < phi: lambda_GMNPR uses the adjusted branch lambda_2* of eq. (7)")    \
    X(SWARP_INFO_GLPR_NO_SOLUTION, 1002,                                            \
      "GLPR has no positive lambda here; the largest admissible value was written")

/* >>> status: geometry (100..199, 1100..1199) */
#define SWARP_STATUS_LIST_GEOMETRY(X)
/* <<< status: geometry */

/* >>> status: lixel (200..299, 1200..1299) */
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
/* <<< status: lixel */

/* >>> status: filter (300..399, 1300..1399) */
#define SWARP_STATUS_LIST_FILTER(X)
/* <<< status: filter */

/* >>> status: splits (400..499, 1400..1499) */
#define SWARP_STATUS_LIST_SPLITS(X)
/* <<< status: splits */

/* >>> status: plan (500..599, 1500..1599) */
#define SWARP_STATUS_LIST_PLAN(X)
/* <<< status: plan */

/* >>> status: extras (600..699, 1600..1699) */
#define SWARP_STATUS_LIST_EXTRAS(X)
/* <<< status: extras */

#define SWARP_STATUS_LIST(X)          \
    SWARP_STATUS_LIST_CORE(X)         \
    SWARP_STATUS_LIST_GEOMETRY(X)     \
    SWARP_STATUS_LIST_LIXEL(X)        \
    SWARP_STATUS_LIST_FILTER(X)       \
    SWARP_STATUS_LIST_SPLITS(X)       \
    SWARP_STATUS_LIST_PLAN(X)         \
    SWARP_STATUS_LIST_EXTRAS(X)

#define SWARP_STATUS_ENUM_ENTRY_(name, value, message) name = value,
typedef enum swarp_status {
    SWARP_STATUS_LIST(SWARP_STATUS_ENUM_ENTRY_)
    SWARP_STATUS_FORCE_I32 = 0x7FFFFFFF
} swarp_status;
#undef SWARP_STATUS_ENUM_ENTRY_

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

/* ======================================================================== */
/* Types at the boundary                                                    */
/* ======================================================================== */

typedef struct swarp_vec3 { double x, y, z; } swarp_vec3;
typedef struct swarp_vec4 { double x, y, z, w; } swarp_vec4;
/** Column-major 4x4 matrix: element (row r, column c) is m[c*4 + r]. */
typedef struct swarp_mat4 { double m[16]; } swarp_mat4;
typedef struct swarp_aabb { swarp_vec3 min, max; } swarp_aabb;
/** Plane a*x + b*y + c*z + d = 0; (a, b, c) is the normal (any length > 0). */
typedef struct swarp_plane { double a, b, c, d; } swarp_plane;

/** Clip-space depth convention of a projection matrix. */
typedef enum swarp_depth_range {
    SWARP_DEPTH_DEFAULT = 0,          /**< = SWARP_DEPTH_NEG_ONE_TO_ONE */
    SWARP_DEPTH_NEG_ONE_TO_ONE = 1,   /**< OpenGL: z_ndc in [-1, 1] */
    SWARP_DEPTH_ZERO_TO_ONE = 2,      /**< D3D, Vulkan, Metal: z_ndc in [0, 1] */
    SWARP_DEPTH_RANGE_FORCE_I32 = 0x7FFFFFFF
} swarp_depth_range;

/** The viewer.  dir and up need not be unit length; up must not be parallel
 *  to dir.  fovy is the FULL vertical field of view in radians, in (0, pi);
 *  Θ = fovy/2 in the papers.  aspect = width/height > 0; 0 < near < far. */
typedef struct swarp_camera {
    swarp_vec3 eye;
    swarp_vec3 dir;
    swarp_vec3 up;
    double fovy;
    double aspect;
    double near;
    double far;
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
 *  an omni light (no light frustum L). */
typedef struct swarp_light {
    swarp_light_type type;
    uint32_t _reserved0;
    swarp_vec3 direction;
    swarp_vec3 position;
    double cone_angle;
    uint32_t _reserved[4];
} swarp_light;

/** @brief Convert a matrix to float for the GPU (column-major kept).
 *  @param[in] m  matrix; @param[out] out 16 floats.
 *  @return SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (an element is NaN/Inf
 *  or overflows float; out untouched), SWARP_OK. */
SWARP_API swarp_status swarp_mat4_to_float(const swarp_mat4* m, float out[16]);

/** @brief r = a * b (column-major). r may alias a or b. */
SWARP_API swarp_status swarp_mat4_mul(const swarp_mat4* a, const swarp_mat4* b, swarp_mat4* r);

/** @brief r = inverse(a), Gauss-Jordan with partial pivoting in double.
 *  @return SWARP_ERR_SINGULAR when the pivot falls below 1e-300 relative to
 *  the largest element. */
SWARP_API swarp_status swarp_mat4_invert(const swarp_mat4* a, swarp_mat4* r);

/** @brief Apply a matrix to a point (w = 1) and return the homogeneous result. */
SWARP_API swarp_status swarp_mat4_transform(const swarp_mat4* m, const swarp_vec3* p, swarp_vec4* out);

/* ======================================================================== */
/* Core: closed-form warp parameters            (src/params.c)              */
/* ======================================================================== */
/*
 * Naming: the warp parameter n (or n') is the distance from the projection
 * centre C of the warping frustum P to its near plane [RHS] §3.2.1.  n = n_e
 * (the eye's near distance, overhead light) is PSM; n -> inf is uniform.
 */

/** @brief LiSPSM n_opt, general form.  [RHS] (3.2) (from [WS06])
 *  n_opt = d / (sqrt(z_1/z_0) - 1).
 *  @param d   extent of the warping frustum P along light-space z (> 0)
 *  @param z_0 eye-space depth where the error peaks near (> 0)
 *  @param z_1 eye-space depth where the error peaks far (>= z_0)
 *  @param[out] out_n_opt  n_opt; +INFINITY when z_1 == z_0
 *  @return SWARP_OK; SWARP_INFO_WARP_UNIFORM when z_1 == z_0 (n_opt = inf);
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_OUT_OF_RANGE (d <= 0, z_0 <= 0,
 *          z_1 < z_0), SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_warp_nopt(double d, double z_0, double z_1, double* out_n_opt);

/** @brief n_opt with pseudo-near and pseudo-far planes.  [RHS] (4.2)
 *  Read as n_opt = d/(z_1 - z_0) * (z_0 + sqrt((z_0 + n_p (z_1 - z_0))
 *  (z_1 - f_p (z_1 - z_0)))) (papers README); reduces to (3.2) at
 *  n_p = f_p = 0.
 *  @param n_p, f_p  in [0, 1], n_p + f_p < 1 (pseudo planes as fractions of
 *                   the depth range measured from near and from far)
 *  @return as swarp_warp_nopt; SWARP_ERR_OUT_OF_RANGE for n_p, f_p outside. */
SWARP_API swarp_status swarp_warp_nopt_pseudo(double d, double z_0, double z_1, double n_p,
                                              double f_p, double* out_n_opt);

/** @brief Lloyd's warp strength η(γ, Θ).  [RHS] (3.3)
 *  @param gamma angle between light direction and view direction, radians,
 *               in [0, pi/2] (callers fold γ > pi/2 to pi - γ)
 *  @param theta half the field of view Θ, radians, in (0, pi/2)
 *  @param[out] out_eta η in [-1, 0] */
SWARP_API swarp_status swarp_warp_eta(double gamma, double theta, double* out_eta);

/** @brief Width W_lz of the view frustum along the light-space z axis for a
 *  directional light.  [RHS] (3.5)
 *  @param gamma in [0, pi/2]; @param theta in (0, pi/2); @param n_e, f_e eye
 *  near/far (0 < n_e < f_e); @param W_e width of the near plane (> 0). */
SWARP_API swarp_status swarp_warp_wlz(double gamma, double theta, double n_e, double f_e,
                                      double W_e, double* out_W_lz);

/** @brief Re-parameterised LiSPSM n_repar(η).  [RHS] (3.4), second case read
 *  as η·sqrt(α) + 1 (papers README).  η = -1 gives +INFINITY with
 *  SWARP_INFO_WARP_UNIFORM; η = 0 gives W_lz/(sqrt(α) - 1) (n_opt);
 *  η = 1 gives W_lz/(α - 1) (PSM).
 *  @param eta in [-1, 1]; @param alpha f_e/n_e > 1; @param W_lz > 0. */
SWARP_API swarp_status swarp_warp_nrepar(double eta, double alpha, double W_lz, double* out_n);

/*
 * [GMNPR] uses λ = P_n / (P_f - P_n): the warp parameter for a warping frustum
 * whose depth range is normalised to 1.  θ is the angle between light and
 * view direction (γ in [RHS]), φ the half field of view (Θ in [RHS]).
 */

/** @brief ψ(λ, θ) of [GMNPR] eq. (2). λ > 0, θ in (0, pi/2], φ in (0, pi/2),
 *  0 < n < f. */
SWARP_API swarp_status swarp_gmnpr_psi(double lambda, double theta, double phi, double n,
                                       double f, double* out_psi);
/** @brief φ(λ, θ) of [GMNPR] eq. (2) (the offset inside (z + φ)^2).  Named
 *  "offset" here to keep it apart from the half field of view φ. */
SWARP_API swarp_status swarp_gmnpr_offset(double lambda, double theta, double phi, double n,
                                          double f, double* out_offset);
/** @brief Aliasing function F(λ, θ, z) = ψ (z + φ(λ,θ))^2 / z.  [GMNPR] (2) */
SWARP_API swarp_status swarp_gmnpr_F(double lambda, double theta, double phi, double n,
                                     double f, double z, double* out_F);
/** @brief λ_1(θ) and λ_2(θ) of [GMNPR] (4), for analysis (λ_2 may be <= 0).
 *  θ in (0, pi/2]. */
SWARP_API swarp_status swarp_gmnpr_lambda12(double theta, double phi, double n, double f,
                                            double* out_lambda_1, double* out_lambda_2);
/** @brief λ_GMNPR(θ) of [GMNPR] (8), with λ_2* of (7) for θ < φ.
 *  θ in [0, pi/2]; θ = 0 gives +INFINITY with SWARP_INFO_WARP_UNIFORM.
 *  @return SWARP_OK (θ >= φ), SWARP_INFO_GMNPR_ADJUSTED (0 < θ < φ), ... */
SWARP_API swarp_status swarp_gmnpr_lambda(double theta, double phi, double n, double f,
                                          double* out_lambda);
/** @brief λ_LiSPSM(θ) of [GMNPR] (9). θ in [0, pi/2]; θ = 0 gives +INFINITY
 *  with SWARP_INFO_WARP_UNIFORM. */
SWARP_API swarp_status swarp_gmnpr_lambda_lispsm(double theta, double phi, double n, double f,
                                                 double* out_lambda);
/** @brief λ_GLPR: the λ that makes F(λ, θ, z) linear in z (GLPR, [GMNPR] §3,
 *  derived from (2): F linear in z <=> φ(λ, θ) = 0).  See docs/parameters.md
 *  for the derivation and for what is written where no positive solution
 *  exists (SWARP_INFO_GLPR_NO_SOLUTION). */
SWARP_API swarp_status swarp_gmnpr_lambda_glpr(double theta, double phi, double n, double f,
                                               double* out_lambda);

/* ======================================================================== */
/* Core: Lloyd's error metric                    (src/error.c)              */
/* ======================================================================== */

/** Inputs of Lloyd's error metric [RHS] (2.3)-(2.8).  res_ix >= res_iy is the
 *  image resolution, res_s >= res_t the shadow-map resolution (texels);
 *  theta is Θ, half the field of view, radians in (0, pi/2).  near/far are
 *  the range [n, f] the curve refers to. */
typedef struct swarp_error_config {
    double near;
    double far;
    double theta;
    double res_ix;
    double res_iy;
    double res_s;
    double res_t;
    uint32_t _reserved[4];
} swarp_error_config;

/** @brief m_x(z, n') [RHS] (2.3); n' = n gives (2.5) (PSM); n' = +INFINITY
 *  gives the closed-form uniform limit (2.7).  z in [near, far]; n' > 0. */
SWARP_API swarp_status swarp_error_mx(const swarp_error_config* cfg, double z, double n_prime,
                                      double* out_mx);
/** @brief m_z(z, n') [RHS] (2.4); n' = n gives (2.6); n' = +INFINITY gives (2.8). */
SWARP_API swarp_status swarp_error_mz(const swarp_error_config* cfg, double z, double n_prime,
                                      double* out_mz);
/** @brief Exact maxima of m_x and m_z over [near, far].  Both curves are
 *  convex in z (m_z ∝ a^2/z + 2a + z with a = n' - n), so the maximum is at
 *  an end point: no sampling.  Either output pointer may be NULL. */
SWARP_API swarp_status swarp_error_max(const swarp_error_config* cfg, double n_prime,
                                       double* out_max_mx, double* out_max_mz);
/** @brief The piecewise curve of a partitioned frustum ([RHS] Fig. 3.15, 3.18):
 *  split i covers [splits[i], splits[i+1]] with its own warp n_primes[i] and
 *  a full map of res_s x res_t.  splits has m + 1 strictly increasing entries
 *  (cfg->near/far are ignored).  Evaluates at each z[k] (a z on a border
 *  belongs to the split that starts there).  out_mx or out_mz may be NULL. */
SWARP_API swarp_status swarp_error_split_curve(const swarp_error_config* cfg,
                                               const double* splits,
                                               const double* n_primes, size_t m,
                                               const double* z, size_t count,
                                               double* out_mx, double* out_mz);
/** @brief Exact per-split and overall maxima of the piecewise curve.
 *  out_split_max_mx/mz may be NULL or hold m values; out_max_mx/mz may be NULL. */
SWARP_API swarp_status swarp_error_split_max(const swarp_error_config* cfg,
                                             const double* splits,
                                             const double* n_primes, size_t m,
                                             double* out_split_max_mx,
                                             double* out_split_max_mz,
                                             double* out_max_mx, double* out_max_mz);

/* ======================================================================== */
/* Core: split schemes                           (src/split.c)              */
/* ======================================================================== */
/** Worst case: the schemes write m + 1 values. */
#define SWARP_SPLIT_MAX_COUNT 64

/** @brief Uniform split scheme C_i = n + (f - n) i/m.  [RHS] (3.6)
 *  Writes m + 1 distances (C_0 = n, C_m = f) into out. */
SWARP_API swarp_status swarp_split_uniform(double n, double f, uint32_t m, double* out,
                                           size_t capacity, size_t* out_count);
/** @brief Logarithmic scheme C_i = n (f/n)^(i/m).  [RHS] (3.7) */
SWARP_API swarp_status swarp_split_log(double n, double f, uint32_t m, double* out,
                                       size_t capacity, size_t* out_count);
/** @brief Practical scheme, λ in [0, 1] (0 uniform, 1 logarithmic).  [RHS] (3.8) */
SWARP_API swarp_status swarp_split_practical(double n, double f, double lambda, uint32_t m,
                                             double* out, size_t capacity,
                                             size_t* out_count);
/** @brief Pseudo-near/far practical scheme.  [RHS] (4.1): the practical scheme
 *  over [n_p, f_p] (eye-space distances, n <= n_p < f_p <= f); C_0 = n and
 *  C_m = f are kept so the splits still cover the whole view. */
SWARP_API swarp_status swarp_split_pseudo(double n, double f, double n_p, double f_p,
                                          double lambda, uint32_t m, double* out,
                                          size_t capacity, size_t* out_count);

/* >>> api: geometry (src/poly.c body.c focus.c warp.c psm.c setup.c) */
/* <<< api: geometry */

/* >>> api: lixel (src/lixel.c) */
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
 *          SWARP_ERR_LIXEL_COPLANAR (conditioning < 1e-13), SWARP_ERR_NON_FINITE,
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
 *  _LIGHT_PARALLEL_PLANE, _PLANE_NOT_VISIBLE, SWARP_ERR_SINGULAR (M_v),
 *  SWARP_ERR_RESOLUTION, SWARP_ERR_ZERO_VECTOR, SWARP_ERR_OUT_OF_RANGE
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
 *  SWARP_ERR_LIXEL_RECT_TOO_LARGE, SWARP_ERR_OUT_OF_RANGE (scale < 0),
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
 *  @return SWARP_OK; SWARP_ERR_LIXEL_TWIST_LINE (the line images to a point
 *  or a point has q <= 0), SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_twist_for_line(const swarp_mat4* M_l, const swarp_vec3* a,
                                                  const swarp_vec3* b, const swarp_vec3* below,
                                                  double* out_twist);

/** @brief Factor M_l (after restriction, lixels 0..width-1 x 0..height-1)
 *  into M_l' = GLV · GLP for standard clipping.  [LIXEL] §2 ('M_l = GLV GLP')
 *  GLP is world -> clip (use it as the light's view-projection; w > 0 on
 *  the wanted side); GLV is the viewport NDC -> lixels
 *  (x = (x_ndc + 1) width/2 - 1/2) with depth passed through.  The depth
 *  row is remapped affinely (allowed by the paper's footnote): the raised
 *  point p-hat lands on the near plane (NDC -1, or 0) and P at the fraction
 *  plane_depth of the depth range (default 0.5), so geometry slightly
 *  behind P is not clipped.  (x, y, q) of M_l' equal those of M_l.
 *  @param plane_depth in [0, 1): 0 = default 0.5
 *  @return SWARP_OK; SWARP_ERR_RESOLUTION, SWARP_ERR_OUT_OF_RANGE,
 *  SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
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
 *  swarp_lixel_restrict (all points or all directions).
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
 *  @return SWARP_OK; SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER. */
SWARP_API swarp_status swarp_lixel_select(const swarp_mat4* GLP, size_t count, const swarp_vec3* p,
                                          uint32_t* out_index);
/* <<< api: lixel */

/* >>> api: filter (src/filter.c) */
/* <<< api: filter */

/* >>> api: splits (src/cascade.c stabilize.c bias.c atlas.c) */
/* <<< api: splits */

/* >>> api: plan (src/plan.c) */
/* <<< api: plan */

/* >>> api: extras (src/cube.c mindepth.c) */
/* <<< api: extras */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SHADOWWARP_H */
