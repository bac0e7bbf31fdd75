/* PCF sample sets and PCSS kernel sizes.  [RHS] §3.6 (PCF on a Poisson disk
 * with Fernando's PCSS blocker search). */
#include "filter/filter_internal.h"

#define SW_PCF_DEFAULT_CANDIDATES 32u

/* splitmix64 (Steele, Lea, Flood 2014): a tiny, well-mixed, stateless-step
 * generator; the state lives on the caller's stack, so no globals. */
static uint64_t sw_splitmix64(uint64_t* s) {
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/* uniform in [0, 1) with 53 random bits */
static double sw_unit(uint64_t* s) { return (double)(sw_splitmix64(s) >> 11) * 0x1.0p-53; }

SWARP_API swarp_status swarp_pcf_poisson_disk(uint64_t seed, uint32_t count, uint32_t candidates,
                                              double* out_xy, size_t capacity,
                                              size_t* out_count, double* out_min_distance) {
    if (!out_xy || !out_count || !out_min_distance) return SWARP_ERR_NULL_POINTER;
    if (count < 1 || count > SWARP_PCF_MAX_SAMPLES) return SWARP_ERR_OUT_OF_RANGE;
    if (capacity < count) {
        *out_count = count;
        return SWARP_ERR_CAPACITY;
    }
    uint32_t k = candidates ? candidates : SW_PCF_DEFAULT_CANDIDATES;
    double xy[2 * SWARP_PCF_MAX_SAMPLES];
    uint64_t s = seed;
    /* Mitchell's best candidate: keep, of k uniform candidates in the disk,
     * the one farthest from every point placed so far. */
    for (uint32_t n = 0; n < count; ++n) {
        double best_x = 0.0, best_y = 0.0, best_d2 = -1.0;
        for (uint32_t c = 0; c < k; ++c) {
            double r = sqrt(sw_unit(&s)), a = 2.0 * SWARP_PI * sw_unit(&s);
            double x = r * cos(a), y = r * sin(a);
            double d2 = 1e300; /* nearest placed point; none yet: any is best */
            for (uint32_t i = 0; i < n; ++i) {
                double dx = x - xy[2 * i], dy = y - xy[2 * i + 1];
                double e = dx * dx + dy * dy;
                if (e < d2) d2 = e;
            }
            if (d2 > best_d2) {
                best_d2 = d2;
                best_x = x;
                best_y = y;
            }
            if (n == 0) break; /* the first point: one candidate suffices */
        }
        xy[2 * n] = best_x;
        xy[2 * n + 1] = best_y;
    }
    double min_d2 = -1.0;
    for (uint32_t i = 0; i < count; ++i)
        for (uint32_t j = i + 1; j < count; ++j) {
            double dx = xy[2 * i] - xy[2 * j], dy = xy[2 * i + 1] - xy[2 * j + 1];
            double e = dx * dx + dy * dy;
            if (min_d2 < 0.0 || e < min_d2) min_d2 = e;
        }
    memcpy(out_xy, xy, 2 * (size_t)count * sizeof(double));
    *out_count = count;
    *out_min_distance = min_d2 < 0.0 ? 0.0 : sqrt(min_d2);
    return SWARP_OK;
}

/* Similar triangles through the light's near plane n_light for a receiver
 * at d_r >= n_light: the search region of the near plane that can hold
 * blockers (search: w (d_r - n_light)/d_r) or the penumbra's width on the
 * near plane (w n_light/d_r).  Each ratio is in [0, 1]: no overflow for
 * any finite w. */
static swarp_status sw_pcss_near_plane(double w, double n_light, double d_r, int search, double* out) {
    if (!out) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(w) || !sw_finite(n_light) || !sw_finite(d_r)) return SWARP_ERR_NON_FINITE;
    if (w < 0.0 || !(n_light > 0.0) || d_r < n_light) return SWARP_ERR_OUT_OF_RANGE;
    *out = search ? w * ((d_r - n_light) / d_r) : w * (n_light / d_r);
    return SWARP_OK;
}

/* Fernando 2005 via [RHS] §3.6: the region of the near plane that can hold
 * blockers of a receiver at d_r, by similar triangles. */
SWARP_API swarp_status swarp_pcss_search_width(double w_light, double n_light, double d_r,
                                               double* out_w_search) {
    return sw_pcss_near_plane(w_light, n_light, d_r, 1, out_w_search);
}

/* [RHS] §3.6 (Fernando 2005): w = (d_r - d_b) w_light / d_b. */
SWARP_API swarp_status swarp_pcss_penumbra(double d_r, double d_b, double w_light,
                                           double* out_w_penumbra) {
    if (!out_w_penumbra) return SWARP_ERR_NULL_POINTER;
    if (!sw_finite(d_r) || !sw_finite(d_b) || !sw_finite(w_light)) return SWARP_ERR_NON_FINITE;
    if (w_light < 0.0) return SWARP_ERR_OUT_OF_RANGE;
    if (!(d_b > 0.0) || d_b > d_r) return SWARP_ERR_FILTER_BLOCKER;
    /* w_light (d_r - d_b)/d_b on mantissas and exponents separately: no
     * intermediate overflow (d_b tiny) or underflow (w_light subnormal, where
     * (d_r - d_b) w_light rounded to a few bits before the division); one
     * final rounding in ldexp */
    int e_w, e_d, e_b;
    double m_w = frexp(w_light, &e_w), m_d = frexp(d_r - d_b, &e_d), m_b = frexp(d_b, &e_b);
    double w = ldexp(m_w * m_d / m_b, e_w + e_d - e_b);
    if (!sw_finite(w)) return SWARP_ERR_OVERFLOW; /* the width itself exceeds DBL_MAX */
    *out_w_penumbra = w;
    return SWARP_OK;
}

/* [RHS] §3.6: the penumbra width scaled to the near plane. */
SWARP_API swarp_status swarp_pcss_filter_width(double w_penumbra, double n_light, double d_r,
                                               double* out_w_filter) {
    return sw_pcss_near_plane(w_penumbra, n_light, d_r, 0, out_w_filter);
}
