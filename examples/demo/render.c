/* render.c -- shadow passes into a depth texture array (one layer per map)
 * and the main pass with the shadow test, the split selection and the
 * visualisations of [RHS] chapter 5. */
#include "render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>

#include "filtering_glsl.h"
#include "splits_glsl.h"

double demo_now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static const char* const filter_names[DEMO_FILTER_COUNT] = {"none", "pcf2", "pcf3", "pcf5",
                                                           "poisson", "vsm", "evsm", "projblur"};

const char* demo_filter_name(demo_filter f) {
    return (unsigned)f < DEMO_FILTER_COUNT ? filter_names[f] : "?";
}

int demo_filter_parse(const char* name) {
    for (int i = 0; i < DEMO_FILTER_COUNT; ++i)
        if (strcmp(name, filter_names[i]) == 0) return i;
    return -1;
}

/* The moment pass (VSM / EVSM): the GLSL twins of swarp_vsm_moments and
 * swarp_evsm_moments (docs/filtering.md) on the window depth. */
static const char* const moment_fs =
    "uniform int u_kind;\n"
    "uniform float u_c;\n"
    "layout(location = 0) out vec4 o_m;\n"
    "void main() {\n"
    "  float x = gl_FragCoord.z;\n"
    "  if (u_kind == 0) o_m = vec4(x, x * x, 0.0, 0.0);\n"
    "  else { float p = exp(u_c * x), n = -exp(-u_c * x); o_m = vec4(p, p * p, n, n * n); }\n"
    "}\n";

/* Geometry cloning ([RHS] §3.3.6, Listing A.1, after ZSN07): one draw, the
 * geometry shader emits every triangle once per map, transformed by that
 * map's matrix, into layer i (gl_Layer) and viewport i (gl_ViewportIndex). */
static const char* const clone_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "out vec3 g_p;\n"
    "void main() { g_p = a_p; }\n";
static const char* const clone_gs =
    "layout(triangles, invocations = 16) in;\n"
    "layout(triangle_strip, max_vertices = 3) out;\n"
    "in vec3 g_p[];\n"
    "uniform mat4 u_light[16];\n"
    "uniform int u_count;\n"
    "void main() {\n"
    "  int i = gl_InvocationID;\n"
    "  if (i >= u_count) return;\n"
    "  vec4 c[3];\n"
    "  for (int k = 0; k < 3; ++k) c[k] = u_light[i] * vec4(g_p[k], 1.0);\n"
    /* cull triangles wholly outside one side of this map's clip volume */
    "  for (int a = 0; a < 2; ++a) {\n"
    "    if (c[0][a] > c[0].w && c[1][a] > c[1].w && c[2][a] > c[2].w) return;\n"
    "    if (c[0][a] < -c[0].w && c[1][a] < -c[1].w && c[2][a] < -c[2].w) return;\n"
    "  }\n"
    "  for (int k = 0; k < 3; ++k) {\n"
    "    gl_Position = c[k];\n"
    "    gl_Layer = i;\n"
    "    gl_ViewportIndex = i;\n"
    "    EmitVertex();\n"
    "  }\n"
    "  EndPrimitive();\n"
    "}\n";

/* [KOZ] §14.3.2 projective blur: the colour part of the shadow map is 1
 * where the light sees the receiver (the ground) and 0 where it sees a
 * caster; blurred, it is projected onto the ground as a soft shadow. */
static const char* const receiver_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "layout(location = 1) in vec3 a_n;\n"
    "uniform mat4 u_m;\n"
    "out float v_ground;\n"
    "void main() {\n"
    "  v_ground = (abs(a_p.y) < 1e-3 && a_n.y > 0.99) ? 1.0 : 0.0;\n"
    "  gl_Position = u_m * vec4(a_p, 1.0);\n"
    "}\n";
static const char* const receiver_fs =
    "in float v_ground;\n"
    "layout(location = 0) out vec4 o_c;\n"
    "void main() { o_c = vec4(v_ground > 0.5 ? 1.0 : 0.0); }\n";
/* one separable Gaussian pass (sigma u_sigma texels, radius 3 sigma) */
static const char* const blur_vs =
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID & 2) * 2 - 1);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";
static const char* const blur_fs =
    "uniform sampler2DArray u_src;\n"
    "uniform int u_layer;\n"
    "uniform ivec2 u_dir;\n"
    "uniform float u_sigma;\n"
    "layout(location = 0) out vec4 o_c;\n"
    "void main() {\n"
    "  ivec2 c = ivec2(gl_FragCoord.xy);\n"
    "  ivec2 m = textureSize(u_src, 0).xy - 1;\n"
    "  int rad = int(ceil(3.0 * u_sigma));\n"
    "  float sum = 0.0, wsum = 0.0;\n"
    "  for (int k = -rad; k <= rad; ++k) {\n"
    "    float w = exp(-0.5 * float(k * k) / (u_sigma * u_sigma));\n"
    "    sum += w * texelFetch(u_src, ivec3(clamp(c + k * u_dir, ivec2(0), m), u_layer), 0).r;\n"
    "    wsum += w;\n"
    "  }\n"
    "  o_c = vec4(sum / wsum);\n"
    "}\n";

