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
        fprintf(stderr, "demo: %s %s shader:\n%s\n", name,
                type == GL_VERTEX_SHADER ? "vertex" : type == GL_GEOMETRY_SHADER ? "geometry" : "fragment", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
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
