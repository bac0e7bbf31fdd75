/* Hard-case / fuzz entries for the splits stage: the atlas ([RHS] §3.3.5,
 * (3.9)), stabilisation (§3.5: enclosing sphere, light view), bias toward the
 * light, cascade selection and blending (§3.3.3), the split options and the
 * per-split warps and error curves.  NULL, non-finite, enum and count errors
 * are predicted; other documented domain errors are accepted with outputs
 * untouched.  Properties: tile viewports inside the atlas and disjoint; l_sc
 * = 1/grid; the sphere holds the split frustum's corners; the stabilised
 * light view is a rotation; split selection and blend weights consistent
 * with the splits; cascade splits from n to f strictly increasing; one n'
 * per split, > 0 or +inf. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "swr.h"

SWR_WEAK(swarp_atlas_layout)
SWR_WEAK(swarp_atlas_lsc)
SWR_WEAK(swarp_atlas_kernel_scale)
SWR_WEAK(swarp_stabilize_sphere)
SWR_WEAK(swarp_stabilize_light_view)
SWR_WEAK(swarp_bias_to_light)
SWR_WEAK(swarp_cascade_select_depth)
SWR_WEAK(swarp_cascade_blend)
SWR_WEAK(swarp_cascade_splits)
SWR_WEAK(swarp_cascade_nopt)


static int fin3(const swarp_vec3* v) { return swr_isfin(v->x) && swr_isfin(v->y) && swr_isfin(v->z); }

static void e_atlas_layout(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_atlas_layout);
    uint32_t m = swr_one_in(c, 16) ? (swr_one_in(c, 2) ? 0 : SWARP_ATLAS_MAX_SPLITS + 1) : 1 + swr_u8(c) % SWARP_ATLAS_MAX_SPLITS;
    uint32_t res = swr_one_in(c, 16) ? (swr_one_in(c, 2) ? 0 : (1u << 24) + 1) : 1 + swr_u32(c) % 8192;
    int32_t dr = swr_enum(c, 3);
    size_t cap = swr_one_in(c, 8) ? swr_u8(c) % 17 : SWARP_ATLAS_MAX_SPLITS;
    int n_i = swr_one_in(c, 4), n_t = swr_null(c), n_c = swr_null(c);
    if (n_c || (n_t && cap > 0)) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_t && cap == 0) swr_domain(c, SWARP_ERR_NULL_POINTER);
    if (m == 0 || m > SWARP_ATLAS_MAX_SPLITS) swr_expect(c, SWARP_ERR_ATLAS_SPLITS);
    if (res == 0 || res > (1u << 24)) swr_expect(c, SWARP_ERR_RESOLUTION);
    if (dr < 0 || dr > 2) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    int short_cap = m >= 1 && m <= SWARP_ATLAS_MAX_SPLITS && cap < m;
    if (short_cap) swr_expect(c, SWARP_ERR_CAPACITY);
    swarp_atlas_info info;
    swarp_atlas_tile tiles[SWARP_ATLAS_MAX_SPLITS];
    size_t count;
    swr_fill(&info, sizeof info);
    swr_fill(tiles, sizeof tiles);
    swr_fill(&count, sizeof count);
    swarp_status st = SWR_CALL(c, swarp_atlas_layout(m, res, (swarp_depth_range)dr, n_i ? NULL : &info, n_t ? NULL : tiles,
                                                    cap, n_c ? NULL : &count));
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, count == m, "CAPACITY with count %zu, want %u", count, m);
        SWR_CHECK(c, swr_untouched(tiles, sizeof tiles), "CAPACITY but tiles written");
        swr_fill(&count, sizeof count);
        if (!n_i && !swr_untouched(&info, sizeof info)) swr_fill(&info, sizeof info); /* info is not an error output */
    }
    if (!swr_verdict(c, st, 3, (void*)&info, sizeof info, (void*)tiles, sizeof tiles, (void*)&count, sizeof count)) return;
    SWR_CHECK(c, count == m, "count %zu, m %u", count, m);
    uint32_t grid = m == 1 ? 1 : m <= 4 ? 2 : m <= 9 ? 3 : 4;
    double atlas = (double)grid * res;
    if (!n_i) {
        swr_rec(c, "l_sc", info.l_sc);
        /* 1/grid to within its rounding (the caller's rounding mode applies) */
        SWR_CHECK(c, info.grid == grid && fabs(info.l_sc - 1.0 / grid) <= 2 * DBL_EPSILON / grid, "grid %u l_sc %.17g for m = %u",
                  info.grid, info.l_sc, m);
        SWR_CHECK(c, info.atlas_res == atlas && info.tile_res == res, "atlas %g tile %g", info.atlas_res, info.tile_res);
    }
    for (uint32_t i = 0; i < m; ++i) {
        const swarp_atlas_tile* t = &tiles[i];
        swr_rec(c, "viewport", t->viewport_x);
        swr_rec(c, "viewport", t->viewport_y);
        for (int k = 0; k < 16; ++k) swr_rec(c, "clip_to_atlas", t->clip_to_atlas.m[k]);
        SWR_CHECK(c, t->viewport_x >= 0 && t->viewport_y >= 0 && t->viewport_x + t->viewport_width <= atlas &&
                         t->viewport_y + t->viewport_height <= atlas && t->viewport_width == res && t->viewport_height == res,
                  "tile %u viewport (%g %g %g %g) outside the %g atlas", i, t->viewport_x, t->viewport_y, t->viewport_width,
                  t->viewport_height, atlas);
        for (uint32_t j = 0; j < i; ++j)
            SWR_CHECK(c, tiles[j].viewport_x != t->viewport_x || tiles[j].viewport_y != t->viewport_y, "tiles %u and %u overlap", j, i);
    }
}

