/*
 * swr.h -- the robustness harness shared by the hard-case sweep
 * (tests/robust/hard_cases.c), the libFuzzer targets and their corpus replay
 * (tests/fuzz/), the threads test and the floating-point-environment test.
 *
 * Every public entry point of libshadowwarp has ONE function
 *     static void e_<name>(swr_ctx* c)
 * in tests/robust/entries_<stage>.c.  It decodes its arguments from the
 * byte string in c (swr_num & co.: a fuzzer's bytes or a seeded PRNG's bytes,
 * biased toward the documented edges), states which error statuses the
 * arguments call for (swr_expect), calls the library with outputs prefilled
 * by a sentinel, and checks the invariant:
 *   error status    => it is one of the expected ones and every output is
 *                      untouched (swr_verdict compares with the sentinel);
 *   success / info  => no error was expected, every output is finite (except
 *                      the documented +INFINITY of SWARP_INFO_WARP_UNIFORM)
 *                      and the documented properties hold (swr_check*).
 * Outputs are recorded (swr_rec) so the threads and fenv tests can compare
 * runs.  Adding a stage = one new entries_<stage>.c with a table, listed in
 * entries.c.
 *
 * Functions are declared weak (SWR_WEAK): an entry whose function is not in
 * the library yet reports "skipped" instead of breaking the link.
 */
#ifndef SWR_H
#define SWR_H

#include <stddef.h>
#include <stdint.h>

#include "shadowwarp.h"

#define SWR_STR_(x) #x
#define SWR_WEAK(f) _Pragma(SWR_STR_(weak f))

#define SWR_MAX_REC 512
#define SWR_MAX_EXPECT 16

typedef struct swr_ctx {
    const uint8_t* data;
    size_t size, pos;
    int lazy;        /* bytes come from the PRNG on demand into buf */
    uint64_t prng;
    uint8_t buf[4096];
    int had_subnormal; /* an input was subnormal (DAZ changes it) */
    int n_expect;
    swarp_status expect[SWR_MAX_EXPECT];
    int n_allow;
    swarp_status allow[SWR_MAX_EXPECT];
    int n_domain;
    swarp_status domain[SWR_MAX_EXPECT];
    int n_findst;
    swarp_status findst[SWR_MAX_EXPECT];
    int called, skipped;
    swarp_status status;
    double rec[SWR_MAX_REC];
    size_t n_rec;
    int failed;
    char msg[512];
    char args[768]; /* the decoded arguments, for failure reports */
    /* An input is extreme when a finite non-zero value has magnitude below
     * 1e-100 (incl. subnormals) or above 1e100.  There, accuracy checks
     * (reference comparisons, the huge-value rule, "valid input rejected")
     * and even the finiteness of outputs after a success are recorded as
     * findings (c->finding, c->finding_msg) instead of failures -- every
     * swr_fail/SWR_CHECK of an entry does that -- inside the
     * documented domain, but far outside any use; the hard-case table counts
     * them and docs/quality.md lists them.  What stays strict on every input:
     * no crash or sanitizer report, the status is an expected/documented one,
     * outputs untouched after an error, nothing written past a count. */
    int extreme;
    int finding;
    char finding_msg[512];
    /* floating-point environment for the library call only (fenv test):
     * 0 = leave alone, else an FE_* rounding mode + SWR_FENV_SET, or
     * SWR_FENV_FTZ_DAZ */
    int fenv_mode;
    unsigned saved_env;
    /* how sensitive the recorded outputs are (the fenv test's tolerance is
     * max(1e-9, tol_min, 64 eps cond) relative to the largest output): cond
     * is the largest condition number the checks met (swr_close_cond sets
     * it), tol_min a floor (e.g. one float ulp for float outputs) */
    double cond, tol_min;
    /* 1 when the case sits on a threshold that rounding decides: an
     * overflow (under FE_TOWARDZERO / FE_DOWNWARD / FE_UPWARD it may round to
     * +-DBL_MAX instead of +-inf, IEEE 754) or a domain bound on a rounded
     * sum (n_p + f_p < 1); the status may then legitimately change with the
     * rounding mode; the fenv test leaves such cases out and counts them */
    int rounding_edge;
    /* the natural scale of the outputs when larger than the outputs
     * themselves (eta in [-1, 0]: 1); swr_close_cond_floor sets it */
    double out_scale;
    /* the output regions registered with swr_out (checked by swr_done) */
    /* non-NULL: property failures are a known problem of the library (this
     * text says which, docs/quality.md lists it), counted as findings */
    const char* known_as;
    int n_out;
    void* out_p[8];
    size_t out_n[8];
} swr_ctx;
#define SWR_FENV_SET 0x10000
#define SWR_FENV_FTZ_DAZ 0x20000
/* Wraps the one library call an entry checks: sets c->fenv_mode around it
 * (decoding and checking run in the default environment). */
