/* scene.h -- triangle soup of the built-in scenes (scene.c) and OBJ loading. */
#ifndef DEMO_SCENE_H
#define DEMO_SCENE_H

#include <stddef.h>

#include "shadowwarp.h"

/** Interleaved vertex: position, normal, albedo. */
typedef struct demo_vertex {
    float p[3];
    float n[3];
    float c[3];
} demo_vertex;

typedef struct demo_scene {
    demo_vertex* v;
    size_t count;    /**< vertices (3 per triangle) */
    size_t capacity;
    swarp_aabb box;  /**< bounds of every vertex: the scene box S */
} demo_scene;

/** The default scene: ~800 x 800 m ground, a lattice tower, rows of box
 *  buildings, cone/box trees, spheres and a room corner (floor + wall).
 *  0 on success. */
int demo_scene_default(demo_scene* s);
/** The room corner of the default scene, for the lixel technique: the
 *  floor's top face and the back wall's inner face, each as a plane and the
 *  four corners of its rectangle (counter-clockwise seen from the room). */
typedef struct demo_room {
    swarp_plane floor, wall;
    swarp_vec3 floor_rect[4], wall_rect[4];
} demo_room;
void demo_scene_room(demo_room* out);

/** Flat ground (200 x 200 m) with one box of 10 x 10 x 10 m at the origin:
 *  the scene whose shadow the tests compute geometrically.  The box's
 *  bounds are written to *out_box when not NULL. */
int demo_scene_box(demo_scene* s, swarp_aabb* out_box);
/** Wavefront OBJ (v, vn ignored: flat normals, f with any polygon size,
 *  negative indices) plus a ground quad under it.  0 on success. */
int demo_scene_obj(demo_scene* s, const char* path);
void demo_scene_free(demo_scene* s);

#endif
