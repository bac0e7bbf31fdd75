/* A swarp_camera from an engine's view and projection matrices: read the
 * matrices into the library's form (column vectors, right-handed view space
 * looking down -z), check that the view is rigid and the projection
 * perspective, then read eye, dir, up from the view and fovy, aspect, near
 * and far from the projection.  An infinite far plane is bounded by the
 * scene box ([RHS] §3.3.1). */
#include "common/swarp_internal.h"

/* A 3x3 determinant this small relative to the product of the row lengths
 * (|det| <= |r0||r1||r2| by Hadamard's inequality) leaves no direction: the
 * rows are parallel to the rounding of double. */
#define SW_CAMERA_SINGULAR_REL 1e-12

/* Element (r, c) of the column-vector matrix the convention's numbers hold,
 * with the left-handed view's z negated: S = diag(1, 1, -1, 1) maps a
 * left-handed view space (looking down +z) to the right-handed one, so the
 * view becomes S V and the projection P S (P V = (P S)(S V)). */
static void sw_engine_matrix(const swarp_mat4* in, swarp_matrix_convention c, int is_view, double out[4][4]) {
    const int transposed = (c == SWARP_MATRIX_RH_TRANSPOSED || c == SWARP_MATRIX_LH_TRANSPOSED);
    const int lh = (c == SWARP_MATRIX_LH || c == SWARP_MATRIX_LH_TRANSPOSED);
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) out[r][k] = transposed ? in->m[r * 4 + k] : in->m[k * 4 + r];
    if (!lh) return;
    for (int k = 0; k < 4; ++k) {
        if (is_view)
            out[2][k] = -out[2][k];
        else
            out[k][2] = -out[k][2];
    }
}

static double sw_det3(const double a[4][4]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

static swarp_vec3 sw_row3(const double a[4][4], int r) { return sw_v3(a[r][0], a[r][1], a[r][2]); }

/* The view V = [R t; 0 w]: w > 0 with a zero bottom row (affine; a lookAt
 * and every product of rigid matrices give these exactly), R a rotation
 * with rows orthonormal to SWARP_CAMERA_RIGID_TOL.  det R is taken in the
 * engine's own handedness (lh_sign = -1 undoes the z flip), where a
 * proper view matrix has det +1: det < 0 is a mirror. */
static swarp_status sw_view_check(const double V[4][4], double lh_sign) {
    if (V[3][0] != 0.0 || V[3][1] != 0.0 || V[3][2] != 0.0 || !(V[3][3] > 0.0))
        return SWARP_ERR_CAMERA_VIEW_NOT_RIGID;
    const double det = lh_sign * sw_det3(V);
    const double scale = sw_len(sw_row3(V, 0)) * sw_len(sw_row3(V, 1)) * sw_len(sw_row3(V, 2));
    if (!sw_finite(det) || !(fabs(det) > SW_CAMERA_SINGULAR_REL * scale)) return SWARP_ERR_SINGULAR;
    if (det < 0.0) return SWARP_ERR_CAMERA_MIRRORED;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double g = sw_dot(sw_row3(V, i), sw_row3(V, j)) / (V[3][3] * V[3][3]);
            if (!(fabs(g - (i == j ? 1.0 : 0.0)) <= SWARP_CAMERA_RIGID_TOL)) return SWARP_ERR_CAMERA_VIEW_NOT_RIGID;
        }
    return SWARP_OK;
}

/* eye solves R eye + t = 0 (Cramer's rule: exact for a nearly orthonormal R,
 * where R^T t would carry R's departure from orthonormality into eye); dir
 * is the world direction of view -z, up that of view +y. */
static void sw_view_camera(const double V[4][4], swarp_camera* cam) {
    const double det = sw_det3(V);
    double eye[3];
    for (int k = 0; k < 3; ++k) {
        double a[4][4];
        memcpy(a, V, sizeof a);
        for (int r = 0; r < 3; ++r) a[r][k] = -V[r][3];
        eye[k] = sw_det3(a) / det;
    }
    cam->eye = sw_v3(eye[0], eye[1], eye[2]);
    cam->dir = sw_scale(sw_row3(V, 2), -1.0);
    cam->up = sw_row3(V, 1);
}

