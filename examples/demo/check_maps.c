/* check_maps.c -- demo-check: the rendered shadow against the geometric one
 * (iou), the measured sampling rate against Lloyd's model (measure) and the
 * shader's map selection against the library's CPU references (select). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checks.h"

/* 2-D convex hull (monotone chain) of n points; returns the hull size. */
static int hull2(double (*p)[2], int n, double (*out)[2]) {
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && (p[j][0] < p[j - 1][0] ||
                                  (p[j][0] == p[j - 1][0] && p[j][1] < p[j - 1][1]));
             --j) {
            double t0 = p[j][0], t1 = p[j][1];
            p[j][0] = p[j - 1][0];
            p[j][1] = p[j - 1][1];
            p[j - 1][0] = t0;
            p[j - 1][1] = t1;
        }
    int k = 0;
#define CROSS(o, a, b) (((a)[0] - (o)[0]) * ((b)[1] - (o)[1]) - ((a)[1] - (o)[1]) * ((b)[0] - (o)[0]))
    for (int i = 0; i < n; ++i) {
        while (k >= 2 && CROSS(out[k - 2], out[k - 1], p[i]) <= 0) --k;
        out[k][0] = p[i][0];
        out[k][1] = p[i][1];
        ++k;
    }
    for (int i = n - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && CROSS(out[k - 2], out[k - 1], p[i]) <= 0) --k;
        out[k][0] = p[i][0];
        out[k][1] = p[i][1];
        ++k;
    }
    return k - 1;
}

static int inside_hull(double (*h)[2], int n, double x, double y) {
    for (int i = 0; i < n; ++i) {
        double q[2] = {x, y};
        if (CROSS(h[i], h[(i + 1) % n], q) < 0) return 0;
    }
    return 1;
}

int demo_check_iou(const demo_options* o) {
    demo_scene scene;
    swarp_aabb caster;
    if (demo_scene_box(&scene, &caster)) return 1;
    demo_view v;
    demo_sized_view(o, &v);
    v.cam.eye = (swarp_vec3){0, 30, 45};
    v.cam.dir = (swarp_vec3){0, -0.75, -1};
    v.cam.up = (swarp_vec3){0, 1, 0};
    v.cam.fovy = 50 * DEMO_DEG;
    v.cam.aspect = (double)v.w / v.h;
    v.cam.z_near = 1;
    v.cam.z_far = 150;
    v.light.type = SWARP_LIGHT_DIRECTIONAL;
    demo_view_update(&v);
    demo_renderer r;
    if (demo_render_init(&r, &scene, v.w, v.h, o->map, DEMO_MAX_SPLITS)) return 1;
    const demo_technique techs[8] = {DEMO_TECH_UNIFORM, DEMO_TECH_LISPSM, DEMO_TECH_PSSM,
                                     DEMO_TECH_PSM, DEMO_TECH_PSSM_LISPSM, DEMO_TECH_PSSM_STABLE,
                                     DEMO_TECH_GMNPR, DEMO_TECH_PSM_CUBE};
    /* two lights: the first lies behind the viewer as PSM sees it (the
     * camera looks steeply down, the sun is high: SWARP_INFO_PSM_INVERSE,
     * Kozlov's inverse projection, [KOZ] §14.2.1), the second, low and
     * ahead, in front of it (the ordinary PSM) */
    const swarp_vec3 lights[2] = {{0.45, -1, 0.3}, {0.2, -0.5, 1}};
    int fails = 0, ran = 0;
    float* tex = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    float* pos = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    for (int li = 0; li < 2; ++li) {
        v.light.direction = lights[li];
        /* the geometric shadow: the box's corners projected along the light
         * onto y = 0, and their convex hull */
        double pts[8][2], hull[10][2];
        const swarp_vec3 ld = v.light.direction;
        for (int i = 0; i < 8; ++i) {
            double x = (i & 1) ? caster.max.x : caster.min.x;
            double y = (i & 2) ? caster.max.y : caster.min.y;
            double z = (i & 4) ? caster.max.z : caster.min.z;
            double t = -y / ld.y;
            pts[i][0] = x + t * ld.x;
            pts[i][1] = z + t * ld.z;
        }
        int nh = hull2(pts, 8, hull);
        for (int k = 0; k < 8 && tex && pos; ++k) {
            if (!demo_technique_available(techs[k])) {
                printf("iou %-12s not in this build\n", demo_technique_name(techs[k]));
                ++fails;
                continue;
            }
            demo_shadow sh;
            if (demo_setup_for(o, &v, &scene.box, techs[k], 4, &sh)) {
                ++fails;
                continue;
            }
            int errs = demo_render_shadow(&r, &sh, DEMO_FILTER_PCF2, NULL);
            demo_main_params p;
            memset(&p, 0, sizeof p);
            memcpy(p.view, v.view, sizeof p.view);
            memcpy(p.proj, v.proj, sizeof p.proj);
            p.light_dir[0] = (float)ld.x;
            p.light_dir[1] = (float)ld.y;
            p.light_dir[2] = (float)ld.z;
            p.filter = DEMO_FILTER_PCF2;
            p.mode = DEMO_MODE_SHADED;
            p.vw = v.w;
            p.vh = v.h;
            errs += demo_render_main(&r, &sh, &p, NULL);
            demo_render_read_aux(&r, tex, pos);
            long inter = 0, uni = 0, ground = 0;
            for (size_t i = 0; i < (size_t)v.w * v.h; ++i) {
                const float* q = pos + 4 * i;
                if (q[3] < 0 || fabsf(q[1]) > 1e-3f) continue; /* not ground */
                ++ground;
                int rendered = q[3] < 0.5f;
                int geometric = inside_hull(hull, nh, q[0], q[2]);
                inter += rendered && geometric;
                uni += rendered || geometric;
            }
            double iou = uni ? (double)inter / uni : 0;
            int ok = iou >= 0.95 && errs == 0 && uni > 200;
            printf("iou %-12s light %s: %.4f (%ld shadow pixels of %ld ground pixels, gl errors "
                   "%d%s%s) %s\n",
                   demo_technique_name(techs[k]), li ? "2" : "1", iou, uni,
                   ground, errs, sh.status != SWARP_OK ? ", " : "",
                   sh.status != SWARP_OK ? swarp_status_name(sh.status) : "", ok ? "ok" : "FAIL");
            fails += !ok;
            ++ran;
        }
    }
    free(tex);
    free(pos);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails || !ran ? 1 : 0;
}

