/* sheets.c -- the gallery's two comparison sheets:
 *   blur_sheet.png          [KOZ] §14.3.2 projective blur (--filter projblur)
 *                           against PCF 3x3 on the same view, full and crop
 *   cube_sheet.png,         [KOZ] §14.2.2 PSM with cube-map faces (psm-cube)
 *   cube_sheet_behind.png   against single-map PSM with unit cube clipping
 *                           (Figs. 14-9/14-10), with the camera's near plane
 *                           and the near plane measured by the GPU min-depth
 *                           chain ([RHS] §4.3); the sun in front of and
 *                           behind the camera (the inverse-projection faces)
 * Everything shadow-mathematical comes from demo_shadow_setup (the library);
 * these functions only render and lay the pictures out. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"

static const uint8_t k_white[3] = {255, 255, 255}, k_black[3] = {0, 0, 0};

static int setup(const demo_view* v, const demo_scene* scene, demo_technique t, int map,
                 demo_shadow* sh) {
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = t;
    req.splits = 1;
    req.scheme_lambda = 0.5;
    req.map_res = map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    return demo_shadow_setup(&v->cam, &v->light, &scene->box, &req, sh);
}

/* shadow passes + main pass; the colour picture into *im (allocated) */
static int picture(demo_renderer* r, const demo_view* v, const demo_shadow* sh, demo_mode mode,
                   demo_filter filter, demo_image* im, double* shadow_ms) {
    double ms[DEMO_MAX_SPLITS];
    memset(im, 0, sizeof *im);
    int errs = demo_render_shadow(r, sh, filter, ms);
    if (shadow_ms) {
        *shadow_ms = 0;
        for (int i = 0; i < sh->count; ++i) *shadow_ms += ms[i];
    }
    demo_main_params p;
    demo_main_params_for(v, mode, filter, 0, &p);
    p.grid = 16;
    errs += demo_render_main(r, sh, &p, NULL);
    if (demo_image_alloc(im, v->w, v->h)) return errs + 1;
    demo_render_read_color(r, v->w, v->h, im->px);
    return errs;
}

static int crop(const demo_image* src, int x, int y, int w, int h, int ow, int oh,
                demo_image* out) {
    demo_image c;
    if (demo_image_alloc(&c, w, h)) return -1;
    for (int j = 0; j < h; ++j)
        memcpy(c.px + 4 * (size_t)j * w, src->px + 4 * ((size_t)(y + j) * src->w + x), 4 * (size_t)w);
    int rc = demo_image_resize(&c, ow, oh, out);
    demo_image_free(&c);
    return rc;
}

static void blit_scaled(demo_image* sheet, const demo_image* im, int x, int y, int w, int h) {
    demo_image s;
    if (demo_image_resize(im, w, h, &s) == 0) {
        demo_image_blit(sheet, x, y, &s);
        demo_image_free(&s);
    }
}

static int write_sheet(const char* dir, const char* name, const demo_image* im) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    int rc = demo_image_write_png(im, path);
    if (rc) fprintf(stderr, "demo: cannot write %s\n", path);
    else printf("  wrote %s\n", path);
    return rc ? 1 : 0;
}

int demo_sheet_blur(demo_renderer* r, const demo_view* v, const demo_scene* scene, int map,
                    const char* out_dir) {
    /* a uniform map, so the penumbra's width in the map is the same
     * everywhere and its width on the ground follows the texel size */
    demo_shadow sh;
    if (setup(v, scene, DEMO_TECH_UNIFORM, map, &sh)) return 1;
    demo_image pics[3];
    const char* labs[3] = {"PCF 3x3 on everything", "colour part, unblurred, on the ground",
                           "[KOZ] 14.3.2: blurred colour part on the ground"};
    const demo_filter f[3] = {DEMO_FILTER_PCF3, DEMO_FILTER_PROJBLUR, DEMO_FILTER_PROJBLUR};
    double shadow_ms[3];
    int rc = 0;
    for (int k = 0; k < 3; ++k) {
        r->blur_off = k == 1;
        rc |= picture(r, v, &sh, DEMO_MODE_SHADED, f[k], &pics[k], &shadow_ms[k]) != 0;
    }
    r->blur_off = 0;
    printf("  projective blur ([KOZ] 14.3.2), uniform map %d^2: shadow pass depth only %.2f ms, depth "
           "+ colour part %.2f ms, blur passes %.2f ms\n",
           map, shadow_ms[0], shadow_ms[1], r->blur_ms);
    const int cw = 480, ch = 270, hdr = 28;
    demo_image sheet;
    if (rc || demo_image_alloc(&sheet, 3 * cw, hdr + 2 * ch)) {
        r->blur_off = 0;
        for (int k = 0; k < 3; ++k) demo_image_free(&pics[k]);
        return 1;
    }
    demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, k_white);
    demo_image_text(&sheet, 8, 8, 2, "projective blur vs PCF on the same view (uniform map)", k_black);
    /* the crop: the ground in front of the camera, 2.5x */
    int x0 = v->w * 3 / 10, y0 = v->h * 11 / 20, w0 = v->w * 2 / 5, h0 = v->h * 2 / 5;
    for (int k = 0; k < 3; ++k) {
        blit_scaled(&sheet, &pics[k], k * cw, hdr, cw, ch);
        demo_image s;
        if (crop(&pics[k], x0, y0, w0, h0, cw, ch, &s) == 0) {
            demo_image_blit(&sheet, k * cw, hdr + ch, &s);
            demo_image_free(&s);
        }
        demo_image_label(&sheet, k * cw + 8, hdr + 8, 1, labs[k]);
        demo_image_label(&sheet, k * cw + 8, hdr + ch + 8, 1, "crop, 2.5x");
        demo_image_free(&pics[k]);
    }
    rc |= write_sheet(out_dir, "blur_sheet", &sheet);
    demo_image_free(&sheet);
    return rc;
}

