/* third.c -- the third-person "visualization view" ([RHS] §5.2-5.3, Fig. 5.1,
 * 5.2, 5.4b): the scene from an outside camera, coloured by the map that
 * shades each point (5.1), with the viewer's frustum and split frusta, the
 * light direction, each map's footprint on the ground, the intersection body
 * B of every map as a polyhedron (per split B_i for the cascades:
 * swarp_body_h + swarp_body_from_h, the polyhedra behind swarp_body_points)
 * and the points of B that the setup returned. */
#include <cglm/cglm.h>
#include <math.h>
#include <string.h>

#include "demo.h"
#include "shadowwarp_cglm.h"

static const uint8_t split_rgb[4][3] = {{230, 0, 0}, {230, 200, 0}, {0, 190, 0}, {0, 60, 255}};

/* the ground footprint of a map: where the edges of its clip cube cross
 * the plane y = ground, as a convex polygon in (x, z) */
static int footprint(const swarp_mat4* m, double ground, double out[16][2]) {
    swarp_mat4 inv;
    if (swarp_mat4_invert(m, &inv) != SWARP_OK) return 0;
    swarp_vec3 c[8];
    for (int i = 0; i < 8; ++i) {
        swarp_vec3 ndc = {(i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1};
        swarp_vec4 h;
        swarp_mat4_transform(&inv, &ndc, &h);
        if (!(fabs(h.w) > 1e-12)) return 0;
        c[i] = (swarp_vec3){h.x / h.w, h.y / h.w, h.z / h.w};
    }
    static const int e[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                 {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    double p[12][2];
    int n = 0;
    for (int k = 0; k < 12; ++k) {
        const swarp_vec3* a = &c[e[k][0]];
        const swarp_vec3* b = &c[e[k][1]];
        double da = a->y - ground, db = b->y - ground;
        if ((da < 0) == (db < 0) || da == db) continue;
        double t = da / (da - db);
        p[n][0] = a->x + t * (b->x - a->x);
        p[n][1] = a->z + t * (b->z - a->z);
        ++n;
    }
    if (n < 3) return 0;
    /* order around the centroid (the section of a convex body is convex) */
    double cx = 0, cz = 0;
    for (int i = 0; i < n; ++i) {
        cx += p[i][0] / n;
        cz += p[i][1] / n;
    }
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && atan2(p[j][1] - cz, p[j][0] - cx) <
                                      atan2(p[j - 1][1] - cz, p[j - 1][0] - cx);
             --j) {
            double t0 = p[j][0], t1 = p[j][1];
            p[j][0] = p[j - 1][0];
            p[j][1] = p[j - 1][1];
            p[j - 1][0] = t0;
            p[j - 1][1] = t1;
        }
    memcpy(out, p, sizeof(double) * 2 * (size_t)n);
    return n;
}

static int project(const swarp_mat4* m, const demo_image* im, swarp_vec3 p, double* x, double* y) {
    swarp_vec4 h;
    swarp_mat4_transform(m, &p, &h);
    if (h.w <= 1e-6) return 0;
    *x = (h.x / h.w * 0.5 + 0.5) * im->w;
    *y = (0.5 - h.y / h.w * 0.5) * im->h;
    return 1;
}

static void segment(demo_image* im, const swarp_mat4* m, swarp_vec3 a, swarp_vec3 b, int thick,
                    const uint8_t rgb[3]) {
    double x0, y0, x1, y1;
    if (project(m, im, a, &x0, &y0) && project(m, im, b, &x1, &y1))
        demo_image_line(im, x0, y0, x1, y1, thick, rgb);
}

/* convex polygon with every vertex in front of the camera (w > 0), blended
 * with alpha: one scanline fill */
static void fill_polygon(demo_image* im, const swarp_mat4* m, const swarp_vec3* pts, int n,
                         const uint8_t c[3], double alpha) {
    double x[SWARP_POLY_MAX_FACE_VERTICES], y[SWARP_POLY_MAX_FACE_VERTICES];
    if (n < 3 || n > SWARP_POLY_MAX_FACE_VERTICES) return;
    double ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < n; ++i)
        if (!project(m, im, pts[i], &x[i], &y[i])) return;
    for (int i = 0; i < n; ++i) {
        ymin = fmin(ymin, y[i]);
        ymax = fmax(ymax, y[i]);
    }
    int y0 = (int)fmax(0, ceil(ymin - 0.5)), y1 = (int)fmin(im->h - 1, floor(ymax - 0.5));
    for (int yy = y0; yy <= y1; ++yy) {
        double sy = yy + 0.5, lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < n; ++i) {
            int j = (i + 1) % n;
            if ((sy < y[i]) == (sy < y[j])) continue;
            double xx = x[i] + (sy - y[i]) / (y[j] - y[i]) * (x[j] - x[i]);
            lo = fmin(lo, xx);
            hi = fmax(hi, xx);
        }
        if (!(hi >= lo)) continue;
        int xa = (int)fmax(0, ceil(lo - 0.5)), xb = (int)fmin(im->w - 1, floor(hi - 0.5));
        for (int xx = xa; xx <= xb; ++xx) {
            uint8_t* px = im->px + 4 * ((size_t)yy * im->w + xx);
            for (int k = 0; k < 3; ++k) px[k] = (uint8_t)lround((1 - alpha) * px[k] + alpha * c[k]);
        }
    }
}

