/* extras_main.c -- demo-extras: the demo parts of issue 10.
 *
 *   demo-extras                      every part into ./out/extras/ + tables
 *   demo-extras --part viz|cloning|blur|mindepth|cube
 *   demo-extras --test cloning|mindepth|cube|blur   headless checks (77: no OSMesa)
 */
#include <cglm/cglm.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ctx.h"
#include "extras.h"
#include "shadowwarp_cglm.h"

#define DEG (3.14159265358979323846 / 180.0)

void extras_camera_preset(const char* name, int w, int h, swarp_camera* c) {
    /* the gallery's presets (main.c camera_preset) */
    memset(c, 0, sizeof *c);
    c->up.y = 1;
    c->fovy = 60 * DEG;
    c->aspect = (double)w / h;
    c->near = 1;
    c->far = 800;
    if (!strcmp(name, "street")) {
        c->eye = (swarp_vec3){0, 2, 385};
        c->dir = (swarp_vec3){0, 0.05, -1};
    } else if (!strcmp(name, "high")) {
        c->eye = (swarp_vec3){-220, 160, 390};
        c->dir = (swarp_vec3){220, -160, -480};
        c->far = 1000;
    } else if (!strcmp(name, "measure")) {
        c->eye = (swarp_vec3){0, 20, 390};
        c->dir = (swarp_vec3){0, 0, -1};
        c->far = 600;
    } else {
        c->eye = (swarp_vec3){8, 28, 395};
        c->dir = (swarp_vec3){-0.02, -0.11, -1};
    }
}

void extras_light(double elev, double azim, swarp_light* l) {
    memset(l, 0, sizeof *l);
    l->type = SWARP_LIGHT_DIRECTIONAL;
    double e = elev * DEG, a = azim * DEG;
    l->direction = (swarp_vec3){-cos(e) * sin(a), -sin(e), -cos(e) * cos(a)};
    if (elev >= 90) l->direction = (swarp_vec3){0, -1, 0};
}

int extras_setup(const extras_env* e, const demo_view* v, demo_technique t, int splits,
                 demo_shadow* sh) {
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = t;
    req.splits = splits;
    req.scheme = DEMO_SCHEME_PRACTICAL;
    req.scheme_lambda = 0.5;
    req.pseudo_near = 0.05;
    req.map_res = e->map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    return demo_shadow_setup(&v->cam, &v->light, &e->scene.box, &req, sh);
}

void extras_main_params(const demo_view* v, demo_mode mode, demo_filter filter, float blend,
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

int extras_render(extras_env* e, const demo_view* v, const demo_shadow* sh, demo_mode mode,
                  demo_image* im) {
    int errs = demo_render_shadow(&e->r, sh, e->filter, NULL);
    demo_main_params p;
    extras_main_params(v, mode, e->filter, sh->count > 1 && mode == DEMO_MODE_SHADED ? 0.1f : 0.0f,
                       &p);
    errs += demo_render_main(&e->r, sh, &p, NULL);
    if (im) {
        if (demo_image_alloc(im, v->w, v->h)) return errs + 1;
        demo_render_read_color(&e->r, v->w, v->h, im->px);
    }
    return errs;
}

int extras_write(const extras_env* e, const char* name, const demo_image* im) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s.png", e->out, name);
    int rc = demo_image_write_png(im, path);
    if (rc) fprintf(stderr, "demo-extras: cannot write %s\n", path);
    else printf("  wrote %s\n", path);
    return rc;
}

void extras_view_matrix(const demo_view* v, swarp_mat4* out) {
    swarp_mat4 a, b;
    mat4 view, proj;
    memcpy(view, v->view, sizeof view);
    memcpy(proj, v->proj, sizeof proj);
    swarp_cglm_mat4_to_swarp(view, &a);
    swarp_cglm_mat4_to_swarp(proj, &b);
    swarp_mat4_mul(&b, &a, out);
}

static int clip_segment(swarp_vec4* p, swarp_vec4* q) {
    const double eps = 1e-6;
    if (p->w < eps && q->w < eps) return 0;
    if (p->w < eps || q->w < eps) {
        double t = (eps - p->w) / (q->w - p->w);
        swarp_vec4 m = {p->x + t * (q->x - p->x), p->y + t * (q->y - p->y),
                        p->z + t * (q->z - p->z), eps};
        if (p->w < eps) *p = m;
        else *q = m;
    }
    return 1;
}

