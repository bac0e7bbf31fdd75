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
#define SWARP_STATUS_LIST_LIXEL(X)
/* <<< status: lixel */

/* >>> status: filter (300..399, 1300..1399) */
#define SWARP_STATUS_LIST_FILTER(X)
/* <<< status: filter */

/* >>> status: splits (400..499, 1400..1499) */
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
      "the normal faces away from the light; N.L clamped to 0")
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
/* <<< api: lixel */

/* >>> api: filter (src/filter.c) */
/* <<< api: filter */

/* >>> api: splits (src/cascade.c stabilize.c bias.c atlas.c) */
/*
 * Splits, atlas, stabilisation and bias.  Guide: docs/splits.md.
 */

/* ---- texture atlas and filter kernel   (src/atlas.c)   [RHS] §3.3.5, (3.9) */

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
 *  the window depth in [0, 1] (whatever the clip depth range). */
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
 *          SWARP_ERR_OUT_OF_RANGE (r_l < 0, max <= min), SWARP_ERR_ATLAS_SPLITS. */
SWARP_API swarp_status swarp_atlas_kernel_scale(double r_l, uint32_t m, double min_x,
                                                double max_x, double min_y, double max_y,
                                                double out_s[2]);

/* ---- flicker reduction                 (src/stabilize.c)   [RHS] §3.5 (ZZB09) */

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
 *  @param[out] out_center world centre; @param[out] out_radius radius;
 *  @param[out] out_centroid_radius may be NULL
 *  @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,
 *          SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV, SWARP_ERR_ZERO_VECTOR,
 *          SWARP_ERR_OUT_OF_RANGE (aspect <= 0), SWARP_ERR_DEGENERATE (up
 *          parallel to dir), SWARP_ERR_RESERVED_NONZERO. */
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
 *  world size 2 r res/(res - 1)); LEVELS: the light-space box of body_points
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
 *  @return SWARP_OK, SWARP_INFO_LEVEL_ABOVE_RANGE, SWARP_ERR_NULL_POINTER,
 *          SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV,
 *          SWARP_ERR_ZERO_VECTOR, SWARP_ERR_RESOLUTION, SWARP_ERR_UNKNOWN_ENUM,
 *          SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE,
 *          SWARP_ERR_DEGENERATE. */
SWARP_API swarp_status swarp_stabilize_directional(const swarp_camera* cam, double n_i, double f_i,
                                                   const swarp_vec3* light_dir,
                                                   const swarp_vec3* body_points, size_t body_count,
                                                   const swarp_aabb* scene, uint32_t res,
                                                   const swarp_stabilize_options* opt,
                                                   swarp_mat4* out_matrix,
                                                   swarp_stabilize_report* out_report);

/* ---- bias                               (src/bias.c)   [KOZ] §14.2.3 */

/** A shadow map as the bias functions see it: the final world -> clip matrix
 *  (uniform or warped, per split), its resolution and clip depth range.
 *  "Depth units" below are WINDOW depth d in [0, 1] (the value stored in the
 *  depth texture): d = (z_ndc + 1)/2 for [-1, 1], d = z_ndc for [0, 1]. */
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
 *  -direction for a directional light, (position - p)/|.| for a point light. */
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
 *  (may be NULL). */
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
 *  turns a world-space bias into the depth units of this split's map (the
 *  derivative of d along L at p).  Uniform maps: constant per split. */
SWARP_API swarp_status swarp_bias_depth_per_world(const swarp_bias_map* map, const swarp_light* light,
                                                  const swarp_vec3* p, double* out_depth_per_world);

/** @brief Receiver-plane depth bias: the depth gradient (dd/ds, dd/dt) in
 *  window depth per TEXEL of the receiver plane at p spanned by the world
 *  tangents tangent_a, tangent_b (e.g. dFdx/dFdy of the world position, or
 *  two edges of the triangle).  Exact derivative of the (possibly
 *  projective) map at p.  A PCF tap offset by (ds, dt) texels compares
 *  against d + dd/ds ds + dd/dt dt.  GLSL twin in docs/splits.md.
 *  @return as swarp_bias_texel_size; SWARP_ERR_DEGENERATE when the plane is
 *          seen edge-on by the light (its texel-space image is a line). */
SWARP_API swarp_status swarp_bias_receiver_plane(const swarp_bias_map* map, const swarp_vec3* p,
                                                 const swarp_vec3* tangent_a,
                                                 const swarp_vec3* tangent_b, double out_grad[2]);

/* ---- cascades: split selection and blending   (src/cascade.c)   [RHS] §3.3.3 */

/** @brief Split selection by eye depth (PSSM, ZSXL06; [RHS] §3.3.3):
 *  the i with splits[i] <= view_depth < splits[i+1] (a depth on a border
 *  belongs to the split that starts there; the far end to the last split).
 *  GLSL twin in docs/splits.md.
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
 *  docs/splits.md.
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
 *  GLSL twin in docs/splits.md.
 *  @param band  fraction of each split's length, in [0, 1) (0: hard switch)
 *  @return as swarp_cascade_select_depth; SWARP_ERR_OUT_OF_RANGE for band. */
SWARP_API swarp_status swarp_cascade_blend(const double* splits, size_t m, double view_depth,
                                           double band, uint32_t* out_index, double* out_weight);
/* <<< api: splits */

/* >>> api: plan (src/plan.c) */
/* <<< api: plan */

/* >>> api: extras (src/cube.c mindepth.c) */
/* <<< api: extras */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SHADOWWARP_H */
