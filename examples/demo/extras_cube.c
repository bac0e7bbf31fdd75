/* extras_cube.c -- PSM with cube-map faces in the camera's post-perspective
 * space, [KOZ] §14.2.2, next to the single-map PSM with unit cube clipping
 * (the library's SWARP_TECHNIQUE_PSM): the comparison of Figs. 14-9/14-10.
 *
 * The library gives the faces (swarp_cube_faces: the unit-cube faces that
 * are back-facing w.r.t. the light P, each with its view-projection in
 * post-perspective space).  The demo renders face i with
 * world -> face clip = face[i].view_proj * M_c, where M_c is the virtual
 * camera's view-projection: the real camera slid back along -dir until every
 * point of the body B (swarp_body_points) lies in front of its near plane
 * ([KOZ] §14.2.1 "virtual slide-back"), so no caster of B has w <= 0.  A
 * user clip plane w_c > 0 drops the rest of the scene behind the virtual
 * camera (it cannot shadow anything in view and would wrap around).
 *
 * Lookup: the face whose clip square holds the point (w > 0), which is the
 * argmax of Listing 14-1 (the face pyramids from P through the back faces
 * do not overlap) -- the gallery's shader does exactly that for
 * DEMO_SELECT_LIXEL ("first map covering p"), so the main pass is reused
 * unchanged and checked against swarp_cube_lookup pixel by pixel. */
#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extras.h"
#include "shadowwarp_cglm.h"

static const char* const face_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "uniform mat4 u_m;\n"
    "uniform vec4 u_cam_w;\n"
    "out float gl_ClipDistance[1];\n"
    "void main() {\n"
    "  gl_Position = u_m * vec4(a_p, 1.0);\n"
    "  gl_ClipDistance[0] = dot(u_cam_w, vec4(a_p, 1.0));\n"
    "}\n";

typedef struct cube_setup {
    demo_shadow sh;            /* one map per face, DEMO_SELECT_LIXEL */
    swarp_cube_face faces[SWARP_CUBE_MAX_FACES];
    size_t nfaces;
    swarp_mat4 M_c;            /* virtual camera, world -> post-perspective (clip) */
    swarp_vec4 ps_light;
    double slide;              /* slide-back distance */
    double near_v, far_v;      /* virtual near/far */
} cube_setup;

