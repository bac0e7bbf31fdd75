/* extras_mindepth.c -- the min-depth near plane of [RHS] §4.3 measured every
 * frame: a depth pre-pass into a LINEAR depth target (view-space depth along
 * the view direction, +inf where nothing was drawn), the mip-min chain of
 * Listing A.2 on the GPU (2x2 min per level, sizes rounded up, the odd last
 * row/column clamped -- the library's documented variant), the 1x1 level
 * read back, and swarp_mindepth_near for the adjusted near plane.  Compared
 * with the library's CPU reduction (swarp_mindepth_pyramid, _direct) of the
 * same buffer read back whole, and with the pseudo-near plane of [RHS] (4.2)
 * (Figs. 7.8 and 7.9). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extras.h"

static const char* const lin_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "uniform mat4 u_view, u_proj;\n"
    "out float v_depth;\n"
    "void main() { vec4 vs = u_view * vec4(a_p, 1.0); v_depth = -vs.z; gl_Position = u_proj * vs; }\n";
static const char* const lin_fs =
    "in float v_depth;\n"
    "layout(location = 0) out vec4 o;\n"
    "void main() { o = vec4(v_depth); }\n";
static const char* const quad_vs =
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";
/* [RHS] Listing A.2: the min of four adjacent texels of the level above */
static const char* const min_fs =
    "uniform sampler2D u_src;\n"
    "layout(location = 0) out vec4 o;\n"
    "void main() {\n"
    "  ivec2 c = 2 * ivec2(gl_FragCoord.xy), m = textureSize(u_src, 0) - 1;\n"
    "  float d = texelFetch(u_src, min(c, m), 0).r;\n"
    "  d = min(d, texelFetch(u_src, min(c + ivec2(0, 1), m), 0).r);\n"
    "  d = min(d, texelFetch(u_src, min(c + ivec2(1, 0), m), 0).r);\n"
    "  d = min(d, texelFetch(u_src, min(c + ivec2(1, 1), m), 0).r);\n"
    "  o = vec4(d);\n"
    "}\n";

enum { MAX_LEVELS = 16 };

typedef struct md_ctx {
    GLuint prog_lin, prog_min;
    extras_target lin;                /* w x h linear depth + depth buffer */
    extras_target level[MAX_LEVELS];  /* ceil halvings down to 1 x 1 */
    int levels;
} md_ctx;

static int md_init(extras_env* e, md_ctx* m) {
    memset(m, 0, sizeof *m);
    m->prog_lin = extras_gl_program("linear depth", lin_vs, NULL, lin_fs);
    m->prog_min = extras_gl_program("mip-min", quad_vs, NULL, min_fs);
    if (!m->prog_lin || !m->prog_min) return -1;
    if (extras_target_init(&m->lin, e->w, e->h, GL_R32F, 0, 1)) return -1;
    int w = e->w, h = e->h;
    while ((w > 1 || h > 1) && m->levels < MAX_LEVELS) {
        w = (w + 1) / 2;
        h = (h + 1) / 2;
        if (extras_target_init(&m->level[m->levels++], w, h, GL_R32F, 0, 0)) return -1;
    }
    return demo_gl_check("mindepth init") ? -1 : 0;
}

static void md_free(md_ctx* m) {
    if (m->prog_lin) glDeleteProgram(m->prog_lin);
    if (m->prog_min) glDeleteProgram(m->prog_min);
    extras_target_free(&m->lin);
    for (int i = 0; i < m->levels; ++i) extras_target_free(&m->level[i]);
}