void extras_line3(demo_image* im, const swarp_mat4* m, swarp_vec3 a, swarp_vec3 b, int thick,
                  const uint8_t c[3]) {
    swarp_vec4 p, q;
    swarp_mat4_transform(m, &a, &p);
    swarp_mat4_transform(m, &b, &q);
    if (!clip_segment(&p, &q)) return;
    double x0 = (p.x / p.w * 0.5 + 0.5) * im->w, y0 = (0.5 - p.y / p.w * 0.5) * im->h;
    double x1 = (q.x / q.w * 0.5 + 0.5) * im->w, y1 = (0.5 - q.y / q.w * 0.5) * im->h;
    double lim = 8.0 * (im->w + im->h);
    if (fabs(x0) > lim || fabs(x1) > lim || fabs(y0) > lim || fabs(y1) > lim) return;
    demo_image_line(im, x0, y0, x1, y1, thick, c);
}

void extras_fill3(demo_image* im, const swarp_mat4* m, const swarp_vec3* pts, int n,
                  const uint8_t c[3], double alpha) {
    /* convex polygon, all vertices in front (w > 0), scanline fill */
    enum { MAXN = 64 };
    double x[MAXN], y[MAXN];
    if (n < 3 || n > MAXN) return;
    double ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < n; ++i) {
        swarp_vec4 h;
        swarp_mat4_transform(m, &pts[i], &h);
        if (!(h.w > 1e-6)) return;
        x[i] = (h.x / h.w * 0.5 + 0.5) * im->w;
        y[i] = (0.5 - h.y / h.w * 0.5) * im->h;
        ymin = fmin(ymin, y[i]);
        ymax = fmax(ymax, y[i]);
    }
    int y0 = (int)fmax(0, ceil(ymin - 0.5)), y1 = (int)fmin(im->h - 1, floor(ymax - 0.5));
    for (int yy = y0; yy <= y1; ++yy) {
        double sy = yy + 0.5, lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < n; ++i) {
            int j = (i + 1) % n;
            double ya = y[i], yb = y[j];
            if ((sy < ya) == (sy < yb)) continue;
            double t = (sy - ya) / (yb - ya);
            double xx = x[i] + t * (x[j] - x[i]);
            lo = fmin(lo, xx);
            hi = fmax(hi, xx);
        }
        if (!(hi >= lo)) continue;
        int xa = (int)fmax(0, ceil(lo - 0.5)), xb = (int)fmin(im->w - 1, floor(hi - 0.5));
        for (int xx = xa; xx <= xb; ++xx) {
            uint8_t* px = im->px + 4 * ((size_t)yy * im->w + xx);
            for (int k = 0; k < 3; ++k)
                px[k] = (uint8_t)lround((1 - alpha) * px[k] + alpha * c[k]);
        }
    }
}

static int cmp_d(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

double extras_median(double* a, int n) {
    if (n <= 0) return NAN;
    qsort(a, (size_t)n, sizeof *a, cmp_d);
    return n % 2 ? a[n / 2] : 0.5 * (a[n / 2 - 1] + a[n / 2]);
}

void extras_print_bench(const char* title, const extras_bench_row* rows, int n) {
    printf("\n%s\n", title);
    printf("%-48s %-10s %10s %10s %10s %10s %8s\n", "applied techniques", "3D passes",
           "shadow_ms", "extra_ms", "main_ms", "frame_ms", "fps");
    for (int i = 0; i < n; ++i)
        printf("%-48s %-10s %10.2f %10.2f %10.2f %10.2f %8.1f\n", rows[i].name, rows[i].passes,
               rows[i].shadow_ms, rows[i].extra_ms, rows[i].main_ms, rows[i].frame_ms,
               1000.0 / rows[i].frame_ms);
}

static int mkdir_p(const char* dir) {
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char* p = tmp + 1; *p; ++p)
        if (*p == '/') {
            *p = 0;
            if (mkdir(tmp, 0755) && errno != EEXIST) return -1;
            *p = '/';
        }
    if (mkdir(tmp, 0755) && errno != EEXIST) return -1;
    return 0;
}

static void usage(void) {
    printf("usage: demo-extras [options]\n"
           "  (no options)        every part of issue 10 into ./out/extras and the tables\n"
           "  --part P            viz | cloning | blur | mindepth | cube (repeatable)\n"
           "  --test T            cloning | mindepth | cube | blur | viz: headless check\n"
           "                      (exit 0 pass, 1 fail, 77 no OSMesa context)\n"
           "  --size WxH          picture size (default 960x540)\n"
           "  --map RES           texels per map side (default 1024)\n"
           "  --frames N          frames per timing (median; default 15)\n"
           "  --light-angle E[,A] sun elevation and azimuth, degrees (default 35,115)\n"
           "  --out DIR           output directory (default out/extras)\n");
}

