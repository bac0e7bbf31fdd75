/* measure.c -- measured against predicted (texel coordinates read back and
 * differentiated), the error graph of [RHS] Fig. 5.8, and the frustum
 * wireframe of the light views (Fig. 5.5). */
#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"

void demo_view_update(demo_view* v) {
    const swarp_camera* c = &v->cam;
    vec3 eye = {(float)c->eye.x, (float)c->eye.y, (float)c->eye.z};
    vec3 dir = {(float)c->dir.x, (float)c->dir.y, (float)c->dir.z};
    vec3 up = {(float)c->up.x, (float)c->up.y, (float)c->up.z};
    mat4 view, proj;
    glm_look(eye, dir, up, view);
    glm_perspective((float)c->fovy, (float)c->aspect, (float)c->z_near, (float)c->z_far, proj);
    memcpy(v->view, view, sizeof v->view);
    memcpy(v->proj, proj, sizeof v->proj);
}

static int cmp_double(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

double demo_median(double* a, int n) {
    if (n <= 0) return NAN;
    qsort(a, (size_t)n, sizeof *a, cmp_double);
    return n % 2 ? a[n / 2] : 0.5 * (a[n / 2 - 1] + a[n / 2]);
}

void demo_main_params_for(const demo_view* v, demo_mode mode, demo_filter filter, float blend,
                          demo_main_params* p) {
    memset(p, 0, sizeof *p);
    memcpy(p->view, v->view, sizeof p->view);
    memcpy(p->proj, v->proj, sizeof p->proj);
    p->light_dir[0] = (float)v->light.direction.x;
    p->light_dir[1] = (float)v->light.direction.y;
    p->light_dir[2] = (float)v->light.direction.z;
    p->mode = mode;
    p->filter = filter;
    p->blend = blend;
    p->grid = 8;
    p->normal_offset = 1;
    p->vw = v->w;
    p->vh = v->h;
}

/* The model's pixel footprint at eye depth z: 2 z tan(Θ) / res_iy, the same
 * vertically and horizontally for square pixels ([RHS] (2.3)-(2.8) compare
 * this with the texel footprint on the surface). */
static double pixel_size(const demo_view* v, double z) {
    return 2.0 * z * tan(0.5 * v->cam.fovy) / v->h;
}

/* A ground pixel: world y == 0 (the default and box scenes put the ground
 * there) and something was drawn (pos.w >= 0). */
static int is_ground(const float* pos, int w, int x, int y) {
    const float* p = pos + 4 * ((size_t)y * w + x);
    return p[3] >= 0.0f && fabsf(p[1]) < 1e-3f;
}

typedef struct sample {
    int key; /* depth bin * DEMO_MAX_SPLITS + split */
    double z, mx, mz, pmx, pmz;
} sample;

static int cmp_sample(const void* a, const void* b) {
    const sample* x = a;
    const sample* y = b;
    if (x->key != y->key) return x->key - y->key;
    return (x->z > y->z) - (x->z < y->z);
}

int demo_measure(const demo_view* v, const demo_shadow* sh, int map_res, const float* tex,
                 const float* pos, demo_measure_row* rows, int cap) {
    int w = v->w, h = v->h;
    enum { NB = 12, COLS = 4 };
    sample* all = malloc(sizeof *all * (size_t)h * COLS);
    if (!all) return 0;
    int n_all = 0;
    double ln0 = log(sh->z_near), ln1 = log(sh->z_far);
    /* the centre columns (the view vector is the centre of the picture) */
    for (int dx = -COLS / 2; dx < COLS / 2; ++dx) {
        int x = w / 2 + dx;
        for (int y = 0; y + 1 < h; ++y) {
            if (!is_ground(pos, w, x, y) || !is_ground(pos, w, x, y + 1) ||
                !is_ground(pos, w, x + 1, y))
                continue;
            const float* t0 = tex + 4 * ((size_t)y * w + x);
            const float* t1 = tex + 4 * ((size_t)(y + 1) * w + x);
            const float* t2 = tex + 4 * ((size_t)y * w + x + 1);
            /* the integer part is the map index (the fraction holds the
             * blend weight) */
            if ((int)t0[2] != (int)t1[2] || (int)t0[2] != (int)t2[2]) continue; /* border */
            const float* p0 = pos + 4 * ((size_t)y * w + x);
            const float* p1 = pos + 4 * ((size_t)(y + 1) * w + x);
            const float* p2 = pos + 4 * ((size_t)y * w + x + 1);
            double dst_z = hypot(t1[0] - t0[0], t1[1] - t0[1]);
            double dst_x = hypot(t2[0] - t0[0], t2[1] - t0[1]);
            double dw_z = sqrt(pow(p1[0] - p0[0], 2) + pow(p1[1] - p0[1], 2) + pow(p1[2] - p0[2], 2));
            double dw_x = sqrt(pow(p2[0] - p0[0], 2) + pow(p2[1] - p0[1], 2) + pow(p2[2] - p0[2], 2));
            if (dst_z <= 0 || dst_x <= 0) continue;
            double z = 0.5 * ((double)t0[3] + t1[3]);
            if (z < sh->z_near || z > sh->z_far) continue;
            int split = (int)t0[2];
            /* the sample must lie in the split the library's curve uses for
             * its z (depth selection): skip the pixel pairs that straddle a
             * border in depth */
            if (split < 0 || split >= sh->count || z < sh->split[split] ||
                z >= sh->split[split + 1])
                continue;
            int b = (int)((log(z) - ln0) / (ln1 - ln0) * NB);
            if (b < 0 || b >= NB) continue;
            sample* q = &all[n_all++];
            q->key = b * DEMO_MAX_SPLITS + split;
            q->z = z;
            /* texel footprint on the surface / pixel footprint of the model */
            q->mz = (dw_z / dst_z) / pixel_size(v, z);
            q->mx = (dw_x / dst_x) / pixel_size(v, z);
            if (demo_predict(sh, v->cam.fovy, w, h, map_res, z, &q->pmx, &q->pmz))
                q->pmx = q->pmz = NAN;
        }
    }
    qsort(all, (size_t)n_all, sizeof *all, cmp_sample);
    int n = 0;
    double* tmp = malloc(sizeof(double) * (size_t)(n_all > 0 ? n_all : 1));
    for (int i = 0; i < n_all && n < cap && tmp;) {
        int j = i;
        while (j < n_all && all[j].key == all[i].key) ++j;
        int cnt = j - i;
        if (cnt >= 4) {
            demo_measure_row r;
            r.samples = cnt;
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].z;
            r.z = demo_median(tmp, cnt);
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].mx;
            r.mx = demo_median(tmp, cnt);
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].mz;
            r.mz = demo_median(tmp, cnt);
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].pmx;
            r.pred_mx = demo_median(tmp, cnt);
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].pmz;
            r.pred_mz = demo_median(tmp, cnt);
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].mx / all[i + k].pmx;
            r.ratio_mx = demo_median(tmp, cnt);
            for (int k = 0; k < cnt; ++k) tmp[k] = all[i + k].mz / all[i + k].pmz;
            r.ratio_mz = demo_median(tmp, cnt);
            r.split = all[i].key % DEMO_MAX_SPLITS;
            rows[n++] = r;
        }
        i = j;
    }
    free(tmp);
    free(all);
    return n;
}

