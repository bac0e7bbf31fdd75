/* Hard-case / fuzz entries for the extras ([KOZ] §14.2.2 cube-map faces in
 * post-projective space, [RHS] §4.3 min-depth near plane) and the plan's
 * name functions, in the table-driven shape of swr.h.  Properties, each
 * against an independent evaluation: the faces are exactly the unit-cube
 * faces back-facing from P (d_i = 1 - P.N_i > 0: 3..5 outside, 6 inside),
 * with distance d_i, an orthonormal frame and view_proj = proj view; a
 * looked-up point lies on its face of the unit cube at S = P + u/a; the
 * pyramid minimum equals the direct minimum (min is exact); the near plane
 * is max(n, min_depth (1 - margin)) below f; names are non-empty, "?"
 * exactly outside the enum. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_cube_faces)
SWR_WEAK(swarp_cube_lookup)
SWR_WEAK(swarp_mindepth_pyramid)
SWR_WEAK(swarp_mindepth_direct)
SWR_WEAK(swarp_mindepth_near)
SWR_WEAK(swarp_plan_warp_name)
SWR_WEAK(swarp_plan_scheme_name)
SWR_WEAK(swarp_plan_filter_name)

/* ---- cube ---------------------------------------------------------------- */
static const double axis_n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

typedef struct cube_args {
    swarp_vec4 L;
    swarp_cube_options o;
    int use_o;
    double P[3], d[6]; /* P = xyz/w and d_i = 1 - P.N_i */
    int valid;         /* no argument error: P and d are meaningful */
} cube_args;

/* a light inside, outside, on a face plane, on an edge, at a corner, behind
 * the camera (w < 0), at infinity (w = 0), far away */
