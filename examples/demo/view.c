/* view.c -- the views of the command line: camera presets over the
 * default scene, the sun, the scene, the shadow request and the GL context. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "options.h"

/* Camera presets over the default scene (y up, ground at y = 0). */
int demo_camera_preset(const char* name, int w, int h, swarp_camera* c) {
    memset(c, 0, sizeof *c);
    c->up.y = 1;
    c->fovy = 60 * DEMO_DEG;
    c->aspect = (double)w / h;
    c->z_near = 1;
    c->z_far = 800;
    if (!strcmp(name, "default")) {
        c->eye = (swarp_vec3){8, 28, 395};
        c->dir = (swarp_vec3){-0.02, -0.11, -1};
    } else if (!strcmp(name, "measure")) {
        /* horizontal view, the setting of Lloyd's error model */
        c->eye = (swarp_vec3){0, 20, 390};
        c->dir = (swarp_vec3){0, 0, -1};
        c->z_far = 600;
    } else if (!strcmp(name, "street")) {
        c->eye = (swarp_vec3){0, 2, 385};
        c->dir = (swarp_vec3){0, 0.05, -1};
    } else if (!strcmp(name, "high")) {
        c->eye = (swarp_vec3){-220, 160, 390};
        c->dir = (swarp_vec3){220, -160, -480};
        c->z_far = 1000;
    } else if (!strcmp(name, "room")) {
        c->eye = (swarp_vec3){-52, 12, 48};
        c->dir = (swarp_vec3){-23, -11, -40};
        c->z_near = 0.5;
        c->z_far = 600;
    } else if (!strcmp(name, "path")) {
        /* a camera path file: presets' defaults, eye/dir set by the caller */
        c->eye = (swarp_vec3){0, 20, 390};
        c->dir = (swarp_vec3){0, 0, -1};
    } else {
        fprintf(stderr, "demo: unknown camera preset %s\n", name);
        return -1;
    }
    return 0;
}

int demo_options_camera(const demo_options* o, swarp_camera* c) {
    if (o->path_count == 0) return demo_camera_preset(o->camera, o->w, o->h, c);
    if (demo_camera_preset("path", o->w, o->h, c)) return -1;
    c->eye = (swarp_vec3){o->path[0], o->path[1], o->path[2]};
    c->dir = (swarp_vec3){o->path[3], o->path[4], o->path[5]};
    return 0;
}

void demo_options_light(const demo_options* o, swarp_light* l) {
    memset(l, 0, sizeof *l);
    l->type = SWARP_LIGHT_DIRECTIONAL;
    if (o->have_light_dir) {
        l->direction = o->light_dir;
    } else {
        double e = o->light_elev * DEMO_DEG, a = o->light_azim * DEMO_DEG;
        /* the light comes FROM azimuth a (0 = from +z, behind the default
         * camera) at elevation e, and travels the other way */
        l->direction = (swarp_vec3){-cos(e) * sin(a), -sin(e), -cos(e) * cos(a)};
        if (o->light_elev >= 90) l->direction = (swarp_vec3){0, -1, 0};
    }
}

/* --light-gamma: the light's direction at gamma to the view direction v,
 * in the plane of v and the world's down vector (y up), turned from v
 * toward the ground: l = cos(gamma) v + sin(gamma) d_perp with d_perp the
 * unit part of (0, -1, 0) normal to v, so the angle of l to v is gamma
 * exactly and the light always reaches the ground from above for a camera
 * not looking below the horizon.  A camera looking straight up or down has
 * no such plane; its up vector's opposite takes the place of the down. */