/* ------------------------------------------------------------------------ */
/* the measured error of docs/accuracy.md, from the render                  */
/* ------------------------------------------------------------------------ */

/* Receivers that face the light at least this much (cos psi_l, [RHS] (2.2)).
 * Below it the projection aliasing 1/cos psi_l grows without bound and the
 * texel coordinates the render reads back (float, s and t up to the map
 * size: resolution about 6e-5 texels) change across a pixel by so little
 * that their differences are rounding; where cos psi_l <= 0 the shader
 * shades by N.l alone (lit = 0), so the map decides nothing there. */
#define DEMO_MEASURE_MIN_COS_LIGHT 0.05
/* Neighbouring pixels lie on the same plane when their facet normals agree
 * to this cosine (float normals of one triangle agree to about 1e-6; the
 * scene's distinct planes meet at 10 degrees or more, cos 0.985) ... */
#define DEMO_MEASURE_SAME_NORMAL 0.9995
/* ... and the step between them leaves the plane by less than this
 * fraction of its length (float positions of about 400 m: 3e-5 m apart at
 * pixel steps of 1 cm or more). */
#define DEMO_MEASURE_IN_PLANE 0.01

static const float* px4(const float* a, int w, int x, int y) {
    return a + 4 * ((size_t)y * w + x);
}

