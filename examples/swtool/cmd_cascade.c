/* swtool cascade / stabwalk: cascades (z-partitioning), stabilisation and
 * the data behind the pictures of docs/splits.md.  [RHS] §3.3-3.5. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* 8 corners of the camera's frustum slice [n, f] */
static void walk_corners(const swarp_camera* c, double n, double f, swarp_vec3 out[8]) {
    double l = sqrt(c->dir.x * c->dir.x + c->dir.y * c->dir.y + c->dir.z * c->dir.z);
    swarp_vec3 fw = {c->dir.x / l, c->dir.y / l, c->dir.z / l};
    swarp_vec3 r = {fw.y * c->up.z - fw.z * c->up.y, fw.z * c->up.x - fw.x * c->up.z,
                    fw.x * c->up.y - fw.y * c->up.x};
    double rl = sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    r.x /= rl, r.y /= rl, r.z /= rl;
    swarp_vec3 u = {r.y * fw.z - r.z * fw.y, r.z * fw.x - r.x * fw.z, r.x * fw.y - r.y * fw.x};
    double t = tan(c->fovy / 2);
    for (int k = 0; k < 8; ++k) {
        double z = k < 4 ? n : f, x = (k & 1 ? 1 : -1) * z * t * c->aspect, y = (k & 2 ? 1 : -1) * z * t;
        out[k].x = c->eye.x + fw.x * z + r.x * x + u.x * y;
        out[k].y = c->eye.y + fw.y * z + r.y * x + u.y * y;
        out[k].z = c->eye.z + fw.z * z + r.z * x + u.z * y;
    }
}

/* swtool stabwalk: texel coordinates of a fixed world point while the camera
 * walks and turns slowly, for each stabilisation mode. */
int cmd_stabwalk(sw_args* a) {
    static const char* const known[] = {"steps", "res", "near", "far", "speed", "turn", "levels", NULL};
    if (!cli_check_known(a, known)) return 2;
    unsigned steps, res, levels;
    double n, f, speed, turn;
    if (!cli_uint(a, "steps", 200, &steps) || !cli_uint(a, "res", 1024, &res) ||
        !cli_uint(a, "levels", 64, &levels) || !cli_double(a, "near", 1, &n) ||
        !cli_double(a, "far", 60, &f) || !cli_double(a, "speed", 0.013, &speed) ||
        !cli_double(a, "turn", 0.02, &turn))
        return 2;
    const swarp_stabilize_mode modes[3] = {SWARP_STABILIZE_NONE, SWARP_STABILIZE_SPHERE,
                                           SWARP_STABILIZE_LEVELS};
    const char* names[3] = {"none", "sphere", "levels"};
    swarp_vec3 light = {0.4, -1.0, 0.25};
    swarp_vec3 P = {3.0, 0.0, -25.0};
    if (a->json) {
        json_begin();
        json_key("frames");
        json_open_arr();
    } else {
        printf("# frame  s_none t_none  s_sphere t_sphere  s_levels t_levels  (texels)\n");
    }
    for (unsigned k = 0; k < steps; ++k) {
        swarp_camera cam;
        memset(&cam, 0, sizeof cam);
        double yaw = turn * (double)k / (double)(steps > 1 ? steps - 1 : 1);
        cam.eye.x = speed * k;
        cam.eye.y = 8.0;
        cam.eye.z = -0.5 * speed * k;
        cam.dir.x = sin(yaw);
        cam.dir.y = -0.35;
        cam.dir.z = -cos(yaw);
        cam.up.y = 1.0;
        cam.fovy = 60.0 * SW_DEG;
        cam.aspect = 16.0 / 9.0;
        cam.near = n;
        cam.far = f;
        swarp_vec3 body[8];
        walk_corners(&cam, n, f, body);
        double st[3][2];
        for (int m = 0; m < 3; ++m) {
            swarp_stabilize_options o;
            memset(&o, 0, sizeof o);
            o.mode = modes[m];
            o.levels = levels;
            swarp_mat4 M;
            swarp_status s = swarp_stabilize_directional(&cam, n, f, &light, body, 8, NULL, res, &o, &M, NULL);
            if (swarp_status_is_error(s)) return cli_report_status(a, s, "swarp_stabilize_directional");
            swarp_vec4 h;
            swarp_mat4_transform(&M, &P, &h);
            st[m][0] = (h.x / h.w * 0.5 + 0.5) * res;
            st[m][1] = (h.y / h.w * 0.5 + 0.5) * res;
        }
        if (a->json) {
            json_open_obj();
            json_kv_num("frame", k);
            for (int m = 0; m < 3; ++m) json_kv_arr(names[m], st[m], 2);
            json_close_obj();
        } else {
            printf("%u %.9f %.9f %.9f %.9f %.9f %.9f\n", k, st[0][0], st[0][1], st[1][0], st[1][1],
                   st[2][0], st[2][1]);
        }
    }
    if (a->json) {
        json_close_arr();
        json_end();
    }
    return 0;
}
