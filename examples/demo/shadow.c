/* shadow.c -- technique -> light matrices.
 *
 * The library computes every shadow matrix.  Until the geometry stage (the
 * setup call) and the splits stage are on main, this file holds ONE
 * temporary stand-in, marked TEMPORARY below: a light-space aligned
 * orthographic fit of the view frustum (or of each split frustum).  It is
 * replaced by the library's setup call as soon as that lands; nothing else
 * in the demo computes shadow maths. */
#include "shadow.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char* const tech_names[DEMO_TECH_COUNT] = {
    "uniform", "lispsm", "repar", "gmnpr", "psm", "pssm", "pssm-lispsm", "lixel"};

const char* demo_technique_name(demo_technique t) {
    return (unsigned)t < DEMO_TECH_COUNT ? tech_names[t] : "?";
}

int demo_technique_parse(const char* name) {
    for (int i = 0; i < DEMO_TECH_COUNT; ++i)
        if (strcmp(name, tech_names[i]) == 0) return i;
    return -1;
}

static const char* const scheme_names[DEMO_SCHEME_COUNT] = {"practical", "uniform", "log"};

const char* demo_scheme_name(demo_scheme s) {
    return (unsigned)s < DEMO_SCHEME_COUNT ? scheme_names[s] : "?";
}

int demo_scheme_parse(const char* name, double* lambda) {
    if (strncmp(name, "practical", 9) == 0) {
        *lambda = 0.5;
        if (name[9] == ':') {
            char* end;
            *lambda = strtod(name + 10, &end);
            if (*end || !(*lambda >= 0 && *lambda <= 1)) return -1;
        } else if (name[9]) {
            return -1;
        }
        return DEMO_SCHEME_PRACTICAL;
    }
    if (strcmp(name, "uniform") == 0) return DEMO_SCHEME_UNIFORM;
    if (strcmp(name, "log") == 0) return DEMO_SCHEME_LOG;
    return -1;
}

int demo_technique_available(demo_technique t) {
    /* TEMPORARY: only what the stand-in fit can do. */
    return t == DEMO_TECH_UNIFORM || t == DEMO_TECH_PSSM;
}

