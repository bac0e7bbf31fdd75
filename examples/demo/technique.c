/* technique.c -- one technique for one view: every picture of [RHS]
 * chapter 5, the measurement along the view vector and the timing. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "technique.h"

/* Median of 101 calls of demo_shadow_setup, in microseconds: the median
 * discards the calls a busy machine slowed down. */
static double time_setup(const demo_view* v, const swarp_aabb* box,
                         const demo_shadow_request* req, demo_shadow* sh) {
    enum { REPS = 101 };
    double t[REPS];
    for (int i = 0; i < REPS; ++i) {
        double t0 = demo_now_ms();
        if (demo_shadow_setup(&v->cam, &v->light, box, req, sh)) return -1;
        t[i] = (demo_now_ms() - t0) * 1e3;
    }
    return demo_median(t, REPS);
}

int demo_read_picture(demo_renderer* r, int w, int h, demo_image* im) {
    if (demo_image_alloc(im, w, h)) return -1;
    demo_render_read_color(r, w, h, im->px);
    return 0;
}

static int light_view_picture(demo_renderer* r, const demo_view* v, const demo_shadow* sh,
                              demo_image* out) {
    /* one tile per map (Fig. 5.5): the scene as the light sees it, the view
     * (split) frustum in black, the view vector in blue in the first tile */
    int k = sh->count, cols = (int)ceil(sqrt((double)k));
    int rows = (k + cols - 1) / cols;
    int side = v->h < v->w ? v->h : v->w;
    int tile = side / (cols > rows ? cols : rows);
    if (demo_image_alloc(out, tile * cols, tile * rows)) return -1;
    const uint8_t white[3] = {255, 255, 255};
    demo_image_fill(out, 0, 0, out->w, out->h, white);
    int errors = 0;
    for (int i = 0; i < k; ++i) {
        demo_shadow one = *sh;
        one.count = 1;
        one.light[0] = sh->light[i];
        demo_main_params p;
        memset(&p, 0, sizeof p);
        float ident[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        memcpy(p.view, ident, sizeof ident);
        if (swarp_mat4_to_float(&sh->light[i], p.proj) != SWARP_OK) return -1;
        p.light_dir[0] = (float)v->light.direction.x;
        p.light_dir[1] = (float)v->light.direction.y;
        p.light_dir[2] = (float)v->light.direction.z;
        p.mode = DEMO_MODE_UNSHADOWED;
        p.vw = tile;
        p.vh = tile;
        errors += demo_render_main(r, &one, &p, NULL);
        demo_image t;
        if (demo_read_picture(r, tile, tile, &t)) return -1;
        const uint8_t black[3] = {0, 0, 0};
        /* split frustum for cascades, the whole view for lixel maps */
        int whole = sh->select == DEMO_SELECT_LIXEL;
        demo_draw_frustum(&t, &sh->light[i], v, whole ? sh->z_near : sh->split[i],
                          whole ? sh->z_far : sh->split[i + 1], black, i == 0);
        char lab[32];
        snprintf(lab, sizeof lab, "map %d", i);
        if (k > 1) demo_image_label(&t, 6, 6, 1, lab);
        demo_image_blit(out, (i % cols) * tile, (i / cols) * tile, &t);
        demo_image_free(&t);
    }
    return errors;
}

int demo_write_png(const demo_options* o, const char* label, const char* what, const demo_image* im) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s_%s.png", o->out, label, what);
    return demo_image_write_png(im, path);
}

/* The label of the pictures: the planned entry's, "nameK" for the split
 * techniques, else the technique's name. */
static void technique_label(const demo_options* o, demo_technique t, int splits, char* out,
                            size_t cap) {
    if (o->label_override)
        snprintf(out, cap, "%s", o->label_override);
    else if (demo_technique_is_split((demo_technique)t))
        snprintf(out, cap, "%s%d", demo_technique_name(t), splits);
    else
        snprintf(out, cap, "%s", demo_technique_name(t));
}

/* The command line's shadow request for technique t with `splits` maps. */
static void technique_request(const demo_options* o, const demo_view* v, demo_technique t,
                              int splits, demo_shadow_request* req) {
    memset(req, 0, sizeof *req);
    req->technique = t;
    req->splits = splits;
    req->scheme = o->scheme;
    req->scheme_lambda = o->scheme_lambda;
    req->pseudo_near = o->pseudo_near;
    req->pseudo_far = o->pseudo_far;
    req->scheme_np = o->scheme_np;
    req->scheme_fp = o->scheme_fp;
    req->select = o->select;
    req->map_res = o->map;
    req->screen_w = v->w;
    req->screen_h = v->h;
    req->nprime_measured = o->nprime_measured;
    req->basis_aligned = o->basis_aligned;
}

/* The command line's main-pass parameters for view v and its sh.count maps
 * (no blend band with one map). */
