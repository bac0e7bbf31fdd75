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
#include <stdio.h>
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
    if (dr < 0 || dr > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
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
    double l;
    double* po = swr_out(c, &l, sizeof l, SWR_REQ);
    if (m == 0 || m > SWARP_ATLAS_MAX_SPLITS) swr_expect(c, SWARP_ERR_ATLAS_SPLITS);
    swarp_status st = SWR_CALL(c, swarp_atlas_lsc(m, po));
    if (!swr_done(c, st)) return;
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
    double s[2];
    double* po = swr_out(c, s, sizeof s, SWR_REQ);
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
    swarp_status st = SWR_CALL(c, swarp_atlas_kernel_scale(r, m, x0, x1, y0, y1, po));
    if (!swr_done(c, st)) return;
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
    /* sin(angle(dir, up)) on the documented 1e-9 bound (dir drawn 1e-9
     * from up): DEGENERATE or not is decided by rounding */
    double md = fmax(fabs(cam->dir.x), fmax(fabs(cam->dir.y), fabs(cam->dir.z)));
    double mu = fmax(fabs(cam->up.x), fmax(fabs(cam->up.y), fabs(cam->up.z)));
    if (fin3(&cam->dir) && fin3(&cam->up) && md > 0 && mu > 0) {
        const swarp_vec3 d = {cam->dir.x / md, cam->dir.y / md, cam->dir.z / md};
        const swarp_vec3 u = {cam->up.x / mu, cam->up.y / mu, cam->up.z / mu};
        const swarp_vec3 r = {d.y * u.z - d.z * u.y, d.z * u.x - d.x * u.z, d.x * u.y - d.y * u.x};
        const double rr = r.x * r.x + r.y * r.y + r.z * r.z, dd = d.x * d.x + d.y * d.y + d.z * d.z,
                     uu = u.x * u.x + u.y * u.y + u.z * u.z;
        if (fabs(sqrt(rr / (dd * uu)) / 1e-9 - 1) < 1e-9) c->rounding_edge = 1;
    }
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
    swr_args(c, "eye (%g %g %g) dir (%g %g %g) fovy %.17g aspect %.17g n %.17g f %.17g", cam.eye.x, cam.eye.y,
             cam.eye.z, cam.dir.x, cam.dir.y, cam.dir.z, cam.fovy, cam.aspect, n, f);
    {   /* documented OVERFLOW: radius ~ f tan(fovy/2) sqrt(1 + aspect^2), centre
         * within |eye| + f + radius; a margin of 4 for the library's roundings */
        long double t = tanl(cam.fovy / 2.0L), rr = (long double)f * t * sqrtl(1.0L + (long double)cam.aspect * cam.aspect);
        long double far_pt = fabsl((long double)cam.eye.x) + fabsl((long double)cam.eye.y) + fabsl((long double)cam.eye.z) + f + rr;
        if (swr_isfin(f) && swr_isfin(cam.aspect) && !(far_pt < DBL_MAX / 4.0L)) swr_allow(c, SWARP_ERR_OVERFLOW);
    }
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
        if ((int)o.scheme < 0 || (int)o.scheme > 5) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        /* SWARP_SCHEME_MEASURED needs the scene of swarp_cascade_setup */
        if ((int)o.scheme == 5) swr_expect(c, SWARP_ERR_INVALID_ARGUMENT);
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
        /* Every scheme refuses n_p + f_p >= 1 (OUT_OF_RANGE) on the rounded
         * sum: 0.5 - 2^-54 plus 0.5 is 1 to nearest, 1 - 2^-53 downward, so
         * within an ulp of 1 the caller's rounding mode decides the status.
         * The pseudo scheme [RHS] (4.1) also refuses an empty pseudo range,
         * n_p = n + n_p (f - n) >= f_p = f - f_p (f - n) on the rounded
         * planes; their exact distance is (1 - n_p - f_p)(f - n), and each
         * plane is a rounded product and sum within 2 ulps of f, so below
         * 8 eps f the rounding decides too.  A sum of exactly 1 or more is
         * refused in every mode (the rounded sum of two non-negative terms
         * is >= 1 when the exact one is). */
        if (swr_isfin(o.pseudo_near) && swr_isfin(o.pseudo_far)) {
            const long double gap = 1.0L - o.pseudo_near - o.pseudo_far; /* within 2^-64: far below the bounds */
            if (gap > 0 && gap <= 2 * DBL_EPSILON) c->rounding_edge = 1;
            if (sch == 4 && gap > 0 && swr_isfin(n) && swr_isfin(f) && f > n &&
                gap * ((long double)f - n) <= 8 * DBL_EPSILON * (long double)f)
                c->rounding_edge = 1;
        }
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
    /* n_p + f_p < 1 on the rounded sum (as swarp_warp_nopt_pseudo's entry,
     * entries_core.c): 0.5 - 2^-54 + 0.5 is 1 to nearest, 1 - 2^-53
     * downward, so the status is the rounding mode's within an ulp of 1 */
    if (m == 1 && fabs(np + fp - 1.0) <= 4 * DBL_EPSILON) c->rounding_edge = 1;
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

/* ------------------------------------------------------------------------ */
/* stabilised matrices, bias, split selection by resolution, error curve     */
/* (table-driven shape of swr.h; references in long double from the        */
/* definitions, not from src/)                                              */
/* ------------------------------------------------------------------------ */
SWR_WEAK(swarp_stabilize_directional)
SWR_WEAK(swarp_stabilize_snap_matrix)
SWR_WEAK(swarp_bias_texel_size)
SWR_WEAK(swarp_bias_kozlov)
SWR_WEAK(swarp_bias_normal_offset)
SWR_WEAK(swarp_bias_slope_scaled)
SWR_WEAK(swarp_bias_depth_per_world)
SWR_WEAK(swarp_bias_receiver_plane)
SWR_WEAK(swarp_cascade_view_depth)
SWR_WEAK(swarp_cascade_select_best)
SWR_WEAK(swarp_cascade_error_curve)

typedef long double ld;
static swarp_vec3 V3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}
static double vmax3(swarp_vec3 v) { return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z))); }
static double dot3(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static swarp_vec3 unit3(swarp_vec3 a) {
    double m = vmax3(a); /* scaled first: tiny and huge vectors are valid */
    if (!(m > 0)) return a;
    a = V3(a.x / m, a.y / m, a.z / m);
    double l = sqrt(dot3(a, a));
    return V3(a.x / l, a.y / l, a.z / l);
}
/* clip coordinates of p: h[r] = sum_c M(r, c) p_c, in long double */
static void clip_of(const swarp_mat4* M, swarp_vec3 p, ld h[4]) {
    for (int r = 0; r < 4; ++r) h[r] = (ld)M->m[r] * p.x + (ld)M->m[4 + r] * p.y + (ld)M->m[8 + r] * p.z + M->m[12 + r];
}
/* sum of |terms| of clip row r: what the double evaluation of h[r] is rounded against */
static ld clip_mag(const swarp_mat4* M, swarp_vec3 p, int r) {
    return fabsl((ld)M->m[r] * p.x) + fabsl((ld)M->m[4 + r] * p.y) + fabsl((ld)M->m[8 + r] * p.z) + fabsl((ld)M->m[12 + r]);
}
/* kappa of M (infinity norm, long double Gauss-Jordan); 1e300 when singular */
static int gauss_jordan(ld A[4][8], int ncols);
static double mat_cond_inv(const swarp_mat4* M, ld inv[4][4]);
static double mat_cond(const swarp_mat4* M) {
    ld inv[4][4];
    return mat_cond_inv(M, inv);
}
static double mat_cond_inv(const swarp_mat4* M, ld inv[4][4]) {
    ld A[4][8];
    ld nm = 0, ni = 0;
    for (int r = 0; r < 4; ++r) {
        ld row = 0;
        for (int k = 0; k < 4; ++k) A[r][k] = M->m[k * 4 + r], A[r][4 + k] = r == k, row += fabsl(A[r][k]);
        nm = fmaxl(nm, row);
    }
    if (!gauss_jordan(A, 8)) return 1e300;
    for (int r = 0; r < 4; ++r) {
        ld row = 0;
        for (int k = 0; k < 4; ++k) row += fabsl(inv[r][k] = A[r][4 + k] / A[r][r]);
        ni = fmaxl(ni, row);
    }
    return (double)(nm * ni);
}
/* Gauss-Jordan with partial pivoting on the 4 rows of A, columns [0, ncols):
 * afterwards A[r][r] is the pivot and the right-hand columns hold A[r][r] x;
 * 0 when singular */
static int gauss_jordan(ld A[4][8], int ncols) {
    for (int col = 0; col < 4; ++col) {
        int piv = col;
        for (int r = col + 1; r < 4; ++r)
            if (fabsl(A[r][col]) > fabsl(A[piv][col])) piv = r;
        if (!(fabsl(A[piv][col]) > 0)) return 0;
        for (int k = 0; k < ncols; ++k) {
            ld t = A[col][k];
            A[col][k] = A[piv][k], A[piv][k] = t;
        }
        for (int r = 0; r < 4; ++r)
            if (r != col) {
                ld f = A[r][col] / A[col][col];
                for (int k = col; k < ncols; ++k) A[r][k] -= f * A[col][k];
            }
    }
    return 1;
}
/* the world point whose NDC is (x, y, z): solves M q = w (x, y, z, 1) for
 * q = (q, 1) (long double) */
static int world_of(const swarp_mat4* M, ld x, ld y, ld z, ld q[3]) {
    /* unknowns q0 q1 q2 and w: M(r,0..2) q - w ndc_r = -M(r,3) */
    ld A[4][8];
    const ld ndc[4] = {x, y, z, 1};
    for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 3; ++k) A[r][k] = M->m[k * 4 + r];
        A[r][3] = -ndc[r];
        A[r][4] = -(ld)M->m[12 + r];
    }
    if (!gauss_jordan(A, 5)) return 0;
    for (int k = 0; k < 3; ++k) q[k] = A[k][4] / A[k][k];
    return isfinite((double)q[0]) && isfinite((double)q[1]) && isfinite((double)q[2]);
}

