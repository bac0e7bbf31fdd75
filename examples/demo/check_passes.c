/* check_passes.c -- demo-check: renderer paths that must agree bit for bit
 * or must differ: geometry cloning (clone), the min-depth near plane
 * (mindepth), projective blur (blur), stabilised cascades (flicker). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checks.h"

/* Geometry cloning against K passes ([RHS] §3.3.6, Listing A.1): the same
 * depth in every texel of every layer (the same triangles rasterised with
 * the same matrices) and the same shadow mask (the `lit` value the main pass
 * writes for every pixel), bit for bit.  A control swaps the matrices of
 * maps 0 and 1 for the clone and must see differing pixels, so the
 * comparison can fail. */
int demo_check_clone(const demo_options* o) {
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 1, &scene, &r)) return 1;
    size_t n = (size_t)o->map * o->map, npx = (size_t)o->w * o->h;
    float* a = malloc(sizeof(float) * n);
    float* multi_depth = malloc(sizeof(float) * n * DEMO_MAX_SPLITS);
    float* pos_multi = malloc(sizeof(float) * 4 * npx);
    float* pos_clone = malloc(sizeof(float) * 4 * npx);
    int fails = 0;
    const struct {
        demo_technique t;
        int k;
        const char* camera;
    } cases[6] = {{DEMO_TECH_PSSM, 4, "default"},         {DEMO_TECH_PSSM, 8, "default"},
                  {DEMO_TECH_PSSM, 16, "default"},        {DEMO_TECH_PSSM_LISPSM, 4, "default"},
                  {DEMO_TECH_PSSM_LISPSM, 8, "high"},     {DEMO_TECH_PSSM_STABLE, 4, "street"}};
    for (int c = 0; c < 6 && a && multi_depth && pos_multi && pos_clone; ++c) {
        demo_view v;
        demo_shadow sh;
        if (demo_preset_view(o, cases[c].camera, &v) ||
            demo_setup_for(o, &v, &scene.box, cases[c].t, cases[c].k, &sh)) {
            ++fails;
            continue;
        }
        demo_main_params p;
        demo_main_params_for(&v, DEMO_MODE_SHADED, DEMO_FILTER_PCF3, 0.1f, &p);
        /* K passes: every layer read back, then the main pass's mask */
        int errs = demo_render_shadow(&r, &sh, DEMO_FILTER_PCF3, NULL);
        for (int i = 0; i < sh.count; ++i) errs += demo_render_read_depth(&r, i, multi_depth + n * (size_t)i);
        errs += demo_render_main(&r, &sh, &p, NULL);
        demo_render_read_aux(&r, NULL, pos_multi);
        /* one pass by cloning: the same again */
        long differ = 0, covered = 0;
        errs += demo_render_shadow_single(&r, &sh, NULL);
        for (int i = 0; i < sh.count; ++i) {
            errs += demo_render_read_depth(&r, i, a);
            const float* m = multi_depth + n * (size_t)i;
            for (size_t k = 0; k < n; ++k) {
                covered += m[k] < 1.0f;
                differ += a[k] != m[k];
            }
        }
        errs += demo_render_main(&r, &sh, &p, NULL);
        demo_render_read_aux(&r, NULL, pos_clone);
        long mask_px = 0, mask_diff = 0, shadowed = 0;
        for (size_t k = 0; k < npx; ++k) {
            if (pos_multi[4 * k + 3] < 0) continue; /* sky */
            ++mask_px;
            shadowed += pos_multi[4 * k + 3] < 0.5f;
            mask_diff += memcmp(&pos_multi[4 * k + 3], &pos_clone[4 * k + 3], sizeof(float)) != 0;
        }
        int ok = errs == 0 && differ == 0 && covered > (long)n / 4 && mask_diff == 0 &&
                 shadowed > 100;
        printf("clone %-11s K=%-2d %-7s: %ld texels with geometry, %ld differ from the K-pass maps; "
               "shadow mask %ld pixels (%ld shadowed), %ld differ; gl errors %d %s\n",
               demo_technique_name(cases[c].t), cases[c].k, cases[c].camera, covered, differ,
               mask_px, shadowed, mask_diff, errs, ok ? "ok" : "FAIL");
        fails += !ok;
        if (c == 0) {
            /* control: maps 0 and 1 swapped for the clone only */
            demo_shadow sw = sh;
            sw.light[0] = sh.light[1];
            sw.light[1] = sh.light[0];
            errs = demo_render_shadow_single(&r, &sw, NULL);
            errs += demo_render_main(&r, &sh, &p, NULL);
            demo_render_read_aux(&r, NULL, pos_clone);
            long cdiff = 0;
            for (size_t k = 0; k < npx; ++k)
                cdiff += pos_multi[4 * k + 3] >= 0 &&
                         memcmp(&pos_multi[4 * k + 3], &pos_clone[4 * k + 3], sizeof(float)) != 0;
            int cok = errs == 0 && cdiff > 100;
            printf("clone control (maps 0 and 1 swapped): %ld mask pixels differ (must be > 100) %s\n",
                   cdiff, cok ? "ok" : "FAIL");
            fails += !cok;
        }
    }
    if (!a || !multi_depth || !pos_multi || !pos_clone) ++fails;
    free(a);
    free(multi_depth);
    free(pos_multi);
    free(pos_clone);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}

