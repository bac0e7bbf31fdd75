/* image.h -- RGBA8 images on the CPU: PNG output, text, lines, legends,
 * contact sheets and the error graph (image.c). */
#ifndef DEMO_IMAGE_H
#define DEMO_IMAGE_H

#include <stddef.h>
#include <stdint.h>

typedef struct demo_image {
    int w, h;
    uint8_t* px; /**< RGBA, top row first */
} demo_image;

int demo_image_alloc(demo_image* im, int w, int h);
void demo_image_free(demo_image* im);
void demo_image_fill(demo_image* im, int x, int y, int w, int h, const uint8_t rgb[3]);
void demo_image_line(demo_image* im, double x0, double y0, double x1, double y1, int thick,
                     const uint8_t rgb[3]);
/** Text with stb_easy_font at integer scale; (x, y) = top left. */
void demo_image_text(demo_image* im, int x, int y, int scale, const char* text,
                     const uint8_t rgb[3]);
/** Text on a filled box that keeps it readable over any picture. */
void demo_image_label(demo_image* im, int x, int y, int scale, const char* text);
void demo_image_blit(demo_image* dst, int x, int y, const demo_image* src);
/** Nearest-neighbour downscale/upscale copy into a new image. */
int demo_image_resize(const demo_image* src, int w, int h, demo_image* out);
/** The [RHS] Listing A.3 colour for texels per pixel `area`. */
void demo_sampling_color(double area, uint8_t rgb[3]);
/** Legend of the Listing A.3 scale drawn at (x, y), width w. */
void demo_image_sampling_legend(demo_image* im, int x, int y, int w);
/** Writes a PNG (libpng).  0 on success. */
int demo_image_write_png(const demo_image* im, const char* path);
/** Fraction of pixels that differ from the first pixel by more than 8 in
 *  some channel: 0 for a blank image. */
double demo_image_nonblank(const demo_image* im);

#endif
