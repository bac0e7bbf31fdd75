/* The one set of input checks: the same bad camera, light, scene box,
 * setup option, reserved field or NULL gets the same status from
 * swarp_setup, swarp_setup_range, swarp_cascade_setup (split and stabilised
 * paths) and swarp_plan, and that status is the one the header documents
 * for the field (written here by hand from include/shadowwarp.h: the
 * camera's "fovy in (0, pi)", "aspect > 0", "0 < near < far", "up must not
 * be parallel to dir"; the light's "direction ... any length > 0",
 * "cone_angle in (0, pi/2)"; the status list's BOX_INVERTED and
 * BOX_DEGENERATE; "a _reserved field is not zero"; "Errors leave every
 * output untouched").  Every other argument of each call is valid: the
 * unmodified inputs succeed from every entry point (base_inputs_valid). */
#include <check.h>
#include <math.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define PI 3.14159265358979323846
#define CANARY 0xA5

typedef struct inputs {
    swarp_camera cam;
    swarp_light light;
    swarp_aabb box;
    swarp_setup_options opt;
} inputs;

/* A camera 3 units up looking slightly down along -z at a 40 x 6 x 40 box,
 * the sun from above at an angle: every entry point maps it. */
static inputs base(void) {
    inputs in;
    memset(&in, 0, sizeof in);
    in.cam.eye = (swarp_vec3){0.0, 3.0, 10.0};
    in.cam.dir = (swarp_vec3){0.0, -0.2, -1.0};
    in.cam.up = (swarp_vec3){0.0, 1.0, 0.0};
    in.cam.fovy = 1.0;
    in.cam.aspect = 1.5;
    in.cam.z_near = 1.0;
    in.cam.z_far = 100.0;
    in.light.type = SWARP_LIGHT_DIRECTIONAL;
    in.light.direction = (swarp_vec3){0.3, -1.0, 0.2};
    in.box.min = (swarp_vec3){-20.0, -1.0, -40.0};
    in.box.max = (swarp_vec3){20.0, 5.0, 0.0};
    return in;
}

/* a point light above the box (omni, or a spot with cone > 0 along -y) */
static void point_light(inputs* in, double cone) {
    in->light.type = SWARP_LIGHT_POINT;
    in->light.position = (swarp_vec3){0.0, 60.0, -20.0};
    in->light.direction = (swarp_vec3){0.0, -1.0, 0.0};
    in->light.cone_angle = cone;
}

/* up at sin(angle) = s to dir = -z (s < 0: toward +z, nearly antiparallel) */
static void up_at(inputs* in, double s, int anti) {
    in->cam.dir = (swarp_vec3){0.0, 0.0, -1.0};
    in->cam.up = (swarp_vec3){0.0, s, anti ? 1.0 : -1.0};
}

/* ---- the calls, each with its outputs canary-filled -------------------------- */

enum { E_SETUP, E_RANGE, E_CASCADE, E_CASCADE_STABLE, E_PLAN, E_COUNT };
static const char* const entry_name[E_COUNT] = {"swarp_setup", "swarp_setup_range", "swarp_cascade_setup",
                                                "swarp_cascade_setup (stabilised)", "swarp_plan"};

typedef struct outputs {
    swarp_setup_result res;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t count;
    swarp_cascade_result cres;
    swarp_cascade_split splits[SWARP_CASCADE_MAX_SPLITS];
    struct swarp_plan plan;
} outputs;

static int untouched(const void* p, size_t n) {
    const unsigned char* b = (const unsigned char*)p;
    for (size_t i = 0; i < n; ++i)
        if (b[i] != CANARY) return 0;
    return 1;
}

/* which pointer argument is NULL (0: none) */
enum { N_NONE, N_CAM, N_LIGHT, N_BOX, N_OUT };