static void gen_cube(swr_ctx* c, cube_args* a) {
    memset(a, 0, sizeof *a);
    static const double brk[] = {1.0, -1.0, 0.0};
    double p[3];
    uint8_t where = swr_u8(c) % 8;
    for (int k = 0; k < 3; ++k) p[k] = swr_num(c, -3, 3, brk, 3);
    if (where == 1) p[swr_u8(c) % 3] = swr_one_in(c, 2) ? 1 : -1;       /* on a face plane */
    if (where == 2) p[0] = 1, p[1] = -1;                                /* on an edge line */
    if (where == 3) p[0] = p[1] = p[2] = 1;                             /* a corner */
    if (where == 4) for (int k = 0; k < 3; ++k) p[k] *= 1e6;           /* far */
    static const double brk_w[] = {0.0, 1.0, -1.0, 1e-300};
    double w = swr_one_in(c, 3) ? 1.0 : swr_num(c, -2, 2, brk_w, 4);
    a->L.x = p[0] * w, a->L.y = p[1] * w, a->L.z = p[2] * w, a->L.w = w;
    a->use_o = !swr_one_in(c, 4);
    static const double brk_z[] = {0.0, 1.0, 0.01};
    a->o.z1 = swr_one_in(c, 2) ? 0 : swr_num(c, 0, 1, brk_z, 3);
    a->o.depth_range = (swarp_depth_range)swr_enum(c, 3);
    a->o._reserved[swr_u8(c) % 5] = swr_reserved(c);
    swr_args(c, "light (%.17g %.17g %.17g %.17g) z1 %g depth %d", a->L.x, a->L.y, a->L.z, a->L.w, a->o.z1, (int)a->o.depth_range);
}
static void expect_cube(swr_ctx* c, cube_args* a) {
    int ok = 1;
    if (!swr_isfin(a->L.x) || !swr_isfin(a->L.y) || !swr_isfin(a->L.z) || !swr_isfin(a->L.w))
        swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
    if (a->use_o) {
        for (int i = 0; i < 5; ++i)
            if (a->o._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO), ok = 0;
        if ((int)a->o.depth_range < 0 || (int)a->o.depth_range > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM), ok = 0;
        if (!swr_isfin(a->o.z1)) swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
        else if (a->o.z1 != 0 && !(a->o.z1 > 0 && a->o.z1 < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE), ok = 0;
    }
    if (ok && a->L.w == 0) swr_expect(c, SWARP_ERR_CUBE_LIGHT_AT_INFINITY), ok = 0;
    swr_domain(c, SWARP_ERR_CUBE_LIGHT_AT_INFINITY); /* P too far for finite matrices */
    swr_domain(c, SWARP_ERR_NON_FINITE);             /* xyz/w overflows */
    if (!ok) return;
    a->P[0] = a->L.x / a->L.w, a->P[1] = a->L.y / a->L.w, a->P[2] = a->L.z / a->L.w;
    for (int i = 0; i < 6; ++i) a->d[i] = 1 - (a->P[0] * axis_n[i][0] + a->P[1] * axis_n[i][1] + a->P[2] * axis_n[i][2]);
    a->valid = swr_isfin(a->P[0]) && swr_isfin(a->P[1]) && swr_isfin(a->P[2]);
    /* the face matrices scale with |P| / d_i: that is their sensitivity; far
     * lights meet the "too far for finite matrices" threshold */
    double pm = fmax(fabs(a->P[0]), fmax(fabs(a->P[1]), fabs(a->P[2]))), dmin = INFINITY;
    for (int i = 0; i < 6; ++i)
        if (a->d[i] > 0) dmin = fmin(dmin, a->d[i]);
    if (dmin < INFINITY) swr_cond(c, (1 + pm) / dmin);
    int on_plane = 0; /* P within rounding of a face plane: in or out is up to the rounding */
    for (int i = 0; i < 6; ++i) on_plane |= fabs(a->d[i]) <= 1e-9 * (1 + pm);
    if (pm > 1e9 || on_plane) c->rounding_edge = 1;
    /* Z_1 within rounding of 1: far - near = d (1 - Z_1) may round to 0 */
    if (a->use_o && 1 - a->o.z1 < 1e-12) c->rounding_edge = 1;
}

static void e_cube_faces(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cube_faces);
    cube_args a;
    gen_cube(c, &a);
    size_t cap = swr_one_in(c, 8) ? swr_u8(c) % 6 : SWARP_CUBE_MAX_FACES;
    const swarp_vec4* pl = swr_in(c, &a.L);
    swarp_cube_face f[SWARP_CUBE_MAX_FACES];
    size_t count;
    swarp_cube_face* pf = swr_out(c, f, sizeof f, cap ? SWR_REQ : SWR_OPT);
    size_t* pc = swr_out(c, &count, sizeof count, SWR_REQ);
    expect_cube(c, &a);
    int want = 0;
    for (int i = 0; i < 6; ++i) want += a.valid && a.d[i] > 0;
    if (a.valid && (size_t)want > cap) swr_expect(c, SWARP_ERR_CAPACITY);
    if (!pf && cap == 0) swr_domain(c, SWARP_ERR_CAPACITY);
    swr_domain(c, SWARP_ERR_DEGENERATE);
    swarp_status st = SWR_CALL(c, swarp_cube_faces(pl, a.use_o ? &a.o : NULL, pf, cap, pc));
    if (st == SWARP_ERR_CAPACITY) { /* the needed count is written */
        if (a.valid) SWR_CHECK(c, count == (size_t)want, "CAPACITY with count %zu, %d faces back-facing", count, want);
        swr_fill(&count, sizeof count);
    }
    if (!swr_done(c, st)) return;
    /* exactly the back-facing faces, in SWARP_CUBE_FACE_* order */
    size_t k = 0;
    for (uint32_t i = 0; i < 6; ++i) {
        /* a face within rounding of P: either way */
        if (fabs(a.d[i]) <= 1e-12 * (1 + fabs(a.P[i / 2]))) {
            if (k < count && f[k].face == i) ++k;
            continue;
        }
        if (!(a.d[i] > 0)) continue;
        SWR_CHECK(c, k < count && f[k].face == i, "face %u (d = %g) missing or out of order", i, a.d[i]);
        if (k >= count || f[k].face != i) return;
        const swarp_cube_face* F = &f[k++];
        swr_rec(c, "distance", F->distance);
        for (int e = 0; e < 16; ++e) swr_rec(c, "view_proj", F->view_proj.m[e]);
        swr_close(c, "distance", F->distance, a.d[i], 1e-12, 1);
        SWR_CHECK(c, F->normal.x == axis_n[i][0] && F->normal.y == axis_n[i][1] && F->normal.z == axis_n[i][2], "face %u normal", i);
        SWR_CHECK(c, F->inverse == (a.L.w < 0), "face %u inverse %u with w %g", i, F->inverse, a.L.w);
        const swarp_vec3 r = F->right, u = F->up, n = F->normal;
        double rr = r.x * r.x + r.y * r.y + r.z * r.z, uu = u.x * u.x + u.y * u.y + u.z * u.z;
        double ru = r.x * u.x + r.y * u.y + r.z * u.z, rn = r.x * n.x + r.y * n.y + r.z * n.z, un = u.x * n.x + u.y * n.y + u.z * n.z;
        SWR_CHECK(c, fabs(rr - 1) <= 1e-12 && fabs(uu - 1) <= 1e-12 && fabs(ru) <= 1e-12 && fabs(rn) <= 1e-12 && fabs(un) <= 1e-12,
                  "face %u frame not orthonormal", i);
        /* view_proj = proj view, normwise */
        double sc = 0;
        for (int e = 0; e < 16; ++e) sc = fmax(sc, fabs(F->view_proj.m[e]));
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row) {
                long double acc = 0, mag = 0;
                for (int q = 0; q < 4; ++q) {
                    long double t = (long double)F->proj.m[q * 4 + row] * F->view.m[col * 4 + q];
                    acc += t, mag += fabsl(t);
                }
                SWR_CHECK_ACC(c, fabsl(acc - F->view_proj.m[col * 4 + row]) <= 1e-12L * (mag + sc) + 1e-300L, "face %u view_proj[%d][%d]",
                              i, row, col);
            }
    }
    SWR_CHECK(c, k == count, "%zu faces written, %zu expected", count, k);
    int on_plane = 0;
    for (int i = 0; i < 6; ++i) on_plane |= fabs(a.d[i]) <= 1e-12 * (1 + fabs(a.P[i / 2]));
    if (!on_plane) SWR_CHECK(c, count >= 3 && count <= 6, "%zu faces", count);
    if (count < SWARP_CUBE_MAX_FACES) SWR_CHECK(c, swr_untouched(f + count, sizeof f - count * sizeof f[0]), "wrote past count");
}

