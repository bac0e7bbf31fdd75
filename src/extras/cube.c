/* Extras: [KOZ] §14.2.2 "Using Cube Maps" -- cube-map faces on the unit
 * cube's back faces in post-projective space, their matrices, and the
 * texture coordinate / depth computation of [KOZ] Listing 14-1.
 *
 * Face i of the unit cube [-1, 1]^3 has outward normal N_i and lies in the
 * plane x . N_i = 1.  From the light P its distance is d_i = 1 - P . N_i; the
 * face is back-facing (the light's rays leave the cube through it) iff
 * d_i > 0.  Face i's camera sits at P, looks along N_i, has the face square
 * at its far plane d_i and its near plane at Z_1 d_i ("another small cube").
 */
#include "common/depth_range.h"

/* Default Z_1 = Z_n/Z_f of the face cameras: a near cube 1/100 the size of
 * the unit cube around the light, as small as 24-bit depth comfortably
 * allows for the [KOZ] ratios (Z_f/Z_n = 100). */
#define SW_CUBE_DEFAULT_Z1 0.01
/* A light position beyond this (any component) counts as at infinity: its
 * products with the face distances would overflow the matrices. */
#define SW_CUBE_LIGHT_FAR 1e150

_Static_assert(sizeof(swarp_cube_face) == 8 + 8 + 3 * sizeof(swarp_vec3) + 3 * sizeof(swarp_mat4),
               "swarp_cube_face size");

