/* The headless OGRE frame of headless.h. */
#include "headless.h"

#include <cmath>

namespace swarp_ogre_test {

NullRenderSystem::NullRenderSystem()
{
    /* RenderSystem's destructor deletes mRealCapabilities */
    mRealCapabilities = createRenderSystemCapabilities();
    mCurrentCapabilities = mRealCapabilities;
}

NullRenderSystem::~NullRenderSystem() {}

const Ogre::String& NullRenderSystem::getName(void) const
{
    static const Ogre::String name("Null Rendering Subsystem");
    return name;
}

Ogre::RenderSystemCapabilities* NullRenderSystem::createRenderSystemCapabilities() const
{
    Ogre::RenderSystemCapabilities* caps = OGRE_NEW Ogre::RenderSystemCapabilities();
    caps->setRenderSystemName(getName());
    return caps;
}

SizedTarget::SizedTarget(const Ogre::String& name, unsigned width, unsigned height)
{
    mName = name;
    mWidth = width;
    mHeight = height;
}

bool ProbeCamera::storedMatricesFinite() const
{
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            if (isCustomProjectionMatrixEnabled() && !std::isfinite(mProjMatrix[r][c]))
                return false;
            if (r < 3 && isCustomViewMatrixEnabled() && !std::isfinite(mViewMatrix[r][c]))
                return false;
        }
    return true;
}

HeadlessSceneManager::HeadlessSceneManager(const Ogre::String& name) : Ogre::SceneManager(name)
{
    _setDestinationRenderSystem(Ogre::Root::getSingleton().getRenderSystem());
}

HeadlessSceneManager::~HeadlessSceneManager()
{
    /* the viewports on the targets refer to the cameras: targets first */
    mTexTargets.clear();
    clearScene();
    destroyAllCameras();
}

const Ogre::String& HeadlessSceneManager::getTypeName(void) const
{
    static const Ogre::String type("HeadlessSceneManager");
    return type;
}

void HeadlessSceneManager::createShadowCameras(size_t count, unsigned map_size)
{
    for (size_t i = mTexCams.size(); i < count; ++i) {
        /* ensureShadowTexturesCreated: camera named after the texture, aspect
         * of the texture, its own child node of the root, one viewport */
        Ogre::String name = "ShadowTexture" + Ogre::StringConverter::toString(i) + "Cam";
        /* createCamera, with the probing camera */
        ProbeCamera* texCam = OGRE_NEW ProbeCamera(name, this);
        mCameras.emplace(name, texCam);
        mCamVisibleObjectsMap[texCam] = Ogre::VisibleObjectsBoundsInfo();
        texCam->setAspectRatio(1);
        getRootSceneNode()->createChildSceneNode(name)->attachObject(texCam);
        mTexTargets.emplace_back(new SizedTarget(name + "Target", map_size, map_size));
        Ogre::Viewport* v = mTexTargets.back()->addViewport(texCam);
        v->setClearEveryFrame(true);
        v->setOverlaysEnabled(false);
        mTexTargets.back()->setAutoUpdated(false);
        mTexCams.push_back(texCam);
        mUsable.push_back(true);
    }
}

void HeadlessSceneManager::resetShadowCameras()
{
    /* Frustum's defaults */
    for (Ogre::Camera* texCam : mTexCams) {
        texCam->setCustomViewMatrix(false);
        texCam->setCustomProjectionMatrix(false);
        texCam->setProjectionType(Ogre::PT_PERSPECTIVE);
        texCam->setFOVy(Ogre::Radian(Ogre::Math::PI / 4));
        texCam->setNearClipDistance(100);
        texCam->setFarClipDistance(100000);
        texCam->getParentSceneNode()->setPosition(Ogre::Vector3::ZERO);
        texCam->getParentSceneNode()->setOrientation(Ogre::Quaternion::IDENTITY);
        mCamVisibleObjectsMap[texCam].reset();
    }
}

void HeadlessSceneManager::findVisible(Ogre::Camera* cam, bool only_casters)
{
    /* _renderScene: scene graph for this camera, then the bounds of what it
     * sees (shadow casters only in the render-to-texture stage) */
    _updateSceneGraph(cam);
    Ogre::VisibleObjectsBoundsInfo& bounds = mCamVisibleObjectsMap[cam];
    bounds.reset();
    _findVisibleObjects(cam, &bounds, only_casters);
}

