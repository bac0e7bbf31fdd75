/* The helpers of ogre_scene.h. */
#include "ogre_scene.h"

#include <cmath>

namespace swarp_ogre_test {

swarp_mat4 matFromOgre(const Ogre::Matrix4& m)
{
    swarp_mat4 r;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            r.m[col * 4 + row] = m[row][col];
    return r;
}

bool matFinite(const Ogre::Matrix4& m)
{
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(m[i / 4][i % 4]))
            return false;
    return true;
}

Ogre::Matrix4 shadowViewProj(const HeadlessSceneManager* sm, size_t i)
{
    const Ogre::Camera* texCam = sm->shadowCamera(i);
    if (!sm->shadowCameraUsable(i))
        return Ogre::Matrix4(NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
                             NAN, NAN);
    return texCam->getProjectionMatrix() * Ogre::Matrix4(texCam->getViewMatrix());
}

void addBoxObject(Ogre::SceneManager* sm, const char* name, const swarp_aabb& b)
{
    Ogre::ManualObject* mo = sm->createManualObject(name);
    mo->begin("BaseWhite", Ogre::RenderOperation::OT_TRIANGLE_LIST);
    for (int i = 0; i < 8; ++i)
        mo->position(Ogre::Real((i & 1) ? b.max.x : b.min.x), Ogre::Real((i & 2) ? b.max.y : b.min.y),
                     Ogre::Real((i & 4) ? b.max.z : b.min.z));
    static const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                     {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (const auto& t : faces)
        mo->triangle(t[0], t[1], t[2]);
    mo->end();
    sm->getRootSceneNode()->attachObject(mo);
}

} // namespace swarp_ogre_test
