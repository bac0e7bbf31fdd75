/* shadow.c -- technique -> light matrices.
 *
 * The library computes every shadow matrix: swarp_setup (uniform, LiSPSM
 * variants, PSM), swarp_cascade_setup (PSSM with or without LiSPSM),
 * swarp_split_* + swarp_stabilize_directional (stabilised cascades),
 * swarp_cube_faces (PSM cube maps), swarp_lixel_* (plane-stabilised maps)
 * and swarp_error_* (the predicted m_x, m_z).  This file only chooses
 * options and collects the results; nothing in the demo computes shadow
 * maths of its own. */
#include "shadow.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "shadowwarp_cglm.h"

static const char* const tech_names[DEMO_TECH_COUNT] = {
    "uniform", "lispsm", "repar", "gmnpr", "pseudo", "psm", "psm-cube",
    "pssm",    "pssm-lispsm", "pssm-stable", "lixel"};

int demo_technique_is_split(demo_technique t) {
    return t == DEMO_TECH_PSSM || t == DEMO_TECH_PSSM_LISPSM || t == DEMO_TECH_PSSM_STABLE;
}

const char* demo_technique_name(demo_technique t) {
    return (unsigned)t < DEMO_TECH_COUNT ? tech_names[t] : "?";
}

int demo_technique_parse(const char* name) {
    for (int i = 0; i < DEMO_TECH_COUNT; ++i)
        if (strcmp(name, tech_names[i]) == 0) return i;
    return -1;
}

static const char* const scheme_names[DEMO_SCHEME_COUNT] = {"practical", "uniform", "log",
                                                             "pseudo"};

const char* demo_scheme_name(demo_scheme s) {
    return (unsigned)s < DEMO_SCHEME_COUNT ? scheme_names[s] : "?";
}

int demo_scheme_parse(const char* name, double* lambda, double* np, double* fp) {
    if (strncmp(name, "pseudo:", 7) == 0) {
        /* n_p, f_p as fractions of the range, as swarp_split_options has them */
        *lambda = 0.5;
        int k = sscanf(name + 7, "%lf,%lf,%lf", np, fp, lambda);
        if (k < 2 || !(*np >= 0 && *fp >= 0 && *np + *fp < 1 && *lambda >= 0 && *lambda <= 1))
            return -1;
        return DEMO_SCHEME_PSEUDO;
    }
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
    return (unsigned)t < DEMO_TECH_COUNT;
}

/* The viewer's view-projection (world -> clip) in double, from the
 * renderer's own cglm matrices. */
static void viewer_matrix(const swarp_camera* cam, swarp_mat4* out) {
    vec3 eye = {(float)cam->eye.x, (float)cam->eye.y, (float)cam->eye.z};
    vec3 dir = {(float)cam->dir.x, (float)cam->dir.y, (float)cam->dir.z};
    vec3 up = {(float)cam->up.x, (float)cam->up.y, (float)cam->up.z};
    mat4 view, proj;
    glm_look(eye, dir, up, view);
    glm_perspective((float)cam->fovy, (float)cam->aspect, (float)cam->z_near, (float)cam->z_far, proj);
    swarp_mat4 v, p;
    swarp_cglm_mat4_to_swarp(view, &v);
    swarp_cglm_mat4_to_swarp(proj, &p);
    swarp_mat4_mul(&p, &v, out);
}

/* One plane of interest [LIXEL]: M_l from the viewer matrix, restricted to
 * the rays through the plane's rectangle inside the view (Fig. 6), scaled
 * down only if the rectangle would not fit the map, and factored into the
 * clip matrix GLP the shadow pass renders with.  0 on success. */