int demo_check_measure(const demo_options* o) {
    /* overhead light, horizontal camera: Lloyd's model's own setting */
    demo_options q = *o;
    demo_view v;
    demo_sized_view(o, &v);
    if (demo_camera_preset("measure", v.w, v.h, &v.cam)) return 1;
    q.light_elev = 90;
    q.have_light_dir = 0;
    demo_options_light(&q, &v.light);
    demo_view_update(&v);
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 1, &scene, &r)) return 1;
    /* uniform, LiSPSM and PSSM(4), and the other techniques the error
     * model describes */
    const demo_technique techs[8] = {DEMO_TECH_UNIFORM, DEMO_TECH_LISPSM, DEMO_TECH_PSSM,
                                     DEMO_TECH_REPAR,   DEMO_TECH_GMNPR,  DEMO_TECH_PSEUDO,
                                     DEMO_TECH_PSM,     DEMO_TECH_PSSM_LISPSM};
    int fails = 0, ran = 0;
    for (int k = 0; k < 8; ++k) {
        if (!demo_technique_available(techs[k])) {
            printf("measure %-12s not in this build\n", demo_technique_name(techs[k]));
            ++fails;
            continue;
        }
        demo_tech_result res;
        q.filter = DEMO_FILTER_NONE;
        if (demo_run_technique(&q, &r, &v, &scene.box, techs[k], 4, 0, &res)) {
            ++fails;
            continue;
        }
        demo_print_measure(&res);
        int bad = res.gl_errors != 0 || res.nrows < 4;
        int compared = 0;
        double worst = 0;
        for (int i = 0; i < res.nrows; ++i) {
            const demo_measure_row* m = &res.rows[i];
            if (isnan(m->pred_mz)) continue;
            ++compared;
            worst = fmax(worst, fabs(m->ratio_mz - 1));
            if (!(fabs(m->ratio_mz - 1) <= 0.10)) bad = 1;
        }
        printf("measure %-12s %s (%d depth bins compared with the library's m_z, worst |ratio - 1| "
               "%.4f)\n", res.label, bad ? "FAIL" : compared ? "ok" : "no depth bin to compare",
               compared, worst);
        fails += bad;
        ran += compared > 0;
        demo_tech_result_free(&res);
    }
    demo_render_free(&r);
    demo_scene_free(&scene);
    if (fails) return 1;
    return ran ? 0 : DEMO_EXIT_SKIP;
}

/* One case of the selection check: technique, selection, camera and sun
 * (elevation, azimuth in degrees; 0, 0 = --light-angle). */
typedef struct select_case {
    demo_technique t;
    demo_select sel;
    const char* camera;
    double elev, azim;
} select_case;

