/* Plane-stabilised light matrices: [LIXEL] Chong & Gortler, "A Lixel for
 * every Pixel".  The matrix M_l, its restriction to a set of rays C (Fig. 6),
 * its factorisation into viewport x projection, and the multi-plane
 * selection of §3.  The five-point solver is in lixel_solve.c. */
#include <float.h>
#include <limits.h>

#include "lixel/lixel_internal.h"
#include "common/depth_range.h"

_Static_assert(sizeof(swarp_lixel_options) == sizeof(double) + 16, "swarp_lixel_options size");
_Static_assert(sizeof(swarp_lixel_info) == 5 * sizeof(swarp_vec4) + 8 + sizeof(double) + 16,
               "swarp_lixel_info size");
_Static_assert(sizeof(swarp_lixel_rect) == 24, "swarp_lixel_rect size");
_Static_assert(sizeof(swarp_lixel_restrict_options) == 3 * sizeof(double) + 16 + 16,
               "swarp_lixel_restrict_options size");

/* |pi'_z| relative to the whole image-space plane below this: the plane
 * contains the eye (it images to a line).  A plane 1e-10 of the near
 * distance away from the eye still works, but carries few digits. */
#define SW_LX_EYE_EPS 1e-10
/* Normalised w of a corner point above this: the ray hits P in front of the
 * eye (w <= this: behind, or so far that 1/w overflows the scene, ~1e12). */
#define SW_LX_FRONT_EPS 1e-12
/* |n.d| (unit vectors) below this: the directional light grazes the plane. */
#define SW_LX_PARALLEL_EPS 1e-10
/* Light-to-plane distance below this fraction of the light-to-corner
 * distance: the point light lies on the plane. */
#define SW_LX_ON_PLANE_EPS 1e-10
/* |n.v| (unit vectors) below this: the plane is parallel to the view
 * direction (horizon through the image centre). */
#define SW_LX_VIEW_PARALLEL_EPS 1e-9
/* Snap distance (lixels) of the rectangle corners to integers. */
#define SW_LX_SNAP 1e-6
/* Largest |corner| of a restricted rectangle (lixels): below 2^31, so the
 * corners convert to int32_t exactly. */
#define SW_LX_RECT_MAX_COORD 2e9
/* A vertex of C with q below this fraction of |row 4| |X| is outside. */
#define SW_LX_Q_EPS 1e-12

static swarp_status sw_lixel_light(const swarp_light* light, swarp_vec4* L, swarp_vec3* d_unit) {
    if (!sw_reserved_zero(light->_reserved, 4) || light->_reserved0 != 0) return SWARP_ERR_RESERVED_NONZERO;
    swarp_light_type t = light->type == SWARP_LIGHT_DEFAULT ? SWARP_LIGHT_DIRECTIONAL : light->type;
    if (t == SWARP_LIGHT_DIRECTIONAL) {
        if (!sw_finite3(&light->direction)) return SWARP_ERR_NON_FINITE;
        if (!sw_normalize(light->direction, d_unit)) return SWARP_ERR_ZERO_VECTOR;
        /* the centre of projection is the point at infinity of the rays */
        *L = sw_v4(d_unit->x, d_unit->y, d_unit->z, 0.0);
        return SWARP_OK;
    }
    if (t == SWARP_LIGHT_POINT) {
        if (!sw_finite3(&light->position)) return SWARP_ERR_NON_FINITE;
        *L = sw_v4(light->position.x, light->position.y, light->position.z, 1.0);
        *d_unit = sw_v3(0.0, 0.0, 0.0);
        return SWARP_OK;
    }
    return SWARP_ERR_UNKNOWN_ENUM;
}

/* Viewer pixels: x_pix = (x_ndc + 1) g/2 - 1/2 (pixel centres at integers). */
static void sw_viewport_pixels(double g, double h, swarp_mat4* Vp) {
    sw_identity(Vp);
    Vp->m[0] = 0.5 * g;
    Vp->m[5] = 0.5 * h;
    Vp->m[12] = 0.5 * g - 0.5;
    Vp->m[13] = 0.5 * h - 0.5;
}

static swarp_vec4 sw_xform_col(const swarp_mat4* m, double x, double y, double z, double w) {
    return sw_xform4(m, sw_v4(x, y, z, w));
}

/* The point of P whose viewer pixel is (x, y): the ray of (2) is the line
 * where (row0 - x row3).X = 0 and (row1 - y row3).X = 0 (rows of V); with
 * pi.X = 0 it is their common null vector.  Done projectively, so a hit at
 * or beyond infinity (Fig. 5) needs no special case, and without V^-1 or
 * the image-space depth (which loses digits far from the eye).  The sign
 * makes the viewer's q = row3.X positive: then X.w > 0 means the hit is in
 * front of the eye, X.w < 0 behind it, X.w = 0 on the horizon. */
static swarp_vec4 sw_plane_point(const swarp_vec4 rows[4], swarp_vec4 pi, double x, double y) {
    swarp_vec4 a = sw_unit4(sw_v4(rows[0].x - x * rows[3].x, rows[0].y - x * rows[3].y,
                                   rows[0].z - x * rows[3].z, rows[0].w - x * rows[3].w));
    swarp_vec4 b = sw_unit4(sw_v4(rows[1].x - y * rows[3].x, rows[1].y - y * rows[3].y,
                                   rows[1].z - y * rows[3].z, rows[1].w - y * rows[3].w));
    swarp_vec4 X = sw_unit4(sw_cross4(a, b, pi));
    if (sw_dot4(rows[3], X) < 0.0) X = sw_scale4(X, -1.0);
    return X;
}