/* Pixel (x, y) and its neighbour (x + dx, y + dy) lie on one plane and in
 * one map (the integer part of tex.z). */
static int same_receiver(const float* tex, const float* pos, const float* nrm, int w, int x, int y,
                         int dx, int dy) {
    const float* n0 = px4(nrm, w, x, y);
    const float* n1 = px4(nrm, w, x + dx, y + dy);
    if (!(n1[3] > 0.5f)) return 0;
    if ((int)px4(tex, w, x, y)[2] != (int)px4(tex, w, x + dx, y + dy)[2]) return 0;
    double c = (double)n0[0] * n1[0] + (double)n0[1] * n1[1] + (double)n0[2] * n1[2];
    if (!(c >= DEMO_MEASURE_SAME_NORMAL)) return 0;
    const float* p0 = px4(pos, w, x, y);
    const float* p1 = px4(pos, w, x + dx, y + dy);
    double d[3] = {(double)p1[0] - p0[0], (double)p1[1] - p0[1], (double)p1[2] - p0[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double off = fabs(d[0] * n0[0] + d[1] * n0[1] + d[2] * n0[2]);
    return len > 0 && off <= DEMO_MEASURE_IN_PLANE * len;
}

/* D = T^-1 with T = d(s, t)/d(pixel x, y) by central differences of the
 * read-back texel coordinates: m_s = |D e_s| = |(dt/dy, -dt/dx)| / |det T|,
 * m_t = |D e_t| = |(ds/dy, -ds/dx)| / |det T|, sigma = 1 / sigma_min(T).
 * The tangent basis of docs/accuracy.md cancels: D is the same map from
 * texel steps to pixel steps in any basis of the receiver plane.  0 when T
 * is singular. */
static int render_error(const float* tex, int w, int x, int y, swarp_texel_error* out) {
    const float* xp = px4(tex, w, x + 1, y);
    const float* xm = px4(tex, w, x - 1, y);
    const float* yp = px4(tex, w, x, y + 1);
    const float* ym = px4(tex, w, x, y - 1);
    double sx = 0.5 * ((double)xp[0] - xm[0]), sy = 0.5 * ((double)yp[0] - ym[0]);
    double tx = 0.5 * ((double)xp[1] - xm[1]), ty = 0.5 * ((double)yp[1] - ym[1]);
    double det = sx * ty - sy * tx;
    if (!(fabs(det) > 0)) return 0;
    out->m_s = hypot(tx, ty) / fabs(det);
    out->m_t = hypot(sx, sy) / fabs(det);
    /* singular values of T: sqrt of the eigenvalues of T^T T */
    double a = sx * sx + tx * tx, b = sx * sy + tx * ty, c = sy * sy + ty * ty;
    double half = 0.5 * (a + c), disc = sqrt(0.25 * (a - c) * (a - c) + b * b);
    double lmin = det * det / (half + disc); /* lmin lmax = det^2, no cancellation */
    out->sigma = 1.0 / sqrt(lmin);
    return 1;
}

/* The pixel's receiver for the library: world point, facet normal, and
 * whether it faces the light enough to be measured. */
static int pixel_receiver(const demo_view* v, const float* pos, const float* nrm, int w, int x,
                          int y, swarp_vec3* P, swarp_vec3* N, double* cos_light) {
    const float* p = px4(pos, w, x, y);
    const float* n = px4(nrm, w, x, y);
    *P = (swarp_vec3){p[0], p[1], p[2]};
    *N = (swarp_vec3){n[0], n[1], n[2]};
    const swarp_vec3* l = &v->light.direction;
    double ll = sqrt(l->x * l->x + l->y * l->y + l->z * l->z);
    double cl = fabs(N->x * l->x + N->y * l->y + N->z * l->z) / ll;
    /* the facet normal's side is the rasteriser's; the receiver's lit side
     * faces the eye (the camera sees it) and the light */
    swarp_vec3 e = {v->cam.eye.x - P->x, v->cam.eye.y - P->y, v->cam.eye.z - P->z};
    double se = N->x * e.x + N->y * e.y + N->z * e.z;
    double sl = -(N->x * l->x + N->y * l->y + N->z * l->z);
    *cos_light = cl;
    return se * sl > 0 && cl >= DEMO_MEASURE_MIN_COS_LIGHT;
}

static void keep_max(double* m_s, double* m_t, double* sigma, swarp_vec3* at,
                     const swarp_texel_error* e, const swarp_vec3* P) {
    *m_s = fmax(*m_s, e->m_s);
    *m_t = fmax(*m_t, e->m_t);
    if (e->sigma > *sigma) {
        *sigma = e->sigma;
        *at = *P;
    }
}

int demo_measure_render(const demo_view* v, const demo_shadow* sh, const float* tex,
                        const float* pos, const float* nrm, demo_measured* out) {
    int w = v->w, h = v->h;
    demo_measured m;
    memset(&m, 0, sizeof m);
    double* dev = malloc(sizeof *dev * (size_t)w * h);
    if (!dev) return -1;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            if (!(px4(nrm, w, x, y)[3] > 0.5f)) continue;
            if (!same_receiver(tex, pos, nrm, w, x, y, 1, 0) ||
                !same_receiver(tex, pos, nrm, w, x, y, -1, 0) ||
                !same_receiver(tex, pos, nrm, w, x, y, 0, 1) ||
                !same_receiver(tex, pos, nrm, w, x, y, 0, -1))
                continue;
            int i = (int)px4(tex, w, x, y)[2];
            if (i < 0 || i >= sh->count) continue;
            swarp_vec3 P, N;
            double cl;
            if (!pixel_receiver(v, pos, nrm, w, x, y, &P, &N, &cl)) continue;
            swarp_measure_res mr = {(uint32_t)w, (uint32_t)h, (uint32_t)sh->viewport[i][0],
                                    (uint32_t)sh->viewport[i][1]};
            swarp_texel_error pe, re;
            swarp_status st = swarp_measure_points(&v->cam, &sh->light[i], &mr, &P, &N, 1, &pe);
            if (swarp_status_is_error(st)) {
                fprintf(stderr, "demo: swarp_measure_points: %s\n", swarp_status_string(st));
                free(dev);
                return -1;
            }
            if (!(pe.flags & SWARP_TEXEL_INSIDE) || (pe.flags & SWARP_TEXEL_SINGULAR)) continue;
            if (!render_error(tex, w, x, y, &re)) continue;
            if (re.sigma > m.render_sigma) m.render_cos_light = cl;
            keep_max(&m.render_m_s, &m.render_m_t, &m.render_sigma, &m.render_at, &re, &P);
            keep_max(&m.points_m_s, &m.points_m_t, &m.points_sigma, &m.points_at, &pe, &P);
            dev[m.pixels++] = fabs(re.sigma / pe.sigma - 1.0);
        }
    if (m.pixels > 0) {
        demo_median(dev, m.pixels); /* sorts */
        m.pixel_dev_p99 = dev[(size_t)(0.99 * (m.pixels - 1))];
        m.pixel_dev_max = dev[m.pixels - 1];
    }
    free(dev);
    *out = m;
    return 0;
}

/* ------------------------------------------------------------------------ */
/* error graph                                                              */
/* ------------------------------------------------------------------------ */
int demo_error_graph(const demo_view* v, const demo_shadow* sh, int map_res,
                     const demo_measure_row* rows, int nrows, const char* title,
                     demo_image* out) {
    const int W = 800, H = 480, L = 70, R = 20, T = 40, B = 60;
    if (demo_image_alloc(out, W, H)) return -1;
    const uint8_t white[3] = {255, 255, 255}, black[3] = {0, 0, 0}, grey[3] = {200, 200, 200};
    const uint8_t orange[3] = {240, 130, 0}, blue[3] = {30, 80, 220}, red[3] = {200, 0, 0};
    demo_image_fill(out, 0, 0, W, H, white);
    enum { NS = 600 };
    double zs[NS], mx[NS], mz[NS];
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < NS; ++i) {
        zs[i] = sh->z_near + (sh->z_far - sh->z_near) * i / (NS - 1.0);
        if (demo_predict(sh, v->cam.fovy, v->w, v->h, map_res, zs[i], &mx[i], &mz[i])) {
            mx[i] = mz[i] = NAN;
            continue;
        }
        lo = fmin(lo, fmin(mx[i], mz[i]));
        hi = fmax(hi, fmax(mx[i], mz[i]));
    }
    for (int i = 0; i < nrows; ++i) {
        lo = fmin(lo, fmin(rows[i].mx, rows[i].mz));
        hi = fmax(hi, fmax(rows[i].mx, rows[i].mz));
    }
    if (!(lo > 0) || !(hi > lo)) {
        lo = 0.01;
        hi = 100;
    }
    /* log y axis over whole decades */
    double y0 = floor(log10(lo)), y1 = ceil(log10(hi));
    if (y1 <= y0) y1 = y0 + 1;
#define PX(z) (L + ((z) - sh->z_near) / (sh->z_far - sh->z_near) * (W - L - R))
#define PY(m) (H - B - (log10(m) - y0) / (y1 - y0) * (H - T - B))
    char buf[128];
    for (double d = y0; d <= y1 + 1e-9; d += 1) {
        double yy = PY(pow(10, d));
        demo_image_line(out, L, yy, W - R, yy, 1, grey);
        snprintf(buf, sizeof buf, "1e%+.0f", d);
        demo_image_text(out, 8, (int)yy - 4, 1, buf, black);
    }
    {
        double yy = PY(1.0);
        demo_image_line(out, L, yy, W - R, yy, 2, grey);
    }
    /* split markers (and near/far) */
    for (int i = 0; i <= sh->count; ++i) {
        double xx = PX(sh->split[i]);
        demo_image_line(out, xx, T, xx, H - B, 1, i == 0 || i == sh->count ? black : red);
        snprintf(buf, sizeof buf, "%.0f", sh->split[i]);
        demo_image_text(out, (int)xx - 8, H - B + 6 + 12 * (i % 2), 1, buf, black);
    }
    demo_image_line(out, L, H - B, W - R, H - B, 1, black);
    demo_image_line(out, L, T, L, H - B, 1, black);
    for (int i = 0; i + 1 < NS; ++i) {
        if (isnan(mx[i]) || isnan(mx[i + 1])) continue;
        /* a split border makes a jump: no line across it */
        int jump = 0;
        for (int k = 1; k < sh->count; ++k)
            if (zs[i] < sh->split[k] && zs[i + 1] >= sh->split[k]) jump = 1;
        if (jump) continue;
        demo_image_line(out, PX(zs[i]), PY(mx[i]), PX(zs[i + 1]), PY(mx[i + 1]), 2, orange);
        demo_image_line(out, PX(zs[i]), PY(mz[i]), PX(zs[i + 1]), PY(mz[i + 1]), 2, blue);
    }
    for (int i = 0; i < nrows; ++i) {
        double xx = PX(rows[i].z);
        demo_image_fill(out, (int)xx - 3, (int)PY(rows[i].mx) - 3, 7, 7, orange);
        demo_image_fill(out, (int)xx - 3, (int)PY(rows[i].mz) - 3, 7, 7, blue);
        demo_image_fill(out, (int)xx - 1, (int)PY(rows[i].mx) - 1, 3, 3, white);
        demo_image_fill(out, (int)xx - 1, (int)PY(rows[i].mz) - 1, 3, 3, white);
    }
#undef PX
#undef PY
    demo_image_text(out, L, 10, 2, title, black);
    demo_image_text(out, W / 2 - 60, H - 22, 1, "eye depth z along the view vector", black);
    demo_image_fill(out, W - 330, T + 6, 14, 4, orange);
    demo_image_text(out, W - 310, T + 2, 1, sh->model_applies ? "m_x (library, [RHS] (2.3)-(2.8))" : "m_x: model does not apply", black);
    demo_image_fill(out, W - 330, T + 22, 14, 4, blue);
    demo_image_text(out, W - 310, T + 18, 1, sh->model_applies ? "m_z (library)" : "m_z: model does not apply", black);
    demo_image_fill(out, W - 328, T + 34, 7, 7, black);
    demo_image_text(out, W - 310, T + 34, 1, "measured from the render (squares)", black);
    demo_image_text(out, 8, T - 14, 1, "screen px per texel", black);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* frustum wireframe in a light view                                        */
/* ------------------------------------------------------------------------ */
static void clip_line(demo_image* im, const swarp_vec4* a, const swarp_vec4* b, const uint8_t c[3]) {
    /* clip against w > eps in homogeneous space so lines through the light's
     * centre of projection (PSM) stay correct */
    const double eps = 1e-6;
    swarp_vec4 p = *a, q = *b;
    if (p.w < eps && q.w < eps) return;
    if (p.w < eps || q.w < eps) {
        double t = (eps - p.w) / (q.w - p.w);
        swarp_vec4 m = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), p.z + t * (q.z - p.z), eps};
        if (p.w < eps) p = m; else q = m;
    }
    double x0 = (p.x / p.w * 0.5 + 0.5) * im->w, y0 = (0.5 - p.y / p.w * 0.5) * im->h;
    double x1 = (q.x / q.w * 0.5 + 0.5) * im->w, y1 = (0.5 - q.y / q.w * 0.5) * im->h;
    /* keep the drawing finite: skip segments far outside the picture */
    double lim = 8.0 * (im->w + im->h);
    if (fabs(x0) > lim || fabs(x1) > lim || fabs(y0) > lim || fabs(y1) > lim) return;
    demo_image_line(im, x0, y0, x1, y1, 2, c);
}

