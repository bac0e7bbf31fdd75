/* Data for docs/img/geometry_footprints.png (docs/plots/geometry_footprints.sh):
 * the shadow map's footprint on the ground (y = 0) for three lights
 * (overhead, γ = 30° into the light, 20° from behind the camera) and two
 * techniques (uniform, LiSPSM n_opt), as gnuplot data blocks:
 *   index 6*0 + panel: map grid lines on the ground (every 1/8 of the map)
 *   index 6*1 + panel: the view frustum's ground footprint V ∩ {y = 0}
 *   index 6*2 + panel: the points of B projected to the ground (x, z)
 * Not a test: prints to stdout. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shadowwarp.h"

#define DEG (3.14159265358979323846 / 180.0)

/* the ground point (y = 0) whose map position is (cx, cy) in clip x, y */
static int ground_point(const swarp_mat4* m, double cx, double cy, double* X, double* Z) {
    /* rows r_i(p) = m[i] x + m[4+i] y + m[8+i] z + m[12+i]; y = 0 */
    double a11 = m->m[0] - cx * m->m[3], a12 = m->m[8] - cx * m->m[11], b1 = -(m->m[12] - cx * m->m[15]);
    double a21 = m->m[1] - cy * m->m[3], a22 = m->m[9] - cy * m->m[11], b2 = -(m->m[13] - cy * m->m[15]);
    double det = a11 * a22 - a12 * a21;
    if (fabs(det) < 1e-300) return 0;
    *X = (b1 * a22 - a12 * b2) / det;
    *Z = (a11 * b2 - a21 * b1) / det;
    return 1;
}

int main(void) {
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (swarp_vec3){0, 4, 0};
    cam.dir = (swarp_vec3){0, -0.12, -1};
    cam.up = (swarp_vec3){0, 1, 0};
    cam.fovy = 50 * DEG;
    cam.aspect = 16.0 / 9.0;
    cam.z_near = 1;
    cam.z_far = 60;
    swarp_aabb box = {{-80, 0, -80}, {80, 6, 10}};
    double s30 = sin(30 * DEG), c30 = cos(30 * DEG), s20 = sin(20 * DEG), c20 = cos(20 * DEG);
    const swarp_vec3 lights[3] = {{0, -1, 0}, {0, -s30, c30} /* toward the camera */,
                                  {0, -s20, -c20} /* from behind the camera */};
    const swarp_technique techs[2] = {SWARP_TECHNIQUE_UNIFORM, SWARP_TECHNIQUE_LISPSM};
    swarp_setup_result res[6];
    swarp_vec3 pts[6][SWARP_BODY_MAX_POINTS];
    size_t np[6];
    for (int p = 0; p < 6; ++p) {
        swarp_light light;
        memset(&light, 0, sizeof light);
        light.type = SWARP_LIGHT_DIRECTIONAL;
        light.direction = lights[p % 3];
        swarp_setup_options o;
        memset(&o, 0, sizeof o);
        o.technique = techs[p / 3];
        swarp_status s = swarp_setup(&cam, &light, &box, &o, &res[p], pts[p], SWARP_BODY_MAX_POINTS, &np[p]);
        fprintf(stderr, "panel %d: %s n' = %g gamma = %.1f max m_x %.3g m_z %.3g\n", p, swarp_status_name(s),
                res[p].n_eye, res[p].gamma / DEG, res[p].max_mx, res[p].max_mz);
        if (swarp_status_is_error(s)) return 1;
    }
    /* grid lines */
    for (int p = 0; p < 6; ++p) {
        printf("# panel %d grid\n", p);
        for (int dir = 0; dir < 2; ++dir)
            for (int k = 0; k <= 8; ++k) {
                double c = -1 + k / 4.0;
                for (int j = 0; j <= 64; ++j) {
                    double t = -1 + j / 32.0, X, Z;
                    if (ground_point(&res[p].matrix, dir ? c : t, dir ? t : c, &X, &Z)) printf("%.6g %.6g\n", X, Z);
                }
                printf("\n");
            }
        printf("\n\n");
    }
    /* the view frustum on the ground: V clipped to the slab |y| <= 0 */
    for (int p = 0; p < 6; ++p) {
        swarp_polyhedron V;
        swarp_poly_from_camera(&cam, &V);
        swarp_plane up = {0, 1, 0, 0}, down = {0, -1, 0, 0};
        swarp_poly_clip(&V, &up, &V);
        swarp_poly_clip(&V, &down, &V);
        printf("# panel %d frustum footprint\n", p);
        if (V.face_count > 0) {
            for (uint32_t k = 0; k <= V.face_vertex_count[0]; ++k) {
                swarp_vec3 q = V.vertices[V.face_vertices[0][k % V.face_vertex_count[0]]];
                printf("%.6g %.6g\n", q.x, q.z);
            }
        }
        printf("\n\n");
    }
    for (int p = 0; p < 6; ++p) {
        printf("# panel %d points of B\n", p);
        for (size_t k = 0; k < np[p]; ++k) printf("%.6g %.6g\n", pts[p][k].x, pts[p][k].z);
        printf("\n\n");
    }
    return 0;
}