static void e_cube_lookup(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cube_lookup);
    cube_args a;
    gen_cube(c, &a);
    static const double brk_v[] = {1.0, -1.0, 0.0};
    double vr = swr_one_in(c, 4) ? 1.5 : 1.0; /* mostly inside the unit cube (the view), sometimes on or past it */
    swarp_vec3 V = {swr_num(c, -vr, vr, brk_v, 3), swr_num(c, -vr, vr, brk_v, 3), swr_num(c, -vr, vr, brk_v, 3)};
    if (swr_one_in(c, 16) && swr_isfin(a.L.w) && a.L.w != 0) V.x = a.L.x / a.L.w, V.y = a.L.y / a.L.w, V.z = a.L.z / a.L.w; /* at the light */
    const swarp_vec4* pl = swr_in(c, &a.L);
    const swarp_vec3* pv = swr_in(c, &V);
    uint32_t face;
    swarp_vec3 S;
    double depth;
    uint32_t* pf = swr_out(c, &face, sizeof face, SWR_OPT);
    swarp_vec3* ps = swr_out(c, &S, sizeof S, SWR_OPT);
    double* pd = swr_out(c, &depth, sizeof depth, SWR_OPT);
    expect_cube(c, &a);
    if (!swr_isfin(V.x) || !swr_isfin(V.y) || !swr_isfin(V.z)) swr_expect(c, SWARP_ERR_NON_FINITE), a.valid = 0;
    /* a = max over the back-facing faces of (u.N_i)/d_i, u = V - P */
    double amax = -INFINITY, second = -INFINITY, u[3] = {0, 0, 0};
    int arg = -1;
    if (a.valid) {
        for (int k = 0; k < 3; ++k) u[k] = (&V.x)[k] - a.P[k];
        for (int i = 0; i < 6; ++i) {
            if (!(a.d[i] > 0)) continue;
            double ai = (u[0] * axis_n[i][0] + u[1] * axis_n[i][1] + u[2] * axis_n[i][2]) / a.d[i];
            if (ai > amax) second = amax, amax = ai, arg = i;
            else if (ai > second) second = ai;
        }
        double um = fmax(fabs(u[0]), fmax(fabs(u[1]), fabs(u[2])));
        swr_cond(c, 1 + um); /* S = P + u/a: |P| and |u| cancel to a point of the unit cube */
        if (!(amax > 1e-9 * um)) swr_domain(c, SWARP_ERR_CUBE_POINT_UNCOVERED), c->rounding_edge = 1;
        if (amax < -1e-9 * um || arg < 0) swr_expect(c, SWARP_ERR_CUBE_POINT_UNCOVERED);
        /* S = P + u/a is not representable for |u| near DBL_MAX and a < 1:
         * evaluated independently in long double (wider exponent range), the
         * documented SWARP_ERR_OVERFLOW beyond DBL_MAX, either way within
         * 1e-12 of it (the double rounding of u and a) */
        long double ul[3], al = -INFINITY;
        for (int k = 0; k < 3; ++k) ul[k] = (long double)(&V.x)[k] - a.P[k];
        for (int i = 0; i < 6; ++i)
            if (a.d[i] > 0) al = fmaxl(al, (ul[0] * axis_n[i][0] + ul[1] * axis_n[i][1] + ul[2] * axis_n[i][2]) / a.d[i]);
        if (al > 0) {
            for (int k = 0; k < 3; ++k) {
                long double Sk = fabsl(a.P[k] + ul[k] / al);
                if (Sk > DBL_MAX * (1 + 1e-12L)) swr_expect(c, SWARP_ERR_OVERFLOW);
                else if (Sk > DBL_MAX * (1 - 1e-12L)) swr_domain(c, SWARP_ERR_OVERFLOW);
            }
        }
    }
    swr_domain(c, SWARP_ERR_CUBE_POINT_UNCOVERED);
    if (!swr_done(c, SWR_CALL(c, swarp_cube_lookup(pl, a.use_o ? &a.o : NULL, pv, pf, ps, pd)))) return;
    if (ps) swr_rec(c, "S", S.x), swr_rec(c, "S", S.y), swr_rec(c, "S", S.z);
    if (pd) swr_rec(c, "depth", depth);
    if (!a.valid || arg < 0 || !(amax > 0)) return;
    /* S on the unit cube's surface, on the chosen face; S = P + u/a */
    /* the reference S = P + u/a in long double: with a component of V near
     * DBL_MAX, a = (u . N)/d overflows in double (amax = inf, u/amax = 0)
     * while the exact S is on the cube (the contract) */
    long double ul[3], al = -INFINITY;
    for (int k = 0; k < 3; ++k) ul[k] = (long double)(&V.x)[k] - a.P[k];
    for (int i = 0; i < 6; ++i)
        if (a.d[i] > 0) al = fmaxl(al, (ul[0] * axis_n[i][0] + ul[1] * axis_n[i][1] + ul[2] * axis_n[i][2]) / a.d[i]);
    const double ua[3] = {(double)(ul[0] / al), (double)(ul[1] / al), (double)(ul[2] / al)};
    {
        /* the depth alpha + beta/a ([KOZ] Listing 14-1's projective transform
         * of a, units of d = 1) moves by |beta/a| times a's relative error;
         * a = (u . N)/d carries that of u = V - P and d = 1 - P . N (P = xyz/w
         * rounded in the caller's mode).  For Z_1 near 1, |beta| ~ 2/(1 - Z_1)
         * while the depth is O(1): e.g. Z_1 = 1 - 1e-9 and a = 1 + 1e-12 give
         * terms of 2e9 cancelling to 1.002, which the rounding mode moves by
         * 5e-7 -- the conditioning of the result, not a library loss (no
         * formula avoids it: the depth's derivative in a is beta/a^2) */
        double z1c = a.use_o && a.o.z1 != 0 ? a.o.z1 : 0.01, pm = fabs(a.P[0]) + fabs(a.P[1]) + fabs(a.P[2]);
        double beta = a.L.w < 0 ? z1c : 2 * z1c / (1 - z1c); /* |beta|, [-1, 1] (twice the [0, 1] one) */
        /* in long double: |V| near DBL_MAX overflows u . N and a in double */
        const long double un = ul[0] * axis_n[arg][0] + ul[1] * axis_n[arg][1] + ul[2] * axis_n[arg][2];
        const long double vm = fabsl((long double)V.x) + fabsl((long double)V.y) + fabsl((long double)V.z);
        const long double ka = (vm + pm) / fabsl(un) + (1 + pm) / a.d[arg]; /* a's relative condition */
        swr_cond(c, (double)(1 + beta / al * ka));
    }
    double tol = 1e-9 * (1 + fabs(a.P[0]) + fabs(a.P[1]) + fabs(a.P[2]) + fabs(ua[0]) + fabs(ua[1]) + fabs(ua[2]));
    int tie = second > amax * (1 - 1e-9);
    if (pf && !tie) SWR_CHECK(c, face == (uint32_t)arg, "face %u, argmax %d", face, arg);
    if (ps) {
        const double s[3] = {S.x, S.y, S.z};
        for (int k = 0; k < 3; ++k) {
            SWR_CHECK_ACC(c, fabs(s[k] - (a.P[k] + ua[k])) <= tol, "S[%d] = %.17g, P + u/a = %.17g", k, s[k], a.P[k] + ua[k]);
            /* a point of the view (inside the unit cube): the ray from P leaves it at S */
            if (fabs(V.x) <= 1 && fabs(V.y) <= 1 && fabs(V.z) <= 1)
                SWR_CHECK_ACC(c, fabs(s[k]) <= 1 + tol, "S = (%g %g %g) off the cube", S.x, S.y, S.z);
        }
        if (pf && face < 6) {
            double sn = s[0] * axis_n[face][0] + s[1] * axis_n[face][1] + s[2] * axis_n[face][2];
            SWR_CHECK_ACC(c, fabs(sn - 1) <= tol, "S not on face %u (S.N = %.17g)", face, sn);
        }
    }
    double z1 = a.use_o && a.o.z1 != 0 ? a.o.z1 : 0.01;
    if (pd) {
        /* the depth: the projective transform of a with Z_n = Z_1, Z_f = 1
         * (inverse: -Z_1, Z_1) in units of d = 1, [-1, 1] or [0, 1]
         * (swarp_cube_lookup's @brief), in long double; within 64 eps of its
         * terms, |beta/a| carrying a's relative condition (above) */
        /* reversed-Z (3): the [0, 1] depth turned over, 1 - (alpha + beta/a) */
        const int rev = a.use_o && (int)a.o.depth_range == 3;
        const int zo = a.use_o && ((int)a.o.depth_range == 2 || rev);
        const long double n = a.L.w < 0 ? -(long double)z1 : z1, f = a.L.w < 0 ? (long double)z1 : 1.0L;
        const long double alpha = zo ? f / (f - n) : (f + n) / (f - n), beta = zo ? n * f / (n - f) : 2 * n * f / (n - f);
        const long double ref = rev ? 1.0L - (alpha + beta / al) : alpha + beta / al;
        SWR_CHECK_ACC(c, fabsl(depth - ref) <= 64 * DBL_EPSILON * (fabsl(alpha) + fabsl(beta / al) * c->cond) + 1e-300L,
                      "depth %.17g, alpha + beta/a = %.17Lg (cond %g, al %Lg)", depth, ref, c->cond, al);
    }
    if (c->status == SWARP_INFO_CUBE_NEAR_CLIPPED) SWR_CHECK(c, amax <= z1 * (1 + 1e-9), "NEAR_CLIPPED with a = %g >= Z_1 %g", amax, z1);
    else SWR_CHECK(c, amax >= z1 * (1 - 1e-9), "a = %g < Z_1 %g without NEAR_CLIPPED", amax, z1);
}