static void light_from_gamma(double gamma_deg, const swarp_camera* cam, swarp_light* l) {
    double vl = sqrt(cam->dir.x * cam->dir.x + cam->dir.y * cam->dir.y + cam->dir.z * cam->dir.z);
    swarp_vec3 v = {cam->dir.x / vl, cam->dir.y / vl, cam->dir.z / vl};
    swarp_vec3 d = {0, -1, 0};
    if (fabs(v.y) > 0.999) d = (swarp_vec3){-cam->up.x, -cam->up.y, -cam->up.z};
    double dv = d.x * v.x + d.y * v.y + d.z * v.z;
    swarp_vec3 p = {d.x - dv * v.x, d.y - dv * v.y, d.z - dv * v.z};
    double pl = sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    double c = cos(gamma_deg * DEMO_DEG), s = sin(gamma_deg * DEMO_DEG);
    memset(l, 0, sizeof *l);
    l->type = SWARP_LIGHT_DIRECTIONAL;
    l->direction = (swarp_vec3){c * v.x + s * p.x / pl, c * v.y + s * p.y / pl, c * v.z + s * p.z / pl};
}

/* The sun of the command line for camera cam: --light-gamma relative to it,
 * else --light-angle / --light-dir. */
static void options_light_for(const demo_options* o, const swarp_camera* cam, swarp_light* l) {
    if (o->have_light_gamma) light_from_gamma(o->light_gamma, cam, l);
    else demo_options_light(o, l);
}

/* View v of the command line: --camera (or the explicit eye/dir) at --size
 * with the --light-angle / --light-dir sun.  Non-zero: a bad camera. */
int demo_options_view(const demo_options* o, demo_view* v) {
    demo_sized_view(o, v);
    if (demo_options_camera(o, &v->cam)) return -1;
    options_light_for(o, &v->cam, &v->light);
    return 0;
}

/* View v of preset `camera` at --size with the --light-angle / --light-dir sun. */
int demo_preset_view(const demo_options* o, const char* camera, demo_view* v) {
    demo_sized_view(o, v);
    if (demo_camera_preset(camera, v->w, v->h, &v->cam)) return -1;
    options_light_for(o, &v->cam, &v->light);
    demo_view_update(v);
    return 0;
}

/* demo_shadow_setup of technique t with K maps (practical scheme, lambda
 * 0.5) for view v at --map. */
int demo_setup_for(const demo_options* o, const demo_view* v, const swarp_aabb* box, demo_technique t,
                     int splits, demo_shadow* sh) {
    demo_shadow_request req;
    memset(&req, 0, sizeof req);
    req.technique = t;
    req.splits = splits;
    req.scheme_lambda = 0.5;
    req.map_res = o->map;
    req.screen_w = v->w;
    req.screen_h = v->h;
    return demo_shadow_setup(&v->cam, &v->light, box, &req, sh);
}

int demo_load_scene(const demo_options* o, demo_scene* s) {
    if (o->obj) return demo_scene_obj(s, o->obj);
    return demo_scene_default(s);
}

demo_ctx* demo_open_context(void) {
    int maj = 0, min = 0;
    demo_ctx* ctx = demo_ctx_create(&maj, &min);
    if (!ctx) {
        fprintf(stderr, "demo: OSMesa could not create a core-profile context\n");
        return NULL;
    }
    if (demo_gl_load()) {
        demo_ctx_destroy(ctx);
        return NULL;
    }
    printf("OpenGL %s on %s (core %d.%d requested)\n", (const char*)glGetString(GL_VERSION),
           (const char*)glGetString(GL_RENDERER), maj, min);
    return ctx;
}

int demo_mkdir_p(const char* dir) {
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

void demo_sized_view(const demo_options* o, demo_view* v) {
    memset(v, 0, sizeof *v);
    v->w = o->w;
    v->h = o->h;
}

int demo_open_renderer(const demo_options* o, int builtin, demo_scene* s, demo_renderer* r) {
    if (builtin ? demo_scene_default(s) : demo_load_scene(o, s)) return -1;
    if (demo_render_init(r, s, o->w, o->h, o->map, DEMO_MAX_SPLITS)) {
        demo_scene_free(s);
        return -1;
    }
    return 0;
}
