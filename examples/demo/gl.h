/* gl.h -- GL 4.5 core entry points loaded through OSMesaGetProcAddress,
 * plus small shader / error helpers (gl.c). */
#ifndef DEMO_GL_H
#define DEMO_GL_H

#include <GL/glcorearb.h>

#define DEMO_GL_FUNCS(X)                                               \
    X(PFNGLGETSTRINGPROC, glGetString)                                 \
    X(PFNGLGETERRORPROC, glGetError)                                   \
    X(PFNGLGETINTEGERVPROC, glGetIntegerv)                             \
    X(PFNGLFINISHPROC, glFinish)                                       \
    X(PFNGLVIEWPORTPROC, glViewport)                                   \
    X(PFNGLCLEARPROC, glClear)                                         \
    X(PFNGLCLEARCOLORPROC, glClearColor)                               \
    X(PFNGLCLEARDEPTHPROC, glClearDepth)                               \
    X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                         \
    X(PFNGLENABLEPROC, glEnable)                                       \
    X(PFNGLDISABLEPROC, glDisable)                                     \
    X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                 \
    X(PFNGLDEPTHMASKPROC, glDepthMask)                                 \
    X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                         \
    X(PFNGLCULLFACEPROC, glCullFace)                                   \
    X(PFNGLLINEWIDTHPROC, glLineWidth)                                 \
    X(PFNGLPIXELSTOREIPROC, glPixelStorei)                             \
    X(PFNGLREADPIXELSPROC, glReadPixels)                               \
    X(PFNGLREADBUFFERPROC, glReadBuffer)                               \
    X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                             \
    X(PFNGLDRAWARRAYSPROC, glDrawArrays)                               \
    X(PFNGLGENBUFFERSPROC, glGenBuffers)                               \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                         \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                               \
    X(PFNGLBUFFERDATAPROC, glBufferData)                               \
    X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                     \
    X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)               \
    X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                     \
    X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)             \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)     \
    X(PFNGLCREATESHADERPROC, glCreateShader)                           \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                           \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                           \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                         \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                             \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                   \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                         \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                         \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                           \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                             \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                           \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                 \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                               \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)               \
    X(PFNGLUNIFORM1IPROC, glUniform1i)                                 \
    X(PFNGLUNIFORM1FPROC, glUniform1f)                                 \
    X(PFNGLUNIFORM1FVPROC, glUniform1fv)                               \
    X(PFNGLUNIFORM2FPROC, glUniform2f)                                 \
    X(PFNGLUNIFORM2FVPROC, glUniform2fv)                               \
    X(PFNGLUNIFORM2IPROC, glUniform2i)                                 \
    X(PFNGLUNIFORM3FPROC, glUniform3f)                                 \
    X(PFNGLUNIFORM3FVPROC, glUniform3fv)                               \
    X(PFNGLUNIFORM4FVPROC, glUniform4fv)                               \
    X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                   \
    X(PFNGLGENTEXTURESPROC, glGenTextures)                             \
    X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                       \
    X(PFNGLBINDTEXTUREPROC, glBindTexture)                             \
    X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                         \
    X(PFNGLTEXIMAGE3DPROC, glTexImage3D)                               \
    X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                               \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)           \
    X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                         \
    X(PFNGLTEXPARAMETERFVPROC, glTexParameterfv)                       \
    X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                     \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)               \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                     \
    X(PFNGLFRAMEBUFFERTEXTURELAYERPROC, glFramebufferTextureLayer)     \
    X(PFNGLFRAMEBUFFERTEXTUREPROC, glFramebufferTexture)               \
    X(PFNGLVIEWPORTINDEXEDFPROC, glViewportIndexedf)                   \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)       \
    X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                   \
    X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)             \
    X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                   \
    X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)             \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)

#define DEMO_GL_DECLARE_(type, name) extern type dgl_##name;
DEMO_GL_FUNCS(DEMO_GL_DECLARE_)
#undef DEMO_GL_DECLARE_

