"""The C API of include/shadowwarp.h as data (generated; do not edit).

Regenerate with:
    /usr/bin/python3 examples/python/gen_capi.py include/shadowwarp.h examples/python/shadowwarp/_capi.py

FUNCTIONS entries: (name, return type, [(param, base type, pointer depth,
const, array dims)], experimental).  STRUCTS: (typedef, [(field, type,
dims)]) in header order."""

CONSTANTS = {'SWARP_VERSION_MAJOR': 0,
 'SWARP_VERSION_MINOR': 2,
 'SWARP_VERSION_PATCH': 0,
 'SWARP_MAT4_MAX_CONDITION': 140737488355328.0,
 'SWARP_CAMERA_STRAY_NDC': 1e-06,
 'SWARP_CAMERA_RIGID_TOL': 1e-05,
 'SWARP_BODY_MAX_POINTS': 128,
 'SWARP_FOCUS_BLEND_SIN': 0.17364817766693033,
 'SWARP_FOCUS_BLEND_WEIGHT': 0.5,
 'SWARP_SPLIT_MAX_COUNT': 64,
 'SWARP_ATLAS_MAX_SPLITS': 16,
 'SWARP_CASCADE_MAX_SPLITS': 16,
 'SWARP_LVSM_MAX_LAYERS': 64,
 'SWARP_MSM_ALPHA_DEFAULT': 3e-05,
 'SWARP_PCF_MAX_SAMPLES': 256,
 'SWARP_POLY_MAX_VERTICES': 128,
 'SWARP_POLY_MAX_FACES': 64,
 'SWARP_POLY_MAX_FACE_VERTICES': 32,
 'SWARP_POLY_EPS_REL': 1e-12,
 'SWARP_FOLLOW_KAPPA': 4.0,
 'SWARP_LIXEL_DEFAULT_MAX_SIZE': 16384,
 'SWARP_PLAN_MAX_SPLITS': 16,
 'SWARP_PLAN_MAX_PLANES': 4,
 'SWARP_PLAN_EXPLAIN_MAX': 4608,
 'SWARP_PLAN_MAX_COST_NS': 1000000000000000.0,
 'SWARP_PLAN_WHY_ONE_MAP_MEETS': 1,
 'SWARP_PLAN_WHY_SPLITS_NEEDED': 2,
 'SWARP_PLAN_WHY_WARP_LOWERS_ERROR': 4,
 'SWARP_PLAN_WHY_NO_WARP_NO_GAIN': 8,
 'SWARP_PLAN_WHY_NO_WARP_MOVING': 16,
 'SWARP_PLAN_WHY_STABILIZE_MOVING': 32,
 'SWARP_PLAN_WHY_NO_STABILIZE_STATIC': 64,
 'SWARP_PLAN_WHY_INVERSE_PROJECTION': 128,
 'SWARP_PLAN_WHY_NO_INVERSE': 256,
 'SWARP_PLAN_WHY_FILTER_SOFT': 512,
 'SWARP_PLAN_WHY_NO_FILTER_HARD': 1024,
 'SWARP_PLAN_WHY_LIXEL_PLANE': 2048,
 'SWARP_PLAN_WHY_NO_LIXEL_NONE': 4096,
 'SWARP_PLAN_WHY_NO_LIXEL_SKIPPED': 8192,
 'SWARP_PLAN_WHY_DEPTH_CLAMP': 16384,
 'SWARP_PLAN_WHY_NO_CLAMP_DISALLOWED': 32768,
 'SWARP_PLAN_WHY_NO_CLAMP_WARPED': 65536,
 'SWARP_PLAN_WHY_BUDGET_UNMET': 131072,
 'SWARP_PLAN_WHY_TIME_LIMITED': 262144,
 'SWARP_PLAN_WHY_ATLAS_SHRINK': 524288,
 'SWARP_PLAN_WHY_NEAR_FAR_ADJUSTED': 1048576,
 'SWARP_PLAN_WHY_POINT_AS_DIRECTIONAL': 2097152,
 'SWARP_PLAN_WHY_PASS_LIMITED': 4194304,
 'SWARP_PLAN_WHY_FORCED': 8388608,
 'SWARP_PLAN_WHY_RANKED_MEASURED': 16777216,
 'SWARP_PLAN_PLANE_USED': 0,
 'SWARP_PLAN_PLANE_CAMERA_ON_PLANE': 1,
 'SWARP_PLAN_PLANE_LIGHT_GRAZING': 2,
 'SWARP_PLAN_PLANE_NOT_VISIBLE': 3,
 'SWARP_PLAN_PLANE_NO_PASS_LEFT': 4,
 'SWARP_PLAN_PLANE_LIXEL_REFUSED': 5,
 'SWARP_CUBE_FACE_POS_X': 0,
 'SWARP_CUBE_FACE_NEG_X': 1,
 'SWARP_CUBE_FACE_POS_Y': 2,
 'SWARP_CUBE_FACE_NEG_Y': 3,
 'SWARP_CUBE_FACE_POS_Z': 4,
 'SWARP_CUBE_FACE_NEG_Z': 5,
 'SWARP_CUBE_MAX_FACES': 6}

ENUMS = {'swarp_depth_range': {'SWARP_DEPTH_DEFAULT': 0,
                       'SWARP_DEPTH_NEG_ONE_TO_ONE': 1,
                       'SWARP_DEPTH_ZERO_TO_ONE': 2,
                       'SWARP_DEPTH_REVERSED_ZERO_TO_ONE': 3,
                       'SWARP_DEPTH_RANGE_FORCE_I32': 2147483647},
 'swarp_light_type': {'SWARP_LIGHT_DEFAULT': 0,
                      'SWARP_LIGHT_DIRECTIONAL': 1,
                      'SWARP_LIGHT_POINT': 2,
                      'SWARP_LIGHT_TYPE_FORCE_I32': 2147483647},
 'swarp_matrix_convention': {'SWARP_MATRIX_DEFAULT': 0,
                             'SWARP_MATRIX_RH': 1,
                             'SWARP_MATRIX_LH': 2,
                             'SWARP_MATRIX_RH_TRANSPOSED': 3,
                             'SWARP_MATRIX_LH_TRANSPOSED': 4,
                             'SWARP_MATRIX_CONVENTION_FORCE_I32': 2147483647},
 'swarp_texel_flag': {'SWARP_TEXEL_INSIDE': 1,
                      'SWARP_TEXEL_BEHIND_EYE': 2,
                      'SWARP_TEXEL_SINGULAR': 4,
                      'SWARP_TEXEL_FLAG_FORCE_U32': 2147483647},
 'swarp_warp_param': {'SWARP_WARP_PARAM_DEFAULT': 0,
                      'SWARP_WARP_PARAM_NOPT': 1,
                      'SWARP_WARP_PARAM_NREPAR': 2,
                      'SWARP_WARP_PARAM_GMNPR': 3,
                      'SWARP_WARP_PARAM_PSEUDO': 4,
                      'SWARP_WARP_PARAM_USER': 5,
                      'SWARP_WARP_PARAM_MEASURED': 6,
                      'SWARP_WARP_PARAM_FORCE_I32': 2147483647},
 'swarp_warp_center': {'SWARP_WARP_CENTER_DEFAULT': 0,
                       'SWARP_WARP_CENTER_VIEW_VECTOR': 1,
                       'SWARP_WARP_CENTER_NEAREST_VERTEX': 2,
                       'SWARP_WARP_CENTER_FORCE_I32': 2147483647},
 'swarp_technique': {'SWARP_TECHNIQUE_DEFAULT': 0,
                     'SWARP_TECHNIQUE_UNIFORM': 1,
                     'SWARP_TECHNIQUE_LISPSM': 2,
                     'SWARP_TECHNIQUE_PSM': 3,
                     'SWARP_TECHNIQUE_FORCE_I32': 2147483647},
 'swarp_stabilize_mode': {'SWARP_STABILIZE_DEFAULT': 0,
                          'SWARP_STABILIZE_NONE': 1,
                          'SWARP_STABILIZE_SPHERE': 2,
                          'SWARP_STABILIZE_LEVELS': 3,
                          'SWARP_STABILIZE_MODE_FORCE_I32': 2147483647},
 'swarp_split_scheme': {'SWARP_SCHEME_DEFAULT': 0,
                        'SWARP_SCHEME_UNIFORM': 1,
                        'SWARP_SCHEME_LOG': 2,
                        'SWARP_SCHEME_PRACTICAL': 3,
                        'SWARP_SCHEME_PSEUDO': 4,
                        'SWARP_SCHEME_MEASURED': 5,
                        'SWARP_SCHEME_FORCE_I32': 2147483647},
 'swarp_cascade_warp': {'SWARP_CASCADE_WARP_DEFAULT': 0,
                        'SWARP_CASCADE_WARP_EACH': 1,
                        'SWARP_CASCADE_WARP_FROM_FIRST': 2,
                        'SWARP_CASCADE_WARP_FORCE_I32': 2147483647},
 'swarp_texel_format': {'SWARP_TEXEL_DEFAULT': 0,
                        'SWARP_TEXEL_FP16': 1,
                        'SWARP_TEXEL_FP32': 2,
                        'SWARP_TEXEL_FORMAT_FORCE_I32': 2147483647},
 'swarp_plan_bleed': {'SWARP_PLAN_BLEED_DEFAULT': 0,
                      'SWARP_PLAN_BLEED_NONE': 1,
                      'SWARP_PLAN_BLEED_LOW': 2,
                      'SWARP_PLAN_BLEED_HIGH': 3,
                      'SWARP_PLAN_BLEED_EXTREME': 4,
                      'SWARP_PLAN_BLEED_FORCE_I32': 2147483647},
 'swarp_plan_by': {'SWARP_PLAN_BY_MEASURED': 0,
                   'SWARP_PLAN_BY_MODEL': 1,
                   'SWARP_PLAN_BY_FORCE_I32': 2147483647},
 'swarp_plan_warp': {'SWARP_PLAN_WARP_DEFAULT': 0,
                     'SWARP_PLAN_WARP_UNIFORM': 1,
                     'SWARP_PLAN_WARP_LISPSM_NOPT': 2,
                     'SWARP_PLAN_WARP_LISPSM_NREPAR': 3,
                     'SWARP_PLAN_WARP_LISPSM_GMNPR': 4,
                     'SWARP_PLAN_WARP_LISPSM_PSEUDO': 5,
                     'SWARP_PLAN_WARP_PSM': 6,
                     'SWARP_PLAN_WARP_FORCE_I32': 2147483647},
 'swarp_plan_scheme': {'SWARP_PLAN_SCHEME_DEFAULT': 0,
                       'SWARP_PLAN_SCHEME_NONE': 1,
                       'SWARP_PLAN_SCHEME_PRACTICAL': 2,
                       'SWARP_PLAN_SCHEME_LOG': 3,
                       'SWARP_PLAN_SCHEME_FORCE_I32': 2147483647},
 'swarp_plan_stabilize': {'SWARP_PLAN_STABILIZE_DEFAULT': 0,
                          'SWARP_PLAN_STABILIZE_NONE': 1,
                          'SWARP_PLAN_STABILIZE_APPROX64': 2,
                          'SWARP_PLAN_STABILIZE_FORCE_I32': 2147483647},
 'swarp_plan_filter': {'SWARP_PLAN_FILTER_DEFAULT': 0,
                       'SWARP_PLAN_FILTER_NONE': 1,
                       'SWARP_PLAN_FILTER_PCF': 2,
                       'SWARP_PLAN_FILTER_VSM': 3,
                       'SWARP_PLAN_FILTER_MSM': 4,
                       'SWARP_PLAN_FILTER_EVSM': 5,
                       'SWARP_PLAN_FILTER_LVSM': 6,
                       'SWARP_PLAN_FILTER_FORCE_I32': 2147483647},
 'swarp_plan_cost_model': {'SWARP_PLAN_COST_UNCALIBRATED': 0,
                           'SWARP_PLAN_COST_PER_PASS': 1,
                           'SWARP_PLAN_COST_LINEAR': 2,
                           'SWARP_PLAN_COST_FORCE_I32': 2147483647},
 'swarp_plan_matrices': {'SWARP_PLAN_MATRICES_MEASURED': 0,
                         'SWARP_PLAN_MATRICES_UNMEASURED': 1,
                         'SWARP_PLAN_MATRICES_NONE': 2,
                         'SWARP_PLAN_MATRICES_FORCE_I32': 2147483647}}

SCALAR_TYPEDEFS = {'swarp_status': 'int32_t'}

STATUSES = [('SWARP_OK', 0, 'ok'),
 ('SWARP_ERR_NULL_POINTER', 1, 'a required pointer argument is NULL'),
 ('SWARP_ERR_NON_FINITE', 2, 'an input value is NaN or infinite'),
 ('SWARP_ERR_INVALID_ARGUMENT', 3, 'an argument is invalid'),
 ('SWARP_ERR_OUT_OF_RANGE', 4, 'a value lies outside its documented domain'),
 ('SWARP_ERR_NEAR_FAR', 5, 'near must be > 0 and far must be > near'),
 ('SWARP_ERR_FOV', 6, 'field of view (or half angle) outside its open interval'),
 ('SWARP_ERR_RESOLUTION', 7, 'a resolution is zero, negative or not finite'),
 ('SWARP_ERR_CAPACITY', 8, 'output capacity too small; needed count written'),
 ('SWARP_ERR_ZERO_VECTOR', 9, 'a direction vector has zero length'),
 ('SWARP_ERR_RESERVED_NONZERO', 10, 'a _reserved field is not zero'),
 ('SWARP_ERR_DEGENERATE', 11, 'degenerate configuration'),
 ('SWARP_ERR_SPLIT_COUNT',
  12,
  'split count m is 0 (or above SWARP_SPLIT_MAX_COUNT for a split scheme)'),
 ('SWARP_ERR_UNKNOWN_ENUM', 13, 'an enum value is not one of the documented ones'),
 ('SWARP_ERR_NOT_INCREASING', 14, 'split distances must be strictly increasing'),
 ('SWARP_ERR_SINGULAR', 15, 'a matrix is singular or too ill-conditioned'),
 ('SWARP_ERR_OVERFLOW', 16, 'the result does not fit a finite double (inputs too extreme)'),
 ('SWARP_INFO_WARP_UNIFORM',
  1000,
  'warp faded to uniform (duelling frusta: light parallel to the view)'),
 ('SWARP_INFO_GMNPR_ADJUSTED',
  1001,
  'theta < phi: lambda_GMNPR uses the adjusted branch lambda_2* of eq. (7)'),
 ('SWARP_INFO_GLPR_NO_SOLUTION',
  1002,
  'GLPR has no positive lambda here (theta <= phi); lambda_GMNPR was written'),
 ('SWARP_INFO_MEASURE_SINGULAR',
  1003,
  'the map is singular at a measured point: its error is +inf there'),
 ('SWARP_ERR_BODY_EMPTY',
  100,
  'the view frustum misses the scene box (H = V intersect S is empty)'),
 ('SWARP_ERR_BOX_INVERTED', 101, 'scene box min exceeds max on some axis'),
 ('SWARP_ERR_BOX_DEGENERATE', 102, 'scene box has zero extent along two or more axes'),
 ('SWARP_ERR_LIGHT_INSIDE_BODY',
  103,
  'point light inside the body B: one perspective map cannot cover it'),
 ('SWARP_ERR_FOLLOW_FRAME',
  104,
  "the previous result's light frame is not orthonormal or not from this technique"),
 ('SWARP_ERR_CAMERA_NOT_PERSPECTIVE',
  105,
  'the projection is not a perspective one (orthographic, or x, y, z mixed or translated)'),
 ('SWARP_ERR_CAMERA_MIRRORED',
  106,
  'the view matrix mirrors (det < 0) or the projection looks backward for this handedness'),
 ('SWARP_ERR_CAMERA_VIEW_NOT_RIGID',
  107,
  'the view matrix is not a rotation and a translation (scaled, sheared or projective)'),
 ('SWARP_ERR_CAMERA_FAR_UNBOUNDED',
  108,
  "the projection's far plane is at infinity and no scene box bounds the view"),
 ('SWARP_INFO_LIGHT_PARALLEL',
  1100,
  'light nearly parallel to the view: light-space up blended toward camera right'),
 ('SWARP_INFO_FLAT_EXTENT', 1101, 'an extent of the focused body is zero; its width was padded'),
 ('SWARP_INFO_PSM_INVERSE',
  1102,
  'light behind the camera: PSM uses the inverse projection (near < 0 < far)'),
 ('SWARP_INFO_LIGHT_NEAR_CLIPPED',
  1103,
  'spot light on or inside B: points nearer than its near plane left out'),
 ('SWARP_INFO_FOLLOW_LAG',
  1104,
  'followed light frame still turning toward the aligned one (light near the view axis; LiSPSM '
  'weaker)'),
 ('SWARP_INFO_CAMERA_FAR_FROM_SCENE',
  1105,
  'infinite far plane: z_far is the farthest view depth of the scene box ([RHS] 3.3.1)'),
 ('SWARP_INFO_CASTERS_CLAMPED',
  1106,
  "casters over 1e10 times the receivers' size toward the light left out of the depth range (depth "
  'clamp)'),
 ('SWARP_ERR_LIXEL_COPLANAR',
  200,
  'four of the five points are coplanar (or a point is zero): no unique matrix'),
 ('SWARP_ERR_LIXEL_PLANE_THROUGH_EYE',
  201,
  "the plane of interest passes through the viewer's eye"),
 ('SWARP_ERR_LIXEL_LIGHT_ON_PLANE', 202, 'the point light lies on the plane of interest'),
 ('SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE',
  203,
  'the directional light is parallel to the plane of interest'),
 ('SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE',
  204,
  'no corner ray of the viewer hits the plane of interest in front of the eye'),
 ('SWARP_ERR_LIXEL_RAY_OUTSIDE', 205, 'a ray of C is outside the light frustum of M_l (q <= 0)'),
 ('SWARP_ERR_LIXEL_RECT_TOO_LARGE',
  206,
  'the light-image rectangle exceeds the allowed size (C approaches the line pi)'),
 ('SWARP_ERR_LIXEL_TWIST_LINE', 207, 'the twist line projects to a point in the light image'),
 ('SWARP_ERR_LIXEL_EMPTY', 208, "no ray of C hits the plane inside the viewer's frustum"),
 ('SWARP_INFO_LIXEL_ILL_CONDITIONED',
  1200,
  'the five-point configuration is ill-conditioned; the matrix may be inaccurate'),
 ('SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY',
  1201,
  'the quad Q straddles infinity (horizon visible); exact on the visible part'),
 ('SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW',
  1202,
  'the plane of interest is parallel to the view direction (horizon through the centre)'),
 ('SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE',
  1203,
  'light and viewer are on opposite sides of the plane of interest'),
 ('SWARP_ERR_FILTER_LAYER_COUNT', 300, 'LVSM layer count must be in 1..SWARP_LVSM_MAX_LAYERS'),
 ('SWARP_ERR_FILTER_OVERLAP',
  301,
  'LVSM overlap delta must be >= 0 and smaller than the thinnest layer'),
 ('SWARP_ERR_FILTER_BAND',
  302,
  'LVSM transition band must lie in [0, delta] and below half the thinnest layer'),
 ('SWARP_ERR_FILTER_NO_SAMPLES', 303, 'Lloyd relaxation needs at least one sample'),
 ('SWARP_ERR_FILTER_BLOCKER', 304, 'PCSS blocker depth must be > 0 and not beyond the receiver'),
 ('SWARP_ERR_FILTER_EXPONENT', 305, 'EVSM exponent must be > 0 and keep e^(2c) finite in double'),
 ('SWARP_INFO_FILTER_NOT_CONVERGED',
  1300,
  'Lloyd relaxation reached its iteration bound before converging; splits written'),
 ('SWARP_INFO_FILTER_NO_WEIGHT',
  1301,
  'all Lloyd sample weights are zero: splits written unchanged'),
 ('SWARP_INFO_FILTER_MSM_DEGENERATE',
  1302,
  'moment matrix singular (at most two distinct depths): exact discrete form used'),
 ('SWARP_INFO_FILTER_DEPTH_CLAMPED',
  1303,
  'depth outside [s_0, s_N]: the first or last layer was used'),
 ('SWARP_ERR_ATLAS_SPLITS', 400, 'atlas layouts hold 1..16 splits'),
 ('SWARP_ERR_STABILIZE_WARPED',
  401,
  'stabilisation is defined for uniform light-space aligned maps; a warp was requested'),
 ('SWARP_ERR_STABILIZE_LIGHT', 402, 'stabilisation needs a directional light'),
 ('SWARP_ERR_BEHIND_PROJECTION',
  403,
  'the point maps to w <= 0 (behind the centre of projection of the light matrix)'),
 ('SWARP_ERR_SPLIT_EMPTY', 404, 'a split frustum does not intersect the scene'),
 ('SWARP_INFO_LEVEL_ABOVE_RANGE',
  1400,
  'the body is larger than the reference size: quantised level above the level count'),
 ('SWARP_INFO_OUTSIDE_SPLITS',
  1401,
  'the point lies in no split map; the split nearest in eye depth was chosen'),
 ('SWARP_INFO_BACKFACING', 1402, 'the normal faces away from the light; N.L clamped to 0'),
 ('SWARP_INFO_SPLIT_NO_SCENE',
  1403,
  'a stabilised split misses the scene box; its map covers the split frustum'),
 ('SWARP_ERR_PLAN_TOO_MANY_PLANES', 500, 'plane_count exceeds SWARP_PLAN_MAX_PLANES'),
 ('SWARP_ERR_PLAN_EMPTY_VIEW',
  501,
  'the scene box lies entirely outside the view depth range: nothing to shadow'),
 ('SWARP_INFO_PLAN_BUDGET_UNMET',
  1500,
  'no chain meets the budget; the plan is the most accurate within the pass limit'),
 ('SWARP_INFO_PLAN_POINT_LIGHT',
  1501,
  "point light planned as a directional light toward the view frustum's centre"),
 ('SWARP_ERR_CUBE_LIGHT_AT_INFINITY',
  600,
  'light at infinity in post-projective space (w = 0): no cube map, use one orthographic map'),
 ('SWARP_ERR_CUBE_POINT_UNCOVERED',
  601,
  'the point is in no cube-map face frustum (it coincides with the light or lies behind it)'),
 ('SWARP_INFO_CUBE_NEAR_CLIPPED',
  1601,
  "the point lies inside the faces' near cube (a < Z_1): the face camera clips it"),
 ('SWARP_INFO_MINDEPTH_EMPTY',
  1600,
  'the depth buffer holds nothing nearer than far: near plane left unchanged')]