static const char* const depth_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "uniform mat4 u_m;\n"
    "void main() { gl_Position = u_m * vec4(a_p, 1.0); }\n";

static const char* const main_vs =
    "layout(location = 0) in vec3 a_p;\n"
    "layout(location = 1) in vec3 a_n;\n"
    "layout(location = 2) in vec3 a_c;\n"
    "uniform mat4 u_view, u_proj, u_sel_view;\n"
    "uniform int u_has_sel_view;\n"
    "out vec3 v_p; out vec3 v_n; out vec3 v_c; out float v_depth;\n"
    "void main() {\n"
    "  vec4 vs = u_view * vec4(a_p, 1.0);\n"
    /* split selection always uses the VIEWER's eye depth, also when an
     * outside camera draws the picture */
    "  vec4 es = u_has_sel_view != 0 ? u_sel_view * vec4(a_p, 1.0) : vs;\n"
    "  v_p = a_p; v_n = a_n; v_c = a_c; v_depth = -es.z;\n"
    "  gl_Position = u_proj * vs;\n"
    "}\n";

/* The main pass.  The fragment shader is shaders/splits.glsl and
 * shaders/filtering.glsl (the library's GLSL twins, tested against the C
 * functions by the splits and filter stages) followed by this source.
 * Map selection, mirroring the library's CPU references:
 *   u_select 0: by eye depth, swarp_select_split_depth (splits.glsl, twin of
 *     swarp_cascade_select_depth [RHS] §3.3.3), with swarp_cascade_blend's
 *     band (weight w of split i, 1 - w of i + 1);
 *   u_select 1: best resolution, swarp_select_split_best (twin of
 *     swarp_cascade_select_best, ZZB09), else the depth choice;
 *   u_select 2: swarp_lixel_select: the first map whose clip volume holds
 *     p in x and y (w > 0), else the last map (the fallback);
 *   u_select 3: the cube face of [KOZ] Listing 14-1 (swarp_cube_lookup).
 * Bias: swarp_bias_normal_offset (splits.glsl).  VSM / EVSM: vsm_chebyshev,
 * vsm_reduce_bleeding, evsm_visibility (filtering.glsl). */
