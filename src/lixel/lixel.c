/* Plane-stabilised light matrices: [LIXEL] Chong & Gortler, "A Lixel for
 * every Pixel".  The matrix M_l, its restriction to a set of rays C (Fig. 6),
 * its factorisation into viewport x projection, and the multi-plane
 * selection of §3.  The five-point solver is in lixel_solve.c. */
#include <float.h>
#include <limits.h>

#include "lixel/lixel_internal.h"

_Static_assert(sizeof(swarp_lixel_options) == sizeof(double) + 16, "swarp_lixel_options size");
_Static_assert(sizeof(swarp_lixel_info) == 5 * sizeof(swarp_vec4) + 8 + sizeof(double) + 16,
               "swarp_lixel_info size");
_Static_assert(sizeof(swarp_lixel_rect) == 24, "swarp_lixel_rect size");
_Static_assert(sizeof(swarp_lixel_restrict_options) == 3 * sizeof(double) + 16 + 16,
               "swarp_lixel_restrict_options size");

/* |pi'_z| relative to the whole image-space plane below this: the plane
 * contains the eye (it images to a line).  A plane 1e-10 of the near
 * distance away from the eye still works, but carries few digits. */
#define LX_EYE_EPS 1e-10
/* Normalised w of a corner point above this: the ray hits P in front of the
 * eye (w <= this: behind, or so far that 1/w overflows the scene, ~1e12). */
#define LX_FRONT_EPS 1e-12
/* |n.d| (unit vectors) below this: the directional light grazes the plane. */
#define LX_PARALLEL_EPS 1e-10
/* Light-to-plane distance below this fraction of the light-to-corner
 * distance: the point light lies on the plane. */
#define LX_ON_PLANE_EPS 1e-10
/* |n.v| (unit vectors) below this: the plane is parallel to the view
 * direction (horizon through the image centre). */
#define LX_VIEW_PARALLEL_EPS 1e-9
/* Snap distance (lixels) of the rectangle corners to integers. */
#define LX_SNAP 1e-6
/* A vertex of C with q below this fraction of |row 4| |X| is outside. */
#define LX_Q_EPS 1e-12

static swarp_status check_light(const swarp_light* light, swarp_vec4* L, swarp_vec3* d_unit) {
    if (!sw_reserved_zero(light->_reserved, 4) || light->_reserved0 != 0) return SWARP_ERR_RESERVED_NONZERO;
    swarp_light_type t = light->type == SWARP_LIGHT_DEFAULT ? SWARP_LIGHT_DIRECTIONAL : light->type;
    if (t == SWARP_LIGHT_DIRECTIONAL) {
        if (!sw_finite3(&light->direction)) return SWARP_ERR_NON_FINITE;
        if (!sw_normalize(light->direction, d_unit)) return SWARP_ERR_ZERO_VECTOR;
        /* the centre of projection is the point at infinity of the rays */
        *L = lx_v4(d_unit->x, d_unit->y, d_unit->z, 0.0);
        return SWARP_OK;
    }
    if (t == SWARP_LIGHT_POINT) {
        if (!sw_finite3(&light->position)) return SWARP_ERR_NON_FINITE;
        *L = lx_v4(light->position.x, light->position.y, light->position.z, 1.0);
        *d_unit = sw_v3(0.0, 0.0, 0.0);
        return SWARP_OK;
    }
    return SWARP_ERR_UNKNOWN_ENUM;
}

/* Viewer pixels: x_pix = (x_ndc + 1) g/2 - 1/2 (pixel centres at integers). */
static void viewport_pixels(double g, double h, swarp_mat4* Vp) {
    sw_identity(Vp);
    Vp->m[0] = 0.5 * g;
    Vp->m[5] = 0.5 * h;
    Vp->m[12] = 0.5 * g - 0.5;
    Vp->m[13] = 0.5 * h - 0.5;
}

static swarp_vec4 xform_col(const swarp_mat4* m, double x, double y, double z, double w) {
    return sw_xform4(m, lx_v4(x, y, z, w));
}

/* The point of P whose viewer pixel is (x, y): the ray of (2) is the line
 * where (row0 - x row3).X = 0 and (row1 - y row3).X = 0 (rows of V); with
 * pi.X = 0 it is their common null vector.  Done projectively, so a hit at
 * or beyond infinity (Fig. 5) needs no special case, and without V^-1 or
 * the image-space depth (which loses digits far from the eye).  The sign
 * makes the viewer's q = row3.X positive: then X.w > 0 means the hit is in
 * front of the eye, X.w < 0 behind it, X.w = 0 on the horizon. */
static swarp_vec4 plane_point(const swarp_vec4 rows[4], swarp_vec4 pi, double x, double y) {
    swarp_vec4 a = lx_unit4(lx_v4(rows[0].x - x * rows[3].x, rows[0].y - x * rows[3].y,
                                   rows[0].z - x * rows[3].z, rows[0].w - x * rows[3].w));
    swarp_vec4 b = lx_unit4(lx_v4(rows[1].x - y * rows[3].x, rows[1].y - y * rows[3].y,
                                   rows[1].z - y * rows[3].z, rows[1].w - y * rows[3].w));
    swarp_vec4 X = lx_unit4(lx_cross4(a, b, pi));
    if (lx_dot4(rows[3], X) < 0.0) X = lx_scale4(X, -1.0);
    return X;
}

