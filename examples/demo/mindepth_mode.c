/* mindepth_mode.c -- --mindepth: [RHS] §4.3's near plane from the minimum
 * depth the viewer sees, and LiSPSM's sampling rate with it. */
#include <stdio.h>
#include <string.h>

#include "modes.h"
#include "technique.h"

int demo_mindepth_report(demo_renderer* r, const char* cam, const demo_view* v,
                         demo_mindepth_result* md) {
    int rc = demo_mindepth(r, v, md) ? 1 : 0;
    printf("min depth of the view, camera %s (near %.3g, far %.3g):\n", cam, v->cam.z_near,
           v->cam.z_far);
    printf("  GPU 2x2 min chain (%d passes) %.6f   [depth pass %.2f ms, chain + 1-texel read-back "
           "%.2f ms]\n",
           md->levels, md->gpu_min, md->depth_pass_ms, md->chain_ms);
    printf("  CPU swarp_mindepth_pyramid    %.6f   [full read-back %.2f ms, reduction %.3f ms]\n",
           md->cpu_pyramid_min, md->readback_ms, md->cpu_pyramid_ms);
    printf("  CPU swarp_mindepth_direct     %.6f   [reduction %.3f ms]\n", md->cpu_direct_min,
           md->cpu_direct_ms);
    printf("  adjusted near plane (swarp_mindepth_near) %.6f\n", md->adjusted_near);
    return rc;
}

/* [RHS] §4.3: the GPU chain and both CPU reductions take the minimum of the
 * same depth buffer, so they agree bit for bit; the adjusted near plane
 * lies in [camera near, min], so it clips nothing the camera saw. */
int demo_mindepth_consistent(const demo_view* v, const demo_mindepth_result* md) {
    int same = md->gpu_min == md->cpu_pyramid_min && md->gpu_min == md->cpu_direct_min;
    int safe = md->adjusted_near <= md->gpu_min && md->adjusted_near >= v->cam.z_near;
    if (!same || !safe || md->gl_errors)
        printf("  FAIL: %s%s%s\n", same ? "" : "GPU and CPU minima differ; ",
               safe ? "" : "adjusted near clips what the camera saw; ",
               md->gl_errors ? "GL errors" : "");
    return same && safe && md->gl_errors == 0;
}

/* Picture k of the sampling rate of LiSPSM: with the camera's near plane
 * (k = 0), the adjusted near plane (1) and the pseudo-near plane (2);
 * written as o->out/mindepth_NAME_sampling.png.  0, 1 on failure, 2 when
 * the picture cannot be read back. */
static int mindepth_sampling_picture(const demo_options* o, demo_renderer* r,
                                     const demo_scene* scene, const demo_view* v,
                                     const demo_mindepth_result* md, int k) {
    static const char* const names[3] = {"near", "adjusted", "pseudo"};
    demo_view vk = *v;
    if (k == 1) vk.cam.z_near = md->adjusted_near;
    demo_view_update(&vk);
    demo_options q = *o;
    q.pseudo_near = k == 2 ? 0.05 : 0;
    q.pseudo_far = 0;
    demo_tech_result res;
    demo_technique t = k == 2 ? DEMO_TECH_PSEUDO : DEMO_TECH_LISPSM;
    char label[64];
    snprintf(label, sizeof label, "mindepth_%s", names[k]);
    if (demo_run_technique(&q, r, &vk, &scene->box, t, 1, 0, &res)) return 1;
    demo_main_params p;
    demo_main_params_for(&vk, DEMO_MODE_SAMPLING, o->filter, 0, &p);
    p.grid = 0;
    p.normal_offset = o->offset;
    res.gl_errors += demo_render_main(r, &res.sh, &p, NULL);
    demo_image im;
    if (demo_read_picture(r, vk.w, vk.h, &im)) return 2;
    char cap[160];
    snprintf(cap, sizeof cap, "LiSPSM, %s: near %.2f, predicted max m_z %.2f",
             k == 0   ? "camera near"
             : k == 1 ? "adjusted near [RHS] 4.3"
                      : "pseudo-near 0.05 (4.2)",
             res.sh.z_near, res.sh.predicted_max_mz);
    demo_image_label(&im, 8, 8, 1, cap);
    demo_image_sampling_legend(&im, 20, vk.h - 44, vk.w / 2 > 420 ? 420 : vk.w / 2);
    int rc = demo_write_png(o, label, "sampling", &im) ? 1 : 0;
    printf("  %-28s view range [%.3f, %.1f], n' %.3f, predicted max m_x %.3f, m_z %.3f -> "
           "%s/%s_sampling.png\n",
           cap, res.sh.z_near, res.sh.z_far, res.sh.n_prime[0], res.sh.predicted_max_mx,
           res.sh.predicted_max_mz, o->out, label);
    if (res.gl_errors) rc = 1;
    demo_image_free(&im);
    demo_tech_result_free(&res);
    return rc;
}

/* [RHS] §4.3 / Figs. 7.8-7.9: the min-depth near plane measured on the GPU
 * and on the CPU for the --camera (default street), then the sampling rate
 * of LiSPSM with the camera's near plane, the adjusted near plane and the
 * pseudo-near plane side by side. */
int demo_run_mindepth(const demo_options* o) {
    demo_view v;
    demo_sized_view(o, &v);
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 0, &scene, &r)) return 2;
    const char* cam = o->camera_given ? o->camera : "street";
    if (demo_camera_preset(cam, v.w, v.h, &v.cam)) return 2;
    demo_options_light(o, &v.light);
    demo_view_update(&v);
    demo_mindepth_result md;
    int rc = demo_mindepth_report(&r, cam, &v, &md);
    rc |= demo_mindepth_consistent(&v, &md) ? 0 : 1;
    if (rc == 0) {
        /* sampling rate: camera near | adjusted near | pseudo-near */
        if (demo_mkdir_p(o->out)) return 2;
        for (int k = 0; k < 3; ++k) {
            int e = mindepth_sampling_picture(o, &r, &scene, &v, &md, k);
            if (e == 2) return 2;
            rc |= e;
        }
    }
    demo_render_free(&r);
    demo_scene_free(&scene);
    return rc;
}
