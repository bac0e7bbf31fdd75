/* extras_blur.c -- [KOZ] §14.3.2 "Blurring": the colour part of the shadow
 * map (cleared to 1; the receiver -- the ground -- draws 1, every caster 0)
 * is rendered in the same pass as the depth map, blurred by ping-pong
 * Gaussian passes at half resolution, and projected onto the receiver
 * instead of the depth test.  Everything else keeps the depth map (PCF).
 *
 * The blurred ground is drawn as a second pass over the gallery's main pass
 * (same vertex expression, depth test LEQUAL, non-receivers discarded), so
 * the rest of the picture is exactly the gallery's PCF picture. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extras.h"

/* the receiver: the ground quads (y = 0, normal +y) of demo_scene_default */
#define RECEIVER_GLSL "(a_n.y > 0.99 && abs(a_p.y) < 1e-3)"

static const char* const colour_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "layout(location = 1) in vec3 a_n;\n"
    "uniform mat4 u_m;\n"
    "flat out float v_recv;\n"
    "void main() { v_recv = " RECEIVER_GLSL " ? 1.0 : 0.0; gl_Position = u_m * vec4(a_p, 1.0); }\n";
static const char* const colour_fs =
    "flat in float v_recv;\n"
    "layout(location = 0) out vec4 o;\n"
    "void main() { o = vec4(v_recv); }\n";

static const char* const quad_vs =
    "out vec2 v_uv;\n"
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "  v_uv = p; gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";
/* one 1-D Gaussian pass (u_dir = texel step); 9 taps, sigma u_sigma texels */
static const char* const blur_fs =
    "in vec2 v_uv;\n"
    "layout(location = 0) out vec4 o;\n"
    "uniform sampler2D u_src;\n"
    "uniform vec2 u_dir;\n"
    "uniform float u_sigma;\n"
    "void main() {\n"
    "  float s = 0.0, wsum = 0.0;\n"
    "  for (int k = -4; k <= 4; ++k) {\n"
    "    float w = exp(-0.5 * float(k * k) / (u_sigma * u_sigma));\n"
    "    s += w * texture(u_src, v_uv + float(k) * u_dir).r; wsum += w;\n"
    "  }\n"
    "  o = vec4(s / wsum);\n"
    "}\n";

static const char* const ground_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "layout(location = 1) in vec3 a_n;\n"
    "layout(location = 2) in vec3 a_c;\n"
    "uniform mat4 u_view, u_proj;\n"
    "out vec3 v_p; out vec3 v_n; out vec3 v_c; out float v_depth; flat out int v_recv;\n"
    "void main() {\n"
    "  vec4 vs = u_view * vec4(a_p, 1.0);\n"
    "  v_p = a_p; v_n = a_n; v_c = a_c; v_depth = -vs.z;\n"
    "  v_recv = " RECEIVER_GLSL " ? 1 : 0;\n"
    "  gl_Position = u_proj * vs;\n"
    "}\n";
/* the gallery's lighting (render.c): v_c * (0.35 + 0.65 ndl lit) */
static const char* const ground_fs =
    "in vec3 v_p; in vec3 v_n; in vec3 v_c; in float v_depth; flat in int v_recv;\n"
    "layout(location = 0) out vec4 o_color;\n"
    "layout(location = 1) out vec4 o_tex;\n"
    "layout(location = 2) out vec4 o_pos;\n"
    "uniform sampler2D u_mask;\n"
    "uniform mat4 u_light;\n"
    "uniform vec3 u_light_dir;\n"
    "uniform float u_res;\n"
    "void main() {\n"
    "  if (v_recv == 0) discard;\n"
    "  vec3 n = normalize(v_n);\n"
    "  float ndl = max(dot(n, -normalize(u_light_dir)), 0.0);\n"
    "  vec4 h = u_light * vec4(v_p, 1.0);\n"
    "  vec3 sc = h.xyz / h.w * 0.5 + 0.5;\n"
    "  float lit = 1.0;\n"
    "  if (all(greaterThanEqual(sc.xy, vec2(0.0))) && all(lessThanEqual(sc.xy, vec2(1.0))))\n"
    "    lit = texture(u_mask, sc.xy).r;\n"
    "  if (ndl <= 0.0) lit = 0.0;\n"
    "  o_color = vec4(v_c * (0.35 + 0.65 * ndl * lit), 1.0);\n"
    "  o_tex = vec4(sc.xy * u_res, 0.0, v_depth);\n"
    "  o_pos = vec4(v_p, lit);\n"
    "}\n";

typedef struct blur_ctx {
    GLuint prog_colour, prog_blur, prog_ground;
    GLuint fbo;              /* depth layer 0 of the gallery's array + colour part */
    extras_target colour;    /* R8, map_res^2: the colour part (Fig. 14-18) */
    extras_target half[2];   /* R16F, (map_res/2)^2: ping-pong (Fig. 14-19) */
    float sigma;             /* Gaussian sigma in half-resolution texels */
    int iterations;          /* H+V pairs */
} blur_ctx;