/* normal and up of each face, SWARP_CUBE_FACE_* order; right = up x (-normal) */
static const double sw_cube_normal[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                            {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
static const double sw_cube_up[6][3] = {{0, 1, 0}, {0, 1, 0}, {0, 0, 1},
                                        {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

typedef struct sw_cube_setup {
    swarp_vec3 P;   /* light position in post-projective space */
    int inverse;    /* w < 0: inverse-projection variant */
    double z1;      /* Z_1 */
    int zero_to_one;
    int reversed;   /* reversed-Z: the [0, 1] faces with z/w turned to 1 - z/w */
    double d[6];    /* distance to each face plane; back-facing iff > 0 */
} sw_cube_setup;

static swarp_status sw_cube_setup_make(const swarp_vec4* L, const swarp_cube_options* opt,
                                       sw_cube_setup* s) {
    if (!L) return SWARP_ERR_NULL_POINTER;
    double z1 = SW_CUBE_DEFAULT_Z1;
    int zo = 0, rev = 0;
    if (opt) {
        if (!sw_reserved_zero(opt->_reserved, 5)) return SWARP_ERR_RESERVED_NONZERO;
        if (isnan(opt->z1) || isinf(opt->z1)) return SWARP_ERR_NON_FINITE;
        if (opt->z1 != 0.0) {
            if (!(opt->z1 > 0.0 && opt->z1 < 1.0)) return SWARP_ERR_OUT_OF_RANGE;
            z1 = opt->z1;
        }
        switch (opt->depth_range) {
            case SWARP_DEPTH_DEFAULT:
            case SWARP_DEPTH_NEG_ONE_TO_ONE: zo = 0; break;
            case SWARP_DEPTH_ZERO_TO_ONE: zo = 1; break;
            case SWARP_DEPTH_REVERSED_ZERO_TO_ONE: zo = 1, rev = 1; break;
            default: return SWARP_ERR_UNKNOWN_ENUM;
        }
    }
    if (!sw_finite(L->x) || !sw_finite(L->y) || !sw_finite(L->z) || !sw_finite(L->w))
        return SWARP_ERR_NON_FINITE;
    if (L->w == 0.0) return SWARP_ERR_CUBE_LIGHT_AT_INFINITY;
    s->P = sw_v3(L->x / L->w, L->y / L->w, L->z / L->w);
    /* |P| so large that d_i * P overflows the matrices: a light at infinity */
    if (!sw_finite3(&s->P) || fabs(s->P.x) > SW_CUBE_LIGHT_FAR || fabs(s->P.y) > SW_CUBE_LIGHT_FAR ||
        fabs(s->P.z) > SW_CUBE_LIGHT_FAR)
        return SWARP_ERR_CUBE_LIGHT_AT_INFINITY;
    s->inverse = L->w < 0.0;
    s->z1 = z1;
    s->zero_to_one = zo;
    s->reversed = rev;
    for (int i = 0; i < 6; ++i) {
        swarp_vec3 N = sw_v3(sw_cube_normal[i][0], sw_cube_normal[i][1], sw_cube_normal[i][2]);
        s->d[i] = 1.0 - sw_dot(s->P, N);
    }
    return SWARP_OK;
}

/* NDC depth of a point at face-eye depth e (> 0 in front of the camera):
 * z_ndc = alpha + beta / e with the near plane at -1 (or 0) and far at 1.
 * In ratio form, with n and f the multiples Z_n/Z_f of d: alpha depends on
 * Z_1 only and beta = bd d.  The textbook (f + n)/(f - n) with n = Z_1 d
 * rounded first loses up to eps/(1 - Z_1) of alpha (f - n cancels for Z_1
 * near 1), a loss the caller's rounding mode decides (alpha ~ 2e9 would
 * move by 2e-7 relative between rounding upward and to nearest); here
 * 1 - Z_1 is exact for Z_1 >= 1/2 (Sterbenz) and alpha, bd carry a few eps.
 *   regular  n = Z_1, f = 1:  alpha = (1 + Z_1)/(1 - Z_1), bd = -2 Z_1/(1 - Z_1)
 *                             ([0, 1]: 1/(1 - Z_1), -Z_1/(1 - Z_1))
 *   inverse  n = -Z_1, f = Z_1: alpha = 0, bd = Z_1  ([0, 1]: 1/2, Z_1/2) */
static void sw_cube_depth_ratio(const sw_cube_setup* s, double* alpha, double* bd) {
    const double z1 = s->z1;
    if (s->inverse) {
        *alpha = s->zero_to_one ? 0.5 : 0.0;
        *bd = s->zero_to_one ? 0.5 * z1 : z1;
    } else {
        const double m = 1.0 - z1;
        *alpha = s->zero_to_one ? 1.0 / m : (1.0 + z1) / m;
        *bd = s->zero_to_one ? -z1 / m : -2.0 * z1 / m;
    }
}
static void sw_cube_depth_coeffs(const sw_cube_setup* s, double d, double* alpha, double* beta) {
    double bd;
    sw_cube_depth_ratio(s, alpha, &bd);
    *beta = bd * d;
}

static void sw_cube_face_make(const sw_cube_setup* s, int i, swarp_cube_face* F) {
    swarp_vec3 N = sw_v3(sw_cube_normal[i][0], sw_cube_normal[i][1], sw_cube_normal[i][2]);
    swarp_vec3 U = sw_v3(sw_cube_up[i][0], sw_cube_up[i][1], sw_cube_up[i][2]);
    swarp_vec3 Z = sw_scale(N, -1.0); /* the camera looks down its -z */
    swarp_vec3 R = sw_cross(U, Z);
    double d = s->d[i];
    memset(F, 0, sizeof *F);
    F->face = (uint32_t)i;
    F->inverse = (uint32_t)s->inverse;
    F->distance = d;
    F->right = R;
    F->up = U;
    F->normal = N;
    /* view: rows R, U, Z, translation -(R.P, U.P, Z.P) */
    swarp_mat4* V = &F->view;
    sw_identity(V);
    sw_set(V, 0, 0, R.x), sw_set(V, 0, 1, R.y), sw_set(V, 0, 2, R.z), sw_set(V, 0, 3, -sw_dot(R, s->P));
    sw_set(V, 1, 0, U.x), sw_set(V, 1, 1, U.y), sw_set(V, 1, 2, U.z), sw_set(V, 1, 3, -sw_dot(U, s->P));
    sw_set(V, 2, 0, Z.x), sw_set(V, 2, 1, Z.y), sw_set(V, 2, 2, Z.z), sw_set(V, 2, 3, -sw_dot(Z, s->P));
    /* proj: the face square [-1, 1]^2 (in R, U) at eye depth d fills NDC
     * [-1, 1]^2: x_ndc = d x_e / e + R.P with e = -z_e, so
     * x_clip = d x_e - (R.P) z_e, w_clip = -z_e. */
    double alpha, beta;
    sw_cube_depth_coeffs(s, d, &alpha, &beta);
    swarp_mat4* Pm = &F->proj;
    memset(Pm, 0, sizeof *Pm);
    sw_set(Pm, 0, 0, d), sw_set(Pm, 0, 2, -sw_dot(R, s->P));
    sw_set(Pm, 1, 1, d), sw_set(Pm, 1, 2, -sw_dot(U, s->P));
    sw_set(Pm, 2, 2, -alpha), sw_set(Pm, 2, 3, beta);
    sw_set(Pm, 3, 2, -1.0);
    /* view_proj = proj view in closed form (R, U, Z are axis vectors, so
     * every entry is one rounded operation).  The product evaluated in
     * floating point would sum d (R.P) - (R.P)(Z.P) with Z.P = d - 1 to the
     * exact -R.P: for a far light (|P| ~ 3e6) a cancellation of |P| d, which
     * the caller's rounding mode would move by 1e-9 of the matrix.
     * Row 2's translation alpha Z.P + beta is (alpha + bd) d - alpha, with
     * alpha + bd = 1 (regular), Z_1 (inverse), (1 + Z_1)/2 (inverse, [0, 1]). */
    sw_cube_depth_ratio(s, &alpha, &(double){0.0});
    const double RP = sw_dot(R, s->P), UP = sw_dot(U, s->P), ZP = sw_dot(Z, s->P);
    const double Rv[3] = {R.x, R.y, R.z}, Uv[3] = {U.x, U.y, U.z}, Zv[3] = {Z.x, Z.y, Z.z};
    swarp_mat4* W = &F->view_proj;
    memset(W, 0, sizeof *W);
    for (int c = 0; c < 3; ++c) {
        /* one of each pair of terms is an exact zero (R, U orthogonal to Z) */
        sw_set(W, 0, c, Zv[c] != 0.0 ? -RP * Zv[c] : d * Rv[c]);
        sw_set(W, 1, c, Zv[c] != 0.0 ? -UP * Zv[c] : d * Uv[c]);
        sw_set(W, 2, c, -alpha * Zv[c]);
        sw_set(W, 3, c, -Zv[c]);
    }
    sw_set(W, 0, 3, -RP);
    sw_set(W, 1, 3, -UP);
    const double ab = !s->inverse ? 1.0 : s->zero_to_one ? 0.5 * (1.0 + s->z1) : s->z1;
    sw_set(W, 2, 3, ab * d - alpha);
    sw_set(W, 3, 3, ZP);
    if (s->reversed) sw_depth_reverse(Pm), sw_depth_reverse(W);
}

/* [KOZ] §14.2.2 */
SWARP_API swarp_status swarp_cube_faces(const swarp_vec4* ps_light, const swarp_cube_options* opt,
                                        swarp_cube_face* out, size_t capacity, size_t* out_count) {
    if (!out_count || (!out && capacity > 0)) return SWARP_ERR_NULL_POINTER;
    sw_cube_setup s;
    swarp_status st = sw_cube_setup_make(ps_light, opt, &s);
    if (st != SWARP_OK) return st;
    size_t count = 0;
    for (int i = 0; i < 6; ++i) count += s.d[i] > 0.0;
    if (count == 0) return SWARP_ERR_DEGENERATE; /* impossible for a finite P */
    if (capacity < count) {
        *out_count = count;
        return SWARP_ERR_CAPACITY;
    }
    swarp_cube_face faces[6];
    size_t k = 0;
    for (int i = 0; i < 6; ++i) {
        if (!(s.d[i] > 0.0)) continue;
        sw_cube_face_make(&s, i, &faces[k]);
        if (!sw_mat_finite(&faces[k].view_proj)) return SWARP_ERR_CUBE_LIGHT_AT_INFINITY;
        ++k;
    }
    memcpy(out, faces, k * sizeof faces[0]);
    *out_count = k;
    return SWARP_OK;
}

/* [KOZ] Listing 14-1 */
SWARP_API swarp_status swarp_cube_lookup(const swarp_vec4* ps_light, const swarp_cube_options* opt,
                                         const swarp_vec3* ps_point, uint32_t* out_face,
                                         swarp_vec3* out_texcoord, double* out_depth) {
    if (!ps_point) return SWARP_ERR_NULL_POINTER;
    sw_cube_setup s;
    swarp_status st = sw_cube_setup_make(ps_light, opt, &s);
    if (st != SWARP_OK) return st;
    if (!sw_finite3(ps_point)) return SWARP_ERR_NON_FINITE;
    swarp_vec3 u = sw_sub(*ps_point, s.P); /* "vertex position - light position" */
    /* S = P + u/a does not depend on the scale of u: u scaled by 2^-k
     * (exact) when its largest component is beyond 2^960, so that
     * a = (u . N)/d (d >= 2^-53 when > 0) cannot overflow -- a component
     * near DBL_MAX would make a = inf, u/a = 0 and S = P, off the cube.
     * Only down to 2^900: a smaller component that
     * decides a is >= a d_i, far above the subnormals, as long as S is
     * finite (all the way to [1, 2) would make it subnormal).  Below 2^-500
     * up to [1, 2) (no component shrinks): a = |u| / d with d up to 1e150
     * stays far from the subnormals. */
    const double ax = fabs(u.x), ay = fabs(u.y), az = fabs(u.z); /* finite: |P| <= 1e150 */
    const double axy = ax > ay ? ax : ay, um = axy > az ? axy : az;
    int k = 0; /* the usual case: no libm call on this path (bench_core) */
    if (um > 0x1p960 || (um < 0x1p-500 && um > 0.0)) {
        const int eu = ilogb(um);
        k = eu > 0 ? eu - 900 : eu;
        u = sw_v3(scalbn(u.x, -k), scalbn(u.y, -k), scalbn(u.z, -k));
    }
    /* a = max over back faces of (u . N_i)/d_i = 1 / (ray parameter of the exit face) */
    double a = -INFINITY;
    int face = -1;
    for (int i = 0; i < 6; ++i) {
        if (!(s.d[i] > 0.0)) continue;
        swarp_vec3 N = sw_v3(sw_cube_normal[i][0], sw_cube_normal[i][1], sw_cube_normal[i][2]);
        double r = sw_dot(u, N) / s.d[i];
        if (r > a) {
            a = r;
            face = i;
        }
    }
    if (face < 0 || !(a > 0.0)) return SWARP_ERR_CUBE_POINT_UNCOVERED;
    swarp_vec3 S = sw_add(s.P, sw_scale(u, 1.0 / a)); /* on the unit cube */
    /* the projective transform of a (units of d: far = 1 or Z_1); the
     * unscaled a is 2^k a (inf beyond DBL_MAX: then 1/a is 0 to rounding) */
    double alpha, beta;
    sw_cube_depth_coeffs(&s, 1.0, &alpha, &beta);
    double depth = alpha + beta / a, a_full = a;
    if (k != 0) {
        int eb = 0;
        const double mb = frexp(beta, &eb); /* beta / (2^k a) = (mb / a) 2^(eb - k): no spurious overflow */
        depth = alpha + scalbn(mb / a, eb - k);
        a_full = scalbn(a, k);
    }
    if (s.reversed) depth = 1.0 - depth;
    if (!sw_finite3(&S) || !sw_finite(depth)) return SWARP_ERR_OVERFLOW;
    if (out_face) *out_face = (uint32_t)face;
    if (out_texcoord) *out_texcoord = S;
    if (out_depth) *out_depth = depth;
    return a_full < s.z1 ? SWARP_INFO_CUBE_NEAR_CLIPPED : SWARP_OK;
}