static int lixel_map(const swarp_mat4* M_v, const demo_shadow_request* req,
                     const swarp_light* light, const swarp_plane* plane,
                     const swarp_vec3 rect[4], swarp_mat4* out_GLP, int out_vp[2],
                     swarp_status* out_status) {
    swarp_mat4 M_l, M_r, GLV, GLP;
    swarp_status st = swarp_lixel_matrix(M_v, (uint32_t)req->screen_w, (uint32_t)req->screen_h,
                                         light, plane, NULL, &M_l, NULL);
    if (swarp_status_is_error(st)) {
        *out_status = st;
        return -1;
    }
    swarp_vec4 C[4];
    for (int i = 0; i < 4; ++i) C[i] = (swarp_vec4){rect[i].x, rect[i].y, rect[i].z, 1.0};
    swarp_lixel_restrict_options ro;
    memset(&ro, 0, sizeof ro);
    ro.view_width = (uint32_t)req->screen_w;
    ro.view_height = (uint32_t)req->screen_h;
    swarp_lixel_rect r;
    swarp_status st2 = swarp_lixel_restrict(&M_l, C, 4, &ro, &r, NULL, &M_r);
    if (!swarp_status_is_error(st2) &&
        (r.width > (uint32_t)req->map_res || r.height > (uint32_t)req->map_res)) {
        /* fewer lixels than pixels: the largest scale that fits the map */
        double sc = (double)req->map_res / (double)(r.width > r.height ? r.width : r.height);
        ro.scale_x = ro.scale_y = 0.999 * sc;
        st2 = swarp_lixel_restrict(&M_l, C, 4, &ro, &r, NULL, &M_r);
    }
    if (swarp_status_is_error(st2)) {
        *out_status = st2;
        return -1;
    }
    st2 = swarp_lixel_factor(&M_r, r.width, r.height, SWARP_DEPTH_NEG_ONE_TO_ONE, 0.0, &GLV, &GLP);
    if (swarp_status_is_error(st2)) {
        *out_status = st2;
        return -1;
    }
    *out_GLP = GLP;
    out_vp[0] = (int)r.width;
    out_vp[1] = (int)r.height;
    *out_status = st;
    return 0;
}

/* The library's options for a technique (the parameter choice of the
 * LiSPSM variants; the PSSM techniques use the same per split). */
static void setup_options(const demo_shadow_request* req, demo_technique t,
                          swarp_setup_options* out) {
    swarp_setup_options opt;
    memset(&opt, 0, sizeof opt);
    opt.technique = SWARP_TECHNIQUE_UNIFORM;
    opt.map_width = opt.map_height = (uint32_t)req->map_res;
    opt.screen_width = (uint32_t)req->screen_w;
    opt.screen_height = (uint32_t)req->screen_h;
    switch (t) {
    case DEMO_TECH_LISPSM:
    case DEMO_TECH_PSSM_LISPSM:
        opt.technique = SWARP_TECHNIQUE_LISPSM;
        opt.param = SWARP_WARP_PARAM_NOPT;
        break;
    case DEMO_TECH_REPAR:
        opt.technique = SWARP_TECHNIQUE_LISPSM;
        opt.param = SWARP_WARP_PARAM_NREPAR;
        break;
    case DEMO_TECH_GMNPR:
        opt.technique = SWARP_TECHNIQUE_LISPSM;
        opt.param = SWARP_WARP_PARAM_GMNPR;
        break;
    case DEMO_TECH_PSEUDO:
        opt.technique = SWARP_TECHNIQUE_LISPSM;
        opt.param = SWARP_WARP_PARAM_PSEUDO;
        opt.pseudo_near = req->pseudo_near;
        opt.pseudo_far = req->pseudo_far;
        break;
    case DEMO_TECH_PSM:
        opt.technique = SWARP_TECHNIQUE_PSM;
        break;
    default:
        break;
    }
    if (req->nprime_measured && opt.technique == SWARP_TECHNIQUE_LISPSM) {
        opt.param = SWARP_WARP_PARAM_DEFAULT; /* = SWARP_WARP_PARAM_MEASURED */
        opt.pseudo_near = opt.pseudo_far = 0.0;
    }
    *out = opt;
}

