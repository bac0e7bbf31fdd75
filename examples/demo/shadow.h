/* shadow.h -- the demo's one seam to the library: technique -> light
 * matrices.  Everything the renderer needs about a shadow configuration
 * (matrices per split, split distances, warp parameters for the error model)
 * comes out of demo_shadow_setup(); the renderer never computes shadow maths
 * of its own. */
#ifndef DEMO_SHADOW_H
#define DEMO_SHADOW_H

#include "shadowwarp.h"

#define DEMO_MAX_SPLITS 16
#define DEMO_MAX_BODY 128

typedef enum demo_technique {
    DEMO_TECH_UNIFORM = 0, /**< light-space aligned, focused uniform map */
    DEMO_TECH_LISPSM,      /**< LiSPSM with n_opt [RHS] (3.2) */
    DEMO_TECH_REPAR,       /**< LiSPSM with Lloyd's n_repar [RHS] (3.4) */
    DEMO_TECH_GMNPR,       /**< LiSPSM with lambda_GMNPR [GMNPR] (8) */
    DEMO_TECH_PSEUDO,      /**< LiSPSM with pseudo-near/far n_opt [RHS] (4.2) */
    DEMO_TECH_PSM,         /**< PSM [KOZ] */
    DEMO_TECH_PSM_CUBE,    /**< PSM with cube-map faces in post-projective space [KOZ] §14.2.2 */
    DEMO_TECH_PSSM,        /**< z-partitioned uniform maps [RHS] §3.3 */
    DEMO_TECH_PSSM_LISPSM, /**< z-partitioning + LiSPSM per split [RHS] §3.4 */
    DEMO_TECH_PSSM_STABLE, /**< stabilised cascades: exact minimal sphere + texel snap [RHS] §3.5 */
    DEMO_TECH_LIXEL,       /**< plane-stabilised maps [LIXEL] */
    DEMO_TECH_COUNT
} demo_technique;

typedef enum demo_scheme {
    DEMO_SCHEME_PRACTICAL = 0, /**< [RHS] (3.8), lambda */
    DEMO_SCHEME_UNIFORM,       /**< [RHS] (3.6) */
    DEMO_SCHEME_LOG,           /**< [RHS] (3.7) */
    DEMO_SCHEME_PSEUDO,        /**< [RHS] (4.1): practical lambda over [n_p, f_p] */
    DEMO_SCHEME_COUNT
} demo_scheme;

/** How the main pass picks the map for a fragment. */
typedef enum demo_select {
    DEMO_SELECT_DEPTH = 0, /**< by eye depth, swarp_cascade_select_depth [RHS] §3.3.3 */
    DEMO_SELECT_BEST,      /**< best resolution, swarp_cascade_select_best (ZZB09) */
    DEMO_SELECT_LIXEL,     /**< first map covering p, else the fallback: swarp_lixel_select */
    DEMO_SELECT_CUBE       /**< the cube face of [KOZ] Listing 14-1: swarp_cube_lookup */
} demo_select;

typedef struct demo_shadow_request {
    demo_technique technique;
    int splits;          /**< K for the PSSM techniques (1..DEMO_MAX_SPLITS) */
    demo_scheme scheme;
    double scheme_lambda; /**< practical scheme's lambda in [0, 1] */
    double pseudo_near, pseudo_far; /**< n_p, f_p of [RHS] (4.2), fractions (technique pseudo) */
    double scheme_np, scheme_fp;    /**< n_p, f_p of [RHS] (4.1), fractions (scheme pseudo) */
    int map_res;          /**< texels per side of each map */
    demo_select select;   /**< DEPTH or BEST for the PSSM techniques */
    int screen_w, screen_h;
    int nprime_measured;  /**< LiSPSM: the library's default n' (measured) instead of the
                               technique's closed form */
    int basis_aligned;    /**< uniform / lispsm one map: the view-aligned light basis of
                               swarp_focus_light_view, the matrix built from the steps */
} demo_shadow_request;


typedef struct demo_shadow {
    int count;                              /**< number of maps (passes) */
    demo_select select;
    int viewport[DEMO_MAX_SPLITS][2];       /**< texels of the layer each map uses */
    int depth_clamp;                        /**< pancake casters in front of the near plane */
    int model_applies;                      /**< Lloyd's m_x, m_z describe this configuration */
    swarp_mat4 light[DEMO_MAX_SPLITS];      /**< world -> light clip, per map */
    double split[DEMO_MAX_SPLITS + 1];      /**< eye-depth split distances C_i */
    double n_prime[DEMO_MAX_SPLITS];        /**< warp n' per map (INFINITY = uniform) */
    double z_near, z_far;                       /**< eye-depth range the maps cover */
    double predicted_max_mx, predicted_max_mz; /**< Lloyd's model; NAN when not available */
    swarp_measured_error measured;          /**< the library's measured error of the maps
                                                 over H (per split: split frustum ∩ S) with
                                                 bisector receivers, the worst map's */
    int have_measured;                      /**< 0: no such figure (lixel, cube faces) */
    swarp_status status;                    /**< library status of the setup */
    const char* source;                     /**< who computed the matrices */
    swarp_vec3 body[DEMO_MAX_BODY];         /**< points of B from the setup (whole view) */
    /* DEMO_SELECT_CUBE: the post-projective light and the faces */
    swarp_mat4 cube_camera;                 /**< world -> the camera's post-projective space */
    swarp_vec4 cube_light;                  /**< the light there, homogeneous */
    swarp_vec3 cube_normal[6];              /**< N_i per map */
    double cube_distance[6];                /**< d_i per map */
    uint32_t cube_face[6];                  /**< SWARP_CUBE_FACE_* per map */
    int body_count;
} demo_shadow;

const char* demo_technique_name(demo_technique t);
/** Parses a --technique name ("uniform", "lispsm", "pssm", ...); -1 if unknown. */
int demo_technique_parse(const char* name);
/** 1 for the z-partitioned techniques (they use --splits). */
int demo_technique_is_split(demo_technique t);
/** 1 if the library linked into this build can compute technique t. */
int demo_technique_available(demo_technique t);
const char* demo_scheme_name(demo_scheme s);
/** Parses practical[:L] | uniform | log | pseudo:NP,FP[,L]. */
int demo_scheme_parse(const char* name, double* lambda, double* np, double* fp);

/** Technique -> light matrices.  0 on success, -1 with a message on stderr
 *  (unavailable technique or a library error). */
int demo_shadow_setup(const swarp_camera* cam, const swarp_light* light,
                      const swarp_aabb* scene, const demo_shadow_request* req,
                      demo_shadow* out);

/** m_x and m_z [RHS] (2.3)-(2.8) at eye depth z for configuration sh, seen
 *  on a screen of w x h pixels with vertical fov fovy (radians).  0 on
 *  success, -1 if the model does not apply (lixel) or fails. */
int demo_predict(const demo_shadow* sh, double fovy, int w, int h, int map_res, double z,
                 double* out_mx, double* out_mz);

#endif