/* What the pixels of one case said. */
typedef struct select_tally {
    long n, diff;          /**< pixels compared, pixels whose map differs */
    long wn, wdiff, wband; /**< depth case: blend weights compared, differing, in a band */
    int hist[DEMO_MAX_SPLITS];
} select_tally;

/* The blend band of the depth case, a fraction of a split. */
#define SELECT_BAND 0.2

/* The map the library's CPU reference picks for world point q at eye depth
 * z (*want); for the depth selection also the blend weight the shader
 * wrote (texel coordinate's fraction tex_s) against swarp_cascade_blend.
 * Returns the reference's status. */
static swarp_status select_reference(const demo_shadow* sh, const swarp_bias_map* maps,
                                     swarp_vec3 q, double z, float tex_s, uint32_t* want,
                                     select_tally* t) {
    uint32_t depth_i = 0;
    swarp_status st = swarp_cascade_select_depth(sh->split, (size_t)sh->count, z, &depth_i);
    *want = 0;
    if (sh->select == DEMO_SELECT_DEPTH) {
        *want = depth_i;
        uint32_t bi;
        double bw;
        if (!swarp_status_is_error(
                swarp_cascade_blend(sh->split, (size_t)sh->count, z, SELECT_BAND, &bi, &bw)) &&
            bi == depth_i) {
            double got_w = 1.0 - 2.0 * (tex_s - floorf(tex_s));
            ++t->wn;
            t->wband += bw < 1.0;
            t->wdiff += fabs(got_w - bw) > 2e-3;
        }
    } else if (sh->select == DEMO_SELECT_BEST) {
        st = swarp_cascade_select_best(maps, (size_t)sh->count, &q, depth_i, want, NULL);
    } else if (sh->select == DEMO_SELECT_CUBE) {
        /* [KOZ] Listing 14-1 on the CPU: the face of V, mapped to the index
         * of that face's map */
        swarp_vec4 hv;
        swarp_mat4_transform(&sh->cube_camera, &q, &hv);
        swarp_vec3 V = {hv.x / hv.w, hv.y / hv.w, hv.z / hv.w};
        uint32_t face = 99;
        st = swarp_cube_lookup(&sh->cube_light, NULL, &V, &face, NULL, NULL);
        *want = 99;
        for (int i = 0; i < sh->count; ++i)
            if (sh->cube_face[i] == face) *want = (uint32_t)i;
    } else {
        st = swarp_lixel_select(sh->light, (size_t)(sh->count - 1), &q, want);
    }
    return st;
}

/* Every non-sky pixel: the map the shader chose (integer part of the
 * texel target's s) against the CPU reference's. */
static void select_compare(const demo_shadow* sh, const float* tex, const float* pos, size_t npx,
                           select_tally* t) {
    swarp_bias_map maps[DEMO_MAX_SPLITS];
    for (int i = 0; i < sh->count; ++i) {
        memset(&maps[i], 0, sizeof maps[i]);
        maps[i].world_to_clip = sh->light[i];
        maps[i].res_s = sh->viewport[i][0];
        maps[i].res_t = sh->viewport[i][1];
        maps[i].depth = SWARP_DEPTH_NEG_ONE_TO_ONE;
    }
    for (size_t k = 0; k < npx; ++k) {
        if (pos[4 * k + 3] < 0) continue; /* sky */
        swarp_vec3 q = {pos[4 * k], pos[4 * k + 1], pos[4 * k + 2]};
        uint32_t want;
        if (swarp_status_is_error(
                select_reference(sh, maps, q, tex[4 * k + 3], tex[4 * k + 2], &want, t)))
            continue;
        int got = (int)tex[4 * k + 2];
        ++t->n;
        if (got >= 0 && got < DEMO_MAX_SPLITS) t->hist[got]++;
        t->diff += got != (int)want;
    }
}

/* Sets up case c for view v (camera and sun set here; the sun's options
 * in *lo) and renders it; the read-back targets into tex, pos.  GL errors,
 * or -1 when the setup failed. */
static int select_render(const demo_options* o, demo_renderer* r, const demo_scene* scene,
                         const select_case* c, demo_view* v, demo_options* lo, demo_shadow* sh,
                         float* tex, float* pos) {
    *lo = *o;
    if (c->elev > 0) {
        lo->have_light_dir = 0;
        lo->light_elev = c->elev;
        lo->light_azim = c->azim;
    }
    demo_options_light(lo, &v->light);
    demo_view_update(v);
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = c->t;
    req.splits = 4;
    req.scheme_lambda = 0.5;
    req.select = c->sel;
    req.map_res = o->map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    if (demo_shadow_setup(&v->cam, &v->light, &scene->box, &req, sh)) return -1;
    int errs = demo_render_shadow(r, sh, DEMO_FILTER_PCF2, NULL);
    /* the sun straight down, no filter, no bias: only the selection counts */
    demo_main_params p;
    demo_main_params_for(v, DEMO_MODE_SHADED, DEMO_FILTER_NONE, (float)SELECT_BAND, &p);
    p.light_dir[0] = p.light_dir[2] = 0;
    p.light_dir[1] = -1;
    p.grid = 0;
    p.normal_offset = 0;
    errs += demo_render_main(r, sh, &p, NULL);
    demo_render_read_aux(r, tex, pos);
    return errs;
}