static const char* const main_fs =
    "in vec3 v_p; in vec3 v_n; in vec3 v_c; in float v_depth;\n"
    "layout(location = 0) out vec4 o_color;\n"
    "layout(location = 1) out vec4 o_tex;\n"
    "layout(location = 2) out vec4 o_pos;\n"
    "layout(location = 3) out vec4 o_nrm;\n"
    "uniform sampler2DArrayShadow u_shadow;\n"
    "uniform sampler2DArray u_moments;\n"
    "uniform vec2 u_poisson[16];\n"
    "uniform float u_evsm_c;\n"
    "uniform mat4 u_light[16];\n"
    "uniform mat4 u_light_inv[16];\n"
    "uniform vec2 u_uvscale[16];\n"
    "uniform float u_split[17];\n"
    "uniform int u_count, u_mode, u_filter, u_select;\n"
    "uniform float u_res, u_blend, u_grid, u_offset;\n"
    "uniform vec3 u_light_dir;\n"
    "uniform mat4 u_cube_cam;\n"
    "uniform vec3 u_cube_P;\n"
    "uniform vec3 u_cube_N[6];\n"
    "uniform float u_cube_d[6];\n"
    /* swarp_lixel_select: x and y only, w > 0 */
    "bool covers(int i, vec3 p) {\n"
    "  vec4 h = u_light[i] * vec4(p, 1.0);\n"
    "  return h.w > 0.0 && abs(h.x) <= h.w && abs(h.y) <= h.w;\n"
    "}\n"
    /* [KOZ] Listing 14-1 (swarp_cube_lookup): u = V - P in post-projective
     * space, the face with the largest (u . N_i) / d_i */
    "int select_cube(vec3 p) {\n"
    "  vec4 h = u_cube_cam * vec4(p, 1.0);\n"
    "  vec3 u = h.xyz / h.w - u_cube_P;\n"
    "  int best = 0; float a = -1e30;\n"
    "  for (int i = 0; i < u_count; ++i) {\n"
    "    float ai = dot(u, u_cube_N[i]) / u_cube_d[i];\n"
    "    if (ai > a) { a = ai; best = i; }\n"
    "  }\n"
    "  return best;\n"
    "}\n"
    "int select_map(vec3 p, float z) {\n"
    "  if (u_select == 3) return select_cube(p);\n"
    "  if (u_select == 2) {\n"
    "    for (int i = 0; i < u_count - 1; ++i) if (covers(i, p)) return i;\n"
    "    return u_count - 1;\n"
    "  }\n"
    "  int d = swarp_select_split_depth(u_split, u_count, z);\n"
    "  if (u_select == 0) return d;\n"
    "  return swarp_select_split_best(u_light, u_light_inv, u_count, vec2(u_res), false, p, d);\n"
    "}\n"
    "vec3 map_coord(int i, vec3 p) {\n"
    "  vec4 c = u_light[i] * vec4(p, 1.0);\n"
    "  vec3 sc = c.xyz / c.w * 0.5 + 0.5;\n"
    "  return vec3(sc.xy * u_uvscale[i], sc.z);\n"
    "}\n"
    "bool v_ground = false;\n"
    "float lookup(int i, vec3 sc) {\n"
    "  if (any(lessThan(sc, vec3(0.0))) || sc.x > u_uvscale[i].x || sc.y > u_uvscale[i].y ||\n"
    "      sc.z > 1.0) return 1.0;\n"
    "  float ref = sc.z;\n"
    "  if (u_filter == 0) {\n"
    "    vec2 t = (floor(sc.xy * u_res) + 0.5) / u_res;\n"
    "    return texture(u_shadow, vec4(t, float(i), ref));\n"
    "  }\n"
    "  if (u_filter == 1) return texture(u_shadow, vec4(sc.xy, float(i), ref));\n"
    "  if (u_filter == 4) {\n"
    "    float s = 0.0;\n"
    "    for (int k = 0; k < 16; ++k)\n"
    "      s += texture(u_shadow, vec4(sc.xy + 2.0 * u_poisson[k] / u_res, float(i), ref));\n"
    "    return s / 16.0;\n"
    "  }\n"
    "  if (u_filter == 7) {\n"
    /* projective blur on the ground; ordinary 3x3 PCF on everything else */
    "    if (v_ground) return texture(u_moments, vec3(sc.xy, float(i))).r;\n"
    "    float s = 0.0;\n"
    "    for (int y = -1; y <= 1; ++y) for (int x = -1; x <= 1; ++x)\n"
    "      s += texture(u_shadow, vec4(sc.xy + vec2(x, y) / u_res, float(i), ref));\n"
    "    return s / 9.0;\n"
    "  }\n"
    "  if (u_filter >= 5) {\n"
    /* filtering the moments over the same 3x3 bilinear footprint as pcf3 */
    "    vec4 m = vec4(0.0);\n"
    "    for (int y = -1; y <= 1; ++y) for (int x = -1; x <= 1; ++x)\n"
    "      m += texture(u_moments, vec3(sc.xy + vec2(x, y) / u_res, float(i)));\n"
    "    m /= 9.0;\n"
    "    if (u_filter == 5) return vsm_reduce_bleeding(vsm_chebyshev(m.xy, ref, 1e-6), 0.2);\n"
    "    return evsm_visibility(m, ref, u_evsm_c, u_evsm_c, 1e-6);\n"
    "  }\n"
    "  int k = u_filter == 2 ? 1 : 2;\n"
    "  float s = 0.0;\n"
    "  for (int y = -k; y <= k; ++y) for (int x = -k; x <= k; ++x)\n"
    "    s += texture(u_shadow, vec4(sc.xy + vec2(x, y) / u_res, float(i), ref));\n"
    "  return s / float((2 * k + 1) * (2 * k + 1));\n"
    "}\n"
    /* [RHS] Listing A.3: interval bounds and colours of the sampling scale */
    "const float iv[7] = float[7](0.0, 1.0/7.75, 1.0/3.25, 1.0, 3.25, 7.75, 10.0);\n"
    "const vec3 clr[7] = vec3[7](vec3(0.2,0.0,0.0), vec3(1.0,0.2,0.0), vec3(1.0,1.0,0.0),\n"
    "  vec3(0.0,1.0,0.0), vec3(0.3,0.8,1.0), vec3(0.0,0.0,1.0), vec3(0.0,0.0,0.4));\n"
    "vec3 sampling_color(vec2 uv) {\n"
    "  vec2 dSdX = u_res * dFdx(uv);\n"
    "  vec2 dSdY = u_res * dFdy(uv);\n"
    "  float area = abs(dSdX.x * dSdY.y - dSdY.x * dSdX.y);\n"
    "  vec3 result = clr[6];\n"
    "  for (int i = 0; i < 6; ++i)\n"
    "    if (area >= iv[i] && area < iv[i + 1]) {\n"
    "      result = mix(clr[i], clr[i + 1], (area - iv[i]) / (iv[i + 1] - iv[i]));\n"
    "      break;\n"
    "    }\n"
    "  return result;\n"
    "}\n"
    /* [RHS] Listing A.4 (Lloyd's texel grid), size = u_grid texels per cell */
    "float grid_line(vec2 uv) {\n"
    "  float texel = u_grid / u_res;\n"
    "  vec2 tc = uv / texel;\n"
    "  vec2 dS = vec2(dFdx(tc.x), dFdy(tc.x));\n"
    "  vec2 dT = vec2(dFdx(tc.y), dFdy(tc.y));\n"
    "  vec2 m = fract(tc);\n"
    "  return (m.x < length(dS) || m.y < length(dT)) ? 1.0 : 0.0;\n"
    "}\n"
    "void main() {\n"
    "  vec3 n = normalize(v_n);\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  v_ground = abs(v_p.y) < 1e-3 && n.y > 0.99;\n"
    "  vec3 to_light = -normalize(u_light_dir);\n"
    "  float ndl = max(dot(n, to_light), 0.0);\n"
    "  int i = select_map(v_p, v_depth);\n"
    /* normal-offset bias (docs/splits.md twin of swarp_bias_normal_offset) */
    "  vec3 pb = swarp_bias_normal_offset(u_light[i], u_light_inv[i], u_res * u_uvscale[i], v_p,\n"
    "                                     n, to_light, u_offset);\n"
    "  vec3 sc = map_coord(i, pb);\n"
    "  float lit = 1.0;\n"
    "  float w = 1.0;\n"
    "  if (u_mode != 4) {\n"
    "    lit = lookup(i, sc);\n"
    "    if (u_select == 0) {\n"
    "      int bi;\n"
    "      w = swarp_cascade_blend(u_split, u_count, v_depth, u_blend, bi);\n"
    "      if (w < 1.0) lit = mix(lookup(i + 1, map_coord(i + 1, pb)), lit, w);\n"
    "    }\n"
    "  }\n"
    "  if (ndl <= 0.0) lit = 0.0;\n"
    "  vec3 sc0 = map_coord(i, v_p);\n"
    "  vec3 shaded = v_c * (0.35 + 0.65 * ndl * lit);\n"
    "  vec3 col = shaded;\n"
    "  if (u_mode == 1) col = sampling_color(sc0.xy) * (0.55 + 0.45 * ndl * lit);\n"
    "  else if (u_mode == 2) {\n"
    "    const vec3 sp[4] = vec3[4](vec3(1,0,0), vec3(1,1,0), vec3(0,1,0), vec3(0,0,1));\n"
    "    col = mix(shaded, sp[i % 4] * (0.45 + 0.55 * ndl * lit), 0.6);\n"
    "  } else if (u_mode == 3) col = mix(shaded, vec3(0.0), grid_line(sc0.xy));\n"
    "  o_color = vec4(col, 1.0);\n"
    /* the map index, and in its fraction the blend weight: i + (1 - w)/2 */
    "  o_tex = vec4(sc0.xy * u_res, float(i) + 0.5 * (1.0 - w), v_depth);\n"
    "  o_pos = vec4(v_p, lit);\n"
    /* the facet normal of the rasterised triangle: v_p is affine over the
     * triangle, so its screen derivatives span the triangle's plane (the
     * interpolated vertex normal v_n is not that plane on curved meshes) */
    "  o_nrm = vec4(normalize(cross(dFdx(v_p), dFdy(v_p))), 1.0);\n"
    "}\n";