static swarp_status call(int e, const inputs* in, int null_arg, outputs* out) {
    memset(out, CANARY, sizeof *out);
    const swarp_camera* cam = null_arg == N_CAM ? NULL : &in->cam;
    const swarp_light* light = null_arg == N_LIGHT ? NULL : &in->light;
    const swarp_aabb* box = null_arg == N_BOX ? NULL : &in->box;
    const int no_out = null_arg == N_OUT;
    swarp_cascade_options co;
    memset(&co, 0, sizeof co);
    co.setup = in->opt;
    switch (e) {
    case E_SETUP:
        return swarp_setup(cam, light, box, &in->opt, no_out ? NULL : &out->res, out->pts, SWARP_BODY_MAX_POINTS,
                           &out->count);
    case E_RANGE: /* the camera's range as the explicit one (cam->z_near/far are ignored) */
        return swarp_setup_range(cam, light, box, in->cam.z_near, in->cam.z_far, &in->opt, no_out ? NULL : &out->res,
                                 out->pts, SWARP_BODY_MAX_POINTS, &out->count);
    case E_CASCADE_STABLE: /* a path that never calls swarp_setup */
        co.setup.technique = SWARP_TECHNIQUE_UNIFORM;
        co.stabilize.mode = SWARP_STABILIZE_SPHERE;
        /* fall through */
    case E_CASCADE:
        return swarp_cascade_setup(cam, light, box, &co, no_out ? NULL : &out->cres, out->splits,
                                   SWARP_CASCADE_MAX_SPLITS, &out->count);
    default: {
        /* the planner takes camera, light and box inside its needs (no
         * pointers of their own) and has no setup options */
        swarp_scene_needs needs;
        memset(&needs, 0, sizeof needs);
        needs.camera = in->cam;
        needs.light = in->light;
        needs.scene_box = in->box;
        return swarp_plan(&needs, NULL, no_out ? NULL : &out->plan);
    }
    }
}

static int outputs_untouched(int e, const outputs* o) {
    switch (e) {
    case E_SETUP:
    case E_RANGE: return untouched(&o->res, sizeof o->res) && untouched(o->pts, sizeof o->pts) &&
                         untouched(&o->count, sizeof o->count);
    case E_CASCADE:
    case E_CASCADE_STABLE: return untouched(&o->cres, sizeof o->cres) && untouched(o->splits, sizeof o->splits) &&
                                  untouched(&o->count, sizeof o->count);
    default: return untouched(&o->plan, sizeof o->plan);
    }
}

/* ---- the bad inputs ---------------------------------------------------------- */

typedef void (*mutate_fn)(inputs*);
#define MUT(name, ...) \
    static void name(inputs* in) { __VA_ARGS__; }

/* camera */
MUT(c_eye_nan, in->cam.eye.x = NAN)
MUT(c_eye_inf, in->cam.eye.z = -INFINITY)
MUT(c_dir_nan, in->cam.dir.y = NAN)
MUT(c_dir_zero, in->cam.dir = (swarp_vec3){0, 0, 0})
MUT(c_up_inf, in->cam.up.y = INFINITY)
MUT(c_up_zero, in->cam.up = (swarp_vec3){0, 0, 0})
MUT(c_fovy_nan, in->cam.fovy = NAN)
MUT(c_fovy_inf, in->cam.fovy = INFINITY)
MUT(c_fovy_zero, in->cam.fovy = 0.0)
MUT(c_fovy_neg, in->cam.fovy = -0.5)
MUT(c_fovy_pi, in->cam.fovy = PI)
MUT(c_fovy_4, in->cam.fovy = 4.0)
MUT(c_aspect_nan, in->cam.aspect = NAN)
MUT(c_aspect_zero, in->cam.aspect = 0.0)
MUT(c_aspect_neg, in->cam.aspect = -1.5)
MUT(c_near_nan, in->cam.z_near = NAN)
MUT(c_far_inf, in->cam.z_far = INFINITY)
MUT(c_near_zero, in->cam.z_near = 0.0)
MUT(c_near_neg, in->cam.z_near = -1.0)
MUT(c_far_eq_near, in->cam.z_far = in->cam.z_near)
MUT(c_far_lt_near, in->cam.z_far = 0.5)
MUT(c_reserved0, in->cam._reserved[0] = 1)
MUT(c_reserved3, in->cam._reserved[3] = 0x80000000u)
/* up parallel to dir: exactly, and with sin(angle) below the bound 1e-9 */
MUT(c_up_eq_dir, in->cam.up = in->cam.dir)
MUT(c_up_scaled_dir, in->cam.up = (swarp_vec3){0.0, -2e6, -1e7})
MUT(c_up_anti_dir, in->cam.up = (swarp_vec3){0.0, 0.2, 1.0})
MUT(c_up_sin_1e_12, up_at(in, 1e-12, 0))
MUT(c_up_sin_3e_10, up_at(in, 3e-10, 0))
MUT(c_up_sin_0_9e_9, up_at(in, 0.9e-9, 0))
MUT(c_up_anti_sin_0_5e_9, up_at(in, 0.5e-9, 1))
/* light */
MUT(l_type_7, in->light.type = (swarp_light_type)7)
MUT(l_type_neg, in->light.type = (swarp_light_type)-1)
MUT(l_type_force, in->light.type = SWARP_LIGHT_TYPE_FORCE_I32)
MUT(l_reserved0, in->light._reserved0 = 1)
MUT(l_reserved2, in->light._reserved[2] = 1)
MUT(l_dir_zero, in->light.direction = (swarp_vec3){0, 0, 0})
MUT(l_dir_nan, in->light.direction.x = NAN)
MUT(l_dir_inf, in->light.direction.y = -INFINITY)
MUT(l_default_dir_zero, in->light.type = SWARP_LIGHT_DEFAULT; in->light.direction = (swarp_vec3){0, 0, 0};
    in->light.position = (swarp_vec3){1, 2, 3})