/* The map of swarp_setup's pipeline with the view-aligned light basis of
 * swarp_focus_light_view ([RHS] §3.2.1, blended toward the camera's right
 * vector near parallel light) instead of the setup's minimum-area rotation
 * there: the adjusted range [RHS] §3.3.1, B, the light view, the LiSPSM
 * warp with the options' closed-form n' (none for uniform), the focus
 * [RHS] (3.1), and swarp_measure_max over the range ∩ S with the map and
 * screen the setup would measure with.  The measured n' needs the setup's
 * region and is not offered here. */
static int aligned_map(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                       const swarp_setup_options* opt, swarp_mat4* out_m, double* out_n,
                       double* out_near, double* out_far, swarp_vec3* body, int* body_count,
                       swarp_measured_error* out_measured, swarp_status* out_status) {
    swarp_vec3 B[SWARP_BODY_MAX_POINTS];
    size_t nb = 0;
    double zn, zf;
    swarp_mat4 L, P, PL, A, M;
    swarp_warp_info info;
    memset(&info, 0, sizeof info);
    info.n_eye = INFINITY;
    swarp_status st = swarp_body_adjusted_range(cam, scene, &zn, &zf);
    if (!swarp_status_is_error(st)) st = swarp_body_points(cam, zn, zf, light, scene, B, SWARP_BODY_MAX_POINTS, &nb);
    if (!swarp_status_is_error(st)) st = swarp_focus_light_view(cam, light, NULL, &L);
    *out_status = st;
    if (!swarp_status_is_error(st) && opt->technique == SWARP_TECHNIQUE_LISPSM) {
        swarp_warp_options w;
        memset(&w, 0, sizeof w);
        w.param = opt->param;
        w.pseudo_near = opt->pseudo_near;
        w.pseudo_far = opt->pseudo_far;
        st = swarp_warp_lispsm(&L, cam, zn, zf, B, nb, NULL, &w, &P, &info);
        if (!swarp_status_is_error(st)) st = swarp_mat4_mul(&P, &L, &PL);
    } else {
        PL = L;
    }
    if (!swarp_status_is_error(st)) st = swarp_focus_fit(&PL, B, nb, NULL, 0, opt->depth_range, &A);
    if (!swarp_status_is_error(st)) st = swarp_mat4_mul(&A, &PL, &M);
    swarp_measure_res res = {opt->screen_width, opt->screen_height, opt->map_width, opt->map_height};
    if (!swarp_status_is_error(st))
        st = swarp_measure_max(cam, zn, zf, light, scene, &M, &res, NULL, out_measured);
    if (swarp_status_is_error(st)) {
        fprintf(stderr, "demo: the aligned-basis map: %s\n", swarp_status_string(st));
        *out_status = st;
        if (body_count) *body_count = 0;
        return -1;
    }
    if (body) memcpy(body, B, nb * sizeof *B);
    if (body_count) *body_count = body ? (int)nb : 0;
    *out_m = M;
    *out_n = info.n_eye;
    *out_near = zn;
    *out_far = zf;
    return 0;
}

/* One map over the view's adjusted range ([RHS] §3.3.1): the library's
 * swarp_setup for the technique, with the points of B when asked for. */
static int conventional_map(const swarp_camera* cam, const swarp_light* light,
                            const swarp_aabb* scene, const demo_shadow_request* req,
                            demo_technique t, swarp_mat4* out_m, double* out_n, double* out_near, double* out_far,
                            swarp_vec3* body, int* body_count, swarp_measured_error* out_measured,
                            swarp_status* out_status) {
    swarp_setup_options opt;
    setup_options(req, t, &opt);
    if (req->basis_aligned) {
        if (opt.technique == SWARP_TECHNIQUE_PSM || req->nprime_measured) {
            fprintf(stderr, "demo: --basis aligned takes uniform or a closed-form LiSPSM\n");
            return -1;
        }
        swarp_measured_error m;
        if (aligned_map(cam, light, scene, &opt, out_m, out_n, out_near, out_far, body, body_count, &m,
                        out_status))
            return -1;
        if (out_measured) *out_measured = m;
        return 0;
    }
    swarp_setup_result res;
    size_t nb = 0;
    _Static_assert(DEMO_MAX_BODY >= SWARP_BODY_MAX_POINTS, "room for every point of B");
    swarp_status st = swarp_setup(cam, light, scene, &opt, &res, body, body ? DEMO_MAX_BODY : 0,
                                  body ? &nb : NULL);
    if (body_count) *body_count = swarp_status_is_error(st) ? 0 : (int)nb;
    *out_status = st;
    if (swarp_status_is_error(st)) {
        fprintf(stderr, "demo: swarp_setup (%s): %s\n", demo_technique_name(t),
                swarp_status_string(st));
        return -1;
    }
    *out_m = res.matrix;
    *out_n = res.n_eye;
    *out_near = res.view_near;
    *out_far = res.view_far;
    if (out_measured) *out_measured = res.measured;
    return 0;
}