static void technique_main_params(const demo_options* o, const demo_view* v,
                                  const demo_shadow* sh, demo_main_params* p) {
    demo_main_params_for(v, DEMO_MODE_SHADED, o->filter, sh->count > 1 ? o->blend : 0.0f, p);
    p->grid = o->grid;
    p->normal_offset = o->offset;
}

/* The shaded view, then from the same pass's float targets (texel
 * coordinates, world positions, facet normals): the measured error of
 * docs/accuracy.md over every visible receiver, and m_x, m_z along the view
 * vector for Lloyd's graph. */
static int technique_shade_and_measure(const demo_options* o, demo_renderer* r,
                                       const demo_view* v, const demo_shadow* sh,
                                       demo_main_params* p, demo_tech_result* res) {
    p->mode = DEMO_MODE_SHADED;
    res->gl_errors += demo_render_main(r, sh, p, &res->main_ms);
    if (demo_read_picture(r, v->w, v->h, &res->shaded)) return -1;
    size_t n = 4 * (size_t)v->w * v->h;
    float* tex = malloc(sizeof(float) * n);
    float* pos = malloc(sizeof(float) * n);
    float* nrm = malloc(sizeof(float) * n);
    int rc = tex && pos && nrm ? 0 : -1;
    if (rc == 0) {
        demo_render_read_aux(r, tex, pos);
        demo_render_read_normals(r, nrm);
        rc = demo_measure_render(v, sh, tex, pos, nrm, &res->measured);
        /* Lloyd's model along the view vector only where it describes the
         * configuration (not for lixel or cube-face maps) */
        res->nrows = sh->model_applies
                         ? demo_measure(v, sh, o->map, tex, pos, res->rows, DEMO_MEASURE_ROWS)
                         : 0;
    }
    free(tex);
    free(pos);
    free(nrm);
    return rc;
}

/* The sampling-rate, split-colour and texel-grid views, the light view and
 * the third-person view of sh, rendered and read back. */
static int technique_render_pictures(demo_renderer* r, const demo_view* v,
                                     const swarp_aabb* box, const demo_shadow* sh,
                                     demo_main_params* p, demo_tech_result* res,
                                     demo_image* third) {
    p->mode = DEMO_MODE_SAMPLING;
    p->blend = 0;
    res->gl_errors += demo_render_main(r, sh, p, NULL);
    if (demo_read_picture(r, v->w, v->h, &res->sampling)) return -1;
    p->mode = DEMO_MODE_SPLITS;
    res->gl_errors += demo_render_main(r, sh, p, NULL);
    if (demo_read_picture(r, v->w, v->h, &res->splits)) return -1;
    p->mode = DEMO_MODE_GRID;
    res->gl_errors += demo_render_main(r, sh, p, NULL);
    if (demo_read_picture(r, v->w, v->h, &res->grid)) return -1;
    int e = light_view_picture(r, v, sh, &res->light);
    if (e < 0) return -1;
    res->gl_errors += e;
    int body_faces = 0;
    int e3 = demo_third_person(r, v, sh, box, p, third, &body_faces);
    if (e3 < 0) return -1;
    res->gl_errors += e3;
    if (body_faces < 4) {
        /* a body B is a polyhedron: the library gave none to draw */
        fprintf(stderr, "demo: %s: no body B drawn in the third-person view\n", res->label);
        ++res->gl_errors;
    }
    return 0;
}

/* Labels the pictures, records the least non-blank one and writes all
 * seven as o->out/LABEL_WHAT.png. */
static int technique_write_pictures(const demo_options* o, const demo_view* v,
                                    demo_tech_result* res, const demo_image* graph,
                                    const demo_image* third) {
    demo_image_label(&res->shaded, 8, 8, 2, res->label);
    demo_image_label(&res->sampling, 8, 8, 2, res->label);
    demo_image_sampling_legend(&res->sampling, 20, v->h - 44, v->w / 2 > 420 ? 420 : v->w / 2);
    demo_image_label(&res->splits, 8, 8, 2, res->label);
    demo_image_label(&res->grid, 8, 8, 2, res->label);
    char gl[64];
    snprintf(gl, sizeof gl, "grid: %g texels per cell", (double)o->grid);
    demo_image_label(&res->grid, 8, 40, 1, gl);
    demo_image_label(&res->light, 8, res->light.h - 20, 1, res->label);
    const demo_image* all[7] = {&res->shaded, &res->sampling, &res->splits, &res->grid,
                                &res->light,  graph,          third};
    static const char* const what[7] = {"shaded", "sampling", "splits", "grid",
                                        "light",  "error",    "third"};
    res->min_nonblank = 1.0;
    for (int k = 0; k < 7; ++k) {
        double nb = demo_image_nonblank(all[k]);
        if (nb < res->min_nonblank) res->min_nonblank = nb;
    }
    int w = 0;
    for (int k = 0; k < 7; ++k) w |= demo_write_png(o, res->label, what[k], all[k]);
    return w ? -1 : 0;
}

