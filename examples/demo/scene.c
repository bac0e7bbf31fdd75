/* scene.c -- the built-in scenes, generated in code (no asset files). */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct v3 { float x, y, z; } v3;

static v3 mk(float x, float y, float z) { v3 r = {x, y, z}; return r; }
static v3 sub(v3 a, v3 b) { return mk(a.x - b.x, a.y - b.y, a.z - b.z); }
static v3 add(v3 a, v3 b) { return mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 scl(v3 a, float s) { return mk(a.x * s, a.y * s, a.z * s); }
static v3 cross(v3 a, v3 b) {
    return mk(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static v3 norm(v3 a) {
    float l = sqrtf(a.x * a.x + a.y * a.y + a.z * a.z);
    return l > 0 ? scl(a, 1.0f / l) : mk(0, 1, 0);
}

static int grow(demo_scene* s, size_t extra) {
    if (s->count + extra <= s->capacity) return 0;
    size_t cap = s->capacity ? s->capacity * 2 : 4096;
    while (cap < s->count + extra) cap *= 2;
    demo_vertex* nv = realloc(s->v, cap * sizeof *nv);
    if (!nv) return -1;
    s->v = nv;
    s->capacity = cap;
    return 0;
}

static void put(demo_scene* s, v3 p, v3 n, v3 c) {
    demo_vertex* d = &s->v[s->count++];
    d->p[0] = p.x; d->p[1] = p.y; d->p[2] = p.z;
    d->n[0] = n.x; d->n[1] = n.y; d->n[2] = n.z;
    d->c[0] = c.x; d->c[1] = c.y; d->c[2] = c.z;
}

/* Flat-shaded triangle, counter-clockwise seen from the front. */
static int tri(demo_scene* s, v3 a, v3 b, v3 c, v3 col) {
    if (grow(s, 3)) return -1;
    v3 n = norm(cross(sub(b, a), sub(c, a)));
    put(s, a, n, col);
    put(s, b, n, col);
    put(s, c, n, col);
    return 0;
}

static int quad(demo_scene* s, v3 a, v3 b, v3 c, v3 d, v3 col) {
    return tri(s, a, b, c, col) | tri(s, a, c, d, col);
}

/* Box spanned by an origin and three edge vectors (right-handed frame). */
static int box_frame(demo_scene* s, v3 o, v3 ex, v3 ey, v3 ez, v3 col) {
    v3 p[8];
    for (int i = 0; i < 8; ++i)
        p[i] = add(add(add(o, (i & 1) ? ex : mk(0, 0, 0)), (i & 2) ? ey : mk(0, 0, 0)),
                   (i & 4) ? ez : mk(0, 0, 0));
    int r = 0;
    r |= quad(s, p[0], p[4], p[6], p[2], col); /* -x */
    r |= quad(s, p[1], p[3], p[7], p[5], col); /* +x */
    r |= quad(s, p[0], p[1], p[5], p[4], col); /* -y */
    r |= quad(s, p[2], p[6], p[7], p[3], col); /* +y */
    r |= quad(s, p[0], p[2], p[3], p[1], col); /* -z */
    r |= quad(s, p[4], p[5], p[7], p[6], col); /* +z */
    return r;
}

static int box(demo_scene* s, v3 lo, v3 hi, v3 col) {
    return box_frame(s, lo, mk(hi.x - lo.x, 0, 0), mk(0, hi.y - lo.y, 0),
                     mk(0, 0, hi.z - lo.z), col);
}

/* A square beam of width w from a to b (tower lattice). */
static int beam(demo_scene* s, v3 a, v3 b, float w, v3 col) {
    v3 d = sub(b, a);
    v3 any = fabsf(d.y) < 0.9f * sqrtf(d.x * d.x + d.y * d.y + d.z * d.z) ? mk(0, 1, 0)
                                                                         : mk(1, 0, 0);
    v3 u = scl(norm(cross(d, any)), w);
    v3 v = scl(norm(cross(u, d)), w);
    v3 o = sub(a, scl(add(u, v), 0.5f));
    /* frame (u, v, d) must be right-handed for outward normals */
    return box_frame(s, o, u, v, d, col);
}

static int cone(demo_scene* s, v3 base, float r, float h, int seg, v3 col) {
    v3 apex = add(base, mk(0, h, 0));
    int res = 0;
    for (int i = 0; i < seg; ++i) {
        float a0 = 6.2831853f * (float)i / (float)seg;
        float a1 = 6.2831853f * (float)(i + 1) / (float)seg;
        v3 p0 = add(base, mk(r * cosf(a0), 0, -r * sinf(a0)));
        v3 p1 = add(base, mk(r * cosf(a1), 0, -r * sinf(a1)));
        res |= tri(s, p0, p1, apex, col);
        res |= tri(s, p1, p0, base, col);
    }
    return res;
}

static int sphere(demo_scene* s, v3 c, float r, int seg, v3 col) {
    int res = 0;
    size_t start = s->count;
    int rings = seg / 2;
    for (int j = 0; j < rings; ++j) {
        float t0 = 3.14159265f * (float)j / (float)rings;
        float t1 = 3.14159265f * (float)(j + 1) / (float)rings;
        for (int i = 0; i < seg; ++i) {
            float a0 = 6.2831853f * (float)i / (float)seg;
            float a1 = 6.2831853f * (float)(i + 1) / (float)seg;
#define SP(t, a) add(c, mk(r * sinf(t) * cosf(a), r * cosf(t), -r * sinf(t) * sinf(a)))
            v3 p00 = SP(t0, a0), p01 = SP(t0, a1), p10 = SP(t1, a0), p11 = SP(t1, a1);
#undef SP
            if (j > 0) res |= tri(s, p00, p10, p01, col);
            if (j < rings - 1) res |= tri(s, p01, p10, p11, col);
        }
    }
    /* smooth normals for the sphere: replace the flat ones */
    for (size_t i = start; i < s->count; ++i) {
        v3 n = norm(sub(mk(s->v[i].p[0], s->v[i].p[1], s->v[i].p[2]), c));
        s->v[i].n[0] = n.x; s->v[i].n[1] = n.y; s->v[i].n[2] = n.z;
    }
    return res;
}

/* A small deterministic PRNG so the scene is the same on every run. */
static uint32_t rng_next(uint32_t* st) {
    *st = *st * 1664525u + 1013904223u;
    return *st >> 8;
}
static float rng_unit(uint32_t* st) { return (float)rng_next(st) / 16777216.0f; }

static void bounds(demo_scene* s) {
    swarp_aabb b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (size_t i = 0; i < s->count; ++i) {
        const float* p = s->v[i].p;
        if (p[0] < b.min.x) b.min.x = p[0];
        if (p[1] < b.min.y) b.min.y = p[1];
        if (p[2] < b.min.z) b.min.z = p[2];
        if (p[0] > b.max.x) b.max.x = p[0];
        if (p[1] > b.max.y) b.max.y = p[1];
        if (p[2] > b.max.z) b.max.z = p[2];
    }
    s->box = b;
}

static int ground(demo_scene* s, float half, v3 col) {
    /* A grid of quads rather than one huge one: keeps interpolated
     * attributes accurate on llvmpipe. */
    const int n = 16;
    int r = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float x0 = -half + 2 * half * (float)i / n, x1 = -half + 2 * half * (float)(i + 1) / n;
            float z0 = -half + 2 * half * (float)j / n, z1 = -half + 2 * half * (float)(j + 1) / n;
            r |= quad(s, mk(x0, 0, z0), mk(x0, 0, z1), mk(x1, 0, z1), mk(x1, 0, z0), col);
        }
    return r;
}

static int tower(demo_scene* s, v3 base, float h, float w0, float w1, v3 col) {
    /* Four tapering legs, horizontal rings and X braces between them. */
    const int levels = 20;
    int r = 0;
    v3 prev[4];
    for (int l = 0; l <= levels; ++l) {
        float t = (float)l / levels;
        float y = h * t;
        /* curved taper like the Sights-of-Paris tower */
        float w = w1 + (w0 - w1) * (1 - t) * (1 - t);
        v3 c[4] = {add(base, mk(-w, y, -w)), add(base, mk(w, y, -w)), add(base, mk(w, y, w)),
                   add(base, mk(-w, y, w))};
        float bw = 0.8f + 1.5f * (1 - t);
        for (int k = 0; k < 4; ++k) {
            if (l > 0) {
                r |= beam(s, prev[k], c[k], bw, col);
                r |= beam(s, prev[k], c[(k + 1) % 4], 0.5f * bw, col);
                r |= beam(s, prev[(k + 1) % 4], c[k], 0.5f * bw, col);
            }
            if (l % 2 == 0 || l == levels) r |= beam(s, c[k], c[(k + 1) % 4], 0.7f * bw, col);
        }
        if (l == 3) r |= box(s, add(base, mk(-w - 2, y - 1.5f, -w - 2)),
                             add(base, mk(w + 2, y + 1.5f, w + 2)), col);
        memcpy(prev, c, sizeof c);
    }
    r |= beam(s, add(base, mk(0, h, 0)), add(base, mk(0, h + 25, 0)), 1.5f, col);
    return r;
}

/* room corner centre; floor slab top at y = 0.3, back wall inner face at
 * z = ROOM_Z - 14 */
#define ROOM_X (-75.0f)
#define ROOM_Z 5.0f

void demo_scene_room(demo_room* r) {
    const double fy = 0.3, wz = ROOM_Z - 14.0, x0 = ROOM_X - 15.0, x1 = ROOM_X + 14.0;
    const double z0 = ROOM_Z - 14.0, z1 = ROOM_Z + 15.0, wy = 9.0;
    r->floor = (swarp_plane){0, 1, 0, -fy};
    r->wall = (swarp_plane){0, 0, 1, -wz};
    r->floor_rect[0] = (swarp_vec3){x0, fy, z1};
    r->floor_rect[1] = (swarp_vec3){x1, fy, z1};
    r->floor_rect[2] = (swarp_vec3){x1, fy, z0};
    r->floor_rect[3] = (swarp_vec3){x0, fy, z0};
    r->wall_rect[0] = (swarp_vec3){x0, fy, wz};
    r->wall_rect[1] = (swarp_vec3){x1, fy, wz};
    r->wall_rect[2] = (swarp_vec3){x1, wy, wz};
    r->wall_rect[3] = (swarp_vec3){x0, wy, wz};
}

int demo_scene_default(demo_scene* s) {
    memset(s, 0, sizeof *s);
    uint32_t st = 12345u;
    int r = 0;
    r |= ground(s, 400.0f, mk(0.55f, 0.62f, 0.45f));
    /* the tower: ~300 m, 110 m wide at the base */
    r |= tower(s, mk(0, 0, -120), 300.0f, 55.0f, 4.0f, mk(0.55f, 0.42f, 0.30f));
    /* rows of buildings along a boulevard (x = +-45 .. +-200), z from 330 to -380 */
    for (int side = -1; side <= 1; side += 2)
        for (int row = 0; row < 3; ++row)
            for (int k = 0; k < 14; ++k) {
                float z = 330.0f - 50.0f * k + 10.0f * rng_unit(&st);
                if (z < 40 && z > -280 && row == 0 && side == 1 && k % 3 == 0) continue;
                float x = side * (45.0f + 55.0f * row + 8.0f * rng_unit(&st));
                float wx = 14.0f + 14.0f * rng_unit(&st), wz = 18.0f + 18.0f * rng_unit(&st);
                float hh = 12.0f + 38.0f * rng_unit(&st);
                if (fabsf(x) < 110 && z < 40 && z > -280) continue; /* tower park */
                v3 col = mk(0.75f + 0.15f * rng_unit(&st), 0.72f, 0.62f + 0.1f * rng_unit(&st));
                r |= box(s, mk(x - wx / 2, 0, z - wz / 2), mk(x + wx / 2, hh, z + wz / 2), col);
            }
    /* trees along the boulevard: cone crowns on box trunks, and some box trees */
    for (int side = -1; side <= 1; side += 2)
        for (int k = 0; k < 40; ++k) {
            float z = 380.0f - 18.0f * k;
            float x = side * 24.0f;
            float h = 6.0f + 4.0f * rng_unit(&st);
            r |= box(s, mk(x - 0.4f, 0, z - 0.4f), mk(x + 0.4f, h * 0.4f, z + 0.4f),
                     mk(0.4f, 0.3f, 0.2f));
            if (k % 4 == 3)
                r |= box(s, mk(x - 2.2f, h * 0.4f, z - 2.2f), mk(x + 2.2f, h, z + 2.2f),
                         mk(0.2f, 0.5f, 0.2f));
            else
                r |= cone(s, mk(x, h * 0.3f, z), 2.8f, h * 0.8f, 12, mk(0.15f, 0.45f, 0.15f));
        }
    /* spheres near the viewer */
    for (int k = 0; k < 7; ++k) {
        float rad = 2.0f + 1.5f * (float)(k % 3);
        r |= sphere(s, mk(-14.0f + 5.0f * (float)k, rad, 330.0f - 22.0f * (float)k), rad, 24,
                    mk(0.8f, 0.3f + 0.1f * (float)k, 0.3f));
    }
    /* room corner (lixel's floor + wall): floor slab and an L of walls with a
     * table and a ball inside */
    v3 rc = mk(ROOM_X, 0.0f, ROOM_Z);
    r |= box(s, add(rc, mk(-15, 0, -15)), add(rc, mk(15, 0.3f, 15)), mk(0.7f, 0.7f, 0.75f));
    r |= box(s, add(rc, mk(-15, 0.3f, -15)), add(rc, mk(15, 9, -14)), mk(0.85f, 0.8f, 0.7f));
    r |= box(s, add(rc, mk(14, 0.3f, -14)), add(rc, mk(15, 9, 15)), mk(0.85f, 0.8f, 0.7f));
    r |= box(s, add(rc, mk(-3, 0.3f, -4)), add(rc, mk(3, 1.2f, 2)), mk(0.5f, 0.35f, 0.2f));
    r |= sphere(s, add(rc, mk(6, 1.8f, 4)), 1.5f, 20, mk(0.3f, 0.4f, 0.9f));
    if (r) {
        demo_scene_free(s);
        return -1;
    }
    bounds(s);
    return 0;
}

int demo_scene_box(demo_scene* s, swarp_aabb* out_box) {
    memset(s, 0, sizeof *s);
    int r = ground(s, 100.0f, mk(0.6f, 0.6f, 0.6f));
    r |= box(s, mk(-5, 0, -5), mk(5, 10, 5), mk(0.8f, 0.3f, 0.3f));
    if (r) {
        demo_scene_free(s);
        return -1;
    }
    if (out_box) {
        swarp_aabb b = {{-5, 0, -5}, {5, 10, 5}};
        *out_box = b;
    }
    bounds(s);
    return 0;
}

int demo_scene_obj(demo_scene* s, const char* path) {
    memset(s, 0, sizeof *s);
    FILE* f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "demo: cannot open %s\n", path);
        return -1;
    }
    v3* pos = NULL;
    size_t np = 0, cp = 0;
    char line[1024];
    int r = 0;
    while (!r && fgets(line, sizeof line, f)) {
        if (line[0] == 'v' && line[1] == ' ') {
            if (np == cp) {
                cp = cp ? 2 * cp : 1024;
                v3* nn = realloc(pos, cp * sizeof *nn);
                if (!nn) { r = -1; break; }
                pos = nn;
            }
            v3 p = {0, 0, 0};
            if (sscanf(line + 2, "%f %f %f", &p.x, &p.y, &p.z) != 3) { r = -1; break; }
            pos[np++] = p;
        } else if (line[0] == 'f' && line[1] == ' ') {
            long idx[64];
            int k = 0;
            char* c = line + 2;
            while (*c && k < 64) {
                char* end;
                long v = strtol(c, &end, 10);
                if (end == c) { ++c; continue; }
                idx[k++] = v < 0 ? (long)np + v : v - 1;
                c = end;
                while (*c && *c != ' ' && *c != '\t') ++c; /* skip /vt/vn */
            }
            for (int t = 1; t + 1 < k; ++t) {
                if (idx[0] < 0 || idx[t] < 0 || idx[t + 1] < 0 || (size_t)idx[0] >= np ||
                    (size_t)idx[t] >= np || (size_t)idx[t + 1] >= np) { r = -1; break; }
                r |= tri(s, pos[idx[0]], pos[idx[t]], pos[idx[t + 1]], mk(0.8f, 0.8f, 0.8f));
            }
        }
    }
    fclose(f);
    free(pos);
    if (r || s->count == 0) {
        fprintf(stderr, "demo: %s: no usable triangles\n", path);
        demo_scene_free(s);
        return -1;
    }
    bounds(s);
    /* a ground quad a little wider than the model, at its lowest point */
    swarp_aabb b = s->box;
    float ex = (float)(b.max.x - b.min.x), ez = (float)(b.max.z - b.min.z);
    float m = 0.5f * (ex > ez ? ex : ez);
    float y = (float)b.min.y;
    r = quad(s, mk((float)b.min.x - m, y, (float)b.min.z - m), mk((float)b.min.x - m, y, (float)b.max.z + m),
             mk((float)b.max.x + m, y, (float)b.max.z + m), mk((float)b.max.x + m, y, (float)b.min.z - m),
             mk(0.55f, 0.6f, 0.45f));
    if (r) {
        demo_scene_free(s);
        return -1;
    }
    bounds(s);
    return 0;
}

void demo_scene_free(demo_scene* s) {
    free(s->v);
    memset(s, 0, sizeof *s);
}