static const char* matrix_source(demo_technique t) {
    if (t == DEMO_TECH_PSSM_STABLE) return "library (swarp_split_*, swarp_stabilize_directional)";
    if (demo_technique_is_split(t)) return "library (swarp_cascade_setup)";
    return "library (swarp_setup)";
}

/* The maps of lixel and cube-face configurations each cover the whole
 * adjusted range [near, far] (no eye-depth splits), are picked per fragment
 * by `select`, clamp depth for casters in front of the near plane, and lie
 * outside Lloyd's model of a warped map along the view. */
static void whole_view_maps(demo_shadow* sh, int count, demo_select select, swarp_status status,
                            const char* source) {
    sh->count = count;
    sh->split[0] = sh->z_near;
    sh->split[1] = sh->z_far;
    sh->select = select;
    sh->depth_clamp = 1;
    sh->model_applies = 0;
    sh->status = status;
    sh->source = source;
}

/* [LIXEL] §3 for the room corner: a map for the floor, one for the wall,
 * and a conventional fallback map for everything else.  sh holds the
 * defaults of demo_shadow_setup. */
static int setup_lixel(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                       const demo_shadow_request* req, demo_shadow* sh) {
    swarp_status st = SWARP_OK;
    demo_room room;
    demo_scene_room(&room);
    swarp_mat4 M_v;
    viewer_matrix(cam, &M_v);
    int n = 0;
    const swarp_plane* planes[2] = {&room.floor, &room.wall};
    const swarp_vec3* rects[2] = {room.floor_rect, room.wall_rect};
    for (int k = 0; k < 2; ++k) {
        swarp_status sk;
        if (lixel_map(&M_v, req, light, planes[k], rects[k], &sh->light[n], sh->viewport[n], &sk) == 0)
            ++n;
        if (sk != SWARP_OK && st == SWARP_OK) st = sk; /* first note or error */
    }
    swarp_status sf;
    if (conventional_map(cam, light, scene, req, DEMO_TECH_UNIFORM, &sh->light[n],
                         &sh->n_prime[n], &sh->z_near, &sh->z_far, NULL, NULL, NULL, &sf))
        return -1;
    whole_view_maps(sh, n + 1, DEMO_SELECT_LIXEL, st != SWARP_OK ? st : sf,
                    n == 2 ? "library (swarp_lixel_* + uniform fallback)"
                           : "library (swarp_lixel_*: a plane failed; + uniform fallback)");
    return 0;
}

/* [KOZ] §14.2.2: the adjusted view range from the setup, the camera's
 * post-projective space over it, the light there, and one map per
 * back-facing face of the unit cube. */
