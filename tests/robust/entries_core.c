/* Hard-case / fuzz entries for the core: status and version, the mat4
 * helpers, the closed-form warp parameters ([RHS] (3.2)-(3.5), (4.2),
 * [GMNPR] (2), (8), (9)), Lloyd's error metric ([RHS] (2.3)-(2.8)) and the
 * split schemes ([RHS] (3.6)-(3.8), (4.1)).  One function per entry point;
 * see swr.h for the invariant.  References are written from the papers in
 * long double, independently of src/. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_mat4_to_float)
SWR_WEAK(swarp_mat4_mul)
SWR_WEAK(swarp_mat4_invert)
SWR_WEAK(swarp_mat4_transform)
SWR_WEAK(swarp_warp_nopt)
SWR_WEAK(swarp_warp_nopt_pseudo)
SWR_WEAK(swarp_warp_eta)
SWR_WEAK(swarp_warp_wlz)
SWR_WEAK(swarp_warp_nrepar)
SWR_WEAK(swarp_gmnpr_psi)
SWR_WEAK(swarp_gmnpr_offset)
SWR_WEAK(swarp_gmnpr_F)
SWR_WEAK(swarp_gmnpr_lambda12)
SWR_WEAK(swarp_gmnpr_lambda)
SWR_WEAK(swarp_gmnpr_lambda_lispsm)
SWR_WEAK(swarp_gmnpr_lambda_glpr)
SWR_WEAK(swarp_error_mx)
SWR_WEAK(swarp_error_mz)
SWR_WEAK(swarp_error_max)
SWR_WEAK(swarp_error_split_curve)
SWR_WEAK(swarp_error_split_max)
SWR_WEAK(swarp_split_uniform)
SWR_WEAK(swarp_split_log)
SWR_WEAK(swarp_split_practical)
SWR_WEAK(swarp_split_pseudo)

#define PI_ 3.14159265358979323846
#define HALF_PI 1.57079632679489661923

/* ------------------------------------------------------------------------ */
/* status, version                                                           */
/* ------------------------------------------------------------------------ */
static const int known_codes[] = {
#define X(name, value, msg) value,
    SWARP_STATUS_LIST(X)
#undef X
};

static void e_status(swr_ctx* c) {
    size_t nk = sizeof known_codes / sizeof known_codes[0];
    uint32_t r = swr_u32(c);
    int known = swr_one_in(c, 4) ? 0 : 1;
    swarp_status s = known ? (swarp_status)known_codes[r % nk] : (swarp_status)(int32_t)r;
    const char* str = swarp_status_string(s);
    const char* name = swarp_status_name(s);
    int err = swarp_status_is_error(s);
    c->called = 1;
    c->rec[c->n_rec++] = err;
    SWR_CHECK(c, str && name, "NULL string for status %d", (int)s);
    int v = (int)s;
    SWR_CHECK(c, err == !(v == 0 || (v >= 1000 && v <= 1999)), "is_error(%d) = %d", v, err);
    if (known) SWR_CHECK(c, name && strncmp(name, "SWARP_", 6) == 0, "name of %d is %s", v, name);
    SWR_CHECK(c, swarp_version_number() == SWARP_VERSION_NUMBER, "version number");
    SWR_CHECK(c, strcmp(swarp_version_string(), SWARP_VERSION_STRING) == 0, "version string");
}

/* ------------------------------------------------------------------------ */
/* mat4                                                                      */
/* ------------------------------------------------------------------------ */
static void gen_mat(swr_ctx* c, swarp_mat4* m) {
    static const double brk[] = {0.0, 1.0, -1.0, 1e-9, FLT_MAX, -FLT_MAX};
    uint8_t kind = swr_u8(c) % 6;
    double scale = kind == 1 ? 1e6 : kind == 2 ? 1e-6 : kind == 3 ? 1e150 : 1.0;
    for (int i = 0; i < 16; ++i) m->m[i] = scale * swr_num_in(c, -10.0, 10.0, brk, 3);
    if (swr_one_in(c, 4)) m->m[swr_u8(c) % 16] = swr_num(c, -10.0, 10.0, brk, 6); /* an edge value */
    if (kind == 4) { /* a projection-like matrix with a large translation */
        memset(m->m, 0, sizeof m->m);
        m->m[0] = swr_num(c, 0.1, 10, NULL, 0);
        m->m[5] = swr_num(c, 0.1, 10, NULL, 0);
        m->m[10] = swr_num(c, -2, 0, NULL, 0);
        m->m[11] = -1.0;
        m->m[14] = swr_num(c, -2, 0, NULL, 0);
        m->m[12] = swr_offset(c);
    }
    if (kind == 5) { /* rank-deficient, plus a tiny perturbation */
        int a = swr_u8(c) % 4, b = (a + 1 + swr_u8(c) % 3) % 4;
        double e = swr_num(c, 0, 1e-12, NULL, 0);
        for (int r = 0; r < 4; ++r) m->m[b * 4 + r] = m->m[a * 4 + r] * 2.0 + (r == 0 ? e : 0.0);
    }
}
static int mat_finite(const swarp_mat4* m) {
    for (int i = 0; i < 16; ++i)
        if (!swr_isfin(m->m[i])) return 0;
    return 1;
}

static void e_mat4_to_float(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mat4_to_float);
    swarp_mat4 m;
    gen_mat(c, &m);
    int null_in = swr_null(c), null_out = swr_null(c);
    float out[16];
    swr_fill(out, sizeof out);
    if (null_in || null_out) swr_expect(c, SWARP_ERR_NULL_POINTER);
    for (int i = 0; i < 16; ++i)
        if (!swr_isfin(m.m[i]) || fabs(m.m[i]) > FLT_MAX) swr_expect(c, SWARP_ERR_NON_FINITE);
    swarp_mat4 keep = m;
    swarp_status st = SWR_CALL(c, swarp_mat4_to_float(null_in ? NULL : &m, null_out ? NULL : out));
    SWR_CHECK(c, memcmp(&keep, &m, sizeof m) == 0, "input modified");
    if (!swr_verdict(c, st, 1, (void*)out, sizeof out)) return;
    c->tol_min = 0x1p-23; /* one float ulp: the conversion rounds in the caller's mode */
    for (int i = 0; i < 16; ++i) {
        swr_rec(c, "out[i]", out[i]);
        volatile double src = m.m[i];
        volatile float want;
        swr_enter(c); /* the cast rounds in the same mode as the library did */
        want = (float)src;
        swr_leave(c, SWARP_OK);
        SWR_CHECK(c, out[i] == want, "out[%d] = %.9g, (float)m = %.9g", i, out[i], (double)want);
    }
}

static void e_mat4_mul(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mat4_mul);
    swarp_mat4 a, b, r;
    gen_mat(c, &a);
    gen_mat(c, &b);
    int alias = swr_u8(c) % 8; /* 0: r = a, 1: r = b */
    int n_a = swr_null(c), n_b = swr_null(c), n_r = swr_null(c);
    if (n_a || n_b || n_r) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!mat_finite(&a) || !mat_finite(&b)) swr_expect(c, SWARP_ERR_NON_FINITE);
    /* reference in long double; a product that overflows double must be
     * refused, one near the limit may be */
    long double ref[16], mag[16];
    int overflow = 0, near_overflow = 0;
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            long double s = 0, sa = 0;
            for (int k = 0; k < 4; ++k) {
                long double t = (long double)a.m[k * 4 + row] * b.m[col * 4 + k];
                s += t;
                sa += fabsl(t);
                if (fabsl(t) > DBL_MAX / 8) near_overflow = 1;
            }
            ref[col * 4 + row] = s;
            mag[col * 4 + row] = sa;
            if (fabsl(s) > (long double)DBL_MAX * (1.0L + 1e-15L)) overflow = 1;
        }
    if (mat_finite(&a) && mat_finite(&b)) {
        if (overflow) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (near_overflow) swr_allow(c, SWARP_ERR_NON_FINITE);
        c->rounding_edge = overflow || near_overflow;
    }
    swarp_mat4 ka = a, kb = b;
    swarp_mat4* out = &r;
    if (alias == 0) out = &a;
    else if (alias == 1) out = &b;
    else swr_fill(&r, sizeof r);
    swarp_status st = SWR_CALL(c, swarp_mat4_mul(n_a ? NULL : &a, n_b ? NULL : &b, n_r ? NULL : out));
    if (alias > 1) {
        SWR_CHECK(c, memcmp(&ka, &a, sizeof a) == 0 && memcmp(&kb, &b, sizeof b) == 0, "input modified");
        if (!swr_verdict(c, st, 1, (void*)&r, sizeof r)) return;
    } else {
        if (swarp_status_is_error(st))
            SWR_CHECK(c, memcmp(&ka, &a, sizeof a) == 0 && memcmp(&kb, &b, sizeof b) == 0,
                      "aliased output modified on error");
        if (!swr_verdict(c, st, 0)) return;
    }
    for (int i = 0; i < 16; ++i) {
        if (ref[i] != 0) swr_cond(c, (double)(mag[i] / fabsl(ref[i])));
        swr_rec(c, "r", out->m[i]);
        long double err = fabsl(out->m[i] - ref[i]);
        SWR_CHECK(c, err <= 8 * DBL_EPSILON * mag[i] + DBL_MIN, "r[%d] = %.17g, reference %.17Lg", i,
                  out->m[i], ref[i]);
    }
}