static int blur_init(extras_env* e, blur_ctx* b) {
    memset(b, 0, sizeof *b);
    b->sigma = 2.0f;
    b->iterations = 2;
    b->prog_colour = extras_gl_program("colour part", colour_vs, NULL, colour_fs);
    b->prog_blur = extras_gl_program("blur", quad_vs, NULL, blur_fs);
    b->prog_ground = extras_gl_program("blurred ground", ground_vs, NULL, ground_fs);
    if (!b->prog_colour || !b->prog_blur || !b->prog_ground) return -1;
    if (extras_target_init(&b->colour, e->map, e->map, GL_R8, 1, 0)) return -1;
    for (int i = 0; i < 2; ++i)
        if (extras_target_init(&b->half[i], e->map / 2, e->map / 2, GL_R16F, 1, 0)) return -1;
    glGenFramebuffers(1, &b->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, b->fbo);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, e->r.shadow_tex, 0, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, b->colour.tex, 0);
    GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    int ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ok && !demo_gl_check("blur init") ? 0 : -1;
}

static void blur_free(blur_ctx* b) {
    GLuint p[3] = {b->prog_colour, b->prog_blur, b->prog_ground};
    for (int i = 0; i < 3; ++i)
        if (p[i]) glDeleteProgram(p[i]);
    if (b->fbo) glDeleteFramebuffers(1, &b->fbo);
    extras_target_free(&b->colour);
    extras_target_free(&b->half[0]);
    extras_target_free(&b->half[1]);
}

/* Step 1: depth (layer 0, as demo_render_shadow) and colour part together. */
static int colour_pass(extras_env* e, blur_ctx* b, const demo_shadow* sh) {
    glBindFramebuffer(GL_FRAMEBUFFER, b->fbo);
    glViewport(0, 0, e->map, e->map);
    const float one[4] = {1, 1, 1, 1};
    glClearBufferfv(GL_COLOR, 0, one);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    if (sh->depth_clamp) glEnable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 8.0f);
    glUseProgram(b->prog_colour);
    float m[16];
    if (swarp_mat4_to_float(&sh->light[0], m) != SWARP_OK) return 1;
    glUniformMatrix4fv(glGetUniformLocation(b->prog_colour, "u_m"), 1, GL_FALSE, m);
    glBindVertexArray(e->r.vao);
    glDrawArrays(GL_TRIANGLES, 0, e->r.vertex_count);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("colour part pass");
}

static void blur_step(extras_env* e, blur_ctx* b, GLuint src, const extras_target* dst, float dx,
                      float dy) {
    glBindFramebuffer(GL_FRAMEBUFFER, dst->fbo);
    glViewport(0, 0, dst->w, dst->h);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, src);
    glUniform1i(glGetUniformLocation(b->prog_blur, "u_src"), 0);
    glUniform2f(glGetUniformLocation(b->prog_blur, "u_dir"), dx, dy);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    (void)e;
}

/* Step 2: ping-pong Gaussian at half resolution.  The first horizontal
 * pass reads the full-resolution colour part (bilinear: a 2x2 box down). */
static int blur_passes(extras_env* e, blur_ctx* b) {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(b->prog_blur);
    glUniform1f(glGetUniformLocation(b->prog_blur, "u_sigma"), b->sigma);
    glBindVertexArray(e->r.vao);
    float t = 1.0f / (float)b->half[0].w;
    for (int it = 0; it < b->iterations; ++it) {
        blur_step(e, b, it == 0 ? b->colour.tex : b->half[1].tex, &b->half[0], t, 0);
        blur_step(e, b, b->half[0].tex, &b->half[1], 0, t);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_DEPTH_TEST);
    return demo_gl_check("blur passes");
}

/* Step 3: the receiver drawn over the gallery's main pass with the
 * projected (blurred or raw) colour part. */
static int ground_pass(extras_env* e, blur_ctx* b, const demo_shadow* sh, GLuint mask) {
    demo_renderer* r = &e->r;
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    const GLenum bufs[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(3, bufs);
    glViewport(0, 0, e->w, e->h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    GLuint p = b->prog_ground;
    glUseProgram(p);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view"), 1, GL_FALSE, e->v.view);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_proj"), 1, GL_FALSE, e->v.proj);
    float m[16];
    if (swarp_mat4_to_float(&sh->light[0], m) != SWARP_OK) return 1;
    glUniformMatrix4fv(glGetUniformLocation(p, "u_light"), 1, GL_FALSE, m);
    glUniform3f(glGetUniformLocation(p, "u_light_dir"), (float)e->v.light.direction.x,
                (float)e->v.light.direction.y, (float)e->v.light.direction.z);
    glUniform1f(glGetUniformLocation(p, "u_res"), (float)e->map);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mask);
    glUniform1i(glGetUniformLocation(p, "u_mask"), 0);
    glBindVertexArray(r->vao);
    glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("blurred ground pass");
}

