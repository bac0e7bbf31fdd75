/* libshadowwarp in OGRE 1.12: shadow camera setups whose texture camera
 * gets the library's light view and projection.
 *
 *   sm->setShadowTechnique(Ogre::SHADOWTYPE_TEXTURE_MODULATIVE);
 *   sm->setShadowCameraSetup(std::make_shared<swarp_ogre::ShadowCameraSetup>());
 *
 * or, one map per split (sm->setShadowTextureCountPerLightType(
 * Ogre::Light::LT_DIRECTIONAL, m) with m the cascade's split count):
 *
 *   auto pssm = std::make_shared<swarp_ogre::PSSMShadowCameraSetup>(opts);
 *   light->setCustomShadowCameraSetup(pssm);
 *   ... per frame, after the shadow pass: pssm->getSplitPoints()
 *
 * OGRE's getShadowCamera(sm, cam, vp, light, texCam, iteration) calls the
 * library with
 *   - the camera: derived position, direction and up, full vertical field of
 *     view, aspect ratio, near plane; far = the camera's far plane, or the
 *     light's shadow far distance when that is nearer or the far plane is
 *     infinite (OGRE draws no texture shadow beyond it);
 *   - the light: directional (the direction light travels, as OGRE's
 *     derived direction), spot (a point light with half the outer angle as
 *     its cone) or point (omni);
 *   - the scene box S: setSceneBox's box, else the world bounds of every
 *     attached visible movable object of the scene manager except lights;
 *   - the map resolution of the texture camera's viewport and the screen
 *     resolution of the main viewport;
 * and sets the texture camera's custom view and projection matrices to
 * light_view and light_proj, clip depth [-1, 1] (OGRE's projection matrix
 * convention; the render system converts it).  When the library refuses
 * (for example SWARP_ERR_BODY_EMPTY: the camera sees nothing of S) the
 * texture camera gets OGRE's DefaultShadowCameraSetup and lastStatus() says
 * why.  Camera-relative rendering, orthographic cameras and frustum offsets
 * are not translated: they also fall back (SWARP_ERR_INVALID_ARGUMENT). */
#ifndef SWARP_OGRE_H
#define SWARP_OGRE_H

#include <OgreCamera.h>
#include <OgreLight.h>
#include <OgreSceneManager.h>
#include <OgreShadowCameraSetup.h>

#include <shadowwarp.h>

#include <vector>

namespace swarp_ogre {

/* The library's camera for an OGRE camera (z_far as described above). */
swarp_status cameraFromOgre(const Ogre::Camera& cam, const Ogre::Light& light, swarp_camera* out);
/* The library's light for an OGRE light. */
swarp_status lightFromOgre(const Ogre::Light& light, swarp_light* out);
/* The scene box S from the scene manager's movable objects; false when there
 * is none. */
bool sceneBoxFromOgre(const Ogre::SceneManager& sm, swarp_aabb* out);
/* A column-major library matrix as an OGRE (row-major) matrix. */
Ogre::Matrix4 toOgre(const swarp_mat4& m);

/* What both setups share: the inputs of one getShadowCamera call. */
class SetupBase : public Ogre::DefaultShadowCameraSetup {
public:
    /* S given by the caller; a null box returns to the scene manager's */
    void setSceneBox(const Ogre::AxisAlignedBox& box) { mSceneBox = box; }
    /* the status of the last getShadowCamera call (SWARP_OK or an
     * informational status: the library's matrix is in use) */
    swarp_status lastStatus() const { return mStatus; }

protected:
    swarp_status gatherInputs(const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                              const Ogre::Viewport* vp, const Ogre::Light* light,
                              const Ogre::Camera* texCam, swarp_setup_options* setup,
                              swarp_camera* c, swarp_light* l, swarp_aabb* s) const;
    /* the library's matrices on the texture camera, or OGRE's default setup
     * when status is an error */
    void apply(swarp_status status, const swarp_mat4* view, const swarp_mat4* proj,
               const Ogre::SceneManager* sm, const Ogre::Camera* cam, const Ogre::Viewport* vp,
               const Ogre::Light* light, Ogre::Camera* texCam, size_t iteration) const;

    Ogre::AxisAlignedBox mSceneBox;
    mutable swarp_status mStatus = SWARP_OK;
};

/* One map per light: swarp_setup (LiSPSM with n_opt unless the options say
 * otherwise). */
class ShadowCameraSetup : public SetupBase {
public:
    explicit ShadowCameraSetup(const swarp_setup_options& opts = swarp_setup_options());
    void getShadowCamera(const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                         const Ogre::Viewport* vp, const Ogre::Light* light, Ogre::Camera* texCam,
                         size_t iteration) const override;
    /* the library's result of the last call (valid when lastStatus() is not
     * an error) */
    const swarp_setup_result& lastResult() const { return mResult; }

private:
    swarp_setup_options mOptions;
    mutable swarp_setup_result mResult;
};

/* One map per split: swarp_cascade_setup, iteration i gets split i. */
class PSSMShadowCameraSetup : public SetupBase {
public:
    explicit PSSMShadowCameraSetup(const swarp_cascade_options& opts = swarp_cascade_options());
    void getShadowCamera(const Ogre::SceneManager* sm, const Ogre::Camera* cam,
                         const Ogre::Viewport* vp, const Ogre::Light* light, Ogre::Camera* texCam,
                         size_t iteration) const override;
    /* the split distances C_0 .. C_m of the last call (view depths), what a
     * receiver shader compares its depth with, as OGRE's PSSM's */
    const std::vector<Ogre::Real>& getSplitPoints() const { return mSplitPoints; }
    /* the library's split of the last call */
    const swarp_cascade_split& lastSplit() const { return mSplit; }

private:
    static void splitViewProjection(const swarp_cascade_options& o, const swarp_camera& c,
                                    const swarp_light& l, const swarp_cascade_split& split,
                                    swarp_mat4* view, swarp_mat4* proj);
    swarp_cascade_options mOptions;
    mutable swarp_cascade_split mSplit;
    mutable std::vector<Ogre::Real> mSplitPoints;
};

} // namespace swarp_ogre

#endif