MUT(l_point_pos_nan, point_light(in, 0.0); in->light.position.y = NAN)
MUT(l_point_pos_inf, point_light(in, 0.0); in->light.position.x = INFINITY)
MUT(l_point_cone_nan, point_light(in, NAN))
MUT(l_point_cone_inf, point_light(in, INFINITY))
MUT(l_point_cone_neg, point_light(in, -0.1))
MUT(l_point_cone_half_pi, point_light(in, 0.5 * PI))
MUT(l_point_cone_2, point_light(in, 2.0))
MUT(l_spot_dir_zero, point_light(in, 0.6); in->light.direction = (swarp_vec3){0, 0, 0})
MUT(l_spot_dir_nan, point_light(in, 0.6); in->light.direction.z = NAN)
MUT(l_point_reserved, point_light(in, 0.6); in->light._reserved[0] = 7)
/* scene box */
MUT(b_min_nan, in->box.min.y = NAN)
MUT(b_max_inf, in->box.max.x = INFINITY)
MUT(b_inverted_x, in->box.min.x = 30.0)
MUT(b_inverted_y, in->box.max.y = -2.0)
MUT(b_inverted_z, in->box.min.z = 1.0)
MUT(b_line, in->box.min.x = in->box.max.x = 1.0; in->box.min.y = in->box.max.y = 1.0)
MUT(b_point, in->box.min = in->box.max = (swarp_vec3){1.0, 1.0, -5.0})
/* setup options (the planner has none: N/A there) */
MUT(o_reserved, in->opt._reserved[0] = 1)
MUT(o_skip_measure, in->opt.skip_measure = 2)
MUT(o_pad0, in->opt._pad0 = 1)
MUT(o_pad1, in->opt._pad1 = 2)
MUT(o_technique, in->opt.technique = (swarp_technique)4)
MUT(o_technique_force, in->opt.technique = SWARP_TECHNIQUE_FORCE_I32)
MUT(o_param, in->opt.param = (swarp_warp_param)7)
MUT(o_center, in->opt.center = (swarp_warp_center)3)
MUT(o_depth, in->opt.depth_range = (swarp_depth_range)4)
MUT(o_pancake, in->opt.pancake = 2)
MUT(o_psm_slideback, in->opt.psm_slideback = 5)
MUT(o_slideback_nan, in->opt.slideback = NAN)
MUT(o_slideback_neg, in->opt.slideback = -1.0)
MUT(o_min_depth_nan, in->opt.min_depth = NAN)
MUT(o_min_depth_neg, in->opt.min_depth = -1.0)
MUT(o_min_depth_ninf, in->opt.min_depth = -INFINITY)
MUT(o_n_user_zero, in->opt.param = SWARP_WARP_PARAM_USER; in->opt.n_user = 0.0)
MUT(o_n_user_neg, in->opt.param = SWARP_WARP_PARAM_USER; in->opt.n_user = -3.0)
MUT(o_n_user_nan, in->opt.param = SWARP_WARP_PARAM_USER; in->opt.n_user = NAN)
MUT(o_pseudo_nan, in->opt.param = SWARP_WARP_PARAM_PSEUDO; in->opt.pseudo_near = NAN)
MUT(o_pseudo_inf, in->opt.param = SWARP_WARP_PARAM_PSEUDO; in->opt.pseudo_far = INFINITY)
MUT(o_pseudo_neg, in->opt.param = SWARP_WARP_PARAM_PSEUDO; in->opt.pseudo_near = -0.1)
/* [RHS] (4.2) needs n_p + f_p < 1 */
MUT(o_pseudo_sum, in->opt.param = SWARP_WARP_PARAM_PSEUDO; in->opt.pseudo_near = 0.6; in->opt.pseudo_far = 0.5)