/* ---- min depth ------------------------------------------------------------- */
#define MD_MAX 24
typedef struct md_args {
    float buf[MD_MAX * (MD_MAX + 3)];
    uint32_t w, h;
    size_t stride;
    double ref; /* the direct minimum over the w x h texels, +inf if all +inf */
    int bad;    /* a NaN / -inf (NON_FINITE) or a negative (OUT_OF_RANGE) */
} md_args;

static void gen_md(swr_ctx* c, md_args* m) {
    m->w = swr_one_in(c, 32) ? 0 : 1 + swr_u8(c) % MD_MAX;
    m->h = swr_one_in(c, 32) ? 0 : 1 + swr_u8(c) % MD_MAX;
    m->stride = m->w + (swr_one_in(c, 3) ? swr_u8(c) % 4 : 0);
    if (swr_one_in(c, 32) && m->w) m->stride = m->w - 1;
    uint8_t kind = swr_u8(c) % 4; /* 0: all cleared, else a scene with some sky */
    /* one byte per texel (the whole case stays within swr_ctx's 4 KiB of
     * bytes): 255 = sky (+inf), else a multiple of a drawn scale, often 0 */
    float scale = (float)swr_num_in(c, 1e-6, 1e4, NULL, 0), base = (float)swr_num_in(c, 0, 1e4, NULL, 0);
    for (size_t i = 0; i < sizeof m->buf / sizeof m->buf[0]; ++i) {
        uint8_t b = kind == 0 ? 255 : swr_u8(c);
        m->buf[i] = b >= 192 ? INFINITY : base + scale * (float)b;
    }
    if (swr_one_in(c, 8)) { /* one edge value: 0, a subnormal, FLT_MAX, NaN, -inf, negative */
        static const float ev[] = {0.0f, 1e-45f, FLT_MAX, NAN, -INFINITY, -1.0f, -0.0f, 1e-38f};
        size_t n = m->h ? (m->h - 1) * m->stride + m->w : 0;
        if (n) m->buf[swr_u32(c) % n] = ev[swr_u8(c) % 8];
    }
    m->ref = INFINITY;
    m->bad = 0;
    for (uint32_t r = 0; r < m->h; ++r)
        for (uint32_t k = 0; k < m->w; ++k) {
            float v = m->buf[r * m->stride + k];
            if (v != 0 && fabsf(v) < FLT_MIN) c->rounding_edge = 1; /* a float subnormal: DAZ reads it as 0 */
            if (v != v || v == -INFINITY) m->bad |= 1;
            else if (v < 0) m->bad |= 2;
            else if (v < m->ref) m->ref = v;
        }
}
static void expect_md(swr_ctx* c, const md_args* m) {
    if (m->w == 0 || m->h == 0 || m->stride < m->w) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT);
    else if (m->bad & 1) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (m->bad & 2) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (m->bad == 3) swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
}
static void check_md(swr_ctx* c, const md_args* m, double got) {
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = got; /* +inf when empty */
    SWR_CHECK(c, got == m->ref || (got == 0 && m->ref == 0), "minimum %.9g, direct scan %.9g", got, m->ref);
    SWR_CHECK(c, (c->status == SWARP_INFO_MINDEPTH_EMPTY) == (m->ref == INFINITY), "%s with minimum %g", swarp_status_name(c->status), got);
}

