/* The robustness harness: byte decoding biased to edges, expectations,
 * verdicts, checks.  See swr.h. */
#include "swr.h"

#if defined(__x86_64__) || defined(__SSE2__)
#include <xmmintrin.h>
#define SWR_HAVE_MXCSR 1
#endif

#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

uint64_t swr_splitmix64(uint64_t* state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint64_t fnv1a(const char* s) {
    uint64_t h = 1469598103934665603ull;
    for (; *s; ++s) h = (h ^ (uint8_t)*s) * 1099511628211ull;
    return h;
}

int swr_run_seeded(const swr_entry* e, swr_ctx* c, uint64_t seed, uint64_t index) {
    swr_ctx_init(c, NULL, 0);
    c->lazy = 1;
    c->data = c->buf;
    c->prng = seed ^ fnv1a(e->name) ^ (index * 0xD1B54A32D192ED03ull);
    e->fn(c);
    return c->failed ? 1 : 0;
}

void swr_ctx_init(swr_ctx* c, const uint8_t* data, size_t size) {
    memset(c, 0, sizeof *c);
    c->data = data;
    c->size = size;
}

int swr_run(const swr_entry* e, swr_ctx* c, const uint8_t* data, size_t size) {
    swr_ctx_init(c, data, size);
    e->fn(c);
    return c->failed ? 1 : 0;
}

/* ---- decoding ------------------------------------------------------------- */
uint8_t swr_u8(swr_ctx* c) {
    if (c->pos >= c->size && c->lazy && c->size + 8 <= sizeof c->buf) {
        uint64_t v = swr_splitmix64(&c->prng);
        for (int k = 0; k < 8; ++k) c->buf[c->size + (size_t)k] = (uint8_t)(v >> (8 * k));
        c->size += 8;
    }
    return c->pos < c->size ? c->data[c->pos++] : 0;
}
uint32_t swr_u32(swr_ctx* c) {
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= (uint32_t)swr_u8(c) << (8 * k);
    return v;
}
uint64_t swr_u64(swr_ctx* c) {
    uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v |= (uint64_t)swr_u8(c) << (8 * k);
    return v;
}
int swr_one_in(swr_ctx* c, unsigned k) { return k <= 1 || swr_u8(c) % k == 0; }

static const double specials[] = {
    0.0, -0.0, 1.0, -1.0, NAN, -NAN, INFINITY, -INFINITY, DBL_MIN, 4.9406564584124654e-324,
    1e-300, -1e-300, DBL_MAX, -DBL_MAX, 1e300, 1e-9, 1e-6, 1e6, 1e7, -1e6, 3.14159265358979323846,
    1.57079632679489661923, 0.78539816339744830962, 6.28318530717958647692, 1e-15, 0.5, 2.0, 1e-7,
    1e5, 2.2250738585072009e-308 /* largest subnormal */};

static double note(swr_ctx* c, double v) {
    if (v != 0.0 && fabs(v) < DBL_MIN) c->had_subnormal = 1;
    if (v != 0.0 && swr_isfin(v) && (fabs(v) < 1e-100 || fabs(v) > 1e100)) c->extreme = 1;
    return v;
}

static double uniform(double lo, double hi, double u, int logscale) {
    if (logscale && lo > 0.0 && hi / lo > 1e3) return lo * exp(u * log(hi / lo));
    return lo * (1.0 - u) + hi * u; /* no overflow of hi - lo */
}

static double perturb(double b, int how, double u) {
    double s = fabs(b) > 1.0 ? fabs(b) : 1.0;
    switch (how) {
        case 0: return b;
        case 1: return nextafter(b, INFINITY);
        case 2: return nextafter(b, -INFINITY);
        case 3: return b + 1e-9 * s;
        case 4: return b - 1e-9 * s;
        case 5: return b + 1e-12 * s;
        case 6: return b - 1e-12 * s;
        default: return b + (u - 0.5) * 1e-6 * s;
    }
}

static double num(swr_ctx* c, double lo, double hi, const double* brk, int nbrk, int inside) {
    uint8_t sel = swr_u8(c);
    uint64_t bits = swr_u64(c);
    double u = (double)(bits >> 11) * 0x1p-53;
    int how = (sel >> 5) & 7;
    double v;
    switch (sel % 20) {
        case 10: case 11: case 12:
            if (nbrk > 0) {
                v = perturb(brk[bits % (unsigned)nbrk], how, u);
                break;
            }
            /* fall through */
        case 13: {
            double e = (bits & 1) ? hi : lo;
            if (how < 4) v = e;
            else if (how < 6) v = nextafter(e, (bits & 1) ? -INFINITY : INFINITY); /* inward */
            else v = nextafter(e, (bits & 1) ? INFINITY : -INFINITY);              /* outward */
            break;
        }
        case 14:
            v = specials[bits % (sizeof specials / sizeof specials[0])];
            break;
        case 15:
            memcpy(&v, &bits, sizeof v);
            break;
        default:
            v = uniform(lo, hi, u, sel & 0x20);
            break;
    }
    if (inside && !(v >= lo && v <= hi)) v = uniform(lo, hi, u, 0);
    return note(c, v);
}

double swr_num(swr_ctx* c, double lo, double hi, const double* brk, int nbrk) {
    return num(c, lo, hi, brk, nbrk, 0);
}
double swr_num_in(swr_ctx* c, double lo, double hi, const double* brk, int nbrk) {
    return num(c, lo, hi, brk, nbrk, 1);
}

int32_t swr_enum(swr_ctx* c, int32_t n) {
    uint8_t s = swr_u8(c);
    if (s < 250) return (int32_t)(s % (uint8_t)(n > 0 ? n : 1)); /* about 2% invalid */
    switch (s % 4) {
        case 0: return n;
        case 1: return -1;
        case 2: return 0x7FFFFFFF;
        default: return (int32_t)swr_u32(c);
    }
}
uint32_t swr_reserved(swr_ctx* c) {
    uint8_t s = swr_u8(c);
    return s == 255 ? (swr_u32(c) | 1u) : 0u;
}
int swr_null(swr_ctx* c) { return swr_u8(c) % 48 == 47; }
double swr_offset(swr_ctx* c) {
    uint8_t s = swr_u8(c);
    switch (s % 8) {
        case 0: case 1: case 2: return 0.0;
        case 3: return 1e6;
        case 4: return -1e6;
        case 5: return 1e5;
        case 6: return -3e6;
        default: return (double)(int32_t)swr_u32(c) * 1e-3;
    }
}

/* ---- expectations and verdicts ---------------------------------------------- */
void swr_expect(swr_ctx* c, swarp_status s) {
    for (int i = 0; i < c->n_expect; ++i)
        if (c->expect[i] == s) return;
    if (c->n_expect < SWR_MAX_EXPECT) c->expect[c->n_expect++] = s;
}
void swr_domain(swr_ctx* c, swarp_status s) {
    if (c->n_domain < SWR_MAX_EXPECT) c->domain[c->n_domain++] = s;
}
void swr_finding_status(swr_ctx* c, swarp_status s) {
    if (c->n_findst < SWR_MAX_EXPECT) c->findst[c->n_findst++] = s;
}
void swr_allow(swr_ctx* c, swarp_status s) {
    if (c->n_allow < SWR_MAX_EXPECT) c->allow[c->n_allow++] = s;
}

#define SWR_SENTINEL 0xA7
void swr_fill(void* p, size_t n) { memset(p, SWR_SENTINEL, n); }
int swr_untouched(const void* p, size_t n) {
    const uint8_t* b = (const uint8_t*)p;
    for (size_t i = 0; i < n; ++i)
        if (b[i] != SWR_SENTINEL) return 0;
    return 1;
}

/* A property failure: on extreme inputs a finding (see swr.h). */
static void known_as(swr_ctx* c, const char* fmt, va_list ap) {
    if (!c->finding) {
        int w = snprintf(c->finding_msg, sizeof c->finding_msg, "KNOWN (%s): ", c->known_as);
        if (w >= 0 && (size_t)w < sizeof c->finding_msg)
            vsnprintf(c->finding_msg + w, sizeof c->finding_msg - (size_t)w, fmt, ap);
    }
    c->finding++;
}
static void vfail(swr_ctx* c, const char* fmt, va_list ap) {
    if (c->known_as) known_as(c, fmt, ap);
    else if (c->extreme) {
        if (!c->finding) vsnprintf(c->finding_msg, sizeof c->finding_msg, fmt, ap);
        c->finding++;
    } else {
        if (!c->failed) vsnprintf(c->msg, sizeof c->msg, fmt, ap);
        c->failed++;
    }
}
void swr_fail(swr_ctx* c, const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vfail(c, fmt, ap);
    va_end(ap);
}
/* A structural failure (status, untouched outputs): strict on every input. */
static void swr_fail_strict(swr_ctx* c, const char* fmt, ...) {
    if (!c->failed) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(c->msg, sizeof c->msg, fmt, ap);
        va_end(ap);
    }
    c->failed++;
}