/* which entry points a case applies to */
#define ALL 0u
#define NO_PLAN 1u   /* setup options: the planner has none */
#define NO_STABLE 2u /* options the stabilised cascade overrides or refuses first (technique) */

static const struct {
    const char* name;
    mutate_fn fn;
    swarp_status want;
    unsigned skip;
} bad[] = {
    {"camera eye NaN", c_eye_nan, SWARP_ERR_NON_FINITE, ALL},
    {"camera eye -inf", c_eye_inf, SWARP_ERR_NON_FINITE, ALL},
    {"camera dir NaN", c_dir_nan, SWARP_ERR_NON_FINITE, ALL},
    {"camera dir zero", c_dir_zero, SWARP_ERR_ZERO_VECTOR, ALL},
    {"camera up inf", c_up_inf, SWARP_ERR_NON_FINITE, ALL},
    {"camera up zero", c_up_zero, SWARP_ERR_ZERO_VECTOR, ALL},
    {"camera fovy NaN", c_fovy_nan, SWARP_ERR_NON_FINITE, ALL},
    {"camera fovy inf", c_fovy_inf, SWARP_ERR_NON_FINITE, ALL},
    {"camera fovy 0", c_fovy_zero, SWARP_ERR_FOV, ALL},
    {"camera fovy < 0", c_fovy_neg, SWARP_ERR_FOV, ALL},
    {"camera fovy pi", c_fovy_pi, SWARP_ERR_FOV, ALL},
    {"camera fovy 4", c_fovy_4, SWARP_ERR_FOV, ALL},
    {"camera aspect NaN", c_aspect_nan, SWARP_ERR_NON_FINITE, ALL},
    {"camera aspect 0", c_aspect_zero, SWARP_ERR_OUT_OF_RANGE, ALL},
    {"camera aspect < 0", c_aspect_neg, SWARP_ERR_OUT_OF_RANGE, ALL},
    {"camera near NaN", c_near_nan, SWARP_ERR_NON_FINITE, ALL},
    {"camera far inf", c_far_inf, SWARP_ERR_NON_FINITE, ALL},
    {"camera near 0", c_near_zero, SWARP_ERR_NEAR_FAR, ALL},
    {"camera near < 0", c_near_neg, SWARP_ERR_NEAR_FAR, ALL},
    {"camera far = near", c_far_eq_near, SWARP_ERR_NEAR_FAR, ALL},
    {"camera far < near", c_far_lt_near, SWARP_ERR_NEAR_FAR, ALL},
    {"camera _reserved[0]", c_reserved0, SWARP_ERR_RESERVED_NONZERO, ALL},
    {"camera _reserved[3]", c_reserved3, SWARP_ERR_RESERVED_NONZERO, ALL},
    {"camera up = dir", c_up_eq_dir, SWARP_ERR_DEGENERATE, ALL},
    {"camera up = 1e7 dir", c_up_scaled_dir, SWARP_ERR_DEGENERATE, ALL},
    {"camera up = -dir", c_up_anti_dir, SWARP_ERR_DEGENERATE, ALL},
    {"camera sin(dir, up) 1e-12", c_up_sin_1e_12, SWARP_ERR_DEGENERATE, ALL},
    {"camera sin(dir, up) 3e-10", c_up_sin_3e_10, SWARP_ERR_DEGENERATE, ALL},
    {"camera sin(dir, up) 0.9e-9", c_up_sin_0_9e_9, SWARP_ERR_DEGENERATE, ALL},
    {"camera sin(dir, -up) 0.5e-9", c_up_anti_sin_0_5e_9, SWARP_ERR_DEGENERATE, ALL},
    {"light type 7", l_type_7, SWARP_ERR_UNKNOWN_ENUM, ALL},
    {"light type -1", l_type_neg, SWARP_ERR_UNKNOWN_ENUM, ALL},
    {"light type FORCE_I32", l_type_force, SWARP_ERR_UNKNOWN_ENUM, ALL},
    {"light _reserved0", l_reserved0, SWARP_ERR_RESERVED_NONZERO, ALL},
    {"light _reserved[2]", l_reserved2, SWARP_ERR_RESERVED_NONZERO, ALL},
    {"directional direction zero", l_dir_zero, SWARP_ERR_ZERO_VECTOR, ALL},
    {"directional direction NaN", l_dir_nan, SWARP_ERR_NON_FINITE, ALL},
    {"directional direction -inf", l_dir_inf, SWARP_ERR_NON_FINITE, ALL},
    {"default-type direction zero", l_default_dir_zero, SWARP_ERR_ZERO_VECTOR, ALL},
    {"point position NaN", l_point_pos_nan, SWARP_ERR_NON_FINITE, ALL},
    {"point position inf", l_point_pos_inf, SWARP_ERR_NON_FINITE, ALL},
    {"point cone NaN", l_point_cone_nan, SWARP_ERR_NON_FINITE, ALL},
    {"point cone inf", l_point_cone_inf, SWARP_ERR_NON_FINITE, ALL},
    {"point cone < 0", l_point_cone_neg, SWARP_ERR_OUT_OF_RANGE, ALL},
    {"point cone pi/2", l_point_cone_half_pi, SWARP_ERR_OUT_OF_RANGE, ALL},
    {"point cone 2", l_point_cone_2, SWARP_ERR_OUT_OF_RANGE, ALL},
    {"spot direction zero", l_spot_dir_zero, SWARP_ERR_ZERO_VECTOR, ALL},
    {"spot direction NaN", l_spot_dir_nan, SWARP_ERR_NON_FINITE, ALL},
    {"spot _reserved[0]", l_point_reserved, SWARP_ERR_RESERVED_NONZERO, ALL},
    {"box min NaN", b_min_nan, SWARP_ERR_NON_FINITE, ALL},
    {"box max inf", b_max_inf, SWARP_ERR_NON_FINITE, ALL},
    {"box inverted x", b_inverted_x, SWARP_ERR_BOX_INVERTED, ALL},
    {"box inverted y", b_inverted_y, SWARP_ERR_BOX_INVERTED, ALL},
    {"box inverted z", b_inverted_z, SWARP_ERR_BOX_INVERTED, ALL},
    {"box a line", b_line, SWARP_ERR_BOX_DEGENERATE, ALL},
    {"box a point", b_point, SWARP_ERR_BOX_DEGENERATE, ALL},
    {"options _reserved[0]", o_reserved, SWARP_ERR_RESERVED_NONZERO, NO_PLAN},
    {"options skip_measure 2", o_skip_measure, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    {"options _pad0", o_pad0, SWARP_ERR_RESERVED_NONZERO, NO_PLAN},
    {"options _pad1", o_pad1, SWARP_ERR_RESERVED_NONZERO, NO_PLAN},
    {"options technique 4", o_technique, SWARP_ERR_UNKNOWN_ENUM, NO_PLAN | NO_STABLE},
    {"options technique FORCE_I32", o_technique_force, SWARP_ERR_UNKNOWN_ENUM, NO_PLAN | NO_STABLE},
    {"options param 7", o_param, SWARP_ERR_UNKNOWN_ENUM, NO_PLAN},
    {"options center 3", o_center, SWARP_ERR_UNKNOWN_ENUM, NO_PLAN},
    {"options depth_range 4", o_depth, SWARP_ERR_UNKNOWN_ENUM, NO_PLAN},
    {"options pancake 2", o_pancake, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    {"options psm_slideback 5", o_psm_slideback, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    {"options slideback NaN", o_slideback_nan, SWARP_ERR_NON_FINITE, NO_PLAN},
    {"options slideback < 0", o_slideback_neg, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    {"options min_depth NaN", o_min_depth_nan, SWARP_ERR_NON_FINITE, NO_PLAN},
    {"options min_depth < 0", o_min_depth_neg, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    {"options min_depth -inf", o_min_depth_ninf, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    /* LiSPSM's parameters: a uniform (stabilised) map does not read them */
    {"options n_user 0", o_n_user_zero, SWARP_ERR_OUT_OF_RANGE, NO_PLAN | NO_STABLE},
    {"options n_user < 0", o_n_user_neg, SWARP_ERR_OUT_OF_RANGE, NO_PLAN | NO_STABLE},
    {"options n_user NaN", o_n_user_nan, SWARP_ERR_NON_FINITE, NO_PLAN | NO_STABLE},
    {"options pseudo_near NaN", o_pseudo_nan, SWARP_ERR_NON_FINITE, NO_PLAN | NO_STABLE},
    {"options pseudo_far inf", o_pseudo_inf, SWARP_ERR_NON_FINITE, NO_PLAN | NO_STABLE},
    {"options pseudo_near < 0", o_pseudo_neg, SWARP_ERR_OUT_OF_RANGE, NO_PLAN | NO_STABLE},
    {"options pseudo_near + pseudo_far >= 1", o_pseudo_sum, SWARP_ERR_OUT_OF_RANGE, NO_PLAN | NO_STABLE},
};

static int applies(int e, unsigned skip) {
    if (e == E_PLAN && (skip & NO_PLAN)) return 0;
    if (e == E_CASCADE_STABLE && (skip & NO_STABLE)) return 0;
    return 1;
}

/* ---- tests ------------------------------------------------------------------- */

/* the unmodified inputs (and the point-light and spot variants the light
 * cases start from) succeed everywhere: a bad case's error is its field's */
START_TEST(base_inputs_valid) {
    for (int v = 0; v < 3; ++v) {
        inputs in = base();
        if (v > 0) point_light(&in, v == 1 ? 0.0 : 0.6);
        for (int e = 0; e < E_COUNT; ++e) {
            if (e == E_CASCADE_STABLE && v > 0) continue; /* stabilisation: directional only */
            outputs out;
            swarp_status s = call(e, &in, N_NONE, &out);
            ck_assert_msg(!swarp_status_is_error(s), "variant %d, %s: %s", v, entry_name[e], swarp_status_name(s));
        }
    }
}
END_TEST

START_TEST(bad_input_same_documented_status) {
    inputs in = base();
    bad[_i].fn(&in);
    for (int e = 0; e < E_COUNT; ++e) {
        if (!applies(e, bad[_i].skip)) continue;
        outputs out;
        swarp_status s = call(e, &in, N_NONE, &out);
        ck_assert_msg(s == bad[_i].want, "%s, %s: %s (documented: %s)", bad[_i].name, entry_name[e],
                      swarp_status_name(s), swarp_status_name(bad[_i].want));
        ck_assert_msg(outputs_untouched(e, &out), "%s, %s: an output was written", bad[_i].name, entry_name[e]);
    }
}
END_TEST

/* A NULL camera, light, box or result: SWARP_ERR_NULL_POINTER, nothing
 * written (the planner's camera, light and box are inside its needs; its
 * result pointer is the one it must have). */
START_TEST(null_pointer_same_status) {
    const inputs in = base();
    for (int null_arg = N_CAM; null_arg <= N_OUT; ++null_arg)
        for (int e = 0; e < E_COUNT; ++e) {
            if (e == E_PLAN && null_arg != N_OUT) continue;
            outputs out;
            swarp_status s = call(e, &in, null_arg, &out);
            ck_assert_msg(s == SWARP_ERR_NULL_POINTER, "NULL argument %d, %s: %s", null_arg, entry_name[e],
                          swarp_status_name(s));
            ck_assert_msg(outputs_untouched(e, &out), "NULL argument %d, %s: an output was written", null_arg,
                          entry_name[e]);
        }
}
END_TEST

/* up at sin(angle) 1.1e-9 .. 1e-3 from dir (or -dir): above the bound, a
 * valid camera everywhere (the frame is defined; the statuses may be
 * informational) */
START_TEST(up_near_parallel_above_bound_valid) {
    static const double sines[] = {1.1e-9, 2e-9, 1e-8, 1e-6, 1e-3};
    for (size_t k = 0; k < sizeof sines / sizeof sines[0]; ++k)
        for (int anti = 0; anti < 2; ++anti) {
            inputs in = base();
            up_at(&in, sines[k], anti);
            for (int e = 0; e < E_COUNT; ++e) {
                outputs out;
                swarp_status s = call(e, &in, N_NONE, &out);
                ck_assert_msg(!swarp_status_is_error(s), "sin %g%s, %s: %s", sines[k], anti ? " (anti)" : "",
                              entry_name[e], swarp_status_name(s));
            }
        }
}
END_TEST

/* Fields the light's type does not use are not checked (the header: a
 * directional light uses direction, a point light position and
 * cone_angle, a spot also direction): garbage there changes nothing. */
START_TEST(unused_light_fields_ignored) {
    for (int v = 0; v < 2; ++v) {
        inputs clean = base(), dirty;
        if (v == 1) point_light(&clean, 0.0); /* omni: no axis */
        dirty = clean;
        if (v == 0) dirty.light.position = (swarp_vec3){NAN, INFINITY, -INFINITY};
        else dirty.light.direction = (swarp_vec3){NAN, 0.0, INFINITY};
        for (int e = 0; e < E_COUNT; ++e) {
            if (e == E_CASCADE_STABLE && v == 1) continue;
            outputs a, b;
            swarp_status sa = call(e, &clean, N_NONE, &a), sb = call(e, &dirty, N_NONE, &b);
            ck_assert_msg(!swarp_status_is_error(sa), "%s: %s", entry_name[e], swarp_status_name(sa));
            ck_assert_msg(sa == sb, "variant %d, %s: %s with the unused field, %s without", v, entry_name[e],
                          swarp_status_name(sb), swarp_status_name(sa));
        }
    }
}
END_TEST

/* Two bad fields at once: the first in the one order of the checks wins
 * everywhere (camera: reserved, non-finite, fovy, aspect, zero vectors, up
 * parallel; then the light, the setup options, the view range, the box). */
MUT(m_fov_and_zero_up, in->cam.fovy = 0.0; in->cam.up = (swarp_vec3){0, 0, 0})
MUT(m_aspect_and_parallel, in->cam.aspect = -1.0; in->cam.up = in->cam.dir)
MUT(m_fov_and_near_nan, in->cam.fovy = 4.0; in->cam.z_near = NAN)
MUT(m_reserved_and_nan, in->cam._reserved[1] = 1; in->cam.eye.y = NAN)
MUT(m_camera_and_light, in->cam.dir = (swarp_vec3){0, 0, 0}; in->light.type = (swarp_light_type)9)
MUT(m_light_and_box, in->light.direction.z = NAN; in->box.min.x = 99.0)
MUT(m_light_and_options, in->light._reserved0 = 3; in->opt.pancake = 9)
MUT(m_options_and_range, in->opt.slideback = -2.0; in->cam.z_near = 0.0)
MUT(m_range_and_box, in->cam.z_far = 0.25; in->box.max = in->box.min)

static const struct {
    const char* name;
    mutate_fn fn;
    swarp_status want;
    unsigned skip;
} two_bad[] = {
    {"fovy 0 and up zero", m_fov_and_zero_up, SWARP_ERR_FOV, ALL},
    {"aspect < 0 and up = dir", m_aspect_and_parallel, SWARP_ERR_OUT_OF_RANGE, ALL},
    {"fovy 4 and near NaN", m_fov_and_near_nan, SWARP_ERR_FOV, ALL},
    {"camera _reserved and eye NaN", m_reserved_and_nan, SWARP_ERR_RESERVED_NONZERO, ALL},
    {"dir zero and light type 9", m_camera_and_light, SWARP_ERR_ZERO_VECTOR, ALL},
    {"light NaN and box inverted", m_light_and_box, SWARP_ERR_NON_FINITE, ALL},
    {"light _reserved0 and pancake 9", m_light_and_options, SWARP_ERR_RESERVED_NONZERO, NO_PLAN},
    {"slideback < 0 and near 0", m_options_and_range, SWARP_ERR_OUT_OF_RANGE, NO_PLAN},
    {"far < near and box a point", m_range_and_box, SWARP_ERR_NEAR_FAR, ALL},
};

START_TEST(two_bad_fields_same_first_status) {
    inputs in = base();
    two_bad[_i].fn(&in);
    for (int e = 0; e < E_COUNT; ++e) {
        if (!applies(e, two_bad[_i].skip)) continue;
        outputs out;
        swarp_status s = call(e, &in, N_NONE, &out);
        ck_assert_msg(s == two_bad[_i].want, "%s, %s: %s (first in order: %s)", two_bad[_i].name, entry_name[e],
                      swarp_status_name(s), swarp_status_name(two_bad[_i].want));
        ck_assert_msg(outputs_untouched(e, &out), "%s, %s: an output was written", two_bad[_i].name, entry_name[e]);
    }
}
END_TEST

/* The stabilisation stage's own entry points take the camera through the
 * same check: the same statuses at the same bound. */
START_TEST(stabilize_camera_same_bound) {
    static const struct {
        double s;
        swarp_status want;
    } k[] = {{0.5e-9, SWARP_ERR_DEGENERATE}, {0.9e-9, SWARP_ERR_DEGENERATE}, {1.1e-9, SWARP_OK},
             {3e-9, SWARP_OK}, {5e-9, SWARP_OK}, {1e-6, SWARP_OK}};
    for (size_t i = 0; i < sizeof k / sizeof k[0]; ++i) {
        inputs in = base();
        up_at(&in, k[i].s, 0);
        swarp_vec3 c;
        double r;
        memset(&c, CANARY, sizeof c);
        memset(&r, CANARY, sizeof r);
        swarp_status s = swarp_stabilize_sphere(&in.cam, 1.0, 50.0, &c, &r, NULL);
        ck_assert_msg(s == k[i].want, "sin %g: %s", k[i].s, swarp_status_name(s));
        if (s != SWARP_OK) ck_assert(untouched(&c, sizeof c) && untouched(&r, sizeof r));
        outputs out;
        ck_assert_int_eq(call(E_SETUP, &in, N_NONE, &out) == SWARP_ERR_DEGENERATE, k[i].want == SWARP_ERR_DEGENERATE);
    }
}
END_TEST

static Suite* checks_suite(void) {
    Suite* s = suite_create("checks");
    TCase* t = tcase_create("core");
    tcase_add_test(t, base_inputs_valid);
    tcase_add_loop_test(t, bad_input_same_documented_status, 0, (int)(sizeof bad / sizeof bad[0]));
    tcase_add_test(t, null_pointer_same_status);
    tcase_add_test(t, up_near_parallel_above_bound_valid);
    tcase_add_test(t, unused_light_fields_ignored);
    tcase_add_loop_test(t, two_bad_fields_same_first_status, 0, (int)(sizeof two_bad / sizeof two_bad[0]));
    tcase_add_test(t, stabilize_camera_same_bound);
    suite_add_tcase(s, t);
    return s;
}

int main(void) { return tu_run_suite(checks_suite()) ? 1 : 0; }
