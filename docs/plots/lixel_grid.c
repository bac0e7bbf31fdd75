/* Writes docs/img/lixel_grid.png: the viewer's image of a room (floor y = 0,
 * wall z = -10) with the shadow-map texel grid drawn on it.
 *   left:  [LIXEL] plane-stabilised maps, one for the floor (twisted so the
 *          floor/wall line is horizontal) and one for the wall, clipped to
 *          the view; every 8 x 8 block of lixels is one checker cell.
 *   right: a conventional (uniform) perspective shadow map from the same
 *          light with the SAME number of texels, fitted to the rays of the
 *          visible room (as focused as the lixel maps).
 * Built by meson (tests/meson.build, stage lixel) when libpng is found:
 *   ./build/tests/lixel_grid docs/img/lixel_grid.png */
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"

#define PW 720 /* one panel */
#define PH 480
#define CELL 8.0

typedef struct v3 { double x, y, z; } v3;
static v3 V(double x, double y, double z) { v3 r = {x, y, z}; return r; }
static v3 sub(v3 a, v3 b) { return V(a.x - b.x, a.y - b.y, a.z - b.z); }
static v3 add(v3 a, v3 b) { return V(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 mul(v3 a, double s) { return V(a.x * s, a.y * s, a.z * s); }
static double dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static v3 cross(v3 a, v3 b) { return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static v3 unit(v3 a) { return mul(a, 1.0 / sqrt(dot(a, a))); }

static const v3 eye = {1.0, 1.7, 4.0};
static v3 f, s, u;
static double tan_half, aspect;

static swarp_mat4 camera(void) {
    f = unit(V(-0.2, -0.35, -1.0));
    s = unit(cross(f, V(0, 1, 0)));
    u = cross(s, f);
    tan_half = tan(30.0 * M_PI / 180.0);
    aspect = (double)PW / PH;
    double n = 0.1, fa = 100.0;
    double P[4][4] = {{1 / (tan_half * aspect), 0, 0, 0}, {0, 1 / tan_half, 0, 0},
                      {0, 0, (fa + n) / (n - fa), 2 * fa * n / (n - fa)}, {0, 0, -1, 0}};
    double Vw[4][4] = {{s.x, s.y, s.z, -dot(s, eye)}, {u.x, u.y, u.z, -dot(u, eye)},
                       {-f.x, -f.y, -f.z, dot(f, eye)}, {0, 0, 0, 1}};
    swarp_mat4 M;
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) {
            double acc = 0;
            for (int j = 0; j < 4; ++j) acc += P[r][j] * Vw[j][k];
            M.m[k * 4 + r] = acc;
        }
    return M;
}

/* the room surface seen through pixel (x, y): 1 floor, 2 wall, 0 none */
static int hit(double x, double y, v3* X) {
    double xn = (x + 0.5) * 2.0 / PW - 1.0, yn = (y + 0.5) * 2.0 / PH - 1.0;
    v3 d = add(f, add(mul(s, xn * tan_half * aspect), mul(u, yn * tan_half)));
    double tf = d.y < 0 ? -eye.y / d.y : INFINITY, tw = d.z < 0 ? (-10.0 - eye.z) / d.z : INFINITY;
    if (!isfinite(tf) && !isfinite(tw)) return 0;
    int wall = tw < tf;
    *X = add(eye, mul(d, wall ? tw : tf));
    if (fabs(X->x) > 8.0 || X->y > 6.0) return 0;
    return wall ? 2 : 1;
}

static void proj(const swarp_mat4* M, v3 X, double* x, double* y, double* q) {
    double o[4];
    for (int r = 0; r < 4; ++r) o[r] = M->m[r] * X.x + M->m[4 + r] * X.y + M->m[8 + r] * X.z + M->m[12 + r];
    *q = o[3];
    *x = o[0] / o[3];
    *y = o[1] / o[3];
}

static void shade(unsigned char* px, double tx, double ty, const unsigned char base[3]) {
    long cx = (long)floor(tx / CELL), cy = (long)floor(ty / CELL);
    double k = ((cx + cy) & 1) ? 1.0 : 0.72;
    for (int c = 0; c < 3; ++c) px[c] = (unsigned char)(base[c] * k);
}

static int check(swarp_status st, const char* what) {
    if (swarp_status_is_error(st)) {
        fprintf(stderr, "lixel_grid: %s: %s\n", what, swarp_status_string(st));
        return 0;
    }
    return 1;
}

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: lixel_grid out.png\n");
        return 2;
    }
    swarp_mat4 Mv = camera();
    swarp_plane floor_p = {0, 1, 0, 0}, wall_p = {0, 0, 1, 10};
    v3 lp = V(-3, 6, 2);
    swarp_light L;
    memset(&L, 0, sizeof L);
    L.type = SWARP_LIGHT_POINT;
    L.position.x = lp.x, L.position.y = lp.y, L.position.z = lp.z;
    /* C_tot: the rays toward the room's floor and wall */
    v3 corners[4] = {V(-8, 0, 4), V(8, 0, 4), V(8, 6, -10), V(-8, 6, -10)};
    swarp_vec4 C_tot[4], Cf[5], Cw[5];
    for (int i = 0; i < 4; ++i) {
        v3 d = sub(corners[i], lp);
        C_tot[i].x = d.x, C_tot[i].y = d.y, C_tot[i].z = d.z, C_tot[i].w = 0.0;
    }
    size_t nf, nw;
    if (!check(swarp_lixel_split(&L, &floor_p, &wall_p, C_tot, 4, Cf, 5, &nf, Cw, 5, &nw), "split")) return 1;
    swarp_mat4 Mf, Mw, Mf_r, Mw_r, GLV, GLP[2];
    if (!check(swarp_lixel_matrix(&Mv, PW, PH, &L, &floor_p, NULL, &Mf, NULL), "floor matrix") ||
        !check(swarp_lixel_matrix(&Mv, PW, PH, &L, &wall_p, NULL, &Mw, NULL), "wall matrix"))
        return 1;
    swarp_lixel_restrict_options of, ow;
    memset(&of, 0, sizeof of);
    of.view_width = PW, of.view_height = PH;
    ow = of;
    swarp_vec3 a = {-5, 0, -10}, b = {5, 0, -10}, below = {0, 0, -5};
    if (!check(swarp_lixel_twist_for_line(&Mf, &a, &b, &below, &of.twist), "twist")) return 1;
    swarp_lixel_rect Rf, Rw;
    if (!check(swarp_lixel_restrict(&Mf, Cf, nf, &of, &Rf, NULL, &Mf_r), "floor rect") ||
        !check(swarp_lixel_restrict(&Mw, Cw, nw, &ow, &Rw, NULL, &Mw_r), "wall rect") ||
        !check(swarp_lixel_factor(&Mf_r, Rf.width, Rf.height, SWARP_DEPTH_DEFAULT, 0, &GLV, &GLP[0]), "factor") ||
        !check(swarp_lixel_factor(&Mw_r, Rw.width, Rw.height, SWARP_DEPTH_DEFAULT, 0, &GLV, &GLP[1]), "factor"))
        return 1;
    double total = (double)Rf.width * Rf.height + (double)Rw.width * Rw.height;
    /* the uniform map: perspective from the light, axis = mean ray of C_tot,
     * square frustum fitted to C_tot, N x N texels with N^2 = total */
    v3 axis = V(0, 0, 0);
    for (int i = 0; i < 4; ++i) axis = add(axis, unit(V(C_tot[i].x, C_tot[i].y, C_tot[i].z)));
    axis = unit(axis);
    v3 ls = unit(cross(axis, V(0, 0, -1))), lu = cross(ls, axis);
    /* focused like the lixel maps: fitted to the rays of the VISIBLE room */
    double lo_a = INFINITY, hi_a = -INFINITY, lo_b = INFINITY, hi_b = -INFINITY;
    for (int y = 0; y < PH; ++y)
        for (int x = 0; x < PW; ++x) {
            v3 X;
            if (!hit(x, y, &X)) continue;
            v3 d = sub(X, lp);
            double ta = dot(d, ls) / dot(d, axis), tb = dot(d, lu) / dot(d, axis);
            lo_a = fmin(lo_a, ta), hi_a = fmax(hi_a, ta), lo_b = fmin(lo_b, tb), hi_b = fmax(hi_b, tb);
        }
    /* N_a x N_b texels in the aspect of the fitted window, N_a N_b = total */
    double N_a = floor(sqrt(total * (hi_a - lo_a) / (hi_b - lo_b))), N_b = floor(total / N_a);

    static unsigned char img[PH][2 * PW + 8][3];
    memset(img, 255, sizeof img);
    static const unsigned char c_floor[3] = {70, 120, 210}, c_wall[3] = {230, 140, 50}, c_fb[3] = {150, 150, 150},
                               c_uni[3] = {80, 170, 90};
    long counts[3] = {0, 0, 0};
    for (int y = 0; y < PH; ++y)
        for (int x = 0; x < PW; ++x) {
            v3 X;
            int surf = hit(x, y, &X);
            int row = PH - 1 - y; /* PNG rows top-down, pixel y up */
            if (!surf) {
                for (int c = 0; c < 3; ++c) img[row][x][c] = img[row][PW + 8 + x][c] = 40;
                continue;
            }
            swarp_vec3 p = {X.x, X.y, X.z};
            uint32_t idx = 2;
            swarp_lixel_select(GLP, 2, &p, &idx);
            double tx, ty, q;
            if (idx == 0) {
                proj(&Mf_r, X, &tx, &ty, &q);
                shade(img[row][x], tx, ty, c_floor);
            } else if (idx == 1) {
                proj(&Mw_r, X, &tx, &ty, &q);
                shade(img[row][x], tx, ty, c_wall);
            } else {
                shade(img[row][x], x, y, c_fb);
            }
            ++counts[idx];
            v3 d = sub(X, lp);
            double ta = dot(d, ls) / dot(d, axis), tb = dot(d, lu) / dot(d, axis);
            shade(img[row][PW + 8 + x], (ta - lo_a) / (hi_a - lo_a) * N_a, (tb - lo_b) / (hi_b - lo_b) * N_b, c_uni);
        }
    FILE* fp = fopen(argv[1], "wb");
    if (!fp) {
        perror(argv[1]);
        return 1;
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        fclose(fp);
        return 1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, 2 * PW + 8, PH, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < PH; ++y) png_write_row(png, (png_bytep)img[y]);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(fp);
    printf("floor map %u x %u (twist %.4f rad), wall map %u x %u, total %.0f lixels; uniform map %.0f x %.0f\n",
           Rf.width, Rf.height, of.twist, Rw.width, Rw.height, total, N_a, N_b);
    printf("pixels: floor map %ld, wall map %ld, fallback %ld\n", counts[0], counts[1], counts[2]);
    return 0;
}