typedef struct bias_args {
    swarp_bias_map map;
    swarp_light light;
    swarp_vec3 p, normal, ta, tb;
    int perspective;
} bias_args;

/* A map: an ortho or perspective projection times a rigid view (rotation
 * from a random unit quaternion, the eye offset by up to 1e6), a point in
 * front of it (sometimes behind, on the eye plane, or outside the map), a
 * light, a normal and two tangents. */
static void gen_bias(swr_ctx* c, bias_args* b) {
    memset(b, 0, sizeof *b);
    double qw = swr_num_in(c, -1, 1, NULL, 0), qx = swr_num_in(c, -1, 1, NULL, 0), qy = swr_num_in(c, -1, 1, NULL, 0),
           qz = swr_num_in(c, -1, 1, NULL, 0);
    double ql = sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
    if (!(ql > 1e-3)) qw = 1, qx = qy = qz = 0, ql = 1;
    qw /= ql, qx /= ql, qy /= ql, qz /= ql;
    const double R[3][3] = {{1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)},
                            {2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)},
                            {2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)}};
    swarp_vec3 eye = V3(swr_offset(c) + swr_num_in(c, -50, 50, NULL, 0), swr_num_in(c, -50, 50, NULL, 0), swr_offset(c));
    /* view = [R | -R eye] */
    double V[16] = {0};
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) V[k * 4 + r] = R[r][k];
        V[12 + r] = -(R[r][0] * eye.x + R[r][1] * eye.y + R[r][2] * eye.z);
    }
    V[15] = 1;
    static const double brk_n[] = {1e-6, 1.0};
    double n = swr_num_in(c, 1e-6, 10, brk_n, 2), f = n * swr_num_in(c, 1.5, 1e7, NULL, 0);
    double P[16] = {0};
    b->perspective = swr_one_in(c, 2);
    double sx = swr_num_in(c, 1e-3, 10, NULL, 0), sy = swr_num_in(c, 1e-3, 10, NULL, 0);
    if (b->perspective) { /* OpenGL-style frustum */
        P[0] = sx, P[5] = sy, P[10] = -(f + n) / (f - n), P[11] = -1, P[14] = -2 * f * n / (f - n);
    } else { /* ortho over depth [n, f] */
        P[0] = sx / 10, P[5] = sy / 10, P[10] = -2 / (f - n), P[14] = -(f + n) / (f - n), P[15] = 1;
    }
    b->map.depth = (swarp_depth_range)swr_enum(c, 3);
    if ((int)b->map.depth == 2) { /* [0, 1]: z' = (z + w)/2 */
        for (int k = 0; k < 4; ++k) P[k * 4 + 2] = 0.5 * (P[k * 4 + 2] + P[k * 4 + 3]);
    }
    if ((int)b->map.depth == 3) { /* reversed-Z: z' = w - (z + w)/2 = (w - z)/2 */
        for (int k = 0; k < 4; ++k) P[k * 4 + 2] = 0.5 * (P[k * 4 + 3] - P[k * 4 + 2]);
    }
    for (int col = 0; col < 4; ++col)
        for (int r = 0; r < 4; ++r) {
            double acc = 0;
            for (int k = 0; k < 4; ++k) acc += P[k * 4 + r] * V[col * 4 + k];
            b->map.world_to_clip.m[col * 4 + r] = acc;
        }
    static const double brk_res[] = {1.0, 2048.0};
    b->map.res_s = swr_num(c, 1, 8192, brk_res, 2);
    b->map.res_t = swr_one_in(c, 2) ? b->map.res_s : swr_num(c, 1, 8192, brk_res, 2);
    b->map._reserved[swr_u8(c) % 4] = swr_reserved(c);
    if (swr_one_in(c, 64)) b->map._reserved0 = 1;
    if (swr_one_in(c, 32)) b->map.world_to_clip.m[swr_u8(c) % 16] = swr_num(c, -1, 1, NULL, 0);
    /* the point: view space (x, y, -z) then world = R^T (v) + eye */
    double z = swr_num_in(c, n, f, brk_n, 0), ext = b->perspective ? z : 10;
    double vx = swr_num_in(c, -1.2, 1.2, NULL, 0) * ext / sx, vy = swr_num_in(c, -1.2, 1.2, NULL, 0) * ext / sy, vz = -z;
    uint8_t where = swr_u8(c) % 32;
    if (where == 0) vz = 0;        /* on the eye plane: w = 0 for a perspective map */
    if (where == 1) vz = z;        /* behind */
    b->p = V3(R[0][0] * vx + R[1][0] * vy + R[2][0] * vz + eye.x, R[0][1] * vx + R[1][1] * vy + R[2][1] * vz + eye.y,
              R[0][2] * vx + R[1][2] * vy + R[2][2] * vz + eye.z);
    if (swr_one_in(c, 32)) b->p.y = swr_num(c, -1, 1, NULL, 0);
    /* the light: directional (often along the map's view axis) or a point */
    swarp_light* L = &b->light;
    L->type = (swarp_light_type)swr_enum(c, 3);
    swarp_vec3 axis = V3(-R[2][0], -R[2][1], -R[2][2]); /* the map looks along -z of its view */
    L->direction = swr_one_in(c, 2) ? axis : V3(swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0));
    if (swr_one_in(c, 32)) L->direction = V3(0, 0, 0);
    L->position = swr_one_in(c, 16) ? b->p : V3(eye.x + swr_num(c, -10, 10, NULL, 0), eye.y, eye.z + swr_num(c, -10, 10, NULL, 0));
    L->_reserved[swr_u8(c) % 4] = swr_reserved(c);
    b->normal = V3(swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0));
    if (swr_one_in(c, 4)) b->normal = V3(-L->direction.x, -L->direction.y, -L->direction.z); /* facing the light */
    if (swr_one_in(c, 32)) b->normal = V3(0, 0, 0);
    b->ta = V3(swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0));
    b->tb = swr_one_in(c, 16) ? b->ta : V3(swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, 1, NULL, 0));
    swr_cond(c, (vmax3(eye) + f) / fmin(n, 1)); /* positions of magnitude |eye| + f against the near plane */
    const double* M = b->map.world_to_clip.m;
    swr_args(c, "M cols (%.17g %.17g %.17g %.17g) (%.17g %.17g %.17g %.17g) (%.17g %.17g %.17g %.17g) (%.17g %.17g %.17g %.17g) res %g %g depth %d p (%.17g %.17g %.17g) light %d",
             M[0], M[1], M[2], M[3], M[4], M[5], M[6], M[7], M[8], M[9], M[10], M[11], M[12], M[13], M[14], M[15], b->map.res_s,
             b->map.res_t, (int)b->map.depth, b->p.x, b->p.y, b->p.z, (int)b->light.type);
    {
        size_t used = strlen(c->args);
        snprintf(c->args + used, sizeof c->args - used, " normal (%.17g %.17g %.17g)", b->normal.x, b->normal.y, b->normal.z);
    }
}
/* what the map and p call for; returns 1 when they are valid (references apply) */
/* the map's own fields; returns 1 when they are valid */
static int expect_map_fields(swr_ctx* c, const swarp_bias_map* m) {
    int ok = 1;
    for (int i = 0; i < 4; ++i)
        if (m->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO), ok = 0;
    if (m->_reserved0) swr_expect(c, SWARP_ERR_RESERVED_NONZERO), ok = 0;
    if ((int)m->depth < 0 || (int)m->depth > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM), ok = 0;
    for (int i = 0; i < 16; ++i)
        if (!swr_isfin(m->world_to_clip.m[i])) swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
    if (!(m->res_s > 0) || !(m->res_t > 0) || !swr_isfin(m->res_s) || !swr_isfin(m->res_t))
        swr_expect(c, SWARP_ERR_RESOLUTION), ok = 0;
    return ok;
}
static int expect_map(swr_ctx* c, const bias_args* b) {
    const swarp_bias_map* m = &b->map;
    int ok = 1;
    /* a normal whose length overflows (components near DBL_MAX) is a valid
     * direction, not a ZERO_VECTOR */
    ok = expect_map_fields(c, m);
    if (!fin3(&b->p)) swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
    if (ok) {
        ld h[4], mag = clip_mag(&m->world_to_clip, b->p, 3);
        clip_of(&m->world_to_clip, b->p, h);
        /* w within the rounding of its terms: either side */
        if (fabsl(h[3]) <= 1e-299L) swr_domain(c, SWARP_ERR_BEHIND_PROJECTION); /* the library's w threshold is 1e-300 */
        if (fabsl(h[3]) <= 1024 * DBL_EPSILON * mag) swr_domain(c, SWARP_ERR_BEHIND_PROJECTION), c->rounding_edge = 1;
        else if (!(h[3] > 0)) swr_expect(c, SWARP_ERR_BEHIND_PROJECTION), ok = 0;
        /* the library inverts M before it looks at w: a numerically singular
         * M (cond > 1/(64 eps)) may be refused with SINGULAR in one rounding
         * mode and pass on to BEHIND_PROJECTION in another (e.g. a 2e25
         * entry swamps the
         * rest of M's last column in the elimination, the last pivot is 0
         * or rounding noise), whatever the sign of w */
        if (!(h[3] > 0)) swr_cond(c, mat_cond(&m->world_to_clip));
        if (h[3] > 0) { /* conditioning: the matrix (texel steps map back through M^-1), the rows' cancellation */
            ld k = 1;
            for (int r = 0; r < 4; ++r)
                if (h[r] != 0) k = fmaxl(k, clip_mag(&m->world_to_clip, b->p, r) / fabsl(h[r]));
            swr_cond(c, (double)k * mat_cond(&m->world_to_clip));
        }
    }
    swr_domain(c, SWARP_ERR_SINGULAR);
    swr_domain(c, SWARP_ERR_NON_FINITE); /* a step that overflows */
    return ok;
}
/* the light's part; returns 1 when valid; *Lv = unit vector toward the light */
static int expect_light(swr_ctx* c, const swarp_light* L, swarp_vec3 p, swarp_vec3* Lv) {
    int t = (int)L->type, ok = 1;
    for (int i = 0; i < 4; ++i)
        if (L->_reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO), ok = 0;
    if (L->_reserved0) swr_expect(c, SWARP_ERR_RESERVED_NONZERO), ok = 0;
    if (t < 0 || t > 2) return swr_expect(c, SWARP_ERR_UNKNOWN_ENUM), 0;
    swarp_vec3 d = t == 2 ? V3(L->position.x - p.x, L->position.y - p.y, L->position.z - p.z)
                          : V3(-L->direction.x, -L->direction.y, -L->direction.z);
    if (!fin3(t == 2 ? &L->position : &L->direction)) return swr_expect(c, SWARP_ERR_NON_FINITE), 0;
    if (d.x == 0 && d.y == 0 && d.z == 0) return swr_expect(c, SWARP_ERR_ZERO_VECTOR), 0;
    *Lv = unit3(d);
    swr_domain(c, SWARP_ERR_ZERO_VECTOR); /* a difference that underflows */
    return ok;
}
/* window depth of p (long double) */
static ld window_depth(const swarp_bias_map* m, swarp_vec3 p) {
    ld h[4];
    clip_of(&m->world_to_clip, p, h);
    ld zn = h[2] / h[3];
    return (int)m->depth == 2 || (int)m->depth == 3 ? zn : (zn + 1) / 2; /* 3: reversed-Z, d = z_ndc */
}
/* d(s, t, d)/d(world) along u: s = (x/w + 1) res_s/2 texels, exact quotient rule */
static void jac_along(swr_ctx* cc_, const swarp_bias_map* m, swarp_vec3 p, swarp_vec3 u, ld out[3]) {
    ld h[4], g[4];
    clip_of(&m->world_to_clip, p, h);
    for (int r = 0; r < 4; ++r) g[r] = (ld)m->world_to_clip.m[r] * u.x + (ld)m->world_to_clip.m[4 + r] * u.y + (ld)m->world_to_clip.m[8 + r] * u.z;
    ld dq[3];
    /* the double evaluation of h = M p carries eps sum|terms| per row: that
     * relative error (k_h) is amplified by the quotient rule's cancellation */
    ld k_h = 1;
    for (int r = 0; r < 4; ++r)
        if (h[r] != 0) k_h = fmaxl(k_h, clip_mag(&m->world_to_clip, p, r) / fabsl(h[r]));
    for (int r = 0; r < 3; ++r) {
        dq[r] = (g[r] * h[3] - h[r] * g[3]) / (h[3] * h[3]);
        ld num = fabsl(g[r] * h[3] - h[r] * g[3]);
        if (num > 0) swr_cond(cc_, (double)(k_h * (fabsl(g[r] * h[3]) + fabsl(h[r] * g[3])) / num));
    }
    out[0] = dq[0] * m->res_s / 2, out[1] = dq[1] * m->res_t / 2, out[2] = (int)m->depth == 2 || (int)m->depth == 3 ? dq[2] : dq[2] / 2;
}
/* the world lengths of one texel step along s and t at constant depth */
static int ref_texel_z(const swarp_bias_map* m, swarp_vec3 p, ld* Ls, ld* Lt, ld zrel, double* kappa_out) {
    ld h[4], q[3];
    clip_of(&m->world_to_clip, p, h);
    ld x = h[0] / h[3], y = h[1] / h[3], z = h[2] / h[3] * zrel;
    /* a texel wider than the map (res < 1): the step leaves the map's frustum and
     * may cross w = 0; no reference */
    if (fabsl(x) + 2.0L / m->res_s > 3 || fabsl(y) + 2.0L / m->res_t > 3) return 0;
    /* mapping an NDC point back divides by w' = row 3 of M^-1 . ndc: its
     * cancellation (a far point has a tiny w') and M's condition number
     * are how much the library's double back-projection may lose */
    if (kappa_out) {
        ld inv[4][4];
        double km = mat_cond_inv(&m->world_to_clip, inv);
        const ld nd[4] = {x + 2.0L / m->res_s, y, z, 1};
        ld w2 = 0, mag = 0;
        for (int k = 0; k < 4; ++k) w2 += inv[3][k] * nd[k], mag += fabsl(inv[3][k] * nd[k]);
        *kappa_out = w2 != 0 ? (double)(mag / fabsl(w2)) * km : 1e300;
    }
    if (!world_of(&m->world_to_clip, x + 2.0L / m->res_s, y, z, q)) return 0;
    *Ls = sqrtl((q[0] - p.x) * (q[0] - p.x) + (q[1] - p.y) * (q[1] - p.y) + (q[2] - p.z) * (q[2] - p.z));
    if (!world_of(&m->world_to_clip, x, y + 2.0L / m->res_t, z, q)) return 0;
    *Lt = sqrtl((q[0] - p.x) * (q[0] - p.x) + (q[1] - p.y) * (q[1] - p.y) + (q[2] - p.z) * (q[2] - p.z));
    return 1;
}
/* ... and its sensitivity to the rounding of NDC z (a double in the library:
 * far depths of a perspective map resolve the world position coarsely),
 * raised into c->cond */
