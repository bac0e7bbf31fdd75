/* Every byte the library writes is a function of its inputs alone.
 *
 * The property: for every entry point that writes a struct or an array,
 * two identical calls give byte-identical outputs even
 * when the caller's output memory and the stack the library runs on hold
 * different bytes before the call.  Fixed-size outputs (structs, matrices,
 * fixed arrays, polyhedra) are compared byte for byte over their whole size,
 * padding, reserved words and the slots beyond vertex / face counts
 * included: the library must write them all (unused slots as zero).  Arrays
 * whose capacity the caller chooses are compared up to the count the call
 * reports, and beyond it they must still hold the caller's bytes ("nothing
 * is written past a count", docs/quality.md).
 *
 * How: each case below calls one entry point with fixed valid inputs; the
 * runner fills the output memory with PAT_A and scribbles PAT_A over a deep
 * region of the stack below it, calls, then repeats with PAT_B, and compares
 * the two results byte by byte (det_run).  A byte that depends on the
 * pattern is either stale stack (an uninitialised local copied out) or a
 * byte the library left unwritten.  The control (det_control_fails) runs a
 * deliberately incomplete writer through the same runner and requires it to
 * be caught, so the comparison is not vacuous. */
#include <check.h>
#include <float.h>
#include <stddef.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "test_util.h"

#define PI 3.14159265358979323846

/* Two byte patterns with no bit in common, neither a plausible result
 * (0x00 would pass for "zeroed", so it is not used). */
#define PAT_A 0x5A
#define PAT_B 0xA5

/* Output memory of one case: the largest case (a cascade of 16 splits, or
 * three polyhedra) fits with room to spare. */
#define DET_BUF (96 * 1024)

/* Stack scribbled below the call: well above the deepest frame of the
 * library (a setup holds about ten 7.4 KB polyhedra at once). */
#define DET_STACK (512 * 1024)

enum { DET_UNUSED = 0, DET_OUTPUT = 1, DET_CALLER = 2 };

typedef struct det_out {
    unsigned char* base;
    unsigned char* kind; /* per byte: DET_UNUSED, DET_OUTPUT or DET_CALLER */
    size_t used;
} det_out;

/* n bytes of output memory, 16-byte aligned (the gaps stay DET_UNUSED:
 * nothing may write there). */
static void* det_alloc(det_out* o, size_t n) {
    size_t off = (o->used + 15u) & ~(size_t)15u;
    ck_assert_uint_le(off + n, DET_BUF);
    memset(o->kind + off, DET_OUTPUT, n);
    o->used = off + n;
    return o->base + off;
}

/* An array of `capacity` elements of which the call reported `count`: the
 * elements from count on are the caller's. */
static void det_counted(det_out* o, const void* array, size_t elem, size_t count, size_t capacity) {
    ck_assert_uint_le(count, capacity);
    size_t off = (size_t)((const unsigned char*)array - o->base);
    memset(o->kind + off + count * elem, DET_CALLER, (capacity - count) * elem);
}

typedef swarp_status (*det_case)(det_out* o);

#if defined(__GNUC__)
#define DET_NOINLINE __attribute__((noinline))
#else
#define DET_NOINLINE
#endif

/* Fills the stack below the caller's frame with pat: the library's frames
 * land there next. */
static DET_NOINLINE void det_scribble_stack(unsigned char pat) {
    volatile unsigned char junk[DET_STACK];
    for (size_t i = 0; i < sizeof junk; ++i) junk[i] = pat;
}

static DET_NOINLINE swarp_status det_call(det_case f, det_out* o, unsigned char pat) {
    memset(o->base, pat, DET_BUF);
    memset(o->kind, DET_UNUSED, DET_BUF);
    o->used = 0;
    det_scribble_stack(pat);
    return f(o);
}

static unsigned char det_a[DET_BUF], det_b[DET_BUF], det_kind_a[DET_BUF], det_kind_b[DET_BUF];

typedef struct det_verdict {
    swarp_status status_a, status_b;
    size_t bad;       /* bytes that break the property */
    size_t first_bad; /* offset of the first */
    size_t used;
} det_verdict;

static det_verdict det_run(det_case f) {
    det_out a = {det_a, det_kind_a, 0}, b = {det_b, det_kind_b, 0};
    det_verdict v = {0, 0, 0, 0, 0};
    v.status_a = det_call(f, &a, PAT_A);
    v.status_b = det_call(f, &b, PAT_B);
    v.used = a.used;
    for (size_t i = 0; i < DET_BUF; ++i) {
        int ok = det_kind_a[i] == det_kind_b[i];
        if (ok && det_kind_a[i] == DET_OUTPUT)
            ok = det_a[i] == det_b[i];
        else if (ok)
            ok = det_a[i] == PAT_A && det_b[i] == PAT_B;
        if (!ok && v.bad++ == 0) v.first_bad = i;
    }
    return v;
}

/* 0 when the case keeps the property; else prints why and returns 1 (every
 * case of a table runs, so one run lists every offender). */
static int det_check(const char* name, det_case f) {
    det_verdict v = det_run(f);
    const char* why = NULL;
    if (swarp_status_is_error(v.status_a))
        why = "the valid call failed";
    else if (v.status_a != v.status_b)
        why = "the status depends on the caller's memory";
    else if (v.used == 0)
        why = "no output registered";
    else if (v.bad > 0)
        why = "output bytes depend on the caller's memory";
    if (!why) return 0;
    fprintf(stderr, "%s: %s (%s / %s; %zu of %zu bytes, first at offset %zu)\n", name, why,
            swarp_status_name(v.status_a), swarp_status_name(v.status_b), v.bad, v.used, v.first_bad);
    return 1;
}

/* ---- inputs ----------------------------------------------------------------- */

static swarp_vec3 v3(double x, double y, double z) {
    swarp_vec3 v = {x, y, z};
    return v;
}

