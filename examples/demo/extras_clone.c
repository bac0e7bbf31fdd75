/* extras_clone.c -- single-pass split rendering by geometry cloning, [RHS]
 * §3.3.6 and Listing A.1 ([ZSN07]): the scene is sent once; a geometry
 * shader emits every triangle once per split with that split's light matrix,
 * gl_Layer = split (the layer of the depth array the gallery samples) and
 * gl_ViewportIndex = split (the split's viewport from the viewport array:
 * sh->viewport[i], the part of the layer the split uses).  Against the
 * gallery's K + 1 passes (demo_render_shadow: one pass per split).
 *
 * Listing A.1 loops over g_firstSplit..g_lastSplit, the splits a CPU pass
 * found for the object's bounding box; this scene is one triangle soup, so
 * the per-object range is every split, and the optional per-triangle cull
 * (u_cull) drops a clone whose three vertices lie outside the same side
 * plane of the split's clip volume -- the GPU-side analogue. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extras.h"

static const char* const clone_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "void main() { gl_Position = vec4(a_p, 1.0); }\n";

/* u_m[s] * p is the same float expression the gallery's depth pass
 * evaluates per split (u_m * vec4(a_p, 1.0)), so both paths rasterise the
 * same clip coordinates. */
static const char* const clone_gs =
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 48) out;\n"
    "uniform mat4 u_m[16];\n"
    "uniform int u_count, u_cull;\n"
    "void main() {\n"
    "  for (int s = 0; s < u_count; ++s) {\n"
    "    vec4 c[3];\n"
    "    for (int k = 0; k < 3; ++k) c[k] = u_m[s] * gl_in[k].gl_Position;\n"
    "    if (u_cull != 0) {\n"
    "      bool out_side = false;\n"
    "      for (int a = 0; a < 2; ++a) {\n"
    "        if (c[0][a] > c[0].w && c[1][a] > c[1].w && c[2][a] > c[2].w) out_side = true;\n"
    "        if (c[0][a] < -c[0].w && c[1][a] < -c[1].w && c[2][a] < -c[2].w) out_side = true;\n"
    "      }\n"
    "      if (out_side) continue;\n"
    "    }\n"
    "    for (int k = 0; k < 3; ++k) {\n"
    "      gl_Position = c[k];\n"
    "      gl_Layer = s;\n"
    "      gl_ViewportIndex = s;\n"
    "      EmitVertex();\n"
    "    }\n"
    "    EndPrimitive();\n"
    "  }\n"
    "}\n";

typedef struct clone_ctx {
    GLuint prog, fbo;
} clone_ctx;

static int clone_init(extras_env* e, clone_ctx* c) {
    memset(c, 0, sizeof *c);
    GLint maxvp = 0;
    glGetIntegerv(GL_MAX_VIEWPORTS, &maxvp);
    if (maxvp < DEMO_MAX_SPLITS) {
        fprintf(stderr, "demo-extras: only %d viewports\n", maxvp);
        return -1;
    }
    c->prog = extras_gl_program("geometry cloning", clone_vs, clone_gs, NULL);
    if (!c->prog) return -1;
    glGenFramebuffers(1, &c->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);
    /* layered: every layer of the depth array at once */
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, e->r.shadow_tex, 0);
    GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    int ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) fprintf(stderr, "demo-extras: layered shadow framebuffer incomplete\n");
    return ok && !demo_gl_check("cloning init") ? 0 : -1;
}

static void clone_free(clone_ctx* c) {
    if (c->prog) glDeleteProgram(c->prog);
    if (c->fbo) glDeleteFramebuffers(1, &c->fbo);
}

/* All K maps in one pass; the same state as demo_render_shadow (depth
 * compare maps: depth test LESS, slope-scaled offset 2, 8, depth clamp
 * when the configuration asks for it). */
static int clone_pass(extras_env* e, const clone_ctx* c, const demo_shadow* sh, int cull) {
    demo_renderer* r = &e->r;
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);
    glViewport(0, 0, r->map_res, r->map_res);
    glEnable(GL_DEPTH_TEST);
    if (sh->depth_clamp) glEnable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glClear(GL_DEPTH_BUFFER_BIT); /* layered attachment: clears every layer */
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 8.0f);
    glUseProgram(c->prog);
    float m[16 * DEMO_MAX_SPLITS];
    for (int i = 0; i < sh->count; ++i) {
        if (swarp_mat4_to_float(&sh->light[i], m + 16 * i) != SWARP_OK) return 1;
        glViewportIndexedf((GLuint)i, 0, 0, (float)sh->viewport[i][0], (float)sh->viewport[i][1]);
    }
    glUniformMatrix4fv(glGetUniformLocation(c->prog, "u_m"), sh->count, GL_FALSE, m);
    glUniform1i(glGetUniformLocation(c->prog, "u_count"), sh->count);
    glUniform1i(glGetUniformLocation(c->prog, "u_cull"), cull);
    glBindVertexArray(r->vao);
    glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    glViewport(0, 0, r->map_res, r->map_res); /* resets every viewport of the array */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("geometry cloning pass");
}