static int cube_build(const extras_env* e, const demo_view* v, cube_setup* out) {
    memset(out, 0, sizeof *out);
    const swarp_camera* c = &v->cam;
    double n_adj, f_adj;
    swarp_status st = swarp_body_adjusted_range(c, &e->scene.box, &n_adj, &f_adj);
    if (swarp_status_is_error(st)) {
        fprintf(stderr, "demo-extras: adjusted range: %s\n", swarp_status_string(st));
        return -1;
    }
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
    size_t np = 0;
    st = swarp_body_points(c, n_adj, f_adj, &v->light, &e->scene.box, pts, SWARP_BODY_MAX_POINTS, &np);
    if (swarp_status_is_error(st) || np == 0) {
        fprintf(stderr, "demo-extras: body points: %s\n", swarp_status_string(st));
        return -1;
    }
    double dl = sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z);
    swarp_vec3 d = {c->dir.x / dl, c->dir.y / dl, c->dir.z / dl};
    double z_min = INFINITY;
    for (size_t i = 0; i < np; ++i)
        z_min = fmin(z_min, (pts[i].x - c->eye.x) * d.x + (pts[i].y - c->eye.y) * d.y +
                                (pts[i].z - c->eye.z) * d.z);
    /* slide back so every point of B has virtual depth >= n_adj */
    out->slide = fmax(0.0, n_adj - z_min);
    out->near_v = n_adj;
    out->far_v = f_adj + out->slide;
    swarp_camera vc = *c;
    vc.eye = (swarp_vec3){c->eye.x - d.x * out->slide, c->eye.y - d.y * out->slide,
                          c->eye.z - d.z * out->slide};
    vc.near = out->near_v;
    vc.far = out->far_v;
    demo_view vv = *v;
    vv.cam = vc;
    demo_view_update(&vv);
    extras_view_matrix(&vv, &out->M_c);
    /* the light, homogeneous, in post-perspective space: (-d, 0) for a
     * directional light travelling along d, (p, 1) for a point light */
    swarp_vec4 L;
    if (v->light.type == SWARP_LIGHT_DIRECTIONAL)
        L = (swarp_vec4){-v->light.direction.x, -v->light.direction.y, -v->light.direction.z, 0};
    else
        L = (swarp_vec4){v->light.position.x, v->light.position.y, v->light.position.z, 1};
    const double* m = out->M_c.m;
    out->ps_light = (swarp_vec4){m[0] * L.x + m[4] * L.y + m[8] * L.z + m[12] * L.w,
                                 m[1] * L.x + m[5] * L.y + m[9] * L.z + m[13] * L.w,
                                 m[2] * L.x + m[6] * L.y + m[10] * L.z + m[14] * L.w,
                                 m[3] * L.x + m[7] * L.y + m[11] * L.z + m[15] * L.w};
    st = swarp_cube_faces(&out->ps_light, NULL, out->faces, SWARP_CUBE_MAX_FACES, &out->nfaces);
    if (swarp_status_is_error(st) || out->nfaces == 0) {
        fprintf(stderr, "demo-extras: swarp_cube_faces: %s\n", swarp_status_string(st));
        return -1;
    }
    demo_shadow* sh = &out->sh;
    sh->count = (int)out->nfaces;
    sh->select = DEMO_SELECT_LIXEL;
    sh->depth_clamp = 0;
    sh->model_applies = 0;
    sh->near = c->near;
    sh->far = c->far;
    sh->split[0] = c->near;
    sh->split[1] = c->far;
    sh->predicted_max_mx = sh->predicted_max_mz = NAN;
    sh->status = st;
    sh->source = "library (swarp_cube_faces, post-perspective cube map)";
    for (int i = 0; i < sh->count; ++i) {
        swarp_mat4_mul(&out->faces[i].view_proj, &out->M_c, &sh->light[i]);
        sh->viewport[i][0] = sh->viewport[i][1] = e->map;
        sh->n_prime[i] = INFINITY;
    }
    return 0;
}

/* one pass per face into the gallery's depth array, clipped at w_c > 0 */
static int cube_shadow(extras_env* e, GLuint prog, const cube_setup* cs, double* ms) {
    demo_renderer* r = &e->r;
    double t0 = demo_now_ms();
    glBindFramebuffer(GL_FRAMEBUFFER, r->shadow_fbo);
    GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
    glUseProgram(prog);
    glBindVertexArray(r->vao);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CLIP_DISTANCE0);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 8.0f);
    const double* m = cs->M_c.m;
    /* row 3 of M_c (w_c), less a hair so points at w_c = 0 are dropped */
    glUniform4f(glGetUniformLocation(prog, "u_cam_w"), (float)m[3], (float)m[7], (float)m[11],
                (float)(m[15] - 1e-3 * cs->near_v));
    GLint loc = glGetUniformLocation(prog, "u_m");
    for (int i = 0; i < cs->sh.count; ++i) {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, r->shadow_tex, 0, i);
        glViewport(0, 0, r->map_res, r->map_res);
        glClear(GL_DEPTH_BUFFER_BIT);
        float f[16];
        if (swarp_mat4_to_float(&cs->sh.light[i], f) != SWARP_OK) return 1;
        glUniformMatrix4fv(loc, 1, GL_FALSE, f);
        glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CLIP_DISTANCE0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glFinish();
    if (ms) *ms = demo_now_ms() - t0;
    return demo_gl_check("cube-map face passes");
}