static void e_mat4_invert(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mat4_invert);
    swarp_mat4 a, r;
    gen_mat(c, &a);
    int n_a = swr_null(c), n_r = swr_null(c);
    if (n_a || n_r) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!mat_finite(&a)) swr_expect(c, SWARP_ERR_NON_FINITE);
    swr_allow(c, SWARP_ERR_SINGULAR);
    swr_fill(&r, sizeof r);
    swarp_mat4 ka = a;
    swarp_status st = SWR_CALL(c, swarp_mat4_invert(n_a ? NULL : &a, n_r ? NULL : &r));
    SWR_CHECK(c, memcmp(&ka, &a, sizeof a) == 0, "input modified");
    if (!swr_verdict(c, st, 1, (void*)&r, sizeof r)) return;
    /* Forward error against an inverse computed in long double (Gauss
     * elimination with partial pivoting, 64-bit mantissa): Gauss-Jordan is
     * forward stable, |X - A^-1| <= c_n eps |A^-1| |A| |A^-1|; c_n = n^3
     * 2^(n-1) = 512 for n = 4 (cubic accumulation times the worst growth of
     * partial pivoting).  A wrong inverse misses by order 1.  (The residual
     * |AX - I| is NOT bounded by eps |A||X| for Gauss-Jordan once A is ill
     * conditioned, which the fuzzer showed.) */
    long double w[4][8];
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) {
            w[row][col] = a.m[col * 4 + row];
            w[row][col + 4] = row == col;
        }
    for (int col = 0; col < 4; ++col) {
        int p = col;
        for (int row = col + 1; row < 4; ++row)
            if (fabsl(w[row][col]) > fabsl(w[p][col])) p = row;
        for (int k = 0; k < 8; ++k) {
            long double t = w[col][k];
            w[col][k] = w[p][k];
            w[p][k] = t;
        }
        if (w[col][col] == 0.0L) { /* singular in long double too: no claim */
            swr_cond(c, INFINITY);
            return;
        }
        for (int row = 0; row < 4; ++row) {
            if (row == col) continue;
            long double fct = w[row][col] / w[col][col];
            for (int k = 0; k < 8; ++k) w[row][k] -= fct * w[col][k];
        }
    }
    long double na = 0, nx = 0, err = 0;
    for (int row = 0; row < 4; ++row) {
        long double sa = 0, sx = 0;
        for (int k = 0; k < 4; ++k) {
            w[row][k + 4] /= w[row][row];
            sa += fabsl((long double)a.m[k * 4 + row]);
        }
        for (int k = 0; k < 4; ++k) sx += fabsl(w[row][k + 4]);
        if (sa > na) na = sa;
        if (sx > nx) nx = sx;
    }
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) {
            long double d = fabsl(r.m[col * 4 + row] - w[row][col + 4]);
            if (d > err) err = d;
        }
    for (int i = 0; i < 16; ++i) swr_rec(c, "inverse", r.m[i]);
    swr_cond(c, (double)(na * nx));
    /* Beyond kappa = 1/(512 eps) the bound says nothing (it exceeds |A^-1|);
     * there the library still answers SWARP_OK (its singularity threshold is a
     * pivot below 1e-300 of the largest entry) with inverses that are off by
     * many orders of magnitude: reported in docs/quality.md, "findings". */
    if (na * nx <= 1.0L / (512 * DBL_EPSILON))
        SWR_CHECK(c, err <= 512 * DBL_EPSILON * nx * na * nx, "inverse error %.3Lg, |A^-1| = %.3Lg, kappa = %.3Lg", err, nx,
              na * nx);
}

static void e_mat4_transform(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_mat4_transform);
    swarp_mat4 m;
    gen_mat(c, &m);
    swarp_vec3 p;
    double off = swr_offset(c);
    p.x = off + swr_num(c, -100, 100, NULL, 0);
    p.y = swr_num(c, -100, 100, NULL, 0);
    p.z = off + swr_num(c, -100, 100, NULL, 0);
    int n_m = swr_null(c), n_p = swr_null(c), n_o = swr_null(c);
    if (n_m || n_p || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    int fin = mat_finite(&m) && swr_isfin(p.x) && swr_isfin(p.y) && swr_isfin(p.z);
    if (!fin) swr_expect(c, SWARP_ERR_NON_FINITE);
    const double pv[4] = {p.x, p.y, p.z, 1.0};
    long double ref[4], mag[4];
    int overflow = 0, near_overflow = 0;
    for (int row = 0; row < 4; ++row) {
        long double s = 0, sa = 0;
        for (int k = 0; k < 4; ++k) {
            long double t = (long double)m.m[k * 4 + row] * pv[k];
            s += t;
            sa += fabsl(t);
            if (fabsl(t) > DBL_MAX / 8) near_overflow = 1;
        }
        ref[row] = s;
        mag[row] = sa;
        if (fabsl(s) > (long double)DBL_MAX * (1.0L + 1e-15L)) overflow = 1;
    }
    if (fin) {
        if (overflow) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (near_overflow) swr_allow(c, SWARP_ERR_NON_FINITE);
        c->rounding_edge = overflow || near_overflow;
    }
    swarp_vec4 o;
    swr_fill(&o, sizeof o);
    swarp_status st = SWR_CALL(c, swarp_mat4_transform(n_m ? NULL : &m, n_p ? NULL : &p, n_o ? NULL : &o));
    if (!swr_verdict(c, st, 1, (void*)&o, sizeof o)) return;
    double got[4] = {o.x, o.y, o.z, o.w};
    for (int i = 0; i < 4; ++i) {
        if (ref[i] != 0) swr_cond(c, (double)(mag[i] / fabsl(ref[i])));
        swr_rec(c, "out", got[i]);
        SWR_CHECK(c, fabsl(got[i] - ref[i]) <= 8 * DBL_EPSILON * mag[i] + DBL_MIN, "out[%d] = %.17g, ref %.17Lg",
                  i, got[i], ref[i]);
    }
}

/* ------------------------------------------------------------------------ */
/* warp parameters                                                           */
/* ------------------------------------------------------------------------ */
/* [RHS] (3.2): n_opt = d / (sqrt(z_1/z_0) - 1), written as
 * d sqrt(z_0) / (sqrt(z_1) - sqrt(z_0)) */
static long double ref_nopt(const long double* a) {
    /* z_1 - z_0 is exact in long double for double inputs */
    return a[0] * sqrtl(a[1]) * (sqrtl(a[2]) + sqrtl(a[1])) / (a[2] - a[1]);
}
/* [RHS] (4.2) as read in the papers README */
static long double ref_nopt_pseudo(const long double* a) {
    long double d = a[0], z0 = a[1], z1 = a[2], np = a[3], fp = a[4], w = z1 - z0;
    return d / w * (z0 + sqrtl((z0 + np * w) * (z1 - fp * w)));
}