/* Eye depth of every pixel of view v (INFINITY for sky) from the main
 * pass's float target: what the depth buffer saw. */
static int eye_depths(demo_renderer* r, const demo_view* v, const demo_shadow* sh, float* tex,
                      float* pos, float* out) {
    demo_main_params p;
    demo_main_params_for(v, DEMO_MODE_SHADED, DEMO_FILTER_NONE, 0, &p);
    int errs = demo_render_main(r, sh, &p, NULL);
    demo_render_read_aux(r, tex, pos);
    for (size_t k = 0; k < (size_t)v->w * v->h; ++k)
        out[k] = pos[4 * k + 3] < 0 ? INFINITY : tex[4 * k + 3];
    return errs;
}

/* Pixels whose eye depth differs (relative rel; sky against geometry counts). */
static long depth_changes(const float* a, const float* b, size_t n, double rel) {
    long d = 0;
    for (size_t k = 0; k < n; ++k) {
        if (isinf(a[k]) || isinf(b[k])) d += isinf(a[k]) != isinf(b[k]);
        else d += fabs((double)a[k] - b[k]) > rel * fabs((double)a[k]);
    }
    return d;
}

/* [RHS] §4.3: re-rendering with the adjusted near plane changes no pixel's
 * depth (it clips nothing the depth buffer saw), while a control near plane
 * 5 % beyond the minimum changes some, so the comparison can fail. */
static int mindepth_clips_nothing(const demo_options* o, demo_renderer* r,
                                  const demo_scene* scene, const demo_view* v,
                                  const demo_mindepth_result* md) {
    int ok;
    size_t npx = (size_t)v->w * v->h;
    float* tex = malloc(sizeof(float) * 4 * npx);
    float* pos = malloc(sizeof(float) * 4 * npx);
    float* d[3] = {malloc(sizeof(float) * npx), malloc(sizeof(float) * npx), malloc(sizeof(float) * npx)};
    demo_shadow sh;
    int errs = 0;
    if (!tex || !pos || !d[0] || !d[1] || !d[2] || demo_setup_for(o, v, &scene->box, DEMO_TECH_UNIFORM, 1, &sh)) {
        ok = 0;
    } else {
        errs += demo_render_shadow(r, &sh, DEMO_FILTER_NONE, NULL);
        const double nears[3] = {v->cam.z_near, md->adjusted_near, 1.05 * md->gpu_min};
        for (int k = 0; k < 3; ++k) {
            demo_view vk = *v;
            vk.cam.z_near = nears[k];
            demo_view_update(&vk);
            errs += eye_depths(r, &vk, &sh, tex, pos, d[k]);
        }
        long adj = depth_changes(d[0], d[1], npx, 1e-4), ctl = depth_changes(d[0], d[2], npx, 1e-4);
        ok = errs == 0 && adj == 0 && ctl > 100;
        printf("  re-rendered with the adjusted near %.4f: %ld pixels change depth (must be 0); "
               "control near %.4f (min + 5%%): %ld change (must be > 100) %s\n",
               md->adjusted_near, adj, nears[2], ctl, ok ? "ok" : "FAIL");
    }
    free(tex);
    free(pos);
    for (int k = 0; k < 3; ++k) free(d[k]);
    return ok ? 0 : 1;
}

/* [RHS] §4.3 for the cameras default, street, high and measure (or
 * --camera): the GPU chain and the CPU reductions agree, the adjusted near
 * plane is safe and clips nothing. */