/* a camera 3 units up looking slightly down along -z at a 40 x 6 x 40 box */
static swarp_camera cam0(void) {
    swarp_camera c;
    memset(&c, 0, sizeof c);
    c.eye = v3(0.0, 3.0, 10.0);
    c.dir = v3(0.0, -0.2, -1.0);
    c.up = v3(0.0, 1.0, 0.0);
    c.fovy = 1.0;
    c.aspect = 1.5;
    c.z_near = 1.0;
    c.z_far = 100.0;
    return c;
}
static swarp_light sun0(void) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_DIRECTIONAL;
    l.direction = v3(0.3, -1.0, 0.2);
    return l;
}
/* above the box: omni (cone 0) or a spot along -y */
static swarp_light point0(double cone) {
    swarp_light l;
    memset(&l, 0, sizeof l);
    l.type = SWARP_LIGHT_POINT;
    l.position = v3(0.0, 60.0, -20.0);
    l.direction = v3(0.0, -1.0, 0.0);
    l.cone_angle = cone;
    return l;
}
static swarp_aabb box0(void) {
    swarp_aabb b = {{-20.0, -1.0, -40.0}, {20.0, 5.0, 0.0}};
    return b;
}
static swarp_setup_options opts0(swarp_technique t) {
    swarp_setup_options o;
    memset(&o, 0, sizeof o);
    o.technique = t;
    return o;
}

/* ---- the control: a writer that leaves bytes unwritten must be caught ---- */

/* writes only the counted part of a polyhedron (as sw_poly_copy does) */
static swarp_status c_control_partial(det_out* o) {
    swarp_polyhedron* p = det_alloc(o, sizeof *p);
    p->vertex_count = 1;
    p->face_count = 0;
    p->vertices[0] = v3(1, 2, 3);
    return SWARP_OK;
}
/* copies an uninitialised local out: stale stack bytes */
static DET_NOINLINE swarp_status c_control_stale(det_out* o) {
    volatile unsigned char local[64];
    unsigned char* out = det_alloc(o, sizeof local);
    local[0] = 1;
    for (size_t i = 0; i < sizeof local; ++i) out[i] = local[i];
    return SWARP_OK;
}

START_TEST(det_control_fails) {
    det_verdict v = det_run(c_control_partial);
    /* all of the struct but the 8 count bytes and one vertex */
    ck_assert_uint_eq(v.bad, sizeof(swarp_polyhedron) - 8 - sizeof(swarp_vec3));
    ck_assert_uint_eq(v.first_bad, 8 + sizeof(swarp_vec3));
    /* ASan gives locals frames of its own (redzones, the fake stack), which
     * the fill of the stack below the call does not reach: a stale local is
     * not observable there; valgrind reports the stale read itself (it is
     * the point of the control): tests/run.sh sets SWARP_UNDER_VALGRIND */
    if (!SW_UNDER_ASAN && !getenv("SWARP_UNDER_VALGRIND")) {
        v = det_run(c_control_stale);
        ck_assert_uint_gt(v.bad, 0);
    }
}
END_TEST

/* ---- core ------------------------------------------------------------------- */

