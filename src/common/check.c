/* The one set of input checks of the entry points (camera, light, scene box,
 * setup options, reserved fields) and the defaults they resolve.  Every
 * entry point that takes one of these arguments validates it here, so the
 * same bad argument gets the same status from swarp_setup,
 * swarp_setup_range, swarp_cascade_setup, swarp_plan and the stage
 * functions.  Each check returns the first failing status in a fixed order:
 * reserved fields, enums, non-finite values, domains, then geometry (zero
 * vectors, up parallel to dir); the order is that of swarp_setup. */
#include "common/depth_range.h"

swarp_status sw_check_depth_range(swarp_depth_range d) {
    if (d != SWARP_DEPTH_DEFAULT && d != SWARP_DEPTH_NEG_ONE_TO_ONE && d != SWARP_DEPTH_ZERO_TO_ONE)
        return SWARP_ERR_UNKNOWN_ENUM;
    return SWARP_OK;
}

swarp_status sw_check_camera_shape(const swarp_camera* cam) {
    if (!sw_reserved_zero(cam->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
    if (!sw_finite3(&cam->eye) || !sw_finite3(&cam->dir) || !sw_finite3(&cam->up) ||
        !sw_finite(cam->fovy) || !sw_finite(cam->aspect))
        return SWARP_ERR_NON_FINITE;
    if (!(cam->fovy > 0.0 && cam->fovy < SWARP_PI)) return SWARP_ERR_FOV;
    if (!(cam->aspect > 0.0)) return SWARP_ERR_OUT_OF_RANGE;
    swarp_vec3 f, u;
    if (!sw_normalize_fast(cam->dir, &f) || !sw_normalize_fast(cam->up, &u)) return SWARP_ERR_ZERO_VECTOR;
    if (!(sw_len_fast(sw_cross(f, u)) >= SW_CAMERA_MIN_UP_SIN)) return SWARP_ERR_DEGENERATE;
    return SWARP_OK;
}

swarp_status sw_check_view_range(double near, double far) {
    if (!sw_finite(near) || !sw_finite(far)) return SWARP_ERR_NON_FINITE;
    if (!(near > 0.0 && far > near)) return SWARP_ERR_NEAR_FAR;
    return SWARP_OK;
}

swarp_status sw_check_camera(const swarp_camera* cam) {
    swarp_status s = sw_check_camera_shape(cam);
    if (s != SWARP_OK) return s;
    return sw_check_view_range(cam->z_near, cam->z_far);
}

/* A direction the caller must give: finite and not zero. */
static swarp_status sw_check_direction(const swarp_vec3* d) {
    if (!sw_finite3(d)) return SWARP_ERR_NON_FINITE;
    swarp_vec3 a;
    if (!sw_normalize_fast(*d, &a)) return SWARP_ERR_ZERO_VECTOR;
    return SWARP_OK;
}

/* Only the fields the light's type uses are checked (the header: a
 * directional light uses direction, a point light position and cone_angle,
 * a spot also direction): an unused field may hold anything. */
swarp_status sw_check_light(const swarp_light* light) {
    if (light->_reserved0 != 0 || !sw_reserved_zero(light->_reserved, 4))
        return SWARP_ERR_RESERVED_NONZERO;
    swarp_light_type t = light->type;
    if (t != SWARP_LIGHT_DEFAULT && t != SWARP_LIGHT_DIRECTIONAL && t != SWARP_LIGHT_POINT)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (t != SWARP_LIGHT_POINT) return sw_check_direction(&light->direction);
    if (!sw_finite3(&light->position) || !sw_finite(light->cone_angle)) return SWARP_ERR_NON_FINITE;
    if (light->cone_angle == 0.0) return SWARP_OK; /* omni: no axis */
    if (!(light->cone_angle > 0.0 && light->cone_angle < 0.5 * SWARP_PI)) return SWARP_ERR_OUT_OF_RANGE;
    return sw_check_direction(&light->direction);
}

swarp_status sw_check_box(const swarp_aabb* box) {
    if (!sw_finite3(&box->min) || !sw_finite3(&box->max)) return SWARP_ERR_NON_FINITE;
    if (!(box->min.x <= box->max.x && box->min.y <= box->max.y && box->min.z <= box->max.z))
        return SWARP_ERR_BOX_INVERTED;
    int zero = (box->min.x == box->max.x) + (box->min.y == box->max.y) + (box->min.z == box->max.z);
    if (zero >= 2) return SWARP_ERR_BOX_DEGENERATE;
    return SWARP_OK;
}

swarp_warp_options sw_setup_warp_options(const swarp_setup_options* o) {
    swarp_warp_options w;
    memset(&w, 0, sizeof w);
    w.param = o->param;
    w.center = o->center;
    w.n_user = o->n_user;
    w.pseudo_near = o->pseudo_near;
    w.pseudo_far = o->pseudo_far;
    return w;
}

/* The LiSPSM parameter fields are checked only where the technique reads
 * them (a uniform or PSM map ignores n_user and the pseudo fractions). */
static swarp_status sw_check_setup_warp(const swarp_setup_options* o) {
    const swarp_warp_options w = sw_setup_warp_options(o);
    if ((uint32_t)w.param > (uint32_t)SWARP_WARP_PARAM_MEASURED) return SWARP_ERR_UNKNOWN_ENUM;
    if ((uint32_t)w.center > (uint32_t)SWARP_WARP_CENTER_NEAREST_VERTEX) return SWARP_ERR_UNKNOWN_ENUM;
    if (o->technique != SWARP_TECHNIQUE_LISPSM && o->technique != SWARP_TECHNIQUE_DEFAULT) return SWARP_OK;
    if (w.param == SWARP_WARP_PARAM_USER) {
        if (isnan(w.n_user)) return SWARP_ERR_NON_FINITE;
        if (!(w.n_user > 0.0)) return SWARP_ERR_OUT_OF_RANGE;
    }
    if (w.param == SWARP_WARP_PARAM_PSEUDO) {
        if (!sw_finite(w.pseudo_near) || !sw_finite(w.pseudo_far)) return SWARP_ERR_NON_FINITE;
        /* [RHS] (4.2) needs n_p + f_p < 1 */
        if (!(w.pseudo_near >= 0.0 && w.pseudo_far >= 0.0 && w.pseudo_near + w.pseudo_far < 1.0))
            return SWARP_ERR_OUT_OF_RANGE;
    }
    return SWARP_OK;
}

swarp_status sw_check_setup_options(const swarp_setup_options* o) {
    if (!sw_reserved_zero(o->_reserved, 1) || o->_pad0 != 0 || o->_pad1 != 0) return SWARP_ERR_RESERVED_NONZERO;
    if (o->skip_measure > 1) return SWARP_ERR_OUT_OF_RANGE;
    if (isnan(o->min_depth)) return SWARP_ERR_NON_FINITE;
    if (o->min_depth < 0.0) return SWARP_ERR_OUT_OF_RANGE; /* also -INFINITY; +INFINITY: nothing seen */
    if ((uint32_t)o->technique > (uint32_t)SWARP_TECHNIQUE_PSM) return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_light_depth_range_ok(o->depth_range)) return SWARP_ERR_UNKNOWN_ENUM;
    if (o->pancake > 1 || o->psm_slideback > 1) return SWARP_ERR_OUT_OF_RANGE;
    if (!sw_finite(o->slideback)) return SWARP_ERR_NON_FINITE;
    if (o->slideback < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    return sw_check_setup_warp(o);
}

swarp_status sw_resolve_setup_options(const swarp_setup_options* opts, swarp_setup_options* o) {
    memset(o, 0, sizeof *o);
    if (opts) *o = *opts;
    return sw_check_setup_options(o);
}

swarp_status sw_check_increasing(const double* v, size_t m) {
    for (size_t i = 0; i <= m; ++i)
        if (!sw_finite(v[i])) return SWARP_ERR_NON_FINITE;
    for (size_t i = 0; i < m; ++i)
        if (!(v[i + 1] > v[i])) return SWARP_ERR_NOT_INCREASING;
    return SWARP_OK;
}

/* ---- defaults ------------------------------------------------------------ */

void sw_setup_map_size(const swarp_setup_options* o, uint32_t* width, uint32_t* height) {
    *width = o->map_width ? o->map_width : SW_DEFAULT_MAP_RES;
    *height = o->map_height ? o->map_height : *width;
}

/* [RHS] (2.3)-(2.8) take the larger resolution as res_ix / res_s (the
 * direction the error model measures) and the smaller as res_iy / res_t. */
void sw_setup_error_config(const swarp_setup_options* o, double theta, double near, double far,
                           swarp_error_config* cfg) {
    uint32_t mw, mh;
    sw_setup_map_size(o, &mw, &mh);
    const uint32_t sw = o->screen_width ? o->screen_width : SW_DEFAULT_SCREEN_W;
    const uint32_t sh = o->screen_height ? o->screen_height : SW_DEFAULT_SCREEN_H;
    memset(cfg, 0, sizeof *cfg);
    cfg->z_near = near;
    cfg->z_far = far;
    cfg->theta = theta;
    cfg->res_ix = sw > sh ? sw : sh;
    cfg->res_iy = sw > sh ? sh : sw;
    cfg->res_s = mw > mh ? mw : mh;
    cfg->res_t = mw > mh ? mh : mw;
}
