/* The table of docs/engines.md "Reversed-Z": depth resolution of a float32
 * depth buffer at the near and far ends of the body B, for the light
 * matrices swarp_setup returns with each depth range.  Resolution is the
 * world distance along the light ray over which the stored float32 depth
 * stays the same: ulp32(z_win) / |d z_win / ds| (the derivative by a central
 * difference in double along the ray; z_win = (z_ndc + 1)/2 for [-1, 1],
 * as glDepthRange(0, 1) stores it, z_ndc otherwise).  Not a test: prints a
 * Markdown table (docs/plots/depth_precision.sh). */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "shadowwarp.h"

typedef struct kase {
    const char* name;
    swarp_technique tech;
    int point;
    swarp_vec3 v; /* light direction or position */
    double cone;
} kase;

static double z_window(const swarp_mat4* M, swarp_depth_range dr, swarp_vec3 p) {
    swarp_vec4 h;
    swarp_mat4_transform(M, &p, &h);
    double z = h.z / h.w;
    return dr == SWARP_DEPTH_NEG_ONE_TO_ONE ? 0.5 * z + 0.5 : z;
}

/* the float32 step at z (stored rounded to float), in world units along u */
static double resolution(const swarp_mat4* M, swarp_depth_range dr, swarp_vec3 p, swarp_vec3 u, double scale) {
    const double h = 1e-6 * scale;
    swarp_vec3 a = {p.x - h * u.x, p.y - h * u.y, p.z - h * u.z}, b = {p.x + h * u.x, p.y + h * u.y, p.z + h * u.z};
    const double dz = (z_window(M, dr, b) - z_window(M, dr, a)) / (2.0 * h);
    const float zf = (float)z_window(M, dr, p);
    const double ulp = (double)nextafterf(zf, INFINITY) - (double)zf;
    return ulp / fabs(dz);
}

static swarp_vec3 ray_dir(const kase* k, swarp_vec3 p) {
    swarp_vec3 u = k->point ? (swarp_vec3){p.x - k->v.x, p.y - k->v.y, p.z - k->v.z} : k->v;
    double l = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    return (swarp_vec3){u.x / l, u.y / l, u.z / l};
}

int main(void) {
    swarp_camera cam = {0};
    cam.eye = (swarp_vec3){0, 10, 0};
    cam.dir = (swarp_vec3){0, -0.2, -1};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 1.0472;
    cam.aspect = 1.7778;
    cam.z_near = 1;
    cam.z_far = 1000;
    const swarp_aabb scene = {{-2000, -5, -3000}, {2000, 30, 60}};
    const kase ks[] = {
        {"spot light 300 above, cone 35°", SWARP_TECHNIQUE_LISPSM, 1, {20, 300, -50}, 0.6},
        {"spot light 60 above, cone 60°", SWARP_TECHNIQUE_LISPSM, 1, {0, 60, -40}, 1.05},
        {"sun, LiSPSM (n_opt)", SWARP_TECHNIQUE_LISPSM, 0, {0.3, -1, 0.2}, 0.0},
        {"sun, PSM", SWARP_TECHNIQUE_PSM, 0, {0.3, -1, 0.2}, 0.0},
        {"sun, uniform", SWARP_TECHNIQUE_UNIFORM, 0, {0.3, -1, 0.2}, 0.0},
    };
    const swarp_depth_range drs[3] = {SWARP_DEPTH_NEG_ONE_TO_ONE, SWARP_DEPTH_ZERO_TO_ONE,
                                      SWARP_DEPTH_REVERSED_ZERO_TO_ONE};
    printf("| light, technique | along the depth range | [-1, 1] | [0, 1] | reversed [1, 0] | [0, 1] / reversed |\n");
    printf("|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; ++i) {
        const kase* k = &ks[i];
        swarp_light L = {0};
        L.type = k->point ? SWARP_LIGHT_POINT : SWARP_LIGHT_DIRECTIONAL;
        if (k->point) L.position = k->v, L.cone_angle = k->cone, L.direction = (swarp_vec3){0, -1, -0.3};
        else L.direction = k->v;
        swarp_setup_options o = {0};
        o.technique = k->tech;
        swarp_setup_result r[3];
        swarp_vec3 B[SWARP_BODY_MAX_POINTS];
        size_t nb = 0;
        swarp_status st = SWARP_OK;
        for (int d = 0; d < 3 && !swarp_status_is_error(st); ++d) {
            o.depth_range = drs[d];
            st = swarp_setup(&cam, &L, &scene, &o, &r[d], B, SWARP_BODY_MAX_POINTS, &nb);
        }
        if (swarp_status_is_error(st) || nb == 0) {
            printf("| %s | %s | | | | |\n", k->name, swarp_status_name(st));
            continue;
        }
        /* the light ray through the centroid of B, from where the [0, 1]
         * depth is 0 to where it is 1 (bisection: depth is monotonic along
         * a ray from the light); resolution at 1%, 50% and 99% of it */
        swarp_vec3 c = {0, 0, 0};
        for (size_t j = 0; j < nb; ++j) c.x += B[j].x / nb, c.y += B[j].y / nb, c.z += B[j].z / nb;
        const swarp_vec3 u = ray_dir(k, c);
        const double scale = fmax(scene.max.x - scene.min.x, scene.max.z - scene.min.z);
        double s01[2];
        for (int e = 0; e < 2; ++e) {
            double a = -4.0 * scale, b = 4.0 * scale; /* depth(a) < e < depth(b) along u */
            if (k->point) a = -sqrt((c.x - k->v.x) * (c.x - k->v.x) + (c.y - k->v.y) * (c.y - k->v.y) +
                                    (c.z - k->v.z) * (c.z - k->v.z)) * 0.999;
            for (int it = 0; it < 200; ++it) {
                const double m = 0.5 * (a + b);
                swarp_vec3 q = {c.x + m * u.x, c.y + m * u.y, c.z + m * u.z};
                if (z_window(&r[1].matrix, drs[1], q) < (double)e) a = m;
                else b = m;
            }
            s01[e] = 0.5 * (a + b);
        }
        const double ts[3] = {0.01, 0.5, 0.99};
        const char* where[3] = {"1% (near)", "50%", "99% (far)"};
        for (int e = 0; e < 3; ++e) {
            const double sm = s01[0] + ts[e] * (s01[1] - s01[0]);
            swarp_vec3 q = {c.x + sm * u.x, c.y + sm * u.y, c.z + sm * u.z};
            double res[3];
            for (int d = 0; d < 3; ++d) res[d] = resolution(&r[d].matrix, drs[d], q, u, scale);
            printf("| %s | %s | %.3g | %.3g | %.3g | %.3g |\n", e ? "" : k->name, where[e], res[0], res[1], res[2],
                   res[1] / res[2]);
        }
    }
    printf("\nWorld units along the light ray through the centroid of B per float32 depth step "
           "(smaller is finer), at 1%%, 50%% and 99%% of the way from the map's near to its far plane; "
           "camera eye (0, 10, 0), view (0, -0.2, -1), 60° x 1.78, depth 1..1000, "
           "scene box (-2000, -5, -3000)..(2000, 30, 60).\n");
    return 0;
}