#define glGetString dgl_glGetString
#define glGetError dgl_glGetError
#define glGetIntegerv dgl_glGetIntegerv
#define glFinish dgl_glFinish
#define glViewport dgl_glViewport
#define glClear dgl_glClear
#define glClearColor dgl_glClearColor
#define glClearDepth dgl_glClearDepth
#define glClearBufferfv dgl_glClearBufferfv
#define glEnable dgl_glEnable
#define glDisable dgl_glDisable
#define glDepthFunc dgl_glDepthFunc
#define glDepthMask dgl_glDepthMask
#define glPolygonOffset dgl_glPolygonOffset
#define glCullFace dgl_glCullFace
#define glLineWidth dgl_glLineWidth
#define glPixelStorei dgl_glPixelStorei
#define glReadPixels dgl_glReadPixels
#define glReadBuffer dgl_glReadBuffer
#define glDrawBuffers dgl_glDrawBuffers
#define glDrawArrays dgl_glDrawArrays
#define glGenBuffers dgl_glGenBuffers
#define glDeleteBuffers dgl_glDeleteBuffers
#define glBindBuffer dgl_glBindBuffer
#define glBufferData dgl_glBufferData
#define glGenVertexArrays dgl_glGenVertexArrays
#define glDeleteVertexArrays dgl_glDeleteVertexArrays
#define glBindVertexArray dgl_glBindVertexArray
#define glVertexAttribPointer dgl_glVertexAttribPointer
#define glEnableVertexAttribArray dgl_glEnableVertexAttribArray
#define glCreateShader dgl_glCreateShader
#define glDeleteShader dgl_glDeleteShader
#define glShaderSource dgl_glShaderSource
#define glCompileShader dgl_glCompileShader
#define glGetShaderiv dgl_glGetShaderiv
#define glGetShaderInfoLog dgl_glGetShaderInfoLog
#define glCreateProgram dgl_glCreateProgram
#define glDeleteProgram dgl_glDeleteProgram
#define glAttachShader dgl_glAttachShader
#define glLinkProgram dgl_glLinkProgram
#define glGetProgramiv dgl_glGetProgramiv
#define glGetProgramInfoLog dgl_glGetProgramInfoLog
#define glUseProgram dgl_glUseProgram
#define glGetUniformLocation dgl_glGetUniformLocation
#define glUniform1i dgl_glUniform1i
#define glUniform1f dgl_glUniform1f
#define glUniform1fv dgl_glUniform1fv
#define glUniform2f dgl_glUniform2f
#define glUniform2fv dgl_glUniform2fv
#define glUniform2i dgl_glUniform2i
#define glUniform3f dgl_glUniform3f
#define glUniform3fv dgl_glUniform3fv
#define glUniform4fv dgl_glUniform4fv
#define glUniformMatrix4fv dgl_glUniformMatrix4fv
#define glGenTextures dgl_glGenTextures
#define glDeleteTextures dgl_glDeleteTextures
#define glBindTexture dgl_glBindTexture
#define glActiveTexture dgl_glActiveTexture
#define glTexImage3D dgl_glTexImage3D
#define glTexImage2D dgl_glTexImage2D
#define glFramebufferTexture2D dgl_glFramebufferTexture2D
#define glTexParameteri dgl_glTexParameteri
#define glTexParameterfv dgl_glTexParameterfv
#define glGenFramebuffers dgl_glGenFramebuffers
#define glDeleteFramebuffers dgl_glDeleteFramebuffers
#define glBindFramebuffer dgl_glBindFramebuffer
#define glFramebufferTextureLayer dgl_glFramebufferTextureLayer
#define glFramebufferTexture dgl_glFramebufferTexture
#define glViewportIndexedf dgl_glViewportIndexedf
#define glCheckFramebufferStatus dgl_glCheckFramebufferStatus
#define glGenRenderbuffers dgl_glGenRenderbuffers
#define glDeleteRenderbuffers dgl_glDeleteRenderbuffers
#define glBindRenderbuffer dgl_glBindRenderbuffer
#define glRenderbufferStorage dgl_glRenderbufferStorage
#define glFramebufferRenderbuffer dgl_glFramebufferRenderbuffer

/** Loads every entry point; 0 on success, -1 (with a message) if one is
 *  missing. */
int demo_gl_load(void);

/** Compiles and links a program from vertex + fragment source (a common
 *  "#version 450 core" header is prepended).  0 and a message on failure. */
GLuint demo_gl_program(const char* name, const char* vs, const char* fs);
/** A program whose fragment shader is the concatenation of fs_parts (after
 *  the common #version line): library GLSL files first, then the demo's. */
GLuint demo_gl_program_parts(const char* name, const char* vs, const char* const* fs_parts,
                             int fs_count);
/** The same with a geometry shader between them (gs may be NULL). */
GLuint demo_gl_program_gs(const char* name, const char* vs, const char* gs, const char* fs);

/** glGetError after a pass: prints the pass name and returns the number of
 *  errors drained (0 = clean). */
int demo_gl_check(const char* pass);

#endif
