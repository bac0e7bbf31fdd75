/* extras_gl.c -- extra GL entry points and the geometry-stage program builder. */
#include "extras_gl.h"

#include <stdio.h>
#include <string.h>

#include "ctx.h"

#define EXTRAS_GL_DEFINE_(type, name) type xgl_##name;
EXTRAS_GL_FUNCS(EXTRAS_GL_DEFINE_)
#undef EXTRAS_GL_DEFINE_

int extras_gl_load(void) {
    int missing = 0;
#define EXTRAS_GL_LOAD_(type, name)                                     \
    xgl_##name = (type)demo_ctx_getproc(#name);                         \
    if (!xgl_##name) {                                                  \
        fprintf(stderr, "demo-extras: GL entry point %s missing\n", #name); \
        missing = 1;                                                    \
    }
    EXTRAS_GL_FUNCS(EXTRAS_GL_LOAD_)
#undef EXTRAS_GL_LOAD_
    return missing ? -1 : 0;
}

static GLuint compile(const char* name, GLenum type, const char* src) {
    const char* parts[2] = {"#version 450 core\n", src};
    GLuint s = glCreateShader(type);
    glShaderSource(s, 2, parts, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "demo-extras: %s %s shader:\n%s\n", name,
                type == GL_VERTEX_SHADER     ? "vertex"
                : type == GL_GEOMETRY_SHADER ? "geometry"
                                             : "fragment",
                log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

GLuint extras_gl_program(const char* name, const char* vs, const char* gs, const char* fs) {
    GLuint sh[3] = {compile(name, GL_VERTEX_SHADER, vs),
                    gs ? compile(name, GL_GEOMETRY_SHADER, gs) : 0,
                    fs ? compile(name, GL_FRAGMENT_SHADER, fs) : 0};
    if (!sh[0] || (gs && !sh[1]) || (fs && !sh[2])) {
        for (int i = 0; i < 3; ++i)
            if (sh[i]) glDeleteShader(sh[i]);
        return 0;
    }
    GLuint p = glCreateProgram();
    for (int i = 0; i < 3; ++i)
        if (sh[i]) glAttachShader(p, sh[i]);
    glLinkProgram(p);
    for (int i = 0; i < 3; ++i)
        if (sh[i]) glDeleteShader(sh[i]);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        fprintf(stderr, "demo-extras: %s link:\n%s\n", name, log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

int extras_target_init(extras_target* t, int w, int h, GLenum internal_format, int linear,
                       int depth) {
    memset(t, 0, sizeof *t);
    t->w = w;
    t->h = h;
    glGenTextures(1, &t->tex);
    glBindTexture(GL_TEXTURE_2D, t->tex);
    GLenum fmt = GL_RED, type = GL_FLOAT;
    if (internal_format == GL_R8) type = GL_UNSIGNED_BYTE;
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal_format, w, h, 0, fmt, type, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenFramebuffers(1, &t->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->tex, 0);
    if (depth) {
        glGenRenderbuffers(1, &t->depth_rb);
        glBindRenderbuffer(GL_RENDERBUFFER, t->depth_rb);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  t->depth_rb);
    }
    GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    int ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) fprintf(stderr, "demo-extras: %dx%d target incomplete\n", w, h);
    return ok ? 0 : -1;
}

void extras_target_free(extras_target* t) {
    if (t->tex) glDeleteTextures(1, &t->tex);
    if (t->fbo) glDeleteFramebuffers(1, &t->fbo);
    if (t->depth_rb) glDeleteRenderbuffers(1, &t->depth_rb);
    memset(t, 0, sizeof *t);
}