static int ref_texel(swr_ctx* c, const swarp_bias_map* m, swarp_vec3 p, ld* Ls, ld* Lt) {
    double kb = 0;
    if (!ref_texel_z(m, p, Ls, Lt, 1, &kb)) return swr_cond(c, 1e300), 0; /* ill-posed: no claim, any sensitivity */
    swr_cond(c, kb);
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        ld s2, t2;
        if (!ref_texel_z(m, p, &s2, &t2, 1 + sgn * 4 * (ld)DBL_EPSILON, NULL) || !(*Ls > 0 && *Lt > 0)) {
            swr_cond(c, 1e300);
            continue;
        }
        swr_cond(c, (double)(fmaxl(fabsl(s2 - *Ls) / *Ls, fabsl(t2 - *Lt) / *Lt) / (4 * (ld)DBL_EPSILON)));
    }
    /* beyond 1e10 double keeps fewer than 6 digits and the estimate above is
     * a lower bound (the library's own cancellations come on top): the
     * rounding mode may move the result; the fenv test leaves it out */
    if (c->cond > 1e10) c->rounding_edge = 1;
    return 1;
}
/* the texel-size check shared by the bias entries: got vs the reference, relative 1e-6 (the
 * library inverts the matrix in double: conditioning c->cond) */
static void check_texel(swr_ctx* c, const bias_args* b, double got, int which, const char* what) {
    ld Ls, Lt;
    if (!ref_texel(c, &b->map, b->p, &Ls, &Lt)) return;
    ld ref = which == 0 ? (Ls > Lt ? Ls : Lt) : which == 1 ? Ls : Lt;
    /* a difference of two points of magnitude |p|, each resolved to eps |p| kappa */
    swr_close_abs(c, what, got, ref, 1e-6 + 64 * DBL_EPSILON * c->cond, 64 * DBL_EPSILON * c->cond * vmax3(b->p));
}

static void e_bias_texel_size(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_texel_size);
    bias_args b;
    gen_bias(c, &b);
    const swarp_bias_map* pm = swr_in(c, &b.map);
    const swarp_vec3* pp = swr_in(c, &b.p);
    double o[3];
    double* po[3];
    for (int k = 0; k < 3; ++k) po[k] = swr_out(c, &o[k], sizeof o[k], SWR_OPT);
    if (!po[0] && !po[1] && !po[2]) swr_expect(c, SWARP_ERR_NULL_POINTER);
    expect_map(c, &b);
    if (!swr_done(c, SWR_CALL(c, swarp_bias_texel_size(pm, pp, po[0], po[1], po[2])))) return;
    static const char* const names[] = {"L_texel", "L_s", "L_t"};
    for (int k = 0; k < 3; ++k)
        if (po[k]) {
            swr_rec(c, names[k], o[k]);
            /* >= 0: a texel below the resolution of p's coordinates (res 1e84)
             * rounds to 0; the reference comparison's absolute part covers it */
            SWR_CHECK(c, o[k] >= 0, "%s = %g", names[k], o[k]);
            check_texel(c, &b, o[k], k, names[k]);
        }
}