/* The state of one swarp_lixel_matrix call, filled step by step. */
typedef struct sw_lx_setup {
    double g, h;          /* viewer resolution (pixels) */
    double t;             /* raise fraction of Fig. 2 */
    swarp_vec4 L;         /* the light: its centre of projection */
    swarp_vec3 d_unit;    /* unit direction of a directional light, else 0 */
    swarp_vec4 pi;        /* the plane P as a covector with unit normal */
    swarp_vec3 n_unit;    /* its normal */
    swarp_mat4 V;         /* world -> viewer pixels */
    swarp_vec4 rows[4];   /* the rows of V */
    double px[4], py[4];  /* the corner pixels */
    swarp_vec4 P[4];      /* their hit points p^1..p^4 on P */
    uint32_t in_front;    /* how many of them lie in front of the eye */
    int best;             /* the one most in front */
    int r;                /* the raised corner */
    int eye_finite;       /* perspective viewer: the eye e is a point */
    swarp_vec3 e;
    swarp_vec3 p_hat;     /* the raised point */
} sw_lx_setup;

/* Raise p^4 only when its w is at least this fraction of the best corner's:
 * a corner almost at the horizon would put p-hat absurdly far out. */
#define SW_LX_RAISE_FAR 1e-3

/* Checks the arguments in the documented order and resolves the defaults:
 * the raise fraction t (0.5) and the plane as a unit covector. */
static swarp_status sw_lixel_check(const swarp_mat4* M_v, uint32_t g, uint32_t h, const swarp_light* light,
                                   const swarp_plane* plane, const swarp_lixel_options* opt, sw_lx_setup* s) {
    s->t = 0.5;
    if (opt) {
        if (!sw_reserved_zero(opt->_reserved, 4)) return SWARP_ERR_RESERVED_NONZERO;
        if (!sw_finite(opt->raise)) return SWARP_ERR_NON_FINITE;
        if (opt->raise < 0.0 || opt->raise >= 1.0) return SWARP_ERR_OUT_OF_RANGE;
        if (opt->raise > 0.0) s->t = opt->raise;
    }
    if (!sw_mat_finite(M_v)) return SWARP_ERR_NON_FINITE;
    if (!sw_finite(plane->a) || !sw_finite(plane->b) || !sw_finite(plane->c) || !sw_finite(plane->d))
        return SWARP_ERR_NON_FINITE;
    if (g < 2 || h < 2) return SWARP_ERR_RESOLUTION;
    s->g = (double)g;
    s->h = (double)h;
    swarp_status st = sw_lixel_light(light, &s->L, &s->d_unit);
    if (st != SWARP_OK) return st;
    double n_len = sw_len(sw_v3(plane->a, plane->b, plane->c));
    if (!(n_len > 0.0)) return SWARP_ERR_ZERO_VECTOR;
    s->pi = sw_v4(plane->a / n_len, plane->b / n_len, plane->c / n_len, plane->d / n_len);
    s->n_unit = sw_v3(s->pi.x, s->pi.y, s->pi.z);
    return SWARP_OK;
}

/* V: world -> viewer pixels [x_v q, y_v q, z_v q, q] as in [LIXEL] §2, and
 * the test that P does not contain the eye (it would image to a line). */
static swarp_status sw_lixel_viewer(const swarp_mat4* M_v, sw_lx_setup* s) {
    swarp_mat4 Vp, V_inv;
    sw_viewport_pixels(s->g, s->h, &Vp);
    sw_mul(&Vp, M_v, &s->V);
    if (!sw_invert(&s->V, &V_inv)) return SWARP_ERR_SINGULAR;
    /* pi' = V^-t pi: the plane in viewer-image space */
    swarp_vec4 pi_img;
    pi_img.x = sw_dot4(s->pi, sw_xform_col(&V_inv, 1, 0, 0, 0));
    pi_img.y = sw_dot4(s->pi, sw_xform_col(&V_inv, 0, 1, 0, 0));
    pi_img.z = sw_dot4(s->pi, sw_xform_col(&V_inv, 0, 0, 1, 0));
    pi_img.w = sw_dot4(s->pi, sw_xform_col(&V_inv, 0, 0, 0, 1));
    /* pi'_z = pi . eye (the eye is V^-1 (0,0,1,0)); compared with the plane
     * in units where pixel coordinates are O(1) */
    double pi_scale = hypot(hypot(pi_img.x * s->g, pi_img.y * s->h), hypot(pi_img.z, pi_img.w));
    if (!(fabs(pi_img.z) > SW_LX_EYE_EPS * pi_scale)) return SWARP_ERR_LIXEL_PLANE_THROUGH_EYE;
    for (int i = 0; i < 4; ++i) s->rows[i] = sw_row4(&s->V, i);
    return SWARP_OK;
}

/* [LIXEL] (2): the four corner pixels and their hit points p^1..p^4 on P;
 * at least one must lie in front of the eye. */
static swarp_status sw_lixel_corners(sw_lx_setup* s) {
    const double px[4] = {0.0, 0.0, s->g - 1.0, s->g - 1.0};
    const double py[4] = {0.0, s->h - 1.0, s->h - 1.0, 0.0};
    s->in_front = 0;
    s->best = -1;
    for (int i = 0; i < 4; ++i) {
        s->px[i] = px[i];
        s->py[i] = py[i];
        s->P[i] = sw_plane_point(s->rows, s->pi, px[i], py[i]);
        if (!sw_finite4(s->P[i])) return SWARP_ERR_SINGULAR;
        if (s->P[i].w > SW_LX_FRONT_EPS) {
            ++s->in_front;
            if (s->best < 0 || s->P[i].w > s->P[s->best].w) s->best = i;
        }
    }
    return s->in_front == 0 ? SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE : SWARP_OK;
}