/* The RGBA32F arrays (moments, projective-blur colour) are big (16 bytes a
 * texel): made on first use only. */
static GLuint float_array(int res, int layers) {
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D_ARRAY, t);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, res, res, layers, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

int demo_render_init(demo_renderer* r, const demo_scene* s, int w, int h, int map_res,
                     int max_layers) {
    memset(r, 0, sizeof *r);
    r->w = w;
    r->h = h;
    r->map_res = map_res;
    r->layers = max_layers;
    r->vertex_count = (int)s->count;
    glGenVertexArrays(1, &r->vao);
    glBindVertexArray(r->vao);
    glGenBuffers(1, &r->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, r->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(s->count * sizeof(demo_vertex)), s->v,
                 GL_STATIC_DRAW);
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(demo_vertex),
                              (const void*)(a * 3 * sizeof(float)));
    }
    r->prog_depth = demo_gl_program("depth", depth_vs, NULL);
    r->prog_moment = demo_gl_program("moments", depth_vs, moment_fs);
    r->prog_clone = demo_gl_program_gs("clone", clone_vs, clone_gs, NULL);
    r->prog_receiver = demo_gl_program("receiver", receiver_vs, receiver_fs);
    r->prog_blur = demo_gl_program("blur", blur_vs, blur_fs);
    if (!r->prog_receiver || !r->prog_blur) return -1;
    if (!r->prog_clone) return -1;
    if (!r->prog_moment) return -1;
    double xy[32], dmin;
    size_t np = 0;
    if (swarp_pcf_poisson_disk(7, 16, 0, xy, 16, &np, &dmin) != SWARP_OK || np != 16) return -1;
    for (int i = 0; i < 32; ++i) r->poisson[i] = (float)xy[i];
    double c;
    if (swarp_evsm_max_exponent(SWARP_TEXEL_FP32, &c) != SWARP_OK) return -1;
    r->evsm_c = (float)c;
    r->blur_sigma = 2.0f;
    const char* const fs_parts[3] = {demo_splits_glsl, demo_filtering_glsl, main_fs};
    r->prog_main = demo_gl_program_parts("main", main_vs, fs_parts, 3);
    if (!r->prog_depth || !r->prog_main) return -1;

    glGenTextures(1, &r->shadow_tex);
    glBindTexture(GL_TEXTURE_2D_ARRAY, r->shadow_tex);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, map_res, map_res, max_layers, 0,
                 GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &r->shadow_fbo);
    glGenFramebuffers(1, &r->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    GLuint* rbs[5] = {&r->rb_color, &r->rb_tex, &r->rb_pos, &r->rb_nrm, &r->rb_depth};
    const GLenum fmts[5] = {GL_RGBA8, GL_RGBA32F, GL_RGBA32F, GL_RGBA32F, GL_DEPTH_COMPONENT24};
    const GLenum atts[5] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                            GL_COLOR_ATTACHMENT3, GL_DEPTH_ATTACHMENT};
    for (int i = 0; i < 5; ++i) {
        glGenRenderbuffers(1, rbs[i]);
        glBindRenderbuffer(GL_RENDERBUFFER, *rbs[i]);
        glRenderbufferStorage(GL_RENDERBUFFER, fmts[i], w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, atts[i], GL_RENDERBUFFER, *rbs[i]);
    }
    const GLenum bufs[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                            GL_COLOR_ATTACHMENT3};
    glDrawBuffers(4, bufs);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        fprintf(stderr, "demo: main framebuffer incomplete\n");
        return -1;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("init") ? -1 : 0;
}