SWARP_API swarp_status swarp_lixel_matrix(const swarp_mat4* M_v, uint32_t g, uint32_t h,
                                          const swarp_light* light, const swarp_plane* plane,
                                          const swarp_lixel_options* opt, swarp_mat4* out_M_l,
                                          swarp_lixel_info* out_info) {
    if (!M_v || !light || !plane || !out_M_l) return SWARP_ERR_NULL_POINTER;
    double t = 0.5;
    if (opt) {
        if (!sw_reserved_zero(opt->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
        if (!sw_finite(opt->raise)) return SWARP_ERR_NON_FINITE;
        if (opt->raise < 0.0 || opt->raise >= 1.0) return SWARP_ERR_OUT_OF_RANGE;
        if (opt->raise > 0.0) t = opt->raise;
    }
    if (!sw_mat_finite(M_v)) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(plane->a) || !sw_finite(plane->b) || !sw_finite(plane->c) || !sw_finite(plane->d))
        return SWARP_ERR_NON_FINITE;
    if (g < 2 || h < 2) return SWARP_ERR_RESOLUTION;
    swarp_vec4 L;
    swarp_vec3 d_unit;
    swarp_status st = check_light(light, &L, &d_unit);
    if (st != SWARP_OK) return st;
    double n_len = sw_len(sw_v3(plane->a, plane->b, plane->c));
    if (!(n_len > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    /* the plane as a covector with unit normal */
    swarp_vec4 pi = lx_v4(plane->a / n_len, plane->b / n_len, plane->c / n_len, plane->d / n_len);
    swarp_vec3 n_unit = sw_v3(pi.x, pi.y, pi.z);

    /* V: world -> viewer pixels [x_v q, y_v q, z_v q, q] as in [LIXEL] §2 */
    swarp_mat4 Vp, V, V_inv;
    viewport_pixels((double)g, (double)h, &Vp);
    sw_mul(&Vp, M_v, &V);
    if (!sw_invert(&V, &V_inv)) return SWARP_ERR_SINGULAR;

    /* pi' = V^-t pi: the plane in viewer-image space */
    swarp_vec4 pi_img;
    pi_img.x = lx_dot4(pi, xform_col(&V_inv, 1, 0, 0, 0));
    pi_img.y = lx_dot4(pi, xform_col(&V_inv, 0, 1, 0, 0));
    pi_img.z = lx_dot4(pi, xform_col(&V_inv, 0, 0, 1, 0));
    pi_img.w = lx_dot4(pi, xform_col(&V_inv, 0, 0, 0, 1));
    /* pi'_z = pi . eye (the eye is V^-1 (0,0,1,0)); compared with the plane
     * in units where pixel coordinates are O(1) */
    double pi_scale = hypot(hypot(pi_img.x * g, pi_img.y * h), hypot(pi_img.z, pi_img.w));
    if (!(fabs(pi_img.z) > LX_EYE_EPS * pi_scale)) return SWARP_ERR_LIXEL_PLANE_THROUGH_EYE;

    /* [LIXEL] (2): the four corner pixels, hit points p^1..p^4 on P */
    const double px[4] = {0.0, 0.0, (double)g - 1.0, (double)g - 1.0};
    const double py[4] = {0.0, (double)h - 1.0, (double)h - 1.0, 0.0};
    swarp_vec4 rows[4] = {lx_row(&V, 0), lx_row(&V, 1), lx_row(&V, 2), lx_row(&V, 3)};
    swarp_vec4 P[4];
    uint32_t in_front = 0;
    int best = -1;
    for (int i = 0; i < 4; ++i) {
        P[i] = plane_point(rows, pi, px[i], py[i]);
        if (!lx_finite4(P[i])) return SWARP_ERR_SINGULAR;
        if (P[i].w > LX_FRONT_EPS) {
            ++in_front;
            if (best < 0 || P[i].w > P[best].w) best = i;
        }
    }
    if (in_front == 0) return SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE;
    /* Raise p^4 as in the paper when it lies in front (and not absurdly far
     * compared with the best corner); otherwise the corner most in front, so
     * the raised point sits between the light and the visible part of P. */
    int r = (P[3].w > LX_FRONT_EPS && P[3].w >= 1e-3 * P[best].w) ? 3 : best;
    swarp_vec3 p_r = sw_scale(sw_v3(P[r].x, P[r].y, P[r].z), 1.0 / P[r].w);

    /* the light must not lie on P */
    if (L.w == 0.0) {
        if (fabs(sw_dot(n_unit, d_unit)) < LX_PARALLEL_EPS) return SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE;
    } else {
        swarp_vec3 l = sw_v3(L.x, L.y, L.z);
        double dist = fabs(lx_dot4(pi, L));
        if (!(dist > LX_ON_PLANE_EPS * sw_len(sw_sub(l, p_r)))) return SWARP_ERR_LIXEL_LIGHT_ON_PLANE;
    }

    /* the eye (finite for a perspective viewer) */
    swarp_vec4 E = lx_cross4(lx_unit4(rows[0]), lx_unit4(rows[1]), lx_unit4(rows[3]));
    int eye_finite = fabs(E.w) > LX_FRONT_EPS * lx_len4(E);
    swarp_vec3 e = eye_finite ? sw_scale(sw_v3(E.x, E.y, E.z), 1.0 / E.w) : sw_v3(0, 0, 0);

    /* Fig. 2: p-hat on the ray from the light through p^r */
    swarp_vec3 p_hat;
    if (L.w == 0.0) {
        double s = eye_finite ? sw_len(sw_sub(p_r, e)) : sw_len(p_r) + 1.0;
        p_hat = sw_sub(p_r, sw_scale(d_unit, t * s));
    } else {
        p_hat = sw_add(sw_scale(p_r, 1.0 - t), sw_scale(sw_v3(L.x, L.y, L.z), t));
    }

    /* [LIXEL] (1), (7)-(10): five correspondences ((9) read as
     * [(g-1)q, (h-1)q, 1q, q]^t = M_l p^3, papers README); the corner rays
     * of [LIXEL] (2) gave p^1..p^4 above */
    swarp_vec4 src[5], dst[5];
    src[0] = L;
    dst[0] = lx_v4(0.0, 0.0, 1.0, 0.0);
    for (int i = 0; i < 4; ++i) {
        src[i + 1] = P[i];
        dst[i + 1] = lx_v4(px[i], py[i], 1.0, 1.0);
    }
    src[r + 1] = lx_v4(p_hat.x, p_hat.y, p_hat.z, 1.0);
    dst[r + 1].z = -1.0;
    swarp_mat4 M;
    double cond = 0.0;
    swarp_status sst = swarp_lixel_solve5(src, dst, &M, &cond);
    if (swarp_status_is_error(sst)) return sst;

    /* Sign of +-GLP (Fig. 5): on P the two images agree, so q_l = c q_v for
     * every (homogeneous) point of P; make c > 0 so q_l > 0 exactly on the
     * part of P in front of the viewer. */
    double q_l = sw_xform4(&M, P[r]).w, q_v = sw_xform4(&V, P[r]).w;
    if (q_l * q_v < 0.0)
        for (int i = 0; i < 16; ++i) M.m[i] = -M.m[i];
    if (!sw_mat_finite(&M)) return SWARP_ERR_SINGULAR;

    /* informational results, most important first */
    swarp_status info = SWARP_OK;
    /* The view direction: the centre pixel's ray (row0 - c_x row3).X =
     * (row1 - c_y row3).X = 0 (as in plane_point) at infinity, w = 0: the
     * cross product of the two covectors' x, y, z parts, which hold no
     * translation.  Through V^-1, the far point minus the near point cancelled
     * at the eye's magnitude: with the eye 1e6 out, n . v carried 1e-10 of
     * rounding against LX_VIEW_PARALLEL_EPS (issue 9: PLANE_PARALLEL_VIEW to
     * nearest, QUAD_ACROSS_INFINITY under FE_TOWARDZERO, n . v = 2e-15). */
    const double c_x = 0.5 * ((double)g - 1.0), c_y = 0.5 * ((double)h - 1.0);
    swarp_vec3 ra, rb, v_unit;
    int view_parallel =
        sw_normalize(sw_v3(rows[0].x - c_x * rows[3].x, rows[0].y - c_x * rows[3].y, rows[0].z - c_x * rows[3].z),
                     &ra) &&
        sw_normalize(sw_v3(rows[1].x - c_y * rows[3].x, rows[1].y - c_y * rows[3].y, rows[1].z - c_y * rows[3].z),
                     &rb) &&
        sw_normalize(sw_cross(ra, rb), &v_unit) && fabs(sw_dot(v_unit, n_unit)) < LX_VIEW_PARALLEL_EPS;
    double side_eye = eye_finite ? lx_dot4(pi, lx_v4(e.x, e.y, e.z, 1.0)) : 0.0;
    double side_light = L.w == 0.0 ? -sw_dot(n_unit, d_unit) : lx_dot4(pi, L);
    if (sst == SWARP_INFO_LIXEL_ILL_CONDITIONED)
        info = sst;
    else if (view_parallel)
        info = SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW;
    else if (in_front < 4)
        info = SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY;
    else if (side_eye * side_light < 0.0)
        info = SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE;

    *out_M_l = M;
    if (out_info) {
        swarp_lixel_info inf;
        memset(&inf, 0, sizeof inf);
        for (int i = 0; i < 4; ++i) inf.corners[i] = P[i];
        inf.raised = lx_v4(p_hat.x, p_hat.y, p_hat.z, 1.0);
        inf.raised_index = (uint32_t)r;
        inf.corners_in_front = in_front;
        inf.conditioning = cond;
        *out_info = inf;
    }
    return info;
}

/* ---- Fig. 6: restriction to the rays C ----------------------------------- */

/* A vertex of C as a homogeneous point: w != 0 is divided out (a point),
 * w = 0 stays a direction from the light. */
static swarp_vec4 ray_vertex(swarp_vec4 c) {
    return c.w != 0.0 ? lx_v4(c.x / c.w, c.y / c.w, c.z / c.w, 1.0) : c;
}

/* Light-image (x, y) of X when q is safely positive. */
static int light_xy(const swarp_mat4* M, swarp_vec4 X, double* x, double* y) {
    swarp_vec4 o = sw_xform4(M, X);
    double q_scale = lx_len4(lx_row(M, 3)) * lx_len4(X);
    if (!(o.w > LX_Q_EPS * q_scale)) return 0;
    *x = o.x / o.w;
    *y = o.y / o.w;
    return sw_finite(*x) && sw_finite(*y);
}

typedef struct box2 { double lo_x, lo_y, hi_x, hi_y; } box2;

static void box_add(box2* b, double x, double y, double c, double s, double s_x, double s_y) {
    double xt = s_x * (c * x - s * y), yt = s_y * (s * x + c * y);
    b->lo_x = fmin(b->lo_x, xt);
    b->hi_x = fmax(b->hi_x, xt);
    b->lo_y = fmin(b->lo_y, yt);
    b->hi_y = fmax(b->hi_y, yt);
}

/* The x, y, q rows of M as columns P_i (i = 0..3), each scaled by a power
 * of two to a largest entry in [1/2, 1); a vertex X of C is scaled by the
 * inverse (ray_init), which is exact and keeps every product P_i X_i. */
typedef struct lx_cols {
    double P[12];
    int e[4];
} lx_cols;

static void cols_init(const swarp_mat4* M, lx_cols* pc) {
    for (int i = 0; i < 4; ++i) {
        const double col[3] = {M->m[4 * i], M->m[4 * i + 1], M->m[4 * i + 3]};
        int e = 0;
        const double big = fmax(fabs(col[0]), fmax(fabs(col[1]), fabs(col[2])));
        if (big > 0.0) (void)frexp(big, &e);
        for (int r = 0; r < 3; ++r) pc->P[3 * i + r] = ldexp(col[r], -e);
        pc->e[i] = e;
    }
}

/* A vertex of C: its ray X (ray_init) and the unit light-image vector
 * a = (x q, y q, q) / |.| of it (any positive scale describes the same ray
 * of the convex cone). */
typedef struct lx_ray {
    double X[4];
    double a[3];
} lx_ray;

/* X is the ray of ray_vertex without its division (w made >= 0), its
 * entries times 2^e_i of the columns, then all by one power of two to a
 * largest entry in [2^499, 2^500): a term p_ik (P_i x P_k) of edge_line is
 * below 2^1003, and entries down to 2^-500 of the largest keep their
 * products normal.  Neither M (lixel_matrix's is normalised, a caller's
 * need not be) nor C near DBL_MAX overflows, a column of M 1e300 times the
 * others (q ~ w) does not push the others' products below DBL_MIN, and x/w
 * does not overflow for a tiny w. */
static void ray_init(const lx_cols* pc, swarp_vec4 c, lx_ray* r) {
    const double sg = c.w < 0.0 ? -1.0 : 1.0;
    const double v[4] = {sg * c.x, sg * c.y, sg * c.z, sg * c.w};
    int top = INT_MIN;
    for (int i = 0; i < 4; ++i)
        if (v[i] != 0.0) {
            int f = 0;
            (void)frexp(v[i], &f);
            top = f + pc->e[i] > top ? f + pc->e[i] : top;
        }
    if (top == INT_MIN) top = 0;
    double o[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 4; ++i) {
        r->X[i] = ldexp(v[i], pc->e[i] + 500 - top);
        for (int k = 0; k < 3; ++k) o[k] += pc->P[3 * i + k] * r->X[i];
    }
    double l = hypot(hypot(o[0], o[1]), o[2]);
    if (!(l > 0.0)) l = 1.0;
    r->a[0] = o[0] / l;
    r->a[1] = o[1] / l;
    r->a[2] = o[2] / l;
}

static void cross3(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The light-image line of the edge A B of C as a unit covector l on
 * (X, Y, Q), a positive multiple of a x b for their image vectors; 0 when
 * A and B are the same ray (A ^ B = 0).  With P_i the columns (x, y, q
 * rows) of M, (P A) x (P B) = sum_{i<k} (A_i B_k - A_k B_i) P_i x P_k over
 * the Plucker coordinates of the world line A B: the product of the two
 * image vectors also rounds the terms A_i B_i P_i x P_i, zero exactly, at
 * eps |A_i B_i| |P_i|^2.  For A and B far out on either side of the origin
 * along one axis (C's vertices 1.7e38 and 4.7e31 along x, issue 9) a and b
 * are antipodal to 1e-30, their x, y parts cancel, and the edge's image --
 * a line 95 lixels from the view's corner -- was lost to rounding; the
 * Plucker terms keep it (A_x B_z - A_z B_x has no such cancellation). */
static void edge_line(const lx_cols* pc, const lx_ray* A, const lx_ray* B, double l[3]) {
    double L[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 4; ++i)
        for (int k = i + 1; k < 4; ++k) {
            const double p = A->X[i] * B->X[k] - A->X[k] * B->X[i];
            double x[3];
            cross3(&pc->P[3 * i], &pc->P[3 * k], x);
            L[0] += p * x[0], L[1] += p * x[1], L[2] += p * x[2];
        }
    double len = hypot(hypot(L[0], L[1]), L[2]);
    if (!(len > 0.0) || !sw_finite(len)) len = INFINITY; /* no line: l = 0 */
    l[0] = L[0] / len;
    l[1] = L[1] / len;
    l[2] = L[2] / len;
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Slack allowed when testing a computed intersection against the other
 * rectangle sides (in lixels: far below one). */
#define LX_CLIP_TOL 1e-9

/* l . v of a unit edge line and a vector v is rounded by a few eps |v|_1
 * (3 products, 2 sums, and l's own rounding); within 64 eps |v|_1 it is
 * rounding.  Summed over the n edges of C: n times that. */
#define LX_CONE_FLAT (64.0 * DBL_EPSILON)

/* The orientation of C's cone: +1 when its interior is on the positive side
 * of the edge lines l_j, -1 on the negative side, 0 when the cone is flat to
 * rounding.  For a convex cone every l_j . a_m has that sign or is zero, and
 * so has (sum_j l_j) . a_m, which sums them. */
static int cone_orientation(const lx_cols* pc, const swarp_vec4* C, size_t n) {
    double N[3] = {0.0, 0.0, 0.0};
    lx_ray r0, A, B;
    ray_init(pc, C[0], &r0);
    B = r0;
    for (size_t j = 0; j < n; ++j) {
        A = B;
        if (j + 1 < n)
            ray_init(pc, C[j + 1], &B);
        else
            B = r0;
        double l[3];
        edge_line(pc, &A, &B, l);
        N[0] += l[0], N[1] += l[1], N[2] += l[2];
    }
    double pos = 0.0, neg = 0.0;
    for (size_t m = 0; m < n; ++m) {
        ray_init(pc, C[m], &A);
        const double t = dot3(N, A.a);
        pos = fmax(pos, t);
        neg = fmax(neg, -t);
    }
    const double tol = LX_CONE_FLAT * (double)n;
    /* both signs beyond rounding: C is not convex (outside the documented
     * domain), and which vertex is largest a near tie that the rounding
     * broke (fenv 6000000 case 3500922): no orientation, as if flat */
    if (pos > tol && neg > tol) return 0;
    return pos > tol ? 1 : neg > tol ? -1 : 0;
}

/* The bounding box of (image of the cone C) clipped to the viewer's pixel
 * centres [0, g - 1] x [0, h - 1] (one lixel per pixel needs no more),
 * without storing the clipped polygon:
 * its vertices are (a) vertices of C inside, (b) edges of C crossing a
 * side of the rectangle, (c) rectangle corners inside the cone.  All tests
 * are linear in the homogeneous vectors, so rays with q <= 0 need no case.
 * Returns 0 when the clipped set is empty. */
static int clipped_box(const swarp_mat4* M, const swarp_vec4* C, size_t n, double g, double h, double c,
                       double s, double s_x, double s_y, box2* box) {
    /* sides as functionals l(v) >= 0 on v = (X, Y, Q) */
    const double side[4][3] = {{1, 0, 0}, {-1, 0, g - 1.0}, {0, 1, 0}, {0, -1, h - 1.0}};
    int any = 0;
    double S[3] = {0, 0, 0};
    lx_cols pc;
    cols_init(M, &pc);
    lx_ray r0, A, B;
    ray_init(&pc, C[0], &r0);
    B = r0;
    for (size_t j = 0; j < n; ++j) {
        A = B;
        if (j + 1 < n)
            ray_init(&pc, C[j + 1], &B);
        else
            B = r0;
        const double* a = A.a;
        const double* b = B.a;
        double l[3];
        edge_line(&pc, &A, &B, l);
        S[0] += a[0], S[1] += a[1], S[2] += a[2];
        double la[4], lb[4];
        int inside_a = a[2] > 0.0;
        for (int k = 0; k < 4; ++k) {
            la[k] = dot3(side[k], a);
            lb[k] = dot3(side[k], b);
            if (la[k] < 0.0) inside_a = 0;
        }
        if (inside_a) { /* (a) */
            box_add(box, a[0] / a[2], a[1] / a[2], c, s, s_x, s_y);
            any = 1;
        }
        for (int k = 0; k < 4; ++k) { /* (b) */
            if (!((la[k] < 0.0 && lb[k] > 0.0) || (la[k] > 0.0 && lb[k] < 0.0))) continue;
            /* the crossing (lb a - la b)/(lb - la): a combination with
             * weights in [0, 1], which for a . b >= 0 cancels nothing; for
             * a and b (nearly) antipodal it cancels to the rounding, and is
             * formed as (s_k x (a x b))/(lb - la) ((a x b) x s =
             * (a.s) b - (b.s) a) from l, a positive multiple of a x b
             * (edge_line) */
            const double ta = lb[k] / (lb[k] - la[k]), tb = -la[k] / (lb[k] - la[k]);
            double v[3] = {ta * a[0] + tb * b[0], ta * a[1] + tb * b[1], ta * a[2] + tb * b[2]};
            if (dot3(a, b) < 0.0) {
                cross3(side[k], l, v);
                if (lb[k] - la[k] < 0.0) v[0] = -v[0], v[1] = -v[1], v[2] = -v[2];
            }
            if (!(v[2] > 0.0)) continue;
            double x = v[0] / v[2], y = v[1] / v[2];
            if (x < -LX_CLIP_TOL || x > g - 1.0 + LX_CLIP_TOL || y < -LX_CLIP_TOL || y > h - 1.0 + LX_CLIP_TOL)
                continue;
            box_add(box, x, y, c, s, s_x, s_y);
            any = 1;
        }
    }
    /* (c): corner K inside the cone when every edge sees it on the side of
     * the interior vector S (sum of the unit vertex vectors).  Where l_j . S
     * is within rounding (LX_CONE_FLAT) S lies on the edge's plane and its
     * side is the rounding's: two a_m antipodal to 1e-30 (issue 9: vertices
     * 1.7e38 and 4.7e31 out on either side along x) cancel in S, which then
     * lies on the planes of the edges to the third vertex, and the corner
     * test took a fat cone for flat.  Such an edge takes the cone's
     * orientation instead.  A cone flat to rounding (orientation 0: e.g. a
     * cluster of rays and one direction at q = 0, a wedge of width 1e-76,
     * issue 9) has no inside: its clipped image is a segment whose ends are
     * (a) or (b) points, a corner on it adds nothing, and one off it is out
     * (before, the sign of the rounding noise put a corner 1835 lixels off
     * the wedge inside under FE_UPWARD). */
    const double kx[4] = {0.0, g - 1.0, g - 1.0, 0.0}, ky[4] = {0.0, 0.0, h - 1.0, h - 1.0};
    const double s_norm = fabs(S[0]) + fabs(S[1]) + fabs(S[2]);
    int inside[4] = {n >= 3, n >= 3, n >= 3, n >= 3};
    int orient = 2; /* not yet known */
    B = r0;
    for (size_t j = 0; j < n && (inside[0] || inside[1] || inside[2] || inside[3]); ++j) {
        A = B;
        if (j + 1 < n)
            ray_init(&pc, C[j + 1], &B);
        else
            B = r0;
        double l[3];
        edge_line(&pc, &A, &B, l);
        const double dS = dot3(l, S);
        const int flat = !(fabs(dS) > LX_CONE_FLAT * s_norm);
        if (flat && orient == 2) orient = cone_orientation(&pc, C, n);
        for (int q = 0; q < 4; ++q) {
            const double K[3] = {kx[q], ky[q], 1.0};
            const double dK = dot3(l, K);
            if (flat ? orient == 0 || orient * dK < 0.0 : dS * dK < 0.0) inside[q] = 0;
        }
    }
    for (int q = 0; q < 4; ++q)
        if (inside[q]) {
            box_add(box, kx[q], ky[q], c, s, s_x, s_y);
            any = 1;
        }
    return any && sw_finite(box->lo_x) && sw_finite(box->hi_x) && sw_finite(box->lo_y) && sw_finite(box->hi_y);
}

SWARP_API swarp_status swarp_lixel_restrict(const swarp_mat4* M_l, const swarp_vec4* C, size_t n,
                                            const swarp_lixel_restrict_options* opt,
                                            swarp_lixel_rect* out_rect, swarp_mat4* out_A_l,
                                            swarp_mat4* out_M_l) {
    if (!M_l || !C || !out_rect || !out_M_l) return SWARP_ERR_NULL_POINTER;
    if (n == 0) return SWARP_ERR_INVALID_ARGUMENT;
    double s_x = 1.0, s_y = 1.0, twist = 0.0;
    uint32_t max_size = SWARP_LIXEL_DEFAULT_MAX_SIZE, view_w = 0, view_h = 0;
    if (opt) {
        if (!sw_reserved_zero(opt->_reserved, 4) || opt->_reserved0 != 0) return SWARP_ERR_RESERVED_NONZERO;
        if ((opt->view_width == 0) != (opt->view_height == 0)) return SWARP_ERR_RESOLUTION;
        view_w = opt->view_width;
        view_h = opt->view_height;
        if (!sw_finite(opt->scale_x) || !sw_finite(opt->scale_y) || !sw_finite(opt->twist))
            return SWARP_ERR_NON_FINITE;
        if (opt->scale_x < 0.0 || opt->scale_y < 0.0) return SWARP_ERR_OUT_OF_RANGE;
        if (opt->scale_x > 0.0) s_x = opt->scale_x;
        if (opt->scale_y > 0.0) s_y = opt->scale_y;
        twist = opt->twist;
        if (opt->max_size > 0) max_size = opt->max_size;
    }
    if (!sw_mat_finite(M_l)) return SWARP_ERR_NON_FINITE;
    for (size_t j = 0; j < n; ++j)
        if (!lx_finite4(C[j])) return SWARP_ERR_NON_FINITE;
    /* A_l without the translation: scale . rotate(twist) on (x, y) */
    double c = cos(twist), s = sin(twist);
    box2 box = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    if (view_w > 0) {
        if (!clipped_box(M_l, C, n, (double)view_w, (double)view_h, c, s, s_x, s_y, &box))
            return SWARP_ERR_LIXEL_EMPTY;
    } else {
        for (size_t j = 0; j < n; ++j) {
            double x, y;
            /* all rays of C must be in the light frustum (q > 0); then the
             * image of the convex set is the hull of the vertex images */
            if (!light_xy(M_l, ray_vertex(C[j]), &x, &y)) return SWARP_ERR_LIXEL_RAY_OUTSIDE;
            box_add(&box, x, y, c, s, s_x, s_y);
        }
    }
    double lo_x = box.lo_x, lo_y = box.lo_y, hi_x = box.hi_x, hi_y = box.hi_y;
    /* integer (lixel-centre) corners enclosing the image; a value within
     * LX_SNAP of an integer snaps to it (rounding noise of ~1e-12 lixel
     * must not add a row: the clip volume reaches half a lixel beyond the
     * centres anyway, so nothing is lost) */
    double x0 = floor(lo_x + LX_SNAP), x1 = ceil(hi_x - LX_SNAP), y0 = floor(lo_y + LX_SNAP),
           y1 = ceil(hi_y - LX_SNAP);
    if (!(x1 - x0 + 1.0 <= (double)max_size) || !(y1 - y0 + 1.0 <= (double)max_size) ||
        !(fabs(x0) < 2e9) || !(fabs(x1) < 2e9) || !(fabs(y0) < 2e9) || !(fabs(y1) < 2e9))
        return SWARP_ERR_LIXEL_RECT_TOO_LARGE;
    swarp_mat4 A;
    sw_identity(&A);
    sw_set(&A, 0, 0, s_x * c);
    sw_set(&A, 0, 1, -s_x * s);
    sw_set(&A, 0, 3, -x0);
    sw_set(&A, 1, 0, s_y * s);
    sw_set(&A, 1, 1, s_y * c);
    sw_set(&A, 1, 3, -y0);
    swarp_mat4 M;
    sw_mul(&A, M_l, &M); /* [LIXEL] Fig. 6, §2 "Less of the plane": M_l := A_l M_l */
    /* valid (finite) inputs whose product exceeds DBL_MAX (huge scale_x/y):
     * not representable -> OUT_OF_RANGE, not NON_FINITE */
    if (!sw_mat_finite(&M)) return SWARP_ERR_OUT_OF_RANGE;
    swarp_lixel_rect rect;
    rect.x0 = (int32_t)x0;
    rect.x1 = (int32_t)x1;
    rect.y0 = (int32_t)y0;
    rect.y1 = (int32_t)y1;
    rect.width = (uint32_t)(x1 - x0 + 1.0);
    rect.height = (uint32_t)(y1 - y0 + 1.0);
    *out_rect = rect;
    *out_M_l = M;
    if (out_A_l) *out_A_l = A;
    return SWARP_OK;
}

/* Below this (relative to the image coordinates) the line images to a point,
 * and `below` lies on the line. */
#define LX_TWIST_EPS 1e-12

SWARP_API swarp_status swarp_lixel_twist_for_line(const swarp_mat4* M_l, const swarp_vec3* a,
                                                  const swarp_vec3* b, const swarp_vec3* below,
                                                  double* out_twist) {
    if (!M_l || !a || !b || !below || !out_twist) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(M_l) || !sw_finite3(a) || !sw_finite3(b) || !sw_finite3(below)) return SWARP_ERR_NON_FINITE;
    double xa, ya, xb, yb, xc, yc;
    if (!light_xy(M_l, lx_v4(a->x, a->y, a->z, 1.0), &xa, &ya) ||
        !light_xy(M_l, lx_v4(b->x, b->y, b->z, 1.0), &xb, &yb) ||
        !light_xy(M_l, lx_v4(below->x, below->y, below->z, 1.0), &xc, &yc))
        return SWARP_ERR_LIXEL_TWIST_LINE;
    double dx = xb - xa, dy = yb - ya;
    double scale = fmax(fmax(fabs(xa), fabs(ya)), fmax(fabs(xb), fabs(yb))) + 1.0;
    if (!(hypot(dx, dy) > LX_TWIST_EPS * scale)) return SWARP_ERR_LIXEL_TWIST_LINE;
    /* rotate by -angle(line): the line becomes horizontal */
    double twist = -atan2(dy, dx);
    /* the rotated y of `below` relative to the line must be negative */
    double c = cos(twist), s = sin(twist);
    double rel = s * (xc - xa) + c * (yc - ya);
    /* `below` on the line (its distance within LX_TWIST_EPS of the image
     * scale, as for the line's length above) has no side: the sign of rel
     * would be the rounding's, and the twist would flip by pi with the
     * caller's rounding mode (issue 9: b and below on a line parallel to x,
     * a at 1e97 on x imaging to its vanishing point; below 5e-17 lixel off
     * the line in exact arithmetic) */
    const double scale_c = fmax(scale, fmax(fabs(xc), fabs(yc)) + 1.0);
    if (!(fabs(rel) > LX_TWIST_EPS * scale_c)) return SWARP_ERR_LIXEL_TWIST_LINE;
    if (rel > 0.0) twist = twist > 0.0 ? twist - SWARP_PI : twist + SWARP_PI;
    *out_twist = twist;
    return SWARP_OK;
}

/* ---- 'M_l = GLV GLP' ----------------------------------------------------- */

SWARP_API swarp_status swarp_lixel_factor(const swarp_mat4* M_l, uint32_t width, uint32_t height,
                                          swarp_depth_range depth_range, double plane_depth,
                                          swarp_mat4* out_GLV, swarp_mat4* out_GLP) {
    if (!M_l || !out_GLV || !out_GLP) return SWARP_ERR_NULL_POINTER;
    if (width == 0 || height == 0) return SWARP_ERR_RESOLUTION;
    if (depth_range != SWARP_DEPTH_DEFAULT && depth_range != SWARP_DEPTH_NEG_ONE_TO_ONE &&
        depth_range != SWARP_DEPTH_ZERO_TO_ONE)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_finite(plane_depth) || !sw_mat_finite(M_l)) return SWARP_ERR_NON_FINITE;
    if (plane_depth < 0.0 || plane_depth >= 1.0) return SWARP_ERR_OUT_OF_RANGE;
    double f = plane_depth > 0.0 ? plane_depth : 0.5;
    double W = (double)width, H = (double)height;
    swarp_vec4 X = lx_row(M_l, 0), Y = lx_row(M_l, 1), Z = lx_row(M_l, 2), Q = lx_row(M_l, 3);
    /* depth z' = alpha z + beta: p-hat (z = -1) to the near plane, P (z = 1)
     * to the fraction f of the range ([LIXEL] footnote: any affine map of z) */
    double alpha, beta;
    if (depth_range == SWARP_DEPTH_ZERO_TO_ONE) {
        alpha = 0.5 * f;
        beta = 0.5 * f;
    } else {
        alpha = f;
        beta = f - 1.0;
    }
    swarp_mat4 P, Vw;
    /* x_ndc = (2 x + 1)/W - 1: lixel centres 0 .. W-1 inside (-1, 1) */
    lx_set_row(&P, 0, lx_v4(2.0 / W * X.x + (1.0 / W - 1.0) * Q.x, 2.0 / W * X.y + (1.0 / W - 1.0) * Q.y,
                            2.0 / W * X.z + (1.0 / W - 1.0) * Q.z, 2.0 / W * X.w + (1.0 / W - 1.0) * Q.w));
    lx_set_row(&P, 1, lx_v4(2.0 / H * Y.x + (1.0 / H - 1.0) * Q.x, 2.0 / H * Y.y + (1.0 / H - 1.0) * Q.y,
                            2.0 / H * Y.z + (1.0 / H - 1.0) * Q.z, 2.0 / H * Y.w + (1.0 / H - 1.0) * Q.w));
    lx_set_row(&P, 2, lx_v4(alpha * Z.x + beta * Q.x, alpha * Z.y + beta * Q.y, alpha * Z.z + beta * Q.z,
                            alpha * Z.w + beta * Q.w));
    lx_set_row(&P, 3, Q);
    viewport_pixels(W, H, &Vw);
    /* finite M_l but an entry of GLP beyond DBL_MAX (row 0/1 reach
     * (2/W + 1) max|M_l| <= 3 max|M_l|): the inputs were valid, the result is
     * not representable -> OUT_OF_RANGE, not NON_FINITE */
    if (!sw_mat_finite(&P)) return SWARP_ERR_OUT_OF_RANGE;
    *out_GLV = Vw;
    *out_GLP = P;
    return SWARP_OK;
}

/* ---- §3: several planes -------------------------------------------------- */

/* |u| = |n_floor x n_wall| below this (unit normals): the planes are parallel. */
#define LX_SPLIT_EPS 1e-9

/* Sutherland-Hodgman against side(X) = sign * Sigma.X >= 0; writes at most
 * n + 1 vertices when out != NULL, returns the count. */
static size_t clip_side(const swarp_vec4* C, size_t n, swarp_vec4 Sigma, double sign, swarp_vec4* out) {
    size_t m = 0;
    for (size_t j = 0; j < n; ++j) {
        swarp_vec4 A = ray_vertex(C[j]), B = ray_vertex(C[(j + 1) % n]);
        double sa = sign * lx_dot4(Sigma, A), sb = sign * lx_dot4(Sigma, B);
        if (sa >= 0.0) {
            if (out) out[m] = A;
            ++m;
        }
        if ((sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)) {
            /* the point of segment AB on Sigma: (sa B - sb A)/(sa - sb) */
            double ta = -sb / (sa - sb), tb = sa / (sa - sb);
            if (out)
                out[m] = lx_v4(ta * A.x + tb * B.x, ta * A.y + tb * B.y, ta * A.z + tb * B.z, ta * A.w + tb * B.w);
            ++m;
        }
    }
    return m;
}

SWARP_API swarp_status swarp_lixel_split(const swarp_light* light, const swarp_plane* floor_plane,
                                         const swarp_plane* wall_plane, const swarp_vec4* C_tot,
                                         size_t n, swarp_vec4* out_floor, size_t floor_capacity,
                                         size_t* out_floor_count, swarp_vec4* out_wall,
                                         size_t wall_capacity, size_t* out_wall_count) {
    if (!light || !floor_plane || !wall_plane || !C_tot || !out_floor_count || !out_wall_count)
        return SWARP_ERR_NULL_POINTER;
    if ((!out_floor && floor_capacity) || (!out_wall && wall_capacity)) return SWARP_ERR_NULL_POINTER;
    if (n < 3) return SWARP_ERR_INVALID_ARGUMENT;
    swarp_vec4 L;
    swarp_vec3 d_unit;
    swarp_status st = check_light(light, &L, &d_unit);
    if (st != SWARP_OK) return st;
    const swarp_plane* pl[2] = {floor_plane, wall_plane};
    for (int k = 0; k < 2; ++k)
        if (!sw_finite(pl[k]->a) || !sw_finite(pl[k]->b) || !sw_finite(pl[k]->c) || !sw_finite(pl[k]->d))
            return SWARP_ERR_NON_FINITE;
    int kind = -1; /* 1: points, 0: directions */
    for (size_t j = 0; j < n; ++j) {
        if (!lx_finite4(C_tot[j])) return SWARP_ERR_NON_FINITE;
        int k = C_tot[j].w != 0.0;
        if (kind >= 0 && k != kind) return SWARP_ERR_INVALID_ARGUMENT; /* mixed */
        kind = k;
    }
    if (kind == 0 && L.w == 0.0) return SWARP_ERR_INVALID_ARGUMENT; /* directions need a point light */
    swarp_vec3 nf, nw;
    double lf = sw_len(sw_v3(floor_plane->a, floor_plane->b, floor_plane->c));
    double lw = sw_len(sw_v3(wall_plane->a, wall_plane->b, wall_plane->c));
    if (!(lf > 0.0) || !(lw > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    nf = sw_scale(sw_v3(floor_plane->a, floor_plane->b, floor_plane->c), 1.0 / lf);
    nw = sw_scale(sw_v3(wall_plane->a, wall_plane->b, wall_plane->c), 1.0 / lw);
    double hf = -floor_plane->d / lf, hw = -wall_plane->d / lw;
    /* the floor/wall line: point A, direction u */
    swarp_vec3 u = sw_cross(nf, nw);
    double uu = sw_dot(u, u);
    if (!(sqrt(uu) > LX_SPLIT_EPS)) return SWARP_ERR_DEGENERATE;
    swarp_vec3 A = sw_scale(sw_add(sw_scale(sw_cross(nw, u), hf), sw_scale(sw_cross(u, nf), hw)), 1.0 / uu);
    /* Sigma: the plane through the light and the line */
    swarp_vec3 n_sigma = L.w == 0.0 ? sw_cross(u, d_unit) : sw_cross(u, sw_sub(sw_v3(L.x, L.y, L.z), A));
    double ls = sw_len(n_sigma);
    double lscale = L.w == 0.0 ? 1.0 : sw_len(sw_sub(sw_v3(L.x, L.y, L.z), A)) + 1e-300;
    if (!(ls > LX_SPLIT_EPS * lscale)) return SWARP_ERR_DEGENERATE; /* light on the line / along it */
    n_sigma = sw_scale(n_sigma, 1.0 / ls);
    swarp_vec4 Sigma = lx_v4(n_sigma.x, n_sigma.y, n_sigma.z, -sw_dot(n_sigma, A));
    /* a floor point in front of the wall (on the side its normal points to):
     * F = A + w_f / |w_f|, so Σ · F = n_Σ · w_f / |w_f| -- formed from the
     * unit vectors, not as n_Σ · F - n_Σ · A: with the line 1e6 from the
     * origin that difference carried 1e-10 of rounding against the 1e-9
     * bound, and the caller's rounding mode decided DEGENERATE (issue 9) */
    swarp_vec3 w_f = sw_sub(nw, sw_scale(nf, sw_dot(nw, nf)));
    double side_floor = sw_dot(n_sigma, w_f) / sw_len(w_f);
    if (!(fabs(side_floor) > LX_SPLIT_EPS)) return SWARP_ERR_DEGENERATE; /* light on the floor */
    double sign = side_floor > 0.0 ? 1.0 : -1.0;
    size_t need_f = clip_side(C_tot, n, Sigma, sign, NULL);
    size_t need_w = clip_side(C_tot, n, Sigma, -sign, NULL);
    if (need_f > floor_capacity || need_w > wall_capacity) {
        *out_floor_count = need_f;
        *out_wall_count = need_w;
        return SWARP_ERR_CAPACITY;
    }
    clip_side(C_tot, n, Sigma, sign, out_floor);
    clip_side(C_tot, n, Sigma, -sign, out_wall);
    *out_floor_count = need_f;
    *out_wall_count = need_w;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lixel_select(const swarp_mat4* GLP, size_t count, const swarp_vec3* p,
                                          uint32_t* out_index) {
    if ((!GLP && count) || !p || !out_index) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite3(p)) return SWARP_ERR_NON_FINITE;
    for (size_t i = 0; i < count; ++i)
        if (!sw_mat_finite(&GLP[i])) return SWARP_ERR_NON_FINITE;
    uint32_t idx = (uint32_t)count;
    for (size_t i = 0; i < count; ++i) {
        swarp_vec4 c = sw_xform_point(&GLP[i], *p);
        /* the shader's test: inside the clip volume's x, y slab, in front */
        if (c.w > 0.0 && fabs(c.x) <= c.w && fabs(c.y) <= c.w) {
            idx = (uint32_t)i;
            break;
        }
    }
    *out_index = idx;
    return SWARP_OK;
}
