/* Small helpers for programs that drive OGRE headless (headless.h) and
 * measure its shadow cameras with the library: OGRE's matrices in the
 * library's column-major layout, a texture camera's world -> light clip
 * matrix, and a box as a scene object. */
#ifndef SWARP_OGRE_SCENE_H
#define SWARP_OGRE_SCENE_H

#include "headless.h"
#include "shadowwarp.h"

namespace swarp_ogre_test {

/* OGRE's row-major Matrix4 (column vectors) as a swarp_mat4 (column-major) */
swarp_mat4 matFromOgre(const Ogre::Matrix4& m);

/* every element finite */
bool matFinite(const Ogre::Matrix4& m);

/* texture camera i's projection x view as OGRE forms it (float); NaN in every
 * element when the setup left it non-finite (asking OGRE's frustum would
 * abort) */
Ogre::Matrix4 shadowViewProj(const HeadlessSceneManager* sm, size_t i);

/* the box as a closed triangle mesh attached to the root node: a caster and
 * receiver whose bounds are exactly b */
void addBoxObject(Ogre::SceneManager* sm, const char* name, const swarp_aabb& b);

} // namespace swarp_ogre_test

#endif