static const char* face_name(uint32_t f) {
    static const char* const n[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    return f < 6 ? n[f] : "?";
}

/* pixel by pixel: the face the shader used against swarp_cube_lookup */
static int check_faces(extras_env* e, const cube_setup* cs, const float* tex, const float* pos,
                       long* out_n, long* out_diff) {
    long n = 0, diff = 0;
    for (size_t k = 0; k < (size_t)e->w * e->h; ++k) {
        if (pos[4 * k + 3] < 0) continue;
        swarp_vec3 p = {pos[4 * k], pos[4 * k + 1], pos[4 * k + 2]};
        swarp_vec4 h;
        swarp_mat4_transform(&cs->M_c, &p, &h);
        if (!(h.w > 0)) continue;
        swarp_vec3 q = {h.x / h.w, h.y / h.w, h.z / h.w};
        uint32_t face = 99;
        swarp_status st = swarp_cube_lookup(&cs->ps_light, NULL, &q, &face, NULL, NULL);
        if (swarp_status_is_error(st)) continue;
        int got = (int)tex[4 * k + 2];
        ++n;
        diff += got < 0 || got >= cs->sh.count || cs->faces[got].face != face;
    }
    *out_n = n;
    *out_diff = diff;
    return 0;
}

static int test_cube(extras_env* e, GLuint prog) {
    /* (1) the shader's face = swarp_cube_lookup's face, over light angles;
     * (2) the box scene's shadow against its geometric shadow (IoU, as the
     * gallery's iou test) */
    int fails = 0;
    size_t npx = (size_t)e->w * e->h;
    float* tex = malloc(sizeof(float) * 4 * npx);
    float* pos = malloc(sizeof(float) * 4 * npx);
    if (!tex || !pos) {
        free(tex);
        free(pos);
        return 1;
    }
    const double angles[4][2] = {{35, 115}, {60, 20}, {20, 200}, {80, 300}};
    for (int a = 0; a < 4; ++a) {
        demo_view v = e->v;
        extras_light(angles[a][0], angles[a][1], &v.light);
        cube_setup cs;
        if (cube_build(e, &v, &cs)) {
            ++fails;
            continue;
        }
        demo_view saved = e->v;
        e->v = v;
        int errs = cube_shadow(e, prog, &cs, NULL);
        demo_main_params p;
        extras_main_params(&v, DEMO_MODE_SHADED, DEMO_FILTER_NONE, 0, &p);
        errs += demo_render_main(&e->r, &cs.sh, &p, NULL);
        demo_render_read_aux(&e->r, tex, pos);
        e->v = saved;
        long n = 0, diff = 0;
        check_faces(e, &cs, tex, pos, &n, &diff);
        double frac = n ? (double)diff / n : 1;
        int ok = errs == 0 && n > 1000 && frac <= 0.005 && cs.nfaces >= 3;
        printf("cube light %2.0f,%3.0f: P w %+.3g, %zu faces, %ld pixels, %ld use another face "
               "than swarp_cube_lookup (%.3f%%) %s\n",
               angles[a][0], angles[a][1], cs.ps_light.w, cs.nfaces, n, diff, 100 * frac,
               ok ? "ok" : "FAIL");
        fails += !ok;
    }
    /* IoU on the box scene */
    demo_scene box_scene;
    swarp_aabb caster;
    if (demo_scene_box(&box_scene, &caster) == 0) {
        extras_env be = *e;
        demo_renderer saved_r = e->r;
        if (demo_render_init(&be.r, &box_scene, e->w, e->h, e->map, DEMO_MAX_SPLITS) == 0) {
            be.scene = box_scene;
            demo_view v = e->v;
            v.cam.eye = (swarp_vec3){0, 30, 45};
            v.cam.dir = (swarp_vec3){0, -0.75, -1};
            v.cam.fovy = 50 * 3.14159265358979323846 / 180;
            v.cam.near = 1;
            v.cam.far = 150;
            v.light.type = SWARP_LIGHT_DIRECTIONAL;
            v.light.direction = (swarp_vec3){0.45, -1, 0.3};
            demo_view_update(&v);
            be.v = v;
            cube_setup cs;
            if (cube_build(&be, &v, &cs) == 0) {
                int errs = cube_shadow(&be, prog, &cs, NULL);
                demo_main_params p;
                extras_main_params(&v, DEMO_MODE_SHADED, DEMO_FILTER_PCF2, 0, &p);
                errs += demo_render_main(&be.r, &cs.sh, &p, NULL);
                demo_render_read_aux(&be.r, NULL, pos);
                /* the box's shadow on y = 0: the corners projected along the
                 * light; the shadow of a box is the convex hull, and a point
                 * is inside iff the light ray through it hits the box */
                const swarp_vec3 ld = v.light.direction;
                long inter = 0, uni = 0;
                for (size_t i = 0; i < npx; ++i) {
                    const float* q = pos + 4 * i;
                    if (q[3] < 0 || fabsf(q[1]) > 1e-3f) continue;
                    /* ray q - t ld, t >= 0, against the box (slabs) */
                    double o[3] = {q[0], q[1], q[2]}, dd[3] = {-ld.x, -ld.y, -ld.z};
                    double lo[3] = {caster.min.x, caster.min.y, caster.min.z};
                    double hi[3] = {caster.max.x, caster.max.y, caster.max.z};
                    double t0 = 0, t1 = INFINITY;
                    for (int k = 0; k < 3; ++k) {
                        if (fabs(dd[k]) < 1e-12) {
                            if (o[k] < lo[k] || o[k] > hi[k]) t1 = -1;
                            continue;
                        }
                        double ta = (lo[k] - o[k]) / dd[k], tb = (hi[k] - o[k]) / dd[k];
                        t0 = fmax(t0, fmin(ta, tb));
                        t1 = fmin(t1, fmax(ta, tb));
                    }
                    int geometric = t1 >= t0;
                    int rendered = q[3] < 0.5f;
                    inter += rendered && geometric;
                    uni += rendered || geometric;
                }
                double iou = uni ? (double)inter / uni : 0;
                int ok = errs == 0 && iou >= 0.95 && uni > 200;
                printf("cube box scene: %zu faces, IoU with the geometric shadow %.4f (%ld pixels) %s\n",
                       cs.nfaces, iou, uni, ok ? "ok" : "FAIL");
                fails += !ok;
            } else {
                ++fails;
            }
            demo_render_free(&be.r);
        } else {
            ++fails;
        }
        e->r = saved_r;
        demo_scene_free(&box_scene);
    } else {
        ++fails;
    }
    free(tex);
    free(pos);
    return fails ? 1 : 0;
}

static int cube_part(extras_env* e, GLuint prog, demo_image* sheet, int pass, int cw, int ch,
                     int hdr) {
    int rc = 0;
    cube_setup cs;
    demo_shadow psm;
    if (cube_build(e, &e->v, &cs) || extras_setup(e, &e->v, DEMO_TECH_PSM, 1, &psm)) return 1;
    printf("  camera near %.2f: light in post-perspective space (%.4g, %.4g, %.4g, %.4g), "
           "slide-back %.2f, virtual near/far %.2f/%.2f\n",
           e->v.cam.near, cs.ps_light.x, cs.ps_light.y, cs.ps_light.z, cs.ps_light.w, cs.slide,
           cs.near_v, cs.far_v);
    printf("  %zu faces:", cs.nfaces);
    for (size_t i = 0; i < cs.nfaces; ++i)
        printf(" %s (d = %.3f%s)", face_name(cs.faces[i].face), cs.faces[i].distance,
               cs.faces[i].inverse ? ", inverse" : "");
    printf("\n");
    int F = e->frames;
    double* t = malloc(sizeof(double) * 2 * (size_t)F);
    if (!t) return 1;
    for (int f = 0; f < F; ++f) {
        rc |= cube_shadow(e, prog, &cs, &t[f]) != 0;
        double ms[DEMO_MAX_SPLITS];
        rc |= demo_render_shadow(&e->r, &psm, DEMO_FILTER_PCF3, ms) != 0;
        t[F + f] = ms[0];
    }
    printf("  shadow passes: cube map %zu faces %.2f ms (%.0f texels), single-map PSM %.2f ms "
           "(%.0f texels); median of %d\n",
           cs.nfaces, extras_median(t, F), (double)cs.nfaces * e->map * e->map,
           extras_median(t + F, F), (double)e->map * e->map, F);
    free(t);
    const demo_mode modes[3] = {DEMO_MODE_SHADED, DEMO_MODE_SAMPLING, DEMO_MODE_GRID};
    for (int row = 0; row < 2; ++row) {
        const demo_shadow* sh = row ? &cs.sh : &psm;
        for (int c = 0; c < 3; ++c) {
            if (row) rc |= cube_shadow(e, prog, &cs, NULL) != 0;
            else rc |= demo_render_shadow(&e->r, sh, e->filter, NULL) != 0;
            demo_main_params p;
            extras_main_params(&e->v, modes[c], e->filter, 0, &p);
            p.grid = 16;
            rc |= demo_render_main(&e->r, sh, &p, NULL) != 0;
            demo_image im, small;
            if (demo_image_alloc(&im, e->w, e->h)) continue;
            demo_render_read_color(&e->r, e->w, e->h, im.px);
            if (c == 1) demo_image_sampling_legend(&im, 20, e->h - 44, e->w / 2 > 420 ? 420 : e->w / 2);
            if (c == 0) {
                char lab[128];
                if (row)
                    snprintf(lab, sizeof lab, "PSM cube map, %zu faces, near %.1f", cs.nfaces,
                             e->v.cam.near);
                else
                    snprintf(lab, sizeof lab, "PSM one map (unit cube clip), near %.1f", e->v.cam.near);
                demo_image_label(&im, 8, 8, 2, lab);
            }
            if (demo_image_resize(&im, cw, ch, &small) == 0) {
                demo_image_blit(sheet, c * cw, hdr + (2 * (pass % 2) + row) * ch, &small);
                demo_image_free(&small);
            }
            if (c == 0 && row == 1 && pass == 0) {
                /* which face each pixel uses (split colours of (5.1)) */
                demo_image fi;
                extras_main_params(&e->v, DEMO_MODE_SPLITS, e->filter, 0, &p);
                rc |= demo_render_main(&e->r, sh, &p, NULL) != 0;
                if (demo_image_alloc(&fi, e->w, e->h) == 0) {
                    demo_render_read_color(&e->r, e->w, e->h, fi.px);
                    demo_image_label(&fi, 8, 8, 2, "PSM cube map: face per pixel (colours of (5.1))");
                    rc |= extras_write(e, "cube_faces", &fi);
                    demo_image_free(&fi);
                }
            }
            demo_image_free(&im);
        }
    }
    return rc;
}

int extras_cube(extras_env* e, int test) {
    GLuint prog = extras_gl_program("cube-map faces", face_vs, NULL, NULL);
    if (!prog) return 1;
    if (test) {
        int rc = test_cube(e, prog);
        glDeleteProgram(prog);
        return rc;
    }
    int rc = 0;
    /* rows: PSM one map / cube map with the camera's near plane, then both
     * with the near plane measured by the GPU mip-min chain ([RHS] §4.3,
     * which is what PSM needs most: [RHS] Fig. 4.3).  Two suns: the
     * default one (in front of the camera: w > 0) and one from behind the
     * camera (w < 0: the inverse-projection faces and a virtual slide-back) */
    const int cw = 480, ch = 270, hdr = 28;
    demo_view saved = e->v;
    for (int light = 0; light < 2; ++light) {
        demo_image sheet;
        if (demo_image_alloc(&sheet, 3 * cw, hdr + 4 * ch)) return 1;
        const uint8_t white[3] = {255, 255, 255}, black[3] = {0, 0, 0};
        demo_image_fill(&sheet, 0, 0, sheet.w, sheet.h, white);
        const char* cols[3] = {"shaded", "sampling rate (Listing A.3)", "texel grid (Listing A.4)"};
        for (int c = 0; c < 3; ++c) demo_image_text(&sheet, c * cw + 8, 8, 2, cols[c], black);
        if (light == 1) {
            extras_light(35, 10, &e->v.light);
            printf("  sun from behind the camera (elevation 35, azimuth 10):\n");
        }
        demo_view lit = e->v;
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) {
                double n = extras_measured_near(e, &lit);
                if (!(n > 0)) {
                    rc = 1;
                    break;
                }
                e->v.cam.near = n;
                demo_view_update(&e->v);
            }
            rc |= cube_part(e, prog, &sheet, pass + 2 * light, cw, ch, hdr);
        }
        e->v = saved;
        rc |= extras_write(e, light ? "cube_sheet_behind" : "cube_sheet", &sheet);
        demo_image_free(&sheet);
    }
    glDeleteProgram(prog);
    return rc;
}
