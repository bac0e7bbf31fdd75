/* Hard-case / fuzz entries for the lixel stage ([LIXEL] Chong & Gortler).
 * Beyond the specific statuses predicted for NULL pointers, non-finite
 * inputs, reserved words and enums, a domain error must be one of the
 * function's documented statuses (swr_allow) and leave every output
 * untouched.  Properties: the five correspondences of solve5; the defining
 * property of M_l (a point of the plane of interest has the same (x, y) in
 * viewer pixels and lixels, q > 0 in front of the viewer); the restriction
 * rectangle encloses C; GLV GLP reproduces (x, y, q) of M_l. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_lixel_solve5)
SWR_WEAK(swarp_lixel_matrix)
SWR_WEAK(swarp_lixel_restrict)
SWR_WEAK(swarp_lixel_twist_for_line)
SWR_WEAK(swarp_lixel_factor)
SWR_WEAK(swarp_lixel_split)
SWR_WEAK(swarp_lixel_select)


static int fin(double x) { return swr_isfin(x); }
static int fin3(const swarp_vec3* v) { return fin(v->x) && fin(v->y) && fin(v->z); }
static int fin4(const swarp_vec4* v) { return fin(v->x) && fin(v->y) && fin(v->z) && fin(v->w); }
static int finm(const swarp_mat4* m) {
    for (int i = 0; i < 16; ++i)
        if (!fin(m->m[i])) return 0;
    return 1;
}
static void rec_mat(swr_ctx* c, const char* what, const swarp_mat4* m) {
    for (int i = 0; i < 16; ++i) swr_rec(c, what, m->m[i]);
}
static double maxabs(const swarp_mat4* m) {
    double a = 0;
    for (int i = 0; i < 16; ++i) a = fmax(a, fabs(m->m[i]));
    return a;
}
static swarp_vec4 xf(const swarp_mat4* m, swarp_vec4 p) {
    swarp_vec4 o;
    o.x = m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12] * p.w;
    o.y = m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13] * p.w;
    o.z = m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14] * p.w;
    o.w = m->m[3] * p.x + m->m[7] * p.y + m->m[11] * p.z + m->m[15] * p.w;
    return o;
}
static swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static swarp_vec3 cross(swarp_vec3 a, swarp_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static swarp_vec3 unit(swarp_vec3 a) {
    double l = sqrt(dot(a, a));
    return l > 0 ? v3(a.x / l, a.y / l, a.z / l) : v3(0, 0, 1);
}

/* a direction, sometimes axis-aligned or tiny */
static swarp_vec3 gen_dir(swr_ctx* c) {
    static const double brk[] = {0.0, 1.0, -1.0};
    swarp_vec3 d = v3(swr_num(c, -1, 1, brk, 3), swr_num(c, -1, 1, brk, 3), swr_num(c, -1, 1, brk, 3));
    if (swr_one_in(c, 16)) d = v3(0, 0, 0);
    return d;
}

/* A viewer: eye (offset up to 1e6), looking along dir, perspective with
 * fovy, aspect; M_v = P V (OpenGL). */
typedef struct viewer {
    swarp_vec3 eye, dir, up;
    double fovy, aspect, z_near, z_far;
    swarp_mat4 M_v;
} viewer;
static void gen_viewer(swr_ctx* c, viewer* v) {
    double off = swr_offset(c);
    v->eye = v3(off + swr_num_in(c, -10, 10, NULL, 0), swr_num_in(c, 0.1, 10, NULL, 0), off + swr_num_in(c, -10, 10, NULL, 0));
    v->dir = unit(v3(swr_num_in(c, -1, 1, NULL, 0), swr_num_in(c, -1, 0.3, NULL, 0), swr_num_in(c, -1, 1, NULL, 0)));
    v->up = v3(0, 1, 0);
    if (fabs(v->dir.y) > 0.999) v->up = v3(1, 0, 0);
    v->fovy = swr_num_in(c, 0.2, 2.5, NULL, 0);
    v->aspect = swr_num_in(c, 0.5, 2.5, NULL, 0);
    v->z_near = swr_num_in(c, 1e-3, 1, NULL, 0);
    v->z_far = v->z_near * swr_num_in(c, 10, 1e5, NULL, 0);
    swarp_vec3 f = v->dir, s = unit(cross(f, v->up)), u = cross(s, f);
    swarp_mat4 V = {{0}}, P = {{0}};
    V.m[0] = s.x; V.m[4] = s.y; V.m[8] = s.z;
    V.m[1] = u.x; V.m[5] = u.y; V.m[9] = u.z;
    V.m[2] = -f.x; V.m[6] = -f.y; V.m[10] = -f.z;
    V.m[12] = -dot(s, v->eye); V.m[13] = -dot(u, v->eye); V.m[14] = dot(f, v->eye);
    V.m[15] = 1;
    double t = 1.0 / tan(v->fovy / 2);
    P.m[0] = t / v->aspect; P.m[5] = t;
    P.m[10] = -(v->z_far + v->z_near) / (v->z_far - v->z_near);
    P.m[11] = -1;
    P.m[14] = -2 * v->z_far * v->z_near / (v->z_far - v->z_near);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            double acc = 0;
            for (int k = 0; k < 4; ++k) acc += P.m[k * 4 + row] * V.m[col * 4 + k];
            v->M_v.m[col * 4 + row] = acc;
        }
}