/* the entries that move p toward the light: kozlov (0), normal offset (1) */
static void e_bias_move(swr_ctx* c, int normal_offset) {
    bias_args b;
    gen_bias(c, &b);
    static const double brk[] = {0.0, -1e-9};
    double a = swr_num(c, 0, 0.1, brk, 2), k = swr_num(c, 0, 2, brk, 2);
    const swarp_bias_map* pm = swr_in(c, &b.map);
    const swarp_light* pl = swr_in(c, &b.light);
    const swarp_vec3* pp = swr_in(c, &b.p);
    const swarp_vec3* pn = normal_offset ? swr_in(c, &b.normal) : NULL;
    swarp_vec3 q;
    double amount;
    swarp_vec3* pq = swr_out(c, &q, sizeof q, SWR_REQ);
    double* pa = swr_out(c, &amount, sizeof amount, SWR_OPT);
    int ok = expect_map(c, &b);
    swarp_vec3 L = {0, 0, 0}, N = {0, 0, 0};
    ok &= expect_light(c, &b.light, b.p, &L);
    if (!normal_offset) FIN(c, a); /* a: Kozlov's only */
    FIN(c, k);
    if (normal_offset) {
        if (!fin3(&b.normal)) swr_expect(c, SWARP_ERR_NON_FINITE);
        else if (b.normal.x == 0 && b.normal.y == 0 && b.normal.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
        else N = unit3(b.normal);
        if (k < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    } else {
        swr_domain(c, SWARP_ERR_OUT_OF_RANGE); /* a + b L_texel < 0: predicted below */
    }
    ld Ls = 0, Lt = 0;
    int have_ref = ok && ref_texel(c, &b.map, b.p, &Ls, &Lt);
    ld Ltex = Ls > Lt ? Ls : Lt;
    if (!normal_offset && have_ref && swr_isfin(a) && swr_isfin(k)) {
        ld want = a + k * Ltex;
        /* predicted only when L_texel's own error (conditioning) cannot flip the sign */
        if (want < 0 && fabsl(k * Ltex) < 0.5L * fabsl(a) && 64 * DBL_EPSILON * c->cond < 0.1) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    }
    swarp_status st = normal_offset ? SWR_CALL(c, swarp_bias_normal_offset(pm, pl, pp, pn, k, pq, pa))
                                    : SWR_CALL(c, swarp_bias_kozlov(pm, pl, pp, a, k, pq, pa));
    if (!swr_done(c, st)) return;
    swr_rec(c, "p'", q.x), swr_rec(c, "p'", q.y), swr_rec(c, "p'", q.z);
    if (!have_ref) return;
    /* the move: along L by a + b L_texel (Kozlov), along N by k L_texel (1 - clamp(N.L)) */
    ld NL = (ld)N.x * L.x + (ld)N.y * L.y + (ld)N.z * L.z;
    ld amt = normal_offset ? k * Ltex * (1 - (NL < 0 ? 0 : NL > 1 ? 1 : NL)) : a + k * Ltex;
    swarp_vec3 dir = normal_offset ? N : L;
    double tol = 1e-6 + 64 * DBL_EPSILON * c->cond, pscale = vmax3(b.p);
    double abs_tol = 64 * DBL_EPSILON * c->cond * pscale * (fabs(k) + 1);
    if (pa) swr_close_abs(c, "amount", amount, amt, tol, abs_tol);
    const double got[3] = {q.x - b.p.x, q.y - b.p.y, q.z - b.p.z}, d[3] = {dir.x, dir.y, dir.z};
    for (int i = 0; i < 3; ++i) swr_close_abs(c, "p' - p", got[i], amt * d[i], tol, (double)fabsl(amt) * tol + abs_tol + 4 * DBL_EPSILON * pscale);
    if (normal_offset) {
        if (c->status == SWARP_INFO_BACKFACING) SWR_CHECK(c, NL <= 1e-12L, "BACKFACING with N.L = %Lg", NL);
        else SWR_CHECK(c, NL >= -1e-12L, "N.L = %Lg < 0 without SWARP_INFO_BACKFACING", NL);
    }
}
static void e_bias_kozlov(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_kozlov);
    e_bias_move(c, 0);
}
static void e_bias_normal_offset(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_normal_offset);
    e_bias_move(c, 1);
}

static void e_bias_slope_scaled(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_slope_scaled);
    bias_args b;
    gen_bias(c, &b);
    static const double brk[] = {0.0, -1e-9};
    double cc = swr_num(c, 0, 0.1, brk, 2), ss = swr_num(c, 0, 4, brk, 2);
    const swarp_bias_map* pm = swr_in(c, &b.map);
    const swarp_light* pl = swr_in(c, &b.light);
    const swarp_vec3* pp = swr_in(c, &b.p);
    const swarp_vec3* pn = swr_in(c, &b.normal);
    double wb, db;
    double* pw = swr_out(c, &wb, sizeof wb, SWR_OPT);
    double* pd = swr_out(c, &db, sizeof db, SWR_OPT);
    if (!pw && !pd) swr_expect(c, SWARP_ERR_NULL_POINTER);
    int ok = expect_map(c, &b);
    swarp_vec3 L = {0, 0, 0};
    ok &= expect_light(c, &b.light, b.p, &L);
    FIN(c, cc);
    FIN(c, ss);
    if (cc < 0 || ss < 0) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    if (!fin3(&b.normal)) swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
    else if (b.normal.x == 0 && b.normal.y == 0 && b.normal.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR), ok = 0;
    swr_domain(c, SWARP_ERR_BEHIND_PROJECTION); /* p moved toward the light leaves the map's front */
    if (!swr_done(c, SWR_CALL(c, swarp_bias_slope_scaled(pm, pl, pp, pn, cc, ss, pw, pd)))) return;
    if (pw) {
        swr_rec(c, "world bias", wb);
        SWR_CHECK(c, wb >= 0, "world bias %g", wb);
    }
    if (pd) swr_rec(c, "depth bias", db);
    ld Ls, Lt;
    if (!ok || !ref_texel(c, &b.map, b.p, &Ls, &Lt)) return;
    /* tan from sin = |N x L| and cos = N.L of the raw vectors in long double
     * (sqrt(1 - cos^2) of rounded unit vectors loses half the digits near N || L) */
    const swarp_light* Lg = &b.light;
    ld Lr[3], Nr[3] = {b.normal.x, b.normal.y, b.normal.z};
    if (Lg->type == SWARP_LIGHT_POINT) Lr[0] = (ld)Lg->position.x - b.p.x, Lr[1] = (ld)Lg->position.y - b.p.y, Lr[2] = (ld)Lg->position.z - b.p.z;
    else Lr[0] = -(ld)Lg->direction.x, Lr[1] = -(ld)Lg->direction.y, Lr[2] = -(ld)Lg->direction.z;
    ld cr[3] = {Nr[1] * Lr[2] - Nr[2] * Lr[1], Nr[2] * Lr[0] - Nr[0] * Lr[2], Nr[0] * Lr[1] - Nr[1] * Lr[0]};
    ld sn = sqrtl(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), cs = Nr[0] * Lr[0] + Nr[1] * Lr[1] + Nr[2] * Lr[2];
    ld NL = cs / sqrtl((Nr[0] * Nr[0] + Nr[1] * Nr[1] + Nr[2] * Nr[2]) * (Lr[0] * Lr[0] + Lr[1] * Lr[1] + Lr[2] * Lr[2]));
    ld tn = cs > 0 ? sn / cs : 10;
    if (tn > 10) tn = 10;
    ld want = cc + ss * (Ls > Lt ? Ls : Lt) * tn;
    {
        size_t used = strlen(c->args);
        snprintf(c->args + used, sizeof c->args - used, " | c %.17g s %.17g N.L %.17Lg tan %.17Lg Ls %.17Lg Lt %.17Lg", cc, ss, NL, tn, Ls, Lt);
    }
    double tol = 1e-6 + 64 * DBL_EPSILON * c->cond;
    if (fabsl(NL) < 1e-6L) tol = 1e-3; /* tan's clamp decided by N.L's last bits */
    if (pw) swr_close_abs(c, "world bias", wb, want, tol, 64 * DBL_EPSILON * c->cond * vmax3(b.p) * (ss + 1));
    if (pd && pw) { /* the window-depth difference over the world bias toward the light */
        swarp_vec3 q = V3(b.p.x + wb * L.x, b.p.y + wb * L.y, b.p.z + wb * L.z);
        ld dd = window_depth(&b.map, b.p) - window_depth(&b.map, q);
        /* a difference of two window depths, each rounded to eps kappa */
        swr_close_abs(c, "|depth bias|", fabs(db), fabsl(dd), 1e-5 + 64 * DBL_EPSILON * c->cond, 64 * DBL_EPSILON * c->cond);
    }
}

static void e_bias_depth_per_world(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_depth_per_world);
    bias_args b;
    gen_bias(c, &b);
    const swarp_bias_map* pm = swr_in(c, &b.map);
    const swarp_light* pl = swr_in(c, &b.light);
    const swarp_vec3* pp = swr_in(c, &b.p);
    double k;
    double* pk = swr_out(c, &k, sizeof k, SWR_REQ);
    int ok = expect_map(c, &b);
    swarp_vec3 L = {0, 0, 0};
    ok &= expect_light(c, &b.light, b.p, &L);
    if (!swr_done(c, SWR_CALL(c, swarp_bias_depth_per_world(pm, pl, pp, pk)))) return;
    swr_rec(c, "depth per world", k);
    if (!ok) return;
    ld J[3];
    jac_along(c, &b.map, b.p, L, J); /* minus the derivative of d along L, exactly */
    ld h[4];
    clip_of(&b.map.world_to_clip, b.p, h);
    if (64 * DBL_EPSILON * c->cond < 1) /* else numerically singular: no claim */
        swr_close(c, "depth per world", k, -J[2], 1e-6 + 64 * DBL_EPSILON * c->cond, 1e-9 * (fabsl(h[2] / h[3]) + 1) / (vmax3(b.p) + 1));
}

static void e_bias_receiver_plane(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_bias_receiver_plane);
    bias_args b;
    gen_bias(c, &b);
    const swarp_bias_map* pm = swr_in(c, &b.map);
    const swarp_vec3* pp = swr_in(c, &b.p);
    const swarp_vec3* pa = swr_in(c, &b.ta);
    const swarp_vec3* pb = swr_in(c, &b.tb);
    double g[2];
    double* pg = swr_out(c, g, sizeof g, SWR_REQ);
    int ok = expect_map(c, &b);
    if (!fin3(&b.ta) || !fin3(&b.tb)) swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
    else if ((b.ta.x == 0 && b.ta.y == 0 && b.ta.z == 0) || (b.tb.x == 0 && b.tb.y == 0 && b.tb.z == 0))
        swr_expect(c, SWARP_ERR_ZERO_VECTOR), ok = 0;
    ld Ja[3] = {0}, Jb[3] = {0}, det = 0;
    if (ok) {
        jac_along(c, &b.map, b.p, b.ta, Ja);
        jac_along(c, &b.map, b.p, b.tb, Jb);
        det = Ja[0] * Jb[1] - Ja[1] * Jb[0];
        ld sc = (fabsl(Ja[0]) + fabsl(Ja[1])) * (fabsl(Jb[0]) + fabsl(Jb[1]));
        if (det == 0) swr_expect(c, SWARP_ERR_DEGENERATE);
        if (fabsl(det) < 1e-6L * sc) c->rounding_edge = 1;
        swr_domain(c, SWARP_ERR_DEGENERATE); /* edge-on within the library's 1e-12 */
        swr_cond(c, (double)(sc / fabsl(det)) * (c->cond > 1 ? c->cond : 1)); /* the solve amplifies the derivatives' errors */
    }
    if (!swr_done(c, SWR_CALL(c, swarp_bias_receiver_plane(pm, pp, pa, pb, pg)))) return;
    swr_rec(c, "dd/ds", g[0]), swr_rec(c, "dd/dt", g[1]);
    if (!ok || det == 0) return;
    /* d_a = g_s s_a + g_t t_a, d_b = g_s s_b + g_t t_b (Cramer) */
    ld gs = (Ja[2] * Jb[1] - Jb[2] * Ja[1]) / det, gt = (Ja[0] * Jb[2] - Jb[0] * Ja[2]) / det;
    double fl = 1e-9 * (double)(fabsl(gs) + fabsl(gt)) + 1e-300;
    if (64 * DBL_EPSILON * c->cond >= 1) return; /* numerically singular: no claim */
    /* Cramer's numerators cancel too (a gradient near 0): their own factor */
    ld ns = fabsl(Ja[2] * Jb[1] - Jb[2] * Ja[1]), nt = fabsl(Ja[0] * Jb[2] - Jb[0] * Ja[2]);
    double ks = ns > 0 ? (double)((fabsl(Ja[2] * Jb[1]) + fabsl(Jb[2] * Ja[1])) / ns) : 1e300;
    double kt = nt > 0 ? (double)((fabsl(Ja[0] * Jb[2]) + fabsl(Jb[0] * Ja[2])) / nt) : 1e300;
    swr_close(c, "dd/ds", g[0], gs, 1e-6 + 64 * DBL_EPSILON * c->cond * ks, fl);
    swr_close(c, "dd/dt", g[1], gt, 1e-6 + 64 * DBL_EPSILON * c->cond * kt, fl);
}