/* the extra 3D pass: linear depth of the view */
static int depth_prepass(extras_env* e, md_ctx* m, const demo_view* v) {
    glBindFramebuffer(GL_FRAMEBUFFER, m->lin.fbo);
    glViewport(0, 0, m->lin.w, m->lin.h);
    const float inf[4] = {INFINITY, INFINITY, INFINITY, INFINITY};
    glClearBufferfv(GL_COLOR, 0, inf);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glUseProgram(m->prog_lin);
    glUniformMatrix4fv(glGetUniformLocation(m->prog_lin, "u_view"), 1, GL_FALSE, v->view);
    glUniformMatrix4fv(glGetUniformLocation(m->prog_lin, "u_proj"), 1, GL_FALSE, v->proj);
    glBindVertexArray(e->r.vao);
    glDrawArrays(GL_TRIANGLES, 0, e->r.vertex_count);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("linear depth pre-pass");
}

static int mip_chain(extras_env* e, md_ctx* m) {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(m->prog_min);
    glBindVertexArray(e->r.vao);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(m->prog_min, "u_src"), 0);
    GLuint src = m->lin.tex;
    for (int i = 0; i < m->levels; ++i) {
        glBindFramebuffer(GL_FRAMEBUFFER, m->level[i].fbo);
        glViewport(0, 0, m->level[i].w, m->level[i].h);
        glBindTexture(GL_TEXTURE_2D, src);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        src = m->level[i].tex;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_DEPTH_TEST);
    return demo_gl_check("mip-min chain");
}

static float read_back_min(md_ctx* m) {
    float d = NAN;
    glBindFramebuffer(GL_FRAMEBUFFER, m->level[m->levels - 1].fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, 1, 1, GL_RED, GL_FLOAT, &d);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return d;
}