static swarp_mat4 mat0(void) {
    swarp_mat4 m;
    for (int i = 0; i < 16; ++i) m.m[i] = (i % 5 == 0) ? 2.0 + i : 0.25 * i;
    return m;
}
static swarp_status c_mat4_to_float(det_out* o) {
    swarp_mat4 m = mat0();
    return swarp_mat4_to_float(&m, det_alloc(o, 16 * sizeof(float)));
}
static swarp_status c_mat4_mul(det_out* o) {
    swarp_mat4 a = mat0(), b = mat0();
    return swarp_mat4_mul(&a, &b, det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status c_mat4_invert(det_out* o) {
    swarp_mat4 a = mat0();
    return swarp_mat4_invert(&a, det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status c_mat4_transform(det_out* o) {
    swarp_mat4 a = mat0();
    swarp_vec3 p = v3(1, 2, 3);
    return swarp_mat4_transform(&a, &p, det_alloc(o, sizeof(swarp_vec4)));
}

/* ---- geometry: the one call and its steps ---------------------------------- */

static swarp_status setup_with(det_out* o, const swarp_light* l, swarp_technique t) {
    swarp_camera c = cam0();
    swarp_aabb b = box0();
    swarp_setup_options op = opts0(t);
    swarp_setup_result* r = det_alloc(o, sizeof *r);
    swarp_vec3* pts = det_alloc(o, SWARP_BODY_MAX_POINTS * sizeof *pts);
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_setup(&c, l, &b, &op, r, pts, SWARP_BODY_MAX_POINTS, n);
    if (!swarp_status_is_error(s)) det_counted(o, pts, sizeof *pts, *n, SWARP_BODY_MAX_POINTS);
    return s;
}
static swarp_status c_setup_lispsm(det_out* o) {
    swarp_light l = sun0();
    return setup_with(o, &l, SWARP_TECHNIQUE_LISPSM);
}
static swarp_status c_setup_uniform(det_out* o) {
    swarp_light l = sun0();
    return setup_with(o, &l, SWARP_TECHNIQUE_UNIFORM);
}
static swarp_status c_setup_psm(det_out* o) {
    swarp_light l = sun0();
    return setup_with(o, &l, SWARP_TECHNIQUE_PSM);
}
static swarp_status c_setup_spot(det_out* o) {
    swarp_light l = point0(0.6);
    return setup_with(o, &l, SWARP_TECHNIQUE_LISPSM);
}
static swarp_status c_setup_omni_psm(det_out* o) {
    swarp_light l = point0(0.0);
    return setup_with(o, &l, SWARP_TECHNIQUE_PSM);
}
static swarp_status c_setup_range(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_aabb b = box0();
    swarp_setup_result* r = det_alloc(o, sizeof *r);
    swarp_vec3* pts = det_alloc(o, SWARP_BODY_MAX_POINTS * sizeof *pts);
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_setup_range(&c, &l, &b, 2.0, 20.0, NULL, r, pts, SWARP_BODY_MAX_POINTS, n);
    if (!swarp_status_is_error(s)) det_counted(o, pts, sizeof *pts, *n, SWARP_BODY_MAX_POINTS);
    return s;
}
/* the eight corners of a box in front of the camera */
static void corners0(swarp_vec3 p[8]) {
    for (int i = 0; i < 8; ++i) p[i] = v3((i & 1) ? 5.0 : -5.0, (i & 2) ? 4.0 : -1.0, (i & 4) ? -30.0 : -2.0);
}
static swarp_status c_setup_points(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_vec3 p[8];
    corners0(p);
    return swarp_setup_points(&c, &l, p, 8, p, 8, 1.0, 45.0, NULL, det_alloc(o, sizeof(swarp_setup_result)));
}
static swarp_status c_body_points(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_aabb b = box0();
    swarp_vec3* pts = det_alloc(o, SWARP_BODY_MAX_POINTS * sizeof *pts);
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_body_points(&c, 1.0, 100.0, &l, &b, pts, SWARP_BODY_MAX_POINTS, n);
    if (!swarp_status_is_error(s)) det_counted(o, pts, sizeof *pts, *n, SWARP_BODY_MAX_POINTS);
    return s;
}
static swarp_status c_body_adjusted_range(det_out* o) {
    swarp_camera c = cam0();
    swarp_aabb b = box0();
    return swarp_body_adjusted_range(&c, &b, det_alloc(o, sizeof(double)), det_alloc(o, sizeof(double)));
}
static swarp_status c_focus_light_view(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = point0(0.6);
    swarp_vec3 axis = v3(0.0, -1.0, 0.1);
    return swarp_focus_light_view(&c, &l, &axis, det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status c_focus_fit(det_out* o) {
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    m.m[0] = m.m[5] = m.m[10] = m.m[15] = 1.0;
    swarp_vec3 p[8];
    corners0(p);
    return swarp_focus_fit(&m, p, 8, p, 8, SWARP_DEPTH_ZERO_TO_ONE, det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status c_warp_lispsm(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_aabb b = box0();
    swarp_setup_result r;
    swarp_vec3 pts[SWARP_BODY_MAX_POINTS], lv[SWARP_BODY_MAX_POINTS];
    size_t n = 0;
    swarp_status s = swarp_setup(&c, &l, &b, NULL, &r, pts, SWARP_BODY_MAX_POINTS, &n);
    if (swarp_status_is_error(s)) return s;
    for (size_t i = 0; i < n; ++i) {
        swarp_vec4 h;
        swarp_mat4_transform(&r.light_view, &pts[i], &h);
        lv[i] = v3(h.x / h.w, h.y / h.w, h.z / h.w);
    }
    return swarp_warp_lispsm(&r.light_view, &c, r.view_near, r.view_far, lv, n, NULL, NULL,
                             det_alloc(o, sizeof(swarp_mat4)), det_alloc(o, sizeof(swarp_warp_info)));
}
/* swarp_setup's result for cam0, sun0, box0 (inputs of the cases below) */
static swarp_status setup0(swarp_camera* c, swarp_light* l, swarp_aabb* b, swarp_setup_result* r) {
    *c = cam0();
    *l = sun0();
    *b = box0();
    return swarp_setup(c, l, b, NULL, r, NULL, 0, NULL);
}
static swarp_measure_res res0(void) {
    swarp_measure_res r = {1920, 1080, 2048, 2048};
    return r;
}
/* the measured error of sun0's map at three points (one behind the eye),
 * or its maximum over H */
static swarp_status measure_with(det_out* o, int max) {
    swarp_camera c;
    swarp_light l;
    swarp_aabb b;
    swarp_setup_result r;
    swarp_status s = setup0(&c, &l, &b, &r);
    if (swarp_status_is_error(s)) return s;
    swarp_measure_res res = res0();
    if (max) {
        swarp_measure_options mo = {3, 3, 2, 0};
        return swarp_measure_max(&c, r.view_near, r.view_far, &l, &b, &r.matrix, &res, &mo,
                                 det_alloc(o, sizeof(swarp_measured_error)));
    }
    swarp_vec3 p[3] = {{0, 0, -5}, {3, 0, -20}, {0, 0, 30}};
    swarp_vec3 nrm[3] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    return swarp_measure_points(&c, &r.matrix, &res, p, nrm, 3, det_alloc(o, 3 * sizeof(swarp_texel_error)));
}
static swarp_status c_measure_points(det_out* o) { return measure_with(o, 0); }
static swarp_status c_measure_max(det_out* o) { return measure_with(o, 1); }
static swarp_status c_setup_follow(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_aabb b = box0();
    swarp_setup_result prev;
    swarp_status s = swarp_setup(&c, &l, &b, NULL, &prev, NULL, 0, NULL);
    if (swarp_status_is_error(s)) return s;
    l.direction = v3(0.32, -1.0, 0.2);
    swarp_setup_result* r = det_alloc(o, sizeof *r);
    swarp_vec3* pts = det_alloc(o, SWARP_BODY_MAX_POINTS * sizeof *pts);
    size_t* n = det_alloc(o, sizeof *n);
    s = swarp_setup_follow(&c, &l, &b, NULL, NULL, &prev, r, pts, SWARP_BODY_MAX_POINTS, n);
    if (!swarp_status_is_error(s)) det_counted(o, pts, sizeof *pts, *n, SWARP_BODY_MAX_POINTS);
    return s;
}
static swarp_status c_focus_light_view_follow(det_out* o) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_mat4 prev;
    swarp_status s = swarp_focus_light_view(&c, &l, NULL, &prev);
    if (swarp_status_is_error(s)) return s;
    l.direction = v3(0.32, -1.0, 0.2);
    return swarp_focus_light_view_follow(&c, &l, NULL, NULL, &prev, det_alloc(o, sizeof(swarp_mat4)));
}

/* ---- polyhedra and bodies ------------------------------------------------------ */

static swarp_status c_poly_from_aabb(det_out* o) {
    swarp_aabb b = box0();
    return swarp_poly_from_aabb(&b, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_from_aabb_flat(det_out* o) {
    swarp_aabb b = box0();
    b.max.y = b.min.y; /* a rectangle: 4 vertices, 1 or 2 faces */
    return swarp_poly_from_aabb(&b, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_from_camera_range(det_out* o) {
    swarp_camera c = cam0();
    return swarp_poly_from_camera_range(&c, 2.0, 30.0, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_from_camera(det_out* o) {
    swarp_camera c = cam0();
    return swarp_poly_from_camera(&c, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_from_inverse_matrix(det_out* o) {
    swarp_mat4 m = mat0();
    return swarp_poly_from_inverse_matrix(&m, SWARP_DEPTH_ZERO_TO_ONE, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_polyhedron unit_box(void) {
    swarp_aabb b = {{0, 0, 0}, {1, 1, 1}};
    swarp_polyhedron p;
    memset(&p, 0, sizeof p);
    ck_assert_int_eq(swarp_poly_from_aabb(&b, &p), SWARP_OK);
    return p;
}
static swarp_status c_poly_clip(det_out* o) {
    swarp_polyhedron in = unit_box();
    swarp_plane pl = {1.0, 1.0, 1.0, -1.5}; /* a hexagonal cut */
    return swarp_poly_clip(&in, &pl, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_clip_unchanged(det_out* o) {
    swarp_polyhedron in = unit_box();
    swarp_plane pl = {1.0, 0.0, 0.0, -2.0}; /* removes nothing */
    return swarp_poly_clip(&in, &pl, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_clip_empty(det_out* o) {
    swarp_polyhedron in = unit_box();
    swarp_plane pl = {-1.0, 0.0, 0.0, -2.0}; /* removes everything */
    return swarp_poly_clip(&in, &pl, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_poly_clip_aabb(det_out* o) {
    swarp_polyhedron in = unit_box();
    swarp_aabb b = {{0.25, -1, 0.5}, {2, 0.75, 2}};
    return swarp_poly_clip_aabb(&in, &b, det_alloc(o, sizeof(swarp_polyhedron)));
}
static swarp_status c_body_h(det_out* o) {
    swarp_camera c = cam0();
    swarp_aabb b = box0();
    return swarp_body_h(&c, 1.0, 100.0, &b, det_alloc(o, sizeof(swarp_polyhedron)));
}
/* H = V ∩ S of cam0 and box0 over [1, 100], then B (from_h) or the
 * receivers for light l */
static swarp_status body_step_with(det_out* o, const swarp_light* l, int receivers) {
    swarp_camera c = cam0();
    swarp_aabb b = box0();
    swarp_polyhedron H;
    swarp_status s = swarp_body_h(&c, 1.0, 100.0, &b, &H);
    if (swarp_status_is_error(s)) return s;
    swarp_polyhedron* out = det_alloc(o, sizeof *out);
    return receivers ? swarp_body_receivers(&H, l, out) : swarp_body_from_h(&H, l, &b, out);
}
static swarp_status c_body_from_h_sun(det_out* o) {
    swarp_light l = sun0();
    return body_step_with(o, &l, 0);
}
static swarp_status c_body_from_h_spot(det_out* o) {
    swarp_light l = point0(0.6);
    return body_step_with(o, &l, 0);
}
static swarp_status c_body_receivers_spot(det_out* o) {
    swarp_light l = point0(0.3);
    return body_step_with(o, &l, 1);
}
static swarp_status c_body_receivers_sun(det_out* o) {
    swarp_light l = sun0();
    return body_step_with(o, &l, 1);
}

/* Bytes of p beyond its counts that are not zero, read field by field from
 * the header's layout (not through the library): vertices past
 * vertex_count, planes, loop counts and loop rows past face_count, and each
 * loop past its own face_vertex_count. */
static size_t poly_nonzero_beyond_counts(const swarp_polyhedron* p) {
    const unsigned char* b = (const unsigned char*)p;
    size_t bad = 0;
    const size_t nv = p->vertex_count, nf = p->face_count;
    for (size_t i = offsetof(swarp_polyhedron, vertices) + nv * sizeof(swarp_vec3);
         i < offsetof(swarp_polyhedron, planes); ++i)
        bad += b[i] != 0;
    for (size_t i = offsetof(swarp_polyhedron, planes) + nf * sizeof(swarp_plane);
         i < offsetof(swarp_polyhedron, face_vertex_count); ++i)
        bad += b[i] != 0;
    for (size_t i = offsetof(swarp_polyhedron, face_vertex_count) + nf * sizeof(uint32_t);
         i < offsetof(swarp_polyhedron, face_vertices); ++i)
        bad += b[i] != 0;
    for (size_t f = 0; f < SWARP_POLY_MAX_FACES; ++f)
        for (size_t k = f < nf ? p->face_vertex_count[f] : 0; k < SWARP_POLY_MAX_FACE_VERTICES; ++k)
            bad += p->face_vertices[f][k] != 0;
    /* no padding in between: the fields tile the struct exactly */
    ck_assert_uint_eq(sizeof *p, offsetof(swarp_polyhedron, face_vertices) +
                                     SWARP_POLY_MAX_FACES * SWARP_POLY_MAX_FACE_VERTICES);
    return bad;
}

/* The camera, light and box of the scene: eye (0, 2, 0) looking
 * along (0, -0.3, -1), fovy 1, aspect 16/9, near 1, far 100; the sun along
 * (0.3, -1, 0.2); box (-50, -1, -200)-(50, 10, 50). */
static void scene1(swarp_camera* c, swarp_light* l, swarp_aabb* b) {
    memset(c, 0, sizeof *c);
    c->eye = v3(0, 2, 0);
    c->dir = v3(0, -0.3, -1);
    c->up = v3(0, 1, 0);
    c->fovy = 1.0;
    c->aspect = 16.0 / 9.0;
    c->z_near = 1.0;
    c->z_far = 100.0;
    *l = sun0();
    *b = (swarp_aabb){{-50, -1, -200}, {50, 10, 50}};
}

/* body_h, body_from_h and poly_clip wrote the bytes beyond the counts from
 * the stack they were built on (6 209 - 6 604 of 7 432 bytes changed with
 * the caller's stack); every such byte is zero now, whatever the output
 * memory and the stack held. */
START_TEST(polyhedron_bytes_beyond_counts_are_zero) {
    swarp_camera c;
    swarp_light l;
    swarp_aabb b;
    scene1(&c, &l, &b);
    static swarp_polyhedron H, B, K;
    for (int pat = 0; pat < 2; ++pat) {
        const unsigned char fill = pat ? PAT_B : PAT_A;
        memset(&H, fill, sizeof H);
        memset(&B, fill, sizeof B);
        memset(&K, fill, sizeof K);
        det_scribble_stack(fill);
        ck_assert_int_eq(swarp_body_h(&c, 1.0, 100.0, &b, &H), SWARP_OK);
        det_scribble_stack(fill);
        ck_assert_int_eq(swarp_body_from_h(&H, &l, &b, &B), SWARP_OK);
        swarp_plane pl = {0.0, 1.0, 0.0, -1.0}; /* keeps y <= 1 */
        det_scribble_stack(fill);
        ck_assert_int_eq(swarp_poly_clip(&B, &pl, &K), SWARP_OK);
        /* the property is not vacuous: each has faces and leaves slots free */
        ck_assert_uint_gt(H.face_count, 3);
        ck_assert_uint_lt(B.vertex_count, SWARP_POLY_MAX_VERTICES);
        ck_assert_uint_gt(K.vertex_count, 3);
        ck_assert_uint_eq(poly_nonzero_beyond_counts(&H), 0);
        ck_assert_uint_eq(poly_nonzero_beyond_counts(&B), 0);
        ck_assert_uint_eq(poly_nonzero_beyond_counts(&K), 0);
        /* the clip kept exactly the part y <= 1 (each vertex, up to the
         * clipper's on-plane tolerance SWARP_POLY_EPS_REL of the scale) */
        for (uint32_t i = 0; i < K.vertex_count; ++i) ck_assert(K.vertices[i].y <= 1.0 + 1e-9);
    }
}
END_TEST

/* ---- model: error curves and split schemes ------------------------------------ */

static swarp_error_config cfg0(void) {
    swarp_error_config e;
    memset(&e, 0, sizeof e);
    e.z_near = 1.0;
    e.z_far = 100.0;
    e.theta = 0.5;
    e.res_ix = e.res_iy = 1024;
    e.res_s = e.res_t = 2048;
    return e;
}
static swarp_status c_error_split_curve(det_out* o) {
    swarp_error_config e = cfg0();
    double sp[3] = {1.0, 10.0, 100.0}, np[2] = {2.0, 20.0}, z[4] = {1.0, 5.0, 10.0, 90.0};
    return swarp_error_split_curve(&e, sp, np, 2, z, 4, det_alloc(o, 4 * sizeof(double)),
                                   det_alloc(o, 4 * sizeof(double)));
}
static swarp_status c_error_split_max(det_out* o) {
    swarp_error_config e = cfg0();
    double sp[3] = {1.0, 10.0, 100.0}, np[2] = {2.0, 20.0};
    return swarp_error_split_max(&e, sp, np, 2, det_alloc(o, 2 * sizeof(double)), det_alloc(o, 2 * sizeof(double)),
                                 det_alloc(o, sizeof(double)), det_alloc(o, sizeof(double)));
}
#define SPLIT_CAP 12
static swarp_status split_counted(det_out* o, int scheme) {
    double* out = det_alloc(o, SPLIT_CAP * sizeof(double));
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s;
    if (scheme == 0)
        s = swarp_split_uniform(1.0, 100.0, 4, out, SPLIT_CAP, n);
    else if (scheme == 1)
        s = swarp_split_log(1.0, 100.0, 4, out, SPLIT_CAP, n);
    else if (scheme == 2)
        s = swarp_split_practical(1.0, 100.0, 0.5, 4, out, SPLIT_CAP, n);
    else
        s = swarp_split_pseudo(1.0, 100.0, 5.0, 80.0, 0.5, 4, out, SPLIT_CAP, n);
    if (!swarp_status_is_error(s)) det_counted(o, out, sizeof *out, *n, SPLIT_CAP);
    return s;
}
static swarp_status c_split_uniform(det_out* o) { return split_counted(o, 0); }
static swarp_status c_split_log(det_out* o) { return split_counted(o, 1); }
static swarp_status c_split_practical(det_out* o) { return split_counted(o, 2); }
static swarp_status c_split_pseudo(det_out* o) { return split_counted(o, 3); }

/* ---- cascades: atlas, stabilisation, bias, selection, the one call ------------- */

static swarp_status c_atlas_layout(det_out* o) {
    swarp_atlas_info* info = det_alloc(o, sizeof *info);
    swarp_atlas_tile* t = det_alloc(o, 8 * sizeof *t);
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_atlas_layout(3, 1024, SWARP_DEPTH_ZERO_TO_ONE, info, t, 8, n);
    if (!swarp_status_is_error(s)) det_counted(o, t, sizeof *t, *n, 8);
    return s;
}
static swarp_status c_atlas_kernel_scale(det_out* o) {
    return swarp_atlas_kernel_scale(0.5, 4, -10, 10, -5, 5, det_alloc(o, 2 * sizeof(double)));
}
static swarp_status c_stabilize_sphere(det_out* o) {
    swarp_camera c = cam0();
    return swarp_stabilize_sphere(&c, 2.0, 20.0, det_alloc(o, sizeof(swarp_vec3)), det_alloc(o, sizeof(double)),
                                  det_alloc(o, sizeof(double)));
}
static swarp_status c_stabilize_light_view(det_out* o) {
    swarp_vec3 d = v3(0.3, -1.0, 0.2);
    return swarp_stabilize_light_view(&d, det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status stabilize_with(det_out* o, swarp_stabilize_mode mode) {
    swarp_camera c = cam0();
    swarp_aabb b = box0();
    swarp_vec3 d = v3(0.3, -1.0, 0.2);
    swarp_vec3 p[8];
    corners0(p);
    swarp_stabilize_options so;
    memset(&so, 0, sizeof so);
    so.mode = mode;
    so.origin = v3(100.0, 0.0, -50.0);
    return swarp_stabilize_directional(&c, 2.0, 20.0, &d, p, 8, &b, 1024, &so, det_alloc(o, sizeof(swarp_mat4)),
                                       det_alloc(o, sizeof(swarp_stabilize_report)));
}
static swarp_status c_stabilize_sphere_mode(det_out* o) { return stabilize_with(o, SWARP_STABILIZE_SPHERE); }
static swarp_status c_stabilize_levels(det_out* o) { return stabilize_with(o, SWARP_STABILIZE_LEVELS); }
static swarp_status c_stabilize_none(det_out* o) { return stabilize_with(o, SWARP_STABILIZE_NONE); }
static swarp_status c_stabilize_snap_matrix(det_out* o) {
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    m.m[0] = 0.05, m.m[5] = 0.05, m.m[10] = -0.01, m.m[15] = 1.0, m.m[12] = 0.3, m.m[13] = -0.2;
    swarp_vec3 origin = v3(1.0, 2.0, 3.0);
    return swarp_stabilize_snap_matrix(&m, 1024, 1024, &origin, det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_bias_map bias_map0(void) {
    swarp_bias_map bm;
    memset(&bm, 0, sizeof bm);
    bm.world_to_clip.m[0] = 0.05, bm.world_to_clip.m[6] = 0.05, bm.world_to_clip.m[9] = 0.02;
    bm.world_to_clip.m[15] = 1.0;
    bm.res_s = bm.res_t = 2048;
    return bm;
}
static swarp_status c_bias_to_light(det_out* o) {
    swarp_light l = point0(0.0);
    swarp_vec3 p = v3(1, 0, -5);
    return swarp_bias_to_light(&l, &p, det_alloc(o, sizeof(swarp_vec3)));
}
static swarp_status c_bias_kozlov(det_out* o) {
    swarp_bias_map bm = bias_map0();
    swarp_light l = sun0();
    swarp_vec3 p = v3(1, 0, -5);
    return swarp_bias_kozlov(&bm, &l, &p, 1.0, 1e-3, det_alloc(o, sizeof(swarp_vec3)), det_alloc(o, sizeof(double)));
}
static swarp_status c_bias_normal_offset(det_out* o) {
    swarp_bias_map bm = bias_map0();
    swarp_light l = sun0();
    swarp_vec3 p = v3(1, 0, -5), nrm = v3(0, 1, 0);
    return swarp_bias_normal_offset(&bm, &l, &p, &nrm, 1.0, det_alloc(o, sizeof(swarp_vec3)),
                                    det_alloc(o, sizeof(double)));
}
static swarp_status c_bias_receiver_plane(det_out* o) {
    swarp_bias_map bm = bias_map0();
    swarp_vec3 p = v3(1, 0, -5), ta = v3(1, 0, 0), tb = v3(0, 0, 1);
    return swarp_bias_receiver_plane(&bm, &p, &ta, &tb, det_alloc(o, 2 * sizeof(double)));
}
static swarp_status c_cascade_blend(det_out* o) {
    double sp[5] = {1, 3, 10, 30, 100};
    return swarp_cascade_blend(sp, 4, 9.5, 0.1, det_alloc(o, sizeof(uint32_t)), det_alloc(o, sizeof(double)));
}
static swarp_status c_cascade_splits(det_out* o) {
    double* out = det_alloc(o, SPLIT_CAP * sizeof(double));
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_cascade_splits(1.0, 100.0, NULL, out, SPLIT_CAP, n);
    if (!swarp_status_is_error(s)) det_counted(o, out, sizeof *out, *n, SPLIT_CAP);
    return s;
}
static swarp_status c_cascade_nopt(det_out* o) {
    double sp[5] = {1, 3, 10, 30, 100};
    return swarp_cascade_nopt(sp, 4, 0.0, 0.0, det_alloc(o, 4 * sizeof(double)));
}
static swarp_status c_cascade_error_curve(det_out* o) {
    swarp_error_config e = cfg0();
    double sp[3] = {1.0, 10.0, 100.0}, np[2] = {2.0, 20.0};
    enum { CAP = 16 };
    double* z = det_alloc(o, CAP * sizeof(double));
    double* mx = det_alloc(o, CAP * sizeof(double));
    double* mz = det_alloc(o, CAP * sizeof(double));
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_cascade_error_curve(&e, sp, np, 2, 5, z, mx, mz, CAP, n);
    if (!swarp_status_is_error(s)) {
        det_counted(o, z, sizeof(double), *n, CAP);
        det_counted(o, mx, sizeof(double), *n, CAP);
        det_counted(o, mz, sizeof(double), *n, CAP);
    }
    return s;
}
static swarp_status cascade_with(det_out* o, swarp_technique t, swarp_stabilize_mode mode) {
    swarp_camera c = cam0();
    swarp_light l = sun0();
    swarp_aabb b = box0();
    swarp_cascade_options co;
    memset(&co, 0, sizeof co);
    co.setup.technique = t;
    co.stabilize.mode = mode;
    swarp_cascade_result* r = det_alloc(o, sizeof *r);
    swarp_cascade_split* sp = det_alloc(o, SWARP_CASCADE_MAX_SPLITS * sizeof *sp);
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_cascade_setup(&c, &l, &b, &co, r, sp, SWARP_CASCADE_MAX_SPLITS, n);
    if (!swarp_status_is_error(s)) det_counted(o, sp, sizeof *sp, *n, SWARP_CASCADE_MAX_SPLITS);
    return s;
}
static swarp_status c_cascade_setup(det_out* o) {
    return cascade_with(o, SWARP_TECHNIQUE_LISPSM, SWARP_STABILIZE_NONE);
}
static swarp_status c_cascade_setup_psm(det_out* o) {
    return cascade_with(o, SWARP_TECHNIQUE_PSM, SWARP_STABILIZE_NONE);
}
static swarp_status c_cascade_setup_sphere(det_out* o) {
    return cascade_with(o, SWARP_TECHNIQUE_UNIFORM, SWARP_STABILIZE_SPHERE);
}
static swarp_status c_cascade_setup_levels(det_out* o) {
    return cascade_with(o, SWARP_TECHNIQUE_UNIFORM, SWARP_STABILIZE_LEVELS);
}

/* ---- filters ------------------------------------------------------------------- */

static swarp_status c_vsm_moments(det_out* o) { return swarp_vsm_moments(0.3, det_alloc(o, 2 * sizeof(double))); }
static swarp_status c_lvsm_moments(det_out* o) {
    return swarp_lvsm_moments(0.3, 0.2, 0.6, det_alloc(o, 2 * sizeof(double)));
}
static swarp_status c_lvsm_transition(det_out* o) {
    double sp[4] = {0.0, 0.3, 0.6, 1.0};
    return swarp_lvsm_transition(0.31, sp, 3, 0.05, det_alloc(o, sizeof(uint32_t)), det_alloc(o, sizeof(uint32_t)),
                                 det_alloc(o, sizeof(double)));
}
static swarp_status c_lvsm_lloyd(det_out* o) {
    double mu[6] = {0.1, 0.15, 0.4, 0.45, 0.8, 0.9}, s2[6] = {1e-3, 2e-3, 1e-3, 3e-3, 1e-3, 2e-3};
    double sp[4] = {0.0, 0.3, 0.6, 1.0};
    return swarp_lvsm_lloyd(mu, s2, 6, NULL, sp, 3, det_alloc(o, 4 * sizeof(double)),
                            det_alloc(o, sizeof(swarp_lloyd_report)));
}
static swarp_status c_evsm_moments(det_out* o) {
    return swarp_evsm_moments(0.3, 40.0, 5.0, det_alloc(o, 4 * sizeof(double)));
}
static swarp_status c_msm_moments(det_out* o) { return swarp_msm_moments(0.3, det_alloc(o, 4 * sizeof(double))); }
static swarp_status c_msm_bias(det_out* o) {
    double b[4] = {0.3, 0.1, 0.04, 0.02};
    return swarp_msm_bias(b, 3e-5, det_alloc(o, 4 * sizeof(double)));
}
static swarp_status c_pcf_poisson_disk(det_out* o) {
    enum { CAP = 32 };
    double* xy = det_alloc(o, 2 * CAP * sizeof(double));
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_pcf_poisson_disk(7, 12, 0, xy, CAP, n, det_alloc(o, sizeof(double)));
    if (!swarp_status_is_error(s)) det_counted(o, xy, 2 * sizeof(double), *n, CAP);
    return s;
}

/* ---- lixel maps ------------------------------------------------------------------ */

/* the viewer's view-projection: eye (0, 2, 0) looking down -z, fovy 60°,
 * aspect 1.5, near 0.1, far 100 (OpenGL perspective times the translation
 * by -eye; column-major) */
static swarp_mat4 viewer0(void) {
    const double f = 1.0 / tan(PI / 6.0), n = 0.1, fa = 100.0;
    swarp_mat4 m;
    memset(&m, 0, sizeof m);
    m.m[0] = f / 1.5;
    m.m[5] = f;
    m.m[10] = (fa + n) / (n - fa);
    m.m[11] = -1.0;
    m.m[13] = -2.0 * f;
    m.m[14] = 2.0 * fa * n / (n - fa);
    return m;
}
static const swarp_plane floor0 = {0, 1, 0, 0};
static swarp_light lixel_light0(void) {
    swarp_light l = point0(0.0);
    l.position = v3(4.0, 6.0, -8.0);
    return l;
}
static swarp_status lixel_ml(swarp_mat4* Ml) {
    swarp_mat4 Mv = viewer0();
    swarp_light l = lixel_light0();
    return swarp_lixel_matrix(&Mv, 960, 640, &l, &floor0, NULL, Ml, NULL);
}
static swarp_status c_lixel_solve5(det_out* o) {
    swarp_vec4 src[5] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {0, 0, 0, 1}, {1, 1, 1, 1}};
    swarp_vec4 dst[5] = {{2, 0, 0, 1}, {0, 3, 0, 1}, {0, 0, 1, 2}, {0.5, 0, 0, 1}, {1, 2, 1, 1}};
    return swarp_lixel_solve5(src, dst, det_alloc(o, sizeof(swarp_mat4)), det_alloc(o, sizeof(double)));
}
static swarp_status c_lixel_matrix(det_out* o) {
    swarp_mat4 Mv = viewer0();
    swarp_light l = lixel_light0();
    return swarp_lixel_matrix(&Mv, 960, 640, &l, &floor0, NULL, det_alloc(o, sizeof(swarp_mat4)),
                              det_alloc(o, sizeof(swarp_lixel_info)));
}
static swarp_status c_lixel_restrict(det_out* o) {
    swarp_mat4 Ml;
    swarp_status s = lixel_ml(&Ml);
    if (swarp_status_is_error(s)) return s;
    swarp_vec4 C[3] = {{0, 0, -5, 1}, {2, 0, -6, 1}, {0.5, 0, -9, 1}};
    return swarp_lixel_restrict(&Ml, C, 3, NULL, det_alloc(o, sizeof(swarp_lixel_rect)),
                                det_alloc(o, sizeof(swarp_mat4)), det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status c_lixel_factor(det_out* o) {
    swarp_mat4 Ml;
    swarp_status s = lixel_ml(&Ml);
    if (swarp_status_is_error(s)) return s;
    return swarp_lixel_factor(&Ml, 960, 640, SWARP_DEPTH_DEFAULT, 0.0, det_alloc(o, sizeof(swarp_mat4)),
                              det_alloc(o, sizeof(swarp_mat4)));
}
static swarp_status c_lixel_split(det_out* o) {
    swarp_light l = point0(0.0);
    l.position = v3(-3, 6, 2);
    swarp_plane wall = {0, 0, 1, 10};
    swarp_vec3 cn[4] = {{-8, 0, 3}, {8, 0, 3}, {8, 6, -10}, {-8, 6, -10}};
    swarp_vec4 C[4];
    for (int i = 0; i < 4; ++i)
        C[i] = (swarp_vec4){cn[i].x - l.position.x, cn[i].y - l.position.y, cn[i].z - l.position.z, 0.0};
    enum { CAP = 8 };
    swarp_vec4* fl = det_alloc(o, CAP * sizeof *fl);
    size_t* nf = det_alloc(o, sizeof *nf);
    swarp_vec4* wl = det_alloc(o, CAP * sizeof *wl);
    size_t* nw = det_alloc(o, sizeof *nw);
    swarp_status s = swarp_lixel_split(&l, &floor0, &wall, C, 4, fl, CAP, nf, wl, CAP, nw);
    if (!swarp_status_is_error(s)) {
        det_counted(o, fl, sizeof *fl, *nf, CAP);
        det_counted(o, wl, sizeof *wl, *nw, CAP);
    }
    return s;
}

/* ---- the planner ------------------------------------------------------------------ */

static swarp_scene_needs needs0(void) {
    swarp_scene_needs n;
    memset(&n, 0, sizeof n);
    n.camera = cam0();
    n.light = sun0();
    n.scene_box = box0();
    return n;
}
static swarp_status c_plan_default(det_out* o) { return swarp_plan(NULL, NULL, det_alloc(o, sizeof(swarp_plan_result))); }
static swarp_status c_plan_soft_planes(det_out* o) {
    swarp_scene_needs n = needs0();
    n.soft_shadows = 1;
    n.bleed_risk = SWARP_PLAN_BLEED_HIGH;
    n.camera_moves = 1;
    n.plane_count = 2;
    n.planes[0] = floor0;
    n.planes[1] = (swarp_plane){0, 0, 1, 40};
    swarp_budget b;
    memset(&b, 0, sizeof b);
    b.max_error = 0.5;
    return swarp_plan(&n, &b, det_alloc(o, sizeof(swarp_plan_result)));
}
static swarp_status c_plan_evaluate(det_out* o) {
    swarp_scene_needs n = needs0();
    swarp_plan_chain ch;
    memset(&ch, 0, sizeof ch);
    ch.warp = SWARP_PLAN_WARP_LISPSM_NOPT;
    ch.scheme = SWARP_PLAN_SCHEME_PRACTICAL;
    ch.split_count = 3;
    return swarp_plan_evaluate(&n, NULL, &ch, det_alloc(o, sizeof(swarp_plan_result)));
}
static swarp_status c_plan_explain(det_out* o) {
    swarp_plan_result p;
    swarp_status s = swarp_plan(NULL, NULL, &p);
    if (swarp_status_is_error(s)) return s;
    enum { CAP = 8192 };
    char* text = det_alloc(o, CAP);
    size_t* n = det_alloc(o, sizeof *n);
    s = swarp_plan_explain(&p, text, CAP, n);
    if (!swarp_status_is_error(s)) det_counted(o, text, 1, *n, CAP);
    return s;
}

/* ---- extras ----------------------------------------------------------------------- */

static swarp_status c_cube_faces(det_out* o) {
    swarp_vec4 L = {0.2, 0.3, 3.0, 1.0};
    swarp_cube_face* f = det_alloc(o, SWARP_CUBE_MAX_FACES * sizeof *f);
    size_t* n = det_alloc(o, sizeof *n);
    swarp_status s = swarp_cube_faces(&L, NULL, f, SWARP_CUBE_MAX_FACES, n);
    if (!swarp_status_is_error(s)) det_counted(o, f, sizeof *f, *n, SWARP_CUBE_MAX_FACES);
    return s;
}
static swarp_status c_cube_lookup(det_out* o) {
    swarp_vec4 L = {0.2, 0.3, 3.0, 1.0};
    swarp_vec3 P = v3(0.1, -0.2, 0.5);
    return swarp_cube_lookup(&L, NULL, &P, det_alloc(o, sizeof(uint32_t)), det_alloc(o, sizeof(swarp_vec3)),
                             det_alloc(o, sizeof(double)));
}
static const float depth0[15] = {5, 4, 3, 9, 8, INFINITY, 2.5f, 7, 6, 5, 4, 3, 2, 1.5f, 9};
static swarp_status c_mindepth_pyramid(det_out* o) {
    enum { W = 5, H = 3 };
    const size_t need = SWARP_MINDEPTH_SCRATCH(W, H);
    float* scratch = det_alloc(o, need * sizeof(float));
    return swarp_mindepth_pyramid(depth0, W, H, W, scratch, need, det_alloc(o, sizeof(size_t)),
                                  det_alloc(o, sizeof(double)));
}
static swarp_status c_mindepth_direct(det_out* o) {
    return swarp_mindepth_direct(depth0, 5, 3, 5, det_alloc(o, sizeof(double)));
}
static swarp_status c_mindepth_near(det_out* o) {
    return swarp_mindepth_near(1.0, 100.0, 2.5, NULL, det_alloc(o, sizeof(double)));
}

/* ---- the table -------------------------------------------------------------------- */

typedef struct det_entry {
    const char* name;
    det_case f;
} det_entry;

#define E(fn) {#fn, fn}
static const det_entry det_core[] = {
    E(c_mat4_to_float), E(c_mat4_mul), E(c_mat4_invert), E(c_mat4_transform),
    E(c_error_split_curve), E(c_error_split_max), E(c_split_uniform), E(c_split_log),
    E(c_split_practical), E(c_split_pseudo),
};
static const det_entry det_geometry[] = {
    E(c_setup_lispsm), E(c_setup_uniform), E(c_setup_psm), E(c_setup_spot), E(c_setup_omni_psm),
    E(c_setup_range), E(c_setup_points), E(c_body_points), E(c_body_adjusted_range),
    E(c_focus_light_view), E(c_focus_fit), E(c_warp_lispsm), E(c_measure_points), E(c_measure_max),
    E(c_setup_follow), E(c_focus_light_view_follow),
};
static const det_entry det_poly[] = {
    E(c_poly_from_aabb), E(c_poly_from_aabb_flat), E(c_poly_from_camera_range), E(c_poly_from_camera),
    E(c_poly_from_inverse_matrix), E(c_poly_clip), E(c_poly_clip_unchanged), E(c_poly_clip_empty),
    E(c_poly_clip_aabb), E(c_body_h), E(c_body_from_h_sun), E(c_body_from_h_spot),
    E(c_body_receivers_spot), E(c_body_receivers_sun),
};
static const det_entry det_cascade[] = {
    E(c_atlas_layout), E(c_atlas_kernel_scale), E(c_stabilize_sphere), E(c_stabilize_light_view),
    E(c_stabilize_sphere_mode), E(c_stabilize_levels), E(c_stabilize_none), E(c_stabilize_snap_matrix),
    E(c_bias_to_light), E(c_bias_kozlov), E(c_bias_normal_offset), E(c_bias_receiver_plane),
    E(c_cascade_blend), E(c_cascade_splits), E(c_cascade_nopt), E(c_cascade_error_curve),
    E(c_cascade_setup), E(c_cascade_setup_psm), E(c_cascade_setup_sphere), E(c_cascade_setup_levels),
};
static const det_entry det_filter[] = {
    E(c_vsm_moments), E(c_lvsm_moments), E(c_lvsm_transition), E(c_lvsm_lloyd), E(c_evsm_moments),
    E(c_msm_moments), E(c_msm_bias), E(c_pcf_poisson_disk),
};
static const det_entry det_lixel[] = {
    E(c_lixel_solve5), E(c_lixel_matrix), E(c_lixel_restrict), E(c_lixel_factor), E(c_lixel_split),
};
static const det_entry det_plan[] = {
    E(c_plan_default), E(c_plan_soft_planes), E(c_plan_evaluate), E(c_plan_explain),
};
static const det_entry det_extras[] = {
    E(c_cube_faces), E(c_cube_lookup), E(c_mindepth_pyramid), E(c_mindepth_direct), E(c_mindepth_near),
};
#undef E

#define DET_TABLE_TEST(tname, table)                                   \
    START_TEST(tname) {                                                \
        int failed = 0;                                                \
        for (size_t i = 0; i < sizeof table / sizeof table[0]; ++i)   \
            failed += det_check(table[i].name, table[i].f);            \
        ck_assert_msg(failed == 0, "%d case(s) not deterministic", failed); \
    }                                                                  \
    END_TEST

DET_TABLE_TEST(outputs_deterministic_core, det_core)
DET_TABLE_TEST(outputs_deterministic_geometry, det_geometry)
DET_TABLE_TEST(outputs_deterministic_polyhedra, det_poly)
DET_TABLE_TEST(outputs_deterministic_cascade, det_cascade)
DET_TABLE_TEST(outputs_deterministic_filter, det_filter)
DET_TABLE_TEST(outputs_deterministic_lixel, det_lixel)
DET_TABLE_TEST(outputs_deterministic_plan, det_plan)
DET_TABLE_TEST(outputs_deterministic_extras, det_extras)

static Suite* suite(void) {
    Suite* s = suite_create("determinism");
    TCase* t = tcase_create("all");
    tcase_add_test(t, det_control_fails);
    tcase_add_test(t, polyhedron_bytes_beyond_counts_are_zero);
    tcase_add_test(t, outputs_deterministic_core);
    tcase_add_test(t, outputs_deterministic_geometry);
    tcase_add_test(t, outputs_deterministic_polyhedra);
    tcase_add_test(t, outputs_deterministic_cascade);
    tcase_add_test(t, outputs_deterministic_filter);
    tcase_add_test(t, outputs_deterministic_lixel);
    tcase_add_test(t, outputs_deterministic_plan);
    tcase_add_test(t, outputs_deterministic_extras);
    suite_add_tcase(s, t);
    return s;
}

int main(void) { return tu_run_suite(suite()); }