static void e_cascade_view_depth(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_view_depth);
    swarp_camera cam;
    gen_cam(c, &cam);
    swarp_vec3 p = V3(cam.eye.x + swr_num(c, -100, 100, NULL, 0), cam.eye.y + swr_num(c, -100, 100, NULL, 0),
                      cam.eye.z + swr_num(c, -100, 100, NULL, 0));
    const swarp_camera* pc = swr_in(c, &cam);
    const swarp_vec3* pp = swr_in(c, &p);
    double z;
    double* pz = swr_out(c, &z, sizeof z, SWR_REQ);
    if (!fin3(&cam.eye) || !fin3(&cam.dir) || !fin3(&p)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (cam.dir.x == 0 && cam.dir.y == 0 && cam.dir.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    else {
        /* documented: OVERFLOW when the depth itself exceeds DBL_MAX (near
         * it, within rounding, either answer) */
        swarp_vec3 d0 = unit3(cam.dir);
        ld r0 = ((ld)p.x - cam.eye.x) * d0.x + ((ld)p.y - cam.eye.y) * d0.y + ((ld)p.z - cam.eye.z) * d0.z;
        if (fabsl(r0) > 0.999 * (ld)DBL_MAX) swr_domain(c, SWARP_ERR_OVERFLOW);
    }
    if (!swr_done(c, SWR_CALL(c, swarp_cascade_view_depth(pc, pp, pz)))) return;
    swr_rec(c, "view depth", z);
    swarp_vec3 d = unit3(cam.dir);
    ld ref = ((ld)p.x - cam.eye.x) * d.x + ((ld)p.y - cam.eye.y) * d.y + ((ld)p.z - cam.eye.z) * d.z;
    if (ref != 0) swr_cond(c, (vmax3(p) + vmax3(cam.eye)) / (double)fabsl(ref)); /* p - eye cancels */
    swr_close_abs(c, "view depth", z, ref, 1e-12, 8 * DBL_EPSILON * (vmax3(p) + vmax3(cam.eye)));
    /* p exactly on the eye's plane (ref 0): the depth is resolved only to
     * eps (|p| + |eye|) absolute, so 0 in one rounding mode and 3e-14 in
     * another are the same answer; relative to z its condition number is
     * (|p| + |eye|)/|z|.  Set after the absolute check above, which holds
     * there and which a singular cond would waive. */
    if (ref == 0 && z != 0) swr_cond(c, (vmax3(p) + vmax3(cam.eye)) / fabs(z));
}

/* p covered by the map: w > 0, |x|, |y| <= w, depth inside; -1 when too close to call */
static int covers(const swarp_bias_map* m, swarp_vec3 p) {
    ld h[4];
    clip_of(&m->world_to_clip, p, h);
    if (!(h[3] > 0)) return h[3] > -1e-9L * (fabsl(h[0]) + fabsl(h[1])) ? -1 : 0;
    /* the margin: 1e-9 of w plus the rounding of the rows' double evaluation */
    ld mag = 0;
    for (int r = 0; r < 4; ++r) mag = fmaxl(mag, clip_mag(&m->world_to_clip, p, r));
    ld lo = (int)m->depth == 2 || (int)m->depth == 3 ? 0 : -h[3], e = 1e-9L * h[3] + 64 * (ld)DBL_EPSILON * mag;
    ld v[3] = {fabsl(h[0]) - h[3], fabsl(h[1]) - h[3], fmaxl(h[2] - h[3], lo - h[2])};
    ld worst = fmaxl(v[0], fmaxl(v[1], v[2]));
    return worst > e ? 0 : worst < -e ? 1 : -1;
}

static void e_cascade_select_best(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_select_best);
    bias_args b[4];
    size_t m = swr_one_in(c, 32) ? (swr_one_in(c, 2) ? 0 : 17) : 1 + swr_u8(c) % 4;
    for (size_t i = 0; i < 4; ++i) gen_bias(c, &b[i]);
    swarp_bias_map maps[17];
    memset(maps, 0, sizeof maps);
    for (size_t i = 0; i < 17; ++i) maps[i] = b[i % 4].map;
    swarp_vec3 p = b[swr_u8(c) % 4].p;
    uint32_t fb = swr_one_in(c, 16) ? (uint32_t)m + swr_u8(c) % 3 : (uint32_t)(m ? swr_u8(c) % m : 0);
    const swarp_bias_map* pm = swr_in(c, maps);
    const swarp_vec3* pp = swr_in(c, &p);
    uint32_t idx;
    double Lt;
    uint32_t* pi = swr_out(c, &idx, sizeof idx, SWR_REQ);
    double* pl = swr_out(c, &Lt, sizeof Lt, SWR_OPT);
    if (m == 0 || m > SWARP_SPLIT_MAX_COUNT) swr_expect(c, SWARP_ERR_SPLIT_COUNT);
    else if (fb >= m) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    int ok = 1;
    for (size_t i = 0; i < m && i < 17; ++i) /* the maps' own errors (p need not be in front of every map) */
        ok &= expect_map_fields(c, &maps[i]);
    if (!fin3(&p)) swr_expect(c, SWARP_ERR_NON_FINITE), ok = 0;
    swr_domain(c, SWARP_ERR_SINGULAR), swr_domain(c, SWARP_ERR_NON_FINITE), swr_domain(c, SWARP_ERR_BEHIND_PROJECTION);
    const swarp_status st = SWR_CALL(c, swarp_cascade_select_best(pm, m, pp, fb, pi, pl));
    /* SINGULAR comes from the first map (in order) whose texel step maps
     * back to w' = 0 (swarp_bias_texel_size validates every map); w' is a
     * cancellation, and when its condition (ref_texel_z's kappa: |terms| /
     * |w'| times M's) is beyond the 1e10 up to which ref_texel trusts the
     * double back-projection, whether it is exactly 0 is the rounding's:
     * under FE_DOWNWARD the map passes and a later map's own error (a NaN
     * resolution: RESOLUTION) is reported instead (e.g.
     * p at 1e10, a map of condition 5e8).  Maps after one with invalid
     * fields are never reached. */
    if (st == SWARP_ERR_SINGULAR && fin3(&p) && m <= SWARP_SPLIT_MAX_COUNT) {
        for (size_t i = 0; i < m; ++i) {
            int valid = 1; /* the fields swarp_bias_texel_size checks first */
            for (int k = 0; k < 16; ++k) valid &= swr_isfin(maps[i].world_to_clip.m[k]);
            valid &= maps[i].res_s > 0 && maps[i].res_t > 0 && swr_isfin(maps[i].res_s) && swr_isfin(maps[i].res_t);
            valid &= (int)maps[i].depth >= 0 && (int)maps[i].depth <= 3 && !maps[i]._reserved0;
            for (int k = 0; k < 4; ++k) valid &= !maps[i]._reserved[k];
            if (!valid) break;
            ld Ls, Lt;
            double kb = 0;
            (void)ref_texel_z(&maps[i], p, &Ls, &Lt, 1, &kb);
            if (kb > 1e10) {
                c->rounding_edge = 1;
                break;
            }
        }
    }
    if (!swr_done(c, st)) return;
    if (c->n_rec < SWR_MAX_REC) c->rec[c->n_rec++] = idx;
    if (pl) swr_rec(c, "L_texel", Lt);
    SWR_CHECK(c, idx < m, "index %u of %zu", idx, m);
    if (!ok || idx >= m) return;
    for (size_t i = 0; i < m; ++i) swr_cond(c, mat_cond(&maps[i].world_to_clip));
    int cov[17], unsure = 0, any = 0;
    ld L[17];
    for (size_t i = 0; i < m; ++i) {
        cov[i] = covers(&maps[i], p);
        ld Ls, Lt2;
        L[i] = cov[i] && ref_texel(c, &maps[i], p, &Ls, &Lt2) ? (Ls > Lt2 ? Ls : Lt2) : INFINITY;
        unsure |= cov[i] < 0, any |= cov[i] == 1;
    }
    if (unsure) { /* a border decided by rounding */
        c->rounding_edge = 1;
        return;
    }
    if (c->status == SWARP_INFO_OUTSIDE_SPLITS) {
        SWR_CHECK(c, !any && idx == fb, "OUTSIDE_SPLITS with a covering map (index %u, fallback %u)", idx, fb);
        if (pl) SWR_CHECK(c, Lt == 0, "fallback with L_texel %g", Lt);
        return;
    }
    SWR_CHECK(c, cov[idx] == 1, "map %u chosen but it does not cover p", idx);
    /* The library compares its own L_texel of each map, each within the
     * accuracy check_texel grants swarp_bias_texel_size (relative 1e-6 +
     * 64 eps cond, absolute 64 eps cond |p|: the matrix inverted in double);
     * a map is finer only beyond both maps' errors.  (A fixed 1e-6 flagged
     * ill-conditioned maps whose texels the double inversion cannot rank.) */
    const ld rel = 1e-6L + 64 * (ld)DBL_EPSILON * c->cond, abs_e = 64 * (ld)DBL_EPSILON * c->cond * vmax3(p);
    for (size_t i = 0; i < m && isfinite((double)L[idx]); ++i) /* (L = inf: no reference for the chosen map) */
        if (cov[i] == 1 && i != idx)
            SWR_CHECK_ACC(c, L[i] * (1 + rel) + abs_e >= L[idx] * (1 - rel) - abs_e, "map %zu has the finer texel (%Lg < %Lg of map %u)", i, L[i], L[idx], idx);
    if (pl && isfinite((double)L[idx]))
        swr_close_abs(c, "L_texel", Lt, L[idx], 1e-6 + 64 * DBL_EPSILON * c->cond, 64 * DBL_EPSILON * c->cond * vmax3(p));
}