static void read_back_all(md_ctx* m, float* buf) {
    glBindFramebuffer(GL_FRAMEBUFFER, m->lin.fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, m->lin.w, m->lin.h, GL_RED, GL_FLOAT, buf);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

typedef struct md_measure {
    float gpu;         /* the 1x1 level */
    double cpu_pyr, cpu_direct;
    double near_adj;   /* swarp_mindepth_near */
    long covered;      /* finite pixels of the linear depth buffer */
    swarp_status st_pyr, st_dir, st_near;
} md_measure;

static int measure(extras_env* e, md_ctx* m, const demo_view* v, float* buf, float* scratch,
                   size_t scratch_cap, md_measure* out) {
    memset(out, 0, sizeof *out);
    int errs = depth_prepass(e, m, v) + mip_chain(e, m);
    out->gpu = read_back_min(m);
    read_back_all(m, buf);
    size_t need = 0;
    out->st_pyr = swarp_mindepth_pyramid(buf, (uint32_t)e->w, (uint32_t)e->h, (size_t)e->w,
                                         scratch, scratch_cap, &need, &out->cpu_pyr);
    out->st_dir = swarp_mindepth_direct(buf, (uint32_t)e->w, (uint32_t)e->h, (size_t)e->w,
                                        &out->cpu_direct);
    out->st_near = swarp_mindepth_near(v->cam.near, v->cam.far, out->cpu_pyr, NULL, &out->near_adj);
    for (size_t i = 0; i < (size_t)e->w * e->h; ++i) out->covered += isfinite(buf[i]);
    return errs;
}

static long changed(const float* a, const float* b, size_t n) {
    long k = 0;
    for (size_t i = 0; i < n; ++i) {
        if (isinf(a[i]) || isinf(b[i])) k += isinf(a[i]) != isinf(b[i]);
        else k += fabsf(a[i] - b[i]) > 1e-4f * a[i];
    }
    return k;
}

static int test_mindepth(extras_env* e, md_ctx* m, float* buf, float* scratch, size_t cap) {
    int fails = 0;
    size_t npx = (size_t)e->w * e->h;
    float* ref = malloc(sizeof(float) * npx);
    if (!ref) return 1;
    const char* cams[4] = {"default", "street", "high", "measure"};
    for (int c = 0; c < 4; ++c) {
        demo_view v = e->v;
        extras_camera_preset(cams[c], v.w, v.h, &v.cam);
        demo_view_update(&v);
        md_measure a;
        int errs = measure(e, m, &v, buf, scratch, cap, &a);
        memcpy(ref, buf, sizeof(float) * npx);
        /* GPU mip-min == library CPU pyramid == direct scan, bit for bit
         * (min is exact in float) */
        int ok = errs == 0 && !swarp_status_is_error(a.st_pyr) && !swarp_status_is_error(a.st_dir) &&
                 !swarp_status_is_error(a.st_near) && (double)a.gpu == a.cpu_pyr &&
                 a.cpu_pyr == a.cpu_direct && a.cpu_pyr > v.cam.near &&
                 a.near_adj <= a.cpu_pyr && a.near_adj >= v.cam.near;
        /* nothing the depth buffer saw is clipped by the adjusted near
         * plane: every pixel keeps its depth (relative 1e-4) */
        demo_view va = v;
        va.cam.near = a.near_adj;
        demo_view_update(&va);
        md_measure b;
        errs = measure(e, m, &va, buf, scratch, cap, &b);
        long ch_adj = changed(ref, buf, npx);
        int ok2 = errs == 0 && ch_adj == 0;
        /* control: a near plane 5% beyond the minimum does clip */
        demo_view vc = v;
        vc.cam.near = a.cpu_pyr * 1.05;
        demo_view_update(&vc);
        md_measure cc;
        errs = measure(e, m, &vc, buf, scratch, cap, &cc);
        long ch_ctl = changed(ref, buf, npx);
        int ok3 = errs == 0 && ch_ctl > 0;
        printf("mindepth %-8s GPU mip-min %.6g, CPU pyramid %.6g, CPU direct %.6g, adjusted near "
               "%.6g (near %g) %s; pixels changed by the adjusted near %ld %s; by a near 5%% "
               "beyond the minimum %ld (control) %s\n",
               cams[c], (double)a.gpu, a.cpu_pyr, a.cpu_direct, a.near_adj, v.cam.near,
               ok ? "ok" : "FAIL", ch_adj, ok2 ? "ok" : "FAIL", ch_ctl, ok3 ? "ok" : "FAIL");
        fails += !ok + !ok2 + !ok3;
    }
    free(ref);
    return fails ? 1 : 0;
}

static int sampling_and_graph(extras_env* e, const demo_view* v, const demo_shadow* sh,
                              const char* title, demo_image* samp, demo_image* graph) {
    int errs = extras_render(e, v, sh, DEMO_MODE_SAMPLING, samp);
    demo_image_label(samp, 8, 8, 2, title);
    demo_image_sampling_legend(samp, 20, v->h - 44, v->w / 2 > 420 ? 420 : v->w / 2);
    if (demo_error_graph(v, sh, e->map, NULL, 0, title, graph)) return errs + 1;
    return errs;
}

double extras_measured_near(extras_env* e, const demo_view* v) {
    md_ctx m;
    size_t npx = (size_t)e->w * e->h, cap = SWARP_MINDEPTH_SCRATCH(e->w, e->h);
    float* buf = malloc(sizeof(float) * npx);
    float* scratch = malloc(sizeof(float) * cap);
    double near = NAN;
    md_measure a;
    if (buf && scratch && md_init(e, &m) == 0 && measure(e, &m, v, buf, scratch, cap, &a) == 0 &&
        !swarp_status_is_error(a.st_near))
        near = a.near_adj;
    md_free(&m);
    free(buf);
    free(scratch);
    return near;
}

struct extras_md {
    md_ctx m;
};

extras_md* extras_md_create(extras_env* e) {
    extras_md* x = calloc(1, sizeof *x);
    if (x && md_init(e, &x->m)) {
        extras_md_destroy(x);
        return NULL;
    }
    return x;
}

void extras_md_destroy(extras_md* x) {
    if (!x) return;
    md_free(&x->m);
    free(x);
}

double extras_md_frame(extras_env* e, extras_md* x, const demo_view* v, float* out_min) {
    glFinish();
    double t0 = demo_now_ms();
    int errs = depth_prepass(e, &x->m, v) + mip_chain(e, &x->m);
    float d = read_back_min(&x->m);
    double t = demo_now_ms() - t0;
    if (out_min) *out_min = d;
    return errs ? -1 : t;
}

int extras_mindepth(extras_env* e, int test) {
    md_ctx m;
    size_t npx = (size_t)e->w * e->h;
    size_t cap = SWARP_MINDEPTH_SCRATCH(e->w, e->h);
    float* buf = malloc(sizeof(float) * npx);
    float* scratch = malloc(sizeof(float) * cap);
    int rc = 0;
    if (!buf || !scratch || md_init(e, &m)) {
        free(buf);
        free(scratch);
        md_free(&m);
        return 1;
    }
    if (test) {
        rc = test_mindepth(e, &m, buf, scratch, cap);
        goto done;
    }
    /* ---- Figs. 7.8 / 7.9: n_opt LiSPSM, pseudo-near, adjusted near */
    md_measure a;
    rc |= measure(e, &m, &e->v, buf, scratch, cap, &a) != 0;
    printf("  default view: GPU mip-min %.4f (%d levels), CPU pyramid %.4f, CPU direct %.4f -> "
           "adjusted near %.4f (camera near %g)\n",
           (double)a.gpu, m.levels, a.cpu_pyr, a.cpu_direct, a.near_adj, e->v.cam.near);
    demo_shadow common, pseudo, adjusted;
    if (extras_setup(e, &e->v, DEMO_TECH_LISPSM, 1, &common)) {
        rc = 1;
        goto done;
    }
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = DEMO_TECH_PSEUDO;
    req.scheme_lambda = 0.5;
    req.map_res = e->map;
    req.screen_w = e->w;
    req.screen_h = e->h;
    /* the pseudo-near plane at the measured depth, as a fraction of the
     * adjusted range [RHS] (4.2) takes */
    req.pseudo_near = (a.near_adj - common.near) / (common.far - common.near);
    if (!(req.pseudo_near >= 0 && req.pseudo_near < 0.9)) req.pseudo_near = 0.05;
    if (demo_shadow_setup(&e->v.cam, &e->v.light, &e->scene.box, &req, &pseudo)) {
        rc = 1;
        goto done;
    }
    demo_view va = e->v;
    va.cam.near = a.near_adj;
    demo_view_update(&va);
    if (extras_setup(e, &va, DEMO_TECH_LISPSM, 1, &adjusted)) {
        rc = 1;
        goto done;
    }
    /* the library's m_x, m_z: max over the whole range the map covers, and
     * over the part the camera can see [measured min depth, far] (the
     * region in front of it is empty, [RHS] §7.4) */
    printf("  %-32s %8s %9s %11s %11s %13s %13s\n", "", "near", "n'", "max m_x", "max m_z",
           "seen max m_x", "seen max m_z");
    const demo_shadow* shs[3] = {&common, &pseudo, &adjusted};
    const char* names[3] = {"n_opt LiSPSM (Fig. 7.7)", "pseudo-near plane (Fig. 7.8)",
                            "adjusted near plane (Fig. 7.9)"};
    for (int i = 0; i < 3; ++i) {
        double smx = NAN, smz = NAN;
        for (int k = 0; k <= 400; ++k) {
            double z = a.cpu_pyr + (shs[i]->far - a.cpu_pyr) * k / 400.0, mx, mz;
            if (demo_predict(shs[i], e->v.cam.fovy, e->w, e->h, e->map, z, &mx, &mz)) break;
            smx = k ? fmax(smx, mx) : mx;
            smz = k ? fmax(smz, mz) : mz;
        }
        printf("  %-32s %8.3f %9.3f %11.4f %11.4f %13.4f %13.4f\n", names[i], shs[i]->near,
               shs[i]->n_prime[0], shs[i]->predicted_max_mx, shs[i]->predicted_max_mz, smx, smz);
    }
    {
        const int cw = 640, ch = 360, gw = 600;
        demo_image sheet;
        if (demo_image_alloc(&sheet, cw + gw, 3 * ch) == 0) {
            const uint8_t white[3] = {255, 255, 255};
            demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, white);
            const demo_view* views[3] = {&e->v, &e->v, &va};
            char title[3][96];
            snprintf(title[0], sizeof title[0], "n_opt LiSPSM, near %.1f", common.near);
            snprintf(title[1], sizeof title[1], "pseudo-near n_p = %.3f (PN at %.1f)",
                     req.pseudo_near, common.near + req.pseudo_near * (common.far - common.near));
            snprintf(title[2], sizeof title[2], "adjusted near %.1f (GPU mip-min)", adjusted.near);
            for (int i = 0; i < 3; ++i) {
                demo_image s, g, small;
                rc |= sampling_and_graph(e, views[i], shs[i], title[i], &s, &g) != 0;
                if (demo_image_resize(&s, cw, ch, &small) == 0) {
                    demo_image_blit(&sheet, 0, i * ch, &small);
                    demo_image_free(&small);
                }
                if (demo_image_resize(&g, gw, ch, &small) == 0) {
                    demo_image_blit(&sheet, cw, i * ch, &small);
                    demo_image_free(&small);
                }
                demo_image_free(&s);
                demo_image_free(&g);
            }
            rc |= extras_write(e, "mindepth_sheet", &sheet);
            demo_image_free(&sheet);
        }
    }
    /* ---- the frame-time cost of the read-back */
    {
        int F = e->frames;
        double* t = malloc(sizeof(double) * 8 * (size_t)F);
        if (!t) {
            rc = 1;
            goto done;
        }
        for (int f = 0; f < F; ++f) {
            glFinish();
            double t0 = demo_now_ms();
            rc |= depth_prepass(e, &m, &e->v) != 0;
            glFinish();
            double t1 = demo_now_ms();
            rc |= mip_chain(e, &m) != 0;
            glFinish();
            double t2 = demo_now_ms();
            volatile float d = read_back_min(&m);
            (void)d;
            double t3 = demo_now_ms();
            read_back_all(&m, buf);
            double t4 = demo_now_ms();
            double mn = 0;
            size_t need = 0;
            swarp_mindepth_pyramid(buf, (uint32_t)e->w, (uint32_t)e->h, (size_t)e->w, scratch, cap,
                                   &need, &mn);
            double t5 = demo_now_ms();
            swarp_mindepth_direct(buf, (uint32_t)e->w, (uint32_t)e->h, (size_t)e->w, &mn);
            double t6 = demo_now_ms();
            t[f] = t1 - t0;
            t[F + f] = t2 - t1;
            t[2 * F + f] = t3 - t2;
            t[3 * F + f] = t4 - t3;
            t[4 * F + f] = (t5 - t4) * 1e3;
            t[5 * F + f] = (t6 - t5) * 1e3;
            t[6 * F + f] = t3 - t0;
        }
        printf("  min-depth cost, %dx%d, median of %d frames:\n", e->w, e->h, F);
        printf("    depth pre-pass (3D)            %8.2f ms\n", extras_median(t, F));
        printf("    GPU mip-min chain (%2d levels)  %8.2f ms\n", m.levels, extras_median(t + F, F));
        printf("    read-back of the 1x1 level     %8.2f ms\n", extras_median(t + 2 * F, F));
        printf("    GPU path total                 %8.2f ms\n", extras_median(t + 6 * F, F));
        printf("    read-back of the whole buffer  %8.2f ms\n", extras_median(t + 3 * F, F));
        printf("    CPU swarp_mindepth_pyramid     %8.1f us\n", extras_median(t + 4 * F, F));
        printf("    CPU swarp_mindepth_direct      %8.1f us\n", extras_median(t + 5 * F, F));
        free(t);
    }
done:
    free(buf);
    free(scratch);
    md_free(&m);
    return rc;
}