STRUCTS = [('swarp_vec3', [('x', 'double', ()), ('y', 'double', ()), ('z', 'double', ())]),
 ('swarp_vec4',
  [('x', 'double', ()), ('y', 'double', ()), ('z', 'double', ()), ('w', 'double', ())]),
 ('swarp_mat4', [('m', 'double', (16,))]),
 ('swarp_plane',
  [('a', 'double', ()), ('b', 'double', ()), ('c', 'double', ()), ('d', 'double', ())]),
 ('swarp_camera',
  [('eye', 'swarp_vec3', ()),
   ('dir', 'swarp_vec3', ()),
   ('up', 'swarp_vec3', ()),
   ('fovy', 'double', ()),
   ('aspect', 'double', ()),
   ('z_near', 'double', ()),
   ('z_far', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_light',
  [('type', 'swarp_light_type', ()),
   ('_reserved0', 'uint32_t', ()),
   ('direction', 'swarp_vec3', ()),
   ('position', 'swarp_vec3', ()),
   ('cone_angle', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_aabb', [('min', 'swarp_vec3', ()), ('max', 'swarp_vec3', ())]),
 ('swarp_camera_from_info',
  [('reversed_z', 'uint32_t', ()),
   ('infinite_far', 'uint32_t', ()),
   ('off_center_x', 'double', ()),
   ('off_center_y', 'double', ())]),
 ('swarp_measure_res',
  [('screen_width', 'uint32_t', ()),
   ('screen_height', 'uint32_t', ()),
   ('map_width', 'uint32_t', ()),
   ('map_height', 'uint32_t', ())]),
 ('swarp_texel_error',
  [('m_s', 'double', ()),
   ('m_t', 'double', ()),
   ('sigma', 'double', ()),
   ('flags', 'uint32_t', ()),
   ('_pad', 'uint32_t', ())]),
 ('swarp_measured_error',
  [('max_m_s', 'double', ()),
   ('max_m_t', 'double', ()),
   ('max_sigma', 'double', ()),
   ('at', 'swarp_vec3', ()),
   ('samples', 'uint32_t', ()),
   ('outside', 'uint32_t', ())]),
 ('swarp_measure_options',
  [('grid', 'uint32_t', ()),
   ('depths', 'uint32_t', ()),
   ('refine', 'uint32_t', ()),
   ('_reserved', 'uint32_t', ())]),
 ('swarp_setup_options',
  [('technique', 'swarp_technique', ()),
   ('param', 'swarp_warp_param', ()),
   ('center', 'swarp_warp_center', ()),
   ('depth_range', 'swarp_depth_range', ()),
   ('map_width', 'uint32_t', ()),
   ('map_height', 'uint32_t', ()),
   ('screen_width', 'uint32_t', ()),
   ('screen_height', 'uint32_t', ()),
   ('pancake', 'uint32_t', ()),
   ('psm_slideback', 'uint32_t', ()),
   ('_pad0', 'uint32_t', ()),
   ('_pad1', 'uint32_t', ()),
   ('n_user', 'double', ()),
   ('pseudo_near', 'double', ()),
   ('pseudo_far', 'double', ()),
   ('slideback', 'double', ()),
   ('min_depth', 'double', ()),
   ('skip_measure', 'uint32_t', ()),
   ('_reserved', 'uint32_t', (1,))]),
 ('swarp_setup_result',
  [('light_view', 'swarp_mat4', ()),
   ('light_proj', 'swarp_mat4', ()),
   ('matrix', 'swarp_mat4', ()),
   ('n_eye', 'double', ()),
   ('n_light', 'double', ()),
   ('view_near', 'double', ()),
   ('view_far', 'double', ()),
   ('gamma', 'double', ()),
   ('max_mx', 'double', ()),
   ('max_mz', 'double', ()),
   ('light_near', 'double', ()),
   ('light_far', 'double', ()),
   ('point_count', 'uint32_t', ()),
   ('_pad', 'uint32_t', ()),
   ('measured', 'swarp_measured_error', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_warp_options',
  [('param', 'swarp_warp_param', ()),
   ('center', 'swarp_warp_center', ()),
   ('n_user', 'double', ()),
   ('pseudo_near', 'double', ()),
   ('pseudo_far', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_warp_info',
  [('n_light', 'double', ()),
   ('n_eye', 'double', ()),
   ('d', 'double', ()),
   ('z_0', 'double', ()),
   ('z_1', 'double', ()),
   ('gamma', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_error_config',
  [('z_near', 'double', ()),
   ('z_far', 'double', ()),
   ('theta', 'double', ()),
   ('res_ix', 'double', ()),
   ('res_iy', 'double', ()),
   ('res_s', 'double', ()),
   ('res_t', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_atlas_info',
  [('split_count', 'uint32_t', ()),
   ('grid', 'uint32_t', ()),
   ('tile_res', 'double', ()),
   ('atlas_res', 'double', ()),
   ('l_sc', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_atlas_tile',
  [('viewport_x', 'double', ()),
   ('viewport_y', 'double', ()),
   ('viewport_width', 'double', ()),
   ('viewport_height', 'double', ()),
   ('clip_to_atlas', 'swarp_mat4', ())]),
 ('swarp_stabilize_options',
  [('mode', 'swarp_stabilize_mode', ()),
   ('levels', 'uint32_t', ()),
   ('origin', 'swarp_vec3', ()),
   ('level_max_size', 'double', ()),
   ('depth', 'swarp_depth_range', ()),
   ('_reserved0', 'uint32_t', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_stabilize_report',
  [('sphere_center', 'swarp_vec3', ()),
   ('sphere_radius', 'double', ()),
   ('centroid_radius', 'double', ()),
   ('area_saved', 'double', ()),
   ('texel_size_x', 'double', ()),
   ('texel_size_y', 'double', ()),
   ('offset_x', 'double', ()),
   ('offset_y', 'double', ()),
   ('level_x', 'uint32_t', ()),
   ('level_y', 'uint32_t', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_bias_map',
  [('world_to_clip', 'swarp_mat4', ()),
   ('res_s', 'double', ()),
   ('res_t', 'double', ()),
   ('depth', 'swarp_depth_range', ()),
   ('_reserved0', 'uint32_t', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_split_options',
  [('count', 'uint32_t', ()),
   ('scheme', 'swarp_split_scheme', ()),
   ('lambda', 'double', ()),
   ('pseudo_near', 'double', ()),
   ('pseudo_far', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_cascade_options',
  [('setup', 'swarp_setup_options', ()),
   ('split', 'swarp_split_options', ()),
   ('stabilize', 'swarp_stabilize_options', ()),
   ('kernel_world_size', 'double', ()),
   ('n_user', 'double', (16,)),
   ('warp_per_split', 'swarp_cascade_warp', ()),
   ('_reserved', 'uint32_t', (3,))]),
 ('swarp_cascade_split',
  [('z_near', 'double', ()),
   ('z_far', 'double', ()),
   ('matrix', 'swarp_mat4', ()),
   ('atlas_matrix', 'swarp_mat4', ()),
   ('tile', 'swarp_atlas_tile', ()),
   ('n_eye', 'double', ()),
   ('kernel_scale', 'double', (2,)),
   ('max_mx', 'double', ()),
   ('max_mz', 'double', ()),
   ('mx_start', 'double', ()),
   ('mz_start', 'double', ()),
   ('mx_end', 'double', ()),
   ('mz_end', 'double', ()),
   ('texel_size', 'double', ()),
   ('depth_per_world', 'double', ()),
   ('status', 'swarp_status', ()),
   ('point_count', 'uint32_t', ()),
   ('measured', 'swarp_measured_error', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_cascade_result',
  [('split_count', 'uint32_t', ()),
   ('_pad', 'uint32_t', ()),
   ('view_near', 'double', ()),
   ('view_far', 'double', ()),
   ('splits', 'double', (17,)),
   ('max_mx', 'double', ()),
   ('max_mz', 'double', ()),
   ('atlas', 'swarp_atlas_info', ()),
   ('measured', 'swarp_measured_error', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_lloyd_options',
  [('max_iterations', 'uint32_t', ()),
   ('_pad0', 'uint32_t', ()),
   ('weight_clamp_lo', 'double', ()),
   ('weight_clamp_hi', 'double', ()),
   ('tolerance', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_lloyd_report',
  [('iterations', 'uint32_t', ()),
   ('teleports', 'uint32_t', ()),
   ('converged', 'uint32_t', ()),
   ('_pad0', 'uint32_t', ()),
   ('max_shift', 'double', ())]),
 ('swarp_polyhedron',
  [('vertex_count', 'uint32_t', ()),
   ('face_count', 'uint32_t', ()),
   ('vertices', 'swarp_vec3', (128,)),
   ('planes', 'swarp_plane', (64,)),
   ('face_vertex_count', 'uint32_t', (64,)),
   ('face_vertices', 'uint8_t', (64, 32))]),
 ('swarp_lixel_options', [('raise', 'double', ()), ('_reserved', 'uint32_t', (4,))]),
 ('swarp_lixel_info',
  [('corners', 'swarp_vec4', (4,)),
   ('raised', 'swarp_vec4', ()),
   ('raised_index', 'uint32_t', ()),
   ('corners_in_front', 'uint32_t', ()),
   ('conditioning', 'double', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_lixel_rect',
  [('x0', 'int32_t', ()),
   ('y0', 'int32_t', ()),
   ('x1', 'int32_t', ()),
   ('y1', 'int32_t', ()),
   ('width', 'uint32_t', ()),
   ('height', 'uint32_t', ())]),
 ('swarp_lixel_restrict_options',
  [('scale_x', 'double', ()),
   ('scale_y', 'double', ()),
   ('twist', 'double', ()),
   ('max_size', 'uint32_t', ()),
   ('view_width', 'uint32_t', ()),
   ('view_height', 'uint32_t', ()),
   ('_reserved0', 'uint32_t', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_scene_needs',
  [('camera', 'swarp_camera', ()),
   ('light', 'swarp_light', ()),
   ('scene_box', 'swarp_aabb', ()),
   ('screen_width', 'uint32_t', ()),
   ('screen_height', 'uint32_t', ()),
   ('camera_moves', 'uint32_t', ()),
   ('soft_shadows', 'uint32_t', ()),
   ('soft_width', 'double', ()),
   ('bleed_risk', 'swarp_plan_bleed', ()),
   ('allow_depth_clamp', 'uint32_t', ()),
   ('plane_count', 'uint32_t', ()),
   ('_pad0', 'uint32_t', ()),
   ('planes', 'swarp_plane', (4,)),
   ('plan_by', 'swarp_plan_by', ()),
   ('_reserved', 'uint32_t', (3,))]),
 ('swarp_budget',
  [('max_error', 'double', ()),
   ('map_resolution', 'uint32_t', ()),
   ('atlas_limit', 'uint32_t', ()),
   ('max_passes', 'uint32_t', ()),
   ('_pad0', 'uint32_t', ()),
   ('time_budget_ns', 'double', ()),
   ('pass_cost_ns', 'double', ()),
   ('blur_pass_cost_ns', 'double', ()),
   ('pass_overhead_ns', 'double', ()),
   ('texel_cost_ns', 'double', ())]),
 ('swarp_plan_result',
  [('warp', 'swarp_plan_warp', ()),
   ('scheme', 'swarp_plan_scheme', ()),
   ('split_count', 'uint32_t', ()),
   ('map_resolution', 'uint32_t', ()),
   ('atlas_tiles', 'uint32_t', ()),
   ('stabilize', 'swarp_plan_stabilize', ()),
   ('inverse_projection', 'uint32_t', ()),
   ('depth_clamp', 'uint32_t', ()),
   ('gamma', 'double', ()),
   ('z_near', 'double', ()),
   ('z_far', 'double', ()),
   ('splits', 'double', (17,)),
   ('n_prime', 'double', (16,)),
   ('split_max_mx', 'double', (16,)),
   ('split_max_mz', 'double', (16,)),
   ('max_mx', 'double', ()),
   ('max_mz', 'double', ()),
   ('max_error', 'double', ()),
   ('error_area', 'double', ()),
   ('lixel_count', 'uint32_t', ()),
   ('lixel_planes', 'uint32_t', (4,)),
   ('plane_reason', 'uint32_t', (4,)),
   ('lixel_error', 'double', ()),
   ('filter', 'swarp_plan_filter', ()),
   ('filter_layers', 'uint32_t', ()),
   ('filter_width', 'double', ()),
   ('filter_exponent_pos', 'double', ()),
   ('filter_exponent_neg', 'double', ()),
   ('shadow_passes', 'uint32_t', ()),
   ('blur_passes', 'uint32_t', ()),
   ('texels', 'double', ()),
   ('cost_ns', 'double', ()),
   ('meets_budget', 'uint32_t', ()),
   ('reasons', 'uint32_t', ()),
   ('candidates', 'uint32_t', ()),
   ('plane_count', 'uint32_t', ()),
   ('built', 'uint32_t', ()),
   ('built_status', 'swarp_status', ()),
   ('built_splits', 'double', (17,)),
   ('built_n_eye', 'double', (16,)),
   ('split_measured', 'swarp_measured_error', (16,)),
   ('measured', 'swarp_measured_error', ()),
   ('cost_model', 'swarp_plan_cost_model', ()),
   ('_reserved', 'uint32_t', (3,))]),
 ('swarp_plan_chain',
  [('warp', 'swarp_plan_warp', ()),
   ('scheme', 'swarp_plan_scheme', ()),
   ('split_count', 'uint32_t', ()),
   ('stabilize', 'swarp_plan_stabilize', ()),
   ('matrices', 'swarp_plan_matrices', ()),
   ('_reserved', 'uint32_t', (4,))]),
 ('swarp_cube_options',
  [('z1', 'double', ()),
   ('depth_range', 'swarp_depth_range', ()),
   ('_reserved', 'uint32_t', (5,))]),
 ('swarp_cube_face',
  [('face', 'uint32_t', ()),
   ('inverse', 'uint32_t', ()),
   ('distance', 'double', ()),
   ('right', 'swarp_vec3', ()),
   ('up', 'swarp_vec3', ()),
   ('normal', 'swarp_vec3', ()),
   ('view', 'swarp_mat4', ()),
   ('proj', 'swarp_mat4', ()),
   ('view_proj', 'swarp_mat4', ())]),
 ('swarp_mindepth_options', [('margin', 'double', ()), ('_reserved', 'uint32_t', (4,))])]

STRUCT_TAGS = {'swarp_vec3': 'swarp_vec3',
 'swarp_vec4': 'swarp_vec4',
 'swarp_mat4': 'swarp_mat4',
 'swarp_plane': 'swarp_plane',
 'swarp_camera': 'swarp_camera',
 'swarp_light': 'swarp_light',
 'swarp_aabb': 'swarp_aabb',
 'swarp_camera_from_info': 'swarp_camera_from_info',
 'swarp_measure_res': 'swarp_measure_res',
 'swarp_texel_error': 'swarp_texel_error',
 'swarp_measured_error': 'swarp_measured_error',
 'swarp_measure_options': 'swarp_measure_options',
 'swarp_setup_options': 'swarp_setup_options',
 'swarp_setup_result': 'swarp_setup_result',
 'swarp_warp_options': 'swarp_warp_options',
 'swarp_warp_info': 'swarp_warp_info',
 'swarp_error_config': 'swarp_error_config',
 'swarp_atlas_info': 'swarp_atlas_info',
 'swarp_atlas_tile': 'swarp_atlas_tile',
 'swarp_stabilize_options': 'swarp_stabilize_options',
 'swarp_stabilize_report': 'swarp_stabilize_report',
 'swarp_bias_map': 'swarp_bias_map',
 'swarp_split_options': 'swarp_split_options',
 'swarp_cascade_options': 'swarp_cascade_options',
 'swarp_cascade_split': 'swarp_cascade_split',
 'swarp_cascade_result': 'swarp_cascade_result',
 'swarp_lloyd_options': 'swarp_lloyd_options',
 'swarp_lloyd_report': 'swarp_lloyd_report',
 'swarp_polyhedron': 'swarp_polyhedron',
 'swarp_lixel_options': 'swarp_lixel_options',
 'swarp_lixel_info': 'swarp_lixel_info',
 'swarp_lixel_rect': 'swarp_lixel_rect',
 'swarp_lixel_restrict_options': 'swarp_lixel_restrict_options',
 'swarp_scene_needs': 'swarp_scene_needs',
 'swarp_budget': 'swarp_budget',
 'swarp_plan': 'swarp_plan_result',
 'swarp_plan_chain': 'swarp_plan_chain',
 'swarp_cube_options': 'swarp_cube_options',
 'swarp_cube_face': 'swarp_cube_face',
 'swarp_mindepth_options': 'swarp_mindepth_options'}

FUNCTIONS = [('swarp_status_string', 'const char *', [('status', 'swarp_status', 0, False, ())], False),
 ('swarp_status_name', 'const char *', [('status', 'swarp_status', 0, False, ())], False),
 ('swarp_status_is_error', 'int', [('status', 'swarp_status', 0, False, ())], False),
 ('swarp_version_number', 'int', [], False),
 ('swarp_version_string', 'const char *', [], False),
 ('swarp_mat4_to_float',
  'swarp_status',
  [('m', 'swarp_mat4', 1, True, ()), ('out', 'float', 0, False, (16,))],
  False),
 ('swarp_mat4_mul',
  'swarp_status',
  [('a', 'swarp_mat4', 1, True, ()),
   ('b', 'swarp_mat4', 1, True, ()),
   ('r', 'swarp_mat4', 1, False, ())],
  False),
 ('swarp_mat4_invert',
  'swarp_status',
  [('a', 'swarp_mat4', 1, True, ()), ('r', 'swarp_mat4', 1, False, ())],
  False),
 ('swarp_mat4_transform',
  'swarp_status',
  [('m', 'swarp_mat4', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('out', 'swarp_vec4', 1, False, ())],
  False),
 ('swarp_camera_from_matrices',
  'swarp_status',
  [('view', 'swarp_mat4', 1, True, ()),
   ('projection', 'swarp_mat4', 1, True, ()),
   ('convention', 'swarp_matrix_convention', 0, False, ()),
   ('depth_range', 'swarp_depth_range', 0, False, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('out_cam', 'swarp_camera', 1, False, ()),
   ('out_info', 'swarp_camera_from_info', 1, False, ())],
  False),
 ('swarp_setup',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('opts', 'swarp_setup_options', 1, True, ()),
   ('out', 'swarp_setup_result', 1, False, ()),
   ('out_points', 'swarp_vec3', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_setup_range',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('opts', 'swarp_setup_options', 1, True, ()),
   ('out', 'swarp_setup_result', 1, False, ()),
   ('out_points', 'swarp_vec3', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_setup_points',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('points', 'swarp_vec3', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('receivers', 'swarp_vec3', 1, True, ()),
   ('receiver_count', 'size_t', 0, False, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('opts', 'swarp_setup_options', 1, True, ()),
   ('out', 'swarp_setup_result', 1, False, ())],
  False),
 ('swarp_body_points',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('out', 'swarp_vec3', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_body_adjusted_range',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('out_near', 'double', 1, False, ()),
   ('out_far', 'double', 1, False, ())],
  False),
 ('swarp_focus_light_view',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('axis', 'swarp_vec3', 1, True, ()),
   ('out_view', 'swarp_mat4', 1, False, ())],
  False),
 ('swarp_focus_fit',
  'swarp_status',
  [('m', 'swarp_mat4', 1, True, ()),
   ('points', 'swarp_vec3', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('z_points', 'swarp_vec3', 1, True, ()),
   ('z_count', 'size_t', 0, False, ()),
   ('depth_range', 'swarp_depth_range', 0, False, ()),
   ('out_A_fit', 'swarp_mat4', 1, False, ())],
  False),
 ('swarp_warp_lispsm',
  'swarp_status',
  [('light_view', 'swarp_mat4', 1, True, ()),
   ('cam', 'swarp_camera', 1, True, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('points', 'swarp_vec3', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('nearest', 'swarp_vec3', 1, True, ()),
   ('opts', 'swarp_warp_options', 1, True, ()),
   ('out_P', 'swarp_mat4', 1, False, ()),
   ('out_info', 'swarp_warp_info', 1, False, ())],
  False),
 ('swarp_warp_nopt',
  'swarp_status',
  [('d', 'double', 0, False, ()),
   ('z_0', 'double', 0, False, ()),
   ('z_1', 'double', 0, False, ()),
   ('out_n_opt', 'double', 1, False, ())],
  False),
 ('swarp_warp_nopt_pseudo',
  'swarp_status',
  [('d', 'double', 0, False, ()),
   ('z_0', 'double', 0, False, ()),
   ('z_1', 'double', 0, False, ()),
   ('n_p', 'double', 0, False, ()),
   ('f_p', 'double', 0, False, ()),
   ('out_n_opt', 'double', 1, False, ())],
  False),
 ('swarp_warp_eta',
  'swarp_status',
  [('gamma', 'double', 0, False, ()),
   ('theta', 'double', 0, False, ()),
   ('out_eta', 'double', 1, False, ())],
  False),
 ('swarp_warp_wlz',
  'swarp_status',
  [('gamma', 'double', 0, False, ()),
   ('theta', 'double', 0, False, ()),
   ('n_e', 'double', 0, False, ()),
   ('f_e', 'double', 0, False, ()),
   ('W_e', 'double', 0, False, ()),
   ('out_W_lz', 'double', 1, False, ())],
  False),
 ('swarp_warp_nrepar',
  'swarp_status',
  [('eta', 'double', 0, False, ()),
   ('alpha', 'double', 0, False, ()),
   ('W_lz', 'double', 0, False, ()),
   ('out_n', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_psi',
  'swarp_status',
  [('lambda', 'double', 0, False, ()),
   ('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('out_psi', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_offset',
  'swarp_status',
  [('lambda', 'double', 0, False, ()),
   ('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('out_offset', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_F',
  'swarp_status',
  [('lambda', 'double', 0, False, ()),
   ('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('z', 'double', 0, False, ()),
   ('out_F', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_lambda12',
  'swarp_status',
  [('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('out_lambda_1', 'double', 1, False, ()),
   ('out_lambda_2', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_lambda',
  'swarp_status',
  [('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('out_lambda', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_lambda_lispsm',
  'swarp_status',
  [('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('out_lambda', 'double', 1, False, ())],
  False),
 ('swarp_gmnpr_lambda_glpr',
  'swarp_status',
  [('theta', 'double', 0, False, ()),
   ('phi', 'double', 0, False, ()),
   ('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('out_lambda', 'double', 1, False, ())],
  False),
 ('swarp_measure_points',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('matrix', 'swarp_mat4', 1, True, ()),
   ('res', 'swarp_measure_res', 1, True, ()),
   ('points', 'swarp_vec3', 1, True, ()),
   ('normals', 'swarp_vec3', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('out', 'swarp_texel_error', 1, False, ())],
  False),
 ('swarp_measure_max',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('matrix', 'swarp_mat4', 1, True, ()),
   ('res', 'swarp_measure_res', 1, True, ()),
   ('opts', 'swarp_measure_options', 1, True, ()),
   ('out', 'swarp_measured_error', 1, False, ())],
  False),
 ('swarp_error_mx',
  'swarp_status',
  [('cfg', 'swarp_error_config', 1, True, ()),
   ('z', 'double', 0, False, ()),
   ('n_prime', 'double', 0, False, ()),
   ('out_mx', 'double', 1, False, ())],
  False),
 ('swarp_error_mz',
  'swarp_status',
  [('cfg', 'swarp_error_config', 1, True, ()),
   ('z', 'double', 0, False, ()),
   ('n_prime', 'double', 0, False, ()),
   ('out_mz', 'double', 1, False, ())],
  False),
 ('swarp_error_max',
  'swarp_status',
  [('cfg', 'swarp_error_config', 1, True, ()),
   ('n_prime', 'double', 0, False, ()),
   ('out_max_mx', 'double', 1, False, ()),
   ('out_max_mz', 'double', 1, False, ())],
  False),
 ('swarp_error_split_curve',
  'swarp_status',
  [('cfg', 'swarp_error_config', 1, True, ()),
   ('splits', 'double', 1, True, ()),
   ('n_primes', 'double', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('z', 'double', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('out_mx', 'double', 1, False, ()),
   ('out_mz', 'double', 1, False, ())],
  False),
 ('swarp_error_split_max',
  'swarp_status',
  [('cfg', 'swarp_error_config', 1, True, ()),
   ('splits', 'double', 1, True, ()),
   ('n_primes', 'double', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('out_split_max_mx', 'double', 1, False, ()),
   ('out_split_max_mz', 'double', 1, False, ()),
   ('out_max_mx', 'double', 1, False, ()),
   ('out_max_mz', 'double', 1, False, ())],
  False),
 ('swarp_split_uniform',
  'swarp_status',
  [('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('m', 'uint32_t', 0, False, ()),
   ('out', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_split_log',
  'swarp_status',
  [('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('m', 'uint32_t', 0, False, ()),
   ('out', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_split_practical',
  'swarp_status',
  [('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('lambda', 'double', 0, False, ()),
   ('m', 'uint32_t', 0, False, ()),
   ('out', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_split_pseudo',
  'swarp_status',
  [('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('n_p', 'double', 0, False, ()),
   ('f_p', 'double', 0, False, ()),
   ('lambda', 'double', 0, False, ()),
   ('m', 'uint32_t', 0, False, ()),
   ('out', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_atlas_layout',
  'swarp_status',
  [('m', 'uint32_t', 0, False, ()),
   ('tile_res', 'uint32_t', 0, False, ()),
   ('depth', 'swarp_depth_range', 0, False, ()),
   ('out_info', 'swarp_atlas_info', 1, False, ()),
   ('out_tiles', 'swarp_atlas_tile', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_atlas_lsc',
  'swarp_status',
  [('m', 'uint32_t', 0, False, ()), ('out_l_sc', 'double', 1, False, ())],
  False),
 ('swarp_atlas_kernel_scale',
  'swarp_status',
  [('r_l', 'double', 0, False, ()),
   ('m', 'uint32_t', 0, False, ()),
   ('min_x', 'double', 0, False, ()),
   ('max_x', 'double', 0, False, ()),
   ('min_y', 'double', 0, False, ()),
   ('max_y', 'double', 0, False, ()),
   ('out_s', 'double', 0, False, (2,))],
  False),
 ('swarp_stabilize_sphere',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('n_i', 'double', 0, False, ()),
   ('f_i', 'double', 0, False, ()),
   ('out_center', 'swarp_vec3', 1, False, ()),
   ('out_radius', 'double', 1, False, ()),
   ('out_centroid_radius', 'double', 1, False, ())],
  False),
 ('swarp_stabilize_light_view',
  'swarp_status',
  [('light_dir', 'swarp_vec3', 1, True, ()), ('out_view', 'swarp_mat4', 1, False, ())],
  False),
 ('swarp_stabilize_directional',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('n_i', 'double', 0, False, ()),
   ('f_i', 'double', 0, False, ()),
   ('light_dir', 'swarp_vec3', 1, True, ()),
   ('body_points', 'swarp_vec3', 1, True, ()),
   ('body_count', 'size_t', 0, False, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('res', 'uint32_t', 0, False, ()),
   ('opt', 'swarp_stabilize_options', 1, True, ()),
   ('out_matrix', 'swarp_mat4', 1, False, ()),
   ('out_report', 'swarp_stabilize_report', 1, False, ())],
  False),
 ('swarp_stabilize_snap_matrix',
  'swarp_status',
  [('m', 'swarp_mat4', 1, True, ()),
   ('res_s', 'double', 0, False, ()),
   ('res_t', 'double', 0, False, ()),
   ('origin', 'swarp_vec3', 1, True, ()),
   ('out', 'swarp_mat4', 1, False, ())],
  False),
 ('swarp_bias_texel_size',
  'swarp_status',
  [('map', 'swarp_bias_map', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('out_L_texel', 'double', 1, False, ()),
   ('out_L_s', 'double', 1, False, ()),
   ('out_L_t', 'double', 1, False, ())],
  False),
 ('swarp_bias_to_light',
  'swarp_status',
  [('light', 'swarp_light', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('out_L', 'swarp_vec3', 1, False, ())],
  False),
 ('swarp_bias_kozlov',
  'swarp_status',
  [('map', 'swarp_bias_map', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('a', 'double', 0, False, ()),
   ('b', 'double', 0, False, ()),
   ('out_p', 'swarp_vec3', 1, False, ()),
   ('out_amount', 'double', 1, False, ())],
  False),
 ('swarp_bias_normal_offset',
  'swarp_status',
  [('map', 'swarp_bias_map', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('normal', 'swarp_vec3', 1, True, ()),
   ('k', 'double', 0, False, ()),
   ('out_p', 'swarp_vec3', 1, False, ()),
   ('out_amount', 'double', 1, False, ())],
  False),
 ('swarp_bias_slope_scaled',
  'swarp_status',
  [('map', 'swarp_bias_map', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('normal', 'swarp_vec3', 1, True, ()),
   ('c', 'double', 0, False, ()),
   ('s', 'double', 0, False, ()),
   ('out_world_bias', 'double', 1, False, ()),
   ('out_depth_bias', 'double', 1, False, ())],
  False),
 ('swarp_bias_depth_per_world',
  'swarp_status',
  [('map', 'swarp_bias_map', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('out_depth_per_world', 'double', 1, False, ())],
  False),
 ('swarp_bias_receiver_plane',
  'swarp_status',
  [('map', 'swarp_bias_map', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('tangent_a', 'swarp_vec3', 1, True, ()),
   ('tangent_b', 'swarp_vec3', 1, True, ()),
   ('out_grad', 'double', 0, False, (2,))],
  False),
 ('swarp_cascade_view_depth',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('out_depth', 'double', 1, False, ())],
  False),
 ('swarp_cascade_select_depth',
  'swarp_status',
  [('splits', 'double', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('view_depth', 'double', 0, False, ()),
   ('out_index', 'uint32_t', 1, False, ())],
  False),
 ('swarp_cascade_select_best',
  'swarp_status',
  [('maps', 'swarp_bias_map', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('fallback_index', 'uint32_t', 0, False, ()),
   ('out_index', 'uint32_t', 1, False, ()),
   ('out_L_texel', 'double', 1, False, ())],
  False),
 ('swarp_cascade_blend',
  'swarp_status',
  [('splits', 'double', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('view_depth', 'double', 0, False, ()),
   ('band', 'double', 0, False, ()),
   ('out_index', 'uint32_t', 1, False, ()),
   ('out_weight', 'double', 1, False, ())],
  False),
 ('swarp_cascade_splits',
  'swarp_status',
  [('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('opt', 'swarp_split_options', 1, True, ()),
   ('out', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_cascade_nopt',
  'swarp_status',
  [('splits', 'double', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('pseudo_near', 'double', 0, False, ()),
   ('pseudo_far', 'double', 0, False, ()),
   ('out_n_primes', 'double', 1, False, ())],
  False),
 ('swarp_cascade_error_curve',
  'swarp_status',
  [('cfg', 'swarp_error_config', 1, True, ()),
   ('splits', 'double', 1, True, ()),
   ('n_primes', 'double', 1, True, ()),
   ('m', 'size_t', 0, False, ()),
   ('samples_per_split', 'size_t', 0, False, ()),
   ('out_z', 'double', 1, False, ()),
   ('out_mx', 'double', 1, False, ()),
   ('out_mz', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_cascade_setup',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('opts', 'swarp_cascade_options', 1, True, ()),
   ('out', 'swarp_cascade_result', 1, False, ()),
   ('out_splits', 'swarp_cascade_split', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  False),
 ('swarp_vsm_moments',
  'swarp_status',
  [('x', 'double', 0, False, ()), ('out_moments', 'double', 0, False, (2,))],
  False),
 ('swarp_vsm_chebyshev',
  'swarp_status',
  [('moments', 'double', 0, True, (2,)),
   ('t', 'double', 0, False, ()),
   ('min_variance', 'double', 0, False, ()),
   ('out_p_max', 'double', 1, False, ())],
  False),
 ('swarp_vsm_reduce_bleeding',
  'swarp_status',
  [('p', 'double', 0, False, ()),
   ('amount', 'double', 0, False, ()),
   ('out_p', 'double', 1, False, ())],
  False),
 ('swarp_lvsm_layer_interval',
  'swarp_status',
  [('splits', 'double', 1, True, ()),
   ('n_layers', 'uint32_t', 0, False, ()),
   ('i', 'uint32_t', 0, False, ()),
   ('delta', 'double', 0, False, ()),
   ('out_p', 'double', 1, False, ()),
   ('out_q', 'double', 1, False, ())],
  False),
 ('swarp_lvsm_warp',
  'swarp_status',
  [('t', 'double', 0, False, ()),
   ('p', 'double', 0, False, ()),
   ('q', 'double', 0, False, ()),
   ('out_phi', 'double', 1, False, ())],
  False),
 ('swarp_lvsm_moments',
  'swarp_status',
  [('t', 'double', 0, False, ()),
   ('p', 'double', 0, False, ()),
   ('q', 'double', 0, False, ()),
   ('out_moments', 'double', 0, False, (2,))],
  False),
 ('swarp_lvsm_layer_uniform',
  'swarp_status',
  [('t', 'double', 0, False, ()),
   ('s_0', 'double', 0, False, ()),
   ('s_N', 'double', 0, False, ()),
   ('n_layers', 'uint32_t', 0, False, ()),
   ('out_layer', 'uint32_t', 1, False, ())],
  False),
 ('swarp_lvsm_layer_find',
  'swarp_status',
  [('t', 'double', 0, False, ()),
   ('splits', 'double', 1, True, ()),
   ('n_layers', 'uint32_t', 0, False, ()),
   ('out_layer', 'uint32_t', 1, False, ())],
  False),
 ('swarp_lvsm_transition',
  'swarp_status',
  [('t', 'double', 0, False, ()),
   ('splits', 'double', 1, True, ()),
   ('n_layers', 'uint32_t', 0, False, ()),
   ('band', 'double', 0, False, ()),
   ('out_layer_lo', 'uint32_t', 1, False, ()),
   ('out_layer_hi', 'uint32_t', 1, False, ()),
   ('out_w_hi', 'double', 1, False, ())],
  False),
 ('swarp_lvsm_visibility',
  'swarp_status',
  [('layer_moments', 'double', 1, True, ()),
   ('splits', 'double', 1, True, ()),
   ('n_layers', 'uint32_t', 0, False, ()),
   ('delta', 'double', 0, False, ()),
   ('band', 'double', 0, False, ()),
   ('t', 'double', 0, False, ()),
   ('min_variance', 'double', 0, False, ()),
   ('out_visibility', 'double', 1, False, ())],
  False),
 ('swarp_lvsm_second_occluder',
  'swarp_status',
  [('mu', 'double', 0, False, ()),
   ('sigma2', 'double', 0, False, ()),
   ('out_depth', 'double', 1, False, ())],
  False),
 ('swarp_lvsm_lloyd',
  'swarp_status',
  [('mu', 'double', 1, True, ()),
   ('sigma2', 'double', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('opt', 'swarp_lloyd_options', 1, True, ()),
   ('splits_in', 'double', 1, True, ()),
   ('n_layers', 'uint32_t', 0, False, ()),
   ('splits_out', 'double', 1, False, ()),
   ('out_report', 'swarp_lloyd_report', 1, False, ())],
  False),
 ('swarp_evsm_max_exponent',
  'swarp_status',
  [('format', 'swarp_texel_format', 0, False, ()), ('out_c', 'double', 1, False, ())],
  False),
 ('swarp_evsm_moments',
  'swarp_status',
  [('x', 'double', 0, False, ()),
   ('c_pos', 'double', 0, False, ()),
   ('c_neg', 'double', 0, False, ()),
   ('out_moments', 'double', 0, False, (4,))],
  False),
 ('swarp_evsm_visibility',
  'swarp_status',
  [('moments', 'double', 0, True, (4,)),
   ('t', 'double', 0, False, ()),
   ('c_pos', 'double', 0, False, ()),
   ('c_neg', 'double', 0, False, ()),
   ('min_variance', 'double', 0, False, ()),
   ('out_visibility', 'double', 1, False, ())],
  False),
 ('swarp_msm_moments',
  'swarp_status',
  [('z', 'double', 0, False, ()), ('out_b', 'double', 0, False, (4,))],
  False),
 ('swarp_msm_bias',
  'swarp_status',
  [('b', 'double', 0, True, (4,)),
   ('alpha', 'double', 0, False, ()),
   ('out_b', 'double', 0, False, (4,))],
  False),
 ('swarp_msm_visibility',
  'swarp_status',
  [('b', 'double', 0, True, (4,)),
   ('z_f', 'double', 0, False, ()),
   ('out_visibility', 'double', 1, False, ())],
  False),
 ('swarp_pcf_poisson_disk',
  'swarp_status',
  [('seed', 'uint64_t', 0, False, ()),
   ('count', 'uint32_t', 0, False, ()),
   ('candidates', 'uint32_t', 0, False, ()),
   ('out_xy', 'double', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ()),
   ('out_min_distance', 'double', 1, False, ())],
  False),
 ('swarp_pcss_search_width',
  'swarp_status',
  [('w_light', 'double', 0, False, ()),
   ('n_light', 'double', 0, False, ()),
   ('d_r', 'double', 0, False, ()),
   ('out_w_search', 'double', 1, False, ())],
  False),
 ('swarp_pcss_penumbra',
  'swarp_status',
  [('d_r', 'double', 0, False, ()),
   ('d_b', 'double', 0, False, ()),
   ('w_light', 'double', 0, False, ()),
   ('out_w_penumbra', 'double', 1, False, ())],
  False),
 ('swarp_pcss_filter_width',
  'swarp_status',
  [('w_penumbra', 'double', 0, False, ()),
   ('n_light', 'double', 0, False, ()),
   ('d_r', 'double', 0, False, ()),
   ('out_w_filter', 'double', 1, False, ())],
  False),
 ('swarp_poly_from_aabb',
  'swarp_status',
  [('box', 'swarp_aabb', 1, True, ()), ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_poly_from_camera_range',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_poly_from_camera',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()), ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_poly_from_inverse_matrix',
  'swarp_status',
  [('inv_view_proj', 'swarp_mat4', 1, True, ()),
   ('depth_range', 'swarp_depth_range', 0, False, ()),
   ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_poly_clip',
  'swarp_status',
  [('in', 'swarp_polyhedron', 1, True, ()),
   ('plane', 'swarp_plane', 1, True, ()),
   ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_poly_clip_aabb',
  'swarp_status',
  [('in', 'swarp_polyhedron', 1, True, ()),
   ('box', 'swarp_aabb', 1, True, ()),
   ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_body_h',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('z_near', 'double', 0, False, ()),
   ('z_far', 'double', 0, False, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('out_H', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_body_from_h',
  'swarp_status',
  [('H', 'swarp_polyhedron', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('out_B', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_body_receivers',
  'swarp_status',
  [('H', 'swarp_polyhedron', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('out', 'swarp_polyhedron', 1, False, ())],
  True),
 ('swarp_setup_follow',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('scene', 'swarp_aabb', 1, True, ()),
   ('opts', 'swarp_setup_options', 1, True, ()),
   ('previous_cam', 'swarp_camera', 1, True, ()),
   ('previous', 'swarp_setup_result', 1, True, ()),
   ('out', 'swarp_setup_result', 1, False, ()),
   ('out_points', 'swarp_vec3', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  True),
 ('swarp_focus_light_view_follow',
  'swarp_status',
  [('cam', 'swarp_camera', 1, True, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('axis', 'swarp_vec3', 1, True, ()),
   ('previous_cam', 'swarp_camera', 1, True, ()),
   ('previous_view', 'swarp_mat4', 1, True, ()),
   ('out_view', 'swarp_mat4', 1, False, ())],
  True),
 ('swarp_lixel_solve5',
  'swarp_status',
  [('src', 'swarp_vec4', 0, True, (5,)),
   ('dst', 'swarp_vec4', 0, True, (5,)),
   ('out_M', 'swarp_mat4', 1, False, ()),
   ('out_conditioning', 'double', 1, False, ())],
  True),
 ('swarp_lixel_matrix',
  'swarp_status',
  [('M_v', 'swarp_mat4', 1, True, ()),
   ('g', 'uint32_t', 0, False, ()),
   ('h', 'uint32_t', 0, False, ()),
   ('light', 'swarp_light', 1, True, ()),
   ('plane', 'swarp_plane', 1, True, ()),
   ('opt', 'swarp_lixel_options', 1, True, ()),
   ('out_M_l', 'swarp_mat4', 1, False, ()),
   ('out_info', 'swarp_lixel_info', 1, False, ())],
  True),
 ('swarp_lixel_restrict',
  'swarp_status',
  [('M_l', 'swarp_mat4', 1, True, ()),
   ('C', 'swarp_vec4', 1, True, ()),
   ('n', 'size_t', 0, False, ()),
   ('opt', 'swarp_lixel_restrict_options', 1, True, ()),
   ('out_rect', 'swarp_lixel_rect', 1, False, ()),
   ('out_A_l', 'swarp_mat4', 1, False, ()),
   ('out_M_l', 'swarp_mat4', 1, False, ())],
  True),
 ('swarp_lixel_twist_for_line',
  'swarp_status',
  [('M_l', 'swarp_mat4', 1, True, ()),
   ('a', 'swarp_vec3', 1, True, ()),
   ('b', 'swarp_vec3', 1, True, ()),
   ('below', 'swarp_vec3', 1, True, ()),
   ('out_twist', 'double', 1, False, ())],
  True),
 ('swarp_lixel_factor',
  'swarp_status',
  [('M_l', 'swarp_mat4', 1, True, ()),
   ('width', 'uint32_t', 0, False, ()),
   ('height', 'uint32_t', 0, False, ()),
   ('depth_range', 'swarp_depth_range', 0, False, ()),
   ('plane_depth', 'double', 0, False, ()),
   ('out_GLV', 'swarp_mat4', 1, False, ()),
   ('out_GLP', 'swarp_mat4', 1, False, ())],
  True),
 ('swarp_lixel_split',
  'swarp_status',
  [('light', 'swarp_light', 1, True, ()),
   ('floor_plane', 'swarp_plane', 1, True, ()),
   ('wall_plane', 'swarp_plane', 1, True, ()),
   ('C_tot', 'swarp_vec4', 1, True, ()),
   ('n', 'size_t', 0, False, ()),
   ('out_floor', 'swarp_vec4', 1, False, ()),
   ('floor_capacity', 'size_t', 0, False, ()),
   ('out_floor_count', 'size_t', 1, False, ()),
   ('out_wall', 'swarp_vec4', 1, False, ()),
   ('wall_capacity', 'size_t', 0, False, ()),
   ('out_wall_count', 'size_t', 1, False, ())],
  True),
 ('swarp_lixel_select',
  'swarp_status',
  [('GLP', 'swarp_mat4', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('p', 'swarp_vec3', 1, True, ()),
   ('out_index', 'uint32_t', 1, False, ())],
  True),
 ('swarp_plan',
  'swarp_status',
  [('needs', 'swarp_scene_needs', 1, True, ()),
   ('budget', 'swarp_budget', 1, True, ()),
   ('out_plan', 'swarp_plan_result', 1, False, ())],
  True),
 ('swarp_plan_evaluate',
  'swarp_status',
  [('needs', 'swarp_scene_needs', 1, True, ()),
   ('budget', 'swarp_budget', 1, True, ()),
   ('chain', 'swarp_plan_chain', 1, True, ()),
   ('out_plan', 'swarp_plan_result', 1, False, ())],
  True),
 ('swarp_plan_cost_fit',
  'swarp_status',
  [('texels', 'double', 1, True, ()),
   ('pass_ns', 'double', 1, True, ()),
   ('count', 'size_t', 0, False, ()),
   ('out_overhead_ns', 'double', 1, False, ()),
   ('out_texel_cost_ns', 'double', 1, False, ()),
   ('out_rms_ns', 'double', 1, False, ())],
  True),
 ('swarp_plan_explain',
  'swarp_status',
  [('plan', 'swarp_plan_result', 1, True, ()),
   ('out', 'char', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  True),
 ('swarp_plan_warp_name', 'const char *', [('w', 'swarp_plan_warp', 0, False, ())], True),
 ('swarp_plan_scheme_name', 'const char *', [('s', 'swarp_plan_scheme', 0, False, ())], True),
 ('swarp_plan_filter_name', 'const char *', [('f', 'swarp_plan_filter', 0, False, ())], True),
 ('swarp_cube_faces',
  'swarp_status',
  [('ps_light', 'swarp_vec4', 1, True, ()),
   ('opt', 'swarp_cube_options', 1, True, ()),
   ('out', 'swarp_cube_face', 1, False, ()),
   ('capacity', 'size_t', 0, False, ()),
   ('out_count', 'size_t', 1, False, ())],
  True),
 ('swarp_cube_lookup',
  'swarp_status',
  [('ps_light', 'swarp_vec4', 1, True, ()),
   ('opt', 'swarp_cube_options', 1, True, ()),
   ('ps_point', 'swarp_vec3', 1, True, ()),
   ('out_face', 'uint32_t', 1, False, ()),
   ('out_texcoord', 'swarp_vec3', 1, False, ()),
   ('out_depth', 'double', 1, False, ())],
  True),
 ('swarp_mindepth_pyramid',
  'swarp_status',
  [('depth', 'float', 1, True, ()),
   ('width', 'uint32_t', 0, False, ()),
   ('height', 'uint32_t', 0, False, ()),
   ('row_stride', 'size_t', 0, False, ()),
   ('scratch', 'float', 1, False, ()),
   ('scratch_capacity', 'size_t', 0, False, ()),
   ('out_scratch_needed', 'size_t', 1, False, ()),
   ('out_min', 'double', 1, False, ())],
  True),
 ('swarp_mindepth_direct',
  'swarp_status',
  [('depth', 'float', 1, True, ()),
   ('width', 'uint32_t', 0, False, ()),
   ('height', 'uint32_t', 0, False, ()),
   ('row_stride', 'size_t', 0, False, ()),
   ('out_min', 'double', 1, False, ())],
  True),
 ('swarp_mindepth_near',
  'swarp_status',
  [('n', 'double', 0, False, ()),
   ('f', 'double', 0, False, ()),
   ('min_depth', 'double', 0, False, ()),
   ('opt', 'swarp_mindepth_options', 1, True, ()),
   ('out_near', 'double', 1, False, ())],
  True)]

DOCS = {'swarp_status_string': '@brief Readable message for a status; never NULL ("unknown status" for\n'
                        ' numbers not in the list).  The string is static.',
 'swarp_status_name': '@brief Symbolic name of a status ("SWARP_ERR_CAPACITY"); never NULL.',
 'swarp_status_is_error': '@brief 1 if status is an error (1..999 or unknown), 0 for SWARP_OK and\n'
                          ' informational results (1000..1999).',
 'swarp_version_number': '@brief SWARP_VERSION_NUMBER of the library actually linked.',
 'swarp_version_string': '@brief SWARP_VERSION_STRING of the library actually linked.',
 'swarp_mat4_to_float': '@brief Convert a matrix to float for the GPU (column-major kept).\n'
                        ' @param[in] m  matrix; @param[out] out 16 floats.\n'
                        ' @return SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (an element is '
                        'NaN/Inf\n'
                        ' or overflows float; out untouched), SWARP_OK.',
 'swarp_mat4_mul': '@brief r = a * b (column-major). r may alias a or b.',
 'swarp_mat4_invert': '@brief r = inverse(a), Gauss-Jordan with partial pivoting in double.\n'
                      ' @param[in] a matrix; @param[out] r its inverse (may alias a).\n'
                      ' @return SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (an element of a is\n'
                      ' NaN/Inf), SWARP_ERR_SINGULAR (a pivot is 0 or below 1e-300 of the largest\n'
                      ' element, the inverse overflows, or the computed condition number exceeds\n'
                      ' SWARP_MAT4_MAX_CONDITION: numerically singular; r untouched), SWARP_OK.',
 'swarp_mat4_transform': '@brief Apply a matrix to a point (w = 1) and return the homogeneous '
                         'result.',
 'swarp_camera_from_matrices': "@brief The swarp_camera of an engine's view and projection "
                               'matrices.\n'
                               '\n'
                               ' The projection must be a perspective one: w = -k z_view (k > 0 '
                               'after the\n'
                               " convention's handedness), x and y scaled (a flipped axis, like "
                               "Vulkan's y\n"
                               ' flip, leaves the frustum unchanged and is accepted) and possibly '
                               'shifted,\n'
                               ' z_ndc = -A + B/d at view depth d.  depth_range says which clip '
                               'depth the\n'
                               ' graphics API uses ([-1, 1]: SWARP_DEPTH_NEG_ONE_TO_ONE or '
                               'DEFAULT; [0, 1]:\n'
                               ' SWARP_DEPTH_ZERO_TO_ONE or SWARP_DEPTH_REVERSED_ZERO_TO_ONE): the '
                               'matrix\n'
                               ' alone cannot tell them apart (every forward matrix is valid in '
                               'both, with\n'
                               ' other planes).  Whether depth runs forward or reversed is read '
                               'from the\n'
                               ' sign of B; z_near and z_far are the depths whose NDC are the ends '
                               'of the\n'
                               ' range.  A far end that depth reaches only at infinity (A = -1 '
                               'forward,\n'
                               ' A = 0 reversed [0, 1], to SWARP_CAMERA_STRAY_NDC) is an infinite '
                               'far\n'
                               ' plane: the view is then bounded by the scene box as [RHS] §3.3.1 '
                               'bounds\n'
                               " it, z_far = the largest view depth of the box's corners (H = V ∩ "
                               'S lies\n'
                               ' in S), and the status is SWARP_INFO_CAMERA_FAR_FROM_SCENE.  An '
                               'off-centre\n'
                               ' frustum (P[0][2], P[1][2] != 0) becomes the smallest symmetric '
                               'frustum\n'
                               ' containing it: tan(fovy/2) = (1 + |c_y|) / |s_y|, aspect '
                               'likewise.\n'
                               '\n'
                               ' @param[in] view        world -> view (rigid: a rotation and a '
                               'translation)\n'
                               ' @param[in] projection  view -> clip\n'
                               ' @param[in] convention  storage and handedness of both matrices\n'
                               " @param[in] depth_range the API's clip depth ([-1, 1] or [0, 1])\n"
                               ' @param[in] scene       box S of casters and receivers; needed '
                               'only when\n'
                               '                        the far plane is infinite (may be NULL '
                               'otherwise;\n'
                               '                        checked when given)\n'
                               ' @param[out] out_cam    eye, dir, up, fovy, aspect, z_near, z_far\n'
                               ' @param[out] out_info   what was recognised (may be NULL)\n'
                               ' @return SWARP_OK, SWARP_INFO_CAMERA_FAR_FROM_SCENE; errors leave '
                               'outputs\n'
                               '         untouched: SWARP_ERR_NULL_POINTER, '
                               'SWARP_ERR_UNKNOWN_ENUM,\n'
                               "         SWARP_ERR_NON_FINITE, SWARP_ERR_SINGULAR (view's 3x3 part "
                               'or the\n'
                               "         projection's x, y or depth scale zero), "
                               'SWARP_ERR_CAMERA_MIRRORED,\n'
                               '         SWARP_ERR_CAMERA_VIEW_NOT_RIGID, '
                               'SWARP_ERR_CAMERA_NOT_PERSPECTIVE\n'
                               '         (orthographic included), SWARP_ERR_NEAR_FAR (near <= 0, '
                               'or the\n'
                               '         far plane behind the eye), '
                               'SWARP_ERR_CAMERA_FAR_UNBOUNDED, the\n'
                               "         scene box's errors (SWARP_ERR_BOX_INVERTED, ...), and\n"
                               '         SWARP_ERR_BODY_EMPTY (an infinite view whose scene box '
                               'lies\n'
                               '         wholly nearer than z_near).',
 'swarp_setup': '@brief The one call: H = V ∩ S, adjusted near/far [RHS] §3.3.1, B\n'
                " [RHS] §3.1.1, light view with light-space alignment, the technique's\n"
                " warp ([RHS] §3.2.1 / [KOZ]), focusing [RHS] (3.1) and the error model's\n"
                ' prediction [RHS] (2.3)-(2.8).  No allocation.\n'
                ' @param[in] cam, light, scene  (scene: the box S of casters and receivers)\n'
                ' @param[in] opts     NULL or zeroed for defaults\n'
                ' @param[out] out     matrices and report\n'
                ' @param[out] out_points  the points of B (NULL: not wanted); capacity\n'
                '                     SWARP_BODY_MAX_POINTS always suffices\n'
                ' @param[out] out_count   number of points of B (may be NULL)\n'
                ' @return SWARP_OK or an informational status (SWARP_INFO_WARP_UNIFORM,\n'
                '         SWARP_INFO_PSM_INVERSE, SWARP_INFO_LIGHT_PARALLEL,\n'
                "         SWARP_INFO_LIGHT_NEAR_CLIPPED (B clipped at a point light's near plane, "
                '1e-4 of\n'
                '         its farthest depth), SWARP_INFO_CASTERS_CLAMPED (S reaches more than '
                '1e10 times\n'
                '         H toward the light: casters beyond rely on depth clamping), '
                'SWARP_INFO_FLAT_EXTENT);\n'
                '         SWARP_ERR_DEGENERATE also for PSM when its map would not project along '
                'the\n'
                '         light in double, and for PSM on a frustum thinner than 1e-4 '
                '(tan(fovy/2),\n'
                '         tan(fovy/2)*aspect or (far - near)/near below it: PPS rounds like '
                'eps/t^2);\n'
                '         SWARP_ERR_BODY_EMPTY (camera looks away from the box),\n'
                '         SWARP_ERR_LIGHT_INSIDE_BODY, SWARP_ERR_BOX_INVERTED,\n'
                '         SWARP_ERR_BOX_DEGENERATE, SWARP_ERR_CAPACITY, and the argument\n'
                '         errors (NULL, NON_FINITE, FOV, NEAR_FAR, ZERO_VECTOR, DEGENERATE,\n'
                '         UNKNOWN_ENUM, RESERVED_NONZERO, OUT_OF_RANGE); SWARP_ERR_DEGENERATE\n'
                '         also when the map is finer than world coordinates resolve (B far\n'
                '         below the rounding of coordinates of size |eye|: its world-space\n'
                '         matrix cannot be evaluated in double).  Computed relative to the\n'
                '         eye (the translation is folded into light_view and matrix).',
 'swarp_setup_range': '@brief swarp_setup for an explicit view depth range [near, far] (a split\n'
                      ' frustum), used as given (no adjustment).  cam->z_near/far are ignored.\n'
                      ' @return as swarp_setup.',
 'swarp_setup_points': '@brief The light matrices for given points of B (count <=\n'
                       ' SWARP_BODY_MAX_POINTS) and the view depth range [near, far] they refer\n'
                       ' to.  receivers (may be NULL): the points of H, used for pancaking, the\n'
                       " nearest vertex e ([WS06] centre) and PSM's unit cube clipping.\n"
                       ' @return as swarp_setup; SWARP_ERR_INVALID_ARGUMENT for count 0 or above\n'
                       '         the maximum.',
 'swarp_body_points': '@brief The points of B (its vertices) for the view depths [near, far].\n'
                      ' @param[out] out capacity points; SWARP_BODY_MAX_POINTS always suffices.\n'
                      ' @param[out] out_count number of points (also on SWARP_ERR_CAPACITY).\n'
                      ' @return SWARP_OK, SWARP_ERR_BODY_EMPTY, SWARP_ERR_BOX_DEGENERATE,\n'
                      '         SWARP_ERR_CAPACITY, and the argument errors of the camera, light\n'
                      '         and box (SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                      '         SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR, SWARP_ERR_ZERO_VECTOR,\n'
                      '         SWARP_ERR_DEGENERATE (up parallel to dir), '
                      'SWARP_ERR_UNKNOWN_ENUM,\n'
                      '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE): the statuses\n'
                      '         of the experimental swarp_body_h and swarp_body_from_h.',
 'swarp_body_adjusted_range': '@brief Adjusted near/far [RHS] §3.3.1 ([ZSN07]): min and max view '
                              'depth\n'
                              ' over the points of H = V ∩ S (view frustum '
                              'cam->z_near..cam->z_far).\n'
                              ' @return SWARP_OK, SWARP_ERR_BODY_EMPTY, SWARP_ERR_BOX_DEGENERATE, '
                              'and the\n'
                              '         argument errors of the camera and box '
                              '(SWARP_ERR_NULL_POINTER,\n'
                              '         SWARP_ERR_NON_FINITE, SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR,\n'
                              '         SWARP_ERR_ZERO_VECTOR, SWARP_ERR_DEGENERATE,\n'
                              '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE): the '
                              'statuses\n'
                              '         of the experimental swarp_body_h.',
 'swarp_focus_light_view': '@brief Light view matrix (right-handed, looks down -z) with '
                           'light-space\n'
                           ' alignment.  [RHS] §3.2.1\n'
                           ' @param[in] cam    the viewer (its dir and up give the alignment)\n'
                           ' @param[in] light  the light\n'
                           ' @param[in] axis   point lights: the direction the light view looks '
                           'along\n'
                           '                   (any length > 0); NULL means light->direction '
                           '(spot)\n'
                           '                   or, for an omni light, the direction to cam->eye.\n'
                           '                   Ignored for directional lights.\n'
                           ' @param[out] out_view  light view; origin at cam->eye (directional) or '
                           'at\n'
                           '                   the light position (point light).\n'
                           ' @return SWARP_OK, SWARP_INFO_LIGHT_PARALLEL, SWARP_ERR_NULL_POINTER,\n'
                           '         SWARP_ERR_NON_FINITE, SWARP_ERR_ZERO_VECTOR, '
                           'SWARP_ERR_OVERFLOW\n'
                           '         (an origin so far out, |origin| near DBL_MAX, that its '
                           'distance\n'
                           "         along an axis of the view, the matrix's translation, exceeds\n"
                           '         DBL_MAX), ...',
 'swarp_focus_fit': '@brief The focusing matrix A_fit.  [RHS] (3.1)\n'
                    ' Maps the bounding box of the points transformed by m (with perspective\n'
                    ' division) to x, y in [-1, 1] and z in [-1, 1] (SWARP_DEPTH_NEG_ONE_TO_ONE)\n'
                    ' or [0, 1] (SWARP_DEPTH_ZERO_TO_ONE); (3.1) is the [0, 1] case.\n'
                    ' @param[in] m          transform applied to the points first (e.g. P·L)\n'
                    ' @param[in] points     world-space points (xy extent), count >= 1\n'
                    ' @param[in] z_points   points whose depth extent is used (NULL: points).\n'
                    '                       Pancaking passes the receivers (H) here.\n'
                    ' @param[out] out_A_fit the fit; a flat extent (below 1e-12 of its\n'
                    '                       coordinates: rounding noise) gets the widest other\n'
                    '                       extent as its width, or, all flat, width 1 (1e-6\n'
                    '                       of the coordinates beyond 1e6) (status).\n'
                    ' @return SWARP_OK, SWARP_INFO_FLAT_EXTENT (an extent was zero),\n'
                    '         SWARP_ERR_NULL_POINTER, SWARP_ERR_INVALID_ARGUMENT (count 0, or\n'
                    '         z_points given with z_count 0), SWARP_ERR_NON_FINITE,\n'
                    '         SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_DEGENERATE (a point maps to\n'
                    '         w <= 0).',
 'swarp_warp_lispsm': '@brief The LiSPSM warp P for the points of B in light view space.\n'
                      ' [RHS] §3.2.1, (3.2), §4.1; [WS06].\n'
                      ' P is a perspective along light-space +y with projection centre C, written\n'
                      ' in the normalised form w = 1 + (y - y_min)/n, so n = +inf is exactly the\n'
                      ' identity-like uniform map (continuous fade as γ -> 0).  Follow it with\n'
                      ' swarp_focus_fit(P·L, ...).  n (out_info->n_light) is at least 1e-6 times\n'
                      ' the largest |y| of B in light space: below that the matrix cannot carry\n'
                      ' the 1 of w next to the rounding of y (w would reach 0 on B), so a smaller\n'
                      ' parameter is raised to this bound (w >= 1 on B to ~1e-9 relative).\n'
                      ' @param[in] light_view  L from swarp_focus_light_view\n'
                      ' @param[in] cam         the viewer (eye, dir, fovy)\n'
                      ' @param[in] near, far   the view depth range the warp refers to (adjusted\n'
                      '                        or split range; 0 < near < far)\n'
                      ' @param[in] points      points of B (world), count >= 1\n'
                      ' @param[in] nearest     the nearest vertex e of H to the eye (used by\n'
                      '                        SWARP_WARP_CENTER_NEAREST_VERTEX; NULL: the point\n'
                      '                        s on the view vector at depth near, [RHS] §4.1)\n'
                      ' @param[in] opts        NULL or zeroed for defaults\n'
                      ' @param[out] out_P      the warp (applied after L)\n'
                      ' @param[out] out_info   may be NULL\n'
                      ' @return SWARP_OK, SWARP_INFO_WARP_UNIFORM (n = inf: θ -> 0 or η = -1),\n'
                      '         SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR,\n'
                      '         SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,\n'
                      '         SWARP_ERR_OUT_OF_RANGE (n_user, pseudo fractions),\n'
                      '         SWARP_ERR_DEGENERATE (a point of B at w <= 0 under light_view, or\n'
                      '         a warp that cannot be represented), SWARP_ERR_SINGULAR (a\n'
                      '         light_view that is not a rigid look-at and not invertible; a\n'
                      '         look-at is inverted exactly).',
 'swarp_warp_nopt': '@brief LiSPSM n_opt, general form.  [RHS] (3.2) (from [WS06])\n'
                    ' n_opt = d / (sqrt(z_1/z_0) - 1), evaluated as\n'
                    ' d (z_0 + sqrt(z_0 z_1)) / (z_1 - z_0) (no cancellation for z_1 ~ z_0).\n'
                    " For an overhead light (d = f - n, z_0 = n, z_1 = f) it is the n' that makes\n"
                    " Lloyd's m_z(n) = m_z(f) ([RHS] (2.4)); n_opt / d is [GMNPR]'s "
                    'λ_LiSPSM(π/2).\n'
                    ' @param[in] d   extent of the warping frustum P along light-space z (> 0),\n'
                    '                world units\n'
                    ' @param[in] z_0 eye-space depth where the error peaks near (> 0)\n'
                    ' @param[in] z_1 eye-space depth where the error peaks far (>= z_0)\n'
                    ' @param[out] out_n_opt  n_opt, world units; +INFINITY when z_1 == z_0\n'
                    ' @return SWARP_OK; SWARP_INFO_WARP_UNIFORM when z_1 == z_0 (n_opt = inf) or\n'
                    '         the value overflows (DBL_MAX); SWARP_ERR_NULL_POINTER,\n'
                    '         SWARP_ERR_NON_FINITE, SWARP_ERR_OUT_OF_RANGE (d <= 0, z_0 <= 0,\n'
                    '         z_1 < z_0).',
 'swarp_warp_nopt_pseudo': '@brief n_opt with pseudo-near and pseudo-far planes.  [RHS] (4.2)\n'
                           ' Read as n_opt = d/(z_1 - z_0) * (z_0 + sqrt((z_0 + n_p (z_1 - z_0))\n'
                           ' (z_1 - f_p (z_1 - z_0)))) (papers README); reduces to (3.2) at\n'
                           ' n_p = f_p = 0.  For an overhead light (d = z_1 - z_0) it equalises '
                           'm_z at\n'
                           ' the pseudo-near depth z_0 + n_p (z_1 - z_0) and the pseudo-far depth\n'
                           ' z_1 - f_p (z_1 - z_0).\n'
                           ' @param[in] d, z_0, z_1  as swarp_warp_nopt\n'
                           ' @param[in] n_p, f_p  in [0, 1], n_p + f_p < 1: the pseudo planes as\n'
                           '                  fractions of the depth range measured from near and '
                           'from\n'
                           '                  far (NOT eye-space distances; compare '
                           'swarp_split_pseudo)\n'
                           ' @param[out] out_n_opt  n_opt, world units\n'
                           ' @return as swarp_warp_nopt; SWARP_ERR_NON_FINITE / '
                           'SWARP_ERR_OUT_OF_RANGE\n'
                           '         for n_p, f_p.',
 'swarp_warp_eta': "@brief Lloyd's warp strength η(γ, Θ).  [RHS] (3.3)\n"
                   ' Piecewise in γ with γ_a = Θ/3, γ_b = Θ, γ_c = Θ + 0.3 (π/2 - Θ),\n'
                   ' η_b = -0.2, η_c = 0; continuous in γ.\n'
                   ' @param[in] gamma angle between light direction and view direction, radians,\n'
                   '              in [0, pi/2] (callers fold γ > pi/2 to pi - γ)\n'
                   ' @param[in] theta half the field of view Θ, radians, in (0, pi/2)\n'
                   ' @param[out] out_eta η in [-1, 0]\n'
                   ' @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                   '         SWARP_ERR_FOV (theta), SWARP_ERR_OUT_OF_RANGE (gamma).',
 'swarp_warp_wlz': '@brief Width W_lz of the view frustum along the light-space z axis for a\n'
                   ' directional light.  [RHS] (3.5)\n'
                   ' W_lz = W_e cos γ + W_s sin(Θ + γ) + [γ <= Θ] W_s (1 - cos(Θ - γ)),\n'
                   ' W_s = (f_e - n_e)/cos Θ.  Overhead light (γ = π/2): W_lz = f_e - n_e.\n'
                   ' @param[in] gamma in [0, pi/2] radians; @param[in] theta Θ in (0, pi/2)\n'
                   ' @param[in] n_e, f_e eye near/far (0 < n_e < f_e), world units\n'
                   " @param[in] W_e width of the eye's near plane (> 0), world units; in the\n"
                   '            2D side view of [RHS] Fig. 3.7 this is 2 n_e tan Θ\n'
                   ' @param[out] out_W_lz  W_lz, world units\n'
                   ' @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                   '         SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV, SWARP_ERR_OUT_OF_RANGE (gamma,\n'
                   '         W_e), SWARP_ERR_OVERFLOW.',
 'swarp_warp_nrepar': '@brief Re-parameterised LiSPSM n_repar(η).  [RHS] (3.4), second case read\n'
                      ' as η·sqrt(α) + 1 (papers README).  η = -1 gives +INFINITY with\n'
                      ' SWARP_INFO_WARP_UNIFORM; η = 0 gives W_lz/(sqrt(α) - 1) (n_opt);\n'
                      ' η = 1 gives W_lz/(α - 1) (PSM).\n'
                      ' @param[in] eta in [-1, 1]; @param[in] alpha f_e/n_e > 1\n'
                      ' @param[in] W_lz > 0, world units (swarp_warp_wlz)\n'
                      " @param[out] out_n  n_repar, world units (light space: the warp frustum's\n"
                      '             depth is W_lz)\n'
                      ' @return SWARP_OK; SWARP_INFO_WARP_UNIFORM (η = -1, or overflow: DBL_MAX);\n'
                      '         SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                      '         SWARP_ERR_OUT_OF_RANGE.',
 'swarp_gmnpr_psi': '@brief ψ(λ, θ) of [GMNPR] eq. (2).  λ > 0, θ in (0, pi/2], φ in (0, pi/2),\n'
                    ' 0 < n < f.\n'
                    ' @return SWARP_OK, the common checks, SWARP_ERR_OVERFLOW (λ or θ so small\n'
                    ' that ψ exceeds DBL_MAX).',
 'swarp_gmnpr_offset': '@brief φ(λ, θ) of [GMNPR] eq. (2) (the offset inside (z + φ)^2).  Named\n'
                       ' "offset" here to keep it apart from the half field of view φ.  Same '
                       'domain\n'
                       ' and statuses as swarp_gmnpr_psi.',
 'swarp_gmnpr_F': '@brief Aliasing function F(λ, θ, z) = ψ (z + φ(λ,θ))^2 / z.  [GMNPR] (2)\n'
                  ' @param[in] z eye-space depth in [n, f] (SWARP_ERR_OUT_OF_RANGE outside).\n'
                  ' Other parameters and statuses as swarp_gmnpr_psi.',
 'swarp_gmnpr_lambda12': '@brief λ_1(θ) and λ_2(θ) of [GMNPR] (4), for analysis (either may be <= '
                         '0\n'
                         ' off its own case).  λ_1 is read with tanφ/tanθ (papers README).\n'
                         ' θ in (0, pi/2]; both outputs required.\n'
                         ' @return SWARP_OK, the common checks, SWARP_ERR_OVERFLOW.',
 'swarp_gmnpr_lambda': '@brief λ_GMNPR(θ) of [GMNPR] (8), with λ_2* of (7) for θ < φ.\n'
                       ' θ in [0, pi/2]; finite and positive for θ > 0, continuous at θ = φ,\n'
                       ' growing without bound as θ -> 0; never Inf or NaN: θ = 0 (and θ so\n'
                       ' small that λ overflows) gives DBL_MAX with SWARP_INFO_WARP_UNIFORM.\n'
                       ' @return SWARP_OK (θ >= φ), SWARP_INFO_GMNPR_ADJUSTED (0 < θ < φ),\n'
                       ' SWARP_INFO_WARP_UNIFORM, the common checks.',
 'swarp_gmnpr_lambda_lispsm': '@brief λ_LiSPSM(θ) of [GMNPR] (9): P_n = (n + sqrt(fn))/sin θ over '
                              'the\n'
                              ' normalised depth P_f - P_n.  θ in [0, pi/2]; θ = 0 gives DBL_MAX '
                              '(finite)\n'
                              ' with SWARP_INFO_WARP_UNIFORM.  At θ = π/2 it equals n_opt/(f - '
                              'n).\n'
                              ' @return SWARP_OK, SWARP_INFO_WARP_UNIFORM, the common checks.',
 'swarp_gmnpr_lambda_glpr': '@brief λ_GLPR: the λ that makes F(λ, θ, z) linear in z (GLPR, [GMNPR] '
                            '§3,\n'
                            ' derived from (2): F linear in z <=> φ(λ, θ) = 0).  For θ > φ:\n'
                            ' λ = n (1 - tanφ/tanθ) / (f - n + (f + n) tanφ/tanθ), which is n/(f - '
                            'n)\n'
                            ' (PSM) at θ = π/2; a solution below the smallest subnormal (n '
                            'subnormal\n'
                            ' with f >> n, or θ just above φ) is written as DBL_TRUE_MIN with '
                            'SWARP_OK.\n'
                            ' For θ <= φ there is no positive solution: λ_GMNPR(θ) is\n'
                            ' written instead with SWARP_INFO_GLPR_NO_SOLUTION (θ = 0: DBL_MAX '
                            'with\n'
                            ' SWARP_INFO_WARP_UNIFORM).  Derivation in docs/parameters.md.\n'
                            ' @return SWARP_OK, SWARP_INFO_GLPR_NO_SOLUTION, '
                            'SWARP_INFO_WARP_UNIFORM,\n'
                            ' the common checks.',
 'swarp_measure_points': '@brief The measured error of matrix at caller-given receiver points and\n'
                         ' normals (e.g. world positions and normals read back from the '
                         'G-buffer).\n'
                         " Analytic, in double; the camera's near/far are not used (any planar "
                         'depth\n'
                         ' > 0 is on screen).\n'
                         ' @param[in] cam     the camera the screen belongs to (checked as in '
                         'swarp_setup\n'
                         '                    except near/far)\n'
                         ' @param[in] matrix  world -> light clip (swarp_setup_result.matrix, a '
                         "split's matrix)\n"
                         ' @param[in] res     screen and map resolutions\n'
                         ' @param[in] points, normals  count points and their normals (any length '
                         '> 0)\n'
                         ' @param[out] out    count results\n'
                         ' @return SWARP_OK; SWARP_INFO_MEASURE_SINGULAR (some point has\n'
                         '         SWARP_TEXEL_SINGULAR: its values are +inf); '
                         'SWARP_ERR_NULL_POINTER\n'
                         '         (NULL with count > 0), SWARP_ERR_NON_FINITE (a matrix element, '
                         'point\n'
                         '         or normal), SWARP_ERR_ZERO_VECTOR (a zero normal), '
                         'SWARP_ERR_RESOLUTION,\n'
                         "         and the camera's errors.  On error out is untouched.",
 'swarp_measure_max': '@brief The largest measured error of matrix over H = V ∩ S, V the view\n'
                      " frustum between planar depths z_near and z_far (a split's range, or the\n"
                      ' adjusted range of swarp_setup_result.view_near/view_far), with bisector\n'
                      ' receivers: N = normalize(e + l), e and l the unit directions from the\n'
                      ' point to the eye and to the light (the receiver for which projection\n'
                      ' aliasing vanishes, leaving the perspective aliasing of the '
                      'parameterisation).\n'
                      ' Sampling: the vertices of H, a grid x grid NDC lattice at depths '
                      'geometric\n'
                      ' in [z_near, z_far] (points outside S skipped) and a finer lattice on the\n'
                      ' near face, then from the worst vertex, the two worst local maxima of the\n'
                      ' lattice and the worst near-face point refine steps of a deterministic '
                      'compass\n'
                      ' search over (NDC x, NDC y, log z), halving the step each time it finds no\n'
                      ' larger sigma; a flat S (H a polygon) is sampled on its plane '
                      '(docs/accuracy.md\n'
                      ' states the sampling and its error).  No allocation; the result is '
                      'deterministic.\n'
                      ' @return SWARP_OK; SWARP_INFO_MEASURE_SINGULAR (max_sigma = +inf);\n'
                      '         SWARP_ERR_BODY_EMPTY (no sample of V lies in S); the errors of\n'
                      '         swarp_measure_points, SWARP_ERR_NEAR_FAR (not 0 < z_near < '
                      'z_far),\n'
                      "         the light's and box's errors as in swarp_setup, "
                      'SWARP_ERR_OUT_OF_RANGE\n'
                      '         (grid or depths 1), SWARP_ERR_RESERVED_NONZERO.  On error out is\n'
                      '         untouched.',
 'swarp_error_mx': "@brief m_x(z, n') [RHS] (2.3); n' = n gives (2.5) (PSM); n' = +INFINITY\n"
                   ' gives the closed-form uniform limit (2.7).\n'
                   ' @param[in] cfg  see swarp_error_config\n'
                   ' @param[in] z    eye-space depth in [near, far]\n'
                   " @param[in] n_prime  warp parameter n' in (0, +INFINITY] (+INFINITY =\n"
                   '                 uniform), world units\n'
                   ' @param[out] out_mx  m_x (dimensionless: screen pixels per shadow texel)\n'
                   ' @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_RESERVED_NONZERO,\n'
                   "         SWARP_ERR_NON_FINITE (NaN anywhere, n' = -inf), SWARP_ERR_FOV,\n"
                   '         SWARP_ERR_RESOLUTION, SWARP_ERR_NEAR_FAR, SWARP_ERR_OUT_OF_RANGE\n'
                   "         (z outside [near, far], n' <= 0), SWARP_ERR_OVERFLOW.",
 'swarp_error_mz': "@brief m_z(z, n') [RHS] (2.4); n' = n gives (2.6); n' = +INFINITY gives\n"
                   ' (2.8).  Parameters and statuses as swarp_error_mx (both are evaluated\n'
                   ' without intermediate under/overflow; a true value below DBL_TRUE_MIN/2,\n'
                   ' e.g. with res_ix or res_iy near DBL_TRUE_MIN, is returned as 0).',
 'swarp_error_max': '@brief Exact maxima of m_x and m_z over [near, far].  m_x ∝ 1 + a/z is\n'
                    " monotone and m_z ∝ a^2/z + 2a + z (a = n' - n) is convex in z, so the\n"
                    ' maximum is at an end point: no sampling.  Either output pointer may be\n'
                    ' NULL.  Statuses as swarp_error_mx (no z).',
 'swarp_error_split_curve': '@brief The piecewise curve of a partitioned frustum ([RHS] Fig. 3.15, '
                            '3.18):\n'
                            ' split i covers [splits[i], splits[i+1]] with its own warp '
                            'n_primes[i] and\n'
                            ' a full map of res_s x res_t (the metric evaluated with n = '
                            'splits[i],\n'
                            ' f = splits[i+1]).  splits has m + 1 strictly increasing entries, the '
                            'first\n'
                            ' > 0 (cfg->z_near/far are ignored).  Evaluates at each z[k] in\n'
                            ' [splits[0], splits[m]] (a z on a border belongs to the split that '
                            'starts\n'
                            ' there; splits[m] to the last split).  out_mx or out_mz may be NULL; '
                            'z may\n'
                            ' be NULL when count is 0.\n'
                            ' @return SWARP_OK; SWARP_ERR_NULL_POINTER, '
                            'SWARP_ERR_RESERVED_NONZERO,\n'
                            ' SWARP_ERR_NON_FINITE, SWARP_ERR_FOV, SWARP_ERR_RESOLUTION,\n'
                            ' SWARP_ERR_SPLIT_COUNT (m = 0), SWARP_ERR_NEAR_FAR (splits[0] <= 0),\n'
                            ' SWARP_ERR_NOT_INCREASING, SWARP_ERR_OUT_OF_RANGE (a z outside, an\n'
                            " n' <= 0), SWARP_ERR_OVERFLOW.  On error no output is written.",
 'swarp_error_split_max': '@brief Exact per-split and overall maxima of the piecewise curve.\n'
                          ' out_split_max_mx/mz may be NULL or hold m values; out_max_mx/mz may be '
                          'NULL.\n'
                          ' Statuses as swarp_error_split_curve.',
 'swarp_split_uniform': '@brief Uniform split scheme C_i = n + (f - n) i/m.  [RHS] (3.6)',
 'swarp_split_log': '@brief Logarithmic scheme C_i = n (f/n)^(i/m).  [RHS] (3.7)',
 'swarp_split_practical': '@brief Practical scheme C_i = (1 - λ) C_i^uni + λ C_i^log, λ in [0, 1]\n'
                          ' (0 uniform, 1 logarithmic; PSSM uses 0.5).  [RHS] (3.8)',
 'swarp_split_pseudo': '@brief Pseudo-near/far practical scheme.  [RHS] (4.1): the practical '
                       'scheme\n'
                       ' over [n_p, f_p] (EYE-SPACE distances, n <= n_p < f_p <= f) for\n'
                       ' C_1..C_{m-1}; C_0 = n and C_m = f are kept so the splits still cover the\n'
                       ' whole view.  n_p = n, f_p = f gives swarp_split_practical.',
 'swarp_atlas_layout': '@brief Atlas layout for m splits ([RHS] §3.3.5, Fig. 3.16).\n'
                       ' m = 1 uses the whole texture (grid 1, l_sc = 1); 2..4 a 2 x 2 grid,\n'
                       ' 5..9 a 3 x 3 grid, 10..16 a 4 x 4 grid.\n'
                       ' @param m          number of splits, 1..SWARP_ATLAS_MAX_SPLITS\n'
                       ' @param tile_res   texels per tile side (> 0, at most 2^24)\n'
                       ' @param depth      clip depth convention of the split matrices\n'
                       ' @param[out] out_info  layout facts (may be NULL)\n'
                       ' @param[out] out_tiles m tiles; capacity >= m\n'
                       ' @param[out] out_count m (also written with SWARP_ERR_CAPACITY)\n'
                       ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_ATLAS_SPLITS,\n'
                       '         SWARP_ERR_RESOLUTION, SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_CAPACITY.',
 'swarp_atlas_lsc': '@brief l_sc of [RHS] (3.9) for m splits: 1 (m = 1), 1/2, 1/3, 1/4.',
 'swarp_atlas_kernel_scale': '@brief PCF kernel scale of one split, [RHS] (3.9):\n'
                             ' s_i = r_l l_sc (2/(max_x - min_x), 2/(max_y - min_y)).\n'
                             " min/max are the split's focus box in light space (the box of "
                             '(3.1)), in\n'
                             " world units for a uniform map.  s_i is in the split's clip units "
                             'scaled by\n'
                             ' l_sc; s_i/2 is the extent of r_l in atlas texture coordinates, so a '
                             'kernel\n'
                             ' of s_i has the same world size r_l in every split.\n'
                             ' @param r_l  kernel size in world units (>= 0)\n'
                             ' @param m    split count (selects l_sc)\n'
                             ' @param min_x, max_x, min_y, max_y  max > min\n'
                             ' @param[out] out_s  s_i (x, y)\n'
                             ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                             '         SWARP_ERR_OUT_OF_RANGE (r_l < 0, max <= min), '
                             'SWARP_ERR_ATLAS_SPLITS,\n'
                             '         SWARP_ERR_OVERFLOW (a scale beyond DBL_MAX: width ~ '
                             'r_l/DBL_MAX).',
 'swarp_stabilize_sphere': '@brief Exact minimal enclosing sphere of the split frustum [n_i, f_i] '
                           'of a\n'
                           " camera (closed form: by the frustum's two mirror symmetries the "
                           'centre\n'
                           ' lies on the view axis at depth min(f_i, (n_i + f_i)(1 + k^2)/2), k^2 '
                           '=\n'
                           ' tan^2(fovy/2)(1 + aspect^2)), and the centroid sphere engines use.\n'
                           ' [RHS] §3.5 exact solution (ZZB09).\n'
                           ' @param cam      camera (near/far ignored; the split range is n_i, '
                           'f_i)\n'
                           ' @param n_i, f_i split range, 0 < n_i < f_i\n'
                           ' @param[out] out_center world centre; @param[out] out_radius radius\n'
                           ' (> 0: at least the smallest positive double, for a range of a few\n'
                           ' subnormals); @param[out] out_centroid_radius may be NULL (>= radius)\n'
                           ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                           '         SWARP_ERR_NEAR_FAR, SWARP_ERR_FOV, SWARP_ERR_ZERO_VECTOR,\n'
                           '         SWARP_ERR_OUT_OF_RANGE (aspect <= 0), SWARP_ERR_DEGENERATE '
                           '(up\n'
                           '         parallel to dir), SWARP_ERR_RESERVED_NONZERO, '
                           'SWARP_ERR_OVERFLOW\n'
                           "         (the sphere's radius or centre exceeds DBL_MAX, e.g. f "
                           'tan(fovy/2)\n'
                           '         aspect > DBL_MAX).',
 'swarp_stabilize_light_view': '@brief Light-space basis of a directional light used by the '
                               'stabiliser:\n'
                               ' rows of out_view are u (right), v (up), w = -light direction, '
                               'each unit;\n'
                               ' out_view maps origin-relative world coordinates to light view '
                               'space (a\n'
                               ' right-handed view looking along the light).  It depends on the '
                               'light\n'
                               ' direction only, never on the camera, so texels keep their '
                               'orientation.\n'
                               ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                               '         SWARP_ERR_ZERO_VECTOR.',
 'swarp_stabilize_directional': '@brief Stabilised (flicker-free) uniform light matrix of one '
                                'split for a\n'
                                ' directional light.  [RHS] §3.5 (ZZB09).\n'
                                " SPHERE: the map covers the split frustum's exact minimal sphere "
                                '(constant\n'
                                ' world size 2 r res/(res - 1), rounded up to 2^-20 relative so '
                                'ulp-level\n'
                                ' wobble of n_i, f_i leaves it bit-identical); LEVELS: the '
                                'light-space box of body_points\n'
                                " with each axis' size rounded up to a multiple of "
                                'level_max_size/levels;\n'
                                ' NONE: that box unquantised and unsnapped.  SPHERE and LEVELS '
                                'snap the\n'
                                ' light-space map centre to whole texels relative to opt->origin, '
                                'in double,\n'
                                " so a world point's texel coordinates change by whole numbers "
                                'only and\n'
                                ' jitter does not grow with the distance from the world origin.\n'
                                ' Depth covers the sphere / body and, toward the light, the scene '
                                'box.\n'
                                ' out_matrix maps ORIGIN-RELATIVE world coordinates (p - origin) '
                                'to clip\n'
                                ' space (large-world rendering); for origin = 0 it is the ordinary '
                                'matrix.\n'
                                ' @param cam        camera; @param n_i, f_i split range (0 < n_i < '
                                'f_i)\n'
                                ' @param light_dir  direction the light travels (non-zero)\n'
                                " @param body_points world points of the split's body B_i (LEVELS, "
                                'NONE:\n'
                                '                    count >= 1 required; SPHERE: may be NULL, 0)\n'
                                ' @param scene      scene box (may be NULL): extends depth toward '
                                'the light\n'
                                ' @param res        map resolution in texels (>= 2)\n'
                                ' @param opt        options (may be NULL = defaults)\n'
                                ' @param[out] out_matrix  the light matrix; @param[out] out_report '
                                'may be NULL\n'
                                ' @return SWARP_OK, SWARP_INFO_LEVEL_ABOVE_RANGE, '
                                'SWARP_INFO_CASTERS_CLAMPED\n'
                                "         (the scene box reaches more than 1e10 times the map's "
                                'size toward\n'
                                '         the light: the depth window stops there and casters '
                                'beyond rely on\n'
                                '         depth clamping; outranks LEVEL_ABOVE_RANGE), '
                                'SWARP_ERR_NULL_POINTER,\n'
                                '         SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR, '
                                'SWARP_ERR_FOV,\n'
                                '         SWARP_ERR_ZERO_VECTOR, SWARP_ERR_RESOLUTION, '
                                'SWARP_ERR_UNKNOWN_ENUM,\n'
                                '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE,\n'
                                '         SWARP_ERR_DEGENERATE, SWARP_ERR_OVERFLOW (finite '
                                'arguments but a\n'
                                '         matrix entry or texel size beyond DBL_MAX: coordinates '
                                'near\n'
                                '         DBL_MAX, or an extent tiny against the coordinates).',
 'swarp_stabilize_snap_matrix': "@brief Offset snapping for a caller's own uniform light matrix "
                                '([RHS]\n'
                                ' §3.5, the offset problem): shifts the clip-space translation by '
                                'less than\n'
                                ' half a texel so that `origin` lands on a texel corner.  While '
                                "the matrix's\n"
                                ' scale and orientation stay the same (e.g. quantised with '
                                'LEVELS), every\n'
                                ' world point then moves by whole texels between frames.  Done in '
                                'double on\n'
                                ' (origin-relative) coordinates.\n'
                                ' @param[in] m  world -> clip matrix of a uniform map (last row 0 '
                                '0 0 w)\n'
                                ' @param res_s, res_t  map resolution in texels (> 0)\n'
                                ' @param[in] origin  snapping origin (world)\n'
                                ' @param[out] out  the snapped matrix (may alias m)\n'
                                ' @return SWARP_OK, SWARP_ERR_STABILIZE_WARPED (m is projective: a '
                                'warped\n'
                                '         map has no uniform texel grid), SWARP_ERR_NULL_POINTER,\n'
                                '         SWARP_ERR_NON_FINITE, SWARP_ERR_RESOLUTION, '
                                'SWARP_ERR_SINGULAR\n'
                                '         (w = 0).',
 'swarp_bias_texel_size': '@brief World-space size of the texel at p ([KOZ] §14.2.3): p is mapped '
                          'to\n'
                          ' the map, shifted by one texel along s (and t) at constant depth and\n'
                          ' mapped back; the lengths of the world displacements are L_s and L_t.\n'
                          ' Exact for warped maps at any point (finite one-texel step, no '
                          'centre-of-\n'
                          ' map approximation).  L_texel = max(L_s, L_t).\n'
                          ' @param[out] out_L_texel, out_L_s, out_L_t (each may be NULL, not all)\n'
                          ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                          '         SWARP_ERR_RESOLUTION, SWARP_ERR_UNKNOWN_ENUM,\n'
                          '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_SINGULAR,\n'
                          '         SWARP_ERR_BEHIND_PROJECTION.',
 'swarp_bias_to_light': '@brief Unit vector from p toward the light (the L of [KOZ] §14.2.3):\n'
                        ' -direction for a directional light, (position - p)/|.| for a point '
                        'light.\n'
                        ' @param[in] light, p; @param[out] out_L unit vector\n'
                        ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                        '         SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,\n'
                        '         SWARP_ERR_ZERO_VECTOR (zero direction, point light at p).',
 'swarp_bias_kozlov': '@brief [KOZ] §14.2.3 world-space bias: P_biased = P + L (a + b L_texel),\n'
                      ' L the unit vector toward the light, L_texel from swarp_bias_texel_size.\n'
                      ' The point moves toward the light by exactly a + b L_texel world units.\n'
                      ' @param a  constant bias, world units; @param b  bias per texel size\n'
                      ' (dimensionless); a + b L_texel must be >= 0 (else SWARP_ERR_OUT_OF_RANGE)\n'
                      ' @param[out] out_p  biased point; @param[out] out_amount may be NULL\n'
                      ' @return as swarp_bias_texel_size, plus SWARP_ERR_OUT_OF_RANGE,\n'
                      '         SWARP_ERR_ZERO_VECTOR (point light at p).',
 'swarp_bias_normal_offset': "@brief Normal-offset bias: P' = P + N k L_texel (1 - N.L), N the "
                             'unit\n'
                             ' normal, L the unit vector to the light, N.L clamped to [0, 1] (a '
                             'back-\n'
                             ' facing normal gives SWARP_INFO_BACKFACING and the full offset k '
                             'L_texel).\n'
                             ' @param k  offset in texels (>= 0)\n'
                             ' @param[out] out_p; @param[out] out_amount offset length in world '
                             'units\n'
                             ' (may be NULL).\n'
                             ' @return SWARP_OK, SWARP_INFO_BACKFACING, SWARP_ERR_OUT_OF_RANGE (k '
                             '< 0),\n'
                             '         SWARP_ERR_ZERO_VECTOR (normal), and the errors of\n'
                             '         swarp_bias_texel_size and swarp_bias_to_light.',
 'swarp_bias_slope_scaled': '@brief Constant plus slope-scaled depth bias, given in WORLD units '
                            'and\n'
                            " converted to the map's depth units at p:\n"
                            ' world bias  = c + s L_texel tan(acos(N.L))  (tan clamped to 10; the '
                            'depth\n'
                            ' step of a receiver tilted by the angle between N and L across one '
                            'texel),\n'
                            ' depth bias  = window-depth difference between p and p moved by the '
                            'world\n'
                            ' bias toward the light (exact for warped maps; linear for uniform '
                            'maps).\n'
                            ' @param c  constant, world units (>= 0); @param s slope scale (>= 0)\n'
                            ' @param[out] out_world_bias, out_depth_bias (either may be NULL, not '
                            'both)\n'
                            ' @return as swarp_bias_normal_offset.',
 'swarp_bias_depth_per_world': '@brief Window depth per world unit toward the light at p: the '
                               'factor that\n'
                               " turns a world-space bias into the depth units of this split's map "
                               '(minus\n'
                               ' the derivative of d along L at p, so > 0 for a forward map '
                               'looking along\n'
                               ' the light and < 0 under reversed-Z, exactly the forward value '
                               'negated).\n'
                               ' Uniform maps: constant per split.\n'
                               ' @param[out] out_depth_per_world window depth units per world '
                               'unit\n'
                               ' @return SWARP_OK, SWARP_ERR_BEHIND_PROJECTION, and the argument '
                               'errors of\n'
                               '         swarp_bias_texel_size and swarp_bias_to_light.',
 'swarp_bias_receiver_plane': '@brief Receiver-plane depth bias: the depth gradient (dd/ds, dd/dt) '
                              'in\n'
                              ' window depth per TEXEL of the receiver plane at p spanned by the '
                              'world\n'
                              ' tangents tangent_a, tangent_b (e.g. dFdx/dFdy of the world '
                              'position, or\n'
                              ' two edges of the triangle).  Exact derivative of the (possibly\n'
                              ' projective) map at p (under reversed-Z the gradient of the '
                              'reversed d:\n'
                              ' the [0, 1] gradient negated).  A PCF tap offset by (ds, dt) texels '
                              'compares\n'
                              ' against d + dd/ds ds + dd/dt dt.  GLSL twin in '
                              'shaders/splits.glsl.\n'
                              ' @return as swarp_bias_texel_size; SWARP_ERR_DEGENERATE when the '
                              'plane is\n'
                              '         seen edge-on by the light (its texel-space image is a '
                              'line): the\n'
                              "         tangents' texel-space images parallel to 1e-12, or their\n"
                              '         determinant within its own rounding bound (the double '
                              'evaluation\n'
                              '         of M p and M T cannot tell the plane from an edge-on one, '
                              'e.g.\n'
                              "         a point far from the map's centre of projection).",
 'swarp_cascade_view_depth': '@brief View depth of a world point: (p - eye) . dir/|dir|, the z '
                             'that\n'
                             ' swarp_cascade_select_depth and swarp_cascade_blend take (in a '
                             'shader:\n'
                             ' -view_space_position.z).\n'
                             ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                             '         SWARP_ERR_ZERO_VECTOR, SWARP_ERR_OVERFLOW (the depth '
                             'exceeds\n'
                             '         DBL_MAX: p and eye near opposite ends of the double range).',
 'swarp_cascade_select_depth': '@brief Split selection by eye depth (PSSM, ZSXL06; [RHS] §3.3.3):\n'
                               ' the i with splits[i] <= view_depth < splits[i+1] (a depth on a '
                               'border\n'
                               ' belongs to the split that starts there; the far end to the last '
                               'split).\n'
                               ' GLSL twin in shaders/splits.glsl.\n'
                               ' @param splits   m + 1 strictly increasing eye-space distances\n'
                               ' @param m        split count (1..SWARP_SPLIT_MAX_COUNT)\n'
                               ' @param view_depth  positive distance along the view direction\n'
                               ' @param[out] out_index\n'
                               ' @return SWARP_OK; SWARP_INFO_OUTSIDE_SPLITS (depth before the '
                               'first or\n'
                               '         after the last split: the nearest split is written);\n'
                               '         SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE, '
                               'SWARP_ERR_SPLIT_COUNT,\n'
                               '         SWARP_ERR_NOT_INCREASING.',
 'swarp_cascade_select_best': '@brief Split selection by best resolution (ZZB09; [RHS] §3.3.3): '
                              'among\n'
                              ' the splits whose map covers p (w > 0, |x|, |y| <= w, depth inside '
                              'the clip\n'
                              ' range) the one with the smallest world texel size L_texel at p '
                              '(exact,\n'
                              ' swarp_bias_texel_size; ties go to the lower index).  GLSL twin in\n'
                              ' shaders/splits.glsl.\n'
                              ' @param maps  m split maps (world -> clip, resolution, depth '
                              'range)\n'
                              ' @param fallback_index  written with SWARP_INFO_OUTSIDE_SPLITS when '
                              'no map\n'
                              '                        covers p (pass the depth selection), < m\n'
                              ' @param[out] out_index; @param[out] out_L_texel (may be NULL; the '
                              'chosen\n'
                              " split's L_texel, 0 for the fallback)\n"
                              ' @return SWARP_OK, SWARP_INFO_OUTSIDE_SPLITS, '
                              'SWARP_ERR_NULL_POINTER,\n'
                              '         SWARP_ERR_NON_FINITE, SWARP_ERR_SPLIT_COUNT, '
                              'SWARP_ERR_OUT_OF_RANGE\n'
                              '         (fallback_index >= m), and the map errors of '
                              'swarp_bias_texel_size.',
 'swarp_cascade_blend': '@brief Cascade blend weight in a transition band: the last `band` '
                        'fraction\n'
                        " of each split's depth range (except the last split's) fades linearly "
                        'into\n'
                        ' the next split.  Writes the depth-selected split i and the weight w of\n'
                        ' split i; the shader mixes shadow_i w + shadow_{i+1} (1 - w).  w = 1\n'
                        ' outside the bands, w -> 0 at the border, so the result is continuous.\n'
                        ' GLSL twin in shaders/splits.glsl.\n'
                        " @param band  fraction of each split's length, in [0, 1) (0: hard "
                        'switch)\n'
                        ' @return as swarp_cascade_select_depth; SWARP_ERR_OUT_OF_RANGE for band.',
 'swarp_cascade_splits': '@brief Split distances C_0 = n < C_1 < ... < C_m = f of a scheme, on '
                         'the\n'
                         ' (adjusted, [RHS] §3.3.1) range [n, f], through the core schemes\n'
                         ' swarp_split_uniform/log/practical/pseudo.  PSEUDO converts the '
                         'fractions\n'
                         ' to distances n + n_p (f - n) and f - f_p (f - n) for (4.1).\n'
                         ' @param[out] out  m + 1 distances; capacity >= m + 1 '
                         '(SWARP_ERR_CAPACITY\n'
                         ' with the count written otherwise)\n'
                         ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                         '         SWARP_ERR_NEAR_FAR, SWARP_ERR_SPLIT_COUNT, '
                         'SWARP_ERR_OUT_OF_RANGE,\n'
                         '         SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,\n'
                         '         SWARP_ERR_CAPACITY, SWARP_ERR_INVALID_ARGUMENT '
                         '(SWARP_SCHEME_MEASURED:\n'
                         '         it needs the camera, light and scene of swarp_cascade_setup).\n'
                         '         SWARP_SCHEME_DEFAULT here is PRACTICAL with lambda 0.5.',
 'swarp_cascade_nopt': "@brief Warp parameter n' of each split for LiSPSM with an overhead light\n"
                       " in the error model's frame: n_opt of [RHS] (3.2) with d = C_{i+1} - C_i,\n"
                       ' z_0 = C_i, z_1 = C_{i+1}; the first split uses the pseudo-near fraction\n'
                       ' and the last the pseudo-far fraction of (4.2) ([RHS] §4.2), when given.\n'
                       ' @param[out] out_n_primes m values.\n'
                       ' @return SWARP_OK and the errors of swarp_warp_nopt_pseudo.',
 'swarp_cascade_error_curve': '@brief The error curve of a whole configuration ([RHS] §3.3.4, Fig. '
                              '3.15,\n'
                              " 3.18) through the core's piecewise model swarp_error_split_curve: "
                              'for\n'
                              ' each split `samples_per_split` depths from C_i (the value just '
                              'after the\n'
                              ' border: a border belongs to the split that starts there) up to the '
                              'left\n'
                              ' limit at C_{i+1} (the last sample is nextafter(C_{i+1}, 0), f '
                              'itself for\n'
                              ' the last split).  out_mx or out_mz may be NULL.\n'
                              ' @param samples_per_split >= 2\n'
                              ' @return SWARP_OK, SWARP_ERR_CAPACITY (count written), '
                              'SWARP_ERR_NULL_POINTER,\n'
                              '         SWARP_ERR_OUT_OF_RANGE, and the errors of '
                              'swarp_error_split_curve.',
 'swarp_cascade_setup': '@brief Cascaded (z-partitioned) shadow maps with any geometry technique.\n'
                        ' [RHS] §3.3-3.4, §4.1-4.2, §3.3.5, (3.9), §3.5.\n'
                        ' Adjusted near/far ([RHS] §3.3.1), split distances '
                        '(swarp_cascade_splits),\n'
                        ' per split its body B_i and light matrix through swarp_setup_range (the\n'
                        ' split frustum instead of the view frustum, [RHS] §3.4; LiSPSM with the\n'
                        ' robust projection centre of §4.1 unless setup.center says otherwise),\n'
                        ' the atlas place and kernel scale, the stabilised matrix if asked for,\n'
                        " and the error model's values per split.  With one split the result is\n"
                        " swarp_setup's, bit for bit.  opts->setup is checked as swarp_setup "
                        'checks its\n'
                        ' options, on every path (stabilised too).\n'
                        ' @param[in] cam, light, scene  as swarp_setup\n'
                        ' @param[in] opts   NULL or zeroed for defaults\n'
                        ' @param[out] out   whole-cascade facts\n'
                        ' @param[out] out_splits  one entry per split; capacity >= count\n'
                        ' @param[out] out_count   split count (also with SWARP_ERR_CAPACITY)\n'
                        ' o.warp_per_split FROM_FIRST: [RHS] §3.4 arbitrary warping, see\n'
                        ' swarp_cascade_warp.  o.setup.min_depth: [RHS] §4.3 measured min depth, '
                        'as\n'
                        ' in swarp_setup (not for stabilised cascades).  o.split.scheme DEFAULT\n'
                        ' (unstabilised) or MEASURED: the split positions are the practical\n'
                        " scheme's on the adjusted range (after min_depth) with the λ whose worst\n"
                        ' split measures least (SWARP_SCHEME_MEASURED, docs/splits.md); MEASURED\n'
                        ' with stabilisation is SWARP_ERR_INVALID_ARGUMENT (its ranges must not\n'
                        ' move with the view), DEFAULT with stabilisation is PRACTICAL λ = 0.5.\n'
                        ' @return SWARP_OK or the first informational status of a split\n'
                        '         (SWARP_INFO_SPLIT_NO_SCENE: LEVELS, a split of the constant\n'
                        '         range misses the scene box and its map covers the split '
                        'frustum);\n'
                        '         SWARP_ERR_STABILIZE_WARPED, SWARP_ERR_STABILIZE_LIGHT,\n'
                        '         SWARP_ERR_INVALID_ARGUMENT (MEASURED stabilised),\n'
                        '         SWARP_ERR_SPLIT_COUNT (count > 16), SWARP_ERR_SPLIT_EMPTY,\n'
                        '         SWARP_ERR_CAPACITY, and the errors of swarp_setup,\n'
                        '         swarp_cascade_splits and swarp_stabilize_directional (with\n'
                        "         stabilisation: SWARP_ERR_OVERFLOW when the split's sphere or\n"
                        '         matrix exceeds DBL_MAX).',
 'swarp_vsm_moments': '@brief Moments of one depth sample, [VSM] (3.1): out = (x, x^2).\n'
                      ' Filtering (averaging) these over a region gives M_1 = E[x], M_2 = E[x^2].\n'
                      ' Also the moments of a warped depth: pass the warped value.\n'
                      ' @param[in] x  depth (any finite value; VSMs usually store [0, 1])\n'
                      ' @param[out] out_moments  (M_1, M_2)\n'
                      ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE.',
 'swarp_vsm_chebyshev': "@brief Chebyshev's one-tailed bound p_max(t), [VSM] (3.2)-(3.3):\n"
                        ' mu = M_1, sigma2 = max(M_2 - M_1^2, min_variance),\n'
                        ' p_max = sigma2 / (sigma2 + (t - mu)^2) for t > mu, and 1 for t <= mu.\n'
                        ' @param[in] moments  filtered (M_1, M_2), same depth units as t\n'
                        ' @param[in] t  receiver depth\n'
                        ' @param[in] min_variance  >= 0, depth units squared: the clamp that '
                        'hides\n'
                        '            rounding of M_2 - M_1^2 (it also makes flat lit regions stay '
                        'lit)\n'
                        ' @param[out] out_p_max  in [0, 1]: an upper bound of the lit fraction\n'
                        ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                        '         SWARP_ERR_OUT_OF_RANGE (min_variance < 0).',
 'swarp_vsm_reduce_bleeding': '@brief Light-bleeding reduction by clamping ([VSM] §3.4, ref. [10] '
                              'there),\n'
                              ' a separate step after the bound: out = linstep(amount, 1, p) =\n'
                              ' clamp((p - amount) / (1 - amount), 0, 1).  It darkens every '
                              'penumbra: tails\n'
                              ' of the bound below `amount` vanish, the rest is stretched to [0, '
                              '1].\n'
                              ' @param[in] p  visibility in [0, 1]; @param[in] amount in [0, 1)\n'
                              ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                              '         SWARP_ERR_OUT_OF_RANGE.',
 'swarp_lvsm_layer_interval': '@brief Depth interval [p_i, q_i] of layer i with overlaps, [VSM] '
                              '§4.1.1:\n'
                              ' L_0 = [s_0, s_1 + delta], L_i = [s_i - delta, s_{i+1} + delta],\n'
                              ' L_{N-1} = [s_{N-1} - delta, s_N] (layers counted from 0 here).\n'
                              ' @param[in] splits  N + 1 strictly increasing split depths '
                              's_0..s_N\n'
                              ' @param[in] n_layers N in 1..SWARP_LVSM_MAX_LAYERS; @param[in] i in '
                              '0..N-1\n'
                              ' @param[in] delta  overlap, 0 <= delta < thinnest layer\n'
                              ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                              '         SWARP_ERR_FILTER_LAYER_COUNT, SWARP_ERR_OUT_OF_RANGE (i >= '
                              'N),\n'
                              '         SWARP_ERR_NOT_INCREASING, SWARP_ERR_FILTER_OVERLAP.',
 'swarp_lvsm_warp': '@brief Layer warp phi_i(t), [VSM] (4.2): 0 for t <= p, (t - p)/(q - p)\n'
                    ' inside, 1 for t >= q.\n'
                    ' @param[in] p, q  layer interval, p < q\n'
                    ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                    '         SWARP_ERR_OUT_OF_RANGE (q <= p).',
 'swarp_lvsm_moments': '@brief Moments of a warped depth for layer [p, q]: (phi, phi^2), [VSM]\n'
                       ' (4.2) then (3.1).  Same statuses as swarp_lvsm_warp.',
 'swarp_lvsm_layer_uniform': '@brief The layer holding depth t for the uniform scheme s_i = s_0 +\n'
                             ' (s_N - s_0) i / N, in closed form ([VSM] §4.1.3).  A depth on a '
                             'split\n'
                             ' belongs to the layer that starts there; t outside [s_0, s_N] gives '
                             'the\n'
                             ' first/last layer and SWARP_INFO_FILTER_DEPTH_CLAMPED.\n'
                             ' @return SWARP_OK, SWARP_INFO_FILTER_DEPTH_CLAMPED, '
                             'SWARP_ERR_NULL_POINTER,\n'
                             '         SWARP_ERR_NON_FINITE, SWARP_ERR_FILTER_LAYER_COUNT,\n'
                             '         SWARP_ERR_NOT_INCREASING (s_N <= s_0).',
 'swarp_lvsm_layer_find': '@brief The layer holding depth t for given split points (binary search '
                          'of\n'
                          ' the monotonic split sequence, [VSM] §4.1.3).  Conventions and statuses '
                          'as\n'
                          ' swarp_lvsm_layer_uniform; splits must be strictly increasing, and\n'
                          ' SWARP_ERR_OUT_OF_RANGE when the range s_N - s_0 overflows a double.',
 'swarp_lvsm_transition': '@brief Transition band between adjacent layers ([VSM] §4.1.3): for t\n'
                          ' within `band` of an inner split s_j the visibility is\n'
                          ' (1 - w) V_{j-1} + w V_j with w = (t - (s_j - band)) / (2 band) rising\n'
                          ' linearly across the band; elsewhere lo = hi = the layer of t and w = '
                          '0.\n'
                          ' band = 0 switches blending off.\n'
                          ' @param[in] band  half width, 0 <= band < half the thinnest layer\n'
                          ' @param[out] out_layer_lo, out_layer_hi, out_w_hi\n'
                          ' @return as swarp_lvsm_layer_find, plus SWARP_ERR_FILTER_BAND.',
 'swarp_lvsm_visibility': '@brief Full LVSM shading of a receiver at depth t ([VSM] §4.1): pick '
                          'the\n'
                          ' layer (and its neighbour in a transition band), warp t with the '
                          "layer's\n"
                          " overlapped interval (4.2), apply Chebyshev (3.3) to the layer's "
                          'filtered\n'
                          ' warped moments and blend.  The minimum variance is given in depth '
                          'units\n'
                          " and scaled by 1/(q - p)^2 into each layer's warped space.\n"
                          ' @param[in] layer_moments  2 N values: filtered (M_1, M_2) of layer i '
                          'at\n'
                          '            [2i], [2i+1], made with swarp_lvsm_moments and the '
                          'intervals of\n'
                          '            swarp_lvsm_layer_interval(splits, N, i, delta)\n'
                          ' @param[in] band  transition half width, 0 <= band <= delta\n'
                          ' @return SWARP_OK, SWARP_INFO_FILTER_DEPTH_CLAMPED, and the errors of '
                          'the\n'
                          '         functions above (SWARP_ERR_FILTER_BAND for band > delta).',
 'swarp_lvsm_second_occluder': '@brief Second-occluder depth estimate mu + sigma ([VSM] §4.1.2), '
                               'exact\n'
                               ' (= max(a, b)) for two depths at coverage 1/2.  sigma2 < 0 '
                               '(rounding of a\n'
                               ' filtered VSM) counts as 0.\n'
                               ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE.',
 'swarp_lvsm_lloyd': '@brief Layer placement by weighted Lloyd relaxation, [VSM] §4.1.2: 1-D\n'
                     ' weighted k-means whose K = N - 1 "means" are the inner split points\n'
                     ' s_1..s_{N-1}.  Sample j has position mu_j + sigma_j (second-occluder\n'
                     ' estimate, clamped to [s_0, s_N]) and weight clamp(sigma2_j, lo, hi); each\n'
                     ' sample joins its nearest split point (ties to the lower one), each split\n'
                     ' moves to the weighted mean of its samples.  Teleportation: a cluster with\n'
                     ' zero total weight is removed (its two adjacent layers merge) and the\n'
                     ' heaviest cluster is split in two at its weighted mean -/+ its weighted\n'
                     ' standard deviation.  s_0 and s_N stay fixed; splits are kept strictly\n'
                     ' increasing (minimum gap max(1e-9 (s_N - s_0), 2 ulp(max(|s_0|, |s_N|))),\n'
                     ' at least one ulp when the range holds too few doubles for that).\n'
                     ' Deterministic, no allocation.\n'
                     ' @param[in] mu, sigma2  count samples of an unwarped VSM (e.g. 2x2 '
                     'filtered)\n'
                     ' @param[in] opt  may be NULL (all defaults)\n'
                     ' @param[in] splits_in  N + 1 strictly increasing initial splits\n'
                     ' @param[out] splits_out N + 1 relaxed splits (may alias splits_in)\n'
                     ' @param[out] out_report may be NULL\n'
                     ' @return SWARP_OK (converged), SWARP_INFO_FILTER_NOT_CONVERGED,\n'
                     '         SWARP_INFO_FILTER_NO_WEIGHT, SWARP_ERR_NULL_POINTER,\n'
                     '         SWARP_ERR_NON_FINITE, SWARP_ERR_FILTER_NO_SAMPLES,\n'
                     '         SWARP_ERR_FILTER_LAYER_COUNT, SWARP_ERR_NOT_INCREASING,\n'
                     '         SWARP_ERR_OUT_OF_RANGE (bad clamps or tolerance),\n'
                     '         SWARP_ERR_RESERVED_NONZERO.',
 'swarp_evsm_max_exponent': '@brief Largest safe EVSM exponent c for a texel format ([VSM] §4.2): '
                            'for\n'
                            ' depths x in [0, 1] the largest moment is e^{2c}, so c = (ln F_max - '
                            'm)/2\n'
                            " where F_max = (2 - 2^-p) 2^e_max is the format's largest finite "
                            'value\n'
                            ' (computed from p mantissa bits and e_max) and m = 4 u (u = 2^-(p+1), '
                            'the\n'
                            ' unit roundoff) leaves room for a few ulps of GPU exp() error.  '
                            'Averaging\n'
                            ' (filtering) never exceeds the largest texel, so filtered moments '
                            'stay\n'
                            ' finite too.  fp32 gives c ~ 44.36, fp16 c ~ 5.545.\n'
                            ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_UNKNOWN_ENUM.',
 'swarp_evsm_moments': '@brief EVSM moments of depth x ([VSM] §4.2): positive warp e^{c_pos x}\n'
                       ' and negative warp -e^{-c_neg x}, each with its square:\n'
                       ' out = (e^{c_pos x}, e^{2 c_pos x}, -e^{-c_neg x}, e^{-2 c_neg x}).\n'
                       ' @param[in] c_pos, c_neg  in (0, 354]: e^{2c} finite in double, so every\n'
                       '                depth in [0, 1] has finite moments\n'
                       ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE (x, c_pos '
                       'or\n'
                       '         c_neg NaN/Inf), SWARP_ERR_FILTER_EXPONENT (c_pos or c_neg <= 0 '
                       'or\n'
                       '         > 354, or a moment e^{2c|x|} overflows for this x, |x| > 1).',
 'swarp_evsm_visibility': '@brief EVSM visibility ([VSM] §4.2): Chebyshev (3.3) on the positive '
                          'and\n'
                          ' on the negative warp, then the minimum of both upper bounds.  The '
                          'minimum\n'
                          ' variance is given in depth units and mapped into each warp by its\n'
                          ' derivative at t: min_variance (c e^{+-c t})^2.\n'
                          ' @param[in] moments  filtered moments laid out as swarp_evsm_moments\n'
                          ' @return as swarp_evsm_moments (SWARP_ERR_FILTER_EXPONENT also when\n'
                          '         e^{c|t|} overflows for the receiver depth t), plus\n'
                          '         SWARP_ERR_OUT_OF_RANGE (min_variance < 0) and '
                          'SWARP_ERR_NON_FINITE\n'
                          '         (a moment, t or min_variance NaN/Inf; finite moments of any\n'
                          '         magnitude and a floor min_variance (c e^{c t})^2 beyond '
                          'DBL_MAX\n'
                          '         give a bound in [0, 1]).',
 'swarp_msm_moments': '@brief The four power moments of a depth z in [0, 1]: (z, z^2, z^3, z^4)\n'
                      ' (Peters & Klein 2015, §3; the optimised quantisation transform is a GPU\n'
                      ' storage detail and not part of this).\n'
                      ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                      '         SWARP_ERR_OUT_OF_RANGE (z outside [0, 1]).',
 'swarp_msm_bias': '@brief Moment bias (Peters & Klein 2015, Algorithm 3 step 1):\n'
                   " b' = (1 - alpha) b + alpha (1/2, 1/2, 1/2, 1/2), a blend toward the\n"
                   ' moments of half the mass at 0 and half at 1, which keeps the Hankel matrix\n'
                   ' positive definite after quantisation.\n'
                   ' @param[in] alpha in [0, 1]\n'
                   ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                   '         SWARP_ERR_OUT_OF_RANGE.',
 'swarp_msm_visibility': '@brief Hamburger 4-moment shadow bound (Peters & Klein 2015, Algorithm '
                         '3):\n'
                         ' solve B c = (1, z_f, z_f^2) with the Hankel matrix B of (1, b_1..b_4)\n'
                         ' (Cholesky), take the roots z_2 <= z_3 of c_1 + c_2 z + c_3 z^2, and '
                         'the\n'
                         ' sharp lower bound G of the occluded fraction from the three-atom\n'
                         ' distribution at (z_f, z_2, z_3).  Visibility = 1 - G, clamped to [0, '
                         '1].\n'
                         ' When B is singular to rounding (one or two distinct depths, no bias) '
                         'the\n'
                         ' distribution is determined by its moments and the exact discrete '
                         'answer\n'
                         ' is returned with SWARP_INFO_FILTER_MSM_DEGENERATE.\n'
                         ' @param[in] b  filtered (and usually biased) moments\n'
                         ' @param[in] z_f  receiver depth\n'
                         ' Moments with b_2 < b_1^2 (rounding) count as a single depth at b_1; in\n'
                         ' the degenerate branch a receiver within ~1e-7 (relative) of a '
                         'recovered\n'
                         ' depth counts as at it, hence lit (recovered depths carry rounding).\n'
                         ' @return SWARP_OK, SWARP_INFO_FILTER_MSM_DEGENERATE, '
                         'SWARP_ERR_NULL_POINTER,\n'
                         '         SWARP_ERR_NON_FINITE (a NaN/Inf input, or recovered depths '
                         'that\n'
                         '         overflow; moments and z_f of any magnitude are first rescaled '
                         'by a\n'
                         '         power of two, the bound being invariant under depth scaling),\n'
                         '         SWARP_ERR_OUT_OF_RANGE\n'
                         '         (b_2 < 0 or b_4 < 0: not moments of any distribution).',
 'swarp_pcf_poisson_disk': '@brief Poisson-disk sample set in the unit disk for PCF ([RHS] §3.6,\n'
                           " after Fernando's PCSS), deterministic from a seed: Mitchell's best\n"
                           ' candidate (each new point is the candidate farthest from the points '
                           'so\n'
                           ' far) with a splitmix64 generator.  Writes count points as x, y '
                           'pairs.\n'
                           ' @param[in] seed  any value; the same seed gives the same set '
                           'everywhere\n'
                           ' @param[in] count 1..SWARP_PCF_MAX_SAMPLES points\n'
                           ' @param[in] candidates  candidates per point, 0 = 32\n'
                           ' @param[out] out_xy  2 * count doubles; capacity counts POINTS\n'
                           ' @param[out] out_count  count (or the needed count with '
                           'SWARP_ERR_CAPACITY)\n'
                           ' @param[out] out_min_distance  smallest pairwise distance (0 for count '
                           '= 1)\n'
                           ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_OUT_OF_RANGE,\n'
                           '         SWARP_ERR_CAPACITY.',
 'swarp_pcss_search_width': '@brief PCSS blocker-search width ([RHS] §3.6, Fernando 2005): by '
                            'similar\n'
                            ' triangles between the light of width w_light (measured on the '
                            "light's\n"
                            ' near plane, e.g. in shadow-map UV) and the receiver at depth d_r,\n'
                            ' w_search = w_light (d_r - n_light) / d_r.\n'
                            ' @param[in] n_light  light near-plane distance, 0 < n_light <= d_r\n'
                            ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                            '         SWARP_ERR_OUT_OF_RANGE.',
 'swarp_pcss_penumbra': '@brief PCSS penumbra width w = (d_r - d_b) w_light / d_b ([RHS] §3.6,\n'
                        ' Fernando 2005), d_b the average blocker depth, d_r the receiver depth\n'
                        ' (both distances from the light), in the units of w_light.\n'
                        ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                        '         SWARP_ERR_OUT_OF_RANGE (w_light < 0),\n'
                        '         SWARP_ERR_FILTER_BLOCKER (d_b <= 0 or d_b > d_r),\n'
                        '         SWARP_ERR_OVERFLOW (the width exceeds DBL_MAX).',
 'swarp_pcss_filter_width': "@brief PCSS filter width on the shadow map's near plane: the penumbra "
                            'at\n'
                            ' the receiver projected back, w_filter = w_penumbra n_light / d_r.\n'
                            ' @return as swarp_pcss_search_width.',
 'swarp_poly_from_aabb': '@brief The box as a polyhedron (8 vertices, 6 faces; fewer if flat).\n'
                         ' @param[in] box min <= max componentwise, finite.\n'
                         ' @param[out] out the polyhedron.\n'
                         ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                         '         SWARP_ERR_BOX_INVERTED.',
 'swarp_poly_from_camera_range': "@brief The camera's view frustum V between view depths near and "
                                 'far\n'
                                 ' (world units along cam->dir; cam->z_near/far are ignored, so a '
                                 'split\n'
                                 ' frustum [RHS] §3.3 is the same call).  A face narrower than '
                                 'the\n'
                                 " clipper's tolerance (SWARP_POLY_EPS_REL of the corners' scale; "
                                 'the near\n'
                                 ' face of a needle frustum) is held at 2 tolerances from the '
                                 'axis: a\n'
                                 ' superset of V by at most that, never a welded (thinner) one.\n'
                                 ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, '
                                 'SWARP_ERR_NON_FINITE,\n'
                                 '         SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR, '
                                 'SWARP_ERR_ZERO_VECTOR,\n'
                                 '         SWARP_ERR_DEGENERATE (up parallel to dir),\n'
                                 '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE '
                                 '(aspect <= 0, or a\n'
                                 '         corner beyond the double range: |eye| + far·|(1, tan, '
                                 'aspect·tan)|\n'
                                 '         over DBL_MAX).',
 'swarp_poly_from_camera': "@brief The camera's view frustum V between cam->z_near and cam->z_far.",
 'swarp_poly_from_inverse_matrix': '@brief The frustum whose clip cube is mapped to world space by '
                                   'an inverse\n'
                                   ' view-projection matrix (the 8 corners of the NDC cube, depth '
                                   'per\n'
                                   ' depth_range: near face at NDC -1, 0, or 1 for reversed-Z, '
                                   'whose far\n'
                                   ' face is at 0; an infinite reversed far plane maps to w = 0: '
                                   'DEGENERATE).\n'
                                   ' @return SWARP_OK, SWARP_ERR_NULL_POINTER, '
                                   'SWARP_ERR_NON_FINITE,\n'
                                   '         SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_DEGENERATE (a '
                                   'corner maps to\n'
                                   '         infinity: w <= 0).',
 'swarp_poly_clip': '@brief Keep the part of a convex polyhedron where a*x+b*y+c*z+d <= 0\n'
                    " (the plane's normal points to the side removed).  out may equal in.\n"
                    ' @return SWARP_OK (possibly empty: vertex_count 0), SWARP_ERR_NULL_POINTER,\n'
                    '         SWARP_ERR_NON_FINITE, SWARP_ERR_ZERO_VECTOR (zero normal),\n'
                    '         SWARP_ERR_CAPACITY (a maximum above would be exceeded).',
 'swarp_poly_clip_aabb': '@brief in ∩ box (six clips).  out may equal in.\n'
                         ' @return as swarp_poly_clip; SWARP_ERR_BOX_INVERTED.',
 'swarp_body_h': '@brief H = V ∩ S for the view depths [near, far].  [RHS] §3.1.1\n'
                 ' @return SWARP_OK, SWARP_ERR_BODY_EMPTY (the frustum misses the box,\n'
                 '         e.g. the camera looks away from it), SWARP_ERR_BOX_DEGENERATE,\n'
                 '         and the statuses of swarp_poly_from_camera_range.',
 'swarp_body_from_h': '@brief B from H.  [RHS] §3.1.1 (Fig. 3.2).  Directional light: H extruded\n'
                      ' against the light direction until it leaves S, then ∩ S.  Point light:\n'
                      ' conv(H ∪ {l}) ∩ S ∩ L, where L (cone_angle > 0) is the square pyramid\n'
                      ' with apex l, axis light->direction and half-angle cone_angle that\n'
                      " circumscribes the spot cone (the spot's shadow-map frustum).\n"
                      ' @return SWARP_OK, SWARP_ERR_BODY_EMPTY, SWARP_ERR_NULL_POINTER,\n'
                      '         SWARP_ERR_NON_FINITE, SWARP_ERR_ZERO_VECTOR, '
                      'SWARP_ERR_UNKNOWN_ENUM,\n'
                      '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE (cone angle, or '
                      'B\n'
                      '         swept through a box reaching beyond DBL_MAX/4 leaves the double '
                      'range).',
 'swarp_body_receivers': '@brief The receivers a light can reach: H ∩ L for a spot light (L the\n'
                         ' square pyramid around its cone, as in swarp_body_from_h), H itself for\n'
                         ' directional and omni lights.  Pass its vertices as the receivers of\n'
                         ' swarp_setup_points (pancaking, PSM unit cube clipping).  out may equal '
                         'H.\n'
                         ' @return SWARP_OK, SWARP_ERR_BODY_EMPTY (the cone misses H), and the\n'
                         "         statuses of swarp_body_from_h's argument checks.",
 'swarp_setup_follow': "@brief swarp_setup with a light frame that follows the previous frame's\n"
                       ' continuously (no flips anywhere on the sphere of light directions).\n'
                       ' @param[in] cam, light, scene, opts  as swarp_setup\n'
                       ' @param[in] previous_cam  the camera of the previous frame (its view\n'
                       '                    direction lets the frame realign as the camera '
                       'turns);\n'
                       "                    NULL: the same as cam (only the light's motion "
                       'counts)\n'
                       " @param[in] previous  the previous frame's result of swarp_setup or\n"
                       '                    swarp_setup_follow with the SAME technique and light\n'
                       "                    type; NULL: exactly swarp_setup's result (bit for "
                       'bit).\n'
                       "                    Read: light_view's rotation rows; PSM also "
                       'light_proj,\n'
                       "                    view_near, view_far and n_eye (with previous_cam's, "
                       'or\n'
                       "                    cam's, fovy and aspect) to recover its light camera\n"
                       ' @param[out] out, out_points, out_count  as swarp_setup\n'
                       ' @return as swarp_setup, plus SWARP_INFO_FOLLOW_LAG (the frame is still\n'
                       '         turning toward the aligned one); SWARP_ERR_NON_FINITE (NaN/Inf '
                       'in\n'
                       '         the rows of previous that are read), SWARP_ERR_ZERO_VECTOR (a '
                       'zero\n'
                       '         row), SWARP_ERR_FOLLOW_FRAME (rows not orthonormal within 1e-6 '
                       'or\n'
                       '         left-handed, or a PSM result whose ranges are invalid).  Outputs '
                       'untouched on\n'
                       '         error.  [RHS] §3.2.1, [KOZ] §14.2.2',
 'swarp_focus_light_view_follow': '@brief swarp_focus_light_view whose up vector follows a '
                                  'previous light\n'
                                  ' view continuously (the rule of swarp_setup_follow: the '
                                  'previous up turned\n'
                                  ' toward ±v̂ by at most SWARP_FOLLOW_KAPPA times the angle the '
                                  'light axis\n'
                                  ' and the view direction turned).  [RHS] §3.2.1\n'
                                  ' @param[in] cam, light, axis  as swarp_focus_light_view\n'
                                  " @param[in] previous_cam   the previous frame's camera (NULL: "
                                  'cam)\n'
                                  ' @param[in] previous_view  the previous light view (its '
                                  'rotation rows are\n'
                                  '                           read); NULL: exactly '
                                  'swarp_focus_light_view\n'
                                  ' @param[out] out_view      the light view\n'
                                  ' @return as swarp_focus_light_view (SWARP_INFO_LIGHT_PARALLEL '
                                  'only with\n'
                                  '         previous_view NULL), SWARP_INFO_FOLLOW_LAG, '
                                  'SWARP_ERR_ZERO_VECTOR,\n'
                                  '         SWARP_ERR_NON_FINITE, SWARP_ERR_FOLLOW_FRAME (rows not '
                                  'a rigid\n'
                                  '         right-handed frame within 1e-6), SWARP_ERR_OVERFLOW '
                                  '(as\n'
                                  '         swarp_focus_light_view: a translation beyond DBL_MAX).',
 'swarp_lixel_solve5': '@brief The 4x4 projective matrix fixed (up to scale) by five point\n'
                       ' correspondences M src[i] ~ dst[i] (no four coplanar).  [LIXEL] §2, via\n'
                       ' [Fau93]: both sets are mapped to the projective basis, in double, after '
                       'a\n'
                       ' similarity normalisation of each set, with partial pivoting.\n'
                       ' @param[in] src five homogeneous points (w = 0 allowed: points at '
                       'infinity)\n'
                       ' @param[in] dst five homogeneous image points\n'
                       ' @param[out] out_M the matrix, scaled so its largest |element| is 1\n'
                       ' @param[out] out_conditioning may be NULL: the smallest |det| of four of\n'
                       '        the five normalised points of either set, in [0, 1]; 0 = coplanar\n'
                       ' @return SWARP_OK; SWARP_INFO_LIXEL_ILL_CONDITIONED (conditioning < 1e-6\n'
                       '         or a constraint residual above 1e-9: the matrix is written);\n'
                       '         SWARP_ERR_LIXEL_COPLANAR (conditioning < 1e-13, or the finite\n'
                       '         points of a set within 64 eps |c| of their median centre c in\n'
                       '         median: two of them coincide to rounding), SWARP_ERR_NON_FINITE,\n'
                       '         SWARP_ERR_NULL_POINTER.',
 'swarp_lixel_matrix': '@brief Plane-stabilised light matrix M_l.  [LIXEL] (1), (2), (7)-(10)\n'
                       ' Rays through the corner pixels (2) hit P in p^1..p^4 (homogeneous, so a\n'
                       ' quad across infinity, Fig. 5, is fine); a corner in front of the eye '
                       '(p^4\n'
                       ' when possible) is raised toward the light (Fig. 2); the light maps to\n'
                       ' [0,0,1,0] (1), p^1..p^3 to their own pixel with z = 1, the raised point\n'
                       ' with z = -1 ((7)-(10), (9) read as [(g-1)q, (h-1)q, 1q, q]).  The sign\n'
                       ' of the matrix is chosen so that q > 0 exactly on the part of P in front\n'
                       ' of the viewer (on P, q_l = c q_v with c > 0).\n'
                       ' @param[in] M_v viewer view-projection (world -> clip, OpenGL style)\n'
                       ' @param g, h viewer image width and height in pixels (>= 2)\n'
                       ' @param[in] light point (position) or directional (direction of travel)\n'
                       ' @param[in] plane the plane of interest P (normal non-zero)\n'
                       ' @param[in] opt may be NULL (defaults)\n'
                       ' @param[out] out_M_l world -> light image (lixels), largest |element| 1\n'
                       ' @param[out] out_info may be NULL\n'
                       ' @return SWARP_OK; informational SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY,\n'
                       ' _PLANE_PARALLEL_VIEW, _LIGHT_BEHIND_PLANE, _ILL_CONDITIONED (most\n'
                       ' important first: ill-conditioned, parallel, across infinity, behind);\n'
                       ' errors SWARP_ERR_LIXEL_PLANE_THROUGH_EYE, _LIGHT_ON_PLANE,\n'
                       ' _LIGHT_PARALLEL_PLANE, _PLANE_NOT_VISIBLE, SWARP_ERR_LIXEL_COPLANAR (the\n'
                       " five constraint points of (1), (7)-(10) nearly coplanar: the solver's\n"
                       ' conditioning < 1e-13, reached only in near-degenerate configurations),\n'
                       ' SWARP_ERR_SINGULAR (M_v), SWARP_ERR_RESOLUTION, SWARP_ERR_ZERO_VECTOR, '
                       'SWARP_ERR_OUT_OF_RANGE\n'
                       ' (raise), SWARP_ERR_UNKNOWN_ENUM, SWARP_ERR_RESERVED_NONZERO,\n'
                       ' SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER.',
 'swarp_lixel_restrict': '@brief Light-image restriction (Fig. 6): the smallest axis-aligned\n'
                         ' rectangle with integer corners enclosing the light image of the convex '
                         'set\n'
                         ' of rays C, and M_l := A_l M_l where A_l = translate(-x0, -y0) ·\n'
                         ' scale(scale_x, scale_y) · rotate(twist) (rows x, y only).  [LIXEL] §2\n'
                         ' "Less of the plane".\n'
                         ' @param[in] M_l from swarp_lixel_matrix\n'
                         ' @param[in] C vertices of the convex polygon of rays: world points (w = '
                         '1,\n'
                         '        any light) or directions from a point light (w = 0); any w != 0 '
                         'is\n'
                         '        divided out\n'
                         ' @param n number of vertices (>= 1)\n'
                         ' @param[in] opt may be NULL\n'
                         ' @param[out] out_rect the rectangle in the twisted/scaled image BEFORE\n'
                         '        the translation (so x0, y0 tell where it was)\n'
                         ' @param[out] out_A_l the 2D affine map as a 4x4 (may be NULL)\n'
                         ' @param[out] out_M_l A_l · M_l: lixel (0, 0) is the lower-left of the '
                         'rectangle\n'
                         ' @return SWARP_OK; SWARP_ERR_LIXEL_RAY_OUTSIDE (a vertex has q <= 0,\n'
                         ' without view clipping), SWARP_ERR_LIXEL_EMPTY (nothing of C in view),\n'
                         ' SWARP_ERR_LIXEL_RECT_TOO_LARGE, SWARP_ERR_OUT_OF_RANGE (scale < 0, or\n'
                         ' an entry of A_l M_l would exceed DBL_MAX, e.g. scale near DBL_MAX),\n'
                         ' SWARP_ERR_INVALID_ARGUMENT (n = 0), SWARP_ERR_RESERVED_NONZERO,\n'
                         ' SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER.',
 'swarp_lixel_twist_for_line': '@brief Twist angle that makes the light image of the world line '
                               'through a\n'
                               ' and b horizontal, with the light image of `below` (a point on the '
                               'side\n'
                               ' that should stay inside, e.g. on the floor in front of the wall) '
                               'at\n'
                               ' smaller y.  [LIXEL] §3 (twist in A_floor).\n'
                               ' @param[in] M_l from swarp_lixel_matrix (before restriction)\n'
                               ' @param[in] a, b two world points of the line (q > 0 in M_l)\n'
                               ' @param[in] below a world point on the side that should map below '
                               'the line\n'
                               ' @param[out] out_twist radians, for '
                               'swarp_lixel_restrict_options.twist\n'
                               ' @return SWARP_OK; SWARP_ERR_LIXEL_TWIST_LINE (the line images to '
                               'a point,\n'
                               ' `below` images onto the line -- within 1e-12 of the image '
                               'coordinates,\n'
                               ' where its side is rounding noise -- or a point has q <= 0),\n'
                               ' SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER.',
 'swarp_lixel_factor': '@brief Factor M_l (after restriction, lixels 0..width-1 x 0..height-1)\n'
                       " into M_l' = GLV · GLP for standard clipping.  [LIXEL] §2 ('M_l = GLV "
                       "GLP')\n"
                       " GLP is world -> clip (use it as the light's view-projection; w > 0 on\n"
                       ' the wanted side); GLV is the viewport NDC -> lixels\n'
                       ' (x = (x_ndc + 1) width/2 - 1/2) with depth passed through.  The depth\n'
                       " row is remapped affinely (allowed by the paper's footnote): the raised\n"
                       ' point p-hat lands on the near plane (NDC -1, 0, or 1 under reversed-Z)\n'
                       ' and P at the fraction plane_depth of the depth range from the near\n'
                       ' plane (default 0.5; NDC 1 - plane_depth reversed), so geometry slightly\n'
                       " behind P is not clipped.  (x, y, q) of M_l' equal those of M_l.\n"
                       ' @param[in] M_l restricted light matrix (lixels; depth as built by\n'
                       '        swarp_lixel_matrix: p-hat at z = -1, P at z = +1)\n'
                       ' @param width, height the map size in lixels (swarp_lixel_rect)\n'
                       ' @param depth_range clip depth convention (DEFAULT = [-1, 1])\n'
                       ' @param plane_depth in [0, 1): 0 = default 0.5\n'
                       ' @param[out] out_GLV viewport, NDC -> lixels\n'
                       ' @param[out] out_GLP world -> clip\n'
                       ' @return SWARP_OK; SWARP_ERR_RESOLUTION, SWARP_ERR_OUT_OF_RANGE\n'
                       ' (plane_depth outside [0, 1), or an entry of GLP would exceed DBL_MAX:\n'
                       ' possible once max|M_l| > DBL_MAX/3), SWARP_ERR_UNKNOWN_ENUM,\n'
                       ' SWARP_ERR_NON_FINITE (M_l or plane_depth not finite),\n'
                       ' SWARP_ERR_NULL_POINTER.',
 'swarp_lixel_split': '@brief Split the convex polygon of rays C_tot by the floor/wall line\n'
                      ' ([LIXEL] §3): C_floor holds the rays that hit the floor in front of the\n'
                      ' wall (on the side its normal points to), C_wall the others (they hit the\n'
                      ' wall above the line when the light is in the room).  The cut is the plane\n'
                      ' through the light and the floor/wall line.  Vertices as in\n'
                      ' swarp_lixel_restrict (all points or all directions; directions need a\n'
                      ' point light).\n'
                      ' @param[in] light the light (point or directional)\n'
                      ' @param[in] floor_plane, wall_plane the two planes of interest (normal of\n'
                      '        the wall pointing into the room)\n'
                      ' @param[in] C_tot n >= 3 vertices of the convex polygon of rays, in order\n'
                      ' @param[out] out_floor, out_wall capacity each; counts written (either\n'
                      '        may be 0 when C_tot lies on one side)\n'
                      ' @return SWARP_OK; SWARP_ERR_CAPACITY (needed counts written),\n'
                      ' SWARP_ERR_DEGENERATE (floor parallel to wall, or light on the line),\n'
                      ' SWARP_ERR_ZERO_VECTOR, SWARP_ERR_INVALID_ARGUMENT, SWARP_ERR_NON_FINITE,\n'
                      ' SWARP_ERR_NULL_POINTER.',
 'swarp_lixel_select': '@brief Which shadow map to use for a world point ([LIXEL] §3, the CPU\n'
                       ' reference of the shader in docs/lixel.md): the first i whose clip matrix\n'
                       ' GLP[i] puts p inside (w > 0, |x| <= w, |y| <= w), else count (the\n'
                       ' conventional fallback map).\n'
                       ' @param[in] GLP count clip matrices (swarp_lixel_factor), in the order '
                       'the\n'
                       '        shader tries them (e.g. floor, wall); may be NULL when count = 0\n'
                       ' @param count number of plane maps\n'
                       ' @param[in] p world point\n'
                       ' @param[out] out_index 0 .. count-1, or count for the fallback map\n'
                       ' @return SWARP_OK; SWARP_ERR_NON_FINITE, SWARP_ERR_NULL_POINTER.',
 'swarp_plan': '@brief Plan the cheapest chain that meets the budget.\n'
               ' Candidates: uniform, LiSPSM (n_opt, n_repar, λ_GMNPR, pseudo-near/far),\n'
               ' PSM (+ inverse projection when the light is behind) as one map; PSSM with\n'
               ' K = 2..16 splits (practical λ = 0.5 or logarithmic) unwarped, with n_opt\n'
               ' or with n_repar per split.  A moving camera admits only unwarped chains\n'
               " (stabilised, [RHS] §3.5).  The model's rule: the fewest passes whose\n"
               ' predicted max(m_x, m_z) <= the budget (and cost <= time budget); ties go\n'
               ' to the lower error, then to the earlier (simpler) candidate.  With\n'
               ' needs->plan_by = SWARP_PLAN_BY_MEASURED (the default) that rule proposes a\n'
               ' chain, its matrices are built (as swarp_plan_evaluate) and measured; while\n'
               ' the measured max(m_s, m_t) exceeds budget->max_error the rule is applied\n'
               ' again against max_error × model/measured of the last chain (at least 3 %\n'
               ' tighter each round, at most 8 rounds): meets_budget then means the\n'
               " MEASURED error meets it, and the built_* fields hold the chosen chain's\n"
               ' matrices.  Chains that cannot be built (point light) fall back to the\n'
               ' model.  SWARP_PLAN_BY_MODEL: the rule alone.  If none meets the budget:\n'
               ' the most accurate chain found (measured, or by the model within the pass\n'
               ' limit) and SWARP_INFO_PLAN_BUDGET_UNMET.  Then the filter (soft shadows only), '
               'depth\n'
               ' clamping and lixel maps for declared lixel-friendly planes (passes left).\n'
               ' Error model [RHS] (2.3)-(2.8), generalised to any γ (docs/planning.md).\n'
               ' @param[in]  needs   scene; NULL or zeroed fields mean the defaults\n'
               ' @param[in]  budget  budget; NULL or zeroed fields mean the defaults\n'
               ' @param[out] out_plan the plan (untouched on error)\n'
               ' @return SWARP_OK; SWARP_INFO_PLAN_BUDGET_UNMET; SWARP_INFO_PLAN_POINT_LIGHT;\n'
               '         SWARP_ERR_NULL_POINTER (out_plan), SWARP_ERR_NON_FINITE,\n'
               '         SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_UNKNOWN_ENUM,\n'
               '         SWARP_ERR_ZERO_VECTOR, SWARP_ERR_DEGENERATE (up parallel to dir),\n'
               '         SWARP_ERR_FOV, SWARP_ERR_NEAR_FAR, SWARP_ERR_OUT_OF_RANGE (aspect,\n'
               '         cone, soft_width, max_error, time, costs (negative or above\n'
               '         SWARP_PLAN_MAX_COST_NS), max_passes > 32), SWARP_ERR_BOX_INVERTED, '
               'SWARP_ERR_BOX_DEGENERATE\n'
               '         (as swarp_setup; the all-zero box means unbounded),\n'
               '         SWARP_ERR_RESOLUTION (screen or map above 65536),\n'
               '         SWARP_ERR_PLAN_TOO_MANY_PLANES, SWARP_ERR_PLAN_EMPTY_VIEW.',
 'swarp_plan_evaluate': '@brief Predict one given chain (no choice of warp or splits): the same\n'
                        ' error and cost model and the same filter / lixel / clamp decisions as\n'
                        ' swarp_plan(), for reports and for callers that force a technique.\n'
                        ' meets_budget says whether it meets the budget (by the model); the pass\n'
                        ' limit is not enforced on the chain (lixel maps still use only passes '
                        'left).\n'
                        " Then the chain's matrices, built as an engine builds them\n"
                        " (swarp_cascade_setup with the needs' camera, light and box (an all-zero\n"
                        " box: the view frustum's bounding box), technique and parameter of the\n"
                        ' warp, split count, scheme and λ, 64-level stabilisation, pancaking for\n'
                        " depth_clamp, the plan's map_resolution and the screen; docs/planning.md\n"
                        ' §9): built_splits, built_n_eye, split_measured and measured are exactly\n'
                        " that cascade's.  Cost: one swarp_cascade_setup with its measurement\n"
                        ' (about 60 µs for one map, 30 µs more per split).\n'
                        ' @return as swarp_plan (never SWARP_INFO_PLAN_BUDGET_UNMET), plus\n'
                        '         SWARP_ERR_SPLIT_COUNT (K > 16, or K > 1 with SCHEME_NONE, or K = '
                        '1\n'
                        '         with a split scheme) and SWARP_ERR_UNKNOWN_ENUM for the chain\n'
                        '         (also its matrices).  A\n'
                        '         chain no engine can build (a stabilised warp or point light) is\n'
                        '         still predicted: built = 0 and built_status says why.',
 'swarp_plan_cost_fit': "@brief Least-squares fit of the planner's cost model to measured shadow\n"
                        ' passes: pass_ns[i] ≈ overhead + texels[i] x per_texel over the count\n'
                        " pairs (texels of the pass's map, its measured time in ns), both terms\n"
                        ' >= 0 (a negative least-squares term is set to 0 and the other refitted:\n'
                        ' a line through the origin, or the mean time).  Put the results into\n'
                        ' swarp_budget.pass_overhead_ns and texel_cost_ns.  No allocation.\n'
                        ' @param[in]  texels  texels of each measured pass (> 0, finite), count '
                        'entries\n'
                        ' @param[in]  pass_ns measured time of each pass, ns (>= 0, finite)\n'
                        ' @param[in]  count   pairs, >= 2\n'
                        ' @param[out] out_overhead_ns, out_texel_cost_ns the fitted terms\n'
                        ' @param[out] out_rms_ns  root-mean-square residual of the fit, ns (may be '
                        'NULL)\n'
                        ' @return SWARP_OK; SWARP_ERR_NULL_POINTER; SWARP_ERR_NON_FINITE;\n'
                        '         SWARP_ERR_OUT_OF_RANGE (count < 2, texels <= 0, pass_ns < 0, or '
                        'a\n'
                        '         fitted term above the limits swarp_plan accepts);\n'
                        '         SWARP_ERR_DEGENERATE (all texel counts equal: the two terms '
                        'cannot\n'
                        '         be told apart).  Outputs untouched on error.',
 'swarp_plan_explain': '@brief Readable text of a plan: the chain, the predicted error and cost,\n'
                       ' and one line per reason flag and per left-out plane.  '
                       'Locale-independent.\n'
                       ' @param[out] out       text, NUL-terminated; may be NULL when capacity is '
                       '0\n'
                       ' @param[in]  capacity  bytes available in out\n'
                       ' @param[out] out_count bytes needed including the NUL (always written)\n'
                       ' @return SWARP_OK; SWARP_ERR_CAPACITY (out untouched, *out_count = '
                       'needed);\n'
                       '         SWARP_ERR_NULL_POINTER (plan or out_count, or out with capacity > '
                       '0);\n'
                       "         SWARP_ERR_UNKNOWN_ENUM (plan's enums).",
 'swarp_plan_warp_name': '@brief Short name of a warp kind ("uniform", "lispsm-nopt", "psm", '
                         '...).\n'
                         ' @param w the warp kind\n'
                         ' @return a static string, never NULL ("?" for values not in the enum).',
 'swarp_plan_scheme_name': '@brief Short name of a split scheme ("none", "pssm-practical", '
                           '"pssm-log").\n'
                           ' @param s the scheme\n'
                           ' @return a static string, never NULL ("?" for values not in the enum).',
 'swarp_plan_filter_name': '@brief Short name of a filter kind ("none", "pcf", "vsm", "msm", '
                           '"evsm", "lvsm").\n'
                           ' @param f the filter kind\n'
                           ' @return a static string, never NULL ("?" for values not in the enum).',
 'swarp_cube_faces': '@brief The cube-map faces of [KOZ] §14.2.2 for a light in post-projective\n'
                     ' space, with their view, projection and view-projection matrices.\n'
                     ' @param[in] ps_light light in post-projective space, homogeneous (see '
                     'above)\n'
                     ' @param[in] opt      options, or NULL for the defaults\n'
                     ' @param[out] out     capacity faces (SWARP_CUBE_MAX_FACES always suffices),\n'
                     '                     in SWARP_CUBE_FACE_* order\n'
                     ' @param[out] out_count number of faces (3..6 unless P lies on a face plane)\n'
                     ' @return SWARP_OK; SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE,\n'
                     ' SWARP_ERR_RESERVED_NONZERO, SWARP_ERR_OUT_OF_RANGE (z1 outside (0, 1)),\n'
                     ' SWARP_ERR_UNKNOWN_ENUM (depth_range), SWARP_ERR_CUBE_LIGHT_AT_INFINITY\n'
                     ' (w = 0 or P too far for finite matrices), SWARP_ERR_DEGENERATE (no\n'
                     ' back-facing face: cannot happen for finite P), SWARP_ERR_CAPACITY\n'
                     ' (*out_count = faces needed, out untouched).',
 'swarp_cube_lookup': '@brief Texture coordinate and depth of a point for the cube map: the\n'
                      ' computation of [KOZ] Listing 14-1.  With u = V - P,\n'
                      ' a = max_i (u . N_i)/d_i over the back-facing faces, the point is looked '
                      'up\n'
                      ' in face argmax at the cube point S = P + u/a ("vertex position minus '
                      'light\n'
                      ' position", re-centred on the unit cube) and compared against the\n'
                      ' projective transform of a with Z_n = Z_1, Z_f = 1 (or -Z_1, Z_1), i.e. '
                      'the\n'
                      " NDC depth the face's view_proj gives V.\n"
                      ' @param[in] ps_light, opt  as swarp_cube_faces\n'
                      ' @param[in] ps_point V in post-projective space\n'
                      ' @param[out] out_face SWARP_CUBE_FACE_* (may be NULL)\n'
                      " @param[out] out_texcoord S, a point on the unit cube's surface (may be "
                      'NULL)\n'
                      ' @param[out] out_depth NDC depth in opt->depth_range (may be NULL)\n'
                      ' @return SWARP_OK; SWARP_INFO_CUBE_NEAR_CLIPPED (a < Z_1: inside the near\n'
                      ' cube, the depth is outside the range); the errors of swarp_cube_faces\n'
                      ' (but not CAPACITY); SWARP_ERR_CUBE_POINT_UNCOVERED (a <= 0);\n'
                      ' SWARP_ERR_OVERFLOW (S or the depth not representable: a light within\n'
                      ' ~1e-300 of w = 0 or a point near DBL_MAX).',
 'swarp_mindepth_pyramid': '@brief Minimum of a linear depth buffer by the 2x2 min pyramid of '
                           '[RHS]\n'
                           ' Listing A.2, on the CPU.  Each level halves the size rounding UP and '
                           'an\n'
                           ' odd last row/column takes the min of the texels that exist (Listing '
                           "A.2's\n"
                           ' wrap addressing with rounded-down sizes would skip them).\n'
                           ' @param[in] depth  height rows of width floats, row r at depth + '
                           'r*row_stride\n'
                           ' @param[in] width, height  >= 1; @param[in] row_stride >= width '
                           '(floats)\n'
                           ' @param[out] scratch  SWARP_MINDEPTH_SCRATCH(width, height) floats '
                           '(may be\n'
                           '             NULL when that is 0, i.e. never; 1x1 needs 1)\n'
                           ' @param[in] scratch_capacity  floats in scratch\n'
                           ' @param[out] out_scratch_needed  written with the need (always)\n'
                           ' @param[out] out_min  the minimum (+INFINITY if every value is '
                           '+INFINITY)\n'
                           ' @return SWARP_OK; SWARP_INFO_MINDEPTH_EMPTY (every value +INFINITY);\n'
                           ' SWARP_ERR_NULL_POINTER, SWARP_ERR_INVALID_ARGUMENT (width or height '
                           '0,\n'
                           ' row_stride < width), SWARP_ERR_NON_FINITE (a NaN or -INFINITY),\n'
                           ' SWARP_ERR_OUT_OF_RANGE (a negative depth), SWARP_ERR_CAPACITY.',
 'swarp_mindepth_direct': '@brief The same minimum by a direct scan (the reference the pyramid is\n'
                          ' tested against, and the cheaper choice on the CPU).  Statuses as\n'
                          ' swarp_mindepth_pyramid without the scratch ones.',
 'swarp_mindepth_near': '@brief The adjusted near plane of [RHS] §4.3: the measured minimum depth\n'
                        ' less a relative margin, never below the original near and always < far,\n'
                        ' so nothing the depth buffer saw is clipped.\n'
                        " @param[in] n, f  the camera's near and far (0 < n < f)\n"
                        ' @param[in] min_depth  measured minimum linear depth (>= 0 or +INFINITY)\n'
                        ' @param[in] opt  or NULL; @param[out] out_near  the adjusted near plane\n'
                        ' @return SWARP_OK; SWARP_INFO_MINDEPTH_EMPTY (min_depth >= f: near '
                        'kept);\n'
                        ' SWARP_ERR_NULL_POINTER, SWARP_ERR_NON_FINITE, SWARP_ERR_NEAR_FAR,\n'
                        ' SWARP_ERR_OUT_OF_RANGE (min_depth < 0, margin outside [0, 1)),\n'
                        ' SWARP_ERR_RESERVED_NONZERO.'}