/* ------------------------------------------------------------------------ */
static void e_lixel_solve5(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_solve5);
    swarp_vec4 src[5], dst[5];
    double off = swr_offset(c);
    for (int i = 0; i < 5; ++i) {
        src[i].x = off + swr_num(c, -10, 10, NULL, 0);
        src[i].y = swr_num(c, -10, 10, NULL, 0);
        src[i].z = off + swr_num(c, -10, 10, NULL, 0);
        src[i].w = swr_one_in(c, 8) ? 0.0 : 1.0;
        dst[i].x = swr_num(c, -1000, 1000, NULL, 0);
        dst[i].y = swr_num(c, -1000, 1000, NULL, 0);
        dst[i].z = swr_one_in(c, 2) ? 1.0 : -1.0;
        dst[i].w = swr_one_in(c, 10) ? 0.0 : 1.0;
    }
    if (swr_one_in(c, 6)) { /* four coplanar */
        src[3].x = 0.5 * (src[0].x + src[1].x);
        src[3].y = 0.5 * (src[0].y + src[1].y);
        src[3].z = 0.5 * (src[0].z + src[1].z);
        src[3].w = 0.5 * (src[0].w + src[1].w);
    }
    int n_s = swr_null(c), n_d = swr_null(c), n_m = swr_null(c), n_c = swr_one_in(c, 3);
    if (n_s || n_d || n_m) swr_expect(c, SWARP_ERR_NULL_POINTER);
    for (int i = 0; i < 5; ++i)
        if (!fin4(&src[i]) || !fin4(&dst[i])) swr_expect(c, SWARP_ERR_NON_FINITE);
    swr_allow(c, SWARP_ERR_LIXEL_COPLANAR);
    swarp_mat4 M;
    double cond;
    swr_fill(&M, sizeof M);
    swr_fill(&cond, sizeof cond);
    swarp_status st = SWR_CALL(c, swarp_lixel_solve5(n_s ? NULL : src, n_d ? NULL : dst, n_m ? NULL : &M, n_c ? NULL : &cond));
    /* the OK / ILL_CONDITIONED / COPLANAR thresholds are on a computed
     * conditioning: rounding decides near them (fenv test) */
    if (st == SWARP_INFO_LIXEL_ILL_CONDITIONED || st == SWARP_ERR_LIXEL_COPLANAR) c->rounding_edge = 1;
    if (!swr_verdict(c, st, 2, (void*)&M, sizeof M, (void*)&cond, sizeof cond)) return;
    /* the conditioning is the call's whether or not the caller asked for it:
     * without out_conditioning it is measured by a second call (default
     * environment), so the fenv tolerance scales with it either way */
    double k = cond;
    if (n_c) {
        swarp_mat4 M2;
        if (swarp_status_is_error(swarp_lixel_solve5(src, dst, &M2, &k))) k = 0;
    }
    if (k > 0) swr_cond(c, 1.0 / (k * k));
    if (k < 1e-4) c->rounding_edge = 1;
    rec_mat(c, "M", &M);
    SWR_CHECK(c, maxabs(&M) == 1.0, "largest |element| %.17g, documented 1", maxabs(&M));
    if (!n_c) {
        swr_rec(c, "conditioning", cond);
        SWR_CHECK(c, cond >= 0 && cond <= 1, "conditioning %g outside [0, 1]", cond);
    }
    if (st != SWARP_OK) return; /* ill-conditioned: written, no accuracy claim */
    /* M src[i] ~ dst[i]: the 2x2 minors of (M src, dst) vanish */
    for (int i = 0; i < 5; ++i) {
        swarp_vec4 p = xf(&M, src[i]);
        double a[4] = {p.x, p.y, p.z, p.w}, b[4] = {dst[i].x, dst[i].y, dst[i].z, dst[i].w};
        double na = 0, nb = 0, worst = 0;
        for (int k = 0; k < 4; ++k) {
            na = fmax(na, fabs(a[k]));
            nb = fmax(nb, fabs(b[k]));
        }
        for (int j = 0; j < 4; ++j)
            for (int k = j + 1; k < 4; ++k) worst = fmax(worst, fabs(a[j] * b[k] - a[k] * b[j]));
        SWR_CHECK_ACC(c, worst <= 1e-6 * na * nb, "M src[%d] not parallel to dst[%d]: minor %.3g of %.3g", i, i, worst,
                      na * nb);
    }
}

/* light and plane of interest for a viewer: a floor (y = const) or a wall,
 * sometimes through the eye, light sometimes on the plane or parallel */
static void gen_scene(swr_ctx* c, const viewer* v, swarp_light* L, swarp_plane* P) {
    memset(L, 0, sizeof *L);
    uint8_t k = swr_u8(c) % 5;
    swarp_vec3 nrm = k == 0 ? v3(0, 1, 0) : k == 1 ? v3(1, 0, 0) : k == 2 ? v3(0, 0, 1) : unit(gen_dir(c));
    if (k == 4) nrm = gen_dir(c); /* maybe zero */
    swarp_vec3 on = v3(v->eye.x + swr_num_in(c, -5, 5, NULL, 0), v->eye.y - swr_num_in(c, 0.5, 5, NULL, 0),
                       v->eye.z + swr_num_in(c, -5, 5, NULL, 0));
    if (swr_one_in(c, 12)) { /* plane through the eye (an exact degeneracy: rounding decides) */
        on = v->eye;
        c->rounding_edge = 1;
    }
    P->a = nrm.x;
    P->b = nrm.y;
    P->c = nrm.z;
    P->d = -dot(nrm, on);
    /* the same degeneracy when an offset above came out 0 (the generator
     * favours 0) and the normal is an axis: P then contains the eye to
     * within the rounding of its d, and PLANE_THROUGH_EYE (LX_EYE_EPS) is
     * decided by the rounding of V^-1 at the eye's magnitude (e.g. eye
     * ~1e5..1e6, THROUGH_EYE under round-to-nearest,
     * NOT_VISIBLE / LIGHT_PARALLEL_PLANE / LIGHT_ON_PLANE under directed).
     * The eye is implied by M_v, whose translation column (magnitude
     * |eye|) the harness rounds twice (V, then P V) and the library inverts
     * (V^-1, condition a few): it is known to a few ulps of |eye| times
     * that, 64 eps |eye| as the fenv tolerance takes it.  A plane within
     * that of the eye is through it to rounding (e.g. planes 9 and 10 ulps of
     * 1e6 from the eye, pi'_z/|pi'| = 1e-10
     * = LX_EYE_EPS to nearest, 0.7e-10 .. 1.7e-10 by rounding mode). */
    {
        long double e = (long double)nrm.x * v->eye.x + (long double)nrm.y * v->eye.y + (long double)nrm.z * v->eye.z;
        long double m = fabsl((long double)nrm.x * v->eye.x) + fabsl((long double)nrm.y * v->eye.y) +
                        fabsl((long double)nrm.z * v->eye.z);
        if (fabsl(e + P->d) <= 64 * DBL_EPSILON * m) c->rounding_edge = 1;
    }
    L->type = (swarp_light_type)swr_enum(c, 3);
    L->direction = gen_dir(c);
    if (swr_one_in(c, 8)) { /* maybe parallel to P */
        L->direction = v3(-nrm.y, nrm.x, 0);
        c->rounding_edge = 1;
    }
    L->position = v3(on.x + swr_num_in(c, -20, 20, NULL, 0), on.y + swr_num(c, 0.1, 30, NULL, 0), on.z + swr_num_in(c, -20, 20, NULL, 0));
    if (swr_one_in(c, 12)) { /* light on the plane */
        L->position = on;
        c->rounding_edge = 1;
    }
    if (swr_one_in(c, 12)) {
        L->position = v->eye;
        c->rounding_edge = 1;
    }
    L->cone_angle = swr_one_in(c, 2) ? 0.0 : swr_num(c, 0.1, 1.5, NULL, 0);
    L->_reserved[swr_u8(c) % 4] = swr_reserved(c);
}

