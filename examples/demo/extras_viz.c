/* extras_viz.c -- the third-person "visualization view" of [RHS] §5.2-5.3:
 * the scene from an outside camera with the common view's frustum (and
 * split frusta), the light direction, the intersection body B of every map
 * (swarp_body_h / swarp_body_from_h, the polyhedra behind swarp_body_points)
 * and each shadow map's world-space footprint (tint, border and a texel grid
 * every map_res/16 texels, [RHS] §5.4 "texel borders" seen from outside),
 * plus the common view as a minimap (Fig. 5.1). */
#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extras.h"

static const char* const viz_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "layout(location = 1) in vec3 a_n;\n"
    "layout(location = 2) in vec3 a_c;\n"
    "uniform mat4 u_view, u_proj;\n"
    "out vec3 v_p; out vec3 v_n; out vec3 v_c;\n"
    "void main() { v_p = a_p; v_n = a_n; v_c = a_c; gl_Position = u_proj * u_view * vec4(a_p, 1.0); }\n";

/* Shadow of the COMMON view's configuration: the map is picked by the
 * common camera's eye depth (swarp_cascade_select_depth, as the gallery's
 * main pass), only inside the common view frustum; outside it the scene is
 * drawn unshadowed and darker.  Footprint: the first (finest) map whose
 * clip square holds p, tinted with the split colour of (5.1). */
static const char* const viz_fs =
    "in vec3 v_p; in vec3 v_n; in vec3 v_c;\n"
    "layout(location = 0) out vec4 o_color;\n"
    "uniform sampler2DArrayShadow u_shadow;\n"
    "uniform mat4 u_light[16];\n"
    "uniform vec2 u_uvscale[16];\n"
    "uniform float u_split[17];\n"
    "uniform int u_count;\n"
    "uniform float u_res, u_grid;\n"
    "uniform vec3 u_light_dir, u_eye, u_dir;\n"
    "uniform mat4 u_cam;\n"
    "const vec3 sp[4] = vec3[4](vec3(1,0,0), vec3(1,1,0), vec3(0,1,0), vec3(0,0,1));\n"
    "void main() {\n"
    "  vec3 n = normalize(v_n);\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  float ndl = max(dot(n, -normalize(u_light_dir)), 0.0);\n"
    "  vec4 cc = u_cam * vec4(v_p, 1.0);\n"
    "  bool inview = cc.w > 0.0 && all(lessThanEqual(abs(cc.xyz), vec3(cc.w)));\n"
    "  float z = dot(v_p - u_eye, u_dir);\n"
    "  int i = u_count - 1;\n"
    "  for (int k = 0; k < u_count - 1; ++k) if (z < u_split[k + 1]) { i = k; break; }\n"
    "  float lit = 1.0;\n"
    "  if (inview) {\n"
    "    vec4 h = u_light[i] * vec4(v_p, 1.0);\n"
    "    vec3 sc = h.xyz / h.w * 0.5 + 0.5;\n"
    "    if (all(greaterThanEqual(sc, vec3(0.0))) && all(lessThanEqual(sc, vec3(1.0)))) {\n"
    "      lit = 0.0;\n"
    "      for (int y = -1; y <= 1; ++y) for (int x = -1; x <= 1; ++x)\n"
    "        lit += texture(u_shadow, vec4(sc.xy * u_uvscale[i] + vec2(x, y) / u_res, float(i), sc.z));\n"
    "      lit /= 9.0;\n"
    "    }\n"
    "  }\n"
    "  if (ndl <= 0.0) lit = 0.0;\n"
    "  vec3 col = v_c * (0.35 + 0.65 * ndl * lit);\n"
    "  if (!inview) col *= 0.7;\n"
    "  for (int k = 0; k < u_count; ++k) {\n"
    "    vec4 h = u_light[k] * vec4(v_p, 1.0);\n"
    "    if (!(h.w > 0.0 && abs(h.x) <= h.w && abs(h.y) <= h.w)) continue;\n"
    "    vec2 res = u_res * u_uvscale[k];\n"
    "    vec2 uv = (h.xy / h.w * 0.5 + 0.5) * res;\n"
    "    vec3 tint = u_count == 1 ? vec3(1.0, 0.1, 0.1) : sp[k % 4];\n"
    "    col = mix(col, tint, 0.3);\n"
    "    vec2 fw = max(fwidth(uv), vec2(1e-6));\n"
    "    vec2 g = fract(uv / u_grid) * u_grid;\n"
    "    if (any(lessThan(g, fw)))\n"
    "      col = mix(col, tint * 0.35, 0.6);\n"
    "    vec2 edge = min(uv, res - uv);\n"
    "    if (any(lessThan(edge, 2.5 * fw))) col = tint * 0.45;\n"
    "    break;\n"
    "  }\n"
    "  o_color = vec4(col, 1.0);\n"
    "}\n";