static const char* face_name(uint32_t f) {
    static const char* const n[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    return f < 6 ? n[f] : "?";
}

/* rows 2 pass, 2 pass + 1 of the sheet: single-map PSM, then the cube map */
static int cube_rows(demo_renderer* r, const demo_view* v, const demo_scene* scene, int map,
                     demo_image* sheet, int row0, int cw, int ch, int hdr) {
    demo_shadow sh[2];
    if (setup(v, scene, DEMO_TECH_PSM, map, &sh[0]) || setup(v, scene, DEMO_TECH_PSM_CUBE, map, &sh[1]))
        return 1;
    printf("  camera near %.2f: light in post-projective space (%.4g, %.4g, %.4g, %.4g), %d faces:",
           v->cam.z_near, sh[1].cube_light.x, sh[1].cube_light.y, sh[1].cube_light.z, sh[1].cube_light.w,
           sh[1].count);
    for (int i = 0; i < sh[1].count; ++i)
        printf(" %s (d = %.3f)", face_name(sh[1].cube_face[i]), sh[1].cube_distance[i]);
    printf("%s\n", sh[1].cube_light.w < 0 ? ", inverse projection" : "");
    const demo_mode modes[3] = {DEMO_MODE_SHADED, DEMO_MODE_SAMPLING, DEMO_MODE_GRID};
    int rc = 0;
    double ms[2] = {0, 0};
    for (int row = 0; row < 2; ++row)
        for (int c = 0; c < 3; ++c) {
            demo_image im;
            double t = 0;
            rc |= picture(r, v, &sh[row], modes[c], DEMO_FILTER_PCF3, &im, &t) != 0;
            if (c == 0) ms[row] = t;
            if (!im.px) continue;
            if (c == 1) demo_image_sampling_legend(&im, 20, v->h - 44, v->w / 2 > 420 ? 420 : v->w / 2);
            if (c == 0) {
                char lab[128];
                if (row)
                    snprintf(lab, sizeof lab, "PSM cube map, %d faces, near %.1f", sh[1].count, v->cam.z_near);
                else
                    snprintf(lab, sizeof lab, "PSM one map (unit cube clip), near %.1f", v->cam.z_near);
                demo_image_label(&im, 8, 8, 2, lab);
            }
            blit_scaled(sheet, &im, c * cw, hdr + (row0 + row) * ch, cw, ch);
            demo_image_free(&im);
        }
    printf("  shadow passes: cube map %d faces %.2f ms (%.0f texels), single-map PSM %.2f ms (%.0f texels)\n",
           sh[1].count, ms[1], (double)sh[1].count * map * map, ms[0], (double)map * map);
    return rc;
}

int demo_sheet_cube(demo_renderer* r, const demo_view* v, const demo_scene* scene, int map,
                    const swarp_light* behind, const char* out_dir) {
    const int cw = 480, ch = 270, hdr = 28;
    int rc = 0;
    for (int light = 0; light < 2; ++light) {
        demo_view lv = *v;
        if (light) {
            lv.light = *behind;
            printf("  sun from behind the camera:\n");
        }
        demo_image sheet;
        if (demo_image_alloc(&sheet, 3 * cw, hdr + 4 * ch)) return 1;
        demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, k_white);
        const char* cols[3] = {"shaded", "sampling rate (Listing A.3)", "texel grid (Listing A.4)"};
        for (int c = 0; c < 3; ++c) demo_image_text(&sheet, c * cw + 8, 8, 2, cols[c], k_black);
        /* rows 0-1: the camera's near plane; rows 2-3: the near plane the
         * GPU min-depth chain measured ([RHS] §4.3: what PSM needs most) */
        rc |= cube_rows(r, &lv, scene, map, &sheet, 0, cw, ch, hdr);
        demo_mindepth_result md;
        if (demo_mindepth(r, &lv, &md) || !(md.adjusted_near > lv.cam.z_near)) {
            fprintf(stderr, "demo: the min-depth chain gave no near plane\n");
            rc = 1;
        } else {
            lv.cam.z_near = md.adjusted_near;
            demo_view_update(&lv);
            rc |= cube_rows(r, &lv, scene, map, &sheet, 2, cw, ch, hdr);
        }
        rc |= write_sheet(out_dir, light ? "cube_sheet_behind" : "cube_sheet", &sheet);
        demo_image_free(&sheet);
    }
    return rc;
}