void demo_render_free(demo_renderer* r) {
    if (r->prog_depth) glDeleteProgram(r->prog_depth);
    if (r->prog_moment) glDeleteProgram(r->prog_moment);
    if (r->prog_clone) glDeleteProgram(r->prog_clone);
    if (r->moment_tex) glDeleteTextures(1, &r->moment_tex);
    if (r->blur_tex) glDeleteTextures(1, &r->blur_tex);
    if (r->prog_receiver) glDeleteProgram(r->prog_receiver);
    if (r->prog_blur) glDeleteProgram(r->prog_blur);
    if (r->prog_main) glDeleteProgram(r->prog_main);
    glDeleteTextures(1, &r->shadow_tex);
    glDeleteFramebuffers(1, &r->shadow_fbo);
    glDeleteFramebuffers(1, &r->fbo);
    GLuint rbs[5] = {r->rb_color, r->rb_tex, r->rb_pos, r->rb_nrm, r->rb_depth};
    glDeleteRenderbuffers(5, rbs);
    glDeleteBuffers(1, &r->vbo);
    glDeleteVertexArrays(1, &r->vao);
    memset(r, 0, sizeof *r);
}

static void to_float(const swarp_mat4* m, float out[16]) {
    /* swarp_mat4_to_float checks finiteness; a light matrix that does not
     * fit a float is a library bug worth seeing, so fall back loudly. */
    if (swarp_mat4_to_float(m, out) != SWARP_OK) {
        fprintf(stderr, "demo: light matrix not representable as float\n");
        for (int i = 0; i < 16; ++i) out[i] = (i % 5 == 0) ? 1.0f : 0.0f;
    }
}