static void e_cascade_error_curve(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_cascade_error_curve);
    double s[9] = {0}, np[9];
    size_t m = gen_cascade(c, s, 8);
    swarp_error_config cfg;
    memset(&cfg, 0, sizeof cfg);
    static const double brk_th[] = {1e-9, 1.5707963267948966};
    cfg.theta = swr_num(c, 0.05, 1.5, brk_th, 2);
    cfg.res_ix = swr_num(c, 1, 4096, NULL, 0), cfg.res_iy = swr_num_in(c, 1, cfg.res_ix > 1 ? cfg.res_ix : 1, NULL, 0);
    cfg.res_s = swr_num(c, 1, 8192, NULL, 0), cfg.res_t = swr_num_in(c, 1, cfg.res_s > 1 ? cfg.res_s : 1, NULL, 0);
    cfg._reserved[swr_u8(c) % 4] = swr_reserved(c);
    for (size_t i = 0; i < 9; ++i) np[i] = swr_one_in(c, 8) ? INFINITY : swr_num(c, 1e-3, 1e3, NULL, 0);
    size_t sps = swr_one_in(c, 16) ? swr_u8(c) % 3 : 2 + swr_u8(c) % 24;
    size_t total = m * sps, cap = swr_one_in(c, 8) ? swr_u8(c) % 64 : 8 * 26;
    const swarp_error_config* pc = swr_in(c, &cfg);
    const double* pn = swr_in(c, np);
    double z[8 * 26], mx[8 * 26], mz[8 * 26];
    size_t count;
    double* pz = swr_out(c, z, sizeof z, SWR_REQ);
    double* px = swr_out(c, mx, sizeof mx, SWR_OPT);
    double* pm = swr_out(c, mz, sizeof mz, SWR_OPT);
    size_t* pcount = swr_out(c, &count, sizeof count, SWR_REQ);
    expect_cascade(c, s, m);
    int valid = m >= 1 && m <= SWARP_SPLIT_MAX_COUNT;
    if (valid && (sps < 2)) swr_expect(c, SWARP_ERR_OUT_OF_RANGE);
    else if (valid && cap < total) swr_expect(c, SWARP_ERR_CAPACITY);
    for (int i = 0; i < 4; ++i)
        if (cfg._reserved[i]) swr_domain(c, SWARP_ERR_RESERVED_NONZERO);
    static const swarp_status dom[] = {SWARP_ERR_NON_FINITE, SWARP_ERR_FOV, SWARP_ERR_RESOLUTION, SWARP_ERR_OUT_OF_RANGE,
                                       SWARP_ERR_OVERFLOW, SWARP_ERR_NEAR_FAR};
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; ++i) swr_domain(c, dom[i]);
    swarp_status st = SWR_CALL(c, swarp_cascade_error_curve(pc, s, pn, m, sps, pz, px, pm, cap, pcount));
    if (st == SWARP_ERR_CAPACITY) { /* the needed count is written */
        SWR_CHECK(c, count == total, "CAPACITY with count %zu, needed %zu", count, total);
        swr_fill(&count, sizeof count);
    }
    if (!swr_done(c, st)) return;
    SWR_CHECK(c, count == total, "count %zu, want %zu", count, total);
    if (count != total) return;
    /* the depths: from C_i (inclusive) to just below C_{i+1}, the last one C_m; non-decreasing */
    for (size_t i = 0; i < m; ++i)
        for (size_t j = 0; j < sps; ++j) {
            size_t g = i * sps + j;
            if (g < 64) swr_rec(c, "z", z[g]);
            if (j == 0) SWR_CHECK(c, z[g] == s[i], "split %zu starts at %.17g, not C_i = %.17g", i, z[g], s[i]);
            if (g) SWR_CHECK(c, z[g] >= z[g - 1], "depths decrease at %zu", g);
            int last = i + 1 == m;
            SWR_CHECK(c, z[g] >= s[i] && (last ? z[g] <= s[i + 1] : z[g] < s[i + 1]), "sample %zu (%.17g) outside split %zu", g,
                      z[g], i);
            if (px && g < 64) swr_rec_inf(c, "m_x", mx[g]);
            if (pm && g < 64) swr_rec_inf(c, "m_z", mz[g]);
            if (px) SWR_CHECK(c, mx[g] >= 0, "m_x %g", mx[g]);
            if (pm) SWR_CHECK(c, mz[g] >= 0, "m_z %g", mz[g]);
        }
    SWR_CHECK(c, z[total - 1] == s[m], "the curve ends at %.17g, not C_m = %.17g", z[total - 1], s[m]);
}

static swarp_mat4 uniform_matrix(swr_ctx* c, double* w) {
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    for (int col = 0; col < 3; ++col)
        for (int r = 0; r < 3; ++r) m.m[col * 4 + r] = swr_num_in(c, -1, 1, NULL, 0) * (r == col ? 1 : 0.3) * 1e-2;
    for (int r = 0; r < 3; ++r) m.m[12 + r] = swr_num_in(c, -2, 2, NULL, 0);
    static const double brk_w[] = {0.0, 1.0, -1.0};
    *w = m.m[15] = swr_one_in(c, 2) ? 1.0 : swr_num(c, 0.5, 2, brk_w, 3);
    if (swr_one_in(c, 16)) m.m[3 + 4 * (swr_u8(c) % 3)] = swr_num(c, -1e-3, 1e-3, NULL, 0); /* projective */
    return m;
}

static void e_stabilize_snap_matrix(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_stabilize_snap_matrix);
    double w;
    swarp_mat4 m = uniform_matrix(c, &w);
    static const double brk_r[] = {1.0, 0.0, 2048.0};
    double rs = swr_num(c, 1, 8192, brk_r, 3), rt = swr_one_in(c, 2) ? rs : swr_num(c, 1, 8192, brk_r, 3);
    swarp_vec3 o = V3(swr_offset(c) + swr_num(c, -100, 100, NULL, 0), swr_num(c, -100, 100, NULL, 0), swr_offset(c));
    if (swr_one_in(c, 32)) m.m[swr_u8(c) % 16] = swr_num(c, -1, 1, NULL, 0);
    int in_place = swr_one_in(c, 8);
    const swarp_mat4* pm = swr_in(c, &m);
    const swarp_vec3* po = swr_in(c, &o);
    swarp_mat4 out;
    swarp_mat4* pout = in_place ? NULL : swr_out(c, &out, sizeof out, SWR_REQ);
    int finite = fin3(&o);
    for (int i = 0; i < 16; ++i) finite &= swr_isfin(m.m[i]);
    if (!finite) swr_expect(c, SWARP_ERR_NON_FINITE);
    if (!(rs > 0) || !(rt > 0) || !swr_isfin(rs) || !swr_isfin(rt)) swr_expect(c, SWARP_ERR_RESOLUTION);
    if (finite && (m.m[3] != 0 || m.m[7] != 0 || m.m[11] != 0)) swr_expect(c, SWARP_ERR_STABILIZE_WARPED);
    else if (finite && m.m[15] == 0) swr_expect(c, SWARP_ERR_SINGULAR);
    swr_domain(c, SWARP_ERR_NON_FINITE);
    swarp_mat4 keep = m;
    if (in_place) out = m, pout = pm ? &out : NULL, pm = pm ? &out : NULL; /* out may alias m */
    if (in_place && !pout) swr_expect(c, SWARP_ERR_NULL_POINTER);
    swarp_status st = SWR_CALL(c, swarp_stabilize_snap_matrix(pm, rs, rt, po, pout));
    if (in_place && swarp_status_is_error(st))
        SWR_CHECK(c, memcmp(&out, &keep, sizeof out) == 0, "error %s but the matrix (in place) was written", swarp_status_name(st));
    if (!swr_done(c, st)) return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "snapped", out.m[i]);
    /* the linear part is kept, the translation moves by at most half a texel,
     * and the origin lands on a texel corner */
    for (int i = 0; i < 12; ++i) SWR_CHECK(c, out.m[i] == keep.m[i], "element %d changed", i);
    SWR_CHECK(c, out.m[15] == keep.m[15] && out.m[14] == keep.m[14], "w or z translation changed");
    const double res[2] = {rs, rt};
    w = keep.m[15];
    for (int a = 0; a < 2; ++a) {
        ld shift = (ld)out.m[12 + a] - keep.m[12 + a];
        ld h = (ld)out.m[a] * o.x + (ld)out.m[4 + a] * o.y + (ld)out.m[8 + a] * o.z + out.m[12 + a];
        ld u = (h / w + 1) * res[a] / 2; /* texel coordinate of the origin */
        {   /* before the snap: half-way between two corners is a tie the rounding decides */
            ld h0 = h - shift, u0 = (h0 / w + 1) * res[a] / 2;
            ld hm = fabsl((ld)keep.m[a] * o.x) + fabsl((ld)keep.m[4 + a] * o.y) + fabsl((ld)keep.m[8 + a] * o.z) + fabsl((ld)keep.m[12 + a]);
            if (fabsl(u0 - floorl(u0) - 0.5L) < 1e-6L + 64 * DBL_EPSILON * (hm / fabsl((ld)w) + 1) * res[a]) c->rounding_edge = 1;
        }
        /* the origin's clip x is resolved to eps times the sum of its terms */
        ld hmag = fabsl((ld)out.m[a] * o.x) + fabsl((ld)out.m[4 + a] * o.y) + fabsl((ld)out.m[8 + a] * o.z) + fabsl((ld)out.m[12 + a]);
        ld lin = (hmag / fabsl((ld)w) + 1) * res[a]; /* (x/w + 1) res/2: the + 1 rounds too */
        SWR_CHECK_ACC(c, fabsl(shift) <= fabsl((ld)w) / res[a] * (1 + 1e-9L) + 16 * DBL_EPSILON * hmag, "axis %d: shifted by %Lg > half a texel", a,
                      shift);
        SWR_CHECK_ACC(c, fabsl(u - roundl(u)) <= 1e-6L + 8 * DBL_EPSILON * lin, "axis %d: the origin at texel %.17Lg, not a corner", a, u);
        /* The translation's shift is round(s) - s of the origin's clip x, a
         * sum of terms of magnitude hmag: its inputs resolve it to eps hmag
         * (absolute), so under another rounding mode the snapped translation
         * moves by that much -- at a 1e6 offset with a 1e-2 scale ~1e-4 of a
         * texel, 1e-7..1e-4 of the outputs.  Its condition number relative to
         * the largest output is hmag / max|out|. */
        double omax = 0;
        for (int i = 0; i < 16; ++i) omax = fmax(omax, fabs(out.m[i]));
        if (omax > 0) swr_cond(c, (double)hmag / omax);
    }
}