static int setup_cube(const swarp_camera* cam, const swarp_light* light, const swarp_aabb* scene,
                      const demo_shadow_request* req, demo_shadow* sh) {
    swarp_status st = SWARP_OK;
    double nprime;
    if (conventional_map(cam, light, scene, req, DEMO_TECH_UNIFORM, &sh->light[0],
                         &nprime, &sh->z_near, &sh->z_far, sh->body, &sh->body_count, NULL, &st))
        return -1;
    swarp_camera c2 = *cam;
    c2.z_near = sh->z_near;
    c2.z_far = sh->z_far;
    viewer_matrix(&c2, &sh->cube_camera);
    swarp_vec3 lp = light->type == SWARP_LIGHT_POINT ? light->position : light->direction;
    swarp_vec4 hl;
    swarp_mat4_transform(&sh->cube_camera, &lp, &hl);
    if (light->type != SWARP_LIGHT_POINT) {
        /* (-d, 0): C (-d, 0) = -(C (d, 1) - C (0, 1)) */
        swarp_vec3 zero = {0, 0, 0};
        swarp_vec4 h0;
        swarp_mat4_transform(&sh->cube_camera, &zero, &h0);
        hl = (swarp_vec4){-(hl.x - h0.x), -(hl.y - h0.y), -(hl.z - h0.z), -(hl.w - h0.w)};
    }
    sh->cube_light = hl;
    swarp_cube_face faces[SWARP_CUBE_MAX_FACES];
    size_t nf = 0;
    swarp_status sc = swarp_cube_faces(&hl, NULL, faces, SWARP_CUBE_MAX_FACES, &nf);
    if (swarp_status_is_error(sc)) {
        fprintf(stderr, "demo: swarp_cube_faces: %s\n", swarp_status_string(sc));
        return -1;
    }
    for (size_t i = 0; i < nf; ++i) {
        swarp_mat4_mul(&faces[i].view_proj, &sh->cube_camera, &sh->light[i]);
        sh->cube_normal[i] = faces[i].normal;
        sh->cube_distance[i] = faces[i].distance;
        sh->cube_face[i] = faces[i].face;
        sh->n_prime[i] = NAN;
    }
    whole_view_maps(sh, (int)nf, DEMO_SELECT_CUBE, sc != SWARP_OK ? sc : st,
                    "library (swarp_setup's range + swarp_cube_faces)");
    return 0;
}

/* The measured error of the stabilised maps the demo renders: per split
 * swarp_measure_max over the split frustum ∩ S with that split's matrix,
 * and the worst split's maxima (as swarp_cascade_result.measured combines
 * its splits: maxima and the worst point, samples and outside summed). */
static int measure_stable_maps(const swarp_camera* cam, const swarp_light* light,
                               const swarp_aabb* scene, const demo_shadow_request* req,
                               demo_shadow* sh) {
    swarp_measure_res mr = {(uint32_t)req->screen_w, (uint32_t)req->screen_h,
                            (uint32_t)req->map_res, (uint32_t)req->map_res};
    swarp_measured_error all;
    memset(&all, 0, sizeof all);
    for (int i = 0; i < sh->count; ++i) {
        swarp_measured_error m;
        swarp_status sm = swarp_measure_max(cam, sh->split[i], sh->split[i + 1], light, scene,
                                            &sh->light[i], &mr, NULL, &m);
        if (sm == SWARP_ERR_BODY_EMPTY) continue; /* the split sees no part of S */
        if (swarp_status_is_error(sm)) {
            fprintf(stderr, "demo: swarp_measure_max (split %d): %s\n", i,
                    swarp_status_string(sm));
            return -1;
        }
        all.max_m_s = fmax(all.max_m_s, m.max_m_s);
        all.max_m_t = fmax(all.max_m_t, m.max_m_t);
        if (m.max_sigma > all.max_sigma || all.samples == 0) {
            all.max_sigma = m.max_sigma;
            all.at = m.at;
        }
        all.samples += m.samples;
        all.outside += m.outside;
    }
    sh->measured = all;
    sh->have_measured = all.samples > 0;
    return 0;
}

/* [RHS] §3.5 exact solution per split: the split frustum's minimal
 * sphere, texel-snapped.  The splits divide the CAMERA's fixed [near, far]:
 * swarp_cascade_setup would split the adjusted range of §3.3.1, which moves
 * with the camera, so the spheres and their texels would change size every
 * frame (measured: 0.4 texel of drift per frame against 0.0000 here; see
 * --frames).  *st: the first note. */
