/* osmesa_ctx.c -- the only file that sees OSMesa: creates the offscreen core
 * context and hands out GL entry points (OSMesaGetProcAddress).  Kept apart
 * from gl.c so that <GL/gl.h> (pulled in by osmesa.h) never meets
 * <GL/glcorearb.h>. */
#include <GL/osmesa.h>
#include <stdlib.h>

#include "ctx.h"

struct demo_ctx {
    OSMesaContext ctx;
    void* buffer;
};

demo_ctx* demo_ctx_create(int* out_major, int* out_minor) {
    /* Core profile 4.5 first (llvmpipe in Mesa 22 offers it), then lower
     * core versions; the version actually obtained is reported. */
    static const int versions[][2] = {{4, 5}, {4, 3}, {4, 1}, {3, 3}};
    for (size_t i = 0; i < sizeof versions / sizeof versions[0]; ++i) {
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               24,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               versions[i][0],
                               OSMESA_CONTEXT_MINOR_VERSION,
                               versions[i][1],
                               0};
        OSMesaContext c = OSMesaCreateContextAttribs(attribs, NULL);
        if (!c) continue;
        /* The default framebuffer is tiny: every pass renders into FBOs. */
        void* buf = calloc(16 * 16, 4);
        if (!buf || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 16, 16)) {
            free(buf);
            OSMesaDestroyContext(c);
            continue;
        }
        demo_ctx* d = calloc(1, sizeof *d);
        if (!d) {
            free(buf);
            OSMesaDestroyContext(c);
            return NULL;
        }
        d->ctx = c;
        d->buffer = buf;
        *out_major = versions[i][0];
        *out_minor = versions[i][1];
        return d;
    }
    return NULL;
}

void demo_ctx_destroy(demo_ctx* d) {
    if (!d) return;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(d->ctx);
    free(d->buffer);
    free(d);
}

demo_glproc demo_ctx_getproc(const char* name) {
    return (demo_glproc)OSMesaGetProcAddress(name);
}
