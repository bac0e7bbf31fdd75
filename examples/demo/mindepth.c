/* mindepth.c -- [RHS] §4.3 min-depth near plane: the viewer's linear depth
 * rendered into an R32F texture, reduced on the GPU by a chain of 2x2 min
 * passes (Listing A.2) to 1x1 and read back; the same buffer read back and
 * reduced on the CPU by the library (swarp_mindepth_pyramid, _direct); the
 * adjusted near plane from swarp_mindepth_near. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"

static const char* const lin_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "uniform mat4 u_view, u_proj;\n"
    "out float v_depth;\n"
    "void main() {\n"
    "  vec4 vs = u_view * vec4(a_p, 1.0);\n"
    "  v_depth = -vs.z;\n"
    "  gl_Position = u_proj * vs;\n"
    "}\n";
static const char* const lin_fs =
    "in float v_depth;\n"
    "layout(location = 0) out float o_d;\n"
    "void main() { o_d = v_depth; }\n";
/* one level of the chain: each output texel is the min of its (up to) 2x2
 * source texels; an odd last row/column takes only the texels that exist
 * (clamping to the last texel repeats one, which leaves the min unchanged) */
static const char* const quad_vs =
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID & 2) * 2 - 1);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";
static const char* const min_fs =
    "uniform sampler2D u_src;\n"
    "uniform ivec2 u_src_size;\n"
    "layout(location = 0) out float o_d;\n"
    "void main() {\n"
    "  ivec2 o = ivec2(gl_FragCoord.xy) * 2;\n"
    "  ivec2 m = u_src_size - 1;\n"
    "  float a = texelFetch(u_src, min(o, m), 0).r;\n"
    "  float b = texelFetch(u_src, min(o + ivec2(1, 0), m), 0).r;\n"
    "  float c = texelFetch(u_src, min(o + ivec2(0, 1), m), 0).r;\n"
    "  float d = texelFetch(u_src, min(o + ivec2(1, 1), m), 0).r;\n"
    "  o_d = min(min(a, b), min(c, d));\n"
    "}\n";

static GLuint r32f(int w, int h) {
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, w, h, 0, GL_RED, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

/* Step 3 of demo_mindepth: the level-0 buffer (lvl0, bound to the current
 * framebuffer) read back whole and reduced by swarp_mindepth_pyramid and
 * swarp_mindepth_direct, each timed.  0, or -1 when either failed. */
static int cpu_reductions(int w, int h, GLuint lvl0, demo_mindepth_result* out) {
    float* buf0 = malloc(sizeof(float) * (size_t)w * h);
    int rc = buf0 ? 0 : -1;
    if (buf0) {
        double t0 = demo_now_ms();
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, lvl0, 0);
        glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, buf0);
        out->readback_ms = demo_now_ms() - t0;
        size_t need = SWARP_MINDEPTH_SCRATCH(w, h), got = 0;
        float* scratch = malloc(sizeof(float) * need);
        swarp_status s1 = SWARP_ERR_NULL_POINTER, s2;
        t0 = demo_now_ms();
        if (scratch)
            s1 = swarp_mindepth_pyramid(buf0, (uint32_t)w, (uint32_t)h, (size_t)w, scratch, need,
                                        &got, &out->cpu_pyramid_min);
        out->cpu_pyramid_ms = demo_now_ms() - t0;
        t0 = demo_now_ms();
        s2 = swarp_mindepth_direct(buf0, (uint32_t)w, (uint32_t)h, (size_t)w, &out->cpu_direct_min);
        out->cpu_direct_ms = demo_now_ms() - t0;
        if (swarp_status_is_error(s1) || swarp_status_is_error(s2)) {
            fprintf(stderr, "demo: swarp_mindepth_*: %s / %s\n", swarp_status_string(s1),
                    swarp_status_string(s2));
            rc = -1;
        }
        free(scratch);
        free(buf0);
    }
    return rc;
}

int demo_mindepth(demo_renderer* r, const demo_view* v, demo_mindepth_result* out) {
    memset(out, 0, sizeof *out);
    int w = v->w, h = v->h;
    GLuint lin = demo_gl_program("linear depth", lin_vs, lin_fs);
    GLuint red = demo_gl_program("min chain", quad_vs, min_fs);
    if (!lin || !red) return -1;
    GLuint fbo, rb_depth, empty_vao;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &rb_depth);
    glGenVertexArrays(1, &empty_vao);
    glBindRenderbuffer(GL_RENDERBUFFER, rb_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    GLuint lvl0 = r32f(w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, lvl0, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb_depth);
    GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    int errors = 0;
    /* 1. the linear depth pass; "nothing here" is +INFINITY */
    double t0 = demo_now_ms();
    glViewport(0, 0, w, h);
    const float inf[4] = {INFINITY, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, inf);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(lin);
    glUniformMatrix4fv(glGetUniformLocation(lin, "u_view"), 1, GL_FALSE, v->view);
    glUniformMatrix4fv(glGetUniformLocation(lin, "u_proj"), 1, GL_FALSE, v->proj);
    glBindVertexArray(r->vao);
    glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    glFinish();
    out->depth_pass_ms = demo_now_ms() - t0;
    errors += demo_gl_check("linear depth pass");
    /* 2. the GPU chain of 2x2 min passes down to 1x1 */
    t0 = demo_now_ms();
    glDisable(GL_DEPTH_TEST);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    glUseProgram(red);
    glBindVertexArray(empty_vao);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(red, "u_src"), 0);
    GLuint src = lvl0;
    int sw = w, shh = h, levels = 0;
    while (sw > 1 || shh > 1) {
        int dw = (sw + 1) / 2, dh = (shh + 1) / 2;
        GLuint dst = r32f(dw, dh);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, dst, 0);
        glViewport(0, 0, dw, dh);
        glBindTexture(GL_TEXTURE_2D, src);
        glUniform2i(glGetUniformLocation(red, "u_src_size"), sw, shh);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (src != lvl0) glDeleteTextures(1, &src);
        src = dst;
        sw = dw;
        shh = dh;
        ++levels;
    }
    float gpu_min = 0;
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, 1, 1, GL_RED, GL_FLOAT, &gpu_min);
    out->chain_ms = demo_now_ms() - t0; /* the read-back of one texel included */
    out->levels = levels;
    errors += demo_gl_check("min chain");
    glDeleteTextures(1, &src);
    /* 3. the whole buffer read back and reduced on the CPU by the library */
    int rc = cpu_reductions(w, h, lvl0, out);
    out->gpu_min = gpu_min;
    swarp_status s3 = swarp_mindepth_near(v->cam.z_near, v->cam.z_far, out->gpu_min, NULL,
                                          &out->adjusted_near);
    if (swarp_status_is_error(s3)) rc = -1;
    glDeleteTextures(1, &lvl0);
    glDeleteRenderbuffers(1, &rb_depth);
    glDeleteFramebuffers(1, &fbo);
    glDeleteVertexArrays(1, &empty_vao);
    glDeleteProgram(lin);
    glDeleteProgram(red);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    out->gl_errors = errors;
    return rc;
}