static const uint8_t split_rgb[4][3] = {{230, 0, 0}, {230, 200, 0}, {0, 190, 0}, {0, 60, 255}};

static void draw_body(demo_image* im, const swarp_mat4* m, const swarp_polyhedron* B,
                      const uint8_t c[3]) {
    for (uint32_t f = 0; f < B->face_count; ++f) {
        swarp_vec3 pts[SWARP_POLY_MAX_FACE_VERTICES];
        uint32_t n = B->face_vertex_count[f];
        for (uint32_t k = 0; k < n; ++k) pts[k] = B->vertices[B->face_vertices[f][k]];
        extras_fill3(im, m, pts, (int)n, c, 0.10);
    }
    uint8_t dark[3] = {(uint8_t)(c[0] * 0.6), (uint8_t)(c[1] * 0.6), (uint8_t)(c[2] * 0.6)};
    for (uint32_t f = 0; f < B->face_count; ++f) {
        uint32_t n = B->face_vertex_count[f];
        for (uint32_t k = 0; k < n; ++k)
            extras_line3(im, m, B->vertices[B->face_vertices[f][k]],
                         B->vertices[B->face_vertices[f][(k + 1) % n]], 2, dark);
    }
}

/* the outside camera: high, behind and to the left of the common view */
static void outside_view(const extras_env* e, demo_view* ov) {
    *ov = e->v;
    ov->cam.eye = (swarp_vec3){-700, 640, 960};
    swarp_vec3 target = {20, 10, 20};
    ov->cam.dir = (swarp_vec3){target.x - ov->cam.eye.x, target.y - ov->cam.eye.y,
                               target.z - ov->cam.eye.z};
    ov->cam.fovy = 46 * 3.14159265358979323846 / 180;
    ov->cam.near = 10;
    ov->cam.far = 4000;
    demo_view_update(ov);
}

