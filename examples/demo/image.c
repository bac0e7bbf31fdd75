/* image.c -- CPU-side drawing and PNG output. */
#include "image.h"

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

int demo_image_alloc(demo_image* im, int w, int h) {
    im->w = w;
    im->h = h;
    im->px = calloc((size_t)w * (size_t)h, 4);
    return im->px ? 0 : -1;
}

void demo_image_free(demo_image* im) {
    free(im->px);
    im->px = NULL;
    im->w = im->h = 0;
}

static void put(demo_image* im, int x, int y, const uint8_t c[3]) {
    if (x < 0 || y < 0 || x >= im->w || y >= im->h) return;
    uint8_t* p = im->px + ((size_t)y * im->w + x) * 4;
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
    p[3] = 255;
}

void demo_image_fill(demo_image* im, int x, int y, int w, int h, const uint8_t rgb[3]) {
    for (int j = y; j < y + h; ++j)
        for (int i = x; i < x + w; ++i) put(im, i, j, rgb);
}

void demo_image_line(demo_image* im, double x0, double y0, double x1, double y1, int thick,
                     const uint8_t rgb[3]) {
    double dx = x1 - x0, dy = y1 - y0;
    double len = fmax(fabs(dx), fabs(dy));
    int n = (int)ceil(len) + 1;
    if (n > 20000) n = 20000;
    for (int k = 0; k <= n; ++k) {
        double t = (double)k / n;
        int x = (int)lround(x0 + t * dx), y = (int)lround(y0 + t * dy);
        for (int j = -(thick / 2); j < thick - thick / 2; ++j)
            for (int i = -(thick / 2); i < thick - thick / 2; ++i) put(im, x + i, y + j, rgb);
    }
}

void demo_image_text(demo_image* im, int x, int y, int scale, const char* text,
                     const uint8_t rgb[3]) {
    static char buf[60000];
    char tmp[512];
    snprintf(tmp, sizeof tmp, "%s", text);
    unsigned char col[4] = {255, 255, 255, 255};
    int quads = stb_easy_font_print(0, 0, tmp, col, buf, sizeof buf);
    for (int q = 0; q < quads; ++q) {
        const float* v = (const float*)(buf + (size_t)q * 64);
        /* 4 vertices of 16 bytes: x, y, z, colour */
        float x0 = v[0], y0 = v[1], x1 = v[8], y1 = v[9];
        demo_image_fill(im, x + (int)(x0 * scale), y + (int)(y0 * scale),
                        (int)((x1 - x0) * scale), (int)((y1 - y0) * scale), rgb);
    }
}

void demo_image_label(demo_image* im, int x, int y, int scale, const char* text) {
    char tmp[512];
    snprintf(tmp, sizeof tmp, "%s", text);
    int w = stb_easy_font_width(tmp) * scale, h = stb_easy_font_height(tmp) * scale;
    const uint8_t bg[3] = {255, 255, 255}, fg[3] = {0, 0, 0};
    demo_image_fill(im, x - 3, y - 3, w + 6, h + 4, bg);
    demo_image_text(im, x, y, scale, text, fg);
}

void demo_image_blit(demo_image* dst, int x, int y, const demo_image* src) {
    for (int j = 0; j < src->h; ++j) {
        int yy = y + j;
        if (yy < 0 || yy >= dst->h) continue;
        for (int i = 0; i < src->w; ++i) {
            int xx = x + i;
            if (xx < 0 || xx >= dst->w) continue;
            memcpy(dst->px + ((size_t)yy * dst->w + xx) * 4, src->px + ((size_t)j * src->w + i) * 4,
                   4);
        }
    }
}