/* Fig. 2: the raised point p-hat on the ray from the light through p^r.
 * p^4 is raised as in the paper when it lies in front (and not absurdly far
 * compared with the best corner); otherwise the corner most in front, so
 * the raised point sits between the light and the visible part of P.  The
 * light must not lie on P. */
static swarp_status sw_lixel_raise(sw_lx_setup* s) {
    const swarp_vec4* P = s->P;
    s->r = (P[3].w > SW_LX_FRONT_EPS && P[3].w >= SW_LX_RAISE_FAR * P[s->best].w) ? 3 : s->best;
    swarp_vec3 p_r = sw_scale(sw_v3(P[s->r].x, P[s->r].y, P[s->r].z), 1.0 / P[s->r].w);
    const swarp_vec4 L = s->L;
    if (L.w == 0.0) {
        if (fabs(sw_dot(s->n_unit, s->d_unit)) < SW_LX_PARALLEL_EPS) return SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE;
    } else {
        swarp_vec3 l = sw_v3(L.x, L.y, L.z);
        double dist = fabs(sw_dot4(s->pi, L));
        if (!(dist > SW_LX_ON_PLANE_EPS * sw_len(sw_sub(l, p_r)))) return SWARP_ERR_LIXEL_LIGHT_ON_PLANE;
    }
    /* the eye (finite for a perspective viewer) */
    swarp_vec4 E = sw_cross4(sw_unit4(s->rows[0]), sw_unit4(s->rows[1]), sw_unit4(s->rows[3]));
    s->eye_finite = fabs(E.w) > SW_LX_FRONT_EPS * sw_len4(E);
    s->e = s->eye_finite ? sw_scale(sw_v3(E.x, E.y, E.z), 1.0 / E.w) : sw_v3(0, 0, 0);
    if (L.w == 0.0) {
        double d = s->eye_finite ? sw_len(sw_sub(p_r, s->e)) : sw_len(p_r) + 1.0;
        s->p_hat = sw_sub(p_r, sw_scale(s->d_unit, s->t * d));
    } else {
        s->p_hat = sw_add(sw_scale(p_r, 1.0 - s->t), sw_scale(sw_v3(L.x, L.y, L.z), s->t));
    }
    return SWARP_OK;
}

/* [LIXEL] (1), (7)-(10): M_l from five correspondences ((9) read as
 * [(g-1)q, (h-1)q, 1q, q]^t = M_l p^3, papers README): the light to the
 * point at infinity of the depth axis, the corners p^i to their pixels on
 * the far plane, the raised corner's p-hat to the near plane.  Then the
 * sign of +-GLP (Fig. 5): on P the two images agree, so q_l = c q_v for
 * every (homogeneous) point of P; c > 0 makes q_l > 0 exactly on the part
 * of P in front of the viewer.  Returns the solver's status (OK or
 * INFO_LIXEL_ILL_CONDITIONED) or an error. */
static swarp_status sw_lixel_solve(const sw_lx_setup* s, swarp_mat4* M, double* cond) {
    swarp_vec4 src[5], dst[5];
    src[0] = s->L;
    dst[0] = sw_v4(0.0, 0.0, 1.0, 0.0);
    for (int i = 0; i < 4; ++i) {
        src[i + 1] = s->P[i];
        dst[i + 1] = sw_v4(s->px[i], s->py[i], 1.0, 1.0);
    }
    src[s->r + 1] = sw_v4(s->p_hat.x, s->p_hat.y, s->p_hat.z, 1.0);
    dst[s->r + 1].z = -1.0;
    *cond = 0.0;
    swarp_status sst = swarp_lixel_solve5(src, dst, M, cond);
    if (swarp_status_is_error(sst)) return sst;
    double q_l = sw_xform4(M, s->P[s->r]).w, q_v = sw_xform4(&s->V, s->P[s->r]).w;
    if (q_l * q_v < 0.0)
        for (int i = 0; i < 16; ++i) M->m[i] = -M->m[i];
    if (!sw_mat_finite(M)) return SWARP_ERR_SINGULAR;
    return sst;
}

/* The informational status of a solved M_l, most important first.  The
 * view direction is the centre pixel's ray (row0 - c_x row3).X =
 * (row1 - c_y row3).X = 0 (as in sw_plane_point) at infinity, w = 0: the
 * cross product of the two covectors' x, y, z parts, which hold no
 * translation.  Through V^-1 the far point minus the near point would
 * cancel at the eye's magnitude: with the eye 1e6 out, n . v would carry
 * 1e-10 of rounding against SW_LX_VIEW_PARALLEL_EPS, and a plane along the
 * view would be classified by the rounding mode. */
static swarp_status sw_lixel_info_status(const sw_lx_setup* s, swarp_status sst) {
    const swarp_vec4* rows = s->rows;
    const double c_x = 0.5 * (s->g - 1.0), c_y = 0.5 * (s->h - 1.0);
    swarp_vec3 ra, rb, v_unit;
    int view_parallel =
        sw_normalize(sw_v3(rows[0].x - c_x * rows[3].x, rows[0].y - c_x * rows[3].y, rows[0].z - c_x * rows[3].z),
                     &ra) &&
        sw_normalize(sw_v3(rows[1].x - c_y * rows[3].x, rows[1].y - c_y * rows[3].y, rows[1].z - c_y * rows[3].z),
                     &rb) &&
        sw_normalize(sw_cross(ra, rb), &v_unit) && fabs(sw_dot(v_unit, s->n_unit)) < SW_LX_VIEW_PARALLEL_EPS;
    double side_eye = s->eye_finite ? sw_dot4(s->pi, sw_v4(s->e.x, s->e.y, s->e.z, 1.0)) : 0.0;
    double side_light = s->L.w == 0.0 ? -sw_dot(s->n_unit, s->d_unit) : sw_dot4(s->pi, s->L);
    if (sst == SWARP_INFO_LIXEL_ILL_CONDITIONED) return sst;
    if (view_parallel) return SWARP_INFO_LIXEL_PLANE_PARALLEL_VIEW;
    if (s->in_front < 4) return SWARP_INFO_LIXEL_QUAD_ACROSS_INFINITY;
    if (side_eye * side_light < 0.0) return SWARP_INFO_LIXEL_LIGHT_BEHIND_PLANE;
    return SWARP_OK;
}

