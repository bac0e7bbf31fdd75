/* swtool lixel: the plane-stabilised light matrix of [LIXEL] for one viewer,
 * light and plane of interest; prints M_l, the light-image rectangle of the
 * visible part of the plane, the GL factorisation and the measured
 * deviation between viewer pixels and light pixels on the plane. */
#include <math.h>
#include <string.h>

#include "cli.h"

typedef struct lx_cam {
    swarp_vec3 eye, f, s, u;
    double tan_half, aspect;
} lx_cam;

static swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 r = {x, y, z};
    return r;
}
static double dot3(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static swarp_vec3 cross3(swarp_vec3 a, swarp_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static swarp_vec3 unit3(swarp_vec3 a) {
    double l = sqrt(dot3(a, a));
    return v3(a.x / l, a.y / l, a.z / l);
}

/* OpenGL lookAt x perspective; 0 if the camera is degenerate. */
static int camera_matrix(swarp_vec3 eye, swarp_vec3 dir, swarp_vec3 up, double fovy, double aspect, double n,
                         double f, swarp_mat4* M, lx_cam* c) {
    if (!(dot3(dir, dir) > 0) || !(fovy > 0 && fovy < 3.14159265358979) || !(aspect > 0) || !(n > 0) || !(f > n))
        return 0;
    c->eye = eye;
    c->f = unit3(dir);
    swarp_vec3 s = cross3(c->f, up);
    if (!(dot3(s, s) > 1e-20)) return 0;
    c->s = unit3(s);
    c->u = cross3(c->s, c->f);
    c->tan_half = tan(0.5 * fovy);
    c->aspect = aspect;
    double P[4][4] = {{1 / (c->tan_half * aspect), 0, 0, 0},
                      {0, 1 / c->tan_half, 0, 0},
                      {0, 0, (f + n) / (n - f), 2 * f * n / (n - f)},
                      {0, 0, -1, 0}};
    double Vw[4][4] = {{c->s.x, c->s.y, c->s.z, -dot3(c->s, eye)},
                       {c->u.x, c->u.y, c->u.z, -dot3(c->u, eye)},
                       {-c->f.x, -c->f.y, -c->f.z, dot3(c->f, eye)},
                       {0, 0, 0, 1}};
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) {
            double acc = 0;
            for (int j = 0; j < 4; ++j) acc += P[r][j] * Vw[j][k];
            M->m[k * 4 + r] = acc;
        }
    return 1;
}

/* The ray through viewer pixel (x, y) hits P: parameter t along the ray
 * (whose forward component is 1, so t is the view depth) and the point. */
static double ray_hit(const lx_cam* c, unsigned g, unsigned h, const swarp_plane* P, double x, double y,
                      swarp_vec3* X) {
    double xn = (x + 0.5) * 2.0 / g - 1.0, yn = (y + 0.5) * 2.0 / h - 1.0;
    double a = xn * c->tan_half * c->aspect, b = yn * c->tan_half;
    swarp_vec3 d = v3(c->f.x + a * c->s.x + b * c->u.x, c->f.y + a * c->s.y + b * c->u.y,
                      c->f.z + a * c->s.z + b * c->u.z);
    swarp_vec3 n = v3(P->a, P->b, P->c);
    double t = -(dot3(n, c->eye) + P->d) / dot3(n, d);
    *X = v3(c->eye.x + t * d.x, c->eye.y + t * d.y, c->eye.z + t * d.z);
    return t;
}

int cmd_lixel(sw_args* a) {
    static const char* const known[] = {"eye", "dir", "up", "fovy", "aspect", "near", "far", "screen",
                                        "light-pos", "light-dir", "plane", "twist-line", "scale",
                                        "extent", "depth", "plane-depth", NULL};
    CLI_ACCEPT(a, known);
    /* aspect 0 until given: then the screen's */
    swarp_camera c = {{0, 1.7, 5}, {0, -0.3, -1}, {0, 1, 0}, 60.0 * SW_DEG, 0.0, 0.1, 100.0, {0}};
    double scale = 1, extent = 0, plane_depth = 0;
    unsigned g = 1024, h = 768;
    swarp_light light;
    memset(&light, 0, sizeof light);
    double pl[4] = {0, 1, 0, 0}, tl[9];
    swarp_depth_range dr;
    if (!cli_camera(a, 0, &c) || !cli_size(a, "screen", 1024, 768, &g, &h) || !cli_double(a, "scale", 1, &scale) ||
        !cli_double(a, "extent", 0, &extent) || !cli_double(a, "plane-depth", 0, &plane_depth) ||
        !cli_light(a, 1, &light) || !cli_list(a, "plane", 4, "A,B,C,D", pl) ||
        !cli_list(a, "twist-line", 9, "AX,AY,AZ,BX,BY,BZ,CX,CY,CZ: two points of the line, then a point on the "
                  "side kept below it", tl) ||
        !cli_depth(a, &dr))
        return CLI_EXIT_USAGE;
    if (!cli_opt(a, "aspect")) c.aspect = (double)g / h;
    swarp_vec3 eye = c.eye, dir = c.dir, up = c.up;
    double fovy = c.fovy / SW_DEG, aspect = c.aspect, near = c.z_near, far = c.z_far;
    swarp_plane P = {pl[0], pl[1], pl[2], pl[3]};
    int has_twist = cli_opt(a, "twist-line") != NULL;
    swarp_mat4 Mv;
    lx_cam cam;
    if (!camera_matrix(eye, dir, up, fovy * SW_DEG, aspect, near, far, &Mv, &cam)) {
        return cli_fail(a, NULL, "the camera is degenerate: need |--dir| > 0, 0 < --fovy < 180, --aspect > 0, "
                        "0 < --near < --far");
    }

    swarp_mat4 Ml;
    swarp_lixel_info info;
    swarp_status st = swarp_lixel_matrix(&Mv, g, h, &light, &P, NULL, &Ml, &info);
    if (swarp_status_is_error(st)) return cli_report_status(a, st, "swarp_lixel_matrix");

    /* C: the square of half-size `extent` (default far) on P around the
     * foot of the eye, clipped to the viewer's frustum by the restriction */
    double nl = sqrt(P.a * P.a + P.b * P.b + P.c * P.c);
    swarp_vec3 n = v3(P.a / nl, P.b / nl, P.c / nl);
    double de = dot3(n, eye) + P.d / nl;
    swarp_vec3 foot = v3(eye.x - de * n.x, eye.y - de * n.y, eye.z - de * n.z);
    swarp_vec3 e1 = unit3(cross3(n, fabs(n.x) < 0.9 ? v3(1, 0, 0) : v3(0, 1, 0))), e2 = cross3(n, e1);
    double r = extent > 0 ? extent : far;
    swarp_vec4 C[4];
    for (int j = 0; j < 4; ++j) {
        double sa = (j == 0 || j == 3) ? -r : r, sb = (j < 2) ? -r : r;
        C[j].x = foot.x + sa * e1.x + sb * e2.x;
        C[j].y = foot.y + sa * e1.y + sb * e2.y;
        C[j].z = foot.z + sa * e1.z + sb * e2.z;
        C[j].w = 1.0;
    }
    swarp_lixel_restrict_options ro;
    memset(&ro, 0, sizeof ro);
    ro.scale_x = ro.scale_y = scale;
    ro.view_width = g;
    ro.view_height = h;
    if (has_twist) {
        swarp_vec3 pa = v3(tl[0], tl[1], tl[2]), pb = v3(tl[3], tl[4], tl[5]), pc = v3(tl[6], tl[7], tl[8]);
        swarp_status ts = swarp_lixel_twist_for_line(&Ml, &pa, &pb, &pc, &ro.twist);
        if (swarp_status_is_error(ts)) return cli_report_status(a, ts, "swarp_lixel_twist_for_line");
    }
    swarp_lixel_rect R;
    swarp_mat4 A, Mr, GLV, GLP;
    swarp_status rs = swarp_lixel_restrict(&Ml, C, 4, &ro, &R, &A, &Mr);
    if (swarp_status_is_error(rs)) return cli_report_status(a, rs, "swarp_lixel_restrict");
    swarp_status fs = swarp_lixel_factor(&Mr, R.width, R.height, dr, plane_depth, &GLV, &GLP);
    if (swarp_status_is_error(fs)) return cli_report_status(a, fs, "swarp_lixel_factor");

    /* measured deviation on P: a 97 x 97 grid of viewer pixels whose ray
     * hits P at view depth in [near, far]; light pixel of the hit point by
     * M_l in double and with the float matrix */
    float Mf[16];
    swarp_status cs = swarp_mat4_to_float(&Ml, Mf);
    double dev = 0, dev_f = 0;
    int samples = 0;
    for (int i = 0; i <= 96; ++i)
        for (int j = 0; j <= 96; ++j) {
            double x = (g - 1) * i / 96.0, y = (h - 1) * j / 96.0;
            swarp_vec3 X;
            double t = ray_hit(&cam, g, h, &P, x, y, &X);
            if (!(t >= near && t <= far)) continue;
            double o[4], of[4];
            for (int k = 0; k < 4; ++k) {
                o[k] = Ml.m[k] * X.x + Ml.m[4 + k] * X.y + Ml.m[8 + k] * X.z + Ml.m[12 + k];
                of[k] = (double)Mf[k] * X.x + (double)Mf[4 + k] * X.y + (double)Mf[8 + k] * X.z + (double)Mf[12 + k];
            }
            dev = fmax(dev, fmax(fabs(o[0] / o[3] - x), fabs(o[1] / o[3] - y)));
            if (cs == SWARP_OK) dev_f = fmax(dev_f, fmax(fabs(of[0] / of[3] - x), fabs(of[1] / of[3] - y)));
            ++samples;
        }
    swarp_status shown = st != SWARP_OK ? st : rs;
    if (a->json) {
        json_begin();
        json_kv_status(shown);
        json_kv_mat("M_l", &Ml);
        json_key("rect");
        json_open_obj();
        json_kv_num("x0", R.x0);
        json_kv_num("y0", R.y0);
        json_kv_num("x1", R.x1);
        json_kv_num("y1", R.y1);
        json_kv_num("width", R.width);
        json_kv_num("height", R.height);
        json_close_obj();
        json_kv_num("twist", ro.twist);
        json_kv_num("scale", scale);
        json_kv_mat("A_l", &A);
        json_kv_mat("M_l_restricted", &Mr);
        json_kv_mat("GLV", &GLV);
        json_kv_mat("GLP", &GLP);
        json_kv_str("depth_range", dr == SWARP_DEPTH_ZERO_TO_ONE ? "[0,1]" : "[-1,1]");
        json_kv_num("raised_index", info.raised_index);
        json_kv_num("corners_in_front", info.corners_in_front);
        json_kv_num("conditioning", info.conditioning);
        json_kv_num("samples", samples);
        json_kv_num("max_deviation_px", samples ? dev : NAN);
        json_kv_num("max_deviation_px_float", samples && cs == SWARP_OK ? dev_f : NAN);
        json_kv_num("viewer_pixels", (double)g * h);
        json_kv_num("lixels", (double)R.width * R.height);
        json_end();
    } else {
        if (shown != SWARP_OK) cli_report_status(a, shown, "note");
        printf("M_l (rows of the matrix; the JSON and C arrays are column-major):\n");
        for (int r4 = 0; r4 < 4; ++r4)
            printf("  % .9e % .9e % .9e % .9e\n", Ml.m[r4], Ml.m[4 + r4], Ml.m[8 + r4], Ml.m[12 + r4]);
        printf("rectangle  x %d..%d  y %d..%d  (%u x %u lixels for %u x %u pixels)\n", R.x0, R.x1, R.y0, R.y1,
               R.width, R.height, g, h);
        printf("twist %.9g rad, scale %g; raised corner p^%u, %u corners in front, conditioning %.3g\n", ro.twist,
               scale, info.raised_index + 1, info.corners_in_front, info.conditioning);
        printf("max deviation on the plane: %.3e px (double), %.3e px (float matrix), %d samples\n", dev, dev_f,
               samples);
    }
    return 0;
}