static void e_mindepth_pyramid(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mindepth_pyramid);
    md_args m;
    gen_md(c, &m);
    size_t need = SWARP_MINDEPTH_SCRATCH(m.w, m.h);
    float scratch[((MD_MAX + 1) / 2) * ((MD_MAX + 1) / 2) + 4];
    size_t cap = swr_one_in(c, 8) ? (need ? need - 1 : 0) : need + swr_u8(c) % 4;
    const float* pd = swr_in(c, m.buf);
    double mn;
    size_t needed;
    float* ps = swr_out(c, scratch, sizeof scratch, cap ? SWR_REQ : SWR_OPT);
    double* pm = swr_out(c, &mn, sizeof mn, SWR_REQ);
    size_t* pn = swr_null(c) ? NULL : &needed;
    if (!pn) swr_expect(c, SWARP_ERR_NULL_POINTER);
    swr_fill(&needed, sizeof needed);
    expect_md(c, &m);
    if (cap < need) swr_expect(c, SWARP_ERR_CAPACITY);
    if (!ps && cap == 0) swr_domain(c, SWARP_ERR_CAPACITY);
    swr_args(c, "w %u h %u stride %zu cap %zu need %zu bad %d ref %g", m.w, m.h, m.stride, cap, need, m.bad, m.ref);
    swarp_status st = SWR_CALL(c, swarp_mindepth_pyramid(pd, m.w, m.h, m.stride, ps, cap, pn, pm));
    /* scratch is work space: written on success (and maybe on error: not an output) */
    if (swarp_status_is_error(st)) swr_fill(scratch, sizeof scratch);
    if (pn && (st == SWARP_OK || st == SWARP_INFO_MINDEPTH_EMPTY || st == SWARP_ERR_CAPACITY))
        SWR_CHECK(c, needed == need, "scratch needed %zu, SWARP_MINDEPTH_SCRATCH %zu", needed, need);
    if (!swr_done(c, st)) return;
    check_md(c, &m, mn);
}
static void e_mindepth_direct(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mindepth_direct);
    md_args m;
    gen_md(c, &m);
    const float* pd = swr_in(c, m.buf);
    double mn;
    double* pm = swr_out(c, &mn, sizeof mn, SWR_REQ);
    expect_md(c, &m);
    if (!swr_done(c, SWR_CALL(c, swarp_mindepth_direct(pd, m.w, m.h, m.stride, pm)))) return;
    check_md(c, &m, mn);
}