/* Prints the verdict of case c; 1 when it passed. */
static int select_verdict(const select_case* c, const demo_options* lo, const demo_shadow* sh,
                          int errs, const select_tally* t) {
    double frac = t->n ? (double)t->diff / t->n : 1;
    int used = 0;
    for (int i = 0; i < sh->count; ++i) used += t->hist[i] > 0;
    /* every map must actually be chosen somewhere, or the test says
     * nothing about the selection */
    int ok = errs == 0 && t->n > 1000 && frac <= 0.005 && used >= 2;
    if (sh->select == DEMO_SELECT_DEPTH) {
        printf("blend  pssm   depth: %ld pixels (%ld in blend bands), %ld blend weights differ "
               "from swarp_cascade_blend by > 2e-3\n", t->wn, t->wband, t->wdiff);
        ok = ok && t->wn > 1000 && t->wband > 500 && (double)t->wdiff / (double)t->wn <= 0.005;
    }
    if (sh->select == DEMO_SELECT_CUBE) {
        /* all faces drawn, and a cube map has 3 to 5 faces for a sun */
        ok = ok && sh->count >= 3 && sh->count <= 5;
        printf("cube light %2.0f,%3.0f: P w %+.3f, %d faces:", lo->light_elev, lo->light_azim,
               sh->cube_light.w, sh->count);
        static const char* const face_name[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
        for (int i = 0; i < sh->count; ++i)
            printf(" %s%s", face_name[sh->cube_face[i] % 6],
                   sh->cube_light.w < 0 ? " (inverse)" : "");
        printf("\n");
    }
    printf("select %-6s %-5s: %ld pixels, %ld differ from the library (%.3f%%), %d maps used %s\n",
           demo_technique_name(c->t),
           c->sel == DEMO_SELECT_DEPTH  ? "depth"
           : c->sel == DEMO_SELECT_BEST ? "best"
           : c->sel == DEMO_SELECT_CUBE ? "cube"
                                        : "lixel",
           t->n, t->diff, 100 * frac, used, ok ? "ok" : "FAIL");
    return ok;
}

/* The shader's map selection against the library's CPU references, pixel
 * by pixel: swarp_cascade_select_depth and swarp_cascade_select_best for
 * PSSM(4), swarp_lixel_select for the lixel maps, swarp_cube_lookup for the
 * cube faces.  A few pixels may differ where float (GPU) and double (CPU)
 * disagree right on a border. */
int demo_check_select(const demo_options* o) {
    demo_view v;
    demo_sized_view(o, &v);
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 1, &scene, &r)) return 1;
    float* tex = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    float* pos = malloc(sizeof(float) * 4 * (size_t)v.w * v.h);
    int fails = 0;
    /* the cube cases: four suns, the light in the camera's post-projective
     * space in front (w > 0) and behind (w < 0, Kozlov's inverse-projection
     * faces) */
    static const select_case cases[7] = {{DEMO_TECH_PSSM, DEMO_SELECT_DEPTH, "default", 0, 0},
                                         {DEMO_TECH_PSSM, DEMO_SELECT_BEST, "high", 0, 0},
                                         {DEMO_TECH_LIXEL, DEMO_SELECT_LIXEL, "room", 0, 0},
                                         {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 0, 0},
                                         {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 60, 20},
                                         {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 20, 200},
                                         {DEMO_TECH_PSM_CUBE, DEMO_SELECT_CUBE, "default", 80, 300}};
    for (int c = 0; c < 7 && tex && pos; ++c) {
        if (demo_camera_preset(cases[c].camera, v.w, v.h, &v.cam)) return 1;
        demo_options lo;
        demo_shadow sh;
        int errs = select_render(o, &r, &scene, &cases[c], &v, &lo, &sh, tex, pos);
        if (errs < 0) {
            ++fails;
            continue;
        }
        select_tally t;
        memset(&t, 0, sizeof t);
        select_compare(&sh, tex, pos, (size_t)v.w * v.h, &t);
        fails += !select_verdict(&cases[c], &lo, &sh, errs, &t);
    }
    free(tex);
    free(pos);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}