int demo_image_resize(const demo_image* src, int w, int h, demo_image* out) {
    if (demo_image_alloc(out, w, h)) return -1;
    /* box filter when shrinking: each output pixel averages its source area */
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            int x0 = i * src->w / w, x1 = (i + 1) * src->w / w;
            int y0 = j * src->h / h, y1 = (j + 1) * src->h / h;
            if (x1 <= x0) x1 = x0 + 1;
            if (y1 <= y0) y1 = y0 + 1;
            unsigned sum[4] = {0, 0, 0, 0}, n = 0;
            for (int y = y0; y < y1 && y < src->h; ++y)
                for (int x = x0; x < x1 && x < src->w; ++x) {
                    const uint8_t* p = src->px + ((size_t)y * src->w + x) * 4;
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                    ++n;
                }
            uint8_t* d = out->px + ((size_t)j * w + i) * 4;
            for (int c = 0; c < 4; ++c) d[c] = (uint8_t)(n ? sum[c] / n : 0);
        }
    return 0;
}

/* [RHS] Listing A.3: the same intervals and colours as the shader. */
static const double iv[7] = {0.0, 1.0 / 7.75, 1.0 / 3.25, 1.0, 3.25, 7.75, 10.0};
static const double clr[7][3] = {{0.2, 0, 0}, {1, 0.2, 0}, {1, 1, 0}, {0, 1, 0},
                                 {0.3, 0.8, 1}, {0, 0, 1}, {0, 0, 0.4}};

void demo_sampling_color(double area, uint8_t rgb[3]) {
    double c[3] = {clr[6][0], clr[6][1], clr[6][2]};
    for (int i = 0; i < 6; ++i)
        if (area >= iv[i] && area < iv[i + 1]) {
            double t = (area - iv[i]) / (iv[i + 1] - iv[i]);
            for (int k = 0; k < 3; ++k) c[k] = clr[i][k] + t * (clr[i + 1][k] - clr[i][k]);
            break;
        }
    for (int k = 0; k < 3; ++k) rgb[k] = (uint8_t)lround(255.0 * c[k]);
}

void demo_image_sampling_legend(demo_image* im, int x, int y, int w) {
    /* The bar is piecewise linear in the interval index (each interval of
     * Listing A.3 gets the same width), labelled at the interval bounds. */
    const uint8_t white[3] = {255, 255, 255}, black[3] = {0, 0, 0};
    int bar_h = 14;
    demo_image_fill(im, x - 6, y - 20, w + 12, bar_h + 44, white);
    demo_image_text(im, x, y - 16, 1, "shadow-map texels per screen pixel ([RHS] Listing A.3)",
                    black);
    int seg = w / 7;
    for (int px = 0; px < 7 * seg; ++px) {
        int i = px / seg;
        double t = (double)(px % seg) / seg;
        double area = i < 6 ? iv[i] + t * (iv[i + 1] - iv[i]) : 10.0 + t;
        uint8_t c[3];
        demo_sampling_color(area, c);
        demo_image_fill(im, x + px, y, 1, bar_h, c);
    }
    const char* lab[7] = {"0", "1/7.75", "1/3.25", "1", "3.25", "7.75", "10"};
    for (int i = 0; i < 7; ++i) {
        demo_image_fill(im, x + i * seg, y + bar_h, 1, 4, black);
        demo_image_text(im, x + i * seg - 4, y + bar_h + 6, 1, lab[i], black);
    }
    demo_image_text(im, x + 6 * seg + 28, y + bar_h + 6, 1, ">10", black);
}

int demo_image_write_png(const demo_image* im, const char* path) {
    FILE* f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "demo: cannot write %s\n", path);
        return -1;
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)im->w, (png_uint_32)im->h, 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 6);
    png_write_info(png, info);
    for (int y = 0; y < im->h; ++y) png_write_row(png, im->px + (size_t)y * im->w * 4);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fclose(f) == 0 ? 0 : -1;
}

double demo_image_nonblank(const demo_image* im) {
    size_t n = (size_t)im->w * im->h, diff = 0;
    if (!n) return 0;
    const uint8_t* p0 = im->px;
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = im->px + i * 4;
        if (abs(p[0] - p0[0]) > 8 || abs(p[1] - p0[1]) > 8 || abs(p[2] - p0[2]) > 8) ++diff;
    }
    return (double)diff / (double)n;
}