static void expect_light(swr_ctx* c, const swarp_light* L) {
    int t = (int)L->type;
    if (t < 0 || t > 2) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    /* only the fields the type uses are checked (documented per field) */
    if (t == 0 || t == 1) {
        if (!fin3(&L->direction)) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (L->direction.x == 0 && L->direction.y == 0 && L->direction.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    }
    if (t == 2 && !fin3(&L->position)) swr_expect(c, SWARP_ERR_NON_FINITE);
    /* the lixel stage does not use cone_angle: a NaN there may be refused
     * or ignored (noted in docs/quality.md) */
    if (t == 2 && !fin(L->cone_angle)) swr_allow(c, SWARP_ERR_NON_FINITE);
    for (int i = 0; i < 4; ++i)
        if (L->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    if (L->_reserved0) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
}

/* The condition of the five correspondences' positions, which the solve's
 * conditioning (1/k^2 above) then amplifies (the condition of a composition
 * is at most the product).  M_v holds the eye in its translation column
 * (R eye, magnitude |eye|): its entries perturbed by eps move the eye by
 * eps |eye|, and with it the corner rays' hit points on P, which lie at
 * least the eye's distance to P from the eye and fix M_l: eps |eye| against
 * that distance (P's d, of magnitude |n| |eye| for a plane near the eye,
 * moves P as much).  A point light's position enters as given: eps |l| against
 * its distance to P, which its images (p-hat, the centre of projection) are
 * measured by.  (e.g. eye 1.4e6 from the origin, 0.73
 * above the floor, 1/k^2 = 55: M_l 1.1e-9 relative by rounding mode; M_v's
 * entries moved by one ulp move M_l by 7.5e6 eps, below 55 * 1.4e6.) */
static double offset_cond(const viewer* v, const swarp_light* L, const swarp_plane* P) {
    const double nn = sqrt(P->a * P->a + P->b * P->b + P->c * P->c);
    if (!(nn > 0) || !swr_isfin(nn)) return 1;
    const double de = fabs(P->a * v->eye.x + P->b * v->eye.y + P->c * v->eye.z + P->d) / nn;
    const double me = fmax(fabs(v->eye.x), fmax(fabs(v->eye.y), fabs(v->eye.z)));
    double k = de > 0 ? 1 + me / de : INFINITY;
    if (L->type == SWARP_LIGHT_POINT) {
        const swarp_vec3* l = &L->position;
        const double dl = fabs(P->a * l->x + P->b * l->y + P->c * l->z + P->d) / nn;
        const double ml = fmax(fabs(l->x), fmax(fabs(l->y), fabs(l->z)));
        k = fmax(k, dl > 0 ? 1 + ml / dl : INFINITY);
    }
    return k;
}

static void e_lixel_matrix(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_matrix);
    viewer v;
    gen_viewer(c, &v);
    swarp_light L;
    swarp_plane P;
    gen_scene(c, &v, &L, &P);
    uint32_t g = swr_one_in(c, 20) ? swr_u8(c) % 3 : 64 + swr_u32(c) % 4000;
    uint32_t h = swr_one_in(c, 20) ? swr_u8(c) % 3 : 64 + swr_u32(c) % 4000;
    swarp_lixel_options opt;
    memset(&opt, 0, sizeof opt);
    static const double brk[] = {0.0, 1.0};
    opt.raise = swr_one_in(c, 2) ? 0.0 : swr_num(c, 0, 1, brk, 2);
    opt._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use_opt = !swr_one_in(c, 3);
    int n_mv = swr_null(c), n_l = swr_null(c), n_p = swr_null(c), n_out = swr_null(c), n_info = swr_one_in(c, 3);
    if (n_mv || n_l || n_p || n_out) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_light(c, &L);
    if (!fin(P.a) || !fin(P.b) || !fin(P.c) || !fin(P.d)) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (P.a == 0 && P.b == 0 && P.c == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    if (g < 2 || h < 2) swr_expect(c, SWARP_ERR_RESOLUTION);
    if (use_opt) {
        if (!fin(opt.raise)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (!(opt.raise >= 0 && opt.raise < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        for (int i = 0; i < 4; ++i)
            if (opt._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    }
    static const swarp_status dom[] = {SWARP_ERR_LIXEL_PLANE_THROUGH_EYE, SWARP_ERR_LIXEL_LIGHT_ON_PLANE,
                                       SWARP_ERR_LIXEL_LIGHT_PARALLEL_PLANE, SWARP_ERR_LIXEL_PLANE_NOT_VISIBLE,
                                       SWARP_ERR_SINGULAR, SWARP_ERR_ZERO_VECTOR};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
    /* COPLANAR is documented (header: the five constraint points nearly
     * coplanar, conditioning < 1e-13); the sweep meets it for eyes offset by
     * 1e5..1e6 with the plane within a few units of the eye, which the
     * harness does not predict exactly -> a domain status */
    swr_domain(c, SWARP_ERR_LIXEL_COPLANAR);
    swarp_mat4 M;
    swarp_lixel_info info;
    swr_fill(&M, sizeof M);
    swr_fill(&info, sizeof info);
    swr_args(c, "eye=(%.17g %.17g %.17g) dir=(%.17g %.17g %.17g) fovy %.17g aspect %.17g near %.17g far %.17g light type %d dir=(%.17g %.17g %.17g) pos=(%.17g %.17g %.17g) plane (%.17g %.17g %.17g %.17g) g=%u h=%u raise %.17g%s",
             v.eye.x, v.eye.y, v.eye.z, v.dir.x, v.dir.y, v.dir.z, v.fovy, v.aspect, v.z_near, v.z_far, (int)L.type,
             L.direction.x, L.direction.y, L.direction.z, L.position.x, L.position.y, L.position.z, P.a, P.b, P.c, P.d, g, h,
             opt.raise, use_opt ? "" : " (no options)");
    swarp_status st = SWR_CALL(c, swarp_lixel_matrix(n_mv ? NULL : &v.M_v, g, h, n_l ? NULL : &L, n_p ? NULL : &P,
                                                    use_opt ? &opt : NULL, n_out ? NULL : &M, n_info ? NULL : &info));
    if (st == SWARP_INFO_LIXEL_ILL_CONDITIONED || st == SWARP_ERR_LIXEL_COPLANAR) c->rounding_edge = 1;
    /* PLANE_PARALLEL_VIEW is |n . v| < 1e-9 (LX_VIEW_PARALLEL_EPS) for the
     * unit normal and the view direction, which the library takes from the
     * x, y, z parts of M_v's rows (rounded by the harness's P V product:
     * a few eps, the rows' condition a few): within 64 eps of the bound the
     * rounding decides (e.g. the
     * generator's 1e-9 component of dir along n, |n . v| - 1e-9 = 3e-25;
     * PARALLEL_VIEW or QUAD_ACROSS_INFINITY by rounding mode) */
    {
        const double nn = sqrt(P.a * P.a + P.b * P.b + P.c * P.c);
        const double nv = fabs(P.a * v.dir.x + P.b * v.dir.y + P.c * v.dir.z) / nn;
        if (nn > 0 && swr_isfin(nv) && fabs(nv - 1e-9) <= 64 * DBL_EPSILON) c->rounding_edge = 1;
    }
    if (!swr_verdict(c, st, 2, (void*)&M, sizeof M, (void*)&info, sizeof info)) return;
    /* the conditioning of the call, asked for or not (as in swarp_lixel_solve5's
     * entry): without out_info a second call in the default environment */
    double k = n_info ? 0 : info.conditioning;
    if (n_info) {
        swarp_mat4 M2;
        swarp_lixel_info i2;
        if (!swarp_status_is_error(swarp_lixel_matrix(&v.M_v, g, h, &L, &P, use_opt ? &opt : NULL, &M2, &i2)))
            k = i2.conditioning;
    }
    if (k > 0) swr_cond(c, 1.0 / (k * k) * offset_cond(&v, &L, &P));
    if (k < 1e-4) c->rounding_edge = 1;
    rec_mat(c, "M_l", &M);
    SWR_CHECK(c, maxabs(&M) == 1.0, "largest |element| %.17g, documented 1", maxabs(&M));
    if (!n_info) SWR_CHECK(c, info.corners_in_front <= 4 && info.raised_index <= 3, "info out of range");
    if (st != SWARP_OK) return;
    /* the defining property: on P, viewer pixel == lixel, q > 0 in front */
    swarp_vec3 nrm = v3(P.a, P.b, P.c);
    double nn = dot(nrm, nrm);
    for (int k = 0; k < 4; ++k) {
        /* a point of P seen by the viewer: along a ray through the image */
        double sx = swr_num_in(c, -0.9, 0.9, NULL, 0), sy = swr_num_in(c, -0.9, 0.9, NULL, 0);
        swarp_vec3 f = v.dir, s = unit(cross(f, v.up)), u = cross(s, f);
        double t = tan(v.fovy / 2);
        swarp_vec3 ray = v3(f.x + sx * t * v.aspect * s.x + sy * t * u.x, f.y + sx * t * v.aspect * s.y + sy * t * u.y,
                            f.z + sx * t * v.aspect * s.z + sy * t * u.z);
        double den = dot(nrm, ray);
        if (fabs(den) < 1e-6 * sqrt(nn * dot(ray, ray))) continue;
        double lam = -(dot(nrm, v.eye) + P.d) / den;
        if (!(lam > 0)) continue; /* P behind the viewer along this ray */
        swarp_vec4 p = {v.eye.x + lam * ray.x, v.eye.y + lam * ray.y, v.eye.z + lam * ray.z, 1.0};
        swarp_vec4 cv = xf(&v.M_v, p), cl = xf(&M, p);
        if (!(cv.w > 0)) continue;
        double xp = (cv.x / cv.w + 1) * g / 2 - 0.5, yp = (cv.y / cv.w + 1) * h / 2 - 0.5;
        SWR_CHECK(c, cl.w > 0, "q = %g <= 0 at a point of P in front of the viewer", cl.w);
        if (!(cl.w > 0)) return;
        double xl = cl.x / cl.w, yl = cl.y / cl.w;
        double tol = 1e-6 * (1 + fabs(xp) + fabs(yp) + g + h);
        SWR_CHECK_ACC(c, fabs(xl - xp) <= tol && fabs(yl - yp) <= tol,
                      "on P: lixel (%.9g, %.9g) != pixel (%.9g, %.9g)", xl, yl, xp, yp);
    }
}

static void e_lixel_restrict(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_restrict);
    swarp_mat4 M;
    for (int i = 0; i < 16; ++i) M.m[i] = swr_num_in(c, -1, 1, NULL, 0);
    M.m[3] = M.m[7] = M.m[11] = 0;
    M.m[15] = swr_num(c, 0.5, 2, NULL, 0);
    swarp_vec4 C[8];
    size_t n = swr_one_in(c, 16) ? 0 : 1 + swr_u8(c) % 8;
    for (size_t i = 0; i < 8; ++i) {
        C[i].x = swr_num(c, -100, 100, NULL, 0);
        C[i].y = swr_num(c, -100, 100, NULL, 0);
        C[i].z = swr_num(c, -100, 100, NULL, 0);
        C[i].w = swr_one_in(c, 10) ? 0.0 : 1.0;
    }
    swarp_lixel_restrict_options opt;
    memset(&opt, 0, sizeof opt);
    static const double brk[] = {0.0, 1.0};
    opt.scale_x = swr_num(c, 0, 4, brk, 2);
    opt.scale_y = swr_num(c, 0, 4, brk, 2);
    opt.twist = swr_num(c, -3.2, 3.2, brk, 2);
    opt.max_size = swr_one_in(c, 4) ? swr_u32(c) % 100000 : 0;
    if (swr_one_in(c, 4)) {
        opt.view_width = 64 + swr_u32(c) % 2000;
        opt.view_height = 64 + swr_u32(c) % 2000;
    }
    opt._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use_opt = !swr_one_in(c, 3);
    int n_m = swr_null(c), n_c = swr_null(c), n_r = swr_null(c), n_a = swr_one_in(c, 3), n_o = swr_null(c);
    if (n_m || (n_c && n > 0) || n_r || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_c && n == 0) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!finm(&M)) swr_expect(c, SWARP_ERR_NON_FINITE);
    for (size_t i = 0; i < n; ++i)
        if (!fin4(&C[i])) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (use_opt) {
        if (!fin(opt.scale_x) || !fin(opt.scale_y) || !fin(opt.twist)) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (opt.scale_x < 0 || opt.scale_y < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
        for (int i = 0; i < 4; ++i)
            if (opt._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    }
    if (n == 0) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT);
    static const swarp_status dom[] = {SWARP_ERR_LIXEL_RAY_OUTSIDE, SWARP_ERR_LIXEL_EMPTY,
                                       SWARP_ERR_LIXEL_RECT_TOO_LARGE, SWARP_ERR_OUT_OF_RANGE};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
    swarp_lixel_rect r;
    swarp_mat4 A, out;
    swr_fill(&r, sizeof r);
    swr_fill(&A, sizeof A);
    swr_fill(&out, sizeof out);
    swarp_status st = SWR_CALL(c, swarp_lixel_restrict(n_m ? NULL : &M, n_c ? NULL : C, n, use_opt ? &opt : NULL,
                                                      n_r ? NULL : &r, n_a ? NULL : &A, n_o ? NULL : &out));
    if (!swr_verdict(c, st, 3, (void*)&r, sizeof r, (void*)&A, sizeof A, (void*)&out, sizeof out)) return;
    rec_mat(c, "A_l M_l", &out);
    if (!n_a) rec_mat(c, "A_l", &A);
    c->rec[c->n_rec < SWR_MAX_REC ? c->n_rec++ : 0] = r.x0;
    SWR_CHECK(c, r.x1 >= r.x0 && r.y1 >= r.y0, "empty rectangle [%d, %d] x [%d, %d]", r.x0, r.x1, r.y0, r.y1);
    SWR_CHECK(c, r.width == (uint32_t)(r.x1 - r.x0 + 1) && r.height == (uint32_t)(r.y1 - r.y0 + 1),
              "width/height %u %u disagree with the corners", r.width, r.height);
    uint32_t maxs = use_opt && opt.max_size ? opt.max_size : SWARP_LIXEL_DEFAULT_MAX_SIZE;
    SWR_CHECK(c, r.width <= maxs && r.height <= maxs, "rect %ux%u above max_size %u", r.width, r.height, maxs);
    /* without view clipping every vertex of C lands inside [0, w-1] x [0, h-1] (+1/2) */
    if (use_opt && opt.view_width) return;
    for (size_t i = 0; i < n; ++i) {
        swarp_vec4 q = xf(&out, C[i]);
        if (!(q.w > 0)) continue;
        double x = q.x / q.w, y = q.y / q.w, slack = 1e-6 * (1 + r.width + r.height);
        SWR_CHECK_ACC(c, x >= -0.5 - slack && x <= r.width - 0.5 + slack && y >= -0.5 - slack && y <= r.height - 0.5 + slack,
                      "vertex %zu at (%g, %g) outside the %ux%u rectangle", i, x, y, r.width, r.height);
    }
}

static void e_lixel_twist_for_line(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_twist_for_line);
    swarp_mat4 M;
    for (int i = 0; i < 16; ++i) M.m[i] = swr_num(c, -1, 1, NULL, 0);
    swarp_vec3 a = v3(swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0));
    swarp_vec3 b = swr_one_in(c, 10) ? a : v3(swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0));
    swarp_vec3 bl = v3(swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0));
    int n_m = swr_null(c), n_a = swr_null(c), n_b = swr_null(c), n_bl = swr_null(c), n_o = swr_null(c);
    if (n_m || n_a || n_b || n_bl || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!finm(&M) || !fin3(&a) || !fin3(&b) || !fin3(&bl)) swr_expect(c, SWARP_ERR_NON_FINITE);
    swr_allow(c, SWARP_ERR_LIXEL_TWIST_LINE);
    double tw;
    swr_fill(&tw, sizeof tw);
    swarp_status st = SWR_CALL(c, swarp_lixel_twist_for_line(n_m ? NULL : &M, n_a ? NULL : &a, n_b ? NULL : &b,
                                                            n_bl ? NULL : &bl, n_o ? NULL : &tw));
    if (!swr_verdict(c, st, 1, (void*)&tw, sizeof tw)) return;
    swr_rec(c, "twist", tw);
    SWR_CHECK(c, fabs(tw) <= 2 * 3.14159265358979323846 + 1e-9, "twist %g beyond 2 pi", tw);
    /* rotated by tw, the images of a and b have the same y */
    swarp_vec4 pa = xf(&M, (swarp_vec4){a.x, a.y, a.z, 1}), pb = xf(&M, (swarp_vec4){b.x, b.y, b.z, 1});
    double xa = pa.x / pa.w, ya = pa.y / pa.w, xb = pb.x / pb.w, yb = pb.y / pb.w;
    double ra = sin(tw) * xa + cos(tw) * ya, rb = sin(tw) * xb + cos(tw) * yb;
    double scale = fabs(xa) + fabs(ya) + fabs(xb) + fabs(yb);
    SWR_CHECK_ACC(c, fabs(ra - rb) <= 1e-9 * scale + 1e-300, "rotated line not horizontal: y %.17g vs %.17g", ra, rb);
}

static void e_lixel_factor(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_factor);
    swarp_mat4 M;
    for (int i = 0; i < 16; ++i) M.m[i] = swr_num(c, -1, 1, NULL, 0);
    uint32_t w = swr_one_in(c, 16) ? 0 : 1 + swr_u32(c) % 8192, h = swr_one_in(c, 16) ? 0 : 1 + swr_u32(c) % 8192;
    int32_t dr = swr_enum(c, 3);
    static const double brk[] = {0.0, 1.0, 0.5};
    double pd = swr_num(c, 0, 1, brk, 3);
    int n_m = swr_null(c), n_v = swr_null(c), n_p = swr_null(c);
    if (n_m || n_v || n_p) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!finm(&M) || !fin(pd)) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (w == 0 || h == 0) swr_expect(c, SWARP_ERR_RESOLUTION);
    if (dr < 0 || dr > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    if (fin(pd) && !(pd >= 0 && pd < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swr_allow(c, SWARP_ERR_OUT_OF_RANGE);
    swr_allow(c, SWARP_ERR_SINGULAR);
    swarp_mat4 V, P;
    swr_fill(&V, sizeof V);
    swr_fill(&P, sizeof P);
    swarp_status st = SWR_CALL(c, swarp_lixel_factor(n_m ? NULL : &M, w, h, (swarp_depth_range)dr, pd, n_v ? NULL : &V,
                                                    n_p ? NULL : &P));
    if (!swr_verdict(c, st, 2, (void*)&V, sizeof V, (void*)&P, sizeof P)) return;
    rec_mat(c, "GLV", &V);
    rec_mat(c, "GLP", &P);
    /* (x, y, q) of GLV GLP equal those of M_l.  The product is formed in long
     * double: with |M_l| near DBL_MAX the terms V_rk P_kc (each finite, and
     * cancelling to a finite M_l) overflow double and inf - inf gave a NaN in
     * the CHECK, not in the library's outputs (which are finite). */
    long double scale = maxabs(&M);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            if (row == 2) continue;
            long double acc = 0, mag = 0;
            for (int k = 0; k < 4; ++k) {
                acc += (long double)V.m[k * 4 + row] * P.m[col * 4 + k];
                mag += fabsl((long double)V.m[k * 4 + row] * P.m[col * 4 + k]);
            }
            SWR_CHECK_ACC(c, fabsl(acc - M.m[col * 4 + row]) <= 1e-12L * (mag + scale),
                          "(GLV GLP)[%d][%d] = %.17Lg, M_l %.17g", row, col, acc, M.m[col * 4 + row]);
        }
}

/* swarp_lixel_split's "light on the floor" test compares side = Σ · F (the
 * plane Σ through the light and the floor/wall line A + t u, at the floor
 * point F = A + w_f one unit in front of the wall) with the absolute 1e-9.
 * The library forms it as n_Σ · w_f / |w_f| from unit vectors (rounding
 * ~16 eps absolute); for a point light n_Σ = u x (L - A) also carries the
 * rounding of L - A, eps (|L| + |A|) / |L - A| of its direction.  When the
 * exact side (long double) is within that of the bound, the caller's
 * rounding mode decides DEGENERATE (e.g. |side| = 1e-9 within 3e-12; formed
 * as n_Σ · F - n_Σ · A it would carry 1e-10 of rounding with the line 1e6
 * from the origin). */
static int split_side_on_bound(const swarp_light* L, const swarp_plane* fl, const swarp_plane* wa) {
    typedef long double ld;
    const int point = L->type == SWARP_LIGHT_POINT;
    if (!point && L->type != SWARP_LIGHT_DIRECTIONAL && L->type != SWARP_LIGHT_DEFAULT) return 0;
    const double in[14] = {fl->a, fl->b, fl->c, fl->d, wa->a, wa->b, wa->c, wa->d, L->direction.x, L->direction.y,
                           L->direction.z, L->position.x, L->position.y, L->position.z};
    for (int i = 0; i < 14; ++i)
        if (!fin(in[i])) return 0;
    const ld lf = sqrtl((ld)fl->a * fl->a + (ld)fl->b * fl->b + (ld)fl->c * fl->c);
    const ld lw = sqrtl((ld)wa->a * wa->a + (ld)wa->b * wa->b + (ld)wa->c * wa->c);
    if (!(lf > 0) || !(lw > 0)) return 0;
    const ld nf[3] = {fl->a / lf, fl->b / lf, fl->c / lf}, nw[3] = {wa->a / lw, wa->b / lw, wa->c / lw};
    const ld hf = -fl->d / lf, hw = -wa->d / lw;
    const ld u[3] = {nf[1] * nw[2] - nf[2] * nw[1], nf[2] * nw[0] - nf[0] * nw[2], nf[0] * nw[1] - nf[1] * nw[0]};
    const ld uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    if (!(uu > 0)) return 0;
    /* A = (hf (nw x u) + hw (u x nf)) / |u|^2 */
    const ld a1[3] = {nw[1] * u[2] - nw[2] * u[1], nw[2] * u[0] - nw[0] * u[2], nw[0] * u[1] - nw[1] * u[0]};
    const ld a2[3] = {u[1] * nf[2] - u[2] * nf[1], u[2] * nf[0] - u[0] * nf[2], u[0] * nf[1] - u[1] * nf[0]};
    ld A[3], amax = 0;
    for (int k = 0; k < 3; ++k) A[k] = (hf * a1[k] + hw * a2[k]) / uu, amax = fmaxl(amax, fabsl(A[k]));
    ld t[3];
    if (point) {
        t[0] = L->position.x - A[0], t[1] = L->position.y - A[1], t[2] = L->position.z - A[2];
    } else {
        const ld dl = sqrtl((ld)L->direction.x * L->direction.x + (ld)L->direction.y * L->direction.y +
                            (ld)L->direction.z * L->direction.z);
        if (!(dl > 0)) return 0;
        t[0] = L->direction.x / dl, t[1] = L->direction.y / dl, t[2] = L->direction.z / dl;
    }
    ld ns[3] = {u[1] * t[2] - u[2] * t[1], u[2] * t[0] - u[0] * t[2], u[0] * t[1] - u[1] * t[0]};
    const ld ls = sqrtl(ns[0] * ns[0] + ns[1] * ns[1] + ns[2] * ns[2]);
    if (!(ls > 0)) return 0;
    const ld c = nw[0] * nf[0] + nw[1] * nf[1] + nw[2] * nf[2];
    const ld wf[3] = {nw[0] - c * nf[0], nw[1] - c * nf[1], nw[2] - c * nf[2]};
    const ld lwf = sqrtl(wf[0] * wf[0] + wf[1] * wf[1] + wf[2] * wf[2]);
    if (!(lwf > 0)) return 0;
    const ld side = (ns[0] * wf[0] + ns[1] * wf[1] + ns[2] * wf[2]) / (ls * lwf);
    ld k = 1;
    if (point) {
        const ld lt = sqrtl(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        const ld lmax = fmaxl(fabsl((ld)L->position.x), fmaxl(fabsl((ld)L->position.y), fabsl((ld)L->position.z)));
        k += lt > 0 ? (lmax + amax) / lt : 1e300L;
    }
    return fabsl(fabsl(side) - 1e-9L) <= 16 * DBL_EPSILON * k;
}

static void e_lixel_split(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_split);
    viewer v;
    gen_viewer(c, &v);
    swarp_light L;
    swarp_plane fl, wa;
    gen_scene(c, &v, &L, &fl);
    gen_scene(c, &v, &L, &wa);
    size_t n = swr_u8(c) % 9;
    swarp_vec4 C[8];
    double y0 = v.eye.y - swr_num_in(c, 0, 5, NULL, 0), rad = swr_num_in(c, 0.1, 20, NULL, 0);
    for (size_t i = 0; i < 8; ++i) { /* a convex polygon (regular, in a horizontal plane) */
        double a = 6.283185307179586 * (double)i / (double)(n ? n : 1);
        C[i].x = v.eye.x + rad * cos(a);
        C[i].y = y0;
        C[i].z = v.eye.z + rad * sin(a);
        C[i].w = 1.0;
    }
    if (swr_one_in(c, 16)) C[0].x = swr_num(c, -1, 1, NULL, 0) / 0.0;
    size_t cap_f = swr_one_in(c, 6) ? swr_u8(c) % 10 : 9, cap_w = swr_one_in(c, 6) ? swr_u8(c) % 10 : 9;
    int n_l = swr_null(c), n_f = swr_null(c), n_w = swr_null(c), n_c = swr_null(c);
    int n_of = swr_null(c), n_ofc = swr_null(c), n_ow = swr_null(c), n_owc = swr_null(c);
    if (n_l || n_f || n_w || n_c || (n_of && cap_f > 0) || n_ofc || (n_ow && cap_w > 0) || n_owc)
        swr_expect(c, SWARP_ERR_NULL_POINTER);
    if ((n_of && cap_f == 0) || (n_ow && cap_w == 0)) swr_allow(c, SWARP_ERR_NULL_POINTER);
    expect_light(c, &L);
    for (size_t i = 0; i < n; ++i)
        if (!fin4(&C[i])) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (!fin(fl.a) || !fin(fl.b) || !fin(fl.c) || !fin(fl.d) || !fin(wa.a) || !fin(wa.b) || !fin(wa.c) || !fin(wa.d))
        swr_expect(c, SWARP_ERR_NON_FINITE);
    if (n < 3) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT);
    static const swarp_status dom[] = {SWARP_ERR_CAPACITY, SWARP_ERR_DEGENERATE, SWARP_ERR_ZERO_VECTOR,
                                       SWARP_ERR_INVALID_ARGUMENT};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
    swarp_vec4 of[10], ow[10];
    size_t cf, cw;
    swr_fill(of, sizeof of);
    swr_fill(ow, sizeof ow);
    swr_fill(&cf, sizeof cf);
    swr_fill(&cw, sizeof cw);
    if (split_side_on_bound(&L, &fl, &wa)) c->rounding_edge = 1;
    swarp_status st = SWR_CALL(c, swarp_lixel_split(n_l ? NULL : &L, n_f ? NULL : &fl, n_w ? NULL : &wa, n_c ? NULL : C, n,
                                                   n_of ? NULL : of, cap_f, n_ofc ? NULL : &cf, n_ow ? NULL : ow, cap_w,
                                                   n_owc ? NULL : &cw));
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, swr_untouched(of, sizeof of) && swr_untouched(ow, sizeof ow), "CAPACITY but vertices written");
        SWR_CHECK(c, cf <= SWARP_LIXEL_SPLIT_MAX(n) && cw <= SWARP_LIXEL_SPLIT_MAX(n), "needed counts %zu %zu", cf, cw);
        SWR_CHECK(c, cf > cap_f || cw > cap_w, "CAPACITY with counts %zu %zu <= capacities %zu %zu", cf, cw, cap_f, cap_w);
        swr_fill(&cf, sizeof cf);
        swr_fill(&cw, sizeof cw);
    }
    if (!swr_verdict(c, st, 4, (void*)of, sizeof of, (void*)ow, sizeof ow, (void*)&cf, sizeof cf, (void*)&cw, sizeof cw))
        return;
    SWR_CHECK(c, cf <= cap_f && cw <= cap_w && cf <= SWARP_LIXEL_SPLIT_MAX(n) && cw <= SWARP_LIXEL_SPLIT_MAX(n),
              "counts %zu %zu", cf, cw);
    for (size_t i = 0; i < cf && i < 10; ++i) {
        swr_rec(c, "floor", of[i].x);
        swr_rec(c, "floor", of[i].y);
        swr_rec(c, "floor", of[i].z);
        swr_rec(c, "floor", of[i].w);
    }
    for (size_t i = 0; i < cw && i < 10; ++i) {
        swr_rec(c, "wall", ow[i].x);
        swr_rec(c, "wall", ow[i].y);
        swr_rec(c, "wall", ow[i].z);
        swr_rec(c, "wall", ow[i].w);
    }
}