#define SWR_CALL(c, call) (swr_enter(c), swr_leave((c), (call)))
void swr_enter(swr_ctx* c);
swarp_status swr_leave(swr_ctx* c, swarp_status st);

typedef void (*swr_entry_fn)(swr_ctx* c);
typedef struct swr_entry {
    const char* name;  /* the library function, e.g. "swarp_warp_nopt" */
    const char* stage; /* core, geometry, ... */
    swr_entry_fn fn;
} swr_entry;

/* ---- the table of every entry point (entries.c) ------------------------ */
size_t swr_entry_count(void);
const swr_entry* swr_entry_at(size_t i);
const swr_entry* swr_entry_find(const char* name);

/* ---- running one case ---------------------------------------------------- */
void swr_ctx_init(swr_ctx* c, const uint8_t* data, size_t size);
/* Runs e on data; returns 0 when the invariant held (or skipped), 1 on a
 * violation (message in c->msg). */
int swr_run(const swr_entry* e, swr_ctx* c, const uint8_t* data, size_t size);
/* Case `index` of `entry` for `seed`: the bytes come from splitmix64 on
 * demand; afterwards c->buf[0..c->pos) are the bytes the entry consumed, a
 * file that replays the case exactly (tests/fuzz/corpus). */
int swr_run_seeded(const swr_entry* e, swr_ctx* c, uint64_t seed, uint64_t index);
uint64_t swr_splitmix64(uint64_t* state);

/* ---- decoding arguments (never fails: missing bytes read as zero) ------- */
uint8_t swr_u8(swr_ctx* c);
uint32_t swr_u32(swr_ctx* c);
uint64_t swr_u64(swr_ctx* c);
/* 1 with probability about 1/k */
int swr_one_in(swr_ctx* c, unsigned k);
/* A double, usually in [lo, hi] (uniform, or log-uniform for wide positive
 * ranges), often exactly at or within 1 ulp / 1e-9 / 1e-12 of one of the
 * breakpoints brk[0..nbrk), at the ends or just outside, sometimes a
 * special value (0, -0, NaN, +-Inf, DBL_MAX, subnormals, 1e+-300, ...) or raw
 * bits.  About 10% of the values leave [lo, hi]. */
double swr_num(swr_ctx* c, double lo, double hi, const double* brk, int nbrk);
/* Same, but never leaves [lo, hi] */
double swr_num_in(swr_ctx* c, double lo, double hi, const double* brk, int nbrk);
/* an angle-like value near 0 / pi / etc. is covered by brk */
/* An enum value: mostly 0..n-1, sometimes n, -1, 0x7FFFFFFF or random. */
int32_t swr_enum(swr_ctx* c, int32_t n);
/* A reserved word: almost always 0 */
uint32_t swr_reserved(swr_ctx* c);
/* 1 when the output pointer should be NULL this time (about 1/48) */
int swr_null(swr_ctx* c);
/* A point offset far away: 0 usually, +-1e6 often, sometimes 1e5 or 3e6 */
double swr_offset(swr_ctx* c);

/* ---- expectations ---------------------------------------------------------- */
/* The arguments call for status s (an error): add to the accepted set. */
void swr_expect(swr_ctx* c, swarp_status s);
/* s may legitimately come back for arguments inside the domain (e.g.
 * SWARP_ERR_SINGULAR from an inverse); the outputs must then be untouched. */
void swr_allow(swr_ctx* c, swarp_status s);
/* s is one of the function's documented domain errors that the harness
 * does not predict exactly: accepted on valid input (as swr_allow) and also
 * when other errors are expected (several errors apply at once). */
void swr_domain(swr_ctx* c, swarp_status s);
/* s is not documented for this function but the sweep met it on valid
 * input: a finding (reported, docs/quality.md), not a failure; outputs must
 * still be untouched.  Each use names a problem reported to the stage. */