/* d, z_0, z_1 with z_1 = z_0 exactly, within an ulp, or far/near up to 1e7 */
static void gen_depths(swr_ctx* c, double* d, double* z0, double* z1) {
    static const double brk_z[] = {1e-6, 1.0, 1e6};
    static const double brk_r[] = {1.0, 1.0 + 1e-9, 1e7};
    *d = swr_num(c, 1e-3, 1e4, NULL, 0);
    *z0 = swr_num(c, 1e-6, 1e6, brk_z, 3);
    uint8_t k = swr_u8(c) % 8;
    if (k == 0) *z1 = *z0;
    else if (k == 1) *z1 = nextafter(*z0, INFINITY);
    else if (k == 2) *z1 = swr_num(c, 1e-6, 1e7, brk_z, 3);
    else *z1 = *z0 * swr_num(c, 1.0, 1e7, brk_r, 3);
}
static void expect_depths(swr_ctx* c, double d, double z0, double z1) {
    FIN(c, d);
    FIN(c, z0);
    FIN(c, z1);
    if (d <= 0 || z0 <= 0 || z1 < z0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
}
/* The huge-value rule of the header for warp parameters: the exactly
 * degenerate input gives +INFINITY, a value that is finite but exceeds
 * DBL_MAX gives DBL_MAX; both with SWARP_INFO_WARP_UNIFORM.  Returns 1 when
 * the value is an ordinary one (the caller goes on to compare it). */
static int check_huge(swr_ctx* c, const char* what, double v, int degenerate, long double ref) {
    swr_rec_inf(c, what, v);
    if (degenerate) {
        SWR_CHECK(c, c->status == SWARP_INFO_WARP_UNIFORM && v == INFINITY,
                  "degenerate input gives %s, %s = %g (want INFO_WARP_UNIFORM, +inf)", swarp_status_name(c->status), what, v);
        return 0;
    }
    SWR_CHECK(c, v != INFINITY, "%s = +inf for a non-degenerate input", what);
    if (v == DBL_MAX && c->status == SWARP_INFO_WARP_UNIFORM) {
        SWR_CHECK_ACC(c, !(ref < (long double)DBL_MAX * (1 - 1e-12L)), "%s = DBL_MAX where the value is %.6Lg", what, ref);
        return 0;
    }
    if (c->status == SWARP_INFO_WARP_UNIFORM)
        swr_fail(c, "%s: SWARP_INFO_WARP_UNIFORM with %.17g (neither +inf nor DBL_MAX)", what, v);
    if (ref > (long double)DBL_MAX * (1 + 1e-12L))
        swr_fail_acc(c, "%s = %.17g where the value %.6Lg exceeds DBL_MAX (want DBL_MAX + INFO)", what, v, ref);
    return swr_isfin(v);
}

/* SWARP_ERR_OVERFLOW is right when the value exceeds DBL_MAX; a margin of
 * 1e6 leaves room for intermediate terms.  ref < 0 means "no reference". */
static void allow_overflow(swr_ctx* c, long double ref) {
    if (c->n_expect > 0) swr_expect(c, SWARP_ERR_OVERFLOW); /* any of several errors */
    else if (ref < 0 || !(ref < (long double)DBL_MAX * 1e-6L)) swr_allow(c, SWARP_ERR_OVERFLOW);
}

/* n' in a success: finite > 0 (or the huge-value rule) */
static void check_nprime(swr_ctx* c, double n, double z0, double z1, long double ref) {
    if (!check_huge(c, "n_opt", n, z1 == z0, ref)) return;
    SWR_CHECK_ACC(c, n >= 0.0 && (n > 0.0 || ref < DBL_MIN), "n_opt = %g <= 0", n);
    SWR_CHECK(c, c->status == SWARP_OK, "z_1 > z_0 but status %s", swarp_status_name(c->status));
}

static void e_warp_nopt(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_warp_nopt);
    double d, z0, z1;
    gen_depths(c, &d, &z0, &z1);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_depths(c, d, z0, z1);
    swr_args(c, "d=%.17g z_0=%.17g z_1=%.17g", d, z0, z1);
    swarp_status st = SWR_CALL(c, swarp_warp_nopt(d, z0, z1, po));
    if (!swr_done(c, st)) return;
    const double args[3] = {d, z0, z1};
    long double ref = ref_nopt((const long double[]){d, z0, z1});
    check_nprime(c, out, z0, z1, ref);
    if (swr_isfin(out) && z1 != z0 && out != DBL_MAX) swr_close_cond(c, "n_opt [RHS] (3.2)", out, ref_nopt, args, 3);
}

