/* gl_harness: the OSMesa / compute-shader plumbing shared by the GLSL-twin
 * tests (filter_glsl.c, splits_glsl.c).  Each test keeps its own driver
 * shader, cases and tolerances; this file only makes a GL 4.3+ core context,
 * loads the entry points, reads the .glsl file, compiles a compute program
 * and moves shader-storage buffers.  `tag` prefixes every message. */
#ifndef GL_HARNESS_H
#define GL_HARNESS_H

#include <GL/osmesa.h>
#include <stddef.h>

/* ---- GL entry points (loaded by glh_open) ------------------------------- */
#define GLH_FUNCS(X)                                                \
    X(PFNGLCREATESHADERPROC, glCreateShader)                        \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                        \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                      \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                          \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                        \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                      \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                        \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                          \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                        \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)              \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                            \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                      \
    X(PFNGLGENBUFFERSPROC, glGenBuffers)                            \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                      \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                            \
    X(PFNGLBUFFERDATAPROC, glBufferData)                            \
    X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                    \
    X(PFNGLGETBUFFERSUBDATAPROC, glGetBufferSubData)                \
    X(PFNGLDISPATCHCOMPUTEPROC, glDispatchCompute)                  \
    X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)
#define GLH_DECL(type, name) extern type p_##name;
GLH_FUNCS(GLH_DECL)
#undef GLH_DECL

/* A GL 4.5 (else 4.3) core context on a 4x4 RGBA buffer, made current, with
 * the entry points loaded.  NULL (message printed) when there is none: the
 * caller then skips (exit 77). */
OSMesaContext glh_open(const char* tag);
/* Releases and destroys a context from glh_open. */
void glh_close(OSMesaContext ctx);
/* The whole file, NUL-terminated, from malloc (free it); NULL if unreadable. */
char* glh_read_file(const char* path);
/* A linked compute program from the concatenated parts; 0 (log printed) if it
 * does not compile or link. */
GLuint glh_compile(const char* tag, const char* const* parts, int n_parts, const char* what);
/* Fills shader-storage buffer `buf` (data may be NULL) and binds it to `binding`. */
void glh_ssbo(GLuint buf, GLuint binding, size_t size, const void* data, GLenum usage);
/* Runs `prog` on `groups` work groups, then reads `size` bytes of buffer `out_buf`. */
void glh_run(GLuint prog, GLuint groups, GLuint out_buf, size_t size, void* out);

#endif