static int setup_stable(const swarp_camera* cam, const swarp_light* light,
                        const swarp_aabb* scene, const demo_shadow_request* req, demo_shadow* sh,
                        swarp_status* st) {
    sh->z_near = cam->z_near;
    sh->z_far = cam->z_far;
    size_t n = 0;
    swarp_status ss;
    if (req->scheme == DEMO_SCHEME_UNIFORM)
        ss = swarp_split_uniform(sh->z_near, sh->z_far, (uint32_t)sh->count, sh->split,
                                 DEMO_MAX_SPLITS + 1, &n);
    else if (req->scheme == DEMO_SCHEME_LOG)
        ss = swarp_split_log(sh->z_near, sh->z_far, (uint32_t)sh->count, sh->split, DEMO_MAX_SPLITS + 1,
                             &n);
    else if (req->scheme == DEMO_SCHEME_PSEUDO)
        ss = swarp_split_pseudo(sh->z_near, sh->z_far, sh->z_near + req->scheme_np * (sh->z_far - sh->z_near),
                                sh->z_far - req->scheme_fp * (sh->z_far - sh->z_near), req->scheme_lambda,
                                (uint32_t)sh->count, sh->split, DEMO_MAX_SPLITS + 1, &n);
    else
        ss = swarp_split_practical(sh->z_near, sh->z_far, req->scheme_lambda, (uint32_t)sh->count,
                                   sh->split, DEMO_MAX_SPLITS + 1, &n);
    if (swarp_status_is_error(ss) || n != (size_t)sh->count + 1) {
        fprintf(stderr, "demo: split scheme: %s\n", swarp_status_string(ss));
        return -1;
    }
    for (int i = 0; i < sh->count; ++i) {
        swarp_stabilize_options so;
        memset(&so, 0, sizeof so);
        so.mode = SWARP_STABILIZE_SPHERE;
        swarp_status si = swarp_stabilize_directional(cam, sh->split[i], sh->split[i + 1],
                                                      &light->direction, NULL, 0, scene,
                                                      (uint32_t)req->map_res, &so,
                                                      &sh->light[i], NULL);
        if (swarp_status_is_error(si)) {
            fprintf(stderr, "demo: swarp_stabilize_directional: %s\n", swarp_status_string(si));
            return -1;
        }
        sh->n_prime[i] = INFINITY;
        if (si != SWARP_OK && *st == SWARP_OK) *st = si;
    }
    return measure_stable_maps(cam, light, scene, req, sh);
}

/* [RHS] §3.3-3.4 in one library call: adjusted range, split distances,
 * per split B_i and its matrix.  *st: the call's note. */
static int setup_cascade(const swarp_camera* cam, const swarp_light* light,
                         const swarp_aabb* scene, const demo_shadow_request* req,
                         demo_technique t, demo_shadow* sh, swarp_status* st) {
    swarp_cascade_options co;
    memset(&co, 0, sizeof co);
    setup_options(req, t == DEMO_TECH_PSSM_LISPSM ? DEMO_TECH_LISPSM : DEMO_TECH_UNIFORM,
                  &co.setup);
    co.split.count = (uint32_t)sh->count;
    co.split.scheme = req->scheme == DEMO_SCHEME_UNIFORM ? SWARP_SCHEME_UNIFORM
                      : req->scheme == DEMO_SCHEME_LOG   ? SWARP_SCHEME_LOG
                      : req->scheme == DEMO_SCHEME_PSEUDO ? SWARP_SCHEME_PSEUDO
                                                          : SWARP_SCHEME_PRACTICAL;
    co.split.lambda = req->scheme_lambda;
    co.split.pseudo_near = req->scheme_np;
    co.split.pseudo_far = req->scheme_fp;
    swarp_cascade_result cr;
    swarp_cascade_split cs[SWARP_CASCADE_MAX_SPLITS];
    size_t n = 0;
    swarp_status sc = swarp_cascade_setup(cam, light, scene, &co, &cr, cs,
                                          SWARP_CASCADE_MAX_SPLITS, &n);
    if (swarp_status_is_error(sc) || n != (size_t)sh->count) {
        fprintf(stderr, "demo: swarp_cascade_setup (%s): %s\n", demo_technique_name(t),
                swarp_status_string(sc));
        return -1;
    }
    sh->z_near = cr.view_near;
    sh->z_far = cr.view_far;
    for (int i = 0; i <= sh->count; ++i) sh->split[i] = cr.splits[i];
    for (int i = 0; i < sh->count; ++i) {
        sh->light[i] = cs[i].matrix;
        sh->n_prime[i] = cs[i].n_eye;
    }
    sh->measured = cr.measured;
    sh->have_measured = 1;
    if (sc != SWARP_OK) *st = sc;
    return 0;
}