static void e_atlas_lsc(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_atlas_lsc);
    uint32_t m = swr_one_in(c, 8) ? swr_u32(c) : swr_u8(c) % 18;
    int nul = swr_null(c);
    if (nul) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (m == 0 || m > SWARP_ATLAS_MAX_SPLITS) swr_expect(c, SWARP_ERR_ATLAS_SPLITS);
    double l;
    swr_fill(&l, sizeof l);
    swarp_status st = SWR_CALL(c, swarp_atlas_lsc(m, nul ? NULL : &l));
    if (!swr_verdict(c, st, 1, (void*)&l, sizeof l)) return;
    swr_rec(c, "l_sc", l);
    double want = m == 1 ? 1.0 : m <= 4 ? 0.5 : m <= 9 ? 1.0 / 3 : 0.25; /* [RHS] (3.9) */
    SWR_CHECK(c, fabs(l - want) <= 2 * DBL_EPSILON * want, "l_sc(%u) = %.17g, want %.17g", m, l, want);
}

static void e_atlas_kernel_scale(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_atlas_kernel_scale);
    static const double brk[] = {0.0, 1.0, -1.0};
    double r = swr_num(c, 0, 10, brk, 1);
    uint32_t m = swr_one_in(c, 12) ? swr_u8(c) % 40 : 1 + swr_u8(c) % 16;
    double x0 = swr_num(c, -1, 1, brk, 3), x1 = swr_one_in(c, 10) ? x0 : swr_num(c, -1, 1, brk, 3);
    double y0 = swr_num(c, -1, 1, brk, 3), y1 = swr_one_in(c, 10) ? y0 : swr_num(c, -1, 1, brk, 3);
    int nul = swr_null(c);
    if (nul) swr_expect(c, SWARP_ERR_NULL_POINTER);
    FIN(c, r);
    FIN(c, x0);
    FIN(c, x1);
    FIN(c, y0);
    FIN(c, y1);
    if (swr_isfin(r) && r < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (swr_isfin(x0) && swr_isfin(x1) && !(x1 > x0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (swr_isfin(y0) && swr_isfin(y1) && !(y1 > y0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (m == 0 || m > SWARP_ATLAS_MAX_SPLITS) swr_expect(c, SWARP_ERR_ATLAS_SPLITS);
    swr_domain(c, SWARP_ERR_OVERFLOW);
    double s[2];
    swr_fill(s, sizeof s);
    swarp_status st = SWR_CALL(c, swarp_atlas_kernel_scale(r, m, x0, x1, y0, y1, nul ? NULL : s));
    if (!swr_verdict(c, st, 1, (void*)s, sizeof s)) return;
    swr_rec(c, "s_x", s[0]);
    swr_rec(c, "s_y", s[1]);
    SWR_CHECK(c, s[0] >= 0 && s[1] >= 0, "kernel scale (%g, %g) negative", s[0], s[1]);
}

static void gen_cam(swr_ctx* c, swarp_camera* cam) {
    memset(cam, 0, sizeof *cam);
    double off = swr_offset(c);
    cam->eye.x = off + swr_num(c, -10, 10, NULL, 0);
    cam->eye.y = swr_num(c, 0, 10, NULL, 0);
    cam->eye.z = off + swr_num(c, -10, 10, NULL, 0);
    cam->dir.x = swr_num(c, -1, 1, NULL, 0);
    cam->dir.y = swr_num(c, -1, 1, NULL, 0);
    cam->dir.z = swr_one_in(c, 20) ? 0 : -1;
    if (swr_one_in(c, 30)) cam->dir.x = cam->dir.y = cam->dir.z = 0;
    cam->up.y = 1;
    if (swr_one_in(c, 30)) cam->up = cam->dir;
    static const double brk_f[] = {1e-6, 3.14159265358979 - 1e-6};
    cam->fovy = swr_num(c, 0.1, 2.8, brk_f, 2);
    cam->aspect = swr_num(c, 0.3, 3, NULL, 0);
    cam->_reserved[swr_u8(c) % 4] = swr_reserved(c);
}
static void expect_cam(swr_ctx* c, const swarp_camera* cam) {
    if (!fin3(&cam->eye) || !fin3(&cam->dir) || !fin3(&cam->up) || !swr_isfin(cam->fovy) || !swr_isfin(cam->aspect))
        swr_expect(c, SWARP_ERR_NON_FINITE);
    if (swr_isfin(cam->fovy) && !(cam->fovy > 0 && cam->fovy < 3.14159265358979323846)) swr_expect(c, SWARP_ERR_FOV);
    if (swr_isfin(cam->aspect) && !(cam->aspect > 0)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (cam->dir.x == 0 && cam->dir.y == 0 && cam->dir.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    for (int i = 0; i < 4; ++i)
        if (cam->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
    swr_domain(c, SWARP_ERR_DEGENERATE);
    swr_domain(c, SWARP_ERR_ZERO_VECTOR);
}

static void e_stabilize_sphere(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_stabilize_sphere);
    swarp_camera cam;
    gen_cam(c, &cam);
    static const double brk_n[] = {1e-6, 1.0};
    double n = swr_num(c, 1e-6, 10, brk_n, 2), f = swr_one_in(c, 16) ? n : n * swr_num(c, 1, 1e7, NULL, 0);
    int n_c = swr_null(c), n_ctr = swr_null(c), n_r = swr_null(c), n_cr = swr_one_in(c, 3);
    if (n_c || n_ctr || n_r) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_cam(c, &cam);
    FIN(c, n);
    FIN(c, f);
    if (swr_isfin(n) && swr_isfin(f) && !(n > 0 && f > n)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    swarp_vec3 ctr;
    double rad, crad;
    swr_fill(&ctr, sizeof ctr);
    swr_fill(&rad, sizeof rad);
    swr_fill(&crad, sizeof crad);
    swarp_status st = SWR_CALL(c, swarp_stabilize_sphere(n_c ? NULL : &cam, n, f, n_ctr ? NULL : &ctr, n_r ? NULL : &rad,
                                                        n_cr ? NULL : &crad));
    if (!swr_verdict(c, st, 3, (void*)&ctr, sizeof ctr, (void*)&rad, sizeof rad, (void*)&crad, sizeof crad)) return;
    swr_rec(c, "center", ctr.x);
    swr_rec(c, "center", ctr.y);
    swr_rec(c, "center", ctr.z);
    swr_rec(c, "radius", rad);
    SWR_CHECK(c, rad > 0, "radius %g", rad);
    /* positions (and so radii of tiny spheres far from the origin) carry an ulp of the eye's magnitude */
    double eye_ulp = 8 * DBL_EPSILON * (fabs(cam.eye.x) + fabs(cam.eye.y) + fabs(cam.eye.z) + f);
    if (!n_cr) SWR_CHECK(c, crad >= rad * (1 - 1e-12) - eye_ulp, "centroid radius %g below the minimal %g", crad, rad);
    /* the far corners are inside the sphere */
    double l = sqrt(cam.dir.x * cam.dir.x + cam.dir.y * cam.dir.y + cam.dir.z * cam.dir.z);
    double ty = tan(cam.fovy / 2), tx = ty * cam.aspect;
    double halfdiag = f * sqrt(1 + tx * tx + ty * ty); /* distance eye -> far corner */
    double dist = hypot(hypot(ctr.x - cam.eye.x, ctr.y - cam.eye.y), ctr.z - cam.eye.z); /* no overflow */
    (void)l;
    /* positions carry an ulp of their magnitude */
    double pos_ulp = 8 * DBL_EPSILON * (fabs(cam.eye.x) + fabs(cam.eye.y) + fabs(cam.eye.z) + fabs(ctr.x) + fabs(ctr.y) + fabs(ctr.z));
    SWR_CHECK(c, dist <= rad + halfdiag * (1 + 1e-9) + pos_ulp && rad <= halfdiag * (1 + 1e-9) + 1e-300,
              "sphere (eye %g %g %g dir %g %g %g fovy %g aspect %g n %g f %g; |c - eye| %g, r %g) inconsistent with the frustum (corner %g)", cam.eye.x, cam.eye.y,
              cam.eye.z, cam.dir.x, cam.dir.y, cam.dir.z, cam.fovy, cam.aspect, n, f, dist, rad, halfdiag);
}

static void e_stabilize_light_view(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_stabilize_light_view);
    swarp_vec3 d = {swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0)};
    if (swr_one_in(c, 8)) d.x = d.z = 0; /* straight down: the up fallback */
    if (swr_one_in(c, 20)) d.y = 0, d.x = d.z = 0;
    int n_d = swr_null(c), n_o = swr_null(c);
    if (n_d || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (!fin3(&d)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (d.x == 0 && d.y == 0 && d.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    swr_domain(c, SWARP_ERR_ZERO_VECTOR);
    swarp_mat4 V;
    swr_fill(&V, sizeof V);
    swarp_status st = SWR_CALL(c, swarp_stabilize_light_view(n_d ? NULL : &d, n_o ? NULL : &V));
    if (!swr_verdict(c, st, 1, (void*)&V, sizeof V)) return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "view", V.m[i]);
    /* the upper 3x3 is a rotation: orthonormal rows */
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            double dd = 0;
            for (int k = 0; k < 3; ++k) dd += V.m[k * 4 + a] * V.m[k * 4 + b];
            SWR_CHECK(c, fabs(dd - (a == b)) <= 1e-12, "rows %d, %d: dot %.17g", a, b, dd);
        }
}

static void e_bias_to_light(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_to_light);
    swarp_light L;
    memset(&L, 0, sizeof L);
    L.type = (swarp_light_type)swr_enum(c, 3);
    L.direction.x = swr_num(c, -1, 1, NULL, 0);
    L.direction.y = swr_num(c, -1, 1, NULL, 0);
    L.direction.z = swr_num(c, -1, 1, NULL, 0);
    if (swr_one_in(c, 16)) L.direction.x = L.direction.y = L.direction.z = 0;
    L.position.x = swr_num(c, -100, 100, NULL, 0);
    L.position.y = swr_num(c, -100, 100, NULL, 0);
    L.position.z = swr_num(c, -100, 100, NULL, 0);
    swarp_vec3 p = L.position;
    if (!swr_one_in(c, 10)) p.x += swr_num(c, -10, 10, NULL, 0); /* else: the point is the light */
    L._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int n_l = swr_null(c), n_p = swr_null(c), n_o = swr_null(c);
    if (n_l || n_p || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    int t = (int)L.type;
    if (t < 0 || t > 2) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
    if (!fin3(&p)) swr_expect(c, SWARP_ERR_NON_FINITE);
    if ((t == 0 || t == 1) && !fin3(&L.direction)) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (t == 2 && !fin3(&L.position)) swr_expect(c, SWARP_ERR_NON_FINITE);
    for (int i = 0; i < 4; ++i)
        if (L._reserved[i]) swr_domain(c, SWARP_ERR_RESERVED_NONZERO);
    swr_domain(c, SWARP_ERR_ZERO_VECTOR);
    swr_domain(c, SWARP_ERR_NON_FINITE);
    swarp_vec3 o;
    swr_fill(&o, sizeof o);
    swarp_status st = SWR_CALL(c, swarp_bias_to_light(n_l ? NULL : &L, n_p ? NULL : &p, n_o ? NULL : &o));
    if (!swr_verdict(c, st, 1, (void*)&o, sizeof o)) return;
    swr_rec(c, "L", o.x);
    swr_rec(c, "L", o.y);
    swr_rec(c, "L", o.z);
    SWR_CHECK(c, fabs(o.x * o.x + o.y * o.y + o.z * o.z - 1) <= 1e-12, "|L| = %.17g, not unit",
              sqrt(o.x * o.x + o.y * o.y + o.z * o.z));
}

/* m + 1 increasing splits (sometimes not) */
static size_t gen_cascade(swr_ctx* c, double* s, size_t maxm) {
    size_t m = swr_one_in(c, 20) ? 0 : 1 + swr_u8(c) % maxm;
    s[0] = swr_num(c, 1e-3, 10, NULL, 0);
    for (size_t i = 1; i <= m; ++i) s[i] = s[i - 1] * swr_num_in(c, 1.01, 10, NULL, 0);
    if (m >= 2 && swr_one_in(c, 16)) s[1 + swr_u8(c) % m] = s[0];
    return m;
}
static int incr(const double* s, size_t m) {
    for (size_t i = 0; i < m; ++i)
        if (!(s[i + 1] > s[i])) return 0;
    return 1;
}
static void expect_cascade(swr_ctx* c, const double* s, size_t m) {
    if (m == 0 || m > SWARP_SPLIT_MAX_COUNT) {
        swr_expect(c, SWARP_ERR_SPLIT_COUNT);
        return;
    }
    for (size_t i = 0; i <= m; ++i) FIN(c, s[i]);
    if (!incr(s, m)) swr_expect(c, SWARP_ERR_NOT_INCREASING);
    if (!(s[0] > 0)) swr_domain(c, SWARP_ERR_NEAR_FAR), swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
}

static void e_cascade_select_depth(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_select_depth);
    double s[9] = {0};
    size_t m = gen_cascade(c, s, 8);
    size_t k = m <= 8 ? m : 8;
    const double brk[] = {s[0], s[k], s[k / 2]};
    double z = swr_num(c, s[0] * 0.5, s[k] * 2, brk, 3);
    int n_s = swr_null(c), n_o = swr_null(c);
    if (n_s || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_cascade(c, s, m);
    FIN(c, z);
    uint32_t idx;
    swr_fill(&idx, sizeof idx);
    swarp_status st = SWR_CALL(c, swarp_cascade_select_depth(n_s ? NULL : s, m, z, n_o ? NULL : &idx));
    if (!swr_verdict(c, st, 1, (void*)&idx, sizeof idx)) return;
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = idx;
    SWR_CHECK(c, idx < m, "index %u of %zu", idx, m);
    int outside = z < s[0] || z > s[m];
    SWR_CHECK(c, (st == SWARP_INFO_OUTSIDE_SPLITS) == outside, "%s for depth %s", swarp_status_name(st), outside ? "outside" : "inside");
    if (!outside) SWR_CHECK(c, z >= s[idx] && z <= s[idx + 1], "depth %.17g not in split %u [%.17g, %.17g]", z, idx, s[idx], s[idx + 1]);
}

static void e_cascade_blend(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_blend);
    double s[9] = {0};
    size_t m = gen_cascade(c, s, 8);
    size_t k = m <= 8 ? m : 8;
    const double brk[] = {s[0], s[k], s[k / 2]}, brk_b[] = {0.0, 1.0, 0.5};
    double z = swr_num(c, s[0] * 0.5, s[k] * 2, brk, 3), band = swr_num(c, 0, 1, brk_b, 3);
    int n_s = swr_null(c), n_i = swr_null(c), n_w = swr_null(c);
    if (n_s || n_i || n_w) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_cascade(c, s, m);
    FIN(c, z);
    FIN(c, band);
    if (swr_isfin(band) && !(band >= 0 && band < 1)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    uint32_t idx;
    double w;
    swr_fill(&idx, sizeof idx);
    swr_fill(&w, sizeof w);
    swarp_status st = SWR_CALL(c, swarp_cascade_blend(n_s ? NULL : s, m, z, band, n_i ? NULL : &idx, n_w ? NULL : &w));
    if (!swr_verdict(c, st, 2, (void*)&idx, sizeof idx, (void*)&w, sizeof w)) return;
    c->out_scale = 1;
    swr_rec(c, "weight", w);
    SWR_CHECK(c, idx < m && w >= 0 && w <= 1, "index %u of %zu, weight %g", idx, m, w);
    if (band == 0) SWR_CHECK(c, w == 0 || w == 1, "band 0 but weight %g", w);
}

static void e_cascade_splits(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_splits);
    static const double brk_n[] = {1e-6, 1.0};
    double n = swr_num(c, 1e-6, 10, brk_n, 2), f = swr_one_in(c, 20) ? n : n * swr_num(c, 1.5, 1e7, NULL, 0);
    swarp_split_options o;
    memset(&o, 0, sizeof o);
    o.count = swr_one_in(c, 10) ? swr_u8(c) : swr_u8(c) % 17;
    o.scheme = (swarp_split_scheme)swr_enum(c, 5);
    static const double brk01[] = {0.0, 1.0, 0.5};
    o.lambda = swr_num(c, 0, 1, brk01, 3);
    o.pseudo_near = swr_num(c, 0, 0.5, brk01, 1);
    o.pseudo_far = swr_num(c, 0, 0.5, brk01, 1);
    o._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use = !swr_one_in(c, 4);
    size_t cap = swr_one_in(c, 8) ? swr_u8(c) % 20 : SWARP_SPLIT_MAX_COUNT + 1;
    int n_o = swr_null(c), n_c = swr_null(c);
    if (n_c || (n_o && cap > 0)) swr_expect(c, SWARP_ERR_NULL_POINTER);
    if (n_o && cap == 0) swr_domain(c, SWARP_ERR_NULL_POINTER);
    FIN(c, n);
    FIN(c, f);
    if (swr_isfin(n) && swr_isfin(f) && !(n > 0 && f > n)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    uint32_t m = use && o.count ? o.count : 4;
    if (use) {
        if ((int)o.scheme < 0 || (int)o.scheme > 4) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        if (o.count > SWARP_SPLIT_MAX_COUNT) swr_expect(c, SWARP_ERR_SPLIT_COUNT);
        for (int i = 0; i < 4; ++i)
            if (o._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        /* lambda and the pseudo planes are read only by the schemes that use
         * them: a NaN elsewhere may be refused or ignored */
        int sch = (int)o.scheme;
        if ((sch == 3 || sch == 4) && !swr_isfin(o.lambda)) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (sch == 4 && (!swr_isfin(o.pseudo_near) || !swr_isfin(o.pseudo_far))) swr_expect(c, SWARP_ERR_NON_FINITE);
        if (!swr_isfin(o.lambda) || !swr_isfin(o.pseudo_near) || !swr_isfin(o.pseudo_far)) swr_domain(c, SWARP_ERR_NON_FINITE);
        swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
    }
    swr_domain(c, SWARP_ERR_CAPACITY);
    swr_domain(c, SWARP_ERR_DEGENERATE);
    double out[SWARP_SPLIT_MAX_COUNT + 2];
    size_t count;
    swr_fill(out, sizeof out);
    swr_fill(&count, sizeof count);
    swarp_status st = SWR_CALL(c, swarp_cascade_splits(n, f, use ? &o : NULL, n_o ? NULL : out, cap, n_c ? NULL : &count));
    if (st == SWARP_ERR_CAPACITY) {
        SWR_CHECK(c, swr_untouched(out, sizeof out), "CAPACITY but splits written");
        swr_fill(&count, sizeof count);
    }
    if (!swr_verdict(c, st, 2, (void*)out, sizeof out, (void*)&count, sizeof count)) return;
    SWR_CHECK(c, count == (size_t)m + 1, "count %zu for m %u", count, m);
    if (count != (size_t)m + 1) return;
    SWR_CHECK(c, out[0] == n && out[m] == f, "C_0 %.17g C_m %.17g", out[0], out[m]);
    for (uint32_t i = 0; i <= m; ++i) {
        swr_rec(c, "C_i", out[i]);
        if (i) SWR_CHECK(c, out[i] > out[i - 1], "not increasing at %u", i);
    }
}

static void e_cascade_nopt(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_nopt);
    double s[9] = {0};
    size_t m = gen_cascade(c, s, 8);
    static const double brk01[] = {0.0, 0.5};
    double np = swr_num(c, 0, 0.5, brk01, 2), fp = swr_num(c, 0, 0.5, brk01, 2);
    int n_s = swr_null(c), n_o = swr_null(c);
    if (n_s || n_o) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_cascade(c, s, m);
    FIN(c, np);
    FIN(c, fp);
    swr_args(c, "m=%zu n_p=%.17g f_p=%.17g s0=%g", m, np, fp, s[0]);
    /* n_p warps the first split, f_p the last: together only when m = 1 */
    if (swr_isfin(np) && swr_isfin(fp) && (np < 0 || !(np < 1) || fp < 0 || !(fp < 1) || (m == 1 && !(np + fp < 1))))
        swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
    double out[9];
    swr_fill(out, sizeof out);
    swarp_status st = SWR_CALL(c, swarp_cascade_nopt(n_s ? NULL : s, m, np, fp, n_o ? NULL : out));
    if (!swr_verdict(c, st, 1, (void*)out, sizeof out)) return;
    for (size_t i = 0; i < m; ++i) {
        if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = out[i];
        SWR_CHECK(c, out[i] > 0 && out[i] == out[i], "n'[%zu] = %g", i, out[i]);
        if (out[i] == INFINITY) SWR_CHECK(c, st == SWARP_INFO_WARP_UNIFORM, "+inf with %s", swarp_status_name(st));
    }
    SWR_CHECK(c, swr_untouched(out + m, sizeof out - m * sizeof out[0]), "wrote past m");
}

const swr_entry swr_entries_splits[] = {
    {"swarp_atlas_layout", "splits", e_atlas_layout},
    {"swarp_atlas_lsc", "splits", e_atlas_lsc},
    {"swarp_atlas_kernel_scale", "splits", e_atlas_kernel_scale},
    {"swarp_stabilize_sphere", "splits", e_stabilize_sphere},
    {"swarp_stabilize_light_view", "splits", e_stabilize_light_view},
    {"swarp_bias_to_light", "splits", e_bias_to_light},
    {"swarp_cascade_select_depth", "splits", e_cascade_select_depth},
    {"swarp_cascade_blend", "splits", e_cascade_blend},
    {"swarp_cascade_splits", "splits", e_cascade_splits},
    {"swarp_cascade_nopt", "splits", e_cascade_nopt},
    {NULL, NULL, NULL},
};