static void e_warp_nopt_pseudo(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_warp_nopt_pseudo);
    static const double brk[] = {0.0, 0.5, 1.0};
    double d, z0, z1;
    gen_depths(c, &d, &z0, &z1);
    double np = swr_num(c, 0.0, 1.0, brk, 3);
    double fp = swr_one_in(c, 8) ? 1.0 - np : swr_num(c, 0.0, 1.0, brk, 3);
    if (swr_one_in(c, 4)) np = fp = 0.0;
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_depths(c, d, z0, z1);
    FIN(c, np);
    FIN(c, fp);
    if (np < 0 || np > 1 || fp < 0 || fp > 1 || !(np + fp < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (fabs(np + fp - 1.0) <= 4 * DBL_EPSILON) c->rounding_edge = 1; /* n_p + f_p < 1 decided by rounding */
    swr_args(c, "d=%.17g z_0=%.17g z_1=%.17g n_p=%.17g f_p=%.17g", d, z0, z1, np, fp);
    swarp_status st = SWR_CALL(c, swarp_warp_nopt_pseudo(d, z0, z1, np, fp, po));
    if (!swr_done(c, st)) return;
    const double args[5] = {d, z0, z1, np, fp};
    long double ref = ref_nopt_pseudo((const long double[]){d, z0, z1, np, fp});
    check_nprime(c, out, z0, z1, ref);
    if (swr_isfin(out) && z1 != z0 && out != DBL_MAX)
        swr_close_cond(c, "n_opt pseudo [RHS] (4.2)", out, ref_nopt_pseudo, args, 5);
}

/* [RHS] (3.3) */
static long double ref_eta(const long double* a) {
    long double g = a[0], th = a[1];
    long double ga = th / 3, gb = th, gc = th + 0.3L * (HALF_PI - th), eb = -0.2L, ec = 0.0L;
    if (g <= ga) return -1.0L;
    if (g <= gb) return -1.0L + (eb + 1.0L) * (g - ga) / (gb - ga);
    if (g <= gc) return eb + (ec - eb) * sinl(HALF_PI * (g - gb) / (gc - gb));
    return ec;
}
static double gen_theta(swr_ctx* c) {
    static const double brk[] = {0.0, HALF_PI, 0.5235987755982988, 1e-9};
    return swr_num(c, 1e-3, HALF_PI - 1e-3, brk, 4);
}
static double gen_gamma(swr_ctx* c, double th) {
    const double brk[] = {0.0, th / 3, th, th + 0.3 * (HALF_PI - th), HALF_PI, 1e-9, HALF_PI - 1e-9};
    return swr_num(c, 0.0, HALF_PI, brk, 7);
}
static void expect_theta(swr_ctx* c, double th) {
    FIN(c, th);
    if (!(th > 0 && th < HALF_PI)) swr_expect(c, SWARP_ERR_FOV);
}
static void expect_gamma(swr_ctx* c, double g) {
    FIN(c, g);
    if (!(g >= 0 && g <= HALF_PI)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
}

static void e_warp_eta(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_warp_eta);
    double th = gen_theta(c), g = gen_gamma(c, th);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_theta(c, th);
    expect_gamma(c, g);
    swr_args(c, "gamma=%.17g theta=%.17g", g, th);
    swarp_status st = SWR_CALL(c, swarp_warp_eta(g, th, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "eta", out);
    SWR_CHECK(c, out >= -1.0 && out <= 0.0, "eta = %.17g outside [-1, 0]", out);
    const double args[2] = {g, th};
    /* eta is a sum of terms of size <= 1 (-0.2 + 0.2 sin(...)): scale 1 */
    swr_close_cond_floor(c, "eta [RHS] (3.3)", out, ref_eta, args, 2, 1.0);
}

/* [RHS] (3.5) */
static long double ref_wlz(const long double* a) {
    long double g = a[0], th = a[1], n = a[2], f = a[3], We = a[4];
    long double Ws = (f - n) / cosl(th);
    long double w = We * cosl(g) + Ws * sinl(th + g);
    if (g <= th) w += Ws * (1.0L - cosl(th - g));
    return w;
}
static void gen_near_far(swr_ctx* c, double* n, double* f) {
    static const double brk_n[] = {1e-6, 1.0};
    static const double brk_r[] = {1.0, 1e7, 1e6};
    *n = swr_num(c, 1e-6, 1e3, brk_n, 2);
    if (swr_one_in(c, 16)) *f = swr_num(c, 1e-6, 1e9, brk_n, 2);
    else *f = *n * swr_num(c, 1.0 + 1e-9, 1e7, brk_r, 3);
}
static void expect_near_far(swr_ctx* c, double n, double f) {
    FIN(c, n);
    FIN(c, f);
    if (!(n > 0 && f > n)) swr_expect(c, SWARP_ERR_NEAR_FAR);
}

static void e_warp_wlz(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_warp_wlz);
    double th = gen_theta(c), g = gen_gamma(c, th), n, f;
    gen_near_far(c, &n, &f);
    double We = swr_num(c, 1e-6, 1e6, NULL, 0);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_theta(c, th);
    expect_gamma(c, g);
    expect_near_far(c, n, f);
    FIN(c, We);
    if (!(We > 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    const double args[5] = {g, th, n, f, We};
    swr_args(c, "gamma=%.17g theta=%.17g n_e=%.17g f_e=%.17g W_e=%.17g", g, th, n, f, We);
    allow_overflow(c, ref_wlz((const long double[]){g, th, n, f, We}));
    swarp_status st = SWR_CALL(c, swarp_warp_wlz(g, th, n, f, We, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "W_lz", out);
    SWR_CHECK_ACC(c, out > 0 || (out == 0 && ref_wlz((const long double[]){g, th, n, f, We}) < DBL_MIN), "W_lz = %g <= 0", out);
    /* a sum of W_e cos and W_s (sin, 1 - cos) terms: scale W_e + 2 W_s */
    swr_close_cond_floor(c, "W_lz [RHS] (3.5)", out, ref_wlz, args, 5, We + 2 * (f - n) / cos(th));
}

/* [RHS] (3.4), second case read as eta sqrt(alpha) + 1 */
static long double ref_nrepar(const long double* a) {
    long double eta = a[0], al = a[1], W = a[2], sa = sqrtl(al);
    if (eta < 0) return W / (al - 1) * (1 + sa - eta * (al - 1)) / (eta + 1);
    return W / (al - 1) * (1 + sa) / (eta * sa + 1);
}
static void e_warp_nrepar(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_warp_nrepar);
    static const double brk_e[] = {-1.0, 0.0, 1.0, -0.2};
    static const double brk_a[] = {1.0, 1e7};
    double eta = swr_num(c, -1.0, 1.0, brk_e, 4);
    double al = swr_num(c, 1.0 + 1e-9, 1e7, brk_a, 2);
    double W = swr_num(c, 1e-6, 1e6, NULL, 0);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    FIN(c, eta);
    FIN(c, al);
    FIN(c, W);
    if (!(eta >= -1 && eta <= 1) || !(al > 1) || !(W > 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swr_args(c, "eta=%.17g alpha=%.17g W_lz=%.17g", eta, al, W);
    swarp_status st = SWR_CALL(c, swarp_warp_nrepar(eta, al, W, po));
    if (!swr_done(c, st)) return;
    const double args[3] = {eta, al, W};
    long double ref = ref_nrepar((const long double[]){eta, al, W});
    if (!check_huge(c, "n_repar", out, eta == -1.0, ref)) return;
    SWR_CHECK_ACC(c, out > 0 || (out == 0 && ref < DBL_MIN), "n_repar = %g <= 0", out);
    swr_close_cond(c, "n_repar [RHS] (3.4)", out, ref_nrepar, args, 3);
}

/* ------------------------------------------------------------------------ */
/* [GMNPR]                                                                   */
/* ------------------------------------------------------------------------ */
/* psi of [GMNPR] (2) */
static long double ref_psi(const long double* a) {
    long double l = a[0], th = a[1], ph = a[2], n = a[3], f = a[4];
    long double t = tanl(ph) / tanl(th);
    if (th >= ph) return 1.0L / tanl(ph) / ((f - n + (f + n) * t) * l * (l + 1));
    return 1.0L / tanl(ph) / (2 * f * l * (l + 1) * tanl(th) / tanl(ph));
}
/* offset phi(lambda, theta) of [GMNPR] (2) */
static long double ref_offset(const long double* a) {
    long double l = a[0], th = a[1], ph = a[2], n = a[3], f = a[4], t = tanl(ph) / tanl(th);
    if (th >= ph) return (f - n + (f + n) * t) * l + n * t - n;
    return f * (2 * l + 1) * t - f;
}
/* the magnitude of its terms (cancellation below it is rounding) */
/* F = psi (z + offset)^2 / z, [GMNPR] (2) */
static long double ref_F(const long double* a) {
    long double o = ref_offset(a), z = a[5];
    return ref_psi(a) * (z + o) * (z + o) / z;
}
/* the magnitude of the offset's terms */
static double offset_terms(double lambda, double theta, double phi, double n, double f) {
    double t = tan(phi) / tan(theta);
    return theta >= phi ? (f - n + (f + n) * t) * lambda + n * t + n : f * (2 * lambda + 1) * t + f;
}
/* lambda_GMNPR of [GMNPR] (8) */
static long double ref_lgmnpr(const long double* a) {
    long double th = a[0], ph = a[1], n = a[2], f = a[3], t = tanl(ph) / tanl(th);
    if (th >= ph) return (n + sqrtl(f * n) - n * t) / (f - n + (f + n) * t);
    return sqrtl(f * n) / (2 * f) / tanl(th / (4 * ph) * 3.14159265358979323846264338327950288L);
}
/* lambda_1 of [GMNPR] (4) with the tan(phi)/tan(theta) reading of (8) */
static long double ref_l1(const long double* a) {
    long double th = a[0], ph = a[1], n = a[2], f = a[3], t = tanl(ph) / tanl(th);
    return (n + sqrtl(f * n) - n * t) / (f - n + (f + n) * t);
}
/* lambda_2 of [GMNPR] (4): (f + sqrt(fn))/(2f) tan(theta)/tan(phi) - 1/2 */
static long double ref_l2(const long double* a) {
    long double th = a[0], ph = a[1], n = a[2], f = a[3];
    return (f + sqrtl(f * n)) / (2 * f) * tanl(th) / tanl(ph) - 0.5L;
}
/* lambda_LiSPSM of [GMNPR] (9) */
static long double ref_llispsm(const long double* a) {
    long double th = a[0], ph = a[1], n = a[2], f = a[3], t = tanl(ph) / tanl(th);
    long double Pn = (n + sqrtl(f * n)) / sinl(th);
    if (th >= ph) return Pn / ((n * t + f - n + f * t) * sinl(th));
    return Pn / (2 * f * tanl(ph) * cosl(th));
}

/* GLPR: offset(lambda, theta) = 0 solved for lambda (docs/parameters.md) */
static long double ref_glpr(const long double* a) {
    long double th = a[0], ph = a[1], n = a[2], f = a[3], t = tanl(ph) / tanl(th);
    return n * (1 - t) / (f - n + (f + n) * t);
}

typedef struct gm_args {
    double lambda, theta, phi, n, f, z;
} gm_args;
/* theta in [0, pi/2] with theta == phi often; phi in (0, pi/2) */
static void gen_gm(swr_ctx* c, gm_args* g, int theta_may_be_zero) {
    static const double brk_l[] = {1e-9, 1.0, 1e9};
    static const double brk_p[] = {0.5235987755982988, 1e-6, HALF_PI - 1e-6};
    g->phi = swr_num(c, 0.01, HALF_PI - 0.01, brk_p, 3);
    const double brk_t[] = {0.0, g->phi, HALF_PI, 1e-9, g->phi + 1e-9, g->phi - 1e-9};
    g->theta = swr_one_in(c, 6) ? g->phi : swr_num(c, theta_may_be_zero ? 0.0 : 1e-9, HALF_PI, brk_t, 6);
    g->lambda = swr_num(c, 1e-3, 1e3, brk_l, 3);
    gen_near_far(c, &g->n, &g->f);
    const double brk_z[] = {g->n, g->f};
    g->z = swr_num(c, g->n, g->f, brk_z, 2);
}
static void expect_gm(swr_ctx* c, const gm_args* g, int theta_zero_ok, int uses_lambda, int uses_z) {
    swr_args(c, "lambda=%.17g theta=%.17g phi=%.17g n=%.17g f=%.17g z=%.17g", g->lambda, g->theta, g->phi, g->n, g->f,
             g->z);
    FIN(c, g->theta);
    FIN(c, g->phi);
    if (!(g->phi > 0 && g->phi < HALF_PI)) swr_expect(c, SWARP_ERR_FOV);
    if (!(theta_zero_ok ? g->theta >= 0 : g->theta > 0) || !(g->theta <= HALF_PI))
        swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    expect_near_far(c, g->n, g->f);
    if (uses_lambda) {
        FIN(c, g->lambda);
        if (!(g->lambda > 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    if (uses_z) {
        FIN(c, g->z);
        if (!(g->z > 0) || (swr_isfin(g->n) && swr_isfin(g->f) && g->f > g->n && !(g->z >= g->n && g->z <= g->f)))
            swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
}

static void e_gmnpr_psi(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_psi);
    gm_args g;
    gen_gm(c, &g, 0);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_gm(c, &g, 0, 1, 0);
    allow_overflow(c, ref_psi((const long double[]){g.lambda, g.theta, g.phi, g.n, g.f}));
    swarp_status st = SWR_CALL(c, swarp_gmnpr_psi(g.lambda, g.theta, g.phi, g.n, g.f, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "psi", out);
    SWR_CHECK(c, out >= 0, "psi = %g < 0", out);
    const double args[5] = {g.lambda, g.theta, g.phi, g.n, g.f};
    swr_close_cond(c, "psi [GMNPR] (2)", out, ref_psi, args, 5);
}

static void e_gmnpr_offset(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_offset);
    gm_args g;
    gen_gm(c, &g, 0);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_gm(c, &g, 0, 1, 0);
    allow_overflow(c, -1);
    swarp_status st = SWR_CALL(c, swarp_gmnpr_offset(g.lambda, g.theta, g.phi, g.n, g.f, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "offset", out);
    const double args[5] = {g.lambda, g.theta, g.phi, g.n, g.f};
    swr_close_cond_floor(c, "offset [GMNPR] (2)", out, ref_offset, args, 5,
                         offset_terms(g.lambda, g.theta, g.phi, g.n, g.f));
}

static void e_gmnpr_F(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_F);
    gm_args g;
    gen_gm(c, &g, 0);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_gm(c, &g, 0, 1, 1);
    allow_overflow(c, -1);
    swarp_status st = SWR_CALL(c, swarp_gmnpr_F(g.lambda, g.theta, g.phi, g.n, g.f, g.z, po));
    if (!swr_done(c, st)) return;
    swr_rec(c, "F", out);
    SWR_CHECK(c, out >= 0, "F = %g < 0", out);
    {
        const double args[6] = {g.lambda, g.theta, g.phi, g.n, g.f, g.z};
        long double zo = (long double)g.z + offset_terms(g.lambda, g.theta, g.phi, g.n, g.f);
        long double scale = ref_psi(&(const long double[]){g.lambda, g.theta, g.phi, g.n, g.f}[0]) * zo * zo / g.z;
        if (!(scale < (long double)DBL_MAX / 4)) c->rounding_edge = 1; /* F near overflow */
        swr_close_cond_floor(c, "F [GMNPR] (2)", out, ref_F, args, 6, (double)fminl(scale, DBL_MAX));
    }
    /* F = psi (z + offset)^2 / z: the three entry points agree, [GMNPR] (2) */
    double psi, off;
    if (swarp_gmnpr_psi && swarp_gmnpr_offset &&
        !swarp_status_is_error(swarp_gmnpr_psi(g.lambda, g.theta, g.phi, g.n, g.f, &psi)) &&
        !swarp_status_is_error(swarp_gmnpr_offset(g.lambda, g.theta, g.phi, g.n, g.f, &off))) {
        long double ref = (long double)psi * ((long double)g.z + off) * ((long double)g.z + off) / g.z;
        long double zo = (long double)g.z + offset_terms(g.lambda, g.theta, g.phi, g.n, g.f);
        long double scale = (long double)psi * zo * zo / g.z;
        /* psi comes back rounded to double: below DBL_MIN (lambda > ~1e160)
         * it is subnormal or 0 with an absolute error up to DBL_TRUE_MIN/2,
         * which the factor (z + phi)^2/z carries into this cross-check (F
         * itself is checked against the long-double ref_F above); likewise
         * the offset rounded to double near a subnormal z, through
         * d/d(off) = 2 psi (z + off)/z */
        long double psi_abs = 0.5L * DBL_TRUE_MIN * zo * zo / g.z + DBL_TRUE_MIN * fabsl((long double)psi * zo / g.z);
        /* with n, f subnormal the common factor X = f - n + (f + n) t (theta
         * >= phi; 2 f otherwise) of psi and offset is formed in double with
         * an absolute error of a few DBL_TRUE_MIN, i.e. relative 8
         * DBL_TRUE_MIN/|X|: psi and offset carry it once each, F's
         * combination (psi (z+off)^2) up to three times.  Negligible
         * (< 2e-15) once X is normal. */
        long double tt = tanl((long double)g.phi) / tanl((long double)g.theta);
        long double X = g.theta >= g.phi ? fabsl((long double)g.f - g.n + ((long double)g.f + g.n) * tt)
                                         : 2.0L * g.f;
        if (X > 0) psi_abs += 3.0L * scale * (8.0L * DBL_TRUE_MIN / X);
        if (!c->rounding_edge)
            SWR_CHECK_ACC(c, fabsl(out - ref) <= 1e-12L * scale + DBL_MIN + psi_abs,
                          "F = %.17g but psi (z+phi)^2/z = %.17Lg", out, ref);
    }
}

static void e_gmnpr_lambda12(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_lambda12);
    gm_args g;
    gen_gm(c, &g, 0);
    int n1 = swr_null(c), n2 = swr_null(c);
    if (n1 || n2) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_gm(c, &g, 0, 0, 0);
    allow_overflow(c, -1);
    double l1, l2;
    swr_fill(&l1, sizeof l1);
    swr_fill(&l2, sizeof l2);
    swarp_status st = SWR_CALL(c, swarp_gmnpr_lambda12(g.theta, g.phi, g.n, g.f, n1 ? NULL : &l1, n2 ? NULL : &l2));
    if (!swr_verdict(c, st, 2, (void*)&l1, sizeof l1, (void*)&l2, sizeof l2)) return;
    swr_rec(c, "lambda_1", l1);
    swr_rec(c, "lambda_2", l2);
    const double args[4] = {g.theta, g.phi, g.n, g.f};
    swr_close_cond(c, "lambda_1 [GMNPR] (4)", l1, ref_l1, args, 4);
    /* a difference of terms of size ~tan(theta)/tan(phi) and 1/2 */
    swr_close_cond_floor(c, "lambda_2 [GMNPR] (4)", l2, ref_l2, args, 4, 0.5 + tan(g.theta) / tan(g.phi));
}

/* The defining property of lambda_GMNPR for theta >= phi: F(n) == F(f). */
static void check_equal_ends(swr_ctx* c, const gm_args* g, double lambda) {
    double Fn, Ff;
    if (!swarp_gmnpr_F || !swr_isfin(lambda)) return;
    if (swarp_status_is_error(swarp_gmnpr_F(lambda, g->theta, g->phi, g->n, g->f, g->n, &Fn)) ||
        swarp_status_is_error(swarp_gmnpr_F(lambda, g->theta, g->phi, g->n, g->f, g->f, &Ff)))
        return;
    /* the equality is as well conditioned as lambda itself */
    SWR_CHECK(c, fabs(Fn - Ff) <= 1e-6 * fmax(Fn, Ff), "F(n) = %.17g != F(f) = %.17g", Fn, Ff);
}

static void e_gmnpr_lambda(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_lambda);
    gm_args g;
    gen_gm(c, &g, 1);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_gm(c, &g, 1, 0, 0);
    swarp_status st = SWR_CALL(c, swarp_gmnpr_lambda(g.theta, g.phi, g.n, g.f, po));
    if (!swr_done(c, st)) return;
    const double args[4] = {g.theta, g.phi, g.n, g.f};
    long double ref = g.theta > 0 ? ref_lgmnpr((const long double[]){g.theta, g.phi, g.n, g.f}) : INFINITY;
    /* theta = 0 is finite by contract (DBL_MAX + INFO_WARP_UNIFORM, documented): not "degenerate" */
    if (!check_huge(c, "lambda_GMNPR", out, 0, ref)) return;
    SWR_CHECK_ACC(c, out > 0, "lambda = %g <= 0", out);
    if (g.theta >= g.phi) SWR_CHECK(c, st == SWARP_OK, "theta >= phi but %s", swarp_status_name(st));
    else SWR_CHECK(c, st == SWARP_INFO_GMNPR_ADJUSTED, "theta < phi but %s", swarp_status_name(st));
    swr_close_cond(c, "lambda_GMNPR [GMNPR] (8)", out, ref_lgmnpr, args, 4);
    if (g.theta >= g.phi) check_equal_ends(c, &g, out);
}

static void e_gmnpr_lambda_lispsm(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_lambda_lispsm);
    gm_args g;
    gen_gm(c, &g, 1);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_gm(c, &g, 1, 0, 0);
    swarp_status st = SWR_CALL(c, swarp_gmnpr_lambda_lispsm(g.theta, g.phi, g.n, g.f, po));
    if (!swr_done(c, st)) return;
    const double args[4] = {g.theta, g.phi, g.n, g.f};
    long double ref = g.theta > 0 ? ref_llispsm((const long double[]){g.theta, g.phi, g.n, g.f}) : INFINITY;
    if (!check_huge(c, "lambda_LiSPSM", out, 0, ref)) return;
    SWR_CHECK_ACC(c, out > 0 || (out == 0 && ref < DBL_MIN), "lambda = %g <= 0", out);
    swr_close_cond(c, "lambda_LiSPSM [GMNPR] (9)", out, ref_llispsm, args, 4);
}

static void e_gmnpr_lambda_glpr(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_gmnpr_lambda_glpr);
    gm_args g;
    gen_gm(c, &g, 1);
    double out;
    double* po = swr_out(c, &out, sizeof out, SWR_REQ);
    expect_gm(c, &g, 1, 0, 0);
    swarp_status st = SWR_CALL(c, swarp_gmnpr_lambda_glpr(g.theta, g.phi, g.n, g.f, po));
    if (!swr_done(c, st)) return;
    if (g.theta <= g.phi) {
        /* no positive solution: lambda_GMNPR is written instead */
        double lg = 0;
        swarp_status sg = swarp_gmnpr_lambda ? SWR_CALL(c, swarp_gmnpr_lambda(g.theta, g.phi, g.n, g.f, &lg)) : SWARP_OK;
        swr_rec_inf(c, "lambda_GLPR", out);
        if (g.theta == 0.0) SWR_CHECK(c, out == DBL_MAX && st == SWARP_INFO_WARP_UNIFORM, "theta = 0: %g, %s", out,
                                      swarp_status_name(st));
        else if (sg == SWARP_INFO_WARP_UNIFORM) SWR_CHECK(c, out == lg, "GLPR %.17g, lambda_GMNPR %.17g (huge)", out, lg);
        else {
            SWR_CHECK(c, st == SWARP_INFO_GLPR_NO_SOLUTION, "theta <= phi but %s", swarp_status_name(st));
            if (swarp_gmnpr_lambda) SWR_CHECK(c, out == lg, "GLPR wrote %.17g, lambda_GMNPR is %.17g", out, lg);
        }
        return;
    }
    swr_rec(c, "lambda_GLPR", out);
    SWR_CHECK_ACC(c, st == SWARP_OK, "theta > phi but %s", swarp_status_name(st));
    SWR_CHECK_ACC(c, out > 0 || (out == 0 && ref_glpr((const long double[]){g.theta, g.phi, g.n, g.f}) < DBL_MIN),
              "lambda_GLPR = %g <= 0", out);
    const double args[4] = {g.theta, g.phi, g.n, g.f};
    swr_close_cond(c, "lambda_GLPR [GMNPR] (2): offset = 0", out, ref_glpr, args, 4);
    if (st == SWARP_OK && swr_isfin(out) && swarp_gmnpr_offset) {
        /* GLPR: F linear in z <=> offset(lambda, theta) = 0 */
        double off;
        /* lambda is only known to the spacing of doubles near it; below
         * DBL_MIN that is DBL_TRUE_MIN (a solution under DBL_TRUE_MIN is
         * written as DBL_TRUE_MIN), which moves the offset by
         * d(offset)/d(lambda) DBL_TRUE_MIN = (f - n + (f + n) t) DBL_TRUE_MIN */
        double d_off = (g.f - g.n + (g.f + g.n) * (tan(g.phi) / tan(g.theta))) * DBL_TRUE_MIN;
        if (!swarp_status_is_error(swarp_gmnpr_offset(out, g.theta, g.phi, g.n, g.f, &off)))
            SWR_CHECK(c, fabs(off) <= 1e-6 * (g.n + fabs(out) * (g.f - g.n)) + 2.0 * d_off,
                      "offset(lambda_GLPR) = %g", off);
    }
}

/* ------------------------------------------------------------------------ */
/* Lloyd's error metric                                                      */
/* ------------------------------------------------------------------------ */
static void gen_cfg(swr_ctx* c, swarp_error_config* cfg) {
    static const double brk_res[] = {1.0, 4096.0, 16384.0};
    memset(cfg, 0, sizeof *cfg);
    gen_near_far(c, &cfg->z_near, &cfg->z_far);
    cfg->theta = gen_theta(c);
    cfg->res_ix = swr_num(c, 1.0, 16384.0, brk_res, 3);
    cfg->res_iy = swr_num(c, 1.0, 16384.0, brk_res, 3);
    cfg->res_s = swr_num(c, 1.0, 16384.0, brk_res, 3);
    cfg->res_t = swr_num(c, 1.0, 16384.0, brk_res, 3);
    if (!swr_one_in(c, 16)) { /* documented order res_ix >= res_iy, res_s >= res_t */
        if (cfg->res_iy > cfg->res_ix) { double t = cfg->res_ix; cfg->res_ix = cfg->res_iy; cfg->res_iy = t; }
        if (cfg->res_t > cfg->res_s) { double t = cfg->res_s; cfg->res_s = cfg->res_t; cfg->res_t = t; }
    }
    cfg->_reserved[swr_u8(c) % 4] = swr_reserved(c);
}
static void expect_cfg(swr_ctx* c, const swarp_error_config* cfg, int uses_near_far) {
    swr_args(c, "near=%.17g far=%.17g theta=%.17g res=%.17g %.17g %.17g %.17g", cfg->z_near, cfg->z_far, cfg->theta,
             cfg->res_ix, cfg->res_iy, cfg->res_s, cfg->res_t);
    if (uses_near_far) expect_near_far(c, cfg->z_near, cfg->z_far);
    expect_theta(c, cfg->theta);
    const double r[4] = {cfg->res_ix, cfg->res_iy, cfg->res_s, cfg->res_t};
    for (int i = 0; i < 4; ++i)
        if (!(r[i] > 0) || !swr_isfin(r[i])) {
            swr_expect(c, SWARP_ERR_RESOLUTION);
            if (!swr_isfin(r[i])) swr_expect(c, SWARP_ERR_NON_FINITE);
        }
    for (int i = 0; i < 4; ++i)
        if (cfg->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
}
static double gen_nprime(swr_ctx* c, double near) {
    const double brk[] = {near, INFINITY, 1e-9, 1e12};
    if (swr_one_in(c, 6)) return INFINITY;
    return swr_num(c, 1e-6, 1e6, brk, 4);
}
static void expect_nprime(swr_ctx* c, double np) {
    if (np != np || np == -INFINITY) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (!(np > 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
}

typedef swarp_status (*err_fn)(const swarp_error_config*, double, double, double*);
static void e_error_curve(swr_ctx* c, err_fn fn, const char* what) {
    swarp_error_config cfg;
    gen_cfg(c, &cfg);
    const double brk_z[] = {cfg.z_near, cfg.z_far};
    double z = swr_num(c, cfg.z_near, cfg.z_far, brk_z, 2);
    double np = gen_nprime(c, cfg.z_near);
    int n_cfg = swr_null(c), n_out = swr_null(c);
    if (n_cfg || n_out) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_cfg(c, &cfg, 1);
    FIN(c, z);
    if (swr_isfin(cfg.z_near) && swr_isfin(cfg.z_far) && cfg.z_near > 0 && cfg.z_far > cfg.z_near && !(z >= cfg.z_near && z <= cfg.z_far))
        swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    expect_nprime(c, np);
    allow_overflow(c, -1);
    double out;
    swr_fill(&out, sizeof out);
    swarp_error_config keep = cfg;
    swarp_status st = SWR_CALL(c, fn(n_cfg ? NULL : &cfg, z, np, n_out ? NULL : &out));
    SWR_CHECK(c, memcmp(&keep, &cfg, sizeof cfg) == 0, "cfg modified");
    if (!swr_verdict(c, st, 1, (void*)&out, sizeof out)) return;
    swr_rec(c, what, out);
    SWR_CHECK(c, out >= 0, "%s = %g < 0", what, out);
    {
        /* [RHS] (2.3)/(2.4) in long double (no underflow there): a true value
         * below DBL_TRUE_MIN/2 (e.g. res_ix = DBL_TRUE_MIN) rounds to 0, as
         * documented; only a representable one must come back positive */
        long double n = cfg.z_near, f = cfg.z_far, zz = z, npl = np, ref;
        long double r = isinf(np) ? 1.0L : (npl + zz - n) / (npl + f - n);
        if (what[2] == 'x')
            ref = (long double)cfg.res_ix / cfg.res_s * (f / zz) * r;
        else
            ref = (long double)cfg.res_iy / cfg.res_t * (f - n) / (2.0L * tanl(cfg.theta)) / zz *
                  (isinf(np) ? 1.0L : (npl + zz - n) / npl * r);
        SWR_CHECK_ACC(c, out > 0 || ref < DBL_TRUE_MIN, "%s = 0 (underflow), reference %.6Lg", what, ref);
    }
    /* the uniform limit (2.7)/(2.8) is the limit of (2.3)/(2.4) */
    if (np == INFINITY) {
        double big;
        if (!swarp_status_is_error(fn(&cfg, z, 1e9 * cfg.z_far, &big)))
            SWR_CHECK(c, fabs(big - out) <= 1e-5 * out, "%s(n' = inf) = %.17g, %s(n' = 1e9 f) = %.17g", what, out,
                      what, big);
    }
}
static void e_error_mx(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_error_mx);
    e_error_curve(c, swarp_error_mx, "m_x");
}
static void e_error_mz(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_error_mz);
    e_error_curve(c, swarp_error_mz, "m_z");
}

static void e_error_max(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_error_max);
    swarp_error_config cfg;
    gen_cfg(c, &cfg);
    double np = gen_nprime(c, cfg.z_near);
    int n_cfg = swr_null(c), n_x = swr_null(c) || swr_one_in(c, 8), n_z = swr_null(c) || swr_one_in(c, 8);
    if (n_cfg) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_x && n_z) swr_allow(c, SWARP_ERR_NULL_POINTER);
    expect_cfg(c, &cfg, 1);
    expect_nprime(c, np);
    allow_overflow(c, -1);
    double mx, mz;
    swr_fill(&mx, sizeof mx);
    swr_fill(&mz, sizeof mz);
    swarp_status st = SWR_CALL(c, swarp_error_max(n_cfg ? NULL : &cfg, np, n_x ? NULL : &mx, n_z ? NULL : &mz));
    if (!swr_verdict(c, st, 2, (void*)&mx, sizeof mx, (void*)&mz, sizeof mz)) return;
    if (!n_x) swr_rec(c, "max m_x", mx);
    if (!n_z) swr_rec(c, "max m_z", mz);
    /* the curves are convex in z: the maximum is at an end point */
    double a, b;
    if (!n_x && swarp_error_mx && SWR_CALL(c, swarp_error_mx(&cfg, cfg.z_near, np, &a)) == st && SWR_CALL(c, swarp_error_mx(&cfg, cfg.z_far, np, &b)) == st)
        SWR_CHECK(c, mx == fmax(a, b), "max m_x = %.17g, ends %.17g %.17g", mx, a, b);
    if (!n_z && swarp_error_mz && SWR_CALL(c, swarp_error_mz(&cfg, cfg.z_near, np, &a)) == st && SWR_CALL(c, swarp_error_mz(&cfg, cfg.z_far, np, &b)) == st)
        SWR_CHECK(c, mz == fmax(a, b), "max m_z = %.17g, ends %.17g %.17g", mz, a, b);
}

#define MAX_M 8
#define MAX_Z 16
typedef struct split_args {
    swarp_error_config cfg;
    double splits[MAX_M + 1], np[MAX_M];
    size_t m;
} split_args;
static void gen_split_args(swr_ctx* c, split_args* s) {
    gen_cfg(c, &s->cfg);
    s->m = swr_one_in(c, 24) ? 0 : 1 + swr_u8(c) % MAX_M;
    double n = s->cfg.z_near, f = s->cfg.z_far;
    uint8_t k = swr_u8(c) % 6;
    for (size_t i = 0; i <= s->m; ++i) {
        double t = s->m ? (double)i / (double)s->m : 0.0;
        s->splits[i] = k == 0 ? n + (f - n) * t : n * pow(f / n, t);
        if (k == 5 && i > 0) s->splits[i] = swr_num(c, n, f, NULL, 0); /* maybe not increasing */
    }
    if (s->m > 0) s->splits[s->m] = f;
    for (size_t i = 0; i < s->m; ++i) s->np[i] = gen_nprime(c, s->splits[i]);
}
static void expect_split_args(swr_ctx* c, const split_args* s) {
    expect_cfg(c, &s->cfg, 0);
    if (s->m == 0) swr_expect(c, SWARP_ERR_SPLIT_COUNT);
    for (size_t i = 0; i <= s->m; ++i) FIN(c, s->splits[i]);
    if (s->m > 0 && !(s->splits[0] > 0)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    for (size_t i = 0; i < s->m; ++i) {
        if (!(s->splits[i + 1] > s->splits[i])) swr_expect(c, SWARP_ERR_NOT_INCREASING);
        expect_nprime(c, s->np[i]);
    }
}

static void e_error_split_curve(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_error_split_curve);
    split_args s;
    gen_split_args(c, &s);
    size_t count = swr_u8(c) % (MAX_Z + 1);
    double z[MAX_Z];
    double lo = s.splits[0], hi = s.m ? s.splits[s.m] : s.splits[0];
    for (size_t k = 0; k < count; ++k) {
        const double brk[] = {lo, hi, s.splits[s.m / 2]};
        z[k] = swr_num(c, lo, hi, brk, 3);
    }
    int n_cfg = swr_null(c), n_sp = swr_null(c), n_np = swr_null(c), n_z = swr_null(c);
    int n_x = swr_null(c) || swr_one_in(c, 8), n_zz = swr_null(c) || swr_one_in(c, 8);
    if (n_cfg || n_sp || n_np || (n_z && count > 0)) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_x && n_zz) swr_allow(c, SWARP_ERR_NULL_POINTER);
    expect_split_args(c, &s);
    int increasing = 1;
    for (size_t i = 0; i < s.m; ++i) increasing &= s.splits[i + 1] > s.splits[i];
    for (size_t k = 0; k < count; ++k) {
        FIN(c, z[k]);
        if (increasing && s.m > 0 && swr_isfin(lo) && swr_isfin(hi) && !(z[k] >= lo && z[k] <= hi))
            swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    allow_overflow(c, -1);
    double mx[MAX_Z], mz[MAX_Z];
    swr_fill(mx, sizeof mx);
    swr_fill(mz, sizeof mz);
    swarp_status st = SWR_CALL(c, swarp_error_split_curve(n_cfg ? NULL : &s.cfg, n_sp ? NULL : s.splits, n_np ? NULL : s.np, s.m,
                                              n_z ? NULL : z, count, n_x ? NULL : mx, n_zz ? NULL : mz));
    if (!swr_verdict(c, st, 2, (void*)mx, sizeof mx, (void*)mz, sizeof mz)) return;
    for (size_t k = 0; k < count; ++k) {
        if (!n_x) swr_rec(c, "m_x", mx[k]);
        if (!n_zz) swr_rec(c, "m_z", mz[k]);
    }
    if (!n_x) SWR_CHECK(c, swr_untouched(mx + count, sizeof mx - count * sizeof mx[0]), "wrote past count");
    /* inside split i the curve is that split's m_x with near/far = its ends */
    if (!n_x && swarp_error_mx)
        for (size_t k = 0; k < count; ++k)
            for (size_t i = 0; i < s.m; ++i)
                if (z[k] > s.splits[i] && z[k] < s.splits[i + 1]) {
                    swarp_error_config ci = s.cfg;
                    ci.z_near = s.splits[i];
                    ci.z_far = s.splits[i + 1];
                    double v;
                    if (!swarp_status_is_error(SWR_CALL(c, swarp_error_mx(&ci, z[k], s.np[i], &v))))
                        SWR_CHECK(c, fabs(v - mx[k]) <= 1e-12 * v, "split curve m_x(%g) = %.17g, m_x of split %zu = %.17g",
                                  z[k], mx[k], i, v);
                }
}

static void e_error_split_max(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_error_split_max);
    split_args s;
    gen_split_args(c, &s);
    int n_cfg = swr_null(c), n_sp = swr_null(c), n_np = swr_null(c);
    int n_sx = swr_one_in(c, 3), n_sz = swr_one_in(c, 3), n_x = swr_one_in(c, 4), n_z = swr_one_in(c, 4);
    if (n_cfg || n_sp || n_np) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_sx && n_sz && n_x && n_z) swr_allow(c, SWARP_ERR_NULL_POINTER);
    expect_split_args(c, &s);
    allow_overflow(c, -1);
    double sx[MAX_M], sz[MAX_M], mx, mz;
    swr_fill(sx, sizeof sx);
    swr_fill(sz, sizeof sz);
    swr_fill(&mx, sizeof mx);
    swr_fill(&mz, sizeof mz);
    swarp_status st = SWR_CALL(c, swarp_error_split_max(n_cfg ? NULL : &s.cfg, n_sp ? NULL : s.splits, n_np ? NULL : s.np, s.m,
                                            n_sx ? NULL : sx, n_sz ? NULL : sz, n_x ? NULL : &mx, n_z ? NULL : &mz));
    if (!swr_verdict(c, st, 4, (void*)sx, sizeof sx, (void*)sz, sizeof sz, (void*)&mx, sizeof mx, (void*)&mz, sizeof mz))
        return;
    double best_x = 0, best_z = 0;
    for (size_t i = 0; i < s.m; ++i) {
        if (!n_sx) { swr_rec(c, "split max m_x", sx[i]); best_x = fmax(best_x, sx[i]); }
        if (!n_sz) { swr_rec(c, "split max m_z", sz[i]); best_z = fmax(best_z, sz[i]); }
    }
    if (!n_x) swr_rec(c, "max m_x", mx);
    if (!n_z) swr_rec(c, "max m_z", mz);
    if (!n_x && !n_sx) SWR_CHECK(c, mx == best_x, "overall max m_x %.17g != max of splits %.17g", mx, best_x);
    if (!n_z && !n_sz) SWR_CHECK(c, mz == best_z, "overall max m_z %.17g != max of splits %.17g", mz, best_z);
}

/* ------------------------------------------------------------------------ */
/* split schemes                                                             */
/* ------------------------------------------------------------------------ */
typedef struct scheme_args {
    double n, f, n_p, f_p, lambda;
    uint32_t m;
    size_t cap;
    int null_out, null_count;
} scheme_args;
enum { SCH_UNIFORM, SCH_LOG, SCH_PRACTICAL, SCH_PSEUDO };

static void e_split_scheme(swr_ctx* c, int kind) {
    scheme_args a;
    static const double brk_l[] = {0.0, 1.0, 0.5};
    gen_near_far(c, &a.n, &a.f);
    const double brk_p[] = {a.n, a.f};
    a.n_p = swr_num(c, a.n, a.f, brk_p, 2);
    a.f_p = swr_num(c, a.n, a.f, brk_p, 2);
    if (a.f_p < a.n_p && !swr_one_in(c, 8)) { double t = a.n_p; a.n_p = a.f_p; a.f_p = t; }
    swr_args(c, "n=%.17g f=%.17g n_p=%.17g f_p=%.17g", a.n, a.f, a.n_p, a.f_p);
    a.lambda = swr_num(c, 0.0, 1.0, brk_l, 3);
    uint8_t mk = swr_u8(c);
    a.m = mk < 200 ? 1u + mk % 16u : mk < 240 ? (uint32_t)(mk % 3) * 31u + 2u /* 2, 33, 64 */
                                           : mk < 250 ? 0u : (uint32_t)swr_u32(c);
    a.cap = swr_one_in(c, 10) ? swr_u8(c) % 70 : SWARP_SPLIT_MAX_COUNT + 1;
    a.null_out = swr_null(c) || swr_one_in(c, 40);
    a.null_count = swr_null(c);
    if (a.null_out && swr_one_in(c, 2)) a.cap = 0; /* out = NULL, capacity = 0 asks for the count */
    if (a.null_count || (a.null_out && a.cap > 0)) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_near_far(c, a.n, a.f);
    if (kind == SCH_PRACTICAL || kind == SCH_PSEUDO) {
        FIN(c, a.lambda);
        if (!(a.lambda >= 0 && a.lambda <= 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    if (kind == SCH_PSEUDO) {
        FIN(c, a.n_p);
        FIN(c, a.f_p);
        if (!(a.n <= a.n_p && a.n_p < a.f_p && a.f_p <= a.f)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    if (a.m == 0 || a.m > SWARP_SPLIT_MAX_COUNT) swr_expect(c, SWARP_ERR_SPLIT_COUNT);
    /* [n, f] (or [n_p, f_p]) too narrow for m distinct doubles */
    double width = a.f - a.n, ulp_f = nextafter(a.f, INFINITY) - a.f;
    if (kind == SCH_PSEUDO && a.f_p - a.n_p < width) width = a.f_p - a.n_p;
    if (swr_isfin(width) && width <= 64.0 * (a.m + 1.0) * ulp_f) {
        swr_allow(c, SWARP_ERR_DEGENERATE);
        /* the documented "[n, f] too narrow for m distinct splits" threshold
         * (src/cascade/split_schemes.c, strict increase of C_i): with C_i a few ulp apart,
         * whether a rounded C_i lands on its neighbour is decided by the
         * rounding mode (e.g. n, f 2 ulp apart, m = 2, DEGENERATE
         * under every directed mode) -- a legitimate rounding edge */
        c->rounding_edge = 1;
    }
    /* log-spaced splits over a subnormal [n, f] (n (f/n)^(i/m)) can be closer
     * than the DBL_TRUE_MIN spacing there although [n, f] is wide: two
     * consecutive references within 2 DBL_TRUE_MIN (the library's rounding
     * bound below DBL_MIN, see the C_i check) have no distinct doubles */
    if (kind != SCH_UNIFORM && a.m >= 1 && a.m <= SWARP_SPLIT_MAX_COUNT && swr_isfin(a.n) && swr_isfin(a.f) &&
        a.n > 0 && a.f > a.n && a.n < DBL_MIN && (kind == SCH_LOG || (swr_isfin(a.lambda) && a.lambda > 0 && a.lambda <= 1))) {
        long double lo = a.n, hi = a.f, prev = lo, lam = kind == SCH_LOG ? 1.0L : a.lambda;
        if (kind == SCH_PSEUDO && swr_isfin(a.n_p) && swr_isfin(a.f_p) && a.n_p > 0 && a.f_p > a.n_p) {
            lo = a.n_p;
            hi = a.f_p;
        }
        for (uint32_t i = 1; i <= a.m; ++i) {
            long double t = (long double)i / a.m;
            long double r = i == a.m ? (long double)a.f
                                     : lam * lo * powl(hi / lo, t) + (1.0L - lam) * (lo + (hi - lo) * t);
            if (r - prev <= 2.0L * DBL_TRUE_MIN) swr_allow(c, SWARP_ERR_DEGENERATE);
            prev = r;
        }
    }
    double out[SWARP_SPLIT_MAX_COUNT + 2];
    size_t count;
    swr_fill(out, sizeof out);
    swr_fill(&count, sizeof count);
    /* too small a capacity: CAPACITY with the needed count written (checked
     * below; it is the one error that writes an output) */
    int cap_short = a.m > 0 && a.m <= SWARP_SPLIT_MAX_COUNT && a.cap < (size_t)a.m + 1;
    if (cap_short) swr_expect(c, SWARP_ERR_CAPACITY);
    double* o = a.null_out ? NULL : out;
    size_t* oc = a.null_count ? NULL : &count;
    swarp_status st;
    switch (kind) {
        case SCH_UNIFORM: st = SWR_CALL(c, swarp_split_uniform(a.n, a.f, a.m, o, a.cap, oc)); break;
        case SCH_LOG: st = SWR_CALL(c, swarp_split_log(a.n, a.f, a.m, o, a.cap, oc)); break;
        case SCH_PRACTICAL: st = SWR_CALL(c, swarp_split_practical(a.n, a.f, a.lambda, a.m, o, a.cap, oc)); break;
        default: st = SWR_CALL(c, swarp_split_pseudo(a.n, a.f, a.n_p, a.f_p, a.lambda, a.m, o, a.cap, oc)); break;
    }
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, !oc || count == (size_t)a.m + 1, "CAPACITY but needed count %zu, want %u", count, a.m + 1);
        SWR_CHECK(c, swr_untouched(out, sizeof out), "CAPACITY but out written");
        swr_fill(&count, sizeof count);
    }
    if (!swr_verdict(c, st, 2, (void*)out, sizeof out, (void*)&count, sizeof count)) return;
    SWR_CHECK(c, count == (size_t)a.m + 1, "count %zu, want m + 1 = %u", count, a.m + 1);
    if (count != (size_t)a.m + 1) return;
    SWR_CHECK(c, swr_untouched(out + count, sizeof out - count * sizeof out[0]), "wrote past count");
    SWR_CHECK(c, out[0] == a.n && out[a.m] == a.f, "C_0 = %.17g, C_m = %.17g, want n = %.17g, f = %.17g", out[0],
              out[a.m], a.n, a.f);
    for (uint32_t i = 0; i <= a.m; ++i) {
        swr_rec(c, "C_i", out[i]);
        if (i > 0) SWR_CHECK(c, out[i] > out[i - 1], "C_%u = %.17g <= C_%u = %.17g", i, out[i], i - 1, out[i - 1]);
        long double t = (long double)i / a.m, lo = a.n, hi = a.f;
        if (kind == SCH_PSEUDO) {
            if (i == 0 || i == a.m) continue;
            lo = a.n_p;
            hi = a.f_p;
        }
        long double u = lo + (hi - lo) * t, l = lo * powl(hi / lo, t), ref;
        if (kind == SCH_UNIFORM) ref = u;                                       /* [RHS] (3.6) */
        else if (kind == SCH_LOG) ref = l;                                      /* [RHS] (3.7) */
        else ref = (long double)a.lambda * l + (1.0L - a.lambda) * u;          /* [RHS] (3.8), (4.1) */
        /* below DBL_MIN the doubles are spaced DBL_TRUE_MIN apart: each of the
         * at most ~8 roundings of (3.6)-(3.8), (4.1) then costs up to
         * DBL_TRUE_MIN/2 absolute (no cancellation: all terms >= 0), so allow
         * 4 DBL_TRUE_MIN absolute besides 1e-12 relative (the floor is the
         * |ref| below which the absolute bound is the larger one) */
        swr_close(c, "C_i", out[i], ref, 1e-12, 4.0 * DBL_TRUE_MIN / 1e-12);
    }
}
static void e_split_uniform(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_split_uniform);
    e_split_scheme(c, SCH_UNIFORM);
}
static void e_split_log(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_split_log);
    e_split_scheme(c, SCH_LOG);
}
static void e_split_practical(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_split_practical);
    e_split_scheme(c, SCH_PRACTICAL);
}
static void e_split_pseudo(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_split_pseudo);
    e_split_scheme(c, SCH_PSEUDO);
}