/* The K + 1 version for timing: demo_render_shadow's passes without its
 * per-pass glFinish (which it needs for per-pass times), so both versions
 * are timed the same way, one glFinish around all the passes. */
static int multi_pass(extras_env* e, const demo_shadow* sh) {
    demo_renderer* r = &e->r;
    glBindFramebuffer(GL_FRAMEBUFFER, r->shadow_fbo);
    GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    glUseProgram(r->prog_depth);
    glBindVertexArray(r->vao);
    glEnable(GL_DEPTH_TEST);
    if (sh->depth_clamp) glEnable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 8.0f);
    GLint loc = glGetUniformLocation(r->prog_depth, "u_m");
    for (int i = 0; i < sh->count; ++i) {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, r->shadow_tex, 0, i);
        glViewport(0, 0, r->map_res, r->map_res);
        glClear(GL_DEPTH_BUFFER_BIT);
        glViewport(0, 0, sh->viewport[i][0], sh->viewport[i][1]);
        float m[16];
        if (swarp_mat4_to_float(&sh->light[i], m) != SWARP_OK) return 1;
        glUniformMatrix4fv(loc, 1, GL_FALSE, m);
        glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("multi-pass shadow");
}

/* main pass; the shadow mask (pos.w = lit) read back into mask */
static int main_mask(extras_env* e, const demo_shadow* sh, demo_filter f, float* pos,
                     double* ms) {
    demo_main_params p;
    extras_main_params(&e->v, DEMO_MODE_SHADED, f, sh->count > 1 ? 0.1f : 0.0f, &p);
    int errs = demo_render_main(&e->r, sh, &p, ms);
    if (pos) demo_render_read_aux(&e->r, NULL, pos);
    return errs;
}

static int test_cloning(extras_env* e, clone_ctx* c) {
    size_t npx = (size_t)e->w * e->h;
    float* a = malloc(sizeof(float) * 4 * npx);
    float* b = malloc(sizeof(float) * 4 * npx);
    if (!a || !b) {
        free(a);
        free(b);
        return 1;
    }
    int fails = 0;
    const struct {
        demo_technique t;
        int k;
        const char* cam;
    } cases[] = {{DEMO_TECH_PSSM, 4, "default"},       {DEMO_TECH_PSSM_LISPSM, 4, "default"},
                 {DEMO_TECH_PSSM_LISPSM, 8, "high"},   {DEMO_TECH_PSSM, 16, "default"},
                 {DEMO_TECH_PSSM_STABLE, 4, "street"}};
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ++ci) {
        demo_view v = e->v;
        extras_camera_preset(cases[ci].cam, v.w, v.h, &v.cam);
        demo_view_update(&v);
        demo_view saved = e->v;
        e->v = v;
        demo_shadow sh;
        if (extras_setup(e, &v, cases[ci].t, cases[ci].k, &sh)) {
            e->v = saved;
            ++fails;
            continue;
        }
        for (int cull = 0; cull < 2; ++cull) {
            /* reference: the gallery's K passes */
            int errs = demo_render_shadow(&e->r, &sh, DEMO_FILTER_NONE, NULL);
            errs += main_mask(e, &sh, DEMO_FILTER_NONE, a, NULL);
            errs += clone_pass(e, c, &sh, cull);
            errs += main_mask(e, &sh, DEMO_FILTER_NONE, b, NULL);
            long n = 0, diff = 0, shadowed = 0;
            for (size_t i = 0; i < npx; ++i) {
                if (a[4 * i + 3] < 0) continue; /* sky */
                ++n;
                shadowed += a[4 * i + 3] < 0.5f;
                diff += memcmp(&a[4 * i + 3], &b[4 * i + 3], sizeof(float)) != 0;
            }
            /* pixel-identical: the same clip coordinates, the same
             * rasteriser, the same depth offset */
            int ok = errs == 0 && diff == 0 && n > 1000 && shadowed > 100;
            printf("cloning %-12s K=%-2d %-8s cull=%d: %ld pixels (%ld in shadow), %ld differ from "
                   "the %d-pass maps %s\n",
                   demo_technique_name(cases[ci].t), cases[ci].k, cases[ci].cam, cull, n, shadowed,
                   diff, sh.count, ok ? "ok" : "FAIL");
            fails += !ok;
        }
        if (ci == 0) {
            /* negative control: maps 0 and 1 swapped must show */
            demo_shadow bad = sh;
            bad.light[0] = sh.light[1];
            bad.light[1] = sh.light[0];
            int errs = clone_pass(e, c, &bad, 0);
            errs += main_mask(e, &sh, DEMO_FILTER_NONE, b, NULL);
            long diff = 0;
            for (size_t i = 0; i < npx; ++i)
                diff += a[4 * i + 3] >= 0 && memcmp(&a[4 * i + 3], &b[4 * i + 3], sizeof(float));
            int ok = errs == 0 && diff > 1000;
            printf("cloning control: maps 0 and 1 swapped: %ld pixels differ (must be many) %s\n",
                   diff, ok ? "ok" : "FAIL");
            fails += !ok;
        }
        e->v = saved;
    }
    free(a);
    free(b);
    return fails ? 1 : 0;
}