static void e_lixel_select(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_lixel_select);
    swarp_mat4 G[3];
    size_t count = swr_u8(c) % 4;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 16; ++i) G[k].m[i] = swr_num(c, -1, 1, NULL, 0);
    swarp_vec3 p = v3(swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0), swr_num(c, -10, 10, NULL, 0));
    int n_g = swr_null(c), n_p = swr_null(c), n_o = swr_null(c);
    if ((n_g && count > 0) || n_p || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    for (size_t k = 0; k < count; ++k)
        if (!finm(&G[k])) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (!fin3(&p)) swr_expect(c, SWARP_ERR_NON_FINITE);
    uint32_t idx;
    swr_fill(&idx, sizeof idx);
    swarp_status st = SWR_CALL(c, swarp_lixel_select(n_g ? NULL : G, count, n_p ? NULL : &p, n_o ? NULL : &idx));
    if (!swr_verdict(c, st, 1, (void*)&idx, sizeof idx)) return;
    c->rec[c->n_rec < SWR_MAX_REC ? c->n_rec++ : 0] = idx;
    SWR_CHECK(c, idx <= count, "index %u > count %zu", idx, count);
    /* the first map that holds p (w > 0, |x|, |y| <= w) */
    uint32_t want = (uint32_t)count;
    for (size_t k = 0; k < count; ++k) {
        swarp_vec4 q = xf(&G[k], (swarp_vec4){p.x, p.y, p.z, 1});
        if (q.w > 0 && fabs(q.x) <= q.w && fabs(q.y) <= q.w) {
            want = (uint32_t)k;
            break;
        }
    }
    SWR_CHECK_ACC(c, idx == want, "index %u, the first map holding p is %u", idx, want);
    /* The test is a documented threshold (w > 0, |x| <= w, |y| <= w) on
     * rounded dot products: a coordinate of G p carries at most 4 roundings
     * of the terms |G_ij p_j| (eps each, to nearest or directed), so when
     * w, w - |x| or w - |y| of a map up to the chosen one is within 8 eps of
     * the sum of those magnitudes, p is on the map's border and the caller's
     * rounding mode decides which map holds it. */
    for (size_t k = 0; k < count && k <= want; ++k) {
        const double* g = G[k].m;
        double mag[4];
        for (int r = 0; r < 4; ++r)
            mag[r] = fabs(g[r] * p.x) + fabs(g[4 + r] * p.y) + fabs(g[8 + r] * p.z) + fabs(g[12 + r]);
        swarp_vec4 q = xf(&G[k], (swarp_vec4){p.x, p.y, p.z, 1});
        double tol = 8 * DBL_EPSILON;
        if (fabs(q.w) <= tol * mag[3] || fabs(q.w - fabs(q.x)) <= tol * (mag[3] + mag[0]) ||
            fabs(q.w - fabs(q.y)) <= tol * (mag[3] + mag[1]))
            c->rounding_edge = 1;
    }
}

const swr_entry swr_entries_lixel[] = {
    {"swarp_lixel_solve5", "lixel", e_lixel_solve5},
    {"swarp_lixel_matrix", "lixel", e_lixel_matrix},
    {"swarp_lixel_restrict", "lixel", e_lixel_restrict},
    {"swarp_lixel_twist_for_line", "lixel", e_lixel_twist_for_line},
    {"swarp_lixel_factor", "lixel", e_lixel_factor},
    {"swarp_lixel_split", "lixel", e_lixel_split},
    {"swarp_lixel_select", "lixel", e_lixel_select},
    {NULL, NULL, NULL},
};