const swr_entry swr_entries_core[] = {
    {"swarp_status", "core", e_status},
    {"swarp_mat4_to_float", "core", e_mat4_to_float},
    {"swarp_mat4_mul", "core", e_mat4_mul},
    {"swarp_mat4_invert", "core", e_mat4_invert},
    {"swarp_mat4_transform", "core", e_mat4_transform},
    {"swarp_warp_nopt", "core", e_warp_nopt},
    {"swarp_warp_nopt_pseudo", "core", e_warp_nopt_pseudo},
    {"swarp_warp_eta", "core", e_warp_eta},
    {"swarp_warp_wlz", "core", e_warp_wlz},
    {"swarp_warp_nrepar", "core", e_warp_nrepar},
    {"swarp_gmnpr_psi", "core", e_gmnpr_psi},
    {"swarp_gmnpr_offset", "core", e_gmnpr_offset},
    {"swarp_gmnpr_F", "core", e_gmnpr_F},
    {"swarp_gmnpr_lambda12", "core", e_gmnpr_lambda12},
    {"swarp_gmnpr_lambda", "core", e_gmnpr_lambda},
    {"swarp_gmnpr_lambda_lispsm", "core", e_gmnpr_lambda_lispsm},
    {"swarp_gmnpr_lambda_glpr", "core", e_gmnpr_lambda_glpr},
    {"swarp_error_mx", "core", e_error_mx},
    {"swarp_error_mz", "core", e_error_mz},
    {"swarp_error_max", "core", e_error_max},
    {"swarp_error_split_curve", "core", e_error_split_curve},
    {"swarp_error_split_max", "core", e_error_split_max},
    {"swarp_split_uniform", "core", e_split_uniform},
    {"swarp_split_log", "core", e_split_log},
    {"swarp_split_practical", "core", e_split_practical},
    {"swarp_split_pseudo", "core", e_split_pseudo},
    {NULL, NULL, NULL},
};
