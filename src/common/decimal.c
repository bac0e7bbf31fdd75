/* The exact decimal printer of the explanation texts (decimal.h).  Every
 * rounding decision is an integer comparison, so the text is the same in
 * every rounding mode; the floating-point arithmetic only estimates. */
#include <math.h>
#include <string.h>

#include "common/decimal.h"

void sw_puts(sw_text* t, const char* s) {
    for (; *s; ++s) {
        if (t->write) t->out[t->n] = *s;
        ++t->n;
    }
}

void sw_putu(sw_text* t, uint64_t v) {
    char buf[24];
    int k = 0;
    do {
        buf[k++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    char s[24];
    for (int i = 0; i < k; ++i) s[i] = buf[k - 1 - i];
    s[k] = 0;
    sw_puts(t, s);
}

/* Exact decimal rounding for sw_putd.  The digits must not depend on the
 * caller's rounding mode: log10, pow, a division and a product rounded
 * upward or downward move a value across a decimal rounding boundary
 * (0.5325 -> "0.532" or "0.533").  The floating-point path below
 * only estimates; every decision is an exact comparison of the double v =
 * M 2^E with (num2 / 2) 10^k in integers, M 2^(E+1) 10^-k vs num2 10^k with
 * the powers of two cancelled: at most ~830 bits for any double. */
#define SW_BIG_WORDS 40
typedef struct sw_big {
    uint32_t w[SW_BIG_WORDS]; /* little-endian 32-bit words */
    int n;                    /* words in use (the rest are zero) */
} sw_big;

static void sw_big_set(sw_big* b, uint64_t v) {
    b->w[0] = (uint32_t)v;
    b->w[1] = (uint32_t)(v >> 32);
    b->n = 2;
}
static void sw_big_mul_small(sw_big* b, uint32_t m) {
    uint64_t carry = 0;
    for (int i = 0; i < b->n; ++i) {
        uint64_t x = (uint64_t)b->w[i] * m + carry;
        b->w[i] = (uint32_t)x;
        carry = x >> 32;
    }
    if (carry) b->w[b->n++] = (uint32_t)carry; /* n stays below SW_BIG_WORDS: ~830 bits at most */
}
static void sw_big_shl(sw_big* b, int bits) {
    const int words = bits / 32, r = bits % 32;
    const int n = b->n + words + 1;
    for (int i = n - 1; i >= 0; --i) {
        uint64_t hi = (i - words >= 0 && i - words < b->n) ? b->w[i - words] : 0;
        uint64_t lo = (r && i - words - 1 >= 0 && i - words - 1 < b->n) ? b->w[i - words - 1] : 0;
        b->w[i] = (uint32_t)((hi << r) | (r ? lo >> (32 - r) : 0));
    }
    b->n = n;
}
static int sw_big_cmp(const sw_big* a, const sw_big* b) {
    const int n = a->n > b->n ? a->n : b->n;
    for (int i = n - 1; i >= 0; --i) {
        uint32_t x = i < a->n ? a->w[i] : 0, y = i < b->n ? b->w[i] : 0;
        if (x != y) return x < y ? -1 : 1;
    }
    return 0;
}
static void sw_big_mul_pow5(sw_big* b, int n) {
    for (; n >= 13; n -= 13) sw_big_mul_small(b, 1220703125u); /* 5^13 */
    uint32_t p = 1;
    for (; n > 0; --n) p *= 5;
    sw_big_mul_small(b, p);
}

/* v = M 2^E for finite v > 0, from the bits: no floating-point operation,
 * so neither the rounding mode nor DAZ (subnormal inputs read as 0) enters. */
static uint64_t sw_mantissa(double v, int* E) {
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    const int ex = (int)((b >> 52) & 0x7FF);
    const uint64_t frac = b & ((1ull << 52) - 1);
    if (ex == 0) {
        *E = -1074;
        return frac;
    }
    *E = ex - 1075;
    return frac | (1ull << 52);
}

/* sign of v - (num2 / 2) 10^k, exactly; v > 0 finite, |k| <= 340 */
static int sw_cmp_decimal(double v, uint64_t num2, int k) {
    int E;
    uint64_t M = sw_mantissa(v, &E); /* v = M 2^E */
    sw_big L, R;
    sw_big_set(&L, M);
    sw_big_set(&R, num2);
    int l2 = E + 1, r2 = 0; /* 2 v = M 2^(E+1) */
    if (k < 0) {
        sw_big_mul_pow5(&L, -k);
        l2 -= k;
    } else {
        sw_big_mul_pow5(&R, k);
        r2 += k;
    }
    if (l2 > r2) sw_big_shl(&L, l2 - r2);
    else sw_big_shl(&R, r2 - l2);
    return sw_big_cmp(&L, &R);
}

/* Decimal exponents from 10^7 up, and below 10^-3, are printed in
 * scientific form. */
#define SW_DEC_SCI_HI 7
#define SW_DEC_SCI_LO (-3)
/* floor(e2 log10 2) as (e2 * 1233) >> 12 (1233/4096 ~ log10 2), within 1
 * for every double's binary exponent. */
#define SW_DEC_LOG10_2_Q12 1233

/* The decimal exponent e10 of v = M 2^E > 0: 10^e10 <= v < 10^(e10+1).  An
 * integer estimate from the binary exponent, then exact comparisons; no
 * floating-point estimate (under DAZ log10 of a subnormal is -inf). */
static int sw_decimal_exponent(double v, uint64_t M, int E) {
    int e2 = E;
    for (uint64_t m = M; m > 1; m >>= 1) ++e2; /* floor(log2 v) */
    int e10 = (e2 * SW_DEC_LOG10_2_Q12) >> 12; /* arithmetic shift: floor */
    while (sw_cmp_decimal(v, 2, e10) < 0) --e10;
    while (sw_cmp_decimal(v, 2, e10 + 1) >= 0) ++e10;
    return e10;
}

/* q with (q - 1/2) 10^k <= v < (q + 1/2) 10^k, q <= q_max.  A
 * floating-point estimate (right or off by one in every mode) checked by two
 * exact comparisons; bisection on the exact comparison when the estimate is
 * not usable (DAZ, a subnormal v). */
static uint64_t sw_decimal_round(double v, int k, uint64_t q_max) {
    const double est = k >= 0 ? v / pow(10.0, k) : v * pow(10.0, -k);
    uint64_t q = (est >= 1.0 && est < (double)q_max) ? (uint64_t)llround(est) : 0;
    if (q >= 1 && sw_cmp_decimal(v, 2 * q - 1, k) >= 0 && sw_cmp_decimal(v, 2 * q + 1, k) < 0) return q;
    uint64_t lo = 0, hi = q_max; /* invariant: q in [lo, hi] */
    while (lo < hi) {
        uint64_t mid = lo + (hi - lo + 1) / 2;
        if (sw_cmp_decimal(v, 2 * mid - 1, k) >= 0)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* q (3 digits) 10^(e10 - 2) as "d.dde+XX". */
static void sw_put_sci(sw_text* t, uint64_t q, int e10) {
    sw_putu(t, q / 100);
    sw_puts(t, ".");
    sw_putu(t, (q / 10) % 10);
    sw_putu(t, q % 10);
    sw_puts(t, e10 < 0 ? "e-" : "e+");
    int ae = e10 < 0 ? -e10 : e10;
    if (ae < 10) sw_puts(t, "0");
    sw_putu(t, (uint64_t)ae);
}

/* q 10^k, k <= 0, in fixed form with -k decimals. */
static void sw_put_fixed(sw_text* t, uint64_t q, int k) {
    int dec = -k;
    uint64_t scale = 1;
    for (int i = 0; i < dec; ++i) scale *= 10;
    sw_putu(t, q / scale);
    if (dec > 0) {
        sw_puts(t, ".");
        uint64_t frac = q % scale;
        for (uint64_t d = scale / 10; d > 0; d /= 10) sw_putu(t, (frac / d) % 10);
    }
}

/* decimal.h: 3 significant digits, half away from zero, decided exactly. */
void sw_putd(sw_text* t, double v) {
    if (v != v) { sw_puts(t, "nan"); return; }
    if (v < 0.0) { sw_puts(t, "-"); v = -v; }
    if (v == INFINITY) { sw_puts(t, "inf"); return; }
    if (v == 0.0) { sw_puts(t, "0"); return; }
    int E;
    uint64_t M = sw_mantissa(v, &E);
    if (M == 0) { sw_puts(t, "0"); return; } /* a subnormal read as 0 (DAZ) */
    int e10 = sw_decimal_exponent(v, M, E);
    int sci, k;
    uint64_t q;
    for (;;) {
        sci = e10 >= SW_DEC_SCI_HI || e10 < SW_DEC_SCI_LO;
        /* the rounding unit 10^k: 3 significant digits, whole numbers at
         * least; then q <= 10^3 in scientific form, <= 10^7 in fixed form */
        k = sci ? e10 - 2 : (e10 - 2 < 0 ? e10 - 2 : 0);
        q = sw_decimal_round(v, k, sci ? 1000 : 10000000);
        /* rounding carried into the next decade (99.96 -> 100): format as
         * that decade, so 99.99999999999999 and 100 give the same "100" */
        uint64_t next = 1;
        for (int i = k; i <= e10; ++i) next *= 10;
        if (q < next) break;
        ++e10;
    }
    if (sci)
        sw_put_sci(t, q, e10);
    else
        sw_put_fixed(t, q, k);
}
