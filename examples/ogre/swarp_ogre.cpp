/* The OGRE 1.12 shadow camera setups of swarp_ogre.h. */
#include "swarp_ogre.h"

#include <OgreMovableObject.h>
#include <OgreRoot.h>
#include <OgreSceneNode.h>
#include <OgreViewport.h>

#include <cmath>

namespace swarp_ogre {

namespace {

swarp_vec3 toSwarp(const Ogre::Vector3& v)
{
    return swarp_vec3{v.x, v.y, v.z};
}

/* OGRE's own fallback when neither a far plane nor a shadow far distance is
 * set: FocusedShadowCameraSetup makes up near * 3000. */
const double SW_OGRE_MADE_UP_FAR = 3000.0;

} // namespace

swarp_status cameraFromOgre(const Ogre::Camera& cam, const Ogre::Light& light, swarp_camera* out)
{
    if (cam.getProjectionType() != Ogre::PT_PERSPECTIVE || cam.getFrustumOffset() != Ogre::Vector2::ZERO)
        return SWARP_ERR_INVALID_ARGUMENT;
    swarp_camera c = swarp_camera();
    c.eye = toSwarp(cam.getDerivedPosition());
    c.dir = toSwarp(cam.getDerivedDirection());
    c.up = toSwarp(cam.getDerivedUp());
    /* OGRE's FOVy is the full vertical angle, as the library's fovy */
    c.fovy = cam.getFOVy().valueRadians();
    c.aspect = cam.getAspectRatio();
    c.z_near = cam.getNearClipDistance();
    /* far 0 is OGRE's infinite far plane; no texture shadow is drawn beyond
     * the shadow far distance, so that bounds V */
    double far = cam.getFarClipDistance();
    double shadow_far = light.getShadowFarDistance();
    if (shadow_far > 0 && (far == 0 || shadow_far < far))
        far = shadow_far;
    if (far == 0)
        far = c.z_near * SW_OGRE_MADE_UP_FAR;
    c.z_far = far;
    *out = c;
    return SWARP_OK;
}

swarp_status lightFromOgre(const Ogre::Light& light, swarp_light* out)
{
    swarp_light l = swarp_light();
    switch (light.getType()) {
    case Ogre::Light::LT_DIRECTIONAL:
        l.type = SWARP_LIGHT_DIRECTIONAL;
        break;
    case Ogre::Light::LT_SPOTLIGHT:
        l.type = SWARP_LIGHT_POINT;
        /* OGRE's outer angle is the full cone (its default setup uses it as
         * the field of view): the half angle is the library's cone */
        l.cone_angle = 0.5 * light.getSpotlightOuterAngle().valueRadians();
        break;
    case Ogre::Light::LT_POINT:
        l.type = SWARP_LIGHT_POINT;
        break;
    default:
        return SWARP_ERR_UNKNOWN_ENUM;
    }
    /* OGRE's derived direction is the direction the light shines, the
     * library's "direction light travels" */
    l.direction = toSwarp(light.getDerivedDirection());
    l.position = toSwarp(light.getDerivedPosition());
    *out = l;
    return SWARP_OK;
}

bool sceneBoxFromOgre(const Ogre::SceneManager& sm, swarp_aabb* out)
{
    Ogre::AxisAlignedBox box;
    /* OGRE hands setups a const scene manager, but its getMovableObjects is
     * not const (it makes an empty collection for a type it has none of) */
    Ogre::SceneManager& msm = const_cast<Ogre::SceneManager&>(sm);
    for (const auto& factory : Ogre::Root::getSingleton().getMovableObjectFactories()) {
        /* a light's bounds are its range, not geometry */
        if (factory.first == Ogre::LightFactory::FACTORY_TYPE_NAME)
            continue;
        for (const auto& named : msm.getMovableObjects(factory.first)) {
            const Ogre::MovableObject* mo = named.second;
            if (mo->isAttached() && mo->isVisible())
                box.merge(mo->getWorldBoundingBox(true));
        }
    }
    if (!box.isFinite())
        return false;
    out->min = toSwarp(box.getMinimum());
    out->max = toSwarp(box.getMaximum());
    return true;
}

Ogre::Matrix4 toOgre(const swarp_mat4& m)
{
    Ogre::Matrix4 r;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            r[row][col] = static_cast<Ogre::Real>(m.m[col * 4 + row]);
    return r;
}

swarp_status SetupBase::gatherInputs(const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                                     const Ogre::Viewport* vp, const Ogre::Light* light,
                                     const Ogre::Camera* texCam, swarp_setup_options* setup,
                                     swarp_camera* c, swarp_light* l, swarp_aabb* s) const
{
    if (sm->getCameraRelativeRendering())
        return SWARP_ERR_INVALID_ARGUMENT;
    swarp_status status = cameraFromOgre(*cam, *light, c);
    if (status == SWARP_OK)
        status = lightFromOgre(*light, l);
    if (status != SWARP_OK)
        return status;
    if (mSceneBox.isFinite()) {
        s->min = toSwarp(mSceneBox.getMinimum());
        s->max = toSwarp(mSceneBox.getMaximum());
    } else if (!sceneBoxFromOgre(*sm, s)) {
        return SWARP_ERR_BODY_EMPTY;
    }
    /* OGRE's getProjectionMatrix is [-1, 1] clip depth; the render system
     * converts it to its own range */
    setup->depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
    if (const Ogre::Viewport* tv = texCam->getViewport()) {
        setup->map_width = static_cast<uint32_t>(tv->getActualWidth());
        setup->map_height = static_cast<uint32_t>(tv->getActualHeight());
    }
    if (vp) {
        setup->screen_width = static_cast<uint32_t>(vp->getActualWidth());
        setup->screen_height = static_cast<uint32_t>(vp->getActualHeight());
    }
    return SWARP_OK;
}

void SetupBase::apply(swarp_status status, const swarp_mat4* view, const swarp_mat4* proj,
                      const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                      const Ogre::Viewport* vp, const Ogre::Light* light, Ogre::Camera* texCam,
                      size_t iteration) const
{
    mStatus = status;
    if (swarp_status_is_error(status)) {
        DefaultShadowCameraSetup::getShadowCamera(sm, cam, vp, light, texCam, iteration);
        return;
    }
    Ogre::Matrix4 v = toOgre(*view);
    Ogre::Matrix4 p = toOgre(*proj);
    /* OGRE's view matrix is affine; the library's light views are rigid
     * (rotation and translation) for directional and point lights.  Should
     * one not be, the whole matrix goes into the projection. */
    if (v[3][0] != 0 || v[3][1] != 0 || v[3][2] != 0 || v[3][3] != 1) {
        p = p * v;
        v = Ogre::Matrix4::IDENTITY;
    }
    texCam->setCustomViewMatrix(true, Ogre::Affine3(v));
    texCam->setCustomProjectionMatrix(true, p);
}

ShadowCameraSetup::ShadowCameraSetup(const swarp_setup_options& opts)
    : mOptions(opts), mResult(swarp_setup_result())
{
}

void ShadowCameraSetup::getShadowCamera(const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                                        const Ogre::Viewport* vp, const Ogre::Light* light,
                                        Ogre::Camera* texCam, size_t iteration) const
{
    swarp_setup_options o = mOptions;
    swarp_camera c;
    swarp_light l;
    swarp_aabb s;
    swarp_status status = gatherInputs(sm, cam, vp, light, texCam, &o, &c, &l, &s);
    if (status == SWARP_OK)
        status = swarp_setup(&c, &l, &s, &o, &mResult, nullptr, 0, nullptr);
    apply(status, &mResult.light_view, &mResult.light_proj, sm, cam, vp, light, texCam, iteration);
}

PSSMShadowCameraSetup::PSSMShadowCameraSetup(const swarp_cascade_options& opts)
    : mOptions(opts), mSplit(swarp_cascade_split())
{
}

void PSSMShadowCameraSetup::getShadowCamera(const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                                            const Ogre::Viewport* vp, const Ogre::Light* light,
                                            Ogre::Camera* texCam, size_t iteration) const
{
    swarp_cascade_options o = mOptions;
    swarp_camera c;
    swarp_light l;
    swarp_aabb s;
    swarp_cascade_result result;
    swarp_cascade_split splits[SWARP_CASCADE_MAX_SPLITS];
    size_t count = 0;
    swarp_status status = gatherInputs(sm, cam, vp, light, texCam, &o.setup, &c, &l, &s);
    if (status == SWARP_OK)
        status = swarp_cascade_setup(&c, &l, &s, &o, &result, splits, SWARP_CASCADE_MAX_SPLITS, &count);
    /* OGRE asks for as many maps as the scene manager has textures per
     * light; a texture beyond the cascade's splits gets no split */
    if (!swarp_status_is_error(status) && iteration >= count)
        status = SWARP_ERR_SPLIT_COUNT;
    if (swarp_status_is_error(status)) {
        apply(status, nullptr, nullptr, sm, cam, vp, light, texCam, iteration);
        return;
    }
    mSplit = splits[iteration];
    mSplitPoints.assign(result.splits, result.splits + result.split_count + 1);
    swarp_mat4 view, proj;
    splitViewProjection(o, c, l, mSplit, &view, &proj);
    apply(mSplit.status, &view, &proj, sm, cam, vp, light, texCam, iteration);
}

void PSSMShadowCameraSetup::splitViewProjection(const swarp_cascade_options& o,
                                                const swarp_camera& c, const swarp_light& l,
                                                const swarp_cascade_split& split,
                                                swarp_mat4* view, swarp_mat4* proj)
{
    /* a split's matrix maps world to split clip space; stabilised, it takes
     * p - origin, so it is composed with the translation by -origin */
    swarp_mat4 world = split.matrix;
    if (o.stabilize.mode != SWARP_STABILIZE_DEFAULT && o.stabilize.mode != SWARP_STABILIZE_NONE) {
        swarp_mat4 shift = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
        shift.m[12] = -o.stabilize.origin.x;
        shift.m[13] = -o.stabilize.origin.y;
        shift.m[14] = -o.stabilize.origin.z;
        swarp_mat4_mul(&split.matrix, &shift, &world);
    }
    /* OGRE keeps a view (its position, culling, LOD) and a projection: the
     * light-aligned view of the library's single map, and the projection
     * world * view^-1, whose product with the view is the split's matrix */
    swarp_mat4 inverse;
    if (swarp_status_is_error(swarp_focus_light_view(&c, &l, nullptr, view)) ||
        swarp_status_is_error(swarp_mat4_invert(view, &inverse))) {
        *view = swarp_mat4{{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
        *proj = world;
        return;
    }
    swarp_mat4_mul(&world, &inverse, proj);
}

} // namespace swarp_ogre