void swr_finding_status(swr_ctx* c, swarp_status s);
/* The sentinel bytes outputs are prefilled with. */
void swr_fill(void* p, size_t n);
int swr_untouched(const void* p, size_t n);
/* After the call: checks status against the expectations and, on error,
 * that the `nout` output regions are untouched.  Returns 1 when the call
 * succeeded (status not an error) so the caller goes on to check
 * properties; 0 otherwise. */
int swr_verdict(swr_ctx* c, swarp_status st, int nout, ...);

/* ---- the table-driven shape of an entry (most newer entries) --------------
 * An entry decodes its arguments, passes every input pointer through swr_in
 * and every output through swr_out, calls the library inside SWR_CALL and
 * hands the status to swr_done, which checks it against the expectations and
 * the registered outputs against the sentinel:
 *     const swarp_camera* pc = swr_in(c, &cam);          NULL about 1/48: expects NULL_POINTER
 *     double* po = swr_out(c, &o, sizeof o, SWR_REQ);    prefilled, maybe NULL
 *     if (!swr_done(c, SWR_CALL(c, swarp_f(pc, po)))) return;   then the properties */
#define SWR_REQ 0   /* required output: NULL expects SWARP_ERR_NULL_POINTER */
#define SWR_OPT 1   /* optional output: NULL is valid */
#define SWR_NONULL 2 /* never passed as NULL */
const void* swr_in(swr_ctx* c, const void* p);
void* swr_out(swr_ctx* c, void* p, size_t n, int kind);
int swr_done(swr_ctx* c, swarp_status st);
#define SKIP_IF_MISSING(c, f) \
    do {                      \
        if (!(f)) {           \
            (c)->skipped = 1; \
            return;           \
        }                     \
    } while (0)
#define FIN(c, x) \
    do { if (!swr_isfin(x)) swr_expect((c), SWARP_ERR_NON_FINITE); } while (0)

/* ---- checks -------------------------------------------------------------- */
/* Notes the decoded arguments (printed with a failure). */
void swr_args(swr_ctx* c, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void swr_fail(swr_ctx* c, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* A known problem of the library (reported to its stage, docs/quality.md):
 * counted as a finding on any input, so the suite stays usable until it is
 * fixed; SWARP_STRICT=1 in the environment makes hard_cases fail on every
 * finding. */
void swr_known(swr_ctx* c, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* A failure of accuracy: a finding when the input is extreme (see above). */
void swr_fail_acc(swr_ctx* c, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
#define SWR_CHECK_ACC(c, cond, ...)                  \
    do {                                             \
        if (!(cond)) swr_fail_acc((c), __VA_ARGS__); \
    } while (0)
#define SWR_CHECK(c, cond, ...)              \
    do {                                     \
        if (!(cond)) swr_fail((c), __VA_ARGS__); \
    } while (0)
/* Raises c->cond to k (the condition number of an output). */
void swr_cond(swr_ctx* c, double k);
/* Records v (for threads/fenv comparisons) and checks it is finite. */
void swr_rec(swr_ctx* c, const char* what, double v);
/* Records v, allowing +INFINITY. */
void swr_rec_inf(swr_ctx* c, const char* what, double v);
/* Relative comparison with a reference: |got - ref| <= tol * max(|ref|, floor) */
void swr_close(swr_ctx* c, const char* what, double got, long double ref, double tol, double floor);

/* |got - ref| <= rel |ref| + abs (a relative tolerance plus the absolute
 * rounding of the inputs, e.g. eps times a coordinate offset) */
void swr_close_abs(swr_ctx* c, const char* what, double got, long double ref, double rel, double abs);

/* A reference function of up to 8 long double arguments, for
 * swr_close_cond: evaluated in long double from the paper's formula. */
typedef long double (*swr_ref_fn)(const long double* a);
/* Compares got with f(args) within 64 eps (1 + kappa), kappa being the
 * relative condition number of f at args estimated by perturbing each
 * argument by 2^-26 relative (so a forward-stable implementation passes and
 * an unstable one does not). */
void swr_close_cond(swr_ctx* c, const char* what, double got, swr_ref_fn f, const double* args,
                    int nargs);
/* Same with an absolute floor: |got - ref| <= tol * max(|ref|, floor), for
 * results that are sums of terms of magnitude `floor` (cancellation there is
 * rounding of the terms, not error). */
void swr_close_cond_floor(swr_ctx* c, const char* what, double got, swr_ref_fn f, const double* args,
                          int nargs, double floor);

static inline int swr_isfin(double x) { return x - x == 0.0; }

#endif