/* The projection, divided by k = -P[3][2] > 0 so that w = -z_view = d. */
typedef struct sw_persp {
    double sx, sy, ox, oy; /* x_ndc = sx x/d - ox, y likewise */
    double A, B;           /* z_ndc = -A + B/d */
    double tx, ty;         /* tan of the half angles of the symmetric frustum containing it */
} sw_persp;

static swarp_status sw_persp_read(const double P[4][4], sw_persp* p) {
    const double k = -P[3][2];
    if (P[3][2] == 0.0) return SWARP_ERR_CAMERA_NOT_PERSPECTIVE; /* orthographic: w = P[3][3] */
    if (!(k > 0.0)) return SWARP_ERR_CAMERA_MIRRORED;            /* w > 0 behind the eye */
    p->sx = P[0][0] / k, p->sy = P[1][1] / k;
    p->ox = P[0][2] / k, p->oy = P[1][2] / k;
    p->A = P[2][2] / k, p->B = P[2][3] / k;
    if (!sw_finite(p->sx) || !sw_finite(p->sy) || !sw_finite(p->A) || !sw_finite(p->B) || !sw_finite(p->ox) ||
        !sw_finite(p->oy))
        return SWARP_ERR_SINGULAR;
    if (p->sx == 0.0 || p->sy == 0.0 || p->B == 0.0) return SWARP_ERR_SINGULAR;
    p->tx = (1.0 + fabs(p->ox)) / fabs(p->sx);
    p->ty = (1.0 + fabs(p->oy)) / fabs(p->sy);
    if (!sw_finite(p->tx) || !sw_finite(p->ty)) return SWARP_ERR_SINGULAR;
    return SWARP_OK;
}

/* The entries a perspective projection has zero, each weighted by the
 * largest |x/d|, |y/d| (tx, ty) or 1/near it multiplies over the frustum:
 * their sum is how far they can move NDC (the w row relative to w = d). */
static int sw_persp_strays_ok(const double P[4][4], const sw_persp* p, double near) {
    const double k = -P[3][2];
    const double wx[4] = {p->tx, p->ty, 0.0, 1.0 / near};
    const double stray[4][4] = {{0, 1, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 0}, {1, 1, 0, 1}};
    for (int r = 0; r < 4; ++r) {
        double s = 0.0;
        for (int c = 0; c < 4; ++c)
            if (stray[r][c]) s += fabs(P[r][c] / k) * wx[c];
        if (!(s <= SWARP_CAMERA_STRAY_NDC)) return 0;
    }
    return 1;
}

/* near, far from z_ndc(d) = -A + B/d: the end of the range depth takes at
 * near is zlo forward (B < 0: z grows with d) and zhi reversed.  The far
 * end is reached at d = B/(z_far_ndc + A); a denominator of the wrong sign
 * (or zero, or a quotient that overflows) within SWARP_CAMERA_STRAY_NDC
 * means depth reaches the end only at infinity (A = -1 forward, A = 0
 * reversed [0, 1]: the infinite projections). */
static swarp_status sw_persp_depth(const sw_persp* p, double zlo, double zhi, double* near, double* far,
                                   int* reversed, int* infinite) {
    *reversed = p->B > 0.0;
    const double zn = *reversed ? zhi : zlo, zf = *reversed ? zlo : zhi;
    const double n = p->B / (zn + p->A);
    if (!sw_finite(n) || !(n > 0.0)) return SWARP_ERR_NEAR_FAR;
    const double den = zf + p->A;
    const double f = p->B / den;
    *infinite = !(sw_finite(f) && f > n);
    if (*infinite && !(fabs(den) <= SWARP_CAMERA_STRAY_NDC)) return SWARP_ERR_NEAR_FAR;
    *near = n;
    *far = *infinite ? INFINITY : f;
    return SWARP_OK;
}

/* [RHS] §3.3.1 bounds the view by H = V ∩ S; H lies in S, so the largest
 * view depth of S's corners bounds H's. */