int demo_render_shadow(demo_renderer* r, const demo_shadow* sh, demo_filter filter,
                       double* ms_out) {
    int errors = 0;
    int blur = filter == DEMO_FILTER_PROJBLUR;
    int moments = filter == DEMO_FILTER_VSM || filter == DEMO_FILTER_EVSM || blur;
    if (moments && !r->moment_tex) r->moment_tex = float_array(r->map_res, r->layers);
    glBindFramebuffer(GL_FRAMEBUFFER, r->shadow_fbo);
    GLenum buf = moments ? GL_COLOR_ATTACHMENT0 : GL_NONE;
    glDrawBuffers(1, &buf);
    glReadBuffer(GL_NONE);
    GLuint prog = blur ? r->prog_receiver : moments ? r->prog_moment : r->prog_depth;
    glUseProgram(prog);
    if (moments && !blur) {
        glUniform1i(glGetUniformLocation(prog, "u_kind"), filter == DEMO_FILTER_EVSM);
        glUniform1f(glGetUniformLocation(prog, "u_c"), r->evsm_c);
    }
    glBindVertexArray(r->vao);
    glEnable(GL_DEPTH_TEST);
    if (sh->depth_clamp) glEnable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    /* slope-scaled depth bias against acne for the depth compare (moment
     * maps store the unbiased depth: Chebyshev's bound needs no offset) */
    if (!moments || blur) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(2.0f, 8.0f);
    }
    GLint loc = glGetUniformLocation(prog, "u_m");
    /* what an empty texel holds: depth 1 (the far plane) */
    const float far_vsm[4] = {1, 1, 0, 0};
    const float far_evsm[4] = {expf(r->evsm_c), expf(2 * r->evsm_c), -expf(-r->evsm_c),
                               expf(-2 * r->evsm_c)};
    for (int i = 0; i < sh->count && i < r->layers; ++i) {
        double t0 = demo_now_ms();
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, r->shadow_tex, 0, i);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, moments ? r->moment_tex : 0,
                                  0, i);
        glViewport(0, 0, r->map_res, r->map_res);
        glClear(GL_DEPTH_BUFFER_BIT);
        const float lit[4] = {1, 1, 1, 1};
        if (moments)
            glClearBufferfv(GL_COLOR, 0, blur ? lit : filter == DEMO_FILTER_EVSM ? far_evsm : far_vsm);
        glViewport(0, 0, sh->viewport[i][0], sh->viewport[i][1]);
        float m[16];
        to_float(&sh->light[i], m);
        glUniformMatrix4fv(loc, 1, GL_FALSE, m);
        /* llvmpipe compiles a program's shaders at its first draw (the
         * first shadow pass of the gallery took 15.7 ms, the same pass
         * after 5.2): each program's first pass is drawn once untimed,
         * so the pass times the planner is calibrated with are the
         * passes' own */
        const unsigned bit = prog == r->prog_depth ? 1u : prog == r->prog_moment ? 2u : 4u;
        if (!(r->warmed & bit)) {
            glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
            glFinish();
            glClear(GL_DEPTH_BUFFER_BIT);
            if (moments)
                glClearBufferfv(GL_COLOR, 0, blur ? lit : filter == DEMO_FILTER_EVSM ? far_evsm : far_vsm);
            r->warmed |= bit;
            t0 = demo_now_ms();
        }
        glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
        glFinish();
        if (ms_out) ms_out[i] = demo_now_ms() - t0;
        char name[32];
        snprintf(name, sizeof name, "shadow pass %d", i);
        errors += demo_gl_check(name);
    }
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    if (blur && !r->blur_off) {
        /* ping-pong: moment_tex -> blur_tex (x) -> moment_tex (y), per map */
        if (!r->blur_tex) r->blur_tex = float_array(r->map_res, r->layers);
        glDisable(GL_DEPTH_TEST);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, 0, 0, 0);
        glUseProgram(r->prog_blur);
        glUniform1i(glGetUniformLocation(r->prog_blur, "u_src"), 0);
        glUniform1f(glGetUniformLocation(r->prog_blur, "u_sigma"), r->blur_sigma);
        glActiveTexture(GL_TEXTURE0);
        glBindVertexArray(r->vao);
        double t0 = demo_now_ms();
        for (int i = 0; i < sh->count && i < r->layers; ++i) {
            glViewport(0, 0, sh->viewport[i][0], sh->viewport[i][1]);
            glUniform1i(glGetUniformLocation(r->prog_blur, "u_layer"), i);
            for (int pass = 0; pass < 2; ++pass) {
                GLuint src = pass ? r->blur_tex : r->moment_tex;
                GLuint dst = pass ? r->moment_tex : r->blur_tex;
                glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, dst, 0, i);
                glBindTexture(GL_TEXTURE_2D_ARRAY, src);
                glUniform2i(glGetUniformLocation(r->prog_blur, "u_dir"), pass == 0, pass == 1);
                glDrawArrays(GL_TRIANGLES, 0, 3);
            }
        }
        glFinish();
        r->blur_ms = demo_now_ms() - t0;
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
        errors += demo_gl_check("projective blur passes");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return errors;
}