/* ------------------------------------------------------------------------ */
/* TEMPORARY stand-in until the library's setup call is on main.            */
/* ------------------------------------------------------------------------ */
typedef struct tv3 { double x, y, z; } tv3;
static tv3 t_mk(double x, double y, double z) { tv3 r = {x, y, z}; return r; }
static tv3 t_add(tv3 a, tv3 b) { return t_mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static tv3 t_scl(tv3 a, double s) { return t_mk(a.x * s, a.y * s, a.z * s); }
static double t_dot(tv3 a, tv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static tv3 t_cross(tv3 a, tv3 b) {
    return t_mk(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static tv3 t_norm(tv3 a) { return t_scl(a, 1.0 / sqrt(t_dot(a, a))); }

static void temp_fit(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                     double d0, double d1, swarp_mat4* out) {
    tv3 f = t_norm(t_mk(cam->dir.x, cam->dir.y, cam->dir.z));
    tv3 r = t_norm(t_cross(f, t_mk(cam->up.x, cam->up.y, cam->up.z)));
    tv3 u = t_cross(r, f);
    tv3 ld = t_norm(t_mk(light->direction.x, light->direction.y, light->direction.z));
    /* light view: looks along ld; its up is the view direction projected
     * perpendicular to ld (light-space alignment), any perpendicular if the
     * two are parallel */
    tv3 lb = t_scl(ld, -1.0);
    tv3 lu = t_add(f, t_scl(ld, -t_dot(f, ld)));
    if (t_dot(lu, lu) < 1e-12) lu = fabs(ld.x) < 0.9 ? t_mk(1, 0, 0) : t_mk(0, 1, 0);
    lu = t_norm(t_add(lu, t_scl(ld, -t_dot(lu, ld))));
    tv3 lr = t_cross(lu, lb);
    double ty = tan(0.5 * cam->fovy), tx = ty * cam->aspect;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    tv3 eye = t_mk(cam->eye.x, cam->eye.y, cam->eye.z);
    for (int i = 0; i < 8; ++i) {
        double d = (i & 4) ? d1 : d0;
        tv3 p = t_add(eye, t_scl(f, d));
        p = t_add(p, t_scl(r, ((i & 1) ? 1 : -1) * d * tx));
        p = t_add(p, t_scl(u, ((i & 2) ? 1 : -1) * d * ty));
        double q[3] = {t_dot(p, lr), t_dot(p, lu), t_dot(p, lb)};
        for (int k = 0; k < 3; ++k) {
            if (q[k] < lo[k]) lo[k] = q[k];
            if (q[k] > hi[k]) hi[k] = q[k];
        }
    }
    /* depth: the whole scene box, so every caster is in the map */
    for (int i = 0; i < 8; ++i) {
        tv3 p = t_mk((i & 1) ? scene->max.x : scene->min.x, (i & 2) ? scene->max.y : scene->min.y,
                     (i & 4) ? scene->max.z : scene->min.z);
        double q = t_dot(p, lb);
        if (q < lo[2]) lo[2] = q;
        if (q > hi[2]) hi[2] = q;
    }
    /* ortho(l, r, b, t, near = -hi_z, far = -lo_z) * view */
    double sx = 2.0 / (hi[0] - lo[0]), sy = 2.0 / (hi[1] - lo[1]);
    double sz = -2.0 / (hi[2] - lo[2]);
    double cx = -(hi[0] + lo[0]) / (hi[0] - lo[0]), cy = -(hi[1] + lo[1]) / (hi[1] - lo[1]);
    double near = -hi[2], far = -lo[2];
    double cz = -(far + near) / (far - near);
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    tv3 ax[3] = {lr, lu, lb};
    double s[3] = {sx, sy, sz}, c[3] = {cx, cy, cz};
    for (int row = 0; row < 3; ++row) {
        m.m[0 * 4 + row] = s[row] * ax[row].x;
        m.m[1 * 4 + row] = s[row] * ax[row].y;
        m.m[2 * 4 + row] = s[row] * ax[row].z;
        m.m[3 * 4 + row] = c[row];
    }
    m.m[15] = 1.0;
    *out = m;
}

/* Split distances C_0..C_K over [near, far] from the library's schemes
 * [RHS] (3.6)-(3.8). */
static int split_distances(const demo_shadow_request* req, double near, double far, int k,
                           double* out) {
#ifdef DEMO_HAVE_ERROR_MODEL
    size_t n = 0;
    swarp_status st;
    if (req->scheme == DEMO_SCHEME_UNIFORM)
        st = swarp_split_uniform(near, far, (uint32_t)k, out, DEMO_MAX_SPLITS + 1, &n);
    else if (req->scheme == DEMO_SCHEME_LOG)
        st = swarp_split_log(near, far, (uint32_t)k, out, DEMO_MAX_SPLITS + 1, &n);
    else
        st = swarp_split_practical(near, far, req->scheme_lambda, (uint32_t)k, out,
                                   DEMO_MAX_SPLITS + 1, &n);
    if (swarp_status_is_error(st) || n != (size_t)k + 1) {
        fprintf(stderr, "demo: split scheme: %s\n", swarp_status_string(st));
        return -1;
    }
    return 0;
#else
    /* TEMPORARY until the core stage (swarp_split_*) is linked in */
    for (int i = 0; i <= k; ++i) {
        double t = (double)i / k;
        double c_uni = near + (far - near) * t;
        double c_log = near * pow(far / near, t);
        double lambda = req->scheme == DEMO_SCHEME_UNIFORM ? 0.0
                        : req->scheme == DEMO_SCHEME_LOG   ? 1.0
                                                           : req->scheme_lambda;
        out[i] = lambda * c_log + (1 - lambda) * c_uni;
    }
    out[0] = near;
    out[k] = far;
    return 0;
#endif
}

int demo_shadow_setup(const swarp_camera* cam, const swarp_light* light,
                      const swarp_aabb* scene, const demo_shadow_request* req,
                      demo_shadow* out) {
    if (!demo_technique_available(req->technique)) {
        fprintf(stderr, "demo: technique %s is not available in this build\n",
                demo_technique_name(req->technique));
        return -1;
    }
    demo_shadow sh;
    memset(&sh, 0, sizeof sh);
    sh.near = cam->near;
    sh.far = cam->far;
    sh.count = req->technique == DEMO_TECH_PSSM ? req->splits : 1;
    if (sh.count < 1 || sh.count > DEMO_MAX_SPLITS) return -1;
    if (split_distances(req, sh.near, sh.far, sh.count, sh.split)) return -1;
    for (int i = 0; i < sh.count; ++i) {
        temp_fit(cam, light, scene, sh.split[i], sh.split[i + 1], &sh.light[i]);
        sh.n_prime[i] = INFINITY;
    }
    sh.predicted_max_mx = NAN;
    sh.predicted_max_mz = NAN;
    sh.status = SWARP_OK;
    sh.source = "demo stand-in (temporary ortho fit)";
    *out = sh;
    return 0;
}

int demo_have_error_model(void) {
#ifdef DEMO_HAVE_ERROR_MODEL
    return 1;
#else
    return 0;
#endif
}

int demo_predict(const demo_shadow* sh, double fovy, int w, int h, int map_res, double z,
                 double* out_mx, double* out_mz) {
#ifdef DEMO_HAVE_ERROR_MODEL
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.near = sh->near;
    cfg.far = sh->far;
    cfg.theta = 0.5 * fovy;
    cfg.res_ix = w;
    cfg.res_iy = h;
    cfg.res_s = map_res;
    cfg.res_t = map_res;
    double mx, mz;
    swarp_status st = swarp_error_split_curve(&cfg, sh->split, sh->n_prime, (size_t)sh->count,
                                              &z, 1, &mx, &mz);
    if (swarp_status_is_error(st)) return -1;
    *out_mx = mx;
    *out_mz = mz;
    return 0;
#else
    (void)sh; (void)fovy; (void)w; (void)h; (void)map_res; (void)z;
    *out_mx = NAN;
    *out_mz = NAN;
    return -1;
#endif
}