/* a·(p - p0) in long double: p - p0 of doubles is exact there when they
 * are within 2^11 of each other in magnitude (the body points here) */
static ld along(swarp_vec3 a, swarp_vec3 p, swarp_vec3 p0) {
    return (ld)a.x * ((ld)p.x - p0.x) + (ld)a.y * ((ld)p.y - p0.y) + (ld)a.z * ((ld)p.z - p0.z);
}

static void e_stabilize_directional(swr_ctx* c) {
    SKIP_IF_MISSING(c, swarp_stabilize_directional);
    swarp_camera cam;
    gen_cam(c, &cam);
    static const double brk_n[] = {1e-6, 1.0};
    double n = swr_num(c, 1e-6, 10, brk_n, 2), f = swr_one_in(c, 16) ? n : n * swr_num(c, 1.5, 1e5, NULL, 0);
    swarp_vec3 ld_ = V3(swr_num(c, -1, 1, NULL, 0), swr_num(c, -1, -0.05, NULL, 0), swr_num(c, -1, 1, NULL, 0));
    if (swr_one_in(c, 8)) ld_ = unit3(cam.dir); /* along the view */
    if (swr_one_in(c, 32)) ld_ = V3(0, 0, 0);
    swarp_vec3 pts[8];
    size_t np = swr_one_in(c, 8) ? 0 : 1 + swr_u8(c) % 8;
    for (size_t i = 0; i < 8; ++i)
        pts[i] = V3(cam.eye.x + swr_num_in(c, -1, 1, NULL, 0) * f, cam.eye.y + swr_num_in(c, -1, 1, NULL, 0) * f,
                    cam.eye.z + swr_num_in(c, -1, 1, NULL, 0) * f);
    swarp_aabb box = {V3(cam.eye.x - 2 * f, cam.eye.y - 2 * f, cam.eye.z - 2 * f), V3(cam.eye.x + 2 * f, cam.eye.y + f, cam.eye.z + 2 * f)};
    if (swr_one_in(c, 16)) box.min.x = box.max.x + 1;
    int use_box = swr_one_in(c, 2);
    static const double brk_res[] = {2.0, 1.0, 2048.0};
    uint32_t res = swr_one_in(c, 16) ? swr_u8(c) % 3 : (uint32_t)swr_num_in(c, 2, 8192, brk_res, 3);
    swarp_stabilize_options o;
    memset(&o, 0, sizeof o);
    o.mode = (swarp_stabilize_mode)swr_enum(c, 4);
    o.levels = swr_one_in(c, 2) ? 0 : swr_u8(c);
    o.origin = V3(swr_offset(c), 0, swr_offset(c));
    o.level_max_size = swr_one_in(c, 2) ? 0 : swr_num(c, 0, 1e4, NULL, 0);
    o.depth = (swarp_depth_range)swr_enum(c, 3);
    o._reserved[swr_u8(c) % 4] = swr_reserved(c);
    int use_o = !swr_one_in(c, 4);
    int mode = use_o ? (int)o.mode : 0;
    const swarp_camera* pc = swr_in(c, &cam);
    const swarp_vec3* pd = swr_in(c, &ld_);
    const swarp_vec3* pp = np ? (swr_null(c) ? NULL : pts) : NULL;
    if (np && !pp) (mode == 2 ? swr_domain : swr_expect)(c, SWARP_ERR_NULL_POINTER); /* SPHERE: points may be NULL */
    swarp_mat4 M;
    swarp_stabilize_report rep;
    swarp_mat4* pm = swr_out(c, &M, sizeof M, SWR_REQ);
    swarp_stabilize_report* pr = swr_out(c, &rep, sizeof rep, SWR_OPT);
    expect_cam(c, &cam);
    FIN(c, n);
    FIN(c, f);
    if (swr_isfin(n) && swr_isfin(f) && !(n > 0 && f > n)) swr_expect(c, SWARP_ERR_NEAR_FAR);
    if (!fin3(&ld_)) swr_expect(c, SWARP_ERR_NON_FINITE);
    else if (ld_.x == 0 && ld_.y == 0 && ld_.z == 0) swr_expect(c, SWARP_ERR_ZERO_VECTOR);
    if (res < 2) swr_expect(c, SWARP_ERR_RESOLUTION);
    if (use_o) {
        if (mode < 0 || mode > 3 || (int)o.depth < 0 || (int)o.depth > 3) swr_expect(c, SWARP_ERR_UNKNOWN_ENUM);
        for (int i = 0; i < 4; ++i)
            if (o._reserved[i]) swr_expect(c, SWARP_ERR_RESERVED_NONZERO);
        if (!swr_isfin(o.level_max_size)) swr_domain(c, SWARP_ERR_NON_FINITE);
        swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
    }
    if (np == 0 && mode != 2) swr_domain(c, SWARP_ERR_NULL_POINTER), swr_domain(c, SWARP_ERR_INVALID_ARGUMENT), swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
    if (use_box && box.min.x > box.max.x) swr_domain(c, SWARP_ERR_BOX_INVERTED), swr_domain(c, SWARP_ERR_OUT_OF_RANGE);
    if (use_box && (!fin3(&box.min) || !fin3(&box.max))) swr_expect(c, SWARP_ERR_NON_FINITE); /* eye +- 2f overflowed */
    for (size_t i = 0; pp && i < np; ++i)
        if (!fin3(&pts[i])) swr_expect(c, SWARP_ERR_NON_FINITE); /* eye + r f overflowed */
    swr_domain(c, SWARP_ERR_DEGENERATE);
    /* FINDING (docs/quality.md): NON_FINITE for finite arguments (e.g. LEVELS
     * with one body point of a 1e-6..7e-5 split at origin 3e6) */
    if (!use_o || swr_isfin(o.level_max_size)) swr_finding_status(c, SWARP_ERR_NON_FINITE);
    {   /* documented OVERFLOW: the matrix holds (coordinate)/(map half size)
         * and 2/(depth extent); coordinates ~ |eye| + |origin| + f (1 + k),
         * the map and depth extents >= ~ the split's size min(f - n, f tan),
         * a texel (size/res) or a ulp of the coordinates.  Estimated in long
         * double; allowed within a factor 1e6 of DBL_MAX (the extents of the
         * body points and box are not bounded more tightly here), and when
         * the coordinates themselves come within that factor of DBL_MAX. */
        ld k = tanl((ld)cam.fovy / 2) * (1 + (ld)cam.aspect);
        ld M = (ld)vmax3(cam.eye) + vmax3(o.origin) + (ld)f * (1 + k);
        ld size = fminl((ld)f - n, (ld)f * tanl((ld)cam.fovy / 2)) / (res > 0 ? res : 1);
        size = fminl(size, (ld)f * tanl((ld)cam.fovy / 2) * 2 / (o.levels ? o.levels : 64) / (res > 0 ? res : 1));
        if (use_o && o.level_max_size > 0) size = fminl(size, (ld)o.level_max_size / (o.levels ? o.levels : 64));
        if (swr_isfin(f) && swr_isfin(n) && fin3(&cam.eye) && (!(M / size < (ld)DBL_MAX * 1e-6L) || !(M < (ld)DBL_MAX * 1e-6L)))
            swr_allow(c, SWARP_ERR_OVERFLOW);
    }
    if (vmax3(cam.eye) > 1e300 || f > 1e300) swr_domain(c, SWARP_ERR_NON_FINITE); /* an overflow before the other checks */
    swr_cond(c, (vmax3(cam.eye) + vmax3(o.origin) + f) / n);
    /* the map's lateral extent is about the split's width f tan(fovy/2) (x
     * also times the aspect): the matrix divides coordinates resolved to eps
     * |eye| by it, so its relative condition is (coordinates) / (width) as
     * well (fovy 1e-6 at an eye 3e6 away: width 7.5e-6, cond 6e11; the
     * translation moved by 8e-9 with the rounding mode) */
    if (swr_isfin(cam.fovy) && cam.fovy > 0 && cam.fovy < 3.14159 && swr_isfin(cam.aspect) && cam.aspect > 0 && swr_isfin(f) && f > 0) {
        const double width = f * tan(cam.fovy / 2) * fmin(1.0, cam.aspect);
        if (width > 0) swr_cond(c, (vmax3(cam.eye) + vmax3(o.origin) + f) / width);
    }
    /* The same for the depth: outside SPHERE the depth row is 2/dt (1/dt)
     * and its translation -(t_max + t_min)/dt, dt the extent along the light
     * of the body points (and the box's corners toward it), t = d·(p - O)
     * from coordinates resolved to eps (|eye| + |origin| + f): the depth
     * row's relative condition is (coordinates) / dt (body points 0.08 deep
     * along the light, the origin 1e6 away: cond 1.2e7; the depth
     * translation -2.5e7 moved by 4e-9 relative with the rounding mode).  dt = 0 is the library's flat case (one
     * texel either side, covered by the width's).  The extents are taken
     * from differences to the first point (p - p_0 is exact in long
     * double): a light axis 1e-95 off a world axis adds 1e-95 x to the
     * coordinates, which a sum at the origin's 1e6 loses and a difference
     * keeps (e.g. two points with
     * the same z under such a light, extent 0 to nearest, DEGENERATE, and
     * one ulp in the directed modes). */
    if (mode != 2 && pp && np > 0 && fin3(&ld_) && vmax3(ld_) > 0) {
        const swarp_vec3 dl = unit3(ld_);
        const ld coords = (ld)vmax3(cam.eye) + vmax3(o.origin) + f;
        ld t_lo = 0, t_hi = 0;
        for (size_t i = 1; i < np; ++i) t_lo = fminl(t_lo, along(dl, pts[i], pts[0])), t_hi = fmaxl(t_hi, along(dl, pts[i], pts[0]));
        if (use_box)
            for (int k = 0; k < 8; ++k) {
                const swarp_vec3 q = V3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z);
                t_lo = fminl(t_lo, along(dl, q, pts[0]));
            }
        const ld dt = t_hi - t_lo;
        if (dt > 0 && isfinite((double)dt)) swr_cond(c, (double)(coords / dt));
        /* NONE fits the map to the body points' light-space box as well:
         * x and y rows 1/h_x, 1/h_y with h the half extents along the
         * light's right and up axes (the library's basis: helper axis y, x
         * for a light within 8° of vertical), of the same coordinates: the
         * condition is (coordinates) / (smaller extent) (two points whose x
         * differ by 2 ulps of 5e5 under a vertical light: h_y 5.8e-11, 1/h_y
         * 2^34 to nearest and 2^33 in the directed modes, cond 4e15:
         * numerically singular). */
        /* LEVELS quantises the padded extent e res/(res - 1) up to a whole
         * number of steps ref/levels (ref: level_max_size, or the diameter
         * of the split's minimal sphere): the level is an integer the
         * rounding of e decides when the exact quotient q lies within a few
         * ulps of its condition of an integer: e is a difference of two dot
         * products of coordinates, each rounded by a few eps coords, so q is
         * off by ~4 eps q coords/e; 8 eps q (coords/e + 1) is the bound
         * (the + 1: res/(res - 1) and the step's own rounding).  7 points
         * 3e-6 across at 1.1e6 from the origin: cond 4e11, q = 23.9998 (2e-4
         * from 24 against a bound of 0.016), level 24 or 25 by rounding
         * mode, the map 4 % larger. */
        const int levels_mode = mode == 3 && use_o;
        ld step = 0;
        if (levels_mode && res >= 2 && swr_isfin(n) && swr_isfin(f) && f > n && swr_isfin(o.level_max_size)) {
            ld ref = o.level_max_size;
            if (!(ref > 0)) { /* 2 r of the minimal sphere, as src/cascade/stabilize.c */
                const ld t = tanl((ld)cam.fovy / 2), k = hypotl(t, t * cam.aspect);
                ld d_far = k < 1 ? 0.5L * ((ld)f - n) - 0.5L * ((ld)n + f) * k * k : 0;
                if (!(d_far > 0)) d_far = 0;
                ref = 2 * hypotl(d_far, (ld)f * k);
            }
            step = ref / (o.levels ? o.levels : 64);
        }
        if (mode == 0 || mode == 1 || levels_mode) {
            const swarp_vec3 helper = fabs(dl.y) > 0.99 ? V3(1, 0, 0) : V3(0, 1, 0);
            const swarp_vec3 ua = unit3(V3(dl.y * helper.z - dl.z * helper.y, dl.z * helper.x - dl.x * helper.z,
                                           dl.x * helper.y - dl.y * helper.x));
            const swarp_vec3 va = V3(ua.y * dl.z - ua.z * dl.y, ua.z * dl.x - ua.x * dl.z, ua.x * dl.y - ua.y * dl.x);
            const swarp_vec3 ax[2] = {ua, va};
            for (int a = 0; a < 2; ++a) {
                ld lo = 0, hi = 0;
                for (size_t i = 1; i < np; ++i) lo = fminl(lo, along(ax[a], pts[i], pts[0])), hi = fmaxl(hi, along(ax[a], pts[i], pts[0]));
                const ld e = hi - lo;
                if (!(e > 0) || !isfinite((double)e)) continue;
                if (!levels_mode) {
                    swr_cond(c, (double)(coords / e));
                } else if (step > 0 && isfinite((double)step)) {
                    const ld q = e * res / (res - 1.0L) / step;
                    if (q >= 0.5L && fabsl(q - roundl(q)) <= 8 * DBL_EPSILON * q * (coords / e + 1)) c->rounding_edge = 1;
                }
            }
        }
    }
    swr_args(c, "eye (%g %g %g) dir (%g %g %g) fovy %g aspect %g n %.17g f %.17g light (%g %g %g) np %zu res %u mode %d levels %u origin (%g %g %g) lms %g box %d",
             cam.eye.x, cam.eye.y, cam.eye.z, cam.dir.x, cam.dir.y, cam.dir.z, cam.fovy, cam.aspect, n, f, ld_.x, ld_.y, ld_.z, np, res,
             mode, o.levels, o.origin.x, o.origin.y, o.origin.z, o.level_max_size, use_box);
    swarp_status st = SWR_CALL(c, swarp_stabilize_directional(pc, n, f, pd, pp, np, use_box ? &box : NULL, res, use_o ? &o : NULL, pm, pr));
    if (!swr_done(c, st)) return;
    for (int i = 0; i < 16; ++i) swr_rec(c, "matrix", M.m[i]);
    if (!pr) return;
    swr_rec(c, "texel x", rep.texel_size_x), swr_rec(c, "texel y", rep.texel_size_y);
    swr_rec(c, "offset x", rep.offset_x), swr_rec(c, "offset y", rep.offset_y);
    SWR_CHECK(c, rep.texel_size_x > 0 && rep.texel_size_y > 0, "texel sizes %g %g", rep.texel_size_x, rep.texel_size_y);
    if (mode == 2 || mode == 3) { /* snapped: the centre offsets are whole texels */
        ld ux = (ld)rep.offset_x / rep.texel_size_x, uy = (ld)rep.offset_y / rep.texel_size_y;
        SWR_CHECK_ACC(c, fabsl(ux - roundl(ux)) <= 1e-6L + 8 * DBL_EPSILON * fabsl(ux) && fabsl(uy - roundl(uy)) <= 1e-6L + 8 * DBL_EPSILON * fabsl(uy),
                      "offsets %.17Lg, %.17Lg texels: not whole", ux, uy);
    }
    if (mode == 2) { /* the split frustum's corners map into the square (matrix takes p - origin) */
        swarp_vec3 d = unit3(cam.dir), up = unit3(cam.up), r;
        r = V3(d.y * up.z - d.z * up.y, d.z * up.x - d.x * up.z, d.x * up.y - d.y * up.x);
        r = unit3(r);
        up = V3(r.y * d.z - r.z * d.y, r.z * d.x - r.x * d.z, r.x * d.y - r.y * d.x);
        /* tx in long double: aspect near DBL_MAX overflows tan(fovy/2) aspect
         * in double (the corners came out NaN) while f tx is finite */
        ld ty = tanl((ld)cam.fovy / 2), tx = ty * cam.aspect;
        for (int k = 0; k < 8; ++k) {
            ld z = (k & 4) ? f : n, sx = (k & 1) ? 1 : -1, sy = (k & 2) ? 1 : -1;
            ld q[3] = {(ld)cam.eye.x + z * (d.x + sx * tx * r.x + sy * ty * up.x) - o.origin.x,
                       (ld)cam.eye.y + z * (d.y + sx * tx * r.y + sy * ty * up.y) - o.origin.y,
                       (ld)cam.eye.z + z * (d.z + sx * tx * r.z + sy * ty * up.z) - o.origin.z};
            ld h[4];
            for (int row = 0; row < 4; ++row) h[row] = M.m[row] * q[0] + M.m[4 + row] * q[1] + M.m[8 + row] * q[2] + M.m[12 + row];
            double tol = 1e-6 + 64 * DBL_EPSILON * c->cond;
            SWR_CHECK_ACC(c, fabsl(h[0] / h[3]) <= 1 + tol && fabsl(h[1] / h[3]) <= 1 + tol, "corner %d maps to (%Lg, %Lg)", k,
                          h[0] / h[3], h[1] / h[3]);
        }
    }
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
    {"swarp_stabilize_directional", "splits", e_stabilize_directional},
    {"swarp_stabilize_snap_matrix", "splits", e_stabilize_snap_matrix},
    {"swarp_bias_texel_size", "splits", e_bias_texel_size},
    {"swarp_bias_kozlov", "splits", e_bias_kozlov},
    {"swarp_bias_normal_offset", "splits", e_bias_normal_offset},
    {"swarp_bias_slope_scaled", "splits", e_bias_slope_scaled},
    {"swarp_bias_depth_per_world", "splits", e_bias_depth_per_world},
    {"swarp_bias_receiver_plane", "splits", e_bias_receiver_plane},
    {"swarp_cascade_view_depth", "splits", e_cascade_view_depth},
    {"swarp_cascade_select_best", "splits", e_cascade_select_best},
    {"swarp_cascade_error_curve", "splits", e_cascade_error_curve},
    {NULL, NULL, NULL},
};