/* B over the view depths [d0, d1]: translucent faces, darker edges.
 * Returns the number of faces drawn (-1 if the library refused). */
static int draw_body(demo_image* im, const swarp_mat4* m, const demo_view* v,
                     const swarp_aabb* scene, double d0, double d1, const uint8_t c[3]) {
    swarp_polyhedron H, B;
    swarp_status st = swarp_body_h(&v->cam, d0, d1, scene, &H);
    if (!swarp_status_is_error(st)) st = swarp_body_from_h(&H, &v->light, scene, &B);
    if (swarp_status_is_error(st)) return -1;
    for (uint32_t f = 0; f < B.face_count; ++f) {
        swarp_vec3 pts[SWARP_POLY_MAX_FACE_VERTICES];
        uint32_t n = B.face_vertex_count[f];
        for (uint32_t k = 0; k < n; ++k) pts[k] = B.vertices[B.face_vertices[f][k]];
        fill_polygon(im, m, pts, (int)n, c, 0.12);
    }
    const uint8_t dark[3] = {(uint8_t)(c[0] * 0.6), (uint8_t)(c[1] * 0.6), (uint8_t)(c[2] * 0.6)};
    for (uint32_t f = 0; f < B.face_count; ++f) {
        uint32_t n = B.face_vertex_count[f];
        for (uint32_t k = 0; k < n; ++k)
            segment(im, m, B.vertices[B.face_vertices[f][k]], B.vertices[B.face_vertices[f][(k + 1) % n]],
                    2, dark);
    }
    return (int)B.face_count;
}