/* OGRE 1.12.10's order, line numbers of OgreMain/src/OgreSceneManager.cpp
 * (SM) and OgreShadowRenderer.cpp (SR) at tag v1.12.10:
 *   SM 1257  _renderScene: _updateSceneGraph(camera)
 *   SM 1277  findLightsAffectingFrustum(camera) (SM 2981-3000 sorts the
 *            shadow-casting lights first)
 *   SM 1296  prepareShadowTextures(camera, vp) -> SM 3305-3316: the
 *            illumination stage becomes IRS_RENDER_TO_TEXTURE, the light list
 *            mLightsAffectingFrustum, then SR 783 ShadowRenderer::
 *            prepareShadowTextures: SR 786 ensureShadowTexturesCreated
 *            (here createShadowCameras, done once beforehand), and per
 *            shadow-casting light and texture j of its type (SR 825, 840):
 *   SR 847   shadowView->setCamera(texCam)
 *   SR 850   texCam->setLodCamera(cam)
 *   SR 853, 855  node direction (not for point lights), position (not for
 *            directional lights)
 *   SR 859, 862  viewport material scheme and visibility mask
 *   SR 870, 872  getShadowCamera of the light's custom setup or the default
 *   SR 875   background colour white
 *   SR 878   fireShadowTexturesPreCaster(light, texCam, j)
 *   SR 881   shadowRTT->update(): stands in here for the caster pass,
 *            SM 1257 _updateSceneGraph(texCam) and SM 1355 _findVisibleObjects
 *            with only the shadow casters (the stage is RENDER_TO_TEXTURE),
 *            which fill the texture camera's bounds
 *   then the main camera's visibility pass (SM 1355, its receiver bounds). */
void HeadlessSceneManager::renderShadows(Ogre::Camera* cam, Ogre::Viewport* vp)
{
    _updateSceneGraph(cam);
    findLightsAffectingFrustum(cam);
    const IlluminationRenderStage savedStage = mIlluminationStage;
    mIlluminationStage = IRS_RENDER_TO_TEXTURE;
    size_t next = 0;
    for (Ogre::Light* light : _getLightsAffectingFrustum()) {
        if (!light->getCastShadows())
            continue;
        size_t per_light = getShadowTextureCountPerLightType(light->getType());
        for (size_t j = 0; j < per_light && next < mTexCams.size(); ++j, ++next) {
            ProbeCamera* texCam = mTexCams[next];
            Ogre::Viewport* shadowView = texCam->getViewport();
            /* prepareShadowTextures, the body of its loop */
            shadowView->setCamera(texCam);
            texCam->setLodCamera(cam);
            if (light->getType() != Ogre::Light::LT_POINT)
                texCam->getParentSceneNode()->setDirection(light->getDerivedDirection(),
                                                           Ogre::Node::TS_WORLD);
            if (light->getType() != Ogre::Light::LT_DIRECTIONAL)
                texCam->getParentSceneNode()->setPosition(light->getDerivedPosition());
            shadowView->setMaterialScheme(vp->getMaterialScheme());
            shadowView->setVisibilityMask(vp->getVisibilityMask());
            if (!light->getCustomShadowCameraSetup())
                getShadowCameraSetup()->getShadowCamera(this, cam, vp, light, texCam, j);
            else
                light->getCustomShadowCameraSetup()->getShadowCamera(this, cam, vp, light, texCam, j);
            shadowView->setBackgroundColour(Ogre::ColourValue::White);
            fireShadowTexturesPreCaster(light, texCam, j);
            /* shadowRTT->update(): the caster pass of the texture camera */
            mUsable[next] = texCam->storedMatricesFinite();
            if (mUsable[next]) {
                findVisible(texCam, true);
            } else {
                /* OGRE would abort here; the harness disarms the camera so
                 * that the rest of the frame (which visits the texture
                 * camera as a scene object) runs */
                texCam->setCustomViewMatrix(false);
                texCam->setCustomProjectionMatrix(false);
            }
        }
    }
    mIlluminationStage = savedStage;
    findVisible(cam, false);
}

HeadlessRoot::HeadlessRoot()
{
    mLog = OGRE_NEW Ogre::LogManager();
    /* default log, no file, no console output, errors only */
    mLog->createLog("swarp-ogre.log", true, false, true)->setLogDetail(Ogre::LL_LOW);
    mRoot = OGRE_NEW Ogre::Root("", "", "");
    mBuffers = OGRE_NEW Ogre::DefaultHardwareBufferManager();
    mRenderSystem = OGRE_NEW NullRenderSystem();
    mRoot->setRenderSystem(mRenderSystem);
    Ogre::MaterialManager::getSingleton().initialise();
    /* bounds exactly as given: the library receives the same box */
    Ogre::MeshManager::getSingleton().setBoundsPaddingFactor(0);
}

HeadlessRoot::~HeadlessRoot()
{
    mRoot->setRenderSystem(nullptr);
    OGRE_DELETE mRoot;
    OGRE_DELETE mRenderSystem;
    OGRE_DELETE mBuffers;
    OGRE_DELETE mLog;
}

} // namespace swarp_ogre_test