int demo_check_mindepth(const demo_options* o) {
    demo_view v;
    demo_sized_view(o, &v);
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 0, &scene, &r)) return 2;
    const char* cams[4] = {"default", "street", "high", "measure"};
    int ncam = !o->camera_given ? 4 : 1;
    int rc = 0;
    demo_mindepth_result md;
    for (int c = 0; c < ncam; ++c) {
        const char* cam = ncam > 1 ? cams[c] : o->camera;
        if (demo_camera_preset(cam, v.w, v.h, &v.cam)) return 2;
        demo_options_light(o, &v.light);
        demo_view_update(&v);
        rc |= demo_mindepth_report(&r, cam, &v, &md);
        if (!demo_mindepth_consistent(&v, &md)) rc = 1;
        else rc |= mindepth_clips_nothing(o, &r, &scene, &v, &md);
    }
    demo_render_free(&r);
    demo_scene_free(&scene);
    return rc;
}

/* [KOZ] §14.3.2 projective blur (--filter projblur): on the ground, the raw
 * colour part of the shadow map (1 receiver, 0 caster; blur switched off)
 * projected as a texture agrees with the ordinary depth compare, and the
 * blurred one has a penumbra (lit strictly between 0.05 and 0.95) several
 * times wider than the raw texture's one-texel bilinear edge. */
int demo_check_blur(const demo_options* o) {
    demo_view v;
    if (demo_preset_view(o, "default", &v)) return 1;
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 1, &scene, &r)) return 1;
    size_t npx = (size_t)v.w * v.h;
    float* pos[3] = {malloc(sizeof(float) * 4 * npx), malloc(sizeof(float) * 4 * npx),
                     malloc(sizeof(float) * 4 * npx)};
    int ok = 0;
    demo_shadow sh;
    if (pos[0] && pos[1] && pos[2] && !demo_setup_for(o, &v, &scene.box, DEMO_TECH_UNIFORM, 1, &sh)) {
        /* 0: depth compare, 1 nearest tap; 1: raw colour part; 2: blurred */
        const demo_filter f[3] = {DEMO_FILTER_NONE, DEMO_FILTER_PROJBLUR, DEMO_FILTER_PROJBLUR};
        int errs = 0;
        for (int k = 0; k < 3; ++k) {
            r.blur_off = k == 1;
            errs += demo_render_shadow(&r, &sh, f[k], NULL);
            demo_main_params p;
            demo_main_params_for(&v, DEMO_MODE_SHADED, f[k], 0, &p);
            errs += demo_render_main(&r, &sh, &p, NULL);
            demo_render_read_aux(&r, NULL, pos[k]);
        }
        r.blur_off = 0;
        long ground = 0, agree = 0, soft_raw = 0, soft_blur = 0, shadowed = 0;
        for (size_t k = 0; k < npx; ++k) {
            const float* q = pos[0] + 4 * k;
            if (q[3] < 0 || fabsf(q[1]) > 1e-3f) continue; /* sky, not the ground */
            float depth = q[3], raw = pos[1][4 * k + 3], blur = pos[2][4 * k + 3];
            ++ground;
            shadowed += depth < 0.5f;
            agree += (depth > 0.5f) == (raw > 0.5f);
            soft_raw += raw > 0.05f && raw < 0.95f;
            soft_blur += blur > 0.05f && blur < 0.95f;
        }
        double fa = ground ? (double)agree / ground : 0;
        ok = errs == 0 && ground > 1000 && shadowed > 100 && fa >= 0.98 && soft_blur > 3 * soft_raw &&
             soft_blur > 100;
        printf("blur: %ld ground pixels (%ld shadowed by the depth compare); raw colour part agrees "
               "on %.2f%% (>= 98%%); penumbra pixels: raw %ld, blurred %ld (> 3x raw) %s\n",
               ground, shadowed, 100 * fa, soft_raw, soft_blur, ok ? "ok" : "FAIL");
    }
    for (int k = 0; k < 3; ++k) free(pos[k]);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return ok ? 0 : 1;
}

/* [RHS] §3.5: a fixed ground point keeps its place inside its texel while
 * the camera moves and turns (stabilised cascades), and does not without
 * stabilisation (the control that shows the check can fail). */
int demo_check_flicker(const demo_options* o) {
    demo_options q = *o;
    q.frames = 8;
    q.splits = 4;
    double drift_stable = 0, drift_plain = 0;
    q.technique = DEMO_TECH_PSSM_STABLE;
    int rc = demo_run_frames(&q, &drift_stable);
    q.technique = DEMO_TECH_PSSM;
    rc |= demo_run_frames(&q, &drift_plain);
    int ok = rc == 0 && drift_stable < 1e-4 && drift_plain > 1e-2;
    printf("flicker: largest sub-texel drift per frame: pssm-stable %.6f, pssm %.6f %s\n",
           drift_stable, drift_plain, ok ? "ok" : "FAIL");
    return ok ? 0 : 1;
}