static int one(extras_env* e, GLuint prog, demo_technique t, int splits, const char* name,
               demo_image* out) {
    demo_shadow sh;
    if (extras_setup(e, &e->v, t, splits, &sh)) return -1;
    demo_image common;
    memset(&common, 0, sizeof common);
    int errs = extras_render(e, &e->v, &sh, DEMO_MODE_SHADED, &common);
    if (errs) {
        demo_image_free(&common);
        return -1;
    }
    demo_view ov;
    outside_view(e, &ov);

    /* third-person pass (the shadow maps of sh are still bound) */
    demo_renderer* r = &e->r;
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    glViewport(0, 0, e->w, e->h);
    const float sky[4] = {0.62f, 0.75f, 0.92f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, sky);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glUseProgram(prog);
    glBindVertexArray(r->vao);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_view"), 1, GL_FALSE, ov.view);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_proj"), 1, GL_FALSE, ov.proj);
    float lm[16 * DEMO_MAX_SPLITS], uvs[2 * DEMO_MAX_SPLITS], split[DEMO_MAX_SPLITS + 1];
    for (int i = 0; i < sh.count; ++i) {
        if (swarp_mat4_to_float(&sh.light[i], lm + 16 * i) != SWARP_OK) {
            demo_image_free(&common);
            return -1;
        }
        uvs[2 * i] = (float)sh.viewport[i][0] / (float)e->map;
        uvs[2 * i + 1] = (float)sh.viewport[i][1] / (float)e->map;
    }
    for (int i = 0; i <= sh.count; ++i) split[i] = (float)sh.split[i];
    swarp_mat4 cam_m, out_m;
    extras_view_matrix(&e->v, &cam_m);
    extras_view_matrix(&ov, &out_m);
    float cm[16];
    swarp_mat4_to_float(&cam_m, cm);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_light"), sh.count, GL_FALSE, lm);
    glUniform2fv(glGetUniformLocation(prog, "u_uvscale"), sh.count, uvs);
    glUniform1fv(glGetUniformLocation(prog, "u_split"), sh.count + 1, split);
    glUniform1i(glGetUniformLocation(prog, "u_count"), sh.count);
    glUniform1f(glGetUniformLocation(prog, "u_res"), (float)e->map);
    glUniform1f(glGetUniformLocation(prog, "u_grid"), (float)e->map / 16.0f);
    const swarp_camera* c = &e->v.cam;
    double dl = sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z);
    glUniform3f(glGetUniformLocation(prog, "u_light_dir"), (float)e->v.light.direction.x,
                (float)e->v.light.direction.y, (float)e->v.light.direction.z);
    glUniform3f(glGetUniformLocation(prog, "u_eye"), (float)c->eye.x, (float)c->eye.y,
                (float)c->eye.z);
    glUniform3f(glGetUniformLocation(prog, "u_dir"), (float)(c->dir.x / dl), (float)(c->dir.y / dl),
                (float)(c->dir.z / dl));
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_cam"), 1, GL_FALSE, cm);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, r->shadow_tex);
    glUniform1i(glGetUniformLocation(prog, "u_shadow"), 0);
    glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    glFinish();
    if (demo_gl_check("visualization view") || demo_image_alloc(out, e->w, e->h)) {
        demo_image_free(&common);
        return -1;
    }
    demo_render_read_color(r, e->w, e->h, out->px);

    /* bodies B (per map), the frusta, the light direction */
    swarp_vec3 centre = {0, 0, 0};
    int ncentre = 0;
    for (int k = 0; k < sh.count; ++k) {
        double d0 = sh.count > 1 ? sh.split[k] : sh.near, d1 = sh.count > 1 ? sh.split[k + 1] : sh.far;
        swarp_polyhedron H, B;
        swarp_status st = swarp_body_h(c, d0, d1, &e->scene.box, &H);
        if (!swarp_status_is_error(st)) st = swarp_body_from_h(&H, &e->v.light, &e->scene.box, &B);
        swarp_vec3 pts[SWARP_BODY_MAX_POINTS];
        size_t np = 0;
        swarp_status sp = swarp_body_points(c, d0, d1, &e->v.light, &e->scene.box, pts,
                                            SWARP_BODY_MAX_POINTS, &np);
        if (swarp_status_is_error(st) || swarp_status_is_error(sp)) {
            fprintf(stderr, "demo-extras: body of map %d: %s\n", k, swarp_status_string(st));
            continue;
        }
        printf("  %s map %d: view depths [%.1f, %.1f], B has %u vertices, %u faces "
               "(swarp_body_points: %zu points)\n",
               name, k, d0, d1, B.vertex_count, B.face_count, np);
        const uint8_t* col = sh.count == 1 ? split_rgb[0] : split_rgb[k % 4];
        draw_body(out, &out_m, &B, col);
        demo_draw_frustum(out, &out_m, &e->v, d0, d1, col, 0);
        for (size_t i = 0; i < np; ++i) {
            centre.x += pts[i].x;
            centre.y += pts[i].y;
            centre.z += pts[i].z;
            ++ncentre;
        }
    }
    const uint8_t black[3] = {0, 0, 0}, grey[3] = {90, 90, 90};
    /* the whole camera frustum [near, far] in grey, the view vector in blue */
    demo_draw_frustum(out, &out_m, &e->v, c->near, c->far, grey, 1);
    if (ncentre) {
        centre.x /= ncentre;
        centre.y /= ncentre;
        centre.z /= ncentre;
        const swarp_vec3 d = e->v.light.direction;
        double len = 420;
        swarp_vec3 from = {centre.x - d.x * len, centre.y - d.y * len, centre.z - d.z * len};
        extras_line3(out, &out_m, from, centre, 4, black);
        /* arrow head: a short cross near the tip */
        swarp_vec4 a, b;
        swarp_mat4_transform(&out_m, &from, &a);
        swarp_mat4_transform(&out_m, &centre, &b);
        if (a.w > 0 && b.w > 0) {
            double ax = (a.x / a.w * 0.5 + 0.5) * out->w, ay = (0.5 - a.y / a.w * 0.5) * out->h;
            double bx = (b.x / b.w * 0.5 + 0.5) * out->w, by = (0.5 - b.y / b.w * 0.5) * out->h;
            double ux = bx - ax, uy = by - ay, l = sqrt(ux * ux + uy * uy);
            if (l > 1) {
                ux /= l;
                uy /= l;
                demo_image_line(out, bx, by, bx - 22 * ux + 10 * uy, by - 22 * uy - 10 * ux, 4, black);
                demo_image_line(out, bx, by, bx - 22 * ux - 10 * uy, by - 22 * uy + 10 * ux, 4, black);
                demo_image_label(out, (int)ax + 6, (int)ay - 6, 1, "light");
            }
        }
    }
    /* minimap: the common view (Fig. 5.1) */
    demo_image mini;
    int mw = e->w / 4, mh = e->h / 4;
    if (demo_image_resize(&common, mw, mh, &mini) == 0) {
        demo_image_fill(out, 6, e->h - mh - 10, mw + 4, mh + 4, black);
        demo_image_blit(out, 8, e->h - mh - 8, &mini);
        demo_image_free(&mini);
    }
    demo_image_free(&common);
    char lab[200];
    snprintf(lab, sizeof lab, "%s: visualization view [RHS] 5.2-5.3", name);
    demo_image_label(out, 8, 8, 2, lab);
    demo_image_label(out, 8, 40, 1,
                     sh.count > 1 ? "bodies B_i and split frusta in split colours (5.1); map "
                                    "footprints tinted, grid every map/16 texels"
                                  : "body B and adjusted frustum (red); map footprint tinted, "
                                    "grid every map/16 texels");
    demo_image_label(out, 8, 56, 1, "grey: camera frustum [near, far], blue: view vector, "
                                    "black arrow: light direction");
    return 0;
}