void swr_args(swr_ctx* c, const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->args, sizeof c->args, fmt, ap);
    va_end(ap);
}

void swr_known(swr_ctx* c, const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    if (!c->finding) vsnprintf(c->finding_msg, sizeof c->finding_msg, fmt, ap);
    c->finding++;
    va_end(ap);
}

void swr_fail_acc(swr_ctx* c, const char* fmt, ...) { /* the same rule as swr_fail (kept as a name for accuracy checks) */
    va_list ap;
    va_start(ap, fmt);
    vfail(c, fmt, ap);
    va_end(ap);
}

static int in_list(const swarp_status* l, int n, swarp_status s) {
    for (int i = 0; i < n; ++i)
        if (l[i] == s) return 1;
    return 0;
}

/* The verdict on regions outs[0..nout) (NULL entries: not passed). */
static int verdict(swr_ctx* c, swarp_status st, int nout, void* const* outs, const size_t* sizes) {
    c->called = 1;
    c->status = st;
    c->rec[c->n_rec++] = (double)st;
    int is_err = swarp_status_is_error(st);
    if (is_err) {
        for (int i = 0; i < nout; ++i)
            if (outs[i] && !swr_untouched(outs[i], sizes[i]))
                swr_fail_strict(c, "error %s but output %d was written", swarp_status_name(st), i);
        if (c->n_expect > 0) {
            if (!in_list(c->expect, c->n_expect, st) && !in_list(c->domain, c->n_domain, st)) {
                char buf[256] = "";
                size_t used = 0;
                for (int i = 0; i < c->n_expect && used + 1 < sizeof buf; ++i) { /* (the fuzzer found the old strncat overflow) */
                    int w = snprintf(buf + used, sizeof buf - used, "%s ", swarp_status_name(c->expect[i]));
                    if (w < 0) break;
                    used += (size_t)w;
                }
                swr_fail_strict(c, "returned %s, expected one of: %s", swarp_status_name(st), buf);
            }
        } else if (in_list(c->findst, c->n_findst, st)) {
            if (!c->finding)
                snprintf(c->finding_msg, sizeof c->finding_msg, "undocumented status %s on valid arguments",
                         swarp_status_name(st));
            c->finding++;
        } else if (!in_list(c->allow, c->n_allow, st) && !in_list(c->domain, c->n_domain, st)) {
            swr_fail_acc(c, "valid arguments rejected with %s", swarp_status_name(st));
        }
        return 0;
    }
    if (c->n_expect > 0) {
        swr_fail_strict(c, "returned %s although the arguments call for %s", swarp_status_name(st),
                 swarp_status_name(c->expect[0]));
        return 0;
    }
    if (st != SWARP_OK && !(st >= 1000 && st <= 1999))
        swr_fail_strict(c, "status %d is neither OK nor informational", (int)st);
    return 1;
}