int demo_render_shadow_single(demo_renderer* r, const demo_shadow* sh, double* ms_out) {
    glBindFramebuffer(GL_FRAMEBUFFER, r->shadow_fbo);
    GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
    /* the whole array: layered rendering */
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, r->shadow_tex, 0);
    double t0 = demo_now_ms();
    glViewport(0, 0, r->map_res, r->map_res);
    glEnable(GL_DEPTH_TEST);
    if (sh->depth_clamp) glEnable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glClear(GL_DEPTH_BUFFER_BIT); /* clears every layer */
    for (int i = 0; i < sh->count; ++i)
        glViewportIndexedf((GLuint)i, 0, 0, (float)sh->viewport[i][0], (float)sh->viewport[i][1]);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 8.0f);
    glUseProgram(r->prog_clone);
    float lm[DEMO_MAX_SPLITS * 16];
    for (int i = 0; i < sh->count; ++i) to_float(&sh->light[i], lm + 16 * i);
    glUniformMatrix4fv(glGetUniformLocation(r->prog_clone, "u_light"), sh->count, GL_FALSE, lm);
    glUniform1i(glGetUniformLocation(r->prog_clone, "u_count"), sh->count);
    glBindVertexArray(r->vao);
    glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    glFinish();
    if (ms_out) *ms_out = demo_now_ms() - t0;
    int errors = demo_gl_check("single-pass shadow (geometry cloning)");
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    glViewport(0, 0, r->map_res, r->map_res); /* resets every viewport index */
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, 0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return errors;
}

int demo_render_read_depth(demo_renderer* r, int layer, float* out) {
    glBindFramebuffer(GL_FRAMEBUFFER, r->shadow_fbo);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, r->shadow_tex, 0, layer);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, r->map_res, r->map_res, GL_DEPTH_COMPONENT, GL_FLOAT, out);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return demo_gl_check("depth read-back");
}

