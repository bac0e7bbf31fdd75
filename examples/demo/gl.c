/* gl.c -- GL entry points and shader helpers. */
#include "gl.h"

#include <stdio.h>
#include <stdlib.h>

#include "ctx.h"

#define DEMO_GL_DEFINE_(type, name) type dgl_##name;
DEMO_GL_FUNCS(DEMO_GL_DEFINE_)
#undef DEMO_GL_DEFINE_

int demo_gl_load(void) {
    int missing = 0;
#define DEMO_GL_LOAD_(type, name)                                       \
    dgl_##name = (type)demo_ctx_getproc(#name);                         \
    if (!dgl_##name) {                                                  \
        fprintf(stderr, "demo: GL entry point %s missing\n", #name);   \
        missing = 1;                                                    \
    }
    DEMO_GL_FUNCS(DEMO_GL_LOAD_)
#undef DEMO_GL_LOAD_
    return missing ? -1 : 0;
}

static GLuint compile_parts(const char* name, GLenum type, const char* const* src, int n) {
    const char* parts[8] = {"#version 450 core\n"};
    if (n > 7) n = 7;
    for (int i = 0; i < n; ++i) parts[i + 1] = src[i];
    GLuint s = glCreateShader(type);
    glShaderSource(s, n + 1, parts, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "demo: %s %s shader:\n%s\n", name,
                type == GL_VERTEX_SHADER ? "vertex" : type == GL_GEOMETRY_SHADER ? "geometry" : "fragment", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static GLuint compile(const char* name, GLenum type, const char* src) {
    return compile_parts(name, type, &src, 1);
}

GLuint demo_gl_program_parts(const char* name, const char* vs, const char* const* fs_parts,
                             int fs_count) {
    GLuint v = compile(name, GL_VERTEX_SHADER, vs);
    GLuint f = compile_parts(name, GL_FRAGMENT_SHADER, fs_parts, fs_count);
    if (!v || !f) {
        if (v) glDeleteShader(v);
        if (f) glDeleteShader(f);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        fprintf(stderr, "demo: %s link:\n%s\n", name, log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

GLuint demo_gl_program(const char* name, const char* vs, const char* fs) {
    return demo_gl_program_gs(name, vs, NULL, fs);
}

GLuint demo_gl_program_gs(const char* name, const char* vs, const char* gs, const char* fs) {
    GLuint v = compile(name, GL_VERTEX_SHADER, vs);
    GLuint g = gs ? compile(name, GL_GEOMETRY_SHADER, gs) : 0;
    GLuint f = fs ? compile(name, GL_FRAGMENT_SHADER, fs) : 0;
    if (!v || (fs && !f) || (gs && !g)) {
        if (v) glDeleteShader(v);
        if (g) glDeleteShader(g);
        if (f) glDeleteShader(f);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    if (g) glAttachShader(p, g);
    if (f) glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    if (g) glDeleteShader(g);
    if (f) glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        fprintf(stderr, "demo: %s link:\n%s\n", name, log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

int demo_gl_check(const char* pass) {
    int n = 0;
    GLenum e;
    while ((e = glGetError()) != GL_NO_ERROR && n < 16) {
        fprintf(stderr, "demo: GL error 0x%04x after %s\n", (unsigned)e, pass);
        ++n;
    }
    return n;
}