/* Every picture of sh for view v: rendered, the error graph drawn, all
 * written. */
static int technique_pictures(const demo_options* o, demo_renderer* r, const demo_view* v,
                              const swarp_aabb* box, const demo_shadow* sh,
                              demo_main_params* p, demo_tech_result* res) {
    demo_image third;
    if (technique_render_pictures(r, v, box, sh, p, res, &third)) return -1;
    char title[160];
    snprintf(title, sizeof title, "%s: m_x, m_z along the view vector", res->label);
    demo_image graph;
    if (demo_error_graph(v, sh, o->map, res->rows, res->nrows, title, &graph)) return -1;
    int w = technique_write_pictures(o, v, res, &graph, &third);
    demo_image_free(&graph);
    demo_image_free(&third);
    return w;
}

int demo_run_technique(const demo_options* o, demo_renderer* r, const demo_view* v,
                       const swarp_aabb* box, demo_technique t, int splits, int write,
                       demo_tech_result* res) {
    memset(res, 0, sizeof *res);
    res->tech = t;
    technique_label(o, t, splits, res->label, sizeof res->label);
    demo_shadow_request req;
    technique_request(o, v, t, splits, &req);
    demo_shadow sh;
    res->setup_us = time_setup(v, box, &req, &sh);
    if (res->setup_us < 0) return -2;
    res->source = sh.source;
    res->sh = sh;
    res->passes = sh.count + 1;
    res->texels = (double)sh.count * o->map * o->map;
    res->gl_errors += demo_render_shadow(r, &sh, o->filter, res->shadow_ms);
    for (int i = 0; i < sh.count; ++i) res->shadow_ms_total += res->shadow_ms[i];
    demo_main_params p;
    technique_main_params(o, v, &sh, &p);
    if (technique_shade_and_measure(o, r, v, &sh, &p, res)) return -1;
    res->max_mx = sh.predicted_max_mx;
    res->max_mz = sh.predicted_max_mz;
    if (write && technique_pictures(o, r, v, box, &sh, &p, res)) return -1;
    res->ok = 1;
    return 0;
}

void demo_tech_result_free(demo_tech_result* r) {
    demo_image_free(&r->shaded);
    demo_image_free(&r->sampling);
    demo_image_free(&r->splits);
    demo_image_free(&r->grid);
    demo_image_free(&r->light);
}

void demo_print_measured(const demo_tech_result* r) {
    const demo_measured* m = &r->measured;
    const swarp_measured_error* h = &r->sh.measured;
    printf("  measured error (docs/accuracy.md) over %d receiver pixels (%s):\n", m->pixels,
           r->label);
    printf("    render (texel coordinates read back): max m_s %.4g, m_t %.4g, sigma %.4g at "
           "(%.1f %.1f %.1f), cos psi_l %.3f\n", m->render_m_s, m->render_m_t, m->render_sigma,
           m->render_at.x, m->render_at.y, m->render_at.z, m->render_cos_light);
    printf("    swarp_measure_points, same pixels:    max m_s %.4g, m_t %.4g, sigma %.4g at "
           "(%.1f %.1f %.1f)\n", m->points_m_s, m->points_m_t, m->points_sigma, m->points_at.x,
           m->points_at.y, m->points_at.z);
    printf("    per pixel |render/points - 1| of sigma: 99th percentile %.2e, max %.2e\n",
           m->pixel_dev_p99, m->pixel_dev_max);
    if (r->sh.have_measured)
        printf("    result's measured (H, bisector receivers): max m_s %.4g, m_t %.4g, sigma %.4g at "
               "(%.1f %.1f %.1f), %u samples\n", h->max_m_s, h->max_m_t, h->max_sigma, h->at.x,
               h->at.y, h->at.z, h->samples);
    if (r->sh.have_measured && r->sh.count == 1)
        printf("    n' %.4g (eye units; inf: uniform)\n", r->sh.n_prime[0]);
}

void demo_print_measure(const demo_tech_result* r) {
    printf("  measured vs predicted along the view vector (%s):\n", r->label);
    printf("  %9s %5s %9s %9s %7s %9s %9s %7s %6s\n", "z", "split", "meas m_x", "pred m_x",
           "ratio", "meas m_z", "pred m_z", "ratio", "n");
    for (int i = 0; i < r->nrows; ++i) {
        const demo_measure_row* q = &r->rows[i];
        printf("  %9.2f %5d %9.4f %9.4f %7.3f %9.4f %9.4f %7.3f %6d\n", q->z, q->split, q->mx,
               q->pred_mx, q->ratio_mx, q->mz, q->pred_mz, q->ratio_mz, q->samples);
    }
}
