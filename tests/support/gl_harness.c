/* gl_harness: see gl_harness.h. */
#define _POSIX_C_SOURCE 200809L
#include "gl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define GLH_DEF(type, name) type p_##name;
GLH_FUNCS(GLH_DEF)
#undef GLH_DEF

static int load_gl(const char* tag) {
    int ok = 1;
#define LOAD(type, name)                                         \
    p_##name = (type)(void (*)(void))OSMesaGetProcAddress(#name); \
    if (!p_##name) {                                             \
        fprintf(stderr, "%s: missing %s\n", tag, #name);         \
        ok = 0;                                                  \
    }
    GLH_FUNCS(LOAD)
#undef LOAD
    return ok;
}

OSMesaContext glh_open(const char* tag) {
    static const int versions[][2] = {{4, 5}, {4, 3}};
    OSMesaContext ctx = NULL;
    for (int v = 0; v < 2 && !ctx; ++v) {
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, versions[v][0],
                               OSMESA_CONTEXT_MINOR_VERSION, versions[v][1], 0};
        ctx = OSMesaCreateContextAttribs(attribs, NULL);
    }
    if (!ctx) {
        fprintf(stderr, "%s: no GL 4.3+ core context: skipped\n", tag);
        return NULL;
    }
    static unsigned char fb[4 * 4 * 4];
    if (!OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, 4, 4) || !load_gl(tag)) {
        OSMesaDestroyContext(ctx);
        fprintf(stderr, "%s: cannot make the context current: skipped\n", tag);
        return NULL;
    }
    return ctx;
}

void glh_close(OSMesaContext ctx) {
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

char* glh_read_file(const char* path) {
    FILE* f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char* s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n) {
        free(s);
        s = NULL;
    }
    if (s) s[n] = 0;
    fclose(f);
    return s;
}

GLuint glh_compile(const char* tag, const char* const* parts, int n_parts, const char* what) {
    GLuint s = p_glCreateShader(GL_COMPUTE_SHADER);
    p_glShaderSource(s, n_parts, parts, NULL);
    p_glCompileShader(s);
    GLint ok = 0;
    p_glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[8192];
        p_glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "%s: %s does not compile:\n%s\n", tag, what, log);
        p_glDeleteShader(s);
        return 0;
    }
    GLuint p = p_glCreateProgram();
    p_glAttachShader(p, s);
    p_glLinkProgram(p);
    p_glDeleteShader(s);
    p_glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[8192];
        p_glGetProgramInfoLog(p, sizeof log, NULL, log);
        fprintf(stderr, "%s: %s does not link:\n%s\n", tag, what, log);
        p_glDeleteProgram(p);
        return 0;
    }
    return p;
}

void glh_ssbo(GLuint buf, GLuint binding, size_t size, const void* data, GLenum usage) {
    p_glBindBuffer(GL_SHADER_STORAGE_BUFFER, buf);
    p_glBufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)size, data, usage);
    p_glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buf);
}

void glh_run(GLuint prog, GLuint groups, GLuint out_buf, size_t size, void* out) {
    p_glUseProgram(prog);
    p_glDispatchCompute(groups, 1, 1);
    p_glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    p_glBindBuffer(GL_SHADER_STORAGE_BUFFER, out_buf);
    p_glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)size, out);
}