SWARP_API swarp_status swarp_lixel_matrix(const swarp_mat4* M_v, uint32_t g, uint32_t h,
                                          const swarp_light* light, const swarp_plane* plane,
                                          const swarp_lixel_options* opt, swarp_mat4* out_M_l,
                                          swarp_lixel_info* out_info) {
    if (!M_v || !light || !plane || !out_M_l) return SWARP_ERR_NULL_POINTER;
    sw_lx_setup s;
    swarp_status st = sw_lixel_check(M_v, g, h, light, plane, opt, &s);
    if (st == SWARP_OK) st = sw_lixel_viewer(M_v, &s);
    if (st == SWARP_OK) st = sw_lixel_corners(&s);
    if (st == SWARP_OK) st = sw_lixel_raise(&s);
    if (st != SWARP_OK) return st;
    swarp_mat4 M;
    double cond;
    swarp_status sst = sw_lixel_solve(&s, &M, &cond);
    if (swarp_status_is_error(sst)) return sst;
    swarp_status info = sw_lixel_info_status(&s, sst);
    *out_M_l = M;
    if (out_info) {
        swarp_lixel_info inf;
        memset(&inf, 0, sizeof inf);
        for (int i = 0; i < 4; ++i) inf.corners[i] = s.P[i];
        inf.raised = sw_v4(s.p_hat.x, s.p_hat.y, s.p_hat.z, 1.0);
        inf.raised_index = (uint32_t)s.r;
        inf.corners_in_front = s.in_front;
        inf.conditioning = cond;
        *out_info = inf;
    }
    return info;
}

/* ---- Fig. 6: restriction to the rays C ----------------------------------- */

/* A vertex of C as a homogeneous point: w != 0 is divided out (a point),
 * w = 0 stays a direction from the light. */
static swarp_vec4 sw_ray_vertex(swarp_vec4 c) {
    return c.w != 0.0 ? sw_v4(c.x / c.w, c.y / c.w, c.z / c.w, 1.0) : c;
}

/* Light-image (x, y) of X when q is safely positive. */
static int sw_light_xy(const swarp_mat4* M, swarp_vec4 X, double* x, double* y) {
    swarp_vec4 o = sw_xform4(M, X);
    double q_scale = sw_len4(sw_row4(M, 3)) * sw_len4(X);
    if (!(o.w > SW_LX_Q_EPS * q_scale)) return 0;
    *x = o.x / o.w;
    *y = o.y / o.w;
    return sw_finite(*x) && sw_finite(*y);
}

typedef struct sw_box2 { double lo_x, lo_y, hi_x, hi_y; } sw_box2;

static void sw_box_add(sw_box2* b, double x, double y, double c, double s, double s_x, double s_y) {
    double xt = s_x * (c * x - s * y), yt = s_y * (s * x + c * y);
    b->lo_x = fmin(b->lo_x, xt);
    b->hi_x = fmax(b->hi_x, xt);
    b->lo_y = fmin(b->lo_y, yt);
    b->hi_y = fmax(b->hi_y, yt);
}

/* The x, y, q rows of M as columns P_i (i = 0..3), each scaled by a power
 * of two to a largest entry in [1/2, 1); a vertex X of C is scaled by the
 * inverse (sw_ray_init), which is exact and keeps every product P_i X_i. */
typedef struct sw_lx_cols {
    swarp_vec3 P[4];
    int e[4];
} sw_lx_cols;

static void sw_cols_init(const swarp_mat4* M, sw_lx_cols* pc) {
    for (int i = 0; i < 4; ++i) {
        const swarp_vec3 col = sw_v3(M->m[4 * i], M->m[4 * i + 1], M->m[4 * i + 3]);
        int e = 0;
        const double big = fmax(fabs(col.x), fmax(fabs(col.y), fabs(col.z)));
        if (big > 0.0) (void)frexp(big, &e);
        pc->P[i] = sw_v3(ldexp(col.x, -e), ldexp(col.y, -e), ldexp(col.z, -e));
        pc->e[i] = e;
    }
}

/* A vertex of C: its ray X (sw_ray_init) and the unit light-image vector
 * a = (x q, y q, q) / |.| of it (any positive scale describes the same ray
 * of the convex cone). */
typedef struct sw_lx_ray {
    double X[4];
    swarp_vec3 a;
} sw_lx_ray;

/* Binary exponent of the largest entry of a scaled ray X (sw_ray_init). */
#define SW_LX_RAY_EXP 500

/* X is the ray of sw_ray_vertex without its division (w made >= 0), its
 * entries times 2^e_i of the columns, then all by one power of two to a
 * largest entry in [2^499, 2^500): a term p_ik (P_i x P_k) of sw_edge_line is
 * below 2^1003, and entries down to 2^-500 of the largest keep their
 * products normal.  Neither M (lixel_matrix's is normalised, a caller's
 * need not be) nor C near DBL_MAX overflows, a column of M 1e300 times the
 * others (q ~ w) does not push the others' products below DBL_MIN, and x/w
 * does not overflow for a tiny w. */