int swr_verdict(swr_ctx* c, swarp_status st, int nout, ...) {
    void* outs[16];
    size_t sizes[16];
    va_list ap;
    va_start(ap, nout);
    for (int i = 0; i < nout && i < 16; ++i) {
        outs[i] = va_arg(ap, void*);
        sizes[i] = va_arg(ap, size_t);
    }
    va_end(ap);
    return verdict(c, st, nout < 16 ? nout : 16, outs, sizes);
}

const void* swr_in(swr_ctx* c, const void* p) {
    if (!swr_null(c)) return p;
    swr_expect(c, SWARP_ERR_NULL_POINTER);
    return NULL;
}
void* swr_out(swr_ctx* c, void* p, size_t n, int kind) {
    swr_fill(p, n);
    if (c->n_out < (int)(sizeof c->out_p / sizeof c->out_p[0])) {
        c->out_p[c->n_out] = p;
        c->out_n[c->n_out++] = n;
    }
    if (kind == SWR_NONULL) return p;
    if (kind == SWR_OPT ? !swr_one_in(c, 4) : !swr_null(c)) return p;
    if (kind == SWR_REQ) swr_expect(c, SWARP_ERR_NULL_POINTER);
    return NULL;
}
int swr_done(swr_ctx* c, swarp_status st) { return verdict(c, st, c->n_out, c->out_p, c->out_n); }

