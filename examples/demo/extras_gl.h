/* extras_gl.h -- the few GL entry points the issue-10 extras need beyond
 * gl.h (layered attachments, viewport arrays, 2D textures), loaded through
 * the same OSMesaGetProcAddress, and a program builder with a geometry
 * stage.  Kept apart from gl.h so the two files never conflict; if gl.h
 * later loads one of these too, its name wins (the #ifndef guards). */
#ifndef DEMO_EXTRAS_GL_H
#define DEMO_EXTRAS_GL_H

#include "gl.h"

#define EXTRAS_GL_FUNCS(X)                                         \
    X(PFNGLFRAMEBUFFERTEXTUREPROC, glFramebufferTexture)           \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)       \
    X(PFNGLVIEWPORTINDEXEDFPROC, glViewportIndexedf)               \
    X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                           \
    X(PFNGLUNIFORM4FPROC, glUniform4f)                             \
    X(PFNGLUNIFORM3FVPROC, glUniform3fv)                           \
    X(PFNGLBLENDFUNCPROC, glBlendFunc)

#define EXTRAS_GL_DECLARE_(type, name) extern type xgl_##name;
EXTRAS_GL_FUNCS(EXTRAS_GL_DECLARE_)
#undef EXTRAS_GL_DECLARE_

#ifndef glFramebufferTexture
#define glFramebufferTexture xgl_glFramebufferTexture
#endif
#ifndef glFramebufferTexture2D
#define glFramebufferTexture2D xgl_glFramebufferTexture2D
#endif
#ifndef glViewportIndexedf
#define glViewportIndexedf xgl_glViewportIndexedf
#endif
#ifndef glTexImage2D
#define glTexImage2D xgl_glTexImage2D
#endif
#ifndef glUniform4f
#define glUniform4f xgl_glUniform4f
#endif
#ifndef glUniform3fv
#define glUniform3fv xgl_glUniform3fv
#endif
#ifndef glBlendFunc
#define glBlendFunc xgl_glBlendFunc
#endif

/** Loads the entry points above; 0 on success. */
int extras_gl_load(void);

/** Program from vertex + optional geometry + optional fragment source
 *  ("#version 450 core" prepended).  0 and a message on failure. */
GLuint extras_gl_program(const char* name, const char* vs, const char* gs, const char* fs);

/** An R32F (or R8 when r8 != 0) 2D texture w x h with nearest (or linear)
 *  filtering and clamped edges, and an FBO that renders into it (with a
 *  24-bit depth renderbuffer when depth != 0).  0 on success. */
typedef struct extras_target {
    GLuint tex, fbo, depth_rb;
    int w, h;
} extras_target;
int extras_target_init(extras_target* t, int w, int h, GLenum internal_format, int linear,
                       int depth);
void extras_target_free(extras_target* t);

#endif