static void sw_ray_init(const sw_lx_cols* pc, swarp_vec4 c, sw_lx_ray* r) {
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
    swarp_vec3 o = sw_v3(0.0, 0.0, 0.0);
    for (int i = 0; i < 4; ++i) {
        r->X[i] = ldexp(v[i], pc->e[i] + SW_LX_RAY_EXP - top);
        o = sw_add(o, sw_scale(pc->P[i], r->X[i]));
    }
    double l = sw_len(o);
    if (!(l > 0.0)) l = 1.0;
    /* divided, not scaled by 1/l: the same unit vector in every mode */
    r->a = sw_v3(o.x / l, o.y / l, o.z / l);
}

/* The light-image line of the edge A B of C as a unit covector l on
 * (X, Y, Q), a positive multiple of a x b for their image vectors; 0 when
 * A and B are the same ray (A ^ B = 0).  With P_i the columns (x, y, q
 * rows) of M, (P A) x (P B) = sum_{i<k} (A_i B_k - A_k B_i) P_i x P_k over
 * the Plucker coordinates of the world line A B.  The product of the two
 * image vectors would also round the terms A_i B_i P_i x P_i, zero exactly,
 * at eps |A_i B_i| |P_i|^2: for A and B far out on either side of the
 * origin along one axis (1e38 and 1e31 along x) a and b are antipodal to
 * 1e-30, their x, y parts cancel, and an edge imaging to a line near the
 * view would be lost to rounding.  The Plucker terms keep it
 * (A_x B_z - A_z B_x has no such cancellation). */
static swarp_vec3 sw_edge_line(const sw_lx_cols* pc, const sw_lx_ray* A, const sw_lx_ray* B) {
    swarp_vec3 L = sw_v3(0.0, 0.0, 0.0);
    for (int i = 0; i < 4; ++i)
        for (int k = i + 1; k < 4; ++k) {
            const double p = A->X[i] * B->X[k] - A->X[k] * B->X[i];
            L = sw_add(L, sw_scale(sw_cross(pc->P[i], pc->P[k]), p));
        }
    double len = sw_len(L);
    if (!(len > 0.0) || !sw_finite(len)) len = INFINITY; /* no line: l = 0 */
    return sw_v3(L.x / len, L.y / len, L.z / len);
}

/* The edges of C in order, C[j] C[j + 1] and finally C[n - 1] C[0]: moves
 * B to A and loads the next vertex into B (r0 is C[0], prepared once). */
static void sw_next_edge(const sw_lx_cols* pc, const swarp_vec4* C, size_t n, size_t j, const sw_lx_ray* r0,
                         sw_lx_ray* A, sw_lx_ray* B) {
    *A = *B;
    if (j + 1 < n)
        sw_ray_init(pc, C[j + 1], B);
    else
        *B = *r0;
}

/* Slack allowed when testing a computed intersection against the other
 * rectangle sides (in lixels: far below one). */
#define SW_LX_CLIP_TOL 1e-9

/* l . v of a unit edge line and a vector v is rounded by a few eps |v|_1
 * (3 products, 2 sums, and l's own rounding); within 64 eps |v|_1 it is
 * rounding.  Summed over the n edges of C: n times that. */
#define SW_LX_CONE_FLAT (64.0 * DBL_EPSILON)

/* The orientation of C's cone: +1 when its interior is on the positive side
 * of the edge lines l_j, -1 on the negative side, 0 when the cone is flat to
 * rounding.  For a convex cone every l_j . a_m has that sign or is zero, and
 * so has (sum_j l_j) . a_m, which sums them. */
static int sw_cone_orientation(const sw_lx_cols* pc, const swarp_vec4* C, size_t n) {
    swarp_vec3 N = sw_v3(0.0, 0.0, 0.0);
    sw_lx_ray r0, A, B;
    sw_ray_init(pc, C[0], &r0);
    B = r0;
    for (size_t j = 0; j < n; ++j) {
        sw_next_edge(pc, C, n, j, &r0, &A, &B);
        N = sw_add(N, sw_edge_line(pc, &A, &B));
    }
    double pos = 0.0, neg = 0.0;
    for (size_t m = 0; m < n; ++m) {
        sw_ray_init(pc, C[m], &A);
        const double t = sw_dot(N, A.a);
        pos = fmax(pos, t);
        neg = fmax(neg, -t);
    }
    const double tol = SW_LX_CONE_FLAT * (double)n;
    /* both signs beyond rounding: C is not convex (outside the documented
     * domain), and which vertex is largest is a near tie that the rounding
     * breaks: no orientation, as if flat, so the answer does not depend on
     * the rounding mode */
    if (pos > tol && neg > tol) return 0;
    return pos > tol ? 1 : neg > tol ? -1 : 0;
}

/* The clip of the cone's image to the viewer's pixel centres [0, g - 1] x
 * [0, h - 1], accumulated as a bounding box in the rotated, scaled frame
 * (c, s: the twist; s_x, s_y: the scales). */
typedef struct sw_lx_clip {
    double g, h, c, s, s_x, s_y;
    sw_box2* box;
    int any;
} sw_lx_clip;

static void sw_clip_add(sw_lx_clip* k, double x, double y) {
    sw_box_add(k->box, x, y, k->c, k->s, k->s_x, k->s_y);
    k->any = 1;
}

/* Points (a) and (b) of sw_clipped_box for the edge a b with line l: a
 * inside the rectangle, and the crossings of a b with its sides. */