int demo_render_main(demo_renderer* r, const demo_shadow* sh, const demo_main_params* p,
                     double* ms_out) {
    double t0 = demo_now_ms();
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    const GLenum bufs[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                            GL_COLOR_ATTACHMENT3};
    glDrawBuffers(4, bufs);
    glViewport(0, 0, p->vw, p->vh);
    const float sky[4] = {0.62f, 0.75f, 0.92f, 1.0f}, zero[4] = {0, 0, 0, 0};
    const float nopos[4] = {0, 0, 0, -1};
    glClearBufferfv(GL_COLOR, 0, sky);
    glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfv(GL_COLOR, 2, nopos);
    glClearBufferfv(GL_COLOR, 3, zero);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    /* a light view shows what the shadow pass saw: pancaked casters too */
    if (p->mode == DEMO_MODE_UNSHADOWED && sh->depth_clamp) glEnable(GL_DEPTH_CLAMP);
    GLuint pr = r->prog_main;
    glUseProgram(pr);
    glBindVertexArray(r->vao);
    glUniformMatrix4fv(glGetUniformLocation(pr, "u_view"), 1, GL_FALSE, p->view);
    glUniformMatrix4fv(glGetUniformLocation(pr, "u_sel_view"), 1, GL_FALSE, p->sel_view);
    glUniform1i(glGetUniformLocation(pr, "u_has_sel_view"), p->has_sel_view);
    glUniformMatrix4fv(glGetUniformLocation(pr, "u_proj"), 1, GL_FALSE, p->proj);
    float lm[DEMO_MAX_SPLITS * 16], li[DEMO_MAX_SPLITS * 16], uvs[DEMO_MAX_SPLITS * 2];
    float split[DEMO_MAX_SPLITS + 1];
    for (int i = 0; i < sh->count; ++i) {
        to_float(&sh->light[i], lm + 16 * i);
        swarp_mat4 inv;
        if (swarp_mat4_invert(&sh->light[i], &inv) != SWARP_OK) memset(&inv, 0, sizeof inv);
        to_float(&inv, li + 16 * i);
        uvs[2 * i] = (float)sh->viewport[i][0] / (float)r->map_res;
        uvs[2 * i + 1] = (float)sh->viewport[i][1] / (float)r->map_res;
    }
    for (int i = 0; i <= sh->count; ++i) split[i] = (float)sh->split[i];
    glUniformMatrix4fv(glGetUniformLocation(pr, "u_light"), sh->count, GL_FALSE, lm);
    glUniformMatrix4fv(glGetUniformLocation(pr, "u_light_inv"), sh->count, GL_FALSE, li);
    glUniform2fv(glGetUniformLocation(pr, "u_uvscale"), sh->count, uvs);
    glUniform1i(glGetUniformLocation(pr, "u_select"), (int)sh->select);
    glUniform1f(glGetUniformLocation(pr, "u_offset"), p->normal_offset);
    if (sh->select == DEMO_SELECT_CUBE) {
        float cam[16], P[3], N[18], d[6];
        to_float(&sh->cube_camera, cam);
        P[0] = (float)(sh->cube_light.x / sh->cube_light.w);
        P[1] = (float)(sh->cube_light.y / sh->cube_light.w);
        P[2] = (float)(sh->cube_light.z / sh->cube_light.w);
        for (int i = 0; i < sh->count && i < 6; ++i) {
            N[3 * i] = (float)sh->cube_normal[i].x;
            N[3 * i + 1] = (float)sh->cube_normal[i].y;
            N[3 * i + 2] = (float)sh->cube_normal[i].z;
            d[i] = (float)sh->cube_distance[i];
        }
        glUniformMatrix4fv(glGetUniformLocation(pr, "u_cube_cam"), 1, GL_FALSE, cam);
        glUniform3f(glGetUniformLocation(pr, "u_cube_P"), P[0], P[1], P[2]);
        glUniform3fv(glGetUniformLocation(pr, "u_cube_N"), sh->count, N);
        glUniform1fv(glGetUniformLocation(pr, "u_cube_d"), sh->count, d);
    }
    glUniform1fv(glGetUniformLocation(pr, "u_split"), sh->count + 1, split);
    glUniform1i(glGetUniformLocation(pr, "u_count"), sh->count);
    glUniform1i(glGetUniformLocation(pr, "u_mode"), (int)p->mode);
    glUniform1i(glGetUniformLocation(pr, "u_filter"), (int)p->filter);
    glUniform1f(glGetUniformLocation(pr, "u_res"), (float)r->map_res);
    glUniform1f(glGetUniformLocation(pr, "u_blend"), p->blend);
    glUniform1f(glGetUniformLocation(pr, "u_grid"), p->grid > 0 ? p->grid : 1.0f);
    glUniform3f(glGetUniformLocation(pr, "u_light_dir"), p->light_dir[0], p->light_dir[1],
                p->light_dir[2]);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, r->shadow_tex);
    glUniform1i(glGetUniformLocation(pr, "u_shadow"), 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D_ARRAY, r->moment_tex);
    glUniform1i(glGetUniformLocation(pr, "u_moments"), 1);
    glActiveTexture(GL_TEXTURE0);
    glUniform2fv(glGetUniformLocation(pr, "u_poisson"), 16, r->poisson);
    glUniform1f(glGetUniformLocation(pr, "u_evsm_c"), r->evsm_c);
    glDrawArrays(GL_TRIANGLES, 0, r->vertex_count);
    glFinish();
    glDisable(GL_DEPTH_CLAMP);
    if (ms_out) *ms_out = demo_now_ms() - t0;
    return demo_gl_check(p->mode == DEMO_MODE_UNSHADOWED ? "light view pass" : "main pass");
}

void demo_render_read_color(demo_renderer* r, int vw, int vh, uint8_t* rgba) {
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, vw, vh, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    /* flip to top row first */
    size_t row = (size_t)vw * 4;
    uint8_t* tmp = malloc(row);
    if (tmp) {
        for (int y = 0; y < vh / 2; ++y) {
            uint8_t* a = rgba + (size_t)y * row;
            uint8_t* b = rgba + (size_t)(vh - 1 - y) * row;
            memcpy(tmp, a, row);
            memcpy(a, b, row);
            memcpy(b, tmp, row);
        }
        free(tmp);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void demo_render_read_aux(demo_renderer* r, float* tex, float* pos) {
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (tex) {
        glReadBuffer(GL_COLOR_ATTACHMENT1);
        glReadPixels(0, 0, r->w, r->h, GL_RGBA, GL_FLOAT, tex);
    }
    if (pos) {
        glReadBuffer(GL_COLOR_ATTACHMENT2);
        glReadPixels(0, 0, r->w, r->h, GL_RGBA, GL_FLOAT, pos);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void demo_render_read_normals(demo_renderer* r, float* nrm) {
    glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadBuffer(GL_COLOR_ATTACHMENT3);
    glReadPixels(0, 0, r->w, r->h, GL_RGBA, GL_FLOAT, nrm);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