static int read_mask(const extras_target* t, demo_image* im) {
    if (demo_image_alloc(im, t->w, t->h)) return -1;
    float* f = malloc(sizeof(float) * (size_t)t->w * t->h);
    if (!f) return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, t->w, t->h, GL_RED, GL_FLOAT, f);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (int y = 0; y < t->h; ++y)
        for (int x = 0; x < t->w; ++x) {
            float v = f[(size_t)(t->h - 1 - y) * t->w + x];
            uint8_t g = (uint8_t)lroundf(255.0f * fminf(fmaxf(v, 0.0f), 1.0f));
            uint8_t* px = im->px + 4 * ((size_t)y * t->w + x);
            px[0] = px[1] = px[2] = g;
            px[3] = 255;
        }
    free(f);
    return 0;
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

static int test_blur(extras_env* e, blur_ctx* b, const demo_shadow* sh) {
    /* the colour part is the depth test's answer on the receiver: the raw
     * (unblurred, nearest) colour part against the gallery's unfiltered
     * depth compare on the ground pixels */
    size_t npx = (size_t)e->w * e->h;
    float* a = malloc(sizeof(float) * 4 * npx);
    float* c = malloc(sizeof(float) * 4 * npx);
    int fails = 0;
    if (!a || !c) fails = 1;
    int errs = 0;
    demo_main_params p;
    extras_main_params(&e->v, DEMO_MODE_SHADED, DEMO_FILTER_NONE, 0, &p);
    if (!fails) {
        errs += colour_pass(e, b, sh);
        errs += demo_render_main(&e->r, sh, &p, NULL);
        demo_render_read_aux(&e->r, NULL, a);
        glBindTexture(GL_TEXTURE_2D, b->colour.tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        errs += ground_pass(e, b, sh, b->colour.tex);
        glBindTexture(GL_TEXTURE_2D, b->colour.tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        demo_render_read_aux(&e->r, NULL, c);
        long ground = 0, agree = 0, shadowed = 0;
        for (size_t i = 0; i < npx; ++i) {
            const float* q = a + 4 * i;
            if (q[3] < 0 || fabsf(q[1]) > 1e-3f) continue;
            ++ground;
            shadowed += q[3] < 0.5f;
            agree += (q[3] < 0.5f) == (c[4 * i + 3] < 0.5f);
        }
        double frac = ground ? (double)agree / ground : 0;
        /* disagreement only along shadow edges (the gallery's normal-offset
         * bias moves them by up to a texel) */
        int ok = errs == 0 && ground > 1000 && shadowed > 100 && frac >= 0.98;
        printf("blur: raw colour part vs depth compare on %ld ground pixels (%ld in shadow): "
               "%.3f%% agree %s\n",
               ground, shadowed, 100 * frac, ok ? "ok" : "FAIL");
        fails += !ok;
        /* the blur keeps the values in [0, 1] and makes a penumbra */
        errs += blur_passes(e, b);
        demo_image bl;
        if (read_mask(&b->half[1], &bl) == 0) {
            long grey = 0;
            for (size_t i = 0; i < (size_t)bl.w * bl.h; ++i)
                grey += bl.px[4 * i] > 12 && bl.px[4 * i] < 243;
            int ok2 = errs == 0 && grey > 100;
            printf("blur: %ld penumbra texels (between 0.05 and 0.95) after %d Gaussian pairs %s\n",
                   grey, b->iterations, ok2 ? "ok" : "FAIL");
            fails += !ok2;
            demo_image_free(&bl);
        } else {
            ++fails;
        }
    }
    free(a);
    free(c);
    return fails ? 1 : 0;
}

int extras_blur(extras_env* e, int test) {
    blur_ctx b;
    if (blur_init(e, &b)) {
        blur_free(&b);
        return 1;
    }
    demo_shadow sh;
    int rc = 0;
    if (extras_setup(e, &e->v, DEMO_TECH_UNIFORM, 1, &sh)) {
        blur_free(&b);
        return 1;
    }
    if (test) {
        rc = test_blur(e, &b, &sh);
        blur_free(&b);
        return rc;
    }
    /* timing, interleaved per frame */
    int F = e->frames;
    double* t = malloc(sizeof(double) * 6 * (size_t)F);
    if (!t) {
        blur_free(&b);
        return 1;
    }
    demo_main_params p3, p5;
    extras_main_params(&e->v, DEMO_MODE_SHADED, DEMO_FILTER_PCF3, 0, &p3);
    extras_main_params(&e->v, DEMO_MODE_SHADED, DEMO_FILTER_PCF5, 0, &p5);
    for (int f = 0; f < F; ++f) {
        double ms;
        rc |= demo_render_shadow(&e->r, &sh, DEMO_FILTER_PCF3, &ms) != 0;
        t[f] = ms;
        glFinish();
        double t0 = demo_now_ms();
        rc |= colour_pass(e, &b, &sh) != 0;
        glFinish();
        t[F + f] = demo_now_ms() - t0;
        t0 = demo_now_ms();
        rc |= blur_passes(e, &b) != 0;
        glFinish();
        t[2 * F + f] = demo_now_ms() - t0;
        rc |= demo_render_main(&e->r, &sh, &p5, &t[3 * F + f]) != 0;
        rc |= demo_render_main(&e->r, &sh, &p3, &t[4 * F + f]) != 0;
        glFinish();
        t0 = demo_now_ms();
        rc |= ground_pass(e, &b, &sh, b.half[1].tex) != 0;
        glFinish();
        t[5 * F + f] = demo_now_ms() - t0;
    }
    const char* what[6] = {"shadow pass, depth only (gallery)",
                           "shadow pass, depth + colour part",
                           "blur: 2x(H+V) 9-tap Gaussian at half res",
                           "main pass PCF 5x5 (gallery)",
                           "main pass PCF 3x3 (gallery)",
                           "blurred-ground pass over the PCF 3x3 picture"};
    printf("  [KOZ] 14.3.2 projective blur, %dx%d, map %d^2, median of %d frames:\n", e->w, e->h,
           e->map, F);
    for (int k = 0; k < 6; ++k) printf("  %-46s %8.2f ms\n", what[k], extras_median(t + k * F, F));
    free(t);

    /* pictures: the colour part raw and blurred; PCF vs blur, full and crop */
    demo_image raw, blurred, pcf, blur, sheet;
    rc |= colour_pass(e, &b, &sh) != 0;
    rc |= blur_passes(e, &b) != 0;
    if (read_mask(&b.colour, &raw) || read_mask(&b.half[1], &blurred)) rc = 1;
    rc |= demo_render_main(&e->r, &sh, &p3, NULL) != 0;
    if (demo_image_alloc(&pcf, e->w, e->h) == 0) demo_render_read_color(&e->r, e->w, e->h, pcf.px);
    rc |= ground_pass(e, &b, &sh, b.half[1].tex) != 0;
    if (demo_image_alloc(&blur, e->w, e->h) == 0) demo_render_read_color(&e->r, e->w, e->h, blur.px);
    const int cw = 640, ch = 360, ms = 360;
    if (demo_image_alloc(&sheet, 2 * cw, 2 * ch + ms) == 0) {
        const uint8_t white[3] = {255, 255, 255};
        demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, white);
        demo_image s;
        if (demo_image_resize(&raw, ms, ms, &s) == 0) {
            demo_image_blit(&sheet, (cw - ms) / 2, 0, &s);
            demo_image_free(&s);
        }
        if (demo_image_resize(&blurred, ms, ms, &s) == 0) {
            demo_image_blit(&sheet, cw + (cw - ms) / 2, 0, &s);
            demo_image_free(&s);
        }
        demo_image_label(&sheet, 8, 8, 1, "colour part: 1 receiver, 0 casters (Fig. 14-18)");
        demo_image_label(&sheet, cw + 8, 8, 1, "blurred, 2x(H+V) Gaussian at half res (Fig. 14-19)");
        /* crop: the ground in front of the camera */
        int x0 = e->w * 3 / 10, y0 = e->h * 11 / 20, w0 = e->w * 2 / 5, h0 = e->h * 2 / 5;
        const demo_image* pics[2] = {&pcf, &blur};
        const char* labs[2] = {"PCF 3x3 on everything (gallery)",
                               "[KOZ] 14.3.2: blurred colour part on the ground"};
        for (int k = 0; k < 2; ++k) {
            if (demo_image_resize(pics[k], cw, ch, &s) == 0) {
                demo_image_blit(&sheet, k * cw, ms, &s);
                demo_image_free(&s);
            }
            if (crop(pics[k], x0, y0, w0, h0, cw, ch, &s) == 0) {
                demo_image_blit(&sheet, k * cw, ms + ch, &s);
                demo_image_free(&s);
            }
            demo_image_label(&sheet, k * cw + 8, ms + 8, 1, labs[k]);
            demo_image_label(&sheet, k * cw + 8, ms + ch + 8, 1, "crop, 2.5x");
        }
        rc |= extras_write(e, "blur_sheet", &sheet);
        demo_image_free(&sheet);
    }
    demo_image_free(&raw);
    demo_image_free(&blurred);
    demo_image_free(&pcf);
    demo_image_free(&blur);
    blur_free(&b);
    return rc;
}
