/* frames.c -- --frames: the camera flies (or walks a path file) and every
 * frame reports its timing and how far a fixed ground point moved inside
 * its texel. */
#include <math.h>
#include <stdio.h>

#include "modes.h"
#include "technique.h"

/* Flicker: a fixed world point's position inside its texel.  Texels that
 * slide under the scene (unstabilised maps) change the fraction from frame
 * to frame; snapped maps ([RHS] §3.5) keep it. */
typedef struct texel_probe {
    swarp_vec3 p;
    double prev_frac[2];
    int prev_map; /**< -1: no frame yet */
} texel_probe;

/* Camera of frame f: the path file's line (looped), or the boulevard. */
static void frame_camera(const demo_options* o, int f, swarp_camera* cam) {
    if (o->path_count > 0) {
        /* a camera path file: one "ex ey ez dx dy dz" line per frame, looped */
        const double* k = o->path + 6 * (f % o->path_count);
        cam->eye = (swarp_vec3){k[0], k[1], k[2]};
        cam->dir = (swarp_vec3){k[3], k[4], k[5]};
    } else {
        /* fly down the boulevard, turning slowly */
        cam->eye.z -= 2.5;
        double yaw = 0.15 * sin(0.05 * f);
        cam->dir = (swarp_vec3){sin(yaw), -0.06, -cos(yaw)};
    }
}

/* The probe's map by eye depth (*map) and how far its position inside the
 * texel moved since the previous frame, in texels, the shorter way round
 * (NAN when the previous frame shaded it from another map). */
static double probe_drift(texel_probe* pr, const demo_view* v, const demo_shadow* sh,
                          uint32_t* map) {
    const swarp_camera* c = &v->cam;
    const swarp_vec3 probe = pr->p;
    double dz = (probe.x - c->eye.x) * c->dir.x + (probe.y - c->eye.y) * c->dir.y +
                (probe.z - c->eye.z) * c->dir.z;
    dz /= sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z);
    uint32_t mi = 0;
    swarp_cascade_select_depth(sh->split, (size_t)sh->count, dz, &mi);
    swarp_vec4 h;
    swarp_mat4_transform(&sh->light[mi], &probe, &h);
    double ts = (h.x / h.w * 0.5 + 0.5) * sh->viewport[mi][0];
    double tt = (h.y / h.w * 0.5 + 0.5) * sh->viewport[mi][1];
    double frac[2] = {ts - floor(ts), tt - floor(tt)};
    double drift = NAN;
    if ((int)mi == pr->prev_map) {
        double a = fabs(frac[0] - pr->prev_frac[0]), b = fabs(frac[1] - pr->prev_frac[1]);
        a = fmin(a, 1 - a);
        b = fmin(b, 1 - b);
        drift = fmax(a, b);
    }
    pr->prev_frac[0] = frac[0];
    pr->prev_frac[1] = frac[1];
    pr->prev_map = (int)mi;
    *map = mi;
    return drift;
}

/* Every frame of the flight with technique t; the largest drift into
 * *out_max_drift (may be NULL). */
static int fly(const demo_options* o, demo_renderer* r, demo_view* v, const demo_scene* scene,
               demo_technique t, double* out_max_drift) {
    int rc = 0;
    texel_probe pr = {{5, 0, v->cam.eye.z - 80}, {NAN, NAN}, -1};
    for (int f = 0; f < o->frames; ++f) {
        frame_camera(o, f, &v->cam);
        demo_view_update(v);
        demo_tech_result res;
        if (demo_run_technique(o, r, v, &scene->box, t, o->splits, 0, &res)) {
            rc = 1;
            break;
        }
        uint32_t mi = 0;
        double drift = probe_drift(&pr, v, &res.sh, &mi);
        if (out_max_drift && !isnan(drift) && drift > *out_max_drift) *out_max_drift = drift;
        printf("frame %d/%d: setup %.2f us, %d shadow passes %.2f ms, main %.2f ms, gl errors %d, "
               "probe in map %u, sub-texel drift %.4f texel\n",
               f + 1, o->frames, res.setup_us, res.passes - 1, res.shadow_ms_total, res.main_ms,
               res.gl_errors, mi, drift);
        fflush(stdout);
        if (res.gl_errors) rc = 1;
        demo_tech_result_free(&res);
    }
    return rc;
}

int demo_run_frames(const demo_options* o, double* out_max_drift) {
    demo_view v;
    if (demo_options_view(o, &v)) return 2;
    demo_scene scene;
    if (demo_load_scene(o, &scene)) return 2;
    demo_ctx* ctx = demo_open_context();
    if (!ctx) {
        demo_scene_free(&scene);
        return 2;
    }
    demo_renderer r;
    if (demo_render_init(&r, &scene, o->w, o->h, o->map, DEMO_MAX_SPLITS)) {
        demo_ctx_destroy(ctx);
        demo_scene_free(&scene);
        return 2;
    }
    int t = o->technique < 0 ? DEMO_TECH_UNIFORM : o->technique;
    int rc = fly(o, &r, &v, &scene, (demo_technique)t, out_max_drift);
    demo_render_free(&r);
    demo_ctx_destroy(ctx);
    demo_scene_free(&scene);
    return rc;
}