void demo_draw_frustum(demo_image* im, const swarp_mat4* m, const demo_view* v, double d0,
                       double d1, const uint8_t rgb[3], int view_vector) {
    const swarp_camera* c = &v->cam;
    vec3 f = {(float)c->dir.x, (float)c->dir.y, (float)c->dir.z}, up = {(float)c->up.x, (float)c->up.y, (float)c->up.z};
    vec3 r, u;
    glm_vec3_normalize(f);
    glm_vec3_crossn(f, up, r);
    glm_vec3_cross(r, f, u);
    double ty = tan(0.5 * c->fovy), tx = ty * c->aspect;
    swarp_vec4 k[8];
    for (int i = 0; i < 8; ++i) {
        double d = (i & 4) ? d1 : d0;
        double sx = ((i & 1) ? 1 : -1) * d * tx, sy = ((i & 2) ? 1 : -1) * d * ty;
        swarp_vec3 p = {c->eye.x + f[0] * d + r[0] * sx + u[0] * sy,
                        c->eye.y + f[1] * d + r[1] * sx + u[1] * sy,
                        c->eye.z + f[2] * d + r[2] * sx + u[2] * sy};
        swarp_mat4_transform(m, &p, &k[i]);
    }
    static const int e[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                 {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (int i = 0; i < 12; ++i) clip_line(im, &k[e[i][0]], &k[e[i][1]], rgb);
    if (view_vector) {
        const uint8_t blue[3] = {0, 60, 255};
        swarp_vec3 a = {c->eye.x + f[0] * d0, c->eye.y + f[1] * d0, c->eye.z + f[2] * d0};
        swarp_vec3 b = {c->eye.x + f[0] * d1, c->eye.y + f[1] * d1, c->eye.z + f[2] * d1};
        swarp_vec4 pa, pb;
        swarp_mat4_transform(m, &a, &pa);
        swarp_mat4_transform(m, &b, &pb);
        clip_line(im, &pa, &pb, blue);
    }
}