static void sw_clip_edge(sw_lx_clip* k, swarp_vec3 a, swarp_vec3 b, swarp_vec3 l) {
    /* sides as functionals l(v) >= 0 on v = (X, Y, Q) */
    const swarp_vec3 side[4] = {{1, 0, 0}, {-1, 0, k->g - 1.0}, {0, 1, 0}, {0, -1, k->h - 1.0}};
    double la[4], lb[4];
    int inside_a = a.z > 0.0;
    for (int q = 0; q < 4; ++q) {
        la[q] = sw_dot(side[q], a);
        lb[q] = sw_dot(side[q], b);
        if (la[q] < 0.0) inside_a = 0;
    }
    if (inside_a) sw_clip_add(k, a.x / a.z, a.y / a.z); /* (a) */
    for (int q = 0; q < 4; ++q) { /* (b) */
        if (!((la[q] < 0.0 && lb[q] > 0.0) || (la[q] > 0.0 && lb[q] < 0.0))) continue;
        /* the crossing (lb a - la b)/(lb - la): a combination with weights
         * in [0, 1], which for a . b >= 0 cancels nothing; for a and b
         * (nearly) antipodal it cancels to the rounding, and is formed as
         * (s_q x (a x b))/(lb - la) ((a x b) x s = (a.s) b - (b.s) a) from
         * l, a positive multiple of a x b (sw_edge_line) */
        const double ta = lb[q] / (lb[q] - la[q]), tb = -la[q] / (lb[q] - la[q]);
        swarp_vec3 v = sw_v3(ta * a.x + tb * b.x, ta * a.y + tb * b.y, ta * a.z + tb * b.z);
        if (sw_dot(a, b) < 0.0) {
            v = sw_cross(side[q], l);
            if (lb[q] - la[q] < 0.0) v = sw_v3(-v.x, -v.y, -v.z);
        }
        if (!(v.z > 0.0)) continue;
        double x = v.x / v.z, y = v.y / v.z;
        if (x < -SW_LX_CLIP_TOL || x > k->g - 1.0 + SW_LX_CLIP_TOL || y < -SW_LX_CLIP_TOL ||
            y > k->h - 1.0 + SW_LX_CLIP_TOL)
            continue;
        sw_clip_add(k, x, y);
    }
}

/* Points (c) of sw_clipped_box: corner K inside the cone when every edge
 * sees it on the side of the interior vector S (the sum of the unit vertex
 * vectors).  Where l_j . S is within rounding (SW_LX_CONE_FLAT) S lies on
 * the edge's plane and its side is the rounding's: two a_m antipodal to
 * 1e-30 (vertices 1e38 and 1e31 out on either side along one axis) cancel
 * in S, which then lies on the planes of the edges to the third vertex, and
 * a fat cone would be taken for flat.  Such an edge takes the cone's
 * orientation instead.  A cone flat to rounding (orientation 0: e.g. a
 * cluster of rays and one direction at q = 0, a wedge of width 1e-76) has
 * no inside: its clipped image is a segment whose ends are (a) or (b)
 * points, a corner on it adds nothing, and one off it is out (the sign of
 * the rounding noise must not put a corner far off the wedge inside). */
static void sw_clip_corners(sw_lx_clip* k, const sw_lx_cols* pc, const swarp_vec4* C, size_t n,
                            const sw_lx_ray* r0, swarp_vec3 S) {
    const double kx[4] = {0.0, k->g - 1.0, k->g - 1.0, 0.0}, ky[4] = {0.0, 0.0, k->h - 1.0, k->h - 1.0};
    const double s_norm = fabs(S.x) + fabs(S.y) + fabs(S.z);
    int inside[4] = {n >= 3, n >= 3, n >= 3, n >= 3};
    int orient = 2; /* not yet known */
    sw_lx_ray A, B = *r0;
    for (size_t j = 0; j < n && (inside[0] || inside[1] || inside[2] || inside[3]); ++j) {
        sw_next_edge(pc, C, n, j, r0, &A, &B);
        const swarp_vec3 l = sw_edge_line(pc, &A, &B);
        const double dS = sw_dot(l, S);
        const int flat = !(fabs(dS) > SW_LX_CONE_FLAT * s_norm);
        if (flat && orient == 2) orient = sw_cone_orientation(pc, C, n);
        for (int q = 0; q < 4; ++q) {
            const double dK = sw_dot(l, sw_v3(kx[q], ky[q], 1.0));
            if (flat ? orient == 0 || orient * dK < 0.0 : dS * dK < 0.0) inside[q] = 0;
        }
    }
    for (int q = 0; q < 4; ++q)
        if (inside[q]) sw_clip_add(k, kx[q], ky[q]);
}

/* The bounding box of (image of the cone C) clipped to the viewer's pixel
 * centres [0, g - 1] x [0, h - 1] (one lixel per pixel needs no more),
 * without storing the clipped polygon:
 * its vertices are (a) vertices of C inside, (b) edges of C crossing a
 * side of the rectangle, (c) rectangle corners inside the cone.  All tests
 * are linear in the homogeneous vectors, so rays with q <= 0 need no case.
 * Returns 0 when the clipped set is empty. */
