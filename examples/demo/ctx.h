/* ctx.h -- OSMesa context (osmesa_ctx.c). */
#ifndef DEMO_CTX_H
#define DEMO_CTX_H

typedef struct demo_ctx demo_ctx;
typedef void (*demo_glproc)(void);

/** Offscreen core-profile context, made current.  NULL if OSMesa cannot
 *  create one.  *out_major.*out_minor: the core version requested and got. */
demo_ctx* demo_ctx_create(int* out_major, int* out_minor);
void demo_ctx_destroy(demo_ctx* ctx);
demo_glproc demo_ctx_getproc(const char* name);

#endif