int extras_cloning(extras_env* e, int test, extras_bench_row* rows, int* nrows) {
    clone_ctx c;
    if (clone_init(e, &c)) {
        clone_free(&c);
        return 1;
    }
    if (test) {
        int rc = test_cloning(e, &c);
        clone_free(&c);
        return rc;
    }
    /* The table of [RHS] Tables 7.1/7.2 on this machine: every variant of
     * one K is run in the same frame loop, so load changes hit all alike.
     * Variants: 0 the K + 1 passes, 1 + 2 geometry cloning without / with
     * the per-triangle cull, 3 the automatic adjusted near plane ([RHS]
     * §4.3: depth pre-pass, GPU mip-min chain, 1x1 read-back, then the
     * K + 1 passes of the configuration set up with that near plane). */
    enum { NV = 4 };
    int F = e->frames, rc = 0;
    double* t = malloc(sizeof(double) * 3 * NV * (size_t)F); /* shadow, extra, main */
    extras_md* md = extras_md_create(e);
    double near_adj = extras_measured_near(e, &e->v);
    if (!t || !md || !(near_adj > 0)) {
        free(t);
        extras_md_destroy(md);
        clone_free(&c);
        return 1;
    }
    demo_view va = e->v;
    va.cam.near = near_adj;
    demo_view_update(&va);
#define T_SH(v, f) t[(3 * (v) + 0) * F + (f)]
#define T_EX(v, f) t[(3 * (v) + 1) * F + (f)]
#define T_MN(v, f) t[(3 * (v) + 2) * F + (f)]
    const int ks[4] = {1, 4, 8, 16};
    for (int ki = 0; ki < 4; ++ki) {
        int K = ks[ki];
        demo_technique tech = K == 1 ? DEMO_TECH_LISPSM : DEMO_TECH_PSSM_LISPSM;
        demo_shadow sh, sh_adj;
        if (extras_setup(e, &e->v, tech, K, &sh) || extras_setup(e, &va, tech, K, &sh_adj)) {
            rc = 1;
            break;
        }
        memset(t, 0, sizeof(double) * 3 * NV * (size_t)F);
        for (int f = 0; f < F; ++f) {
            for (int v = 0; v < NV; ++v) {
                if (K == 1 && (v == 1 || v == 2)) continue;
                const demo_shadow* s = v == 3 ? &sh_adj : &sh;
                if (v == 3) {
                    T_EX(v, f) = extras_md_frame(e, md, &e->v, NULL);
                    rc |= T_EX(v, f) < 0;
                }
                glFinish();
                double t0 = demo_now_ms();
                if (v == 0 || v == 3) rc |= multi_pass(e, s) != 0;
                else rc |= clone_pass(e, &c, s, v == 2) != 0;
                glFinish();
                T_SH(v, f) = demo_now_ms() - t0;
                demo_main_params p;
                extras_main_params(v == 3 ? &va : &e->v, DEMO_MODE_SHADED, DEMO_FILTER_PCF3,
                                   K > 1 ? 0.1f : 0.0f, &p);
                rc |= demo_render_main(&e->r, s, &p, &T_MN(v, f)) != 0;
            }
        }
        const int order[NV] = {0, 3, 1, 2};
        for (int oi = 0; oi < NV && rows && *nrows < 32; ++oi) {
            int v = order[oi];
            if (K == 1 && (v == 1 || v == 2)) continue;
            extras_bench_row* row = &rows[(*nrows)++];
            memset(row, 0, sizeof *row);
            char base[24];
            if (K == 1) snprintf(base, sizeof base, "LiSPSM");
            else snprintf(base, sizeof base, "PSSM(%d) + LiSPSM", K);
            if (v == 0) snprintf(row->name, sizeof row->name, "%s", base);
            else if (v == 3) snprintf(row->name, sizeof row->name, "Automatic adjusted zNear + %s", base);
            else if (v == 1) snprintf(row->name, sizeof row->name, "Geometry Cloning %s", base);
            else snprintf(row->name, sizeof row->name, "Geometry Cloning + tri cull %s", base);
            if (v == 0) snprintf(row->passes, sizeof row->passes, "%d + 1", K);
            else if (v == 3) snprintf(row->passes, sizeof row->passes, "1 + %d + 1", K);
            else snprintf(row->passes, sizeof row->passes, "1 + 1");
            double frame[512];
            int n = F < 512 ? F : 512;
            for (int f = 0; f < n; ++f) frame[f] = T_SH(v, f) + T_EX(v, f) + T_MN(v, f);
            row->frame_ms = extras_median(frame, n);
            row->shadow_ms = extras_median(&T_SH(v, 0), F);
            row->extra_ms = extras_median(&T_EX(v, 0), F);
            row->main_ms = extras_median(&T_MN(v, 0), F);
        }
        printf("  K=%d: every variant timed over %d frames (adjusted near %.2f)\n", K, F, near_adj);
    }
#undef T_SH
#undef T_EX
#undef T_MN
    extras_md_destroy(md);
    free(t);
    clone_free(&c);
    return rc;
}