static int sw_clipped_box(const swarp_mat4* M, const swarp_vec4* C, size_t n, double g, double h, double c,
                          double s, double s_x, double s_y, sw_box2* box) {
    sw_lx_clip k = {g, h, c, s, s_x, s_y, box, 0};
    swarp_vec3 S = sw_v3(0, 0, 0);
    sw_lx_cols pc;
    sw_cols_init(M, &pc);
    sw_lx_ray r0, A, B;
    sw_ray_init(&pc, C[0], &r0);
    B = r0;
    for (size_t j = 0; j < n; ++j) {
        sw_next_edge(&pc, C, n, j, &r0, &A, &B);
        const swarp_vec3 l = sw_edge_line(&pc, &A, &B);
        S = sw_add(S, A.a);
        sw_clip_edge(&k, A.a, B.a, l);
    }
    sw_clip_corners(&k, &pc, C, n, &r0, S);
    return k.any && sw_finite(box->lo_x) && sw_finite(box->hi_x) && sw_finite(box->lo_y) && sw_finite(box->hi_y);
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
        if (!sw_finite4(C[j])) return SWARP_ERR_NON_FINITE;
    /* A_l without the translation: scale . rotate(twist) on (x, y) */
    double c = cos(twist), s = sin(twist);
    sw_box2 box = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    if (view_w > 0) {
        if (!sw_clipped_box(M_l, C, n, (double)view_w, (double)view_h, c, s, s_x, s_y, &box))
            return SWARP_ERR_LIXEL_EMPTY;
    } else {
        for (size_t j = 0; j < n; ++j) {
            double x, y;
            /* all rays of C must be in the light frustum (q > 0); then the
             * image of the convex set is the hull of the vertex images */
            if (!sw_light_xy(M_l, sw_ray_vertex(C[j]), &x, &y)) return SWARP_ERR_LIXEL_RAY_OUTSIDE;
            sw_box_add(&box, x, y, c, s, s_x, s_y);
        }
    }
    double lo_x = box.lo_x, lo_y = box.lo_y, hi_x = box.hi_x, hi_y = box.hi_y;
    /* integer (lixel-centre) corners enclosing the image; a value within
     * SW_LX_SNAP of an integer snaps to it (rounding noise of ~1e-12 lixel
     * must not add a row: the clip volume reaches half a lixel beyond the
     * centres anyway, so nothing is lost) */
    double x0 = floor(lo_x + SW_LX_SNAP), x1 = ceil(hi_x - SW_LX_SNAP), y0 = floor(lo_y + SW_LX_SNAP),
           y1 = ceil(hi_y - SW_LX_SNAP);
    if (!(x1 - x0 + 1.0 <= (double)max_size) || !(y1 - y0 + 1.0 <= (double)max_size) ||
        !(fabs(x0) < SW_LX_RECT_MAX_COORD) || !(fabs(x1) < SW_LX_RECT_MAX_COORD) ||
        !(fabs(y0) < SW_LX_RECT_MAX_COORD) || !(fabs(y1) < SW_LX_RECT_MAX_COORD))
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
#define SW_LX_TWIST_EPS 1e-12

SWARP_API swarp_status swarp_lixel_twist_for_line(const swarp_mat4* M_l, const swarp_vec3* a,
                                                  const swarp_vec3* b, const swarp_vec3* below,
                                                  double* out_twist) {
    if (!M_l || !a || !b || !below || !out_twist) return SWARP_ERR_NULL_POINTER;
    if (!sw_mat_finite(M_l) || !sw_finite3(a) || !sw_finite3(b) || !sw_finite3(below)) return SWARP_ERR_NON_FINITE;
    double xa, ya, xb, yb, xc, yc;
    if (!sw_light_xy(M_l, sw_v4(a->x, a->y, a->z, 1.0), &xa, &ya) ||
        !sw_light_xy(M_l, sw_v4(b->x, b->y, b->z, 1.0), &xb, &yb) ||
        !sw_light_xy(M_l, sw_v4(below->x, below->y, below->z, 1.0), &xc, &yc))
        return SWARP_ERR_LIXEL_TWIST_LINE;
    double dx = xb - xa, dy = yb - ya;
    double scale = fmax(fmax(fabs(xa), fabs(ya)), fmax(fabs(xb), fabs(yb))) + 1.0;
    if (!(hypot(dx, dy) > SW_LX_TWIST_EPS * scale)) return SWARP_ERR_LIXEL_TWIST_LINE;
    /* rotate by -angle(line): the line becomes horizontal */
    double twist = -atan2(dy, dx);
    /* the rotated y of `below` relative to the line must be negative */
    double c = cos(twist), s = sin(twist);
    double rel = s * (xc - xa) + c * (yc - ya);
    /* `below` on the line (its distance within SW_LX_TWIST_EPS of the image
     * scale, as for the line's length above) has no side: the sign of rel
     * would be the rounding's, and the twist would flip by pi with the
     * caller's rounding mode (e.g. b and below on a line parallel to x, a at
     * 1e97 on x imaging to its vanishing point, below 5e-17 lixel off the
     * line in exact arithmetic) */
    const double scale_c = fmax(scale, fmax(fabs(xc), fabs(yc)) + 1.0);
    if (!(fabs(rel) > SW_LX_TWIST_EPS * scale_c)) return SWARP_ERR_LIXEL_TWIST_LINE;
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
    if (!sw_light_depth_range_ok(depth_range)) return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_finite(plane_depth) || !sw_mat_finite(M_l)) return SWARP_ERR_NON_FINITE;
    if (plane_depth < 0.0 || plane_depth >= 1.0) return SWARP_ERR_OUT_OF_RANGE;
    double f = plane_depth > 0.0 ? plane_depth : 0.5;
    double W = (double)width, H = (double)height;
    swarp_vec4 X = sw_row4(M_l, 0), Y = sw_row4(M_l, 1), Z = sw_row4(M_l, 2), Q = sw_row4(M_l, 3);
    /* depth z' = alpha z + beta: p-hat (z = -1) to the near plane, P (z = 1)
     * to the fraction f of the range ([LIXEL] footnote: any affine map of z) */
    double alpha, beta;
    if (depth_range == SWARP_DEPTH_ZERO_TO_ONE) {
        alpha = 0.5 * f;
        beta = 0.5 * f;
    } else if (depth_range == SWARP_DEPTH_REVERSED_ZERO_TO_ONE) {
        /* the [0, 1] row turned over, z' = w - z'_[0,1] (common/depth_range.h):
         * p-hat to 1 (the near plane), P to 1 - f */
        alpha = -0.5 * f;
        beta = 1.0 - 0.5 * f;
    } else {
        alpha = f;
        beta = f - 1.0;
    }
    swarp_mat4 P, Vw;
    /* x_ndc = (2 x + 1)/W - 1: lixel centres 0 .. W-1 inside (-1, 1) */
    sw_set_row4(&P, 0, sw_v4(2.0 / W * X.x + (1.0 / W - 1.0) * Q.x, 2.0 / W * X.y + (1.0 / W - 1.0) * Q.y,
                            2.0 / W * X.z + (1.0 / W - 1.0) * Q.z, 2.0 / W * X.w + (1.0 / W - 1.0) * Q.w));
    sw_set_row4(&P, 1, sw_v4(2.0 / H * Y.x + (1.0 / H - 1.0) * Q.x, 2.0 / H * Y.y + (1.0 / H - 1.0) * Q.y,
                            2.0 / H * Y.z + (1.0 / H - 1.0) * Q.z, 2.0 / H * Y.w + (1.0 / H - 1.0) * Q.w));
    sw_set_row4(&P, 2, sw_v4(alpha * Z.x + beta * Q.x, alpha * Z.y + beta * Q.y, alpha * Z.z + beta * Q.z,
                            alpha * Z.w + beta * Q.w));
    sw_set_row4(&P, 3, Q);
    sw_viewport_pixels(W, H, &Vw);
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
#define SW_LX_SPLIT_EPS 1e-9
/* Added to the light-to-line distance: a floor for the scale of the
 * SW_LX_SPLIT_EPS test, so a light at the line's point A itself (distance
 * 0) does not pass with a subnormal |n_Sigma| of pure rounding. */
#define SW_LX_TINY 1e-300

/* Sutherland-Hodgman against side(X) = sign * Sigma.X >= 0; writes at most
 * n + 1 vertices when out != NULL, returns the count. */
static size_t sw_clip_side(const swarp_vec4* C, size_t n, swarp_vec4 Sigma, double sign, swarp_vec4* out) {
    size_t m = 0;
    for (size_t j = 0; j < n; ++j) {
        swarp_vec4 A = sw_ray_vertex(C[j]), B = sw_ray_vertex(C[(j + 1) % n]);
        double sa = sign * sw_dot4(Sigma, A), sb = sign * sw_dot4(Sigma, B);
        if (sa >= 0.0) {
            if (out) out[m] = A;
            ++m;
        }
        if ((sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)) {
            /* the point of segment AB on Sigma: (sa B - sb A)/(sa - sb) */
            double ta = -sb / (sa - sb), tb = sa / (sa - sb);
            if (out)
                out[m] = sw_v4(ta * A.x + tb * B.x, ta * A.y + tb * B.y, ta * A.z + tb * B.z, ta * A.w + tb * B.w);
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
    swarp_status st = sw_lixel_light(light, &L, &d_unit);
    if (st != SWARP_OK) return st;
    const swarp_plane* pl[2] = {floor_plane, wall_plane};
    for (int k = 0; k < 2; ++k)
        if (!sw_finite(pl[k]->a) || !sw_finite(pl[k]->b) || !sw_finite(pl[k]->c) || !sw_finite(pl[k]->d))
            return SWARP_ERR_NON_FINITE;
    int kind = -1; /* 1: points, 0: directions */
    for (size_t j = 0; j < n; ++j) {
        if (!sw_finite4(C_tot[j])) return SWARP_ERR_NON_FINITE;
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
    if (!(sqrt(uu) > SW_LX_SPLIT_EPS)) return SWARP_ERR_DEGENERATE;
    swarp_vec3 A = sw_scale(sw_add(sw_scale(sw_cross(nw, u), hf), sw_scale(sw_cross(u, nf), hw)), 1.0 / uu);
    /* Sigma: the plane through the light and the line */
    swarp_vec3 n_sigma = L.w == 0.0 ? sw_cross(u, d_unit) : sw_cross(u, sw_sub(sw_v3(L.x, L.y, L.z), A));
    double ls = sw_len(n_sigma);
    double lscale = L.w == 0.0 ? 1.0 : sw_len(sw_sub(sw_v3(L.x, L.y, L.z), A)) + SW_LX_TINY;
    if (!(ls > SW_LX_SPLIT_EPS * lscale)) return SWARP_ERR_DEGENERATE; /* light on the line / along it */
    n_sigma = sw_scale(n_sigma, 1.0 / ls);
    swarp_vec4 Sigma = sw_v4(n_sigma.x, n_sigma.y, n_sigma.z, -sw_dot(n_sigma, A));
    /* a floor point in front of the wall (on the side its normal points to):
     * F = A + w_f / |w_f|, so Σ · F = n_Σ · w_f / |w_f| -- formed from the
     * unit vectors, not as n_Σ · F - n_Σ · A: with the line 1e6 from the
     * origin that difference carries 1e-10 of rounding against the
     * SW_LX_SPLIT_EPS bound, and the rounding mode would decide DEGENERATE */
    swarp_vec3 w_f = sw_sub(nw, sw_scale(nf, sw_dot(nw, nf)));
    double side_floor = sw_dot(n_sigma, w_f) / sw_len(w_f);
    if (!(fabs(side_floor) > SW_LX_SPLIT_EPS)) return SWARP_ERR_DEGENERATE; /* light on the floor */
    double sign = side_floor > 0.0 ? 1.0 : -1.0;
    size_t need_f = sw_clip_side(C_tot, n, Sigma, sign, NULL);
    size_t need_w = sw_clip_side(C_tot, n, Sigma, -sign, NULL);
    if (need_f > floor_capacity || need_w > wall_capacity) {
        *out_floor_count = need_f;
        *out_wall_count = need_w;
        return SWARP_ERR_CAPACITY;
    }
    sw_clip_side(C_tot, n, Sigma, sign, out_floor);
    sw_clip_side(C_tot, n, Sigma, -sign, out_wall);
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