int extras_viz(extras_env* e, int test) {
    GLuint prog = extras_gl_program("visualization view", viz_vs, NULL, viz_fs);
    if (!prog) return 1;
    const struct {
        demo_technique t;
        int k;
        const char* name;
        const char* file;
    } techs[3] = {{DEMO_TECH_UNIFORM, 1, "uniform", "viz_uniform"},
                  {DEMO_TECH_LISPSM, 1, "lispsm", "viz_lispsm"},
                  {DEMO_TECH_PSSM, 4, "pssm4", "viz_pssm4"}};
    int rc = 0;
    for (int i = 0; i < 3; ++i) {
        demo_image im;
        if (one(e, prog, techs[i].t, techs[i].k, techs[i].name, &im)) {
            fprintf(stderr, "demo-extras: visualization view %s failed\n", techs[i].name);
            rc = 1;
            continue;
        }
        /* the overlays are there: pixels in the colour of B's edges */
        long edge = 0;
        for (size_t k = 0; k < (size_t)im.w * im.h; ++k) {
            const uint8_t* q = im.px + 4 * k;
            edge += (q[0] == 138 && q[1] == 0 && q[2] == 0) || (q[0] == 0 && q[1] == 36 && q[2] == 153);
        }
        double nb = demo_image_nonblank(&im);
        int ok = nb >= 0.01 && edge > 50;
        if (test)
            printf("viz %-8s non-blank %.1f%%, %ld pixels of body edges %s\n", techs[i].name,
                   100 * nb, edge, ok ? "ok" : "FAIL");
        if (!ok) rc = 1;
        if (!test && extras_write(e, techs[i].file, &im)) rc = 1;
        demo_image_free(&im);
    }
    glDeleteProgram(prog);
    return rc;
}