/* The predicted worst error of the whole configuration [RHS] (2.3)-(2.8),
 * piecewise for splits; left NAN when the model cannot say. */
static void predict_max_error(const swarp_camera* cam, const demo_shadow_request* req,
                              demo_shadow* sh) {
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = sh->z_near;
    cfg.z_far = sh->z_far;
    cfg.theta = 0.5 * cam->fovy;
    cfg.res_ix = req->screen_w;
    cfg.res_iy = req->screen_h;
    cfg.res_s = cfg.res_t = req->map_res;
    double mx, mz;
    if (!swarp_status_is_error(swarp_error_split_max(&cfg, sh->split, sh->n_prime,
                                                     (size_t)sh->count, NULL, NULL, &mx, &mz))) {
        sh->predicted_max_mx = mx;
        sh->predicted_max_mz = mz;
    }
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
    sh.select = req->select == DEMO_SELECT_BEST ? DEMO_SELECT_BEST : DEMO_SELECT_DEPTH;
    sh.model_applies = 1;
    sh.predicted_max_mx = sh.predicted_max_mz = NAN;
    for (int i = 0; i < DEMO_MAX_SPLITS; ++i) sh.viewport[i][0] = sh.viewport[i][1] = req->map_res;
    swarp_status st = SWARP_OK;
    demo_technique t = req->technique;
    if (t == DEMO_TECH_LIXEL || t == DEMO_TECH_PSM_CUBE) {
        int e = t == DEMO_TECH_LIXEL ? setup_lixel(cam, light, scene, req, &sh)
                                     : setup_cube(cam, light, scene, req, &sh);
        if (e) return -1;
        *out = sh;
        return 0;
    }
    int pssm = demo_technique_is_split(t);
    sh.count = pssm ? req->splits : 1;
    if (sh.count < 1 || sh.count > DEMO_MAX_SPLITS) return -1;
    if (t == DEMO_TECH_PSSM_STABLE) {
        if (setup_stable(cam, light, scene, req, &sh, &st)) return -1;
    } else if (pssm) {
        if (setup_cascade(cam, light, scene, req, t, &sh, &st)) return -1;
    } else {
        /* one map over the view's adjusted range [RHS] §3.3.1 */
        if (conventional_map(cam, light, scene, req, t, &sh.light[0], &sh.n_prime[0], &sh.z_near,
                             &sh.z_far, sh.body, &sh.body_count, &sh.measured, &st))
            return -1;
        sh.have_measured = 1;
        sh.split[0] = sh.z_near;
        sh.split[1] = sh.z_far;
    }
    predict_max_error(cam, req, &sh);
    sh.status = st;
    sh.source = req->basis_aligned && sh.count == 1
                    ? "library (swarp_focus_light_view, swarp_warp_lispsm, swarp_focus_fit)"
                    : matrix_source(t);
    *out = sh;
    return 0;
}

int demo_predict(const demo_shadow* sh, double fovy, int w, int h, int map_res, double z,
                 double* out_mx, double* out_mz) {
    if (!sh->model_applies) {
        *out_mx = *out_mz = NAN;
        return -1;
    }
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.z_near = sh->z_near;
    cfg.z_far = sh->z_far;
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
}