int demo_third_person(demo_renderer* r, const demo_view* v, const demo_shadow* sh,
                      const swarp_aabb* scene, const demo_main_params* base, demo_image* out,
                      int* out_body_faces) {
    /* the outside camera: behind, to the right of and above the viewer */
    const swarp_camera* c = &v->cam;
    double len = sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z);
    swarp_vec3 d = {c->dir.x / len, c->dir.y / len, c->dir.z / len};
    double hl = sqrt(d.x * d.x + d.z * d.z);
    swarp_vec3 dh = hl > 1e-6 ? (swarp_vec3){d.x / hl, 0, d.z / hl} : (swarp_vec3){0, 0, -1};
    swarp_vec3 right = {-dh.z, 0, dh.x};
    double reach = fmin(sh->z_far, 700.0);
    swarp_vec3 target = {c->eye.x + d.x * reach * 0.4, fmax(0.0, c->eye.y + d.y * reach * 0.4),
                         c->eye.z + d.z * reach * 0.4};
    swarp_vec3 eye3 = {c->eye.x - dh.x * reach * 0.3 + right.x * reach * 0.7,
                       c->eye.y + reach * 0.75,
                       c->eye.z - dh.z * reach * 0.3 + right.z * reach * 0.7};
    vec3 e3 = {(float)eye3.x, (float)eye3.y, (float)eye3.z};
    vec3 t3 = {(float)target.x, (float)target.y, (float)target.z};
    vec3 up = {0, 1, 0};
    mat4 view3, proj3;
    glm_lookat(e3, t3, up, view3);
    glm_perspective((float)(60.0 * 3.14159265358979 / 180.0), (float)v->w / (float)v->h, 1.0f,
                    6000.0f, proj3);
    demo_main_params p = *base;
    memcpy(p.view, view3, sizeof p.view);
    memcpy(p.proj, proj3, sizeof p.proj);
    memcpy(p.sel_view, v->view, sizeof p.sel_view);
    p.has_sel_view = 1;
    p.mode = DEMO_MODE_SPLITS;
    p.blend = 0;
    int errors = demo_render_main(r, sh, &p, NULL);
    if (demo_image_alloc(out, v->w, v->h)) return -1;
    demo_render_read_color(r, v->w, v->h, out->px);

    swarp_mat4 V3, P3, M3;
    swarp_cglm_mat4_to_swarp(view3, &V3);
    swarp_cglm_mat4_to_swarp(proj3, &P3);
    swarp_mat4_mul(&P3, &V3, &M3);
    /* each map's ground footprint in its split colour */
    double ground = 0.0;
    for (int i = 0; i < sh->count; ++i) {
        double fp[16][2];
        int n = footprint(&sh->light[i], ground, fp);
        for (int k = 0; k < n; ++k) {
            swarp_vec3 a = {fp[k][0], ground, fp[k][1]};
            swarp_vec3 b = {fp[(k + 1) % n][0], ground, fp[(k + 1) % n][1]};
            segment(out, &M3, a, b, 3, split_rgb[i % 4]);
        }
    }
    /* the intersection body B of every map: per split B_i over [C_i, C_i+1]
     * for the cascades (with the split frustum in its colour), else one B
     * over the maps' whole range (magenta) */
    int cascade = sh->count > 1 && (sh->select == DEMO_SELECT_DEPTH || sh->select == DEMO_SELECT_BEST);
    int faces = 0;
    const uint8_t black[3] = {0, 0, 0}, magenta[3] = {230, 0, 230}, yellow[3] = {255, 230, 0};
    for (int i = 0; i < (cascade ? sh->count : 1); ++i) {
        double d0 = cascade ? sh->split[i] : sh->z_near, d1 = cascade ? sh->split[i + 1] : sh->z_far;
        int nf = draw_body(out, &M3, v, scene, d0, d1, cascade ? split_rgb[i % 4] : magenta);
        faces += nf > 0 ? nf : 0;
        if (cascade) demo_draw_frustum(out, &M3, v, d0, d1, split_rgb[i % 4], 0);
    }
    if (out_body_faces) *out_body_faces = faces;
    /* the view frustum (black) with the view vector (blue) */
    demo_draw_frustum(out, &M3, v, sh->z_near, sh->z_far, black, 1);
    /* the points of B (magenta) */
    for (int i = 0; i < sh->body_count; ++i) {
        double x, y;
        if (project(&M3, out, sh->body[i], &x, &y))
            demo_image_fill(out, (int)x - 3, (int)y - 3, 7, 7, magenta);
    }
    /* the light direction: an arrow toward the target */
    swarp_vec3 ld = v->light.direction;
    double ll = sqrt(ld.x * ld.x + ld.y * ld.y + ld.z * ld.z);
    swarp_vec3 from = {target.x - ld.x / ll * reach * 0.3, target.y - ld.y / ll * reach * 0.3,
                       target.z - ld.z / ll * reach * 0.3};
    segment(out, &M3, from, target, 4, yellow);
    double x, y;
    if (project(&M3, out, target, &x, &y)) demo_image_fill(out, (int)x - 5, (int)y - 5, 11, 11, yellow);
    demo_image_label(out, 8, v->h - 22, 1,
                     cascade ? "third person: map colours (5.1), footprints, bodies B_i and split frusta, view frustum, light, points of B"
                             : "third person: map colours (5.1), footprints, body B, view frustum, light, points of B");
    return errors;
}