/* ---- checks ------------------------------------------------------------------ */
void swr_cond(swr_ctx* c, double k) {
    if (k > c->cond || k != k) c->cond = k;
}
void swr_rec(swr_ctx* c, const char* what, double v) {
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = v;
    /* the cardinal invariant; on extreme inputs a finding (see swr.h) */
    if (!swr_isfin(v)) swr_fail_acc(c, "%s = %g is not finite after %s", what, v, swarp_status_name(c->status));
}
void swr_rec_inf(swr_ctx* c, const char* what, double v) {
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = v;
    if (v != v || v == -INFINITY) swr_fail(c, "%s = %g after %s", what, v, swarp_status_name(c->status));
    /* the statuses that bound the coverage outrank WARP_UNIFORM (the one
     * status reported, src/geometry/setup.c sw_info_merge) */
    if (v == INFINITY && c->status != SWARP_INFO_WARP_UNIFORM && c->status != SWARP_INFO_LIGHT_NEAR_CLIPPED &&
        c->status != SWARP_INFO_CASTERS_CLAMPED)
        swr_fail(c, "%s = +inf with %s (only SWARP_INFO_WARP_UNIFORM may give +inf)", what,
                 swarp_status_name(c->status));
}

void swr_close(swr_ctx* c, const char* what, double got, long double ref, double tol, double floor) {
    long double scale = fabsl(ref) > floor ? fabsl(ref) : floor;
    long double err = fabsl((long double)got - ref);
    if (!(err <= tol * scale))
        swr_fail_acc(c, "%s = %.17g, reference %.17Lg (error %.3Lg > tol %.3Lg)", what, got, ref, err / scale,
                     (long double)tol);
}

void swr_close_abs(swr_ctx* c, const char* what, double got, long double ref, double rel, double abs) {
    /* numerically singular at double precision (64 eps kappa >= 1): no claim */
    if (64 * DBL_EPSILON * c->cond >= 1) return;
    long double err = fabsl((long double)got - ref);
    if (!(err <= rel * fabsl(ref) + abs))
        swr_fail_acc(c, "%s = %.17g, reference %.17Lg (error %.3Lg > %.3g relative + %.3g)", what, got, ref, err, rel, abs);
}

void swr_close_cond(swr_ctx* c, const char* what, double got, swr_ref_fn f, const double* args,
                    int nargs) {
    swr_close_cond_floor(c, what, got, f, args, nargs, 0.0);
}
void swr_close_cond_floor(swr_ctx* c, const char* what, double got, swr_ref_fn f, const double* args,
                          int nargs, double floor) {
    long double a[8] = {0};
    for (int i = 0; i < nargs && i < 8; ++i) a[i] = args[i];
    long double ref = f(a);
    if (!isfinite(ref)) return; /* the reference itself breaks down: no claim */
    /* a step small enough not to cross a nearby singularity (z_1 one ulp
     * above z_0 is 2^-52 away) and large enough that long double rounding
     * (2^-64) adds only ~0.01 to kappa */
    const long double h = 0x1p-56L;
    long double kappa = 0.0L;
    for (int i = 0; i < nargs && i < 8; ++i) {
        if (a[i] == 0.0L) continue;
        long double keep = a[i];
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            a[i] = keep * (1.0L + sgn * h);
            long double fp = f(a);
            long double k = isfinite(fp) ? fabsl(fp - ref) / (h * (fabsl(ref) > 0 ? fabsl(ref) : 1.0L))
                                         : 1e30L;
            if (k > kappa) kappa = k;
        }
        a[i] = keep;
    }
    swr_cond(c, (double)kappa);
    double tol = 64.0 * DBL_EPSILON * (1.0 + (double)kappa);
    /* below DBL_MIN the result underflows: absolute differences of DBL_MIN
     * are rounding, not error */
    if (floor > c->out_scale) c->out_scale = floor;
    swr_close(c, what, got, ref, tol, floor > DBL_MIN / tol ? floor : DBL_MIN / tol);
}

/* ---- floating-point environment around the library call ------------------ */
void swr_enter(swr_ctx* c) {
    if (c->fenv_mode & SWR_FENV_SET) {
        c->saved_env = (unsigned)fegetround();
        fesetround(c->fenv_mode & 0xFFFF);
    }
#ifdef SWR_HAVE_MXCSR
    if (c->fenv_mode & SWR_FENV_FTZ_DAZ) {
        c->saved_env = _mm_getcsr();
        _mm_setcsr(c->saved_env | 0x8040u); /* FTZ (bit 15) | DAZ (bit 6) */
    }
#endif
}
swarp_status swr_leave(swr_ctx* c, swarp_status st) {
    if (c->fenv_mode & SWR_FENV_SET) fesetround((int)c->saved_env);
#ifdef SWR_HAVE_MXCSR
    if (c->fenv_mode & SWR_FENV_FTZ_DAZ) _mm_setcsr(c->saved_env);
#endif
    return st;
}