static void e_mindepth_near(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mindepth_near);
    static const double brk_n[] = {1e-6, 1.0};
    double n = swr_num(c, 1e-6, 10, brk_n, 2), f = swr_one_in(c, 16) ? n : n * swr_num(c, 1.5, 1e7, NULL, 0);
    const double brk_md[] = {n, f, 0.0, INFINITY};
    double md = swr_num(c, n * 0.5, f * 1.5, brk_md, 4);
    swarp_mindepth_options o;
    memset(&o, 0, sizeof o);
    static const double brk_m[] = {0.0, 1.0, 1e-3};
    o.margin = swr_one_in(c, 2) ? 0 : swr_num(c, 0, 0.5, brk_m, 3);
    o._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use_o = !swr_one_in(c, 4);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    if (!swr_isfin(n) || !swr_isfin(f) || md != md || md == -INFINITY) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (!(n > 0 && f > n)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    if (md < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (use_o) {
        for (int i = 0; i < 4; ++i)
            if (o._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        if (!swr_isfin(o.margin)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (!(o.margin >= 0 && o.margin < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    swr_args(c, "n %.17g f %.17g min_depth %.17g margin %.17g", n, f, md, use_o ? o.margin : -1.0);
    if (!swr_done(c, SWR_CALL(c, swarp_mindepth_near(n, f, md, use_o ? &o : NULL, po)))) return;
    swr_rec(c, "near", out);
    double margin = use_o && o.margin != 0 ? o.margin : 1e-3;
    if (md >= f) {
        SWR_CHECK(c, c->status == SWARP_INFO_MINDEPTH_EMPTY && out == n, "min_depth %g >= far: %s, near %g", md, swarp_status_name(c->status), out);
        return;
    }
    SWR_CHECK(c, c->status == SWARP_OK, "%s for min_depth %g < far", swarp_status_name(c->status), md);
    /* never below n, below f, and nothing the buffer saw is clipped */
    long double want = fmaxl(n, (long double)md * (1 - (long double)margin));
    SWR_CHECK(c, out >= n && out < f, "near' %.17g outside [n, f) = [%.17g, %.17g)", out, n, f);
    if (md > n) SWR_CHECK(c, out <= md, "near' %.17g above min_depth %.17g (would clip)", out, md);
    /* near' = md (1 - margin) in double: 1 - margin rounds (eps/2 relative),
     * the product rounds to eps/2 relative in the normal range but to half a
     * subnormal ulp, DBL_TRUE_MIN/2 absolute, below DBL_MIN (fewer digits
     * there); hence 4 eps relative plus DBL_TRUE_MIN absolute. */
    swr_close_abs(c, "near'", out, want, 4 * DBL_EPSILON, DBL_TRUE_MIN);
}

/* ---- the plan's names --------------------------------------------------------- */
static void names_common(swr_ctx* c, const char* (*fn)(int32_t), int32_t last) {
    int32_t v = swr_one_in(c, 4) ? (int32_t)swr_u32(c) : swr_enum(c, last + 2);
    const char* s = (swr_enter(c), fn(v));
    swr_leave(c, SWARP_OK);
    swr_verdict(c, SWARP_OK, 0);
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = s ? (double)strlen(s) : -1;
    SWR_CHECK(c, s && s[0], "name of %d is %s", (int)v, s ? "empty" : "NULL");
    if (!s) return;
    int valid = v >= 0 && v <= last;
    SWR_CHECK(c, valid == (strcmp(s, "?") != 0), "name of %d is \"%s\"", (int)v, s);
}
/* the enums are int-sized (_FORCE_I32): a cast of the function type is not portable, so wrappers */
static const char* warp_name(int32_t v) { return swarp_plan_warp_name((swarp_plan_warp)v); }
static const char* scheme_name(int32_t v) { return swarp_plan_scheme_name((swarp_plan_scheme)v); }
static const char* filter_name(int32_t v) { return swarp_plan_filter_name((swarp_plan_filter)v); }
static void e_plan_warp_name(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_plan_warp_name);
    names_common(c, warp_name, SWARP_PLAN_WARP_PSM);
}
static void e_plan_scheme_name(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_plan_scheme_name);
    names_common(c, scheme_name, SWARP_PLAN_SCHEME_LOG);
}
static void e_plan_filter_name(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_plan_filter_name);
    names_common(c, filter_name, SWARP_PLAN_FILTER_LVSM);
}

const swr_entry swr_entries_extras[] = {
    {"swarp_cube_faces", "extras", e_cube_faces},
    {"swarp_cube_lookup", "extras", e_cube_lookup},
    {"swarp_mindepth_pyramid", "extras", e_mindepth_pyramid},
    {"swarp_mindepth_direct", "extras", e_mindepth_direct},
    {"swarp_mindepth_near", "extras", e_mindepth_near},
    {"swarp_plan_warp_name", "plan", e_plan_warp_name},
    {"swarp_plan_scheme_name", "plan", e_plan_scheme_name},
    {"swarp_plan_filter_name", "plan", e_plan_filter_name},
    {NULL, NULL, NULL},
};