int main(int argc, char** argv) {
    setvbuf(stdout, NULL, _IOLBF, 0); /* progress lines also when redirected */
    extras_env e;
    memset(&e, 0, sizeof e);
    e.w = 960;
    e.h = 540;
    e.map = 1024;
    e.frames = 15;
    e.out = "out/extras";
    e.light_elev = 35;
    e.light_azim = 115;
    e.filter = DEMO_FILTER_PCF3;
    const char* parts[8];
    int nparts = 0;
    const char* test = NULL;
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        const char* val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage();
            return 0;
        }
        if (!val) {
            fprintf(stderr, "demo-extras: %s needs a value (try --help)\n", a);
            return 2;
        }
        ++i;
        if (!strcmp(a, "--part") && nparts < 8) parts[nparts++] = val;
        else if (!strcmp(a, "--test")) test = val;
        else if (!strcmp(a, "--out")) e.out = val;
        else if (!strcmp(a, "--frames")) e.frames = atoi(val);
        else if (!strcmp(a, "--map")) e.map = atoi(val);
        else if (!strcmp(a, "--size")) {
            if (sscanf(val, "%dx%d", &e.w, &e.h) != 2 || e.w < 16 || e.h < 16 || e.w > 8192 ||
                e.h > 8192) {
                fprintf(stderr, "demo-extras: --size WxH (16..8192)\n");
                return 2;
            }
        } else if (!strcmp(a, "--light-angle")) {
            if (sscanf(val, "%lf,%lf", &e.light_elev, &e.light_azim) < 1 ||
                !(e.light_elev > 0 && e.light_elev <= 90)) {
                fprintf(stderr, "demo-extras: --light-angle E[,A] with 0 < E <= 90\n");
                return 2;
            }
        } else {
            fprintf(stderr, "demo-extras: unknown option %s (try --help)\n", a);
            return 2;
        }
    }
    if (e.map < 64 || e.map > 8192 || e.frames < 1) {
        fprintf(stderr, "demo-extras: --map 64..8192, --frames >= 1\n");
        return 2;
    }
    int maj = 0, min = 0;
    demo_ctx* ctx = demo_ctx_create(&maj, &min);
    if (!ctx) {
        printf("SKIP: OSMesa cannot create a core-profile context\n");
        return test ? 77 : 2;
    }
    if (demo_gl_load() || extras_gl_load()) {
        demo_ctx_destroy(ctx);
        return test ? 77 : 2;
    }
    printf("OpenGL %s on %s\n", (const char*)glGetString(GL_VERSION),
           (const char*)glGetString(GL_RENDERER));
    if (demo_scene_default(&e.scene) ||
        demo_render_init(&e.r, &e.scene, e.w, e.h, e.map, DEMO_MAX_SPLITS)) {
        demo_ctx_destroy(ctx);
        return 2;
    }
    e.v.w = e.w;
    e.v.h = e.h;
    extras_camera_preset("default", e.w, e.h, &e.v.cam);
    extras_light(e.light_elev, e.light_azim, &e.v.light);
    demo_view_update(&e.v);
    int rc = 0;
    if (test) {
        if (!strcmp(test, "cloning")) rc = extras_cloning(&e, 1, NULL, NULL);
        else if (!strcmp(test, "viz")) rc = extras_viz(&e, 1);
        else if (!strcmp(test, "mindepth")) rc = extras_mindepth(&e, 1);
        else if (!strcmp(test, "cube")) rc = extras_cube(&e, 1);
        else if (!strcmp(test, "blur")) rc = extras_blur(&e, 1);
        else {
            fprintf(stderr, "demo-extras: unknown test %s\n", test);
            rc = 2;
        }
    } else {
        if (mkdir_p(e.out)) {
            fprintf(stderr, "demo-extras: cannot create %s\n", e.out);
            rc = 2;
        }
        if (!nparts) {
            static const char* all[5] = {"viz", "cloning", "blur", "mindepth", "cube"};
            for (int i = 0; i < 5; ++i) parts[nparts++] = all[i];
        }
        extras_bench_row rows[32];
        int nrows = 0;
        double t0 = demo_now_ms();
        for (int i = 0; i < nparts && rc != 2; ++i) {
            int r = 0;
            printf("\n== %s ==\n", parts[i]);
            if (!strcmp(parts[i], "viz")) r = extras_viz(&e, 0);
            else if (!strcmp(parts[i], "cloning")) r = extras_cloning(&e, 0, rows, &nrows);
            else if (!strcmp(parts[i], "blur")) r = extras_blur(&e, 0);
            else if (!strcmp(parts[i], "mindepth")) r = extras_mindepth(&e, 0);
            else if (!strcmp(parts[i], "cube")) r = extras_cube(&e, 0);
            else {
                fprintf(stderr, "demo-extras: unknown part %s\n", parts[i]);
                r = 2;
            }
            if (r) rc = r;
        }
        if (nrows)
            extras_print_bench("frame cost, shaped like [RHS] Tables 7.1/7.2 (llvmpipe, glFinish-"
                               "bracketed, median of --frames)",
                               rows, nrows);
        printf("total %.1f s\n", (demo_now_ms() - t0) / 1e3);
    }
    demo_render_free(&e.r);
    demo_scene_free(&e.scene);
    demo_ctx_destroy(ctx);
    return rc;
}