static swarp_status sw_far_from_scene(const swarp_camera* cam, const swarp_aabb* S, double* far) {
    swarp_vec3 f;
    if (!sw_normalize(cam->dir, &f)) return SWARP_ERR_SINGULAR;
    double mx = -INFINITY;
    for (int i = 0; i < 8; ++i) {
        swarp_vec3 c = sw_v3(i & 1 ? S->max.x : S->min.x, i & 2 ? S->max.y : S->min.y, i & 4 ? S->max.z : S->min.z);
        mx = fmax(mx, sw_dot(sw_sub(c, cam->eye), f));
    }
    if (!sw_finite(mx)) return SWARP_ERR_OVERFLOW;
    if (!(mx > cam->z_near)) return SWARP_ERR_BODY_EMPTY;
    *far = mx;
    return SWARP_OK;
}

static swarp_status sw_camera_args(const swarp_mat4* view, const swarp_mat4* proj, swarp_matrix_convention c,
                                   swarp_depth_range dr, const swarp_aabb* scene) {
    if ((uint32_t)c > (uint32_t)SWARP_MATRIX_LH_TRANSPOSED) return SWARP_ERR_UNKNOWN_ENUM;
    if (dr != SWARP_DEPTH_DEFAULT && dr != SWARP_DEPTH_NEG_ONE_TO_ONE && dr != SWARP_DEPTH_ZERO_TO_ONE &&
        dr != SWARP_DEPTH_REVERSED_ZERO_TO_ONE)
        return SWARP_ERR_UNKNOWN_ENUM;
    if (!sw_mat_finite(view) || !sw_mat_finite(proj)) return SWARP_ERR_NON_FINITE;
    return scene ? sw_check_box(scene) : SWARP_OK;
}

SWARP_API swarp_status swarp_camera_from_matrices(const swarp_mat4* view, const swarp_mat4* projection,
                                                  swarp_matrix_convention convention,
                                                  swarp_depth_range depth_range, const swarp_aabb* scene,
                                                  swarp_camera* out_cam, swarp_camera_from_info* out_info) {
    if (!view || !projection || !out_cam) return SWARP_ERR_NULL_POINTER;
    swarp_status s = sw_camera_args(view, projection, convention, depth_range, scene);
    if (s != SWARP_OK) return s;
    double V[4][4], P[4][4];
    sw_engine_matrix(view, convention, 1, V);
    sw_engine_matrix(projection, convention, 0, P);
    const int lh = (convention == SWARP_MATRIX_LH || convention == SWARP_MATRIX_LH_TRANSPOSED);
    s = sw_view_check(V, lh ? -1.0 : 1.0);
    if (s != SWARP_OK) return s;
    sw_persp p;
    s = sw_persp_read(P, &p);
    if (s != SWARP_OK) return s;
    const double zlo = (depth_range == SWARP_DEPTH_DEFAULT || depth_range == SWARP_DEPTH_NEG_ONE_TO_ONE) ? -1.0 : 0.0;
    double near, far;
    int reversed, infinite;
    s = sw_persp_depth(&p, zlo, 1.0, &near, &far, &reversed, &infinite);
    if (s != SWARP_OK) return s;
    if (!sw_persp_strays_ok(P, &p, near)) return SWARP_ERR_CAMERA_NOT_PERSPECTIVE;
    swarp_camera cam;
    memset(&cam, 0, sizeof cam);
    sw_view_camera(V, &cam);
    cam.fovy = 2.0 * atan(p.ty);
    cam.aspect = p.tx / p.ty;
    cam.z_near = near;
    cam.z_far = far;
    if (!sw_finite3(&cam.eye) || !(cam.aspect > 0.0) || !sw_finite(cam.aspect)) return SWARP_ERR_OVERFLOW;
    if (infinite) {
        if (!scene) return SWARP_ERR_CAMERA_FAR_UNBOUNDED;
        s = sw_far_from_scene(&cam, scene, &cam.z_far);
        if (s != SWARP_OK) return s;
    }
    s = sw_check_camera(&cam);
    if (s != SWARP_OK) return s;
    *out_cam = cam;
    if (out_info) {
        out_info->reversed_z = (uint32_t)reversed;
        out_info->infinite_far = (uint32_t)infinite;
        out_info->off_center_x = p.ox;
        out_info->off_center_y = p.oy;
    }
    return infinite ? SWARP_INFO_CAMERA_FAR_FROM_SCENE : SWARP_OK;
}
